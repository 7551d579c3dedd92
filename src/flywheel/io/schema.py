"""Case files' schemas: one strict pydantic base model, one field-path error, one loader and one
error formatter, shared by every case kind (flywheel.cases.run, .tabulated, .task2, .aggregate).

A problem becomes one line: ``file: field.path: what is wrong (what is allowed)``.
"""
from __future__ import annotations

import difflib
import math
import re
from collections.abc import Callable, Iterable
from pathlib import Path
from typing import TypeVar

from pydantic import BaseModel, ConfigDict, ValidationError

from flywheel.errors import CaseFileError, Notice, led, said
from flywheel.io.text import ECHO, cut, cut_echoes, cut_end  # noqa: F401  (the formatter's)
from flywheel.io.text import Text, in_language  # noqa: F401  (a title or source in two languages)


class StrictModel(BaseModel):
    """The base of every case-file table: unknown keys, NaN, infinity, quoted numbers and
    ``true`` for a number are errors; a field with an alias (``from``) also takes its name."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, strict=True,
                              populate_by_name=True)


class FieldError(ValueError):
    """A problem found by a check that spans fields: ``loc`` is the field path, as a tuple
    (``("cylinders", 0, "piston")``) or a dotted string (``"motor.J"``). ``msg`` may be an
    errors.Notice (said in the user's --lang)."""

    def __init__(self, loc: tuple | str, msg: str):
        super().__init__(msg)
        self.loc = loc

    @property
    def where(self) -> str:
        """The field path as the file spells it ('' at the top level)."""
        if isinstance(self.loc, str):
            return self.loc
        return loc_str(self.loc) if self.loc else ""


def within(lo: float, hi: float, unit: str = ""):
    """A pydantic validator refusing values outside [lo, hi] with the range and unit in the
    message: numbers are checked where they enter, in a physically meaningful range, so nothing
    overflows later in the arithmetic (issue 17)."""
    from pydantic import AfterValidator

    def check(v):
        vals = v if isinstance(v, (tuple, list)) else (v,)
        for x in vals:
            if isinstance(x, (int, float)) and not lo <= x <= hi:
                u = f" {unit}" if unit else ""
                raise ValueError(Notice.of(
                    "out_of_range", "{x:g}{unit_shown} is out of range (allowed: {lo:g} … "
                    "{hi:g}{unit_shown})", x=x, lo=lo, hi=hi, unit=unit, unit_shown=u))
        return v
    return AfterValidator(check)


#: the longest title, source, note or name a case may give [characters]
MAX_TEXT = 1000

def at_most(n: int, what: str):
    """A pydantic validator (run before the items are validated) refusing a list of more than
    ``n`` items in one line: "has 100001 points (allowed: at most 100000)"."""
    from pydantic import BeforeValidator

    def check(v):
        if isinstance(v, (list, tuple)) and len(v) > n:
            raise ValueError(Notice.of(
                "too_many_items", "has {count} {items} (allowed: at most {most})", count=len(v),
                items=what, most=n))
        return v
    return BeforeValidator(check)


def text_field(default: str = "", description: str = ""):
    """A title, source, note or name: a string of at most MAX_TEXT characters, refused in one
    line beyond (its value not echoed whole)."""
    from pydantic import Field

    return Field(default, max_length=MAX_TEXT, description=description)


_LANGS = ("ru", "en")


def title_field(default: str = "", description: str = ""):
    """A title or source: a string of at most MAX_TEXT characters, or a table
    ``{ ru = "…", en = "…" }`` of two (a :class:`Text`); anything else refused in one line.
    Use as ``title: TitleText = title_field(…)``."""
    from pydantic import Field

    return Field(default, max_length=MAX_TEXT, description=description)


def _title_text(value, handler):
    """The WrapValidator of :data:`TitleText`: a string through pydantic's own check (type and
    length), a table's two strings likewise, joined into a :class:`Text`."""
    if isinstance(value, dict):
        if set(value) != set(_LANGS):
            raise ValueError(Notice.of(
                "text_languages", "a table of a title or source has the keys {got} (allowed: a "
                "string, or exactly ru and en: {{ ru = \"…\", en = \"…\" }})",
                got=", ".join(sorted(map(str, value))) or "none"))
        return Text(handler(value["en"]), handler(value["ru"]))
    return handler(value)


def _title_schema():
    from typing import Annotated

    from pydantic import WithJsonSchema, WrapValidator

    text = {"type": "string", "maxLength": MAX_TEXT}
    return Annotated[str, WrapValidator(_title_text), WithJsonSchema({
        "anyOf": [text, {"type": "object", "properties": {k: text for k in _LANGS},
                         "required": list(_LANGS), "additionalProperties": False}],
        "description": "a string, or the text in both languages: { ru = \"…\", en = \"…\" }"})]


#: the type of a case's title and source (every case kind): a string or { ru = "…", en = "…" }
TitleText = _title_schema()

M = TypeVar("M", bound=BaseModel)


def validate(data, model: type[M], source: str, describe_error: Callable[[list[dict]], str],
             check: Callable[[M], object] | None = None, context: dict | None = None) -> M:
    """``model`` validated from a parsed document, else one CaseFileError line naming ``source``.

    ``describe_error(errors)`` words pydantic's errors (the case kind knows its tags and keys);
    a FieldError raised inside a model validator keeps its own path below the model's; a
    FieldError from ``check(model)`` (checks that span tables) names its path. ``context``:
    pydantic's validation context, for a table whose checks depend on another (a [tabulated]
    table covers the machine's cycle)."""
    try:
        obj = model.model_validate(data, context=context)
    except ValidationError as exc:
        errs = exc.errors()
        for e in errs:
            ctx = e.get("ctx", {}).get("error")
            if isinstance(ctx, FieldError) and isinstance(ctx.loc, tuple):
                raise CaseFileError(led(f"{source}: {loc_str(e['loc'] + ctx.loc)}: ",
                                        said(ctx))) from None
        raise CaseFileError(led(f"{source}: ", describe_error(errs))) from None
    if check is not None:
        try:
            check(obj)
        except FieldError as exc:
            raise CaseFileError(led(f"{source}: {exc.where + ': ' if exc.where else ''}",
                                    said(exc))) from None
    return obj


def load(path, parse: Callable[[dict, str], M], what: str = "a TOML case file") -> M:
    """Read the TOML file at ``path`` and hand it to ``parse(data, source)`` (a case kind's
    ``parse_*``): the one way every case file is loaded."""
    from flywheel.io.toml import read_toml

    data = read_toml(path, what)
    try:
        return parse(data, str(path))
    except CaseFileError as exc:
        hinted = _comma_hint(path, said(exc))
        if hinted is None:
            raise
        raise CaseFileError(hinted) from None


def _comma_hint(path, error: str) -> str | None:
    """``error`` (a field's error in the case file at ``path``) with a hint when an array of the
    file holds a number written with a decimal comma («[0.0, -9,81]»: three numbers to TOML,
    so "too many items"), the field's own array first; None when none does."""
    from flywheel.io.toml import comma_in_array

    lead = getattr(error, "lead", "")
    if not getattr(error, "code", ""):
        return None
    try:
        text = Path(path).read_bytes().decode("utf-8-sig")
    except (OSError, UnicodeDecodeError):
        return None
    keys = re.findall(r"(?:^|\.)([A-Za-z_][\w-]*)(?:\[\d+\])*$", lead.rstrip(": ").split(": ")[-1])
    given, line = comma_in_array(text, keys[-1]) if keys else ("", 0)
    if not given:
        given, line = comma_in_array(text)
    if not given:
        return None
    what = Notice(str(error)[len(lead):], error.code, **error.params)
    what.template = error.template
    return led(lead, Notice.of(
        "comma_in_array", "{what}; if {given} on line {line} is one number written with a "
        "decimal comma, write it with a point: {fixed}", what=what, given=given, line=line,
        fixed=given.replace(",", ".")))


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
            out += ("." if out else "") + cut(str(part))
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
    error type ({'greater_than': 'must be positive'}). An errors.Notice: the field path is its
    ``lead``, the code the kind of problem (pydantic's own types as "pydantic_<type>")."""
    text = _describe(err, allowed, drop, messages)
    where = loc_str(clean_loc(err["loc"], drop))
    if isinstance(text, Notice):
        return text
    got = err.get("input")
    kind = err["type"]
    ctx = {k: v for k, v in (err.get("ctx") or {}).items() if isinstance(v, (int, float, str))}
    code = "pydantic_" + kind
    if kind == "missing":
        code = "missing"
    elif kind in ("model_type", "model_attributes_type", "dict_type"):
        code = "not_a_table"
    elif kind == "finite_number":
        code = "not_finite_number"
    out = Notice(text[len(where) + 2:], code, got=cut(repr(got)) if not isinstance(got, (dict, list))
                 else "", **ctx)
    return led(f"{where}: ", out)


def _as_number(text: str) -> str:
    """A number written as a string («0,05», "10", «−9,81»), as TOML writes it ("0.05", "10",
    "-9.81"); "" for a string that is no number."""
    fixed = text.strip().replace(",", ".").replace("\u2212", "-")
    try:
        value = float(fixed)
    except ValueError:
        return ""
    return fixed if math.isfinite(value) else ""


def _describe(err, allowed, drop, messages) -> str:
    loc = clean_loc(err["loc"], drop)
    kind, msg = err["type"], err["msg"]
    where = loc_str(loc)
    got = err.get("input")
    got_s = f" (got {cut(repr(got))})" if not isinstance(got, (dict, list)) else ""
    if kind == "extra_forbidden":
        key = str(loc[-1])
        keys = allowed(tuple(err["loc"][:-1]))
        lower = {a.lower(): a for a in keys}
        near = difflib.get_close_matches(key.lower(), list(lower), n=1)
        hint = f"; did you mean {lower[near[0]]!r}?" if near else ""
        return led(f"{where}: ", Notice.of(
            "unknown_key", "unknown key{hint} (allowed: {allowed})", key=key,
            near=lower[near[0]] if near
                                        else "", allowed=", ".join(keys), hint=hint))
    if kind == "missing":
        return f"{where}: missing required field"
    if kind == "finite_number":
        return f"{where}: must be a finite number{got_s}"
    if kind in ("model_type", "model_attributes_type", "dict_type"):
        return f"{where}: must be a table of keys, e.g. {{ key = value, … }}{got_s}"
    if kind == "value_error":
        ctx = err.get("ctx", {}).get("error")
        if ctx is not None and isinstance(said(ctx), Notice):
            return led(f"{where}: ", said(ctx))
        return f"{where}: {msg.removeprefix('Value error, ')}"
    if kind in ("float_type", "float_parsing", "int_type") and isinstance(got, str) and (
            fixed := _as_number(got)):   # «"0,05"», «"10"»: a number in quotes
        return led(f"{where}: ", Notice.of(
            "quoted_number", "must be a number, written without quotes (a decimal point, not a "
            "comma): {fixed} (got {got})", fixed=fixed, got=cut(repr(got))))
    if messages and kind in messages:
        return f"{where}: {messages[kind]}{got_s}"
    return f"{where}: {msg[0].lower() + msg[1:]}{got_s}"
