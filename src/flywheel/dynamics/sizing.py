"""Flywheel sizing for a coefficient of speed fluctuation δ, and its dimensions."""
from __future__ import annotations

import math

import numpy as np


def J_required_merzalov(delta_T_max: float, omega_mean: float, delta: float) -> float:
    """J_I = ΔT_нб/(ω_m²·δ) [kg·m²] (seed 000 §4: J_PRI := ΔT_нб/(ω_1ср²·δ1); Merzalov)."""
    return delta_T_max / (omega_mean**2 * delta)


def J_required_exact(A: np.ndarray, J_II: np.ndarray, omega_mean: float, delta: float) -> tuple[float, float]:
    """Exact J_I [kg·m²] and the initial total kinetic energy T0 [J] (Wittenbauer's energy–mass
    diagram, done numerically; design.md §2).

    With T(φ) = T0 + A(φ) = ½(J_I + J_II(φ))·ω², ω_max = ω_m(1 + δ/2) and ω_min = ω_m(1 − δ/2)
    require T0 + A ≤ k₊(J_I + J_II) and T0 + A ≥ k₋(J_I + J_II), k± = ω_m²(1 ± δ/2)²/2, with
    equality somewhere: J_I = [max(A − k₊J_II) − min(A − k₋J_II)]/(k₊ − k₋),
    T0 = k₊·J_I − max(A − k₊J_II).

    >>> A = np.array([0.0, 10.0, 0.0]); J = np.zeros(3)   # constant inertia: J = ΔT/(δ·ω_m²)
    >>> round(J_required_exact(A, J, 10.0, 0.1)[0], 12)   # ΔT/(δ·ω_m²) = 10/(0.1·100)
    1.0
    """
    k_plus, k_minus = tangent_slopes(omega_mean, delta)
    top = np.max(A - k_plus * J_II)
    bottom = np.min(A - k_minus * J_II)
    J_I = (top - bottom) / (k_plus - k_minus)
    return float(J_I), float(k_plus * J_I - top)


def tangent_slopes(omega_mean: float, delta: float) -> tuple[float, float]:
    """k± = ω_m²(1 ± δ/2)²/2 = ω_max²/2, ω_min²/2 [J/(kg·m²)]: the slopes of the two tangents
    to the energy–mass curve (:func:`J_required_exact`).

    >>> tangent_slopes(10.0, 0.2)
    (60.50000000000001, 40.5)
    """
    return omega_mean**2 * (1 + delta / 2) ** 2 / 2, omega_mean**2 * (1 - delta / 2) ** 2 / 2


def tangency_points(A: np.ndarray, J_II: np.ndarray, omega_mean: float, delta: float) -> tuple[int, int]:
    """Grid indices of the points where the tangents of :func:`J_required_exact` touch the
    energy–mass curve (A against J_II): the maximum of A − k₊·J_II (ψ_max) and the minimum of
    A − k₋·J_II (ψ_min)."""
    k_plus, k_minus = tangent_slopes(omega_mean, delta)
    return int(np.argmax(A - k_plus * J_II)), int(np.argmin(A - k_minus * J_II))


def disk(J: float, density: float = 7800.0, width_ratio: float = 0.2) -> dict:
    """Solid disk of diameter D, width b = w·D: J = π·ρ·b·D⁴/32, so
    D = (32·J/(π·ρ·w))^(1/5), mass = ρ·π·D²·b/4 = 8·J/D².
    Steel ρ = 7800, w = 0.2 gives the seed's D = 0.366·J^(1/5) (seed 000, last block).

    >>> round((32 / (math.pi * 7800 * 0.2)) ** 0.2, 3)
    0.366
    """
    if J <= 0:
        return {"D": 0.0, "b": 0.0, "mass": 0.0}
    D = (32 * J / (math.pi * density * width_ratio)) ** 0.2
    b = width_ratio * D
    return {"D": D, "b": b, "mass": density * math.pi * D**2 * b / 4}


def rim(J: float, density: float = 7800.0, width_ratio: float = 0.2, inner_ratio: float = 0.8) -> dict:
    """Rim (hub and spokes neglected) of outer diameter D, inner D1 = c·D, width b = w·D:
    J = π·ρ·b·(D⁴ − D1⁴)/32, so D = (32·J/(π·ρ·w·(1 − c⁴)))^(1/5), mass = ρ·π·(D² − D1²)·b/4.
    Steel with w = 0.2, c = 0.8 gives the seed's D = 0.406·J^(1/5) and its mass constant
    6123 ≈ ρπ/4 = 6126.1 (seed 000, last block).

    >>> round((32 / (math.pi * 7800 * 0.2 * (1 - 0.8**4))) ** 0.2, 3)
    0.406
    """
    if J <= 0:
        return {"D": 0.0, "D_inner": 0.0, "b": 0.0, "mass": 0.0}
    D = (32 * J / (math.pi * density * width_ratio * (1 - inner_ratio**4))) ** 0.2
    D1 = inner_ratio * D
    b = width_ratio * D
    return {"D": D, "D_inner": D1, "b": b, "mass": density * math.pi * (D**2 - D1**2) * b / 4}


def disk_course(J: float) -> dict:
    """The course's empirical disk rule (seed 000, last block): D = 0.366·J^(1/5),
    m = 8·J/D², b = 0.2·D (steel; the constant is (32/(π·7800·0.2))^(1/5) rounded)."""
    if J <= 0:
        return {"D": 0.0, "b": 0.0, "mass": 0.0}
    D = 0.366 * J**0.2
    return {"D": D, "b": 0.2 * D, "mass": 8 * J / D**2}


def rim_course(J: float) -> dict:
    """The course's empirical rim rule (seed 000, last block): D = 0.406·J^(1/5), b = 0.2·D,
    D1 = 0.8·D, m = 6123·(D² − D1²)·b (6123 ≈ ρπ/4 for steel, rounded)."""
    if J <= 0:
        return {"D": 0.0, "D_inner": 0.0, "b": 0.0, "mass": 0.0}
    D = 0.406 * J**0.2
    D1, b = 0.8 * D, 0.2 * D
    return {"D": D, "D_inner": D1, "b": b, "mass": 6123 * (D**2 - D1**2) * b}


def rim_speed_limit(allowable_stress: float, density: float) -> float:
    """Largest peripheral speed of a rotating rim [m/s]: the hoop stress of a thin ring is
    σ = ρ·v², so v_max = √(σ_allow/ρ) (the thin rotating ring; e.g. Timoshenko, Strength of
    Materials, part II, rotating rings). σ_allow = 7 MPa for cast iron and 20 MPa for steel give
    the customary limits of about 30 and 50 m/s."""
    return math.sqrt(allowable_stress / density)
