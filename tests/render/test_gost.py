"""Issue 28, items 3, 5 and 6 (glyphs): Russian typography through the one number formatter
(render/numbers.py) and the ГОСТ 7.32 layout of the Russian PDF and DOCX (render/report_gost.py),
read back with pypdf and python-docx."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render.numbers import MINUS, THIN, fmt, typography

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
A4 = (595.28, 841.89)           # pt: 210 × 297 mm


# -- the Russian policy -------------------------------------------------------------------------
@pytest.mark.parametrize("x, kw, text", [
    (-12345.678, {}, f"{MINUS}12{THIN}346"),      # whole above four digits, grouped, true minus
    (1234.5678, {}, "1235"),                       # four digits: not grouped
    (0.0496522, {}, "0,04965"),                    # four significant digits, decimal comma
    (9.9996, {}, "10"),
    (0.1 + 0.2, {}, "0,3"),
    (1.5e-5, {}, "0,000015"),                      # small but real: fixed notation
    (5.7e-14, {}, "0"), (-8.882e-15, {}, "0"),     # round-off: 0, no sign, no exponent
    (-0.0, {}, "0"), (None, {}, "—"),
    (142.8, {"spec": ".2f"}, "142,80"),            # an f spec keeps its decimals
    (2.31e-15, {"spec": ".2e"}, "0"),
    (1800.0, {"spec": "+.1e"}, "+1800"),
    (0.086603, {"given": True}, "0,086603"),       # an input: the digits it was given
    (123456.0, {"given": True}, f"123{THIN}456"),
    (-2.5e-6, {"given": True}, f"{MINUS}0,0000025"),
])
def test_the_russian_policy(x, kw, text):
    with typography("ru"):
        assert fmt(x, 6, **kw) == text


def test_the_noise_the_formatter_is_told():
    with typography("ru", noise=1e-3):
        assert fmt(5e-4) == "0" and fmt(2e-3) == "0,002"
    with typography("ru"):
        assert fmt(5e-4) == "0,0005"


def test_english_and_outside_the_block_unchanged():
    with typography("en"):
        assert fmt(1234567.0) == "1.23457e+06" and fmt(-2.5) == "-2.5"
    with typography("ru"):
        pass
    assert fmt(1234567.0) == "1.23457e+06" and fmt(0.0496522, 4) == "0.04965"


def test_a_warning_in_a_russian_document_has_russian_numbers():
    from flywheel.errors import Notice
    from flywheel.render.messages import message

    n = Notice("δ = 0.5: the speed swings by more than 30 % of the mean", "duty_delta_large",
               delta=0.5)
    assert "δ = 0.5" in message(n, "ru")                   # stderr: as before
    with typography("ru"):
        assert "δ = 0,5" in message(n, "ru")


# -- the records of a run -----------------------------------------------------------------------
@pytest.fixture(scope="module")
def gost_run(tmp_path_factory):
    """compressor.toml with a [document] table (right margin 15 mm) in Russian, every format;
    --teacher over the case's teacher."""
    root = tmp_path_factory.mktemp("gost")
    case = root / "case.toml"
    case.write_text((CASES / "compressor.toml").read_text(encoding="utf-8") + """
[document]
student = "Иванов И. И."
group = "МТ-301"
teacher = "Петров П. П."
university = "Университет машиностроения"
department = "Кафедра теории механизмов и машин"
city = "Москва"
year = 2026
margin_right_mm = 15
""", encoding="utf-8")
    out = root / "o"
    res = runner.invoke(app, ["run", str(case), "--out", str(out), "--points", "360", "--lang", "ru",
                              "--report", "md", "--report", "pdf", "--report", "docx",
                              "--teacher", "Сидоров С. С."])
    assert res.exit_code == 0, res.output
    return out


def _model(lang="ru"):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typeset

    c = load_case(CASES / "compressor.toml")
    return typeset(lang, build_document, analyze(c, n_points=360), lang, [], case=c)


