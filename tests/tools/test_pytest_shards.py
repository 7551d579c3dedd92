"""tools/pytest_shards.py and its pytest plugin tests/shards.py: the split of ``--shard K/N``
(every test in exactly one share, a file's tests together, the files balanced by their measured
seconds), the durations table it writes and reads, and the runner's verdict on small test
trees of its own (a failure, a collection error, Ctrl-C) — never the project's suite."""
from __future__ import annotations

import importlib.util
import json
import os
import re
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path
from types import SimpleNamespace

import pytest

import shards

ROOT = Path(__file__).resolve().parents[2]
TOOL = ROOT / "tools" / "pytest_shards.py"
_spec = importlib.util.spec_from_file_location("pytest_shards", TOOL)
runner = sys.modules.setdefault("pytest_shards", importlib.util.module_from_spec(_spec))
if not hasattr(runner, "main"):
    _spec.loader.exec_module(runner)


# -- the split -----------------------------------------------------------------------------------

def test_split_puts_the_heaviest_first_on_the_least_loaded_share():
    """By hand: 10 → A; 6 → B; 5 → B (6 < 10); 4 → A (11 > 10); 1 → B (11 < 14)."""
    weights = {"a": 10.0, "b": 6.0, "c": 5.0, "d": 4.0, "e": 1.0}
    assert shards.split(weights, 2) == {"a": 0, "b": 1, "c": 1, "d": 0, "e": 1}
    assert shards.split(dict(reversed(weights.items())), 2) == shards.split(weights, 2)
    assert shards.split({"x": 1.0, "y": 1.0}, 3) == {"x": 0, "y": 1}     # ties: lower share


def test_weights_are_the_tables_seconds_per_test_of_the_file_and_kind():
    table = {"tests/a.py": {"quick": [10, 5.0], "slow": [2, 30.0]},
             "tests/b.py": {"quick": [30, 3.0]}}
    counts = {"tests/a.py": {"quick": 12, "slow": 1},     # two quick tests added, a slow gone
              "tests/b.py": {"quick": 30, "slow": 1},     # a slow test the table has none of
              "tests/new.py": {"quick": 4, "slow": 0}}    # a file the table does not know
    mean_quick, mean_slow = 8.0 / 40, 30.0 / 2
    w = shards.file_weights(counts, table)
    assert w["tests/a.py"] == pytest.approx(12 * 0.5 + 15.0)
    assert w["tests/b.py"] == pytest.approx(3.0 + mean_slow)
    assert w["tests/new.py"] == pytest.approx(4 * mean_quick)
    assert shards.file_weights(counts, {}) == {"tests/a.py": 12 + shards.SLOW_WEIGHT,
                                               "tests/b.py": 30 + shards.SLOW_WEIGHT,
                                               "tests/new.py": 4}


def _items(sizes, slow=()):
    mark = SimpleNamespace(name="slow")
    return [SimpleNamespace(nodeid=f"{path}::t{i}",
                            get_closest_marker=lambda name, s=path in slow: mark if s else None)
            for path, n in sizes.items() for i in range(n)]


def _config(dropped, table=None, tmp=None):
    options = {"shard_table": str(table) if table else None}
    return SimpleNamespace(getoption=lambda name, default=None: options.get(name, default),
                           rootpath=tmp or Path("/nonexistent"),
                           hook=SimpleNamespace(pytest_deselected=lambda items:
                                                dropped.extend(items)))


def _shares(sizes, n, **kw):
    out = []
    for k in range(1, n + 1):
        kept, dropped = _items(sizes, kw.get("slow", ())), []
        shards.keep_share(_config(dropped, kw.get("table")), kept, f"{k}/{n}")
        assert len(kept) + len(dropped) == sum(sizes.values())
        out.append({it.nodeid for it in kept})
    return out


