"""Loads at any point of any link, couples over a part of the cycle, springs (issue 24): each
as its vector on the grid for the force analysis, its reduced moment, and its cumulative work
A(φ), exact where the integrand allows it.

Pure functions on arrays (SI, radians). Conventions of design.md §2: the reduced moment of a
force F⃗ at a point with velocity analogue v_q [m/rad] is F⃗·v_q, of a couple M on a link
M·ω_q; positive drives the crank. A load that acts over ``rng`` = (from, to) [rad] of crank
angle acts on the closed range, wrapping through 0 when from > to (:func:`nodes_on`); its
range's ends are nodes of the grid (:func:`grid_nodes`), so every interval of the grid is
wholly inside or wholly outside it (:func:`intervals_on`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.dynamics.loads import LoadKey
from flywheel.errors import InputError, Notice

TOL = 1e-9
"""rad: a node this close to a range's end is on it (the grid merges nodes closer than this)."""


def _span(rng: tuple[float, float], cycle: float) -> tuple[float, float]:
    """(start, length) [rad] of a range over the cycle Φ; from = to mod Φ is the whole cycle."""
    a, b = rng
    length = (b - a) % cycle
    return a % cycle, (cycle if length < TOL else length)


def nodes_on(phi: np.ndarray, rng, cycle: float) -> np.ndarray:
    """True at the nodes φ [rad] inside the closed range ``rng`` (None: the whole cycle):
    (φ − from) mod Φ ≤ (to − from) mod Φ, so a range with from > to wraps through 0.

    >>> nodes_on(np.radians([0, 90, 180, 270, 360]), np.radians([270, 90]), 2 * np.pi).tolist()
    [True, True, False, True, True]
    """
    if rng is None:
        return np.ones(phi.size, bool)
    a, length = _span(rng, cycle)
    d = np.mod(phi - a, cycle)
    return (d <= length + TOL) | (d >= cycle - TOL)


def intervals_on(phi: np.ndarray, rng, cycle: float) -> np.ndarray:
    """True for the grid's intervals [φ_i, φ_i+1] inside the range (by their midpoints: the
    range's ends are nodes)."""
    if rng is None:
        return np.ones(phi.size - 1, bool)
    a, length = _span(rng, cycle)
    return np.mod(0.5 * (phi[:-1] + phi[1:]) - a, cycle) < length


def table_value(x: np.ndarray, table) -> np.ndarray:
    """A load's table [[x, value], …] at x, linear between its rows and 0 outside its first
    and last x (the load acts where its table says)."""
    t = np.asarray(table, float)
    return np.interp(x, t[:, 0], t[:, 1], left=0.0, right=0.0)


def table_integral(x: np.ndarray, table) -> np.ndarray:
    """G(x) = ∫ value dx from the table's first x [value·x], exact for the table's piecewise
    linear function (0 outside it): the trapezoid areas of its rows summed, plus the part
    of the row x falls in, (x − x_k)·(v_k + v(x))/2.

    >>> float(table_integral(np.array([3.0]), [[0.0, 0.0], [1.0, 2.0], [2.0, 2.0]])[0])
    3.0
    """
    t = np.asarray(table, float)
    xs, vs = t[:, 0], t[:, 1]
    area = np.concatenate([[0.0], np.cumsum(np.diff(xs) * (vs[:-1] + vs[1:]) / 2)])
    xc = np.clip(x, xs[0], xs[-1])
    k = np.clip(np.searchsorted(xs, xc, side="right") - 1, 0, xs.size - 2)
    v = np.interp(xc, xs, vs)
    return area[k] + (xc - xs[k]) * (vs[k] + v) / 2


def path_steps(r: np.ndarray) -> np.ndarray:
    """The path length [m] a point covers in each interval of the grid, as the chord |Δr|:
    exact on a straight path (a slider), O(h³) short of the arc on a curved one."""
    return np.hypot(*np.diff(r, axis=0).T)


def travel(phi: np.ndarray, steps: np.ndarray, rng, cycle: float) -> np.ndarray:
    """The point's travel s [m] along its path since its range began (φ = from; 0 without a
    range), at every node; it runs on through the range and past it to the cycle's end."""
    cum = np.concatenate([[0.0], np.cumsum(steps)])
    if rng is None:
        return cum
    a = _span(rng, cycle)[0]
    i0 = int(np.argmin(np.abs(phi - a)))
    s = cum - cum[i0]
    return np.where(phi >= phi[i0] - TOL, s, s + cum[-1])


