"""Case files, one schema module per kind: :mod:`.run` (a linkage or a table of kinematics:
``flywheel run``), :mod:`.tabulated` (its ``[tabulated]`` section), :mod:`.task2` (given moment
graphs: ``flywheel task2 --case``), :mod:`.aggregate` (elastic couplings: ``flywheel aggregate``),
:mod:`.duty_cycle` (presses: ``flywheel duty-cycle``).

A file given to the wrong command is recognised by its tables (:func:`kind_of`) and the error
names the command that reads it.
"""
from __future__ import annotations

# the tables only one kind has (a file with any of these is of that kind)
_OWN_TABLES = {
    "run": ("crank", "dyads", "tabulated", "cylinders", "links", "points", "design", "couples",
            "forces", "ground", "output"),
    "task2": ("driving", "resistance", "diagram", "speed", "cycle_deg"),
    "aggregate": ("coupling", "rotors", "shafts", "load"),
    "duty_cycle": ("operation", "cycle"),
}
COMMANDS = {
    "run": "flywheel run {file}",
    "task2": "flywheel task2 --case {file}",
    "aggregate": "flywheel aggregate {file}",
    "variants": "flywheel variants {file} --count N --out DIR",
    "duty_cycle": "flywheel duty-cycle {file}",
}
NAMES = {"run": "a flywheel run case", "task2": "a task-2 case (given moment graphs)",
         "aggregate": "an aggregate case (elastic couplings)",
         "variants": "a variants template",
         "duty_cycle": "a duty-cycle case (a press, riveter or shear)"}


def kind_of(data) -> str | None:
    """The kind of case a parsed TOML document is, by its top-level tables: "variants" (it
    has a [variants] table), "run", "task2", "aggregate", "duty_cycle", or None if its tables say
    nothing.

    >>> kind_of({"machine": {}, "crank": {}, "dyads": []})
    'run'
    >>> kind_of({"speed": {}, "driving": {}, "resistance": {}})
    'task2'
    >>> kind_of({"motor": {}, "coupling": {}, "machine": {}})
    'aggregate'
    """
    if not isinstance(data, dict):
        return None
    if "variants" in data:
        return "variants"
    votes = {k: sum(t in data for t in own) for k, own in _OWN_TABLES.items()}
    best = max(votes, key=votes.get)
    if votes[best] == 0 or list(votes.values()).count(votes[best]) > 1:
        return None
    return best


def wrong_kind(data, expected: str, source: str) -> str | None:
    """The one-line message for a document of another kind than ``expected`` ("this is a
    task-2 case: use `flywheel task2 --case FILE`"), or None if it looks like ``expected``."""
    kind = kind_of(data)
    if kind is None or kind == expected:
        return None
    from flywheel.errors import Notice

    return Notice.of(
        "wrong_kind", "{source}: this is {kind_name}, not {expected_name}: use `{command}`",
        source=source, kind=kind, expected=expected, command=COMMANDS[kind].format(file=source),
        kind_name=NAMES[kind], expected_name=NAMES[expected])
