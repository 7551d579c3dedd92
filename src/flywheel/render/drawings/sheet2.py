"""Sheet 2, the force analysis at the first report angle: the scheme in that position to a
ГОСТ 2.302 scale, the velocity and acceleration plans to their round scales, each Assur group
(and the crank) drawn apart with the forces on it, the force polygons, Zhukovsky's lever and
the table of the reactions. Everything read from the results: the plans' images, vectors and
scales from dynamics/plans.py (:class:`~flywheel.dynamics.plans.PlanSet`, the same that
render/plots_plans.py draws), the reactions from ``results.at``.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.io.text import in_language
from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.drawings.diagram import mu_text, num
from flywheel.render.drawings.model import View, indexed, text_width
from flywheel.dynamics.plans import link_pair, round_scale
from flywheel.render.drawings.scheme import _block, gost_scale, scheme_view
from flywheel.render.labels import around, beside, toward

T = words("drawings2", {
    "scheme": "Kinematic scheme at φ = {a}°, scale {s}",
    "velocity": "Velocity plan",
    "acceleration": "Acceleration plan",
    "group": "Group of links {l} ({k}) with its forces",
    "crank": "Initial mechanism (link {l}) with its forces",
    "polygon": "Force polygon of links {l}",
    "polygon_link": "Force polygon of link {l}",
    "lever": "Zhukovsky's lever",
    "balancing": "M_y = {m} N·m",
    "reactions": "Reactions in the kinematic pairs",
    "reaction": "Reaction",
    "point": "Point",
    "magnitude": "R, N",
    "angle": "Angle to x, °",
    "hodograph": "Hodograph of the load on the crank pin over the cycle",
    "hodograph_linkage": "Hodograph of the load on the crank pin over the cycle",
})
ARROW_MM = 15.0        # a force's arrow on a group drawn apart (its direction, not its size)


def _t(lang: str) -> dict:
    return T["ru" if lang == "ru" else "en"]


def _image(label: str) -> str:
    """An image's letter with its digits as a subscript: "s2" → "s_2"."""
    return indexed(label)


def force_label(label: str, lang: str) -> str:
    """A force's name in the sheet's markup: "G_2", "Φ_3", "R_12^τ" → "Rτ_12", "P_y" → "P_у"
    (Russian), "R_1,r4^τ" → "Rτ_{1,r4}" (the pair whole in the subscript); a load's label in
    two languages (io.text.Text, dynamics/plans.py) in ``lang``: «F_ВД»."""
    base, _, sup = in_language(label, lang).partition("^")
    sym, _, sub = base.partition("_")
    if sym == "P" and sub == "y" and lang == "ru":
        sub = "у"
    if "," in sub:                          # links named by more than a digit: «R_{1,r4}»
        sub = f"{{{sub}}}"
    return f"{sym}{sup}_{sub}" if sub else f"{sym}{sup}"


def _per_mm(key: str, lang: str) -> str:
    """The unit a scale's μ is «per mm» of (the nomenclature's "(m/s)/mm" → "м/с")."""
    u = nm.unit_of(key, lang)
    for mm in ("/mm", "/мм"):
        u = u[:-len(mm)] if u.endswith(mm) else u
    return u[1:-1] if u.startswith("(") and u.endswith(")") else u


def _plan_view(name: str, title: str, plan, pole: str, key: str, lang: str,
               longest_mm: float) -> View:
    """A velocity or acceleration plan: every vector from the pole at the round μ that draws
    the longest within ``longest_mm`` (plans.round_scale, the plan module's rule), the absolute
    ones in main lines, their components thin, the images lettered."""
    mu = round_scale(plan.longest, longest_mm)
    v = View(name)
    v.scales[key] = mu
    P = lambda xy: (float(xy[0]) / mu, float(xy[1]) / mu)       # noqa: E731
    marks = {"normal": "n", "tangential": "τ", "coriolis": "k", "sliding": "r"}
    drawn = [vec for vec in plan.vectors if vec.value / mu >= 0.5]
    for vec in drawn:
        line = "main" if vec.kind in ("absolute", "relative") else "thin"
        v.arrow(P(vec.tail), P(vec.head), line=line, full=True)
    v.circle((0.0, 0.0), 0.6, line="thin", filled=True)
    images = []
    seen: set = set()
    for point, xy in plan.images.items():
        c = P(xy)
        key_c = (round(c[0], 1), round(c[1], 1))
        if math.hypot(*c) < 0.5 or key_c in seen:
            continue
        seen.add(key_c)
        images.append((c, _image(plan.image_labels[point])))
    # the letters, the pole's, then the components' marks, by the one placer (render/labels.py)
    placer = v.placer()
    for c, text in images:
        v.label(placer, c, text, 3.5, np.vstack([[toward(c, 1.5)], around(1.2)]))
    v.label(placer, (0.0, 0.0), pole, 3.5, np.vstack([[(-1.0, -1.0, 1.0, 1.0)], around(1.2)]))
    for vec in drawn:
        if vec.kind in marks:
            anchors, places, prefer = beside(P(vec.tail), P(vec.head), gaps=(0.8, 2.0, 4.0))
            v.label(placer, anchors, marks[vec.kind], 2.5, places, prefer)
    x0, _, _, y1 = v.box()
    v.rich(x0, y1 + 3.0, mu_text(key.split("_")[1], mu, _per_mm(key, lang), lang), 3.5)
    v.text(x0, y1 + 9.0, title, 5.0)
    return v


