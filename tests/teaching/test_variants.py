"""`flywheel variants`: templates, deterministic draws, the answer key equal to a direct
analysis of each variant file, the grid it uses, one-line errors for bad templates."""
import csv
import json
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.render.task2 import to_dict
from flywheel.cases.task2 import load_task2_case, solve_case
from flywheel.teaching.variants import RUN_POINTS, answer_value, load_template
from helpers import err_text  # a CliRunner result's stderr (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
COMPRESSOR = CASES / "variants_compressor.toml"
TASK2 = CASES / "variants_task2.toml"

runner = CliRunner()


def invoke(*args):
    return runner.invoke(app, ["variants", *map(str, args)])



def one_line_error(res, *fragments):
    assert res.exit_code == 2, res.output
    err = err_text(res)
    assert "Traceback" not in err and "Traceback" not in res.output
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    for f in fragments:
        assert f in lines[0], lines[0]
    return lines[0]


@pytest.fixture(scope="module")
def compressor_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("v") / "compressor"
    res = invoke(COMPRESSOR, "--count", 3, "--seed", 11, "--out", out)
    assert res.exit_code == 0, res.output
    return out


@pytest.fixture(scope="module")
def task2_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("v") / "task2"
    res = invoke(TASK2, "--count", 4, "--seed", 5, "--out", out)
    assert res.exit_code == 0, res.output
    return out


