"""Bounded work and readers that cannot be crashed (issue 23).

The work of task 2 is counted, never timed: evaluations of a graph's pieces, numpy calls of a long
harmonic series. The limits (terms, points, angles, texts, nesting, integers) are refused in one
line; an error line echoes a huge value cut to about 80 characters. Timings are in
benchmarks/bench_bounds.py.
"""
from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.constant_inertia import crossings as cr
from flywheel.constant_inertia import graphs
from flywheel.constant_inertia.graphs import Piece, constant, harmonic, piecewise_linear
from flywheel.constant_inertia.solve import solve
from flywheel.errors import CaseFileError
from flywheel.io.text import cut, cut_echoes, cut_end
from flywheel.io.toml import MAX_DEPTH, read_toml

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "cases"
runner = CliRunner()


# -- task 2: work linear in the size of a graph ------------------------------------------------

def _points_graph(n: int):
    """A piecewise-linear M_D of n points, 1000 + 500·sin(0.37·i) N·m, over 360°."""
    pts = [(2 * math.pi * i / (n - 1), 1000.0 + 500.0 * math.sin(0.37 * i)) for i in range(n)]
    return piecewise_linear(pts)


def _evaluations(monkeypatch, n: int) -> int:
    """Evaluations of pieces (Piece.value, Piece.work) in one solve of an n-point graph
    balanced by a constant."""
    count = [0]
    value, work = Piece.value, Piece.work

    def counted_value(self, phi):
        count[0] += 1
        return value(self, phi)

    def counted_work(self, phi):
        count[0] += 1
        return work(self, phi)

    monkeypatch.setattr(Piece, "value", counted_value)
    monkeypatch.setattr(Piece, "work", counted_work)
    M_D = _points_graph(n)
    solve(M_D, constant(M_D.work() / (2 * math.pi)), 10.0, omega0=15.0)
    return count[0]


def test_a_points_graph_costs_a_fixed_number_of_evaluations_per_point(monkeypatch):
    """Four times the points, four times the evaluations (it was quadratic: a linear search of
    the pieces for every row, min(A) recomputed for every row)."""
    small, big = _evaluations(monkeypatch, 2000), _evaluations(monkeypatch, 8000)
    assert 3.5 < big / small < 4.5
    assert big < 40 * 8000


def test_moment_value_finds_its_piece_by_bisection():
    """The piece of an angle, found by bisection, is the one a linear search finds: at a jump
    the value after (side +1) or before (−1), outside the cycle the end pieces."""
    m = piecewise_linear([(0, 0), (1, 10), (1, 20), (2, 0), (3, 5)], cycle=3)
    assert [m.value(x) for x in (0.0, 0.5, 1.0, 1.5, 2.0, 3.0)] == [0.0, 5.0, 20.0, 10.0, 0.0,
                                                                      5.0]
    assert [m.value(x, -1) for x in (0.0, 1.0, 2.0, 3.0)] == [0.0, 10.0, 0.0, 5.0]


def _series(n: int, main: int) -> tuple:
    """sin(main·φ) plus n − 1 other orders of amplitude 1e-20: a long series whose crossings
    are those of sin(main·φ), at jπ/main, to 1e-19 rad."""
    return tuple((float(k), 1.0 if k == main else 1e-20, 0.0) for k in range(1, n + 1))


def test_a_long_series_finds_the_known_crossings_with_a_few_numpy_calls(monkeypatch):
    """A series of 300 terms (> LONG_SERIES: numpy, level by level): the 99 crossings of
    sin 50φ on (0, 2π) at jπ/50; the series is evaluated in at most a few hundred numpy calls
    (one per level of the subdivision and per bisection step), not once per point."""
    calls = [0]
    many = Piece.values_and_slopes

    def counted(self, phis):
        calls[0] += 1
        return many(self, phis)

    monkeypatch.setattr(Piece, "values_and_slopes", counted)
    p = Piece(0.0, 2 * math.pi, 0.0, 0.0, _series(300, 50))
    assert p.arrays is not None
    roots = cr.crossings(p)
    assert len(roots) == 99
    assert max(abs(x - j * math.pi / 50) for j, x in enumerate(roots, 1)) < 1e-12
    assert calls[0] < 300


