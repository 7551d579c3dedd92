"""Where ``M_D − M_C`` changes sign on a piece: the angles where ω is extreme (task 2).

``ω`` is extreme where ``A(φ) = ∫₀^φ (M_D − M_C) dφ`` is, i.e. at the sign changes of the net
moment: at the breakpoints of the graphs (jumps) and at the crossings inside a piece, found here
exactly (linear pieces) or by a certified subdivision (Taylor bounds on the moment and its
derivative, so no cluster of close roots is missed) and bisection to machine precision (harmonic
pieces). Seed ``002_10afb132413d2537.txt`` places the crossings of its triangle at
``π/2 + (2/π)·M_D/M_C``; they are at 5π/8 and 11π/8.

Pure functions on plain floats (``math`` only).
"""
from __future__ import annotations

import math
from typing import Callable

from flywheel.constant_inertia.graphs import Piece


def bisect_root(f: Callable[[float], float], lo: float, hi: float, flo: float) -> float:
    """A root of f in [lo, hi] with f(lo)·f(hi) < 0, to machine precision."""
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        fm = f(mid)
        if fm == 0.0:
            return mid
        if (fm < 0.0) == (flo < 0.0):
            lo, flo = mid, fm
        else:
            hi = mid
    return 0.5 * (lo + hi)


def _derivative(p: Piece, phi: float) -> float:
    """dM/dφ of the piece's formula [N·m/rad]: slope + Σ k·(a·cos kφ − b·sin kφ)."""
    if p.arrays is not None:
        return p.value_and_slope(phi)[1]
    d = p.slope
    for k, a, b in p.harmonics:
        d += k * (a * math.cos(k * phi) - b * math.sin(k * phi))
    return d


def _harmonic_crossings(p: Piece) -> list[float]:
    """Sign changes of ``f = m0 + slope·(φ − φ0) + Σ (a·sin kφ + b·cos kφ)`` on the piece.

    Certified subdivision: with ``R = √(a² + b²)`` each term has ``|d/dφ| ≤ k·R`` and
    ``|d²/dφ²| ≤ k²·R`` (Cauchy–Schwarz), so ``L₂ = Σ k²·R`` bounds ``|f″|`` and Taylor's
    theorem with the Lagrange remainder about the midpoint m of [m − r, m + r] gives::

        |f(φ)|  ≥ |f(m)| − |f′(m)|·r − ½·L₂·r²    (> 0: no zero in the interval)
        |f′(φ)| ≥ |f′(m)| − L₂·r                  (> 0: f monotone, one bisection finds the root)

    An interval that passes neither test is halved. Each test keeps a margin for the round-off
    of evaluating f and f′ (16 ulp of the sizes of their terms; the argument k·φ is rounded, so
    a term's error grows with k·|φ|). Where f stays within that round-off of zero over a whole
    interval (a tangency, or roots closer than round-off can separate) its sign is unknown; a
    crossing is reported there only if the known signs on both sides differ: what makes ω
    extreme is a sign change of M_D − M_C, and a touching zero is none.

    Unlike sampling, this cannot step over a cluster of roots, and it also serves the pieces
    where a sloped line meets a harmonic series (no polynomial substitution applies there).
    """
    eps = 2.220446049250313e-16
    x_abs = max(abs(p.phi0), abs(p.phi1))
    h = p.phi1 - p.phi0
    L2 = err = err1 = 0.0
    for k, a, b in p.harmonics:
        R = math.hypot(a, b)
        L2 += k * k * R
        err += R * (1.0 + k * x_abs)
        err1 += k * R * (1.0 + k * x_abs)
    err = 16 * eps * (err + abs(p.m0) + abs(p.slope) * h)
    err1 = 16 * eps * (err1 + abs(p.slope))
    f = p.value

    def sign(v: float) -> int:
        return 0 if abs(v) <= err else (1 if v > 0.0 else -1)

    # (lo, hi, sign at lo, sign at hi, root inside or None), left to right
    segs: list[tuple[float, float, int, int, float | None]] = []

    def visit(lo: float, hi: float, flo: float, fhi: float, depth: int) -> None:
        m, r = 0.5 * (lo + hi), 0.5 * (hi - lo)
        fm, dm = p.value_and_slope(m)
        if abs(fm) - abs(dm) * r - 0.5 * L2 * r * r > err:          # no zero here
            s = 1 if fm > 0.0 else -1
            segs.append((lo, hi, s, s, None))
            return
        if abs(dm) - L2 * r > err1:                                  # monotone
            s0, s1 = sign(flo), sign(fhi)
            root = bisect_root(f, lo, hi, flo) if s0 * s1 < 0 else None
            segs.append((lo, hi, s0, s1, root))
            return
        if (abs(fm) + abs(dm) * r + 0.5 * L2 * r * r <= err or depth >= 64
                or not lo < m < hi):                                 # f ≈ 0 to round-off
            segs.append((lo, hi, 0, 0, None))
            return
        visit(lo, m, flo, fm, depth + 1)
        visit(m, hi, fm, fhi, depth + 1)

    if p.arrays is None:
        visit(p.phi0, p.phi1, f(p.phi0), f(p.phi1), 0)
    else:
        segs = _segments_batched(p, L2, err, err1, sign)

    roots: list[float] = []
    last = 0                                   # the last known sign
    unknown: list[float] = []                  # [first, last] angle of unknown sign since then

    def see(x: float, s: int) -> None:
        nonlocal last, unknown
        if s == 0:
            unknown = [unknown[0] if unknown else x, x]
            return
        if last and s != last:                 # the sign changed across the unknown stretch
            lo, hi = unknown or [x, x]
            flo, fhi = f(lo), f(hi)
            roots.append(bisect_root(f, lo, hi, flo) if flo * fhi < 0.0 else 0.5 * (lo + hi))
        last, unknown = s, []

    for lo, hi, s0, s1, root in segs:
        see(lo, s0)
        if root is not None:
            roots.append(root)
            last, unknown = s1, []
        see(hi, s1)
    return [r for r in roots if p.phi0 < r < p.phi1]


