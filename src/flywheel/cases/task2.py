"""The TOML case format of ``flywheel task2`` (documented field by field in docs/task2.md).

A case gives the cycle, the speed, the flywheel, and either two moment graphs (``[driving]``
and ``[resistance]``) or a turning-moment diagram by its areas (``[diagram]``). Angles are in
degrees in the file and radians inside; moments in N·m; J in kg·m². One value of one graph may
be the string ``"balance"``: the unknown found from the cycle balance; one value may be
``"power"``: found from the mean power ``power`` [W] at the mean speed (T_mean = P/ω_ср).
``at_deg`` lists angles where ω, ε and t are reported.

Every problem becomes one :class:`~flywheel.errors.CaseFileError` line:
``file: field.path: what is wrong (what is allowed)``.
"""
from __future__ import annotations

import difflib
import math
from typing import Annotated, ClassVar, Literal, Union

from pydantic import Field, Strict, field_validator

from flywheel.cases.rim import MATERIALS, Density, Material, RimSpec, Stress
from flywheel.constant_inertia import graphs
from flywheel.constant_inertia.solve import (BALANCE_RTOL, Task2Result, balance, power_value, solve,
                                            solve_areas)
from flywheel.errors import CaseFileError, InputError, Notice, led, said
from flywheel.io.schema import TitleText, title_field, FieldError, StrictModel, at_most, load, text_field, validate, within, clean_loc, describe, loc_str, pick
from flywheel.cases.document import DocumentSpec

BALANCE = "balance"
POWER = "power"
#: the largest harmonic amplitude or mean term [N·m] (the largest engines give 1e7)
MAX_MOMENT = 1e9
#: the largest area [mm²] or energy [J] of a diagram
MAX_ENERGY = 1e15
#: the most angles of at_deg, areas of a diagram
MAX_ANGLES = 1000
#: the most work of the two graphs together: pieces of M_D − M_C × (1 + its terms) (about 10 s)
MAX_WORK = 2_000_000




def _amount(v):
    """A number, or the string "balance" (the unknown of the cycle balance) or "power" (the
    unknown of the mean power)."""
    if isinstance(v, str) and v not in (BALANCE, POWER):
        raise ValueError(Notice.of("amount_word", 'must be a number, "balance" or "power" '
                                   "(got {value})", value=repr(v)))
    return v


Amount = Union[float, str]


class _Graph(StrictModel):
    _AMOUNTS: ClassVar[tuple[str, ...]] = ()

    @field_validator("value", "scale", "peak", "a0", check_fields=False)
    @classmethod
    def _balance_or_number(cls, v):
        return _amount(v)

    def unknown_field(self) -> str | None:
        """The field that is "balance", if any."""
        for name in self._AMOUNTS:
            if getattr(self, name) == BALANCE:
                return name
        return None

    def power_field(self) -> str | None:
        """The field that is "power", if any."""
        for name in self._AMOUNTS:
            if getattr(self, name) == POWER:
                return name
        return None


class ConstantGraph(_Graph):
    """M = value over the whole cycle."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("value",)
    kind: Literal["constant"]
    value: Amount = Field(description='the moment [N·m], or "balance" or "power"')


class PointsGraph(_Graph):
    """Piecewise-linear through [angle, moment] points spanning the cycle."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("scale",)
    kind: Literal["points"]
    points: Annotated[list[Annotated[tuple[float, float], Strict(False)]],
                      at_most(graphs.MAX_POINTS, "points")] = Field(
        description="[[φ (deg), M (N·m)], …] from 0 to cycle_deg, angles never decreasing; "
                    "a repeated angle is a jump")
    scale: Amount = Field(1.0, description='multiplier of every ordinate, or "balance" or '
                                           '"power"')


class TriangleGraph(_Graph):
    """base outside [from, to]; linear up to peak at apex and down again."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("peak",)
    kind: Literal["triangle"]
    from_deg: float = Field(description="start of the triangle [deg]")
    to_deg: float = Field(description="end of the triangle [deg]")
    apex_deg: float | None = Field(None, description="angle of the peak [deg]; default middle")
    peak: Amount = Field(description='the peak [N·m], or "balance" or "power"')
    base: float = Field(0.0, description="the level outside the triangle [N·m]")


class RectangleGraph(_Graph):
    """peak on [from, to], base elsewhere."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("peak",)
    kind: Literal["rectangle"]
    from_deg: float = Field(description="start [deg]")
    to_deg: float = Field(description="end [deg]")
    peak: Amount = Field(description='the height [N·m], or "balance" or "power"')
    base: float = Field(0.0, description="the level outside [N·m]")


