"""The TOML case format of ``flywheel duty-cycle`` (documented field by field in
docs/duty-cycle.md): a press, riveter or shear whose flywheel gives the energy of each operation.

A case gives ``[operation]`` (its work, and how long it takes), ``[cycle]`` (how often), an
optional ``[motor]`` and ``[flywheel]``: its speed limits (or one speed when the flywheel itself
is given) and its radius of gyration or rim. Units are SI; a non-SI
value says so in its key (``_rpm``, ``_deg``, ``percent``). Every number is checked where it
enters, in a physically meaningful range stated in the message, and every problem becomes one
:class:`~flywheel.errors.CaseFileError` line ``file: field.path: what is wrong (allowed …)``.
"""
from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import AfterValidator, Field

from flywheel.duty_cycle import work as wk
from flywheel.duty_cycle.solve import (DutyCycle, DutyCycleError, DutyCycleResult, Work,
                                       nonfinite, solve)
from flywheel.errors import CaseFileError, InputError, Notice, led, said
from flywheel.io.schema import TitleText, title_field, FieldError, StrictModel, describe, load, pick, text_field, validate
from flywheel.cases.document import DocumentSpec
from flywheel.cases.rim import MATERIALS, Density, Material, RimSpec, Stress
from flywheel.units import RAD_S_PER_RPM


def _within(lo: float, hi: float, unit: str, lo_open: bool = False, hi_open: bool = False,
            above: str = ""):
    """A validator refusing values outside the range with the range and unit in the message;
    ``above`` says what a value at or above ``hi`` would mean."""
    def check(v):
        ok = (lo < v if lo_open else lo <= v) and (v < hi if hi_open else v <= hi)
        if not ok:
            u = f" {unit}" if unit else ""
            left = f"{lo:g} <" if lo_open else f"{lo:g} ≤"
            right = f"< {hi:g}" if hi_open else f"≤ {hi:g}"
            why = f": {above}" if above and v >= hi else ""
            raise ValueError(Notice.of(
                "duty_out_of_range", "{x:g}{unit_shown} is out of range{why} (allowed: {left} "
                "value {right}{unit_shown})", x=v, unit=unit, left=left, right=right,
                below_zero=bool(why), unit_shown=u, why=why))
        return v
    return AfterValidator(check)


def _num(lo, hi, unit, **kw):
    return Annotated[float, _within(lo, hi, unit, **kw)] | None


_BELOW_ZERO = "the speed would drop to zero or below"


Energy = _num(1e-6, 1e12, "J")
Length = _num(1e-6, 1e3, "m")
Share = _num(0.0, 1.0, "", lo_open=True)
Seconds = _num(1e-6, 1e7, "s")
Rpm = _num(0.06, 6e5, "rpm")
Omega = _num(1e-3, 1e5, "rad/s")
RimSpeed = _num(1e-3, 1e4, "m/s")

SPEEDS = {  # key → (level, unit family)
    "max_rpm": ("max", "rpm"), "min_rpm": ("min", "rpm"), "mean_rpm": ("mean", "rpm"),
    "max_omega": ("max", "omega"), "min_omega": ("min", "omega"), "mean_omega": ("mean", "omega"),
    "max_rim_speed": ("max", "rim"), "min_rim_speed": ("min", "rim"),
    "mean_rim_speed": ("mean", "rim"),
}
FLUCTUATIONS = ("percent", "total_percent", "delta", "drop_percent")
TIMINGS = ("duration", "cycle_share", "angle_deg", "stroke", "delta_E",
           "energy_fluctuation_coefficient")
CYCLES = ("per_hour", "per_minute", "period", "every_revolutions")


