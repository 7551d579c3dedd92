"""The kinematics engine (design.md §3): Assur dyads RRP, RRR, RPR and points on links.

Layers:
(a) seed 000_e85f126679b234dc.txt, the compressor's analogues at φ = 75° (§2.2–2.3 of the seed);
(b) every analogue of every dyad type against an independent numerical derivative of the
    positions and angles (8th-order central differences), agreement 1e-8 relative;
(c) the slider-crank against its closed forms (stroke, dead-centre angles, x(φ) and x′(φ));
(d) a four-bar and a slotted-link mechanism placed by hand geometry at two angles each;
(e) a dyad that cannot be assembled names itself and the crank angle;
(f) loop closure: every rod keeps its length over the cycle.

Style: a seed's printed number in a comment, the tolerance half a unit of its last digit.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from flywheel.cases.run import load_case, to_mechanism
from flywheel.errors import AssemblyError
from flywheel.linkage import RPR, RRP, RRR, Crank, Guide, LinkPoint, Mechanism, solve
from flywheel.linkage.deadcentres import dead_centres

CASES = Path(__file__).resolve().parents[2] / "cases"
DEG = math.pi / 180


# -- helpers ------------------------------------------------------------------------------------

# 8th-order central differences (Fornberg): first and second derivative, offsets −4 … 4.
D1 = np.array([1 / 280, -4 / 105, 1 / 5, -4 / 5, 0.0, 4 / 5, -1 / 5, 4 / 105, -1 / 280])
D2 = np.array([-1 / 560, 8 / 315, -1 / 5, 8 / 5, -205 / 72, 8 / 5, -1 / 5, 8 / 315, -1 / 560])
OFFSETS = np.arange(-4, 5)
H1 = 1e-3   # step for d/dφ: truncation ~h⁸, round-off ~1e-16/h
H2 = 4e-3   # step for d²/dφ²: round-off grows as 1e-16/h², so a larger step


def numerical_analogues(mech: Mechanism, phi0: np.ndarray) -> dict:
    """d/dφ and d²/dφ² of every point's position and every link's angle at ``phi0``, by
    central differences of the solver's positions and angles alone (angles unwrapped about
    the centre of each stencil)."""
    out = {}
    for h, w, order in ((H1, D1, 1), (H2, D2, 2)):
        grid = (phi0[:, None] + h * OFFSETS[None, :]).ravel()
        k = solve(mech, grid)
        n = phi0.size
        for name, pm in k.points.items():
            r = pm.r.reshape(n, OFFSETS.size, 2)
            out[("point", name, order)] = np.einsum("k,nkj->nj", w, r) / h**order
        for name, lm in k.links.items():
            th = lm.theta.reshape(n, OFFSETS.size)
            th = th[:, 4:5] + np.angle(np.exp(1j * (th - th[:, 4:5])))   # unwrap about the centre
            out[("link", name, order)] = (th @ w) / h**order
    return out


def assert_analogues_match(mech: Mechanism, phi0, scale: float, rtol: float = 1e-8) -> int:
    """Compare every v_q, a_q, ω_q, ε_q with the numerical derivatives; return how many arrays
    were compared. ``scale`` [m] sets the absolute floor for near-zero values: rtol·scale for
    point analogues and rtol·scale/(shortest link) ~ rtol for link analogues."""
    phi0 = np.asarray(phi0, float)
    k = solve(mech, phi0)
    num = numerical_analogues(mech, phi0)
    checked = 0
    for name, pm in k.points.items():
        for order, exact in ((1, pm.v_q), (2, pm.a_q)):
            approx = num[("point", name, order)]
            np.testing.assert_allclose(exact, approx, rtol=rtol, atol=rtol * scale,
                                       err_msg=f"point {name}, d^{order}r/dφ^{order}")
            checked += 1
    for name, lm in k.links.items():
        for order, exact in ((1, lm.omega_q), (2, lm.eps_q)):
            approx = num[("link", name, order)]
            np.testing.assert_allclose(exact, approx, rtol=rtol, atol=rtol,
                                       err_msg=f"link {name}, d^{order}θ/dφ^{order}")
            checked += 1
    return checked


SAMPLE = np.radians([0.0, 17.0, 75.0, 90.0, 133.0, 180.0, 222.0, 270.0, 301.0, 359.0])


def slider_crank(r=0.1, l=0.4, e=0.0, guide_deg=0.0, branch=1, direction=1, start_deg=0.0,
                 through=(0.0, 0.0), pivot=(0.0, 0.0)) -> Mechanism:
    """Crank 1 (O → A), rod 2 (A → B), slider 3 at B; S2 by fraction, K by distance/angle."""
    g = Guide(through, guide_deg * DEG, e)
    return Mechanism(
        Crank("1", "O", pivot, "A", r, start_deg * DEG, direction),
        (RRP("B", "A", "B", "2", l, "3", g, branch),),
        (LinkPoint("S2", "2", "A", "B", 0.3),
         LinkPoint("T2", "2", "A", "B", 0.6, 0.05),              # off the rod's axis
         LinkPoint("K2", "2", "A", None, distance=0.2, angle=0.4),
         LinkPoint("K1", "1", "O", None, distance=0.07, angle=-0.3)),   # on the crank
    )


def four_bar(r=0.1, a=0.4, b=0.3, ground=(0.4, 0.0), branch=1, direction=1) -> Mechanism:
    """Crank 1 (O → A), coupler 2 (A → B), rocker 3 (D → B); coupler point P off the axis."""
    return Mechanism(
        Crank("1", "O", (0.0, 0.0), "A", r, 0.0, direction),
        (RRR("B", "A", "2", a, "D", "3", b, "B", branch),),
        (LinkPoint("S2", "2", "A", "B", 0.5),
         LinkPoint("P", "2", "A", "B", 0.5, 0.1),
         LinkPoint("Q", "2", "A", None, distance=0.25, angle=-0.5),
         LinkPoint("S3", "3", "D", None, distance=0.15)),
        {"D": ground},
    )


def slotted_link(r=0.15, c=0.36, e=0.0, branch=1, direction=1, arm=0.65, ram_y=0.29, rod=0.3,
                 ram_branch=1) -> Mechanism:
    """Shaper: crank 1 (O → A), block 2 at A on rocker 3 about P = (0, −c); the rocker's end D at
    ``arm`` from P drives rod 4 to the ram 5 at E on a horizontal guide at height ``ram_y``."""
    return Mechanism(
        Crank("1", "O", (0.0, 0.0), "A", r, 0.0, direction),
        (RPR("3", "A", "P", "3", "2", e, branch),
         RRP("E", "D", "E", "4", rod, "5", Guide((0.0, ram_y), 0.0), ram_branch)),
        (LinkPoint("D", "3", "P", None, distance=arm),
         LinkPoint("S3", "3", "P", None, distance=arm / 2, angle=0.1),
         LinkPoint("S4", "4", "D", "E", 0.5, -0.02)),
        {"P": (0.0, -c)},
    )


# -- (a) seed 000 at φ = 75° --------------------------------------------------------------------

@pytest.fixture(scope="module")
def compressor_at_75():
    mech = to_mechanism(load_case(CASES / "compressor.toml"))
    return solve(mech, np.array([75 * DEG]))


@pytest.mark.parametrize("point, printed", [
    ("A", 0.1),      # seed: V_qA(f) = 0.1
    ("B", 0.103),    # seed: V_qB(f) = 0.103
    ("C", 0.032),    # seed: V_qC(f) = 0.032
    ("S2", 0.1),     # seed: V_qS2(f) = 0.1
    ("S4", 0.073),   # seed: V_qS4(f) = 0.073
])
def test_seed_velocity_analogues_at_75(compressor_at_75, point, printed):
    # Mathcad shows 3 decimals and drops trailing zeros: a printed 0.1 is 0.100 ± 0.0005
    v = np.linalg.norm(compressor_at_75.points[point].v_q[0])
    assert v == pytest.approx(printed, abs=5e-4)


@pytest.mark.parametrize("link, which, printed", [
    ("2", "omega_q", 0.067),    # seed: ω_q2(f) = 0.067
    ("4", "omega_q", 0.242),    # seed: ω_q4(f) = 0.242
    ("2", "eps_q", -0.248),     # seed: ε_q2(f) = −0.248
    ("4", "eps_q", 0.061),      # seed: ε_q4(f) = 0.061
])
def test_seed_link_analogues_at_75(compressor_at_75, link, which, printed):
    # The seed's φ2 = asin(X_A/l2) is rod 2's angle from the upward vertical, counter-clockwise
    # positive (B = A + l2·(−sin φ2, cos φ2)), and φ4 = −asin(Y_A/l4) rod 4's angle from +x
    # (C = A + l4·(cos φ4, sin φ4)): both differ from our θ (from +x, ccw) by a constant, so
    # their derivatives are ours, signs included.
    value = getattr(compressor_at_75.links[link], which)[0]
    assert value == pytest.approx(printed, abs=5e-4)


def test_seed_positions_at_75(compressor_at_75):
    k = compressor_at_75
    # seed: X_A = l1·cos(π/2 − φ), Y_A = l1·sin(π/2 − φ); B on the vertical, C on the horizontal
    xa, ya = 0.1 * math.sin(75 * DEG), 0.1 * math.cos(75 * DEG)
    np.testing.assert_allclose(k.points["A"].r[0], [xa, ya], atol=1e-15)
    np.testing.assert_allclose(k.points["B"].r[0], [0.0, ya + math.sqrt(0.16 - xa**2)], atol=1e-15)
    np.testing.assert_allclose(k.points["C"].r[0], [xa + math.sqrt(0.16 - ya**2), 0.0], atol=1e-15)


# -- (b) analogues against numerical derivatives ------------------------------------------------

@pytest.mark.parametrize("kw", [
    dict(),                                                   # centric, horizontal
    dict(branch=-1),                                          # the other assembly
    dict(e=0.05),                                             # offset guide
    dict(e=-0.03, branch=-1, direction=-1),
    dict(guide_deg=30.0, through=(0.02, -0.01)),              # inclined guide
    dict(guide_deg=-120.0, e=0.04, branch=-1, start_deg=40.0),
    dict(guide_deg=90.0, direction=-1, start_deg=90.0),       # the compressor's rod 2
    dict(pivot=(0.1, 0.2), through=(0.12, 0.2), guide_deg=15.0, e=0.02, r=0.05, l=0.12),
], ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items()) or "centric")
def test_rrp_analogues_match_numerical_derivatives(kw):
    mech = slider_crank(**kw)
    assert assert_analogues_match(mech, SAMPLE, scale=mech.crank.length) == 2 * (7 + 3)


@pytest.mark.parametrize("kw", [
    dict(),
    dict(branch=-1),
    dict(direction=-1),
    dict(branch=-1, direction=-1, ground=(0.3, 0.15)),
    dict(r=0.05, a=0.2, b=0.18, ground=(0.1, -0.17)),
], ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items()) or "crank-rocker")
def test_rrr_analogues_match_numerical_derivatives(kw):
    mech = four_bar(**kw)
    assert assert_analogues_match(mech, SAMPLE, scale=mech.crank.length) == 2 * (8 + 3)


@pytest.mark.parametrize("kw", [
    dict(),                                        # rocker oscillates (r < c)
    dict(e=0.06),                                  # slide line offset from the pivot
    dict(e=-0.05, direction=-1),
    dict(branch=-1, arm=-0.65),                    # block on the rocker's negative side
    dict(r=0.3, c=0.12, e=0.05, arm=0.2, ram_y=-0.12, rod=0.4),  # rocker turns round (r > c)
], ids=lambda kw: ",".join(f"{k}={v}" for k, v in kw.items()) or "shaper")
def test_rpr_analogues_match_numerical_derivatives(kw):
    mech = slotted_link(**kw)
    assert assert_analogues_match(mech, SAMPLE, scale=mech.crank.length) == 2 * (7 + 5)


def test_six_bar_with_two_moving_ends():
    """An RRR whose both ends move (a coupler point and a rocker point), then an RRP: the
    Watt–Stephenson chains of the course."""
    base = four_bar()
    mech = Mechanism(
        base.crank,
        base.dyads + (RRR("F", "P", "4", 0.35, "S3", "5", 0.3, "F", -1),
                      RRP("G", "F", "G", "6", 0.3, "7", Guide((0.0, -0.3), 0.0, 0.0), 1)),
        base.points, base.ground)
    assert assert_analogues_match(mech, SAMPLE, scale=0.1) == 2 * (10 + 7)


def test_rpr_about_a_moving_pivot():
    """A slotted link whose rocker turns about a moving joint (B of a four-bar), offset slide."""
    base = four_bar()
    mech = Mechanism(base.crank,
                     base.dyads + (RPR("R", "P", "B", "6", "7", 0.02, 1),),
                     base.points + (LinkPoint("Z", "6", "B", None, distance=0.3, angle=0.2),),
                     base.ground)
    assert assert_analogues_match(mech, SAMPLE, scale=0.1) == 2 * (9 + 5)


def test_compressor_analogues_match_numerical_derivatives():
    mech = to_mechanism(load_case(CASES / "compressor.toml"))
    assert assert_analogues_match(mech, SAMPLE, scale=0.1) > 0


lengths = st.floats(0.05, 1.0, allow_nan=False, allow_infinity=False)
angles = st.floats(-180.0, 180.0, allow_nan=False, allow_infinity=False)
unit = st.floats(-1.0, 1.0, allow_nan=False, allow_infinity=False)
signs = st.sampled_from([1, -1])
phis = st.lists(st.floats(0.0, 2 * math.pi, allow_nan=False), min_size=1, max_size=4)
# the examples' count is the profile's (tests/conftest.py: 60 in the suite, fewer in the quick loop)
SETTINGS = settings(deadline=None, derandomize=True,  # CI: the same examples every run
                    database=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(r=lengths, ratio=st.floats(1.5, 6.0), e_share=unit, guide=angles, branch=signs,
       direction=signs, start=angles, phi=phis)
def test_property_slider_crank(r, ratio, e_share, guide, branch, direction, start, phi):
    """Any slider-crank whose rod stays at least ~37° off the guide's normal."""
    l = ratio * r
    e = e_share * (0.8 * l - r)          # |e| + r ≤ 0.8·l: assembles, and never perpendicular
    mech = slider_crank(r=r, l=l, e=e, guide_deg=guide, branch=branch, direction=direction,
                        start_deg=start)
    assert_analogues_match(mech, np.array(phi), scale=r)
    k = solve(mech, np.array(phi))
    np.testing.assert_allclose(np.linalg.norm(k.points["B"].r - k.points["A"].r, axis=1), l,
                               rtol=1e-13)


