"""`flywheel check` and `flywheel schema` through the CLI (typer's CliRunner), and
`python -m flywheel` in a subprocess.

Bad input: exit 2, one `error:` line on stderr naming file and field, no traceback.
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
BASE = (CASES / "compressor.toml").read_text(encoding="utf-8")
runner = CliRunner()


def invoke(*args):
    # a fixed width, so that rich lays the tables out alike on every terminal and in CI
    return runner.invoke(app, [str(a) for a in args], env={"COLUMNS": "160"})


def rows(text: str) -> list[list[str]]:
    """Cells of the rich table rows in ``text`` (split on the box-drawing bar)."""
    return [[c.strip() for c in line.rstrip().split("│")[1:-1]] for line in text.splitlines()
            if line.startswith("│")]


def test_check_compressor_prints_the_case_and_its_dead_centres():
    res = invoke("check", CASES / "compressor.toml")
    assert res.exit_code == 0, res.output
    out = res.stdout
    assert "Two-stage V-type air compressor" in out
    assert "case is valid" in out
    for title in ("Mechanism", "Links", "Cylinders", "Dead centres", "Points at the dead centres",
                  "Links at the dead centres"):
        assert title in out
    assert res.stderr == ""
    for unit in ("mass [kg]", "J_S [kg·m²]", "bore [m]", "x along guide [m]", "|v_q| [m/rad]"):
        assert unit in out                      # headers keep their units (not eaten as markup)
    dead = {(r[0], r[1]): r[2:] for r in rows(out) if len(r) == 4 and r[1] in ("outer", "inner")}
    # piston 3 (B, vertical) at its top at φ = 0 and bottom at 180°; piston 5 (C) at 90° and 270°;
    # x = l2 ± l1 = 0.5 / 0.3 m
    assert dead == {("3", "outer"): ["0.0000", "0.5"], ("3", "inner"): ["180.0000", "0.3"],
                    ("5", "outer"): ["90.0000", "0.5"], ("5", "inner"): ["270.0000", "0.3"]}
    strokes = [r for r in rows(out) if len(r) == 4 and r[1] == "stroke"]
    assert [(r[0], r[3]) for r in strokes] == [("3", "0.2"), ("5", "0.2")]   # 2·l1
    points = {r[0]: r[1:] for r in rows(out) if len(r) == 7 and r[0].endswith(".0000")}
    # columns O, A, B, S2, C, S4: the pistons stand still at their dead centres with
    # |a_q| = l1·(1 ± l1/l2) = 0.125 / 0.075; the crank pin: |v_q| = |a_q| = l1
    assert points["0.0000"][1:3] == ["0.1 / 0.1", "0 / 0.125"]
    assert points["180.0000"][2] == "0 / 0.075"
    assert points["90.0000"][4] == "0 / 0.125"
    links = {r[0]: r[1:] for r in rows(out) if len(r) == 6 and r[0].endswith(".0000")}
    # rod 2 at φ = 0: ω_q2 = λ = l1/l2 = 0.25, ε_q2 = 0 (the crank turns clockwise: ω_q1 = −1)
    assert links["0.0000"][:2] == ["-1 / 0", "0.25 / 0"]


def test_check_in_russian_names_the_groups_and_the_cylinders_as_the_outputs_do():
    """--lang ru: an Assur group by its kind in Russian («ВВП B», as the record and the sheets
    name it; it printed the case file's «RRP B»), a cylinder by its key and its label
    («HP (ВД)»); in English as the case file spells them."""
    ru = invoke("check", CASES / "compressor.toml", "--lang", "ru")
    en = invoke("check", CASES / "compressor.toml")
    assert ru.exit_code == en.exit_code == 0, ru.output
    assert [r[0] for r in rows(ru.stdout) if r[0].startswith(("ВВП", "RRP"))] == ["ВВП B", "ВВП C"]
    assert [r[0] for r in rows(en.stdout) if r[0].startswith("RRP")] == ["RRP B", "RRP C"]
    assert [r[0] for r in rows(ru.stdout) if r[0].startswith(("HP", "LP"))] == ["HP (ВД)",
                                                                                "LP (НД)"]
    assert [r[0] for r in rows(en.stdout) if r[0] in ("HP", "LP")] == ["HP", "LP"]


def test_check_letters_a_points_digits_as_the_figures_do():
    """`check` printed «S3», «A2», «B1» where the scheme, the record and the sheets letter
    S₃, A₂, B₁ (mathfmt.point_name): in the mechanism's table, the links' centroids and the
    dead centres' columns."""
    res = invoke("check", CASES / "engine_inline4.toml", "--lang", "ru")
    assert res.exit_code == 0, res.output
    cells = {c for r in rows(res.stdout) for c in r}
    assert {"ВВП B₁", "O → A₂", "A₁ → B₁", "S₂"} <= cells, sorted(cells)[:40]
    assert not {c for c in cells if re.fullmatch(r"(?:[A-Z]\d+|.*[A-Z]\d+ → .*)", c)}
    res = invoke("check", CASES / "shaper.toml")
    header = next(line for line in res.stdout.splitlines() if "┃" in line and " P " in line)
    assert "S₃" in header and "S3" not in header


@pytest.mark.parametrize("name, expected", [
    ("fourbar.toml", "Crank-rocker four-bar"),
    ("slotted_link.toml", "Shaper: slotted-link mechanism"),
])
def test_check_example_cases(name, expected):
    res = invoke("check", CASES / name)
    assert res.exit_code == 0, res.output
    assert expected in res.stdout and "case is valid" in res.stdout


def one_error_line(res, *fragments: str) -> str:
    assert res.exit_code == 2, res.output
    assert res.stdout == ""
    err = res.stderr
    assert err.count("\n") == 1 and err.startswith("error: "), err
    assert "Traceback" not in err and "Traceback" not in res.stdout
    assert res.exception is None or isinstance(res.exception, SystemExit)
    for f in fragments:
        assert f in err, err
    return err


@pytest.mark.parametrize("old, new, fragments", [
    ("speed_rps = 10.0", "speed_rps = = 10.0", ["TOML syntax error", "line 10, column 13"]),
    ("speed_rps = 10.0", "speed_rsp = 10.0", ["machine.speed_rsp: unknown key; did you mean 'speed_rps'?"]),
    ("bore = 0.12                      # d2 [m]", "", ["cylinders[0].bore: missing required field"]),
    ("bore = 0.12 ", 'bore = "wide" ', ["cylinders[0].bore: input should be a valid number"]),
    ("bore = 0.12 ", "bore = nan ", ["cylinders[0].bore: must be a finite number (got nan)"]),
    ("[crank]\n", "[crank]\nlength = -0.1\n", ["crank.length: input should be greater than 0"]),
    ('"3" = { mass = 0.6,', '"3" = { mass = -0.6,', ["links.3.mass: input should be greater than 0"]),
    ('from = "A"\njoint = "B"', 'from = "C"\njoint = "B"', ["dyads[0].from: point 'C' is used before it is defined"]),
    ('joint = "C"', 'joint = "B"', ["dyads[1].joint: point name 'B' is already defined"]),
    ("delta     = 0.05", "delta     = 1.0", ["machine.delta: input should be less than 1"]),
    ('piston = "3"', 'piston = "4"', ["cylinders[0].piston: '4' is not the slider of an RRP dyad"]),
    ("rod_to_crank      = 4.0", "rod_to_crank      = 0.5",     # l2 = 0.05 m < l1: no assembly
     ["dyads[0]: dyad B (RRP, rod 2) cannot be assembled at crank angle φ = ",
      "the rod (0.05 m) must be at least 0.1 m"]),
], ids=["syntax", "unknown-key", "missing", "wrong-type", "nan", "negative-length", "negative-mass",
        "used-before-defined", "duplicate-name", "delta", "piston", "cannot-assemble"])
def test_check_bad_file_exits_2_with_one_line(tmp_path, old, new, fragments):
    assert old in BASE
    path = tmp_path / "bad.toml"
    path.write_text(BASE.replace(old, new, 1), encoding="utf-8")
    err = one_error_line(invoke("check", path), *fragments)
    assert err.startswith(f"error: {path}: ")


def test_a_file_saved_with_a_byte_order_mark_is_read(tmp_path):
    # Windows editors may start a UTF-8 file with a BOM; tomllib alone calls it a syntax error
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + BASE.encode("utf-8"))
    res = invoke("check", path)
    assert res.exit_code == 0, res.output


