"""Issue 24, items 1 and 2: loads at any point of any link over any part of the cycle, couples
with a range or a table, springs — each checked against a truth computed here from the
positions alone (never through the reduction): the work of a couple is M·Δθ of its link over
its range, a force-versus-travel table's work is the table's area, a spring's reduced moment is
−dU/dφ by central differences of U and its cycle work is 0, and the kinetostatics still closes
(M_y with the first group's inertia equals the dynamics' constant at every node)."""
from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import parse_case
from flywheel.dynamics.pipeline import analyze
from flywheel.dynamics import applied as A
from flywheel.dynamics.loads import LoadKey as K
from flywheel.errors import InputError
from flywheel.linkage import solve

CASES = Path(__file__).resolve().parents[2] / "cases"
BUNDLED = CASES / "fourbar_rocker_load.toml"


def case_of(extra: str = "", drop: tuple[str, ...] = ()):
    """The bundled rocker case with TOML text added and top-level tables left out."""
    data = tomllib.loads(BUNDLED.read_text(encoding="utf-8") + extra)
    for key in drop:
        data.pop(key, None)
    return parse_case(data, str(BUNDLED))


def rocker_angle(case, phi_deg) -> np.ndarray:
    """θ3 [rad] of the rocker D → B from the positions of B and D alone."""
    k = solve(case.mechanism(), np.radians(np.atleast_1d(phi_deg)))
    d = k.points["B"].r - k.points["D"].r
    return np.arctan2(d[:, 1], d[:, 0])


@pytest.fixture(scope="module")
def bundled():
    case = case_of()
    return case, analyze(case, n_points=720)


def test_rocker_couple_work_is_moment_times_its_swing_over_the_range(bundled):
    case, r = bundled
    th = rocker_angle(case, [40.0, 220.0])
    truth = -40.0 * (th[1] - th[0])
    assert r.loads.W_parts[K("couple", "resistance")][-1] == pytest.approx(truth, rel=1e-12)
    # the spring gives back what it takes: the cycle's resistance work is the couple's alone
    assert r.energy.cycle_work_resistance == pytest.approx(truth, rel=1e-9)
    assert r.energy.driving_moment == pytest.approx(-truth / (2 * math.pi), rel=1e-9)


def test_couple_acts_on_its_closed_range_only(bundled):
    case, r = bundled
    phi = np.degrees(r.phi)
    M = r.loads.M_parts[K("couple", "resistance")]
    omega_q3 = r.kinematics.links["3"].omega_q
    inside = (phi >= 40 - 1e-9) & (phi <= 220 + 1e-9)
    assert np.all(M[~inside] == 0)
    np.testing.assert_allclose(M[inside], -40.0 * omega_q3[inside], rtol=0, atol=1e-12)
    assert 40.0 in np.round(phi, 9) and 220.0 in np.round(phi, 9)     # its ends are nodes


def test_a_range_that_wraps_through_zero():
    case = case_of(drop=("springs",))
    data = tomllib.loads(BUNDLED.read_text(encoding="utf-8"))
    data.pop("springs")
    data["couples"][0]["phi_range_deg"] = [300.0, 60.0]     # the return swing, and on
    data["couples"][0]["moment"] = 40.0                         # against it
    r = analyze(parse_case(data, "wrap.toml"), n_points=720)
    th = rocker_angle(case, [300.0, 360.0, 0.0, 60.0])
    truth = 40.0 * ((th[1] - th[0]) + (th[3] - th[2]))
    assert truth < 0
    assert r.loads.W_parts[K("couple", "resistance")][-1] == pytest.approx(truth, rel=1e-12)


def test_couple_table_against_phi_converges_to_its_integral():
    """A couple M(φ) = 10·(1 − φ/π) on the rocker over [0°, 180°] by a table of two rows: its
    work ∫M·dθ3 by a fine trapezoid of positions, independent of the program's grid."""
    data = tomllib.loads(BUNDLED.read_text(encoding="utf-8"))
    data.pop("springs")
    data["couples"].append({"name": "t", "link": "3", "table": [[0.0, 10.0], [180.0, -10.0]]})
    case = parse_case(data, "table.toml")
    fine = np.linspace(0.0, 180.0, 200001)
    th = np.unwrap(rocker_angle(case, fine))
    M = 10.0 * (1 - fine / 90.0)
    truth = float(np.sum((M[:-1] + M[1:]) / 2 * np.diff(th)))
    r = analyze(case, n_points=3600)
    assert r.loads.W_parts[K("couple", "t")][-1] == pytest.approx(truth, rel=1e-6)


