"""Printable task sheets of ``flywheel variants … --sheets`` (docs/teacher.md): one A4 page per
variant — the drawing, «Дано» (the variant's data with units), «Определить» (the answers asked,
with units and the grader's tolerance) and the student's name line — as HTML and PDF through
the записка's path (a :class:`~flywheel.render.document.Document` written by
render/report_formats.py: Jinja2 for HTML, typst for PDF).

What goes on a sheet is teaching/sheets.py's (:class:`~flywheel.teaching.sheets.Sheet`); this
module only words, draws and typesets it. No answer and no solving hint is printed. Quantities
of the results (the find-list's symbols and units) come from render/nomenclature.py; the input
fields of a case file have no entry there, so their labels are the sentence templates of
:data:`FIELDS` below.
"""
from __future__ import annotations

import re
import tempfile
from pathlib import Path

from flywheel.render import nomenclature as nm
from flywheel.render.document import Document, Figure, Heading, Paragraph, Table

FORMATS = ("both", "html", "pdf")
#: the sheet's own print style, after the записка's: the drawing small enough for one A4 page
_CSS = ("figure img { max-height: 68mm; width: auto; } "
        "@media print { body { font-size: 9.5pt; } table { font-size: 0.8em; } "
        "td, th { padding: 0.05em 0.35em; } } td:nth-child(2) { white-space: normal; }")
#: the combined file of all sheets, one per page, for printing the class set
COMBINED = "sheets.pdf"
FOLDER = "sheets"

WORDS = {
    "en": {"variant": "Variant {n}", "student": "Student ______________________________"
           "        Group ____________", "given": "Given", "drawn": "Data of the variant",
           "fixed": "Other data", "find": "Determine", "quantity": "Quantity",
           "value": "Value", "unit": "Unit",
           "item": "Determine {what}{sym}{unit}; accepted within ±{tol} %.",
           "scheme": "Kinematic scheme of the mechanism at φ = {a:g}°",
           "moments": "The given moment graphs {MD}(φ) and {MC}(φ)",
           "unknown": "{M} = ? (from the cycle balance)"},
    "ru": {"variant": "Вариант {n}", "student": "Студент ______________________________"
           "        Группа ____________", "given": "Дано", "drawn": "Данные варианта",
           "fixed": "Прочие данные", "find": "Определить", "quantity": "Величина",
           "value": "Значение", "unit": "Ед. изм.",
           "item": "{What}{sym}{unit} (допуск ±{tol} %).",
           "scheme": "Кинематическая схема механизма при φ = {a:g}°",
           "moments": "Заданные графики моментов {MD}(φ) и {MC}(φ)",
           "unknown": "{M} = ? (из условия установившегося движения)"},
}

