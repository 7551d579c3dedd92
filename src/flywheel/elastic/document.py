"""The document of ``flywheel aggregate --json`` as typed entries, which the one serializer
(io/serialize.py) writes: :func:`document` reads an :class:`~flywheel.elastic.model.AggregateResult`
into them (no physics here: conversions of units and the reductions the keys name). The keys
and their order are the contract of docs/aggregate.md; a None entry of the top level and of
the steady state is written as null."""
from __future__ import annotations

from dataclasses import dataclass

from flywheel.units import RPM_PER_RAD_S, TWO_PI


@dataclass(frozen=True)
class RotorEntry:
    """A rotor: its name, J reduced to shaft I [kg·m²], speed ratio to shaft I [1]."""

    name: str
    J_reduced: float
    speed_ratio: float


@dataclass(frozen=True)
class ConnectionEntry:
    """A connection reduced to shaft I: stiffness [N·m/rad] and damping [N·m·s/rad]."""

    c_reduced: float
    damping_reduced: float


@dataclass(frozen=True)
class NodeEntry:
    """A node of a torsional mode (elastic/modes.py ``Node``)."""

    shaft: int | None
    between: tuple[str, ...] | None
    fraction: float | None
    distance: float | None
    rotor: str | None

    KEEP_NONE = ("shaft", "between", "fraction", "distance", "rotor")


@dataclass(frozen=True)
class ModeEntry:
    """A torsional mode: its frequency [Hz, 1/min, rad/s], shape, nodes."""

    natural_hz: float
    natural_rpm: float
    natural_rad_s: float
    shape: tuple[float, ...]
    nodes: tuple[NodeEntry, ...]


@dataclass(frozen=True)
class ShaftEntry:
    """A shaft of the case: its rotors, gear ratio, stiffness at its input speed and reduced
    [N·m/rad], length and equivalent length [m] at the reference diameter [m] and shear modulus
    [Pa] (None without a geometry)."""

    between: tuple[str, ...]
    gear_ratio: float
    c: float
    c_reduced: float
    length: float | None
    equivalent_length: float | None
    reference_diameter: float | None
    shear_modulus: float | None

    KEEP_NONE = ("length", "equivalent_length", "reference_diameter", "shear_modulus")


@dataclass(frozen=True)
class MotorEntry:
    """The motor and load reduced to shaft I [N·m, rad/s]."""

    characteristic: str
    starting_torque: float | None
    synchronous_speed: float | None
    M0_reduced: float
    amplitude_reduced: float

    KEEP_NONE = ("starting_torque", "synchronous_speed")


@dataclass(frozen=True)
class SteadyEntry:
    """The steady forced vibration: speeds [rad/s], forcing [Hz], twists [rad], elastic
    moments [N·m], δ of every rotor [1]."""

    omega_motor: float
    omega_machine: float
    omega_forcing: float
    forcing_hz: float
    omega_motor_max: float
    omega_motor_min: float
    omega_machine_max: float
    omega_machine_min: float
    twist_mean: tuple[float, ...]
    twist_amplitudes: tuple[float, ...]
    elastic_moment_mean: tuple[float, ...]
    elastic_moment_amplitudes: tuple[float, ...]
    delta: tuple[float, ...]


@dataclass(frozen=True)
class ResonanceEntry:
    """A mode's resonance margin: its frequency [Hz], forcing/natural ratio and margin [1]."""

    natural_hz: float
    ratio: float
    margin: float


@dataclass(frozen=True)
class TimeDomainEntry:
    """The time-domain check and the start-up: twist amplitude [rad], δ [1], durations [s],
    peak elastic moment [N·m], the method of the check."""

    twist_amplitude: float | None
    delta_motor: float | None
    delta_machine: float | None
    start_up_duration: float
    start_up_peak_elastic_moment: float | None
    start_up_time_to_95_percent: float | None
    steady_check_method: str

    KEEP_NONE = ("twist_amplitude", "delta_motor", "delta_machine",
                 "start_up_peak_elastic_moment", "start_up_time_to_95_percent")


@dataclass(frozen=True)
class AggregateDocument:
    """The whole document (docs/aggregate.md, "Results")."""

    natural_frequencies_hz: tuple[float, ...]
    twist_amplitude: float | None
    elastic_moment_amplitude: float | None
    delta_motor: float | None
    delta_machine: float | None
    natural_frequencies_rad_s: tuple[float, ...]
    rotors: tuple[RotorEntry, ...]
    connections: tuple[ConnectionEntry, ...]
    a: list[list[float]]
    c: list[list[float]]
    mode_shapes: list[list[float]]
    natural_frequencies_rpm: tuple[float, ...]
    modes: tuple[ModeEntry, ...]
    shafts: tuple[ShaftEntry, ...]
    fixed_ends: tuple[str, ...]
    motor: MotorEntry | None = None
    steady: SteadyEntry | None = None
    resonance: tuple[ResonanceEntry, ...] | None = None
    time_domain: TimeDomainEntry | None = None
    notes: tuple[str, ...] | None = None

    KEEP_NONE = ("twist_amplitude", "elastic_moment_amplitude", "delta_motor", "delta_machine")


