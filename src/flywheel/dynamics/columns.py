"""The columns of table.csv (and positions.csv): every array of a run with its unit and its
English and Russian description — the one place where both routes name their quantities.
"""
from __future__ import annotations

import numpy as np

from flywheel.dynamics.results import (Column, EnergyResult, LoadsResult, MotionResult,
                                       ReductionResult, TabulatedResult)


def _phi(phi: np.ndarray) -> dict[str, Column]:
    return {"phi_deg": Column(np.degrees(phi), "deg", "crank angle φ", "угол φ")}


def _kinematics(kin, crank: str) -> dict[str, Column]:
    """Positions and analogues of the points that move, angles and analogues of the links that
    turn (the crank left out)."""
    cols: dict[str, Column] = {}
    for name, pm in kin.points.items():
        if np.all(pm.v_q == 0) and np.all(pm.a_q == 0):
            continue
        cols[f"x_{name}"] = Column(pm.r[:, 0], "m", f"x of {name}", f"x точки {name}")
        cols[f"y_{name}"] = Column(pm.r[:, 1], "m", f"y of {name}", f"y точки {name}")
        cols[f"vq_{name}"] = Column(np.hypot(*pm.v_q.T), "m/rad", f"|v_q| of {name}",
                                    f"аналог скорости {name}")
        cols[f"vqx_{name}"] = Column(pm.v_q[:, 0], "m/rad", f"v_qx of {name}", f"v_qx {name}")
        cols[f"vqy_{name}"] = Column(pm.v_q[:, 1], "m/rad", f"v_qy of {name}", f"v_qy {name}")
        cols[f"aq_{name}"] = Column(np.hypot(*pm.a_q.T), "m/rad²", f"|a_q| of {name}",
                                    f"аналог ускорения {name}")
        cols[f"aqx_{name}"] = Column(pm.a_q[:, 0], "m/rad²", f"a_qx of {name}", f"a_qx {name}")
        cols[f"aqy_{name}"] = Column(pm.a_q[:, 1], "m/rad²", f"a_qy of {name}", f"a_qy {name}")
    for name, lm in kin.links.items():
        if name == crank or (np.all(lm.omega_q == 0) and np.all(lm.eps_q == 0)):
            continue
        cols[f"theta_{name}"] = Column(np.degrees(lm.theta), "deg", f"angle of link {name}",
                                       f"угол звена {name}")
        cols[f"omega_q_{name}"] = Column(lm.omega_q, "-", f"ω_q of link {name}", f"аналог угл. скорости {name}")
        cols[f"eps_q_{name}"] = Column(lm.eps_q, "1/rad", f"ε_q of link {name}",
                                       f"аналог угл. ускорения {name}")
    return cols


def _loads(ld: LoadsResult) -> dict[str, Column]:
    """Each cylinder's travel, pressure and force; each technological force."""
    cols: dict[str, Column] = {}
    for c in ld.cylinders:
        cols[f"s_{c.name}"] = Column(c.s, "-", f"relative piston travel from the head, {c.name}",
                                     f"относительное перемещение поршня {c.name}")
        cols[f"p_{c.name}"] = Column(c.p, "Pa", f"gas pressure, {c.name}", f"давление {c.name}")
        cols[f"F_{c.name}"] = Column(c.F, "N", f"gas force on piston {c.piston}",
                                     f"сила давления газа на поршень {c.piston}")
        if c.stroke is not None:      # a four-stroke cylinder: which stroke at each node
            cols[f"stroke_{c.name}"] = Column(
                c.stroke.astype(float), "-", f"stroke of {c.name}: 0 intake, 1 compression, "
                "2 expansion, 3 exhaust", f"такт {c.name}: 0 впуск, 1 сжатие, 2 расширение, 3 выпуск")
    for name, F in ld.forces.items():
        cols[f"F_{name}"] = Column(F, "N", f"technological force {name}", f"сила {name}")
    return cols