FORCE_TABLE = """
[[forces]]
name = "press"
point = "B"
direction = "against-velocity"
table_of = "travel"
table = [[0.0, 0.0], [0.05, 100.0], [0.10, 100.0], [0.15, 0.0]]
phi_range_deg = [40.0, 220.0]
"""


def test_force_versus_travel_work_is_the_tables_area():
    case = case_of(FORCE_TABLE)
    r = analyze(case, n_points=720)
    area = float(np.trapezoid([0.0, 100.0, 100.0, 0.0], [0.0, 0.05, 0.10, 0.15]))
    assert r.loads.W_parts[K("force", "press")][-1] == pytest.approx(-area, rel=1e-12)
    # the table ends within the range: B's arc over it, 0.3·Δθ3, is longer than 0.15 m
    th = rocker_angle(case, [40.0, 220.0])
    assert 0.3 * abs(th[1] - th[0]) > 0.15
    assert r.forces.closure < 1e-9


def test_force_versus_travel_on_a_slider_is_exact_on_its_straight_path():
    """The shaper's ram (a straight path): a force table against its travel over the working
    stroke does −(the table's area) of work, to round-off."""
    text = (CASES / "shaper.toml").read_text(encoding="utf-8")
    data = tomllib.loads(text)
    ram = next(d for d in data["dyads"] if d["kind"] == "RRP")
    data["forces"] = [{"name": "f", "point": ram["joint"], "table_of": "travel",
                       "table": [[0.0, 0.0], [0.02, 500.0], [0.2, 500.0]],
                       "phi_range_deg": [0.0, 90.0]}]
    r = analyze(parse_case(data, "shaper.toml"), n_points=720)
    k = r.kinematics.points[ram["joint"]].r
    i0, i1 = (int(np.argmin(np.abs(np.degrees(r.phi) - a))) for a in (0.0, 90.0))
    path = float(np.sum(np.hypot(*np.diff(k[i0:i1 + 1], axis=0).T)))
    # the area of the table up to the travel reached (the stroke may end before 0.2 m)
    s = min(path, 0.2)
    area = 0.5 * 0.02 * 500.0 + 500.0 * (s - 0.02)
    assert r.loads.W_parts[K("force", "f")][-1] == pytest.approx(-area, rel=1e-9)


def spring_energy(case, r, P, Q, c, L0):
    k = r.kinematics.points
    L = np.hypot(*(k[P].r - k[Q].r).T)
    return 0.5 * c * (L - L0) ** 2


def test_linear_spring_moment_is_minus_dU_dphi_and_does_no_cycle_work(bundled):
    case, r = bundled
    # the free length from the preload, by the positions at φ = 37°
    at = solve(case.mechanism(), np.radians([37.0]))
    L37 = float(np.hypot(*(at.points["E"].r[0] - at.points["B"].r[0])))
    U = spring_energy(case, r, "E", "B", 200.0, L37 - 20.0 / 200.0)
    dU = np.gradient(U, r.phi, edge_order=2)
    M = r.loads.M_parts[K("spring", "return")]
    np.testing.assert_allclose(M, -dU, rtol=0, atol=2e-4 * np.max(np.abs(M)))
    assert r.loads.W_parts[K("spring", "return")][-1] == pytest.approx(0.0, abs=1e-12)
    trapezoid = float(np.sum((M[:-1] + M[1:]) / 2 * np.diff(r.phi)))
    assert abs(trapezoid) < 1e-4 * np.max(np.abs(M))
    assert r.loads.tensions["return"][int(np.argmin(np.abs(r.phi - math.radians(37))))] == \
        pytest.approx(20.0, rel=1e-9)


TORSION = """
[[springs]]
name = "torsion"
kind = "torsional"
link = "3"
about = "D"
stiffness = 30.0
free_angle_deg = 80.0
"""


