"""Textbook asks of a run (issue 24 item 7) and the hook of [start] (item 5, :func:`with_start`): the crank's acceleration at a stated angle and
speed (``--snapshot PHI_DEG:RPM``, ``[output] snapshots``), positions given by a slider's
travel (``--at-travel POINT:METRES``: the crank angles become report angles), and the crank
angles where a column of table.csv changes sign (``--roots COLUMN``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from flywheel.dynamics.start import ReducedMachine, acceleration, start_result
from flywheel.errors import InputError, Notice
from flywheel.units import RAD_S_PER_RPM, SECONDS_PER_MINUTE, TWO_PI

MAX_ASKS = 72          # of each kind on one command line
MAX_ROOTS = 1000       # sign changes listed per column
RPM_LIMIT = 1e6        # [rev/min]


@dataclass(frozen=True)
class Snapshot:
    """The crank's angular acceleration at a stated angle and speed (not the periodic motion's):
    ε = (M_Σ(φ) − ½·J′(φ)·ω²)/J(φ), M_Σ the loads with the balancing moment."""

    phi_deg: float      # [deg]
    omega: float        # [rad/s]
    rpm: float          # [rev/min]
    J: float            # J_I + J_II(φ) [kg·m²]
    dJ: float           # dJ_II/dφ [kg·m²/rad]
    M_sum: float        # M_Σ(φ) [N·m]
    epsilon: float      # [rad/s²]


@dataclass(frozen=True)
class TravelAt:
    """The crank angles where a slider's point is ``travel`` [m] from its outer dead centre."""

    point: str
    travel: float               # [m]
    phi_deg: tuple[float, ...]  # [deg], in the cycle, increasing


@dataclass(frozen=True)
class Roots:
    """The crank angles [deg] where a table.csv column changes sign, each linearly
    interpolated between the two nodes around it (a node where it is 0: that node)."""

    column: str
    phi_deg: tuple[float, ...]


def _pair(option: str, text: str) -> tuple[str, str]:
    head, sep, tail = text.rpartition(":")
    if not sep or not head or not tail:
        if option == "--snapshot":
            raise InputError(Notice.of(
                "ask_snapshot_format", "--snapshot: {got!r} is not PHI_DEG:RPM (allowed: an angle "
                "and a speed joined by a colon, e.g. 30:1500)", got=text))
        raise InputError(Notice.of(
            "ask_travel_format", "--at-travel: {got!r} is not POINT:METRES (allowed: a slider's "
            "point and a travel joined by a colon, e.g. B:0.05)", got=text))
    return head, tail


def _number(option: str, text: str, lo: float, hi: float) -> float:
    try:
        v = float(text)
    except ValueError:
        v = math.nan
    if not (math.isfinite(v) and lo <= v <= hi):
        raise InputError(Notice.of(
            "ask_number", "{option}: {got!r} is not a number within {lo:g} … {hi:g}",
            option=option, got=text, lo=lo, hi=hi))
    return v


def _count(option: str, given: list) -> None:
    if len(given) > MAX_ASKS:
        raise InputError(Notice.of(
            "ask_too_many", "{option}: {count} given (allowed: at most {most})", option=option,
            count=len(given), most=MAX_ASKS))


def parse_snapshots(given: list[str] | None) -> list[tuple[float, float]]:
    """``--snapshot PHI_DEG:RPM`` values as (φ [deg], n [rev/min]); InputError (one line)."""
    given = given or []
    _count("--snapshot", given)
    out = []
    for text in given:
        a, b = _pair("--snapshot", text)
        out.append((_number("--snapshot", a, -1e6, 1e6),
                    _number("--snapshot", b, -RPM_LIMIT, RPM_LIMIT)))
    return out


def travel_angles(case, given: list[str] | None) -> tuple[TravelAt, ...]:
    """``--at-travel POINT:METRES``: for each, the crank angles of the cycle where the slider
    point POINT (the joint of an RRP dyad) is METRES from its outer dead centre (the one
    farther from the crank axis) along its guide: the sign changes of the travel minus METRES
    on a 3600-interval grid, each refined by Brent's method on the exact kinematics
    (scipy.optimize.brentq). InputError for a point that is no slider's or a travel beyond
    the stroke."""
    given = given or []
    _count("--at-travel", given)
    if not given:
        return ()
    if case.tabulated is not None:
        raise InputError(Notice.of(
            "ask_travel_tabulated", "--at-travel: the case gives its kinematics as a table "
            "([tabulated]): there is no slider to measure (allowed: a case with [crank])"))
    from scipy.optimize import brentq

    from flywheel.linkage import solve
    from flywheel.linkage.deadcentres import dead_centres, guide_frame

    mech = case.mechanism()
    joints = {d.joint: d for d in mech.dyads if hasattr(d, "guide")}
    cycle = math.radians(case.machine.cycle_deg)
    out = []
    for text in given:
        name, value = _pair("--at-travel", text)
        if name not in joints:
            raise InputError(Notice.of(
                "ask_travel_point", "--at-travel: {point!r} is not the point of a slider (the "
                "sliders' points: {points})", point=name, points=", ".join(sorted(joints)) or "—"))
        d = joints[name]
        u, base = guide_frame(d)
        outer = next(dc for dc in dead_centres(mech, d.slider) if dc.kind == "outer")
        inner = next(dc for dc in dead_centres(mech, d.slider) if dc.kind == "inner")
        stroke = abs(outer.x - inner.x)
        metres = _number("--at-travel", value, 0.0, stroke)     # within the stroke [m]

        def f(phi):
            x = (solve(mech, np.atleast_1d(phi)).points[d.joint].r - base) @ u
            return np.abs(x - outer.x) - metres

        grid = np.linspace(0.0, cycle, 3601)
        y = f(grid)
        found = [float(grid[i]) for i in np.nonzero(y == 0)[0] if grid[i] < cycle]
        for i in np.nonzero(y[:-1] * y[1:] < 0)[0]:
            found.append(brentq(lambda p: float(f(p)[0]), grid[i], grid[i + 1], xtol=1e-13))
        out.append(TravelAt(name, metres, tuple(sorted(math.degrees(p) for p in found))))
    return tuple(out)


