"""The записка of `flywheel aggregate CASE --out DIR`: the machine aggregate with elastic
couplings as a textbook solution (Ефанов, «Теория механизмов и машин», ch. 9), a document
model (render/document.py) written as report.md/.html/.pdf/.docx like the one of `flywheel run`.

Sections: the given data (rotors and connections reduced to shaft I, the motor and the load),
the method (Lagrange's equations in the generalised coordinates, 9.24–9.25; the frequency
equation; the steady forced vibration), the coefficients a_ij and c_ij, the natural frequencies
with their shapes, the resonance margins, the steady state and the start-up, the figure, the
sources. Every number is a field of the :class:`~flywheel.elastic.model.AggregateResult`;
labels come from render/nomenclature.py, this module keeps the section titles.
"""
from __future__ import annotations

from flywheel.render.blocks import referenced, sentence
from flywheel.render.catalogue import words
from flywheel.render.document import (T as RECORD, Bullets, Document, Figure, Formula, Heading,
                                      Paragraph, Where, put_into)
from flywheel.render.nomenclature import name as text, rotor_name, unit
from flywheel.render.numbers import fmt as _number, fmt_worked, separator
from flywheel.units import RPM_PER_RAD_S, TWO_PI

FIGURE = "aggregate.png"

T = words("report_aggregate", {
    "title": "Machine aggregate with elastic couplings", "source": "Source",
    "given": "1. Given data", "rotors": "Rotors reduced to shaft I (J·u², u = ω/ω_I)",
    "connections": "Connections reduced to shaft I (c·u²)", "drive": "Motor and load reduced to shaft I",
    "method": "2. Method",
    "method_note": ("The aggregate is a chain of rigid rotors joined by elastic shafts and "
                    "couplings, every quantity reduced to shaft I. Lagrange's equations in "
                    "the generalised coordinates give the inertia and stiffness coefficients "
                    "a_ij, c_ij; the natural frequencies are the roots of the frequency "
                    "equation; the steady forced vibration under the harmonic load is found "
                    "in closed form and checked by integrating in time (solve_ivp)."),
    "coefficients": "3. Coefficients of the equations", "frequencies": "4. Natural frequencies",
    "modes_caption": "Natural frequencies and mode shapes",
    "resonance": "5. Forced vibration and start-up",
    "resonance_caption": "Resonance margins", "steady_caption": "Steady state and start-up",
    "no_motor": "No [motor]: natural frequencies only.",
    "figure": "Speeds and the elastic moment against time: start-up and steady state",
    "sources": "Sources", "case_source": "Input data: {s}.",
    "book": ("Efanov A. M. Teoriya mekhanizmov i mashin (Theory of Mechanisms and Machines), "
             "ch. 9: the machine aggregate with an elastic coupling (eqs. 9.20–9.25)."),
    "kind": "motor characteristic", "linear": "linear M_D = M_s·(1 − ω/ω_x)",
    "constant": "constant torque", "M_start": "starting torque M_s",
    "omega_x": "synchronous speed ω_x", "omega_nominal": "speed ω_I",
    "M0": "mean resistance M_0·i31", "amplitude": "amplitude of the load M̃·i31",
    "forcing_ratio": "forcing frequency / ω_I",
    "quantity": "quantity", "value": "value", "unit": "unit", "matrix": "{name}, {u}",
    "check": "solve_ivp check",
    # the symbols of the method's formulas, a line each (ГОСТ 7.32-2017, 6.8.2)
    "where": ("where a_ij, b_ij, c_ij are the inertia, damping and stiffness coefficients, "
              "q_j the generalised coordinates, Q_i the generalised forces;\n"
              "ω a natural circular frequency, f the same in hertz"),
    "where_two": (";\nJ_1, J_2 the two masses' moments of inertia and c the stiffness of their "
                  "connection, reduced to shaft I"),
    "where_drive": (";\nω_max, ω_min, ω_m the greatest, least and mean angular velocities of "
                    "shaft I, δ the coefficient of speed fluctuation;\n"
                    "ω_f the forcing frequency, ω_n the natural frequency of mode n, Δ the margin "
                    "from resonance"),
    # the generalised coordinates of the equations below (the terminal prints them with the
    # equations in one line: render/aggregate.py, the nomenclature's ag_equations*)
    "coords": ("Generalised coordinates: q_1 = φ_1, the angle of the first rotor; "
               "q_{k+1} = φ_{k+1} − φ_k, the twist of connection k."),
    "coords_fixed": ("Generalised coordinates: the rotors' absolute angles φ_j (a shaft fixed to "
                     "the frame: no rigid rotation; a = M, c = K)."),
    "coords_tree": ("Generalised coordinates: q_1, the angle of the first rotor; "
                    "q_{k+1} = φ_to − φ_from, the twist of shaft k (the angles of its end and "
                    "its start)."),
})


