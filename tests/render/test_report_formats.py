"""The записка in md, html, pdf and docx (render/document.py, render/report_formats.py):
each format is produced and reads back; the HTML is self-contained and its numbers are
summary.json's; reruns are byte-identical."""
from __future__ import annotations

import json
import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render import mathfmt

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def run(out: Path, *extra, case="compressor.toml"):
    res = runner.invoke(app, ["run", str(CASES / case), "--out", str(out), "--points", "360", *extra])
    assert res.exit_code == 0, res.output
    return res


class _Page(HTMLParser):
    def __init__(self):
        super().__init__()
        self.text, self.refs, self.captions, self.cells, self.stack = [], [], [], [], []
        self._cap = None

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.refs += [v for k, v in attrs if k in ("src", "href") and v]
        self.stack.append(tag)
        if tag in ("figcaption",) or (tag == "p" and a.get("class") == "caption"):
            self._cap = []
        if tag == "td":
            self.cells.append("")

    def handle_endtag(self, tag):
        if self.stack:
            self.stack.pop()
        if self._cap is not None and tag in ("figcaption", "p"):
            self.captions.append("".join(self._cap))
            self._cap = None

    def handle_data(self, data):
        if "style" in self.stack:
            return
        self.text.append(data)
        if self._cap is not None:
            self._cap.append(data)
        if self.stack and self.stack[-1] == "td":
            self.cells[-1] += data


@pytest.fixture(scope="module")
def ru_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("ru") / "o"
    run(out, "--lang", "ru", "--report", "md", "--report", "html", "--report", "pdf", "--report", "docx")
    return out


def test_formula_notation_converts():
    src = r"J_{I} = \frac{\Delta T_{нб}}{\delta \cdot \omega_{ср}^{2}}"
    assert mathfmt.plain(src) == "J_I = ΔT_нб/(δ·ω_ср²)"
    ml = mathfmt.mathml(src)
    assert "<mfrac>" in ml and "<mi>нб</mi>" in ml and "http" not in ml
    assert mathfmt.typst(src) == 'J_("I") = frac(Δ T_("нб"), δ · ω_("ср")^(2))'
    with pytest.raises(ValueError):
        mathfmt.parse(r"\nosuchthing x")


def test_a_decimal_comma_stays_inside_its_number():
    """Russian typography puts a comma in numbers (ГОСТ 8.417); typst's math spaces every
    comma as punctuation («0, 452»), so a number with one is typeset as one upright text."""
    src = r"J_I = 0,452\,\text{кг·м}^2"
    assert mathfmt.parse(src).kids[2].text == "0,452"
    assert '"0,452"' in mathfmt.typst(src)
    assert "<mn>0,452</mn>" in mathfmt.mathml(src)
    assert mathfmt.typst(r"f(x, 2)") == r"f \( x \, 2 \)"      # a list's comma is not a number's


def test_default_formats_are_md_and_html(tmp_path):
    res = run(tmp_path / "o", "--no-plots")
    assert {p.name for p in (tmp_path / "o").glob("report.*")} == {"report.md", "report.html"}
    assert "report.md, report.html" in res.output


def test_html_is_self_contained_and_numbered(ru_run):
    page = _Page()
    text = (ru_run / "report.html").read_text(encoding="utf-8")
    page.feed(text)
    assert not re.search(r"https?://", text)
    assert page.refs and all(r.startswith("data:image/png;base64,") for r in page.refs)
    figs = [int(m) for c in page.captions for m in re.findall(r"^Рис\. (\d+)\u00a0— ", c)]
    tabs = [int(m) for c in page.captions for m in re.findall(r"^Таблица (\d+)\u00a0— ", c)]
    assert figs == list(range(1, len(figs) + 1)) and len(figs) == len(page.refs) >= 10
    assert tabs == list(range(1, len(tabs) + 1)) and len(tabs) >= 10
    assert "<math" in text and "@media print" in text and "size: A4" in text
    body = "".join(page.text)
    for english in ("rad/s", "kg·m²", "N·m", "[deg]"):
        assert english not in body.split("Предупреждения")[0], english
    assert "Чебышева" in body and "W = 3n" not in body  # the formula is MathML, not text
    assert "группа Ассура II класса вида ВВП: звенья 2, 3" in body   # RRP: В and П