@SETTINGS
@given(a=st.floats(0.3, 1.0), b=st.floats(0.3, 1.0), d=st.floats(0.3, 1.0),
       r_share=st.floats(0.05, 0.9), ground_deg=angles, branch=signs, direction=signs, phi=phis)
def test_property_four_bar(a, b, d, r_share, ground_deg, branch, direction, phi):
    """Crank-rockers whose transmission angle stays within 15° … 165°."""
    r = r_share * 0.25
    lo, hi = d - r, d + r                              # the range of |AD| over a turn
    # the joint lies off the line A–D by a margin: cos of the angle at B stays within ±cos 15°
    for dist in (lo, hi):
        cos_b = (a * a + b * b - dist * dist) / (2 * a * b)
        assume(abs(cos_b) < math.cos(15 * DEG))
    assume(lo > abs(a - b) and hi < a + b)
    mech = four_bar(r=r, a=a, b=b, ground=(d * math.cos(ground_deg * DEG),
                                          d * math.sin(ground_deg * DEG)),
                    branch=branch, direction=direction)
    assert_analogues_match(mech, np.array(phi), scale=r, rtol=1e-8)
    k = solve(mech, np.array(phi))
    np.testing.assert_allclose(np.linalg.norm(k.points["B"].r - k.points["A"].r, axis=1), a,
                               rtol=1e-12)
    np.testing.assert_allclose(np.linalg.norm(k.points["B"].r - k.points["D"].r, axis=1), b,
                               rtol=1e-12)