def _segments_batched(p: Piece, L2: float, err: float, err1: float,
                      sign: Callable[[float], int]) -> list:
    """The segments of ``_harmonic_crossings``'s subdivision for a long series, found level by
    level: every interval of a level is tested with one evaluation of the series at all their
    midpoints (:meth:`Piece.values_and_slopes`), and the roots of all monotone segments are
    bisected together (:func:`bisect_roots`). The same tests as the recursive ``visit``, so the
    same segments; the work is (number of intervals) × (terms), in a few numpy calls per level."""
    segs = []
    brackets = []                 # (index in segs, lo, hi, f(lo)) of the roots to bisect
    f = p.value
    todo = [(p.phi0, p.phi1, f(p.phi0), f(p.phi1), 0)]
    while todo:
        mids = [0.5 * (lo + hi) for lo, hi, *_ in todo]
        fms, dms = p.values_and_slopes(mids)
        nxt = []
        for (lo, hi, flo, fhi, depth), m, fm, dm in zip(todo, mids, fms.tolist(), dms.tolist()):
            r = 0.5 * (hi - lo)
            if abs(fm) - abs(dm) * r - 0.5 * L2 * r * r > err:
                s = 1 if fm > 0.0 else -1
                segs.append((lo, hi, s, s, None))
            elif abs(dm) - L2 * r > err1:
                s0, s1 = sign(flo), sign(fhi)
                if s0 * s1 < 0:
                    brackets.append((len(segs), lo, hi, flo))
                segs.append((lo, hi, s0, s1, None))
            elif (abs(fm) + abs(dm) * r + 0.5 * L2 * r * r <= err or depth >= 64
                    or not lo < m < hi):
                segs.append((lo, hi, 0, 0, None))
            else:
                nxt.append((lo, m, flo, fm, depth + 1))
                nxt.append((m, hi, fm, fhi, depth + 1))
        todo = nxt
    if brackets:
        roots = bisect_roots(p, [b[1] for b in brackets], [b[2] for b in brackets],
                             [b[3] for b in brackets])
        for (i, *_), root in zip(brackets, roots):
            segs[i] = segs[i][:4] + (root,)
    segs.sort(key=lambda seg: seg[0])
    return segs


