"""The dynamic analysis of the compressor against seed 000_e85f126679b234dc.txt and against
independent truths (cycle balance, numerical derivatives, the energy equation, closed forms).

Style: the seed's printed number in a comment, the tolerance half a unit of its last digit.
Where the seed's defects (seeds README) move a number, the test states the seed's value,
the program's, the gap, and reproduces the seed's number by re-introducing its defect.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.dynamics import energy, loads, sizing
from flywheel.dynamics.loads import LoadKey
from flywheel.cases.run import load_case, parse_case
from flywheel.errors import InputError
from flywheel.dynamics.pipeline import analyze

CASES = Path(__file__).resolve().parents[2] / "cases"
SEED_OMEGA = 2 * math.pi * 10          # ω_1ср = 62.832 rad/s
G = 9.81


def with_worksheet_spline(name: str = "compressor.toml"):
    """The case ``name`` with the worksheet's interpolation of the indicator tables, Mathcad's
    natural spline (cases/compressor.toml itself interpolates them monotonically: PCHIP)."""
    import tomllib

    data = tomllib.loads((CASES / name).read_text(encoding="utf-8"))
    for cy in data["cylinders"]:
        cy["interpolation"] = "natural-spline"
    return parse_case(data)


@pytest.fixture(scope="module")
def printed():
    """The compressor as cases/compressor.toml gives it (the seed's printed tables), with the
    worksheet's natural spline."""
    return analyze(with_worksheet_spline())


@pytest.fixture(scope="module")
def worksheet():
    """The compressor with the LP column recovered from the worksheet (seeds README, defect 2)."""
    return analyze(load_case(CASES / "compressor_worksheet.toml"))


@pytest.fixture(scope="module")
def fine_worksheet():
    return analyze(load_case(CASES / "compressor_worksheet.toml"), n_points=36000)


def at(results, deg):
    return results.index_of(math.radians(deg))


# -- values the defects do not touch (seeds README, item 9) ------------------------------------

def test_link_lengths_and_mean_speed(printed):
    s = printed.scalars
    assert s.crank_length == pytest.approx(0.1, abs=1e-12)       # seed: l1 = 0.1
    assert s.omega_mean == pytest.approx(62.832, abs=5e-4)        # seed: ω_1ср = 62.832


def test_forces_and_their_moments_at_120_deg(printed):
    a = printed.at[0]
    assert a.phi_deg == 120.0
    assert a.forces["HP"] == pytest.approx(2993, abs=0.5)         # seed: F_B(f) = 2.993·10³
    assert a.forces["LP"] == pytest.approx(3957, abs=0.5)         # seed: F_C(f) = 3.957·10³
    assert a.moments["gas HP"] == pytest.approx(225.981, abs=5e-4)  # seed: M_PRFB(f) = 225.981
    assert a.moments["gas LP"] == pytest.approx(241.04, abs=5e-3)   # seed: M_PRFC(f) = 241.04


def test_linear_interpolation_would_not_give_the_seeds_force():
    """Seeds README, defect 1: the printed F_C(120°) = 3957 N needs Mathcad's natural spline;
    linear interpolation gives 4120.2 N."""
    text = (CASES / "compressor.toml").read_text(encoding="utf-8")
    import tomllib

    data = tomllib.loads(text)
    for cy in data["cylinders"]:
        cy["interpolation"] = "linear"
    r = analyze(parse_case(data), n_points=720)
    assert r.at[0].forces["LP"] == pytest.approx(4120.2, abs=0.05)


def test_cycle_work_and_driving_moment_with_the_worksheet_column(worksheet):
    s = worksheet.scalars
    assert s.cycle_work_resistance == pytest.approx(-1204, abs=0.5)  # seed: A_C = −1.204·10³
    assert s.driving_moment == pytest.approx(191.6, abs=0.05)        # seed: M_PRD = 191.6


def test_cycle_work_with_the_printed_column(printed):
    """Seeds README, defect 2: with the printed p_ВВЕРХ1 column A_C ≈ −1237.4 J, M_PRD ≈ 196.94."""
    s = printed.scalars
    assert s.cycle_work_resistance == pytest.approx(-1237.4, abs=0.05)
    assert s.driving_moment == pytest.approx(196.94, abs=0.005)
    # the printed column is 2.8 % more work than the worksheet's results
    assert s.cycle_work_resistance / -1204 - 1 == pytest.approx(0.0278, abs=5e-4)


def test_flywheel_dimensions_by_the_course_formulas():
    """Seed 000, last block, for J_доп = 3.5476 (seeds README, defect 8: the printed D and m
    belong to 3.5476, not to the 3.5486 that its J_PRI gives)."""
    d, r = sizing.disk_course(3.5476), sizing.rim_course(3.5476)
    assert d["D"] == pytest.approx(0.471, abs=5e-4)          # seed: D_MX = 0.471
    assert d["mass"] == pytest.approx(127.67, abs=5e-3)      # seed: m_MX = 127.67
    assert d["b"] == pytest.approx(0.094, abs=5e-4)          # seed: b = 0.094
    assert r["D"] == pytest.approx(0.523, abs=5e-4)          # seed: D_MXc = 0.523
    assert r["b"] == pytest.approx(0.105, abs=5e-4)          # seed: b_MXc = 0.105
    assert r["D_inner"] == pytest.approx(0.418, abs=5e-4)    # seed: D_MX1 = 0.418
    assert r["mass"] == pytest.approx(63.072, abs=5e-4)      # seed: m_MXc = 63.072


def test_flywheel_dimensions_from_first_principles():
    """J = πρbD⁴/32 (disk), πρb(D⁴ − D1⁴)/32 (rim): steel reproduces the course's constants
    0.366 and 0.406 to their 3 digits; its masses differ from the rounded rules by 0.24 %
    (disk) and 0.2 % (rim), the diameters by under 0.1 %."""
    J = 3.5476
    d, r = sizing.disk(J), sizing.rim(J)
    assert math.pi * 7800 * d["b"] * d["D"] ** 4 / 32 == pytest.approx(J, rel=1e-12)
    assert math.pi * 7800 * r["b"] * (r["D"] ** 4 - r["D_inner"] ** 4) / 32 == pytest.approx(J, rel=1e-12)
    assert d["D"] == pytest.approx(0.471, abs=5e-4)
    assert d["mass"] / 127.67 - 1 == pytest.approx(0.0023, abs=2e-4)
    assert r["D"] == pytest.approx(0.523, abs=5e-4)
    assert r["mass"] / 63.072 - 1 == pytest.approx(0.0020, abs=2e-4)


def test_course_formulas_option_in_a_case():
    import tomllib

    data = tomllib.loads((CASES / "compressor.toml").read_text(encoding="utf-8"))
    data["flywheel"] = {"formulas": "course"}
    r = analyze(parse_case(data), n_points=360)
    s = r.scalars
    assert sizing.disk_course(s.J_flywheel).items() <= s.flywheel_disk.as_dict().items()
    assert sizing.rim_course(s.J_flywheel).items() <= s.flywheel_rim.as_dict().items()


def test_flywheel_on_a_faster_shaft_and_its_rim_speed():
    """A flywheel on a shaft turning i times faster needs J_M/i² (seed 003, eqs. 9.21–9.23);
    its rim speed is ω_max·i·D/2, checked against √(σ/ρ)."""
    import tomllib

    data = tomllib.loads((CASES / "compressor.toml").read_text(encoding="utf-8"))
    data["flywheel"] = {"speed_ratio": 4.0, "material": "cast-iron"}
    s = analyze(parse_case(data), n_points=720).scalars
    assert s.flywheel_J_on_its_shaft == pytest.approx(s.J_flywheel / 16, rel=1e-12)
    d = s.flywheel_disk
    assert math.pi * 7200 * d.b * d.D ** 4 / 32 == pytest.approx(s.J_flywheel / 16, rel=1e-12)
    assert d.rim_speed == pytest.approx(s.omega_max * 4 * d.D / 2, rel=1e-12)
    assert s.flywheel_rim_speed_limit == pytest.approx(math.sqrt(7e6 / 7200), rel=1e-12)  # 31.2 m/s


def test_rim_speed_warning_states_the_limit_its_source_and_the_material():
    import tomllib

    data = tomllib.loads((CASES / "compressor.toml").read_text(encoding="utf-8"))
    data["flywheel"] = {"speed_ratio": 4.0, "material": "cast-iron"}
    r = analyze(parse_case(data), n_points=720)
    rim = [w for w in r.warnings if w.startswith("flywheel as a rim: rim speed")]
    assert len(rim) == 1, r.warnings
    assert "exceeds the safe 31.2 m/s = √(σ/ρ) of a thin rotating ring" in rim[0]
    assert "Timoshenko" in rim[0] and "for cast-iron: σ = 7 MPa, ρ = 7200 kg/m³" in rim[0]
    data["flywheel"] = {"speed_ratio": 4.0, "density": 7000.0, "allowable_stress": 1e6}
    r = analyze(parse_case(data), n_points=720)
    rim = [w for w in r.warnings if w.startswith("flywheel as a rim: rim speed")]
    assert "for the given material: σ = 1 MPa, ρ = 7000 kg/m³" in rim[0]      # not "steel"
    data["flywheel"] = {}                                                     # the seed's: safe
    assert not [w for w in analyze(parse_case(data), n_points=720).warnings if "rim speed" in w]


# -- values the defects do touch: the seed's number, the program's, the defect ------------------

def _seed_projection(v_q, phi):
    """The seed's gravity 'projection' on (sin φ, cos φ), a direction turning with the crank
    (seeds README, defect 5)."""
    return v_q[:, 0] * np.sin(phi) + v_q[:, 1] * np.cos(phi)


def test_gravity_moments_seed_formula_and_the_correct_one(printed):
    """Seed: M_PRG2(f) = 0.089, M_PRG4 = −0.124, M_PRG3 = 0.222, M_PRG5 = −0.517 at 120°, with
    its turning projection; the correct moment m·g⃗·v_qS differs, and both stay below 1 N·m."""
    i = at(printed, 120)
    P, phi = printed.kinematics.points, printed.phi
    for point, mass, seed in (("S2", 0.8, 0.089), ("S4", 0.8, -0.124), ("B", 0.6, 0.222), ("C", 1.0, -0.517)):
        assert mass * G * _seed_projection(P[point].v_q, phi)[i] == pytest.approx(seed, abs=5e-4)
    ours = printed.at[0].moments
    assert ours["gravity 2"] == pytest.approx(0.8 * -G * P["S2"].v_q[i, 1], rel=1e-12)
    assert ours["gravity 5"] == 0.0                      # piston 5 moves horizontally
    assert max(abs(v) for k, v in ours.items() if k.startswith("gravity")) < 1


def test_reduced_inertia_seed_value_needs_its_halving_defect(printed):
    """Seed: J_PRII(75°) = 0.023 with every mass term multiplied by cos²(π/4) = ½ (defect 3);
    the kinetic energy of the links gives J_II(75°) = 0.03294 (+43 %)."""
    k = printed.kinematics
    i = at(printed, 75)
    P, L = k.points, k.links
    j_links = 0.21 * L["2"].omega_q[i] ** 2 + 0.21 * L["4"].omega_q[i] ** 2
    m_terms = (0.8 * P["S2"].v_q[i] @ P["S2"].v_q[i] + 0.6 * P["B"].v_q[i, 1] ** 2
               + 0.8 * P["S4"].v_q[i] @ P["S4"].v_q[i] + 1.0 * P["C"].v_q[i, 0] ** 2)
    assert j_links + 0.5 * m_terms == pytest.approx(0.023, abs=5e-4)      # seed: 0.023
    J_II = printed.columns["J_II"].values[i]
    assert J_II == pytest.approx(j_links + m_terms, rel=1e-12)
    assert J_II == pytest.approx(0.03294, abs=5e-6)


def test_derivative_of_reduced_inertia_seed_formula(printed):
    """Seed: dJ_PRII(75°) = −7.919·10⁻³, with m_4 in place of m_5 in dJ_PRM5 (defect 4);
    the program uses m_5 and gets −9.44·10⁻³."""
    k = printed.kinematics
    i = at(printed, 75)
    P, L = k.points, k.links
    common = (2 * 0.21 * L["2"].omega_q[i] * L["2"].eps_q[i] + 2 * 0.21 * L["4"].omega_q[i] * L["4"].eps_q[i]
              + 2 * 0.8 * P["S2"].v_q[i] @ P["S2"].a_q[i] + 2 * 0.6 * P["B"].v_q[i, 1] * P["B"].a_q[i, 1]
              + 2 * 0.8 * P["S4"].v_q[i] @ P["S4"].a_q[i])
    c_term = 2 * P["C"].v_q[i, 0] * P["C"].a_q[i, 0]
    assert common + 0.8 * c_term == pytest.approx(-7.919e-3, abs=5e-7)   # seed, with m_4
    dJ = printed.columns["dJ_II"].values[i]
    assert dJ == pytest.approx(common + 1.0 * c_term, rel=1e-12)
    assert dJ == pytest.approx(-9.44e-3, abs=5e-6)


def test_seed_energy_extremes_reproduced_with_its_defects_and_corrected(fine_worksheet):
    """Seed: ΔT_I local min −47.611 J at 0.66°, max 785.896 J at 222.98°, ΔT_нб = 833.507 J,
    J_PRI = 4.223. Re-introducing its defects (halved mass terms, turning gravity projection,
    local search from 30° and 120°) on our kinematics reproduces them; the global minimum of the
    same curve lies at 63.2°, 61.6 J lower (defect 6), so the seed undersizes the flywheel."""
    r = fine_worksheet
    phi, P, L = r.phi, r.kinematics.points, r.kinematics.links
    Mg = sum(m * G * _seed_projection(P[p].v_q, phi) for p, m in (("S2", .8), ("S4", .8), ("B", .6), ("C", 1.)))
    M_c = r.M_parts[LoadKey("gas", "HP")] + r.M_parts[LoadKey("gas", "LP")] + Mg
    M_d = -energy.cumulative_work(M_c, phi)[-1] / (2 * math.pi)
    A = energy.cumulative_work(M_c + M_d, phi)
    J_seed = (0.21 * L["2"].omega_q ** 2 + 0.21 * L["4"].omega_q ** 2
              + 0.5 * (0.8 * np.sum(P["S2"].v_q ** 2, 1) + 0.6 * P["B"].v_q[:, 1] ** 2
                       + 0.8 * np.sum(P["S4"].v_q ** 2, 1) + 1.0 * P["C"].v_q[:, 0] ** 2))
    dT = A - J_seed * SEED_OMEGA ** 2 / 2
    near0 = phi < math.radians(30)
    i_min = np.argmin(dT[near0])
    assert math.degrees(phi[near0][i_min]) == pytest.approx(0.66, abs=0.02)   # seed: 0.66°
    assert dT[near0][i_min] == pytest.approx(-47.611, abs=5e-3)              # seed: −47.611
    i_max = np.argmax(dT)
    assert math.degrees(phi[i_max]) == pytest.approx(222.98, abs=0.02)       # seed: 222.98°
    assert dT[i_max] == pytest.approx(785.896, abs=0.01)                     # seed: 785.896
    dT_seed = dT[i_max] - dT[near0][i_min]
    assert dT_seed == pytest.approx(833.507, abs=0.01)                       # seed: 833.507
    assert dT_seed / (SEED_OMEGA ** 2 * 0.05) == pytest.approx(4.223, abs=5e-4)   # seed: J_PRI
    # the same defective curve, searched globally
    assert math.degrees(phi[np.argmin(dT)]) == pytest.approx(63.2, abs=0.1)
    assert dT[near0][i_min] - dT.min() == pytest.approx(61.6, abs=0.1)
    # the program (all defects corrected): ΔT_нб = 902.6 J, J_I = 4.5726, +8.3 % on the seed
    s = r.scalars
    assert s.delta_T_max == pytest.approx(902.6, abs=0.05)
    assert s.J_required == pytest.approx(4.5726, abs=5e-4)
    assert s.J_required / 4.223 - 1 == pytest.approx(0.083, abs=1e-3)


def test_what_follows_from_the_seeds_J_PRI(worksheet):
    """The seed's numbers downstream of J_PRI, against the program's on the same inputs
    (worksheet column). Defect 6 (local ΔT_I minimum) makes J_PRI 8.3 % small, and with it the
    flywheel; defect 8 (ω(φ) from a hard-coded J_I = 2.68, ε with J_II in place of J_PRI)
    moves ω and ε at 120°."""
    s, a = worksheet.scalars, worksheet.at[0]
    # J_доп = J_PRI − J_10 − J_ред: seed 3.548, program 3.8986 (+9.9 %, defect 6)
    assert s.J_flywheel == pytest.approx(3.8986, abs=5e-4)
    assert s.J_flywheel / 3.548 - 1 == pytest.approx(0.099, abs=1e-3)
    # the course's disk for it: seed D = 0.471 m, m = 127.67 kg; program 0.4805 m, 135.10 kg
    disk = sizing.disk_course(s.J_flywheel)
    assert (disk["D"], disk["mass"]) == (pytest.approx(0.4805, abs=5e-5), pytest.approx(135.10, abs=5e-3))
    # the rim: seed D = 0.523 m, m = 63.072 kg; program 0.5330 m, 66.745 kg
    rim = sizing.rim_course(s.J_flywheel)
    assert (rim["D"], rim["mass"]) == (pytest.approx(0.5330, abs=5e-5), pytest.approx(66.745, abs=5e-4))
    # at 120°: seed ω1 = −62.732, ε = 152.592 (defect 8); program −62.9015, 140.04 from the
    # energy equation with the sized flywheel
    assert a.phi_deg == 120.0
    assert a.links["1"].omega == pytest.approx(-62.9015, abs=5e-4)
    assert a.epsilon == pytest.approx(140.04, abs=5e-3)
    # the rods: seed ω2 = −8.032, ω4 = 13.689; program −8.0537, 13.7262 (only ω differs)
    assert a.links["2"].omega == pytest.approx(-8.0537, abs=5e-4)
    assert a.links["4"].omega == pytest.approx(13.7262, abs=5e-4)


def test_seed_flywheel_gives_more_than_its_delta(fine_worksheet):
    """Defect 6 in physical terms: with the seed's J_PRI = 4.223 on the true loads the speed
    fluctuates by δ = 0.054 > 0.05."""
    from flywheel.dynamics import motion

    r = fine_worksheet
    A, J_II = r.columns["A"].values, r.columns["J_II"].values
    T0 = motion.T0_for_mean_speed(A, 4.223, J_II, SEED_OMEGA)
    delta = motion.speed_fluctuation(motion.omega_from_energy(T0, A, 4.223, J_II))[3]
    assert delta == pytest.approx(0.0538, abs=5e-4)


def test_true_velocities_from_the_seeds_omega_and_epsilon(printed):
    """Seed at 120°: with its ω = 62.732 and ε = 152.592 (both from defect 8's J_I = 2.68),
    the true values follow from our analogues to its printed digits: the formulas v = v_q·ω,
    a = a_q·ω² + v_q·ε, ω_i = ω_q·ω, ε_i = ε_q·ω² + ω_q·ε are the same."""
    i = at(printed, 120)
    P, L = printed.kinematics.points, printed.kinematics.links
    # the seed prints ω_1(f) = −62.732; its accelerations need more digits: 62.73155 (inside
    # the printed rounding) reproduces them all, to ±1 in their last digit
    w, e = 62.73155, 152.592
    v = lambda p: np.hypot(*P[p].v_q[i]) * w
    a = lambda p: np.hypot(*(P[p].a_q[i] * w ** 2 + P[p].v_q[i] * e))
    assert v("A") == pytest.approx(6.273, abs=5e-4)            # seed: V_A(f) = 6.273
    assert v("B") == pytest.approx(4.737, abs=5e-4)            # seed: V_B(f) = 4.737
    assert v("S2") == pytest.approx(5.667, abs=5e-4)           # seed: V_S2(f) = 5.667
    assert v("C") == pytest.approx(3.821, abs=5e-4)            # seed: V_C(f) = 3.821
    assert v("S4") == pytest.approx(5.063, abs=5e-4)           # seed: V_S4(f) = 5.063
    assert a("A") == pytest.approx(393.82, abs=5e-3)           # seed: a_A(f) = 393.82
    assert a("B") == pytest.approx(234.386, abs=1.5e-3)          # seed: a_B(f) = 234.386
    assert a("C") == pytest.approx(400.857, abs=1.5e-3)          # seed: a_C(f) = 400.857
    assert a("S2") == pytest.approx(314.658, abs=1.5e-3)         # seed: a_S2(f) = 314.658
    assert a("S4") == pytest.approx(386.161, abs=1.5e-3)         # seed: a_S4(f) = 386.161
    assert L["1"].omega_q[i] * w == pytest.approx(-62.732, abs=5e-4)   # seed: ω_1(f) = −62.732
    assert L["2"].omega_q[i] * w == pytest.approx(-8.032, abs=5e-4)    # seed: ω_2(f) = −8.032
    assert L["4"].omega_q[i] * w == pytest.approx(13.689, abs=5e-4)    # seed: ω_4(f) = 13.689
    eps = lambda k: L[k].eps_q[i] * w ** 2 + L[k].omega_q[i] * e
    assert eps("2") == pytest.approx(-877.936, abs=1.5e-3)       # seed: ε_2(f) = −877.936
    assert eps("4") == pytest.approx(-438.887, abs=1.5e-3)       # seed: ε_4(f) = −438.887


# -- independent checks ------------------------------------------------------------------------

@pytest.mark.parametrize("name", ["compressor.toml", "compressor_worksheet.toml"])
def test_cycle_work_is_the_area_of_the_indicator_diagrams(name):
    """The gas forces' work over a cycle is the area of each indicator diagram, independent of
    the linkage and of the φ integration: −p_max·(πd²/4)·stroke·∫₀¹(p_towards − p_away) ds, with
    the tables' natural splines integrated by scipy (gravity does no net work). The balancing
    moment then makes A(Φ) = 0."""
    from scipy.interpolate import CubicSpline

    case = with_worksheet_spline(name)
    r = analyze(case)
    stroke = 2 * case.crank_length                    # both guides pass through the crank axis
    area = 0.0
    for cy in case.cylinders:
        up = CubicSpline(cy.s, cy.towards_head, bc_type="natural").integrate(0, 1)
        down = CubicSpline(cy.s, cy.away_from_head, bc_type="natural").integrate(0, 1)
        area += -cy.p_max * math.pi * cy.bore**2 / 4 * stroke * (up - down)
    assert r.scalars.cycle_work_resistance == pytest.approx(area, rel=1e-6)
    assert r.scalars.driving_moment == pytest.approx(-area / (2 * math.pi), rel=1e-6)
    A = r.columns["A"].values
    assert abs(A[-1]) < 1e-9 * np.max(np.abs(A))


def test_gravity_does_no_work_over_a_cycle(fine_worksheet):
    r = fine_worksheet
    for k, M in r.M_parts.items():
        if k.kind == "gravity":
            assert abs(energy.cumulative_work(M, r.phi)[-1]) < 1e-9


def test_dJ_is_the_derivative_of_J(fine_worksheet):
    r = fine_worksheet
    J, dJ = r.columns["J_II"].values, r.columns["dJ_II"].values
    num = np.gradient(J, r.phi, edge_order=2)
    assert np.max(np.abs(num - dJ)) < 1e-6 * np.max(np.abs(dJ))


def test_epsilon_is_omega_domega_dphi(fine_worksheet):
    r = fine_worksheet
    w, e = r.columns["omega"].values, r.columns["epsilon"].values
    num = w * np.gradient(w, r.phi, edge_order=2)
    inner = slice(5, -5)
    assert np.max(np.abs(num[inner] - e[inner])) < 2e-3 * np.max(np.abs(e))


def test_delta_achieved(printed):
    s = printed.scalars
    # the exact size gives the target δ; Merzalov's (ω_m² in place of the varying ω²) gives
    # 0.7 % less fluctuation on this machine
    assert s.delta_achieved_exact == pytest.approx(0.05, rel=1e-4)
    assert s.delta_achieved == pytest.approx(0.05, rel=0.02)
    assert s.delta_achieved < 0.05
    # both ways give a mean speed of ω_m
    assert 0.5 * (s.omega_max + s.omega_min) == pytest.approx(s.omega_mean, rel=1e-9)


@pytest.mark.parametrize("name", ["compressor.toml", "slotted_link.toml", "fourbar.toml"])
def test_convergence_with_a_finer_grid(name):
    """Headline results change by less than 1e-4 relative between the default grid and one
    four times finer (the slotted link has a cutting force over part of the ram's stroke)."""
    case = load_case(CASES / name)
    a, b = analyze(case).scalars, analyze(case, n_points=4 * 3600).scalars
    for key in ("cycle_work_resistance", "driving_moment", "delta_T_max", "J_II_mean", "J_required",
                "J_required_exact", "J_flywheel", "delta_achieved", "delta_achieved_exact"):
        assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-4), key


