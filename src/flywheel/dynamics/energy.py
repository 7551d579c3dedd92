"""Work and kinetic energy over the cycle (Merzalov's method, seed 000 §3.2.7 and §4).

φ grids here are closed: phi[0] = 0, phi[-1] = Φ (the cycle), possibly non-uniform.
"""
from __future__ import annotations

import numpy as np


def trapezoid_areas(y: np.ndarray, x: np.ndarray) -> np.ndarray:
    """The trapezoid rule's strips ½·(y_i + y_{i+1})·(x_{i+1} − x_i), one per interval: the one
    quadrature of the package (:func:`cumulative_work` sums them running; a cycle total may sum
    them pairwise with np.sum, which is more accurate and differs in the last bits)."""
    return 0.5 * (y[1:] + y[:-1]) * np.diff(x)


def cumulative_work(M: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """A(φ) = ∫₀^φ M dφ [J] by the trapezoid rule (A[0] = 0); any running integral ∫₀^x y dx
    (time t(φ) = ∫dφ/ω, angle φ(t) = ∫ω dt) is the same call.

    >>> phi = np.linspace(0, np.pi, 5)
    >>> float(cumulative_work(np.ones(5), phi)[-1]) == float(np.pi)
    True
    """
    out = np.empty_like(phi)
    out[0] = 0.0
    np.cumsum(trapezoid_areas(M, phi), out=out[1:])
    return out


def balancing_moment(A_known: np.ndarray, phi: np.ndarray) -> float:
    """The constant moment that makes the work over the cycle zero [N·m]:
    M = −A_known(Φ)/Φ = −(1/Φ)·∮ M_known dφ (seed 000: M_PRD = −A_C/2π), from the known loads'
    cumulative work A_known(φ) (:func:`cumulative_work`, or exact where a load's work is)."""
    return -float(A_known[-1]) / (phi[-1] - phi[0])


def extreme(y: np.ndarray, phi: np.ndarray, kind: str) -> tuple[float, float]:
    """Global maximum or minimum of y over the whole grid, refined by the vertex of the parabola
    through the best node and its neighbours (the seed's local search missed the global minimum:
    seeds README, defect 6). Returns (φ [rad], value)."""
    i = int(np.argmax(y) if kind == "max" else np.argmin(y))
    if 0 < i < y.size - 1:
        x0, x1, x2 = phi[i - 1:i + 2]
        y0, y1, y2 = y[i - 1:i + 2]
        d = (x1 - x0) * (x1 - x2) * (x0 - x2)
        a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / d
        b = (x2**2 * (y0 - y1) + x1**2 * (y2 - y0) + x0**2 * (y1 - y2)) / d
        if a != 0 and (a < 0) == (kind == "max"):
            xv = -b / (2 * a)
            if x0 <= xv <= x2:
                c = y1 - a * x1**2 - b * x1
                return float(xv), float(a * xv**2 + b * xv + c)
    return float(phi[i]), float(y[i])


def first_group_energy_change(A: np.ndarray, J_II: np.ndarray, omega_mean: float) -> tuple[np.ndarray, np.ndarray]:
    """T_II(φ) = J_II·ω_m²/2 and ΔT_I(φ) = A(φ) − (T_II(φ) − T_II(0)) [J] (design.md §2;
    seed 000 §4.1.1 writes A − T_II, which differs by the constant T_II(0))."""
    T_II = J_II * omega_mean**2 / 2
    return T_II, A - (T_II - T_II[0])
