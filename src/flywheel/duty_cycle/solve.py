"""Duty-cycle machines in time: a press (punching, shearing, riveting, stamping) whose flywheel
gives the energy of each operation and whose motor restores it before the next one.

The model (Khurmi & Gupta, *Theory of Machines*, ch. 16 "Turning Moment Diagrams and Flywheel",
the section "Flywheel in Punching Press", Ex. 16.19–16.23; Артоболевский, «Теория механизмов
и машин», on the coefficient of unevenness δ of machines with a periodic load):

- one operation takes the work ``E`` [J] in the time ``t_op`` [s] (the crank angle
  ``Δφ_op`` [rad]) of each cycle of ``T_c`` [s]; the rest of the cycle the machine runs idle;
- the motor gives the constant torque ``M_Д`` [N·m] (power ``P = M_Д·ω_ср`` [W]) while the
  flywheel is below its top speed ``ω_max``; at ``ω_max`` it idles (its torque falls to what
  keeps that speed: the no-load friction, taken as zero);
- during the operation the resisting moment on the flywheel shaft is taken constant,
  ``M_op = E/Δφ_op`` [N·m]: how the force varies over the travel sets ``E`` (see
  :mod:`flywheel.duty_cycle.work`) but not the end speed, which depends on energies only.

Then the speed falls linearly in time from ``ω_max`` to ``ω_min`` during the operation
(``ε = (M_Д − M_op)/J``) and rises linearly back (``ε = M_Д/J``) while the motor recovers it,
so the time mean of ω over both is exactly ``ω_ср = (ω_max + ω_min)/2`` and the program turns
time into angle and back exactly: ``Δφ = ω_ср·t``. The energy balances are then exact:

- operation: ``ΔE = E − M_Д·Δφ_op = E − P·t_op`` — the energy the flywheel gives, the
  textbook's ``ΔE = E₁ − E₂`` with ``E₂ = P·t`` the motor's share (Ex. 16.19–16.22);
- flywheel: ``ΔE = ½·J·(ω_max² − ω_min²) = J·ω_ср²·δ``, ``δ = (ω_max − ω_min)/ω_ср``
  (Khurmi & Gupta, "Energy Stored in a Flywheel": ``ΔE = I·ω²·C_s``, exact with
  ``ω = ω_ср``); with the mass at the radius of gyration ``k``: ``J = m·k²``, and for a rim
  ``ΔE = m·v²·δ`` with the rim speed ``v = ω_ср·k`` (the same section: ``ΔE = m·v²·C_s``);
- recovery: ``M_Д·Δφ_rec = ΔE``, ``t_rec = ΔE/P = J·(ω_max − ω_min)/M_Д``;
- the cycle: ``P·(t_op + t_rec) = E`` (the motor works for ``E/P`` of each cycle) and
  ``t_op + t_rec + t_idle = T_c``; the mean power of the operations is ``E/T_c`` (Ex. 16.19:
  "energy required per second").

The cycle is set in time (operations per hour or per minute, or the period) or, for a machine
that makes one operation every ``k`` revolutions of the flywheel shaft, in angle:
``θ_c = 2π·k``; then the motor (if not given) is found from ``M_Д·2π·k = E`` and
``T_c = 2π·k/ω_ср``. Without a cycle the motor sets the largest rate: ``T_c = E/P``
(Ex. 16.21: "how many rivets can be closed per minute": ``60·P/E``).

Pure functions on plain floats (``math`` only).
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from flywheel.errors import InputError, Notice
from flywheel.units import RPM_PER_RAD_S, TWO_PI

_TOL = 1e-12                   # relative slack of the "motor strong enough" and "op fits" tests


class DutyCycleError(InputError):
    """A problem that cannot be solved as given: ``field`` is the case-file path to blame."""

    def __init__(self, field: str, message: str):
        super().__init__(message)
        self.field = field


@dataclass(frozen=True)
class Work:
    """How the work of one operation was found (the inputs the case gave, SI).

    ``energy`` [J]; ``sheared_area`` [m²]; ``energy_per_area`` [J/m²]; ``force_max`` [N];
    ``thickness`` [m] (the travel); ``shape`` of the force over the travel."""

    energy: float
    sheared_area: float | None = None
    energy_per_area: float | None = None
    force_max: float | None = None
    thickness: float | None = None
    shape: str | None = None

    #: its document's keys (``work`` of the duty-cycle JSON; every None written as null)
    DOCUMENT = ("sheared_area", "energy_per_area", "force_max", "thickness", "shape")
    KEEP_NONE = DOCUMENT


@dataclass(frozen=True)
class DutyCycle:
    """A duty-cycle problem, SI. Exactly one way to time the operation (``duration`` [s],
    ``cycle_share`` of the cycle time, ``angle`` [rad] of the flywheel shaft, or ``delta_E``
    [J] given); at most one cycle (``period`` [s] or ``revolutions`` per operation); at most
    one motor (``motor_power`` [W] or ``motor_torque`` [N·m]); ``efficiency`` of the motor.

    Speeds [rad/s] (or [m/s] at the flywheel's radius when ``linear_speeds``: the radius is
    not known, so J, ω and angles are not either): two of ``speed_max``, ``speed_min``,
    ``speed_mean``, ``delta`` to size the flywheel; or the flywheel (``J``, or ``mass`` with
    ``radius`` [m], or ``mass`` alone with linear speeds) and one speed, to find the others.
    """

    work: Work | None = None
    duration: float | None = None
    cycle_share: float | None = None
    angle: float | None = None
    delta_E: float | None = None
    period: float | None = None
    revolutions: float | None = None
    motor_power: float | None = None
    motor_torque: float | None = None
    efficiency: float = 1.0
    speed_max: float | None = None
    speed_min: float | None = None
    speed_mean: float | None = None
    delta: float | None = None
    J: float | None = None
    mass: float | None = None
    radius: float | None = None
    linear_speeds: bool = False
    # the case-file fields to blame for an impossible problem
    fields: tuple[tuple[str, str], ...] = ()

    def field(self, what: str, default: str) -> str:
        return dict(self.fields).get(what, default)

    @property
    def energy(self) -> float | None:
        return None if self.work is None else self.work.energy

    @property
    def flywheel_given(self) -> bool:
        return self.J is not None or self.mass is not None


@dataclass(frozen=True)
class DutyCycleResult:
    """The duty cycle solved (SI; None where the case gives too little to know it).

    Energies [J]: ``energy`` E of one operation, ``delta_E`` ΔE the flywheel gives per
    operation; ``energy_fluctuation_coefficient`` C_E = ΔE/E [-].
    Motor: ``motor_power`` P [W] while it works, ``motor_input_power`` P/η [W],
    ``motor_torque`` M_Д = P/ω_ср [N·m]; ``mean_power`` E/T_c [W].
    Speeds of the flywheel shaft [rad/s]: ``omega_max`` (at the start of the operation),
    ``omega_min`` (at its end), ``omega_mean`` = (ω_max + ω_min)/2; ``rim_speed_*`` [m/s] at the
    radius ``radius`` [m]; ``delta`` δ [-]. Flywheel: ``J`` [kg·m²], ``mass`` [kg].
    Timing [s] and angles of the flywheel shaft [rad]: ``operation_*``, ``recovery_*`` (back to
    ω_max with the motor's torque), ``idle_*`` (at ω_max, the motor idle), ``cycle_*``;
    ``operation_share`` = t_op/T_c; ``operation_moment`` M_op = E/Δφ_op [N·m];
    ``revolutions_per_operation`` [-]; ``operations_per_hour`` [1/h].
    ``checks``: (name, residual [J or s]) of the identities; ``warnings``: what to know;
    ``rim``: the rim designed for J at ω_ср (``[flywheel.rim]``, set by the case's adapter:
    :func:`flywheel.cases.duty_cycle.solve_case`), or None."""

    work: Work | None
    energy: float | None
    delta_E: float
    energy_fluctuation_coefficient: float | None
    motor_power: float | None
    motor_input_power: float | None
    motor_torque: float | None
    mean_power: float | None
    efficiency: float
    omega_max: float | None
    omega_min: float | None
    omega_mean: float | None
    rim_speed_max: float | None
    rim_speed_min: float | None
    rim_speed_mean: float | None
    delta: float
    J: float | None
    mass: float | None
    radius: float | None
    operation_time: float | None
    operation_angle: float | None
    operation_share: float | None
    operation_moment: float | None
    recovery_time: float | None
    recovery_angle: float | None
    idle_time: float | None
    idle_angle: float | None
    cycle_time: float | None
    cycle_angle: float | None
    revolutions_per_operation: float | None
    operations_per_hour: float | None
    flywheel_given: bool
    checks: tuple[tuple[str, float], ...]
    warnings: tuple[str, ...]
    rim: object | None = None     # [flywheel.rim]: the designed rim (dynamics.sizing.RimDesign)
    #: a given flywheel's given speed, "max", "mean" or "min" (the others found from it by
    #: ½·J·(ω_max² − ω_min²) = ΔE); None for a flywheel found from its speeds
    speed_given: str | None = None

    #: the JSON document's keys in order (io/serialize.py; every None is written as null):
    #: docs/duty-cycle.md "Results"
    DOCUMENT = ("energy", "delta_E", "energy_fluctuation_coefficient", "motor_power",
                "motor_input_power", "motor_torque", "mean_power", "efficiency", "omega_max",
                "omega_min", "omega_mean", "rpm_max", "rpm_min", "rpm_mean", "rim_speed_max",
                "rim_speed_min", "rim_speed_mean", "delta", "J", "mass", "radius",
                "operation_time", "operation_angle_deg", "operation_share", "operation_moment",
                "recovery_time", "recovery_angle_deg", "idle_time", "idle_angle_deg",
                "cycle_time", "cycle_angle_deg", "revolutions_per_operation",
                "operations_per_hour", "operations_per_minute", "flywheel_given", "work",
                ("checks", "checks_by_name"), "warnings")
    KEEP_NONE = DOCUMENT
    #: the designed rim, [flywheel.rim] (run's results.flywheel_rim), left out without one
    DOCUMENT = DOCUMENT + (("flywheel_rim", "rim"),)

    @property
    def rpm_max(self) -> float | None:
        """ω_max [rev/min]."""
        return _rpm(self.omega_max)

    @property
    def rpm_min(self) -> float | None:
        """ω_min [rev/min]."""
        return _rpm(self.omega_min)

    @property
    def rpm_mean(self) -> float | None:
        """ω_ср [rev/min]."""
        return _rpm(self.omega_mean)

    @property
    def operation_angle_deg(self) -> float | None:
        """The operation's angle of the flywheel shaft [deg]."""
        return _deg(self.operation_angle)

    @property
    def recovery_angle_deg(self) -> float | None:
        """The recovery's angle [deg]."""
        return _deg(self.recovery_angle)

    @property
    def idle_angle_deg(self) -> float | None:
        """The idle run's angle [deg]."""
        return _deg(self.idle_angle)

    @property
    def cycle_angle_deg(self) -> float | None:
        """The cycle's angle [deg]."""
        return _deg(self.cycle_angle)

    @property
    def operations_per_minute(self) -> float | None:
        """Operations per minute [1/min]."""
        return None if self.operations_per_hour is None else self.operations_per_hour / 60.0

    @property
    def checks_by_name(self) -> dict[str, float]:
        """The identities' residuals by name [J or s]."""
        return {name: value for name, value in self.checks}

    def to_document(self) -> dict:
        """The JSON document (SI; angles in degrees where the key ends ``_deg``; speeds also in
        rev/min where it ends ``_rpm``), by the one serializer. Keys: see docs/duty-cycle.md
        "Results"."""
        from flywheel.io.serialize import to_json

        return to_json(self)


def _deg(x: float | None) -> float | None:
    """Radians → degrees; None stays None."""
    return None if x is None else math.degrees(x)


def _rpm(x: float | None) -> float | None:
    """rad/s → rev/min; None stays None."""
    return None if x is None else x * RPM_PER_RAD_S


# -- the cycle for given speeds -----------------------------------------------------------------

@dataclass(frozen=True)
class _Timeline:
    """Everything that follows from the speeds ω_max, ω_min (see the module's model)."""

    w1: float
    w2: float
    wm: float
    P: float | None
    T: float | None
    dE: float
    t_op: float | None
    t_rec: float | None
    t_idle: float | None
    Tc: float | None


def _timeline(d: DutyCycle, w1: float, w2: float) -> _Timeline:
    """The motor, the cycle and the operation's timing with the flywheel shaft between ``w1``
    (ω_max) and ``w2`` (ω_min); never raises (the checks come after the solution)."""
    wm = 0.5 * (w1 + w2)
    E = d.energy
    if E is None:                     # ΔE given alone: no motor, no cycle
        return _Timeline(w1, w2, wm, None, None, d.delta_E, None, None, None, None)
    if d.motor_power is not None:
        P = d.motor_power
        T = P / wm
    elif d.motor_torque is not None:
        T = d.motor_torque
        P = T * wm
    elif d.period is not None:        # the motor found: the mean power of the operations
        P = E / d.period
        T = P / wm
    else:                             # one operation every k revolutions: M_Д·2πk = E
        T = E / (TWO_PI * d.revolutions)
        P = T * wm
    t_active = E / P                  # the motor works E/P of each cycle
    if d.period is not None:
        Tc = d.period
        t_idle = Tc - t_active
    elif d.revolutions is not None:   # the rest of the k revolutions at ω_max
        t_idle = (TWO_PI * d.revolutions - E / T) / w1
        Tc = t_active + t_idle
    else:                             # no cycle: the motor sets the largest rate
        Tc, t_idle = t_active, 0.0
    if d.delta_E is not None:
        dE = d.delta_E
        t_op = (E - dE) / P
    else:
        if d.duration is not None:
            t_op = d.duration
        elif d.cycle_share is not None:
            t_op = d.cycle_share * Tc
        else:
            t_op = d.angle / wm
        dE = max(0.0, E - P * t_op)
    return _Timeline(w1, w2, wm, P, T, dE, t_op, dE / P, t_idle, Tc)


def _bisect(f, lo: float, hi: float) -> float:
    """The root of ``f`` on ``[lo, hi]`` (f(lo) ≤ 0 ≤ f(hi)) to the last bit."""
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if mid <= lo or mid >= hi:
            break
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    return lo if abs(f(lo)) <= abs(f(hi)) else hi


def _speeds_from_flywheel(d: DutyCycle, J: float) -> _Timeline:
    """The speeds when the flywheel is given with one speed: the drop ``x = ω_max − ω_min``
    solves ``½·J·(ω_max² − ω_min²) = ΔE`` (ΔE may depend on the speeds through
    ``P = M_Д·ω_ср`` or ``t_op = Δφ_op/ω_ср``), by bisection to the last bit."""
    if d.speed_max is not None:
        w = d.speed_max
        pair = (lambda x: (w, w - x))
        top = w
    elif d.speed_mean is not None:
        w = d.speed_mean
        pair = (lambda x: (w + 0.5 * x, w - 0.5 * x))
        top = 2.0 * w
    else:
        w = d.speed_min
        pair = (lambda x: (w + x, w))
        top = None

    def f(x: float) -> float:
        w1, w2 = pair(x)
        return 0.5 * J * (w1 - w2) * (w1 + w2) - _timeline(d, w1, w2).dE

    if f(0.0) >= 0.0:                 # ΔE = 0: the speed does not drop
        return _timeline(d, *pair(0.0))
    if top is None:                   # from ω_min up: grow the bracket
        top = max(w, 1.0)
        for _ in range(2000):
            if f(top) > 0:
                break
            top *= 2.0
    if not f(top) > 0:
        w1 = pair(top)[0]
        need = _timeline(d, w1, 0.0).dE
        what = "½·m·v²" if d.linear_speeds else "½·J·ω²"
        raise DutyCycleError(d.field("flywheel", "flywheel"),
                             Notice.of(
                                 "duty_flywheel_small", "the flywheel is too small: to give the "
                                 "{need:.6g} J (ΔE) of each operation its speed would fall to zero "
                                 "({energy} = {top:.6g} J at most); give a larger flywheel",
                                 need=need, energy=what, top=0.5 * J * w1 ** 2))
    x = _bisect(f, 0.0, top)
    return _timeline(d, *pair(x))


def solve(d: DutyCycle) -> DutyCycleResult:
    """Solve a duty cycle (see the module's model). Raises :class:`DutyCycleError` naming the
    field for a motor weaker than the operations need, an operation longer than the cycle, or a
    flywheel that would stop.

    Khurmi & Gupta, *Theory of Machines*, Ex. 16.19: 720 holes an hour, 15 kN·m and 2 s each,
    225 → 200 rpm, k = 0.5 m (the book: P = 3 kW, m = 618 kg):

    >>> from flywheel.units import RAD_S_PER_RPM as rpm
    >>> r = solve(DutyCycle(work=Work(15e3), duration=2.0, period=3600 / 720,
    ...                     speed_max=225 * rpm, speed_min=200 * rpm, radius=0.5))
    >>> round(r.motor_power, 9), round(r.delta_E, 6), round(r.mass, 3)
    (3000.0, 9000.0, 617.94)
    """
    if d.linear_speeds and (d.angle is not None or d.revolutions is not None
                            or d.motor_torque is not None):
        # library use only: no CLI input reaches this
        raise DutyCycleError(d.field("speed", "speed"),
                             "speeds given at the radius (m/s) without the radius: an angle, "
                             "revolutions or a motor torque need the shaft's speed (give the "
                             "flywheel's radius, or the speeds in rpm)")
    if d.flywheel_given:
        J = d.J if d.J is not None else d.mass * (1.0 if d.linear_speeds else d.radius ** 2)
        tl = _speeds_from_flywheel(d, J)
    else:
        w1, w2 = _speed_pair(d)
        if not w1 > w2 > 0:
            raise DutyCycleError(d.field("speed", "flywheel"), Notice.of(
                "dc_no_drop", "the speed limits {w1:.17g} and {w2:.17g} leave no drop (allowed: "
                "ω_max > ω_min > 0)", w1=w1, w2=w2))
        tl = _timeline(d, w1, w2)
        J = 2.0 * tl.dE / ((w1 - w2) * (w1 + w2))
    _check_timeline(d, tl)
    return _result(d, tl, J)


def _speed_pair(d: DutyCycle) -> tuple[float, float]:
    from flywheel.duty_cycle.work import speed_limits

    return speed_limits(d.speed_max, d.speed_min, d.speed_mean, d.delta)


def _check_timeline(d: DutyCycle, tl: _Timeline) -> None:
    E = d.energy
    if E is None:
        return
    if d.period is not None and tl.P < E / d.period * (1 - _TOL):
        what = "power" if d.motor_torque is None else "torque"
        have = (f"{tl.P:.6g} W" if what == "power"
                else f"{tl.T:.6g} N·m (P = M_D·ω_m = {tl.P:.6g} W)")
        raise DutyCycleError(d.field("motor", f"motor.{what}"), Notice.of(
            "dc_motor_weak", "the motor's {have} is less than the mean power of the operations "
            "E/T_c = {need:.6g} W: the flywheel would never recover (allowed: at least {need:.6g} "
            "W)", by=what, P=tl.P, T=tl.T, need=E / d.period, have=have))
    if d.revolutions is not None and tl.T < E / (TWO_PI * d.revolutions) * (1 - _TOL):
        need = E / (TWO_PI * d.revolutions)
        raise DutyCycleError(d.field("motor", "motor.torque"), Notice.of(
            "dc_torque_weak", "the motor's torque {T:.6g} N·m is less than the mean moment of the "
            "operations E/(2π·k) = {need:.6g} N·m: the flywheel would never recover (allowed: at "
            "least {need:.6g} N·m)", T=tl.T, need=need))
    if tl.t_op is not None and tl.Tc is not None and tl.t_op > tl.Tc * (1 + _TOL):
        raise DutyCycleError(d.field("operation", "operation"), Notice.of(
            "dc_operation_too_long", "the operation takes {t_op:.6g} s, longer than the cycle T_c "
            "= {Tc:.6g} s (allowed: at most the cycle)", t_op=tl.t_op, Tc=tl.Tc))
    if tl.t_op is not None and tl.t_op < 0:
        # library use only: no CLI input reaches this
        raise DutyCycleError(d.field("operation", "operation"),
                             f"ΔE = {d.delta_E:.6g} J leaves the motor a negative share of the "
                             f"operation's energy (allowed: ΔE ≤ E = {E:.6g} J)")


def _result(d: DutyCycle, tl: _Timeline, J: float) -> DutyCycleResult:
    E, lin = d.energy, d.linear_speeds
    w1, w2, wm, dE = tl.w1, tl.w2, tl.wm, tl.dE
    known_radius = d.radius is not None
    # with linear speeds the radius is unknown: J, ω, torques and angles cannot be known
    omega = (lambda x: None if lin or x is None else x)
    angle = (lambda t, w: None if lin or t is None else w * t)
    if lin:
        rim = (w1, w2, wm)
        mass = J                       # J computed with the radius 1 m: m = ΔE/(v²·δ)
        J_out = None
    else:
        rim = (w1 * d.radius, w2 * d.radius, wm * d.radius) if known_radius else (None,) * 3
        mass = J / d.radius ** 2 if known_radius else None
        J_out = J
    delta = (w1 - w2) / wm
    if tl.t_idle is not None and abs(tl.t_idle) <= 1e-12 * tl.Tc:     # round-off of Tc − E/P
        tl = _Timeline(w1, w2, wm, tl.P, tl.T, dE, tl.t_op, tl.t_rec, 0.0, tl.Tc)
    a_op = angle(tl.t_op, wm)
    a_rec = angle(tl.t_rec, wm)
    a_idle = angle(tl.t_idle, w1)
    cycle_angle = None if a_op is None else a_op + a_rec + a_idle
    warnings = []
    checks: list[tuple[str, float]] = []
    kinetic = 0.5 * J * (w1 - w2) * (w1 + w2)
    checks.append(("flywheel_energy", kinetic - dE))
    if E is not None:
        P = tl.P
        checks.append(("operation_energy_balance", E - P * tl.t_op - kinetic))
        checks.append(("recovery_energy_balance", P * tl.t_rec - kinetic))
        checks.append(("cycle_energy_balance", P * (tl.t_op + tl.t_rec) - E))
        checks.append(("cycle_time_balance", tl.t_op + tl.t_rec + tl.t_idle - tl.Tc))
        if not lin and tl.T > 0:
            checks.append(("recovery_time_two_ways", J * (w1 - w2) / tl.T - tl.t_rec))
        if dE == 0.0:
            warnings.append(Notice.of(
                "duty_motor_alone", "the motor alone gives the operation its energy (P·t_op ≥ E): "
                "the flywheel gives nothing, ΔE = 0"))
        if tl.t_idle > tl.Tc * 1e-9:
            warnings.append(Notice.of(
                "duty_motor_idles", "the motor is stronger than the operations need: it works "
                "{t_work:.6g} s of each {t_cycle:.6g} s cycle and idles {t_idle:.6g} s at ω_max "
                "(its torque taken to fall to zero there)", t_work=tl.t_op + tl.t_rec,
                t_cycle=tl.Tc, t_idle=tl.t_idle))
    if not 0 < delta <= 0.3 and dE > 0:
        warnings.append(Notice.of(
            "duty_delta_large", "δ = {delta:.4g}: the speed swings by more than 30 % of the mean",
            delta=delta))
    return DutyCycleResult(
        work=d.work, energy=E, delta_E=dE,
        energy_fluctuation_coefficient=None if not E else dE / E,
        motor_power=tl.P,
        motor_input_power=None if tl.P is None else tl.P / d.efficiency,
        motor_torque=None if lin else tl.T,
        mean_power=None if E is None else E / tl.Tc,
        efficiency=d.efficiency,
        omega_max=omega(w1), omega_min=omega(w2), omega_mean=omega(wm),
        rim_speed_max=rim[0], rim_speed_min=rim[1], rim_speed_mean=rim[2],
        delta=delta, J=J_out, mass=mass, radius=d.radius,
        operation_time=tl.t_op, operation_angle=a_op,
        operation_share=None if tl.t_op is None else tl.t_op / tl.Tc,
        operation_moment=None if a_op is None or a_op == 0 else E / a_op,
        recovery_time=tl.t_rec, recovery_angle=a_rec,
        idle_time=tl.t_idle, idle_angle=a_idle,
        cycle_time=tl.Tc, cycle_angle=cycle_angle,
        revolutions_per_operation=None if cycle_angle is None else cycle_angle / TWO_PI,
        operations_per_hour=None if tl.Tc is None else 3600.0 / tl.Tc,
        flywheel_given=d.flywheel_given,
        checks=tuple(checks), warnings=tuple(warnings),
        speed_given=None if not d.flywheel_given else "max" if d.speed_max is not None
        else "mean" if d.speed_mean is not None else "min")


def nonfinite(r: DutyCycleResult) -> str | None:
    """The name of the first result that is not a finite number (inputs near the limits of
    double precision), else None."""
    def walk(d: dict, prefix: str) -> str | None:
        for name, v in d.items():
            if isinstance(v, dict):
                bad = walk(v, f"{prefix}{name}.")
                if bad:
                    return bad
            elif isinstance(v, float) and not math.isfinite(v):
                return prefix + name
        return None

    return walk(r.to_document(), "")
