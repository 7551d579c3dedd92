"""The записка as a document model, built once from the results: a list of blocks (headings,
paragraphs, bullet lists, formulas, numbered tables and figures with captions) that every
format (report.md, .html, .pdf, .docx) writes out the same way.

Every quantity's name, symbol and unit comes from the nomenclature (render/nomenclature.py);
this module keeps only section titles and sentence templates. Nothing is computed here but
formatting and counting (the degree of freedom counts the mechanism's links and pairs).
Sources: Артоболевский И. И., «Теория механизмов и машин», ch. 2 (structure, Chebyshev's
formula), ch. 16–17 (reduction, Merzalov's method, the energy–mass diagram).
"""
from __future__ import annotations

import math
from flywheel.dynamics.loads import LoadKey
from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name, subscripted
from flywheel.render.sheet_labels import field_label, field_value, part_name
from flywheel.render import blocks
from flywheel.render.blocks import (  # noqa: F401  (the model, re-exported)
    Bullets, Document, Figure, Formula, Heading, Paragraph, Table, Where)
from flywheel.io.text import in_language
from flywheel.render.numbers import apart, column_zero, fmt as _number, fmt_worked, separator
from flywheel.render.positions import numbered, position_cells
from flywheel.units import PA_PER_MPA


# -- words ----------------------------------------------------------------------------------------
T = words("report", {
    "title": "Dynamic analysis", "source": "Source", "input": "1. Input data",
    "machine": "Machine, crank and flywheel", "lengths": "Dimensions of the mechanism",
    "masses": "Masses and moments of inertia of the links", "cyl": "Cylinders",
    "indicator": "Indicator table of cylinder {c}", "forces": "Technological forces and couples",
    "load_table": "a table of {n} rows against {of}", "of_phi": "φ", "of_travel": "the travel s",
    "over": "at φ = {a}° … {b}°",
    "s_range": "at s = {a} … {b} from the {ref} dead centre, the slider moving {stroke}",
    "dead_centre": {"outer": "outer", "inner": "inner"},
    "structure": "Structure of the mechanism",
    "structure_note": ("The mechanism is the input mechanism (crank {c} on the frame) with "
                       "Assur groups attached in order:"),
    "group": "Assur group of class II, kind {kind}: links {links}",
    "chebyshev": ("Degree of freedom by Chebyshev's formula: n = {n} moving links, "
                  "p₅ = {p5} lower pairs, p₄ = {p4} higher pairs:"),
    "tabulated": "The kinematics are given as a table (no linkage to describe).",
    "kin": "2. Kinematics at the standard positions",
    "kin_caption": "Velocity analogues at the standard positions",
    "kin_note": "Velocity analogues {vq} = dr/dφ [{u}] of the points, {wq} = dθ/dφ of the links.",
    "red": "3. Reduction of masses and forces",
    "red_caption": "Reduced inertia and moments at the standard positions",
    "red_note": ("J_II is the links' kinetic energy per ½ω²; the reduced moment of a force is "
                 "its power per ω; a link's weight acts at its centroid."),
    # the symbols of a section's formulas, a line each (ГОСТ 7.32-2017, 6.8.2)
    "where_red": ("where m_i is the mass of link i, v_qSi the velocity analogue of its centroid;\n"
                  "J_Si the moment of inertia of link i about its centroid, ω_qi its angular "
                  "velocity analogue;\n"
                  "F a force, v_q the velocity analogue of its point (the scalar product);\n"
                  "m the mass of a link, g_x, g_y the components of gravity, v_qSx, v_qSy those "
                  "of its centroid's velocity analogue."),
    # the table's last column adds the constant moment of the cycle balance, not a column of it
    "sum_note": "{S} in Table {n} is the sum of its moments' columns and the constant {M} = {v} "
                "{u} of the cycle balance.",
    "where_M": {"driving": "reduced moment of the resistance forces",
                "resistance": "reduced moment of the driving forces"},
    "where_energy": ("where {M} is the {M_name}, Φ the crank's angle of turn over the cycle;\n"
                     "A the {A_name} of the reduced moments;\n"
                     "{T} the {T_name}, {J} the {J_name}, {w} the {w_name}."),
    "where_motion": ("where v_q, a_q are the velocity and acceleration analogues of a point;\n"
                     "ω, ε the angular velocity and acceleration of the crank (the true motion);\n"
                     "ω_qi, ε_qi the angular velocity and acceleration analogues of link i."),
    # the line before a record's formulas worked with their numbers (run, task 2, duty cycle)
    "put_one": "The values found, put into formula ({n}):",
    "put_two": "The values found, put into formulas ({n}) and ({m}):",
    "put_many": "The values found, put into formulas {head} and ({m}):",
    "where_given": ("where {JM} is the given flywheel's moment of inertia on the crank shaft;\n"
                    "{J1} the moment of inertia of the first group's links on the crank shaft "
                    "(without the flywheel)."),
    "where_sizing": ("where {dT} is the largest change of the first group's kinetic energy over "
                     "the cycle;\n"
                     "δ the coefficient of speed fluctuation, {w} the mean angular velocity;\n"
                     "{J1} the moment of inertia of the first group's links on the crank shaft "
                     "(without the flywheel)."),
    "energy": "4. Works and kinetic energy",
    "energy_caption": "Works and kinetic energy at the standard positions",
    "sizing": "5. Flywheel", "sizing_caption": "The flywheel by both methods",
    "dims_caption": "Flywheel dimensions", "method": "method",
    "m_merzalov": "Merzalov", "m_exact": "energy–mass diagram (exact)",
    "shape": "shape", "disk_word": "disk", "rim_word": "rim",
    "motion": "6. True velocities and accelerations",
    "points_caption": "Points at φ = {a}°", "links_caption": "Links at φ = {a}°",
    "warn": "Warnings", "figures": "Figures", "sources": "Sources",
    "conclusion": "Conclusion", "conclusion_lead": "The dynamic analysis of the machine gives:",
    "no_plots": "The figures were not drawn (run with --plots none).",
    "pos": "position", "no": "no.", "qty": "quantity", "val": "value", "unit": "unit", "point": "point",
    "link": "link", "name": "name", "piston": "piston", "head": "head dead centre",
    "first_group": "first group", "centroid": "centroid",
    "J_first": "moment of inertia of the first group's links (on the crank shaft)",
    "part_of": "of which: {part}",
    "pivot": "crank pivot {p}",
    "length_of": "length of link {x}", "throw": "throw of crank pin {p}",
    "pin_angle": "angle of crank pin {p} to crank pin {tip}",
    "guide_point": "guide of slider {x}: a point",
    "guide_angle": "guide of slider {x}: angle to the x axis",
    "guide_offset": "guide of slider {x}: offset",
    "slide_offset": "slide line of link {x}: offset from its pivot",
    "share": "point {p} of link {x}: share of {ab}",
    "across": "point {p} of link {x}: offset across {ab}",
    "distance": "point {p} of link {x}: distance from {a}",
    "at_angle": "point {p} of link {x}: angle to the link",
    "tab_masses": "Masses and moments of inertia of the links (the table's rows they use)",
    "tab_loads": "Loads", "tab_rows": "Loads at the table's positions",
    "per_position": "at each position (table {n})", "moves_with": "point (|V_q|)",
    "turns_with": "rotation (ω_q)",
    "tab_note": ("α is the angle between a force and its point's velocity (180° opposes the "
                 "motion); a force's reduced moment is M = F·|V_q|·cos α."),
    "trace": ("The indicator diagram of cylinder {c} is a pressure trace against {against} "
              "({where}); its greatest gauge pressure p_max = {p} MPa."),
    "trace_against": {"crank_angle": "the crank angle", "volume": "the cylinder's volume",
                      "travel": "the piston's travel"},
    "trace_file": "file {f}", "trace_inline": "given in the case file",
    "ind_note": ("s is the piston's travel from the head over its stroke (0 … 1); p/p_max ↑ while "
                 "the piston moves towards the head, ↓ while it moves away."),
    "balance_word": {"driving": "driving", "resistance": "resistance"},
    "balance_row": "constant moment balancing the cycle",
    "signs": ("Signs: a reduced moment and its work are positive where they drive (act in the "
              "direction of rotation) and negative where they resist."),
    "balance": {
        "driving": ("- {A} = {vA} {uJ} by formula ({nA}); {Mx} = {vM} {uM} by formula ({nM}) "
                    "(the cycle condition: the driving moment is constant, Φ = {cycle}°)"),
        "resistance": ("- {A} = {vA} {uJ} by formula ({nA}); {Mx} = {vM} {uM} by formula "
                       "({nM}) (the cycle condition: the moment of resistance is constant, "
                       "Φ = {cycle}°)"),
    },
    "extremes": ("- {dT} max = {vmax} {uJ} at {amax}°, min = {vmin} {uJ} at {amin}° (global "
                 "extremes); {span} = {v} {uJ}"),
    "merzalov": "- Merzalov, formula ({n}): {J} = {v} {uI}, δ achieved = {d}",
    "given": ("- the flywheel is given (not sized): {J} = {v} {uI} on the crank shaft by formula "
              "({n}) gives δ = {d}"),
    "exact": "- exact (energy–mass diagram): {J} = {v} {uI}, δ achieved = {d}",
    "flywheel": "- flywheel, formula ({n}): {JM} = {v} {uI}",
    "flywheel_given": "- flywheel {JM} = {v} {uI}",
    "shaft": "; on a shaft {i:g} times faster: {v} {uI}",
    "disk": "- disk ({mat}): {dims}, {speed} {v} {u}",
    "rim": "- rim: {dims}, {speed} {v} {u} (limit {lim} {u})",
    "rim_design": ("- the rim as designed (share {share} of the flywheel's J; thin ring, Khurmi & "
                   "Gupta ch. 16): {dims}; σ = ρ·v² = {sigma} MPa"),
    "omega_extremes": "- {wmax} = {vmax} {uw} at {amax}°, {wmin} = {vmin} {uw} at {amin}°; {T} {v} {uT}",
    "at": "ω = {w} {uw}, ε = {e} {ue}", "at_phi": "At φ = {a}°",
    "time": "7. Motion in time",
    "time_note": ("The equation of motion J(φ)·φ̈ + ½·J′(φ)·φ̇² = M(φ, φ̇), J = J_I + J_II(φ), "
                  "integrated in time with scipy's solve_ivp; J, J′ and M are the tables of §3–4, "
                  "so the integration is independent of the energy solution of §5."),
    "verify": ("steady motion from the energy solution's state at φ = 0 over {n} cycles: ω repeats "
               "from cycle to cycle to {rep} (relative), and follows ω(φ) of the energy equation to "
               "{dev} (relative to ω_m)"),
    "period": "cycle time: {T} s from the integration, {Te} s from t(φ) = ∫dφ/ω",
    "motor": ("motor M_Д = M_п·(1 − ω/ω_x), reduced to the crank: M_п = {Mp} N·m, ω_x = {wx} rad/s; "
              "the steady cycle-mean speed that the motor line balances against the loads "
              "ω_s = {ws} rad/s; time constant τ = J/(M_п/ω_x) ≈ {tau} s"),
    "st_ok": ("start-up from rest: the cycle-mean speed is within δ/10 of ω_s after **{t} s** "
              "({n} cycles); steady cycle-mean speed {w} rad/s"),
    "st_no": ("start-up from rest: the steady state was **not reached** within {n} cycles ({t} s); "
              "the last cycle-mean speed is {w} rad/s"),
    "st_stall": "start-up from rest: the motor cannot start the machine — it stops at φ = {a}°",
    "st_none": "start-up: not computed ({reason})",
    "rd": "run-down after the drive is cut at φ = 0: {t} s, {rev} revolutions of the crank",
    "rd_not": " (not stopped within the integration limit)",
    "rd_never": "run-down: none — {reason}",
    "book": ("Artobolevsky I. I. Teoriya mekhanizmov i mashin (Theory of Mechanisms and "
             "Machines). 4th ed. Moscow: Nauka, 1988: ch. 2 (structure), ch. 16–17 (reduction, "
             "Merzalov's method, the energy–mass diagram)."),
    "case_source": "Input data: {s}.",
    "fig": {
        "positions": "Position functions of the points x(φ), y(φ)", "scheme": "Scheme of the mechanism",
        "reactions": "Reactions in the kinematic pairs",
        "balancing_moment": "Balancing moment on the crank: of the Assur groups and with the flywheel's inertia",
        # a tabulated case's: no groups, the power balance alone (dynamics/forces.py)
        "balancing_moment_power": "Balancing moment on the crank from the power balance",
        "hodographs": "Polar diagrams of the crank-pin, main-bearing and shaking loads",
        "hodographs_linkage": "Polar diagrams of the crank-pin, main-bearing and shaking loads",
        "velocity_analogues": "Velocity analogues of the points",
        "acceleration_analogues": "Acceleration analogues of the points",
        "indicator": "Indicator diagram, cylinder {x}", "piston_forces": "Gas forces on the pistons",
        "applied_forces": "Applied forces",
        "reduced_moments": "Reduced moments of the loads", "works": "Works and kinetic energy",
        "energy_mass": "Energy–mass diagram (Wittenbauer)",
        "time_law": "Angular velocity and acceleration of the crank in time ω(t), ε(t) over a cycle",
        "transients": "Start-up and run-down",
        "plan_positions": "The mechanism in its standard positions",
        "plan_velocity": "Velocity plan at φ = {a}°", "plan_acceleration": "Acceleration plan at φ = {a}°",
        "plan_forces": "Force polygons of the Assur groups at φ = {a}°",
        "plan_lever": "Zhukovsky's lever at φ = {a}°",
    },
})

