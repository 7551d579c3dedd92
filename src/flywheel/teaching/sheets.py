"""What goes on a student's task sheet (``flywheel variants … --sheets``; docs/teacher.md):
the variant's input data with their units, the list of what to find with the tolerance the
grader will use, and what the drawing needs — the linkage of a run case (its kinematics on a
coarse grid) or the given moment graphs M_D(φ), M_C(φ) of a task2 case.

No answer goes on a sheet: the data are the variant file's own inputs, the find-list names the
answers without their values. The words and the typesetting are render/sheets.py's.

Units come from the case schema (each field's description says its unit in brackets, e.g.
``bore d [m]``); a field without one is dimensionless (a ratio, δ) or its unit is unknown.
Computation only: no typer, rich or matplotlib.
"""
from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from typing import Any

from flywheel.cases.describe import unit_of_path

#: top-level tables of a case that are not data of the task (how to report, the start-up motor)
NOT_DATA = ("title", "source", "output", "motor", "force_analysis")
#: text fields a student needs (the rest name the elements the drawing shows, or say how to
#: compute): a dotted-path pattern, ``#`` an array index
TEXT_DATA = ("machine.firing_order", "machine.balance", "crank.rotation", "cylinders.#.head",
             "flywheel.material", "forces.#.reference", "forces.#.stroke")
#: intervals of the φ grid of the drawing's kinematics (the drawing needs no finer one)
DRAWING_POINTS = 360


@dataclass(frozen=True)
class Given:
    """One input of the variant: ``path`` in the case document ("links.2.mass"), its ``value``
    (a number or a text, or a tuple for an array: "machine.firing_order"), its SI ``unit`` from the schema ("" dimensionless or
    not stated) and whether this variant drew it (``varied``)."""

    path: str
    value: Any
    unit: str
    varied: bool


@dataclass(frozen=True)
class Find:
    """One answer asked: its result key ("J_flywheel", "flywheel_disk.D") and the relative
    tolerance the grader applies to it [1]."""

    answer: str
    tolerance: float


@dataclass(frozen=True)
class MomentGraphs:
    """The given moment graphs of a task2 variant on a φ grid: phi_deg [deg], M_D, M_C [N·m];
    ``unknown``: the graph whose value the cycle balance (or the power) gives — the sheet marks
    it "?" and prints no scale; ``breaks_deg``: the graphs' corners [deg]; ``cycle_deg``."""

    phi_deg: tuple[float, ...]
    M_D: tuple[float, ...]
    M_C: tuple[float, ...]
    unknown: str | None
    breaks_deg: tuple[float, ...]
    cycle_deg: float


@dataclass(frozen=True)
class Sheet:
    """One task sheet: variant ``number`` (1-based) and ``stem`` of its files ("variant_07"),
    the template's ``kind`` and ``title`` (a plain string, or an io.text.Text given in both
    languages), the inputs (``given``), what to find (``find``), and
    the drawing: ``linkage`` (Results of the variant on a coarse grid, drawn at ``angle_deg``)
    or ``moments``; ``no_drawing`` says why there is none ("" when there is one); ``names``:
    the names of the elements of the case's arrays ("cylinders.0" → "HP", "dyads.1" → "C")."""

    number: int
    id: str
    stem: str
    kind: str
    title: str
    given: tuple[Given, ...]
    find: tuple[Find, ...]
    linkage: Any = None
    angle_deg: float | None = None
    moments: MomentGraphs | None = None
    no_drawing: str = ""
    names: dict[str, str] = field(default_factory=dict)
    tables: tuple = ()           # teaching.tables.TableSpec: blank tables to fill in
    default_tolerance: float = 0.01   # the template's: a table column's without its own
    at_deg: tuple = ()           # the report angles [deg] an ``at.N.…`` answer is asked at
    loads: tuple = ({}, {})      # the loads' titles and labels an ``at.N.…`` answer names
    #: whether an answer asked is negative in some variant of the set (an engine's M_С and
    #: A_С): the sheet then says the sign convention, on every sheet of the set alike
    signed: bool = False


# -- the data rows ---------------------------------------------------------------------------------

def _number(v) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _numeric(v) -> bool:
    if _number(v):
        return True
    return isinstance(v, list) and bool(v) and all(_numeric(x) for x in v)


def _text(v) -> bool:
    return isinstance(v, str) or (isinstance(v, list) and bool(v)
                                  and all(isinstance(x, str) for x in v))


def _leaves(node, prefix: str = ""):
    """(path, value) of every number or array of numbers below ``node``, and of every text
    or array of texts of :data:`TEXT_DATA`, in document order."""
    items = node.items() if isinstance(node, dict) else enumerate(node)
    for k, v in items:
        path = f"{prefix}{k}"
        if _numeric(v) or (_text(v) and re.sub(r"\.\d+\.", ".#.", path) in TEXT_DATA):
            yield path, (_tuple(v) if isinstance(v, list) else v)
        elif isinstance(v, (dict, list)):
            yield from _leaves(v, path + ".")


