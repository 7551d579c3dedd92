"""Tabulated kinematics (design.md §3 end; issue 5; seed 004_112cd67daf63ceba.txt).

The graphical-analytical way of the course: the kinematics come as a table read off velocity
plans at a few crank positions instead of a mechanism. A case gives, per position,

* the velocity analogues |V_q| = V/ω1 [m] of the points that carry mass or force,
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
its derivative) and handed to :func:`flywheel.dynamics.pipeline.dynamics`: energy, sizing and motion
are exactly those of the linkage route.

The case's schema is :mod:`flywheel.cases.tabulated`; scipy is imported inside the functions
that need it.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.cases.tabulated import (TabulatedSpec, link_inertia_at_positions,  # noqa: F401
                                      load_moments_at_positions, reduced_inertia_at_positions,
                                      static_moments)
from flywheel.dynamics.periodic import periodic_linear

# -- periodic interpolation ---------------------------------------------------------------------

def periodic_interpolate(nodes: np.ndarray, values: np.ndarray, phi: np.ndarray, kind: str,
                         derivative: bool = False) -> np.ndarray:
    """Interpolate values given at the distinct ``nodes`` [rad] (increasing, within one cycle)
    onto ``phi`` [rad], periodically over 2π.

    kind: 'periodic-spline' (scipy CubicSpline, bc_type='periodic'), or 'linear' /
    'finite-differences' (piecewise linear; its derivative on [φ_i, φ_{i+1}) is the forward
    difference (y_{i+1} − y_i)/(φ_{i+1} − φ_i), seed 004 eq. 10). ``derivative``: d/dφ instead.

    >>> x = np.radians(np.arange(0, 360, 30)); y = np.sin(x)
    >>> float(periodic_interpolate(x, y, np.array([0.0]), "finite-differences", True)[0])
    0.954929658551372
    """
    nodes = np.asarray(nodes, float)
    values = np.asarray(values, float)
    period = 2 * np.pi
    xe = np.append(nodes, nodes[0] + period)
    ye = np.append(values, values[0])
    if kind == "periodic-spline":
        from scipy.interpolate import CubicSpline

        t = nodes[0] + np.mod(np.asarray(phi, float) - nodes[0], period)
        cs = CubicSpline(xe, ye, bc_type="periodic")
        return cs(t, 1 if derivative else 0)
    # a grid node within 1e-9 rad of a position belongs to the interval that starts there
    return periodic_linear(xe, ye, phi, period, derivative=derivative, snap=1e-9)


def _nodes_rad(spec: TabulatedSpec) -> np.ndarray:
    return np.radians(spec.nodes_deg)


def _distinct(spec: TabulatedSpec, values) -> np.ndarray:
    return np.asarray(values, float)[: spec.nodes_deg.size]


def inertia_derivative_at_positions(spec: TabulatedSpec) -> np.ndarray:
    """dJ_II/dφ [kg·m²/rad] at every row, by the spec's interpolation (the spline's derivative,
    or the seed's forward difference (I_{i+1} − I_i)/(φ_{i+1} − φ_i))."""
    J = _distinct(spec, reduced_inertia_at_positions(spec))
    phi = np.radians(np.asarray(spec.positions_deg, float))
    return periodic_interpolate(_nodes_rad(spec), J, phi, spec.interpolation, derivative=True)


def dynamic_moments(spec: TabulatedSpec, omega: float) -> np.ndarray:
    """The seed's dynamic moment Мдин = ω1²/2·dIпр/dφ [N·m] at every row (seed 004, eq. 6;
    ω1 [rad/s] constant, so the ε1·Iпр term of eq. 5 vanishes)."""
    return omega**2 / 2 * inertia_derivative_at_positions(spec)


# -- the analysis ------------------------------------------------------------------------------