class Operation(StrictModel):
    """The work of one operation and how long it takes."""

    energy: Energy = Field(None, description="work of one operation E [J]")
    energy_per_area: _num(1e-3, 1e12, "J/m²") = Field(
        None, description="work per unit of sheared area [J/m²] (7 N·m/mm² = 7e6 J/m²)")
    sheared_area: _num(1e-12, 1e4, "m²") = Field(None, description="sheared area A [m²]")
    hole_diameter: Length = Field(None, description="punched hole's diameter d: A = π·d·t [m]")
    cut_length: Length = Field(None, description="length of a straight cut L: A = L·t [m]")
    thickness: Length = Field(None, description="plate thickness t, the travel of the force [m]")
    force: _num(1e-6, 1e12, "N") = Field(None, description="largest force F_max [N]")
    shear_strength: _num(1.0, 1e11, "Pa") = Field(
        None, description="ultimate shear strength τ_u: F_max = A·τ_u [Pa]")
    shape: Literal["constant", "falling", "triangle"] | None = Field(
        None, description="the force over the travel: constant (E = F·t), falling (linear "
                          "F_max → 0, E = F·t/2), triangle (0 → F_max → 0, E = F·t/2)")
    duration: Seconds = Field(None, description="time the operation takes t_op [s]")
    cycle_share: Share = Field(None, description="share of the cycle time it takes, (0, 1]")
    angle_deg: _num(1e-6, 1e6, "deg") = Field(
        None, description="angle the flywheel shaft turns during it [deg]")
    stroke: Length = Field(None, description="punch stroke s: share t/(2·s) of a cycle of one "
                                             "crank revolution [m]")
    delta_E: Energy = Field(None, description="energy the flywheel gives ΔE, given [J]")
    energy_fluctuation_coefficient: Share = Field(
        None, description="C_E = ΔE/E, given, (0, 1]")


class Cycle(StrictModel):
    """How often: one of the four."""

    per_hour: _num(1e-3, 1e8, "1/h") = Field(None, description="operations per hour")
    per_minute: _num(1e-5, 1e6, "1/min") = Field(None, description="operations per minute")
    period: Seconds = Field(None, description="cycle time T_c [s]")
    every_revolutions: _num(1e-3, 1e6, "rev") = Field(
        None, description="one operation every k revolutions of the flywheel shaft")


class Motor(StrictModel):
    """The motor: its power or its constant torque."""

    power: _num(1e-6, 1e10, "W") = Field(None, description="mean power while it works P [W]")
    torque: _num(1e-6, 1e10, "N·m") = Field(None, description="constant torque M_D [N·m]")
    efficiency: Annotated[float, _within(0.0, 1.0, "", lo_open=True)] = Field(
        1.0, description="the motor's (drive's) efficiency η: input P/η, (0, 1]")


