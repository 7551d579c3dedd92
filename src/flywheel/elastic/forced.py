"""The periodic steady state of the linear aggregate in closed form (seed 003, eqs. 9.20, 9.24).

Both motor models are linear in ω and the forcing is a sine of time, so the system is linear: its
steady state is a constant mean speed, a static twist that carries the mean torque, and a harmonic
response from the dynamic stiffness K − ω²·M + i·ω·C. Units: SI; angles in rad.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.elastic.chain import Chain, Drive
from flywheel.elastic.modes import RESONANCE_TOL, Modes, natural_frequencies, resonant_mode
from flywheel.errors import InputError, Notice


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
        try:
            y = np.linalg.solve(A / scale, F) / scale
        except np.linalg.LinAlgError:     # ω²·J underflows to 0 (a forcing frequency ≈ 0)
            y = np.full(n, np.nan, dtype=complex)
    t = y[1:]
    X = y[0] + np.concatenate([[0.0], np.cumsum(t)])
    return X, t


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
            raise InputError(Notice.of(
                "ag_resonance", "the forcing frequency {w:.6g} rad/s ({hz:.6g} Hz) equals the "
                "natural frequency {wn:.6g} rad/s of torsional mode {mode} (within {tol:g}) and "
                "nothing damps it: the steady amplitude is unbounded (give a coupling damping, a "
                "linear motor characteristic, or change the speed)", w=w, hz=w / (2 * math.pi),
                wn=wn, mode=k + 1, tol=RESONANCE_TOL))
        X, t = _harmonic(ch, drive, w)
        if not (np.all(np.isfinite(X)) and np.all(np.isfinite(t))):
            raise InputError(Notice.of(
                "ag_amplitudes_not_finite", "the steady amplitudes are not finite at the forcing "
                "frequency {w:.6g} rad/s: the harmonic solution overflows double precision", w=w))
    twist_mean = -drive.M0 / ch.c
    theta = np.concatenate([[0.0], np.cumsum(twist_mean)])
    twist_amp = np.abs(t)
    omega_amp = w * np.abs(X)
    swing = int(np.argmax(omega_amp))
    if omega_amp[swing] >= omega_s:
        raise InputError(_reversal_message(ch, drive, modes, w, omega_s, X, swing))
    return Steady(omega_s, w, X, theta, twist_mean, twist_amp, np.full(len(ch.c), drive.M0),
                  ch.c * twist_amp, omega_amp, 2.0 * omega_amp / omega_s)


def _reversal_message(ch, drive, modes, w, omega_s, X, k) -> Notice:
    amp = float(w * abs(X[k]))
    rigid = float(w * abs(ch.J @ X) / ch.J.sum())   # speed swing of the centre of inertia
    tail = ("so it would stop and turn backwards every period: there is no steady run of this "
            "model (raise the speed, add inertia or a flywheel, or lower M_amplitude)")
    if rigid >= 0.5 * amp and len(modes.elastic) and w < modes.elastic[0]:
        held = ("which a constant-torque motor does not hold" if drive.slope == 0
                else "which the motor characteristic hardly holds")
        return Notice.of(
            "ag_reversal_rigid", "the forcing frequency {w:.6g} rad/s is far below the lowest "
            "natural frequency {wn:.6g} rad/s, so the load swings the whole machine as a rigid "
            "body (the ω = 0 mode, {held}): the speed would vary by ±{amp:.6g} rad/s about the "
            "mean {mean:.6g} rad/s, {tail}", w=w, wn=float(modes.elastic[0]),
            constant=drive.slope == 0, amp=amp, mean=omega_s, held=held, tail=tail)
    return Notice.of(
        "ag_reversal_rotor", "the speed of rotor {name} would vary by ±{amp:.6g} rad/s about the "
        "mean {mean:.6g} rad/s (δ = {delta:.4g}), {tail}", name=ch.names[k], amp=amp, mean=omega_s,
        delta=2 * amp / omega_s, tail=tail)


def forced_twist_two_mass(J1: float, J2: float, c: float, amplitude: float, w: float) -> float:
    """Undamped steady twist amplitude of the two-mass model, the motor a constant torque, the
    force M̃·sin(ω·t) on the second mass: |q2| = M̃/(J2·|ω² − ω_n²|), ω_n² = c·(J1 + J2)/(J1·J2)
    (from Cramer's rule on (K − ω²M)·X = F; ω ≠ ω_n).

    >>> forced_twist_two_mass(1.0, 1.0, 2.0, 1.0, 1.0)
    0.3333333333333333
    """
    wn2 = c * (J1 + J2) / (J1 * J2)
    return amplitude / (J2 * abs(w * w - wn2))


__all__ = ["Steady", "steady_state", "forced_twist_two_mass"]
