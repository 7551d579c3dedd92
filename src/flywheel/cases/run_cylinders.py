"""The cylinders of a run case file: indicator tables (two-stroke, or four-stroke by strokes or
by one closed diagram), split into strokes (re-exported by :mod:`flywheel.cases.run`; the
format: docs/case-format.md)."""
from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, PrivateAttr, model_validator

from flywheel.errors import Notice
from flywheel.io.schema import FieldError, StrictModel
from flywheel.cases.run_fields import Angle, Name, _within


class StrokesSpec(StrictModel):
    """A four-stroke cylinder's indicator diagram: p/p_max at each relative travel ``s`` of the
    cylinder, one table per stroke (the piston moves away from the head on intake and
    expansion, towards it on compression and exhaust)."""

    intake: list[float] = Field(description="p/p_max on the intake stroke (head → far)")
    compression: list[float] = Field(description="p/p_max on the compression stroke (far → head)")
    expansion: list[float] = Field(description="p/p_max on the expansion (working) stroke (head → far)")
    exhaust: list[float] = Field(description="p/p_max on the exhaust stroke (far → head)")


class DiagramSpec(StrictModel):
    """A four-stroke indicator diagram as one table over the cycle: the points (s, p/p_max) in
    the order the piston passes them, from the head dead centre where the cylinder fires."""

    s: list[float] = Field(description="relative travel from the head, 0 → 1 → 0 → 1 → 0 over "
                                        "expansion, exhaust, intake, compression")
    p: list[float] = Field(description="p/p_max at each point")


STROKE_ORDER = ("expansion", "exhaust", "intake", "compression")   # from the firing


def _values_per_s(n: int, count: int) -> Notice:
    """The error of a table whose length is not that of its s."""
    return Notice.of("values_per_s", "needs {n} values, one per s (got {count})", n=n, count=count)


def _split_cycle(s: list[float], p: list[float], tol: float) -> dict[str, tuple[list, list]]:
    """The strokes of a diagram given as one table over the cycle (:class:`DiagramSpec`):
    {stroke: (s increasing, p/p_max)}. The travel grows to 1 on expansion, falls to 0 on
    exhaust, grows on intake and falls on compression, back to where it began; a stroke ends
    where s reaches its dead centre and the next begins there. A repeated s at a dead centre is
    a vertical step of the diagram: allowed up to ``tol`` (the strokes must meet), as is the
    step between the end and the start. Raises FieldError at diagram.s[i] / diagram.p[i]."""
    n = len(s)
    if len(p) != n:
        raise FieldError(("diagram", "p"), _values_per_s(n, len(p)))
    if n < 5:
        raise FieldError(("diagram", "s"), Notice.of(
            "run_diagram_too_short", "needs at least 5 values (0, 1, 0, 1, 0: four strokes)"))
    for i, v in enumerate(s):
        if not 0.0 <= v <= 1.0:
            raise FieldError(("diagram", "s", i), Notice.of(
                "run_s_outside", "{v:g} is outside the stroke (allowed: 0 … 1)", v=v))
    if s[0] != 0.0:
        raise FieldError(("diagram", "s", 0), Notice.of(
            "run_diagram_start", "{s0:g}: the diagram begins at the head dead centre where the "
            "cylinder fires (allowed: 0)", s0=s[0]))

    def step(at: int, end: str, begin: str, p0: float, p1: float, closing: bool = False) -> None:
        if abs(p1 - p0) > tol:          # closing: the step from the end back to the start
            raise FieldError(("diagram", "p", at), Notice.of(
                "run_diagram_step", "steps from p/p_max = {p0:g} to {p1:g} at s = {at:g}, where "
                "{end} ends and {begin} {begins}: the strokes do not meet (a jump of {jump:.4g}; "
                "allowed: at most join_tolerance = {tol:g})", p0=p0, p1=p1, at=s[at], end=end,
                begin=begin, closing=closing, jump=abs(p1 - p0), tol=tol,
                begins='began' if closing else 'begins'))

    out: dict[str, tuple[list, list]] = {}
    i = 0
    for k, name in enumerate(STROKE_ORDER):
        up = k % 2 == 0
        target = 1.0 if up else 0.0
        start = i
        while k and start + 1 < n and s[start + 1] == s[i]:      # a vertical step
            start += 1
        if start > i:
            step(start, STROKE_ORDER[k - 1], name, p[i], p[start])
        m = start
        while True:
            if m + 1 >= n:
                raise FieldError(("diagram", "s"), Notice.of(
                    "run_diagram_ends_inside", "ends inside the {stroke} stroke (allowed: s runs "
                    "0 → 1 → 0 → 1 → 0 over expansion, exhaust, intake, compression)", stroke=name))
            a, b = s[m], s[m + 1]
            if (b <= a) if up else (b >= a):
                raise FieldError(("diagram", "s", m + 1), Notice.of(
                    "run_diagram_direction", "{b:g} after {a:g}: on the {stroke} stroke s must "
                    "{way} to {target:g}", b=b, a=a, stroke=name, up=up, target=target,
                    way='grow' if up else 'fall'))
            m += 1
            if s[m] == target:
                break
        seg_s, seg_p = list(s[start:m + 1]), list(p[start:m + 1])
        out[name] = (seg_s, seg_p) if up else (seg_s[::-1], seg_p[::-1])
        i = m
    if i != n - 1:
        raise FieldError(("diagram", "s", i + 1), Notice.of(
            "run_diagram_goes_on", "goes on after compression closed the cycle at s = 0 (allowed: "
            "four strokes)"))
    step(n - 1, "compression", "expansion", p[0], p[-1], closing=True)
    return out


