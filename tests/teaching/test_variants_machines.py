"""The `flywheel variants` templates of the engine (720° cycle, an indicator diagram in four
strokes) and the shaper (six-bar, cutting force on the working stroke): five variants with a
seed; every variant file runs with `flywheel run`, whose results are the key's answers (to the
last digit on the key's grid, to 1e-4 on run's default grid); the key itself, handed in as a
sheet, scores full marks (issue 13 item 7)."""
import csv
import json
import math
import tomllib
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.teaching.variants import RUN_POINTS, answer_value

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
TEMPLATES = {"engine": ("variants_engine.toml", "engine_4stroke.toml"),
             "shaper": ("variants_shaper.toml", "shaper.toml")}


@pytest.fixture(scope="module", params=sorted(TEMPLATES))
def generated(request, tmp_path_factory):
    template, case = TEMPLATES[request.param]
    out = tmp_path_factory.mktemp(request.param) / "v"
    res = runner.invoke(app, ["variants", str(CASES / template), "--count", "5", "--seed", "7",
                              "--out", str(out)])
    assert res.exit_code == 0, res.output
    return request.param, out, json.loads((out / "answers.json").read_text())


def _run(path: Path, tmp: Path, *options) -> dict:
    res = runner.invoke(app, ["run", str(path), "--no-plots", "--json", "--out", str(tmp),
                              *options])
    assert res.exit_code == 0, res.output
    return json.loads(res.stdout)


def test_the_template_is_the_bundled_case_plus_variants(generated):
    """The case part of each template is the bundled case, unchanged, its title and source in
    both languages too (a Russian task sheet shows the Russian title)."""
    name, _, _ = generated
    template, case = TEMPLATES[name]
    t = tomllib.loads((CASES / template).read_text(encoding="utf-8"))
    c = tomllib.loads((CASES / case).read_text(encoding="utf-8"))
    assert set(t.pop("variants")) >= {"answers", "tolerance"}
    assert t == c


def test_five_distinct_variants_each_with_every_answer(generated):
    name, out, key = generated
    assert key["kind"] == "run" and key["seed"] == 7 and key["count"] == 5
    assert sorted(key["variants"]) == ["01", "02", "03", "04", "05"]
    drawn = [json.dumps(d, sort_keys=True) for d in key["drawn"].values()]
    assert len(set(drawn)) == 5
    for vid, answers in key["variants"].items():
        assert list(answers) == key["answers"]
        assert all(math.isfinite(v) for v in answers.values()), (vid, answers)
    if name == "engine":
        assert "balancing_moment" in key["answers"] and "J_flywheel" in key["answers"]


def test_every_variant_runs_and_gives_the_key(generated, tmp_path):
    """`flywheel run variant --points 1440` gives the key's answers to the last digit; the
    default grid (3600) within 1e-4; no variant warns (a variant handed out should not)."""
    name, out, key = generated
    for vid, answers in key["variants"].items():
        path = out / f"variant_{vid}.toml"
        doc = _run(path, tmp_path / f"k{vid}", "--points", str(RUN_POINTS))
        assert doc["warnings"] == [], (vid, doc["warnings"])
        assert doc["results"]["cycle_deg"] == (720 if name == "engine" else 360)
        for a, v in answers.items():
            assert answer_value(doc["results"], a) == v, (vid, a)
        fine = _run(path, tmp_path / f"d{vid}")["results"]
        for a, v in answers.items():
            assert answer_value(fine, a) == pytest.approx(v, rel=1e-4), (vid, a)


def test_the_drawn_values_are_in_the_variant_files(generated):
    _, out, key = generated
    for vid, drawn in key["drawn"].items():
        doc = tomllib.loads((out / f"variant_{vid}.toml").read_text(encoding="utf-8"))
        for path, value in drawn.items():
            assert answer_value(doc, path) == value, (vid, path)


def test_the_engine_key_balances_the_gas_work(generated):
    """An engine's answers agree with each other: the resistance moment times the 720° cycle
    is the resistance's work, M_C·4π = A_C."""
    name, _, key = generated
    if name != "engine":
        pytest.skip("engine only")
    for vid, a in key["variants"].items():
        assert a["balancing_moment"] * 4 * math.pi == pytest.approx(a["cycle_work_resistance"],
                                                                    rel=1e-9), vid


def test_grading_the_key_itself_scores_full_marks(generated, tmp_path):
    _, out, key = generated
    sheet = tmp_path / "filled.csv"
    with open(sheet, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", *key["answers"]])
        for i, (vid, ans) in enumerate(key["variants"].items()):
            w.writerow([f"student {i + 1}", vid, *(repr(ans[a]) for a in key["answers"])])
    res = runner.invoke(app, ["grade", str(out / "answers.json"), str(sheet), "--json"])
    assert res.exit_code == 0, res.output
    report = json.loads(res.stdout)
    assert report["summary"]["graded"] == 5
    assert report["summary"]["full_marks"] == 5
    assert report["problems"] == []
