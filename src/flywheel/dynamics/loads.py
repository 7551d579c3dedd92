"""Loads on the φ grid: gas forces from indicator diagrams, technological forces, gravity.

Pure functions on arrays (SI). Sign convention: a force vector F [N] on a point with velocity
analogue v_q [m/rad] has the reduced moment M = F·v_q [N·m] (design.md §2), positive when it
drives the crank.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class LoadKey:
    """A load's key in the reduced moments and works (``LoadsResult.M_parts``, ``W_parts``):
    its ``kind`` — "gas", "force", "gravity", "couple", "spring", "moment" (a tabulated case's
    given moment) — and its ``name`` (a cylinder's, a force's, a link's, …). Its text
    "kind name" is the spelling of table.csv's columns ("M gas HP") and of summary.json's
    moments, unchanged; renderers read ``kind`` and ``name``, never split the text.

    >>> str(LoadKey("gas", "HP")), LoadKey.parse("gravity 2")
    ('gas HP', LoadKey(kind='gravity', name='2'))
    """

    kind: str
    name: str

    def __str__(self) -> str:
        return f"{self.kind} {self.name}"

    @classmethod
    def parse(cls, text: str) -> "LoadKey":
        """The key of the text "kind name" (a column's family member, a message's parameter)."""
        kind, _, name = text.partition(" ")
        return cls(kind, name)


def natural_spline(x: np.ndarray, y: np.ndarray, xq: np.ndarray) -> np.ndarray:
    """Natural cubic spline through (x, y) evaluated at xq (second derivative 0 at both ends).

    This is Mathcad's ``lspline`` + ``interp`` (seed 000, §3.2.2; seeds README, defect 1):
    the spline's second derivatives M_i solve
    h_{i−1}·M_{i−1} + 2(h_{i−1} + h_i)·M_i + h_i·M_{i+1} = 6·(Δ_i − Δ_{i−1}), M_0 = M_n = 0,
    with Δ_i = (y_{i+1} − y_i)/h_i. Written with numpy because importing scipy.interpolate costs
    0.7 s per run; the tests check it against scipy's CubicSpline(bc_type="natural").

    >>> natural_spline(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 0.0]), np.array([0.5, 1.0]))
    array([0.6875, 1.    ])
    """
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    h = np.diff(x)
    slope = np.diff(y) / h
    n = x.size
    M = np.zeros(n)
    if n > 2:
        A = np.zeros((n - 2, n - 2))
        idx = np.arange(n - 2)
        A[idx, idx] = 2 * (h[:-1] + h[1:])
        A[idx[1:], idx[:-1]] = h[1:-1]
        A[idx[:-1], idx[1:]] = h[1:-1]
        M[1:-1] = np.linalg.solve(A, 6 * np.diff(slope))
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, n - 2)
    t = xq - x[i]
    hi = h[i]
    b = slope[i] - hi * (2 * M[i] + M[i + 1]) / 6
    return y[i] + b * t + M[i] / 2 * t**2 + (M[i + 1] - M[i]) / (6 * hi) * t**3


def pchip(x: np.ndarray, y: np.ndarray, xq: np.ndarray) -> np.ndarray:
    """The monotone piecewise cubic Hermite interpolant (PCHIP) through (x, y) at xq in
    [x_0, x_n] — Fritsch & Carlson, "Monotone piecewise cubic interpolation", SIAM J. Numer.
    Anal. 17 (1980), with the weighted harmonic mean of the neighbouring slopes at the inner
    nodes (Fritsch & Butland 1984) and Moler's one-sided three-point ends (Numerical Computing
    with MATLAB, § 3.6, pchiptx.m): at an inner node d_k = 0 where the slopes m_{k−1}, m_k
    differ in sign or one is 0, else (w1 + w2)/d_k = w1/m_{k−1} + w2/m_k, w1 = 2h_k + h_{k−1},
    w2 = h_k + 2h_{k−1}. Each piece y_i + d_i·t + c2·t² + c3·t³ (t = x − x_i), evaluated term by
    term as scipy's PPoly does, so the values are scipy's PchipInterpolator's to the last bit
    (the tests check it) without importing scipy.interpolate (0.3 – 0.7 s a run).

    >>> pchip(np.array([0.0, 1.0, 2.0]), np.array([0.0, 1.0, 1.0]), np.array([0.5, 1.5]))
    array([0.6875, 1.    ])
    """
    x, y, xq = (np.asarray(a, float) for a in (x, y, xq))
    h = np.diff(x)
    m = np.diff(y) / h
    if x.size == 2:                                # two points: the straight line
        d = np.array([m[0], m[0]])
    else:
        sm = np.sign(m)
        flat = (sm[1:] != sm[:-1]) | (m[1:] == 0) | (m[:-1] == 0)
        w1, w2 = 2 * h[1:] + h[:-1], h[1:] + 2 * h[:-1]
        with np.errstate(divide="ignore", invalid="ignore"):
            whmean = (w1 / m[:-1] + w2 / m[1:]) / (w1 + w2)
        d = np.zeros_like(y)
        d[1:-1][~flat] = 1.0 / whmean[~flat]

        def end(h0, h1, m0, m1) -> float:
            e = ((2 * h0 + h1) * m0 - h0 * m1) / (h0 + h1)
            if np.sign(e) != np.sign(m0):
                return 0.0
            if np.sign(m0) != np.sign(m1) and abs(e) > 3.0 * abs(m0):
                return 3.0 * m0
            return e

        d[0] = end(h[0], h[1], m[0], m[1])
        d[-1] = end(h[-1], h[-2], m[-1], m[-2])
    t = (d[:-1] + d[1:] - 2 * m) / h               # scipy's CubicHermiteSpline coefficients
    c3, c2 = t / h, (m - d[:-1]) / h - t
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, x.size - 2)
    u = xq - x[i]
    return ((0.0 + y[:-1][i]) + d[:-1][i] * u) + c2[i] * (u * u) + c3[i] * (u * u * u)


def interpolate_table(s: np.ndarray, p: np.ndarray, sq: np.ndarray, method: str) -> np.ndarray:
    """p/p_max of an indicator table (s, p) at relative travel sq ∈ [0, 1].

    method: 'linear' (np.interp), 'pchip' (the monotone cubic, no overshoot: :func:`pchip`) or
    'natural-spline' (Mathcad lspline: may overshoot and give small negative pressures).
    """
    sq = np.clip(sq, s[0], s[-1])
    if method == "linear":
        return np.interp(sq, s, p)
    if method == "pchip":
        return pchip(s, p, sq)
    if method == "natural-spline":
        return natural_spline(s, p, sq)
    # library use only: no CLI input reaches this
    raise ValueError(f"unknown interpolation {method!r}")


def relative_travel(x: np.ndarray, x_head: float, x_far: float) -> np.ndarray:
    """s = (x − x_head)/(x_far − x_head) ∈ [0, 1]: relative travel from the head dead centre
    (seed 000, §3.2.3: s5 = (l1 + l2 − Y_B)/(2·l1))."""
    return np.clip((x - x_head) / (x_far - x_head), 0.0, 1.0)


def gas_force(x: np.ndarray, x_dot: np.ndarray, x_head: float, x_far: float,
              s_table: np.ndarray, towards: np.ndarray, away: np.ndarray,
              p_max: float, bore: float, method: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Gas pressure p [Pa] and force magnitude F [N] on a piston, and the travel s.

    x [m]: piston position along its guide; x_dot = dx/dφ [m/rad]. The piston moves towards
    the head while x_dot·(x_head − x_far) > 0 (table ``towards``), else away (``away``)
    (seed 000, §3.2.4: P5 = pu2(s5)·P_max2 if V_qBy > 0, pd2 otherwise). F = p·π·d²/4 (§3.2.5).
    """
    s = relative_travel(x, x_head, x_far)
    toward_head = x_dot * (x_head - x_far) > 0
    ratio = np.where(toward_head, interpolate_table(s_table, towards, s, method),
                     interpolate_table(s_table, away, s, method))
    p = ratio * p_max
    return p, p * np.pi * bore**2 / 4, s


