"""Printable task sheets of ``flywheel variants … --sheets`` (docs/teacher.md): one A4 page per
variant — the drawing, «Дано» (the variant's data with units), «Задание» (the answers asked,
with units and the grader's tolerance) and the student's name line — as HTML and PDF through
the записка's path (a :class:`~flywheel.render.document.Document` written by
render/report_formats.py: Jinja2 for HTML, typst for PDF).

What goes on a sheet is teaching/sheets.py's (:class:`~flywheel.teaching.sheets.Sheet`); this
module only words, draws and typesets it. No answer and no solving hint is printed. The labels
of the input fields and the find-list's words, symbols and units come from
render/nomenclature.py (its block ``--- sheets ---``); this module keeps the sentence templates
(:data:`WORDS`).
"""
from __future__ import annotations

import re
import tempfile
from pathlib import Path

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.document import Document, Figure, Heading, Paragraph, Table
from flywheel.render.numbers import fmt as _number
from flywheel.render.numbers import russian, separator, typeset
from flywheel.render.sheet_labels import as_printed, field_kinds

FORMATS = ("both", "html", "pdf")
#: the drawing's printed height on a sheet [mm]
IMAGE_MM = 52
#: the sheet's own print style, after the записка's and as the PDF sheet's layout (typst_sheet:
#: margins 15 × 10 mm, the drawing 52 mm high): one A4 page for a run template's 40-odd data
#: rows too; a table longer than what is left of a page breaks rather than moving whole
_CSS = (f"figure img {{ max-height: {IMAGE_MM}mm; width: auto; }} "
        "@page { size: A4; margin: 10mm 15mm; } "
        "@media print { body { font-size: 9pt; line-height: 1.25; } h1 { font-size: 1.3em; "
        "margin: 0 0 0.3em; } h2 { margin: 0.45em 0 0.2em; } figure { margin: 0.3em 0; } "
        "table { font-size: 0.78em; break-inside: auto; page-break-inside: auto; } "
        "td, th { padding: 0 0.35em; } p { margin: 0.2em 0; } .caption { margin: 0.4em 0 0.1em; } "
        "li { margin: 0.1em 0; } td:first-child { white-space: nowrap; } } "
        "td:nth-child(2) { white-space: normal; }")
#: the combined file of all sheets, one per page, for printing the class set
COMBINED = "sheets.pdf"
FOLDER = "sheets"

WORDS = words("sheets", {"variant": "Variant {n}", "student": "Student ______________________________"
                         "        Group ____________", "given": "Given", "drawn": "Data of the variant",
                         "fixed": "Other data", "find": "Task", "quantity": "Quantity",
                         "value": "Value", "unit": "Unit",
                         "item": "Determine {what}{sym}{unit}; accepted within ±{tol} %.",
                         "scheme": "Kinematic scheme of the mechanism at φ = {a:g}°",
                         "moments": "The given moment graphs {MD}(φ) and {MC}(φ)",
                         "unknown": "{M} = ? (from the cycle balance)",
                         "fill": "Fill in Table {n}: {title}; each cell is accepted within ±{tol} %.",
                         "signs": "Moments and works with their signs: positive in the crank's "
                                  "direction of rotation (driving), negative against it "
                                  "(resisting).",
                         # the title of a Russian sheet whose template says its title in English
                         # only: the kind of task
                         "title": {"run": "Dynamic analysis of a machine",
                                   "task2": "Motion of a machine with a constant reduced moment "
                                            "of inertia"}})
#: a word of Latin letters (two or more): English on a sheet (a lone letter, as in «V-образный»,
#: is a symbol)
_LATIN_WORD = re.compile(r"[A-Za-z]{2,}")

#: a subscript as marked in a sheet's text (private-use characters, which no number or word of
#: ours contains), typeset by :func:`sheet_html` (<sub>) and :func:`sheet_typst` (#sub[])
SUB = ("\ue000", "\ue001")
_SUB_RX = re.compile(r"(?:(?<!\w)|(?<=Δ))([^\W\d_])_([^\W_]+(?:,[^\W_]+)?)")


