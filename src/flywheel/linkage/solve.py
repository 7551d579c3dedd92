"""Place a :class:`~flywheel.linkage.mechanism.Mechanism` on a φ grid.

For every named point: position r, velocity analogue v_q = dr/dφ [m/rad] and acceleration
analogue a_q = d²r/dφ² [m/rad²], each an (N, 2) array. For every link: angle θ [rad],
ω_q = dθ/dφ and ε_q = d²θ/dφ² (design.md §2–3). Closed-form positions; analogues from the
closure equations differentiated once and twice (exact, no finite differences).

Sources: the mechanism as a crank plus Assur groups of the second class (RRR, RRP, RPR) and
their analytical kinematics by vector closure — И. И. Артоболевский, «Теория механизмов и
машин», 4-е изд., М.: Наука, 1988, гл. 3 (structure) and гл. 4 (kinematics of the groups);
the analogues of velocity and acceleration (передаточные функции) as seed 000 computes them
(V_q = d/dφ, a_q = d²/dφ² of the position functions); the slider-crank's closed forms that
the tests use — R. L. Norton, «Design of Machinery», 5th ed., ch. 4 and 7 (offset slider-crank
position and acceleration).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flywheel.errors import AssemblyError, Notice
from flywheel.linkage.mechanism import RPR, RRP, RRR, LinkPoint, Mechanism


@dataclass(frozen=True)
class PointMotion:
    """r [m], v_q [m/rad], a_q [m/rad²]: arrays of shape (N, 2)."""

    r: np.ndarray
    v_q: np.ndarray
    a_q: np.ndarray


@dataclass(frozen=True)
class LinkMotion:
    """theta [rad], omega_q [-] = dθ/dφ, eps_q [1/rad] = d²θ/dφ²: arrays of shape (N,).

    ``ref`` names a point of the link, so points can be placed by distance and angle.
    ``theta`` is None for a link whose direction is not known (none so far)."""

    theta: np.ndarray
    omega_q: np.ndarray
    eps_q: np.ndarray
    ref: str


@dataclass(frozen=True)
class Kinematics:
    """The whole mechanism on the grid ``phi`` [rad]."""

    phi: np.ndarray
    points: dict[str, PointMotion]
    links: dict[str, LinkMotion]


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def _dot(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return np.einsum("ij,ij->i", a, b)


def _rotation_of(r: np.ndarray, v: np.ndarray, a: np.ndarray) -> tuple:
    """Angle, ω_q, ε_q of a vector r(φ) of constant length with derivatives v, a:
    θ = atan2(r_y, r_x); ω_q = (r × v)/|r|²; ε_q = (r × a)/|r|² (the r·v = 0 term vanishes)."""
    rr = _dot(r, r)
    return np.arctan2(r[:, 1], r[:, 0]), _cross(r, v) / rr, _cross(r, a) / rr


def _fail_where(bad: np.ndarray, phi: np.ndarray, what: str, dyad: str | None = None,
                need=None) -> None:
    """Raise AssemblyError naming the group and the first crank angle where ``bad`` holds;
    ``need()`` says what would assemble it (a length, a reach)."""
    if np.any(bad):
        deg = np.degrees(phi[np.argmax(bad)])
        need = need() if need is not None else ""
        err = AssemblyError(
            Notice.of("cannot_assemble_need", "{what} cannot be assembled at crank angle φ = "
                      "{deg:.2f}°: {need}", what=what, deg=deg, need=need) if need else
            Notice.of("cannot_assemble", "{what} cannot be assembled at crank angle φ = "
                      "{deg:.2f}°", what=what, deg=deg))
        err.dyad = dyad
        raise err


def _crank(mech: Mechanism, phi: np.ndarray, points: dict, links: dict) -> None:
    """A = O + l·(cos θ1, sin θ1), θ1 = θ0 + s·φ: v_q = s·l·(−sin, cos), a_q = −l·(cos, sin);
    each further pin likewise at its own length and at θ1 + β (β its angle to the tip)."""
    c = mech.crank
    n = phi.size
    theta = c.start_angle + c.direction * phi
    cs = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    sn = np.stack([-np.sin(theta), np.cos(theta)], axis=1)
    origin = np.broadcast_to(np.asarray(c.pivot_at, float), (n, 2)).copy()
    zero = np.zeros((n, 2))
    points[c.pivot] = PointMotion(origin, zero, zero)
    points[c.tip] = PointMotion(origin + c.length * cs, c.direction * c.length * sn, -c.length * cs)
    for pin in c.pins:
        th = theta + pin.angle
        pc = np.stack([np.cos(th), np.sin(th)], axis=1)
        ps = np.stack([-np.sin(th), np.cos(th)], axis=1)
        points[pin.name] = PointMotion(origin + pin.length * pc, c.direction * pin.length * ps,
                                       -pin.length * pc)
    links[c.name] = LinkMotion(theta, np.full(n, float(c.direction)), np.zeros(n), c.pivot)


def _rrp(d: RRP, phi: np.ndarray, points: dict, links: dict) -> None:
    """Joint B = P + e·n + x·u on the guide, |B − A| = L.

    Position: with q = A − P − e·n, x = q·u + branch·√(L² − (q·n)²).
    Velocity: (B − A)·(B′ − A′) = 0 with B′ = x′u gives x′ = (B − A)·A′ / ((B − A)·u).
    Acceleration: x″ = [(B − A)·A″ − |B′ − A′|²] / ((B − A)·u).
    """
    A = points[d.origin]
    n_pts = phi.size
    u = np.array([np.cos(d.guide.angle), np.sin(d.guide.angle)])
    nrm = np.array([-u[1], u[0]])
    base = np.asarray(d.guide.through, float) + d.guide.offset * nrm
    q = A.r - base
    qu, qn = q @ u, q @ nrm
    disc = d.rod_length**2 - qn**2
    _fail_where(disc < 0, phi, Notice.of(
        "dyad_rrp", "dyad {name} (RRP, rod {rod})", name=d.name, rod=d.rod), d.name,
                lambda: Notice.of(
                    "need_rod", "the rod ({rod_length:.6g} m) must be at least {reach:.6g} m, the "
                    "largest distance of {origin} from the guide over the cycle",
                    rod_length=d.rod_length, reach=np.max(np.abs(qn)), origin=d.origin))
    x = qu + d.branch * np.sqrt(disc)
    B = base + x[:, None] * u
    rel = B - A.r
    denom = rel @ u
    _fail_where(np.abs(denom) < 1e-12 * d.rod_length, phi,
                Notice.of(
                    "dyad_rrp_perpendicular", "dyad {name} (RRP, rod {rod} perpendicular to the "
                    "guide)", name=d.name, rod=d.rod), d.name,
                lambda: Notice.of(
                    "need_rod_dead", "a dead position: make the rod longer than the largest "
                    "distance of {origin} from the guide", origin=d.origin))
    x1 = _dot(rel, A.v_q) / denom
    B1 = x1[:, None] * u
    rel1 = B1 - A.v_q
    x2 = (_dot(rel, A.a_q) - _dot(rel1, rel1)) / denom
    B2 = x2[:, None] * u
    points[d.joint] = PointMotion(B, B1, B2)
    theta, w, e = _rotation_of(rel, rel1, B2 - A.a_q)
    links[d.rod] = LinkMotion(theta, w, e, d.origin)
    links[d.slider] = LinkMotion(np.full(n_pts, d.guide.angle), np.zeros(n_pts), np.zeros(n_pts), d.joint)


def _solve2(r1: np.ndarray, r2: np.ndarray, b1: np.ndarray, b2: np.ndarray) -> np.ndarray:
    """Solve r1·x = b1, r2·x = b2 for x (N, 2) by Cramer's rule."""
    det = _cross(r1, r2)
    x = (b1 * r2[:, 1] - b2 * r1[:, 1]) / det
    y = (r1[:, 0] * b2 - r2[:, 0] * b1) / det
    return np.stack([x, y], axis=1)


