"""The dependency chain of a run case's answers (issue 27): how each answer of a variant is
computed from the earlier ones, so that ``flywheel grade`` can recompute a later answer from
a student's own earlier values (error carried forward) and try the classic mistakes
(:mod:`flywheel.teaching.mistakes`) on the same chain.

The chain of the course (seed 000 §3.2.7 and §4; seeds README's summary of the worksheet)::

    M (the constant moment of the cycle balance, −A_known(Φ)/Φ)
      ├─ balancing_moment = M, driving_moment = ±M, cycle_work_resistance = ∓M·Φ
      └─ delta_T_max = max ΔT_I − min ΔT_I,  ΔT_I(φ) = A_known + M·φ − (T_II − T_II(0))
           └─ J_required = ΔT_нб/(ω_m²·δ)
                └─ J_flywheel = J_required − J_first_group
                     └─ flywheel_J_on_its_shaft = max(J_flywheel, 0)/i²
                          └─ flywheel_disk.* (D, b, mass), flywheel_rim.* (D, D_inner, b, mass)

Every step calls the function the analysis itself uses (``dynamics.energy``,
``dynamics.sizing``): the chain is not a copy of the physics. What a step needs besides its
parent — ω_m, δ, J_first_group, the flywheel's ratio and material, and the curves A_known(φ),
J_II(φ) (and its masses' share, for a classic mistake) sampled at most :data:`SAMPLES` times
over the cycle — is the variant's :class:`Givens`, written into answers.json.

Computation only: no typer, no rich.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from flywheel.dynamics import energy, sizing

#: intervals of the φ grid kept for the chain's curves (the analysis's grid is cut down to
#: at most this many, every k-th node, the extremes of ΔT_I kept): ΔT_нб recomputed from them
#: differs from a full grid's by under 5e-4 relative (tests/teaching/test_chain.py)
SAMPLES = 120
#: significant digits of the curves written into answers.json
DIGITS = 7


@dataclass(frozen=True)
class Givens:
    """What a variant's chain needs besides the answers (SI units): the balance, the cycle Φ
    [rad], ω_m [rad/s], δ, J_first_group [kg·m²], the flywheel's speed ratio i, material
    density ρ [kg/m³], b/D, D_inner/D, the rim's share, the formulas ("first-principles" or
    "course"), and on a φ grid [rad] A_known [J], J_II [kg·m²] and J_II's share of the links'
    masses [kg·m²] (None when the kinematics are a table)."""

    balance: str
    cycle: float
    omega_mean: float
    delta: float
    J_first: float
    speed_ratio: float
    density: float
    width_ratio: float
    inner_ratio: float
    rim_share: float
    formulas: str
    phi: np.ndarray
    A_known: np.ndarray
    J_II: np.ndarray
    J_II_masses: np.ndarray | None

    SCALARS = ("balance", "cycle", "omega_mean", "delta", "J_first", "speed_ratio", "density",
               "width_ratio", "inner_ratio", "rim_share", "formulas")
    CURVES = ("phi", "A_known", "J_II", "J_II_masses")

    def steps(self) -> dict:
        """The steps of a run case's chain (:data:`STEPS`)."""
        return STEPS

    def to_document(self) -> dict:
        doc = {k: getattr(self, k) for k in self.SCALARS}
        for k in self.CURVES:
            v = getattr(self, k)
            doc[k] = None if v is None else [float(f"{x:.{DIGITS}g}") for x in v]
        return doc

    @classmethod
    def from_document(cls, doc: dict) -> "Givens":
        """From answers.json's ``chain.givens.<id>`` (ValueError/TypeError/KeyError if broken)."""
        scalars = {k: doc[k] for k in cls.SCALARS}
        for k in cls.SCALARS:
            if k not in ("balance", "formulas"):
                scalars[k] = float(scalars[k])
                if not math.isfinite(scalars[k]):
                    raise ValueError
        curves = {k: None if doc.get(k) is None else np.asarray(doc[k], dtype=float)
                  for k in cls.CURVES}
        n = curves["phi"].size
        if n < 3 or any(c is not None and (c.shape != (n,) or not np.all(np.isfinite(c)))
                        for c in curves.values()):
            raise ValueError
        return cls(**scalars, **curves)


