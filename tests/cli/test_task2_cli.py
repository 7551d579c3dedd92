"""`flywheel task2` through the CLI: JSON contract, determinism, plots, one-line errors."""
import json
import math
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from helpers import err_text  # a CliRunner result's stderr (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
KEYS = {"omega_max", "omega_min", "omega_mean", "delta", "phi_omega_max_deg",
        "phi_omega_min_deg", "delta_T_max", "M_C", "segments"}

runner = CliRunner()


def run(*args):
    return runner.invoke(app, ["task2", *map(str, args)])



def test_json_contract_triangle():
    res = run("--json")
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert KEYS <= set(d)
    assert "J_required" not in d
    assert d["M_C"] == 60.0
    assert d["phi_omega_max_deg"] == 112.5 and d["phi_omega_min_deg"] == 247.5
    assert d["delta"] == pytest.approx(1.10446617e-4, rel=1e-8)
    assert [s["phi_deg"] for s in d["segments"]] == pytest.approx(
        [0, 90, 112.5, 180, 247.5, 270, 360])
    assert d["segments"][2]["kind"] == "crossing"


def test_json_is_byte_identical():
    a, b = run("--json", "--profile", "rectangle"), run("--json", "--profile", "rectangle")
    assert a.exit_code == 0 and a.stdout == b.stdout


def test_options_and_delta():
    res = run("--json", "--profile", "rectangle", "--md", 30, "--j", 6, "--omega0", 100,
              "--from", 0, "--to", 180, "--delta", 0.001)
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert d["M_C"] == pytest.approx(60.0)           # 30·2π = M_C·π
    assert d["J_required"] == pytest.approx(d["delta_T_max"] / (0.001 * d["omega_mean"] ** 2))


def test_given_peak_says_not_steady():
    res = run("--mc", 50)
    assert res.exit_code == 0, res.output
    assert "not steady" in res.stdout
    d = json.loads(run("--mc", 50, "--json").stdout)
    assert d["steady"] is False
    assert d["omega_end"] == pytest.approx(math.sqrt(40000 + 2 * 5 * math.pi / 12))


def test_summary_shows_the_table():
    res = run("--profile", "triangle")
    assert res.exit_code == 0
    for text in ("M_D = M_C", "112.5", "247.5", "199.988955", "0.000110447", "ΔT_max"):
        assert text in res.stdout


@pytest.mark.parametrize("name", sorted(p.name for p in CASES.glob("task2_*.toml")))
def test_every_case_runs(name):
    res = run("--case", CASES / name, "--json")
    assert res.exit_code == 0, res.output
    assert KEYS <= set(json.loads(res.stdout))


def test_plot(tmp_path):
    out = tmp_path / "t2.png"
    res = run("--plot", out)
    assert res.exit_code == 0, res.output
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    out2 = tmp_path / "areas.png"
    res = run("--case", CASES / "task2_khurmi_16_4.toml", "--plot", out2)
    assert res.exit_code == 0, res.output
    assert out2.stat().st_size > 1000


def test_plot_structure(monkeypatch):
    from matplotlib.figure import Figure

    from flywheel.constant_inertia.preset import seed_task
    from flywheel.render.mathfmt import sub_mathtext as mt
    from flywheel.render.task2 import plot

    r = seed_task("triangle")
    seen = {}
    orig = Figure.savefig

    def keep(fig, *a, **kw):
        seen["fig"] = fig
        return orig(fig, *a, **kw)

    monkeypatch.setattr(Figure, "savefig", keep)
    import io
    plot(r, io.BytesIO())
    axes = seen["fig"].axes
    assert len(axes) == 4                      # M, A, ω and ε beside ω (below it, same φ axis)
    labels = [line.get_label() for ax in axes for line in ax.get_lines()]
    # the symbols' subscripts are mathtext, never a literal "M_D" (issue 15)
    assert mt("M_D (driving)") == r"M$_\mathregular{D}$ (driving)"
    assert mt("M_D (driving)") in labels and mt("M_C (resistance)") in labels and "ω(φ)" in labels
    assert not [x for x in labels                  # "_child1": matplotlib's unnamed lines
                if "_" in x.replace(r"$_\mathregular", "") and not x.startswith("_child")]
    # units as every English figure writes them: "ω [rad/s]" (tests/render/test_nomenclature.py)
    assert axes[2].get_ylabel() == "ω [rad/s]"
    assert axes[3].get_xlabel() == "φ [deg]" and axes[3].get_ylabel() == "ε [rad/s²]"
    # the ε curve is (M_D − M_C)/J: 15/12 outside the triangle, (15 − 60)/12 at its apex;
    # its extremes are marked where the result puts them
    eps = next(line for line in axes[3].get_lines()
               if line.get_label() == mt("ε(φ) = (M_D − M_C)/J"))
    x, y = eps.get_xdata(), eps.get_ydata()
    assert max(y) == 15 / 12 and min(y) == (15 - 60) / 12 and y[list(x).index(180.0)] == -3.75
    marks = {line.get_label(): (line.get_xdata()[0], line.get_ydata()[0])
             for line in axes[3].get_lines() if line.get_label().startswith("ε$_")}
    assert marks == {mt("ε_max = 1.25 rad/s² at 0°"): (0.0, 1.25),
                     mt("ε_min = -3.75 rad/s² at 180°"): (180.0, -3.75)}


