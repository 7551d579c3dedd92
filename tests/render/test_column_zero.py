"""Round-off relative to a column's scale prints as 0 in the record's tables (numbers.column_zero).

Independent truths: the shaper's resistance work at φ = 180° is the weights' alone (the ram has
not reached the stretch the cutting force acts over), and at 0° and 180° the crank, the lever
and the link are mirror images about the vertical through the fulcrum, so every centroid is at
the height it started from: A_С(180°) = 0 exactly; the computed value is −1.06·10⁻⁹ J, the
round-off of a work of hundreds of joules integrated over the grid. An engine's crank at its
dead centre carries a reaction along the line of stroke: R_y = 0 (computed: −1.2·10⁻¹³ N of
1923 N)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render.numbers import column_zero, fmt

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def _rows(md: str, first: str) -> list[list[str]]:
    return [[c.strip() for c in line.strip("|").split("|")] for line in md.splitlines()
            if line.startswith(f"| {first} ")]


def test_column_zero_is_the_columns_scale_times_the_noise():
    assert column_zero([0.0, -1.06e-9, 556.9, -545.5]) == pytest.approx(556.9e-9)
    assert column_zero([0.0, 0.0], 1e-13) == 1e-13
    assert fmt(-1.06e-9, 6, zero=column_zero([556.9])) == "0"
    assert fmt(-1.06e-9, 6, zero=column_zero([1e-8])) == "-1.06e-09"   # a small column's own


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_a_work_that_returns_to_zero_prints_zero(tmp_path, lang):
    out = tmp_path / "o"
    res = runner.invoke(app, ["run", str(CASES / "shaper.toml"), "--no-plots", "--lang", lang,
                              "-o", str(out)])
    assert res.exit_code == 0, res.output
    md = (out / "report.md").read_text(encoding="utf-8")
    energy = [r for r in _rows(md, "6") if len(r) == 9 and r[1] == "180"]   # energy table, 180°
    assert len(energy) == 1
    assert energy[0][3] == "0"                                   # A_С (A_C)
    assert not re.search(r"\d[eE]-\d|0[.,]0{6}", "\n".join(
        line for line in md.splitlines() if line.startswith("| ")))


def test_a_reaction_along_the_line_of_stroke_has_no_y_component(tmp_path):
    out = tmp_path / "o"
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--no-plots",
                              "-o", str(out)])
    assert res.exit_code == 0, res.output
    md = (out / "report.md").read_text(encoding="utf-8")
    rows = _rows(md, "R_03 (B)")
    assert rows and all(r[5] == "0" for r in rows)
    assert not re.search(r"\d[eE]-1\d", "\n".join(
        line for line in md.splitlines() if line.startswith("| ")))
