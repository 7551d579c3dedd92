"""The kinematic scheme on a sheet, to a scale of ГОСТ 2.302-68: the mechanism at grid node i
in main lines (links, hinges as circles, fixed pivots on hatched bases, sliders on their
guides, the points' letters), and optionally the other standard positions in thin lines
numbered at the crank pin, with the trajectories of the moving points. Reads
``results.kinematics`` and ``results.drawing`` only (linkage/drawing.py).
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.render.drawings.diagram import num
from flywheel.render.drawings.model import View, indexed
from flywheel.render.labels import around, toward

#: ГОСТ 2.302-68 scales as (paper, real), largest first
GOST_SCALES = ((10, 1), (5, 1), (4, 1), (2.5, 1), (2, 1), (1, 1), (1, 2), (1, 2.5), (1, 4),
               (1, 5), (1, 10), (1, 15), (1, 20), (1, 25), (1, 40), (1, 50), (1, 75),
               (1, 100), (1, 200), (1, 400), (1, 500), (1, 800), (1, 1000))
HINGE_R = 1.5          # a hinge's circle [mm]


def gost_scale(span_m: float, room_mm: float, lang: str = "en") -> tuple[float, str]:
    """(paper mm per real mm, «1:5») — the largest ГОСТ 2.302 scale that draws ``span_m`` [m]
    within ``room_mm`` [mm]; its numbers in ``lang`` («1:2,5» in Russian, as ГОСТ 2.302 writes
    it)."""
    paper, real = next(((p, r) for p, r in GOST_SCALES if span_m * 1000.0 * p / r <= room_mm),
                       GOST_SCALES[-1])
    return paper / real, f"{num(paper, lang)}:{num(real, lang)}"


def _pivot(v: View, c) -> None:
    """A fixed pivot: the hinge on a triangle over a hatched base."""
    x, y = c
    v.line((x, y), (x - 3.0, y - 5.0), (x + 3.0, y - 5.0), closed=True)
    v.line((x - 5.0, y - 5.0), (x + 5.0, y - 5.0))
    for k in range(5):
        x0 = x - 4.0 + 2.0 * k
        v.line((x0, y - 5.0), (x0 - 1.5, y - 6.5), line="thin")


def scheme_view(results, i: int, room_mm: float, lang: str, *, positions: bool,
                trajectories: bool = True, name: str = "scheme", title: str = "") -> View:
    """The scheme at grid node ``i`` within ``room_mm`` [mm] square, to a ГОСТ scale (in
    ``view.scales``: "k" paper/real, "label" «1:5», "mu_l" m/mm)."""
    d = results.drawing
    P = results.kinematics.points
    k, label = gost_scale(max(d.span, 1e-9), room_mm, lang)
    m2mm = 1000.0 * k
    xy = lambda r: (float(r[0]) * m2mm, float(r[1]) * m2mm)     # noqa: E731
    v = View(name)
    v.scales.update(k=k, label=label, mu_l=1.0 / m2mm)
    # what does not move: trajectories and guides
    for pname in d.moving_points if trajectories else ():
        r = P[pname].r
        step = max(1, len(r) // 720)
        v.poly([xy(p) for p in r[::step]] + [xy(r[0])], line="thin")
    for link, joint, angle in d.guided_sliders:
        r = P[joint].r
        u = np.array([math.cos(angle), math.sin(angle)])
        nrm = np.array([-u[1], u[0]])
        s = r @ u
        foot = r[0] - s[0] * u
        a, b = s.min() - 8.0 / m2mm, s.max() + 8.0 / m2mm
        for side in (-1.0, 1.0):
            off = side * 3.5 / m2mm * nrm
            p0, p1 = xy(foot + a * u + off), xy(foot + b * u + off)
            v.line(p0, p1)
            n = int(math.hypot(p1[0] - p0[0], p1[1] - p0[1]) // 4)
            for j in range(n + 1):
                t = j / max(n, 1)
                px, py = p0[0] + t * (p1[0] - p0[0]), p0[1] + t * (p1[1] - p0[1])
                hx, hy = side * 1.6 * nrm + 1.6 * u
                v.line((px, py), (px + hx, py + hy), line="thin")
    for pname in d.fixed_points:
        _pivot(v, xy(P[pname].r[0]))
    # the standard positions, thin (numbered at the crank pin once all is drawn)
    crank = d.links[0]
    numbers = []
    if positions:
        for pos in results.position_angles:
            j = results.index_of(pos.phi)
            if j != i:            # the position drawn in main lines is numbered all the same
                for link, pts in d.links:
                    ends = [xy(P[p].r[j]) for p in pts[:2]]
                    v.line(*ends, line="thin")
            if pos.number is not None:
                tip = np.array(xy(P[crank[1][1]].r[j]))
                piv = np.array(xy(P[crank[1][0]].r[j]))
                out = tip - piv
                numbers.append((tip, out / (np.hypot(*out) or 1.0), str(pos.number)))
    # the mechanism at node i, main lines
    centre = np.mean([xy(P[n].r[i]) for n in d.moving_points + d.fixed_points], axis=0)
    for link, joint, angle in d.guided_sliders:
        _block(v, xy(P[joint].r[i]), angle)
    for link, pivot in d.moving_blocks:
        _block(v, xy(P[pivot].r[i]), float(results.kinematics.links[link].theta[i]))
    for link, pts in d.members:
        pp = np.array([xy(P[p].r[i]) for p in pts])
        dd = pp - pp.mean(axis=0)
        _, sv, vt = np.linalg.svd(dd, full_matrices=False)
        if len(pts) <= 2 or sv[-1] <= 1e-9 * max(sv[0], 1e-300):
            t = dd @ vt[0]
            v.line(pp[int(np.argmin(t))], pp[int(np.argmax(t))])
        else:
            order = np.argsort(np.arctan2(dd[:, 1], dd[:, 0]), kind="stable")
            v.line(*pp[order], closed=True)
    for pname in d.moving_points + d.fixed_points:
        c = np.array(xy(P[pname].r[i]))
        if pname in d.joints or pname in d.fixed_points:
            v.circle(c, HINGE_R, line="main")
        else:
            v.circle(c, 0.8, line="thin", filled=True)
    # the letters, then the numbers, by the one placer (render/labels.py): off the hinges,
    # the blocks and each other, off the lines where they can
    placer = v.placer()
    for pname in d.moving_points + d.fixed_points:
        c = np.array(xy(P[pname].r[i]))
        out = c - centre
        nrm = np.hypot(*out)
        out = out / nrm if nrm > 1e-9 else np.array([-0.7, 0.7])
        if pname in d.fixed_points:
            out = np.array([-0.95, 0.3])
        v.label(placer, c, indexed(pname), 3.5, np.vstack([[toward(out, 2.5)], around(2.0)]))
    for tip, out, text in numbers:
        v.label(placer, tip, text, 2.5, np.array([toward(out, g) for g in (2.0, 4.0, 6.0)]))
    if title:
        x0, y0, x1, y1 = v.box()
        v.text(x0, y1 + 3.0, title, 5.0)
    return v


def _block(v: View, c, angle: float) -> None:
    """A slider block 9 × 5 mm turned ``angle`` [rad] about its centre ``c``."""
    ca, sa = math.cos(angle), math.sin(angle)
    pts = [(c[0] + ca * u - sa * w, c[1] + sa * u + ca * w)
           for u, w in ((-4.5, -2.5), (4.5, -2.5), (4.5, 2.5), (-4.5, 2.5))]
    v.line(*pts, closed=True)
