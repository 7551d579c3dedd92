"""The geometry of a drawing sheet: primitives in millimetres on the paper (x right, y up,
origin at the sheet's lower left corner), each drawn with a line type of ГОСТ 2.303, and the
view — a group of primitives with its caption that the layout moves as one.

Line types (ГОСТ 2.303-68, table 1): the solid main line of thickness s = 0.5 … 1.4 mm (here
0.7 mm), the solid thin line s/3 … s/2 (0.35 mm), the thin dash-dot axis line (dashes 5 … 30
mm, gaps 3 … 5 mm: here 15 and 3), the thin dashed line (dashes 2 … 8 mm, gaps 1 … 2 mm: here 5
and 1.5). Lettering (ГОСТ 2.304-81): type B, sloped 75° (15° from the vertical), heights from
the series 2.5, 3.5, 5, 7, 10, 14 mm; never below 2.5 mm on paper.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

#: line type → (thickness [mm], dash pattern [mm] or () for solid) — ГОСТ 2.303-68, table 1
LINE_TYPES: dict[str, tuple[float, tuple[float, ...]]] = {
    "main": (0.7, ()),
    "thin": (0.35, ()),
    "axis": (0.35, (15.0, 3.0, 0.5, 3.0)),
    "dashed": (0.35, (5.0, 1.5)),
}
#: the slope of type-B lettering from the vertical [deg] (ГОСТ 2.304-81: 75° to the line)
SLANT_DEG = 15.0
#: the lettering heights of ГОСТ 2.304-81 [mm]
HEIGHTS = (2.5, 3.5, 5.0, 7.0, 10.0, 14.0)
MIN_HEIGHT = 2.5
#: [mm] of lines under a label's every candidate place from which farther places are tried
ON_LINE = 3.0


@dataclass(frozen=True)
class Polyline:
    """Points joined by straight lines [mm]; ``closed`` back to the first; ``filled`` solid
    black (an arrow head)."""

    points: tuple[tuple[float, float], ...]
    line: str = "main"
    closed: bool = False
    filled: bool = False

    def moved(self, dx: float, dy: float) -> Polyline:
        return replace(self, points=tuple((x + dx, y + dy) for x, y in self.points))

    def box(self) -> tuple[float, float, float, float]:
        xs, ys = [p[0] for p in self.points], [p[1] for p in self.points]
        return min(xs), min(ys), max(xs), max(ys)


@dataclass(frozen=True)
class Circle:
    """A circle (or with ``filled`` a dot) [mm]."""

    centre: tuple[float, float]
    radius: float
    line: str = "main"
    filled: bool = False

    def moved(self, dx: float, dy: float) -> Circle:
        return replace(self, centre=(self.centre[0] + dx, self.centre[1] + dy))

    def box(self) -> tuple[float, float, float, float]:
        (x, y), r = self.centre, self.radius
        return x - r, y - r, x + r, y + r


@dataclass(frozen=True)
class Text:
    """One line of lettering: ``height`` the capital letters' height [mm] (ГОСТ 2.304),
    ``angle`` [deg] counter-clockwise, anchored at (x, y) by ``halign`` (left, center, right)
    and ``valign`` (bottom, middle, top) of its capitals' box; ``width`` its length [mm] in the
    sheet's font (text_width), ``squeeze`` already applied."""

    x: float
    y: float
    text: str
    height: float
    angle: float = 0.0
    halign: str = "left"
    valign: str = "bottom"
    width: float = 0.0
    squeeze: float = 1.0          # the letters' width factor (a narrow cell of a title block)

    def moved(self, dx: float, dy: float) -> Text:
        return replace(self, x=self.x + dx, y=self.y + dy)

    def corners(self) -> list[tuple[float, float]]:
        """The four corners of its box on the paper [mm]."""
        w, h = self.width, self.height
        x0 = {"left": 0.0, "center": -w / 2, "right": -w}[self.halign]
        y0 = {"bottom": 0.0, "middle": -h / 2, "top": -h}[self.valign]
        c, s = math.cos(math.radians(self.angle)), math.sin(math.radians(self.angle))
        return [(self.x + c * u - s * v, self.y + s * u + c * v)
                for u, v in ((x0, y0), (x0 + w, y0), (x0 + w, y0 + h), (x0, y0 + h))]

    def box(self) -> tuple[float, float, float, float]:
        pts = self.corners()
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return min(xs), min(ys), max(xs), max(ys)


Item = Polyline | Circle | Text


def bounds(items) -> tuple[float, float, float, float]:
    """The box (x0, y0, x1, y1) [mm] holding ``items``."""
    boxes = [it.box() for it in items]
    return (min(b[0] for b in boxes), min(b[1] for b in boxes),
            max(b[2] for b in boxes), max(b[3] for b in boxes))


