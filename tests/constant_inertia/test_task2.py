"""flywheel.constant_inertia (graphs, crossings, solve, the seed preset) and its case format: seed 002, closed forms, textbook problems.

Reference values: the seed's printed numbers sit in comments next to the exact values asserted;
where the seed is wrong (its crossings, ω4 = ω5 = 199.91, δ printed as 0) the test says so.
"""
import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.constant_inertia.crossings import crossings
from flywheel.constant_inertia.graphs import Piece, constant, harmonic, piecewise_linear, triangle
from flywheel.constant_inertia.preset import seed_task
from flywheel.constant_inertia.solve import (NotFiniteError, balance, sample, solve,
                                            solve_areas)
from flywheel.errors import CaseFileError, InputError
from flywheel.cases.task2 import load_task2_case, parse_task2_case, solve_case

CASES = Path(__file__).resolve().parents[2] / "cases"
PI = math.pi


def solve_file(name):
    path = CASES / name
    return solve_case(load_task2_case(path), str(path))


def numeric_A(m_d, m_c, phi, n=400_001, jumps=()):
    """Independent work A(φ) = ∫₀^φ (M_D − M_C) dφ: trapezoid rule on a fine grid, split at
    the given jumps (a jump inside a trapezoid is only first-order accurate)."""
    cuts = [0.0, *[j for j in jumps if 0.0 < j < phi], phi]
    total = 0.0
    for a, b in zip(cuts, cuts[1:]):
        x = np.linspace(a, b, n)
        f = m_d(x) - m_c(x)
        # ends of each piece evaluated just inside it, so a jump at a cut is never straddled
        f[0] = m_d(np.array([a + 1e-12 * (b - a)]))[0] - m_c(np.array([a + 1e-12 * (b - a)]))[0]
        f[-1] = m_d(np.array([b - 1e-12 * (b - a)]))[0] - m_c(np.array([b - 1e-12 * (b - a)]))[0]
        total += float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(x)))
    return total


def omega_numeric(A, J=12.0, w0=200.0):
    return math.sqrt(w0 * w0 + 2 * A / J)


# -- seed 002 -------------------------------------------------------------------------------------

@pytest.mark.parametrize("profile", ["triangle", "rectangle"])
def test_seed_balance_gives_60(profile):
    # seed: M_C := 4·M_D = 60 Н·м in both tasks (M_D·2π = M_C·π/2)
    r = seed_task(profile)
    assert r.M_C == pytest.approx(60.0, rel=1e-15)
    assert r.unknown == "resistance"
    assert r.steady
    assert r.work_driving == pytest.approx(r.work_resistance, rel=1e-14)


def _triangle_mc(x):
    return np.interp(x, [0, PI / 2, PI, 3 * PI / 2, 2 * PI], [0, 0, 60, 0, 0])


def test_seed_triangle_crossings_are_5pi_8_and_11pi_8():
    r = seed_task("triangle")
    phis = [row.phi for row in r.rows]
    assert phis == pytest.approx([0, PI / 2, 5 * PI / 8, PI, 11 * PI / 8, 3 * PI / 2, 2 * PI],
                                 abs=1e-14)
    assert [row.kind for row in r.rows] == ["bound", "bound", "crossing", "bound", "crossing",
                                            "bound", "bound"]
    # the seed puts them at π/2 + (2/π)·M_D/M_C = 1.73 rad and 4.55 rad: wrong
    assert abs(r.rows[2].phi - 1.73) > 0.2
    assert r.rows[2].M_C == pytest.approx(15.0, abs=1e-12)   # M_C = M_D there
    assert r.rows[4].M_C == pytest.approx(15.0, abs=1e-12)


@pytest.mark.parametrize("profile,mc", [("triangle", _triangle_mc),
                                        ("rectangle", lambda x: np.where(
                                            (x >= PI / 2) & (x < PI), 60.0, 0.0))])
def test_seed_omega_at_every_row_matches_numerical_integration(profile, mc):
    r = seed_task(profile)
    for row in r.rows:
        A = numeric_A(lambda x: np.full_like(x, 15.0), mc, row.phi,
                      jumps=(PI / 2, PI, 3 * PI / 2))
        assert row.A == pytest.approx(A, abs=1e-8)
        assert row.omega == pytest.approx(omega_numeric(A), abs=1e-7)


