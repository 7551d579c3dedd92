"""The записка of `flywheel duty-cycle CASE --out DIR`: a press, riveter or shear whose flywheel
gives each operation's energy, as a textbook solution (Khurmi & Gupta, «Theory of Machines»,
ch. 16, "Flywheel in Punching Press"), a document model (render/document.py) written as
report.md/.html/.pdf/.docx like the one of `flywheel run`.

Sections: the method with its formulas, the operation, the motor, the speeds, the flywheel and
the timing (the same tables as the summary, render/duty_cycle.py ``summary_tables``), the checks,
the warnings and the sources. There is no figure (the command draws none). Every number is the
result (``DutyCycleResult``, by attribute).
"""
from __future__ import annotations

from flywheel.render.numbers import fmt as _number, fmt_worked

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.document import (Bullets, Document, Formula, Heading, Paragraph, Where,
                                      put_into)
from flywheel.render.blocks import sentence
from flywheel.render.duty_cycle import summary_tables

T = words("report_duty_cycle", {
    "title": "Flywheel of a machine that works in operations", "source": "Source",
    "method": "1. Method",
    "method_note": ("One operation takes the energy E in the time t_op of each cycle T_c; the "
                    "motor gives the constant torque M_D (power P) and the flywheel the rest, "
                    "ΔE; its speed falls from ω_max to ω_min during the operation and the motor "
                    "brings it back before the next one."),
    # the symbols of the formulas, a line each (ГОСТ 7.32-2017, 6.8.2)
    "where": ("where E is the work of one operation, {top} its time, P the motor's power and "
              "{MD} its torque;\n"
              "J the flywheel's moment of inertia, m its mass, k its radius of gyration, v the "
              "speed at the radius k;\n"
              "ω_max, ω_min the shaft's angular velocities at the start and the end of the "
              "operation, ω_m their mean, δ the coefficient of speed fluctuation;\n"
              "{trec} the time in which the motor brings the speed back"),
    "where_rim": (";\n{D} the rim's mean diameter, {k} its share of J, {m} its mass, R its mean "
                  "radius, ρ the density, b, t the rim's width and thickness, σ its hoop stress"),
    "results": "2. Solution", "checks": "3. Checks", "warn": "Warnings", "sources": "Sources",
    "case_source": "Input data: {s}.",
    "book": ("Khurmi R. S., Gupta J. K. Theory of Machines, ch. 16: Turning Moment Diagrams "
             "and Flywheel, the section \"Flywheel in Punching Press\" (Ex. 16.19–16.23)."),
})


def build_duty_cycle_document(r, title: str, source: str, lang: str = "en") -> Document:
    """The записка of one duty-cycle result."""
    t = T[lang]
    doc = Document.titled(t["title"], title, source, t["source"], lang)
    add, table = doc.blocks.append, doc.add_table
    add(Heading(2, t["method"]))
    add(Paragraph(t["method_note"]))
    MD = r"M_{\text{Д}}" if lang == "ru" else r"M_{D}"
    top = r"t_{\text{оп}}" if lang == "ru" else r"t_{op}"
    wm = r"\omega_{\text{ср}}" if lang == "ru" else r"\omega_{m}"
    add(Formula(rf"\Delta E = E - P {top}, P = {MD} {wm}"))
    n_J = doc.add_formula(
        rf"\Delta E = \frac{{J (\omega_{{max}}^{{2}} - \omega_{{min}}^{{2}})}}{{2}} = "
        rf"J {wm}^{{2}} \delta, \delta = \frac{{\omega_{{max}} - \omega_{{min}}}}{{{wm}}}")
    n_m = doc.add_formula(r"J = m k^{2}, \Delta E = m v^{2} \delta")
    add(Formula(rf"t_{{\text{{{'вос' if lang == 'ru' else 'rec'}}}}} = \frac{{\Delta E}}{{P}}"))
    if r.rim is not None:             # [flywheel.rim]: Khurmi & Gupta ch. 16, the rim's dimensions
        k, m, D = ((r"k_{\text{об}}", r"m_{\text{об}}", r"D_{\text{ср}}") if lang == "ru"
                   else (r"k_{rim}", r"m_{rim}", r"D_{m}"))
        add(Formula(rf"{D} = \frac{{2 v}}{{{wm}}}, {m} = \frac{{{k} J}}{{R^{{2}}}} = "
                    rf"\rho \pi {D} b t, \sigma = \rho v^{{2}}"))
    sym = lambda key: nm.symbol(key, lang)        # noqa: E731  (the one nomenclature's)
    add(Where(t["where"].format(MD=sym("motor_torque"), top=sym("operation_time"),
                                trec=sym("recovery_time"))
              + (t["where_rim"].format(D=sym("D_mean"), k=sym("share"),
                                       m=sym("rim_mass_designed")) if r.rim is not None else "")
              + "."))

    add(Heading(2, t["results"]))
    for caption, header, rows, note, _ in summary_tables(r, lang):
        if rows:
            table(caption, header, rows)
        if note:                      # a line of the terminal: a sentence here
            add(Paragraph(sentence(note)))
    # a flywheel found from the speeds: J and m worked with six digits of the numbers the
    # tables print (numbers.fmt_worked); a given flywheel's speeds are found the other way,
    # and its J is the case's
    if not r.flywheel_given and None not in (r.J, r.omega_mean, r.delta):
        n6 = fmt_worked
        kg = rf"\,\text{{{nm.unit('kg·m²', lang)}}}"
        mass = r.mass is not None and r.radius is not None
        add(Paragraph(put_into(lang, n_J, n_m) if mass else put_into(lang, n_J)))
        add(Formula(rf"J = \frac{{\Delta E}}{{{wm}^{{2}} \delta}} = \frac{{{n6(r.delta_E)}}}"
                    rf"{{{n6(r.omega_mean)}^{{2}} \cdot {n6(r.delta)}}} = {n6(r.J)}{kg}"))
        if mass:
            add(Formula(rf"m = \frac{{J}}{{k^{{2}}}} = \frac{{{n6(r.J)}}}{{{n6(r.radius)}^{{2}}}} = "
                        rf"{n6(r.mass)}\,\text{{{nm.unit('kg', lang)}}}"))
    if r.checks:
        from flywheel.render.duty_cycle import L10N

        add(Heading(2, t["checks"]))
        L = L10N[lang]
        table(L["checks"], (L["quantity"], L["value"], L["unit"]),
              [(nm.name(k, lang), _number(v, spec=".1e", zero=None, nonfinite="show"),
                nm.unit_of(k, lang)) for k, v in r.checks])
    if r.warnings:
        add(Heading(2, t["warn"]))
        add(Bullets(tuple(nm.message(w, lang) for w in r.warnings)))
    add(Heading(2, t["sources"]))
    src = ([t["case_source"].format(s=source)] if source else []) + [t["book"]]
    add(Bullets(tuple(f"[{i}] {x}" for i, x in enumerate(src, 1))))
    return doc
