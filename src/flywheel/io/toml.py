"""Reading a TOML case file: every failure becomes one CaseFileError line naming the file."""
from __future__ import annotations

import tomllib
from pathlib import Path

from flywheel.errors import CaseFileError


def read_toml(path, what: str = "a TOML case file") -> dict:
    """The parsed TOML document at ``path`` (UTF-8), or CaseFileError: no such file, a folder,
    not UTF-8, unreadable, or a syntax error with its line and column. ``what`` names the
    expected kind of file in the folder message."""
    path = Path(path)
    try:
        text = path.read_bytes().decode("utf-8-sig")   # a BOM (Windows editors) is no error
    except FileNotFoundError:
        raise CaseFileError(f"{path}: no such file") from None
    except IsADirectoryError:
        raise CaseFileError(f"{path}: is a folder, expected {what}") from None
    except UnicodeDecodeError as exc:
        raise CaseFileError(f"{path}: not UTF-8 text ({exc.reason} at byte {exc.start})") from None
    except OSError as exc:
        raise CaseFileError(f"{path}: cannot be read ({exc.strerror})") from None
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(f"{path}: TOML syntax error: {exc}") from None