def _case(tmp_path, text):
    p = tmp_path / "c.toml"
    p.write_text(text, encoding="utf-8")
    return p


GOOD = """
[speed]
omega0 = 200
[flywheel]
J = 12
[driving]
kind = "constant"
value = 15
"""


@pytest.mark.parametrize("args,match", [
    (["--j", 0], "--j must be positive"),
    (["--j", -12], "--j must be positive"),
    (["--omega0", 0], "--omega0 must be positive"),
    (["--omega0", -200], "--omega0 must be positive"),
    (["--md", 0], "--md must be positive"),
    (["--from", 200, "--to", 100], "--from (200°) must be less than --to (100°)"),
    (["--from", 90, "--to", 90], "must be less than"),
    (["--from", 300], "must be less than"),             # triangle's default --to is 270
    (["--to", 400], "within 0…360°"),
    (["--profile", "circle"], "--profile must be triangle or rectangle"),
    (["--delta", 0], "--delta must lie between 0 and 2"),
    (["--mc", 1e6, "--omega0", 1], "the machine stops at φ = "),
    (["--case", "nope.toml"], "nope.toml: no such file"),
    (["--case", "x.toml", "--md", 3], "--case takes its data from the file; drop --md"),
])
def test_bad_options_exit_2_with_one_line(args, match):
    res = run(*args)
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert match in err
    assert err.startswith("error: ") and err.count("\n") == 1
    assert "Traceback" not in res.output


@pytest.mark.parametrize("extra,match", [
    ("""[resistance]
kind = "points"
points = [[0, 0], [180, 60], [90, 0], [360, 0]]
scale = "balance"
""", "resistance.points[2]: angle 90° comes after 180°: angles must not decrease"),
    ("""[resistance]
kind = "points"
points = [[0, 0], [180, 60], [300, 0]]
""", "resistance.points: must span the cycle 0…360° (spans 0…300°)"),
    ("""[resistance]
kind = "triangle"
from_deg = 90
to_deg = 270
base = 30
peak = "balance"
""", "resistance.peak: the cycle balance needs a negative resistance moment"),
    ("""[resistance]
kind = "rectangle"
from_deg = 90
to_deg = 180
peek = 60
""", "resistance.peek: unknown key; did you mean 'peak'?"),
])
def test_bad_case_files_exit_2_with_one_line(tmp_path, extra, match):
    res = run("--case", _case(tmp_path, GOOD + extra))
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert match in err, err
    assert err.count("\n") == 1 and "c.toml: " in err


def test_areas_not_summing_to_zero(tmp_path):
    text = """[speed]
mean_rpm = 600
[flywheel]
J = 10
[diagram]
areas = [52, -124, 92, -140, 85, -72, 100]
moment_scale = 600
angle_scale_deg = 3
"""
    res = run("--case", _case(tmp_path, text))
    assert res.exit_code == 2
    assert "diagram.areas: sum to -7, not 0" in err_text(res)


