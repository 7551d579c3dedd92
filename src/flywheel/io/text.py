"""Cutting what an error line or a terminal summary echoes: a value, a title, a field path of a
huge input is shown cut to about 80 characters with «…», never whole (issue 23). No imports of
the package: io.schema and io.toml both use it."""
from __future__ import annotations

import re

#: the longest echo of a given value in an error line [characters]
ECHO = 80


def cut(text: str, width: int = ECHO) -> str:
    """``text`` cut to at most ``width`` characters with «…» in the middle (its start and its
    end both shown), unchanged when it fits: an error line echoes a bad value this way.

    >>> cut("a" * 10 + "b" * 10, 9)
    'aaaa…bbbb'
    >>> cut("short")
    'short'
    """
    text = str(text)
    if len(text) <= width:
        return text
    head = (width - 1) // 2
    return text[:head] + "…" + text[len(text) - (width - 1 - head):]


def cut_end(text: str, width: int = 1000) -> str:
    """``text`` cut to at most ``width`` characters with «…» at the end: a title or source on
    the terminal (a case's are refused beyond 1000 characters; this catches what reaches a
    summary another way, e.g. through the library)."""
    text = str(text)
    return text if len(text) <= width else text[:width - 1] + "…"


def cut_echoes(line: str, width: int = ECHO) -> str:
    """Every run of more than ``width`` characters without a space in ``line`` cut to ``width``
    (:func:`cut`; a file path, a run with a slash and no quote, only beyond ``5·width``), and a
    line still longer than ``12·width`` cut in its middle: no error line echoes a huge value
    whole, whatever formatted it.

    >>> cut_echoes("x: got '" + "7" * 500 + "' (allowed: 0 … 1)", 20)
    "x: got '77777777…777777777' (allowed: 0 … 1)"
    """
    def one(m) -> str:
        run = m.group(0)
        path = "/" in run and not any(q in run for q in "'\"")
        return cut(run, 5 * width if path else width)

    out = re.sub(r"\S{%d,}" % (width + 1), one, line)
    return cut(out, 12 * width)


class Text(str):
    """A title or source given in both languages: the string is the English text (what the
    JSON documents and every English output carry), ``ru`` the Russian. A plain string in a
    case is both (a :class:`str`, not a Text)."""

    def __new__(cls, en: str, ru: str) -> "Text":
        obj = super().__new__(cls, en)
        obj.ru = ru
        return obj

    def __reduce__(self):                    # pickled whole into the plotting processes
        return (Text, (str(self), self.ru))


def in_language(text, lang: str) -> str:
    """``text`` (a title or source: a :class:`Text` or a plain string) in ``lang`` ("en"/"ru")
    as a plain string; a plain string is the same in both."""
    if lang == "ru" and isinstance(text, Text):
        return text.ru
    return str(text)
