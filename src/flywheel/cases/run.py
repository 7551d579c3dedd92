"""Case files: TOML read with tomllib, validated by pydantic into typed models.

Units are SI; angles are degrees in the file (``*_deg``) and radians everywhere inside.
Unknown keys are errors (with the nearest valid key), NaN and infinity are refused, names
must be defined before they are used. Every problem becomes one
:class:`~flywheel.errors.CaseFileError` line: ``file: field.path: what is wrong (allowed)``.
The format is documented field by field in docs/case-format.md.
"""
from __future__ import annotations

import math
import typing
from typing import Annotated, Literal, Union

from pydantic import BaseModel, Field, PrivateAttr, Strict, model_validator

from flywheel.errors import CaseFileError, Notice, led
from flywheel.io.schema import FieldError, StrictModel, within, clean_loc, describe, load, loc_str, pick, validate
from flywheel.cases.rim import MATERIALS, RimSpec  # shared with the task2 format
from flywheel.cases.tabulated import TabulatedSpec

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
Name = Annotated[str, Field(min_length=1)]


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




class Machine(StrictModel):
    """Operating data of the machine."""

    speed_rps: Annotated[float, Field(gt=0), _within(1e-3, 1e4, "rev/s")] | None = Field(
        None, description="crank speed n1 [rev/s]")
    speed_rpm: Annotated[float, Field(gt=0), _within(0.06, 6e5, "rpm")] | None = Field(
        None, description="crank speed [rev/min] (instead of speed_rps)")
    delta: Annotated[float, Field(gt=0, lt=1), _within(1e-6, 1.0, "")] | None = Field(
        None, description="coefficient of speed fluctuation δ, 1e-6 ≤ δ < 1: the flywheel is "
                          "sized for it (omit it when the flywheel is given: flywheel.J …)")
    power: Annotated[float, Field(gt=0), _within(1e-3, 1e10, "W")] | None = Field(
        None, description="the machine's mean power at the mean speed [W] (an engine's indicated "
                          "power, a compressor's drive): M = P/ω_m is checked against the "
                          "constant moment of the cycle balance")
    balance: Literal["driving", "resistance"] = Field(
        "driving", description="the unknown constant moment found from the cycle balance")
    gravity: Annotated[tuple[float, float], Strict(False), _within(-1e3, 1e3, "m/s²")] = Field(
        (0.0, -9.81), description="gravity vector g [m/s²]")
    first_group: dict[str, Annotated[float, Field(ge=0), _within(0.0, 1e9, "kg·m²")]] = Field(
        default_factory=dict,
        description="moments of inertia already on the crank shaft, reduced to it [kg·m²]")
    cycle_deg: float = Field(
        360.0, description="length of the cycle Φ [deg]: a whole number of crank revolutions, "
                           "360 … 3600 (720 for a four-stroke engine)")
    firing_order: list[Name] | None = Field(
        None, description="four-stroke cylinders by name in the order they fire; each fires at "
                          "its first head dead centre after the one before")

    @model_validator(mode="after")
    def _check(self):
        if (self.speed_rps is None) == (self.speed_rpm is None):
            raise ValueError(Notice.of(
                "speed_rps_or_rpm", "give exactly one of speed_rps, speed_rpm"))
        revs = self.cycle_deg / 360.0
        if not (1 <= revs <= CYCLE_REVS_MAX and revs == round(revs)):
            raise FieldError(("cycle_deg",), Notice.of(
                "cycle_not_whole", "{cycle:g}° is not a whole number of revolutions (allowed: 360, "
                "720, 1080 … {top}°)", cycle=self.cycle_deg, top=360 * CYCLE_REVS_MAX))
        return self

    @property
    def cycle(self) -> float:
        """The cycle Φ [rad]: 2π·(number of revolutions); 4π for a four-stroke engine."""
        return 2 * math.pi * round(self.cycle_deg / 360.0)

    @property
    def omega_mean(self) -> float:
        """ω_m = 2π·n1 [rad/s] (seed 000: ω_1ср = 2·π·n1)."""
        n = self.speed_rps if self.speed_rps is not None else self.speed_rpm / 60.0
        return 2 * math.pi * n


class Design(StrictModel):
    """Optional design rules that derive lengths as seed 000 does."""

    mean_piston_speed: Annotated[float, Field(gt=0), _within(1e-4, 1e3, "m/s")] | None = Field(
        None, description="V_ср [m/s]: crank length l1 = V_ср/(4·n1) where crank.length is omitted")
    rod_to_crank: Annotated[float, Field(gt=0), _within(1e-3, 1e3, "")] | None = Field(
        None, description="k: rod length = k·l1 for every RRP dyad whose rod_length is omitted")


class PinSpec(StrictModel):
    """A further crank pin (throw) of a multi-throw crankshaft, on the crank's link."""

    name: Name = Field(description="name of the pin (a new point)")
    angle_deg: Angle = Field(description="its angle to the crank's tip (the crank pin `tip`), "
                                         "counter-clockwise positive [deg]")
    length: Length | None = Field(None, description="its throw [m] (default: the crank's length)")


