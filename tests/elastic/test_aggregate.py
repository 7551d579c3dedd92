"""`flywheel aggregate`: the two-mass aggregate of seed 003 (Ефанов, ch. 9, eqs. 9.20–9.25), rotor
chains with gears, the steady forced vibration, start-up, the textbook problem and the CLI."""
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from helpers import en_numbers, ru_numbers, same_numbers  # tests/helpers.py

from flywheel.elastic.chain import (Drive, chain, coefficients, damping_matrix, mass_matrix,
                                    mean_reduced_inertia, reduced_inertia_I, shaft_stiffness,
                                    starting_torque_from_rated, stiffness_matrix, twist_transform)
from flywheel.elastic.modes import natural_frequencies, resonant_mode, two_mass_frequency
from flywheel.elastic.forced import forced_twist_two_mass, steady_state
from flywheel.elastic.timedomain import (MAX_FAST_PERIODS, energy, simulate, start_up, state_space,
                                         steady_run)
from flywheel.elastic.model import analyze
from flywheel.cases.aggregate import load_aggregate_case, parse_aggregate_case, to_model
from flywheel.errors import CaseFileError, InputError
from helpers import err_text  # a CliRunner result's stderr (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
KEYS = {"natural_frequencies_hz", "twist_amplitude", "elastic_moment_amplitude", "delta_motor",
        "delta_machine"}


# -- coefficients and natural frequencies --------------------------------------------------------

@pytest.mark.parametrize("J1, J2, c", [(0.1, 0.787, 3000.0), (2.0, 5.0, 1.0e5), (1e-3, 40.0, 7.5)])
def test_two_mass_natural_frequency(J1, J2, c):
    modes = natural_frequencies(chain([J1, J2], [c]))
    assert modes.omega[0] == 0.0                                  # the rigid-body mode
    assert modes.elastic[0] == pytest.approx(math.sqrt(c * (J1 + J2) / (J1 * J2)), rel=1e-12)
    assert two_mass_frequency(J1, J2, c) == pytest.approx(modes.elastic[0], rel=1e-12)


def test_coefficients_of_the_seed():
    # (9.25): T = ½[J_Д q̇1² + J_пр.I (q̇1 + q̇2)²] -> a11 = J_Д + J_пр.I, a12 = a21 = a22 = J_пр.I;
    # Π = ½ c q2² -> c22 = c, the rest 0
    a, c = coefficients(chain([0.4, 2.5], [800.0]))
    assert a.tolist() == [[2.9, 2.5], [2.5, 2.5]]
    assert c.tolist() == [[0.0, 0.0], [0.0, 800.0]]


def test_coefficients_give_the_same_frequencies_in_q():
    from scipy.linalg import eigh

    ch = chain([1.0, 2.0, 0.5, 3.0], [100.0, 250.0, 80.0])
    a, c = coefficients(ch)
    lam = eigh(c, a, eigvals_only=True)
    assert np.sqrt(np.clip(lam, 0, None)) == pytest.approx(natural_frequencies(ch).omega,
                                                             rel=1e-10, abs=1e-6)


def test_flywheel_reduction_9_21_to_9_23():
    J_III, J_M, i21, i31 = 0.7, 4.0, 0.6, 0.25
    assert reduced_inertia_I(J_III, i31, J_M, "III") == pytest.approx(J_M * i31**2 + J_III * i31**2)
    assert reduced_inertia_I(J_III, i31, J_M, "II", i21) == pytest.approx(J_M * i21**2 + J_III * i31**2)
    assert reduced_inertia_I(J_III, i31, J_M, "I") == pytest.approx(J_M + J_III * i31**2)
    # J_пр.III = J_пр.0 + ΣJ̃_i/12 over the 12 positions
    assert mean_reduced_inertia(0.5, [0.12] * 6 + [0.0] * 6) == pytest.approx(0.56)


def test_three_rotor_chain_against_its_matrices():
    ch = chain([0.8, 2.0, 0.3], [1.2e4, 3.0e4])
    M, K = mass_matrix(ch), stiffness_matrix(ch)
    ref = np.sort(np.sqrt(np.clip(np.linalg.eigvals(np.linalg.solve(M, K)).real, 0, None)))
    got = natural_frequencies(ch).omega
    assert got == pytest.approx(ref, rel=1e-10, abs=1e-6)
    # the closed form of the free three-rotor system: ω⁴ − ω²·[c1(1/J1 + 1/J2) + c2(1/J2 + 1/J3)]
    # + c1·c2·(J1 + J2 + J3)/(J1·J2·J3) = 0
    J1, J2, J3, c1, c2 = 0.8, 2.0, 0.3, 1.2e4, 3.0e4
    b = c1 * (1 / J1 + 1 / J2) + c2 * (1 / J2 + 1 / J3)
    p = c1 * c2 * (J1 + J2 + J3) / (J1 * J2 * J3)
    roots = sorted([(b - math.sqrt(b * b - 4 * p)) / 2, (b + math.sqrt(b * b - 4 * p)) / 2])
    assert got[1:] ** 2 == pytest.approx(roots, rel=1e-10)


def test_mode_shapes_are_m_orthogonal():
    ch = chain([0.8, 2.0, 0.3, 1.1], [1.2e4, 3.0e4, 5e3])
    X = natural_frequencies(ch).shapes
    G = X.T @ mass_matrix(ch) @ X
    assert np.abs(G - np.diag(np.diag(G))).max() < 1e-10 * np.abs(G).max()


# -- the case format: shafts, gears, segments -----------------------------------------------------

