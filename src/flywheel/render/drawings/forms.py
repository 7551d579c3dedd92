"""The title blocks of ГОСТ 2.104-2006 as tables of cells: the columns every form shares (its
left part, columns 14–18 and the signatures), form 2 (a text document's first sheet,
185 × 40 mm) and form 2a (its further sheets, 185 × 15 mm). The drawing sheets' form 1
(185 × 55 mm) is drawn by sheet.py from the same left part; the записка's frame
(render/report_frame.py, ``--frame eskd``) sets forms 2 and 2a from these cells in typst and
in Word.

The left part of every form (ГОСТ 2.104-2006, appendix A): columns 7, 10, 23, 15, 10 mm (Изм.,
Лист, № докум., Подп., Дата), rows 5 mm: the rows of changes above the row of headings, the
signatures below it (Разраб., Пров., Т. контр., Н. контр., Утв.: form 1 has a free row between
Т. контр. and Н. контр.; form 2 has one free row, the third, which carries Т. контр. here).

Form 2 (185 × 40 mm): the left part (2 rows of changes, the headings, 5 signatures); the
designation 120 × 15 mm across the top; the name 70 × 25 mm (the product and «Пояснительная
записка»); Лит. 3 × 5 mm, Лист 15 mm, Листов 20 mm (a row of headings and a row of values,
5 mm each); the organisation 50 × 15 mm. Form 2a (185 × 15 mm): the left part (2 rows of
changes, the headings), the designation 110 × 15 mm, Лист 10 mm (its heading 7 mm high, the
number 8 mm).
"""
from __future__ import annotations

from dataclasses import dataclass

#: columns 14–18 of every form, left to right: (width [mm], the heading's key in sheet.T)
LEFT_COLUMNS = ((7.0, "rev"), (10.0, "sheet_col"), (23.0, "doc_no"), (15.0, "sign"),
                (10.0, "date"))
ROW = 5.0                                 # the rows of the left part [mm]
#: the signatures of column 10, top to bottom (None: the free row)
ROLES_FORM1 = ("drawn", "checked", "tech_control", None, "norm_control", "approved")
ROLES_FORM2 = ("drawn", "checked", "tech_control", "norm_control", "approved")
#: the ``[document]`` field (cases/document.py) naming who signs each role
ROLE_FIELDS = {"drawn": "student", "checked": "teacher", "tech_control": "tech_control",
               "norm_control": "norm_control", "approved": "approved"}
WIDTH = 185.0                             # every form's width [mm]


def left_edges() -> list[float]:
    """The x of the left part's column edges from the form's left edge [mm]: 0, 7, …, 65."""
    out = [0.0]
    for w, _ in LEFT_COLUMNS:
        out.append(out[-1] + w)
    return out


@dataclass(frozen=True)
class Cell:
    """One cell of a form: its box [mm] from the form's upper left corner (y down), what it
    holds — ``"label:<key>"`` (a heading of sheet.T), or a field: a ``[document]`` field of
    ROLE_FIELDS, ``designation``, ``title`` (the name), ``sheet``, ``sheets``, ``organisation``
    — its lettering height [mm] (ГОСТ 2.304) and alignment; "" an empty cell."""

    x: float
    y: float
    w: float
    h: float
    text: str = ""
    size: float = 2.5
    align: str = "center"


@dataclass(frozen=True)
class Form:
    """A title block: its height [mm], its cells, and the segments drawn in thin line (x0, y0,
    x1, y1) [mm]; every other edge of a cell is a main line (as the forms of ГОСТ 2.104-2006
    draw them: thin between the rows of changes and of signatures, and inside «Лит.»)."""

    name: str
    height: float
    cells: tuple[Cell, ...]
    thin: tuple[tuple[float, float, float, float], ...]

    def is_thin(self, x0: float, y0: float, x1: float, y1: float) -> bool:
        """Whether the edge from (x0, y0) to (x1, y1) lies on a thin segment."""
        for a, b, c, d in self.thin:
            if y0 == y1 == b == d and a <= min(x0, x1) and max(x0, x1) <= c:
                return True
            if x0 == x1 == a == c and b <= min(y0, y1) and max(y0, y1) <= d:
                return True
        return False


def _left_part(changes: int, roles: tuple) -> tuple[list[Cell], list[tuple]]:
    """The cells of the left part: ``changes`` rows of changes, the headings, the signatures of
    ``roles``; and its thin segments (between two rows of changes, between two signatures)."""
    xs = left_edges()
    cells, thin = [], []
    for r in range(changes):
        cells += [Cell(xs[c], r * ROW, w, ROW) for c, (w, _) in enumerate(LEFT_COLUMNS)]
        if r < changes - 1:
            thin.append((0.0, (r + 1) * ROW, xs[-1], (r + 1) * ROW))
    y = changes * ROW
    cells += [Cell(xs[c], y, w, ROW, f"label:{key}") for c, (w, key) in enumerate(LEFT_COLUMNS)]
    for k, role in enumerate(roles):
        y = (changes + 1 + k) * ROW
        cells += [Cell(0.0, y, xs[2], ROW, f"label:{role}" if role else "", align="left"),
                  Cell(xs[2], y, LEFT_COLUMNS[2][0], ROW, ROLE_FIELDS[role] if role else "", 3.5,
                       "left"),
                  Cell(xs[3], y, LEFT_COLUMNS[3][0], ROW), Cell(xs[4], y, LEFT_COLUMNS[4][0], ROW)]
        if k < len(roles) - 1:
            thin.append((0.0, y + ROW, xs[-1], y + ROW))
    return cells, thin


def form2() -> Form:
    """Form 2: a text document's first sheet (185 × 40 mm)."""
    cells, thin = _left_part(2, ROLES_FORM2)
    x = left_edges()[-1]                                       # 65
    cells += [Cell(x, 0.0, WIDTH - x, 15.0, "designation", 7.0),
              Cell(x, 15.0, 70.0, 25.0, "title", 5.0),
              Cell(x + 70, 15.0, 15.0, ROW, "label:stage"),
              Cell(x + 85, 15.0, 15.0, ROW, "label:sheet"),
              Cell(x + 100, 15.0, 20.0, ROW, "label:sheets"),
              Cell(x + 70, 20.0, 5.0, ROW, "label:stage_letter", 3.5),
              Cell(x + 75, 20.0, 5.0, ROW), Cell(x + 80, 20.0, 5.0, ROW),
              Cell(x + 85, 20.0, 15.0, ROW, "sheet", 3.5),
              Cell(x + 100, 20.0, 20.0, ROW, "sheets", 3.5),
              Cell(x + 70, 25.0, 50.0, 15.0, "organisation", 3.5)]
    thin += [(x + 75, 20.0, x + 75, 25.0), (x + 80, 20.0, x + 80, 25.0)]    # Лит.'s cells
    return Form("form 2", 40.0, tuple(cells), tuple(thin))


def form2a() -> Form:
    """Form 2a: a text document's further sheets (185 × 15 mm)."""
    cells, thin = _left_part(2, ())
    x = left_edges()[-1]
    cells += [Cell(x, 0.0, 110.0, 15.0, "designation", 7.0),
              Cell(x + 110, 0.0, 10.0, 7.0, "label:sheet"),
              Cell(x + 110, 7.0, 10.0, 8.0, "sheet", 3.5)]
    return Form("form 2a", 15.0, tuple(cells), tuple(thin))
