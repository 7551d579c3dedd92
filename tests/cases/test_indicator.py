"""Measured indicator diagrams (issue 24 item 6): a cylinder's pressure as a trace against the
crank angle over the cycle, or as a loop against volume or travel, from a CSV file or inline.

Independent truths: a trace sampled from engine_4stroke's own tables at the crank angles of the
tables' breakpoints (found here by the closed-form slider-crank travel and scipy's brentq) is
the same polyline in s, so the engine's numbers are those of the table case; a loop in volume
and absolute pressure is the same; the gas work of the bundled measured case against
scipy.integrate.quad of its diagram.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from flywheel.cases.run import load_case, parse_case
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
R, L = 0.04, 0.16                       # engine_4stroke: crank, rod [m]
ORDER = (("expansion", 0, +1), ("exhaust", 1, -1), ("intake", 2, +1), ("compression", 3, -1))


def travel(a: float) -> float:
    """s of the central slider-crank at a crank angle a [rad] after its top dead centre."""
    return (R + L - (R * math.cos(a) + math.sqrt(L * L - (R * math.sin(a)) ** 2))) / (2 * R)


def angle_of(s: float, k: int) -> float:
    """The angle ψ [rad] after the firing dead centre in stroke k (0 … 3) where the travel is s."""
    if s in (0.0, 1.0):
        return k * math.pi + (math.pi if (s == 1.0) == (k % 2 == 0) else 0.0)
    a = brentq(lambda x: travel(x) - s, 0.0, math.pi, xtol=1e-15, rtol=1e-15)
    return k * math.pi + (a if k % 2 == 0 else math.pi - a)


def loop_points(data):
    """(ψ [rad], s, p/p_max) of engine_4stroke's diagram in cycle order, each dead centre once."""
    cy = data["cylinders"][0]
    out = []
    for name, k, way in ORDER:
        pts = list(zip(cy["s"], cy["strokes"][name]))
        pts = pts if way > 0 else pts[::-1]
        for j, (s, p) in enumerate(pts):
            if j == 0 and out:
                continue
            out.append((angle_of(s, k), s, p))
    return out[:-1]                      # the closing point is the first


def measured(data, indicator: dict, file=None, p_max=True):
    d = copy.deepcopy(data)
    cy = d["cylinders"][0]
    p = cy["p_max"]
    for k in ("s", "strokes", "p_max"):
        del cy[k]
    if p_max:
        cy["p_max"] = p
    cy["indicator"] = indicator
    if file is not None:
        cy["indicator_file"] = file
    return d


@pytest.fixture(scope="module")
def engine():
    data = read_toml(CASES / "engine_4stroke.toml")
    return data, analyze(parse_case(copy.deepcopy(data), "e.toml"), n_points=720)


def same(a, b):
    assert b.energy.balancing_moment == pytest.approx(a.energy.balancing_moment, rel=1e-9)
    assert b.energy.delta_T_max == pytest.approx(a.energy.delta_T_max, rel=1e-9)
    assert np.allclose(b.cylinders[0].p, a.cylinders[0].p, rtol=0, atol=1e-9 * a.cylinders[0].p_max)


def test_crank_angle_trace_at_the_breakpoints_is_the_table(engine, tmp_path):
    """In degrees, MPa, gauge, from a CSV file (semicolons and decimal commas, as a Russian
    Excel writes), the firing dead centre at 100° of the file."""
    data, ref = engine
    p_max = data["cylinders"][0]["p_max"]
    rows = [(math.degrees(a) + 100.0, p * p_max / 1e6) for a, _, p in loop_points(data)]
    text = "# bench\nугол;давление\n" + "".join(
        f"{a!r};{p!r}\n".replace(".", ",") for a, p in rows)
    (tmp_path / "trace.csv").write_text(text, encoding="cp1251")
    case = tmp_path / "e.toml"
    import tomli_w
    case.write_text(tomli_w.dumps(measured(data, {
        "against": "crank_angle", "columns": ["угол", "давление"], "x_unit": "deg",
        "p_unit": "MPa", "tdc_offset_deg": 100.0}, file="trace.csv")), encoding="utf-8")
    same(ref, analyze(load_case(case), n_points=720))


