"""The flywheel's rim designed as engineers finish it ([flywheel.rim], issue 14 item 3), in `run`
and in `task2`.

Truths independent of the code: the hoop stress of a thin rotating ring σ = ρ·v²; the thin-ring
identity mass·R² = share·J; the mass of a rectangular annulus ρ·π·(D_o² − D_i²)/4·b; its moment
of inertia ½·m·(R_o² + R_i²) against the thin ring's; the worked Example 16.16 of R.S. Khurmi &
J.K. Gupta, *Theory of Machines*, ch. 16, computed here step by step as the book does.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest

from flywheel.cases.run import load_case, parse_case
from flywheel.cases.task2 import load_task2_case, parse_task2_case, solve_case
from flywheel.dynamics.pipeline import analyze
from flywheel.dynamics.sizing import design_rim
from flywheel.errors import CaseFileError, InputError
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
PI = math.pi


def test_khurmi_16_16_rim():
    # Khurmi & Gupta, Theory of Machines, ch. 16, Example 16.16 (FOSSEE companion, p. 595): a
    # multi-cylinder engine at 600 rpm, areas +160, −172, +168, −191, +197, −162 mm² at
    # 1 mm = 250 N·m and 1 mm = 3°, speed within ±1 %; cast-iron rim, b = 2·t, ρ = 7250 kg/m³,
    # σ = 6 MPa, the rim gives 92 % of the flywheel effect.
    # Printed: I = 32.7 kg·m², t = 58.6 mm, b = 117.2 mm.
    r = solve_case(load_task2_case(CASES / "task2_khurmi_16_16_rim.toml"), "16.16")
    c = 250 * PI / 60                                 # J per mm² of the diagram
    sums = [0, 160, -12, 156, -35, 162, 0]            # the energy at the crossings [mm²]
    dE = (max(sums) - min(sums)) * c                  # 197 mm²
    w, Cs = 2 * PI * 600 / 60, 0.02
    I = dE / (w ** 2 * Cs)
    v = math.sqrt(6e6 / 7250)                          # σ = ρ·v²
    D = v * 60 / (PI * 600)                            # v = π·D·N/60
    m = 0.92 * dE / (v ** 2 * Cs)                      # ΔE_rim = m·v²·C_s
    t = math.sqrt(m / (PI * D * 2 * 7250))             # m = ρ·π·D·b·t, b = 2t
    assert r.J == pytest.approx(I, rel=1e-13) and round(I, 1) == 32.7
    rim = r.rim
    assert rim.D_mean == pytest.approx(D, rel=1e-14)
    assert rim.mass == pytest.approx(m, rel=1e-13)
    assert rim.thickness == pytest.approx(t, rel=1e-13) and round(t * 1000, 1) == 58.6
    assert rim.width == pytest.approx(2 * t, rel=1e-13) and round(2 * t * 1000, 1) == 117.2
    assert rim.stress == pytest.approx(6e6, rel=1e-14) and rim.share == 0.92
    doc = r.to_document()["flywheel_rim"]
    for key in ("D_mean", "thickness", "width", "mass", "rim_speed", "stress", "share"):
        assert key in doc
    # its stress at ω_max = ω_m·(1 + δ/2)
    assert rim.stress_at_omega_max == pytest.approx(6e6 * 1.01 ** 2, rel=1e-12)


def _compressor(rim: dict, **flywheel) -> dict:
    data = copy.deepcopy(read_toml(CASES / "compressor.toml"))
    data["flywheel"].update(flywheel)
    data["flywheel"]["rim"] = rim
    return data


@pytest.mark.parametrize("rim, extra", [
    ({}, {}),
    ({"share": 0.85, "width_to_thickness": 4.0}, {}),
    ({"speed": 30.0, "width": 0.12}, {"speed_ratio": 2.0}),
    ({"share": 1.0}, {"material": "cast-iron", "density": None}),
])
def test_run_rim_identities(rim, extra):
    fw = {k: v for k, v in extra.items() if v is not None}
    data = _compressor(rim, **fw)
    if extra.get("density", 1) is None:
        del data["flywheel"]["density"]
    case = parse_case(data, "c.toml")
    res = analyze(case, n_points=360)
    s = res.to_document()["results"]
    d = s["flywheel_rim"]
    rho, sigma = case.flywheel.rho, case.flywheel.sigma
    J = res.sizing.J_on_its_shaft
    share = rim.get("share", 0.9)
    assert s["flywheel_rim_share"] == share == d["share"]
    # thin ring: σ = ρ·v², v = ω·i·D_mean/2, mass·R² = share·J
    assert d["stress"] == pytest.approx(rho * d["rim_speed"] ** 2, rel=1e-14)
    assert d["rim_speed"] == pytest.approx(rim.get("speed", math.sqrt(sigma / rho)), rel=1e-14)
    assert d["D_mean"] == pytest.approx(2 * d["rim_speed"] / (case.machine.omega_mean
                                                              * case.flywheel.speed_ratio), rel=1e-14)
    assert d["mass"] * (d["D_mean"] / 2) ** 2 == pytest.approx(share * J, rel=1e-13)
    # the mass is the annulus's exactly; its J as a thick annulus exceeds the thin ring's by (t/D)²
    area = PI * (d["D"] ** 2 - d["D_inner"] ** 2) / 4
    assert d["mass"] == pytest.approx(rho * area * d["width"], rel=1e-12)
    J_thick = 0.5 * d["mass"] * ((d["D"] / 2) ** 2 + (d["D_inner"] / 2) ** 2)
    assert d["J_rim_exact"] == pytest.approx(J_thick, rel=1e-13)
    assert J_thick / (share * J) - 1 == pytest.approx((d["thickness"] / d["D_mean"]) ** 2, rel=1e-9)
    if "width" in rim:
        assert d["width"] == rim["width"]
    else:
        assert d["width"] / d["thickness"] == pytest.approx(rim.get("width_to_thickness", 2.0),
                                                            rel=1e-14)
    assert d["stress_at_omega_max"] == pytest.approx(
        rho * (res.motion.omega_max * case.flywheel.speed_ratio * d["D_mean"] / 2) ** 2, rel=1e-14)


def test_without_the_rim_design_the_outputs_keep_their_keys():
    s = analyze(load_case(CASES / "compressor.toml"), n_points=360).to_document()["results"]
    assert list(s["flywheel_rim"]) == ["D", "D_inner", "b", "mass", "rim_speed"]
    assert s["flywheel_rim_share"] == 1.0


def test_bad_rims():
    with pytest.raises(CaseFileError, match=r"flywheel\.rim\.speed: .*at most √\(σ/ρ\) = 50\.637"):
        parse_case(_compressor({"speed": 51.0}), "c.toml")
    parse_case(_compressor({"speed": 50.6}), "c.toml")            # just under the limit
    for share in (0.0, -0.1, 1.0000001):
        with pytest.raises(CaseFileError, match=r"flywheel\.rim\.share"):
            parse_case(_compressor({"share": share}), "c.toml")
    with pytest.raises(InputError, match="no hole"):
        design_rim(1e6, 10.0, 7800.0, 20e6, width=1e-3)
    doc = read_toml(CASES / "task2_khurmi_16_16_rim.toml")
    doc["flywheel"]["rim"]["speed"] = 28.8                           # √(6e6/7250) = 28.77
    with pytest.raises(CaseFileError, match=r"flywheel\.rim\.speed: .*28\.7678"):
        parse_task2_case(doc, "k.toml")


def test_khurmi_16_14_rim_of_the_fluctuation():
    # Khurmi & Gupta, Example 16.14 (FOSSEE companion, p. 592): an engine at 800 rpm, speed
    # within ±2 % (C_s = 0.04), ΔE = (420 − (−30)) mm² at 1 mm² = 500·π/30 N·m; cast-iron rim,
    # σ = 7 MPa, ρ = 7200 kg/m³, width = 5 × thickness, the whole flywheel effect in the rim.
    # Printed: D = 0.744 m, t = 84 mm, b = 424 mm (the companion prints t and b with %d).
    dE = 450 * 500 * PI / 30
    w, Cs = 2 * PI * 800 / 60, 0.04
    rim = design_rim(dE / (w ** 2 * Cs), w, 7200.0, 7e6, share=1.0, width_to_thickness=5.0)
    v = math.sqrt(7e6 / 7200)
    D = v * 60 / (PI * 800)
    m = dE / (v ** 2 * Cs)
    t = math.sqrt(m / (PI * D * 5 * 7200))
    assert rim.D_mean == pytest.approx(D, rel=1e-14) and round(D, 3) == 0.744
    assert rim.mass == pytest.approx(m, rel=1e-13)
    assert rim.thickness == pytest.approx(t, rel=1e-13) and math.floor(t * 1000) == 84
    assert rim.width == pytest.approx(5 * t, rel=1e-13) and math.floor(5 * t * 1000) == 424


@pytest.mark.parametrize("rim", [{}, {"width": 0.05}])
def test_a_hoop_thin_rim_is_warned_with_the_speed_that_makes_it_a_rim(rim):
    """The press (n = 1 rev/s) with the default rim speed √(σ/ρ): a rim 2 mm thick on 6.9 m
    (t/D ≈ 3e-4) is warned about; the hint's rim speed, given back, gives t/D = 0.05 exactly
    (design_rim's own scaling t/D ∝ D^(−5/2) for b = ratio·t, ∝ D⁻⁴ for a given width)."""
    from flywheel.dynamics.sizing import THIN_RIM_AIM, rim_speed_for_thickness

    data = read_toml(CASES / "press.toml")
    data.setdefault("flywheel", {})["rim"] = dict(rim)
    res = analyze(parse_case(data, "c.toml"), n_points=360)
    d = res.sizing.rim_design
    assert d.thickness / d.D_mean < 0.01
    (w,) = [w for w in res.warnings if getattr(w, "code", "") == "rim_thin"]
    v_aim = rim_speed_for_thickness(d)
    assert f"about {v_aim:.3g} m/s gives t/D = 0.05" in w
    data["flywheel"]["rim"] = dict(rim, speed=v_aim)
    again = analyze(parse_case(data, "c.toml"), n_points=360)
    d2 = again.sizing.rim_design
    assert d2.thickness / d2.D_mean == pytest.approx(THIN_RIM_AIM, rel=1e-12)
    assert not [w for w in again.warnings if getattr(w, "code", "") == "rim_thin"]
    # the in-line four's rim (t/D ≈ 0.031 at 3000 rpm) is a rim: no warning
    data = read_toml(CASES / "engine_inline4.toml")
    data["flywheel"]["rim"] = {}
    ok = analyze(parse_case(data, "c.toml"), n_points=720)
    assert 0.01 < ok.sizing.rim_design.thickness / ok.sizing.rim_design.D_mean
    assert not [w for w in ok.warnings if getattr(w, "code", "") == "rim_thin"]


def test_a_hoop_of_a_given_thickness_to_radius_is_told_the_ratio_not_a_speed():
    """thickness_to_radius given: t = (t/R)·R, so t/D_mean = (t/R)/2 whatever the rim speed or
    the diameter, and the warning's advice is t/R = 2·0.05 = 0.1, not a rim speed (which
    would change nothing). Given back, t/R = 0.1 gives t/D = 0.05 and no warning."""
    from flywheel.render.nomenclature import message

    data = read_toml(CASES / "press.toml")
    data.setdefault("flywheel", {})["rim"] = {"thickness_to_radius": 0.01}
    res = analyze(parse_case(data, "c.toml"), n_points=360)
    d = res.sizing.rim_design
    assert d.thickness / d.D_mean == pytest.approx(0.005, rel=1e-12)
    (w,) = [w for w in res.warnings if getattr(w, "code", "").startswith("rim_thin")]
    assert w.code == "rim_thin_ratio"
    assert "thickness_to_radius = 0.01 sets t/D = 0.005" in w
    assert "give flywheel.rim.thickness_to_radius about 0.1 (t/D = 0.05)" in w
    assert "rim.speed" not in w
    ru = message(w, "ru")
    assert "задайте flywheel.rim.thickness_to_radius около 0.1 (t/D = 0.05)" in ru
    for speed in (5.0, 20.0):              # the speed changes the diameter, not t/D
        data["flywheel"]["rim"] = {"thickness_to_radius": 0.01, "speed": speed}
        other = analyze(parse_case(data, "c.toml"), n_points=360).sizing.rim_design
        assert other.thickness / other.D_mean == pytest.approx(0.005, rel=1e-12)
    data["flywheel"]["rim"] = {"thickness_to_radius": 0.1}
    again = analyze(parse_case(data, "c.toml"), n_points=360)
    d2 = again.sizing.rim_design
    assert d2.thickness / d2.D_mean == pytest.approx(0.05, rel=1e-12)
    assert not [w for w in again.warnings if getattr(w, "code", "").startswith("rim_thin")]
