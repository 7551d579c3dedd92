"""Duty-cycle presses (`flywheel duty-cycle`, issue 14 item 2): the worked examples of Khurmi &
Gupta, *Theory of Machines*, ch. 16 (Ex. 16.19–16.23), the identities of the model checked
independently of the code (energy balance over one operation and over the recovery, the cycle,
a time integration of J·dω/dt = M_Д − M_op), time ↔ angle round trips, bad input (one line,
exit 2, file and field), the JSON keys and the Russian summary.

Style: the book's printed number in a comment and asserted to its printed precision; the exact
value of the formula asserted to 1e-12. The printed answers are those of the FOSSEE Python
companion of the book (Theory_Of_Machines/ch16.ipynb), which reproduces its solutions.
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
import tomli_w
from typer.testing import CliRunner

from flywheel.cases.duty_cycle import load_duty_case, parse_duty_case, solve_case
from flywheel.cli import app
from flywheel.errors import CaseFileError
from flywheel.io.toml import read_toml

ROOT = Path(__file__).resolve().parents[2]
CASES = ROOT / "cases"
runner = CliRunner()
RPM = math.pi / 30


def solved(name: str):
    return solve_case(load_duty_case(CASES / name), name)


def close(a, b, rel=1e-12):
    return a == pytest.approx(b, rel=rel, abs=0)


# -- the book's examples ------------------------------------------------------------------------

def test_khurmi_16_19_punching_press_720_holes_an_hour():
    r = solved("duty_khurmi_16_19_punch.toml")
    # E1 = 15 kN·m per hole, 720 holes/h: P = 15000·720/3600; E2 = P·2 s; ΔE = E1 − E2
    assert close(r.motor_power, 15000 * 720 / 3600)          # book: P = 3 kW
    assert round(r.motor_power / 1000) == 3
    assert close(r.delta_E, 15000 - 3000 * 2)
    # m = ΔE·900/(π²·k²·N·(N1 − N2)), N = (N1 + N2)/2
    m = 9000 * 900 / (math.pi ** 2 * 0.5 ** 2 * 212.5 * 25)
    assert close(r.mass, m)                                   # book: m = 618 kg
    assert round(r.mass) == 618
    assert close(r.J, m * 0.25)
    assert close(r.omega_min * 30 / math.pi, 200.0)


def test_khurmi_16_20_punching_with_the_stroke_and_rim_speed():
    r = solved("duty_khurmi_16_20_punch_stroke.toml")
    E1 = 7.0 * math.pi * 38 * 32                              # N·m: 7 N·m/mm² × π·d·t mm²
    assert close(r.energy, E1)
    assert close(r.motor_power, E1 / 10)                      # book: 2.674 kW
    assert round(r.motor_power / 1000, 3) == 2.674
    dE = E1 * (1 - 32 / (2 * 100))                            # ΔE = E1·(1 − t/2s)
    assert close(r.delta_E, dE)
    assert close(r.mass, dE / (25 ** 2 * 0.03))               # book: m = 1198 kg
    assert round(r.mass) == 1198
    assert close(r.operation_time, 1.6)
    # the rim's radius is not given: no J, no shaft speed, no angle
    assert r.J is None and r.omega_max is None and r.operation_angle is None
    assert close(r.rim_speed_mean, 25.0) and close(r.delta, 0.03)


def test_khurmi_16_21_riveting_machine_speed_after_riveting():
    r = solved("duty_khurmi_16_21_riveting.toml")
    w1 = 300 * RPM
    w2 = math.sqrt(w1 ** 2 - 2 * (10000 - 3000 * 1) / (150 * 0.6 ** 2))
    assert close(r.omega_min, w2)
    assert round(r.omega_min * 30 / math.pi, 1) == 257.6      # book: N2 = 257.6 rpm
    assert close(r.operations_per_hour / 60, 3000 * 60 / 10000)   # book: 18 rivets a minute
    assert r.flywheel_given and r.idle_time == 0.0


def test_khurmi_16_22_punching_press_30_holes_a_minute():
    r = solved("duty_khurmi_16_22_punch.toml")
    E1 = 6.0 * math.pi * 40 * 15
    P = E1 * 30 / 60
    dE = E1 - P * 0.1
    m = dE * 900 / (math.pi ** 2 * 1.0 ** 2 * 150 * 20)
    assert close(r.mass, m)                                   # FOSSEE prints 327 kg
    assert round(r.mass) == 327


def test_khurmi_16_23_punching_with_the_shear_strength():
    r = solved("duty_khurmi_16_23_punch_force.toml")
    F = math.pi * 0.025 * 0.018 * 300e6                       # F_s = π·d·t·τ_u
    E = 0.5 * F * 0.018                                       # E = ½·F_s·t
    assert close(r.work.force_max, F) and close(r.energy, E)
    assert close(r.motor_input_power, E * 25 / 60 / 0.95)     # printed: 1.674 kW
    assert round(r.motor_input_power / 1000, 3) == 1.674
    assert close(r.delta_E, 0.9 * E)                          # ΔE = 9/10·E
    # the whole flywheel (the book sizes a rim with 95 % of it): m = ΔE/(R²·ω²·δ)
    assert close(r.mass, 0.9 * E / (0.7 ** 2 * (225 * RPM) ** 2 * 0.1))


# -- identities, independent of the code ----------------------------------------------------------

WITH_SHAFT = ["duty_khurmi_16_19_punch.toml", "duty_khurmi_16_21_riveting.toml",
              "duty_khurmi_16_22_punch.toml", "duty_khurmi_16_23_punch_force.toml",
              "duty_readme_press.toml"]


@pytest.mark.parametrize("name", WITH_SHAFT)
def test_energy_balance_over_one_operation_and_the_recovery(name):
    d = solved(name).to_document()
    J, w1, w2, T = d["J"], d["omega_max"], d["omega_min"], d["motor_torque"]
    a_op, a_rec = math.radians(d["operation_angle_deg"]), math.radians(d["recovery_angle_deg"])
    kinetic = 0.5 * J * (w1 ** 2 - w2 ** 2)
    scale = d["energy"]
    # the operation: the work E comes from the motor (M_Д·Δφ_op) and the flywheel
    assert abs(d["energy"] - T * a_op - kinetic) <= 1e-10 * scale
    assert abs(kinetic - d["delta_E"]) <= 1e-10 * scale
    # the recovery: the motor's work over the recovery angle restores the flywheel's energy
    assert abs(T * a_rec - kinetic) <= 1e-10 * scale
    # over the cycle: the motor's work equals E; the angles add up to the cycle's
    assert abs(T * (a_op + a_rec) - d["energy"]) <= 1e-10 * scale
    a_idle = math.radians(d["idle_angle_deg"])
    assert close(a_op + a_rec + a_idle, math.radians(d["cycle_angle_deg"]), rel=1e-12)
    assert close(d["operation_time"] + d["recovery_time"] + d["idle_time"], d["cycle_time"])
    # time ↔ angle: ω is linear in time in both phases, so Δφ = ω_ср·t; idle at ω_max
    wm = 0.5 * (w1 + w2)
    assert close(a_op, wm * d["operation_time"]) and close(a_rec, wm * d["recovery_time"])
    assert close(d["recovery_time"], J * (w1 - w2) / T)
    assert abs(a_idle - w1 * d["idle_time"]) <= 1e-12 * a_op
    for value in d["checks"].values():
        assert abs(value) <= 1e-9 * scale


@pytest.mark.parametrize("name", ["duty_khurmi_16_19_punch.toml", "duty_readme_press.toml",
                                  "duty_khurmi_16_21_riveting.toml"])
def test_a_time_integration_reproduces_the_cycle(name):
    """J·dω/dt = M_Д − M_op·[φ < Δφ_op] integrated by solve_ivp from ω_max: the operation ends
    at t_op with ω_min, the speed is back to ω_max at t_op + t_rec, the cycle closes at T_c."""
    from scipy.integrate import solve_ivp

    r = solved(name)
    J, T, w1 = r.J, r.motor_torque, r.omega_max
    a_op, M_op = r.operation_angle, r.operation_moment

    def end_of_operation(t, y):
        return y[0] - a_op
    end_of_operation.terminal = True
    op = solve_ivp(lambda t, y: [y[1], (T - M_op) / J], (0, 10 * r.cycle_time), [0.0, w1],
                   events=end_of_operation, rtol=1e-12, atol=1e-12)
    t_op, (phi, w) = op.t_events[0][0], op.y_events[0][0]
    assert close(t_op, r.operation_time, rel=1e-9) and close(w, r.omega_min, rel=1e-9)

    def back_to_top(t, y):
        return y[1] - w1
    back_to_top.terminal = True
    rec = solve_ivp(lambda t, y: [y[1], T / J], (t_op, t_op + 10 * r.cycle_time), [phi, w],
                    events=back_to_top, rtol=1e-12, atol=1e-12)
    t_rec, phi_rec = rec.t_events[0][0] - t_op, rec.y_events[0][0][0] - phi
    assert close(t_rec, r.recovery_time, rel=1e-9)
    assert close(phi_rec, r.recovery_angle, rel=1e-9)
    # idle at ω_max for the rest of the cycle
    cycle_angle = rec.y_events[0][0][0] + w1 * r.idle_time
    assert close(cycle_angle, r.cycle_angle, rel=1e-9)


def test_the_end_speed_depends_on_the_energy_only_not_on_the_force_shape():
    """A triangular resisting moment over the same angle with the same work E gives the same ω
    at the end of the operation (the model's constant M_op is a convenience, not an
    assumption about the end speed)."""
    from scipy.integrate import solve_ivp

    r = solved("duty_readme_press.toml")
    J, T, a = r.J, r.motor_torque, r.operation_angle
    peak = 2 * r.energy / a

    def rhs(t, y):
        m = peak * (1 - abs(2 * y[0] / a - 1))
        return [y[1], (T - m) / J]

    def end(t, y):
        return y[0] - a
    end.terminal = True
    sol = solve_ivp(rhs, (0, 1.0), [0.0, r.omega_max], events=end, rtol=1e-12, atol=1e-12,
                    max_step=a / r.omega_max / 200)
    assert close(sol.y_events[0][0][1], r.omega_min, rel=1e-8)


def _case(tmp_path, data: dict, name: str = "case.toml") -> Path:
    p = tmp_path / name
    p.write_text(tomli_w.dumps(data), encoding="utf-8")
    return p


def _doc(path: Path) -> dict:
    res = runner.invoke(app, ["duty-cycle", str(path), "--json"])
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


def test_time_and_angle_round_trip_through_the_program(tmp_path):
    """The operation given as the angle the program printed for 2 s gives back 2 s; the cycle
    given as the revolutions it printed for 720 holes/h gives back 5 s; the same flywheel."""
    base = read_toml(CASES / "duty_khurmi_16_19_punch.toml")
    d0 = _doc(CASES / "duty_khurmi_16_19_punch.toml")
    data = json.loads(json.dumps(base))
    del data["operation"]["duration"]
    data["operation"]["angle_deg"] = d0["operation_angle_deg"]
    data["cycle"] = {"every_revolutions": d0["revolutions_per_operation"]}
    d1 = _doc(_case(tmp_path, data))
    for key in ("operation_time", "cycle_time", "recovery_time", "J", "mass", "motor_power",
                "motor_torque", "delta_E"):
        assert close(d1[key], d0[key], rel=1e-12), key
    # and the share of the cycle
    data["operation"] = {"energy": 15000.0, "cycle_share": d0["operation_share"]}
    data["cycle"] = {"per_hour": 720}
    d2 = _doc(_case(tmp_path, data, "share.toml"))
    assert close(d2["operation_time"], 2.0) and close(d2["J"], d0["J"])


@pytest.mark.parametrize("given", ["max_rpm", "mean_rpm", "min_rpm"])
def test_sizing_and_a_given_flywheel_agree(tmp_path, given):
    """Size the flywheel for 300 → 270 rpm, then give that J with one speed: the other speeds
    come back (bisection on the drop, to the last bit)."""
    d0 = _doc(CASES / "duty_readme_press.toml")
    data = read_toml(CASES / "duty_readme_press.toml")
    value = {"max_rpm": 300.0, "mean_rpm": 285.0, "min_rpm": 270.0}[given]
    data["flywheel"] = {given: value, "J": d0["J"], "rim_diameter": 0.8}
    d1 = _doc(_case(tmp_path, data))
    for key in ("rpm_max", "rpm_min", "rpm_mean", "delta_E", "cycle_time", "mass"):
        assert close(d1[key], d0[key], rel=1e-11), key
    assert d1["flywheel_given"] is True


def test_a_stronger_motor_idles_and_the_largest_rate_has_no_idle(tmp_path):
    data = read_toml(CASES / "duty_khurmi_16_19_punch.toml")
    data["motor"] = {"power": 4000.0}
    res = runner.invoke(app, ["duty-cycle", str(_case(tmp_path, data)), "--json"])
    assert res.exit_code == 0
    d = json.loads(res.stdout)
    assert close(d["idle_time"], 5.0 - 15000 / 4000)          # the motor works E/P of 5 s
    assert close(d["delta_E"], 15000 - 4000 * 2)
    assert "warning: the motor is stronger" in res.stderr
    del data["cycle"]
    d = _doc(_case(tmp_path, data, "rate.toml"))
    assert d["idle_time"] == 0.0 and close(d["operations_per_hour"], 3600 * 4000 / 15000)


def test_delta_E_and_the_coefficient_of_fluctuation_of_energy_given(tmp_path):
    """ΔE given directly sizes the flywheel alone; C_E with the work gives ΔE = C_E·E and the
    operation's time from the balance P·t_op = E − ΔE."""
    data = {"operation": {"delta_E": 9000.0},
            "flywheel": {"max_rpm": 225, "min_rpm": 200, "radius_of_gyration": 0.5}}
    d = _doc(_case(tmp_path, data))
    assert close(d["mass"], 9000 * 900 / (math.pi ** 2 * 0.25 * 212.5 * 25))
    assert d["motor_power"] is None and d["cycle_time"] is None
    data = read_toml(CASES / "duty_khurmi_16_19_punch.toml")
    data["operation"] = {"energy": 15000.0, "energy_fluctuation_coefficient": 0.6}
    d = _doc(_case(tmp_path, data, "ce.toml"))
    assert close(d["delta_E"], 9000.0) and close(d["operation_time"], 2.0)


