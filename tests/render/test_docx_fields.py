"""The DOCX records open with their fields filled and their tables readable across pages:
the Russian (ГОСТ) DOCX asks Word to update its fields on opening (``w:updateFields`` in
settings.xml, in the schema's place), so the contents get their page numbers; every table's
header row repeats on each page (``w:tblHeader``) in both the Russian and the English DOCX."""
from __future__ import annotations

import io
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


@pytest.mark.slow
def test_libreoffice_opens_the_russian_docx(tmp_path):
    """LibreOffice (which ignores updateFields) still opens the record and converts it to PDF
    with its contents page."""
    soffice = shutil.which("soffice")
    if soffice is None or shutil.which("pdftotext") is None:
        pytest.skip("LibreOffice or pdftotext is not installed")
    (tmp_path / "r.docx").write_bytes(report_gost.docx(_doc("ru")))
    subprocess.run([soffice, "--headless", f"-env:UserInstallation=file://{tmp_path}/profile",
                    "--convert-to", "pdf", "--outdir", str(tmp_path), str(tmp_path / "r.docx")],
                   capture_output=True, timeout=240, check=True)
    text = subprocess.run(["pdftotext", str(tmp_path / "r.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    assert "СОДЕРЖАНИЕ" in text and "1 Раздел" in text and "Таблица 1" in text
