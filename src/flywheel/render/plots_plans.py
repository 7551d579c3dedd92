"""PNG drawings of the plans a student draws by hand (issue 12 item 6): at each report angle the
velocity plan, the acceleration plan, the force polygons of the Assur groups and Zhukovsky's
lever, each to its stated round scale (μ_v (m/s)/mm, μ_a (m/s²)/mm, μ_F N/mm: the axes are
millimetres of the sheet, so a student can lay a ruler on their own); and the positions drawing
(план положений): the mechanism in its 12 standard positions (24 over a 720° cycle) overlaid
and numbered.

The plans are :class:`flywheel.dynamics.plans.PlanSet` objects in ``Results.plans``; this
module only divides by the scales and draws. The mechanism itself is drawn by render/plots.py's
scheme code, called through the one wrapper :func:`_scheme`. Figures are pyplot-free
:class:`matplotlib.figure.Figure` objects with fixed margins in inches (render/plots.py's
layout), saved by its pool of workers (:func:`figures` is registered in
``plots.all_figures``); matplotlib is imported inside the functions. Quantities are named by
:mod:`flywheel.render.nomenclature`; this module keeps the titles.
"""
from __future__ import annotations

import math
import re

import numpy as np

from flywheel.render import nomenclature as nm

_TEXT = {
    "en": {
        "velocity": "{p} at φ = {a:g}°",
        "acceleration": "{p} at φ = {a:g}°",
        "forces": "{p} at φ = {a:g}°",
        "lever": "{p} at φ = {a:g}° (the velocity plan turned 90° clockwise)",
        "positions": "{p} (план положений), {n} positions every 30°",
        "group": "group {g} ({k}: links {l})",
        "crank": "crank {l} and the frame",
        "pole_v": "pole p",
        "pole_a": "pole π",
        "absolute": "absolute",
        "relative": "relative",
        "normal": "normal n",
        "tangential": "tangential τ",
        "coriolis": "Coriolis k",
        "sliding": "relative in the slot r",
        "weight": "weights G",
        "inertia": "inertia forces Φ",
        "given": "given forces F",
        "known": "reactions of the groups solved before",
        "reaction": "reactions found",
        "chord": "whole reaction R = Rⁿ + Rτ",
        "closes": "closes to {c:.2g} N",
        "omega": "ω = {w:.5g} rad/s, ε = {e:.5g} rad/s²",
        "links_w": "ω of the links, rad/s: {x}",
        "links_e": "ε of the links, rad/s²: {x}",
        "lever_sum": "Σ moments about p: {s:.6g} W",
        "lever_My": "M_y = −Σ/ω = {m:.6g} N·m (kinetostatics: {k:.6g} N·m)",
        "lever_Py": "P_y = M_y/l₁ = {p:.6g} N at the crank pin",
        "couple": "{n} on link {l}: M·ω_i = {m:.5g} N·m · {w:.5g} rad/s = {p:.5g} W",
        "moment": "{n}: h = {h:.4g} mm, F·h = {p:.5g} W",
        "d_c": "dead centres",
        "position_k": "positions 0 … {n}",
        "crank_circle": "path of the crank pin",
    },
    "ru": {
        "velocity": "{p} при φ = {a:g}°",
        "acceleration": "{p} при φ = {a:g}°",
        "forces": "{p} при φ = {a:g}°",
        "lever": "{p} при φ = {a:g}° (план скоростей, повёрнутый на 90° по часовой стрелке)",
        "positions": "{p}, {n} положений через 30°",
        "group": "группа {g} ({k}: звенья {l})",
        "crank": "кривошип {l} и стойка",
        "pole_v": "полюс p",
        "pole_a": "полюс π",
        "absolute": "абсолютные",
        "relative": "относительные",
        "normal": "нормальные n",
        "tangential": "касательные τ",
        "coriolis": "кориолисово k",
        "sliding": "относительное в кулисе r",
        "weight": "силы тяжести G",
        "inertia": "силы инерции Φ",
        "given": "заданные силы F",
        "known": "реакции ранее рассчитанных групп",
        "reaction": "найденные реакции",
        "chord": "полная реакция R = Rⁿ + Rτ",
        "closes": "невязка {c:.2g} Н",
        "omega": "ω = {w:.5g} рад/с, ε = {e:.5g} рад/с²",
        "links_w": "ω звеньев, рад/с: {x}",
        "links_e": "ε звеньев, рад/с²: {x}",
        "lever_sum": "Σ моментов относительно p: {s:.6g} Вт",
        "lever_My": "M_у = −Σ/ω = {m:.6g} Н·м (кинетостатика: {k:.6g} Н·м)",
        "lever_Py": "P_у = M_у/l₁ = {p:.6g} Н на пальце кривошипа",
        "couple": "{n} на звене {l}: M·ω_i = {m:.5g} Н·м · {w:.5g} рад/с = {p:.5g} Вт",
        "moment": "{n}: h = {h:.4g} мм, F·h = {p:.5g} Вт",
        "d_c": "мёртвые положения",
        "position_k": "положения 0 … {n}",
        "crank_circle": "траектория пальца кривошипа",
    },
}