def _chain_case(rotors, shafts, **extra):
    data = {"rotors": [{"J": j} for j in rotors], "shafts": shafts, **extra}
    return to_model(parse_aggregate_case(data))


def test_shaft_stiffness_and_stepped_shaft():
    c = shaft_stiffness(80e9, 0.05, 0.8)
    assert c == pytest.approx(80e9 * math.pi * 0.05**4 / 32 / 0.8)
    ch, _ = _chain_case([1.0, 2.0], [{"G": 80e9, "segments": [{"d": 0.05, "L": 0.8},
                                                              {"d": 0.08, "L": 0.3},
                                                              {"c": 2.0e5}]}])
    expected = 1 / (1 / c + 1 / shaft_stiffness(80e9, 0.08, 0.3) + 1 / 2.0e5)
    assert ch.c[0] == pytest.approx(expected, rel=1e-12)


def test_geared_branch_reduced_by_the_square_of_the_ratio():
    # motor J1 — shaft c1 (motor speed) — gears, pump turns at i = 1/3 — shaft c2 — pump J2:
    # reduced to the motor's speed J2·i², c2·i², in series with c1 (Khurmi & Gupta ch. 24,
    # "torsionally equivalent shaft" of a geared system)
    J1, J2, c1, c2, i = 400.0, 1500.0, 3.5e5, 1.4e6, 1 / 3
    ch, _ = _chain_case([J1, J2], [{"i": i, "segments": [{"c": c1}, {"c": c2, "side": "out"}]}])
    c_eq = 1 / (1 / c1 + 1 / (c2 * i * i))
    assert ch.J[1] == pytest.approx(J2 * i * i)
    assert ch.ratio.tolist() == pytest.approx([1.0, i])
    assert natural_frequencies(ch).elastic[0] == pytest.approx(
        two_mass_frequency(J1, J2 * i * i, c_eq), rel=1e-12)


def test_gear_between_three_rotors():
    # the ratio of the first connection also reduces the second shaft and the third rotor
    ch, _ = _chain_case([1.0, 2.0, 3.0], [{"c": 100.0, "i": 2.0}, {"c": 50.0}])
    assert ch.J.tolist() == pytest.approx([1.0, 8.0, 12.0])
    assert ch.c.tolist() == pytest.approx([100.0, 200.0])


# -- the textbook problem -------------------------------------------------------------------------

def test_khurmi_three_rotor_oil_engine_and_pump():
    # R.S. Khurmi & J.K. Gupta, Theory of Machines, ch. 24 "Torsional Vibrations": three-rotor
    # system, I_A = 0.15, I_B = 0.3, I_C = 0.09 kg·m², 70 mm shaft, A–B 1.5 m, B–C 1 m,
    # C = 84 kN/mm². Published: two-node frequency 277 Hz, nodes 0.4356 m from A and 0.726 m
    # from C (printed to 1 Hz and to 0.1 mm / 1 mm: the tolerances below are that precision).
    case = load_aggregate_case(CASES / "aggregate_khurmi_three_rotor.toml")
    ch, drive = to_model(case)
    assert drive is None
    f = natural_frequencies(ch).elastic / (2 * math.pi)
    assert f[1] == pytest.approx(277, abs=0.5)                     # book: 277 Hz
    assert f[1] == pytest.approx(277.034007, rel=1e-8)
    # the book's node method: a disc at the end of the shaft and its node form a cantilever with
    # the system's frequency, I_A·l_A = I_C·l_C, and the middle disc B between the two nodes:
    # 1/(I_A·l_A) = (1/I_B)·[1/(l1 − l_A) + 1/(l2 − l_C)]  ->  a quadratic in l_A whose two roots
    # are the two-node and the single-node mode
    IA, IB, IC, l1, l2 = 0.15, 0.3, 0.09, 1.5, 1.0
    GIp = 84e9 * math.pi * 0.07**4 / 32
    k = IA / IC
    roots = np.roots([IB * k + IA * (k + 1), -(IB * (k * l1 + l2) + IA * (l1 + l2)), IB * l1 * l2])
    lA = np.sort(roots.real)
    assert lA[0] == pytest.approx(0.4356, abs=1e-4)              # book: 0.4356 m from A
    assert k * lA[0] == pytest.approx(0.726, abs=5e-4)           # book: 0.726 m from C
    f_node = np.sqrt(GIp / (lA * IA)) / (2 * math.pi)            # [two-node, single-node]
    assert f_node[0] == pytest.approx(f[1], rel=1e-9)            # 277.03 Hz
    assert f_node[1] == pytest.approx(f[0], rel=1e-9)            # 170.69 Hz (l_A = 1.148 m)
    assert f[0] == pytest.approx(170.687713, rel=1e-8)


def test_stiffness_coefficients_are_exact_for_a_chain():
    # Π = ½·Σ c_k·(φ_(k+1) − φ_k)² = ½·Σ c_k·q_(k+1)²: c_ij = diag(0, c_1, …); no round-off
    ch = to_model(load_aggregate_case(CASES / "aggregate_khurmi_three_rotor.toml"))[0]
    a, c = coefficients(ch)
    assert c.tolist() == np.diag([0.0, *ch.c]).tolist()
    T = twist_transform(ch.n)
    assert a == pytest.approx(T.T @ mass_matrix(ch) @ T, rel=1e-15)
    assert (a == a.T).all()
    assert c == pytest.approx(T.T @ stiffness_matrix(ch) @ T, abs=1e-9)
    d = json.loads(cli(CASES / "aggregate_khurmi_three_rotor.toml", "--json").stdout)
    assert d["c"][0] == [0.0, 0.0, 0.0] and d["c"][1][0] == 0.0 and d["c"][1][2] == 0.0