@pytest.mark.parametrize("fluct, value, delta", [("percent", 1.5, 0.03),
                                                 ("total_percent", 3.0, 0.03),
                                                 ("delta", 0.03, 0.03),
                                                 ("drop_percent", 3.0, None)])
def test_the_ways_to_state_the_speed_drop(tmp_path, fluct, value, delta):
    top = "mean_rpm" if fluct != "drop_percent" else "max_rpm"
    data = {"operation": {"energy": 15000.0, "duration": 2.0}, "cycle": {"per_hour": 720},
            "flywheel": {top: 200.0, fluct: value}}
    d = _doc(_case(tmp_path, data))
    if delta is not None:
        assert close(d["delta"], delta) and close(d["rpm_mean"], 200.0)
        assert close(d["rpm_max"] - d["rpm_min"], 6.0)
    else:
        assert close(d["rpm_min"], 194.0)
    # the mean torque from the power and the mean speed
    assert close(d["motor_torque"], d["motor_power"] / d["omega_mean"])


def test_shapes_of_the_force_over_the_travel():
    from flywheel.duty_cycle.work import work_of_stroke

    F, t = 1.0e5, 0.02
    # the area under each force–travel curve, by the trapezoid rule on a fine grid
    import numpy as np
    s = np.linspace(0.0, t, 200001)
    curves = {"constant": np.full_like(s, F), "falling": F * (1 - s / t),
              "triangle": F * (1 - np.abs(2 * s / t - 1))}
    for shape, f in curves.items():
        area = float(np.sum((f[1:] + f[:-1]) / 2 * np.diff(s)))
        assert work_of_stroke(F, t, shape) == pytest.approx(area, rel=1e-9), shape


