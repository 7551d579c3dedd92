"""Answers that are tables, graded cell by cell (issue 27, step 4).

A run template asks for tables in ``[variants]``: ``tables = ["analogues", "delta_T",
"reactions"]`` (default none):

- ``analogues``: the velocity analogues at the numbered positions (0 … 11 every 30°, 0 … 23
  over 720°): every point's v_q [m/rad] and every link's ω_q [–] that varies over the cycle
  (the crank's pin, whose v_q is the crank's length, is left out);
- ``delta_T``: the work A [J], the second group's kinetic energy T_II [J] and the first
  group's ΔT_I [J] at the same positions;
- ``reactions``: the joint reactions R_x, R_y, R [N] at the first report angle, one row a
  joint (its key as forces.csv names it: ``O:0->1``, the force of link 0 on link 1).

The values are the solved variant's own arrays — the columns ``flywheel run`` writes to
table.csv (``Results.columns`` at the positions' grid nodes) and summary.json's
``results.at[0].joints`` — never recomputed. In the key every cell is an answer of its own,
named ``TABLE.ROW.COLUMN`` (``analogues.3.vq_B``, ``reactions.O:0->1.F``), so the native
sheet has a column per cell and the Moodle bank a numerical question per cell; answers.json's
``tables`` says which cells make which table (rows, columns, units, the tolerance of each
column: ``tolerances = { analogues = 0.02, "analogues.vq_B" = 0.05 }``).

A cell's error is relative to the larger of |key| and :data:`CELL_FLOOR` times the largest
|key| of its column in the variant: a cell whose key is near zero (an analogue at a dead
centre: 10⁻¹⁸ of round-off) is judged against its column's scale, not against the round-off.

Computation only: no typer, no rich.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from flywheel.errors import CaseFileError, InputError, Notice, led

KINDS = ("analogues", "delta_T", "reactions")
#: a cell is judged against max(|key|, CELL_FLOOR·max|key| of its column)
CELL_FLOOR = 0.01
DELTA_T_COLUMNS = ("A", "T_II", "dT_I")
REACTION_COLUMNS = ("Rx", "Ry", "R")
#: a reaction's column → its attribute of ``dynamics.results.JointAt``
_JOINT_ATTRIBUTE = {"Rx": "Fx", "Ry": "Fy", "R": "F"}


@dataclass(frozen=True)
class TableSpec:
    """One table of the key: ``name`` (one of KINDS), what a row is (``row_label``:
    "position" or "joint"), the rows' labels, each row's crank angle [deg], the columns (the
    nomenclature's keys), their SI units and tolerances (None: the key's default)."""

    name: str
    row_label: str
    rows: tuple[str, ...]
    phi_deg: tuple[float, ...]
    columns: tuple[str, ...]
    units: tuple[str, ...]
    tolerances: tuple[float | None, ...]

    def cell(self, row: str, column: str) -> str:
        return f"{self.name}.{row}.{column}"

    @property
    def cells(self) -> tuple[str, ...]:
        """Every cell's answer name, row by row."""
        return tuple(self.cell(r, c) for r in self.rows for c in self.columns)

    def to_document(self) -> dict:
        return {"row_label": self.row_label, "rows": list(self.rows),
                "phi_deg": list(self.phi_deg), "columns": list(self.columns),
                "units": list(self.units), "tolerances": list(self.tolerances)}

    @classmethod
    def from_document(cls, name: str, doc) -> "TableSpec":
        """From answers.json's ``tables.<name>`` (ValueError/TypeError/KeyError if broken)."""
        rows = tuple(str(r) for r in doc["rows"])
        cols = tuple(str(c) for c in doc["columns"])
        phi = tuple(float(x) for x in doc["phi_deg"])
        units = tuple(str(u) for u in doc["units"])
        tols = tuple(None if t is None else float(t) for t in doc["tolerances"])
        if (not rows or not cols or len(phi) != len(rows) or len(units) != len(cols)
                or len(tols) != len(cols) or doc["row_label"] not in ("position", "joint")
                or any(t is not None and not (math.isfinite(t) and t > 0) for t in tols)):
            raise ValueError
        return cls(name, doc["row_label"], rows, phi, cols, units, tols)


