"""Tabulated kinematics (design.md §3 end; issue 5; seed 004_112cd67daf63ceba.txt).

The graphical-analytical way of the course: the kinematics come as a table read off velocity
plans at a few crank positions instead of a mechanism. A case gives, per position,

* the velocity analogues |V_q| = V/ω1 [m/rad] of the points that carry mass or force,
* the angular-velocity analogues ω_q = ω_i/ω1 [-] of the links that turn,
* the loads: forces F [N] at those points with the angle α [deg] between each force and its
  point's velocity, and reduced moments given outright [N·m],

and the links' masses and moments of inertia with the point / ω_q row each one uses. From these

    J_II,i = Σ m·V_q,i² + J·ω_q,i²                     (seed 004, eq. 7: Iпр)
    M_i    = F_i·V_q,i·cos α_i                          (reduced moment, positive when it drives)
    Мст_i  = −Σ M_i                                     (seed 004: the static moment, resisting
                                                         positive: Мст = −Σ G·V·cos(G, V))
    Мдин_i = ω1²/2·dJ_II/dφ                             (seed 004, eq. 6)

are interpolated periodically onto the φ grid (J_II by a periodic cubic spline by default,
or piecewise linearly with the seed's forward differences (I_{i+1} − I_i)/(φ_{i+1} − φ_i) as
its derivative) and handed to the shared stages (:mod:`flywheel.dynamics.stages`): energy,
sizing and motion are exactly those of the linkage route.

The case's schema is :mod:`flywheel.cases.tabulated`; scipy is imported inside the functions
that need it.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics import stages
from flywheel.dynamics.columns import tabulated_columns
from flywheel.dynamics.grid import DEFAULT_POINTS, closed_grid, grid_options, report_index
from flywheel.dynamics.loads import LoadKey
from flywheel.dynamics.periodic import periodic_linear
from flywheel.dynamics.results import (AtAngle, EnergyResult, LinkAt, LoadsResult,
                                       PointAt, Position, ReductionResult, Results, TabulatedResult,
                                       warnings_of, with_forces)
from flywheel.errors import Notice

# -- per-position values: the table's own arithmetic (seed 004, eq. 7 and Мст), used by the
#    analysis below and by the case's validation (overflow, flywheel.cases.tabulated) ---------

def _per_position(value, n: int) -> np.ndarray:
    return np.full(n, float(value)) if not isinstance(value, list) else np.asarray(value, float)


def link_inertia_at_positions(spec) -> dict[str, np.ndarray]:
    """Each link's share of J_II at every row of the table [kg·m²]: m·V_q² + J·ω_q².

    >>> from flywheel.cases.tabulated import TabulatedSpec
    >>> s = TabulatedSpec(positions_deg=[0, 60, 120, 180, 240, 300],
    ...                   points={"B": [0, 1, 2, 0, 1, 2]}, links={"3": {"mass": 2.0, "point": "B"}})
    >>> link_inertia_at_positions(s)["3"]
    array([0., 2., 8., 0., 2., 8.])
    """
    n = len(spec.positions_deg)
    out = {}
    for name, lk in spec.links.items():
        J = np.zeros(n)
        if lk.mass > 0:
            J += lk.mass * np.asarray(spec.points[lk.point], float) ** 2
        if lk.J > 0:
            J += lk.J * np.asarray(spec.omega_q[lk.omega_q or name], float) ** 2
        out[name] = J
    return out


def reduced_inertia_at_positions(spec) -> np.ndarray:
    """J_II (the seed's Iпр) at every row of the table [kg·m²]."""
    parts = link_inertia_at_positions(spec)
    return sum(parts.values()) if parts else np.zeros(len(spec.positions_deg))


def load_moments_at_positions(spec) -> dict[LoadKey, np.ndarray]:
    """Reduced moment of each load at every row [N·m], positive when it drives the crank:
    a force F·|V_q|·cos α (kind "force"), a moment as given (kind "moment")."""
    n = len(spec.positions_deg)
    out = {}
    for f in spec.forces:
        F = _per_position(f.magnitude, n)
        alpha = np.radians(_per_position(f.angle_deg, n))
        out[LoadKey("force", f.name)] = F * np.asarray(spec.points[f.point], float) * np.cos(alpha)
    for m in spec.moments:
        out[LoadKey("moment", m.name)] = np.asarray(m.values, float)
    return out


def static_moments(spec) -> np.ndarray:
    """The seed's static moment Мст at every row [N·m]: −Σ of the loads' reduced moments, so a
    resisting load counts positive (seed 004: Мст = −(Σ G·V·cos(G, V) − F·V_B4)).

    >>> from flywheel.cases.tabulated import TabulatedSpec
    >>> s = TabulatedSpec(positions_deg=[0, 60, 120, 180, 240, 300],
    ...                   points={"B": [0.1] * 6},
    ...                   forces=[{"name": "G", "point": "B", "magnitude": 100.0,
    ...                            "angle_deg": [180, 180, 0, 0, 0, 180]}])
    >>> static_moments(s)
    array([ 10.,  10., -10., -10., -10.,  10.])
    """
    parts = load_moments_at_positions(spec)
    return -sum(parts.values()) if parts else np.zeros(len(spec.positions_deg))


# -- periodic interpolation ---------------------------------------------------------------------

def periodic_interpolate(nodes: np.ndarray, values: np.ndarray, phi: np.ndarray, kind: str,
                         derivative: bool = False, period: float = 2 * np.pi) -> np.ndarray:
    """Interpolate values given at the distinct ``nodes`` [rad] (increasing, within one cycle)
    onto ``phi`` [rad], periodically over the cycle ``period`` [rad] (2π, or 4π for a table
    over a 720° cycle).

    kind: 'periodic-spline' (scipy CubicSpline, bc_type='periodic'), or 'linear' /
    'finite-differences' (piecewise linear; its derivative on [φ_i, φ_{i+1}) is the forward
    difference (y_{i+1} − y_i)/(φ_{i+1} − φ_i), seed 004 eq. 10). ``derivative``: d/dφ instead.

    >>> x = np.radians(np.arange(0, 360, 30)); y = np.sin(x)
    >>> float(periodic_interpolate(x, y, np.array([0.0]), "finite-differences", True)[0])
    0.954929658551372
    """
    nodes = np.asarray(nodes, float)
    values = np.asarray(values, float)
    xe = np.append(nodes, nodes[0] + period)
    ye = np.append(values, values[0])
    if kind == "periodic-spline":
        from scipy.interpolate import CubicSpline

        t = nodes[0] + np.mod(np.asarray(phi, float) - nodes[0], period)
        cs = CubicSpline(xe, ye, bc_type="periodic")
        return cs(t, 1 if derivative else 0)
    # a grid node within 1e-9 rad of a position belongs to the interval that starts there
    return periodic_linear(xe, ye, phi, period, derivative=derivative, snap=1e-9)


def _nodes_rad(spec) -> np.ndarray:
    return np.radians(spec.nodes_deg)


def _period(spec) -> float:
    """The table's cycle [rad]: 2π, or machine.cycle_deg (4π for 720°)."""
    return math.radians(spec.cycle_deg)


def _distinct(spec, values) -> np.ndarray:
    return np.asarray(values, float)[: spec.nodes_deg.size]


def inertia_derivative_at_positions(spec) -> np.ndarray:
    """dJ_II/dφ [kg·m²/rad] at every row, by the spec's interpolation (the spline's derivative,
    or the seed's forward difference (I_{i+1} − I_i)/(φ_{i+1} − φ_i))."""
    J = _distinct(spec, reduced_inertia_at_positions(spec))
    phi = np.radians(np.asarray(spec.positions_deg, float))
    return periodic_interpolate(_nodes_rad(spec), J, phi, spec.interpolation, derivative=True,
                                period=_period(spec))


def dynamic_moments(spec, omega: float) -> np.ndarray:
    """The seed's dynamic moment Мдин = ω1²/2·dIпр/dφ [N·m] at every row (seed 004, eq. 6;
    ω1 [rad/s] constant, so the ε1·Iпр term of eq. 5 vanishes)."""
    return omega**2 / 2 * inertia_derivative_at_positions(spec)


# -- the analysis ------------------------------------------------------------------------------

def analyze_tabulated(case, n_points: int = DEFAULT_POINTS, at_deg: list[float] | None = None,
                      transients: bool = False, motion: str = "true", progress=None) -> Results:
    """The dynamic analysis of a case whose kinematics are a table (``case.tabulated``).

    The table is a second source of the loads and of J_II's parts, on the grid with its
    positions and the report angles as nodes; from there the stages are those of
    :func:`flywheel.dynamics.pipeline.analyze` (:mod:`flywheel.dynamics.stages`). Results have
    ``kinematics=None`` (no positions: nothing to draw) and the table's positions as
    ``position_angles``. The force analysis has no joint reactions without a linkage: only
    M_y by the power balance (``motion``: "true" or "steady", :func:`stages.force_analysis`).
    """
    spec = case.tabulated
    at_deg = grid_options(case, n_points, at_deg)
    phi = closed_grid(n_points, list(_nodes_rad(spec)) + [math.radians(a) for a in at_deg],
                      _period(spec))
    red = tabulated_reduction(spec, phi)
    ld = tabulated_loads(spec, phi)
    en, sz, mo = stages.dynamics(phi, ld, red, case.machine, case.flywheel)
    tab = tabulated_kinematics(spec, phi, red, en, case.machine.omega_mean)
    fo = stages.force_analysis(phi, red, en, mo, case.machine.omega_mean, motion)
    at = report_angles(at_deg, phi, tab, ld, red, en, fo.omega, fo.epsilon)   # the motion used
    td = stages.time_domain(case, phi, red, en, mo, progress) if transients else None
    return Results(
        title=case.title, source=case.source, phi=phi, kinematics=None, loads=ld, reduction=red,
        energy=en, sizing=sz, motion=mo, columns=tabulated_columns(phi, tab, ld, red, en, mo),
        at=with_forces(at, fo, phi), position_angles=tuple(
            Position(phi=math.radians(p), table_row=k + 1, table_deg=p)
            for k, p in enumerate(spec.positions_deg)),
        links_drawn=(), crank_length=float(spec.crank_length) if spec.crank_length else float("nan"),
        tabulated=tab, time_domain=td, forces=fo,
        warnings=tuple(case.plausibility_warnings()) + warnings_of(red, ld, en, sz, mo, fo, td))


def tabulated_reduction(spec, phi: np.ndarray) -> ReductionResult:
    """Each link's share of J_II (seed 004, eq. 7) interpolated onto ``phi`` by the spec's
    interpolation, its derivative from the interpolant; a warning where a share dips below zero
    by more than 1 % of its largest value (too few positions for the spline)."""
    nodes, kind = _nodes_rad(spec), spec.interpolation
    J_parts, dJ_parts, warnings = {}, {}, []
    for name, J in link_inertia_at_positions(spec).items():
        Jd = _distinct(spec, J)
        J_parts[name] = periodic_interpolate(nodes, Jd, phi, kind, period=_period(spec))
        dJ_parts[name] = periodic_interpolate(nodes, Jd, phi, kind, derivative=True,
                                              period=_period(spec))
        if J_parts[name].min() < -0.01 * Jd.max():
            i = int(np.argmin(J_parts[name]))
            J_low, at = float(J_parts[name][i]), math.degrees(phi[i])
            warnings.append(Notice.of(
                "tabulated_negative_J", "tabulated: the {kind} interpolation of link {link}'s "
                "share of J_II dips below zero ({J:.3g} kg·m² at φ = {phi_deg:.1f}°): give more "
                "positions near there", kind=kind, link=name, J=J_low, phi_deg=at))
    return stages.reduced_inertia(phi, J_parts, dJ_parts, warnings)


def tabulated_loads(spec, phi: np.ndarray) -> LoadsResult:
    """The reduced moments of the table's forces (F·|V_q|·cos α) and given moments, per
    position, interpolated onto ``phi`` each by its own interpolation."""
    nodes = _nodes_rad(spec)
    kinds = {LoadKey("force", f.name): f.interpolation for f in spec.forces}
    kinds.update({LoadKey("moment", m.name): m.interpolation for m in spec.moments})
    M_parts = {key: periodic_interpolate(nodes, _distinct(spec, M), phi, kinds[key],
                                         period=_period(spec))
               for key, M in load_moments_at_positions(spec).items()}
    titles = {LoadKey(kind, x.name): x.title for kind, given in (
        ("force", spec.forces), ("moment", spec.moments)) for x in given if x.title}
    return LoadsResult(M_parts=M_parts, W_parts={}, titles=titles)


def tabulated_kinematics(spec, phi: np.ndarray, red: ReductionResult,
                         en: EnergyResult, omega_mean: float) -> TabulatedResult:
    """The table's |V_q| and |ω_q| on the grid (interpolated as squares, so smooth through 0;
    linearly unless J_II is a periodic spline) and the seed's Мст = −M_known and
    Мдин = ω_m²/2·dJ_II/dφ (seed 004, eq. 6)."""
    nodes, kind_J = _nodes_rad(spec), spec.interpolation
    kind_kin = "periodic-spline" if kind_J == "periodic-spline" else "linear"

    def magnitude(values) -> np.ndarray:
        sq = periodic_interpolate(nodes, _distinct(spec, values) ** 2, phi, kind_kin,
                                  period=_period(spec))
        return np.sqrt(np.maximum(sq, 0.0))

    return TabulatedResult(
        interpolation=kind_J, positions_deg=tuple(float(p) for p in spec.positions_deg),
        v_q={name: magnitude(v) for name, v in spec.points.items()},
        omega_q={name: magnitude(w) for name, w in spec.omega_q.items()},
        M_st=-en.M_known, M_dyn=omega_mean**2 / 2 * red.dJ_II)


def report_angles(at_deg: list[float], phi: np.ndarray, tab: TabulatedResult, ld: LoadsResult,
                  red: ReductionResult, en: EnergyResult, omega: np.ndarray,
                  epsilon: np.ndarray) -> tuple[AtAngle, ...]:
    """summary.json's "at" of the tabulated route: ω, ε, J_II, Мст, Мдин, the moments, and the
    table's points and links with their true speeds (v = |V_q|·ω, ω_i = ω_q·ω); ``omega``,
    ``epsilon``: the crank's motion as the force analysis takes it (true or steady)."""
    out = []
    for a in at_deg:
        i = report_index(phi, a)
        w, e = float(omega[i]), float(epsilon[i])
        out.append(AtAngle(
            phi_deg=float(a), omega=w, epsilon=e,
            J_II=float(red.J_II[i]), dJ_II=float(red.dJ_II[i]),
            M_sum=float(en.M_sum[i]), M_st=float(tab.M_st[i]), M_dyn=float(tab.M_dyn[i]),
            moments={str(k): float(v[i]) for k, v in ld.M_parts.items()},
            points={k: PointAt(v_q=float(v[i]), v=float(v[i] * w)) for k, v in tab.v_q.items()},
            links={k: LinkAt(omega_q=float(v[i]), omega=float(v[i] * w))
                   for k, v in tab.omega_q.items()}))
    return tuple(out)