def g(x, fmt: str = ".6g") -> str:
    """A number as the report prints it (tiny → 0; None or non-finite → "—")."""
    return _number(x, spec=fmt, zero=1e-300, nonfinite="dash")


def _clean(label: str) -> str:
    """A nomenclature label made for rich (``\\[`` escapes) as plain text."""
    return label.replace("\\[", "[")


def build_aggregate_document(r, title: str, source: str, lang: str = "en",
                             figure: str | None = FIGURE) -> Document:
    """The записка of one aggregate result; ``figure`` the plot's name under plots/ (None: none)."""
    t = T[lang]

    def L(key: str, **fields) -> str:
        return _clean(text(key, lang, **fields))

    def U(u: str) -> str:
        return unit(u, lang)

    doc = Document.titled(t["title"], title, source, t["source"], lang)
    add = doc.blocks.append

    def table(caption, header, rows):
        doc.add_table(caption[:1].upper() + caption[1:], header, rows)

    # 1. given data ---------------------------------------------------------------------------
    ch = r.chain
    names = [rotor_name(n, lang) for n in ch.names]
    add(Heading(2, t["given"]))
    table(t["rotors"], [RECORD[lang]["no"], L("rotor"), f"J_{'пр' if lang == 'ru' else 'reduced'}, {U('kg·m²')}", "u"],
          [[k + 1, n, g(j), g(u)] for k, (n, j, u) in enumerate(zip(names, ch.J, ch.ratio))])
    table(t["connections"], [RECORD[lang]["no"], L("between"), f"c, {U('N·m/rad')}", f"b, {U('N·m·s/rad')}"],
          [[k + 1, f"{names[i]} – {names[j]}", g(c), g(b)]
           for k, (c, b, (i, j)) in enumerate(zip(ch.c, ch.damping, ch.pairs))])
    dr = r.drive
    if dr is not None:
        rows = [[t["kind"], t.get(dr.kind, dr.kind), U("-")]]
        if dr.kind == "linear":
            rows += [[t["M_start"], g(dr.M_start), U("N·m")], [t["omega_x"], g(dr.omega_x), U("rad/s")]]
        elif dr.omega_nominal is not None:
            rows.append([t["omega_nominal"], g(dr.omega_nominal), U("rad/s")])
        rows += [[t["M0"], g(dr.M0), U("N·m")], [t["amplitude"], g(dr.amplitude), U("N·m")],
                 [t["forcing_ratio"], g(dr.forcing_ratio), U("-")]]
        table(t["drive"], [t["quantity"], t["value"], t["unit"]], rows)

    # 2. method -------------------------------------------------------------------------------
    add(Heading(2, t["method"]))
    add(Paragraph(t["method_note"]))
    add(Paragraph(t["coords_fixed" if ch.fixed else "coords" if ch.ends is None
                    else "coords_tree"]))
    add(Formula(r"\sum_{j} (a_{ij} \frac{d^{2}q_{j}}{dt^{2}} + b_{ij} \frac{dq_{j}}{dt} + "
                r"c_{ij} q_{j}) = Q_{i}"))
    add(Formula(r"\text{det}(c_{ij} - \omega^{2} a_{ij}) = 0, f = \frac{\omega}{2\pi}"))
    # two free masses: the determinant's root in closed form (seed 003, Ефанов ch. 9)
    two = len(ch.J) == 2 and not ch.fixed
    n_two = doc.add_formula(r"\omega = \sqrt{\frac{c (J_{1} + J_{2})}{J_{1} J_{2}}}") if two else None
    wm, wf = ("ср", "вын") if lang == "ru" else ("m", "f")   # mean; forcing (as the tables)
    n_margin = None
    if dr is not None:
        n_margin = doc.add_formula(
            rf"\delta = \frac{{\omega_{{max}} - \omega_{{min}}}}{{\omega_{{\text{{{wm}}}}}}}, "
            rf"\Delta = |1 - \frac{{\omega_{{\text{{{wf}}}}}}}{{\omega_{{n}}}}|")
    add(Where(t["where"] + (t["where_two"] if two else "")
              + (t["where_drive"] if dr is not None else "") + "."))

    # 3. coefficients -------------------------------------------------------------------------
    add(Heading(2, t["coefficients"]))
    n = r.a.shape[0]
    for key, m, u in (("a_ij", r.a, "kg·m²"), ("c_ij", r.c, "N·m/rad")):
        table(t["matrix"].format(name=L(key), u=U(u)),
              [""] + [L("matrix_j", j=j + 1) for j in range(n)],
              [[L("matrix_i", i=i + 1)] + [g(m[i, j]) for j in range(n)] for i in range(n)])

    # 4. natural frequencies ------------------------------------------------------------------
    add(Heading(2, t["frequencies"]))
    rigid = r.modes.rigid
    table(t["modes_caption"], [L("mode"), f"ω, {U('rad/s')}", f"f, {U('Hz')}",
                               f"n, {U('rpm')}", L("shape")],
          [[L("rigid_body") if k < rigid else k - rigid + 1, g(w), g(w / TWO_PI), g(w * RPM_PER_RAD_S),
            separator(lang).join(g(x, ".4g") for x in r.modes.shapes[:, k])]
           for k, w in enumerate(r.modes.omega)])
    if n_two is not None:             # worked with six digits of the tables' numbers
        n6 = fmt_worked
        J1, J2, c = (n6(float(x)) for x in (ch.J[0], ch.J[1], ch.c[0]))
        add(Paragraph(put_into(lang, n_two)))
        add(Formula(rf"\omega = \sqrt{{\frac{{{c} \cdot ({J1} + {J2})}}{{{J1} \cdot {J2}}}}} = "
                    rf"{n6(float(r.modes.omega[-1]))}\,\text{{{U('rad/s')}}}"))

    # 5. forced vibration ---------------------------------------------------------------------
    add(Heading(2, t["resonance"]))
    st = r.steady
    if st is None:
        add(Paragraph(t["no_motor"]))
    else:
        add(Paragraph(sentence(L("ag_forcing", w=g(st.omega_forcing), f=g(st.omega_forcing / TWO_PI),
                                 omega=g(st.omega_mean), n=g(st.omega_mean * RPM_PER_RAD_S)))))
        table(t["resonance_caption"], [L("mode"), f"f_n, {U('Hz')}", L("ratio"), L("margin")],
              [[k + 1, g(x.omega_n / TWO_PI), g(x.ratio, ".4f"), g(x.margin, ".4f")]
               for k, x in enumerate(r.resonance)])
        if r.resonance and n_margin is not None:      # the first mode's, worked
            x = r.resonance[0]
            add(Paragraph(put_into(lang, n_margin)))
            add(Formula(rf"\Delta_{{1}} = |1 - \frac{{{fmt_worked(st.omega_forcing)}}}"
                        rf"{{{fmt_worked(x.omega_n)}}}| = {fmt_worked(x.margin)}"))
        u_last = float(ch.ratio[-1])
        rows = [
            [L("twist_mean"), g(st.twist_mean[0]), U("rad"), ""],
            [L("twist_amp"), g(st.twist_amplitude[0]), U("rad"), g(r.check_twist_amplitude)],
            [L("moment_mean"), g(st.moment_mean[0]), U("N·m"), ""],
            [L("moment_amp"), g(st.moment_amplitude[0]), U("N·m"), ""],
            [L("omega_motor"), f"{g(st.omega_mean - st.omega_amplitude[0])} … "
             f"{g(st.omega_mean + st.omega_amplitude[0])}", U("rad/s"), ""],
            [L("delta_motor"), g(st.delta[0]), U("-"), g(r.check_delta[0] if r.check_delta else None)],
            [L("omega_machine"), f"{g((st.omega_mean - st.omega_amplitude[-1]) * u_last)} … "
             f"{g((st.omega_mean + st.omega_amplitude[-1]) * u_last)}", U("rad/s"), ""],
            [L("delta_machine"), g(st.delta[-1]), U("-"), g(r.check_delta[1] if r.check_delta else None)],
        ]
        if r.startup is not None:
            rows.append([L("startup_peak"), g(r.startup_peak_moment), U("N·m"),
                         L("startup_over", t=g(r.startup.t[-1], ".4g"))])
            if r.startup_time is not None:
                rows.append([L("startup_time"), g(r.startup_time), U("s"), ""])
        table(t["steady_caption"], [t["quantity"], t["value"], t["unit"], t["check"]], rows)
    if r.notes:
        add(Bullets(tuple(L("note", note=L(f"note_{x.kind}", **dict(x.values))) for x in r.notes)))
    if figure:
        add(Figure(1, t["figure"], figure))

    add(Heading(2, t["sources"]))
    src = ([t["case_source"].format(s=source)] if source else []) + [t["book"]]
    add(Bullets(tuple(f"[{i}] {x}" for i, x in enumerate(src, 1))))
    doc.blocks[:] = referenced(doc.blocks, lang)         # every table and figure cited
    return doc
