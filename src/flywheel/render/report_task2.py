"""The записка of `flywheel task2 --out DIR`: a textbook solution of «Задача 2» (steady motion of
a machine with constant reduced inertia under given moment graphs) as a document model
(render/document.py), written as report.md/.html/.pdf/.docx like the one of `flywheel run`.

Sections: the given data (the constants and the moment graphs at their breakpoints), the method
with its formulas, the segment table, the results, the motion (ε, phases, time), the figure
with its caption, the sources. Nothing is computed here: every number is a field of the
:class:`~flywheel.constant_inertia.solve.Task2Result` (the graphs are only read at their
breakpoints). Labels come from the nomenclature (render/nomenclature.py); this module keeps
the section titles and the sentences.
Source of the method: the textbook task «Задача 2» (½·J·(ω² − ω0²) = ∫(M_Д − M_С)dφ,
δ = (ω_max − ω_min)/ω_ср, J = ΔT_нб/(δ·ω_ср²)); Артоболевский И. И., «Теория механизмов и
машин», ch. 16–17.
"""
from __future__ import annotations

import math

from flywheel.render.blocks import referenced, sentence
from flywheel.render.catalogue import words
from flywheel.render.document import (T as RECORD, Bullets, Document, Figure, Formula, Heading,
                                      Paragraph, Where, put_into)
from flywheel.render.nomenclature import name as text, symbol, unit
from flywheel.render.numbers import fmt as _number, fmt_worked

FIGURE = "task2.png"

T = words("report_task2", {
    "title": "Steady motion with constant reduced inertia", "source": "Source",
    "given": "1. Given data", "given_caption": "Given data",
    "graphs_caption": "Moment graphs at their breakpoints (values just after the angle)",
    "areas_caption": "Work of the moments between the crossings (area diagram)",
    "method": "2. Method",
    "method_note": ("The reduced inertia J is constant, so the kinetic energy theorem over "
                    "the angle φ gives the speed directly; the extremes of ω lie where "
                    "M_D = M_C, and the cycle is steady when ∮(M_D − M_C)dφ = 0."),
    # the symbols of the method's formulas, a line each (ГОСТ 7.32-2017, 6.8.2)
    "where": ("where {MD}, {MC} are the reduced driving and resistance moments;\n"
              "{J} the reduced moment of inertia (constant), ω₀ the angular velocity at φ = 0;\n"
              "ω_max, ω_min the greatest and least angular velocities over the cycle, {wm} "
              "their mean;\n"
              "{dT} the largest change of kinetic energy, δ the coefficient of speed "
              "fluctuation"),
    "where_time": ";\nε the angular acceleration, t the time from φ = 0",
    "solution": "3. Solution", "segments_caption": "Segments: works and speeds at the breakpoints and crossings",
    "results_caption": "Results",
    "motion": "4. Acceleration, phases and time", "motion_caption": "Acceleration and cycle time",
    "phases_caption": "Phases between the extremes of ω",
    "at_caption": "The motion at the asked angles",
    "figure": "Moments M_D, M_C, work A, speed ω(φ) and acceleration ε(φ)",
    "figure_areas": "Energy and speed at the crossings",
    "sources": "Sources", "case_source": "Input data: {s}.",
    "book": ("Artobolevsky I. I. Teoriya mekhanizmov i mashin (Theory of Mechanisms and "
             "Machines). 4th ed. Moscow: Nauka, 1988: ch. 16–17 (reduction, speed "
             "fluctuation, the flywheel)."),
    "given_J": "reduced moment of inertia", "given_w0": "speed at φ = 0",
    "given_cycle": "cycle", "given_MD": "driving moment {kind}",
    "given_MC": "resistance moment {kind}", "found": "found from the cycle balance",
    "given_delta": "asked coefficient of speed fluctuation",
    "given_R": "mean radius of the rim", "given_k": "radius of gyration",
    "steady_no": ("The motion is not steady: the work over the cycle is {work} J, ω after "
                  "one cycle {omega_end} rad/s."),
    "quantity": "quantity", "symbol": "symbol", "value": "value", "unit": "unit",
    "case_caption": "The data as the task states them",
})

#: the sections of a task-2 case file whose numbers the record lists as given
CASE_SECTIONS = ("speed", "flywheel", "diagram", "power")

