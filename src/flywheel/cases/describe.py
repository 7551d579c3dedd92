"""The case file's fields as its JSON Schema describes them (`flywheel schema`): every description
with the paths that use it (what tools/i18n.py puts in the catalogue, msgctxt "field"), and the
field reference of every table (what tools/casedoc.py writes as docs/case-fields.md and, in
Russian, docs/ru/case-format.md). The descriptions live once, in the pydantic models; their
Russian, in the catalogue."""
from __future__ import annotations

import json
import re
from dataclasses import dataclass
from functools import lru_cache


def case_schema() -> dict:
    """The JSON Schema of a `flywheel run` case file (pydantic's, by alias)."""
    from flywheel.cases.run import case_json_schema

    return case_json_schema()


def descriptions(schema: dict | None = None) -> dict[str, list[str]]:
    """Every non-empty description of the schema, English → the paths that use it ("#" the
    top level, "Machine" a table's own, "Machine.speed_rps" a field's), in the schema's order."""
    schema = case_schema() if schema is None else schema
    out: dict[str, list[str]] = {}

    def add(text, where):
        if isinstance(text, str) and text.strip():
            out.setdefault(text, []).append(where)

    def fields(node: dict, where: str):
        add(node.get("description"), where)
        for key, sub in node.get("properties", {}).items():
            add(sub.get("description"), f"{where}.{key}" if where != "#" else key)

    fields(schema, "#")
    for name, node in schema.get("$defs", {}).items():
        fields(node, name)
    return out


@dataclass(frozen=True)
class FieldRow:
    """One key of a table: its name, JSON type, default (JSON text, "" when required or none),
    whether it is required, and its English description."""

    key: str
    type: str
    default: str
    required: bool
    description: str


@dataclass(frozen=True)
class TableDoc:
    """A table of the case file (a pydantic model): its name, its own description, its keys."""

    name: str
    description: str
    rows: tuple[FieldRow, ...]


def _type(node: dict, defs: dict) -> str:
    """A short name of a schema node's type: number, string, array of number, a table by its
    heading ([machine]); ``defs``: a table's schema name → its heading."""
    if "$ref" in node:
        ref = node["$ref"].rsplit("/", 1)[-1]
        return "→ " + defs.get(ref, ref)
    if "anyOf" in node or "oneOf" in node:
        parts = [_type(n, defs) for n in [*node.get("anyOf", ()), *node.get("oneOf", ())]
                 if n.get("type") != "null"]
        return " | ".join(dict.fromkeys(parts))
    if "enum" in node:
        return " | ".join(json.dumps(v, ensure_ascii=False) for v in node["enum"])
    if "const" in node:
        return json.dumps(node["const"], ensure_ascii=False)
    t = node.get("type", "")
    if t == "array":
        items = node.get("items") or node.get("prefixItems")
        if isinstance(items, list):
            return "array [" + ", ".join(_type(i, defs) for i in items) + "]"
        return f"array of {_type(items or {}, defs)}"
    if t == "object" and "additionalProperties" in node and isinstance(node["additionalProperties"], dict):
        return f"table of {_type(node['additionalProperties'], defs)}"
    return t or "any"


def _headings(schema: dict) -> dict[str, str]:
    """Each table's name as a case file writes it (``[machine]``, ``[[dyads]]``,
    ``[flywheel.rim]``, ``[links] (each)``), by the first place the schema uses it, in the
    order of the file's keys."""
    defs = schema.get("$defs", {})
    out: dict[str, str] = {}

    def refs(node: dict):
        """(ref, how) of a node: "table", "array" or "each" (a table of tables)."""
        if "$ref" in node:
            yield node["$ref"].rsplit("/", 1)[-1], "table"
        for n in [*node.get("anyOf", ()), *node.get("oneOf", ())]:
            yield from refs(n)
        if node.get("type") == "array" and isinstance(node.get("items"), dict):
            for r, _ in refs(node["items"]):
                yield r, "array"
        if isinstance(node.get("additionalProperties"), dict):
            for r, _ in refs(node["additionalProperties"]):
                yield r, "each"

    def walk(node: dict, path: str, parent: str):
        for key, sub in node.get("properties", {}).items():
            here = f"{path}.{key}" if path else key
            for ref, how in refs(sub):
                if ref in out:
                    continue
                if parent.startswith("[[") or " of " in parent:   # inside an array of tables
                    out[ref] = f"{key} of {parent}"
                else:
                    out[ref] = {"table": f"[{here}]", "array": f"[[{here}]]",
                                "each": f"[{here}] (each entry)"}[how]
                walk(defs.get(ref, {}), here, out[ref])

    walk(schema, "", "")
    return out


