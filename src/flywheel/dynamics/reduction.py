"""Reduction of masses to the crank: the reduced moment of inertia of the second group.

J_II(φ) = Σ m_i·|v_qSi|² + J_Si·ω_qi²   (kinetic energy of the links per ½ω², design.md §2;
seed 000 §3.1.1 without its cos(π/4) factor, seeds README defect 3);
dJ_II/dφ = 2·Σ (m_i·v_qSi·a_qSi + J_Si·ω_qi·ε_qi)   (seed 000 §3.1.2).
Each link's contribution is kept by name.
"""
from __future__ import annotations

import numpy as np


def link_inertia(mass: float, J_S: float, v_q: np.ndarray, a_q: np.ndarray,
                 omega_q: np.ndarray, eps_q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One link's share of J_II [kg·m²] and of dJ_II/dφ [kg·m²/rad].

    v_q, a_q: (N, 2) analogues of its centroid [m/rad, m/rad²]; omega_q, eps_q: (N,) of the link.

    >>> v = np.array([[0.0, 0.1]]); a = np.array([[-0.1, 0.0]]); z = np.zeros(1)
    >>> link_inertia(2.0, 0.0, v, a, z, z)
    (array([0.02]), array([0.]))
    """
    J = mass * np.einsum("ij,ij->i", v_q, v_q) + J_S * omega_q**2
    dJ = 2 * (mass * np.einsum("ij,ij->i", v_q, a_q) + J_S * omega_q * eps_q)
    return J, dJ


def reduced_inertia(parts: dict[str, tuple[np.ndarray, np.ndarray]]) -> tuple[np.ndarray, np.ndarray]:
    """Sum the links' (J, dJ/dφ) into J_II and dJ_II/dφ."""
    J = sum(p[0] for p in parts.values())
    dJ = sum(p[1] for p in parts.values())
    return J, dJ
