"""Command-line conventions (issue 17): --version, -q/--quiet, --debug, an internal error as
one line with exit 1, a closed pipe, completion."""
from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

CASES = Path(__file__).resolve().parents[2] / "cases"


def flywheel(*args, code: str | None = None, **kw):
    """Run the console entry point (flywheel.cli.main) in a fresh interpreter; ``code`` runs
    first (to plant a bug)."""
    prog = textwrap.dedent(code or "") + "\nimport sys\nfrom flywheel.cli import main\n" \
        f"sys.argv = ['flywheel', *{[str(a) for a in args]!r}]\nmain()\n"
    return subprocess.run([sys.executable, "-c", prog], capture_output=True, text=True, **kw)


def console_script(*args):
    """The console entry point (flywheel.cli.main) with ``flywheel ARGS`` as its command line,
    in this process (its output captured, its exit code kept, the signal handlers it sets
    restored): what `flywheel ARGS` does, without an interpreter started per call."""
    import contextlib
    import io
    import signal
    from types import SimpleNamespace

    from flywheel.cli import main

    out, err = io.StringIO(), io.StringIO()
    argv, handlers = sys.argv, {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    sys.argv = ["flywheel", *map(str, args)]
    code = 0
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            main()
    except SystemExit as stop:
        code = stop.code or 0
    finally:
        sys.argv = argv
        for s, h in handlers.items():
            signal.signal(s, h)
    return SimpleNamespace(returncode=code, stdout=out.getvalue(), stderr=err.getvalue())


def test_version():
    from flywheel import __version__

    res = console_script("--version")
    assert res.returncode == 0 and res.stdout.strip() == f"flywheel {__version__}"


def test_quiet_prints_nothing_but_errors(tmp_path):
    res = console_script("-q", "run", CASES / "compressor.toml", "--no-plots", "--points",
                         "360", "--out", tmp_path / "o")
    assert res.returncode == 0 and res.stdout == "" and res.stderr == ""
    assert (tmp_path / "o" / "summary.json").is_file()
    res = console_script("-q", "run", CASES / "compressor.toml", "--no-plots", "--points",
                         "360", "--out", tmp_path / "o", "--json")
    assert res.stdout.lstrip().startswith("{")          # the asked-for JSON still comes
    res = console_script("--quiet", "run", tmp_path / "missing.toml")
    assert res.returncode == 2 and res.stderr.startswith("error: ") and res.stdout == ""


def test_quiet_is_taken_after_the_command_too(tmp_path):
    """`flywheel run case.toml -q`, as one writes it, had been refused («no such option: -q»):
    every command takes -q/--quiet after its name, a --json on either side of it still
    printed."""
    args = [CASES / "compressor.toml", "--no-plots", "--points", "360", "--out", tmp_path / "o"]
    res = console_script("run", *args, "-q")
    assert res.returncode == 0 and res.stdout == "" and res.stderr == ""
    assert (tmp_path / "o" / "summary.json").is_file()
    for flags in (("--json", "-q"), ("--quiet", "--json")):
        res = console_script("run", *args, *flags)
        assert res.returncode == 0 and res.stdout.lstrip().startswith("{") and res.stderr == ""
    for command in (["check", CASES / "compressor.toml"], ["task2", "--profile", "triangle"],
                    ["schema"]):
        res = console_script(*command, "-q")
        assert res.returncode == 0 and res.stdout == "" and res.stderr == "", command
    res = console_script("check", tmp_path / "missing.toml", "--quiet")
    assert res.returncode == 2 and res.stderr.startswith("error: ") and res.stdout == ""
    res = console_script("run", "--help")
    assert "--quiet" in res.stdout and "-q" in res.stdout


BUG = """
import flywheel.cases.run as r
def broken(path):
    return 1 / 0
r.load_case = broken
"""


def test_an_internal_error_is_one_line_naming_it_a_bug():
    res = flywheel("check", CASES / "compressor.toml", code=BUG)
    assert res.returncode == 1
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1, res.stderr
    assert lines[0].startswith("error: internal error in flywheel ")
    assert "ZeroDivisionError" in lines[0] and "--debug" in lines[0]


def test_debug_shows_the_traceback():
    res = flywheel("--debug", "check", CASES / "compressor.toml", code=BUG)
    assert res.returncode == 1 and "Traceback" in res.stderr and "in broken" in res.stderr


def test_a_closed_pipe_ends_quietly(tmp_path):
    prog = [sys.executable, "-m", "flywheel", "task2", "--json"]
    p1 = subprocess.Popen(prog, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    p1.stdout.read(5)
    p1.stdout.close()                                   # like `| head -c 5`
    err = p1.stderr.read().decode()
    p1.wait(timeout=60)
    assert "Traceback" not in err and "Exception ignored" not in err, err


def test_completion_is_offered():
    res = console_script("--help")
    assert "--install-completion" in res.stdout


def test_a_usage_error_is_one_error_line():
    """The parser's own errors (a value of the wrong type, an unknown option or command, a
    missing argument) are one `error:` line with exit 2, not the parser's box."""
    for args, fragment in ((["run", CASES / "compressor.toml", "--points", "many"],
                            "flywheel run: Invalid value for '--points'"),
                           (["run"], "flywheel run: Missing argument 'CASE'"),
                           (["bogus"], "No such command 'bogus'"),
                           (["task2", "--md", "abc"], "Invalid value for '--md'")):
        res = console_script(*args)
        lines = [ln for ln in res.stderr.splitlines() if ln.strip()]
        assert res.returncode == 2 and len(lines) == 1, res.stderr
        assert lines[0].startswith("error: ") and fragment in lines[0], lines[0]
        assert "--help)" in lines[0] and res.stdout == ""
    res = console_script()                               # no arguments: the help, exit 0
    assert res.returncode == 0 and "Commands" in res.stdout


import pytest  # noqa: E402


@pytest.mark.parametrize("args", [("task2", "--profile", "triangle"),
                                  ("aggregate", CASES / "aggregate.toml", "--t-end", "0.2")])
def test_russian_terminal_tables_number_rows_under_the_number_sign(args):
    """A Russian terminal table numbers its rows under «№», as the records do; task 2's and the
    aggregate's had a bare «#». English keeps «#». The aggregate's min … max is said in words."""
    ru = console_script(*args, "--lang", "ru")
    assert ru.returncode == 0, ru.stderr
    heads = [ln for ln in ru.stdout.splitlines() if ln.startswith("┃")]
    assert heads and not any(ln.split("┃")[1].strip() == "#" for ln in heads), heads
    assert any(ln.split("┃")[1].strip() == "№" for ln in heads), heads
    assert "min … max" not in ru.stdout
    en = console_script(*args)
    assert any(ln.split("┃")[1].strip() == "#" for ln in en.stdout.splitlines()
               if ln.startswith("┃"))
