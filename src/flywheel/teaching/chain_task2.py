"""The dependency chain of a ``flywheel task2`` template's answers (issue 27): «Задача 2»
(constant reduced inertia J, given moment graphs) as teaching/chain.py does it for a run case,
so that ``flywheel grade`` carries an error forward and names the classic mistakes there too::

    M (the value of the graph the cycle balance finds: M_C, or M_D; constant_inertia.balance)
      ├─ M_C (or M_D) = M
      ├─ delta_T_max = max A − min A,  A(φ) = A_D(φ) − A_C(φ), the found graph scaled by M
      │    ├─ delta = ΔT_нб/(J·ω_ср²)            (ω_max² − ω_min² = 2ΔT_нб/J, ω_ср = (ω_max + ω_min)/2)
      │    └─ J_required = ΔT_нб/(ω_ср²·δ)     (sizing.J_required_merzalov)
      │         └─ rim_mass = J_required/R²
      └─ omega_max, omega_min = √(ω0² + 2·A_max/J), √(ω0² + 2·A_min/J)

δ and J_required take the student's own ω_ср (his ω_max and ω_min where he gave them, else the
motion's with his ΔT_нб): at a machine's δ it moves with M (``mean_speed``).

The graphs' works A_D(φ), A_C(φ) are sampled on the cycle (every 1.5° and the segment
table's angles: its bounds and crossings, where A has its extremes) from the moment graphs of
the solved variant (``Piece.work``, the closed form the solver uses); the found graph's work
is proportional to its value (a constant, a peak or a scale), so A for a student's M is the
key's with that graph's work scaled by M/M_key.

Computation only: no typer, no rich.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.dynamics import energy, sizing

#: intervals of the sampled cycle (plus the segment table's angles)
SAMPLES = 240
DIGITS = 9


def _cumulative(moment, xs) -> np.ndarray:
    """∫₀^φ M dφ [J] at the angles ``xs`` (sorted) from the graph's pieces (``Piece.work``)."""
    out, acc, j = [], 0.0, 0
    pieces = moment.pieces
    for x in xs:
        while j < len(pieces) - 1 and x >= pieces[j].phi1:
            acc += pieces[j].work(pieces[j].phi1)
            j += 1
        out.append(acc + pieces[j].work(x))
    return np.asarray(out, dtype=float)


@dataclass(frozen=True)
class Task2Givens:
    """What a task2 variant's chain needs besides the answers (SI): which graph the balance
    found ("driving", "resistance" or None) and its value M_key [N·m], J [kg·m²], ω0 [rad/s]
    (None: the mean speed is given), the key's ω_ср [rad/s], the asked δ (None: not asked), the
    rim's mean radius R [m] (None), and on a φ grid [rad] the works A_D, A_C [J]."""

    found: str | None
    nominal: float
    J: float
    omega0: float | None
    omega_mean: float
    delta: float | None
    rim_radius: float | None
    phi: np.ndarray
    A_D: np.ndarray
    A_C: np.ndarray

    SCALARS = ("found", "nominal", "J", "omega0", "omega_mean", "delta", "rim_radius")
    CURVES = ("phi", "A_D", "A_C")

    def to_document(self) -> dict:
        doc = {"kind": "task2", **{k: getattr(self, k) for k in self.SCALARS}}
        for k in self.CURVES:
            doc[k] = [float(f"{x:.{DIGITS}g}") for x in getattr(self, k)]
        return doc

    @classmethod
    def from_document(cls, doc: dict) -> "Task2Givens":
        """From answers.json's ``chain.givens.<id>`` (ValueError/TypeError/KeyError if broken)."""
        s = {k: doc[k] for k in cls.SCALARS}
        if s["found"] not in ("driving", "resistance", None):
            raise ValueError
        for k in ("nominal", "J", "omega_mean", "omega0", "delta", "rim_radius"):
            if s[k] is not None:
                s[k] = float(s[k])
                if not math.isfinite(s[k]):
                    raise ValueError
        if s["nominal"] is None or s["J"] is None:
            raise ValueError
        curves = {k: np.asarray(doc[k], dtype=float) for k in cls.CURVES}
        n = curves["phi"].size
        if n < 3 or any(c.shape != (n,) or not np.all(np.isfinite(c)) for c in curves.values()):
            raise ValueError
        return cls(**s, **curves)

    def steps(self) -> dict:
        """The steps of this variant's chain (J_required only when δ is asked, rim_mass only
        with a rim's radius)."""
        drop = ({"J_required", "rim_mass"} if self.delta is None else set()) | (
            {"rim_mass"} if self.rim_radius is None else set())
        return {k: s for k, s in STEPS[self.found].items() if k not in drop}


