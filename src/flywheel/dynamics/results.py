"""The results of one analysis: one typed, frozen result per stage, and the run's Results.

The stages (:mod:`flywheel.dynamics.stages`, the linkage route :mod:`~flywheel.dynamics.pipeline`
and the tabulated route :mod:`~flywheel.dynamics.tabulated`) fill them; renderers read them and
compute nothing. SI units throughout; angles in radians unless a name ends in ``_deg``. Arrays
are on the run's closed φ grid (``Results.phi``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from flywheel.dynamics.loads import LoadKey
from flywheel.io.serialize import json_schema, to_json
from flywheel.dynamics.sizing import RimDesign
from flywheel.dynamics.asks import Roots, Snapshot, TravelAt
from flywheel.dynamics.start import StartResult
from flywheel.linkage.drawing import Drawing
from flywheel.linkage.output_link import OutputLink

UNITS = "SI (m, kg, s, rad, N, N·m, J, kg·m²); angles *_deg in degrees"


@dataclass(frozen=True)
class Column:
    """An array on the grid with its SI unit (its name: render/nomenclature.py, by key)."""

    values: np.ndarray
    unit: str


@dataclass(frozen=True)
class CylinderResult:
    """One cylinder on the grid and its indicator tables."""

    name: str
    piston: str                 # the piston's slider link
    s: np.ndarray               # relative travel from the head dead centre [-], 0 … 1
    towards_head: np.ndarray    # bool: the piston moves towards the head
    p: np.ndarray               # gas pressure [Pa]
    F: np.ndarray               # gas force on the piston [N]
    M: np.ndarray               # its reduced moment [N·m]
    table_s: np.ndarray         # indicator table: relative travel [-]
    table_towards: np.ndarray   # p/p_max [-] while moving towards the head
    table_away: np.ndarray      # p/p_max [-] while moving away from it
    p_max: float                # [Pa]
    head_phi: float             # crank angle of the head dead centre [rad]
    # a four-stroke cylinder (None for two tables, one per direction): the stroke at each node,
    # an index into flywheel.dynamics.loads.FOUR_STROKES (intake, compression, expansion,
    # exhaust); each stroke's table p/p_max [-] at its travels stroke_s [-]; where it fires
    # [rad, 0 … 4π). table_s, table_towards, table_away then hold expansion's travels and the
    # compression and expansion tables at them.
    stroke: np.ndarray | None = None
    stroke_tables: dict[str, np.ndarray] | None = None
    fires_at: float | None = None
    stroke_s: dict[str, np.ndarray] | None = None
    label: str = ""             # its short name in the documents (io.text.Text in two
    #                             languages, or a string); "": its name


@dataclass(frozen=True)
class LoadsResult:
    """The given loads reduced to the crank (design.md §2; seed 000 §3.2)."""

    M_parts: dict[LoadKey, np.ndarray]  # load key (gas HP, force punch, gravity 2, spring s,
    #                                  couple c, moment m) → reduced moment [N·m]
    W_parts: dict[LoadKey, np.ndarray]  # load key → its cumulative work A(φ) [J], exact, for the
    #                                  loads whose work the trapezoid rule gets only to first
    #                                  order (technological forces switching inside an interval)
    cylinders: tuple[CylinderResult, ...] = ()
    forces: dict[str, np.ndarray] = field(default_factory=dict)  # technological force → F(φ) [N]
    warnings: tuple[str, ...] = ()
    tensions: dict[str, np.ndarray] = field(default_factory=dict)  # linear spring → T(φ) [N]
    titles: dict[LoadKey, str] = field(default_factory=dict)  # a load's own title (io.text.Text
    #                                  in two languages), where the case gives one

    @property
    def labels(self) -> dict[LoadKey, str]:
        """Each labelled cylinder's gas load → its label (io.text.Text or a string), for the
        load's name («газ ВД»)."""
        return {LoadKey("gas", c.name): c.label for c in self.cylinders if c.label}


@dataclass(frozen=True)
class ReductionResult:
    """Reduction of masses: J_II and its derivative, with each link's share (seed 000 §3.1)."""

    J_parts: dict[str, np.ndarray]    # link → its share of J_II [kg·m²]
    dJ_parts: dict[str, np.ndarray]   # link → its share of dJ_II/dφ [kg·m²/rad]
    J_II: np.ndarray                  # reduced inertia of the second group [kg·m²]
    dJ_II: np.ndarray                 # dJ_II/dφ [kg·m²/rad]
    J_II_mean: float                  # cycle mean (1/Φ)∮J_II dφ [kg·m²]
    J_II_min: float                   # [kg·m²]
    J_II_max: float                   # [kg·m²]
    warnings: tuple[str, ...] = ()


