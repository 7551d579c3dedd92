"""The catalogue of bad inputs (issue 17, item 8): every command given broken files, wrong
options and absurd numbers answers with one `error:` line on stderr naming the file and the
field, exit code 2, no traceback, nothing on stdout and nothing written.

The catalogue is data: tests/bad_inputs/catalogue.toml, one ``[[entry]]`` per bad input.

    [[entry]]
    id = "run/speed-1e308"                        # unique, "<command>/<what>"
    args = ["run", "{tmp}/c.toml", "--out", "{tmp}/out"]
    fragments = ["{tmp}/c.toml", "machine.speed_rps", "out of range"]
    subprocess = true                             # optional: run `python -m flywheel`
    timeout = 4                                   # optional: an entry that could run away: run
                                                  #   it in a subprocess killed after HANG_LIMIT
                                                  #   s (the value says how long it takes idle;
                                                  #   it is not asserted: no test times work)
    usage = true                                  # optional: a command-line usage error (below)
    xfail = "the bug, one line"                   # optional: a known bug of flywheel
    [entry.files."c.toml"]                        # files written into tmp_path first
    from = "compressor"                           # cases/compressor.toml, then, in this order:
    set = { "machine.speed_rps" = 1e308 }         #   dotted paths (a number indexes an array;
                                                  #   'variants."motor.J"': a key with dots)
    delete = ["crank.tip"]                        #   keys or array elements removed
    rename = { "machine.delta" = "dleta" }        #   a key renamed (new last name)
    replace = [["old text", "new text"]]          #   edits of the text (comments kept)
    append = "text"                               #   text added at the end
    encoding = "cp866"                            #   written in this encoding (default UTF-8;
                                                  #   a character it lacks becomes '?')

A file may instead be ``text = "…"`` (with ``encoding``), ``hex = "89504e47…"`` (bytes) or
``folder = true``. ``{tmp}`` is the test's tmp_path and ``{cases}`` the bundled cases/ folder,
in args and fragments. With set/delete/rename the case is parsed, edited and written again with
tomli_w (its comments are lost); replace/append edit the original text.

A command-line usage error (an unknown option, a value of the wrong type for an option) is
answered by the command-line parser with its own multi-line box; those entries (``usage =
true``) check exit 2, no traceback, nothing on stdout, nothing written and the fragments in
stderr, and test_usage_error_is_one_error_line records the one-line form as not yet done.
"""
from __future__ import annotations

import copy
import hashlib
import os
import signal
import subprocess
import sys
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

ROOT = Path(__file__).resolve().parents[1]
CASES = ROOT / "cases"
CATALOGUE = Path(__file__).resolve().parent / "bad_inputs" / "catalogue.toml"
COMMANDS = ("run", "check", "task2", "aggregate", "duty-cycle", "variants", "grade", "schema")
runner = CliRunner()


@dataclass(frozen=True)
class Entry:
    """One bad input: the command line, the files it needs and what the error line says."""

    id: str
    args: list[str]
    fragments: list[str]
    files: dict = field(default_factory=dict)
    subprocess: bool = False
    usage: bool = False
    xfail: str = ""
    timeout: float = 0

    @property
    def command(self) -> str:
        return next(a for a in self.args if not a.startswith("-"))


def load_catalogue() -> list[Entry]:
    data = tomllib.loads(CATALOGUE.read_text(encoding="utf-8"))
    return [Entry(**e) for e in data["entry"]]


ENTRIES = load_catalogue()


def _params():
    for e in ENTRIES:
        marks = [pytest.mark.xfail(strict=True, reason=e.xfail)] if e.xfail else []
        yield pytest.param(e, id=e.id, marks=marks)


# -- building the files -----------------------------------------------------------------------

def _split(path: str) -> list[str]:
    """The names of a dotted path; a name in double quotes may contain dots:
    ``variants."motor.J"`` is the key "motor.J" of the table [variants]."""
    parts, name, quoted, was_quoted = [], "", False, False
    for ch in path:
        if ch == '"':
            quoted, was_quoted = not quoted, True
        elif ch == "." and not quoted:
            parts.append(name)
            name, was_quoted = "", False
        else:
            name += ch
    assert not quoted and (name or was_quoted), f"bad path {path!r}"
    return [*parts, name]