@pytest.mark.slow
def test_the_russian_record_has_russian_numbers(gost_run):
    md = (gost_run / "report.md").read_text(encoding="utf-8")
    body = [ln for ln in md.splitlines() if not ln.startswith(("- [", "Источник"))]  # sources as given
    text = "\n".join(body)
    assert not re.search(r"\d[eE][-+]?\d", text), "e-notation"
    cells = [c.strip() for ln in body if ln.startswith("|") for c in ln.strip("|").split("|")]
    numbers = [c for c in cells if re.fullmatch(r"[−+]?[\d\u202f]+(,\d+)?", c)]
    assert len(numbers) > 200
    assert not [c for c in cells if re.fullmatch(r"-?\d+\.\d+", c)], "a decimal point"
    assert not [c for c in cells if re.fullmatch(r"-\d[\d.,]*", c)], "a hyphen-minus"
    assert any(c.startswith(MINUS) for c in numbers) and any("," in c for c in numbers)


@pytest.mark.slow
def test_the_pdf_is_a4_with_title_page_and_contents(gost_run):
    import pypdf

    pdf = pypdf.PdfReader(str(gost_run / "report.pdf"))
    for p in pdf.pages:
        size = sorted((float(p.mediabox.width), float(p.mediabox.height)))
        assert size == pytest.approx(sorted(A4), abs=0.5)
    pages = [p.extract_text() for p in pdf.pages]
    title = " ".join(pages[0].split())
    for words in ("ПОЯСНИТЕЛЬНАЯ ЗАПИСКА", "к курсовому проекту по теории механизмов и машин",
                  "Университет машиностроения", "Кафедра теории механизмов и машин",
                  "Иванов И. И.", "МТ-301", "Сидоров С. С.", "Москва 2026"):
        assert words in title, words
    assert "Петров" not in title                       # --teacher over the case's
    assert "СОДЕРЖАНИЕ" in pages[1]
    # the contents: sections numbered 1, 2, 3, … without a gap, each with its page number
    sections = [int(m.group(1)) for m in re.finditer(r"^(\d+) \D.*?\d+$", pages[1], re.M)]
    assert sections == list(range(1, len(sections) + 1)) and len(sections) >= 6
    assert "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ" in pages[1] and "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ" in pages[-1]
    # the sources numbered «1. …», «2. …» (ГОСТ 7.32-2017, 6.16), no bullets, no «[1]»
    sources = pages[-1].split("СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ", 1)[1]
    assert re.search(r"^1\. Исходные данные", sources, re.M)
    assert re.search(r"^2\. Артоболевский", sources, re.M)
    assert "[1]" not in sources and "•" not in sources
    whole = "\n".join(pages)
    # the compressor's tables are all short, none split: a continued table is
    # test_a_short_table_is_never_split_a_long_one_is_continued's
    assert "Продолжение таблицы" not in whole
    assert re.search(r"Таблица 1 — ", whole) and re.search(r"Рисунок 1 — ", whole)
    # page numbers at the foot, none on the title page
    assert not pages[0].rstrip().endswith("1")
    assert pages[2].rstrip().endswith("3")


@pytest.mark.slow
def test_a_short_table_is_never_split_a_long_one_is_continued():
    """engine_inline4's Russian record: no table of SHORT_TABLE rows or fewer runs onto the next
    page (the masses' had left its last row under «Продолжение таблицы 3», a cylinder's
    indicator diagram two); the long ones (the positions) still continue, headed so; the DOCX
    keeps a short table's rows each with the next (Word's way of keeping it on one page)."""
    import io
    import zipfile

    import pypdf

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render import report_gost
    from flywheel.render.blocks import Table
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typeset

    c = load_case(CASES / "engine_inline4.toml")
    doc = typeset("ru", build_document, analyze(c, n_points=360), "ru", [], case=c)
    tables = [b for b in report_gost.sections(doc) if isinstance(b, Table)]
    short = [b.number for b in tables if len(b.rows) <= report_gost.SHORT_TABLE]
    assert len(short) > 10 and len(short) < len(tables)
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(io.BytesIO(
        report_gost.pdf(doc, None))).pages)
    continued = {int(n) for n in re.findall(r"Продолжение таблицы (\d+)", text)}
    assert continued and not continued & set(short)
    xml = zipfile.ZipFile(io.BytesIO(report_gost.docx(doc, None))).read("word/document.xml").decode()
    grids = [t.split("<w:tr>")[1:] for t in re.findall(r"<w:tbl>.*?</w:tbl>", xml, re.S)]
    assert sorted(len(r) - 1 for r in grids) == sorted(len(b.rows) for b in tables)
    for rows in grids:
        kept = ["<w:keepNext/>" in r for r in rows]
        if len(rows) - 1 <= report_gost.SHORT_TABLE:
            assert all(kept[:-1]) and not kept[-1]
        else:
            assert kept[0] and not any(kept[1:])            # the header with the first row


