"""Task 2: steady motion of a machine with constant reduced inertia under given moment graphs.

The problem (seed ``002_10afb132413d2537.txt``, «Задача 2»; R.S. Khurmi & J.K. Gupta,
*Theory of Machines*, ch. 16 "Turning Moment Diagrams and Flywheel"): the forces and masses of a
machine are reduced to one link with constant moment of inertia ``J`` [kg·m²]; the driving moment
``M_D(φ)`` and the resistance moment ``M_C(φ)`` [N·m] are given as graphs over one cycle of
length ``Φ`` [rad] (:mod:`flywheel.constant_inertia.graphs`). The kinetic-energy theorem on
``[0, φ]``::

    ½·J·(ω(φ)² − ω0²) = A(φ) = ∫₀^φ (M_D − M_C) dφ

gives the speed ``ω(φ)`` [rad/s]. Every piece is integrated in closed form; ``ω`` is extreme at
the sign changes of ``M_D − M_C`` (:mod:`flywheel.constant_inertia.crossings`).

Results (all SI): ``ω_max``, ``ω_min`` and their angles; ``ω_ср = (ω_max + ω_min)/2``;
``δ = (ω_max − ω_min)/ω_ср``; ``ΔT_нб = A_max − A_min`` [J]. Because
``ω_max² − ω_min² = 2·ΔT_нб/J``, the exact relations ``δ = ΔT_нб/(J·ω_ср²)`` and
``J = ΔT_нб/(δ·ω_ср²)`` hold (the textbook's ``ΔE = I·ω²·C_s`` is exact with ``ω = ω_ср``); the
latter is :func:`flywheel.dynamics.sizing.J_required_merzalov`.

The seed divides by ω0 instead of ω_ср and prints ``ω4 = ω5 = 199.91`` (the true minimum is
199.98896 rad/s at 11π/8); its ``M_C = 60 N·m`` is right.

Pure functions on plain floats (``math`` only at import; the sizing formula's module, which
imports numpy, only where a J is asked for): importing this module is cheap.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable, Sequence

from flywheel.constant_inertia.crossings import bisect_root, crossings, stationary_points
from flywheel.constant_inertia.graphs import TWO_PI, Moment, Piece, net_pieces, size
from flywheel.errors import InputError, Notice
# the time law's quadrature (re-exported: flywheel.constant_inertia.solve keeps the names)
from flywheel.constant_inertia.quadrature import TIME_RTOL, _gk15, integrate  # noqa: F401
from flywheel.units import RPM_PER_RAD_S

# relative tolerance of the cycle balance (steady motion) and of the sum of areas
BALANCE_RTOL = 1e-9


class NotFiniteError(OverflowError):
    """A quantity came out inf or NaN (inputs near the limits of double precision), so no
    extreme can be chosen and no result stated. ``quantity`` names it as the results document
    does (``M_C``, ``work_driving``, ``segments[3].A``); ``detail`` says what happened."""

    def __init__(self, quantity: str, detail: str):
        super().__init__(f"{quantity} is not finite ({detail})")
        self.quantity = quantity
        self.detail = detail


def python_detail(text: str) -> Notice:
    """What Python's arithmetic said ("-inf + inf in fsum"), the detail of a NotFiniteError: a
    Notice, so that render/messages.py can say the known ones in Russian."""
    return Notice.of("t2_python_error", "{words}", words=text)


def _cycle_work(m: Moment, quantity: str) -> float:
    """∮ M dφ [J]; NotFiniteError when the sum overflows (fsum raises on inf − inf)."""
    try:
        return m.work()
    except (OverflowError, ValueError) as exc:
        raise NotFiniteError(quantity, python_detail(str(exc))) from None


def _J_for(delta_T_max: float, omega_mean: float, delta: float) -> float:
    """J = ΔT_нб/(δ·ω_ср²) [kg·m²]: :func:`flywheel.dynamics.sizing.J_required_merzalov`
    (imported here: its module loads numpy)."""
    from flywheel.dynamics.sizing import J_required_merzalov

    return J_required_merzalov(delta_T_max, omega_mean, delta)


@dataclass(frozen=True)
class Row:
    """One line of the segment table: a bound of a segment or a crossing M_D = M_C.

    phi [rad]; M_D, M_C [N·m] on the segment that starts here (at the cycle end: before it),
    None for a diagram given by areas; A = ∫₀^φ (M_D − M_C) dφ [J]; omega [rad/s];
    t : the time since φ = 0, t(φ) = ∫₀^φ dφ/ω [s] (None for a diagram given by areas).
    """

    phi: float
    kind: str  # "bound" | "crossing"
    M_D: float | None
    M_C: float | None
    A: float
    omega: float
    t: float | None = None

    DOCUMENT = (("phi_deg", "phi_deg"), ("phi", "phi_or_none"), "kind", "M_D", "M_C", "A",
                "omega", "t")
    KEEP_NONE = ("phi_deg", "phi", "M_D", "M_C", "t")

    @property
    def phi_deg(self) -> float | None:
        """φ [deg] (None for no angle)."""
        return _deg(self.phi)

    @property
    def phi_or_none(self) -> float | None:
        """φ [rad], None for no angle."""
        return None if math.isnan(self.phi) else self.phi


@dataclass(frozen=True)
class AtPoint:
    """The motion at an asked angle: phi [rad]; omega [rad/s]; epsilon = (M_D − M_C)/J
    [rad/s²] (at a jump of a graph: just after it; at the cycle's end: just before it);
    t = ∫₀^φ dφ/ω [s]."""

    phi: float
    omega: float
    epsilon: float
    t: float

    DOCUMENT = (("phi_deg", "phi_deg"), "omega", "epsilon", "t")
    KEEP_NONE = ("phi_deg", "omega", "epsilon", "t")

    @property
    def phi_deg(self) -> float | None:
        """φ [deg]."""
        return _deg(self.phi)


@dataclass(frozen=True)
class Phase:
    """A stretch of the cycle where the speed only rises (trend "up", M_D > M_C), only falls
    ("down", M_D < M_C) or stays ("steady", M_D = M_C): from phi_start to phi_end [rad],
    entered at t_start [s], lasting duration [s]. Its ends are the extremes of ω (the sign
    changes of M_D − M_C, crossings or jumps)."""

    phi_start: float
    phi_end: float
    t_start: float
    duration: float
    trend: str   # "up" | "down" | "steady"

    DOCUMENT = (("from_deg", "from_deg"), ("to_deg", "to_deg"), "t_start", "duration", "trend")
    KEEP_NONE = ("from_deg", "to_deg", "t_start", "duration")

    @property
    def from_deg(self) -> float | None:
        """Where the stretch starts [deg]."""
        return _deg(self.phi_start)

    @property
    def to_deg(self) -> float | None:
        """Where it ends [deg]."""
        return _deg(self.phi_end)


def _deg(x: float | None) -> float | None:
    """Degrees, rounded to 1e-10° so that 247.49999999999997 reads 247.5; None for no angle."""
    return None if x is None or math.isnan(x) else round(math.degrees(x), 10) + 0.0


@dataclass(frozen=True)
class Task2Result:
    """Everything task 2 reports; SI units (angles in rad, speeds in rad/s, energies in J).

    cycle : length Φ of the cycle [rad]; J : reduced moment of inertia used for the motion
    [kg·m²]; omega0 : ω at φ = 0 [rad/s]; omega_max, omega_min : extreme speeds [rad/s];
    omega_mean : ω_ср = (ω_max + ω_min)/2 [rad/s]; delta : δ = (ω_max − ω_min)/ω_ср [1];
    phi_omega_max, phi_omega_min : their angles [rad] (None when an area diagram gives none);
    delta_T_max : ΔT_нб = A_max − A_min [J]; rows : the segment table; steady : ∮(M_D − M_C)dφ = 0;
    omega_end : ω after one cycle [rad/s]; work_end : A(Φ) [J] (0 for steady motion);
    M_D, M_C : nominal driving and resistance moments (constant, peak, a0) [N·m]; unknown : the
    moment the cycle balance found, "driving" | "resistance" | None; work_driving, work_resistance :
    ∮M_D dφ, ∮M_C dφ [J]; power : mean driving moment × ω_ср [W] (steady motion only);
    J_required : J giving delta_target at the same ω_ср [kg·m²]; delta_target : the asked δ [1];
    rim_radius : mean radius of a rim [m]; rim_mass : m = J/R² [kg]; driving, resistance : the
    graphs (None for an area diagram); epsilon_max, epsilon_min : the global extremes of
    ε(φ) = (M_D − M_C)/J over the cycle [rad/s²]; phi_epsilon_max, phi_epsilon_min : the first
    angles where they occur [rad]; cycle_time : the time of one cycle ∫₀^Φ dφ/ω [s]; at : the
    motion at the asked angles (:class:`AtPoint`); phases : the stretches of rising and falling
    speed (:class:`Phase`); (all of these None or empty for an area diagram); work_per_cycle :
    the work done per cycle, ∮M_D dφ or given [J]; energy_fluctuation_coefficient :
    C_E = ΔT_нб/work per cycle [1]; power_found : which graph's value the mean power gave,
    "driving" | "resistance" | None; radius_of_gyration : k [m] and flywheel_mass : m = J/k²
    [kg] when a radius of gyration was given without the mass.
    """

    cycle: float                 # Φ [rad]
    J: float                     # reduced moment of inertia used for the motion [kg·m²]
    omega0: float                # ω at φ = 0 [rad/s]
    omega_max: float             # [rad/s]
    omega_min: float             # [rad/s]
    omega_mean: float            # (ω_max + ω_min)/2 [rad/s]
    delta: float                 # (ω_max − ω_min)/ω_ср [1]
    phi_omega_max: float | None  # [rad]; None if the diagram gives no angles
    phi_omega_min: float | None  # [rad]
    delta_T_max: float           # ΔT_нб = A_max − A_min [J]
    rows: tuple[Row, ...]
    steady: bool = True
    omega_end: float = 0.0       # ω after one cycle [rad/s]
    work_end: float = 0.0        # A(Φ) [J]; 0 for steady motion
    M_D: float | None = None     # nominal driving moment (constant/peak/a0) [N·m]
    M_C: float | None = None     # nominal resistance moment (the seed's peak) [N·m]
    unknown: str | None = None   # which moment the balance found: "driving" | "resistance"
    work_driving: float | None = None     # ∮ M_D dφ [J]
    work_resistance: float | None = None  # ∮ M_C dφ [J]
    power: float | None = None   # mean driving moment × ω_ср [W]
    J_required: float | None = None       # J for delta_target at the same ω_ср [kg·m²]
    delta_target: float | None = None     # the asked δ [1]
    rim_radius: float | None = None       # mean radius of a rim [m]
    rim_mass: float | None = None         # m = J/R² [kg]
    driving: Moment | None = field(default=None, repr=False)
    resistance: Moment | None = field(default=None, repr=False)
    epsilon_max: float | None = None      # [rad/s²]
    epsilon_min: float | None = None      # [rad/s²]
    phi_epsilon_max: float | None = None  # [rad]
    phi_epsilon_min: float | None = None  # [rad]
    cycle_time: float | None = None       # ∫₀^Φ dφ/ω [s]
    at: tuple[AtPoint, ...] = ()
    phases: tuple[Phase, ...] = ()
    work_per_cycle: float | None = None   # [J]
    energy_fluctuation_coefficient: float | None = None   # ΔT_нб/work per cycle [1]
    power_found: str | None = None        # which graph's value the mean power gave
    radius_of_gyration: float | None = None   # k [m]
    flywheel_mass: float | None = None        # m = J/k² [kg]
    rim: object | None = None    # the designed rim (flywheel.dynamics.sizing.RimDesign) of J
    #                              (J_required when δ is asked) at ω_ср

    #: ``flywheel task2 --json``'s keys in order (io/serialize.py); a None entry is left
    #: out unless kept. Keys of the contract: omega_max, omega_min, omega_mean, delta,
    #: phi_omega_max_deg, phi_omega_min_deg, delta_T_max, M_C, J_required (only when asked),
    #: segments; epsilon_max, epsilon_min [rad/s²], phi_epsilon_max_deg, phi_epsilon_min_deg
    #: [deg], cycle_time [s], at [{phi_deg, omega, epsilon, t}].
    DOCUMENT = ("omega_max", "omega_min", "omega_mean", "delta",
                ("phi_omega_max_deg", "phi_omega_max_deg"), ("phi_omega_min_deg", "phi_omega_min_deg"),
                "delta_T_max", "M_C", "J_required", "M_D", ("balance_found", "unknown"), "J",
                "omega0", "steady", "omega_end", "work_end", ("cycle_deg", "cycle_deg"),
                ("rpm", "rpm"), "work_driving", "work_resistance", "power", "delta_target",
                ("rim_radius", "rim_radius_shown"), "rim_mass",
                ("radius_of_gyration", "radius_of_gyration_shown"), "flywheel_mass",
                ("flywheel_rim", "rim"), "epsilon_max", "epsilon_min",
                ("phi_epsilon_max_deg", "phi_epsilon_max_deg"),
                ("phi_epsilon_min_deg", "phi_epsilon_min_deg"), "cycle_time", "at", "phases",
                "work_per_cycle", "energy_fluctuation_coefficient", "power_found",
                ("segments", "rows"))
    KEEP_NONE = ("phi_omega_max_deg", "phi_omega_min_deg", "M_C", "M_D", "balance_found",
                 "work_driving", "work_resistance", "power", "epsilon_max", "epsilon_min",
                 "phi_epsilon_max_deg", "phi_epsilon_min_deg", "cycle_time", "work_per_cycle",
                 "energy_fluctuation_coefficient", "power_found")

    @property
    def phi_omega_max_deg(self) -> float | None:
        """φ of ω_max [deg] (None when the diagram gives no angle)."""
        return _deg(self.phi_omega_max)

    @property
    def phi_omega_min_deg(self) -> float | None:
        """φ of ω_min [deg]."""
        return _deg(self.phi_omega_min)

    @property
    def phi_epsilon_max_deg(self) -> float | None:
        """φ of ε_max [deg]."""
        return _deg(self.phi_epsilon_max)

    @property
    def phi_epsilon_min_deg(self) -> float | None:
        """φ of ε_min [deg]."""
        return _deg(self.phi_epsilon_min)

    @property
    def cycle_deg(self) -> float:
        """Φ [deg]."""
        return math.degrees(self.cycle)

    @property
    def rpm(self) -> dict[str, float]:
        """The speeds in rev/min: omega0, omega_max, omega_min, omega_mean."""
        return {"omega0": self.omega0 * RPM_PER_RAD_S, "omega_max": self.omega_max * RPM_PER_RAD_S,
                "omega_min": self.omega_min * RPM_PER_RAD_S,
                "omega_mean": self.omega_mean * RPM_PER_RAD_S}

    @property
    def rim_radius_shown(self) -> float | None:
        """The rim's mean radius [m], shown with the rim's mass only."""
        return self.rim_radius if self.rim_mass is not None else None

    @property
    def radius_of_gyration_shown(self) -> float | None:
        """k [m], shown with the flywheel's mass only."""
        return self.radius_of_gyration if self.flywheel_mass is not None else None

    def to_document(self, title: str = "", source: str = "") -> dict:
        """The results document, the JSON of ``flywheel task2 --json`` (SI units; angles in
        degrees where the key says ``_deg``; speeds in rev/min under ``rpm``): ``title`` and
        ``source`` when given, then :attr:`DOCUMENT` by the one serializer. An angle that is
        not known (an area diagram without crossing angles) is None; so are ε and the times of
        an area diagram."""
        from flywheel.io.serialize import to_json

        d: dict = {}
        if title:
            d["title"] = title
        if source:
            d["source"] = source
        d.update(to_json(self))
        return d


# -- ε(φ) and the time law ---------------------------------------------------------------------

def epsilon_extremes(pieces: Sequence[Piece], J: float) -> tuple[float, float, float, float]:
    """(ε_max, φ of ε_max, ε_min, φ of ε_min) of ε(φ) = (M_D − M_C)/J over the cycle
    [rad/s², rad]: the global extremes, exact, not sampled.

    For constant J the equation of motion J·ε = M_D − M_C (the kinetic-energy theorem
    ½·J·ω² = ∫(M_D − M_C) dφ differentiated: ω·dω/dφ = ε) makes ε proportional to the net
    moment. Its candidates are the ends of every piece, each from its own side (a jump of a graph
    has two values, both candidates), and the stationary points inside a harmonic piece
    (:func:`~flywheel.constant_inertia.crossings.stationary_points`); a linear piece is extreme
    at its ends. Of equal extremes (to 1e-12 of the swing) the first in φ is reported: a
    plateau's start. A textbook that sets d(M_D − M_C)/dφ = 0 and takes a root finds a *local*
    extreme: Khurmi & Gupta's Example 16.12 reports 3.46 rad/s² at 35° as the maximum, whereas
    the global maximum is 12.2 rad/s² at 232.4° (the mirror image of its minimum).
    """
    cands: list[tuple[float, float]] = []
    for p in pieces:
        cands.append((p.value(p.phi0), p.phi0))
        cands.extend((p.value(x), x) for x in stationary_points(p))
        cands.append((p.value(p.phi1), p.phi1))
    vals = [v for v, _ in cands]
    hi, lo = max(vals), min(vals)
    tol = 1e-12 * (hi - lo)
    m_max, x_max = next(c for c in cands if c[0] >= hi - tol)
    m_min, x_min = next(c for c in cands if c[0] <= lo + tol)
    return m_max / J, x_max, m_min / J, x_min


def time_linear(h: float, w0: float, w1: float, eps0: float, kappa: float, dw: float) -> float:
    """∫ dφ/ω [s] over h [rad] of a piece whose net moment is linear, so that
    ε = (M_D − M_C)/J is linear in φ with dε/dφ = κ [1/s²] and ω² is quadratic in φ; exact.

    w0, w1 : ω at the ends [rad/s]; eps0 : ε at the start [rad/s²]; dw = w1 − w0, computed by
    the caller as 2·ΔA/(J·(w0 + w1)) (no difference of two close speeds). The closed forms of
    ∫dφ/√(aφ² + bφ + c) (e.g. Gradshteyn & Ryzhik 2.261) written in ε and ω, each arranged
    without cancellation:

    * κ = 0 (ε constant, ω² linear): t = 2h/(ω0 + ω1);
    * κ > 0: ε² − κ·ω² is constant along the motion, d ln(√κ·ω + ε) = √κ·dt, so
      t = ln((√κ·ω1 + ε1)/(√κ·ω0 + ε0))/√κ (for ε0 < 0 the equal ratio
      (ε0 − √κ·ω0)/(ε1 − √κ·ω1), whose terms do not cancel), by log1p of the relative change;
    * κ < 0, λ = √(−κ): ε² + λ²·ω² is constant, and the angle ψ of the vector (ε, λ·ω) turns
      at dψ/dt = λ, so t = Δψ/λ, Δψ = atan2(u0 × u1, u0 · u1) with
      u0 × u1 = λ·(ε0·Δω − ω0·κ·h).

    >>> round(time_linear(2.0, 1.0, 3.0, 2.0, 0.0, 2.0), 12)     # ε = 2: ω² = 1 + 4φ, t = 1
    1.0
    """
    if h == 0.0:
        return 0.0
    de = kappa * h
    if kappa == 0.0:
        return 2.0 * h / (w0 + w1)
    if kappa > 0.0:
        r = math.sqrt(kappa)
        if eps0 >= 0.0:
            return math.log1p((r * dw + de) / (r * w0 + eps0)) / r
        return -math.log1p((de - r * dw) / (eps0 - r * w0)) / r
    lam = math.sqrt(-kappa)
    cross = lam * (eps0 * dw - w0 * de)
    dot = eps0 * (eps0 + de) + lam * lam * w0 * w1
    return math.atan2(cross, dot) / lam


def _span_time(p: Piece, x0: float, x1: float, w0: float, w1: float, J: float) -> float:
    """∫_{x0}^{x1} dφ/ω [s] inside piece p, ω(x0) = w0, ω(x1) = w1 [rad/s]: exact for a linear
    net moment (:func:`time_linear`), adaptive Gauss–Kronrod with relative tolerance TIME_RTOL
    where harmonics make ω² transcendental in φ (:func:`integrate`)."""
    sub = Piece(x0, x1, p.linear_at(x0), p.slope, p.harmonics)
    if not p.harmonics:
        dw = 2.0 * sub.work(x1) / (J * (w0 + w1))
        return time_linear(x1 - x0, w0, w1, sub.m0 / J, p.slope / J, dw)
    w0sq = w0 * w0

    def inv_omega(x: float) -> float:
        return 1.0 / math.sqrt(max(w0sq + 2.0 * sub.work(x) / J, 1e-300))

    if sub.arrays is None:
        return integrate(inv_omega, x0, x1)
    import numpy as np

    def inv_omegas(xs):
        return 1.0 / np.sqrt(np.maximum(w0sq + 2.0 * sub.works(xs) / J, 1e-300))

    return integrate(inv_omega, x0, x1, many=inv_omegas)


def _locate(bounds: Sequence[float], x: float) -> int:
    """Index i of the table interval [bounds[i], bounds[i+1]] holding x (the last one at the
    cycle's end)."""
    from bisect import bisect_right

    return min(max(bisect_right(bounds, x, 1, len(bounds) - 1) - 1, 0), max(len(bounds) - 2, 0))


def _time_law(pieces: Sequence[Piece], bounds: Sequence[float], owner: Sequence[int],
              omega: Sequence[float], J: float, at: Sequence[float]) -> tuple:
    """(t at every row [s], the AtPoints of ``at``, the phases): t(φ) = ∫₀^φ dφ/ω summed over
    the table's intervals, each inside one piece and free of sign changes of M_D − M_C."""
    t = [0.0]
    trend = []
    for i in range(len(bounds) - 1):
        p = pieces[owner[i]]
        t.append(t[-1] + _span_time(p, bounds[i], bounds[i + 1], omega[i], omega[i + 1], J))
        dA = Piece(bounds[i], bounds[i + 1], p.linear_at(bounds[i]), p.slope,
                   p.harmonics).work(bounds[i + 1])
        trend.append("up" if dA > 0.0 else "down" if dA < 0.0 else "steady")
    phases: list[Phase] = []
    start = 0
    for i in range(1, len(trend) + 1):
        if i == len(trend) or trend[i] != trend[start]:
            phases.append(Phase(bounds[start], bounds[i], t[start], t[i] - t[start],
                                trend[start]))
            start = i
    points = []
    for x in at:
        i = _locate(bounds, x)
        p = pieces[owner[i]]
        sub = Piece(bounds[i], bounds[i + 1], p.linear_at(bounds[i]), p.slope, p.harmonics)
        w = math.sqrt(max(omega[i] ** 2 + 2.0 * sub.work(x) / J, 0.0))
        points.append(AtPoint(x, w, p.value(x) / J,
                              t[i] + _span_time(p, bounds[i], x, omega[i], w, J)))
    return t, tuple(points), tuple(phases)


def check_angles(at: Sequence[float], cycle: float) -> list[float]:
    """The asked angles [rad], each within the cycle 0…Φ (a hair beyond its ends, round-off of
    a conversion from degrees, is its end); InputError naming the first outside."""
    out = []
    for x in at:
        if not math.isfinite(x) or x < -1e-12 * cycle or x > cycle * (1 + 1e-12):
            # library use only: no CLI input reaches this
            raise InputError(f"the angle {math.degrees(x):g}° lies outside the cycle "
                             f"0…{math.degrees(cycle):g}°")
        out.append(min(max(x, 0.0), cycle))
    return out


def power_value(make: Callable[[float], Moment], power: float, omega_mean: float,
                which: str) -> float:
    """The value x of a graph (constant, peak, scale, a0) that makes its mean moment over the
    cycle equal to P/ω_ср: T_mean = P/ω (Khurmi & Gupta, §16: "the mean torque ... = power /
    mean angular speed"), i.e. ∮M dφ = P·Φ/ω_ср. The work is affine in x, as in :func:`balance`.

    >>> from flywheel.constant_inertia.graphs import constant
    >>> power_value(lambda x: constant(x), 20000.0, 10 * math.pi, "driving") * math.pi
    2000.0
    """
    check_positive("the power", power, "W")
    check_positive("the mean speed", omega_mean, "rad/s")
    quantity = "M_D" if which == "driving" else "M_C"
    m0, m1 = make(0.0), make(1.0)
    w0 = _cycle_work(m0, "work_driving" if which == "driving" else "work_resistance")
    w1 = _cycle_work(m1, "work_driving" if which == "driving" else "work_resistance")
    if w1 == w0:
        raise InputError(Notice.of(
            "t2_power_no_change", "the {which} moment's value does not change its work: the mean "
            "power cannot find it", which=which))
    target = power * m0.cycle / omega_mean
    x = (target - w0) / (w1 - w0)
    x = float(round(x, 12)) if abs(x - round(x, 12)) < 1e-12 * max(1.0, abs(x)) else x
    x += 0.0
    if not math.isfinite(x):
        raise NotFiniteError(quantity, Notice.of(
            "nf_power_moment", "the mean power gives a {which} moment of {x} N·m", which=which,
            x=repr(x)))
    if x < 0.0:
        raise InputError(Notice.of(
            "t2_power_negative", "the mean power {power:.6g} W needs a negative {which} moment "
            "value ({x:.6g}): the graph's fixed part alone does more work than P·Φ/ω_m = "
            "{target:.6g} J", power=power, which=which, x=x, target=target))
    return x


def balance(make_D: Callable[[float], Moment], make_C: Callable[[float], Moment],
            unknown: str) -> float:
    """The unknown parameter x of one graph (a constant, a peak, a scale) from the cycle
    balance ∮ M_D dφ = ∮ M_C dφ (steady motion; seed 002: M_D·2π = M_C·π/2).

    The work of a graph is affine in x, so x = (W_other − W(0))/(W(1) − W(0)); x = 0 when
    W_other − W(0) is round-off (within 1e-9 of the graphs' ``size``). Raises InputError when
    no positive x balances the cycle.

    >>> from flywheel.constant_inertia.graphs import constant, triangle
    >>> balance(lambda x: constant(15.0), lambda x: triangle(x, math.pi/2, 3*math.pi/2),
    ...         "resistance")
    60.0
    """
    if unknown == "resistance":
        known, make = make_D(1.0), make_C
    elif unknown == "driving":
        known, make = make_C(1.0), make_D
    else:
        # library use only: no CLI input reaches this
        raise InputError(f"unknown moment must be 'driving' or 'resistance' (got {unknown!r})")
    mine, theirs = (("work_resistance", "work_driving") if unknown == "resistance"
                    else ("work_driving", "work_resistance"))
    other = _cycle_work(known, theirs)
    w0, w1 = _cycle_work(make(0.0), mine), _cycle_work(make(1.0), mine)
    if w1 == w0:
        raise InputError(Notice.of(
            "t2_balance_no_change", "the {which} moment's unknown value does not change its work: "
            "the cycle balance cannot find it", which=unknown))
    # a net work within round-off of zero (zero-mean harmonics leave 1e-13 J) balances with
    # x = 0; the same tolerance as the steadiness test of ``solve``
    if math.isfinite(other - w0) and \
            abs(other - w0) <= BALANCE_RTOL * (size(known) + size(make(0.0))):
        return 0.0
    x = (other - w0) / (w1 - w0)
    x = float(round(x, 12)) if abs(x - round(x, 12)) < 1e-12 * max(1.0, abs(x)) else x
    x += 0.0    # no −0.0
    if not math.isfinite(x):
        raise NotFiniteError("M_C" if unknown == "resistance" else "M_D",
                             Notice.of(
                                 "nf_balance_moment", "the cycle balance gives a {which} moment "
                                 "of {x} N·m", which=unknown, x=repr(x)))
    if x < 0.0:
        raise InputError(Notice.of(
            "t2_balance_negative", "the cycle balance needs a negative {which} moment ({x:.6g} "
            "N·m): the {other_graph} graph does {more_or_less} work than the {which} graph can "
            "{absorb_or_supply}", which=unknown, x=x,
            other_graph='resistance' if unknown == 'driving' else 'driving',
            more_or_less='more' if unknown == 'resistance' else 'less',
            absorb_or_supply='absorb' if unknown == 'resistance' else 'supply'))
    return x


def _speed_from_mean(A_max: float, A_min: float, J: float, omega_mean: float) -> float:
    """ω0² from the mean speed: ω_max + ω_min = 2ω_ср and ω_max² − ω_min² = 2ΔT/J give
    ω_max = ω_ср + ΔT/(2Jω_ср); then ω0² = ω_max² − 2A_max/J."""
    dT = A_max - A_min
    w_max = omega_mean + dT / (2 * J * omega_mean)
    w_min = omega_mean - dT / (2 * J * omega_mean)
    if w_min <= 0.0:
        raise InputError(Notice.of(
            "t2_J_too_small", "J = {J:.6g} kg·m² is too small for a mean speed of {omega:.6g} "
            "rad/s: the energy fluctuation {dT:.6g} J would stop the machine", J=J,
            omega=omega_mean, dT=dT))
    return w_max * w_max - 2 * A_max / J


def _check_delta(delta: float | None) -> None:
    """δ, when asked, within 0 < δ < 2 (ω_min = ω_ср·(1 − δ/2) > 0)."""
    if delta is not None and not (0.0 < delta < 2.0):
        raise InputError(Notice.of(
            "t2_delta_0_2", "δ must lie between 0 and 2 (got {delta:g})", delta=delta))


def check_positive(name: str, value: float | None, unit: str) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        # library use only: no CLI input reaches this
        raise InputError(f"{name} must be positive (got {value:g} {unit})")


def _stop_angle(pieces: list[Piece], A_start: list[float], J: float, w0sq: float) -> float:
    """First φ where ω² = ω0² + 2A/J reaches zero (A is monotonic between table rows)."""
    target = -0.5 * J * w0sq
    for p, a0 in zip(pieces, A_start):
        pts = [p.phi0, *crossings(p), p.phi1]
        for x0, x1 in zip(pts, pts[1:]):
            f0 = a0 + p.work(x0) - target
            f1 = a0 + p.work(x1) - target
            if f1 <= 0.0:
                if f0 <= 0.0:
                    return x0
                return bisect_root(lambda x: a0 + p.work(x) - target, x0, x1, f0)
    return pieces[-1].phi1


def _motion(bounds: list[float], kinds: list[str], A: list[float], J: float | None,
            omega0: float | None, omega_mean: float | None, steady: bool,
            delta: float | None, angles_known: bool = True,
            stop: Callable[[float, float], float] | None = None) -> dict:
    """ω at each row and the summary numbers (shared by graphs and area diagrams).

    Raises NotFiniteError when a work is not finite (moments near the limit of double
    precision): no extreme can be chosen among infinities.
    """
    bad = next((i for i, a in enumerate(A) if not math.isfinite(a)), None)
    if bad is not None:
        raise NotFiniteError(f"segments[{bad}].A", Notice.of(
            "nf_work", "the work A(φ) = {x} J", x=repr(A[bad])))
    # the first of equal extremes (equal to 1e-12 of the swing: round-off must not choose)
    A_max, A_min = max(A), min(A)
    tol = 1e-12 * (A_max - A_min)
    i_max = next(i for i, a in enumerate(A) if a >= A_max - tol)
    i_min = next(i for i, a in enumerate(A) if a <= A_min + tol)
    dT = A_max - A_min
    if J is None:
        if delta is None:
            # library use only: no CLI input reaches this
            raise InputError("give the flywheel: J, or mass and radius of gyration, or δ")
        if omega_mean is None:
            raise InputError(Notice.of(
                "t2_delta_needs_mean", "to find J from δ give the mean speed, not ω0"))
        if dT <= 0.0:
            raise InputError(Notice.of(
                "t2_no_fluctuation", "the energy does not fluctuate: any J gives δ = 0"))
        J = _J_for(dT, omega_mean, delta)
    if omega_mean is not None:
        if not steady:
            raise InputError(Notice.of(
                "t2_mean_needs_steady", "a mean speed needs steady motion (the work over the cycle "
                "is {work:.6g} J, not 0): give ω0 instead", work=A[-1]))
        w0sq = _speed_from_mean(A_max, A_min, J, omega_mean)
    else:
        w0sq = omega0 * omega0
    wsq = [w0sq + 2 * a / J for a in A]
    if min(wsq) <= 0.0:
        i = next(i for i, w in enumerate(wsq) if w <= 0.0)
        if stop is not None:
            phi_stop = math.degrees(stop(J, w0sq))
            where = f"at φ = {phi_stop:.6g}°"
        else:
            where = f"before row {i}"
        raise InputError(Notice.of(
            "machine_stops", "the machine stops {where}: the kinetic energy ½·J·ω0² = {T0:.6g} J "
            "cannot cover the deficit {deficit:.6g} J",
            where_ru=(f"при φ = {phi_stop:.6g}°" if stop is not None else f"до строки {i}"),
            T0=0.5 * J * w0sq, deficit=-min(A), where=where))
    omega = [math.sqrt(w) for w in wsq]
    w_max, w_min = omega[i_max], omega[i_min]
    if omega_mean is not None:       # exact, free of round-off in the square roots
        w_mean = omega_mean
        diff = dT / (J * omega_mean)
    else:
        w_mean = 0.5 * (w_max + w_min)
        diff = 2 * dT / (J * (w_max + w_min))
    out = dict(J=J, omega0=math.sqrt(w0sq), omega_max=w_max, omega_min=w_min,
               omega_mean=w_mean, delta=diff / w_mean,
               phi_omega_max=bounds[i_max] if angles_known else None,
               phi_omega_min=bounds[i_min] if angles_known else None,
               delta_T_max=dT, omega_end=omega[-1], omega=omega, steady=steady,
               work_end=A[-1])
    return out


def _finish(res: dict, delta: float | None, rim_radius: float | None,
            radius_of_gyration: float | None = None, work_per_cycle: float | None = None,
            rim: dict | None = None) -> dict:
    if delta is not None:
        res["delta_target"] = delta
        res["J_required"] = _J_for(res["delta_T_max"], res["omega_mean"], delta)
    if rim_radius is not None:
        J_rim = res.get("J_required") or res["J"]
        res["rim_radius"] = rim_radius
        res["rim_mass"] = J_rim / rim_radius ** 2
    if radius_of_gyration is not None:     # m = J/k² (Khurmi & Gupta §16: I = m·k²)
        res["radius_of_gyration"] = radius_of_gyration
        res["flywheel_mass"] = (res.get("J_required") or res["J"]) / radius_of_gyration ** 2
    if work_per_cycle is not None and work_per_cycle > 0.0:
        # C_E = ΔE / work done per cycle (Khurmi & Gupta §16.4)
        res["work_per_cycle"] = work_per_cycle
        res["energy_fluctuation_coefficient"] = res["delta_T_max"] / work_per_cycle
    if rim is not None:     # the rim as engineers finish it (Khurmi & Gupta ch. 16)
        from dataclasses import replace

        from flywheel.dynamics.sizing import design_rim
        d = design_rim(res.get("J_required") or res["J"], res["omega_mean"], **rim)
        res["rim"] = replace(d, stress_at_omega_max=d.density * (
            d.rim_speed * res["omega_max"] / res["omega_mean"]) ** 2)
    return res


def solve(M_D: Moment, M_C: Moment, J: float | None = None, *, omega0: float | None = None,
          omega_mean: float | None = None, delta: float | None = None,
          rim_radius: float | None = None, unknown: str | None = None,
          at: Sequence[float] = (), radius_of_gyration: float | None = None,
          power_found: str | None = None, rim: dict | None = None) -> Task2Result:
    """Steady (or not) motion under M_D(φ), M_C(φ) with constant J.

    Parameters: ``M_D``, ``M_C`` graphs [N·m over rad]; ``J`` [kg·m²] (None: found from
    ``delta`` at ``omega_mean``); exactly one of ``omega0`` (ω at φ = 0) or ``omega_mean``
    (ω_ср, steady motion only) [rad/s]; ``delta`` asks for the J giving that δ at the same
    ω_ср; ``rim_radius`` [m] asks for the rim mass m = J/R²; ``at`` [rad]: angles where ω, ε
    and t are reported; ``radius_of_gyration`` [m] asks for the mass m = J/k²; ``unknown``,
    ``power_found``: which graph's value the balance or the mean power found (for the record);
    ``rim``: the keyword arguments of :func:`flywheel.dynamics.sizing.design_rim` (density,
    allowable_stress, share, speed, width_to_thickness, width) to design the rim of the J.

    Besides ω: ε(φ) = (M_D − M_C)/J and its global extremes (:func:`epsilon_extremes`), and
    the time law t(φ) = ∫₀^φ dφ/ω (:func:`time_linear`, :func:`integrate`): the cycle time, the
    time at every row, the phases of rising and falling speed.

    The motion is steady when ∮ (M_D − M_C) dφ = 0 (to 1e-9 of ∮(|M_D| + |M_C|) dφ, see
    ``size``); otherwise ω_end after one cycle differs from ω0.

    >>> from flywheel.constant_inertia.graphs import constant, triangle
    >>> r = solve(constant(15.0), triangle(60.0, math.pi/2, 3*math.pi/2), 12.0, omega0=200.0)
    >>> [round(math.degrees(x.phi), 6) for x in r.rows]
    [0.0, 90.0, 112.5, 180.0, 247.5, 270.0, 360.0]
    >>> round(r.omega_max, 6), round(r.omega_min, 6), f"{r.delta:.6g}"
    (200.011044, 199.988955, '0.000110447')
    """
    if (omega0 is None) == (omega_mean is None):
        # library use only: no CLI input reaches this
        raise InputError("give exactly one speed: ω0 or the mean speed")
    check_positive("J", J, "kg·m²")
    check_positive("ω0", omega0, "rad/s")
    check_positive("the mean speed", omega_mean, "rad/s")
    check_positive("the rim radius", rim_radius, "m")
    check_positive("the radius of gyration", radius_of_gyration, "m")
    _check_delta(delta)
    at = check_angles(at, M_D.cycle)
    pieces = net_pieces(M_D, M_C)
    bounds: list[float] = []
    kinds: list[str] = []
    owner: list[int] = []
    A: list[float] = []
    A_start: list[float] = []
    acc = 0.0
    for j, p in enumerate(pieces):
        A_start.append(acc)
        bounds.append(p.phi0)
        kinds.append("bound")
        owner.append(j)
        A.append(acc)
        for x in crossings(p):
            bounds.append(x)
            kinds.append("crossing")
            owner.append(j)
            A.append(acc + p.work(x))
        acc += p.work(p.phi1)
    bounds.append(pieces[-1].phi1)
    kinds.append("bound")
    owner.append(len(pieces) - 1)
    W_D, W_C = _cycle_work(M_D, "work_driving"), _cycle_work(M_C, "work_resistance")
    # relative to the size of the moments (``size``), not to W_D, W_C: zero-mean moments
    # have works of pure round-off and are steady all the same
    size_D, size_C = size(M_D), size(M_C)
    if not math.isfinite(size_D + size_C) and any(p.harmonics for p in pieces):
        # 1e308·sin 2φ: no crossing can be certified and A stays 0, so "the energy does not
        # fluctuate" would be said (issue 23); linear pieces overflow A itself (_motion)
        raise NotFiniteError("work_driving" if not math.isfinite(size_D) else "work_resistance",
                             Notice.of("nf_moment_size", "the moment's size ∮|M| dφ overflows"))
    scale = max(abs(W_D), abs(W_C), size_D + size_C, 1e-300)
    steady = abs(acc) <= BALANCE_RTOL * scale
    if steady:
        acc = 0.0
    A.append(acc)
    res = _motion(bounds, kinds, A, J, omega0, omega_mean, steady, delta,
                  stop=lambda J_, w0sq: _stop_angle(pieces, A_start, J_, w0sq))
    omega = res.pop("omega")
    times, points, phases = _time_law(pieces, bounds, owner, omega, res["J"], at)
    rows = tuple(Row(x, k, M_D.value(x, +1 if i < len(bounds) - 1 else -1),
                     M_C.value(x, +1 if i < len(bounds) - 1 else -1), a, w, t)
                 for i, (x, k, a, w, t) in enumerate(zip(bounds, kinds, A, omega, times)))
    e_max, x_max, e_min, x_min = epsilon_extremes(pieces, res["J"])
    res = _finish(res, delta, rim_radius, radius_of_gyration, W_D if steady else None, rim)
    power = (W_D / M_D.cycle) * res["omega_mean"] if steady else None
    return Task2Result(rows=rows, cycle=M_D.cycle, M_D=M_D.nominal, M_C=M_C.nominal,
                       unknown=unknown, work_driving=W_D, work_resistance=W_C, power=power,
                       driving=M_D, resistance=M_C, epsilon_max=e_max, epsilon_min=e_min,
                       phi_epsilon_max=x_max, phi_epsilon_min=x_min, cycle_time=times[-1],
                       at=points, phases=phases, power_found=power_found, **res)


def solve_areas(energies: Sequence[float], J: float | None = None, *, cycle: float = TWO_PI,
                omega0: float | None = None, omega_mean: float | None = None,
                delta: float | None = None, rim_radius: float | None = None,
                crossings_at: Sequence[float] | None = None, at: Sequence[float] = (),
                radius_of_gyration: float | None = None,
                work_per_cycle: float | None = None, rim: dict | None = None) -> Task2Result:
    """A turning-moment diagram given by the signed areas between its crossings with the mean
    line (Khurmi & Gupta, §16.5): ``energies`` [J] in order, positive above the mean line.

    The energy at the n-th crossing is the running sum; ΔT_нб = max − min of the running sums
    (with the start). The areas of a cycle sum to zero. ``crossings_at`` [rad], n + 1 angles
    from the start of the first area to the end of the last, label the rows; without them
    the angles of ω_max and ω_min are unknown (None). A maximum fluctuation of energy ΔE given
    directly is the diagram [ΔE, −ΔE]. The areas say nothing of the moments between the
    crossings, so ε(φ) and the time law are unknown: ``at`` must be empty.
    ``work_per_cycle`` [J] gives C_E = ΔT_нб/W; ``radius_of_gyration`` [m] the mass J/k²;
    ``rim`` designs the rim (as in :func:`solve`).

    >>> r = solve_areas([295.0, -685.0, 40.0, -340.0, 960.0, -270.0], J=1.0, omega_mean=100.0)
    >>> r.delta_T_max
    985.0
    """
    check_positive("J", J, "kg·m²")
    check_positive("ω0", omega0, "rad/s")
    check_positive("the mean speed", omega_mean, "rad/s")
    if (omega0 is None) == (omega_mean is None):
        # library use only: no CLI input reaches this
        raise InputError("give exactly one speed: ω0 or the mean speed")
    _check_delta(delta)
    check_positive("the radius of gyration", radius_of_gyration, "m")
    if len(at):
        # library use only: no CLI input reaches this
        raise InputError("a diagram given by areas has no moments between its crossings: "
                         "ε(φ), ω(φ) and t(φ) at an angle are unknown (give the graphs)")
    e = [float(x) for x in energies]
    if len(e) < 2:
        # library use only: no CLI input reaches this
        raise InputError("a diagram needs at least two areas")
    total, size = math.fsum(e), math.fsum(abs(x) for x in e)
    if abs(total) > BALANCE_RTOL * size:
        raise InputError(Notice.of(
            "t2_areas_sum", "the areas sum to {total:.6g}, not 0: over a cycle of steady motion "
            "the areas above and below the mean line are equal", total=total))
    A = [0.0]
    for x in e[:-1]:
        A.append(A[-1] + x)
    A.append(0.0)
    if crossings_at is not None:
        bounds = [float(x) for x in crossings_at]
        if len(bounds) != len(e) + 1:
            # library use only: no CLI input reaches this
            raise InputError(f"{len(e)} areas need {len(e) + 1} crossing angles "
                             f"(got {len(bounds)})")
        if any(b1 <= b0 for b0, b1 in zip(bounds, bounds[1:])):
            raise InputError(Notice.of("t2_crossings_increase", "crossing angles must increase"))
    else:
        bounds = [cycle * i / len(e) for i in range(len(e) + 1)]
    res = _motion(bounds, ["crossing"] * len(A), A, J, omega0, omega_mean, True, delta,
                  angles_known=crossings_at is not None)
    omega = res.pop("omega")
    rows = tuple(Row(x if crossings_at is not None else math.nan, "crossing", None, None, a, w)
                 for x, a, w in zip(bounds, A, omega))
    res = _finish(res, delta, rim_radius, radius_of_gyration, work_per_cycle, rim)
    return Task2Result(rows=rows, cycle=cycle, **res)


def sample(result: Task2Result, n: int = 1441) -> dict[str, list[float]]:
    """Curves for plotting: φ [rad], M_D, M_C [N·m], A [J], ω [rad/s], ε = (M_D − M_C)/J
    [rad/s²] on n + the table's points (+ the angles of ε's extremes).

    Only for results from graphs (``solve``); an area diagram has no curves between rows.
    """
    if result.driving is None or result.resistance is None:
        # library use only: no CLI input reaches this
        raise InputError("a diagram given by areas has no moment curves to sample")
    pieces = net_pieces(result.driving, result.resistance)
    xs = sorted({result.cycle * i / (n - 1) for i in range(n)} | {r.phi for r in result.rows}
                | {x for x in (result.phi_epsilon_max, result.phi_epsilon_min) if x is not None})
    A_start, acc = [], 0.0
    for p in pieces:
        A_start.append(acc)
        acc += p.work(p.phi1)
    out: dict[str, list[float]] = {"phi": [], "M_D": [], "M_C": [], "A": [], "omega": [],
                                   "epsilon": []}
    j = 0
    w0sq = result.omega0 ** 2
    for x in xs:
        while j < len(pieces) - 1 and x >= pieces[j].phi1:
            j += 1
        a = A_start[j] + pieces[j].work(x)
        out["phi"].append(x)
        md, mc = result.driving.value(x), result.resistance.value(x)
        out["M_D"].append(md)
        out["M_C"].append(mc)
        out["epsilon"].append((md - mc) / result.J)
        out["A"].append(a)
        out["omega"].append(math.sqrt(max(w0sq + 2 * a / result.J, 0.0)))
    return out



__all__ = ["BALANCE_RTOL", "TIME_RTOL", "NotFiniteError", "Row", "AtPoint", "Phase",
           "Task2Result", "balance", "power_value", "solve", "solve_areas", "sample",
           "check_positive", "check_angles", "epsilon_extremes", "time_linear", "integrate"]
