"""The sheets' font: ГОСТ 2.304-81 type B lettering.

osifont (ISO 3098 lettering, GPL-3 with the font exception: a document that embeds it is not
covered by the GPL; Debian package ``fonts-osifont``, installed by .ci/run when it can be) is
used when it is installed; else DejaVu Sans, which matplotlib ships (so the fallback is there on
every machine). osifont 2022 draws Ё, ё, Э, э as empty boxes: they are made of its own letters
(:data:`COMPOSED`). A character the font lacks otherwise is taken from DejaVu Sans, scaled to
the same capital height (a lowercase one to osifont's x-height); osifont's «ь» and «з», drawn
taller than its x-height, are brought down to it (:func:`_fit`); a character
neither has is drawn as its nearest one (:data:`STAND_INS`: «…» as three dots). Both fonts
are upright: the PDF and SVG writers slope the letters 15° (type B, 75° to the line); the DXF
names its text style for the ГОСТ font with the same oblique angle, so a CAD program letters
it in its own ГОСТ font (docs/drawings.md).
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from flywheel.render.numbers import THIN

#: where osifont is found (Debian's fonts-osifont, a user's own fonts)
OSIFONT = (Path("/usr/share/fonts/truetype/osifont/osifont.ttf"),
           Path("/usr/local/share/fonts/osifont.ttf"),
           Path.home() / ".local/share/fonts/osifont.ttf",
           Path.home() / ".fonts/osifont.ttf")
#: a character neither font has → what is drawn instead (PDF, SVG)
STAND_INS = {"…": "...", "ᵗ": "t", "ⁿ": "n"}


@lru_cache(maxsize=1)
def fallback_path() -> str:
    """matplotlib's DejaVu Sans: there wherever matplotlib is."""
    import matplotlib

    return str(Path(matplotlib.get_data_path()) / "fonts" / "ttf" / "DejaVuSans.ttf")


@lru_cache(maxsize=1)
def font_path() -> str:
    """The font file the PDF and SVG are lettered with: osifont if installed, else DejaVu Sans."""
    for p in OSIFONT:
        if p.is_file():
            return str(p)
    return fallback_path()


def font_name() -> str:
    """The font's family name (for docs and messages)."""
    return "osifont" if "osifont" in font_path() else "DejaVu Sans"


class _Font:
    """One font file: its glyphs, advance widths and capital height."""

    def __init__(self, path: str):
        from fontTools.ttLib import TTFont

        f = TTFont(path, lazy=True)
        self.cmap = f.getBestCmap()
        self.glyphs = f.getGlyphSet()
        self.hmtx = f["hmtx"]
        cap = getattr(f["OS/2"], "sCapHeight", 0) or 0
        if cap <= 0:                                  # no cap height recorded: measure «H»
            cap = f["glyf"][self.cmap[ord("H")]].yMax
        self.cap = float(cap)
        self.upem = float(f["head"].unitsPerEm)
        self.outlines: dict[str, list] = {}

    def has(self, ch: str) -> bool:
        return ord(ch) in self.cmap and not _is_box(self.outline(ch))

    def _source(self, ch: str) -> str:
        """The character whose glyph draws ``ch``: itself, or the letter :data:`COMPOSED`
        makes it of where this font's own is an empty box."""
        base = COMPOSED.get(ch)
        if base is not None and _is_box(_draw(self, ch)) and ord(base[0]) in self.cmap \
                and not _is_box(_draw(self, base[0])):
            return base[0]
        return ch

    def advance(self, ch: str) -> float:
        src = self._source(ch)
        like = COMPOSED[ch][2] if src != ch else ch
        return self.hmtx[self.cmap[ord(like)]][0] / self.cap

    def outline(self, ch: str) -> list:
        got = self.outlines.get(ch)
        if got is None:
            src = self._source(ch)
            got = _draw(self, src)
            if src != ch:
                _, bar, like = COMPOSED[ch]
                dx = _left(_draw(self, like)) - _left(got)       # into the place of «like»
                got = [[(op, [(x + dx, y) for x, y in ps]) for op, ps in c] for c in got]
                if bar is not None:
                    got = _mirrored_with_bar(got, self.advance(ch), bar)
            self.outlines[ch] = got
        return got


