"""The TOML case format of ``flywheel aggregate`` (documented field by field in docs/aggregate.md).

Two shapes, one per file:

* the seed's two-mass aggregate (seed 003, Ефанов ch. 9): ``[motor]`` (with J_Д), ``[coupling]``
  and ``[machine]`` (J_пр.III, gear ratios i21, i31, the flywheel and its shaft, M_0, M̃);
* a chain of rotors: ``[[rotors]]`` and ``[[shafts]]`` (N rotors, N − 1 shafts, each shaft an
  elastic element given by c or by G, d, L — stepped shafts as segments — with an optional gear
  pair of ratio i = ω_out/ω_in), optionally driven: ``[motor]`` on the first rotor (without J)
  and ``[load]`` on the last. A rotor with ``fixed = true`` is the frame: a shaft end built in
  (a boundary condition). Shafts with ``between = ["A", "B"]`` join any two rotors, so one gear
  may drive two shafts (a branched system, a tree). Fixed or branched systems give their
  natural frequencies, mode shapes and nodes; a motor drives a free unbranched chain only.

SI units; speeds in rev/min where the key says ``_rpm``. Every problem becomes one
:class:`~flywheel.errors.CaseFileError` line: ``file: field.path: what is wrong (what is allowed)``.
"""
from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field

from flywheel.errors import CaseFileError, FlywheelError, Notice, led, said
from flywheel.io.schema import TitleText, title_field, MAX_TEXT, FieldError, StrictModel, load, text_field, validate, within, clean_loc, describe, pick
from flywheel.cases.document import DocumentSpec
from flywheel.units import RAD_S_PER_RPM

Pos = Annotated[float, Field(gt=0)]
NonNeg = Annotated[float, Field(ge=0)]
# physically meaningful ranges (checked where the numbers enter: nothing overflows later)
Inertia = Annotated[float, Field(gt=0), within(1e-9, 1e12, "kg·m²")]
Length = Annotated[float, Field(gt=0), within(1e-4, 100.0, "m")]
Diameter = Annotated[float, Field(gt=0), within(1e-4, 10.0, "m")]
Modulus = Annotated[float, Field(gt=0), within(1e6, 1e12, "Pa")]
Stiffness = Annotated[float, Field(gt=0), within(1e-3, 1e12, "N·m/rad")]
Torque = Annotated[float, Field(gt=0), within(1e-6, 1e9, "N·m")]
Moment = Annotated[float, Field(ge=0), within(0.0, 1e9, "N·m")]
Rpm = Annotated[float, Field(gt=0), within(10.0, 1e5, "rpm")]
Ratio = Annotated[float, Field(gt=0), within(1e-3, 1e3, "")]




class Motor(StrictModel):
    """The driving motor on shaft I."""

    J: Inertia | None = Field(None, description="J_D, the rotor's moment of inertia [kg·m²] (two-mass "
                                            "form only; in a chain the first rotor is the motor)")
    characteristic: Literal["linear", "constant"] = Field(
        "linear", description="linear: M_D = M_st·(1 − ω/ω_x); constant: M_D = M_0·i31")
    synchronous_rpm: Rpm | None = Field(None, description="ω_x, synchronous (no-load) speed "
                                                          "[rev/min] (linear)")
    starting_torque: Torque | None = Field(None, description="M_st, the starting torque [N·m] (linear)")
    rated_torque: Torque | None = Field(None, description="M_r, the rated torque [N·m] (linear, with rated_slip, "
                                                       "instead of starting_torque)")
    rated_slip: float | None = Field(None, gt=0, lt=1, description="s_r, the rated slip, 0 < s_r < 1: M_st = M_r/s_r")
    speed_rpm: Annotated[float, Field(gt=0), within(1e-6, 1e5, "rpm")] | None = Field(None, description="steady speed of shaft I [rev/min] (constant)")


class Segment(StrictModel):
    """One elastic piece of a shaft: c, or d and L (with G here or on the shaft)."""

    c: Stiffness | None = Field(None, description="torsional stiffness [N·m/rad]")
    d: Diameter | None = Field(None, description="diameter [m]")
    L: Length | None = Field(None, description="length [m]")
    G: Modulus | None = Field(None, description="shear modulus [Pa] (default: the shaft's)")
    side: Literal["in", "out"] = Field("in", description="before (in) or after (out) the gear pair")


