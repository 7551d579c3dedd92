"""A torsional spring between two links at their common joint (issue 24 item 2: ``[[springs]]``
kind "torsional" with ``links = [a, b]``): U = ½·c·(θ_a − θ_b − θ0)², checked against truths
computed here from the positions alone: its reduced moment is −dU/dφ by central differences of U,
its cycle work is 0, and in the kinetostatics its couples are equal and opposite on the two links
— the change of the joint reaction at B that the spring alone causes (steady motion, so the
inertia loads are the same with and without it) is the statics of the coupler and the rocker
under the two couples, solved here by hand; the frame's shaking moment does not change (the
spring is inside the machine)."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import parse_case
from flywheel.dynamics.loads import LoadKey as K
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError, InputError

BUNDLED = Path(__file__).resolve().parents[2] / "cases" / "fourbar_rocker_load.toml"
C, FREE_DEG = 25.0, -70.0

KNEE = f"""
[[springs]]
name = "knee"
kind = "torsional"
links = ["2", "3"]
about = "B"
stiffness = {C}
free_angle_deg = {FREE_DEG}
"""
STEADY = '\n[force_analysis]\nmotion = "steady"\n'


def case_of(extra: str = "", drop_springs: bool = False):
    data = tomllib.loads(BUNDLED.read_text(encoding="utf-8") + extra)
    if drop_springs:
        data["springs"] = [s for s in data["springs"] if s["name"] != "return"]
    return parse_case(data, str(BUNDLED))


def angle(k, frm: str, to: str) -> np.ndarray:
    """The angle [rad] of the line frm → to, unwrapped, from the positions alone."""
    d = k.points[to].r - k.points[frm].r
    return np.unwrap(np.arctan2(d[:, 1], d[:, 0]))


def relative_turn(k) -> np.ndarray:
    """Δ = θ2 − θ3 − θ0 [rad]: the coupler A → B against the rocker D → B, θ0 the whole turns
    nearest the start."""
    rel = angle(k, "A", "B") - angle(k, "D", "B")
    free = math.radians(FREE_DEG)
    return rel - (free + 2 * math.pi * round((rel[0] - free) / (2 * math.pi)))


@pytest.fixture(scope="module")
def knee():
    return analyze(case_of(KNEE), n_points=720)


def test_reduced_moment_is_minus_dU_dphi_and_the_cycle_work_is_zero(knee):
    r = knee
    U = 0.5 * C * relative_turn(r.kinematics) ** 2
    dU = np.gradient(U, r.phi, edge_order=2)
    M = r.loads.M_parts[K("spring", "knee")]
    assert np.max(np.abs(M)) > 1.0                                     # it does something
    np.testing.assert_allclose(M, -dU, rtol=0, atol=2e-4 * np.max(np.abs(M)))
    W = r.loads.W_parts[K("spring", "knee")]
    np.testing.assert_allclose(W, -(U - U[0]), rtol=0, atol=1e-12 * np.max(U))
    assert W[-1] == pytest.approx(0.0, abs=1e-12)
    trapezoid = float(np.sum((M[:-1] + M[1:]) / 2 * np.diff(r.phi)))
    assert abs(trapezoid) < 1e-4 * np.max(np.abs(M))


def test_the_kinetostatics_closes_and_agrees_with_the_lever_and_the_power_balance(knee):
    fa = knee.forces
    assert fa.closure < 1e-9
    np.testing.assert_allclose(fa.M_y_zhukovsky, fa.analysis.balancing_moment, rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(fa.M_y_power, fa.analysis.balancing_moment, rtol=1e-9, atol=1e-9)


def test_its_couples_are_equal_and_opposite_on_the_coupler_and_the_rocker():
    """With steady motion the spring changes the reactions by the statics of its couples alone:
    C2 = −c·Δ on the coupler (A, B), C3 = +c·Δ on the rocker (D, B). The rocker about D:
    (r_B − r_D) × R23 + C3 = 0; the coupler about A: (r_B − r_A) × (−R23) + C2 = 0."""
    with_it = analyze(case_of(KNEE + STEADY), n_points=360)
    without = analyze(case_of(STEADY), n_points=360)
    k = with_it.kinematics
    delta = relative_turn(k)
    C2, C3 = -C * delta, C * delta
    u3 = k.points["B"].r - k.points["D"].r
    u2 = k.points["B"].r - k.points["A"].r
    # [−u3y u3x; −u2y u2x]·R = [−C3; C2], node by node
    a = np.stack([np.stack([-u3[:, 1], u3[:, 0]], -1), np.stack([-u2[:, 1], u2[:, 0]], -1)], 1)
    R = np.linalg.solve(a, np.stack([-C3, C2], -1)[..., None])[..., 0]
    j1, j0 = with_it.forces.analysis.joints, without.forces.analysis.joints
    dR = np.stack([j1["B:2->3"].x - j0["B:2->3"].x, j1["B:2->3"].y - j0["B:2->3"].y], -1)
    scale = np.max(np.abs(R))
    assert scale > 1.0
    np.testing.assert_allclose(dR, R, rtol=0, atol=1e-9 * scale)
    # the spring is inside the machine: the frame (with the motor's stator) feels nothing of it
    dS = with_it.forces.analysis.shaking_moment - without.forces.analysis.shaking_moment
    np.testing.assert_allclose(dS, 0.0, rtol=0, atol=1e-9 * scale)
    dMy = with_it.forces.analysis.balancing_moment - without.forces.analysis.balancing_moment
    assert np.max(np.abs(dMy)) > 0.1            # while the drive's moment does change


def test_a_spring_between_links_that_turn_against_each_other_is_refused():
    # the crank turns whole revolutions against its coupler
    case = case_of(KNEE.replace('["2", "3"]', '["1", "2"]').replace('about = "B"', 'about = "A"'))
    with pytest.raises(InputError, match="against each other"):
        analyze(case, n_points=360)


@pytest.mark.parametrize("edit, fragments", [
    (('about = "B"', 'about = "D"'), ["springs[1].about", "'D' is not a joint of links 2 and 3",
                                      "B"]),
    (('["2", "3"]', '["2", "2"]'), ["springs[1].links", "both links are '2'"]),
    (('["2", "3"]', '["2", "9"]'), ["springs[1].links[1]", "no link named '9'"]),
    (('links = ["2", "3"]', 'links = ["2", "3"]\nlink = "3"'), ["springs[1].links",
                                                                "link", "not both"]),
    (('links = ["2", "3"]\n', ''), ["springs[1].link", "link (or links)"]),
])
def test_bad_spring_between_links_is_one_line(edit, fragments):
    with pytest.raises(CaseFileError) as e:
        case_of(KNEE.replace(*edit))
    text = str(e.value)
    assert "\n" not in text
    for f in fragments:
        assert f in text, (f, text)
