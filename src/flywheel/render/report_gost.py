"""The Russian записка in PDF and DOCX laid out as a course project's пояснительная записка
(ГОСТ 7.32-2017, ГОСТ 2.105-2019; docs/report.md):

- A4; margins left 30, right 10 (``[document] margin_right_mm``), top and bottom 20 mm;
- a Times-metric serif with Cyrillic (Liberation Serif; :func:`font_paths` says where it is
  looked for and what stands in when it is absent) at 14 pt, 12 pt in tables (10 or 9 pt in a
  table of more than ``WIDE`` columns, as ГОСТ 2.105 allows), 1.5 line spacing, a 1.25 cm indent;
- a title page (:class:`~flywheel.render.blocks.TitlePage`), «Содержание» with page numbers,
  the sections numbered continuously (1, 1.1, …: the numbers the document model's headings carry
  are replaced by the layout's own), «Список использованных источников» unnumbered;
- «Рисунок N — …» under a figure, «Таблица N — …» above a table and kept with its first rows,
  «Продолжение таблицы N» above the rest of a table split across pages (the PDF; Word repeats
  the header row instead); page numbers at the bottom centre, none on the title page.

The DOCX is python-docx's template with its styles restyled (Normal, Heading 1–2, Caption,
Title, List Bullet, Table Grid), captions numbered by Word fields (SEQ Рисунок, SEQ Таблица),
the contents one line a heading with its page as a PAGEREF field to the heading's bookmark
(Word updates the fields on opening; LibreOffice lays them out with its own pages), numbers
right-aligned in the tables.
Heavy imports (typst, docx) inside the functions.
"""
from __future__ import annotations

import importlib.util
import io
import re
import shutil
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path

from flywheel.render import mathfmt
from flywheel.render.blocks import (Bullets, Document, Figure, Formula, Heading, Paragraph, Where,
                                    Table, TitlePage, section_numbers)
from flywheel.render.catalogue import words
from flywheel.render.typst_blocks import boxed_literal, markup, typst_block

#: a table of more columns than WIDE in 10 pt (9 pt beyond 9); of more than WIDE_PAGE
#: on a landscape page
WIDE, WIDE_PAGE = 7, 12

G = words("report_gost", {
    "contents": "Contents",
    "sources": "List of references",
    "note": "Explanatory note",
    "project": "to the course project in the theory of machines and mechanisms",
    "student": "Student",
    "group": "group",
    "teacher": "Teacher",
    "figure": "Figure",
    "table": "Table",
    "continued": "Continuation of table {n}",
})

#: an entry of the builders' list of sources («Источники», blocks.SOURCES), «[1] …»
_SOURCE_ENTRY = re.compile(r"^\[(\d+)\]\s*")

#: where the Times-metric serif is looked for (Debian/Ubuntu's fonts-liberation, Fedora's,
#: Arch's); $FLYWHEEL_FONTS (folders separated by os.pathsep) first
FONT_DIRS = ("/usr/share/fonts/truetype/liberation", "/usr/share/fonts/truetype/liberation2",
             "/usr/share/fonts/liberation-serif", "/usr/share/fonts/liberation",
             "/usr/share/fonts/TTF")
#: the families in order: the text's serif, then the fallbacks for what it lacks (DejaVu Serif:
#: ∮, sub-/superscript digits; DejaVu Sans: the combining arrow of a vector, g⃗), DejaVu shipped
#: with matplotlib (a dependency), so present everywhere
FAMILIES = ("Liberation Serif", "DejaVu Serif", "DejaVu Sans")


def font_files() -> list[Path]:
    """The font files of FAMILIES in the folders of :func:`font_paths` (typst is given these
    only: reading every font of matplotlib's folder took longer than the typesetting)."""
    stems = tuple(f.replace(" ", "") for f in FAMILIES)
    out = []
    for d in font_paths():
        for f in sorted(Path(d).glob("*.[ot]tf")):
            stem = f.stem.split("-")[0]
            if stem in stems:
                out.append(f)
    return out


def font_paths() -> list[str]:
    """The folders typst reads fonts from: $FLYWHEEL_FONTS, the first of FONT_DIRS holding
    Liberation Serif, matplotlib's own DejaVu fonts. Without Liberation Serif typst sets the text
    in DejaVu Serif (not Times-metric: the pages run longer; .ci/run installs fonts-liberation)."""
    import os

    out = [d for d in os.environ.get("FLYWHEEL_FONTS", "").split(os.pathsep) if d]
    for d in FONT_DIRS:
        if Path(d, "LiberationSerif-Regular.ttf").is_file():
            out.append(d)
            break
    spec = importlib.util.find_spec("matplotlib")
    if spec is not None and spec.submodule_search_locations:
        mpl = Path(list(spec.submodule_search_locations)[0]) / "mpl-data" / "fonts" / "ttf"
        if mpl.is_dir():
            out.append(str(mpl))
    return out


