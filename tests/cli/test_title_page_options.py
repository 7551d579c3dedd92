"""--student, --group and --teacher of task2, aggregate and duty-cycle: the names on the title
page of the Russian PDF and DOCX, over the case's [document] as `run` takes them (a name not
given keeps the case's); a name beyond 1000 characters is one error line."""
from __future__ import annotations

import io
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
NAMES = ["--student", "Иванов И. И.", "--group", "МТ-21", "--teacher", "Петров П. П."]
#: the case's own [document]: its student is replaced by --student, its department is kept
DOCUMENT = '\n[document]\nstudent = "Сидоров С. С."\ndepartment = "Кафедра теории механизмов"\n'


def _case(tmp_path: Path, name: str) -> Path:
    path = tmp_path / f"{name}.toml"
    path.write_text((CASES / f"{name}.toml").read_text(encoding="utf-8") + DOCUMENT,
                    encoding="utf-8")
    return path


COMMANDS = {
    "task2": lambda tmp: ["task2", "--case", _case(tmp, "task2_seed_triangle")],
    "aggregate": lambda tmp: ["aggregate", _case(tmp, "aggregate")],
    "duty-cycle": lambda tmp: ["duty-cycle", _case(tmp, "duty_khurmi_16_19_punch")],
}


def _docx_title_page(path: Path) -> str:
    """The text of the DOCX's paragraphs up to «СОДЕРЖАНИЕ» (the title page), read with
    python-docx."""
    import docx

    out = []
    for p in docx.Document(str(path)).paragraphs:
        if p.text.strip() == "СОДЕРЖАНИЕ":
            break
        out.append(p.text)
    return "\n".join(out)


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_the_names_given_are_on_the_title_page_over_the_cases(command, tmp_path):
    out = tmp_path / "out"
    args = [*COMMANDS[command](tmp_path), "--out", out, "--report", "docx", "--lang", "ru",
            *NAMES]
    res = runner.invoke(app, [str(a) for a in args])
    assert res.exit_code == 0, res.output
    page = _docx_title_page(out / "report.docx")
    for name in ("Иванов И. И.", "МТ-21", "Петров П. П.", "Кафедра теории механизмов"):
        assert name in page, (name, page)
    assert "Сидоров" not in page                     # the case's student, replaced


def test_the_pdf_title_page_of_task2_has_the_names(tmp_path):
    from pypdf import PdfReader

    out = tmp_path / "out"
    res = runner.invoke(app, ["task2", "--out", str(out), "--report", "pdf", "--lang", "ru",
                              *NAMES])
    assert res.exit_code == 0, res.output
    first = PdfReader(io.BytesIO((out / "report.pdf").read_bytes())).pages[0].extract_text()
    for name in ("Иванов", "МТ-21", "Петров"):
        assert name in first, first


@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_a_name_too_long_is_one_line(command, tmp_path):
    args = [*COMMANDS[command](tmp_path), "--out", tmp_path / "out", "--teacher", "x" * 1001]
    res = runner.invoke(app, [str(a) for a in args])
    lines = [ln for ln in res.output.splitlines() if ln.strip()]
    assert res.exit_code == 2 and len(lines) == 1, res.output
    assert "--teacher: 1001 characters (allowed: at most 1000)" in lines[0]
    assert not (tmp_path / "out").exists()