class TrapezoidGraph(_Graph):
    """base → peak on [from, top_from], peak to top_to, back to base at to."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("peak",)
    kind: Literal["trapezoid"]
    from_deg: float = Field(description="start of the rise [deg]")
    top_from_deg: float = Field(description="start of the top [deg]")
    top_to_deg: float = Field(description="end of the top [deg]")
    to_deg: float = Field(description="end of the fall [deg]")
    peak: Amount = Field(description='the top [N·m], or "balance" or "power"')
    base: float = Field(0.0, description="the level outside [N·m]")


class HarmonicGraph(_Graph):
    """M = a0 + Σ (a_k·sin kφ + b_k·cos kφ), φ in radians."""

    _AMOUNTS: ClassVar[tuple[str, ...]] = ("a0",)
    kind: Literal["harmonic"]
    a0: Annotated[Amount, within(-MAX_MOMENT, MAX_MOMENT, "N·m")] = Field(
        0.0, description='the mean term [N·m], or "balance" or "power"')
    a: Annotated[list[float], at_most(graphs.MAX_TERMS, "terms"),
                 within(-MAX_MOMENT, MAX_MOMENT, "N·m")] = Field(
        default_factory=list, description="sine amplitudes a_k [N·m] (at most 1000 terms)")
    b: Annotated[list[float], at_most(graphs.MAX_TERMS, "terms"),
                 within(-MAX_MOMENT, MAX_MOMENT, "N·m")] = Field(
        default_factory=list, description="cosine amplitudes b_k [N·m] (at most 1000 terms)")
    orders: Annotated[list[float], at_most(graphs.MAX_TERMS, "orders"),
                      within(1e-3, 1000.0, "")] | None = Field(
        None, description="the orders k of the terms; default 1, 2, … (at most 1000); each "
                          "repeats over the cycle: k·cycle_deg/360 a whole number")


KINDS = {"constant": ConstantGraph, "points": PointsGraph, "triangle": TriangleGraph,
         "rectangle": RectangleGraph, "trapezoid": TrapezoidGraph, "harmonic": HarmonicGraph}
Graph = Annotated[Union[tuple(KINDS.values())], Field(discriminator="kind")]


class Speed(StrictModel):
    """Exactly one of the four, or the limits max with min (max_rpm with min_rpm)."""

    omega0: Annotated[float, within(1e-3, 1e5, "rad/s")] | None = Field(None, description="ω at φ = 0 [rad/s]")
    omega0_rpm: Annotated[float, within(1e-2, 1e6, "rpm")] | None = Field(None, description="speed at φ = 0 [rev/min]")
    mean: Annotated[float, within(1e-3, 1e5, "rad/s")] | None = Field(None, description="mean speed ω_ср [rad/s]")
    mean_rpm: Annotated[float, within(1e-2, 1e6, "rpm")] | None = Field(None, description="mean speed [rev/min]")
    max: Annotated[float, within(1e-3, 1e5, "rad/s")] | None = Field(None, description="the largest speed allowed [rad/s] (with min): "
                                                "ω_m = (max + min)/2, δ = (max − min)/ω_m")
    min: Annotated[float, within(1e-3, 1e5, "rad/s")] | None = Field(None, description="the smallest speed allowed [rad/s] (with max)")
    max_rpm: Annotated[float, within(1e-2, 1e6, "rpm")] | None = Field(None, description="the largest speed allowed [rev/min]")
    min_rpm: Annotated[float, within(1e-2, 1e6, "rpm")] | None = Field(None, description="the smallest speed allowed [rev/min]")


class Flywheel(StrictModel):
    """The reduced inertia, or what it must achieve."""

    J: float | None = Field(None, description="reduced moment of inertia [kg·m²]")
    mass: float | None = Field(None, description="mass of the rotating parts [kg]")
    radius_of_gyration: float | None = Field(
        None, description="k [m]: with mass, J = m·k²; without it, the mass m = J/k² is reported")
    delta: float | None = Field(None, description="asked δ = (ω_max − ω_min)/ω_ср")
    fluctuation_percent: float | None = Field(
        None, description="asked '±x % of the mean speed': δ = 2x/100 [%]")
    rim_radius: float | None = Field(None, description="mean radius of a rim: m = J/R² [m]")
    material: Material = Field("steel", description="for [flywheel.rim]: sets density (7800 / "
                               "7200 kg/m³) and allowable rim stress (20 / 7 MPa) unless given")
    density: Density | None = Field(None, description="material density ρ [kg/m³]")
    allowable_stress: Stress | None = Field(
        None, description="allowable hoop stress of the rim σ_allow [Pa]")
    rim: RimSpec | None = Field(None, description="design the rim: mean diameter from the rim "
                                                  "speed or the allowable stress, share of J, "
                                                  "section")

    @property
    def rho(self) -> float:
        return self.density if self.density is not None else MATERIALS[self.material][0]

    @property
    def sigma(self) -> float:
        return self.allowable_stress if self.allowable_stress is not None else MATERIALS[self.material][1]


class Diagram(StrictModel):
    """A turning-moment diagram by its areas between crossings with the mean line."""

    areas: Annotated[list[float], at_most(MAX_ANGLES, "areas"),
                     within(-MAX_ENERGY, MAX_ENERGY, "mm²")] | None = Field(
        None, description="signed areas in order [mm²]")
    moment_scale: Annotated[float, within(-MAX_MOMENT, MAX_MOMENT, "N·m")] | None = Field(
        None, description="moment per mm of drawing [N·m/mm]")
    angle_scale_deg: Annotated[float, within(-36000.0, 36000.0, "deg")] | None = Field(
        None, description="angle per mm of drawing [deg/mm]")
    energies: Annotated[list[float], at_most(MAX_ANGLES, "energies"),
                        within(-MAX_ENERGY, MAX_ENERGY, "J")] | None = Field(
        None, description="signed energies instead [J]")
    crossings_deg: Annotated[list[float], at_most(MAX_ANGLES + 1, "angles")] | None = Field(
        None, description="angles of the crossings, one more than the areas [deg]")
    delta_E: Annotated[float, within(-MAX_ENERGY, MAX_ENERGY, "J")] | None = Field(None, description="the maximum fluctuation of energy ΔE "
                                                    "itself [J] (the diagram [ΔE, −ΔE])")
    energy_fluctuation_coefficient: float | None = Field(
        None, description="C_E = ΔE / work done per cycle, with work_per_cycle or the top-level "
                          "power")
    work_per_cycle: Annotated[float, within(-MAX_ENERGY, MAX_ENERGY, "J")] | None = Field(
        None, description="work done per cycle [J] (with "
                                                           "energy_fluctuation_coefficient)")


class Task2Case(StrictModel):
    """A task-2 problem."""

    title: TitleText = title_field(description="what the case is")
    source: TitleText = title_field(description="where it comes from (book, problem)")
    notes: str = text_field(description="anything else")
    cycle_deg: Annotated[float, within(1e-3, 36000.0, "deg")] = Field(
        360.0, description="length of the cycle [deg]: 360, 720, 1080 … (at most 100 revolutions)")
    power: float | None = Field(None, description="mean power [W]: a graph value \"power\" is "
                                                  "found from T_mean = P/ω_ср; with [diagram] "
                                                  "energy_fluctuation_coefficient, W = P·Φ/ω_m")
    at_deg: Annotated[list[float], at_most(MAX_ANGLES, "angles")] = Field(default_factory=list,
                                description="angles [deg] where ω, ε and t are reported")
    speed: Speed
    flywheel: Flywheel
    driving: Graph | None = None
    resistance: Graph | None = None
    diagram: Diagram | None = None
    document: DocumentSpec = Field(default_factory=DocumentSpec, description="names for the title page and the title block (docs/case-format.md, [document])")


TOP = {"speed": Speed, "flywheel": Flywheel, "diagram": Diagram, "document": DocumentSpec}
NESTED = {("flywheel", "rim"): RimSpec}
SINGLE_SPEEDS = ("omega0", "omega0_rpm", "mean", "mean_rpm")


# -- errors ---------------------------------------------------------------------------------------

def _model_at(loc: tuple, data: dict):
    if not loc:
        return Task2Case
    head = loc[0]
    if head in TOP and len(loc) == 1:
        return TOP[head]
    if tuple(loc) in NESTED:
        return NESTED[tuple(loc)]
    if head in ("driving", "resistance") and len(loc) == 1:
        kind = (data.get(head) or {}).get("kind") if isinstance(data.get(head), dict) else None
        return KINDS.get(kind)
    return None


def _describe(err: dict, data: dict) -> str:
    loc = list(err["loc"])
    if len(loc) >= 2 and loc[0] in ("driving", "resistance") and loc[1] in KINDS:
        del loc[1]
    err = {**err, "loc": tuple(loc)}
    if err["type"] in ("union_tag_invalid", "union_tag_not_found"):
        tag = err.get("ctx", {}).get("tag", "")
        near = difflib.get_close_matches(str(tag), list(KINDS), n=1)
        hint = f"; did you mean {near[0]!r}?" if near and tag else ""
        what = f"unknown kind {tag!r}" if tag else "missing kind"
        return led(f"{loc_str(clean_loc(loc))}.kind: ", Notice.of(
            "graph_kind", "{what}{hint} (allowed: {allowed})", tag=str(tag),
            near=near[0] if near and tag else "", allowed=", ".join(KINDS), what=what, hint=hint))

    def allowed(parent: tuple) -> list[str]:
        model = _model_at(clean_loc(parent), data)
        return list(model.model_fields) if model else []

    return describe(err, allowed)




def _pos(field: str, v: float | None, unit: str) -> None:
    if v is not None and not v > 0:
        raise FieldError(field, Notice.of(
            "must_be_positive", "must be positive (got {v:g} {unit})", v=v, unit=unit))


def _check(case: Task2Case) -> None:
    """Checks that pydantic's types do not express; each raises with its field path."""
    if not case.cycle_deg > 0:
        # library use only: no CLI input reaches this
        raise FieldError("cycle_deg", f"must be positive (got {case.cycle_deg:g}°)")
    if not (_whole(case.cycle_deg / 360.0) or _whole(360.0 / case.cycle_deg)):
        raise FieldError("cycle_deg", Notice.of(
            "t2_cycle_not_whole", "{cycle:g}° is neither whole revolutions nor a whole part of "
            "one (allowed: 360, 720, 1080 … 36000°, or 180, 120, 90 … a diagram that repeats "
            "within a revolution)", cycle=case.cycle_deg))
    s = case.speed
    given = [k for k in ("omega0", "omega0_rpm", "mean", "mean_rpm", "max", "min", "max_rpm",
                         "min_rpm") if getattr(s, k) is not None]
    pairs = {("max", "min"), ("max_rpm", "min_rpm")}
    if not (len(given) == 1 and given[0] in SINGLE_SPEEDS or tuple(given) in pairs):
        if len(given) == 1 and given[0] not in SINGLE_SPEEDS:
            other = {"max": "min", "min": "max", "max_rpm": "min_rpm",
                     "min_rpm": "max_rpm"}[given[0]]
            raise FieldError(f"speed.{other}", Notice.of(
                "t2_limits_pair", "missing: speed limits come in pairs ({first} with {other})",
                first=given[0], other=other))
        raise FieldError("speed", Notice.of(
            "task2_speed_one_of", "give exactly one of omega0, omega0_rpm, mean, mean_rpm, or the "
            "limits max and min (or max_rpm and min_rpm){got_note}", given=", ".join(given),
            got_note=f" (got {', '.join(given)})" if given else ''))
    for k in given:
        _pos(f"speed.{k}", getattr(s, k), "rad/s" if "rpm" not in k else "rpm")
    if len(given) == 2 and not getattr(s, given[1]) < getattr(s, given[0]):
        unit = "rpm" if "rpm" in given[0] else "rad/s"
        v, vo = getattr(s, given[1]), getattr(s, given[0])
        raise FieldError(f"speed.{given[1]}", Notice.of(
            "t2_limit_below", "must be below {limit} (got {v:g} {unit} against {vo:g} {unit})",
            limit=given[0], v=v, vo=vo, unit=unit))
    f = case.flywheel
    for name, unit in (("J", "kg·m²"), ("mass", "kg"), ("radius_of_gyration", "m"),
                       ("rim_radius", "m"), ("fluctuation_percent", "%")):
        _pos(f"flywheel.{name}", getattr(f, name), unit)
    if f.delta is not None and not 0 < f.delta < 2:
        raise FieldError("flywheel.delta", Notice.of(
            "delta_0_2", "must lie between 0 and 2 (got {delta:g})", delta=f.delta))
    if f.J is not None and f.mass is not None:
        raise FieldError("flywheel", Notice.of(
            "task2_J_or_mass", "give J or mass with radius_of_gyration, not both"))
    if f.mass is not None and f.radius_of_gyration is None:
        raise FieldError("flywheel", Notice.of(
            "mass_radius_together", "mass and radius_of_gyration go together (J = m·k²)"))
    if f.delta is not None and f.fluctuation_percent is not None:
        raise FieldError("flywheel", Notice.of(
            "task2_delta_or_percent", "give delta or fluctuation_percent, not both"))
    limits = len(given) == 2
    if limits and (f.delta is not None or f.fluctuation_percent is not None):
        which = "delta" if f.delta is not None else "fluctuation_percent"
        raise FieldError(f"flywheel.{which}", Notice.of(
            "t2_limits_give_delta", "the speed limits already give δ = (max − min)/ω_m: give one "
            "or the other"))
    if f.J is None and f.mass is None and f.delta is None and f.fluctuation_percent is None \
            and not limits:
        raise FieldError("flywheel", Notice.of(
            "t2_flywheel_missing", "give J, or mass and radius_of_gyration, or the asked delta (or "
            "fluctuation_percent, or the speed limits)"))
    if f.rim is not None and f.rim.speed is not None:
        try:
            f.rim.check_speed(f.rho, f.sigma, f.material if f.density is None and
                              f.allowable_stress is None else "the given material")
        except FieldError as exc:
            raise FieldError(("flywheel", *exc.loc), said(exc)) from None
    if case.power is not None:
        _pos("power", case.power, "W")
    mean_known = given[0] in ("mean", "mean_rpm") or limits
    for i, x in enumerate(case.at_deg):
        if not 0 <= x <= case.cycle_deg:
            raise FieldError(f"at_deg[{i}]", Notice.of(
                "t2_at_in_cycle", "must lie within the cycle 0…{cycle:g}° (got {x:g})",
                cycle=case.cycle_deg, x=x))
    if case.diagram is not None:
        if case.driving is not None or case.resistance is not None:
            raise FieldError("diagram", Notice.of(
                "diagram_or_graphs", "give either [diagram] or [driving] and [resistance], not both"
            ))
        if case.at_deg:
            raise FieldError("at_deg", Notice.of(
                "t2_diagram_at", "a diagram given by areas has no moments between its crossings: "
                "ε, ω and t at an angle need [driving] and [resistance] graphs"))
        _check_diagram(case.diagram, case.cycle_deg)
        d = case.diagram
        uses_power = d.energy_fluctuation_coefficient is not None and d.work_per_cycle is None
        if uses_power and case.power is None:
            raise FieldError("diagram.energy_fluctuation_coefficient", Notice.of(
                "t2_efc_needs_work", "needs the work done per cycle: give diagram.work_per_cycle "
                "[J], or the mean power (top-level power [W]) with a mean speed"))
        if uses_power and not mean_known:
            raise FieldError("power", Notice.of(
                "t2_work_needs_mean", "the work per cycle P·Φ/ω_m needs the mean speed: give "
                "speed.mean, mean_rpm or the limits max/min"))
        if case.power is not None and not uses_power:
            raise FieldError("power", Notice.of(
                "t2_power_unused_diagram", "is used by a graph value \"power\" or by [diagram] "
                "energy_fluctuation_coefficient without work_per_cycle; nothing here uses it"))
        return
    for name in ("driving", "resistance"):
        if getattr(case, name) is None:
            raise FieldError(name, Notice.of(
                "t2_graphs_missing", "missing: give [driving] and [resistance] graphs, or a "
                "[diagram]"))
    unknowns = [(n, g.unknown_field()) for n, g in (("driving", case.driving),
                                                    ("resistance", case.resistance))
                if g.unknown_field()]
    if len(unknowns) > 1:
        raise FieldError(f"{unknowns[1][0]}.{unknowns[1][1]}", Notice.of(
            "balance_once", '"balance" may stand for one value only (the other is {other})',
            other=f"{unknowns[0][0]}.{unknowns[0][1]}"))
    powered = [(n, g.power_field()) for n, g in (("driving", case.driving),
                                                 ("resistance", case.resistance))
               if g.power_field()]
    if len(powered) > 1:
        raise FieldError(f"{powered[1][0]}.{powered[1][1]}", Notice.of(
            "t2_power_once", '"power" may stand for one value only (the other is {other})',
            other=f"{powered[0][0]}.{powered[0][1]}"))
    if powered and case.power is None:
        raise FieldError(f"{powered[0][0]}.{powered[0][1]}", Notice.of(
            "t2_power_needs_P", "\"power\" needs the mean power: give the top-level power [W]"))
    if powered and not mean_known:
        raise FieldError(f"{powered[0][0]}.{powered[0][1]}", Notice.of(
            "t2_power_needs_mean", "\"power\" (T_mean = P/ω_ср) needs the mean speed: give "
            "speed.mean, mean_rpm or the limits max/min"))
    if case.power is not None and not powered:
        raise FieldError("power", Notice.of(
            "t2_power_unused", "is used by a graph value \"power\" (T_mean = P/ω_ср); no graph "
            "value is \"power\""))
    for name in ("driving", "resistance"):
        _check_graph(name, getattr(case, name), case.cycle_deg)
    _check_work(case.driving, case.resistance)


