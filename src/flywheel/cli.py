"""The command line: thin wrappers that parse options, call the library, hand results to renderers.

Every user mistake becomes one line on stderr and exit code 2 (design.md §6).
"""
from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import typer

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    help="Dynamic analysis of machines: kinematics, reduction, flywheel sizing, true motion.",
    pretty_exceptions_enable=False,
)


def fail(message: str) -> None:
    """Print one line to stderr and exit 2 (bad input)."""
    sys.stderr.write(f"error: {message}\n")
    raise typer.Exit(code=2)


def _guard(func, *args, **kwargs):
    """Call func; turn a FlywheelError into one clear line and exit 2."""
    from flywheel.errors import FlywheelError

    try:
        return func(*args, **kwargs)
    except FlywheelError as exc:
        fail(str(exc))


@app.command()
def schema() -> None:
    """Print the JSON Schema of case files (for editors: completion and checking)."""
    import json

    from flywheel.case import case_json_schema

    typer.echo(json.dumps(case_json_schema(), indent=2, ensure_ascii=False))


@app.command()
def check(case: Path = typer.Argument(..., help="Case file (TOML).")) -> None:
    """Validate a case file and print what it describes; exit 0 if valid, 2 if not."""
    from flywheel.case import load_case
    from flywheel.render.check import print_check

    c = _guard(load_case, case)
    _guard(print_check, c)


def main() -> None:
    """Console-script entry point."""
    app()


if __name__ == "__main__":  # pragma: no cover
    main()
