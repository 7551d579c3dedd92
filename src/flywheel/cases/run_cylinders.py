"""The cylinders of a run case file: indicator tables (two-stroke, or four-stroke by strokes or
by one closed diagram), split into strokes (re-exported by :mod:`flywheel.cases.run`; the
format: docs/case-format.md)."""
from __future__ import annotations

import math
from pathlib import Path
from typing import Annotated, Literal

from pydantic import Field, PrivateAttr, ValidationInfo, model_validator

from flywheel.errors import Notice, said
from flywheel.io.schema import FieldError, StrictModel, TitleText, at_most, title_field
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

MAX_TRACE = 100_000          # rows of a measured indicator diagram (0.1° over 720°: 7 200)
#: the units of an indicator table's columns, to SI (rad, m³, m, Pa); "relative": s itself
X_UNITS = {"crank_angle": {"deg": math.pi / 180, "rad": 1.0},
           "volume": {"m3": 1.0, "dm3": 1e-3, "l": 1e-3, "cm3": 1e-6},
           "travel": {"m": 1.0, "mm": 1e-3, "relative": 1.0}}
P_UNITS = {"Pa": 1.0, "kPa": 1e3, "MPa": 1e6, "bar": 1e5, "atm": 101325.0}
_TRACE_GAP_DEG = 45.0        # a crank-angle trace covers the cycle: no gap wider than this


class IndicatorSpec(StrictModel):
    """A measured indicator diagram (a test bench's or an engine-simulation tool's pressure
    trace), from ``indicator_file`` (CSV) or inline (``x``, ``p``): p against the crank angle
    over the whole cycle, or p against the volume or the piston's travel as one closed loop in
    the order the piston passes it, from the head dead centre (where a four-stroke cylinder
    fires)."""

    against: Literal["crank_angle", "volume", "travel"] = Field(
        description="what the pressure is given against: crank_angle (the whole cycle), volume "
                    "or travel (a loop: 2 strokes, or 4 of a four-stroke engine)")
    cycle: Literal["four-stroke", "two-stroke"] = Field(
        "four-stroke", description="the cylinder's cycle: four strokes over 720° or two over 360°")
    columns: Annotated[list[Name], Field(min_length=2, max_length=2)] | None = Field(
        None, description="indicator_file's header names of x and p (default: its first two "
                          "columns)")
    x_unit: Literal["deg", "rad", "m3", "dm3", "l", "cm3", "m", "mm", "relative"] = Field(
        description="unit of x: deg or rad (crank_angle), m3, dm3, l, cm3 (volume), m, mm or "
                    "relative (travel)")
    p_unit: Literal["Pa", "kPa", "MPa", "bar", "atm"] = Field(description="unit of p")
    pressure: Literal["gauge", "absolute"] = Field(
        "gauge", description="absolute pressures lose the atmosphere (the gas force is the "
                             "gauge pressure's)")
    atmosphere: Annotated[float, _within(0.0, 1e6, "Pa")] = Field(
        101325.0, description="the atmosphere subtracted from absolute pressures [Pa]")
    tdc_offset_deg: Angle = Field(
        0.0, description="crank_angle: the table's angle at the cylinder's head dead centre "
                         "where it fires (a two-stroke's: any head dead centre) [deg]")
    x: Annotated[list[float], at_most(MAX_TRACE, "values")] | None = Field(
        None, description="inline instead of indicator_file: crank angle, volume or travel")
    p: Annotated[list[float], at_most(MAX_TRACE, "values")] | None = Field(
        None, description="inline instead of indicator_file: the pressure at each x")