# -- bad input: one line, exit 2, file and field ------------------------------------------------

BASE = {"operation": {"energy": 15000.0, "duration": 2.0}, "cycle": {"per_hour": 720},
        "flywheel": {"max_rpm": 225.0, "min_rpm": 200.0, "radius_of_gyration": 0.5}}


def _with(**changes) -> dict:
    data = json.loads(json.dumps(BASE))
    for path, value in changes.items():
        table, _, key = path.partition("__")
        if value is None and not key:
            data.pop(table, None)
        elif value is None:
            data[table].pop(key, None)
        elif key:
            data.setdefault(table, {})[key] = value
        else:
            data[table] = value
    return data


BAD = [
    # (changes, field path in the message, a phrase of it)
    (dict(flywheel={"mean_rpm": 200.0, "percent": 120.0}), "flywheel.percent",
     "120 % is out of range: the speed would drop to zero or below (allowed: 1e-06 ≤ value "
     "< 100 %)"),
    (dict(flywheel={"mean_rpm": 200.0, "total_percent": 250.0}), "flywheel.total_percent",
     "out of range"),
    (dict(flywheel={"mean_rpm": 200.0, "delta": 2.5}), "flywheel.delta", "out of range"),
    (dict(flywheel={"max_rpm": 200.0, "drop_percent": 100.0}), "flywheel.drop_percent",
     "the speed would drop to zero or below"),
    (dict(flywheel__min_rpm=230.0), "flywheel.min_rpm", "is not below max_rpm = 225"),
    (dict(flywheel={"mean_rpm": 100.0, "max_rpm": 225.0}), "flywheel.max_rpm",
     "gives min = 2·mean − max = -25"),
    (dict(flywheel={"mean_rpm": 100.0, "min_rpm": 120.0}), "flywheel.min_rpm",
     "is not below mean_rpm"),
    (dict(operation={"energy": 15000.0, "cycle_share": 1.5}), "operation.cycle_share",
     "out of range (allowed: 0 < value ≤ 1)"),
    (dict(operation={"energy": 15000.0, "cycle_share": 0.0}), "operation.cycle_share",
     "out of range"),
    (dict(operation__energy=-5.0), "operation.energy", "out of range (allowed: 1e-06"),
    (dict(operation__energie=5.0), "operation.energie", "did you mean 'energy'?"),
    (dict(motor={"power": 2000.0}), "motor.power", "less than the mean power of the "
     "operations E/T_c = 3000 W"),
    (dict(motor={"torque": 1.0}), "motor.torque", "less than the mean power"),
    (dict(operation__duration=6.0), "operation.duration", "longer than the cycle"),
    (dict(flywheel={"max_rpm": 225.0, "mass": 1.0, "radius_of_gyration": 0.5}),
     "flywheel.mass", "the flywheel is too small"),
    (dict(operation={"energy": 1.0, "force": 2.0, "thickness": 0.01, "shape": "falling",
                     "duration": 1.0}), "operation", "give the work one way"),
    (dict(operation={"force": 2.0e5, "thickness": 0.01, "duration": 1.0}), "operation.shape",
     "allowed: constant, falling, triangle"),
    (dict(operation={"energy": 1.0e4, "thickness": 0.03, "stroke": 0.01}), "operation.stroke",
     "stroke ≥ 0.015 m"),
    (dict(operation={"energy": 1.0e4, "delta_E": 2.0e4}), "operation.delta_E",
     "more than the work of the operation"),
    (dict(operation__cycle_share=0.5), "operation", "give exactly one of duration"),
    (dict(operation__duration=None), "operation", "give exactly one of duration"),
    (dict(cycle=None), "cycle", "missing"),
    (dict(flywheel={"max_rpm": 225.0, "min_omega": 20.0}), "flywheel", "in one unit"),
    (dict(flywheel={"max_rpm": 225.0}), "flywheel", "give two speeds"),
    (dict(flywheel={"mean_rim_speed": 25.0, "percent": 1.0},
          operation={"energy": 1.0e4, "angle_deg": 30.0}), "operation.angle_deg",
     "needs the shaft's speed"),
    (dict(operation__shape="square"), "operation.shape", "'constant', 'falling' or 'triangle'"),
    (dict(motor={"power": 3000.0, "efficiency": 1.5}), "motor.efficiency",
     "out of range (allowed: 0 < value ≤ 1)"),
    (dict(flywheel={"max_rpm": 225.0, "min_rpm": 200.0, "J": 3.0}), "flywheel",
     "with the flywheel given, give one speed"),
]


