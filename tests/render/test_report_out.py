"""`flywheel task2 --out DIR` and `flywheel aggregate CASE --out DIR`: summary.json is the --json
document, the report (render/report_task2.py, render/report_aggregate.py) reads back in every
format with the result's numbers and Russian headings, reruns are byte-identical and a rerun
replaces only its own files, a bad --report is one line with exit 2."""
from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.io.toml import read_toml
from test_report_formats import _Page

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
ALL = ["--report", "md", "--report", "html", "--report", "pdf", "--report", "docx"]


def invoke(*args):
    res = runner.invoke(app, [str(a) for a in args])
    assert res.exit_code == 0, res.output
    return res


def task2(out: Path, *extra):
    return invoke("task2", "--case", CASES / "task2_seed_triangle.toml", "--out", out, *extra)


def aggregate(out: Path, *extra):
    return invoke("aggregate", CASES / "aggregate.toml", "--out", out, *extra)


@pytest.fixture(scope="module")
def t2(tmp_path_factory):
    out = tmp_path_factory.mktemp("t2") / "o"
    task2(out, "--lang", "ru", *ALL)
    return out


@pytest.fixture(scope="module")
def ag(tmp_path_factory):
    out = tmp_path_factory.mktemp("ag") / "o"
    aggregate(out, "--lang", "ru", *ALL)
    return out


def _pdf_text(path: Path) -> str:
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is not installed: the PDF's text is not read back")
    return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True,
                          check=True).stdout


def _ru4(x: float) -> str:
    """A result as a Russian document writes it, for 1e-4 ≤ |x| < 1e4: four significant
    digits, a decimal comma, a true minus."""
    return f"{x:.4g}".replace(".", ",").replace("-", "\u2212")


def test_task2_summary_json_is_the_json_document(t2):
    res = invoke("task2", "--case", CASES / "task2_seed_triangle.toml", "--json")
    assert (t2 / "summary.json").read_text(encoding="utf-8") == res.output
    assert {p.name for p in t2.iterdir()} == {"summary.json", "report.md", "report.html",
                                             "report.pdf", "report.docx", "plots",
                                             ".flywheel-manifest.json"}
    assert (t2 / "plots" / "task2.png").read_bytes()[:4] == b"\x89PNG"


def test_task2_html_reads_back(t2):
    doc = json.loads((t2 / "summary.json").read_text(encoding="utf-8"))
    page = _Page()
    page.feed((t2 / "report.html").read_text(encoding="utf-8"))
    body = "".join(page.text)
    for heading in ("Исходные данные", "Метод решения", "Решение", "Источники"):
        assert heading in body, heading
    # the numbers of the seed task: ω_max 200.011044, ω_min 199.988955 (crossings at 5π/8, 11π/8)
    # Russian typography (render/numbers.py): decimal comma; results to 4 significant digits,
    # an f format keeps its decimals (none of these above 10⁴, none negative)
    def ru(text):
        return text.replace(".", ",")

    assert ru(f"{doc['omega_max']:.6f}") in page.cells and ru(f"{doc['omega_min']:.6f}") in page.cells
    assert ru(f"{doc['delta']:.4g}") in page.cells and ru(f"{doc['delta_T_max']:.4g}") in page.cells
    # the symbols' subscripts typeset (<sub>), not printed as "M_Д"
    assert "Рис. 1\u00a0— Моменты MД, MС" in page.captions[-1]
    assert "Моменты M<sub>Д</sub>, M<sub>С</sub>" in (t2 / "report.html").read_text(encoding="utf-8")
    assert [c.split("\u00a0— ")[0] for c in page.captions[:-1]] == [
        f"Таблица {i}" for i in range(1, len(page.captions))]
    assert page.refs == [r for r in page.refs if r.startswith("data:image/png;base64,")]
    assert len(page.refs) == 1 and "<math" in (t2 / "report.html").read_text(encoding="utf-8")
    # the case's source is cited, in Russian (the JSON carries the English)
    assert read_toml(CASES / "task2_seed_triangle.toml")["source"]["ru"] in body


def test_task2_pdf_and_docx_read_back(t2):
    import docx

    doc = json.loads((t2 / "summary.json").read_text(encoding="utf-8"))
    text = _pdf_text(t2 / "report.pdf")
    assert "Исходные данные" in text and "Таблица 1" in text
    assert f"{doc['omega_max']:.6f}".replace(".", ",") in text        # Russian typography
    d = docx.Document(str(t2 / "report.docx"))
    assert len(d.inline_shapes) == 1
    assert len(d.tables) == (t2 / "report.md").read_text(encoding="utf-8").count("\nТаблица ")
    cells = {c.text for t in d.tables for r in t.rows for c in r.cells}
    assert f"{doc['omega_min']:.6f}".replace(".", ",") in cells


