"""The aggregate in time: scipy's solve_ivp on the periodic orbit (a check of the closed form) and
from rest (the start-up), in the seed's coordinates (seed 003, eqs. 9.20, 9.24).

The integrations are bounded: the explicit method (DOP853) needs about ten steps per period of
the highest natural frequency, so the start-up runs at most MAX_FAST_PERIODS of them, and a
steady check that would need more than CHECK_FAST_PERIODS (a slow machine on a stiff coupling)
uses the implicit Radau method with the system's constant Jacobian. The natural frequencies come
from the caller (computed once, :func:`flywheel.elastic.modes.natural_frequencies`); without them
each function computes them itself. scipy is imported inside the function that uses it.

Every explicit integration is estimated before it starts (:func:`explicit_steps`) and refused
beyond :data:`MAX_STEPS` steps (about 20 s of computing) with one line that says what to change —
except a start-up that is stiff only (a steep motor characteristic on a light rotor, a strong
damper: the state matrix's largest |eigenvalue| ρ, not a fast mode, sets the explicit step): it is
integrated by LSODA with the constant Jacobian and the same largest step, 1/8 of the highest
natural period, so it still resolves every mode (:func:`start_up_method`);
``simulate`` reports ``progress(fraction)`` (the simulated time over t_end, 0 … 1, never
decreasing) to a plain callable.
"""
from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from flywheel.elastic.chain import Chain, Drive
from flywheel.elastic.forced import Steady
from flywheel.elastic.modes import Modes, natural_frequencies
from flywheel.errors import InputError, Notice

#: the explicit start-up runs at most this many periods of the highest natural frequency
MAX_FAST_PERIODS = 2000
#: the steady check is explicit up to this many periods of it, implicit (Radau) beyond
CHECK_FAST_PERIODS = 500
#: the most steps an explicit integration may take (:func:`explicit_steps`), some 20 s
MAX_STEPS = 250_000
#: a run stiff only by ρ (:func:`start_up_method`): over this many explicit steps (~2 s) and this
#: many times the steps that resolve the modes, LSODA instead
STIFF_STEPS = 25_000
STIFF_RATIO = 4.0


def _highest(ch: Chain, modes: Modes | None) -> float:
    """The highest natural frequency [rad/s], from ``modes`` when the caller has them."""
    return (modes or natural_frequencies(ch)).highest


@dataclass(frozen=True)
class History:
    """t [s]; phi [rad] and omega [rad/s] of every rotor (rows), reduced to shaft I; twist [rad]
    of every connection, q_{k+1} = φ_{k+1} − φ_k (rows; integrated as such, not a difference of
    two large angles); method: the solve_ivp method used."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    twist: np.ndarray
    method: str = "DOP853"


def state_space(ch: Chain, drive: Drive | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The equations as ẏ = A·y + b0 + b1·sin(ω·t) in the seed's coordinates, the state
    y = (q1 = φ1, the twists q_2 … q_N, the speeds ω_1 … ω_N), all reduced to shaft I.

    q̇1 = ω1, q̇_{k+1} = ω_{k+1} − ω_k; J_k·ω̇_k = the elastic and damping moments of the
    connections on either side (connection j pulls its left rotor by c_j·q_{j+1} + b_j·q̇_{j+1}
    and its right rotor back by as much) + M_Д(ω1) on the first rotor
    (M_п − (M_п/ω_x)·ω1, or the constant M_0·i31) − (M_0·i31 + M̃·i31·sin ω_III·t) on the last
    (9.20). The system is linear: A is also its (constant) Jacobian. drive None: free, b = 0.
    """
    n = ch.n
    A = np.zeros((2 * n, 2 * n))
    b0 = np.zeros(2 * n)
    b1 = np.zeros(2 * n)
    A[0, n] = 1.0
    for j in range(n - 1):
        A[1 + j, n + j], A[1 + j, n + j + 1] = -1.0, 1.0
        for k, sign in ((j, 1.0), (j + 1, -1.0)):         # left rotor pulled, right held back
            A[n + k, 1 + j] += sign * ch.c[j] / ch.J[k]
            A[n + k, n + j + 1] += sign * ch.damping[j] / ch.J[k]
            A[n + k, n + j] -= sign * ch.damping[j] / ch.J[k]
    if drive is not None:
        if drive.kind == "linear":
            A[n, n] -= drive.slope / ch.J[0]
            b0[n] += drive.M_start / ch.J[0]
        else:
            b0[n] += drive.M0 / ch.J[0]
        b0[-1] -= drive.M0 / ch.J[-1]
        b1[-1] -= drive.amplitude / ch.J[-1]
    return A, b0, b1


