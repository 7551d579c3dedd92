"""CSV tables and the JSON summary (text only: no physics here).

Numbers are written with 12 significant digits (``%.12g``), so the same input gives
byte-identical files.
"""
from __future__ import annotations

import json

import numpy as np

from flywheel.render.nomenclature import csv_header
from flywheel.render.numbers import fmt as _number, fmt_text


def _fmt(x: float) -> str:
    return _number(x, 12, zero=0.0, nonfinite="show")


def table_csv(results) -> str:
    """Every column on the grid; the header names each quantity with its unit: ``key [unit]``
    (the nomenclature's SI unit)."""
    cols = results.columns
    header = ",".join(csv_header(key) for key in cols)
    data = np.column_stack([c.values for c in cols.values()])
    return header + "\n" + _rows_text(data)


def _rows_text(data: np.ndarray) -> str:
    """Each row of ``data`` as :func:`_fmt` writes its numbers, joined by commas, each ended by
    a newline: made a block of rows at a time (numbers.fmt_text; the in-line four's table has
    150 columns), the same text."""
    return fmt_text(data, 12)


def positions_csv(results) -> str:
    """The standard positions (every 30° and the sliders' dead centres): their label, their
    number as plan_positions.png draws it (:func:`number_cell`), every column there."""
    cols = results.columns
    header = "position,number," + ",".join(csv_header(key) for key in cols)
    lines = [header]
    for pos in results.position_angles:
        i = results.index_of(pos.phi)
        lines.append(f"{pos.label},{number_cell(pos.number)},"
                     + ",".join(_fmt(c.values[i]) for c in cols.values()))
    return "\n".join(lines) + "\n"


def number_cell(k: int | None) -> str:
    """A position's number in the CSVs (``Results.position_numbers``): empty where the
    position has none (a dead centre between the 30° positions, a tabulated case)."""
    return "" if k is None else str(k)


def summary_json(results) -> str:
    """summary.json: the results' document ({"title", "source", "units", "results": {…, "at":
    […]}, "warnings"}) as indented UTF-8 JSON text."""
    return json.dumps(results.to_document(), indent=2, ensure_ascii=False) + "\n"