# -- closed forms ------------------------------------------------------------------------------

def test_cutting_force_work_is_force_times_travel():
    """cases/slotted_link.toml: 1500 N over s = 0.05 … 0.95 of the ram's stroke on one stroke:
    A_C = −1500·0.9·stroke, the stroke from the dead centres the program finds."""
    case = load_case(CASES / "slotted_link.toml")
    r = analyze(case, n_points=720)
    from flywheel.cases.run import to_mechanism
    from flywheel.linkage.deadcentres import dead_centres

    xs = [dc.x for dc in dead_centres(to_mechanism(case), "5")]
    stroke = max(xs) - min(xs)
    assert stroke == pytest.approx(0.541667, abs=5e-7)        # the case's comment: 0.541667 m
    # exact up to the dead centres' own precision (6·10⁻¹⁰ relative)
    assert r.scalars.cycle_work_resistance == pytest.approx(-1500 * 0.9 * stroke, rel=1e-8)

def _slider_crank_case(balance="driving", masses=False, towards=1.0, away=0.0):
    """A centric horizontal slider-crank r = 0.05, l = 0.2, one cylinder with constant p/p_max
    on each stroke; massless unless asked."""
    data = {
        "title": "centric slider-crank",
        "machine": {"speed_rpm": 600.0, "delta": 0.02, "balance": balance, "gravity": [0.0, 0.0]},
        "crank": {"length": 0.05, "start_angle_deg": 0.0, "rotation": "ccw"},
        "dyads": [{"kind": "RRP", "from": "A", "joint": "B", "rod": "2", "rod_length": 0.2,
                   "slider": "3", "guide": {"angle_deg": 0.0}}],
        "cylinders": [{"name": "c", "piston": "3", "bore": 0.1, "p_max": 1e6, "head": "outer",
                       "s": [0.0, 1.0], "towards_head": [towards, towards],
                       "away_from_head": [away, away]}],
    }
    if masses:
        data["links"] = {"3": {"mass": 2.0, "centroid": "B"}}
    return parse_case(data)