def analyze_tabulated(case, n_points: int = 3600, at_deg: list[float] | None = None,
                      transients: bool = False):
    """The dynamic analysis of a case whose kinematics are a table (``case.tabulated``).

    Same stages and Results as :func:`flywheel.dynamics.pipeline.analyze`, with ``kinematics=None``
    (no positions: nothing to draw) and the table's positions as ``position_angles``.
    """
    from flywheel.dynamics.pipeline import _grid, _transients, dynamics, grid_options
    from flywheel.dynamics.results import Column, Results

    spec: TabulatedSpec = case.tabulated
    at_deg = grid_options(case, n_points, at_deg)
    nodes = _nodes_rad(spec)
    phi = _grid(n_points, list(nodes) + [math.radians(a) for a in at_deg])
    kind_J = spec.interpolation
    kind_kin = "periodic-spline" if kind_J == "periodic-spline" else "linear"
    warnings: list[str] = []

    # -- reduction of masses: each link's share interpolated, its derivative from the interpolant
    J_parts, dJ_parts = {}, {}
    for name, J in link_inertia_at_positions(spec).items():
        Jd = _distinct(spec, J)
        J_parts[name] = periodic_interpolate(nodes, Jd, phi, kind_J)
        dJ_parts[name] = periodic_interpolate(nodes, Jd, phi, kind_J, derivative=True)
        if J_parts[name].min() < -0.01 * Jd.max():      # more than 1 % of its largest value
            i = int(np.argmin(J_parts[name]))
            warnings.append(f"tabulated: the {kind_J} interpolation of link {name}'s share of J_II "
                            f"dips below zero ({J_parts[name][i]:.3g} kg·m² at φ = "
                            f"{math.degrees(phi[i]):.1f}°): give more positions near there")

    # -- loads ------------------------------------------------------------------------------------
    M_parts: dict[str, np.ndarray] = {}
    kinds = {f"force {f.name}": f.interpolation for f in spec.forces}
    kinds.update({f"moment {m.name}": m.interpolation for m in spec.moments})
    for key, M in load_moments_at_positions(spec).items():
        M_parts[key] = periodic_interpolate(nodes, _distinct(spec, M), phi, kinds[key])

    d = dynamics(phi, J_parts, dJ_parts, M_parts, case.machine, case.flywheel, warnings)
    omega, eps = d["omega"], d["epsilon"]
    w_m = case.machine.omega_mean

    # -- columns: the interpolated table, then the shared stages, then the seed's Мст and Мдин ----
    cols: dict[str, Column] = {"phi_deg": Column(np.degrees(phi), "deg", "crank angle φ", "угол φ")}
    vq, wq = {}, {}
    for name, v in spec.points.items():      # |V_q| from the interpolated V_q² (smooth through 0)
        sq = periodic_interpolate(nodes, _distinct(spec, v) ** 2, phi, kind_kin)
        vq[name] = np.sqrt(np.maximum(sq, 0.0))
        cols[f"vq_{name}"] = Column(vq[name], "m", f"|v_q| of {name} (tabulated)",
                                    f"аналог скорости {name} (по таблице)")
    for name, w in spec.omega_q.items():
        sq = periodic_interpolate(nodes, _distinct(spec, w) ** 2, phi, kind_kin)
        wq[name] = np.sqrt(np.maximum(sq, 0.0))
        cols[f"omega_q_{name}"] = Column(wq[name], "-", f"|ω_q| of link {name} (tabulated)",
                                         f"аналог угл. скорости {name} (по таблице)")
    cols.update(d["columns"])
    M_st = -d["M_known"]
    M_dyn = w_m**2 / 2 * d["dJ_II"]
    cols["M_st"] = Column(M_st, "N·m", "static moment Мст = −Σ reduced moments of the loads "
                                       "(resisting positive)", "приведённый момент сил статического "
                                       "сопротивления Мст")
    cols["M_dyn"] = Column(M_dyn, "N·m", "dynamic moment Мдин = ω_m²/2·dJ_II/dφ",
                           "динамический момент Мдин")

    at_list = []
    for a in at_deg:
        i = int(np.argmin(np.abs(phi - math.radians(a) % (2 * np.pi))))
        w, e = float(omega[i]), float(eps[i])
        at_list.append({
            "phi_deg": float(a), "omega": w, "epsilon": e,
            "J_II": float(d["J_II"][i]), "dJ_II": float(d["dJ_II"][i]),
            "M_sum": float(d["M_sum"][i]), "M_st": float(M_st[i]), "M_dyn": float(M_dyn[i]),
            "moments": {k: float(v[i]) for k, v in M_parts.items()},
            "points": {k: {"v_q": float(v[i]), "v": float(v[i] * w)} for k, v in vq.items()},
            "links": {k: {"omega_q": float(v[i]), "omega": float(v[i] * w)} for k, v in wq.items()},
        })

    scalars = {"crank_length": float(spec.crank_length) if spec.crank_length else float("nan"),
               "kinematics": "tabulated", "tabulated_interpolation": kind_J,
               "tabulated_positions_deg": [float(p) for p in spec.positions_deg],
               **d["scalars"]}
    positions = [(f"{k + 1} ({p:g}°)", math.radians(p)) for k, p in enumerate(spec.positions_deg)]
    time_domain = None
    if transients:
        time_domain = _transients(case, phi, d["J_I"] + d["J_II"], d["dJ_II"], d["M_sum"],
                                  d["M_known"], omega, scalars["driving_moment"], warnings)
        scalars["time_domain"] = {k: v for k, v in time_domain.items() if k != "histories"}
    return Results(
        title=case.title, source=case.source, phi=phi, kinematics=None, columns=cols,
        scalars=scalars, at=at_list, position_angles=positions, J_parts=J_parts,
        dJ_parts=dJ_parts, M_parts=M_parts, cylinders=[], links_drawn=[], warnings=warnings,
        time_domain=time_domain,
    )