DPI = 120                   # as render/plots.py
_TABLE_W = 3.6              # room for the table of values right of a plan [in]
_COLOURS = {"absolute": "k", "relative": "C0", "normal": "C0", "tangential": "C3",
            "coriolis": "C2", "sliding": "C4", "weight": "C2", "inertia": "C3", "given": "C1",
            "known": "C4", "reaction": "k", "reaction_n": "k", "reaction_t": "k"}


def _t(lang: str, key: str, **kw) -> str:
    text = _TEXT["ru" if lang == "ru" else "en"][key]
    return text.format(**kw) if kw else text


def _plain(text: str) -> str:
    """The table's symbols in plain text (no mathtext: a parse per label is slow)."""
    return (text.replace("M_y", "My").replace("M_у", "Mу").replace("P_y", "Py")
            .replace("P_у", "Pу").replace("ω_i", "ωᵢ"))


def _figure(size, nrows=1, ncols=1, *, left=0.7, right=_TABLE_W, bottom=0.6, top=0.75,
            wspace=0.3, hspace=0.35):
    """A pyplot-free Figure and its axes with fixed margins [in] (render/plots.py's layout)."""
    from matplotlib.figure import Figure

    w, h = size
    fig = Figure(figsize=size, dpi=DPI)
    axes = fig.subplots(nrows, ncols, squeeze=False)
    fig.subplots_adjust(left=left / w, right=1 - right / w, bottom=bottom / h, top=1 - top / h,
                        wspace=wspace, hspace=hspace)
    return fig, axes


def _scheme(ax, results, i: int, size: float, scheme) -> None:
    """The one call into render/plots.py's scheme drawing: what does not move (trajectories —
    the crank pin's circle, the sliders' travel —, guides, pivots), then the mechanism at grid
    node i with its names. ``scheme``: plots.py's (draw_fixed(ax, results, size),
    draw_at(ax, results, i, size)), handed in by ``plots.all_figures`` (plots.py imports this
    module, so this one does not import it)."""
    draw_fixed, draw_at = scheme
    draw_fixed(ax, results, size)
    draw_at(ax, results, i, size)


# -- labels ---------------------------------------------------------------------------------------

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _sub(x: str) -> str:
    """A subscript in plain text (mathtext costs a parse per label): digits as ₀ … ₉, anything
    else in brackets ("12" → "₁₂", "1,r4" → "(1,r4)")."""
    if not x:
        return ""
    return x.translate(_SUB) if x.isdigit() else f"({x})"


def _image(label: str) -> str:
    """An image's letter as the course writes it: "s2" → s₂, "a3" → a₃, "p′" → p′."""
    m = re.match(r"^(.*?)(\d+)$", label)
    return m.group(1) + m.group(2).translate(_SUB) if m else label