@dataclass(frozen=True)
class EnergyResult:
    """Works and kinetic energy over the cycle (Merzalov's method, seed 000 §3.2.7, §4)."""

    balance: str                     # "driving" or "resistance": what the constant moment is
    M_known: np.ndarray              # Σ reduced moments of the given loads [N·m]
    balancing_moment: float          # the constant moment that closes the cycle's work [N·m]
    M_sum: np.ndarray                # M_known + balancing_moment = M_Σ [N·m]
    A_D: np.ndarray                  # work of the driving moment [J]
    A_C: np.ndarray                  # work of the resistance [J]
    A: np.ndarray                    # total work A = A_D + A_C [J]
    cycle_work_resistance: float     # A_C over the cycle [J] (negative)
    driving_moment: float            # cycle mean of the driving moment M_D [N·m]
    T_II: np.ndarray                 # kinetic energy of the second group J_II·ω_m²/2 [J]
    dT_I: np.ndarray                 # change of kinetic energy of the first group ΔT_I [J]
    delta_T_I_max: float             # global maximum of ΔT_I [J] …
    phi_delta_T_I_max: float         # … at this angle [rad]
    delta_T_I_min: float             # global minimum of ΔT_I [J] …
    phi_delta_T_I_min: float         # … at this angle [rad]
    delta_T_max: float               # ΔT_нб = max − min [J]
    power: float | None = None       # machine.power, the given mean power [W]
    power_moment: float | None = None      # P/ω_m, the mean moment it means [N·m]
    power_from_loads: float | None = None  # |balancing_moment|·ω_m, the loads' power [W]
    warnings: tuple[str, ...] = ()


@dataclass(frozen=True)
class FlywheelShape:
    """A flywheel as a solid disk (``D_inner`` None) or a rim."""

    D: float                          # outer diameter [m]
    b: float                          # width [m]
    mass: float                       # [kg]
    D_inner: float | None = None      # inner diameter of a rim [m]
    rim_speed: float | None = None    # peripheral speed at ω_max [m/s] (after the motion)

    DOCUMENT = ("D", "D_inner", "b", "mass", "rim_speed")   # summary.json's flywheel_disk / _rim

    def as_dict(self) -> dict:
        """summary.json's flywheel_disk / flywheel_rim."""
        return to_json(self)


@dataclass(frozen=True)
class SizingResult:
    """The flywheel for the coefficient of speed fluctuation δ (seed 000 §4; design.md §2)."""

    omega_mean: float            # ω_m [rad/s]
    delta: float                 # target δ [-] (a given flywheel: the δ it gives)
    J_required: float            # J_I by Merzalov: ΔT_нб/(ω_m²·δ) [kg·m²]
    J_first_group: float         # inertia already on the crank shaft [kg·m²]
    J_flywheel: float            # J_required − J_first_group [kg·m²] (≤ 0: none needed)
    J_required_exact: float      # J_I of the energy–mass diagram (Wittenbauer) [kg·m²]
    J_flywheel_exact: float      # J_required_exact − J_first_group [kg·m²]
    T0_exact: float              # initial total kinetic energy with the exact J_I [J]
    k_plus: float                # slope of the upper tangent ω_max²/2 = ω_m²(1 + δ/2)²/2 [J/(kg·m²)]
    k_minus: float               # slope of the lower tangent ω_min²/2 [J/(kg·m²)]
    T_k: float                   # where the upper tangent cuts J_II = 0 (point k) [J]
    T_l: float                   # where the lower tangent cuts it (point l) [J]
    i_tangent_max: int           # grid index of the upper tangency point (ψ_max)
    i_tangent_min: int           # grid index of the lower one (ψ_min)
    speed_ratio: float           # flywheel shaft speed / crank speed [-]
    J_on_its_shaft: float        # max(J_flywheel, 0)/i² [kg·m²]
    rim_share: float             # share of J on its shaft carried by the rim [-]
    disk: FlywheelShape
    rim: FlywheelShape
    material: str
    material_density: float      # ρ [kg/m³]
    rim_speed_limit: float       # √(σ/ρ) [m/s]
    formulas: str                # "first-principles" or "course"
    rim_design: RimDesign | None = None   # the rim of [flywheel.rim] (replaces ``rim`` in
    #                                       summary.json's flywheel_rim)
    flywheel_given: bool = False          # the flywheel was given (not sized): δ is its δ
    J_flywheel_given: float | None = None  # the given flywheel's J on its own shaft [kg·m²]
    warnings: tuple[str, ...] = ()


@dataclass(frozen=True)
class MotionResult:
    """The true motion of the crank with the flywheel (the energy equation)."""

    J_I: float                   # inertia on the crank shaft: max(J_required, J_first_group) [kg·m²]
    T0: float                    # initial kinetic energy giving (ω_max + ω_min)/2 = ω_m [J]
    omega: np.ndarray            # ω(φ) [rad/s]
    epsilon: np.ndarray          # ε(φ) [rad/s²]
    t: np.ndarray                # t(φ) [s]
    omega_exact: np.ndarray      # ω(φ) with the exact flywheel [rad/s]
    omega_max: float             # [rad/s] …
    phi_omega_max: float         # … at [rad]
    omega_min: float             # [rad/s] …
    phi_omega_min: float         # … at [rad]
    delta_achieved: float        # δ with J_I [-]
    delta_achieved_exact: float  # δ with the exact J_I [-]
    cycle_time: float            # t over the cycle [s]
    warnings: tuple[str, ...] = ()