def _members(results, links) -> list:
    return [(link, pts) for link, pts in results.drawing.members if link in links]


def _group_view(results, i: int, poly, room: float, lang: str) -> View:
    """A group drawn apart to the scheme's scale, every force of its polygon an arrow at its
    point (direction only, ARROW_MM long), named."""
    t = _t(lang)
    P = results.kinematics.points
    pts_all = [p for link, pts in _members(results, poly.links) for p in pts]
    span = np.ptp([P[p].r[i] for p in pts_all], axis=0).max() if pts_all else 0.1
    k, label = gost_scale(max(float(span), 1e-6), room, lang)
    m2mm = 1000.0 * k
    xy = lambda r: np.array([float(r[0]) * m2mm, float(r[1]) * m2mm])    # noqa: E731
    v = View(f"group {poly.group}")
    v.scales.update(k=k, label=label)
    for link, pts in _members(results, poly.links):
        pp = [xy(P[p].r[i]) for p in pts]
        if len(pp) == 2:
            v.line(*pp)
        else:
            v.line(*pp[:2])
            for p in pp[2:]:
                v.line(pp[0], p, line="thin")
        for name, c in zip(pts, pp):
            v.circle(c, 1.5 if name in results.drawing.joints else 0.8, line="main",
                     filled=name not in results.drawing.joints)
    for link, joint, angle in results.drawing.guided_sliders:
        if link in poly.links:
            _block(v, xy(P[joint].r[i]), angle)
    arrows = []
    for vec in poly.vectors:
        if vec.to not in P or vec.value <= 0:
            continue
        c = xy(P[vec.to].r[i])
        d = np.asarray(vec.vector, float) / vec.value
        head = c + ARROW_MM * d
        v.arrow(tuple(c), tuple(head), line="thin")
        arrows.append((head, d, force_label(vec.label, lang)))
    placer = v.placer()
    for head, d, text in arrows:
        _beyond(v, placer, head, d, text)
    x0, _, _, y1 = v.box()
    title = (t["crank"].format(l=", ".join(poly.links)) if poly.kind == "crank" else
             t["group"].format(l=", ".join(poly.links), k=nm.dyad_kind(poly.kind, lang)))
    v.text(x0, y1 + 3.0, f"{title}, {label}", 5.0)
    return v


def _beyond(v: View, placer, head, d, label: str) -> None:
    """A force's name just beyond its arrow's head, on the side the arrow points to, or
    beside the head where that is taken (the one placer, render/labels.py)."""
    d = np.asarray(d, float)
    n = np.array([-d[1], d[0]])
    places = [toward(d, 1.5), toward(d + n, 1.5), toward(d - n, 1.5), toward(n, 2.0),
              toward(-n, 2.0), toward(d, 4.0), toward(d + n, 3.5), toward(d - n, 3.5),
              toward(n, 4.5), toward(-n, 4.5)]
    v.label(placer, head, label, 3.5, np.array(places))


