"""The one label placer of every figure (issue 28 item 6): the plots' schemes, the plan of
positions, the velocity and acceleration plans, the force polygons, Zhukovsky's lever, the
hodographs (render/plots*.py) and the ЕСКД sheets' schemes, plans and group drawings
(render/drawings/).

A label is a box of a known size (its text's extent) to be set beside an anchor (a point, the
middle of a vector). :class:`Placer` keeps, in one unit of length (points of the page for
matplotlib, mm of the sheet for a drawing), what a label must not cover:

- *hard* obstacles: the labels placed before and the markers (hinges, images, marks) —
  a candidate place that meets one is taken only if every place does, and then the placer
  looks farther out, ring by ring, for a free one;
- *soft* obstacles: the lines and curves drawn, sampled as points every ``step`` — the
  fewer of them under a label the better;
- the frame (the axes or the view), which a label should keep inside, and must not leave by
  more than ``slack`` (it would sit on the next panel's tick labels).

Each label's place is the least costly of a small set of candidate offsets (the corners and
sides of a point, :data:`AROUND`; either side of a vector at a few distances), ties broken by
the order given, so the same input gives the same places. The cost of all the candidates of
one label is computed at once (numpy). :class:`AxesLabels` adapts it to a matplotlib Axes:
the boxes are measured with the renderer's own text extents (the box a Text's
``get_window_extent`` returns), and every placed label and marker is recorded on the figure
(``figure.flywheel_labels``: (Text, box [pt]); ``figure.flywheel_markers``: boxes [pt]) so
the tests can check that none overlaps another or covers a marker.
"""
from __future__ import annotations

import math

import numpy as np

HARD = 1.0e4          # the cost of one hard obstacle under a label
OUTSIDE = 100.0       # the cost of a label leaving its frame (plus the distance out)
SHORT = 6.0           # [pt] a vector this short (its arrowhead's size): labelled round its head


def around(gap: float) -> np.ndarray:
    """A point's eight places [dx, dy, fx, fy] at ``gap`` from it: up right first, then the
    other corners, then the sides. (dx, dy): the offset of the label's reference point;
    fx, fy: the share of its width left of it and of its height below it (0 left/bottom
    aligned, 0.5 centred, 1 right/top)."""
    g, s = gap, 1.5 * gap
    return np.array([(g, g, 0.0, 0.0), (-g, g, 1.0, 0.0), (g, -g, 0.0, 1.0), (-g, -g, 1.0, 1.0),
                     (s, 0.0, 0.0, 0.5), (-s, 0.0, 1.0, 0.5), (0.0, s, 0.5, 0.0),
                     (0.0, -s, 0.5, 1.0)])


def aligned(direction) -> tuple[float, float]:
    """(fx, fy) of a label set off its anchor towards unit ``direction``: the box's near side
    towards the anchor."""
    ux, uy = float(direction[0]), float(direction[1])
    fx = 0.0 if ux > 0.35 else 1.0 if ux < -0.35 else 0.5
    fy = 0.0 if uy > 0.35 else 1.0 if uy < -0.35 else 0.5
    return fx, fy


def toward(direction, dist: float) -> tuple[float, float, float, float]:
    """One candidate place [dx, dy, fx, fy] ``dist`` from the anchor towards ``direction``."""
    d = np.asarray(direction, float)
    n = float(np.hypot(*d))
    d = d / n if n > 1e-12 else np.array([0.0, 1.0])
    return (float(d[0] * dist), float(d[1] * dist), *aligned(d))


def ha_va(fx: float, fy: float) -> tuple[str, str]:
    """matplotlib's horizontal and vertical alignment of (fx, fy)."""
    return ({0.0: "left", 0.5: "center", 1.0: "right"}[float(fx)],
            {0.0: "bottom", 0.5: "center", 1.0: "top"}[float(fy)])