def _pieces_and_terms(g) -> tuple[int, int]:
    """(pieces, terms of its series) of a graph: the points graph's pieces, a preset's at most
    four, a series' one piece."""
    if isinstance(g, PointsGraph):
        return max(len(g.points) - 1, 1), 0
    if isinstance(g, HarmonicGraph):
        return 1, max(len(g.a), len(g.b))
    return (1 if isinstance(g, ConstantGraph) else 4), 0


def _check_work(driving, resistance) -> None:
    """M_D − M_C has the pieces of both graphs, each carrying the terms of both series: its work
    (pieces × (1 + terms)) bounded by MAX_WORK, so a long series against a long points graph
    is refused in one line instead of running for minutes."""
    (pd, td), (pc, tc) = _pieces_and_terms(driving), _pieces_and_terms(resistance)
    work = (pd + pc) * (1 + td + tc)
    if work > MAX_WORK:
        raise FieldError("resistance", Notice.of(
            "t2_graphs_too_big", "with the driving graph: {pieces} pieces × {terms} harmonic "
            "terms is too much work (allowed: pieces × (1 + terms) ≤ {most:g}; give fewer points "
            "or fewer terms)", pieces=pd + pc, terms=td + tc, most=MAX_WORK))


def _check_graph(name: str, g, cycle: float) -> None:
    if isinstance(g, PointsGraph):
        if len(g.points) < 2:
            raise FieldError(f"{name}.points", Notice.of(
                "t2_points_two", "needs at least two [angle, moment] points"))
        for i in range(1, len(g.points)):
            if g.points[i][0] < g.points[i - 1][0]:
                raise FieldError(f"{name}.points[{i}]", Notice.of(
                    "points_go_back", "angle {at:g}° comes after {before:g}°: angles must not "
                    "decrease", at=g.points[i][0], before=g.points[i - 1][0]))
            if i >= 2 and g.points[i][0] == g.points[i - 1][0] == g.points[i - 2][0]:
                raise FieldError(f"{name}.points[{i}]", Notice.of(
                    "points_third_value", "a third value at {at:g}°: a jump has two (the value "
                    "before and the value after it)", at=g.points[i][0]))
        if g.points[0][0] != 0 or g.points[-1][0] != cycle:
            raise FieldError(f"{name}.points", Notice.of(
                "points_span", "must span the cycle 0…{cycle:g}° (spans {first:g}…{last:g}°)",
                cycle=cycle, first=g.points[0][0], last=g.points[-1][0]))
    elif isinstance(g, (TriangleGraph, RectangleGraph, TrapezoidGraph)):
        if not 0 <= g.from_deg < g.to_deg <= cycle:
            raise FieldError(f"{name}.from_deg", Notice.of(
                "from_to_deg", "need 0 ≤ from_deg < to_deg ≤ {cycle:g} (got {start:g}, {end:g})",
                cycle=cycle, start=g.from_deg, end=g.to_deg))
        if isinstance(g, TriangleGraph) and g.apex_deg is not None \
                and not g.from_deg <= g.apex_deg <= g.to_deg:
            raise FieldError(f"{name}.apex_deg", Notice.of(
                "t2_apex_within", "must lie within {start:g}…{end:g}° (got {apex:g})",
                start=g.from_deg, end=g.to_deg, apex=g.apex_deg))
        if isinstance(g, TrapezoidGraph) and not (
                g.from_deg <= g.top_from_deg <= g.top_to_deg <= g.to_deg):
            raise FieldError(f"{name}.top_from_deg", Notice.of(
                "trapezoid_top", "need from_deg ≤ top_from_deg ≤ top_to_deg ≤ to_deg"))
    elif isinstance(g, HarmonicGraph):
        n = max(len(g.a), len(g.b))
        if g.orders is not None:
            if len(g.orders) != n:
                raise FieldError(f"{name}.orders", Notice.of(
                    "orders_for_terms", "{orders} orders for {terms} terms", orders=len(g.orders),
                    terms=n))
            if any(not k > 0 for k in g.orders):
                # library use only: no CLI input reaches this
                raise FieldError(f"{name}.orders", "orders must be positive")
        # sin kφ repeats over the cycle Φ only when k·Φ is a whole number of turns
        revs = cycle / 360.0
        for i, k in enumerate(g.orders if g.orders is not None else range(1, n + 1)):
            if not _whole(k * revs):
                where = f"{name}.orders[{i}]" if g.orders is not None else f"{name}.orders"
                step = 1.0 / revs
                raise FieldError(where, Notice.of(
                    "t2_order_not_periodic", "order {k:g} does not repeat over the cycle of "
                    "{cycle:g}° (allowed: whole multiples of 360/cycle_deg = {step:g})", k=k,
                    cycle=cycle, step=step))


