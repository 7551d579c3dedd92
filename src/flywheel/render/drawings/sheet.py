"""The sheet: its format (ГОСТ 2.301-68), the frame, the title block of form 1 and the
additional column 26 (ГОСТ 2.104-2006), and the field the views are laid out in.

Formats (ГОСТ 2.301-68, table 1), landscape: A1 841 × 594, A2 594 × 420, A3 420 × 297 mm. The
frame: 20 mm from the left edge (binding), 5 mm from the others (ГОСТ 2.104-2006, п. 4.3).
Form 1 (ГОСТ 2.104-2006, appendix A, form 1): 185 × 55 mm in the frame's lower right corner;
columns from its left edge 7, 10, 23, 15, 10 mm (Изм., Лист, № докум., Подп., Дата: the left
part every form shares, forms.py), 70 mm
(the name, 25 mm high, over the material, 15 mm), 50 mm (Лит. 3 × 5, Масса 17, Масштаб 18 mm;
Лист 20, Листов 30 mm; the organisation 15 mm high); the designation 120 × 15 mm across the
top. Column 26 (the designation turned 180°): 70 × 14 mm in the frame's upper left corner.
"""
from __future__ import annotations

from flywheel.render.catalogue import words
from flywheel.render.drawings.forms import LEFT_COLUMNS, ROLE_FIELDS, ROLES_FORM1, left_edges
from flywheel.render.drawings.model import View, text_width

#: landscape sheet sizes [mm] (ГОСТ 2.301-68)
FORMATS = {"A1": (841.0, 594.0), "A2": (594.0, 420.0), "A3": (420.0, 297.0)}
LEFT, MARGIN = 20.0, 5.0                 # the frame's distance from the edges [mm]
BLOCK_W, BLOCK_H = 185.0, 55.0           # form 1 [mm]
COL26_W, COL26_H = 70.0, 14.0            # column 26 [mm]
GAP = 5.0                                # between the frame, the title block and the views [mm]
#: the room the views take at each format [mm]: a φ diagram's height, the scheme's square, the
#: longest vector of a plan or polygon, a group drawn apart — the larger the sheet, the larger
#: the drawing (never a lettering smaller: that stays as it is)
ROOM = {"A1": {"plot_h": 100.0, "scheme": 220.0, "plan": 180.0, "group": 150.0},
        "A2": {"plot_h": 70.0, "scheme": 170.0, "plan": 130.0, "group": 110.0},
        "A3": {"plot_h": 55.0, "scheme": 140.0, "plan": 110.0, "group": 90.0}}

T = words("drawings", {
    "rev": "Ch.", "sheet": "Sheet", "sheet_col": "Sh.", "doc_no": "Doc. No.", "sign": "Sign.", "date": "Date",
    "drawn": "Drawn", "checked": "Checked", "tech_control": "T. contr.",
    "norm_control": "N. contr.", "approved": "Appr.", "stage": "Stage", "mass": "Mass",
    "scale": "Scale", "sheets": "Sheets", "stage_letter": "S",
    "sheet1": "Dynamic analysis of the mechanism",
    "sheet2": "Force analysis of the mechanism",
    "group": "group {g}",
})


def words_of(lang: str) -> dict:
    return T["ru" if lang == "ru" else "en"]


def field_of(size: str) -> tuple[float, float, float, float]:
    """The drawing field inside the frame (x0, y0, x1, y1) [mm], GAP from the frame."""
    W, H = FORMATS[size]
    return LEFT + GAP, MARGIN + GAP, W - MARGIN - GAP, H - MARGIN - GAP


def keep_out(size: str) -> list[tuple[float, float, float, float]]:
    """The parts of the field no view may cover: the title block and column 26, with GAP."""
    W, H = FORMATS[size]
    return [(W - MARGIN - BLOCK_W - GAP, 0.0, W, MARGIN + BLOCK_H + GAP),
            (0.0, H - MARGIN - COL26_H - GAP, LEFT + COL26_W + GAP, H)]


SQUEEZE_MIN = 0.8      # the narrowest letters a title block's cell may take [width factor]


def fit(text: str, width: float, heights=(3.5, 2.5)) -> tuple[str, float, float]:
    """(text, height, squeeze): ``text`` at the largest of ``heights`` that fits ``width``
    [mm]; else at the smallest with the letters narrowed down to SQUEEZE_MIN; else cut with
    «…» (the title block's cells are fixed)."""
    for h in heights:
        if text_width(text, h) <= width:
            return text, h, 1.0
    h = heights[-1]
    need = text_width(text, h)
    if need * SQUEEZE_MIN <= width:
        return text, h, width / need
    while text and text_width(text + "…", h) * SQUEEZE_MIN > width:
        text = text[:-1]
    text = text.rstrip() + "…"
    return text, h, min(1.0, width / text_width(text, h))