@pytest.fixture(scope="module")
def ru_text_run(tmp_path_factory):
    """The Russian Markdown and HTML reports without figures (the tests of their text; ru_run
    draws the figures and writes the PDF and DOCX for the tests of those)."""
    out = tmp_path_factory.mktemp("ru_text") / "o"
    run(out, "--lang", "ru", "--report", "md", "--report", "html", "--no-plots")
    return out


def test_html_numbers_are_summary_json(ru_text_run):
    s = json.loads((ru_text_run / "summary.json").read_text(encoding="utf-8"))["results"]
    page = _Page()
    page.feed((ru_text_run / "report.html").read_text(encoding="utf-8"))
    cells = page.cells

    def ru(x):      # a Russian result: four significant digits, a decimal comma (none here ≥ 1e4)
        return f"{x:.4g}".replace(".", ",").replace("-", "\u2212")

    for key in ("J_required", "J_required_exact", "J_flywheel", "delta_achieved"):
        assert ru(s[key]) in cells, key
    assert ru(s['flywheel_disk']['D']) in cells and ru(s['flywheel_rim']['mass']) in cells
    at = s["at"][0]
    assert ru(at['points']['B']['v']) in cells


def test_first_group_parts_are_named_in_russian(ru_text_run):
    """cases/compressor.toml's first_group = { crankshaft, gearbox }: the Russian записка names
    them «коленчатый вал» and «редуктор», not by the case's English keys."""
    md = (ru_text_run / "report.md").read_text(encoding="utf-8")
    assert "коленчатый вал" in md and "редуктор" in md
    assert "crankshaft" not in md and "gearbox" not in md


def test_pdf_is_a_pdf(ru_run):
    data = (ru_run / "report.pdf").read_bytes()
    assert data.startswith(b"%PDF") and len(data) > 10_000
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is not installed: the PDF's text is not read back")
    text = subprocess.run(["pdftotext", str(ru_run / "report.pdf"), "-"], capture_output=True,
                          text=True, check=True).stdout
    assert "Маховик" in text and "Таблица 1" in text


def test_docx_has_the_models_headings_and_tables(ru_run):
    import docx

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document

    d = docx.Document(str(ru_run / "report.docx"))
    heads = [p.text for p in d.paragraphs if p.style.name.startswith(("Heading", "Title"))]
    c = load_case(CASES / "compressor.toml")
    pngs = sorted(p.name for p in (ru_run / "plots").iterdir())
    model = build_document(analyze(c, n_points=360), "ru", pngs, case=c)
    # the ГОСТ layout: «СОДЕРЖАНИЕ», then the model's headings but the title (on the title
    # page), numbered again continuously, the sources «СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ»
    strip = re.compile(r"^\d+(\.\d+)*\.?\s+")
    assert heads[0] == "СОДЕРЖАНИЕ" and heads[-1] == "СПИСОК ИСПОЛЬЗОВАННЫХ ИСТОЧНИКОВ"
    assert [strip.sub("", h) for h in heads[1:-1]] == [
        strip.sub("", h.text).rstrip(".") for h in model.headings[1:-1]]
    assert len(d.tables) == len(model.tables)
    assert len(d.inline_shapes) == len(model.figures) == len(pngs)
    # the caption's number is a Word field (SEQ Таблица), its shown value 1
    assert any(p.text.startswith("Таблица ") and "SEQ Таблица" in p._p.xml
               and ">1</w:t>" in p._p.xml for p in d.paragraphs)