# -- steady forced vibration ----------------------------------------------------------------------

def _constant_drive(M0=0.0, amplitude=10.0, ratio=1.0, omega=30.0):
    return Drive("constant", M0, amplitude, ratio, omega_nominal=omega)


def test_undamped_forced_amplitude_closed_form():
    J1, J2, c, A = 0.5, 2.0, 1.0e3, 40.0
    wn = math.sqrt(c * (J1 + J2) / (J1 * J2))
    for w in (0.3 * wn, 0.8 * wn, 1.7 * wn):         # away from resonance, both sides
        ch = chain([J1, J2], [c])
        st = steady_state(ch, _constant_drive(M0=15.0, amplitude=A, omega=w))
        expected = A / (J2 * abs(w * w - wn * wn))   # derived by Cramer's rule in the docstring
        assert st.twist_amplitude[0] == pytest.approx(expected, rel=1e-12)
        assert forced_twist_two_mass(J1, J2, c, A, w) == pytest.approx(expected, rel=1e-15)
        assert st.moment_amplitude[0] == pytest.approx(c * expected, rel=1e-12)
        assert st.twist_mean[0] == pytest.approx(-15.0 / c)
        assert st.moment_mean[0] == pytest.approx(15.0)


def test_solve_ivp_stays_on_the_closed_form_orbit():
    J1, J2, c = 0.5, 2.0, 1.0e3
    ch = chain([J1, J2], [c])
    drive = _constant_drive(M0=15.0, amplitude=40.0, omega=25.0)
    st = steady_state(ch, drive)
    h = steady_run(ch, drive, st, periods=3, per_period=400)
    q = h.phi[1] - h.phi[0]
    assert (q.max() - q.min()) / 2 == pytest.approx(st.twist_amplitude[0], rel=1e-4)
    assert q.mean() == pytest.approx(st.twist_mean[0], abs=2e-3 * st.twist_amplitude[0])


def test_damped_linear_motor_steady_state_matches_solve_ivp():
    ch = chain([0.3, 1.5], [2.0e3], [3.0])
    drive = Drive("linear", 40.0, 25.0, 0.5, M_start=400.0, omega_x=157.0)
    st = steady_state(ch, drive)
    assert st.omega_mean == pytest.approx(157.0 * (1 - 40.0 / 400.0))
    h = steady_run(ch, drive, st, periods=3, per_period=400)
    for k in (0, 1):
        amp = (h.omega[k].max() - h.omega[k].min()) / 2
        assert amp == pytest.approx(st.omega_amplitude[k], rel=1e-4)


def test_exact_resonance_without_damping_is_an_error():
    J1, J2, c = 1.0, 1.0, 2.0e3
    wn = math.sqrt(c * (J1 + J2) / (J1 * J2))
    with pytest.raises(InputError, match="unbounded"):
        steady_state(chain([J1, J2], [c]), _constant_drive(omega=wn))
    # with damping the amplitude at resonance is finite: M̃/(ω·b) for equal masses, since the
    # relative coordinate obeys (J/2)·q̈ + b·q̇ + c·q = −M̃/2·sin ωt
    st = steady_state(chain([J1, J2], [c], [0.5]), _constant_drive(amplitude=10.0, omega=wn))
    assert st.twist_amplitude[0] == pytest.approx(10.0 / 2 / (wn * 0.5), rel=1e-9)


def test_forcing_near_but_not_at_an_undamped_mode_is_finite():
    J1, J2, c, A = 1.0, 1.0, 2.0e3, 0.01
    wn = math.sqrt(c * (J1 + J2) / (J1 * J2))
    for w in (wn * (1 + 1e-4), wn * (1 - 1e-4)):
        st = steady_state(chain([J1, J2], [c]), _constant_drive(amplitude=A, omega=w))
        assert st.twist_amplitude[0] == pytest.approx(forced_twist_two_mass(J1, J2, c, A, w),
                                                      rel=1e-6)


def test_stiff_light_motor_is_not_a_false_resonance():
    # /tmp/audit d9: J_Д = 1e-30, c = 1e30: ω_n = 1e30 rad/s, the forcing 10.47 rad/s is nowhere
    # near it (the matrix is ill-conditioned, not singular)
    ch = chain([1e-30, 1.0], [1e30])
    st = steady_state(ch, _constant_drive(amplitude=1.0, omega=100 * math.pi / 30))
    w = st.omega_forcing
    assert st.twist_amplitude[0] == pytest.approx(forced_twist_two_mass(1e-30, 1.0, 1e30, 1.0, w),
                                                  rel=1e-9)
    # the whole machine swings as a rigid body: speed amplitude M̃/(ω·ΣJ)
    assert st.omega_amplitude[1] == pytest.approx(1.0 / (w * (1.0 + 1e-30)), rel=1e-9)


def test_slow_forcing_is_the_rigid_body_mode_not_a_resonance(tmp_path):
    # /tmp/audit d1: 1e-6 rev/min; before: "equals the natural frequency 14.1421 rad/s"
    text = TWO_MASS.format(J1=1.0, J2=1.0, c=100.0, i31=1.0).replace("300.0", "1e-6")
    res = cli(_write(tmp_path, text), "--json")
    err = err_text(res)
    assert res.exit_code == 2 and err.count("\n") == 1
    assert "equals the natural frequency" not in err
    assert "rigid body (the ω = 0 mode" in err and "turn backwards" in err
    # the same with a modest speed swing beyond the mean (δ > 2): no steady run either
    with pytest.raises(InputError, match="turn backwards"):
        steady_state(chain([0.01, 0.01], [1e6]), Drive("constant", 1.0, 0.5, 0.1,
                                                                omega_nominal=2 * math.pi))


