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
from flywheel.render.blocks import referenced, sentence
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
    n_E = doc.add_formula(rf"\Delta E = E - P {top}, P = {MD} {wm}")
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
    _work(doc, r, lang, {"E": n_E, "J": n_J, "m": n_m, "w": n_w}, wm, top)
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
    doc.blocks[:] = referenced(doc.blocks, lang)         # every table and figure cited
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


def _work(doc: Document, r, lang: str, n: dict, wm: str, top: str) -> None:
    """The record's results worked with the numbers the tables print, six digits each
    (numbers.fmt_worked), citing the method's formulas ``n`` (by "E", "J", "m", "w"): the
    energy the flywheel gives, ΔE = E − P·t_оп; a flywheel found from its speeds, J =
    ΔE/(ω_ср²·δ) and m = J/k² (Khurmi & Gupta Ex. 16.19: m = 617,94 кг, printed 618 kg), or
    from the speeds at its radius, m = ΔE/(v_ср²·δ) (Ex. 16.20: 1198 кг); a given one, J =
    m·k² and its other speed from the given one (Ex. 16.21: ω_min = √(ω_max² − 2·ΔE/J),
    n_min = 257,6 об/мин). Nothing where the case gives too little to work them."""
    n6, out, cited = fmt_worked, [], []

    def unit(u: str) -> str:
        return rf"\,\text{{{nm.unit(u, lang)}}}"

    if r.energy and r.delta_E > 0 and None not in (r.motor_power, r.operation_time):
        cited.append(n["E"])
        out.append(rf"\Delta E = E - P {top} = {n6(r.energy)} - {n6(r.motor_power)} \cdot "
                   rf"{n6(r.operation_time)} = {n6(r.delta_E)}{unit('J')}")
    mass = r.mass is not None and r.radius is not None
    if not r.flywheel_given and r.delta_E > 0 and None not in (r.J, r.omega_mean):
        cited += [n["J"]] + ([n["m"]] if mass else [])
        out.append(rf"J = \frac{{\Delta E}}{{{wm}^{{2}} \delta}} = \frac{{{n6(r.delta_E)}}}"
                   rf"{{{n6(r.omega_mean)}^{{2}} \cdot {n6(r.delta)}}} = {n6(r.J)}{unit('kg·m²')}")
        if mass:
            out.append(rf"m = \frac{{J}}{{k^{{2}}}} = \frac{{{n6(r.J)}}}{{{n6(r.radius)}^{{2}}}} = "
                       rf"{n6(r.mass)}{unit('kg')}")
    elif (not r.flywheel_given and r.delta_E > 0 and r.omega_mean is None
          and None not in (r.mass, r.rim_speed_mean)):      # speeds at the radius (m/s)
        cited.append(n["m"])
        vm = r"v_{\text{ср}}" if lang == "ru" else r"v_{m}"
        out.append(rf"m = \frac{{\Delta E}}{{{vm}^{{2}} \delta}} = \frac{{{n6(r.delta_E)}}}"
                   rf"{{{n6(r.rim_speed_mean)}^{{2}} \cdot {n6(r.delta)}}} = {n6(r.mass)}{unit('kg')}")
    if n["w"] is not None:
        if mass:
            cited.append(n["m"])
            out.append(rf"J = m k^{{2}} = {n6(r.mass)} \cdot {n6(r.radius)}^{{2}} = {n6(r.J)}"
                       rf"{unit('kg·m²')}")
        cited.append(n["w"])
        out += _speeds_worked(r, unit)
    if out:
        doc.blocks.append(Paragraph(put_into(lang, *cited)))
        doc.blocks.extend(Formula(f) for f in out)


def _speeds_worked(r, unit) -> list[str]:
    """A given flywheel's other speed from the given one (formula :data:`_SPEEDS_FROM_J`), and
    in rev/min."""
    n6 = fmt_worked
    w1, w2, wmean, dE, J = (n6(x) for x in (r.omega_max, r.omega_min, r.omega_mean, r.delta_E, r.J))
    rad = unit("rad/s")
    n = (r"n_{max}", r"\omega_{max}", r.rpm_max) if r.speed_given == "min" else (
        r"n_{min}", r"\omega_{min}", r.rpm_min)
    in_rpm = rf"{n[0]} = \frac{{30 {n[1]}}}{{\pi}} = {n6(n[2])}{unit('rpm')}"
    if r.speed_given == "max":
        return [rf"\omega_{{min}} = \sqrt{{{w1}^{{2}} - \frac{{2 \cdot {dE}}}{{{J}}}}} = {w2}{rad}",
                in_rpm]
    if r.speed_given == "min":
        return [rf"\omega_{{max}} = \sqrt{{{w2}^{{2}} + \frac{{2 \cdot {dE}}}{{{J}}}}} = {w1}{rad}",
                in_rpm]
    return [rf"\delta = \frac{{{dE}}}{{{J} \cdot {wmean}^{{2}}}} = {n6(r.delta)}, "
            rf"\omega_{{max}} = {w1}{rad}, \omega_{{min}} = {w2}{rad}"]
