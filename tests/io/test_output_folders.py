"""Output folders: written whole or not at all, and nothing of the user's is ever lost
(flywheel.io.output; issue 17: the manifest, user files, edited files, killed runs)."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from flywheel.errors import InputError
from flywheel.io.output import MANIFEST, remove_stale_temporaries, write_folder

CASES = Path(__file__).resolve().parents[2] / "cases"


def _builder(files: dict[str, str]):
    def build(folder: Path) -> None:
        for rel, text in files.items():
            p = folder / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text, encoding="utf-8")
    return build


RUN1 = {"summary.json": '{"results": {}, "units": "SI"}\n', "table.csv": "a\n1\n",
        "plots/J_II.png": "png1", "plots/omega.png": "png2"}
RUN2 = {"summary.json": '{"results": {"x": 1}, "units": "SI"}\n', "table.csv": "a\n2\n"}


def test_new_folder_gets_a_manifest_of_its_files(tmp_path):
    out = write_folder(tmp_path / "o", _builder(RUN1), "summary.json")
    doc = json.loads((out / MANIFEST).read_text())
    assert doc["written_by"] == "flywheel" and doc["kind"] == "output"
    assert sorted(doc["files"]) == sorted(RUN1)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]      # no temporary left


def test_rerun_replaces_only_its_own_files_and_keeps_the_users(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    (out / "notes.txt").write_text("my notes")                     # the user's own file
    (out / "plots" / "sketch.png").write_text("mine")              # … even among the plots
    notes: list[str] = []
    write_folder(out, _builder(RUN2), "summary.json", notes=notes)
    assert (out / "notes.txt").read_text() == "my notes"
    assert (out / "plots" / "sketch.png").read_text() == "mine"
    assert (out / "table.csv").read_text() == "a\n2\n"
    assert not (out / "plots" / "J_II.png").exists()               # stale output: removed …
    assert any("removed 2 file(s)" in n and "plots/J_II.png" in n for n in notes)   # … and said
    assert sorted(json.loads((out / MANIFEST).read_text())["files"]) == sorted(RUN2)


def test_a_file_the_user_edited_is_kept_aside(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    (out / "table.csv").write_text("edited by hand")
    notes: list[str] = []
    write_folder(out, _builder(RUN1), "summary.json", notes=notes)
    assert (out / "table.csv.edited").read_text() == "edited by hand"
    assert (out / "table.csv").read_text() == RUN1["table.csv"]
    assert any("table.csv → table.csv.edited" in n for n in notes)
    (out / "table.csv").write_text("edited again")
    write_folder(out, _builder(RUN1), "summary.json")
    assert (out / "table.csv.edited-2").read_text() == "edited again"


def test_a_file_named_like_an_output_does_not_make_a_folder_ours(tmp_path):
    p = tmp_path / "p"
    p.mkdir()
    (p / "summary.json").write_text("{}")
    (p / "thesis.docx").write_text("x")
    with pytest.raises(InputError, match="not an earlier output folder"):
        write_folder(p, _builder(RUN1), "summary.json")
    assert (p / "thesis.docx").read_text() == "x" and (p / "summary.json").read_text() == "{}"
    # nor does a forged manifest of another kind
    (p / MANIFEST).write_text(json.dumps({"written_by": "flywheel", "kind": "variants",
                                          "files": {"thesis.docx": "0"}}))
    with pytest.raises(InputError):
        write_folder(p, _builder(RUN1), "summary.json")
    assert (p / "thesis.docx").read_text() == "x"


def test_a_manifest_cannot_reach_outside_its_folder(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    victim = tmp_path / "victim.txt"
    victim.write_text("keep")
    doc = json.loads((out / MANIFEST).read_text())
    doc["files"]["../victim.txt"] = doc["files"]["table.csv"]
    (out / MANIFEST).write_text(json.dumps(doc))
    write_folder(out, _builder(RUN2), "summary.json")
    assert victim.read_text() == "keep"


def test_a_folder_without_its_manifest_is_the_users_whatever_it_holds(tmp_path):
    """A summary.json with "results" and "units" does not make a folder flywheel's (issue 23):
    without a manifest the folder is refused in one line, every file as it was."""
    old = tmp_path / "old"
    old.mkdir()
    (old / "summary.json").write_text('{"results": {}, "units": "SI"}')
    (old / "table.csv").write_text("my own table")
    with pytest.raises(InputError, match="not an earlier output folder"):
        write_folder(old, _builder(RUN2), "summary.json")
    assert (old / "table.csv").read_text() == "my own table"
    assert sorted(p.name for p in old.iterdir()) == ["summary.json", "table.csv"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["old"]


def test_a_failed_build_leaves_everything_as_it_was(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}

    def broken(folder: Path) -> None:
        (folder / "summary.json").write_text("half")
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        write_folder(out, broken, "summary.json")
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]


def test_a_temporary_of_a_killed_run_is_removed_by_the_next(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True)
    stale = tmp_path / ".o.tmp-abc123"
    stale.mkdir()
    (stale / ".flywheel-writer-pid").write_text(dead.stdout.strip())
    (stale / "table.csv").write_text("half-written")
    foreign = tmp_path / ".o.tmp-notours"          # no pid file: not flywheel's, left alone
    foreign.mkdir()
    write_folder(tmp_path / "o", _builder(RUN1), "summary.json")
    assert not stale.exists() and foreign.exists()
    live = tmp_path / ".o.tmp-live"                # its writer still runs: left alone
    live.mkdir()
    (live / ".flywheel-writer-pid").write_text(str(os.getppid()))
    assert remove_stale_temporaries(tmp_path, "o") == [] and live.exists()


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_an_interrupted_run_leaves_the_output_folder_as_it_was(tmp_path, sig):
    """Ctrl-C or SIGTERM while a run writes: exit 130 / 143 with one line, no temporary
    folder left, the earlier output untouched."""
    out = tmp_path / "o"
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    first = subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                            "--out", str(out), "--no-plots", "--points", "360"],
                           capture_output=True, text=True, env=env)
    assert first.returncode == 0, first.stderr
    before = {p: p.read_bytes() for p in out.rglob("*") if p.is_file()}
    proc = subprocess.Popen([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                             "--out", str(out), "--points", "3600", "--transients"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    deadline = time.monotonic() + 30
    while not any(tmp_path.glob(".o.tmp-*")) and time.monotonic() < deadline:
        time.sleep(0.01)                           # wait until it is writing
    workers = _descendants_of(proc.pid)
    proc.send_signal(sig)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == (130 if sig == signal.SIGINT else 143), err
    time.sleep(0.2)
    assert not [w for w in workers if _alive(w)]       # the plot workers stopped with it
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1, err
    assert {p: p.read_bytes() for p in out.rglob("*") if p.is_file()} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"], list(tmp_path.rglob("*"))


def _alive(pid: int) -> bool:
    """A process that runs (a zombie, dead but not yet reaped, does not count)."""
    try:
        state = (Path(f"/proc/{pid}") / "stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _children_of(pid: int) -> list[int]:
    out = []
    for p in Path("/proc").iterdir():
        if p.name.isdigit():
            try:
                stat = (p / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            if int(stat[1]) == pid:
                out.append(int(p.name))
    return out


def _descendants_of(pid: int) -> list[int]:
    """Its children, theirs, … (the first plot worker forks the others)."""
    out, todo = [], [pid]
    while todo:
        kids = _children_of(todo.pop())
        out += kids
        todo += kids
    return out


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc (Linux)")
def test_ctrl_c_to_the_process_group_stops_the_plot_workers_too(tmp_path):
    """A terminal's Ctrl-C reaches the whole process group, the plot workers included: one
    line, exit 130, no worker's traceback, no worker left running, nothing left behind."""
    out = tmp_path / "o"
    proc = subprocess.Popen([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                             "--out", str(out)], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True)
    deadline = time.monotonic() + 30
    while not list(tmp_path.glob(".o.tmp-*/plots/*.png")) and time.monotonic() < deadline:
        time.sleep(0.01)                           # the workers are drawing
    workers = _descendants_of(proc.pid)
    assert len(workers) == 2, "two workers: one forked by the run, one by the first"
    os.killpg(proc.pid, signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 130, err
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    time.sleep(0.2)
    assert not [w for w in workers if _alive(w)]
    assert sorted(p.name for p in tmp_path.iterdir()) == []


@pytest.mark.skipif(not Path("/proc").is_dir(), reason="needs /proc (Linux)")
def test_a_killed_run_takes_its_workers_along_and_the_next_run_cleans_up(tmp_path):
    out = tmp_path / "o"
    proc = subprocess.Popen([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                             "--out", str(out)], stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 30
    while not list(tmp_path.glob(".o.tmp-*/plots/*.png")) and time.monotonic() < deadline:
        time.sleep(0.01)
    workers = _descendants_of(proc.pid)
    assert len(workers) == 2, "the plots are drawn by two forked workers"
    proc.kill()                                    # SIGKILL: no cleanup in the parent
    proc.wait(timeout=30)
    time.sleep(0.5)
    assert not [w for w in workers if _alive(w)]                       # died with the parent
    assert list(tmp_path.glob(".o.tmp-*"))         # the temporary is left behind …
    res = subprocess.run([sys.executable, "-m", "flywheel", "run", str(CASES / "compressor.toml"),
                          "--out", str(out), "--no-plots", "--points", "360"],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]       # … and the next run removes it


# -- the newer writers (task mut): a user's files in their folders survive a rerun ---------------

NEWER_WRITERS = {
    "task2": (["task2", "--case", str(CASES / "task2_khurmi_16_16_rim.toml")], "plots"),
    "aggregate": (["aggregate", str(CASES / "aggregate.toml")], "plots"),
    "duty-cycle": (["duty-cycle", str(CASES / "duty_readme_press.toml")], None),
    "variants-sheets": (["variants", str(CASES / "variants_task2.toml"), "-n", "2", "--seed", "1",
                         "--sheets", "--sheets-format", "html"], "sheets"),
}


@pytest.mark.parametrize("name", sorted(NEWER_WRITERS))
def test_a_rerun_of_the_newer_writers_keeps_the_users_files(tmp_path, name):
    """task2/aggregate/duty-cycle --out and variants --sheets into their earlier output folder
    with the user's own files added (beside the outputs and inside plots/ or sheets/) and an
    output the user edited: the rerun (with other options) keeps the user's files, keeps the
    edited one aside (.edited) and refuses a folder of the user's that is no output."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    args, sub = NEWER_WRITERS[name]
    out = tmp_path / "o"
    run = CliRunner().invoke
    first = run(app, [*args, "--out", str(out)])
    assert first.exit_code == 0, first.output
    ours = json.loads((out / MANIFEST).read_text(encoding="utf-8"))
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    if sub:
        (out / sub / "my_drawing.png").write_bytes(b"mine")
    edited = next(p for p in ("report.md", "answers.csv") if (out / p).is_file())
    (out / edited).write_text("edited by the user", encoding="utf-8")
    again = [*args, "--out", str(out)]
    if name.startswith("variants"):
        again = [a if a != "2" else "3" for a in again]          # three variants this time
    else:
        again += ["--report", "md"]
    second = run(app, again)
    assert second.exit_code == 0, second.output
    assert (out / "notes.txt").read_text(encoding="utf-8") == "mine"
    if sub:
        assert (out / sub / "my_drawing.png").read_bytes() == b"mine"
    assert (out / f"{edited}.edited").read_text(encoding="utf-8") == "edited by the user"
    assert ours                                                    # (a manifest was written)
    users = tmp_path / "thesis"
    users.mkdir()
    (users / "thesis.docx").write_bytes(b"precious")
    third = run(app, [*args, "--out", str(users)])
    assert third.exit_code == 2
    assert sorted(p.name for p in users.iterdir()) == ["thesis.docx"]


def test_a_ctrl_c_while_the_interpreter_exits_prints_no_traceback():
    """A Ctrl-C that comes after the command is over (the outputs whole), while Python runs its
    exit handlers (the plot workers joined): ignored, no "Exception ignored in atexit callback"
    traceback, the command's own exit code."""
    code = ("import atexit, os, signal, sys\n"
            "sys.argv = ['flywheel', 'task2', '--case', sys.argv[1], '--json']\n"
            "from flywheel.cli import main\n"
            "atexit.register(lambda: os.kill(os.getpid(), signal.SIGINT))\n"
            "main()\n")
    res = subprocess.run([sys.executable, "-c", code, str(CASES / "task2_seed_triangle.toml")],
                         capture_output=True, text=True, timeout=60)
    assert res.returncode == 0 and "Traceback" not in res.stderr, res.stderr
    assert json.loads(res.stdout)


@pytest.mark.parametrize("lang, line", [("en", "error: terminated (SIGTERM)"),
                                        ("ru", "ошибка: остановлено (SIGTERM)")])
def test_a_sigterm_after_the_output_is_whole_is_one_line_and_143(tmp_path, lang, line):
    """A SIGTERM that comes after the command is over (its output folder whole, Python running
    its exit handlers): one line and exit 143, the output and stdout kept (before: a silent
    death by the signal, exit −15)."""
    code = ("import atexit, os, signal, sys\n"
            "sys.argv = ['flywheel', 'task2', '--case', sys.argv[1], '--out', sys.argv[2],\n"
            "            '--json', '--lang', sys.argv[3]]\n"
            "from flywheel.cli import main\n"
            "atexit.register(lambda: os.kill(os.getpid(), signal.SIGTERM))\n"
            "main()\n")
    out = tmp_path / "t2"
    res = subprocess.run([sys.executable, "-c", code, str(CASES / "task2_seed_triangle.toml"),
                          str(out), lang], capture_output=True, text=True, timeout=120)
    assert res.returncode == 143, res.stderr
    assert res.stderr.strip().splitlines() == [line], res.stderr
    assert json.loads(res.stdout) == json.loads((out / "summary.json").read_text("utf-8"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t2"]


def test_an_error_raised_while_a_ctrl_c_unwinds_is_the_interruption(monkeypatch, capsys):
    """A library's clean-up that fails while a Ctrl-C unwinds it (matplotlib: "Invalid bounding
    box" in a sheet's figure, seen once by hand) is the interruption: one line, exit 130, not
    "internal error … a bug"."""
    import flywheel.cli as cli

    def interrupted(*a, **k):
        try:
            raise cli.Stopped(signal.SIGINT)
        finally:
            raise ValueError("Invalid bounding box")

    monkeypatch.setattr(cli, "app", interrupted)
    monkeypatch.setattr(signal, "signal", lambda *a: None)   # leave pytest's handlers alone
    with pytest.raises(SystemExit) as e:
        cli.main()
    assert e.value.code == 130
    assert capsys.readouterr().err == "error: interrupted (Ctrl-C)\n"