def gas_moment(F: np.ndarray, x_dot: np.ndarray, x_head: float, x_far: float) -> np.ndarray:
    """Reduced moment [N·m] of a gas force F [N] that pushes the piston away from its head:
    M = F·(unit vector head → far)·v_q = F·x_dot·sign(x_far − x_head)
    (seed 000, §3.2.6: M_PRFB = −F_B·V_qBy, the head of cylinder 2 being at the top)."""
    return F * x_dot * np.sign(x_far - x_head)


def technological_moment(x: np.ndarray, x_dot: np.ndarray, x_ref: float, x_other: float,
                         magnitude: float, s_range: tuple[float, float], stroke: str
                         ) -> tuple[np.ndarray, np.ndarray]:
    """A resistance force of ``magnitude`` [N] against the slider's motion while its relative
    travel s from the reference dead centre lies in ``s_range`` and it moves in ``stroke``
    ('towards' the reference, 'away' from it, or 'both'). Returns (F [N], M [N·m]),
    with M = −F·|x_dot| (a force opposing the velocity absorbs F·|v_q| per radian)."""
    s = relative_travel(x, x_ref, x_other)
    moving_away = x_dot * (x_other - x_ref) > 0
    on = (s >= s_range[0]) & (s <= s_range[1])
    if stroke == "towards":
        on &= ~moving_away
    elif stroke == "away":
        on &= moving_away
    F = np.where(on, magnitude, 0.0)
    return F, -F * np.abs(x_dot)


