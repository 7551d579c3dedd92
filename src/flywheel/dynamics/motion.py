"""The true motion of the crank with the flywheel: ω(φ), ε(φ), t(φ) from the energy equation."""
from __future__ import annotations

import numpy as np

from flywheel.dynamics.energy import cumulative_work


def omega_from_energy(T0: float, A: np.ndarray, J_I: float, J_II: np.ndarray) -> np.ndarray:
    """ω(φ) [rad/s] from ½(J_I + J_II(φ))·ω² = T0 + A(φ) (the kinetic-energy theorem;
    design.md §2, seed 000: T̃(φ) = T0 + A(φ))."""
    return np.sqrt(2 * (T0 + A) / (J_I + J_II))


def T0_for_mean_speed(A: np.ndarray, J_I: float, J_II: np.ndarray, omega_mean: float) -> float:
    """The initial kinetic energy T0 [J] that makes (ω_max + ω_min)/2 = ω_m, by bisection
    (ω grows monotonically with T0)."""
    J = J_I + J_II
    lo = -np.min(A) + 1e-12 * (1 + abs(np.min(A)))   # ω ≥ 0 everywhere
    hi = lo + 0.5 * np.max(J) * (2 * omega_mean) ** 2 + np.ptp(A)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        w = np.sqrt(2 * (mid + A) / J)
        if 0.5 * (w.max() + w.min()) < omega_mean:
            lo = mid
        else:
            hi = mid
        if hi - lo <= 1e-15 * hi:
            break
    return 0.5 * (lo + hi)


def angular_acceleration(M_sum: np.ndarray, omega: np.ndarray, J: np.ndarray, dJ: np.ndarray) -> np.ndarray:
    """ε(φ) = (M_Σ − ½·dJ/dφ·ω²)/J [rad/s²]: the equation of motion in differential form
    (seed 000 §4, ε(φ) with J_I + J_II in the denominator)."""
    return (M_sum - 0.5 * dJ * omega**2) / J


def time_law(omega: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """t(φ) = ∫₀^φ dφ/ω [s] (the trapezoid rule of :func:`~flywheel.dynamics.energy.cumulative_work`)."""
    return cumulative_work(1.0 / omega, phi)


def speed_fluctuation(omega: np.ndarray) -> tuple[float, float, float, float]:
    """(ω_max, ω_min, ω_ср = (ω_max + ω_min)/2, δ = (ω_max − ω_min)/ω_ср)."""
    wmax, wmin = float(omega.max()), float(omega.min())
    wm = 0.5 * (wmax + wmin)
    return wmax, wmin, wm, (wmax - wmin) / wm
