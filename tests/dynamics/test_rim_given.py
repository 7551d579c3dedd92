"""[flywheel.rim] with a given mean diameter and a thickness proportioned to the radius, and the
rim's cross-section area (issue 24 item 7).

Hand calculation (Khurmi & Gupta, «Theory of Machines», ch. 16): v = ω·D/2, σ = ρ·v²,
m = share·J/R², t = (t/R)·R, b = m/(ρ·π·D·t), A = b·t.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest

from flywheel.cases.run import parse_case
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError, InputError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"


def compressor(rim: dict):
    d = read_toml(CASES / "compressor.toml")
    d["flywheel"]["rim"] = rim
    return parse_case(d, "c.toml")


def test_given_diameter_and_thickness_ratio_by_hand():
    r = analyze(compressor({"diameter": 0.8, "thickness_to_radius": 0.2, "share": 0.9}))
    rim, s = r.sizing.rim_design, r.sizing
    J, w, rho = s.J_on_its_shaft, s.omega_mean * s.speed_ratio, s.material_density
    R = 0.4
    m = 0.9 * J / R ** 2
    t = 0.2 * R
    b = m / (rho * math.pi * 0.8 * t)
    assert rim.D_mean == 0.8 and rim.rim_speed == pytest.approx(w * R, rel=1e-12)
    assert rim.stress == pytest.approx(rho * (w * R) ** 2, rel=1e-12)
    assert rim.mass == pytest.approx(m, rel=1e-12) and rim.thickness == pytest.approx(t, rel=1e-12)
    assert rim.width == pytest.approx(b, rel=1e-12)
    assert rim.area == pytest.approx(b * t, rel=1e-12)
    doc = r.to_document()["results"]["flywheel_rim"]
    assert doc["area"] == pytest.approx(b * t, rel=1e-12) and doc["D_mean"] == 0.8


def test_area_of_the_default_rim():
    r = analyze(compressor({}))
    rim = r.sizing.rim_design
    assert rim.area == pytest.approx(rim.width * rim.thickness, rel=1e-15)
    assert rim.mass == pytest.approx(rim.density * math.pi * rim.D_mean * rim.area, rel=1e-12)


def test_too_large_a_diameter_is_one_line():
    with pytest.raises(InputError) as exc:
        analyze(compressor({"diameter": 50.0}))
    msg = str(exc.value)
    assert "flywheel.rim.diameter: 50 m turns at" in msg and "\n" not in msg


@pytest.mark.parametrize("rim, fragment", [
    ({"diameter": 0.8, "speed": 20.0}, "flywheel.rim.diameter: give diameter or speed"),
    ({"thickness_to_radius": 0.2, "width": 0.1}, "flywheel.rim.thickness_to_radius: give"),
    ({"thickness_to_radius": 2.0}, "flywheel.rim.thickness_to_radius"),
])
def test_conflicts_one_line(rim, fragment):
    with pytest.raises(CaseFileError) as exc:
        compressor(rim)
    assert fragment in str(exc.value)


def test_task2_rim_of_a_given_diameter():
    from flywheel.cases.task2 import load_task2_case, solve_case

    d = read_toml(CASES / "task2_khurmi_16_16_rim.toml")
    d["flywheel"]["rim"] = {k: v for k, v in d["flywheel"]["rim"].items() if k != "speed"}
    d["flywheel"]["rim"]["diameter"] = 0.8
    import tomli_w, tempfile, os
    with tempfile.TemporaryDirectory() as tmp:
        p = os.path.join(tmp, "t.toml")
        with open(p, "wb") as f:
            tomli_w.dump(d, f)
        res = solve_case(load_task2_case(p))
    assert res.rim.D_mean == 0.8
    assert res.rim.rim_speed == pytest.approx(res.omega_mean * 0.4, rel=1e-12)
