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

The parts: :mod:`flywheel.elastic.chain` (building blocks, the chain, its matrices and
coefficients, the motor), :mod:`flywheel.elastic.modes` (natural frequencies, resonance),
:mod:`flywheel.elastic.forced` (the steady state in closed form), :mod:`flywheel.elastic.timedomain`
(solve_ivp: the check and the start-up); this module runs them in order (:func:`analyze`),
computing the natural frequencies once, and holds the result.

Units: SI; angles in radians; J in kg·m²; c in N·m/rad; damping in N·m·s/rad. numpy only at
import; scipy is imported inside the functions that use it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.elastic.chain import Chain, Drive, coefficients
from flywheel.elastic.forced import Steady, steady_state
from flywheel.elastic.modes import Modes, Node, mode_nodes, natural_frequencies
from flywheel.elastic.timedomain import (CHECK_FAST_PERIODS, MAX_FAST_PERIODS, History, check_work,
                                         explicit_steps, start_up_method,
                                         start_up,
                                         start_up_duration, steady_method, steady_run)
from flywheel.errors import InputError


@dataclass(frozen=True)
class Resonance:
    """omega_n : a torsional natural frequency [rad/s]; ratio = ω_forcing/ω_n [1];
    margin = |1 − ratio| [1] (0 at resonance)."""

    omega_n: float
    ratio: float
    margin: float


#: the notes' English text, as the results document states it (``AggregateResult.notes``)
NOTE_TEXT = {
    "radau": ("solve_ivp check: 5 forcing periods are {fast:.4g} periods of the highest natural "
              "frequency {f_top:.6g} Hz, more than the explicit method's {limit}: integrated with "
              "the implicit Radau method and the constant Jacobian, which follows the forced "
              "motion but damps that mode's own oscillation"),
    "lsoda": ("start-up: stiff (the fastest decay rate of the system {rho:.4g} 1/s, from the "
              "motor's slope or a damper): integrated with LSODA and the constant Jacobian, steps "
              "of at most 1/8 of the period of the highest natural frequency {f_top:.6g} Hz"),
    "cap_linear": ("start-up: integrated over {t_end:.4g} s = {limit} periods of the highest "
                   "natural frequency {f_top:.6g} Hz (the cap), not the default {wanted:.4g} s "
                   "(the longer of five time constants and 20 forcing periods); --t-end sets the "
                   "duration"),
    "cap_constant": ("start-up: integrated over {t_end:.4g} s = {limit} periods of the highest "
                     "natural frequency {f_top:.6g} Hz (the cap), not the default {wanted:.4g} s "
                     "(20 forcing periods); --t-end sets the duration"),
}


@dataclass(frozen=True)
class Note:
    """What the reader should know about how a time-domain run was bounded. kind : "radau" (the
    steady check integrated implicitly), "cap_linear" or "cap_constant" (the start-up capped at
    MAX_FAST_PERIODS periods of the highest natural frequency; by the motor's kind), "lsoda" (the
    start-up stiff, integrated by LSODA: rho [1/s]); values :
    the numbers it states, (name, value) pairs: fast [periods], f_top [Hz], limit [periods],
    t_end and wanted [s]."""

    kind: str
    values: tuple[tuple[str, float], ...]

    @property
    def text(self) -> str:
        """The note in English, as the results document has it."""
        return NOTE_TEXT[self.kind].format(**dict(self.values))


@dataclass(frozen=True)
class AggregateResult:
    """Everything :func:`analyze` finds, reduced to shaft I (SI units).

    chain : the rotors and connections; a : inertia coefficients a_ij [kg·m²]; c : stiffness
    coefficients c_ij [N·m/rad] (9.24–9.25); modes : natural frequencies [rad/s] and shapes;
    drive : the motor and load (None: natural frequencies only); steady : the closed-form steady
    state; resonance : the margin of each torsional mode; check : the solve_ivp run on the
    periodic orbit; check_twist_amplitude : its amplitude of the first twist [rad];
    check_delta : its δ of the motor and of the machine [1]; startup : the start-up run;
    startup_peak_moment : the largest |c·q2| during it [N·m]; startup_time : time to 95 % of the
    steady ω1 [s] (linear motor only, None if not reached); notes : what the reader should know
    about how the time-domain runs were bounded (:class:`Note`); nodes : the nodes of every
    torsional mode, in the order of modes.elastic (:class:`~flywheel.elastic.modes.Node`).
    """

    chain: Chain
    a: np.ndarray                          # a_ij [kg·m²]
    c: np.ndarray                          # c_ij [N·m/rad]
    modes: Modes
    drive: Drive | None = None
    steady: Steady | None = None
    resonance: tuple[Resonance, ...] = ()
    check: History | None = None
    check_twist_amplitude: float | None = None   # [rad]
    check_delta: tuple[float, float] | None = None   # (motor, machine) [1]
    startup: History | None = None
    startup_peak_moment: float | None = None     # [N·m]
    startup_time: float | None = None            # [s]
    notes: tuple[Note, ...] = ()
    nodes: tuple[tuple[Node, ...], ...] = ()

    def to_document(self, title: str = "", source: str = "") -> dict:
        """The results document, the JSON of ``flywheel aggregate --json``: SI units, reduced to
        shaft I.

        Keys of the contract: natural_frequencies_hz (ascending, the rigid-body 0 excluded),
        twist_amplitude [rad] (the first coupling, q2 of seed 003), elastic_moment_amplitude
        [N·m] (the amplitude of c·q2, the same as of the transmitted moment −c·q2), delta_motor,
        delta_machine; the last four are null without a motor. steady.elastic_moment_mean is the
        mean transmitted moment c·(φ_k − φ_(k+1)) = −c·q (positive, M_0·i31); steady.twist_mean is
        the mean of q (negative). notes: how the time-domain runs were bounded (empty if nothing
        to say). natural_frequencies_rpm: the same frequencies in vibrations per minute; modes:
        per torsional mode natural_hz, natural_rpm, natural_rad_s, shape (per rotor, largest 1)
        and nodes (shaft, between, fraction of its compliance, distance [m] from its first
        rotor; or a rotor that stands still); shafts: per shaft of the case between, gear_ratio,
        c (at its input speed) and c_reduced [N·m/rad], length and equivalent_length [m] at
        reference_diameter [m] and shear_modulus [Pa] (null without a geometry); fixed_ends:
        the names of the rotors fixed to the frame.
        """
        from flywheel.elastic.document import document
        from flywheel.io.serialize import to_json

        d: dict = {}
        if title:
            d["title"] = title
        if source:
            d["source"] = source
        d.update(to_json(document(self)))
        return d