def read_trace(spec: IndicatorSpec, file: str | None, case_dir: str) -> tuple[list, list, tuple]:
    """(x [SI: rad, m³, m or s], gauge p [Pa], the field path of the data) of an indicator
    given by ``file`` (relative to ``case_dir``; read by :func:`flywheel.io.table.read_columns`)
    or inline. Raises FieldError (one line) for a file that cannot be read, data given twice or
    not at all, a unit that does not fit ``against``, or fewer than 3 rows."""
    if spec.x_unit not in X_UNITS[spec.against]:
        raise FieldError(("indicator", "x_unit"), Notice.of(
            "indicator_unit", "{unit!r} is not a unit of {against} (allowed: {allowed})",
            unit=spec.x_unit, against=spec.against, allowed=", ".join(X_UNITS[spec.against])))
    inline = spec.x is not None or spec.p is not None
    if file is not None and inline:
        raise FieldError(("indicator", "x" if spec.x is not None else "p"), Notice.of(
            "indicator_twice", "give the data either in indicator_file or inline (x and p), "
            "not both"))
    if file is not None:
        from flywheel.io.table import TableError, read_columns

        path = Path(file) if Path(file).is_absolute() else Path(case_dir) / file
        try:
            _, (x, p) = read_columns(path, spec.columns)
        except TableError as exc:
            problem = said(exc)
            raise FieldError(("indicator_file",), problem) from None
        where = ("indicator_file",)
    else:
        if spec.x is None or spec.p is None:
            raise FieldError(("indicator", "p" if spec.x is not None else "x"), Notice.of(
                "indicator_missing", "missing: give indicator_file, or x and p inline"))
        if spec.columns is not None:
            raise FieldError(("indicator", "columns"), Notice.of(
                "indicator_columns_inline", "names the columns of indicator_file, which is not "
                "given"))
        x, p = spec.x, spec.p
        if len(p) != len(x):
            raise FieldError(("indicator", "p"), Notice.of(
                "values_per_x", "needs {n} values, one per x (got {count})", n=len(x),
                count=len(p)))
        where = ("indicator", "x")
    if len(x) < 3:
        raise FieldError(where, Notice.of(
            "indicator_too_short", "{n} rows (allowed: at least 3)", n=len(x)))
    kx, kp = X_UNITS[spec.against][spec.x_unit], P_UNITS[spec.p_unit]
    atm = spec.atmosphere if spec.pressure == "absolute" else 0.0
    return [v * kx for v in x], [v * kp - atm for v in p], where


def loop_runs(s: list[float], p: list[float], strokes: int, where: tuple
              ) -> tuple[list[float], list[float]]:
    """A measured loop (volume or travel ``s`` from the head dead centre, scaled to 0 … 1 by its
    own extremes; gauge ``p``) as the diagram of :func:`_split_cycle`: its ``strokes`` runs
    between its turning points, each run carried on to its dead centre (1, then 0, …) with its
    end pressure where the samples stop short of it (as a table is read beyond its ends), so
    the loop begins and closes at s = 0. Raises FieldError for a loop that does not begin by
    moving away from the head, does not turn ``strokes`` − 1 times, or repeats a position."""
    lo, hi = min(s), max(s)
    if not hi > lo:
        raise FieldError(where, Notice.of(
            "indicator_no_stroke", "the piston does not move: every x is {x:g}", x=lo))
    u = [(v - lo) / (hi - lo) for v in s]
    for i in range(1, len(u)):
        if u[i] == u[i - 1]:
            raise FieldError(where, Notice.of(
                "indicator_repeated", "rows {i} and {j} are at the same position (allowed: each "
                "row a new position along the loop; leave out the repeated row)", i=i, j=i + 1))
    turns = [i for i in range(1, len(u) - 1) if (u[i] - u[i - 1]) * (u[i + 1] - u[i]) < 0]
    if u[1] < u[0] or len(turns) != strokes - 1:
        raise FieldError(where, Notice.of(
            "indicator_strokes", "is not a loop of {want} strokes from the head dead centre (it "
            "turns {n} times; allowed: a loop that begins at the least volume or travel, moves "
            "away from the head and turns {turns} times)", want=strokes, n=len(turns),
            turns=strokes - 1))
    bounds = [0] + turns + [len(u) - 1]
    out_s, out_p = [0.0], [p[0]]
    for k in range(strokes):
        target = 1.0 if k % 2 == 0 else 0.0
        for i in range(bounds[k] if k == 0 else bounds[k] + 1, bounds[k + 1] + 1):
            if u[i] != out_s[-1]:
                out_s.append(u[i]), out_p.append(p[i])
        if out_s[-1] != target:
            out_s.append(target), out_p.append(out_p[-1])
    return out_s, out_p


