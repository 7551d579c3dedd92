"""The field reference of the case file, generated from its JSON Schema (cases/describe.py) in
English (docs/case-fields.md) or Russian (docs/ru/case-format.md): one table per table of the
file, each key with its type, default and description. tools/casedoc.py writes the files;
tests/cases/test_case_reference.py fails when they are stale. The descriptions live in the
models, their Russian in the catalogue (msgctxt "field")."""
from __future__ import annotations

import re

from flywheel.render.catalogue import description, words

T = words("case_reference", {
    "title": "The case file: every field",
    "intro": ("Generated from the case file's JSON Schema (`flywheel schema`) by "
              "`python tools/casedoc.py`: do not edit by hand. The descriptions are the "
              "models' own; the guide with examples is docs/case-format.md."),
    "top": "(top level)",
    "each": "(each entry)",
    "of": "of",
    "key": "key", "type": "type", "default": "default", "meaning": "meaning",
    "required": "required",
    "types": {"number": "number", "integer": "integer", "string": "string",
              "boolean": "boolean", "array_of": "array of", "table_of": "table of",
              "array": "array", "any": "any", "object": "table"},
})


def _type(text: str, lang: str) -> str:
    """A type's words in ``lang``: "array of number" → "массив из число"… kept short."""
    t = T[lang]["types"]
    text = text.replace("array of ", t["array_of"] + " ").replace("table of ", t["table_of"] + " ")
    text = text.replace("array [", t["array"] + " [").replace("(each entry)", T[lang]["each"])
    return re.sub(r"\b(number|integer|string|boolean|any|object)\b", lambda m: t[m.group(1)], text)


def _heading(name: str, lang: str) -> str:
    w = T[lang]
    name = name.replace("(top level)", w["top"]).replace("(each entry)", w["each"])
    return re.sub(r"^(\w+) of ", rf"\1 {w['of']} ", name) if lang == "en" else re.sub(
        r"^(\w+) of (.*)$", r"\1 (\2)", name)


def _cell(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def reference_markdown(tables, lang: str = "en") -> str:
    """The reference as Markdown (``tables``: cases.describe.tables())."""
    w = T[lang]
    out = [f"# {w['title']}", "", w["intro"], ""]
    for tab in tables:
        out += [f"## `{_heading(tab.name, lang)}`", ""]
        if tab.description:
            out += [_cell(description(tab.description, lang)), ""]
        out += [f"| {w['key']} | {w['type']} | {w['default']} | {w['meaning']} |",
                "|---|---|---|---|"]
        for row in tab.rows:
            default = f"`{row.default}`" if row.default else (w["required"] if row.required
                                                              else "–")
            out.append(f"| `{row.key}` | {_cell(_type(row.type, lang))} | {_cell(default)} | "
                       f"{_cell(description(row.description, lang)) or '–'} |")
        out.append("")
    return "\n".join(out)
