"""The rotor chain of the machine aggregate (seed 003: Ефанов, «Теория механизмов и машин», ch. 9),
reduced to shaft I, and its motor and load: the building blocks of the model, the matrices M, K, C
and the seed's coefficients a_ij, c_ij (9.24–9.25).

Every rotor and every shaft is reduced to the speed of the first rotor (the motor, shaft I) by the
square of its speed ratio u = ω/ω_I (equal kinetic and potential energy: J·u², c·u²); in absolute
angles M·φ̈ + C·φ̇ + K·φ = F with a diagonal M and a tridiagonal K. The twists
q_{k+1} = φ_{k+1} − φ_k, q1 = φ1 (φ = T·q, T lower triangular of ones) give the seed's
coefficients as a = Tᵀ·M·T, c = Tᵀ·K·T. References: S.P. Timoshenko, *Vibration Problems in
Engineering*, ch. "Torsional vibration of shafts"; R.S. Khurmi & J.K. Gupta, *Theory of Machines*,
ch. "Torsional Vibrations" (geared systems: equivalent system reduced by the square of the gear
ratio).

The motor (:class:`Drive`) is a constant torque or the course's linear static characteristic of an
asynchronous motor M_Д = M_п·(1 − ω/ω_x).

Units: SI; J in kg·m²; c in N·m/rad; damping in N·m·s/rad. numpy only.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.errors import InputError, Notice


# -- building blocks ---------------------------------------------------------------------------

def shaft_stiffness(G: float, d: float, L: float) -> float:
    """Torsional stiffness of a solid round shaft, c = G·I_p/L = G·π·d⁴/(32·L) [N·m/rad].

    G : shear modulus [Pa]; d : diameter [m]; L : length [m].

    >>> round(shaft_stiffness(84e9, 0.07, 1.5), 1)   # 70 mm shaft, 1.5 m, C = 84 GN/m²
    132001.9
    """
    return G * math.pi * d ** 4 / (32.0 * L)


def series_stiffness(stiffnesses) -> float:
    """Stiffness of elastic elements in series (a stepped shaft): 1/c = Σ 1/c_k [N·m/rad].

    >>> series_stiffness([2.0, 2.0])
    1.0
    """
    return 1.0 / sum(1.0 / c for c in stiffnesses)


def reduced_inertia_I(J_III: float, i31: float, J_M: float = 0.0, flywheel_shaft: str = "I",
                      i21: float | None = None) -> float:
    """J_пр.I: the machine reduced to shaft I (seed 003, eqs. 9.21–9.23).

    Flywheel on shaft III: J_пр.I = J_M·i31² + J_пр.III·i31²   (9.21)
    on shaft II:          J_пр.I = J_M·i21² + J_пр.III·i31²   (9.22)
    on shaft I:           J_пр.I = J_M + J_пр.III·i31²        (9.23)
    with i31 = ω_III/ω_I, i21 = ω_II/ω_I; J_III and J_M in kg·m² on their own shafts.

    >>> reduced_inertia_I(2.0, 0.1, J_M=50.0, flywheel_shaft="III")
    0.52
    >>> reduced_inertia_I(2.0, 0.1, J_M=50.0, flywheel_shaft="II", i21=0.5)
    12.52
    """
    ratio = {"I": 1.0, "II": i21, "III": i31}[flywheel_shaft]
    if ratio is None:
        # library use only: no CLI input reaches this
        raise InputError("a flywheel on shaft II needs the gear ratio i21")
    return J_M * ratio ** 2 + J_III * i31 ** 2


def mean_reduced_inertia(J_0: float, J_positions) -> float:
    """J_пр.III = J_пр.0 + Σ J̃_i / 12 (seed 003): the constant part plus the mean of the
    variable part over the 12 positions of the cycle (any number of positions here).

    >>> mean_reduced_inertia(1.0, [0.0, 0.5, 1.0, 0.5])
    1.5
    """
    vals = list(J_positions)
    return J_0 + sum(vals) / len(vals)


def starting_torque_from_rated(rated_torque: float, rated_slip: float) -> float:
    """M_п of the linear characteristic M_Д = M_п·(1 − ω/ω_x) through the rated point:
    at ω_н = ω_x·(1 − s_н) the torque is M_п·s_н = M_н, so M_п = M_н/s_н [N·m].

    >>> starting_torque_from_rated(100.0, 0.04)
    2500.0
    """
    return rated_torque / rated_slip


def equivalent_length(c: float, d_ref: float, G_ref: float) -> float:
    """The length of a uniform solid shaft of diameter d_ref and shear modulus G_ref with the
    torsional stiffness c [m]: L = G·π·d⁴/(32·c). For a stepped shaft (pieces in series,
    1/c = Σ L_k·32/(G_k·π·d_k⁴)) this is Khurmi & Gupta's torsionally equivalent shaft
    (ch. 24: l = l1 + l2·(d1/d2)⁴ + l3·(d1/d3)⁴ for one material); a piece behind a gear pair of
    ratio i counts at the input speed, L_k·(d_ref/d_k)⁴/i².

    >>> round(equivalent_length(series_stiffness([shaft_stiffness(80e9, 0.075, 0.275),
    ...     shaft_stiffness(80e9, 0.05, 0.5), shaft_stiffness(80e9, 0.0375, 0.475)]),
    ...     0.075, 80e9), 10)                   # 0.275 + 0.5·1.5⁴ + 0.475·2⁴
    10.40625
    """
    return G_ref * math.pi * d_ref ** 4 / (32.0 * c)


@dataclass(frozen=True)
class ShaftLine:
    """One shaft of the case as a line, for the nodes along it and its equivalent length.

    index : its position in the case; ends : (from, to) indices of the free rotors it joins, −1
    for a fixed end (the frame); names : the rotors' (or the frame's) names; compliance : of each
    piece in order from the ``from`` end, at the shaft's input speed (the ``from`` end's)
    [rad/(N·m)]; length : each piece's length [m] or None (a piece given by its stiffness);
    c_input : the shaft's stiffness at its input speed [N·m/rad]; gear : its gear ratio
    ω_out/ω_in; d_ref, G_ref : the diameter [m] and shear modulus [Pa] of its first piece with a
    diameter (None: no piece has one).
    """

    index: int
    ends: tuple[int, int]
    names: tuple[str, str]
    compliance: tuple[float, ...]
    length: tuple[float | None, ...]
    c_input: float
    gear: float = 1.0
    d_ref: float | None = None
    G_ref: float | None = None

    @property
    def total_length(self) -> float | None:
        """Σ L_k [m], None if a piece has no length."""
        return None if any(x is None for x in self.length) else math.fsum(self.length)

    @property
    def equivalent_length(self) -> float | None:
        """:func:`equivalent_length` at (d_ref, G_ref) [m], None without a diameter."""
        if self.d_ref is None or self.G_ref is None:
            return None
        return equivalent_length(self.c_input, self.d_ref, self.G_ref)

    def position(self, fraction: float) -> float | None:
        """The distance from the ``from`` end [m] of the point at ``fraction`` of the shaft's
        compliance (the twist grows linearly along the compliance: a node of a mode lies where
        the amplitude, linear in it between the two rotors, is zero); None without lengths."""
        target = fraction * math.fsum(self.compliance)
        done, dist = 0.0, 0.0
        for k, (f, L) in enumerate(zip(self.compliance, self.length)):
            last = k == len(self.compliance) - 1
            if target <= done + f or last:
                if L is None:
                    return None
                return dist + L * min(max((target - done) / f, 0.0), 1.0)
            if L is None:
                return None
            done += f
            dist += L
        return dist


# -- the chain ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class Chain:
    """Rotors in a line (or a tree: a gear driving two shafts), reduced to the speed of the
    first (shaft I), free or with shafts fixed to the frame.

    names : rotor names; J : reduced inertias [kg·m²] (N); c : reduced stiffness of each
    connection [N·m/rad] (N − 1); damping : reduced viscous damping of each connection
    [N·m·s/rad] (N − 1); ratio : speed of each rotor over the first's, u_k = ω_k/ω_I (N);
    ends : the (from, to) rotor indices of each connection, None for a line (k, k + 1);
    ground : each rotor's stiffness to the frame through its fixed shafts [N·m/rad] (N), None
    for a free system; lines : the case's shafts as lines (:class:`ShaftLine`), for the nodes
    and equivalent lengths; frames : the names of the fixed ends.
    """

    names: tuple
    J: np.ndarray
    c: np.ndarray
    damping: np.ndarray
    ratio: np.ndarray
    ends: tuple[tuple[int, int], ...] | None = None
    ground: np.ndarray | None = None
    lines: tuple[ShaftLine, ...] = ()
    frames: tuple[str, ...] = ()

    def __post_init__(self):
        # (the case file's checks, cases/aggregate.py, come first: a chain from a case has its
        # rotors, connections and ground stiffness in the right numbers)
        if len(self.J) < 2 and (self.ground is None or len(self.J) < 1):
            # library use only: no CLI input reaches this
            raise InputError("a chain needs at least two rotors")
        if len(self.c) != len(self.J) - 1 or len(self.damping) != len(self.c):
            # library use only: no CLI input reaches this
            raise InputError("a chain of N rotors needs N − 1 connections")
        if self.ends is not None and len(self.ends) != len(self.c):
            # library use only: no CLI input reaches this
            raise InputError("every connection needs its two rotors")
        if self.ground is not None:
            if len(self.ground) != len(self.J):
                # library use only: no CLI input reaches this
                raise InputError("the ground stiffness needs one value per rotor")
            for k, v in enumerate(self.ground):
                if not (math.isfinite(v) and v >= 0):
                    raise InputError(Notice.of(
                        "ag_ground_not_finite", "rotor {name}: the stiffness to the frame reduced "
                        "to shaft I must be finite and not negative (got {v:g} N·m/rad)",
                        name=self.names[k], v=v))
            if not np.any(self.ground > 0):      # every one underflows to 0 (gear ratios ≪ 1)
                raise InputError(Notice.of(
                    "ag_ground_zero", "a system fixed to the frame needs a shaft to it"))
        for what, vals, unit, rotor in (("moment of inertia", self.J, " kg·m²", True),
                                        ("speed ratio", self.ratio, "", True),
                                        ("stiffness", self.c, " N·m/rad", False),
                                        ("damping", self.damping, " N·m·s/rad", False)):
            for k, v in enumerate(vals):
                if not math.isfinite(v):
                    where = f"rotor {self.names[k]}" if rotor else f"connection {k + 1}"
                    why = ": it overflows double precision" if math.isinf(v) else ""
                    raise InputError(Notice.of(
                        "ag_reduced_not_finite", "{where}: the {quantity} reduced to shaft I is "
                        "not finite (got {v:g}{unit_shown}){why}",
                        rotor=self.names[k] if rotor else None, connection=k + 1, quantity=what,
                        v=v, unit=unit.strip(), overflow=math.isinf(v), where=where,
                        unit_shown=unit, why=why))
        # a reduced J or c of 0: the product J·u² or c·u² underflows (gear ratios ≪ 1)
        for k, v in enumerate(self.J):
            if not v > 0:
                raise InputError(Notice.of(
                    "ag_J_not_positive", "rotor {name}: moment of inertia must be positive (got "
                    "{v:g} kg·m²)", name=self.names[k], v=v))
        for k, v in enumerate(self.c):
            if not v > 0:
                raise InputError(Notice.of(
                    "ag_c_not_positive", "connection {connection}: stiffness must be positive (got "
                    "{v:g} N·m/rad)", connection=k + 1, v=v))
        for k, v in enumerate(self.damping):
            if not v >= 0:
                # library use only: no CLI input reaches this
                raise InputError(f"connection {k + 1}: damping must not be negative (got {v:g})")

    @property
    def n(self) -> int:
        return len(self.J)

    @property
    def pairs(self) -> tuple[tuple[int, int], ...]:
        """(from, to) rotor indices of every connection: ``ends``, or (k, k + 1) for a line."""
        return self.ends if self.ends is not None else tuple((k, k + 1) for k in range(len(self.c)))

    @property
    def fixed(self) -> bool:
        """True if a shaft holds the system to the frame (no rigid-body mode)."""
        return self.ground is not None

    @property
    def is_line(self) -> bool:
        """A free, unbranched chain: the seed's model, which a motor and a load can drive."""
        return self.ground is None and all(e == (k, k + 1) for k, e in enumerate(self.pairs))


