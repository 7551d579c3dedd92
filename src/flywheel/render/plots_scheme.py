"""The kinematic scheme on a matplotlib Axes (render/plots.py re-exports it: the scheme
figure, the plan of positions, the animation and the task sheets draw the mechanism with it):
what does not move (trajectories, guides, fixed pivots), what does at one grid node (links,
joints, sliders), and the names set by the one label placer (render/labels.py) once the
figure is all drawn. Reads ``results.kinematics`` and ``results.drawing`` only
(linkage/drawing.py); matplotlib is imported inside the functions.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.render import nomenclature as nm
from flywheel.render.mathfmt import point_name



def _guide(r: np.ndarray, angle: float, size: float):
    """A slider's guide along ``angle`` [rad] for the slider's path ``r`` (N×2) [m]: the point
    of the path's line at coordinate 0 along it, the unit vectors along and across it, and the
    guide's ends a, b as coordinates along it [m] (1.2·size beyond the travel)."""
    u = np.array([math.cos(angle), math.sin(angle)])
    nrm = np.array([-u[1], u[0]])
    x = r @ u
    foot = r[0] - x[0] * u
    return foot, u, nrm, x.min() - 1.2 * size, x.max() + 1.2 * size

def draw_scheme(ax, results, i: int, size: float, lang: str = "en") -> None:
    """The kinematic scheme of ``results`` (a linkage case's run results) at grid node ``i`` on
    the matplotlib Axes ``ax``: what does not move (trajectories, guides, fixed pivots), then
    what does (links, joints, sliders), equal axes labelled x, y [m] in ``lang``, then the
    names placed by the one label placer (render/labels.py). ``size`` [m] scales the symbols
    (the scheme uses 0.035 of ``results.drawing.span``). Reads only ``results.kinematics``
    and ``results.drawing`` (linkage/drawing.py); a public entry point for other figures that
    draw the mechanism (the task sheets)."""
    from flywheel.render.labels import AxesLabels

    draw_scheme_fixed(ax, results, size)
    draw_scheme_at(ax, results, i, size, names=False)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(nm.axis("x", lang))
    ax.set_ylabel(nm.axis("y", lang))
    scheme_names(AxesLabels(ax), results, i, size)


def draw_scheme_fixed(ax, results, size: float) -> None:
    """The parts of the scheme that do not move: the trajectories of the moving points, the
    guides with their hatching, the fixed pivots on their hatched bases."""
    from matplotlib.patches import Polygon

    P = results.kinematics.points
    moving, fixed = results.drawing.moving_points, results.drawing.fixed_points
    # trajectories, the first moving point's (the crank pin's: the plan of positions' legend
    # names its colour, C0) drawn last, over another point's on the same circle (an engine's
    # pins of one throw angle apart: A1 and A2)
    for k, name in reversed(list(enumerate(moving))):
        r = P[name].r
        ax.plot(r[:, 0], r[:, 1], color=f"C{k % 10}", linewidth=0.8, alpha=0.8, zorder=1)
    # guides with hatching on one side, sliders as blocks
    for link, joint, angle in results.drawing.guided_sliders:
        foot, u, nrm, a, b = _guide(P[joint].r, angle, size)
        ends = np.array([foot + a * u, foot + b * u]) - 0.5 * size * nrm
        ax.plot(ends[:, 0], ends[:, 1], color="k", linewidth=1.0, zorder=2)
        ends2 = ends + size * nrm
        ax.plot(ends2[:, 0], ends2[:, 1], color="k", linewidth=1.0, zorder=2)
        for side, e in ((-1, ends[0]), (1, ends2[0])):       # the hatching of each side
            ticks = []
            for t in np.linspace(a, b, max(int((b - a) / (0.5 * size)), 2)):
                p0 = e + (t - a) * u
                ticks.append((p0, p0 + side * 0.35 * size * (nrm + u)))
            _strokes(ax, ticks, color="k", linewidth=0.5, zorder=2)
    # fixed pivots: a triangle on a hatched base
    for name in fixed:
        c = P[name].r[0]
        tri = Polygon([c, c + [-0.6 * size, -1.1 * size], c + [0.6 * size, -1.1 * size]],
                      closed=True, facecolor="white", edgecolor="k", linewidth=1.0, zorder=2.5)
        ax.add_patch(tri)
        base_y = c[1] - 1.1 * size
        ax.plot([c[0] - size, c[0] + size], [base_y, base_y], color="k", linewidth=1.0, zorder=2.5)
        _strokes(ax, [((c[0] + t, base_y), (c[0] + t - 0.35 * size, base_y - 0.35 * size))
                      for t in np.linspace(-size, size, 5)], color="k", linewidth=0.5, zorder=2.5)