KINDS = words("report_task2_kinds", {"constant": "(constant)", "triangle": "(triangle, peak)",
                                     "rectangle": "(rectangle)", "points": "(largest ordinate)",
                                     "series": "(a0)"})


def g(x, fmt: str = ".6g") -> str:
    """A number as the report prints it (−0 → 0; None or NaN → "—")."""
    return _number(x, spec=fmt, zero=1e-12, nonfinite="dash")


def _deg(phi) -> str:
    return "—" if phi is None or math.isnan(phi) else g(math.degrees(phi))


def _case_rows(case, lang: str, listed: set = frozenset()) -> list[list[str]]:
    """The numbers a task-2 case file gives in :data:`CASE_SECTIONS` but those at the paths
    ``listed``, each by its label as a task sheet words it (render/sheet_labels.py) with the
    digits it was given; a list's numbers set apart as the language sets them («295; −685»)."""
    from flywheel.cases.describe import unit_of_path
    from flywheel.render.numbers import separator
    from flywheel.render.sheet_labels import field_label

    data = case.model_dump(exclude_unset=True, exclude_none=True)
    rows = []

    def walk(node, path: str) -> None:
        if isinstance(node, dict):
            for k, v in node.items():
                walk(v, f"{path}.{k}" if path else k)
        elif isinstance(node, (int, float)) and not isinstance(node, bool) or (
                isinstance(node, list) and node and all(isinstance(x, (int, float)) for x in node)):
            if path in listed:
                return
            values = node if isinstance(node, list) else [node]
            rows.append([field_label(path, lang, kinds=("task2",)),
                         separator(lang).join(_number(float(x), 6, given=True) for x in values),
                         unit(unit_of_path("task2", path), lang)])

    for section in CASE_SECTIONS:
        if section in data:
            walk(data[section], section)
    return rows


def _sub(base: str, en: str, ru: str, lang: str) -> str:
    """A symbol with a subscript in the formula notation (render/mathfmt.py)."""
    return rf"{base}_{{\text{{{ru if lang == 'ru' else en}}}}}"


