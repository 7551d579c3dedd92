"""A case file given to the wrong command is named for what it is, with the command that
reads it (issue 17): one line, exit 2."""
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cases import kind_of
from flywheel.cli import app
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


@pytest.mark.parametrize("path", sorted(CASES.glob("*.toml")), ids=lambda p: p.name)
def test_every_bundled_case_is_recognised(path):
    expected = ("variants" if path.name.startswith("variants_") else
                "task2" if path.name.startswith("task2_") else
                "aggregate" if path.name.startswith("aggregate") else
                "duty_cycle" if path.name.startswith("duty_") else "run")
    assert kind_of(read_toml(path)) == expected


@pytest.mark.parametrize("command, case, hint", [
    (["run"], "task2_khurmi_16_4.toml", "use `flywheel task2 --case "),
    (["check"], "aggregate.toml", "use `flywheel aggregate "),
    (["run"], "variants_task2.toml", "use `flywheel variants "),
])
def test_run_and_check_name_the_right_command(command, case, hint):
    res = runner.invoke(app, [*command, str(CASES / case)])
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"error: {CASES / case}: this is "), lines
    assert hint in lines[0]