def test_the_long_series_path_agrees_with_the_short_one(monkeypatch):
    """The same series of 40 terms summed by numpy (LONG_SERIES = 16) and term by term
    (LONG_SERIES raised): the same crossings, stationary points and time law, to 1e-12."""
    terms = tuple((float(k), math.sin(3.0 * k) / k, math.cos(5.0 * k) / k) for k in range(1, 41))

    def run():
        r = solve(harmonic(300.0, [t[1] for t in terms], [t[2] for t in terms]),
                  constant(300.0), 0.5, omega0=40.0)
        return [row.phi for row in r.rows], [row.t for row in r.rows], r.epsilon_max, r.omega_min

    fast = run()
    monkeypatch.setattr(graphs, "LONG_SERIES", 10 ** 9)
    slow = run()
    assert len(fast[0]) == len(slow[0]) > 5
    for a, b in zip(fast[:2], slow[:2]):
        assert max(abs(x - y) for x, y in zip(a, b)) < 1e-12
    assert fast[2] == pytest.approx(slow[2], rel=1e-12)
    assert fast[3] == pytest.approx(slow[3], rel=1e-14)


def test_series_evaluation_memory_is_chunked():
    """values_and_slopes evaluates at most CHUNK entries of terms × angles at a time, and
    gives what value() gives at each angle."""
    p = Piece(0.0, 2 * math.pi, 1.0, 0.5, _series(1000, 7))
    xs = [2 * math.pi * i / 999 for i in range(1000)]      # 1e6 entries: four chunks
    m, d = p.values_and_slopes(xs)
    assert max(abs(m[i] - p.value(x)) for i, x in enumerate(xs)) < 1e-12
    assert max(abs(d[i] - p.value_and_slope(x)[1]) for i, x in enumerate(xs)) < 1e-9
    assert graphs.CHUNK // 1000 < len(xs)


# -- the limits, refused in one line -------------------------------------------------------------

def _task2(tmp_path, text: str, *args: str):
    path = tmp_path / "c.toml"
    path.write_text(text, encoding="utf-8")
    return runner.invoke(app, ["task2", "--case", str(path), "--json", *args])


def _one_line(res) -> str:
    assert res.exit_code == 2, res.output
    line = res.stderr
    assert line.count("\n") == 1 and "Traceback" not in line and not res.stdout, line
    return line


POINTS_CASE = """[speed]
omega0 = 15.0
[flywheel]
J = 10.0
[resistance]
kind = "constant"
value = "balance"
[driving]
kind = "points"
points = {points}
"""


def test_points_beyond_the_limit_are_refused(tmp_path):
    n = graphs.MAX_POINTS
    pts = ", ".join(f"[{360.0 * i / n!r}, {1000.0 + (i % 7)}]" for i in range(n + 1))
    line = _one_line(_task2(tmp_path, POINTS_CASE.format(points=f"[{pts}]")))
    assert f"c.toml: driving.points: has {n + 1} points (allowed: at most {n})" in line


def test_points_at_the_limit_are_solved(tmp_path):
    n = graphs.MAX_POINTS
    pts = ", ".join(f"[{360.0 * i / (n - 1)!r}, {1000.0 + (i % 7)}]" for i in range(n))
    res = _task2(tmp_path, POINTS_CASE.format(points=f"[{pts}]"))
    assert res.exit_code == 0, res.stderr


def test_terms_at_the_limit_are_solved(tmp_path):
    a = ", ".join(["1e-9"] * graphs.MAX_TERMS)
    text = POINTS_CASE.replace('kind = "points"\npoints = {points}',
                               f'kind = "harmonic"\na0 = 100.0\na = [{a}]')
    res = _task2(tmp_path, text)
    assert res.exit_code == 0, res.stderr


@pytest.mark.parametrize("lang, words", [
    ("en", "driving.a: has 1001 terms (allowed: at most 1000)"),
    ("ru", "driving.a: 1001 член — слишком много (допустимо не больше 1000)"),
])
def test_too_many_terms_in_both_languages(tmp_path, lang, words):
    a = ", ".join(["1.0"] * 1001)
    text = POINTS_CASE.replace('kind = "points"\npoints = {points}',
                               f'kind = "harmonic"\na0 = 100.0\na = [{a}]')
    assert words in _one_line(_task2(tmp_path, text, "--lang", lang))


def test_a_long_title_is_refused_and_its_echo_cut(tmp_path):
    text = (CASES / "task2_seed_triangle.toml").read_text(encoding="utf-8")
    text = "\n".join('title = "' + "x" * 100_000 + '"' if ln.startswith("title") else ln
                     for ln in text.splitlines())
    line = _one_line(_task2(tmp_path, text))
    assert "c.toml: title: string should have at most 1000 characters" in line
    assert len(line) < 300 and "…" in line