def subscripts(text: str) -> str:
    """The symbols of ``text`` written with an underscore ("M_Д", "ΔT_нб", "p/p_max", "J_S2",
    a cylinder's "p_max,ВД" — a comma with no space after it is inside the subscript) with
    their subscripts marked for typesetting; an underscore inside a word (a case file's name
    like "crank_gear") is left as it is."""
    return _SUB_RX.sub(lambda m: f"{m[1]}{SUB[0]}{m[2]}{SUB[1]}", text)


def plain(text: str) -> str:
    """Marked text back as plain text with underscores ("M_Д")."""
    return text.replace(SUB[0], "_").replace(SUB[1], "")


# -- words --------------------------------------------------------------------------------------

def field_label(path: str, lang: str, names: dict[str, str] | None = None,
                kinds: tuple[str, ...] = ()) -> str:
    """The label of an input field ("links.2.mass" → "масса звена 2 m_2": the nomenclature's
    :func:`~flywheel.render.nomenclature.field_label`), the subscript marked
    (:func:`subscripts`)."""
    return subscripts(nm.field_label(path, lang, names, kinds))


def _kinds(sheet) -> tuple[str, ...]:
    """The nomenclature's kinds of the sheet's fields (:func:`field_kinds` of its flywheel's
    speed ratio)."""
    ratio = next((g.value for g in sheet.given if g.path == "flywheel.speed_ratio"), 1)
    return field_kinds(sheet.kind, ratio)


def _num(v) -> str:
    """A datum the case gave, through the one formatter (in Russian, within ``typeset``: its
    own digits, a decimal comma, numbers of a list separated by «; »)."""
    if isinstance(v, tuple):
        return separator().join(_num(x) for x in v)
    if isinstance(v, int) and not russian():
        return str(v)
    return _number(float(v), 6, zero=0.0, nonfinite="show", given=True)


def _value(g, lang: str) -> str:
    """A datum as printed: a number or numbers (:func:`_num`), a text field in the
    nomenclature's words (:func:`~flywheel.render.nomenclature.field_value`: "1-3-4-2",
    "по часовой стрелке")."""
    first = g.value[0] if isinstance(g.value, tuple) and g.value else g.value
    if isinstance(first, str):
        return subscripts(nm.field_value(g.path, g.value, lang))
    return _num(g.value)


def _in_mpa(g):
    """A datum with its value in the unit the sheet prints (:func:`as_printed`: a pressure in
    MPa)."""
    from dataclasses import replace

    value, unit = as_printed(g.value, g.unit)
    return replace(g, value=value, unit=unit)


def _answer_words(kind: str, key: str, lang: str, at_deg: tuple = (),
                  loads: tuple = ({}, {})) -> tuple[str, str, str]:
    """(what, symbol, unit) of an answer in ``lang`` (the nomenclature's
    :func:`~flywheel.render.nomenclature.answer_words`; a report angle's quantity at its angle
    of ``at_deg``, a load by its title or label of ``loads``), the subscripts marked."""
    what, sym, unit = nm.answer_words(kind, key, lang, at_deg, loads)
    return subscripts(what), subscripts(sym), unit


def _tol(t: float) -> str:
    return _number(float("%.3g" % (100 * t)), 6, zero=None, given=True)


def find_items(sheet, lang: str) -> list[str]:
    """The find-list as sentences: «Определить момент инерции маховика J_М, кг·м² (допуск
    ±1 %).» / "Determine the moment of inertia of the flywheel J_M [kg·m²]; accepted within
    ±1 %."."""
    w = WORDS[lang]
    out = []
    for k, f in enumerate(sheet.find, 1):
        what, sym, unit = _answer_words(sheet.kind, f.answer, lang, sheet.at_deg, sheet.loads)
        if unit:
            unit = f", {unit}" if lang == "ru" else f" [{unit}]"
        text = w["item"].format(what=what, sym=f" {sym}" if sym else "", unit=unit,
                                tol=_tol(f.tolerance))
        out.append(f"{k}. {text}")
    return out


