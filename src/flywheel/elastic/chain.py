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

from flywheel.errors import InputError


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


# -- the chain ---------------------------------------------------------------------------------

@dataclass(frozen=True)
class Chain:
    """Rotors in a line, reduced to the speed of the first (shaft I).

    names : rotor names; J : reduced inertias [kg·m²] (N); c : reduced stiffness of each
    connection [N·m/rad] (N − 1); damping : reduced viscous damping of each connection
    [N·m·s/rad] (N − 1); ratio : speed of each rotor over the first's, u_k = ω_k/ω_I (N).
    """

    names: tuple
    J: np.ndarray
    c: np.ndarray
    damping: np.ndarray
    ratio: np.ndarray

    def __post_init__(self):
        if len(self.J) < 2:
            raise InputError("a chain needs at least two rotors")
        if len(self.c) != len(self.J) - 1 or len(self.damping) != len(self.c):
            raise InputError("a chain of N rotors needs N − 1 connections")
        for what, vals, unit, rotor in (("moment of inertia", self.J, " kg·m²", True),
                                        ("speed ratio", self.ratio, "", True),
                                        ("stiffness", self.c, " N·m/rad", False),
                                        ("damping", self.damping, " N·m·s/rad", False)):
            for k, v in enumerate(vals):
                if not math.isfinite(v):
                    where = f"rotor {self.names[k]}" if rotor else f"connection {k + 1}"
                    why = ": it overflows double precision" if math.isinf(v) else ""
                    raise InputError(f"{where}: the {what} reduced to shaft I is not finite "
                                     f"(got {v:g}{unit}){why}")
        for k, v in enumerate(self.J):
            if not v > 0:
                raise InputError(f"rotor {self.names[k]}: moment of inertia must be positive "
                                 f"(got {v:g} kg·m²)")
        for k, v in enumerate(self.c):
            if not v > 0:
                raise InputError(f"connection {k + 1}: stiffness must be positive "
                                 f"(got {v:g} N·m/rad)")
        for k, v in enumerate(self.damping):
            if not v >= 0:
                raise InputError(f"connection {k + 1}: damping must not be negative (got {v:g})")

    @property
    def n(self) -> int:
        return len(self.J)


def chain(J, c, damping=None, ratio=None, names=None) -> Chain:
    """A :class:`Chain` from plain lists (already reduced to shaft I)."""
    J = np.asarray(J, dtype=float)
    c = np.asarray(c, dtype=float)
    damping = np.zeros(len(c)) if damping is None else np.asarray(damping, dtype=float)
    ratio = np.ones(len(J)) if ratio is None else np.asarray(ratio, dtype=float)
    names = tuple(names) if names is not None else tuple(str(k + 1) for k in range(len(J)))
    return Chain(names, J, c, damping, ratio)


def mass_matrix(ch: Chain) -> np.ndarray:
    """M = diag(J_k) in absolute angles φ [kg·m²]."""
    return np.diag(ch.J)


def _tridiagonal(values: np.ndarray, n: int) -> np.ndarray:
    K = np.zeros((n, n))
    for k, v in enumerate(values):
        K[k, k] += v
        K[k + 1, k + 1] += v
        K[k, k + 1] -= v
        K[k + 1, k] -= v
    return K


def stiffness_matrix(ch: Chain) -> np.ndarray:
    """K in absolute angles: Π = ½·Σ c_k·(φ_{k+1} − φ_k)² [N·m/rad]."""
    return _tridiagonal(ch.c, ch.n)


def damping_matrix(ch: Chain, motor_slope: float = 0.0) -> np.ndarray:
    """C in absolute angles: the connections' damping plus the motor's slope M_п/ω_x acting on
    the first rotor (a linear characteristic drops by M_п/ω_x per rad/s) [N·m·s/rad]."""
    C = _tridiagonal(ch.damping, ch.n)
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
    """
    tail = np.cumsum(ch.J[::-1])[::-1]            # tail[k] = J_k + … + J_N
    idx = np.arange(ch.n)
    a = tail[np.maximum.outer(idx, idx)]
    c = np.diag(np.concatenate([[0.0], ch.c]))
    return a, c


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
                raise InputError(
                    f"the motor cannot drive the machine: the mean resistance reduced to shaft I, "
                    f"M_0·i31 = {self.M0:g} N·m, is not below the starting torque "
                    f"M_п = {self.M_start:g} N·m")
            return self.omega_x * (1.0 - self.M0 / self.M_start)
        return self.omega_nominal

    def torque(self, omega1):
        """M_Д(ω1) [N·m]."""
        if self.kind == "linear":
            return self.M_start * (1.0 - omega1 / self.omega_x)
        return self.M0


__all__ = ["shaft_stiffness", "series_stiffness", "reduced_inertia_I", "mean_reduced_inertia",
           "starting_torque_from_rated", "Chain", "chain", "mass_matrix", "stiffness_matrix",
           "damping_matrix", "twist_transform", "coefficients", "Drive"]
