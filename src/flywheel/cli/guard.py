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
    """The user's ``--lang``: as the parser read it, else as the entry point found it among its
    arguments (an error may come before the option is parsed), else "en" (cli/options.py)."""
    from flywheel.cli.options import state

    return state.lang


def say_error(text: str, lead: str = "", tail: str = "") -> None:
    """Write the one error line to stderr in the user's --lang: «error:» / «ошибка:», ``lead``,
    the message (an errors.Notice with a Russian template is said in Russian, the rest as it
    is), ``tail``. Every error line of the command line is written here."""
    from flywheel.io.text import cut_echoes
    from flywheel.render.nomenclature import message as say, prefix

    ln = lang()
    line = say(text, ln)
    # the file and field path (the Notice's lead) whole; a value echoed after it cut to about
    # 80 characters (io.schema.cut_echoes), whatever message echoed it
    known = getattr(text, "lead", "")
    if ln == "ru":
        known = known.replace(": (top level): ", ": (верхний уровень): ")
    keep = len(known) if known and line.startswith(known) else 0
    line = line[:keep] + cut_echoes(line[keep:])
    sys.stderr.write(f"{prefix('error', ln)}: {lead}{line}{tail}\n")


def fail(message: str) -> None:
    """Print one line to stderr (:func:`say_error`) and exit 2 (bad input)."""
    say_error(message)
    raise typer.Exit(code=2)


def choice(option: str, got, what: str, allowed: str):
    """The error of an option's value that is not one of ``allowed``: "--csv: 'excel' is not a
    CSV dialect (allowed: plain, excel-ru)", an errors.Notice (said in Russian too)."""
    from flywheel.errors import Notice

    return Notice.of("option_choice", "{option}: {got} is not {what} (allowed: {allowed})",
                     option=option, got=repr(got), allowed=allowed, what=what)


def frame_notice(frame: str, lang: str, formats):
    """The Notice refusing ``--frame``: a value other than none and eskd, or the ЕСКД frame
    where it would draw nothing (it frames the Russian PDF and DOCX only); None if it applies."""
    from flywheel.errors import Notice
    from flywheel.render.choices import FRAMES

    if frame not in FRAMES:
        return choice("--frame", frame, "a page frame", ", ".join(FRAMES))
    if frame != "none" and (lang != "ru" or not {"pdf", "docx"} & set(formats or ())):
        return Notice.of(
            "frame_without_gost", "--frame {frame}: the frame is drawn on the Russian PDF and "
            "DOCX report only (allowed: with --lang ru and --report pdf or --report docx)",
            frame=frame)
    return None


def check_lang(lang: str) -> None:
    """Refuse a ``--lang`` that is not en or ru: one error line, exit 2 (every command)."""
    if lang not in ("en", "ru"):
        fail(choice("--lang", lang, "a language", "en, ru"))


def plot_failed(plot: Path, exc: Exception):
    """The error of a --plot image that cannot be written (task2, aggregate): the system's
    reason (an OSError, said in Russian by its errno) or matplotlib's (a format it does not
    know), an errors.Notice."""
    from flywheel.errors import Notice

    return Notice.of(
        "plot_cannot_write", "--plot {plot}: cannot write the image ({reason})", plot=str(plot),
        reason=str(exc), errno=getattr(exc, "errno", None),
        strerror=getattr(exc, "strerror", None))


def write_plot(plot: Path, draw) -> None:
    """The --plot image (task2, aggregate) whole or not at all: ``draw(path)`` draws into a
    temporary beside it, renamed into place (io.output.write_file_with); a format matplotlib
    does not know, or a file the system refuses, is one :func:`plot_failed` line."""
    from flywheel.errors import InputError
    from flywheel.io.output import write_file_with

    def draw_to(tmp):
        try:
            draw(tmp)
        except ValueError as exc:           # a format matplotlib does not know
            raise InputError(plot_failed(plot, exc)) from None

    write_file_with(plot, draw_to, "--plot", "an image file",
                    failed=lambda exc: plot_failed(plot, exc), make_folder=False)


def report_formats(report, out, frame: str, lang: str) -> list[str]:
    """The --report formats of task2, aggregate and duty-cycle, checked with --out and
    --frame: an InputError (one line) for a format it does not know, --report without --out,
    or a frame that cannot apply."""
    from flywheel.errors import InputError
    from flywheel.render.report_folder import check_formats

    formats = check_formats(report)
    if report and out is None:
        raise InputError(needs_out())
    refused = frame_notice(frame, lang, formats)
    if refused is not None:
        raise InputError(refused)
    return formats


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

    fail(Notice.of(
        "not_finite", "{who_lead}{quantity} is not finite ({detail}): the values overflow double "
        "precision (the numbers are too large or too small)", who=who, quantity=quantity,
        detail=detail, who_lead=who + ': ' if who else ''))


def refuse_nonfinite(document, who: str = "") -> None:
    """:func:`not_finite` for the first inf or NaN in a results document; nothing if none."""
    hit = first_nonfinite(document)
    if hit is not None:
        not_finite(hit[0], repr(hit[1]), who)


# |x| outside this range is a suspect when the results overflow double precision
_SANE = (1e-100, 1e100)


def _extreme(numbers: list[tuple[str, float]]) -> list[tuple[str, float]]:
    """The (name, value) pairs of extreme magnitude: the likely cause of an overflow."""
    return [(n, v) for n, v in numbers if v != 0 and not _SANE[0] <= abs(v) <= _SANE[1]]


def case_numbers(data, path: str = "") -> list[tuple[str, float]]:
    """(field path, number) of every number in a case's fields, e.g. ("driving.value", 1e308).

    >>> case_numbers({"a": {"b": [1, 2.5]}, "c": True, "d": "x"})
    [('a.b[0]', 1.0), ('a.b[1]', 2.5)]
    """
    out: list[tuple[str, float]] = []
    if isinstance(data, dict):
        for k, v in data.items():
            out += case_numbers(v, f"{path}.{k}" if path else str(k))
    elif isinstance(data, (list, tuple)):
        for i, v in enumerate(data):
            out += case_numbers(v, f"{path}[{i}]")
    elif isinstance(data, (int, float)) and not isinstance(data, bool):
        out.append((path, float(data)))
    return out


def solve_finite(run, blame: list[tuple[str, float]], case: Path | None = None):
    """``run()``'s result, refused by :func:`not_finite` when it overflows: a NotFiniteError of
    the solver, an arithmetic error, or an inf/NaN in its document. The line blames the inputs
    of extreme magnitude among ``blame`` — "file: field, field" for a case file (the file alone
    if none stands out), "--md 1e+308" for options (every given option if none stands out)."""
    from flywheel.constant_inertia.solve import NotFiniteError, python_detail
    from flywheel.errors import FlywheelError

    hit = None
    try:
        result = run()
        found = first_nonfinite(result.to_document())
        if found is not None:
            hit = (found[0], repr(found[1]))
    except NotFiniteError as exc:
        hit = (exc.quantity, exc.detail)
    except FlywheelError:
        raise
    except (ArithmeticError, ValueError) as exc:
        hit = ("a result", python_detail(f"{exc.args[-1] if exc.args else type(exc).__name__}"))
    if hit is None:
        return result
    if case is not None:
        fields = [n for n, _ in _extreme(blame)]
        who = f"{case}: {', '.join(fields)}" if fields else str(case)
    else:
        who = ", ".join(f"{n} {v:g}" for n, v in (_extreme(blame) or blame))
    not_finite(*hit, who=who)
