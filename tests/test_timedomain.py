"""The equation of motion in time (scipy's solve_ivp) against the energy solution, start-up with
a linear motor, run-down; exact and Merzalov sizes against the δ they achieve."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from flywheel import timedomain
from flywheel.case import load_case, parse_case
from flywheel.pipeline import analyze

CASES = Path(__file__).resolve().parents[1] / "cases"


@pytest.fixture(scope="module")
def compressor():
    return analyze(load_case(CASES / "compressor.toml"), transients=True)


def test_time_integration_repeats_and_matches_the_energy_solution(compressor):
    v = compressor.scalars["time_domain"]["verification"]
    assert v["repeat_error"] < 1e-6          # the motion repeats cycle after cycle
    assert v["max_deviation"] < 1e-6         # and follows ω(φ) of the energy equation
    assert v["period"] == pytest.approx(compressor.scalars["cycle_time"], rel=1e-6)


def test_rundown_energy(compressor):
    """Cut the drive: the loads alone stop the crank. Over whole cycles the loads absorb
    |A_C| per cycle, so the kinetic energy at the cut lasts about T/|A_C| cycles."""
    rd = compressor.scalars["time_domain"]["rundown"]
    assert rd["stopped"]
    s = compressor.scalars
    T_cut = compressor.scalars["T0"]          # total kinetic energy at φ = 0
    cycles = rd["angle_deg"] / 360
    assert cycles == pytest.approx(T_cut / -s["cycle_work_resistance"], abs=1.0)


def test_startup_needs_a_motor(compressor):
    assert compressor.scalars["time_domain"]["startup"]["computed"] is False


def _constant_inertia_case(motor=None):
    """A flywheel-only machine: no second-group masses; a slider-crank whose cylinder resists on
    one stroke (the moment depends on φ only)."""
    data = {
        "title": "constant inertia",
        "machine": {"speed_rpm": 600.0, "delta": 0.04, "gravity": [0.0, 0.0]},
        "crank": {"length": 0.05},
        "dyads": [{"kind": "RRP", "from": "A", "joint": "B", "rod": "2", "rod_length": 0.2,
                   "slider": "3", "guide": {"angle_deg": 0.0}}],
        "cylinders": [{"name": "c", "piston": "3", "bore": 0.1, "p_max": 1e6,
                       "s": [0.0, 1.0], "towards_head": [1.0, 1.0], "away_from_head": [0.0, 0.0]}],
    }
    if motor:
        data["motor"] = motor
    return parse_case(data)


def test_constant_inertia_both_methods_agree_and_reach_delta():
    s = analyze(_constant_inertia_case(), n_points=3600).scalars
    assert s["J_required"] == pytest.approx(s["J_required_exact"], rel=1e-12)
    assert s["delta_achieved_exact"] == pytest.approx(0.04, rel=1e-4)
    # Merzalov takes ω_max² − ω_min² = 2δω_m², true here, so its δ is right to δ²/4-order terms
    assert s["delta_achieved"] == pytest.approx(0.04, rel=1e-3)


def test_exact_size_reaches_delta_on_the_compressor(compressor):
    s = compressor.scalars
    assert s["delta_achieved_exact"] == pytest.approx(s["delta"], rel=1e-4)
    # Merzalov's size on the compressor: 0.7 % below the target δ (it overestimates J_I)
    assert s["delta_achieved"] / s["delta"] - 1 == pytest.approx(-0.0070, abs=5e-4)


def test_startup_with_a_linear_motor_reaches_the_steady_state():
    """Motor M_Д = M_п(1 − ω/ω_x) with ω_x 5 % above the mean speed: from rest the machine
    settles at the speed where the mean motor torque balances the loads (≈ ω_m)."""
    case = _constant_inertia_case(motor={"no_load_speed_rpm": 630.0})
    r = analyze(case, n_points=1440, transients=True)
    st = r.scalars["time_domain"]["startup"]
    assert not st["stalled"]
    w_m = 2 * math.pi * 10
    assert st["omega_mean_steady"] == pytest.approx(w_m, rel=2e-3)
    assert st["time_to_steady"] > 0 and st["cycles_to_steady"] >= 1
    # M_п from the balance: M_п·(1 − ω_m/ω_x) = M_D
    assert st["starting_torque"] * (1 - w_m / st["no_load_speed"]) == pytest.approx(
        r.scalars["driving_moment"], rel=1e-12)


def test_rundown_closed_form_for_constant_resistance():
    """Constant J and a constant resisting moment M: ω² = ω0² − 2Mφ/J, stopping after
    φ = Jω0²/(2M) in t = Jω0/M."""
    phi = np.linspace(0, 2 * np.pi, 721)
    J, M, w0 = 2.0, 50.0, 30.0
    rd = timedomain.rundown(phi, np.full_like(phi, J), np.zeros_like(phi), np.full_like(phi, -M), w0)
    assert rd["stopped"]
    assert rd["time"] == pytest.approx(J * w0 / M, rel=1e-6)
    assert math.radians(rd["angle_deg"]) == pytest.approx(J * w0**2 / (2 * M), rel=1e-6)


def test_motor_speed_must_exceed_the_mean_speed():
    from flywheel.errors import CaseFileError

    with pytest.raises(CaseFileError, match=r"motor\.no_load_speed_rpm"):
        _constant_inertia_case(motor={"no_load_speed_rpm": 500.0})