def test_resonance_needs_an_undamped_mode():
    # three rotors, damping on one connection only: every mode twists it, so none is undamped
    ch = chain([1.0, 2.0, 1.5], [1.0e4, 2.0e4], [0.0, 3.0])
    modes = natural_frequencies(ch)
    for wn in modes.elastic:
        d = _constant_drive(omega=float(wn))
        assert resonant_mode(ch, d, modes, float(wn)) is None
        assert np.isfinite(steady_state(ch, d, modes).twist_amplitude).all()
    free = chain([1.0, 2.0, 1.5], [1.0e4, 2.0e4])
    wn = float(natural_frequencies(free).elastic[1])
    with pytest.raises(InputError, match="torsional mode 2"):
        steady_state(free, _constant_drive(omega=wn))


def test_energy_is_conserved_without_load_and_damping():
    ch = chain([0.4, 1.0, 0.7], [900.0, 1500.0])
    h = simulate(ch, None, np.array([0.0, 0.01, -0.02]), np.array([50.0, 48.0, 53.0]),
                    t_end=1.0, n_samples=501)
    E = energy(ch, h)
    assert np.abs(E - E[0]).max() < 1e-8 * E[0]
    # and the angular momentum too (no external moments)
    L = (ch.J[:, None] * h.omega).sum(axis=0)
    assert np.abs(L - L[0]).max() < 1e-9 * abs(L[0])


def test_motor_from_rated_point_and_stall():
    assert starting_torque_from_rated(97.78, 0.02) == pytest.approx(4889.0)
    d = Drive("linear", 500.0, 0.0, 1.0, M_start=400.0, omega_x=157.0)
    with pytest.raises(InputError, match="cannot drive"):
        d.steady_speed()


def test_state_space_is_the_equations_of_motion():
    # ẏ = A·y + b0 + b1·sin ωt in y = (φ1, twists, speeds) against M·φ̈ = −K·φ − C·φ̇ + F
    ch = chain([0.3, 1.5, 0.8], [2.0e3, 5.0e3], [3.0, 0.5])
    drive = Drive("linear", 40.0, 25.0, 0.5, M_start=400.0, omega_x=157.0)
    A, b0, b1 = state_space(ch, drive)
    rng = np.random.default_rng(1)
    phi, om, s = rng.normal(size=3), rng.normal(size=3) + 100.0, 0.3
    y = np.concatenate([[phi[0]], np.diff(phi), om])
    F = np.zeros(3)
    F[0] += drive.torque(om[0])
    F[-1] -= drive.M0 + drive.amplitude * s
    acc = (-stiffness_matrix(ch) @ phi - damping_matrix(ch) @ om + F) / ch.J
    assert A @ y + b0 + b1 * s == pytest.approx(np.concatenate([[om[0]], np.diff(om), acc]),
                                                rel=1e-12)


MIXER = """
# a slow stiff machine: 1500 rev/min motor through 1:100 to a mixer, stiff steel coupling
[motor]
J = 0.05
synchronous_rpm = 1500.0
rated_torque = 30.0
rated_slip = 0.04
[coupling]
c = 1.0e6
[machine]
J_III = 50.0
i31 = 0.01
M0 = 1500.0
M_amplitude = 500.0
"""


def test_stiff_slow_machine_is_checked_with_an_implicit_method(tmp_path):
    # the torsional mode is ~10⁴ × the forcing: 5 forcing periods of explicit steps resolving it
    # took about a minute; Radau with the constant Jacobian follows the forced motion instead
    # (the time it takes is measured in benchmarks/, not here)
    ch, drive = to_model(load_aggregate_case(_write(tmp_path, MIXER)))
    r = analyze(ch, drive)
    assert r.check.method == "Radau" and r.startup.method == "DOP853"
    assert r.check_twist_amplitude == pytest.approx(r.steady.twist_amplitude[0], rel=1e-4)
    assert r.check_delta[0] == pytest.approx(r.steady.delta[0], rel=1e-3)
    assert r.check_delta[1] == pytest.approx(r.steady.delta[1], rel=1e-3)
    assert r.startup.t[-1] == pytest.approx(MAX_FAST_PERIODS * 2 * math.pi / r.modes.omega[-1])
    assert len(r.notes) == 2
    assert [n.kind for n in r.notes] == ["radau", "cap_linear"]
    assert "Radau" in r.notes[0].text and "start-up" in r.notes[1].text
    assert "(the cap)" in r.notes[1].text
    res = cli(_write(tmp_path, MIXER), "--json")
    assert res.exit_code == 0
    d = json.loads(res.stdout)
    assert len(d["notes"]) == 2 and d["time_domain"]["steady_check_method"] == "Radau"
    # the example case needs neither
    r = analyze(*to_model(load_aggregate_case(CASES / "aggregate.toml")), t_end=0.2)
    assert r.notes == () and r.check.method == "DOP853"


