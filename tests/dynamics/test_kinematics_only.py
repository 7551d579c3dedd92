"""The kinematics alone (issue 24, item 3): a linkage with no masses, loads or flywheel (or
`machine.analysis = "kinematics"`) runs at the constant crank speed ω_m — no refusal for want
of inertia. The true velocities and accelerations are checked against central differences of
the positions alone (not the analogues), the grid's columns likewise."""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case, parse_case
from flywheel.dynamics.kinematics_only import analyze_kinematics
from flywheel.io.toml import read_toml
from flywheel.linkage import solve
from helpers import flywheel_in_process

ROOT = Path(__file__).resolve().parents[2]
BARE = """title = "Four-bar, kinematics only"
[machine]
speed_rpm = 90.0
[crank]
name = "1"
pivot = "O"
tip = "A"
length = 0.1
start_angle_deg = 0.0
[ground]
D = [0.4, 0.0]
[[dyads]]
kind = "RRR"
from = "A"
link_from = "2"
length_from = 0.4
to = "D"
link_to = "3"
length_to = 0.3
joint = "B"
[points]
P = { link = "2", from = "A", to = "B", fraction = 0.5, across = 0.1 }
[output]
at_deg = [0.0, 75.0, 180.0]
"""


def flywheel(*args, cwd):
    """The command line in-process (returncode, stdout, stderr: as subprocess.run's)."""
    return flywheel_in_process(*args, cwd=cwd)


def _by_differences(mech, phi_deg: float, omega: float) -> dict[str, tuple[float, float]]:
    """|v|, |a| of every point at constant ω from its positions alone: central differences
    r′ ≈ (r(φ+h) − r(φ−h))/2h, r″ ≈ (r(φ+h) − 2r(φ) + r(φ−h))/h²."""
    h = 1e-4
    k = solve(mech, np.radians(phi_deg) + np.array([-h, 0.0, h]))
    out = {}
    for name, pm in k.points.items():
        r = pm.r
        out[name] = (float(np.hypot(*(r[2] - r[0]) / (2 * h))) * omega,
                     float(np.hypot(*(r[2] - 2 * r[1] + r[0]) / h**2)) * omega**2)
    return out


