"""Four-stroke cylinders: where each fires in the 720° cycle, and its gas force stroke by stroke.

A four-stroke cylinder's cycle is two revolutions: expansion (the working stroke) from the
head dead centre where it fires, exhaust, intake, compression (Артоболевский, «Теория
механизмов и машин», the dynamics of a machine with an internal-combustion engine; the
cycle Φ = 4π). Each stroke reads its own indicator table against the relative travel s from
the head (:func:`flywheel.dynamics.loads.four_stroke_pressure`); the gas force pushes the piston
away from the head as in any cylinder. Where each cylinder fires is set by a firing order
(``machine.firing_order``: each fires at its first head dead centre after the one before) or
by each cylinder's ``fires_at_deg``.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics import loads as L
from flywheel.dynamics.grid import slider_frame
from flywheel.dynamics.results import CylinderResult
from flywheel.errors import InputError, Notice, led

_TWO_REV = 4 * np.pi
_SAME = 1e-9            # rad: two firings closer than this are the same instant


def _head_centre(mech, dcs: dict, cy) -> float:
    """The crank angle [rad, 0 … 2π) of the cylinder's head dead centre."""
    return slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")[3].phi


def _deg(phi: float) -> str:
    return f"{math.degrees(phi):.6g}°"


def firing_angles(case, mech, dcs: dict) -> dict[str, float]:
    """φ_f [rad, 0 … 4π) of each four-stroke cylinder of ``case``: the head dead centre that
    begins its expansion stroke.

    With ``machine.firing_order`` the first cylinder of the order fires at its head dead centre
    nearest to its ``fires_at_deg`` (default: in the first revolution), and each next one at
    its first head dead centre after the one before; the order must go round the cycle once
    (every firing before the first cylinder's next one). Without an order, each cylinder fires
    at its head dead centre nearest to its ``fires_at_deg`` (default: in the first revolution).
    Raises InputError naming the field for an order that does not fit the crank's pins, or a
    ``fires_at_deg`` far (more than 90°) from a head dead centre."""
    four = [c for c in case.cylinders if c.four_stroke]
    idx = {c.name: i for i, c in enumerate(case.cylinders)}
    heads = {c.name: _head_centre(mech, dcs, c) for c in four}

    def nearest(c) -> float:
        h = heads[c.name]
        if c.fires_at_deg is None:
            return h
        want = math.radians(c.fires_at_deg) % _TWO_REV
        best = min((h, h + 2 * np.pi), key=lambda a: abs((want - a + np.pi * 2) % _TWO_REV - 2 * np.pi))
        gap = abs((want - best + 2 * np.pi) % _TWO_REV - 2 * np.pi)
        if gap > np.pi / 2 + 1e-12:
            raise InputError(led(f"cylinders[{idx[c.name]}].fires_at_deg: ", Notice.of(
                "run_fires_far", "{deg:g}° is {gap:.4g}° from the nearest head dead centre of "
                "piston {piston} ({h1}, {h2}): a cylinder fires at its head dead centre (allowed: "
                "within 90° of one)", deg=c.fires_at_deg, gap=math.degrees(gap), piston=c.piston,
                h1=_deg(h), h2=_deg(h + 2 * np.pi))))
        return best

    order = case.machine.firing_order
    if order is None:
        return {c.name: nearest(c) for c in four}
    by_name = {c.name: c for c in four}
    first = nearest(by_name[order[0]])
    out = {order[0]: first}
    prev = first
    for k, name in enumerate(order[1:], start=1):
        h = heads[name]
        step = (h - prev) % (2 * np.pi)          # its next head dead centre after `prev`
        if step < _SAME:
            step += 2 * np.pi
        at = prev + step
        if at >= first + _TWO_REV - _SAME:
            listing = ", ".join(f"{n} at {_deg(heads[n])}/{_deg(heads[n] + 2 * np.pi)}" for n in order)
            raise InputError(Notice.of(
                "firing_order_fit", "machine.firing_order: {order} does not fit in one 720° "
                "cycle: cylinder {name} (position {position}) would fire at {at}, not before "
                "cylinder {first} fires again at {again} (allowed: an order in which each "
                "cylinder reaches its head dead centre after the one before, all within 720°; the "
                "head dead centres: {listing})", order="-".join(order), name=name, position=k + 1,
                at=_deg(at), first=order[0], again=_deg(first + _TWO_REV),
                heads=[(n, _deg(heads[n]), _deg(heads[n] + 2 * np.pi)) for n in order],
                listing=listing))
        out[name] = at
        prev = at
    return {n: a % _TWO_REV for n, a in out.items()}


