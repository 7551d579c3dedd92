"""The output link of the last group (linkage/output_link.py) against closed forms the test
derives itself: a crank-rocker's extreme positions where crank and coupler are collinear
(law of cosines) and its K = (180° + θ)/(180° − θ); a slotted link's extremes where the slot
is tangent to the crank circle; the four-bar's transmission angle by the law of cosines; a
slider-crank's stroke (2r in line, the offset formula) and its least transmission angle."""
from __future__ import annotations

import math

import numpy as np
import pytest

from flywheel.linkage import RPR, RRP, RRR, Crank, Guide, Mechanism, solve
from flywheel.linkage.output_link import output_link, rrr_transmission


def fourbar(a=0.1, b=0.4, c=0.3, d=0.4, start=0.0, direction=1, branch=1):
    return Mechanism(Crank("1", "O", (0.0, 0.0), "A", a, start, direction),
                     (RRR("B", "A", "2", b, "D", "3", c, "B", branch),), ground={"D": (d, 0.0)})


def law_of_cosines(x, y, z):
    """The angle opposite z in a triangle of sides x, y, z [rad]."""
    return math.acos((x * x + y * y - z * z) / (2 * x * y))


@pytest.mark.parametrize("a,b,c,d", [(0.1, 0.4, 0.3, 0.4), (0.05, 0.3, 0.2, 0.25),
                                     (0.12, 0.35, 0.28, 0.3)])
def test_crank_rocker_extremes_and_time_ratio(a, b, c, d):
    out = output_link(fourbar(a, b, c, d))
    assert out.kind == "rocker" and out.link == "3"
    # extended: O, A, B in line with OB = b + a; folded: OB = b − a, the crank pointing away
    psi_ext = law_of_cosines(a + b, d, c)
    psi_fold = law_of_cosines(b - a, d, c)
    expected = sorted([math.degrees(psi_ext) % 360, (math.degrees(psi_fold) + 180) % 360])
    assert out.extremes_phi_deg == pytest.approx(expected, abs=1e-9)
    theta = math.degrees(abs(psi_fold - psi_ext))
    assert out.time_ratio_K == pytest.approx((180 + theta) / (180 - theta), rel=1e-12)
    assert out.strokes_deg == pytest.approx((180 + theta, 180 - theta), abs=1e-9)
    # the rocker's angles there: at D, between DB and DO, by the law of cosines again
    at_d = [law_of_cosines(c, d, a + b), law_of_cosines(c, d, b - a)]
    rocker = sorted(180 - math.degrees(x) for x in at_d)
    assert sorted(out.extremes_output) == pytest.approx(rocker, abs=1e-9)
    assert out.swing_deg == pytest.approx(rocker[1] - rocker[0], abs=1e-9)
    assert out.stroke is None


def test_crank_rocker_transmission_angle_by_the_law_of_cosines():
    a, b, c, d = 0.1, 0.4, 0.3, 0.4
    m = fourbar(a, b, c, d)
    phi = np.linspace(0, 2 * np.pi, 73)
    k = solve(m, phi)
    z = np.sqrt(a * a + d * d - 2 * a * d * np.cos(phi))     # crank pin to rocker pivot
    mu = np.arccos((b * b + c * c - z * z) / (2 * b * c))
    gamma = np.minimum(mu, np.pi - mu)
    got = rrr_transmission(k.points["B"].r - k.points["A"].r, k.points["B"].r - k.points["D"].r)
    assert got == pytest.approx(gamma, abs=1e-12)
    # least at the least z = d − a (φ = 0) or the largest z = d + a, whichever is farther from 90°
    mus = [math.degrees(law_of_cosines(b, c, d - a)), math.degrees(law_of_cosines(b, c, d + a))]
    least = min(min(x, 180 - x) for x in mus)
    out = output_link(m)
    assert out.transmission_angle_min_deg == pytest.approx(least, abs=1e-9)
    assert out.phi_transmission_angle_min_deg == pytest.approx(0.0, abs=1e-6)


def test_a_clockwise_crank_and_a_start_angle_give_the_same_strokes():
    """K and the swing are the linkage's, whatever way the crank turns or where φ starts."""
    base = output_link(fourbar())
    for m in (fourbar(direction=-1), fourbar(start=math.radians(70))):
        out = output_link(m)
        assert out.time_ratio_K == pytest.approx(base.time_ratio_K, rel=1e-12)
        assert out.swing_deg == pytest.approx(base.swing_deg, abs=1e-9)


