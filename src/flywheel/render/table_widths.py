"""The columns' widths of a DOCX table, fixed in the file (the Russian ГОСТ record and the
English one): Word and LibreOffice then draw the same table. With the widths left to the
program ("auto") LibreOffice gives every column the same share, and a narrow share breaks
words inside: «положе|ние», «внутрен|няя» in the kinematics table's first column.

The widths follow the automatic table layout of CSS 2.1 (§17.5.2.2) and of word processors:
each column's least width is its longest word, its wanted width its longest line; a table
whose wanted widths fit is that wide, with 30 % to spare (:data:`ROOMY`), else each column gets
its least width (with as much of that spare as fits) and a share of the rest in proportion to
what it wants more. A text's width is estimated from the
advance widths of Times New Roman (metric-compatible Liberation Serif, its hmtx table), by
classes of characters, so the widths do not depend on the fonts installed where the record is
written: the same table, the same bytes.
"""
from __future__ import annotations

from flywheel.render import mathfmt

#: advance widths [em] of Times New Roman by class of character (Liberation Serif's hmtx:
#: the classes' means, rounded up)
_EM = {"digit": 0.5, "thin": 0.25, "colon": 0.28, "bracket": 0.34, "degree": 0.4,
       "operator": 0.57, "dash": 0.5, "emdash": 1.0, "lower": 0.46, "upper": 0.67,
       "cyr_lower": 0.53, "cyr_upper": 0.72, "greek": 0.53, "other": 0.6}
#: a bold text is this much wider (Liberation Serif Bold's Cyrillic: 0.569 against 0.529 em)
BOLD = 1.08
#: a subscript's size against its text's (Word's and LibreOffice's subscript: 58 – 65 %)
SUBSCRIPT = 0.65
#: a cell's left and right margins in Word's and LibreOffice's table grid style (0.19 cm
#: each) [twips]; a wide table's, narrowed to 1 mm each (report_gost.py)
MARGIN, NARROW_MARGIN = 108, 57
#: slack for the estimate [twips]
SLACK = 40
#: a column's wanted width this much wider where the table still fits: the font a program
#: puts for a missing Times New Roman or Calibri (DejaVu Serif without fonts-liberation or
#: fonts-crosextra-carlito) is up to a quarter wider
ROOMY = 1.3


def _em(ch: str) -> float:
    """The advance width [em] of one character, by its class."""
    if ch.isdigit():
        kind = "digit"
    elif ch in " .,·'’!|":
        kind = "thin"
    elif ch in ":;/":
        kind = "colon"
    elif ch in "()[]{}":
        kind = "bracket"
    elif ch in "°²³¹":
        kind = "degree"
    elif ch in "=+−-<>±×≈≤≥":
        kind = "operator" if ch != "-" else "colon"
    elif ch == "–":
        kind = "dash"
    elif ch in "—%":
        kind = "emdash" if ch == "—" else "operator"
    elif "a" <= ch <= "z":
        kind = "lower"
    elif "A" <= ch <= "Z":
        kind = "upper"
    elif "а" <= ch <= "я" or ch == "ё":
        kind = "cyr_lower"
    elif "А" <= ch <= "Я" or ch == "Ё":
        kind = "cyr_upper"
    elif "\u0370" <= ch <= "\u03ff":
        kind = "greek"
    else:
        kind = "other"
    return _EM[kind]


def text_width(text: str, half_points: int, bold: bool = False) -> float:
    """The width [twips] of ``text`` (a cell's: **bold** parts, the symbols' subscripts as
    :func:`flywheel.render.mathfmt.subscripts` cuts them) set in ``half_points``."""
    size = half_points * 10.0                          # twips per em: half-points × 20 / 2
    total = 0.0
    for i, part in enumerate(text.split("**")):
        heavy = BOLD if (bold or i % 2 == 1) else 1.0
        for seg, sub in mathfmt.subscripts(part) if part else ():
            total += sum(_em(ch) for ch in seg) * size * heavy * (SUBSCRIPT if sub else 1.0)
    return total


def section_width(section) -> int:
    """The text's width [twips] of a python-docx section: its page less its margins (lengths
    in EMU, 635 a twip)."""
    return round((section.page_width - section.left_margin - section.right_margin) / 635)


def _words(text: str) -> list[str]:
    """The pieces a line of ``text`` may break between (at spaces; a subscript's markup kept
    whole: «v_qS2»)."""
    return [w for w in text.split(" ") if w] or [""]


def column_widths(rows: list[tuple[str, ...]], width: int, half_points: int,
                  bold_rows: int = 1, margin: int = MARGIN) -> list[int]:
    """The widths [twips] of the columns of a table of ``rows`` (the first ``bold_rows`` bold:
    the header) set in ``half_points`` with cells' left and right ``margin`` [twips], within
    ``width`` [twips] (the text's width): the wanted widths where they fit; else each column's
    longest word and a share of the rest in proportion to what it wants more (the module's
    docstring). Whole twips, the same for the same table; their sum at most ``width`` unless
    the longest words alone are wider."""
    n = max(len(r) for r in rows)
    least, wanted = [0.0] * n, [0.0] * n
    for k, row in enumerate(rows):
        bold = k < bold_rows
        for c, text in enumerate(row):
            least[c] = max(least[c], max(text_width(w, half_points, bold) for w in _words(text)))
            wanted[c] = max(wanted[c], text_width(text, half_points, bold))
    pad = 2 * margin + SLACK
    least = [w + pad for w in least]
    wanted = [max(w + pad, lw) for w, lw in zip(wanted, least)]
    if sum(wanted) * ROOMY <= width:           # room to spare: for a wider font than Times
        out = [w * ROOMY for w in wanted]
    else:          # each column its longest word, as roomy as fits, then the rest shared out
        k = min(ROOMY, width / sum(least))     # below 1: even the words do not fit
        floor = [lw * k for lw in least]
        more = [max(w * ROOMY - f, 0.0) for w, f in zip(wanted, floor)]
        rest = width - sum(floor)
        share = min(1.0, rest / sum(more)) if rest > 0 and sum(more) > 0 else 0.0
        out = [f + m * share for f, m in zip(floor, more)]
    return [int(w) for w in out]
