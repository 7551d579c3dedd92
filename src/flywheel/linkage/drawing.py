"""What a drawing of the mechanism shows, worked out from the mechanism and its kinematics: which
points move and which are fixed pivots, which links turn, the sliders on fixed guides (and
their guides' directions) and on turning links, which points ride on each drawn link, each
slider's travel from its outer dead centre and the extent of the motion.

Computed once per run (:func:`describe`, called by the pipeline) and carried on the results
(:attr:`flywheel.dynamics.results.Results.drawing`), so the renderers (the kinematic scheme,
the animation, the positions plot, the velocity and acceleration plans) only read it. Pure
topology and geometry of the solved positions; no physics, no matplotlib.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Drawing:
    """The drawing description of a linkage.

    links : (link, its points) of every drawn link — the crank, each dyad's links, and the
        other points (centroids …) on the link that carries them (:func:`links_drawn`)
    members : ``links`` with every other joint that moves rigidly with the link added (the
        point of a rocker that drives the next dyad beyond its slider block)
    joints : the points of ``links``, each once, in order
    moving_points : points whose velocity or acceleration analogue is not identically zero
    fixed_points : the others (fixed pivots)
    turning_links : links other than the crank whose ω_q or ε_q is not identically zero
    guided_sliders : (slider link, its joint, guide direction [rad]) of every slider on a
        fixed guide
    moving_blocks : (slider link, its pivot point) of the sliders on turning links (RPR, кулиса)
    slider_travel : slider link → its joint's distance [m] along the guide from the dead centre
        farther from the crank pivot, at every grid node
    bounds : (x_min, y_min, x_max, y_max) [m] of every point over the cycle
    slider_analogues : slider link → (v_q [m/rad], a_q [m/rad²]) of its joint along the guide,
        signed: positive in the sense ``slider_travel`` grows (away from the outer dead
        centre), so v_q = dS/dφ and a_q = d²S/dφ² as the course differentiates S(φ)
    """

    links: tuple[tuple[str, tuple[str, ...]], ...]
    members: tuple[tuple[str, tuple[str, ...]], ...]
    joints: tuple[str, ...]
    moving_points: tuple[str, ...]
    fixed_points: tuple[str, ...]
    turning_links: tuple[str, ...]
    guided_sliders: tuple[tuple[str, str, float], ...]
    moving_blocks: tuple[tuple[str, str], ...]
    slider_travel: dict[str, np.ndarray]
    bounds: tuple[float, float, float, float]
    slider_analogues: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)

    @property
    def span(self) -> float:
        """The larger side [m] of the box holding every point over the cycle."""
        x0, y0, x1, y1 = self.bounds
        return max(x1 - x0, y1 - y0)


def links_drawn(mech) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """(link, its points) of every link of the kinematic scheme: the crank, each dyad's links,
    and the other points (centroids …) on the link that carries them."""
    drawn = [(mech.crank.name, [mech.crank.pivot, mech.crank.tip]
              + [pin.name for pin in mech.crank.pins])]
    for d in mech.dyads:
        if hasattr(d, "guide"):
            drawn.append((d.rod, [d.origin, d.joint]))
        elif hasattr(d, "rocker"):
            drawn.append((d.rocker, [d.pivot, d.origin]))
        else:
            drawn.append((d.link_a, [d.point_a, d.joint]))
            drawn.append((d.link_b, [d.point_b, d.joint]))
    for p in mech.points:               # centroids and other points drawn on their links
        for link, pts in drawn:
            if link == p.link and p.name not in pts:
                pts.append(p.name)
    return tuple((link, tuple(pts)) for link, pts in drawn)


def _moves(pm) -> bool:
    return bool(np.any(pm.v_q != 0) or np.any(pm.a_q != 0))


def _link_members(kin, links) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """``links`` with every other joint that moves rigidly with the link added: a point X rides
    on link L if X − P, turned back by L's angle θ, stays constant (P: L's first point)."""
    P, L = kin.points, kin.links
    joints = list(dict.fromkeys(p for _, pts in links for p in pts))
    allr = np.concatenate([pm.r for pm in P.values()])
    tol = 1e-9 * max(float(np.ptp(allr[:, 0])), float(np.ptp(allr[:, 1])), 1e-12)
    out = []
    for link, pts in links:
        members = list(pts)
        lm = L.get(link)
        if lm is not None and lm.theta is not None and pts:
            c, s = np.cos(lm.theta), np.sin(lm.theta)
            base = P[pts[0]].r
            for x in joints:
                if x in members:
                    continue
                rel = P[x].r - base
                local = np.stack([rel[:, 0] * c + rel[:, 1] * s, -rel[:, 0] * s + rel[:, 1] * c])
                if np.all(np.ptp(local, axis=1) <= tol):
                    members.append(x)
        out.append((link, tuple(members)))
    return tuple(out)


def _travel_sense(kin, joint: str, angle: float, fixed) -> tuple[np.ndarray, float]:
    """The unit vector along the guide in the sense the travel from the dead centre farther
    from the crank pivot grows, and that dead centre's coordinate along the guide [m]."""
    pm = kin.points[joint]
    u = np.array([math.cos(angle), math.sin(angle)])
    x = pm.r @ u
    pivot = kin.points[fixed[0]].r[0] if fixed else np.zeros(2)
    i_hi, i_lo = int(np.argmax(x)), int(np.argmin(x))
    far = i_hi if (np.linalg.norm(pm.r[i_hi] - pivot) >= np.linalg.norm(pm.r[i_lo] - pivot)) else i_lo
    return (-u if far == i_hi else u), float(x[far])


