"""`flywheel run` through the CLI: outputs, the results contract (design.md §5), bad input."""
from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import parse_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def run(*args):
    return runner.invoke(app, [str(a) for a in args])


def test_run_writes_every_output(tmp_path):
    out = tmp_path / "out"
    res = run("run", CASES / "compressor.toml", "--out", out, "--no-plots", "--points", "720")
    assert res.exit_code == 0, res.output
    assert {p.name for p in out.iterdir()} == {"summary.json", "table.csv", "positions.csv", "report.md",
                                              "report.html", "forces.csv", "forces_positions.csv",
                                              ".flywheel-manifest.json"}
    report = (out / "report.md").read_text(encoding="utf-8")
    assert report.startswith("# Dynamic analysis: Two-stage V-type air compressor")
    assert "ΔT_max = " in report and "ΔT_нб" not in report and "## 5. Flywheel" in report and "## 6. True velocities" in report
    assert "J_I" in res.output and "written" in res.output
    header = (out / "table.csv").read_text(encoding="utf-8").splitlines()[0]
    assert header.startswith("phi_deg [deg],") and "J_II [kg·m²]" in header and "omega [rad/s]" in header
    rows = (out / "positions.csv").read_text(encoding="utf-8").splitlines()
    labels = [r.split(",")[0] for r in rows[1:]]
    # 12 positions every 30°; the dead centres fall on 0, 90, 180, 270° here and share their rows
    assert labels[:3] == ["0° = 3 outer d.c.", "30°", "60°"]
    assert labels[3] == "90° = 5 outer d.c."
    assert len(labels) == 12
    assert not list(tmp_path.glob(".out.tmp-*"))


@pytest.mark.parametrize("case", ["compressor.toml", "press.toml"])
def test_russian_summary_and_report_are_russian(tmp_path, case):
    """--lang ru: units, row labels, the standard positions and the closing line in Russian;
    the numbers the same as in English."""
    res = run("run", CASES / case, "--out", tmp_path / "o", "--no-plots", "--points", "360",
              "--lang", "ru", "--at", "75")
    assert res.exit_code == 0, res.output
    report = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    summary = res.stdout.split("записано:")[0]
    assert "записано:" in res.stdout and "written" not in res.stdout
    for text in (summary, report):
        assert "рад/с" in text and "кг·м²" in text and "Дж" in text
        for english in ("rad/s", "kg·m²", "N·m", " d.c.", "[deg]", "M_PRD", "J_PRI", "Merzalov",
                        "steel", "gravity ", "gas ", "at 2", "flywheel", "rim"):
            assert english not in re.split(r"## \d+\. Предупреждения", text.split(
                "предупреждение:")[0])[0], english
    assert "ω_ср" in summary and "M_Д" in report and "ΔT_нб" in report
    en = run("run", CASES / case, "--out", tmp_path / "e", "--no-plots", "--points", "360", "--at", "75")
    assert en.exit_code == 0

    def numbers(md: str, pattern: str) -> list[str]:
        """The numbers in the tables (the first cell of a row, a label, left out)."""
        return [c.strip() for ln in md.splitlines() if ln.startswith("| ")
                for c in ln.split("|")[2:] if re.fullmatch(pattern, c.strip())]

    # the same numbers in Russian typography (render/numbers.py): a decimal comma, a true
    # minus, narrow spaces, four significant digits (the English text has five or six)
    ru = [float(x.replace("\u2212", "-").replace("\u202f", "").replace(",", "."))
          for x in numbers(report, r"[\u2212]?[\d\u202f]+(,\d+)?")]
    en = [float(x) for x in numbers((tmp_path / "e" / "report.md").read_text(encoding="utf-8"),
                                    r"-?[\d.e+-]+")]
    assert len(ru) == len(en) > 100
    assert all(abs(r - e) <= 5e-4 * abs(e) + 1e-9 for r, e in zip(ru, en))


