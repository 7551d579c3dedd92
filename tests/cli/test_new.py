"""`flywheel new KIND [FILE]`: every starter case, in both languages, is written and then runs
through its own command (exit 0); its comments are in the language asked for and mark the
lines to change; an existing file (or link, or folder) is never written over."""
from __future__ import annotations

import os
import re

import pytest

from flywheel.cases import kind_of
from flywheel.cases.starter import KINDS, starter_text
from flywheel.io.toml import read_toml
from helpers import flywheel_in_process


def flywheel(*args, cwd):
    """The command line in-process (the process itself: tests/cli/test_cli_check.py)."""
    return flywheel_in_process(*args, cwd=cwd)


def _command(kind: str, file: str) -> list[str]:
    cmd = KINDS[kind][1]
    if cmd == "task2":
        return ["task2", "--case", file]
    if cmd == "run":
        return ["run", file, "--no-plots", "--out", "o"]
    return [cmd, file]


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("kind", list(KINDS))
def test_every_template_runs_through_its_command(tmp_path, kind, lang):
    res = flywheel("new", kind, "--lang", lang, cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    path = tmp_path / f"{kind}.toml"
    text = path.read_text(encoding="utf-8")
    assert text == starter_text(kind, lang)
    assert "#en" not in text and "#ru" not in text
    comments = [ln.partition("#")[2] for ln in text.splitlines() if "#" in ln]
    marker = "CHANGE" if lang == "en" else "ИЗМЕНИТЕ"
    assert sum(marker in c for c in comments) >= 3
    if lang == "ru":
        assert not any("CHANGE" in c for c in comments)
        cyrillic = sum(bool(re.search("[а-яА-Я]", c)) for c in comments)
        assert cyrillic >= 0.8 * len(comments)
    expected = {"run": "run", "task2": "task2", "aggregate": "aggregate",
                "duty-cycle": "duty_cycle"}[KINDS[kind][1]]
    assert kind_of(read_toml(path)) == expected
    ran = flywheel(*_command(kind, path.name), cwd=tmp_path)
    assert ran.returncode == 0, ran.stderr


def test_an_existing_file_is_never_written_over(tmp_path):
    mine = tmp_path / "four-bar.toml"
    mine.write_text("my own case\n", encoding="utf-8")
    res = flywheel("new", "four-bar", cwd=tmp_path)
    assert res.returncode == 2
    assert res.stderr.count("\n") == 1 and "already exists" in res.stderr
    assert mine.read_text(encoding="utf-8") == "my own case\n"
    os.symlink("nowhere.toml", tmp_path / "link.toml")           # a dangling link counts too
    res = flywheel("new", "shaper", "link.toml", cwd=tmp_path)
    assert res.returncode == 2 and not (tmp_path / "nowhere.toml").exists()
    (tmp_path / "folder").mkdir()
    assert flywheel("new", "shaper", "folder", cwd=tmp_path).returncode == 2
    ru = flywheel("new", "four-bar", "--lang", "ru", cwd=tmp_path)
    assert ru.returncode == 2 and "уже существует" in ru.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["folder", "four-bar.toml", "link.toml"]


def test_an_unknown_kind_and_a_missing_folder(tmp_path):
    res = flywheel("new", "sixbar", cwd=tmp_path)
    assert res.returncode == 2 and res.stderr.count("\n") == 1 and "slider-crank" in res.stderr
    res = flywheel("new", "four-bar", "no/such/folder.toml", cwd=tmp_path)
    assert res.returncode == 2 and res.stderr.count("\n") == 1
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("kind, field, want", [
    ("v-compressor", "cylinders", ["ВД", "НД"]),
    ("shaper", "forces", ["пс"]),
    ("slider-crank", "forces", ["пс"]),
])
def test_a_starters_loads_are_named_in_russian(tmp_path, kind, field, want):
    """A case begun from `flywheel new` names its cylinders and forces in the Russian outputs
    as the bundled cases do («цилиндр ВД», F_пс): the starters gave none, and a student's
    record said «цилиндр HP», «F(cutting)»."""
    from flywheel.cases.run import load_case
    from flywheel.io.text import in_language

    path = tmp_path / "c.toml"
    path.write_text(starter_text(kind, "ru"), encoding="utf-8")
    got = [in_language(x.label, "ru") for x in getattr(load_case(path), field)]
    assert got == want


@pytest.mark.parametrize("kind", list(KINDS))
def test_a_starters_title_and_source_are_in_both_languages(kind):
    """The starters' title and source in both languages (an untouched starter's Russian record
    had an English title, «Two-stage V-type air compressor», and «(starter case)»)."""
    import tomllib

    data = tomllib.loads(starter_text(kind, "ru"))
    for field in ("title", "source"):
        ru, en = data[field]["ru"], data[field]["en"]
        assert ru != en and re.search("[а-яё]", ru) and not re.search("[а-яё]", en), (field, ru)


def test_a_starters_force_is_named_in_russian_in_its_record(tmp_path):
    """The shaper's starter: «сила резания» in the Russian record (it said «сила cutting»)."""
    res = flywheel("new", "shaper", "--lang", "ru", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    res = flywheel("run", "shaper.toml", "--lang", "ru", "--no-plots", "--out", "o", cwd=tmp_path)
    assert res.returncode == 0, res.stderr
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    assert "Сила резания" in md and "cutting" not in md and "starter case" not in md


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("kind", list(KINDS))
def test_a_starter_points_to_its_formats_page_in_its_language(kind, lang):
    """Every docs/ page a starter names exists; a Russian starter of `run` names the Russian
    page of the fields, docs/ru/case-format.md (it had sent a Russian student to the English
    one)."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    text = starter_text(kind, lang)
    pages = re.findall(r"docs/[\w/.-]+\.md", text)
    assert pages and all((root / p).is_file() for p in pages), pages
    if lang == "ru" and KINDS[kind][1] == "run":
        assert "docs/ru/case-format.md" in pages and "docs/case-format.md" not in pages
