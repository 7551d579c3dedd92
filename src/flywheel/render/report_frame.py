"""The ЕСКД frame of the Russian записка (``--frame eskd``): every page but the title page
inside the frame of ГОСТ 2.104-2006 (20 mm from the left edge, 5 mm from the others), the
title block of form 2 (185 × 40 mm) on the contents page — the first sheet of the text, as
departments fill it — and form 2a (185 × 15 mm) on every further page, both from the cells of
render/drawings/forms.py, lettered as the drawing sheets are (ГОСТ 2.304 type B: osifont,
else DejaVu Sans, sloped 15°; render/drawings/fonts.py).

Filled from ``[document]`` (the title page, render/blocks.py ``TitlePage``): the designation
with «ПЗ», Разраб. (student), Пров. (teacher), Т. контр. (in form 2's free row), Н. контр.,
Утв., the name (the machine and «Пояснительная записка»), the sheet and the number of sheets
(the title page is sheet 1), the university and the group. The text moves inside the frame
(ГОСТ 2.105-95, 4.1.9, as departments still apply it: at least 3 mm from the frame at the
lines' ends, 10 mm from the frame or the title block above and below): left 25 mm, right ``[document] margin_right_mm`` (10),
top 15 mm, bottom 30 mm (55 mm on the page of form 2); the page numbers are the title blocks'.

PDF (typst): the frame and the title blocks drawn in each page's background. DOCX: the frame a
VML rectangle anchored to the page in the section's headers, the title blocks tables in its
footers (form 2 in the first page's footer, 2a in the others'), the sheet numbers PAGE and
NUMPAGES fields — Word and LibreOffice keep them on every page the student adds.
"""
from __future__ import annotations

from flywheel.render.drawings.forms import WIDTH, Cell, Form, form2, form2a
from flywheel.render.choices import FRAMES  # noqa: F401 (re-exported)

#: the frame's distances from the sheet's edges [mm] (ГОСТ 2.104-2006, 4.3) and the sheet
LEFT, MARGIN, PAGE_W, PAGE_H = 20.0, 5.0, 210.0, 297.0
#: the text's distance from the frame at the top and above a title block [mm] (ГОСТ 2.105)
TEXT_GAP = 10.0
#: the text's margins inside the frame [mm]: left, top, bottom over form 2a, over form 2
TEXT_LEFT, TEXT_TOP = LEFT + 5.0, MARGIN + TEXT_GAP
TEXT_BOTTOM = MARGIN + 15.0 + TEXT_GAP
TEXT_BOTTOM_FIRST = MARGIN + 40.0 + TEXT_GAP
SLANT = 15.0                        # the letters' slope from the vertical [deg] (ГОСТ 2.304)


def _line_mm(kind: str) -> float:
    from flywheel.render.drawings.model import LINE_TYPES

    return LINE_TYPES[kind][0]


def _font_mm(height: float) -> float:
    """The font size [mm] whose capitals are ``height`` mm high in the sheets' font."""
    from flywheel.render.drawings.fonts import _font, font_path

    f = _font(font_path())
    return height * f.upem / f.cap


def font_family() -> str:
    from flywheel.render.drawings.fonts import font_name

    return font_name()


def font_file():
    """The sheets' font file (typst is given it beside the text's)."""
    from pathlib import Path

    from flywheel.render.drawings.fonts import font_path

    return Path(font_path())


# -- what each cell says ------------------------------------------------------------------------
def _labels(lang: str) -> dict:
    from flywheel.render.drawings.sheet import words_of

    return words_of(lang)


def _designation(f) -> str:
    from flywheel.cases.document import DEFAULT_DESIGNATION

    return f"{f.designation or DEFAULT_DESIGNATION} ПЗ"