#: input fields of a case file: a dotted-path pattern (``#`` an array index, ``*`` a name) →
#: (English, Russian) label; ``{x}`` is the element's name (a link, a cylinder, a point);
#: "@key" takes the name of a quantity the nomenclature has
FIELDS: list[tuple[str, str, str]] = [
    ("machine.speed_rps", "@crank_speed", ""),          # "@key": the nomenclature's name
    ("machine.speed_rpm", "@crank_speed", ""),
    ("machine.delta", "coefficient of speed fluctuation δ", "коэффициент неравномерности хода δ"),
    ("machine.gravity", "gravity g (x, y)", "ускорение свободного падения g (x, y)"),
    ("machine.cycle_deg", "cycle Φ", "цикл Φ"),
    ("machine.first_group.*", "J of the {x} (reduced to the crank)",
     "момент инерции: {x} (приведён к кривошипу)"),
    ("design.mean_piston_speed", "mean piston speed V_m", "средняя скорость поршня V_ср"),
    ("design.rod_to_crank", "rod to crank length ratio k", "отношение длин шатуна и кривошипа k"),
    ("crank.length", "@crank_length", ""),
    ("crank.pivot_at", "crank pivot (x, y)", "координаты опоры кривошипа (x, y)"),
    ("crank.start_angle_deg", "crank angle at φ = 0, from +x",
     "положение кривошипа при φ = 0 (от оси x)"),
    ("dyads.#.rod_length", "rod length, joint {x}", "длина шатуна, шарнир {x}"),
    ("dyads.#.length_from", "first link length, joint {x}", "длина первого звена, шарнир {x}"),
    ("dyads.#.length_to", "second link length, joint {x}", "длина второго звена, шарнир {x}"),
    ("dyads.#.offset", "slide line offset, joint {x}", "смещение линии ползуна, шарнир {x}"),
    ("dyads.#.guide.through", "guide of {x}: a point (x, y)", "направляющая {x}: точка (x, y)"),
    ("dyads.#.guide.angle_deg", "guide of {x}: angle from +x", "направляющая {x}: угол к оси x"),
    ("dyads.#.guide.offset", "guide of {x}: offset", "направляющая {x}: смещение"),
    ("points.*.fraction", "point {x}: share of its link's length",
     "точка {x}: доля длины звена"),
    ("points.*.distance", "point {x}: distance along its link", "точка {x}: расстояние по звену"),
    ("points.*.across", "point {x}: offset across its link", "точка {x}: смещение поперёк звена"),
    ("links.*.mass", "mass of link {x} m_{x}", "масса звена {x} m_{x}"),
    ("links.*.J_S", "moment of inertia of link {x} about its centroid J_S{x}",
     "момент инерции звена {x} относительно центра масс J_S{x}"),
    ("cylinders.#.bore", "bore of cylinder {x} d", "диаметр цилиндра {x} d"),
    ("cylinders.#.p_max", "maximum pressure in cylinder {x} p_max",
     "максимальное давление в цилиндре {x} p_max"),
    ("cylinders.#.s", "cylinder {x}: relative piston travel s",
     "цилиндр {x}: относительное перемещение поршня s"),
    ("cylinders.#.towards_head", "cylinder {x}: p/p_max, piston moving to the head",
     "цилиндр {x}: p/p_max при движении поршня к головке"),
    ("cylinders.#.away_from_head", "cylinder {x}: p/p_max, piston moving from the head",
     "цилиндр {x}: p/p_max при движении поршня от головки"),
    ("forces.#.magnitude", "force {x}", "сила {x}"),
    ("forces.#.s_range", "force {x}: where it acts (relative travel)",
     "сила {x}: участок действия (отн. перемещение)"),
    ("flywheel.density", "density of the flywheel material ρ", "плотность материала маховика ρ"),
    ("flywheel.width_ratio", "flywheel width to diameter b/D",
     "отношение ширины маховика к диаметру b/D"),
    ("flywheel.inner_ratio", "rim inner to outer diameter D1/D",
     "отношение диаметров обода D₁/D"),
    ("flywheel.speed_ratio", "flywheel shaft speed ratio i", "передаточное отношение к валу маховика i"),
    # --- audit: engines (issue 13), a given flywheel and its rim (issues 13, 14) ---
    ("machine.power", "mean power P", "средняя мощность P"),
    ("crank.pins.#.angle_deg", "crank pin {x}: angle to the crank",
     "шатунная шейка {x}: угол к кривошипу"),
    ("crank.pins.#.length", "crank pin {x}: throw", "шатунная шейка {x}: радиус кривошипа"),
    ("ground.*", "fixed point {x} (x, y)", "неподвижная точка {x} (x, y)"),
    ("cylinders.#.fires_at_deg", "cylinder {x}: fires at φ", "цилиндр {x}: воспламенение при φ"),
    ("cylinders.#.strokes.intake", "cylinder {x}: p/p_max on the intake stroke",
     "цилиндр {x}: p/p_max на такте впуска"),
    ("cylinders.#.strokes.compression", "cylinder {x}: p/p_max on the compression stroke",
     "цилиндр {x}: p/p_max на такте сжатия"),
    ("cylinders.#.strokes.expansion", "cylinder {x}: p/p_max on the expansion stroke",
     "цилиндр {x}: p/p_max на такте расширения"),
    ("cylinders.#.strokes.exhaust", "cylinder {x}: p/p_max on the exhaust stroke",
     "цилиндр {x}: p/p_max на такте выпуска"),
    ("cylinders.#.diagram.s", "cylinder {x}: indicator diagram, travel s",
     "цилиндр {x}: индикаторная диаграмма, перемещение s"),
    ("cylinders.#.diagram.p", "cylinder {x}: indicator diagram, p/p_max",
     "цилиндр {x}: индикаторная диаграмма, p/p_max"),
    ("flywheel.mass", "flywheel mass m", "масса маховика m"),
    ("flywheel.radius_of_gyration", "radius of gyration of the flywheel k",
     "радиус инерции маховика k"),
    ("flywheel.allowable_stress", "allowable stress of the rim [σ]",
     "допускаемое напряжение обода [σ]"),
    ("flywheel.rim.share", "share of J carried by the rim", "доля J, приходящаяся на обод"),
    ("flywheel.rim.width_to_thickness", "rim width to thickness b/t",
     "отношение ширины обода к толщине b/t"),
    ("flywheel.rim.width", "rim width b", "ширина обода b"),
    ("flywheel.rim.speed", "rim speed v", "окружная скорость обода v"),
    # task2 («Задача 2»)
    ("cycle_deg", "cycle Φ", "цикл Φ"),
    ("speed.omega0", "angular velocity at φ = 0, ω0", "угловая скорость при φ = 0, ω₀"),
    ("speed.mean", "mean angular velocity ω_m", "средняя угловая скорость ω_ср"),
    ("flywheel.J", "reduced moment of inertia J", "приведённый момент инерции J_пр"),
    ("flywheel.delta", "coefficient of speed fluctuation asked δ",
     "заданный коэффициент неравномерности хода δ"),
    ("driving.value", "driving moment M_D", "движущий момент M_Д"),
    ("driving.peak", "driving moment M_D, peak", "движущий момент M_Д, наибольший"),
    ("resistance.value", "resistance moment M_C", "момент сопротивления M_С"),
    ("resistance.peak", "resistance moment M_C, peak", "момент сопротивления M_С, наибольший"),
    ("driving.from_deg", "M_D: start of its graph", "M_Д: начало участка"),
    ("driving.to_deg", "M_D: end of its graph", "M_Д: конец участка"),
    ("resistance.from_deg", "M_C: start of its graph", "M_С: начало участка"),
    ("resistance.to_deg", "M_C: end of its graph", "M_С: конец участка"),
    ("resistance.apex_deg", "M_C: angle of its peak", "M_С: угол вершины"),
    ("resistance.base", "M_C outside its graph", "M_С вне участка"),
    ("driving.base", "M_D outside its graph", "M_Д вне участка"),
    # --- audit: task2 fields of the bundled cases (issue 14) ---
    ("power", "mean power P", "средняя мощность P"),
    ("at_deg", "angles asked φ", "заданные углы φ"),
    ("speed.omega0_rpm", "speed at φ = 0, n0", "частота вращения при φ = 0, n₀"),
    ("speed.mean_rpm", "mean speed n_m", "средняя частота вращения n_ср"),
    ("speed.max_rpm", "greatest speed n_max", "наибольшая частота вращения n_max"),
    ("speed.min_rpm", "least speed n_min", "наименьшая частота вращения n_min"),
    ("flywheel.fluctuation_percent", "speed fluctuation ± % of the mean",
     "колебание скорости, ± % от средней"),
    ("flywheel.rim_radius", "rim radius R", "радиус обода R"),
    ("diagram.areas", "areas of the turning-moment diagram", "площади диаграммы моментов"),
    ("diagram.moment_scale", "diagram: moment scale", "диаграмма: масштаб моментов"),
    ("diagram.angle_scale_deg", "diagram: angle scale", "диаграмма: масштаб углов"),
    ("diagram.delta_E", "maximum fluctuation of energy ΔE", "наибольшее изменение энергии ΔE"),
    ("diagram.energy_fluctuation_coefficient", "coefficient of fluctuation of energy C_E",
     "коэффициент колебания энергии C_E"),
    ("diagram.work_per_cycle", "work per cycle A", "работа за цикл A"),
] + [entry for graph, en, ru in (("driving", "M_D", "M_Д"), ("resistance", "M_C", "M_С"))
     for entry in (
         (f"{graph}.points", f"{en}: points (φ, M)", f"{ru}: точки графика (φ, M)"),
         (f"{graph}.scale", f"{en}: scale of the graph", f"{ru}: масштаб графика"),
         (f"{graph}.a0", f"{en}: constant term a_0", f"{ru}: постоянная составляющая a_0"),
         (f"{graph}.a", f"{en}: sine coefficients a_k", f"{ru}: коэффициенты при sin kφ a_k"),
         (f"{graph}.b", f"{en}: cosine coefficients b_k", f"{ru}: коэффициенты при cos kφ b_k"),
         (f"{graph}.orders", f"{en}: harmonic orders k", f"{ru}: порядки гармоник k"),
         (f"{graph}.top_from_deg", f"{en}: start of the top", f"{ru}: начало верхнего участка"),
         (f"{graph}.top_to_deg", f"{en}: end of the top", f"{ru}: конец верхнего участка"))]