def _tuple(v):
    return tuple(_tuple(x) if isinstance(x, list) else x for x in v)


#: answers that depend on the flywheel's material and proportions (summary.json keys' first part)
_FLYWHEEL_DIMENSIONS = ("flywheel_disk", "flywheel_rim")


#: a flywheel's proportions and material, by the answers that need them (summary.json keys'
#: first part): a sheet that asks no rim has no use for the rim's D₁/D, one that asks no
#: dimension none for ρ and b/D — a datum that no answer uses reads as a contradiction
#: («D₁/D = 0,8» beside «a solid disk D»)
_FLYWHEEL_DATA = {"flywheel.density": _FLYWHEEL_DIMENSIONS,
                  "flywheel.width_ratio": _FLYWHEEL_DIMENSIONS,
                  "flywheel.inner_ratio": ("flywheel_rim",)}


def _needed(path: str, asked: set) -> bool:
    """Whether a flywheel datum of :data:`_FLYWHEEL_DATA` is needed by an answer ``asked``
    (their first parts); any other datum is."""
    return path not in _FLYWHEEL_DATA or not asked.isdisjoint(_FLYWHEEL_DATA[path])


def given_rows(kind: str, document: dict, varied, answers=None) -> tuple[Given, ...]:
    """The inputs of a case document: the drawn values first (``varied``: their paths, in the
    template's order), then the fixed data a student needs (every number of the case but the
    report settings and the start-up motor, and the text fields of :data:`TEXT_DATA`, in
    document order; with the ``answers`` asked, a flywheel's proportion or material that none
    of them needs is left out, :data:`_FLYWHEEL_DATA`)."""
    order = {p: i for i, p in enumerate(varied)}
    asked = None if answers is None else {a.split(".")[0] for a in answers}

    def needed(path: str) -> bool:
        return asked is None or path in order or _needed(path, asked)

    rows = [Given(p, v, unit_of_path(kind, p), p in order)
            for p, v in _leaves({k: v for k, v in document.items() if k not in NOT_DATA})
            if needed(p)]
    drawn = sorted((g for g in rows if g.varied), key=lambda g: order[g.path])
    return tuple(drawn + [g for g in rows if not g.varied])


def default_rows(document: dict, source: str, answers) -> tuple[Given, ...]:
    """The defaults an answer depends on that the case leaves out, as given data: a flywheel's
    diameter (``flywheel_disk.D``, ``flywheel_rim.*``) needs ρ of its material and b/D (and the
    rim's D_inner/D), which cases/run.py defaults (steel, 0.2, 0.8) when [flywheel] does not
    say them; a student cannot find D without them. Only for the first-principles formulas
    (the course's formulas take none of them)."""
    if not any(a.split(".")[0] in _FLYWHEEL_DIMENSIONS for a in answers):
        return ()
    from flywheel.cases.run import parse_case

    fw = parse_case(document, source).flywheel
    if fw.formulas == "course":
        return ()
    given = document.get("flywheel", {}) if isinstance(document.get("flywheel"), dict) else {}
    value = {"density": (fw.rho, "kg/m³"), "width_ratio": (fw.width_ratio, ""),
             "inner_ratio": (fw.inner_ratio, "")}
    asked = {a.split(".")[0] for a in answers}
    return tuple(Given(path, float(value[k][0]), value[k][1], False)
                 for path in _FLYWHEEL_DATA if _needed(path, asked)
                 and (k := path.split(".")[1]) not in given)


#: the symbol whose subscript a load's ``label`` is, by its array: «сила F_пс», «пара сил M_с»
_LABELLED = {"forces": "F_", "springs": "F_", "couples": "M_", "cylinders": ""}


def element_names(document: dict, prefix: str = "") -> dict[str, str]:
    """The name of each table of an array of tables ("cylinders.0" → "HP", "crank.pins.0" →
    "A2"): a load's ``label`` (a string, or an io.text.Text of its ``{ ru, en }``) — a
    cylinder's as it is («цилиндр ВД»), a force's or spring's as its F's subscript («сила
    F_пс»), a couple's as its M's — else its ``name``, else its ``joint`` (a dyad is named by
    its joint); arrays inside a table too (a crank's pins); a point's link and the joints it is
    measured from and to ("points.S2.from" → "A")."""
    from flywheel.io.text import Text

    out = {}
    for key, value in document.items():
        if isinstance(value, list):
            for i, entry in enumerate(value):
                if isinstance(entry, dict):
                    label = entry.get("label") if key in _LABELLED else None
                    symbol = _LABELLED.get(key, "")
                    if isinstance(label, dict) and isinstance(label.get("en"), str) and \
                            isinstance(label.get("ru"), str) and label["en"] and label["ru"]:
                        label = Text(symbol + label["en"], symbol + label["ru"])
                    elif isinstance(label, str) and label:
                        label = symbol + label
                    name = label if isinstance(label, str) and label else \
                        entry.get("name", entry.get("joint"))
                    if isinstance(name, str) and name:
                        out[f"{prefix}{key}.{i}"] = name
        elif isinstance(value, dict) and not prefix:
            out.update(element_names(value, f"{key}."))
    points = document.get("points") if not prefix else None
    for name, p in (points.items() if isinstance(points, dict) else ()):
        for k in ("link", "from", "to"):        # a point on its link: «l_AS2/l_AB» on the sheet
            if isinstance(p, dict) and isinstance(p.get(k), str) and p[k]:
                out[f"points.{name}.{k}"] = p[k]
    return out


