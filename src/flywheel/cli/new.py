"""`flywheel new KIND [FILE]`: write a commented starter case that runs as written.

The template is package data (:mod:`flywheel.cases.starter`); the file is created whole or not
at all and never over an existing one (issue 23: nothing of the user's is lost): it is written
to a temporary beside FILE and hard-linked into place, which fails if FILE has appeared in the
meantime; where the system has no hard links it is created exclusively (O_EXCL).
"""
from __future__ import annotations

import errno
import os
import tempfile
from pathlib import Path
from typing import Annotated, Optional

import typer

from flywheel.cli.options import Lang, Quiet, state


Kind = Annotated[str, typer.Argument(
    metavar="KIND", help="What to start: slider-crank, v-compressor, four-bar, slotted-link, shaper, engine, "
    "task2, aggregate, duty-cycle.")]
File = Annotated[Optional[Path], typer.Argument(
    metavar="FILE", help="The case file to write (default: KIND.toml here); never written over if it exists.")]


def new_command(kind: Kind, file: File = None, lang: Lang = "en", quiet: Quiet = False) -> None:
    """Write a commented starter case of KIND that runs as written; its comments (in --lang)
    say which lines to change for your own variant."""
    from flywheel.cases.starter import KINDS, starter_text
    from flywheel.cli.guard import check_lang, choice, fail, guard
    from flywheel.render.nomenclature import prefix

    check_lang(lang)
    if kind not in KINDS:
        fail(choice("KIND", kind, "a kind of starter case", ", ".join(KINDS)))
    path = Path(file) if file is not None else Path(f"{kind}.toml")
    guard(create_new, path, starter_text(kind, lang))
    command = KINDS[kind][1]
    run = f"flywheel {command} {'--case ' if command == 'task2' else ''}{path}"
    if not state.quiet:
        typer.echo(f"{prefix('written', lang)}: {path} ({run})")


def create_new(path: Path, text: str) -> None:
    """Create ``path`` holding ``text`` (UTF-8), whole or not at all; InputError (one line) if
    anything stands at ``path`` already (a file, a folder, a link, even a dangling one) or the
    system refuses."""
    from flywheel.errors import InputError, Notice
    from flywheel.io.output import cannot_write

    def exists():
        return InputError(Notice.of(
            "new_exists", "{path}: already exists; flywheel new never writes over a file (give "
            "another file name, or move that one away)", path=str(path)))

    if os.path.lexists(path):
        raise exists()
    data = text.encode("utf-8")
    parent = path.parent if str(path.parent) else Path(".")
    tmp = None
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.tmp-{os.getpid()}-", dir=parent)
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.chmod(tmp, 0o644)
        try:
            os.link(tmp, path)                     # fails if path exists: never replaces it
        except FileExistsError:
            raise exists() from None
        except OSError as exc:
            if exc.errno not in (errno.EPERM, errno.ENOTSUP, errno.EOPNOTSUPP, errno.EXDEV,
                                 errno.EMLINK):
                raise
            fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o644)
            try:
                with os.fdopen(fd, "wb") as f:
                    f.write(data)
            except BaseException:
                os.unlink(path)
                raise
    except FileExistsError:
        raise exists() from None
    except OSError as exc:
        raise InputError(cannot_write("FILE", path, exc)) from None
    finally:
        if tmp is not None and os.path.lexists(tmp):
            os.unlink(tmp)
