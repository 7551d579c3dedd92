"""Tabulated cases over a cycle of several revolutions (issue 13 item 1, "cycles of 4π", for the
tabulated route): `machine.cycle_deg = 720` with a [tabulated] table over 0 … 720°.

Independent truths: the press's 360° table written twice over 720° is the same machine, so
its flywheel, ΔT_нб and speeds are those of the 360° case while the cycle's works double; a
press that punches every second revolution balances its cycle, M_D·4π = the work of the
loads over the 720° (computed here from the table with scipy, not through the code)."""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import parse_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def _twice(values):
    """A closed 360° row (13 values, the last repeating the first) written over 720°."""
    return values[:-1] + values[:-1] + [values[0]] if isinstance(values, list) else values


@pytest.fixture(scope="module")
def press_doc():
    return read_toml(CASES / "press.toml")


def press_720(doc: dict, punch_every_revolution: bool = True) -> dict:
    d = copy.deepcopy(doc)
    t = d["tabulated"]
    t["positions_deg"] = t["positions_deg"][:-1] + [p + 360 for p in t["positions_deg"]]
    for section in ("points", "omega_q"):
        t[section] = {k: _twice(v) for k, v in t[section].items()}
    for f in t["forces"]:
        f["magnitude"], f["angle_deg"] = _twice(f["magnitude"]), _twice(f["angle_deg"])
        if f["name"] == "punch" and not punch_every_revolution:
            f["magnitude"] = f["magnitude"][:13] + [0.0] * 12
    d["machine"]["cycle_deg"] = 720
    return d


def test_the_360_table_twice_over_720_is_the_same_flywheel(press_doc):
    r1 = analyze(parse_case(press_doc, "press.toml"), n_points=3600).scalars
    r2 = analyze(parse_case(press_720(press_doc), "press720.toml"), n_points=7200).scalars
    assert r1.cycle_deg == 360 and r2.cycle_deg == 720
    for key in ("driving_moment", "delta_T_max", "J_required", "J_required_exact", "J_flywheel",
                "omega_max", "omega_min", "delta_achieved", "delta_achieved_exact", "J_II_mean"):
        assert getattr(r2, key) == pytest.approx(getattr(r1, key), rel=1e-12), key
    # the works over the cycle double; the extremes of ω repeat, the first one is reported
    assert r2.cycle_work_resistance == pytest.approx(2 * r1.cycle_work_resistance, rel=1e-12)
    assert r2.phi_omega_max_deg == pytest.approx(r1.phi_omega_max_deg, abs=1e-9)


def test_a_press_that_punches_every_second_revolution_balances_its_720_cycle(press_doc):
    """M_D·4π = −∮M dφ over 720°: the weights' reduced moments G·V_q·cos α are periodic
    splines through the positions (integrated exactly with scipy's CubicSpline.integrate), the
    punch's F·V_q·cos 180° joined linearly (the trapezoid rule over its positions)."""
    from scipy.interpolate import CubicSpline

    d = press_720(press_doc, punch_every_revolution=False)
    r = analyze(parse_case(d, "press720.toml"), n_points=7200).scalars
    t = d["tabulated"]
    x = np.radians(t["positions_deg"])
    work = 0.0
    for f in t["forces"]:
        mag = np.broadcast_to(np.asarray(f["magnitude"], float), x.shape)
        ang = np.broadcast_to(np.radians(np.asarray(f["angle_deg"], float)), x.shape)
        M = mag * np.asarray(t["points"][f["point"]]) * np.cos(ang)
        if f["interpolation"] == "periodic-spline":
            work += CubicSpline(x, M, bc_type="periodic").integrate(x[0], x[-1])
        else:
            work += float(np.sum((M[1:] + M[:-1]) / 2 * np.diff(x)))
    assert r.driving_moment * 4 * math.pi == pytest.approx(-work, rel=1e-9)
    # half the punching: less than the 360° press's driving moment, more than half of it
    # (the weights' small net work is per revolution)
    r360 = analyze(parse_case(press_doc, "press.toml"), n_points=3600).scalars
    assert 0.45 * r360.driving_moment < r.driving_moment < 0.55 * r360.driving_moment
    # one punch per 720° stores the energy of the whole idle revolution: ΔT_нб is larger
    assert r.delta_T_max > r360.delta_T_max
    assert r.cycle_deg == 720


def test_run_and_check_on_a_720_table(press_doc, tmp_path):
    import tomli_w

    path = tmp_path / "p720.toml"
    path.write_text(tomli_w.dumps(press_720(press_doc)), encoding="utf-8")
    res = runner.invoke(app, ["check", str(path)])
    assert res.exit_code == 0, res.output
    res = runner.invoke(app, ["run", str(path), "--no-plots", "--json", "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    import json

    doc = json.loads(res.stdout)
    assert doc["results"]["cycle_deg"] == 720
    assert doc["results"]["tabulated_positions_deg"][-1] == 720


def test_a_720_table_in_a_360_case_is_refused(press_doc):
    d = press_720(press_doc)
    del d["machine"]["cycle_deg"]
    with pytest.raises(CaseFileError, match=r"tabulated\.positions_deg\[13\]: 390° is outside "
                                            r"the cycle \(allowed: 0 … 360\)"):
        parse_case(d, "c.toml")


def test_a_360_table_in_a_720_case_does_not_cover_the_cycle(press_doc):
    d = copy.deepcopy(press_doc)
    d["machine"]["cycle_deg"] = 720
    with pytest.raises(CaseFileError, match=r"tabulated\.positions_deg: the positions do not "
                                            r"cover the cycle: nothing between 360° and 0° "
                                            r"\(360° gap.*0 … 720, the cycle of machine\.cycle_deg"):
        parse_case(d, "c.toml")