def test_constant_force_on_one_stroke_closed_form():
    """Compression at constant p over the stroke 2r: A_C = −p·(πd²/4)·2r,
    M_D = −A_C/2π, and A(φ) = M_D·φ − F·(x(0) − x(φ)) while compressing,
    x(φ) = r·cos φ + √(l² − r² sin² φ)."""
    r_, l_, F = 0.05, 0.2, 1e6 * math.pi * 0.1 ** 2 / 4
    res = analyze(_slider_crank_case(), n_points=7200)
    s = res.scalars
    # the trapezoid rule on 7200 intervals: 6·10⁻⁸ relative
    assert s.cycle_work_resistance == pytest.approx(-F * 2 * r_, rel=1e-6)
    M_D = F * 2 * r_ / (2 * math.pi)
    assert s.driving_moment == pytest.approx(M_D, rel=1e-6)
    phi = res.phi
    x = r_ * np.cos(phi) + np.sqrt(l_ ** 2 - r_ ** 2 * np.sin(phi) ** 2)
    # head outer at φ = 0; the piston moves towards the head for φ in (π, 2π)
    A_exact = M_D * phi - np.where(phi > math.pi, F * (x - x[np.argmin(np.abs(phi - math.pi))]), 0.0)
    assert np.max(np.abs(res.columns["A"].values - A_exact)) < 1e-5 * F * r_
    # no second-group inertia: J_II = 0 and Merzalov's size is exact: ΔT_нб/(δ·ω_m²)
    assert s.J_required_exact == pytest.approx(s.J_required, rel=1e-12)
    dT = A_exact.max() - A_exact.min()
    assert s.delta_T_max == pytest.approx(dT, rel=1e-6)