@dataclass(frozen=True, kw_only=True)
class Verification:
    """The steady motion integrated in time (timedomain.verify_steady): over ``cycles`` cycles,
    the relative repeat error of the cycle start speeds [-], the largest relative deviation
    from ω(φ) [-], and the period [s]."""

    cycles: int
    repeat_error: float
    max_deviation: float
    period: float


@dataclass(frozen=True, kw_only=True)
class StartupNotComputed:
    """No start-up: the case has no [motor] (``reason`` says why)."""

    computed: bool = False
    reason: str


@dataclass(frozen=True, kw_only=True)
class StartupStalled:
    """The motor cannot start the machine: it stops at ``stall_angle_deg`` [deg] after
    ``time`` [s] (timedomain.startup); the motor line's M_п [N·m] and ω_x [rad/s]."""

    stalled: bool = True
    converged: bool = False
    stall_angle_deg: float
    time: float
    omega_final_predicted: float | None      # the motor line's steady speed [rad/s]
    time_constant: float | None              # τ = J̄/(M_п/ω_x) [s]
    warning: str
    starting_torque: float
    no_load_speed: float

    KEEP_NONE = ("omega_final_predicted", "time_constant")

    @property
    def computed(self) -> bool:
        return True


@dataclass(frozen=True, kw_only=True)
class StartupRun:
    """The start-up from rest (timedomain.startup): the cycles run and their time [s], the last
    cycle-mean speed [rad/s]; converged: when [s] and after how many cycles the cycle means
    enter the band ±δ/10 for good and their limit [rad/s] (None when not converged, then
    ``warning`` says how far it got); the motor line's M_п [N·m] and ω_x [rad/s]."""

    stalled: bool = False
    converged: bool
    omega_final_predicted: float | None
    time_constant: float | None
    omega_mean_last: float
    cycles_run: int
    time_run: float
    time_to_steady: float | None = None
    cycles_to_steady: int | None = None
    omega_mean_steady: float | None = None
    warning: str | None = None
    starting_torque: float
    no_load_speed: float

    KEEP_NONE = ("omega_final_predicted", "time_constant", "time_to_steady", "cycles_to_steady",
                 "omega_mean_steady")

    @property
    def computed(self) -> bool:
        return True


@dataclass(frozen=True, kw_only=True)
class Rundown:
    """The run-down after the drive is cut (timedomain.rundown): time [s] and crank rotation
    [deg] to standstill; ``reason`` why it never runs down (then ``stopped`` is False)."""

    stopped: bool
    time: float
    angle_deg: float
    reason: str | None = None


@dataclass(frozen=True)
class TimeDomainResult:
    """--transients: the equation of motion integrated in time (see
    :mod:`flywheel.dynamics.timedomain`) and the histories for the plots."""

    verification: Verification
    startup: StartupNotComputed | StartupStalled | StartupRun
    rundown: Rundown
    histories: dict              # "startup" / "rundown" → (t [s], ω [rad/s])
    startup_cycle_means: tuple | None = None   # (t [s], cycle-mean ω [rad/s]) of the start-up
    warnings: tuple[str, ...] = ()

    DOCUMENT = ("verification", "startup", "rundown")      # summary.json's results.time_domain

    def as_dict(self) -> dict:
        """summary.json's results.time_domain."""
        return to_json(self)


@dataclass(frozen=True)
class TabulatedResult:
    """What the tabulated route adds: the table's kinematics on the grid and the seed's
    static and dynamic moments (seed 004)."""

    interpolation: str                # J_II's interpolation kind
    positions_deg: tuple[float, ...]  # the table's crank positions [deg]
    v_q: dict[str, np.ndarray]        # point → |V_q| [m], interpolated
    omega_q: dict[str, np.ndarray]    # link → |ω_q| [-], interpolated
    M_st: np.ndarray                  # static moment Мст = −M_known (resisting positive) [N·m]
    M_dyn: np.ndarray                 # dynamic moment Мдин = ω_m²/2·dJ_II/dφ [N·m]


@dataclass(frozen=True)
class DeadCentre:
    """A slider's dead centre at a standard position: the slider link and which end of its
    travel, "outer" or "inner" (flywheel.linkage.deadcentres)."""

    slider: str
    kind: str


@dataclass(frozen=True, kw_only=True)
class Position:
    """A standard position of the run (positions.csv, the report's tables, plan_positions.png):
    the crank angle φ [rad]; the course's number (:func:`flywheel.dynamics.grid.position_number`:
    0 … 11 every 30°, 0 … 23 over 720°; None off the 30° grid and for a tabulated case); the
    30° position's angle [deg] it is (None for a dead centre between them); the sliders' dead
    centres there; a tabulated case's row (1-based) and its angle [deg] instead."""

    phi: float
    number: int | None = None
    standard_deg: int | None = None
    dead_centres: tuple[DeadCentre, ...] = ()
    table_row: int | None = None
    table_deg: float | None = None

    def parts(self) -> tuple[str | DeadCentre, ...]:
        """What the position is, in order: the angle ("90°") or the table's row ("2 (30°)"),
        then each dead centre; the label joins them with " = "."""
        head = (() if self.standard_deg is None else (f"{self.standard_deg}°",)) + (
            () if self.table_row is None else (f"{self.table_row} ({self.table_deg:g}°)",))
        return head + self.dead_centres

    @property
    def label(self) -> str:
        """The English label, positions.csv's ``position``: "90°", "90° = 3 outer d.c.",
        "5 inner d.c.", a table's "2 (30°)"."""
        return " = ".join(p if isinstance(p, str) else f"{p.slider} {p.kind} d.c."
                          for p in self.parts())


