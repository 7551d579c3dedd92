"""The Russian guides (docs/ru/) say what the program does: every TOML example in them is a
valid case (a fragment is checked inside the bundled case it belongs to), every `flywheel`
command they show runs in a scratch copy of cases/ with exit code 0, every link to another
page of the docs leads to a file that exists, and every table has as many cells in each row as
in its header (else a Markdown viewer does not draw it as a table).

The worked variants (docs/ru/variants/*.md) hold one whole case each: it must be the bundled
case it names (the same TOML data, Russian comments aside), it must run, and every number the
page quotes from the run is checked against the run of the page's own TOML: a table headed
«строка сводки» against the terminal summary of `run --lang ru --no-plots`, «строка записки»
against report.md, «ключ summary.json» against summary.json to the digits the page shows."""
from __future__ import annotations

import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from helpers import flywheel_in_process

ROOT = Path(__file__).resolve().parents[1]
GUIDES = sorted((ROOT / "docs" / "ru").rglob("*.md"))
VARIANTS = sorted((ROOT / "docs" / "ru" / "variants").glob("*.md"))
#: the machine kinds the course hands out, each with its worked variant (issue 29)
KINDS = {"engine_4stroke", "engine_inline4", "pump", "press", "fourbar_rocker_load",
         "slotted_link", "shaper"}


def _blocks(path: Path, lang: str) -> list[str]:
    return re.findall(rf"```{lang}\n(.*?)```", path.read_text(encoding="utf-8"), re.S)


def _flywheel(args: list[str], cwd: Path):
    """The command line in-process (returncode, stdout, stderr: as subprocess.run's)."""
    return flywheel_in_process(*args, cwd=cwd)


def _process(args: list[str], cwd: Path) -> subprocess.CompletedProcess:
    """`flywheel ARGS` as a user types it: a whole process (every figure drawn by its own
    workers, not forked from the test's process)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "COLUMNS": "100"}
    return subprocess.run([sys.executable, "-m", "flywheel", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_there_are_guides():
    assert {p.name for p in GUIDES} >= {"README.md", "student.md", "teacher.md"}
    assert {p.stem for p in VARIANTS} == KINDS


@pytest.mark.parametrize("index", ["student.md", "README.md"])
def test_every_worked_variant_is_linked_from_the_guide(index):
    text = (ROOT / "docs" / "ru" / index).read_text(encoding="utf-8")
    for kind in KINDS:
        assert f"](variants/{kind}.md)" in text, (index, kind)


def _tables(text: str) -> list[list[list[str]]]:
    """Markdown tables outside code blocks: each a list of rows, each row its cells (a `|`
    inside backticks or escaped as `\\|` is text, not a border)."""
    text = re.sub(r"```.*?```", "", text, flags=re.S)
    tables, rows = [], []
    for line in text.splitlines() + [""]:
        if line.startswith("|"):
            cells = re.split(r"(?<!\\)\|", re.sub(r"`[^`]*`", lambda m: m[0].replace("|", "¦"), line))
            rows.append([c.strip().replace("¦", "|") for c in cells[1:-1]])
        elif rows:
            tables.append(rows)
            rows = []
    return tables


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_every_table_renders(path):
    """The header, the rule under it and every row have the same number of cells."""
    for table in _tables(path.read_text(encoding="utf-8")):
        assert len(table) >= 2 and all(set(c) <= set("-: ") for c in table[1]), (path.name, table[0])
        assert {len(r) for r in table} == {len(table[0])}, (path.name, table[0])


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_headings_are_numbered_in_order(path):
    """«## 1. …», «## 2. …»: no number skipped or repeated (a page's table of contents)."""
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    numbers = [int(n) for n in re.findall(r"^## (\d+)\. ", text, re.M)]
    assert numbers == list(range(1, len(numbers) + 1)), (path.name, numbers)


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_every_link_to_the_docs_leads_to_a_file(path):
    for target in re.findall(r"\]\(([^)#]+?\.md)(?:#[^)]*)?\)", path.read_text(encoding="utf-8")):
        assert (path.parent / target).resolve().is_file(), (path.name, target)


def _anchors(path: Path) -> set[str]:
    """The anchors GitHub gives a page's headings: lower case, punctuation dropped, spaces
    made hyphens."""
    text = re.sub(r"```.*?```", "", path.read_text(encoding="utf-8"), flags=re.S)
    return {re.sub(r"[^\w\- ]", "", h.strip().lower()).replace(" ", "-")
            for h in re.findall(r"^#+ (.+)$", text, re.M)}


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_every_anchor_leads_to_a_heading(path):
    """A table of contents' «(#3-команды)» and «(other.md#1-…)» name a heading that exists."""
    for target, anchor in re.findall(r"\]\(([^)#]*?)#([^)]+)\)", path.read_text(encoding="utf-8")):
        page = (path.parent / target).resolve() if target else path
        if page.suffix == ".md" and page.is_relative_to(ROOT / "docs" / "ru"):
            assert anchor in _anchors(page), (path.name, target, anchor)