def _vec_label(plan, v) -> str:
    """The course's name of a plan's vector: pa, ab, πa; aⁿBA, aτBA, aᵏ, aʳ in the table."""
    lab = plan.image_labels
    if v.kind == "absolute":
        return ("π" if plan.quantity == "acceleration" else "p") + _image(lab[v.to])
    if plan.quantity == "velocity":
        return _image(lab[v.rel]) + _image(lab[v.to])
    sup = {"normal": "ⁿ", "tangential": "τ", "coriolis": "ᵏ", "sliding": "ʳ"}[v.kind]
    return f"a{sup} {v.to}{v.rel}"


_ON_PLAN = {"normal": "n", "tangential": "τ", "coriolis": "k", "sliding": "r"}


def _force_label(label: str, lang: str) -> str:
    """A force's name in plain text: "G_2" → G₂, "Φ_3" → Φ₃, "R_12^τ" → Rτ₁₂, "R_12^n" →
    Rⁿ₁₂, "M_Φ2" → MΦ₂, "F_HP" → F(HP), "P_y" → Pу in Russian."""
    base, _, sup = label.partition("^")
    sym, _, sub = base.partition("_")
    if sym == "P" and sub == "y":
        return "Pу" if lang == "ru" else "Py"
    sup = {"n": "ⁿ", "τ": "τ"}.get(sup, sup)
    if sub.startswith("Φ"):
        return f"{sym}Φ{_sub(sub[1:])}"
    return f"{sym}{sup}{_sub(sub)}"


def _unit(u: str, lang: str) -> str:
    return nm.unit(u, lang)


def _fmt_angle(a: float) -> str:
    """A report angle in a file name: 120 → "120", 22.5 → "22_5", −30 → "m30"."""
    return f"{a:g}".replace("-", "m").replace(".", "_")


def _title(results, what: str) -> str:
    """The case's title over what the figure shows (two lines: a long title is not cut)."""
    return f"{results.title}\n{what}"


def _scale_text(key: str, mu: float, lang: str) -> str:
    return f"{nm.tex(key, lang)} = {mu:g} {nm.unit_of(key, lang)}"


# -- the kinematic plans --------------------------------------------------------------------------

def _arrows(ax, tails: np.ndarray, heads: np.ndarray, colour: str, width: float = 1.6,
            style: str = "-") -> None:
    """Arrows from tails to heads [mm], their heads a fixed size on the page."""
    from matplotlib.patches import FancyArrowPatch

    for t, h in zip(tails, heads):
        if float(np.hypot(*(h - t))) <= 1e-9:
            continue
        ax.add_patch(FancyArrowPatch(tuple(t), tuple(h), arrowstyle="-|>", mutation_scale=9,
                                     shrinkA=0.0, shrinkB=0.0, color=colour, linewidth=width,
                                     linestyle=style, zorder=3))


def _frame_plan(ax, pts: np.ndarray, lang: str) -> None:
    """Equal axes in mm round the points, with a margin."""
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = max(float(np.max(hi - lo)), 10.0)
    pad = 0.12 * span
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlabel(f"{nm.name('plan_length', lang)}, {nm.unit_of('plan_length', lang)}")
    ax.grid(True, alpha=0.3)


