"""A diagram drawn as the course draws it on a sheet: axes with arrows, the curves to round
scale factors μ stated beside the title, ticks with their values, each curve named beside it
(the one label placer, render/labels.py). Layout only: the values come from the results; the scale factors are
:func:`flywheel.dynamics.plans.round_scale`'s round values (1, 2, 2.5, 5 × 10^k per mm).
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics.plans import round_scale
from flywheel.render.labels import around
from flywheel.render.drawings.model import View
from flywheel.render.numbers import fmt, typography

PLOT_H = 70.0          # the curves' span on paper at most [mm]
TICK = 1.5             # a tick's length [mm]
MAX_POINTS = 1200       # a curve's vertices at most


def num(v: float, lang: str, sig: int = 4) -> str:
    """A number as the sheet prints it: ``sig`` significant digits, never in e-notation (a
    number of more digits whole: 17 693, not 1,769e+04); Russian: the Russian policy of
    render/numbers.py (decimal comma, true minus, five digits and more grouped)."""
    if lang == "ru":
        with typography("ru"):
            return fmt(v, sig)
    return fmt(v, sig, integers_above=True).replace("−", "-")


_SUPER = str.maketrans("0123456789-−", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁻")


def scale_num(mu: float, lang: str) -> str:
    """A scale factor as the course writes it: 0,05; 2·10⁻⁵ (never «2e−05»)."""
    if mu != 0 and not 1e-3 <= abs(mu) < 1e5:
        e = math.floor(math.log10(abs(mu)))
        m = mu / 10.0 ** e
        mant = num(round(m, 3), lang)
        power = f"10{str(e).translate(_SUPER)}"
        return power if mant == "1" else f"{mant}·{power}"
    return num(mu, lang)


def mu_text(symbol: str, mu: float, unit: str, lang: str) -> str:
    """«μ_M = 10 Н·м/мм»: a scale factor as the course states it."""
    mm = "мм" if lang == "ru" else "mm"
    unit = f"({unit})" if "/" in unit else unit
    return f"μ_{symbol} = {scale_num(mu, lang)} {unit}/{mm}"


def _decimate(x: np.ndarray, y: np.ndarray) -> list[tuple[float, float]]:
    step = max(1, math.ceil(len(x) / MAX_POINTS))
    idx = list(range(0, len(x), step))
    if idx[-1] != len(x) - 1:
        idx.append(len(x) - 1)
    return [(float(x[i]), float(y[i])) for i in idx]


def _ticks(lo: float, hi: float, mu: float) -> list[float]:
    """Tick values every 10 or 20 mm of paper between lo and hi (a multiple of 10·μ)."""
    step = 10.0 * mu
    while (hi - lo) / step > 6:
        step *= 2
    k0, k1 = math.ceil(lo / step - 1e-9), math.floor(hi / step + 1e-9)
    return [k * step for k in range(k0, k1 + 1)]


def _name_places(px, py, gap: float = 1.0, spots: int = 32):
    """Candidate places of a curve's name [mm] for the one placer (render/labels.py): the
    eight places round each of ``spots`` points spread along the curve; the preference (an
    extra cost below one point of a line under the name) for the curve's upper part, as the
    course names a curve near its crest. Returns (anchors, places, prefer)."""
    px, py = np.asarray(px, float), np.asarray(py, float)
    idx = np.unique(np.linspace(0, len(px) - 1, min(len(px), spots)).astype(int))
    top, low = float(py.max()), float(py.min())
    height = (py[idx] - low) / (top - low) if top > low else np.ones(len(idx))
    ring = around(gap)
    anchors = np.repeat(np.column_stack([px[idx], py[idx]]), len(ring), axis=0)
    places = np.tile(ring, (len(idx), 1))
    prefer = (np.repeat(0.5 * (1.0 - height), len(ring))
              + 0.01 * np.tile(np.arange(len(ring)), len(idx)))
    return anchors, places, prefer


def diagram(name: str, title: str, x, curves, *, x_mu: float, x_symbol: str, x_unit: str,
            x_label: str, y_symbol: str, y_unit: str, y_label: str, lang: str,
            x_ticks=None, y_mu: float | None = None, height: float = PLOT_H, marks=(),
            lines=(), lifted: bool = False, x_scale_text: str | None = None) -> View:
    """One diagram. ``x`` [x's unit]; ``curves``: (values, name or "", line type[, own abscissa]) each;
    ``marks``: (x, y, label) points marked with a dot; ``lines``: ((x0, y0), (x1, y1), line
    type, label) straight lines in the data's units (tangents, constant levels). The y scale:
    the round μ that puts the span of every curve (with zero) within ``height`` mm. ``lifted``: the
    abscissa at a round value below the curves instead of zero (ω(φ): its ripple, not its
    mean, fills the height), as the course draws it. ``x_scale_text``: the abscissa's scale said
    otherwise than by a μ (the indicator diagram: «stroke = 100 mm»)."""
    x = np.asarray(x, float)
    ys = [np.asarray(c[0], float) for c in curves]
    lo = min(float(np.min(y)) for y in ys)
    hi = max(float(np.max(y)) for y in ys)
    if not lifted:
        lo, hi = min(0.0, lo), max(0.0, hi)
    mu = y_mu or round_scale(hi - lo, height * (0.8 if lifted else 1.0))
    base = math.floor(lo / (10.0 * mu)) * 10.0 * mu if lifted else 0.0
    if lifted:
        lo = base
    v = View(name)
    X = lambda a: (np.asarray(a, float) - 0.0) / x_mu         # noqa: E731
    Y = lambda a: (np.asarray(a, float) - base) / mu          # noqa: E731
    x_lo, x_hi = float(min(0.0, np.min(x))), float(np.max(x))
    xa, xb = float(X(x_lo)), float(X(x_hi))
    ya, yb = float(Y(lo)), float(Y(hi))
    # axes: the abscissa at zero, the ordinate at x = x_lo, both with arrows
    v.arrow((xa, 0.0), (xb + 10.0, 0.0), line="thin")
    v.arrow((xa, ya - (3.0 if lo < 0 else 0.0)), (xa, yb + 10.0), line="thin")
    v.rich(xa + 2.0, yb + 8.0, y_label, 3.5, halign="left", valign="top")
    # the abscissa's values under the diagram: clear of the curves below the axis
    below = min(ya, min(float(np.min(Y(y))) for y in ys)) - TICK - 1.0
    for t in (x_ticks if x_ticks is not None else _ticks(x_lo, x_hi, x_mu)):
        px = float(X(t))
        v.line((px, -TICK), (px, TICK), line="thin")
        v.text(px, min(-TICK - 1.0, below), num(t, lang), 2.5, halign="center", valign="top")
    for t in _ticks(lo, hi, mu):
        if abs(t - base) < 1e-9 * max(abs(lo), abs(hi), 1e-300) and not lifted:
            continue
        py = float(Y(t))
        v.line((xa - TICK, py), (xa + TICK, py), line="thin")
        v.text(xa - TICK - 1.0, py, num(t, lang), 2.5, halign="right", valign="middle")
    drawn = []
    for c, y in zip(curves, ys):
        cx = np.asarray(c[3], float) if len(c) > 3 else x      # a curve over its own abscissa
        drawn.append((X(cx), Y(y)))
        v.poly(_decimate(*drawn[-1]), line=c[2])
    ends = []
    for (p0, p1, line, label) in lines:
        a, b = (float(X(p0[0])), float(Y(p0[1]))), (float(X(p1[0])), float(Y(p1[1])))
        v.line(a, b, line=line)
        ends.append((b, label))
    dots = []
    for (mx, my, label) in marks:
        c = (float(X(mx)), float(Y(my)))
        v.circle(c, 0.8, line="thin", filled=True)
        dots.append((c, label))
    # the names by the one placer (render/labels.py), over everything drawn: a line's at its
    # end, a mark's beside it, then each curve's along it, off the lines, the ticks' values
    # and the names placed before
    placer = v.placer()
    # the abscissa's name at its arrow: above it, else below it or past the tip, off the
    # curves (the energy–mass diagram's curve runs along its abscissa to the end)
    v.label(placer, (xb + 10.0, 0.0), x_label, 3.5,
            [(0.0, 1.6, 1.0, 0.0), (0.0, -1.6, 1.0, 1.0), (1.5, 0.0, 0.0, 0.5)], rings=None,
            margin=0.4)
    for b, label in ends:
        if label:
            v.label(placer, b, label, 3.5, [(1.5, 0.0, 0.0, 0.5), *around(1.5)])
    for c, label in dots:
        if label:
            v.label(placer, c, label, 3.5, around(1.5))
    for c, (px, py) in zip(curves, drawn):
        if c[1]:
            anchors, places, prefer = _name_places(px, py)
            v.label(placer, anchors, c[1], 3.5, places, prefer)
    # the caption above: the title, then the scale factors
    top = max(yb + 10.0, *(it.box()[3] for it in v.items)) + 3.0
    x_unit_text = x_scale_text or mu_text(x_symbol, x_mu, x_unit, lang)
    v.rich(xa, top, f"{mu_text(y_symbol, mu, y_unit, lang)};  {x_unit_text}", 3.5)
    v.text(xa, top + 6.0, title, 5.0)
    v.scales.update(y=mu, x=x_mu)
    return v