def _drop_none(data):
    if isinstance(data, dict):
        return {k: _drop_none(v) for k, v in data.items() if v is not None}
    return data


@pytest.mark.parametrize("changes, field, phrase", BAD,
                         ids=[b[1] + ":" + b[2][:25] for b in BAD])
def test_bad_input_is_one_line_naming_file_and_field(tmp_path, changes, field, phrase):
    path = _case(tmp_path, _drop_none(_with(**changes)))
    res = runner.invoke(app, ["duty-cycle", str(path)])
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    assert lines[0].startswith(f"error: {path}: {field}: "), lines[0]
    assert phrase in lines[0], lines[0]
    assert "Traceback" not in res.output


def test_a_file_of_another_kind_names_its_command():
    path = CASES / "task2_khurmi_16_4.toml"
    res = runner.invoke(app, ["duty-cycle", str(path)])
    assert res.exit_code == 2
    assert res.stderr.strip() == (f"error: {path}: this is a task-2 case (given moment graphs), "
                                  f"not a duty-cycle case (a press, riveter or shear): use "
                                  f"`flywheel task2 --case {path}`")
    res = runner.invoke(app, ["run", str(CASES / "duty_readme_press.toml")])
    assert res.exit_code == 2 and "use `flywheel duty-cycle " in res.stderr