@SETTINGS
@given(r=st.floats(0.1, 0.5), c=st.floats(0.1, 0.5), e_share=unit, branch=signs,
       direction=signs, phi=phis)
def test_property_slotted_link(r, c, e_share, branch, direction, phi):
    """Oscillating (r < c) and rotating (r > c) slotted links, the block never over the pivot."""
    assume(abs(r - c) > 0.05)
    e = e_share * 0.7 * abs(r - c)
    mech = Mechanism(Crank("1", "O", (0.0, 0.0), "A", r, 0.0, direction),
                     (RPR("3", "A", "P", "3", "2", e, branch),),
                     (LinkPoint("D", "3", "P", None, distance=0.5, angle=0.2),),
                     {"P": (0.0, -c)})
    # |A − P| ≥ |r − c| > |e|/0.7 keeps s away from 0, where the rocker's derivatives blow up
    assert_analogues_match(mech, np.array(phi), scale=r, rtol=1e-8)


# -- (c) slider-crank closed forms --------------------------------------------------------------

def test_centric_slider_crank_position_and_velocity():
    # x(φ) = r·cos φ + √(l² − r²·sin² φ); x′(φ) = −r·sin φ − r²·sin φ·cos φ/√(l² − r²·sin² φ)
    r, l = 0.1, 0.35
    phi = np.linspace(0, 2 * np.pi, 361)
    k = solve(slider_crank(r=r, l=l), phi)
    root = np.sqrt(l**2 - r**2 * np.sin(phi) ** 2)
    x = r * np.cos(phi) + root
    x1 = -r * np.sin(phi) - r**2 * np.sin(phi) * np.cos(phi) / root
    # x″ = −r·cos φ − r²·cos 2φ/√(…) − r⁴·sin² φ·cos² φ/√(…)³
    x2 = -r * np.cos(phi) - r**2 * np.cos(2 * phi) / root - r**4 * (np.sin(phi) * np.cos(phi))**2 / root**3
    B = k.points["B"]
    np.testing.assert_allclose(B.r[:, 0], x, rtol=0, atol=1e-15)
    np.testing.assert_allclose(B.r[:, 1], 0.0, atol=1e-15)
    np.testing.assert_allclose(B.v_q[:, 0], x1, rtol=0, atol=1e-15)
    np.testing.assert_allclose(B.a_q[:, 0], x2, rtol=0, atol=1e-15)
    np.testing.assert_allclose(B.v_q[:, 1], 0.0, atol=1e-15)


