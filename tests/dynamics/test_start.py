"""Motion from rest ([start], issue 24 item 5) and the crank's acceleration at a stated angle
and speed (--snapshot, item 7).

Independent truths: J_II(φ) and dJ_II/dφ summed here from the linkage's analogues by the
definition (Σ m·|v_qS|² + J_S·ω_q², its derivative 2·Σ(m·v_qS·a_qS + J_S·ω_q·ε_q)); a
slider-crank with no loads keeps ½·J(φ)·ω² (energy); under a constant moment M from rest
½·J(φ)·ω² = M·(φ − φ0); ε at t = 0 is (M − ½·J′·ω0²)/J by hand; halving the tolerance moves
the answer by less than the tolerance.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import parse_case
from flywheel.dynamics.pipeline import analyze
from flywheel.dynamics.start import ReducedMachine, motion_from_rest
from flywheel.errors import CaseFileError, InputError
from flywheel.io.toml import read_toml
from flywheel.linkage import solve

CASES = Path(__file__).resolve().parents[2] / "cases"


def slider_crank(start: dict, gravity=(0.0, 0.0), **machine) -> dict:
    """engine_4stroke's slider-crank without its cylinder, on a 360° cycle, with ``start``."""
    d = read_toml(CASES / "engine_4stroke.toml")
    d.pop("cylinders")
    d["machine"].update(cycle_deg=360, gravity=list(gravity), **machine)
    d["start"] = start
    return d


def inertia(case, phi_deg: float) -> tuple[float, float, float]:
    """(J_II, dJ_II/dφ, the weights' moment Σ m·g·v_qS) at φ by their definitions."""
    kin = solve(case.mechanism(), np.array([math.radians(phi_deg)]))
    J = dJ = Mg = 0.0
    g = np.asarray(case.machine.gravity, float)
    for name, lk in case.links.items():
        p, w = kin.points[lk.centroid], kin.links[name]
        v, a = p.v_q[0], p.a_q[0]
        J += lk.mass * (v @ v) + lk.J_S * w.omega_q[0] ** 2
        dJ += 2 * (lk.mass * (v @ a) + lk.J_S * w.omega_q[0] * w.eps_q[0])
        Mg += lk.mass * (g @ v)
    return J, dJ, Mg


def test_no_loads_conserves_kinetic_energy():
    d = slider_crank({"omega0": 100.0, "moment": 0.0, "t_end": 0.5,
                      "times": [0.0, 0.01, 0.1, 0.2, 0.37, 0.5], "rtol": 1e-11, "atol": 1e-11})
    case = parse_case(d, "s.toml")
    r = analyze(case)
    J_I = r.motion.J_I
    T0 = 0.5 * (J_I + inertia(case, 0.0)[0]) * 100.0 ** 2
    omegas = []
    for a in r.start.at:
        T = 0.5 * (J_I + inertia(case, a.phi_deg)[0]) * a.omega ** 2
        assert T == pytest.approx(T0, rel=1e-9), a
        omegas.append(a.omega)
    assert max(omegas) - min(omegas) > 1e-3      # J_II varies: ω does
    assert r.start.at[-1].phi_deg > 2 * 360       # several revolutions


def test_from_rest_under_a_constant_moment():
    """½·J(φ)·ω² = M·(φ − φ0), from rest at φ0 = 45°."""
    M = 20.0
    d = slider_crank({"phi0_deg": 45.0, "moment": M, "t_end": 0.3, "times": [0.05, 0.1, 0.3]})
    case = parse_case(d, "s.toml")
    r = analyze(case)
    for a in r.start.at:
        J = r.motion.J_I + inertia(case, a.phi_deg)[0]
        assert 0.5 * J * a.omega ** 2 == pytest.approx(M * math.radians(a.phi_deg - 45.0), rel=1e-8)


def test_epsilon_at_the_start_by_hand():
    """ε(0) = (M_g(φ0) + M − ½·J′(φ0)·ω0²)/J(φ0), with gravity, at φ0 = 30° (a grid node)."""
    M, w0 = 15.0, 80.0
    d = slider_crank({"phi0_deg": 30.0, "omega0": w0, "moment": M, "t_end": 0.01,
                      "times": [0.0, 0.01]}, gravity=(0.0, -9.81))
    case = parse_case(d, "s.toml")
    r = analyze(case)
    J_II, dJ, Mg = inertia(case, 30.0)
    J = r.motion.J_I + J_II
    first = r.start.at[0]
    assert (first.t, first.omega) == (0.0, w0) and first.phi_deg == pytest.approx(30.0, abs=1e-12)
    assert first.epsilon == pytest.approx((Mg + M - 0.5 * dJ * w0 ** 2) / J, rel=1e-9)


def test_halving_the_tolerance_changes_the_answer_below_it():
    runs = {}
    for rtol in (1e-7, 5e-8, 1e-12):
        d = slider_crank({"moment": 30.0, "t_end": 0.4, "times": [0.4], "rtol": rtol,
                          "atol": rtol})
        runs[rtol] = analyze(parse_case(d, "s.toml")).start.at[-1]
    ref = runs[1e-12]
    for rtol in (1e-7, 5e-8):
        assert abs(runs[rtol].omega / ref.omega - 1) < rtol * 10
        assert abs(runs[rtol].phi_deg / ref.phi_deg - 1) < rtol * 10
    assert abs(runs[1e-7].omega - runs[5e-8].omega) < 1e-7 * abs(ref.omega)


def test_motor_drives_towards_its_speed():
    """With the [motor] and no loads, from rest: ε(0) = M_п/J(φ0) and ω stays below ω_x."""
    d = slider_crank({"driver": "motor", "t_end": 2.0, "times": [0.0, 2.0]})
    d["motor"] = {"no_load_speed_rpm": 3100.0, "starting_torque": 40.0}
    case = parse_case(d, "s.toml")
    r = analyze(case)
    J = r.motion.J_I + inertia(case, 0.0)[0]
    assert r.start.at[0].epsilon == pytest.approx(40.0 / J, rel=1e-9)
    assert 0 < r.start.at[-1].omega < 3100 * math.pi / 30


def test_the_work_is_bounded():
    machine = ReducedMachine([0.0, math.pi, 2 * math.pi], [1.0, 2.0, 1.0], [0.0, 0.0, 0.0],
                             [0.0, 0.0, 0.0])
    with pytest.raises(InputError, match="more than 100 evaluations"):
        motion_from_rest(machine, 0.0, 0.0, lambda w: 1.0, 100.0, [100.0], 1e-12, 1e-12,
                         max_evaluations=100)


@pytest.mark.parametrize("start, fragment", [
    ({"t_end": 1.0, "times": [0.5]}, "start.moment: missing"),
    ({"moment": 1.0, "t_end": 1.0, "times": [0.5, 2.0]}, "start.times[1]: 2 s is after t_end"),
    ({"moment": 1.0, "t_end": 1.0, "times": [0.5, 0.5]}, "start.times[1]"),
    ({"moment": 1.0, "t_end": 1.0, "times": [0.5], "rtol": 1e-13}, "start.rtol"),
])
def test_bad_start_one_line(start, fragment):
    with pytest.raises(CaseFileError) as exc:
        parse_case(slider_crank(start), "s.toml")
    assert fragment in str(exc.value) and "\n" not in str(exc.value)


def test_motor_driver_needs_a_motor():
    d = slider_crank({"driver": "motor", "t_end": 1.0, "times": [1.0]})
    with pytest.raises(InputError, match="needs a \\[motor\\]"):
        analyze(parse_case(d, "s.toml"))