def test_a_bare_linkage_runs_at_constant_speed(tmp_path):
    (tmp_path / "k.toml").write_text(BARE, encoding="utf-8")
    res = flywheel("run", "k.toml", "--no-plots", "--out", "o", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    assert res.stderr == ""
    doc = json.loads((tmp_path / "o" / "summary.json").read_text(encoding="utf-8"))["results"]
    w = 90.0 * math.pi / 30
    assert doc["analysis"] == "kinematics" and doc["omega_mean"] == pytest.approx(w, rel=1e-15)
    assert "J_required" not in doc and "delta" not in doc
    mech = load_case(tmp_path / "k.toml").mechanism()
    for a in doc["at"]:
        assert a["omega"] == pytest.approx(w, rel=1e-15) and a["epsilon"] == 0.0
        truth = _by_differences(mech, a["phi_deg"], w)
        for name, p in a["points"].items():
            assert p["v"] == pytest.approx(truth[name][0], rel=1e-7, abs=1e-9)
            assert p["a"] == pytest.approx(truth[name][1], rel=1e-5, abs=1e-6)
    # at φ = 180° by hand (the 3-4-5 triangle A = (−0.1, 0), B = (0.22, 0.24), D = (0.4, 0)):
    # the normals to v_A (the line OA) and to v_B (the line DB) meet at D, the coupler's
    # instantaneous centre: ω_2 = v_A/|DA| = 0.1·ω/0.5, v_B = ω_2·|DB| = 0.06·ω, ω_3 = v_B/|DB|
    at180 = doc["at"][2]
    assert at180["links"]["2"]["omega"] == pytest.approx(0.2 * w, rel=1e-12)
    assert at180["links"]["3"]["omega"] == pytest.approx(0.2 * w, rel=1e-12)
    assert at180["points"]["B"]["v"] == pytest.approx(0.06 * w, rel=1e-12)
    assert doc["output_link"]["link"] == "3"
    with open(tmp_path / "o" / "table.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    row = rows[100]
    assert float(row["v_B [m/s]"]) == pytest.approx(float(row["vq_B [m/rad]"]) * w, rel=1e-11)
    assert float(row["eps_3 [rad/s²]"]) == pytest.approx(float(row["eps_q_3 [1/rad]"]) * w * w,
                                                         rel=1e-11, abs=1e-12)
    assert sorted(p.name for p in (tmp_path / "o").iterdir()) == [
        ".flywheel-manifest.json", "positions.csv", "report.html", "report.md", "summary.json",
        "table.csv"]


def test_analysis_kinematics_on_a_case_with_masses():
    """machine.analysis = "kinematics": the masses and the flywheel are left alone."""
    data = read_toml(ROOT / "cases" / "slotted_link.toml")
    data["machine"]["analysis"] = "kinematics"
    case = parse_case(data, "c.toml")
    assert case.kinematics_only
    res = analyze_kinematics(case, n_points=360, at_deg=[90.0])
    w = case.machine.omega_mean
    truth = _by_differences(case.mechanism(), 90.0, w)
    assert res.at[0].points["E"].v == pytest.approx(truth["E"][0], rel=1e-7)
    assert res.output_link.link == "5"
    plan = res.plans[0]                      # the velocity and acceleration plans at ω_m, ε = 0
    assert np.hypot(*plan.velocity.images["E"]) == pytest.approx(truth["E"][0], rel=1e-7)
    assert np.hypot(*plan.acceleration.images["E"]) == pytest.approx(truth["E"][1], rel=1e-5,
                                                                     abs=1e-5)
    assert "at" in res.to_document()["results"]


def test_the_bundled_cases_still_run_their_dynamics():
    for name in ("fourbar", "compressor", "shaper"):
        assert not load_case(ROOT / "cases" / f"{name}.toml").kinematics_only


def test_transients_are_refused_in_one_line(tmp_path):
    (tmp_path / "k.toml").write_text(BARE, encoding="utf-8")
    res = flywheel("run", "k.toml", "--no-plots", "--transients", "--out", "o", cwd=tmp_path)
    assert res.returncode == 2 and res.stderr.count("\n") == 1
    assert "kinematics alone" in res.stderr and not (tmp_path / "o").exists()


def test_plots_and_russian_report(tmp_path):
    (tmp_path / "k.toml").write_text(BARE, encoding="utf-8")
    res = flywheel("run", "k.toml", "--out", "o", "--lang", "ru", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    assert sorted(p.name for p in (tmp_path / "o" / "plots").iterdir()) == sorted(
        ["acceleration_analogues.png", "positions.png", "scheme.png", "velocity_analogues.png",
         "plan_positions.png"] + [f"plan_{w}_{a}.png" for w in ("velocity", "acceleration")
                                  for a in (0, 75, 180)])
    text = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    assert "# Кинематический анализ" in text and "Выходное звено 3 (коромысло)" in text
    # the formula's symbols under it, from «где» (ГОСТ 7.32-2017, 6.8.2): ω constant here
    assert ("где v_q, a_q — аналоги скорости и ускорения точки, ω — постоянная угловая "
            "скорость кривошипа;  \n") in text


def test_animate_and_a_given_motion_option(tmp_path):
    """--animate draws the linkage as for any linkage case; --motion changes nothing (ε = 0)."""
    (tmp_path / "k.toml").write_text(BARE, encoding="utf-8")
    res = flywheel("run", "k.toml", "--no-plots", "--animate", "--motion", "true", "--out", "o",
                   "--json", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    assert (tmp_path / "o" / "mechanism.gif").stat().st_size > 0
    assert json.loads(res.stdout)["results"]["at"][1]["epsilon"] == 0.0