#: the answers as a task: key → (English, Russian) object of "Determine …" (the symbol and
#: the unit are the nomenclature's; "{kind}"-specific entries first)
ANSWERS: dict[str, tuple[str, str]] = {
    "run:J_required": ("the required moment of inertia of the first group",
                       "необходимый момент инерции первой группы звеньев"),
    "task2:J_required": ("the moment of inertia that gives the asked δ,",
                         "приведённый момент инерции, обеспечивающий заданный δ,"),
    "task2:delta": ("the coefficient of speed fluctuation", "коэффициент неравномерности хода"),
    "driving_moment": ("the driving moment that balances the cycle",
                       "приведённый движущий момент из условия цикла"),
    "delta_T_max": ("the largest fluctuation of kinetic energy",
                    "наибольшее изменение кинетической энергии"),
    "J_flywheel": ("the moment of inertia of the flywheel", "момент инерции маховика"),
    "flywheel_disk.D": ("the outer diameter of the flywheel as a solid disk",
                        "наружный диаметр маховика в виде сплошного диска"),
    "flywheel_disk.b": ("the width of the flywheel as a solid disk",
                        "ширину маховика в виде сплошного диска"),
    "flywheel_disk.mass": ("the mass of the flywheel as a solid disk",
                           "массу маховика в виде сплошного диска"),
    "flywheel_rim.D": ("the outer diameter of the flywheel's rim", "наружный диаметр обода маховика"),
    "flywheel_rim.mass": ("the mass of the flywheel's rim", "массу обода маховика"),
    "M_C": ("the resistance moment", "момент сопротивления"),
    "M_D": ("the driving moment", "движущий момент"),
    "omega_max": ("the greatest angular velocity", "наибольшую угловую скорость"),
    "omega_min": ("the least angular velocity", "наименьшую угловую скорость"),
    "omega_mean": ("the mean angular velocity", "среднюю угловую скорость"),
    "cycle_work_resistance": ("the work of the resistance over a cycle",
                              "работу сил сопротивления за цикл"),
    "balancing_moment": ("the constant moment that balances the cycle (with its sign)",
                         "постоянный момент из условия цикла (со знаком)"),
    "flywheel_J_on_its_shaft": ("the moment of inertia of the flywheel on its own shaft",
                                "момент инерции маховика на его валу"),
}
#: answers whose nomenclature symbol differs between the two kinds (J_I of a run, J_пр of task2)
_SYMBOLS = {"task2:J_required": ("J", "J_пр"), "task2:delta": ("δ", "δ")}

