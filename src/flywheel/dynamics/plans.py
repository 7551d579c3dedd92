"""The plans a student draws by hand at one crank position: the velocity plan, the
acceleration plan, the force polygon of each Assur group and Zhukovsky's lever, each with the
scale of the drawing (μ_v (m/s)/mm, μ_a (m/s²)/mm, μ_F N/mm).

Design note. Pure functions (numpy only) on what the run already has at grid node i: the
mechanism and its kinematics (positions, analogues v_q, a_q, ω_q, ε_q), the force analysis
(:class:`~flywheel.dynamics.forces.ForceAnalysis`: the crank's ω, ε of its motion, the
reactions, d'Alembert's loads) and the loads (:class:`~flywheel.dynamics.forces.Loads`). The
plans are built the way the course builds them — by the vector equations of each group from
the crank outwards, not by copying the analogues:

* velocities: v_A = ω₁ × OA for the crank pin; for a group's joint B, v_B = v_A + v_BA with
  v_BA = ω_i × AB (ω_i = ω_qi·ω); for a point S on a link, v_S = v_A + ω_i × AS (the
  similarity theorem); for a slotted link (RPR) the rocker's point A₃ under the block's pin A,
  v_A3 = v_P + ω₃ × PA, and the sliding velocity v_A3A = v_A3 − v_A along the slot;
* accelerations: a_B = a_A + aⁿ_BA + aᵗ_BA, aⁿ = −ω_i²·AB (|aⁿ| = v_BA²/l, directed from B to
  the centre A), aᵗ = ε_i × AB (|aᵗ| = |ε_i|·l), ε_i = ε_qi·ω² + ω_qi·ε; the crank's pin too
  (its aᵗ = ε₁·l₁ with the true motion); for the slotted link a_A3 = a_P + aⁿ + aᵗ and
  a_A3 = a_A + aᵏ + aʳ with Coriolis's aᵏ = 2·ω₃ × v_A3A (|aᵏ| = 2·|ω₃|·|v_A3A|) and the
  relative aʳ along the slot;
* the force polygon of a group: the known forces on its links (weights G, inertia forces Φ,
  the given forces, the reactions of the groups solved before it) and the reactions it finds
  (a revolute pair's on a link split into the normal Rⁿ along the link and the tangential Rᵗ
  across it, as the course finds them), head to tail; they close because the group is in
  equilibrium;
* Zhukovsky's lever: the velocity plan turned 90° clockwise about its pole, every force at
  its point's image, every couple M on link i as its power M·ω_i; the moment about the pole
  Σ F·v + Σ M·ω_i + M_y·ω = 0 gives M_y (in the crank's direction of rotation).

Scales: :func:`round_scale` — a round value 1, 2, 2.5 or 5 × 10^k per mm, the smallest for
which the longest vector is at most 120 mm on the sheet (so it is longer than 60 mm).

Sources: И. И. Артоболевский, «Теория механизмов и машин», 4-е изд., М.: Наука, 1988 —
планы скоростей и ускорений (кинематический анализ групп, гл. 4 as linkage/solve.py cites
it; теорема подобия; ускорение Кориолиса), силовой расчёт групп Ассура и план сил, рычаг
Н. Е. Жуковского (as dynamics/forces.py cites them); the course's labels pa, pb, ab, πa, n, τ, k.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from flywheel.dynamics.forces import FRAME, ForceAnalysis, Loads, carriers
from flywheel.linkage.mechanism import RPR, RRP, RRR, Mechanism
from flywheel.linkage.solve import Kinematics

SHEET_MM = (60.0, 120.0)
"""The longest vector of a plan on the sheet lies in this range [mm]."""

_ROUND = (1.0, 2.0, 2.5, 5.0)


def round_scale(largest: float, longest_mm: float = SHEET_MM[1]) -> float:
    """The drawing's scale [unit/mm]: the smallest round value 1, 2, 2.5, 5 × 10^k with
    ``largest``/μ ≤ ``longest_mm`` — the course's choice of a scale (a round μ, the longest
    vector 60 … 120 mm). Consecutive round values differ by at most twice, so the longest
    vector is longer than ``longest_mm``/2. ``largest`` = 0 (nothing to draw): 1.

    >>> round_scale(6.283), round_scale(1000.0), round_scale(0.0417)
    (0.1, 10.0, 0.0005)
    """
    if not (largest > 0 and math.isfinite(largest)):
        return 1.0
    need = largest / longest_mm
    k = math.floor(math.log10(need))
    for e in (k - 1, k, k + 1):
        for m in _ROUND:
            mu = float(f"{m}e{e}")
            if mu >= need * (1 - 1e-12):
                return mu
    return float(f"1e{k + 2}")                      # not reached


# -- results ------------------------------------------------------------------------------------

@dataclass(frozen=True)
class PlanVector:
    """One vector of a plan, drawn from ``tail`` to ``head`` (plan coordinates in the plan's
    SI unit: m/s, m/s² or N). ``kind``: velocity and acceleration plans "absolute" (from the
    pole), "relative" (v_BA), "normal" (aⁿ), "tangential" (aᵗ), "coriolis" (aᵏ), "sliding"
    (v or aʳ of the slot); force polygons "weight", "inertia", "given", "known" (a reaction
    of a group solved before), "reaction", "reaction_n", "reaction_t" (the pair's reaction and
    its parts along and across the link). ``to``/``rel``: the point it leads to and the one it
    is relative to (v_BA: to "B", rel "A"); a force: its point in ``to``, its link in ``rel``.
    ``label``: as the course writes it on the drawing ("pa", "ab", "πb", "n_BA", "G_2")."""

    kind: str
    label: str
    to: str
    rel: str | None
    tail: tuple[float, float]
    head: tuple[float, float]

    @property
    def vector(self) -> np.ndarray:
        """head − tail, (2,) [the plan's unit]."""
        return np.subtract(self.head, self.tail)

    @property
    def value(self) -> float:
        """The vector's magnitude [the plan's unit]."""
        return float(np.hypot(*self.vector))


@dataclass(frozen=True)
class KinematicPlan:
    """A velocity plan (``quantity`` "velocity": pole p, m/s) or an acceleration plan
    ("acceleration": pole π, m/s²) at crank angle ``phi_deg`` [deg] with the crank's ``omega``
    [rad/s] and ``epsilon`` [rad/s²] of the force analysis's motion.

    images: point → its image (2,) [m/s or m/s²], the absolute velocity (acceleration) as a
    vector from the pole (fixed points at the pole); image_labels: point → the image's letter
    ("a", "b", "s2"); vectors: in the order drawn; links: link → ω_i [rad/s] (velocity plan)
    or ε_i [rad/s²] (acceleration plan), counter-clockwise; scale: μ [(m/s)/mm or
    (m/s²)/mm], round; the longest vector is ``longest``/μ mm on the sheet."""

    quantity: str
    phi_deg: float
    omega: float
    epsilon: float
    images: dict[str, tuple[float, float]]
    image_labels: dict[str, str]
    vectors: tuple[PlanVector, ...]
    links: dict[str, float]
    scale: float

    @property
    def longest(self) -> float:
        """The longest vector [m/s or m/s²]."""
        return max((v.value for v in self.vectors), default=0.0)


@dataclass(frozen=True)
class ForcePolygon:
    """The force polygon of one Assur group (``kind`` "RRR", "RRP", "RPR") or of the initial
    mechanism (``kind`` "crank": the crank and the frame), at the plan's angle: ``vectors``
    head to tail from (0, 0) [N] — the known forces on its ``links`` and the reactions the
    group finds — closing at (0, 0); ``chords``: the whole reactions whose parts Rⁿ, Rᵗ are in
    the polygon, drawn across it; ``scale`` μ_F [N/mm], round."""

    group: str
    kind: str
    links: tuple[str, ...]
    vectors: tuple[PlanVector, ...]
    chords: tuple[PlanVector, ...]
    scale: float

    @property
    def closure(self) -> float:
        """|Σ vectors| [N]: round-off for a group in equilibrium."""
        return float(np.hypot(*np.sum([v.vector for v in self.vectors], axis=0))) \
            if self.vectors else 0.0

    @property
    def longest(self) -> float:
        """The longest vector or chord [N]."""
        return max((v.value for v in self.vectors + self.chords), default=0.0)


@dataclass(frozen=True)
class LeverForce:
    """A force on Zhukovsky's lever: ``name`` ("G_2", "Φ_3", "F_HP", "P_y"), ``kind``
    ("weight", "inertia", "given", "balancing"), on ``link`` at ``point``; ``force`` (2,) [N];
    ``image`` (2,) [m/s]: the point's velocity image turned 90° clockwise about the pole."""

    name: str
    kind: str
    link: str
    point: str
    force: tuple[float, float]
    image: tuple[float, float]

    @property
    def moment(self) -> float:
        """Its moment about the pole, image × force [W = N·m/s], counter-clockwise: F·v."""
        (x, y), (fx, fy) = self.image, self.force
        return x * fy - y * fx


@dataclass(frozen=True)
class LeverCouple:
    """A couple on Zhukovsky's lever: ``name`` ("M_Φ2" an inertia couple, "M_I" the first
    group's −J_I·ε, a given couple's name), on ``link``; ``M`` [N·m] counter-clockwise;
    ``omega`` = ω_i [rad/s] of the link; its moment on the lever M·ω_i [W]."""

    name: str
    link: str
    M: float
    omega: float

    @property
    def moment(self) -> float:
        return self.M * self.omega


@dataclass(frozen=True)
class ZhukovskyLever:
    """Zhukovsky's lever at ``phi_deg``: the velocity plan turned 90° clockwise about the pole
    (``images`` [m/s], by point; ``image_labels`` as the velocity plan's), the loads
    (``forces``, ``couples``), the crank's ``omega`` [rad/s] and ``direction`` (+1 ccw).

    moment_of_loads [W]: Σ F·v + Σ M·ω_i about the pole (the balancing force left out);
    balancing_moment [N·m]: M_y = −moment_of_loads/ω, in the direction of rotation;
    balancing_force: P_у = M_y/l₁ at the crank pin ``crank_pin``, across the crank in the
    direction of rotation (on the lever its moment is M_y·ω); ``scale`` μ_v [(m/s)/mm] of the
    turned plan, ``force_scale`` μ_F [N/mm] of the drawn forces."""

    phi_deg: float
    omega: float
    direction: int
    images: dict[str, tuple[float, float]]
    image_labels: dict[str, str]
    forces: tuple[LeverForce, ...]
    couples: tuple[LeverCouple, ...]
    crank_pin: str
    balancing_force: LeverForce
    scale: float
    force_scale: float

    @property
    def moment_of_loads(self) -> float:
        """Σ F·v + Σ M·ω_i about the pole [W], the balancing force left out."""
        return sum(f.moment for f in self.forces) + sum(c.moment for c in self.couples)

    @property
    def balancing_moment(self) -> float:
        """M_y [N·m] in the direction of rotation, from the lever's equilibrium."""
        return -self.moment_of_loads / self.omega if self.omega else float("nan")


@dataclass(frozen=True)
class PlanSet:
    """Everything drawn at one report angle ``phi_deg`` [deg] (grid node ``index``): the
    velocity and acceleration plans, the force polygons (the groups from the last one back,
    then the crank, as they are solved) and Zhukovsky's lever."""

    phi_deg: float
    index: int
    velocity: KinematicPlan
    acceleration: KinematicPlan
    polygons: tuple[ForcePolygon, ...]
    lever: ZhukovskyLever


# -- helpers ------------------------------------------------------------------------------------

def _perp(r: np.ndarray) -> np.ndarray:
    """k × r: r turned 90° counter-clockwise."""
    return np.array([-r[1], r[0]])


def _t(v) -> tuple[float, float]:
    return (float(v[0]), float(v[1]))


def image_label(point: str) -> str:
    """The image of a point on a plan: its name in lower case ("B" → "b", "S2" → "s2")."""
    return point.lower()


def link_pair(a: str, b: str) -> str:
    """Two link or point names side by side ("12", "r1,1" when a name is longer): a reaction's
    subscript (R_12, R_r1,1), here and wherever a reaction is named (render/forces.py, the
    sheets)."""
    return f"{a}{b}" if len(a) == 1 and len(b) == 1 else f"{a},{b}"


class _Structure:
    """Which link each moving point is reached from: (point, link, base point) in the order a
    plan is built — the crank's pins, each group's joint, the points on links as soon as their
    link is known — and the slotted links' coincident points."""

    def __init__(self, mech: Mechanism, kin: Kinematics) -> None:
        c = mech.crank
        # in the case's order (a set's would change with the hash seed, and with it the order
        # of the letters at the pole: p, o, c or p, c, o — outputs differing between runs)
        self.fixed = dict.fromkeys([*mech.ground, c.pivot])
        self.steps: list[tuple] = []
        known_links = {c.name}
        placed = set(self.fixed)
        for tip in [c.tip] + [p.name for p in c.pins]:
            self.steps.append(("crank", tip, c.name, c.pivot))
            placed.add(tip)
        pending = list(mech.points)

        def place_points() -> None:
            progress = True
            while progress:
                progress = False
                for p in list(pending):
                    base = kin.links[p.link].ref if p.link in kin.links else None
                    if p.link in known_links and base in placed:
                        self.steps.append(("point", p.name, p.link, base))
                        placed.add(p.name)
                        pending.remove(p)
                        progress = True

        place_points()
        for d in mech.dyads:
            if isinstance(d, RRR):
                self.steps.append(("rrr", d))
                placed.add(d.joint)
                known_links |= {d.link_a, d.link_b}
            elif isinstance(d, RRP):
                self.steps.append(("rrp", d))
                placed.add(d.joint)
                known_links |= {d.rod, d.slider}
            elif isinstance(d, RPR):
                self.steps.append(("rpr", d, coincident_point(d, kin)))
                known_links |= {d.rocker, d.slider}
            place_points()


def coincident_point(d: RPR, kin: Kinematics) -> str:
    """The name of the rocker's point under the block's pin of a slotted link: the pin's name
    with the rocker's ("A" on rocker 3 → "A3"), primed if a point has that name."""
    name = f"{d.origin}{d.rocker}"
    while name in kin.points:
        name += "′"
    return name


# -- the kinematic plans ------------------------------------------------------------------------

def kinematic_plans(mech: Mechanism, kin: Kinematics, i: int, omega: float, epsilon: float,
                    phi_deg: float) -> tuple[KinematicPlan, KinematicPlan]:
    """The velocity and the acceleration plan at grid node ``i`` with the crank's ``omega``
    [rad/s] and ``epsilon`` [rad/s²] (the module's vector equations)."""
    P, L = kin.points, kin.links
    w, e = float(omega), float(epsilon)
    om = {n: float(lm.omega_q[i]) * w for n, lm in L.items()}
    ep = {n: float(lm.eps_q[i]) * w * w + float(lm.omega_q[i]) * e for n, lm in L.items()}
    st = _Structure(mech, kin)
    r = {n: pm.r[i].astype(float) for n, pm in P.items()}
    zero = np.zeros(2)
    v = {n: zero for n in st.fixed}
    a = {n: zero for n in st.fixed}
    labels = {n: image_label(n) for n in P}
    vv: list[PlanVector] = []
    av: list[PlanVector] = []
    pole_v, pole_a = "p", "π"
    for n in list(labels):
        if labels[n] == pole_v:
            labels[n] = "p′"

    def absolute(to: str) -> None:
        vv.append(PlanVector("absolute", pole_v + labels[to], to, None, (0.0, 0.0), _t(v[to])))
        av.append(PlanVector("absolute", pole_a + labels[to], to, None, (0.0, 0.0), _t(a[to])))

    def rotate(to: str, base: str, link: str, rel_velocity: bool = True) -> None:
        """to = base + ω × (to − base): the relative velocity and the acceleration's normal
        and tangential parts, chained from the base's images."""
        d = r[to] - r[base]
        v_rel = om[link] * _perp(d)
        n = -om[link] ** 2 * d
        tau = ep[link] * _perp(d)
        v[to] = v[base] + v_rel
        a[to] = a[base] + n + tau
        if rel_velocity and base not in st.fixed:
            vv.append(PlanVector("relative", labels[base] + labels[to], to, base, _t(v[base]),
                                 _t(v[to])))
        mid = a[base] + n
        av.append(PlanVector("normal", f"n_{to}{base}", to, base, _t(a[base]), _t(mid)))
        av.append(PlanVector("tangential", f"τ_{to}{base}", to, base, _t(mid), _t(a[to])))

    for step in st.steps:
        kind = step[0]
        if kind in ("crank", "point"):
            _, to, link, base = step
            rotate(to, base, link)
            absolute(to)
        elif kind == "rrr":
            d = step[1]
            rotate(d.joint, d.point_a, d.link_a)
            vb, ab = v[d.joint], a[d.joint]
            rotate(d.joint, d.point_b, d.link_b)          # the second equation of the group
            v[d.joint], a[d.joint] = vb, ab               # b as the first found it
            absolute(d.joint)
        elif kind == "rrp":
            d = step[1]
            rotate(d.joint, d.origin, d.rod)
            absolute(d.joint)
        else:                                             # the slotted link
            d, x = step[1], step[2]
            r[x] = r[d.origin]
            labels[x] = image_label(x)
            rotate(x, d.pivot, d.rocker, rel_velocity=True)
            absolute(x)
            v_rel = v[x] - v[d.origin]                    # v_A3A, along the slot
            k = 2 * om[d.rocker] * _perp(v_rel)           # Coriolis: 2·ω₃ × v_A3A
            vv.append(PlanVector("sliding", labels[d.origin] + labels[x], x, d.origin,
                                 _t(v[d.origin]), _t(v[x])))
            mid = a[d.origin] + k
            av.append(PlanVector("coriolis", f"k_{x}{d.origin}", x, d.origin, _t(a[d.origin]),
                                 _t(mid)))
            av.append(PlanVector("sliding", f"r_{x}{d.origin}", x, d.origin, _t(mid), _t(a[x])))
    images_v = {n: _t(v[n]) for n in v}
    images_a = {n: _t(a[n]) for n in a}
    lab = {n: labels[n] for n in v}
    vp = KinematicPlan("velocity", phi_deg, w, e, images_v, lab, tuple(vv), om,
                       round_scale(max((x.value for x in vv), default=0.0)))
    ap = KinematicPlan("acceleration", phi_deg, w, e, images_a, dict(lab), tuple(av), ep,
                       round_scale(max((x.value for x in av), default=0.0)))
    return vp, ap


# -- the force polygons ---------------------------------------------------------------------------

def _called(symbol: str, load) -> str:
    """A given load's name on the plans: "F_HP" — its ``label`` the subscript where the case
    gives one, in both languages (an io.text.Text: "F_HP", «F_ВД»), else its name."""
    from flywheel.io.text import Text, in_language

    if not load.label:
        return f"{symbol}_{load.name}"
    return Text(f"{symbol}_{in_language(load.label, 'en')}",
                f"{symbol}_{in_language(load.label, 'ru')}")


def _given_forces(kin: Kinematics, fa: ForceAnalysis, loads: Loads, i: int) -> list[tuple]:
    """(kind, label, link, point, F (2,)) of every force on the moving links at node i: the
    given forces, the weights, the inertia forces."""
    out = []
    for f in loads.forces:
        F = np.asarray(f.F, float)
        F = F if F.ndim == 1 else F[i]
        out.append(("given", _called("F", f), f.link, f.point, F.astype(float)))
    g = np.asarray(loads.gravity, float)
    for name, m in loads.masses.items():
        if m.mass and m.centroid is not None and np.any(g != 0):
            out.append(("weight", f"G_{name}", name, m.centroid, m.mass * g))
    for name, il in fa.inertia.items():
        if il.point is not None:
            out.append(("inertia", f"Φ_{name}", name, il.point,
                        np.array([il.x[i], il.y[i]], float)))
    return out


def _groups(mech: Mechanism) -> list[tuple[str, str, tuple[str, ...], list[tuple]]]:
    """(group, kind, links, unknowns) in the order the kinetostatics solves them: the dyads
    from the last back, then the crank. An unknown is (key, link it acts on, split along the
    link from point to point or None)."""
    c = carriers(mech)
    out = []
    for d in reversed(mech.dyads):
        if isinstance(d, RRR):
            out.append((d.name, "RRR", d.links, [
                (f"{d.point_a}:{c[d.point_a]}->{d.link_a}", (d.point_a, d.joint)),
                (f"{d.point_b}:{c[d.point_b]}->{d.link_b}", (d.point_b, d.joint))]))
        elif isinstance(d, RRP):
            out.append((d.name, "RRP", d.links, [
                (f"{d.origin}:{c[d.origin]}->{d.rod}", (d.origin, d.joint)),
                (f"{d.joint}:{FRAME}->{d.slider}", None)]))
        else:
            out.append((d.name, "RPR", d.links, [
                (f"{d.origin}:{c[d.origin]}->{d.slider}", None),
                (f"{d.pivot}:{c[d.pivot]}->{d.rocker}", None)]))
    k = mech.crank
    out.append((k.name, "crank", (k.name,), [(f"{k.pivot}:{FRAME}->{k.name}", None)]))
    return out


def force_polygons(mech: Mechanism, kin: Kinematics, fa: ForceAnalysis, loads: Loads,
                   i: int) -> tuple[ForcePolygon, ...]:
    """The force polygon of every Assur group and of the crank at grid node i (see
    :class:`ForcePolygon`): per link — the reactions of the groups solved before it, its
    weight, inertia force and given forces — then the reactions the group finds; an RRR's and
    an RRP's revolute outer pairs split into Rᵗ (first) and Rⁿ (last), as the course draws
    them: Rᵗ₁₂ + G₂ + Φ₂ + … + R₀₃ + Rⁿ₁₂ = 0."""
    loads_i = _given_forces(kin, fa, loads, i)
    out = []
    for group, kind, links, unknowns in _groups(mech):
        S = set(links)
        unknown_keys = {u[0] for u in unknowns}
        known: list[tuple] = []
        for link in links:
            for key, R in fa.joints.items():   # reactions of the groups solved before
                if R.by == link and R.on not in S and key not in unknown_keys:
                    F = -np.array([R.x[i], R.y[i]])
                    known.append(("known", f"R_{link_pair(R.on, R.by)}", R.joint, link, F))
            for kd, label, lk, point, F in loads_i:
                if lk == link:
                    known.append((kd, label, point, link, F))
        first, last, chords = [], [], []
        for key, split in unknowns:
            R = fa.joints[key]
            F = np.array([R.x[i], R.y[i]], float)
            label = f"R_{link_pair(R.by, R.on)}"
            if split is None:
                last.append(("reaction", label, R.joint, R.on, F))
                continue
            d = kin.points[split[1]].r[i] - kin.points[split[0]].r[i]
            u = d / np.hypot(*d)
            Fn = (F @ u) * u
            first.append(("reaction_t", f"{label}^τ", R.joint, R.on, F - Fn))
            last.append(("reaction_n", f"{label}^n", R.joint, R.on, Fn))
            chords.append((label, R.joint, R.on, F))
        if kind == "RRR":       # Rᵗ_a, knowns, Rᵗ_b, Rⁿ_b, Rⁿ_a
            order = first[:1] + known + first[1:] + last[::-1]
        else:
            order = first + known + last[1:] + last[:1] if first else known + last
        vectors, tip, start = [], np.zeros(2), {}
        for kd, label, point, link, F in order:
            if not np.any(F != 0):
                continue
            start[label] = tip
            vectors.append(PlanVector(kd, label, point, link, _t(tip), _t(tip + F)))
            tip = tip + F
        cv = []
        names = [x.label for x in vectors]
        for label, point, link, F in chords:      # the whole R = Rᵗ + Rⁿ across the polygon
            n, t = f"{label}^n", f"{label}^τ"
            if n not in start or t not in start:
                continue
            # Rᵗ just before Rⁿ: from Rᵗ's tail; Rⁿ last and Rᵗ first: from Rⁿ's tail
            tail = start[t] if names.index(n) == names.index(t) + 1 else start[n]
            cv.append(PlanVector("reaction", label, point, link, _t(tail), _t(tail + F)))
        pv = tuple(vectors)
        out.append(ForcePolygon(group, kind, links, pv, tuple(cv),
                                round_scale(max((x.value for x in pv + tuple(cv)), default=0.0))))
    return tuple(out)


# -- Zhukovsky's lever ----------------------------------------------------------------------------

def zhukovsky_lever(mech: Mechanism, kin: Kinematics, fa: ForceAnalysis, loads: Loads, i: int,
                    velocity: KinematicPlan) -> ZhukovskyLever:
    """Zhukovsky's lever at grid node i on the velocity plan ``velocity`` (see
    :class:`ZhukovskyLever`): the images turned 90° clockwise, (v_x, v_y) → (v_y, −v_x)."""
    turned = {n: (y, -x) for n, (x, y) in velocity.images.items()}
    om = velocity.links
    forces = []
    for kd, label, link, point, F in _given_forces(kin, fa, loads, i):
        if np.any(F != 0):
            forces.append(LeverForce(label, kd, link, point, _t(F), turned[point]))
    couples = []
    for c in loads.couples:
        M = np.asarray(c.M, float)
        couples.append(LeverCouple(_called("M", c) if c.label else c.name, c.link,
                                   float(M if M.ndim == 0 else M[i]), om[c.link]))
    for name, il in fa.inertia.items():
        if il.couple[i] != 0:
            couples.append(LeverCouple(f"M_Φ{name}", name, float(il.couple[i]), om[name]))
    k = mech.crank
    if fa.first_group_couple[i] != 0:
        couples.append(LeverCouple("M_I", k.name, float(fa.first_group_couple[i]), om[k.name]))
    lever = ZhukovskyLever(velocity.phi_deg, velocity.omega, k.direction, turned,
                           dict(velocity.image_labels), tuple(forces), tuple(couples), k.tip,
                           LeverForce("P_y", "balancing", k.name, k.tip, (0.0, 0.0),
                                      turned[k.tip]), velocity.scale, 1.0)
    My = lever.balancing_moment
    OA = kin.points[k.tip].r[i] - kin.points[k.pivot].r[i]
    t = k.direction * _perp(OA) / np.hypot(*OA)          # across the crank, with the rotation
    Py = LeverForce("P_y", "balancing", k.name, k.tip, _t(My / k.length * t), turned[k.tip])
    largest = max([np.hypot(*f.force) for f in forces] + [np.hypot(*Py.force)], default=0.0)
    return ZhukovskyLever(lever.phi_deg, lever.omega, lever.direction, turned,
                          lever.image_labels, lever.forces, lever.couples, k.tip, Py,
                          velocity.scale, round_scale(float(largest), SHEET_MM[1] / 2))


# -- all of them ----------------------------------------------------------------------------------

def plan_set(mech: Mechanism, kin: Kinematics, fa: ForceAnalysis, loads: Loads, i: int,
             phi_deg: float) -> PlanSet:
    """The plans at grid node ``i`` (crank angle ``phi_deg`` [deg]) with the force analysis's
    motion (fa.omega[i], fa.epsilon[i]): those whose inertia forces ``fa`` holds."""
    w, e = float(fa.omega[i]), float(fa.epsilon[i])
    vp, ap = kinematic_plans(mech, kin, i, w, e, phi_deg)
    return PlanSet(phi_deg, i, vp, ap, force_polygons(mech, kin, fa, loads, i),
                   zhukovsky_lever(mech, kin, fa, loads, i, vp))


def plan_sets(mech: Mechanism, kin: Kinematics, fa: ForceAnalysis, loads: Loads,
              at_deg) -> tuple[PlanSet, ...]:
    """:func:`plan_set` at each report angle [deg] (grid nodes: dynamics.grid.report_index)."""
    from flywheel.dynamics.grid import report_index

    return tuple(plan_set(mech, kin, fa, loads, report_index(kin.phi, a), float(a))
                 for a in at_deg)
