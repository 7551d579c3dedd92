"""Force analysis (flywheel.dynamics.forces) against truths that do not use it.

Layers:
(a) the slider-crank's closed forms at constant ω (Khurmi & Gupta, «Theory of Machines»,
    ch. 15 "Inertia forces in reciprocating parts": net piston effort F_P = F_L − F_I, thrust
    in the rod F_Q = F_P/cos β, on the cylinder walls F_N = F_P·tan β, crank-pin effort
    F_T = F_Q·sin(θ + β), F_R = F_Q·cos(θ + β), turning moment T = F_T·r =
    F_P·r·(sin θ + sin 2θ/(2√(n² − sin²θ)))), with the exact piston acceleration written here;
(b) statics (ω = 0) by hand: a force on a piston, weights on a crank and on a slider whose
    centroid is off its joint (where the guide's force acts);
(c) an independent formulation: the whole mechanism's Newton–Euler equations (three per
    moving link, every pair's unknowns at once, Norton, «Design of Machinery», ch. 11) in one
    matrix solved by numpy.linalg.solve at single angles — no Assur groups, no order — for the
    four-bar, the slotted link and the compressor, with their true motion;
(d) the three balancing moments (kinetostatics, Zhukovsky's lever, power balance) agree at
    every grid node; the closure M_y = M_D with the true motion on every bundled linkage case;
(e) the frame's shaking force and moment against −Σ m·a_S (and Σ moments) plus outside loads;
(f) singular groups and bad names give one InputError line.
"""
from __future__ import annotations

import functools
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case, to_mechanism
from flywheel.dynamics import forces as fo
from flywheel.errors import InputError
from flywheel.linkage import RRP, Crank, Guide, LinkPoint, Mechanism, solve
from flywheel.linkage.solve import Kinematics, PointMotion

from helpers import case_setup  # the bundled cases' loads built in the tests (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
DEG = math.pi / 180
G = 9.81


# -- (a) the slider-crank's textbook closed forms ------------------------------------------------

def engine(r: float, l: float, m_piston: float, direction: int = 1) -> tuple:
    """A horizontal engine: crank r from O = (0, 0), θ = 0 at the inner dead centre with the
    crank pointing at the piston (Khurmi's i.d.c.), rod l, piston on the +x axis; massless
    crank and rod, the reciprocating mass on the piston."""
    mech = Mechanism(Crank("1", "O", (0.0, 0.0), "A", r, 0.0, direction),
                     (RRP("B", "A", "B", "2", l, "3", Guide((0.0, 0.0), 0.0)),))
    return mech, {"3": fo.LinkMass(m_piston, 0.0, "B")}


def piston_closed_form(r: float, l: float, theta: np.ndarray) -> tuple:
    """x = r·cos θ + √(l² − r²·sin²θ) and its exact d²x/dθ² (written out here):
    x″ = −r·cos θ − r²·cos 2θ/q − r⁴·sin²θ·cos²θ/q³, q = √(l² − r²·sin²θ); sin β = sin θ/n."""
    s, c = np.sin(theta), np.cos(theta)
    q = np.sqrt(l**2 - r**2 * s**2)
    x2 = -r * c - r**2 * (c**2 - s**2) / q - r**4 * s**2 * c**2 / q**3
    beta = np.arcsin(s * r / l)
    return x2, beta