@dataclass(frozen=True, kw_only=True)
class PointAt:
    """A point at a report angle (summary.json's results.at[k].points): position [m], the
    analogues |v_q| [m/rad] and |a_q| [m/rad²], the true speed [m/s] and acceleration [m/s²] and
    their components. A tabulated case gives only v_q and v (the rest None, left out)."""

    x: float | None = None
    y: float | None = None
    v_q: float
    a_q: float | None = None
    v: float
    a: float | None = None
    v_x: float | None = None
    v_y: float | None = None
    a_x: float | None = None
    a_y: float | None = None


@dataclass(frozen=True, kw_only=True)
class LinkAt:
    """A link at a report angle: the analogues ω_q [-], ε_q [1/rad] and the true ω [rad/s],
    ε [rad/s²]. A tabulated case gives only omega_q and omega."""

    omega_q: float
    epsilon_q: float | None = None
    omega: float
    epsilon: float | None = None


@dataclass(frozen=True)
class VectorAt:
    """A force at a report angle: magnitude |F| [N], components [N], its angle from +x,
    counter-clockwise, in (−180°, 180°] [deg]."""

    F: float
    Fx: float
    Fy: float
    angle_deg: float

    @classmethod
    def of(cls, x: float, y: float) -> VectorAt:
        """The force (x, y) [N]."""
        return cls(math.hypot(x, y), x, y, math.degrees(math.atan2(y, x)))


@dataclass(frozen=True, kw_only=True)
class JointAt:
    """A joint reaction at a report angle (docs/forces.md): at ``point``, of link ``by`` on
    link ``on``; for a sliding pair also the normal force [N] and its offset along the guide [m]."""

    point: str
    by: str
    on: str
    F: float
    Fx: float
    Fy: float
    angle_deg: float
    normal: float | None = None
    offset: float | None = None


@dataclass(frozen=True, kw_only=True)
class CrankPinAt:
    """The links' force on the crank pin [N] with its parts along the pin's velocity
    (tangential, positive drives) and along the crank towards the shaft (radial)."""

    F: float
    Fx: float
    Fy: float
    angle_deg: float
    tangential: float
    radial: float


@dataclass(frozen=True, kw_only=True)
class SliderCrankAt:
    """The slider-crank quantities of one slider at a report angle [N; N·m] (forces.SliderCrank)."""

    rod: str
    piston_effort: float
    side_thrust: float
    rod_thrust: float
    crank_pin_x: float
    crank_pin_y: float
    crank_pin_tangential: float
    crank_pin_radial: float
    turning_moment: float


@dataclass(frozen=True, kw_only=True)
class BalancingMomentAt:
    """M_y at a report angle [N·m]: kinetostatic, by Zhukovsky's lever, by the power balance
    (a tabulated case: the power balance only); ``groups``: the moment the crank delivers to
    the Assur groups, without the first group's inertia, M_y − J_I·ε (kinetostatic)."""

    kinetostatic: float | None = None
    zhukovsky: float | None = None
    power: float
    groups: float | None = None


@dataclass(frozen=True, kw_only=True)
class AtAngle:
    """One report angle (summary.json's results.at[k], docs/results.md): the crank's ω [rad/s]
    and ε [rad/s²], J_II [kg·m²] and dJ_II/dφ, M_Σ and each load's reduced moment [N·m]
    (by load name), the given forces [N], every point and link; a tabulated case adds the
    seed's M_st and M_dyn and has no forces. With a force analysis: M_y three ways, the joint
    reactions from the crank outwards, the slider-crank quantities, the main bearing's and the
    crank pin's loads, the shaking force and moment."""

    phi_deg: float
    omega: float
    epsilon: float
    J_II: float
    dJ_II: float
    M_sum: float
    M_st: float | None = None
    M_dyn: float | None = None
    moments: dict[str, float]
    forces: dict[str, float] | None = None
    points: dict[str, PointAt]
    links: dict[str, LinkAt]
    balancing_moment: BalancingMomentAt | None = None
    joints: dict[str, JointAt] | None = None
    slider_crank: dict[str, SliderCrankAt] | None = None
    main_bearing_load: VectorAt | None = None
    crank_pin_load: CrankPinAt | None = None
    shaking_force: VectorAt | None = None
    shaking_moment: float | None = None


def with_forces(at: tuple[AtAngle, ...], forces: ForceResult, phi: np.ndarray) -> tuple[AtAngle, ...]:
    """The report angles ``at`` with the force analysis at each one's node of the grid ``phi``."""
    cycle = float(phi[-1] - phi[0])
    return tuple(replace(a, **forces.at_entry(
        int(np.argmin(np.abs(phi - math.radians(a.phi_deg) % cycle))))) for a in at)


