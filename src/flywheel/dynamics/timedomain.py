"""The equation of motion integrated in time: an independent check of ω(φ), start-up, run-down.

J(φ)·φ̈ + ½·J′(φ)·φ̇² = M(φ, φ̇)   (Lagrange's equation for a one-degree-of-freedom machine
with reduced inertia J = J_I + J_II(φ); Артоболевский, «Теория механизмов и машин», ch. on
the equation of motion of the machine; design.md §2). J, J′ and M come from the φ grid as
periodic tables (linear interpolation), so the integration never sees the energy solution.

The work is bounded and estimated before it starts: a start-up needs about
ω̄·τ·(ln(50/δ) − 1)/Φ cycles (τ = J̄/(M_п/ω_x) the mechanical time constant, :func:`startup_cycles`), a
run-down about ½·J(0)·ω0²/|A_cycle| cycles (the kinetic energy over the work the loads take per
cycle, :func:`rundown_cycles`); beyond :data:`MAX_STARTUP_CYCLES` or :data:`MAX_RUNDOWN_CYCLES`
the caller refuses (``stages.time_domain``). Each integration takes an optional ``progress``
callable, ``progress(fraction)`` with fractions 0 … 1 that never decrease (a plain callable: the
command line draws the bar).

scipy.integrate is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from flywheel.dynamics.energy import cumulative_work, trapezoid_areas
from flywheel.dynamics.periodic import PeriodicTables, periodic_linear
from flywheel.errors import Notice

#: the largest start-up allowed, in cycles as estimated by :func:`startup_cycles` (the
#: integration's own cap, ``startup(max_cycles=…)``, is twice that)
MAX_STARTUP_CYCLES = 1000
#: the largest run-down allowed, in cycles as estimated by :func:`rundown_cycles` (the
#: integration's own cap, ``rundown(max_cycles=…)``, is twice that)
MAX_RUNDOWN_CYCLES = 500

Progress = Callable[[float], None]


class _Monotone:
    """``progress`` called with fractions 0 … 1 that never decrease, at most about every 1 %."""

    def __init__(self, progress: Progress | None):
        self.progress = progress
        self.done = 0.0

    def __call__(self, fraction: float) -> None:
        if self.progress is None:
            return
        fraction = min(max(float(fraction), 0.0), 1.0)
        if fraction >= self.done + 0.01 or (fraction == 1.0 and self.done < 1.0):
            self.done = fraction
            self.progress(fraction)


@dataclass(frozen=True)
class TimeHistory:
    """t [s], φ [rad] (unwrapped), ω [rad/s] of the crank."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray


def _solve(tables: PeriodicTables, omega0: float, cycles: float, motor, rtol: float, atol: float,
           t_max: float | None, phi0: float, method: str = "DOP853", quadrature: bool = False,
           on_phi: Callable[[float], None] | None = None):
    """solve_ivp from (φ0, ω0) until φ = φ0 + cycles·Φ, ω falls to 0, or t = t_max.
    With ``quadrature`` a third state q′ = ω² (q = ∫ω dφ) is carried along; ``on_phi(φ)`` is
    called at every evaluation (for progress: it must not change anything)."""
    from scipy.integrate import solve_ivp

    period = tables.period
    phi_end = phi0 + cycles * period

    def rhs(t, y):
        phi, w = y[0], y[1]
        if on_phi is not None:
            on_phi(phi)
        J, dJ, m = tables(phi)
        if motor is not None:
            m += motor(w)
        acc = (m - 0.5 * dJ * w * w) / J
        return [w, acc, w * w] if quadrature else [w, acc]

    def done(t, y):
        return y[0] - phi_end

    done.terminal = True
    done.direction = 1

    def stalled(t, y):
        return y[1]

    stalled.terminal = True
    stalled.direction = -1
    horizon = t_max if t_max is not None else 10 * cycles * period / max(omega0, 1e-9) + 1.0
    y0 = [phi0, omega0, 0.0] if quadrature else [phi0, omega0]
    return solve_ivp(rhs, (0.0, horizon), y0, method=method, rtol=rtol, atol=atol,
                     events=[done, stalled], dense_output=False,
                     max_step=period / 90 / max(omega0, 1e-3))