class CrankSpec(StrictModel):
    """The driving link (link 1)."""

    name: Name = Field("1", description="link name")
    pivot: Name = Field("O", description="name of the fixed pivot")
    pivot_at: XY = Field((0.0, 0.0), description="pivot position [m]")
    tip: Name = Field("A", description="name of the crank pin")
    length: Length | None = Field(None, description="crank length l1 [m]")
    start_angle_deg: Angle = Field(0.0, description="crank angle from +x at φ = 0 [deg]")
    rotation: Literal["cw", "ccw"] = Field("ccw", description="direction of rotation")
    pins: list[PinSpec] = Field(default_factory=list,
                                description="further crank pins of a multi-throw crankshaft")


class GuideSpec(StrictModel):
    """A fixed straight guide."""

    through: XY = Field((0.0, 0.0), description="a point of the guide line [m]")
    angle_deg: Angle = Field(description="direction of the guide from +x [deg]")
    offset: Coord = Field(0.0, description="shift along the guide's left normal [m]")


Branch = Literal["+", "-"]


class RRPSpec(StrictModel):
    """Connecting rod + slider on a fixed guide."""

    kind: Literal["RRP"]
    name: str | None = Field(None, description="dyad name (default: the joint's)")
    from_: Name = Field(alias="from", description="known point the rod starts from")
    joint: Name = Field(description="name of the rod–slider joint (new point)")
    rod: Name = Field(description="link name of the rod")
    rod_length: Length | None = Field(None, description="rod length [m]")
    slider: Name = Field(description="link name of the slider")
    guide: GuideSpec
    branch: Branch = Field("+", description="assembly: joint ahead (+) of or behind (−) the "
                                            "rod's foot along the guide direction")


class RRRSpec(StrictModel):
    """Two links, three revolute joints."""

    kind: Literal["RRR"]
    name: str | None = None
    from_: Name = Field(alias="from", description="known point of the first link")
    link_from: Name = Field(description="link name from `from` to the joint")
    length_from: Length = Field(description="its length [m]")
    to: Name = Field(description="known point of the second link")
    link_to: Name = Field(description="link name from `to` to the joint")
    length_to: Length = Field(description="its length [m]")
    joint: Name = Field(description="name of the middle joint (new point)")
    branch: Branch = Field("+", description="joint left (+) or right (−) of the line from → to")


class RPRSpec(StrictModel):
    """Slotted link (кулиса): a block at a known point slides on a rocker about a pivot."""

    kind: Literal["RPR"]
    name: str | None = None
    from_: Name = Field(alias="from", description="known point carrying the block")
    pivot: Name = Field(description="known point the rocker turns about")
    rocker: Name = Field(description="link name of the rocker")
    slider: Name = Field(description="link name of the block")
    offset: Coord = Field(0.0, description="slide line offset from the pivot [m]")
    branch: Branch = Field("+", description="block on the rocker's positive (+) side of the pivot")


DyadSpec = Annotated[Union[RRPSpec, RRRSpec, RPRSpec], Field(discriminator="kind")]


class PointSpec(StrictModel):
    """A point fixed on a link: by fraction from→to (+ across) or by distance and angle."""

    link: Name
    from_: Name = Field(alias="from", description="a point of the link")
    to: str | None = Field(None, description="another point of the link")
    fraction: Annotated[float, _within(-1e3, 1e3, "")] = Field(0.0, description="share of the way from → to")
    across: Coord = Field(0.0, description="shift along the left normal of from → to [m]")
    distance: Annotated[float, Field(ge=0), _within(0.0, 1e3, "m")] | None = Field(None, description="distance from `from` [m]")
    angle_deg: Angle = Field(0.0, description="angle to the link's direction [deg]")

    @model_validator(mode="after")
    def _one_way(self):
        if (self.to is None) == (self.distance is None):
            raise ValueError(Notice.of(
                "point_to_or_distance", "give either `to` (with fraction) or `distance` (with "
                "angle_deg)"))
        if self.distance is not None and (self.fraction or self.across):
            raise ValueError(Notice.of(
                "run_point_fraction_with_distance", "`fraction` and `across` go with `to`, not "
                "with `distance`"))
        if self.to is not None and self.angle_deg:
            raise ValueError(Notice.of(
                "run_point_angle_with_to", "`angle_deg` goes with `distance`, not with `to`"))
        return self


class LinkSpec(StrictModel):
    """Mass data of a link."""

    mass: Mass = Field(0.0, description="mass [kg], > 0 (leave it out for a massless link)")
    J_S: Inertia = Field(0.0, description="moment of inertia about the centroid [kg·m²]")
    centroid: str | None = Field(None, description="point where the mass sits")

    @model_validator(mode="after")
    def _centroid(self):
        if self.mass > 0 and self.centroid is None:
            raise ValueError(Notice.of("link_mass_centroid", "a link with mass needs `centroid`"))
        return self


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
            raise FieldError(("diagram", "p", at), Notice(
                f"steps from p/p_max = {p0:g} to {p1:g} at s = {s[at]:g}, where {end} ends and "
                f"{begin} {'began' if closing else 'begins'}: the strokes do not meet (a jump of "
                f"{abs(p1 - p0):.4g}; allowed: at most join_tolerance = {tol:g})",
                "run_diagram_step", p0=p0, p1=p1, at=s[at], end=end, begin=begin,
                closing=closing, jump=abs(p1 - p0), tol=tol))

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
                    "run_diagram_ends_inside", "ends inside the {stroke} stroke (allowed: s runs 0 "
                    "→ 1 → 0 → 1 → 0 over expansion, exhaust, intake, compression)", stroke=name))
            a, b = s[m], s[m + 1]
            if (b <= a) if up else (b >= a):
                raise FieldError(("diagram", "s", m + 1), Notice(
                    f"{b:g} after {a:g}: on the {name} stroke s must "
                    f"{'grow' if up else 'fall'} to {target:g}", "run_diagram_direction",
                    b=b, a=a, stroke=name, up=up, target=target))
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
                            "strokes_do_not_meet", "begins at p/p_max = {p_begin:g} at s = {at:g}, "
                            "where {end} ends at {p_end:g}: the strokes do not meet (a jump of "
                            "{jump:.4g}; allowed: at most join_tolerance = {tol:g}; a rise at "
                            "firing belongs inside the expansion table, just after s = 0)",
                            p_begin=p_begin, at=at, end=end, p_end=p_end, jump=abs(p_begin - p_end),
                            tol=self.join_tolerance))
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