def test_engine_balance_takes_a_resistance_moment():
    """An 'engine': gas pushes the piston on its stroke away from the head; the constant
    resistance moment balances it: M_C = −F·2r/2π."""
    r_, F = 0.05, 1e6 * math.pi * 0.1 ** 2 / 4
    res = analyze(_slider_crank_case("resistance", towards=0.0, away=1.0), n_points=3600)
    assert res.scalars.balancing_moment == pytest.approx(-F * 2 * r_ / (2 * math.pi), rel=1e-6)
    assert res.scalars.cycle_work_resistance == pytest.approx(-F * 2 * r_, rel=1e-6)


def test_wrong_balance_sign_is_an_input_error():
    with pytest.raises(InputError, match="balance"):
        analyze(_slider_crank_case("driving", towards=0.0, away=1.0), n_points=360)
    with pytest.raises(InputError, match="balance"):
        analyze(_slider_crank_case("resistance"), n_points=360)


@pytest.mark.parametrize("balance", ["driving", "resistance"])
def test_loads_without_net_work_need_no_constant_moment_whichever_the_balance(balance):
    """The four-bar under its weights only: gravity is conservative, its work over a cycle is
    zero (the potential energy returns), so no constant moment balances anything: M = 0, the
    flywheel only smooths the weights' periodic moment — the same machine whichever balance
    is named, with a warning."""
    from flywheel.io.toml import read_toml

    doc = read_toml(CASES / "fourbar.toml")
    base = analyze(parse_case(doc, "fourbar.toml"), n_points=720).scalars
    doc["machine"]["balance"] = balance
    res = analyze(parse_case(doc, "fourbar.toml"), n_points=720)
    s = res.scalars
    assert s.balancing_moment == 0.0 and s.driving_moment == 0.0
    assert s.cycle_work_resistance == 0.0
    for key in ("delta_T_max", "J_required", "J_required_exact", "omega_max", "omega_min"):
        assert getattr(s, key) == getattr(base, key), key
    assert any("no net work" in w for w in res.warnings)