def integrate(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M: np.ndarray, omega0: float,
              cycles: float, motor=None, rtol: float = 1e-10, atol: float = 1e-10,
              t_max: float | None = None, phi0: float = 0.0,
              on_phi: Callable[[float], None] | None = None) -> TimeHistory:
    """Integrate φ̈ = (M(φ) + M_motor(ω) − ½J′φ̇²)/J from (φ0, ω0) until φ = φ0 + cycles·Φ
    (or t = t_max) with scipy's solve_ivp (DOP853).

    J, dJ, M: tables on the closed grid ``phi_grid`` (one cycle Φ); ``motor``: optional
    callable ω → additional driving moment [N·m] (a motor characteristic); ``on_phi(φ)``: called
    at every evaluation of the right-hand side (progress).
    """
    sol = _solve(PeriodicTables(phi_grid, J, dJ, M), omega0, cycles, motor, rtol, atol, t_max, phi0,
                 on_phi=on_phi)
    return TimeHistory(sol.t, sol.y[0], sol.y[1])


def linear_motor(starting_torque: float, no_load_speed: float):
    """The course's model of an asynchronous motor on its working branch:
    M_Д = M_п·(1 − ω/ω_x), with the starting torque M_п and the synchronous (no-load) speed ω_x
    (Артоболевский; Ефанов, ch. 9). Returns ω → M_Д."""

    def motor(w):
        return starting_torque * (1.0 - w / no_load_speed)

    return motor


def verify_steady(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M: np.ndarray,
                  omega: np.ndarray, cycles: int = 3, progress: Progress | None = None) -> dict:
    """Integrate the equation of motion in time from the energy solution's state at φ = 0 over
    ``cycles`` cycles. Returns the largest relative change of ω from one cycle start to the next
    (``repeat_error``), the largest deviation from ω(φ) of the energy equation relative to its
    mean (``max_deviation``), and the cycle period from the time integration [s].

    Each cycle is one solve_ivp call that ends on the event φ = φ0 + Φ, so ω at the cycle starts
    and the period are the solver's own values there (not read off the step points by linear
    interpolation, whose error, ~h²·ω″/8 with steps of Φ/90, is some 1e-5 of ω).
    ``progress(fraction)``: after each cycle."""
    tables = PeriodicTables(phi_grid, J, dJ, M)
    period = tables.period
    report = _Monotone(progress)
    starts, periods, dev = [float(omega[0])], [], 0.0
    for k in range(cycles):
        sol = _solve(tables, starts[-1], 1.0, None, 1e-10, 1e-10, None, k * period)
        report((k + 1) / cycles)
        if sol.y[0][-1] < (k + 1) * period - 1e-9:
            raise RuntimeError("verify_steady: the machine stopped inside a cycle")
        periods.append(float(sol.t[-1]))
        starts.append(float(sol.y[1][-1]))
        w_e = periodic_linear(phi_grid, omega, sol.y[0], period)
        dev = max(dev, float(np.max(np.abs(w_e - sol.y[1]))))
    return {
        "cycles": cycles,
        "repeat_error": float(np.max(np.abs(np.diff(starts))) / starts[0]),
        "max_deviation": dev / float(np.mean(omega)),
        "period": periods[0],
    }


def predicted_steady_speed(phi_grid: np.ndarray, M_loads: np.ndarray, motor, omega_ref: float):
    """The cycle mean ω̄ = (1/Φ)∮ω dφ of the steady motion under a linear motor, or None.

    Over one cycle of steady (periodic) motion the kinetic energy ½J(φ)ω² returns to its value,
    so the work of the motor and the loads is zero: ∮(M_L + M_п − (M_п/ω_x)·ω) dφ = 0, i.e.
    ω̄ = (M_п + M̄_L)/(M_п/ω_x) with M̄_L = (1/Φ)∮M_L dφ — exact for any J(φ) and M_L(φ).
    The line is taken through ``motor(0)`` and ``motor(omega_ref)``. None if the motor's moment
    does not fall with speed or cannot carry the mean load (ω̄ ≤ 0)."""
    slope = _motor_slope(motor, omega_ref)
    if not slope > 0:
        return None
    w = (float(motor(0.0)) + _cycle_mean(M_loads, phi_grid)) / slope
    return w if w > 0 else None


