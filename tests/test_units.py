"""flywheel.units: each constant against an independent definition, and the promise of its
docstring that a conversion through it gives the bits the code computed in place before."""
from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest

from flywheel import units


def test_speed_constants_against_their_definitions():
    # 1 rev/min = 2π rad / 60 s; math.tau is 2π independently of units.TWO_PI
    assert units.RAD_S_PER_RPM == pytest.approx(math.tau / 60, rel=1e-15)
    assert units.RPM_PER_RAD_S == pytest.approx(60 / math.tau, rel=1e-15)
    assert units.RAD_S_PER_RPM * units.RPM_PER_RAD_S == pytest.approx(1.0, rel=1e-15)
    # a textbook value: 1450 rpm (an induction motor) is 151.84 rad/s
    assert 1450 * units.RAD_S_PER_RPM == pytest.approx(151.8436, abs=1e-4)
    assert units.TWO_PI == math.tau
    assert units.SECONDS_PER_MINUTE == 60


def test_angle_constants_are_those_of_math_degrees_and_radians():
    for x in (1.0, 0.5, 3.0, -2.25, 1e-9, 1e9):
        assert x * units.DEG_PER_RAD == math.degrees(x)
        assert x * units.RAD_PER_DEG == math.radians(x)
    assert 180 * units.RAD_PER_DEG == pytest.approx(math.pi, rel=1e-15)


def test_pressure_constant():
    assert units.PA_PER_MPA == Fraction(10) ** 6
    assert 101_325 / units.PA_PER_MPA == 0.101325


def test_the_same_bits_as_the_expressions_they_replaced():
    """The constants are the old literals' floats; n·2π/60 written as n·TWO_PI/60 is the
    same float (doubling is exact), which is why that order was kept at its two sites."""
    assert units.RAD_S_PER_RPM == math.pi / 30
    assert units.RPM_PER_RAD_S == 30 / math.pi
    rng = random.Random(5)
    for _ in range(10_000):
        n = rng.uniform(1.0, 1e5)
        assert n * 2 * math.pi / 60 == n * units.TWO_PI / units.SECONDS_PER_MINUTE


def test_units_is_a_leaf():
    import ast
    from pathlib import Path
    tree = ast.parse(Path(units.__file__).read_text(encoding="utf-8"))
    imported = {a.name for n in ast.walk(tree) if isinstance(n, ast.Import) for a in n.names}
    imported |= {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom)}
    assert imported <= {"math", "__future__"}