#: strokes per line of :func:`_strokes`: 3 vertices each, under matplotlib's 128 from which a
#: line's path is simplified (path.simplify), so that each stroke is drawn as its own line was
_STROKES_PER_LINE = 40


def _strokes(ax, segments, **kw) -> None:
    """Short strokes (p0, p1) that touch nothing else of theirs (a hatching) drawn as lines of
    up to :data:`_STROKES_PER_LINE` strokes broken by NaN — the same pixels as a line each
    (Agg draws each piece of a broken path as its own), with one artist where there were up
    to forty to make and draw (an engine's scheme had 450 lines)."""
    for k in range(0, len(segments), _STROKES_PER_LINE):
        xy = np.full((3 * len(segments[k:k + _STROKES_PER_LINE]), 2), np.nan)
        for j, (p0, p1) in enumerate(segments[k:k + _STROKES_PER_LINE]):
            xy[3 * j], xy[3 * j + 1] = p0, p1
        ax.plot(xy[:, 0], xy[:, 1], **kw)


def draw_scheme_at(ax, results, i: int, size: float, names: bool = True) -> None:
    """The parts of the scheme that move, at grid node i: sliders, links, joints; and their
    names (:func:`scheme_names`) unless ``names`` is False (a figure that draws more on the
    axes names them once it is all drawn)."""
    from matplotlib.patches import Polygon, Rectangle
    from matplotlib.transforms import Affine2D

    P = results.kinematics.points
    moving, fixed = results.drawing.moving_points, results.drawing.fixed_points
    joints = results.drawing.joints
    for link, joint, angle in results.drawing.guided_sliders:
        c = P[joint].r[i]
        block = Rectangle((-0.9 * size, -0.45 * size), 1.8 * size, 0.9 * size, facecolor="0.85",
                          edgecolor="k", linewidth=1.2, zorder=4)
        block.set_transform(Affine2D().rotate(angle).translate(*c) + ax.transData)
        ax.add_patch(block)
    for link, pivot in results.drawing.moving_blocks:
        c = P[pivot].r[i]
        block = Rectangle((-0.9 * size, -0.45 * size), 1.8 * size, 0.9 * size, facecolor="0.85",
                          edgecolor="k", linewidth=1.2, zorder=4)
        block.set_transform(Affine2D().rotate(float(results.kinematics.links[link].theta[i]))
                            .translate(*c) + ax.transData)
        ax.add_patch(block)
    # links: a bar through their joints, or a plate if the joints are not in line
    for link, xy in _member_shapes(results, i):
        if len(xy) == 2:
            ax.plot(xy[:, 0], xy[:, 1], color="k", linewidth=2.5, solid_capstyle="round", zorder=3)
        else:
            ax.add_patch(Polygon(xy, closed=True, facecolor="0.9", edgecolor="k",
                                 linewidth=2.0, zorder=3))
    # joints and other points
    for name in moving + fixed:
        c = P[name].r[i]
        if name in joints or name in fixed:
            ax.plot(*c, "o", markersize=6.5, markerfacecolor="white", markeredgecolor="k",
                    markeredgewidth=1.3, zorder=5)
        else:
            ax.plot(*c, "o", markersize=4.5, color="k", zorder=5)
    if names:
        from flywheel.render.labels import AxesLabels

        scheme_names(AxesLabels(ax, frame=False), results, i, size)


def _member_shapes(results, i: int) -> list:
    """(link, its outline at node i): a bar's two ends, or a plate's corners in turn."""
    P = results.kinematics.points
    out = []
    for link, pts in results.drawing.members:
        xy = np.array([P[p].r[i] for p in pts])
        d = xy - xy.mean(axis=0)
        _, sv, vt = np.linalg.svd(d, full_matrices=False)
        if len(pts) <= 2 or sv[-1] <= 1e-9 * max(sv[0], 1e-300):
            t = d @ vt[0]
            out.append((link, xy[[int(np.argmin(t)), int(np.argmax(t))]]))
        else:
            out.append((link, xy[np.argsort(np.arctan2(d[:, 1], d[:, 0]), kind="stable")]))
    return out