class ForceSpec(StrictModel):
    """A technological (resistance) force on a slider over part of its stroke; it acts against
    the slider's motion."""

    name: Name
    slider: Name = Field(description="slider link of an RRP dyad")
    magnitude: Force = Field(description="force [N] (> 0 resists the motion)")
    reference: Literal["outer", "inner"] = Field("outer", description="dead centre s is measured from")
    s_range: XY = Field((0.0, 1.0), description="relative travel where the force acts, 0 … 1")
    stroke: Literal["towards", "away", "both"] = Field(
        "both", description="acts while the slider moves towards / away from the reference")


class CoupleSpec(StrictModel):
    """A constant couple on a link [N·m], counter-clockwise positive."""

    name: Name
    link: Name
    moment: Moment




class GivenDisk(StrictModel):
    """A given flywheel: a solid disk of the material of [flywheel]."""

    D: Length = Field(description="diameter [m]")
    b: Length = Field(description="width [m]")


class GivenRim(StrictModel):
    """A given flywheel: a rim (hub and spokes neglected) of the material of [flywheel]."""

    D: Length = Field(description="outer diameter [m]")
    D_inner: Length = Field(description="inner diameter [m], below D")
    b: Length = Field(description="width [m]")

    @model_validator(mode="after")
    def _check(self):
        if not self.D_inner < self.D:
            raise FieldError(("D_inner",), Notice.of(
                "rim_inner_above_outer", "{inner:g} m is not below D = {D:g} m", inner=self.D_inner,
                D=self.D))
        return self


class FlywheelSpec(StrictModel):
    """Flywheel make and placement (design.md §2; seed 003, eqs. 9.21–9.23 for the ratio)."""

    material: Literal["steel", "cast-iron"] = Field(
        "steel", description="sets density (7800 / 7200 kg/m³) and allowable rim stress "
                             "(20 / 7 MPa) unless given")
    density: Annotated[float, Field(gt=0), _within(1.0, 1e5, "kg/m³")] | None = Field(None, description="material density ρ [kg/m³]")
    allowable_stress: Annotated[float, Field(gt=0), _within(1e3, 1e11, "Pa")] | None = Field(
        None, description="allowable hoop stress of the rim [Pa]: rim speed limit √(σ/ρ)")
    speed_ratio: Annotated[float, Field(gt=0), _within(1e-3, 1e3, "")] = Field(
        1.0, description="i = flywheel shaft speed / crank speed: the flywheel needs J_M/i²")
    width_ratio: Annotated[float, Field(gt=0), _within(1e-3, 10.0, "")] = Field(0.2, description="b/D")
    inner_ratio: float = Field(0.8, gt=0, lt=1, description="rim: D_inner/D")
    rim_share: float = Field(1.0, gt=0, le=1, description="share of J_M carried by the rim "
                                                          "(hub and spokes carry the rest)")
    formulas: Literal["first-principles", "course"] = Field(
        "first-principles",
        description="'first-principles': J = πρbD⁴/32 with the density and ratios above; "
                    "'course': the seed's rounded empirical constants 0.366, 0.406, 6123 "
                    "(steel, b = 0.2·D, D1 = 0.8·D)")
    rim: RimSpec | None = Field(
        None, description="design the rim (rim speed or allowable stress, share, section): "
                          "results.flywheel_rim then holds the designed rim")
    # a given flywheel (instead of machine.delta): one of the four
    J: Annotated[float, Field(gt=0), _within(0.0, 1e9, "kg·m²")] | None = Field(
        None, description="a given flywheel: its moment of inertia on its own shaft [kg·m²] "
                          "(J_I = first group + J·i²); machine.delta is then omitted")
    mass: Annotated[float, Field(gt=0), _within(0.0, 1e9, "kg")] | None = Field(
        None, description="a given flywheel's mass [kg], with radius_of_gyration: J = m·k²")
    radius_of_gyration: Annotated[float, Field(gt=0), _within(1e-6, 1e3, "m")] | None = Field(
        None, description="its radius of gyration k [m] (with mass)")
    given_disk: GivenDisk | None = Field(
        None, description="a given solid disk (D, b): J = π·ρ·b·D⁴/32")
    given_rim: GivenRim | None = Field(
        None, description="a given rim (D, D_inner, b): J = π·ρ·b·(D⁴ − D_inner⁴)/32")

    @model_validator(mode="after")
    def _rim_share_once(self):
        if self.rim is not None and "rim_share" in self.model_fields_set:
            raise FieldError(("rim_share",), Notice.of(
                "rim_share_twice", "with [flywheel.rim] the share is flywheel.rim.share (give it "
                "there)"))
        forms = [k for k in ("J", "mass", "given_disk", "given_rim") if getattr(self, k) is not None]
        if len(forms) > 1:
            raise FieldError((forms[1],), Notice.of(
                "given_flywheel_forms", "a given flywheel is one of J, mass with "
                "radius_of_gyration, given_disk, given_rim (got {forms})", forms=", ".join(forms)))
        if (self.mass is None) != (self.radius_of_gyration is None):
            which = "radius_of_gyration" if self.mass is not None else "mass"
            raise FieldError((which,), Notice.of(
                "mass_radius_missing", "missing: mass and radius_of_gyration go together (J = m·k²)"
            ))
        if self.rim is not None and self.rim.speed is not None:
            self.rim.check_speed(self.rho, self.sigma, self.material
                                 if self.density is None and self.allowable_stress is None
                                 else "the given material")
        return self

    @property
    def rho(self) -> float:
        return self.density if self.density is not None else MATERIALS[self.material][0]

    @property
    def given_J(self) -> float | None:
        """The given flywheel's J on its own shaft [kg·m²]: J, m·k², π·ρ·b·D⁴/32 of a disk or
        π·ρ·b·(D⁴ − D1⁴)/32 of a rim (:func:`flywheel.dynamics.sizing.disk`, ``rim``); None
        when the flywheel is to be sized for machine.delta."""
        if self.J is not None:
            return self.J
        if self.mass is not None:
            return self.mass * self.radius_of_gyration ** 2
        if self.given_disk is not None:
            d = self.given_disk
            return math.pi * self.rho * d.b * d.D ** 4 / 32
        if self.given_rim is not None:
            r = self.given_rim
            return math.pi * self.rho * r.b * (r.D ** 4 - r.D_inner ** 4) / 32
        return None

    @property
    def sigma(self) -> float:
        return self.allowable_stress if self.allowable_stress is not None else MATERIALS[self.material][1]


