"""Individual variants of a course task and their answer key (``flywheel variants``).

A *template* is a normal case file — a ``flywheel run`` case or a ``flywheel task2`` case —
plus a ``[variants]`` table that says what to vary and which results are the answers::

    [variants]
    "machine.speed_rps" = { values = [8, 10, 12] }            # one of these
    "links.2.mass"      = { min = 0.6, max = 1.2, step = 0.1 } # one of 0.6, 0.7, …, 1.2
    answers   = ["J_required", "delta_T_max"]                  # keys of the answer key
    tolerance = 0.01                                           # relative, for grading
    tolerances = { delta_T_max = 0.02 }                        # per answer (optional)

A path is dotted into the TOML document; a number in it indexes an array of tables
(``cylinders.0.p_max``). Every variant draws one value per path with
``numpy.random.default_rng(seed)`` (in the order the paths are written), is validated as its
kind of case and analysed; a draw that fails either is drawn again (up to
:data:`MAX_FAILED_DRAWS` times in a row). Variants are distinct while the grid of possible
draws allows it.

The kind of a template is found by validating it: first as a ``flywheel run`` case, then as a
``flywheel task2`` case; the first that validates wins. If neither does, the error reported is
that of a run case when the template has a ``[machine]`` table, else that of a task2 case.

Computation only: no typer, no rich. Every mistake is one :class:`CaseFileError` or
:class:`InputError` line.
"""
from __future__ import annotations

import copy
import csv
import difflib
import io
import json
import math
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from flywheel.errors import CaseFileError, FlywheelError, InputError, Notice, led, said
from flywheel.io.toml import read_toml

#: intervals of the φ grid for the answers of a run case (4 per degree; the answers differ from
#: the default 3600-point grid by well under 1e-4 relative — tests/teaching/test_variants.py checks it)
RUN_POINTS = 1440
#: a variant whose draws fail validation or analysis this many times in a row is an error
MAX_FAILED_DRAWS = 50
#: draws spent looking for a variant unlike the ones before, per variant
MAX_DUPLICATE_DRAWS = 2000
MAX_COUNT = 9999
DEFAULT_TOLERANCE = 0.01
SPEC_KEYS = ("values", "min", "max", "step")
RESERVED = ("answers", "tolerance", "tolerances", "tables")


# -- the [variants] table -----------------------------------------------------------------------

@dataclass(frozen=True)
class Varied:
    """One path of the document and the values a variant may take there."""

    path: str
    parts: tuple[str | int, ...]
    choices: tuple[Any, ...]


@dataclass(frozen=True)
class Template:
    """A parsed template: the case document without [variants], its kind and what to vary."""

    source: str
    name: str
    kind: str                    # "run" | "task2"
    document: dict
    varied: tuple[Varied, ...]
    answers: tuple[str, ...]
    tolerance: float
    tolerances: dict[str, float]
    tables: tuple = ()           # teaching.tables.TableSpec: answers that are tables

    @property
    def keyed(self) -> tuple[str, ...]:
        """Every answer of the key: the answers, then each table's cells (row by row)."""
        return self.answers + tuple(c for t in self.tables for c in t.cells)

    def tolerance_of(self, answer: str) -> float:
        """An answer's tolerance (a table's cell: its column's), else the default."""
        if answer in self.tolerances:
            return self.tolerances[answer]
        for t in self.tables:
            if answer.startswith(t.name + "."):
                column = answer.rsplit(".", 1)[1]
                tol = t.tolerances[t.columns.index(column)]
                return self.tolerance if tol is None else tol
        return self.tolerance

    @property
    def combinations(self) -> int:
        return math.prod(len(v.choices) for v in self.varied)


def _is_number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)


def _flatten(table: dict, doc, prefix: str = "") -> list[tuple[str, Any]]:
    """(path, spec) pairs: a quoted key "a.b" and nested tables a.b both name the path a.b (a
    nested table is followed while the document has a table or an array there)."""
    out = []
    for k, v in table.items():
        path = f"{prefix}{k}"
        if not prefix and k in RESERVED:
            continue
        node = _peek(doc, path)
        if (isinstance(v, dict) and v and not (set(v) & set(SPEC_KEYS))
                and isinstance(node, (dict, list))):
            out += _flatten(v, doc, path + ".")
        else:
            out.append((path, v))
    return out


