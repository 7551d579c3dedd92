"""A given flywheel in `flywheel run` (issue 13 item 5): `[flywheel] J = …` (or mass with
radius_of_gyration, a given disk or rim) instead of machine.delta; the program reports the δ it
gives. And machine.power, the mean power at the mean speed, checked against the cycle balance.

Truths independent of the code: the round trip (the sized J given back gives the sized δ; the
exact J of the energy–mass diagram given back gives the asked δ), and δ recomputed here from the
energy equation ½·(J_I + J_II)·ω² = T0 + A with scipy (cumulative_trapezoid for A, brentq for
the T0 whose (ω_max + ω_min)/2 = ω_m)."""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import parse_case
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
N = 720


def _given(name: str, **flywheel) -> dict:
    data = copy.deepcopy(read_toml(CASES / f"{name}.toml"))
    data["machine"].pop("delta", None)
    data.setdefault("flywheel", {}).update(flywheel)
    return data


def _delta_by_scipy(res) -> float:
    """δ of the motion with J_I = res.motion.J_I from the energy equation, independently."""
    from scipy.integrate import cumulative_trapezoid
    from scipy.optimize import brentq

    phi, J = res.phi, res.motion.J_I + res.reduction.J_II
    A = cumulative_trapezoid(res.energy.M_sum, phi, initial=0.0)
    A = A + sum(W - cumulative_trapezoid(res.loads.M_parts[k], phi, initial=0.0)
                for k, W in res.loads.W_parts.items())         # exact works of switching forces
    w_m = res.sizing.omega_mean

    def mean_gap(T0):
        w = np.sqrt(2 * (T0 + A) / J)
        return 0.5 * (w.max() + w.min()) - w_m

    lo = -A.min() + 1e-9 * (1 + abs(A.min()))
    T0 = brentq(mean_gap, lo, lo + J.max() * (2 * w_m) ** 2 + np.ptp(A), xtol=1e-14, rtol=1e-15)
    w = np.sqrt(2 * (T0 + A) / J)
    return float((w.max() - w.min()) / w_m)


@pytest.mark.parametrize("name", ["compressor", "fourbar", "engine_4stroke", "pump"])
def test_round_trip(name):
    sized_case = parse_case(read_toml(CASES / f"{name}.toml"), name)
    sized = analyze(sized_case, n_points=N)
    s = sized.sizing
    assert s.J_flywheel > 0 and not s.flywheel_given
    i = sized_case.flywheel.speed_ratio
    # the Merzalov flywheel given back: the same motion, so the same δ achieved
    back = analyze(parse_case(_given(name, J=s.J_on_its_shaft), name), n_points=N)
    assert back.sizing.flywheel_given and back.sizing.J_flywheel_given == s.J_on_its_shaft
    assert back.motion.J_I == pytest.approx(sized.motion.J_I, rel=1e-14)
    assert back.motion.delta_achieved == pytest.approx(sized.motion.delta_achieved, rel=1e-12)
    assert back.sizing.delta == back.motion.delta_achieved
    # the exact flywheel (energy–mass diagram) given back: exactly the asked δ
    exact = analyze(parse_case(_given(name, J=s.J_flywheel_exact / i ** 2), name), n_points=N)
    assert exact.motion.delta_achieved == pytest.approx(sized_case.machine.delta, rel=1e-9)
    # … and the diagram of the δ it gives comes back to its J_I
    assert exact.sizing.J_required_exact == pytest.approx(exact.motion.J_I, rel=1e-9)
    # δ of the given flywheel against the energy equation solved here with scipy
    assert back.motion.delta_achieved == pytest.approx(_delta_by_scipy(back), rel=1e-9)
    doc = back.to_document()["results"]
    assert doc["flywheel_given"] is True and doc["delta"] == doc["delta_achieved"]
    eps = back.motion.epsilon
    assert doc["epsilon_max"] == eps.max() and doc["epsilon_min"] == eps.min()
    assert doc["phi_epsilon_max_deg"] == pytest.approx(math.degrees(back.phi[eps.argmax()]))


