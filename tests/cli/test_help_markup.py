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
        for word in re.findall(r"(?<!\\)\[([A-Za-z_][\w.]*)\]", text):
            assert f"[{word}]" in shown, (name, param.name, word)