def _dynamics(ld: LoadsResult, red: ReductionResult, en: EnergyResult,
              mo: MotionResult) -> dict[str, Column]:
    """The stages both routes share: J_II and its parts, the moments, works, energies, motion."""
    cols: dict[str, Column] = {}
    for name, J in red.J_parts.items():
        cols[f"J_{name}"] = Column(J, "kg·m²", f"link {name}'s share of J_II", f"вклад звена {name} в J_II")
    for name, dJ in red.dJ_parts.items():
        cols[f"dJ_{name}"] = Column(dJ, "kg·m²/rad", f"link {name}'s share of dJ_II/dφ",
                                    f"вклад звена {name} в dJ_II/dφ")
    cols["J_II"] = Column(red.J_II, "kg·m²", "reduced inertia of the second group J_II",
                          "приведённый момент инерции II группы")
    cols["dJ_II"] = Column(red.dJ_II, "kg·m²/rad", "dJ_II/dφ", "производная J_II")
    for name, M in ld.M_parts.items():
        cols[f"M {name}"] = Column(M, "N·m", f"reduced moment: {name}", f"приведённый момент: {name}")
    cols["M_known"] = Column(en.M_known, "N·m", "sum of the given loads' reduced moments",
                             "суммарный приведённый момент заданных сил")
    cols["M_sum"] = Column(en.M_sum, "N·m", "total reduced moment M_Σ", "суммарный приведённый момент")
    cols["A_D"] = Column(en.A_D, "J", "work of the driving moment A_D", "работа движущих сил")
    cols["A_C"] = Column(en.A_C, "J", "work of the resistance A_C", "работа сил сопротивления")
    cols["A"] = Column(en.A, "J", "total work A", "суммарная работа")
    cols["T_II"] = Column(en.T_II, "J", "kinetic energy of the second group T_II", "кин. энергия II группы")
    cols["dT_I"] = Column(en.dT_I, "J", "change of kinetic energy of the first group ΔT_I",
                          "изменение кин. энергии I группы")
    cols["omega"] = Column(mo.omega, "rad/s", "crank angular velocity ω", "угловая скорость звена приведения")
    cols["epsilon"] = Column(mo.epsilon, "rad/s²", "crank angular acceleration ε", "угловое ускорение")
    cols["omega_exact"] = Column(mo.omega_exact, "rad/s", "ω with the exact flywheel size",
                                 "ω при точном моменте инерции маховика")
    cols["t"] = Column(mo.t, "s", "time t(φ)", "время")
    return cols


def linkage_columns(phi: np.ndarray, kin, crank: str, ld: LoadsResult, red: ReductionResult,
                    en: EnergyResult, mo: MotionResult) -> dict[str, Column]:
    """table.csv of the linkage route: φ, the kinematics (``crank``: the crank's link, left
    out), the loads, then the shared stages."""
    return {**_phi(phi), **_kinematics(kin, crank), **_loads(ld), **_dynamics(ld, red, en, mo)}


def tabulated_columns(phi: np.ndarray, tab: TabulatedResult, ld: LoadsResult,
                      red: ReductionResult, en: EnergyResult, mo: MotionResult) -> dict[str, Column]:
    """table.csv of the tabulated route: φ, the interpolated table, the shared stages, then the
    seed's static and dynamic moments."""
    cols = _phi(phi)
    for name, v in tab.v_q.items():
        cols[f"vq_{name}"] = Column(v, "m", f"|v_q| of {name} (tabulated)",
                                    f"аналог скорости {name} (по таблице)")
    for name, w in tab.omega_q.items():
        cols[f"omega_q_{name}"] = Column(w, "-", f"|ω_q| of link {name} (tabulated)",
                                         f"аналог угл. скорости {name} (по таблице)")
    cols.update(_dynamics(ld, red, en, mo))
    cols["M_st"] = Column(tab.M_st, "N·m", "static moment Мст = −Σ reduced moments of the loads "
                                           "(resisting positive)", "приведённый момент сил статического "
                                           "сопротивления Мст")
    cols["M_dyn"] = Column(tab.M_dyn, "N·m", "dynamic moment Мдин = ω_m²/2·dJ_II/dφ",
                           "динамический момент Мдин")
    return cols
