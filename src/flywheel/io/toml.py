"""Reading a TOML case file: every failure becomes one CaseFileError line naming the file."""
from __future__ import annotations

import tomllib
from pathlib import Path

from flywheel.errors import CaseFileError, Notice


def read_toml(path, what: str = "a TOML case file") -> dict:
    """The parsed TOML document at ``path`` (UTF-8), or CaseFileError: no such file, a folder,
    not UTF-8, unreadable, or a syntax error with its line and column. ``what`` names the
    expected kind of file in the folder message."""
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8-sig")   # a BOM (Windows editors) is no error
    except FileNotFoundError:
        raise CaseFileError(Notice.of(
            "no_such_file", "{path}: no such file", path=str(path))) from None
    except IsADirectoryError:
        raise CaseFileError(Notice.of(
            "is_a_folder", "{path}: is a folder, expected {what}", path=str(path), what=what
        )) from None
    except UnicodeDecodeError as exc:
        raise CaseFileError(Notice.of(
            "not_utf8", "{path}: not UTF-8 text ({reason} at byte {byte})", path=str(path),
            reason=exc.reason, byte=exc.start)) from None
    except OSError as exc:
        raise CaseFileError(Notice.of(
            "run_cannot_read", "{path}: cannot be read ({reason})", path=str(path),
            reason=exc.strerror, errno=exc.errno)) from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(Notice.of(
            "toml_syntax", "{path}: TOML syntax error: {detail}", path=str(path), detail=str(exc)
        )) from None