def test_volume_loop_inline_absolute(engine):
    """A loop against the volume [cm³] with absolute pressures [bar], p_max from the trace."""
    data, ref = engine
    cy = data["cylinders"][0]
    Vd = math.pi * cy["bore"] ** 2 / 4 * 2 * R * 1e6
    pts = loop_points(data) + [loop_points(data)[0]]
    ind = {"against": "volume", "x_unit": "cm3", "p_unit": "bar", "pressure": "absolute",
           "x": [Vd / 7 + Vd * s for _, s, _ in pts],
           "p": [(p * cy["p_max"] + 101325.0) / 1e5 for _, _, p in pts]}
    case = parse_case(measured(data, ind, p_max=False), "e.toml")
    assert case.cylinders[0].p_max == pytest.approx(cy["p_max"], rel=1e-12)
    same(ref, analyze(case, n_points=720))


def test_bundled_measured_case_work_is_the_diagram_area():
    """cases/engine_measured.toml: the constant resistance is −W/4π with W the quad of its
    converted diagram, stroke by stroke."""
    case = load_case(CASES / "engine_measured.toml")
    cy = case.cylinders[0]
    st = cy.stroke_tables()

    def area(k):
        s, p = st[k]
        return quad(lambda x: np.interp(x, s, p), 0, 1, points=s[1:-1], limit=1000,
                    epsabs=0, epsrel=1e-13)[0]
    W = cy.p_max * math.pi * cy.bore ** 2 / 4 * 2 * R * (
        area("expansion") + area("intake") - area("compression") - area("exhaust"))
    assert analyze(case).energy.balancing_moment == pytest.approx(-W / (4 * math.pi), rel=1e-9)
    ref = analyze(load_case(CASES / "engine_4stroke.toml"))
    # the same engine sampled every 2°: within 0.1 % of the table case
    assert analyze(case).energy.balancing_moment == pytest.approx(ref.energy.balancing_moment,
                                                                   rel=1e-3)


def test_two_stroke_travel_loop_is_the_two_tables():
    """A compressor's two tables (read linearly) as one loop against the travel in mm."""
    data = read_toml(CASES / "compressor.toml")
    for c in data["cylinders"]:
        c["interpolation"] = "linear"
    ref = analyze(parse_case(copy.deepcopy(data), "c.toml"), n_points=360)
    d = copy.deepcopy(data)
    c = d["cylinders"][0]
    s, up, down = c.pop("s"), c.pop("towards_head"), c.pop("away_from_head")
    xs = [v * 100.0 for v in s] + [v * 100.0 for v in s[::-1][1:]]
    ps = list(down) + list(up[::-1][1:])
    c["indicator"] = {"against": "travel", "cycle": "two-stroke", "x_unit": "mm",
                      "p_unit": "Pa", "x": xs, "p": [v * c["p_max"] for v in ps]}
    got = analyze(parse_case(d, "c.toml"), n_points=360)
    assert got.energy.balancing_moment == pytest.approx(ref.energy.balancing_moment, rel=1e-9)


@pytest.mark.parametrize("edit, fragments", [
    ({"x_unit": "cm3"}, ["indicator.x_unit", "not a unit of crank_angle"]),
    ({"x": [0.0, 10.0, 20.0], "p": [1.0, 2.0, 1.0]}, ["indicator.x", "gap of"]),
    ({"columns": ["a", "b"]}, ["indicator.columns", "indicator_file"]),
    ({"x": None}, ["indicator.x", "missing"]),
])
def test_bad_traces_one_line(engine, edit, fragments):
    data, _ = engine
    ind = {"against": "crank_angle", "x_unit": "deg", "p_unit": "MPa",
           "x": [float(a) for a in range(0, 720, 10)], "p": [1.0] * 72}
    ind.update(edit)
    ind = {k: v for k, v in ind.items() if v is not None}
    with pytest.raises(CaseFileError) as exc:
        parse_case(measured(data, ind), "e.toml")
    msg = str(exc.value)
    assert "\n" not in msg and all(f in msg for f in fragments), msg


def test_bad_file_one_line(engine, tmp_path):
    data, _ = engine
    (tmp_path / "t.csv").write_text("phi,p\n0,1\n10,x1\n", encoding="utf-8")
    ind = {"against": "crank_angle", "x_unit": "deg", "p_unit": "bar"}
    with pytest.raises(CaseFileError) as exc:
        parse_case(measured(data, ind, file=str(tmp_path / "t.csv")), str(tmp_path / "e.toml"))
    assert "line 3, column p: 'x1' is not a finite number" in str(exc.value)