def test_check_missing_file_exits_2(tmp_path):
    one_error_line(invoke("check", tmp_path / "nope.toml"), "nope.toml: no such file")


def test_check_without_argument_is_a_usage_error():
    res = invoke("check")
    assert res.exit_code == 2
    assert "Traceback" not in res.output


def test_schema_prints_json():
    res = invoke("schema")
    assert res.exit_code == 0, res.output
    schema = json.loads(res.stdout)
    assert schema["title"] == "flywheel case file"
    assert {"machine", "crank", "dyads", "points", "links", "cylinders"} <= set(schema["properties"])
    assert "RRPSpec" in schema["$defs"]


def test_python_m_flywheel_help():
    proc = subprocess.run([sys.executable, "-m", "flywheel", "--help"], capture_output=True,
                          text=True, timeout=120, cwd=CASES.parent)
    assert proc.returncode == 0, proc.stderr
    for command in ("check", "schema", "run"):
        assert re.search(rf"\b{command}\b", proc.stdout)


def test_python_m_flywheel_in_process(monkeypatch, capsys):
    """`python -m flywheel check BAD` run as runpy runs it (flywheel/__main__.py as __main__,
    in this process; the process itself: the two tests above and below): the console script's
    one error line and exit 2; the signal handlers main() sets are restored after."""
    import runpy
    import signal

    from flywheel import __main__ as entry          # as a module: it runs nothing
    assert entry.__doc__.startswith("`python -m flywheel`")
    monkeypatch.delitem(sys.modules, "flywheel.__main__")   # runpy runs it afresh, as python -m
    monkeypatch.setattr(sys, "argv", ["flywheel", "check", str(CASES / "no_such_case.toml")])
    handlers = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        with pytest.raises(SystemExit) as stop:
            runpy.run_module("flywheel", run_name="__main__", alter_sys=True)
    finally:
        for s, h in handlers.items():
            signal.signal(s, h)
    out = capsys.readouterr()
    assert stop.value.code == 2 and out.out == ""
    assert out.err.startswith("error: ") and "no_such_case.toml" in out.err
    assert out.err.count("\n") == 1