#: a subscript as marked in a sheet's text (private-use characters, which no number or word of
#: ours contains), typeset by :func:`sheet_html` (<sub>) and :func:`sheet_typst` (#sub[])
SUB = ("\ue000", "\ue001")
_SUB_RX = re.compile(r"(?:(?<!\w)|(?<=Δ))([^\W\d_])_([^\W_]+)")


def subscripts(text: str) -> str:
    """The symbols of ``text`` written with an underscore ("M_Д", "ΔT_нб", "p/p_max", "J_S2")
    with their subscripts marked for typesetting; an underscore inside a word (a case file's
    name like "crank_gear") is left as it is."""
    return _SUB_RX.sub(lambda m: f"{m[1]}{SUB[0]}{m[2]}{SUB[1]}", text)


def plain(text: str) -> str:
    """Marked text back as plain text with underscores ("M_Д")."""
    return text.replace(SUB[0], "_").replace(SUB[1], "")


# -- words --------------------------------------------------------------------------------------

def _pattern(p: str) -> re.Pattern:
    rx = re.escape(p).replace("\\#", r"(?P<i>\d+)").replace("\\*", r"(?P<x>[^.]+)")
    return re.compile("^" + rx + "$")


_FIELD_RX = [(_pattern(p), en, ru) for p, en, ru in FIELDS]