def test_start_up_from_rest_reaches_the_steady_speed():
    ch = chain([0.3, 1.5], [2.0e3], [3.0])
    drive = Drive("linear", 40.0, 0.0, 0.5, M_start=400.0, omega_x=157.0)
    tau = 1.8 * 157.0 / 400.0          # ΣJ·ω_x/M_п, the mechanical time constant
    h = start_up(ch, drive, t_end=10 * tau, n_samples=1001)
    assert h.omega[:, 0].tolist() == [0.0, 0.0]
    # without forcing the mean motion follows ω_s·(1 − e^(−t/τ)); the twist's vibration decays
    mean = (ch.J[:, None] * h.omega).sum(axis=0) / ch.J.sum()
    late = h.t > 3 * tau
    ref = 157.0 * 0.9 * (1 - np.exp(-h.t[late] / tau))
    assert np.abs(mean[late] - ref).max() < 1e-3 * 157.0
    assert h.omega[0, -1] == pytest.approx(157.0 * 0.9, rel=1e-4)


# -- the seed's example case ----------------------------------------------------------------------

def test_example_case():
    case = load_aggregate_case(CASES / "aggregate.toml")
    ch, drive = to_model(case)
    # J_пр.I = (J_M + J_пр.III)·i31² (9.21); M_C.I = M_0·i31 (9.20)
    assert ch.J[1] == pytest.approx((3.975 + 0.7074) * 0.41**2)
    assert drive.M0 == pytest.approx(196.94 * 0.41)
    assert drive.M_start == pytest.approx(97.78 / 0.02333)
    r = analyze(ch, drive, t_end=0.3)
    assert r.steady.twist_amplitude[0] == pytest.approx(r.check_twist_amplitude, rel=1e-3)
    assert r.steady.delta[0] == pytest.approx(r.check_delta[0], rel=1e-3)
    assert r.steady.delta[1] == pytest.approx(r.check_delta[1], rel=1e-3)
    assert all(x.margin > 0.5 for x in r.resonance)


@pytest.mark.parametrize("patch, where", [
    ({"motor": {"J": 0.0}}, "motor.J: must be positive"),
    ({"coupling": {"c": -5.0}}, "coupling.c: must be positive"),
    ({"machine": {"i31": 0.0}}, "machine.i31: must be positive"),
    ({"machine": {"flywheel": {"J": 1.0, "shaft": "II"}}}, "machine.i21: missing"),
    ({"machine": {"M0": 1e6}}, "motor.starting_torque: the motor cannot drive"),
    ({"coupling": {"cc": 1.0}}, "coupling.cc: unknown key; did you mean 'c'?"),
    ({"motor": {"characteristic": "constant"}}, "motor.synchronous_rpm: only for"),
])
def test_case_errors_name_the_field(patch, where):
    base = {"motor": {"J": 0.1, "synchronous_rpm": 1500.0, "starting_torque": 500.0},
            "coupling": {"c": 3000.0}, "machine": {"J_III": 0.7, "i31": 0.4, "M0": 100.0}}
    for k, v in patch.items():
        base[k] = {**base[k], **v}
    with pytest.raises(CaseFileError) as e:
        parse_aggregate_case(base, "x.toml")
    assert str(e.value).startswith("x.toml: ")
    assert where in str(e.value)
    assert "\n" not in str(e.value)


@pytest.mark.parametrize("patch, english, russian", [
    ({"motor": {"J": None}}, "(J_D, the motor's rotor", "(J_Д, момент инерции ротора"),
    ({"motor": {"starting_torque": None, "rated_torque": 100.0}}, "(M_st = M_r/s_r)",
     "(M_п = M_н/s_н)"),
    ({"machine": {"M0": 1e6}}, "M_st = 500 N·m is not above", "M_п = 500 Н·м не больше"),
    ({"machine": {"J_III": None}}, "(J_red.III [kg·m²])", "(J_пр.III, кг·м²)"),
])
def test_an_english_error_writes_english_symbols_a_russian_one_efanovs(patch, english, russian):
    """English error lines had carried Efanov's Cyrillic symbols (J_Д, M_п = M_н/s_н, J_пр.III);
    they write J_D, M_st = M_r/s_r, J_red.III, and the Russian lines keep his."""
    from flywheel.render.messages import message

    base = {"motor": {"J": 0.1, "synchronous_rpm": 1500.0, "starting_torque": 500.0},
            "coupling": {"c": 3000.0}, "machine": {"J_III": 0.7, "i31": 0.4, "M0": 100.0}}
    for k, v in patch.items():
        base[k] = {key: x for key, x in {**base[k], **v}.items() if x is not None}
    with pytest.raises(CaseFileError) as e:
        parse_aggregate_case(base, "x.toml")
    from flywheel.errors import said

    en, ru = message(said(e.value), "en"), message(said(e.value), "ru")
    assert english in en and not re.search("[А-Яа-яЁё]", en.replace("x.toml", "")), en
    assert russian in ru, ru


# -- CLI ------------------------------------------------------------------------------------------

runner = CliRunner()


def cli(*args):
    from flywheel.cli import app

    return runner.invoke(app, ["aggregate", *map(str, args)])



def test_cli_json_contract():
    res = cli(CASES / "aggregate.toml", "--json", "--t-end", "0.2")
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert KEYS <= set(d)
    assert d["natural_frequencies_hz"] == sorted(d["natural_frequencies_hz"])
    assert len(d["natural_frequencies_hz"]) == 1 and d["natural_frequencies_hz"][0] > 0
    assert d["elastic_moment_amplitude"] == pytest.approx(3000.0 * d["twist_amplitude"])
    assert 0 < d["delta_motor"] < 1 and 0 < d["delta_machine"] < 1


def test_cli_textbook_chain_json():
    res = cli(CASES / "aggregate_khurmi_three_rotor.toml", "--json")
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert [round(f) for f in d["natural_frequencies_hz"]] == [171, 277]
    assert d["twist_amplitude"] is None and d["delta_machine"] is None