def test_seed_triangle_numbers():
    r = seed_task("triangle")
    w = [row.omega for row in r.rows]
    # seed: ω1 = 200.01, ω2 = 200.01 (at its wrong φ2), ω3 = 200
    assert w[1] == pytest.approx(math.sqrt(200 ** 2 + 2 * 15 * (PI / 2) / 12), rel=1e-15)
    assert w[3] == pytest.approx(200.0, rel=1e-14)
    # ω_max at 5π/8: A = 15·5π/8 − 15·(π/8)/2 = 135π/16
    assert r.omega_max == pytest.approx(math.sqrt(40000 + 2 * 135 * PI / 16 / 12), rel=1e-15)
    assert r.omega_max == pytest.approx(200.0110444, abs=1e-7)
    # seed: ω4 = ω5 = 199.91 -- wrong; the minimum is at 11π/8: A = −135π/16
    assert r.omega_min == pytest.approx(math.sqrt(40000 - 2 * 135 * PI / 16 / 12), rel=1e-15)
    assert r.omega_min == pytest.approx(199.9889550, abs=1e-7)
    assert w[5] == pytest.approx(199.9901823, abs=1e-7)      # not 199.91 either
    assert r.phi_omega_max == pytest.approx(5 * PI / 8, abs=1e-14)
    assert r.phi_omega_min == pytest.approx(11 * PI / 8, abs=1e-14)
    # seed: ω_ср = 199.96 (from its wrong ω_min), δ printed as 0 (rounding)
    assert r.omega_mean == pytest.approx(199.9999997, abs=1e-7)
    assert r.delta == pytest.approx(1.10446617e-4, rel=1e-8)
    assert r.delta_T_max == pytest.approx(135 * PI / 8, rel=1e-14)


def test_seed_rectangle_numbers():
    r = seed_task("rectangle")
    assert [row.phi for row in r.rows] == pytest.approx([0, PI / 2, PI, 2 * PI], abs=1e-15)
    # seed: ω1 = 200.01, ω2 = 199.98, ω_ср := ω0 = 200 (it should be (ω_max + ω_min)/2)
    assert r.omega_max == pytest.approx(math.sqrt(40000 + 2 * 7.5 * PI / 12), rel=1e-15)
    assert r.omega_min == pytest.approx(math.sqrt(40000 - 2 * 15 * PI / 12), rel=1e-15)
    assert r.omega_min == pytest.approx(199.98, abs=5e-3)
    assert r.phi_omega_max == PI / 2 and r.phi_omega_min == PI
    assert r.delta == pytest.approx((r.omega_max - r.omega_min) / r.omega_mean, rel=1e-9)
    assert r.delta == pytest.approx(1.47269e-4, rel=1e-5)


def test_seed_given_peak_is_not_steady():
    r = seed_task("triangle", M_C=50.0)
    assert not r.steady
    # A(2π) = 15·2π − 50·π/2 = 5π
    assert r.work_end == pytest.approx(5 * PI, rel=1e-14)
    assert r.omega_end == pytest.approx(math.sqrt(40000 + 2 * 5 * PI / 12), rel=1e-15)


def test_seed_machine_that_stops():
    with pytest.raises(InputError, match="stops at φ = "):
        seed_task("rectangle", M_C=200000.0, omega0=1.0)


def test_seed_delta_asks_for_J():
    r = seed_task("triangle", delta=1e-5)
    assert r.J_required == pytest.approx(r.delta_T_max / (1e-5 * r.omega_mean ** 2), rel=1e-15)
    # with that J at the same mean speed the motion has exactly that δ
    again = solve(r.driving, r.resistance, r.J_required, omega_mean=r.omega_mean)
    assert again.delta == pytest.approx(1e-5, rel=1e-12)


@pytest.mark.parametrize("kw,match", [
    (dict(J=0.0), "J must be positive"),
    (dict(J=-3.0), "J must be positive"),
    (dict(omega0=0.0), "ω0 must be positive"),
    (dict(M_D=-1.0), "M_D must be positive"),
    (dict(start=PI, end=PI / 2), "must be less than"),
    (dict(start=PI, end=3 * PI), "within 0…360°"),
])
def test_seed_bad_input(kw, match):
    with pytest.raises(InputError, match=match):
        seed_task("triangle", **kw)