def sheet_title(sheet, lang: str) -> str:
    """The sheet's title in ``lang``: the template's (a ``{ ru, en }`` title in its language);
    on a Russian sheet, a title the template gives in English only (a plain string with Latin
    words) gives way to the Russian name of the kind of task, never English words on a Russian
    sheet; "" for none."""
    from flywheel.io.text import Text, in_language

    text = in_language(sheet.title, lang)
    if lang == "ru" and not isinstance(sheet.title, Text) and _LATIN_WORD.search(text):
        return WORDS[lang]["title"].get(sheet.kind, "")
    return text


def build_sheet(sheet, lang: str = "ru", figure: str | None = None) -> Document:
    """The sheet as a document: title, name line, the drawing (``figure``: the PNG's name, or
    None), «Дано» (the drawn values, then the other data), «Задание» (what to determine)."""
    w = WORDS[lang]
    doc = Document(w["variant"].format(n=sheet.number), lang)
    doc.blocks.append(Heading(1, w["variant"].format(n=sheet.number)))
    title = sheet_title(sheet, lang)
    if title:
        doc.blocks.append(Paragraph(f"**{title}**"))
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
    names, kinds = sheet.names, _kinds(sheet)
    number = 0
    for part, rows in (("drawn", [g for g in sheet.given if g.varied]),
                       ("fixed", [g for g in sheet.given if not g.varied])):
        if rows:
            number += 1
            doc.blocks.append(Table(number, w[part], header, tuple(
                (field_label(g.path, lang, names, kinds), _value(g, lang),
                 nm.unit(g.unit, lang) if g.unit else "–") for g in map(_in_mpa, rows))))
    doc.blocks.append(Heading(2, w["find"]))
    items = find_items(sheet, lang)
    doc.blocks += [Paragraph(item) for item in items]
    if sheet.signed:                # an engine's M_С = −50 N·m: which way is positive
        doc.blocks.append(Paragraph(w["signs"]))
    doc.blocks += blank_tables(sheet, lang, number, len(items))
    return doc


#: a blank cell of a table to fill in: wide enough for a number written by hand
BLANK = "\u00a0" * 16


def blank_tables(sheet, lang: str, tables_before: int, items_before: int) -> list:
    """The tables a student fills in (``[variants] tables``, teaching/tables.py): per table
    a find-item «Fill in Table 3: …» and the table with its rows' labels, the rows' angles
    and the columns with their units, the cells blank."""
    from flywheel.render.sheet_labels import column_heading, row_text, row_word, table_title

    w = WORDS[lang]
    out = []
    for k, spec in enumerate(sheet.tables, 1):
        number = tables_before + k
        title = subscripts(table_title(spec.name, spec.phi_deg[0], lang))
        tols = [sheet.default_tolerance if t is None else t for t in spec.tolerances]
        low, high = _tol(min(tols)), _tol(max(tols))
        out.append(Paragraph(f"{items_before + k}. " + w["fill"].format(
            n=number, title=title, tol=low if low == high else f"{low}–{high}")))
        head = [row_word(spec.row_label, lang)]
        if spec.row_label == "position":
            head.append("φ, °" if lang == "ru" else "φ [°]")
        head += [subscripts(column_heading(spec.name, c, lang)) for c in spec.columns]
        rows = []
        for r, phi in zip(spec.rows, spec.phi_deg):
            label = row_text(spec.name, r)
            first = [label] + ([_num(phi)] if spec.row_label == "position" else [])
            rows.append(tuple(first + [BLANK] * len(spec.columns)))
        out.append(Table(number, title, tuple(head), tuple(rows)))
    return out



# -- drawings -----------------------------------------------------------------------------------

def draw_linkage(ax, results, i: int, lang: str) -> None:
    """The mechanism at grid node ``i`` with its points named: render/plots.py's scheme
    drawing (``draw_scheme``), symbols scaled to the drawing's span as the run's scheme is."""
    from flywheel.render import plots

    plots.draw_scheme(ax, results, i, 0.035 * results.drawing.span, lang)


def _style(lang: str):
    from flywheel.render import figure

    return figure.style(lang)