def _motor_slope(motor, omega_ref: float) -> float:
    """M_п/ω_x of a linear characteristic: its fall per rad/s between 0 and ``omega_ref``."""
    return (float(motor(0.0)) - float(motor(omega_ref))) / omega_ref


def _cycle_mean(y: np.ndarray, phi_grid: np.ndarray) -> float:
    """(1/Φ)∮y dφ by the trapezoid rule, as :func:`flywheel.dynamics.energy.cumulative_work`."""
    return float(cumulative_work(np.asarray(y, float), phi_grid)[-1] / (phi_grid[-1] - phi_grid[0]))


def startup_cycles(phi_grid: np.ndarray, J: np.ndarray, M_loads: np.ndarray, motor,
                   omega_steady: float, delta: float) -> float | None:
    """The cycles a start-up from rest takes, estimated before it is integrated: a machine of
    constant inertia J̄ under a constant load and the linear motor approaches its steady speed
    as ω = ω̄·(1 − e^(−t/τ)), τ = J̄/(M_п/ω_x), so it is within δ/50 of it (the test of
    :func:`startup`) after t* = τ·ln(50/δ), having turned φ = ∫ω dt = ω̄·τ·(ln(50/δ) − 1 + δ/50),
    i.e. φ/Φ cycles (exact for that machine). None if the motor line has no
    steady speed (its moment does not fall with speed, or it cannot carry the mean load: the
    machine stalls, which the integration finds within a cycle)."""
    w_pred = predicted_steady_speed(phi_grid, np.asarray(M_loads, float), motor, omega_steady)
    slope = _motor_slope(motor, omega_steady)
    if w_pred is None or not slope > 0:
        return None
    tau = _cycle_mean(J, phi_grid) / slope
    period = float(phi_grid[-1] - phi_grid[0])
    return w_pred * tau * (math.log(50.0 / delta) - 1.0 + delta / 50.0) / period


def rundown_cycles(phi_grid: np.ndarray, J: np.ndarray, M_loads: np.ndarray,
                   omega0: float) -> float | None:
    """The cycles a run-down from ω0 at φ = 0 takes, estimated before it is integrated: the
    kinetic energy ½·J(0)·ω0² over the work the loads take per cycle, |∮M dφ| (the energy
    falls by that much every cycle). None if the loads take no net work (the machine keeps
    turning; :func:`rundown` integrates three cycles then)."""
    work = float(np.sum(trapezoid_areas(M_loads, phi_grid)))
    scale = float(np.sum(trapezoid_areas(np.abs(M_loads), phi_grid)))
    if not work < -1e-9 * scale:
        return None
    return 0.5 * float(J[0]) * omega0 * omega0 / -work


