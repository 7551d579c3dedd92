"""The записка (render/document.py) as HTML, PDF and DOCX (docs/report.md).

- html: one self-contained file (Jinja2): styles inline with a print stylesheet for A4, the
  figures inline as data: URIs of the PNGs, formulas as MathML; nothing fetched.
- pdf: typst (its Python package; bundled fonts typeset Cyrillic), formulas in typst math.
- docx: python-docx, formulas as Word equations (OMML written from mathfmt's tree); the zip's
  dates fixed so reruns are identical.

A Russian PDF and DOCX take the ГОСТ 7.32-2017 layout of a пояснительная записка instead
(render/report_gost.py: title page, contents, captions, margins, fonts).

Heavy imports (jinja2, typst, docx, and render/report_gost.py) live inside the function of
their format.
"""
from __future__ import annotations

import base64
import io
import re
from dataclasses import dataclass
from pathlib import Path

from flywheel.render import mathfmt
from flywheel.render.document import Bullets, Document, Figure, Formula, Heading, Paragraph, Table, Where
from flywheel.render.report import CAPTION
from flywheel.render.choices import REPORT_FORMATS
from flywheel.render.typst_blocks import markup, typst_block

FORMATS = REPORT_FORMATS
#: a table of more columns than WIDE gets a smaller font; of more than WIDE_PAGE a landscape page
WIDE, WIDE_PAGE = 8, 12

_CSS = """
body { font-family: "DejaVu Serif", "Times New Roman", serif; max-width: 190mm; margin: 1em auto;
       padding: 0 1em; line-height: 1.4; color: #111; }
h1 { font-size: 1.5em; } h2 { font-size: 1.25em; margin-top: 1.4em; } h3 { font-size: 1.05em; }
table { border-collapse: collapse; margin: 0.3em 0 1em; font-size: 0.85em; }
th, td { border: 1px solid #888; padding: 0.15em 0.45em; text-align: right; }
th { background: #eee; text-align: center; } td:first-child { text-align: left; }
.caption { font-size: 0.9em; margin: 0.8em 0 0.2em; }
figure { margin: 1em 0; text-align: center; page-break-inside: avoid; break-inside: avoid; }
figure img { max-width: 100%; height: auto; }
figcaption { font-size: 0.9em; margin-top: 0.3em; }
math[display="block"] { margin: 0.5em 0; }
.eq { display: flex; align-items: center; } .eq math { flex: 1; } .eqn { margin-left: 1em; }
.tab { overflow-x: auto; } .wide table { font-size: 0.72em; } .wide th, .wide td { padding: 0.1em 0.25em; }
@page { size: A4; margin: 18mm 15mm; }
@page landscape { size: A4 landscape; margin: 15mm 15mm; }
@media print { body { max-width: none; margin: 0; padding: 0; font-size: 10.5pt; }
  h2, h3 { page-break-after: avoid; break-after: avoid; }
  table { page-break-inside: avoid; break-inside: avoid; }
  .tab { overflow: visible; } .landscape { page: landscape; } .landscape table { font-size: 0.65em; } }
"""

_TEMPLATE = """<!DOCTYPE html>
<html lang="{{ doc.lang }}">
<head>
<meta charset="utf-8">
<title>{{ doc.title }}</title>
<style>{{ css }}</style>
</head>
<body>
{% for b in blocks -%}
{% if b.kind == "h" %}<h{{ b.level }}>{{ b.html }}</h{{ b.level }}>
{% elif b.kind == "p" %}<p>{{ b.html }}</p>
{% elif b.kind == "ul" %}<ul>{% for i in b.entries %}<li>{{ i }}</li>{% endfor %}</ul>
{% elif b.kind == "f" %}<div class="eq" id="formula-{{ b.number }}">{{ b.mathml }}<span class="eqn">({{ b.number }})</span></div>
{% elif b.kind == "t" %}<div class="tab{{ b.width }}"><p class="caption" id="table-{{ b.number }}">{{ b.label }}</p>
<table>
<thead><tr>{% for c in b.header %}<th>{{ c }}</th>{% endfor %}</tr></thead>
<tbody>
{% for r in b.rows %}<tr>{% for c in r %}<td>{{ c }}</td>{% endfor %}</tr>
{% endfor %}</tbody>
</table></div>
{% elif b.kind == "img" %}<figure id="figure-{{ b.number }}">{% if b.src %}<img src="{{ b.src }}" alt="{{ b.label }}">{% endif %}
<figcaption>{{ b.caption }}</figcaption></figure>
{% endif %}
{%- endfor %}
</body>
</html>
"""