def field_label(path: str, lang: str, names: dict[str, str] | None = None) -> str:
    """The label of an input field ("links.2.mass" → "масса звена 2 m_2", the subscript
    marked: :func:`subscripts`); ``names``: the element name of an indexed path ("cylinders.0"
    → "HP"); an unknown field by its dotted path as the case file spells it."""
    for rx, en, ru in _FIELD_RX:
        m = rx.match(path)
        if m:
            if en.startswith("@"):
                return subscripts(nm.name(en[1:], lang))
            d = m.groupdict()
            x = d.get("x") or ""
            if not x and d.get("i") is not None:
                x = (names or {}).get(path[:m.end("i")]) or str(int(d["i"]) + 1)
            return subscripts((ru if lang == "ru" else en).format(x=x))
    return path


def _num(v) -> str:
    if isinstance(v, tuple):
        return ", ".join(_num(x) for x in v)
    if isinstance(v, int):
        return str(v)
    return "%.6g" % (0.0 if v == 0 else v)


def _answer_words(kind: str, key: str, lang: str) -> tuple[str, str, str]:
    """(what, symbol, unit) of an answer in ``lang``: the object of "Determine …", its symbol
    and SI unit as printed (nomenclature; "" where it has none)."""
    last = key.rsplit(".", 1)[-1]
    words = ANSWERS.get(f"{kind}:{key}") or ANSWERS.get(key)
    try:
        sym, unit = nm.symbol(last, lang), nm.unit_of(last, lang)
        name = nm.name(key if key in nm.TERMS else last, lang)
    except KeyError:
        sym, unit, name = "", "", key
    if f"{kind}:{key}" in _SYMBOLS:
        sym = _SYMBOLS[f"{kind}:{key}"][lang == "ru"]
    what = words[lang == "ru"] if words else name
    if sym and what.endswith(sym):          # a name that ends with its symbol: not twice
        what = what[:-len(sym)].rstrip(" ,")
    return subscripts(what), subscripts(sym), "" if unit in ("–", "") else unit


def _tol(t: float) -> str:
    return "%g" % float("%.3g" % (100 * t))


def find_items(sheet, lang: str) -> list[str]:
    """The find-list as sentences: «Определить момент инерции маховика J_М, кг·м² (допуск
    ±1 %).» / "Determine the moment of inertia of the flywheel J_M [kg·m²]; accepted within
    ±1 %."."""
    w = WORDS[lang]
    out = []
    for k, f in enumerate(sheet.find, 1):
        what, sym, unit = _answer_words(sheet.kind, f.answer, lang)
        if lang == "ru":
            what = "Определить " + what
            text = w["item"].format(What=what, sym=f" {sym}" if sym else "",
                                    unit=f", {unit}" if unit else "", tol=_tol(f.tolerance))
        else:
            text = w["item"].format(what=what, sym=f" {sym}" if sym else "",
                                    unit=f" [{unit}]" if unit else "", tol=_tol(f.tolerance))
        out.append(f"{k}. {text}")
    return out


