"""The caches render/figure.py's style() puts around matplotlib (issue 26): the same pixels as
matplotlib's own drawing, each mathtext label parsed once and each glyph rendered once for a
place for every figure, and matplotlib given back unchanged when the style ends; the PNG
writer's pixels against matplotlib's; the scheme's hatching against a line per stroke. Work is
counted, not timed."""
from __future__ import annotations

import io

import pytest

pytest.importorskip("matplotlib")

from flywheel.render import figure as fg  # noqa: E402
from flywheel.render import figure_cache  # noqa: E402


def _draw(pil: bool = False) -> bytes:
    """A small figure with what the caches touch: mathtext, plain tick labels, markers (ticks
    copied from the first), a legend; its PNG (``pil``: written by matplotlib's savefig)."""
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
    if pil:
        fig.savefig(out, format="png", dpi=fg.DPI, metadata={"Software": None})
    else:
        fg.save(fig, out)
    return out.getvalue()


def _matplotlibs_own(pil: bool = False) -> bytes:
    """The same figure in the same settings, drawn by matplotlib with its texts drawn whole
    (figure_cache.whole_texts) and none of the caches."""
    import matplotlib

    with matplotlib.rc_context(), figure_cache.whole_texts():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        return _draw(pil)


def test_the_caches_keep_every_pixel():
    reference = _matplotlibs_own()
    with fg.style():
        first, again = _draw(), _draw()          # again: every text from the caches
    assert first == reference
    assert again == reference


def test_each_mathtext_label_parsed_once_in_a_style(monkeypatch):
    """Counted where matplotlib's cache of parses calls the parse (whichever parser reads
    the label: render/mathparse.py's or pyparsing's)."""
    from matplotlib.mathtext import MathTextParser

    parsed: list[str] = []
    own = MathTextParser.__dict__["_parse_cached"].__wrapped__

    def counting(self, s, *args, **kw):
        parsed.append(s)
        return own(self, s, *args, **kw)

    monkeypatch.setattr(MathTextParser.__dict__["_parse_cached"], "__wrapped__", counting)
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

    from matplotlib import _mathtext, axis
    from matplotlib.ft2font import FT2Font

    def now():
        return (RendererAgg.__dict__["draw_text"], MarkerStyle.__dict__["_set_marker"],
                MathTextParser.__dict__["_parse_cached"],
                RendererAgg.__dict__["draw_mathtext"],
                FT2Font.__dict__["get_sfnt_table"], _mathtext.Parser.__dict__["parse"],
                _mathtext.TruetypeFonts.__dict__["_get_info"], axis.Axis.__dict__["_get_tick"],
                RendererAgg.__dict__["get_text_width_height_descent"])

    before = now()
    with fg.style():
        assert RendererAgg.__dict__["draw_text"] is not before[0]
        assert RendererAgg.__dict__["draw_mathtext"] is not before[3]
        assert FT2Font.__dict__["get_sfnt_table"] is not before[4]
        assert now()[5:] != before[5:] and all(a is not b for a, b in zip(now()[5:], before[5:]))
        _draw()
    assert now() == before


def test_png_writer_keeps_the_pixels_of_matplotlibs_png():
    """fg.save writes its own PNG (RGB, unfiltered rows): decoded, the same pixels and dpi as
    matplotlib's PIL writer gives for the same figure; the same bytes when written again."""
    import numpy as np
    from PIL import Image

    reference = _matplotlibs_own(pil=True)   # written by matplotlib's savefig (PIL)
    with fg.style():
        ours, again = _draw(), _draw()
    assert ours == again
    assert ours != reference                 # another writer …
    a, b = Image.open(io.BytesIO(ours)), Image.open(io.BytesIO(reference))
    assert a.mode == "RGB" and b.mode == "RGBA"
    assert a.info["dpi"] == b.info["dpi"]
    assert (np.asarray(b)[..., 3] == 255).all()
    assert np.array_equal(np.asarray(a), np.asarray(b)[..., :3])   # … the same pixels


def test_png_bytes_translucent_pixels_keep_their_alpha():
    import numpy as np
    from PIL import Image

    rng = np.random.default_rng(7)
    rgba = rng.integers(0, 256, (5, 7, 4), dtype=np.uint8)
    decoded = Image.open(io.BytesIO(fg.png_bytes(rgba, 120)))
    assert decoded.mode == "RGBA" and decoded.size == (7, 5)
    assert np.array_equal(np.asarray(decoded), rgba)
    rgba[..., 3] = 255
    decoded = Image.open(io.BytesIO(fg.png_bytes(rgba, 300)))
    assert decoded.mode == "RGB" and round(decoded.info["dpi"][0]) == 300
    assert np.array_equal(np.asarray(decoded), rgba[..., :3])


