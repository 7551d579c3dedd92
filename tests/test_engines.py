"""Four-stroke engines (issue 13 items 2–5): indicator diagrams stroke by stroke over a 720°
cycle, firing orders, multi-throw crankshafts, and the bundled engine cases.

Independent truths: the cycle work of a cylinder is the area of its indicator diagram times
the bore area and the stroke, integrated here by scipy/numpy from the case's own tables; the
pressure at an angle is the table at the closed-form slider-crank travel; the in-line four's
reciprocating inertia torque against its closed form; an engine's ΔT_нб as cylinders are added.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case, parse_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError, InputError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[1] / "cases"
STROKES = ("intake", "compression", "expansion", "exhaust")
runner = CliRunner()


def single():
    return read_toml(CASES / "engine_4stroke.toml")


def parsed(data, name="e.toml"):
    return parse_case(data, name)


def diagram_area(cy: dict, method: str = "linear") -> float:
    """∮ (p/p_max) ds of a four-stroke diagram: the strokes away from the head (intake,
    expansion) give the gas work, those towards it (compression, exhaust) take it back.
    Linear tables by numpy's trapezoid rule (exact for a polyline), pchip by scipy."""
    s = np.asarray(cy["s"], float)
    st = cy["strokes"]
    if method == "linear":
        integral = {k: np.trapezoid(np.asarray(st[k], float), s) for k in STROKES}
    else:
        from scipy.interpolate import PchipInterpolator

        integral = {k: float(PchipInterpolator(s, st[k]).integrate(0.0, 1.0)) for k in STROKES}
    return (integral["expansion"] + integral["intake"] - integral["compression"]
            - integral["exhaust"])


# -- item 2: four strokes ---------------------------------------------------------------------

@pytest.mark.parametrize("method", ["linear", "pchip"])
def test_cycle_work_is_the_indicator_diagram_area(method):
    """W = p_max·∮(p/p_max) ds·(πd²/4)·stroke per cylinder and cycle; the engine's constant
    resistance takes exactly that: A_C = −W over the 720° cycle, M_C = −W/4π. Gravity does no
    net work; the stroke of a central slider-crank is 2r."""
    data = single()
    cy = data["cylinders"][0]
    cy["interpolation"] = method
    r = analyze(parsed(data), n_points=7200)
    stroke = 2 * data["crank"]["length"]
    W = cy["p_max"] * diagram_area(cy, method) * math.pi * cy["bore"] ** 2 / 4 * stroke
    assert W > 0                                                   # the gas drives
    assert r.scalars["cycle_work_resistance"] == pytest.approx(-W, rel=2e-6)
    assert r.scalars["balancing_moment"] == pytest.approx(-W / (4 * math.pi), rel=2e-6)
    assert r.scalars["driving_moment"] == pytest.approx(W / (4 * math.pi), rel=2e-6)
    assert r.scalars["balance"] == "resistance" and r.scalars["cycle_deg"] == 720


def test_pressure_stroke_by_stroke_at_the_closed_form_travel():
    """At an angle inside each stroke the pressure is that stroke's table at the travel of the
    centric slider-crank, s = (r + l − x)/(2r), x = r·cos φ + √(l² − r² sin² φ): expansion from
    the firing at 0°, exhaust from 180°, intake from 360°, compression from 540°."""
    data = single()
    cy = data["cylinders"][0]
    r_, l_ = data["crank"]["length"], data["dyads"][0]["rod_length"]
    at = [20.0, 250.0, 400.0, 700.0]
    res = analyze(parsed(data), n_points=720, at_deg=at)
    c = res.cylinders[0]
    for a, name in zip(at, ("expansion", "exhaust", "intake", "compression")):
        phi = math.radians(a)
        x = r_ * math.cos(phi) + math.sqrt(l_ ** 2 - (r_ * math.sin(phi)) ** 2)
        s = (r_ + l_ - x) / (2 * r_)
        want = np.interp(s, cy["s"], cy["strokes"][name]) * cy["p_max"]
        i = res.index_of(phi)
        assert c.p[i] == pytest.approx(want, rel=1e-12), name
        assert c.F[i] == pytest.approx(want * math.pi * cy["bore"] ** 2 / 4, rel=1e-12)
        assert STROKES[c.stroke[i]] == name