class Flywheel(StrictModel):
    """The flywheel: its speeds (two values, or one and the fluctuation, to size it; one value
    when the flywheel itself is given) and its radius (for the mass and the rim speed)."""

    max_rpm: Rpm = Field(None, description="top speed, at the start of the operation [rpm]")
    min_rpm: Rpm = Field(None, description="lowest speed, at its end [rpm]")
    mean_rpm: Rpm = Field(None, description="mean speed (max + min)/2 [rpm]")
    max_omega: Omega = Field(None, description="ω_max [rad/s]")
    min_omega: Omega = Field(None, description="ω_min [rad/s]")
    mean_omega: Omega = Field(None, description="ω_ср = (ω_max + ω_min)/2 [rad/s]")
    max_rim_speed: RimSpeed = Field(None, description="top speed at the flywheel's radius [m/s]")
    min_rim_speed: RimSpeed = Field(None, description="lowest speed at the radius [m/s]")
    mean_rim_speed: RimSpeed = Field(None, description="mean speed at the radius [m/s]")
    percent: _num(1e-6, 100.0, "%", hi_open=True, above=_BELOW_ZERO) = Field(
        None, description="±x % of the mean speed: δ = 2x/100")
    total_percent: _num(1e-6, 200.0, "%", hi_open=True, above=_BELOW_ZERO) = Field(
        None, description="total fluctuation x % of the mean: δ = x/100")
    delta: _num(1e-8, 2.0, "", hi_open=True, above=_BELOW_ZERO) = Field(
        None, description="coefficient of fluctuation of speed δ = C_s")
    drop_percent: _num(1e-6, 100.0, "%", hi_open=True, above=_BELOW_ZERO) = Field(
        None, description="the speed falls x % below the top: ω_min = (1 − x/100)·ω_max")

    J: _num(1e-9, 1e9, "kg·m²") = Field(None, description="moment of inertia, given [kg·m²]")
    mass: _num(1e-6, 1e9, "kg") = Field(None, description="mass, given [kg]")
    radius_of_gyration: Length = Field(None, description="k: J = m·k² [m]")
    rim_radius: Length = Field(None, description="mean radius of a rim (k = R) [m]")
    rim_diameter: Length = Field(None, description="mean diameter of a rim (k = D/2) [m]")
    material: Material | None = Field(
        None, description="for [flywheel.rim]: sets density (7800 / 7200 kg/m³) and allowable "
                          "rim stress (20 / 7 MPa) unless given; default steel")
    density: Density | None = Field(None, description="for [flywheel.rim]: material density ρ "
                                                      "[kg/m³]")
    allowable_stress: Stress | None = Field(
        None, description="for [flywheel.rim]: allowable hoop stress of the rim σ_allow [Pa]")
    rim: RimSpec | None = Field(
        None, description="design the rim as `run` does (docs/case-format.md, [flywheel.rim]): "
                          "its mean diameter (given, or from the rim speed), share of J, section; "
                          "the result's flywheel_rim")

    @property
    def rho(self) -> float:
        """ρ [kg/m³] of the rim: given, or the material's."""
        return self.density if self.density is not None else MATERIALS[self.material or "steel"][0]

    @property
    def sigma(self) -> float:
        """σ_allow [Pa] of the rim: given, or the material's."""
        return (self.allowable_stress if self.allowable_stress is not None
                else MATERIALS[self.material or "steel"][1])

    @property
    def material_named(self) -> str:
        """The material as a message names it."""
        return (self.material or "steel") if self.density is None and \
            self.allowable_stress is None else "the given material"


class DutyCase(StrictModel):
    """A duty-cycle problem."""

    title: TitleText = title_field(description="what the case is")
    source: TitleText = title_field(description="where it comes from (book, problem)")
    notes: str = text_field(description="anything else")
    operation: Operation
    cycle: Cycle | None = None
    motor: Motor | None = None
    flywheel: Flywheel
    document: DocumentSpec = Field(default_factory=DocumentSpec, description="names for the title page and the title block (docs/case-format.md, [document])")


TABLES = {"operation": Operation, "cycle": Cycle, "motor": Motor, "flywheel": Flywheel,
          "document": DocumentSpec}
NESTED = {("flywheel", "rim"): RimSpec}


def _given(model, keys) -> list[str]:
    return [k for k in keys if model is not None and getattr(model, k) is not None]


def _one_of(table: str, model, keys, required: bool = True) -> str | None:
    got = _given(model, keys)
    if len(got) > 1 or (required and not got):
        raise FieldError(table, Notice.of(
            "one_of_keys", "give exactly one of {keys}{got_note}", keys=", ".join(keys),
            given=", ".join(got), got_note=f" (got {', '.join(got)})" if got else ''))
    return got[0] if got else None


def _goes_with(loc: str, a: str, b: str) -> FieldError:
    """A key given without the keys it belongs to ("goes with a or b")."""
    return FieldError(loc, Notice.of("dc_goes_with", "goes with {a} or {b}", a=a, b=b))