# -- closed forms -------------------------------------------------------------------------------

def test_constant_moments_closed_form():
    # M_D − M_C = 10 N·m throughout: ω² = ω0² + 2·10·φ/J
    r = solve(constant(30.0), constant(20.0), 2.0, omega0=10.0)
    assert not r.steady
    assert r.omega_end == pytest.approx(math.sqrt(100 + 20 * PI), rel=1e-15)
    assert r.omega_max == r.omega_end and r.omega_min == 10.0
    r = solve(constant(20.0), constant(20.0), 2.0, omega0=10.0)
    assert r.steady and r.delta == 0.0 and r.delta_T_max == 0.0


@pytest.mark.parametrize("a", [7.0, -7.0])
def test_single_harmonic_closed_form(a):
    # M_D − M_C = a·sin φ  →  ω² = ω0² + 2a(1 − cos φ)/J
    J, w0 = 3.0, 5.0
    r = solve(harmonic(100.0, [a]), constant(100.0), J, omega0=w0)
    assert r.steady
    for row in r.rows:
        assert row.omega == pytest.approx(math.sqrt(w0 ** 2 + 2 * a * (1 - math.cos(row.phi)) / J),
                                          rel=1e-14)
    s = sample(r, 181)
    for phi, w in zip(s["phi"], s["omega"]):
        assert w == pytest.approx(math.sqrt(w0 ** 2 + 2 * a * (1 - math.cos(phi)) / J), rel=1e-14)
    assert [row.kind for row in r.rows] == ["bound", "crossing", "bound"]
    extreme = r.phi_omega_max if a > 0 else r.phi_omega_min
    assert extreme == pytest.approx(PI, abs=1e-14)
    assert r.delta_T_max == pytest.approx(2 * abs(a), rel=1e-14)   # A = a(1 − cos φ)


def test_harmonic_crossings_found_robustly():
    # 1500·sin 3φ: crossings at every 60°
    r = solve(harmonic(5000.0, [1500.0], orders=[3]), constant(5000.0), 1000.0,
                 omega0=31.4)
    inner = [math.degrees(row.phi) for row in r.rows if row.kind == "crossing"]
    assert inner == pytest.approx([60, 120, 180, 240, 300], abs=1e-10)
    # a pair of close roots: sin φ·(cos φ − 0.999) crosses at ±2.56°
    p = Piece(0.0, 2 * PI, 0.0, 0.0, ((1, -0.999, 0.0), (2, 0.5, 0.0)))
    roots = crossings(p)
    c = math.degrees(math.acos(0.999))
    assert [math.degrees(x) for x in roots] == pytest.approx([c, 180, 360 - c], abs=1e-9)


def test_mean_speed_is_exact():
    r = solve(constant(15.0), triangle(60.0, PI / 2, 3 * PI / 2), 12.0,
                 omega_mean=50.0)
    assert r.omega_mean == 50.0
    assert 0.5 * (r.omega_max + r.omega_min) == pytest.approx(50.0, rel=1e-15)
    assert r.delta * r.J * r.omega_mean ** 2 == pytest.approx(r.delta_T_max, rel=1e-14)


def test_library_errors():
    with pytest.raises(InputError, match="must not decrease"):
        piecewise_linear([(0, 0), (2, 1), (1, 1), (2 * PI, 0)])
    with pytest.raises(InputError, match="must span the cycle"):
        piecewise_linear([(0, 0), (PI, 1)])
    with pytest.raises(InputError, match="negative resistance"):
        balance(lambda x: constant(100.0),
                   lambda x: triangle(x, 1.0, 2.0, base=200.0), "resistance")
    with pytest.raises(InputError, match="sum to"):
        solve_areas([1.0, -2.0], J=1.0, omega0=1.0)
    with pytest.raises(InputError, match="mean speed needs steady"):
        solve(constant(2.0), constant(1.0), 1.0, omega_mean=10.0)


# -- the case files -------------------------------------------------------------------------------

@pytest.mark.parametrize("name,profile", [("task2_seed_triangle.toml", "triangle"),
                                          ("task2_seed_rectangle.toml", "rectangle")])