def test_every_test_is_in_exactly_one_share_and_a_files_tests_together():
    sizes = {"tests/a.py": 40, "tests/b.py": 25, "tests/c.py": 20, "tests/d.py": 9,
             "tests/e.py": 3, "tests/f.py": 1}
    got = _shares(sizes, 3)
    every = [n for s in got for n in s]
    assert sorted(every) == sorted(it.nodeid for it in _items(sizes))
    for path in sizes:
        assert sum(any(n.startswith(path + "::") for n in s) for s in got) == 1
    counts = [len(s) for s in got]
    assert max(counts) - min(counts) <= max(sizes.values())
    with pytest.raises(pytest.UsageError):
        shards.keep_share(_config([]), _items(sizes), "4/3")
    with pytest.raises(pytest.UsageError):
        shards.keep_share(_config([]), _items(sizes), "1-3")


def test_the_table_balances_seconds_where_counts_would_not(tmp_path):
    """One slow file of 2 tests that take 100 s, eight quick files of 10 tests, 5 s each: by
    the table, the slow file alone in one share; without it (a slow test = 20 quick ones) the
    slow file's share also gets quick files: 100 + 10 s against 30 s."""
    sizes = {"tests/slow.py": 2} | {f"tests/q{i}.py": 10 for i in range(8)}
    table = tmp_path / "durations.json"
    runner.write_table(table, ({"tests/slow.py": {"slow": [2, 100.0]}}
                               | {f"tests/q{i}.py": {"quick": [10, 5.0]} for i in range(8)}, {}))
    by_table = _shares(sizes, 2, slow={"tests/slow.py"}, table=table)
    alone = [s for s in by_table if any(n.startswith("tests/slow.py") for n in s)][0]
    assert {n.split("::")[0] for n in alone} == {"tests/slow.py"}
    by_count = _shares(sizes, 2, slow={"tests/slow.py"})
    with_slow = [s for s in by_count if any(n.startswith("tests/slow.py") for n in s)][0]
    assert len({n.split("::")[0] for n in with_slow}) > 1


def test_a_heavy_test_is_a_unit_by_itself(tmp_path):
    """A file of three tests, two of them heavy (60 s and 50 s), and four quick files of 10 s:
    the heavy ones in different shares, the file's third test with neither necessarily; the
    shares 60 + 10 + 10 and 50 + 10 + 10 + 1."""
    sizes = {"tests/big.py": 3} | {f"tests/q{i}.py": 10 for i in range(4)}
    table = tmp_path / "durations.json"
    runner.write_table(table, ({"tests/big.py": {"quick": [1, 1.0]}}
                               | {f"tests/q{i}.py": {"quick": [10, 10.0]} for i in range(4)},
                               {"tests/big.py::t0": 60.0, "tests/big.py::t1": 50.0}))
    got = _shares(sizes, 2, table=table)
    assert ("tests/big.py::t0" in got[0]) != ("tests/big.py::t1" in got[0])
    files = [sorted({n.split("::")[0] for n in s if not n.startswith("tests/big.py")})
             for s in got]
    assert sorted(map(len, files)) == [2, 2]
    assert ({"tests/big.py::t0", "tests/big.py::t2"} <= got[0]) or \
        ({"tests/big.py::t1", "tests/big.py::t2"} <= got[1])      # 1 s to the lighter share


def test_a_table_that_does_not_read_is_one_usage_error(tmp_path):
    bad = tmp_path / "durations.json"
    for text in ('{"files": {"tests/a.py": {"quick": [1]}}}', '{"file": {}}',
                 '{"files": {}, "tests": {"tests/a.py::t": -1}}', "{"):
        bad.write_text(text, encoding="utf-8")
        with pytest.raises(pytest.UsageError, match="not a durations table"):
            shards.read_table(bad)
    assert shards.read_table(tmp_path / "absent.json") == ({}, {})


# -- the table -----------------------------------------------------------------------------------