class Shaft(StrictModel):
    """An elastic connection: one piece (c, or G with d and L) or segments in series, an optional
    gear pair, an optional viscous damping; in a chain, the rotors it joins."""

    between: list[str] | None = Field(None, description="the names of the two rotors it joins, "
                                                        "input side first (default: rotors k and "
                                                        "k + 1)")
    c: Stiffness | None = Field(None, description="torsional stiffness [N·m/rad]")
    G: Modulus | None = Field(None, description="shear modulus [Pa]")
    d: Diameter | None = Field(None, description="diameter [m]")
    L: Length | None = Field(None, description="length [m]")
    segments: list[Segment] | None = Field(None, description="pieces in series (stepped shaft, "
                                                             "or both sides of a gear pair)")
    i: Ratio = Field(1.0, description="gear ratio ω_out/ω_in of a gear pair in this connection")
    damping: NonNeg = Field(0.0, description="viscous damping of the twist [N·m·s/rad], at the "
                                             "input speed")


class Flywheel(StrictModel):
    J: Inertia = Field(description="J_M, the flywheel's moment of inertia [kg·m²]")
    shaft: Literal["I", "II", "III"] = Field(description="the shaft it sits on")


class Machine(StrictModel):
    """The machine behind the coupling (seed 003)."""

    J_III: Inertia | None = Field(None, description="J_red.III, the mechanism reduced to shaft III "
                                                "[kg·m²]")
    J_III_0: NonNeg | None = Field(None, description="J_red.0, its constant part [kg·m²] (with "
                                                     "J_III_positions)")
    J_III_positions: list[NonNeg] | None = Field(
        None, description="J̃_i, the variable part at the positions of a cycle [kg·m²]: "
                          "J_red.III = J_red.0 + ΣJ̃_i/n")
    i21: Ratio | None = Field(None, description="ω_II/ω_I (needed with a flywheel on shaft II)")
    i31: Ratio = Field(description="ω_III/ω_I")
    flywheel: Flywheel | None = None
    M0: Moment = Field(0.0, description="M_0, mean resistance moment on shaft III [N·m]")
    M_amplitude: Moment = Field(0.0, description="M̃, amplitude of its harmonic part [N·m]")
    order: Pos = Field(1.0, description="forcing frequency / ω_III (1: sin ω_III·t as in 9.20)")


class Rotor(StrictModel):
    name: str | None = Field(None, max_length=MAX_TEXT)
    J: Inertia | None = Field(None, description="moment of inertia [kg·m²] (not for a fixed end)")
    fixed: bool = Field(False, description="true: the frame, a shaft end built in (no J)")


class Load(StrictModel):
    """Resistance on the last rotor of a chain, on its own shaft."""

    M0: Moment = Field(0.0, description="mean resistance moment [N·m]")
    M_amplitude: Moment = Field(0.0, description="amplitude of its harmonic part [N·m]")
    order: Pos = Field(1.0, description="forcing frequency / the last rotor's speed")


class AggregateCase(StrictModel):
    title: TitleText = title_field()
    source: TitleText = title_field()
    motor: Motor | None = None
    coupling: Shaft | None = None
    machine: Machine | None = None
    rotors: list[Rotor] | None = None
    shafts: list[Shaft] | None = None
    load: Load | None = None
    document: DocumentSpec = Field(default_factory=DocumentSpec, description="names for the title page and the title block (docs/case-format.md, [document])")


FIELDS = {"(top level)": AggregateCase, "motor": Motor, "coupling": Shaft, "machine": Machine,
          "machine.flywheel": Flywheel, "rotors": Rotor, "shafts": Shaft, "load": Load,
          "shafts.segments": Segment, "coupling.segments": Segment,
          "document": DocumentSpec}


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
    c, i, _ = _stiffness_pieces(s, where)
    return c, i


