"""CSV text in two dialects, written with the csv module:

* ``plain`` — comma separators, decimal points, no byte-order mark (the default: what
  scripts and most spreadsheets read);
* ``excel-ru`` — semicolon separators, decimal commas and a UTF-8 byte-order mark, so a
  Russian Excel opens the file with the columns split and the numbers as numbers.

Numbers are passed as ``float``/``int`` and formatted here (``fmt``), spelled for ``excel-ru`` by
the one number formatter's module (render/numbers.py ``excel_ru``); strings stay as they are.

>>> csv_text([["student", "J"], ["Иванов", 0.5]], "excel-ru")
'\\ufeffstudent;J\\r\\nИванов;0,5\\r\\n'
>>> csv_text([["a", "b"], [1, 2.5]])
'a,b\\n1,2.5\\n'
>>> restyle("position,x [m]\\n0° = 3 outer d.c.,-1.5e-05\\n", "excel-ru")
'\\ufeffposition;x [m]\\r\\n0° = 3 outer d.c.;-1,5e-05\\r\\n'
"""
from __future__ import annotations

import csv
import io
import re
from collections.abc import Callable, Iterable, Iterator, Sequence

from flywheel.render.numbers import excel_ru
from flywheel.render.choices import CSV_STYLES

STYLES = CSV_STYLES


def csv_text(rows: Iterable[Sequence], style: str = "plain",
             fmt: Callable[[float], str] = repr) -> str:
    """The rows as CSV text in ``style`` (see the module's docstring)."""
    if style not in STYLES:
        # library use only: no CLI input reaches this
        raise ValueError(f"unknown CSV style {style!r} (allowed: {', '.join(STYLES)})")
    ru = style == "excel-ru"
    buf = io.StringIO()
    w = csv.writer(buf, delimiter=";" if ru else ",", lineterminator="\r\n" if ru else "\n")
    for row in rows:
        out = []
        for v in row:
            if isinstance(v, bool) or v is None:
                out.append("" if v is None else str(int(v)))
            elif isinstance(v, (int, float)):
                t = str(v) if isinstance(v, int) else fmt(v)
                out.append(excel_ru(t) if ru else t)
            else:
                out.append(str(v))
        w.writerow(out)
    return ("\ufeff" if ru else "") + buf.getvalue()


_NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")


class _Spelled(float):
    """A number read from CSV text that keeps its spelling (so restyling changes only the
    separators and the decimal mark, never a digit)."""

    text: str

    def __new__(cls, text: str):
        obj = super().__new__(cls, text)
        obj.text = text
        return obj


def restyle(text: str, style: str) -> str:
    """CSV text written in the plain dialect, in ``style``: the same cells; a cell that is a
    number gets the style's decimal mark, every other cell stays as it is."""
    if style == "plain":
        return text
    rows = [[_Spelled(c) if _NUMBER.fullmatch(c) else c for c in row]
            for row in csv.reader(io.StringIO(text))]
    return csv_text(rows, style, fmt=lambda x: getattr(x, "text", repr(x)))


def _number_or_text(cell: str):
    """A CSV cell back as a float if it is one (for the decimal commas of excel-ru)."""
    try:
        return float(cell) if cell.strip() and cell.strip()[0] in "-0123456789" else cell
    except ValueError:
        return cell


def excel_ru_pieces(pieces: Iterable[str]) -> Iterator[str]:
    """Pieces of one plain CSV text (``flywheel grade --out``) restyled for a Russian Excel
    (';', decimal commas, a BOM at the start only), piece by piece."""
    for i, text in enumerate(pieces):
        rows = list(csv.reader(io.StringIO(text)))
        out = csv_text([[_number_or_text(c) for c in row] for row in rows], "excel-ru",
                       fmt=lambda x: f"{x!r}")
        yield out if i == 0 else out.removeprefix("\ufeff")