def chain(J, c, damping=None, ratio=None, names=None, ends=None, ground=None, lines=(),
          frames=()) -> Chain:
    """A :class:`Chain` from plain lists (already reduced to shaft I); ``ends`` (from, to) per
    connection for a tree, ``ground`` the stiffness of each rotor to the frame."""
    J = np.asarray(J, dtype=float)
    c = np.asarray(c, dtype=float)
    damping = np.zeros(len(c)) if damping is None else np.asarray(damping, dtype=float)
    ratio = np.ones(len(J)) if ratio is None else np.asarray(ratio, dtype=float)
    names = tuple(names) if names is not None else tuple(str(k + 1) for k in range(len(J)))
    ends = None if ends is None else tuple((int(a), int(b)) for a, b in ends)
    ground = None if ground is None else np.asarray(ground, dtype=float)
    return Chain(names, J, c, damping, ratio, ends, ground, tuple(lines), tuple(frames))


def mass_matrix(ch: Chain) -> np.ndarray:
    """M = diag(J_k) in absolute angles φ [kg·m²]."""
    return np.diag(ch.J)


def _assemble(values: np.ndarray, pairs, n: int) -> np.ndarray:
    """Σ over connections of v·(e_i − e_j)(e_i − e_j)ᵀ: tridiagonal for a line."""
    K = np.zeros((n, n))
    for v, (i, j) in zip(values, pairs):
        K[i, i] += v
        K[j, j] += v
        K[i, j] -= v
        K[j, i] -= v
    return K


