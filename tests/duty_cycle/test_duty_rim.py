"""The rim of a duty-cycle flywheel, ``[flywheel.rim]`` in `flywheel duty-cycle` (issue 24 item 7:
rim design as in `run`): Khurmi & Gupta's Ex. 16.23, which sizes the rim of a punching press's
flywheel, against the book's printed dimensions and the exact formulas written out here; the
rim's mass at its mean radius against the J the operation needs; the document's existing keys
unchanged by the rim; the other ways to state the rim (from the allowable stress, a given speed,
a given flywheel); the summary's and the записка's rim table in both languages.

The printed answers are those of the FOSSEE Python companion of the book
(Theory_Of_Machines/ch16.ipynb, Ex. 16.23), which reproduces its solution.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import pytest

from flywheel.cases.duty_cycle import parse_duty_case, solve_case
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
RPM = math.pi / 30
CASE_16_23 = CASES / "duty_khurmi_16_23_punch_force.toml"


def close(a, b, rel=1e-12):
    return a == pytest.approx(b, rel=rel, abs=0)


def solve_data(data: dict, name: str = "case.toml"):
    return solve_case(parse_duty_case(data, name), name)


def test_khurmi_16_23_the_rim_of_the_punching_press():
    """Ex. 16.23: cast iron, ρ = 7250 kg/m³, σ = 6 MPa; b = 2·t; the rim gives 95 % of the
    inertia; mean diameter 1.4 m; the flywheel at 225 rpm with δ = 0.1; ΔE = 0.9·E."""
    r = solve_data(read_toml(CASE_16_23))
    rim = r.rim
    F = math.pi * 0.025 * 0.018 * 300e6                 # F_s = π·d·t·τ_u
    E = 0.5 * F * 0.018                                 # E = ½·F_s·t
    omega = 225 * RPM
    J = 0.9 * E / (omega ** 2 * 0.1)                    # ΔE = J·ω²·δ
    m = 0.95 * J / 0.7 ** 2                             # the rim: 95 % of J at R = D/2
    t = math.sqrt(m / (math.pi * 1.4 * 2 * 7250.0))     # m = ρ·π·D·b·t, b = 2·t
    # printed: t = 43 mm, b = 86 mm (whole millimetres, the mass rounded to 120 kg first)
    assert int(rim.thickness * 1e3) == 43 and int(rim.width * 1e3) == 86
    # exact: t = 43.3725 mm, b = 86.7449 mm, m = 119.970 kg, A = b·t = 3762.34 mm²
    assert close(rim.thickness, t) and close(rim.width, 2 * t)
    assert close(rim.mass, m) and close(rim.area, 2 * t * t)
    assert round(rim.thickness * 1e3, 4) == 43.3725 and round(rim.area * 1e6, 2) == 3762.34
    assert rim.D_mean == 1.4 and close(rim.rim_speed, omega * 0.7)
    assert close(rim.stress, 7250.0 * (omega * 0.7) ** 2)               # σ = ρ·v²
    assert close(rim.stress_at_omega_max, 7250.0 * (r.omega_max * 0.7) ** 2)
    # the rim's mass × R² is its share of the J the operation needs
    assert close(rim.mass * 0.7 ** 2, 0.95 * r.J) and close(r.J, J)


def test_the_rim_adds_flywheel_rim_and_leaves_every_other_key_as_it_was():
    data = read_toml(CASE_16_23)
    plain = copy.deepcopy(data)
    for key in ("material", "density", "allowable_stress", "rim"):
        del plain["flywheel"][key]
    plain["flywheel"]["rim_diameter"] = 1.4              # the case as it was before the rim
    with_rim, without = solve_data(data).to_document(), solve_data(plain).to_document()
    assert "flywheel_rim" not in without
    rim = with_rim.pop("flywheel_rim")
    assert with_rim == without
    for key in ("D_mean", "thickness", "width", "mass", "rim_speed", "stress", "share", "area",
                "stress_at_omega_max"):
        assert math.isfinite(rim[key]), key


def _press(rim: dict, **flywheel) -> dict:
    """Ex. 16.19's press (15 kJ in 2 s, 720 an hour, 225 → 200 rpm) with a rim."""
    return {"operation": {"energy": 15000.0, "duration": 2.0}, "cycle": {"per_hour": 720},
            "flywheel": {"max_rpm": 225, "min_rpm": 200, **flywheel, "rim": rim}}


def test_a_rim_at_the_largest_speed_the_stress_allows():
    r = solve_data(_press({"share": 0.9}, material="cast-iron"))
    wm = 212.5 * RPM
    J = 9000.0 / (0.5 * ((225 * RPM) ** 2 - (200 * RPM) ** 2))       # ΔE = ½·J·(ω₁² − ω₂²)
    v = math.sqrt(7e6 / 7200.0)                                      # √(σ/ρ) of cast iron
    D = 2 * v / wm
    m = 0.9 * J / (D / 2) ** 2
    t = math.sqrt(m / (math.pi * D * 2 * 7200.0))                    # b = 2·t by default
    rim = r.rim
    assert rim.speed_from == "allowable stress"
    assert close(rim.D_mean, D) and close(rim.mass, m) and close(rim.thickness, t)
    assert close(rim.stress, 7e6)
    assert r.radius is None and r.mass is None       # no radius of gyration given: k unknown