def _polygon_view(poly, lang: str, longest_mm: float) -> View:
    """The force polygon: the vectors head to tail at a round μ_F (the longest within
    ``longest_mm``), the whole reactions dashed."""
    t = _t(lang)
    mu = round_scale(poly.longest, longest_mm)
    v = View(f"polygon {poly.group}")
    v.scales["mu_F"] = mu
    P = lambda xy: (float(xy[0]) / mu, float(xy[1]) / mu)       # noqa: E731
    vecs = [vec for vec in poly.vectors if vec.value / mu >= 0.3]
    chords = [ch for ch in poly.chords if ch.value / mu >= 0.3]
    for vec in vecs:
        v.arrow(P(vec.tail), P(vec.head),
                line="main" if vec.kind.startswith("reaction") else "thin", full=True)
    for ch in chords:
        v.arrow(P(ch.tail), P(ch.head), line="dashed", full=True)
    placer = v.placer()        # the names beside their vectors (render/labels.py)
    for vec in sorted(vecs, key=lambda x: -float(x.value)):
        anchors, places, prefer = beside(P(vec.tail), P(vec.head), gaps=(1.5, 3.0, 6.0))
        v.label(placer, anchors, force_label(vec.label, lang), 3.5, places, prefer)
    for ch in chords:
        anchors, places, prefer = beside(P(ch.tail), P(ch.head), gaps=(1.5, 3.0, 6.0),
                                         shares=(0.3, 0.5, 0.7))
        v.label(placer, anchors, force_label(ch.label, lang), 3.5, places, prefer)
    x0, _, _, y1 = v.box()
    v.rich(x0, y1 + 3.0, mu_text("F", mu, _per_mm("mu_F", lang), lang), 3.5)
    v.text(x0, y1 + 9.0, t["polygon" if len(poly.links) > 1 else "polygon_link"].format(
        l=", ".join(poly.links)), 5.0)
    return v


def _lever_view(results, ps, lang: str, longest_mm: float) -> View:
    """Zhukovsky's lever: the velocity plan turned 90° at μ_v, every force at its point's
    image (at μ_F of the lever), the balancing force P_y at the crank pin's image."""
    t = _t(lang)
    L = ps.lever
    mu = round_scale(max(math.hypot(*xy) for xy in L.images.values()), longest_mm)
    muF = round_scale(max(math.hypot(*f.force) for f in tuple(L.forces) + (L.balancing_force,)),
                      0.5 * longest_mm)
    v = View("lever")
    v.scales.update(mu_v=mu, mu_F=muF)
    img = {p: (float(x) / mu, float(y) / mu) for p, (x, y) in L.images.items()}
    for vec in ps.velocity.vectors:
        if vec.kind not in ("absolute", "relative") or vec.value / mu < 0.5:
            continue
        a = (0.0, 0.0) if vec.kind == "absolute" else img[vec.rel]
        v.line(a, img[vec.to])
    v.circle((0.0, 0.0), 0.6, line="thin", filled=True)
    arrows = []
    for f in tuple(L.forces) + (L.balancing_force,):
        c = img[f.point]
        F = np.asarray(f.force, float) / muF
        if math.hypot(*F) < 0.5:
            continue
        head = (c[0] + F[0], c[1] + F[1])
        v.arrow(c, head, line="main" if f.kind == "balancing" else "thin", full=True)
        arrows.append((head, F / math.hypot(*F), force_label(f.name, lang)))
    placer = v.placer()        # the letters, then the forces' names (render/labels.py)
    down_left = np.vstack([[(-1.0, -1.0, 1.0, 1.0)], around(1.2)])
    v.label(placer, (0.0, 0.0), "p", 3.5, down_left)
    for p, c in img.items():
        if math.hypot(*c) >= 0.5:
            v.label(placer, c, _image(L.image_labels[p]), 3.5, down_left)
    for head, d, text in arrows:
        _beyond(v, placer, head, d, text)
    x0, _, _, y1 = v.box()
    mm = "мм" if lang == "ru" else "mm"
    v.rich(x0, y1 + 3.0, f"{mu_text('v', mu, _per_mm('mu_v', lang), lang)};  "
           f"{mu_text('F', muF, _per_mm('mu_F', lang), lang)}", 3.5)
    v.rich(x0, y1 + 8.0, t["balancing"].replace("N·m", nm.unit("N·m", lang))
           .format(m=num(L.balancing_moment, lang)), 3.5)
    v.text(x0, y1 + 14.0, t["lever"], 5.0)
    del mm
    return v