def test_cli_summary_and_plot(tmp_path):
    png = tmp_path / "agg.png"
    res = cli(CASES / "aggregate.toml", "--plot", png, "--t-end", "0.2")
    assert res.exit_code == 0, res.output
    assert "a_ij" in res.stdout and "Resonance margins" in res.stdout
    # the forcing frequency by one symbol in the sentence and the margins' table (ω_вын in
    # Russian: test_lang_ru_steady_state_and_start_up)
    out = " ".join(res.stdout.replace("│", " ").replace("┃", " ").split())
    assert "forcing frequency ω_f = " in out and "ω_f/ω_n margin |1 − ω_f/ω_n|" in out, out
    assert "ω_III" not in out and "ω_forcing" not in out
    assert png.stat().st_size > 10000
    assert b"Software" not in png.read_bytes()[:4000]


@pytest.mark.parametrize("suffix", [".svg", ".pdf"])
def test_cli_plot_svg_pdf_same_bytes_on_a_rerun(tmp_path, suffix):
    """--plot chooses the format by the suffix; SVG and PDF carry no date and the SVG's ids a
    fixed salt, so two runs write the same bytes."""
    paths = [tmp_path / f"a{suffix}", tmp_path / f"b{suffix}"]
    for p in paths:
        res = cli(CASES / "aggregate.toml", "--plot", p, "--t-end", "0.2")
        assert res.exit_code == 0, res.output
    assert paths[0].read_bytes() == paths[1].read_bytes()
    assert paths[0].read_bytes()[:5] == (b"%PDF-" if suffix == ".pdf" else b"<?xml")


def _summary(path, t_end=None):
    # print_summary on a wide console: no wrapped cells; box characters dropped
    import io

    from rich.console import Console

    from flywheel.render.aggregate import print_summary

    case = load_aggregate_case(path)
    buf = io.StringIO()
    r = analyze(*to_model(case), t_end=t_end)
    print_summary(r, case.title, case.source, Console(file=buf, width=250, color_system=None))
    return " ".join(buf.getvalue().replace("│", " ").replace("┃", " ").split())


def test_summary_keeps_units_in_brackets():
    res = cli(CASES / "aggregate_khurmi_three_rotor.toml")
    assert res.exit_code == 0 and "J_reduced [kg·m²]" in res.stdout
    out = _summary(CASES / "aggregate_khurmi_three_rotor.toml")
    assert "J_reduced [kg·m²]" in out and "ω [rad/s]" in out and "c [N·m/rad]" in out
    assert "a_ij [kg·m²]" in out and "c_ij [N·m/rad]" in out
    assert "no [motor]: natural frequencies only" in out


def test_summary_moment_sign_matches_the_twist():
    # the twist q2 = φ2 − φ1 is negative while the motor drives; the moment in the summary is
    # the transmitted c·(φ1 − φ2) = −c·q2 (the plot's), its mean M_0·i31 > 0
    r = analyze(*to_model(load_aggregate_case(CASES / "aggregate.toml")), time_domain=False)
    st = r.steady
    assert st.twist_mean[0] < 0
    assert st.moment_mean[0] == pytest.approx(-r.chain.c[0] * st.twist_mean[0], rel=1e-12)
    out = _summary(CASES / "aggregate.toml", t_end=0.2)
    assert "elastic moment c·(φ1 − φ2) = −c·q2, mean 80.7454 N·m" in out
    assert "twist q2 = φ2 − φ1, mean -0.0269151 rad" in out
    assert "elastic moment c·q2" not in out


def test_non_finite_results_are_refused(tmp_path):
    # J = 1e-300, c = 1e300: c/J overflowed; before: "natural_frequencies_hz": [NaN], exit 0;
    # now the numbers are refused where they enter, with the range
    p = _write(tmp_path, "[[rotors]]\nJ = 1e-300\n[[rotors]]\nJ = 1.0\n[[shafts]]\nc = 1e300\n")
    for args in (("--json",), ()):
        res = cli(p, *args)
        err = err_text(res)
        assert res.exit_code == 2 and err.startswith("error: ") and err.count("\n") == 1
        assert "rotors[0].J: 1e-300 kg·m² is out of range (allowed: 1e-09 … 1e+12 kg·m²)" in err
    with pytest.raises(InputError, match="not finite"):
        chain([1.0, float("inf")], [1.0])


def _write(tmp_path, text):
    p = tmp_path / "case.toml"
    p.write_text(text, encoding="utf-8")
    return p


TWO_MASS = """
[motor]
J = {J1}
characteristic = "constant"
speed_rpm = 300.0
[coupling]
c = {c}
[machine]
J_III = {J2}
i31 = {i31}
M0 = 10.0
M_amplitude = 5.0
"""


@pytest.mark.parametrize("values, message", [
    (dict(J1=0.0, J2=1.0, c=100.0, i31=1.0), "motor.J: must be positive"),
    (dict(J1=1.0, J2=-1.0, c=100.0, i31=1.0), "machine.J_III: must be positive"),
    (dict(J1=1.0, J2=1.0, c=0.0, i31=1.0), "coupling.c: must be positive"),
    (dict(J1=1.0, J2=1.0, c=100.0, i31=0.0), "machine.i31: must be positive"),
    # ω_III = 300 rev/min = 10π rad/s and √(c·(J1 + J2)/(J1·J2)) = √(2c): c = (10π)²/2
    (dict(J1=1.0, J2=1.0, c=repr((10 * math.pi) ** 2 / 2), i31=1.0), "unbounded"),
])
def test_cli_bad_input_one_line(tmp_path, values, message):
    res = cli(_write(tmp_path, TWO_MASS.format(**values)), "--json")
    assert res.exit_code == 2
    err = err_text(res)
    assert err.startswith("error: ") and message in err
    assert err.count("\n") == 1 and "Traceback" not in err


