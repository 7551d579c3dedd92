"""The shares of the test suite: a pytest plugin (tests/conftest.py loads it; the runner is
tools/pytest_shards.py, which starts N pytest processes at once, one a share).

``--shard K/N`` keeps the K-th of N shares of the selected tests. A file's tests stay together
(its module fixtures run once), but for the heavy ones: a test whose call took
:data:`HEAVY_S` s or more goes alone (else one file of a few such tests would be the last to
end, whatever the split). Each unit weighs its measured seconds: the table
tests/durations.json, written by ``python tools/pytest_shards.py --record``, gives per file the
count and the seconds of its quick tests and of its slow ones (the heavy ones apart), and each
heavy test's seconds. A file the table does not know, or a kind of test it recorded none of
there, weighs the table's mean seconds per test of that kind; without a table, a quick test
weighs 1 and a slow one :data:`SLOW_WEIGHT`. The units go heaviest first (ties by name) to the
share with the least so far (ties: the lower share): the same split in every process, so each
test is in exactly one share.

``--report-out FILE`` writes the process's outcome as JSON for the runner: pytest's own counts
(passed, failed, skipped, errors, …), the failed tests' and errors' node ids, each test's
seconds (setup + call + teardown), which are slow and which heavy. ``--guard-out FILE`` is the
quick loop's guard (tests/conftest.py writes it).
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

#: without a table, a slow test's weight (a quick one: 1): about the ratio of their mean times
SLOW_WEIGHT = 20

#: a test whose call phase takes this long or longer is a unit of the split by itself
HEAVY_S = 5.0

#: the table of measured durations, from the rootdir
TABLE = "tests/durations.json"

#: pytest's outcome keys (its terminal summary's words) the report counts
OUTCOMES = ("failed", "passed", "skipped", "deselected", "xfailed", "xpassed", "error")


def pytest_addoption(parser):
    group = parser.getgroup("shards", "the shares of tools/pytest_shards.py")
    group.addoption("--shard", default=None, metavar="K/N",
                    help="run the K-th of N shares of the test files (1 ≤ K ≤ N), split by "
                         "their measured seconds (tests/durations.json): tools/pytest_shards.py "
                         "runs the N at once")
    group.addoption("--shard-table", default=None, metavar="FILE",
                    help=f"the durations table of --shard (default: {TABLE} of the rootdir)")
    group.addoption("--report-out", default=None, metavar="FILE",
                    help="write the counts, the failures' node ids and each test's seconds to "
                         "FILE (JSON) for tools/pytest_shards.py")
    group.addoption("--guard-out", default=None, metavar="FILE",
                    help="with --shard: write the modules the share's tests imported to FILE "
                         "(JSON) for tools/pytest_shards.py to check their union")


def parse_shard(shard: str) -> tuple[int, int]:
    """``K/N`` → (k, n), 1 ≤ k ≤ n; else a usage error."""
    try:
        k, n = (int(v) for v in shard.split("/"))
        assert 1 <= k <= n
    except (ValueError, AssertionError):
        raise pytest.UsageError(f"--shard {shard}: not K/N with 1 ≤ K ≤ N") from None
    return k, n


def read_table(path: Path) -> tuple[dict[str, dict[str, list[float]]], dict[str, float]]:
    """The table's files, {path: {"quick": [count, seconds], "slow": [count, seconds]}}, and
    its heavy tests, {node id: seconds}; empty without a table; a usage error naming the file
    for one that does not read."""
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return {}, {}
    try:
        table = json.loads(text)
        files, heavy = table["files"], table.get("tests", {})
        for entry in files.values():
            for kind in ("quick", "slow"):
                count, seconds = entry.get(kind, (0, 0.0))
                assert count >= 0 and seconds >= 0
        assert all(seconds >= 0 for seconds in heavy.values())
        return files, heavy
    except (ValueError, KeyError, TypeError, AssertionError, AttributeError):
        raise pytest.UsageError(f"{path}: not a durations table ({{\"files\": {{path: "
                                f"{{\"quick\": [count, seconds], \"slow\": [count, seconds]}}}}, "
                                "\"tests\": {node id: seconds}}); write it again: "
                                "python tools/pytest_shards.py --record") from None


def file_weights(counts: dict[str, dict[str, int]], table: dict) -> dict[str, float]:
    """Each file's weight from its selected tests' counts by kind ({path: {"quick": n, "slow":
    m}}): the table's seconds per test of that file and kind, else the table's mean of that
    kind, else 1 a quick test and :data:`SLOW_WEIGHT` a slow one."""
    known = {}
    for kind in ("quick", "slow"):
        n = sum(e.get(kind, (0, 0))[0] for e in table.values())
        s = sum(e.get(kind, (0, 0))[1] for e in table.values())
        if n and s > 0:
            known[kind] = s / n
    mean = {"quick": known.get("quick", known.get("slow", SLOW_WEIGHT) / SLOW_WEIGHT),
            "slow": known.get("slow", known.get("quick", 1.0) * SLOW_WEIGHT)}
    weights = {}
    for path, by_kind in counts.items():
        w = 0.0
        for kind, n in by_kind.items():
            count, seconds = table.get(path, {}).get(kind, (0, 0.0))
            w += n * (seconds / count if count else mean[kind])
        weights[path] = w
    return weights


def split(weights: dict[str, float], n: int) -> dict[str, int]:
    """{path: share index 0 … n−1}: heaviest first (ties by path), each to the least loaded
    share (ties: the lower one)."""
    load, share_of = [0.0] * n, {}
    for path in sorted(weights, key=lambda p: (-weights[p], p)):
        s = min(range(n), key=lambda i: (load[i], i))
        share_of[path] = s
        load[s] += weights[path]
    return share_of


def _path(nodeid: str) -> str:
    return nodeid.split("::", 1)[0]


def _slow(item) -> bool:
    return item.get_closest_marker("slow") is not None


@pytest.hookimpl(trylast=True)
def pytest_collection_modifyitems(config, items):
    """After the marks (tests/conftest.py) and ``-m``/``-k`` have chosen: keep the share."""
    shard = config.getoption("shard", None)
    if shard:
        keep_share(config, items, shard)


def keep_share(config, items, shard: str) -> None:
    """Keep, in ``items``, the K-th share of ``shard`` = "K/N"; the others deselected."""
    k, n = parse_shard(shard)
    table_path = config.getoption("shard_table", None) or Path(config.rootpath) / TABLE
    files, heavy = read_table(Path(table_path))
    unit_of = [it.nodeid if it.nodeid in heavy else _path(it.nodeid) for it in items]
    counts: dict[str, dict[str, int]] = {}
    for item, unit in zip(items, unit_of):
        if unit != item.nodeid:
            by_kind = counts.setdefault(unit, {"quick": 0, "slow": 0})
            by_kind["slow" if _slow(item) else "quick"] += 1
    weights = file_weights(counts, files) | {u: heavy[u] for u in unit_of if u in heavy}
    share_of = split(weights, n)
    kept, dropped = [], []
    for it, unit in zip(items, unit_of):
        (kept if share_of[unit] == k - 1 else dropped).append(it)
    if dropped:
        config.hook.pytest_deselected(items=dropped)
    items[:] = kept


# -- the report for the runner ---------------------------------------------------------------------

class _Report:
    """Each test's seconds and slowness, gathered as its phases are reported."""

    def __init__(self):
        self.seconds: dict[str, float] = {}
        self.slow: set[str] = set()
        self.heavy: set[str] = set()        # its call took HEAVY_S or more

    def pytest_runtest_logreport(self, report):
        self.seconds[report.nodeid] = self.seconds.get(report.nodeid, 0.0) + report.duration
        if report.when == "call" and report.duration >= HEAVY_S:
            self.heavy.add(report.nodeid)
        if report.when == "setup" and "slow" in report.keywords:
            self.slow.add(report.nodeid)