def _cut(text: str, width: float, height: float) -> str:
    """``text`` cut with «…» to ``width`` [mm] at ``height``, letters not narrowed."""
    while text and text_width(text + "…", height) > width:
        text = text[:-1]
    return text.rstrip() + "…"


def wrap(text: str, width: float, height: float, lines: int) -> list[str]:
    """``text`` broken at spaces into at most ``lines`` lines of ``width`` [mm] at ``height``;
    the last one cut with «…» if it still does not fit."""
    out: list[str] = []
    cur = ""
    for w in text.split():
        trial = f"{cur} {w}".strip()
        if text_width(trial, height) <= width or not cur:
            cur = trial
        else:
            out.append(cur)
            cur = w
    if cur:
        out.append(cur)
    if len(out) > lines:
        out = out[:lines - 1] + [" ".join(out[lines - 1:])]
    if out and text_width(out[-1], height) > width:
        out[-1] = _cut(out[-1], width, height)
    return out


def frame_view(size: str, lang: str, *, document, title: str, sheet_name: str, number: int,
               count: int, scale: str) -> View:
    """The frame, the title block (form 1) filled in, and column 26 of a sheet."""
    W, H = FORMATS[size]
    t = words_of(lang)
    v = View("frame")
    v.line((0, 0), (W, 0), (W, H), (0, H), line="thin", closed=True)          # the trim line
    v.line((LEFT, MARGIN), (W - MARGIN, MARGIN), (W - MARGIN, H - MARGIN), (LEFT, H - MARGIN),
           closed=True)
    x0, y0 = W - MARGIN - BLOCK_W, MARGIN
    X = lambda x: x0 + x                     # noqa: E731 — the block's own coordinates
    Y = lambda y: y0 + y                     # noqa: E731
    v.line((X(0), Y(0)), (X(0), Y(55)), (X(185), Y(55)))                     # outline
    xs = left_edges()                                      # the left part (forms.py)
    v.line((X(xs[1]), Y(30)), (X(xs[1]), Y(55)))           # Изм. | Лист: above the roles only
    for x in xs[2:]:                                                          # left columns
        v.line((X(x), Y(0)), (X(x), Y(55)))
    for y in (5, 10, 15, 20, 25, 40, 45, 50):                                 # thin rows
        v.line((X(0), Y(y)), (X(65), Y(y)), line="thin")
    for y in (30, 35):
        v.line((X(0), Y(y)), (X(65), Y(y)))
    v.line((X(65), Y(40)), (X(185), Y(40)))                                   # designation
    v.line((X(65), Y(15)), (X(185), Y(15)))
    v.line((X(135), Y(0)), (X(135), Y(40)))
    v.line((X(135), Y(35)), (X(185), Y(35)))
    v.line((X(135), Y(20)), (X(185), Y(20)))
    v.line((X(150), Y(20)), (X(150), Y(40)))
    v.line((X(167), Y(20)), (X(167), Y(40)))
    v.line((X(140), Y(20)), (X(140), Y(35)), line="thin")
    v.line((X(145), Y(20)), (X(145), Y(35)), line="thin")
    v.line((X(155), Y(15)), (X(155), Y(20)))

    def cell(x, y, w, text, h=2.5, align="left"):
        if not text:
            return
        text, h, q = fit(text, w - 1.0, (h, 2.5) if h > 2.5 else (h,))
        ax = {"left": X(x) + 0.5, "center": X(x) + w / 2}[align]
        v.text(ax, Y(y) + 2.5, text, h, halign=align, valign="middle", squeeze=q)

    for x, (w, key) in zip(xs, LEFT_COLUMNS):
        cell(x, 30, w, t[key], align="center")
    for k, key in enumerate(ROLES_FORM1):
        y = 25 - 5 * k
        if key:
            cell(0, y, xs[2], t[key])
        name = getattr(document, ROLE_FIELDS[key]) if key else ""
        cell(xs[2], y, LEFT_COLUMNS[2][0], name, 3.5)
    for x, w, key in ((135, 15, "stage"), (150, 17, "mass"), (167, 18, "scale")):
        cell(x, 35, w, t[key], align="center")
    v.text(X(137.5), Y(27.5), t["stage_letter"], 5.0, halign="center", valign="middle")
    if scale:
        v.text(X(176), Y(27.5), scale, 5.0, halign="center", valign="middle")
    # ГОСТ 2.104-2006, 5.2: column 7 (Лист) is left blank on a document of one sheet, column 8
    # (Листов) is filled on the first sheet only
    cell(135, 15, 20, t["sheet"] if count == 1 else f"{t['sheet']} {number}")
    cell(155, 15, 30, f"{t['sheets']} {count}" if number == 1 else t["sheets"])
    designation = document.designation_or_default
    d, h, q = fit(designation, 116.0, (7.0, 5.0, 3.5))
    v.text(X(125), Y(47.5), d, h, halign="center", valign="middle", squeeze=q)
    for line, h, y in name_lines(title, sheet_name, Y(27.5)):
        v.text(X(100), y, line, h, halign="center", valign="middle")
    org_lines = organisation_lines(document, t)
    for k, line in enumerate(org_lines):
        v.text(X(160), Y(7.5) + (len(org_lines) / 2 - k - 0.5) * 4.6, line, 3.5,
               halign="center", valign="middle")
    # column 26: the designation turned 180°, in the frame's upper left corner
    cx0, cy1 = LEFT, H - MARGIN
    v.line((cx0, cy1 - COL26_H), (cx0 + COL26_W, cy1 - COL26_H), (cx0 + COL26_W, cy1))
    d26, h26, q26 = fit(designation, COL26_W - 4.0, (5.0, 3.5, 2.5))
    v.text(cx0 + COL26_W / 2, cy1 - COL26_H / 2, d26, h26, angle=180.0, halign="center",
           valign="middle", squeeze=q26)
    return v