def _walk(doc, path: str):
    """(parent container, last key) of a dotted path; a number indexes an array.

    A table's own key may contain dots (the [variants] table of a template has keys like
    "speed.omega0"): at each table the longest run of names that is one of its keys is taken,
    so ``variants.speed.omega0`` finds [variants]' key "speed.omega0". A key that does not
    exist yet must be the last name (quote it if it has dots: ``variants."motor.J"``)."""
    parts = _split(path)
    node, i = doc, 0
    while True:
        if isinstance(node, list):
            idx = int(parts[i])
            if i == len(parts) - 1:
                return node, idx
            node, i = node[idx], i + 1
            continue
        if not isinstance(node, dict):
            raise KeyError(f"{path!r}: {'.'.join(parts[:i])} is not a table or an array")
        for j in range(len(parts), i, -1):
            key = ".".join(parts[i:j])
            if key in node and (j == len(parts) or isinstance(node[key], (dict, list))):
                break
        else:
            if i == len(parts) - 1:
                return node, parts[i]            # a new key of an existing table
            raise KeyError(f"{path!r}: no {parts[i]!r} in {'.'.join(parts[:i]) or 'the file'}"
                           f" (a new key with dots is written in quotes)")
        if j == len(parts):
            return node, key
        node, i = node[key], j


def _edited(spec: dict) -> str:
    text = (CASES / f"{spec['from']}.toml").read_text(encoding="utf-8")
    if any(k in spec for k in ("set", "delete", "rename")):
        import tomli_w

        doc = copy.deepcopy(tomllib.loads(text))
        for path, value in spec.get("set", {}).items():
            parent, key = _walk(doc, path)
            if isinstance(parent, list) and key == len(parent):
                parent.append(value)
            else:
                parent[key] = value
        for path in spec.get("delete", []):
            parent, key = _walk(doc, path)
            del parent[key]
        for path, new in spec.get("rename", {}).items():
            parent, key = _walk(doc, path)
            parent[new] = parent.pop(key)
        text = tomli_w.dumps(doc)
    for old, new in spec.get("replace", []):
        assert old in text, f"{spec['from']}: no {old!r} to replace"
        text = text.replace(old, new, 1)
    return text + spec.get("append", "")


def build_files(entry: Entry, tmp: Path) -> None:
    for name, spec in entry.files.items():
        path = tmp / name
        path.parent.mkdir(parents=True, exist_ok=True)
        if spec.get("folder"):
            path.mkdir()
            continue
        if "hex" in spec:
            path.write_bytes(bytes.fromhex(spec["hex"]))
            continue
        text = spec["text"] if "text" in spec else _edited(spec)
        # a DOS or Windows editor has no φ or δ: characters the encoding lacks become '?'
        path.write_bytes(text.encode(spec.get("encoding", "utf-8"), errors="replace"))


def subst(s: str, tmp: Path) -> str:
    return s.replace("{tmp}", str(tmp)).replace("{cases}", str(CASES))


def snapshot(tmp: Path) -> dict[str, str]:
    """Every file and folder under tmp with a hash of its content: nothing written or lost."""
    out = {}
    for p in sorted(tmp.rglob("*")):
        rel = str(p.relative_to(tmp))
        out[rel] = "dir" if p.is_dir() else hashlib.sha256(p.read_bytes()).hexdigest()
    return out


# -- running the command ----------------------------------------------------------------------

IN_PROCESS_LIMIT = 60      # s: a command run in-process that takes longer is stopped (a hang)
HANG_LIMIT = 180           # s: the same guard for an entry run in a subprocess


@dataclass(frozen=True)
class Outcome:
    code: int | None
    stdout: str
    stderr: str
    exception: BaseException | None = None


class TooLong(BaseException):
    """Raised by the alarm in a command run in-process (BaseException: no `except Exception`
    of the command swallows it)."""


def _alarm(signum, frame):
    raise TooLong(f"still running after {IN_PROCESS_LIMIT} s")