def overlap(a, b) -> bool:
    """Whether boxes a and b (x0, y0, x1, y1) share an area."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


class Placer:
    """Chooses each label's place among candidates: fewest hard obstacles (labels placed
    before, markers), then fewest points of the lines, inside the frame, the earliest
    candidate on a tie. All lengths in one unit."""

    def __init__(self, frame=None, step: float = 2.0, slack: float = 8.0):
        self.frame = None if frame is None else tuple(float(v) for v in frame)
        self.slack = float(slack)
        self.step = float(step)
        self.labels: list[tuple[float, float, float, float]] = []
        self.markers: list[tuple[float, float, float, float]] = []
        self._clouds: list[np.ndarray] = [np.zeros((0, 2))]
        self._cloud = None
        self._by_x = None

    # -- obstacles ------------------------------------------------------------------------
    def marker(self, xy, radius: float) -> None:
        """A marker (a hinge, an image, a mark) of ``radius`` at ``xy``: no label on it."""
        x, y = float(xy[0]), float(xy[1])
        self.markers.append((x - radius, y - radius, x + radius, y + radius))

    def box(self, b) -> None:
        """A hard obstacle: a box (x0, y0, x1, y1) no label may cover (a slider's block)."""
        self.markers.append(tuple(float(v) for v in b))

    def segments(self, segs) -> None:
        """Lines drawn: (tail, head) pairs, sampled every ``step``."""
        pairs = [(np.asarray(a, float), np.asarray(b, float)) for a, b in segs]
        if pairs:
            self._sample(np.array([a for a, _ in pairs]), np.array([b for _, b in pairs]))

    def heads(self, tails, heads, length: float, half_width: float) -> None:
        """Arrowheads drawn at ``heads`` of the vectors from ``tails`` (rows): each a triangle,
        its tip at the head, its base ``length`` back along the vector, ``half_width`` either
        side — soft like the lines, its outline and its axis sampled every ``step``. A tiny
        vector's head is larger than the vector itself: without it, a neighbour's label was
        set over it (the compressor's Φ₄ over G₄'s head)."""
        t, h = np.asarray(tails, float).reshape(-1, 2), np.asarray(heads, float).reshape(-1, 2)
        d = h - t
        n = np.hypot(d[:, 0], d[:, 1])
        keep = n > 1e-9
        if not keep.any():
            return
        u = d[keep] / n[keep, None]
        tip = h[keep]
        base = tip - length * u
        side = half_width * np.column_stack([-u[:, 1], u[:, 0]])
        a, b = base + side, base - side
        self._sample(np.vstack([tip, a, b, tip]), np.vstack([a, b, tip, base]))

    def curve(self, xy) -> None:
        """A polyline drawn (rows of x, y), sampled every ``step`` along each piece."""
        xy = np.asarray(xy, float)
        if len(xy) >= 2:
            self._sample(xy[:-1], xy[1:])

    def _sample(self, tails: np.ndarray, heads: np.ndarray) -> None:
        """Each piece tail → head (rows) sampled at n points, n = ⌊length / step⌋ + 1 (at least
        2), evenly from tail to head: the points ``numpy.linspace`` gives, all pieces at once."""
        d = heads - tails
        n = np.maximum(2, (np.hypot(d[:, 0], d[:, 1]) / self.step).astype(int) + 1)
        piece = np.repeat(np.arange(len(n)), n)
        first = np.cumsum(n) - n
        t = (np.arange(int(n.sum())) - first[piece]) * (1.0 / (n - 1))[piece]
        t[first + n - 1] = 1.0                           # each piece ends at its head
        self._clouds.append(tails[piece] + t[:, None] * d[piece])
        self._cloud = None

    @property
    def cloud(self) -> np.ndarray:
        """The lines' sampled points (rows of x, y), line by line."""
        if self._cloud is None:
            self._cloud = np.concatenate(self._clouds)
            self._by_x = None
        return self._cloud

    @property
    def cloud_by_x(self) -> np.ndarray:
        """:attr:`cloud` in the order of x."""
        cloud = self.cloud
        if self._by_x is None:
            self._by_x = cloud[np.argsort(cloud[:, 0], kind="stable")]
        return self._by_x

    # -- choosing -------------------------------------------------------------------------
    def boxes_of(self, anchor, size, places) -> np.ndarray:
        """The candidate boxes (m × 4) of a label of ``size`` (w, h) at ``places``
        (m × 4: dx, dy, fx, fy) from ``anchor`` (one point, or m rows: one each)."""
        p = np.asarray(places, float).reshape(-1, 4)
        a = np.asarray(anchor, float).reshape(-1, 2)
        w, h = float(size[0]), float(size[1])
        x0 = a[:, 0] + p[:, 0] - p[:, 2] * w
        y0 = a[:, 1] + p[:, 1] - p[:, 3] * h
        return np.column_stack([x0, y0, x0 + w, y0 + h])

    def costs(self, boxes: np.ndarray) -> np.ndarray:
        """The cost of each candidate box (m × 4), all at once."""
        m = len(boxes)
        c = np.zeros(m)
        x0, y0, x1, y1 = boxes.T
        hard = self.labels + self.markers
        if hard:
            q = np.asarray(hard)
            hit = ((x0[:, None] < q[None, :, 2]) & (q[None, :, 0] < x1[:, None])
                   & (y0[:, None] < q[None, :, 3]) & (q[None, :, 1] < y1[:, None]))
            c += HARD * hit.sum(axis=1)
        pts = self.cloud_by_x
        if len(pts) and m:       # only the points within the candidates' span of x can count
            pts = pts[np.searchsorted(pts[:, 0], x0.min(), side="right"):
                      np.searchsorted(pts[:, 0], x1.max(), side="left")]
        if len(pts):
            px, py = pts[None, :, 0], pts[None, :, 1]
            chunk = max(1, 400_000 // len(pts))     # candidates × points at once, bounded
            for k in range(0, m, chunk):
                s = slice(k, k + chunk)
                c[s] += np.count_nonzero((px > x0[s, None]) & (px < x1[s, None])
                                         & (py > y0[s, None]) & (py < y1[s, None]), axis=1)
        if self.frame is not None:      # out of the frame: the farther the worse; past the
            f0, g0, f1, g1 = self.frame  # slack (over the next panel) worse than on a label
            out = np.maximum.reduce([f0 - x0, g0 - y0, x1 - f1, y1 - g1])
            c += np.where(out > 0, OUTSIDE + out, 0.0) + np.where(out > self.slack, 2 * HARD, 0.0)
        return c

    def choose(self, anchor, size, places, prefer=None, *, rings: float | None = None,
               ring_at=None, enough: float = HARD):
        """Place a label of ``size`` (w, h) at the least costly of ``places`` from
        ``anchor`` (one point, or one row per place), ``prefer``: each place's own extra
        cost (else 0.01 per rank). If each costs ``enough`` or more (default: each meets a
        hard obstacle), farther out round ``ring_at`` (default the first anchor), where it
        costs less: ``rings`` the first ring's distance, then 1.5, 2, … 4 times it, 16
        directions. Records the box; returns (anchor (x, y), dx, dy, fx, fy, box)."""
        places = np.asarray(places, float).reshape(-1, 4)
        anchors = np.broadcast_to(np.asarray(anchor, float).reshape(-1, 2), (len(places), 2))
        boxes = self.boxes_of(anchors, size, places)
        extra = 0.01 * np.arange(len(places)) if prefer is None else np.asarray(prefer, float)
        cost = self.costs(boxes) + extra
        k = int(np.argmin(cost))
        if cost[k] >= enough and rings:
            at = anchors[0] if ring_at is None else np.asarray(ring_at, float)
            angles = np.arange(16) * (math.pi / 8)
            dirs = np.column_stack([np.cos(angles), np.sin(angles)])
            for f in (1.0, 1.5, 2.0, 2.5, 3.0, 4.0):
                ring = np.array([toward(d, rings * f) for d in dirs])
                rb = self.boxes_of(at, size, ring)
                rc = self.costs(rb) + 0.01 * f
                j = int(np.argmin(rc))
                if rc[j] < cost[k]:
                    anchors = np.broadcast_to(at, (len(ring), 2))
                    places, boxes, cost, k = ring, rb, rc, j
                if cost[k] < enough:
                    break
        b = tuple(float(v) for v in boxes[k])
        self.labels.append(b)
        return (tuple(float(v) for v in anchors[k]), *(float(v) for v in places[k]), b)

    def free(self, box) -> bool:
        """Whether ``box`` meets no label placed and no marker."""
        return not any(overlap(box, q) for q in self.labels + self.markers)


def beside(tail, head, gaps=(2.5, 8.0, 16.0, 26.0), shares=(0.5, 0.35, 0.65, 0.2, 0.8)):
    """Candidate places of a vector's label [anchor, place rows]: at ``shares`` of its length,
    either side of it, ``gaps`` off it. Returns (anchors m × 2, places m × 4, prefer m)."""
    t, h = np.asarray(tail, float), np.asarray(head, float)
    d = h - t
    L = float(np.hypot(*d))
    n = np.array([-d[1], d[0]]) / L if L > 1e-12 else np.array([0.0, 1.0])
    anchors, places, prefer = [], [], []
    for s in shares:
        for side in (1.0, -1.0):
            for g in gaps:
                anchors.append(t + s * d)
                places.append(toward(side * n, g))
                prefer.append(0.01 * g + 0.05 * abs(s - 0.5) + (0.0 if side > 0 else 0.001))
    return np.array(anchors), np.array(places), np.array(prefer)


# -- matplotlib --------------------------------------------------------------------------------

class AxesLabels:
    """The placer on a matplotlib Axes, in points of the page: call once the axes have their
    final place and limits. Labels are annotations offset from their anchor in points."""

    def __init__(self, ax, *, frame: bool = True, step: float = 2.0):
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        self.ax, self.fig = ax, ax.figure
        canvas = self.fig.canvas
        if not isinstance(canvas, FigureCanvasAgg):
            canvas = FigureCanvasAgg(self.fig)
        self.renderer = canvas.get_renderer()
        ax.get_xlim()                  # the view limits autoscaled, then fitted to the aspect
        ax.apply_aspect()
        self.pt = 72.0 / self.fig.dpi  # points per pixel
        fb = ax.get_window_extent(self.renderer)
        self.placer = Placer((fb.x0 * self.pt, fb.y0 * self.pt, fb.x1 * self.pt,
                              fb.y1 * self.pt) if frame else None, step)
        self._probe = None
        if not hasattr(self.fig, "flywheel_labels"):
            self.fig.flywheel_labels = []
            self.fig.flywheel_markers = []

    def to_pt(self, xy) -> np.ndarray:
        """Data coordinates (rows of x, y) → points of the page."""
        xy = np.asarray(xy, float).reshape(-1, 2)
        return self.ax.transData.transform(xy) * self.pt

    def size(self, text: str, **kw) -> tuple[float, float]:
        """The extent (w, h) [pt] a Text of ``text`` and ``kw`` (fontsize, fontweight …)
        draws — the renderer's own measure, of one Text of the figure's kept for measuring
        (not drawn): its font set anew for each, as a new Text's would be."""
        from matplotlib.font_manager import FontProperties
        from matplotlib.text import Text

        if self._probe is None:
            self._probe = Text(0.0, 0.0, "", transform=self.fig.transSubfigure)
            self._probe.set_figure(self.fig)
        probe = self._probe
        probe.set_text(text)
        probe.set_fontproperties(FontProperties())
        probe.update(kw)
        bb = probe.get_window_extent(self.renderer)
        return bb.width * self.pt, bb.height * self.pt

    def markers(self, xy, radius: float) -> None:
        """Markers at data ``xy`` (rows), ``radius`` [pt] each."""
        for p in self.to_pt(xy):
            self.placer.marker(p, radius)
            self.fig.flywheel_markers.append(self.placer.markers[-1])

    def box(self, corners) -> None:
        """A hard obstacle: the box round ``corners`` (data rows), e.g. a slider's block."""
        p = self.to_pt(corners)
        self.placer.box((*p.min(axis=0), *p.max(axis=0)))

    def segments(self, segs) -> None:
        """Lines drawn: (tail, head) pairs in data coordinates."""
        self.placer.segments((self.to_pt(a)[0], self.to_pt(b)[0]) for a, b in segs)

    def heads(self, tails, heads, length: float, half_width: float) -> None:
        """Arrowheads at ``heads`` of the vectors from ``tails`` (data rows), ``length`` and
        ``half_width`` [pt] on the page (:meth:`Placer.heads`)."""
        self.placer.heads(self.to_pt(tails), self.to_pt(heads), length, half_width)

    def curve(self, xy) -> None:
        self.placer.curve(self.to_pt(xy))

    def _draw(self, place, text: str, kw: dict):
        (ax_, ay_), dx, dy, fx, fy, b = place
        ha, va = ha_va(fx, fy)
        xy = self.ax.transData.inverted().transform((ax_ / self.pt, ay_ / self.pt))
        a = self.ax.annotate(text, (float(xy[0]), float(xy[1])), xytext=(dx, dy),
                             textcoords="offset points", ha=ha, va=va, **kw)
        self.fig.flywheel_labels.append((a, b))
        return a

    def point(self, xy, text: str, gap: float = 4.0, places=None, *, optional: bool = False,
              **kw):
        """``text`` beside the point ``xy`` (data) at the least costly of ``places``
        (default :func:`around` at ``gap`` [pt]); ``kw``: the Text's properties. A label
        that meets a hard obstacle at every place is set farther out, or, if ``optional``,
        left out (returns None)."""
        anchor = self.to_pt(xy)[0]
        size = self.size(text, **_font(kw))
        pl = np.asarray(around(gap) if places is None else places, float).reshape(-1, 4)
        if optional:
            cost = self.placer.costs(self.placer.boxes_of(anchor, size, pl))
            if float(cost.min()) >= HARD:
                return None
        return self._draw(self.placer.choose(anchor, size, pl, rings=max(gap, 6.0)), text, kw)

    def along(self, tail, head, text: str, **kw):
        """``text`` beside the vector tail → head (data)."""
        t, h = self.to_pt(tail)[0], self.to_pt(head)[0]
        anchors, places, prefer = beside(t, h)
        if float(np.hypot(*(h - t))) < SHORT:   # shorter than its head: round the head too,
            gaps = (4.0, 8.0, 14.0, 22.0)      # where no place beside it is free
            anchors = np.vstack([anchors, np.repeat(h[None], 8 * len(gaps), axis=0)])
            places = np.vstack([places, *(around(g) for g in gaps)])
            prefer = np.concatenate([prefer, [prefer.max() + 0.01 * g + 0.001 * k
                                              for g in gaps for k in range(8)]])
        return self.best(anchors, places, prefer, text, ring_at=0.5 * (t + h), **kw)

    def best(self, anchors, places, prefer, text: str, *, ring_at=None, **kw):
        """``text`` at the least costly of candidate ``places`` (m × 4), each from its own
        anchor (m × 2, points of the page), ``prefer`` their extra costs; on a hard obstacle
        wherever, round ``ring_at`` (default the first anchor) farther out."""
        size = self.size(text, **_font(kw))
        return self._draw(self.placer.choose(anchors, size, places, prefer, rings=20.0,
                                             ring_at=ring_at), text, kw)


def _font(kw: dict) -> dict:
    """The properties of a Text that change its extent."""
    keys = ("fontsize", "fontweight", "fontstyle", "style", "weight", "size", "family")
    return {k: v for k, v in kw.items() if k in keys}
