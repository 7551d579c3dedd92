"""The TOML case format of ``flywheel aggregate`` (documented field by field in docs/aggregate.md).

Two shapes, one per file:

* the seed's two-mass aggregate (seed 003, Ефанов ch. 9): ``[motor]`` (with J_Д), ``[coupling]``
  and ``[machine]`` (J_пр.III, gear ratios i21, i31, the flywheel and its shaft, M_0, M̃);
* a chain of rotors: ``[[rotors]]`` and ``[[shafts]]`` (N rotors, N − 1 shafts, each shaft an
  elastic element given by c or by G, d, L — stepped shafts as segments — with an optional gear
  pair of ratio i = ω_out/ω_in), optionally driven: ``[motor]`` on the first rotor (without J)
  and ``[load]`` on the last.

SI units; speeds in rev/min where the key says ``_rpm``. Every problem becomes one
:class:`~flywheel.errors.CaseFileError` line: ``file: field.path: what is wrong (what is allowed)``.
"""
from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field

from flywheel.errors import CaseFileError, FlywheelError
from flywheel.io.schema import FieldError, StrictModel, load, validate, clean_loc, describe, pick

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
RPM = math.pi / 30.0  # rev/min → rad/s




class Motor(StrictModel):
    """The driving motor on shaft I."""

    J: Pos | None = Field(None, description="J_Д, the rotor's moment of inertia [kg·m²] (two-mass "
                                            "form only; in a chain the first rotor is the motor)")
    characteristic: Literal["linear", "constant"] = Field(
        "linear", description="linear: M_Д = M_п·(1 − ω/ω_x); constant: M_Д = M_0·i31")
    synchronous_rpm: Pos | None = Field(None, description="ω_x, synchronous (no-load) speed "
                                                          "[rev/min] (linear)")
    starting_torque: Pos | None = Field(None, description="M_п [N·m] (linear)")
    rated_torque: Pos | None = Field(None, description="M_н [N·m] (linear, with rated_slip, "
                                                       "instead of starting_torque)")
    rated_slip: float | None = Field(None, gt=0, lt=1, description="s_н, 0 < s < 1: M_п = M_н/s_н")
    speed_rpm: Pos | None = Field(None, description="steady speed of shaft I [rev/min] (constant)")


class Segment(StrictModel):
    """One elastic piece of a shaft: c, or d and L (with G here or on the shaft)."""

    c: Pos | None = Field(None, description="torsional stiffness [N·m/rad]")
    d: Pos | None = Field(None, description="diameter [m]")
    L: Pos | None = Field(None, description="length [m]")
    G: Pos | None = Field(None, description="shear modulus [Pa] (default: the shaft's)")
    side: Literal["in", "out"] = Field("in", description="before (in) or after (out) the gear pair")


class Shaft(StrictModel):
    """An elastic connection: one piece (c, or G with d and L) or segments in series, an optional
    gear pair, an optional viscous damping."""

    c: Pos | None = Field(None, description="torsional stiffness [N·m/rad]")
    G: Pos | None = Field(None, description="shear modulus [Pa]")
    d: Pos | None = Field(None, description="diameter [m]")
    L: Pos | None = Field(None, description="length [m]")
    segments: list[Segment] | None = Field(None, description="pieces in series (stepped shaft, "
                                                             "or both sides of a gear pair)")
    i: Pos = Field(1.0, description="gear ratio ω_out/ω_in of a gear pair in this connection")
    damping: NonNeg = Field(0.0, description="viscous damping of the twist [N·m·s/rad], at the "
                                             "input speed")


class Flywheel(StrictModel):
    J: Pos = Field(description="J_M, the flywheel's moment of inertia [kg·m²]")
    shaft: Literal["I", "II", "III"] = Field(description="the shaft it sits on")