@dataclass(frozen=True)
class Applied:
    """One load's share: ``M`` [N·m] its reduced moment at the nodes, ``W`` [J] its
    cumulative work from φ = 0 (None: the trapezoid rule on M is used), ``F`` [N] its signed
    size (a force, a spring's tension) or None, ``vectors`` ((link, point, (N, 2) force [N],
    on_frame), …) and ``couples`` ((link, M [N·m], on_frame), …) for the force analysis."""

    M: np.ndarray
    W: np.ndarray | None
    F: np.ndarray | None
    vectors: tuple = ()
    couples: tuple = ()


def _cumulative(dW: np.ndarray) -> np.ndarray:
    return np.concatenate([[0.0], np.cumsum(dW)])


def couple(phi: np.ndarray, cycle: float, omega_q: np.ndarray, theta: np.ndarray | None,
           link: str, moment: float | None, table, rng) -> Applied:
    """A couple on a link over a range of φ: constant ``moment`` [N·m] or ``table`` [[φ rad, M]].
    Reduced moment M·ω_q (design.md §2); work M(mid)·Δθ per interval inside the range — exact
    for a constant couple, M·(θ(to) − θ(from)) over its range (the work of a couple is M·dθ)."""
    def value(x):
        return np.full(x.shape, float(moment)) if table is None else table_value(
            np.mod(x, cycle), table)

    on = nodes_on(phi, rng, cycle)
    M_link = np.where(on, value(phi), 0.0)
    M = M_link * omega_q
    if theta is None:         # no angle known: the trapezoid rule on M
        return Applied(M, None, None, couples=((link, M_link, True),))
    mid = 0.5 * (phi[:-1] + phi[1:])
    dW = intervals_on(phi, rng, cycle) * value(mid) * np.diff(np.unwrap(theta))
    return Applied(M, _cumulative(dW), None, couples=((link, M_link, True),))


def point_force(phi: np.ndarray, cycle: float, r: np.ndarray, v_q: np.ndarray,
                link_theta: np.ndarray | None, link: str, point: str, direction: str,
                angle: float | None, magnitude: float | None, table, table_of: str,
                rng) -> Applied:
    """A force at a named point: its direction e (fixed at ``angle`` [rad] from +x; along or
    across the link at its angle θ; against the velocity, −v_q/|v_q|), its size (constant, a
    table against φ [rad] or against the point's travel s [m] since the range began, 0 outside
    the table) over the range. F⃗ = F·e, reduced moment F⃗·v_q (design.md §2). Work per interval
    inside the range: against the velocity −∫F ds over the chord's length (exact in s for a
    travel table: :func:`table_integral`), a fixed direction F·e·Δr (exact for a constant), along
    or across a link the trapezoid rule on F⃗·v_q."""
    n = phi.size
    on = nodes_on(phi, rng, cycle)
    act = intervals_on(phi, rng, cycle).astype(float)
    steps = path_steps(r)
    mid = 0.5 * (phi[:-1] + phi[1:])
    s = None
    if table is None:
        size, size_mid = np.full(n, float(magnitude)), np.full(n - 1, float(magnitude))
    elif table_of == "phi":
        size, size_mid = table_value(np.mod(phi, cycle), table), table_value(np.mod(mid, cycle), table)
    else:
        s = travel(phi, steps, rng, cycle)
        size, size_mid = table_value(s, table), None
    if direction == "against-velocity":
        speed = np.hypot(v_q[:, 0], v_q[:, 1])
        e = -np.divide(v_q, speed[:, None], out=np.zeros_like(v_q), where=speed[:, None] > 0)
    elif direction == "fixed":
        e = np.broadcast_to(np.array([math.cos(angle), math.sin(angle)]), (n, 2))
    else:
        c, sn = np.cos(link_theta), np.sin(link_theta)
        e = np.stack([c, sn] if direction == "along" else [-sn, c], axis=1)
    F = np.where(on, size, 0.0)
    vec = F[:, None] * e
    M = np.einsum("ij,ij->i", vec, v_q)
    if direction == "against-velocity":
        if s is not None:
            dW = -act * np.diff(table_integral(s, table))     # s grows: ds ≥ 0
        else:
            dW = -act * size_mid * steps
    elif direction == "fixed":
        dW = act * size_mid * (np.diff(r, axis=0) @ e[0])
    else:
        full = size[:, None] * e
        Mf = np.einsum("ij,ij->i", full, v_q)
        dW = act * 0.5 * (Mf[:-1] + Mf[1:]) * np.diff(phi)
    return Applied(M, _cumulative(dW), F, vectors=((link, point, vec, True),))