def _kept_nodes(phi: np.ndarray, dT_I: np.ndarray) -> np.ndarray:
    """Every k-th node of the grid (at most SAMPLES intervals), the ends, and the nodes of
    ΔT_I's global extremes with their neighbours (the parabola of ``energy.extreme``)."""
    n = phi.size - 1
    step = max(1, math.ceil(n / SAMPLES))
    keep = set(range(0, n + 1, step)) | {n}
    for i in (int(np.argmax(dT_I)), int(np.argmin(dT_I))):
        keep |= {j for j in (i - 1, i, i + 1) if 0 <= j <= n}
    return np.array(sorted(keep))


def givens_of(case, results) -> Givens | None:
    """The chain's givens of one analysed run case (``cases.run.Case``, ``dynamics.Results``);
    None when the flywheel is given (not sized: J_required is then not ΔT_нб/(ω_m²·δ))."""
    fw = case.flywheel
    if fw.given_J is not None:
        return None
    en, red = results.energy, results.reduction
    phi = results.phi
    A_known = en.A - en.balancing_moment * phi       # A = A_known + M·φ (stages.work_and_energy)
    masses = None
    kin = results.kinematics
    if kin is not None:
        from flywheel.dynamics import reduction

        masses = np.zeros_like(phi)
        for name, lk in case.links.items():
            if lk.mass == 0 or not lk.centroid:
                continue
            c = kin.points[lk.centroid]
            lm = kin.links[name]
            masses = masses + reduction.link_inertia(lk.mass, 0.0, c.v_q, c.a_q, lm.omega_q,
                                                     lm.eps_q)[0]
    idx = _kept_nodes(phi, en.dT_I)
    return Givens(
        balance=en.balance, cycle=float(phi[-1] - phi[0]), omega_mean=float(case.machine.omega_mean),
        delta=float(case.machine.delta), J_first=float(sum(case.machine.first_group.values())),
        speed_ratio=float(fw.speed_ratio), density=float(fw.rho), width_ratio=float(fw.width_ratio),
        inner_ratio=float(fw.inner_ratio), rim_share=float(fw.rim_share), formulas=fw.formulas,
        phi=phi[idx], A_known=A_known[idx], J_II=red.J_II[idx],
        J_II_masses=None if masses is None else masses[idx])


# -- the steps ----------------------------------------------------------------------------------

def cycle_moment(g: Givens) -> float:
    """M = −A_known(Φ)/Φ [N·m]: the constant moment of the cycle balance
    (``energy.balancing_moment``; seed 000: M_PRD = −A_C/2π)."""
    return energy.balancing_moment(g.A_known, g.phi)


def driving_scale(g: Givens) -> float:
    """driving_moment/M: 1 when the constant moment drives, −1 when it resists (the driving
    moment is then the loads' mean, A_known(Φ)/Φ = −M; stages.work_and_energy)."""
    return 1.0 if g.balance == "driving" else -1.0


def work_scale(g: Givens) -> float:
    """cycle_work_resistance/M: Φ when M is the resistance (A_C = M·Φ), −Φ when M drives
    (A_C = A_known(Φ) = −M·Φ; stages.work_and_energy)."""
    return g.cycle if g.balance == "resistance" else -g.cycle


def energy_swing(g: Givens, M: float, J_II: np.ndarray | None = None,
                 omega: float | None = None) -> float:
    """ΔT_нб = max ΔT_I − min ΔT_I [J] with ΔT_I(φ) = A_known + M·φ − (T_II − T_II(0))
    (``energy.first_group_energy_change``, the global extremes of ``energy.extreme``;
    seed 000 §4). ``J_II`` and ``omega`` replace the variant's (a classic mistake's)."""
    A = g.A_known + M * g.phi
    _, dT = energy.first_group_energy_change(A, g.J_II if J_II is None else J_II,
                                             g.omega_mean if omega is None else omega)
    return energy.extreme(dT, g.phi, "max")[1] - energy.extreme(dT, g.phi, "min")[1]


