"""The DOCX records open with their fields filled and their tables readable across pages:
the Russian (ГОСТ) DOCX asks Word to update its fields on opening (``w:updateFields`` in
settings.xml, in the schema's place); its contents give each heading's page as a PAGEREF field
to a bookmark round the heading, which LibreOffice lays out too; every table's header row
repeats on each page (``w:tblHeader``) in both the Russian and the English DOCX."""
from __future__ import annotations

import io
import re
import shutil
import subprocess
import zipfile

import pytest

from flywheel.render import report_formats, report_gost
from flywheel.render.blocks import Document, Heading, Paragraph, Table

W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
#: w:settings' sequence around updateFields (ECMA-376 part 1, 17.15.1.78): these come before it
BEFORE = ("zoom", "proofState", "defaultTabStop", "characterSpacingControl")
#: and these after it
AFTER = ("compat", "rsids", "mathPr", "themeFontLang", "clrSchemeMapping", "shapeDefaults",
         "decimalSymbol", "listSeparator")


def _doc(lang: str) -> Document:
    doc = Document("Машина", lang)
    rows = tuple((f"{i}", f"{i * 0.5:g}") for i in range(80))         # runs onto a second page
    doc.blocks += [Heading(1, "Машина"), Heading(2, "1. Раздел"), Paragraph("Текст."),
                   Table(1, "Таблица", ("φ, °", "ω, рад/с"), rows)]
    return doc


def _part(data: bytes, name: str):
    from lxml import etree

    return etree.fromstring(zipfile.ZipFile(io.BytesIO(data)).read(name))


def test_the_russian_docx_updates_its_fields_on_opening_in_the_schemas_place():
    settings = _part(report_gost.docx(_doc("ru")), "word/settings.xml")
    names = [c.tag.replace(W, "") for c in settings]
    (flag,) = settings.findall(f"{W}updateFields")
    assert flag.get(f"{W}val") == "true"
    at = names.index("updateFields")
    assert all(names.index(n) < at for n in BEFORE if n in names), names
    assert all(names.index(n) > at for n in AFTER if n in names), names
    assert "compat" in names                           # python-docx's template has one


@pytest.mark.parametrize("writer", [report_gost.docx, report_formats.docx],
                         ids=["ru-gost", "en"])
def test_every_tables_header_row_repeats_on_each_page(writer):
    body = _part(writer(_doc("ru" if writer is report_gost.docx else "en")), "word/document.xml")
    tables = body.findall(f".//{W}tbl")
    assert tables
    for t in tables:
        rows = t.findall(f"{W}tr")
        assert rows[0].find(f"{W}trPr/{W}tblHeader") is not None
        assert all(r.find(f"{W}trPr/{W}tblHeader") is None for r in rows[1:])


def _pages_doc() -> Document:
    """Three sections, the second after a table of two pages, the third on a page of its own."""
    doc = _doc("ru")
    rows = tuple((f"{i}", f"{i * 0.25:g}") for i in range(60))
    doc.blocks += [Heading(2, "2. Второй раздел"), Paragraph("Текст."),
                   Table(2, "Таблица", ("s, м", "F, Н"), rows), Heading(2, "3. Третий раздел"),
                   Paragraph("Конец.")]
    return doc


def test_the_title_pages_city_and_year_stand_at_its_foot():
    """The last line of the title page in a frame at the foot of the text (w:framePr, yAlign
    bottom), in the place the schema's sequence gives it within w:pPr: before, it sat wherever
    the empty lines above left it, a quarter of the page from the foot in LibreOffice."""
    body = _part(report_gost.docx(_doc("ru")), "word/document.xml")
    frames = body.findall(f".//{W}pPr/{W}framePr")
    assert len(frames) == 1 and frames[0].get(f"{W}yAlign") == "bottom"
    names = [c.tag.replace(W, "") for c in frames[0].getparent()]
    assert names.index("framePr") < min(names.index(n) for n in ("ind", "jc") if n in names)
    text = "".join(t.text for t in frames[0].getparent().getparent().iter(f"{W}t"))
    assert text.startswith("_") and text.endswith("_")      # the city and the year, blank


