"""Cycles of several revolutions (`[machine] cycle_deg`, issue 13 item 1).

Independent truth: a machine whose loads repeat every revolution, analysed over a cycle of two
revolutions, is the same machine: every per-revolution quantity (the balancing moment, ΔT_нб,
J_II's mean, the flywheel, ω(φ)) equals the one-revolution analysis, and the cycle's totals
(work, time) double. The grid over 720° with 7200 intervals has the same nodes as the grid over
360° with 3600, so the values agree to round-off.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import parse_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def _compressor(cycle_deg=None):
    data = read_toml(CASES / "compressor.toml")
    if cycle_deg is not None:
        data["machine"]["cycle_deg"] = cycle_deg
    return parse_case(data, "compressor.toml")


@pytest.fixture(scope="module")
def one_and_two():
    return analyze(_compressor(), n_points=3600), analyze(_compressor(720), n_points=7200)


def test_two_revolutions_of_a_one_revolution_machine(one_and_two):
    one, two = one_and_two
    s1, s2 = one.scalars, two.scalars
    assert (s1.cycle_deg, s2.cycle_deg) == (360, 720)
    for key in ("driving_moment", "balancing_moment", "delta_T_max", "J_II_mean", "J_II_min",
                "J_II_max", "J_required", "J_required_exact", "delta_achieved",
                "delta_achieved_exact", "omega_max", "omega_min", "T0"):
        assert getattr(s2, key) == pytest.approx(getattr(s1, key), rel=1e-11, abs=1e-12), key
    for key in ("cycle_work_resistance", "cycle_time"):          # totals over the cycle
        assert getattr(s2, key) == pytest.approx(2 * getattr(s1, key), rel=1e-11), key
    # ω(φ) repeats: the second revolution equals the first
    w1 = one.columns["omega"].values
    w2 = two.columns["omega"].values
    n = w1.size
    assert np.allclose(w2[:n], w1, rtol=1e-11) and np.allclose(w2[n - 1:], w1, rtol=1e-11)
    # extremes over the whole cycle: in the first or the second revolution, same place
    assert s2.phi_omega_max_deg % 360 == pytest.approx(s1.phi_omega_max_deg, abs=1e-9)
    assert two.phi[-1] == 4 * math.pi


def test_standard_positions_and_dead_centres_over_the_cycle(one_and_two):
    one, two = one_and_two
    labels = [p.label for p in two.position_angles]
    angles = [round(math.degrees(p.phi), 9) for p in two.position_angles]
    assert len([lab for lab in labels if lab.endswith("°") or "° =" in lab]) == 24   # every 30°
    assert angles[:3] == [0.0, 30.0, 60.0] and angles[-1] == 690.0
    # each dead centre once per revolution: the compressor's four fall on 30° positions
    assert labels.count("360° = 3 outer d.c.") == 1 and labels.count("0° = 3 outer d.c.") == 1
    assert "630° = 5 inner d.c." in labels
    assert len(two.position_angles) == 2 * len(one.position_angles)


def test_report_angles_beyond_one_revolution():
    r = analyze(_compressor(720), n_points=7200, at_deg=[120.0, 480.0, 840.0])
    a120, a480, a840 = r.at
    assert a480.phi_deg == 480.0
    assert a480.omega == pytest.approx(a120.omega, rel=1e-11)   # loads repeat each turn
    assert a840.omega == a120.omega                              # 840° = 120° of the cycle
    i = r.index_of(math.radians(480.0))
    assert r.phi[i] == pytest.approx(math.radians(480.0), abs=1e-12)


def _run_cases() -> list[str]:
    from flywheel.cases import kind_of

    return [p.name for p in sorted(CASES.glob("*.toml")) if kind_of(read_toml(p)) == "run"]


def test_cycle_deg_is_in_every_summary(tmp_path):
    """Every bundled run case, its summary's results.cycle_deg the case's machine.cycle_deg
    (360 unless it says otherwise: 720 for the engines)."""
    names = _run_cases()
    assert {"compressor.toml", "press.toml", "engine_4stroke.toml", "engine_inline4.toml",
            "shaper.toml", "pump.toml"} <= set(names)
    for name in names:
        res = runner.invoke(app, ["run", str(CASES / name), "--no-plots", "--json", "--points",
                                  "720", "--out", str(tmp_path / name)])
        assert res.exit_code == 0, res.output
        want = read_toml(CASES / name)["machine"].get("cycle_deg", 360)
        assert json.loads(res.stdout)["results"]["cycle_deg"] == want, name
        assert want == (720 if name.startswith("engine") else 360)


def test_a_720_degree_run_writes_every_output(tmp_path):
    case = tmp_path / "c720.toml"
    text = (CASES / "compressor.toml").read_text(encoding="utf-8")
    case.write_text(text.replace("[machine]", "[machine]\ncycle_deg = 720", 1), encoding="utf-8")
    res = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "o"), "--points", "720"])
    assert res.exit_code == 0, res.output
    doc = json.loads((tmp_path / "o" / "summary.json").read_text(encoding="utf-8"))
    assert doc["results"]["cycle_deg"] == 720
    rows = (tmp_path / "o" / "positions.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(rows) == 24
    phi = np.loadtxt(tmp_path / "o" / "table.csv", delimiter=",", skiprows=1, usecols=0)
    assert phi[0] == 0.0 and phi[-1] == 720.0
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    assert "M_D = -\\frac{A_C}{\\Phi} = \\frac{" in md and "}{4\\pi} = " in md   # Φ = 4π
    assert "Φ = 720°" in md


@pytest.mark.parametrize("value, words", [
    (500, "500° is not a whole number of revolutions (allowed: 360, 720"),
    (0, "0° is out of range (allowed: 360, 720"),
    (540.5, "540.5° is not a whole number of revolutions"),
    (7200, "7200° is out of range (allowed: 360, 720, 1080 … 3600°)"),
    (3.6e9, "3.6e+09° is out of range (allowed: 360, 720, 1080 … 3600°)"),
])
def test_cycle_that_is_not_whole_revolutions(tmp_path, value, words):
    case = tmp_path / "bad.toml"
    text = (CASES / "compressor.toml").read_text(encoding="utf-8")
    case.write_text(text.replace("[machine]", f"[machine]\ncycle_deg = {value}", 1), encoding="utf-8")
    res = runner.invoke(app, ["check", str(case)])
    assert res.exit_code == 2
    line = res.output.strip()
    assert "\n" not in line and "machine.cycle_deg" in line and words in line, line


def test_a_table_of_one_revolution_refuses_a_longer_cycle():
    """A table covers the machine's cycle: one revolution's table does not cover 720° (a table
    over 720° does: tests/dynamics/test_tabulated_cycles.py)."""
    data = read_toml(CASES / "press.toml")            # kinematics from a table (seed 004)
    data["machine"]["cycle_deg"] = 720
    with pytest.raises(Exception, match=r"tabulated\.positions_deg: the positions do not cover "
                                        r"the cycle.*0 … 720, the cycle of machine\.cycle_deg"):
        parse_case(data, "t.toml")