def _whole(x: float) -> bool:
    """x is a whole number to round-off (1e-9 relative): 720/360, 3·(1080/360)."""
    return abs(x - round(x)) <= 1e-9 * max(1.0, abs(x)) and round(x) >= 1


def _check_diagram(d: Diagram, cycle: float) -> None:
    forms = [k for k in ("areas", "energies", "delta_E", "energy_fluctuation_coefficient")
             if getattr(d, k) is not None]
    if len(forms) != 1:
        raise FieldError("diagram", Notice.of(
            "t2_diagram_form", "give one of areas (with moment_scale and angle_scale_deg), "
            "energies, delta_E, or energy_fluctuation_coefficient{got_note}",
            given=", ".join(forms), got_note=f" (got {', '.join(forms)})" if forms else ''))
    if d.work_per_cycle is not None and forms[0] != "energy_fluctuation_coefficient":
        raise FieldError("diagram.work_per_cycle", Notice.of(
            "t2_work_only_efc", "only with energy_fluctuation_coefficient"))
    if forms[0] in ("delta_E", "energy_fluctuation_coefficient"):
        for k in ("delta_E", "energy_fluctuation_coefficient", "work_per_cycle"):
            _pos(f"diagram.{k}", getattr(d, k), "J" if k != "energy_fluctuation_coefficient"
                 else "")
        for k in ("crossings_deg", "moment_scale", "angle_scale_deg"):
            if getattr(d, k) is not None:
                raise FieldError(f"diagram.{k}", Notice.of(
                    "t2_only_areas", "only with areas or energies (not with {form})", form=forms[0]
                ))
        return
    vals, key = (d.areas, "areas") if d.areas is not None else (d.energies, "energies")
    if d.areas is not None:
        for k in ("moment_scale", "angle_scale_deg"):
            if getattr(d, k) is None:
                raise FieldError(f"diagram.{k}", Notice.of(
                    "t2_areas_scales", "missing: areas need the drawing's scales"))
            _pos(f"diagram.{k}", getattr(d, k), "")
    if len(vals) < 2:
        raise FieldError(f"diagram.{key}", Notice.of("t2_two_areas", "needs at least two areas"))
    total, size = math.fsum(vals), math.fsum(abs(v) for v in vals)
    if abs(total) > BALANCE_RTOL * size:
        raise FieldError(f"diagram.{key}", Notice.of(
            "areas_do_not_close", "sum to {total:.6g}, not 0: over a cycle the areas above and "
            "below the mean line must be equal", total=total))
    if d.crossings_deg is not None:
        c = d.crossings_deg
        if len(c) != len(vals) + 1:
            raise FieldError("diagram.crossings_deg", Notice.of(
                "t2_crossings_count", "needs {n} angles for {areas} areas (got {count})",
                n=len(vals) + 1, areas=len(vals), count=len(c)))
        for i in range(1, len(c)):
            if not c[i] > c[i - 1]:
                raise FieldError(f"diagram.crossings_deg[{i}]", Notice.of(
                    "t2_angles_increase", "angles must increase"))
        if c[0] < 0 or c[-1] > cycle:
            raise FieldError("diagram.crossings_deg", Notice.of(
                "t2_crossings_within", "must lie within 0…{cycle:g}°", cycle=cycle))


