"""linkage/drawing.py: what the scheme draws, worked out on the computation side and carried on
the run's results, checked against what the mechanisms are by construction."""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.linkage.drawing import Drawing, describe, links_drawn

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def compressor():
    case = load_case(ROOT / "cases" / "compressor.toml")
    return case, analyze(case, n_points=360, transients=False)


def test_the_results_carry_the_drawing(compressor):
    case, r = compressor
    d = r.drawing
    assert isinstance(d, Drawing)
    assert d.links == r.links_drawn == links_drawn(case.mechanism())
    again = describe(case.mechanism(), r.kinematics)
    assert (again.moving_points, again.guided_sliders) == (d.moving_points, d.guided_sliders)


def test_compressor_topology(compressor):
    """Crank OA, rods AB and AC, pistons B (vertical guide) and C (horizontal guide) through O:
    O is the only fixed pivot, the rods turn, the pistons slide on fixed guides."""
    case, r = compressor
    d = r.drawing
    mech = case.mechanism()
    assert d.fixed_points == (mech.crank.pivot,)
    assert set(d.moving_points) == set(r.kinematics.points) - {mech.crank.pivot}
    assert mech.crank.name not in d.turning_links
    guides = {joint: angle for _, joint, angle in d.guided_sliders}
    assert len(guides) == 2
    assert sorted(round(math.degrees(a)) % 180 for a in guides.values()) == [0, 90]
    assert d.moving_blocks == ()
    for link, pts in d.members:                        # every drawn link keeps its own points
        assert set(dict(d.links)[link]) <= set(pts)


def test_slider_travel_is_the_stroke(compressor):
    """A central slider-crank's stroke is twice the crank (Артоболевский, ch. 3): the travel
    from the outer dead centre runs from 0 to 2·l1 and is never negative."""
    case, r = compressor
    l1 = case.mechanism().crank.length
    for link, travel in r.drawing.slider_travel.items():
        assert travel.min() == pytest.approx(0.0, abs=1e-12)
        assert travel.max() == pytest.approx(2 * l1, rel=1e-6), link


def test_bounds_hold_every_point(compressor):
    _, r = compressor
    x0, y0, x1, y1 = r.drawing.bounds
    for pm in r.kinematics.points.values():
        assert np.all(pm.r[:, 0] >= x0) and np.all(pm.r[:, 0] <= x1)
        assert np.all(pm.r[:, 1] >= y0) and np.all(pm.r[:, 1] <= y1)
    assert r.drawing.span == pytest.approx(max(x1 - x0, y1 - y0))


def test_draw_scheme_is_public(compressor):
    """plots.draw_scheme draws the mechanism at a grid node on a given Axes (for other figures)."""
    from matplotlib.figure import Figure

    from flywheel.render.plots import draw_scheme

    _, r = compressor
    fig = Figure()
    ax = fig.subplots()
    draw_scheme(ax, r, 0, 0.035 * r.drawing.span, "en")
    assert ax.lines and ax.get_aspect() == 1.0
    fig.clear()