# which section a figure belongs to (the stem of its file, or its prefix before "_<name>")
_FIGURE_SECTION = {"positions": "kin", "scheme": "kin", "velocity_analogues": "kin",
                   "acceleration_analogues": "kin", "J_II": "red", "indicator": "red",
                   "piston_forces": "red", "reduced_moments": "red", "works": "energy",
                   "energy_mass": "sizing", "omega": "motion", "epsilon": "motion",
                   "time_law": "motion", "transients": "time", "reactions": "forces",
                   "balancing_moment": "forces", "hodographs": "forces",
                   # the plans (render/plots_plans.py): plan_<what>[_<angle>]
                   "plan_positions": "kin", "plan_velocity": "kin", "plan_acceleration": "kin",
                   "plan_forces": "forces", "plan_lever": "forces"}


def g(x, digits: int = 5, zero: float = 1e-13) -> str:
    """A number as the report prints it (``digits`` significant; −0, and |x| below ``zero``,
    → 0; None → "—")."""
    return _number(x, digits, zero=zero, nonfinite="dash")


def gi(x, digits: int = 6) -> str:
    """An input of the case as the report prints it: as :func:`g`; in a Russian document with
    the digits it was given (render/numbers.py)."""
    return _number(x, digits, zero=1e-13, nonfinite="dash", given=True)