def test_strokes_drawn_as_broken_lines_keep_the_pixels_of_a_line_each():
    """The scheme's hatching (plots_scheme._strokes: strokes joined by NaN breaks, 40 to a line)
    gives the pixels of one Line2D per stroke, 95 strokes (three lines) included."""
    import numpy as np

    from flywheel.render.plots_scheme import _strokes

    rng = np.random.default_rng(5)
    starts = rng.uniform(0.0, 10.0, (95, 2))
    segments = [(p, p + (0.3, 0.3)) for p in starts]

    def png(joined: bool) -> bytes:
        fig, ax = fg.figure((4.0, 4.0), right=0.3)
        if joined:
            _strokes(ax, segments, color="k", linewidth=0.5, zorder=2)
        else:
            for p0, p1 in segments:
                ax.plot([p0[0], p1[0]], [p0[1], p1[1]], color="k", linewidth=0.5, zorder=2)
        assert len(ax.lines) == (3 if joined else 95)
        out = io.BytesIO()
        fg.save(fig, out)
        return out.getvalue()

    with fg.style():
        assert png(True) == png(False)


def _constrained():
    """A figure laid out by matplotlib's constrained layout, as plots_extra makes them."""
    import numpy as np
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6.0, 5.0), dpi=fg.DPI, layout="constrained")
    axd = fig.subplot_mosaic([["a", "a"], ["b", "c"]], height_ratios=[1.1, 1])
    x = np.linspace(0.0, 10.0, 40)
    for k, ax in enumerate(axd.values()):
        ax.plot(x, 10.0 ** k * np.sin(x + k), label=rf"$\omega_{k}$ of a long legend {k}")
        ax.set_ylabel(r"$\Delta T_{I}$ [J]")
        ax.legend(loc="upper right")
    fig.suptitle("a title\nof two lines", fontsize=11)
    return fig


@pytest.mark.parametrize("dpi", [77, fg.DPI, 200])
def test_constrained_layout_run_without_savefigs_extra_draw(dpi, monkeypatch):
    """fg.save lays a constrained figure out as savefig does, without savefig's drawing of it
    with nothing rendered: the figure drawn once, not twice; the same pixels; its layout engine
    back after."""
    import numpy as np
    from matplotlib.figure import Figure

    with fg.style():
        reference = _constrained()
        raw = io.BytesIO()
        reference.savefig(raw, format="rgba", dpi=dpi)
        w, h = (int(x * dpi) for x in reference.get_size_inches())
        expected = fg.png_bytes(np.frombuffer(raw.getbuffer(), np.uint8).reshape(h, w, 4), dpi)

        draws: list[int] = []
        own = Figure.draw

        def counting(self, renderer):
            draws.append(1)
            return own(self, renderer)

        monkeypatch.setattr(Figure, "draw", counting)
        fig = _constrained()
        engine = fig.get_layout_engine()
        out = io.BytesIO()
        fg.save(fig, out, dpi=dpi)
    assert out.getvalue() == expected
    assert len(draws) == 1
    assert fig.get_layout_engine() is engine


def test_prepare_moves_what_exists_out_of_the_collectors_generations():
    """After prepare(), the objects made before it are frozen (gc.freeze): the collector's
    passes while drawing skip them."""
    import gc

    before = gc.get_freeze_count()
    made = [[k] for k in range(2000)]               # 2000 containers the collector tracks
    try:
        fg.prepare()
        assert gc.get_freeze_count() >= before + len(made)
    finally:
        gc.unfreeze()                               # the test process keeps nothing frozen


def test_png_bytes_copies_opaque_pixels_as_three_byte_items():
    """An opaque canvas's rows copied as 3-byte items give the bytes of the copy byte by byte
    (the general path, taken by an array that is not C-contiguous); decoded, the pixels."""
    import numpy as np
    from PIL import Image

    rgba = np.random.default_rng(7).integers(0, 256, (37, 53, 4), dtype=np.uint8)
    rgba[..., 3] = 255
    quick = fg.png_bytes(rgba, 120)
    assert quick == fg.png_bytes(np.asfortranarray(rgba), 120)
    assert np.array_equal(np.asarray(Image.open(io.BytesIO(quick))), rgba[..., :3])


