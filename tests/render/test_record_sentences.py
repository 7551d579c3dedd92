"""Every paragraph of a записка is a sentence: a capital first letter (a line of the terminal
copied into the record — «доля цикла, занятая операцией: …», «баланс работ за цикл …»,
«вынуждающая частота …», the crank pin's loads — had kept its small letter and no full stop).
A paragraph that opens with a formula's symbol (ω = …) is one; so is a heading's text."""
from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()

COMMANDS = {
    "run": ["run", str(CASES / "shaper.toml"), "--no-plots"],
    "duty-cycle": ["duty-cycle", str(CASES / "duty_khurmi_16_20_punch_stroke.toml")],
    "task2": ["task2", "--case", str(CASES / "task2_khurmi_16_9_power.toml")],
    "aggregate": ["aggregate", str(CASES / "aggregate.toml")],
}


def _paragraphs(md: str) -> list[str]:
    lines = md.split("\n")
    return [ln for i, ln in enumerate(lines)
            if ln and (i == 0 or not lines[i - 1]) and ln[0].isalpha()]


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_no_paragraph_begins_with_a_small_letter(command, lang, tmp_path):
    res = runner.invoke(app, [*COMMANDS[command], "--lang", lang, "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    small = [p for p in _paragraphs(md) if p[0].islower() and p[0] not in "ωεφδ"]
    assert not small, small