def test_json_contract(tmp_path):
    res = run("run", CASES / "compressor.toml", "--out", tmp_path / "o", "--no-plots", "--json",
              "--at", "120", "--at", "75")
    assert res.exit_code == 0, res.output
    doc = json.loads(res.stdout)
    r = doc["results"]
    for key in ("crank_length", "omega_mean", "cycle_work_resistance", "driving_moment", "delta_T_max",
                "J_II_mean", "J_required", "J_required_exact", "J_flywheel", "delta_achieved"):
        assert isinstance(r[key], float), key
    assert set(r["flywheel_disk"]) >= {"D", "b", "mass"}
    assert set(r["flywheel_rim"]) >= {"D", "D_inner", "b", "mass"}
    assert [a["phi_deg"] for a in r["at"]] == [120.0, 75.0]
    a75 = r["at"][1]
    assert set(a75["points"]) == {"O", "A", "B", "C", "S2", "S4"}
    assert set(a75["links"]) == {"1", "2", "3", "4", "5"}
    assert set(a75["points"]["B"]) >= {"x", "y", "v_q", "a_q", "v", "a"}
    assert set(a75["links"]["2"]) >= {"omega_q", "epsilon_q", "omega", "epsilon"}
    assert a75["points"]["B"]["v_q"] == pytest.approx(0.103, abs=5e-4)   # seed: V_qB(75°)
    assert a75["links"]["2"]["epsilon_q"] == pytest.approx(-0.248, abs=5e-4)
    assert json.loads((tmp_path / "o" / "summary.json").read_text(encoding="utf-8")) == doc


def test_same_input_gives_identical_files(tmp_path):
    for name in ("a", "b"):
        assert run("run", CASES / "compressor.toml", "--out", tmp_path / name, "--no-plots",
                   "--points", "360").exit_code == 0
    for f in ("summary.json", "table.csv", "positions.csv", "report.md"):
        assert (tmp_path / "a" / f).read_bytes() == (tmp_path / "b" / f).read_bytes()


def test_rerun_replaces_its_own_files_only(tmp_path):
    out = tmp_path / "o"
    assert run("run", CASES / "compressor.toml", "--out", out, "--points", "360").exit_code == 0
    assert (out / "plots").is_dir()
    (out / "notes.txt").write_text("mine")          # the user's file in an output folder: kept
    res = run("run", CASES / "compressor.toml", "--out", out, "--no-plots", "--points", "360")
    assert res.exit_code == 0
    assert (out / "notes.txt").read_text() == "mine"
    assert not (out / "plots").exists()             # the earlier run's plots: removed, and said
    assert "plots/" in res.stderr and "removed" in res.stderr


def test_out_never_deletes_a_folder_it_did_not_write(tmp_path):
    thesis = tmp_path / "thesis"
    thesis.mkdir()
    (thesis / "notes.txt").write_text("precious")
    _one_error_line(run("run", CASES / "compressor.toml", "--out", thesis, "--no-plots"),
                    f"--out {thesis}: the folder exists, is not empty and is not an earlier "
                    "output folder of flywheel (no .flywheel-manifest.json)")
    assert (thesis / "notes.txt").read_text() == "precious"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["thesis"]   # no temporary left
    empty = tmp_path / "empty"
    empty.mkdir()
    assert run("run", CASES / "compressor.toml", "--out", empty, "--no-plots", "--points", "360").exit_code == 0


def _one_error_line(res, *fragments):
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), res.stderr
    for f in fragments:
        assert f in lines[0], lines[0]
    assert "Traceback" not in res.output


