"""The work of one operation of a press (punching, shearing, riveting, stamping) and the speed
limits a problem states: pure formulas on plain floats (``math`` only).

The work of an operation is the area under its force–travel curve, ``E = ∫ F ds`` [J], over the
travel ``s`` = the plate's thickness ``t`` [m]. The books give it in one of three ways:

- directly, "15 kN·m of energy per hole" (Khurmi & Gupta, *Theory of Machines*, Ex. 16.19);
- as energy per unit of sheared area, "7 N·m per mm² of sheared area" (Ex. 16.20, 16.22):
  ``E = e·A`` with the sheared area ``A = π·d·t`` of a hole of diameter ``d`` (the hole's
  cylindrical wall) or ``A = L·t`` of a straight cut of length ``L``;
- as the largest force ``F_max = A·τ_u`` (the sheared area times the ultimate shear strength,
  Khurmi & Gupta, "Flywheel in Punching Press", Ex. 16.23) with a stated shape of the force
  over the travel, see :data:`SHAPES`.

The speed limits: ``δ = (ω_max − ω_min)/ω_ср`` with ``ω_ср = (ω_max + ω_min)/2`` — the
coefficient of fluctuation of speed ``C_s`` of Khurmi & Gupta, ch. 16 ("total fluctuation of
speed 3 % of the mean": δ = 0.03; "±1.5 %": δ = 0.03) and the coefficient of unevenness of
Артоболевский, «Теория механизмов и машин» (δ = (ω_max − ω_min)/ω_ср).
"""
from __future__ import annotations

import math

# shape of the force over the travel → the share of F_max·t that is the work E
SHAPES = {
    "constant": 1.0,   # F = F_max over the whole travel: E = F_max·t
    "falling": 0.5,    # F falls linearly from F_max to 0 (the plate sheared through): E = F·t/2
    "triangle": 0.5,   # F rises linearly from 0 to F_max at mid-travel, falls to 0: E = F·t/2
}


def work_of_stroke(force_max: float, travel: float, shape: str) -> float:
    """The work ``E`` [J] of a force with the largest value ``force_max`` [N] over ``travel`` [m]
    with a force–travel curve of ``shape`` (the area under it):

    - ``constant``: ``E = F_max·t``;
    - ``falling``: linear from ``F_max`` to 0, ``E = ½·F_max·t`` — the punching force of
      Khurmi & Gupta, *Theory of Machines*, ch. 16, Ex. 16.23 ("energy required per stroke
      = ½ × maximum shearing force × thickness of plate");
    - ``triangle``: 0 → ``F_max`` at mid-travel → 0, ``E = ½·F_max·t``.

    >>> work_of_stroke(1000.0, 0.02, "constant"), work_of_stroke(1000.0, 0.02, "falling")
    (20.0, 10.0)
    """
    return SHAPES[shape] * force_max * travel


def sheared_area_hole(diameter: float, thickness: float) -> float:
    """The sheared area of a punched hole, the wall of a cylinder: ``A = π·d·t`` [m²]
    (Khurmi & Gupta, Ex. 16.20: "sheared area = π·d·t").

    >>> round(sheared_area_hole(0.038, 0.032) * 1e6, 3)      # mm²; the book: 3820 mm²
    3820.177
    """
    return math.pi * diameter * thickness


def sheared_area_cut(length: float, thickness: float) -> float:
    """The sheared area of a straight cut of ``length`` through a plate: ``A = L·t`` [m²]."""
    return length * thickness


def share_from_stroke(thickness: float, stroke: float) -> float:
    """The share of the cycle the operation takes when the crank makes one revolution per
    operation and the punch is taken to move uniformly over its down-and-up travel ``2·s``:
    ``(θ₂ − θ₁)/2π = t/(2·s)`` (Khurmi & Gupta, *Theory of Machines*, ch. 16,
    "Flywheel in Punching Press"; used in Ex. 16.20).

    >>> share_from_stroke(0.032, 0.100)       # Ex. 16.20: 32 mm plate, 100 mm stroke
    0.16
    """
    return thickness / (2.0 * stroke)


def speed_limits(maximum: float | None = None, minimum: float | None = None,
                 mean: float | None = None, delta: float | None = None) -> tuple[float, float]:
    """``(ω_max, ω_min)`` from two of: ``maximum``, ``minimum``, ``mean`` (= (ω_max + ω_min)/2)
    and ``delta`` (δ = (ω_max − ω_min)/ω_ср). Any unit (rad/s, rev/min, m/s at a radius):
    the relations are linear. From ``δ``: ``ω_max = ω_ср·(1 + δ/2)``, ``ω_min = ω_ср·(1 − δ/2)``
    (Khurmi & Gupta, ch. 16: ``C_s = (N₁ − N₂)/N = 2·(N₁ − N₂)/(N₁ + N₂)``).

    >>> speed_limits(mean=100.0, delta=0.04)
    (102.0, 98.0)
    >>> speed_limits(maximum=102.0, delta=0.04)
    (102.0, 98.0)
    """
    if maximum is not None and minimum is not None:
        return maximum, minimum
    if mean is not None and maximum is not None:
        return maximum, 2.0 * mean - maximum
    if mean is not None and minimum is not None:
        return 2.0 * mean - minimum, minimum
    if delta is None:
        # library use only: no CLI input reaches this
        raise ValueError("two of maximum, minimum, mean, delta are needed")
    if mean is not None:
        return mean * (1.0 + delta / 2.0), mean * (1.0 - delta / 2.0)
    if maximum is not None:
        return maximum, maximum * (2.0 - delta) / (2.0 + delta)
    if minimum is not None:
        return minimum * (2.0 + delta) / (2.0 - delta), minimum
    # library use only: no CLI input reaches this
    raise ValueError("a speed is needed besides delta")
