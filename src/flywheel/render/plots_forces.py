"""PNG plots of the force analysis (issue 12): the joint reactions over φ, the balancing moment
three ways with the constant moment of the dynamics, and the polar diagrams (hodographs) of
the crank-pin load, the main-bearing load and the shaking force.

Drawn with render/figure.py's toolkit, as render/plots.py draws — pyplot-free figures with
fixed margins in inches, A4's text width, the legend below the axes or in a free cell, the
hodographs' angle labels none over another (render/labels.py) — and saved by plots.py's
pool of workers in the fixed style (:func:`figures` is registered in ``plots.all_figures``;
this module does not import render/plots.py, which imports it). Quantities are named by
:mod:`flywheel.render.nomenclature`, and so are the titles. Nothing is computed here but
degrees and the axis limits; matplotlib is imported inside the functions.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.render import figure as fg
from flywheel.render.nomenclature import axis, name, symbol, unit_of, tex

def _typeset(key: str, lang: str) -> str:
    """The quantity's name with its plain symbol typeset as mathtext (no literal underscore)."""

    return name(key, lang).replace(symbol(key, lang), tex(key, lang))


def _t(lang: str, key: str, **kw) -> str:
    return name(f"forces_plot_{key}", lang, **kw)


def figure_reactions(results, lang: str = "en"):
    """|R_ij|(φ) of every joint, one curve each (linkage cases)."""
    fig, ax = fg.figure(fg.WIDE)
    deg = np.degrees(results.phi)
    from flywheel.render.forces import reaction_label

    for k, r in enumerate(results.forces.joints.values()):   # past ten: dashed (fg.series)
        ax.plot(deg, r.magnitude, label=_reaction_tex(reaction_label(r, lang)), **fg.series(k))
    ax.set_ylabel(axis("reaction", lang))
    fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
    ax.set_title(fg.title(results, _t(lang, "reactions")))
    fg.legend(ax)            # after the title: a title too wide is broken
    return fig


