"""The figure toolkit every plot of ``flywheel run`` is drawn with (render/plots.py,
plots_forces.py, plots_engine.py, animate.py; plots_extra.py's figures are drawn inside
:func:`style`): the fixed style, pyplot-free figures with fixed margins, the legends below the
axes (figures as wide as A4's text, :data:`A4_W`: no width lost to a legend), the φ axis,
the titles (labels beside points and vectors: render/labels.py, the one placer).

The figures are plain :class:`matplotlib.figure.Figure` objects rendered by the Agg canvas:
they never go through pyplot, so they need no display, register no global state (nothing to
leak or to close) and leave the caller's backend alone (a notebook keeps its own). The style is
reset to matplotlib's defaults plus a few fixed settings for every figure, so a user's
matplotlibrc cannot change the files; with fixed sizes, dpi and no metadata the files are the
same for the same input. matplotlib is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations

from contextlib import contextmanager

import numpy as np

from flywheel.render import nomenclature as nm
from flywheel.render.choices import DPI_RANGE, FIGURE_FORMATS  # noqa: F401 (DPI_RANGE re-exported)

DPI = 120
LEGEND_W = 3.9            # room for a legend right of the axes [in]
WIDE = (11.0, 5.0)         # one φ plot and its legend [in]
TALL = (11.0, 7.0)         # two stacked φ plots [in]
A4_W = 7.45               # a figure as wide as A4's text [in]
RC = {
    "font.family": "DejaVu Sans",
    "mathtext.fontset": "dejavusans",
    "font.size": 9.0,
    "axes.titlesize": 10.0,
    "axes.labelsize": 9.0,
    "legend.fontsize": 8.0,
    "axes.grid": True,
    "grid.alpha": 0.35,
    "lines.linewidth": 1.4,
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    # the title at the top of its axes, not placed by measuring every tick label (a tenth of
    # a figure's time): no figure has tick labels or an x label above its axes; an axis's
    # offset text ("1e5") is kept clear of the title by its own position (left)
    "axes.titley": 1.0,
}

#: the line styles of a figure's curves past the ten colours of the cycle: the 11th curve
#: dashed in the first colour, … (a figure of many like curves: engine_inline4's 13 reactions)
SERIES_STYLES = ("-", "--", "-.", ":")


def series(k: int) -> dict:
    """The colour and line style of a figure's curve ``k`` (from 0) of many like ones: the
    cycle's ten colours, then again dashed, dash-dotted, dotted — no two curves alike up to 40.

    >>> series(0), series(10)
    ({'color': 'C0', 'linestyle': '-'}, {'color': 'C0', 'linestyle': '--'})
    """
    return {"color": f"C{k % 10}", "linestyle": SERIES_STYLES[(k // 10) % len(SERIES_STYLES)]}


FORMATS = FIGURE_FORMATS             # `run --figure-format`; DPI_RANGE: `run --dpi`
SVG_SALT = "flywheel"                # svg.hashsalt: the same ids in the SVG on every run

_styled = 0        # depth of nested style() blocks: only the outermost one sets the style


@contextmanager
def style(lang: str = "en"):
    """matplotlib's defaults plus :data:`RC`, whatever the user's matplotlibrc says; the
    caller's settings come back on exit. ``lang`` "ru": the figures drawn inside are Russian
    figures — their tick labels (:func:`_russian_ticks`) and every number a figure's text takes
    from the one formatter in Russian typography (render/numbers.py)."""
    global _styled
    if _styled:
        yield
        return
    import matplotlib

    from flywheel.render import figure_cache as fc
    from flywheel.render import mathparse, ticks
    from flywheel.render.numbers import typography

    with matplotlib.rc_context(), typography(lang):
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(RC)
        _styled += 1
        restore = fc.share_text_metrics()
        restore_fonts = fc.remember_fonts()
        restore_ticks = _russian_ticks() if lang == "ru" else (lambda: None)
        restore_math = fc.share_mathtext()
        restore_parse = mathparse.install()
        restore_copies = ticks.install()
        restore_markers = fc.copy_markers_shallow()
        restore_texts = fc.share_text_images()
        restore_tables = fc.share_font_tables()
        try:
            yield
        finally:
            restore_tables()
            restore_texts()
            restore_markers()
            restore_copies()
            restore_parse()
            restore_math()
            restore_ticks()
            restore_fonts()
            restore()
            _styled -= 1


def _tick_decimals(locs) -> int | None:
    """The decimals that tell ticks ``locs`` apart: those of their spacing (0.25 → 2, 30 → 0);
    None for fewer than two ticks."""
    xs = sorted(set(float(x) for x in locs))
    steps = [b - a for a, b in zip(xs, xs[1:]) if b - a > 0]
    if not steps:
        return None
    step = min(steps)
    for d in range(12):
        scaled = step * 10.0 ** d
        if abs(scaled - round(scaled)) <= 1e-6 * max(1.0, scaled):
            return d
    return None


def _russian_ticks():
    """Within :func:`style` of a Russian figure, every linear axis made gets a FuncFormatter
    that writes its tick values through the one formatter in Russian typography (decimal
    comma, true minus, thin spaces in long numbers, never an exponent or an offset), to the
    decimals of the ticks' spacing. matplotlib's locale support (``axes.formatter.use_locale``)
    would depend on the machine's locale: not used. Returns the function that undoes it."""
    from matplotlib import scale
    from matplotlib.ticker import FuncFormatter

    from flywheel.render.numbers import fmt, typography

    # a linear axis, and a secondary axis of a function of another's values (the indicator
    # diagrams' p [MPa] beside p/p_max), which matplotlib gives a FuncScale
    owns = {cls: cls.set_default_locators_and_formatters
            for cls in (scale.LinearScale, scale.FuncScale)}

    def ticks(self, axis):
        next(own for cls, own in owns.items() if isinstance(self, cls))(self, axis)

        locs: list = []                  # the ticks about to be labelled (set_locs)

        def label(x, pos=None):
            d = _tick_decimals(locs)
            with typography("ru"):
                return fmt(x, spec=None if d is None else f".{d}f")

        def set_locs(values) -> None:
            locs[:] = [float(v) for v in values]
        formatter = FuncFormatter(label)
        formatter.set_locs = set_locs
        axis.set_major_formatter(formatter)

    for cls in owns:
        cls.set_default_locators_and_formatters = ticks

    def restore() -> None:
        for cls, own in owns.items():
            cls.set_default_locators_and_formatters = own
    return restore