def task2_givens_of(result) -> Task2Givens | None:
    """The chain's givens of a solved task2 case (``constant_inertia.solve.Task2Result``);
    None for an area diagram (no graphs)."""
    if result.driving is None or result.resistance is None:
        return None
    rows = sorted({r.phi for r in result.rows})
    grid = [result.cycle * i / SAMPLES for i in range(SAMPLES + 1)]
    # the table's angles, and the grid's nodes not within 1e-6 rad of one (no two nodes
    # that round to one: the parabola of energy.extreme needs three distinct angles)
    xs = sorted(rows + [x for x in grid if min(abs(x - r) for r in rows) > 1e-6])
    nominal = result.M_C if result.unknown == "resistance" else result.M_D
    if result.unknown is None or nominal is None or nominal == 0:
        return None
    try:
        A_D, A_C = _cumulative(result.driving, xs), _cumulative(result.resistance, xs)
    except (ArithmeticError, ValueError):
        return None
    g = Task2Givens(
        found=result.unknown, nominal=float(nominal), J=float(result.J),
        omega0=None if result.omega0 is None else float(result.omega0),
        omega_mean=float(result.omega_mean),
        delta=None if result.delta_target is None else float(result.delta_target),
        rim_radius=None if result.rim_mass is None else float(result.rim_radius),
        phi=np.asarray(xs), A_D=A_D, A_C=A_C)
    numbers = [x for x in (g.nominal, g.J, g.omega0, g.omega_mean, g.delta, g.rim_radius)
               if x is not None]
    if not (np.all(np.isfinite(numbers)) and np.all(np.isfinite(A_D))
            and np.all(np.isfinite(A_C)) and A_D[-1] != 0 and A_C[-1] != 0):
        return None               # no chain where the works do not stay finite numbers
    return g


# -- the steps ----------------------------------------------------------------------------------

def found_value(g: Task2Givens) -> float:
    """M of the found graph from the cycle balance ∮M_D dφ = ∮M_C dφ, the graph's work being
    proportional to its value (``constant_inertia.solve.balance``; «Задача 2»: M_C from
    A_D(Φ) = A_C(Φ))."""
    if g.found == "resistance":
        return g.nominal * g.A_D[-1] / g.A_C[-1]
    return g.nominal * g.A_C[-1] / g.A_D[-1]


def work_curve(g: Task2Givens, M: float) -> np.ndarray:
    """A(φ) = A_D(φ) − A_C(φ) [J] with the found graph's value M (its work scaled by M/M_key;
    ``constant_inertia.solve.sample``)."""
    k = M / g.nominal
    if g.found == "resistance":
        return g.A_D - k * g.A_C
    return k * g.A_D - g.A_C


def _extremes(g: Task2Givens, M: float) -> tuple[float, float]:
    A = work_curve(g, M)
    return energy.extreme(A, g.phi, "max")[1], energy.extreme(A, g.phi, "min")[1]


def energy_swing(g: Task2Givens, M: float) -> float:
    """ΔT_нб = A_max − A_min [J] (constant J: ΔT = A; ``constant_inertia.solve._motion``)."""
    top, bottom = _extremes(g, M)
    return top - bottom


def speed_at(g: Task2Givens, M: float, which: str) -> float:
    """ω_max or ω_min [rad/s]: √(ω0² + 2·A/J) at A's extreme (``constant_inertia.solve.sample``),
    ω0² from the mean speed when that is given (``constant_inertia.solve._speed_from_mean``)."""
    from flywheel.constant_inertia.solve import _speed_from_mean

    top, bottom = _extremes(g, M)
    w0sq = g.omega0 ** 2 if g.omega0 is not None else _speed_from_mean(top, bottom, g.J,
                                                                         g.omega_mean)
    return math.sqrt(w0sq + 2 * (top if which == "max" else bottom) / g.J)


#: the bisection's steps in :func:`mean_speed_for` (the bracket halves to 2⁻⁶⁰ of its width)
BISECTIONS = 60