def two_tables(loop_s: list[float], loop_p: list[float]) -> tuple[list, list, list]:
    """A two-stroke loop (0 → 1 → 0) as (s, towards_head, away_from_head) on the union of both
    strokes' travels: each table read linearly at the other's travels is the same polyline."""
    import numpy as np

    far = loop_s.index(1.0)
    s_away, p_away = loop_s[:far + 1], loop_p[:far + 1]
    s_back, p_back = loop_s[far:][::-1], loop_p[far:][::-1]
    grid = sorted(set(s_away) | set(s_back))
    return (grid, np.interp(grid, s_back, p_back).tolist(), np.interp(grid, s_away, p_away).tolist())


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
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    label: TitleText = title_field(description="the cylinder's short name in the documents, figures and "
                                                  "sheets, as ВД in «цилиндр ВД»: a string, or { ru = …, en = … } "
                                                  "(default: its name)")
    piston: Name = Field(description="slider link of an RRP dyad")
    bore: Annotated[float, Field(gt=0), _within(1e-4, 10.0, "m")] = Field(description="bore d [m]")
    p_max: Annotated[float, Field(gt=0), _within(1.0, 1e10, "Pa")] | None = Field(
        None, description="maximum (gauge) pressure [Pa], the tables' 1 (with an indicator: "
                          "default its greatest gauge pressure)")
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

    indicator_file: Annotated[str, Field(min_length=1, max_length=4096)] | None = Field(
        None, description="a measured indicator diagram: a CSV file (relative to the case "
                          "file) described by [cylinders.indicator]")
    indicator: IndicatorSpec | None = Field(
        None, description="a measured indicator diagram instead of s and the tables: what the "
                          "columns of indicator_file are and their units, or the data inline")

    _loop: dict | None = PrivateAttr(None)     # diagram's strokes: name → (s, p)
    _trace: tuple | None = PrivateAttr(None)   # a crank-angle trace: (ψ [rad], p/p_max)

    @model_validator(mode="after")
    def _tables(self, info: ValidationInfo):
        if self.indicator_file is not None and self.indicator is None:
            raise FieldError(("indicator",), Notice.of(
                "indicator_needs_table", "missing: indicator_file needs [cylinders.indicator] "
                "saying what its columns are (against, x_unit, p_unit)"))
        if self.indicator is not None:
            self._measured((info.context or {}).get("case_dir", "."))
            if self._trace is not None:
                return self             # tables from the trace with the mechanism: resolve_traces
        elif self.p_max is None:
            raise FieldError(("p_max",), Notice.of(
                "p_max_missing", "missing required field (only a measured indicator diagram "
                "gives its own)"))
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

    def _measured(self, case_dir: str) -> None:
        """The indicator's data as this cylinder's tables: p_max (given, else the greatest
        gauge pressure) and p/p_max; a loop against volume or travel becomes the diagram (four
        strokes) or s with its two tables; a crank-angle trace is kept as (ψ, p/p_max) with ψ
        from the head dead centre, for :func:`resolve_traces`."""
        spec = self.indicator
        given = [k for k in ("s", "towards_head", "away_from_head", "strokes", "diagram")
                 if getattr(self, k) is not None]
        if given:
            raise FieldError((given[0],), Notice.of(
                "indicator_or_tables", "give either a measured indicator diagram (indicator) or "
                "the tables, not both"))
        x, p, where = read_trace(spec, self.indicator_file, case_dir)
        if self.p_max is None:
            top = max(p)
            if not 1.0 <= top <= 1e10:
                raise FieldError(where, Notice.of(
                    "indicator_p_top", "the greatest gauge pressure is {top:g} Pa (allowed: 1 … "
                    "1e10 Pa; are p_unit and pressure right?)", top=top))
            self.p_max = top
        if max(p) > self.p_max * (1 + 1e-9):
            raise FieldError(where, Notice.of(
                "indicator_above_p_max", "reaches {top:g} Pa, above p_max = {p_max:g} Pa "
                "(allowed: at most p_max; leave p_max out to take the trace's greatest)",
                top=max(p), p_max=self.p_max))
        rel = [v / self.p_max for v in p]
        strokes = 4 if spec.cycle == "four-stroke" else 2
        if spec.against != "crank_angle":
            if spec.tdc_offset_deg != 0.0:
                raise FieldError(("indicator", "tdc_offset_deg"), Notice.of(
                    "indicator_offset_angle", "goes with against = \"crank_angle\" (a loop "
                    "against {against} begins at the head dead centre)", against=spec.against))
            loop_s, loop_p = loop_runs(x, rel, strokes, where)
            if strokes == 4:
                self.diagram = DiagramSpec(s=loop_s, p=loop_p)
            else:
                self.s, self.towards_head, self.away_from_head = two_tables(loop_s, loop_p)
            return
        cycle = strokes * math.pi
        psi = [(a - math.radians(spec.tdc_offset_deg)) % cycle for a in x]
        order = sorted(range(len(psi)), key=lambda i: psi[i])
        for i in range(1, len(x)):
            if not x[i] > x[i - 1]:
                raise FieldError(where, Notice.of(
                    "indicator_angles_increasing", "row {j}: the crank angle {a:g}° does not "
                    "grow (allowed: strictly increasing angles)", j=i + 1,
                    a=math.degrees(x[i])))
        if x[-1] - x[0] > cycle * (1 + 1e-12):
            raise FieldError(where, Notice.of(
                "indicator_angles_span", "spans {span:g}° (allowed: at most one cycle, "
                "{cycle:g}°)", span=math.degrees(x[-1] - x[0]), cycle=math.degrees(cycle)))
        ps = [psi[i] for i in order]
        gaps = [b - a for a, b in zip(ps, ps[1:])] + [ps[0] + cycle - ps[-1]]
        if max(gaps) > math.radians(_TRACE_GAP_DEG):
            raise FieldError(where, Notice.of(
                "indicator_angles_gap", "leaves a gap of {gap:.4g}° (allowed: a trace over the "
                "whole {cycle:g}° cycle, no gap over {most:g}°)", gap=math.degrees(max(gaps)),
                cycle=math.degrees(cycle), most=_TRACE_GAP_DEG))
        self._trace = (ps, [rel[i] for i in order])

    @property
    def measured_by_angle(self) -> bool:
        """A crank-angle trace whose tables :func:`resolve_traces` has not yet made."""
        return self._trace is not None and self._loop is None and self.s is None

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
        return (self.strokes is not None or self.diagram is not None
                or (self.indicator is not None and self.indicator.cycle == "four-stroke"))