def test_slotted_link_extremes_where_the_slot_touches_the_crank_circle():
    r, dist = 0.075, 0.2                     # crank radius, fixed pivot below the crank's
    m = Mechanism(Crank("1", "C", (0.0, 0.0), "P", r, 0.0, 1),
                  (RPR("G", "P", "O", "3", "2"),), ground={"O": (0.0, -dist)})
    out = output_link(m)
    assert out.kind == "slotted link" and out.link == "3"
    alpha = math.degrees(math.acos(r / dist))   # crank ⊥ slot at ±α from the direction C → O
    assert sorted(out.extremes_phi_deg) == pytest.approx(sorted([(-90 - alpha) % 360,
                                                                 (-90 + alpha) % 360]), abs=1e-9)
    assert out.time_ratio_K == pytest.approx((360 - 2 * alpha) / (2 * alpha), rel=1e-12)
    assert out.swing_deg == pytest.approx(2 * math.degrees(math.asin(r / dist)), abs=1e-9)
    # the slide through the pivot: the block's force is normal to the rocker, like its velocity
    assert out.transmission_angle_min_deg == pytest.approx(90.0, abs=1e-9)
    assert out.phi_transmission_angle_min_deg is None
    # said as the course says it: a slotted link's swing, not a rocker's («коромысла»)
    from flywheel.render.output_link import lines
    assert lines(out, "ru")[0].startswith("угол размаха кулисы ψ = ")
    assert lines(output_link(fourbar()), "ru")[0].startswith("угол размаха коромысла ψ = ")


def test_slotted_link_with_an_offset_slide():
    r, dist, e = 0.075, 0.2, 0.02
    m = Mechanism(Crank("1", "C", (0.0, 0.0), "P", r, 0.0, 1),
                  (RPR("G", "P", "O", "3", "2", offset=e),), ground={"O": (0.0, -dist)})
    out = output_link(m)
    # γ = 90° − atan(|e|/|s|), least where |s| = √(ρ² − e²) is least: ρ = dist − r, φ = 270°
    s = math.sqrt((dist - r) ** 2 - e * e)
    assert out.transmission_angle_min_deg == pytest.approx(90 - math.degrees(math.atan(e / s)),
                                                           abs=1e-9)
    assert out.phi_transmission_angle_min_deg == pytest.approx(270.0, abs=1e-6)


@pytest.mark.parametrize("e", [0.0, 0.03, -0.05])
def test_slider_crank_stroke_time_ratio_and_transmission(e):
    r, l = 0.1, 0.4
    m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", r, 0.0, 1),
                  (RRP("G", "A", "B", "2", l, "3", Guide((0.0, 0.0), 0.0, e)),))
    out = output_link(m)
    assert out.kind == "slider" and out.link == "3" and out.swing_deg is None
    stroke = math.sqrt((l + r) ** 2 - e * e) - math.sqrt((l - r) ** 2 - e * e)
    assert out.stroke == pytest.approx(stroke, abs=1e-12)
    if e == 0:
        assert out.stroke == pytest.approx(2 * r, abs=1e-12)
    # extremes where crank and rod are collinear: at asin(e/(l + r)) and 180° + asin(e/(l − r))
    b1, b2 = math.asin(e / (l + r)), math.asin(e / (l - r))
    assert out.extremes_phi_deg == pytest.approx(
        sorted([math.degrees(b1) % 360, (180 + math.degrees(b2)) % 360]), abs=1e-9)
    theta = math.degrees(abs(b2 - b1))
    assert out.time_ratio_K == pytest.approx((180 + theta) / (180 - theta), rel=1e-12)
    # the rod's largest angle to the guide: sin β = (r + |e|)/l, crank ⊥ guide
    least = 90 - math.degrees(math.asin((r + abs(e)) / l))
    assert out.transmission_angle_min_deg == pytest.approx(least, abs=1e-9)
    assert out.phi_transmission_angle_min_deg == pytest.approx(90.0 if e <= 0 else 270.0, abs=1e-6)


def test_a_double_crank_has_no_output_link():
    """The shortest link is the frame: the 'rocker' turns fully, it has no extremes."""
    m = fourbar(a=0.3, b=0.35, c=0.3, d=0.1)
    assert output_link(m) is None


def test_the_shaper_of_the_source_has_its_time_ratio():
    """cases/shaper.toml: the source (LEC 06, exercise 2) gives the time ratio 1.647."""
    from pathlib import Path

    from flywheel.cases.run import load_case

    case = load_case(Path(__file__).resolve().parents[2] / "cases" / "shaper.toml")
    out = output_link(case.mechanism())
    assert out.link == "5" and out.kind == "slider"
    alpha = math.acos(0.075 / 0.2)
    assert out.time_ratio_K == pytest.approx((2 * math.pi - 2 * alpha) / (2 * alpha), rel=1e-12)
    assert round(out.time_ratio_K, 3) == 1.648