def invoke(entry: Entry, tmp: Path) -> Outcome:
    args = [subst(a, tmp) for a in entry.args]
    if entry.subprocess or entry.timeout:
        env = dict(os.environ, PYTHONPATH=str(ROOT / "src"), COLUMNS="200")
        limit = HANG_LIMIT
        try:
            res = subprocess.run([sys.executable, "-m", "flywheel", *args], capture_output=True,
                                 text=True, cwd=tmp, env=env, timeout=limit)
        except subprocess.TimeoutExpired as exc:
            return Outcome(None, "", "", TooLong(f"killed: still running after {limit} s"))
        return Outcome(res.returncode, res.stdout, res.stderr)
    cwd = os.getcwd()
    os.chdir(tmp)                       # a default output folder (out/<case>) lands in tmp
    old = signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(IN_PROCESS_LIMIT)
    try:
        res = runner.invoke(app, args)
    except TooLong as exc:
        return Outcome(None, "", "", exc)
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
        os.chdir(cwd)
    exc = res.exception if not isinstance(res.exception, SystemExit) else None
    return Outcome(res.exit_code, res.stdout, res.stderr, exc)


#: each entry's own run (English), once per session: tests/render/test_messages.py runs the
#: same entry with --lang ru in the same folder and compares the two lines
_RUNS: dict[str, tuple[Path, dict, Outcome, dict]] = {}


def english_run(entry: Entry, tmp_path_factory) -> tuple[Path, dict, Outcome, dict]:
    """The entry's files built in a folder of its own and its command run there, once per
    session: (the folder, its files before, the outcome, its files after). Read-only: the
    outcome is frozen, the snapshots are copies."""
    if entry.id not in _RUNS:
        tmp = tmp_path_factory.mktemp("bad")
        build_files(entry, tmp)
        before = snapshot(tmp)
        o = invoke(entry, tmp)
        _RUNS[entry.id] = (tmp, before, o, snapshot(tmp))
    tmp, before, o, after = _RUNS[entry.id]
    return tmp, dict(before), o, dict(after)


def describe(o: Outcome) -> str:
    exc = "" if o.exception is None else f"\nexception: {type(o.exception).__name__}: {o.exception}"
    return f"exit {o.code}{exc}\nstdout: {o.stdout[:800]!r}\nstderr: {o.stderr[:1500]!r}"


# -- the catalogue ----------------------------------------------------------------------------

def test_the_catalogue_covers_every_command():
    ids = [e.id for e in ENTRIES]
    assert len(ids) == len(set(ids)), "duplicate ids"
    assert len(ENTRIES) >= 100
    per = {c: sum(e.command == c for e in ENTRIES) for c in COMMANDS}
    assert all(n >= 3 for n in per.values()), per             # a few for every command
    assert all(e.id.startswith(e.command + "/") for e in ENTRIES), "id = <command>/<what>"
    assert sum(e.subprocess for e in ENTRIES) >= 4
    for e in ENTRIES:
        assert e.fragments, e.id
        for name, spec in e.files.items():
            assert len({"from", "text", "hex", "folder"} & set(spec)) == 1, (e.id, name)


@pytest.mark.parametrize("entry", list(_params()))
def test_bad_input(entry: Entry, tmp_path_factory):
    tmp_path, before, o, after = english_run(entry, tmp_path_factory)
    what = describe(o)
    assert o.exception is None, what                      # in-process: no uncaught exception
    assert "Traceback" not in o.stdout + o.stderr, what
    assert o.code == 2, what
    assert o.stdout.strip() == "", what                   # no partial result
    assert after == before, "files written or lost\n" + what
    fragments = [subst(f, tmp_path) for f in entry.fragments]
    if entry.usage:
        flat = " ".join(o.stderr.replace("│", " ").split())
        for f in fragments:
            assert f in flat, f"{f!r} not in the usage error\n{what}"
        return
    lines = [ln for ln in o.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), what
    for f in fragments:
        assert f in lines[0], f"{f!r} not in the error line\n{what}"


def test_usage_error_is_one_error_line(tmp_path):
    o = invoke(Entry("run/points-not-a-number", ["run", f"{CASES}/compressor.toml", "--points",
                                                 "many", "--out", "{tmp}/out"], ["--points"],
                     subprocess=True), tmp_path)
    lines = [ln for ln in o.stderr.splitlines() if ln.strip()]
    assert o.code == 2 and len(lines) == 1 and lines[0].startswith("error: "), describe(o)