def test_slider_mass_reduced_inertia_closed_form():
    """A piston of mass m on a centric slider-crank: J_II = m·ẋ_q², with
    ẋ_q = −r·sin φ·(1 + r·cos φ/√(l² − r² sin² φ))."""
    res = analyze(_slider_crank_case(masses=True), n_points=720)
    phi, r_, l_ = res.phi, 0.05, 0.2
    xq = -r_ * np.sin(phi) * (1 + r_ * np.cos(phi) / np.sqrt(l_ ** 2 - r_ ** 2 * np.sin(phi) ** 2))
    assert np.allclose(res.columns["J_II"].values, 2.0 * xq ** 2, rtol=1e-12, atol=1e-15)


def test_natural_spline_matches_scipy():
    from scipy.interpolate import CubicSpline

    s = np.linspace(0, 1, 11)
    p = np.array([1, 1, 1, .58, .46, .28, .26, .16, .08, .04, 0])
    q = np.linspace(0, 1, 1001)
    assert np.allclose(loads.natural_spline(s, p, q), CubicSpline(s, p, bc_type="natural")(q),
                       rtol=0, atol=1e-13)


@pytest.mark.parametrize("seed", range(6))
def test_pchip_is_scipys_to_the_last_bit(seed):
    """loads.pchip (numpy, so a run does not import scipy.interpolate) against scipy's
    PchipInterpolator: the compressor's indicator table, and random tables with flat parts,
    sign changes and uneven spacing, at random points and at the nodes — equal, not close."""
    from scipy.interpolate import PchipInterpolator

    rng = np.random.default_rng(seed)
    tables = [(np.linspace(0, 1, 11), np.array([1, 1, 1, .58, .46, .28, .26, .16, .08, .04, 0]))]
    for n in (2, 3, 5, 12):
        x = np.cumsum(rng.uniform(0.05, 1.0, n))
        y = rng.normal(size=n) * rng.choice([1.0, 0.0], n, p=[0.8, 0.2])
        tables.append((x, y))
    for x, y in tables:
        q = np.concatenate([rng.uniform(x[0], x[-1], 500), x])
        assert np.array_equal(loads.pchip(x, y, q), PchipInterpolator(x, y)(q))


