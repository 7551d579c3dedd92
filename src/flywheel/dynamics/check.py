"""`flywheel check`: what a case describes and the numbers that show it is sound — the
mechanism assembled over the whole cycle, each slider's dead centres and stroke, and the
analogues at the dead centres; for a tabulated case its per-position Мст, J_II, dJ_II/dφ and
Мдин. Computed here, printed by :mod:`flywheel.render.check`.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class SliderCheck:
    """A slider on a fixed guide: its dead centres (by angle) and stroke."""

    slider: str
    dead_centres: tuple            # flywheel.linkage.deadcentres.DeadCentre: φ [rad], x [m], kind
    stroke: float                  # distance between the extreme dead centres [m]; 0 if < 2


@dataclass(frozen=True)
class TabulatedCheck:
    """A tabulated case reduced to the crank at each row (position) of its table."""

    static_moments: np.ndarray     # Мст [N·m] (seed 004: resisting positive)
    J_II: np.ndarray               # Iпр [kg·m²] (seed 004, eq. 7)
    dJ_II: np.ndarray              # dJ_II/dφ [kg·m²/rad] by the table's interpolation
    dynamic_moments: np.ndarray    # Мдин = ω_m²/2·dJ_II/dφ [N·m] (seed 004, eq. 6)


@dataclass(frozen=True)
class CheckReport:
    """Everything `flywheel check` prints about a valid case."""

    case: object                   # the validated case (flywheel.cases.run.Case)
    crank_speed_rps: float         # n1 = ω_m/2π [rev/s]
    mechanism: object = None       # flywheel.linkage.Mechanism; None for a tabulated case
    sliders: tuple[SliderCheck, ...] = ()
    dead_centre_angles: tuple[float, ...] = ()   # the distinct dead-centre angles, sorted [rad]
    point_analogues: dict | None = None   # point → (|v_q| [m/rad], |a_q| [m/rad²]) at those angles
    link_analogues: dict | None = None    # link → (ω_q [-], ε_q [1/rad]) at those angles
    tabulated: TabulatedCheck | None = None
    firing_deg: dict | None = None        # four-stroke cylinder → where it fires [deg], in order
    output_link: object = None            # flywheel.linkage.output_link.OutputLink, or None


def check_case(case) -> CheckReport:
    """The :class:`CheckReport` of a validated case. Raises AssemblyError (from the kinematics)
    if the mechanism cannot be assembled at some angle of the cycle (checked on 721 angles),
    and whatever error ``flywheel run`` would raise (loads whose cycle work has the wrong sign
    for the balance, a machine without inertia, …): the analysis is run on a coarse grid
    (360 intervals), so a case that `check` calls valid also runs."""
    from flywheel.dynamics.pipeline import analyze

    n1 = case.machine.omega_mean / (2 * math.pi)
    if case.kinematics_only:                       # no dynamics to run (kinematics_only.py)
        from flywheel.dynamics.kinematics_only import analyze_kinematics

        headline = analyze_kinematics(case, n_points=360).scalars
    else:
        headline = analyze(case, n_points=360).scalars
    firing = None if case.kinematics_only else headline.firing_deg
    if case.tabulated is not None:
        return CheckReport(case=case, crank_speed_rps=n1, tabulated=_tabulated(case))

    from flywheel.linkage import solve
    from flywheel.linkage.deadcentres import dead_centres

    mech = case.mechanism()
    solve(mech, np.linspace(0, 2 * np.pi, 721))   # assembles over the whole cycle, or raises
    sliders, angles = [], []
    for s in (d.slider for d in mech.dyads if hasattr(d, "guide")):
        dcs = dead_centres(mech, s)
        for dc in dcs:
            if not any(abs(dc.phi - a) < 1e-9 for a in angles):
                angles.append(dc.phi)
        stroke = (max(dc.x for dc in dcs) - min(dc.x for dc in dcs)) if len(dcs) > 1 else 0.0
        sliders.append(SliderCheck(s, tuple(dcs), stroke))
    points = links = None
    if angles:
        angles.sort()
        k = solve(mech, np.array(angles))
        n = len(angles)
        points = {name: (np.array([np.linalg.norm(pm.v_q[i]) for i in range(n)]),
                         np.array([np.linalg.norm(pm.a_q[i]) for i in range(n)]))
                  for name, pm in k.points.items()}
        links = {name: (lm.omega_q, lm.eps_q) for name, lm in k.links.items()}
    return CheckReport(case=case, crank_speed_rps=n1, mechanism=mech, sliders=tuple(sliders),
                       dead_centre_angles=tuple(angles), point_analogues=points,
                       link_analogues=links, firing_deg=firing, output_link=headline.output_link)


def _tabulated(case) -> TabulatedCheck:
    from flywheel.dynamics.tabulated import (dynamic_moments, inertia_derivative_at_positions,
                                             reduced_inertia_at_positions, static_moments)

    tab = case.tabulated
    return TabulatedCheck(static_moments=static_moments(tab), J_II=reduced_inertia_at_positions(tab),
                          dJ_II=inertia_derivative_at_positions(tab),
                          dynamic_moments=dynamic_moments(tab, case.machine.omega_mean))