def test_the_contents_link_each_heading_and_its_page_field_to_its_bookmark():
    """One line of the contents a heading, in order: its text the heading's, a hyperlink to
    the bookmark round the heading and a PAGEREF field to the same bookmark (no TOC field,
    whose result LibreOffice would show frozen, without pages)."""
    body = _part(report_gost.docx(_pages_doc()), "word/document.xml")
    text = lambda el: "".join(t.text or "" for t in el.iter(f"{W}t"))      # noqa: E731
    instr = [i.text.strip() for i in body.iter(f"{W}instrText")]
    assert not [i for i in instr if i.startswith("TOC")]
    heads = [p for p in body.iter(f"{W}p")
             if (p.find(f"{W}pPr/{W}pStyle") is not None
                 and p.find(f"{W}pPr/{W}pStyle").get(f"{W}val").startswith("Heading"))]
    marks = [p.find(f"{W}bookmarkStart").get(f"{W}name") for p in heads]
    assert len(heads) >= 3 and len(set(marks)) == len(marks)
    ids = [b.get(f"{W}id") for b in body.iter(f"{W}bookmarkStart")]
    assert len(set(ids)) == len(ids)
    links = body.findall(f".//{W}hyperlink")
    assert [h.get(f"{W}anchor") for h in links] == marks
    for link, head in zip(links, heads):
        assert text(link) == text(head)
        (ref,) = [i.text.strip() for i in link.iter(f"{W}instrText")] \
            + [f.get(f"{W}instr").strip() for f in link.iter(f"{W}fldSimple")]
        assert ref == f"PAGEREF {link.get(f'{W}anchor')} \\h"


@pytest.mark.slow
def test_libreoffice_opens_the_russian_docx_with_the_contents_pages(tmp_path):
    """LibreOffice (which ignores updateFields) opens the record and converts it to PDF; its
    contents give every heading the page LibreOffice set it on (the PDF's page where the
    heading is); before, the contents had no page numbers in LibreOffice."""
    soffice = shutil.which("soffice")
    if soffice is None or shutil.which("pdftotext") is None:
        pytest.skip("LibreOffice or pdftotext is not installed")
    (tmp_path / "r.docx").write_bytes(report_gost.docx(_pages_doc()))
    subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp_path}/profile",
                    "--convert-to", "pdf", "--outdir", str(tmp_path), str(tmp_path / "r.docx")],
                   capture_output=True, timeout=240, check=True)
    text = subprocess.run(["pdftotext", "-layout", str(tmp_path / "r.pdf"), "-"],
                          capture_output=True, text=True, check=True).stdout
    pages = text.split("\f")
    assert "СОДЕРЖАНИЕ" in text and "Таблица 1" in text
    contents = next(p for p in pages if "СОДЕРЖАНИЕ" in p)
    listed = {}
    for line in contents.splitlines():
        m = re.fullmatch(r"\s*(.+?)\.{3,}\s*(\d+)\s*", line)
        if m:
            listed[m.group(1).strip()] = int(m.group(2))
    assert len(listed) >= 3, contents
    later = pages[pages.index(contents) + 1:]
    for heading, page in listed.items():
        on = [k for k, p in enumerate(pages, start=1) if p in later
              and any(ln.strip() == heading for ln in p.splitlines())]
        assert on and on[0] == page, (heading, page, on)
    assert max(listed.values()) >= 5                     # the pages are counted, not guessed
    # the title page's city and year at its foot (ГОСТ 7.32), whatever the lines above take
    words = subprocess.run(["pdftotext", "-f", "1", "-l", "1", "-bbox", str(tmp_path / "r.pdf"),
                            "-"], capture_output=True, text=True, check=True).stdout
    low = max(float(m) for m in re.findall(r'yMax="([\d.]+)"', words))
    assert low > 0.88 * 842, low                        # A4: 842 pt; the text ends at 785