class MotorSpec(StrictModel):
    """Linear static characteristic of the motor, reduced to the crank: M_Д = M_п·(1 − ω/ω_x)
    (the course's model of an asynchronous motor). Used by `flywheel run --transients`."""

    no_load_speed_rpm: Annotated[float, Field(gt=0), _within(0.06, 6e5, "rpm")] = Field(description="ω_x: synchronous (no-load) speed reduced to the "
                                               "crank [rev/min]; must exceed the mean speed")
    starting_torque: Annotated[float, Field(gt=0), _within(0.0, 1e9, "N·m")] | None = Field(
        None, description="M_п reduced to the crank [N·m]; default: the value whose mean torque "
                          "at the mean speed equals the driving moment, M_п = M_D/(1 − ω_m/ω_x)")


class OutputSpec(StrictModel):
    """What to report."""

    at_deg: list[float] = Field(default_factory=lambda: [120.0],
                                description="report angles [deg]")


class ForceAnalysisSpec(StrictModel):
    """The force analysis (kinetostatics) of `flywheel run` (docs/forces.md)."""

    motion: Literal["true", "steady"] = Field(
        "true", description="the crank's motion for the inertia loads: 'true' = ω(φ), ε(φ) of "
                            "the dynamics with the flywheel; 'steady' = ω_m constant, ε = 0 "
                            "(`flywheel run --motion` overrides)")


class Case(StrictModel):
    """A whole case file."""

    title: str = ""
    source: str = ""
    machine: Machine
    design: Design = Field(default_factory=Design)
    crank: CrankSpec | None = Field(None, description="the driving link of a linkage")
    tabulated: TabulatedSpec | None = Field(
        None, description="kinematics as a table instead of a linkage (docs/tabulated.md)")
    ground: dict[str, XY] = Field(default_factory=dict, description="fixed points [m]")
    dyads: list[DyadSpec] = Field(default_factory=list)
    points: dict[str, PointSpec] = Field(default_factory=dict)
    links: dict[str, LinkSpec] = Field(default_factory=dict)
    cylinders: list[CylinderSpec] = Field(default_factory=list)
    forces: list[ForceSpec] = Field(default_factory=list)
    couples: list[CoupleSpec] = Field(default_factory=list)
    flywheel: FlywheelSpec = Field(default_factory=FlywheelSpec)
    motor: MotorSpec | None = None
    output: OutputSpec = Field(default_factory=OutputSpec)
    force_analysis: ForceAnalysisSpec = Field(default_factory=ForceAnalysisSpec)

    # -- derived -------------------------------------------------------------------------
    @property
    def crank_length(self) -> float:
        """l1 [m]: given, or V_ср/(4·n1) (seed 000, §1.1: l1 := V_ср/(n1·4))."""
        if self.crank.length is not None:
            return self.crank.length
        n1 = self.machine.omega_mean / (2 * math.pi)
        return self.design.mean_piston_speed / (4 * n1)

    def rod_length(self, dyad: RRPSpec) -> float:
        """Rod length [m]: given, or k·l1 (seed 000: l2 := l1·k)."""
        return dyad.rod_length if dyad.rod_length is not None else self.design.rod_to_crank * self.crank_length

    @model_validator(mode="after")
    def _references(self):
        _check_references(self)
        return self

    def mechanism(self):
        """The linkage as the kinematics describe it (:class:`flywheel.linkage.Mechanism`)."""
        return to_mechanism(self)

    def plausibility_warnings(self) -> list[str]:
        """Allowed but unusual values, one line each (see :func:`plausibility_warnings`)."""
        return plausibility_warnings(self)