def tables(schema: dict | None = None) -> tuple[TableDoc, ...]:
    """The top level and every table of the schema, in the order a case file meets them, each
    named as the file writes it."""
    schema = case_schema() if schema is None else schema
    defs = schema.get("$defs", {})
    headings = _headings(schema)
    names = {ref: _kind_heading(h, defs[ref]) if _shared(ref, headings) else h
             for ref, h in headings.items()}

    def table(name: str, node: dict) -> TableDoc:
        required = set(node.get("required", ()))
        rows = []
        for key, sub in node.get("properties", {}).items():
            given = sub.get("default")
            default = json.dumps(given, ensure_ascii=False) if given not in (None, "") else ""
            rows.append(FieldRow(key, _type(sub, names), default, key in required,
                                 sub.get("description", "")))
        return TableDoc(name, node.get("description", ""), tuple(rows))

    named = [(headings[ref], ref) for ref in headings] + sorted(
        (ref, ref) for ref in defs if ref not in headings)
    return (table("(top level)", schema),
            *(table(_kind_heading(heading, defs[ref]) if _shared(ref, headings) else heading,
                    defs[ref]) for heading, ref in named))


def _kind_heading(heading: str, node: dict) -> str:
    """``[[dyads]] kind = "RRP"``: a table of a union, named by its tag."""
    kind = node.get("properties", {}).get("kind", {}).get("const")
    return f'{heading} kind = "{kind}"' if kind else heading


def _shared(ref: str, headings: dict[str, str]) -> bool:
    """Whether another table goes by the same heading (the kinds of [[dyads]])."""
    return sum(h == headings[ref] for h in headings.values()) > 1


# -- units from the schema -------------------------------------------------------------------------

@lru_cache(maxsize=2)
def field_units(kind: str) -> dict[str, str]:
    """Field name → unit as its description states it ("[kg·m²]"; a name ending in _deg: deg),
    over every model of a ``kind`` ("run", "task2") case's schema; a name whose models disagree
    is left out (the unit is then not printed). The one source of a case field's unit: the task
    sheets (teaching/sheets.py) and task2's record (render/report_task2.py) print it."""
    if kind == "run":
        schema = case_schema()
    else:
        from flywheel.cases.task2 import Task2Case

        schema = Task2Case.model_json_schema()
    found: dict[str, set[str]] = {}
    for model in [schema, *schema.get("$defs", {}).values()]:
        for name, prop in model.get("properties", {}).items():
            m = re.search(r"\[([^\]]+)\]", prop.get("description", ""))
            unit = m.group(1) if m else ("deg" if name.endswith("_deg") else "")
            if unit in ("-", "1"):
                unit = ""
            found.setdefault(name, set()).add(unit)
    return {k: next(iter(v)) for k, v in found.items() if len(v) == 1}


def unit_of_path(kind: str, path: str) -> str:
    """The unit of a field of the case document: its own name's, else the nearest table's
    that states one (``machine.first_group.crankshaft`` → kg·m² of first_group).

    >>> unit_of_path("run", "machine.first_group.crankshaft"), unit_of_path("task2", "speed.mean_rpm")
    ('kg·m²', 'rev/min')
    """
    units = field_units(kind)
    parts = [p for p in path.split(".") if not p.isdigit()]
    for name in reversed(parts):
        if units.get(name):
            return units[name]
        if name in units:           # known and dimensionless
            return ""
    return ""
