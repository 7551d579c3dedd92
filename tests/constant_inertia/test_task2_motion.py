"""task2: ε(φ) = (M_D − M_C)/J, its global extremes, the time law t(φ) = ∫dφ/ω, the motion at
asked angles, and the case conveniences (speed limits, mean power, ΔE, C_E, radius of gyration).

Truths independent of the code: the equation of motion J·φ̈ = M_D(φ) − M_C(φ) integrated in time
by scipy's solve_ivp; ∫ε dt = 0 over a cycle of steady motion; ε = dω/dt by a central difference
of ω(t); closed forms for the rectangle and the triangle written out here; the worked examples
of R.S. Khurmi & J.K. Gupta, *Theory of Machines*, ch. 16.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from flywheel.cases.task2 import load_task2_case, parse_task2_case, solve_case
from flywheel.constant_inertia.graphs import constant, harmonic, piecewise_linear, rectangle
from flywheel.constant_inertia.preset import seed_task
from flywheel.constant_inertia.solve import solve, time_linear
from flywheel.errors import CaseFileError, InputError

CASES = Path(__file__).resolve().parents[2] / "cases"
PI = math.pi


def solve_file(name: str):
    return solve_case(load_task2_case(CASES / name), name)


def _ode_times(r, rtol=1e-12):
    """The time and ω at every row of r's table from the equation of motion J·dω/dt = M_D − M_C,
    dφ/dt = ω integrated by solve_ivp (DOP853) from (φ, ω) = (0, ω0), stopped at each row's
    angle by an event; each segment restarts there, so no step straddles a jump of a graph."""
    from scipy.integrate import solve_ivp

    J, D, C = r.J, r.driving, r.resistance
    t, w = 0.0, r.omega0
    out = [(0.0, w)]
    for a, b in zip(r.rows, r.rows[1:]):
        x0, x1 = a.phi, b.phi
        mid = 0.5 * (x0 + x1)
        side = lambda phi: +1 if phi < mid else -1            # noqa: E731  (the open segment)

        def rhs(_, y):
            phi = min(max(y[0], x0), x1)
            return [y[1], (D.value(phi, side(phi)) - C.value(phi, side(phi))) / J]

        def reach(_, y):
            return y[0] - x1
        reach.terminal, reach.direction = True, 1
        T = 4 * (x1 - x0) / w
        sol = solve_ivp(rhs, (t, t + T), [x0, w], method="DOP853", rtol=rtol, atol=1e-14,
                        events=reach)
        assert sol.status == 1, "the event was not reached"
        t, w = float(sol.t_events[0][0]), float(sol.y_events[0][0][1])
        out.append((t, w))
    return out


# -- the time law against the equation of motion --------------------------------------------------

@pytest.mark.parametrize("make", [
    lambda: seed_task("triangle"),                       # κ = 0, κ < 0 and κ > 0 pieces
    lambda: seed_task("rectangle"),                      # jumps: constant ε on each piece
    lambda: seed_task("triangle", M_C=50.0),             # not steady
    lambda: seed_task("triangle", J=0.5, omega0=20.0),   # a large fluctuation (δ ≈ 0.34)
    lambda: solve_file("task2_khurmi_16_12.toml"),       # harmonics: adaptive quadrature
    lambda: solve_file("task2_khurmi_16_6.toml"),        # trapezoid over 1080°
    lambda: solve_file("task2_khurmi_16_8.toml"),        # sum of three triangles
    lambda: solve(piecewise_linear([(0, 0), (PI, 400), (2 * PI, 0)]) ,   # slope + harmonics
                  harmonic(200.0, [150.0], [-80.0], orders=[3]), 2.0, omega0=30.0),
], ids=["triangle", "rectangle", "unsteady", "large-delta", "harmonic", "trapezoid", "khurmi-16.8",
        "sloped-harmonic"])
def test_time_law_matches_the_equation_of_motion(make):
    r = make()
    ode = _ode_times(r)
    for row, (t, w) in zip(r.rows, ode):
        assert row.t == pytest.approx(t, rel=1e-9, abs=1e-15)
        assert row.omega == pytest.approx(w, rel=1e-10)
    assert r.cycle_time == r.rows[-1].t == pytest.approx(ode[-1][0], rel=1e-9)


def test_integral_of_epsilon_over_time_is_zero_in_steady_motion():
    # ∫ε dt over a cycle = ω(Φ) − ω(0) = 0: the trapezoid rule on the program's own ε(t) at 2001
    # angles (ε and t reported by ``at``) vanishes to the rule's error, against ∫|ε| dt
    for r0 in (seed_task("triangle"), solve_file("task2_khurmi_16_12.toml"),
               solve_file("task2_khurmi_16_11.toml")):
        n = 2001
        at = [r0.cycle * i / (n - 1) for i in range(n)]
        r = solve(r0.driving, r0.resistance, r0.J, omega0=r0.omega0, at=at)
        assert r.steady
        eps = [a.epsilon for a in r.at]
        t = [a.t for a in r.at]
        integral = sum(0.5 * (e0 + e1) * (t1 - t0)
                       for e0, e1, t0, t1 in zip(eps, eps[1:], t, t[1:]))
        size = sum(0.5 * (abs(e0) + abs(e1)) * (t1 - t0)
                   for e0, e1, t0, t1 in zip(eps, eps[1:], t, t[1:]))
        assert abs(integral) < 1e-5 * size
        assert t[-1] == pytest.approx(r.cycle_time, rel=1e-14)


@pytest.mark.parametrize("deg", [20.0, 100.0, 150.0, 200.0, 300.0])
def test_epsilon_is_the_time_derivative_of_omega(deg):
    # a central difference of ω(t) between φ ± h, both read from ``at``: Δω/Δt → ε(φ)
    for r0 in (seed_task("triangle"), solve_file("task2_khurmi_16_12.toml")):
        phi, h = math.radians(deg), 1e-4
        r = solve(r0.driving, r0.resistance, r0.J, omega0=r0.omega0, at=[phi - h, phi, phi + h])
        lo, mid, hi = r.at
        assert (hi.omega - lo.omega) / (hi.t - lo.t) == pytest.approx(mid.epsilon, rel=1e-6)
        d_md_mc = r0.driving.value(phi) - r0.resistance.value(phi)
        assert mid.epsilon == pytest.approx(d_md_mc / r0.J, rel=1e-15)


# -- closed forms ---------------------------------------------------------------------------------

def test_rectangle_closed_form():
    # M_D = D, M_C = P on [a, b] with P·(b − a) = D·2π. ε = D/J outside, (D − P)/J inside;
    # ω² is linear on each piece, so the time of a piece is 2h/(ω_start + ω_end):
    #   ω_a² = ω0² + 2·D·a/J,  ω_b² = ω_a² + 2·(D − P)·(b − a)/J,  ω(2π) = ω0,
    #   T = 2a/(ω0 + ω_a) + 2(b − a)/(ω_a + ω_b) + 2(2π − b)/(ω_b + ω0)
    D, J, w0, a, b = 15.0, 12.0, 200.0, PI / 2, PI
    P = D * 2 * PI / (b - a)
    r = solve(constant(D), rectangle(P, a, b), J, omega0=w0)
    wa = math.sqrt(w0 ** 2 + 2 * D * a / J)
    wb = math.sqrt(wa ** 2 + 2 * (D - P) * (b - a) / J)
    T = 2 * a / (w0 + wa) + 2 * (b - a) / (wa + wb) + 2 * (2 * PI - b) / (wb + w0)
    assert r.cycle_time == pytest.approx(T, rel=1e-13)
    assert [row.t for row in r.rows] == pytest.approx(
        [0.0, 2 * a / (w0 + wa), 2 * a / (w0 + wa) + 2 * (b - a) / (wa + wb), T], rel=1e-13)
    assert (r.epsilon_max, r.phi_epsilon_max) == (D / J, 0.0)       # the plateau's start
    assert (r.epsilon_min, r.phi_epsilon_min) == ((D - P) / J, a)   # just after the jump at a
    assert [(ph.trend, ph.phi_start, ph.phi_end) for ph in r.phases] == [
        ("up", 0.0, a), ("down", a, b), ("up", b, 2 * PI)]
    assert sum(ph.duration for ph in r.phases) == pytest.approx(T, rel=1e-14)


def _table_integral(a2, b1, c0, u):
    """∫₀^u du/√(a2·u² + b1·u + c0) by the antiderivatives of the tables (Gradshteyn & Ryzhik
    2.261): a2 > 0: ln(2√(a2·Q) + 2·a2·u + b1)/√a2; a2 < 0: −arcsin((2·a2·u + b1)/√Δ)/√(−a2),
    Δ = b1² − 4·a2·c0; a2 = 0: 2√Q/b1 (or u/√c0 for b1 = 0)."""
    Q = lambda x: a2 * x * x + b1 * x + c0                             # noqa: E731
    if a2 > 0:
        F = lambda x: math.log(2 * math.sqrt(a2 * Q(x)) + 2 * a2 * x + b1) / math.sqrt(a2)  # noqa
    elif a2 < 0:
        disc = b1 * b1 - 4 * a2 * c0
        F = lambda x: -math.asin((2 * a2 * x + b1) / math.sqrt(disc)) / math.sqrt(-a2)  # noqa
    elif b1 != 0:
        F = lambda x: 2 * math.sqrt(Q(x)) / b1                          # noqa: E731
    else:
        F = lambda x: x / math.sqrt(c0)                                 # noqa: E731
    return F(u) - F(0.0)


def test_triangle_closed_form():
    # seed 002's triangle with J = 0.5, ω0 = 20 (a visible fluctuation): M_D = 15, M_C rises
    # linearly from 0 at π/2 to 60 at π and falls back to 0 at 3π/2. On each piece the net
    # moment is m0 + s·u, so ω² = ω_start² + (2/J)(m0·u + s·u²/2): a2 = s/J, b1 = 2·m0/J.
    J, w0 = 0.5, 20.0
    r = seed_task("triangle", J=J, omega0=w0)
    s = 60.0 / (PI / 2)
    pieces = [(0.0, PI / 2, 15.0, 0.0), (PI / 2, PI, 15.0, -s), (PI, 3 * PI / 2, -45.0, s),
              (3 * PI / 2, 2 * PI, 15.0, 0.0)]
    t, wsq = 0.0, w0 * w0
    times = {0.0: 0.0}
    for p0, p1, m0, slope in pieces:
        h = p1 - p0
        t += _table_integral(slope / J, 2 * m0 / J, wsq, h)
        wsq += (2 / J) * (m0 * h + slope * h * h / 2)
        times[p1] = t
    assert r.cycle_time == pytest.approx(times[2 * PI], rel=1e-12)
    for row in r.rows:
        if row.kind == "bound":
            assert row.t == pytest.approx(times[row.phi], rel=1e-12, abs=1e-15)
    # ε: 15/J on the flats (the first angle of the plateau, 0), (15 − 60)/J at the apex
    assert (r.epsilon_max, r.phi_epsilon_max) == (15 / J, 0.0)
    assert (r.epsilon_min, r.phi_epsilon_min) == ((15 - 60) / J, PI)


@pytest.mark.parametrize("h, w0, eps0, kappa", [
    (1.0, 10.0, 2.0, 0.0), (1.0, 10.0, 2.0, 3.0), (1.0, 10.0, -2.0, 3.0),
    (3.0, 5.0, -10.0, 5.0),                      # ω falls to √5 of 5, then rises again
    (1.0, 10.0, 2.0, -3.0), (3.0, 4.0, 7.0, -4.0),  # κ < 0 with the vector (ε, λω) turning > 90°
    (1e-6, 200.0, 1.25, 0.0), (0.5, 200.0, 1e-20, 1e-30),
])
def test_time_linear_against_quadrature(h, w0, eps0, kappa):
    # ω² = w0² + 2·(ε0·u + κ·u²/2): the exact ∫dφ/ω against scipy's adaptive quadrature
    from scipy.integrate import quad

    wsq = lambda u: w0 * w0 + 2 * (eps0 * u + kappa * u * u / 2)        # noqa: E731
    assert min(wsq(h * i / 1000) for i in range(1001)) > 0
    w1 = math.sqrt(wsq(h))
    dw = 2 * (eps0 * h + kappa * h * h / 2) / (w0 + w1)
    ref, _ = quad(lambda u: 1 / math.sqrt(wsq(u)), 0.0, h, epsabs=0, epsrel=1e-13, limit=200)
    assert time_linear(h, w0, w1, eps0, kappa, dw) == pytest.approx(ref, rel=1e-12)


# -- ε: global extremes, exact ------------------------------------------------------------------

def test_epsilon_extremes_are_global_and_exact():
    # dense sampling can only come near them from inside: every sample is within
    # [ε_min, ε_max], and the best sample is within the sampling's reach of the exact value
    for r in (seed_task("triangle"), solve_file("task2_khurmi_16_12.toml"),
              solve_file("task2_khurmi_16_11.toml"), solve_file("task2_khurmi_16_8.toml")):
        n = 20001
        eps = [(r.driving.value(r.cycle * i / (n - 1)) - r.resistance.value(r.cycle * i / (n - 1)))
               / r.J for i in range(n)]
        span = r.epsilon_max - r.epsilon_min
        assert max(eps) <= r.epsilon_max + 1e-12 * span
        assert min(eps) >= r.epsilon_min - 1e-12 * span
        assert max(eps) == pytest.approx(r.epsilon_max, abs=1e-6 * span)
        assert min(eps) == pytest.approx(r.epsilon_min, abs=1e-6 * span)
        for value, phi in ((r.epsilon_max, r.phi_epsilon_max), (r.epsilon_min, r.phi_epsilon_min)):
            net = r.driving.value(phi) - r.resistance.value(phi)
            left = r.driving.value(phi, -1) - r.resistance.value(phi, -1)
            assert any(value == pytest.approx(m / r.J, rel=1e-14) for m in (net, left))


def test_khurmi_16_12_book_gives_a_local_maximum():
    # Khurmi & Gupta, Theory of Machines, Example 16.12 (p. 587 per the FOSSEE Python Textbook
    # Companion, Theory_Of_Machines/ch16.ipynb): d(600 sin 2θ − 500 sin θ)/dθ = 0 gives
    # 24cos²θ − 5cosθ − 12 = 0; the book prints θ = 35° and 127.6°, α_max = 3.46 rad/s² and
    # α_min = 12.2 rad/s² (retardation). The 3.46 at 35.03° is only a local maximum: the global
    # maximum, at the mirror image 360° − 127.63°, is 12.2 rad/s².
    r = solve_file("task2_khurmi_16_12_accel.toml")
    J = 500.0 * 0.4 ** 2
    c_plus, c_minus = (5 + math.sqrt(1177)) / 48, (5 - math.sqrt(1177)) / 48
    th_local, th_min = math.acos(c_plus), math.acos(c_minus)
    net = lambda th: 600 * math.sin(2 * th) - 500 * math.sin(th)       # noqa: E731
    assert net(th_local) / J == pytest.approx(3.46, abs=0.005)         # the book's α_max
    assert net(th_min) / J == pytest.approx(-12.2, abs=0.05)           # the book's α_min
    assert r.epsilon_min == pytest.approx(net(th_min) / J, rel=1e-14)
    assert r.phi_epsilon_min == pytest.approx(th_min, rel=1e-12)
    assert r.epsilon_max == pytest.approx(net(2 * PI - th_min) / J, rel=1e-14)
    assert r.phi_epsilon_max == pytest.approx(2 * PI - th_min, rel=1e-12)
    assert math.degrees(r.phi_epsilon_max) == pytest.approx(232.3691599774, abs=1e-9)
    assert r.epsilon_max == pytest.approx(12.202990605104748, rel=1e-13)
    assert r.epsilon_max > 3.5 * net(th_local) / J          # the book's maximum is not it
    # at the book's printed angles (at_deg = [35, 127.6])
    a35, a127 = r.at
    assert a35.epsilon == pytest.approx(net(math.radians(35.0)) / J, rel=1e-14)
    assert a127.epsilon == pytest.approx(net(math.radians(127.6)) / J, rel=1e-14)
    assert round(a35.epsilon, 2) == 3.46 and round(a127.epsilon, 1) == -12.2


def test_khurmi_16_11_acceleration_at_45_degrees():
    # Khurmi & Gupta, Example 16.11, part 3 (FOSSEE companion, p. 585): α = 3.044 rad/s² at 45°,
    # = 9500/3121 with the book's rounded I = 3121 kg·m². Exactly: T − T_mean = 9500·sin 90° −
    # 5700·cos 90° = 9500 N·m, ε = 9500/J with J = ΔE/(ω²·δ) = 3118.1 kg·m².
    r = solve_file("task2_khurmi_16_11_accel.toml")
    (a,) = r.at
    assert a.phi == math.radians(45.0)
    assert a.epsilon == pytest.approx(9500.0 / r.J, rel=1e-14)
    assert r.J == pytest.approx(3118.1055575549735, rel=1e-12)
    assert a.epsilon == pytest.approx(3.044, abs=0.005)        # the book's value, to its rounding
    # ω(45°) from the energy: ½J(ω² − ω0²) = ∫₀^{π/4} (9500 sin 2θ − 5700 cos 2θ) dθ
    work = 9500 * (1 - math.cos(PI / 2)) / 2 - 5700 * math.sin(PI / 2) / 2
    assert a.omega == pytest.approx(math.sqrt(r.omega0 ** 2 + 2 * work / r.J), rel=1e-14)
    # the global extremes are at the maximum of 9500 sin 2θ − 5700 cos 2θ = R·sin(2θ − β)
    R, beta = math.hypot(9500, 5700), math.atan2(5700, 9500)
    assert r.epsilon_max == pytest.approx(R / r.J, rel=1e-14)
    assert r.phi_epsilon_max == pytest.approx((PI / 2 + beta) / 2, rel=1e-12)


def test_khurmi_16_8_three_cylinders():
    # Khurmi & Gupta, Example 16.8 (FOSSEE companion, p. 580): P = 4.24 kW, C_s = 4 % (rounded),
    # C_E = 2.78 %, α_max = 292 rad/s² (its code prints (90 − 67.5)/(12·0.08²) = 292.97 with %d).
    r = solve_file("task2_khurmi_16_8.toml")
    J = 12 * 0.08 ** 2
    T_mean = 3 * 0.5 * PI * 90 / (2 * PI)                   # three triangles of base π, height 90
    assert r.M_C == pytest.approx(T_mean, rel=1e-14) and T_mean == 67.5
    assert r.power == pytest.approx(T_mean * 20 * PI, rel=1e-14)
    assert round(r.power / 1000, 2) == 4.24
    # each hump above the mean: a triangle 60° wide, 22.5 N·m high: ΔE = ½·(π/3)·22.5
    dE = 0.5 * (PI / 3) * 22.5
    assert r.delta_T_max == pytest.approx(dE, rel=1e-13)
    assert r.delta == pytest.approx(dE / (J * (20 * PI) ** 2), rel=1e-13)
    assert round(r.delta * 100) == 4
    assert r.energy_fluctuation_coefficient == pytest.approx(dE / (T_mean * 2 * PI), rel=1e-13)
    assert round(r.energy_fluctuation_coefficient * 100, 2) == 2.78
    assert r.epsilon_max == pytest.approx((90 - 67.5) / J, rel=1e-14)
    assert math.floor(r.epsilon_max) == 292
    assert r.phi_epsilon_max == pytest.approx(PI / 3, rel=1e-15)


# -- conveniences of the case format -------------------------------------------------------------

def _base(**extra) -> dict:
    doc = {"speed": {"mean_rpm": 150.0}, "flywheel": {"J": 80.0},
           "driving": {"kind": "harmonic", "a0": 5000.0, "a": [600.0], "orders": [2]},
           "resistance": {"kind": "harmonic", "a0": 5000.0, "a": [500.0]}}
    for k, v in extra.items():
        if isinstance(v, dict) and isinstance(doc.get(k), dict):
            doc[k] = {n: x for n, x in {**doc[k], **v}.items() if x is not None}
        elif v is None:
            doc.pop(k, None)
        else:
            doc[k] = v
    return doc


def _solve(doc, at_deg=()):
    return solve_case(parse_task2_case(doc, "x.toml"), "x.toml", at_deg=at_deg)


def test_speed_limits_give_mean_and_delta():
    # Khurmi & Gupta §16.6: C_s = (N1 − N2)/N with N = (N1 + N2)/2
    limits = _solve(_base(speed={"mean_rpm": None, "max_rpm": 153.0, "min_rpm": 147.0},
                          flywheel={"J": None}))
    given = _solve(_base(flywheel={"J": None, "delta": 6.0 / 150.0}))
    assert limits.delta_target == pytest.approx(0.04, rel=1e-15)
    assert limits.J == pytest.approx(given.J, rel=1e-15)
    assert limits.omega_max * 30 / PI == pytest.approx(153.0, rel=1e-12)
    assert limits.omega_min * 30 / PI == pytest.approx(147.0, rel=1e-12)
    rad = _solve(_base(speed={"mean_rpm": None, "max": 16.0, "min": 15.0}, flywheel={"J": None}))
    assert rad.omega_mean == 15.5 and rad.delta_target == pytest.approx(1 / 15.5, rel=1e-15)


def test_mean_power_gives_the_graph_value():
    # Example 16.9 stated with its power: the scale is the hand computation's 8000/π
    by_power = solve_file("task2_khurmi_16_9_power.toml")
    by_hand = solve_file("task2_khurmi_16_9.toml")
    assert by_power.power_found == "driving" and by_hand.power_found is None
    assert by_power.M_D == pytest.approx(3 * 8000 / PI, rel=1e-13)    # nominal = 3 × scale
    assert by_power.J == pytest.approx(by_hand.J, rel=1e-13)
    assert by_power.J == pytest.approx(255.4, abs=0.05)                # the book
    assert by_power.power == pytest.approx(20000.0, rel=1e-13)
    # a constant resistance from the power, the driving graph from the balance
    r = _solve(_base(power=78539.81633974482, resistance={"a0": "power"},
                     driving={"a0": "balance"}))
    assert r.M_C == pytest.approx(5000.0, rel=1e-12) and r.M_D == pytest.approx(5000.0, rel=1e-12)


def test_delta_E_given_directly_khurmi_16_1():
    # Khurmi & Gupta, Example 16.1 (FOSSEE companion, p. 573): N1 = 121 rpm, N2 = 119 rpm.
    # ΔE = (π²/900)·m·k²·N·(N1 − N2), N1 + N2 = 2N
    r = solve_file("task2_khurmi_16_1.toml")
    diff = 56000 / (PI ** 2 / 900 * 6500 * 1.8 ** 2 * 120)
    n1, n2 = 120 + diff / 2, 120 - diff / 2
    assert r.omega_max * 30 / PI == pytest.approx(n1, rel=1e-13)
    assert r.omega_min * 30 / PI == pytest.approx(n2, rel=1e-13)
    assert (round(n1), round(n2)) == (121, 119)
    assert r.delta_T_max == 56000.0 and r.epsilon_max is None and r.cycle_time is None


def test_energy_fluctuation_coefficient_khurmi_16_3():
    # Khurmi & Gupta, Example 16.3 (FOSSEE companion, p. 574): m = 5628 kg (printed with %d).
    # W = P·60/N per revolution, ΔE = C_E·W, m = ΔE/(k²·ω²·C_s)
    r = solve_file("task2_khurmi_16_3.toml")
    W = 300e3 * 60 / 90
    w = 2 * PI * 90 / 60
    m = 0.1 * W / (2.0 ** 2 * w ** 2 * 0.01)
    assert r.delta_T_max == pytest.approx(0.1 * W, rel=1e-14)
    assert r.flywheel_mass == pytest.approx(m, rel=1e-13)
    assert math.floor(r.flywheel_mass) == 5628
    assert r.energy_fluctuation_coefficient == pytest.approx(0.1, rel=1e-14)
    assert r.work_per_cycle == pytest.approx(W, rel=1e-14)
    same = _solve({"speed": {"mean_rpm": 90.0}, "flywheel": {"delta": 0.01,
                   "radius_of_gyration": 2.0},
                   "diagram": {"energy_fluctuation_coefficient": 0.1, "work_per_cycle": W}})
    assert same.flywheel_mass == pytest.approx(r.flywheel_mass, rel=1e-14)


def test_radius_of_gyration_alone_gives_the_mass():
    r = _solve(_base(flywheel={"J": None, "delta": 0.05, "radius_of_gyration": 0.4}))
    assert r.flywheel_mass == pytest.approx(r.J / 0.16, rel=1e-15)
    with_J = _solve(_base(flywheel={"radius_of_gyration": 0.4}))
    assert with_J.flywheel_mass == pytest.approx(80.0 / 0.16, rel=1e-15)


def test_at_deg_in_a_case_and_from_the_command_line():
    r = _solve(_base(at_deg=[35.0]), at_deg=(127.6, 360.0))
    assert [round(math.degrees(a.phi), 10) for a in r.at] == [35.0, 127.6, 360.0]
    assert r.at[-1].t == r.cycle_time and r.at[-1].omega == pytest.approx(r.omega0, rel=1e-15)
    doc = r.to_document()
    assert [list(a) for a in doc["at"]] == [["phi_deg", "omega", "epsilon", "t"]] * 3
    assert doc["at"][0]["phi_deg"] == 35.0


def test_document_keys_and_units():
    doc = seed_task("triangle").to_document()
    for key in ("epsilon_max", "epsilon_min", "phi_epsilon_max_deg", "phi_epsilon_min_deg",
                "cycle_time", "at"):
        assert key in doc
    assert doc["phi_epsilon_min_deg"] == 180.0 and doc["epsilon_min"] == -3.75
    assert doc["cycle_time"] == pytest.approx(2 * PI / 200, rel=1e-4)   # ω ≈ 200 rad/s
    assert [s["t"] for s in doc["segments"]][0] == 0.0
    json.dumps(doc, allow_nan=False)


@pytest.mark.parametrize("changes, match", [
    (dict(at_deg=[400.0]), r"at_deg\[0\]: must lie within the cycle 0…360° \(got 400\)"),
    (dict(speed={"mean_rpm": None, "max_rpm": 150.0}), r"speed.min_rpm: missing"),
    (dict(speed={"mean_rpm": None, "max_rpm": 150.0, "min_rpm": 150.0}),
     r"speed.min_rpm: must be below max_rpm"),
    (dict(speed={"max_rpm": 150.0, "min_rpm": 140.0}), r"speed: give exactly one"),
    (dict(speed={"mean_rpm": None, "max_rpm": 150.0, "min_rpm": 140.0},
          flywheel={"delta": 0.01}), r"flywheel.delta: the speed limits already give δ"),
    (dict(driving={"a0": "power"}), r'driving.a0: "power" needs the mean power'),
    (dict(power=1000.0), r'power: is used by a graph value "power"'),
    (dict(power=1000.0, driving={"a0": "power"}, resistance={"a0": "power"}),
     r'resistance.a0: "power" may stand for one value only'),
    (dict(power=1000.0, driving={"a0": "power"}, speed={"mean_rpm": None, "omega0": 16.0}),
     r'driving.a0: "power" \(T_mean = P/ω_ср\) needs the mean speed'),
    (dict(power=-5.0, driving={"a0": "power"}), r"power: must be positive"),
    (dict(driving=None, resistance=None, diagram={"delta_E": 100.0, "energies": [1, -1]}),
     r"diagram: give one of areas"),
    (dict(driving=None, resistance=None, diagram={"energy_fluctuation_coefficient": 0.1}),
     r"diagram.energy_fluctuation_coefficient: needs the work done per cycle"),
    (dict(driving=None, resistance=None, diagram={"delta_E": 100.0, "work_per_cycle": 5.0}),
     r"diagram.work_per_cycle: only with energy_fluctuation_coefficient"),
    (dict(driving=None, resistance=None, diagram={"delta_E": -1.0}),
     r"diagram.delta_E: must be positive"),
    (dict(driving=None, resistance=None, at_deg=[10.0], diagram={"delta_E": 100.0}),
     r"at_deg: a diagram given by areas has no moments"),
])
def test_case_errors_are_one_line(changes, match):
    with pytest.raises(CaseFileError, match=match) as exc:
        _solve(_base(**changes))
    assert "\n" not in str(exc.value) and str(exc.value).startswith("x.toml: ")


def test_power_too_small_for_the_fixed_part_is_refused():
    # a trapezoid whose base alone does more work than P·Φ/ω_ср: its peak cannot make the mean
    with pytest.raises(CaseFileError, match=r"driving.peak: the mean power 1 W needs a negative"):
        _solve(_base(power=1.0, driving={"kind": "trapezoid", "a0": None, "a": None,
                                         "orders": None, "from_deg": 0, "top_from_deg": 90,
                                         "top_to_deg": 180, "to_deg": 270, "peak": "power",
                                         "base": 1000.0}))


def test_solve_refuses_angles_outside_the_cycle_and_for_diagrams():
    from flywheel.constant_inertia.solve import solve_areas

    with pytest.raises(InputError, match=r"the angle 400° lies outside the cycle 0…360°"):
        seed_task("triangle", at=[math.radians(400.0)])
    with pytest.raises(InputError, match=r"a diagram given by areas has no moments"):
        solve_areas([10.0, -10.0], 1.0, omega_mean=10.0, at=[0.5])


def test_harmonic_cycle_time_against_scipy_quadrature():
    # Example 16.12 in closed form: A(φ) = ∫₀^φ (600 sin 2θ − 500 sin θ) dθ
    # = 300·(1 − cos 2φ) − 500·(1 − cos φ); t = ∫ dφ/√(ω0² + 2A/J) by scipy's quad at 1e-13
    from scipy.integrate import quad

    r = solve_file("task2_khurmi_16_12.toml")
    A = lambda p: 300 * (1 - math.cos(2 * p)) - 500 * (1 - math.cos(p))    # noqa: E731
    f = lambda p: 1 / math.sqrt(r.omega0 ** 2 + 2 * A(p) / r.J)            # noqa: E731
    T, _ = quad(f, 0, 2 * PI, epsabs=0, epsrel=1e-13, limit=200)
    assert r.cycle_time == pytest.approx(T, rel=1e-12)
    for row in r.rows:
        t, _ = quad(f, 0, row.phi, epsabs=0, epsrel=1e-13, limit=200) if row.phi else (0.0, 0)
        assert row.t == pytest.approx(t, rel=1e-12, abs=1e-16)


# -- the command line ----------------------------------------------------------------------------

def _run(*args):
    from typer.testing import CliRunner

    from flywheel.cli import app

    return CliRunner().invoke(app, ["task2", *map(str, args)])


def _err(res):
    try:
        return res.stderr
    except (ValueError, AttributeError):
        return res.output


def test_cli_at_is_repeatable_and_json_has_it():
    res = _run("--at", 45, "--at", 200, "--json")
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert [a["phi_deg"] for a in d["at"]] == [45.0, 200.0]
    assert d["at"][0]["epsilon"] == 1.25                       # (15 − 0)/12 before the triangle
    assert d["at"][1]["epsilon"] == pytest.approx((15 - 60 * (1 - 20 / 90)) / 12, rel=1e-14)
    plain = json.loads(_run("--json").stdout)
    assert plain["at"] == [] and plain["epsilon_max"] == d["epsilon_max"]
    # with a case the angles add to its own at_deg
    res = _run("--case", CASES / "task2_khurmi_16_11_accel.toml", "--at", 90, "--json")
    assert [a["phi_deg"] for a in json.loads(res.stdout)["at"]] == [45.0, 90.0]


def test_cli_summary_shows_motion_only_when_asked():
    plain = _run()
    assert plain.exit_code == 0 and "ε_max" not in plain.stdout
    for args in (("--epsilon",), ("--at", 45)):
        res = _run(*args)
        assert res.exit_code == 0, res.output
        assert "ε_max (largest over the cycle)" in res.stdout and "cycle time" in res.stdout
        assert "rises (M_D > M_C)" in res.stdout and "falls (M_D < M_C)" in res.stdout
    assert "At the asked angles" in _run("--at", 45).stdout
    assert "At the asked angles" not in _run("--epsilon").stdout
    ru = _run("--epsilon", "--lang", "ru")
    assert "ε_max (наибольшее за цикл)" in ru.stdout and "время цикла" in ru.stdout
    assert "растёт (M_Д > M_С)" in ru.stdout


def test_cli_case_file_with_at_deg_shows_the_book_angles():
    res = _run("--case", CASES / "task2_khurmi_16_12_accel.toml")
    assert res.exit_code == 0, res.output
    assert "232.369" in res.stdout and "127.631" in res.stdout       # the global extremes
    assert "3.46284" in res.stdout                                  # the book's local one


@pytest.mark.parametrize("args, match", [
    (("--at", 400), "error: --at 400: must lie within the cycle 0…360°"),
    (("--at", -1), "error: --at -1: must lie within the cycle 0…360°"),
    (("--at", "nan"), "error: --at nan: must lie within the cycle 0…360°"),
    (("--case", CASES / "task2_khurmi_16_6.toml", "--at", 1081),
     "error: --at 1081: must lie within the cycle 0…1080°"),
    (("--case", CASES / "task2_khurmi_16_4.toml", "--at", 10),
     "gives a diagram by areas, which has no moments"),
])
def test_cli_bad_at_is_one_line(args, match):
    res = _run(*args)
    assert res.exit_code == 2
    err = _err(res)
    assert match in err and err.count("\n") == 1


def test_cli_new_cases_run(tmp_path):
    for name in ("task2_khurmi_16_1.toml", "task2_khurmi_16_3.toml", "task2_khurmi_16_8.toml",
                 "task2_khurmi_16_9_power.toml", "task2_khurmi_16_11_accel.toml",
                 "task2_khurmi_16_12_accel.toml"):
        res = _run("--case", CASES / name, "--plot", tmp_path / f"{name}.png")
        assert res.exit_code == 0, (name, res.output)
        assert (tmp_path / f"{name}.png").stat().st_size > 1000
    power = _run("--case", CASES / "task2_khurmi_16_9_power.toml")
    assert "mean power P = 20000 W at ω_m: mean M_D = P/ω_m = 636.62 N·m" in power.stdout
    mass = _run("--case", CASES / "task2_khurmi_16_3.toml")
    assert "mass at k = 2 m" in mass.stdout and "5628.95" in mass.stdout
    assert "C_E = ΔT_max" in mass.stdout