def _check_references(case: Case) -> None:
    """Names are unique and defined before use; lengths can be derived."""
    if (case.crank is None) == (case.tabulated is None):
        raise FieldError((), Notice.of(
            "crank_or_tabulated", "give exactly one of [crank] (a linkage) and [tabulated] "
            "(kinematics from a table)"))
    given = case.flywheel.given_J is not None
    if given and case.machine.delta is not None:
        raise FieldError(("machine", "delta"), Notice.of(
            "delta_and_given_flywheel", "give exactly one of machine.delta (the flywheel is sized "
            "for it) and a given flywheel (flywheel.J, mass with radius_of_gyration, given_disk or "
            "given_rim), not both"))
    if not given and case.machine.delta is None:
        raise FieldError(("machine", "delta"), Notice.of(
            "delta_missing", "missing: give machine.delta (the flywheel is sized for it) or a "
            "given flywheel (flywheel.J, mass with radius_of_gyration, given_disk or given_rim)"))
    if case.motor is not None and case.motor.no_load_speed_rpm * 2 * math.pi / 60 <= case.machine.omega_mean:
        raise FieldError(("motor", "no_load_speed_rpm"), Notice.of(
            "motor_too_slow", "{n0:g} rpm is not above the mean speed {n:g} rpm",
            n0=case.motor.no_load_speed_rpm, n=case.machine.omega_mean * 30 / math.pi))
    if case.tabulated is not None:   # no linkage: masses and loads live in [tabulated]
        for key in ("ground", "dyads", "points", "links", "cylinders", "forces", "couples"):
            if getattr(case, key):
                raise FieldError((key,), Notice.of(
                    "run_not_with_tabulated", "not allowed with [tabulated]: give masses and loads "
                    "in [tabulated] (docs/tabulated.md)"))
        return
    if case.crank.length is None and case.design.mean_piston_speed is None:
        raise FieldError(("crank", "length"), Notice.of(
            "crank_length_missing", "missing: give crank.length or design.mean_piston_speed"))
    points: set[str] = set()
    links: set[str] = set()

    def new_point(name: str, loc: tuple) -> None:
        if name in points:
            raise FieldError(loc, Notice.of(
                "point_twice", "point name {name!r} is already defined", name=name))
        points.add(name)

    def new_link(name: str, loc: tuple) -> None:
        if name in links:
            raise FieldError(loc, Notice.of(
                "link_twice", "link name {name!r} is already defined", name=name))
        links.add(name)

    def known(name: str, loc: tuple) -> None:
        if name not in points:
            raise FieldError(loc, Notice.of(
                "point_used_before", "point {name!r} is used before it is defined (defined so far: "
                "{so_far})", name=name, so_far=", ".join(sorted(points))))

    for name in case.ground:
        new_point(name, ("ground", name))
    new_point(case.crank.pivot, ("crank", "pivot"))
    new_point(case.crank.tip, ("crank", "tip"))
    _check_pins(case)
    for i, pin in enumerate(case.crank.pins):
        new_point(pin.name, ("crank", "pins", i, "name"))
    new_link(case.crank.name, ("crank", "name"))
    on: dict[str, set[str]] = {case.crank.name: {case.crank.pivot, case.crank.tip}  # link → its points
                               | {pin.name for pin in case.crank.pins}}
    pending = dict(case.points)
    sliders: set[str] = set()

    def place_points() -> None:
        progress = True
        while progress:
            progress = False
            for name, p in list(pending.items()):
                if p.link in links and p.from_ in points and (p.to is None or p.to in points):
                    for key, q in (("from", p.from_), ("to", p.to)):
                        if q is not None and q not in on[p.link]:
                            raise FieldError(("points", name, key),
                                             _not_on_link(q, p.link, on[p.link], placed=True))
                    new_point(name, ("points", name))
                    on[p.link].add(name)
                    del pending[name]
                    progress = True

    place_points()
    for i, d in enumerate(case.dyads):
        place_points()
        known(d.from_, ("dyads", i, "from"))
        if isinstance(d, RRPSpec):
            if d.rod_length is None and case.design.rod_to_crank is None:
                raise FieldError(("dyads", i, "rod_length"), Notice.of(
                    "run_rod_length_missing", "missing: give rod_length or design.rod_to_crank"))
            new_link(d.rod, ("dyads", i, "rod"))
            new_link(d.slider, ("dyads", i, "slider"))
            new_point(d.joint, ("dyads", i, "joint"))
            sliders.add(d.slider)
            on[d.rod], on[d.slider] = {d.from_, d.joint}, {d.joint}
        elif isinstance(d, RRRSpec):
            known(d.to, ("dyads", i, "to"))
            new_link(d.link_from, ("dyads", i, "link_from"))
            new_link(d.link_to, ("dyads", i, "link_to"))
            new_point(d.joint, ("dyads", i, "joint"))
            on[d.link_from], on[d.link_to] = {d.from_, d.joint}, {d.to, d.joint}
        else:
            known(d.pivot, ("dyads", i, "pivot"))
            new_link(d.rocker, ("dyads", i, "rocker"))
            new_link(d.slider, ("dyads", i, "slider"))
            on[d.rocker], on[d.slider] = {d.pivot}, {d.from_}
    place_points()
    for name, p in pending.items():
        if p.link not in links:
            raise FieldError(("points", name, "link"), Notice.of(
                "link_not_defined", "link {name!r} is not defined (links: {links})", name=p.link,
                links=", ".join(sorted(links))))
        missing = p.from_ if p.from_ not in points else p.to
        raise FieldError(("points", name), Notice.of(
            "point_never_defined", "point {name!r} is never defined", name=missing))
    for name, link in case.links.items():
        if name not in links:
            raise FieldError(("links", name), Notice.of(
                "no_link_named", "no link named {name!r} (links: {links})", name=name,
                links=", ".join(sorted(links))))
        if link.centroid is not None and link.centroid not in points:
            raise FieldError(("links", name, "centroid"), Notice.of(
                "point_not_defined", "point {name!r} is not defined", name=link.centroid))
        if link.centroid is not None and link.centroid not in on[name]:
            raise FieldError(("links", name, "centroid"),
                             _not_on_link(link.centroid, name, on[name]))
    for i, c in enumerate(case.cylinders):
        if c.piston not in sliders:
            raise FieldError(("cylinders", i, "piston"), Notice(
                f"{c.piston!r} is not the slider of an RRP dyad "
                f"(sliders: {', '.join(sorted(sliders)) or 'none'})", "not_a_slider_of",
                name=c.piston, sliders=", ".join(sorted(sliders))))
    for i, c in enumerate(case.cylinders):
        for key, values in c.tables().items():
            low, high = min(values), max(values)
            if not high <= 1 + 1e-9:          # (mut) 1e300 here overflowed the energy silently
                raise FieldError(("cylinders", i) + c.table_loc(key),
                                 Notice.of(
                                     "pressure_above_p_max", "p/p_max = {high:g} is above 1: p_max "
                                     "= {p_max:g} Pa is the largest pressure of the diagram "
                                     "(allowed: −0.101325 MPa/p_max … 1; to go higher, raise p_max)",
                                     high=high, p_max=c.p_max))
            if low * c.p_max < -ATM:
                raise FieldError(("cylinders", i) + c.table_loc(key),
                                 Notice.of(
                                     "pressure_below_vacuum", "p/p_max = {low:g} gives {mpa:.4g} "
                                     "MPa gauge, below absolute vacuum (allowed: p ≥ −0.101325 MPa "
                                     "gauge)", low=low, mpa=low * c.p_max / 1e6))
    _check_engine(case)
    for i, f in enumerate(case.forces):
        if f.slider not in sliders:
            raise FieldError(("forces", i, "slider"), Notice.of(
                "not_a_slider", "{name!r} is not the slider of an RRP dyad", name=f.slider))
        lo, hi = f.s_range
        if not 0 <= lo < hi <= 1:
            raise FieldError(("forces", i, "s_range"), Notice.of(
                "s_range", "must satisfy 0 ≤ from < to ≤ 1 (got {lo}, {hi})", lo=lo, hi=hi))
    for i, c in enumerate(case.couples):
        if c.link not in links:
            raise FieldError(("couples", i, "link"), Notice.of(
                "no_link", "no link named {name!r}", name=c.link))
    names = ([(("cylinders", i, "name"), c.name) for i, c in enumerate(case.cylinders)]
             + [(("forces", i, "name"), f.name) for i, f in enumerate(case.forces)]
             + [(("couples", i, "name"), c.name) for i, c in enumerate(case.couples)])
    seen: set[str] = set()
    for loc, n in names:
        if n in seen:
            raise FieldError(loc, Notice.of(
                "load_twice", "load name {name!r} is used twice", name=n))
        seen.add(n)


