"""The one serializer of the typed results: a frozen dataclass → its JSON document, and the
JSON Schema of that document, both read off the dataclass.

A result class says what its document holds with a class attribute ``DOCUMENT``: the
attribute names in the document's order, each either ``"name"`` (the contract key is the
attribute's name) or ``("key", "attribute")`` (the contract key differs; the attribute may be a
property). Without ``DOCUMENT`` the document is every field in declaration order. An attribute
that is None is left out of the document unless its key is in the class attribute
``KEEP_NONE`` (then it is written as null). Nested result dataclasses, dicts, lists and tuples
are serialized in turn; :func:`flywheel.dynamics.results.json_ready` then makes floats finite
(NaN → null) and numpy scalars plain.
"""
from __future__ import annotations

import dataclasses
import typing
from types import NoneType, UnionType

import numpy as np


def document_keys(cls) -> tuple[tuple[str, str], ...]:
    """(contract key, attribute) of each entry of ``cls``'s document, in order."""
    spec = getattr(cls, "DOCUMENT", None)
    if spec is None:
        return tuple((f.name, f.name) for f in dataclasses.fields(cls))
    return tuple((s, s) if isinstance(s, str) else tuple(s) for s in spec)


def to_json(obj):
    """``obj`` as JSON-ready Python values (before :func:`json_ready`'s float cleaning): a
    result dataclass as a dict by :func:`document_keys`, None left out unless kept."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        keep = getattr(type(obj), "KEEP_NONE", ())
        out = {}
        for key, attr in document_keys(type(obj)):
            value = getattr(obj, attr)
            if value is None and key not in keep:
                continue
            out[key] = to_json(value)
        return out
    if isinstance(obj, dict):
        return {str(k): to_json(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [to_json(v) for v in obj]
    return obj


def _hints(cls) -> dict:
    """The type hints of ``cls``'s fields and of its properties' return values."""
    hints = typing.get_type_hints(cls)
    for name in dir(cls):
        p = getattr(cls, name, None)
        if isinstance(p, property) and p.fget is not None:
            r = typing.get_type_hints(p.fget).get("return")
            if r is not None:
                hints[name] = r
    return hints


def json_schema(tp) -> dict:
    """The JSON Schema (draft 2020-12 subset: type, properties, required,
    additionalProperties, items, anyOf) of the document of the type ``tp``: a result
    dataclass, a union, dict[str, X], tuple/list, or a scalar. A float may be null (a
    non-finite value is written as null)."""
    origin, args = typing.get_origin(tp), typing.get_args(tp)
    if origin in (typing.Union, UnionType):
        options = [a for a in args if a is not NoneType]
        if len(options) == 1:
            return json_schema(options[0])
        return {"anyOf": [json_schema(a) for a in options]}
    if dataclasses.is_dataclass(tp):
        hints = _hints(tp)
        keep = getattr(tp, "KEEP_NONE", ())
        props, required = {}, []
        for key, attr in document_keys(tp):
            h = hints[attr]
            optional = NoneType in typing.get_args(h)
            s = json_schema(h)
            if optional and key in keep:
                s = {"anyOf": [s, {"type": "null"}]}
            props[key] = s
            if not optional or key in keep:
                required.append(key)
        return {"type": "object", "properties": props, "required": required,
                "additionalProperties": False}
    if tp is dict:
        return {"type": "object"}
    if origin is dict:
        return {"type": "object", "additionalProperties": json_schema(args[1])}
    if origin in (tuple, list):
        return {"type": "array", "items": json_schema(args[0])}
    if tp is bool:
        return {"type": "boolean"}
    if tp is int:
        return {"type": "integer"}
    if tp is float:
        return {"type": ["number", "null"]}
    if tp is str:
        return {"type": "string"}
    if tp is typing.Any or tp is object:
        return {}
    if tp is np.ndarray:
        return {"type": "array"}
    raise TypeError(f"no JSON Schema for {tp!r}")
