"""The report-angle entries describe the motion the force analysis uses: with `--motion steady`
ω = ω_m and ε = 0 there (they used the true ω(φ), ε(φ) before), so a point's velocity is
v_q·ω_m and its acceleration a_q·ω_m², taken here from the kinematics on their own."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.linkage import solve

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.mark.parametrize("name", ["fourbar", "slotted_link", "press"])
def test_steady_motion_at_the_report_angles(name):
    case = load_case(CASES / f"{name}.toml")
    res = analyze(case, n_points=360, at_deg=[30.0, 200.0], motion="steady")
    w = case.machine.omega_mean
    for a in res.at:
        assert a.omega == w and a.epsilon == 0.0
        assert a.balancing_moment is not None                  # the force analysis is there too
    if case.tabulated is not None:
        return
    k = solve(case.mechanism(), np.radians([30.0, 200.0]))
    for j, a in enumerate(res.at):
        for p, pm in k.points.items():
            assert a.points[p].v == pytest.approx(np.hypot(*pm.v_q[j]) * w, rel=1e-12, abs=1e-12)
            assert a.points[p].a == pytest.approx(np.hypot(*pm.a_q[j]) * w * w, rel=1e-12, abs=1e-12)
        for n, lm in k.links.items():
            assert a.links[n].epsilon == pytest.approx(lm.eps_q[j] * w * w, rel=1e-12, abs=1e-12)


def test_true_motion_is_unchanged():
    case = load_case(CASES / "fourbar.toml")
    res = analyze(case, n_points=360, at_deg=[30.0])
    i = res.at_index(30.0)
    assert res.at[0].omega == res.motion.omega[i] and res.at[0].epsilon == res.motion.epsilon[i]