def stiffness_matrix(ch: Chain) -> np.ndarray:
    """K in absolute angles: Π = ½·Σ c_k·(φ_to − φ_from)² + ½·Σ g_r·φ_r² [N·m/rad], the second
    sum over the rotors held by a shaft fixed to the frame (g_r its stiffness, the fixed end's
    angle zero: a boundary condition, not a huge inertia)."""
    K = _assemble(ch.c, ch.pairs, ch.n)
    if ch.ground is not None:
        K[np.diag_indices(ch.n)] += ch.ground
    return K


def damping_matrix(ch: Chain, motor_slope: float = 0.0) -> np.ndarray:
    """C in absolute angles: the connections' damping plus the motor's slope M_п/ω_x acting on
    the first rotor (a linear characteristic drops by M_п/ω_x per rad/s) [N·m·s/rad]."""
    C = _assemble(ch.damping, ch.pairs, ch.n)
    C[0, 0] += motor_slope
    return C


def twist_transform(n: int) -> np.ndarray:
    """T with φ = T·q, q1 = φ1, q_{k+1} = φ_{k+1} − φ_k (seed 003: φ2 = q1 + q2)."""
    return np.tril(np.ones((n, n)))


def coefficients(ch: Chain) -> tuple[np.ndarray, np.ndarray]:
    """The inertia and stiffness coefficients a_ij, c_ij of eqs. (9.24) in the coordinates q
    (9.25): a = Tᵀ·M·T, c = Tᵀ·K·T, built term by term so that the zeros are exact.

    With φ_k = q1 + … + q_k the kinetic energy ½·Σ J_k·φ̇_k² gives a_ij = Σ_{k ≥ max(i, j)} J_k
    (the inertia of everything beyond both coordinates) and the potential energy
    ½·Σ c_k·(φ_{k+1} − φ_k)² = ½·Σ c_k·q_{k+1}² gives c = diag(0, c_1, …, c_{N−1}): the shafts
    are uncoupled in the twists, and q1 (the rigid rotation) stores no energy.

    >>> a, c = coefficients(chain([3.0, 2.0], [100.0]))
    >>> a.tolist(), c.tolist()
    ([[5.0, 2.0], [2.0, 2.0]], [[0.0, 0.0], [0.0, 100.0]])
    >>> coefficients(chain([0.15, 0.3, 0.09], [132001.9, 198002.9]))[1].tolist()
    [[0.0, 0.0, 0.0], [0.0, 132001.9, 0.0], [0.0, 0.0, 198002.9]]

    A branched free system (a tree) keeps the coordinates q1 = φ of the first rotor and each
    connection's twist q = φ_to − φ_from: a_ij = Σ J over the rotors that both coordinates move,
    c = diag(0, c_1, …) still. A system fixed to the frame has no rigid rotation: its coordinates
    are the rotors' absolute angles, a = M = diag(J), c = K.
    """
    if ch.ground is not None:
        return mass_matrix(ch), stiffness_matrix(ch)
    c = np.diag(np.concatenate([[0.0], ch.c]))
    if ch.ends is None:
        tail = np.cumsum(ch.J[::-1])[::-1]            # tail[k] = J_k + … + J_N
        idx = np.arange(ch.n)
        a = tail[np.maximum.outer(idx, idx)]
        return a, c
    T = tree_transform(ch)
    a = np.zeros((ch.n, ch.n))
    for i in range(ch.n):
        for j in range(ch.n):
            a[i, j] = math.fsum(ch.J[r] * T[r, i] * T[r, j] for r in range(ch.n))
    return a, c


