"""The φ grid of a run: uniform intervals plus the angles whose values must be computed, not
interpolated — report angles, the 12 standard positions, the sliders' dead centres, and the
angles where a technological force switches on or off.
"""
from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from flywheel.dynamics import applied, loads
from flywheel.dynamics.results import DeadCentre, Position
from flywheel.errors import InputError, Notice, led
from flywheel.linkage import Kinematics, LinkMotion, PointMotion, solve
from flywheel.linkage.deadcentres import dead_centres, guide_frame, slider_dyad

DEFAULT_POINTS = 3600
MAX_POINTS = 100_000      # ≈ 0.5 GB of arrays; far past convergence (tests/dynamics/test_dynamics.py)


def closed_grid(n_points: int, extra: list[float], cycle: float = 2 * np.pi) -> np.ndarray:
    """Closed grid over the cycle [0, Φ] (``cycle`` Φ [rad]: 2π, or 4π for a four-stroke
    engine): n_points uniform intervals plus the extra angles [rad] (taken mod Φ; one closer than
    1e-9 rad to a node merges with it, the smaller one stays).

    >>> closed_grid(4, [1.0, 7.0]).round(4).tolist()
    [0.0, 0.7168, 1.0, 1.5708, 3.1416, 4.7124, 6.2832]
    >>> closed_grid(4, [7.0], cycle=4 * np.pi).round(4).tolist()
    [0.0, 3.1416, 6.2832, 7.0, 9.4248, 12.5664]
    """
    base = np.linspace(0.0, cycle, n_points + 1)
    extra = np.mod(np.asarray(extra, float), cycle)
    phi = np.sort(np.concatenate([base, extra]))   # np.union1d without its import of numpy.ma
    # merge nodes closer than 1e-9 rad (an extra angle that is already a node; equal ones too)
    keep = np.concatenate([[True], np.diff(phi) > 1e-9])
    phi = phi[keep]
    phi[-1] = cycle
    return phi


def grid_options(case, n_points: int, at_deg: list[float] | None) -> list[float]:
    """Check --points and --at; the report angles [deg] (default: the case's output.at_deg)."""
    if not 36 <= n_points <= MAX_POINTS:
        raise InputError(Notice.of(
            "points_range", "--points: {n} is out of range (allowed: 36 … {top}; results converge "
            "well before: the default {default} is within 1e-4 of a 4× finer grid)", n=n_points,
            top=MAX_POINTS, default=DEFAULT_POINTS))
    at_deg = list(case.output.at_deg if at_deg is None else at_deg)
    for a in at_deg:
        if not math.isfinite(a):
            raise InputError(Notice.of(
                "at_not_finite", "--at: {a} is not a finite angle in degrees", a=str(a)))
    return at_deg


def report_index(phi: np.ndarray, a_deg: float) -> int:
    """Grid index of the report angle ``a_deg`` [deg] (a node of the closed grid ``phi`` over
    the cycle, taken mod the cycle: 360°, or 720° for a four-stroke engine)."""
    return int(np.argmin(np.abs(phi - math.radians(a_deg) % (phi[-1] - phi[0]))))


def position_number(phi: float) -> int | None:
    """The course's number of the standard position at ``phi`` [rad]: k for φ = 30°·k (0 … 11,
    0 … 23 over a 720° cycle), as plan_positions.png numbers the crank's positions; None off
    the 30° grid (a slider's dead centre between two positions: drawn, not numbered)."""
    k = math.degrees(phi) / 30.0
    return int(round(k)) if abs(k - round(k)) < 1e-6 else None


def standard_positions(mech, cycle: float = 2 * np.pi) -> tuple[list[Position], dict]:
    """The standard positions over the cycle ``cycle`` [rad], by angle: every 30° (12 over 360°,
    24 over 720°, as course projects number them) and the dead centres of every slider in every
    revolution, a dead centre on a 30° position (or on another dead centre) sharing its row
    (label "90° = 3 outer d.c."). Returns ([Position], {slider: [DeadCentre] of one revolution})."""
    sliders = [d.slider for d in mech.dyads if hasattr(d, "guide")]
    dcs = {s: dead_centres(mech, s) for s in sliders}
    revs = int(round(cycle / (2 * np.pi)))
    positions = [Position(phi=math.radians(k * 30), number=position_number(math.radians(k * 30)),
                          standard_deg=k * 30) for k in range(12 * revs)]
    for s, lst in dcs.items():
        for dc in (replace(dc, phi=dc.phi + 2 * np.pi * r) for r in range(revs) for dc in lst):
            mark = DeadCentre(s, dc.kind)
            same = [i for i, p in enumerate(positions) if abs(p.phi - dc.phi) < 1e-9]
            if same:     # a dead centre on a standard position: one row, both names
                i = same[0]
                positions[i] = replace(positions[i], dead_centres=positions[i].dead_centres + (mark,))
            else:
                positions.append(Position(phi=dc.phi, number=position_number(dc.phi),
                                          dead_centres=(mark,)))
    positions.sort(key=lambda p: p.phi)
    return positions, dcs


