"""What a course variant asks of a linkage's output link: its extreme positions, swing or
stroke, the time ratio K and the transmission angle (угол передачи) over the cycle.

The output link is that of the mechanism's last group: the rocker of an RRR group one of whose
links turns about a fixed point (a crank-rocker four-bar's rocker), the rocker of an RPR group
(a slotted link, кулиса), or the slider of an RRP group (a slider-crank's piston, a shaper's
ram). A group whose output turns fully (a double crank) or never moves has no extremes and no
output link here.

- Extreme positions: where the output's velocity analogue (the rocker's ω_q = dθ/dφ, the
  slider's x′ = v_q·u) changes sign over one crank revolution, each found exactly by bisection
  inside the grid interval that brackets it (the exact analogues of
  :func:`flywheel.linkage.solve`; a bracketing solver, so it never leaves the interval).
- Swing ψ = θ_max − θ_min of a rocker [deg]; stroke H = x_max − x_min of a slider [m].
- Time ratio (коэффициент изменения средней скорости хода) K = φ_рх/φ_хх: the crank angles
  of the two strokes between the extremes, the slower one (the larger angle) taken as the
  working stroke, so K ≥ 1 — И. И. Артоболевский, «Теория механизмов и машин», 4-е изд., 1988,
  § 26 (K = (180° + θ)/(180° − θ)); R. L. Norton, «Design of Machinery», 5th ed., § 3.3
  (time ratio of quick-return mechanisms).
- Transmission angle γ ∈ [0°, 90°] (the acute angle; the pressure angle is 90° − γ):
  an RRR group: the acute angle between its two links at the joint (Norton § 4.10: for the
  four-bar cos μ = (b² + c² − z²)/(2bc), z the distance from the crank pin to the rocker
  pivot); an RRP group: 90° minus the acute angle between the rod and the guide (the rod's
  force against the slider's velocity); an RPR group: 90° − atan(|e|/|s|), the block's force
  (normal to the slide) against the velocity of the rocker's point under it (normal to
  A − P = s·u + e·n), so 90° everywhere for a slide through the pivot (e = 0). Its minimum is
  exact: at a root (by bisection) of the rate that makes γ stationary — ω_q,a − ω_q,b (RRR),
  the rod's ω_q (RRP), (A − P)·(A′ − P′) (RPR).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.linkage.mechanism import RPR, RRP, RRR, Mechanism
from flywheel.linkage.solve import Kinematics, solve

GRID_NODES = 721            # one crank revolution, every 0.5°: the brackets of the roots
BISECTIONS = 64             # halvings of a 0.5° bracket: below the round-off of φ
LEVELS = 6                  # halvings per call of solve (bracketed_roots)


@dataclass(frozen=True)
class OutputLink:
    """The output link of the last group: ``link`` (its name), ``kind`` ("rocker", "slotted
    link" or "slider"); its extremes by crank angle ``extremes_phi_deg`` [deg, 0 … 360) with
    the output's angle [deg] or position along the guide [m] there (``extremes_output``);
    ``swing_deg`` (a rocker) or ``stroke`` [m] (a slider); ``time_ratio_K`` (None unless there
    are exactly two extremes) from ``strokes_deg`` = (working, return) crank angles [deg];
    the transmission angle's minimum [deg] and the crank angle where it is reached [deg]
    (None when γ is the same all the cycle)."""

    DOCUMENT = ("link", "extremes_phi_deg", "swing_deg", "stroke", "time_ratio_K",
                "transmission_angle_min_deg", "phi_transmission_angle_min_deg")
    KEEP_NONE = ("time_ratio_K", "phi_transmission_angle_min_deg")

    link: str
    kind: str
    extremes_phi_deg: tuple[float, ...]
    extremes_output: tuple[float, ...]
    swing_deg: float | None
    stroke: float | None
    time_ratio_K: float | None
    strokes_deg: tuple[float, float] | None
    transmission_angle_min_deg: float
    phi_transmission_angle_min_deg: float | None


def time_ratio(phi_extremes: np.ndarray) -> tuple[float, float, float]:
    """(K, working, return) [-, rad, rad] of two extremes at crank angles ``phi_extremes``
    [rad]: the crank turns Δ = φ₂ − φ₁ (mod 2π) from one to the other and 2π − Δ back; the
    larger is the working stroke, K = φ_рх/φ_хх ≥ 1 (Артоболевский § 26).

    >>> [round(x, 6) for x in time_ratio(np.radians([0.0, 200.0]))[:1]]
    [1.25]
    """
    d = float(np.mod(phi_extremes[1] - phi_extremes[0], 2 * math.pi))
    work, back = max(d, 2 * math.pi - d), min(d, 2 * math.pi - d)
    return work / back, work, back


def rrr_transmission(ra: np.ndarray, rb: np.ndarray) -> np.ndarray:
    """γ [rad] of an RRR group from its links' vectors ra = B − A, rb = B − C at the joint B:
    μ = the angle between them, γ = min(μ, π − μ) (Norton § 4.10)."""
    mu = np.arctan2(np.abs(ra[:, 0] * rb[:, 1] - ra[:, 1] * rb[:, 0]),
                    np.einsum("ij,ij->i", ra, rb))
    return np.minimum(mu, math.pi - mu)


def rrp_transmission(rod: np.ndarray, u: np.ndarray) -> np.ndarray:
    """γ [rad] of an RRP group from its rod's vector ``rod`` = B − A and the guide's unit
    direction ``u``: γ = π/2 − β, β the acute angle between rod and guide (the pressure angle
    of the slider, whose velocity is along u; Артоболевский, угол давления)."""
    along = np.abs(rod @ u)
    across = np.abs(rod[:, 0] * u[1] - rod[:, 1] * u[0])
    return math.pi / 2 - np.arctan2(across, along)


def rpr_transmission(d: np.ndarray, offset: float) -> np.ndarray:
    """γ [rad] of an RPR group from d = A − P (the block's pin from the rocker's pivot) and the
    slide line's offset e: γ = π/2 − atan(|e|/|s|), |s| = √(|d|² − e²)."""
    s = np.sqrt(np.maximum(np.einsum("ij,ij->i", d, d) - offset**2, 0.0))
    return math.pi / 2 - np.arctan2(abs(offset), s)


def _is_fixed(mech: Mechanism, point: str) -> bool:
    return point in mech.ground or point == mech.crank.pivot


class _Output:
    """How to read the last group's output from kinematics: its value (θ [rad] or x [m]), its
    rate (the velocity analogue), the transmission angle γ [rad] and γ's stationary rate."""

    def __init__(self, mech: Mechanism):
        d = mech.dyads[-1]
        self.d = d
        if isinstance(d, RRP):
            self.kind, self.link = "slider", d.slider
            self.u = np.array([math.cos(d.guide.angle), math.sin(d.guide.angle)])
            nrm = np.array([-self.u[1], self.u[0]])
            self.base = np.asarray(d.guide.through, float) + d.guide.offset * nrm
        elif isinstance(d, RPR):
            self.kind, self.link = "slotted link", d.rocker
        elif isinstance(d, RRR) and _is_fixed(mech, d.point_b):
            self.kind, self.link = "rocker", d.link_b
        elif isinstance(d, RRR) and _is_fixed(mech, d.point_a):
            self.kind, self.link = "rocker", d.link_a
        else:
            self.kind = None

    def value(self, k: Kinematics) -> np.ndarray:
        if self.kind == "slider":
            return (k.points[self.d.joint].r - self.base) @ self.u
        return k.links[self.link].theta

    def rate(self, k: Kinematics) -> np.ndarray:
        if self.kind == "slider":
            return k.points[self.d.joint].v_q @ self.u
        return k.links[self.link].omega_q

    def gamma(self, k: Kinematics) -> np.ndarray:
        d, P = self.d, k.points
        if isinstance(d, RRP):
            return rrp_transmission(P[d.joint].r - P[d.origin].r, self.u)
        if isinstance(d, RPR):
            return rpr_transmission(P[d.origin].r - P[d.pivot].r, d.offset)
        return rrr_transmission(P[d.joint].r - P[d.point_a].r, P[d.joint].r - P[d.point_b].r)

    def gamma_rate(self, k: Kinematics) -> np.ndarray:
        d, P, L = self.d, k.points, k.links
        if isinstance(d, RRP):
            return L[d.rod].omega_q
        if isinstance(d, RPR):
            rel = P[d.origin].r - P[d.pivot].r
            return np.einsum("ij,ij->i", rel, P[d.origin].v_q - P[d.pivot].v_q)
        return L[d.link_a].omega_q - L[d.link_b].omega_q


def bracketed_roots(mech: Mechanism, f, phi: np.ndarray, values: np.ndarray) -> np.ndarray:
    """The crank angles [rad, 0 … 2π) where ``f(kinematics)`` changes sign over one revolution,
    given its ``values`` on the closed grid ``phi`` (0 … 2π): each root by bisection inside its
    grid interval (all brackets at once, :data:`BISECTIONS` halvings; the exact analogues are
    evaluated by :func:`solve` at the midpoints). A node where f is zero to round-off is a
    root of either neighbouring interval, counted once.

    The bisection runs :data:`LEVELS` halvings per call of :func:`solve`: the midpoints of
    every path the next LEVELS halvings could take (2^LEVELS − 1 per bracket, each computed as
    the halving itself would, ½·(lo + hi)) are solved at once, then the halvings walk down
    that tree — the same midpoints, the same decisions, the same roots to the last bit as one
    halving per call, at a seventh of the calls (a call of solve costs its Python overhead,
    not its points)."""
    v = np.array(values, float)
    v[-1] = v[0]                                   # the closing node is φ = 0 again
    sa, sb = np.sign(v[:-1]), np.sign(v[1:])
    idx = np.flatnonzero((sa != sb) & ((sa != 0) | (sb != 0)))
    if idx.size == 0:
        return np.empty(0)
    lo, hi = phi[idx].copy(), phi[idx + 1].copy()
    f_lo = v[idx]
    rows = np.arange(idx.size)
    done = converged = 0
    while done < BISECTIONS and not converged:
        depth = min(LEVELS, BISECTIONS - done)
        # the tree of midpoints, level by level: node j of level l has children 2j (the root
        # right of its midpoint: lo moves up) and 2j + 1 (hi moves down)
        los, his, mids = [lo[:, None]], [hi[:, None]], []
        for level in range(depth):
            mid = 0.5 * (los[-1] + his[-1])
            mids.append(mid)
            if level + 1 < depth:
                los.append(np.stack([mid, los[-1]], axis=2).reshape(idx.size, -1))
                his.append(np.stack([his[-1], mid], axis=2).reshape(idx.size, -1))
        flat = np.concatenate([m.ravel() for m in mids])
        f_all = f(solve(mech, flat))
        f_tree, start = [], 0
        for m in mids:
            f_tree.append(f_all[start:start + m.size].reshape(m.shape))
            start += m.size
        node = np.zeros(idx.size, int)
        for level in range(depth):
            mid, f_mid = mids[level][rows, node], f_tree[level][rows, node]
            left = np.sign(f_mid) == np.sign(f_lo)
            lo = np.where(left, mid, lo)
            f_lo = np.where(left, f_mid, f_lo)
            hi = np.where(left, hi, mid)
            node = 2 * node + np.where(left, 0, 1)
            done += 1
            if np.all(hi - lo <= 4 * np.finfo(float).eps * 2 * math.pi):
                converged = 1
                break
    roots = np.where(f_lo == 0, lo, 0.5 * (lo + hi))
    roots = np.mod(roots, 2 * math.pi)
    roots[roots > 2 * math.pi - 1e-9] = 0.0
    out: list[float] = []
    for r in np.sort(roots):
        if not out or r - out[-1] > 1e-9:
            out.append(float(r))
    if len(out) > 1 and out[0] + 2 * math.pi - out[-1] <= 1e-9:
        out.pop()
    return np.array(out)


def output_link(mech: Mechanism) -> OutputLink | None:
    """The :class:`OutputLink` of ``mech``'s last group, or None (no group, a group whose
    output turns fully or stands still, an RRR group with neither link on a fixed pivot)."""
    if not mech.dyads:
        return None
    out = _Output(mech)
    if out.kind is None:
        return None
    phi = np.linspace(0.0, 2 * math.pi, GRID_NODES)
    k = solve(mech, phi)
    ext = bracketed_roots(mech, out.rate, phi, out.rate(k))
    if ext.size < 2:
        return None
    kx = solve(mech, ext)
    value = out.value(kx)
    if out.kind != "slider":                       # the rocker's angle, continuous over the swing
        theta = np.unwrap(out.value(k))
        near = np.interp(ext, phi, theta)
        value = near + np.mod(value - near + math.pi, 2 * math.pi) - math.pi
        shift = 2 * math.pi * math.floor((theta[0] + math.pi) / (2 * math.pi))
        value = np.degrees(value - shift)
    span = float(np.max(value) - np.min(value))
    K = strokes = None
    if ext.size == 2:
        K, work, back = time_ratio(ext)
        strokes = (math.degrees(work), math.degrees(back))
    gamma_min, phi_gamma = _least_transmission(mech, out, phi, k)
    return OutputLink(
        link=out.link, kind=out.kind, extremes_phi_deg=tuple(float(x) for x in np.degrees(ext)),
        extremes_output=tuple(float(x) for x in value),
        swing_deg=None if out.kind == "slider" else span,
        stroke=span if out.kind == "slider" else None,
        time_ratio_K=K, strokes_deg=strokes, transmission_angle_min_deg=math.degrees(gamma_min),
        phi_transmission_angle_min_deg=None if phi_gamma is None else math.degrees(phi_gamma))


def _least_transmission(mech: Mechanism, out: _Output, phi: np.ndarray,
                        k: Kinematics) -> tuple[float, float | None]:
    """γ's minimum over the revolution [rad] and its crank angle [rad] (None if γ is constant
    to round-off): the least γ at the roots of γ's stationary rate, or at a grid node if that
    is less (γ's fold at 90° is a maximum, never a minimum)."""
    g = out.gamma(k)
    if float(np.max(g) - np.min(g)) <= 1e-12:
        return float(np.min(g)), None
    roots = bracketed_roots(mech, out.gamma_rate, phi, out.gamma_rate(k))
    cand_phi = np.concatenate([roots, phi[:-1]])
    cand_g = np.concatenate([out.gamma(solve(mech, roots)) if roots.size else np.empty(0),
                             g[:-1]])
    i = int(np.argmin(cand_g))                     # a root first: the exact one on a tie
    return float(cand_g[i]), float(cand_phi[i])