def bisect_roots(p: Piece, lo, hi, flo) -> list[float]:
    """:func:`bisect_root` of the piece's moment on many brackets at once (a long series: one
    evaluation of the series at all the brackets' midpoints per step); each bracket takes the
    same steps as :func:`bisect_root` alone."""
    import numpy as np

    lo, hi, flo = (np.array(v, dtype=float) for v in (lo, hi, flo))
    out = np.full_like(lo, np.nan)
    active = np.arange(len(lo))
    for _ in range(200):
        if not len(active):
            break
        l, h = lo[active], hi[active]
        mid = 0.5 * (l + h)
        stuck = (mid <= l) | (mid >= h)
        out[active[stuck]] = mid[stuck]
        active, mid = active[~stuck], mid[~stuck]
        fm = p.values_and_slopes(mid)[0]
        zero = fm == 0.0
        out[active[zero]] = mid[zero]
        active, mid, fm = active[~zero], mid[~zero], fm[~zero]
        same = (fm < 0.0) == (flo[active] < 0.0)
        lo[active[same]], flo[active[same]] = mid[same], fm[same]
        hi[active[~same]] = mid[~same]
    out[active] = 0.5 * (lo[active] + hi[active])
    return out.tolist()


def crossings(p: Piece) -> list[float]:
    """Angles inside (phi0, phi1) where the piece's moment changes sign [rad].

    Linear: the exact root of m0 + slope·(φ − φ0) = 0. With harmonics: certified subdivision
    by Taylor bounds on f and f′, then bisection to machine precision (see
    ``_harmonic_crossings``); close clusters of roots are all found, and a touching zero
    without a sign change is no extremum, so it is not reported.

    >>> crossings(Piece(math.pi / 2, math.pi, 15.0, -120.0 / math.pi))[0] / math.pi   # 5π/8
    0.625
    >>> [round(math.degrees(x), 3) for x in crossings(Piece(0, 2 * math.pi, 0, 0,
    ...                                                      ((1, 0.999, 0), (2, 0.5, 0))))]
    [177.437, 180.0, 182.563]
    """
    if not p.harmonics:
        m1 = p.m0 + p.slope * (p.phi1 - p.phi0)
        if (p.m0 < 0.0 < m1) or (m1 < 0.0 < p.m0):
            return [p.phi0 - p.m0 / p.slope]
        return []
    return _harmonic_crossings(p)


def derivative_piece(p: Piece) -> Piece:
    """dM/dφ of a piece as a piece of the same form [N·m/rad]::

        slope + Σ k·(a·cos kφ − b·sin kφ) = slope + Σ ((−k·b)·sin kφ + (k·a)·cos kφ)

    >>> derivative_piece(Piece(0.0, 1.0, 5.0, 2.0, ((2.0, 3.0, 4.0),)))
    Piece(phi0=0.0, phi1=1.0, m0=2.0, slope=0.0, harmonics=((2.0, -8.0, 6.0),))
    """
    return Piece(p.phi0, p.phi1, p.slope, 0.0,
                 tuple((k, -k * b, k * a) for k, a, b in p.harmonics))


def stationary_points(p: Piece) -> list[float]:
    """Angles inside (phi0, phi1) where the piece's moment has a local extreme [rad]: the sign
    changes of dM/dφ (:func:`derivative_piece`), found by the same certified subdivision and
    bisection as :func:`crossings`. A linear piece has none (its extremes are its ends); a point
    where dM/dφ only touches 0 (an inflection) is no extreme and is not reported.

    Khurmi & Gupta, *Theory of Machines*, Example 16.12: 600·sin 2φ − 500·sin φ is stationary
    where 24·cos²φ − 5·cos φ − 12 = 0, cos φ = (5 ± √1177)/48, i.e. at 35.03°, 127.63° and
    their mirror images 232.37°, 324.97°:

    >>> p = Piece(0.0, 2 * math.pi, 0.0, 0.0, ((1.0, -500.0, 0.0), (2.0, 600.0, 0.0)))
    >>> [round(math.degrees(x), 2) for x in stationary_points(p)]
    [35.03, 127.63, 232.37, 324.97]
    """
    if not p.harmonics:
        return []
    return crossings(derivative_piece(p))


__all__ = ["bisect_root", "crossings", "derivative_piece", "stationary_points"]