def prepare() -> None:
    """Import what drawing and saving a figure needs (matplotlib's figure and Agg canvas: 0.35 s
    of CPU) and build mathtext's parser (its grammar, 25 ms): called by the first plot worker
    before it forks the others, so that they share this instead of each making its own. Then
    every object made so far (the modules, the results) is moved out of the garbage
    collector's generations (``gc.freeze``): it lives as long as the worker, and the
    collector's passes while drawing — about 260 for the compressor's figures — no longer
    traverse it (their time 0.17 – 0.24 s → 0.07 – 0.08 s), nor touch its memory pages in the
    forked workers."""
    import gc

    import matplotlib.backends.backend_agg  # noqa: F401
    import matplotlib.figure  # noqa: F401
    from matplotlib import _mathtext
    from matplotlib.mathtext import MathTextParser

    if getattr(MathTextParser, "_parser", None) is None and hasattr(_mathtext, "Parser"):
        MathTextParser._parser = _mathtext.Parser()         # as its first parse would
    gc.freeze()


def figure(size, nrows=1, ncols=1, sharex=False, squeeze=True, *, left=0.85, right=LEGEND_W,
           bottom=0.6, top=0.4, hspace=0.35, wspace=0.45):
    """A pyplot-free Figure and its axes, with fixed margins given in inches (a layout engine
    would cost half the time of a plot). ``right`` leaves room for a legend outside the axes
    (:func:`legend` and :func:`legends_below` then cut the figure to the axes)."""
    from matplotlib.figure import Figure

    w, h = size
    fig = Figure(figsize=size, dpi=DPI)
    axes = fig.subplots(nrows, ncols, sharex=sharex, squeeze=squeeze)
    fig.subplots_adjust(left=left / w, right=1 - right / w, bottom=bottom / h, top=1 - top / h,
                        hspace=hspace, wspace=wspace)
    return fig, axes


def drawn(build):
    """Run ``build`` inside the fixed style; return its figure."""
    with style():
        return build()


def title(results, what: str) -> str:
    """A figure's title: the case's title, then what the figure shows."""
    return f"{results.title}: {what}"