def test_reruns_are_byte_identical_and_no_plots_says_so(tmp_path):
    formats = ["--report", "md", "--report", "html", "--report", "docx", "--report", "pdf"]
    run(tmp_path / "a", "--no-plots", *formats)
    run(tmp_path / "b", "--no-plots", *formats)
    for f in ("md", "html", "docx", "pdf"):
        assert (tmp_path / "a" / f"report.{f}").read_bytes() == (tmp_path / "b" / f"report.{f}").read_bytes(), f
    html = (tmp_path / "a" / "report.html").read_text(encoding="utf-8")
    assert "<img" not in html and "--plots none" in html


def test_bad_report_format_is_one_line(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--out", str(tmp_path / "o"),
                              "--report", "odt"])
    assert res.exit_code == 2 and "--report" in res.output and "allowed: md, html, pdf, docx" in res.output


def test_docx_formulas_are_word_equations(ru_run):
    """Every formula of the model is an OMML equation (m:oMath) whose runs spell the formula:
    the fraction of Merzalov's J_I is an m:f, ω_ср² an m:sSubSup, Chebyshev's W = 3n − 2p₅ − p₄
    reads back from the runs."""
    import docx

    from flywheel.render.mathfmt import OMML_NS

    d = docx.Document(str(ru_run / "report.docx"))
    body = d.element.body
    maths = body.findall(f".//{{{OMML_NS}}}oMath")
    md = (ru_run / "report.md").read_text(encoding="utf-8")
    assert len(maths) == md.count("\n$$ ") + md.startswith("$$ ") >= 8
    texts = ["".join(t.text for t in m.iter(f"{{{OMML_NS}}}t")) for m in maths]
    assert any(t.startswith("W=3n−2p5−p4=3·") for t in (x.replace(" ", "") for x in texts)), texts
    assert body.findall(f".//{{{OMML_NS}}}f") and body.findall(f".//{{{OMML_NS}}}sSubSup")
    assert not any(p.text.startswith("W = 3n") for p in d.paragraphs)   # no plain-text copy


def _pages(pdf: Path) -> list[tuple[float, float, float, str]]:
    """(width, height, the largest right edge of a word, the text) of each page [pt]."""
    xml = subprocess.run(["pdftotext", "-bbox", str(pdf), "-"], capture_output=True, text=True,
                         check=True).stdout
    out = []
    for w, h, body in re.findall(r'<page width="([\d.]+)" height="([\d.]+)">(.*?)</page>', xml, re.S):
        right = max([float(x) for x in re.findall(r'xMax="([\d.]+)"', body)] or [0.0])
        out.append((float(w), float(h), right, " ".join(re.findall(r">([^<]+)</word>", body))))
    return out


def test_wide_tables_fit_a4(tmp_path):
    """The reduction table of the inline four (17 columns) goes on a landscape page of its own
    in a smaller font; no word of any page runs past the right margin (18 mm, typst)."""
    run(tmp_path / "o", "--no-plots", "--report", "pdf", "--report", "html", case="engine_inline4.toml")
    html = (tmp_path / "o" / "report.html").read_text(encoding="utf-8")
    assert '<div class="tab wide landscape">' in html and "@page landscape" in html
    assert "size: A4 landscape" in html and ".landscape { page: landscape; }" in html
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is not installed: the PDF's pages are not measured")
    pages = _pages(tmp_path / "o" / "report.pdf")
    for w, h, right, _ in pages:
        assert right <= w - 18 / 25.4 * 72 + 1, (w, right)
    wide = [p for p in pages if "Reduced inertia and moments at the standard positions" in p[3]]
    assert wide and wide[0][0] > wide[0][1]          # landscape
    assert all(w < h for w, h, _, t in pages if "Table 1 —" in t)   # the rest stays portrait