def _stiffness_pieces(s: Shaft, where: str) -> tuple[float, float, list]:
    """(stiffness reduced to the shaft's input speed, gear ratio, pieces): each piece
    (its stiffness at the input speed, length or None, diameter or None, G or None), the pieces
    before the gear pair ("in") first, then those after it ("out")."""
    from flywheel.elastic.chain import series_stiffness, shaft_stiffness

    direct = [k for k in ("c", "d", "L") if getattr(s, k) is not None]
    if s.segments is not None and direct:
        raise FieldError(f"{where}.{direct[0]}", Notice.of(
            "ag_stiffness_twice", "give the stiffness either directly or as segments, not both"))
    pieces = s.segments if s.segments is not None else [Segment(c=s.c, d=s.d, L=s.L)]
    if not pieces:
        raise FieldError(f"{where}.segments", Notice.of(
            "ag_no_segments", "needs at least one segment"))
    cs = []
    info = []
    for k, p in enumerate(pieces):
        at = f"{where}.segments[{k}]" if s.segments is not None else where
        if p.c is not None:
            if p.d is not None or p.L is not None:
                raise FieldError(f"{at}.c", Notice.of(
                    "coupling_c_or_dL", "give c, or d and L (with G), not both"))
            c = p.c
            G = None
        else:
            if p.d is None or p.L is None:
                missing = "d" if p.d is None else "L"
                raise FieldError(f"{at}.{missing}", Notice.of(
                    "ag_c_or_dL_missing", "missing: give c, or d and L with G"))
            G = p.G if p.G is not None else s.G
            if G is None:
                raise FieldError(f"{at}.G", Notice.of(
                    "shaft_G", "missing: the shear modulus is needed with d and L (e.g. 8.0e10 Pa "
                    "for steel)"))
            c = shaft_stiffness(G, p.d, p.L)
        u = s.i if p.side == "out" else 1.0   # speed of the piece over the input speed
        cs.append(c * u * u)
        info.append((p.side == "out", c * u * u, p.L, p.d, G))
    info.sort(key=lambda x: x[0])             # stable: "in" pieces first, in order
    return series_stiffness(cs), s.i, [x[1:] for x in info]


def _line(s: Shaft, where: str, index: int, ends: tuple[int, int], names: tuple[str, str]):
    """The shaft as a :class:`~flywheel.elastic.chain.ShaftLine` (nodes, equivalent length)."""
    from flywheel.elastic.chain import ShaftLine

    c, i, pieces = _stiffness_pieces(s, where)
    ref = next(((d, G) for _, _, d, G in pieces if d is not None), (None, None))
    return ShaftLine(index, ends, names, tuple(1.0 / ck for ck, *_ in pieces),
                     tuple(L for _, L, _, _ in pieces), c, i, ref[0], ref[1])


def _motor(m: Motor, M0: float, forcing_ratio: float, amplitude: float, chain_form: bool):
    from flywheel.elastic.chain import Drive, starting_torque_from_rated

    if chain_form and m.J is not None:
        raise FieldError("motor.J", Notice.of(
            "ag_chain_motor_J", "in a chain the first rotor is the motor: give its J in rotors[0]"))
    if not chain_form and m.J is None:
        raise FieldError("motor.J", Notice.of(
            "motor_J_missing", "missing required field (J_D, the motor's rotor [kg·m²])"))
    if m.characteristic == "linear":
        for k in ("speed_rpm",):
            if getattr(m, k) is not None:
                raise FieldError(f"motor.{k}", Notice.of(
                    "ag_only_constant", "only for characteristic = \"constant\" (a linear motor "
                    "finds its own speed)"))
        if m.synchronous_rpm is None:
            raise FieldError("motor.synchronous_rpm", Notice.of(
                "ag_omega_x_missing", "missing: the linear characteristic needs ω_x"))
        given = [k for k in ("starting_torque", "rated_torque") if getattr(m, k) is not None]
        if len(given) != 1:
            raise FieldError("motor.starting_torque", Notice.of(
                "motor_torque_one_of", "give exactly one of starting_torque, or rated_torque with "
                "rated_slip"))
        if m.rated_torque is not None and m.rated_slip is None:
            raise FieldError("motor.rated_slip", Notice.of(
                "ag_slip_missing", "missing: needed with rated_torque (M_st = M_r/s_r)"))
        if m.starting_torque is not None and m.rated_slip is not None:
            raise FieldError("motor.rated_slip", Notice.of(
                "ag_slip_only_rated", "only with rated_torque"))
        M_start = (m.starting_torque if m.starting_torque is not None
                   else starting_torque_from_rated(m.rated_torque, m.rated_slip))
        if not M0 < M_start:
            raise FieldError("motor.starting_torque", Notice.of(
                "ag_motor_too_weak", "the motor cannot drive the machine: M_st = {M_start:g} N·m is "
                "not above the mean resistance reduced to shaft I, {M0:g} N·m", M_start=M_start,
                M0=M0))
        return Drive("linear", M0, amplitude, forcing_ratio, M_start=M_start,
                     omega_x=m.synchronous_rpm * RAD_S_PER_RPM)
    for k in ("synchronous_rpm", "starting_torque", "rated_torque", "rated_slip"):
        if getattr(m, k) is not None:
            raise FieldError(f"motor.{k}", Notice.of(
                "ag_only_linear", "only for characteristic = \"linear\""))
    if m.speed_rpm is None:
        raise FieldError("motor.speed_rpm", Notice.of(
            "ag_speed_missing", "missing: a constant-torque motor needs the steady speed of shaft "
            "I"))
    return Drive("constant", M0, amplitude, forcing_ratio, omega_nominal=m.speed_rpm * RAD_S_PER_RPM)


