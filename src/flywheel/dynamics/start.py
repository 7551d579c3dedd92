"""Motion from rest (issue 24 item 5) and the reduced machine it integrates (with the
acceleration at a stated state that :mod:`flywheel.dynamics.asks` reports, item 7).

The reduced equation of motion of a one-degree-of-freedom machine (Lagrange's equation with the
reduced inertia J(φ) = J_I + J_II(φ); Артоболевский, «Теория механизмов и машин», the equation
of motion of the machine in differential form; design.md §2):

    J(φ)·ε + ½·J′(φ)·ω² = M(φ, ω).

J comes from the grid's J_II and dJ_II/dφ as a periodic cubic Hermite interpolant (value and
slope at each node), and J′ is that interpolant's own derivative, so the equation conserves
½·J·ω² + ∫M dφ exactly for the J it integrates (which is the linkage's J_II to O(h⁴)); M, the
loads' reduced moments, is linear between nodes. scipy.integrate.solve_ivp (DOP853) is imported
inside the function. The work is bounded: at most MAX_EVALUATIONS evaluations of the
right-hand side, refused in one line beyond.
"""
from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass

import numpy as np

from flywheel.errors import InputError, Notice

#: the most evaluations of the equation's right-hand side a motion from rest may take
MAX_EVALUATIONS = 500_000


@dataclass(frozen=True)
class StartAt:
    """The crank at one reported instant of a motion from rest."""

    t: float            # [s]
    phi_deg: float      # φ [deg], unwrapped (it grows past the cycle)
    omega: float        # ω [rad/s]
    epsilon: float      # ε [rad/s²]


@dataclass(frozen=True)
class StartResult:
    """summary.json's results.start: a motion from (φ0, ω0) under a constant driving moment or
    the motor, integrated by solve_ivp (DOP853) with the case's tolerances."""

    phi0_deg: float                 # [deg]
    omega0: float                   # [rad/s]
    driver: str                     # "moment" or "motor"
    moment: float | None            # the constant driving moment [N·m] (driver "moment")
    t_end: float                    # [s]
    rtol: float
    atol: float
    evaluations: int                # of the right-hand side
    at: tuple[StartAt, ...]         # at the requested times


class ReducedMachine:
    """J(φ), J′(φ) and M(φ) of a machine over its cycle, at one scalar angle (plain floats:
    the right-hand side of an ODE). ``phi``: the closed grid (phi[-1] − phi[0] = Φ); ``J``,
    ``dJ``: J_I + J_II and dJ_II/dφ there; ``M``: the loads' reduced moment there.

    J is the cubic Hermite interpolant of (J, dJ) between nodes, J′ its derivative (Hermite
    basis h00 = 2τ³ − 3τ² + 1, h10 = τ³ − 2τ² + τ, h01 = −2τ³ + 3τ², h11 = τ³ − τ²): exact at
    the nodes, O(h⁴) between them. M is linear.

    >>> m = ReducedMachine([0.0, 1.0, 2.0], [1.0, 2.0, 1.0], [0.0, 0.0, 0.0], [0.0, 1.0, 0.0])
    >>> m(0.5), m(2.5)[0]
    ((1.5, 1.5, 0.5), 1.5)
    """

    def __init__(self, phi, J, dJ, M):
        self.x = [float(v) for v in phi]
        self.J, self.dJ, self.M = (np.asarray(f, float).tolist() for f in (J, dJ, M))
        self.x0, self.period, self.last = self.x[0], self.x[-1] - self.x[0], len(self.x) - 2

    def __call__(self, phi: float) -> tuple[float, float, float]:
        x = (phi - self.x0) % self.period + self.x0
        i = min(max(bisect_right(self.x, x) - 1, 0), self.last)
        h = self.x[i + 1] - self.x[i]
        t = (x - self.x[i]) / h
        J0, J1, d0, d1 = self.J[i], self.J[i + 1], self.dJ[i], self.dJ[i + 1]
        t2, t3 = t * t, t * t * t
        J = (2 * t3 - 3 * t2 + 1) * J0 + (t3 - 2 * t2 + t) * h * d0 + (3 * t2 - 2 * t3) * J1 \
            + (t3 - t2) * h * d1
        dJ = ((6 * t2 - 6 * t) * J0 + (6 * t2 - 6 * t) * -J1) / h \
            + (3 * t2 - 4 * t + 1) * d0 + (3 * t2 - 2 * t) * d1
        M = self.M[i] + (self.M[i + 1] - self.M[i]) * t
        return J, dJ, M