def _rrr(d: RRR, phi: np.ndarray, points: dict, links: dict) -> None:
    """Joint B with |B − A| = a, |B − C| = b (circle intersection).

    Position: with g = C − A, D = |g|, p = (a² − b² + D²)/(2D), h = √(a² − p²):
    B = A + p·g/D + branch·h·perp(g)/D, perp(g) = (−g_y, g_x).
    Velocity: (B − A)·B′ = (B − A)·A′, (B − C)·B′ = (B − C)·C′.
    Acceleration: (B − A)·B″ = (B − A)·A″ − |B′ − A′|², likewise for C.
    """
    A, C = points[d.point_a], points[d.point_b]
    g = C.r - A.r
    D = np.sqrt(_dot(g, g))
    what = Notice.of(
        "dyad_rrr", "dyad {name} (RRR, links {a}–{b})", name=d.name, a=d.link_a, b=d.link_b)
    inline = Notice.of("dyad_in_line", "{what} (links in line: a dead position)", what=what)
    a, b = d.length_a, d.length_b
    def need():
        lo, hi = abs(a - b), a + b
        tol = 1e-9 * hi
        if D.max() == 0:
            return Notice.of(
                "need_base", "{a} and {b} coincide: the group has no base (move the pivot)",
                a=d.point_a, b=d.point_b)
        if abs(D.min() - lo) <= tol or abs(D.max() - hi) <= tol:
            edge = f"|{a:.6g} − {b:.6g}| = {lo:.6g}" if abs(D.min() - lo) <= tol else \
                f"{a:.6g} + {b:.6g} = {hi:.6g}"
            return Notice.of(
                "need_in_line", "the distance {a}–{b} reaches {edge} m: the links lie in line (a "
                "dead position; change a length so that the distance stays strictly between "
                "{lo:.6g} and {hi:.6g} m)", a=d.point_a, b=d.point_b, edge=edge, lo=lo, hi=hi)
        return Notice.of(
            "need_reach", "the distance {a}–{b} ranges over {dmin:.6g} … {dmax:.6g} m, the links "
            "({la:.6g} and {lb:.6g} m) reach only {lo:.6g} … {hi:.6g} m", a=d.point_a, b=d.point_b,
            dmin=D.min(), dmax=D.max(), la=a, lb=b, lo=lo, hi=hi)

    _fail_where(D == 0, phi, what, d.name, need)
    edge = 1e-9 * (a + b)                   # in line within round-off: a dead position
    _fail_where((np.abs(D - abs(a - b)) <= edge) | (np.abs(D - (a + b)) <= edge), phi,
                inline, d.name, need)
    p = (a**2 - b**2 + D**2) / (2 * D)
    h2 = a**2 - p**2
    _fail_where(h2 < 0, phi, what, d.name, need)
    gu = g / D[:, None]
    perp = np.stack([-gu[:, 1], gu[:, 0]], axis=1)
    B = A.r + p[:, None] * gu + d.branch * np.sqrt(h2)[:, None] * perp
    ra, rc = B - A.r, B - C.r
    _fail_where(np.abs(_cross(ra, rc)) < 1e-12 * d.length_a * d.length_b, phi,
                inline, d.name, need)
    B1 = _solve2(ra, rc, _dot(ra, A.v_q), _dot(rc, C.v_q))
    va, vc = B1 - A.v_q, B1 - C.v_q
    B2 = _solve2(ra, rc, _dot(ra, A.a_q) - _dot(va, va), _dot(rc, C.a_q) - _dot(vc, vc))
    points[d.joint] = PointMotion(B, B1, B2)
    links[d.link_a] = LinkMotion(*_rotation_of(ra, va, B2 - A.a_q), d.point_a)
    links[d.link_b] = LinkMotion(*_rotation_of(rc, vc, B2 - C.a_q), d.point_b)