def test_seed_case_files_equal_the_command_defaults(name, profile):
    a, b = solve_file(name), seed_task(profile)
    assert a.M_C == 60.0
    assert [r.omega for r in a.rows] == [r.omega for r in b.rows]
    assert a.delta == b.delta


def test_khurmi_16_4_areas():
    # Khurmi & Gupta, Theory of Machines, ch. 16, Example 16.4 (petrol engine, areas 295 … 270
    # mm², 1 mm = 5 N·m, 1 mm = 1°, 36 kg at k = 150 mm, 1800 rpm)
    r = solve_file("task2_khurmi_16_4.toml")
    # ΔE = (295 + 690) mm² · 5·π/180 J/mm²
    assert r.delta_T_max == pytest.approx(985 * 5 * PI / 180, rel=1e-14)
    # book: C_s = 0.003 (0.3 %)
    assert r.delta == pytest.approx(0.003, abs=5e-5)
    assert r.delta == pytest.approx(985 * 5 * PI / 180 / (36 * 0.15 ** 2 * (60 * PI) ** 2),
                                    rel=1e-13)
    assert r.phi_omega_max is None


def test_khurmi_16_5_rim_mass():
    # Khurmi & Gupta, ch. 16, Example 16.5 (areas +52 … +107 mm², 1 mm = 600 N·m, 1 mm = 3°,
    # 600 rpm, ±1.5 %, rim radius 0.5 m)
    r = solve_file("task2_khurmi_16_5.toml")
    assert r.delta_T_max == pytest.approx(172 * 600 * 3 * PI / 180, rel=1e-14)
    # book: m = 182 kg
    assert r.rim_mass == pytest.approx(182, abs=1)
    assert r.rim_mass == pytest.approx(182.4977, abs=1e-4)
    assert r.delta == pytest.approx(0.03, rel=1e-14)


def test_khurmi_16_6_three_revolutions():
    # Khurmi & Gupta, ch. 16, Example 16.6 (750 → 3000 N·m over 3 revolutions, 250 rpm,
    # 500 kg at k = 0.6 m)
    r = solve_file("task2_khurmi_16_6.toml")
    assert r.M_D == pytest.approx(1875.0, rel=1e-14)          # mean torque
    # book: P = 49.1 kW
    assert r.power / 1000 == pytest.approx(49.1, abs=0.05)
    # book: C_s = 0.072
    assert r.delta == pytest.approx(0.072, abs=5e-4)
    assert r.delta_T_max == pytest.approx(2812.5 * PI, rel=1e-13)
    assert r.rows[-1].phi == pytest.approx(6 * PI)


def test_khurmi_16_9_four_stroke():
    # Khurmi & Gupta, ch. 16, Example 16.9 (20 kW at 300 rpm, four-stroke, triangles, ±2 %)
    r = solve_file("task2_khurmi_16_9.toml")
    assert r.power == pytest.approx(20e3, rel=1e-12)
    # book: I = 255.4 kg·m²
    assert r.J_required == pytest.approx(255.4, abs=0.05)
    assert math.degrees(r.cycle) == 720.0


def test_khurmi_16_11_harmonic():
    # Khurmi & Gupta, ch. 16, Example 16.11 (T = 20 000 + 9500 sin 2θ − 5700 cos 2θ, 180 rpm,
    # 1 % of the mean speed)
    r = solve_file("task2_khurmi_16_11.toml")
    # book: P = 377 kW
    assert r.power / 1000 == pytest.approx(377, abs=0.5)
    # book: ΔE = 11 078 N·m (the amplitude √(9500² + 5700²))
    assert r.delta_T_max == pytest.approx(math.hypot(9500, 5700), rel=1e-13)
    assert r.delta_T_max == pytest.approx(11078, abs=1)
    # book: I = 3121 kg·m² (it rounds ω²·C_s to 3.55); exactly 3118.1
    assert r.J_required == pytest.approx(3121, rel=1e-3)
    assert r.J_required == pytest.approx(math.hypot(9500, 5700) / (0.01 * (6 * PI) ** 2),
                                         rel=1e-13)


