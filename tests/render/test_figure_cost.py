"""The caches render/figure.py's style() puts around matplotlib (issue 26): the same pixels as
matplotlib's own drawing, each mathtext label parsed once for every figure, and matplotlib
given back unchanged when the style ends. Work is counted, not timed."""
from __future__ import annotations

import io

import pytest

pytest.importorskip("matplotlib")

from flywheel.render import figure as fg  # noqa: E402


def _draw() -> bytes:
    """A small figure with what the caches touch: mathtext, plain tick labels, markers (ticks
    copied from the first), a legend; its PNG."""
    import numpy as np

    fig, ax = fg.figure((4.0, 3.0), right=0.3)
    x = np.linspace(0.0, 360.0, 50)
    ax.plot(x, np.sin(np.radians(x)), "o-", markevery=7, label=r"$\omega_{q}(\varphi)$ of link 2")
    ax.plot(x, np.cos(np.radians(x)), label="plain words")
    fg.phi_axis(ax, "en")
    ax.set_ylabel(r"$\varepsilon$ [rad/s²]")
    ax.set_title("a title: −1,5")
    for k in range(6):           # the same glyphs whole pixels apart, and a fraction apart
        fig.text(0.1 + k * 10.0 / 480, 0.5 + 0.37 * k / 360, "AVWa 0,5", rotation=30 * (k % 2))
    ax.legend()
    out = io.BytesIO()
    fg.save(fig, out)
    return out.getvalue()


def _matplotlibs_own() -> bytes:
    """The same figure in the same settings, drawn by matplotlib alone (none of the caches)."""
    import matplotlib

    with matplotlib.rc_context():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        return _draw()


def test_the_caches_keep_every_pixel():
    reference = _matplotlibs_own()
    with fg.style():
        first, again = _draw(), _draw()          # again: every text from the caches
    assert first == reference
    assert again == reference


def test_each_mathtext_label_parsed_once_in_a_style(monkeypatch):
    from matplotlib import _mathtext

    parsed: list[str] = []
    own = _mathtext.Parser.parse

    def counting(self, s, *args, **kw):
        parsed.append(s)
        return own(self, s, *args, **kw)

    monkeypatch.setattr(_mathtext.Parser, "parse", counting)
    with fg.style():
        _draw()
        _draw()                                  # a second figure: new renderers
    assert sorted(parsed) == sorted({r"$\omega_{q}(\varphi)$ of link 2",
                                     r"$\varphi$ [deg]", r"$\varepsilon$ [rad/s²]"})


def test_each_glyph_rendered_once_for_a_place(monkeypatch):
    """The second figure's glyphs all come from the cache: none rendered by FreeType again."""
    from matplotlib.ft2font import FT2Font

    rendered: list[int] = []
    own = FT2Font._render_glyph

    def counting(self, index, *args, **kw):
        rendered.append(index)
        return own(self, index, *args, **kw)

    monkeypatch.setattr(FT2Font, "_render_glyph", counting)
    with fg.style():
        _draw()
        first = len(rendered)
        _draw()
    assert first > 0
    assert len(rendered) == first


def test_matplotlib_given_back_after_the_style():
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.markers import MarkerStyle
    from matplotlib.mathtext import MathTextParser

    def now():
        return (RendererAgg.__dict__["draw_text"], MarkerStyle.__dict__["_set_marker"],
                MathTextParser.__dict__["_parse_cached"],
                RendererAgg.__dict__["_draw_text_glyphs_and_boxes"])

    before = now()
    with fg.style():
        assert RendererAgg.__dict__["draw_text"] is not before[0]
        assert RendererAgg.__dict__["_draw_text_glyphs_and_boxes"] is not before[3]
        _draw()
    assert now() == before
