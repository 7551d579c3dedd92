"""Helpers of the tests of issue 27 (test_chain, test_carried, test_mistakes, …): variants
made by the CLI, sheets written from a key, graded by the CLI, and the textbook's formulas."""
import csv
import json
import math
import tomllib
from pathlib import Path

from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def make(tmp_path_factory, template, count=3, seed=11):
    out = tmp_path_factory.mktemp("chain") / "v"
    res = runner.invoke(app, ["variants", str(CASES / template), "--count", str(count),
                              "--seed", str(seed), "--out", str(out)])
    assert res.exit_code == 0, res.output
    return out


def key_of(folder):
    return json.loads((folder / "answers.json").read_text(encoding="utf-8"))


def data_of(folder, vid):
    return tomllib.loads((folder / f"variant_{vid}.toml").read_text(encoding="utf-8"))


def textbook(data, dT):
    """J_I, J_доп and the steel disk's D from ΔT_нб by the textbook (seed 000 §4)."""
    m = data["machine"]
    n = m["speed_rps"] if "speed_rps" in m else m["speed_rpm"] / 60
    omega = 2 * math.pi * n
    J_I = dT / (omega ** 2 * m["delta"])
    J_fly = J_I - sum(m["first_group"].values())
    D = (32 * J_fly / (math.pi * 7800 * data.get("flywheel", {}).get("width_ratio", 0.2))) ** 0.2
    return {"J_required": J_I, "J_flywheel": J_fly, "flywheel_disk.D": D}


def write_sheet(path, key, rows):
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", *key["answers"]])
        for name, vid, ans in rows:
            w.writerow([name, vid, *(repr(ans[a]) for a in key["answers"])])
    return path


def graded(key_path, sheet, *options):
    res = runner.invoke(app, ["grade", str(key_path), str(sheet), "--json", *options])
    assert res.exit_code == 0, res.output
    return {s["student"]: s for s in json.loads(res.stdout)["students"]}


def verdicts(student):
    return {a["answer"]: a["verdict"] for a in student["answers"]}