def _check(c: DutyCase) -> None:
    """Checks that span fields; each raises with its field path."""
    op, fw = c.operation, c.flywheel
    sp = fw
    # the work of the operation
    routes = _given(op, ("energy", "energy_per_area", "force", "shear_strength"))
    if len(routes) > 1:
        raise FieldError("operation", Notice.of(
            "duty_work_one_way", "give the work one way: energy, or energy_per_area with the "
            "sheared area, or force (or shear_strength) with thickness and shape (got {given})",
            given=", ".join(routes)))
    route = routes[0] if routes else None
    if route is None and op.delta_E is None:
        raise FieldError("operation", Notice.of(
            "duty_work_missing", "missing: give the work of one operation (energy, energy_per_area "
            "with the sheared area, or force with thickness and shape), or delta_E"))
    area_keys = ("sheared_area", "hole_diameter", "cut_length")
    if route in ("energy_per_area", "shear_strength"):
        a = _one_of("operation", op, area_keys)
        if a != "sheared_area" and op.thickness is None:
            area = "π·d·t" if a == "hole_diameter" else "L·t"
            raise FieldError("operation.thickness", Notice.of(
                "dc_area_thickness", "missing: {key} needs the plate's thickness (A = {area})",
                key=a, area=area))
    else:
        for k in area_keys:
            if getattr(op, k) is not None:
                raise _goes_with(f"operation.{k}", "energy_per_area", "shear_strength")
    if route in ("force", "shear_strength"):
        if op.thickness is None:
            raise FieldError("operation.thickness", Notice.of(
                "duty_thickness_missing", "missing: the force's travel (the plate's thickness) "
                "sets the work"))
        if op.shape is None:
            raise FieldError("operation.shape", Notice.of(
                "duty_shape_missing", "missing: state the force over the travel (allowed: "
                "constant, falling, triangle)"))
    elif op.shape is not None:
        raise _goes_with("operation.shape", "force", "shear_strength")
    # the timing
    timing = _one_of("operation", op, TIMINGS)
    if timing == "energy_fluctuation_coefficient" and route is None:
        # library use only: no CLI input reaches this
        raise FieldError("operation.energy_fluctuation_coefficient",
                         "C_E = ΔE/E needs the work of one operation E")
    if timing == "stroke":
        if op.thickness is None:
            raise FieldError("operation.thickness", Notice.of(
                "dc_stroke_thickness", "missing: the stroke gives the share t/(2·s) of the cycle, "
                "which needs the plate's thickness t"))
        if op.thickness > 2 * op.stroke:
            raise FieldError("operation.stroke", Notice.of(
                "dc_stroke_short", "{stroke:g} m is less than half the thickness {thickness:g} m: "
                "the share t/(2·s) would exceed 1 (allowed: stroke ≥ {half:g} m)", stroke=op.stroke,
                thickness=op.thickness, half=op.thickness / 2))
    if timing == "delta_E" and route is not None:
        E = _work(op).energy
        if op.delta_E > E:
            raise FieldError("operation.delta_E", Notice.of(
                "dc_delta_E_above_E", "{delta_E:g} J is more than the work of the operation E = "
                "{E:.6g} J (allowed: ΔE ≤ E)", delta_E=op.delta_E, E=E))
    # cycle and motor
    if c.cycle is not None:
        _one_of("cycle", c.cycle, CYCLES)
    motor = None if c.motor is None else _one_of("motor", c.motor, ("power", "torque"),
                                                  required=False)
    if route is None:
        for name in ("cycle", "motor"):
            if getattr(c, name) is not None:
                raise FieldError(name, Notice.of(
                    "dc_needs_work", "needs the work of one operation (operation.energy, "
                    "energy_per_area or force); with only delta_E the flywheel alone is sized"))
    elif c.cycle is None and motor is None:
        raise FieldError("cycle", Notice.of(
            "duty_cycle_missing", "missing: give [cycle] (how often), or the motor's power or "
            "torque to find the largest rate it can keep"))
    # the flywheel
    radius = _one_of("flywheel", fw, ("radius_of_gyration", "rim_radius", "rim_diameter"),
                     required=False)
    if fw.rim is None:
        for k in ("material", "density", "allowable_stress"):
            if getattr(fw, k) is not None:
                raise FieldError(f"flywheel.{k}", Notice.of(
                    "dc_material_needs_rim", "goes with [flywheel.rim]: the material sizes the "
                    "designed rim"))
    else:
        if radius in ("rim_radius", "rim_diameter"):
            raise FieldError(f"flywheel.{radius}", Notice.of(
                "dc_rim_diameter_once", "with [flywheel.rim] the rim's mean diameter is "
                "flywheel.rim.diameter (or follows from flywheel.rim.speed): give it there"))
        if radius is None and fw.rim.diameter is not None:
            radius = "rim.diameter"               # k = D_mean/2, as rim_diameter gives it
        if fw.rim.speed is not None:
            try:
                fw.rim.check_speed(fw.rho, fw.sigma, fw.material_named)
            except FieldError as exc:
                raise FieldError(("flywheel", *exc.loc), said(exc)) from None
    if fw.J is not None and fw.mass is not None:
        raise FieldError("flywheel", Notice.of("duty_J_or_mass", "give J or mass, not both"))
    # the speeds
    speeds = _given(sp, SPEEDS)
    flucts = _given(sp, FLUCTUATIONS)
    units = {SPEEDS[k][1] for k in speeds}
    if len(units) > 1:
        raise FieldError("flywheel", Notice.of(
            "dc_speed_units", "give the speeds in one unit (got {given})", given=", ".join(speeds)))
    linear = units == {"rim"}
    given = fw.J is not None or fw.mass is not None
    if given:
        if len(speeds) != 1 or flucts:
            got = ", ".join(speeds + flucts)
            raise FieldError("flywheel", Notice.of(
                "dc_given_one_speed", "with the flywheel given, give one speed (max, mean or min) "
                "and no fluctuation: the program finds the others{got_note}", given=got,
                got_note=f' (got {got})' if got else ''))
        if fw.mass is not None and radius is None and not linear:
            raise FieldError("flywheel.mass", Notice.of(
                "dc_mass_radius", "needs the radius (radius_of_gyration, rim_radius or "
                "rim_diameter): J = m·k²"))
        if fw.J is not None and linear and radius is None:
            raise FieldError("flywheel.J", Notice.of(
                "dc_J_radius", "with speeds at the radius (m/s), give the radius too"))
    else:
        if len(flucts) > 1:
            raise FieldError("flywheel", Notice.of(
                "one_of_keys", "give one of {keys} (got {given})", keys=", ".join(FLUCTUATIONS),
                given=", ".join(flucts)))
        if len(speeds) + len(flucts) != 2 or len(speeds) == 0:
            got = ", ".join(speeds + flucts)
            raise FieldError("flywheel", Notice.of(
                "dc_two_speeds", "give two speeds (two of max, min, mean) or one speed and the "
                "fluctuation (percent, total_percent, delta, drop_percent), or give the flywheel "
                "(J or mass) and one speed{got_note}", given=got,
                got_note=f' (got {got})' if got else ''))
        _check_speed_pair(sp, speeds, flucts)
    if linear and radius is None:
        for loc, bad in (("operation.angle_deg", op.angle_deg),
                         ("cycle.every_revolutions", c.cycle and c.cycle.every_revolutions),
                         ("motor.torque", c.motor and c.motor.torque)):
            if bad is not None:
                raise FieldError(loc, Notice.of(
                    "dc_shaft_speed", "needs the shaft's speed: with speeds at the radius (m/s) "
                    "give the flywheel's radius too, or the speeds in rpm"))
    if linear and radius is None and fw.rim is not None:
        raise FieldError("flywheel.rim", Notice.of(
            "dc_rim_shaft_speed", "needs the shaft's speed (D_mean = 2·v/ω): with speeds at the "
            "radius (m/s) give flywheel.rim.diameter or radius_of_gyration too, or the speeds in "
            "rpm"))