def test_firing_in_the_second_revolution_shifts_the_cycle_by_360():
    """fires_at_deg = 360: the same engine, its cycle half a cycle later: the gas moment at φ
    equals the first one's at φ − 360°."""
    a = analyze(parsed(single()), n_points=720)
    data = single()
    data["cylinders"][0]["fires_at_deg"] = 350.0          # the head dead centre nearest: 360°
    b = analyze(parsed(data), n_points=720)
    Ma, Mb = a.M_parts["gas 1"], b.M_parts["gas 1"]
    tol = dict(rtol=1e-9, atol=1e-9 * np.abs(Ma).max())
    assert a.phi.size == 721                                # 1° nodes: 360° is 360 nodes
    assert np.allclose(Mb[360:], Ma[:361], **tol) and np.allclose(Mb[:361], Ma[360:], **tol)
    assert b.cylinders[0].fires_at == pytest.approx(2 * math.pi)
    assert b.scalars["delta_T_max"] == pytest.approx(a.scalars["delta_T_max"], rel=1e-9)


def test_engine_case_runs_end_to_end(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    out = tmp_path / "o"
    assert (out / "plots" / "indicator_1.png").exists()
    rows = (out / "positions.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(rows) == 24 and rows[12].startswith("360° = 3 outer d.c.")


# -- bad input ----------------------------------------------------------------------------------

def _error(data) -> str:
    with pytest.raises(CaseFileError) as e:
        parsed(data)
    msg = str(e.value)
    assert "\n" not in msg
    return msg


def test_a_720_diagram_for_a_360_cycle():
    data = single()
    data["machine"]["cycle_deg"] = 360
    assert _error(data) == (
        "e.toml: cylinders[0].strokes: a four-stroke diagram spans 720° of crank angle, the "
        "machine's cycle is 360° (allowed: machine.cycle_deg = 720, or a multiple of 720)")


def test_strokes_that_do_not_meet():
    data = single()
    data["cylinders"][0]["strokes"]["expansion"][0] = 1.0        # a jump at firing
    msg = _error(data)
    assert msg.startswith("e.toml: cylinders[0].strokes.expansion: begins at p/p_max = 1 at "
                          "s = 0, where compression ends at 0.2639: the strokes do not meet "
                          "(a jump of 0.7361; allowed: at most join_tolerance = 0.02")
    data["cylinders"][0]["join_tolerance"] = 0.8                 # stated: allowed
    parsed(data)
    data = single()
    data["cylinders"][0]["strokes"]["compression"][-1] = 0.1     # intake ends at −0.0022
    assert "cylinders[0].strokes.compression: begins at p/p_max = 0.1 at s = 1, where intake " \
           "ends at -0.0022" in _error(data)


@pytest.mark.parametrize("change, words", [
    (lambda c: c.update(towards_head=[0.0] * 15), "cylinders[0].towards_head: give either "
                                                  "towards_head and away_from_head"),
    (lambda c: c["strokes"].update(exhaust=[0.0] * 3), "cylinders[0].strokes.exhaust: needs 15 "
                                                       "values, one per s (got 3)"),
    (lambda c: c["strokes"].pop("intake"), "cylinders[0].strokes.intake"),
    (lambda c: c.pop("strokes"), "cylinders[0].towards_head: missing"),
    (lambda c: c.update(strokes={**c["strokes"], "compression": [-0.03] * 15}, join_tolerance=1.0),
     "cylinders[0].strokes.compression: p/p_max = -0.03 gives -0.158 MPa gauge, below absolute "
     "vacuum"),
])
def test_bad_strokes(change, words):
    data = single()
    change(data["cylinders"][0])
    assert words in _error(data)


def test_fires_far_from_a_dead_centre():
    data = single()
    data["cylinders"][0]["fires_at_deg"] = 180.0
    with pytest.raises(InputError, match=r"^cylinders\[0\]\.fires_at_deg: 180° is 180° from the "
                                         r"nearest head dead centre of piston 3 \(0°, 360°\)"):
        analyze(parsed(data), n_points=360)
    res = runner.invoke(app, ["check", str(_write(data))])
    assert res.exit_code == 2 and "cylinders[0].fires_at_deg: 180°" in res.output


def _write(data) -> Path:
    import tempfile

    import tomli_w

    path = Path(tempfile.mkdtemp()) / "e.toml"
    path.write_bytes(tomli_w.dumps(data).encode())
    return path
