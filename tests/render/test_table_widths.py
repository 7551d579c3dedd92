"""The DOCX tables' column widths (render/table_widths.py): fixed in the file so that Word and
LibreOffice draw the same table; LibreOffice gave columns left to it equal shares and broke
words inside («положе|ние», «внутрен|няя»)."""
from __future__ import annotations

import io
import shutil
import subprocess
import zipfile
from pathlib import Path

import pytest

from flywheel.render import report_formats, report_gost
from flywheel.render.blocks import Document, Heading, Table
from flywheel.render.table_widths import MARGIN, ROOMY, SLACK, column_widths, text_width

W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
LIBERATION = Path("/usr/share/fonts/truetype/liberation/LiberationSerif-Regular.ttf")
#: the kinematics table's first column and ten more of numbers, as the record has them
ROWS = [("положение", "№", "φ, °", "v_qA", "v_qB", "v_qS2", "v_qC", "v_qS4", "ω_q2", "ω_q4")] + [
    (f"{a}° = ползун 3: внутренняя мёртвая точка" if a % 90 == 0 else f"{a}°", str(k), str(a),
     "0,1", "0,06091", "0,0807", "0,09769", "0,0965", "−0,2182", "0,128")
    for k, a in enumerate(range(0, 360, 30))]


def _pad(margin: int = MARGIN) -> int:
    return 2 * margin + SLACK


def test_a_narrow_table_is_as_wide_as_its_lines_and_a_little_roomier():
    rows = [("s", "p/p_max"), ("0", "1"), ("0,1", "0,52")]
    w = column_widths(rows, 9000, 24)
    wanted = [max(text_width("s", 24, True), text_width("0,1", 24)) + _pad(),
              max(text_width("p/p_max", 24, True), text_width("0,52", 24)) + _pad()]
    assert w == [int(x * ROOMY) for x in wanted]
    assert sum(w) < 9000


def test_a_wide_table_fills_the_width_and_breaks_no_word():
    width = 9638                                     # A4, margins 30 and 15 mm [twips]
    w = column_widths(ROWS, width, 20)
    assert width - len(w) <= sum(w) <= width
    for c in range(len(w)):                           # each column holds its longest word
        longest = max(text_width(word, 20, k == 0) for k, r in enumerate(ROWS)
                      for word in r[c].split(" "))
        assert w[c] >= longest + _pad(), (c, w[c], longest)
    assert w[0] > max(w[1:])                         # the words' column gets the most room


def test_words_wider_than_the_page_share_it_in_proportion():
    rows = [("Пропорционально",) * 4]
    w = column_widths(rows, 4000, 24)
    assert sum(w) <= 4000 and max(w) - min(w) <= 1


def test_a_subscript_is_narrower_and_bold_wider():
    assert text_width("v_qS2", 24) < text_width("vqS2", 24)
    assert text_width("**ω**", 24) == pytest.approx(text_width("ω", 24, bold=True))
    assert text_width("ω", 24, bold=True) > text_width("ω", 24)


@pytest.mark.skipif(not LIBERATION.is_file(), reason="Liberation Serif is not installed")
@pytest.mark.parametrize("text", ["положение", "внутренняя мёртвая точка", "0,06091",
                                  "−0,2182", "кг·м²/рад", "Приведённый момент", "Table 9 (a)"])
def test_the_estimate_is_times_new_romans_width_or_a_little_more(text):
    """Against Liberation Serif (metric-compatible with Times New Roman), read by fontTools:
    the sum of its advance widths. Never much narrower (a word would break), at most 15 %
    wider."""
    from fontTools.ttLib import TTFont

    font = TTFont(str(LIBERATION))
    cmap, hmtx, upm = font.getBestCmap(), font["hmtx"], font["head"].unitsPerEm
    true = sum(hmtx[cmap[ord(ch)]][0] for ch in text) / upm * 24 * 10     # 12 pt [twips]
    assert 0.97 * true <= text_width(text, 24) <= 1.15 * true


def _tables(data: bytes):
    from lxml import etree

    body = etree.fromstring(zipfile.ZipFile(io.BytesIO(data)).read("word/document.xml"))
    return body.findall(f".//{W}tbl")


def _doc(lang: str) -> Document:
    doc = Document("Машина", lang)
    doc.blocks += [Heading(1, "Машина"), Heading(2, "1. Кинематика"),
                   Table(1, "Аналоги скоростей", ROWS[0], tuple(ROWS[1:]))]
    return doc


@pytest.mark.parametrize("writer", [report_gost.docx, report_formats.docx], ids=["ru", "en"])
def test_the_docx_tables_have_fixed_widths_within_the_text(writer):
    (tbl,) = _tables(writer(_doc("ru" if writer is report_gost.docx else "en")))
    assert tbl.find(f"{W}tblPr/{W}tblLayout").get(f"{W}type") == "fixed"
    grid = [int(g.get(f"{W}w")) for g in tbl.findall(f"{W}tblGrid/{W}gridCol")]
    assert len(grid) == len(ROWS[0]) and sum(grid) <= 9865          # the widest text: 174 mm
    for tr in tbl.findall(f"{W}tr"):
        cells = [int(tc.find(f"{W}tcPr/{W}tcW").get(f"{W}w")) for tc in tr.findall(f"{W}tc")]
        assert cells == grid


@pytest.mark.slow
def test_libreoffice_breaks_no_word_of_the_russian_docx_tables(tmp_path):
    """LibreOffice's PDF of the record's kinematics table: every word of its first column on
    one line (with equal columns it broke «внутренняя» into «внутрен» and «няя»)."""
    soffice = shutil.which("soffice")
    if soffice is None or shutil.which("pdftotext") is None:
        pytest.skip("LibreOffice or pdftotext is not installed")
    (tmp_path / "r.docx").write_bytes(report_gost.docx(_doc("ru")))
    subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp_path}/profile",
                    "--convert-to", "pdf", "--outdir", str(tmp_path), str(tmp_path / "r.docx")],
                   capture_output=True, timeout=240, check=True)
    text = subprocess.run(["pdftotext", str(tmp_path / "r.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    words = text.split()
    assert words.count("внутренняя") == 4 and words.count("Положение") == 1, words[:80]
