"""cli/outputs.py, the one output path, and `run --plots`: which figures are written, the order
the plot workers take them in, the progress they report, nothing of the bar on a pipe."""
from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.render import plots

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


@pytest.fixture(scope="module")
def press():
    """A tabulated case: the fewest figures (no kinematics drawn)."""
    return analyze(load_case(CASES / "press.toml"), n_points=360)


def test_a_figures_kind_is_its_file_name_without_cylinder_or_angle():
    assert plots._stem_of("plan_velocity_120.png") == "plan_velocity"
    assert plots._stem_of("plan_velocity_22_5.png") == "plan_velocity"
    assert plots._stem_of("indicator_HP.png") == "indicator"
    assert plots._stem_of("positions.png") == "positions"
    assert plots._stem_of("plan_positions.png") == "plan_positions"
    assert plots._stem_of("omega.png") == "omega"


def test_record_is_the_all_set_less_the_figures_beyond_the_record(press):
    every = plots.chosen(press, "en", "all")
    record = plots.chosen(press, "en", "record")
    assert plots.chosen(press, "en", "none") == []
    assert record == [n for n in every if n in record]            # same order, a subset
    beyond = set(every) - set(record)
    assert "J_II.png" in record and "energy_mass.png" in record and "omega.png" in record
    assert "time_law.png" in beyond and "epsilon.png" in beyond
    with pytest.raises(ValueError):
        plots.chosen(press, "en", "some")


def test_the_workers_take_the_costliest_first_and_count_every_figure(press, tmp_path):
    seen = []
    with plots.start_plots(press, tmp_path, jobs=2, which="record") as job:
        assert [n for n in job.names] == plots.chosen(press, "en", "record")
        paths = job.wait(lambda done, total: seen.append((done, total)))
    total = len(job.names)
    assert [p.name for p in paths] == job.names and all(p.is_file() for p in paths)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(job.names)
    assert seen[-1] == (total, total)
    assert all(t == total for _, t in seen)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)      # never backwards
    order = plots.PlotJob(press, tmp_path / "x", "en", job.names, 1, "png", 120)._draw_here[3]
    every = [n for n, _ in plots.all_figures(press, "en")]
    assert every[order[0]] == "energy_mass.png"                   # the costliest first


def test_two_workers_write_the_bytes_drawn_in_process(press, tmp_path):
    """The first worker imports matplotlib and forks the second: the files are those drawn in
    this process, byte for byte, rerun included."""
    two = plots.write_plots(press, tmp_path / "two", jobs=2, which="record")
    again = plots.write_plots(press, tmp_path / "again", jobs=2, which="record")
    one = plots.write_plots(press, tmp_path / "one", jobs=1, which="record")
    assert [p.name for p in two] == [p.name for p in one] == [p.name for p in again]
    for a, b, c in zip(two, again, one):
        assert a.read_bytes() == b.read_bytes() == c.read_bytes(), a.name


def test_a_figure_that_fails_in_a_worker_fails_the_plots(press, tmp_path, monkeypatch):
    """A figure raising in either worker (the first, or the one it forked): the wait raises,
    every worker is gone."""
    own = plots._save_some

    def failing(results, folder, lang, indices, *args):
        if plots.all_figures(results, lang)[indices[0]][0] == "omega.png":
            raise ValueError("a figure failed")
        return own(results, folder, lang, indices, *args)

    monkeypatch.setattr(plots, "_save_some", failing)
    with plots.start_plots(press, tmp_path, jobs=2, which="record") as job:
        with pytest.raises(RuntimeError, match="a plotting process failed"):
            job.wait()
    assert all(not c.is_alive() for c in job.children)


def test_drawn_in_process_the_progress_is_counted_too(press, tmp_path):
    seen = []
    paths = plots.write_plots(press, tmp_path, jobs=1, which="record",
                              progress=lambda d, t: seen.append(d))
    assert seen == list(range(len(paths) + 1))


@pytest.mark.parametrize("choice, figures", [("none", False), ("record", True)])
def test_run_plots_choice(tmp_path, choice, figures, press):
    out = tmp_path / "o"
    res = runner.invoke(app, ["run", str(CASES / "press.toml"), "--points", "360",
                              "--plots", choice, "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert (out / "plots").is_dir() == figures
    if figures:
        assert sorted(p.name for p in (out / "plots").iterdir()) == \
            sorted(plots.chosen(press, "en", "record"))
        assert "plots/*.png" in res.stdout
    else:
        assert "plots/" not in res.stdout
    assert "figures" not in res.stderr and "━" not in res.stderr   # no bar on a pipe


def test_no_plots_is_plots_none(tmp_path):
    a, b = tmp_path / "a", tmp_path / "b"
    for out, opt in ((a, ["--no-plots"]), (b, ["--plots", "none"])):
        res = runner.invoke(app, ["run", str(CASES / "press.toml"), "--points", "360", *opt,
                                  "--out", str(out)])
        assert res.exit_code == 0, res.output
    files = sorted(p.name for p in a.iterdir())
    assert files == sorted(p.name for p in b.iterdir()) and "plots" not in files
    assert (a / "report.md").read_bytes() == (b / "report.md").read_bytes()


def test_the_written_line_lists_what_run_writes():
    from flywheel.cli.outputs import RunOutputs

    assert RunOutputs().names() == ["summary.json", "table.csv", "positions.csv", "forces.csv",
                                    "forces_positions.csv", "report.md", "report.html",
                                    "plots/*.png"]
    assert RunOutputs(plots="none", formats=("md", "md", "pdf"), animate=True).names()[-3:] == \
        ["report.md", "report.pdf", "mechanism.gif"]
    assert RunOutputs(figure_format="svg").names()[-2:] == ["plots/*.png", "plots/*.svg"]