def test_given_forms_agree():
    J = 4.0
    by_J = analyze(parse_case(_given("compressor", J=J), "c"), n_points=360)
    by_mk = analyze(parse_case(_given("compressor", mass=100.0, radius_of_gyration=0.2), "c"),
                    n_points=360)
    assert by_mk.sizing.J_flywheel_given == pytest.approx(100.0 * 0.04, rel=1e-15)
    assert by_mk.motion.delta_achieved == pytest.approx(by_J.motion.delta_achieved, rel=1e-12)
    # a disk of steel (ρ = 7800) with J = π·ρ·b·D⁴/32, and a rim with π·ρ·b·(D⁴ − D1⁴)/32
    D, b = 0.5, 0.1
    disk = parse_case(_given("compressor", given_disk={"D": D, "b": b}), "c")
    assert disk.flywheel.given_J == pytest.approx(math.pi * 7800 * b * D ** 4 / 32, rel=1e-15)
    rim = parse_case(_given("compressor", given_rim={"D": D, "D_inner": 0.4, "b": b}), "c")
    assert rim.flywheel.given_J == pytest.approx(math.pi * 7800 * b * (D ** 4 - 0.4 ** 4) / 32,
                                                 rel=1e-15)
    # a bigger flywheel gives a smaller δ, nearly in inverse proportion to J_I
    big = analyze(parse_case(_given("compressor", J=2 * J), "c"), n_points=360)
    ratio = by_J.motion.delta_achieved / big.motion.delta_achieved
    assert ratio == pytest.approx(big.motion.J_I / by_J.motion.J_I, rel=0.02)


def test_the_bundled_given_case():
    res = analyze(parse_case(read_toml(CASES / "compressor_given_flywheel.toml"), "c"))
    doc = res.to_document()
    r = doc["results"]
    assert r["flywheel_given"] and r["J_flywheel_given"] == 4.0 and r["J_flywheel"] == 4.0
    assert 0.049 < r["delta"] < 0.05
    assert [a["phi_deg"] for a in r["at"]] == [0.0, 120.0, 224.2]
    assert r["power"] == 12400.0 and r["power_moment"] == pytest.approx(12400.0 / (20 * math.pi))
    assert r["power_from_loads"] == pytest.approx(r["driving_moment"] * 20 * math.pi, rel=1e-12)
    assert not any("machine.power" in w for w in doc["warnings"])


def test_power_checked_against_the_balance():
    data = _given("compressor", J=4.0)
    data["machine"]["power"] = 20000.0
    res = analyze(parse_case(data, "c"), n_points=360)
    assert any(w.startswith("machine.power: P = 20000 W") for w in res.warnings)
    # an engine: the power is the resistance's, −M_C·ω_m
    eng = copy.deepcopy(read_toml(CASES / "engine_4stroke.toml"))
    sized = analyze(parse_case(eng, "e"), n_points=360)
    P = -sized.energy.balancing_moment * sized.sizing.omega_mean
    eng["machine"]["power"] = P
    res = analyze(parse_case(eng, "e"), n_points=360)
    assert res.energy.power_from_loads == pytest.approx(P, rel=1e-12)
    assert not any("machine.power" in w for w in res.warnings)


@pytest.mark.parametrize("edit, fragment", [
    (lambda d: d["flywheel"].update(J=4.0), "machine.delta: give exactly one"),
    (lambda d: d["machine"].pop("delta"), "machine.delta: missing"),
    (lambda d: (d["machine"].pop("delta"), d["flywheel"].update(J=-1.0)), "flywheel.J"),
    (lambda d: (d["machine"].pop("delta"), d["flywheel"].update(mass=10.0)),
     "flywheel.radius_of_gyration: missing"),
    (lambda d: (d["machine"].pop("delta"), d["flywheel"].update(J=1.0, mass=1.0,
                                                                 radius_of_gyration=1.0)),
     "flywheel.mass: a given flywheel is one of"),
    (lambda d: (d["machine"].pop("delta"),
                d["flywheel"].update(given_rim={"D": 0.4, "D_inner": 0.5, "b": 0.1})),
     "flywheel.given_rim.D_inner"),
])
def test_bad_given_flywheels(edit, fragment):
    data = copy.deepcopy(read_toml(CASES / "compressor.toml"))
    edit(data)
    with pytest.raises(CaseFileError, match=fragment.replace(".", r"\.")):
        parse_case(data, "c.toml")