def _not_on_link(point: str, link: str, its: set[str], placed: bool = False) -> Notice:
    """The error of a point named on a link that does not carry it; ``placed``: the point is
    one the case places on that link (``[points]``)."""
    return Notice(f"point {point!r} is not on link {link} (its points: {', '.join(sorted(its))})"
                  + (": a point fixed on a link is placed from that link's own points"
                     if placed else ""), "run_point_not_on_link", point=point, link=link,
                  points=", ".join(sorted(its)), placed=placed)


def _check_pins(case: Case) -> None:
    """Two pins of one crankshaft at the same angle and throw are one point of the plane
    mechanism: they must have one name (rods of an in-line engine's cylinders 1 and 4 share a
    pin), so a second name there is refused."""
    seen = [((0.0, case.crank_length), case.crank.tip, "the crank's tip")]
    for i, pin in enumerate(case.crank.pins):
        where = (pin.angle_deg % 360.0, pin.length if pin.length is not None else case.crank_length)
        for (angle, length), name, what in seen:
            gap = abs((where[0] - angle + 180.0) % 360.0 - 180.0)
            if gap < 1e-9 and abs(where[1] - length) <= 1e-12 * length:
                raise FieldError(("crank", "pins", i, "angle_deg"),
                                 Notice.of(
                                     "pin_twice", "{angle:g}° puts pin {pin!r} where {whom} "
                                     "{name!r} is (same angle and throw): pins at the same angle "
                                     "are one pin with one name (allowed: attach the rods to "
                                     "{name!r}, or give another angle)", angle=pin.angle_deg,
                                     pin=pin.name, whom=what, name=name))
        seen.append((where, pin.name, f"pin (crank.pins[{i}])"))