def four_stroke_cylinder(cy, mech, dcs: dict, kin, fires_at: float) -> CylinderResult:
    """A four-stroke cylinder on the grid of ``kin``: the stroke at each node
    (:func:`~flywheel.dynamics.loads.four_stroke_index`), p = p_max·(its table at s), the gas
    force F = p·πd²/4 away from the head and its reduced moment (seed 000 §3.2.4–3.2.6, with
    four tables instead of two). ``fires_at`` [rad]: where it fires (:func:`firing_angles`)."""
    d, u, base, head, far = slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")
    P = kin.points[d.joint]
    x, x_dot = (P.r - base) @ u, P.v_q @ u
    tables = {k: (np.asarray(a, float), np.asarray(b, float))
              for k, (a, b) in cy.stroke_tables().items()}
    s = L.relative_travel(x, head.x, far.x)
    stroke = L.four_stroke_index(kin.phi, fires_at, (far.phi - head.phi) % (2 * np.pi))
    p = L.four_stroke_pressure(s, stroke, tables, cy.interpolation) * cy.p_max
    F = p * np.pi * cy.bore**2 / 4
    M = L.gas_moment(F, x_dot, head.x, far.x)
    towards = (stroke == 1) | (stroke == 3)
    s_exp, p_exp = tables["expansion"]      # the two-table fields: compression and expansion
    return CylinderResult(cy.name, cy.piston, s, towards, p, F, M, s_exp,  # at expansion's s
                          np.interp(s_exp, *tables["compression"]), p_exp, cy.p_max, head.phi,
                          stroke=stroke, stroke_tables={k: v[1] for k, v in tables.items()},
                          fires_at=float(fires_at),
                          stroke_s={k: v[0] for k, v in tables.items()}, label=cy.label)


# -- the gas work, exact for piecewise-linear tables -------------------------------------------

def table_integral(s_table: np.ndarray, p_table: np.ndarray, s: np.ndarray) -> np.ndarray:
    """G(s) = ∫ p(σ) dσ from s_table[0] to s [-] of the piecewise-linear table (s_table, p_table)
    (s clipped to the table's span, as :func:`~flywheel.dynamics.loads.interpolate_table`
    reads it): the whole segments' trapezoids, plus the part of the segment holding s,
    p_i·t + ½·(Δp/Δs)·t² with t = s − s_i — exact, the integrand being linear there.

    >>> table_integral(np.array([0.0, 0.5, 1.0]), np.array([0.0, 1.0, 0.0]), np.array([0.25, 1.0])).tolist()
    [0.0625, 0.5]
    """
    s_table, p_table = np.asarray(s_table, float), np.asarray(p_table, float)
    s = np.clip(np.asarray(s, float), s_table[0], s_table[-1])
    h = np.diff(s_table)
    whole = np.concatenate([[0.0], np.cumsum(0.5 * (p_table[1:] + p_table[:-1]) * h)])
    i = np.clip(np.searchsorted(s_table, s, side="right") - 1, 0, s_table.size - 2)
    t = s - s_table[i]
    return whole[i] + p_table[i] * t + 0.5 * (p_table[i + 1] - p_table[i]) / h[i] * t**2


def exact_gas_work(s: np.ndarray, table_of_interval: np.ndarray, tables: list, scale: float
                   ) -> np.ndarray:
    """Cumulative work A(φ) [J] of a gas force on the grid, exact for piecewise-linear tables:
    in each interval the piston moves one way inside one stroke (the dead centres are nodes of
    the grid), so the force p_max·(πd²/4)·p(s) pushing it away from the head does
    scale·(G(s_{i+1}) − G(s_i)) there (:func:`table_integral` of the interval's table;
    scale = p_max·πd²/4·|x_far − x_head| [J]): ∮p dV over the cycle, whatever the grid. The
    trapezoid rule on M = F·x′ is only second-order over the kinks of a table (issue 24).
    s: the nodes' relative travel; table_of_interval: index into ``tables`` [(s, p/p_max)] of
    the table in force in each interval."""
    dW = np.zeros(s.size - 1)
    for k, (s_tab, p_tab) in enumerate(tables):
        G = table_integral(s_tab, p_tab, s)
        on = table_of_interval == k
        dW[on] = (G[1:] - G[:-1])[on]
    return np.concatenate([[0.0], np.cumsum(scale * dW)])


def gas_work(cy, mech, dcs: dict, kin, cr: CylinderResult) -> np.ndarray | None:
    """The exact cumulative work [J] of cylinder ``cy`` on the grid of ``kin``
    (:func:`exact_gas_work`) when its tables are piecewise-linear (``interpolation = "linear"``),
    else None (the trapezoid rule on its moment stays). ``cr``: its result on the grid. A
    two-table cylinder reads away_from_head while s grows in an interval and towards_head while
    it falls; a four-stroke one the table of the stroke at the interval's middle."""
    if cy.interpolation != "linear":
        return None
    _, _, _, head, far = slider_frame(mech, dcs, cy.piston, cy.head, f"cylinders {cy.name}: piston")
    scale = cy.p_max * np.pi * cy.bore**2 / 4 * abs(far.x - head.x)
    if cr.stroke is None:
        tables = [(cr.table_s, cr.table_away), (cr.table_s, cr.table_towards)]
        which = (np.diff(cr.s) < 0).astype(int)
    else:
        tables = [(cr.stroke_s[n], cr.stroke_tables[n]) for n in L.FOUR_STROKES]
        middle = 0.5 * (kin.phi[1:] + kin.phi[:-1])
        which = L.four_stroke_index(middle, cr.fires_at, (far.phi - head.phi) % (2 * np.pi))
    return exact_gas_work(cr.s, which, tables, scale)
