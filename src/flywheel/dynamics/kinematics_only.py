"""The kinematics alone (issue 24, item 3): a linkage turned at the constant crank speed ω_m,
with no masses, loads or flywheel — positions, analogues, the true velocities and
accelerations of every point and link at the report angles and on the grid, the standard
positions, the output link and what the scheme draws. No dynamics and no refusal for a machine
without inertia: ω = ω_m, ε = 0 (the crank "turns uniformly" of textbook kinematics).

True values at constant speed: v = v_q·ω_m, a = a_q·ω_m², ω_i = ω_q·ω_m, ε_i = ε_q·ω_m²
(Артоболевский, «Теория механизмов и машин», гл. 4: the analogues of velocity and
acceleration; the ε·v_q terms vanish with ε = 0).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.dynamics.columns import kinematics_columns
from flywheel.dynamics.grid import (DEFAULT_POINTS, grid_options, linkage_grid, report_index,
                                    standard_positions)
from flywheel.dynamics.results import UNITS, Column, CycleGrid, LinkAt, PointAt, Position, json_ready
from flywheel.io.serialize import to_json
from flywheel.linkage.drawing import Drawing, describe, links_drawn
from flywheel.linkage.output_link import OutputLink, output_link


@dataclass(frozen=True, kw_only=True)
class KinematicsAt:
    """One report angle of a kinematics-only run: φ [deg], the crank's ω = ω_m [rad/s] and
    ε = 0 [rad/s²], every point and link (their true values at that constant speed)."""

    phi_deg: float
    omega: float
    epsilon: float
    points: dict[str, PointAt]
    links: dict[str, LinkAt]


@dataclass(frozen=True)
class KinematicPlans:
    """The velocity and acceleration plans at one report angle ``phi_deg`` [deg] (grid node
    ``index``) at ω_m, ε = 0 (:func:`flywheel.dynamics.plans.kinematic_plans`): what
    render/plots_plans.py draws of a PlanSet, without the force polygons and the lever."""

    phi_deg: float
    index: int
    velocity: object                         # dynamics.plans.KinematicPlan
    acceleration: object


@dataclass(frozen=True, kw_only=True)
class KinematicsHeadline:
    """summary.json's "results" of a kinematics-only run without "at"."""

    analysis: str = "kinematics"
    crank_length: float                  # [m]
    omega_mean: float                    # ω_m [rad/s], constant
    n_points: int                        # grid nodes
    cycle_deg: int                       # [deg]
    output_link: OutputLink | None = None


@dataclass(frozen=True)
class KinematicsResults(CycleGrid):
    """Everything a kinematics-only run computed; read by the renderers like
    :class:`flywheel.dynamics.results.Results` where the two share a name (``phi``,
    ``kinematics``, ``columns``, ``at``, ``position_angles``, ``drawing``, ``index_of``)."""

    analysis = "kinematics"                  # Results says "dynamics"

    title: str
    source: str
    phi: np.ndarray                          # the closed grid [rad]
    kinematics: object                       # flywheel.linkage.Kinematics
    omega_mean: float                        # [rad/s]
    columns: dict[str, Column]               # table.csv: φ and the kinematic columns
    at: tuple[KinematicsAt, ...]
    position_angles: tuple[Position, ...]
    links_drawn: tuple[tuple[str, tuple[str, ...]], ...]
    crank_length: float                      # [m]
    drawing: Drawing
    output_link: OutputLink | None = None
    plans: tuple[KinematicPlans, ...] = ()   # at the report angles
    warnings: tuple[str, ...] = ()

    @property
    def scalars(self) -> KinematicsHeadline:
        return KinematicsHeadline(crank_length=self.crank_length, omega_mean=self.omega_mean,
                                  n_points=int(self.phi.size), cycle_deg=self.cycle_deg,
                                  output_link=self.output_link)

    def to_document(self) -> dict:
        """The summary.json document (docs/results.md, "Kinematics alone")."""
        return json_ready({
            "title": self.title, "source": self.source, "units": UNITS,
            "results": {**to_json(self.scalars), "at": to_json(self.at)},
            "warnings": list(self.warnings)})


def at_constant_speed(at_deg: list[float], kin, omega: float) -> tuple[KinematicsAt, ...]:
    """The report angles' entries at the constant crank speed ``omega`` [rad/s]:
    v = v_q·ω, a = a_q·ω², ω_i = ω_q·ω, ε_i = ε_q·ω²."""
    out = []
    for a in at_deg:
        i = report_index(kin.phi, a)
        pts = {}
        for name, pm in kin.points.items():
            v_vec, a_vec = pm.v_q[i] * omega, pm.a_q[i] * omega**2
            pts[name] = PointAt(
                x=float(pm.r[i, 0]), y=float(pm.r[i, 1]),
                v_q=float(np.hypot(*pm.v_q[i])), a_q=float(np.hypot(*pm.a_q[i])),
                v=float(np.hypot(*v_vec)), a=float(np.hypot(*a_vec)),
                v_x=float(v_vec[0]), v_y=float(v_vec[1]), a_x=float(a_vec[0]), a_y=float(a_vec[1]))
        lks = {name: LinkAt(omega_q=float(lm.omega_q[i]), epsilon_q=float(lm.eps_q[i]),
                            omega=float(lm.omega_q[i] * omega),
                            epsilon=float(lm.eps_q[i] * omega**2))
               for name, lm in kin.links.items()}
        out.append(KinematicsAt(phi_deg=float(a), omega=float(omega), epsilon=0.0, points=pts,
                                links=lks))
    return tuple(out)


def analyze_kinematics(case, n_points: int = DEFAULT_POINTS,
                       at_deg: list[float] | None = None) -> KinematicsResults:
    """The kinematics of a validated linkage case (:class:`flywheel.cases.run.Case`) at its
    constant speed ω_m over its cycle; the report angles, standard positions and dead centres
    are grid nodes. Raises AssemblyError where the mechanism cannot be assembled."""
    at_deg = grid_options(case, n_points, at_deg)
    mech = case.mechanism()
    positions, dcs = standard_positions(mech, case.machine.cycle)
    phi, kin = linkage_grid(case, mech, dcs, n_points,
                            [p.phi for p in positions] + [math.radians(a) for a in at_deg])
    w = case.machine.omega_mean
    from flywheel.dynamics.plans import kinematic_plans

    plans = []
    for a in at_deg:
        i = report_index(kin.phi, a)
        plans.append(KinematicPlans(float(a), i, *kinematic_plans(mech, kin, i, w, 0.0, float(a))))
    return KinematicsResults(
        title=case.title, source=case.source, phi=phi, kinematics=kin, omega_mean=w,
        columns=kinematics_columns(phi, kin, mech.crank.name, w),
        at=at_constant_speed(at_deg, kin, w), position_angles=tuple(positions),
        links_drawn=links_drawn(mech), crank_length=float(mech.crank.length),
        drawing=describe(mech, kin), output_link=output_link(mech), plans=tuple(plans))