#: Latin words a Russian page may say outside code: formats, functions, symbols' indices and
#: the program's own labels («ΔT_I max / min»), the Assur groups' names
LATIN = {"PDF", "SVG", "DXF", "Word", "max", "min", "cos", "arccos", "arcsin", "RRR", "RRP",
         "RPR", "ODB", "TOML", "Python", "Windows", "Linux", "macOS", "PowerShell", "Homebrew",
         "Debian", "Ubuntu", "Excel", "Moodle", "VS", "Code", "JSON", "Schema", "CSV", "HTML"}


@pytest.mark.parametrize("page", VARIANTS, ids=lambda p: p.stem)
def test_a_worked_variant_speaks_russian_outside_code(page):
    """No English word and no decimal point outside code (a section «§2.1» aside)."""
    text = re.sub(r"```.*?```", "", page.read_text(encoding="utf-8"), flags=re.S)
    text = re.sub(r"`[^`]*`|\]\([^)]*\)|[\w/.]+\.(?:md|json|toml|png|csv)\b", " ", text)
    words = set(re.findall(r"(?<!\w)[A-Za-z]{3,}", text)) - LATIN
    assert not words, (page.name, sorted(words))
    assert not re.findall(r"(?<![§\d.])\d+\.\d", text), page.name


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_every_toml_example_is_valid(path, tmp_path):
    for i, block in enumerate(_blocks(path, "toml")):
        if re.search(r"^\[machine\]", block, re.M):    # a whole case: checked as it is
            case = tmp_path / f"w{i}.toml"
            case.write_text(block, encoding="utf-8")
            res = _flywheel(["check", str(case)], tmp_path)
        elif block.lstrip().startswith("[variants]"):     # a template's table: in a template
            base = ROOT / "cases" / "variants_compressor.toml"
            text = re.sub(r"^\[variants\].*", "", base.read_text(encoding="utf-8"), flags=re.S | re.M)
            case = tmp_path / f"t{i}.toml"
            case.write_text(text + "\n" + block, encoding="utf-8")
            res = _flywheel(["variants", str(case), "--count", "2", "--seed", "1",
                             "--out", str(tmp_path / f"v{i}")], tmp_path)
        else:                                            # a table of a run case
            base = (ROOT / "cases" / "compressor.toml").read_text(encoding="utf-8")
            case = tmp_path / f"c{i}.toml"
            case.write_text(base + "\n" + block, encoding="utf-8")
            res = _flywheel(["check", str(case)], tmp_path)
        assert res.returncode == 0, (path.name, block, res.stderr)


def _fill_answers(folder: Path) -> None:
    """students.csv with every variant answered right (the key's own values)."""
    key = json.loads((folder / "answers.json").read_text(encoding="utf-8"))
    sheet = folder / "students.csv"
    header = sheet.read_text(encoding="utf-8").splitlines()[0].split(",")
    answers = header[2:]
    rows = [",".join(header)]
    for n, (variant, values) in enumerate(key["variants"].items() if "variants" in key
                                          else key.items()):
        vals = values.get("answers", values)
        rows.append(",".join([f"Студент {n}", variant, *(repr(float(vals[a])) for a in answers)]))
    sheet.write_text("\n".join(rows) + "\n", encoding="utf-8")


def _draws(args: list[str]) -> bool:
    """The command draws figures or sheets (its plot workers are what a whole process adds):
    ``run`` without ``--no-plots``, ``task2`` (its plots), ``variants`` (its sheets)."""
    return (args[0] == "run" and "--no-plots" not in args) or args[0] in {"task2", "variants"}


def _commands(path: Path) -> list[list[str]]:
    """The `flywheel …` command lines of a page's ``sh`` blocks, in order, each once (a line
    shown again, as the install line's run is again «Первый запуск», would be a rerun in the
    same folder: reruns are tests/cli/test_cli_run.py's)."""
    found = []
    for block in _blocks(path, "sh"):
        for line in block.splitlines():
            line = line.strip()
            if "flywheel " not in line or line.startswith("#"):
                continue
            args = shlex.split(line[line.index("flywheel ") + len("flywheel "):])
            if args not in found:
                found.append(args)
    return found


