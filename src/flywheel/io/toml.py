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
        raise CaseFileError(not_utf8(path, exc)) from None
    except OSError as exc:
        raise CaseFileError(Notice.of(
            "run_cannot_read", "{path}: cannot be read ({reason})", path=str(path),
            reason=exc.strerror, errno=exc.errno)) from None
    try:
        doc = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        given = decimal_comma(text, str(exc))
        if given:                   # «delta = 0,05»: the Russian decimal comma
            raise CaseFileError(Notice.of(
                "toml_decimal_comma", "{path}: TOML syntax error: {detail}: a number takes a "
                "decimal point: {fixed}, not {given}", path=str(path), detail=str(exc),
                given=given, fixed=given.replace(",", "."))) from None
        raise CaseFileError(Notice.of(
            "toml_syntax", "{path}: TOML syntax error: {detail}", path=str(path), detail=str(exc)
        )) from None
    except RecursionError:      # tomllib parses nested arrays and tables by recursion
        raise too_deep(path) from None
    except ValueError as exc:   # Python's limit on the digits of an int (4300)
        raise too_long_number(path, str(exc)) from None
    check_document(doc, path)
    return doc


def decimal_comma(text: str, detail: str) -> str:
    """The number written with a decimal comma («0,05», «−9,81») on the line a TOML syntax error
    ``detail`` names («… (at line 11, column 14)»), where that is what the error is; else ""."""
    import re

    at = re.search(r"at line (\d+), column (\d+)", detail)
    lines = text.splitlines()
    if not at or not 0 < int(at.group(1)) <= len(lines):
        return ""
    line = lines[int(at.group(1)) - 1].split("#", 1)[0]
    number = re.search(r"(?<![\w.])[-+]?\d+,\d+(?![\w.])", line)
    return number.group(0) if number else ""


def comma_in_array(text: str, key: str = "") -> tuple[str, int]:
    """A number of an array in the TOML ``text`` that looks written with a decimal comma, and
    its line (from 1): «gravity = [0.0, -9,81]» parses as three numbers, 0.0, −9 and 81, and
    the case then fails as too long a list, or a list not increasing; ("", 0) when there is
    none. ``key``: only the array assigned to that key, else any. The array may run over
    several lines; comments are skipped. A digit, a comma and a digit with no space between
    («-9,81») is the sign: TOML's own style puts a space after a comma."""
    import re

    lines = text.splitlines()
    name = re.escape(key) if key else r"[\w-]+"
    head = re.compile(r'(?:^|[{,\s])"?' + name + r'"?\s*=\s*\[')
    comma = re.compile(r"(?<![\w.])[-+]?\d+,\d+(?![\w.])")
    for i, line in enumerate(lines):
        at = head.search(line.split("#", 1)[0])
        if not at:
            continue
        depth = 0
        for n, part in enumerate([line.split("#", 1)[0][at.end() - 1:]] + [
                ln.split("#", 1)[0] for ln in lines[i + 1:i + 1 + MAX_ARRAY_LINES]]):
            for j, ch in enumerate(part):
                depth += (ch == "[") - (ch == "]")
                if depth == 0:
                    part = part[:j]
                    break
            number = comma.search(part)
            if number:
                return number.group(0), i + 1 + n
            if depth == 0:
                break
    return "", 0


#: the lines an array of a case file is followed over when looking for a decimal comma in it
MAX_ARRAY_LINES = 200


#: the encodings a text file that is not UTF-8 is told to be in (a Windows or DOS editor's
#: Russian text, a Unicode file with its byte-order mark): charset-normalizer's codec → the name
#: said; each a TOML file must be saved again as UTF-8 to be read (TOML 1.0: "A TOML file must be
#: a valid UTF-8 encoded Unicode document")
OTHER_ENCODINGS = {"utf_16": "UTF-16", "utf_32": "UTF-32", "cp1251": "Windows-1251",
                   "cp866": "DOS (cp866)", "koi8_r": "KOI8-R"}
#: a file's first bytes from which its encoding is guessed
GUESS_BYTES = 1 << 16


def not_utf8(path, exc: UnicodeDecodeError) -> Notice:
    """The notice of a text file that is not UTF-8: the encoding it is in where a Unicode
    byte-order mark or charset-normalizer's guess (on its first GUESS_BYTES, decoding as TOML
    text: an "=" on a line) tells one of OTHER_ENCODINGS, else the first byte that is not
    part of a UTF-8 character; with what to do, save it as UTF-8."""
    data = exc.object[:GUESS_BYTES]
    name = None
    if data.startswith((b"\xff\xfe\x00\x00", b"\x00\x00\xfe\xff")):
        name = "UTF-32"
    elif data.startswith((b"\xff\xfe", b"\xfe\xff")):
        name = "UTF-16"
    elif b"\x00" not in data:
        from charset_normalizer import from_bytes

        best = from_bytes(data, cp_isolation=[c for c in OTHER_ENCODINGS if c.startswith(
            ("cp", "koi"))]).best()
        if best is not None and "=" in str(best):
            name = OTHER_ENCODINGS.get(best.encoding)
    if name is not None:
        return Notice.of("not_utf8_encoding", "{path}: not UTF-8 text but {encoding} (allowed: "
                         "UTF-8 only; save the file again as UTF-8)",
                         path=str(path), encoding=name)
    return Notice.of("not_utf8", "{path}: not UTF-8 text (byte {byte} is not part of a UTF-8 "
                     "character; allowed: a text file saved as UTF-8)", path=str(path),
                     byte=exc.start)


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
