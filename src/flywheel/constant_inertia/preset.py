"""The seed 002 preset of task 2 («Задача 2», ``002_10afb132413d2537.txt``): a constant driving
moment against a triangle or a rectangle of resistance, its peak from the cycle balance.

Defaults are the seed's: M_D = 15 N·m, J = 12 kg·m², ω0 = 200 rad/s; the resistance spans
π/2…3π/2 (triangle) or π/2…π (rectangle).
"""
from __future__ import annotations

import math
from typing import Sequence

from flywheel.constant_inertia.graphs import TWO_PI, constant, rectangle, triangle
from flywheel.constant_inertia.solve import Task2Result, balance, check_positive, solve
from flywheel.errors import InputError, Notice

SEED_DEFAULTS = {"M_D": 15.0, "J": 12.0, "omega0": 200.0}
SEED_SPANS_DEG = {"triangle": (90.0, 270.0), "rectangle": (90.0, 180.0)}


def seed_task(profile: str = "triangle", *, M_D: float = 15.0, J: float = 12.0,
              omega0: float = 200.0, start: float | None = None, end: float | None = None,
              M_C: float | None = None, delta: float | None = None,
              at: Sequence[float] = ()) -> Task2Result:
    """Seed 002 («Задача 2»): constant driving moment ``M_D`` [N·m], resistance a triangle
    (peak in the middle) or a rectangle on [start, end] [rad] (defaults π/2…3π/2 and
    π/2…π); J [kg·m²]; ω0 [rad/s] at φ = 0. Without ``M_C`` its peak comes from the balance
    (60 N·m in both seed tasks); with it the motion need not be steady. ``at`` [rad]: angles
    where ω, ε and t are reported.

    >>> round(seed_task("rectangle").omega_min, 6)   # seed: 199.98
    199.980363
    """
    if profile not in SEED_SPANS_DEG:
        # library use only: no CLI input reaches this
        raise InputError(f"profile must be triangle or rectangle (got {profile!r})")
    d0, d1 = SEED_SPANS_DEG[profile]
    start = math.radians(d0) if start is None else start
    end = math.radians(d1) if end is None else end
    if not start < end:
        a, b = math.degrees(start), math.degrees(end)
        raise InputError(Notice.of(
            "t2_from_below_to", "from ({start:g}°) must be less than to ({end:g}°)", start=a, end=b
        ))
    if start < 0 or end > TWO_PI * (1 + 1e-12):
        raise InputError(Notice.of(
            "from_to_cycle", "from and to must lie within 0…360° (got {start:g}°, {end:g}°)",
            start=math.degrees(start), end=math.degrees(end)))
    check_positive("M_D", M_D, "N·m")
    check_positive("J", J, "kg·m²")
    check_positive("ω0", omega0, "rad/s")
    shape = triangle if profile == "triangle" else rectangle
    drive = constant(M_D)
    unknown = None
    if M_C is None:
        M_C = balance(lambda x: drive, lambda x: shape(x, start, end), "resistance")
        unknown = "resistance"
    else:
        check_positive("M_C", M_C, "N·m")
    return solve(drive, shape(M_C, start, end), J, omega0=omega0, delta=delta,
                 unknown=unknown, at=at)



__all__ = ["SEED_DEFAULTS", "SEED_SPANS_DEG", "seed_task"]
