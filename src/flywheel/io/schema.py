"""One line from a pydantic ValidationError: the field path as a case file spells it, what is
wrong, what is allowed. Shared by the case loaders (case.py, task2_case.py, aggregate_case.py).
"""
from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Iterable

# pydantic puts the member of a union it tried into the location ('float', 'list[float]', …):
# not a key of the file
_MEMBER = re.compile(r"^(float|int|str|bool|none|(list|dict|tuple|set)\[.*\]|"
                     r"(constrained|function)-.*|nullable\[.*\])$")


def loc_str(loc: Iterable) -> str:
    """('cylinders', 0, 'bore') -> 'cylinders[0].bore'."""
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part}]"
        else:
            out += ("." if out else "") + str(part)
    return out or "(top level)"


def clean_loc(loc: Iterable, drop: Iterable[str] = ()) -> tuple:
    """The location without union-member tags and without the ``drop`` tags (a dyad's kind)."""
    drop = set(drop)
    return tuple(p for p in loc if isinstance(p, int) or (p not in drop and not _MEMBER.match(p)))


def pick(errors: list[dict], drop: Iterable[str] = ()) -> dict:
    """The error to report: a misspelt key first (it also makes the right key 'missing'), else
    the deepest one (for ``float | list[float]`` given a list, the list member's error names
    the entry), the first of equals."""
    for e in errors:
        if e["type"] == "extra_forbidden":
            return e
    return max(errors, key=lambda e: len(clean_loc(e["loc"], drop)))


def describe(err: dict, allowed: Callable[[tuple], list[str]], drop: Iterable[str] = (),
             messages: dict[str, str] | None = None) -> str:
    """'field.path: what is wrong (got …)'. ``allowed(loc)`` lists the keys valid in the table at
    ``loc`` (the raw pydantic location) for an unknown key; ``messages`` replaces the text of an
    error type ({'greater_than': 'must be positive'})."""
    loc = clean_loc(err["loc"], drop)
    kind, msg = err["type"], err["msg"]
    where = loc_str(loc)
    got = err.get("input")
    got_s = f" (got {got!r})" if not isinstance(got, (dict, list)) else ""
    if kind == "extra_forbidden":
        key = str(loc[-1])
        keys = allowed(tuple(err["loc"][:-1]))
        lower = {a.lower(): a for a in keys}
        near = difflib.get_close_matches(key.lower(), list(lower), n=1)
        hint = f"; did you mean {lower[near[0]]!r}?" if near else ""
        return f"{where}: unknown key{hint} (allowed: {', '.join(keys)})"
    if kind == "missing":
        return f"{where}: missing required field"
    if kind == "finite_number":
        return f"{where}: must be a finite number{got_s}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return f"{where}: must be a table of keys, e.g. {{ key = value, … }}{got_s}"
    if kind == "value_error":
        return f"{where}: {msg.removeprefix('Value error, ')}"
    if messages and kind in messages:
        return f"{where}: {messages[kind]}{got_s}"
    return f"{where}: {msg[0].lower() + msg[1:]}{got_s}"
