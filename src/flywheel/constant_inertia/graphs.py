"""Moment graphs of task 2 over one cycle: pieces in closed form, the presets, the net moment.

A graph is a chain of contiguous pieces on ``[0, Φ]`` [rad], each ``M(φ) = m0 + slope·(φ − φ0)
+ Σ (a·sin kφ + b·cos kφ)`` [N·m], so that every piece's work ``∫ M dφ`` [J] has a closed form
(no numerical quadrature). The presets are the seed's (``002_10afb132413d2537.txt``, «Задача 2»:
the triangle and the rectangle) and the textbook's (R.S. Khurmi & J.K. Gupta, *Theory of
Machines*, ch. 16: the trapezoid, harmonic series of a turning-moment diagram).

Pure functions on plain floats (``math`` only at import): importing this module is cheap. A
series longer than ``LONG_SERIES`` terms is summed by numpy (imported then), one dot product per
evaluation instead of a Python loop over its terms; a short one term by term, as always.

Limits (stated in docs/task2.md, refused by the case schema): ``MAX_TERMS`` terms of a series,
``MAX_POINTS`` points of a piecewise-linear graph.
"""
from __future__ import annotations

import math
from bisect import bisect_left, bisect_right
from dataclasses import dataclass, field
from typing import Sequence

from flywheel.errors import InputError, Notice

TWO_PI = 2.0 * math.pi

#: the most terms of a harmonic series and points of a piecewise-linear graph a case may give
MAX_TERMS = 1000
MAX_POINTS = 100_000
#: a series of more terms than this is summed by numpy (:class:`Piece`)
LONG_SERIES = 16
#: the most entries of one terms × angles matrix of :meth:`Piece.values_and_slopes` (8 bytes each)
CHUNK = 250_000

_SERIES: dict[int, tuple] = {}


def _series_arrays(harmonics: tuple) -> tuple:
    """(k, a, b) of a series as numpy arrays, kept for the last few series (a graph's pieces and
    the pieces cut from them share one tuple of terms)."""
    import numpy as np

    hit = _SERIES.get(id(harmonics))
    if hit is not None and hit[0] is harmonics:
        return hit[1]
    if len(_SERIES) > 32:
        _SERIES.clear()
    arrays = tuple(np.array(c, dtype=float) for c in zip(*harmonics))
    _SERIES[id(harmonics)] = (harmonics, arrays)
    return arrays