def _reaction_tex(label: str) -> str:
    """"R₀₁ (O)" / "R_01 (O)" with the subscript typeset (mathtext, no literal underscore)."""
    sym, _, rest = label.partition(" ")
    sub = sym[1:].lstrip("_").translate(str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
    return f"$R_{{{sub}}}$ {rest}"


def figure_balancing_moment(results, lang: str = "en"):
    """With the true motion: M_y of the Assur groups over the cycle (what the crank delivers
    to them), the first group's inertia torque −J_I·ε, and M_y with it — the constant moment
    of the cycle condition (M_D of a driven machine), the closure check: the flywheel takes up
    the groups' fluctuation. With the steady motion (ε = 0, the two M_y one): M_y by
    kinetostatics, Zhukovsky's lever and the power balance. A tabulated case: the power
    balance alone."""
    f = results.forces
    fig, ax = fg.figure(fg.WIDE)
    deg = np.degrees(results.phi)
    curves = [f.M_y_power]
    groups = f.analysis is not None and f.motion == "true"
    if groups:
        fa = f.analysis
        ax.plot(deg, fa.balancing_moment_groups, color="k", linewidth=2.4,
                label=_typeset("M_y_groups", lang))
        ax.plot(deg, fa.first_group_torque, color="C2", linestyle="-.", linewidth=1.6,
                label=_typeset("first_group_torque", lang))
        ax.plot(deg, fa.balancing_moment, color="C1", linestyle="--", linewidth=1.6,
                label=_typeset("M_y", lang))
        curves += [fa.balancing_moment_groups, fa.first_group_torque, fa.balancing_moment]
    elif f.analysis is not None:
        ax.plot(deg, f.analysis.balancing_moment, color="k", linewidth=2.4, label=_typeset("M_y", lang))
        ax.plot(deg, f.M_y_zhukovsky, color="C1", linestyle="--", linewidth=1.6,
                label=_typeset("M_y_zhukovsky", lang))
        curves += [f.analysis.balancing_moment, f.M_y_zhukovsky]
    if not groups:
        ax.plot(deg, f.M_y_power, color="C0", linestyle=":", linewidth=1.8,
                label=_typeset("M_y_power", lang))
    key = "driving_moment" if results.energy.balance == "driving" else "M_C"
    ax.axhline(f.M_const, color="C3", linewidth=0.9,
               label=_t(lang, "M_const", s=tex(key, lang), v=f.M_const, u=unit_of(key, lang)))
    # limits: 0, M_const and the curves; a span of round-off only (the true motion: M_y = M_D)
    # is drawn as a line within ±10 % of the moments at stake, not magnified into noise
    lo = min(0.0, f.M_const, *(float(np.min(c)) for c in curves))
    hi = max(0.0, f.M_const, *(float(np.max(c)) for c in curves))
    couple = f.analysis.first_group_couple if f.analysis is not None else results.motion.epsilon * results.motion.J_I
    ref = max(abs(f.M_const), float(np.max(np.abs(couple))), 1e-12)
    if hi - lo < 1e-6 * ref:
        lo, hi = min(lo, f.M_const - 0.1 * ref), max(hi, f.M_const + 0.1 * ref)
    pad = 0.08 * (hi - lo)
    ax.set_ylim(lo - pad, hi + pad)
    ax.set_ylabel(axis("M_y", lang))
    fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
    what = (_t(lang, "moment_groups") if groups else
            _t(lang, "moment_power") if f.analysis is None and f.motion == "true" else
            _t(lang, "moment") if f.motion == "true"
            else _t(lang, "moment_steady", w=float(f.omega[0])))
    ax.set_title(fg.title(results, what))
    fg.legend(ax)            # after the title: a title too wide is broken
    return fig


def _hodograph(ax, x: np.ndarray, y: np.ndarray, results, lang: str, color: str) -> None:
    """A closed curve over the cycle with the 30° positions marked (labelled [deg] by
    :func:`_angle_labels` once the figure has its size)."""
    ax.plot(x, y, color=color, linewidth=1.3, label=_t(lang, "curve"))
    ax.plot([0.0], [0.0], "+", color="k", markersize=9, label=_t(lang, "origin"))
    marks = _marks(results)
    ax.plot(x[marks], y[marks], "o", color=color, markersize=3.5)
    ax.set_aspect("equal", adjustable="datalim")


def _mark_angles(results) -> list[int]:
    """The angles [deg] a hodograph marks: every 30° of the cycle (a four-stroke engine's
    720°: both turns of the crank, whose loads differ)."""
    return list(range(0, int(round(results.cycle_deg)), 30))


def _marks(results) -> list[int]:
    """Grid nodes of the positions a hodograph marks (:func:`_mark_angles`)."""
    return [results.index_of(math.radians(a)) for a in _mark_angles(results)]


def _angle_labels(ax, x: np.ndarray, y: np.ndarray, results) -> list:
    """The marks' angles [deg] beside them by the one label placer (render/labels.py): none
    over another or over a mark, off the curve where it can; a label with no free place is
    left out, 0° always kept. Called once the figure has its size."""
    from flywheel.render.labels import AxesLabels, around

    marks = _marks(results)
    labels = AxesLabels(ax)
    labels.curve(np.column_stack([x, y]))
    labels.markers(np.column_stack([x[marks], y[marks]]), 2.5)
    labels.markers([(0.0, 0.0)], 4.5)                # the origin's cross
    placed = []
    for k, a in enumerate(_mark_angles(results)):
        t = labels.point((float(x[marks[k]]), float(y[marks[k]])), f"{a}",
                         places=around(3.0), optional=k > 0, fontsize=7.0)
        if t is not None:
            placed.append(t)
    return placed


def figure_hodographs(results, lang: str = "en"):
    """Polar diagrams over the cycle: (a) the load on the crank pin in the crank's axes
    (F_T along the pin's velocity, F_R towards the shaft), as engine books draw it; (b) the
    crank's load on the main bearing and (c) the shaking force, in the case's axes."""
    f = results.forces
    fa = f.analysis
    # A4 text width: two panels a row, the legend in the fourth cell (never over a curve)
    fig, grid = fg.figure((fg.A4_W, 7.6), 2, 2, left=0.85, right=0.3, bottom=0.55, top=0.75,
                          hspace=0.42, wspace=0.5)
    fg.fit_heading(fig, fig.suptitle(fg.title(results, _t(lang, "hodographs"))), fg.A4_W - 0.2)
    axes = [grid[0, 0], grid[0, 1], grid[1, 0]]
    cell = grid[1, 1].get_position()
    fig.delaxes(grid[1, 1])
    mb, S = fa.main_bearing_load, fa.shaking_force
    panels = [
        (f.crank_pin_tangential, f.crank_pin_radial, "crank_pin_tangential", "crank_pin_radial",
         "pin", "C0"),
        (mb.x, mb.y, "main_bearing_Fx", "main_bearing_Fy", "bearing", "C3"),
        (S[:, 0], S[:, 1], "shaking_Fx", "shaking_Fy", "shaking", "C2"),
    ]
    crank = "" if results.cylinders else "_linkage"     # no crankshaft: the crank's pin, bearing
    for ax, (x, y, kx, ky, title, color) in zip(axes, panels):
        _hodograph(ax, x, y, results, lang, color)
        ax.locator_params(axis="x", nbins=5)      # a narrow panel: the tick labels apart
        ax.set_xlabel(axis(kx, lang))
        ax.set_ylabel(axis(ky, lang))
        ax.set_title(_t(lang, title + crank if title in ("pin", "bearing") else title))
    for ax, (x, y, *_) in zip(axes, panels):      # the figure's size is final: label the marks
        _angle_labels(ax, x, y, results)
    axes[0].legend(loc="center", bbox_to_anchor=((cell.x0 + cell.x1) / 2, (cell.y0 + cell.y1) / 2),
                   bbox_transform=fig.transFigure)
    return fig


def figures(results, lang: str = "en") -> list:
    """(file name, figure-building function) of the force analysis's plots: the balancing
    moment always; the reactions and the hodographs where there is a linkage."""
    if results.forces is None:
        return []
    out = [("balancing_moment.png", lambda: figure_balancing_moment(results, lang))]
    if results.forces.analysis is not None:
        out = [("reactions.png", lambda: figure_reactions(results, lang))] + out
        out.append(("hodographs.png", lambda: figure_hodographs(results, lang)))
    return out