def test_centric_slider_crank_dead_centres_and_stroke():
    r, l = 0.1, 0.35
    dcs = dead_centres(slider_crank(r=r, l=l), "3")
    assert [dc.kind for dc in dcs] == ["outer", "inner"]
    assert dcs[0].phi == pytest.approx(0.0, abs=1e-12)
    assert dcs[1].phi == pytest.approx(math.pi, abs=1e-12)
    assert dcs[0].x == pytest.approx(l + r, abs=1e-15)
    assert dcs[1].x == pytest.approx(l - r, abs=1e-15)
    assert dcs[0].x - dcs[1].x == pytest.approx(2 * r, abs=1e-15)   # stroke = 2r


@pytest.mark.parametrize("e", [0.03, -0.05, 0.12])
@pytest.mark.parametrize("direction", [1, -1])
def test_offset_slider_crank_dead_centres_and_stroke(e, direction):
    # Guide y = e (horizontal, offset along +y), crank from +x. At the outer dead centre crank
    # and rod are in line and extended: B = (l + r)·(cos θ, sin θ) with y = e, θ = asin(e/(l+r));
    # at the inner one they overlap: B = −(l − r)·(cos θ, sin θ), θ = π + asin(e/(l − r)).
    # The stroke is the difference of the two x = √((l ± r)² − e²).
    r, l = 0.1, 0.3
    dcs = dead_centres(slider_crank(r=r, l=l, e=e, direction=direction), "3")
    assert sorted(dc.kind for dc in dcs) == ["inner", "outer"]
    outer = next(dc for dc in dcs if dc.kind == "outer")
    inner = next(dc for dc in dcs if dc.kind == "inner")
    theta_outer = math.asin(e / (l + r))
    theta_inner = math.pi + math.asin(e / (l - r))
    # φ = (θ − θ0)/direction, taken in [0, 2π)
    assert outer.phi == pytest.approx((direction * theta_outer) % (2 * math.pi), abs=1e-12)
    assert inner.phi == pytest.approx((direction * theta_inner) % (2 * math.pi), abs=1e-12)
    assert outer.x == pytest.approx(math.sqrt((l + r) ** 2 - e**2), abs=1e-14)
    assert inner.x == pytest.approx(math.sqrt((l - r) ** 2 - e**2), abs=1e-14)
    stroke = math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)
    assert outer.x - inner.x == pytest.approx(stroke, abs=1e-14)
    assert stroke > 2 * r                                   # an offset lengthens the stroke


