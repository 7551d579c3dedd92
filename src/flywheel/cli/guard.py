"""The one error guard of the command line: a user's mistake becomes one `error:` line on
stderr and exit code 2 (design.md §6). Every command module imports it from here.

Two forms of the same guard: :func:`guard` calls a function, :func:`guarded` wraps a block
(``with guarded(source=path): ...``). One non-finite policy: a result that holds inf or NaN (inputs
near the limits of double precision) is refused by :func:`not_finite` with one line naming the
quantity, ``who: <quantity> is not finite (…): …``, exit 2; :func:`first_nonfinite` finds that
quantity in a results document (a result's ``to_document()``), which is exactly what would be
printed.
"""
from __future__ import annotations

import math
import sys
from contextlib import contextmanager
from pathlib import Path
from typing import Iterator, NoReturn

import typer


def lang() -> str:
    """The ``--lang`` of the command line: the running command's parsed option, else the raw
    arguments (an error may come before the option is parsed), else "en"."""
    from typer._click.globals import get_current_context

    ctx = get_current_context(silent=True)
    while ctx is not None:
        given = ctx.params.get("lang")
        if isinstance(given, str):
            return "ru" if given == "ru" else "en"
        ctx = ctx.parent
    argv = sys.argv[1:]
    for i, a in enumerate(argv):
        if a == "--lang" and i + 1 < len(argv):
            return "ru" if argv[i + 1] == "ru" else "en"
        if a.startswith("--lang="):
            return "ru" if a == "--lang=ru" else "en"
    return "en"


def say_error(text: str, lead: str = "", tail: str = "") -> None:
    """Write the one error line to stderr in the user's --lang: «error:» / «ошибка:», ``lead``,
    the message (an errors.Notice with a Russian template is said in Russian, the rest as it
    is), ``tail``. Every error line of the command line is written here."""
    from flywheel.render.messages import message as say, prefix

    ln = lang()
    sys.stderr.write(f"{prefix('error', ln)}: {lead}{say(text, ln)}{tail}\n")


def fail(message: str) -> None:
    """Print one line to stderr (:func:`say_error`) and exit 2 (bad input)."""
    say_error(message)
    raise typer.Exit(code=2)


def choice(option: str, got, what: str, allowed: str):
    """The error of an option's value that is not one of ``allowed``: "--csv: 'excel' is not a
    CSV dialect (allowed: plain, excel-ru)", an errors.Notice (said in Russian too)."""
    from flywheel.errors import Notice

    return Notice(f"{option}: {got!r} is not {what} (allowed: {allowed})", "option_choice",
                  option=option, got=repr(got), allowed=allowed)


def check_lang(lang: str) -> None:
    """Refuse a ``--lang`` that is not en or ru: one error line, exit 2 (every command)."""
    if lang not in ("en", "ru"):
        fail(choice("--lang", lang, "a language", "en, ru"))


def plot_failed(plot: Path, exc: Exception):
    """The error of a --plot image that cannot be written (task2, aggregate): the system's
    reason (an OSError, said in Russian by its errno) or matplotlib's (a format it does not
    know), an errors.Notice."""
    from flywheel.errors import Notice

    return Notice(f"--plot {plot}: cannot write the image ({exc})", "plot_cannot_write",
                  plot=str(plot), reason=str(exc), errno=getattr(exc, "errno", None),
                  strerror=getattr(exc, "strerror", None))


def needs_out():
    """The error of --report without --out (task2, aggregate, duty-cycle)."""
    from flywheel.errors import Notice

    return Notice.of(
        "report_needs_out", "--report writes into the output folder: give --out DIR as well")


def guard(func, *args, source: Path | None = None, case=None, **kwargs):
    """Call func; turn a FlywheelError into one clear line and exit 2. An error found while
    computing a valid ``case`` (a dyad that cannot be assembled, loads whose work has the wrong
    sign) is prefixed with the case file ``source`` and, where known, the field path."""
    from flywheel.errors import CaseFileError, FlywheelError, led, said

    try:
        return func(*args, **kwargs)
    except FlywheelError as exc:
        msg = said(exc)
        if source is not None and not isinstance(exc, CaseFileError) and not msg.startswith("--"):
            where = _field_of(exc, case)
            msg = led(f"{source}: {where}: " if where else f"{source}: ", msg)
        fail(msg)


@contextmanager
def guarded(source: Path | str | None = None, case=None) -> Iterator[None]:
    """:func:`guard` for a block: ``with guarded(source=path): ...`` turns a FlywheelError raised
    inside into one line and exit 2, prefixed with ``source`` the same way."""
    from flywheel.errors import FlywheelError

    try:
        yield
    except FlywheelError as exc:
        guard(_reraise, exc, source=source, case=case)


def _reraise(exc: Exception) -> NoReturn:
    raise exc


def _field_of(exc: Exception, case) -> str:
    """The case-file path of the dyad an AssemblyError names ('dyads[1]'), else ''."""
    from flywheel.cases.run import field_of

    return field_of(exc, case)


_guard = guard   # the name the command modules used before the package split


def first_nonfinite(document, path: str = "") -> tuple[str, float] | None:
    """(path, value) of the first inf or NaN number in a results document, in the document's
    order, e.g. ``("omega_max", inf)``, ``("rpm.omega0", inf)``, ``("segments[3].A", nan)``;
    None when every number is finite (None, strings and booleans are no numbers).

    >>> first_nonfinite({"a": 1.0, "b": [{"c": 2.0}, {"c": float("inf")}], "d": float("nan")})
    ('b[1].c', inf)
    >>> first_nonfinite({"a": None, "b": "text", "c": True}) is None
    True
    """
    if isinstance(document, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in document.items())
    elif isinstance(document, (list, tuple)):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(document))
    else:
        if isinstance(document, float) and not math.isfinite(document):
            return path, document
        return None
    for where, v in items:
        hit = first_nonfinite(v, where)
        if hit is not None:
            return hit
    return None


def not_finite(quantity: str, detail: str, who: str = "") -> NoReturn:
    """The one non-finite policy: ``error: who: <quantity> is not finite (detail): …``, exit 2.

    ``who`` names the inputs to blame (the case file and its fields, or the options given)."""
    from flywheel.errors import Notice

    fail(Notice(f"{who + ': ' if who else ''}{quantity} is not finite ({detail}): the values "
                "overflow double precision (the numbers are too large or too small)",
                "not_finite", who=who, quantity=quantity, detail=detail))


def refuse_nonfinite(document, who: str = "") -> None:
    """:func:`not_finite` for the first inf or NaN in a results document; nothing if none."""
    hit = first_nonfinite(document)
    if hit is not None:
        not_finite(hit[0], repr(hit[1]), who)