def _slider_travel(kin, joint: str, angle: float, fixed) -> np.ndarray:
    """Distance [m] along the guide from the dead centre farther from the crank pivot."""
    u = np.array([math.cos(angle), math.sin(angle)])
    _, x_far = _travel_sense(kin, joint, angle, fixed)
    return np.abs(kin.points[joint].r @ u - x_far)


def _slider_analogues(kin, joint: str, angle: float, fixed) -> tuple[np.ndarray, np.ndarray]:
    """(v_q, a_q) of the slider's joint projected on its guide's sense of growing travel:
    v_q = dS/dφ [m/rad], a_q = d²S/dφ² [m/rad²] (S: :func:`_slider_travel`; the projection of
    the analogue vectors on the guide, Артоболевский, ТММ, гл. 3: a slider moves along its
    guide, so the projection is the whole analogue with its sign)."""
    e, _ = _travel_sense(kin, joint, angle, fixed)
    pm = kin.points[joint]
    return pm.v_q @ e, pm.a_q @ e


def describe(mech, kin) -> Drawing:
    """The :class:`Drawing` of mechanism ``mech`` moving as ``kin`` (its solved kinematics)."""
    links = links_drawn(mech)
    drawn = {name for name, _ in links}
    moving = tuple(n for n, pm in kin.points.items() if _moves(pm))
    fixed = tuple(n for n, pm in kin.points.items() if not _moves(pm))
    crank = links[0][0] if links else None
    turning = tuple(n for n, lm in kin.links.items()
                    if n != crank and (np.any(lm.omega_q != 0) or np.any(lm.eps_q != 0)))
    guided = tuple((name, lm.ref, float(lm.theta[0])) for name, lm in kin.links.items()
                   if name not in drawn and not np.any(lm.omega_q != 0) and lm.theta is not None
                   and lm.ref in kin.points)
    blocks = tuple((name, lm.ref) for name, lm in kin.links.items()
                   if name not in drawn and np.any(lm.omega_q != 0) and lm.theta is not None
                   and lm.ref in kin.points)
    allr = np.concatenate([pm.r for pm in kin.points.values()])
    return Drawing(
        links=links, members=_link_members(kin, links),
        joints=tuple(dict.fromkeys(p for _, pts in links for p in pts)),
        moving_points=moving, fixed_points=fixed, turning_links=turning, guided_sliders=guided,
        moving_blocks=blocks,
        slider_travel={link: _slider_travel(kin, joint, angle, fixed)
                       for link, joint, angle in guided},
        bounds=(*(float(v) for v in allr.min(axis=0)), *(float(v) for v in allr.max(axis=0))),
        slider_analogues={link: _slider_analogues(kin, joint, angle, fixed)
                          for link, joint, angle in guided})
