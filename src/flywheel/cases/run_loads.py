"""The loads of a run case file that are not cylinders (re-exported by
:mod:`flywheel.cases.run`; the format: docs/case-format.md, [[forces]], [[couples]],
[[springs]]):

- ``[[forces]]``: a technological force on a slider over part of its relative travel (the
  course's cutting force, ``slider``), or a force at any named point of any link (``point``):
  a fixed direction, along or across a link, or against the point's velocity; a constant
  magnitude or a table against the crank angle φ or against the point's travel along its path;
- ``[[couples]]``: a couple on a link, constant or a table against φ;
- ``[[springs]]``: a linear spring between two points, a torsional spring on a link about its
  joint with the frame or between two links about their common joint.

Every load of the first two may act over a part of the cycle only, ``phi_range_deg``. The
checks across tables (names, points, links, ranges against the cycle) are :func:`check_loads`,
called by :func:`flywheel.cases.run_checks._check_references`.
"""
from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, Strict, model_validator

from flywheel.cases.run_fields import XY, Angle, Force, Length, Moment, Name, _within
from flywheel.errors import Notice
from flywheel.io.schema import FieldError, StrictModel, TitleText, at_most, title_field

MAX_TABLE_ROWS = 1000
"""The most rows a load's table may have."""

PhiRange = Annotated[tuple[float, float], Strict(False), _within(0.0, 3600.0, "deg")]
Row = Annotated[tuple[float, float], Strict(False)]
Table = Annotated[list[Row], at_most(MAX_TABLE_ROWS, "rows")]
Stiffness = Annotated[float, Field(gt=0), _within(0.0, 1e12, "")]

ROW_LIMITS = {"phi": (0.0, 3600.0, "deg"), "travel": (0.0, 1e3, "m")}
VALUE_LIMITS = {"force": (-1e9, 1e9, "N"), "couple": (-1e9, 1e9, "N·m")}


def _check_range(model, key: str = "phi_range_deg") -> None:
    rng = getattr(model, key)
    if rng is not None and rng[0] == rng[1]:
        raise FieldError((key,), Notice.of(
            "phi_range_empty", "from = to = {a:g}°: an empty range (allowed: from ≠ to; from > "
            "to wraps through 0)", a=rng[0]))


def _check_table(table, x_kind: str, value_kind: str) -> None:
    """A table of [x, value] rows: at least 2, x strictly increasing, both in their ranges."""
    if len(table) < 2:
        raise FieldError(("table",), Notice.of(
            "load_table_short", "has {n} row(s) (allowed: at least 2 rows [x, value])",
            n=len(table)))
    lo, hi, unit = ROW_LIMITS[x_kind]
    vlo, vhi, vunit = VALUE_LIMITS[value_kind]
    for i, (x, v) in enumerate(table):
        for k, (val, a, b, u) in enumerate(((x, lo, hi, unit), (v, vlo, vhi, vunit))):
            if not a <= val <= b:
                raise FieldError(("table", i, k), Notice.of(
                    "out_of_range", "{x:g}{unit_shown} is out of range (allowed: {lo:g} … "
                    "{hi:g}{unit_shown})", x=val, lo=a, hi=b, unit=u, unit_shown=f" {u}"))
        if i and not x > table[i - 1][0]:
            raise FieldError(("table", i, 0), Notice.of(
                "load_table_order", "{x:g} does not follow {prev:g} (allowed: the first column "
                "strictly increasing)", x=x, prev=table[i - 1][0]))


#: the description of a load's ``label``
LABEL = ("its short name in the force plans, Zhukovsky's lever and the drawing sheets, the "
         "subscript of its F or M (F_пс for a force named cutting): a string, or { ru = …, en "
         "= … } (default: its name)")


