"""The columns of table.csv (and positions.csv): every array of a run by its key, with its SI
unit — the one place where both routes list their quantities. Their names and symbols are the
nomenclature's (render/nomenclature.py, by key); tests/render/test_nomenclature.py checks that every
key resolves there with the same unit.
"""
from __future__ import annotations

import numpy as np

from flywheel.dynamics.results import (Column, EnergyResult, LoadsResult, MotionResult,
                                       ReductionResult, TabulatedResult)


def _phi(phi: np.ndarray) -> dict[str, Column]:
    return {"phi_deg": Column(np.degrees(phi), "deg")}


def _kinematics(kin, crank: str) -> dict[str, Column]:
    """Positions and analogues of the points that move, angles and analogues of the links that
    turn (the crank left out)."""
    cols: dict[str, Column] = {}
    for name, pm in kin.points.items():
        if np.all(pm.v_q == 0) and np.all(pm.a_q == 0):
            continue
        cols[f"x_{name}"] = Column(pm.r[:, 0], "m")
        cols[f"y_{name}"] = Column(pm.r[:, 1], "m")
        cols[f"vq_{name}"] = Column(np.hypot(*pm.v_q.T), "m/rad")
        cols[f"vqx_{name}"] = Column(pm.v_q[:, 0], "m/rad")
        cols[f"vqy_{name}"] = Column(pm.v_q[:, 1], "m/rad")
        cols[f"aq_{name}"] = Column(np.hypot(*pm.a_q.T), "m/rad²")
        cols[f"aqx_{name}"] = Column(pm.a_q[:, 0], "m/rad²")
        cols[f"aqy_{name}"] = Column(pm.a_q[:, 1], "m/rad²")
    for name, lm in kin.links.items():
        if name == crank or (np.all(lm.omega_q == 0) and np.all(lm.eps_q == 0)):
            continue
        cols[f"theta_{name}"] = Column(np.degrees(lm.theta), "deg")
        cols[f"omega_q_{name}"] = Column(lm.omega_q, "-")
        cols[f"eps_q_{name}"] = Column(lm.eps_q, "1/rad")
    return cols


def _loads(ld: LoadsResult) -> dict[str, Column]:
    """Each cylinder's relative travel from the head, gas pressure and the gas force on its
    piston; each technological force."""
    cols: dict[str, Column] = {}
    for c in ld.cylinders:
        cols[f"s_{c.name}"] = Column(c.s, "-")
        cols[f"p_{c.name}"] = Column(c.p, "Pa")
        cols[f"F_{c.name}"] = Column(c.F, "N")
        if c.stroke is not None:      # a four-stroke cylinder: which stroke at each node
            cols[f"stroke_{c.name}"] = Column(c.stroke.astype(float), "-")
    for name, F in ld.forces.items():
        cols[f"F_{name}"] = Column(F, "N")
    for name, T in ld.tensions.items():           # a linear spring's tension
        cols[f"F_{name}"] = Column(T, "N")
    return cols


def _dynamics(ld: LoadsResult, red: ReductionResult, en: EnergyResult,
              mo: MotionResult) -> dict[str, Column]:
    """The stages both routes share: J_II and its parts, the moments, works, energies, motion."""
    cols: dict[str, Column] = {}
    for name, J in red.J_parts.items():
        cols[f"J_{name}"] = Column(J, "kg·m²")
    for name, dJ in red.dJ_parts.items():
        cols[f"dJ_{name}"] = Column(dJ, "kg·m²/rad")
    cols["J_II"] = Column(red.J_II, "kg·m²")
    cols["dJ_II"] = Column(red.dJ_II, "kg·m²/rad")
    for name, M in ld.M_parts.items():
        cols[f"M {name}"] = Column(M, "N·m")
    cols["M_known"] = Column(en.M_known, "N·m")
    cols["M_sum"] = Column(en.M_sum, "N·m")
    cols["A_D"] = Column(en.A_D, "J")
    cols["A_C"] = Column(en.A_C, "J")
    cols["A"] = Column(en.A, "J")
    cols["T_II"] = Column(en.T_II, "J")
    cols["dT_I"] = Column(en.dT_I, "J")
    cols["omega"] = Column(mo.omega, "rad/s")
    cols["epsilon"] = Column(mo.epsilon, "rad/s²")
    cols["omega_exact"] = Column(mo.omega_exact, "rad/s")
    cols["t"] = Column(mo.t, "s")
    return cols


def linkage_columns(phi: np.ndarray, kin, crank: str, ld: LoadsResult, red: ReductionResult,
                    en: EnergyResult, mo: MotionResult) -> dict[str, Column]:
    """table.csv of the linkage route: φ, the kinematics (``crank``: the crank's link, left
    out), the loads, then the shared stages."""
    return {**_phi(phi), **_kinematics(kin, crank), **_loads(ld), **_dynamics(ld, red, en, mo)}


def kinematics_columns(phi: np.ndarray, kin, crank: str, omega: float) -> dict[str, Column]:
    """table.csv of the kinematics alone (dynamics/kinematics_only.py): φ, the kinematics, then
    the true values at the constant speed ``omega`` [rad/s]: |v| = |v_q|·ω, |a| = |a_q|·ω² of
    the moving points, ω_i = ω_q·ω, ε_i = ε_q·ω² of the turning links."""
    cols = {**_phi(phi), **_kinematics(kin, crank)}
    for name, pm in kin.points.items():
        if f"x_{name}" in cols:
            cols[f"v_{name}"] = Column(np.hypot(*pm.v_q.T) * omega, "m/s")
            cols[f"a_{name}"] = Column(np.hypot(*pm.a_q.T) * omega**2, "m/s²")
    for name, lm in kin.links.items():
        if f"theta_{name}" in cols:
            cols[f"omega_{name}"] = Column(lm.omega_q * omega, "rad/s")
            cols[f"eps_{name}"] = Column(lm.eps_q * omega**2, "rad/s²")
    return cols


def tabulated_columns(phi: np.ndarray, tab: TabulatedResult, ld: LoadsResult,
                      red: ReductionResult, en: EnergyResult, mo: MotionResult) -> dict[str, Column]:
    """table.csv of the tabulated route: φ, the interpolated table (|v_q| of its points, ω_q of
    its links), the shared stages, then the seed's static and dynamic moments."""
    cols = _phi(phi)
    for name, v in tab.v_q.items():
        cols[f"vq_{name}"] = Column(v, "m/rad")
    for name, w in tab.omega_q.items():
        cols[f"omega_q_{name}"] = Column(w, "-")
    cols.update(_dynamics(ld, red, en, mo))
    cols["M_st"] = Column(tab.M_st, "N·m")
    cols["M_dyn"] = Column(tab.M_dyn, "N·m")
    return cols