@dataclass
class View:
    """A view of a sheet: its primitives [mm] in its own coordinates, its ``name`` (what it
    shows, for the tests and the overflow) — placed by the layout with :meth:`moved`."""

    name: str
    items: list = field(default_factory=list)
    scales: dict = field(default_factory=dict)     # what its scales are: "mu_v" → μ …
    labels: list = field(default_factory=list)     # the boxes [mm] :meth:`label` placed
    # the box of items[:_boxed], grown by the items appended since (items are only appended)
    _box: tuple | None = field(default=None, init=False, repr=False, compare=False)
    _boxed: int = field(default=0, init=False, repr=False, compare=False)

    def box(self) -> tuple[float, float, float, float]:
        n = len(self.items)
        if self._box is None or self._boxed > n:
            self._box, self._boxed = bounds(self.items), n
        elif self._boxed < n:
            b = bounds(self.items[self._boxed:])
            a = self._box
            self._box = (min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3]))
            self._boxed = n
        return self._box

    @property
    def size(self) -> tuple[float, float]:
        x0, y0, x1, y1 = self.box()
        return x1 - x0, y1 - y0

    def moved(self, dx: float, dy: float) -> View:
        return View(self.name, [it.moved(dx, dy) for it in self.items], self.scales,
                    [(b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy) for b in self.labels])

    # -- labels: the one placer (render/labels.py) -----------------------------------------
    def placer(self, step: float = 0.5):
        """The one label placer over what is drawn so far [mm]: the lines to keep off, and the
        hinges, the lettering and the small closed outlines (blocks, pivots' triangles, arrow
        heads: at most 10 mm across) no label may cover."""
        from flywheel.render.labels import Placer

        p = Placer(step=step)
        for it in self.items:
            if isinstance(it, Circle):
                p.marker(it.centre, it.radius + 0.4)
            elif isinstance(it, Text):
                p.box(it.box())
            else:
                x0, y0, x1, y1 = it.box()
                if it.closed and max(x1 - x0, y1 - y0) <= 10.0:
                    p.box((x0, y0, x1, y1))
                p.curve(list(it.points) + ([it.points[0]] if it.closed else []))
        return p

    def label(self, placer, anchor, text: str, height: float, places, prefer=None, *,
              rings: float | None = 2.0, margin: float = 0.4) -> None:
        """``text`` (:meth:`rich`, ``height`` [mm]) at the least costly of ``places``
        (render.labels rows: dx, dy, fx, fy [mm]) from ``anchor`` (or one anchor each), by
        ``placer``; its box (``margin`` round the letters and a subscript's drop) joins the
        placer's and :attr:`labels`. Where every place lies over :data:`ON_LINE` mm of lines
        or more, the rings round the anchor are tried too (a force's name along its link)."""
        drop = 0.3 * height if "_" in text else 0.0
        size = (rich_width(text, height) + 2 * margin, height + drop + 2 * margin)
        *_, b = placer.choose(anchor, size, places, prefer, rings=rings,
                              enough=ON_LINE / placer.step)
        self.rich(b[0] + margin, b[1] + margin + drop, text, height)
        self.labels.append(b)

    def placed(self, x: float, y: float) -> View:
        """The view with its box's lower left corner at (x, y)."""
        x0, y0, _, _ = self.box()
        return self.moved(x - x0, y - y0)

    # -- drawing helpers ------------------------------------------------------------------
    def line(self, *points, line: str = "main", closed: bool = False) -> None:
        self.items.append(Polyline(tuple((float(x), float(y)) for x, y in points), line, closed))

    def grid(self, widths, n: int, row_h: float) -> tuple[float, float]:
        """A table's lines: the outline and the column lines in main lines, the head row's
        lower line main and the others thin; ``n`` rows of ``row_h`` [mm]. Returns (W, H)."""
        W, H = sum(widths), n * row_h
        self.line((0, 0), (W, 0), (W, H), (0, H), closed=True)
        x = 0.0
        for w in widths[:-1]:
            x += w
            self.line((x, 0), (x, H))
        for k in range(1, n):
            self.line((0, H - k * row_h), (W, H - k * row_h), line="main" if k == 1 else "thin")
        return W, H

    def poly(self, points, line: str = "main") -> None:
        """A curve through ``points`` [mm], its vertices thinned to within TOLERANCE_MM."""
        self.items.append(Polyline(simplify(points), line))

    def circle(self, centre, radius: float, line: str = "main", filled: bool = False) -> None:
        self.items.append(Circle((float(centre[0]), float(centre[1])), float(radius), line,
                                 filled))

    def text(self, x, y, text: str, height: float = 3.5, angle: float = 0.0,
             halign: str = "left", valign: str = "bottom", squeeze: float = 1.0) -> Text:
        t = Text(float(x), float(y), text, height, angle, halign, valign,
                 squeeze * text_width(text, height), squeeze)
        self.items.append(t)
        return t

    def rich(self, x, y, text: str, height: float = 3.5, halign: str = "left",
             valign: str = "bottom") -> float:
        """Horizontal lettering with subscripts: «M_Σ», «ΔT_нб», «μ_φ = 2 °/мм» — a ``_`` makes
        the word after it (up to a space, «,», «=», «)» or «/») a subscript 0.7 as high, set
        0.3 of the height lower. Returns its width [mm]."""
        sizes = _runs(text, height)
        width = sum(text_width(r, h) for r, _, h in sizes)
        x0 = {"left": 0.0, "center": -width / 2, "right": -width}[halign]
        y0 = {"bottom": 0.0, "middle": -height / 2, "top": -height}[valign]
        cx = x + x0
        for r, sub, h in sizes:
            t = Text(float(cx), float(y + y0 - (0.3 * height if sub else 0.0)), r, h, 0.0,
                     "left", "bottom", text_width(r, h))
            self.items.append(t)
            cx += t.width
        return width

    def arrow(self, tail, head, line: str = "main", head_len: float = 3.5,
              head_w: float = 1.0, full: bool = False) -> None:
        """A vector from ``tail`` to ``head`` [mm] with a filled head (ГОСТ 2.307: the arrow's
        length 2.5 … 4 mm for an A1 sheet's lines); ``full``: its line drawn whole, tail to
        head, under the head (a plan's vector: its length measures the quantity)."""
        (x0, y0), (x1, y1) = tail, head
        d = math.hypot(x1 - x0, y1 - y0)
        if d < 1e-9:
            return
        ux, uy = (x1 - x0) / d, (y1 - y0) / d
        L = min(head_len, 0.4 * d)
        bx, by = x1 - L * ux, y1 - L * uy
        self.line((x0, y0), (x1, y1) if full else (bx, by), line=line)
        w = head_w * L / head_len
        self.items.append(Polyline(((x1, y1), (bx - w * uy, by + w * ux),
                                    (bx + w * uy, by - w * ux)), "thin", True, True))


