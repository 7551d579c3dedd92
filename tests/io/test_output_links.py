"""Output folders cannot reach outside themselves (issue 23, item 1): links in an output folder
are never followed, a decoy manifest deletes nothing, a user's file at a name flywheel writes
is kept as NAME.user, --out may be a link to a folder, a swap that fails or is killed midway
leaves the folder exactly as it was (the next run puts back what a killed one moved)."""
from __future__ import annotations

import hashlib
import json
import multiprocessing as mp
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from flywheel.errors import InputError
from flywheel.io import output
from flywheel.io.output import MANIFEST, remove_stale_temporaries, write_file, write_folder

CASES = Path(__file__).resolve().parents[2] / "cases"
ROOT_USER = hasattr(os, "geteuid") and os.geteuid() == 0


def _builder(files: dict[str, str]):
    def build(folder: Path) -> None:
        for rel, text in files.items():
            p = folder / rel
            p.parent.mkdir(parents=True, exist_ok=True)
            p.write_text(text, encoding="utf-8")
    return build


RUN1 = {"summary.json": '{"results": {}, "units": "SI"}\n', "table.csv": "a\n1\n",
        "report.md": "# one\n", "plots/J_II.png": "png1", "plots/omega.png": "png2",
        "plots/deep/x.png": "png3"}
RUN2 = {"summary.json": '{"results": {"x": 1}, "units": "SI"}\n', "table.csv": "a\n2\n",
        "report.md": "# two\n", "report.pdf": "%PDF two", "plots/J_II.png": "png1 again"}


def snapshot(folder: Path) -> dict:
    """Every name below ``folder`` (links not followed): a file's bytes, a link's target, a
    folder's mark."""
    out = {}
    for root, dirs, files in os.walk(folder):
        for n in dirs + files:
            p = Path(root) / n
            rel = p.relative_to(folder).as_posix()
            if p.is_symlink():
                out[rel] = ("link", os.readlink(p))
            elif p.is_dir():
                out[rel] = ("dir",)
            else:
                out[rel] = ("file", p.read_bytes())
    return out