def test_khurmi_horizontal_engine_at_60_deg():
    """Khurmi & Gupta ch. 15, the worked example of a horizontal engine: crank-pin circle
    radius 300 mm, reciprocating mass 250 kg, rod 1.2 m, bore 0.5 m, 250 rpm, θ = 60° from
    the i.d.c., net pressure 0.35 N/mm² on the piston (towards the crank). The book takes
    F_I from the two-term series m·ω²·r·(cos θ + cos 2θ/n); values of that series, computed
    here, in the comments; the exact values asserted (the series is off by O(1/n³))."""
    r, l, m, bore, N = 0.3, 1.2, 250.0, 0.5, 250.0
    w = 2 * math.pi * N / 60
    th = np.array([60 * DEG])
    mech, masses = engine(r, l, m)
    F_L = 0.35e6 * math.pi * bore**2 / 4                       # 68 722.3 N on the piston
    gas = fo.PointForce("gas", "3", "B", np.array([-F_L, 0.0]))
    fa = fo.kinetostatics(mech, solve(mech, th), w, 0.0, fo.Loads(masses, (gas,)))
    sc = fa.slider_crank["3"]

    x2, beta = piston_closed_form(r, l, th)
    F_I = -m * w**2 * x2                                       # series: 19 276.6 N
    F_P = F_L - F_I                                            # series: 49 445.8 N
    assert F_I[0] == pytest.approx(19282.306155, abs=1e-6)
    assert sc.piston_effort == pytest.approx(F_P, rel=1e-13)
    assert sc.piston_effort[0] == pytest.approx(49440.033142, abs=1e-6)
    series = F_L - m * w**2 * r * (math.cos(th[0]) + math.cos(2 * th[0]) * r / l)
    assert sc.piston_effort[0] == pytest.approx(series, rel=2e-4)  # the book's method
    F_Q = F_P / np.cos(beta)                                   # series: 50 647.1 N
    assert sc.rod_thrust == pytest.approx(F_Q, rel=1e-13)
    assert sc.rod_thrust[0] == pytest.approx(50641.180698, abs=1e-6)
    # the piston's thrust on the wall: F_P·tan β (series: 10 965.4 N), pushing it down (−n)
    assert sc.side_thrust == pytest.approx(-F_P * np.tan(beta), rel=1e-13)
    assert sc.crank_pin_tangential == pytest.approx(F_Q * np.sin(th + beta), rel=1e-13)
    assert sc.crank_pin_radial == pytest.approx(F_Q * np.cos(th + beta), rel=1e-13)
    n = l / r
    T = F_P * r * (np.sin(th) + np.sin(2 * th) / (2 * np.sqrt(n**2 - np.sin(th) ** 2)))
    assert sc.turning_moment == pytest.approx(T, rel=1e-13)
    assert fa.balancing_moment == pytest.approx(-T, rel=1e-13)   # massless crank and rod
    # the gudgeon pin load reverses where F_I = F_L: ω = √(F_L/(m·(−x″))), 471.96 rpm
    # (series: 472.03 rpm)
    w_rev = math.sqrt(F_L / (m * -x2[0]))
    for k, sign in ((0.999, 1), (1.0, 0), (1.001, -1)):
        fa_rev = fo.kinetostatics(mech, solve(mech, th), k * w_rev, 0.0, fo.Loads(masses, (gas,)))
        thrust = fa_rev.slider_crank["3"].rod_thrust[0]
        assert (abs(thrust) < 1e-9 * F_L) if sign == 0 else (np.sign(thrust) == sign)


