"""The layout step: the views of a sheet packed into its field, each at the highest, then
leftmost, free place (candidate corners: the field's top left, the right side and the foot
of every view placed), GAP apart, none over another nor over the title block or column 26
(sheet.keep_out). A view that finds no place goes to the next sheet of the same name. Views
are never shrunk (their lettering stays ≥ 2.5 mm on paper); a view larger than a whole field
is left out and named in ``left_out``.
"""
from __future__ import annotations

from flywheel.render.drawings.model import View
from flywheel.render.drawings.sheet import GAP, field_of, keep_out


def _overlaps(a, b) -> bool:
    return a[0] < b[2] - 1e-9 and b[0] < a[2] - 1e-9 and a[1] < b[3] - 1e-9 \
        and b[1] < a[3] - 1e-9


#: the gap [mm] between two views side by side whose tops — their captions, lettered 5 mm
#: high — are within CAPTION_H of each other: at GAP the two captions read as one line
#: («…с приложенными силами, 1:4 План сил звеньев 2, 3»); where the field has no room for it,
#: the second view goes CAPTION_H lower
CAPTION_GAP, CAPTION_H = 12.0, 7.0


def _free(box, taken) -> bool:
    return not any(_overlaps(box, (b[0] - GAP, b[1] - GAP, b[2] + GAP, b[3] + GAP))
                   for b in taken)


def _place(w: float, h: float, field, taken, views: int = 0
           ) -> tuple[float, float, float, float] | None:
    """The highest, then leftmost, box w × h in ``field`` clear of ``taken`` (with GAP); a
    box beside one of the views (``taken[views:]``) with its top near that view's moved
    CAPTION_GAP clear of it, or else CAPTION_H lower, where it is free there (else left where
    it is)."""
    fx0, fy0, fx1, fy1 = field
    xs = sorted({fx0, *(b[2] + GAP for b in taken)})
    tops = sorted({fy1, *(b[1] - GAP for b in taken)}, reverse=True)
    for top in tops:
        if top - h < fy0 - 1e-9 or top > fy1 + 1e-9:
            continue
        for x in xs:
            if x < fx0 - 1e-9 or x + w > fx1 + 1e-9:
                continue
            box = (x, top - h, x + w, top)
            if not _free(box, taken):
                continue
            near = [b[2] for b in taken[views:] if abs(b[3] - top) < CAPTION_H
                    and 0.0 <= x - b[2] < CAPTION_GAP]
            if near:          # set apart: to the right, else lower by a caption's line
                right = (max(near) + CAPTION_GAP, top - h, max(near) + CAPTION_GAP + w, top)
                lower = (x, top - CAPTION_H - h, x + w, top - CAPTION_H)
                for apart in (right, lower):
                    if apart[2] <= fx1 + 1e-9 and apart[1] >= fy0 - 1e-9 \
                            and _free(apart, taken):
                        return apart
            return box
    return None


def pack(views: list[View], size: str) -> tuple[list[list[View]], list[str]]:
    """The views placed on as many sheets as they need, in their order; and the names of the
    views too large for any sheet."""
    field = field_of(size)
    fx0, fy0, fx1, fy1 = field
    sheets: list[list[View]] = []
    left_out: list[str] = []
    todo = []
    for v in views:
        w, h = v.size
        if w > fx1 - fx0 or h > fy1 - fy0:
            left_out.append(v.name)
        else:
            todo.append(v)
    while todo:
        # the title block and column 26: shrunk by GAP, as _place keeps GAP from every box
        taken = [(b[0] + GAP, b[1] + GAP, b[2] - GAP, b[3] - GAP) for b in keep_out(size)]
        fixed = len(taken)
        placed: list[View] = []
        rest: list[View] = []
        for v in todo:
            w, h = v.size
            box = _place(w, h, field, taken, fixed)
            if box is None:
                rest.append(v)
                continue
            placed.append(v.placed(box[0], box[1]))
            taken.append(box)
        if not placed:                    # cannot happen: a view within the field fits alone
            left_out.extend(r.name for r in rest)
            break
        sheets.append(placed)
        todo = rest
    return sheets, left_out