def _kinematic_plan(results, ps, which: str, lang: str):
    """The velocity (``which`` "velocity") or the acceleration plan at one report angle."""
    from matplotlib.lines import Line2D

    plan = ps.velocity if which == "velocity" else ps.acceleration
    key, u = ("mu_v", "m/s") if which == "velocity" else ("mu_a", "m/s²")
    mu = plan.scale
    fig, axes = _figure((10.0, 7.0))
    ax = axes[0, 0]
    pts = [np.zeros(2)]
    kinds = []
    lines = []
    for kind in ("absolute", "relative", "normal", "tangential", "coriolis", "sliding"):
        vs = [v for v in plan.vectors if v.kind == kind]
        if not vs:
            continue
        tails = np.array([v.tail for v in vs]) / mu
        heads = np.array([v.head for v in vs]) / mu
        pts += list(tails) + list(heads)
        _arrows(ax, tails, heads, _COLOURS[kind], 1.8 if kind == "absolute" else 1.2,
                "-" if kind in ("absolute", "tangential") else "--" if kind == "relative" else "-")
        kinds.append(kind)
        for v in vs:
            if kind != "absolute" and which == "acceleration" and v.value > 0:
                mid = (np.array(v.tail) + np.array(v.head)) / (2 * mu)
                ax.annotate(_ON_PLAN[kind], mid, xytext=(3, -9), textcoords="offset points",
                            fontsize=8, color=_COLOURS[kind], zorder=6)
            lines.append(f"{_vec_label(plan, v)} = {v.value:.4g} {_unit(u, lang)}, "
                         f"{v.value / mu:.1f} {_unit('mm', lang)}")
    # the images: their letters (one label per point of the plan)
    seen: dict[tuple, list[str]] = {}
    for point, xy in plan.images.items():
        key_xy = (round(xy[0] / mu, 3), round(xy[1] / mu, 3))
        seen.setdefault(key_xy, []).append(_image(plan.image_labels[point]))
    pole = "π" if which == "acceleration" else "p"
    for xy, labs in seen.items():
        if xy == (0.0, 0.0) or (abs(xy[0]) < 1e-9 and abs(xy[1]) < 1e-9):
            labs = [pole] + labs
        ax.plot(*xy, "o", markersize=3.2, color="k", zorder=5)
        ax.annotate(", ".join(labs), xy, xytext=(4, 4), textcoords="offset points", fontsize=10,
                    fontweight="bold", zorder=7)
    _frame_plan(ax, np.array(pts), lang)
    handles = [Line2D([], [], color=_COLOURS[k], linewidth=1.8 if k == "absolute" else 1.2,
                      linestyle="--" if k == "relative" else "-", label=_t(lang, k))
               for k in kinds]
    ax.legend(handles=handles, loc="lower left", bbox_to_anchor=(1.02, 0.0), borderaxespad=0.0,
              fontsize=8)
    lw = plan.links
    extra = [_t(lang, "omega", w=plan.omega, e=plan.epsilon)]
    name = "links_w" if which == "velocity" else "links_e"
    extra.append(_t(lang, name, x=", ".join(f"{n} {lw[n]:.4g}" for n in lw)))
    fig.text(1 - (_TABLE_W - 0.1) / 10.0, 1 - 0.75 / 7.0,
             "\n".join(_wrap(extra) + [""] + lines), va="top", ha="left", fontsize=7.5)
    what = _t(lang, which, p=nm.name(f"{which}_plan", lang), a=ps.phi_deg)
    ax.set_title(f"{_title(results, what)}, {_scale_text(key, mu, lang)}", loc="left", y=1.01)
    return fig


def _wrap(lines: list[str], width: int = 52) -> list[str]:
    out = []
    for s in lines:
        while len(s) > width:
            cut = s.rfind(", ", 0, width)
            if cut <= 0:
                break
            out.append(s[:cut + 1])
            s = "  " + s[cut + 2:]
        out.append(s)
    return out


def figure_velocity_plan(results, ps, lang: str = "en"):
    """The velocity plan at one report angle (``ps``: a dynamics.plans.PlanSet) to μ_v."""
    return _kinematic_plan(results, ps, "velocity", lang)


def figure_acceleration_plan(results, ps, lang: str = "en"):
    """The acceleration plan at one report angle to μ_a, with the normal, tangential and
    Coriolis components."""
    return _kinematic_plan(results, ps, "acceleration", lang)


# -- the force polygons ---------------------------------------------------------------------------