def explicit_steps(ch: Chain, drive: Drive | None, t_end: float,
                   modes: Modes | None = None) -> tuple[float, float]:
    """(the steps DOP853 takes over ``t_end`` [s], estimated; the system's fastest decay rate
    [1/s]). Two limits on the step: at most 1/8 of the shortest period (that of the highest
    natural frequency ω_top, or of the forcing), about 1.7·ω_top steps per second with the
    rejected ones; and the explicit method's stability, h ≲ 6/ρ with ρ the largest |eigenvalue|
    of the state matrix A (:func:`state_space`) — a steep motor characteristic on a light rotor
    (M_п/ω_x over J_Д) or a strong damper makes ρ large, the system stiff. The larger wins
    (measured on the bundled aggregate: 31 247 steps over 100 s against 31 300 estimated; a
    stiff motor, ρ = 4.0e4 1/s, 428 812 over 68.3 s against 427 000)."""
    A, _, _ = state_space(ch, drive)
    rho = float(np.max(np.abs(np.linalg.eigvals(A)))) if A.size else 0.0
    w = drive.forcing_ratio * drive.steady_speed() if drive is not None else 0.0
    fastest = max(_highest(ch, modes), w)
    return t_end * max(1.7 * fastest, rho / 6.0), rho


def resolving_steps(ch: Chain, drive: Drive | None, t_end: float,
                    modes: Modes | None = None) -> float:
    """The steps over ``t_end`` [s] that resolving the system's oscillations takes whatever the
    method (:func:`explicit_steps` without the stability limit): 1.7·max(ω_top, ω_forcing)·t_end."""
    w = drive.forcing_ratio * drive.steady_speed() if drive is not None else 0.0
    return t_end * 1.7 * max(_highest(ch, modes), w)


def start_up_method(ch: Chain, drive: Drive | None, t_end: float,
                    modes: Modes | None = None) -> str:
    """"LSODA" (stiff: the constant Jacobian, steps still at most 1/8 of the highest natural
    period) when the explicit method would take more than STIFF_STEPS steps (~2 s), more than
    STIFF_RATIO times those that resolve the modes (its stability limit ρ/6 sets the step), and
    resolving them stays within MAX_STEPS; else "DOP853" (explicit; :func:`check_work` refuses
    it beyond MAX_STEPS). LSODA and DOP853 agree to ~1e-8 where both run
    (tests/test_work_bounds.py)."""
    steps, _ = explicit_steps(ch, drive, t_end, modes)
    resolving = resolving_steps(ch, drive, t_end, modes)
    if steps > STIFF_STEPS and steps > STIFF_RATIO * resolving and resolving <= MAX_STEPS:
        return "LSODA"
    return "DOP853"


def check_work(ch: Chain, drive: Drive | None, t_end: float, what: str, option: str = "",
               modes: Modes | None = None, method: str = "DOP853") -> None:
    """Refuse (InputError) an integration over ``t_end`` that would take more than MAX_STEPS
    steps, naming ``option`` (e.g. "--t-end") when the user chose the duration, else what makes
    the system stiff. method "LSODA" (stiff): only the steps that resolve the modes count."""
    steps, rho = explicit_steps(ch, drive, t_end, modes)
    if method == "LSODA":
        steps = resolving_steps(ch, drive, t_end, modes)
    if steps <= MAX_STEPS:
        return
    motor_rate = drive.slope / ch.J[0] if drive is not None and drive.kind == "linear" else 0.0
    kind = "option" if option else "motor" if motor_rate >= 0.5 * rho else "stiff"
    if option:
        cause = f"{option}: "
        fix = f"give a shorter {option}"
    elif motor_rate >= 0.5 * rho:
        cause = "motor: "
        fix = (f"the motor's characteristic is steep for its rotor: M_st/ω_x over J_D = "
               f"{motor_rate:.3g} 1/s; a gentler slope (motor.synchronous_rpm, the torque) or a "
               "heavier rotor (the motor's J) makes it tractable")
    else:
        cause = ""
        fix = "a damper or a shaft this stiff for these rotors makes the system stiff (damping, c)"
    rate = max(rho, _highest(ch, modes))
    raise InputError(Notice.of(
        "too_many_steps", "{cause}the {task} would take about {steps:.3g} integration steps "
        "({t_end:.4g} s; highest rate of the system {rate:.4g} 1/s), more than the limit of "
        "{top}: {fix}", cause=cause, task=what, steps=steps, t_end=t_end, rate=rate, top=MAX_STEPS,
        fix_kind=kind, option=option, motor_rate=motor_rate, fix=fix))