def _bold_html(text: str) -> str:
    """Text as HTML: **bold**, the symbols' subscripts (J_II, ΔT_нб) in <sub> (mathfmt.subscripts)."""
    from markupsafe import Markup

    parts = text.split("**")
    return Markup("".join(mathfmt.sub_html(p) if i % 2 == 0
                          else f"<strong>{mathfmt.sub_html(p)}</strong>"
                          for i, p in enumerate(parts)))


def html(doc: Document, plots_dir: Path | None = None) -> str:
    """The document as one self-contained HTML page; figures read from ``plots_dir``."""
    return html_page(doc)(plots_dir)


def html_page(doc: Document):
    """:func:`html` in two steps: the page's text made now (its blocks, the template), the
    figures read and the page put together by the function returned, given ``plots_dir`` —
    so that a run makes the text while its figures are being drawn."""
    import jinja2
    from markupsafe import Markup

    tab, fig = CAPTION[doc.lang]
    blocks = []
    for b in doc.blocks:
        if isinstance(b, Heading):
            blocks.append({"kind": "h", "level": b.level, "html": _bold_html(b.text)})
        elif isinstance(b, Where):
            blocks.append({"kind": "p", "html": Markup("<br>").join(map(_bold_html, b.lines))})
        elif isinstance(b, Paragraph):
            blocks.append({"kind": "p", "html": _bold_html(b.text)})
        elif isinstance(b, Bullets):
            blocks.append({"kind": "ul", "entries": [_bold_html(i) for i in b.items]})
        elif isinstance(b, Formula):                    # numbered in order: (1), (2), …
            number = sum(x["kind"] == "f" for x in blocks) + 1
            blocks.append({"kind": "f", "number": number, "mathml": Markup(mathfmt.mathml(b.tex))})
        elif isinstance(b, Table):
            n = len(b.header)
            blocks.append({"kind": "t", "number": b.number,
                           "label": _bold_html(f"{tab} {b.number} — {b.caption}"),
                           "header": [_bold_html(c) for c in b.header],
                           "rows": [[_bold_html(c) for c in r] for r in b.rows],
                           "width": "" if n <= WIDE else " wide" if n <= WIDE_PAGE else " wide landscape"})
        elif isinstance(b, Figure):
            blocks.append({"kind": "img", "number": b.number, "label": f"{fig} {b.number} — {b.caption}",
                           "caption": _bold_html(f"{fig} {b.number} — {b.caption}"), "src": None,
                           "file": b.file})
    template = jinja2.Environment(autoescape=True, keep_trailing_newline=True).from_string(_TEMPLATE)

    def page(plots_dir: Path | None) -> str:
        for block in blocks:
            if block["kind"] == "img":
                path = None if plots_dir is None else plots_dir / block["file"]
                block["src"] = ("data:image/png;base64," + base64.b64encode(path.read_bytes()).decode()
                                if path is not None and path.is_file() else None)
        return template.render(doc=doc, blocks=blocks, css=Markup(_CSS))
    return page


# -- typst / PDF ----------------------------------------------------------------------------------
#: text as typst markup: every run a string literal (nothing in it is markup); **bold**; the
#: symbols' subscripts (mathfmt.subscripts) as #sub (render/typst_blocks.py)
_ts = markup


@dataclass(frozen=True)
class TypstLayout:
    """How typst_source sets the page, the narrow tables and the figures: the записка's by
    default; a task sheet (render/sheets.py) fits one A4 page with its own."""

    page: str = 'margin: (x: 18mm, y: 18mm), numbering: "1"'
    table: str = "inset: 3pt, align: (x, y) => if x == 0 { left } else { right }"
    image: str = "width: 100%"


def typst_source(doc: Document, layout: TypstLayout = TypstLayout()) -> str:
    """The document as a typst file (figures referenced as plots/<name>)."""
    tab, fig = CAPTION[doc.lang]
    out = ['#set document(title: ' + _ts(doc.title)[1:] + ', date: none)',
           f'#set page(paper: "a4", {layout.page})',
           f'#set text(lang: "{doc.lang}", size: 10pt)',
           '#set par(justify: false)',
           '#set math.equation(numbering: "(1)")',     # as the ГОСТ layout: (1), (2), …
           ""]
    for b in doc.blocks:
        if isinstance(b, Heading):
            out.append("=" * b.level + " " + _ts(b.text))
        elif (lines := typst_block(b, _ts)) is not None:    # a paragraph, a list, a formula
            out += lines
        elif isinstance(b, Table):
            out.append(_typst_table(b, f"{tab} {b.number} — {b.caption}", layout.table))
        elif isinstance(b, Figure):
            out.append(f'#figure(image("plots/{b.file}", {layout.image}), numbering: none, '
                       f"caption: [{_ts(f'{fig} {b.number} — {b.caption}')}])")
        out.append("")
    return "\n".join(out)