def acceleration(J: float, dJ: float, M: float, omega: float) -> float:
    """ε = (M − ½·J′·ω²)/J [rad/s²]: the reduced equation of motion solved for ε
    (Артоболевский, the equation of motion in differential form)."""
    return (M - 0.5 * dJ * omega * omega) / J


class _TooMuchWork(Exception):
    pass


def motion_from_rest(machine: ReducedMachine, phi0: float, omega0: float, driver, t_end: float,
                     times: list[float], rtol: float, atol: float,
                     max_evaluations: int = MAX_EVALUATIONS) -> tuple[list, int]:
    """[(t, φ, ω, ε)] at ``times`` [s] of the motion from φ0 [rad], ω0 [rad/s] to ``t_end``:
    y = (φ, ω), y′ = (ω, ε(φ, ω)) with M = the machine's M(φ) + driver(ω) [N·m], integrated by
    scipy's solve_ivp (DOP853, ``rtol``, ``atol``). Returns the rows and the number of
    evaluations. Raises InputError beyond ``max_evaluations`` evaluations."""
    from scipy.integrate import solve_ivp

    count = [0]

    def rhs(t, y):
        count[0] += 1
        if count[0] > max_evaluations:
            raise _TooMuchWork
        J, dJ, M = machine(y[0])
        return [y[1], acceleration(J, dJ, M + driver(y[1]), y[1])]

    try:
        sol = solve_ivp(rhs, (0.0, t_end), [phi0, omega0], method="DOP853", rtol=rtol,
                        atol=atol, t_eval=times, dense_output=False)
    except _TooMuchWork:
        raise InputError(Notice.of(
            "start_too_long", "start: the motion to t_end = {t_end:g} s needs more than {most} "
            "evaluations of the equation of motion (allowed: at most {most}; a shorter t_end or "
            "a looser rtol)", t_end=t_end, most=max_evaluations)) from None
    if not sol.success:
        raise InputError(Notice.of(
            "start_failed", "start: the integration stopped at t = {t:g} s ({reason})",
            t=float(sol.t[-1]) if sol.t.size else 0.0, reason=str(sol.message)))
    rows = []
    for t, phi, w in zip(sol.t, sol.y[0], sol.y[1]):
        J, dJ, M = machine(phi)
        rows.append((float(t), float(phi), float(w), float(acceleration(J, dJ, M + driver(w), w))))
    return rows, count[0]


def start_result(spec, phi: np.ndarray, J: np.ndarray, dJ: np.ndarray, M: np.ndarray,
                 motor) -> StartResult:
    """The case's [start] (:class:`flywheel.cases.run_start.StartSpec`) on the grid ``phi``
    with J = J_I + J_II, dJ = dJ_II/dφ and the loads' M; ``motor``: ω → M_Д of the case's
    [motor] (None without one)."""
    if spec.driver == "motor":
        if motor is None:
            raise InputError(Notice.of(
                "start_no_motor", "start.driver: \"motor\" needs a [motor] table (allowed: a "
                "[motor], or driver = \"moment\" with start.moment)"))
        driver = motor
    else:
        moment = float(spec.moment)

        def driver(w):
            return moment
    if not float(np.min(J)) > 0:
        raise InputError(Notice.of(
            "start_no_inertia", "start: the machine has no inertia (J = J_I + J_II ≤ 0): its "
            "motion from rest is undefined (allowed: masses in [links] or machine.first_group)"))
    phi0 = math.radians(spec.phi0_deg)
    rows, n = motion_from_rest(ReducedMachine(phi, J, dJ, M), phi0, spec.omega0, driver,
                               spec.t_end, list(spec.times), spec.rtol, spec.atol)
    return StartResult(
        phi0_deg=float(spec.phi0_deg), omega0=float(spec.omega0), driver=spec.driver,
        moment=None if spec.driver == "motor" else float(spec.moment), t_end=float(spec.t_end),
        rtol=float(spec.rtol), atol=float(spec.atol), evaluations=n,
        at=tuple(StartAt(t, math.degrees(p), w, e) for t, p, w, e in rows))

