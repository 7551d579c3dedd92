"""Starter cases (`flywheel new KIND`): a commented case file of each kind that runs as
written and says in its comments which lines to change for one's own variant.

The templates are package data (``flywheel/cases/templates/<kind>.toml``), one file for both
languages: a whole-line comment ``#en …`` or ``#ru …`` is kept for its language only, and an
inline comment ``#en … #ru …`` keeps the part of the language asked for; every kept comment
is an ordinary ``# …``.
"""
from __future__ import annotations

from importlib import resources

#: kind → (its template's file, the command that runs it)
KINDS: dict[str, tuple[str, str]] = {
    "slider-crank": ("slider-crank.toml", "run"),
    "v-compressor": ("v-compressor.toml", "run"),
    "four-bar": ("four-bar.toml", "run"),
    "slotted-link": ("slotted-link.toml", "run"),
    "shaper": ("shaper.toml", "run"),
    "engine": ("engine.toml", "run"),
    "task2": ("task2.toml", "task2"),
    "aggregate": ("aggregate.toml", "aggregate"),
    "duty-cycle": ("duty-cycle.toml", "duty-cycle"),
}


def localize(text: str, lang: str) -> str:
    """``text`` with the comments of ``lang`` ("en" or "ru") kept as plain ``#`` comments and
    the other language's dropped.

    >>> localize('x = 1  #en one #ru один\\n#en note\\n#ru заметка\\n', "ru")
    'x = 1  # один\\n# заметка\\n'
    """
    other = "#ru" if lang == "en" else "#en"
    own = "#" + lang
    out = []
    for line in text.splitlines(keepends=True):
        bare = line.lstrip()
        end = "\n" if line.endswith("\n") else ""
        if bare.startswith(other):
            continue
        if bare.startswith(own):
            out.append(line.replace(own, "#", 1))
            continue
        code, mark, rest = line.partition(" #en ")
        if mark:
            en, _, ru = rest.rstrip("\n").partition(" #ru ")
            out.append(f"{code} # {(en if lang == 'en' else ru).strip()}{end}")
            continue
        out.append(line)
    return "".join(out)


def starter_text(kind: str, lang: str = "en") -> str:
    """The starter case of ``kind`` (a key of :data:`KINDS`) with comments in ``lang``."""
    name = KINDS[kind][0]
    text = resources.files("flywheel.cases").joinpath("templates", name).read_text(encoding="utf-8")
    return localize(text, lang)