def build_task2_document(r, title: str, source: str, lang: str = "en",
                         figure: str | None = FIGURE, case=None) -> Document:
    """The записка of one task-2 result; ``figure`` the plot's name under plots/ (None: none);
    ``case`` the task-2 case file it solves (cases/task2.Task2Case; None: the options), whose
    numbers are listed as the problem gives them (a mean speed in rpm, a flywheel's mass and
    radius of gyration, a diagram's areas and scales)."""
    t = T[lang]

    def U(u: str) -> str:
        return unit(u, lang)

    doc = Document.titled(t["title"], title, source, t["source"], lang)
    add, table = doc.blocks.append, doc.add_table

    # 1. given data ---------------------------------------------------------------------------
    add(Heading(2, t["given"]))
    MD, MC = symbol("t2_M_D", lang), symbol("t2_M_C", lang)
    rows = [[t["given_J"], symbol("t2_J", lang), g(r.J), U("kg·m²")],
            [t["given_w0"], "ω₀", g(r.omega0), U("rad/s")],
            [t["given_cycle"], "Φ", g(math.degrees(r.cycle)), U("deg")]]
    for sym, graph, kind_key, found in ((MD, r.driving, "given_MD", r.unknown == "driving"),
                                        (MC, r.resistance, "given_MC", r.unknown == "resistance")):
        nominal = r.M_D if sym == MD else r.M_C
        if graph is None and nominal is None:
            continue
        kind = KINDS[lang].get(graph.kind, "") if graph is not None else ""
        rows.append([t[kind_key].format(kind=kind).strip(), sym,
                     t["found"] if found else g(nominal), "" if found else U("N·m")])
    listed = {"flywheel.J", "speed.omega0"}      # the case's fields table 1 states as they are
    for path, key, sym, value, u in (("flywheel.delta", "given_delta", "δ", r.delta_target, ""),
                                     ("flywheel.rim_radius", "given_R", "R", r.rim_radius, "m"),
                                     ("flywheel.radius_of_gyration", "given_k", "k",
                                      r.radius_of_gyration, "m")):
        if value is not None:
            rows.append([t[key], sym, g(value), U(u) if u else ""])
            listed.add(path)
    table(t["given_caption"], [t["quantity"], t["symbol"], t["value"], t["unit"]], rows)
    if case is not None:           # what table 1 does not list already, as the case gives it
        given = _case_rows(case, lang, listed)
        if given:
            table(t["case_caption"], [t["quantity"], t["value"], t["unit"]], given)
    if r.driving is not None and r.resistance is not None:
        cuts = sorted({round(p, 12) for m in (r.driving, r.resistance) for p in m.breakpoints()})
        scale = 1e-9 * max(abs(r.driving.nominal), abs(r.resistance.nominal), 1.0)

        def m(graph, p):       # the rounding of a breakpoint is no value of its own
            v = graph.value(p)
            return g(0.0 if abs(v) < scale else v)

        table(t["graphs_caption"], [f"φ, {U('deg')}", f"{MD}, {U('N·m')}", f"{MC}, {U('N·m')}"],
              [[g(math.degrees(p)), m(r.driving, p), m(r.resistance, p)] for p in cuts])

    # 2. method -------------------------------------------------------------------------------
    add(Heading(2, t["method"]))
    add(Paragraph(t["method_note"]))
    md, mc = _sub("M", "D", "Д", lang), _sub("M", "C", "С", lang)
    J = _sub("J", "", "пр", lang) if lang == "ru" else "J"
    wm, dT = _sub(r"\omega", "m", "ср", lang), _sub(r"\Delta T", "max", "нб", lang)
    add(Formula(rf"A(\varphi) = \int_{{0}}^{{\varphi}} ({md} - {mc}) d\varphi = "
                rf"\frac{{{J} (\omega^{{2}} - \omega_{{0}}^{{2}})}}{{2}}"))
    add(Formula(rf"\omega(\varphi) = \sqrt{{\omega_{{0}}^{{2}} + \frac{{2A(\varphi)}}{{{J}}}}}"))
    n_speed = doc.add_formula(rf"{wm} = \frac{{\omega_{{max}} + \omega_{{min}}}}{{2}}, "
                              rf"\delta = \frac{{\omega_{{max}} - \omega_{{min}}}}{{{wm}}}, "
                              rf"{dT} = A_{{max}} - A_{{min}}")
    if r.driving is not None:
        add(Formula(rf"\varepsilon(\varphi) = \frac{{{md} - {mc}}}{{{J}}}, "
                    rf"t(\varphi) = \int_{{0}}^{{\varphi}} \frac{{d\varphi}}{{\omega}}"))
    n_J = None
    if r.J_required is not None:
        n_J = doc.add_formula(rf"{J} = \frac{{{dT}}}{{\delta {wm}^{{2}}}}")
    add(Where(t["where"].format(MD=symbol("t2_M_D", lang), MC=symbol("t2_M_C", lang),
                                J=symbol("t2_J", lang), wm=symbol("t2_omega_mean", lang),
                                dT=symbol("t2_delta_T_max", lang))
              + (t["where_time"] if r.driving is not None else "") + "."))

    # 3. solution -----------------------------------------------------------------------------
    add(Heading(2, t["solution"]))
    if r.unknown:
        name = symbol({"resistance": "t2_M_C", "driving": "t2_M_D"}[r.unknown], lang)
        val = r.M_C if r.unknown == "resistance" else r.M_D
        add(Paragraph(sentence(text("t2_balance", lang, name=name, value=g(val),
                                     work=g(r.work_driving)))))
    if r.power_found is not None and r.power is not None:
        name = symbol("t2_M_D" if r.power_found == "driving" else "t2_M_C", lang)
        add(Paragraph(sentence(text("t2_power", lang, P=g(r.power), name=name,
                                     T=g(r.power / r.omega_mean)))))
    if not r.steady:
        add(Paragraph(t["steady_no"].format(work=g(r.work_end), omega_end=g(r.omega_end, ".6f"))))
    table(t["segments_caption"],
          [RECORD[lang]["no"], f"φ, {U('deg')}", "φ/π", text("point", lang), f"{MD}, {U('N·m')}",
           f"{MC}, {U('N·m')}", f"A, {U('J')}", f"ω, {U('rad/s')}"],
          [[str(i), _deg(row.phi), "—" if math.isnan(row.phi) else g(row.phi / math.pi),
            text("crossing_MD_MC", lang) if row.kind == "crossing" and row.M_D is not None
            else text("crossing" if row.kind == "crossing" else "bound", lang),
            g(row.M_D), g(row.M_C), g(row.A), g(row.omega, ".6f")] for i, row in enumerate(r.rows)])
    res = [[text("omega_max", lang), g(r.omega_max, ".6f"), U("rad/s"), _deg(r.phi_omega_max)],
           [text("omega_min", lang), g(r.omega_min, ".6f"), U("rad/s"), _deg(r.phi_omega_min)],
           [text("t2_omega_mean", lang), g(r.omega_mean, ".6f"), U("rad/s"), ""],
           [text("t2_delta", lang), g(r.delta), "", ""],
           [text("t2_delta_T_max", lang), g(r.delta_T_max), U("J"), ""]]
    if r.power is not None:
        res.append([text("t2_P", lang), g(r.power), U("W"), ""])
    if r.J_required is not None:
        res.append([text("t2_J_required", lang, delta=g(r.delta_target)), g(r.J_required),
                    U("kg·m²"), ""])
    if r.rim_mass is not None:
        res.append([text("rim_mass", lang, R=g(r.rim_radius)), g(r.rim_mass), U("kg"), ""])
    if r.flywheel_mass is not None:
        res.append([text("t2_flywheel_mass", lang, k=g(r.radius_of_gyration)), g(r.flywheel_mass),
                    U("kg"), ""])
    if r.energy_fluctuation_coefficient is not None:
        res.append([text("t2_energy_fluctuation_coefficient", lang),
                    g(r.energy_fluctuation_coefficient), "", ""])
    table(t["results_caption"], [t["quantity"], t["value"], t["unit"], f"φ, {U('deg')}"], res)
    # the numbers put in are those printed above, so a teacher checks each with a calculator
    w_max, w_min, w_m = (g(w, ".6f") for w in (r.omega_max, r.omega_min, r.omega_mean))
    add(Paragraph(put_into(lang, n_speed) if n_J is None else put_into(lang, n_speed, n_J)))
    add(Formula(rf"{wm} = \frac{{{w_max} + {w_min}}}{{2}} = {w_m}\,\text{{{U('rad/s')}}}"))
    add(Formula(rf"\delta = \frac{{{w_max} - {w_min}}}{{{w_m}}} = {g(r.delta)}"))
    if n_J is not None:
        add(Formula(rf"{J} = \frac{{{fmt_worked(r.delta_T_max)}}}{{{g(r.delta_target)} \cdot "
                    rf"{fmt_worked(r.omega_mean)}^{{2}}}} = {g(r.J_required)}\,\text{{{U('kg·m²')}}}"))

    # 4. motion -------------------------------------------------------------------------------
    if r.driving is not None:
        add(Heading(2, t["motion"]))
        table(t["motion_caption"], [t["quantity"], t["value"], t["unit"], f"φ, {U('deg')}"],
              [[text("t2_epsilon_max", lang), g(r.epsilon_max), U("rad/s²"), _deg(r.phi_epsilon_max)],
               [text("t2_epsilon_min", lang), g(r.epsilon_min), U("rad/s²"), _deg(r.phi_epsilon_min)],
               [text("t2_cycle_time", lang), g(r.cycle_time), U("s"), ""]])
        if r.phases:
            table(t["phases_caption"],
                  [RECORD[lang]["no"], f"φ₁, {U('deg')}", f"φ₂, {U('deg')}", text("trend", lang),
                   f"t, {U('s')}", f"Δt, {U('s')}"],
                  [[str(i), _deg(p.phi_start), _deg(p.phi_end), text(f"trend_{p.trend}", lang),
                    g(p.t_start), g(p.duration)] for i, p in enumerate(r.phases)])
        if r.at:
            table(t["at_caption"], [f"φ, {U('deg')}", f"ω, {U('rad/s')}", f"ε, {U('rad/s²')}",
                                    f"t, {U('s')}"],
                  [[_deg(a.phi), g(a.omega, ".6f"), g(a.epsilon), g(a.t)] for a in r.at])
    if figure:
        add(Figure(1, t["figure"] if r.driving is not None else t["figure_areas"], figure))

    add(Heading(2, t["sources"]))
    src = ([t["case_source"].format(s=source)] if source else []) + [t["book"]]
    add(Bullets(tuple(f"[{i}] {x}" for i, x in enumerate(src, 1))))
    doc.blocks[:] = referenced(doc.blocks, lang)         # every table and figure cited
    return doc