def _figure_caption(file: str, lang: str, pistons: bool = True,
                    cylinders: dict[str, str] | None = None, groups: bool = True) -> str:
    """The caption of plots/``file``; piston_forces.png of a machine with no cylinder draws
    the applied forces (a cutting force, a spring's tension), and its hodographs' crank pin
    and main bearing are the crank's, not a crankshaft's: ``pistons`` False. ``cylinders``:
    an indicator diagram's file stem → its cylinder's label in ``lang`` (else the stem's
    name). ``groups`` False: a tabulated case's balancing moment, from the power balance
    alone."""
    t = T[lang]["fig"]
    stem = file.rsplit(".", 1)[0]
    if stem == "balancing_moment" and not groups:
        return t["balancing_moment_power"]
    if stem == "piston_forces" and not pistons:
        return t["applied_forces"]
    if stem == "hodographs" and not pistons:      # no crankshaft: the crank's pin and bearing
        return t["hodographs_linkage"]
    if stem in t:
        return t[stem]
    if stem.startswith("indicator_"):
        return t["indicator"].format(x=(cylinders or {}).get(stem, stem[len("indicator_"):]))
    if stem.startswith("plan_") and stem.count("_") >= 2:       # plan_velocity_22_5: 22.5°
        what, _, a = stem[len("plan_"):].partition("_")
        if f"plan_{what}" in t:        # the angle as the document writes a number (224,2)
            return t[f"plan_{what}"].format(a=g(float(a.replace("m", "-", 1).replace("_", ".")), 6))
    if stem in ("J_II", "omega", "epsilon"):
        n = nm.name(stem, lang)
        return f"{n[:1].upper()}{n[1:]}(φ)"
    return stem


def _section_of(file: str) -> str:
    stem = file.rsplit(".", 1)[0]
    return _FIGURE_SECTION.get(stem, _FIGURE_SECTION.get(
        "_".join(stem.split("_")[:2]), _FIGURE_SECTION.get(stem.split("_")[0], "figures")))


class _Builder:
    def __init__(self, title: str, lang: str, plots: list[str] | None):
        self.doc = Document(title, lang)
        self.n_tables = 0
        self.n_figures = 0
        self.plots = list(plots or [])
        self.pistons = True             # piston_forces.png draws gas forces (else applied ones)
        self.groups = True              # a linkage's Assur groups (a tabulated case has none)
        self.cylinders: dict[str, str] = {}   # an indicator figure's stem → its cylinder's label

    def add(self, block) -> None:
        self.doc.blocks.append(block)

    def formula(self, tex: str) -> int:
        """Add a display formula; its number «(n)», which the text cites
        (:meth:`~flywheel.render.blocks.Document.add_formula`)."""
        return self.doc.add_formula(tex)

    def table(self, caption: str, header, rows) -> None:
        self.n_tables += 1
        self.add(Table(self.n_tables, caption, tuple(header), tuple(tuple(r) for r in rows)))

    def figures_of(self, section: str) -> None:
        for f in [p for p in self.plots if _section_of(p) == section]:
            self.n_figures += 1
            caption = _figure_caption(f, self.doc.lang, self.pistons, self.cylinders,
                                      self.groups)
            self.add(Figure(self.n_figures, caption, f))
            self.plots.remove(f)


class CycleBalance:
    """The cycle condition as the machine's ``balance`` reads it (Артоболевский, ch. 16: the
    work of the moving forces over a cycle of steady motion is zero): a driven machine
    (``"driving"``) knows its resistance and finds the constant M_Д = −A_С/Φ; an engine
    (``"resistance"``) knows its driving forces and finds the constant M_С = −A_Д/Φ.
    ``keys``: the nomenclature keys of the known work, the known moment and the moment found;
    ``work`` [J] and ``moment`` [N·m]: the result's numbers, signed (driving positive)."""

    def __init__(self, results):
        s, en = results.scalars, results.energy
        self.balance = en.balance
        if en.balance == "resistance":
            self.keys = ("cycle_work_driving", "driving_moment", "resistance_moment")
            self.work, self.moment = float(en.A_D[-1]), s.balancing_moment
        else:
            self.keys = ("cycle_work_resistance", "M_C", "driving_moment")
            self.work, self.moment = s.cycle_work_resistance, s.driving_moment


def put_into(lang: str, *numbers: int) -> str:
    """The line before a record's worked formulas, citing the formulas (their ``numbers``, in
    order, each once) they put the found values into: «… в формулы (1), (2) и (3):»."""
    t = T[lang]
    numbers = sorted(set(numbers))
    if len(numbers) == 1:
        return t["put_one"].format(n=numbers[0])
    if len(numbers) == 2:
        return t["put_two"].format(n=numbers[0], m=numbers[1])
    return t["put_many"].format(head=", ".join(f"({k})" for k in numbers[:-1]), m=numbers[-1])


def cycle_balance(results) -> CycleBalance:
    """The cycle condition of ``results`` (:class:`CycleBalance`)."""
    return CycleBalance(results)


def _mt(key: str, lang: str) -> str:
    """The nomenclature's mathtext symbol without its dollars (the formula notation)."""
    return nm.tex(key, lang).strip("$")


def _xy_head(lang: str) -> str:
    """A point's coordinates named as numbers.separator sets them apart: «(x; y)», "(x, y)"."""
    return f"(x{separator(lang).rstrip()} y)"