def linear_spring(name: str, rP: np.ndarray, vP: np.ndarray, rQ: np.ndarray, vQ: np.ndarray,
                  stiffness: float, free_length: float, ends: tuple) -> Applied:
    """A linear spring between P and Q: length L = |r_P − r_Q|, tension T = c·(L − L0),
    energy U = ½·c·(L − L0)². Reduced moment −dU/dφ = −T·dL/dφ with
    dL/dφ = (r_P − r_Q)·(v_qP − v_qQ)/L (the work of the forces −T·(r_P − r_Q)/L on P and its
    opposite on Q); work −(U(φ) − U(0)), exact, zero over the cycle (a potential's).
    ``ends``: ((link carrying P or None for the frame), (link carrying Q or None)), P and Q
    named in the force vectors. Raises InputError where the ends meet (L = 0)."""
    d = rP - rQ
    L = np.hypot(d[:, 0], d[:, 1])
    if not np.all(L > 1e-12):
        raise InputError(Notice.of(
            "spring_ends_meet", "springs {name}: its ends meet (length 0) during the cycle, where "
            "its direction is undefined (allowed: ends that stay apart)", name=name))
    dL = np.einsum("ij,ij->i", d, vP - vQ) / L
    T = stiffness * (L - free_length)
    U = 0.5 * stiffness * (L - free_length) ** 2
    u = d / L[:, None]
    (lp, p), (lq, q) = ends
    vectors = []
    if lp is not None:
        vectors.append((lp, p, -T[:, None] * u, lq is None))
    if lq is not None:
        vectors.append((lq, q, T[:, None] * u, lp is None))
    return Applied(-T * dL, -(U - U[0]), T, vectors=tuple(vectors))


def torsional_spring(name: str, link: str, theta: np.ndarray, omega_q: np.ndarray,
                     stiffness: float, free_angle: float, other: tuple | None = None) -> Applied:
    """A torsional spring on a link about its joint with the frame, or between two links
    about their common joint (``other`` = (link b, θ_b, ω_q,b); the frame when None). Its
    angle is the relative one, θ = θ_a − θ_b (θ_a alone against the frame), its turn from the
    free angle Δ = θ − θ0 (θ0 taken the nearest whole turns to θ(0)), energy U = ½·c·Δ²,
    couple −c·Δ on link a and +c·Δ on link b (equal and opposite: no reaction on the frame;
    against the frame, its reaction). Reduced moment −dU/dφ = −c·Δ·(ω_q,a − ω_q,b) (the
    virtual work of the two couples, design.md §2); work −(U(φ) − U(0)), exact, zero over the
    cycle. Raises InputError when the angle turns through whole revolutions (the spring would
    wind up: a crank against the frame, a crank against its coupler)."""
    th = np.unwrap(theta)
    if other is not None:
        link_b, theta_b, omega_q_b = other
        th = th - np.unwrap(theta_b)
        omega_q = omega_q - omega_q_b
    if abs(th[-1] - th[0]) > 1e-6:
        if other is not None:
            raise InputError(Notice.of(
                "spring_links_turn", "springs {name}: links {link} and {other} turn through "
                "whole revolutions against each other, so a torsional spring between them would "
                "wind up without end (allowed: links whose relative angle rocks)", name=name,
                link=link, other=other[0]))
        raise InputError(Notice.of(
            "spring_link_turns", "springs {name}: link {link} turns through whole revolutions, "
            "so a torsional spring on it would wind up without end (allowed: a link that rocks)",
            name=name, link=link))
    theta0 = free_angle + 2 * math.pi * round((th[0] - free_angle) / (2 * math.pi))
    delta = th - theta0
    Mc = -stiffness * delta
    U = 0.5 * stiffness * delta ** 2
    couples = ((link, Mc, True),) if other is None else ((link, Mc, False), (other[0], -Mc, False))
    return Applied(Mc * omega_q, -(U - U[0]), None, couples=couples)


def grid_nodes(case) -> list[float]:
    """The crank angles [rad] the grid must have as nodes for the case's loads: the ends of
    every phi_range_deg and the rows of every table against φ (so a load switches on and off,
    and bends, at a node)."""
    out: list[float] = []
    for load in list(case.forces) + list(case.couples):
        rng = getattr(load, "phi_range_deg", None)
        if rng is not None:
            out += [math.radians(a) for a in rng]
        table = getattr(load, "table", None)
        if table is not None and getattr(load, "table_of", "phi") == "phi":
            out += [math.radians(row[0]) for row in table]
    return out