def test_cli_other_errors(tmp_path):
    res = cli(tmp_path / "nope.toml")
    assert res.exit_code == 2 and "no such file" in err_text(res)
    res = cli(CASES / "aggregate_khurmi_three_rotor.toml", "--plot", tmp_path / "x.png")
    assert res.exit_code == 2 and "--plot needs a [motor]" in err_text(res)
    res = cli(CASES / "aggregate.toml", "--t-end", "-1")
    assert res.exit_code == 2 and "--t-end" in err_text(res)
    gear0 = '[[rotors]]\nJ = 1.0\n[[rotors]]\nJ = 2.0\n[[shafts]]\nc = 10.0\ni = 0.0\n'
    res = cli(_write(tmp_path, gear0))
    assert res.exit_code == 2 and "shafts[0].i: must be positive" in err_text(res)


def test_driven_chain_load_reduced_to_the_motor_shaft():
    # motor – shaft – gear 1/2 – shaft – pump – shaft – fan; load on the fan's own shaft
    ch, drive = _chain_case(
        [0.2, 1.0, 0.6], [{"c": 4.0e3, "i": 0.5}, {"c": 9.0e3, "damping": 2.0}],
        motor={"synchronous_rpm": 1000.0, "starting_torque": 300.0},
        load={"M0": 80.0, "M_amplitude": 30.0, "order": 2.0})
    assert drive.M0 == pytest.approx(40.0) and drive.amplitude == pytest.approx(15.0)
    assert drive.forcing_ratio == pytest.approx(1.0)      # order 2 × u = 0.5
    assert ch.damping.tolist() == pytest.approx([0.0, 0.5])
    r = analyze(ch, drive, t_end=0.2)
    assert len(r.resonance) == 2
    assert r.steady.twist_amplitude[0] == pytest.approx(r.check_twist_amplitude, rel=1e-3)
    # no harmonic part: no vibration, no resonance check
    _, quiet = _chain_case([0.2, 1.0], [{"c": 4.0e3}], motor={"synchronous_rpm": 1000.0,
                                                              "starting_torque": 300.0},
                           load={"M0": 80.0})
    st = steady_state(chain([0.2, 1.0], [4.0e3]), quiet)
    assert st.twist_amplitude.tolist() == [0.0] and st.moment_mean.tolist() == [80.0]


def test_analyze_solves_the_eigenproblem_once(monkeypatch):
    # the natural frequencies are computed once and handed to the steady state, the resonance
    # test, the choice of integrator, both solve_ivp runs and the start-up's duration
    import scipy.linalg

    calls = []
    eigh = scipy.linalg.eigh

    def counting(*args, **kwargs):
        calls.append(1)
        return eigh(*args, **kwargs)

    monkeypatch.setattr(scipy.linalg, "eigh", counting)
    r = analyze(*to_model(load_aggregate_case(CASES / "aggregate.toml")), t_end=0.2)
    assert len(calls) == 1
    assert r.check is not None and r.startup is not None
    # and the same frequencies as computed afresh
    assert np.array_equal(r.modes.omega, natural_frequencies(r.chain).omega)


def test_non_finite_result_is_refused_by_the_one_policy(tmp_path, monkeypatch):
    # a result that would print inf (here forced into the start-up peak) is refused in the
    # summary as in the JSON, with one line naming the quantity as the JSON names it
    import dataclasses

    import flywheel.elastic.model as model

    real = model.analyze

    def overflowing(*args, **kwargs):
        return dataclasses.replace(real(*args, **kwargs), startup_peak_moment=math.inf)

    monkeypatch.setattr(model, "analyze", overflowing)
    for args in (("--json",), ()):
        res = cli(CASES / "aggregate.toml", "--t-end", "0.2", *args)
        err = err_text(res)
        assert res.exit_code == 2, res.output
        assert err.startswith(f"error: {CASES / 'aggregate.toml'}: time_domain."
                              "start_up_peak_elastic_moment is not finite (inf): "), err
        assert err.count("\n") == 1 and "Infinity" not in res.output


# -- --lang ru ---------------------------------------------------------------------------------

def wide(*args, columns=250):
    """`flywheel aggregate …` on a console wide enough that no cell wraps."""
    from flywheel.cli import app

    return runner.invoke(app, ["aggregate", *map(str, args)], env={"COLUMNS": str(columns)})


