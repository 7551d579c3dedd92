"""The gas work per stroke, exact for piecewise-linear indicator tables (issue 24 item 6).

Independent truth: scipy.integrate.quad of the case's own tables (np.interp between the
breakpoints, which quad is told), times p_max·πd²/4 and the stroke 2r of a central
slider-crank — never through the code under test.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad

from flywheel.cases.run import load_case, parse_case
from flywheel.dynamics.engine import exact_gas_work, table_integral
from flywheel.dynamics.pipeline import analyze
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"


def quad_table(s, p, a=0.0, b=1.0) -> float:
    """∫_a^b of the polyline (s, p) by adaptive quadrature with its breakpoints."""
    inside = [x for x in s if a < x < b]
    return quad(lambda x: np.interp(x, s, p), a, b, points=inside or None, limit=400,
                epsabs=0.0, epsrel=1e-13)[0]


def four_stroke_work(case) -> float:
    """The cycle's gas work [J] of every four-stroke cylinder: (expansion + intake −
    compression − exhaust) areas·p_max·πd²/4·2r."""
    W = 0.0
    for cy in case.cylinders:
        st = cy.stroke_tables()
        area = sum(sign * quad_table(*st[k]) for k, sign in
                   (("expansion", 1), ("intake", 1), ("compression", -1), ("exhaust", -1)))
        W += cy.p_max * math.pi * cy.bore ** 2 / 4 * 2 * case.crank_length * area
    return W


@pytest.mark.parametrize("name", ["engine_4stroke", "engine_inline4"])
def test_engines_cycle_balance_is_the_exact_integral(name):
    """At the default grid the constant resistance is −W/4π to 1e-9 (it was 2.2·10⁻⁶ off with
    the trapezoid rule on the moment); gravity does no net work."""
    case = load_case(CASES / f"{name}.toml")
    r = analyze(case)
    W = four_stroke_work(case)
    assert r.energy.balancing_moment == pytest.approx(-W / (4 * math.pi), rel=1e-9)
    assert r.energy.cycle_work_resistance == pytest.approx(-W, rel=1e-9)


def test_exact_on_a_coarse_grid():
    """The exact work does not depend on the grid: 72 intervals give the same balance."""
    case = load_case(CASES / "engine_4stroke.toml")
    W = four_stroke_work(case)
    assert analyze(case, n_points=72).energy.balancing_moment == pytest.approx(
        -W / (4 * math.pi), rel=1e-9)


def test_two_table_cylinder_linear():
    """A compressor's two tables read linearly: the driving moment balances
    (∫towards − ∫away)·p_max·πd²/4·stroke exactly, on a coarse grid too."""
    data = read_toml(CASES / "compressor.toml")
    for cy in data["cylinders"]:
        cy["interpolation"] = "linear"
    case = parse_case(copy.deepcopy(data), "c.toml")
    r = analyze(case, n_points=90)
    from flywheel.dynamics.grid import slider_frame, standard_positions

    mech = case.mechanism()
    _, dcs = standard_positions(mech)
    W = 0.0
    for cy in case.cylinders:
        _, _, _, head, far = slider_frame(mech, dcs, cy.piston, cy.head, "")
        area = quad_table(cy.s, cy.away_from_head) - quad_table(cy.s, cy.towards_head)
        W += cy.p_max * math.pi * cy.bore ** 2 / 4 * abs(far.x - head.x) * area
    assert r.energy.balancing_moment == pytest.approx(-W / (2 * math.pi), rel=1e-9)


def test_table_integral_against_quad():
    rng = np.random.default_rng(5)
    s = np.concatenate([[0.0], np.sort(rng.uniform(0, 1, 9)), [1.0]])
    p = rng.uniform(-0.1, 1.0, s.size)
    q = np.linspace(0, 1, 37)
    got = table_integral(s, p, q)
    want = [quad_table(s, p, 0.0, x) if x > 0 else 0.0 for x in q]
    assert np.allclose(got, want, rtol=0, atol=1e-13)


def test_exact_gas_work_out_and_back():
    """Out on the first table (p = 1), back on the second (p = 0.5 s): the work is the area
    between, 1 − 0.25, times the scale."""
    s = np.array([0.0, 0.3, 1.0, 0.4, 0.0])
    tables = [(np.array([0.0, 1.0]), np.array([1.0, 1.0])),
              (np.array([0.0, 1.0]), np.array([0.0, 0.5]))]
    A = exact_gas_work(s, np.array([0, 0, 1, 1]), tables, 2.0)
    assert A.tolist() == pytest.approx([0.0, 0.6, 2.0, 2.0 - 2 * 0.25 * (1 - 0.16),
                                        2.0 - 2 * 0.25])