@dataclass(frozen=True)
class ForceResult:
    """The force analysis (кинетостатика) of the run on the grid: joint reactions, the balancing
    moment M_y three ways, the slider-crank quantities, the loads on the crank pin, the main
    bearing and the frame (design.md §9; conventions in docs/forces.md, keys in
    docs/results.md). Forces [N], moments [N·m]; M_y in the crank's direction of rotation,
    like the driving moment M_D. For a tabulated case (no geometry) only the power balance's
    M_y: ``analysis`` is None and ``note`` says why."""

    motion: str                      # "true": ω(φ), ε(φ) of the dynamics; "steady": ω_m, ε = 0
    omega: np.ndarray                # the crank's ω used [rad/s]
    epsilon: np.ndarray              # the crank's ε used [rad/s²]
    analysis: object | None          # flywheel.dynamics.forces.ForceAnalysis of ``motion``
    M_y_zhukovsky: np.ndarray | None  # M_y by Zhukovsky's lever [N·m]
    M_y_power: np.ndarray            # M_y by the power balance [N·m]
    M_const: float                   # the constant moment of the dynamics (M_D when it drives) [N·m]
    closure: float                   # true motion: max|M_y − M_const|/|M_const| [-] (see closure_reference)
    closure_reference: str           # "M_D": relative to |M_const|; "J_I·ε": to max|J_I·ε| (M_const = 0)
    M_y_cycle_mean: float            # (1/2π)∮M_y dφ of ``motion`` (trapezoid rule) [N·m]
    crank_pin_load: np.ndarray | None        # (N, 2) force of the links on the crank pin [N]
    crank_pin_tangential: np.ndarray | None  # its part along the pin's velocity [N] (positive drives)
    crank_pin_radial: np.ndarray | None      # its part along the crank towards the shaft axis [N]
    note: str = ""                   # why there are no joint reactions (tabulated case)
    warnings: tuple[str, ...] = ()

    @property
    def M_y(self) -> np.ndarray:
        """M_y [N·m], in the direction of rotation: kinetostatic if there is a linkage, else
        the power balance's."""
        return self.analysis.balancing_moment if self.analysis is not None else self.M_y_power

    @property
    def joints(self) -> dict:
        """Reactions (forces.Reaction) by key "<point>:<i>-><j>", from the crank outwards (the
        reverse of the order the groups are solved in); empty if tabulated."""
        return dict(reversed(self.analysis.joints.items())) if self.analysis is not None else {}

    @property
    def slider_crank(self) -> dict:
        """forces.SliderCrank by slider, in the mechanism's order; empty if tabulated."""
        if self.analysis is None:
            return {}
        return dict(reversed(self.analysis.slider_crank.items()))

    def summary(self) -> ForceSummary:
        """summary.json's results.force_analysis, typed."""
        M = self.M_y
        fa = self.analysis
        return ForceSummary(
            motion=self.motion, omega=float(self.omega[0]) if self.motion == "steady" else None,
            closure_reference=self.closure_reference,
            balancing_moment_cycle_mean=self.M_y_cycle_mean,
            balancing_moment_max=float(np.max(M)), balancing_moment_min=float(np.min(M)),
            main_bearing_load_max=None if fa is None else float(np.max(fa.main_bearing_load.magnitude)),
            crank_pin_load_max=None if fa is None else float(np.max(np.hypot(*self.crank_pin_load.T))),
            shaking_force_max=None if fa is None else float(np.max(np.hypot(*fa.shaking_force.T))),
            shaking_moment_max=None if fa is None else float(np.max(np.abs(fa.shaking_moment))),
            note=self.note or None)

    def as_dict(self) -> dict:
        """summary.json's results.force_analysis."""
        return to_json(self.summary())

    def at_entry(self, i: int) -> dict:
        """What a report angle (:class:`AtAngle`) gains at grid node i: its force-analysis
        fields, by name (docs/results.md)."""
        fa = self.analysis
        if fa is None:
            return {"balancing_moment": BalancingMomentAt(power=float(self.M_y_power[i]))}
        out: dict = {"balancing_moment": BalancingMomentAt(
            kinetostatic=float(fa.balancing_moment[i]), zhukovsky=float(self.M_y_zhukovsky[i]),
            power=float(self.M_y_power[i]), groups=float(fa.balancing_moment_groups[i]))}
        joints = {}
        for key, r in self.joints.items():
            v = VectorAt.of(float(r.x[i]), float(r.y[i]))
            sl = fa.slides.get(key)
            joints[key] = JointAt(point=r.joint, by=r.by, on=r.on, F=v.F, Fx=v.Fx, Fy=v.Fy,
                                  angle_deg=v.angle_deg,
                                  normal=None if sl is None else float(sl.normal[i]),
                                  offset=None if sl is None else float(sl.offset[i]))
        out["joints"] = joints
        if fa.slider_crank:
            out["slider_crank"] = {name: SliderCrankAt(
                rod=sc.rod, piston_effort=float(sc.piston_effort[i]),
                side_thrust=float(sc.side_thrust[i]), rod_thrust=float(sc.rod_thrust[i]),
                crank_pin_x=float(sc.crank_pin_x[i]), crank_pin_y=float(sc.crank_pin_y[i]),
                crank_pin_tangential=float(sc.crank_pin_tangential[i]),
                crank_pin_radial=float(sc.crank_pin_radial[i]),
                turning_moment=float(sc.turning_moment[i])) for name, sc in self.slider_crank.items()}
        mb = fa.main_bearing_load
        out["main_bearing_load"] = VectorAt.of(float(mb.x[i]), float(mb.y[i]))
        P = VectorAt.of(float(self.crank_pin_load[i][0]), float(self.crank_pin_load[i][1]))
        out["crank_pin_load"] = CrankPinAt(F=P.F, Fx=P.Fx, Fy=P.Fy, angle_deg=P.angle_deg,
                                           tangential=float(self.crank_pin_tangential[i]),
                                           radial=float(self.crank_pin_radial[i]))
        Sx, Sy = fa.shaking_force[i]
        out["shaking_force"] = VectorAt.of(float(Sx), float(Sy))
        out["shaking_moment"] = float(fa.shaking_moment[i])
        return out