def test_khurmi_16_12_two_harmonics():
    # Khurmi & Gupta, ch. 16, Example 16.12 (engine 5000 + 600 sin 2θ, machine 5000 + 500 sin θ,
    # 500 kg at k = 0.4 m, 150 rpm)
    r = solve_file("task2_khurmi_16_12.toml")
    # book: ΔE = 1204 N·m; exactly 600·119/144 − 500·7/12 + 1000 = 1204.1667
    assert r.delta_T_max == pytest.approx(1204, abs=0.5)
    assert r.delta_T_max == pytest.approx(1204 + 1 / 6, rel=1e-13)
    # book: C_s = 6.1 %
    assert 100 * r.delta == pytest.approx(6.1, abs=0.05)
    # crossings at θ = 0, 65.38°, 180°, 294.62° (cos θ = 5/12)
    inner = [math.degrees(row.phi) for row in r.rows if row.kind == "crossing"]
    c = math.degrees(math.acos(5 / 12))
    assert inner == pytest.approx([c, 180, 360 - c], abs=1e-9)


def test_every_case_file_is_valid():
    files = sorted(CASES.glob("task2_*.toml"))
    assert len(files) >= 8
    for f in files:
        text = f.read_text(encoding="utf-8")
        assert text.startswith("#"), f"{f.name} needs a comment header citing its source"
        solve_file(f.name)


# -- the case format's errors ----------------------------------------------------------------

BASE = {"speed": {"omega0": 200.0}, "flywheel": {"J": 12.0},
        "driving": {"kind": "constant", "value": 15.0},
        "resistance": {"kind": "triangle", "from_deg": 90, "to_deg": 270, "peak": "balance"}}


def _with(**changes):
    import copy

    d = copy.deepcopy(BASE)
    for path, value in changes.items():
        keys = path.split("__")
        t = d
        for k in keys[:-1]:
            t = t.setdefault(k, {})
        if value is None:
            t.pop(keys[-1], None)
        else:
            t[keys[-1]] = value
    return d


@pytest.mark.parametrize("changes,match", [
    (dict(flywheel__J=0.0), r"x.toml: flywheel.J: must be positive"),
    (dict(speed__omega0=-5.0), r"speed.omega0: -5 rad/s is out of range \(allowed: 0.001 … 100000 rad/s\)"),
    (dict(speed__mean=3.0), r"speed: give exactly one of"),
    (dict(resistance__from_deg=300), r"resistance.from_deg: need 0 ≤ from_deg < to_deg"),
    (dict(resistance__peak="balanse"), r'resistance.peak: must be a number, "balance" or "power"'),
    (dict(resistance__kind="triangel"), r"resistance.kind: unknown kind 'triangel'; did you "
                                        r"mean 'triangle'\?"),
    (dict(resistance__peek=3.0), r"resistance.peek: unknown key; did you mean 'peak'\?"),
    (dict(flywheel__j=1.0), r"flywheel.j: unknown key; did you mean 'J'\?"),
    (dict(driving__value="balance"), r'"balance" may stand for one value only'),
    (dict(resistance={"kind": "points", "points": [[0, 0], [200, 5], [100, 5], [360, 0]]}),
     r"resistance.points\[2\]: angle 100° comes after 200°"),
    (dict(resistance={"kind": "points", "points": [[0, 0], [200, 5]]}),
     r"resistance.points: must span the cycle 0…360°"),
    (dict(resistance={"kind": "triangle", "from_deg": 90, "to_deg": 270, "peak": "balance",
                      "base": 100.0}),
     r"resistance.peak: the cycle balance needs a negative resistance moment"),
    (dict(driving=None, resistance=None,
          diagram={"areas": [10, -5, -4], "moment_scale": 1, "angle_scale_deg": 1}),
     r"diagram.areas: sum to 1, not 0"),
    (dict(driving=None, resistance=None, diagram={"areas": [10, -10]}),
     r"diagram.moment_scale: missing"),
    (dict(flywheel={"J": 1.0, "mass": 2.0, "radius_of_gyration": 1.0}), r"not both"),
    (dict(flywheel={}), r"flywheel: give J"),
    (dict(cycle_deg=180), r"resistance.from_deg: need 0 ≤ from_deg < to_deg ≤ 180"),
])
def test_case_errors_are_one_line(changes, match):
    data = _with(**changes)
    with pytest.raises(CaseFileError, match=match) as exc:
        solve_case(parse_task2_case(data, "x.toml"), "x.toml")
    assert "\n" not in str(exc.value)
    assert str(exc.value).startswith("x.toml: ")


