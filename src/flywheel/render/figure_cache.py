"""The caches render/figure.py's ``style()`` puts around matplotlib for every figure drawn in
it (issue 26), each a function that installs one and returns the function that takes it back:
text sizes, parsed mathtext, font files and their tables, markers copied without deep copies,
and every text drawn whole (laid out and rendered once into one bitmap, placed at whole
pixels: :func:`whole_texts`). The style fixes matplotlib's settings, so a cache's key
holds all else a value depends on; tests/render/test_figure_cost.py checks they keep every pixel
of the drawing with whole texts alone, and that drawing against matplotlib's own. numpy only at
import; matplotlib inside the functions."""
from __future__ import annotations

from contextlib import contextmanager

import numpy as np


class _Bounded(dict):
    """A cache of :func:`style` that empties itself rather than grow past ``most`` entries
    (matplotlib's own caches are bounded too): ``put`` stores a value and returns it."""

    def __init__(self, most: int):
        super().__init__()
        self.most = most

    def put(self, key, value):
        if len(self) > self.most:
            self.clear()
        self[key] = value
        return value


def _installed(owner, name: str, new):
    """``new`` put in the place of ``owner``'s ``name`` (a class's own attribute or a module's);
    returns the function that puts the one before back."""
    before = owner.__dict__[name]
    setattr(owner, name, new)

    def restore() -> None:
        setattr(owner, name, before)
    return restore


def share_text_metrics():
    """Within :func:`style`, one cache of text sizes for every figure drawn (matplotlib keeps
    one per renderer, and each figure, each resize and each measuring of a legend makes a new
    renderer: the same tick labels "0", "30" … were laid out again for every figure). A text's
    size depends on the text, its font, whether it is mathtext and the dpi — the cache's key —
    and on the kind of renderer (Agg, PDF, SVG), added to the key; nothing else of the
    renderer. Returns the function that puts matplotlib's own cache back."""
    import matplotlib.text as mtext

    sizes = _Bounded(20000)                      # as matplotlib's own (4096 each)

    def shared(renderer):
        kind = type(renderer)

        def metrics(text, fontprop, ismath, dpi):
            key = (kind, text, fontprop, ismath, dpi)
            found = sizes.get(key)
            if found is None:
                found = sizes.put(key, renderer.get_text_width_height_descent(
                    text, fontprop, ismath))
            return found
        return metrics

    return _installed(mtext, "_get_text_metrics_function", shared)


def share_mathtext():
    """Within :func:`style`, one cache of parsed mathtext for every renderer. matplotlib keeps
    one per parser (50 strings), and each renderer has its own parser: every figure, and every
    measuring of a legend or a title (a renderer of its own), parsed each of its mathtext
    strings again (pyparsing: 4 ms a label, a sixth of a figure's time). A parse depends on
    the string, the dpi, the font (its whole state), antialiasing, the glyph loading flags and
    the kind of output (raster or vector) — the key; the font settings are fixed by the style.
    The parse is read only by the renderers. Returns the function that puts matplotlib's own
    cache back."""
    from matplotlib.mathtext import MathTextParser

    own = MathTextParser.__dict__["_parse_cached"]
    parse = own.__wrapped__                  # the function under matplotlib's lru_cache
    parsed = _Bounded(2000)

    def shared(self, s, dpi, prop, antialiased, load_glyph_flags):
        key = (self._output_type, s, dpi, prop, antialiased, load_glyph_flags)
        found = parsed.get(key)
        if found is None:
            found = parsed.put(key, parse(self, s, dpi, prop, antialiased, load_glyph_flags))
        return found

    return _installed(MathTextParser, "_parse_cached", shared)


def copy_markers_shallow():
    """Within :func:`style`, a marker copied from another (each tick's two tick marks and its
    grid line copy the axis's first tick: 40 ticks a figure) shares the other's paths and
    transforms instead of deep-copying them (matplotlib deep-copies the marker's whole state,
    its marker function's bound marker included: 50 copies for each). A MarkerStyle is
    immutable; the only state a copy changes in place is its user transform (``rotated``),
    which is copied — a marker with a user transform that is not affine is deep-copied as
    before. Returns the function that puts matplotlib's copying back."""
    from matplotlib.markers import MarkerStyle
    from matplotlib.transforms import Affine2DBase

    own = MarkerStyle.__dict__["_set_marker"]

    def set_marker(self, marker):
        if not isinstance(marker, MarkerStyle):
            return own(self, marker)
        state = dict(marker.__dict__)
        user = state.get("_user_transform")
        if user is not None:
            if not isinstance(user, Affine2DBase):
                return own(self, marker)
            state["_user_transform"] = user.frozen()        # a copy of its own
        function = state.get("_marker_function")
        if function is not None:                            # bound to this marker
            state["_marker_function"] = getattr(self, function.__name__)
        self.__dict__ = state

    return _installed(MarkerStyle, "_set_marker", set_marker)