def slider_frame(mech, dcs: dict, slider: str, near: str, what: str) -> tuple:
    """(dyad, guide unit vector u, guide base point, near dead centre, far dead centre) of a
    slider: ``near`` ('outer' or 'inner') names the dead centre that s is measured from (a
    cylinder's head, a force's reference). ``what`` names the load in the error."""
    d = slider_dyad(mech, slider)
    u, base = guide_frame(d)
    kinds = {dc.kind: dc for dc in dcs[slider]}
    if set(kinds) != {"outer", "inner"}:
        lead, sep, role = what.rpartition(": ")        # "cylinders HP: piston"
        raise InputError(led(lead + sep, Notice.of(
            "run_no_dead_centres", "{role} {slider} has no pair of dead centres", role=role,
            slider=slider)))
    a, b = kinds["outer"], kinds["inner"]
    return (d, u, base, a, b) if near == "outer" else (d, u, base, b, a)


def force_switch_angles(forces, mech, dcs: dict, phi: np.ndarray, kin: Kinematics) -> list[float]:
    """Crank angles [rad] where a technological force's slider reaches the ends of its s_range
    (the force switches on or off): found in the grid's intervals, refined by Newton's method
    on x(φ) with the exact analogue x' (4 steps: quadratic convergence from h ≤ 2π/36).
    ``forces``: the case's [[forces]]."""
    out: list[float] = []
    for f in forces:
        d, u, base, ref, other = slider_frame(mech, dcs, f.slider, f.reference, f"forces {f.name}: slider")
        x = (kin.points[d.joint].r - base) @ u
        for s_b in f.s_range:
            if not 0.0 < s_b < 1.0:
                continue                    # the dead centres are nodes already
            x_b = ref.x + s_b * (other.x - ref.x)
            i = loads.travel_crossings(x, x_b)
            if i.size == 0:
                continue
            a = 0.5 * (phi[i] + phi[i + 1])
            for _ in range(4):
                k = solve(mech, a)
                xa = (k.points[d.joint].r - base) @ u
                a = np.clip(a - (xa - x_b) / (k.points[d.joint].v_q @ u), phi[i], phi[i + 1])
            out += [float(v) for v in a]
    return out


def refined(mech, kin: Kinematics, phi: np.ndarray) -> Kinematics:
    """``kin`` moved onto the grid ``phi``: the nodes it has already are copied, only the new
    ones are solved. Every quantity of :func:`~flywheel.linkage.solve` is computed node by node,
    so this equals ``solve(mech, phi)`` bit for bit (tests/dynamics/test_dynamics.py checks it)."""
    pos = np.minimum(np.searchsorted(kin.phi, phi), kin.phi.size - 1)
    have = kin.phi[pos] == phi
    if have.all():
        new, src = None, pos
    else:
        new = solve(mech, phi[~have])
        src = np.where(have, pos, 0)                       # into kin's nodes, then new's
        src[~have] = kin.phi.size + np.arange(new.phi.size)

    def merge(old: np.ndarray | None, added) -> np.ndarray | None:
        if old is None:
            return None
        return np.take(old if new is None else np.concatenate((old, added)), src, axis=0)

    points, links = {}, {}
    for n, pm in kin.points.items():
        pn = new.points[n] if new is not None else pm
        points[n] = PointMotion(merge(pm.r, pn.r), merge(pm.v_q, pn.v_q), merge(pm.a_q, pn.a_q))
    for n, lm in kin.links.items():
        ln = new.links[n] if new is not None else lm
        links[n] = LinkMotion(merge(lm.theta, ln.theta), merge(lm.omega_q, ln.omega_q),
                              merge(lm.eps_q, ln.eps_q), lm.ref)
    return Kinematics(phi, points, links)


def linkage_grid(case, mech, dcs: dict, n_points: int, extra: list[float]) -> tuple[np.ndarray, Kinematics]:
    """The closed grid over the case's cycle (machine.cycle) with the ``extra`` angles [rad] as
    nodes, and the kinematics on it; the angles where a technological force switches on or off
    are added as nodes too (found on the first grid, then only those nodes are solved:
    :func:`refined`)."""
    cycle = case.machine.cycle
    phi = closed_grid(n_points, extra, cycle)
    kin = solve(mech, phi)
    sliding = [f for f in case.forces if f.slider is not None]
    if sliding or case.couples or case.springs:
        switch = (force_switch_angles(sliding, mech, dcs, phi, kin)
                  + applied.grid_nodes(case))       # ranges' ends, tables' rows (issue 24)
        if switch:
            phi = closed_grid(n_points, extra + switch, cycle)
            kin = refined(mech, kin, phi)
    return phi, kin
