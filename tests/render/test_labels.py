"""The one label placer (render/labels.py) and the figures routed through it (issue 28 item 6):
no label's box meets another's or covers a marker, measured with matplotlib's own extents on
the drawn page; the placer's box model is the box matplotlib draws; the ЕСКД sheets' labels
keep apart too; a slider's analogues are signed, dS/dφ and d²S/dφ²."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.render.labels import HARD, Placer, around, overlap

CASES = Path(__file__).resolve().parents[2] / "cases"
LINKAGES = ["compressor", "compressor_given_flywheel", "compressor_worksheet", "engine_4stroke",
            "engine_inline4", "engine_measured", "fourbar", "fourbar_rocker_load", "pump",
            "shaper", "slotted_link"]
LABELLED = ("scheme", "plan_", "hodographs")
_RESULTS: dict = {}


def results_of(name: str):
    if name not in _RESULTS:
        _RESULTS[name] = analyze(load_case(CASES / f"{name}.toml"))
    return _RESULTS[name]


def _shrunk(b, e: float):
    return (b[0] + e, b[1] + e, b[2] - e, b[3] - e)


# -- the placer alone ------------------------------------------------------------------------------

def test_labels_at_one_point_never_overlap_and_keep_off_the_marker():
    """Twenty labels of one point: the first eight take its corners and sides, the rest go
    farther out ring by ring; no two boxes share an area and none covers the marker."""
    p = Placer()
    p.marker((0.0, 0.0), 2.0)
    for _ in range(20):
        p.choose((0.0, 0.0), (10.0, 6.0), around(3.0), rings=6.0)
    boxes = p.labels
    assert not any(overlap(a, b) for i, a in enumerate(boxes) for b in boxes[:i])
    assert not any(overlap(b, p.markers[0]) for b in boxes)
    assert boxes[0] == (3.0, 3.0, 13.0, 9.0)           # up right first: nothing in the way


def test_a_line_under_the_first_place_moves_the_label_and_the_choice_is_deterministic():
    """A line through the first candidate's box: the label goes to the next place free of it;
    the same input gives the same place."""
    def run():
        p = Placer(step=1.0)
        p.segments([((0.0, 8.0), (20.0, 8.0))])          # across the box up right of (0, 0)
        return p.choose((0.0, 0.0), (10.0, 6.0), around(3.0))
    first, again = run(), run()
    assert first == again
    *_, box = first
    assert not (box[1] < 8.0 < box[3] and box[0] < 20.0 and box[2] > 0.0)   # off the line
    assert box != (3.0, 3.0, 13.0, 9.0)


def test_every_place_taken_costs_hard_and_the_rings_find_a_free_one():
    p = Placer()
    for b in p.boxes_of((0.0, 0.0), (10.0, 6.0), around(3.0)):
        p.box(b)                                         # every near place blocked
    assert p.costs(p.boxes_of((0.0, 0.0), (10.0, 6.0), around(3.0))).min() >= HARD
    *_, box = p.choose((0.0, 0.0), (10.0, 6.0), around(3.0), rings=6.0)
    assert p.free(box) or not any(overlap(box, q) for q in p.markers)


# -- the figures -----------------------------------------------------------------------------------

def _labelled_figures(res):
    from flywheel.render import plots
    return [(n, f) for n, f in plots.all_figures(res, "ru") if n.startswith(LABELLED)]


@pytest.mark.parametrize("name", LINKAGES)
def test_no_label_meets_another_or_covers_a_marker(name):
    """Every figure of a bundled case whose labels the placer sets (the schemes, the plans of
    positions, velocities, accelerations, forces, Zhukovsky's lever, the hodographs): drawn,
    each label's box as matplotlib measures it (get_window_extent) meets no other label's
    and covers no marker's (a hinge, an image, a hodograph's mark)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg

    res = results_of(name)
    with fg.style():
        for fname, build in _labelled_figures(res):
            fig = build()
            canvas = FigureCanvasAgg(fig)
            canvas.draw()
            ren = canvas.get_renderer()
            pt = 72.0 / fig.dpi
            placed = getattr(fig, "flywheel_labels", [])
            assert placed, fname
            boxes = []
            for text, _ in placed:
                e = text.get_window_extent(ren)
                boxes.append((e.x0 * pt, e.y0 * pt, e.x1 * pt, e.y1 * pt, text))
            for i, a in enumerate(boxes):
                for b in boxes[:i]:
                    assert not overlap(_shrunk(a, 0.3), b), (fname, a[4].get_text(),
                                                             b[4].get_text())
                for m in fig.flywheel_markers:
                    assert not overlap(_shrunk(a, 0.3), m), (fname, a[4].get_text(), m)
            fig.clear()


