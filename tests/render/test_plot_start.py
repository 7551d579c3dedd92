"""render/plot_start.py and render/plot_wait.py: a run's first plot worker started with the
process — which words start it, that it draws the same bytes, and that a run that draws
nothing (bad input, no figures) ends it and leaves nothing running."""
from __future__ import annotations

import signal
import sys
from pathlib import Path

import pytest

from flywheel.render import plot_start, plot_wait

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.mark.parametrize("argv, started", [
    (["run", "c.toml"], True),
    (["-q", "run", "c.toml", "--plots", "record"], True),
    (["--debug", "run", "c.toml", "--lang", "ru", "--json"], True),
    (["run", "c.toml", "--no-plots"], False),
    (["run", "c.toml", "--plots", "none"], False),
    (["run", "c.toml", "--plots=none"], False),
    (["run", "--help"], False),
    (["run", "c.toml", "-h"], False),
    (["task2", "--profile", "triangle"], False),
    (["check", "c.toml"], False),
    (["--version"], False),
    ([], False),
])
def test_the_words_of_a_run_that_draws_start_the_worker(argv, started, monkeypatch):
    monkeypatch.setattr(plot_start.os, "cpu_count", lambda: 2)
    monkeypatch.setattr(plot_start.sys, "platform", "linux")
    assert plot_start.wanted(argv) is started


def test_one_processor_or_no_fork_starts_none(monkeypatch):
    monkeypatch.setattr(plot_start.os, "cpu_count", lambda: 1)
    assert not plot_start.wanted(["run", "c.toml"])
    monkeypatch.setattr(plot_start.os, "cpu_count", lambda: 8)
    monkeypatch.setattr(plot_start.sys, "platform", "win32")
    assert not plot_start.wanted(["run", "c.toml"])


@pytest.fixture
def started(monkeypatch):
    """Every worker :func:`plot_start.start` makes in the test, released at its end."""
    made = []

    class Recorded(plot_start.Early):
        def __init__(self, target):
            super().__init__(target)
            made.append(self)

    monkeypatch.setattr(plot_start, "Early", Recorded)
    monkeypatch.setattr(plot_start, "wanted", lambda argv: argv[:1] == ["run"])
    yield made
    plot_start.release()
    for early in made:
        if early.process.is_alive():
            early.process.terminate()
        early.process.join()


def test_a_worker_nobody_claims_is_ended(started):
    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)
    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)     # one at a time
    assert len(started) == 1 and started[0].process.is_alive()
    plot_start.release()
    assert plot_start.claim() is None
    assert not started[0].process.is_alive()
    assert started[0].process.exitcode in (0, -signal.SIGTERM)


def test_results_that_cannot_be_pickled_are_drawn_the_old_way(started):
    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)
    early = plot_start.claim()
    assert early.send((lambda: 0,)) is False       # PlotJob then forks its own workers
    early.end()
    assert not early.process.is_alive()


def test_a_worker_whose_pipe_closes_without_a_job_ends_quietly(started, capfd):
    """The run ends before it has figures (its pipe closed): the worker, its import done,
    reads the end of the pipe and ends with 0, printing nothing."""
    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)
    early = plot_start.claim()
    early.writer.close()
    early.process.join(60)
    assert early.process.exitcode == 0
    assert capfd.readouterr() == ("", "")


def test_a_bad_case_ends_the_started_worker(started, tmp_path, capsys, monkeypatch):
    """The console entry point with a case file that does not load: one line, exit 2, the
    worker started for it ended (nothing left running)."""
    from flywheel import cli

    bad = tmp_path / "bad.toml"
    bad.write_text("[crank]\nlength = 'long'\n", encoding="utf-8")
    handlers = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    monkeypatch.setattr(sys, "argv", ["flywheel", "run", str(bad), "--out", str(tmp_path / "o")])
    try:
        with pytest.raises(SystemExit) as stop:
            cli.main()
    finally:
        for s, h in handlers.items():
            signal.signal(s, h)
    assert stop.value.code == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert len(started) == 1 and not started[0].process.is_alive()
    assert plot_start.claim() is None


def test_the_started_worker_draws_the_bytes_drawn_in_process(started, tmp_path):
    """A worker started before the results exist, handed them through its pipe, with the
    worker it forks: the files drawn in this process, byte for byte."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render import plots

    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)
    results = analyze(load_case(CASES / "press.toml"), n_points=360)
    with plots.start_plots(results, tmp_path / "two", jobs=2, which="record") as job:
        assert job.children == [started[0].process]           # the started one, handed the job
        two = job.wait()
    one = plots.write_plots(results, tmp_path / "one", jobs=1, which="record")
    assert [p.name for p in two] == [p.name for p in one]
    for a, b in zip(two, one):
        assert a.read_bytes() == b.read_bytes(), a.name


def test_a_fork_that_fails_starts_nothing_and_the_run_goes_on(monkeypatch):
    """No process to spare when the run starts (fork: EAGAIN): no worker, no error — the run
    forks its workers later as it did before, or draws in its own process."""
    def no_fork(self, target):
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(plot_start.Early, "__init__", no_fork)
    monkeypatch.setattr(plot_start, "wanted", lambda argv: True)
    plot_start.start(["run", "c.toml"], plot_wait.wait_and_draw)
    assert plot_start.claim() is None