# -- the tables of a template -------------------------------------------------------------------

def parse_names(value, where: str, kind: str) -> tuple[str, ...]:
    """``[variants] tables``: a list of distinct table names; a task2 template has none."""
    if (not isinstance(value, list) or not all(isinstance(x, str) for x in value)):
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "var_tables_list", "must be an array of table names (allowed: {allowed}; got {got})",
            allowed=", ".join(KINDS), got=repr(value))))
    for x in value:
        if x not in KINDS:
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_table_unknown", "{name!r} is not a table (allowed: {allowed})", name=x,
                allowed=", ".join(KINDS))))
        if value.count(x) > 1:
            raise CaseFileError(led(f"{where}: ", Notice.of(
                "var_answer_twice", "{name!r} is listed twice", name=x)))
    if value and kind != "run":
        raise CaseFileError(led(f"{where}: ", Notice.of(
            "var_tables_task2", "tables are answers of a flywheel run template only (allowed "
            "here: none; a task2 template has no positions of a mechanism)")))
    return tuple(value)


def _positions(results):
    """The numbered positions (Position.number not None), in order."""
    return [p for p in results.position_angles if p.number is not None]


def specs_of(names, results, tolerances: dict, where: str) -> tuple[TableSpec, ...]:
    """The tables ``names`` of a template from its own solved Results; ``tolerances``: the
    template's per-answer ones (a table's name or ``table.column``). A table the case cannot
    give (no positions, no force analysis) is one CaseFileError line."""
    out = []
    for name in names:
        here = f"{where}: variants.tables: {name!r}"
        if name in ("analogues", "delta_T"):
            pos = _positions(results)
            if name == "analogues":
                cols = [k for k, c in results.columns.items()
                        if k.startswith(("vq_", "omega_q_")) and _varies(c.values)]
            else:
                cols = [k for k in DELTA_T_COLUMNS if k in results.columns]
            if not pos:
                raise CaseFileError(led(f"{here}: ", Notice.of(
                    "var_table_no_positions", "this case cannot give it (it has no numbered "
                    "positions of a mechanism; allowed: a table of a case with a linkage)")))
            if not cols or (name == "delta_T" and len(cols) < len(DELTA_T_COLUMNS)):
                raise CaseFileError(led(f"{here}: ", Notice.of(
                    "var_table_no_columns", "this case cannot give it (its results have no "
                    "{columns}; allowed: a table whose columns the case computes)",
                    columns=", ".join(DELTA_T_COLUMNS) if name == "delta_T" else "vq_*")))
            units = [results.columns[k].unit for k in cols]
            rows = [str(p.number) for p in pos]
            phi = [float(p.standard_deg if p.standard_deg is not None else math.degrees(p.phi))
                   for p in pos]
            spec = TableSpec(name, "position", tuple(rows), tuple(phi), tuple(cols),
                             tuple(units), ())
        else:
            at = results.at[0] if results.at else None
            if at is None or not at.joints:
                raise CaseFileError(led(f"{here}: ", Notice.of(
                    "var_table_no_forces", "this case cannot give it (it has no force analysis "
                    "at a report angle; allowed: a case with masses or forces and output.at_deg)")))
            rows = list(at.joints)
            spec = TableSpec(name, "joint", tuple(rows), (float(at.phi_deg),) * len(rows),
                             REACTION_COLUMNS, ("N",) * len(REACTION_COLUMNS), ())
        out.append(_with_tolerances(spec, tolerances, where))
    return tuple(out)


def _varies(values) -> bool:
    import numpy as np

    top = float(np.max(np.abs(values))) if values.size else 0.0
    return top > 0 and float(np.ptp(values)) > 1e-9 * top