def build(case: AggregateCase):
    """(Chain, Drive or None) from a validated case; raises FieldError with the field path."""
    from flywheel.elastic.chain import chain, mean_reduced_inertia, reduced_inertia_I

    two_mass = [k for k in ("coupling", "machine") if getattr(case, k) is not None]
    chain_keys = [k for k in ("rotors", "shafts", "load") if getattr(case, k) is not None]
    if two_mass and chain_keys:
        raise FieldError(chain_keys[0], Notice.of(
            "chain_or_two_mass", "a case is either the two-mass aggregate ([coupling], [machine]) "
            "or a chain ([[rotors]], [[shafts]]), not both"))
    if two_mass:
        for k in ("coupling", "machine"):
            if getattr(case, k) is None:
                raise FieldError(k, Notice.of(
                    "two_mass_needs", "missing: the two-mass aggregate needs [motor], [coupling] "
                    "and [machine]"))
        if case.motor is None:
            raise FieldError("motor", Notice.of(
                "ag_two_mass_motor", "missing: the two-mass aggregate needs [motor] with J (J_D)"))
        m = case.machine
        if m.J_III is not None and (m.J_III_0 is not None or m.J_III_positions is not None):
            raise FieldError("machine.J_III", Notice.of(
                "ag_J_III_twice", "give J_III, or J_III_0 with J_III_positions, not both"))
        if m.J_III is None:
            if m.J_III_positions is None:
                raise FieldError("machine.J_III", Notice.of(
                    "J_III_missing", "missing: give J_III (J_red.III [kg·m²]), or J_III_0 with "
                    "J_III_positions"))
            if not m.J_III_positions:
                raise FieldError("machine.J_III_positions", Notice.of(
                    "ag_no_positions", "needs at least one value"))
            J_III = mean_reduced_inertia(m.J_III_0 or 0.0, m.J_III_positions)
            if not J_III > 0:
                raise FieldError("machine.J_III_positions", Notice.of(
                    "ag_J_III_zero", "J_red.III comes out zero: must be positive"))
        else:
            J_III = m.J_III
        if m.flywheel is not None and m.flywheel.shaft == "II" and m.i21 is None:
            raise FieldError("machine.i21", Notice.of(
                "i21_missing", "missing: a flywheel on shaft II needs i21 = ω_II/ω_I"))
        J_I = reduced_inertia_I(J_III, m.i31, m.flywheel.J if m.flywheel else 0.0,
                                m.flywheel.shaft if m.flywheel else "I", m.i21)
        c, i = _stiffness(case.coupling, "coupling")
        if case.coupling.i != 1.0:
            raise FieldError("coupling.i", Notice.of(
                "ag_coupling_gear", "the coupling joins the motor to shaft I: no gear pair (the "
                "machine's gears are i21, i31)"))
        if case.coupling.between is not None:
            raise FieldError("coupling.between", Notice.of(
                "ag_coupling_between", "the coupling joins the motor to the machine: between is "
                "for the shafts of a chain"))
        # the motor first: its checks (motor.J missing …) name the field before J_Д enters the chain
        drive = _motor(case.motor, m.M0 * m.i31, m.i31 * m.order, m.M_amplitude * m.i31, False)
        names = ("motor J_Д", "machine J_пр.I")
        ch = chain([case.motor.J, J_I], [c], [case.coupling.damping], [1.0, m.i31],
                   list(names), lines=[_line(case.coupling, "coupling", 0, (0, 1), names)])
        return ch, drive
    frames = [k for k, r in enumerate(case.rotors or []) if r.fixed]
    if frames and not case.shafts:
        raise FieldError("shafts", Notice.of(
            "fixed_end_shafts", "missing: the fixed end rotors[{k}] holds a rotor through a shaft "
            "to the frame; give [[shafts]] (N rotors need N − 1 shafts)", k=frames[0]))
    if case.rotors is None or case.shafts is None:
        raise FieldError("rotors" if case.rotors is None else "shafts",
                   Notice.of(
                       "aggregate_form", "missing: give the two-mass aggregate ([motor], "
                       "[coupling], [machine]) or a chain ([[rotors]] and [[shafts]])"))
    if len(case.rotors) < 2:
        raise FieldError("rotors", Notice.of(
            "two_rotors", "a chain needs at least two rotors (got {count})", count=len(case.rotors)
        ))
    if len(case.shafts) != len(case.rotors) - 1:
        raise FieldError("shafts", Notice.of(
            "shafts_count", "{rotors} rotors need {shafts} shafts between them (got {count})",
            rotors=len(case.rotors), count=len(case.shafts), shafts=len(case.rotors) - 1))
    for k, r in enumerate(case.rotors):
        if r.fixed and r.J is not None:
            raise FieldError(f"rotors[{k}].J", Notice.of(
                "ag_fixed_J", "a fixed end (fixed = true) is the frame: it has no moment of inertia"
            ))
        if not r.fixed and r.J is None:
            raise FieldError(f"rotors[{k}].J", Notice.of(
                "ag_rotor_J_missing", "missing required field (moment of inertia [kg·m²]; or fixed "
                "= true for the frame)"))
    names = [r.name or str(k + 1) for k, r in enumerate(case.rotors)]
    if len(set(names)) != len(names):
        raise FieldError("rotors", Notice.of("rotor_names", "rotor names must differ"))
    given = [k for k, sh in enumerate(case.shafts) if sh.between is not None]
    if frames or given:
        ch = _tree(case, names, frames, given)
    else:
        u = 1.0
        J, cs, bs, us, lines = [], [], [], [], []
        for k, r in enumerate(case.rotors):
            J.append(r.J * u * u)
            us.append(u)
            if k < len(case.shafts):
                c_in, i = _stiffness(case.shafts[k], f"shafts[{k}]")
                cs.append(c_in * u * u)
                bs.append(case.shafts[k].damping * u * u)
                lines.append(_line(case.shafts[k], f"shafts[{k}]", k, (k, k + 1),
                                   (names[k], names[k + 1])))
                u *= i
        ch = chain(J, cs, bs, us, names, lines=lines)
    if case.load is not None and case.motor is None:
        raise FieldError("motor", Notice.of(
            "load_needs_motor", "missing: a [load] needs a [motor] on the first rotor"))
    if case.motor is None:
        return ch, None
    if not ch.is_line:
        what = ("a shaft fixed to the frame cannot turn continuously" if ch.fixed else
                "the forced vibration and the start-up are computed for an unbranched chain")
        raise FieldError("motor", Notice.of(
            "ag_motor_needs_line", "{what}: a [motor] (and a [load]) need a free, unbranched "
            "chain; this system gives its natural frequencies and modes only", fixed=ch.fixed,
            what=what))
    u = float(ch.ratio[-1])
    ld = case.load or Load()
    drive = _motor(case.motor, ld.M0 * u, u * ld.order, ld.M_amplitude * u, True)
    return ch, drive


