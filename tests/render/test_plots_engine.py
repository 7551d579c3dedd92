"""The indicator diagram of a four-stroke cylinder (render/plots_engine.py), built without
saving (the whole engine runs that write it are slow tests): the four stroke curves of the
closed diagram together hold every grid node once, at p/p_max of the cylinder's own pressures;
the 720° panel marks the firing angle."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.render import figure as fg
from flywheel.render import plots_engine

CASES = Path(__file__).resolve().parents[2] / "cases"
STROKE_COLOURS = ("C0", "C2", "C3", "C1")


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_strokes_hold_every_node_once_and_the_firing_is_marked(lang):
    r = analyze(load_case(CASES / "engine_4stroke.toml"), n_points=360)
    cyl = r.cylinders[0]
    with fg.style():
        fig = plots_engine.figure_indicator_strokes(r, cyl, lang)
    ax, bx = fig.axes[0], fig.axes[1]
    curves = [ln for ln in ax.lines
              if ln.get_color() in STROKE_COLOURS and ln.get_linestyle() == "-"]
    assert len(curves) == 4
    assert sum(len(ln.get_xdata()) for ln in curves) == len(cyl.s) == r.phi.size
    drawn = np.sort(np.concatenate([ln.get_ydata() for ln in curves]))
    np.testing.assert_allclose(drawn, np.sort(np.asarray(cyl.p) / cyl.p_max), rtol=1e-12)
    for ln in curves:                                    # each stroke drawn along its travel
        assert np.all(np.diff(ln.get_xdata()) >= 0)
    fired = [ln for ln in bx.lines if ln.get_linestyle() == ":"]
    assert [ln.get_xdata()[0] for ln in fired] == pytest.approx(
        [np.degrees(cyl.fires_at) + 720 * k for k in range(r.cycle_deg // 720)])
    assert cyl.name in ax.get_title()
    fig.clear()