def test_compressor_dead_centres():
    # cases/compressor.toml: piston 3 (B, vertical) at its head (outer) at φ = 0, piston 5
    # (C, horizontal) at φ = 90°; both strokes 2·l1 = 0.2 m.
    mech = to_mechanism(load_case(CASES / "compressor.toml"))
    b = dead_centres(mech, "3")
    c = dead_centres(mech, "5")
    assert [(round(math.degrees(d.phi), 9), d.kind) for d in b] == [(0.0, "outer"), (180.0, "inner")]
    assert [(round(math.degrees(d.phi), 9), d.kind) for d in c] == [(90.0, "outer"), (270.0, "inner")]
    assert b[0].x - b[1].x == pytest.approx(0.2, abs=1e-15)
    assert c[0].x - c[1].x == pytest.approx(0.2, abs=1e-15)


# -- (d) positions by hand ----------------------------------------------------------------------

def test_four_bar_positions_by_hand():
    # O = (0, 0), D = (0.4, 0); crank r = 0.1 from +x, ccw; coupler AB = 0.4; rocker DB = 0.3;
    # branch + puts B to the left of A → D, i.e. above the x axis when A → D points along +x.
    mech = four_bar(r=0.1, a=0.4, b=0.3, ground=(0.4, 0.0))
    k = solve(mech, np.radians([0.0, 180.0]))
    B = k.points["B"].r
    # φ = 180°: A = (−0.1, 0), |AD| = 0.5, AB = 0.4, DB = 0.3: the 3-4-5 triangle, right angle
    # at B. The foot of B on AD lies 0.4²/0.5 = 0.32 from A, the height is 0.4·0.3/0.5 = 0.24:
    # B = (−0.1 + 0.32, 0.24) = (0.22, 0.24).
    np.testing.assert_allclose(B[1], [0.22, 0.24], atol=1e-15)
    # the coupler's angle is atan(0.24/0.32) = atan(3/4), the rocker's (from D) 180° − atan(4/3)
    assert k.links["2"].theta[1] == pytest.approx(math.atan2(3, 4), abs=1e-15)
    assert k.links["3"].theta[1] == pytest.approx(math.pi - math.atan2(4, 3), abs=1e-15)
    # φ = 0: A = (0.1, 0), |AD| = 0.3 = DB: triangle A-D-B is isosceles with apex D. The foot of
    # the height from D bisects AB, so the foot of B on AD lies at p = AB²/(2·AD) = 0.16/0.6
    # = 4/15 from A, and B is h = √(0.4² − p²) = √(0.16 − 16/225) = 0.4·√5/3 above the axis:
    # B = (0.1 + 4/15, 0.4·√5/3) = (11/30, 0.4·√5/3).
    np.testing.assert_allclose(B[0], [11 / 30, 0.4 * math.sqrt(5) / 3], atol=1e-15)
    # the coupler point P sits at the middle of AB, 0.1 to the left of A → B
    A = k.points["A"].r
    mid = (A[0] + B[0]) / 2
    left = np.array([-(B[0] - A[0])[1], (B[0] - A[0])[0]]) / 0.4
    np.testing.assert_allclose(k.points["P"].r[0], mid + 0.1 * left, atol=1e-15)
    # branch −: the mirror image in the axis A → D (the x axis at these two angles)
    k2 = solve(four_bar(r=0.1, a=0.4, b=0.3, ground=(0.4, 0.0), branch=-1), np.radians([0.0, 180.0]))
    np.testing.assert_allclose(k2.points["B"].r, B * [1, -1], atol=1e-15)


