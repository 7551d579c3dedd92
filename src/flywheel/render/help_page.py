"""typer's own words on a help page (``flywheel … --help --lang ru``): the constants of
typer.rich_utils (panel titles, ``[default: …]``, ``[required]``) and the usage line's
``Usage:``, ``[OPTIONS]``, ``COMMAND [ARGS]...``, in both languages (the catalogue's
"help_page:<key>"); cli/options.py sets them while it formats a Russian page."""
from __future__ import annotations

from flywheel.render.catalogue import words

#: key → typer's English (a key in capitals: the typer.rich_utils constant of that name)
TYPER_WORDS = words("help_page", {
    "ARGUMENTS_PANEL_TITLE": "Arguments", "OPTIONS_PANEL_TITLE": "Options",
    "COMMANDS_PANEL_TITLE": "Commands", "DEFAULT_STRING": "[default: {}]",
    "REQUIRED_LONG_STRING": "[required]", "ENVVAR_STRING": "[env var: {}]",
    "DEPRECATED_STRING": "(deprecated) ", "usage": "Usage: ", "options": "[OPTIONS]",
    "command": "COMMAND [ARGS]..."})