def test_writes_the_files(compressor_dir):
    names = sorted(p.name for p in compressor_dir.iterdir())
    assert names == [".flywheel-manifest.json", "answers.csv", "answers.json", "students.csv",
                     "variant_01.toml", "variant_02.toml", "variant_03.toml"]
    key = json.loads((compressor_dir / "answers.json").read_text())
    assert key["kind"] == "run" and key["seed"] == 11 and key["n_points"] == RUN_POINTS
    assert list(key["variants"]) == ["01", "02", "03"]
    assert key["answers"] == ["driving_moment", "delta_T_max", "J_required", "J_flywheel",
                              "flywheel_disk.D"]
    assert key["tolerance"] == 0.01 and key["tolerances"] == {"flywheel_disk.D": 0.02}
    with open(compressor_dir / "students.csv", newline="") as f:
        rows = list(csv.reader(f))
    assert rows[0] == ["student", "variant", *key["answers"]]
    assert [r[1] for r in rows[1:]] == ["01", "02", "03"]
    with open(compressor_dir / "answers.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 3
    assert float(rows[1]["J_required"]) == key["variants"]["02"]["J_required"]


def test_variant_file_is_the_template_with_the_drawn_values(compressor_dir):
    template = tomllib.loads(COMPRESSOR.read_text())
    key = json.loads((compressor_dir / "answers.json").read_text())
    text = (compressor_dir / "variant_03.toml").read_text()
    assert text.startswith("# variant 3 of 3, generated from variants_compressor.toml "
                           "with seed 11\n")
    doc = tomllib.loads(text)
    assert "variants" not in doc
    drawn = key["drawn"]["03"]
    assert doc["machine"]["speed_rps"] == drawn["machine.speed_rps"] in [8, 9, 10, 11, 12]
    assert doc["links"]["2"]["mass"] == drawn["links.2.mass"]
    assert doc["cylinders"][0]["p_max"] == drawn["cylinders.0.p_max"]
    assert round(drawn["machine.delta"] * 100) / 100 == drawn["machine.delta"]
    assert 0.03 <= drawn["machine.delta"] <= 0.08
    # everything not varied is the template's
    assert doc["crank"] == template["crank"] and doc["dyads"] == template["dyads"]
    assert doc["cylinders"][1]["s"] == template["cylinders"][1]["s"]


def test_answer_key_equals_a_direct_run_of_each_variant(compressor_dir):
    key = json.loads((compressor_dir / "answers.json").read_text())
    for vid, answers in key["variants"].items():
        r = analyze(load_case(compressor_dir / f"variant_{vid}.toml"), n_points=RUN_POINTS)
        for name, value in answers.items():
            assert answer_value(r.to_document()["results"], name) == value, (vid, name)


def test_answer_key_equals_task2_of_each_variant(task2_dir):
    key = json.loads((task2_dir / "answers.json").read_text())
    assert key["kind"] == "task2" and key["n_points"] is None
    assert len(key["variants"]) == 4
    for vid, answers in key["variants"].items():
        path = task2_dir / f"variant_{vid}.toml"
        d = to_dict(solve_case(load_task2_case(path), str(path)))
        for name, value in answers.items():
            assert d[name] == value, (vid, name)
        assert (task2_dir / f"variant_{vid}.toml").read_text().splitlines()[1] == \
            "# solve with: flywheel task2 --case <this file>"


def test_the_answer_grid_is_fine_enough(compressor_dir):
    """1440 intervals (the answer key's grid) vs the default 3600: under 1e-4 relative."""
    key = json.loads((compressor_dir / "answers.json").read_text())
    for vid, answers in key["variants"].items():
        r = analyze(load_case(compressor_dir / f"variant_{vid}.toml"))   # default grid
        for name, value in answers.items():
            assert answer_value(r.to_document()["results"], name) == pytest.approx(value, rel=1e-4), (vid, name)


def test_same_seed_same_bytes_other_seed_other_variants(tmp_path, task2_dir):
    again = tmp_path / "again"
    assert invoke(TASK2, "--count", 4, "--seed", 5, "--out", again).exit_code == 0
    for p in task2_dir.iterdir():
        assert (again / p.name).read_bytes() == p.read_bytes(), p.name
    other = tmp_path / "other"
    assert invoke(TASK2, "--count", 4, "--seed", 6, "--out", other).exit_code == 0
    assert (other / "answers.json").read_bytes() != (task2_dir / "answers.json").read_bytes()


def test_variants_differ_and_stay_in_their_grids(task2_dir):
    key = json.loads((task2_dir / "answers.json").read_text())
    drawn = [tuple(d.values()) for d in key["drawn"].values()]
    assert len(set(drawn)) == len(drawn)
    for d in key["drawn"].values():
        assert d["flywheel.J"] in (1.0, 1.5, 2.0, 2.5, 3.0)
        assert 20 <= d["speed.omega0"] <= 40 and d["speed.omega0"] % 2 == 0


def test_default_seed_is_random_and_recorded(tmp_path):
    res = invoke(TASK2, "--count", 1, "--out", tmp_path / "x")
    assert res.exit_code == 0, res.output
    seed = json.loads((tmp_path / "x" / "answers.json").read_text())["seed"]
    assert f"with seed {seed}\n" in (tmp_path / "x" / "variant_01.toml").read_text()
    assert f"seed {seed}" in res.output


def write_template(tmp_path, variants: str, base: Path = TASK2, name="t.toml") -> Path:
    text = base.read_text()
    text = text[:text.index("\n[variants]\n")] + "\n[variants]\n" + variants
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return p


def test_nested_tables_and_integer_grids(tmp_path):
    t = write_template(tmp_path, 'answers = ["M_C"]\n[variants.driving]\n'
                                 'value = { min = 10, max = 12, step = 1 }\n')
    tpl = load_template(t)
    assert [v.path for v in tpl.varied] == ["driving.value"]
    assert tpl.varied[0].choices == (10, 11, 12)
    res = invoke(t, "--count", 3, "--seed", 1, "--out", tmp_path / "o")
    assert res.exit_code == 0, res.output
    key = json.loads((tmp_path / "o" / "answers.json").read_text())
    assert sorted(d["driving.value"] for d in key["drawn"].values()) == [10, 11, 12]
    # M_C = M_D·2π/(π/2) for the triangle over π/2…3π/2
    assert sorted(v["M_C"] for v in key["variants"].values()) == pytest.approx([40, 44, 48])


def test_more_variants_than_combinations_repeat_with_a_warning(tmp_path):
    t = write_template(tmp_path, '"driving.value" = { values = [10.0, 20.0] }\n'
                                 'answers = ["M_C"]\n')
    res = invoke(t, "--count", 3, "--seed", 1, "--out", tmp_path / "o")
    assert res.exit_code == 0, res.output
    assert "only 2 different variants are possible" in res.output


def test_failing_draws_are_redrawn_then_a_clear_error(tmp_path):
    # a negative J fails validation: drawn again; J = -1 only: every draw fails
    t = write_template(tmp_path, '"flywheel.J" = { values = [-1.0, 12.0] }\n'
                                 'answers = ["M_C"]\n')
    res = invoke(t, "--count", 1, "--seed", 3, "--out", tmp_path / "o")
    assert res.exit_code == 0, res.output
    assert json.loads((tmp_path / "o" / "answers.json").read_text())["drawn"]["01"] == \
        {"flywheel.J": 12.0}
    t = write_template(tmp_path, '"flywheel.J" = { values = [-1.0, -2.0] }\n'
                                 'answers = ["M_C"]\n')
    one_line_error(invoke(t, "--count", 2, "--seed", 3, "--out", tmp_path / "p"),
                   "variant 1: 50 draws in a row failed", "flywheel.J")
    assert not (tmp_path / "p").exists()


def test_a_run_case_draw_that_cannot_assemble(tmp_path):
    t = write_template(tmp_path, '"design.rod_to_crank" = { values = [0.5] }\n'
                                 'answers = ["J_required"]\n', base=COMPRESSOR)
    one_line_error(invoke(t, "--count", 1, "--seed", 3, "--out", tmp_path / "p"),
                   "draws in a row failed")


@pytest.mark.parametrize("variants, fragments", [
    ('"speed.omega" = { values = [1.0] }\nanswers = ["M_C"]\n',
     ["variants.\"speed.omega\"", "'omega' is not in [speed]", "did you mean 'omega0'"]),
    ('"speed.omega0" = { values = [1.0] }\nanswers = ["M_CC"]\n',
     ["variants.answers", "'M_CC' is not a result", "did you mean 'M_C'"]),
    ('"speed.omega0" = { values = [1.0] }\nanswers = ["segments"]\n',
     ["'segments' is not a finite number"]),
    ('"speed.omega0" = { values = [1.0] }\n', ["variants.answers: missing"]),
    ('answers = ["M_C"]\n', ["nothing to vary"]),
    ('"speed.omega0" = { min = 300, max = 100, step = 10 }\nanswers = ["M_C"]\n',
     ["max (100) is less than min (300)"]),
    ('"speed.omega0" = { min = 100, max = 300 }\nanswers = ["M_C"]\n', ["step is missing"]),
    ('"speed.omega0" = { low = 1 }\nanswers = ["M_C"]\n', ["unknown key 'low'"]),
    ('"speed.omega0" = { values = [] }\nanswers = ["M_C"]\n', ["must be a non-empty array"]),
    ('"speed" = { values = [1] }\nanswers = ["M_C"]\n', ["is a table"]),
    ('"speed.omega0" = { values = [1.0] }\nanswers = ["M_C"]\ntolerance = -1\n',
     ["variants.tolerance: must be a positive number"]),
    ('"speed.omega0" = { values = [1.0] }\nanswers = ["M_C"]\ntolerances = { delta = 0.1 }\n',
     ["tolerances.delta: not one of the answers"]),
])
def test_bad_variants_tables_fail_with_one_line(tmp_path, variants, fragments):
    t = write_template(tmp_path, variants)
    one_line_error(invoke(t, "--count", 2, "--out", tmp_path / "o"), str(t), *fragments)
    assert not (tmp_path / "o").exists()


def test_array_index_out_of_range(tmp_path):
    t = write_template(tmp_path, '"cylinders.2.p_max" = { values = [1e6] }\n'
                                 'answers = ["J_required"]\n', base=COMPRESSOR)
    one_line_error(invoke(t, "--count", 1, "--out", tmp_path / "o"),
                   "cylinders has 2 entries; index 2 is out of range (allowed: 0…1)")


def test_bad_template_files(tmp_path):
    one_line_error(invoke(tmp_path / "nope.toml", "--count", 1, "--out", tmp_path / "o"),
                   "nope.toml: no such file")
    no_table = tmp_path / "plain.toml"
    no_table.write_text((CASES / "task2_seed_triangle.toml").read_text())
    one_line_error(invoke(no_table, "--count", 1, "--out", tmp_path / "o"),
                   "no [variants] table")
    bad_case = write_template(tmp_path, '"speed.omega0" = { values = [1.0] }\n'
                                        'answers = ["M_C"]\n')
    bad_case.write_text(bad_case.read_text().replace("[flywheel]", "[flywheel]\nJJ = 1"))
    one_line_error(invoke(bad_case, "--count", 1, "--out", tmp_path / "o"), "JJ",
                   "checked as a flywheel task2 case")
    bad_run = write_template(tmp_path, '"machine.delta" = { values = [0.05] }\n'
                                       'answers = ["J_required"]\n', base=COMPRESSOR)
    bad_run.write_text(bad_run.read_text().replace("speed_rps", "speed_rpz"))
    one_line_error(invoke(bad_run, "--count", 1, "--out", tmp_path / "o"), "speed_rpz",
                   "checked as a flywheel run case")
    syntax = tmp_path / "syntax.toml"
    syntax.write_text("[variants\n")
    one_line_error(invoke(syntax, "--count", 1, "--out", tmp_path / "o"), "TOML syntax error")


def test_bad_options(tmp_path):
    one_line_error(invoke(TASK2, "--count", 0, "--out", tmp_path / "o"), "--count")
    one_line_error(invoke(TASK2, "--count", 1, "--seed", -1, "--out", tmp_path / "o"), "--seed")
    one_line_error(invoke(COMPRESSOR, "--count", 1, "--points", 10, "--out", tmp_path / "o"),
                   "--points")


def test_out_refuses_a_folder_that_is_not_a_variants_folder(tmp_path, task2_dir):
    busy = tmp_path / "busy"
    busy.mkdir()
    (busy / "thesis.tex").write_text("keep me")
    one_line_error(invoke(TASK2, "--count", 1, "--seed", 1, "--out", busy),
                   "is not an earlier variants folder of flywheel (no .flywheel-manifest.json)")
    assert (busy / "thesis.tex").read_text() == "keep me"
    # in an earlier variants folder the variants of the earlier run are replaced
    old = tmp_path / "old"
    assert invoke(TASK2, "--count", 3, "--seed", 1, "--out", old).exit_code == 0
    assert invoke(TASK2, "--count", 2, "--seed", 1, "--out", old).exit_code == 0
    assert sorted(p.name for p in old.glob("variant_*")) == ["variant_01.toml",
                                                             "variant_02.toml"]


def test_variants_names_and_texts_at_most_1000_characters():
    """[variants] keeps the case files' limit on texts (io.schema.MAX_TEXT): a varied path, an
    answer, a drawn text of 1000 characters pass the check, of 1001 are refused, the echo cut."""
    from flywheel.errors import CaseFileError
    from flywheel.teaching.variants import _check_lengths

    ok = {"a." + "p" * 998: {"values": ["t" * 1000]}, "answers": ["n" * 1000]}
    _check_lengths(ok, "t.toml")
    for table, where in (({"a." + "p" * 999: {"values": [1]}}, 'variants."a.ppp'),
                         ({"s": {"values": [1, "t" * 1001]}}, "variants.s.values[1]: "),
                         ({"answers": ["M_C", "n" * 1001]}, "variants.answers[1]: ")):
        with pytest.raises(CaseFileError) as e:
            _check_lengths(table, "t.toml")
        line = str(e.value)
        assert line.startswith(f"t.toml: {where}") and "1001 characters" in line
        assert "at most 1000" in line and len(line) < 300


def test_the_russian_table_of_variants_names_answers_by_symbols_and_tells_keys_apart(tmp_path):
    """`variants --lang ru` lists each variant's answers by the task sheet's symbols (M_С, ω_max,
    J_пр; it printed the keys) and each to the digits its tolerance tells apart: task2's ω_max
    and ω_min, within 0.001 %, as «250,0103» and «249,9926» (both had read «250»)."""
    import re

    res = CliRunner().invoke(app, ["variants", str(CASES / "variants_task2.toml"), "--count", "2",
                                   "--seed", "4", "--out", str(tmp_path / "v"), "--lang", "ru"],
                             env={"COLUMNS": "160"})
    assert res.exit_code == 0, res.output
    cells = [c.strip() for ln in res.stdout.splitlines() if ln.startswith("│")
             for c in ln.split("│")[1:-1]]
    answers = [c for c in cells if re.match(r"^(M_С|ω_max|ω_min|δ|ΔT_нб|J_треб) = ", c)]
    assert len(answers) == 12 and not any("omega_m" in c or "J_required" in c for c in cells)
    for c in answers:
        if c.startswith("ω_m"):
            assert re.fullmatch(r"ω_m(ax|in) = \d+,\d{3,}", c), c


def test_the_terminal_words_the_drawn_values_in_russian():
    """`variants --lang ru` had printed what it drew by the case file's paths
    («machine.speed_rpm = 40»); it now words them as the task sheet does, with their units; in
    English the path stays (what the teacher edits in the template)."""
    from types import SimpleNamespace

    from flywheel.render.grading import drawn_line

    shaper = load_template(CASES / "variants_shaper.toml")
    v = SimpleNamespace(drawn={"machine.speed_rpm": 40.0, "links.5.mass": 25.0,
                               "forces.0.magnitude": 3500.0, "flywheel.speed_ratio": 25.0})
    assert drawn_line(shaper, v, "machine.speed_rpm", "ru") == \
        "частота вращения кривошипа n₁ = 40 об/мин"
    assert drawn_line(shaper, v, "links.5.mass", "ru") == "масса звена 5 m_5 = 25 кг"
    assert drawn_line(shaper, v, "forces.0.magnitude", "ru").endswith("= 3500 Н")
    assert drawn_line(shaper, v, "flywheel.speed_ratio", "ru") == \
        "передаточное отношение к валу маховика i = 25"
    assert drawn_line(shaper, v, "machine.speed_rpm") == "machine.speed_rpm = 40"
    task2 = load_template(TASK2)
    v = SimpleNamespace(drawn={"resistance.from_deg": 120.0, "flywheel.J": 12.0})
    assert drawn_line(task2, v, "resistance.from_deg", "ru").endswith(" = 120°")
    assert drawn_line(task2, v, "flywheel.J", "ru") == \
        "приведённый момент инерции J_пр = 12 кг·м²"