def history_cycle_means(t: np.ndarray, omega: np.ndarray, period: float) -> tuple[np.ndarray, np.ndarray]:
    """Cycle means (1/Φ)∮ω dφ of a history starting at φ = 0 (t [s], ω [rad/s]), one per whole
    cycle, placed at the middle of its cycle in time: φ(t) = ∫ω dt and ∫ω² dt by the trapezoid
    rule on the history's points (a picture of the approach for the plot; :func:`startup` takes
    its own means from a quadrature carried in the integration)."""
    phi = cumulative_work(omega, t)
    q = cumulative_work(omega**2, t)
    n = int(phi[-1] // period + 1e-9)
    if n < 1:
        return np.zeros(0), np.zeros(0)
    edges = period * np.arange(n + 1)
    t_edges = np.interp(edges, phi, t)
    q_edges = np.interp(t_edges, t, q)
    return 0.5 * (t_edges[1:] + t_edges[:-1]), np.diff(q_edges) / period


def startup(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M_loads: np.ndarray, motor,
            omega_steady: float, delta: float, max_cycles: int = 2 * MAX_STARTUP_CYCLES,
            max_time: float | None = None, method: str = "RK45",
            progress: Progress | None = None) -> dict:
    """Start from rest at φ = 0 under the loads M_loads(φ) and the motor ω → M_Д(ω) (linear).

    The machine is integrated cycle by cycle; each cycle's mean speed is ω̄_k = (1/Φ)∮ω dφ
    (carried as a quadrature in the integration). The steady speed is known beforehand from the
    motor line (:func:`predicted_steady_speed`, ``omega_final_predicted``); the run is
    ``converged`` once ω̄_k is within δ/50 of it (a fifth of the δ/10 band) and changes by less
    than δ/500 of it from one cycle to the next. The cycle-to-cycle approach of a one-degree-of-
    freedom machine is monotone (trajectories in the (φ, ω) plane cannot cross), so from there
    on ω̄ stays in the band.

    ``time_to_steady`` [s] is when the cycle means — placed at the middle of their cycles,
    starting from ω = 0 at t = 0 — enter the band ω_s·(1 ± δ/10) for good (linear
    interpolation, so accurate to a fraction of a cycle); ``cycles_to_steady`` is the number of
    the first cycle whose mean is in the band for good; ``omega_mean_steady`` is the limit of
    the cycle means (the last one, ``omega_mean_last``, extrapolated by Aitken's Δ²). ``time_constant`` is τ = J̄/(M_п/ω_x) with J̄ the cycle mean of J: for a
    constant J and a constant load the start-up is ω(t) = ω_s·(1 − e^(−t/τ)), so the band is
    reached after τ·ln(10/δ). ``omega_steady`` is a speed scale for the steps (the case's mean
    speed).

    If the run is not converged after ``max_cycles`` cycles (or ``max_time`` seconds),
    ``converged`` is False, the three numbers are None, and ``warning`` says how far it got
    (a slow motor: raise the cap or check M_п and ω_x). ``stalled`` is True if the machine stops
    (the motor cannot overcome the loads). ``progress(fraction)``: after each cycle, the cycles
    run over :func:`startup_cycles`' estimate (at most 0.99 until the end)."""
    tables = PeriodicTables(phi_grid, J, dJ, M_loads)
    report = _Monotone(progress)
    expected = startup_cycles(phi_grid, J, M_loads, motor, omega_steady, delta) or max_cycles
    period = tables.period
    w_pred = predicted_steady_speed(phi_grid, np.asarray(M_loads, float), motor, omega_steady)
    slope = _motor_slope(motor, omega_steady)
    tau = _cycle_mean(J, phi_grid) / slope if slope > 0 else None
    band, tol, tol_step = delta / 10, delta / 50, delta / 500
    phi0, t0 = 0.0, 0.0
    # a tiny initial speed avoids the singular start of the period-based step
    w0 = 1e-6 * omega_steady
    means, mids = [], []
    ts, ws, ps = [np.zeros(1)], [np.zeros(1)], [np.zeros(1)]
    converged = False
    for k in range(max_cycles):
        if max_time is not None and t0 >= max_time:
            break
        sol = _solve(tables, w0, 1.0, motor, 1e-8, 1e-8, 50 * period / max(1e-3 * omega_steady, w0),
                     phi0, method=method, quadrature=True)
        t, phi, w = sol.t, sol.y[0], sol.y[1]
        if phi[-1] < phi0 + period - 1e-9:
            return {"stalled": True, "converged": False,
                    "stall_angle_deg": float(np.degrees(phi[-1])), "time": float(t0 + t[-1]),
                    "omega_final_predicted": w_pred, "time_constant": tau,
                    "warning": Notice.of(
                        "startup_stall", "start-up: the motor cannot start the machine, it stops "
                        "at φ = {phi_deg:.1f}°", phi_deg=float(np.degrees(phi[-1])))}
        dt = float(t[-1])
        means.append(float(sol.y[2][-1]) / period)
        mids.append(t0 + dt / 2)
        ts.append(t0 + t[1:]); ws.append(w[1:]); ps.append(phi[1:])
        t0 += dt
        phi0, w0 = phi0 + period, float(w[-1])
        report(min(0.99, (k + 1) / max(expected, 1.0)))
        if (w_pred is not None and k > 0 and abs(means[-1] - w_pred) <= tol * w_pred
                and abs(means[-1] - means[-2]) <= tol_step * w_pred):
            converged = True
            break
    report(1.0)
    out = {"stalled": False, "converged": converged, "omega_final_predicted": w_pred,
           "time_constant": tau,
           "omega_mean_last": means[-1] if means else 0.0, "cycles_run": len(means),
           "time_run": float(t0), "t": np.concatenate(ts), "omega": np.concatenate(ws),
           "phi": np.concatenate(ps)}
    if not converged:
        target = (f"{w_pred:.5g} rad/s" if w_pred is not None
                  else "none: the motor line cannot carry the mean load")
        out.update(time_to_steady=None, cycles_to_steady=None, omega_mean_steady=None,
                   warning=Notice.of(
                       "startup_not_steady", "start-up: no steady state after {cycles} cycles "
                       "({t:.4g} s); the last cycle-mean speed is {omega:.5g} rad/s, the steady "
                       "speed predicted by the motor line {prediction}", cycles=len(means),
                       t=float(t0), omega=float(out["omega_mean_last"]),
                       omega_pred=None if w_pred is None else float(w_pred), prediction=target))
        return out
    lo, hi = w_pred * (1 - band), w_pred * (1 + band)
    i = len(means)
    while i > 0 and lo <= means[i - 1] <= hi:
        i -= 1
    # the mean enters the band between point i − 1 (or rest at t = 0) and point i
    ta, wa = (mids[i - 1], means[i - 1]) if i > 0 else (0.0, 0.0)
    tb, wb = mids[i], means[i]
    edge = lo if wa < lo else hi
    crossing = ta + (tb - ta) * (edge - wa) / (wb - wa) if wb != wa else tb
    # the limit of the cycle means: Aitken's Δ² on the last three (the approach is geometric
    # from cycle to cycle near the steady state); kept if it agrees with the motor line to δ/50
    steady = means[-1]
    if len(means) >= 3 and means[-2] != means[-3]:
        r = (means[-1] - means[-2]) / (means[-2] - means[-3])
        if 0 <= r < 1:
            limit = means[-1] + (means[-1] - means[-2]) * r / (1 - r)
            if abs(limit - w_pred) <= tol * w_pred:
                steady = limit
    out.update(time_to_steady=float(crossing), cycles_to_steady=i + 1,
               omega_mean_steady=float(steady))
    return out


def rundown(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M_loads: np.ndarray,
            omega0: float, max_cycles: int = 2 * MAX_RUNDOWN_CYCLES,
            progress: Progress | None = None) -> dict:
    """The drive is cut at φ = 0 with speed ω0: the loads alone act until the crank stops.
    Returns ``time`` [s] and ``angle_deg`` (crank rotation) to standstill, and the history.

    If the loads do no net work over a cycle (gravity only, say: |∮M dφ| ≤ 1e-9·∮|M| dφ), or
    positive work (an engine's gas: they drive), the machine never runs down: three cycles are
    integrated for the history and ``reason`` says which (``stopped`` False). ``progress(fraction)``: the angle turned over the estimate of
    :func:`rundown_cycles` (at most 0.99 until the end)."""
    period = phi_grid[-1] - phi_grid[0]
    # cycle totals summed pairwise (np.sum): the running sum's end differs in the last bits,
    # which for loads that do no net work is the whole printed value
    work = float(np.sum(trapezoid_areas(M_loads, phi_grid)))
    scale = float(np.sum(trapezoid_areas(np.abs(M_loads), phi_grid)))
    conservative = not work < -1e-9 * scale
    cycles = 3 if conservative else max_cycles
    report = _Monotone(progress)
    expected = 3.0 if conservative else max(rundown_cycles(phi_grid, J, M_loads, omega0), 1.0)
    on_phi = None if progress is None else (
        lambda phi: report(min(0.99, phi / (expected * period))))
    h = integrate(phi_grid, J, dJ, M_loads, omega0, cycles,
                  t_max=cycles * period / (0.01 * omega0), rtol=1e-8, atol=1e-8, on_phi=on_phi)
    report(1.0)
    stopped = bool(h.omega[-1] <= 1e-6 * omega0)
    out = {"stopped": stopped, "time": float(h.t[-1]), "angle_deg": float(np.degrees(h.phi[-1])),
           "t": h.t, "omega": h.omega, "phi": h.phi}
    if conservative and not stopped:
        out["reason"] = (
            Notice.of(
                "rundown_no_work", "the loads do no net work over a cycle ({work:.3g} J): without "
                "the drive the machine keeps turning", work=work)
            if not work > 1e-9 * scale else
            Notice.of(
                "rundown_positive_work", "the loads do positive work over a cycle ({work:+.3g} J: "
                "they drive, as an engine's gas does): without the constant resistance the machine "
                "speeds up, there is no run-down", work=work))
    return out