def find_list(template) -> tuple[Find, ...]:
    """The answers asked, each with the tolerance ``flywheel grade`` uses for it (the
    template's per-answer tolerance, else its default)."""
    return tuple(Find(a, float(template.tolerances.get(a, template.tolerance)))
                 for a in template.answers)


# -- the drawing -----------------------------------------------------------------------------------

def _linkage(document: dict, source: str):
    """(Results on a coarse grid, the angle [deg] to draw at) of a run case, or (None, reason)
    for a case without a linkage (kinematics given as a table)."""
    from flywheel.cases.run import parse_case
    from flywheel.dynamics.pipeline import analyze

    case = parse_case(document, source)
    if case.tabulated is not None:
        from flywheel.errors import Notice

        return None, Notice.of(
            "sheet_no_drawing_tabulated", "the kinematics are given as a table ([tabulated]): the "
            "sheet has no drawing of the mechanism")
    results = analyze(case, n_points=DRAWING_POINTS)
    angles = [float(a.phi_deg) for a in results.at] or [0.0]
    return results, angles[0]


def _moments(document: dict, source: str) -> tuple[MomentGraphs | None, str]:
    """The given moment graphs of a task2 case, or (None, reason) for an area diagram."""
    from flywheel.cases.task2 import parse_task2_case, solve_case
    from flywheel.constant_inertia.solve import sample

    case = parse_task2_case(document, source)
    r = solve_case(case, source)
    if r.driving is None or r.resistance is None:
        from flywheel.errors import Notice

        return None, Notice.of(
            "sheet_no_drawing_areas", "the task is given as an area diagram, not as moment graphs: "
            "the sheet has no drawing")
    s = sample(r, n=721)
    breaks = sorted({round(math.degrees(x), 9) for m in (r.driving, r.resistance)
                     for x in m.breakpoints()})
    unknown = r.unknown or r.power_found
    return MomentGraphs(tuple(math.degrees(x) for x in s["phi"]), tuple(s["M_D"]),
                        tuple(s["M_C"]), unknown, tuple(breaks),
                        math.degrees(r.cycle)), ""


def _title(said) -> str:
    """A variant's title as the sheet keeps it: a plain string as it is, a ``{ ru, en }`` table
    as an io.text.Text (English, with its Russian), which the sheet shows in its language."""
    from flywheel.io.text import Text

    if isinstance(said, dict) and isinstance(said.get("en"), str) and isinstance(said.get("ru"), str):
        return Text(said["en"], said["ru"])
    return said if isinstance(said, str) else ""


def sheets_of(vs, progress=None) -> list[Sheet]:
    """The task sheet of every variant of a :class:`~flywheel.teaching.variants.VariantSet`;
    ``progress(i)`` after sheet i (1-based)."""
    t = vs.template
    find = find_list(t)
    varied = [v.path for v in t.varied]
    signed = any(isinstance(x, (int, float)) and x < 0 for v in vs.variants
                 for a, x in v.answers.items() if a in t.answers)
    out = []
    for n, v in enumerate(vs.variants, 1):
        doc = tomllib.loads(v.text)
        stem = v.filename.rsplit(".", 1)[0]
        kw: dict[str, Any] = {}
        if t.kind == "run":
            res, how = _linkage(doc, v.filename)
            if res is None:
                kw["no_drawing"] = how
            else:
                kw.update(linkage=res, angle_deg=how)
        else:
            graphs, why = _moments(doc, v.filename)
            kw.update(moments=graphs, no_drawing=why)
        title = _title(doc.get("title", ""))
        given = given_rows(t.kind, doc, varied, t.answers)
        if t.kind == "run":
            given += default_rows(doc, v.filename, t.answers)
            kw.update(at_deg=v.at_deg, loads=v.loads)
        out.append(Sheet(n, v.id, stem, t.kind, title, given, find, names=element_names(doc),
                         tables=t.tables, default_tolerance=t.tolerance, signed=signed, **kw))
        if progress is not None:
            progress(n)
    return out