def _peek(doc, path: str):
    node = doc
    for name in path.split("."):
        if isinstance(node, dict) and name in node:
            node = node[name]
        elif isinstance(node, list) and name.isdigit() and int(name) < len(node):
            node = node[int(name)]
        else:
            return None
    return node


def _q(path: str) -> str:
    return f'variants."{path}"'


def _resolve(doc, path: str, where: str) -> tuple[tuple[str | int, ...], Any]:
    """Walk ``path`` (dotted; integers index arrays) in ``doc``: (parts, value there)."""
    parts: list[str | int] = []
    node = doc
    walked = ""
    for name in path.split("."):
        here = f"[{walked}]" if walked else "the top level"
        if isinstance(node, dict):
            if name not in node:
                near = difflib.get_close_matches(name, [str(k) for k in node], n=1)
                hint = f"; did you mean {near[0]!r}?" if near else ""
                keys = ", ".join(map(str, node)) or "nothing"
                raise CaseFileError(led(f"{where}: ", Notice.of(
                    "path_not_in", "{name!r} is not in {here} (it has: {keys}){hint} — a varied "
                    "field must have a value in the template", name=name, here=here, keys=keys,
                    near=near[0] if near else "", hint=hint)))
            parts.append(name)
            node = node[name]
        elif isinstance(node, list):
            if not name.isdigit():
                raise CaseFileError(led(f"{where}: ", Notice.of(
                    "var_not_an_index", "{array} is an array; {name!r} is not an index (allowed: "
                    "0…{last})", array=walked, name=name, last=len(node) - 1)))
            i = int(name)
            if i >= len(node):
                raise CaseFileError(led(f"{where}: ", Notice.of(
                    "var_index_range", "{array} has {n} entries; index {i} is out of range "
                    "(allowed: 0…{last})", array=walked, n=len(node), i=i, last=len(node) - 1)))
            parts.append(i)
            node = node[i]
        else:
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_inside_a_value", "{value} is a value, not a table; nothing inside it is "
                "called {name!r}", value=walked, name=name)))
        walked = f"{walked}.{name}" if walked else name
    return tuple(parts), node


def _grid(spec: dict, where: str) -> tuple:
    """The values min, min + step, …, ≤ max (rounded to 12 decimals; integers stay integers)."""
    for k in ("min", "max", "step"):
        if k not in spec:
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_grid_missing", "{key} is missing (give min, max and step, or values)", key=k)))
        if not _is_number(spec[k]):
            raise CaseFileError(led(f"{where}.{k}: ", Notice.of(
                "not_finite_number", "must be a finite number (got {got})", got=repr(spec[k]))))
    lo, hi, step = spec["min"], spec["max"], spec["step"]
    if step <= 0:
        raise CaseFileError(led(f"{where}.step: ", Notice.of(
            "positive_got", "must be positive (got {got})", got=repr(step))))
    if hi < lo:
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "max_below_min", "max ({hi}) is less than min ({lo})", hi=repr(hi), lo=repr(lo))))
    n = math.floor((hi - lo) / step * (1 + 1e-12) + 1e-9) + 1
    if n > 100_000:
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "var_grid_too_many", "{n} grid values are too many (allowed: up to 100000; use a "
            "larger step)", n=n)))
    if all(isinstance(spec[k], int) for k in ("min", "max", "step")):
        return tuple(lo + k * step for k in range(n))
    return tuple(round(lo + k * step, 12) + 0.0 for k in range(n))


def _choices(spec, where: str, current) -> tuple:
    if not isinstance(spec, dict):
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "spec_not_table", "must be a table {{ values = [...] }} or {{ min = …, max = …, step "
            "= … }} (got {got})", got=repr(spec))))
    unknown = [k for k in spec if k not in SPEC_KEYS]
    if unknown:
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "var_unknown_key", "unknown key {key!r} (allowed: values, or min, max, step)",
            key=unknown[0])))
    if "values" in spec:
        if set(spec) - {"values"}:
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_values_or_grid", "give either values or min, max, step, not both")))
        vals = spec["values"]
        if not isinstance(vals, list) or not vals:
            raise CaseFileError(led(f"{where}.values: ", Notice.of(
                "nonempty_array", "must be a non-empty array (got {got})", got=repr(vals))))
        if any(isinstance(v, dict) for v in vals):
            raise CaseFileError(led(f"{where}.values: ", Notice.of(
                "var_values_tables", "tables cannot be drawn (vary their fields)")))
        return tuple(vals)
    if not _is_number(current):
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "var_grid_needs_number", "min/max/step need a number in the template (it has "
            "{current}); use values = [...]", current=repr(current))))
    return _grid(spec, where)