# -- the case's loads --------------------------------------------------------------------------

def is_new_couple(c) -> bool:
    """A couple with a range or a table (a constant couple over the whole cycle keeps the
    trapezoid rule of before, so its outputs stay as they were)."""
    return c.phi_range_deg is not None or c.table is not None


def _rad(rng):
    return None if rng is None else (math.radians(rng[0]), math.radians(rng[1]))


def force_at_point(f, case, mech, kin) -> Applied:
    """The case's ``[[forces]]`` entry ``f`` with a ``point`` (:func:`point_force`), on its
    ``link`` or the link that carries the point."""
    from flywheel.dynamics.forces import carriers

    link = f.link or carriers(mech)[f.point]
    pm, lm = kin.points[f.point], kin.links.get(link)
    table = None if f.table is None else [
        (math.radians(x) if f.table_of == "phi" else x, v) for x, v in f.table]
    return point_force(kin.phi, case.machine.cycle, pm.r, pm.v_q,
                       None if lm is None else lm.theta, link, f.point, f.acts,
                       None if f.angle_deg is None else math.radians(f.angle_deg), f.magnitude,
                       table, f.table_of, _rad(f.phi_range_deg))


def couple_on_link(c, case, kin) -> Applied:
    """The case's ``[[couples]]`` entry ``c`` with a range or a table (:func:`couple`)."""
    lm = kin.links[c.link]
    table = None if c.table is None else [(math.radians(x), v) for x, v in c.table]
    return couple(kin.phi, case.machine.cycle, lm.omega_q, lm.theta, c.link, c.moment, table,
                  _rad(c.phi_range_deg))


def spring(sp, case, mech, kin) -> Applied:
    """The case's ``[[springs]]`` entry ``sp`` (:func:`linear_spring`, :func:`torsional_spring`).
    A preload T0 at φ0 gives the free length L0 = L(φ0) − T0/c; InputError if that is ≤ 0."""
    from flywheel.dynamics.forces import FRAME, carriers
    from flywheel.linkage import solve

    if sp.kind == "torsional" and sp.links is not None:    # between two links
        a, b = sp.links
        la, lb = kin.links[a], kin.links[b]
        return torsional_spring(sp.name, a, la.theta, la.omega_q, sp.stiffness,
                                math.radians(sp.free_angle_deg), (b, lb.theta, lb.omega_q))
    if sp.kind == "torsional":
        lm = kin.links[sp.link]
        return torsional_spring(sp.name, sp.link, lm.theta, lm.omega_q, sp.stiffness,
                                math.radians(sp.free_angle_deg))
    P, Q = sp.points
    L0 = sp.free_length
    if L0 is None:
        at = solve(mech, np.array([math.radians(sp.preload_at_deg) % case.machine.cycle]))
        L_at = float(np.hypot(*(at.points[P].r[0] - at.points[Q].r[0])))
        L0 = L_at - sp.preload / sp.stiffness
        if not L0 > 0:
            raise InputError(Notice.of(
                "spring_free_length", "springs {name}: a preload of {T:g} N at φ = {at:g}°, where "
                "the spring is {L:.6g} m long, means a free length of {L0:.6g} m ≤ 0 (allowed: "
                "|preload| below stiffness × length in compression)", name=sp.name, T=sp.preload,
                at=sp.preload_at_deg, L=L_at, L0=L0))
    carry = carriers(mech)
    ends = tuple((None if carry[p] == FRAME else carry[p], p) for p in (P, Q))
    return linear_spring(sp.name, kin.points[P].r, kin.points[P].v_q, kin.points[Q].r,
                         kin.points[Q].v_q, sp.stiffness, L0, ends)


def applied_loads(case, mech, kin) -> dict[LoadKey, Applied]:
    """Every load of the case this module computes, by its key in M_parts (kind "force",
    "couple", "spring"): the point forces, the couples with a range or a table, the springs —
    in the order of the case."""
    out: dict[LoadKey, Applied] = {}
    for f in case.forces:
        if f.point is not None:
            out[LoadKey("force", f.name)] = force_at_point(f, case, mech, kin)
    for c in case.couples:
        if is_new_couple(c):
            out[LoadKey("couple", c.name)] = couple_on_link(c, case, kin)
    for sp in case.springs:
        out[LoadKey("spring", sp.name)] = spring(sp, case, mech, kin)
    return out