def test_a_title_at_the_limit_is_shown_whole_and_a_longer_one_cut(tmp_path):
    """A case's title of 1000 characters reaches the terminal whole; a longer one given through
    the library (no case file to refuse it) is cut with «…» at 1000."""
    import io

    from rich.console import Console

    from flywheel.cases.task2 import load_task2_case, solve_case
    from flywheel.render.task2 import print_summary

    text = (CASES / "task2_seed_triangle.toml").read_text(encoding="utf-8")
    title = next(ln for ln in text.splitlines() if ln.startswith("title"))
    path = tmp_path / "c.toml"
    path.write_text(text.replace(title, 'title = "' + "y" * 1000 + '"'), encoding="utf-8")
    res = runner.invoke(app, ["task2", "--case", str(path)])
    assert res.exit_code == 0 and res.stdout.count("y" * 40) >= 1
    assert "…" not in res.stdout.split("\n\n")[0]
    r = solve_case(load_task2_case(path), str(path))
    out = io.StringIO()
    print_summary(r, "z" * 5000, "", console=Console(file=out, width=120))
    shown = out.getvalue()
    assert shown.count("z") == 999 and "…" in shown


def test_every_error_line_keeps_its_path_and_cuts_the_value(tmp_path):
    """A 40 000-character value and a 20 000-character key: the file and field path whole, the
    value cut to about 80 characters, in English and in Russian."""
    base = (CASES / "task2_seed_triangle.toml").read_text(encoding="utf-8")
    for lang in ("en", "ru"):
        line = _one_line(_task2(tmp_path, base.replace("omega0 = 200.0",
                                                      'omega0 = "' + "7 " * 20000 + '"'),
                                "--lang", lang))
        assert f"{tmp_path / 'c.toml'}: speed.omega0: " in line and len(line) < 400
        line = _one_line(_task2(tmp_path, base.replace("omega0 = 200.0", "omega0 = 200.0\n"
                                                      + "k" * 20000 + " = 1"), "--lang", lang))
        assert f"{tmp_path / 'c.toml'}: speed.kkk" in line and len(line) < 400


def test_cut_helpers():
    assert cut("a" * 200) == "a" * 39 + "…" + "a" * 40 and len(cut("a" * 200)) == 80
    assert cut_end("b" * 3000) == "b" * 999 + "…" and cut_end("b" * 1000) == "b" * 1000
    assert cut_echoes("f.toml: x: " + "z" * 1000) == "f.toml: x: " + cut("z" * 1000)
    path = "/tmp/" + "d" * 150 + "/c.toml"
    assert cut_echoes(f"{path}: bad") == f"{path}: bad"      # a path up to 400 characters
    assert len(cut_echoes("w " * 5000)) == 960


# -- readers that cannot be crashed --------------------------------------------------------------

@pytest.mark.parametrize("depth", [MAX_DEPTH + 1, 400, 5000])
def test_nesting_too_deep_is_one_line(tmp_path, depth):
    path = tmp_path / "deep.toml"
    path.write_text("x = " + "[" * depth + "]" * depth + "\n", encoding="utf-8")
    with pytest.raises(CaseFileError, match=r"deep\.toml: .*nested too deep \(allowed: at most "
                                            r"32 levels\)"):
        read_toml(path)


def test_nesting_at_the_limit_is_read(tmp_path):
    path = tmp_path / "ok.toml"
    path.write_text("x = " + "[" * (MAX_DEPTH - 1) + "]" * (MAX_DEPTH - 1) + "\n",
                    encoding="utf-8")
    assert isinstance(read_toml(path)["x"], list)


@pytest.mark.parametrize("digits, where", [(5000, ""), (20, "a.b: ")])
def test_integers_too_long_are_one_line(tmp_path, digits, where):
    path = tmp_path / "n.toml"
    path.write_text("[a]\nb = " + "9" * digits + "\n", encoding="utf-8")
    with pytest.raises(CaseFileError, match=rf"n\.toml: {where}an integer too long"):
        read_toml(path)
    path.write_text("[a]\nb = 9223372036854775807\nc = -9223372036854775808\n", encoding="utf-8")
    assert read_toml(path)["a"]["b"] == 2 ** 63 - 1


def test_a_deep_file_through_the_whole_process(tmp_path):
    """As a new user: `python -m flywheel task2` with a file nested 10 000 levels deep."""
    path = tmp_path / "deep.toml"
    path.write_text("x = " + "[" * 10000 + "]" * 10000 + "\n", encoding="utf-8")
    res = subprocess.run([sys.executable, "-m", "flywheel", "task2", "--case", str(path)],
                         capture_output=True, text=True, timeout=60)
    assert res.returncode == 2 and res.stderr.count("\n") == 1, res.stderr
    assert "nested too deep" in res.stderr and "Traceback" not in res.stderr