def _typst_table(b: Table, caption: str, narrow: str = TypstLayout.table) -> str:
    """A numbered table as typst: its caption, then a table of up to WIDE columns in 8 pt set
    by ``narrow`` (the layout's inset and alignment: the first column left, the numbers
    right); a wide table (more than WIDE columns) in a smaller font, a very wide one (more than
    WIDE_PAGE) on a landscape page of its own, so that no number runs over its cell or the A4
    margin."""
    n = len(b.header)
    align = "align: (x, y) => if x == 0 { left } else { right }"
    size, style = ("8pt", narrow) if n <= WIDE else \
        ("7pt" if n <= WIDE_PAGE else "6.5pt", f"inset: 2pt, {align}")
    cells = ", ".join(f"[{_ts(c)}]" for r in (b.header, *b.rows) for c in r)
    src = (f"#block(breakable: true)[{_ts(caption)}]\n"
           f"#[#show table.cell: set text(size: {size})\n"
           f"#table(columns: {n}, {style}, {cells})]")
    return f"#page(flipped: true)[\n{src}\n]" if n > WIDE_PAGE else src


def pdf(doc: Document, plots_dir: Path | None = None) -> bytes:
    """The document as PDF (typst)."""
    src = typst_source(doc)
    if plots_dir is None:
        src = re.sub(r'#figure\(image\("plots/[^"]*", width: 100%\), ', "#figure(", src)
    from flywheel.render.report_gost import compile_typst

    return compile_typst(src, doc, plots_dir)