def _block_corners(c, angle: float, size: float) -> np.ndarray:
    """The corners [m] of a slider's block (1.8 × 0.9 ``size``) at ``c`` turned ``angle``."""
    u = np.array([math.cos(angle), math.sin(angle)])
    n = np.array([-u[1], u[0]])
    return np.array([c + a * 0.9 * size * u + b * 0.45 * size * n
                     for a in (-1, 1) for b in (-1, 1)])


def scheme_names(labels, results, i: int, size: float) -> None:
    """The names of the scheme at node i placed by the one label placer (``labels``: a
    render.labels.AxesLabels on the scheme's axes, once everything is drawn): the hinges,
    pivots and blocks are obstacles, the links and trajectories lines to keep off; the
    points' letters first (away from the middle of the drawing, else round the point), then
    the links' numbers beside their bars and the sliders' beside their blocks."""
    from flywheel.render.labels import around, toward

    P = results.kinematics.points
    d = results.drawing
    moving, fixed = d.moving_points, d.fixed_points
    centre = np.mean([P[n].r[i] for n in moving + fixed], axis=0)
    for name in moving + fixed:
        big = name in d.joints or name in fixed
        labels.markers([P[name].r[i]], (4.3 if big else 3.0))
    for name in fixed:               # the pivot's triangle and hatched base
        c = P[name].r[i]
        labels.box([c + (-1.0 * size, -1.45 * size), c + (1.0 * size, -0.2 * size)])
    blocks = [(link, P[joint].r[i], angle) for link, joint, angle in d.guided_sliders]
    blocks += [(link, P[pivot].r[i], float(results.kinematics.links[link].theta[i]))
               for link, pivot in d.moving_blocks]
    for link, c, angle in blocks:
        labels.box(_block_corners(c, angle, size))
    for link, joint, angle in d.guided_sliders:       # the guides and their hatching
        foot, u, nrm, a, b = _guide(P[joint].r, angle, size)
        for off in (-0.85, -0.5, 0.5, 0.85):
            labels.segments([(foot + a * u + off * size * nrm, foot + b * u + off * size * nrm)])
    shapes = _member_shapes(results, i)
    for link, xy in shapes:
        labels.curve(np.vstack([xy, xy[:1]]) if len(xy) > 2 else xy)
    for name in moving:
        labels.curve(P[name].r[::max(1, len(P[name].r) // 180)])
    bold = {"fontsize": 10, "fontweight": "bold", "zorder": 8}
    for name in moving + fixed:
        c = P[name].r[i]
        out = c - centre
        norm = np.hypot(*out)
        out = out / norm if norm > 1e-12 else np.array([-0.7, 0.7])
        if name in fixed:               # beside its support, not on it
            out = np.array([-0.95, 0.3])
        first = np.array(toward(out + 0.5 * np.array([-out[1], out[0]]), 6.0))
        labels.point(c, point_name(name), places=np.vstack([first, around(5.0)]), **bold)
    italic = {"fontsize": 8, "style": "italic", "color": "0.2", "zorder": 7}
    for link, xy in shapes:
        if len(xy) == 2:
            t, h = labels.to_pt(xy[0])[0], labels.to_pt(xy[1])[0]
            dd = h - t
            n = np.array([-dd[1], dd[0]]) / (np.hypot(*dd) or 1.0)
            mid = xy.mean(axis=0)
            if n @ (labels.to_pt(mid)[0] - labels.to_pt(centre)[0]) < 0:
                n = -n
            anchors, places, prefer = [], [], []
            for share in (0.62, 0.4, 0.78, 0.25):
                for side in (1.0, -1.0):
                    for gap in (4.0, 9.0):
                        anchors.append(t + share * dd)
                        places.append(toward(side * n, gap))
                        prefer.append(0.01 * gap + 0.1 * abs(share - 0.62)
                                      + (0.0 if side > 0 else 0.05))
            labels.best(anchors, places, prefer, link, **italic)
        else:
            labels.point(xy.mean(axis=0), link, places=np.array([(0.0, 0.0, 0.5, 0.5)]),
                         **italic)
    for link, c, angle in blocks:
        u = np.array([math.cos(angle), math.sin(angle)])
        n = np.array([-u[1], u[0]])
        corners = labels.to_pt(_block_corners(c, angle, size))
        half = 0.5 * float(np.ptp(corners, axis=0).max())
        places = [toward(-n, half + 3.0), toward(n, half + 3.0), toward(u, half + 3.0),
                  toward(-u, half + 3.0), toward(-n, half + 9.0), toward(n, half + 9.0)]
        labels.point(c, link, places=np.array(places), **italic)