@pytest.mark.slow
def test_no_glyph_missing_in_the_pdf(tmp_path):
    """Every character the PDF typesets (the model's text: headings, paragraphs, lists, tables,
    captions) is in a font the layout gives typst, and reads back from the PDF."""
    import pypdf
    from fontTools.ttLib import TTFont

    from flywheel.render import mathfmt, report_gost
    from flywheel.render.blocks import Bullets, Figure, Heading, Paragraph, Table

    doc = _model()
    (tmp_path / "r.pdf").write_bytes(report_gost.pdf(doc, None))
    text = "\n".join(p.extract_text() for p in pypdf.PdfReader(str(tmp_path / "r.pdf")).pages)
    shown = []
    for b in report_gost.sections(doc):
        if isinstance(b, report_gost.Section):
            shown.append(b.text)
        elif isinstance(b, (Heading, Paragraph)):
            shown.append(b.text)
        elif isinstance(b, Bullets):
            shown += b.items
        elif isinstance(b, Table):
            shown += [b.caption, *b.header, *(c for r in b.rows for c in r)]
        elif isinstance(b, Figure):
            shown.append(b.caption)
    chars = {ch for t in shown for seg, _ in mathfmt.subscripts(t.replace("**", ""))
             for ch in seg if not ch.isspace() and ch != THIN}
    assert {"½", "²", "−", "₅"} <= chars        # what Liberation Serif lacks is in the sample
    cmaps = [TTFont(str(f), lazy=True).getBestCmap() for f in report_gost.font_files()]
    assert cmaps
    uncovered = sorted(ch for ch in chars if not any(ord(ch) in c for c in cmaps))
    assert not uncovered, uncovered
    missing = sorted(ch for ch in chars if ch not in text)
    assert not missing, missing


@pytest.mark.slow
def test_the_docx_has_the_gost_margins_styles_and_caption_fields(gost_run):
    import docx
    from docx.enum.text import WD_ALIGN_PARAGRAPH
    from docx.shared import Pt

    d = docx.Document(str(gost_run / "report.docx"))
    s = d.sections[0]
    mm = [round(x.mm, 1) for x in (s.page_width, s.page_height, s.left_margin, s.right_margin,
                                   s.top_margin, s.bottom_margin)]
    assert mm == [210, 297, 30, 15, 20, 20]             # margin_right_mm = 15 of the case
    normal = d.styles["Normal"]
    assert normal.font.size == Pt(14) and normal.font.name == "Times New Roman"
    assert normal.paragraph_format.line_spacing == 1.5
    assert round(normal.paragraph_format.first_line_indent.cm, 2) == 1.25
    for name in ("Heading 1", "Heading 2", "Caption"):
        assert d.styles[name].font.color.rgb in (None, docx.shared.RGBColor(0, 0, 0))
    xml = d.element.xml
    assert "SEQ Рисунок" in xml and "SEQ Таблица" in xml and " PAGEREF _Toc1 " in xml
    captions = [p for p in d.paragraphs if p.style.name == "Caption"]
    assert any(p.text.startswith("Таблица ") for p in captions)
    assert any(p.text.startswith("Рисунок ") for p in captions)
    # a table's caption at the left, not justified as the text is (its two lines had been
    # stretched); a figure's centred under it
    assert d.styles["Caption"].paragraph_format.alignment == WD_ALIGN_PARAGRAPH.LEFT
    assert all(p.paragraph_format.alignment in (None, WD_ALIGN_PARAGRAPH.LEFT)
               for p in captions if p.text.startswith("Таблица "))
    # the numbers of a table right-aligned, its first column left
    t = d.tables[0]
    body = t.rows[1:]
    assert all(r.cells[1].paragraphs[0].alignment == WD_ALIGN_PARAGRAPH.RIGHT for r in body)
    assert all(r.cells[0].paragraphs[0].alignment == WD_ALIGN_PARAGRAPH.LEFT for r in body)
    # the title page: the case's names, the option's teacher
    head = " ".join(p.text for p in d.paragraphs[:30])
    assert "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА" in head and "Иванов И. И." in head and "Сидоров С. С." in head


def test_an_english_pdf_and_docx_keep_their_layout():
    from flywheel.render import report_formats, report_gost

    doc = _model("en")
    src = report_formats.typst_source(doc)
    assert "СОДЕРЖАНИЕ" not in src and "margin: (x: 18mm, y: 18mm)" in src
    assert report_gost.sections(doc)            # the layout function itself takes any document