def mean_speed_for(g: Task2Givens, dT: float) -> float:
    """ω_ср [rad/s] of the motion whose ΔT_нб is ``dT``: with ω0 given, ω_max and ω_min —
    and their mean — move with the found graph's value M, so a student who took a wrong M has
    his own ω_ср, not the key's (at the textbook's δ ≈ 10⁻⁴ the two differ in the fifth digit;
    at a machine's δ of 0.05 a 50 % wrong M moves ω_ср by a few per cent). M is found from
    ``dT`` on ΔT_нб(M) (:func:`energy_swing`, convex in M: the greatest minus the least of
    functions linear in M) by bisection on the side of the key's M where ``dT`` lies; the
    key's ω_ср when the mean speed is given, or where no M gives ``dT``."""
    M0, dT0 = g.nominal, energy_swing(g, g.nominal)
    if g.omega0 is None or not math.isfinite(dT) or dT <= 0 or dT == dT0:
        return g.omega_mean
    step = 0.01 * abs(M0) or 1.0
    rising = energy_swing(g, M0 + step) >= dT0      # ΔT_нб grows with M here
    sign = 1.0 if (dT > dT0) == rising else -1.0
    near, far = M0, M0 + sign * step
    for _ in range(BISECTIONS):                     # a bracket: ΔT_нб(far) past dT
        if (energy_swing(g, far) - dT) * (dT0 - dT) <= 0:
            break
        near, far = far, M0 + 2 * (far - M0)
    else:
        return g.omega_mean
    for _ in range(BISECTIONS):
        mid = 0.5 * (near + far)
        if (energy_swing(g, mid) - dT) * (dT0 - dT) > 0:
            near = mid
        else:
            far = mid
    M = 0.5 * (near + far)
    return 0.5 * (speed_at(g, M, "max") + speed_at(g, M, "min"))


def mean_speed(g: Task2Givens, dT: float, own: dict | None = None) -> float:
    """ω_ср [rad/s] a student works δ and J with: his own (ω_max + ω_min)/2 where he gave both
    (``own``: his answers), else the motion's with his ΔT_нб (:func:`mean_speed_for`)."""
    w = ((own or {}).get("omega_max", math.nan) + (own or {}).get("omega_min", math.nan)) / 2
    return w if math.isfinite(w) and w > 0 else mean_speed_for(g, dT)


def fluctuation(g: Task2Givens, dT: float, omega: float | None = None,
                own: dict | None = None) -> float:
    """δ = ΔT_нб/(J·ω_ср²): ω_max² − ω_min² = 2ΔT_нб/J with ω_ср = (ω_max + ω_min)/2
    (``constant_inertia.solve``: δ = (ω_max − ω_min)/ω_ср), ω_ср the student's own
    (:func:`mean_speed`). ``omega``: a classic mistake's."""
    w = mean_speed(g, dT, own) if omega is None else omega
    return dT / (g.J * w * w)


def required_inertia(g: Task2Givens, dT: float, omega: float | None = None,
                     delta: float | None = None, own: dict | None = None) -> float:
    """J = ΔT_нб/(ω_ср²·δ) [kg·m²] (``sizing.J_required_merzalov``, as ``_J_for``), ω_ср the
    student's own (:func:`mean_speed`)."""
    return sizing.J_required_merzalov(dT, mean_speed(g, dT, own) if omega is None else omega,
                                      g.delta if delta is None else delta)


def _steps(found: str) -> dict:
    from flywheel.teaching.chain import Step

    name = "M_C" if found == "resistance" else "M_D"
    out = [
        Step("M", None, "constant_inertia.balance", lambda g, _: found_value(g),
             twist_as="task2:M"),
        Step(name, "M", "M", lambda g, M: M, lambda g: 1.0, twist_as=f"task2:{name}"),
        Step("delta_T_max", "M", "A_max − A_min", energy_swing, twist_as="task2:delta_T_max"),
        Step("omega_max", "M", "√(ω0² + 2·A_max/J)", lambda g, M: speed_at(g, M, "max"),
             twist_as="task2:omega_max"),
        Step("omega_min", "M", "√(ω0² + 2·A_min/J)", lambda g, M: speed_at(g, M, "min"),
             twist_as="task2:omega_min"),
        Step("delta", "delta_T_max", "ΔT_нб/(J·ω_ср²)", fluctuation, twist_as="task2:delta",
             also=("omega_max", "omega_min")),
        # the same step as a run case's: its classic mistakes (rev/min, δ/2, …) apply
        Step("J_required", "delta_T_max", "sizing.J_required_merzalov", required_inertia,
             also=("omega_max", "omega_min")),
        Step("rim_mass", "J_required", "J_required/R²", lambda g, J: J / g.rim_radius ** 2,
             twist_as="task2:rim_mass"),
    ]
    return {s.name: s for s in out}


STEPS = {"resistance": _steps("resistance"), "driving": _steps("driving")}