def _sq(x: float) -> float:
    """x², infinity where it overflows (a float's ``**`` raises OverflowError instead): the chain
    then names the quantity that is not finite."""
    try:
        return x ** 2
    except OverflowError:
        return math.inf


def _tree(case: AggregateCase, names: list[str], frames: list[int], given: list[int]):
    """The Chain of a branched system or one with fixed ends: rotors joined by shafts
    ``between`` two names (default: consecutive), forming a tree whose fixed ends (the frame)
    are leaves. Speed ratios spread from the first free rotor along the shafts (u_to = u_from·i);
    every J and c is reduced to it by u²; a shaft to the frame becomes the stiffness of its
    rotor to the ground."""
    from flywheel.elastic.chain import chain

    n = len(case.rotors)
    if given and len(given) != len(case.shafts):
        k = next(k for k in range(len(case.shafts)) if k not in given)
        raise FieldError(f"shafts[{k}].between", Notice.of(
            "ag_between_all_or_none", "missing: give between for every shaft or for none (then "
            "shaft k joins rotors k and k + 1)"))
    ends = []
    for k, sh in enumerate(case.shafts):
        if sh.between is None:
            ends.append((k, k + 1))
            continue
        if len(sh.between) != 2:
            raise FieldError(f"shafts[{k}].between", Notice.of(
                "ag_between_two", "needs two rotor names, input side first (got {count})",
                count=len(sh.between)))
        idx = []
        for name in sh.between:
            if name not in names:
                raise FieldError(f"shafts[{k}].between", Notice.of(
                    "ag_unknown_rotor", "unknown rotor {name!r} (rotors: {rotors})", name=name,
                    rotors=", ".join(names)))
            idx.append(names.index(name))
        if idx[0] == idx[1]:
            raise FieldError(f"shafts[{k}].between", Notice.of(
                "ag_shaft_to_itself", "joins rotor {name!r} to itself", name=names[idx[0]]))
        ends.append((idx[0], idx[1]))
    adj: dict[int, list[tuple[int, int]]] = {r: [] for r in range(n)}
    for k, (a, b) in enumerate(ends):
        adj[a].append((b, k))
        adj[b].append((a, k))
    for f in frames:
        if len(adj[f]) != 1:
            raise FieldError(f"rotors[{f}]", Notice.of(
                "ag_fixed_one_shaft", "a fixed end is an end of the system: one shaft to it (got "
                "{count})", count=len(adj[f])))
    free = [r for r in range(n) if r not in frames]
    if not free:
        raise FieldError("rotors", Notice.of(
            "ag_all_fixed", "every rotor is fixed: at least one must turn"))
    # speed ratios from the first free rotor, through the tree (frames are leaves)
    u: dict[int, float] = {free[0]: 1.0}
    todo = [free[0]]
    while todo:
        r = todo.pop()
        for nxt, k in adj[r]:
            if nxt in u:
                continue
            i = case.shafts[k].i
            u[nxt] = u[r] * i if ends[k][0] == r else u[r] / i
            if nxt not in frames:
                todo.append(nxt)
    missing = [r for r in range(n) if r not in u]
    if missing:
        raise FieldError("shafts", Notice.of(
            "ag_not_connected", "the rotors and shafts must form one connected system without "
            "loops: {name!r} is not joined to {first!r}", name=names[missing[0]],
            first=names[free[0]]))
    pos = {r: j for j, r in enumerate(free)}
    J = [case.rotors[r].J * _sq(u[r]) for r in free]
    cs, bs, pairs, lines = [], [], [], []
    ground = [0.0] * len(free)
    for k, (a, b) in enumerate(ends):
        where = f"shafts[{k}]"
        c_in, _ = _stiffness(case.shafts[k], where)
        c_red, b_red = c_in * _sq(u[a]), case.shafts[k].damping * _sq(u[a])
        lines.append(_line(case.shafts[k], where, k, (pos.get(a, -1), pos.get(b, -1)),
                           (names[a], names[b])))
        if a in frames or b in frames:
            if case.shafts[k].damping:
                raise FieldError(f"{where}.damping", Notice.of(
                    "ag_frame_damping", "a shaft to the frame: its damping is not modelled "
                    "(natural frequencies only)"))
            ground[pos[b if a in frames else a]] += c_red
            continue
        cs.append(c_red)
        bs.append(b_red)
        pairs.append((pos[a], pos[b]))
    line = not frames and all(p == (j, j + 1) for j, p in enumerate(pairs))
    return chain(J, cs, bs, [u[r] for r in free], [names[r] for r in free],
                 ends=None if line else pairs, ground=ground if frames else None, lines=lines,
                 frames=[names[f] for f in frames])


# -- loading --------------------------------------------------------------------------------------

def parse_aggregate_case(data: dict, source: str = "<case>") -> AggregateCase:
    """Validate a parsed TOML document or raise one CaseFileError line (a case of another
    kind is named as such, with its command)."""
    from flywheel.cases import wrong_kind

    other = wrong_kind(data, "aggregate", source)
    if other is not None:
        raise CaseFileError(other)

    def check(case: AggregateCase) -> None:
        try:
            build(case)
        except FlywheelError as exc:
            raise CaseFileError(led(f"{source}: ", said(exc))) from None

    return validate(data, AggregateCase, source, lambda errs: _describe(pick(errs)), check)


def load_aggregate_case(path) -> AggregateCase:
    """Read a TOML aggregate case file and validate it."""
    return load(path, parse_aggregate_case)


def to_model(case: AggregateCase, source: str = "<case>"):
    """(Chain, Drive or None) for :func:`flywheel.elastic.model.analyze`."""
    try:
        return build(case)
    except FieldError as exc:
        raise CaseFileError(led(f"{source}: {exc.where}: ", said(exc))) from None