class Machine(StrictModel):
    """The machine behind the coupling (seed 003)."""

    J_III: Pos | None = Field(None, description="J_пр.III, the mechanism reduced to shaft III "
                                                "[kg·m²]")
    J_III_0: NonNeg | None = Field(None, description="J_пр.0, its constant part [kg·m²] (with "
                                                     "J_III_positions)")
    J_III_positions: list[NonNeg] | None = Field(
        None, description="J̃_i, the variable part at the positions of a cycle [kg·m²]: "
                          "J_пр.III = J_пр.0 + ΣJ̃_i/n")
    i21: Pos | None = Field(None, description="ω_II/ω_I (needed with a flywheel on shaft II)")
    i31: Pos = Field(description="ω_III/ω_I")
    flywheel: Flywheel | None = None
    M0: NonNeg = Field(0.0, description="M_0, mean resistance moment on shaft III [N·m]")
    M_amplitude: NonNeg = Field(0.0, description="M̃, amplitude of its harmonic part [N·m]")
    order: Pos = Field(1.0, description="forcing frequency / ω_III (1: sin ω_III·t as in 9.20)")


class Rotor(StrictModel):
    name: str | None = None
    J: Pos = Field(description="moment of inertia [kg·m²]")


class Load(StrictModel):
    """Resistance on the last rotor of a chain, on its own shaft."""

    M0: NonNeg = Field(0.0, description="mean resistance moment [N·m]")
    M_amplitude: NonNeg = Field(0.0, description="amplitude of its harmonic part [N·m]")
    order: Pos = Field(1.0, description="forcing frequency / the last rotor's speed")


class AggregateCase(StrictModel):
    title: str = ""
    source: str = ""
    motor: Motor | None = None
    coupling: Shaft | None = None
    machine: Machine | None = None
    rotors: list[Rotor] | None = None
    shafts: list[Shaft] | None = None
    load: Load | None = None


FIELDS = {"(top level)": AggregateCase, "motor": Motor, "coupling": Shaft, "machine": Machine,
          "machine.flywheel": Flywheel, "rotors": Rotor, "shafts": Shaft, "load": Load,
          "shafts.segments": Segment, "coupling.segments": Segment}


# -- errors ---------------------------------------------------------------------------------------

def _describe(err: dict) -> str:
    def allowed(parent: tuple) -> list[str]:
        key = ".".join(str(p) for p in clean_loc(parent) if not isinstance(p, int)) or "(top level)"
        model = FIELDS.get(key)
        return list(model.model_fields) if model else []

    return describe(err, allowed, messages={"greater_than": "must be positive",
                                            "greater_than_equal": "must not be negative"})




# -- checks that span fields ----------------------------------------------------------------------

def _stiffness(s: Shaft, where: str) -> tuple[float, float]:
    """(stiffness reduced to the shaft's input speed, gear ratio)."""
    from flywheel.elastic.chain import series_stiffness, shaft_stiffness

    direct = [k for k in ("c", "d", "L") if getattr(s, k) is not None]
    if s.segments is not None and direct:
        raise FieldError(f"{where}.{direct[0]}", "give the stiffness either directly or as segments, "
                                           "not both")
    pieces = s.segments if s.segments is not None else [Segment(c=s.c, d=s.d, L=s.L)]
    if not pieces:
        raise FieldError(f"{where}.segments", "needs at least one segment")
    cs = []
    for k, p in enumerate(pieces):
        at = f"{where}.segments[{k}]" if s.segments is not None else where
        if p.c is not None:
            if p.d is not None or p.L is not None:
                raise FieldError(f"{at}.c", "give c, or d and L (with G), not both")
            c = p.c
        else:
            if p.d is None or p.L is None:
                missing = "d" if p.d is None else "L"
                raise FieldError(f"{at}.{missing}", "missing: give c, or d and L with G")
            G = p.G if p.G is not None else s.G
            if G is None:
                raise FieldError(f"{at}.G", "missing: the shear modulus is needed with d and L "
                                      "(e.g. 8.0e10 Pa for steel)")
            c = shaft_stiffness(G, p.d, p.L)
        u = s.i if p.side == "out" else 1.0   # speed of the piece over the input speed
        cs.append(c * u * u)
    return series_stiffness(cs), s.i


