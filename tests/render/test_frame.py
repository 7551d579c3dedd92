"""Issue 28: the ЕСКД frame of the Russian записка (``--frame eskd``, render/report_frame.py):
the title blocks of ГОСТ 2.104-2006 forms 2 and 2a as cells (render/drawings/forms.py), the
PDF read back with pypdf (every framed page has the designation and its sheet number), the
DOCX read back with python-docx (the frame in the headers, the title blocks in the footers),
and the option refused where it would draw nothing."""
from __future__ import annotations

import io
import itertools
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render.blocks import Document, Heading, Paragraph, Table, TitlePage
from flywheel.render.drawings.forms import LEFT_COLUMNS, form2, form2a

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
MM = 72 / 25.4                                   # pt per mm


# -- the forms (ГОСТ 2.104-2006, appendix A) ---------------------------------------------------
@pytest.mark.parametrize("form, height", [(form2(), 40.0), (form2a(), 15.0)])
def test_a_form_tiles_its_box(form, height):
    """The cells cover 185 × height mm exactly, none over another."""
    area = sum(c.w * c.h for c in form.cells)
    assert area == pytest.approx(185.0 * height)
    for a, b in itertools.combinations(form.cells, 2):
        overlap_x = min(a.x + a.w, b.x + b.w) - max(a.x, b.x)
        overlap_y = min(a.y + a.h, b.y + b.h) - max(a.y, b.y)
        assert overlap_x <= 1e-9 or overlap_y <= 1e-9, (a, b)
    assert all(0 <= c.x and c.x + c.w <= 185.0 and 0 <= c.y and c.y + c.h <= height
               for c in form.cells)


def test_the_forms_have_the_standards_cells():
    """The sizes ГОСТ 2.104 gives: the left part 7, 10, 23, 15, 10 mm; form 2's designation
    120 × 15, name 70 × 25, organisation 50 × 15, Лист 15 and Листов 20 mm wide; form 2a's
    designation 110 × 15 and its Лист 10 mm wide."""
    assert [w for w, _ in LEFT_COLUMNS] == [7, 10, 23, 15, 10]
    by = {c.text: (c.w, c.h) for c in form2().cells if c.text}
    assert by["designation"] == (120, 15) and by["title"] == (70, 25)
    assert by["organisation"] == (50, 15) and by["sheet"][0] == 15 and by["sheets"][0] == 20
    assert [k for k in by if k.startswith("label:") and k[6:] in
            ("drawn", "checked", "tech_control", "norm_control", "approved")] == \
        ["label:drawn", "label:checked", "label:tech_control", "label:norm_control",
         "label:approved"]
    by_a = {c.text: (c.w, c.h) for c in form2a().cells if c.text}
    assert by_a["designation"] == (110, 15) and by_a["sheet"][0] == 10


# -- the записка framed -------------------------------------------------------------------------
FRONT = TitlePage(machine="Кривошипно-ползунный механизм", university="МГТУ", group="МТ-301",
                  student="Иванов И. И.", teacher="Петров П. П.", tech_control="Сидоров С. С.",
                  norm_control="Кузнецов К. К.", approved="Смирнов А. А.",
                  designation="ТММ.КП.07.00", frame="eskd")


def _doc(wide: bool = False) -> Document:
    """A записка of several pages: sections with text and a long table (and, if ``wide``, a
    table of 14 columns, which goes on a landscape page)."""
    blocks = [Heading(1, "Динамический анализ: механизм")]
    for k in range(1, 4):
        blocks += [Heading(2, f"{k}. Раздел {k}")]
        blocks += [Paragraph("Текст раздела, достаточно длинный для нескольких строк. " * 8)] * 4
    blocks.append(Table(1, "Длинная таблица", ("φ, °", "x, м"),
                        tuple((str(i), f"0,{i:03d}") for i in range(90))))
    if wide:
        blocks.append(Table(2, "Широкая таблица", tuple(f"к{i}" for i in range(14)),
                            (tuple(str(i) for i in range(14)),)))
    blocks.append(Heading(2, "Источники"))
    blocks.append(Paragraph("[1] Артоболевский И. И. Теория механизмов и машин."))
    return Document("Кривошипно-ползунный механизм", "ru", blocks, front=FRONT)


def test_every_framed_page_of_the_pdf_has_its_title_block():
    import pypdf

    from flywheel.render import report_gost

    reader = pypdf.PdfReader(io.BytesIO(report_gost.pdf(_doc(wide=True))))
    pages = [p.extract_text() for p in reader.pages]
    n = len(pages)
    assert n >= 5
    assert "Изм." not in pages[0] and "Лист" not in pages[0]  # the title page: no frame
    for k, text in enumerate(pages[1:], start=2):
        assert "ТММ.КП.07.00 ПЗ" in text, k
        assert str(k) in text.split(), k                     # its sheet number, a word of its own
    first = pages[1]                                         # form 2 on the contents page
    assert "СОДЕРЖАНИЕ" in first
    for word in ("Разраб.", "Иванов И. И.", "Пров.", "Петров П. П.", "Т. контр.",
                 "Сидоров С. С.", "Н. контр.", "Кузнецов К. К.", "Утв.", "Смирнов А. А.",
                 "Листов", "МГТУ", "группа МТ-301", "Пояснительная записка"):
        assert word in first, word
    assert str(n) in first.split()                           # «Листов»: the sheets in all
    assert all("Разраб." not in p for p in pages[2:])        # form 2a on the rest
    for page in reader.pages[1:]:                            # every page A4, portrait or turned
        w, h = sorted((float(page.mediabox.width), float(page.mediabox.height)))
        assert (w, h) == pytest.approx((210 * MM, 297 * MM), abs=0.5)
    assert any(float(p.mediabox.width) > float(p.mediabox.height) for p in reader.pages)