def _with_tolerances(spec: TableSpec, tolerances: dict, where: str) -> TableSpec:
    from dataclasses import replace

    whole = tolerances.get(spec.name)
    for k in tolerances:
        if k.startswith(spec.name + ".") and k[len(spec.name) + 1:] not in spec.columns:
            raise CaseFileError(led(f"{where}: variants.tolerances.{k}: ", Notice.of(
                "var_table_column", "{column!r} is not a column of the table {table} (allowed: "
                "{allowed})", column=k[len(spec.name) + 1:], table=spec.name,
                allowed=", ".join(spec.columns))))
    tols = tuple(tolerances.get(f"{spec.name}.{c}", whole) for c in spec.columns)
    return replace(spec, tolerances=tuple(None if t is None else float(t) for t in tols))


def cells_of(specs, results, where: str) -> dict[str, float]:
    """{cell: value} of a solved variant by the template's tables (its Results' own arrays:
    table.csv's columns at the positions, summary.json's joints at the report angle); a table
    that does not fit the variant (a position or joint it lacks) is an InputError line."""
    out: dict[str, float] = {}
    for spec in specs:
        if spec.row_label == "position":
            nodes = {str(p.number): results.index_of(p.phi) for p in _positions(results)}
            for r in spec.rows:
                for c in spec.columns:
                    if r not in nodes or c not in results.columns:
                        raise InputError(led(f"{where}: ", Notice.of(
                            "var_table_mismatch", "the table {table} of the template has no "
                            "cell {row}, {column} in this variant", table=spec.name, row=r,
                            column=c)))
                    out[spec.cell(r, c)] = float(results.columns[c].values[nodes[r]])
        else:
            joints = results.at[0].joints if results.at and results.at[0].joints else {}
            for r in spec.rows:
                if r not in joints:
                    raise InputError(led(f"{where}: ", Notice.of(
                        "var_table_mismatch", "the table {table} of the template has no cell "
                        "{row}, {column} in this variant", table=spec.name, row=r,
                        column=spec.columns[0])))
                for c in spec.columns:
                    out[spec.cell(r, c)] = float(getattr(joints[r], _JOINT_ATTRIBUTE[c]))
    bad = next((k for k, v in out.items() if not math.isfinite(v)), None)
    if bad is not None:
        raise InputError(led(f"{where}: ", Notice.of(
            "not_finite_number", "must be a finite number (got {got})", got=f"{bad} = nan")))
    return out


# -- the tables of a key ------------------------------------------------------------------------

def parse_key_tables(doc, source: str) -> dict[str, TableSpec]:
    """answers.json's ``tables`` {name: TableSpec}; {} without; a broken one one line."""
    if doc is None:
        return {}
    out = {}
    try:
        if not isinstance(doc, dict):
            raise ValueError
        for name, t in doc.items():
            out[str(name)] = TableSpec.from_document(str(name), t)
    except (KeyError, TypeError, ValueError, AttributeError):
        raise CaseFileError(led(f"{source}: tables: ", Notice.of(
            "key_tables_broken", "must be the tables flywheel variants writes ({{name: {{\"rows\": "
            "…, \"columns\": …}}}}); allowed: that, or no tables"))) from None
    return out


@dataclass(frozen=True)
class TableMark:
    """How one table of a variant is marked: the answers' indices of its cells (row by row),
    their bits, and each cell's (row, column)."""

    name: str
    indices: tuple[int, ...]
    bits: int
    where: tuple[tuple[str, str], ...]

    def off(self, mask: int) -> tuple[tuple[str, tuple[str, ...]], ...]:
        """The cells not right, by column: ((column, (rows…)), …) in the table's order."""
        by: dict[str, list[str]] = {}
        for j, (r, c) in zip(self.indices, self.where):
            if not mask >> j & 1:
                by.setdefault(c, []).append(r)
        return tuple((c, tuple(rs)) for c, rs in by.items())

    def right(self, mask: int) -> int:
        return (mask & self.bits).bit_count()