def share_text_images():
    """Within :func:`style`, each plain text on the Agg canvas laid out and rendered once for
    every figure drawn, as matplotlib drew text until 3.10: FreeType and HarfBuzz lay the
    string out (``FT2Font.set_text``) and render it into one bitmap
    (``draw_glyphs_to_bitmap``), drawn with one call at whole pixels, rotated as an image.
    matplotlib 3.11 lays each string out twice (once to measure it, once to draw it, 0.2 ms
    each) and draws it glyph by glyph at the fractions of a pixel its place has, so the same
    tick label "90" is new at every place; here its size and its bitmap come from the one
    layout (matplotlib ≤ 3.10's ``get_text_width_height_descent`` and ``draw_text``). A text
    lands within half a pixel of 3.11's place, its glyphs the same shapes (compared side by
    side, benchmarks/README.md). A mathtext label (parsed once: :func:`share_mathtext`) is
    drawn the same way: its glyphs rendered once, at the fractions of a pixel they have from a
    baseline origin at whole pixels, into one bitmap (their coverages composed as Agg blends
    them one over another), drawn with one call; its rules (fraction bars) as matplotlib draws
    them from the same origin. The key: the text, its font (its whole state), the dpi, the
    hinting and the antialiasing; a text with font features or a language (none of
    flywheel's) is left to matplotlib. Returns the function that puts the canvas's own
    drawing back."""
    import math

    from matplotlib.backends import backend_agg

    agg = backend_agg.RendererAgg
    own_draw, own_size = agg.__dict__["draw_text"], agg.__dict__["get_text_width_height_descent"]
    if not hasattr(agg, "_prepare_font"):
        return lambda: None
    laid = _Bounded(20000)

    def text(self, s, prop, antialiased):
        """(bitmap, width, height, descent, x and y offsets of the bitmap) [px] of ``s``."""
        flags = backend_agg.get_hinting_flag()
        key = (s, prop, self.dpi, flags, antialiased)
        found = laid.get(key)
        if found is None:
            font = self._prepare_font(prop)
            font.set_text(s, 0.0, flags=flags)
            font.draw_glyphs_to_bitmap(antialiased=antialiased)
            w, h = font.get_width_height()
            xo, yo = font.get_bitmap_offset()
            found = laid.put((s, prop.copy(), *key[2:]),      # a copy: the text's may change
                             (np.array(font.get_image()), w / 64.0, h / 64.0,
                              font.get_descent() / 64.0, xo / 64.0, yo / 64.0))
        return found

    def blit(self, image, x: int, y: int, angle: float, gc) -> None:
        """Draw ``image`` turned by ``angle`` about its lower left corner, put at pixel (x, y)
        (y down, the row below the bitmap). A quarter turn (an axis label) is a turn of the
        pixels, exact; any other angle is Agg's, which resamples the bitmap (at 90° it would
        spread a vertical stroke over two grey pixels)."""
        turns = round(angle / 90.0)
        if turns != angle / 90.0 or turns % 2 == 0:
            self._renderer.draw_text_image(image, x, y, angle, gc)
        elif turns % 4 == 1:                  # reads upwards: the bitmap's bottom to the right
            self._renderer.draw_text_image(np.rot90(image), x - image.shape[0], y, 0, gc)
        else:                                 # reads downwards: its bottom to the left
            self._renderer.draw_text_image(np.rot90(image, -1), x, y + image.shape[1], 0, gc)

    def get_text_width_height_descent(self, s, prop, ismath):
        if ismath:
            return own_size(self, s, prop, ismath)
        import matplotlib

        _, w, h, d, _, _ = text(self, s, prop, bool(matplotlib.rcParams["text.antialiased"]))
        return w, h, d

    def draw_text(self, gc, x, y, s, prop, angle, ismath=False, mtext=None):
        if ismath or (mtext is not None and (mtext.get_fontfeatures() is not None
                                             or mtext.get_language() is not None)):
            return own_draw(self, gc, x, y, s, prop, angle, ismath, mtext)
        image, _, _, d, xo, yo = text(self, s, prop, gc.get_antialiased())
        # the bitmap's lower left corner: the descent below the baseline, turned with the text
        radians = math.radians(angle)
        x = round(x + xo + d * math.sin(radians))
        y = round(y + yo + d * math.cos(radians))
        blit(self, image, x, y + 1, angle, gc)

    def math_image(self, s, parse, prop, antialiased):
        """(bitmap, x and y of its lower left corner from the baseline's origin, y down) [px]
        of the mathtext ``s`` parsed as ``parse``, its origin at whole pixels."""
        flags = backend_agg.get_hinting_flag()
        key = (s, prop, self.dpi, flags, antialiased)
        found = laid_math.get(key)
        if found is not None:
            return found
        mode = render_mode.NORMAL if antialiased else render_mode.MONO
        pieces = []
        for font, size, _char, glyph_index, dx, dy in parse.glyphs:     # dy is upwards
            font.set_size(size, self.dpi)
            font._set_transform(np.array([[0x10000, 0], [0, 0x10000]]),
                                [round(0x40 * dx), round(0x40 * dy)])
            bitmap = font._render_glyph(glyph_index, flags, mode)
            buffer = bitmap.buffer
            if not antialiased:
                buffer = buffer * 0xff
            pieces.append((buffer, bitmap.left, -bitmap.top))            # y down
        if not pieces:
            return laid_math.put(key, (np.zeros((0, 0), np.uint8), 0, 0))
        left = min(p[1] for p in pieces)
        top = min(p[2] for p in pieces)
        right = max(p[1] + p[0].shape[1] for p in pieces)
        bottom = max(p[2] + p[0].shape[0] for p in pieces)
        clear = np.full((bottom - top, right - left), 1.0)   # the part left uncovered
        for buffer, x0, y0 in pieces:
            rows, cols = buffer.shape
            clear[y0 - top:y0 - top + rows, x0 - left:x0 - left + cols] *= 1.0 - buffer / 255.0
        image = np.rint(255.0 * (1.0 - clear)).astype(np.uint8)
        return laid_math.put((s, prop.copy(), *key[2:]), (image, left, bottom))

    def draw_mathtext(self, gc, x, y, s, prop, angle):
        antialiased = gc.get_antialiased()
        parse = self.mathtext_parser.parse(s, self.dpi, prop, antialiased=antialiased)
        image, left, bottom = math_image(self, s, parse, prop, antialiased)
        x, y = round(x), round(y)
        if image.size:
            radians = math.radians(angle)
            cos, sin = math.cos(radians), math.sin(radians)
            blit(self, image, round(x + left * cos + bottom * sin),
                 round(y - left * sin + bottom * cos), angle, gc)
        if parse.rects:
            self._draw_text_glyphs_and_boxes(gc, x, y, angle, (), parse.rects)

    render_mode = getattr(backend_agg, "RenderMode", None)
    own_math = agg.__dict__["draw_mathtext"]
    laid_math = _Bounded(5000)
    agg.draw_text, agg.get_text_width_height_descent = draw_text, get_text_width_height_descent
    if render_mode is not None and hasattr(agg, "_draw_text_glyphs_and_boxes"):
        agg.draw_mathtext = draw_mathtext

    def restore() -> None:
        agg.draw_text, agg.get_text_width_height_descent = own_draw, own_size
        agg.draw_mathtext = own_math
    return restore