#: plain and mathtext labels, turned or not: a Cyrillic unit, a true minus, sub- and superscripts,
#: a rule (\frac) and pyparsing's label (\mathregular)
WHOLE = [("AVWa 0,5 −1,5 ρ кг·м²", 0), ("AVWa 0,5 −1,5 ρ кг·м²", 30), ("AVWa 0,5 −1,5 ρ кг·м²", 90),
         ("AVWa |v_q| (0,5)", 270), (r"$|v_{q}|$ [m/s]", 90),
         (r"$\omega_{q}(\varphi)$ of link 2", 0), (r"$\Delta T_{I\,max}$ = 843,88 J", 90),
         (r"$\Delta T_{I\,max}$ = 843,88 J", 45), (r"$\frac{1}{2}\sqrt{x}$ p$_\mathregular{max}$", 0)]


def _ink(s: str, rotation: float, whole: bool):
    """The ink (255 − red) of ``s`` alone on a white 3 in × 3 in figure at 120 dpi, placed at a
    fraction of a pixel, drawn by matplotlib glyph by glyph or (``whole``) as a bitmap."""
    import contextlib

    import matplotlib
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    with matplotlib.rc_context(), (figure_cache.whole_texts() if whole else contextlib.nullcontext()):
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        fig = Figure((3.0, 3.0), dpi=120)
        fig.text(0.31 + 0.37 / 360, 0.42 + 0.21 / 360, s, rotation=rotation)
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        return 255 - np.asarray(canvas.buffer_rgba())[..., 0].astype(int)


@pytest.mark.parametrize("s, rotation", WHOLE)
def test_a_text_drawn_whole_lands_where_matplotlib_draws_it(s, rotation):
    """Drawn as one bitmap at whole pixels (figure_cache.whole_texts), a text covers the box matplotlib's
    own drawing, glyph by glyph at fractions of a pixel, covers — to 2 px on every side (a
    pixel's rounding each way; turned by 30° or 45°, Agg resamples the bitmap) — with the same
    ink to 4 % (turned by 30°: 3.3 %; unturned or a quarter turn: 0.1 %): no glyph lost,
    doubled or misplaced (a wrong descent would move it 3 px at 9 pt)."""
    import numpy as np

    own, whole = _ink(s, rotation, False), _ink(s, rotation, True)

    def box(ink):
        ys, xs = np.nonzero(ink > 0)
        return np.array([xs.min(), xs.max(), ys.min(), ys.max()])

    assert np.abs(box(whole) - box(own)).max() <= 2
    assert abs(whole.sum() / own.sum() - 1.0) < (0.04 if rotation % 90 else 0.01)


@pytest.mark.parametrize("s", ["AVWa |v_q| кг·м² (0,5)", r"$|v_{q}|$, $\Delta T_{I\,max}$ [m/s]"])
def test_a_quarter_turn_turns_the_pixels_exactly(s):
    """An axis label turned by 90° or 270° is the unturned text's pixels turned, exactly (no
    resampling: Agg's turn would spread a vertical stroke over two grey pixels)."""
    import numpy as np

    def patch(ink):
        ys, xs = np.nonzero(ink)
        return ink[ys.min():ys.max() + 1, xs.min():xs.max() + 1]

    flat = patch(_ink(s, 0, True))
    assert np.array_equal(patch(_ink(s, 90, True)), np.rot90(flat))
    assert np.array_equal(patch(_ink(s, 270, True)), np.rot90(flat, -1))


def test_a_plain_text_measures_as_matplotlib_measures_it():
    """The size of a plain text comes from the same FreeType layout as matplotlib's own
    measuring: equal to the last bit."""
    import matplotlib
    from matplotlib.backends.backend_agg import RendererAgg
    from matplotlib.font_manager import FontProperties

    renderer = RendererAgg(300, 200, 120)
    with matplotlib.rc_context():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(fg.RC)
        for size in (7.5, 9.0, 10.0):
            prop = FontProperties(size=size)
            for s in ("0", "−0,025", "AVWa кг·м² (N)", "Ti"):
                own = renderer.get_text_width_height_descent(s, prop, False)
                with figure_cache.whole_texts():
                    assert renderer.get_text_width_height_descent(s, prop, False) == own