@dataclass(frozen=True, kw_only=True)
class ForceSummary:
    """summary.json's results.force_analysis: the force analysis over the cycle (docs/results.md).
    Moments [N·m], forces [N]; the joint-reaction maxima are None for a tabulated case."""

    motion: str                          # "true" or "steady"
    omega: float | None = None           # steady motion: the constant ω used [rad/s]
    closure_reference: str               # "M_D" or "J_I·ε" (ForceResult.closure_reference)
    balancing_moment_cycle_mean: float   # (1/Φ)∮M_y dφ [N·m]
    balancing_moment_max: float          # [N·m]
    balancing_moment_min: float          # [N·m]
    main_bearing_load_max: float | None = None   # [N]
    crank_pin_load_max: float | None = None      # [N]
    shaking_force_max: float | None = None       # [N]
    shaking_moment_max: float | None = None      # [N·m]
    note: str | None = None              # why there are no joint reactions (tabulated case)


@dataclass(frozen=True, kw_only=True)
class Headline:
    """summary.json's "results" without "at": the run's headline scalars, in the document's
    order (docs/results.md; the keys are the field names). A group that does not apply is None
    and left out of the document: the tabulated kinematics, the firing angles of four-stroke
    cylinders, a given flywheel's J and ε extremes, the given power, the time domain, the
    force analysis. SI units; angles ``*_deg`` in degrees."""

    crank_length: float                          # [m]; NaN (null) if a table gives none
    kinematics: str | None = None                # "tabulated"
    tabulated_interpolation: str | None = None   # J_II's interpolation kind
    tabulated_positions_deg: tuple[float, ...] | None = None   # the table's positions [deg]
    omega_mean: float                            # ω_m [rad/s]
    n_points: int                                # grid nodes
    cycle_deg: int                               # the cycle Φ [deg]: 360, 720
    firing_deg: dict[str, float] | None = None   # cylinder → where it fires [deg], firing order
    cycle_work_resistance: float                 # A_C over the cycle [J]
    driving_moment: float                        # M_D [N·m]
    balancing_moment: float                      # the constant moment closing the work [N·m]
    balance: str                                 # "driving" or "resistance"
    delta: float                                 # δ [-] (given flywheel: the δ it gives)
    flywheel_given: bool | None = None           # True when the flywheel was given
    J_flywheel_given: float | None = None        # [kg·m²] on its own shaft
    epsilon_max: float | None = None             # given flywheel: ε's extremes [rad/s²] …
    phi_epsilon_max_deg: float | None = None     # … and their first angles [deg]
    epsilon_min: float | None = None
    phi_epsilon_min_deg: float | None = None
    power: float | None = None                   # the given mean power [W]
    power_moment: float | None = None            # P/ω_m [N·m]
    power_from_loads: float | None = None        # |balancing_moment|·ω_m [W]
    delta_T_max: float                           # ΔT_нб [J]
    delta_T_I_max: float                         # [J]
    phi_delta_T_I_max_deg: float                 # [deg]
    delta_T_I_min: float                         # [J]
    phi_delta_T_I_min_deg: float                 # [deg]
    J_II_mean: float                             # [kg·m²]
    J_II_min: float
    J_II_max: float
    J_first_group: float
    J_required: float
    J_required_exact: float
    J_flywheel: float
    J_flywheel_exact: float
    delta_achieved: float                        # [-]
    delta_achieved_exact: float
    omega_max: float                             # [rad/s]
    phi_omega_max_deg: float                     # [deg]
    omega_min: float
    phi_omega_min_deg: float
    T0: float                                    # [J]
    cycle_time: float                            # [s]
    flywheel_disk: FlywheelShape
    flywheel_rim: FlywheelShape | RimDesign      # RimDesign: the rim of [flywheel.rim]
    flywheel_material: str
    flywheel_material_density: float             # [kg/m³]
    flywheel_speed_ratio: float                  # [-]
    flywheel_J_on_its_shaft: float               # [kg·m²]
    flywheel_rim_share: float                    # [-]
    flywheel_rim_speed_limit: float              # [m/s]
    flywheel_formulas: str                       # "first-principles" or "course"
    time_domain: TimeDomainResult | None = None  # --transients
    balancing_moment_closure: float | None = None   # ForceResult.closure [-]
    force_analysis: ForceSummary | None = None
    output_link: OutputLink | None = None        # the last group's output link (linkage cases)
    start: StartResult | None = None             # [start]: a motion from rest
    snapshots: tuple[Snapshot, ...] | None = None   # --snapshot, [output] snapshots
    at_travel: tuple[TravelAt, ...] | None = None   # --at-travel: the angles of a travel
    roots: tuple[Roots, ...] | None = None          # --roots: a column's sign changes

    @property
    def rim_designed(self) -> bool:
        """The rim is the designed rim of [flywheel.rim] (a RimDesign), not the plain one."""
        return isinstance(self.flywheel_rim, RimDesign)


