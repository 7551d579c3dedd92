"""The Russian guides (docs/ru/) say what the program does: every TOML example in them is a
valid case (a fragment is checked inside the bundled case it belongs to), every `flywheel`
command they show runs in a scratch copy of cases/ with exit code 0, and every link to another
page of the docs leads to a file that exists."""
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

ROOT = Path(__file__).resolve().parents[1]
GUIDES = sorted((ROOT / "docs" / "ru").glob("*.md"))


def _blocks(path: Path, lang: str) -> list[str]:
    return re.findall(rf"```{lang}\n(.*?)```", path.read_text(encoding="utf-8"), re.S)


def _flywheel(args: list[str], cwd: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "COLUMNS": "100"}
    return subprocess.run([sys.executable, "-m", "flywheel", *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_there_are_guides():
    assert {p.name for p in GUIDES} >= {"README.md", "student.md", "teacher.md"}


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: p.name)
def test_every_link_to_the_docs_leads_to_a_file(path):
    for target in re.findall(r"\]\(([^)#]+?\.md)(?:#[^)]*)?\)", path.read_text(encoding="utf-8")):
        assert (path.parent / target).resolve().is_file(), (path.name, target)


@pytest.mark.parametrize("path", GUIDES, ids=lambda p: p.name)
def test_every_toml_example_is_valid(path, tmp_path):
    for i, block in enumerate(_blocks(path, "toml")):
        if block.lstrip().startswith("[variants]"):     # a template's table: in a template
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


@pytest.mark.slow
def test_every_command_shown_runs(tmp_path):
    shutil.copytree(ROOT / "cases", tmp_path / "cases")
    for path in GUIDES:
        for block in _blocks(path, "sh"):
            for line in block.splitlines():
                line = line.strip()
                if "flywheel " not in line or line.startswith("#"):
                    continue
                args = shlex.split(line[line.index("flywheel ") + len("flywheel "):])
                if args[0] == "grade":
                    _fill_answers(tmp_path / Path(args[2]).parent)
                res = _flywheel(args, tmp_path)
                assert res.returncode == 0, (path.name, line, res.stderr[-2000:])