def test_torsional_spring_moment_is_minus_dU_dphi_and_does_no_cycle_work():
    case = case_of(TORSION)
    r = analyze(case, n_points=720)
    th = np.unwrap(np.arctan2(*(r.kinematics.points["B"].r - r.kinematics.points["D"].r).T[::-1]))
    U = 0.5 * 30.0 * (th - math.radians(80.0)) ** 2
    dU = np.gradient(U, r.phi, edge_order=2)
    M = r.loads.M_parts[K("spring", "torsion")]
    np.testing.assert_allclose(M, -dU, rtol=0, atol=2e-4 * np.max(np.abs(M)))
    assert r.loads.W_parts[K("spring", "torsion")][-1] == pytest.approx(0.0, abs=1e-12)
    assert r.forces.closure < 1e-9


def test_torsional_spring_on_a_turning_link_is_refused():
    case = case_of(TORSION.replace('link = "3"', 'link = "1"').replace('about = "D"', 'about = "O"'))
    with pytest.raises(InputError, match="turns through whole revolutions"):
        analyze(case, n_points=360)


POINT_FORCES = """
[[forces]]
name = "weight"
point = "S2"
direction = "fixed"
angle_deg = 270.0
magnitude = 50.0

[[forces]]
name = "push"
point = "B"
link = "3"
direction = "across"
magnitude = 15.0
phi_range_deg = [250.0, 20.0]

[[forces]]
name = "pull"
point = "S2"
direction = "along"
table = [[0.0, 5.0], [180.0, 25.0], [360.0, 5.0]]
"""


def test_point_forces_close_the_kinetostatics_and_a_fixed_force_is_conservative():
    case = case_of(POINT_FORCES)
    r = analyze(case, n_points=720)
    assert r.forces.closure < 1e-9
    np.testing.assert_allclose(r.forces.analysis.balancing_moment, r.energy.balancing_moment,
                               rtol=1e-9)
    # a constant force of fixed direction is a potential's: its work is F·e·(r(φ) − r(0))
    S2 = r.kinematics.points["S2"].r
    W = r.loads.W_parts[K("force", "weight")]
    np.testing.assert_allclose(W, -50.0 * (S2[:, 1] - S2[0, 1]), rtol=0, atol=1e-12)
    # across link 3 at B: M = F·(−sin θ3, cos θ3)·v_qB = F·|DB|·ω_q3 inside its range
    M = r.loads.M_parts[K("force", "push")]
    deg = np.degrees(r.phi)
    inside = (deg >= 250 - 1e-9) | (deg <= 20 + 1e-9)
    np.testing.assert_allclose(M[inside], 15.0 * 0.3 * r.kinematics.links["3"].omega_q[inside],
                               rtol=0, atol=1e-9)
    assert np.all(M[~inside] == 0)


def test_reduced_moments_match_the_force_analysis_power_balance():
    """Σ M_parts + M_y·1 = J·ε + ½·J′·ω²: Zhukovsky's lever and the power balance of the force
    analysis (computed from the vectors, not from M_parts) agree with the kinetostatics."""
    case = case_of(POINT_FORCES + TORSION)
    r = analyze(case, n_points=720)
    fa = r.forces
    np.testing.assert_allclose(fa.M_y_zhukovsky, fa.analysis.balancing_moment, rtol=1e-9,
                               atol=1e-9)
    np.testing.assert_allclose(fa.M_y_power, fa.analysis.balancing_moment, rtol=1e-9, atol=1e-9)


def test_table_integral_and_travel_by_hand():
    table = [[0.0, 0.0], [1.0, 2.0], [2.0, 2.0]]
    G = A.table_integral(np.array([-1.0, 0.5, 1.0, 1.5, 2.0, 5.0]), table)
    np.testing.assert_allclose(G, [0.0, 0.25, 1.0, 2.0, 3.0, 3.0])
    phi = np.linspace(0, 2 * np.pi, 5)
    s = A.travel(phi, np.ones(4), (math.pi, math.pi / 2), 2 * np.pi)
    np.testing.assert_allclose(s, [2.0, 3.0, 0.0, 1.0, 2.0])