def _lines(cell: Cell, f, note: str, t: dict,
           pad: float = 1.0) -> list[tuple[str, float, float, float]]:
    """A cell's text as lines (text, capital height [mm], squeeze, middle's y from the cell's
    top [mm]), ``pad`` [mm] left free across a one-line cell (Word's letters run wider than
    the font's advances: 1.6); the sheet numbers are the writers' (they change from page to
    page)."""
    from flywheel.render.drawings.forms import ROLE_FIELDS
    from flywheel.render.drawings.sheet import fit, name_lines, organisation_lines

    mid = cell.h / 2
    if cell.text == "title":
        return [(ln, h, 1.0, mid - y) for ln, h, y in name_lines(f.machine, note, 0.0)]
    if cell.text == "organisation":
        lines = organisation_lines(f, t)
        return [(ln, 3.5, 1.0, mid - (len(lines) / 2 - k - 0.5) * 4.6)
                for k, ln in enumerate(lines)]
    if cell.text == "designation":
        text, h, q = fit(_designation(f), cell.w - 4.0, (7.0, 5.0, 3.5))
        return [(text, h, q, mid)]
    if cell.text.startswith("label:"):
        text = t[cell.text[6:]]
    elif cell.text in ROLE_FIELDS.values():
        text = getattr(f, cell.text)
    else:
        return []
    if not text:
        return []
    text, h, q = fit(text, cell.w - pad, (cell.size, 2.5) if cell.size > 2.5 else (cell.size,))
    return [(text, h, q, mid)]


def _edges(form: Form):
    """Every cell edge once: (x0, y0, x1, y1, line type) [mm], y down from the form's top."""
    seen, out = set(), []
    for c in form.cells:
        for e in ((c.x, c.y, c.x + c.w, c.y), (c.x, c.y + c.h, c.x + c.w, c.y + c.h),
                  (c.x, c.y, c.x, c.y + c.h), (c.x + c.w, c.y, c.x + c.w, c.y + c.h)):
            if e not in seen:
                seen.add(e)
                out.append((*e, "thin" if form.is_thin(*e) else "main"))
    return out