def simulate(ch: Chain, drive: Drive | None, phi0, omega0, t_end: float, n_samples: int = 2001,
             rtol: float = 1e-9, atol: float = 1e-12, method: str = "DOP853",
             modes: Modes | None = None,
             progress: Callable[[float], None] | None = None) -> History:
    """Integrate M·φ̈ + C·φ̇ + K·φ = F(t, φ̇) with scipy's solve_ivp from φ0, ω0, in the
    coordinates of :func:`state_space`.

    F: the motor torque M_Д(φ̇_1) on the first rotor, −(M_0·i31 + M̃·i31·sin(ω_III·t)) on the last
    (9.20), ω_III = forcing_ratio × the steady speed (the seed's linear model); drive None: free.
    method "DOP853" (explicit) takes steps of at most 1/8 of the shortest period, the highest
    natural frequency's or the forcing's, and so does "LSODA" (for a system stiff by its motor or
    damper, not by a fast mode: the constant Jacobian A); "Radau" (implicit, for a stiff system: a torsional mode
    far faster than the forcing) gets the constant Jacobian and steps of at most 1/8 of the forcing
    period — it follows the forced motion but damps a mode's own oscillation it does not resolve.
    ``progress(fraction)``: t/t_end as the integration advances (non-decreasing, every 1 %).
    """
    from scipy.integrate import solve_ivp

    n = ch.n
    A, b0, b1 = state_space(ch, drive)
    w = drive.forcing_ratio * drive.steady_speed() if drive is not None else 0.0
    phi0 = np.asarray(phi0, dtype=float)
    y0 = np.concatenate([[phi0[0]], np.diff(phi0), np.asarray(omega0, dtype=float)])

    done = [0.0]

    def rhs(t, y):
        if progress is not None and t >= done[0] + 0.01 * t_end:
            done[0] = t
            progress(min(t / t_end, 1.0))
        return A @ y + b0 + b1 * math.sin(w * t)

    fastest = max(_highest(ch, modes), w, 1e-300)
    t_eval = np.linspace(0.0, t_end, n_samples)
    if method == "Radau":
        opts = {"jac": A, "max_step": 2 * math.pi / max(w, 1e-300) / 8}
    elif method == "LSODA":
        opts = {"jac": lambda t, y: A, "max_step": 2 * math.pi / fastest / 8}
    else:
        opts = {"max_step": 2 * math.pi / fastest / 8}
    with np.errstate(all="ignore"):
        sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, t_eval=t_eval, rtol=rtol,
                        atol=atol, **opts)
    if not sol.success or not np.all(np.isfinite(sol.y)):
        reason = sol.message if not sol.success else ""      # scipy's own words
        raise InputError(Notice.of(
            "ag_solve_ivp_failed", "solve_ivp ({method}) failed over 0 … {t_end:.4g} s: "
            "{reason_text}", method=method, t_end=t_end, reason=reason,
            reason_text=reason or 'the solution is not finite'))
    if progress is not None:
        progress(1.0)
    q1, twist, om = sol.y[0], sol.y[1:n], sol.y[n:]
    phi = q1 + np.vstack([np.zeros_like(q1), np.cumsum(twist, axis=0)])
    return History(sol.t, phi, om, twist, method)


def energy(ch: Chain, h: History) -> np.ndarray:
    """Kinetic plus potential energy along a history [J]: ½·Σ J·ω² + ½·Σ c·q²."""
    return (0.5 * (ch.J[:, None] * h.omega ** 2).sum(axis=0)
            + 0.5 * (ch.c[:, None] * h.twist ** 2).sum(axis=0))