def test_four_bar_case_file_positions_by_hand():
    # cases/fourbar.toml is the same linkage as above: B = (0.22, 0.24) at φ = 180°
    mech = to_mechanism(load_case(CASES / "fourbar.toml"))
    k = solve(mech, np.radians([0.0, 180.0]))
    np.testing.assert_allclose(k.points["B"].r[1], [0.22, 0.24], atol=1e-15)
    np.testing.assert_allclose(k.points["B"].r[0], [11 / 30, 0.4 * math.sqrt(5) / 3], atol=1e-15)


def test_slotted_link_positions_by_hand():
    # O = (0, 0), rocker pivot P = (0, −0.36); crank r = 0.15 from +x, ccw; rocker end D at
    # 0.65 from P; rod DE = 0.3 to the ram E on the horizontal y = 0.29.
    mech = slotted_link()
    k = solve(mech, np.radians([90.0, 0.0]))
    # φ = 90°: A = (0, 0.15) is straight above P, the rocker is vertical (θ = 90°) and its end
    # D = (0, −0.36 + 0.65) = (0, 0.29) lies on the ram's guide: E = D + (0.3, 0) = (0.3, 0.29).
    assert k.links["3"].theta[0] == pytest.approx(math.pi / 2, abs=1e-15)
    np.testing.assert_allclose(k.points["D"].r[0], [0.0, 0.29], atol=1e-15)
    np.testing.assert_allclose(k.points["E"].r[0], [0.3, 0.29], atol=1e-15)
    # φ = 0: A = (0.15, 0), A − P = (0.15, 0.36): the 5-12-13 triangle (|A − P| = 0.39), so the
    # rocker points along u = (5/13, 12/13) and D = P + 0.65·u = (0.25, −0.36 + 0.6) = (0.25, 0.24);
    # E lies 0.29 − 0.24 = 0.05 above D at a rod of 0.3: E = (0.25 + √(0.09 − 0.0025), 0.29).
    assert k.links["3"].theta[1] == pytest.approx(math.atan2(12, 5), abs=1e-15)
    np.testing.assert_allclose(k.points["D"].r[1], [0.25, 0.24], atol=1e-15)
    np.testing.assert_allclose(k.points["E"].r[1], [0.25 + math.sqrt(0.0875), 0.29], atol=1e-15)
    # the block turns with the rocker
    np.testing.assert_allclose(k.links["2"].theta, k.links["3"].theta)


