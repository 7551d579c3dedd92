"""The equation of motion integrated in time: an independent check of ω(φ), start-up, run-down.

J(φ)·φ̈ + ½·J′(φ)·φ̇² = M(φ, φ̇)   (Lagrange's equation for a one-degree-of-freedom machine
with reduced inertia J = J_I + J_II(φ); Артоболевский, «Теория механизмов и машин», ch. on
the equation of motion of the machine; design.md §2). J, J′ and M come from the φ grid as
periodic tables (linear interpolation), so the integration never sees the energy solution.

scipy.integrate is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class TimeHistory:
    """t [s], φ [rad] (unwrapped), ω [rad/s] of the crank."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray


def _periodic(phi_grid: np.ndarray, values: np.ndarray):
    period = phi_grid[-1] - phi_grid[0]

    def f(phi):
        return np.interp(np.mod(phi - phi_grid[0], period) + phi_grid[0], phi_grid, values)

    return f


def integrate(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M: np.ndarray, omega0: float,
              cycles: float, motor=None, rtol: float = 1e-10, atol: float = 1e-10,
              t_max: float | None = None, phi0: float = 0.0) -> TimeHistory:
    """Integrate φ̈ = (M(φ) + M_motor(ω) − ½J′φ̇²)/J from (φ0, ω0) until φ = φ0 + cycles·Φ
    (or t = t_max) with scipy's solve_ivp (DOP853).

    J, dJ, M: tables on the closed grid ``phi_grid`` (one cycle Φ); ``motor``: optional
    callable ω → additional driving moment [N·m] (a motor characteristic).
    """
    from scipy.integrate import solve_ivp

    Jf, dJf, Mf = _periodic(phi_grid, J), _periodic(phi_grid, dJ), _periodic(phi_grid, M)
    period = phi_grid[-1] - phi_grid[0]
    phi_end = phi0 + cycles * period

    def rhs(t, y):
        phi, w = y
        m = Mf(phi) + (motor(w) if motor is not None else 0.0)
        return [w, (m - 0.5 * dJf(phi) * w * w) / Jf(phi)]

    def done(t, y):
        return y[0] - phi_end

    done.terminal = True
    done.direction = 1

    def stalled(t, y):
        return y[1]

    stalled.terminal = True
    stalled.direction = -1
    horizon = t_max if t_max is not None else 10 * cycles * period / max(omega0, 1e-9) + 1.0
    sol = solve_ivp(rhs, (0.0, horizon), [phi0, omega0], method="DOP853", rtol=rtol, atol=atol,
                    events=[done, stalled], dense_output=False, max_step=period / 90 / max(omega0, 1e-3))
    return TimeHistory(sol.t, sol.y[0], sol.y[1])


def omega_at_phi(history: TimeHistory, phi: np.ndarray) -> np.ndarray:
    """ω of a time history at crank angles ``phi`` (unwrapped, inside its range)."""
    return np.interp(phi, history.phi, history.omega)


def linear_motor(starting_torque: float, no_load_speed: float):
    """The course's model of an asynchronous motor on its working branch:
    M_Д = M_п·(1 − ω/ω_x), with the starting torque M_п and the synchronous (no-load) speed ω_x
    (Артоболевский; Ефанов, ch. 9). Returns ω → M_Д."""

    def motor(w):
        return starting_torque * (1.0 - w / no_load_speed)

    return motor


def verify_steady(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M: np.ndarray,
                  omega: np.ndarray, cycles: int = 3) -> dict:
    """Integrate the equation of motion in time from the energy solution's state at φ = 0 over
    ``cycles`` cycles. Returns the largest relative change of ω from one cycle start to the next
    (``repeat_error``), the largest deviation from ω(φ) of the energy equation relative to its
    mean (``max_deviation``), and the cycle period from the time integration [s]."""
    h = integrate(phi_grid, J, dJ, M, float(omega[0]), cycles)
    period = phi_grid[-1] - phi_grid[0]
    starts = omega_at_phi(h, period * np.arange(cycles + 1))
    w_energy = np.interp(np.mod(h.phi, period), phi_grid, omega)
    return {
        "cycles": cycles,
        "repeat_error": float(np.max(np.abs(np.diff(starts))) / starts[0]),
        "max_deviation": float(np.max(np.abs(w_energy - h.omega)) / np.mean(omega)),
        "period": float(np.interp(period, h.phi, h.t)),
    }


def startup(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M_loads: np.ndarray, motor,
            omega_steady: float, delta: float, max_cycles: int = 400) -> dict:
    """Start from rest at φ = 0 under the loads M_loads(φ) and the motor ω → M_Д(ω).

    Integrates cycle by cycle until the cycle-mean speed stops changing (1e-7 relative), then
    reports the time at which the cycle-mean speed first came within δ/10 of its final value
    (``time_to_steady`` [s], ``cycles_to_steady``). ``stalled`` is True if the machine stops
    (the motor cannot overcome the loads)."""
    period = phi_grid[-1] - phi_grid[0]
    phi0, w0, t0 = 0.0, 0.0, 0.0
    means, starts_t = [], []
    ts, ws, ps = [np.zeros(1)], [np.zeros(1)], [np.zeros(1)]
    # first step off rest: a tiny initial speed avoids the singular start of the period-based step
    w0 = 1e-6 * omega_steady
    for k in range(max_cycles):
        h = integrate(phi_grid, J, dJ, M_loads, w0, 1.0, motor=motor, phi0=phi0,
                      t_max=50 * period / max(1e-3 * omega_steady, w0), rtol=1e-8, atol=1e-8)
        if h.phi[-1] < phi0 + period - 1e-9:
            return {"stalled": True, "stall_angle_deg": float(np.degrees(h.phi[-1])),
                    "time": float(t0 + h.t[-1])}
        dt = h.t[-1]
        means.append(period / dt)
        starts_t.append(t0)
        ts.append(t0 + h.t[1:]); ws.append(h.omega[1:]); ps.append(h.phi[1:])
        t0 += dt
        phi0, w0 = phi0 + period, float(h.omega[-1])
        if k > 2 and abs(means[-1] - means[-2]) < 1e-7 * means[-1]:
            break
    final = means[-1]
    k_ok = next(i for i, m in enumerate(means) if abs(m - final) <= delta / 10 * final
                and all(abs(mm - final) <= delta / 10 * final for mm in means[i:]))
    return {"stalled": False, "time_to_steady": float(starts_t[k_ok] + period / means[k_ok]),
            "cycles_to_steady": k_ok + 1, "omega_mean_steady": float(final),
            "t": np.concatenate(ts), "omega": np.concatenate(ws), "phi": np.concatenate(ps)}


def rundown(phi_grid: np.ndarray, J: np.ndarray, dJ: np.ndarray, M_loads: np.ndarray,
            omega0: float, max_cycles: int = 1000) -> dict:
    """The drive is cut at φ = 0 with speed ω0: the loads alone act until the crank stops.
    Returns ``time`` [s] and ``angle_deg`` (crank rotation) to standstill, and the history."""
    period = phi_grid[-1] - phi_grid[0]
    h = integrate(phi_grid, J, dJ, M_loads, omega0, max_cycles,
                  t_max=max_cycles * period / (0.01 * omega0), rtol=1e-8, atol=1e-8)
    stopped = bool(h.omega[-1] <= 1e-6 * omega0)
    return {"stopped": stopped, "time": float(h.t[-1]), "angle_deg": float(np.degrees(h.phi[-1])),
            "t": h.t, "omega": h.omega, "phi": h.phi}