def test_a_run_of_the_compressor_imports_no_scipy(tmp_path):
    """Its indicator tables are PCHIP: interpolated by loads.pchip, not scipy (0.3 – 0.7 s)."""
    import subprocess
    import sys

    code = ("import sys; from flywheel.cases.run import load_case; "
            "from flywheel.dynamics.pipeline import analyze; "
            f"analyze(load_case({str(CASES / 'compressor.toml')!r})); "
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'scipy'))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "[]"


def test_negative_pressure_warning(printed):
    assert any("negative pressure" in w for w in printed.warnings)


def test_the_flagship_runs_clean():
    """cases/compressor.toml interpolates its indicator tables monotonically (PCHIP): no
    overshoot, no warning; the worksheet's case keeps its natural spline and its warning."""
    assert load_case(CASES / "compressor.toml").cylinders[0].interpolation == "pchip"
    assert analyze(load_case(CASES / "compressor.toml"), n_points=720).warnings == ()
    ws = load_case(CASES / "compressor_worksheet.toml")
    assert {c.interpolation for c in ws.cylinders} == {"natural-spline"}


# -- the grid and the shape of the results -------------------------------------------------------

def _same_kinematics(a, b) -> bool:
    return (np.array_equal(a.phi, b.phi) and list(a.points) == list(b.points)
            and list(a.links) == list(b.links)
            and all(np.array_equal(getattr(a.points[n], f), getattr(b.points[n], f))
                    for n in a.points for f in ("r", "v_q", "a_q"))
            and all(np.array_equal(getattr(a.links[n], f), getattr(b.links[n], f))
                    for n in a.links for f in ("theta", "omega_q", "eps_q")))