def build_sheet(sheet, lang: str = "ru", figure: str | None = None) -> Document:
    """The sheet as a document: title, name line, the drawing (``figure``: the PNG's name, or
    None), «Дано» (the drawn values, then the other data), «Определить»."""
    w = WORDS[lang]
    doc = Document(w["variant"].format(n=sheet.number), lang)
    doc.blocks.append(Heading(1, w["variant"].format(n=sheet.number)))
    if sheet.title:
        doc.blocks.append(Paragraph(f"**{sheet.title}**"))
    doc.blocks.append(Paragraph(w["student"]))
    if figure is not None:
        if sheet.moments is not None:
            caption = w["moments"].format(MD=subscripts(nm.symbol("driving_moment", lang)),
                                          MC=subscripts(nm.symbol("M_C", lang)))
        else:
            caption = w["scheme"].format(a=sheet.angle_deg)
        doc.blocks.append(Figure(1, caption, figure))
    doc.blocks.append(Heading(2, w["given"]))
    header = (w["quantity"], w["value"], w["unit"])
    names = sheet.names
    number = 0
    for part, rows in (("drawn", [g for g in sheet.given if g.varied]),
                       ("fixed", [g for g in sheet.given if not g.varied])):
        if rows:
            number += 1
            doc.blocks.append(Table(number, w[part], header, tuple(
                (field_label(g.path, lang, names), _num(g.value),
                 nm.unit(g.unit, lang) if g.unit else "–") for g in rows)))
    doc.blocks.append(Heading(2, w["find"]))
    doc.blocks += [Paragraph(item) for item in find_items(sheet, lang)]
    return doc


# -- drawings -----------------------------------------------------------------------------------

def draw_linkage(ax, results, i: int, lang: str) -> None:
    """The mechanism at grid node ``i`` with its points named: render/plots.py's scheme
    drawing (``draw_scheme``), symbols scaled to the drawing's span as the run's scheme is."""
    from flywheel.render import plots

    plots.draw_scheme(ax, results, i, 0.035 * results.drawing.span, lang)


def _style():
    from flywheel.render import figure

    return figure.style()


def _linkage_png(sheet, path: Path, lang: str) -> None:
    import math

    from matplotlib.figure import Figure as MplFigure

    r = sheet.linkage
    with _style():
        fig = MplFigure(figsize=(6.0, 4.6), dpi=120)
        ax = fig.add_axes((0.12, 0.11, 0.85, 0.85))
        draw_linkage(ax, r, r.index_of(math.radians(sheet.angle_deg) % r.cycle), lang)
        fig.savefig(path, format="png", metadata={"Software": None})


def _moments_png(sheet, path: Path, lang: str) -> None:
    """M_D(φ) and M_C(φ) as the textbook draws them: the curves over the cycle, the graphs'
    corners marked on the φ axis, no moment scale (an unknown graph is marked "?")."""
    from matplotlib.figure import Figure as MplFigure

    g = sheet.moments
    w = WORDS[lang]
    with _style():
        fig = MplFigure(figsize=(6.4, 3.2), dpi=120)
        ax = fig.add_axes((0.06, 0.16, 0.9, 0.78))
        for key, ys, which, c in (("driving_moment", g.M_D, "driving", "C0"),
                                  ("M_C", g.M_C, "resistance", "C3")):
            label = nm.tex(key, lang) + "(φ)"
            if g.unknown == which:
                label += ": " + w["unknown"].format(M=nm.tex(key, lang))
            ax.plot(g.phi_deg, ys, color=c, linewidth=1.8, label=label)
        ax.axhline(0.0, color="k", linewidth=0.8)
        ax.set_xlim(0.0, g.cycle_deg)
        ax.set_xticks(list(g.breaks_deg))
        ax.set_xticklabels([f"{b:g}°" for b in g.breaks_deg])
        ax.set_yticks([])
        lo = min(0.0, *g.M_D, *g.M_C)
        hi = max(0.0, *g.M_D, *g.M_C)
        ax.set_ylim(lo - 0.08 * (hi - lo or 1.0), hi + 0.3 * (hi - lo or 1.0))
        ax.set_xlabel("φ")
        ax.set_ylabel("M")
        ax.legend(loc="upper right", fontsize=8)
        fig.savefig(path, format="png", metadata={"Software": None})


