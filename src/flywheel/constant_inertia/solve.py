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

from flywheel.constant_inertia.crossings import bisect_root, crossings
from flywheel.constant_inertia.graphs import TWO_PI, Moment, Piece, net_pieces, size
from flywheel.errors import InputError

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


def _cycle_work(m: Moment, quantity: str) -> float:
    """∮ M dφ [J]; NotFiniteError when the sum overflows (fsum raises on inf − inf)."""
    try:
        return m.work()
    except (OverflowError, ValueError) as exc:
        raise NotFiniteError(quantity, str(exc)) from None


def _J_for(delta_T_max: float, omega_mean: float, delta: float) -> float:
    """J = ΔT_нб/(δ·ω_ср²) [kg·m²]: :func:`flywheel.dynamics.sizing.J_required_merzalov`
    (imported here: its module loads numpy)."""
    from flywheel.dynamics.sizing import J_required_merzalov

    return J_required_merzalov(delta_T_max, omega_mean, delta)


@dataclass(frozen=True)
class Row:
    """One line of the segment table: a bound of a segment or a crossing M_D = M_C.

    phi [rad]; M_D, M_C [N·m] on the segment that starts here (at the cycle end: before it),
    None for a diagram given by areas; A = ∫₀^φ (M_D − M_C) dφ [J]; omega [rad/s].
    """

    phi: float
    kind: str  # "bound" | "crossing"
    M_D: float | None
    M_C: float | None
    A: float
    omega: float


#: rad/s → rev/min
RPM = 30.0 / math.pi


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
    graphs (None for an area diagram).
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

    def to_document(self, title: str = "", source: str = "") -> dict:
        """The results document, the JSON of ``flywheel task2 --json`` (SI units; angles in
        degrees where the key says ``_deg``; speeds in rev/min under ``rpm``).

        Keys of the contract: omega_max, omega_min, omega_mean, delta, phi_omega_max_deg,
        phi_omega_min_deg, delta_T_max, M_C, J_required (only when asked), segments. An angle
        that is not known (an area diagram without crossing angles) is None.
        """
        d: dict = {}
        if title:
            d["title"] = title
        if source:
            d["source"] = source
        d.update({
            "omega_max": self.omega_max,
            "omega_min": self.omega_min,
            "omega_mean": self.omega_mean,
            "delta": self.delta,
            "phi_omega_max_deg": _deg(self.phi_omega_max),
            "phi_omega_min_deg": _deg(self.phi_omega_min),
            "delta_T_max": self.delta_T_max,
            "M_C": self.M_C,
        })
        if self.J_required is not None:
            d["J_required"] = self.J_required
        d.update({
            "M_D": self.M_D,
            "balance_found": self.unknown,
            "J": self.J,
            "omega0": self.omega0,
            "steady": self.steady,
            "omega_end": self.omega_end,
            "work_end": self.work_end,
            "cycle_deg": math.degrees(self.cycle),
            "rpm": {"omega0": self.omega0 * RPM, "omega_max": self.omega_max * RPM,
                    "omega_min": self.omega_min * RPM, "omega_mean": self.omega_mean * RPM},
            "work_driving": self.work_driving,
            "work_resistance": self.work_resistance,
            "power": self.power,
        })
        if self.delta_target is not None:
            d["delta_target"] = self.delta_target
        if self.rim_mass is not None:
            d["rim_radius"] = self.rim_radius
            d["rim_mass"] = self.rim_mass
        d["segments"] = [
            {"phi_deg": _deg(row.phi), "phi": None if math.isnan(row.phi) else row.phi,
             "kind": row.kind, "M_D": row.M_D, "M_C": row.M_C, "A": row.A, "omega": row.omega}
            for row in self.rows]
        return d


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
        raise InputError(f"unknown moment must be 'driving' or 'resistance' (got {unknown!r})")
    mine, theirs = (("work_resistance", "work_driving") if unknown == "resistance"
                    else ("work_driving", "work_resistance"))
    other = _cycle_work(known, theirs)
    w0, w1 = _cycle_work(make(0.0), mine), _cycle_work(make(1.0), mine)
    if w1 == w0:
        raise InputError(f"the {unknown} moment's unknown value does not change its work: "
                         "the cycle balance cannot find it")
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
                             f"the cycle balance gives a {unknown} moment of {x!r} N·m")
    if x < 0.0:
        raise InputError(
            f"the cycle balance needs a negative {unknown} moment ({x:.6g} N·m): "
            f"the {'resistance' if unknown == 'driving' else 'driving'} graph does "
            f"{'more' if unknown == 'resistance' else 'less'} work than the "
            f"{unknown} graph can {'absorb' if unknown == 'resistance' else 'supply'}")
    return x