def test_the_box_model_is_the_box_matplotlib_draws():
    """The placer's box of each label of the compressor's plan of positions (measured before
    drawing, from a probe Text) is the box the drawn annotation occupies, within 0.5 pt."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg

    res = results_of("compressor")
    with fg.style():
        (_, build), = [(n, f) for n, f in _labelled_figures(res) if n == "plan_positions.png"]
        fig = build()
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        ren = canvas.get_renderer()
        pt = 72.0 / fig.dpi
        assert len(fig.flywheel_labels) > 20
        for text, model in fig.flywheel_labels:
            e = text.get_window_extent(ren)
            drawn = (e.x0 * pt, e.y0 * pt, e.x1 * pt, e.y1 * pt)
            assert np.allclose(drawn, model, atol=0.5), (text.get_text(), drawn, model)
        fig.clear()


# -- the ЕСКД sheets ------------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["compressor", "shaper", "slotted_link"])
def test_the_sheets_labels_keep_apart(name):
    """Sheet 1 and sheet 2 (schemes, plans, group drawings, polygons, the lever, the
    hodograph): in every view, the labels the placer set meet no other and no hinge."""
    from flywheel.render.drawings import model, sheet1, sheet2
    from flywheel.render.drawings.sheet import ROOM

    res = results_of(name)
    views = sheet1.views(res, "ru", ROOM["A1"]) + sheet2.views(res, "ru", ROOM["A1"])
    labelled = [v for v in views if v.labels]
    assert labelled
    for v in labelled:
        boxes = v.labels
        for i, a in enumerate(boxes):
            for b in boxes[:i]:
                assert not overlap(_shrunk(a, 0.05), b), v.name
            for it in v.items:
                if isinstance(it, model.Circle) and it.radius >= 1.0:
                    assert not overlap(_shrunk(a, 0.05), it.box()), (v.name, it.centre)


# -- signed slider analogues ---------------------------------------------------------------------

@pytest.mark.parametrize("name", ["compressor", "shaper", "engine_4stroke"])
def test_a_sliders_analogues_are_the_derivatives_of_its_travel(name):
    """v_q of a slider = dS/dφ and a_q = d²S/dφ² of its travel S from the outer dead centre
    (the positions figure's S), by differences on the grid (np.gradient); v_q changes sign (no
    V-shaped magnitude) and the figure draws it so."""
    res = results_of(name)
    d = res.drawing
    assert d.guided_sliders
    phi = np.asarray(res.phi, float)
    for link, joint, _ in d.guided_sliders:
        S = d.slider_travel[link]
        v_q, a_q = d.slider_analogues[link]
        dS = np.gradient(S, phi)[1:-1]                  # the grid may be refined: not uniform
        d2S = np.gradient(v_q, phi)[1:-1]                # d(dS/dφ)/dφ, v_q checked first
        span_v, span_a = np.ptp(v_q), np.ptp(a_q)
        # away from the dead centres, where |x − x_far| has its kink, S is smooth
        smooth = (S[1:-1] > 1e-2 * np.ptp(S)) & (S[1:-1] < (1 - 1e-2) * np.ptp(S))
        assert np.allclose(dS[smooth], v_q[1:-1][smooth], atol=2e-3 * span_v)
        assert np.allclose(d2S[smooth], a_q[1:-1][smooth], atol=2e-2 * span_a)
        assert v_q.min() < -0.1 * span_v and v_q.max() > 0.1 * span_v
    from flywheel.render import figure as fg
    from flywheel.render import plots

    with fg.style():
        fig = plots.figure_velocity_analogues(res, "en")
        drawn = [ln.get_ydata() for ln in fig.axes[0].lines]
        v_q, _ = d.slider_analogues[d.guided_sliders[0][0]]
        assert any(len(y) == len(v_q) and np.allclose(y, v_q) for y in drawn)
        fig.clear()


def test_a_curve_is_sampled_as_linspace_samples_each_piece():
    """Placer.curve samples all pieces at once: the very points numpy.linspace gives piece by
    piece (⌊length / step⌋ + 1 of them, at least 2; a piece of no length included)."""
    import numpy as np

    from flywheel.render.labels import Placer

    rng = np.random.default_rng(3)
    for step in (0.5, 2.0):
        xy = rng.normal(0.0, 40.0, (30, 2))
        xy[5] = xy[4]                                    # a piece of no length
        placer = Placer(step=step)
        placer.curve(xy)
        expected = np.concatenate([
            a + np.linspace(0.0, 1.0, max(2, int(float(np.hypot(*(b - a))) / step) + 1))[:, None]
            * (b - a) for a, b in zip(xy[:-1], xy[1:])])
        assert np.array_equal(placer.cloud, expected)


# -- arrowheads -------------------------------------------------------------------------------------

def test_an_arrowhead_is_soft_like_a_line_and_a_null_vector_has_none():
    """Placer.heads: a box over the head costs its sampled points, one beside it nothing; a
    vector of no length draws no head and adds nothing."""
    p = Placer(step=2.0)
    p.heads([(-1.0, 0.0), (5.0, 5.0)], [(0.0, 0.0), (5.0, 5.0)], 4.35, 2.55)
    over, beside = p.costs(np.array([(-5.0, -3.0, 1.0, 3.0), (2.0, -3.0, 8.0, 3.0)]))
    assert over >= 7 and over < HARD            # the whole triangle: its outline and axis
    assert beside == 0
    assert p.costs(np.array([(4.0, 4.0, 6.0, 6.0)]))[0] == 0     # no head at the null vector


@pytest.mark.parametrize("name", ["compressor", "engine_inline4"])
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_no_label_of_a_force_polygon_covers_an_arrowhead(name, lang):
    """A weight is a vector far shorter than its arrowhead (G₄ = 7.8 N at μ_F = 50 N/mm:
    0.16 mm). The placer saw only the vectors' lines, so a neighbour's label was set over such
    a head (Φ₄ over G₄'s in the compressor's polygon at 120°; 7 to 14 labels over a head in
    each of these four sets); the heads are now obstacles, and a vector shorter than its head is
    labelled round it. No label's box holds a corner of any arrowhead drawn."""
    from matplotlib.patches import FancyArrowPatch

    from flywheel.render import figure as fg
    from flywheel.render import plots

    res = results_of(name)
    specs = dict(plots.all_figures(res, lang))
    for fname in [n for n in specs if n.startswith("plan_forces")]:
        fig = fg.drawn(specs[fname])
        pt = 72.0 / fig.dpi
        corners = []
        for ax in fig.axes:
            for a in ax.get_children():
                if isinstance(a, FancyArrowPatch):
                    t, h = ax.transData.transform(np.array(a._posA_posB)) * pt
                    u = (h - t) / np.hypot(*(h - t))
                    base, side = h - 4.35 * u, 2.55 * np.array([-u[1], u[0]])
                    corners += [h, base + side, base - side]
        assert len(corners) > 30
        for text, b in fig.flywheel_labels:
            for c in corners:
                assert not (b[0] < c[0] < b[2] and b[1] < c[1] < b[3]), (fname, text.get_text())