#: the pages that show commands (each run in a scratch copy of its own, as its reader would)
COMMANDED = [p for p in GUIDES if _commands(p)]


def test_the_guides_show_every_command():
    """The pages below run every kind of command a student and a teacher type."""
    shown = [a for p in COMMANDED for a in _commands(p)]
    assert len(shown) >= 30 and {a[0] for a in shown} >= {"run", "check", "task2", "variants",
                                                          "grade"}
    assert {p.name for p in COMMANDED} >= {"student.md", "teacher.md"} | {f"{k}.md"
                                                                         for k in KINDS}


@pytest.mark.slow
@pytest.mark.parametrize("path", COMMANDED, ids=lambda p: str(p.relative_to(ROOT / "docs" / "ru")))
def test_every_command_shown_runs(path, tmp_path):
    """A page's commands in order, in a scratch copy of cases/ of its own; one that draws as
    a whole process (its own plot workers), one that draws nothing (``check``, ``run
    --no-plots``, ``grade``) in-process: the same command line, without an interpreter
    started for it."""
    shutil.copytree(ROOT / "cases", tmp_path / "cases")
    for args in _commands(path):
        if args[0] == "grade":
            _fill_answers(tmp_path / Path(args[2]).parent)
        res = (_process if _draws(args) else _flywheel)(args, tmp_path)
        assert res.returncode == 0, (path.name, shlex.join(args), res.stderr[-2000:])


def _number(cell: str) -> tuple[float, float]:
    """A number as the page prints it («−35,79», «1 799», «0,04»): its value and half a unit
    of its last digit (the page's rounding)."""
    text = cell.strip("` ").replace("−", "-").replace("\u202f", "").replace(" ", "").replace(",", ".")
    decimals = len(text.split(".")[1]) if "." in text else 0
    return float(text), 0.5 * 10.0 ** -decimals


def _json_at(document, path: str):
    """`results.output_link.extremes_phi_deg[0]` in summary.json."""
    value = document
    for part in re.findall(r"[^.\[\]]+|\[\d+\]", path):
        value = value[int(part[1:-1])] if part.startswith("[") else value[part]
    return value


def _variant_case(page: Path) -> tuple[str, Path]:
    """The page's one whole case (a ```toml block with [machine] or [tabulated]) and the
    bundled case its first `flywheel run` names."""
    cases = [b for b in _blocks(page, "toml") if re.search(r"^\[(machine|tabulated)\]", b, re.M)]
    assert len(cases) == 1, (page.name, len(cases))
    runs = [line for b in _blocks(page, "sh") for line in b.splitlines() if "flywheel run " in line]
    assert runs, page.name
    bundled = ROOT / shlex.split(runs[0].split("flywheel run ", 1)[1])[0]
    return cases[0], bundled


@pytest.mark.parametrize("page", VARIANTS, ids=lambda p: p.stem)
def test_a_worked_variant_is_its_bundled_case(page):
    """The TOML the page explains line by line is the case in cases/ (its data; the comments
    are the page's own, in Russian), so the page cannot drift from the file a student copies."""
    import tomllib
    text, bundled = _variant_case(page)
    assert bundled.name == f"{page.stem}.toml"
    assert tomllib.loads(text) == tomllib.loads(bundled.read_text(encoding="utf-8"))


@pytest.mark.parametrize("page", VARIANTS, ids=lambda p: p.stem)
def test_a_worked_variant_runs_and_says_what_its_page_quotes(page, tmp_path):
    """`flywheel run CASE --lang ru --no-plots` of the page's own TOML, and every number its
    quote tables give found where the page says: on the summary line it names, on the line of
    report.md it names, or in summary.json to the digits shown."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    text, _ = _variant_case(page)
    case = tmp_path / f"{page.stem}.toml"
    case.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    res = CliRunner().invoke(app, ["run", str(case), "--lang", "ru", "--no-plots", "--out", str(out)],
                             env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    summary_lines = res.output.splitlines()
    report_lines = (out / "report.md").read_text(encoding="utf-8").splitlines()
    document = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    quoted = 0
    for table in _tables(page.read_text(encoding="utf-8")):
        head = table[0][0]
        for label, value, *_ in table[2:]:
            label, value = label.strip("`"), value.strip("`")
            if head == "строка сводки":
                assert any(label in line and value in line for line in summary_lines), (label, value)
            elif head == "строка записки":
                assert any(label in line and value in line for line in report_lines), (label, value)
            elif head == "ключ summary.json":
                number, half_unit = _number(value)
                assert abs(_json_at(document, label) - number) <= half_unit * (1 + 1e-9), (label, value)
            else:
                continue
            quoted += 1
    assert quoted >= 8, (page.name, quoted)