# -- the blocks as the layout numbers them ------------------------------------------------------
@dataclass(frozen=True)
class Section:
    """A heading as the layout sets it: its number ("" for a structural element), its level
    (1 a section, 2 a subsection), its text without the model's number."""

    number: str
    level: int
    text: str
    structural: bool = False


def sections(doc: Document) -> list:
    """The document's blocks for the ГОСТ layout: the title heading dropped (it is on the title
    page), every other heading renumbered continuously, the sources a structural element whose
    entries are numbered paragraphs «1. …» (ГОСТ 7.32-2017, 6.16: arabic numerals with a full
    stop, from the paragraph indent), not bullets «• [1] …»."""
    out, waiting, in_sources = [], [], False
    for b, number, text in section_numbers(doc.blocks):
        if in_sources and isinstance(b, Bullets):
            out += [Paragraph(_SOURCE_ENTRY.sub(r"\1. ", x, count=1)) for x in b.items]
            continue
        if not out and not (isinstance(b, Heading) and b.level >= 2):
            if not isinstance(b, Heading):      # the source of the data: into section 1
                waiting.append(b)
            continue
        if not isinstance(b, Heading):
            out.append(b)
        elif b.level >= 2:
            in_sources = number == ""
            if in_sources:
                out.append(Section("", 1, G[doc.lang]["sources"], True))
            elif b.level == 2:
                out.append(Section(number, 1, text.rstrip(".")))
                out += waiting
                waiting = []
            else:
                out.append(Section(number, 2, text.rstrip(".")))
    return out


def _front(doc: Document) -> TitlePage:
    return doc.front if doc.front is not None else TitlePage(machine=doc.title)


# -- typst / PDF --------------------------------------------------------------------------------
_lit = boxed_literal       # a run of text: string literals, a narrow no-break space as a box


def _ts(text: str) -> str:
    """Text as typst markup (render/typst_blocks.py): **bold**, the symbols' subscripts as #sub,
    a narrow no-break space as a box of its width."""
    return markup(text, boxed_literal)


#: the paragraphs' spacing of the ГОСТ layout (a lead-in's sticky block keeps it: typst_blocks)
PAR_SPACING = "1em"

_PREAMBLE = """#set document(title: {title}, date: none)
#set page(paper: "a4", margin: (left: 30mm, right: {right}mm, top: 20mm, bottom: 20mm),
  footer: context {{ if counter(page).get().first() > 1 {{ align(center, counter(page).display()) }} }})
#set text(font: ({fonts}), size: 14pt, lang: "ru", hyphenate: true)
#set par(justify: true, leading: 1em, spacing: {spacing}, first-line-indent: (amount: 1.25cm, all: true))
#show heading: set text(size: 14pt, weight: "bold")
#show heading: it => block(above: 1.5em, below: 1em, sticky: true, width: 100%,
  if it.supplement == [S] {{ align(center, it.body) }} else {{ h(1.25cm) + it.body }})
#set list(indent: 1.25cm)
#show math.equation: set text(font: ("New Computer Modern Math", {fonts}))
#set math.equation(numbering: "(1)")
#set table(stroke: 0.5pt)
"""


def _title_page(f: TitlePage, g: dict, page: str = "footer: none") -> str:
    blank = "#box(width: 45mm, stroke: (bottom: 0.5pt))"

    def line(value: str, width: str = "45mm") -> str:
        return _ts(value) if value else f"#box(width: {width}, stroke: (bottom: 0.5pt))"

    top = ([_ts(f.ministry)] if f.ministry else []) + [line(x, "120mm") for x in (f.university,
                                                                                    f.department)]
    out = [f"#page({page})[",
           "#set par(first-line-indent: 0pt, justify: false, leading: 0.65em)",
           "#align(center)[" + " \\\n#v(0.4em)".join(top) + "]",
           "#v(1fr)",
           f"#align(center)[#text(weight: \"bold\", size: 16pt)[{_ts(g['note'].upper())}] \\\n"
           f"{_ts(g['project'])} \\\n#v(0.6em)#text(weight: \"bold\")[«{_ts(f.machine)}»]"
           + (f" \\\n#v(0.6em){_ts(f.designation)} ПЗ" if f.designation else "") + "]",
           "#v(1fr)",
           "#align(right)[#grid(columns: (auto, auto), column-gutter: 4mm, row-gutter: 1.2em, align: left,",
           f"  [{_ts(g['student'])} {_ts(g['group'])} {line(f.group, '25mm')}], [{blank} {line(f.student)}],",
           f"  [{_ts(g['teacher'])}], [{blank} {line(f.teacher)}])]",
           "#v(1fr)",
           "#align(center)[" + (_ts(f.city) if f.city else "#box(width: 30mm, stroke: (bottom: 0.5pt))")
           + " " + (_ts(f.year) if f.year else "#box(width: 15mm, stroke: (bottom: 0.5pt))") + "]",
           "]"]
    return "\n".join(x for x in out if x)


