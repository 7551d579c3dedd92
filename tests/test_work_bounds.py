"""Bounds on work and progress of the long integrations (issue 17, item 3).

The cost of `run --transients` (start-up, run-down) and of the aggregate's start-up is
estimated before integrating; the estimates are checked here against closed forms and the
integrations themselves; a run beyond the stated maximum is refused (the messages: the
catalogue, tests/bad_inputs/catalogue.toml, "transients-…-too-long", "t-end-too-many-steps",
"startup-stiff-motor"). The progress callable gets fractions 0 … 1 that never decrease.
No timing: the bounds are counts (cycles, steps), not seconds.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from flywheel.dynamics import timedomain
from flywheel.errors import InputError

CASES = Path(__file__).resolve().parents[1] / "cases"


class Recorder:
    """A progress callable that keeps what it was given, per stage."""

    def __init__(self):
        self.calls: dict[str, list[float]] = {}

    def __call__(self, *args):
        stage, fraction = args if len(args) == 2 else ("", args[0])
        self.calls.setdefault(stage, []).append(fraction)

    def check(self, stage: str = "") -> list[float]:
        f = self.calls[stage]
        assert all(0.0 <= x <= 1.0 for x in f), f
        assert all(b >= a for a, b in zip(f, f[1:])), f"{stage}: not monotone: {f}"
        assert f[-1] == 1.0
        return f


# -- the estimates against closed forms and the integration --------------------------------------

def test_rundown_estimate_is_the_closed_form_for_constant_inertia_and_load():
    """Constant J and resisting M: ½Jω0² = M·φ_stop, so φ_stop/Φ = Jω0²/(2MΦ) cycles exactly;
    the integration stops there (test_timedomain checks the angle to 1e-6)."""
    phi = np.linspace(0, 2 * np.pi, 721)
    J, M, w0 = 2.0, 50.0, 30.0
    n = timedomain.rundown_cycles(phi, np.full_like(phi, J), np.full_like(phi, -M), w0)
    assert n == pytest.approx(J * w0**2 / (2 * M) / (2 * np.pi), rel=1e-12)
    rd = timedomain.rundown(phi, np.full_like(phi, J), np.zeros_like(phi), np.full_like(phi, -M), w0)
    assert math.radians(rd["angle_deg"]) / (2 * np.pi) == pytest.approx(n, rel=1e-6)


def test_rundown_estimate_none_without_net_resistance():
    phi = np.linspace(0, 2 * np.pi, 361)
    assert timedomain.rundown_cycles(phi, np.full_like(phi, 2.0), 30.0 * np.sin(phi), 20.0) is None


def test_rundown_of_loads_that_drive_says_so():
    """Loads that do positive work (an engine's gas) never run the machine down: three cycles
    for the history, no estimate, and the reason names the positive work (not 'no net work')."""
    phi = np.linspace(0, 2 * np.pi, 361)
    M = np.full_like(phi, 5.0)
    assert timedomain.rundown_cycles(phi, np.full_like(phi, 2.0), M, 20.0) is None
    rd = timedomain.rundown(phi, np.full_like(phi, 2.0), np.zeros_like(phi), M, 20.0)
    assert not rd["stopped"] and "positive work" in rd["reason"] and "+31.4 J" in rd["reason"]
    assert math.radians(rd["angle_deg"]) == pytest.approx(3 * 2 * np.pi, rel=1e-9)


def test_startup_estimate_is_the_closed_form_for_constant_inertia():
    """J·dω/dt = (M_п/ω_x)(ω_s − ω): ω = ω_s·(1 − e^(−t/τ)), within δ/50 of ω_s after
    t* = τ·ln(50/δ), having turned ∫ω dt = ω_s·τ·(ln(50/δ) − 1 + δ/50), that over 2π cycles;
    the integration converges (a cycle mean within δ/50 and a step below δ/500) within a few
    cycles of that."""
    phi = np.linspace(0.0, 2 * np.pi, 361)
    J, w_x, delta, M_p = 1.0, 100.0, 0.04, 50.0
    w_s, tau = w_x / 2, J * w_x / M_p
    motor = timedomain.linear_motor(M_p, w_x)
    n = timedomain.startup_cycles(phi, np.full_like(phi, J), np.full_like(phi, -M_p / 2), motor,
                                  w_s, delta)
    assert n == pytest.approx(w_s * tau * (math.log(50 / delta) - 1 + delta / 50) / (2 * np.pi),
                             rel=1e-9)
    st = timedomain.startup(phi, np.full_like(phi, J), np.zeros_like(phi),
                            np.full_like(phi, -M_p / 2), motor, w_s, delta)
    assert st["converged"] and abs(st["cycles_run"] - n) < 0.05 * n + 3


def test_startup_estimate_none_when_the_motor_cannot_carry_the_load():
    phi = np.linspace(0.0, 2 * np.pi, 361)
    motor = timedomain.linear_motor(50.0, 100.0)
    assert timedomain.startup_cycles(phi, np.ones_like(phi), np.full_like(phi, -60.0), motor,
                                     50.0, 0.04) is None


@pytest.mark.parametrize("name", ["compressor", "press", "shaper"])
def test_estimates_of_the_bundled_cases_agree_with_their_integration(name):
    """On real machines (J(φ), M(φ) varying) the estimates are of the right size: within 25 %
    of the cycles the integration takes (the limit is meant against runs 10–1000× longer)."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze

    c = load_case(CASES / f"{name}.toml")
    r = analyze(c, n_points=720, transients=True)
    J = r.motion.J_I + r.reduction.J_II
    td = r.time_domain
    n_down = timedomain.rundown_cycles(r.phi, J, r.energy.M_known, float(r.motion.omega[0]))
    assert n_down == pytest.approx(td.rundown.angle_deg / 360, rel=0.25)
    if c.motor is not None:
        m = c.machine
        motor = timedomain.linear_motor(td.startup.starting_torque, td.startup.no_load_speed)
        n_up = timedomain.startup_cycles(r.phi, J, r.energy.M_known, motor, m.omega_mean, m.delta)
        assert n_up == pytest.approx(td.startup.cycles_to_steady, rel=0.25)


def test_aggregate_step_estimate_against_the_solver():
    """explicit_steps against DOP853's own count (nfev/12) on the bundled aggregate over 20 s:
    the step is limited by 1/8 of the highest natural period (plus rejected steps)."""
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic import timedomain as etd

    ch, drive = to_model(load_aggregate_case(CASES / "aggregate.toml"), "aggregate.toml")
    est, _ = etd.explicit_steps(ch, drive, 20.0)
    import scipy.integrate

    seen = []
    real = scipy.integrate.solve_ivp

    def counting(*a, **k):
        sol = real(*a, **k)
        seen.append(sol.nfev / 12)
        return sol

    scipy.integrate.solve_ivp = counting
    try:
        etd.start_up(ch, drive, 20.0)
    finally:
        scipy.integrate.solve_ivp = real
    assert seen[0] == pytest.approx(est, rel=0.3)


# -- the refusals (the computation's side; the CLI lines are in the catalogue) -------------------

def test_rundown_beyond_the_limit_is_refused_before_integrating(monkeypatch):
    from flywheel.cases.run import parse_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.io.toml import read_toml

    doc = read_toml(CASES / "slotted_link.toml")
    doc["forces"][0]["magnitude"] = 1.5
    c = parse_case(doc, "c.toml")
    monkeypatch.setattr(timedomain, "rundown", lambda *a, **k: pytest.fail("integrated"))
    with pytest.raises(InputError, match=r"run-down of --transients would take about .* "
                                         r"more than the limit of 500 cycles"):
        analyze(c, n_points=360, transients=True)


def test_aggregate_t_end_beyond_the_limit_names_the_option():
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic import timedomain as etd
    from flywheel.elastic.model import analyze

    ch, drive = to_model(load_aggregate_case(CASES / "aggregate.toml"), "aggregate.toml")
    t_end = 1.5 * etd.MAX_STEPS / etd.explicit_steps(ch, drive, 1.0)[0]
    with pytest.raises(InputError, match=rf"^--t-end: .* more than the limit of {etd.MAX_STEPS}"):
        analyze(ch, drive, t_end=t_end)


# -- a stiff start-up: LSODA instead of a refusal ---------------------------------------------------

def _stiff_aggregate(synchronous_rpm: float):
    from flywheel.cases.aggregate import parse_aggregate_case, to_model
    from flywheel.io.toml import read_toml

    doc = read_toml(CASES / "aggregate.toml")
    doc["motor"]["synchronous_rpm"] = synchronous_rpm
    return to_model(parse_aggregate_case(doc, "c.toml"), "c.toml")


@pytest.mark.parametrize("rpm, t_end", [(100.0, 3.0), (10.0, 1.5)])
def test_stiff_start_up_lsoda_agrees_with_dop853(rpm, t_end):
    """Where both run, LSODA (the constant Jacobian, the same largest step) gives the explicit
    DOP853's start-up: speeds to 2e-5 of their largest (measured 9e-6), the twist and its peak
    moment to 1e-6 (measured 2–3e-7), both at rtol 1e-9 (a motor of ω_x = 100 rpm:
    ρ = 4e3 1/s; of 10 rpm: ρ = 4e4 1/s, the state matrix's largest |eigenvalue|)."""
    from flywheel.elastic import timedomain as etd

    ch, drive = _stiff_aggregate(rpm)
    explicit = etd.start_up(ch, drive, t_end, method="DOP853")
    stiff = etd.start_up(ch, drive, t_end, method="LSODA")
    assert explicit.method == "DOP853" and stiff.method == "LSODA"
    scale = np.max(np.abs(explicit.omega))
    np.testing.assert_allclose(stiff.omega, explicit.omega, rtol=0, atol=2e-5 * scale)
    tw = np.max(np.abs(explicit.twist))
    np.testing.assert_allclose(stiff.twist, explicit.twist, rtol=0, atol=1e-6 * tw)
    peak = lambda h: np.max(np.abs(ch.c[0] * h.twist[0]))  # noqa: E731
    assert peak(stiff) == pytest.approx(peak(explicit), rel=1e-6)


def _counting_solve_ivp(monkeypatch) -> list[tuple[str, int]]:
    """Record (method, number of right-hand-side evaluations) of every scipy solve_ivp run: the
    work of an integration, counted instead of timed."""
    import scipy.integrate

    runs: list[tuple[str, int]] = []
    solve_ivp = scipy.integrate.solve_ivp

    def counting(*args, **kwargs):
        sol = solve_ivp(*args, **kwargs)
        runs.append((kwargs.get("method", "RK45"), sol.nfev))
        return sol

    monkeypatch.setattr(scipy.integrate, "solve_ivp", counting)
    return runs


def test_stiff_motor_start_up_is_computed_with_lsoda(monkeypatch):
    """synchronous_rpm = 10 in cases/aggregate.toml: DOP853 would take ~4.6e5 steps over the
    default 68.3 s (refused before; measured: 37 s of computing, peak elastic moment 296.463 N·m,
    ω at the end 1.05002 and 1.07353 rad/s); LSODA resolves the modes in ~2e4 steps to the same
    values, and says so in a note. The work is counted: DOP853 takes 12 evaluations of the
    right-hand side per step (≥ 5.5e6 here), LSODA's start-up takes 5.9e4 (measured), the
    steady check's Radau 1.3e4."""
    from flywheel.elastic import timedomain as etd
    from flywheel.elastic.model import analyze

    ch, drive = _stiff_aggregate(10.0)
    t_end, _ = etd.start_up_duration(ch, drive)
    explicit = etd.explicit_steps(ch, drive, t_end)[0]
    assert explicit > etd.MAX_STEPS
    assert etd.start_up_method(ch, drive, t_end) == "LSODA"
    runs = _counting_solve_ivp(monkeypatch)
    r = analyze(ch, drive)
    assert [m for m, _ in runs][-1] == "LSODA"
    work = sum(n for _, n in runs)
    assert work < 2e5 and 20 * work < 12 * explicit
    assert r.startup.method == "LSODA" and any(n.kind == "lsoda" for n in r.notes)
    assert r.startup_peak_moment == pytest.approx(296.46334131193504, rel=1e-6)  # DOP853's
    np.testing.assert_allclose(r.startup.omega[:, -1], [1.05001871, 1.07353374], rtol=1e-7)


def test_steady_check_lsoda_agrees_with_dop853():
    """The steady check (5 forcing periods from the closed-form orbit) by LSODA and by DOP853,
    where both run (ω_x = 100 rpm): the same speeds and twist to 1e-6 of their largest."""
    from flywheel.elastic import timedomain as etd
    from flywheel.elastic.forced import steady_state

    ch, drive = _stiff_aggregate(100.0)
    st = steady_state(ch, drive)
    a = etd.steady_run(ch, drive, st, method="DOP853")
    b = etd.steady_run(ch, drive, st, method="LSODA")
    np.testing.assert_allclose(b.omega, a.omega, rtol=0, atol=1e-6 * np.max(np.abs(a.omega)))
    np.testing.assert_allclose(b.twist, a.twist, rtol=0, atol=1e-6 * np.max(np.abs(a.twist)))


def test_a_very_steep_motor_is_integrated_by_lsoda_in_both_runs(monkeypatch):
    """(mutation survey) rated_slip ×1e-4 in cases/aggregate.toml: ρ = 2.7e6 1/s; the steady
    check's 2.2e5 explicit steps (inside the bound, 2.6e6 evaluations) took 14 s, now LSODA for
    both runs: 1.7e3 and 8.0e3 evaluations of the right-hand side (measured), counted."""
    from flywheel.cases.aggregate import parse_aggregate_case, to_model
    from flywheel.elastic.model import analyze
    from flywheel.io.toml import read_toml

    doc = read_toml(CASES / "aggregate.toml")
    doc["motor"]["rated_slip"] *= 1e-4
    ch, drive = to_model(parse_aggregate_case(doc, "c.toml"), "c.toml")
    runs = _counting_solve_ivp(monkeypatch)
    r = analyze(ch, drive)
    assert [m for m, _ in runs] == ["LSODA", "LSODA"]
    assert sum(n for _, n in runs) < 5e4      # 2.6e6 for the explicit steady check
    assert r.check.method == "LSODA" and r.startup.method == "LSODA"


def test_bundled_aggregate_start_up_stays_explicit():
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic.model import analyze

    ch, drive = to_model(load_aggregate_case(CASES / "aggregate.toml"), "aggregate.toml")
    r = analyze(ch, drive)
    assert r.startup.method == "DOP853" and not any(n.kind == "lsoda" for n in r.notes)


def test_stiff_start_up_beyond_the_resolving_steps_is_still_refused():
    """LSODA too resolves every mode: a --t-end whose modes need more than MAX_STEPS steps is
    refused as before, naming the option."""
    from flywheel.elastic import timedomain as etd
    from flywheel.elastic.model import analyze

    ch, drive = _stiff_aggregate(10.0)
    t_end = 1.2 * etd.MAX_STEPS / etd.resolving_steps(ch, drive, 1.0)
    with pytest.raises(InputError, match=rf"^--t-end: .* more than the limit of {etd.MAX_STEPS}"):
        analyze(ch, drive, t_end=t_end)


# -- progress ------------------------------------------------------------------------------------

def test_progress_of_run_transients_is_monotone_per_stage():
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze

    rec = Recorder()
    analyze(load_case(CASES / "compressor.toml"), n_points=720, transients=True, progress=rec)
    assert set(rec.calls) == {"steady check", "start-up", "run-down"}
    for stage in rec.calls:
        f = rec.check(stage)
        assert len(f) >= 2
    # the run-down (7 cycles) reports along the way, every 1 % at most
    assert 10 <= len(rec.calls["run-down"]) <= 101


def test_progress_of_the_rundown_alone():
    phi = np.linspace(0, 2 * np.pi, 721)
    rec = Recorder()
    timedomain.rundown(phi, np.full_like(phi, 2.0), np.zeros_like(phi), np.full_like(phi, -50.0),
                       30.0, progress=rec)
    f = rec.check()
    assert f[0] < 0.1 and len(f) > 20


def test_progress_of_the_aggregate_startup_is_monotone():
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic.model import analyze

    ch, drive = to_model(load_aggregate_case(CASES / "aggregate.toml"), "aggregate.toml")
    rec = Recorder()
    analyze(ch, drive, progress=rec)
    f = rec.check("start-up")
    assert len(f) > 20


def test_progress_does_not_change_the_results():
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze

    c = load_case(CASES / "compressor.toml")
    a = analyze(c, n_points=360, transients=True).to_document()
    b = analyze(c, n_points=360, transients=True, progress=lambda s, f: None).to_document()
    assert a == b


# -- the bar on a terminal, nothing when piped ----------------------------------------------------

def _flywheel(args, terminal: bool):
    """`python -m flywheel ARGS` with stderr piped; ``terminal``: rich told stderr is a terminal
    (FORCE_COLOR, as a terminal would make it draw)."""
    import os
    import subprocess
    import sys

    env = {k: v for k, v in os.environ.items() if k not in ("FORCE_COLOR", "TTY_COMPATIBLE",
                                                             "NO_COLOR", "TERM")}
    if terminal:
        env["FORCE_COLOR"] = "1"
    return subprocess.run([sys.executable, "-m", "flywheel", *map(str, args)], env=env,
                          capture_output=True, text=True, timeout=120)


def _visible_lines(text: str) -> list[str]:
    import re

    text = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", text).replace("\r", "\n")
    return [ln for ln in text.splitlines() if ln.strip()]


def test_the_bar_shows_on_a_terminal_and_not_when_piped(tmp_path):
    args = ["run", CASES / "press.toml", "--transients", "--no-plots", "--json", "--out"]
    piped = _flywheel(args + [tmp_path / "a"], terminal=False)
    shown = _flywheel(args + [tmp_path / "b"], terminal=True)
    assert piped.returncode == shown.returncode == 0
    assert "run-down" not in piped.stderr and "\x1b" not in piped.stderr
    assert "run-down" in shown.stderr                 # the bar's stage, drawn and then cleared
    assert piped.stdout == shown.stdout               # the results do not depend on it


def test_an_error_on_a_terminal_is_still_one_line(tmp_path):
    """The bar is closed before the error is printed: one line, not wrapped by the display."""
    doc = (CASES / "slotted_link.toml").read_text(encoding="utf-8")
    case = tmp_path / "c.toml"
    case.write_text(doc.replace("magnitude = 1500.0", "magnitude = 1.5"), encoding="utf-8")
    p = _flywheel(["run", case, "--transients", "--no-plots", "--out", tmp_path / "o"],
                  terminal=True)
    assert p.returncode == 2
    lines = _visible_lines(p.stderr)
    assert len(lines) == 1 and lines[0].startswith("error: ") and "500 cycles" in lines[0], lines


def test_a_variants_error_on_a_terminal_is_still_one_line(tmp_path):
    """The same for `variants`' bar: every draw fails (rods too short to assemble), the error
    raised while the bar is drawn is printed after it is gone."""
    text = (CASES / "variants_compressor.toml").read_text(encoding="utf-8")
    lines = text.splitlines()
    i = next(k for k, ln in enumerate(lines) if ln.startswith('"machine.speed_rps"'))
    lines[i] = '"design.rod_to_crank" = { values = [0.5, 0.6] }'
    t = tmp_path / "t.toml"
    t.write_text("\n".join(lines) + "\n", encoding="utf-8")
    p = _flywheel(["variants", t, "--count", "2", "--seed", "1", "--out", tmp_path / "v"],
                  terminal=True)
    assert p.returncode == 2
    err = [ln for ln in _visible_lines(p.stderr) if not ln.lstrip().startswith("variants ")]
    assert len(err) == 1 and err[0].startswith("error: ") and "dyads[0]" in err[0], err