def _draw(font: _Font, ch: str) -> list:
    """The contours of ``ch`` per unit of capital height: lists of ("M"|"L"|"C", points), the
    TrueType quadratics raised to cubics."""
    from fontTools.pens.basePen import BasePen

    k = 1.0 / font.cap
    contours: list = []

    class Pen(BasePen):
        def _moveTo(self, p):
            contours.append([("M", [(p[0] * k, p[1] * k)])])

        def _lineTo(self, p):
            contours[-1].append(("L", [(p[0] * k, p[1] * k)]))

        def _curveToOne(self, p1, p2, p3):
            contours[-1].append(("C", [(q[0] * k, q[1] * k) for q in (p1, p2, p3)]))

        def _qCurveToOne(self, p1, p2):
            p0 = self._getCurrentPoint()
            c1 = (p0[0] + 2 / 3 * (p1[0] - p0[0]), p0[1] + 2 / 3 * (p1[1] - p0[1]))
            c2 = (p2[0] + 2 / 3 * (p1[0] - p2[0]), p2[1] + 2 / 3 * (p1[1] - p2[1]))
            self._curveToOne(c1, c2, p2)

        def _closePath(self):
            pass

    name = font.cmap.get(ord(ch))
    if name is not None:
        font.glyphs[name].draw(Pen(font.glyphs))
    return contours


#: letters a font draws as empty boxes (osifont 2022: Ё, ё, Э, э) made of its own letters, so
#: that they match its strokes: (the letter drawn, a bar's height [capitals] or None, the
#: letter whose place and advance it takes). «ё», «Ё» are the Latin «ë», «Ë» (osifont's Latin
#: letters stand wider apart: set in the Cyrillic «е», «Е»'s place); «э», «Э» are «с», «С»
#: turned over with a bar at half their height (ГОСТ 2.304's «Э»)
COMPOSED = {"ё": ("ë", None, "е"), "Ё": ("Ë", None, "Е"),
            "э": ("с", 0.35, "с"), "Э": ("С", 0.5, "С")}
#: a stroke's width in osifont [capitals] (the width of its «I»)
STROKE = 0.1


def _left(contours: list) -> float:
    return min((p[0] for c in contours for _, ps in c for p in ps), default=0.0)


def _signed_area(pts: list) -> float:
    """The signed area of the polygon through ``pts`` (positive: counter-clockwise)."""
    return 0.5 * sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(pts, pts[1:] + pts[:1]))


def _points(contour) -> list:
    return [p for _, ps in contour for p in ps]


def _mirrored_with_bar(contours: list, width: float, y: float) -> list:
    """``contours`` turned over left to right within the advance ``width``, and a bar STROKE
    thick at height ``y`` from the turned letter's open side into its bowl — wound as the
    letter's outer contour, so that where they overlap the fill stays whole."""
    turned = [[(op, [(width - px, py) for px, py in ps]) for op, ps in c] for c in contours]
    xs = [px for c in turned for _, ps in c for px, _ in ps]
    x0, x1 = min(xs) + 1.2 * STROKE, max(xs) - 0.5 * STROKE
    h = STROKE / 2
    corners = [(x0, y - h), (x1, y - h), (x1, y + h), (x0, y + h)]      # counter-clockwise
    outer = max((_signed_area(_points(c)) for c in turned), key=abs)
    if outer < 0:
        corners.reverse()
    return turned + [[("M", [corners[0]])] + [("L", [p]) for p in corners[1:]]]