def _sha(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()


def _earlier_with_users_things(tmp_path: Path) -> tuple[Path, Path]:
    """An output folder of RUN1 with the user's things in it: an own report.pdf (a name RUN2
    writes for the first time), notes, an edited table.csv, plots/deep replaced by a link to
    a folder outside holding the same files; and that outside folder."""
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    (out / "report.pdf").write_bytes(b"%PDF the user's own")
    (out / "notes.txt").write_text("my notes")
    (out / "table.csv").write_text("edited by hand")
    figs = tmp_path / "figs"
    shutil.move(str(out / "plots" / "deep"), str(figs))
    (out / "plots" / "deep").symlink_to(Path("..", "..", "figs"))
    return out, figs


# -- links ---------------------------------------------------------------------------------------

def test_the_issues_plots_link_deletes_nothing_outside(tmp_path):
    """`run --out o`, `mv o/plots figs; ln -s ../figs o/plots`, `run --no-plots --out o`: the
    PNGs in figs/ outside o/ stay (before: every one deleted, then "Not a directory" and a
    half-merged o/), the link stays; a rerun with plots keeps the link as plots.user."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    out, figs = tmp_path / "o", tmp_path / "figs"
    run = CliRunner().invoke
    base = ["run", str(CASES / "fourbar.toml"), "--points", "72", "--out", str(out)]
    assert run(app, base).exit_code == 0
    pngs = sorted(p.name for p in (out / "plots").iterdir())
    assert pngs
    shutil.move(str(out / "plots"), str(figs))
    (out / "plots").symlink_to("../figs")
    outside = snapshot(figs)
    second = run(app, [*base, "--no-plots"])
    assert second.exit_code == 0, second.output
    assert snapshot(figs) == outside and sorted(outside) == pngs
    assert os.readlink(out / "plots") == "../figs"
    third = run(app, base)
    assert third.exit_code == 0, third.output
    assert snapshot(figs) == outside
    assert os.readlink(out / "plots.user") == "../figs"
    assert not (out / "plots").is_symlink()
    assert sorted(p.name for p in (out / "plots").iterdir()) == pngs
    assert "plots → plots.user" in third.stderr


def test_a_link_on_the_way_to_an_earlier_file_is_never_followed(tmp_path):
    out, figs = _earlier_with_users_things(tmp_path)
    outside = snapshot(figs)
    assert outside == {"x.png": ("file", b"png3")}        # the very file the manifest lists
    notes: list = []
    write_folder(out, _builder(RUN2), "summary.json", notes=notes)
    assert snapshot(figs) == outside
    assert os.readlink(out / "plots" / "deep") == os.path.join("..", "..", "figs")


def test_a_link_where_flywheel_writes_a_file_is_moved_aside_never_written_through(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    victim = tmp_path / "victim.md"
    victim.write_text("keep")
    (out / "report.md").unlink()
    (out / "report.md").symlink_to(victim)
    write_folder(out, _builder(RUN2), "summary.json")
    assert victim.read_text() == "keep"
    assert os.readlink(out / "report.md.user") == str(victim)
    assert (out / "report.md").read_text() == RUN2["report.md"]
    assert not (out / "report.md").is_symlink()


def test_out_may_be_a_link_to_a_folder_and_stays_a_link(tmp_path):
    real = tmp_path / "real"
    real.mkdir()
    link = tmp_path / "lnk"
    link.symlink_to("real")
    write_folder(link, _builder(RUN1), "summary.json")            # before: refused
    assert link.is_symlink() and os.readlink(link) == "real"
    assert (real / "table.csv").read_text() == RUN1["table.csv"]
    notes: list = []
    write_folder(link, _builder(RUN2), "summary.json", notes=notes)   # a rerun through it
    assert link.is_symlink() and (real / "report.pdf").read_text() == RUN2["report.pdf"]
    assert not (real / "plots" / "omega.png").exists()            # own stale file: removed
    assert not any(n.code == "out_manifest_untrusted" for n in notes)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["lnk", "real"]


# -- whose files ---------------------------------------------------------------------------------

def test_a_users_file_at_a_name_flywheel_writes_first_is_kept_as_user(tmp_path):
    out, _ = _earlier_with_users_things(tmp_path)
    notes: list = []
    write_folder(out, _builder(RUN2), "summary.json", notes=notes)
    assert (out / "report.pdf.user").read_bytes() == b"%PDF the user's own"
    assert (out / "report.pdf").read_text() == RUN2["report.pdf"]
    assert (out / "table.csv.edited").read_text() == "edited by hand"
    assert (out / "notes.txt").read_text() == "my notes"
    said = [n for n in notes if n.code == "out_user_kept"]
    assert len(said) == 1 and "report.pdf → report.pdf.user" in said[0]
    # the .user file is the user's: a third run leaves it; report.pdf is flywheel's now, so a
    # file the user writes over it is an edit (.edited); a new own file of the user's at a
    # name taken by a .user file goes to .user-2
    (out / "report.pdf").write_text("mine again")
    (out / "report.pdf.user").rename(out / "summary.json.user")
    (out / "summary.json").unlink()
    (out / "summary.json").symlink_to("notes.txt")
    write_folder(out, _builder(RUN2), "summary.json")
    assert (out / "summary.json.user").read_bytes() == b"%PDF the user's own"
    assert (out / "report.pdf.edited").read_text() == "mine again"
    assert os.readlink(out / "summary.json.user-2") == "notes.txt"
    assert (out / "notes.txt").read_text() == "my notes"


def test_the_cli_says_the_kept_file_once(tmp_path):
    from typer.testing import CliRunner

    from flywheel.cli import app

    out = tmp_path / "o"
    base = ["run", str(CASES / "fourbar.toml"), "--no-plots", "--points", "72", "--out", str(out)]
    run = CliRunner().invoke
    assert run(app, base).exit_code == 0
    (out / "report.pdf").write_bytes(b"my own pdf")
    res = run(app, [*base, "--report", "pdf"])
    assert res.exit_code == 0, res.output
    assert (out / "report.pdf.user").read_bytes() == b"my own pdf"
    assert (out / "report.pdf").read_bytes()[:5] == b"%PDF-"
    assert res.stderr.count("report.pdf → report.pdf.user") == 1
    ru = run(app, [*base, "--lang", "ru"])
    assert ru.exit_code == 0
    assert "удалены файлы прошлого запуска" in ru.stderr


@pytest.mark.parametrize("decoy", ["old format", "new format, no seal", "edited"])
def test_a_decoy_manifest_removes_and_replaces_nothing(tmp_path, decoy):
    """A manifest flywheel did not write for this folder, listing the user's file with its
    right hash: the file is neither removed (not written by this run) nor replaced (kept as
    NAME.user); the folder is still written into, and a note says why."""
    p = tmp_path / "p"
    p.mkdir()
    (p / "thesis.docx").write_text("precious")
    (p / "table.csv").write_text("my table")
    files = {"thesis.docx": _sha("precious"), "table.csv": _sha("my table")}
    if decoy == "old format":
        doc = json.dumps({"written_by": "flywheel", "kind": "output", "files": files})
    elif decoy == "new format, no seal":
        doc = json.dumps({"written_by": "flywheel", "format": 2, "kind": "output",
                          "files": files, "seal": "0" * 64})
    else:                                   # a real manifest with a line added by hand
        other = tmp_path / "x" / "p"
        write_folder(other, _builder({"table.csv": "my table"}), "summary.json")
        d = json.loads((other / MANIFEST).read_text())
        d["files"]["thesis.docx"] = files["thesis.docx"]
        doc = json.dumps(d)
    (p / MANIFEST).write_text(doc)
    notes: list = []
    write_folder(p, _builder(RUN2), "summary.json", notes=notes)
    assert (p / "thesis.docx").read_text() == "precious"
    assert (p / "table.csv.user").read_text() == "my table"
    assert (p / "table.csv").read_text() == RUN2["table.csv"]
    assert [n.code for n in notes] == ["out_manifest_untrusted", "out_user_kept"]
    # the folder's own manifest now: a rerun replaces what flywheel wrote, nothing else
    write_folder(p, _builder(RUN1), "summary.json")
    assert (p / "thesis.docx").read_text() == "precious"
    assert (p / "table.csv.user").read_text() == "my table"
    assert not (p / "report.pdf").exists()


def test_a_moved_output_folder_is_still_flywheels_and_its_manifest_the_same_bytes(tmp_path):
    """The manifest holds nothing of the folder's identity: the same bytes in any folder, and a
    renamed folder reruns as before."""
    write_folder(tmp_path / "a", _builder(RUN1), "summary.json")
    write_folder(tmp_path / "c", _builder(RUN1), "summary.json")
    assert (tmp_path / "a" / MANIFEST).read_bytes() == (tmp_path / "c" / MANIFEST).read_bytes()
    (tmp_path / "a").rename(tmp_path / "b")
    notes: list = []
    write_folder(tmp_path / "b", _builder(RUN2), "summary.json", notes=notes)
    assert not (tmp_path / "b" / "plots" / "omega.png").exists()
    assert [n.code for n in notes] == ["out_removed"]


def test_a_folder_of_the_users_where_a_file_goes_is_refused_before_anything_changes(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    (out / "report.pdf").mkdir()
    (out / "report.pdf" / "mine.txt").write_text("mine")
    (out / "table.csv").write_text("edited")
    before = snapshot(out)
    with pytest.raises(InputError, match="report.pdf is a folder, where flywheel writes a file"):
        write_folder(out, _builder(RUN2), "summary.json")
    assert snapshot(out) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]


# -- all or nothing ------------------------------------------------------------------------------

def _count_replaces(monkeypatch, tmp_path: Path) -> int:
    """How many os.replace calls a swap of RUN2 into the folder of _earlier_with_users_things
    makes (counted on a copy of that folder of the same name)."""
    calls = []
    real = os.replace
    copy, _ = _earlier_with_users_things(tmp_path / "count")
    monkeypatch.setattr(output.os, "replace", lambda *a: (calls.append(a), real(*a))[1])
    write_folder(copy, _builder(RUN2), "summary.json")
    monkeypatch.setattr(output.os, "replace", real)
    return len(calls)


def test_a_failure_at_any_step_of_the_swap_leaves_the_folder_exactly_as_it_was(tmp_path,
                                                                                 monkeypatch):
    """os.replace fails at its k-th call, for every k of the swap: one error line, the folder
    as before (names, bytes, links), nothing outside touched, no temporary left; the next run
    then sets no file of flywheel's aside as .edited (before: a half-new folder with the old
    manifest, and flywheel's own files called the user's edits)."""
    n = _count_replaces(monkeypatch, tmp_path)
    assert n >= 8
    out, figs = _earlier_with_users_things(tmp_path)
    before, outside = snapshot(out), snapshot(figs)
    real = os.replace
    for k in range(1, n + 1):
        calls = []

        def failing(src, dst, k=k, calls=calls):
            calls.append(src)
            if len(calls) == k:
                raise PermissionError(13, "Permission denied", str(dst))
            return real(src, dst)

        monkeypatch.setattr(output.os, "replace", failing)
        with pytest.raises(InputError, match="cannot be written"):
            write_folder(out, _builder(RUN2), "summary.json")
        monkeypatch.setattr(output.os, "replace", real)
        assert snapshot(out) == before, k
        assert snapshot(figs) == outside, k
        assert sorted(p.name for p in tmp_path.iterdir()) == ["count", "figs", "o"], k
    notes: list = []
    write_folder(out, _builder(RUN2), "summary.json", notes=notes)
    assert sorted(p.name for p in out.iterdir() if ".edited" in p.name) == ["table.csv.edited"]


@pytest.mark.skipif(ROOT_USER, reason="root writes into read-only folders")
def test_a_read_only_subfolder_midway_leaves_the_folder_as_it_was(tmp_path):
    out, _ = _earlier_with_users_things(tmp_path)
    before = snapshot(out)
    os.chmod(out / "plots", 0o555)
    try:
        with pytest.raises(InputError, match="cannot be written"):
            write_folder(out, _builder(RUN2), "summary.json")
    finally:
        os.chmod(out / "plots", 0o755)
    assert snapshot(out) == before


def _killed_at(k: int, out: str) -> None:
    """A child process: the swap of RUN2 into ``out`` dies (os._exit, as SIGKILL: no clean-up,
    no finally) at the k-th os.replace."""
    calls = []
    real = os.replace

    def dying(src, dst):
        calls.append(src)
        if len(calls) == k:
            os._exit(9)
        return real(src, dst)

    output.os.replace = dying
    write_folder(Path(out), _builder(RUN2), "summary.json")
    os._exit(0)


@pytest.mark.skipif("fork" not in mp.get_all_start_methods(), reason="needs fork")
def test_a_run_killed_at_any_step_of_the_swap_is_undone_by_the_next(tmp_path, monkeypatch):
    """A run killed (no clean-up) at the k-th move of its swap: its temporary folder, holding
    the earlier files, is found by the next run into the same place, which puts the folder
    back exactly as it was (said in a note), removes the temporary, and then writes its own
    files with nothing of flywheel's called an edit of the user's."""
    n = _count_replaces(monkeypatch, tmp_path)
    ctx = mp.get_context("fork")
    for k in range(1, n + 1):
        case = tmp_path / f"k{k}"
        out, figs = _earlier_with_users_things(case)
        before, outside = snapshot(out), snapshot(figs)
        child = ctx.Process(target=_killed_at, args=(k, str(out)))
        child.start()
        child.join(60)
        assert child.exitcode == 9, k
        left = sorted(p.name for p in case.iterdir() if p.name.startswith(".o.tmp-"))
        assert len(left) == 1, k                # the killed run's temporary, left behind
        notes: list = []
        assert remove_stale_temporaries(case, "o", notes) == [case / left[0]]
        assert snapshot(out) == before, k
        assert snapshot(figs) == outside, k
        assert sorted(p.name for p in case.iterdir()) == ["figs", "o"], k
        assert len(notes) <= 1
        write_folder(out, _builder(RUN2), "summary.json")
        assert sorted(p.name for p in out.iterdir() if ".edited" in p.name) == \
            ["table.csv.edited"], k


def test_a_killed_swap_is_undone_by_a_real_rerun(tmp_path, monkeypatch):
    """The same through the command line: the next `flywheel run` into the folder."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    if "fork" not in mp.get_all_start_methods():
        pytest.skip("needs fork")
    out = tmp_path / "o"
    base = ["run", str(CASES / "fourbar.toml"), "--no-plots", "--points", "72", "--out", str(out)]
    assert CliRunner().invoke(app, base).exit_code == 0
    (out / "notes.txt").write_text("mine")
    before = snapshot(out)
    child = mp.get_context("fork").Process(target=_killed_at, args=(4, str(out)))
    child.start()
    child.join(60)
    assert child.exitcode == 9 and snapshot(out) != before
    res = CliRunner().invoke(app, [*base, "--report", "md"])
    assert res.exit_code == 0, res.output
    assert "put back as it was before a run that was killed" in res.stderr
    assert ".edited" not in res.stderr and not list(out.glob("*.edited"))
    assert (out / "notes.txt").read_text() == "mine"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o"]