def test_case_file_errors(tmp_path):
    with pytest.raises(CaseFileError, match="no such file"):
        load_task2_case(tmp_path / "nope.toml")
    bad = tmp_path / "bad.toml"
    bad.write_text("speed = [", encoding="utf-8")
    with pytest.raises(CaseFileError, match="TOML syntax error"):
        load_task2_case(bad)


def test_half_orders_over_720_with_driving_balance_match_numerical_integration():
    data = {"cycle_deg": 720, "speed": {"omega0_rpm": 1500}, "flywheel": {"J": 2.0},
            "driving": {"kind": "harmonic", "a0": "balance", "a": [300.0, 100.0],
                        "b": [50.0, 0.0], "orders": [0.5, 1.5]},
            "resistance": {"kind": "points",
                           "points": [[0, 100], [360, 100], [360, 50], [720, 50]]}}
    r = solve_case(parse_task2_case(data, "h.toml"), "h.toml")
    assert r.unknown == "driving" and r.M_D == pytest.approx(75.0, rel=1e-13)
    assert r.steady

    def md(x):
        return 75 + 300 * np.sin(0.5 * x) + 50 * np.cos(0.5 * x) + 100 * np.sin(1.5 * x)

    def mc(x):
        return np.where(x < 2 * PI, 100.0, 50.0)

    w0 = 1500 * PI / 30
    for row in r.rows:
        A = numeric_A(md, mc, row.phi, 1_000_001, jumps=(2 * PI,))
        assert row.A == pytest.approx(A, abs=1e-5)
        assert row.omega == pytest.approx(math.sqrt(w0 ** 2 + A), rel=1e-9)   # J = 2
        if row.kind == "crossing":
            assert md(row.phi) - mc(row.phi) == pytest.approx(0.0, abs=1e-9)


def test_mean_speed_with_unsteady_moments_names_the_speed():
    data = {"speed": {"mean": 100.0}, "flywheel": {"J": 2.0},
            "driving": {"kind": "constant", "value": 10.0},
            "resistance": {"kind": "constant", "value": 5.0}}
    with pytest.raises(CaseFileError, match=r"^n.toml: speed: a mean speed needs steady motion"):
        solve_case(parse_task2_case(data, "n.toml"), "n.toml")


# -- zero-mean moments: steadiness judged against the size of the moments ----------------------

ZERO_MEAN = {"speed": {"mean_rpm": 250.0}, "flywheel": {"J": 10.0},
             "driving": {"kind": "harmonic", "a": [300.0], "b": [-500.0], "orders": [2]},
             "resistance": {"kind": "constant", "value": 0.0}}


@pytest.mark.parametrize("speed", [{"mean_rpm": 250.0}, {"omega0_rpm": 250.0}])
def test_zero_mean_moments_are_steady(speed):
    # M_D − M_C = 300 sin 2φ − 500 cos 2φ: ∮ = 0 exactly (its closed form gives 1.2e-13 J of
    # round-off); A = 150(1 − cos 2φ) − 250 sin 2φ, so ΔT_нб = 2·√(150² + 250²)
    r = solve_case(parse_task2_case({**ZERO_MEAN, "speed": speed}, "z.toml"), "z.toml")
    assert r.steady and r.work_end == 0.0
    assert r.omega_end == r.omega0
    assert r.delta_T_max == pytest.approx(2 * math.hypot(150, 250), rel=1e-13)
    if "mean_rpm" in speed:
        assert r.omega_mean == pytest.approx(250 * PI / 30, rel=1e-15)