def figure_force_polygons(results, ps, lang: str = "en"):
    """The force polygon of every Assur group and of the crank at one report angle, each to
    its own μ_F (one panel each)."""
    from matplotlib.lines import Line2D

    polys = ps.polygons
    n = len(polys)
    ncols = min(n, 3)
    nrows = math.ceil(n / ncols)
    size = (4.6 * ncols + 2.6, 4.9 * nrows + 0.6)
    fig, axes = _figure(size, nrows, ncols, left=0.6, right=2.6, top=1.15, bottom=0.55,
                        wspace=0.3, hspace=0.42)
    used = set()
    for k, ax in enumerate(axes.flat):
        if k >= n:
            ax.set_visible(False)
            continue
        pg = polys[k]
        mu = pg.scale
        pts = [np.zeros(2)]
        for kind in ("weight", "inertia", "given", "known", "reaction", "reaction_n", "reaction_t"):
            vs = [v for v in pg.vectors if v.kind == kind]
            if not vs:
                continue
            used.add("reaction" if kind.startswith("reaction") else kind)
            tails = np.array([v.tail for v in vs]) / mu
            heads = np.array([v.head for v in vs]) / mu
            pts += list(tails) + list(heads)
            _arrows(ax, tails, heads, _COLOURS[kind], 1.5)
        if pg.chords:
            used.add("chord")
            tails = np.array([v.tail for v in pg.chords]) / mu
            heads = np.array([v.head for v in pg.chords]) / mu
            _arrows(ax, tails, heads, "0.45", 1.0, "--")
        for v in pg.vectors + pg.chords:
            mid = (np.array(v.tail) + np.array(v.head)) / (2 * mu)
            ax.annotate(f"{_force_label(v.label, lang)} {v.value:.5g}", mid, xytext=(3, 3),
                        textcoords="offset points", fontsize=7,
                        color=_COLOURS.get(v.kind, "k") if v not in pg.chords else "0.35",
                        zorder=6)
        _frame_plan(ax, np.array(pts), lang)
        what = (_t(lang, "crank", l=pg.links[0]) if pg.kind == "crank"
                else _t(lang, "group", g=pg.group, k=pg.kind, l=", ".join(pg.links)))
        scale = _scale_text("mu_F", mu, lang)
        ax.set_title(f"{what}\n{scale}; {_t(lang, 'closes', c=pg.closure)}", fontsize=8.5,
                     y=1.01)   # a fixed place: no layout pass for it
    order = ("weight", "inertia", "given", "known", "reaction", "chord")
    handles = [Line2D([], [], color=_COLOURS.get(k, "0.45"), linewidth=1.5,
                      linestyle="--" if k == "chord" else "-", label=_t(lang, k))
               for k in order if k in used]
    fig.legend(handles=handles, loc="upper left",
               bbox_to_anchor=(1 - 2.5 / size[0], 1 - 1.15 / size[1]), fontsize=8)
    what = _t(lang, "forces", p=nm.name("force_polygon", lang), a=ps.phi_deg)
    fig.suptitle(f"{_title(results, what)} ({_unit('N', lang)})", fontsize=10)
    return fig


# -- Zhukovsky's lever ----------------------------------------------------------------------------