def _is_box(contours: list) -> bool:
    """A glyph drawn as one plain quadrilateral as tall as a capital and half as wide: a
    font's placeholder, not a letter (a minus, a prime, an «I» are quadrilaterals too, but
    thin)."""
    if len(contours) != 1 or len(contours[0]) != 4 or \
            not all(op in ("M", "L") for op, _ in contours[0]):
        return False
    xs = [p[0] for _, pts in contours[0] for p in pts]
    ys = [p[1] for _, pts in contours[0] for p in pts]
    return max(ys) - min(ys) > 0.6 and max(xs) - min(xs) > 0.35


@lru_cache(maxsize=2)
def _font(path: str) -> _Font:
    return _Font(path)


def _font_of(ch: str) -> _Font | None:
    """The font that draws ``ch``: the sheet's, else the fallback; None if neither."""
    for path in (font_path(), fallback_path()):
        f = _font(path)
        if f.has(ch):
            return f
    return None


def drawn_char(ch: str) -> str:
    """``ch``, or its stand-in if neither font has it."""
    if ch.isspace() or _font_of(ch) is not None:
        return ch
    return STAND_INS.get(ch, "?")


def drawn_text(text: str) -> str:
    """``text`` as the PDF and SVG letter it."""
    return "".join(drawn_char(c) for c in text)


_ADVANCE: dict[str, float] = {}


def advance(ch: str) -> float:
    """The advance width of ``ch`` (or of its stand-in) per unit of capital height [-]."""
    got = _ADVANCE.get(ch)
    if got is None and ch == THIN and ord(ch) not in _font(font_path()).cmap:
        got = _ADVANCE[ch] = 0.5 * advance(" ")      # a narrow space: digits grouped
    if got is None:
        total = 0.0
        for c in drawn_char(ch):
            f = _font_of(c) if not c.isspace() else _font(font_path())
            total += (f.advance(c) * _fit(c, f)[0] if f is not None and ord(c) in f.cmap
                      else 0.6)
        got = _ADVANCE[ch] = total
    return got


#: osifont's lowercase letters drawn taller than its x-height (2022: «ь» as tall as «Ь», «з»
#: 0.85 of a capital), which read as capitals in «звеньев»: brought down to the x-height
TOO_TALL = frozenset("ьз")


def _top(contours: list) -> float:
    return max((p[1] for c in contours for _, pts in c for p in pts), default=0.0)


@lru_cache(maxsize=4)
def _x_height(path: str) -> float:
    """A font's x-height per unit of capital height: the top of its «x»."""
    return _top(_font(path).outline("x"))


def _fit(ch: str, f: _Font) -> tuple[float, float]:
    """The horizontal and vertical scales that set ``ch`` of font ``f`` among the sheet font's
    letters: a lowercase letter the fallback draws (osifont has no «э», «ё») at the sheet
    font's x-height, whole (DejaVu Sans' x-height is 0.75 of its capitals', osifont's 0.70);
    one of osifont's :data:`TOO_TALL` lowercase letters down to its x-height."""
    sheet, fallback = font_path(), fallback_path()
    if sheet == fallback:
        return 1.0, 1.0
    if f is not _font(sheet) and ch.islower():
        k = _x_height(sheet) / _x_height(fallback)
        return k, k
    if f is _font(sheet) and ch in TOO_TALL:
        return 1.0, _x_height(sheet) / _top(f.outline(ch))
    return 1.0, 1.0


_FITTED: dict[tuple[str, str], list] = {}


def outline(ch: str) -> list:
    """The contours of one drawn character (not a stand-in's) per unit of capital height, from
    the origin of its baseline (set among the sheet font's letters: :func:`_fit`)."""
    key = (font_path(), ch)
    got = _FITTED.get(key)
    if got is None:
        f = _font_of(ch)
        if f is None:
            return []
        sx, sy = _fit(ch, f)
        got = _FITTED[key] = [[(op, [(x * sx, y * sy) for x, y in pts]) for op, pts in c]
                              for c in f.outline(ch)]
    return got
