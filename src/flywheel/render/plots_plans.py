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

import numpy as np

from flywheel.io.text import in_language
from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.figure import A4_W, DPI
from flywheel.render.labels import AxesLabels, around
from flywheel.render.numbers import fmt as _number

_TEXT = words("plots_plans", {
    "velocity": "{p} at φ = {a}°",
    "acceleration": "{p} at φ = {a}°",
    "forces": "{p} at φ = {a}°",
    "lever": "{p} at φ = {a}° (the velocity plan turned 90° clockwise)",
    "positions": "{p}, {n} positions every 30°",
    "group": "group of links {l} ({k})",
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
    "closes": "closes to {c} N",
    "omega": "ω = {w} rad/s, ε = {e} rad/s²",
    "links_w": "ω of the links, rad/s: {x}",
    "links_e": "ε of the links, rad/s²: {x}",
    "lever_sum": "Σ moments about p, that is Σ powers of the forces: {s} W",
    "lever_My": "M_y = −Σ/ω = {m} N·m (kinetostatics: {k} N·m)",
    "lever_Py": "P_y = M_y/l₁ = {p} N at the crank pin",
    "couple": "{n} on link {l}: M·ω_i = {m} N·m · {w} rad/s = {p} W",
    "moment": "{n}: h = {h} mm, F·h·μᵥ = {p} W",
    "d_c": "dead centres",
    "position_k": "positions 0 … {n}",
    "crank_circle": "path of the crank pin",
})

_COLOURS = {"absolute": "k", "relative": "C0", "normal": "C0", "tangential": "C3",
            "coriolis": "C2", "sliding": "C4", "weight": "C2", "inertia": "C3", "given": "C1",
            "known": "C4", "reaction": "k", "reaction_n": "k", "reaction_t": "k"}


def _t(lang: str, key: str, **kw) -> str:
    text = _TEXT["ru" if lang == "ru" else "en"][key]
    # a bare float field: 4 significant digits, no exponent above 1 (:func:`_num`)
    kw = {k: _num(v) if isinstance(v, (float, np.floating)) and "{" + k + "}" in text else v
          for k, v in kw.items()}
    return text.format(**kw) if kw else text


def _plain(text: str) -> str:
    """The table's symbols in plain text (no mathtext: a parse per label is slow)."""
    return (text.replace("M_y", "My").replace("M_у", "Mу").replace("P_y", "Py")
            .replace("P_у", "Pу").replace("ω_i", "ωᵢ"))