def typst_source(doc: Document, plots: bool = True) -> str:
    """The Russian записка as a typst file in the ГОСТ layout (figures as plots/<name>; none
    when ``plots`` is false)."""
    g = G[doc.lang]
    f = _front(doc)
    fonts = ", ".join(f'"{x}"' for x in FAMILIES)
    contents = [f"#align(center)[#text(weight: \"bold\")[{_ts(g['contents'].upper())}]]",
                "#outline(title: none, indent: 1.25cm, depth: 2)"]
    landscape = "flipped: true"
    out = [_PREAMBLE.format(title=_ts(doc.title)[1:] or '""', right=f"{f.margin_right_mm:g}",
                            fonts=fonts, spacing=PAR_SPACING)]
    if f.frame == "eskd":                       # the ЕСКД frame (render/report_frame.py)
        from flywheel.render import report_frame as rf

        landscape = rf.typst_landscape(f)
        out += [rf.typst_preamble(f, doc.lang, g["note"]),
                _title_page(f, g, "footer: none, " + rf.typst_title_margins(f)),
                f"#page({rf.typst_contents_page(f)})[",
                contents[0] + " <eskd-contents>", contents[1], "]", ""]
    else:
        out += [_title_page(f, g), *contents, ""]
    for b in sections(doc):
        if isinstance(b, Section):
            body = _ts(b.text.upper() if b.structural else b.text)
            if b.level == 1:
                out.append("#pagebreak(weak: true)")
            if b.structural:
                out.append(f"#heading(level: 1, numbering: none, supplement: [S])[{body}]")
            else:
                out.append(f"#heading(level: {b.level}, numbering: none)[{_lit(b.number)}#h(0.6em){body}]")
        elif (lines := typst_block(b, _ts, PAR_SPACING)) is not None:  # a paragraph, a list, a formula
            out += lines
        elif isinstance(b, Table):
            out.append(_table(b, g, landscape))
        elif isinstance(b, Figure):
            cap = _ts(f"{g['figure']} {b.number} — {b.caption}")
            img = f'image("plots/{b.file}", width: 100%), ' if plots else ""
            out.append(f"#figure({img}numbering: none, gap: 0.8em, "
                       f"caption: [#set par(first-line-indent: 0pt); {cap}])")
        out.append("")
    return "\n".join(out)


#: a table of at most this many rows is kept on one page (moved whole to the next where it
#: does not fit), not split with a row or two under «Продолжение таблицы N»
SHORT_TABLE = 15


def _table(b: Table, g: dict, landscape: str = "flipped: true") -> str:
    """A table under its caption «Таблица N — …» (a sticky block: never left at the foot of a
    page without the table), its header row repeated on each page it runs onto with
    «Продолжение таблицы N» above it; the first column left, the numbers right; a short one
    (:data:`SHORT_TABLE`) never split."""
    n = len(b.header)
    size = "12pt" if n <= WIDE else "10pt" if n <= 9 else "9pt"
    label = f"gost-table-{b.number}"
    first = _ts(f"{g['table']} {b.number} — {b.caption}")
    later = _ts(g["continued"].format(n=b.number))
    cont = (f"table.cell(colspan: {n}, stroke: none, inset: 0pt, context {{ "
            f"if here().page() != locate(<{label}>).page() {{ box(height: 1.6em, place(left + horizon, "
            f"box(width: 120mm)[{later}])) }} }})")
    head = ", ".join(f"table.cell(align: center + horizon)[#strong[{_ts(c)}]]" for c in b.header)
    cells = ", ".join(f"[{_ts(c)}]" for r in b.rows for c in r)
    src = (f"#block(sticky: true, above: 1.2em, below: 0.5em)[#set par(first-line-indent: 0pt, "
           f"justify: false); {first}]\n"
           f"#[#set text(size: {size})\n#set par(first-line-indent: 0pt, justify: false, leading: 0.5em)\n"
           f"#block(breakable: {'false' if len(b.rows) <= SHORT_TABLE else 'true'})["
           f"#table(columns: {n}, inset: (x: 2.5pt, y: 4pt), "
           f"align: (x, y) => if x == 0 {{ left + horizon }} else {{ right + horizon }},\n"
           f"table.header(repeat: true, {cont}, {head}),\n{cells}) <{label}>]]")
    return f"#page({landscape})[\n{src}\n]" if n > WIDE_PAGE else src