def _speed_from_mean(A_max: float, A_min: float, J: float, omega_mean: float) -> float:
    """ω0² from the mean speed: ω_max + ω_min = 2ω_ср and ω_max² − ω_min² = 2ΔT/J give
    ω_max = ω_ср + ΔT/(2Jω_ср); then ω0² = ω_max² − 2A_max/J."""
    dT = A_max - A_min
    w_max = omega_mean + dT / (2 * J * omega_mean)
    w_min = omega_mean - dT / (2 * J * omega_mean)
    if w_min <= 0.0:
        raise InputError(
            f"J = {J:.6g} kg·m² is too small for a mean speed of {omega_mean:.6g} rad/s: the "
            f"energy fluctuation {dT:.6g} J would stop the machine")
    return w_max * w_max - 2 * A_max / J


def check_positive(name: str, value: float | None, unit: str) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
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
        raise NotFiniteError(f"segments[{bad}].A", f"the work A(φ) = {A[bad]!r} J")
    # the first of equal extremes (equal to 1e-12 of the swing: round-off must not choose)
    tol = 1e-12 * (max(A) - min(A))
    i_max = next(i for i, a in enumerate(A) if a >= max(A) - tol)
    i_min = next(i for i, a in enumerate(A) if a <= min(A) + tol)
    A_max, A_min = max(A), min(A)
    dT = A_max - A_min
    if J is None:
        if delta is None:
            raise InputError("give the flywheel: J, or mass and radius of gyration, or δ")
        if omega_mean is None:
            raise InputError("to find J from δ give the mean speed, not ω0")
        if dT <= 0.0:
            raise InputError("the energy does not fluctuate: any J gives δ = 0")
        J = _J_for(dT, omega_mean, delta)
    if omega_mean is not None:
        if not steady:
            raise InputError("a mean speed needs steady motion (the work over the cycle "
                             f"is {A[-1]:.6g} J, not 0): give ω0 instead")
        w0sq = _speed_from_mean(A_max, A_min, J, omega_mean)
    else:
        w0sq = omega0 * omega0
    wsq = [w0sq + 2 * a / J for a in A]
    if min(wsq) <= 0.0:
        i = next(i for i, w in enumerate(wsq) if w <= 0.0)
        where = (f"at φ = {math.degrees(stop(J, w0sq)):.6g}°" if stop is not None
                 else f"before row {i}")
        raise InputError(f"the machine stops {where}: the kinetic energy "
                         f"½·J·ω0² = {0.5 * J * w0sq:.6g} J cannot cover the deficit "
                         f"{-min(A):.6g} J")
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


def _finish(res: dict, delta: float | None, rim_radius: float | None) -> dict:
    if delta is not None:
        res["delta_target"] = delta
        res["J_required"] = _J_for(res["delta_T_max"], res["omega_mean"], delta)
    if rim_radius is not None:
        J_rim = res.get("J_required") or res["J"]
        res["rim_radius"] = rim_radius
        res["rim_mass"] = J_rim / rim_radius ** 2
    return res