def _rpr(d: RPR, phi: np.ndarray, points: dict, links: dict) -> None:
    """Slotted link: the origin A lies on the rocker's slide line, A − P = s·u + e·n,
    u = (cos θ, sin θ), n = (−sin θ, cos θ).

    Position: s = branch·√(|A − P|² − e²), θ = atan2(A − P) − atan2(e, s).
    Velocity (d′ = A′ − P′): θ′ = (d′·n)/s, s′ = d′·u + e·θ′.
    Acceleration: θ″ = (d″·n − 2s′θ′ + e·θ′²)/s, s″ = d″·u + s·θ′² + e·θ″.
    """
    A, P = points[d.origin], points[d.pivot]
    dr, d1, d2 = A.r - P.r, A.v_q - P.v_q, A.a_q - P.a_q
    rho2 = _dot(dr, dr)
    disc = rho2 - d.offset**2
    what = Notice.of(
        "dyad_rpr", "dyad {name} (RPR, rocker {rocker})", name=d.name, rocker=d.rocker)
    _fail_where(disc <= 0, phi, what, d.name,
                lambda: Notice.of(
                    "need_offset", "the slide line's offset ({offset:.6g} m) must be smaller than "
                    "the distance {pivot}–{origin}, which falls to {dmin:.6g} m",
                    offset=abs(d.offset), pivot=d.pivot, origin=d.origin, dmin=np.sqrt(rho2.min())))
    through = _passes_through(dr, d1, d2, phi, d.offset)
    if np.any(through):
        deg = np.degrees(phi[np.argmax(through)])
        err = AssemblyError(Notice.of(
            "singular_rpr", "{what} has a singular position near crank angle φ = {deg:.2f}°: "
            "{origin} passes through the rocker's pivot {pivot}, where the rocker's direction is "
            "undefined (move {pivot} off the path of {origin}, or change the slide line's offset)",
            what=what, deg=deg, origin=d.origin, pivot=d.pivot))
        err.dyad = d.name
        raise err
    s = d.branch * np.sqrt(disc)
    theta = np.arctan2(dr[:, 1], dr[:, 0]) - np.arctan2(d.offset, s)
    u = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    nrm = np.stack([-u[:, 1], u[:, 0]], axis=1)
    w = _dot(d1, nrm) / s
    s1 = _dot(d1, u) + d.offset * w
    e = (_dot(d2, nrm) - 2 * s1 * w + d.offset * w**2) / s
    links[d.slider] = LinkMotion(theta, w, e, d.origin)     # the group's order: RPR.links
    links[d.rocker] = LinkMotion(theta, w, e, d.pivot)