def _check_speed_pair(sp: Flywheel, speeds: list[str], flucts: list[str]) -> None:
    """A speed drop larger than the speed, min above max and the like: one line each."""
    level = {SPEEDS[k][0]: (k, getattr(sp, k)) for k in speeds}
    if "max" in level and "min" in level:
        (kx, vx), (kn, vn) = level["max"], level["min"]
        if not vn < vx:
            raise FieldError(f"flywheel.{kn}", Notice.of(
                "speed_not_below", "{v:g} is not below {other} = {vo:g} (allowed: {allowed})", v=vn,
                other=kx, vo=vx, allowed=f"0 < {kn} < {kx}"))
    if "mean" in level and "max" in level:
        (km, vm), (kx, vx) = level["mean"], level["max"]
        if not vm < vx < 2 * vm:
            raise FieldError(f"flywheel.{kx}", Notice.of(
                "dc_max_mean", "{v:g} with {mean_key} = {mean:g} gives min = 2·mean − max = "
                "{low:g} (allowed: {mean:g} < {key} < {top:g})", v=vx, mean_key=km, mean=vm,
                low=2 * vm - vx, key=kx, top=2 * vm))
    if "mean" in level and "min" in level:
        (km, vm), (kn, vn) = level["mean"], level["min"]
        if not vn < vm:
            raise FieldError(f"flywheel.{kn}", Notice.of(
                "speed_not_below", "{v:g} is not below {other} = {vo:g} (allowed: {allowed})", v=vn,
                other=km, vo=vm, allowed=f"0 < {kn} < {vm:g}"))
    if flucts == ["drop_percent"] and "max" not in level:
        raise FieldError("flywheel.drop_percent", Notice.of(
            "dc_drop_needs_max", "is a drop from the top speed: give it with max_rpm, max_omega or "
            "max_rim_speed"))