def hodograph_view(results, lang: str, longest_mm: float) -> View | None:
    """The load on the crank pin over the cycle in the crank's axes (F_T along the pin's
    velocity, F_R towards the shaft: results.forces, as the report's hodographs plot it) at a
    round μ_F, every 30° of the crank marked and numbered, the report angle's load an arrow."""
    f = results.forces
    if f is None or f.crank_pin_tangential is None:
        return None
    t = _t(lang)
    x, y = np.asarray(f.crank_pin_tangential, float), np.asarray(f.crank_pin_radial, float)
    mu = round_scale(float(np.max(np.hypot(x, y))), longest_mm)
    v = View("hodograph")
    v.scales["mu_F"] = mu
    v.poly(list(zip(x / mu, y / mu)), line="main")
    span = float(np.max(np.hypot(x, y))) / mu
    for a, b in (((-span, 0.0), (span, 0.0)), ((0.0, -span), (0.0, span))):
        v.line(a, b, line="axis")
    step = 30 * results.cycle_deg // 360
    marks = []
    for a in range(0, results.cycle_deg, step):
        i = results.index_of(math.radians(a))
        c = (float(x[i]) / mu, float(y[i]) / mu)
        v.circle(c, 0.6, line="thin", filled=True)
        marks.append((c, f"{a}"))
    i = results.plans[0].index if results.plans else 0
    v.arrow((0.0, 0.0), (float(x[i]) / mu, float(y[i]) / mu), line="thin", full=True)
    v.rich(span + 2.0, 1.0, nm.symbol("crank_pin_tangential", lang), 3.5)
    v.rich(1.0, span + 2.0, nm.symbol("crank_pin_radial", lang), 3.5)
    placer = v.placer()        # the angles beside their marks (render/labels.py)
    for c, text in marks:
        v.label(placer, c, text, 2.5, around(0.8))
    x0, _, _, y1 = v.box()
    v.rich(x0, y1 + 3.0, mu_text("F", mu, _per_mm("mu_F", lang), lang), 3.5)
    v.text(x0, y1 + 9.0, t["hodograph" if results.cylinders else "hodograph_linkage"], 5.0)
    return v


def reactions_table(results, lang: str) -> View:
    """The reactions at the angle: each pair's force of link «by» on link «on», its point,
    magnitude [N] and direction to the x axis [deg]."""
    t = _t(lang)
    a = results.at[0]
    rows = [(force_label(f"R_{link_pair(j.by, j.on)}", lang), j.point, num(j.F, lang),
             num(j.angle_deg, lang))
            for j in (a.joints or {}).values()]      # R_12; R_{r1,p1} where a name is longer
    head = (t["reaction"], t["point"], t["magnitude"].replace("N", nm.unit("N", lang)),
            t["angle"])
    widths = [max(text_width(h, 3.5) + 6.0, 22.0) for h in head]
    row_h = 8.0
    v = View("reactions")
    n = len(rows) + 1
    W, H = v.grid(widths, n, row_h)
    for k, row in enumerate([head] + rows):
        y = H - (k + 0.5) * row_h
        x = 0.0
        for w, cell in zip(widths, row):
            v.rich(x + w / 2, y, cell, 3.5, halign="center", valign="middle")
            x += w
    v.text(0.0, H + 3.0, t["reactions"], 5.0)
    return v


def views(results, lang: str, room: dict) -> list[View]:
    """The views of sheet 2 at the first report angle (results.plans[0]); ``room``: sheet.ROOM
    of the format."""
    t = _t(lang)
    ps = results.plans[0]
    i = ps.index
    sv = scheme_view(results, i, room["scheme"], lang, positions=False, trajectories=False)
    x0, _, _, y1 = sv.box()
    sv.text(x0, y1 + 3.0, t["scheme"].format(a=num(ps.phi_deg, lang), s=sv.scales["label"]), 5.0)
    out = [sv,
           _plan_view("velocity", t["velocity"], ps.velocity, "p", "mu_v", lang, room["plan"]),
           _plan_view("acceleration", t["acceleration"], ps.acceleration, "π", "mu_a", lang,
                      room["plan"])]
    out += [_group_view(results, i, poly, room["group"], lang) for poly in ps.polygons]
    out += [_polygon_view(poly, lang, room["plan"]) for poly in ps.polygons]
    out.append(_lever_view(results, ps, lang, room["plan"]))
    if results.at and results.at[0].joints:
        out.append(reactions_table(results, lang))
    hodograph = hodograph_view(results, lang, 0.75 * room["plan"])
    if hodograph is not None:
        out.append(hodograph)
    return out