def test_a_missing_file_and_a_bad_language_are_one_line(tmp_path):
    res = runner.invoke(app, ["duty-cycle", str(tmp_path / "none.toml")])
    assert res.exit_code == 2 and len(res.stderr.strip().splitlines()) == 1
    res = runner.invoke(app, ["duty-cycle", str(CASES / "duty_readme_press.toml"),
                              "--lang", "de"])
    assert res.exit_code == 2 and "--lang: 'de' is not a language" in res.stderr


def test_parse_errors_are_case_file_errors():
    with pytest.raises(CaseFileError, match=r"^x\.toml: flywheel: give two speeds"):
        parse_duty_case(_drop_none(_with(flywheel={"max_rpm": 225.0})), "x.toml")


# -- the command's output -------------------------------------------------------------------------

KEYS = {"energy", "delta_E", "energy_fluctuation_coefficient", "motor_power",
        "motor_input_power", "motor_torque", "mean_power", "efficiency", "omega_max",
        "omega_min", "omega_mean", "rpm_max", "rpm_min", "rpm_mean", "rim_speed_max",
        "rim_speed_min", "rim_speed_mean", "delta", "J", "mass", "radius", "operation_time",
        "operation_angle_deg", "operation_share", "operation_moment", "recovery_time",
        "recovery_angle_deg", "idle_time", "idle_angle_deg", "cycle_time", "cycle_angle_deg",
        "revolutions_per_operation", "operations_per_hour", "operations_per_minute",
        "flywheel_given", "work", "checks", "warnings"}


