"""Reading a JSON file within stated limits: the one check of every JSON flywheel reads (the
answers.json key of ``grade``, the manifest of an output folder).

Limits, checked before or while parsing, so no reader meets a recursion or a number it cannot
convert:

* nesting: at most :data:`MAX_DEPTH` levels of ``[]`` and ``{}`` (counted on the text without
  recursion, before json parses it; the deepest JSON flywheel writes has 3);
* integers: at most :data:`MAX_DIGITS` digits (a float holds at most 309; Python's int()
  refuses 4300 and more);
* size: ``max_bytes`` if the caller gives one (the file is refused before it is read whole).

Failures are exceptions for the caller to say in its own words: OSError (cannot be read, or
larger than ``max_bytes``: :class:`JsonTooLarge`), UnicodeDecodeError, json.JSONDecodeError,
:class:`JsonTooDeep`, :class:`JsonNumberTooLong`.
"""
from __future__ import annotations

import json
import os
import re
import stat

#: the deepest nesting of [] and {} in a JSON file flywheel reads (answers.json has 3 levels)
MAX_DEPTH = 64
#: the longest integer in a JSON file flywheel reads (a float holds at most 309 digits)
MAX_DIGITS = 400

_STRING_OR_BRACKET = re.compile(r'"(?:[^"\\]|\\.)*"?|[\[\]{}]')


class JsonTooDeep(ValueError):
    """JSON text nested deeper than MAX_DEPTH (``depth``: how deep it goes)."""

    def __init__(self, depth: int):
        super().__init__(f"nested {depth} levels deep (allowed: up to {MAX_DEPTH})")
        self.depth = depth


class JsonNumberTooLong(ValueError):
    """An integer of more than MAX_DIGITS digits (``digits``: how many)."""

    def __init__(self, digits: int):
        super().__init__(f"an integer of {digits} digits (allowed: up to {MAX_DIGITS})")
        self.digits = digits


class JsonTooLarge(OSError):
    """A file larger than the caller's ``max_bytes``."""


def json_depth(text: str) -> int:
    """The deepest nesting of [] and {} in JSON text, counted without recursion (brackets
    inside strings skipped; unbalanced text is json's to refuse).

    >>> json_depth('{"a": [1, {"b": "[[["}]}'), json_depth("[]" * 3), json_depth("1")
    (3, 1, 0)
    """
    depth = top = 0
    for m in _STRING_OR_BRACKET.finditer(text):
        c = m.group()
        if c in "[{":
            depth += 1
            top = max(top, depth)
        elif c in "]}":
            depth -= 1
    return top


def _int(text: str) -> int:
    """json's parse_int: more than MAX_DIGITS digits refused before Python's int()."""
    digits = len(text.lstrip("-"))
    if digits > MAX_DIGITS:
        raise JsonNumberTooLong(digits)
    return int(text)


def parse_json(text: str):
    """The JSON document in ``text`` within the limits (see the module's docstring)."""
    depth = json_depth(text)
    if depth > MAX_DEPTH:
        raise JsonTooDeep(depth)
    try:
        return json.loads(text, parse_int=_int)
    except RecursionError:                  # json_depth bounds the nesting: not reached
        raise JsonTooDeep(depth) from None


def read_json(path, *, follow_links: bool = True, max_bytes: int | None = None):
    """The JSON document in the UTF-8 file ``path`` (a BOM allowed) within the limits (see
    the module's docstring). ``follow_links=False``: a symbolic link is refused (OSError), as
    is anything but a regular file."""
    flags = os.O_RDONLY | (0 if follow_links else getattr(os, "O_NOFOLLOW", 0))
    fd = os.open(path, flags)
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise IsADirectoryError(21, "Is a directory", str(path))
        if not follow_links and not stat.S_ISREG(st.st_mode):
            raise OSError(f"{path}: not a regular file")
        if max_bytes is not None and st.st_size > max_bytes:
            raise JsonTooLarge(f"{path}: larger than {max_bytes} bytes")
        chunks = []
        size = 0
        while chunk := os.read(fd, 1 << 20):
            size += len(chunk)
            if max_bytes is not None and size > max_bytes:
                raise JsonTooLarge(f"{path}: larger than {max_bytes} bytes")
            chunks.append(chunk)
    finally:
        os.close(fd)
    return parse_json(b"".join(chunks).decode("utf-8-sig"))