class ForceSpec(StrictModel):
    """A force. On a slider (``slider``): the course's technological force against the slider's
    motion while its relative travel s lies in ``s_range`` (and it moves in ``stroke``). At a
    point (``point``): any direction and magnitude, see docs/case-format.md."""

    name: Name
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    label: TitleText = title_field(description=LABEL)
    # the slider form (the course's cutting force)
    slider: Name | None = Field(None, description="slider link of an RRP dyad (the slider form)")
    reference: Literal["outer", "inner"] = Field("outer", description="dead centre s is measured from")
    s_range: XY = Field((0.0, 1.0), description="relative travel where the force acts, 0 … 1")
    stroke: Literal["towards", "away", "both"] = Field(
        "both", description="acts while the slider moves towards / away from the reference")
    # the point form
    point: Name | None = Field(None, description="the named point the force acts at (the point form)")
    link: Name | None = Field(None, description="the link it acts on (default: the link that "
                                                "carries the point)")
    direction: Literal["fixed", "along", "across", "against-velocity"] | None = Field(
        None, description="fixed (angle_deg from +x), along or across the link, or against the "
                          "point's velocity (a resistance); default against-velocity")
    angle_deg: Angle | None = Field(None, description="the fixed direction from +x [deg]")
    # both forms
    magnitude: Force | None = Field(None, description="force [N] (> 0 resists the motion in the "
                                                      "slider form and against-velocity)")
    table: Table | None = Field(None, description="[[x, F], …]: F [N] against table_of")
    table_of: Literal["phi", "travel"] = Field(
        "phi", description="the table's first column: crank angle φ [deg] or the point's travel "
                           "along its path since the range began [m]")
    phi_range_deg: PhiRange | None = Field(
        None, description="[from, to]: crank angles [deg] where the force acts (closed; from > to "
                          "wraps through 0)")

    @model_validator(mode="after")
    def _forms(self):
        if (self.slider is None) == (self.point is None):
            raise FieldError((), Notice.of(
                "force_slider_or_point", "give exactly one of slider (a technological force on a "
                "slider) and point (a force at a point of a link)"))
        if (self.magnitude is None) == (self.table is None):
            raise FieldError(("magnitude",), Notice.of(
                "load_magnitude_or_table", "give exactly one of magnitude and table"))
        set_ = self.model_fields_set
        if self.slider is not None:
            for key in ("link", "direction", "angle_deg", "table", "table_of"):
                if key in set_:
                    raise FieldError((key,), Notice.of(
                        "force_key_needs_point", "goes with point, not with slider (allowed for "
                        "a slider: magnitude, reference, s_range, stroke, phi_range_deg)"))
        else:
            for key in ("reference", "s_range", "stroke"):
                if key in set_:
                    raise FieldError((key,), Notice.of(
                        "force_key_needs_slider", "goes with slider, not with point (allowed for "
                        "a point: link, direction, angle_deg, magnitude or table, table_of, "
                        "phi_range_deg)"))
            if (self.direction == "fixed") != (self.angle_deg is not None):
                raise FieldError(("angle_deg",), Notice.of(
                    "force_angle_with_fixed", "angle_deg goes with direction = \"fixed\", and "
                    "direction = \"fixed\" needs angle_deg"))
            if self.table is not None:
                _check_table(self.table, self.table_of, "force")
            if self.table_of == "travel" and self.direction not in (None, "against-velocity"):
                raise FieldError(("table_of",), Notice.of(
                    "force_travel_resists", "a force against the travel is a resistance (allowed: "
                    "direction = \"against-velocity\" with table_of = \"travel\")"))
        _check_range(self)
        return self

    @property
    def acts(self) -> str:
        """The direction of a point force (against-velocity when not given)."""
        return self.direction or "against-velocity"


class CoupleSpec(StrictModel):
    """A couple on a link [N·m], counter-clockwise positive: constant, or a table against the
    crank angle φ; over the whole cycle or over ``phi_range_deg``."""

    name: Name
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    label: TitleText = title_field(description=LABEL)
    link: Name
    moment: Moment | None = None
    table: Table | None = Field(None, description="[[φ_deg, M], …]: M [N·m] against φ")
    phi_range_deg: PhiRange | None = Field(
        None, description="[from, to]: crank angles [deg] where the couple acts (closed; from > "
                          "to wraps through 0)")

    @model_validator(mode="after")
    def _forms(self):
        if (self.moment is None) == (self.table is None):
            raise FieldError(("moment",), Notice.of(
                "couple_moment_or_table", "give exactly one of moment and table"))
        if self.table is not None:
            _check_table(self.table, "phi", "couple")
        _check_range(self)
        return self