def test_slotted_link_extremes_by_hand():
    # The rocker's extremes are where it is tangent to the crank circle (PA ⟂ OA): sin γ =
    # r/c = 0.15/0.36 either side of the vertical. Then A·(A − P) = 0, r² = r·c·cos ψ with ψ the
    # angle between OA and OP (straight down): ψ = 90° − γ, so φ = −90° ± ψ = −γ and 180° + γ
    # (−24.62° and 204.62°). D is then at the same height on both sides, so the ram's stroke is
    # 2·0.65·sin γ exactly; the working stroke (towards −x, over the crank's upper arc) lasts
    # 180° + 2γ, the return 180° − 2γ.
    gamma = math.asin(0.15 / 0.36)
    dcs = dead_centres(slotted_link(), "5")
    assert [dc.kind for dc in dcs] == ["inner", "outer"]
    assert dcs[0].phi == pytest.approx(math.pi + gamma, abs=1e-12)
    assert dcs[1].phi == pytest.approx(2 * math.pi - gamma, abs=1e-12)
    assert dcs[1].x - dcs[0].x == pytest.approx(2 * 0.65 * 0.15 / 0.36, abs=1e-14)
    working = dcs[0].phi - (dcs[1].phi - 2 * math.pi)
    assert working == pytest.approx(math.pi + 2 * gamma, abs=1e-12)


def test_slotted_link_with_offset_by_hand():
    # Offset e = 0.15 along the rocker's left normal n = (−sin θ, cos θ). At φ = 0 the block's
    # pivot A = (0.15, 0) is at 0.39 from P, so the slide coordinate is s = √(0.39² − 0.15²) = 0.36.
    # A − P = s·u + e·n with A − P at α = atan(12/5) from +x and (s, e) at β = atan(5/12) in the
    # rocker's frame: θ = α − β, cos θ = (5·12 + 12·5)/169 = 120/169, sin θ = (12·12 − 5·5)/169
    # = 119/169. At φ = 90°: A − P = (0, 0.51), s = √(0.51² − 0.15²), θ = 90° − atan(0.15/s).
    mech = slotted_link(e=0.15, arm=0.5)
    k = solve(mech, np.radians([0.0, 90.0]))
    th = k.links["3"].theta
    np.testing.assert_allclose([math.cos(th[0]), math.sin(th[0])], [120 / 169, 119 / 169], atol=1e-15)
    s90 = math.sqrt(0.51**2 - 0.15**2)
    assert th[1] == pytest.approx(math.pi / 2 - math.atan2(0.15, s90), abs=1e-15)
    # the rocker's end D = P + 0.5·u at φ = 0
    np.testing.assert_allclose(k.points["D"].r[0], [0.5 * 120 / 169, -0.36 + 0.5 * 119 / 169],
                               atol=1e-15)


def test_slotted_link_case_file_positions_by_hand():
    # cases/slotted_link.toml is the shaper above: rocker vertical at φ = 90°, D = (0.25, 0.24)
    # at φ = 0
    mech = to_mechanism(load_case(CASES / "slotted_link.toml"))
    k = solve(mech, np.radians([90.0, 0.0]))
    assert k.links["3"].theta[0] == pytest.approx(math.pi / 2, abs=1e-15)
    np.testing.assert_allclose(k.points["D"].r, [[0.0, 0.29], [0.25, 0.24]], atol=1e-15)


def test_case_files_analogues_match_numerical_derivatives():
    for name in ("fourbar.toml", "slotted_link.toml"):
        mech = to_mechanism(load_case(CASES / name))
        assert assert_analogues_match(mech, SAMPLE, scale=mech.crank.length) > 0


# -- (e) assembly errors ------------------------------------------------------------------------

def test_rrp_rod_too_short_names_dyad_and_angle():
    # r = 0.1, rod 0.05 on a centric horizontal guide: the rod reaches the guide only while
    # |r·sin φ| ≤ 0.05, i.e. up to φ = 30°; the first grid angle past it is 31°.
    mech = slider_crank(r=0.1, l=0.05)
    with pytest.raises(AssemblyError, match=r"dyad B \(RRP, rod 2\) cannot be assembled at "
                                            r"crank angle φ = 31\.00°: the rod \(0\.05 m\) must be "
                                            r"at least 0\.1 m"):
        solve(mech, np.radians(np.arange(0.0, 360.0, 1.0)))


def test_rrr_too_short_names_dyad_and_angle():
    # coupler 0.2 + rocker 0.15 = 0.35 must reach |AD|, |AD|² = (0.4 − 0.1·cos φ)² + (0.1·sin φ)²
    # = 0.17 − 0.08·cos φ; it exceeds 0.35² = 0.1225 once cos φ < 0.59375, φ > 53.57°: the first
    # grid angle past it is 54°.
    mech = four_bar(r=0.1, a=0.2, b=0.15, ground=(0.4, 0.0))
    with pytest.raises(AssemblyError, match=r"dyad B \(RRR, links 2–3\) cannot be assembled "
                                            r"at crank angle φ = 54\.00°: the distance A–D ranges over "
                                            r"0\.3 … 0\.5 m, the links \(0\.2 and 0\.15 m\) reach "
                                            r"only 0\.05 … 0\.35 m"):
        solve(mech, np.radians(np.arange(0.0, 360.0, 1.0)))