def _answers(table: dict, where: str, tables=()) -> tuple[tuple[str, ...], float, dict[str, float]]:
    if "answers" not in table:
        raise CaseFileError(led(f"{where}.answers: ", Notice.of(
            "answers_missing", "missing (the result keys of the answer key, e.g. answers = "
            "[\"J_required\", \"delta_T_max\"])")))
    ans = table["answers"]
    if (not isinstance(ans, list) or not ans
            or not all(isinstance(a, str) and a.strip() for a in ans)):
        raise CaseFileError(led(f"{where}.answers: ", Notice.of(
            "answers_empty", "must be a non-empty array of result names (got {got})",
            got=repr(ans))))
    for a in ans:
        if ans.count(a) > 1:
            raise CaseFileError(led(f"{where}.answers: ", Notice.of(
                "var_answer_twice", "{name!r} is listed twice", name=a)))
        if any(c in a for c in ',;"\n'):
            raise CaseFileError(led(f"{where}.answers: ", Notice.of(
                "var_answer_csv", "{name!r} has a character not allowed in a CSV column name (, ; "
                "\" or a line break)", name=a)))
    tol = table.get("tolerance", DEFAULT_TOLERANCE)
    if not _is_number(tol) or tol <= 0:
        raise CaseFileError(led(f"{where}.tolerance: ", Notice.of(
            "not_positive_relative", "must be a positive number, relative (got {got})",
            got=repr(tol))))
    tols = table.get("tolerances", {})
    if not isinstance(tols, dict):
        raise CaseFileError(led(f"{where}.tolerances: ", Notice.of(
            "var_tolerances_table", "must be a table {{ answer = tolerance }} (got {got})",
            got=repr(tols))))
    for k, v in tols.items():
        if k not in ans and k not in tables and k.split(".")[0] not in tables:
            raise CaseFileError(led(f"{where}.tolerances.{k}: ", Notice.of(
                "not_an_answer", "not one of the answers (allowed: {allowed})",
                allowed=", ".join((*ans, *tables)))))
        if not _is_number(v) or v <= 0:
            raise CaseFileError(led(f"{where}.tolerances.{k}: ", Notice.of(
                "not_positive_number", "must be a positive number (got {got})", got=repr(v))))
    return tuple(ans), float(tol), {k: float(v) for k, v in tols.items()}


# -- validation and analysis of one case document -----------------------------------------------

def _validate(kind: str, doc: dict, source: str):
    if kind == "run":
        from flywheel.cases.run import parse_case

        return parse_case(doc, source)
    from flywheel.cases.task2 import parse_task2_case

    return parse_task2_case(doc, source)


def detect_kind(doc: dict, source: str) -> str:
    """"run" if ``doc`` validates as a ``flywheel run`` case, else "task2" if it validates as a
    task2 case; else the CaseFileError of the likelier kind ([machine] present → run)."""
    errors = {}
    for kind in ("run", "task2"):
        try:
            _validate(kind, doc, source)
            return kind
        except CaseFileError as exc:
            errors[kind] = exc
    likely = "run" if "machine" in doc else "task2"
    what = "a flywheel run case" if likely == "run" else "a flywheel task2 case"
    raise CaseFileError(Notice.of(
        "checked_as", "{detail} [checked as {checked_kind}]", detail=said(errors[likely]),
        as_kind=likely, checked_kind=what))


def results_of(kind: str, doc: dict, source: str, n_points: int = RUN_POINTS) -> dict:
    """The results document of one case: summary.json "results" for a run case, the JSON of
    ``flywheel task2 --json`` for a task2 case (SI units)."""
    return solved(kind, doc, source, n_points)[0]