def test_negative_J_in_case(tmp_path):
    res = run("--case", _case(tmp_path, GOOD.replace("J = 12", "J = -1") + """[resistance]
kind = "constant"
value = "balance"
"""))
    assert res.exit_code == 2
    assert "flywheel.J: must be positive (got -1 kg·m²)" in err_text(res)


# -- audit fixes -----------------------------------------------------------------------------------

ZERO_MEAN = """
[flywheel]
J = 10
[driving]
kind = "harmonic"
a = [300]
b = [-500]
orders = [2]
[resistance]
kind = "constant"
value = 0
"""


def test_zero_mean_moments_with_a_mean_speed(tmp_path):
    res = run("--case", _case(tmp_path, "[speed]\nmean_rpm = 250\n" + ZERO_MEAN), "--json")
    assert res.exit_code == 0, res.output
    d = json.loads(res.stdout)
    assert d["steady"] is True and d["work_end"] == 0.0
    assert d["rpm"]["omega_mean"] == pytest.approx(250.0, rel=1e-14)


def test_zero_mean_moments_with_omega0_are_steady(tmp_path):
    res = run("--case", _case(tmp_path, "[speed]\nomega0_rpm = 250\n" + ZERO_MEAN))
    assert res.exit_code == 0, res.output
    assert "not steady" not in res.stdout
    assert "ω_max" in res.stdout