def _describe(err: dict) -> str:
    def allowed(parent: tuple) -> list[str]:
        if not parent:
            return list(DutyCase.model_fields)
        model = TABLES.get(parent[0]) if len(parent) == 1 else NESTED.get(tuple(parent))
        return list(model.model_fields) if model else []

    return describe(err, allowed)


def parse_duty_case(data: dict, source: str = "<case>") -> DutyCase:
    """Validate a parsed TOML document or raise one CaseFileError line."""
    from flywheel.cases import wrong_kind

    other = wrong_kind(data, "duty_cycle", source)
    if other:
        raise CaseFileError(other)
    return validate(data, DutyCase, source, lambda errs: _describe(pick(errs)), _check)


def load_duty_case(path) -> DutyCase:
    """Read a TOML duty-cycle case file and validate it."""
    return load(path, parse_duty_case)


def _work(op: Operation) -> Work | None:
    """The work of one operation from the fields (formulas in :mod:`flywheel.duty_cycle.work`)."""
    if op.energy is not None:
        return Work(op.energy)
    area = op.sheared_area
    if op.hole_diameter is not None:
        area = wk.sheared_area_hole(op.hole_diameter, op.thickness)
    elif op.cut_length is not None:
        area = wk.sheared_area_cut(op.cut_length, op.thickness)
    if op.energy_per_area is not None:
        return Work(op.energy_per_area * area, sheared_area=area,
                    energy_per_area=op.energy_per_area, thickness=op.thickness)
    if op.force is not None or op.shear_strength is not None:
        force = op.force if op.force is not None else area * op.shear_strength
        return Work(wk.work_of_stroke(force, op.thickness, op.shape), sheared_area=area,
                    force_max=force, thickness=op.thickness, shape=op.shape)
    return None


