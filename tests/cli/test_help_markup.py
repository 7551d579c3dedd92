"""typer renders help through rich, which reads ``[motor]`` as a markup tag and drops it: every
bracketed word of an option's help must be escaped (``\\[motor]``), so that it reaches the
screen. The rendered --help of every command is compared with the help texts themselves."""
import re

import pytest
import typer
from typer.testing import CliRunner

from flywheel.cli import app

runner = CliRunner()
COMMAND = typer.main.get_command(app)


@pytest.mark.parametrize("name", sorted(COMMAND.commands))
def test_every_bracketed_word_of_the_help_is_shown(name):
    res = runner.invoke(app, [name, "--help"], env={"COLUMNS": "400"}, terminal_width=400)
    assert res.exit_code == 0
    shown = " ".join(res.output.split())
    for param in COMMAND.commands[name].params:
        text = getattr(param, "help", None) or ""
        for word in re.findall(r"(?<!\\)\[([A-Za-z_][\w. ]*)\]", text):
            assert f"[{word}]" in shown, (name, param.name, word)


#: what typer 0.29 shows of a parameter unless told otherwise: its Python type (<bool>, <int>,
#: <list[float]>, <path>, <float range>) and a required argument as {case}
TYPE_NAME = re.compile(r"<[a-z][\w.]*(\[[^\]<>]*\])?( range)?>")
PLACEHOLDER = re.compile(r"\{[^{}]*\}")


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("name", [None, *sorted(COMMAND.commands)])
def test_no_help_page_shows_a_type_name_or_a_placeholder(name, lang):
    """Every help page (the root's and each command's, with --lang en and ru) shows what an
    option takes in the user's words (DIR, DEG, PHI_DEG:RPM; nothing for a flag) and the usage
    line as ``run [OPTIONS] CASE``: no ``<bool>``, ``<list[float]>``, ``<path>`` or ``{case}``."""
    args = ([] if name is None else [name]) + ["--help", "--lang", lang]
    res = runner.invoke(app, args, env={"COLUMNS": "400"}, terminal_width=400)
    assert res.exit_code == 0, res.output
    assert not TYPE_NAME.search(res.output), (name, TYPE_NAME.search(res.output)[0])
    assert not PLACEHOLDER.search(res.output), (name, PLACEHOLDER.search(res.output)[0])
    usage = next(ln for ln in res.output.splitlines()
                 if ("Использование:" if lang == "ru" else "Usage:") in ln)
    if name is not None:
        for param in COMMAND.commands[name].params:
            if param.param_type_name == "argument":      # CASE, KEY, ANSWERS..., [FILE]
                assert param.metavar and param.metavar.isupper() and param.metavar in usage


def test_an_option_that_takes_a_value_says_what_in_words():
    """Every option that takes a value has a metavar of capitals (DIR, N, DEG, PHI_DEG:RPM), shown
    on its line of the help page; a flag shows none."""
    res = runner.invoke(app, ["run", "--help"], env={"COLUMNS": "400"}, terminal_width=400)
    lines = {ln.split()[1]: ln for ln in res.output.splitlines() if ln.startswith("│ --")}
    assert lines["--snapshot"].split()[2] == "PHI_DEG:RPM"
    assert lines["--out"].split()[2:4] == ["-o", "DIR"]
    assert lines["--at"].split()[2] == "DEG"
    assert lines["--no-plots"].split()[2] == "No"          # the help text right after the flag
    for name, command in COMMAND.commands.items():
        for p in command.params:
            if p.param_type_name == "option" and not p.is_flag:
                assert p.metavar and re.fullmatch(r"[A-Z][A-Z_:]*", p.metavar), (name, p.name)


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_root_lists_each_command_on_one_line_when_the_terminal_is_wide(lang):
    """The root's list of commands shows each command's first paragraph as a sentence: on a
    wide terminal one line per command, not broken where its docstring's source lines break
    (typer's rich help keeps single line breaks there)."""
    res = runner.invoke(app, ["--help", "--lang", lang], env={"COLUMNS": "400"}, terminal_width=400)
    assert res.exit_code == 0, res.output
    rows = [ln.strip("│ ").split(None, 1) for ln in res.output.splitlines()
            if ln.startswith("│ ") and not ln.startswith("│ -")]
    names = [row[0] for row in rows if row]
    assert names == list(COMMAND.commands), names          # no continuation lines between them