def build_document(results, lang: str = "en", plots: list[str] | None = None,
                   case=None) -> Document:
    """The записка of one run: ``plots`` the PNG names under plots/ (None or empty: no figures),
    ``case`` the validated case (its full input data and structure; None: what the results hold)."""
    t = T[lang]
    s = results.scalars
    cols = results.columns
    title, source = in_language(results.title, lang), in_language(results.source, lang)
    b = _Builder(title, lang, plots)
    b.pistons = bool(results.cylinders)
    b.groups = results.drawing is not None
    b.cylinders = {nm.indicator_stem(c.name): nm.cylinder_label(c, lang) for c in results.cylinders}

    def sym(key):
        return nm.symbol(key, lang)

    def u(key):
        return nm.unit_of(key, lang)

    def h(key, **kw):
        return nm.heading(key, lang, **kw)

    def row(key, value, digits=6, label=None):
        return [label or f"{nm.name(key, lang)}", g(value, digits) if not isinstance(value, str) else value,
                u(key)]

    b.add(Heading(1, f"{t['title']}: {title}"))
    if source:
        b.add(blocks.Source(f"{t['source']}: {source}"))
    if not plots:
        b.add(Paragraph(t["no_plots"]))

    # 1. input data -------------------------------------------------------------------------
    b.add(Heading(2, t["input"]))
    head = [t["qty"], t["val"], t["unit"]]

    def named(key: str, label: str | None = None) -> str:
        """A quantity's name and its symbol («заданный коэффициент неравномерности δ»)."""
        return f"{label or nm.bare_name(key, lang)} {sym(key)}".strip()

    linkage = case is not None and case.crank is not None   # its lengths: table 2
    rows = [
        [f"{named('omega_mean')} = 2π·{sym('crank_speed')}", g(s.omega_mean, 6), u("omega_mean")],
        [named("crank_speed"), g(s.omega_mean / (2 * math.pi), 6), u("crank_speed")],
        [field_label("machine.delta", lang), g(s.delta, 6), u("delta")],
        *([] if linkage else [[named("crank_length"), g(s.crank_length, 6), u("crank_length")]]),
        [named("J_first_group", t["J_first"]), g(s.J_first_group, 6), u("J_first_group")],
    ]
    if case is not None:
        for k, v in case.machine.first_group.items():
            rows.append([t["part_of"].format(part=part_name(k, lang)), gi(v, 6),
                         u("J_first_group")])
        rows.append([t["balance_row"], t["balance_word"][case.machine.balance], ""])
        rows.append([field_label("machine.gravity", lang),
                     separator(lang).join(gi(x, 4) for x in case.machine.gravity), u("gravity")])
    rows += [
        [nm.name("flywheel_material", lang), nm.material(s.flywheel_material, lang), ""],
        [named("flywheel_material_density"), g(s.flywheel_material_density, 6),
         u("flywheel_material_density")],
        [named("flywheel_speed_ratio"), g(s.flywheel_speed_ratio, 6), u("flywheel_speed_ratio")],
    ]
    b.add(Heading(3, f"1.1. {t['machine']}"))
    b.table(t["machine"], head, rows)
    if case is not None and case.crank is not None:
        _input_of_case(b, case, t, lang)
        _structure(b, case, t, lang)
    elif case is not None:
        b.add(Paragraph(t["tabulated"]))
        _input_of_table(b, case.tabulated, t, lang)

    # 2. kinematics ---------------------------------------------------------------------------
    # each position by its number as plan_positions.png draws it, the dead centres named under
    # the first table (a tabulated case's table has no drawing: its rows' labels instead)
    pos = [t["no"]] if numbered(results.position_angles) else [t["pos"]]
    cells, dead_note = position_cells(results.position_angles, lang)
    idx = [([c], results.index_of(p.phi)) for c, p in zip(cells, results.position_angles)]

    def positions_table(caption: str, header, body) -> None:
        """A table of the positions; the dead centres named under the first."""
        nonlocal dead_note
        b.table(caption, header, body)
        if dead_note:
            b.add(Paragraph(dead_note))
            dead_note = ""
    vq = [k for k in cols if k.startswith("vq_") and not k.startswith(("vqx_", "vqy_"))]
    wq = [k for k in cols if k.startswith("omega_q_")]
    zero: dict[str, float] = {}

    def at(k: str, i: int, digits: int) -> str:
        """Column ``k`` at node ``i``, its round-off relative to the column printed 0
        (numbers.column_zero)."""
        if k not in zero:
            zero[k] = column_zero(cols[k].values, 1e-13)
        return g(cols[k].values[i], digits, zero[k])

    if vq or wq:
        b.add(Heading(2, t["kin"]))
        b.add(Paragraph(t["kin_note"].format(vq=sym("v_q"), u=u("v_q"), wq=sym("omega_q"))))
        header = pos + [h("phi_deg")] + [f"{sym(k)}{nm.member(k, lang)}" for k in vq + wq]
        body = [[*lab, g(cols["phi_deg"].values[i], 6)] + [at(k, i, 4) for k in vq + wq]
                for lab, i in idx]
        positions_table(t["kin_caption"], header, body)
        b.figures_of("kin")
    if s.output_link is not None:                        # render/output_link.py
        from flywheel.render.output_link import add_report_section

        add_report_section(b, s.output_link, lang, "2.1",
                           driven=results.energy.balance == "resistance")

    # 3. reduction ----------------------------------------------------------------------------
    b.add(Heading(2, t["red"]))
    b.add(Paragraph(t["red_note"]))
    b.add(Formula(_mt("J_II", lang) + r" = \sum (m_{i} v_{qSi}^{2} + J_{Si} \omega_{qi}^{2})"))
    b.add(Formula(r"M_{F} = F \cdot v_{q}"))
    b.add(Formula(r"M_{G} = m (g_{x} v_{qSx} + g_{y} v_{qSy})"))
    b.add(Where(t["where_red"]))
    mk = [k for k in cols if k.startswith("M ")]
    header = (pos + [h("phi_deg"), h("J_II"), h("dJ_II")]
              + [h(k, label=nm.member(k, lang, results.loads.titles, results.loads.labels)) for k in mk] + [h("M_sum")])
    body = [[*lab, g(cols["phi_deg"].values[i], 6), at("J_II", i, 4), at("dJ_II", i, 4)]
            + [at(k, i, 5) for k in mk] + [at("M_sum", i, 5)] for lab, i in idx]
    positions_table(t["red_caption"], header, body)
    bal = cycle_balance(results)              # M_Σ's constant part, the moment §4 finds
    b.add(Paragraph(t["sum_note"].format(S=sym("M_sum"), n=b.n_tables, M=sym(bal.keys[2]),
                                         v=g(bal.moment, 4), u=u("M_sum"))))
    b.figures_of("red")

    # 4. energy -------------------------------------------------------------------------------
    b.add(Heading(2, t["energy"]))
    kA, kM, kx = bal.keys
    dTI, TII, wm = _mt("dT_I", lang), _mt("T_II", lang), _mt("omega_mean", lang)
    b.add(Paragraph(t["signs"]))
    nA = b.formula(rf"{_mt(kA, lang)} = \oint {_mt(kM, lang)} d\varphi = {g(bal.work, 6)}\,\text{{{u(kA)}}}")
    turns = s.cycle_deg // 180                       # Φ = 2π (a crank's turn), 4π (four strokes)
    cycle = (rf"{'' if turns == 1 else turns}\pi" if s.cycle_deg % 180 == 0
             else g(math.radians(s.cycle_deg), 6))
    nM = b.formula(rf"{_mt(kx, lang)} = -\frac{{{_mt(kA, lang)}}}{{\Phi}} = "
                   rf"{'-' if bal.work > 0 else ''}\frac{{{fmt_worked(abs(bal.work))}}}{{{cycle}}} = "
                   rf"{g(bal.moment, 6)}\,\text{{{u(kx)}}}")
    b.add(Formula(rf"{dTI} = A - ({TII} - {TII}(0)), {TII} = \frac{{{_mt('J_II', lang)} {wm}^{{2}}}}{{2}}"))
    b.add(Where(t["where_energy"].format(
        M=sym(kM), M_name=t["where_M"][bal.balance], A_name=nm.bare_name("A", lang),
        T=sym("T_II"), T_name=nm.bare_name("T_II", lang), J=sym("J_II"),
        J_name=nm.bare_name("J_II", lang), w=sym("omega_mean"),
        w_name=nm.bare_name("omega_mean", lang))))
    b.add(Bullets((
        t["balance"][bal.balance].format(A=sym(kA), Mx=sym(kx), vA=g(bal.work, 6), nA=nA, nM=nM,
                                         uJ=u(kA), vM=g(bal.moment, 6), uM=u(kx),
                                         cycle=g(s.cycle_deg, 6))[2:],
        t["extremes"].format(dT=sym("dT_I"), vmax=g(s.delta_T_I_max, 6), amax=g(round(s.phi_delta_T_I_max_deg, 2), 6),
                             vmin=g(s.delta_T_I_min, 6), amin=g(round(s.phi_delta_T_I_min_deg, 2), 6),
                             span=sym("delta_T_max"), v=g(s.delta_T_max, 6), uJ=u("delta_T_max"))[2:],
    )))
    energy = ("A_D", "A_C", "A", "T_II", "dT_I", "omega", "epsilon")
    header = pos + [h("phi_deg")] + [h(k) for k in energy]
    body = [[*lab, g(cols["phi_deg"].values[i], 6)] + [at(k, i, 6) for k in energy]
            for lab, i in idx]
    positions_table(t["energy_caption"], header, body)
    b.figures_of("energy")

    # 5. flywheel -----------------------------------------------------------------------------
    b.add(Heading(2, t["sizing"]))
    # the numbers put into each formula to six digits (numbers.fmt_worked: a teacher's
    # calculator gives the printed result back), the result as the record prints it (seed 000
    # §4: J_доп = ΔT/(δ·ω²) − J_10 − J_ред; a given flywheel the other way round)
    JI, dT, JM = _mt("J_required", lang), _mt("delta_T_max", lang), _mt("J_flywheel", lang)
    J1, uI = _mt("J_first_group", lang), rf"\,\text{{{u('J_required')}}}"
    if s.flywheel_given:
        numbers = (b.formula(rf"{JI} = {JM} + ({J1}) = {fmt_worked(s.J_flywheel)} + "
                             rf"{fmt_worked(s.J_first_group)} = {g(s.J_required, 6)}{uI}"),)
        b.add(Where(t["where_given"].format(JM=sym("J_flywheel"), J1=sym("J_first_group"))))
    else:
        numbers = (b.formula(rf"{JI} = \frac{{{dT}}}{{\delta \cdot {wm}^{{2}}}} = "
                             rf"\frac{{{fmt_worked(s.delta_T_max)}}}{{{gi(s.delta)} \cdot "
                             rf"{fmt_worked(s.omega_mean)}^{{2}}}} = {g(s.J_required, 6)}{uI}"),
                   b.formula(rf"{JM} = {JI} - ({J1}) = {fmt_worked(s.J_required)} - "
                             rf"{fmt_worked(s.J_first_group)} = {g(s.J_flywheel, 6)}{uI}"))
        b.add(Where(t["where_sizing"].format(dT=sym("delta_T_max"), w=sym("omega_mean"),
                                             J1=sym("J_first_group"))))
    b.add(Bullets(tuple(x[2:] for x in _sizing_lines(s, t, lang, numbers))))
    b.table(t["sizing_caption"], [t["method"], nm.heading("J_required", lang), nm.heading("J_flywheel", lang),
                                  nm.heading("delta_achieved", lang)],
            [[t["m_merzalov"], g(s.J_required, 6), g(s.J_flywheel, 6), g(s.delta_achieved, 6)],
             [t["m_exact"], g(s.J_required_exact, 6), g(s.J_flywheel_exact, 6),
              g(s.delta_achieved_exact, 6)]])
    d, r = s.flywheel_disk, s.flywheel_rim
    b.table(t["dims_caption"], [t["shape"], h("D"), h("D_inner"), h("b"), h("mass"), h("rim_speed")],
            [[t["disk_word"], g(d.D, 4), "—", g(d.b, 4), g(d.mass, 5), g(d.rim_speed, 4)],
             [t["rim_word"], g(r.D, 4), g(r.D_inner, 4), g(r.b, 4), g(r.mass, 5),
              g(r.rim_speed, 4)]])
    b.figures_of("sizing")

    # 6. motion at the report angles ----------------------------------------------------------
    b.add(Heading(2, t["motion"]))
    b.add(Formula(r"v = v_{q} \omega, a = |a_{q} \omega^{2} + v_{q} \varepsilon|, "
                  r"\omega_{i} = \omega_{qi} \omega, \varepsilon_{i} = \varepsilon_{qi} \omega^{2} + \omega_{qi} \varepsilon"))
    b.add(Where(t["where_motion"]))
    point_keys, link_keys = ("v_q", "v", "a_q", "a"), ("omega_q", "omega", "epsilon_q", "epsilon")
    for k, a in enumerate(results.at, 1):
        b.add(Heading(3, f"6.{k}. {t['at_phi'].format(a=g(a.phi_deg, 6))}"))
        b.add(Paragraph(t["at"].format(w=g(a.omega, 6), uw=u("omega"), e=g(a.epsilon, 6),
                                       ue=u("epsilon"))))
        # a column no row has a value for is left out (a tabulated case's kinematics give no
        # acceleration analogues: its a_q, a, ε_q, ε had been columns of dashes)
        pkeys = [x for x in point_keys if any(getattr(p, x) is not None for p in a.points.values())]
        lkeys = [x for x in link_keys if any(getattr(v, x) is not None for v in a.links.values())]
        if a.points:
            b.table(t["points_caption"].format(a=g(a.phi_deg, 6)), [t["point"], *(h(x) for x in pkeys)],
                    [[point_name(n)] + [g(getattr(p, x), 5) for x in pkeys]
                     for n, p in a.points.items()])
        if a.links:
            b.table(t["links_caption"].format(a=g(a.phi_deg, 6)), [t["link"], *(h(x) for x in lkeys)],
                    [[n] + [g(getattr(lk, x), 5) for x in lkeys] for n, lk in a.links.items()])
    b.figures_of("motion")

    td = s.time_domain
    if td is not None:
        b.add(Heading(2, t["time"]))
        b.add(Paragraph(t["time_note"]))
        b.add(Bullets(tuple(x[2:] for x in _time_lines(td, s, t, lang))))
        b.figures_of("time")

    if getattr(results, "forces", None) is not None:    # the force analysis (render/forces.py)
        from flywheel.render.forces import add_report_section

        add_report_section(b, results, lang)
        b.figures_of("forces")

    if results.warnings:
        b.add(Heading(2, t["warn"]))
        b.add(Bullets(tuple(nm.message(w, lang) for w in results.warnings)))
    if b.plots:
        b.add(Heading(2, t["figures"]))
        b.figures_of("figures")
    _conclusion(b, results, t, lang)
    b.add(Heading(2, t["sources"]))
    src = [t["book"]]
    if source:
        src.insert(0, t["case_source"].format(s=source))
    b.add(Bullets(tuple(f"[{i}] {x}" for i, x in enumerate(src, 1))))
    b.doc.blocks[:] = blocks.referenced(blocks.numbered(b.doc.blocks), lang)   # 1.1 … without a
    return b.doc                                          # gap; every table and figure cited