def organisation_lines(document, t: dict) -> list[str]:
    """The organisation cell (50 × 15 mm, forms 1 and 2): the university and the group of
    ``document`` (a ``[document]`` table or a title page), at most three lines at 3.5 mm."""
    org = [s for s in (document.university,
                       t["group"].format(g=document.group) if document.group else "") if s]
    return [ln for s in org for ln in wrap(s, 46.0, 3.5, 2)][:3]


def name_lines(title: str, sheet_name: str, centre: float) -> list[tuple[str, float, float]]:
    """The name field of a title block (70 × 25 mm, forms 1 and 2) as (line, height, y of its
    middle) [mm], y up from ``centre``, the field's middle: the machine at 5 mm (two lines) or
    3.5 mm (three or four), then the sheet's or document's name at 3.5 mm; a title longer
    still, and the name with it, at 2.5 mm (ГОСТ 2.304's next size). Only a title that 2.5 mm
    does not hold either is cut with «…» (the shaper's «… механизм с быстрым обратным ходом и
    ползуном» had been cut at 3.5 mm)."""
    def trial(th: float, most: int):
        sh = min(th, 3.5)
        return wrap(title, 66.0, th, most), th, wrap(sheet_name, 66.0, sh, 2), sh

    for title_lines, th, sheet_lines, sh in (trial(th, most) for th, most in
                                              ((5.0, 2), (3.5, 3), (3.5, 4), (2.5, 4))):
        whole = " ".join(title_lines) == " ".join(title.split())
        if whole and 1.25 * (th * len(title_lines) + sh * len(sheet_lines)) <= 24.0:
            break
    else:                             # none holds it whole: three lines at 3.5 mm, cut below
        title_lines, th, sheet_lines, sh = trial(3.5, 3)
    lines = [(ln, th) for ln in title_lines] + [(ln, sh) for ln in sheet_lines]
    # the lines 1.6 of their height apart, closer (down to 1.25) to stay within 24 mm
    k = max(1.25, min(1.6, 24.0 / sum(h for _, h in lines)))
    while k * sum(h for _, h in lines) > 24.0 and len(lines) > 2:
        cut = len(title_lines) - 1                  # the title's last line goes, cut with «…»
        title_lines = title_lines[:cut]
        title_lines[-1] = _cut(title_lines[-1] + " …", 66.0, th) \
            if text_width(title_lines[-1] + " …", th) > 66.0 else title_lines[-1] + " …"
        lines = [(ln, th) for ln in title_lines] + [(ln, sh) for ln in sheet_lines]
    step = [h * k for _, h in lines]
    y = centre + sum(step) / 2
    out = []
    for (line, h), dy in zip(lines, step):
        y -= dy
        out.append((line, h, y + dy / 2))
    return out