def _amplitude(x: np.ndarray) -> float:
    return float((x.max() - x.min()) / 2.0)


def analyze(ch: Chain, drive: Drive | None = None, t_end: float | None = None,
            time_domain: bool = True, progress=None) -> AggregateResult:
    """Coefficients (9.24–9.25), natural frequencies and — with a drive — the closed-form steady
    state, the resonance margins, a solve_ivp check on the periodic orbit and the start-up. The
    natural frequencies are computed once here and handed to every step that needs them.

    Each explicit integration is estimated first and refused beyond MAX_STEPS steps
    (:func:`~flywheel.elastic.timedomain.check_work`; a ``t_end`` given is named as --t-end).
    ``progress(stage, fraction)``: a plain callable, stage "start-up", fractions 0 … 1."""
    a, c = coefficients(ch)
    modes = natural_frequencies(ch)
    nodes = tuple(mode_nodes(ch, x) for x in modes.elastic_shapes.T)
    if drive is None:
        return AggregateResult(ch, a, c, modes, nodes=nodes)
    if not ch.is_line:            # (cases/aggregate.py refuses such a case first)
        # library use only: no CLI input reaches this
        raise InputError("a motor and a load drive a free, unbranched chain; a branched system "
                         "or one fixed to the frame gives its natural frequencies and modes only")
    st = steady_state(ch, drive, modes)
    res = tuple(Resonance(float(wn), st.omega_forcing / wn, abs(1 - st.omega_forcing / wn))
                for wn in modes.elastic)
    if not time_domain:
        return AggregateResult(ch, a, c, modes, drive, st, res, nodes=nodes)
    notes = []
    f_top = modes.highest / (2 * math.pi)
    method, fast = steady_method(ch, st.omega_forcing, modes=modes)
    if method != "DOP853":
        notes.append(Note("radau", (("fast", fast), ("f_top", f_top),
                                    ("limit", CHECK_FAST_PERIODS))))
    if method == "DOP853":            # LSODA when stiff only by the motor or a damper
        method = start_up_method(ch, drive, 5 * 2 * math.pi / st.omega_forcing, modes)
        check_work(ch, drive, 5 * 2 * math.pi / st.omega_forcing, "steady check", modes=modes,
                   method=method)
    chk = steady_run(ch, drive, st, modes=modes, method=method)
    ch_twist = _amplitude(chk.twist[0])
    ch_delta = tuple(float(2 * _amplitude(chk.omega[k]) / st.omega_mean) for k in (0, -1))
    option = "" if t_end is None else "--t-end"
    if t_end is None:
        t_end, wanted = start_up_duration(ch, drive, modes)
        if t_end < wanted:
            notes.append(Note("cap_linear" if drive.kind == "linear" else "cap_constant",
                              (("t_end", t_end), ("limit", MAX_FAST_PERIODS), ("f_top", f_top),
                               ("wanted", wanted))))
    su_method = start_up_method(ch, drive, t_end, modes)
    check_work(ch, drive, t_end, "start-up", option, modes, su_method)
    if su_method != "DOP853":
        notes.append(Note("lsoda", (("rho", explicit_steps(ch, drive, t_end, modes)[1]),
                                    ("f_top", f_top))))
    su = start_up(ch, drive, t_end, modes=modes, method=su_method,
                  progress=None if progress is None else (lambda f: progress("start-up", f)))
    peak = float(np.max(np.abs(ch.c[0] * su.twist[0])))
    reached = np.nonzero(su.omega[0] >= 0.95 * st.omega_mean)[0]
    t95 = float(su.t[reached[0]]) if drive.kind == "linear" and len(reached) else None
    return AggregateResult(ch, a, c, modes, drive, st, res, chk, ch_twist, ch_delta, su, peak, t95,
                           tuple(notes), nodes)


__all__ = ["Resonance", "Note", "AggregateResult", "analyze"]