def technological_work(x: np.ndarray, x_ref: float, x_other: float, magnitude: float,
                       s_range: tuple[float, float], stroke: str) -> np.ndarray:
    """Cumulative work A(φ) [J] of the force of :func:`technological_moment`, exact on the grid:
    in each interval the slider moves one way (the dead centres are grid nodes), so the force
    does −F·(travel inside s_range) there, with the travel from the clipped ends
    s0, s1 ∈ [s_lo, s_hi]: −F·|x_other − x_ref|·|clip(s1) − clip(s0)|. The trapezoid rule on
    M = −F·|x_dot| is only first-order where the force switches on and off inside an interval.

    >>> x = np.array([0.0, 0.5, 1.0, 0.5, 0.0])        # a stroke out and back, stroke 1 m
    >>> technological_work(x, 0.0, 1.0, 100.0, (0.2, 0.6), "away")
    array([  0., -30., -40., -40., -40.])
    """
    s = relative_travel(x, x_ref, x_other)
    lo, hi = s_range
    sc = np.clip(s, lo, hi)
    moving_away = np.diff(s) > 0
    active = np.ones(moving_away.size, bool)
    if stroke == "towards":
        active = ~moving_away
    elif stroke == "away":
        active = moving_away
    dW = -magnitude * abs(x_other - x_ref) * np.abs(np.diff(sc)) * active
    return np.concatenate([[0.0], np.cumsum(dW)])


def travel_crossings(x: np.ndarray, x_bound: float) -> np.ndarray:
    """Indices i of the intervals [i, i+1] inside which x crosses ``x_bound`` (a position where
    a technological force switches on or off), for refining the grid."""
    d = x - x_bound
    return np.nonzero(d[:-1] * d[1:] < 0)[0]


def gravity_moment(mass: float, gravity: np.ndarray, v_q: np.ndarray) -> np.ndarray:
    """Reduced moment of a link's weight [N·m]: M = m·g⃗·v_qS (design.md §2). The seed projects
    v_qS on a direction that turns with the crank instead (seeds README, defect 5)."""
    return mass * (v_q @ np.asarray(gravity, float))


