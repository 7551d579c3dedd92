"""The standard positions in a record's words: a position's label («90° = ползун 5: внутренняя
мёртвая точка», positions.csv's in English) and the first cells of a record's tables of the
positions with the sentence that names their dead centres (render/document.py,
render/report_kinematics.py, render/forces.py)."""
from __future__ import annotations

import math
import re

from flywheel.render.nomenclature import DEAD_CENTRES

#: a dead centre in a position's label: (English, Russian)
DEAD_CENTRE_LABEL = ("{s} {kind} d.c.", "ползун {s}: {kind} мёртвая точка")


def position_label(position, lang: str = "en") -> str:
    """A standard position's label in ``lang`` (a :class:`flywheel.dynamics.results.Position`):
    "0° = 3 outer d.c." → "0° = ползун 3: внешняя мёртвая точка"; the angle, a table's
    "2 (30°)" as they are.

    >>> from flywheel.dynamics.results import DeadCentre, Position
    >>> position_label(Position(phi=1.5708, standard_deg=90, dead_centres=(DeadCentre("5", "inner"),)), "ru")
    '90° = ползун 5: внутренняя мёртвая точка'
    """
    return " = ".join(p if isinstance(p, str) else DEAD_CENTRE_LABEL[lang == "ru"].format(
        s=p.slider, kind=DEAD_CENTRES[p.kind][lang == "ru"]) for p in position.parts())


#: the dead centres at a position, in the sentence under a record's first table of the
#: positions: (English, Russian) for one slider and for several
DEAD_CENTRE_NOTE = (("{kind} dead centre of slider {s}", "{kind} dead centres of sliders {s}"),
                    ("{kind} мёртвая точка ползуна {s}", "{kinds} мёртвые точки ползунов {s}"))
DEAD_CENTRES_PLURAL = {"outer": "внешние", "inner": "внутренние"}
POSITION_WHERE = ("position {n}", "положение {n}")


#: a tabulated position's label's own angle, «2 (30°)»: the tables give φ in a column beside it
_WITH_ANGLE = re.compile(r"\s*\([−\-+]?[\d.,]+°\)$")


def numbered(positions) -> bool:
    """Whether a record's tables give these positions by their numbers (a linkage's, as
    plan_positions.png draws them) rather than by their labels (a tabulated case's rows)."""
    return any(p.number is not None for p in positions)


def position_cells(positions, lang: str = "en") -> tuple[list[str], str]:
    """The first cell of each standard position's row in a record's table, and the sentence
    under the first such table that names the dead centres among them ("" if none).

    Numbered positions (a linkage's, as plan_positions.png draws them) are their numbers
    alone: the angle is the table's φ column beside it, the dead centres the sentence's —
    «Положение 0 — внешняя мёртвая точка ползуна 3; положение 6 — …»; a position off the
    numbered ones (a dead centre between them) is named by its angle. Unnumbered positions (a
    table's rows) keep their :func:`position_label`, without the angle in brackets «(30°)» it
    may end with (the φ column says it).

    >>> from flywheel.dynamics.results import DeadCentre as D, Position as P
    >>> position_cells([P(phi=0.0, standard_deg=0, number=0, dead_centres=(D("3", "outer"),
    ...                 D("5", "inner"), D("9", "outer"))), P(phi=0.5236, number=1)], "ru")
    (['0', '1'], 'Положение 0 — внешние мёртвые точки ползунов 3 и 9, внутренняя мёртвая точка ползуна 5.')
    """
    ru = lang == "ru"
    if not numbered(positions):                 # a table's row «2 (30°)»: «2», φ beside it
        return [_WITH_ANGLE.sub("", position_label(p, lang)) for p in positions], ""
    from flywheel.render.numbers import fmt

    one, several = DEAD_CENTRE_NOTE[ru]
    notes = []
    for p in positions:
        said = []
        for kind in ("outer", "inner"):
            sliders = [dc.slider for dc in p.dead_centres if dc.kind == kind]
            if sliders:
                said.append((one if len(sliders) == 1 else several).format(
                    kind=DEAD_CENTRES[kind][ru], kinds=DEAD_CENTRES_PLURAL[kind],
                    s=(", ".join(sliders[:-1]) + (" и " if ru else " and ") + sliders[-1]
                       if len(sliders) > 1 else sliders[0])))
        if said:
            where = (POSITION_WHERE[ru].format(n=p.number) if p.number is not None else
                     f"φ = {fmt(math.degrees(p.phi), 4)}°")
            notes.append(f"{where} — {', '.join(said)}")
    text = "; ".join(notes)
    if text and text[0] != "φ":
        text = text[0].upper() + text[1:]
    return (["" if p.number is None else str(p.number) for p in positions],
            text + "." if text else "")
