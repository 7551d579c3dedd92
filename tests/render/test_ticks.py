"""render/ticks.py: within the style an axis's ticks after its first are copies of the first —
the figure's pixels those of matplotlib's own ticks (a figure with ticks restyled after they
were made, minor ticks, shared and twin axes, a log axis, fixed labels), the ticks made anew
counted, each copy's artists its own. Work is counted, not timed."""
from __future__ import annotations

import io

import pytest

pytest.importorskip("matplotlib")

from flywheel.render import figure as fg  # noqa: E402
from flywheel.render import figure_cache  # noqa: E402
from flywheel.render import ticks  # noqa: E402


def _draw() -> bytes:
    """A figure whose ticks are made, restyled, made again (more locations) and drawn."""
    import numpy as np

    fig, (ax, bx) = fg.figure((7.0, 6.0), 2, sharex=True, right=0.8)
    x = np.linspace(0.0, 360.0, 73)
    ax.plot(x, 1e4 * np.sin(np.radians(x)), label=r"$\omega_q$")
    ax.xaxis.get_major_ticks()                      # the first ticks made, then restyled
    ax.tick_params(axis="y", labelsize=7, colors="tab:red", direction="in", length=6)
    ax.tick_params(axis="x", labelrotation=30, pad=6)
    fg.phi_axis(bx, "en")
    bx.plot(x, np.exp(x / 60.0), "o", markevery=9)
    bx.set_yscale("log")                            # minor ticks located and drawn
    bx.minorticks_on()
    twin = bx.twinx()
    twin.plot(x, np.cos(np.radians(x)), color="tab:green")
    twin.set_yticks([-1.0, -0.5, 0.0, 0.5, 1.0])
    twin.set_yticklabels(["−1", "−½", "0", "½", "1"])
    ax.grid(True, which="both", alpha=0.5)
    ax.legend(loc="upper right")
    out = io.BytesIO()
    fg.save(fig, out)
    return out.getvalue()


def _matplotlibs_own() -> bytes:
    import matplotlib

    with matplotlib.rc_context(), figure_cache.whole_texts():     # texts drawn as within the style
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        return _draw()


def test_copied_ticks_keep_every_pixel():
    reference = _matplotlibs_own()
    with fg.style():
        ours = _draw()
    assert ours == reference


def test_only_each_axis_first_ticks_made_anew(monkeypatch):
    """Tick.__init__ runs for an axis's first major and first minor tick only; every other
    tick drawn is a copy."""
    from matplotlib import axis

    made: list[str] = []
    own = axis.Tick.__init__

    def counting(self, *args, **kw):
        made.append(type(self).__name__)
        own(self, *args, **kw)

    monkeypatch.setattr(axis.Tick, "__init__", counting)
    copied = ticks.made["copied"]
    with fg.style():
        fig, axes = fg.figure((8.0, 6.0), 2, right=0.3)
        for ax in axes:
            fg.phi_axis(ax, "en")                   # 13 ticks on x
            ax.set_yticks(range(9))                 # 9 on y
        fg.save(fig, io.BytesIO())
    assert len(made) <= 2 * 2 * 2                   # two axes, x and y, major and minor
    assert ticks.made["copied"] - copied >= 2 * (12 + 8)


@pytest.mark.parametrize("by", ["axis", "copy_tick"])
def test_a_copy_has_its_own_artists(by):
    """A copied tick's artists are new objects; restyling one tick's label or adding a
    callback to it leaves the first tick alone — made by the axis (which then copies the
    first tick's properties onto it, as matplotlib does) or by ``copy_tick`` alone."""
    from matplotlib.cbook import CallbackRegistry

    with fg.style():
        fig, ax = fg.figure((8.0, 3.0), right=0.3)
        fg.phi_axis(ax, "en")
        first, copy = ax.xaxis.get_major_ticks()[:2]
        if by == "copy_tick":
            copy = ticks.copy_tick(first, CallbackRegistry)
    for part in ticks.PARTS:
        a, b = getattr(first, part), getattr(copy, part)
        assert a is not b and type(a) is type(b)
        assert a._callbacks is not b._callbacks
        assert a.sticky_edges.x is not b.sticky_edges.x
    assert first.label1.get_fontproperties() is not copy.label1.get_fontproperties()
    size = first.label1.get_fontsize()
    copy.label1.get_fontproperties().set_size(size + 3)
    copy.label1.add_callback(lambda artist: None)
    assert first.label1.get_fontsize() == size
    assert not first.label1._callbacks.callbacks
    before = list(first.gridline.get_xdata())
    copy.gridline.set_xdata([90.0])
    assert list(first.gridline.get_xdata()) == before != [90.0]