# -- typst --------------------------------------------------------------------------------------
def _typst_text(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _typst_form(form: Form, f, note: str, t: dict, numbers: dict) -> str:
    """A typst function body placing ``form`` at the frame's lower right corner of a portrait
    page (its lines and lettering); ``numbers`` the typst expressions of the sheet numbers."""
    x0, y0 = PAGE_W - MARGIN - WIDTH, PAGE_H - MARGIN - form.height
    out = []
    for a, b, c, d, kind in _edges(form):
        w = _line_mm(kind)
        out.append(f"place(top + left, line(start: ({x0 + a:g}mm, {y0 + b:g}mm), "
                   f"end: ({x0 + c:g}mm, {y0 + d:g}mm), stroke: (thickness: {w:g}mm, "
                   f"cap: \"square\")))")
    for cell in form.cells:
        al = "left" if cell.align == "left" else "center"
        if cell.text in numbers:
            body = [(numbers[cell.text], cell.size, 1.0, cell.h / 2)]
        else:
            body = [(_typst_text(s), h, q, y) for s, h, q, y in _lines(cell, f, note, t)]
        for expr, h, q, y in body:
            size = _font_mm(h)
            letters = f"eskd-letters({expr}, {size:.4f}mm, {q * 100:.2f}%)"
            out.append(f"place(top + left, dx: {x0 + cell.x:g}mm, dy: {y0 + cell.y + y - h:.4f}mm, "
                       f"box(width: {cell.w:g}mm, height: {2 * h:.4f}mm, inset: (x: 0.5mm), "
                       f"align({al} + horizon, {letters})))")
    return "{\n  " + "\n  ".join(out) + "\n}"


def typst_preamble(f, lang: str, note: str) -> str:
    """The typst definitions of the frame (after the записка's preamble): the page's margins
    inside the frame, the background that draws the frame and the title block of each page
    (none on the title page, form 2 on the page labelled <eskd-contents>, form 2a elsewhere; a
    landscape page the portrait sheet turned: its binding edge at the top)."""
    t = _labels(lang)
    right = f"{f.margin_right_mm:g}mm"
    first = _typst_form(form2(), f, note, t, {"sheet": "str(sheet)", "sheets": "str(sheets)"})
    later = _typst_form(form2a(), f, note, t, {"sheet": "str(sheet)"})
    w = _line_mm("main")
    return f"""#let eskd-letters(body, size, squeeze) = text(font: ("{font_family()}", "DejaVu Sans"),
  size: size, top-edge: "cap-height", bottom-edge: "baseline",
  skew(ax: -{SLANT:g}deg, scale(x: squeeze, reflow: true, body)))
#let eskd-form2(sheet, sheets) = {first}
#let eskd-form2a(sheet) = {later}
#let eskd-sheet(sheet, sheets, first) = {{
  place(top + left, dx: {LEFT:g}mm, dy: {MARGIN:g}mm,
        rect(width: {PAGE_W - LEFT - MARGIN:g}mm, height: {PAGE_H - 2 * MARGIN:g}mm, stroke: {w:g}mm))
  if sheet == first {{ eskd-form2(sheet, sheets) }} else {{ eskd-form2a(sheet) }}
}}
#set page(margin: (left: {TEXT_LEFT:g}mm, right: {right}, top: {TEXT_TOP:g}mm, bottom: {TEXT_BOTTOM:g}mm),
  footer: none, background: context {{
    let sheet = here().page()
    if sheet > 1 {{
      let first = query(<eskd-contents>).first().location().page()
      let sheets = counter(page).final().first()
      if page.flipped {{
        place(top + left, dx: {PAGE_H:g}mm, rotate(90deg, origin: top + left,
          box(width: {PAGE_W:g}mm, height: {PAGE_H:g}mm, eskd-sheet(sheet, sheets, first))))
      }} else {{ eskd-sheet(sheet, sheets, first) }}
    }}
  }})
"""


def typst_title_margins(f) -> str:
    """The title page's margins (ГОСТ 7.32-2017: no frame on it)."""
    return f"margin: (left: 30mm, right: {f.margin_right_mm:g}mm, top: 20mm, bottom: 20mm), background: none"


def typst_contents_page(f) -> str:
    """The page setting of the contents (form 2's sheet): the text 10 mm above form 2."""
    return (f"margin: (left: {TEXT_LEFT:g}mm, right: {f.margin_right_mm:g}mm, top: {TEXT_TOP:g}mm, "
            f"bottom: {TEXT_BOTTOM_FIRST:g}mm)")


def typst_landscape(f) -> str:
    """A landscape page's margins: the portrait sheet's turned (binding at the top, the title
    block on the left)."""
    return (f"flipped: true, margin: (left: {TEXT_BOTTOM:g}mm, right: {TEXT_TOP:g}mm, "
            f"top: {TEXT_LEFT:g}mm, bottom: {f.margin_right_mm:g}mm)")


# -- DOCX ---------------------------------------------------------------------------------------
_W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
_V = 'xmlns:v="urn:schemas-microsoft-com:vml"'
_O = 'xmlns:o="urn:schemas-microsoft-com:office:office"'
TWIPS_PER_MM = 1440 / 25.4
PT_PER_MM = 72 / 25.4


def _tw(mm: float) -> int:
    return round(mm * TWIPS_PER_MM)


def _run(text: str, h: float, q: float, field: str = "") -> str:
    """A run of the title block's lettering (the sheets' font, sloped), or a field's."""
    from xml.sax.saxutils import escape

    half = max(2, round(2 * _font_mm(h) * PT_PER_MM))
    fam = font_family()
    squeeze = f'<w:w w:val="{round(q * 100)}"/>' if q < 0.995 else ""
    rpr = (f'<w:rPr><w:rFonts w:ascii="{fam}" w:hAnsi="{fam}" w:cs="{fam}" w:eastAsia="{fam}"/>'
           f'<w:i/><w:iCs/>{squeeze}'
           f'<w:sz w:val="{half}"/><w:szCs w:val="{half}"/></w:rPr>')
    if field:                       # a complex field: each of its runs in the lettering
        return (f'<w:r>{rpr}<w:fldChar w:fldCharType="begin"/></w:r><w:r>{rpr}<w:instrText '
                f'xml:space="preserve"> {field} </w:instrText></w:r><w:r>{rpr}<w:fldChar '
                f'w:fldCharType="separate"/></w:r><w:r>{rpr}<w:t>{text}</w:t></w:r>'
                f'<w:r>{rpr}<w:fldChar w:fldCharType="end"/></w:r>')
    return f'<w:r>{rpr}<w:t xml:space="preserve">{escape(text)}</w:t></w:r>'


def _para(inner: str, align: str, line_mm: float) -> str:
    return (f'<w:p><w:pPr><w:keepNext/><w:spacing w:before="0" w:after="0" '
            f'w:line="{_tw(line_mm)}" w:lineRule="exact"/>'
            f'<w:ind w:left="{_tw(0.5)}" w:right="{_tw(0.5)}" w:firstLine="0"/>'
            f'<w:jc w:val="{"left" if align == "left" else "center"}"/></w:pPr>{inner}</w:p>')


def _cell_paragraphs(cell: Cell, f, note: str, t: dict) -> str:
    if cell.text == "sheet":
        return _para(_run("2", cell.size, 1.0, "PAGE"), cell.align, min(cell.h, 1.3 * cell.size))
    if cell.text == "sheets":
        return _para(_run("2", cell.size, 1.0, "NUMPAGES"), cell.align,
                     min(cell.h, 1.3 * cell.size))
    lines = _lines(cell, f, note, t, pad=1.6)
    if not lines:
        return _para("", cell.align, min(cell.h, 2.0))
    step = min(cell.h / len(lines), 1.5 * max(h for _, h, _, _ in lines))
    return "".join(_para(_run(s, h, q), cell.align, step) for s, h, q, _ in lines)


def table_xml(form: Form, f, note: str, lang: str) -> str:
    """The title block ``form`` as a Word table: fixed columns and exact rows from the cells'
    edges, merged cells, each edge a main or thin line; its left edge on the frame (the text
    starts 5 mm right of it)."""
    t = _labels(lang)
    xs = sorted({v for c in form.cells for v in (c.x, c.x + c.w)})
    ys = sorted({v for c in form.cells for v in (c.y, c.y + c.h)})
    main, thin = round(_line_mm("main") * PT_PER_MM * 8), round(_line_mm("thin") * PT_PER_MM * 8)

    def border(side: str, e) -> str:
        return (f'<w:{side} w:val="single" w:sz="{thin if form.is_thin(*e) else main}" '
                f'w:space="0" w:color="000000"/>')

    rows = []
    for r in range(len(ys) - 1):
        tcs = []
        for c in sorted((c for c in form.cells if c.y <= ys[r] < c.y + c.h), key=lambda c: c.x):
            span = xs.index(c.x + c.w) - xs.index(c.x)
            top, bottom = c.y == ys[r], c.y + c.h == ys[r + 1]
            merge = "" if c.h == ys[r + 1] - ys[r] else \
                '<w:vMerge w:val="restart"/>' if top else "<w:vMerge/>"
            borders = "".join([
                border("top", (c.x, c.y, c.x + c.w, c.y)) if top else "",
                border("left", (c.x, c.y, c.x, c.y + c.h)),
                border("bottom", (c.x, c.y + c.h, c.x + c.w, c.y + c.h)) if bottom else "",
                border("right", (c.x + c.w, c.y, c.x + c.w, c.y + c.h))])
            body = _cell_paragraphs(c, f, note, t) if top else _para("", c.align, 1.0)
            tcs.append(f'<w:tc><w:tcPr><w:tcW w:w="{_tw(c.w)}" w:type="dxa"/>'
                       + (f'<w:gridSpan w:val="{span}"/>' if span > 1 else "")
                       + f'{merge}<w:tcBorders>{borders}</w:tcBorders><w:vAlign w:val="center"/>'
                       f"</w:tcPr>{body}</w:tc>")
        rows.append(f'<w:tr><w:trPr><w:cantSplit/><w:trHeight w:val="{_tw(ys[r + 1] - ys[r])}" '
                    f'w:hRule="exact"/></w:trPr>{"".join(tcs)}</w:tr>')
    grid = "".join(f'<w:gridCol w:w="{_tw(b - a)}"/>' for a, b in zip(xs, xs[1:]))
    return (f'<w:tbl {_W}><w:tblPr><w:tblW w:w="{_tw(xs[-1] - xs[0])}" w:type="dxa"/>'
            f'<w:tblInd w:w="{_tw(LEFT - TEXT_LEFT)}" w:type="dxa"/>'
            '<w:tblLayout w:type="fixed"/><w:tblCellMar><w:top w:w="0" w:type="dxa"/>'
            '<w:left w:w="0" w:type="dxa"/><w:bottom w:w="0" w:type="dxa"/>'
            '<w:right w:w="0" w:type="dxa"/></w:tblCellMar>'
            '<w:tblLook w:val="0000" w:firstRow="0" w:lastRow="0" w:firstColumn="0" '
            'w:lastColumn="0" w:noHBand="1" w:noVBand="1"/></w:tblPr>'
            f"<w:tblGrid>{grid}</w:tblGrid>{''.join(rows)}</w:tbl>")


def _spacer(mm: float) -> str:
    """An empty paragraph exactly ``mm`` high (the gap above a title block; the one Word needs
    after a table, 1 pt)."""
    return (f'<w:p {_W}><w:pPr><w:spacing w:before="0" w:after="0" w:line="{_tw(mm)}" '
            f'w:lineRule="exact"/><w:ind w:firstLine="0"/></w:pPr><w:r><w:rPr>'
            f'<w:sz w:val="2"/></w:rPr></w:r></w:p>')


def _frame_xml() -> str:
    """The frame: a VML rectangle anchored to the page, behind the text."""
    pt = PT_PER_MM
    style = (f"position:absolute;margin-left:{LEFT * pt:.2f}pt;margin-top:{MARGIN * pt:.2f}pt;"
             f"width:{(PAGE_W - LEFT - MARGIN) * pt:.2f}pt;height:{(PAGE_H - 2 * MARGIN) * pt:.2f}pt;"
             "z-index:-251658240;mso-position-horizontal-relative:page;"
             "mso-position-vertical-relative:page")
    return (f'<w:p {_W} {_V} {_O}><w:pPr><w:spacing w:before="0" w:after="0" w:line="20" '
            f'w:lineRule="exact"/><w:ind w:firstLine="0"/></w:pPr><w:r><w:pict>'
            f'<v:rect id="eskd-frame" style="{style}" filled="f" stroked="t" '
            f'strokecolor="black" strokeweight="{_line_mm("main") * pt:.2f}pt"/>'
            "</w:pict></w:r></w:p>")


FOOT_GAP_MM = 0.35                  # the 1 pt paragraph Word keeps after a footer's table


def docx_section(d, f, lang: str, note: str) -> None:
    """Start the framed section after the title page (which stays unframed, with no number):
    margins inside the frame, the frame in both headers, form 2 in the first page's footer,
    form 2a in the others'."""
    from docx.enum.section import WD_SECTION
    from docx.oxml import parse_xml
    from docx.shared import Mm

    first = d.sections[0]
    first.different_first_page_header_footer = False
    sec = d.add_section(WD_SECTION.NEW_PAGE)
    sec.left_margin, sec.right_margin = Mm(TEXT_LEFT), Mm(f.margin_right_mm)
    sec.top_margin, sec.bottom_margin = Mm(TEXT_TOP), Mm(TEXT_BOTTOM)
    sec.header_distance = Mm(MARGIN)
    sec.footer_distance = Mm(MARGIN - FOOT_GAP_MM)
    sec.different_first_page_header_footer = True
    for header in (sec.first_page_header, sec.header):
        header.is_linked_to_previous = False
        _replace(header._element, [parse_xml(_frame_xml())])
    for footer, form, gap in ((sec.first_page_footer, form2(), TEXT_GAP),
                              (sec.footer, form2a(), TEXT_GAP)):
        footer.is_linked_to_previous = False
        _replace(footer._element, [parse_xml(_spacer(gap)), parse_xml(table_xml(form, f, note, lang)),
                                   parse_xml(_spacer(FOOT_GAP_MM))])


def _replace(part_element, children) -> None:
    for child in list(part_element):
        part_element.remove(child)
    for child in children:
        part_element.append(child)