def _motor(m: Motor, M0: float, forcing_ratio: float, amplitude: float, chain_form: bool):
    from flywheel.elastic.chain import Drive, starting_torque_from_rated

    if chain_form and m.J is not None:
        raise FieldError("motor.J", "in a chain the first rotor is the motor: give its J in rotors[0]")
    if not chain_form and m.J is None:
        raise FieldError("motor.J", "missing required field (J_Д, the motor's rotor [kg·m²])")
    if m.characteristic == "linear":
        for k in ("speed_rpm",):
            if getattr(m, k) is not None:
                raise FieldError(f"motor.{k}", "only for characteristic = \"constant\" (a linear motor "
                                         "finds its own speed)")
        if m.synchronous_rpm is None:
            raise FieldError("motor.synchronous_rpm", "missing: the linear characteristic needs ω_x")
        given = [k for k in ("starting_torque", "rated_torque") if getattr(m, k) is not None]
        if len(given) != 1:
            raise FieldError("motor.starting_torque", "give exactly one of starting_torque, or "
                                                "rated_torque with rated_slip")
        if m.rated_torque is not None and m.rated_slip is None:
            raise FieldError("motor.rated_slip", "missing: needed with rated_torque (M_п = M_н/s_н)")
        if m.starting_torque is not None and m.rated_slip is not None:
            raise FieldError("motor.rated_slip", "only with rated_torque")
        M_start = (m.starting_torque if m.starting_torque is not None
                   else starting_torque_from_rated(m.rated_torque, m.rated_slip))
        if not M0 < M_start:
            raise FieldError("motor.starting_torque",
                       f"the motor cannot drive the machine: M_п = {M_start:g} N·m is not above "
                       f"the mean resistance reduced to shaft I, {M0:g} N·m")
        return Drive("linear", M0, amplitude, forcing_ratio, M_start=M_start,
                     omega_x=m.synchronous_rpm * RPM)
    for k in ("synchronous_rpm", "starting_torque", "rated_torque", "rated_slip"):
        if getattr(m, k) is not None:
            raise FieldError(f"motor.{k}", "only for characteristic = \"linear\"")
    if m.speed_rpm is None:
        raise FieldError("motor.speed_rpm", "missing: a constant-torque motor needs the steady speed "
                                      "of shaft I")
    return Drive("constant", M0, amplitude, forcing_ratio, omega_nominal=m.speed_rpm * RPM)