def resolve_traces(case) -> None:
    """The tables of every cylinder given a crank-angle trace (:class:`IndicatorSpec`), made
    with the case's mechanism: each sample's crank angle ψ after the head dead centre (where a
    four-stroke cylinder fires) gives the piston's relative travel s (the exact kinematics at
    that angle), the dead centres are added with the trace read linearly in angle there, and
    the loop (s, p/p_max) becomes the diagram (four strokes) or s with its two tables. Between
    the samples the pressure is then linear in the travel (for a dense trace the same as
    linear in the angle). Raises FieldError at cylinders[i] (a trace whose loop is not a
    diagram) or InputError (a piston without dead centres)."""
    import numpy as np

    from flywheel.dynamics.grid import slider_frame
    from flywheel.dynamics.loads import relative_travel
    from flywheel.linkage import solve
    from flywheel.linkage.deadcentres import dead_centres

    todo = [(i, c) for i, c in enumerate(case.cylinders) if c.measured_by_angle]
    if not todo:
        return
    mech = case.mechanism()
    for i, cy in todo:
        d, u, base, head, far = slider_frame(mech, {cy.piston: dead_centres(mech, cy.piston)},
                                             cy.piston, cy.head, f"cylinders {cy.name}: piston")
        four = cy.indicator.cycle == "four-stroke"
        cycle = 4 * np.pi if four else 2 * np.pi
        far_after = (far.phi - head.phi) % (2 * np.pi)
        centres = [0.0, far_after] + ([2 * np.pi, 2 * np.pi + far_after] if four else [])
        psi, rel = np.asarray(cy._trace[0]), np.asarray(cy._trace[1])
        at_centre = np.interp(centres, psi, rel, period=cycle)
        keep = np.all(np.abs(psi[:, None] - np.asarray(centres)[None, :]) > 1e-9, axis=1)
        psi_all = np.concatenate([psi[keep], centres, [cycle]])
        rel_all = np.concatenate([rel[keep], at_centre, [at_centre[0]]])
        order = np.argsort(psi_all, kind="stable")
        psi_all, rel_all = psi_all[order], rel_all[order]
        kin = solve(mech, np.mod(head.phi + psi_all, 2 * np.pi))
        s = relative_travel((kin.points[d.joint].r - base) @ u, head.x, far.x)
        bound = np.isin(psi_all, centres + [cycle])
        s[bound] = np.where(np.isin(psi_all[bound], [far_after, 2 * np.pi + far_after]), 1.0, 0.0)
        # samples within round-off of a dead centre (s there 0 or 1 to the last bit) are
        # the dead centre's own value: left out
        ok = bound | ((s > 0.0) & (s < 1.0))
        loop_s, loop_p = s[ok].tolist(), rel_all[ok].tolist()
        try:
            if four:
                cy.diagram = DiagramSpec(s=loop_s, p=loop_p)
                cy._loop = _split_cycle(loop_s, loop_p, cy.join_tolerance)
            else:
                cy.s, cy.towards_head, cy.away_from_head = two_tables(loop_s, loop_p)
        except FieldError as exc:
            problem = said(exc)
            raise FieldError(("cylinders", i, "indicator"), problem) from None

