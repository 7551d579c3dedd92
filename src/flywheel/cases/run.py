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
from pathlib import Path
from typing import Annotated, Literal, Union

from pydantic import BaseModel, Field, Strict, model_validator

from flywheel.errors import CaseFileError, Notice, led
from flywheel.io.schema import TitleText, title_field, FieldError, StrictModel, at_most, text_field, within, clean_loc, describe, load, loc_str, pick, validate
from flywheel.cases.document import DocumentSpec
from flywheel.cases.run_start import StartSpec
from flywheel.cases.rim import MATERIALS, RimSpec  # shared with the task2 format
from flywheel.cases.tabulated import TabulatedSpec
# the parts of the format in their own modules, re-exported: flywheel.cases.run keeps every name
from flywheel.cases.run_fields import (  # noqa: F401
    CYCLE_REVS_MAX, XY, Angle, Coord, Force, Inertia, Length, Mass, Moment, Name, NonNeg, Pos,
    _within)
from flywheel.cases.run_linkage import (  # noqa: F401
    Branch, CrankSpec, DyadSpec, GuideSpec, LinkSpec, PinSpec, PointSpec, RPRSpec, RRPSpec, RRRSpec)
from flywheel.cases.run_cylinders import (  # noqa: F401
    STROKE_ORDER, CylinderSpec, DiagramSpec, IndicatorSpec, StrokesSpec, resolve_traces)
from flywheel.cases.run_loads import CoupleSpec, ForceSpec, SpringSpec  # noqa: F401
from flywheel.cases.run_checks import (  # noqa: F401
    ATM, DELTA_USUAL, _check_references, plausibility_warnings)


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
    analysis: Literal["dynamics", "kinematics"] | None = Field(
        None, description="'kinematics': positions, analogues, velocities and accelerations at "
                          "the constant crank speed only (no masses, loads or flywheel needed); "
                          "'dynamics': the whole analysis; omitted: the kinematics alone for a "
                          "linkage with no masses, no first group, no loads and no given "
                          "flywheel, else the dynamics")

    @model_validator(mode="after")
    def _check(self):
        if (self.speed_rps is None) == (self.speed_rpm is None):
            raise ValueError(Notice.of(
                "speed_rps_or_rpm", "give exactly one of speed_rps, speed_rpm"))
        revs = self.cycle_deg / 360.0
        if not 1 <= revs <= CYCLE_REVS_MAX:      # 3.6e9° is whole, but out of range
            raise FieldError(("cycle_deg",), Notice.of(
                "cycle_out_of_range", "{cycle:g}° is out of range (allowed: 360, 720, 1080 … "
                "{top}°)", cycle=self.cycle_deg, top=360 * CYCLE_REVS_MAX))
        if revs != round(revs):
            raise FieldError(("cycle_deg",), Notice.of(
                "cycle_not_whole", "{cycle:g}° is not a whole number of revolutions (allowed: "
                "360, 720, 1080 … {top}°)", cycle=self.cycle_deg, top=360 * CYCLE_REVS_MAX))
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

    at_deg: Annotated[list[float], at_most(72, "angles"), within(-1e6, 1e6, "deg")] = Field(default_factory=lambda: [120.0],
                                description="report angles [deg]")
    snapshots: Annotated[list[Annotated[tuple[float, float], Strict(False), within(-1e6, 1e6, "")]], at_most(72, "snapshots")] = Field(
        default_factory=list, description="[[φ deg, n rev/min], …]: the crank's ε at each stated angle and speed (`flywheel run --snapshot` adds)")


class ForceAnalysisSpec(StrictModel):
    """The force analysis (kinetostatics) of `flywheel run` (docs/forces.md)."""

    motion: Literal["true", "steady"] = Field(
        "true", description="the crank's motion for the inertia loads: 'true' = ω(φ), ε(φ) of "
                            "the dynamics with the flywheel; 'steady' = ω_m constant, ε = 0 "
                            "(`flywheel run --motion` overrides)")


class Case(StrictModel):
    """A whole case file."""

    title: TitleText = title_field(description="what the case is: a string, or { ru = …, en = … }")
    source: TitleText = title_field(description="where its data come from (book, worksheet, variant)")
    machine: Machine = Field(description="speed, δ, the constant moment of the cycle balance, gravity, "
                                         "the first group")
    design: Design = Field(default_factory=Design,
                           description="lengths derived from the mean piston speed (the compressor worksheet)")
    crank: CrankSpec | None = Field(None, description="the driving link of a linkage")
    tabulated: TabulatedSpec | None = Field(
        None, description="kinematics as a table instead of a linkage (docs/tabulated.md)")
    ground: dict[str, XY] = Field(default_factory=dict, description="fixed points [m]")
    dyads: list[DyadSpec] = Field(default_factory=list,
                                  description="Assur groups RRP, RRR, RPR, placed in the order given")
    points: dict[str, PointSpec] = Field(default_factory=dict,
                                         description="points fixed on links (centroids, coupler points)")
    links: dict[str, LinkSpec] = Field(default_factory=dict,
                                       description="masses and moments of inertia of the links")
    cylinders: list[CylinderSpec] = Field(default_factory=list,
                                          description="gas forces from indicator diagrams")
    forces: list[ForceSpec] = Field(default_factory=list,
                                    description="technological forces and forces at points")
    couples: list[CoupleSpec] = Field(default_factory=list, description="couples on links")
    springs: list[SpringSpec] = Field(default_factory=list, description="linear and torsional springs (docs/case-format.md, [[springs]])")
    flywheel: FlywheelSpec = Field(default_factory=FlywheelSpec,
                                   description="material and proportions of the flywheel, or a given one")
    motor: MotorSpec | None = Field(None, description="the motor's characteristic (flywheel run "
                                                      "--transients, [start])")
    output: OutputSpec = Field(default_factory=OutputSpec, description="report angles and snapshots")
    force_analysis: ForceAnalysisSpec = Field(default_factory=ForceAnalysisSpec,
                                              description="the crank's motion in the force analysis")
    document: DocumentSpec = Field(default_factory=DocumentSpec, description="names for the title page and the title block (docs/case-format.md, [document])")
    start: StartSpec | None = Field(None, description="a motion from rest under a constant moment or the motor (docs/case-format.md, [start])")

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

    @property
    def kinematics_only(self) -> bool:
        """The case asks for the kinematics alone at the constant speed ω_m: ``machine.analysis
        = "kinematics"``, or (analysis omitted) a linkage with nothing for the dynamics (no link
        with mass or J_S, no first group, no cylinders, forces or couples, no given flywheel)."""
        if self.tabulated is not None or self.machine.analysis == "dynamics":
            return False
        if self.machine.analysis == "kinematics":
            return True
        return (not any(lk.mass or lk.J_S for lk in self.links.values())
                and not any(v > 0 for v in self.machine.first_group.values())
                and self.flywheel.given_J is None
                and not (self.cylinders or self.forces or self.couples))

    def plausibility_warnings(self) -> list[str]:
        """Allowed but unusual values, one line each (see :func:`plausibility_warnings`)."""
        return plausibility_warnings(self)


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
                    check=resolve_traces,       # measured crank-angle traces: their tables
                    context={**cycle_context(data),  # a [tabulated] table covers the machine's cycle
                             "case_dir": str(Path(source).parent)})   # indicator_file is beside


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