def solved(kind: str, doc: dict, source: str, n_points: int = RUN_POINTS):
    """(results document, the chain's givens or None, the solved results: ``dynamics``'
    Results or task2's Task2Result) of one case (:func:`results_of`;
    teaching/chain.py: the givens of a run case whose flywheel is sized; teaching/chain_task2.py:
    those of a task2 case whose cycle balance finds a graph's value)."""
    case = _validate(kind, doc, source)
    if kind == "run":
        from flywheel.cases.run import field_of
        from flywheel.dynamics.pipeline import analyze
        from flywheel.teaching.chain import givens_of

        try:
            res = analyze(case, n_points=n_points)
            return res.to_document()["results"], givens_of(case, res), res
        except FlywheelError as exc:      # name the field as `flywheel run` does ('dyads[0]: …')
            where = field_of(exc, case)
            if not where:
                raise
            raise type(exc)(led(f"{where}: ", said(exc))) from None
    from flywheel.cases.task2 import solve_case
    from flywheel.teaching.chain_task2 import task2_givens_of

    result = solve_case(case, source)
    return result.to_document(), task2_givens_of(result), result


def answer_value(results: dict, name: str):
    """The result ``name`` (dotted: ``flywheel_disk.mass``, ``at.0.omega``), or None."""
    node: Any = results
    for part in name.split("."):
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return None
    return node


def _numeric_names(results: dict, prefix: str = "") -> list[str]:
    out = []
    for k, v in results.items():
        if isinstance(v, dict):
            out += _numeric_names(v, f"{prefix}{k}.")
        elif _is_number(v):
            out.append(f"{prefix}{k}")
    return out


def pick_answers(results: dict, answers, where: str) -> dict[str, float]:
    """{answer: float} from a results document; a missing or non-numeric one is an error."""
    out = {}
    for a in answers:
        v = answer_value(results, a)
        if not _is_number(v):
            names = _numeric_names(results)
            near = difflib.get_close_matches(a, names, n=1)
            hint = f"; did you mean {near[0]!r}?" if near else ""
            what = "is not a result" if v is None else f"is not a finite number (it is {v!r})"
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "not_a_result", "{name!r} {verdict} (numbers available: {names}){hint}", name=a,
                value=None if v is None else repr(v), names=", ".join(names),
                near=near[0] if near else "", verdict=what, hint=hint)))
        out[a] = float(v)
    return out


# -- the template -------------------------------------------------------------------------------

def _check_lengths(table: dict, source: str) -> None:
    """Every name in [variants] (a varied path, an answer, a key of tolerances) and every text
    it draws at most MAX_TEXT characters, as the texts of a case file (io.schema.text_field):
    refused in one line, the name cut (io.text.cut), before anything is drawn. Iterative (the
    table's nesting is bounded by io.toml.MAX_DEPTH)."""
    from flywheel.io.schema import MAX_TEXT
    from flywheel.io.text import cut

    todo = [(table, "variants")]
    while todo:
        node, loc = todo.pop()
        items = node.items() if isinstance(node, dict) else enumerate(node)
        for k, v in items:
            bare = isinstance(k, str) and re.fullmatch(r"[A-Za-z0-9_-]+", k)
            here = (f"{loc}.{k}" if bare else f'{loc}."{cut(k)}"' if isinstance(k, str)
                    else f"{loc}[{k}]")
            too_long = next((t for t in (k, v) if isinstance(t, str) and len(t) > MAX_TEXT), None)
            if too_long is not None:
                raise CaseFileError(led(f"{source}: {here}: ", Notice.of(
                    "var_text_too_long", "too long ({n} characters; allowed: at most {most}, as "
                    "the texts of a case file)", n=len(too_long), most=MAX_TEXT)))
            if isinstance(v, (dict, list)):
                todo.append((v, here))


