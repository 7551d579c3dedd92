"""Force analysis (кинетостатика): joint reactions, the balancing moment M_y, crank effort.

Design note. Pure functions on arrays (numpy only), vectorized over the φ grid: the loop runs
over links and Assur groups, never over grid points. The inputs are what the rest of the
package already has — a :class:`~flywheel.linkage.Mechanism`, its
:class:`~flywheel.linkage.Kinematics` (positions and analogues v_q = dr/dφ, a_q = d²r/dφ²,
θ, ω_q, ε_q), the crank's ω(φ), ε(φ) (the true motion, or constant ω and ε = 0 for a steady
one) and the loads (:class:`Loads`). Each link's loads — given forces and couples, weights,
d'Alembert's inertia force −m·a_S at S and couple −J_S·ε_i — are reduced to a resultant force
and a moment about the origin of the case's frame. The groups are then solved from the last
one back to the crank, each in closed form for the whole grid at once (a 2×2 system by
Cramer's rule for RRR and RRP, one division for RPR); a group hands the reactions it found at
its outer pairs, reversed, to the links that carry them, and the crank last gives its bearing
reaction and the balancing moment. Nothing here knows of case files, the pipeline or output.

Conventions (docs/forces.md):

* SI: m, kg, s, rad, N, N·m. Vectors are components in the case's frame (x, y).
* R_ij is the force [N] of link i on link j at their joint; the frame is link ``"0"``
  (:data:`FRAME`). Each joint is stored once, under the key ``"<point>:<i>-><j>"``
  (``"A:1->2"`` is the crank 1 acting on rod 2 at A); :meth:`ForceAnalysis.reaction` gives
  either direction (R_ji = −R_ij).
* Couples, angles, ω_q, ε_q are counter-clockwise positive. The balancing moment M_y is the
  couple [N·m] the drive applies to the crank, positive in the crank's direction of rotation
  (``Crank.direction`` = +1 ccw, −1 cw), so it compares directly with the driving moment M_D
  of the dynamics (a reduced moment is positive when it drives, design.md §2);
  ``balancing_moment_ccw`` = direction·M_y is the same couple counter-clockwise positive.
* A prismatic pair without friction carries a force normal to the slide and a couple: the
  force's signed size along the stated unit normal and its line of action, as an offset
  along the slide direction from the reference point (:class:`Slide`).
* True accelerations from the analogues: a = a_q·ω² + v_q·ε, ε_i = ε_q·ω² + ω_q·ε
  (design.md §2). The first group's inertia J_I (crank, shaft, flywheel) adds the couple
  −J_I·ε in the direction of rotation on the crank.
* A point shared by several links that a later group uses (a pin reused as a joint) is
  carried by one link: see :func:`carriers`.

Sources: the method of Assur groups and Zhukovsky's lever — И. И. Артоболевский, «Теория
механизмов и машин», 4-е изд., М.: Наука, 1988 (силовой расчёт механизмов; рычаг
Жуковского); the matrix (Newton–Euler) form the tests check against and the shaking force and
moment — R. L. Norton, «Design of Machinery», 5th ed., ch. 11 (dynamic force analysis); the
slider-crank quantities — R. S. Khurmi, J. K. Gupta, «Theory of Machines», ch. 15 (inertia
forces in reciprocating parts: piston effort, thrust in the rod and on the cylinder walls,
crank-pin effort, turning moment).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from flywheel.dynamics.reduction import link_inertia
from flywheel.errors import InputError, Notice
from flywheel.linkage.mechanism import RPR, RRP, RRR, Mechanism
from flywheel.linkage.solve import Kinematics

FRAME = "0"
"""Name of the frame (the fixed link) in reaction keys."""

_SINGULAR = 1e-9     # a group's determinant below this share of its scale: singular


# -- inputs -------------------------------------------------------------------------------------

@dataclass(frozen=True)
class LinkMass:
    """Mass data of a link: mass [kg] at the point ``centroid``, J_S [kg·m²] about it. Any
    object with these three attributes will do (the case's ``[links]`` entries)."""

    mass: float = 0.0
    J_S: float = 0.0
    centroid: str | None = None


@dataclass(frozen=True)
class PointForce:
    """A given force F [N] — an (N, 2) array on the grid or one (2,) vector — on link ``link``
    at the named point ``point``. ``on_frame``: its reaction acts on the frame (a gas force's
    on the cylinder head, a cutting force's on the work table); False for a force from
    outside the machine. Only the frame's shaking force and moment depend on it."""

    name: str
    link: str
    point: str
    F: Any
    on_frame: bool = True
    label: str = ""         # its short name (io.text.Text or a string; "": its name): F_<label>


@dataclass(frozen=True)
class Couple:
    """A given couple M [N·m] (counter-clockwise positive; an array on the grid or a number)
    on link ``link``; ``on_frame`` as for :class:`PointForce`."""

    name: str
    link: str
    M: Any
    on_frame: bool = True
    label: str = ""         # its short name (io.text.Text or a string; "": its name): M_<label>


@dataclass(frozen=True)
class Loads:
    """Everything that loads the links: ``masses`` (link name → :class:`LinkMass` or alike),
    point forces, couples, the gravity vector g [m/s²] (weights m·g at the centroids, from
    outside the machine) and J_first_group = J_I [kg·m²] on the crank shaft (0: no
    first-group couple)."""

    masses: Mapping[str, Any] = field(default_factory=dict)
    forces: tuple[PointForce, ...] = ()
    couples: tuple[Couple, ...] = ()
    gravity: tuple[float, float] = (0.0, 0.0)
    J_first_group: float = 0.0


# -- results ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class Reaction:
    """R_ij: the force [N] of link ``by`` (i) on link ``on`` (j) at ``joint``, components
    ``x``, ``y`` on the grid. For a prismatic pair ``joint`` is the reference point of the
    slide (see :class:`Slide`)."""

    joint: str
    by: str
    on: str
    x: np.ndarray
    y: np.ndarray

    @property
    def key(self) -> str:
        return f"{self.joint}:{self.by}->{self.on}"

    @property
    def magnitude(self) -> np.ndarray:
        """|R| [N]."""
        return np.hypot(self.x, self.y)

    @property
    def angle(self) -> np.ndarray:
        """Direction of R [rad] from +x, counter-clockwise, in (−π, π]."""
        return np.arctan2(self.y, self.x)

    @property
    def vector(self) -> np.ndarray:
        """(N, 2) components [N]."""
        return np.stack([self.x, self.y], axis=1)

    def reversed(self) -> "Reaction":
        """R_ji = −R_ij."""
        return Reaction(self.joint, self.on, self.by, -self.x, -self.y)


@dataclass(frozen=True)
class Slide:
    """A prismatic pair without friction: link ``by`` pushes link ``on`` with the force
    ``normal``·n [N] along the unit normal ``n`` (N, 2) of the slide, plus the couple
    ``couple`` [N·m] about the reference point ``point``: together, the force ``normal``·n
    along the line through point + ``offset``·t, t the slide direction (t × n = 1).
    ``offset`` [m] is NaN where the force is zero but the couple is not, 0 where both are."""

    point: str
    by: str
    on: str
    normal: np.ndarray
    n: np.ndarray
    couple: np.ndarray
    offset: np.ndarray


@dataclass(frozen=True)
class SliderCrank:
    """The textbook quantities of a slider-crank group (an RRP whose rod starts at the crank
    pin), on the grid (Khurmi & Gupta ch. 15; their symbols in brackets).

    piston_effort [F_P, N]: the resultant of the slider's own loads (gas force, weight, its
    inertia force −m·a, any force from later groups) along the line of stroke, positive
    towards the crank. side_thrust [F_N, N]: the slider's force on its guide (cylinder wall),
    signed along the guide's left normal (−sin α, cos α). rod_thrust [F_Q, N]: the slider's
    force on the rod at the gudgeon pin along the rod, B → A, positive when it compresses the
    rod (F_P/cos β for a massless rod). crank_pin_x, crank_pin_y [N]: the rod's force on the
    crank pin; crank_pin_tangential [F_T, N] its part along the pin's velocity (positive
    drives), crank_pin_radial [F_R, N] its part along the crank towards the shaft axis.
    turning_moment [T, N·m] = F_T·l1, in the direction of rotation.
    """

    slider: str
    rod: str
    joint: str
    piston_effort: np.ndarray
    side_thrust: np.ndarray
    rod_thrust: np.ndarray
    crank_pin_x: np.ndarray
    crank_pin_y: np.ndarray
    crank_pin_tangential: np.ndarray
    crank_pin_radial: np.ndarray
    turning_moment: np.ndarray


@dataclass(frozen=True)
class InertiaLoad:
    """d'Alembert's loads of a link: force −m·a_S [N] at ``point`` (x, y) and couple
    −J_S·ε_i [N·m] (counter-clockwise)."""

    link: str
    point: str | None
    x: np.ndarray
    y: np.ndarray
    couple: np.ndarray


@dataclass(frozen=True)
class ForceAnalysis:
    """The force analysis on the grid ``phi`` [rad] with the crank's ``omega`` [rad/s] and
    ``epsilon`` [rad/s²].

    joints: every reaction by key ``"<point>:<i>-><j>"`` (revolute and prismatic pairs);
    slides: the prismatic pairs' normal forces and lines of action, by the same keys;
    balancing_moment: M_y [N·m], in the direction of rotation; direction: the crank's +1/−1;
    crank_bearing_key: the key of R_01, the frame's force on the crank at its pivot;
    slider_crank: by slider name; inertia: d'Alembert's loads by link;
    first_group_couple: −J_I·ε on the crank [N·m], counter-clockwise (the balancing moment
    without it: :attr:`balancing_moment_groups`);
    shaking_force (N, 2) [N] and shaking_moment [N·m, ccw, about the crank pivot]: all that
    the mechanism puts on its frame — the forces of the moving links in the frame's joints
    and guides, the reactions of the given loads marked ``on_frame`` and of M_y (the drive
    sits on the frame); equal to −Σ m·a_S plus the loads from outside the machine (weights).
    """

    phi: np.ndarray
    omega: np.ndarray
    epsilon: np.ndarray
    joints: dict[str, Reaction]
    slides: dict[str, Slide]
    balancing_moment: np.ndarray
    direction: int
    crank_bearing_key: str
    slider_crank: dict[str, SliderCrank]
    inertia: dict[str, InertiaLoad]
    first_group_couple: np.ndarray
    shaking_force: np.ndarray
    shaking_moment: np.ndarray

    @property
    def balancing_moment_ccw(self) -> np.ndarray:
        """M_y as a counter-clockwise couple on the crank [N·m]."""
        return self.direction * self.balancing_moment

    @property
    def first_group_torque(self) -> np.ndarray:
        """The first group's inertia torque −J_I·ε [N·m], in the direction of rotation."""
        return self.direction * self.first_group_couple

    @property
    def balancing_moment_groups(self) -> np.ndarray:
        """M_y of the groups [N·m], in the direction of rotation: the moment the crank delivers
        to the Assur groups, without the first group's inertia couple. The crank's moment
        balance M_y + (−J_I·ε) − M_y,groups = 0 (Артоболевский, силовой расчёт начального
        звена) gives M_y,groups = M_y + (−J_I·ε) = M_y − J_I·ε: with the true motion M_y = M_D
        and M_y,groups varies over the cycle — what the flywheel smooths; with ε = 0 they are
        one. ``first_group_couple`` is ccw, so −J_I·ε in the direction of rotation is
        direction·first_group_couple."""
        return self.balancing_moment + self.first_group_torque

    @property
    def crank_bearing(self) -> Reaction:
        """R_01: the frame's force on the crank at its pivot [N]."""
        return self.joints[self.crank_bearing_key]

    @property
    def main_bearing_load(self) -> Reaction:
        """R_10: the crank's force on the frame at the main bearing [N]."""
        return self.crank_bearing.reversed()

    def reaction(self, by: str, on: str) -> Reaction:
        """R_ij, the force of link ``by`` on link ``on`` (KeyError if they share no pair)."""
        for r in self.joints.values():
            if r.by == by and r.on == on:
                return r
            if r.by == on and r.on == by:
                return r.reversed()
        raise KeyError(f"links {by} and {on} share no pair")


# -- the carriers of points -------------------------------------------------------------------

def carriers(mech: Mechanism) -> dict[str, str]:
    """The link [name] that carries each named point, :data:`FRAME` for fixed points.

    Fixed points and the crank's pivot: the frame; the crank pins: the crank; a point on a link
    (``LinkPoint``): its link. A dyad's own joint is shared by its two links; when a later
    group starts from it, the pin is taken to be carried by the RRR's ``link_a`` or by the
    RRP's slider (a pin on the piston): the later group's reaction acts on that link, and the
    shared pin passes it on. (The mechanism does not say which: a wanted field of
    :mod:`flywheel.linkage`.)
    """
    out = {name: FRAME for name in mech.ground}
    out[mech.crank.pivot] = FRAME
    out[mech.crank.tip] = mech.crank.name
    for pin in mech.crank.pins:          # the further pins of a multi-throw crankshaft
        out[pin.name] = mech.crank.name
    for p in mech.points:
        out[p.name] = p.link
    for d in mech.dyads:
        if isinstance(d, RRR):
            out[d.joint] = d.link_a
        elif isinstance(d, RRP):
            out[d.joint] = d.slider
    return out


def along_guide(mech: Mechanism, slider: str, F: Any) -> np.ndarray:
    """The (N, 2) vector [N] of a force of signed size F [N] along the guide of the RRP whose
    slider is ``slider``, positive along the guide's direction (cos α, sin α).

    >>> from flywheel.linkage import Crank, Guide, Mechanism, RRP
    >>> m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, 0.0),
    ...               (RRP("B", "A", "B", "2", 0.4, "3", Guide((0.0, 0.0), math.pi / 2)),))
    >>> along_guide(m, "3", np.array([2.0])).round(12)
    array([[0., 2.]])
    """
    for d in mech.dyads:
        if isinstance(d, RRP) and d.slider == slider:
            u = np.array([math.cos(d.guide.angle), math.sin(d.guide.angle)])
            return np.asarray(F, float)[:, None] * u
    raise KeyError(f"no RRP dyad has the slider {slider!r}")


# -- loads --------------------------------------------------------------------------------------

class _Resultant:
    """Resultant of the loads on one link: force (fx, fy) [N] and moment m [N·m] about the
    origin of the frame, on the grid."""

    __slots__ = ("fx", "fy", "m")

    def __init__(self, n: int) -> None:
        self.fx, self.fy, self.m = np.zeros(n), np.zeros(n), np.zeros(n)

    def force(self, fx, fy, x, y) -> None:
        self.fx = self.fx + fx
        self.fy = self.fy + fy
        self.m = self.m + (x * fy - y * fx)

    def couple(self, M) -> None:
        self.m = self.m + M

    def about(self, x, y) -> np.ndarray:
        """Moment about the point (x, y): M_P = M_O − r_P × F."""
        return self.m - (x * self.fy - y * self.fx)


def _grid_array(value, n: int, what: str) -> np.ndarray:
    a = np.asarray(value, float)
    if a.ndim == 0:
        return np.full(n, float(a))
    if a.shape != (n,):
        # library use only: no CLI input reaches this
        raise InputError(f"force analysis: {what} has shape {a.shape}, the grid has {n} points")
    return a


def _force_array(F, n: int, what: str) -> np.ndarray:
    a = np.asarray(F, float)
    if a.shape == (2,):
        return np.broadcast_to(a, (n, 2))
    if a.shape != (n, 2):
        # library use only: no CLI input reaches this
        raise InputError(f"force analysis: {what} has shape {a.shape}, expected (2,) or ({n}, 2)")
    return a


def _motion(kin: Kinematics, omega, eps) -> tuple[np.ndarray, np.ndarray]:
    n = kin.phi.size
    return _grid_array(omega, n, "omega"), _grid_array(eps, n, "epsilon")


def _check_names(kin: Kinematics, loads: Loads) -> None:
    def need(kind: str, name: str, table: dict, where: str) -> None:
        if name not in table:
            # library use only: no CLI input reaches this
            raise InputError(f"force analysis: {where}: no {kind} named {name!r} "
                             f"(allowed: {', '.join(sorted(table))})")

    for name, m in loads.masses.items():
        need("link", name, kin.links, "masses")
        if m.mass != 0 and m.centroid is None:
            # library use only: no CLI input reaches this
            raise InputError(f"force analysis: masses.{name}: a link with mass needs a centroid")
        if m.centroid is not None:
            need("point", m.centroid, kin.points, f"masses.{name}.centroid")
    for f in loads.forces:
        need("link", f.link, kin.links, f"forces.{f.name}.link")
        need("point", f.point, kin.points, f"forces.{f.name}.point")
    for c in loads.couples:
        need("link", c.link, kin.links, f"couples.{c.name}.link")


def _inertia(mech: Mechanism, kin: Kinematics, w: np.ndarray, e: np.ndarray,
             loads: Loads) -> dict[str, InertiaLoad]:
    """d'Alembert's loads: −m·a_S with a_S = a_qS·ω² + v_qS·ε, and −J_S·ε_i with
    ε_i = ε_q·ω² + ω_q·ε (design.md §9)."""
    w2 = w * w
    out = {}
    for name, m in loads.masses.items():
        L = kin.links[name]
        couple = -m.J_S * (L.eps_q * w2 + L.omega_q * e)
        if m.mass and m.centroid is not None:
            S = kin.points[m.centroid]
            ax = S.a_q[:, 0] * w2 + S.v_q[:, 0] * e
            ay = S.a_q[:, 1] * w2 + S.v_q[:, 1] * e
            out[name] = InertiaLoad(name, m.centroid, -m.mass * ax, -m.mass * ay, couple)
        else:
            z = np.zeros_like(w)
            out[name] = InertiaLoad(name, m.centroid, z, z, couple)
    return out


def _load_list(mech: Mechanism, kin: Kinematics, w: np.ndarray, e: np.ndarray, loads: Loads):
    """Every load on the moving links as (link, point, Fx, Fy, on_frame) and
    (link, M, on_frame): given forces and couples, weights, inertia forces and couples, the
    first-group couple. Weights and inertia loads have no reaction on the frame."""
    _check_names(kin, loads)
    if FRAME in kin.links:
        raise InputError(Notice.of(
            "run_link_named_frame", "force analysis: a link is named {frame!r}, the name of the "
            "frame in the reactions (allowed: any other name)", frame=FRAME))
    n = kin.phi.size
    inertia = _inertia(mech, kin, w, e, loads)
    g = np.asarray(loads.gravity, float)
    forces, couples = [], []
    for f in loads.forces:
        F = _force_array(f.F, n, f"forces.{f.name}.F")
        forces.append((f.link, f.point, F[:, 0], F[:, 1], f.on_frame))
    for name, m in loads.masses.items():
        if m.mass and m.centroid is not None and np.any(g != 0):
            forces.append((name, m.centroid, np.full(n, m.mass * g[0]), np.full(n, m.mass * g[1]),
                           False))
    for c in loads.couples:
        couples.append((c.link, _grid_array(c.M, n, f"couples.{c.name}.M"), c.on_frame))
    for name, il in inertia.items():
        if il.point is not None:
            forces.append((name, il.point, il.x, il.y, False))
        couples.append((name, il.couple, False))
    first = -loads.J_first_group * mech.crank.direction * e
    couples.append((mech.crank.name, first, False))
    return forces, couples, inertia, first


# -- the groups ---------------------------------------------------------------------------------

def _singular(bad: np.ndarray, phi: np.ndarray, what: str) -> None:
    if np.any(bad):
        deg = math.degrees(float(phi[np.argmax(bad)]))
        # library use only: no CLI input reaches this
        raise InputError(f"force analysis: {what} at crank angle φ = {deg:.2f}° (its reactions "
                         f"are indeterminate there: give a grid that avoids this angle)")


def _xy(kin: Kinematics, point: str) -> tuple[np.ndarray, np.ndarray]:
    r = kin.points[point].r
    return r[:, 0], r[:, 1]


class _Solver:
    """Holds the links' resultants and collects the reactions while the groups are solved
    from the last one back to the crank."""

    def __init__(self, mech: Mechanism, kin: Kinematics, res: dict[str, _Resultant]) -> None:
        self.mech, self.kin, self.res = mech, kin, res
        self.carrier = carriers(mech)
        self.joints: dict[str, Reaction] = {}
        self.slides: dict[str, Slide] = {}
        self.frame_forces: list[tuple] = []     # (x, y, Rx, Ry, couple): frame on a link
        self.slider_crank: dict[str, SliderCrank] = {}
        self.phi = kin.phi

    def _link(self, name: str) -> _Resultant:
        if name not in self.res:
            self.res[name] = _Resultant(self.phi.size)
        return self.res[name]

    def joint(self, point: str, by: str, on: str, Rx, Ry) -> None:
        """Record R_{by,on}, the force of ``by`` on ``on`` at ``point``."""
        r = Reaction(point, by, on, Rx, Ry)
        self.joints[r.key] = r

    def hand_back(self, point: str, on: str, Rx, Ry) -> None:
        """The carrier of ``point`` exerted (Rx, Ry) on link ``on`` at the point (a revolute
        pair): record it and load the carrier with the reverse."""
        by = self.carrier[point]
        self.joint(point, by, on, Rx, Ry)
        x, y = _xy(self.kin, point)
        if by == FRAME:
            self.frame_forces.append((x, y, Rx, Ry, None))
        else:
            self._link(by).force(-Rx, -Ry, x, y)

    # RRR ----------------------------------------------------------------------------------
    def rrr(self, d: RRR) -> None:
        """Links a (A–B) and b (C–B). Unknown: R_A (carrier of A on a), R_C (carrier of C on
        b). Moments of each link about B and the group's force balance:
        (A − B) × R_A = −M_a^B, (C − B) × R_A = M_b^B − (C − B) × (F_a + F_b),
        R_C = −R_A − F_a − F_b; at B, the force of a on b is R_A + F_a.
        Determinant (A − B) × (C − B): zero when the links are in line."""
        xa, ya = _xy(self.kin, d.point_a)
        xc, yc = _xy(self.kin, d.point_b)
        xb, yb = _xy(self.kin, d.joint)
        La, Lb = self._link(d.link_a), self._link(d.link_b)
        dax, day, dcx, dcy = xa - xb, ya - yb, xc - xb, yc - yb
        det = dax * dcy - day * dcx
        _singular(np.abs(det) <= _SINGULAR * d.length_a * d.length_b, self.phi,
                  f"group {d.name} (RRR, links {d.link_a}–{d.link_b}) is singular: the links "
                  f"are in line")
        Fx, Fy = La.fx + Lb.fx, La.fy + Lb.fy
        b1 = -La.about(xb, yb)
        b2 = Lb.about(xb, yb) - (dcx * Fy - dcy * Fx)
        Rx = (b1 * dcx - dax * b2) / det
        Ry = (dcy * b1 - day * b2) / det
        self.hand_back(d.point_a, d.link_a, Rx, Ry)
        self.hand_back(d.point_b, d.link_b, -Rx - Fx, -Ry - Fy)
        self.joint(d.joint, d.link_a, d.link_b, Rx + La.fx, Ry + La.fy)

    # RRP ----------------------------------------------------------------------------------
    def rrp(self, d: RRP) -> None:
        """Rod r (A–B), slider s at B on the fixed guide (direction u, left normal n).
        Unknown: R_A (carrier of A on r) and the guide's normal force N along n.
        The group's forces along u and the rod's moment about B:
        u·R_A = −u·(F_r + F_s), (A − B) × R_A = −M_r^B (determinant u·(A − B): zero with
        the rod perpendicular to the guide); N = −n·(R_A + F_r + F_s); the rod's force on the
        slider at B is R_A + F_r; the guide's couple about B is −M_s^B."""
        kin = self.kin
        xa, ya = _xy(kin, d.origin)
        xb, yb = _xy(kin, d.joint)
        Lr, Ls = self._link(d.rod), self._link(d.slider)
        ux, uy = math.cos(d.guide.angle), math.sin(d.guide.angle)
        nx, ny = -uy, ux
        dx, dy = xa - xb, ya - yb
        det = ux * dx + uy * dy
        _singular(np.abs(det) <= _SINGULAR * d.rod_length, self.phi,
                  f"group {d.name} (RRP, rod {d.rod}) is singular: the rod is perpendicular "
                  f"to the guide")
        Fx, Fy = Lr.fx + Ls.fx, Lr.fy + Ls.fy
        b1 = -(ux * Fx + uy * Fy)
        b2 = -Lr.about(xb, yb)
        Rx = (b1 * dx - uy * b2) / det
        Ry = (ux * b2 + dy * b1) / det
        N = -(nx * (Rx + Fx) + ny * (Ry + Fy))
        C = -Ls.about(xb, yb)
        n_pts = self.phi.size
        nvec = np.broadcast_to(np.array([nx, ny]), (n_pts, 2))
        slide = Slide(d.joint, FRAME, d.slider, N, nvec, C, _offset(C, N))
        Nx, Ny = N * nx, N * ny
        self.joints[f"{d.joint}:{FRAME}->{d.slider}"] = Reaction(d.joint, FRAME, d.slider, Nx, Ny)
        self.slides[f"{d.joint}:{FRAME}->{d.slider}"] = slide
        self.frame_forces.append((xb, yb, Nx, Ny, C))
        self.hand_back(d.origin, d.rod, Rx, Ry)
        Qx, Qy = Rx + Lr.fx, Ry + Lr.fy           # rod on slider at B
        self.joint(d.joint, d.rod, d.slider, Qx, Qy)
        c = self.mech.crank
        if d.origin == c.tip:
            self.slider_crank[d.slider] = _slider_crank(
                d, kin, c, (ux, uy), Ls, N, Qx, Qy, Rx, Ry)

    # RPR ----------------------------------------------------------------------------------
    def rpr(self, d: RPR) -> None:
        """Block k pivoted at A slides along rocker q, which turns about P; slide direction
        u = (cos θ, sin θ), normal n = (−sin θ, cos θ), s = (A − P)·u. Unknown: R_A (carrier
        of A on k), the rocker's force Q·n on the block with its couple C about A, R_P
        (carrier of P on q). The block's moment about A: C = −M_k^A; the rocker's moment
        about P: M_q^P − Q·s − C = 0, so Q = (M_q^P + M_k^A)/s (zero s: the block on the
        pivot); R_A = −Q·n − F_k, R_P = Q·n − F_q."""
        kin = self.kin
        xa, ya = _xy(kin, d.origin)
        xp, yp = _xy(kin, d.pivot)
        Lk, Lq = self._link(d.slider), self._link(d.rocker)
        th = kin.links[d.rocker].theta
        ux, uy = np.cos(th), np.sin(th)
        nx, ny = -uy, ux
        s = (xa - xp) * ux + (ya - yp) * uy
        scale = float(np.max(np.hypot(xa - xp, ya - yp)))
        _singular(np.abs(s) <= _SINGULAR * scale, self.phi,
                  f"group {d.name} (RPR, rocker {d.rocker}) is singular: the block is on the "
                  f"rocker's pivot")
        C = -Lk.about(xa, ya)
        Q = (Lq.about(xp, yp) + Lk.about(xa, ya)) / s
        key = f"{d.origin}:{d.rocker}->{d.slider}"
        self.joints[key] = Reaction(d.origin, d.rocker, d.slider, Q * nx, Q * ny)
        self.slides[key] = Slide(d.origin, d.rocker, d.slider, Q, np.stack([nx, ny], axis=1),
                                 C, _offset(C, Q))
        # the block's action on the rocker: −Q·n at A and the couple −C
        Lq.force(-Q * nx, -Q * ny, xa, ya)
        Lq.couple(-C)
        Lk.force(Q * nx, Q * ny, xa, ya)
        Lk.couple(C)
        self.hand_back(d.origin, d.slider, -Lk.fx, -Lk.fy)
        self.hand_back(d.pivot, d.rocker, -Lq.fx, -Lq.fy)

    # crank --------------------------------------------------------------------------------
    def crank(self) -> tuple[np.ndarray, str]:
        """R_01 = −F_1 (force balance); M_y, ccw, = −M_1^O (moment balance about O)."""
        c = self.mech.crank
        L1 = self._link(c.name)
        xo, yo = _xy(self.kin, c.pivot)
        self.hand_back(c.pivot, c.name, -L1.fx, -L1.fy)
        return -L1.about(xo, yo), f"{c.pivot}:{FRAME}->{c.name}"


def _offset(C: np.ndarray, N: np.ndarray) -> np.ndarray:
    """Line of action of a slide's force: offset h = C/N [m] (C: couple about the reference
    point); 0 where C = N = 0, NaN where only N = 0."""
    out = np.where(C == 0, 0.0, np.nan)
    np.divide(C, N, out=out, where=N != 0)
    return out


def _slider_crank(d: RRP, kin: Kinematics, c, u, Ls: _Resultant, N, Qx, Qy, Rx, Ry) -> SliderCrank:
    """The textbook quantities (Khurmi & Gupta ch. 15) from the group's reactions: the line of
    stroke w = ±u pointing from B towards the crank axis, piston effort F_P = F_s·w (F_s: the
    slider's own loads), side thrust −N, rod thrust −(rod on slider)·(A − B)/|A − B| (the
    slider's force on the rod along B → A); crank-pin effort −R_A (R_A: the crank on the rod)
    along the pin's velocity direction t = direction·(−sin θ1, cos θ1) and along A → O;
    T = F_T·l1."""
    xa, ya = _xy(kin, d.origin)
    xb, yb = _xy(kin, d.joint)
    xo, yo = _xy(kin, c.pivot)
    ux, uy = u
    sgn = -np.sign((xb - xo) * ux + (yb - yo) * uy)      # w = sgn·u points from B to the axis
    effort = sgn * (Ls.fx * ux + Ls.fy * uy)
    lx, ly = xa - xb, ya - yb
    rod_len = np.hypot(lx, ly)
    rod_thrust = -(Qx * lx + Qy * ly) / rod_len
    px, py = -Rx, -Ry                                    # rod on crank at A
    cx, cy = (xa - xo) / c.length, (ya - yo) / c.length  # (cos θ1, sin θ1)
    tangential = c.direction * (-px * cy + py * cx)      # along direction·(−sin θ1, cos θ1)
    radial = -(px * cx + py * cy)                        # along A → O
    return SliderCrank(d.slider, d.rod, d.joint, effort, -N, rod_thrust, px, py, tangential,
                       radial, tangential * c.length)


# -- the whole mechanism --------------------------------------------------------------------------

def kinetostatics(mech: Mechanism, kin: Kinematics, omega, epsilon, loads: Loads) -> ForceAnalysis:
    """Joint reactions and the balancing moment by Assur groups, last group first.

    mech, kin: the mechanism and :func:`flywheel.linkage.solve` of it on the grid; omega
    [rad/s], epsilon [rad/s²]: the crank's speed and acceleration on the grid (arrays, or
    numbers for a steady motion); loads: :class:`Loads`. Raises InputError naming the group
    and the crank angle where a group's system is singular.

    A massless slider-crank turning uniformly (crank 1 m at 90°, rod 2 m at 30° to the guide)
    with a 10 N force pushing the piston towards the crank: the force drives the crank with
    10 N·m, so the balancing moment is −10 N·m; the rod thrust is 10/cos 30°:

    >>> from flywheel.linkage import Crank, Guide, Mechanism, RRP, solve
    >>> m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 1.0, 0.0),
    ...               (RRP("B", "A", "B", "2", 2.0, "3", Guide((0.0, 0.0), 0.0)),))
    >>> k = solve(m, np.radians([90.0]))
    >>> P = PointForce("P", "3", "B", np.array([-10.0, 0.0]))   # pushes the piston to the crank
    >>> fa = kinetostatics(m, k, 1.0, 0.0, Loads(forces=(P,)))
    >>> fa.balancing_moment.round(9), fa.slider_crank["3"].rod_thrust.round(6)
    (array([-10.]), array([11.547005]))
    """
    w, e = _motion(kin, omega, epsilon)
    n = kin.phi.size
    forces, couples, inertia, first = _load_list(mech, kin, w, e, loads)
    res: dict[str, _Resultant] = {}
    frame_loads = []                  # reactions of given loads on the frame: (x, y, Fx, Fy)
    frame_couples = []
    for link, point, fx, fy, on_frame in forces:
        x, y = _xy(kin, point)
        if link not in res:
            res[link] = _Resultant(n)
        res[link].force(fx, fy, x, y)
        if on_frame:
            frame_loads.append((x, y, fx, fy))
    for link, M, on_frame in couples:
        if link not in res:
            res[link] = _Resultant(n)
        res[link].couple(M)
        if on_frame:
            frame_couples.append(M)
    solver = _Solver(mech, kin, res)
    for d in reversed(mech.dyads):
        {RRR: solver.rrr, RRP: solver.rrp, RPR: solver.rpr}[type(d)](d)
    My_ccw, bearing = solver.crank()

    # the frame: forces of the moving links in its pairs, reactions of the given loads, the drive
    xo, yo = _xy(kin, mech.crank.pivot)
    Sx, Sy, Sm = np.zeros(n), np.zeros(n), -My_ccw
    for x, y, Rx, Ry, C in solver.frame_forces:      # the frame exerts R (and C) on a link
        Sx, Sy = Sx - Rx, Sy - Ry
        Sm = Sm - ((x - xo) * Ry - (y - yo) * Rx)
        if C is not None:
            Sm = Sm - C
    for x, y, fx, fy in frame_loads:
        Sx, Sy = Sx - fx, Sy - fy
        Sm = Sm - ((x - xo) * fy - (y - yo) * fx)
    for M in frame_couples:
        Sm = Sm - M
    d = mech.crank.direction
    return ForceAnalysis(kin.phi, w, e, solver.joints, solver.slides, d * My_ccw, d, bearing,
                         solver.slider_crank, inertia, first, np.stack([Sx, Sy], axis=1), Sm)


def zhukovsky_moment(mech: Mechanism, kin: Kinematics, omega, epsilon, loads: Loads) -> np.ndarray:
    """M_y [N·m, in the direction of rotation] by Zhukovsky's lever (рычаг Жуковского;
    Артоболевский): the velocity plan turned 90° clockwise about its pole is a rigid lever
    in equilibrium under every load, inertia loads included, moved to the turned image of
    its point. The turned image of v_q is (v_qy, −v_qx), whose moment of F about the pole is
    F·v_q; a couple M on link i is a pair of forces on two of its points and gives M·ω_qi.
    So Σ F·v_q + Σ M·ω_q + M_y = 0 (the crank's ω_q is its direction, M_y·direction·direction
    = M_y), per unit of ω: the plan of analogues stands for the plan of velocities."""
    w, e = _motion(kin, omega, epsilon)
    forces, couples, _, _ = _load_list(mech, kin, w, e, loads)
    total = np.zeros(kin.phi.size)
    for link, point, fx, fy, _ in forces:
        v = kin.points[point].v_q
        px, py = v[:, 1], -v[:, 0]                 # the plan turned 90° clockwise
        total = total + (px * fy - py * fx)        # moment about the pole
    for link, M, _ in couples:
        total = total + M * kin.links[link].omega_q
    return -total


def power_balance_moment(mech: Mechanism, kin: Kinematics, omega, epsilon, loads: Loads
                         ) -> np.ndarray:
    """M_y [N·m, in the direction of rotation] from the power balance with the kinetic energy
    instead of inertia forces: the power of M_y and of the given loads changes the kinetic
    energy, M_y·ω + Σ F·v_q·ω + Σ M·ω_q·ω = dT/dt = J·ω·ε + ½·J′·ω³, with the reduced inertia
    of every link and of the first group J = J_I + Σ (m·v_qS² + J_S·ω_q²) and J′ = dJ/dφ
    (reduction.link_inertia; design.md §2). Divided by ω:
    M_y = J·ε + ½·J′·ω² − Σ F·v_q − Σ M·ω_q (given loads and weights only)."""
    w, e = _motion(kin, omega, epsilon)
    _check_names(kin, loads)
    n = kin.phi.size
    J = np.full(n, float(loads.J_first_group))
    dJ = np.zeros(n)
    for name, m in loads.masses.items():
        L = kin.links[name]
        if m.mass and m.centroid is not None:
            S = kin.points[m.centroid]
            v, a = S.v_q, S.a_q
        else:
            v = a = np.zeros((n, 2))
        Ji, dJi = link_inertia(m.mass, m.J_S, v, a, L.omega_q, L.eps_q)
        J, dJ = J + Ji, dJ + dJi
    given = np.zeros(n)
    for f in loads.forces:
        F = _force_array(f.F, n, f"forces.{f.name}.F")
        given = given + np.einsum("ij,ij->i", F, kin.points[f.point].v_q)
    g = np.asarray(loads.gravity, float)
    for name, m in loads.masses.items():
        if m.mass and m.centroid is not None:
            given = given + m.mass * (kin.points[m.centroid].v_q @ g)
    for c in loads.couples:
        given = given + _grid_array(c.M, n, f"couples.{c.name}.M") * kin.links[c.link].omega_q
    return J * e + 0.5 * dJ * w * w - given


def closure(fa: ForceAnalysis, M_D: float) -> float:
    """The closure of a force analysis, :func:`closure_of` its M_y and first-group couple."""
    return closure_of(fa.balancing_moment, M_D, fa.first_group_couple)[0]


def closure_of(M_y: np.ndarray, M_D: float, first_group_couple: np.ndarray) -> tuple[float, str]:
    """The largest relative deviation of M_y [N·m] from the constant moment M_D [N·m] of the
    dynamics over the grid, max |M_y − M_D| / |M_D|, and what it is relative to ("M_D").
    With the true motion and the first-group couple on the crank, M_y = M_D at every φ — the
    equation of motion J·ε + ½·J′·ω² = M_D + M_C read backwards (design.md §9) — so this is
    round-off. A machine whose loads do no net work has M_D = 0: then the deviation is taken
    relative to the largest first-group couple |J_I·ε| [N·m] (what M_y = 0 balances;
    "J_I·ε"), or returned as is ("absolute")."""
    dev = float(np.max(np.abs(M_y - M_D)))
    if M_D != 0:
        return dev / abs(M_D), "M_D"
    scale = float(np.max(np.abs(first_group_couple)))
    return (dev / scale, "J_I·ε") if scale > 0 else (dev, "absolute")