def _runs(text: str, height: float) -> list[tuple[str, bool, float]]:
    """The runs of :meth:`View.rich`'s lettering: (text, a subscript, its height [mm]); a
    subscript in braces may hold the stops («R_{r1,p1}»)."""
    runs: list[tuple[str, bool]] = []
    for k, part in enumerate(text.split("_")):
        if k == 0:
            runs.append((part, False))
            continue
        if part.startswith("{") and "}" in part:      # «R_{r1,p1}»: braces hold it whole
            j = part.index("}")
            runs.append((part[1:j], True))
            runs.append((part[j + 1:], False))
            continue
        cut = len(part)
        for stop in " ,=)/;":
            j = part.find(stop)
            if j != -1:
                cut = min(cut, j)
        runs.append((part[:cut], True))
        runs.append((part[cut:], False))
    return [(r, sub, 0.7 * height if sub else height) for r, sub in runs if r]


def rich_width(text: str, height: float) -> float:
    """The length [mm] of :meth:`View.rich`'s lettering of ``text``."""
    return sum(text_width(r, h) for r, _, h in _runs(text, height))


def indexed(name: str) -> str:
    """A point's or an image's name with its trailing digits as a subscript, as the course
    writes them: "S3" → "S_3" (S₃), "s2" → "s_2"; "B", "AB" stay."""
    import re

    m = re.match(r"^(.*?[^\d_])(\d+)$", name)
    return f"{m.group(1)}_{m.group(2)}" if m else name


TOLERANCE_MM = 0.05      # a curve's vertices kept: its line moves at most this [mm]


def simplify(points) -> tuple[tuple[float, float], ...]:
    """The vertices of a polyline a path within TOLERANCE_MM of it needs (Ramer–Douglas–Peucker:
    Douglas, Peucker, «Algorithms for the reduction of the number of points required to
    represent a digitized line», Cartographica 10 (2), 1973)."""
    import numpy as np

    p = np.asarray(points, float)
    n = len(p)
    if n <= 3:
        return tuple((float(x), float(y)) for x, y in p)
    keep = np.zeros(n, bool)
    keep[0] = keep[-1] = True
    stack = [(0, n - 1)]
    while stack:
        a, b = stack.pop()
        if b - a < 2:
            continue
        d = p[b] - p[a]
        L = float(np.hypot(*d))
        seg = p[a + 1:b] - p[a]
        dist = (np.abs(seg[:, 0] * d[1] - seg[:, 1] * d[0]) / L if L > 1e-12
                else np.hypot(seg[:, 0], seg[:, 1]))
        j = int(np.argmax(dist))
        if dist[j] > TOLERANCE_MM:
            m = a + 1 + j
            keep[m] = True
            stack += [(a, m), (m, b)]
    return tuple((float(x), float(y)) for x, y in p[keep])


# -- the font's widths ------------------------------------------------------------------------
_WIDTHS: dict[str, float] = {}


def text_width(text: str, height: float) -> float:
    """The length [mm] of ``text`` lettered with capitals ``height`` mm high in the sheet's font
    (fonts.py), from the font's advance widths."""
    from flywheel.render.drawings.fonts import advance

    total = 0.0
    for ch in text:
        w = _WIDTHS.get(ch)
        if w is None:
            w = _WIDTHS[ch] = advance(ch)
        total += w
    return total * height
