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
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise CaseFileError(Notice.of(
            "toml_syntax", "{path}: TOML syntax error: {detail}", path=str(path), detail=str(exc)
        )) from None
    except RecursionError:      # tomllib parses nested arrays and tables by recursion
        raise too_deep(path) from None
    except ValueError as exc:   # Python's limit on the digits of an int (4300)
        raise too_long_number(path, str(exc)) from None
    check_document(doc, path)
    return doc


#: the deepest nesting of tables and arrays a case file may have (the deepest bundled case: 4)
MAX_DEPTH = 32
#: the largest integer a case file may give: TOML's own (64-bit signed)
INT_MIN, INT_MAX = -2 ** 63, 2 ** 63 - 1


def too_deep(path, where: str = "") -> CaseFileError:
    """The error of a document nested deeper than MAX_DEPTH (or than the parser can go)."""
    from flywheel.io.text import cut

    where = cut(where)
    at = f"{where}: " if where else ""
    return CaseFileError(Notice.of(
        "doc_too_deep", "{path}: {at}tables and arrays nested too deep (allowed: at most {most} "
        "levels)", path=str(path), where=where, most=MAX_DEPTH, at=at))


def too_long_number(path, detail: str = "", where: str = "") -> CaseFileError:
    """The error of an integer beyond 64 bits (or beyond Python's limit of digits)."""
    at = f"{where}: " if where else ""
    return CaseFileError(Notice.of(
        "doc_number_too_long", "{path}: {at}an integer too long (allowed: {lo} … {hi}, TOML's "
        "64-bit integers; write a larger number as a float, e.g. 1e30)", path=str(path),
        where=where, lo=INT_MIN, hi=INT_MAX, at=at))


def check_document(doc, path) -> None:
    """Refuse a parsed document (TOML or JSON) nested deeper than MAX_DEPTH or holding an
    integer outside 64 bits, naming the place: no later reader (pydantic, a recursive walk of
    the results) meets a recursion or an integer it cannot convert. Iterative: the check
    itself cannot recurse too deep."""
    def loc_str(loc: tuple) -> str:     # ('a', 0, 'b') -> 'a[0].b', as io.schema writes it
        out = ""
        for part in loc:
            out += f"[{part}]" if isinstance(part, int) else ("." if out else "") + str(part)
        return out

    todo = [(doc, (), 0)]
    while todo:
        node, loc, depth = todo.pop()
        if isinstance(node, dict):
            items = node.items()
        elif isinstance(node, list):
            items = enumerate(node)
        else:
            if isinstance(node, int) and not isinstance(node, bool) \
                    and not INT_MIN <= node <= INT_MAX:
                raise too_long_number(path, where=loc_str(loc))
            continue
        if depth >= MAX_DEPTH:
            raise too_deep(path, loc_str(loc))
        todo.extend((v, (*loc, k), depth + 1) for k, v in items)