def parse_template(data: dict, source: str = "<template>", n_points: int = RUN_POINTS) -> Template:
    """Check a template document: its case validates and solves, [variants] is well formed,
    every path exists and every answer is a numeric result of the template itself."""
    if "variants" not in data:
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "no_variants_table", "no [variants] table (it says what to vary and which results are "
            "the answers; see docs/teacher.md)")))
    table = data["variants"]
    if not isinstance(table, dict):
        raise CaseFileError(led(f"{source}: variants: ", Notice.of(
            "var_not_a_table", "must be a table (got {got})", got=repr(table))))
    _check_lengths(table, source)
    doc = {k: v for k, v in data.items() if k != "variants"}
    kind = detect_kind(doc, source)
    from flywheel.teaching import tables as tb

    names = tb.parse_names(table.get("tables", []), f"{source}: variants.tables", kind)
    answers, tol, tols = _answers(table, f"{source}: variants", names)
    varied = []
    for path, spec in _flatten(table, doc):
        where = f"{source}: {_q(path)}"
        if path.split(".")[0] == "variants":
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_vary_variants", "cannot vary the [variants] table itself")))
        parts, current = _resolve(doc, path, where)
        if isinstance(current, dict):
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_path_is_table", "is a table; vary its fields one by one")))
        varied.append(Varied(path, parts, _choices(spec, where, current)))
    if not varied:
        raise CaseFileError(led(f"{source}: variants: ", Notice.of(
            "var_nothing_to_vary", "nothing to vary (add e.g. \"machine.speed_rps\" = {{ values = "
            "[8, 10, 12] }})")))
    for i, v in enumerate(varied):
        for w in varied[:i]:
            short, long_ = sorted((v.parts, w.parts), key=len)
            if long_[:len(short)] == short:
                raise CaseFileError(led(f"{source}: {_q(v.path)}: ", Notice.of(
                    "var_overlap", "overlaps {other}", other=_q(w.path))))
    try:
        base, _, solution = solved(kind, doc, source, n_points)
    except FlywheelError as exc:
        raise CaseFileError(Notice.of(
            "template_not_analysed", "{source}: the template itself cannot be analysed: {detail}",
            source=source, detail=said(exc))) from None
    pick_answers(base, answers, f"{source}: variants.answers")
    specs = tb.specs_of(names, solution, tols, source) if names else ()
    scalars = {k: v for k, v in tols.items() if k in answers}
    return Template(source, Path(source).name, kind, doc, tuple(varied), answers, tol, scalars,
                    specs)


def load_template(path, n_points: int = RUN_POINTS) -> Template:
    """Read and check a template file (see :func:`parse_template`)."""
    return parse_template(read_toml(path, "a TOML template"), str(path), n_points)


# -- drawing variants ---------------------------------------------------------------------------

@dataclass(frozen=True)
class Variant:
    """One generated variant: its id ("01"), file name, drawn values, file text and answers."""

    id: str
    filename: str
    drawn: dict[str, Any]
    text: str
    answers: dict[str, float]
    givens: Any = None           # teaching.chain.Givens of a run case (None: no chain)
    at_deg: tuple = ()           # a run case's report angles [deg]: what at.N answers are at
    loads: tuple = ({}, {})      # a run case's loads' titles and cylinders' labels
                                 # (LoadsResult.titles, .labels): how at.N answers name them


@dataclass(frozen=True)
class VariantSet:
    template: Template
    seed: int
    n_points: int
    variants: tuple[Variant, ...]
    failed_draws: int = 0
    warnings: tuple[str, ...] = field(default=())


def _load_names(loads: tuple) -> dict:
    """answers.json's ``load_names``: {"titles": {load: {en, ru}}, "labels": {…}} of a variant's
    LoadsResult.titles and .labels (``Variant.loads``), a load by its key's text ("force
    cutting"); :func:`flywheel.teaching.grading.parse_key` reads it back."""
    from flywheel.io.text import in_language

    def both(text) -> dict:
        return {"en": str(text), "ru": in_language(text, "ru")}

    titles, labels = loads
    return {"titles": {str(k): both(v) for k, v in titles.items()},
            "labels": {str(k): both(v) for k, v in labels.items()}}


def _report_angles(doc: dict) -> tuple[float, ...]:
    """The report angles [deg] of a run case's document: its ``output.at_deg``, else the case
    file's default (cases.run.OutputSpec)."""
    from flywheel.cases.run import OutputSpec

    at = (doc.get("output") or {}).get("at_deg")
    return tuple(float(a) for a in (at if at is not None else OutputSpec().at_deg))