def test_output_folder_that_cannot_be_written(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    _one_error_line(run("run", CASES / "compressor.toml", "--out", blocker, "--no-plots"), "--out", "not a folder")
    _one_error_line(run("run", CASES / "compressor.toml", "--out", blocker / "sub", "--no-plots"),
                    f"--out {blocker / 'sub'}: {blocker} is a file, not a folder")
    _one_error_line(run("run", CASES / "compressor.toml", "--out", "/proc/flywheel-out", "--no-plots"),
                    "--out /proc/flywheel-out: cannot be written")


def test_bad_options(tmp_path):
    _one_error_line(run("run", CASES / "compressor.toml", "--points", "3", "--out", tmp_path / "o"),
                    "--points: 3 is out of range (allowed: 36 … 100000")
    _one_error_line(run("run", CASES / "compressor.toml", "--points", "20000000", "--out", tmp_path / "o"),
                    "--points: 20000000 is out of range")       # was killed for memory
    _one_error_line(run("run", CASES / "compressor.toml", "--lang", "de", "--out", tmp_path / "o"), "--lang")
    assert not (tmp_path / "o").exists()


def test_wrong_balance_leaves_nothing_behind(tmp_path):
    text = (CASES / "compressor.toml").read_text(encoding="utf-8").replace(
        'balance   = "driving"', 'balance   = "resistance"')
    bad = tmp_path / "engine.toml"
    bad.write_text(text, encoding="utf-8")
    _one_error_line(run("run", bad, "--out", tmp_path / "o", "--no-plots"), "balance")
    assert not (tmp_path / "o").exists()


def test_bad_case_file(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text((CASES / "compressor.toml").read_text(encoding="utf-8").replace(
        "s              = [0, 0.1, 0.2", "s              = [0.05, 0.1, 0.2", 1), encoding="utf-8")
    _one_error_line(run("run", bad, "--out", tmp_path / "o"), str(bad), "cylinders[0]", "span")


def test_technological_force_and_couple():
    """A press-like slider with a constant 1 kN resistance over the second half of its travel away
    from the outer dead centre, and a constant couple on the rod: A_C = −F·stroke/2 (the couple on
    a link that swings back does no net work)."""
    data = {
        "machine": {"speed_rpm": 120.0, "delta": 0.1, "gravity": [0.0, 0.0]},
        "crank": {"length": 0.1},
        "dyads": [{"kind": "RRP", "from": "A", "joint": "B", "rod": "2", "rod_length": 0.5,
                   "slider": "3", "guide": {"angle_deg": 0.0}}],
        "forces": [{"name": "punch", "slider": "3", "magnitude": 1000.0, "s_range": [0.5, 1.0],
                    "stroke": "away"}],
        "couples": [{"name": "friction", "link": "2", "moment": 5.0}],
    }
    r = analyze(parse_case(data), n_points=360)
    # the force's work is integrated exactly (−F·travel in each interval) and the angle where it
    # switches on is a grid node, so even a coarse grid gives the closed form (the trapezoid rule
    # on M = −F·|v_q| was first-order: 2.5·10⁻⁴ relative on 7200 intervals)
    assert r.scalars.cycle_work_resistance == pytest.approx(-1000 * 0.2 / 2, rel=1e-8)  # the
    # dead centres (interval ends) are found numerically: 6·10⁻¹⁰ is left
    # s = 0.5 of the stroke away from the outer dead centre (φ = 0): x = l + r at φ = 0, so
    # x(φ) = r·cos φ + √(l² − r²·sin² φ) = l: cos φ = r/(2l)... solved here by bisection
    from scipy.optimize import brentq

    phi_on = brentq(lambda a: 0.1 * math.cos(a) + math.sqrt(0.25 - 0.01 * math.sin(a) ** 2) - 0.5,
                    0.1, math.pi - 0.1)
    assert np.min(np.abs(r.phi - phi_on)) < 1e-12       # the switch-on angle is a node
    F = r.columns["F_punch"].values
    assert F.max() == 1000.0 and F.min() == 0.0
    # at 120° the slider moves away, past half its travel: the punch acts, and summary.json says so
    assert r.at[0].phi_deg == 120.0 and r.at[0].forces == {"punch": 1000.0}


def test_python_dash_m(tmp_path):
    res = subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                          "--json", "--no-plots", "--points", "360", "--out", str(tmp_path / "o")],
                         capture_output=True, text=True, check=True)
    assert json.loads(res.stdout)["results"]["omega_mean"] == pytest.approx(2 * math.pi * 10)


#: modules `run --no-plots` piped has no use for: the figures and sheets' renderers (their
#: options are checked against render/choices.py), rich (no bar can show on a pipe),
#: numpy.ma (np.unique's import) and the ГОСТ PDF/DOCX writer (no --report pdf/docx): each
#: costs the whole process time (benchmarks/README.md)
UNUSED_BY_NO_PLOTS = ("matplotlib", "rich.progress", "rich.console", "numpy.ma",
                      "flywheel.render.drawings", "flywheel.render.report_frame",
                      "flywheel.render.report_gost",
                      "flywheel.render.plots", "flywheel.render.figure", "scipy")


def test_run_no_plots_imports_nothing_it_does_not_use(tmp_path):
    res = subprocess.run([sys.executable, "-X", "importtime", "-m", "flywheel", "run",
                          str(CASES / "slotted_link.toml"), "--json", "--no-plots", "--points",
                          "360", "--out", str(tmp_path / "o")],
                         capture_output=True, text=True, check=True)
    imported = {line.rsplit("|", 1)[-1].strip() for line in res.stderr.splitlines()
                if line.startswith("import time:")}
    assert "flywheel.dynamics.pipeline" in imported          # the run was timed at all
    assert sorted(m for m in imported if m.split(".")[0] in ("matplotlib", "scipy")
                  or m in UNUSED_BY_NO_PLOTS) == []


def test_conservative_loads_need_no_balancing_moment():
    """Gravity alone does no work over a cycle: the balancing moment is exactly 0, with a
    warning, rather than a round-off sign deciding between 'driving' and an error."""
    from flywheel.cases.run import load_case

    r = analyze(load_case(CASES / "fourbar.toml"), n_points=720)
    assert r.scalars.balancing_moment == 0.0
    assert any("no net work" in w for w in r.warnings)
    assert r.scalars.delta_T_max > 0