@pytest.mark.parametrize("a,b", [(3e6, 5e6), (3e6, -5e6), (-300.0, 500.0)])
def test_balance_of_a_zero_mean_moment_is_zero(a, b):
    # ∮ (a sin 2φ + b cos 2φ) dφ = 0: the constant that balances it is 0, not a negative
    # round-off (−1.95e-10 N·m for a = 3e6, b = 5e6) nor −0.0
    x = balance(lambda x: harmonic(0.0, [a], [b], orders=[2]), lambda x: constant(x),
                   "resistance")
    assert x == 0.0 and math.copysign(1.0, x) == 1.0
    r = solve(harmonic(0.0, [a], [b], orders=[2]), constant(x), 1e6, omega_mean=50.0)
    assert r.steady


def test_small_but_real_cycle_work_is_not_steady():
    # the tolerance scales with the moments, not with the absolute size of the work
    r = solve(harmonic(1e-6, [1e-3], orders=[2]), constant(0.0), 1.0, omega0=1.0)
    assert not r.steady
    assert r.work_end == pytest.approx(2e-6 * PI, rel=1e-9)


# -- crossings: clusters of close roots, tangencies, linear + harmonic ------------------------------

@pytest.mark.parametrize("a1,a2", [(0.999, 0.5), (-0.999, -0.5), (0.999, -0.5), (-0.999, 0.5)])
def test_close_harmonic_crossings(a1, a2):
    # a1 sin φ + a2 sin 2φ = sin φ·(a1 + 2a2 cos φ): roots at 180° and at cos φ = −a1/(2a2),
    # three roots within 5.2° (old sampling found one of them for a1 = a2·2·0.999 > 0)
    p = Piece(0.0, 2 * PI, 0.0, 0.0, ((1, a1, 0.0), (2, a2, 0.0)))
    c = math.degrees(math.acos(-a1 / (2 * a2)))
    want = sorted([c, 180.0, 360.0 - c])
    assert [math.degrees(x) for x in crossings(p)] == pytest.approx(want, abs=1e-9)
    for x in crossings(p):
        assert p.value(x) == pytest.approx(0.0, abs=1e-14)


def test_close_crossings_are_extremes_of_the_motion():
    # the repro: M_D − M_C = 0.999 sin φ + 0.5 sin 2φ; A = 0.999(1 − cos φ) + 0.25(1 − cos 2φ)
    # is largest at 177.437° and 182.563° (equal) and has a local minimum at 180°
    r = solve(harmonic(10.0, [0.999, 0.5]), constant(10.0), 1.0, omega0=10.0)
    inner = [math.degrees(row.phi) for row in r.rows if row.kind == "crossing"]
    c = math.degrees(math.acos(-0.999))
    assert inner == pytest.approx([c, 180, 360 - c], abs=1e-9)
    assert math.degrees(r.phi_omega_max) == pytest.approx(c, abs=1e-9)
    assert r.delta_T_max == pytest.approx(0.999 * (1 - math.cos(math.radians(c)))
                                          + 0.25 * (1 - math.cos(2 * math.radians(c))),
                                          rel=1e-13)


def test_tangent_zeros_are_not_crossings():
    # 1 − cos 2φ touches 0 at 180° without changing sign: no crossing
    assert crossings(Piece(0.0, 2 * PI, 1.0, 0.0, ((2, 0.0, -1.0),))) == []
    # sin φ + ½ sin 2φ = sin φ·(1 + cos φ): a triple zero at 180° that changes sign once
    roots = crossings(Piece(0.0, 2 * PI, 0.0, 0.0, ((1, 1.0, 0.0), (2, 0.5, 0.0))))
    assert len(roots) == 1 and roots[0] == pytest.approx(PI, abs=1e-4)


def test_linear_plus_harmonic_close_crossings_match_dense_sampling():
    # a sloped piece (a line against a harmonic) with three roots 0.014 rad apart:
    # compared with the sign changes on a grid 1e-6 rad apart
    p = Piece(2.0, 4.5, -1e-6 * (PI - 2.0), 1e-6, ((1, 0.9999, 0.0), (2, 0.5, 0.0)))
    x = np.linspace(p.phi0, p.phi1, 2_500_001)
    f = p.m0 + p.slope * (x - p.phi0) + 0.9999 * np.sin(x) + 0.5 * np.sin(2 * x)
    i = np.nonzero(np.sign(f[1:]) != np.sign(f[:-1]))[0]
    want = x[i] - f[i] * (x[i + 1] - x[i]) / (f[i + 1] - f[i])
    assert len(want) == 3
    assert crossings(p) == pytest.approx(list(want), abs=1e-9)


