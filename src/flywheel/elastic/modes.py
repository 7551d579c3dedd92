"""Natural frequencies and mode shapes of the rotor chain, K·x = ω²·M·x, and the resonance test.

A free chain has one rigid-body mode (ω = 0) and N − 1 torsional modes (W.T. Thomson, *Theory of
Vibration with Applications*, ch. "Systems with two or more degrees of freedom"); the seed's
two-mass model (seed 003, Ефанов ch. 9) has ω = √(c·(J1 + J2)/(J1·J2)). Computed once per chain
(:func:`natural_frequencies`) and handed to everything that needs them. scipy is imported inside
the function that uses it.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.elastic.chain import Chain, Drive, damping_matrix, mass_matrix, stiffness_matrix
from flywheel.errors import InputError, Notice

#: relative tolerance under which an eigenvalue counts as the rigid-body mode
RIGID_TOL = 1e-9
#: resonance: |ω − ω_n|/ω_n below this for a mode whose damping ratio is below it too (the
#: dynamic magnification would exceed about 1/(2·√2·RESONANCE_TOL) ≈ 3.5·10⁵)
RESONANCE_TOL = 1e-6


def two_mass_frequency(J1: float, J2: float, c: float) -> float:
    """Natural frequency of the two-mass torsional system [rad/s]:
    ω = √(c·(J1 + J2)/(J1·J2)) (the coupling's mode of the seed's model).

    >>> round(two_mass_frequency(1.0, 1.0, 2.0), 12)
    2.0
    """
    return math.sqrt(c * (J1 + J2) / (J1 * J2))


@dataclass(frozen=True)
class Modes:
    """omega : natural frequencies [rad/s], ascending, the rigid-body 0 first (a free system);
    shapes : the mode shapes in absolute angles (columns, largest component 1); rigid : the
    number of rigid-body modes, 1 for a free system, 0 for one held by a shaft fixed to the
    frame."""

    omega: np.ndarray
    shapes: np.ndarray
    rigid: int = 1

    @property
    def elastic(self) -> np.ndarray:
        """The natural frequencies without the rigid-body mode [rad/s]."""
        return self.omega[self.rigid:]

    @property
    def elastic_shapes(self) -> np.ndarray:
        """The shapes of the torsional modes (columns, largest component 1)."""
        return self.shapes[:, self.rigid:]

    @property
    def highest(self) -> float:
        """The highest natural frequency [rad/s]: it sets the explicit integrator's step."""
        return float(self.omega[-1])


def natural_frequencies(ch: Chain) -> Modes:
    """Solve K·x = ω²·M·x (scipy.linalg.eigh). A free chain has exactly one rigid-body mode,
    ω = 0 (round-off set to zero), and N − 1 torsional modes; a system held by a shaft fixed to
    the frame (K with the fixed shafts' stiffness on its diagonal) has N torsional modes and no
    rigid one (its eigenvalues are all kept, only a negative round-off is clipped to 0).

    >>> from flywheel.elastic.chain import chain
    >>> m = natural_frequencies(chain([1.0, 1.0], [2.0]))
    >>> [round(float(w), 9) for w in m.omega]
    [0.0, 2.0]
    """
    from scipy.linalg import eigh

    with np.errstate(all="ignore"):
        K, M = stiffness_matrix(ch), mass_matrix(ch)     # K sums the stiffnesses: it may overflow
        finite = bool(np.all(np.isfinite(K)) and np.all(np.isfinite(M)))
        if finite:
            lam, vec = eigh(K, M)
    if not (finite and np.all(np.isfinite(lam)) and np.all(np.isfinite(vec))):
        c_top, J_low = float(np.max(ch.c)), float(np.min(ch.J))
        ratio = c_top / J_low
        raise InputError(Notice.of(
            "ag_eigen_not_finite", "the natural frequencies are not finite: the eigenproblem K·x = "
            "ω²·M·x overflows double precision (stiffness up to {c:g} N·m/rad against inertia down "
            "to {J:g} kg·m², c/J = {ratio:g} 1/s²)", c=c_top, J=J_low, ratio=ratio))
    if not ch.fixed:
        scale = max(abs(lam[-1]), 1e-300)
        lam = np.where(np.abs(lam) < RIGID_TOL * scale, 0.0, lam)
    omega = np.sqrt(np.clip(lam, 0.0, None))
    idx = np.argmax(np.abs(vec), axis=0)
    shapes = vec / vec[idx, np.arange(vec.shape[1])]
    return Modes(omega, shapes, 0 if ch.fixed else 1)