# -- no silent nonsense --------------------------------------------------------------------------

@pytest.mark.parametrize("edit, words", [
    (("orders = [2]", "orders = [0.3]"), "driving.orders[0]: order 0.3 does not repeat over the "
                                         "cycle of 360° (allowed: whole multiples of "
                                         "360/cycle_deg = 1)"),
    (("a = [600.0]", "a = [1e200]"), "driving.a: 1e+200 N·m is out of range"),
    (("a = [600.0]", "a = [1e308]"), "driving.a: 1e+308 N·m is out of range"),
    (("title =", "cycle_deg = 1000\ntitle ="), "cycle_deg: 1000° is neither whole revolutions"),
])
def test_meaningless_task2_inputs_are_refused(tmp_path, edit, words):
    text = (CASES / "task2_khurmi_16_12.toml").read_text(encoding="utf-8").replace(*edit)
    assert words in _one_line(_task2(tmp_path, text))


def test_periodic_orders_of_a_longer_or_shorter_cycle_are_accepted(tmp_path):
    """k·Φ/360° whole: order 0.5 over 720° (a four-stroke engine), order 2 over 180°."""
    text = (CASES / "task2_khurmi_16_12.toml").read_text(encoding="utf-8")
    res = _task2(tmp_path, text.replace("orders = [2]", "orders = [0.5]")
                 .replace("title =", "cycle_deg = 720\ntitle ="))
    assert res.exit_code == 0, res.stderr
    res = _task2(tmp_path, text.replace("title =", "cycle_deg = 180\ntitle =")
                 .replace('a = [500.0]', 'a = [500.0]\norders = [2]'))
    assert res.exit_code == 0, res.stderr


def test_an_overflowing_moment_is_not_a_steady_energy():
    """1e308·sin 2φ (the library, below the case's bounds): not 'the energy does not
    fluctuate' but a quantity that is not finite."""
    from flywheel.constant_inertia.solve import NotFiniteError

    with pytest.raises(NotFiniteError, match="work_driving is not finite"):
        solve(harmonic(0.0, [1e308], orders=[2]), constant(0.0), None, omega_mean=10.0,
              delta=0.05)


@pytest.mark.parametrize("at, words", [
    ("1e308", "--at: 1e+308° is out of range (allowed: -1e+06 … 1e+06°"),
    ("-2e6", "--at: -2e+06° is out of range"),
])
def test_run_at_is_bounded(tmp_path, at, words):
    res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots", "--out",
                              str(tmp_path / "o"), "--at", at])
    assert words in _one_line(res)
    assert not (tmp_path / "o").exists()


def test_run_at_within_the_bound_is_taken_modulo_the_cycle(tmp_path):
    """--at 1e6 is reported at 1e6 mod 360 = 280°: the same state as --at 280."""
    import json

    docs = []
    for at in ("1e6", "280"):
        res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots", "--json",
                                  "--out", str(tmp_path / at), "--at", at])
        assert res.exit_code == 0, res.output
        docs.append(json.loads(res.stdout)["results"]["at"][0])
    assert docs[0]["phi_deg"] == 1e6 and docs[1]["phi_deg"] == 280.0
    assert docs[0]["omega"] == pytest.approx(docs[1]["omega"], rel=1e-12)
    assert docs[0]["M_sum"] == pytest.approx(docs[1]["M_sum"], rel=1e-9)


@pytest.mark.parametrize("lang, words", [
    ("en", "c.toml: resistance: with the driving graph: 3000 pieces × 1000 harmonic terms is too "
           "much work (allowed: pieces × (1 + terms) ≤ 2e+06"),
    ("ru", "c.toml: resistance: вместе с графиком движущего момента: 3000 участков × 1000 "
           "гармоник — слишком большая работа"),
])
def test_a_long_series_against_a_long_points_graph_is_refused(tmp_path, lang, words):
    """The pieces of M_D − M_C each carry every term: 3000 points against 1000 terms would be
    6e6 piece-terms, beyond 2e6."""
    n = 3000
    pts = ", ".join(f"[{360.0 * i / (n - 1)!r}, 5000.0]" for i in range(n))
    a = ", ".join(["1.0"] * 1000)
    text = (f'[speed]\nomega0 = 15.0\n[flywheel]\nJ = 10.0\n[driving]\nkind = "harmonic"\n'
            f'a0 = 5000.0\na = [{a}]\n[resistance]\nkind = "points"\npoints = [{pts}]\n')
    assert words in _one_line(_task2(tmp_path, text, "--lang", lang))