def _set(doc: dict, parts, value) -> None:
    node = doc
    for p in parts[:-1]:
        node = node[p]
    node[parts[-1]] = value


def header(number: int, count: int, template_name: str, seed: int, kind: str) -> str:
    """The comment on top of a variant file (tomli_w writes no comments: prepended text)."""
    how = "flywheel run" if kind == "run" else "flywheel task2 --case"
    return (f"# variant {number} of {count}, generated from {template_name} with seed {seed}\n"
            f"# solve with: {how} <this file>\n\n")


def generate(template: Template, count: int, seed: int, n_points: int = RUN_POINTS,
             progress: Callable[[int], None] | None = None) -> VariantSet:
    """Draw ``count`` variants with ``numpy.random.default_rng(seed)`` and solve each.

    The same template, count, seed and n_points give the same variants, byte for byte.
    ``progress(i)`` is called after variant i (1-based) is done.
    """
    import numpy as np
    import tomli_w

    if not 1 <= count <= MAX_COUNT:
        # library use only: no CLI input reaches this
        raise InputError(f"--count: {count} is not allowed (allowed: 1…{MAX_COUNT})")
    if not 0 <= seed < 2 ** 63:
        # library use only: no CLI input reaches this
        raise InputError(f"--seed: {seed} is not allowed (allowed: 0 … 2^63 − 1)")
    rng = np.random.default_rng(seed)
    width = max(2, len(str(count)))
    distinct = count <= template.combinations
    warnings = []
    if not distinct:
        warnings.append(Notice.of(
            "variants_repeat", "only {possible} different variants are possible; {count} asked, so "
            "some repeat", possible=template.combinations, count=count))
    seen: set[str] = set()
    variants = []
    failed_total = 0
    for number in range(1, count + 1):
        failed = dupes = 0
        last_error = ""
        while True:
            idx = [int(rng.integers(len(v.choices))) for v in template.varied]
            drawn = {v.path: v.choices[i] for v, i in zip(template.varied, idx)}
            signature = json.dumps(idx)
            if distinct and signature in seen:
                dupes += 1
                if dupes > MAX_DUPLICATE_DRAWS:
                    raise InputError(Notice.of(
                        "var_no_new_combination", "variant {number}: no new combination found in "
                        "{draws} draws; widen the ranges or ask for fewer variants", number=number,
                        draws=MAX_DUPLICATE_DRAWS))
                continue
            doc = copy.deepcopy(template.document)
            for v, i in zip(template.varied, idx):
                _set(doc, v.parts, copy.deepcopy(v.choices[i]))
            vid = str(number).zfill(width)
            filename = f"variant_{vid}.toml"
            text = header(number, count, template.name, seed, template.kind) + tomli_w.dumps(doc)
            try:
                # solve the file as written, so the key is what a student's run gives
                res, givens, solution = solved(template.kind, tomllib.loads(text), filename,
                                               n_points)
                answers = pick_answers(res, template.answers, filename)
                if template.tables:
                    from flywheel.teaching.tables import cells_of

                    answers.update(cells_of(template.tables, solution, filename))
            except FlywheelError as exc:
                failed += 1
                failed_total += 1
                last_error = said(exc)
                if failed >= MAX_FAILED_DRAWS:
                    raise InputError(led(f"{template.source}: ", Notice.of(
                        "draws_failed", "variant {number}: {failed} draws in a row failed "
                        "validation or analysis; narrow the ranges in [variants] (the last: "
                        "{detail})", number=number, failed=failed, detail=last_error))) from None
                continue
            seen.add(signature)
            run = template.kind == "run"
            variants.append(Variant(vid, filename, drawn, text, answers, givens,
                                    _report_angles(doc) if run else (),
                                    (dict(solution.loads.titles), dict(solution.loads.labels))
                                    if run else ({}, {})))
            break
        if progress is not None:
            progress(number)
    return VariantSet(template, seed, n_points, tuple(variants), failed_total, tuple(warnings))


# -- the files of the answer key ----------------------------------------------------------------