def _check_engine(case: Case) -> None:
    """A four-stroke diagram needs a cycle of 720° (or a multiple); a firing order names every
    four-stroke cylinder once and nothing else, and then sets where each fires."""
    cycle = case.machine.cycle_deg
    four = [c.name for c in case.cylinders if c.four_stroke]
    for i, c in enumerate(case.cylinders):
        if c.four_stroke and round(cycle) % 720:
            raise FieldError(("cylinders", i, "diagram" if c.diagram is not None else "strokes"),
                             Notice.of(
                                 "four_stroke_cycle", "a four-stroke diagram spans 720° of crank "
                                 "angle, the machine's cycle is {cycle:g}° (allowed: "
                                 "machine.cycle_deg = 720, or a multiple of 720)", cycle=cycle))
    order = case.machine.firing_order
    if order is None:
        return
    names = {c.name: c for c in case.cylinders}
    seen: set[str] = set()
    for k, name in enumerate(order):
        loc = ("machine", "firing_order", k)
        if name not in names:
            raise FieldError(loc, Notice(f"no cylinder named {name!r} (four-stroke cylinders: "
                                         f"{', '.join(four) or 'none'})", "run_firing_no_cylinder",
                                         name=name, four=", ".join(four)))
        if not names[name].four_stroke:
            raise FieldError(loc, Notice(f"cylinder {name!r} has no four-stroke diagram (strokes): "
                                         f"only four-stroke cylinders fire in an order (four-stroke "
                                         f"cylinders: {', '.join(four) or 'none'})",
                                         "run_firing_not_four_stroke", name=name,
                                         four=", ".join(four)))
        if name in seen:
            raise FieldError(loc, Notice.of(
                "run_firing_twice", "cylinder {name!r} is already in the order (each fires once "
                "per cycle)", name=name))
        seen.add(name)
    missing = [n for n in four if n not in seen]
    if missing:
        raise FieldError(("machine", "firing_order"), Notice.of(
            "firing_order_missing", "cylinder {name!r} is missing (a firing order lists every "
            "four-stroke cylinder once: {four})", name=missing[0], four=", ".join(four)))
    for i, c in enumerate(case.cylinders):
        if c.fires_at_deg is not None and c.name != order[0]:
            raise FieldError(("cylinders", i, "fires_at_deg"), Notice.of(
                "run_fires_at_with_order", "machine.firing_order sets where cylinder {name!r} "
                "fires (allowed: fires_at_deg on the first cylinder of the order, {first!r}, only)",
                name=c.name, first=order[0]))


# -- plausibility: allowed, but a careful engineer would look twice --------------------------------

ATM = 101_325.0          # Pa: a gauge pressure below −1 atm is below absolute vacuum
# δ of real machines (Артоболевский, «Теория механизмов и машин», table of δ: crushers and
# presses 1/5 … 1/20, pumps 1/5 … 1/30, machine tools 1/20 … 1/50, engines 1/80 … 1/150,
# generators 1/200 … 1/300)
DELTA_USUAL = (1 / 300, 1 / 5)


def plausibility_warnings(case: Case) -> list[str]:
    """Warnings (one line each, with the value and the usual range) for values that are
    allowed but unusual enough to suspect a slip: a crank of less than 5 mm (units?), δ outside
    1/300 … 1/5, a speed outside 1 … 20 000 rpm, negative (vacuum) gauge pressures in an
    indicator table. Values that cannot be right are refused by the schema instead."""
    out = []
    if case.crank is not None and case.crank_length < 5e-3:
        out.append(Notice.of(
            "crank_short", "crank.length: {length:g} m is unusually short (cranks: 5 mm … 2 m); "
            "lengths are in metres", length=case.crank_length))
    d = case.machine.delta
    if d is not None and not DELTA_USUAL[0] <= d <= DELTA_USUAL[1]:
        out.append(Notice.of(
            "delta_unusual", "machine.delta: δ = {delta:g} is outside the usual 1/300 … 1/5 "
            "({lo:.4f} … {hi:.1f}; Артоболевский's table: presses 1/5 … 1/20, engines 1/80 … "
            "1/150, generators 1/200 … 1/300)", delta=d, lo=DELTA_USUAL[0], hi=DELTA_USUAL[1]))
    rpm = case.machine.omega_mean * 30 / math.pi
    if not 1.0 <= rpm <= 20_000.0:
        out.append(Notice.of(
            "rpm_unusual", "machine: the crank speed {rpm:.6g} rpm is outside the usual 1 … 20 000 "
            "rpm", rpm=rpm))
    for i, c in enumerate(case.cylinders):
        for key, values in c.tables().items():
            low = min(values)
            if low < 0 and key not in ("intake", "compression"):   # an engine draws its
                # charge below atmospheric pressure, and compresses it from there
                where = ".".join(c.table_loc(key))
                out.append(Notice(f"cylinders[{i}].{where}: p/p_max down to {low:g} "
                                  f"({low * c.p_max / 1e6:.4g} MPa gauge, a vacuum): the tables "
                                  "are gauge pressures relative to p_max; check the sign",
                                  "cylinder_vacuum", where=f"cylinders[{i}].{where}", low=low,
                                  p=low * c.p_max / 1e6))
    return out


# -- errors ---------------------------------------------------------------------------------

_DYAD_TAGS = ("RRP", "RRR", "RPR")   # pydantic puts a dyad's kind into the error location