def _figure(size, nrows=1, ncols=1, *, left=0.7, right=0.3, bottom=0.6, top=0.75,
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
    node i (named by the third, ``names(labels, results, i, size)``, once the figure is all
    drawn). ``scheme``: plots.py's (draw_fixed, draw_at, names), handed in by ``plots.all_figures`` (plots.py imports this
    module, so this one does not import it)."""
    draw_fixed, draw_at, _ = scheme
    draw_fixed(ax, results, size)
    draw_at(ax, results, i, size, names=False)   # named once everything is drawn


# -- labels ---------------------------------------------------------------------------------------

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _sub(x: str) -> str:
    """A subscript in plain text (mathtext costs a parse per label): digits as ₀ … ₉, anything
    else in brackets ("12" → "₁₂", "1,r4" → "(1,r4)")."""
    if not x:
        return ""
    return x.translate(_SUB) if x.isdigit() else f"({x})"


def _image(label: str) -> str:
    """An image's letter as the course writes it: "s2" → s₂, "a3" → a₃, "p′" → p′
    (mathfmt.point_name)."""
    from flywheel.render.mathfmt import point_name

    return point_name(label)


def _vec_label(plan, v) -> str:
    """The course's name of a plan's vector: pa, ab, πa; aⁿBA, aτBA, aᵏ, aʳ in the table."""
    lab = plan.image_labels
    if v.kind == "absolute":
        return ("π" if plan.quantity == "acceleration" else "p") + _image(lab[v.to])
    if plan.quantity == "velocity":
        return _image(lab[v.rel]) + _image(lab[v.to])
    sup = {"normal": "ⁿ", "tangential": "τ", "coriolis": "ᵏ", "sliding": "ʳ"}[v.kind]
    return f"a{sup} {_image(v.to)}{_image(v.rel)}"


_ON_PLAN = {"normal": "n", "tangential": "τ", "coriolis": "k", "sliding": "r"}


def _force_label(label: str, lang: str) -> str:
    """A force's name in plain text: "G_2" → G₂, "Φ_3" → Φ₃, "R_12^τ" → Rτ₁₂, "R_12^n" →
    Rⁿ₁₂, "M_Φ2" → MΦ₂, "F_HP" → F(HP), "P_y" → Pу in Russian; a load's label in two
    languages (io.text.Text, dynamics/plans.py) in ``lang``: «F_ВД» → F(ВД)."""
    base, _, sup = in_language(label, lang).partition("^")
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


#: characters of a plan's first title line: the narrowest plan figure holds about 75 at 10 pt
TITLE_CHARS = 70


def _title(results, what: str) -> str:
    """The case's title over what the figure shows, two lines. A title longer than
    TITLE_CHARS is shortened, not cut at the figure's edge: to its name before the first ": "
    ("Поперечно-строгальный станок: кривошипно-кулисный механизм …" → "Поперечно-строгальный
    станок"), else at a space, with "…"."""
    return f"{short_title(str(results.title))}\n{what}"


def short_title(title: str, chars: int = TITLE_CHARS) -> str:
    """``title`` if at most ``chars`` characters long, else its part before the first ": ",
    else its longest part before a ", " or a " (" that fits (a whole phrase, not one cut
    after «порядок работы»), if at least a third of ``chars``, else its words up to ``chars``
    − 1 characters and "…".

    >>> short_title("Shaper: crank and slotted lever quick-return mechanism with a ram", 40)
    'Shaper'
    >>> short_title("Four-stroke in-line four engine, firing order 1-3-4-2", 40)
    'Four-stroke in-line four engine'
    >>> short_title("A two-stage compressor (the worksheet's low-pressure column)", 40)
    'A two-stage compressor'
    >>> short_title("A very long machine name without any colon at all", 20)
    'A very long machine…'
    """
    if len(title) <= chars:
        return title
    head = title.split(": ", 1)[0]
    if len(head) < len(title) and len(head) <= chars:
        return head
    phrase = max(title.rfind(", ", 0, chars + 1), title.rfind(" (", 0, chars + 1))
    if phrase >= chars / 3:
        return title[:phrase]
    cut = title.rfind(" ", 0, chars)
    return (title[:cut] if cut > 0 else title[:chars - 1]).rstrip(" ,;:") + "…"


#: between the numbers of a list: «; » in Russian, where the comma is the decimal sign
_SEP = (", ", "; ")


def _scale_text(key: str, mu: float, lang: str) -> str:
    return f"{nm.tex(key, lang)} = {_number(mu, spec='g', zero=None)} {nm.unit_of(key, lang)}"


def _num(v: float, sig: int = 4) -> str:
    """A value to ``sig`` significant digits, never in exponent form above 1 (12345.6 →
    "12346", 253.92 → "253.9", 5.8861 → "5.886")."""
    return _number(v, sig, zero=None, nonfinite="show", integers_above=True)


def _clean(v: float, largest: float) -> float:
    """A value below 1e-9 of the largest of its kind is rounding noise: 0."""
    return 0.0 if abs(float(v)) <= 1e-9 * largest else float(v)


# -- the layout: axes placed by hand in inches, text placed off the lines ---------------------------

_PT = 72.0                  # points per inch
_CHAR_W = 0.56              # a character's mean width over the font size (DejaVu Sans)


def _limits(pts: np.ndarray, aspect_range=(0.55, 1.8)) -> tuple[np.ndarray, np.ndarray]:
    """The lower-left and upper-right corners [mm] of a plan's frame round ``pts``: a margin of
    12 % (at least 10 mm across), the shorter side widened so height/width stays in
    ``aspect_range`` (a flat polygon gets room for its labels, the page no empty band)."""
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = max(float(np.max(hi - lo)), 10.0)
    pad = 0.12 * span
    lo, hi = lo - pad, hi + pad
    w, h = float(hi[0] - lo[0]), float(hi[1] - lo[1])
    a_lo, a_hi = aspect_range
    if h < a_lo * w:
        extra = (a_lo * w - h) / 2
        lo, hi = lo - (0, extra), hi + (0, extra)
    elif h > a_hi * w:
        extra = (h / a_hi - w) / 2
        lo, hi = lo - (extra, 0), hi + (extra, 0)
    return lo, hi


def _set_frame(ax, lo, hi, lang: str, xlabel: bool = True) -> None:
    """Equal axes in mm over [lo, hi] (the axes' box already has the frame's aspect)."""
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_aspect("equal", adjustable="datalim")
    if xlabel:
        ax.set_xlabel(nm.with_unit(nm.name("plan_length", lang), nm.unit_of("plan_length", lang),
                                   lang))
    ax.grid(True, alpha=0.3)


_COL_GAP = 0.25             # between two columns of a table [in]


def _text_width(line: str, fontsize: float) -> float:
    """A line's width [in] at ``fontsize``, estimated from its characters (no renderer)."""
    return len(line) * _CHAR_W * fontsize / _PT


def _column_layout(lines: list[str], width: float, fontsize: float = 7.5,
                   max_cols: int = 4) -> tuple[int, list[float]]:
    """The most columns (up to ``max_cols``) :func:`_columns` can set ``lines`` in within
    ``width`` [in], each column as wide as its longest line: (rows, each column's left edge
    [in from the table's left])."""
    n = len(lines)
    for ncol in range(min(max_cols, max(n, 1)), 0, -1):
        rows = math.ceil(n / ncol) if n else 0
        xs, x = [], 0.0
        for c in range(ncol):
            chunk = lines[c * rows:(c + 1) * rows]
            if not chunk:
                break
            xs.append(x)
            x += max(_text_width(t, fontsize) for t in chunk) + _COL_GAP
        if x - _COL_GAP <= width or ncol == 1:
            return rows, xs
    return 0, []


def _legend_cols(labels: list[str], width: float, fontsize: float = 8.0,
                 max_cols: int = 6) -> int:
    """The most columns (up to ``max_cols``) a legend of ``labels`` fits in within ``width``
    [in], every column as wide as the widest entry (its line and padding: 0.55 in)."""
    entry = max([_text_width(t, fontsize) for t in labels] + [0.0]) + 0.55
    return max(1, min(max_cols, len(labels), int(width // entry)))


def _legend_height(n: int, ncols: int) -> float:
    """The height [in] of a legend of n entries (8 pt) in ``ncols`` columns."""
    return math.ceil(n / max(ncols, 1)) * 0.2 + 0.1


def _columns(fig, lines: list[str], x0: float, y0: float, width: float, H: float, W: float,
             fontsize: float = 7.5) -> None:
    """``lines`` as a compact table in columns below y0 [in from the bottom], from x0 [in]
    across ``width`` [in] (:func:`_column_layout`): one text per column (a text object per
    cell would cost a layout each)."""
    rows, xs = _column_layout(lines, width, fontsize)
    for c, x in enumerate(xs):
        chunk = lines[c * rows:(c + 1) * rows]
        fig.text((x0 + x) / W, y0 / H, "\n".join(chunk), va="top", ha="left",
                 fontsize=fontsize, linespacing=1.3)


def _table_height(lines: list[str], width: float, fontsize: float = 7.5) -> float:
    """The height [in] of :func:`_columns`'s table of ``lines``."""
    rows, _ = _column_layout(lines, width, fontsize)
    return rows * 1.3 * fontsize / _PT + 0.05


# -- the kinematic plans --------------------------------------------------------------------------

#: the plans' arrowheads: matplotlib's "-|>" (head_length 0.4, head_width 0.2 of the mutation
#: scale) at a mutation scale of 9 pt
_HEAD_SCALE = 9.0


def _heads(labels: AxesLabels, segs, width: float = 1.8) -> None:
    """The arrowheads :func:`_arrows` draws at the heads of ``segs`` ((tail, head) pairs [mm]),
    stroked ``width`` [pt], as obstacles to the labels (:meth:`AxesLabels.heads`)."""
    if segs:
        labels.heads([t for t, _ in segs], [h for _, h in segs],
                     0.4 * _HEAD_SCALE + width / 2, 0.2 * _HEAD_SCALE + width / 2)


def _arrows(ax, tails: np.ndarray, heads: np.ndarray, colour: str, width: float = 1.6,
            style: str = "-") -> None:
    """Arrows from tails to heads [mm], their heads a fixed size on the page. Added as artists,
    not patches: a plan's limits are its frame's (:func:`_set_frame`), so an arrow need not
    widen the data limits — which ``add_patch`` does by laying the arrow out in display space
    (its head's shape), a second time besides its drawing (a twentieth of a plan's time)."""
    from matplotlib.patches import FancyArrowPatch

    for t, h in zip(tails, heads):
        if float(np.hypot(*(h - t))) <= 1e-9:
            continue
        ax.add_artist(FancyArrowPatch(tuple(t), tuple(h), arrowstyle="-|>",
                                      mutation_scale=_HEAD_SCALE,
                                      shrinkA=0.0, shrinkB=0.0, color=colour, linewidth=width,
                                      linestyle=style, zorder=3))


def _plan_axes(fig, W: float, H: float, x: float, y: float, w: float, h: float):
    """An axes placed at (x, y), w × h [in] on a W × H [in] figure."""
    return fig.add_axes((x / W, y / H, w / W, h / H))


def _plan_box(lo, hi, max_w: float, max_h: float) -> tuple[float, float]:
    """The axes' size [in] that shows [lo, hi] [mm] at equal scales within max_w × max_h."""
    xs, ys = float(hi[0] - lo[0]), float(hi[1] - lo[1])
    w, h = max_w, max_w * ys / xs
    if h > max_h:
        w, h = max_h * xs / ys, max_h
    return w, h


def _kinematic_plan(results, ps, which: str, lang: str):
    """The velocity (``which`` "velocity") or the acceleration plan at one report angle: the
    plan to its scale, the legend in one row below it, then its values as a compact table
    (A4 text width, :data:`A4_W`; the height what the plan needs)."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    plan = ps.velocity if which == "velocity" else ps.acceleration
    key, u = ("mu_v", "m/s") if which == "velocity" else ("mu_a", "m/s²")
    mu = plan.scale
    pts = [np.zeros(2)]
    groups = []
    lines = []
    vmax = max([abs(float(v.value)) for v in plan.vectors] + [0.0])
    for kind in ("absolute", "relative", "normal", "tangential", "coriolis", "sliding"):
        vs = [v for v in plan.vectors if v.kind == kind]
        if not vs:
            continue
        tails = np.array([v.tail for v in vs]) / mu
        heads = np.array([v.head for v in vs]) / mu
        pts += list(tails) + list(heads)
        groups.append((kind, vs, tails, heads))
        for v in vs:
            val = _clean(v.value, vmax)
            lines.append(f"{_vec_label(plan, v)} = {_num(val)} {_unit(u, lang)}, "
                         f"{_number(val / mu, spec='.1f', zero=None)} {_unit('mm', lang)}")
    lo, hi = _limits(np.array(pts))
    W, left, right = A4_W, 0.7, 0.3
    aw, ah = _plan_box(lo, hi, W - left - right, 6.2)
    lw = plan.links
    wmax = max([abs(float(x)) for x in lw.values()] + [0.0])
    name, sym = ("links_w", "ω") if which == "velocity" else ("links_e", "ε")
    each = _SEP[lang == "ru"].join(f"{sym}{_sub(n)} = {_num(_clean(lw[n], wmax))}" for n in lw)
    head = f"{_t(lang, 'omega', w=plan.omega, e=plan.epsilon)}; {_t(lang, name, x=each)}"
    head = _wrap([head], int((W - left - right) / (_CHAR_W * 7.5 / _PT)))
    handles = [Line2D([], [], color=_COLOURS[k], linewidth=1.8 if k == "absolute" else 1.2,
                      linestyle="--" if k == "relative" else "-", label=_t(lang, k))
               for k, *_ in groups]
    ncols = _legend_cols([h.get_label() for h in handles], W - 0.2)
    top, below, leg = 0.55, 0.5, _legend_height(len(handles), ncols)
    t_h = _table_height(lines, W - left - right)
    h_h = len(head) * 1.3 * 7.5 / _PT + 0.08
    H = top + ah + below + leg + h_h + t_h + 0.1
    fig = Figure(figsize=(W, H), dpi=DPI)
    x_ax = left + (W - left - right - aw) / 2
    y_ax = H - top - ah
    ax = _plan_axes(fig, W, H, x_ax, y_ax, aw, ah)
    segs = [(t, h) for _, _, tails, heads in groups for t, h in zip(tails, heads)]
    _set_frame(ax, lo, hi, lang)
    labels = AxesLabels(ax)
    labels.segments(segs)
    _heads(labels, segs)
    for kind, vs, tails, heads in groups:
        _arrows(ax, tails, heads, _COLOURS[kind], 1.8 if kind == "absolute" else 1.2,
                "-" if kind in ("absolute", "tangential") else "--" if kind == "relative" else "-")
    # the images: their letters (one label per point of the plan)
    seen: dict[tuple, list[str]] = {}
    for point, xy in plan.images.items():
        key_xy = (round(xy[0] / mu, 3), round(xy[1] / mu, 3))
        seen.setdefault(key_xy, []).append(_image(plan.image_labels[point]))
    pole = "π" if which == "acceleration" else "p"
    labels.markers(list(seen), 2.6)
    for xy, labs in seen.items():
        if xy == (0.0, 0.0) or (abs(xy[0]) < 1e-9 and abs(xy[1]) < 1e-9):
            labs = [pole] + labs
        text = ", ".join(labs)
        ax.plot(*xy, "o", markersize=3.2, color="k", zorder=5)
        labels.point(xy, text, 4.0, fontsize=10.0, fontweight="bold", zorder=7)
    if which == "acceleration":
        for kind, vs, tails, heads in groups:
            if kind == "absolute":
                continue
            for v, t, h in zip(vs, tails, heads):
                if float(np.hypot(*(h - t))) >= 2.0:   # shorter than 2 mm: in the table only
                    labels.along(t, h, _ON_PLAN[kind], fontsize=8.0, color=_COLOURS[kind],
                                 zorder=6)
    y = y_ax - below
    fig.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, y / H),
               ncols=ncols, fontsize=8, frameon=False)
    y -= leg
    fig.text(left / W, y / H, "\n".join(head), va="top", ha="left", fontsize=7.5,
             linespacing=1.3)
    _columns(fig, lines, left, y - h_h, W - left - right, H, W)
    what = _t(lang, which, p=nm.name(f"{which}_plan", lang), a=ps.phi_deg)
    fig.text(left / W, 1 - 0.12 / H, f"{_title(results, what)}, {_scale_text(key, mu, lang)}",
             va="top", ha="left", fontsize=10)
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

def _rows_of(aspects: list[float], width: float, gap: float, max_h: float,
             max_total: float, row_extra: float) -> tuple[list[list[int]], float]:
    """The panels (height/width ``aspects``) in rows of one common axes height: the number of
    columns that gives the tallest axes [in] within ``width`` and ``max_total`` (rows' axes
    plus ``row_extra`` each). Returns the rows (panel indices) and the axes' height."""
    n = len(aspects)
    best = None
    for ncols in range(1, n + 1):
        rows = [list(range(k, min(k + ncols, n))) for k in range(0, n, ncols)]
        h = max_h
        for row in rows:
            h = min(h, (width - gap * len(row)) / sum(1.0 / aspects[k] for k in row))
        h = min(h, max_total / len(rows) - row_extra)
        if best is None or h > best[1] + 1e-9:
            best = (rows, h)
    return best


def _within_width(rows: list[list[int]], aspects: list[float], natural: list[float], ah: float,
                  width: float, gap: float) -> list[float]:
    """The panels' aspects (height/width) with each row within ``width`` [in]: a row whose
    panels, widened beyond their polygons (``natural`` aspects) to their titles' width, would
    run past the figure's edge gives up that widening in proportion (the polygons' own widths
    fit: :func:`_rows_of` chose the rows for them). Axes height ``ah`` [in], ``gap`` [in]
    before each panel."""
    out = list(aspects)
    for row in rows:
        own = [ah / natural[k] for k in row]
        extra = [ah / aspects[k] - w for k, w in zip(row, own)]
        excess = sum(own) + sum(extra) + gap * len(row) - width
        if excess > 1e-9 and sum(extra) > 0:
            keep = max(0.0, 1.0 - excess / sum(extra))
            for k, w, e in zip(row, own, extra):
                out[k] = ah / (w + e * keep)
    return out


def figure_force_polygons(results, ps, lang: str = "en"):
    """The force polygon of every Assur group and of the crank at one report angle, each to
    its own μ_F (one panel each; the panels in rows of one height, each as wide as its polygon
    needs, A4 text width :data:`A4_W`: as many a row as fit, the rest stacked below), the
    values beside the vectors (4 significant digits), the legend below in as many columns as
    fit."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    polys = ps.polygons
    frames = []
    for pg in polys:
        mu = pg.scale
        vecs = [v for v in pg.vectors] + list(pg.chords)
        pts = np.array([np.zeros(2)] + [np.array(v.tail) / mu for v in vecs]
                       + [np.array(v.head) / mu for v in vecs])
        frames.append(_limits(pts))
    aspects = [float((hi - lo)[1] / (hi - lo)[0]) for lo, hi in frames]
    W, left, right, gap = A4_W, 0.1, 0.15, 0.6       # gap: each panel's y tick labels [in]
    title_h, row_extra = 0.75, 1.5          # title above, tick labels and x label below [in]
    natural = list(aspects)
    for _ in range(2):      # each panel at least as wide as its title (1.9 in)
        rows, ah = _rows_of(aspects, W - left - right, gap, 4.5, 9.0, row_extra)
        aspects = [min(a, ah / 1.9) for a in aspects]
    aspects = _within_width(rows, aspects, natural, ah, W - left - right, gap)
    for k, (lo, hi) in enumerate(frames):        # a frame widened to its panel's aspect
        extra = (float(hi[1] - lo[1]) / aspects[k] - float(hi[0] - lo[0])) / 2
        frames[k] = (lo - (extra, 0.0), hi + (extra, 0.0))
    order = ("weight", "inertia", "given", "known", "reaction", "chord")
    used = {"reaction" if v.kind.startswith("reaction") else v.kind
            for pg in polys for v in pg.vectors} | ({"chord"} if any(pg.chords for pg in polys)
                                                    else set())
    handles = [Line2D([], [], color=_COLOURS.get(k, "0.45"), linewidth=1.5,
                      linestyle="--" if k == "chord" else "-", label=_t(lang, k))
               for k in order if k in used]
    ncols = _legend_cols([h.get_label() for h in handles], W - 0.2, max_cols=3)
    top, leg = 0.6, _legend_height(len(handles), ncols)
    H = top + len(rows) * (ah + row_extra) + leg
    fig = Figure(figsize=(W, H), dpi=DPI)
    for r, row in enumerate(rows):
        widths = [ah / aspects[k] for k in row]
        x = left + (W - left - right - sum(widths) - gap * len(row)) / 2
        y = H - top - r * (ah + row_extra) - title_h - ah
        for k, aw in zip(row, widths):
            x += gap
            ax = _plan_axes(fig, W, H, x, y, aw, ah)
            x += aw
            pg = polys[k]
            mu = pg.scale
            lo, hi = frames[k]
            segs = []
            for kind in ("weight", "inertia", "given", "known", "reaction", "reaction_n",
                         "reaction_t"):
                vs = [v for v in pg.vectors if v.kind == kind]
                if not vs:
                    continue
                tails = np.array([v.tail for v in vs]) / mu
                heads = np.array([v.head for v in vs]) / mu
                segs += list(zip(tails, heads))
                _arrows(ax, tails, heads, _COLOURS[kind], 1.5)
            if pg.chords:
                tails = np.array([v.tail for v in pg.chords]) / mu
                heads = np.array([v.head for v in pg.chords]) / mu
                segs += list(zip(tails, heads))
                _arrows(ax, tails, heads, "0.45", 1.0, "--")
            for grow in (1.0, 1.15, 1.3):    # a label left the frame: the frame grown
                mid, half = (lo + hi) / 2, (hi - lo) / 2 * grow
                _set_frame(ax, mid - half, mid + half, lang)
                if _force_labels(ax, pg, segs, lang, keep=grow == 1.3):
                    break
            what = (_t(lang, "crank", l=pg.links[0]) if pg.kind == "crank"
                    else _t(lang, "group", k=nm.dyad_kind(pg.kind, lang), l=", ".join(pg.links)))
            scale = _scale_text("mu_F", mu, lang)
            closes = _t(lang, "closes", c=_clean(pg.closure, pg.longest))   # round-off: 0
            ax.set_title(f"{what}\n{scale}\n{closes}", fontsize=8.5,
                         y=1.01)   # a fixed place: no layout pass for it
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.05 / H),
               ncols=ncols, fontsize=8, frameon=False)
    what = _t(lang, "forces", p=nm.name("force_polygon", lang), a=ps.phi_deg)
    fig.suptitle(f"{_title(results, what)} ({_unit('N', lang)})", fontsize=10,
                 y=1 - 0.1 / H, va="top")
    return fig


def _force_labels(ax, pg, segs, lang: str, keep: bool = False) -> bool:
    """The values of a force polygon's vectors beside them, the longest first (the short
    vectors' labels then find room round them); whether every label stays inside the frame
    — where one does not, they are all taken away again (the caller grows the frame), unless
    ``keep``."""
    labels = AxesLabels(ax)
    labels.segments(segs)
    _heads(labels, segs, 1.5)
    mu, placed = pg.scale, []
    for v in sorted(pg.vectors + pg.chords, key=lambda v: -float(v.value)):
        placed.append(labels.along(
            np.array(v.tail) / mu, np.array(v.head) / mu,
            f"{_force_label(v.label, lang)} {_num(v.value)}", fontsize=7.0,
            color=_COLOURS.get(v.kind, "k") if v not in pg.chords else "0.35", zorder=6))
    f0, g0, f1, g1 = labels.placer.frame
    boxes = ax.figure.flywheel_labels[-len(placed):]
    if keep or all(f0 <= b[0] and g0 <= b[1] and b[2] <= f1 and b[3] <= g1 for _, b in boxes):
        return True
    for a in placed:
        a.remove()
    del ax.figure.flywheel_labels[-len(placed):]
    return False


# -- Zhukovsky's lever ----------------------------------------------------------------------------

def figure_lever(results, ps, lang: str = "en"):
    """Zhukovsky's lever at one report angle: the turned velocity plan to μ_v, every force at
    its point's image (drawn to μ_F), and below it the forces' arms and powers, the couples'
    powers, the sum of the moments about the pole and M_y from it beside M_y of the
    kinetostatics (A4 text width, :data:`A4_W`)."""
    from matplotlib.collections import LineCollection
    from matplotlib.figure import Figure

    lv = ps.lever
    mu, muF = lv.scale, lv.force_scale
    pts = [np.zeros(2)]
    imgs = {p: np.array(xy) / mu for p, xy in lv.images.items()}
    pts += list(imgs.values())
    arrows = []
    lines = []
    for f in lv.forces + (lv.balancing_force,):
        tail = imgs[f.point]
        head = tail + np.array(f.force) / muF
        pts += [tail, head]
        arrows.append((f, tail, head))
        F = float(np.hypot(*f.force))
        if f.kind != "balancing" and F > 0:
            lines.append(_plain(_t(lang, "moment", n=_force_label(f.name, lang),
                                   h=f.moment / F / mu, p=f.moment)))
    for c in lv.couples:
        lines.append(_plain(_t(lang, "couple", n=_force_label(c.name, lang), l=c.link, m=c.M,
                               w=c.omega, p=c.moment)))
    fa = results.forces.analysis
    k = fa.balancing_moment[ps.index] if fa is not None else float("nan")
    Py = float(np.hypot(*lv.balancing_force.force)) * (1 if lv.balancing_moment >= 0 else -1)
    sums = [_plain(_t(lang, "lever_sum", s=lv.moment_of_loads)),
            _plain(_t(lang, "lever_My", m=lv.balancing_moment, k=k)),
            _plain(_t(lang, "lever_Py", p=Py))]
    lo, hi = _limits(np.array(pts))
    W, left, right = A4_W, 0.7, 0.3
    aw, ah = _plan_box(lo, hi, W - left - right, 6.2)
    top, below = 0.75, 0.55
    t_h = _table_height(lines, W - left - right)
    s_h = len(sums) * 1.3 * 7.5 / _PT + 0.1
    H = top + ah + below + t_h + s_h + 0.1
    fig = Figure(figsize=(W, H), dpi=DPI)
    y_ax = H - top - ah
    ax = _plan_axes(fig, W, H, left + (W - left - right - aw) / 2, y_ax, aw, ah)
    rays = [np.stack([np.zeros(2), xy]) for xy in imgs.values() if np.hypot(*xy) > 1e-9]
    if rays:
        ax.add_collection(LineCollection(rays, colors="0.6", linewidths=1.0, zorder=2))
    _set_frame(ax, lo, hi, lang)
    labels = AxesLabels(ax)
    labels.segments([(np.zeros(2), r[1]) for r in rays] + [(t, h) for _, t, h in arrows])
    _heads(labels, [(t, h) for _, t, h in arrows], 2.0)
    seen: dict[tuple, list[str]] = {}
    for p, xy in imgs.items():
        seen.setdefault((round(xy[0], 3), round(xy[1], 3)), []).append(_image(lv.image_labels[p]))
    labels.markers(list(seen), 2.6)
    first = np.vstack([[(-12.0, 5.0, 0.0, 0.0)], around(4.0)[1:]])
    for xy, labs in seen.items():
        if abs(xy[0]) < 1e-9 and abs(xy[1]) < 1e-9:
            labs = ["p"] + labs
        text = ", ".join(labs)
        ax.plot(*xy, "o", markersize=3.2, color="k", zorder=5)
        labels.point(xy, text, places=first, fontsize=10.0, fontweight="bold", zorder=7)
    for f, tail, head in arrows:
        colour = "k" if f.kind == "balancing" else _COLOURS[f.kind]
        _arrows(ax, tail[None, :], head[None, :], colour, 2.0 if f.kind == "balancing" else 1.3)
        labels.along(tail, head, _force_label(f.name, lang), fontsize=8.0, color=colour,
                     zorder=6)
    y = y_ax - below
    _columns(fig, lines, left, y, W - left - right, H, W)
    fig.text(left / W, (y - t_h - 0.05) / H, "\n".join(sums), va="top", ha="left",
             fontsize=7.5, linespacing=1.3)
    what = _t(lang, "lever", p=nm.name("zhukovsky_lever", lang), a=ps.phi_deg)
    fig.text(left / W, 1 - 0.12 / H, f"{_title(results, what)}\n"
             f"{_scale_text('mu_v', mu, lang)}, {_scale_text('mu_F', muF, lang)}",
             va="top", ha="left", fontsize=9.5)
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
    fig, axes = _figure((A4_W, A4_W), left=0.75, right=0.25, top=0.6, bottom=0.95)
    ax = axes[0, 0]
    allr = np.concatenate([pm.r for pm in P.values()])
    size = 0.035 * float(max(np.ptp(allr[:, 0]), np.ptp(allr[:, 1]), 1e-9))
    nums = results.position_numbers()          # the one numbering: the CSVs and the report's
    std = [(p.label, p.phi) for p in results.position_angles if p.number is not None]
    dcs = [(p.label, p.phi) for p in results.position_angles if p.number is None]
    i0 = results.index_of(std[0][1]) if std else 0
    if scheme is not None:
        _scheme(ax, results, i0, size, scheme)
    links = results.links_drawn
    numbers: dict[int, list[int]] = {}
    for k in nums:
        if k is not None:
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
    # the names of the scheme, then the numbers, by the one placer (render/labels.py): a
    # number on a label or a marker moves out, 9 pt a step (the sliders' positions crowd near
    # their dead centres)
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.1)          # room inside the frame for the numbers set outwards of the drawing
    labels = AxesLabels(ax)
    labels.segments([(q[0], q[1]) for q in segs + dsegs])
    if scheme is not None:
        scheme[2](labels, results, i0, size)
    steps = np.arange(6)
    for p in [tip, *sliders]:
        for k, ks in numbers.items():
            i = results.index_of(math.radians(30 * k))
            c = P[p].r[i]
            if p == tip:
                d = c - P[pivot].r[i]
                n, dist = d / (np.hypot(*d) or 1.0), 11.0
            else:        # the side of the guide the crank pin is on: strokes apart
                th = sliders[p]
                u = (math.cos(th), math.sin(th))
                rel = P[tip].r[i] - c
                side = -1 if u[0] * rel[1] - u[1] * rel[0] < -1e-12 else 1
                n, dist = np.array([-side * u[1], side * u[0]]), 20.0
            places = np.column_stack([(dist + 9 * steps) * n[0], (dist + 9 * steps) * n[1],
                                      np.full(6, 0.5), np.full(6, 0.5)])
            anchor = labels.to_pt(c)
            labels.best(np.repeat(anchor, 6, axis=0), places, 2.0 * steps,
                        ", ".join(str(x) for x in ks), fontsize=7.5, color="C0", zorder=8)
    ax.set_xlabel(nm.axis("x", lang))
    ax.set_ylabel(nm.axis("y", lang))
    handles = [Line2D([], [], color="0.35", linewidth=0.8,
                      label=_t(lang, "position_k", n=len(std) - 1)),
               Line2D([], [], color="C0", linewidth=0.8, label=_t(lang, "crank_circle"))]
    if dsegs:
        handles.append(Line2D([], [], color="C3", linestyle="--", linewidth=0.8,
                              label=_t(lang, "d_c")))
    fig.legend(handles=handles, loc="lower center", bbox_to_anchor=(0.5, 0.02),
               ncols=len(handles), frameon=False)
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