def draw(sheet, path: Path, lang: str) -> bool:
    """Write the sheet's drawing to ``path`` (PNG); False if it has none."""
    if sheet.linkage is not None:
        _linkage_png(sheet, path, lang)
        return True
    if sheet.moments is not None:
        _moments_png(sheet, path, lang)
        return True
    return False


# -- typesetting --------------------------------------------------------------------------------

def sheet_typst(doc: Document) -> str:
    """The sheet as typst source: the записка's (report_formats.typst_source) on one A4 page —
    narrower margins, no page number, the drawing 62 mm high, tables tighter, the quantity's
    name left-aligned."""
    from flywheel.render.report_formats import TypstLayout, typst_source

    src = typst_source(doc, TypstLayout(page="margin: (x: 15mm, y: 12mm)",
                                        table="inset: 2pt, align: (left, right, left)",
                                        image="height: 62mm"))
    # a marked subscript is inside one of the source's string literals (#"…"): close it
    return src.replace(SUB[0], '"#sub[#"').replace(SUB[1], '"]#"')


def sheet_html(doc: Document, images: Path | None) -> str:
    """The sheet as one self-contained HTML page: the записка's (report_formats.html) with the
    sheet's print style and the marked subscripts as <sub>."""
    from flywheel.render.report_formats import html

    page = html(doc, images).replace("</style>", _CSS + "</style>", 1)
    return page.replace(SUB[0], "<sub>").replace(SUB[1], "</sub>")


def _body(src: str) -> tuple[str, str]:
    """(preamble, body) of a typst source written by :func:`sheet_typst`."""
    head, _, body = src.partition("\n\n")
    return head, body


def combined_typst(sources: list[str]) -> str:
    """One typst source of all sheets, each on its own page."""
    head = _body(sources[0])[0]
    return head + "\n\n" + "\n#pagebreak()\n".join(_body(s)[1] for s in sources)


def _compile(src: str, images: Path | None) -> bytes:
    import shutil

    import typst

    with tempfile.TemporaryDirectory(prefix="flywheel-sheets-") as tmp:
        root = Path(tmp)
        if images is not None:
            shutil.copytree(images, root / "plots")
        (root / "main.typ").write_text(src, encoding="utf-8")
        return typst.compile(str(root / "main.typ"), root=str(root), format="pdf",
                             ignore_system_fonts=True, timestamp=0)


def write_sheets(sheets, folder: Path, lang: str = "ru", formats: str = "both",
                 progress=None) -> list[str]:
    """Write ``folder``/sheets/<variant>.html and/or .pdf for every sheet, and with PDF the
    class set ``folder``/sheets.pdf (one page per sheet); the names written (relative)."""
    if formats not in FORMATS:
        raise ValueError(f"sheet format {formats!r} (allowed: {', '.join(FORMATS)})")
    out = folder / FOLDER
    out.mkdir(exist_ok=True)
    names, sources = [], []
    with tempfile.TemporaryDirectory(prefix="flywheel-drawings-") as tmp:
        images = Path(tmp)
        for k, s in enumerate(sheets, 1):
            png = f"{s.stem}.png"
            doc = build_sheet(s, lang, png if draw(s, images / png, lang) else None)
            if formats in ("both", "html"):
                (out / f"{s.stem}.html").write_text(sheet_html(doc, images), encoding="utf-8")
                names.append(f"{FOLDER}/{s.stem}.html")
            if formats in ("both", "pdf"):
                src = sheet_typst(doc)
                sources.append(src)
                (out / f"{s.stem}.pdf").write_bytes(_compile(src, images))
                names.append(f"{FOLDER}/{s.stem}.pdf")
            if progress is not None:
                progress(k)
        if sources:
            (folder / COMBINED).write_bytes(_compile(combined_typst(sources), images))
            names.append(COMBINED)
    return names