def energy_curve(g: Givens, M: float) -> np.ndarray:
    """ΔT_I(φ) [J] on the givens' grid (``energy.first_group_energy_change``)."""
    return energy.first_group_energy_change(g.A_known + M * g.phi, g.J_II, g.omega_mean)[1]


def required_inertia(g: Givens, dT: float, omega: float | None = None,
                     delta: float | None = None) -> float:
    """J_I = ΔT_нб/(ω_m²·δ) [kg·m²] (``sizing.J_required_merzalov``; seed 000 §4)."""
    return sizing.J_required_merzalov(dT, g.omega_mean if omega is None else omega,
                                      g.delta if delta is None else delta)


def flywheel_inertia(g: Givens, J_I: float) -> float:
    """J_доп = J_I − J_first_group [kg·m²] (seed 000 §4: J_доп = J_PRI − J_10 − J_ред)."""
    return J_I - g.J_first


def on_its_shaft(g: Givens, J_fly: float, power: int = 2) -> float:
    """The flywheel on its own shaft: max(J_доп, 0)/i² [kg·m²] (seed 003, eqs. 9.21–9.23;
    stages.size_flywheel). ``power`` 1 or 0: a classic mistake's."""
    return max(J_fly, 0.0) / g.speed_ratio ** power


def shape(g: Givens, J_shaft: float, which: str, field: str) -> float:
    """A dimension of the flywheel of J on its shaft [kg·m²]: ``sizing.disk`` / ``sizing.rim``
    (or the course's ``disk_course`` / ``rim_course``), as stages.size_flywheel calls them."""
    if which == "disk":
        d = (sizing.disk_course(J_shaft) if g.formulas == "course"
             else sizing.disk(J_shaft, g.density, g.width_ratio))
    else:
        J = J_shaft * g.rim_share
        d = (sizing.rim_course(J) if g.formulas == "course"
             else sizing.rim(J, g.density, g.width_ratio, g.inner_ratio))
    return float(d[field])


@dataclass(frozen=True)
class Step:
    """One quantity of the chain: its parent (None: computed from the givens alone), the
    function (givens, parent's value) → value, and its name written into the key."""

    name: str
    parent: str | None
    by: str
    fn: Callable
    scale: Callable | None = None     # a multiple of M: value = scale(g)·M
    twist_as: str | None = None       # the catalogue's name of the step (None: ``name``)
    #: other answers the step reads as the student gave them, where they come before it:
    #: ``fn(g, x, own={name: value})`` (task 2's δ and J take the student's own ω_ср from his
    #: ω_max and ω_min); a value not given is nan
    also: tuple[str, ...] = ()

    @property
    def twist_key(self) -> str:
        return self.name if self.twist_as is None else self.twist_as


def _steps() -> dict[str, Step]:
    out = [
        Step("M", None, "energy.balancing_moment", lambda g, _: cycle_moment(g)),
        Step("balancing_moment", "M", "M", lambda g, M: M, lambda g: 1.0),
        Step("driving_moment", "M", "±M", lambda g, M: driving_scale(g) * M, driving_scale),
        Step("cycle_work_resistance", "M", "∓M·Φ", lambda g, M: work_scale(g) * M, work_scale),
        Step("delta_T_max", "M", "energy_swing (energy.first_group_energy_change, "
             "energy.extreme)", energy_swing),
        Step("J_required", "delta_T_max", "sizing.J_required_merzalov", required_inertia),
        Step("J_flywheel", "J_required", "J_required − J_first_group", flywheel_inertia),
        Step("flywheel_J_on_its_shaft", "J_flywheel", "max(J_flywheel, 0)/i²", on_its_shaft),
    ]
    for which, fields in (("disk", ("D", "b", "mass")), ("rim", ("D", "D_inner", "b", "mass"))):
        for f in fields:
            out.append(Step(f"flywheel_{which}.{f}", "flywheel_J_on_its_shaft",
                            f"sizing.{which}", lambda g, J, w=which, f=f: shape(g, J, w, f)))
    return {s.name: s for s in out}