def _conclusion(b: _Builder, results, t: dict, lang: str) -> None:
    """«Заключение» (ГОСТ 7.32-2017: the conclusion states the work's results): the main
    results, as drawing sheet 1's table gives them (render/main_results.py), a line each,
    «приведённый движущий момент M_Д = 197,5 Н·м;», the last with a full stop."""
    from flywheel.render.main_results import main_results

    rows = main_results(results, lang, ratio_text=lambda i: g(i, 6))
    b.add(Heading(2, t["conclusion"]))
    b.add(Paragraph(t["conclusion_lead"]))
    items = [f"{name[:1].lower()}{name[1:]} {sym} = {g(value, 4)}"
             + ("" if unit in ("", "–", "-") else f" {unit}") for name, sym, value, unit in rows]
    b.add(Bullets(tuple(x + (";" if k < len(items) - 1 else ".") for k, x in enumerate(items))))


def _sizing_lines(s, t: dict, lang: str, numbers: tuple[int, ...]) -> list[str]:
    """§5's lines; ``numbers``: the numbers of its formulas (J_I's, then J_M's if sized)."""
    def sym(key):
        return nm.symbol(key, lang)

    def u(key):
        return nm.unit_of(key, lang)

    def dims(d: dict, keys, digits) -> str:
        return ", ".join(f"{sym(k)} = {g(getattr(d, k), n)} {u(k)}" for k, n in zip(keys, digits))

    d, r = s.flywheel_disk, s.flywheel_rim
    uI = u("J_required")
    # ω_max and ω_min told apart: a small δ writes both alike to four digits (numbers.apart)
    spec = apart(s.omega_max, s.omega_min)
    w_max, w_min = (g(w, 6) if spec is None else _number(w, spec=spec, zero=1e-13)
                    for w in (s.omega_max, s.omega_min))
    fw = (t["flywheel_given"].format(JM=sym("J_flywheel"), v=g(s.J_flywheel, 6), uI=uI)
          if s.flywheel_given else
          t["flywheel"].format(JM=sym("J_flywheel"), v=g(s.J_flywheel, 6), uI=uI, n=numbers[-1]))
    if s.flywheel_speed_ratio != 1:
        fw += t["shaft"].format(i=s.flywheel_speed_ratio, v=g(s.flywheel_J_on_its_shaft, 6), uI=uI)
    return [
        t["given"].format(J=sym("J_required"), v=g(s.J_required, 6), uI=uI, n=numbers[0],
                          d=g(s.delta_achieved, 6)) if s.flywheel_given else
        t["merzalov"].format(J=sym("J_required"), v=g(s.J_required, 6), uI=uI, n=numbers[0],
                             d=g(s.delta_achieved, 6)),
        t["exact"].format(J=sym("J_required_exact"), v=g(s.J_required_exact, 6), uI=uI,
                          d=g(s.delta_achieved_exact, 6)),
        fw,
        t["disk"].format(mat=nm.material(s.flywheel_material, lang),
                         dims=dims(d, ("D", "b", "mass"), (4, 4, 5)), speed=nm.name("disk_speed", lang),
                         v=g(d.rim_speed, 4), u=u("rim_speed")),
        t["rim"].format(dims=dims(r, ("D", "D_inner", "b", "mass"), (4, 4, 4, 5)),
                        speed=nm.name("rim_speed", lang), v=g(r.rim_speed, 4), u=u("rim_speed"),
                        lim=g(s.flywheel_rim_speed_limit, 3)),
        *([t["rim_design"].format(share=g(r.share, 4), sigma=g(r.stress / PA_PER_MPA, 4),
                                  dims=dims(r, ("D_mean", "thickness", "width", "mass", "rim_speed"),
                                            (4, 4, 4, 5, 4)))] if s.rim_designed else []),
        t["omega_extremes"].format(wmax=sym("omega_max"), vmax=w_max,
                                   amax=g(s.phi_omega_max_deg, 6), wmin=sym("omega_min"),
                                   vmin=w_min, amin=g(s.phi_omega_min_deg, 6),
                                   uw=u("omega_max"), T=nm.name("cycle_time", lang),
                                   v=g(s.cycle_time, 6), uT=u("cycle_time")),
    ]