def phi_axis(ax, lang: str, label: bool = True, cycle_deg: int = 360) -> None:
    """φ over the cycle (360°, 720° …), a tick every 30° per revolution; labelled from the
    nomenclature unless ``label`` is False."""
    ax.set_xlim(0.0, float(cycle_deg))
    ax.set_xticks(np.arange(0, cycle_deg + 1, 30 * cycle_deg // 360))
    if label:
        ax.set_xlabel(nm.axis("phi_deg", lang))


def legend(ax, **kw):
    """A legend that never hides a curve: a figure of one axes gets it below the axes, in one
    or two columns, and loses the room on the right the legend would have taken (the figure
    cut to the axes' width: nothing wasted, issue 15). Stacked axes are laid out together by
    :func:`legends_below` instead; called on one of them, this puts its legend on the right."""
    if len(ax.figure.axes) == 1:
        return _legend_below(ax, **kw)
    return ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0, **kw)


_ROW_H = 0.18             # a legend row at 8 pt [in]
_RIGHT_BELOW = 0.35       # the right margin of a figure whose legend is below [in]
_GAP = 0.08               # between a panel (or its tick labels) and its legend [in]
_XLABEL_H = 0.48          # a panel's x tick labels and axis label [in]
_EDGE = 0.06              # at least this between a y axis's label and the figure's edge [in]


def legends_below(fig, axes, *, max_cols: int = 4, right: float = _RIGHT_BELOW):
    """Stacked axes (one column, drawn with :func:`figure`): each panel's legend below it, in
    as many columns (up to ``max_cols``) as fit the panel's width, measured; the figure cut to
    the panels' width (``right`` [in] kept on the right) and made taller by the legends, the
    panels keeping their size in inches — no width lost to a legend on the right (issue 15)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    w, h = (float(x) for x in fig.get_size_inches())
    sp = fig.subplotpars
    left, top = sp.left * w, (1 - sp.top) * h
    ax_w = (sp.right - sp.left) * w
    new_w = left + ax_w + right
    renderer = FigureCanvasAgg(fig).get_renderer()
    need = _left_room(axes, renderer)             # the figure's width kept: the panels narrower
    if need > left:
        ax_w, left = ax_w - (need - left), need
    top += _fit_title(axes[0], ax_w + 2 * min(left, right), renderer)   # centred on the axes
    rows = []                                     # (axes, its height, its legend's height) [in]
    for ax in axes:
        handles, labels = ax.get_legend_handles_labels()
        leg, leg_h = None, 0.0
        for n in range(min(max_cols, len(labels)), 0, -1):
            leg = ax.legend(handles, labels, loc="upper center", ncols=n, frameon=False,
                            borderaxespad=0.0, borderpad=0.2)
            bb = leg.get_window_extent(renderer)
            leg_h = bb.height / DPI
            if bb.width / DPI <= ax_w + right or n == 1:
                break
        rows.append((ax, ax.get_position().height * h, leg, leg_h))
    below = [(_XLABEL_H if ax.get_xlabel() else 0.0) + (_GAP + leg_h if leg else 0.0)
             for ax, _, leg, leg_h in rows]
    new_h = top + sum(r[1] for r in rows) + sum(below) + 0.12 * (len(rows) - 1) + 0.08
    fig.set_size_inches(new_w, new_h)
    y = new_h - top                               # from the bottom, in inches
    for (ax, ax_h, leg, _), room in zip(rows, below):
        y -= ax_h
        ax.set_position([left / new_w, y / new_h, ax_w / new_w, ax_h / new_h])
        if leg is not None:
            under = y - (_XLABEL_H if ax.get_xlabel() else 0.0) - _GAP
            leg.set_bbox_to_anchor(((left + ax_w / 2) / new_w, under / new_h),
                                   transform=fig.transFigure)
        y -= room + 0.12
    return fig




def _left_room(axes, renderer) -> float:
    """The room [in] left of ``axes`` their y axes' tick labels and axis labels take, with
    :data:`_EDGE` to spare (wide tick labels such as "−0.0100" pushed a label to the figure's
    edge under the fixed margin)."""
    need = 0.0
    for ax in axes:
        if _left_bound(ax) + _EDGE <= ax.get_position().x0 * ax.figure.get_figwidth():
            continue                              # fits whatever the glyphs: not measured
        bb = ax.yaxis.get_tightbbox(renderer)
        if bb is not None:
            need = max(need, (ax.get_window_extent(renderer).x0 - bb.x0) / ax.figure.dpi + _EDGE)
    return need


def _left_bound(ax) -> float:
    """An upper bound [in] of the room left of ``ax`` its y tick labels and axis label take:
    the widest tick label's characters at DejaVu Sans's advances (digits 0.64 em, the minus
    0.84 em, points, commas and spaces 0.32 em, any other character a whole em), the tick,
    its pad, the label's pad and the label's line (measuring them costs a tick layout, 3 ms
    an axes)."""
    import matplotlib

    rc = matplotlib.rcParams
    labels = ax.yaxis.get_major_formatter().format_ticks(list(ax.yaxis.get_major_locator()()))
    ems = max((sum(_EM.get(c, 1.0) for c in t) for t in labels), default=0.0)
    size = float(rc["font.size"])
    return (ems * size + rc["ytick.major.size"] + rc["ytick.major.pad"]
            + rc["axes.labelpad"] + 1.25 * size) / 72.0


#: DejaVu Sans's advance widths [em] of the characters of tick labels (0.636 a digit, 0.838
#: the minus, 0.318 a point, a comma or a space, 0.2 a thin space), each 0.07 em more: a
#: hinted advance is rounded to whole pixels (an em is 15 px at 9 pt and 120 dpi)
_EM = {**dict.fromkeys("0123456789", 0.71), "−": 0.91, "-": 0.43, ".": 0.39, ",": 0.39,
       " ": 0.39, "\u2009": 0.27, "\u202f": 0.27}


def fit_left(fig, axes) -> None:
    """``axes`` (of a :func:`figure` with fixed margins) made narrower from the left, their
    right edges kept, until their y axes' tick labels and labels fit in the figure; nothing
    moves if they fit."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    w = float(fig.get_size_inches()[0])
    need = _left_room(axes, FigureCanvasAgg(fig).get_renderer()) / w
    for ax in axes:
        pos = ax.get_position()
        if need > pos.x0:
            ax.set_position([need, pos.y0, pos.x1 - need, pos.height])


def _legend_below(ax, **kw):
    """:func:`legend` for a figure of one axes: the figure is resized (the axes keep their size
    in inches) so that the legend's rows fit under the axis label, and the title (set before)
    is broken into lines if wider than the figure."""
    import math
    import re

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = ax.figure
    w, h = (float(x) for x in fig.get_size_inches())
    sp = fig.subplotpars
    left, right, bottom, top = sp.left * w, (1 - sp.right) * w, sp.bottom * h, (1 - sp.top) * h
    labels = [t for t in ax.get_legend_handles_labels()[1] if not t.startswith("_")]
    visible = [len(re.sub(r"\\[A-Za-z]+|[$_^{}]", "", t)) for t in labels]   # mathtext's markup
    ncols = 2 if len(labels) > 1 and max(visible) <= 46 else 1
    rows = math.ceil(len(labels) / ncols)
    leg_h = rows * _ROW_H + 0.15
    room = w - left - right + 2 * min(left, _RIGHT_BELOW)        # the title: centred on the axes
    if _may_overflow(ax.title, room):
        top += _fit_title(ax, room, FigureCanvasAgg(fig).get_renderer())
    new_w = w - right + _RIGHT_BELOW
    new_h = h + leg_h + top - (1 - sp.top) * h
    fig.set_size_inches(new_w, new_h)
    fig.subplots_adjust(left=left / new_w, right=1 - _RIGHT_BELOW / new_w,
                        bottom=(bottom + leg_h) / new_h, top=1 - top / new_h)
    return ax.legend(loc="upper center", bbox_to_anchor=(0.5, (leg_h + 0.02) / new_h),
                     bbox_transform=fig.transFigure, ncols=ncols, frameon=False,
                     borderaxespad=0.0, **kw)


def fit_heading(fig, text, width: float) -> float:
    """Break ``text`` (a title or suptitle of ``fig``, a figure of :func:`figure`) into lines
    if wider than ``width`` [in], and make the figure that much taller at the top, the axes
    keeping their size and place in inches; returns the height added [in]."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    extra = fit_text(text, width, FigureCanvasAgg(fig).get_renderer()) \
        if _may_overflow(text, width) else 0.0
    if extra:
        w, h = (float(x) for x in fig.get_size_inches())
        sp = fig.subplotpars
        top, bottom = (1 - sp.top) * h, sp.bottom * h
        fig.set_size_inches(w, h + extra)
        fig.subplots_adjust(top=1 - (top + extra) / (h + extra), bottom=bottom / (h + extra))
    return extra


def wrap_lines(text, width: float) -> None:
    """Each plain line of the Text ``text`` (a heading of a figure laid out by matplotlib's
    constrained layout, which does not break lines) wider than ``width`` [in] broken at spaces
    as :func:`fit_text` breaks a title (:func:`_broken`); its other lines, its line breaks and
    any line with mathtext kept."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    if not _may_overflow(text, width):
        return
    renderer = FigureCanvasAgg(text.figure).get_renderer()
    prop = text.get_fontproperties()

    def wide(line: str) -> float:
        return renderer.get_text_width_height_descent(line, prop, False)[0] / text.figure.dpi

    lines = []
    for line in text.get_text().split("\n"):
        w = wide(line) if "$" not in line else 0.0
        lines += _broken([line], int(len(line) * (width - 0.1) / w), width,
                         lambda ls: max(map(wide, ls))) if w > width - 0.1 else [line]
    text.set_text("\n".join(lines))


def _broken(parts: list[str], chars: int, width: float, widest) -> list[str]:
    """``parts`` (the pieces of a heading that begin a line each) broken at spaces into lines
    of at most ``chars`` characters (12 at least), fewer until ``widest(lines)`` [in] is within
    ``width`` (0.1 in spare) — an estimate of the characters a line holds is off where the
    line's letters are wider than the heading's average."""
    import textwrap

    chars = max(12, chars)
    for _ in range(6):                  # each line measured: narrower until every one fits
        lines = [ln for part in parts for ln in (textwrap.wrap(part, chars,
                                                               break_long_words=False)
                                                 if len(part) > chars else [part])]
        if chars == 12 or widest(lines) <= width - 0.1:
            break
        chars = max(12, int(chars * 0.9))
    return lines


def _may_overflow(text, width: float) -> bool:
    """Whether the Text ``text`` could be wider than ``width`` [in]: no glyph of DejaVu Sans
    is wider than 0.75 em on average over a title, so a shorter one needs no measuring (a
    renderer and a text layout, ~10 ms)."""
    return len(text.get_text()) * 0.75 * float(text.get_fontsize()) / 72.0 > width - 0.1


def _fit_title(ax, width: float, renderer) -> float:
    """:func:`fit_text` for the title of ``ax``."""
    return fit_text(ax.title, width, renderer)


def fit_text(text, width: float, renderer) -> float:
    """A title (a matplotlib Text) wider than ``width`` [in], the room it has, broken after
    the case's name (the last ": ", as :func:`title` joins them), then at spaces if a line is
    still too wide; returns the height [in] the added lines need (0 if none)."""
    import re

    s = text.get_text()
    wide = text.get_window_extent(renderer).width / DPI
    if not s or wide <= width - 0.1:
        return 0.0
    head, sep, tail = s.rpartition(": ")
    parts = [head + ":", tail] if sep else [s]
    # the characters a line holds, from the characters seen (mathtext's markup, such as
    # "$\varepsilon$", draws one glyph: counted whole, it let a long line through)
    seen = len(re.sub(r"\\[A-Za-z]+|[$_^{}]", "", s))

    def widest(lines: list[str]) -> float:
        text.set_text("\n".join(lines))
        return text.get_window_extent(renderer).width / DPI

    lines = _broken(parts, int(seen * (width - 0.1) / wide), width, widest)
    text.set_text("\n".join(lines))
    return (len(lines) - 1) * 1.2 * float(text.get_fontsize()) / 72.0


def stable_metadata(fmt: str) -> dict:
    """savefig's keywords that keep a file the same on a rerun: SVG without its date, PDF
    without its creation date (PNG: nothing to add; its callers choose their own)."""
    return {"svg": {"metadata": {"Date": None}},
            "pdf": {"metadata": {"CreationDate": None}}}.get(fmt, {})


def save(fig, path, fmt: str = "png", dpi: int = DPI) -> None:
    """Write ``fig`` to ``path`` (a path or a binary file) as ``fmt`` (png, svg, pdf) at
    ``dpi``; the same figure gives the same bytes (no software tag or date, a fixed SVG hash
    salt). A PNG is written by :func:`png_bytes` from the Agg canvas's pixels."""
    import matplotlib

    with matplotlib.rc_context({"svg.hashsalt": SVG_SALT}):
        if fmt != "png":
            fig.savefig(path, format=fmt, dpi=dpi, **stable_metadata(fmt))
            return
        import io

        raw = io.BytesIO()
        with _laid_out(fig, dpi):
            fig.savefig(raw, format="rgba", dpi=dpi)   # the pixels savefig's PNG would have
    w, h = (int(x * dpi) for x in fig.get_size_inches())  # as the Agg canvas sizes itself
    pixels = np.frombuffer(raw.getbuffer(), np.uint8)
    if pixels.size != w * h * 4:          # not the canvas this was written for: its own PNG
        fig.savefig(path, format="png", dpi=dpi, metadata={"Software": None},
                    pil_kwargs={"compress_level": 1})
        return
    data = png_bytes(pixels.reshape(h, w, 4), dpi)
    if hasattr(path, "write"):
        path.write(data)
    else:
        with open(path, "wb") as out:
            out.write(data)


@contextmanager
def _laid_out(fig, dpi: int):
    """``fig`` (plots_extra's, with matplotlib's constrained layout) laid out at ``dpi`` as
    ``savefig`` lays it out — the axes' aspects applied, then the layout engine run — without
    the drawing ``savefig`` adds to it (every artist drawn with nothing rendered: a third of
    such a figure's saving); no engine while saving (``savefig`` turns it off for its drawing
    too), the figure's own back after. A figure without an engine: nothing done."""
    engine = fig.get_layout_engine()
    if engine is None or fig.__dict__.get("_layout_engine") is not engine \
            or not hasattr(fig, "_get_draw_artists"):
        yield
        return
    from matplotlib import cbook

    if getattr(fig, "flywheel_laid_out_at", None) != dpi:
        lay_out(fig, dpi)
    with cbook._setattr_cm(fig, _layout_engine=None):
        yield


def lay_out(fig, dpi: int = DPI) -> None:
    """Lay ``fig`` (with matplotlib's constrained layout) out now as :func:`save` lays it out
    at ``dpi`` — its axes' aspects applied, then its layout engine run — for a builder that
    places labels against the panels' final places (plots_extra's energy–mass diagram); a
    save at that dpi keeps this layout instead of running the engine again (what is added
    after must take no part in the layout: ``set_in_layout(False)``)."""
    from matplotlib import cbook
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = fig.canvas
    try:
        with cbook._setattr_cm(fig, dpi=dpi):
            fig._get_draw_artists(FigureCanvasAgg(fig).get_renderer())   # apply_aspect
            fig.get_layout_engine().execute(fig)
    finally:
        fig.set_canvas(canvas)
    fig.flywheel_laid_out_at = dpi


def png_bytes(rgba, dpi: int) -> bytes:
    """A PNG of the pixels ``rgba`` (height × width × 4, 8 bits, not premultiplied) at ``dpi``
    (its pHYs chunk, as matplotlib's PIL writer puts it): RGB if every pixel is opaque (a
    quarter less to compress), else RGBA; rows unfiltered, zlib level 1, as PIL writes them at
    level 1 — half the time of matplotlib's PIL path (which keeps the alpha of opaque pixels
    and copies them twice), 10 % smaller files of the same pixels (PNG: ISO/IEC 15948,
    §§ 11.2, 10, 9)."""
    import struct
    import zlib

    h, w, _ = rgba.shape
    opaque = bool((rgba[..., 3] == 255).all())
    channels = 3 if opaque else 4
    rows = np.empty((h, w * channels + 1), np.uint8)
    rows[:, 0] = 0                                         # filter type 0: none
    if opaque and rgba.flags.c_contiguous:
        # one copy of 3-byte items (a pixel's red, green, blue): 40 % quicker than numpy's
        # copy of the same bytes one by one along a third axis
        pixels = rows[:, 1:].view("V3")                    # a view of the rows: h × w
        pixels[...] = rgba.view([("rgb", "V3"), ("a", "u1")]).reshape(h, w)["rgb"]
    else:
        pixels = rows[:, 1:].reshape(h, w, channels)       # a view of the rows
        pixels[...] = rgba[..., :channels]                 # one copy
    assert np.may_share_memory(pixels, rows)

    def chunk(kind: bytes, body: bytes) -> bytes:
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body)))

    per_metre = int(dpi / 0.0254 + 0.5)
    return b"".join((
        b"\x89PNG\r\n\x1a\n",
        chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2 if opaque else 6, 0, 0, 0)),
        chunk(b"pHYs", struct.pack(">IIB", per_metre, per_metre, 1)),
        chunk(b"IDAT", zlib.compress(rows, 1)),
        chunk(b"IEND", b"")))
