"""The linkage of a run case file: the crank with its further pins, the guides, the dyads
(RRP, RRR, RPR), the points placed on links and the links' masses (re-exported by
:mod:`flywheel.cases.run`; the format: docs/case-format.md)."""
from __future__ import annotations

from typing import Annotated, Literal, Union

from pydantic import Field, model_validator

from flywheel.errors import Notice
from flywheel.io.schema import MAX_TEXT, StrictModel
from flywheel.cases.run_fields import XY, Angle, Coord, Inertia, Length, Mass, Name, _within


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
    name: str | None = Field(None, max_length=MAX_TEXT, description="dyad name (default: the joint's)")
    from_: Name = Field(alias="from", description="known point the rod starts from")
    joint: Name = Field(description="name of the rod–slider joint (new point)")
    rod: Name = Field(description="link name of the rod")
    rod_length: Length | None = Field(None, description="rod length [m]")
    slider: Name = Field(description="link name of the slider")
    guide: GuideSpec
    branch: Branch = Field("+", description="assembly: joint ahead (+) of or behind (−) the "
                                            "rod's foot along the guide direction")

    @property
    def links(self) -> tuple[str, str]:
        """The group's links in the order of its chain (linkage.mechanism.RRP.links)."""
        return self.rod, self.slider


class RRRSpec(StrictModel):
    """Two links, three revolute joints."""

    kind: Literal["RRR"]
    name: str | None = Field(None, max_length=MAX_TEXT)
    from_: Name = Field(alias="from", description="known point of the first link")
    link_from: Name = Field(description="link name from `from` to the joint")
    length_from: Length = Field(description="its length [m]")
    to: Name = Field(description="known point of the second link")
    link_to: Name = Field(description="link name from `to` to the joint")
    length_to: Length = Field(description="its length [m]")
    joint: Name = Field(description="name of the middle joint (new point)")
    branch: Branch = Field("+", description="joint left (+) or right (−) of the line from → to")

    @property
    def links(self) -> tuple[str, str]:
        return self.link_from, self.link_to


class RPRSpec(StrictModel):
    """Slotted link (кулиса): a block at a known point slides on a rocker about a pivot."""

    kind: Literal["RPR"]
    name: str | None = Field(None, max_length=MAX_TEXT)
    from_: Name = Field(alias="from", description="known point carrying the block")
    pivot: Name = Field(description="known point the rocker turns about")
    rocker: Name = Field(description="link name of the rocker")
    slider: Name = Field(description="link name of the block")
    offset: Coord = Field(0.0, description="slide line offset from the pivot [m]")
    branch: Branch = Field("+", description="block on the rocker's positive (+) side of the pivot")

    @property
    def links(self) -> tuple[str, str]:
        """The block, then the rocker (linkage.mechanism.RPR.links)."""
        return self.slider, self.rocker


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