def test_a_journal_that_is_not_flywheels_is_refused_and_kept(tmp_path):
    out = tmp_path / "o"
    write_folder(out, _builder(RUN1), "summary.json")
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    stale = tmp_path / f".o.tmp-{dead}-abc"
    stale.mkdir()
    (stale / ".flywheel-journal.json").write_text(json.dumps(
        {"target": "o", "steps": [["mv", ["tmp", "x"], ["out", "../../etc/passwd"]]]}))
    before = snapshot(out)
    with pytest.raises(InputError, match="cannot be put back"):
        write_folder(out, _builder(RUN2), "summary.json")
    assert snapshot(out) == before and stale.exists()


def test_a_temporary_of_a_run_killed_while_building_is_removed(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    stale = tmp_path / f".o.tmp-{dead}-abc_12"
    stale.mkdir()
    (stale / "table.csv").write_text("half-written")
    mine = tmp_path / ".o.tmp-mine"                # not flywheel's name: left alone
    mine.mkdir()
    write_folder(tmp_path / "o", _builder(RUN1), "summary.json")
    assert not stale.exists() and mine.exists()


# -- one file ------------------------------------------------------------------------------------

def test_write_file_through_a_link_keeps_the_link_and_removes_dead_temporaries(tmp_path):
    real = tmp_path / "real.csv"
    real.write_text("old")
    link = tmp_path / "grades.csv"
    link.symlink_to("real.csv")
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    stale = tmp_path / f".real.csv.tmp-{dead}-zz9"
    stale.write_text("half")
    write_file(link, "a,b\n")
    assert os.readlink(link) == "real.csv" and real.read_text() == "a,b\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["grades.csv", "real.csv"]


def test_write_file_with_a_failing_writer_leaves_the_old_file_and_no_temporary(tmp_path):
    """A writer that writes half its file and fails: the old file keeps its bytes, no
    temporary is left, the OSError is one InputError naming the option."""
    from flywheel.errors import InputError
    from flywheel.io.output import write_file_with

    old = tmp_path / "plot.png"
    old.write_bytes(b"old image \x00\xff")
    seen = []

    def half_then_fail(tmp):
        seen.append(tmp)
        tmp.write_bytes(b"half")
        raise OSError(28, "No space left on device")

    with pytest.raises(InputError) as e:
        write_file_with(old, half_then_fail, "--plot", "an image file")
    assert "--plot" in str(e.value) and "No space left on device" in str(e.value)
    assert old.read_bytes() == b"old image \x00\xff"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plot.png"]
    assert seen[0].parent == tmp_path and seen[0].suffix == ".png"   # the format's suffix kept

    def wrong_format(tmp):
        tmp.write_bytes(b"half")
        raise ValueError("Format 'xyz' is not supported")

    with pytest.raises(ValueError):                 # not an OSError: goes on as it is
        write_file_with(old, wrong_format)
    assert old.read_bytes() == b"old image \x00\xff"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["plot.png"]


def test_write_file_takes_pieces_and_a_writer_writes_through_a_link(tmp_path):
    from flywheel.io.output import write_file_with

    write_file(tmp_path / "a.csv", iter(["x,", "y\n", "1,2\n"]))
    assert (tmp_path / "a.csv").read_bytes() == b"x,y\n1,2\n"
    real = tmp_path / "real.png"
    real.write_bytes(b"old")
    link = tmp_path / "p.png"
    link.symlink_to("real.png")
    write_file_with(link, lambda tmp: tmp.write_bytes(b"new"))
    assert os.readlink(link) == "real.png" and real.read_bytes() == b"new"


def test_dead_temporaries_with_the_suffix_are_removed(tmp_path):
    dead = subprocess.run([sys.executable, "-c", "import os; print(os.getpid())"],
                          capture_output=True, text=True, check=True).stdout.strip()
    stale = tmp_path / f".p.svg.tmp-{dead}-ab_9.svg"
    stale.write_text("half")
    other = tmp_path / f".p.svg.tmp-{dead}-ab_9.svg.mine"      # not flywheel's name: kept
    other.write_text("mine")
    write_file(tmp_path / "p.svg", "<svg/>")
    assert sorted(p.name for p in tmp_path.iterdir()) == [other.name, "p.svg"]
