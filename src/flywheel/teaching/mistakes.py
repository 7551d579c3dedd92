"""The catalogue of classic mistakes of the course (issue 27), in one place: each a documented
transformation of one step of the right chain (:mod:`flywheel.teaching.chain`). ``flywheel
grade`` tries every mistake on a wrong answer — the step itself or a step between it and the
student's earlier answer it is computed from — and names the one that reproduces the
student's number within the answer's tolerance. docs/teacher.md lists them; their names, in
English and Russian, are render/grading.py's (``MISTAKES``).

Computation only: no typer, no rich.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from flywheel.dynamics import energy
from flywheel.teaching import chain as ch
from flywheel.teaching import chain_task2 as t2
from flywheel.units import DEG_PER_RAD, RAD_S_PER_RPM, RPM_PER_RAD_S, TWO_PI


@dataclass(frozen=True)
class Mistake:
    """A classic mistake: its code (the name of the diagnosis), the steps it changes (step's
    name → (givens, the step's input) → candidate values) and, for the docs, what it does."""

    code: str
    does: str
    twists: dict[str, Callable[[ch.Givens, float], tuple[float, ...]]]
    tolerance_matter: bool = False
    #: the mistake in a table's cell (teaching/tables.py): ``table.column`` ("analogues.vq":
    #: every point's v_q) → (tables.CellContext) → candidate values
    cells: dict[str, Callable] = field(default_factory=dict)


def _local_extremes(g: ch.Givens, M: float) -> tuple[float, ...]:
    """ΔT_нб from a local extremum of ΔT_I(φ) taken for the global one (seed 000's own defect,
    seeds README defect 6: Minimize/Maximize from start guesses): the global maximum less each
    other local minimum, and each other local maximum less the global minimum (the extremes
    refined as ``energy.extreme`` does, on the neighbourhood of each)."""
    dT = ch.energy_curve(g, M)
    top = energy.extreme(dT, g.phi, "max")[1]
    bottom = energy.extreme(dT, g.phi, "min")[1]
    inner = np.arange(1, dT.size - 1)
    out = []
    for i in inner[(dT[1:-1] < dT[:-2]) & (dT[1:-1] <= dT[2:])]:
        out.append(top - energy.extreme(dT[i - 1:i + 2], g.phi[i - 1:i + 2], "min")[1])
    for i in inner[(dT[1:-1] > dT[:-2]) & (dT[1:-1] >= dT[2:])]:
        out.append(energy.extreme(dT[i - 1:i + 2], g.phi[i - 1:i + 2], "max")[1] - bottom)
    right = top - bottom
    return tuple(v for v in out if abs(v - right) > 1e-6 * abs(right))


def _masses_halved(g: ch.Givens, M: float) -> tuple[float, ...]:
    """ΔT_нб with the links' masses' share of J_II halved: each velocity analogue multiplied
    by cos 45° (seed 000 §3.1.1, J_PRm2…J_PRm5; seeds README defect 3)."""
    if g.J_II_masses is None:
        return ()
    return (ch.energy_swing(g, M, J_II=g.J_II - g.J_II_masses / 2),)


#: the catalogue, in the order the diagnosis tries them (the first that reproduces the
#: student's number is named)
CATALOGUE: tuple[Mistake, ...] = (
    Mistake("rpm_for_rad_s", "ω_m in rev/min used as rad/s: J_I = ΔT_нб/(n²·δ) with n = "
            "ω_m·30/π; in ΔT_I, T_II = J_II·n²/2", {
                "J_required": lambda g, dT: (ch.required_inertia(g, dT, g.omega_mean *
                                                                 RPM_PER_RAD_S),),
                "delta_T_max": lambda g, M: (ch.energy_swing(g, M, omega=g.omega_mean *
                                                             RPM_PER_RAD_S),),
                "task2:delta": lambda g, dT: (t2.fluctuation(g, dT, g.omega_mean *
                                                             RPM_PER_RAD_S),)},
            cells={"delta_T.T_II": lambda c: (c.key * RPM_PER_RAD_S ** 2,),
                   "delta_T.dT_I": lambda c: (c.key - (c.row["T_II"] - c.first["T_II"])
                                              * (RPM_PER_RAD_S ** 2 - 1),)}),
    Mistake("rad_s_for_rpm", "ω_m in rad/s converted again as if it were rev/min: ω_m·π/30 "
            "used for ω_m", {
                "J_required": lambda g, dT: (ch.required_inertia(g, dT, g.omega_mean *
                                                                 RAD_S_PER_RPM),),
                "task2:delta": lambda g, dT: (t2.fluctuation(g, dT, g.omega_mean *
                                                             RAD_S_PER_RPM),)}),
    Mistake("rps_for_rad_s", "the speed in rev/s (n₁) used as rad/s: ω_m/2π for ω_m", {
        "J_required": lambda g, dT: (ch.required_inertia(g, dT, g.omega_mean / TWO_PI),)}),
    Mistake("half_delta", "δ/2 used for δ (the swing ±δ/2 taken for δ): J_I doubled", {
        "J_required": lambda g, dT: (ch.required_inertia(g, dT, delta=g.delta / 2),)}),
    Mistake("double_delta", "2δ used for δ (±δ taken as the whole fluctuation): J_I halved", {
        "J_required": lambda g, dT: (ch.required_inertia(g, dT, delta=2 * g.delta),)}),
    Mistake("ratio_square_forgotten", "the flywheel on a faster shaft reduced by i instead of "
            "i² (or not reduced): max(J_доп, 0)/i, max(J_доп, 0)", {
                "flywheel_J_on_its_shaft": lambda g, J: tuple(
                    ch.on_its_shaft(g, J, p) for p in (1, 0) if g.speed_ratio != 1)}),
    Mistake("local_extremum", "a local extremum of ΔT_I taken for the global one (the seed "
            "worksheet's own defect)", {"delta_T_max": _local_extremes}),
    Mistake("masses_halved", "the kinetic energy of the links' masses halved by a cos 45° on "
            "each velocity analogue (the worksheet's J_PRm defect); in the bundled templates it "
            "changes ΔT_нб by 0.3–0.5 %, inside a 1 % tolerance",
            {"delta_T_max": _masses_halved}),
    Mistake("sign_lost", "a sign lost in the cycle balance: the constant moment (and the "
            "cycle's work) with the wrong sign, or ΔT_I built with it", {
                "M": lambda g, _: (-ch.cycle_moment(g),),
                "task2:M": lambda g, _: (-t2.found_value(g),),
                "cycle_work_resistance": lambda g, M: (-ch.work_scale(g) * M,),
                "delta_T_max": lambda g, M: (ch.energy_swing(g, -M),)},
            cells={"delta_T.A": lambda c: (c.key - 2 * ch.cycle_moment(c.givens) * c.phi,),
                   "delta_T.dT_I": lambda c: (c.key - 2 * ch.cycle_moment(c.givens) * c.phi,)}),
    Mistake("degrees_for_radians", "the cycle's angle in degrees where radians belong: "
            "M = −A(Φ)/360°, A_C = M·Φ°", {
                "M": lambda g, _: (energy.balancing_moment(g.A_known, g.phi * DEG_PER_RAD),),
                "cycle_work_resistance": lambda g, M: (ch.work_scale(g) * DEG_PER_RAD * M,)},
            cells={"analogues.vq": lambda c: (c.key / DEG_PER_RAD,),
                   "delta_T.A": lambda c: (c.key + ch.cycle_moment(c.givens) * c.phi
                                           * (DEG_PER_RAD - 1),)}),
    Mistake("radius_for_diameter", "the flywheel's radius given for its diameter", {
        f"flywheel_{w}.{f}": (lambda g, J, w=w, f=f: (ch.shape(g, J, w, f) / 2,))
        for w, fs in (("disk", ("D",)), ("rim", ("D", "D_inner"))) for f in fs}),
    Mistake("first_group_not_subtracted", "the first group's own J_10 + J_ред not subtracted "
            "from J_I (J_М = J_I), or added to it (seed 000 §4: J_доп = J_PRI − J_10 − J_ред)",
            {"J_flywheel": lambda g, J_I: (J_I, J_I + g.J_first) if g.J_first else ()}),
    Mistake("g_10", "g = 10 m/s² for 9.81: the weights do no work over a cycle (M unchanged) "
            "and their share of ΔT_I is small: a matter of the tolerance, not tried", {},
            tolerance_matter=True),
)

BY_CODE = {m.code: m for m in CATALOGUE}


def diagnose(chain: ch.Chain, answer: str, given: dict, tolerance: float,
             close: Callable[[float, float, float], bool],
             tolerances: dict | None = None) -> str | None:
    """The code of the first mistake of the catalogue that reproduces the student's value of
    ``answer`` (within ``tolerance`` by ``close(given, candidate, tolerance)``), computed from
    the student's own earlier answers and then from the key's (the givens alone); None if
    none does.

    From the key's givens a mistake in a step must also reproduce the student's other answers
    computed through that step, but not from ``answer`` (a later slip is another matter;
    ``tolerances``: answer → its tolerance, default ``tolerance``): a student whose driving
    moment is right did not take the cycle in degrees, whatever a diameter — D ∝ J^(1/5),
    which brings a wide range of wrong J near a rounded D — happens to match."""
    value = given.get(answer, math.nan)
    if value != value or not chain.knows(answer):
        return None
    steps = chain.path(answer)
    for m in CATALOGUE:
        for step in steps:
            twist = m.twists.get(chain.twist_key(step))
            if twist is None:
                continue
            for source in (given, {}):
                try:
                    cands, _ = chain.recompute(answer, source, (step, twist))
                except (ArithmeticError, ValueError):
                    continue
                if not any(math.isfinite(c) and close(value, c, tolerance) for c in cands):
                    continue
                if source or not _refuted(chain, answer, given, step, twist, tolerance,
                                          close, tolerances or {}):
                    return m.code
    return None


def _refuted(chain: ch.Chain, answer: str, given: dict, step: str, twist, tolerance: float,
             close, tolerances: dict) -> bool:
    """Whether one of the student's other answers computed through ``step``, not from
    ``answer``, is not what the mistake ``twist`` there gives from the key's givens (see
    :func:`diagnose`)."""
    for other, v in given.items():
        if other == answer or v != v or not chain.knows(other):
            continue
        path = chain.path(other)
        if step not in path or answer in path:     # not through the step, or after the answer
            continue
        try:
            cands, _ = chain.recompute(other, {}, (step, twist))
        except (ArithmeticError, ValueError):
            return True
        if not any(math.isfinite(c) and close(v, c, tolerances.get(other, tolerance))
                   for c in cands):
            return True
    return False