class SpringSpec(StrictModel):
    """A spring: linear between two named points (U = ½·c·(L − L0)²), torsional on a link
    about its joint with the frame (U = ½·c·(θ − θ0)²) or torsional between two links about
    their common joint (U = ½·c·(θ_a − θ_b − θ0)²)."""

    name: Name
    title: TitleText = title_field(description="its name in the documents and figures: a string, or { ru = …, en = … } "
                                                  "(default: its kind and name, as 'force cutting')")
    label: TitleText = title_field(description=LABEL)
    kind: Literal["linear", "torsional"]
    stiffness: Stiffness = Field(description="c [N/m] (linear) or [N·m/rad] (torsional)")
    points: Annotated[tuple[Name, Name], Strict(False)] | None = Field(None, description="linear: its two ends (named points)")
    free_length: Length | None = Field(None, description="linear: its free length L0 [m]")
    preload: Force | None = Field(None, description="linear: its force [N] at preload_at_deg, "
                                                    "> 0 in tension, < 0 in compression")
    preload_at_deg: Angle = Field(0.0, description="linear: the crank angle φ of the preload [deg]")
    link: Name | None = Field(None, description="torsional: the link it turns")
    links: Annotated[tuple[Name, Name], Strict(False)] | None = Field(
        None, description="torsional between two links (instead of link): [a, b], the two links "
                          "it joins at about; it acts on their relative angle θ_a − θ_b")
    about: Name | None = Field(None, description="torsional: the link's fixed pivot, or the common "
                                                 "joint of the two links")
    free_angle_deg: Angle | None = Field(None, description="torsional: the link's angle θ (between "
                                                           "two links: θ_a − θ_b) where the spring "
                                                           "is free [deg]")

    @model_validator(mode="after")
    def _forms(self):
        set_ = self.model_fields_set
        if self.kind == "linear":
            mine, other = ("points",), ("link", "links", "about", "free_angle_deg")
            if self.points is None:
                raise FieldError(("points",), Notice.of(
                    "spring_points_missing", "missing: a linear spring needs points = [P, Q]"))
            if self.points[0] == self.points[1]:
                raise FieldError(("points",), Notice.of(
                    "spring_same_point", "both ends are {p!r} (allowed: two different points)",
                    p=self.points[0]))
            if (self.free_length is None) == (self.preload is None):
                raise FieldError(("free_length",), Notice.of(
                    "spring_length_or_preload", "give exactly one of free_length and preload "
                    "(with preload_at_deg)"))
            if "preload_at_deg" in set_ and self.preload is None:
                raise FieldError(("preload_at_deg",), Notice.of(
                    "spring_at_needs_preload", "goes with preload"))
        else:
            between = self.links is not None
            if between and self.link is not None:
                raise FieldError(("links",), Notice.of(
                    "spring_link_or_links", "give link (a spring to the frame) or links (a "
                    "spring between two links), not both"))
            mine = ("links" if between else "link", "about", "free_angle_deg")
            other = ("points", "free_length", "preload", "preload_at_deg")
            for key in mine:
                if getattr(self, key) is None:
                    raise FieldError((key,), Notice.of(
                        "spring_torsional_missing", "missing: a torsional spring needs link (or "
                        "links), about and free_angle_deg"))
            if between and self.links[0] == self.links[1]:
                raise FieldError(("links",), Notice.of(
                    "spring_same_link", "both links are {link!r} (allowed: two different links "
                    "joined at about)", link=self.links[0]))
        for key in other:
            if key in set_:
                raise FieldError((key,), Notice.of(
                    "spring_key_kind", "does not go with kind = {kind!r} (allowed: {allowed})",
                    kind=self.kind, allowed=", ".join(
                        ("name", "kind", "stiffness") + mine
                        + (("free_length", "preload", "preload_at_deg") if self.kind == "linear"
                           else ()))))
        return self


