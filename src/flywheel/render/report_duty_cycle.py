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
    # a given flywheel: its other speeds from the given one by (2) (Khurmi & Gupta, Ex. 16.21)
    n_w = (doc.add_formula(_SPEEDS_FROM_J[r.speed_given].replace("WM", wm))
           if _worked_speeds(r) else None)
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
    if n_w is not None:
        _work_speeds(doc, r, lang, n_m, n_w, wm)
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


#: a given flywheel's other speeds from its given one ("WM": ω_ср in the record's language),
#: formula (2) solved for them: ½·J·(ω_max² − ω_min²) = ΔE, ΔE = J·ω_ср²·δ
_SPEEDS_FROM_J = {
    "max": r"\omega_{min} = \sqrt{\omega_{max}^{2} - \frac{2 \Delta E}{J}}",
    "min": r"\omega_{max} = \sqrt{\omega_{min}^{2} + \frac{2 \Delta E}{J}}",
    "mean": (r"\delta = \frac{\Delta E}{J WM^{2}}, \omega_{max} = WM \left(1 + "
             r"\frac{\delta}{2}\right), \omega_{min} = WM \left(1 - \frac{\delta}{2}\right)"),
}


def _worked_speeds(r) -> bool:
    """Whether the record works a given flywheel's speeds with numbers: a flywheel given with
    the shaft's speed (not speeds at the radius) that gives some energy."""
    return (r.flywheel_given and r.speed_given in _SPEEDS_FROM_J and r.J
            and None not in (r.omega_max, r.omega_min, r.omega_mean) and r.delta_E > 0)


def _work_speeds(doc: Document, r, lang: str, n_m: int, n_w: int, wm: str) -> None:
    """A given flywheel's J = m·k² (where its mass and radius are known) and its other speeds
    from the given one (formula ``n_w``), each with six digits of the numbers the tables print
    (numbers.fmt_worked): Khurmi & Gupta, Ex. 16.21, ω_min = √(ω_max² − 2·ΔE/J)."""
    n6, add = fmt_worked, doc.blocks.append
    rad = rf"\,\text{{{nm.unit('rad/s', lang)}}}"
    rpm = rf"\,\text{{{nm.unit('rpm', lang)}}}"
    mass = r.mass is not None and r.radius is not None
    add(Paragraph(put_into(lang, n_m, n_w) if mass else put_into(lang, n_w)))
    if mass:
        add(Formula(rf"J = m k^{{2}} = {n6(r.mass)} \cdot {n6(r.radius)}^{{2}} = {n6(r.J)}"
                    rf"\,\text{{{nm.unit('kg·m²', lang)}}}"))
    w1, w2, wmean, dE, J = (n6(x) for x in (r.omega_max, r.omega_min, r.omega_mean, r.delta_E, r.J))
    n = (r"n_{max}", r"\omega_{max}", r.rpm_max) if r.speed_given == "min" else (
        r"n_{min}", r"\omega_{min}", r.rpm_min)
    in_rpm = rf"{n[0]} = \frac{{30 {n[1]}}}{{\pi}} = {n6(n[2])}{rpm}"
    if r.speed_given == "max":
        add(Formula(rf"\omega_{{min}} = \sqrt{{{w1}^{{2}} - \frac{{2 \cdot {dE}}}{{{J}}}}} = "
                    rf"{w2}{rad}"))
        add(Formula(in_rpm))
    elif r.speed_given == "min":
        add(Formula(rf"\omega_{{max}} = \sqrt{{{w2}^{{2}} + \frac{{2 \cdot {dE}}}{{{J}}}}} = "
                    rf"{w1}{rad}"))
        add(Formula(in_rpm))
    else:
        add(Formula(rf"\delta = \frac{{{dE}}}{{{J} \cdot {wmean}^{{2}}}} = {n6(r.delta)}, "
                    rf"\omega_{{max}} = {w1}{rad}, \omega_{{min}} = {w2}{rad}"))