def test_rpr_offset_larger_than_reach_names_dyad_and_angle():
    # the block at A can stay on a slide line 0.35 off P only while |A − P| > 0.35:
    # |A − P|² = 0.09 + 0.16 + 0.24·sin φ > 0.1225 fails first past φ = 212.1°
    mech = slotted_link(r=0.3, c=0.4, e=0.35, arm=0.3, rod=1.0)
    with pytest.raises(AssemblyError, match=r"dyad 3 \(RPR, rocker 3\) cannot be assembled "
                                            r"at crank angle φ = 213\.00°: the slide line's offset "
                                            r"\(0\.35 m\) must be smaller than the distance P–A"):
        solve(mech, np.radians(np.arange(0.0, 360.0, 1.0)))


def test_case_file_with_short_rod_fails_on_assembly(tmp_path):
    text = (CASES / "compressor.toml").read_text(encoding="utf-8")
    text = text.replace('rod_to_crank      = 4.0', 'rod_to_crank      = 0.5')
    f = tmp_path / "short.toml"
    f.write_text(text, encoding="utf-8")
    mech = to_mechanism(load_case(f))
    with pytest.raises(AssemblyError, match=r"dyad B \(RRP, rod 2\).*φ = \d+\.\d\d°") as exc:
        solve(mech, np.linspace(0, 2 * np.pi, 361))
    assert "\n" not in str(exc.value)


def test_a_single_angle_is_a_grid_of_one():
    k = solve(slider_crank(), 0.0)
    assert k.points["B"].r.shape == (1, 2)
    assert k.points["B"].r[0, 0] == pytest.approx(0.5, abs=1e-15)
    with pytest.raises(ValueError, match="1-D grid"):
        solve(slider_crank(), np.zeros((2, 2)))


def test_a_slider_that_never_moves_has_no_dead_centres():
    # the rod hangs from a fixed point, so the slider stands still: no dead centres (this used
    # to end `flywheel check` in a traceback, argmax of an empty sequence)
    mech = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, 0.0, 1),
                     (RRP("B", "G", "B", "2", 0.4, "3", Guide((0.0, 0.0), 0.0)),), (),
                     {"G": (0.0, 0.1)})
    assert dead_centres(mech, "3") == []


# -- (f) loop closure ---------------------------------------------------------------------------

@pytest.mark.parametrize("mech, rods", [
    (slider_crank(e=0.05, guide_deg=30.0), [("A", "B", 0.4), ("O", "A", 0.1)]),
    (four_bar(), [("A", "B", 0.4), ("D", "B", 0.3), ("O", "A", 0.1)]),
    (slotted_link(), [("D", "E", 0.3), ("P", "D", 0.65)]),
], ids=["slider-crank", "four-bar", "slotted-link"])
def test_loop_closure_over_the_cycle(mech, rods):
    phi = np.linspace(0, 2 * np.pi, 3601)
    k = solve(mech, phi)
    for p, q, length in rods:
        dist = np.linalg.norm(k.points[q].r - k.points[p].r, axis=1)
        np.testing.assert_allclose(dist, length, rtol=1e-14, atol=0, err_msg=f"|{q} − {p}|")


def test_compressor_loop_closure_and_guides():
    mech = to_mechanism(load_case(CASES / "compressor.toml"))
    k = solve(mech, np.linspace(0, 2 * np.pi, 3601))
    A, B, C = (k.points[n].r for n in "ABC")
    np.testing.assert_allclose(np.linalg.norm(B - A, axis=1), 0.4, rtol=1e-14)
    np.testing.assert_allclose(np.linalg.norm(C - A, axis=1), 0.4, rtol=1e-14)
    np.testing.assert_allclose(B[:, 0], 0.0, atol=1e-16)     # B stays on the vertical
    np.testing.assert_allclose(C[:, 1], 0.0, atol=1e-16)     # C stays on the horizontal
    # the slotted link's block stays on the rocker's slide line
    k2 = solve(slotted_link(e=0.06), np.linspace(0, 2 * np.pi, 721))
    d = k2.points["A"].r - k2.points["P"].r
    th = k2.links["3"].theta
    normal = -d[:, 0] * np.sin(th) + d[:, 1] * np.cos(th)
    np.testing.assert_allclose(normal, 0.06, atol=1e-15)