def pytest_configure(config):
    if config.getoption("report_out", None):
        config.pluginmanager.register(_Report(), "flywheel-shards-report")


@pytest.hookimpl(trylast=True)
def pytest_sessionfinish(session, exitstatus):
    """Write ``--report-out``: pytest's counts as its terminal summary gives them, the failed
    tests' and errors' node ids (a file that did not collect is an error named by its path),
    each test's seconds, and the exit status."""
    config = session.config
    out = config.getoption("report_out", None)
    if not out:
        return
    report = config.pluginmanager.get_plugin("flywheel-shards-report")
    tr = config.pluginmanager.get_plugin("terminalreporter")
    stats = getattr(tr, "stats", {}) if tr is not None else {}
    counts = {key: len(stats.get(key, ())) for key in OUTCOMES}

    def ids(key):
        return sorted({getattr(r, "nodeid", "") or str(getattr(r, "fspath", "?"))
                       for r in stats.get(key, ())})

    Path(out).write_text(json.dumps({
        "exitstatus": int(session.exitstatus),
        "counts": counts,
        "failed": ids("failed"),
        "errors": ids("error"),
        "seconds": {k: round(v, 4) for k, v in sorted(report.seconds.items())},
        "slow": sorted(report.slow),
        "heavy": sorted(report.heavy),
    }), encoding="utf-8")