def test_aggregate_reads_back(ag):
    import docx

    doc = json.loads((ag / "summary.json").read_text(encoding="utf-8"))
    page = _Page()
    page.feed((ag / "report.html").read_text(encoding="utf-8"))
    body = "".join(page.text)
    assert "Исходные данные" in body and "Собственные частоты" in body and "Источники" in body
    # the natural frequency of the two-mass aggregate, √(c·(J1 + J2)/(J1·J2))/2π (the JSON's)
    # in Russian typography: four significant digits, a decimal comma, a true minus
    assert _ru4(doc['natural_frequencies_hz'][0]) in page.cells
    assert _ru4(doc['twist_amplitude']) in page.cells
    assert len(page.refs) == 1 and page.captions[-1].startswith("Рис. 1\u00a0— ")
    text = _pdf_text(ag / "report.pdf")
    assert "Собственные частоты" in text and _ru4(doc['natural_frequencies_hz'][0]) in text
    d = docx.Document(str(ag / "report.docx"))
    assert len(d.inline_shapes) == 1
    assert len(d.tables) == (ag / "report.md").read_text(encoding="utf-8").count("\nТаблица ")


def test_aggregate_without_motor_has_no_figure(tmp_path):
    aggregate_case = CASES / "aggregate_khurmi_three_rotor.toml"
    invoke("aggregate", aggregate_case, "--out", tmp_path / "o")
    assert not (tmp_path / "o" / "plots").exists()
    assert "<img" not in (tmp_path / "o" / "report.html").read_text(encoding="utf-8")


def test_reruns_are_byte_identical_and_replace_only_their_files(tmp_path):
    for name, make in (("t", task2), ("g", aggregate)):
        a, b = tmp_path / f"{name}a", tmp_path / f"{name}b"
        make(a, *ALL)
        make(b, *ALL)
        files = sorted(p.relative_to(a) for p in a.rglob("*") if p.is_file())
        assert len(files) == 7
        for f in files:
            assert (a / f).read_bytes() == (b / f).read_bytes(), f
        (a / "mine.txt").write_text("kept", encoding="utf-8")
        res = make(a)                    # md and html only: the pdf and docx of before go
        assert (a / "mine.txt").read_text(encoding="utf-8") == "kept"
        assert not (a / "report.pdf").exists() and (a / "report.html").exists()
        assert "written" in res.output


def test_one_command_does_not_replace_anothers_folder(tmp_path):
    task2(tmp_path / "o")
    res = runner.invoke(app, ["aggregate", str(CASES / "aggregate.toml"), "--out",
                              str(tmp_path / "o")])
    assert res.exit_code == 2 and len(res.output.strip().splitlines()) == 1


@pytest.mark.parametrize("cmd", [["task2", "--case", str(CASES / "task2_seed_triangle.toml")],
                                 ["aggregate", str(CASES / "aggregate.toml")],
                                 ["duty-cycle", str(CASES / "duty_khurmi_16_19_punch.toml")]])
def test_bad_report_is_one_line(tmp_path, cmd):
    res = runner.invoke(app, [*cmd, "--out", str(tmp_path / "o"), "--report", "odt"])
    assert res.exit_code == 2 and res.output.count("\n") == 1, res.output
    assert "--report: 'odt'" in res.output and "allowed: md, html, pdf, docx" in res.output
    res = runner.invoke(app, [*cmd, "--report", "md"])
    assert res.exit_code == 2 and "--out" in res.output and res.output.count("\n") == 1
    assert not (tmp_path / "o").exists()


def test_duty_cycle_out(tmp_path):
    """`flywheel duty-cycle CASE --out DIR`: summary.json is the --json document, the записка
    has the method, the tables of the summary with its numbers and the case's source; no figure."""
    import docx

    case = CASES / "duty_khurmi_16_19_punch.toml"
    res = invoke("duty-cycle", case, "--out", tmp_path / "o", "--lang", "ru", *ALL)
    assert f"записано: {tmp_path / 'o'}/" in res.stdout
    js = invoke("duty-cycle", case, "--json").output
    assert (tmp_path / "o" / "summary.json").read_text(encoding="utf-8") == js
    doc = json.loads(js)
    page = _Page()
    page.feed((tmp_path / "o" / "report.html").read_text(encoding="utf-8"))
    body = "".join(page.text)
    assert "Метод решения" in body and "Маховик" in body
    assert read_toml(case)["source"]["ru"] in body and doc["source"] == read_toml(case)["source"]["en"]
    # Khurmi & Gupta Ex. 16.19, printed: P = 3 kW, m = 618 kg (exact 617.940 kg)
    assert round(doc["mass"]) == 618 and doc["motor_power"] == 3000.0
    assert _ru4(doc['mass']) in page.cells and _ru4(doc['motor_power']) in page.cells
    assert "<img" not in (tmp_path / "o" / "report.html").read_text(encoding="utf-8")
    assert "Таблица 1" in _pdf_text(tmp_path / "o" / "report.pdf")
    d = docx.Document(str(tmp_path / "o" / "report.docx"))
    assert len(d.tables) == (tmp_path / "o" / "report.md").read_text(encoding="utf-8").count("\nТаблица ")
    invoke("duty-cycle", case, "--out", tmp_path / "p", "--lang", "ru", *ALL)
    for f in ("summary.json", "report.md", "report.html", "report.pdf", "report.docx"):
        assert (tmp_path / "o" / f).read_bytes() == (tmp_path / "p" / f).read_bytes(), f