@contextmanager
def whole_texts():
    """Texts drawn whole as within :func:`style` (:func:`share_text_images`), nothing else of
    the style: the drawing the style's other caches must keep to the pixel (their tests)."""
    restore = share_text_images()
    try:
        yield
    finally:
        restore()


def share_font_tables():
    """Within :func:`style`, each font's tables (OS/2, hhea, head) read once: matplotlib reads
    them from FreeType into a new dict for every text it lays out (20 µs each, 6 000 times for
    one run's figures). A font's tables do not change; each caller gets its own dict. Returns
    the function that puts FreeType's reading back."""
    from matplotlib.ft2font import FT2Font

    own = FT2Font.__dict__["get_sfnt_table"]
    tables: dict = {}
    missing = object()

    def get_sfnt_table(self, name):
        key = (self, name)
        found = tables.get(key, missing)
        if found is missing:
            found = tables[key] = own(self, name)
        return None if found is None else dict(found)

    return _installed(FT2Font, "get_sfnt_table", get_sfnt_table)


def remember_fonts():
    """Within :func:`style` (the font settings fixed), remember which file each font asked for
    is: matplotlib looks it up for every text drawn or measured (13 000 times for one run's
    figures, mathtext's included), each time reading five font settings (30 µs). The key is the font's whole state
    (what its hash is made of). Returns the function that forgets."""
    from matplotlib import _mathtext, font_manager

    manager = font_manager.fontManager
    own = manager.findfont
    found: dict = {}

    def findfont(prop, fontext="ttf", directory=None, fallback_to_default=True,
                 rebuild_if_missing=True):
        what = prop if isinstance(prop, str) else (
            tuple(prop.get_family()), prop.get_slant(), prop.get_variant(), prop.get_weight(),
            prop.get_stretch(), prop.get_size_in_points(), prop.get_file(),
            prop.get_math_fontfamily())              # a name (mathtext's), or the state
        key = (what, fontext, directory, fallback_to_default, rebuild_if_missing)
        path = found.get(key)
        if path is None:
            path = found[key] = own(prop, fontext, directory, fallback_to_default,
                                    rebuild_if_missing)
        return path

    # the manager's method, and the module's name for it that mathtext imported
    before = (font_manager.findfont, _mathtext.findfont)
    manager.findfont = font_manager.findfont = _mathtext.findfont = findfont

    def forget() -> None:
        if manager.__dict__.get("findfont") is findfont:
            del manager.findfont
        font_manager.findfont, _mathtext.findfont = before
    return forget