def _input_of_case(b: _Builder, case, t: dict, lang: str) -> None:
    """The case's lengths, masses, cylinders and forces (§1.2–1.5)."""
    from flywheel.cases.run import RPRSpec, RRPSpec, RRRSpec

    def u(key):
        return nm.unit_of(key, lang)

    c, sep, m = case.crank, separator(lang), u("x")
    ll, ga, go = nm.symbol("link_length", lang), nm.symbol("guide_angle", lang), nm.symbol("guide_offset", lang)

    def xy(p) -> str:
        return f"{gi(p[0], 6)}{sep}{gi(p[1], 6)}"

    def length(a: str, b: str) -> str:          # l_AB: the link's length by its two points
        return subscripted(ll, a + b)

    rows = [[f"{t['pivot'].format(p=point_name(c.pivot))} {_xy_head(lang)}", xy(c.pivot_at), m],
            [f"{nm.bare_name('crank_length', lang)} {length(c.pivot, c.tip)}",
             gi(case.crank_length, 6), u("crank_length")]]
    for pin in c.pins:                       # a multi-throw crankshaft's further pins
        throw = case.crank_length if pin.length is None else pin.length
        rows.append([t["throw"].format(p=point_name(pin.name)), gi(throw, 6), u("crank_length")])
        rows.append([t["pin_angle"].format(p=point_name(pin.name), tip=point_name(c.tip)),
                     gi(pin.angle_deg, 6), u("guide_angle")])
    rows += [[field_label("crank.start_angle_deg", lang), gi(c.start_angle_deg, 6), u("guide_angle")],
             [field_label("crank.rotation", lang), field_value("crank.rotation", c.rotation, lang),
              ""]]
    for d in case.dyads:
        if isinstance(d, RRPSpec):
            rows.append([f"{t['length_of'].format(x=d.rod)} {length(d.from_, d.joint)}",
                         gi(case.rod_length(d), 6), u("link_length")])
            rows.append([f"{t['guide_point'].format(x=d.slider)} {_xy_head(lang)}",
                         xy(d.guide.through), m])
            rows.append([f"{t['guide_angle'].format(x=d.slider)} {subscripted(ga, d.slider)}",
                         gi(d.guide.angle_deg, 6), u("guide_angle")])
            if d.guide.offset:
                rows.append([f"{t['guide_offset'].format(x=d.slider)} {subscripted(go, d.slider)}",
                             gi(d.guide.offset, 6), u("guide_offset")])
        elif isinstance(d, RRRSpec):
            rows.append([f"{t['length_of'].format(x=d.link_from)} {length(d.from_, d.joint)}",
                         gi(d.length_from, 6), u("link_length")])
            rows.append([f"{t['length_of'].format(x=d.link_to)} {length(d.joint, d.to)}",
                         gi(d.length_to, 6), u("link_length")])
        elif isinstance(d, RPRSpec) and d.offset:
            rows.append([f"{t['slide_offset'].format(x=d.rocker)} {subscripted(go, d.rocker)}",
                         gi(d.offset, 6), u("guide_offset")])
    for name, p in case.ground.items():
        rows.append([field_label(f"ground.{name}", lang), xy(p), m])
    for name, p in case.points.items():
        at = {"p": point_name(name), "x": p.link, "a": point_name(p.from_),
              "ab": f"{p.from_}{p.to or ''}"}
        if p.to is not None:
            rows.append([f"{t['share'].format(**at)} {length(p.from_, name)}/{length(p.from_, p.to)}",
                         gi(p.fraction, 6), nm.unit("-", lang)])
            if p.across:
                rows.append([t["across"].format(**at), gi(p.across, 6), m])
        else:
            rows.append([f"{t['distance'].format(**at)} {length(p.from_, name)}",
                         gi(p.distance, 6), m])
            if p.angle_deg:
                rows.append([t["at_angle"].format(**at), gi(p.angle_deg, 6), u("guide_angle")])
    b.add(Heading(3, f"1.2. {t['lengths']}"))
    b.table(t["lengths"], [t["qty"], t["val"], t["unit"]], rows)

    if case.links:
        b.add(Heading(3, f"1.3. {t['masses']}"))
        b.table(t["masses"], [t["link"], nm.heading("link_mass", lang), nm.heading("J_S", lang), t["centroid"]],
                [[k, gi(v.mass, 6), gi(v.J_S, 6), point_name(v.centroid) if v.centroid else "—"]
                 for k, v in case.links.items()])
    if case.cylinders:
        b.add(Heading(3, f"1.4. {t['cyl']}"))
        def p_max(c) -> str:        # in MPa (seed 000: p_max2 = 0.882 MPa) as given, or a
            measured = getattr(c, "indicator", None) is not None     # measured trace's to 4 digits
            mpa = c.p_max / PA_PER_MPA
            return g(float(f"{mpa:.4g}"), 6) if measured else gi(mpa, 6)

        b.table(t["cyl"], [t["name"], t["piston"], nm.heading("bore", lang),
                           nm.heading("p_max", lang, si="MPa"), t["head"]],
                [[nm.cylinder_label(c, lang), c.piston, gi(c.bore, 6), p_max(c),
                  nm.DEAD_CENTRES[c.head][lang == "ru"]] for c in case.cylinders])
        noted = False
        for c in case.cylinders:
            sym_s, sym_p = nm.symbol("s_{cylinder}", lang), nm.symbol("p_rel", lang)
            if getattr(c, "indicator", None) is not None:    # a measured trace: said, not listed
                i = c.indicator
                where = (t["trace_file"].format(f=c.indicator_file) if c.indicator_file
                         else t["trace_inline"])
                b.add(Paragraph(t["trace"].format(c=nm.cylinder_label(c, lang),
                                                  against=t["trace_against"][i.against],
                                                  where=where, p=g(c.p_max / PA_PER_MPA, 4))))
            elif getattr(c, "strokes", None) is not None:    # a four-stroke cylinder
                st = c.strokes
                names = ("intake", "compression", "expansion", "exhaust")
                b.table(t["indicator"].format(c=nm.cylinder_label(c, lang)),
                        [sym_s] + [f"{sym_p} {nm.name('engine_' + n, lang)}" for n in names],
                        [[gi(s_, 4)] + [gi(getattr(st, n)[k], 4) for n in names]
                         for k, s_ in enumerate(c.s)])
            elif getattr(c, "diagram", None) is not None:    # one table over the cycle
                b.table(t["indicator"].format(c=nm.cylinder_label(c, lang)), [sym_s, sym_p],
                        [[gi(s_, 4), gi(p_, 4)] for s_, p_ in zip(c.diagram.s, c.diagram.p)])
            else:
                b.table(t["indicator"].format(c=nm.cylinder_label(c, lang)), [sym_s, f"{sym_p} ↑", f"{sym_p} ↓"],
                        [[gi(s_, 4), gi(a, 4), gi(w, 4)]
                         for s_, a, w in zip(c.s, c.towards_head, c.away_from_head)])
                if not noted:                   # the columns said once, under the first
                    b.add(Paragraph(t["ind_note"]))
                    noted = True
    springs = getattr(case, "springs", ())
    if case.forces or case.couples or springs:
        b.add(Heading(3, f"1.5. {t['forces']}"))

        def value(load, size) -> str:     # a size or a table, and where it acts if not always
            text = gi(size, 6) if size is not None else t["load_table"].format(
                n=len(load.table), of=t["of_" + getattr(load, "table_of", "phi")])
            rng = load.phi_range_deg
            if rng is not None:
                text += f"; {t['over'].format(a=gi(rng[0], 6), b=gi(rng[1], 6))}"
            if getattr(load, "slider", None) is not None and (
                    tuple(load.s_range) != (0.0, 1.0) or load.stroke != "both"):
                text += "; " + t["s_range"].format(
                    a=gi(load.s_range[0], 6), b=gi(load.s_range[1], 6),
                    ref=t["dead_centre"][load.reference],
                    stroke=field_value("forces.0.stroke", load.stroke, lang))
            return text

        rows = [[_load_called("force", f, lang), f.slider if f.slider is not None else f.point,
                 value(f, f.magnitude), u("force_magnitude")] for f in case.forces]
        rows += [[_load_called("couple", c, lang), c.link, value(c, c.moment), u("couple_moment")]
                 for c in case.couples]
        rows += [[_load_called("spring", s, lang),
                  "–".join(s.points) if s.kind == "linear" else
                  "–".join(s.links) if s.links is not None else s.link, f"c = {g(s.stiffness, 6)}",
                  nm.unit("N/m" if s.kind == "linear" else "N·m/rad", lang)] for s in springs]
        b.table(t["forces"], [t["name"], t["link"], t["val"], t["unit"]], rows)