def _fields_at(loc: tuple) -> list[str]:
    """Valid keys of the table at ``loc`` (for 'did you mean')."""
    kinds = {"RRP": RRPSpec, "RRR": RRRSpec, "RPR": RPRSpec}
    tp: object = Case
    for part in loc:
        if tp is kinds:  # a dyad's tag (pydantic puts the kind into the loc): its own fields
            if part not in kinds:
                break
            tp = kinds[part]
            continue
        if isinstance(tp, type) and issubclass(tp, BaseModel):
            f = tp.model_fields.get(part) or next(
                (v for v in tp.model_fields.values() if v.alias == part), None)
            if f is None:
                return []
            tp = f.annotation
        else:
            origin = typing.get_origin(tp)
            args = typing.get_args(tp)
            if origin in (list, dict):
                tp = args[-1]
            else:
                return []
        # unwrap Optional / Annotated unions
        while typing.get_origin(tp) in (Union, Annotated, getattr(__import__("types"), "UnionType")):
            args = [a for a in typing.get_args(tp) if a is not type(None)]
            if typing.get_origin(tp) is Annotated:
                tp = args[0]
            elif all(isinstance(a, type) and issubclass(a, BaseModel) for a in args) and len(args) > 1:
                tp = kinds  # a dyad: resolved by the caller
                break
            else:
                tp = args[0]
    if tp is kinds:
        return sorted({(f.alias or n) for m in kinds.values() for n, f in m.model_fields.items()})
    if isinstance(tp, type) and issubclass(tp, BaseModel):
        return [(f.alias or n) for n, f in tp.model_fields.items()]
    return []


def _describe(err: dict) -> str:
    if err["type"] in ("union_tag_invalid", "union_tag_not_found"):
        return led(f"{loc_str(clean_loc(err['loc'], _DYAD_TAGS))}: ",
                   Notice.of("dyad_kind", "kind must be one of RRP, RRR, RPR"))
    return describe(err, _fields_at, _DYAD_TAGS)


def parse_case(data: dict, source: str = "<case>") -> Case:
    """Validate a parsed TOML document into a :class:`Case` or raise one CaseFileError line
    (a task-2 or aggregate case, or a variants template, is named as such)."""
    from flywheel.cases import wrong_kind

    other = wrong_kind(data, "run", source)
    if other is not None:
        raise CaseFileError(other)
    from flywheel.cases.tabulated import cycle_context

    return validate(data, Case, source, lambda errs: _describe(pick(errs, _DYAD_TAGS)),
                    context=cycle_context(data))   # a [tabulated] table covers the machine's cycle


def load_case(path) -> Case:
    """Read a TOML case file and validate it (one CaseFileError line on any problem)."""
    return load(path, parse_case)


def case_json_schema() -> dict:
    """The JSON Schema of case files (``flywheel schema``)."""
    schema = Case.model_json_schema(by_alias=True)
    schema["title"] = "flywheel case file"
    return schema


# -- to the computation's own types ------------------------------------------------------------

def dyad_name(d) -> str:
    """The name a dyad goes by in the kinematics and its messages: ``name``, else its joint
    (RRR, RRP) or its rocker (RPR)."""
    return d.name or (d.rocker if isinstance(d, RPRSpec) else d.joint)


def field_of(exc: Exception, case) -> str:
    """The case-file path of the dyad an error names (an AssemblyError's ``dyad``: 'dyads[1]'),
    else '' — the one lookup for the CLI guard and the variants' templates."""
    dyad = getattr(exc, "dyad", None)
    if dyad is None or case is None or not hasattr(case, "dyads"):
        return ""
    return next((f"dyads[{i}]" for i, d in enumerate(case.dyads) if dyad_name(d) == dyad), "")


def to_mechanism(case: Case):
    """Build the kinematics description (:class:`flywheel.linkage.Mechanism`) of a case."""
    from flywheel.linkage import RPR, RRP, RRR, Crank, CrankPin, Guide, LinkPoint, Mechanism

    c = case.crank
    pins = tuple(CrankPin(p.name, math.radians(p.angle_deg),
                          p.length if p.length is not None else case.crank_length) for p in c.pins)
    crank = Crank(c.name, c.pivot, tuple(c.pivot_at), c.tip, case.crank_length,
                  math.radians(c.start_angle_deg), -1 if c.rotation == "cw" else 1, pins)
    dyads = []
    for d in case.dyads:
        br = 1 if d.branch == "+" else -1
        if isinstance(d, RRPSpec):
            g = Guide(tuple(d.guide.through), math.radians(d.guide.angle_deg), d.guide.offset)
            dyads.append(RRP(dyad_name(d), d.from_, d.joint, d.rod, case.rod_length(d),
                             d.slider, g, br))
        elif isinstance(d, RRRSpec):
            dyads.append(RRR(dyad_name(d), d.from_, d.link_from, d.length_from, d.to,
                             d.link_to, d.length_to, d.joint, br))
        else:
            dyads.append(RPR(dyad_name(d), d.from_, d.pivot, d.rocker, d.slider, d.offset, br))
    points = tuple(
        LinkPoint(name, p.link, p.from_, p.to, p.fraction, p.across,
                  p.distance or 0.0, math.radians(p.angle_deg))
        for name, p in case.points.items()
    )
    ground = {k: tuple(v) for k, v in case.ground.items()}
    return Mechanism(crank, tuple(dyads), points, ground)