def _passes_through(dr: np.ndarray, d1: np.ndarray, d2: np.ndarray, phi: np.ndarray,
                    offset: float, rtol: float = 1e-5) -> np.ndarray:
    """Where a slotted link's block passes through its singular position: the distance
    ρ = |A − P| comes within ``rtol`` of the largest distance to |offset| (the slide line then
    sweeps through the pivot and θ jumps by 180° while the analogues stay finite: not a motion).

    At the nodes ρ is known; between neighbouring nodes at most 0.2 rad apart (any analysis
    grid: 36 intervals or more) ρ's minimum is that of the cubic Hermite interpolant of A − P
    from its values and exact derivatives A′ − P′ at both nodes (error O(h⁴): 2e-7 of the size
    at h = 0.17 rad), found where d|H|²/dt = 0 — only in the intervals that come near.
    Returns a boolean array on the nodes (the node that starts a singular interval)."""
    rho = np.sqrt(_dot(dr, dr))
    scale = float(rho.max()) or 1.0
    tol = rtol * scale
    bad = rho - abs(offset) <= tol
    if phi.size < 2:
        return bad
    h = np.diff(phi)
    vv = _dot(d1[:-1], d1[:-1])
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.where(vv > 0, -_dot(dr[:-1], d1[:-1]) / vv, 0.0)
    lo, hi = np.minimum(0.0, h), np.maximum(0.0, h)
    t = np.clip(t, lo, hi)
    near = dr[:-1] + t[:, None] * d1[:-1]
    cand = np.flatnonzero((np.abs(h) <= 0.2) & (np.sqrt(_dot(near, near)) - abs(offset)
                                                 < 0.05 * scale))
    for i in cand:
        hh = h[i]
        p0, p1, m0, m1 = dr[i], dr[i + 1], d1[i], d1[i + 1]
        # H(t) = c0 + c1 t + c2 t² + c3 t³ on [0, h] (cubic Hermite)
        c0, c1 = p0, m0
        c2 = (3 * (p1 - p0) / hh - 2 * m0 - m1) / hh
        c3 = (2 * (p0 - p1) / hh + m0 + m1) / hh**2
        cx, cy = np.array([c3[0], c2[0], c1[0], c0[0]]), np.array([c3[1], c2[1], c1[1], c0[1]])
        f = np.polyadd(np.polymul(cx, cx), np.polymul(cy, cy))        # |H(t)|², degree 6
        roots = np.roots(np.polyder(f))
        ts = [0.0, hh] + [r.real for r in roots if abs(r.imag) <= 1e-9 * abs(hh)
                          and min(0.0, hh) <= r.real <= max(0.0, hh)]
        least = min(np.sqrt(max(np.polyval(f, x), 0.0)) for x in ts)
        if least - abs(offset) <= tol:
            bad[i] = True
    return bad