@pytest.mark.parametrize("name", sorted(p.name for p in CASES.glob("duty_*.toml")))
def test_json_keys_and_byte_identical_output(name):
    first = runner.invoke(app, ["duty-cycle", str(CASES / name), "--json"])
    second = runner.invoke(app, ["duty-cycle", str(CASES / name), "--json"])
    assert first.exit_code == 0 and first.stdout == second.stdout
    d = json.loads(first.stdout)
    assert KEYS <= set(d) and d["title"] and d["source"]
    assert set(d["checks"]) >= {"flywheel_energy", "operation_energy_balance",
                                "recovery_energy_balance", "cycle_energy_balance",
                                "cycle_time_balance"}


def _numbers(text: str) -> list[str]:
    return re.findall(r"-?\d+(?:\.\d+)?(?:e[+-]\d+)?", text)


def test_russian_summary_has_russian_labels_and_the_same_numbers():
    path = str(CASES / "duty_khurmi_16_19_punch.toml")
    en = runner.invoke(app, ["duty-cycle", path], env={"COLUMNS": "200"})
    ru = runner.invoke(app, ["duty-cycle", path, "--lang", "ru"], env={"COLUMNS": "200"})
    assert en.exit_code == 0 and ru.exit_code == 0
    for label in ("Маховик", "масса маховика m = J/k²", "мощность двигателя P", "об/мин",
                  "операция", "восстановление ω_max моментом двигателя"):
        assert label in ru.stdout, label
    assert "Flywheel" in en.stdout and "Маховик" not in en.stdout
    for number in ("617.94", "154.485", "3000", "9000", "0.117647", "2", "3", "5"):
        assert number in _numbers(en.stdout), number
    # the same values in Russian typography: a decimal comma, four significant digits
    for number in ("617,9", "154,5", "3000", "9000", "0,1176"):
        assert number in ru.stdout, number


