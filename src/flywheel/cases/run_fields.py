"""The quantities of a run case file (cases/run.py and its sibling modules): annotated floats
with their physically meaningful ranges (SI), far wider than any machine, narrow enough that no
product of them overflows double precision."""
from __future__ import annotations

from typing import Annotated

from pydantic import Field, Strict

from flywheel.io.schema import MAX_TEXT, within


Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
Name = Annotated[str, Field(min_length=1, max_length=MAX_TEXT)]


_within = within


# the physically meaningful ranges (SI): far wider than any machine, narrow enough that no
# product of them overflows double precision
Length = Annotated[float, Field(gt=0), _within(1e-6, 1e3, "m")]
Coord = Annotated[float, _within(-1e3, 1e3, "m")]
Angle = Annotated[float, _within(-36000.0, 36000.0, "deg")]
Mass = Annotated[float, Field(gt=0), _within(0.0, 1e6, "kg")]
Inertia = Annotated[float, Field(ge=0), _within(0.0, 1e6, "kg·m²")]
Force = Annotated[float, _within(-1e9, 1e9, "N")]
Moment = Annotated[float, _within(-1e9, 1e9, "N·m")]
# strict numbers (no true, no "0.1"), but a TOML array is a fine tuple
XY = Annotated[tuple[float, float], Strict(False), _within(-1e3, 1e3, "m")]
CYCLE_REVS_MAX = 10      # a cycle of at most 10 revolutions (3600°)