def build(case: AggregateCase):
    """(Chain, Drive or None) from a validated case; raises FieldError with the field path."""
    from flywheel.elastic.chain import chain, mean_reduced_inertia, reduced_inertia_I

    two_mass = [k for k in ("coupling", "machine") if getattr(case, k) is not None]
    chain_keys = [k for k in ("rotors", "shafts", "load") if getattr(case, k) is not None]
    if two_mass and chain_keys:
        raise FieldError(chain_keys[0], "a case is either the two-mass aggregate ([coupling], "
                                  "[machine]) or a chain ([[rotors]], [[shafts]]), not both")
    if two_mass:
        for k in ("coupling", "machine"):
            if getattr(case, k) is None:
                raise FieldError(k, "missing: the two-mass aggregate needs [motor], [coupling] and "
                              "[machine]")
        if case.motor is None:
            raise FieldError("motor", "missing: the two-mass aggregate needs [motor] with J (J_Д)")
        m = case.machine
        if m.J_III is not None and (m.J_III_0 is not None or m.J_III_positions is not None):
            raise FieldError("machine.J_III", "give J_III, or J_III_0 with J_III_positions, not both")
        if m.J_III is None:
            if m.J_III_positions is None:
                raise FieldError("machine.J_III", "missing: give J_III (J_пр.III [kg·m²]), or J_III_0 "
                                            "with J_III_positions")
            if not m.J_III_positions:
                raise FieldError("machine.J_III_positions", "needs at least one value")
            J_III = mean_reduced_inertia(m.J_III_0 or 0.0, m.J_III_positions)
            if not J_III > 0:
                raise FieldError("machine.J_III_positions", "J_пр.III comes out zero: must be positive")
        else:
            J_III = m.J_III
        if m.flywheel is not None and m.flywheel.shaft == "II" and m.i21 is None:
            raise FieldError("machine.i21", "missing: a flywheel on shaft II needs i21 = ω_II/ω_I")
        J_I = reduced_inertia_I(J_III, m.i31, m.flywheel.J if m.flywheel else 0.0,
                                m.flywheel.shaft if m.flywheel else "I", m.i21)
        c, i = _stiffness(case.coupling, "coupling")
        if case.coupling.i != 1.0:
            raise FieldError("coupling.i", "the coupling joins the motor to shaft I: no gear pair "
                                     "(the machine's gears are i21, i31)")
        ch = chain([case.motor.J, J_I], [c], [case.coupling.damping], [1.0, m.i31],
                   ["motor J_Д", "machine J_пр.I"])
        drive = _motor(case.motor, m.M0 * m.i31, m.i31 * m.order, m.M_amplitude * m.i31, False)
        return ch, drive
    if case.rotors is None or case.shafts is None:
        raise FieldError("rotors" if case.rotors is None else "shafts",
                   "missing: give the two-mass aggregate ([motor], [coupling], [machine]) or a "
                   "chain ([[rotors]] and [[shafts]])")
    if len(case.rotors) < 2:
        raise FieldError("rotors", f"a chain needs at least two rotors (got {len(case.rotors)})")
    if len(case.shafts) != len(case.rotors) - 1:
        raise FieldError("shafts", f"{len(case.rotors)} rotors need {len(case.rotors) - 1} shafts "
                             f"between them (got {len(case.shafts)})")
    u = 1.0
    J, cs, bs, us, names = [], [], [], [], []
    for k, r in enumerate(case.rotors):
        J.append(r.J * u * u)
        us.append(u)
        names.append(r.name or str(k + 1))
        if k < len(case.shafts):
            c_in, i = _stiffness(case.shafts[k], f"shafts[{k}]")
            cs.append(c_in * u * u)
            bs.append(case.shafts[k].damping * u * u)
            u *= i
    if len(set(names)) != len(names):
        raise FieldError("rotors", "rotor names must differ")
    ch = chain(J, cs, bs, us, names)
    if case.load is not None and case.motor is None:
        raise FieldError("motor", "missing: a [load] needs a [motor] on the first rotor")
    if case.motor is None:
        return ch, None
    ld = case.load or Load()
    drive = _motor(case.motor, ld.M0 * u, u * ld.order, ld.M_amplitude * u, True)
    return ch, drive


# -- loading --------------------------------------------------------------------------------------

def parse_aggregate_case(data: dict, source: str = "<case>") -> AggregateCase:
    """Validate a parsed TOML document or raise one CaseFileError line."""

    def check(case: AggregateCase) -> None:
        try:
            build(case)
        except FlywheelError as exc:
            raise CaseFileError(f"{source}: {exc}") from None

    return validate(data, AggregateCase, source, lambda errs: _describe(pick(errs)), check)


def load_aggregate_case(path) -> AggregateCase:
    """Read a TOML aggregate case file and validate it."""
    return load(path, parse_aggregate_case)


def to_model(case: AggregateCase, source: str = "<case>"):
    """(Chain, Drive or None) for :func:`flywheel.elastic.model.analyze`."""
    try:
        return build(case)
    except FieldError as exc:
        raise CaseFileError(f"{source}: {exc.where}: {exc}") from None