def figure_lever(results, ps, lang: str = "en"):
    """Zhukovsky's lever at one report angle: the turned velocity plan to μ_v, every force at
    its point's image (drawn to μ_F), the couples' powers, the sum of the moments about the
    pole and M_y from it beside M_y of the kinetostatics."""
    lv = ps.lever
    mu, muF = lv.scale, lv.force_scale
    fig, axes = _figure((10.5, 7.4), right=4.1, top=0.95)
    ax = axes[0, 0]
    pts = [np.zeros(2)]
    # the lever: the rays from the pole to the images, and the images' letters
    imgs = {p: np.array(xy) / mu for p, xy in lv.images.items()}
    from matplotlib.collections import LineCollection

    rays = [np.stack([np.zeros(2), xy]) for xy in imgs.values() if np.hypot(*xy) > 1e-9]
    if rays:
        ax.add_collection(LineCollection(rays, colors="0.6", linewidths=1.0, zorder=2))
    pts += list(imgs.values())
    seen: dict[tuple, list[str]] = {}
    for p, xy in imgs.items():
        seen.setdefault((round(xy[0], 3), round(xy[1], 3)), []).append(_image(lv.image_labels[p]))
    for xy, labs in seen.items():
        if abs(xy[0]) < 1e-9 and abs(xy[1]) < 1e-9:
            labs = ["p"] + labs
        ax.plot(*xy, "o", markersize=3.2, color="k", zorder=5)
        ax.annotate(", ".join(labs), xy, xytext=(-12, 5), textcoords="offset points",
                    fontsize=10, fontweight="bold", zorder=7)
    lines = []
    for f in lv.forces + (lv.balancing_force,):
        tail = imgs[f.point]
        head = tail + np.array(f.force) / muF
        pts += [tail, head]
        colour = "k" if f.kind == "balancing" else _COLOURS[f.kind]
        _arrows(ax, tail[None, :], head[None, :], colour, 2.0 if f.kind == "balancing" else 1.3)
        F = float(np.hypot(*f.force))
        ax.annotate(_force_label(f.name, lang), head, xytext=(3, 3), textcoords="offset points",
                    fontsize=8, color=colour, zorder=6)
        if f.kind != "balancing" and F > 0:
            lines.append(_plain(_t(lang, "moment", n=_force_label(f.name, lang),
                                   h=f.moment / F / mu, p=f.moment)))
    for c in lv.couples:
        lines.append(_plain(_t(lang, "couple", n=_force_label(c.name, lang), l=c.link, m=c.M,
                               w=c.omega, p=c.moment)))
    fa = results.forces.analysis
    k = fa.balancing_moment[ps.index] if fa is not None else float("nan")
    Py = float(np.hypot(*lv.balancing_force.force)) * (1 if lv.balancing_moment >= 0 else -1)
    lines += ["", _plain(_t(lang, "lever_sum", s=lv.moment_of_loads)),
              _plain(_t(lang, "lever_My", m=lv.balancing_moment, k=k)),
              _plain(_t(lang, "lever_Py", p=Py))]
    _frame_plan(ax, np.array(pts), lang)
    fig.text(1 - 4.0 / 10.5, 1 - 0.95 / 7.4, "\n".join(_wrap(lines, 62)), va="top", ha="left",
             fontsize=7.5)
    what = _t(lang, "lever", p=nm.name("zhukovsky_lever", lang), a=ps.phi_deg)
    ax.set_title(f"{_title(results, what)}\n"
                 f"{_scale_text('mu_v', mu, lang)}, {_scale_text('mu_F', muF, lang)}",
                 fontsize=9.5, loc="left", y=1.01)
    return fig


# -- the positions drawing ------------------------------------------------------------------------