def test_the_summary_in_english():
    res = runner.invoke(app, ["duty-cycle", str(CASES / "duty_khurmi_16_21_riveting.toml")],
                        env={"COLUMNS": "200"})
    assert res.exit_code == 0
    assert "257.601" in res.stdout and "lowest speed (at the end of the operation)" in res.stdout
    assert "operations per minute" in res.stdout


# -- the docs' worked example ---------------------------------------------------------------------

DOC = ROOT / "docs" / "duty-cycle.md"


def test_the_docs_example_is_the_case_file_and_its_numbers_are_the_programs():
    text = DOC.read_text(encoding="utf-8")
    example = text.split("## Worked example", 1)[1]
    block = example.split("```toml\n", 1)[1].split("```", 1)[0]
    case = (CASES / "duty_readme_press.toml").read_text(encoding="utf-8")
    assert block in case                          # the file adds only its leading comments
    assert case.endswith(block)
    rows = text.split("<!-- example-results -->", 1)[1].split("<!-- /example-results -->")[0]
    d = _doc(CASES / "duty_readme_press.toml")
    found = re.findall(r"^\| `(\w+)` \| ([-\d.]+) \|$", rows, re.M)
    assert len(found) >= 10
    for key, printed in found:
        digits = len(printed.replace("-", "").replace(".", "").lstrip("0"))
        assert float(f"{d[key]:.{max(digits, 1)}g}") == float(printed), (key, d[key], printed)


def test_the_readme_links_the_docs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert "docs/duty-cycle.md" in readme and "flywheel duty-cycle" in readme


def test_the_domain_imports_no_presentation():
    import ast

    for path in (ROOT / "src" / "flywheel" / "duty_cycle").glob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        names = {a.name.split(".")[0] for n in ast.walk(tree) if isinstance(n, ast.Import)
                 for a in n.names}
        names |= {(n.module or "").split(".")[0] for n in ast.walk(tree)
                  if isinstance(n, ast.ImportFrom)}
        assert not names & {"typer", "rich", "matplotlib", "pydantic"}, path
        mods = {n.module for n in ast.walk(tree) if isinstance(n, ast.ImportFrom) and n.module}
        assert all(m.split(".")[1] in ("errors", "units", "duty_cycle", "io") for m in mods
                   if m.startswith("flywheel.")), path


def test_a_quantity_is_not_named_twice_beside_its_symbol_column(tmp_path):
    """The summary's and the record's tables print the symbol in a column of its own: the name
    beside it is «площадь среза», not «площадь среза A» next to «A»."""
    from flywheel.render.duty_cycle import summary_tables

    r = solve_case(load_duty_case(CASES / "duty_khurmi_16_20_punch_stroke.toml"))
    rows = [row for _, _, rs, _, _ in summary_tables(r, "ru") for row in rs if len(row) == 4]
    named = {sym: what for what, sym, _, _ in rows}
    assert named["A"] == "площадь среза" and named["E"] == "работа одной операции"
    assert all(not what.endswith(" " + sym) for what, sym, _, _ in rows if sym)