def to_duty_cycle(c: DutyCase) -> DutyCycle:
    """The domain's problem from a validated case (rpm → rad/s, percent → δ, …)."""
    op, fw, cy, mo = c.operation, c.flywheel, c.cycle, c.motor
    sp = fw
    work = _work(op)
    radius = (fw.radius_of_gyration if fw.radius_of_gyration is not None else
              fw.rim_radius if fw.rim_radius is not None else
              fw.rim_diameter / 2 if fw.rim_diameter is not None else
              fw.rim.diameter / 2 if fw.rim is not None and fw.rim.diameter is not None else None)
    speeds = {SPEEDS[k][0]: getattr(sp, k) for k in _given(sp, SPEEDS)}
    unit = {SPEEDS[k][1] for k in _given(sp, SPEEDS)}.pop()
    if unit == "rpm":
        speeds = {k: v * RAD_S_PER_RPM for k, v in speeds.items()}
    linear = unit == "rim"
    if linear and radius is not None:          # v = ω·k
        speeds = {k: v / radius for k, v in speeds.items()}
        linear = False
    delta = (sp.delta if sp.delta is not None else
             2 * sp.percent / 100 if sp.percent is not None else
             sp.total_percent / 100 if sp.total_percent is not None else None)
    if sp.drop_percent is not None:
        speeds["min"] = speeds["max"] * (1 - sp.drop_percent / 100)
    share = op.cycle_share
    if op.stroke is not None:
        share = wk.share_from_stroke(op.thickness, op.stroke)
    delta_E = op.delta_E
    if op.energy_fluctuation_coefficient is not None:
        delta_E = op.energy_fluctuation_coefficient * work.energy
    period = None
    if cy is not None:
        period = (cy.period if cy.period is not None else
                  3600.0 / cy.per_hour if cy.per_hour is not None else
                  60.0 / cy.per_minute if cy.per_minute is not None else None)
    timing = _given(op, TIMINGS)[0]
    return DutyCycle(
        work=work, duration=op.duration, cycle_share=share,
        angle=None if op.angle_deg is None else math.radians(op.angle_deg),
        delta_E=delta_E, period=period,
        revolutions=None if cy is None else cy.every_revolutions,
        motor_power=None if mo is None else mo.power,
        motor_torque=None if mo is None else mo.torque,
        efficiency=1.0 if mo is None else mo.efficiency,
        speed_max=speeds.get("max"), speed_min=speeds.get("min"), speed_mean=speeds.get("mean"),
        delta=delta, J=fw.J, mass=fw.mass, radius=radius, linear_speeds=linear,
        fields=(("operation", f"operation.{timing}"),
                ("motor", "motor.power" if mo is not None and mo.power is not None else
                 "motor.torque" if mo is not None and mo.torque is not None else "cycle"),
                ("flywheel", "flywheel." + ("J" if fw.J is not None else "mass")),
                ("speed", "flywheel")))


def solve_case(c: DutyCase, source: str = "<case>") -> DutyCycleResult:
    """Solve a validated case; a problem that cannot be solved becomes one CaseFileError line."""
    try:
        result = solve(to_duty_cycle(c))
    except DutyCycleError as exc:
        raise CaseFileError(led(f"{source}: {exc.field}: ", said(exc))) from None
    except (ArithmeticError, ValueError) as exc:      # inputs near the limits of doubles
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "dc_double_precision", "the values are too large or too small for double precision "
            "({detail})", detail=str(exc)))) from None
    if c.flywheel.rim is not None:
        result = _with_rim(c.flywheel, result, source)
    bad = nonfinite(result)
    if bad is not None:
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "dc_result_not_finite", "{result} is not a finite number: the values are too large or "
            "too small for double precision", result=bad)))
    return result


def _with_rim(fw: Flywheel, result: DutyCycleResult, source: str) -> DutyCycleResult:
    """The result with the rim of ``[flywheel.rim]`` designed for its J at its mean speed ω_ср,
    as `run` designs it (:meth:`flywheel.cases.rim.RimSpec.design`,
    :func:`flywheel.dynamics.sizing.design_rim`), and its hoop stress at ω_max
    (:meth:`flywheel.dynamics.sizing.RimDesign.at_top_speed`), and run's warning of a rim too
    thin for its diameter (:func:`flywheel.dynamics.sizing.thin_rim_notice`); a rim that cannot
    be made (no hole left, a diameter above the allowable stress) is one CaseFileError line."""
    from dataclasses import replace

    try:
        rim = fw.rim.design(result.J, result.omega_mean, fw.rho, fw.sigma)
    except InputError as exc:
        raise CaseFileError(led(f"{source}: ", Notice.of(
            "dc_rim_flywheel_J", "{detail} (the flywheel's J = {J:.6g} kg·m² at ω_m = "
            "{omega:.6g} rad/s)", detail=said(exc), J=result.J, omega=result.omega_mean))) from None
    from flywheel.dynamics.sizing import thin_rim_notice

    thin = thin_rim_notice(rim)                   # a hoop, not a rim: warned as `run` warns
    return replace(result, rim=rim.at_top_speed(result.omega_max),
                   warnings=result.warnings + (() if thin is None else (thin,)))