def find_roots(results, given: list[str] | None) -> tuple[Roots, ...]:
    """``--roots COLUMN``: the sign changes of the table.csv column COLUMN (its key, e.g.
    ``a_B``, or its header, ``a_B [m/s²]``) over the grid, linearly interpolated
    (:class:`Roots`), at most MAX_ROOTS per column. InputError for a column not in table.csv."""
    given = given or []
    _count("--roots", given)
    out = []
    for name in given:
        key = name.split(" [")[0].strip()
        if key not in results.columns or key == "phi_deg":
            raise InputError(Notice.of(
                "ask_roots_column", "--roots: {column!r} is not a column of table.csv (allowed: "
                "a column's name as its header gives it, e.g. {example})", column=name,
                example=next((k for k in results.columns if k != "phi_deg"), "M_sum")))
        y = np.asarray(results.columns[key].values, float)
        phi = results.phi
        zero = [float(phi[i]) for i in np.nonzero(y[:-1] == 0)[0]]
        i = np.nonzero(y[:-1] * y[1:] < 0)[0]
        cross = phi[i] - y[i] * (phi[i + 1] - phi[i]) / (y[i + 1] - y[i])
        found = sorted(zero + cross.tolist())
        if len(found) > MAX_ROOTS:
            raise InputError(Notice.of(
                "ask_roots_too_many", "--roots: {column} changes sign {count} times (allowed: at "
                "most {most} listed)", column=key, count=len(found), most=MAX_ROOTS))
        out.append(Roots(key, tuple(math.degrees(p) for p in found)))
    return tuple(out)


def with_asks(results, case, snapshot: list[str] | None = None,
              travel: tuple[TravelAt, ...] = (), roots: list[str] | None = None):
    """``results`` with the case's ``[output] snapshots`` and the command line's: the
    snapshots (:func:`flywheel.dynamics.start.snapshots`: ε at φ and n with J = J_I + J_II
    and M_Σ of the run), the travel angles and the roots."""
    asks = [tuple(s) for s in getattr(case.output, "snapshots", ())] + parse_snapshots(snapshot)
    red, en, mo = results.reduction, results.energy, results.motion
    snaps = snapshots(asks, results.phi, mo.J_I + red.J_II, red.dJ_II, en.M_sum) if asks else None
    return replace(results, snapshots=snaps, at_travel=tuple(travel) or None,
                   roots=find_roots(results, roots) or None)


@dataclass(frozen=True)
class TravelAsk:
    """``--at-travel``'s angles (:func:`travel_angles`), to be added to the report angles."""

    found: tuple[TravelAt, ...]

    def at_deg(self, at: list[float] | None, case) -> list[float] | None:
        """The report angles [deg] with the travel angles added (``at``, else the case's
        output.at_deg, first); ``at`` unchanged without --at-travel."""
        if not self.found:
            return at
        base = list(case.output.at_deg if at is None else at)
        return base + [a for t in self.found for a in t.phi_deg if a not in base]


def at_with_travel(case, given: list[str] | None) -> TravelAsk:
    """:func:`travel_angles` of ``--at-travel`` as a :class:`TravelAsk`."""
    return TravelAsk(travel_angles(case, given))


def snapshots(asks: list[tuple[float, float]], phi: np.ndarray, J: np.ndarray, dJ: np.ndarray,
              M_sum: np.ndarray) -> tuple[Snapshot, ...]:
    """ε at each stated (φ [deg], n [rev/min]) (:class:`Snapshot`), J and M_Σ read at φ as in
    :class:`ReducedMachine` (at a node of the grid, its own values)."""
    machine = ReducedMachine(phi, J, dJ, M_sum)
    out = []
    for phi_deg, rpm in asks:
        Jv, dJv, Mv = machine(math.radians(phi_deg))
        w = rpm * RAD_S_PER_RPM
        out.append(Snapshot(float(phi_deg), float(w), float(rpm), float(Jv), float(dJv),
                            float(Mv), float(acceleration(Jv, dJv, Mv, w))))
    return tuple(out)


def with_start(results, case):
    """``results`` with the motion of the case's [start] (None without one) and its
    ``[output] snapshots`` (:func:`flywheel.dynamics.asks.with_asks`): J = J_I + J_II(φ)
    with the flywheel the run sized (or was given), the loads' reduced moments M_known(φ), and
    the constant moment or the [motor] (M_п by default as ``--transients`` takes it: its mean
    torque at ω_m is the driving moment)."""
    spec = getattr(case, "start", None)
    if spec is None:
        return with_asks(results, case)         # [output] snapshots

    from flywheel.dynamics.timedomain import linear_motor

    red, en, mo = results.reduction, results.energy, results.motion
    motor = None
    if case.motor is not None:
        w_x = case.motor.no_load_speed_rpm * TWO_PI / SECONDS_PER_MINUTE
        M_p = case.motor.starting_torque or en.driving_moment / (1 - case.machine.omega_mean / w_x)
        motor = linear_motor(M_p, w_x)
    st = start_result(spec, results.phi, mo.J_I + red.J_II, red.dJ_II, en.M_known, motor)
    return with_asks(replace(results, start=st), case)