def _load_called(kind: str, load, lang: str) -> str:
    """A case's load (a force, a couple, a spring of the case file or of its [tabulated]) by
    its title if the case gives one, else its kind and name (nomenclature.load_name)."""
    key = LoadKey(kind, load.name)
    return nm.load_name(key, lang, {key: load.title} if load.title else None)


def _input_of_table(b: _Builder, tab, t: dict, lang: str) -> None:
    """A ``[tabulated]`` case's links (mass, J, the rows they use) and loads (forces at its
    points, reduced moments given outright), those given per position in a table of their own
    (docs/tabulated.md; the kinematic rows are the table of §2)."""
    def u(key):
        return nm.unit_of(key, lang)

    if tab.links:
        b.add(Heading(3, f"1.2. {t['masses']}"))
        wq = nm.symbol("omega_q", lang)         # a row of the table: «ω_q2», not «2»
        b.table(t["tab_masses"], [t["link"], nm.heading("link_mass", lang),
                                  nm.with_unit("J", u("J_S"), lang), t["moves_with"],
                                  t["turns_with"]],
                [[k, gi(v.mass, 6) if v.mass else "—", gi(v.J, 6) if v.J else "—",
                  point_name(v.point) if v.point else "—",
                  f"{wq}{v.omega_q or k}" if v.J and (v.omega_q or k) in tab.omega_q else "—"]
                 for k, v in tab.links.items()])
    if not (tab.forces or tab.moments):
        return
    rows_table = b.n_tables + 2                      # the table of the per-position values
    per = t["per_position"].format(n=rows_table)
    columns: list[tuple[str, list]] = []             # (heading, a value per position)

    def given(x, head: str) -> str:                  # a number, or a column of the table
        if isinstance(x, (int, float)):
            return gi(x, 6)
        columns.append((head, list(x)))
        return per

    rows = []
    for f in tab.forces:               # a column by its load's name in the document's language
        called = _load_called("force", f, lang)
        F, a = (f"{nm.symbol(k, lang)} ({called})" for k in ("force_magnitude", "guide_angle"))
        rows.append([called, point_name(f.point),
                     given(f.magnitude, nm.with_unit(F, u("force_magnitude"), lang)),
                     given(f.angle_deg, nm.with_unit(a, u("guide_angle"), lang))])
    for m in tab.moments:
        called = _load_called("moment", m, lang)
        rows.append([called, "—", given(m.values, nm.with_unit(f"M ({called})", u("M_sum"), lang)),
                     "—"])
    b.add(Heading(3, f"1.3. {t['tab_loads']}"))
    size = nm.with_unit("F", u("force_magnitude"), lang)
    if tab.moments:
        size += f"{separator(lang)}{nm.with_unit('M', u('M_sum'), lang)}"
    b.table(t["tab_loads"], [t["name"], t["point"], size,
                             nm.with_unit("α", u("guide_angle"), lang)], rows)
    b.add(Paragraph(t["tab_note"]))
    if columns:
        b.table(t["tab_rows"], [nm.heading("phi_deg", lang)] + [hd for hd, _ in columns],
                [[gi(phi, 6)] + [gi(col[k], 6) for _, col in columns]
                 for k, phi in enumerate(tab.positions_deg)])