def compile_typst(src: str, doc: Document, plots_dir: Path | None, fonts=()) -> bytes:
    """The typst source ``src`` compiled to PDF in a scratch folder holding the figures of
    ``doc`` found in ``plots_dir`` (as plots/…) and the font files ``fonts`` (linked); no
    system fonts and a fixed timestamp, so the bytes are the same on a rerun."""
    import typst

    with tempfile.TemporaryDirectory(prefix="flywheel-typst-") as tmp:
        root = Path(tmp)
        (root / "plots").mkdir()
        for f in doc.figures:
            if plots_dir is not None and (plots_dir / f.file).is_file():
                shutil.copyfile(plots_dir / f.file, root / "plots" / f.file)
        (root / "main.typ").write_text(src, encoding="utf-8")
        font_dir = root / "fonts"
        font_dir.mkdir()
        for f in fonts:
            if not (font_dir / f.name).exists():
                (font_dir / f.name).symlink_to(f)
        return typst.compile(str(root / "main.typ"), root=str(root), format="pdf",
                             font_paths=[str(font_dir)], ignore_system_fonts=True, timestamp=0)


def pdf(doc: Document, plots_dir: Path | None = None) -> bytes:
    """The Russian записка as PDF (typst) in the ГОСТ layout."""
    fonts = font_files()
    if _front(doc).frame == "eskd":             # the title blocks' lettering
        from flywheel.render.report_frame import font_file

        fonts.append(font_file())
    return compile_typst(typst_source(doc, plots_dir is not None), doc, plots_dir, fonts)


# -- DOCX ---------------------------------------------------------------------------------------
def _fixed_zip(data: bytes) -> bytes:
    """The zip with every entry dated 1980-01-01 (python-docx stamps the current time)."""
    src = zipfile.ZipFile(io.BytesIO(data))
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            dst.writestr(zipfile.ZipInfo(info.filename, date_time=(1980, 1, 1, 0, 0, 0)),
                         src.read(info.filename), compress_type=zipfile.ZIP_DEFLATED)
    return buf.getvalue()


_SERIF = "Times New Roman"          # Word's Times; LibreOffice sets it in Liberation Serif


def _styles(d) -> None:
    """python-docx's template restyled to the layout: black serif 14 pt, 1.5 lines, 1.25 cm indent."""
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_LINE_SPACING
    from docx.oxml.ns import qn
    from docx.shared import Cm, Pt, RGBColor

    def font(style, size, bold=False, italic=False):
        style.font.name, style.font.size = _SERIF, Pt(size)
        style.font.bold, style.font.italic = bold, italic
        style.font.color.rgb = RGBColor(0, 0, 0)
        rpr = style.element.get_or_add_rPr()
        fonts = rpr.find(qn("w:rFonts"))
        for attr in ("w:ascii", "w:hAnsi", "w:cs", "w:eastAsia"):
            fonts.set(qn(attr), _SERIF)
        for attr in ("w:asciiTheme", "w:hAnsiTheme", "w:cstheme", "w:eastAsiaTheme"):
            fonts.attrib.pop(qn(attr), None)

    normal = d.styles["Normal"]
    font(normal, 14)
    pf = normal.paragraph_format
    pf.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
    pf.first_line_indent, pf.space_before, pf.space_after = Cm(1.25), Pt(0), Pt(0)
    pf.alignment = WD_ALIGN_PARAGRAPH.JUSTIFY
    for name in ("Heading 1", "Heading 2"):
        h = d.styles[name]
        font(h, 14, bold=True)
        h.paragraph_format.first_line_indent = Cm(1.25)
        h.paragraph_format.space_before, h.paragraph_format.space_after = Pt(12), Pt(12)
        h.paragraph_format.keep_with_next = True
        h.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.LEFT
        h.paragraph_format.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
    d.styles["Heading 1"].paragraph_format.page_break_before = True
    title = d.styles["Title"]
    font(title, 14, bold=True)
    title.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.CENTER
    title.paragraph_format.first_line_indent = Cm(0)
    if title.element.pPr is not None:
        title.element.pPr.remove_all("w:pBdr")
    cap = d.styles["Caption"]
    font(cap, 14)
    cap.paragraph_format.first_line_indent = Cm(0)
    # a table's caption at the left (ГОСТ 7.32-2017, 6.6.3), not justified as Normal is: a
    # caption of two lines had had its first stretched across the page
    cap.paragraph_format.alignment = WD_ALIGN_PARAGRAPH.LEFT
    cap.paragraph_format.space_before, cap.paragraph_format.space_after = Pt(6), Pt(6)
    cap.paragraph_format.line_spacing_rule = WD_LINE_SPACING.SINGLE
    lst = d.styles["List Bullet"]
    font(lst, 14)
    lst.paragraph_format.first_line_indent = Cm(0)