def test_record_replaces_the_files_that_ran_and_keeps_the_others(tmp_path):
    (tmp_path / "tests").mkdir()
    for name in ("a.py", "b.py"):
        (tmp_path / "tests" / name).write_text("", encoding="utf-8")
    old = ({"tests/a.py": {"quick": [5, 50.0]}, "tests/b.py": {"quick": [1, 1.0]},
            "tests/gone.py": {"quick": [1, 1.0]}},
           {"tests/a.py::old": 9.0, "tests/b.py::big": 7.0, "tests/gone.py::big": 8.0})
    outcomes = [{"seconds": {"tests/a.py::t1": 0.25, "tests/a.py::t2": 2.0,
                             "tests/a.py::t4": 6.5},
                 "slow": ["tests/a.py::t2"], "heavy": ["tests/a.py::t4"]},
                {"seconds": {"tests/a.py::t3": 0.5}, "slow": [], "heavy": []}]
    new = runner.record(old, outcomes, tmp_path)
    want = ({"tests/a.py": {"quick": [2, 0.75], "slow": [1, 2.0]},
             "tests/b.py": {"quick": [1, 1.0]}},
            {"tests/a.py::t4": 6.5, "tests/b.py::big": 7.0})
    assert new == want
    path = tmp_path / "tests" / "durations.json"
    runner.write_table(path, new)
    first = path.read_bytes()
    assert shards.read_table(path) == want
    runner.write_table(path, (dict(reversed(new[0].items())), dict(reversed(new[1].items()))))
    assert path.read_bytes() == first                       # sorted: the same bytes
    assert len(first.decode().splitlines()) == 7 + 2 + 2    # a line a file and a heavy test


def test_the_checked_in_table_reads():
    """tests/durations.json is a table (an entry of a file renamed or gone is only ignored by
    the split, and dropped by the next --record)."""
    files, heavy = shards.read_table(ROOT / shards.TABLE)
    assert files, "tests/durations.json: write it with python tools/pytest_shards.py --record"
    assert all(entry and all(entry[k][0] > 0 for k in entry) for entry in files.values())
    assert all(seconds >= shards.HEAVY_S - 0.01 for seconds in heavy.values())   # its call


def test_combined_words_are_pytests():
    assert runner.combined_words({"failed": 1, "passed": 30, "error": 2, "skipped": 0}) == \
        "1 failed, 30 passed, 2 errors"
    assert runner.combined_words({"error": 1}) == "1 error"
    assert runner.combined_words({}) == ""


# -- the runner on trees of its own (whole processes: slow) --------------------------------------

def _tree(tmp_path: Path, files: dict[str, str]) -> Path:
    root = tmp_path / "tree"
    (root / "tests").mkdir(parents=True)
    (root / "pytest.ini").write_text(
        f"[pytest]\npythonpath = {ROOT / 'tests'}\naddopts = -p shards -q\n", encoding="utf-8")
    for name, text in files.items():
        (root / "tests" / name).write_text(textwrap.dedent(text), encoding="utf-8")
    return root


def _run(root: Path, capsys, *args) -> tuple[int, list[str]]:
    """The exit code and the verdict's lines (from the first share's line on: after the
    shares' own outputs)."""
    code = runner.main(["--root", str(root), "-n", "2", *args])
    lines = capsys.readouterr().out.splitlines()
    start = next(i for i, ln in enumerate(lines) if ln.startswith("share 1/2: exit "))
    return code, lines[start:], lines[:start]


GOOD = {"test_a.py": "def test_one():\n    pass\ndef test_two():\n    pass\n",
        "test_b.py": "import pytest\n@pytest.mark.skip\ndef test_skipped():\n    pass\n"
                     "def test_three():\n    pass\n"}


def test_a_failure_in_one_share_fails_the_run_and_is_named(tmp_path, capsys):
    root = _tree(tmp_path, GOOD | {"test_c.py": "def test_bad():\n    assert 1 == 2\n"})
    code, out, lines = _run(root, capsys, "--all")
    assert code == 1
    assert out[0].startswith("share 1/2: exit ") and out[1].startswith("share 2/2: exit ")
    assert sorted(out[0][16] + out[1][16]) == ["0", "1"]         # one share failed
    assert out[2:] == ["FAILED tests/test_c.py::test_bad", out[-1]]
    assert out[-1].startswith("FAILED: 1 failed, 3 passed, 1 skipped in ")
    # each share's output whole: its header, then its own pytest output up to its summary
    heads = [i for i, ln in enumerate(lines) if ln.startswith("=" * 30 + " share ")]
    assert len(heads) == 2
    for start, end in zip(heads, heads[1:] + [len(lines)]):
        summary = r"(=+ )?\d+ \w.* in [\d.]+s( =+)?"          # pytest's last line
        ends = [ln for ln in lines[start:end] if re.fullmatch(summary, ln)]
        assert ends == [lines[end - 1]], lines[start:end]    # its own summary, last