def steady_method(ch: Chain, w: float, periods: float = 5.0,
                  modes: Modes | None = None) -> tuple[str, float]:
    """("DOP853" or "Radau", the periods of the highest natural frequency in ``periods`` forcing
    periods): explicit while that is at most CHECK_FAST_PERIODS, implicit beyond.

    >>> from flywheel.elastic.chain import chain
    >>> steady_method(chain([1.0, 1.0], [2.0]), 1.0)
    ('DOP853', 10.0)
    >>> steady_method(chain([1.0, 1.0], [2.0e6]), 1.0)
    ('Radau', 10000.0)
    """
    fast = periods * _highest(ch, modes) / w
    return ("DOP853" if fast <= CHECK_FAST_PERIODS else "Radau"), fast


def steady_run(ch: Chain, drive: Drive, st: Steady, periods: float = 5.0,
               per_period: int = 200, modes: Modes | None = None,
               method: str | None = None) -> History:
    """solve_ivp started on the closed-form periodic orbit (φ = θ + Im X, ω = ω_s + ω·Re X) over a
    few forcing periods: it must stay there (a check of the closed form). Explicit (DOP853) when
    that is at most CHECK_FAST_PERIODS periods of the highest natural frequency, else the implicit
    Radau method with the constant Jacobian (:func:`steady_method`): the cost is bounded either
    way; LSODA when the explicit run is stiff only by ρ (:func:`start_up_method`). method: force
    one."""
    w = st.omega_forcing
    phi0 = st.theta + st.X.imag
    omega0 = st.omega_mean + w * st.X.real
    t_end = periods * 2 * math.pi / w
    modes = modes or natural_frequencies(ch)
    if method is None:
        method, _ = steady_method(ch, w, periods, modes)
        if method == "DOP853":
            method = start_up_method(ch, drive, t_end, modes)
    return simulate(ch, drive, phi0, omega0, t_end, n_samples=int(periods * per_period) + 1,
                    method=method, modes=modes)


def start_up_duration(ch: Chain, drive: Drive, modes: Modes | None = None) -> tuple[float, float]:
    """(the default start-up duration, the duration wanted before the cap) [s]: five mechanical
    time constants τ = ΣJ·ω_x/M_п of the linear characteristic or 20 forcing periods, whichever is
    longer, at most MAX_FAST_PERIODS periods of the highest natural frequency."""
    w = drive.forcing_ratio * drive.steady_speed()
    wanted = 20 * 2 * math.pi / w
    if drive.kind == "linear":
        wanted = max(wanted, 5 * ch.J.sum() * drive.omega_x / drive.M_start)
    fastest = _highest(ch, modes)
    return min(wanted, MAX_FAST_PERIODS * 2 * math.pi / fastest), wanted


def start_up(ch: Chain, drive: Drive, t_end: float | None = None, n_samples: int = 4001,
             modes: Modes | None = None,
             progress: Callable[[float], None] | None = None,
             method: str | None = None) -> History:
    """From rest, all twists zero (linear motor), or from the nominal speed with the load applied
    at t = 0 (constant torque, which has no start-up of its own). Default duration:
    :func:`start_up_duration`. Explicit (DOP853): the start-up excites the torsional modes, and
    their peak moment is what it is for; LSODA when that is stiff (:func:`start_up_method`), with
    the same largest step. method: force one."""
    omega_s = drive.steady_speed()
    modes = modes or natural_frequencies(ch)
    if t_end is None:
        t_end, _ = start_up_duration(ch, drive, modes)
    if method is None:
        method = start_up_method(ch, drive, t_end, modes)
    v0 = 0.0 if drive.kind == "linear" else omega_s
    return simulate(ch, drive, np.zeros(ch.n), np.full(ch.n, v0), t_end, n_samples=n_samples,
                    modes=modes, progress=progress, method=method)


__all__ = ["MAX_FAST_PERIODS", "CHECK_FAST_PERIODS", "MAX_STEPS", "explicit_steps", "check_work",
           "resolving_steps", "start_up_method",
           "History", "state_space", "simulate",
           "energy", "steady_method", "steady_run", "start_up_duration", "start_up"]