def test_python_m_flywheel_check_bad_file(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(BASE.replace("delta     = 0.05", "delta     = 0"), encoding="utf-8")
    proc = subprocess.run([sys.executable, "-m", "flywheel", "check", str(path)],
                          capture_output=True, text=True, timeout=120, cwd=CASES.parent)
    assert proc.returncode == 2
    assert proc.stderr == f"error: {path}: machine.delta: input should be greater than 0 (got 0)\n"
    assert proc.stdout == ""


def test_check_a_slider_that_never_moves(tmp_path):
    # a rod hung from a fixed point: it used to end in a traceback; its kinematics assemble,
    # but nothing carries mass, so `run` refuses it — and `check` says the same (a case that
    # check calls valid also runs)
    path = tmp_path / "still.toml"
    path.write_text("""
[machine]
speed_rps = 1.0
delta = 0.1
analysis = "dynamics"          # asked for: refused (omitted: the kinematics alone)
[crank]
length = 0.1
[ground]
G = [0.0, 0.1]
[[dyads]]
kind = "RRP"
from = "G"
joint = "B"
rod = "2"
rod_length = 0.4
slider = "3"
guide = { angle_deg = 0.0 }
""", encoding="utf-8")
    res = invoke("check", path)
    assert res.exit_code == 2 and "Traceback" not in res.output
    assert "the machine has no inertia" in res.stderr
    assert invoke("run", path, "--no-plots", "--out", tmp_path / "o").stderr == res.stderr


def test_check_case_is_a_library_call_with_typed_numbers():
    """`flywheel check` prints a CheckReport that the library computes: the compressor's
    pistons (l1 = 0.1, l2 = 0.4 m) have strokes 2·l1, dead centres every 90°, and stand still
    there with |a_q| = l1·(1 ± l1/l2)."""
    import math

    import numpy as np

    from flywheel.cases.run import load_case
    from flywheel.dynamics.check import CheckReport, check_case

    rep = check_case(load_case(CASES / "compressor.toml"))
    assert isinstance(rep, CheckReport) and rep.tabulated is None
    assert rep.crank_speed_rps == pytest.approx(10.0, rel=1e-12)
    assert [(s.slider, s.stroke) for s in rep.sliders] == [("3", pytest.approx(0.2, abs=1e-12)),
                                                          ("5", pytest.approx(0.2, abs=1e-12))]
    assert np.degrees(rep.dead_centre_angles) == pytest.approx([0, 90, 180, 270], abs=1e-9)
    v_B, a_B = rep.point_analogues["B"]
    assert v_B[[0, 2]] == pytest.approx([0, 0], abs=1e-12)
    assert a_B[[0, 2]] == pytest.approx([0.1 * 1.25, 0.1 * 0.75], rel=1e-9)
    assert rep.link_analogues["2"][0][0] == pytest.approx(0.25, rel=1e-12)   # ω_q2 = λ at φ = 0
    press = check_case(load_case(CASES / "press.toml"))
    assert press.mechanism is None and press.tabulated.J_II.size == 13
    # Мдин = ω_m²/2·dJ_II/dφ, ω_m = 2π·140/60
    w = 2 * math.pi * 140 / 60
    assert press.tabulated.dynamic_moments == pytest.approx(w**2 / 2 * press.tabulated.dJ_II, rel=1e-12)
