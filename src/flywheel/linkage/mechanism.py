"""Plain descriptions of a mechanism: a crank, dyads and points on links (SI, radians).

These carry no behaviour; :mod:`flywheel.linkage.solve` places them on a φ grid.
The case loader builds them from a case file; tests and notebooks build them directly.
"""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class CrankPin:
    """A further crank pin (throw) on the crank's shaft: point ``name`` at ``length`` [m] from
    the pivot, at ``angle`` [rad] to the crank's tip, counter-clockwise positive; it turns with
    the crank, at θ1 + angle."""

    name: str
    angle: float
    length: float


@dataclass(frozen=True)
class Crank:
    """The driving link.

    name: link name; pivot: fixed point name at ``pivot_at`` [m]; tip: the crank pin's name;
    length [m]; start_angle [rad] from the +x axis at φ = 0; direction +1 (counter-clockwise)
    or −1 (clockwise). The crank's angle is θ1 = start_angle + direction·φ. ``pins``: further
    crank pins of a multi-throw crankshaft (:class:`CrankPin`), points of the same link.
    """

    name: str
    pivot: str
    pivot_at: tuple[float, float]
    tip: str
    length: float
    start_angle: float
    direction: int = 1
    pins: tuple[CrankPin, ...] = ()


@dataclass(frozen=True)
class Guide:
    """A fixed straight guide: the line through ``through`` [m] at ``angle`` [rad] from +x,
    shifted by ``offset`` [m] along its left normal (−sin α, cos α)."""

    through: tuple[float, float]
    angle: float
    offset: float = 0.0


@dataclass(frozen=True)
class RRP:
    """Connecting rod ``rod`` (length [m]) from known point ``origin`` to joint ``joint``,
    which slides with link ``slider`` on a fixed ``guide``. branch +1 puts the joint ahead of
    the foot of the perpendicular from ``origin`` along the guide direction, −1 behind it."""

    name: str
    origin: str
    joint: str
    rod: str
    rod_length: float
    slider: str
    guide: Guide
    branch: int = 1

    @property
    def links(self) -> tuple[str, str]:
        """The group's links in the order of its chain from the known point: rod, slider."""
        return self.rod, self.slider


@dataclass(frozen=True)
class RRR:
    """Two links joined at ``joint``: ``link_a`` (length_a [m]) from known point ``point_a``
    and ``link_b`` (length_b [m]) from known point ``point_b``. branch +1 puts the joint to
    the left of the line point_a → point_b, −1 to the right."""

    name: str
    point_a: str
    link_a: str
    length_a: float
    point_b: str
    link_b: str
    length_b: float
    joint: str
    branch: int = 1

    @property
    def links(self) -> tuple[str, str]:
        return self.link_a, self.link_b


@dataclass(frozen=True)
class RPR:
    """Slotted link (кулиса): a block ``slider`` pivoted at the known point ``origin`` slides
    along link ``rocker``, which turns about the known point ``pivot``. The slide line is
    shifted by ``offset`` [m] along the rocker's left normal. The rocker's angle is that of its
    slide direction, pointing from ``pivot`` towards ``origin`` for branch +1 (s > 0), away
    from it for branch −1."""

    name: str
    origin: str
    pivot: str
    rocker: str
    slider: str
    offset: float = 0.0
    branch: int = 1

    @property
    def links(self) -> tuple[str, str]:
        """The group's links in the order of its chain from the known point: block (on
        ``origin``), then the rocker — «группа звеньев 2, 3» of a shaper."""
        return self.slider, self.rocker


@dataclass(frozen=True)
class LinkPoint:
    """A point fixed on link ``link``: either at ``fraction`` of the way from ``origin`` to
    ``toward`` (both points of the link) plus ``across`` [m] along the left normal of that
    segment, or at ``distance`` [m] from ``origin`` at ``angle`` [rad] to the link's own
    direction (for a link whose direction the solver knows: crank, rods, rockers)."""

    name: str
    link: str
    origin: str
    toward: str | None = None
    fraction: float = 0.0
    across: float = 0.0
    distance: float = 0.0
    angle: float = 0.0


@dataclass(frozen=True)
class Mechanism:
    """A crank, its dyads and extra points, solved in the order given."""

    crank: Crank
    dyads: tuple = ()
    points: tuple[LinkPoint, ...] = ()
    ground: dict[str, tuple[float, float]] = field(default_factory=dict)