def test_crossings_of_many_orders():
    # sin 7φ over 720°: a root every 180°/7 inside (27 of them), all simple
    p = Piece(0.0, 4 * PI, 0.0, 0.0, ((7, 1.0, 0.0),))
    got = crossings(p)
    assert got == pytest.approx([i * PI / 7 for i in range(1, 28)], abs=1e-12)


# -- non-finite results ----------------------------------------------------------------------------

def test_nonfinite_names_the_first_quantity():
    # the one non-finite policy looks at the results document, which is what gets printed
    from flywheel.cli.guard import first_nonfinite

    r = seed_task("triangle")
    assert first_nonfinite(r.to_document()) is None
    import dataclasses

    bad = dataclasses.replace(r, omega_max=math.inf)
    assert first_nonfinite(bad.to_document()) == ("omega_max", math.inf)
    rows = list(r.rows)
    rows[3] = dataclasses.replace(rows[3], A=math.nan)
    hit = first_nonfinite(dataclasses.replace(r, rows=tuple(rows)).to_document())
    assert hit[0] == "segments[3].A" and math.isnan(hit[1])
    # rev/min too: ω0 = 1e308 rad/s is finite, 30·ω0/π is not
    hit = first_nonfinite(dataclasses.replace(r, omega0=1e308).to_document())
    assert hit == ("rpm.omega0", math.inf)
    # an area diagram without crossing angles has NaN angles by design: not an overflow
    assert first_nonfinite(solve_areas([1.0, -1.0], J=1.0, omega0=1.0).to_document()) is None


def test_overflow_inside_the_computation_names_the_quantity():
    # moments near the limit of double precision: the cycle balance and the works cannot be
    # stated; the error names the quantity as the document would
    with pytest.raises(NotFiniteError) as e:
        seed_task("triangle", M_D=1e308)
    assert e.value.quantity == "M_C" and "inf N·m" in e.value.detail
    with pytest.raises(NotFiniteError) as e:
        solve(constant(1e308), triangle(1e308, 0.0, 1e-300), 1.0, omega0=1.0)
    assert e.value.quantity == "work_resistance"         # a slope of 1e308/5e-301 = inf


def test_readme_example_press():
    # the README's example case: M_D = 1500·90/360 N·m; A falls by (1500 − 375)·π/2 over the
    # punch and ΔT_нб = 1125·π/2 J; J = ΔT_нб/(δ·ω_ср²) with ω_ср = 120 rpm = 4π rad/s
    r = solve_file("task2_readme_press.toml")
    assert r.unknown == "driving" and r.M_D == pytest.approx(375.0, rel=1e-14)
    assert r.delta_T_max == pytest.approx(1125 * PI / 2, rel=1e-14)
    assert r.J_required == pytest.approx(1125 * PI / 2 / (0.05 * (4 * PI) ** 2), rel=1e-13)
    assert math.degrees(r.phi_omega_max) == pytest.approx(90.0)
    assert math.degrees(r.phi_omega_min) == pytest.approx(180.0)


def test_the_russian_summary_writes_angles_and_units_as_the_course_does(tmp_path):
    """The triangle's ε is largest on [0, π/2) (M_D alone: 15/12 = 1,25 рад/с²) and smallest at
    its peak π ((15 − 60)/12 = −3,75): said «при φ = 0° (0 рад)» and «при φ = 180° (π рад)»,
    not «0π», «1π»; the columns' units after a comma («длительность, с», «ε, рад/с²»), not in
    brackets beside «ω, рад/с»."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    res = CliRunner().invoke(app, ["task2", "--profile", "triangle", "--lang", "ru",
                                   "--epsilon", "--at", "45", "-o", str(tmp_path / "o")],
                             env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    out = res.stdout
    assert "1,25" in out and "при φ = 0° (0 рад)" in out
    assert "−3,75" in out and "при φ = 180° (π рад)" in out
    assert "(0,625π рад)" in out                      # ω_max where M_D = M_C: 5π/8
    assert "длительность, с" in out and "ε, рад/с²" in out and "от φ, °" in out
    assert "0π" not in out and "1π" not in out and "[с]" not in out and "φ°" not in out
