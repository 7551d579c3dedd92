"""The `[document]` table (cases/document.py) is accepted by every case kind, read whole, and a
misspelt key is one line naming the allowed keys."""
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()

KINDS = [(["check"], "compressor.toml"), (["task2", "--case"], "task2_seed_triangle.toml"),
         (["aggregate"], "aggregate.toml"), (["duty-cycle"], "duty_readme_press.toml")]
TABLE = '\n[document]\nstudent = "Иванов И. И."\ngroup = "МТ-301"\nyear = 2026\n'


def _with(tmp_path, case, tail):
    path = tmp_path / case
    path.write_text((CASES / case).read_text(encoding="utf-8") + tail, encoding="utf-8")
    return path


@pytest.mark.parametrize("command, case", KINDS, ids=lambda x: str(x))
def test_every_kind_reads_the_document_table(tmp_path, command, case):
    path = _with(tmp_path, case, TABLE)
    res = runner.invoke(app, [*command, str(path), "--out", str(tmp_path / "o")]
                        if command[0] in ("aggregate", "duty-cycle", "task2") else
                        [*command, str(path)])
    assert res.exit_code == 0, res.output


@pytest.mark.parametrize("command, case", KINDS, ids=lambda x: str(x))
def test_a_misspelt_key_is_one_line(tmp_path, command, case):
    path = _with(tmp_path, case, '\n[document]\ngrop = "x"\n')
    res = runner.invoke(app, [*command, str(path)])
    assert res.exit_code == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, lines
    assert "document.grop: unknown key; did you mean 'group'?" in lines[0]
    assert "student" in lines[0] and "designation" in lines[0]


def test_the_loaded_case_carries_the_names():
    from flywheel.cases.document import DEFAULT_DESIGNATION
    from flywheel.cases.run import load_case
    import tempfile
    with tempfile.TemporaryDirectory() as d:
        path = _with(Path(d), "compressor.toml", TABLE)
        case = load_case(path)
    assert case.document.student == "Иванов И. И."
    assert case.document.year == 2026
    assert case.document.designation_or_default == DEFAULT_DESIGNATION