#: the elements of w:settings that come after w:updateFields in the schema's sequence (ECMA-376
#: part 1, 17.15.1.78 settings: … alwaysMergeEmptyNamespace, updateFields, hdrShapeDefaults, …)
_AFTER_UPDATE_FIELDS = frozenset((
    "hdrShapeDefaults", "footnotePr", "endnotePr", "compat", "docVars", "rsids", "mathPr",
    "attachedSchema", "themeFontLang", "clrSchemeMapping", "doNotIncludeSubdocsInStats",
    "doNotAutoCompressPictures", "forceUpgrade", "captions", "readModeInkLockDown",
    "smartTagType", "schemaLibrary", "shapeDefaults", "doNotEmbedSmartTags", "decimalSymbol",
    "listSeparator", "docId", "chartTrackingRefBased", "defaultImageDpi", "conflictMode"))


def _update_fields_on_open(settings) -> None:
    """``<w:updateFields w:val="true"/>`` in the document's settings, where the schema's
    sequence puts it (before w:compat, w:rsids, …; Word may ignore or refuse an element out of
    its order): Word asks to update the fields on opening (the contents' pages, the captions'
    numbers)."""
    from docx.oxml import parse_xml

    flag = parse_xml(f'<w:updateFields {_W} w:val="true"/>')
    later = [c for c in settings if c.tag.rsplit("}", 1)[-1] in _AFTER_UPDATE_FIELDS]
    if later:
        later[0].addprevious(flag)
    else:
        settings.append(flag)


def _field(p, instr: str, shown: str) -> None:
    """A Word field (SEQ, PAGE) in paragraph ``p``, its last result ``shown``."""
    from docx.oxml import parse_xml

    w = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
    p._p.append(parse_xml(f'<w:fldSimple {w} w:instr=" {instr} "><w:r><w:t xml:space="preserve">'
                          f'{shown}</w:t></w:r></w:fldSimple>'))


_W = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
_M = 'xmlns:m="http://schemas.openxmlformats.org/officeDocument/2006/math"'


def _r(text: str, bold: bool = False, sub: bool = False, half_points: int | None = None) -> str:
    """A run of text as WordprocessingML (rPr in the schema's order: b, sz, vertAlign)."""
    from xml.sax.saxutils import escape

    props = (("<w:b/>" if bold else "") + (f'<w:sz w:val="{half_points}"/><w:szCs w:val="{half_points}"/>'
                                           if half_points else "")
             + ('<w:vertAlign w:val="subscript"/>' if sub else ""))
    return (f"<w:r>{f'<w:rPr>{props}</w:rPr>' if props else ''}"
            f'<w:t xml:space="preserve">{escape(text)}</w:t></w:r>')


def _runs(text: str, bold: bool = False, half_points: int | None = None) -> str:
    """**bold** runs and the symbols' subscripts (J_II, ΔT_нб) as subscript runs."""
    return "".join(_r(seg, bold or i % 2 == 1, sub, half_points)
                   for i, part in enumerate(text.split("**")) if part
                   for seg, sub in mathfmt.subscripts(part) if seg)


def _p(inner: str, style: str | None = None, jc: str | None = None, indent: bool = False,
       keep: bool = False, single: bool = False) -> str:
    """A paragraph (pPr in the schema's order: pStyle, keepNext, spacing, ind, jc)."""
    props = ((f'<w:pStyle w:val="{style}"/>' if style else "") + ("<w:keepNext/>" if keep else "")
             + ('<w:spacing w:after="0" w:line="240" w:lineRule="auto"/>' if single else "")
             + ('<w:ind w:firstLine="0"/>' if indent else "") + (f'<w:jc w:val="{jc}"/>' if jc else ""))
    return f"<w:p>{f'<w:pPr>{props}</w:pPr>' if props else ''}{inner}</w:p>"


def _numbered_formula(math: str, number: int, width: int) -> str:
    """A formula's paragraph: the formula at a centre tab stop in the middle of the text's
    ``width`` [twips], its number «(n)» at a right tab stop at the margin — as ГОСТ 7.32-2017,
    6.8.3 numbers formulas (the PDF's typst does the same by its equation numbering)."""
    tabs = (f'<w:tabs><w:tab w:val="center" w:pos="{width // 2}"/>'
            f'<w:tab w:val="right" w:pos="{width}"/></w:tabs>')
    return (f'<w:p><w:pPr>{tabs}<w:ind w:firstLine="0"/></w:pPr><w:r><w:tab/></w:r>{math}'
            f'<w:r><w:tab/><w:t xml:space="preserve">({number})</w:t></w:r></w:p>')