def check_loads(case, points: set[str], links: set[str], on: dict[str, set[str]],
                sliders: set[str], fixed: set[str]) -> None:
    """The loads' names against the linkage: a force's slider, point and link, a couple's link,
    a spring's points, link and pivot, every phi_range_deg and table within the cycle. ``on``:
    link → its points; ``fixed``: the points of the frame."""
    cycle = case.machine.cycle_deg

    def within_cycle(loc: tuple, values) -> None:
        for k, a in enumerate(values):
            if a > cycle:
                raise FieldError(loc + (k,), Notice.of(
                    "phi_beyond_cycle", "{a:g}° is beyond the cycle (allowed: 0 … {cycle:g}°, "
                    "machine.cycle_deg)", a=a, cycle=cycle))

    def point_known(loc: tuple, name: str) -> None:
        if name not in points:
            raise FieldError(loc, Notice.of(
                "load_point_unknown", "no point named {name!r} (points: {known})", name=name,
                known=", ".join(sorted(points))))

    def link_known(loc: tuple, name: str) -> None:
        if name not in links:
            raise FieldError(loc, Notice.of(
                "no_link", "no link named {name!r}", name=name))

    for i, f in enumerate(case.forces):
        if f.phi_range_deg is not None:
            within_cycle(("forces", i, "phi_range_deg"), f.phi_range_deg)
        if f.slider is not None:
            if f.slider not in sliders:
                raise FieldError(("forces", i, "slider"), Notice.of(
                    "not_a_slider", "{name!r} is not the slider of an RRP dyad", name=f.slider))
            lo, hi = f.s_range
            if not 0 <= lo < hi <= 1:
                raise FieldError(("forces", i, "s_range"), Notice.of(
                    "s_range", "must satisfy 0 ≤ from < to ≤ 1 (got {lo}, {hi})", lo=lo, hi=hi))
            continue
        point_known(("forces", i, "point"), f.point)
        if f.point in fixed:
            raise FieldError(("forces", i, "point"), Notice.of(
                "load_point_fixed", "{name!r} is a point of the frame: a force there does no "
                "work and loads no link (allowed: a moving point)", name=f.point))
        carrying = sorted(k for k, v in on.items() if f.point in v)
        if f.link is not None:
            link_known(("forces", i, "link"), f.link)
            if f.link not in carrying:
                raise FieldError(("forces", i, "link"), Notice.of(
                    "load_point_not_on_link", "point {point!r} is not on link {link} (links "
                    "carrying it: {carrying})", point=f.point, link=f.link,
                    carrying=", ".join(carrying)))
        if f.table is not None and f.table_of == "phi":
            within_cycle(("forces", i, "table", len(f.table) - 1), [f.table[-1][0]])
    for i, c in enumerate(case.couples):
        if c.link not in links:
            raise FieldError(("couples", i, "link"), Notice.of(
                "no_link", "no link named {name!r}", name=c.link))
        if c.phi_range_deg is not None:
            within_cycle(("couples", i, "phi_range_deg"), c.phi_range_deg)
        if c.table is not None:
            within_cycle(("couples", i, "table", len(c.table) - 1), [c.table[-1][0]])
    for i, s in enumerate(case.springs):
        if s.kind == "linear":
            for k, p in enumerate(s.points):
                point_known(("springs", i, "points", k), p)
            if all(p in fixed for p in s.points):
                raise FieldError(("springs", i, "points"), Notice.of(
                    "spring_both_fixed", "both ends are points of the frame: the spring never "
                    "changes length (allowed: at least one moving point)"))
        elif s.links is not None:           # between two links, at their common joint
            for k, lk in enumerate(s.links):
                link_known(("springs", i, "links", k), lk)
            point_known(("springs", i, "about"), s.about)
            a, b = s.links
            if s.about not in on.get(a, set()) & on.get(b, set()):
                raise FieldError(("springs", i, "about"), Notice.of(
                    "spring_about_joint", "{about!r} is not a joint of links {a} and {b} "
                    "(allowed: a point on both: {joints})", about=s.about, a=a, b=b,
                    joints=", ".join(sorted(on.get(a, set()) & on.get(b, set()))) or "—"))
        else:
            link_known(("springs", i, "link"), s.link)
            point_known(("springs", i, "about"), s.about)
            if s.about not in fixed or s.about not in on.get(s.link, set()):
                raise FieldError(("springs", i, "about"), Notice.of(
                    "spring_about_pivot", "{about!r} is not a fixed pivot of link {link} (allowed: "
                    "the point of the frame the link turns about: {pivots})", about=s.about,
                    link=s.link, pivots=", ".join(sorted(on.get(s.link, set()) & fixed))
                    or "none: the link has no fixed pivot"))