# -- DOCX -----------------------------------------------------------------------------------------
def docx(doc: Document, plots_dir: Path | None = None) -> bytes:
    """The document as Word (python-docx); formulas as native equations (OMML, mathfmt.omml)."""
    import datetime

    import docx as pydocx
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_TAB_ALIGNMENT
    from docx.oxml import parse_xml
    from docx.table import _Cell
    from docx.shared import Mm, Pt, Twips

    from flywheel.render.table_widths import column_widths, section_width

    tab, fig = CAPTION[doc.lang]
    d = pydocx.Document()
    sec = d.sections[0]
    sec.page_width, sec.page_height = Mm(210), Mm(297)
    sec.left_margin = sec.right_margin = Mm(18)
    fixed = datetime.datetime(2000, 1, 1)
    d.core_properties.created = d.core_properties.modified = fixed
    d.core_properties.last_printed = fixed
    d.core_properties.title = doc.title
    d.core_properties.author = d.core_properties.last_modified_by = "flywheel"
    d.core_properties.revision = 1

    def runs(p, text: str, size=None, bold: bool = False):
        """**bold** runs, the symbols' subscripts (J_II, ΔT_нб) as subscript runs."""
        for i, part in enumerate(text.split("**")):
            for seg, sub in mathfmt.subscripts(part) if part else ():
                if seg:
                    r = p.add_run(seg)
                    r.bold = bold or i % 2 == 1
                    if sub:
                        r.font.subscript = True
                    if size is not None:
                        r.font.size = size

    text_width = Mm(210 - 2 * 18)
    formulas = 0
    for b in doc.blocks:
        if isinstance(b, Heading):
            d.add_heading(b.text, level=b.level - 1 if b.level > 1 else 0)
        elif isinstance(b, Where):
            p = d.add_paragraph()
            for k, line in enumerate(b.lines):
                if k:
                    p.add_run().add_break()
                runs(p, line)
        elif isinstance(b, Paragraph):
            p = d.add_paragraph()
            runs(p, b.text)
            if b.leads_in:                  # kept with the formula it leads into
                p.paragraph_format.keep_with_next = True
        elif isinstance(b, Bullets):
            for i in b.items:
                runs(d.add_paragraph(style="List Bullet"), i)
        elif isinstance(b, Formula):        # a native Word equation at a centre tab stop, its
            formulas += 1                   # number «(n)» at a right one (as report_gost's)
            p = d.add_paragraph()
            p.paragraph_format.tab_stops.add_tab_stop(text_width // 2, WD_TAB_ALIGNMENT.CENTER)
            p.paragraph_format.tab_stops.add_tab_stop(text_width, WD_TAB_ALIGNMENT.RIGHT)
            p.paragraph_format.first_line_indent = 0
            p.add_run("\t")
            p._p.append(parse_xml(mathfmt.omml_inline(b.tex)))
            p.add_run(f"\t({formulas})")
        elif isinstance(b, Table):
            runs(d.add_paragraph(), f"{tab} {b.number} — {b.caption}")
            t = d.add_table(rows=1 + len(b.rows), cols=len(b.header))
            t.style = "Table Grid"
            # the header row repeated on every page the table runs onto (as report_gost's)
            t._tbl.tr_lst[0].get_or_add_trPr().append(parse_xml(
                '<w:tblHeader xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/'
                '2006/main"/>'))
            size = Pt(7 if len(b.header) > 7 else 8.5)
            # the columns' widths fixed (render/table_widths.py: LibreOffice gives columns
            # left to it the same share, and a narrow share breaks words)
            widths = column_widths([tuple(b.header), *b.rows], section_width(sec),
                                   round(size.pt * 2))
            t.autofit = False
            for col, w in zip(t.columns, widths):
                col.width = Twips(w)
            # the cells straight from the rows' XML: Table.cell(r, c) rebuilds the whole grid
            # on every call (quadratic; seconds for the report's tables)
            for r, (tr, cells) in enumerate(zip(t._tbl.tr_lst, (b.header, *b.rows))):
                for tc, text, w in zip(tr.tc_lst, cells, widths):
                    cell = _Cell(tc, t)
                    cell.width = Twips(w)
                    runs(cell.paragraphs[0], text, size, bold=r == 0)
        elif isinstance(b, Figure):
            if plots_dir is not None and (plots_dir / b.file).is_file():
                d.add_picture(str(plots_dir / b.file), width=Mm(170))
                d.paragraphs[-1].alignment = WD_ALIGN_PARAGRAPH.CENTER
            p = d.add_paragraph()
            runs(p, f"{fig} {b.number} — {b.caption}")
            p.alignment = WD_ALIGN_PARAGRAPH.CENTER
    buf = io.BytesIO()
    d.save(buf)
    from flywheel.render.report_gost import _fixed_zip

    return _fixed_zip(buf.getvalue())


def write_reports(doc: Document, folder: Path, formats, plots_dir: Path | None) -> list[str]:
    """Write report.<ext> for each format into ``folder``; the names written (a Russian PDF and
    DOCX in the ГОСТ layout of render/report_gost.py)."""
    return start_reports(doc, formats)(folder, plots_dir)


def start_reports(doc: Document, formats):
    """:func:`write_reports` in two steps: what needs no figure made now (the Markdown text,
    the HTML page's text: :func:`html_page`), the reports written by the function returned,
    given ``folder`` and the figures' ``plots_dir`` — a run calls it when its figures are
    drawn, having made the rest while they were."""
    from flywheel.render.report import markdown

    made = {f: markdown(doc) if f == "md" else html_page(doc) if f == "html" else None
            for f in dict.fromkeys(formats)}

    def write(folder: Path, plots_dir: Path | None) -> list[str]:
        return [_write_report(doc, folder, f, plots_dir, text) for f, text in made.items()]
    return write


def _write_report(doc: Document, folder: Path, f: str, plots_dir: Path | None, made) -> str:
    """report.<f> written into ``folder`` (``made``: its text or page made already); its name."""
    name = f"report.{f}"
    if f == "md":
        (folder / name).write_text(made, encoding="utf-8")
    elif f == "html":
        (folder / name).write_text(made(plots_dir), encoding="utf-8")
    elif f == "pdf":
        from flywheel.render import report_gost

        (folder / name).write_bytes(report_gost.pdf(doc, plots_dir) if doc.lang == "ru"
                                    else pdf(doc, plots_dir))
    elif f == "docx":
        from flywheel.render import report_gost

        (folder / name).write_bytes(report_gost.docx(doc, plots_dir) if doc.lang == "ru"
                                    else docx(doc, plots_dir))
    else:
        # library use only: no CLI input reaches this
        raise ValueError(f"report format {f!r} (allowed: {', '.join(FORMATS)})")
    return name