# -- loading and solving --------------------------------------------------------------------------

def parse_task2_case(data: dict, source: str = "<case>") -> Task2Case:
    """Validate a parsed TOML document or raise one CaseFileError line (a case of another
    kind is named as such, with its command)."""
    from flywheel.cases import wrong_kind

    other = wrong_kind(data, "task2", source)
    if other is not None:
        raise CaseFileError(other)
    return validate(data, Task2Case, source, lambda errs: _describe(pick(errs), data), _check)


def load_task2_case(path) -> Task2Case:
    """Read a TOML task-2 case file and validate it."""
    return load(path, parse_task2_case)


def _maker(g, cycle: float, fixed: dict | None = None):
    """x ↦ Moment, with x standing for the graph's "balance" or "power" value (if any);
    ``fixed`` maps a marker already found ("power") to its value."""
    r = math.radians
    fixed = fixed or {}

    def num(v, x):
        if isinstance(v, str):
            return fixed.get(v, x)
        return float(v)

    if isinstance(g, ConstantGraph):
        return lambda x: graphs.constant(num(g.value, x), cycle)
    if isinstance(g, PointsGraph):
        def make(x):
            s = num(g.scale, x)
            return graphs.piecewise_linear([(r(p), s * m) for p, m in g.points], cycle,
                                       nominal=s * max(m for _, m in g.points))
        return make
    if isinstance(g, TriangleGraph):
        return lambda x: graphs.triangle(num(g.peak, x), r(g.from_deg), r(g.to_deg), cycle,
                                     None if g.apex_deg is None else r(g.apex_deg), g.base)
    if isinstance(g, RectangleGraph):
        return lambda x: graphs.rectangle(num(g.peak, x), r(g.from_deg), r(g.to_deg), cycle, g.base)
    if isinstance(g, TrapezoidGraph):
        return lambda x: graphs.trapezoid(num(g.peak, x), r(g.from_deg), r(g.top_from_deg),
                                      r(g.top_to_deg), r(g.to_deg), cycle, g.base)
    return lambda x: graphs.harmonic(num(g.a0, x), g.a, g.b, g.orders, cycle)


