"""Dead centres of sliders: where the slider's velocity analogue along its guide is zero.

Found on the grid by sign changes of v_q·u, then refined by Newton's method on the exact
analogues (x′ = v_q·u, x″ = a_q·u), so they do not depend on the grid size.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from flywheel.linkage.mechanism import RRP, Mechanism
from flywheel.linkage.solve import solve


@dataclass(frozen=True)
class DeadCentre:
    """phi [rad] in [0, 2π); x [m] along the guide; kind 'outer' (farther from the crank pivot)
    or 'inner'."""

    phi: float
    x: float
    kind: str


def slider_dyad(mech: Mechanism, slider: str) -> RRP:
    """The RRP dyad whose slider link is ``slider`` (KeyError if none)."""
    for d in mech.dyads:
        if isinstance(d, RRP) and d.slider == slider:
            return d
    raise KeyError(slider)


def guide_frame(d: RRP) -> tuple[np.ndarray, np.ndarray]:
    """Unit direction u of the guide and a point of the (offset) guide line [m]."""
    u = np.array([np.cos(d.guide.angle), np.sin(d.guide.angle)])
    nrm = np.array([-u[1], u[0]])
    return u, np.asarray(d.guide.through, float) + d.guide.offset * nrm


def dead_centres(mech: Mechanism, slider: str, n_grid: int = 721) -> list[DeadCentre]:
    """Dead centres of the slider link ``slider`` over one crank revolution, by angle.

    >>> import math
    >>> from flywheel.linkage.mechanism import Crank, Guide
    >>> m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, 0.0, 1),
    ...               (RRP("B", "A", "B", "2", 0.4, "3", Guide((0.0, 0.0), 0.0)),))
    >>> [(round(math.degrees(c.phi), 6), round(c.x, 6), c.kind) for c in dead_centres(m, "3")]
    [(0.0, 0.5, 'outer'), (180.0, 0.3, 'inner')]
    """
    d = slider_dyad(mech, slider)
    u, base = guide_frame(d)
    phi = np.linspace(0.0, 2 * np.pi, n_grid)
    k = solve(mech, phi)
    v = k.points[d.joint].v_q @ u
    # the closing node is φ = 0 again: take its value from there, so a dead centre at φ = 0,
    # where v is zero up to round-off of either sign at 0 and at 2π, is found whatever the signs
    v[-1] = v[0]
    idx = np.nonzero(np.sign(v[:-1]) != np.sign(v[1:]))[0]
    if idx.size == 0:   # a slider that never moves (driven from a fixed point) has none
        return []
    guesses = phi[idx] - v[idx] * (phi[idx + 1] - phi[idx]) / (v[idx + 1] - v[idx])
    roots = np.array(guesses, float)
    for _ in range(30):
        kk = solve(mech, roots)
        x1 = kk.points[d.joint].v_q @ u
        x2 = kk.points[d.joint].a_q @ u
        step = x1 / x2
        roots = roots - step
        if np.all(np.abs(step) < 1e-15):
            break
    roots = np.mod(roots, 2 * np.pi)
    roots[np.isclose(roots, 2 * np.pi, atol=1e-12, rtol=0)] = 0.0
    roots = np.sort(np.round(roots, 12))      # np.unique's values, without its import of numpy.ma
    roots = roots[np.concatenate(([True], roots[1:] != roots[:-1]))]
    kk = solve(mech, roots)
    r = kk.points[d.joint].r
    x = (r - base) @ u
    dist = np.linalg.norm(r - np.asarray(mech.crank.pivot_at), axis=1)
    far = np.argmax(dist)
    return [DeadCentre(float(p), float(xx), "outer" if abs(dist[i] - dist[far]) < 1e-9 else "inner")
            for i, (p, xx) in enumerate(zip(roots, x))]