def _structure(b: _Builder, case, t: dict, lang: str) -> None:
    """The Assur groups and the degree of freedom W = 3n − 2p₅ − p₄ (Chebyshev; Артоболевский
    ch. 2): a crank on the frame (one link, one revolute pair) and dyads of class II (two links,
    three lower pairs each)."""
    b.add(Heading(3, f"1.6. {t['structure']}"))
    b.add(Paragraph(t["structure_note"].format(c=case.crank.name)))
    groups = []
    for d in case.dyads:
        groups.append(t["group"].format(kind=nm.dyad_kind(d.kind, lang), links=", ".join(d.links)))
    b.add(Bullets(tuple(groups)))
    n, p5, p4 = 1 + 2 * len(case.dyads), 1 + 3 * len(case.dyads), 0
    b.add(Paragraph(t["chebyshev"].format(n=n, p5=p5, p4=p4)))
    b.add(Formula(rf"W = 3n - 2p_{{5}} - p_{{4}} = 3 \cdot {n} - 2 \cdot {p5} - {p4} = {3 * n - 2 * p5 - p4}"))


def _time_lines(td, s, t: dict, lang: str = "en") -> list[str]:
    """The bullet lines of the "Motion in time" section (--transients): ``td`` the
    TimeDomainResult, ``s`` the headline scalars."""
    v, st, rd = td.verification, td.startup, td.rundown
    lines = [
        "- " + t["verify"].format(n=v.cycles, rep=_number(v.repeat_error, spec=".1e", zero=None, nonfinite="show"),
                                  dev=_number(v.max_deviation, spec=".1e", zero=None, nonfinite="show")),
        "- " + t["period"].format(T=g(v.period, 6), Te=g(s.cycle_time, 6)),
    ]
    if not st.computed:
        return lines + ["- " + t["st_none"].format(reason=nm.message(st.reason, lang)),
                        _rundown_line(rd, t, lang)]
    lines.append("- " + t["motor"].format(Mp=g(st.starting_torque, 5), wx=g(st.no_load_speed, 5),
                                          ws=g(st.omega_final_predicted, 6),
                                          tau=g(st.time_constant, 3)))
    if st.stalled:
        lines.append("- " + t["st_stall"].format(a=_number(st.stall_angle_deg, spec=".1f", zero=None, nonfinite="show")))
    elif st.converged and st.time_to_steady is not None:
        lines.append("- " + t["st_ok"].format(t=g(st.time_to_steady, 4), n=st.cycles_to_steady,
                                              w=g(st.omega_mean_steady, 6)))
    else:
        lines.append("- " + t["st_no"].format(n=st.cycles_run, t=g(st.time_run, 4),
                                              w=g(st.omega_mean_last, 6)))
        if st.warning:
            lines.append(f"- **{nm.message(st.warning, lang)}**")
    return lines + [_rundown_line(rd, t, lang)]


def _rundown_line(rd, t: dict, lang: str = "en") -> str:
    if rd.reason:                # English: the fixed line; Russian: the reason itself
        return "- " + t["rd_never"].format(reason=nm.message(rd.reason, lang))
    return "- " + t["rd"].format(t=g(rd.time, 4), rev=_number(rd.angle_deg / 360, spec=".2f", zero=None, nonfinite="show")) + (
        "" if rd.stopped else t["rd_not"])