def test_the_layout_numbers_sections_continuously():
    from flywheel.render.blocks import Document, Heading, Paragraph
    from flywheel.render.report_gost import Section, sections

    doc = Document("t", "ru", [Heading(1, "Динамический анализ: t"), Paragraph("Источник: x"),
                               Heading(2, "1. Исходные данные"), Heading(3, "1.4. Цилиндры"),
                               Heading(3, "1.6. Структура"), Heading(2, "Силовой расчёт"),
                               Heading(3, "При φ = 120°"), Heading(2, "Источники")])
    heads = [(b.number, b.text) for b in sections(doc) if isinstance(b, Section)]
    assert heads == [("1", "Исходные данные"), ("1.1", "Цилиндры"), ("1.2", "Структура"),
                     ("2", "Силовой расчёт"), ("2.1", "При φ = 120°"),
                     ("", "Список использованных источников")]
    blocks = sections(doc)
    assert isinstance(blocks[1], Paragraph)     # the source under section 1, not on the contents


def test_a_long_option_is_one_line(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--out", str(tmp_path / "o"),
                              "--student", "x" * 1001])
    assert res.exit_code == 2
    assert "--student: 1001 characters (allowed: at most 1000)" in res.output


def test_the_extremes_angles_are_printed_without_trailing_zeros():
    """ω_max/ω_min sit at nodes of the grid (1° apart at 360 points): the record and the
    terminal summary print the node's angle as it is (224°, 62.9°), not to a fixed 0.01°
    («224,30°» was printed); ΔT_I's extremes, refined between nodes, to 0.01° at most."""
    import io
    import math

    import numpy as np
    from rich.console import Console

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typeset
    from flywheel.render.summary import print_summary

    c = load_case(CASES / "compressor.toml")
    r = analyze(c, n_points=720)                          # nodes 0.5° apart
    doc = str(typeset("ru", build_document, r, "ru", [], case=c))
    out = io.StringIO()
    typeset("ru", print_summary, r, Console(file=out, width=200), "ru")
    phi = np.degrees(r.phi)
    w = r.motion.omega
    for text in (doc, out.getvalue()):
        angles = re.findall(r"при (−?\d+(?:,\d+)?)°", text)
        assert len(angles) >= 4, text
        assert not [a for a in angles if re.search(r",\d*0$", a)], angles   # no 224,30°
        printed = [float(a.replace(",", ".").replace(MINUS, "-")) for a in angles]
        for node in (phi[np.argmax(w)], phi[np.argmin(w)]):     # the nodes, as they are
            assert any(math.isclose(p, node, abs_tol=1e-9) for p in printed), (node, printed)
        for refined in (r.scalars.phi_delta_T_I_max_deg, r.scalars.phi_delta_T_I_min_deg):
            assert any(math.isclose(p, refined, abs_tol=0.05 + 1e-9) for p in printed)


def test_formulas_are_numbered_through_the_record_at_the_right():
    """ГОСТ 7.32-2017, 6.8.3: formulas numbered through the document in parentheses at the
    right margin. The PDF's typst numbers its block equations «(1)»; the DOCX sets each
    formula at a centre tab stop and its number at a right tab stop at the text's width, in
    the order of the record's formulas (both had none)."""
    import io
    import re as _re
    import zipfile

    from flywheel.render import report_gost
    from flywheel.render.blocks import Formula

    doc = _model()
    n = sum(isinstance(b, Formula) for b in doc.blocks)
    assert n >= 8
    assert '#set math.equation(numbering: "(1)")' in report_gost.typst_source(doc, plots=False)
    xml = zipfile.ZipFile(io.BytesIO(report_gost.docx(doc, None))).read(
        "word/document.xml").decode()
    numbered = _re.findall(r'<w:tab w:val="center" w:pos="(\d+)"/><w:tab w:val="right" '
                           r'w:pos="(\d+)"/>.*?<m:oMath\b.*?</m:oMath><w:r><w:tab/>'
                           r'<w:t xml:space="preserve">\((\d+)\)</w:t>', xml)
    assert [int(k) for _, _, k in numbered] == list(range(1, n + 1))
    assert all(2 * int(c) in (int(r), int(r) - 1) for c, r, _ in numbered)
    assert "<m:oMathPara" not in xml             # every formula is numbered
