"""The one error guard of the command line: a user's mistake becomes one `error:` line on
stderr and exit code 2 (design.md §6). Every command module imports it from here."""
from __future__ import annotations

import sys
from pathlib import Path

import typer


def fail(message: str) -> None:
    """Print one line to stderr and exit 2 (bad input)."""
    sys.stderr.write(f"error: {message}\n")
    raise typer.Exit(code=2)


def guard(func, *args, source: Path | None = None, case=None, **kwargs):
    """Call func; turn a FlywheelError into one clear line and exit 2. An error found while
    computing a valid ``case`` (a dyad that cannot be assembled, loads whose work has the wrong
    sign) is prefixed with the case file ``source`` and, where known, the field path."""
    from flywheel.errors import CaseFileError, FlywheelError

    try:
        return func(*args, **kwargs)
    except FlywheelError as exc:
        msg = str(exc)
        if source is not None and not isinstance(exc, CaseFileError) and not msg.startswith("--"):
            where = _field_of(exc, case)
            msg = f"{source}: {where}: {msg}" if where else f"{source}: {msg}"
        fail(msg)


def _field_of(exc: Exception, case) -> str:
    """The case-file path of the dyad an AssemblyError names ('dyads[1]'), else ''."""
    from flywheel.cases.run import dyad_name

    dyad = getattr(exc, "dyad", None)
    if dyad is None or case is None:
        return ""
    return next((f"dyads[{i}]" for i, d in enumerate(case.dyads) if dyad_name(d) == dyad), "")


_guard = guard   # the name the command modules used before the package split