def test_the_frame_moves_the_text_inside():
    from flywheel.render import report_gost

    src = report_gost.typst_source(_doc())
    assert "margin: (left: 25mm, right: 10mm, top: 15mm, bottom: 30mm)" in src     # form 2a
    assert "bottom: 55mm" in src                                  # above form 2 (40 + 5 + 10)
    assert "footer: none" in src                                  # the number is the block's
    plain = report_gost.typst_source(Document("t", "ru", _doc().blocks, front=TitlePage()))
    assert "eskd" not in plain and "margin: (left: 30mm" in plain


def test_the_docx_keeps_the_frame_in_its_headers_and_footers():
    import docx

    from flywheel.render import report_gost

    d = docx.Document(io.BytesIO(report_gost.docx(_doc())))
    title, text = d.sections
    assert title.left_margin.mm == pytest.approx(30, abs=0.1)      # the title page: ГОСТ 7.32
    assert "rect" not in title.header._element.xml               # and no frame
    assert text.left_margin.mm == pytest.approx(25, abs=0.1)
    assert text.top_margin.mm == pytest.approx(15, abs=0.1)
    assert text.bottom_margin.mm == pytest.approx(30, abs=0.1)
    assert text.different_first_page_header_footer
    for header in (text.first_page_header, text.header):
        xml = header._element.xml
        assert "<v:rect" in xml and "mso-position-horizontal-relative:page" in xml
        assert f"width:{185 * MM:.2f}pt" in xml and f"height:{287 * MM:.2f}pt" in xml
    first, later = text.first_page_footer, text.footer
    assert len(first.tables) == 1 and len(later.tables) == 1
    cells = {c.text for row in first.tables[0].rows for c in row.cells}
    assert {"ТММ.КП.07.00 ПЗ", "Разраб.", "Иванов И. И.", "Утв.", "Смирнов А. А.",
            "Листов"} <= cells
    assert "PAGE" in first._element.xml and "NUMPAGES" in first._element.xml
    later_cells = {c.text for row in later.tables[0].rows for c in row.cells}
    assert "ТММ.КП.07.00 ПЗ" in later_cells and "Разраб." not in later_cells
    assert " PAGE " in later._element.xml
    heights = [row.height.mm for row in later.tables[0].rows]
    assert sum(heights) == pytest.approx(15.0, abs=0.1)         # form 2a: 15 mm
    assert sum(row.height.mm for row in first.tables[0].rows) == pytest.approx(40.0, abs=0.1)


def test_no_frame_leaves_the_layout_as_it_was():
    import docx

    from flywheel.render import report_gost

    d = docx.Document(io.BytesIO(report_gost.docx(Document("t", "ru", _doc().blocks,
                                                           front=TitlePage()))))
    assert len(d.sections) == 1 and not d.sections[0].footer.tables


@pytest.mark.parametrize("args, says", [
    (["--report", "pdf", "--frame", "eskd"], "--lang ru"),                 # English
    (["--lang", "ru", "--frame", "eskd"], "--report pdf"),                  # md and html only
    (["--lang", "ru", "--report", "md", "--report", "html", "--frame", "eskd"], "--report docx"),
    (["--lang", "ru", "--report", "pdf", "--frame", "gost"], "none, eskd"),
])
def test_a_frame_that_cannot_apply_is_one_line(tmp_path, args, says):
    res = runner.invoke(app, ["run", str(CASES / "fourbar.toml"), "--no-plots", "--out",
                              str(tmp_path / "o"), *args])
    assert res.exit_code == 2
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and "--frame" in lines[0] and says in lines[0]
    assert not (tmp_path / "o").exists()


def test_task2_aggregate_and_duty_cycle_take_the_frame_too(tmp_path):
    """The other commands' записки: framed with --frame eskd (task2's PDF read back), refused
    in one line where nothing would be framed."""
    import pypdf

    res = runner.invoke(app, ["task2", "--case", str(CASES / "task2_khurmi_16_1.toml"), "--lang",
                              "ru", "--out", str(tmp_path / "t"), "--report", "pdf", "--frame",
                              "eskd"])
    assert res.exit_code == 0, res.output
    pages = [p.extract_text() for p in pypdf.PdfReader(tmp_path / "t" / "report.pdf").pages]
    assert all("ТММ.КП.00.01 ПЗ" in p and str(k) in p.split()
               for k, p in enumerate(pages[1:], start=2))
    for args in (["aggregate", str(CASES / "aggregate.toml")],
                 ["duty-cycle", str(CASES / "duty_khurmi_16_19_punch.toml")]):
        res = runner.invoke(app, [*args, "--out", str(tmp_path / "x"), "--report", "pdf",
                                  "--frame", "eskd"])
        assert res.exit_code == 2 and "--frame eskd" in res.output
        assert len(res.output.strip().splitlines()) == 1