#: the children of w:pPr after w:framePr in the schema's sequence (ECMA-376 part 1, 17.3.1.26)
_AFTER_FRAME = frozenset((
    "widowControl", "numPr", "suppressLineNumbers", "pBdr", "shd", "tabs", "suppressAutoHyphens",
    "kinsoku", "wordWrap", "overflowPunct", "topLinePunct", "autoSpaceDE", "autoSpaceDN", "bidi",
    "adjustRightInd", "snapToGrid", "spacing", "ind", "contextualSpacing", "mirrorIndents",
    "suppressOverlap", "jc", "textDirection", "textAlignment", "textboxTightWrap",
    "outlineLvl", "divId", "cnfStyle", "rPr", "sectPr", "pPrChange"))


def _at_foot(p) -> None:
    """Paragraph ``p`` (the title page's city and year) in a frame at the foot of the page's
    text, centred (w:framePr, where the schema's sequence puts it): ГОСТ 7.32 sets them at the
    bottom of the title page, whatever the lines above take."""
    from docx.oxml import parse_xml

    frame = parse_xml(f'<w:framePr {_W} w:hAnchor="margin" w:vAnchor="margin" '
                      'w:xAlign="center" w:yAlign="bottom" w:wrap="around"/>')
    ppr = p._p.get_or_add_pPr()
    later = [c for c in ppr if c.tag.rsplit("}", 1)[-1] in _AFTER_FRAME]
    if later:
        later[0].addprevious(frame)
    else:
        ppr.append(frame)


def _marked(inner: str, k: int) -> str:
    """A heading's runs within the bookmark ``_Toc{k}`` its contents entry refers to."""
    return (f'<w:bookmarkStart w:id="{k}" w:name="_Toc{k}"/>{inner}'
            f'<w:bookmarkEnd w:id="{k}"/>')


def _toc(heads: list, width: int) -> str:
    """The contents: one paragraph a heading (``heads``, the record's sections in order), its
    number and name linked to it, a dot leader to a right tab at the text's ``width``
    [twips], then its page as the field ``PAGEREF _Toc{k} \\h`` to the bookmark
    :func:`_marked` puts round the k-th heading, its result left empty: Word updates the
    fields on opening (w:updateFields), LibreOffice lays them out with its own pages, so no
    page is guessed here. Not a TOC field: LibreOffice shows a TOC field's last result as it
    is, and would print the contents without pages (the PAGEREF fields within it frozen)."""
    from xml.sax.saxutils import escape

    out = []
    for k, s in enumerate(heads, start=1):
        text = escape((s.number + " " if s.number else "")
                      + (s.text.upper() if s.structural else s.text))
        indent = 0 if s.structural or s.level == 1 else 280
        props = (f'<w:tabs><w:tab w:val="right" w:leader="dot" w:pos="{width}"/></w:tabs>'
                 f'<w:spacing w:after="0"/><w:ind w:left="{indent}" w:right="560" '
                 'w:firstLine="0"/><w:jc w:val="left"/>')
        page = _simple_field(f"PAGEREF _Toc{k} \\h")
        out.append(f'<w:p><w:pPr>{props}</w:pPr><w:hyperlink w:anchor="_Toc{k}" w:history="1">'
                   f'<w:r><w:t xml:space="preserve">{text}</w:t></w:r><w:r><w:tab/></w:r>{page}'
                   f'</w:hyperlink></w:p>')
    return "".join(out)


def _simple_field(instr: str, shown: str = "") -> str:
    """A Word field (w:fldSimple) as WordprocessingML, its last result ``shown``."""
    return f'<w:fldSimple w:instr=" {instr} "><w:r><w:t>{shown}</w:t></w:r></w:fldSimple>'


def _seq(name: str, number: int) -> str:
    """A caption's number as the Word field SEQ ``name`` (its shown value ``number``)."""
    return _simple_field(f"SEQ {name} \\* ARABIC", str(number))