# -- four-stroke engines ---------------------------------------------------------------------

FOUR_STROKES = ("intake", "compression", "expansion", "exhaust")
"""The strokes of a four-stroke cylinder, in the order of its cycle (Φ = 4π): intake and
expansion move the piston away from the head, compression and exhaust towards it."""


def four_stroke_index(phi: np.ndarray, fires_at: float, far_after: float) -> np.ndarray:
    """Index into :data:`FOUR_STROKES` of the stroke at each crank angle φ [rad] of a cylinder
    that fires at ``fires_at`` [rad] (its head dead centre that begins expansion), with its far
    dead centre ``far_after`` [rad] after each head dead centre (π for a centric slider-crank).

    With ψ = (φ − φ_f) mod 4π the strokes are expansion [0, ψ_far), exhaust [ψ_far, 2π),
    intake [2π, 2π + ψ_far), compression [2π + ψ_far, 4π) (the four-stroke cycle, two
    revolutions, each stroke between dead centres; Артоболевский, «Теория механизмов и машин»,
    the indicator diagram of a four-stroke engine). A node on a dead centre gets one of the two
    strokes that meet there, never another.

    >>> four_stroke_index(np.radians([0, 90, 180, 270, 360, 450, 540, 630]), 0.0, np.pi).tolist()
    [2, 2, 3, 3, 0, 0, 1, 1]
    """
    psi = np.mod(np.asarray(phi, float) - fires_at, 4 * np.pi)
    rev2 = psi >= 2 * np.pi
    away = np.mod(psi, 2 * np.pi) < far_after
    return np.where(rev2, np.where(away, 0, 1), np.where(away, 2, 3))


def four_stroke_pressure(s: np.ndarray, stroke: np.ndarray,
                         tables: dict[str, tuple[np.ndarray, np.ndarray]], method: str) -> np.ndarray:
    """p/p_max [-] of a four-stroke cylinder at relative travel s ∈ [0, 1] from its head, each
    node read from the table of its stroke (``stroke``: index into :data:`FOUR_STROKES`, as
    :func:`four_stroke_index` gives; ``tables``: stroke name → (s, p/p_max) of that stroke,
    s increasing from 0 to 1), with the interpolation ``method`` of :func:`interpolate_table`.
    All four on the whole grid at once."""
    values = np.stack([interpolate_table(np.asarray(tables[name][0], float),
                                         np.asarray(tables[name][1], float), s, method)
                       for name in FOUR_STROKES])
    return np.take_along_axis(values, np.asarray(stroke)[None, :], axis=0)[0]


def stroke_joins(s_table, tables: dict[str, list[float]]) -> list[tuple[str, str, float, float, float]]:
    """Where the strokes of a four-stroke diagram meet at the dead centres: (stroke that ends,
    stroke that begins, s there, p/p_max at the end, p/p_max at the start), in the cycle's
    order — intake ends at s = 1 where compression begins, compression at s = 0 where expansion
    begins, expansion at s = 1 where exhaust begins, exhaust at s = 0 where intake begins.

    >>> t = {"intake": [0, 0], "compression": [1, 0.1], "expansion": [1, 0.2], "exhaust": [0.1, 0.3]}
    >>> [(a, b, p, q) for a, b, _, p, q in stroke_joins([0, 1], t)]
    [('intake', 'compression', 0, 0.1), ('compression', 'expansion', 1, 1), ('expansion', 'exhaust', 0.2, 0.3), ('exhaust', 'intake', 0.1, 0)]
    """
    out = []
    for k, name in enumerate(FOUR_STROKES):
        nxt = FOUR_STROKES[(k + 1) % 4]
        end = -1 if name in ("intake", "expansion") else 0       # moving away ends at s = 1
        out.append((name, nxt, s_table[end], tables[name][end], tables[nxt][end]))
    return out