def _link_point(p: LinkPoint, points: dict, links: dict) -> None:
    """A point on a link.

    By fraction f of origin→toward plus c across: r = O + f·(T − O) + c·perp((T − O)/|T − O|);
    the perpendicular unit turns with the link, so its derivatives use the link's ω_q, ε_q.
    By distance ρ at angle β to the link direction θ: r = O + ρ·(cos(θ+β), sin(θ+β)),
    r′ = O′ + ρ·ω_q·(−sin, cos), r″ = O″ + ρ·ε_q·(−sin, cos) − ρ·ω_q²·(cos, sin).
    """
    O = points[p.origin]
    if p.toward is not None:
        T = points[p.toward]
        r = O.r + p.fraction * (T.r - O.r)
        v = O.v_q + p.fraction * (T.v_q - O.v_q)
        a = O.a_q + p.fraction * (T.a_q - O.a_q)
        if p.across:
            L = links[p.link]
            g = T.r - O.r
            gu = g / np.sqrt(_dot(g, g))[:, None]
            perp = np.stack([-gu[:, 1], gu[:, 0]], axis=1)
            w, e = L.omega_q[:, None], L.eps_q[:, None]
            r = r + p.across * perp
            v = v - p.across * w * gu
            a = a - p.across * (e * gu + w**2 * perp)
        points[p.name] = PointMotion(r, v, a)
        return
    L = links[p.link]
    ang = L.theta + p.angle
    cs = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    sn = np.stack([-np.sin(ang), np.cos(ang)], axis=1)
    w, e = L.omega_q[:, None], L.eps_q[:, None]
    points[p.name] = PointMotion(
        O.r + p.distance * cs,
        O.v_q + p.distance * w * sn,
        O.a_q + p.distance * (e * sn - w**2 * cs),
    )


def _point_ready(p: LinkPoint, points: dict, links: dict) -> bool:
    needs = [p.origin] + ([p.toward] if p.toward is not None else [])
    ok = all(n in points for n in needs)
    if p.toward is None or p.across:
        ok = ok and p.link in links
    return ok


_SOLVERS = {RRP: _rrp, RRR: _rrr, RPR: _rpr}


def solve(mech: Mechanism, phi: np.ndarray) -> Kinematics:
    """Positions and analogues of every point and link of ``mech`` on the grid ``phi`` [rad].

    Dyads are placed in order; a point on a link is placed as soon as what it needs is known.
    Raises :class:`~flywheel.errors.AssemblyError` naming the dyad and the crank angle where
    it cannot be assembled.

    >>> import math
    >>> from flywheel.linkage.mechanism import Crank, Guide
    >>> m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, math.pi / 2, -1),
    ...               (RRP("B", "A", "B", "2", 0.4, "3", Guide((0.0, 0.0), math.pi / 2)),))
    >>> k = solve(m, np.radians([0.0, 180.0]))
    >>> k.points["B"].r[:, 1].round(6).tolist()   # top and bottom dead centres: l2 ± l1
    [0.5, 0.3]
    """
    phi = np.atleast_1d(np.asarray(phi, dtype=float))   # a single angle is a grid of one
    if phi.ndim != 1:
        # library use only: no CLI input reaches this
        raise ValueError(f"phi must be a 1-D grid of crank angles, got shape {phi.shape}")
    points: dict[str, PointMotion] = {}
    links: dict[str, LinkMotion] = {}
    for name, xy in mech.ground.items():
        xy_arr = np.broadcast_to(np.asarray(xy, float), (phi.size, 2)).copy()
        zero = np.zeros((phi.size, 2))
        points[name] = PointMotion(xy_arr, zero, zero)
    _crank(mech, phi, points, links)
    pending = list(mech.points)

    def place_ready() -> None:
        nonlocal pending
        progress = True
        while progress:
            progress = False
            for p in list(pending):
                if _point_ready(p, points, links):
                    _link_point(p, points, links)
                    pending.remove(p)
                    progress = True

    place_ready()
    for d in mech.dyads:
        place_ready()
        _SOLVERS[type(d)](d, phi, points, links)
    place_ready()
    if pending:
        p = pending[0]
        # library use only: no CLI input reaches this
        raise AssemblyError(f"point {p.name} on link {p.link} needs points or links that are never defined")
    return Kinematics(phi, points, links)