def test_a_collection_error_fails_the_run_and_is_named_once(tmp_path, capsys):
    root = _tree(tmp_path, GOOD | {"test_c.py": "import no_such_module_here\n"})
    code, out, _ = _run(root, capsys, "--all")
    assert code == 1
    assert out[2:] == ["ERROR tests/test_c.py", out[-1]]
    assert out[-1].startswith("FAILED: 1 error in ")


def test_all_passed_is_exit_0_and_record_writes_a_table_the_split_then_reads(tmp_path, capsys):
    root = _tree(tmp_path, GOOD)
    code, out, _ = _run(root, capsys, "--record")
    assert code == 0, out
    assert out[-2].startswith("passed: 3 passed, 1 skipped in ")
    table, heavy = shards.read_table(root / shards.TABLE)
    assert set(table) == {"tests/test_a.py", "tests/test_b.py"} and not heavy
    assert table["tests/test_a.py"]["quick"][0] == 2 and table["tests/test_b.py"]["quick"][0] == 2
    code, out, _ = _run(root, capsys, "--", "-k", "nothing_matches_this")
    assert code == 5 and out[-1].startswith("no tests ran: ")


def test_ctrl_c_stops_every_share_and_the_run_says_so(tmp_path):
    pids = tmp_path / "pids"
    pids.mkdir()
    sleeper = (f"import os, time\nfrom pathlib import Path\n"
               f"def test_sleep_{{n}}():\n"
               f"    Path({str(pids)!r}, str(os.getpid())).write_text('')\n"
               f"    time.sleep(120)\n")
    root = _tree(tmp_path, {f"test_s{n}.py": sleeper.replace("{n}", str(n)) for n in (1, 2)})
    # Ctrl-C as a terminal sends it to a foreground run: SIGINT's default restored for the
    # runner (a suite started in the background, `cmd &`, hands its children SIGINT ignored,
    # and the runner would never see this one)
    proc = subprocess.Popen([sys.executable, str(TOOL), "--root", str(root), "-n", "2", "--all"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    deadline = time.monotonic() + 60
    while len(list(pids.iterdir())) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    assert len(list(pids.iterdir())) == 2, "the shares did not start"
    proc.send_signal(signal.SIGINT)
    out, _ = proc.communicate(timeout=runner.GRACE_S + 30)
    assert proc.returncode == 130, out
    assert re.fullmatch(r"interrupted after [\d.]+ s: share 1/2 exit 2 \(no test ended\), "
                        r"share 2/2 exit 2 \(no test ended\)", out.splitlines()[-1]), out
    for pid in pids.iterdir():
        with pytest.raises(ProcessLookupError):
            os.kill(int(pid.name), 0)


def test_the_default_shares_are_the_usable_processors(tmp_path, monkeypatch):
    """A container's 2 cores, not the host's 64: the affinity, then the cgroup's quota."""
    monkeypatch.setattr(runner.os, "sched_getaffinity", lambda pid: set(range(64)))
    cpu_max = tmp_path / "cpu.max"
    cpu_max.write_text("200000 100000\n")
    assert runner.usable_cores(cpu_max) == 2
    cpu_max.write_text("50000 100000\n")                 # half a core: one share
    assert runner.usable_cores(cpu_max) == 1
    cpu_max.write_text("max 100000\n")
    assert runner.usable_cores(cpu_max) == 64
    assert runner.usable_cores(tmp_path / "none") == 64   # no cgroup v2: the affinity
    monkeypatch.setattr(runner.os, "sched_getaffinity", lambda pid: {0, 1})
    assert runner.usable_cores(tmp_path / "none") == 2