def figure_positions_plan(results, lang: str = "en", scheme=None):
    """The mechanism in its standard positions (every 30°: 12, or 24 over a 720° cycle)
    overlaid, numbered 0, 1, … as course projects number them (a 720° cycle's k and k + 12
    share a drawing: "k, k+12"), the crank pin's circle and the sliders' travel; the first
    position drawn in full (``scheme``: see :func:`_scheme`; None: not drawn), the sliders'
    dead centres dashed."""
    from matplotlib.lines import Line2D

    P = results.kinematics.points
    fig, axes = _figure((10.0, 8.0), right=2.9, top=0.7)
    ax = axes[0, 0]
    allr = np.concatenate([pm.r for pm in P.values()])
    size = 0.035 * float(max(np.ptp(allr[:, 0]), np.ptp(allr[:, 1]), 1e-9))
    def every_30(phi: float) -> bool:
        k = math.degrees(phi) / 30
        return abs(k - round(k)) < 1e-6

    std = [(lab, phi) for lab, phi in results.position_angles if every_30(phi)]
    dcs = [(lab, phi) for lab, phi in results.position_angles if (lab, phi) not in std]
    i0 = results.index_of(std[0][1]) if std else 0
    if scheme is not None:
        _scheme(ax, results, i0, size, scheme)
    links = results.links_drawn
    numbers: dict[int, list[int]] = {}
    for lab, phi in std:
        k = int(round(math.degrees(phi) / 30))
        numbers.setdefault(k % 12, []).append(k)
    segs, dsegs, drawn = [], [], set()
    for lab, phi in std + dcs:
        once = round(math.degrees(phi) % 360.0, 6)    # a 720° cycle repeats the geometry
        if once in drawn:
            continue
        drawn.add(once)
        i = results.index_of(phi % results.cycle)
        for _, pts in links:
            xy = np.array([P[p].r[i] for p in pts])
            for q in xy[1:]:
                (segs if (lab, phi) in std else dsegs).append(np.stack([xy[0], q]))
    from matplotlib.collections import LineCollection

    ax.add_collection(LineCollection(segs, colors="0.35", linewidths=0.8, zorder=2.6))
    if dsegs:
        ax.add_collection(LineCollection(dsegs, colors="C3", linewidths=0.8, linestyles="--",
                                         zorder=2.6))
    # the numbers: at the crank pin (outwards from the pivot) and at each slider's joint
    # (beyond its guide, on the side of the crank pin)
    pivot, tip = links[0][1][0], links[0][1][1]
    sliders, guides = {}, set()        # one slider per guide (an engine's pistons share one)
    for lm in results.kinematics.links.values():
        if lm.theta is not None and not np.any(lm.omega_q != 0) and lm.ref in P \
                and float(np.ptp(P[lm.ref].r, axis=0).max()) > 1e-12:
            r, th = P[lm.ref].r[0], float(lm.theta[0])
            line = (round(th % math.pi, 9), round(r[1] * math.cos(th) - r[0] * math.sin(th), 9))
            if line not in guides and lm.ref != tip:
                guides.add(line)
                sliders[lm.ref] = th              # the guide's direction [rad]
    for p in [tip, *sliders]:
        for k, ks in numbers.items():
            i = results.index_of(math.radians(30 * k))
            c = P[p].r[i]
            if p == tip:
                d = c - P[pivot].r[i]
                n = d / (np.hypot(*d) or 1.0)
                off = (11 * n[0], 11 * n[1])
            else:        # the side of the guide the crank pin is on: strokes apart
                th = sliders[p]
                u = (math.cos(th), math.sin(th))
                rel = P[tip].r[i] - c
                side = -1 if u[0] * rel[1] - u[1] * rel[0] < -1e-12 else 1
                off = (-20 * side * u[1], 20 * side * u[0])
            ax.annotate(", ".join(str(x) for x in ks), c, xytext=off, textcoords="offset points",
                        ha="center", va="center", fontsize=7.5, color="C0", zorder=8)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(nm.axis("x", lang))
    ax.set_ylabel(nm.axis("y", lang))
    handles = [Line2D([], [], color="0.35", linewidth=0.8,
                      label=_t(lang, "position_k", n=len(std) - 1)),
               Line2D([], [], color="C0", linewidth=0.8, label=_t(lang, "crank_circle"))]
    if dsegs:
        handles.append(Line2D([], [], color="C3", linestyle="--", linewidth=0.8,
                              label=_t(lang, "d_c")))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    what = _t(lang, "positions", p=nm.name("positions_plan", lang), n=len(std))
    ax.set_title(_title(results, what), loc="left", y=1.01)
    return fig


# -- the list -------------------------------------------------------------------------------------

def figures(results, lang: str = "en", scheme=None) -> list:
    """(file name, figure-building function) of the plans: the positions drawing, and at each
    report angle the velocity and acceleration plans, the force polygons and Zhukovsky's lever
    (linkage cases; none for a tabulated one). ``scheme``: render/plots.py's scheme drawing
    (:func:`_scheme`)."""
    if results.kinematics is None:
        return []
    out = [("plan_positions.png", lambda: figure_positions_plan(results, lang, scheme))]
    done = set()
    for ps in results.plans:
        a = _fmt_angle(ps.phi_deg)
        if a in done:
            continue
        done.add(a)
        out += [(f"plan_velocity_{a}.png", lambda ps=ps: figure_velocity_plan(results, ps, lang)),
                (f"plan_acceleration_{a}.png",
                 lambda ps=ps: figure_acceleration_plan(results, ps, lang)),
                (f"plan_forces_{a}.png", lambda ps=ps: figure_force_polygons(results, ps, lang)),
                (f"plan_lever_{a}.png", lambda ps=ps: figure_lever(results, ps, lang))]
    return out