STEPS = _STEPS = _steps()


def chain_table(answers, steps: dict | None = None) -> dict[str, dict]:
    """answers.json's ``chain.steps``: for each answer the chain knows, the earlier answers it
    is computed from (the nearest ones up its chain) and the functions on the way (``steps``:
    a task2 chain's, teaching/chain_task2.py; default a run case's)."""
    STEPS = _STEPS if steps is None else steps
    out = {}
    order = list(answers)
    for a in order:
        if a not in STEPS:
            continue
        by, node, sources = [STEPS[a].by], STEPS[a].parent, []
        while node is not None:
            if node in order[:order.index(a)]:
                sources = [node]
                break
            if node == "M":
                sources = [b for b in order[:order.index(a)]
                           if b in STEPS and STEPS[b].scale is not None][:1]
                if sources:
                    break
            by.append(STEPS[node].by)
            node = STEPS[node].parent
        out[a] = {"from": sources, "by": " ∘ ".join(by)}
    return out


# -- a student's chain --------------------------------------------------------------------------

#: a variant of a step: (step's name, function (givens, parent value) → candidate values)
Twist = tuple[str, Callable[[Givens, float], tuple[float, ...]]]


class Chain:
    """A variant's chain over the answers in the key's order. ``recompute(a, given)`` is
    answer ``a`` computed from the student's own earlier answers (``given``: answer → value,
    NaN = none): each input is the student's value where they gave one, else computed
    further up from theirs (at the top from the givens)."""

    def __init__(self, givens, answers):
        self.g = givens
        self.steps = givens.steps()
        self.order = [a for a in answers]
        self.pos = {a: i for i, a in enumerate(self.order)}

    def knows(self, answer: str) -> bool:
        return answer in self.steps and self.steps[answer].parent is not None

    def path(self, answer: str) -> list[str]:
        """``answer`` and the steps above it, up to the top of the chain."""
        out, node = [], answer
        while node is not None:
            out.append(node)
            node = self.steps[node].parent
        return out

    def twist_key(self, step: str) -> str:
        """The catalogue's name of ``step`` (teaching/mistakes.py: a task2 step's is
        ``task2:<name>`` unless it is the run chain's own step)."""
        return self.steps[step].twist_key

    def _value(self, node: str, before: int, given, twist: Twist | None):
        """(values, the answer they came from or None: the givens, a twist applied): the
        student's value(s) of ``node`` as the answers before position ``before`` give it."""
        p = self.pos.get(node)
        if p is not None and p < before:
            v = given.get(node, math.nan)
            if v == v:
                return (v,), node, False
        if node == "M":
            for a in self.order[:before]:
                s = self.steps.get(a)
                v = given.get(a, math.nan)
                if s is not None and s.scale is not None and v == v:
                    k = s.scale(self.g)
                    if k:
                        return (v / k,), a, False
        return self._computed(node, before, given, twist)

    def _computed(self, node: str, before: int, given, twist: Twist | None):
        step = self.steps[node]
        if step.parent is None:
            ins, src, twisted = (math.nan,), None, False
        else:
            ins, src, twisted = self._value(step.parent, before, given, twist)
        if twist is not None and twist[0] == node:
            return tuple(v for x in ins for v in twist[1](self.g, x)), src, True
        if step.also:
            own = {a: given.get(a, math.nan) if self.pos.get(a, before) < before else math.nan
                   for a in step.also}
            return tuple(step.fn(self.g, x, own=own) for x in ins), src, twisted
        return tuple(step.fn(self.g, x) for x in ins), src, twisted

    def recompute(self, answer: str, given, twist: Twist | None = None
                  ) -> tuple[tuple[float, ...], str | None]:
        """(values, source): ``answer`` recomputed from the student's earlier answers, and
        the answer whose value fed it (None: none of the student's answers did). With a
        classic mistake's ``twist`` on one step: the candidates it gives, () when the step
        is not on the way (the student gave its value)."""
        vals, src, twisted = self._computed(answer, self.pos[answer], given, twist)
        if twist is not None and not twisted:
            return (), src
        return vals, src