@dataclass(frozen=True)
class Piece:
    """One piece of a moment graph on ``[phi0, phi1]`` [rad]::

        M(φ) = m0 + slope·(φ − phi0) + Σ (a·sin kφ + b·cos kφ)      [N·m]

    ``harmonics`` holds ``(k, a, b)`` triples (k > 0, dimensionless order; a, b in N·m).
    """

    phi0: float
    phi1: float
    m0: float
    slope: float = 0.0
    harmonics: tuple[tuple[float, float, float], ...] = ()
    #: a long series (> LONG_SERIES terms) as numpy arrays (k, a, b, cos kφ0, sin kφ0), else None
    arrays: tuple | None = field(default=None, init=False, repr=False, compare=False)

    def __post_init__(self):
        if len(self.harmonics) > LONG_SERIES:
            import numpy as np

            k, a, b = _series_arrays(self.harmonics)
            object.__setattr__(self, "arrays", (k, a, b, np.cos(k * self.phi0),
                                                np.sin(k * self.phi0)))

    def values_and_slopes(self, phis) -> tuple:
        """(M, dM/dφ) at many angles at once (numpy arrays): the series summed as matrix
        products over terms × angles, in chunks of at most ``CHUNK`` entries (bounded memory).
        Only for a long series (``arrays`` set); the short one is summed by :meth:`value_and_slope`."""
        import numpy as np

        k, a, b = self.arrays[:3]
        x = np.asarray(phis, dtype=float)
        m = self.m0 + self.slope * (x - self.phi0)
        d = np.full_like(x, self.slope)
        ka, kb = k * a, k * b
        step = max(1, CHUNK // len(k))
        for i in range(0, len(x), step):
            kx = np.outer(x[i:i + step], k)
            s, c = np.sin(kx), np.cos(kx)
            m[i:i + step] += s @ a + c @ b
            d[i:i + step] += c @ ka - s @ kb
        return m, d

    def value(self, phi: float) -> float:
        """M(φ) [N·m] (the formula of this piece, also outside its interval)."""
        m = self.m0 + self.slope * (phi - self.phi0)
        if self.arrays is not None:
            import numpy as np

            k, a, b = self.arrays[:3]
            kx = k * phi
            return m + float(np.dot(a, np.sin(kx)) + np.dot(b, np.cos(kx)))
        for k, a, b in self.harmonics:
            m += a * math.sin(k * phi) + b * math.cos(k * phi)
        return m

    def value_and_slope(self, phi: float) -> tuple[float, float]:
        """(M(φ) [N·m], dM/dφ [N·m/rad]) with one sine and one cosine per term::

            dM/dφ = slope + Σ k·(a·cos kφ − b·sin kφ)
        """
        m = self.m0 + self.slope * (phi - self.phi0)
        d = self.slope
        if self.arrays is not None:
            import numpy as np

            k, a, b = self.arrays[:3]
            kx = k * phi
            s, c = np.sin(kx), np.cos(kx)
            return (m + float(np.dot(a, s) + np.dot(b, c)),
                    d + float(np.dot(k, a * c - b * s)))
        for k, a, b in self.harmonics:
            s, c = math.sin(k * phi), math.cos(k * phi)
            m += a * s + b * c
            d += k * (a * c - b * s)
        return m, d

    def work(self, phi: float) -> float:
        """∫_{phi0}^{φ} M dφ [J], in closed form::

            m0·h + slope·h²/2 + Σ [a·(cos k·φ0 − cos k·φ) + b·(sin k·φ − sin k·φ0)]/k,  h = φ − φ0

        >>> round(Piece(0.0, math.pi, 15.0).work(math.pi / 2), 9)    # 15 N·m over π/2
        23.561944902
        >>> round(Piece(0.0, math.pi, 0.0, harmonics=((1, 2.0, 0.0),)).work(math.pi), 12)
        4.0
        """
        h = phi - self.phi0
        w = self.m0 * h + 0.5 * self.slope * h * h
        if self.arrays is not None:
            import numpy as np

            k, a, b, c0, s0 = self.arrays
            kx = k * phi
            return w + float(np.sum((a * (c0 - np.cos(kx)) + b * (np.sin(kx) - s0)) / k))
        for k, a, b in self.harmonics:
            w += (a * (math.cos(k * self.phi0) - math.cos(k * phi))
                  + b * (math.sin(k * phi) - math.sin(k * self.phi0))) / k
        return w

    def works(self, phis):
        """:meth:`work` at many angles at once (a numpy array), for a long series (``arrays``
        set): the closed form summed as matrix products over terms × angles, in chunks."""
        import numpy as np

        k, a, b, c0, s0 = self.arrays
        x = np.asarray(phis, dtype=float)
        h = x - self.phi0
        w = self.m0 * h + 0.5 * self.slope * h * h
        const = float(np.sum((a * c0 - b * s0) / k))
        ak, bk = a / k, b / k
        step = max(1, CHUNK // len(k))
        for i in range(0, len(x), step):
            kx = np.outer(x[i:i + step], k)
            w[i:i + step] += const - np.cos(kx) @ ak + np.sin(kx) @ bk
        return w

    def linear_at(self, phi: float) -> float:
        """The linear part m0 + slope·(φ − phi0) [N·m]."""
        return self.m0 + self.slope * (phi - self.phi0)


@dataclass(frozen=True)
class Moment:
    """A moment graph over one cycle ``[0, cycle]``: contiguous pieces, in order.

    ``nominal`` is the number that names the graph [N·m]: the constant, the peak of a preset,
    the largest ordinate of a piecewise-linear graph (times its scale), ``a0`` of a series.
    """

    pieces: tuple[Piece, ...]
    cycle: float
    nominal: float
    kind: str = "points"

    def value(self, phi: float, side: int = +1) -> float:
        """M(φ) [N·m]; at a jump the value just after (``side=+1``) or before (``-1``). The
        piece is found by bisection of the breakpoints (log of the number of pieces)."""
        pcs = self.pieces
        if side > 0:    # the first piece with phi < phi1
            i = bisect_right(self._ends(), phi)
            return pcs[min(i, len(pcs) - 1)].value(phi)
        i = bisect_left(self._starts(), phi) - 1     # the last piece with phi0 < phi
        return pcs[max(i, 0)].value(phi)

    def _starts(self) -> list[float]:
        if "_phi0s" not in self.__dict__:
            object.__setattr__(self, "_phi0s", [p.phi0 for p in self.pieces])
        return self.__dict__["_phi0s"]

    def _ends(self) -> list[float]:
        if "_phi1s" not in self.__dict__:
            object.__setattr__(self, "_phi1s", [p.phi1 for p in self.pieces])
        return self.__dict__["_phi1s"]

    def work(self) -> float:
        """Work over the cycle ∮ M dφ [J]."""
        return math.fsum(p.work(p.phi1) for p in self.pieces)

    def breakpoints(self) -> list[float]:
        return [p.phi0 for p in self.pieces] + [self.pieces[-1].phi1]


def size(m: Moment) -> float:
    """A bound on ∮|M| dφ [J] that also covers the round-off of the closed-form works.

    Triangle inequality: on a piece, ``|M| ≤ max(|M(φ0)|, |M(φ1)|)`` for the linear part and
    ``|a·sin kφ + b·cos kφ| ≤ R = √(a² + b²)``, so ∫|M| ≤ Σ [max(|m0|, |m1|) + Σ R]·h. The closed
    form of ``Piece.work`` adds terms of size R/k (at most 2R/k per term) whose round-off is
    what a zero-mean series leaves in ∮M dφ (1.2e-13 J for 300 sin 2φ − 500 cos 2φ), so they
    are counted too. Steadiness and the cycle balance are judged relative to this size, never
    relative to the net works, which vanish for zero-mean moments.

    >>> round(size(harmonic(0.0, [3.0], [4.0], orders=[2])), 12) == round(5 * (TWO_PI + 1), 12)
    True
    """
    total = 0.0
    for p in m.pieces:
        h = p.phi1 - p.phi0
        total += max(abs(p.m0), abs(p.linear_at(p.phi1))) * h
        for k, a, b in p.harmonics:
            total += math.hypot(a, b) * (h + 2.0 / k)
    return total


def _check_cycle(cycle: float) -> None:
    if not (math.isfinite(cycle) and cycle > 0):
        # library use only: no CLI input reaches this
        raise InputError(f"the cycle must be a positive angle (got {cycle!r} rad)")


def constant(value: float, cycle: float = TWO_PI) -> Moment:
    """A constant moment ``value`` [N·m] over the cycle [rad]."""
    _check_cycle(cycle)
    return Moment((Piece(0.0, cycle, float(value)),), cycle, float(value), "constant")


def piecewise_linear(points: Sequence[tuple[float, float]], cycle: float = TWO_PI,
                     nominal: float | None = None, kind: str = "points") -> Moment:
    """A graph through ``points`` = [(φ [rad], M [N·m]), …], straight between them.

    The angles must start at 0, end at ``cycle`` and never decrease; a repeated angle is a
    jump (the rectangle's vertical sides).

    >>> m = piecewise_linear([(0, 0), (1, 10), (2, 0)], cycle=2)
    >>> m.value(0.5), m.work()
    (5.0, 10.0)
    """
    _check_cycle(cycle)
    pts = [(float(p), float(m)) for p, m in points]
    if len(pts) < 2:
        # library use only: no CLI input reaches this
        raise InputError("a graph needs at least two points")
    for i in range(1, len(pts)):
        if pts[i][0] < pts[i - 1][0]:
            at, before = math.degrees(pts[i][0]), math.degrees(pts[i - 1][0])
            raise InputError(Notice.of(
                "t2_graph_angles_back", "graph angles must not decrease: point {i} at {at:g}° "
                "comes after {before:g}°", i=i, at=at, before=before))
    scale = max(cycle, 1.0) * 1e-12
    if abs(pts[0][0]) > scale or abs(pts[-1][0] - cycle) > scale:
        # library use only: no CLI input reaches this
        raise InputError(
            f"the graph must span the cycle 0…{math.degrees(cycle):g}° "
            f"(it spans {math.degrees(pts[0][0]):g}…{math.degrees(pts[-1][0]):g}°)")
    pts[0] = (0.0, pts[0][1])
    pts[-1] = (cycle, pts[-1][1])
    pieces = []
    for (p0, m0), (p1, m1) in zip(pts, pts[1:]):
        if p1 > p0:
            pieces.append(Piece(p0, p1, m0, (m1 - m0) / (p1 - p0)))
    if not pieces:
        # library use only: no CLI input reaches this
        raise InputError("the graph has no length")
    if nominal is None:
        nominal = max(m for _, m in pts)
    return Moment(tuple(pieces), cycle, float(nominal), kind)


def _check_span(start: float, end: float, cycle: float) -> float:
    """Refuse an interval outside 0 ≤ from < to ≤ cycle; returns ``end``, a hair beyond the
    cycle's end (rounding: 360.0000000001°) taken as the cycle's end."""
    if not (0.0 <= start < end <= cycle * (1 + 1e-12)):
        a, b, c = math.degrees(start), math.degrees(end), math.degrees(cycle)
        raise InputError(Notice.of(
            "t2_graph_interval", "the graph's interval {start:g}…{end:g}° must satisfy 0 ≤ from < "
            "to ≤ {cycle:g}°", start=a, end=b, cycle=c))
    return min(end, cycle)


def _frame(start: float, inner: list[tuple[float, float]], end: float, cycle: float,
           base: float) -> list[tuple[float, float]]:
    """Points of a preset: ``base`` outside [start, end], ``inner`` inside."""
    return [(0.0, base), (start, base), *inner, (end, base), (cycle, base)]


def triangle(peak: float, start: float, end: float, cycle: float = TWO_PI,
             apex: float | None = None, base: float = 0.0) -> Moment:
    """``base`` outside [start, end]; rises linearly to ``peak`` at ``apex`` (default the middle)
    and falls back to ``base`` at ``end``. Angles [rad], moments [N·m] (seed 002, task 1).

    >>> triangle(60.0, math.pi / 2, 3 * math.pi / 2).work() / math.pi   # M_C·(π/2)/π
    30.0
    """
    _check_cycle(cycle)
    end = _check_span(start, end, cycle)
    apex = 0.5 * (start + end) if apex is None else apex
    if not start <= apex <= end:
        # library use only: no CLI input reaches this
        raise InputError(f"the triangle's apex {math.degrees(apex):g}° lies outside "
                         f"{math.degrees(start):g}…{math.degrees(end):g}°")
    return piecewise_linear(_frame(start, [(apex, peak)], end, cycle, base), cycle,
                            nominal=peak, kind="triangle")


def rectangle(peak: float, start: float, end: float, cycle: float = TWO_PI,
              base: float = 0.0) -> Moment:
    """``peak`` on [start, end], ``base`` elsewhere (seed 002, task 2). Angles [rad].

    >>> rectangle(60.0, math.pi / 2, math.pi).work() / math.pi
    30.0
    """
    _check_cycle(cycle)
    end = _check_span(start, end, cycle)
    return piecewise_linear(_frame(start, [(start, peak), (end, peak)], end, cycle, base),
                            cycle, nominal=peak, kind="rectangle")


def trapezoid(peak: float, start: float, top_start: float, top_end: float, end: float,
              cycle: float = TWO_PI, base: float = 0.0) -> Moment:
    """``base`` → ``peak`` linearly on [start, top_start], ``peak`` on [top_start, top_end],
    back to ``base`` on [top_end, end]. Angles [rad] (Khurmi & Gupta, Example 16.6).
    """
    _check_cycle(cycle)
    end = _check_span(start, end, cycle)
    if not start <= top_start <= top_end <= end:
        # library use only: no CLI input reaches this
        raise InputError("a trapezoid needs from ≤ top_from ≤ top_to ≤ to")
    return piecewise_linear(_frame(start, [(top_start, peak), (top_end, peak)], end, cycle,
                                   base), cycle, nominal=peak, kind="trapezoid")


def harmonic(a0: float, a: Sequence[float] = (), b: Sequence[float] = (),
             orders: Sequence[float] | None = None, cycle: float = TWO_PI) -> Moment:
    """``M = a0 + Σ (a_k·sin kφ + b_k·cos kφ)`` [N·m]; orders k = 1, 2, … unless given
    (half orders such as 0.5 suit a four-stroke cycle of 4π).

    >>> round(harmonic(5000.0, [1500.0], orders=[3]).work() / TWO_PI, 9)
    5000.0
    """
    _check_cycle(cycle)
    n = max(len(a), len(b))
    a = list(a) + [0.0] * (n - len(a))
    b = list(b) + [0.0] * (n - len(b))
    ks = list(orders) if orders is not None else list(range(1, n + 1))
    if len(ks) != n:
        # library use only: no CLI input reaches this
        raise InputError(f"{len(ks)} orders given for {n} harmonic terms")
    if any(not (k > 0) for k in ks):
        # library use only: no CLI input reaches this
        raise InputError("harmonic orders must be positive")
    terms = tuple((float(k), float(ak), float(bk)) for k, ak, bk in zip(ks, a, b)
                  if ak != 0.0 or bk != 0.0)
    return Moment((Piece(0.0, cycle, float(a0), 0.0, terms),), cycle, float(a0), "harmonic")


# -- the net moment ------------------------------------------------------------------------------

def _sub_piece(p: Piece, x0: float, x1: float) -> Piece:
    return Piece(x0, x1, p.linear_at(x0), p.slope, p.harmonics)


def net_pieces(M_D: Moment, M_C: Moment) -> list[Piece]:
    """``M_D − M_C`` as pieces on the merged breakpoints of both graphs."""
    if abs(M_D.cycle - M_C.cycle) > 1e-12 * M_D.cycle:
        # library use only: no CLI input reaches this
        raise InputError("the driving and resistance graphs span different cycles")
    cuts = sorted(set(M_D.breakpoints()) | set(M_C.breakpoints()))
    out = []
    i = j = 0
    dp, cp = M_D.pieces, M_C.pieces
    for x0, x1 in zip(cuts, cuts[1:]):
        while dp[i].phi1 <= x0:
            i += 1
        while cp[j].phi1 <= x0:
            j += 1
        d, c = _sub_piece(dp[i], x0, x1), _sub_piece(cp[j], x0, x1)
        harm: dict[float, list[float]] = {}
        for k, a, b in d.harmonics:
            s = harm.setdefault(k, [0.0, 0.0])
            s[0] += a
            s[1] += b
        for k, a, b in c.harmonics:
            s = harm.setdefault(k, [0.0, 0.0])
            s[0] -= a
            s[1] -= b
        terms = tuple((k, a, b) for k, (a, b) in sorted(harm.items()) if a != 0.0 or b != 0.0)
        out.append(Piece(x0, x1, d.m0 - c.m0, d.slope - c.slope, terms))
    return out



__all__ = ["TWO_PI", "Piece", "Moment", "size", "constant", "piecewise_linear", "triangle",
           "rectangle", "trapezoid", "harmonic", "net_pieces"]