def solve(M_D: Moment, M_C: Moment, J: float | None = None, *, omega0: float | None = None,
          omega_mean: float | None = None, delta: float | None = None,
          rim_radius: float | None = None, unknown: str | None = None) -> Task2Result:
    """Steady (or not) motion under M_D(φ), M_C(φ) with constant J.

    Parameters: ``M_D``, ``M_C`` graphs [N·m over rad]; ``J`` [kg·m²] (None: found from
    ``delta`` at ``omega_mean``); exactly one of ``omega0`` (ω at φ = 0) or ``omega_mean``
    (ω_ср, steady motion only) [rad/s]; ``delta`` asks for the J giving that δ at the same
    ω_ср; ``rim_radius`` [m] asks for the rim mass m = J/R².

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
        raise InputError("give exactly one speed: ω0 or the mean speed")
    check_positive("J", J, "kg·m²")
    check_positive("ω0", omega0, "rad/s")
    check_positive("the mean speed", omega_mean, "rad/s")
    check_positive("the rim radius", rim_radius, "m")
    if delta is not None and not (0.0 < delta < 2.0):
        raise InputError(f"δ must lie between 0 and 2 (got {delta:g})")
    pieces = net_pieces(M_D, M_C)
    bounds: list[float] = []
    kinds: list[str] = []
    A: list[float] = []
    A_start: list[float] = []
    acc = 0.0
    for p in pieces:
        A_start.append(acc)
        bounds.append(p.phi0)
        kinds.append("bound")
        A.append(acc)
        for x in crossings(p):
            bounds.append(x)
            kinds.append("crossing")
            A.append(acc + p.work(x))
        acc += p.work(p.phi1)
    bounds.append(pieces[-1].phi1)
    kinds.append("bound")
    W_D, W_C = _cycle_work(M_D, "work_driving"), _cycle_work(M_C, "work_resistance")
    # relative to the size of the moments (``size``), not to W_D, W_C: zero-mean moments
    # have works of pure round-off and are steady all the same
    scale = max(abs(W_D), abs(W_C), size(M_D) + size(M_C), 1e-300)
    steady = abs(acc) <= BALANCE_RTOL * scale
    if steady:
        acc = 0.0
    A.append(acc)
    res = _motion(bounds, kinds, A, J, omega0, omega_mean, steady, delta,
                  stop=lambda J_, w0sq: _stop_angle(pieces, A_start, J_, w0sq))
    omega = res.pop("omega")
    rows = tuple(Row(x, k, M_D.value(x, +1 if i < len(bounds) - 1 else -1),
                     M_C.value(x, +1 if i < len(bounds) - 1 else -1), a, w)
                 for i, (x, k, a, w) in enumerate(zip(bounds, kinds, A, omega)))
    res = _finish(res, delta, rim_radius)
    power = (W_D / M_D.cycle) * res["omega_mean"] if steady else None
    return Task2Result(rows=rows, cycle=M_D.cycle, M_D=M_D.nominal, M_C=M_C.nominal,
                       unknown=unknown, work_driving=W_D, work_resistance=W_C, power=power,
                       driving=M_D, resistance=M_C, **res)


def solve_areas(energies: Sequence[float], J: float | None = None, *, cycle: float = TWO_PI,
                omega0: float | None = None, omega_mean: float | None = None,
                delta: float | None = None, rim_radius: float | None = None,
                crossings_at: Sequence[float] | None = None) -> Task2Result:
    """A turning-moment diagram given by the signed areas between its crossings with the mean
    line (Khurmi & Gupta, §16.5): ``energies`` [J] in order, positive above the mean line.

    The energy at the n-th crossing is the running sum; ΔT_нб = max − min of the running sums
    (with the start). The areas of a cycle sum to zero. ``crossings_at`` [rad], n + 1 angles
    from the start of the first area to the end of the last, label the rows; without them
    the angles of ω_max and ω_min are unknown (None).

    >>> r = solve_areas([295.0, -685.0, 40.0, -340.0, 960.0, -270.0], J=1.0, omega_mean=100.0)
    >>> r.delta_T_max
    985.0
    """
    check_positive("J", J, "kg·m²")
    check_positive("ω0", omega0, "rad/s")
    check_positive("the mean speed", omega_mean, "rad/s")
    if (omega0 is None) == (omega_mean is None):
        raise InputError("give exactly one speed: ω0 or the mean speed")
    if delta is not None and not (0.0 < delta < 2.0):
        raise InputError(f"δ must lie between 0 and 2 (got {delta:g})")
    e = [float(x) for x in energies]
    if len(e) < 2:
        raise InputError("a diagram needs at least two areas")
    total, size = math.fsum(e), math.fsum(abs(x) for x in e)
    if abs(total) > BALANCE_RTOL * size:
        raise InputError(f"the areas sum to {total:.6g}, not 0: over a cycle of steady motion "
                         "the areas above and below the mean line are equal")
    A = [0.0]
    for x in e[:-1]:
        A.append(A[-1] + x)
    A.append(0.0)
    if crossings_at is not None:
        bounds = [float(x) for x in crossings_at]
        if len(bounds) != len(e) + 1:
            raise InputError(f"{len(e)} areas need {len(e) + 1} crossing angles "
                             f"(got {len(bounds)})")
        if any(b1 <= b0 for b0, b1 in zip(bounds, bounds[1:])):
            raise InputError("crossing angles must increase")
    else:
        bounds = [cycle * i / len(e) for i in range(len(e) + 1)]
    res = _motion(bounds, ["crossing"] * len(A), A, J, omega0, omega_mean, True, delta,
                  angles_known=crossings_at is not None)
    omega = res.pop("omega")
    rows = tuple(Row(x if crossings_at is not None else math.nan, "crossing", None, None, a, w)
                 for x, a, w in zip(bounds, A, omega))
    res = _finish(res, delta, rim_radius)
    return Task2Result(rows=rows, cycle=cycle, **res)


def sample(result: Task2Result, n: int = 1441) -> dict[str, list[float]]:
    """Curves for plotting: φ [rad], M_D, M_C [N·m], A [J], ω [rad/s] on n + the table's points.

    Only for results from graphs (``solve``); an area diagram has no curves between rows.
    """
    if result.driving is None or result.resistance is None:
        raise InputError("a diagram given by areas has no moment curves to sample")
    pieces = net_pieces(result.driving, result.resistance)
    xs = sorted({result.cycle * i / (n - 1) for i in range(n)} | {r.phi for r in result.rows})
    A_start, acc = [], 0.0
    for p in pieces:
        A_start.append(acc)
        acc += p.work(p.phi1)
    out: dict[str, list[float]] = {"phi": [], "M_D": [], "M_C": [], "A": [], "omega": []}
    j = 0
    w0sq = result.omega0 ** 2
    for x in xs:
        while j < len(pieces) - 1 and x >= pieces[j].phi1:
            j += 1
        a = A_start[j] + pieces[j].work(x)
        out["phi"].append(x)
        out["M_D"].append(result.driving.value(x))
        out["M_C"].append(result.resistance.value(x))
        out["A"].append(a)
        out["omega"].append(math.sqrt(max(w0sq + 2 * a / result.J, 0.0)))
    return out



__all__ = ["BALANCE_RTOL", "NotFiniteError", "Row", "Task2Result", "balance", "solve",
           "solve_areas", "sample", "check_positive"]