def warnings_of(*stages) -> tuple[str, ...]:
    """The warnings of the stage results given (None for a stage not run), in stage order."""
    return tuple(w for r in stages if r is not None for w in r.warnings)


def json_ready(obj):
    """JSON-ready: floats finite (NaN/inf → None), numpy scalars → Python, tuples → lists."""
    if isinstance(obj, dict):
        return {str(k): json_ready(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [json_ready(v) for v in obj]
    if isinstance(obj, (np.floating, float)):
        f = float(obj)
        return f if math.isfinite(f) else None
    if isinstance(obj, np.integer):
        return int(obj)
    return obj


class CycleGrid:
    """What a result on the closed φ grid (``self.phi`` [rad], ``self.position_angles``)
    offers by the grid alone; :class:`Results` and the kinematics-only result share it."""

    @property
    def cycle(self) -> float:
        """The cycle Φ [rad]: the closed grid's span, 2π (4π for a four-stroke engine)."""
        return float(self.phi[-1] - self.phi[0])

    @property
    def cycle_deg(self) -> int:
        """The cycle Φ [deg]: 360, 720 …"""
        return int(round(math.degrees(self.cycle)))

    def position_numbers(self) -> tuple[int | None, ...]:
        """The course's number of each of ``position_angles`` (Position.number: 0 … 11 every
        30°, as plan_positions.png numbers them); None for a dead centre between them and for
        every position of a tabulated case (no drawing)."""
        return tuple(p.number for p in self.position_angles)

    def index_of(self, phi: float) -> int:
        """Grid index of the node at angle ``phi`` [rad] (report angles are grid nodes)."""
        return int(np.argmin(np.abs(self.phi - phi)))


@dataclass(frozen=True)
class Results(CycleGrid):
    """Everything one run computed: the stage results, the table columns and the report angles."""

    analysis = "dynamics"                    # not a field: dynamics/kinematics_only.py says "kinematics"

    title: str
    source: str
    phi: np.ndarray                          # the closed grid [rad]
    kinematics: object                       # flywheel.linkage.Kinematics; None if tabulated
    loads: LoadsResult
    reduction: ReductionResult
    energy: EnergyResult
    sizing: SizingResult
    motion: MotionResult
    columns: dict[str, Column]               # table.csv, in order
    at: tuple[AtAngle, ...]                  # summary.json "results.at", with the force analysis
    position_angles: tuple[Position, ...]    # the standard positions, by φ
    links_drawn: tuple[tuple[str, tuple[str, ...]], ...]  # (link, its points) for the scheme
    crank_length: float                      # [m]; NaN if a table gives none
    tabulated: TabulatedResult | None = None
    time_domain: TimeDomainResult | None = None
    forces: ForceResult | None = None        # the force analysis (kinetostatics)
    plans: tuple = ()                        # dynamics.plans.PlanSet at each report angle (linkage)
    warnings: tuple[str, ...] = ()
    drawing: Drawing | None = None           # what the scheme draws (linkage/drawing.py); None if tabulated
    output_link: OutputLink | None = None    # extremes, K, transmission angle (linkage/output_link.py)
    start: StartResult | None = None         # [start]: a motion from rest (dynamics/start.py)
    snapshots: tuple[Snapshot, ...] | None = None   # ε at stated φ and speed (dynamics/start.py)
    at_travel: tuple[TravelAt, ...] | None = None   # the angles of --at-travel (dynamics/asks.py)
    roots: tuple[Roots, ...] | None = None          # --roots (dynamics/asks.py)

    @property
    def J_parts(self) -> dict[str, np.ndarray]:
        return self.reduction.J_parts

    @property
    def dJ_parts(self) -> dict[str, np.ndarray]:
        return self.reduction.dJ_parts

    @property
    def M_parts(self) -> dict[LoadKey, np.ndarray]:
        return self.loads.M_parts

    @property
    def cylinders(self) -> tuple[CylinderResult, ...]:
        return self.loads.cylinders

    @cached_property
    def scalars(self) -> Headline:
        """summary.json's "results" without "at", typed (NaN kept), built once."""
        e, r, s, m = self.energy, self.reduction, self.sizing, self.motion
        tab, fo = self.tabulated, self.forces
        eps = self._epsilon_extremes() if s.flywheel_given else {}
        return Headline(
            crank_length=self.crank_length,
            kinematics=None if tab is None else "tabulated",
            tabulated_interpolation=None if tab is None else tab.interpolation,
            tabulated_positions_deg=None if tab is None else tuple(tab.positions_deg),
            omega_mean=s.omega_mean, n_points=int(self.phi.size), cycle_deg=self.cycle_deg,
            firing_deg=self._firing(),
            cycle_work_resistance=e.cycle_work_resistance, driving_moment=e.driving_moment,
            balancing_moment=e.balancing_moment, balance=e.balance, delta=s.delta,
            flywheel_given=True if s.flywheel_given else None,
            J_flywheel_given=s.J_flywheel_given if s.flywheel_given else None, **eps,
            power=e.power,
            power_moment=e.power_moment if e.power is not None else None,
            power_from_loads=e.power_from_loads if e.power is not None else None,
            delta_T_max=e.delta_T_max,
            delta_T_I_max=e.delta_T_I_max, phi_delta_T_I_max_deg=math.degrees(e.phi_delta_T_I_max),
            delta_T_I_min=e.delta_T_I_min, phi_delta_T_I_min_deg=math.degrees(e.phi_delta_T_I_min),
            J_II_mean=r.J_II_mean, J_II_min=r.J_II_min, J_II_max=r.J_II_max,
            J_first_group=s.J_first_group, J_required=s.J_required,
            J_required_exact=s.J_required_exact, J_flywheel=s.J_flywheel,
            J_flywheel_exact=s.J_flywheel_exact,
            delta_achieved=m.delta_achieved, delta_achieved_exact=m.delta_achieved_exact,
            omega_max=m.omega_max, phi_omega_max_deg=math.degrees(m.phi_omega_max),
            omega_min=m.omega_min, phi_omega_min_deg=math.degrees(m.phi_omega_min),
            T0=m.T0, cycle_time=m.cycle_time,
            flywheel_disk=s.disk,
            flywheel_rim=s.rim if s.rim_design is None else s.rim_design,
            flywheel_material=s.material, flywheel_material_density=s.material_density,
            flywheel_speed_ratio=s.speed_ratio, flywheel_J_on_its_shaft=s.J_on_its_shaft,
            flywheel_rim_share=s.rim_share if s.rim_design is None else s.rim_design.share,
            flywheel_rim_speed_limit=s.rim_speed_limit, flywheel_formulas=s.formulas,
            time_domain=self.time_domain,
            balancing_moment_closure=None if fo is None else fo.closure,
            force_analysis=None if fo is None else fo.summary(),
            output_link=self.output_link, start=self.start, snapshots=self.snapshots or None,
            at_travel=self.at_travel, roots=self.roots)

    def at_document(self) -> list[dict]:
        """summary.json's results.at: the report angles' entries."""
        return to_json(self.at)

    def at_index(self, phi_deg: float) -> int:
        """Grid index of the report angle ``phi_deg`` [deg] (a node, taken mod the cycle)."""
        return int(np.argmin(np.abs(self.phi - math.radians(phi_deg) % self.cycle)))

    def _epsilon_extremes(self) -> dict:
        """ε's global extremes over the cycle's nodes [rad/s²] and their first angles [deg]."""
        eps = self.motion.epsilon
        i_max, i_min = int(np.argmax(eps)), int(np.argmin(eps))
        return {"epsilon_max": float(eps[i_max]),
                "phi_epsilon_max_deg": math.degrees(self.phi[i_max]),
                "epsilon_min": float(eps[i_min]),
                "phi_epsilon_min_deg": math.degrees(self.phi[i_min])}

    def _firing(self) -> dict[str, float] | None:
        """{cylinder: where it fires [deg]} of the four-stroke cylinders, in firing order;
        None if there are none."""
        fires = sorted((c.fires_at, c.name) for c in self.cylinders if c.fires_at is not None)
        return {n: math.degrees(a) for a, n in fires} if fires else None

    def to_document(self) -> dict:
        """The summary.json document, JSON-ready (:func:`json_ready`)."""
        return json_ready({
            "title": self.title,
            "source": self.source,
            "units": UNITS,
            "results": {**to_json(self.scalars), "at": self.at_document()},
            "warnings": list(self.warnings),
        })


def summary_json_schema() -> dict:
    """The JSON Schema of summary.json (``flywheel schema --results``), read off the result
    dataclasses by :func:`flywheel.io.serialize.json_schema`: ``results`` is the
    :class:`Headline` with ``at``, a list of :class:`AtAngle`. Floats may be null (a
    non-finite value is written as null)."""
    results = json_schema(Headline)
    results["properties"]["at"] = {"type": "array", "items": json_schema(AtAngle)}
    results["required"].append("at")
    return {"$schema": "https://json-schema.org/draft/2020-12/schema",
            "title": "flywheel run: summary.json", "description": UNITS,
            "type": "object",
            "properties": {"title": {"type": "string"}, "source": {"type": "string"},
                           "units": {"type": "string"}, "results": results,
                           "warnings": {"type": "array", "items": {"type": "string"}}},
            "required": ["title", "source", "units", "results", "warnings"],
            "additionalProperties": False}