def _numbers(text):
    import re

    return re.findall(r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?", text)


@pytest.mark.parametrize("name", ["aggregate.toml", "aggregate_khurmi_three_rotor.toml"])
def test_lang_ru_same_numbers_russian_labels(name):
    args = [CASES / name, "--t-end", "0.2"]
    en, ru = wide(*args), wide(*args, "--lang", "ru")
    assert en.exit_code == 0 and ru.exit_code == 0, ru.output
    for heading in ("Массы, приведённые к валу I", "Упругие связи, приведённые к валу I",
                    "инерционные коэффициенты a_ij, кг·м²", "коэффициенты жёсткости c_ij, Н·м/рад",
                    "Собственные частоты (K·x = ω²·M·x)", "твёрдое тело", "ω, рад/с", "f, Гц",
                    "форма колебаний"):
        assert heading in " ".join(ru.stdout.split()), heading      # titles may wrap
    assert "Rotors reduced" not in ru.stdout and "Natural frequencies" not in ru.stdout
    # the values are the JSON's in both languages (below); the Russian cells in Russian
    # typography: decimal commas, no decimal point
    assert len(_numbers(en.stdout)) > 20 and re.search(r"│ *[−-]?\d+,\d", ru.stdout)
    assert not re.search(r"│ *[−-]?\d+\.\d", ru.stdout)
    # a mode's shape: its numbers set apart by «;» («1; −0,307; −0,6433»), the comma being the
    # decimal mark (it wrote «1, −0,307, −0,6433»); English by commas
    assert re.search(r"│ 1; [−-]?\d", ru.stdout) and not re.search(r"\d, [−-]?\d", ru.stdout)
    assert re.search(r"│ 1, [−-]?\d", en.stdout)
    assert cli(*args, "--json", "--lang", "ru").stdout == cli(*args, "--json").stdout


def test_lang_ru_steady_state_and_start_up(tmp_path):
    res = wide(CASES / "aggregate.toml", "--t-end", "0.2", "--lang", "ru", "--plot",
               tmp_path / "ru.png")
    assert res.exit_code == 0, res.output
    out = " ".join(res.stdout.replace("│", " ").split())
    for text in ("двигатель J_Д", "машина J_пр.I", "вынуждающая частота ω_вын = ",
                 "Отстройка от резонанса", "Установившийся режим",
                 "упругий момент c·(φ1 − φ2) = −c·q2, среднее 80,75 Н·м",
                 "угол закручивания q2 = φ2 − φ1, среднее −0,02692 рад",
                 "пуск: наибольший упругий момент", "пуск: время до 95 % ω1", "δ двигателя",
                 "график записан в"):
        assert text in out, text
    assert (tmp_path / "ru.png").stat().st_size > 10000


def test_lang_ru_notes(tmp_path):
    # the mixer's notes (Radau check, capped start-up) in Russian, with the English numbers in
    # Russian typography (no e-notation: «48 177», not «4.818e+04»)
    p = _write(tmp_path, MIXER)
    en, ru = wide(p, columns=400), wide(p, "--lang", "ru", columns=400)
    assert en.exit_code == 0 and ru.exit_code == 0
    notes_en = [line for line in en.stdout.splitlines() if line.startswith("note: ")]
    notes_ru = [line for line in ru.stdout.splitlines() if line.startswith("примечание: ")]
    assert len(notes_en) == len(notes_ru) == 2
    assert "методом Радо" in notes_ru[0] and "пуск: проинтегрирован" in notes_ru[1]
    for ru_note, en_note in zip(notes_ru, notes_en):
        assert "e+" not in ru_note and same_numbers(ru_numbers(ru_note), en_numbers(en_note))


def test_the_notes_print_what_the_results_state():
    # the nomenclature's notes (render/nomenclature.py) print exactly the text the results
    # document states (the whole table's consistency: tests/render/test_nomenclature.py)
    from flywheel.elastic.model import NOTE_TEXT
    from flywheel.render.nomenclature import TERMS, name

    for kind, template in NOTE_TEXT.items():
        assert TERMS[f"note_{kind}"].en == template
    assert name("note_radau", fast=12345.678, f_top=0.5, limit=500) == \
        NOTE_TEXT["radau"].format(fast=12345.678, f_top=0.5, limit=500)


def test_cli_plot_that_fails_leaves_the_old_image_and_no_temporary(tmp_path, monkeypatch):
    from matplotlib.figure import Figure

    out = tmp_path / "agg.svg"
    out.write_bytes(b"<svg>the old one</svg>")

    def half(self, fname, **kw):
        assert Path(fname).suffix == ".svg" and Path(fname).parent == tmp_path
        Path(fname).write_bytes(b"<svg")
        raise OSError(13, "Permission denied")

    monkeypatch.setattr(Figure, "savefig", half)
    res = cli(CASES / "aggregate.toml", "--plot", out, "--t-end", "0.2")
    assert res.exit_code == 2, res.output
    assert "--plot" in err_text(res) and "Permission denied" in err_text(res)
    assert out.read_bytes() == b"<svg>the old one</svg>"
    assert [p.name for p in tmp_path.iterdir()] == ["agg.svg"]



@pytest.mark.parametrize("case", sorted(p.name for p in CASES.glob("aggregate*.toml")))
def test_the_json_document_fits_the_schema_of_its_typed_entries(case):
    """aggregate --json is written by the one serializer from elastic/document.py's typed
    entries: every bundled case's document (with the start-up run) validates against the JSON
    Schema read off them, so a renamed key or a changed type fails here."""
    from dynamics.test_results_typed import errors
    from flywheel.elastic.document import AggregateDocument
    from flywheel.io.serialize import json_schema

    res = cli(CASES / case, "--json", "--t-end", "0.2")
    assert res.exit_code == 0, err_text(res)
    doc = json.loads(res.stdout)
    doc.pop("title", None), doc.pop("source", None)
    assert errors(doc, json_schema(AggregateDocument)) == []


def test_the_russian_report_sets_a_modes_numbers_apart_by_semicolons(tmp_path):
    """The report's table of natural frequencies: a mode's shape «1; −0,307; −0,6433» in
    Russian (it wrote «1, −0,307, −0,6433», the decimal commas and the separator alike)."""
    res = cli(CASES / "aggregate_khurmi_three_rotor.toml", "--lang", "ru", "-o", tmp_path / "o")
    assert res.exit_code == 0, res.output
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    rows = [ln for ln in md.splitlines() if ln.startswith("| 1 | ") and ln.count("|") == 6]
    assert rows and re.search(r"\| 1; [−-]\d,\d+; [−-]\d,\d+ \|$", rows[0]), rows