def _f(x):
    return None if x is None else float(x)


def document(r) -> AggregateDocument:
    """The document of the result ``r`` (an AggregateResult)."""
    ch, st = r.chain, r.steady
    elastic = r.modes.elastic
    u = {n: float(x) for n, x in zip(ch.names, ch.ratio)}
    shafts = tuple(
        ShaftEntry(between=tuple(line.names), gear_ratio=line.gear, c=line.c_input,
                   c_reduced=line.c_input * (u[line.names[0]] if line.ends[0] >= 0
                                             else u[line.names[1]] / line.gear) ** 2,
                   length=line.total_length, equivalent_length=line.equivalent_length,
                   reference_diameter=line.d_ref, shear_modulus=line.G_ref)
        for line in ch.lines)
    modes = tuple(
        ModeEntry(natural_hz=float(w) / TWO_PI, natural_rpm=float(w) * RPM_PER_RAD_S,
                  natural_rad_s=float(w), shape=tuple(float(x) for x in shape),
                  nodes=tuple(NodeEntry(shaft=n.shaft,
                                        between=None if n.between is None else tuple(n.between),
                                        fraction=n.fraction, distance=n.distance, rotor=n.rotor)
                              for n in nodes))
        for w, shape, nodes in zip(elastic, r.modes.elastic_shapes.T, r.nodes))
    extra: dict = {}
    if st is not None:
        dr, u_last = r.drive, float(ch.ratio[-1])
        extra["motor"] = MotorEntry(characteristic=dr.kind, starting_torque=dr.M_start,
                                    synchronous_speed=dr.omega_x, M0_reduced=dr.M0,
                                    amplitude_reduced=dr.amplitude)
        extra["steady"] = SteadyEntry(
            omega_motor=st.omega_mean, omega_machine=st.omega_mean * u_last,
            omega_forcing=st.omega_forcing, forcing_hz=st.omega_forcing / TWO_PI,
            omega_motor_max=st.omega_mean + float(st.omega_amplitude[0]),
            omega_motor_min=st.omega_mean - float(st.omega_amplitude[0]),
            omega_machine_max=(st.omega_mean + float(st.omega_amplitude[-1])) * u_last,
            omega_machine_min=(st.omega_mean - float(st.omega_amplitude[-1])) * u_last,
            twist_mean=tuple(float(x) for x in st.twist_mean),       # q = φ_(k+1) − φ_k
            twist_amplitudes=tuple(float(x) for x in st.twist_amplitude),
            elastic_moment_mean=tuple(float(x) for x in st.moment_mean),  # −c·q, transmitted
            elastic_moment_amplitudes=tuple(float(x) for x in st.moment_amplitude),
            delta=tuple(float(x) for x in st.delta))
        extra["resonance"] = tuple(ResonanceEntry(natural_hz=x.omega_n / TWO_PI, ratio=x.ratio,
                                                  margin=x.margin) for x in r.resonance)
        if r.check is not None:
            extra["time_domain"] = TimeDomainEntry(
                twist_amplitude=r.check_twist_amplitude, delta_motor=r.check_delta[0],
                delta_machine=r.check_delta[1], start_up_duration=float(r.startup.t[-1]),
                start_up_peak_elastic_moment=r.startup_peak_moment,
                start_up_time_to_95_percent=r.startup_time, steady_check_method=r.check.method)
        extra["notes"] = tuple(note.text for note in r.notes)
    return AggregateDocument(
        natural_frequencies_hz=tuple(float(w) / TWO_PI for w in elastic),
        twist_amplitude=_f(st.twist_amplitude[0]) if st else None,
        elastic_moment_amplitude=_f(st.moment_amplitude[0]) if st else None,
        delta_motor=_f(st.delta[0]) if st else None,
        delta_machine=_f(st.delta[-1]) if st else None,
        natural_frequencies_rad_s=tuple(float(w) for w in elastic),
        rotors=tuple(RotorEntry(name=n, J_reduced=float(j), speed_ratio=float(x))
                     for n, j, x in zip(ch.names, ch.J, ch.ratio)),
        connections=tuple(ConnectionEntry(c_reduced=float(c), damping_reduced=float(b))
                          for c, b in zip(ch.c, ch.damping)),
        a=r.a.tolist(), c=r.c.tolist(), mode_shapes=r.modes.elastic_shapes.T.tolist(),
        natural_frequencies_rpm=tuple(float(w) * RPM_PER_RAD_S for w in elastic),
        modes=modes, shafts=shafts, fixed_ends=tuple(ch.frames), **extra)
