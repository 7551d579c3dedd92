"""The command-line parser's own errors (typer's vendored click: an unknown option or command, a
missing argument, an option's value of the wrong type) as one errors.Notice, so that the one
`error:` line is said in the user's --lang (render/messages.py, the catalogue).

The English text is the parser's own, unchanged; the Russian one is made from the exception's
fields (the option's name, its possibilities, the pydantic error type of a value that does not
convert). A parser message this module does not know keeps its English words under a Russian
«ошибка:» prefix.
"""
from __future__ import annotations

import re

from flywheel.errors import Notice

#: pydantic's error types of an option's value that does not convert (typer coerces option
#: values through pydantic TypeAdapters) → the word for what the value must be
_VALUE_KINDS = {"int_parsing": "integer", "int_from_float": "integer", "int_type": "integer",
                "float_parsing": "number", "float_type": "number",
                "bool_parsing": "boolean", "bool_type": "boolean"}


def _value_kind(exc: BaseException) -> str:
    """What the option's value must be, from the pydantic error behind a BadParameter ("" when
    it is no pydantic conversion error this module knows)."""
    cause = exc.__cause__
    errors = getattr(cause, "errors", None)
    if not callable(errors):
        return ""
    try:
        first = errors()[0]
    except Exception:                          # not pydantic's ValidationError after all
        return ""
    return _VALUE_KINDS.get(first.get("type", ""), "")


def usage_notice(exc: BaseException) -> str:
    """The parser's error message, an errors.Notice when its Russian form is known.

    The codes: ``usage_no_such_option`` (option, possible), ``usage_needs_value`` (option,
    count), ``usage_takes_no_value`` (option), ``usage_missing`` (kind, name),
    ``usage_bad_value`` (hint, value_kind, text), ``usage_no_such_command`` (command),
    ``usage_extra_arguments`` (args), ``usage_missing_command``."""
    text = " ".join(exc.format_message().split())
    kind = type(exc).__name__
    if kind == "NoSuchOption":
        possible = ", ".join(sorted(exc.possibilities or ()))
        return Notice.of("usage_no_such_option", "{message}", message=text,
                         option=exc.option_name, possible=possible)
    if kind == "BadOptionUsage":
        m = re.fullmatch(r"Option '(.+)' requires (an argument|(\d+) arguments)\.", text)
        if m:
            return Notice.of("usage_needs_value", "Option '{option}' requires {needs}.",
                             option=m.group(1), needs=m.group(2), count=int(m.group(3) or 1))
        m = re.fullmatch(r"Option '(.+)' does not take a value\.", text)
        if m:
            return Notice.of("usage_takes_no_value", "Option '{option}' does not take a value.",
                             option=m.group(1))
        return text
    if kind == "MissingParameter":
        m = re.fullmatch(r"Missing (argument|option) (\S+)\.", text)
        if m:
            return Notice.of("usage_missing", "Missing {kind} {name}.", kind=m.group(1),
                             name=m.group(2))
        return text
    if kind == "BadParameter":
        m = re.fullmatch(r"Invalid value for (.+?): (.*)", text)
        value_kind = _value_kind(exc)
        if m and value_kind:
            given = _given(exc)
            return Notice.of("usage_bad_value", "Invalid value for {field}: {detail}",
                             field=m.group(1), detail=m.group(2), hint=m.group(1).strip("'"),
                             value_kind=value_kind, got=repr(given) if given else "")
        return text
    m = re.fullmatch(r"No such command '(.+)'\.", text)
    if m:
        return Notice.of("usage_no_such_command", "No such command '{command}'.",
                         command=m.group(1))
    m = re.fullmatch(r"Got unexpected extra (argument(?:\(s\)|s)?) \((.*)\)", text)
    if m:
        return Notice.of("usage_extra_arguments", "Got unexpected extra {noun} ({args})",
                         noun=m.group(1), args=m.group(2))
    if text == "Missing command.":
        return Notice.of("usage_missing_command", "Missing command.")
    return text


def _given(exc: BaseException) -> str:
    """The value the user gave for the option of a BadParameter (pydantic's input)."""
    try:
        return str(exc.__cause__.errors()[0]["input"])
    except Exception:
        return ""