def _table_xml(b: Table, width: int) -> str:
    """A table in the grid style, centred, its header row bold, centred and repeated on every
    page it runs onto (a short one, :data:`SHORT_TABLE`, kept on one page: each row's
    paragraphs kept with the next); the first column left, the numbers right; 12 pt (10 pt if wide, 9 pt
    beyond 9 columns, the cells' margins then 1 mm), single;
    its columns' widths fixed within the text's ``width`` [twips] (render/table_widths.py: left
    to LibreOffice, they were equal and broke words)."""
    from flywheel.render.table_widths import MARGIN, NARROW_MARGIN, column_widths

    n = len(b.header)
    hp = 24 if n <= WIDE else 20 if n <= 9 else 18          # as the PDF: 12, 10, 9 pt
    margin = MARGIN if n <= WIDE else NARROW_MARGIN
    widths = column_widths([tuple(b.header), *b.rows], width, hp, margin=margin)
    rows = []
    short = len(b.rows) <= SHORT_TABLE      # kept on one page: each row with the next
    for r, cells in enumerate((b.header, *b.rows)):
        keep = r == 0 or (short and r < len(b.rows))
        tcs = "".join(
            f'<w:tc><w:tcPr><w:tcW w:w="{widths[c]}" w:type="dxa"/></w:tcPr>'
            + _p(_runs(text, bold=r == 0, half_points=hp), keep=keep, single=True, indent=True,
                 jc="center" if r == 0 else "left" if c == 0 else "right") + "</w:tc>"
            for c, text in enumerate(cells))
        rows.append(f"<w:tr>{'<w:trPr><w:tblHeader/></w:trPr>' if r == 0 else ''}{tcs}</w:tr>")
    grid = "".join(f'<w:gridCol w:w="{w}"/>' for w in widths)
    return ('<w:tbl><w:tblPr><w:tblStyle w:val="TableGrid"/>'
            f'<w:tblW w:w="{sum(widths)}" w:type="dxa"/><w:jc w:val="center"/>'
            '<w:tblLayout w:type="fixed"/>'
            + (f'<w:tblCellMar><w:left w:w="{margin}" w:type="dxa"/><w:right w:w="{margin}" '
               'w:type="dxa"/></w:tblCellMar>' if margin != MARGIN else '')
            + '<w:tblLook w:val="04A0" w:firstRow="1" w:lastRow="0" '
            'w:firstColumn="1" w:lastColumn="0" w:noHBand="0" w:noVBand="1"/></w:tblPr>'
            f'<w:tblGrid>{grid}</w:tblGrid>{"".join(rows)}</w:tbl>')