class CylinderSpec(StrictModel):
    """A cylinder with its indicator diagram (relative pressure against relative travel): two
    tables, one per direction of the piston (a compressor, a two-stroke engine), or four, one
    per stroke of a four-stroke engine (``strokes``), or one table over the four-stroke cycle
    (``diagram``)."""

    name: Name
    piston: Name = Field(description="slider link of an RRP dyad")
    bore: Annotated[float, Field(gt=0), _within(1e-4, 10.0, "m")] = Field(description="bore d [m]")
    p_max: Annotated[float, Field(gt=0), _within(1.0, 1e10, "Pa")] = Field(description="maximum (gauge) pressure [Pa]")
    head: Literal["outer", "inner"] = Field(
        "outer", description="the dead centre at the cylinder head: farther from (outer) or "
                             "nearer to (inner) the crank axis")
    interpolation: Literal["linear", "pchip", "natural-spline"] = "linear"
    s: list[float] | None = Field(None, description="relative travel from the head dead "
                                                    "centre, 0 … 1 (not with diagram)")
    towards_head: list[float] | None = Field(
        None, description="p/p_max while the piston moves towards the head (with away_from_head)")
    away_from_head: list[float] | None = Field(
        None, description="p/p_max while it moves away from the head (with towards_head)")
    strokes: StrokesSpec | None = Field(
        None, description="a four-stroke diagram instead: p/p_max on intake, compression, "
                          "expansion, exhaust (a cycle of 720°)")
    diagram: DiagramSpec | None = Field(
        None, description="a four-stroke diagram as one table over the cycle instead (s and "
                          "p/p_max from the firing dead centre)")
    fires_at_deg: Angle | None = Field(
        None, description="four-stroke: about where the cylinder fires [deg]; it fires at its "
                          "head dead centre nearest to this angle (within 90°)")
    join_tolerance: Annotated[float, Field(ge=0), _within(0.0, 1.0, "")] = Field(
        0.02, description="four-stroke: the largest jump of p/p_max allowed where two strokes "
                          "meet at a dead centre")

    _loop: dict | None = PrivateAttr(None)     # diagram's strokes: name → (s, p)

    @model_validator(mode="after")
    def _tables(self):
        if self.diagram is not None:
            given = [k for k in ("s", "towards_head", "away_from_head", "strokes")
                     if getattr(self, k) is not None]
            if given:
                raise FieldError((given[0],), Notice.of(
                    "run_diagram_or_tables", "give either diagram (one table over the cycle) or s "
                    "with its tables, not both"))
            self._loop = _split_cycle(self.diagram.s, self.diagram.p, self.join_tolerance)
            return self
        s = self.s
        if s is None:
            raise FieldError(("s",), Notice.of(
                "run_s_missing", "missing required field (or give diagram: one table over a "
                "four-stroke cycle)"))
        if len(s) < 2:
            raise FieldError(("s",), Notice.of("run_s_too_short", "needs at least 2 values"))
        if any(b <= a for a, b in zip(s, s[1:])):
            raise FieldError(("s",), Notice.of(
                "strictly_increasing", "must be strictly increasing"))
        if abs(s[0]) > 1e-12 or abs(s[-1] - 1) > 1e-12:
            raise FieldError(("s",), Notice.of(
                "run_s_span", "must span [0, 1] (got {first} … {last})", first=s[0], last=s[-1]))
        two = [k for k in ("towards_head", "away_from_head") if getattr(self, k) is not None]
        if self.strokes is None:
            for key in ("towards_head", "away_from_head"):
                if key not in two:
                    raise FieldError((key,), Notice.of(
                        "run_two_tables_missing", "missing: give towards_head and away_from_head, "
                        "or strokes (a four-stroke diagram)"))
            if self.fires_at_deg is not None:
                raise FieldError(("fires_at_deg",), Notice.of(
                    "run_fires_at_needs_strokes", "goes with strokes (a four-stroke diagram); a "
                    "two-table cylinder repeats every revolution"))
        elif two:
            raise FieldError((two[0],), Notice.of(
                "run_two_tables_or_strokes", "give either towards_head and away_from_head (a "
                "compressor, a two-stroke engine) or strokes (a four-stroke engine), not both"))
        for key, values in self.tables().items():
            if len(values) != len(s):
                loc = ("strokes", key) if self.strokes is not None else (key,)
                raise FieldError(loc, _values_per_s(len(s), len(values)))
        if self.strokes is not None:
            from flywheel.dynamics.loads import stroke_joins

            tables = self.tables()
            for end, begin, at, p_end, p_begin in stroke_joins(s, tables):
                if abs(p_begin - p_end) > self.join_tolerance:
                    raise FieldError(
                        ("strokes", begin),
                        Notice.of(
                            "strokes_do_not_meet", "begins at p/p_max = {p_begin:g} at s = "
                            "{at:g}, where {end} ends at {p_end:g}: the strokes do not meet (a "
                            "jump of {jump:.4g}; allowed: at most join_tolerance = {tol:g}; a "
                            "rise at firing belongs inside the expansion table, just after s = 0)",
                            p_begin=p_begin, at=at, end=end, p_end=p_end,
                            jump=abs(p_begin - p_end), tol=self.join_tolerance))
        return self

    def tables(self) -> dict[str, list[float]]:
        """The indicator tables by name: towards_head and away_from_head, or the four strokes
        (p/p_max; each stroke at the cylinder's s, or of a diagram at its own travels)."""
        if self._loop is not None:
            return {k: self._loop[k][1] for k in ("intake", "compression", "expansion", "exhaust")}
        if self.strokes is not None:
            return {k: getattr(self.strokes, k) for k in ("intake", "compression", "expansion",
                                                          "exhaust")}
        return {k: v for k in ("towards_head", "away_from_head")
                if (v := getattr(self, k)) is not None}

    def stroke_tables(self) -> dict[str, tuple[list[float], list[float]]]:
        """A four-stroke cylinder's strokes: name → (s increasing, p/p_max)."""
        if self._loop is not None:
            return {k: self._loop[k] for k in ("intake", "compression", "expansion", "exhaust")}
        return {k: (self.s, v) for k, v in self.tables().items()}

    def table_loc(self, key: str) -> tuple:
        """The field path of the table ``key`` inside the cylinder."""
        if self.diagram is not None:
            return ("diagram", "p")
        return ("strokes", key) if self.strokes is not None else (key,)

    @property
    def four_stroke(self) -> bool:
        return self.strokes is not None or self.diagram is not None