def linkage_figure(sheet, lang: str):
    """The sheet's drawing of its linkage at the sheet's angle, a matplotlib Figure drawn at
    about its printed size (IMAGE_MM high on the sheet), so that its letters print at 7 – 8 pt,
    not scaled down to 4 pt from a larger figure. Within the figures' style (:func:`_style`)."""
    import math

    from matplotlib.figure import Figure as MplFigure

    r = sheet.linkage
    fig = MplFigure(figsize=SCHEME_INCHES, dpi=SHEET_DPI)
    ax = fig.add_axes((0.17, 0.17, 0.81, 0.80))
    draw_linkage(ax, r, r.index_of(math.radians(sheet.angle_deg) % r.cycle), lang)
    return fig


def _linkage_png(sheet, path: Path, lang: str) -> None:
    with _style(lang):
        linkage_figure(sheet, lang).savefig(path, format="png", metadata={"Software": None})


#: the drawings' size [in] and resolution on a sheet: printed IMAGE_MM high, nearly at this
#: size (tests/teaching/test_sheets.py: its letters print at 7 pt or more)
SCHEME_INCHES = (3.2, 2.45)
MOMENTS_INCHES = (4.4, 2.2)
SHEET_DPI = 300


def _moments_png(sheet, path: Path, lang: str) -> None:
    """M_D(φ) and M_C(φ) as the textbook draws them: the curves over the cycle, the graphs'
    corners marked on the φ axis, no moment scale (an unknown graph is marked "?")."""
    from matplotlib.figure import Figure as MplFigure

    g = sheet.moments
    w = WORDS[lang]
    with _style(lang):
        fig = MplFigure(figsize=MOMENTS_INCHES, dpi=SHEET_DPI)
        ax = fig.add_axes((0.07, 0.2, 0.9, 0.6))
        for key, ys, which, c in (("driving_moment", g.M_D, "driving", "C0"),
                                  ("M_C", g.M_C, "resistance", "C3")):
            label = nm.tex(key, lang) + "(φ)"
            if g.unknown == which:
                label += ": " + w["unknown"].format(M=nm.tex(key, lang))
            ax.plot(g.phi_deg, ys, color=c, linewidth=1.8, label=label)
        ax.axhline(0.0, color="k", linewidth=0.8)
        ax.set_xlim(0.0, g.cycle_deg)
        ax.set_xticks(list(g.breaks_deg))
        ax.set_xticklabels([f"{_number(b, 6, zero=None, given=True)}°" for b in g.breaks_deg])
        ax.set_yticks([])
        lo = min(0.0, *g.M_D, *g.M_C)
        hi = max(0.0, *g.M_D, *g.M_C)
        ax.set_ylim(lo - 0.08 * (hi - lo or 1.0), hi + 0.08 * (hi - lo or 1.0))
        ax.set_xlabel("φ")
        ax.set_ylabel("M")
        # above the graphs, where no curve is (inside, it had covered a triangle's apex)
        ax.legend(loc="lower center", bbox_to_anchor=(0.5, 1.0), fontsize=8, frameon=False)
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
    narrower margins, no page number, the drawing 52 mm high, tables tighter, the quantity's
    name left-aligned."""
    from flywheel.render.report_formats import TypstLayout, typst_source

    src = typst_source(doc, TypstLayout(page="margin: (x: 15mm, y: 10mm)",
                                        table="inset: 2pt, align: (left, right, left)",
                                        image=f"height: {IMAGE_MM}mm"))
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
        # library use only: no CLI input reaches this
        raise ValueError(f"sheet format {formats!r} (allowed: {', '.join(FORMATS)})")
    out = folder / FOLDER
    out.mkdir(exist_ok=True)
    names, sources = [], []
    with tempfile.TemporaryDirectory(prefix="flywheel-drawings-") as tmp:
        images = Path(tmp)
        for k, s in enumerate(sheets, 1):
            png = f"{s.stem}.png"
            doc = typeset(lang, build_sheet, s, lang, png if draw(s, images / png, lang) else None)
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