#: a rotor whose amplitude is below this (the largest being 1) stands still in that mode
NODE_TOL = 1e-9


@dataclass(frozen=True)
class Node:
    """A point that stands still in a torsional mode. On a shaft: ``shaft`` (its index in the
    case), ``between`` (its from and to rotors; the frame's name at a fixed end), ``fraction`` of
    its compliance from the ``from`` end [1] and ``distance`` from that end [m] (None when the
    shaft has no length, only a stiffness); or a rotor itself: ``rotor`` its name."""

    shaft: int | None = None
    between: tuple[str, str] | None = None
    fraction: float | None = None
    distance: float | None = None
    rotor: str | None = None


def mode_nodes(ch: Chain, shape: np.ndarray) -> tuple[Node, ...]:
    """The nodes of one mode shape (absolute angles, largest 1), in the order of the case's
    shafts: the twist grows linearly along a shaft's compliance, so between two rotors whose
    amplitudes x_from, x_to have opposite signs the node lies at the fraction
    x_from/(x_from − x_to) of the compliance (Khurmi & Gupta ch. 24: the node divides the shaft
    so that each part, with its rotor, vibrates at the system's frequency; for two rotors
    l_1 = L·J_2/(J_1 + J_2)). A fixed end is a node of every mode; a rotor that stands still
    (|x| < NODE_TOL) is one too. Needs the chain's ``lines``; none: no nodes.
    """
    out: list[Node] = []
    still = {r for r in range(ch.n) if abs(shape[r]) < NODE_TOL}
    for line in ch.lines:
        i, j = line.ends
        if i < 0 or j < 0:
            frac = 0.0 if i < 0 else 1.0
            out.append(Node(line.index, line.names, frac, line.position(frac)))
            continue
        xi, xj = float(shape[i]), float(shape[j])
        if i in still or j in still or not xi * xj < 0:
            continue
        frac = xi / (xi - xj)
        out.append(Node(line.index, line.names, frac, line.position(frac)))
    out.extend(Node(rotor=ch.names[r]) for r in sorted(still))
    return tuple(out)


def resonant_mode(ch: Chain, drive: Drive, modes: Modes, w: float) -> int | None:
    """Index (into modes.elastic) of a torsional mode the forcing ω sits on with nothing to damp
    it: |ω − ω_n|/ω_n < RESONANCE_TOL and the mode's damping ratio
    ζ = xᵀ·C·x/(2·ω_n·xᵀ·M·x) < RESONANCE_TOL (C: the couplings and the motor's slope). None if
    there is no such mode. The rigid-body mode (ω_n = 0) is never a resonance: ω > 0.

    >>> from flywheel.elastic.chain import chain
    >>> ch = chain([1.0, 1.0], [2.0])
    >>> d = Drive("constant", 0.0, 1.0, 1.0, omega_nominal=2.0)
    >>> resonant_mode(ch, d, natural_frequencies(ch), 2.0), resonant_mode(ch, d, natural_frequencies(ch), 1.9)
    (0, None)
    """
    M, C = mass_matrix(ch), damping_matrix(ch, drive.slope)
    for k, wn in enumerate(modes.elastic):
        if not wn > 0:
            continue
        x = modes.shapes[:, k + modes.rigid]
        zeta = float(x @ C @ x) / (2.0 * wn * float(x @ M @ x))
        if abs(w - wn) / wn < RESONANCE_TOL and zeta < RESONANCE_TOL:
            return k
    return None


__all__ = ["RIGID_TOL", "RESONANCE_TOL", "NODE_TOL", "Modes", "Node", "natural_frequencies",
           "mode_nodes", "two_mass_frequency", "resonant_mode"]