def test_a_hoop_is_warned_about_as_run_warns_and_the_hinted_speed_gives_the_aim():
    """Steel at √(σ/ρ) = 50.6 m/s on a 212.5 rpm shaft: D_mean = 4.55 m, t = 11 mm (t/D =
    0.0024): run's warning, whose hinted rim speed gives t/D_mean = 0.05 when given back."""
    r = solve_data(_press({"share": 0.9}))
    assert r.rim.thickness / r.rim.D_mean < 0.01
    (w,) = [w for w in r.warnings if getattr(w, "code", "") == "rim_thin"]
    v_aim = float(w.split("about ")[1].split(" m/s")[0])
    again = solve_data(_press({"share": 0.9, "speed": v_aim})).rim
    # v_aim is printed to 3 digits (±0.35 %), t/D ∝ v^(−5/2): within 1 %
    assert again.thickness / again.D_mean == pytest.approx(0.05, rel=1e-2)
    assert not [w for w in solve_data(_press({"share": 0.9, "speed": v_aim})).warnings
                if getattr(w, "code", "") == "rim_thin"]


def test_a_rim_of_a_given_speed_and_thickness_to_radius_with_a_radius_of_gyration():
    r = solve_data(_press({"speed": 20.0, "thickness_to_radius": 0.1, "share": 1.0},
                          radius_of_gyration=0.5))
    rim, wm = r.rim, 212.5 * RPM
    D = 2 * 20.0 / wm
    assert close(rim.D_mean, D) and close(rim.thickness, 0.1 * D / 2)
    assert close(rim.mass * (D / 2) ** 2, r.J)                       # share 1: all of J
    assert close(rim.mass * math.pi * D * rim.width * rim.thickness, rim.mass ** 2 / 7800.0)
    assert r.radius == 0.5 and close(r.mass, r.J / 0.25)             # k given: the whole m


def test_a_given_flywheel_with_a_rim_is_sized_at_the_speeds_it_reaches():
    """Ex. 16.21's riveter (150 kg at 0.6 m, 300 rpm before riveting): its rim at the mean of
    the speeds the given flywheel reaches."""
    data = read_toml(CASES / "duty_khurmi_16_21_riveting.toml")
    data["flywheel"]["rim"] = {"diameter": 1.2, "share": 0.8}
    r = solve_data(data)
    assert close(r.J, 150 * 0.6 ** 2)
    assert close(r.rim.mass * 0.6 ** 2, 0.8 * r.J)
    assert close(r.rim.rim_speed, r.omega_mean * 0.6)


@pytest.mark.parametrize("lang, title, area", [("en", "Rim of the flywheel", "cross-section"),
                                               ("ru", "Обод маховика", "площадь сечения")])
def test_the_summary_and_the_report_show_the_rim(lang, title, area):
    from flywheel.render.document import Table
    from flywheel.render.duty_cycle import summary_tables
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    r = solve_data(read_toml(CASE_16_23))
    tables = {head: rows for head, _, rows, _, _ in summary_tables(r, lang)}
    rim = [rows for head, rows in tables.items() if head.startswith(title)]
    assert len(rim) == 1
    names = [row[0] for row in rim[0]]
    assert any(area in n for n in names) and len(names) == 8
    doc = build_duty_cycle_document(r, "t", "s", lang)
    captions = [b.caption for b in doc.blocks if isinstance(b, Table)]
    assert any(c.startswith(title) for c in captions)
    plain = solve_data(_press({"share": 0.9}) | {"flywheel": {"max_rpm": 225, "min_rpm": 200}})
    assert not any(h.startswith(title) for h, *_ in summary_tables(plain, lang))


def test_a_hoop_of_a_given_diameter_is_told_the_diameter_that_makes_it_a_rim():
    """A diameter given (4 m, steel, the press of Ex. 16.19): no rim speed to give (the diameter
    sets it), so the warning names the diameter that gives t/D_mean = 0.05. Independently of
    the warning: at fixed J, share, ω, ρ and b = 2·t, m ∝ D⁻² and t = √(m/(π·D·2·ρ)) ∝ D^(−3/2),
    so t/D ∝ D^(−5/2) and D_aim = D·((t/D)/0.05)^(2/5); given back, it gives t/D = 0.05."""
    from flywheel.render.nomenclature import message

    r = solve_data(_press({"share": 0.9, "diameter": 4.0}))
    ratio = r.rim.thickness / r.rim.D_mean
    assert ratio < 0.01
    (w,) = [w for w in r.warnings if getattr(w, "code", "").startswith("rim_thin")]
    assert w.code == "rim_thin_diameter"
    D_aim = 4.0 * (ratio / 0.05) ** 0.4
    assert f"give a smaller flywheel.rim.diameter (about {D_aim:.3g} m gives t/D = 0.05)" in w
    assert "rim.speed" not in w and "rim speed" not in w
    ru = message(w, "ru")
    assert f"задайте меньший flywheel.rim.diameter (около {D_aim:.3g} м даёт t/D = 0.05)" in ru
    again = solve_data(_press({"share": 0.9, "diameter": D_aim}))
    assert again.rim.thickness / again.rim.D_mean == pytest.approx(0.05, rel=1e-12)
    assert not [w for w in again.warnings if getattr(w, "code", "").startswith("rim_thin")]