def docx(doc: Document, plots_dir: Path | None = None) -> bytes:
    """The Russian записка as Word in the ГОСТ layout (the module's docstring)."""
    import docx as pydocx
    from docx.enum.text import WD_ALIGN_PARAGRAPH, WD_BREAK
    from docx.oxml import parse_xml
    from docx.shared import Cm, Mm, Pt

    from flywheel.render.table_widths import section_width

    g, f = G[doc.lang], _front(doc)
    d = pydocx.Document()
    _styles(d)
    sec = d.sections[0]
    sec.page_width, sec.page_height = Mm(210), Mm(297)
    sec.left_margin, sec.right_margin = Mm(30), Mm(f.margin_right_mm)
    sec.top_margin = sec.bottom_margin = Mm(20)
    sec.header_distance, sec.footer_distance = Mm(10), Mm(10)
    framed = f.frame == "eskd"                               # render/report_frame.py
    if not framed:
        sec.different_first_page_header_footer = True       # no number on the title page
        foot = sec.footer.paragraphs[0]
        foot.alignment = WD_ALIGN_PARAGRAPH.CENTER
        foot.paragraph_format.first_line_indent = Cm(0)
        _field(foot, "PAGE", "2")
    import datetime

    fixed = datetime.datetime(2000, 1, 1)
    cp = d.core_properties
    cp.created = cp.modified = cp.last_printed = fixed
    cp.title, cp.author, cp.last_modified_by, cp.revision = doc.title, "flywheel", "flywheel", 1
    _update_fields_on_open(d.settings.element)              # Word updates the fields on opening

    def runs(p, text: str, size=None, bold: bool = False):
        for i, part in enumerate(text.split("**")):
            for seg, sub in mathfmt.subscripts(part) if part else ():
                if seg:
                    r = p.add_run(seg)
                    r.bold = bold or i % 2 == 1 or None
                    if sub:
                        r.font.subscript = True
                    if size is not None:
                        r.font.size = size

    def plain(text: str = "", align=WD_ALIGN_PARAGRAPH.CENTER, bold=False, size=None):
        p = d.add_paragraph()
        p.alignment = align
        p.paragraph_format.first_line_indent = Cm(0)
        if text:
            runs(p, text, size, bold)
        return p

    # the title page
    if f.ministry:
        plain(f.ministry)
    for x in (f.university, f.department):
        plain(x or "_" * 40)
    for _ in range(6):
        plain()
    plain(g["note"].upper(), bold=True, size=Pt(16))
    plain(g["project"])
    plain(f"«{f.machine}»", bold=True)
    if f.designation:
        plain(f"{f.designation} ПЗ")
    for _ in range(6):
        plain()
    line, blank = "_" * 14, "_" * 20
    plain(f"{g['student']} {g['group']} {f.group or line}   {line}   {f.student or blank}",
          align=WD_ALIGN_PARAGRAPH.RIGHT)
    plain(f"{g['teacher']}   {line}   {f.teacher or blank}", align=WD_ALIGN_PARAGRAPH.RIGHT)
    for _ in range(6):
        plain()
    _at_foot(plain(f"{f.city or '__________'} {f.year or '____'}"))     # ГОСТ 7.32: the foot
    if framed:                          # the frame's section: on a new page
        from flywheel.render.report_frame import docx_section

        docx_section(d, f, doc.lang, g["note"])
    else:
        plain().add_run().add_break(WD_BREAK.PAGE)

    # the contents: a line a heading, its page a PAGEREF field to the heading's bookmark
    p = d.add_paragraph(style="Title")
    p.add_run(g["contents"].upper())
    body = list(sections(doc))
    w = 'xmlns:w="http://schemas.openxmlformats.org/wordprocessingml/2006/main"'
    sect = d.element.body.sectPr
    width = section_width(sec)                                  # [twips]
    heads = [b for b in body if isinstance(b, Section)]

    def put(xml: str) -> None:
        """Blocks of WordprocessingML written here (python-docx's element API takes seconds for
        the record's ~1 000 runs), one parse for each, placed before the section's settings."""
        for element in list(parse_xml(f'<w:body {w} {_M}>{xml}</w:body>')):
            sect.addprevious(element)

    put(_toc(heads, width))

    k = 0                                   # the heading's number: its bookmark _Toc{k}
    formulas = 0                            # the formulas numbered through the record
    for b in body:
        if isinstance(b, Section):
            k += 1
            if b.structural:
                put(_p(_marked(_r(b.text.upper()), k), style="Heading1", jc="center",
                       indent=True))
            else:
                put(_p(_marked(_runs(f"{b.number} {b.text}"), k), style=f"Heading{b.level}"))
        elif isinstance(b, Where):              # left-aligned: a line before a break is not
            put(_p("<w:r><w:br/></w:r>".join(_runs(line) for line in b.lines), jc="left"))
        elif isinstance(b, Paragraph):           # one leading into a formula: kept with it
            put(_p(_runs(b.text), keep=b.leads_in))
        elif isinstance(b, Bullets):
            for i in b.items:
                put(_p(_runs(i), style="ListBullet"))
        elif isinstance(b, Formula):        # centred, its number at the right margin
            formulas += 1                       # (ГОСТ 7.32-2017, 6.8.3)
            put(_numbered_formula(mathfmt.omml_inline(b.tex), formulas, width))
        elif isinstance(b, Table):
            put(_p(_r(g["table"] + " ") + _seq(g["table"], b.number) + _runs(f" — {b.caption}"),
                   style="Caption", keep=True))
            put(_table_xml(b, width))
            put(_p("", single=True))
        elif isinstance(b, Figure):
            if plots_dir is not None and (plots_dir / b.file).is_file():
                inline = d.part.new_pic_inline(str(plots_dir / b.file), Mm(165), None)
                pic = d.add_paragraph()
                pic.alignment = WD_ALIGN_PARAGRAPH.CENTER
                pic.paragraph_format.first_line_indent = Cm(0)
                pic.paragraph_format.keep_with_next = True
                pic.add_run()._r.add_drawing(inline)
            put(_p(_r(g["figure"] + " ") + _seq(g["figure"], b.number) + _runs(f" — {b.caption}"),
                   style="Caption", jc="center"))
    return _package(d)


def _package(d) -> bytes:
    """The document's package as python-docx's ``save`` writes it, in one pass: every entry
    dated 1980-01-01 (reruns identical), the PNGs stored (compressed already; deflating them
    again was most of the writing time)."""
    from docx.opc.pkgwriter import PackageWriter

    class Writer:
        def __init__(self, z):
            self.z = z

        def write(self, uri, blob) -> None:
            name = uri.membername
            self.z.writestr(zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0)), blob,
                            compress_type=zipfile.ZIP_STORED if name.endswith(".png")
                            else zipfile.ZIP_DEFLATED)

    pkg = d.part.package
    for part in pkg.parts:
        part.before_marshal()
    buf = io.BytesIO()
    with zipfile.ZipFile(buf, "w", zipfile.ZIP_DEFLATED) as z:
        w = Writer(z)
        parts = list(pkg.parts)
        PackageWriter._write_content_types_stream(w, parts)
        PackageWriter._write_pkg_rels(w, pkg.rels)
        PackageWriter._write_parts(w, parts)
    return buf.getvalue()