def test_switch_angle_nodes_are_solved_alone_yet_equal_a_whole_solve():
    """The angles where the slotted link's cutting force switches on and off are added to the
    grid and only they are solved (grid.refined); the kinematics equal solve() on the whole
    grid bit for bit, so the results do not depend on how the grid was built."""
    from flywheel.cases.run import to_mechanism
    from flywheel.dynamics.grid import closed_grid, force_switch_angles, linkage_grid, refined, standard_positions
    from flywheel.linkage import solve

    case = load_case(CASES / "slotted_link.toml")
    mech = to_mechanism(case)
    positions, dcs = standard_positions(mech)
    extra = [p.phi for p in positions]
    first = closed_grid(720, extra)
    switch = force_switch_angles(case.forces, mech, dcs, first, solve(mech, first))
    phi, kin = linkage_grid(case, mech, dcs, 720, extra)
    assert len(switch) == 4 and phi.size == first.size + 4    # s = 0.05 and 0.95, both ways
    assert all(np.min(np.abs(phi - a)) == 0 and np.min(np.abs(first - a)) > 1e-6 for a in switch)
    assert _same_kinematics(kin, solve(mech, phi))
    # an added angle a hair below a node takes its place (the smaller one stays): that node is
    # dropped, the new one solved
    coarse = closed_grid(72, [])
    finer = closed_grid(72, [coarse[5] - 5e-10, 1.0])
    assert finer.size == coarse.size + 1 and coarse[5] not in finer
    assert _same_kinematics(refined(mech, solve(mech, coarse), finer), solve(mech, finer))