def answers_json(vs: VariantSet) -> str:
    """answers.json: the answer key ``variants`` {id: {answer: value}} with what grading needs
    (the default ``tolerance`` and the per-answer ``tolerances`` of the template) and what made
    it (template, kind, seed, grid, the drawn values)."""
    t = vs.template
    doc = {
        "template": t.name,
        "kind": t.kind,
        "seed": vs.seed,
        "count": len(vs.variants),
        "n_points": vs.n_points if t.kind == "run" else None,
        "units": "SI (m, kg, s, rad, N, N·m, J, kg·m²); angles *_deg in degrees",
        "answers": list(t.answers),
        "tolerance": t.tolerance,
        "tolerances": dict(t.tolerances),
        "variants": {v.id: v.answers for v in vs.variants},
        "drawn": {v.id: v.drawn for v in vs.variants},
    }
    if t.kind == "run" and any(a.startswith("at.") for a in t.answers):
        # the report angles an at.N answer is asked at (a feedback page names them); none: as
        # before
        doc["at_deg"] = {v.id: list(v.at_deg) for v in vs.variants}
        if any(a.split(".")[2:3] in (["moments"], ["forces"]) for a in t.answers):
            # a load's title and a cylinder's label, by which such an answer names it (the
            # template's, the same for every variant)
            doc["load_names"] = _load_names(vs.variants[0].loads)
    if t.tables:           # the cells of each table (teaching/tables.py); none: as before
        doc["tables"] = {s.name: s.to_document() for s in t.tables}
    text = json.dumps(doc, indent=2, ensure_ascii=False)
    if any(v.givens is not None for v in vs.variants):
        # the chain (teaching/chain.py): how each answer follows from the earlier ones, and
        # per variant what that needs; one line per variant (its curves unindented)
        from flywheel.teaching.chain import chain_table

        first = next(v.givens for v in vs.variants if v.givens is not None)
        steps = json.dumps(chain_table(t.answers, first.steps()), indent=2, ensure_ascii=False)
        givens = ",\n".join(
            f"      {json.dumps(v.id)}: {json.dumps(v.givens.to_document(), ensure_ascii=False)}"
            for v in vs.variants if v.givens is not None)
        text = (text[:-2] + ',\n  "chain": {\n    "steps": ' + steps.replace("\n", "\n    ")
                + ',\n    "givens": {\n' + givens + "\n    }\n  }\n}")
    return text + "\n"


def _cell(v) -> str:
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, (list, dict)):
        return json.dumps(v, ensure_ascii=False)
    return str(v)


def answers_csv(vs: VariantSet) -> str:
    """answers.csv: one row per variant: variant, file, the answers, the drawn values."""
    t = vs.template
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant", "file", *t.keyed, *(v.path for v in t.varied)])
    for v in vs.variants:
        w.writerow([v.id, v.filename, *(_cell(v.answers[a]) for a in t.keyed),
                    *(_cell(v.drawn[p.path]) for p in t.varied)])
    return buf.getvalue()


def students_csv(vs: VariantSet) -> str:
    """students.csv: the blank answer sheet ``student,variant,<answers…>``, one row per variant
    with only the variant filled in."""
    t = vs.template
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["student", "variant", *t.keyed])
    for v in vs.variants:
        w.writerow(["", v.id, *("" for _ in t.keyed)])
    return buf.getvalue()


def write_variants(vs: VariantSet, out, notes: list[str] | None = None,
                   extra: Callable[[Path], Any] | None = None) -> Path:
    """Write the variant files, answers.json, answers.csv and students.csv to ``out``, whole or
    not at all. Refuses a non-empty folder that is not an earlier variants folder; in an
    earlier one only the files flywheel wrote change (what was removed goes to ``notes``).
    ``extra(folder)`` writes more files into the same folder (the task sheets)."""
    from flywheel.io.output import write_folder

    out = Path(out)

    def build(folder: Path) -> None:
        for v in vs.variants:
            (folder / v.filename).write_text(v.text, encoding="utf-8")
        (folder / "answers.json").write_text(answers_json(vs), encoding="utf-8")
        (folder / "answers.csv").write_text(answers_csv(vs), encoding="utf-8")
        (folder / "students.csv").write_text(students_csv(vs), encoding="utf-8")
        if extra is not None:
            extra(folder)

    return write_folder(out, build, "answers.json", "variants", notes)