def test_help_shows_the_units():
    res = runner.invoke(app, ["task2", "--help"], env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    text = " ".join(res.stdout.split())
    for unit in ("J [kg·m²]", "φ = 0 [rad/s]", "resistance graph [deg] (default 90)",
                 "End of the resistance graph [deg]", "M_D [N·m]"):
        assert unit in text, unit


OVERFLOW = ("is not finite", "the values overflow double precision")


# one non-finite policy (cli.guard.not_finite): "who: <quantity> is not finite (…): the values
# overflow …" — the options or fields to blame, the quantity as the JSON names it, what happened
@pytest.mark.parametrize("args,match", [
    (["--md", 1e308], ("error: --md 1e+308: M_C is not finite (the cycle balance gives a "
                       "resistance moment of inf N·m): ")),
    (["--md", 1e308, "--profile", "rectangle"], "error: --md 1e+308: M_C is not finite ("),
    (["--omega0", 1e200], "error: --omega0 1e+200: omega_max is not finite (inf): "),
    (["--delta", 1e-320], "error: --delta 9.99989e-321: J_required is not finite (inf): "),
    (["--from", 1e-300, "--to", 1e-299], "error: --from 1e-300, --to 1e-299: work_resistance is "
                                         "not finite ("),
    (["--mc", 1e308, "--omega0", 1e308],
     "error: --omega0 1e+308, --mc 1e+308: omega_max is not finite (inf): "),
])
def test_overflow_is_one_line(args, match):
    for extra in ([], ["--json"]):
        res = run(*args, *extra)
        assert res.exit_code == 2, res.output
        err = err_text(res)
        assert err.startswith(match), err
        assert OVERFLOW[1] in err
        assert err.count("\n") == 1 and "Infinity" not in res.output and "NaN" not in res.output


def test_overflow_in_a_case_names_the_field(tmp_path):
    res = run("--case", _case(tmp_path, GOOD.replace("value = 15", "value = 1e308") + """
[resistance]
kind = "triangle"
from_deg = 90
to_deg = 270
peak = "balance"
"""), "--json")
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert err.startswith("error: ") and err.count("\n") == 1
    assert "c.toml: driving.value: M_C is not finite (" in err and OVERFLOW[1] in err, err


@pytest.mark.parametrize("args", [["--profile", "rectangle"], ["--profile", "triangle"],
                                  ["--profile", "rectangle", "--md", 3]])
def test_case_rejects_profile(tmp_path, args):
    res = run("--case", _case(tmp_path, GOOD + "[resistance]\nkind = \"constant\"\n"
                                               "value = \"balance\"\n"), *args)
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert err.startswith("error: --case takes its data from the file; drop --profile"), err
    assert err.count("\n") == 1


def test_case_that_is_a_folder(tmp_path):
    res = run("--case", tmp_path)
    assert res.exit_code == 2, res.output
    assert err_text(res) == f"error: {tmp_path}: is a folder, expected a TOML case file\n"


def test_plot_into_a_folder(tmp_path):
    res = run("--plot", tmp_path)
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert err == f"error: --plot {tmp_path}: is a folder, expected an image file\n"


def test_unsteady_summary_prints_a_tiny_work_as_it_is():
    # a real but tiny net work must not read "the work over the cycle is 0 J"
    import io

    from rich.console import Console

    from flywheel.constant_inertia.graphs import constant
    from flywheel.constant_inertia.solve import solve
    from flywheel.render.task2 import print_summary

    r = solve(constant(1e-13), constant(0.0), 1.0, omega0=1.0)
    assert not r.steady
    out = io.StringIO()
    print_summary(r, console=Console(file=out, width=200))
    assert "the work over the cycle is 6.28319e-13 J" in out.getvalue()


# -- --lang ru ---------------------------------------------------------------------------------

NUMBER = r"-?\d+(?:\.\d+)?(?:e[+-]?\d+)?"
NUMBER_RU = r"[\u2212-]?\d+(?:\u202f\d{3})*(?:,\d+)?"


def _numbers(text, skip_title=True, number=NUMBER):
    """Every number printed, in order; the title line (which names the seed in each language)
    left out."""
    import re

    lines = text.splitlines()[1 if skip_title else 0:]
    return re.findall(number, "\n".join(lines))


@pytest.mark.parametrize("args", [[], ["--profile", "rectangle", "--delta", 0.05, "--mc", 50],
                                  ["--case", CASES / "task2_khurmi_16_12.toml"],
                                  ["--case", CASES / "task2_khurmi_16_4.toml"]])
def test_lang_ru_same_numbers_russian_labels(args):
    env = {"COLUMNS": "250"}
    en = runner.invoke(app, ["task2", *map(str, args)], env=env)
    ru = runner.invoke(app, ["task2", *map(str, args), "--lang", "ru"], env=env)
    assert en.exit_code == 0 and ru.exit_code == 0, ru.output
    for heading in ("Участки: ½·J_пр·(ω² − ω₀²) = A(φ) = ∫(M_Д − M_С) dφ", "Результаты",
                    "величина", "значение", "рад/с", "ω_ср = (ω_max + ω_min)/2", "ΔT_нб",
                    "приведённый момент инерции J_пр"):
        assert heading in ru.stdout, heading
    for english in ("Segments", "Results", "quantity", "rad/s", "rpm", "reduced inertia"):
        assert english not in ru.stdout, english
    # the same numbers in Russian typography (render/numbers.py): a decimal comma, a true
    # minus, narrow spaces, four significant digits, round-off as 0
    ru_values = [float(x.replace("\u2212", "-").replace("\u202f", "").replace(",", "."))
                 for x in _numbers(ru.stdout, number=NUMBER_RU)]
    en_values = [float(x) for x in _numbers(en.stdout)]
    assert len(ru_values) == len(en_values) > 30
    assert all(abs(r - e) <= 5e-4 * abs(e) + 1e-9 for r, e in zip(ru_values, en_values))
    # the JSON document is the same in every language
    assert run(*args, "--json", "--lang", "ru").stdout == run(*args, "--json").stdout


def test_lang_ru_seed_words():
    res = run("--lang", "ru", "--profile", "rectangle", "--delta", 0.05)
    assert res.exit_code == 0, res.output
    out = " ".join(res.stdout.split())
    for text in ("Задача 2, момент сопротивления — прямоугольник",
                 "баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт M_С = 60 Н·м",
                 "граница", "об/мин при φ =", "мощность", "J_пр для δ = 0,05"):
        assert text in out, text
    res = run("--lang", "ru", "--mc", 50)
    out = " ".join(res.stdout.split())
    assert "движение не установившееся" in out and "M_Д = 15 Н·м, M_С = 50 Н·м (заданы)" in out
    assert "│ M_Д = M_С │" in out and "треугольник" in out


def test_lang_ru_plot_labels(tmp_path, monkeypatch):
    from matplotlib.figure import Figure

    from flywheel.constant_inertia.preset import seed_task
    from flywheel.render.mathfmt import sub_mathtext as mt
    from flywheel.render.task2 import plot

    seen = {}
    orig = Figure.savefig

    def keep(fig, *a, **kw):
        seen["fig"] = fig
        return orig(fig, *a, **kw)

    monkeypatch.setattr(Figure, "savefig", keep)
    plot(seed_task("triangle"), tmp_path / "ru.png", lang="ru")
    axes = seen["fig"].axes
    labels = [line.get_label() for ax in axes for line in ax.get_lines()]
    assert mt("M_Д (движущий)") == r"M$_\mathregular{Д}$ (движущий)"
    assert mt("M_Д (движущий)") in labels and mt("M_С (сопротивления)") in labels
    assert mt("ε(φ) = (M_Д − M_С)/J_пр") in labels and mt("ω_ср") in labels
    # the course's style "ω, рад/с", as every figure of run writes its axes
    assert axes[2].get_ylabel() == "ω, рад/с"
    assert axes[3].get_xlabel() == "φ, °" and axes[3].get_ylabel() == "ε, рад/с²"
    res = run("--lang", "ru", "--plot", tmp_path / "cli.png")
    assert res.exit_code == 0 and "график записан в" in res.stdout
    assert (tmp_path / "cli.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_lang_unknown_is_one_line():
    res = run("--lang", "de")
    assert res.exit_code == 2
    assert err_text(res) == "error: --lang: 'de' is not a language (allowed: en, ru)\n"


@pytest.mark.parametrize("profile", ["triangle", "rectangle"])
def test_to_a_rounding_hair_beyond_the_cycle_is_the_cycles_end(profile):
    """--to 360.0000000001 passes the range check (its 1e-12 tolerance) and is the cycle's end:
    the same answer as --to 360 (it once failed with "graph angles must not decrease")."""
    hair = run("--json", "--profile", profile, "--to", "360.0000000001")
    exact = run("--json", "--profile", profile, "--to", 360)
    assert hair.exit_code == 0, hair.output
    a, b = json.loads(hair.stdout), json.loads(exact.stdout)
    assert a["M_C"] == pytest.approx(b["M_C"], rel=1e-9)
    assert a["omega_max"] == pytest.approx(b["omega_max"], rel=1e-12)


def test_plot_that_fails_leaves_the_old_image_and_no_temporary(tmp_path, monkeypatch):
    """--plot is written whole or not at all: savefig writes half a file and fails (a full
    disk); the old image keeps its bytes, nothing else is left in the folder."""
    from matplotlib.figure import Figure

    out = tmp_path / "t2.png"
    out.write_bytes(b"the old image")

    def half(self, fname, **kw):
        Path(fname).write_bytes(b"\x89PNG half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", half)
    res = run("--plot", out)
    assert res.exit_code == 2, res.output
    assert err_text(res) == (f"error: --plot {out}: cannot write the image ([Errno 28] No space "
                             f"left on device: '{out}')\n")
    assert out.read_bytes() == b"the old image"
    assert [p.name for p in tmp_path.iterdir()] == ["t2.png"]


def test_the_record_lists_the_data_as_the_book_states_them(tmp_path):
    """Khurmi & Gupta, Example 16.4 (cases/task2_khurmi_16_4.toml): the book gives 1800 rpm, a
    flywheel of 36 kg with a radius of gyration of 150 mm, and the areas 295, 685, 40, 340, 960,
    270 mm² of the turning-moment diagram at 1 mm = 5 N·m and 1 mm = 1°. The Russian record
    lists them so beside the J_пр and ω₀ it computes from them (it had listed only those)."""
    out = tmp_path / "o"
    res = runner.invoke(app, ["task2", "--case", str(CASES / "task2_khurmi_16_4.toml"),
                              "--lang", "ru", "--out", str(out), "--report", "md"])
    assert res.exit_code == 0, res.output
    md = (out / "report.md").read_text(encoding="utf-8")
    for row in ("| Средняя частота вращения n_ср | 1800 | об/мин |",
                "| Масса маховика m | 36 | кг |", "| Радиус инерции маховика k | 0,15 | м |",
                "| Площади диаграммы моментов | 295; −685; 40; −340; 960; −270 | мм² |",
                "| Диаграмма: масштаб моментов | 5 | Н·м/мм |",
                "| Диаграмма: масштаб углов | 1 | °/мм |"):
        assert row in md, row
    assert "Таблица 2 — Данные условия задачи" in md
