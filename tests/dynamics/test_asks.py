"""Textbook asks (issue 24 item 7): --snapshot, [output] snapshots, --at-travel, --roots.

Independent truths: ε = (M_Σ − ½·J′·ω²)/J by hand with J_II and dJ_II/dφ summed here from the
linkage's analogues; the central slider-crank's piston travel from its top dead centre,
x = r(1 − cos ψ) + l(1 − √(1 − λ² sin² ψ)); the zeros of its acceleration analogue,
d²x/dψ² = 0 of that exact x (by scipy's brentq).
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
from flywheel.dynamics.asks import travel_angles, with_asks
from flywheel.dynamics.pipeline import analyze
from flywheel.io.toml import read_toml
from flywheel.linkage import solve

CASES = Path(__file__).resolve().parents[2] / "cases"
R, L = 0.04, 0.16
runner = CliRunner()


def inertia(case, phi_deg):
    kin = solve(case.mechanism(), np.array([math.radians(phi_deg)]))
    J = dJ = 0.0
    for name, lk in case.links.items():
        p, w = kin.points[lk.centroid], kin.links[name]
        v, a = p.v_q[0], p.a_q[0]
        J += lk.mass * (v @ v) + lk.J_S * w.omega_q[0] ** 2
        dJ += 2 * (lk.mass * (v @ a) + lk.J_S * w.omega_q[0] * w.eps_q[0])
    return J, dJ


@pytest.fixture(scope="module")
def engine():
    d = read_toml(CASES / "engine_4stroke.toml")
    d["output"]["snapshots"] = [[30.0, 1500.0], [390.0, 0.0]]
    case = parse_case(d, "e.toml")
    return case, analyze(case)


def test_snapshots_by_hand(engine):
    case, r = engine
    for s, (phi_deg, rpm) in zip(r.snapshots, [(30.0, 1500.0), (390.0, 0.0)]):
        J_II, dJ = inertia(case, phi_deg)
        J = r.motion.J_I + J_II
        M = float(r.energy.M_sum[r.at_index(phi_deg)])
        w = rpm * math.pi / 30
        assert s.J == pytest.approx(J, rel=1e-12) and s.dJ == pytest.approx(dJ, rel=1e-9)
        assert s.epsilon == pytest.approx((M - 0.5 * dJ * w * w) / J, rel=1e-9)
    assert r.to_document()["results"]["snapshots"][0]["phi_deg"] == 30.0


def test_snapshot_option_adds_to_the_case(engine):
    case, r = engine
    r2 = with_asks(r, case, ["60:3000"])
    assert [s.phi_deg for s in r2.snapshots] == [30.0, 390.0, 60.0]
    assert r2.snapshots[-1].rpm == 3000.0


def test_at_travel_closed_form():
    case = load_case(CASES / "engine_4stroke.toml")
    (t,) = travel_angles(case, ["B:0.02"])
    assert len(t.phi_deg) == 4                   # twice per revolution, two revolutions
    lam = R / L
    for a in t.phi_deg:
        psi = math.radians(a)
        x = R * (1 - math.cos(psi)) + L * (1 - math.sqrt(1 - (lam * math.sin(psi)) ** 2))
        assert x == pytest.approx(0.02, abs=1e-12)
    assert t.phi_deg[0] + t.phi_deg[1] == pytest.approx(360.0, abs=1e-9)   # symmetric


def test_roots_of_the_piston_acceleration(engine):
    case, r = engine
    (roots,) = with_asks(r, case, roots=["aqy_B [m/rad²]"]).roots
    from scipy.optimize import brentq

    lam = R / L

    def x2(psi):          # d²x/dψ² / r of the exact travel
        s, c = math.sin(psi), math.cos(psi)
        D = math.sqrt(1 - (lam * s) ** 2)
        return c + lam * ((c * c - s * s) / D + lam ** 2 * s * s * c * c / D ** 3)
    psi = math.degrees(brentq(x2, 0.1, math.pi / 2, xtol=1e-14))
    want = [psi, 360 - psi, 360 + psi, 720 - psi]
    assert roots.column == "aqy_B"
    assert np.allclose(roots.phi_deg, want, atol=1e-3)


def test_cli_options_and_summary(tmp_path):
    out = tmp_path / "o"
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--out", str(out),
                              "--no-plots", "--report", "md", "--snapshot", "30:3000",
                              "--at-travel", "B:0.02", "--roots", "M_sum", "--json"])
    assert res.exit_code == 0, res.output
    import json
    doc = json.loads((out / "summary.json").read_text(encoding="utf-8"))["results"]
    angles = doc["at_travel"][0]["phi_deg"]
    assert [a["phi_deg"] for a in doc["at"]][2:] == angles       # report angles added
    assert doc["snapshots"][0]["rpm"] == 3000.0 and doc["roots"][0]["column"] == "M_sum"


@pytest.mark.parametrize("args, fragment", [
    (["--snapshot", "30"], "--snapshot: '30' is not PHI_DEG:RPM"),
    (["--snapshot", "30:fast"], "--snapshot: 'fast' is not a number"),
    (["--at-travel", "C:0.01"], "--at-travel: 'C' is not the point of a slider"),
    (["--at-travel", "B:0.5"], "--at-travel: '0.5' is not a number within 0 … 0.08"),
    (["--roots", "nope"], "--roots: 'nope' is not a column of table.csv"),
])
def test_bad_asks_one_line(tmp_path, args, fragment):
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--out",
                              str(tmp_path / "o"), "--no-plots", *args])
    assert res.exit_code == 2
    lines = [ln for ln in res.output.splitlines() if ln.strip()]
    assert len(lines) == 1 and fragment in lines[0], res.output
    assert not (tmp_path / "o").exists()