@pytest.mark.parametrize("direction", [1, -1])
def test_slider_crank_closed_forms_over_the_cycle(direction):
    """Constant ω, a constant gas force towards the crank, the piston's mass only: every
    textbook quantity at 24 angles over the cycle (both directions of rotation: Khurmi's θ is
    the angle turned, so with cw rotation θ = −θ1 and the formulas hold with θ)."""
    r, l, m, w, F_L = 0.05, 0.2, 0.8, 300.0, 4000.0
    mech, masses = engine(r, l, m, direction)
    phi = np.arange(24) * 15 * DEG + 1 * DEG                   # off the dead centres
    kin = solve(mech, phi)
    gas = fo.PointForce("gas", "3", "B", np.array([-F_L, 0.0]))
    fa = fo.kinetostatics(mech, kin, w, 0.0, fo.Loads(masses, (gas,)))
    sc = fa.slider_crank["3"]
    x2, beta = piston_closed_form(r, l, phi)                   # θ = φ turned, either way
    F_P = F_L + m * w**2 * x2
    F_Q = F_P / np.cos(beta)
    scale = F_L
    np.testing.assert_allclose(sc.piston_effort, F_P, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(sc.rod_thrust, F_Q, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(np.abs(sc.side_thrust), np.abs(F_P * np.tan(beta)), rtol=0,
                               atol=1e-12 * scale)
    np.testing.assert_allclose(sc.crank_pin_tangential, F_Q * np.sin(phi + beta), rtol=0,
                               atol=1e-12 * scale)
    np.testing.assert_allclose(sc.crank_pin_radial, F_Q * np.cos(phi + beta), rtol=0,
                               atol=1e-12 * scale)
    np.testing.assert_allclose(sc.turning_moment, -fa.balancing_moment, rtol=0, atol=1e-12 * scale * r)
    # with massless crank and rod the main bearing carries the crank-pin effort
    bearing = fa.main_bearing_load
    np.testing.assert_allclose(bearing.x, sc.crank_pin_x, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(bearing.y, sc.crank_pin_y, rtol=0, atol=1e-12 * scale)
    np.testing.assert_allclose(bearing.magnitude, np.hypot(sc.crank_pin_tangential,
                                                           sc.crank_pin_radial), rtol=1e-12)


# -- (b) statics by hand -------------------------------------------------------------------------

@pytest.mark.parametrize("deg", [30.0, 100.0, 250.0])
def test_static_force_on_a_piston_by_hand(deg):
    """ω = 0: a force P on the piston towards the crank, massless links. Hand statics: the rod
    is a two-force member along B → A with F_Q = P/cos β; the wall pushes the piston by
    P·tan β; the crank needs M = F_Q·r·sin(θ + β) against the rotation (M_y = −that); the
    bearing carries −(rod on crank)."""
    r, l, P = 0.1, 0.35, 1000.0
    mech, _ = engine(r, l, 0.0)
    th = np.array([deg * DEG])
    kin = solve(mech, th)
    fa = fo.kinetostatics(mech, kin, 0.0, 0.0,
                          fo.Loads(forces=(fo.PointForce("P", "3", "B", np.array([-P, 0.0])),)))
    A, B = kin.points["A"].r[0], kin.points["B"].r[0]
    e_BA = (A - B) / np.linalg.norm(A - B)
    beta = math.asin(math.sin(th[0]) * r / l)
    F_Q = P / math.cos(beta)
    on_pin = F_Q * e_BA                                         # rod on crank
    assert fa.reaction("2", "1").vector[0] == pytest.approx(on_pin, abs=1e-12 * P)
    assert fa.crank_bearing.vector[0] == pytest.approx(-on_pin, abs=1e-12 * P)
    assert fa.reaction("0", "3").y[0] == pytest.approx(P * math.tan(beta), abs=1e-12 * P)
    assert fa.balancing_moment[0] == pytest.approx(-F_Q * r * math.sin(th[0] + beta), abs=1e-12 * P * r)
    assert fa.reaction("3", "2").vector[0] == pytest.approx(on_pin, abs=1e-12 * P)  # slider on rod


@pytest.mark.parametrize("deg", [0.0, 60.0, 135.0])
def test_static_weight_of_a_crank_by_hand(deg):
    """A crank of mass m with its centroid half way out, at rest in a vertical plane, with a
    massless slider-crank behind it: the drive holds the weight's moment m·g·(r/2)·cos θ
    (counter-clockwise crank), the bearing carries the weight."""
    r, m = 0.2, 3.0
    base, _ = engine(r, 0.6, 0.0)
    mech = replace(base, points=(LinkPoint("S1", "1", "O", distance=r / 2),))
    kin = solve(mech, np.array([deg * DEG]))
    fa = fo.kinetostatics(mech, kin, 0.0, 0.0,
                          fo.Loads({"1": fo.LinkMass(m, 0.01, "S1")}, gravity=(0.0, -G)))
    assert fa.balancing_moment[0] == pytest.approx(m * G * r / 2 * math.cos(deg * DEG), abs=1e-12)
    assert fa.crank_bearing.vector[0] == pytest.approx([0.0, m * G], abs=1e-12)
    assert np.abs(fa.reaction("1", "2").vector).max() < 1e-12


def test_static_weight_of_a_slider_off_its_joint():
    """A slider of weight W whose centroid lies d = 0.05 m ahead of its joint B along a
    horizontal guide: the guide pushes up by W along the vertical through the centroid, so its
    line of action is offset by +d from B; the rod carries nothing."""
    mech0, _ = engine(0.1, 0.3, 0.0)
    mech = replace(mech0, points=(LinkPoint("S3", "3", "B", distance=0.05),))
    W = 2.0 * G
    fa = fo.kinetostatics(mech, solve(mech, np.array([40 * DEG, 200 * DEG])), 0.0, 0.0,
                          fo.Loads({"3": fo.LinkMass(2.0, 0.0, "S3")}, gravity=(0.0, -G)))
    guide = fa.slides["B:0->3"]
    assert guide.normal == pytest.approx([W, W], rel=1e-14)
    assert guide.offset == pytest.approx([0.05, 0.05], rel=1e-12)
    assert guide.n[0] == pytest.approx([0.0, 1.0])
    assert np.abs(fa.reaction("2", "3").vector).max() < 1e-12
    assert np.abs(fa.balancing_moment).max() < 1e-12
    # the foundation feels the weight where it hangs: moment −W·x_S about O
    x_S = solve(mech, fa.phi).points["S3"].r[:, 0]
    assert fa.shaking_force == pytest.approx(np.array([[0.0, -W]] * 2), abs=1e-12)
    assert fa.shaking_moment == pytest.approx(-W * x_S, abs=1e-12)


# -- (c) an independent formulation: Newton–Euler of the whole mechanism ----------------------

def newton_euler(kin, i: int, links: list[str], pairs: list[tuple], applied: dict, crank: str):
    """Solve every link's force and moment balance at grid node i at once.

    pairs: ("R", point, by, on) — a revolute pair, unknown force (Rx, Ry) of ``by`` on ``on``
    at the point; ("P", point, by, on, n) — a prismatic pair, unknown normal force N along the
    unit normal n (2,) through the point and couple C. applied: link → (Fx, Fy, M about the
    origin) of every given and inertia load. Unknown M_y: a ccw couple on the crank.
    Returns {(by, on): unknowns} and M_y (ccw)."""
    row = {name: 3 * k for k, name in enumerate(links)}
    cols = []
    for p in pairs:
        cols += [(p, 0), (p, 1)]
    cols.append(("My", None))
    A = np.zeros((3 * len(links), len(cols)))
    b = np.zeros(3 * len(links))
    for name, (fx, fy, mz) in applied.items():
        b[row[name]: row[name] + 3] -= (fx, fy, mz)
    for c, (p, k) in enumerate(cols):
        if p == "My":
            A[row[crank] + 2, c] = 1.0
            continue
        x, y = kin.points[p[1]].r[i]
        if p[0] == "R":
            f = (1.0, 0.0) if k == 0 else (0.0, 1.0)
            load = (f[0], f[1], x * f[1] - y * f[0])
        elif k == 0:                                  # prismatic: normal force N·n through the point
            nx, ny = p[4]
            load = (nx, ny, x * ny - y * nx)
        else:                                         # prismatic: couple C
            load = (0.0, 0.0, 1.0)
        for link, sign in ((p[3], 1.0), (p[2], -1.0)):
            if link in row:
                A[row[link]: row[link] + 3, c] += sign * np.array(load)
    sol = np.linalg.solve(A, b)
    out = {}
    for c in range(0, len(cols) - 1, 2):
        p = cols[c][0]
        out[(p[2], p[3])] = sol[c: c + 2]
    return out, sol[-1]


def applied_loads(kin, i: int, w: float, e: float, masses: dict, point_forces: list,
                  gravity, J_I: float, crank: str, direction: int) -> dict:
    """The resultant (Fx, Fy, M about the origin) per link at node i of: weights, given point
    forces (link, point, F (2,)), d'Alembert's −m·(a_q·ω² + v_q·ε) and −J_S·(ε_q·ω² + ω_q·ε),
    and −J_I·direction·ε on the crank."""
    out: dict[str, np.ndarray] = {}

    def add(link, point, F):
        x, y = kin.points[point].r[i]
        out.setdefault(link, np.zeros(3))
        out[link] += (F[0], F[1], x * F[1] - y * F[0])

    for name, m in masses.items():
        L = kin.links[name]
        out.setdefault(name, np.zeros(3))
        out[name][2] -= m.J_S * (L.eps_q[i] * w**2 + L.omega_q[i] * e)
        if m.mass:
            S = kin.points[m.centroid]
            a = S.a_q[i] * w**2 + S.v_q[i] * e
            add(name, m.centroid, -m.mass * a + m.mass * np.asarray(gravity))
    for link, point, F in point_forces:
        add(link, point, F)
    out.setdefault(crank, np.zeros(3))
    out[crank][2] -= J_I * direction * e
    return out


@functools.cache
def analysed(name: str) -> dict:
    """case_setup with the force analysis of the true motion, once per case."""
    st = case_setup(name)
    st["name"] = name
    st["fa"] = fo.kinetostatics(st["mech"], st["kin"], st["omega"], st["eps"], st["loads"])
    return st


@pytest.fixture(params=["compressor", "fourbar", "slotted_link"])
def bundled(request):
    return analysed(request.param)


PAIRS = {   # each bundled mechanism's pairs, written out by hand from its case file
    "fourbar": [("R", "O", "0", "1"), ("R", "A", "1", "2"), ("R", "B", "2", "3"),
                ("R", "D", "0", "3")],
    "compressor": [("R", "O", "0", "1"), ("R", "A", "1", "2"), ("R", "A", "1", "4"),
                   ("R", "B", "2", "3"), ("R", "C", "4", "5"),
                   ("P", "B", "0", "3", (-1.0, 0.0)),       # vertical guide: left normal −x
                   ("P", "C", "0", "5", (0.0, 1.0))],
    "slotted_link": [("R", "O", "0", "1"), ("R", "A", "1", "2"), ("P", "A", "3", "2", None),
                     ("R", "P", "0", "3"), ("R", "D", "3", "4"), ("R", "E", "4", "5"),
                     ("P", "E", "0", "5", (0.0, 1.0))],
}


@pytest.mark.parametrize("deg", [0.0, 37.0, 120.0, 233.0, 301.0])
def test_reactions_against_newton_euler(bundled, deg):
    """Every reaction, slide force and couple, and M_y at single angles of each bundled case,
    true motion, against the whole-mechanism Newton–Euler matrix solved directly."""
    kin, mech, loads = bundled["kin"], bundled["mech"], bundled["loads"]
    fa = bundled["fa"]
    i = int(np.argmin(np.abs(kin.phi - deg * DEG)))
    w, e = bundled["omega"][i], bundled["eps"][i]
    pairs = []
    for p in PAIRS[bundled["name"]]:
        if p[0] == "P" and p[4] is None:          # the slot: normal to the rocker
            th = kin.links[p[2]].theta[i]
            p = p[:4] + ((-math.sin(th), math.cos(th)),)
        pairs.append(p)
    pf = [(f.link, f.point, np.asarray(f.F)[i]) for f in loads.forces]
    applied = applied_loads(kin, i, w, e, loads.masses, pf, loads.gravity, loads.J_first_group,
                            mech.crank.name, mech.crank.direction)
    links = sorted(kin.links)
    sol, My_ccw = newton_euler(kin, i, links, pairs, applied, mech.crank.name)
    scale = max(np.abs(v).max() for v in sol.values())
    assert fa.balancing_moment_ccw[i] == pytest.approx(My_ccw, abs=1e-10 * scale)
    assert len(fa.joints) == len(pairs)
    for p in pairs:
        got = sol[(p[2], p[3])]
        if p[0] == "R":
            r = fa.reaction(p[2], p[3])
            assert [r.x[i], r.y[i]] == pytest.approx(got, abs=1e-10 * scale), p
        else:
            s = fa.slides[f"{p[1]}:{p[2]}->{p[3]}"]
            assert s.n[i] == pytest.approx(p[4], abs=1e-14)
            assert [s.normal[i], s.couple[i]] == pytest.approx(got, abs=1e-10 * scale), p


def test_four_bar_with_a_couple_and_a_coupler_force_against_newton_euler():
    """The four-bar under a couple on the rocker, a force at the coupler point P (off the
    joints) and a steady speed, at angles over the cycle: the group's reactions against the
    Newton–Euler matrix, and the three balancing moments."""
    case = load_case(CASES / "fourbar.toml")
    mech = to_mechanism(case)
    phi = np.radians([10.0, 95.0, 180.0, 270.0])
    kin = solve(mech, phi)
    F = np.array([30.0, -80.0])
    loads = fo.Loads(case.links, (fo.PointForce("tool", "2", "P", F, on_frame=False),),
                     (fo.Couple("brake", "3", -15.0),), (0.0, -G), 0.02)
    w, e = 2 * math.pi * 2, 0.0
    fa = fo.kinetostatics(mech, kin, w, e, loads)
    for i in range(phi.size):
        applied = applied_loads(kin, i, w, e, case.links, [("2", "P", F)], (0.0, -G), 0.02, "1", 1)
        applied["3"][2] += -15.0
        sol, My = newton_euler(kin, i, ["1", "2", "3"], PAIRS["fourbar"], applied, "1")
        assert fa.balancing_moment[i] == pytest.approx(My, abs=1e-10 * 100)
        for (by, on), R in sol.items():
            assert fa.reaction(by, on).vector[i] == pytest.approx(R, abs=1e-10 * 100)
    for other in (fo.zhukovsky_moment, fo.power_balance_moment):
        np.testing.assert_allclose(other(mech, kin, w, e, loads), fa.balancing_moment,
                                   rtol=0, atol=1e-12 * 100)


def test_six_bar_with_a_group_on_a_shared_pin_against_newton_euler():
    """The four-bar with a slider-crank group hung on its joint B (a rod 4 from B to a slider
    5 on the horizontal y = 0.45 m): B is shared by the coupler 2, the rocker 3 and the rod 4;
    the rod's reaction goes to the coupler (carriers: an RRR's joint is carried by link_a).
    Every reaction and M_y against the Newton–Euler matrix, true-looking motion (ω and ε
    varying), and the three balancing moments."""
    case = load_case(CASES / "fourbar.toml")
    base = to_mechanism(case)
    mech = replace(base,
                   dyads=base.dyads + (RRP("E", "B", "E", "4", 0.3, "5", Guide((0.0, 0.45), 0.0)),),
                   points=base.points + (LinkPoint("S4", "4", "B", "E", 0.5),))
    assert fo.carriers(mech)["B"] == "2"
    phi = np.radians([0.0, 50.0, 140.0, 260.0])
    kin = solve(mech, phi)
    w = 12.0 + np.sin(phi)
    e = 5.0 * np.cos(phi)
    masses = dict(case.links, **{"4": fo.LinkMass(1.0, 0.01, "S4"), "5": fo.LinkMass(2.0, 0.0, "E")})
    F = np.array([-40.0, 0.0])
    loads = fo.Loads(masses, (fo.PointForce("work", "5", "E", F),), (fo.Couple("c", "4", 2.5),),
                     (0.0, -G), 0.05)
    fa = fo.kinetostatics(mech, kin, w, e, loads)
    pairs = PAIRS["fourbar"] + [("R", "B", "2", "4"), ("R", "E", "4", "5"),
                                ("P", "E", "0", "5", (0.0, 1.0))]
    assert len(fa.joints) == len(pairs)
    for i in range(phi.size):
        applied = applied_loads(kin, i, w[i], e[i], masses, [("5", "E", F)], (0.0, -G), 0.05, "1", 1)
        applied["4"][2] += 2.5
        sol, My = newton_euler(kin, i, ["1", "2", "3", "4", "5"], pairs, applied, "1")
        scale = max(np.abs(v).max() for v in sol.values())
        assert fa.balancing_moment[i] == pytest.approx(My, abs=1e-10 * scale)
        for p in pairs:
            if p[0] == "R":
                assert fa.reaction(p[2], p[3]).vector[i] == pytest.approx(sol[(p[2], p[3])],
                                                                          abs=1e-10 * scale), p
            else:
                sl = fa.slides["E:0->5"]
                assert [sl.normal[i], sl.couple[i]] == pytest.approx(sol[("0", "5")], abs=1e-10 * scale)
    for other in (fo.zhukovsky_moment, fo.power_balance_moment):
        np.testing.assert_allclose(other(mech, kin, w, e, loads), fa.balancing_moment, rtol=0,
                                   atol=1e-12 * float(np.max(np.abs(fa.balancing_moment))))


# -- (d) three balancing moments, and the closure with the dynamics --------------------------

def test_three_balancing_moments_agree_at_every_node(bundled):
    args = (bundled["mech"], bundled["kin"], bundled["omega"], bundled["eps"], bundled["loads"])
    My = bundled["fa"].balancing_moment
    scale = max(abs(bundled["M_D"]), float(np.max(np.abs(bundled["fa"].first_group_couple))))
    for other in (fo.zhukovsky_moment(*args), fo.power_balance_moment(*args)):
        assert np.max(np.abs(other - My)) <= 1e-12 * scale


def test_three_balancing_moments_agree_in_steady_motion(bundled):
    """ω constant, ε = 0 (the textbook's "uniform rotation"): M_y varies, the three agree, and
    its cycle mean is M_D (the inertia loads do no work over a cycle)."""
    w = bundled["case"].machine.omega_mean
    args = (bundled["mech"], bundled["kin"], w, 0.0, bundled["loads"])
    fa = fo.kinetostatics(*args)
    My = fa.balancing_moment
    scale = float(np.max(np.abs(My)))
    assert scale > 0
    for other in (fo.zhukovsky_moment(*args), fo.power_balance_moment(*args)):
        assert np.max(np.abs(other - My)) <= 1e-12 * scale
    phi = bundled["kin"].phi
    mean = float(np.sum(0.5 * (My[1:] + My[:-1]) * np.diff(phi)) / (2 * np.pi))
    assert mean == pytest.approx(bundled["M_D"], abs=1e-3 * scale)


def test_closure_with_the_true_motion(bundled):
    """M_y = M_D at every node with ω(φ), ε(φ) of the dynamics and −J_I·ε on the crank. The
    pipeline's ε is the equation of motion solved at each node, so this is round-off.
    Measured: compressor 2.3e-15, slotted_link 2.7e-15 (relative to M_D); fourbar (M_D = 0)
    8e-16 relative to max |J_I·ε|."""
    assert fo.closure(bundled["fa"], bundled["M_D"]) < 1e-11


def test_closure_fails_without_the_first_group_couple(bundled):
    """A check that can fail: without the flywheel's couple M_y is not M_D."""
    loads = replace(bundled["loads"], J_first_group=0.0)
    fa = fo.kinetostatics(bundled["mech"], bundled["kin"], bundled["omega"], bundled["eps"], loads)
    scale = max(abs(bundled["M_D"]), float(np.max(np.abs(bundled["fa"].first_group_couple))))
    assert np.max(np.abs(fa.balancing_moment - bundled["M_D"])) > 0.1 * scale


def test_cw_crank_moment_is_in_the_direction_of_rotation():
    """The compressor's crank turns clockwise: M_y = +M_D > 0 drives it, so its ccw value is
    negative."""
    st = analysed("compressor")
    assert st["mech"].crank.direction == -1
    fa = st["fa"]
    assert st["M_D"] > 0
    assert np.all(fa.balancing_moment > 0) and np.all(fa.balancing_moment_ccw < 0)


# -- (e) the frame ---------------------------------------------------------------------------------

def test_shaking_force_and_moment(bundled):
    """All that the mechanism puts on its frame (joint and guide forces, reactions of the gas
    and cutting forces, the drive's reaction −M_y) equals −Σ m·a_S plus the weights, and its
    moment about the crank pivot the moments of the inertia loads (first group included) and
    of the weights."""
    kin, loads, fa = bundled["kin"], bundled["loads"], bundled["fa"]
    w, e = bundled["omega"], bundled["eps"]
    O = kin.points[bundled["mech"].crank.pivot].r
    g = np.asarray(loads.gravity)
    F = np.zeros_like(O)
    M = -loads.J_first_group * bundled["mech"].crank.direction * e
    for name, m in loads.masses.items():
        L = kin.links[name]
        M = M - m.J_S * (L.eps_q * w**2 + L.omega_q * e)
        S = kin.points[m.centroid]
        f = -m.mass * (S.a_q * (w**2)[:, None] + S.v_q * e[:, None]) + m.mass * g
        F = F + f
        d = S.r - O
        M = M + d[:, 0] * f[:, 1] - d[:, 1] * f[:, 0]
    scale = float(np.max(np.abs(F)))
    np.testing.assert_allclose(fa.shaking_force, F, rtol=0, atol=1e-11 * scale)
    np.testing.assert_allclose(fa.shaking_moment, M, rtol=0,
                               atol=1e-11 * float(np.max(np.abs(M))))


def test_shaking_force_counts_loads_from_outside():
    """A force from outside the machine (on_frame False) passes to the foundation; one that
    reacts on the frame (on_frame True) does not."""
    mech, masses = engine(0.1, 0.4, 0.0)
    kin = solve(mech, np.radians([30.0, 140.0]))
    F = np.array([-500.0, 20.0])
    for on_frame, expected in ((True, [0.0, 0.0]), (False, F)):
        fa = fo.kinetostatics(mech, kin, 0.0, 0.0, fo.Loads(
            forces=(fo.PointForce("P", "3", "B", F, on_frame=on_frame),)))
        assert fa.shaking_force == pytest.approx(np.array([expected, expected]), abs=1e-10)


# -- conventions, slides -----------------------------------------------------------------------

def test_reaction_keys_and_reversal(bundled):
    fa = bundled["fa"]
    for key, r in fa.joints.items():
        assert key == f"{r.joint}:{r.by}->{r.on}"
        back = fa.reaction(r.on, r.by)
        np.testing.assert_array_equal(back.x, -r.x)
        np.testing.assert_array_equal(back.magnitude, r.magnitude)
    with pytest.raises(KeyError):
        fa.reaction("1", "nonexistent")


def test_slotted_link_block_force_is_normal_to_the_rocker():
    """The rocker's force on the block is normal to the slot and its line of action passes
    where the block's moment balance puts it: Q·h = C."""
    st = analysed("slotted_link")
    fa, kin = st["fa"], st["kin"]
    s = fa.slides["A:3->2"]
    th = kin.links["3"].theta
    np.testing.assert_allclose(s.n[:, 0] * np.cos(th) + s.n[:, 1] * np.sin(th), 0, atol=1e-15)
    ok = s.normal != 0
    np.testing.assert_allclose(s.offset[ok] * s.normal[ok], s.couple[ok], rtol=1e-12)


def test_compressor_textbook_quantities_are_consistent():
    """For each slider-crank group of the compressor (rods with mass): the turning moments of
    the two rods plus the crank's own loads give M_y, and the side thrust is the guide force."""
    fa = analysed("compressor")["fa"]
    assert set(fa.slider_crank) == {"3", "5"}
    T = sum(sc.turning_moment for sc in fa.slider_crank.values())
    # the crank carries only the first-group couple: M_y·dir + T·dir + couple = 0 (ccw)
    d = fa.direction
    np.testing.assert_allclose(fa.balancing_moment_ccw + d * T + fa.first_group_couple, 0,
                               atol=1e-10 * float(np.max(np.abs(T))))
    for slider, key in (("3", "B:0->3"), ("5", "C:0->5")):
        np.testing.assert_array_equal(fa.slider_crank[slider].side_thrust, -fa.slides[key].normal)


# -- (f) bad input ----------------------------------------------------------------------------------

def moved(kin: Kinematics, point: str, i: int, r) -> Kinematics:
    """``kin`` with ``point`` moved to ``r`` at node i (its analogues kept): a position the
    kinematics itself refuses (it stops at a dead or locked position first), made by hand to
    reach the force analysis' own check."""
    pm = kin.points[point]
    pos = pm.r.copy()
    pos[i] = r
    return Kinematics(kin.phi, dict(kin.points, **{point: PointMotion(pos, pm.v_q, pm.a_q)}),
                      kin.links)


def test_rrp_singular_position_names_group_and_angle():
    """The rod perpendicular to the guide (B right below A): the group's 2×2 system is
    singular. (solve() refuses that position itself, as a dead position of the dyad.)"""
    mech, masses = engine(0.1, 0.1, 1.0)
    kin = solve(mech, np.array([30 * DEG, 89 * DEG]))
    A = kin.points["A"].r[1]
    with pytest.raises(InputError, match=r"group B \(RRP, rod 2\) is singular.*φ = 89\.00°") as err:
        fo.kinetostatics(mech, moved(kin, "B", 1, (A[0], 0.0)), 1.0, 0.0, fo.Loads(masses))
    assert "\n" not in str(err.value)


def test_rrr_singular_position_names_group_and_angle():
    """A four-bar whose coupler and rocker are in line (a locked position): B on the line
    A–D. (solve() refuses that position itself.)"""
    case = load_case(CASES / "fourbar.toml")
    mech = to_mechanism(case)
    kin = solve(mech, np.array([0.0, 120 * DEG]))
    A, D = kin.points["A"].r[1], kin.points["D"].r[1]
    locked = moved(kin, "B", 1, A + 0.4 * (D - A) / np.linalg.norm(D - A))
    with pytest.raises(InputError, match=r"group B \(RRR, links 2–3\) is singular.*φ = 120\.00°"):
        fo.kinetostatics(mech, locked, 1.0, 0.0, fo.Loads(case.links))


def test_rpr_singular_position_names_group_and_angle():
    """The block on the rocker's pivot: Q = (M_q^P + M_k^A)/s with s = 0."""
    case = load_case(CASES / "slotted_link.toml")
    mech = to_mechanism(case)
    kin = solve(mech, np.array([0.0, 200 * DEG]))
    with pytest.raises(InputError, match=r"group 3 \(RPR, rocker 3\) is singular.*φ = 200\.00°"):
        fo.kinetostatics(mech, moved(kin, "A", 1, kin.points["P"].r[1]), 1.0, 0.0,
                         fo.Loads(case.links))


def test_bad_names_and_shapes():
    mech, masses = engine(0.1, 0.4, 1.0)
    kin = solve(mech, np.radians([10.0, 20.0]))
    with pytest.raises(InputError, match="masses: no link named '9'"):
        fo.kinetostatics(mech, kin, 1.0, 0.0, fo.Loads({"9": fo.LinkMass(1.0, 0.0, "B")}))
    with pytest.raises(InputError, match="forces.P.point: no point named 'Z'"):
        fo.kinetostatics(mech, kin, 1.0, 0.0,
                         fo.Loads(forces=(fo.PointForce("P", "3", "Z", np.zeros(2)),)))
    with pytest.raises(InputError, match="omega has shape"):
        fo.kinetostatics(mech, kin, np.ones(3), 0.0, fo.Loads(masses))
    zero = replace(mech, crank=replace(mech.crank, name="0"))
    with pytest.raises(InputError, match="a link is named '0', the name of the frame"):
        fo.kinetostatics(zero, solve(zero, np.radians([10.0])), 1.0, 0.0, fo.Loads())


def test_case_without_masses_gives_reactions_of_the_given_forces_alone():
    """No masses, no first group: the reactions come from the given forces only, and do not
    depend on the speed."""
    mech, _ = engine(0.1, 0.4, 0.0)
    kin = solve(mech, np.radians([15.0, 75.0, 200.0]))
    loads = fo.Loads(forces=(fo.PointForce("P", "3", "B", np.array([-100.0, 0.0])),))
    slow = fo.kinetostatics(mech, kin, 1.0, 0.0, loads)
    fast = fo.kinetostatics(mech, kin, 500.0, 3.0, loads)
    for key in slow.joints:
        np.testing.assert_allclose(slow.joints[key].vector, fast.joints[key].vector, atol=1e-12)


def test_closure_of_its_three_references():
    """One closure for both routes (stages.force_analysis and forces.closure): relative to M_D,
    else to max|J_I·ε|, else absolute — checked by hand on three-node grids."""
    M_y = np.array([10.0, 10.5, 9.0])
    assert fo.closure_of(M_y, 10.0, np.zeros(3)) == (0.1, "M_D")
    assert fo.closure_of(M_y - 10.0, 0.0, np.array([2.0, -4.0, 1.0])) == (0.25, "J_I·ε")
    assert fo.closure_of(M_y - 10.0, 0.0, np.zeros(3)) == (1.0, "absolute")