def test_results_are_frozen_and_the_document_is_the_summary(printed, tmp_path):
    """Every stage result is frozen; summary.json is the results' document, which the
    stages' fields fill (the flywheel's tangents from the energy–mass diagram, the rim share)."""
    import dataclasses
    import json

    from flywheel.render.tables import summary_json

    for part in (printed, printed.loads, printed.reduction, printed.energy, printed.sizing,
                 printed.motion):
        with pytest.raises(dataclasses.FrozenInstanceError):
            part.warnings = ()
    doc = printed.to_document()
    assert json.loads(summary_json(printed)) == doc
    assert doc["results"]["J_required_exact"] == printed.sizing.J_required_exact
    assert doc["results"]["flywheel_rim_share"] == printed.sizing.rim_share == 1.0
    assert doc["warnings"] == list(printed.warnings)
    sz, A, J = printed.sizing, printed.energy.A, printed.reduction.J_II
    # the tangents cut J_II = 0 at max(A − k₊J_II) and min(A − k₋J_II), where they touch
    assert sz.T_k == pytest.approx(np.max(A - sz.k_plus * J), rel=1e-12)
    assert sz.T_l == pytest.approx(np.min(A - sz.k_minus * J), rel=1e-12)
    assert A[sz.i_tangent_max] - sz.k_plus * J[sz.i_tangent_max] == np.max(A - sz.k_plus * J)
    assert sz.T_k - sz.T_l == pytest.approx(sz.J_required_exact * (sz.k_plus - sz.k_minus), rel=1e-12)
