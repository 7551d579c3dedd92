"""Task 2: steady motion of a machine with constant reduced inertia under given moment graphs.

The problem (seed ``002_10afb132413d2537.txt``, «Задача 2»; R.S. Khurmi & J.K. Gupta,
*Theory of Machines*, ch. 16 "Turning Moment Diagrams and Flywheel"): the forces and masses of a
machine are reduced to one link with constant moment of inertia ``J`` [kg·m²]; the driving moment
``M_D(φ)`` and the resistance moment ``M_C(φ)`` [N·m] are given as graphs over one cycle of
length ``Φ`` [rad]. The kinetic-energy theorem on ``[0, φ]``::

    ½·J·(ω(φ)² − ω0²) = A(φ) = ∫₀^φ (M_D − M_C) dφ

gives the speed ``ω(φ)`` [rad/s]. Every piece is integrated in closed form (linear pieces and
harmonic series ``a0 + Σ (a_k·sin kφ + b_k·cos kφ)``); there is no numerical quadrature.
``ω`` is extreme where ``A`` is, i.e. at the sign changes of ``M_D − M_C``: at the breakpoints of
the graphs (jumps) and at the crossings inside a piece, which are found exactly (linear pieces)
or by a certified subdivision (Taylor bounds on the moment and its derivative, so no cluster
of close roots is missed) and bisection to machine precision (harmonic pieces).

Results (all SI): ``ω_max``, ``ω_min`` and their angles; ``ω_ср = (ω_max + ω_min)/2``;
``δ = (ω_max − ω_min)/ω_ср``; ``ΔT_нб = A_max − A_min`` [J]. Because
``ω_max² − ω_min² = 2·ΔT_нб/J``, the exact relations ``δ = ΔT_нб/(J·ω_ср²)`` and
``J = ΔT_нб/(δ·ω_ср²)`` hold (the textbook's ``ΔE = I·ω²·C_s`` is exact with ``ω = ω_ср``).

The seed divides by ω0 instead of ω_ср, places the crossings of its triangle at
``π/2 + (2/π)·M_D/M_C`` (they are at 5π/8 and 11π/8) and prints ``ω4 = ω5 = 199.91``
(the true minimum is 199.98896 rad/s at 11π/8); its ``M_C = 60 N·m`` is right.

Pure functions on plain floats (``math`` only): importing this module is cheap.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Sequence

from flywheel.errors import InputError

TWO_PI = 2.0 * math.pi

# relative tolerance of the cycle balance (steady motion) and of the sum of areas
BALANCE_RTOL = 1e-9


# -- graphs -------------------------------------------------------------------------------------

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

    def value(self, phi: float) -> float:
        """M(φ) [N·m] (the formula of this piece, also outside its interval)."""
        m = self.m0 + self.slope * (phi - self.phi0)
        for k, a, b in self.harmonics:
            m += a * math.sin(k * phi) + b * math.cos(k * phi)
        return m

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
        for k, a, b in self.harmonics:
            w += (a * (math.cos(k * self.phi0) - math.cos(k * phi))
                  + b * (math.sin(k * phi) - math.sin(k * self.phi0))) / k
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
        """M(φ) [N·m]; at a jump the value just after (``side=+1``) or before (``-1``)."""
        pcs = self.pieces
        if side > 0:
            for p in pcs:
                if phi < p.phi1:
                    return p.value(phi)
            return pcs[-1].value(phi)
        for p in reversed(pcs):
            if phi > p.phi0:
                return p.value(phi)
        return pcs[0].value(phi)

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
        raise InputError("a graph needs at least two points")
    for i in range(1, len(pts)):
        if pts[i][0] < pts[i - 1][0]:
            raise InputError(
                f"graph angles must not decrease: point {i} at {math.degrees(pts[i][0]):g}° "
                f"comes after {math.degrees(pts[i - 1][0]):g}°")
    scale = max(cycle, 1.0) * 1e-12
    if abs(pts[0][0]) > scale or abs(pts[-1][0] - cycle) > scale:
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
        raise InputError("the graph has no length")
    if nominal is None:
        nominal = max(m for _, m in pts)
    return Moment(tuple(pieces), cycle, float(nominal), kind)


def _check_span(start: float, end: float, cycle: float) -> None:
    if not (0.0 <= start < end <= cycle * (1 + 1e-12)):
        raise InputError(
            f"the graph's interval {math.degrees(start):g}…{math.degrees(end):g}° must satisfy "
            f"0 ≤ from < to ≤ {math.degrees(cycle):g}°")


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
    _check_span(start, end, cycle)
    apex = 0.5 * (start + end) if apex is None else apex
    if not start <= apex <= end:
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
    _check_span(start, end, cycle)
    return piecewise_linear(_frame(start, [(start, peak), (end, peak)], end, cycle, base),
                            cycle, nominal=peak, kind="rectangle")


def trapezoid(peak: float, start: float, top_start: float, top_end: float, end: float,
              cycle: float = TWO_PI, base: float = 0.0) -> Moment:
    """``base`` → ``peak`` linearly on [start, top_start], ``peak`` on [top_start, top_end],
    back to ``base`` on [top_end, end]. Angles [rad] (Khurmi & Gupta, Example 16.6).
    """
    _check_cycle(cycle)
    _check_span(start, end, cycle)
    if not start <= top_start <= top_end <= end:
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
        raise InputError(f"{len(ks)} orders given for {n} harmonic terms")
    if any(not (k > 0) for k in ks):
        raise InputError("harmonic orders must be positive")
    terms = tuple((float(k), float(ak), float(bk)) for k, ak, bk in zip(ks, a, b)
                  if ak != 0.0 or bk != 0.0)
    return Moment((Piece(0.0, cycle, float(a0), 0.0, terms),), cycle, float(a0), "harmonic")


# -- the net moment and its crossings -------------------------------------------------------------

def _sub_piece(p: Piece, x0: float, x1: float) -> Piece:
    return Piece(x0, x1, p.linear_at(x0), p.slope, p.harmonics)


def net_pieces(M_D: Moment, M_C: Moment) -> list[Piece]:
    """``M_D − M_C`` as pieces on the merged breakpoints of both graphs."""
    if abs(M_D.cycle - M_C.cycle) > 1e-12 * M_D.cycle:
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


def _bisect(f: Callable[[float], float], lo: float, hi: float, flo: float) -> float:
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
        fm, dm = f(m), _derivative(p, m)
        if abs(fm) - abs(dm) * r - 0.5 * L2 * r * r > err:          # no zero here
            s = 1 if fm > 0.0 else -1
            segs.append((lo, hi, s, s, None))
            return
        if abs(dm) - L2 * r > err1:                                  # monotone
            s0, s1 = sign(flo), sign(fhi)
            root = _bisect(f, lo, hi, flo) if s0 * s1 < 0 else None
            segs.append((lo, hi, s0, s1, root))
            return
        if (abs(fm) + abs(dm) * r + 0.5 * L2 * r * r <= err or depth >= 64
                or not lo < m < hi):                                 # f ≈ 0 to round-off
            segs.append((lo, hi, 0, 0, None))
            return
        visit(lo, m, flo, fm, depth + 1)
        visit(m, hi, fm, fhi, depth + 1)

    visit(p.phi0, p.phi1, f(p.phi0), f(p.phi1), 0)

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
            roots.append(_bisect(f, lo, hi, flo) if flo * fhi < 0.0 else 0.5 * (lo + hi))
        last, unknown = s, []

    for lo, hi, s0, s1, root in segs:
        see(lo, s0)
        if root is not None:
            roots.append(root)
            last, unknown = s1, []
        see(hi, s1)
    return [r for r in roots if p.phi0 < r < p.phi1]


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


# -- the motion ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class Row:
    """One line of the segment table: a bound of a segment or a crossing M_D = M_C.

    phi [rad]; M_D, M_C [N·m] on the segment that starts here (at the cycle end: before it),
    None for a diagram given by areas; A = ∫₀^φ (M_D − M_C) dφ [J]; omega [rad/s].
    """

    phi: float
    kind: str  # "bound" | "crossing"
    M_D: float | None
    M_C: float | None
    A: float
    omega: float


@dataclass(frozen=True)
class Task2Result:
    """Everything task 2 reports; SI units (angles in rad, speeds in rad/s, energies in J)."""

    cycle: float
    J: float                     # reduced moment of inertia used for the motion [kg·m²]
    omega0: float                # ω at φ = 0 [rad/s]
    omega_max: float
    omega_min: float
    omega_mean: float            # (ω_max + ω_min)/2
    delta: float                 # (ω_max − ω_min)/ω_ср
    phi_omega_max: float | None  # [rad]; None if the diagram gives no angles
    phi_omega_min: float | None
    delta_T_max: float           # ΔT_нб = A_max − A_min [J]
    rows: tuple[Row, ...]
    steady: bool = True
    omega_end: float = 0.0       # ω after one cycle [rad/s]
    work_end: float = 0.0        # A(Φ) [J]; 0 for steady motion
    M_D: float | None = None     # nominal driving moment (constant/peak/a0) [N·m]
    M_C: float | None = None     # nominal resistance moment (the seed's peak) [N·m]
    unknown: str | None = None   # which moment the balance found: "driving" | "resistance"
    work_driving: float | None = None     # ∮ M_D dφ [J]
    work_resistance: float | None = None  # ∮ M_C dφ [J]
    power: float | None = None   # mean driving moment × ω_ср [W]
    J_required: float | None = None       # J for delta_target at the same ω_ср [kg·m²]
    delta_target: float | None = None
    rim_radius: float | None = None       # mean radius of a rim [m]
    rim_mass: float | None = None         # m = J/R² [kg]
    driving: Moment | None = field(default=None, repr=False)
    resistance: Moment | None = field(default=None, repr=False)


def balance(make_D: Callable[[float], Moment], make_C: Callable[[float], Moment],
            unknown: str) -> float:
    """The unknown parameter x of one graph (a constant, a peak, a scale) from the cycle
    balance ∮ M_D dφ = ∮ M_C dφ (steady motion; seed 002: M_D·2π = M_C·π/2).

    The work of a graph is affine in x, so x = (W_other − W(0))/(W(1) − W(0)); x = 0 when
    W_other − W(0) is round-off (within 1e-9 of the graphs' ``size``). Raises InputError when
    no positive x balances the cycle.

    >>> balance(lambda x: constant(15.0), lambda x: triangle(x, math.pi/2, 3*math.pi/2),
    ...         "resistance")
    60.0
    """
    if unknown == "resistance":
        known, make = make_D(1.0), make_C
    elif unknown == "driving":
        known, make = make_C(1.0), make_D
    else:
        raise InputError(f"unknown moment must be 'driving' or 'resistance' (got {unknown!r})")
    other = known.work()
    w0, w1 = make(0.0).work(), make(1.0).work()
    if w1 == w0:
        raise InputError(f"the {unknown} moment's unknown value does not change its work: "
                         "the cycle balance cannot find it")
    # a net work within round-off of zero (zero-mean harmonics leave 1e-13 J) balances with
    # x = 0; the same tolerance as the steadiness test of ``solve``
    if math.isfinite(other - w0) and \
            abs(other - w0) <= BALANCE_RTOL * (size(known) + size(make(0.0))):
        return 0.0
    x = (other - w0) / (w1 - w0)
    x = float(round(x, 12)) if abs(x - round(x, 12)) < 1e-12 * max(1.0, abs(x)) else x
    x += 0.0    # no −0.0
    if not math.isfinite(x):
        raise OverflowError(f"the cycle balance gives a {unknown} moment of {x!r} N·m")
    if x < 0.0:
        raise InputError(
            f"the cycle balance needs a negative {unknown} moment ({x:.6g} N·m): "
            f"the {'resistance' if unknown == 'driving' else 'driving'} graph does "
            f"{'more' if unknown == 'resistance' else 'less'} work than the "
            f"{unknown} graph can {'absorb' if unknown == 'resistance' else 'supply'}")
    return x


def _speed_from_mean(A_max: float, A_min: float, J: float, omega_mean: float) -> float:
    """ω0² from the mean speed: ω_max + ω_min = 2ω_ср and ω_max² − ω_min² = 2ΔT/J give
    ω_max = ω_ср + ΔT/(2Jω_ср); then ω0² = ω_max² − 2A_max/J."""
    dT = A_max - A_min
    w_max = omega_mean + dT / (2 * J * omega_mean)
    w_min = omega_mean - dT / (2 * J * omega_mean)
    if w_min <= 0.0:
        raise InputError(
            f"J = {J:.6g} kg·m² is too small for a mean speed of {omega_mean:.6g} rad/s: the "
            f"energy fluctuation {dT:.6g} J would stop the machine")
    return w_max * w_max - 2 * A_max / J


def _check_positive(name: str, value: float | None, unit: str) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise InputError(f"{name} must be positive (got {value:g} {unit})")


def _stop_angle(pieces: list[Piece], A_start: list[float], J: float, w0sq: float) -> float:
    """First φ where ω² = ω0² + 2A/J reaches zero (A is monotonic between table rows)."""
    target = -0.5 * J * w0sq
    for p, a0 in zip(pieces, A_start):
        pts = [p.phi0, *crossings(p), p.phi1]
        for x0, x1 in zip(pts, pts[1:]):
            f0 = a0 + p.work(x0) - target
            f1 = a0 + p.work(x1) - target
            if f1 <= 0.0:
                if f0 <= 0.0:
                    return x0
                return _bisect(lambda x: a0 + p.work(x) - target, x0, x1, f0)
    return pieces[-1].phi1


def _motion(bounds: list[float], kinds: list[str], A: list[float], J: float | None,
            omega0: float | None, omega_mean: float | None, steady: bool,
            delta: float | None, angles_known: bool = True,
            stop: Callable[[float, float], float] | None = None) -> dict:
    """ω at each row and the summary numbers (shared by graphs and area diagrams).

    Raises OverflowError when a work is not finite (moments near the limit of double
    precision): no extreme can be chosen among infinities.
    """
    if not all(math.isfinite(a) for a in A):
        raise OverflowError("the work A(φ) is not finite")
    # the first of equal extremes (equal to 1e-12 of the swing: round-off must not choose)
    tol = 1e-12 * (max(A) - min(A))
    i_max = next(i for i, a in enumerate(A) if a >= max(A) - tol)
    i_min = next(i for i, a in enumerate(A) if a <= min(A) + tol)
    A_max, A_min = max(A), min(A)
    dT = A_max - A_min
    if J is None:
        if delta is None:
            raise InputError("give the flywheel: J, or mass and radius of gyration, or δ")
        if omega_mean is None:
            raise InputError("to find J from δ give the mean speed, not ω0")
        if dT <= 0.0:
            raise InputError("the energy does not fluctuate: any J gives δ = 0")
        J = dT / (delta * omega_mean ** 2)
    if omega_mean is not None:
        if not steady:
            raise InputError("a mean speed needs steady motion (the work over the cycle "
                             f"is {A[-1]:.6g} J, not 0): give ω0 instead")
        w0sq = _speed_from_mean(A_max, A_min, J, omega_mean)
    else:
        w0sq = omega0 * omega0
    wsq = [w0sq + 2 * a / J for a in A]
    if min(wsq) <= 0.0:
        i = next(i for i, w in enumerate(wsq) if w <= 0.0)
        where = (f"at φ = {math.degrees(stop(J, w0sq)):.6g}°" if stop is not None
                 else f"before row {i}")
        raise InputError(f"the machine stops {where}: the kinetic energy "
                         f"½·J·ω0² = {0.5 * J * w0sq:.6g} J cannot cover the deficit "
                         f"{-min(A):.6g} J")
    omega = [math.sqrt(w) for w in wsq]
    w_max, w_min = omega[i_max], omega[i_min]
    if omega_mean is not None:       # exact, free of round-off in the square roots
        w_mean = omega_mean
        diff = dT / (J * omega_mean)
    else:
        w_mean = 0.5 * (w_max + w_min)
        diff = 2 * dT / (J * (w_max + w_min))
    out = dict(J=J, omega0=math.sqrt(w0sq), omega_max=w_max, omega_min=w_min,
               omega_mean=w_mean, delta=diff / w_mean,
               phi_omega_max=bounds[i_max] if angles_known else None,
               phi_omega_min=bounds[i_min] if angles_known else None,
               delta_T_max=dT, omega_end=omega[-1], omega=omega, steady=steady,
               work_end=A[-1])
    return out


def _finish(res: dict, delta: float | None, rim_radius: float | None) -> dict:
    if delta is not None:
        res["delta_target"] = delta
        res["J_required"] = res["delta_T_max"] / (delta * res["omega_mean"] ** 2)
    if rim_radius is not None:
        J_rim = res.get("J_required") or res["J"]
        res["rim_radius"] = rim_radius
        res["rim_mass"] = J_rim / rim_radius ** 2
    return res


def solve(M_D: Moment, M_C: Moment, J: float | None = None, *, omega0: float | None = None,
          omega_mean: float | None = None, delta: float | None = None,
          rim_radius: float | None = None, unknown: str | None = None) -> Task2Result:
    """Steady (or not) motion under M_D(φ), M_C(φ) with constant J.

    Parameters: ``M_D``, ``M_C`` graphs [N·m over rad]; ``J`` [kg·m²] (None: found from
    ``delta`` at ``omega_mean``); exactly one of ``omega0`` (ω at φ = 0) or ``omega_mean``
    (ω_ср, steady motion only) [rad/s]; ``delta`` asks for the J giving that δ at the same
    ω_ср; ``rim_radius`` [m] asks for the rim mass m = J/R².

    The motion is steady when ∮ (M_D − M_C) dφ = 0 (to 1e-9 of ∮(|M_D| + |M_C|) dφ, see
    ``size``); otherwise ω_end after one cycle differs from ω0.

    >>> r = solve(constant(15.0), triangle(60.0, math.pi/2, 3*math.pi/2), 12.0, omega0=200.0)
    >>> [round(math.degrees(x.phi), 6) for x in r.rows]
    [0.0, 90.0, 112.5, 180.0, 247.5, 270.0, 360.0]
    >>> round(r.omega_max, 6), round(r.omega_min, 6), f"{r.delta:.6g}"
    (200.011044, 199.988955, '0.000110447')
    """
    if (omega0 is None) == (omega_mean is None):
        raise InputError("give exactly one speed: ω0 or the mean speed")
    _check_positive("J", J, "kg·m²")
    _check_positive("ω0", omega0, "rad/s")
    _check_positive("the mean speed", omega_mean, "rad/s")
    _check_positive("the rim radius", rim_radius, "m")
    if delta is not None and not (0.0 < delta < 2.0):
        raise InputError(f"δ must lie between 0 and 2 (got {delta:g})")
    pieces = net_pieces(M_D, M_C)
    bounds: list[float] = []
    kinds: list[str] = []
    A: list[float] = []
    A_start: list[float] = []
    acc = 0.0
    for p in pieces:
        A_start.append(acc)
        bounds.append(p.phi0)
        kinds.append("bound")
        A.append(acc)
        for x in crossings(p):
            bounds.append(x)
            kinds.append("crossing")
            A.append(acc + p.work(x))
        acc += p.work(p.phi1)
    bounds.append(pieces[-1].phi1)
    kinds.append("bound")
    W_D, W_C = M_D.work(), M_C.work()
    # relative to the size of the moments (``size``), not to W_D, W_C: zero-mean moments
    # have works of pure round-off and are steady all the same
    scale = max(abs(W_D), abs(W_C), size(M_D) + size(M_C), 1e-300)
    steady = abs(acc) <= BALANCE_RTOL * scale
    if steady:
        acc = 0.0
    A.append(acc)
    res = _motion(bounds, kinds, A, J, omega0, omega_mean, steady, delta,
                  stop=lambda J_, w0sq: _stop_angle(pieces, A_start, J_, w0sq))
    omega = res.pop("omega")
    rows = tuple(Row(x, k, M_D.value(x, +1 if i < len(bounds) - 1 else -1),
                     M_C.value(x, +1 if i < len(bounds) - 1 else -1), a, w)
                 for i, (x, k, a, w) in enumerate(zip(bounds, kinds, A, omega)))
    res = _finish(res, delta, rim_radius)
    power = (W_D / M_D.cycle) * res["omega_mean"] if steady else None
    return Task2Result(rows=rows, cycle=M_D.cycle, M_D=M_D.nominal, M_C=M_C.nominal,
                       unknown=unknown, work_driving=W_D, work_resistance=W_C, power=power,
                       driving=M_D, resistance=M_C, **res)


def solve_areas(energies: Sequence[float], J: float | None = None, *, cycle: float = TWO_PI,
                omega0: float | None = None, omega_mean: float | None = None,
                delta: float | None = None, rim_radius: float | None = None,
                crossings_at: Sequence[float] | None = None) -> Task2Result:
    """A turning-moment diagram given by the signed areas between its crossings with the mean
    line (Khurmi & Gupta, §16.5): ``energies`` [J] in order, positive above the mean line.

    The energy at the n-th crossing is the running sum; ΔT_нб = max − min of the running sums
    (with the start). The areas of a cycle sum to zero. ``crossings_at`` [rad], n + 1 angles
    from the start of the first area to the end of the last, label the rows; without them
    the angles of ω_max and ω_min are unknown (None).

    >>> r = solve_areas([295.0, -685.0, 40.0, -340.0, 960.0, -270.0], J=1.0, omega_mean=100.0)
    >>> r.delta_T_max
    985.0
    """
    _check_positive("J", J, "kg·m²")
    _check_positive("ω0", omega0, "rad/s")
    _check_positive("the mean speed", omega_mean, "rad/s")
    if (omega0 is None) == (omega_mean is None):
        raise InputError("give exactly one speed: ω0 or the mean speed")
    if delta is not None and not (0.0 < delta < 2.0):
        raise InputError(f"δ must lie between 0 and 2 (got {delta:g})")
    e = [float(x) for x in energies]
    if len(e) < 2:
        raise InputError("a diagram needs at least two areas")
    total, size = math.fsum(e), math.fsum(abs(x) for x in e)
    if abs(total) > BALANCE_RTOL * size:
        raise InputError(f"the areas sum to {total:.6g}, not 0: over a cycle of steady motion "
                         "the areas above and below the mean line are equal")
    A = [0.0]
    for x in e[:-1]:
        A.append(A[-1] + x)
    A.append(0.0)
    if crossings_at is not None:
        bounds = [float(x) for x in crossings_at]
        if len(bounds) != len(e) + 1:
            raise InputError(f"{len(e)} areas need {len(e) + 1} crossing angles "
                             f"(got {len(bounds)})")
        if any(b1 <= b0 for b0, b1 in zip(bounds, bounds[1:])):
            raise InputError("crossing angles must increase")
    else:
        bounds = [cycle * i / len(e) for i in range(len(e) + 1)]
    res = _motion(bounds, ["crossing"] * len(A), A, J, omega0, omega_mean, True, delta,
                  angles_known=crossings_at is not None)
    omega = res.pop("omega")
    rows = tuple(Row(x if crossings_at is not None else math.nan, "crossing", None, None, a, w)
                 for x, a, w in zip(bounds, A, omega))
    res = _finish(res, delta, rim_radius)
    return Task2Result(rows=rows, cycle=cycle, **res)


# the reported numbers, in the order of the JSON document (flywheel.render.task2.to_dict)
_REPORTED = ("omega_max", "omega_min", "omega_mean", "delta", "phi_omega_max", "phi_omega_min",
             "delta_T_max", "M_C", "J_required", "M_D", "J", "omega0", "omega_end", "work_end",
             "work_driving", "work_resistance", "power", "delta_target", "rim_radius",
             "rim_mass")


def nonfinite(result: Task2Result) -> str | None:
    """``"name = inf"`` for the first reported number that is inf or NaN, else None.

    Inputs near the limits of double precision (a moment of 1e308 N·m, ω0 = 1e200 rad/s) make
    the formulas overflow; the caller turns this into one error line instead of printing
    Infinity/NaN (which is not JSON). The rpm equivalents n = 30·ω/π are checked too. A row's
    angle may be NaN by design (an area diagram without crossing angles), so only an infinite
    angle counts.

    >>> nonfinite(seed_task("triangle")) is None
    True
    """
    def bad(x) -> bool:
        return isinstance(x, float) and not math.isfinite(x)

    for name in _REPORTED:
        v = getattr(result, name)
        if bad(v) and not (name.startswith("phi_") and math.isnan(v)):
            return f"{name} = {v!r}"
    for name in ("omega0", "omega_max", "omega_min", "omega_mean"):
        if bad(getattr(result, name) * (30.0 / math.pi)):
            return f"rpm.{name} = inf"
    for i, row in enumerate(result.rows):
        if math.isinf(row.phi):
            return f"segments[{i}].phi = {row.phi!r}"
        for name in ("M_D", "M_C", "A", "omega"):
            if bad(getattr(row, name)):
                return f"segments[{i}].{name} = {getattr(row, name)!r}"
    return None


# -- seed 002 -----------------------------------------------------------------------------------

SEED_DEFAULTS = {"M_D": 15.0, "J": 12.0, "omega0": 200.0}
SEED_SPANS_DEG = {"triangle": (90.0, 270.0), "rectangle": (90.0, 180.0)}


def seed_task(profile: str = "triangle", *, M_D: float = 15.0, J: float = 12.0,
              omega0: float = 200.0, start: float | None = None, end: float | None = None,
              M_C: float | None = None, delta: float | None = None) -> Task2Result:
    """Seed 002 («Задача 2»): constant driving moment ``M_D`` [N·m], resistance a triangle
    (peak in the middle) or a rectangle on [start, end] [rad] (defaults π/2…3π/2 and
    π/2…π); J [kg·m²]; ω0 [rad/s] at φ = 0. Without ``M_C`` its peak comes from the balance
    (60 N·m in both seed tasks); with it the motion need not be steady.

    >>> round(seed_task("rectangle").omega_min, 6)   # seed: 199.98
    199.980363
    """
    if profile not in SEED_SPANS_DEG:
        raise InputError(f"profile must be triangle or rectangle (got {profile!r})")
    d0, d1 = SEED_SPANS_DEG[profile]
    start = math.radians(d0) if start is None else start
    end = math.radians(d1) if end is None else end
    if not start < end:
        raise InputError(f"from ({math.degrees(start):g}°) must be less than to "
                         f"({math.degrees(end):g}°)")
    if start < 0 or end > TWO_PI * (1 + 1e-12):
        raise InputError(f"from and to must lie within 0…360° (got {math.degrees(start):g}°, "
                         f"{math.degrees(end):g}°)")
    _check_positive("M_D", M_D, "N·m")
    _check_positive("J", J, "kg·m²")
    _check_positive("ω0", omega0, "rad/s")
    shape = triangle if profile == "triangle" else rectangle
    drive = constant(M_D)
    unknown = None
    if M_C is None:
        M_C = balance(lambda x: drive, lambda x: shape(x, start, end), "resistance")
        unknown = "resistance"
    else:
        _check_positive("M_C", M_C, "N·m")
    return solve(drive, shape(M_C, start, end), J, omega0=omega0, delta=delta,
                 unknown=unknown)


def sample(result: Task2Result, n: int = 1441) -> dict[str, list[float]]:
    """Curves for plotting: φ [rad], M_D, M_C [N·m], A [J], ω [rad/s] on n + the table's points.

    Only for results from graphs (``solve``); an area diagram has no curves between rows.
    """
    if result.driving is None or result.resistance is None:
        raise InputError("a diagram given by areas has no moment curves to sample")
    pieces = net_pieces(result.driving, result.resistance)
    xs = sorted({result.cycle * i / (n - 1) for i in range(n)} | {r.phi for r in result.rows})
    A_start, acc = [], 0.0
    for p in pieces:
        A_start.append(acc)
        acc += p.work(p.phi1)
    out: dict[str, list[float]] = {"phi": [], "M_D": [], "M_C": [], "A": [], "omega": []}
    j = 0
    w0sq = result.omega0 ** 2
    for x in xs:
        while j < len(pieces) - 1 and x >= pieces[j].phi1:
            j += 1
        a = A_start[j] + pieces[j].work(x)
        out["phi"].append(x)
        out["M_D"].append(result.driving.value(x))
        out["M_C"].append(result.resistance.value(x))
        out["A"].append(a)
        out["omega"].append(math.sqrt(max(w0sq + 2 * a / result.J, 0.0)))
    return out


__all__ = ["Piece", "Moment", "Row", "Task2Result", "constant", "piecewise_linear", "triangle",
           "rectangle", "trapezoid", "harmonic", "net_pieces", "crossings", "balance", "solve",
           "solve_areas", "seed_task", "sample", "size", "nonfinite"]