def table_marks(tables: dict[str, TableSpec], names, keys):
    """(marks, floors, cell bits) of a variant whose answers are ``names`` with the key's
    values ``keys``: a TableMark per table, each answer's floor (0 for an answer that is no
    cell: CELL_FLOOR·max|key| of the cell's column) and the bits of all cells."""
    pos = {a: j for j, a in enumerate(names)}
    floors = [0.0] * len(names)
    marks, cells = [], 0
    for spec in tables.values():
        idx, where, bits = [], [], 0
        for c in spec.columns:
            js = [pos[spec.cell(r, c)] for r in spec.rows if spec.cell(r, c) in pos]
            top = max((abs(keys[j]) for j in js), default=0.0)
            for j in js:
                floors[j] = CELL_FLOOR * top
        for r in spec.rows:
            for c in spec.columns:
                j = pos.get(spec.cell(r, c))
                if j is not None:
                    idx.append(j)
                    where.append((r, c))
                    bits |= 1 << j
        if idx:
            marks.append(TableMark(spec.name, tuple(idx), bits, tuple(where)))
            cells |= bits
    return tuple(marks), tuple(floors), cells


def cell_floors(specs, values: dict) -> dict[str, float]:
    """{cell: floor} of a variant's cells (``values``: answer → key value): CELL_FLOOR times
    the largest |value| of the cell's column (the Moodle bank's absolute tolerance)."""
    out = {}
    for spec in specs:
        for c in spec.columns:
            names = [spec.cell(r, c) for r in spec.rows if spec.cell(r, c) in values]
            top = max((abs(values[n]) for n in names), default=0.0)
            out.update(dict.fromkeys(names, CELL_FLOOR * top))
    return out


def cell_error(given: float, key: float, floor: float) -> tuple[float, str]:
    """(error, kind) of a cell: |given − key|/max(|key|, floor) ("relative", or "column" when
    the floor is the larger), |given − key| when both are 0 ("absolute")."""
    scale = max(abs(key), floor)
    if scale == 0:
        return abs(given - key), "absolute"
    return abs(given - key) / scale, "relative" if abs(key) >= floor else "column"


# -- classic mistakes in a table's cells ----------------------------------------------------------

@dataclass(frozen=True)
class CellContext:
    """What a classic mistake of a cell needs: the variant's chain givens (None: the key has
    none), the row's crank angle [rad], the cell's key value, the key's values of the row and
    of the first row {column: value}."""

    givens: object
    phi: float
    key: float
    row: dict
    first: dict


def diagnose_cells(marking, given, mask: int, givens, close) -> tuple[tuple[int, str], ...]:
    """(answer j, mistake code) of the wrong cells a classic mistake of the catalogue
    (teaching/mistakes.py ``Mistake.cells``) reproduces within the cell's tolerance."""
    from flywheel.teaching.mistakes import CATALOGUE

    out = []
    keys = marking.keys
    for t in marking.tables:
        rows: dict[str, dict[str, float]] = {}
        for j, (r, c) in zip(t.indices, t.where):
            rows.setdefault(r, {})[c] = keys[j]
        first = next(iter(rows.values()), {})
        phis = marking.table_phi.get(t.name, {})
        for j, (r, c) in zip(t.indices, t.where):
            g = given[j]
            if mask >> j & 1 or g != g:
                continue
            ctx = CellContext(givens, math.radians(phis.get(r, 0.0)), keys[j], rows[r], first)
            kind = f"{t.name}.{c.split('_')[0] if t.name == 'analogues' else c}"
            for m in CATALOGUE:
                fn = m.cells.get(kind)
                if fn is None:
                    continue
                try:
                    cands = fn(ctx)
                except (ArithmeticError, ValueError, TypeError, KeyError, AttributeError):
                    continue
                if any(math.isfinite(x) and close(g, x, marking.tolerances[j], marking.floors[j])
                       for x in cands):
                    out.append((j, m.code))
                    break
    return tuple(out)