def _speeds(case: Task2Case) -> dict:
    s = case.speed
    rpm = math.pi / 30
    if s.omega0 is not None:
        return {"omega0": s.omega0}
    if s.omega0_rpm is not None:
        return {"omega0": s.omega0_rpm * rpm}
    if s.mean is not None:
        return {"omega_mean": s.mean}
    if s.mean_rpm is not None:
        return {"omega_mean": s.mean_rpm * rpm}
    hi, lo = (s.max, s.min) if s.max is not None else (s.max_rpm * rpm, s.min_rpm * rpm)
    return {"omega_mean": 0.5 * (hi + lo)}


def speed_limits_delta(case: Task2Case) -> float | None:
    """δ = (ω_max − ω_min)/ω_ср of the speed limits (rev/min cancel), None without limits
    (Khurmi & Gupta §16.6: C_s = (N1 − N2)/N, N = (N1 + N2)/2)."""
    s = case.speed
    if s.max is not None:
        hi, lo = s.max, s.min
    elif s.max_rpm is not None:
        hi, lo = s.max_rpm, s.min_rpm
    else:
        return None
    return (hi - lo) / (0.5 * (hi + lo))


def solve_case(case: Task2Case, source: str = "<case>", at_deg=()) -> Task2Result:
    """Solve a validated case; a physical impossibility becomes one CaseFileError line.
    ``at_deg``: angles [deg] asked besides the case's own ``at_deg``."""
    f = case.flywheel
    J = f.J if f.J is not None else (f.mass * f.radius_of_gyration ** 2 if f.mass else None)
    delta = f.delta if f.delta is not None else (
        2 * f.fluctuation_percent / 100 if f.fluctuation_percent is not None
        else speed_limits_delta(case))
    k_gyr = f.radius_of_gyration if f.mass is None else None
    cycle = math.radians(case.cycle_deg)
    speeds = _speeds(case)
    rim = None if f.rim is None else dict(
        density=f.rho, allowable_stress=f.sigma, share=f.rim.share, speed=f.rim.speed,
        width_to_thickness=f.rim.width_to_thickness, width=f.rim.width,
        diameter=f.rim.diameter, thickness_to_radius=f.rim.thickness_to_radius)
    kw = dict(delta=delta, rim_radius=f.rim_radius, radius_of_gyration=k_gyr, rim=rim, **speeds)
    at = [math.radians(x) for x in (*case.at_deg, *at_deg)]
    field = "flywheel"
    try:
        if case.diagram is not None:
            d = case.diagram
            work = None
            if d.areas is not None:
                k = d.moment_scale * math.radians(d.angle_scale_deg)   # J per mm²
                energies = [a * k for a in d.areas]
            elif d.energies is not None:
                energies = list(d.energies)
            elif d.delta_E is not None:
                energies = [d.delta_E, -d.delta_E]
            else:   # ΔE = C_E·W, W = work per cycle or P·Φ/ω_ср (Khurmi & Gupta §16.4)
                work = (d.work_per_cycle if d.work_per_cycle is not None
                        else case.power * cycle / speeds["omega_mean"])
                energies = [d.energy_fluctuation_coefficient * work,
                            -d.energy_fluctuation_coefficient * work]
            crossings_at = (None if d.crossings_deg is None
                            else [math.radians(c) for c in d.crossings_deg])
            return solve_areas(energies, J, cycle=cycle, crossings_at=crossings_at, at=at,
                               work_per_cycle=work, **kw)
        powered = ("driving" if case.driving.power_field() else
                   "resistance" if case.resistance.power_field() else None)
        fixed = {}
        if powered:
            field = f"{powered}.{getattr(case, powered).power_field()}"
            fixed[POWER] = power_value(_maker(getattr(case, powered), cycle), case.power,
                                       speeds["omega_mean"], powered)
        make_D, make_C = _maker(case.driving, cycle, fixed), _maker(case.resistance, cycle, fixed)
        unknown = ("driving" if case.driving.unknown_field() else
                   "resistance" if case.resistance.unknown_field() else None)
        if unknown:
            field = f"{unknown}.{getattr(case, unknown).unknown_field()}"
            x = balance(make_D, make_C, unknown)
            field = "flywheel"
        else:
            x = 1.0
        field = "flywheel"
        return solve(make_D(x), make_C(x), J, unknown=unknown, at=at, power_found=powered, **kw)
    except InputError as exc:
        if getattr(said(exc), "code", "") in ("t2_mean_needs_steady", "t2_delta_needs_mean",
                                               "machine_stops"):
            field = "speed"
        raise CaseFileError(led(f"{source}: {field}: ", said(exc))) from None