def tree_transform(ch: Chain) -> np.ndarray:
    """T with φ = T·q for a free system: q1 = φ of rotor 0, q_(k+1) = φ_to − φ_from of
    connection k; T[r, k + 1] = ±1 when connection k lies on the path from rotor 0 to r (+1
    walked from → to). A line gives :func:`twist_transform`."""
    n = ch.n
    T = np.zeros((n, n))
    T[:, 0] = 1.0
    adj: dict[int, list[tuple[int, int, float]]] = {r: [] for r in range(n)}
    for k, (i, j) in enumerate(ch.pairs):
        adj[i].append((j, k, 1.0))
        adj[j].append((i, k, -1.0))
    seen, todo = {0}, [0]
    while todo:
        r = todo.pop()
        for nxt, k, sign in adj[r]:
            if nxt not in seen:
                seen.add(nxt)
                T[nxt] = T[r]
                T[nxt, k + 1] = sign
                todo.append(nxt)
    return T


# -- motor and load ----------------------------------------------------------------------------

@dataclass(frozen=True)
class Drive:
    """Motor on the first rotor, resistance on the last, all reduced to shaft I.

    kind : "linear" (M_Д = M_п·(1 − ω/ω_x)) or "constant" (M_Д = M_0·u, the mean resistance);
    M_start : M_п [N·m]; omega_x : synchronous speed ω_x [rad/s]; omega_nominal : the steady
    speed of shaft I for a constant-torque motor [rad/s]; M0 : mean resistance reduced to shaft I,
    M_0·i31 [N·m]; amplitude : M̃·i31 [N·m]; forcing_ratio : forcing frequency over ω_I
    (i31 × the order of the forcing).
    """

    kind: str
    M0: float
    amplitude: float
    forcing_ratio: float
    M_start: float | None = None
    omega_x: float | None = None
    omega_nominal: float | None = None

    @property
    def slope(self) -> float:
        """−dM_Д/dω = M_п/ω_x for the linear characteristic, 0 for a constant torque."""
        return self.M_start / self.omega_x if self.kind == "linear" else 0.0

    def steady_speed(self) -> float:
        """ω_I in steady state: M_п·(1 − ω/ω_x) = M_0·i31 ⇒ ω = ω_x·(1 − M_0·i31/M_п)."""
        if self.kind == "linear":
            if not self.M0 < self.M_start:
                # library use only: no CLI input reaches this
                raise InputError(
                    f"the motor cannot drive the machine: the mean resistance reduced to shaft I, "
                    f"M_0·i31 = {self.M0:g} N·m, is not below the starting torque "
                    f"M_st = {self.M_start:g} N·m")
            return self.omega_x * (1.0 - self.M0 / self.M_start)
        return self.omega_nominal

    def torque(self, omega1):
        """M_Д(ω1) [N·m]."""
        if self.kind == "linear":
            return self.M_start * (1.0 - omega1 / self.omega_x)
        return self.M0


__all__ = ["shaft_stiffness", "series_stiffness", "equivalent_length", "reduced_inertia_I",
           "mean_reduced_inertia", "starting_torque_from_rated", "ShaftLine", "Chain", "chain",
           "mass_matrix", "stiffness_matrix", "damping_matrix", "twist_transform", "tree_transform",
           "coefficients", "Drive"]
