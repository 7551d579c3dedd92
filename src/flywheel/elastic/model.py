"""The machine aggregate with elastic couplings (seed 003: Ефанов, «Теория механизмов и машин»,
ch. 9) and its generalization to a chain of rotors joined by elastic shafts and gear pairs.

The seed's two-mass model: the driving mass J_Д (the motor's rotor) is joined through an elastic
coupling of stiffness c to the machine reduced to shaft I, J_пр.I (eqs. 9.21–9.23). Generalized
coordinates q1 = φ1, q2 = φ2 − φ1 (the twist of the coupling); Lagrange's equations (9.24)

    a11·q̈1 + a12·q̈2 + c11·q1 + c12·q2 = Q1,
    a21·q̈1 + a22·q̈2 + c21·q1 + c22·q2 = Q2,

with the inertia coefficients from the kinetic energy (9.25)
T = ½·[J_Д·q̇1² + J_пр.I·(q̇1 + q̇2)²]: a11 = J_Д + J_пр.I, a12 = a21 = a22 = J_пр.I, and the
stiffness coefficients from the potential energy Π = ½·c·q2²: c22 = c, the others zero. The
resistance reduced to shaft I is M_C.I = M_0·i31 + M̃·i31·sin(ω_III·t) (9.20).

A chain of N rotors generalizes it: every rotor and every shaft is reduced to the speed of the
first rotor (the motor, shaft I) by the square of its speed ratio u = ω/ω_I (equal kinetic and
potential energy: J·u², c·u²); in absolute angles M·φ̈ + C·φ̇ + K·φ = F with a diagonal M and a
tridiagonal K. The twists q_{k+1} = φ_{k+1} − φ_k, q1 = φ1 (φ = T·q, T lower triangular of ones)
give the seed's coefficients as a = Tᵀ·M·T, c = Tᵀ·K·T. Natural frequencies solve
K·x = ω²·M·x (the rigid-body mode has ω = 0). References for the chain: S.P. Timoshenko,
*Vibration Problems in Engineering*, ch. "Torsional vibration of shafts"; W.T. Thomson,
*Theory of Vibration with Applications*, ch. "Systems with two or more degrees of freedom";
R.S. Khurmi & J.K. Gupta, *Theory of Machines*, ch. "Torsional Vibrations" (geared systems:
equivalent system reduced by the square of the gear ratio).

The motor is a constant torque or the course's linear static characteristic of an asynchronous
motor M_Д = M_п·(1 − ω/ω_x). Both are linear in ω, and the forcing is a sine of time, so the whole
system is linear: its steady state is found in closed form (a constant mean speed, a static twist
that carries the mean torque, and a harmonic response from the dynamic stiffness
K − ω²·M + i·ω·C) and checked by scipy's solve_ivp, which also integrates the start-up from rest.
The integrations are bounded: the explicit method (DOP853) needs about ten steps per period of
the highest natural frequency, so the start-up runs at most MAX_FAST_PERIODS of them, and a
steady check that would need more than CHECK_FAST_PERIODS (a slow machine on a stiff coupling)
uses the implicit Radau method with the system's constant Jacobian; the result says so in its
notes.

Units: SI; angles in radians; J in kg·m²; c in N·m/rad; damping in N·m·s/rad. numpy only at
import; scipy is imported inside the functions that use it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from flywheel.errors import InputError

#: relative tolerance under which an eigenvalue counts as the rigid-body mode
RIGID_TOL = 1e-9
#: resonance: |ω − ω_n|/ω_n below this for a mode whose damping ratio is below it too (the
#: dynamic magnification would exceed about 1/(2·√2·RESONANCE_TOL) ≈ 3.5·10⁵)
RESONANCE_TOL = 1e-6
#: the explicit start-up runs at most this many periods of the highest natural frequency
MAX_FAST_PERIODS = 2000
#: the steady check is explicit up to this many periods of it, implicit (Radau) beyond
CHECK_FAST_PERIODS = 500


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


def two_mass_frequency(J1: float, J2: float, c: float) -> float:
    """Natural frequency of the two-mass torsional system [rad/s]:
    ω = √(c·(J1 + J2)/(J1·J2)) (the coupling's mode of the seed's model).

    >>> round(two_mass_frequency(1.0, 1.0, 2.0), 12)
    2.0
    """
    return math.sqrt(c * (J1 + J2) / (J1 * J2))


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


@dataclass(frozen=True)
class Modes:
    """omega : natural frequencies [rad/s], ascending, the rigid-body 0 first; shapes : the
    mode shapes in absolute angles (columns, largest component 1)."""

    omega: np.ndarray
    shapes: np.ndarray

    @property
    def elastic(self) -> np.ndarray:
        """The natural frequencies without the rigid-body mode [rad/s]."""
        return self.omega[1:]


def natural_frequencies(ch: Chain) -> Modes:
    """Solve K·x = ω²·M·x (scipy.linalg.eigh). A free chain has exactly one rigid-body mode,
    ω = 0 (round-off set to zero), and N − 1 torsional modes.

    >>> m = natural_frequencies(chain([1.0, 1.0], [2.0]))
    >>> [round(float(w), 9) for w in m.omega]
    [0.0, 2.0]
    """
    from scipy.linalg import eigh

    with np.errstate(all="ignore"):
        lam, vec = eigh(stiffness_matrix(ch), mass_matrix(ch))
    if not (np.all(np.isfinite(lam)) and np.all(np.isfinite(vec))):
        with np.errstate(all="ignore"):
            ratio = float(np.max(ch.c)) / float(np.min(ch.J))
        raise InputError(
            f"the natural frequencies are not finite: the eigenproblem K·x = ω²·M·x overflows "
            f"double precision (stiffness up to {np.max(ch.c):g} N·m/rad against inertia down to "
            f"{np.min(ch.J):g} kg·m², c/J = {ratio:g} 1/s²)")
    scale = max(abs(lam[-1]), 1e-300)
    lam = np.where(np.abs(lam) < RIGID_TOL * scale, 0.0, lam)
    omega = np.sqrt(np.clip(lam, 0.0, None))
    idx = np.argmax(np.abs(vec), axis=0)
    shapes = vec / vec[idx, np.arange(vec.shape[1])]
    return Modes(omega, shapes)


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


# -- steady state in closed form ---------------------------------------------------------------

@dataclass(frozen=True)
class Steady:
    """The periodic steady state.

    omega_mean : mean speed of shaft I [rad/s]; omega_forcing : forcing frequency [rad/s];
    X : complex amplitudes of φ_k about ω·t + θ_k (response Im(X·e^{iωt})) [rad];
    theta : static offsets [rad] (θ_1 = 0); twist_mean, twist_amplitude : of each connection's
    twist q = φ_{k+1} − φ_k [rad] (the mean is negative: the machine lags); moment_mean : the
    elastic moment each connection transmits, c·(φ_k − φ_{k+1}) = −c·q, mean (= M_0·i31 > 0)
    [N·m]; moment_amplitude : c·|q| amplitude [N·m] (both reduced to shaft I);
    omega_amplitude : speed amplitude of each rotor (reduced) [rad/s];
    delta : (ω_max − ω_min)/ω_mean of each rotor.
    """

    omega_mean: float
    omega_forcing: float
    X: np.ndarray
    theta: np.ndarray
    twist_mean: np.ndarray
    twist_amplitude: np.ndarray
    moment_mean: np.ndarray
    moment_amplitude: np.ndarray
    omega_amplitude: np.ndarray
    delta: np.ndarray


def _harmonic(ch: Chain, drive: Drive, w: float) -> tuple[np.ndarray, np.ndarray]:
    """Solve (K − ω²·M + i·ω·C)·X = F for the complex amplitudes, in the unknowns X1 (the first
    rotor) and the twists t_k = X_{k+1} − X_k, so that a small twist is not the difference of two
    large angles (a slow forcing swings the whole machine by far more than it twists a shaft).

    With X = X1·1 + L·t (L[k, j] = 1 for the rotors beyond connection j) the columns of Z·[1 L]
    are exact: Z·1 = −ω²·J + i·ω·s·e1 (K·1 = 0, the couplings' C·1 = 0, s the motor's slope) and
    Z·L_j = (c_j + i·ω·b_j)·(e_{j+1} − e_j) − ω²·(J on the rotors beyond j). Each column is scaled
    to unit size before the solve. Returns (X, t).
    """
    n = ch.n
    A = np.zeros((n, n), dtype=complex)
    A[:, 0] = -w * w * ch.J
    A[0, 0] += 1j * w * drive.slope
    for j in range(n - 1):
        k = ch.c[j] + 1j * w * ch.damping[j]
        A[j, j + 1] -= k
        A[j + 1, j + 1] += k
        A[j + 1:, j + 1] -= w * w * ch.J[j + 1:]
    F = np.zeros(n, dtype=complex)
    F[-1] = -drive.amplitude
    scale = np.abs(A).max(axis=0)
    scale[scale == 0] = 1.0
    with np.errstate(all="ignore"):
        y = np.linalg.solve(A / scale, F) / scale
    t = y[1:]
    X = y[0] + np.concatenate([[0.0], np.cumsum(t)])
    return X, t


def resonant_mode(ch: Chain, drive: Drive, modes: Modes, w: float) -> int | None:
    """Index (into modes.elastic) of a torsional mode the forcing ω sits on with nothing to damp
    it: |ω − ω_n|/ω_n < RESONANCE_TOL and the mode's damping ratio
    ζ = xᵀ·C·x/(2·ω_n·xᵀ·M·x) < RESONANCE_TOL (C: the couplings and the motor's slope). None if
    there is no such mode. The rigid-body mode (ω_n = 0) is never a resonance: ω > 0.

    >>> ch = chain([1.0, 1.0], [2.0])
    >>> d = Drive("constant", 0.0, 1.0, 1.0, omega_nominal=2.0)
    >>> resonant_mode(ch, d, natural_frequencies(ch), 2.0), resonant_mode(ch, d, natural_frequencies(ch), 1.9)
    (0, None)
    """
    M, C = mass_matrix(ch), damping_matrix(ch, drive.slope)
    for k, wn in enumerate(modes.elastic):
        if not wn > 0:
            continue
        x = modes.shapes[:, k + 1]
        zeta = float(x @ C @ x) / (2.0 * wn * float(x @ M @ x))
        if abs(w - wn) / wn < RESONANCE_TOL and zeta < RESONANCE_TOL:
            return k
    return None


def steady_state(ch: Chain, drive: Drive, modes: Modes | None = None) -> Steady:
    """The exact periodic solution of the linear model.

    Mean part: every rotor turns at ω_s; each connection carries the mean torque M_0·i31, so its
    twist is q = −M_0·i31/c (the elastic moment c·(φ_k − φ_{k+1}) = −c·q = M_0·i31 drives the
    machine). Harmonic part: (K − ω²·M + i·ω·C)·X = F with F = −M̃·i31 on the last rotor and C
    including the motor's slope M_п/ω_x (see :func:`_harmonic`).

    Refused (InputError), never infinity: the forcing on an undamped torsional mode
    (:func:`resonant_mode`); a swing of any rotor's speed as large as the mean speed (the machine
    would stop and turn backwards, which the model — a resistance that does not depend on the
    direction of motion — cannot follow; with a forcing far below the torsional modes it is the
    rigid-body mode ω = 0 that takes the load); amplitudes that overflow.
    """
    omega_s = drive.steady_speed()
    w = drive.forcing_ratio * omega_s
    modes = modes or natural_frequencies(ch)
    if drive.amplitude == 0:
        X = np.zeros(ch.n, dtype=complex)
        t = np.zeros(ch.n - 1, dtype=complex)
    else:
        k = resonant_mode(ch, drive, modes, w)
        if k is not None:
            wn = float(modes.elastic[k])
            raise InputError(
                f"the forcing frequency {w:.6g} rad/s ({w / (2 * math.pi):.6g} Hz) equals the "
                f"natural frequency {wn:.6g} rad/s of torsional mode {k + 1} (within "
                f"{RESONANCE_TOL:g}) and nothing damps it: the steady amplitude is unbounded (give "
                f"a coupling damping, a linear motor characteristic, or change the speed)")
        X, t = _harmonic(ch, drive, w)
        if not (np.all(np.isfinite(X)) and np.all(np.isfinite(t))):
            raise InputError(f"the steady amplitudes are not finite at the forcing frequency "
                             f"{w:.6g} rad/s: the harmonic solution overflows double precision")
    twist_mean = -drive.M0 / ch.c
    theta = np.concatenate([[0.0], np.cumsum(twist_mean)])
    twist_amp = np.abs(t)
    omega_amp = w * np.abs(X)
    swing = int(np.argmax(omega_amp))
    if omega_amp[swing] >= omega_s:
        raise InputError(_reversal_message(ch, drive, modes, w, omega_s, X, swing))
    return Steady(omega_s, w, X, theta, twist_mean, twist_amp, np.full(len(ch.c), drive.M0),
                  ch.c * twist_amp, omega_amp, 2.0 * omega_amp / omega_s)


def _reversal_message(ch, drive, modes, w, omega_s, X, k) -> str:
    amp = float(w * abs(X[k]))
    rigid = float(w * abs(ch.J @ X) / ch.J.sum())   # speed swing of the centre of inertia
    tail = ("so it would stop and turn backwards every period: there is no steady run of this "
            "model (raise the speed, add inertia or a flywheel, or lower M_amplitude)")
    if rigid >= 0.5 * amp and len(modes.elastic) and w < modes.elastic[0]:
        held = ("which a constant-torque motor does not hold" if drive.slope == 0
                else "which the motor characteristic hardly holds")
        return (f"the forcing frequency {w:.6g} rad/s is far below the lowest natural frequency "
                f"{float(modes.elastic[0]):.6g} rad/s, so the load swings the whole machine as a "
                f"rigid body (the ω = 0 mode, {held}): the speed would vary by ±{amp:.6g} rad/s "
                f"about the mean {omega_s:.6g} rad/s, " + tail)
    return (f"the speed of rotor {ch.names[k]} would vary by ±{amp:.6g} rad/s about the mean "
            f"{omega_s:.6g} rad/s (δ = {2 * amp / omega_s:.4g}), " + tail)


def forced_twist_two_mass(J1: float, J2: float, c: float, amplitude: float, w: float) -> float:
    """Undamped steady twist amplitude of the two-mass model, the motor a constant torque, the
    force M̃·sin(ω·t) on the second mass: |q2| = M̃/(J2·|ω² − ω_n²|), ω_n² = c·(J1 + J2)/(J1·J2)
    (from Cramer's rule on (K − ω²M)·X = F; ω ≠ ω_n).

    >>> forced_twist_two_mass(1.0, 1.0, 2.0, 1.0, 1.0)
    0.3333333333333333
    """
    wn2 = c * (J1 + J2) / (J1 * J2)
    return amplitude / (J2 * abs(w * w - wn2))


# -- time domain -------------------------------------------------------------------------------

@dataclass(frozen=True)
class History:
    """t [s]; phi [rad] and omega [rad/s] of every rotor (rows), reduced to shaft I; twist [rad]
    of every connection, q_{k+1} = φ_{k+1} − φ_k (rows; integrated as such, not a difference of
    two large angles); method: the solve_ivp method used."""

    t: np.ndarray
    phi: np.ndarray
    omega: np.ndarray
    twist: np.ndarray
    method: str = "DOP853"


def state_space(ch: Chain, drive: Drive | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The equations as ẏ = A·y + b0 + b1·sin(ω·t) in the seed's coordinates, the state
    y = (q1 = φ1, the twists q_2 … q_N, the speeds ω_1 … ω_N), all reduced to shaft I.

    q̇1 = ω1, q̇_{k+1} = ω_{k+1} − ω_k; J_k·ω̇_k = the elastic and damping moments of the
    connections on either side (connection j pulls its left rotor by c_j·q_{j+1} + b_j·q̇_{j+1}
    and its right rotor back by as much) + M_Д(ω1) on the first rotor
    (M_п − (M_п/ω_x)·ω1, or the constant M_0·i31) − (M_0·i31 + M̃·i31·sin ω_III·t) on the last
    (9.20). The system is linear: A is also its (constant) Jacobian. drive None: free, b = 0.
    """
    n = ch.n
    A = np.zeros((2 * n, 2 * n))
    b0 = np.zeros(2 * n)
    b1 = np.zeros(2 * n)
    A[0, n] = 1.0
    for j in range(n - 1):
        A[1 + j, n + j], A[1 + j, n + j + 1] = -1.0, 1.0
        for k, sign in ((j, 1.0), (j + 1, -1.0)):         # left rotor pulled, right held back
            A[n + k, 1 + j] += sign * ch.c[j] / ch.J[k]
            A[n + k, n + j + 1] += sign * ch.damping[j] / ch.J[k]
            A[n + k, n + j] -= sign * ch.damping[j] / ch.J[k]
    if drive is not None:
        if drive.kind == "linear":
            A[n, n] -= drive.slope / ch.J[0]
            b0[n] += drive.M_start / ch.J[0]
        else:
            b0[n] += drive.M0 / ch.J[0]
        b0[-1] -= drive.M0 / ch.J[-1]
        b1[-1] -= drive.amplitude / ch.J[-1]
    return A, b0, b1


def simulate(ch: Chain, drive: Drive | None, phi0, omega0, t_end: float, n_samples: int = 2001,
             rtol: float = 1e-9, atol: float = 1e-12, method: str = "DOP853") -> History:
    """Integrate M·φ̈ + C·φ̇ + K·φ = F(t, φ̇) with scipy's solve_ivp from φ0, ω0, in the
    coordinates of :func:`state_space`.

    F: the motor torque M_Д(φ̇_1) on the first rotor, −(M_0·i31 + M̃·i31·sin(ω_III·t)) on the last
    (9.20), ω_III = forcing_ratio × the steady speed (the seed's linear model); drive None: free.
    method "DOP853" (explicit) takes steps of at most 1/8 of the shortest period, the highest
    natural frequency's or the forcing's; "Radau" (implicit, for a stiff system: a torsional mode
    far faster than the forcing) gets the constant Jacobian and steps of at most 1/8 of the forcing
    period — it follows the forced motion but damps a mode's own oscillation it does not resolve.
    """
    from scipy.integrate import solve_ivp

    n = ch.n
    A, b0, b1 = state_space(ch, drive)
    w = drive.forcing_ratio * drive.steady_speed() if drive is not None else 0.0
    phi0 = np.asarray(phi0, dtype=float)
    y0 = np.concatenate([[phi0[0]], np.diff(phi0), np.asarray(omega0, dtype=float)])

    def rhs(t, y):
        return A @ y + b0 + b1 * math.sin(w * t)

    fastest = max(float(natural_frequencies(ch).omega[-1]), w, 1e-300)
    t_eval = np.linspace(0.0, t_end, n_samples)
    if method == "Radau":
        opts = {"jac": A, "max_step": 2 * math.pi / max(w, 1e-300) / 8}
    else:
        opts = {"max_step": 2 * math.pi / fastest / 8}
    with np.errstate(all="ignore"):
        sol = solve_ivp(rhs, (0.0, t_end), y0, method=method, t_eval=t_eval, rtol=rtol,
                        atol=atol, **opts)
    if not sol.success or not np.all(np.isfinite(sol.y)):
        raise InputError(f"solve_ivp ({method}) failed over 0 … {t_end:.4g} s: "
                         f"{sol.message if not sol.success else 'the solution is not finite'}")
    q1, twist, om = sol.y[0], sol.y[1:n], sol.y[n:]
    phi = q1 + np.vstack([np.zeros_like(q1), np.cumsum(twist, axis=0)])
    return History(sol.t, phi, om, twist, method)


def energy(ch: Chain, h: History) -> np.ndarray:
    """Kinetic plus potential energy along a history [J]: ½·Σ J·ω² + ½·Σ c·q²."""
    return (0.5 * (ch.J[:, None] * h.omega ** 2).sum(axis=0)
            + 0.5 * (ch.c[:, None] * h.twist ** 2).sum(axis=0))


def steady_method(ch: Chain, w: float, periods: float = 5.0) -> tuple[str, float]:
    """("DOP853" or "Radau", the periods of the highest natural frequency in ``periods`` forcing
    periods): explicit while that is at most CHECK_FAST_PERIODS, implicit beyond.

    >>> steady_method(chain([1.0, 1.0], [2.0]), 1.0)
    ('DOP853', 10.0)
    >>> steady_method(chain([1.0, 1.0], [2.0e6]), 1.0)
    ('Radau', 10000.0)
    """
    fast = periods * float(natural_frequencies(ch).omega[-1]) / w
    return ("DOP853" if fast <= CHECK_FAST_PERIODS else "Radau"), fast


def steady_run(ch: Chain, drive: Drive, st: Steady, periods: float = 5.0,
               per_period: int = 200) -> History:
    """solve_ivp started on the closed-form periodic orbit (φ = θ + Im X, ω = ω_s + ω·Re X) over a
    few forcing periods: it must stay there (a check of the closed form). Explicit (DOP853) when
    that is at most CHECK_FAST_PERIODS periods of the highest natural frequency, else the implicit
    Radau method with the constant Jacobian (:func:`steady_method`): the cost is bounded either
    way."""
    w = st.omega_forcing
    phi0 = st.theta + st.X.imag
    omega0 = st.omega_mean + w * st.X.real
    t_end = periods * 2 * math.pi / w
    method, _ = steady_method(ch, w, periods)
    return simulate(ch, drive, phi0, omega0, t_end, n_samples=int(periods * per_period) + 1,
                    method=method)


def start_up_duration(ch: Chain, drive: Drive) -> tuple[float, float]:
    """(the default start-up duration, the duration wanted before the cap) [s]: five mechanical
    time constants τ = ΣJ·ω_x/M_п of the linear characteristic or 20 forcing periods, whichever is
    longer, at most MAX_FAST_PERIODS periods of the highest natural frequency."""
    w = drive.forcing_ratio * drive.steady_speed()
    wanted = 20 * 2 * math.pi / w
    if drive.kind == "linear":
        wanted = max(wanted, 5 * ch.J.sum() * drive.omega_x / drive.M_start)
    fastest = float(natural_frequencies(ch).omega[-1])
    return min(wanted, MAX_FAST_PERIODS * 2 * math.pi / fastest), wanted


def start_up(ch: Chain, drive: Drive, t_end: float | None = None, n_samples: int = 4001) -> History:
    """From rest, all twists zero (linear motor), or from the nominal speed with the load applied
    at t = 0 (constant torque, which has no start-up of its own). Default duration:
    :func:`start_up_duration`. Explicit (DOP853): the start-up excites the torsional modes, and
    their peak moment is what it is for."""
    omega_s = drive.steady_speed()
    if t_end is None:
        t_end, _ = start_up_duration(ch, drive)
    v0 = 0.0 if drive.kind == "linear" else omega_s
    return simulate(ch, drive, np.zeros(ch.n), np.full(ch.n, v0), t_end, n_samples=n_samples)


# -- everything --------------------------------------------------------------------------------

@dataclass(frozen=True)
class Resonance:
    """omega_n [rad/s]; ratio = ω_forcing/ω_n; margin = |1 − ratio| (0 at resonance)."""

    omega_n: float
    ratio: float
    margin: float


@dataclass(frozen=True)
class AggregateResult:
    """Everything :func:`analyze` finds. ``drive`` None: natural frequencies only. notes: what
    the reader should know about how the time-domain runs were bounded."""

    chain: Chain
    a: np.ndarray
    c: np.ndarray
    modes: Modes
    drive: Drive | None = None
    steady: Steady | None = None
    resonance: list = field(default_factory=list)
    check: History | None = None
    check_twist_amplitude: float | None = None
    check_delta: tuple | None = None
    startup: History | None = None
    startup_peak_moment: float | None = None
    startup_time: float | None = None
    notes: list = field(default_factory=list)


def _amplitude(x: np.ndarray) -> float:
    return float((x.max() - x.min()) / 2.0)


def analyze(ch: Chain, drive: Drive | None = None, t_end: float | None = None,
            time_domain: bool = True) -> AggregateResult:
    """Coefficients (9.24–9.25), natural frequencies and — with a drive — the closed-form steady
    state, the resonance margins, a solve_ivp check on the periodic orbit and the start-up."""
    a, c = coefficients(ch)
    modes = natural_frequencies(ch)
    if drive is None:
        return AggregateResult(ch, a, c, modes)
    st = steady_state(ch, drive, modes)
    res = [Resonance(float(wn), st.omega_forcing / wn, abs(1 - st.omega_forcing / wn))
           for wn in modes.elastic]
    if not time_domain:
        return AggregateResult(ch, a, c, modes, drive, st, res)
    notes = []
    f_top = float(modes.omega[-1]) / (2 * math.pi)
    method, fast = steady_method(ch, st.omega_forcing)
    if method != "DOP853":
        notes.append(
            f"solve_ivp check: 5 forcing periods are {fast:.4g} periods of the highest natural "
            f"frequency {f_top:.6g} Hz, more than the explicit method's {CHECK_FAST_PERIODS}: "
            f"integrated with the implicit Radau method and the constant Jacobian, which follows "
            f"the forced motion but damps that mode's own oscillation")
    chk = steady_run(ch, drive, st)
    ch_twist = _amplitude(chk.twist[0])
    ch_delta = tuple(float(2 * _amplitude(chk.omega[k]) / st.omega_mean) for k in (0, -1))
    if t_end is None:
        t_end, wanted = start_up_duration(ch, drive)
        if t_end < wanted:
            why = ("the longer of five time constants and 20 forcing periods"
                   if drive.kind == "linear" else "20 forcing periods")
            notes.append(
                f"start-up: integrated over {t_end:.4g} s = {MAX_FAST_PERIODS} periods of the "
                f"highest natural frequency {f_top:.6g} Hz (the cap), not the default "
                f"{wanted:.4g} s ({why}); --t-end sets the duration")
    su = start_up(ch, drive, t_end)
    peak = float(np.max(np.abs(ch.c[0] * su.twist[0])))
    reached = np.nonzero(su.omega[0] >= 0.95 * st.omega_mean)[0]
    t95 = float(su.t[reached[0]]) if drive.kind == "linear" and len(reached) else None
    return AggregateResult(ch, a, c, modes, drive, st, res, chk, ch_twist, ch_delta, su, peak, t95,
                           notes)