class _SymbolCells(HTMLParser):
    """The header cells and the first (symbol) column of every table, as raw inner HTML."""

    def __init__(self):
        super().__init__()
        self.cells, self._cell, self._first = [], None, False

    def handle_starttag(self, tag, attrs):
        if tag == "tr":
            self._first = True
        elif tag in ("th", "td"):
            self._cell = [] if tag == "th" or self._first else None
            self._first = False
        elif self._cell is not None:
            self._cell.append(f"<{tag}>")

    def handle_endtag(self, tag):
        if tag in ("th", "td"):
            if self._cell is not None:
                self.cells.append("".join(self._cell))
            self._cell = None
        elif self._cell is not None:
            self._cell.append(f"</{tag}>")

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_symbols_are_typeset_with_subscripts(lang, tmp_path):
    """The symbols of the records' tables and bullets (J_II, ΔT_нб, M_Д, ω_ср) carry their
    subscripts as subscripts: <sub> in HTML (no "_" left in a header or symbol cell), #sub in
    typst, subscript runs in Word; identifiers (summary.json) keep their text; reruns are
    byte-identical."""
    import docx

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render import report_formats
    from flywheel.render.document import build_document

    formats = ["--report", "html", "--report", "docx", "--lang", lang]
    run(tmp_path / "a", "--no-plots", *formats)
    run(tmp_path / "b", "--no-plots", *formats)
    for f in ("html", "docx"):
        assert (tmp_path / "a" / f"report.{f}").read_bytes() == \
            (tmp_path / "b" / f"report.{f}").read_bytes(), f
    page = (tmp_path / "a" / "report.html").read_text(encoding="utf-8")
    sym = _SymbolCells()
    sym.feed(page)
    assert len(sym.cells) > 100
    assert not [c for c in sym.cells if "_" in c]
    subs = [c for c in sym.cells if "<sub>" in c]
    assert "J<sub>II</sub>" in "".join(subs) and len(subs) >= 10
    assert ("ΔT<sub>нб</sub>" if lang == "ru" else "ΔT<sub>max</sub>") in page
    # the bullets: Merzalov's flywheel J_I, its formula cited by number, with its subscripts
    assert re.search(r"<li>[^<]*\(\d+\)\W*J<sub>I</sub> = \d", page)
    # Word: the same subscripts as subscript runs
    d = docx.Document(str(tmp_path / "a" / "report.docx"))
    runs = [r for p in d.paragraphs for r in p.runs]
    runs += [r for t in d.tables for row in t.rows for c in row.cells for p in c.paragraphs
             for r in p.runs]
    sub = {r.text for r in runs if r.font.subscript}
    assert {"I", "II", "нб" if lang == "ru" else "max"} <= sub
    assert not [r.text for r in runs if r.font.subscript is not True and re.search(r"\b[JM]_", r.text)]
    # typst: #sub
    c = load_case(CASES / "compressor.toml")
    src = report_formats.typst_source(build_document(analyze(c, n_points=360), lang, [], case=c))
    assert '#"J"#sub[#"II"]' in src and "#sub[" in src


def test_subscripts_leave_identifiers_alone():
    assert mathfmt.subscripts("see summary.json and `results.flywheel_rim`") == [
        ("see summary.json and `results.flywheel_rim`", False)]
    assert mathfmt.subscripts("plots/J_II.png, t2_plot, a_b_c") == [
        ("plots/J_II.png, t2_plot, a_b_c", False)]
    assert mathfmt.subscripts("M_Д − M_{С}") == [("M", False), ("Д", True), (" − M", False),
                                                ("С", True)]
    assert mathfmt.sub_html("p/p_max <") == "p/p<sub>max</sub> &lt;"


def test_a_russian_report_has_no_english_table_headings(tmp_path):
    """Every table heading of the Russian записка is Russian (or a symbol): the four-stroke
    indicator table's strokes too («p/p_max впуск», not «p/p_max intake»)."""
    run(tmp_path / "o", "--no-plots", "--report", "md", "--lang", "ru",
        case="engine_inline4.toml")
    lines = (tmp_path / "o" / "report.md").read_text(encoding="utf-8").splitlines()
    heads = [ln for ln, nxt in zip(lines, lines[1:]) if ln.startswith("| ") and nxt.startswith("|--")]
    assert len(heads) > 10
    assert "| s | p/p_max впуск | p/p_max сжатие | p/p_max расширение | p/p_max выпуск |" in heads
    words = {w for h in heads for w in re.findall(r"\b[a-z]{4,}\b", h)}
    assert not words, words
