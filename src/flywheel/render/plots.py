"""PNG plots of one analysis (design.md §5: DIR/plots/*.png).

The only module that imports matplotlib, and only inside its functions, so ``import flywheel``
stays fast and headless. Each ``figure_*`` function draws one figure from a
:class:`~flywheel.dynamics.results.Results` and returns it; :func:`write_plots` saves them all.

The figures are drawn with the toolkit of :mod:`flywheel.render.figure` (pyplot-free figures
with fixed margins, one fixed style, the legends below the axes, the φ axis): with fixed
sizes, dpi and no metadata the PNG bytes are the same for the same input.

Renderers compute nothing: everything drawn is read from the results — the quantities, and
what the scheme shows (which points move, the sliders and their guides, the points on each
link, the slider travel) from ``results.drawing`` (:mod:`flywheel.linkage.drawing`); the only
arithmetic here is layout (degrees, where a symbol or a label goes).
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from flywheel.dynamics.loads import LoadKey
from flywheel.render import figure as fg
from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.plots_scheme import (  # noqa: F401  (public here: animate, sheets)
    draw_scheme, draw_scheme_at, draw_scheme_fixed, scheme_names)
from flywheel.render.numbers import apart, fmt, typeset_params
from flywheel.render import plot_start
from flywheel.render.plot_start import start_held, worker_signals
from flywheel.units import PA_PER_MPA
from flywheel.render.choices import PLOT_CHOICES

_SCHEME_LEGEND_COLS = 4     # columns of the scheme's legend (below the panels)

# -- words ----------------------------------------------------------------------------------------
# Sentence templates only: every quantity's symbol, name and unit comes from the nomenclature
# (render/nomenclature.py: axis, tex, legend, name_tex, unit_of), filled in where the
# templates say {…}.
_TEXT = words("plots", {
    "positions": "position functions",
    "travel_of": "{S} of slider {s} (point {p}) from its outer dead centre",
    "velocity": "velocity analogues",
    "acceleration": "acceleration analogues",
    "link": "link {n}",
    "slider": "(slider {s}, along its guide)",
    "J_mean": "mean {J} = {v:.5g} {u}",
    "indicator": "indicator diagram of cylinder {c}",
    "towards": "piston moving towards the head",
    "away": "piston moving away from the head",
    "table_towards": "table points: towards the head",
    "table_away": "table points: away from the head",
    "forces": "forces on the pistons", "forces_applied": "applied forces",
    "F_gas": "gas force on piston {p}, cylinder {c}",
    "F_tech": "technological force {n}",
    "F_spring": "tension of spring {n}",
    "F_at": "{c} at φ = {a:g}°: {v:.4g} {u}",
    "moments": "reduced moments",
    "M_known": "{M}: the given loads",
    "M_const": "{M} = {v:.5g} {u} (constant, balances the cycle)",
    "M_sum": "{M}: total",
    "works": "works and kinetic energies",
    "W_axis": "work, energy [{u}]",
    "extreme": "{s} = {v:.5g} {u} at φ = {a:.1f}°",
    "extreme_text": "{s} = {v} {u} at φ = {a:.1f}°",
    "omega": r"angular velocity of the crank $\omega(\varphi)$",
    "w": r"$\omega(\varphi)$ with {J} by Merzalov, δ = {d:.4g}",
    "w_exact": r"$\omega(\varphi)$ with the exact {J}, δ = {d:.4g}",
    "value": "{s} = {v:.5g} {u}",
    "epsilon": r"angular acceleration of the crank $\varepsilon(\varphi)$",
    "e": r"$\varepsilon(\varphi)$",
    "scheme": "kinematic scheme at φ = {a:g}°",
    "scheme_many": "kinematic scheme",
    "links": "links",
    "joints": "joints",
    "other_points": "other points (centroids)",
    "ground": "fixed pivots",
    "sliders": "sliders",
    "guides": "guides",
    "trajectory": "trajectory of {p}",
})

def _t(lang: str, key: str, **kw) -> str:
    text = _TEXT["ru" if lang == "ru" else "en"][key]
    return text.format(**typeset_params(kw)) if kw else text       # Russian numbers in ru


def _sub(symbol: str, name: str, norm: bool = False) -> str:
    """'$x_{B}$' or '$|v_{q B}|$' for a point name; the name beside the symbol if it is not
    simple."""
    if name.isascii() and name.isalnum():
        return f"$|{symbol}_{{q{name}}}|$" if norm else f"${symbol}_{{{name}}}$"
    return f"$|{symbol}_q|$ {name}" if norm else f"${symbol}$ {name}"


def _phi_deg(results) -> np.ndarray:
    return np.degrees(results.phi)


# -- the figures -------------------------------------------------------------------------------------
def figure_positions(results, lang: str = "en"):
    """x(φ), y(φ) of every moving point (constant coordinates left out) and slider travel."""
    def build():
        sliders = results.drawing.guided_sliders
        rows = 3 if sliders else 2
        fig, axes = fg.figure((11.0, 9.0 if sliders else 7.0), rows, 1, sharex=True, hspace=0.12)
        deg = _phi_deg(results)
        for ax, k, key in ((axes[0], 0, "x"), (axes[1], 1, "y")):
            for name in results.drawing.moving_points:
                v = results.kinematics.points[name].r[:, k]
                if np.ptp(v) > 1e-12 * max(1.0, np.max(np.abs(v))):
                    ax.plot(deg, v, label=_sub("xy"[k], name))
            ax.set_ylabel(nm.axis(key, lang))
        if sliders:
            for link, joint, angle in sliders:
                axes[2].plot(deg, results.drawing.slider_travel[link],
                             label=_t(lang, "travel_of", S=nm.tex("slider_travel", lang), s=link,
                                      p=joint))
            axes[2].set_ylabel(nm.axis("slider_travel", lang))
        for ax in axes:
            fg.phi_axis(ax, lang, label=ax is axes[-1], cycle_deg=results.cycle_deg)
        axes[0].set_title(fg.title(results, _t(lang, "positions")))
        return fg.legends_below(fig, axes)
    return fg.drawn(build)


def _analogue_figure(results, lang, which: str):
    def build():
        fig, (ax1, ax2) = fg.figure(fg.TALL, 2, 1, sharex=True, hspace=0.12)
        deg = _phi_deg(results)
        # a slider on a fixed guide: its analogue along the guide, signed (+ as its travel S
        # from the outer dead centre grows: dS/dφ, d²S/dφ²); any other point: the magnitude
        sliders = {joint: link for link, joint, _ in results.drawing.guided_sliders}
        sym = "v" if which == "velocity" else "a"
        for name in results.drawing.moving_points:
            pm = results.kinematics.points[name]
            if name in sliders:
                v_q, a_q = results.drawing.slider_analogues[sliders[name]]
                ax1.plot(deg, v_q if which == "velocity" else a_q,
                         label=f"{_sub(sym, 'q' + name)} {_t(lang, 'slider', s=sliders[name])}")
                continue
            vec = pm.v_q if which == "velocity" else pm.a_q
            ax1.plot(deg, np.hypot(vec[:, 0], vec[:, 1]), label=_sub(sym, name, norm=True))
        if sliders:
            ax1.axhline(0.0, color="0.3", linewidth=0.6)
            ax1.set_ylabel(nm.axis("vq_signed" if which == "velocity" else "aq_signed", lang))
        else:
            ax1.set_ylabel(nm.axis("vq_{point}" if which == "velocity" else "aq_{point}", lang))
        link_key = "omega_q_{link}" if which == "velocity" else "eps_q_{link}"
        for name in results.drawing.turning_links:
            lm = results.kinematics.links[name]
            ax2.plot(deg, lm.omega_q if which == "velocity" else lm.eps_q,
                     label=f"{nm.tex(link_key, lang)} {_t(lang, 'link', n=name)}")
        ax2.axhline(0.0, color="0.3", linewidth=0.6)
        ax2.set_ylabel(nm.axis(link_key, lang))
        fg.phi_axis(ax1, lang, label=False, cycle_deg=results.cycle_deg)
        fg.phi_axis(ax2, lang, cycle_deg=results.cycle_deg)
        ax1.set_title(fg.title(results, _t(lang, which)))
        return fg.legends_below(fig, (ax1, ax2))
    return fg.drawn(build)


def figure_velocity_analogues(results, lang: str = "en"):
    """|v_q| of the moving points [m/rad], a slider's v_q along its guide signed (+ away from
    its outer dead centre: dS/dφ); ω_q of the turning links [–]."""
    return _analogue_figure(results, lang, "velocity")


def figure_acceleration_analogues(results, lang: str = "en"):
    """|a_q| of the moving points [m/rad²], a slider's a_q along its guide signed (d²S/dφ²);
    ε_q of the turning links [1/rad]."""
    return _analogue_figure(results, lang, "acceleration")


def figure_J_II(results, lang: str = "en"):
    """J_II(φ) with each link's share and its mean; dJ_II/dφ below."""
    def build():
        fig, (ax1, ax2) = fg.figure(fg.TALL, 2, 1, sharex=True, hspace=0.12)
        deg = _phi_deg(results)
        ax1.plot(deg, results.columns["J_II"].values, color="k", linewidth=2.0,
                 label=nm.tex("J_II", lang))
        for name, J in results.J_parts.items():
            ax1.plot(deg, J, label=_t(lang, "link", n=name))
        ax1.axhline(results.scalars.J_II_mean, color="k", linestyle=":", linewidth=1.0,
                    label=_t(lang, "J_mean", J=nm.tex("J_II", lang),
                             v=results.scalars.J_II_mean, u=nm.unit_of("J_II_mean", lang)))
        ax1.set_ylabel(nm.axis("J_II", lang))
        ax2.plot(deg, results.columns["dJ_II"].values, color="k", label=nm.tex("dJ_II", lang))
        ax2.axhline(0.0, color="0.3", linewidth=0.6)
        ax2.set_ylabel(nm.axis("dJ_II", lang))
        fg.phi_axis(ax1, lang, label=False, cycle_deg=results.cycle_deg)
        fg.phi_axis(ax2, lang, cycle_deg=results.cycle_deg)
        ax1.set_title(fg.title(results, nm.name_tex("J_II", lang)))
        return fg.legends_below(fig, (ax1, ax2))
    return fg.drawn(build)


def figure_indicator(results, cylinder, lang: str = "en"):
    """p/p_max against s as the program used it (the grid values, split by the direction of
    the piston's motion), with the indicator tables as markers; p [MPa] on the right axis."""
    def build():
        fig, ax = fg.figure((fg.A4_W, 5.8), right=0.85, bottom=1.35)
        s = np.asarray(cylinder.s, float)
        rel = np.asarray(cylinder.p, float) / cylinder.p_max
        towards = np.asarray(cylinder.towards_head, bool)
        ends = {}
        for mask, key, color in ((towards, "towards", "C3"), (~towards, "away", "C0")):
            order = np.argsort(s[mask], kind="stable")
            ax.plot(s[mask][order], rel[mask][order], color=color, label=_t(lang, key))
            if order.size:
                ends[key] = (rel[mask][order][0], rel[mask][order][-1])
        if len(ends) == 2:      # the loop closed at the dead centres, where the piston turns:
            ax.plot([0.0, 0.0], [ends["towards"][0], ends["away"][0]], color="C0")   # at the head
            ax.plot([1.0, 1.0], [ends["away"][1], ends["towards"][1]], color="C3")   # at s = 1
        ax.plot(cylinder.table_s, cylinder.table_towards, "o", color="C3", markersize=5,
                markerfacecolor="none", label=_t(lang, "table_towards"))
        ax.plot(cylinder.table_s, cylinder.table_away, "s", color="C0", markersize=5,
                markerfacecolor="none", label=_t(lang, "table_away"))
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_xlim(-0.02, 1.02)            # the dead centres' lines off the frame
        ax.set_xlabel(nm.axis("s_{cylinder}", lang))
        ax.set_ylabel(nm.axis("p_rel", lang))
        p_max = float(cylinder.p_max)
        sec = ax.secondary_yaxis("right", functions=(lambda r: r * p_max / PA_PER_MPA,
                                                     lambda p: p * PA_PER_MPA / p_max))
        sec.set_ylabel(nm.axis("p_{cylinder}", lang, si="MPa"))
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.13), ncols=2)
        ax.set_title(fg.title(results, _t(lang, "indicator", c=nm.cylinder_label(cylinder, lang))))
        fg.fit_heading(fig, ax.title, fg.A4_W)     # a long case title broken into lines
        return fig
    return fg.drawn(build)


def figure_piston_forces(results, lang: str = "en"):
    """Gas force on every piston (and any technological force) against φ, with the values at
    the report angles marked."""
    def build():
        fig, ax = fg.figure(fg.WIDE)
        deg = _phi_deg(results)
        names = set()
        for k, c in enumerate(results.cylinders):
            names.add(f"F_{c.name}")
            line, = ax.plot(deg, c.F, color=f"C{k}",
                            label=_t(lang, "F_gas", p=c.piston, c=nm.cylinder_label(c, lang)))
            for a in results.at:
                i = results.index_of(math.radians(a.phi_deg) % results.cycle)
                ax.plot(deg[i], c.F[i], "o", color=line.get_color(),
                        label=_t(lang, "F_at", c=nm.cylinder_label(c, lang), a=a.phi_deg, v=float(c.F[i]),
                                 u=nm.unit_of(f"F_{c.name}", lang)))
        for key, col in results.columns.items():
            if key.startswith("F_") and key not in names:
                spring = key[2:] in results.loads.tensions
                ax.plot(deg, col.values, linestyle=":" if spring else "--",
                        label=_load_label(results, key[2:], spring, lang))
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_ylabel(nm.axis("F_{load}", lang))
        fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
        ax.set_title(fg.title(results, _t(lang, "forces" if results.cylinders else "forces_applied")))
        fg.legend(ax)            # after the title: a title too wide is broken
        return fig
    return fg.drawn(build)


def _load_label(results, name: str, spring: bool, lang: str) -> str:
    """A force's curve label: the case's title of the load, else "technological force {name}"
    (a spring's "spring {name}")."""
    kind = "spring" if spring else "force"
    title = results.loads.titles.get(LoadKey(kind, name))
    if title:
        return nm.load_name(LoadKey(kind, name), lang, results.loads.titles,
                            results.loads.labels)
    return _t(lang, "F_spring" if spring else "F_tech", n=nm.member("F_" + name, lang))


def figure_reduced_moments(results, lang: str = "en"):
    """Every reduced moment by name, M_known, the constant balancing moment and M_Σ; gravity
    and couples (small) on a second plot below."""
    def build():
        small = [k for k in results.M_parts if k.kind in ("gravity", "couple")]
        big = [k for k in results.M_parts if k not in small]
        rows = 2 if small else 1
        fig, axes = fg.figure(fg.TALL if small else fg.WIDE, rows, 1, sharex=True, squeeze=False,
                            hspace=0.12)
        axes = axes[:, 0]
        deg = _phi_deg(results)
        ax = axes[0]
        for name in big:
            ax.plot(deg, results.M_parts[name], label=nm.load_name(
                name, lang, results.loads.titles, results.loads.labels))
        ax.plot(deg, results.columns["M_known"].values, color="0.4", linestyle="--",
                label=_t(lang, "M_known", M=nm.tex("M_known", lang)))
        m_const = results.scalars.balancing_moment
        key = "driving_moment" if results.scalars.balance == "driving" else "M_C"
        ax.axhline(m_const, color="C3", linestyle="-.",
                   label=_t(lang, "M_const", M=nm.tex(key, lang), v=m_const,
                            u=nm.unit_of(key, lang)))
        ax.plot(deg, results.columns["M_sum"].values, color="k", linewidth=2.0,
                label=_t(lang, "M_sum", M=nm.tex("M_sum", lang)))
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_ylabel(nm.axis("M {load}", lang))
        if small:
            for name in small:
                axes[1].plot(deg, results.M_parts[name],
                             label=nm.load_name(name, lang, results.loads.titles,
                                                 results.loads.labels))
            axes[1].axhline(0.0, color="0.3", linewidth=0.6)
            axes[1].set_ylabel(nm.axis("M {load}", lang))
        for a in axes:
            fg.phi_axis(a, lang, label=a is axes[-1], cycle_deg=results.cycle_deg)
        ax.set_title(fg.title(results, _t(lang, "moments")))
        return fg.legends_below(fig, axes)
    return fg.drawn(build)


def figure_works(results, lang: str = "en"):
    """A_D, A_C, A, T_II and ΔT_I against φ; ΔT_I's global max and min marked."""
    def build():
        fig, ax = fg.figure(fg.WIDE)
        deg = _phi_deg(results)
        cols = results.columns
        # ΔT_I differs from A only by T_II's change: A is drawn dashed, over it
        for key, style in (("A_D", {"color": "C0"}), ("A_C", {"color": "C1"}),
                           ("T_II", {"color": "C4"}), ("dT_I", {"color": "k", "linewidth": 2.0}),
                           ("A", {"color": "C2", "linestyle": "--", "linewidth": 1.6})):
            ax.plot(deg, cols[key].values, label=nm.legend(key, lang), **style)
        sc = results.scalars
        for tag, marker in (("max", "^"), ("min", "v")):
            key = f"delta_T_I_{tag}"
            v, a = getattr(sc, key), getattr(sc, f"phi_delta_T_I_{tag}_deg")
            ax.plot(a, v, marker, color="C3", markersize=8,
                    label=_t(lang, "extreme", s=nm.tex(key, lang), v=v,
                             u=nm.unit_of(key, lang), a=a))
            ax.axvline(a, color="C3", linestyle=":", linewidth=0.8)
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_ylabel(_t(lang, "W_axis", u=nm.unit_of("A", lang)))
        fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
        ax.set_title(fg.title(results, _t(lang, "works")))
        fg.legend(ax)            # after the title: a title too wide is broken
        return fig
    return fg.drawn(build)


def figure_omega(results, lang: str = "en"):
    """ω(φ) with J_I by Merzalov, ω(φ) with the exact J_I (dashed), and the lines ω_max,
    ω_min, ω_m."""
    def build():
        fig, ax = fg.figure(fg.WIDE)
        deg = _phi_deg(results)
        sc = results.scalars
        ax.plot(deg, results.columns["omega"].values, color="k", linewidth=1.8,
                label=_t(lang, "w", J=nm.tex("J_required", lang),
                         d=sc.delta_achieved))
        if "omega_exact" in results.columns:
            ax.plot(deg, results.columns["omega_exact"].values, color="C0", linestyle="--",
                    label=_t(lang, "w_exact", J=nm.tex("J_required_exact", lang),
                             d=sc.delta_achieved_exact))
        # ω_max and ω_min told apart: a small δ writes both alike to four digits (numbers.apart)
        spec = apart(sc.omega_max, sc.omega_min) or ".5g"
        for key, color in (("omega_max", "C3"), ("omega_min", "C2")):
            ax.axhline(getattr(sc, key), color=color, linestyle=":",
                       label=_t(lang, "extreme_text", s=nm.tex(key, lang),
                                v=fmt(getattr(sc, key), spec=spec, zero=None),
                                u=nm.unit_of(key, lang), a=getattr(sc, f"phi_{key}_deg")))
        ax.axhline(sc.omega_mean, color="0.4", linestyle="-.",
                   label=_t(lang, "value", s=nm.tex("omega_mean", lang), v=sc.omega_mean,
                            u=nm.unit_of("omega_mean", lang)))
        ax.set_ylabel(nm.axis("omega", lang))
        fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
        ax.set_title(fg.title(results, _t(lang, "omega")))
        fg.legend(ax)            # after the title: a title too wide is broken
        return fig
    return fg.drawn(build)


def figure_epsilon(results, lang: str = "en"):
    """ε(φ) of the crank."""
    def build():
        fig, ax = fg.figure(fg.WIDE)
        ax.plot(_phi_deg(results), results.columns["epsilon"].values, color="k", label=_t(lang, "e"))
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_ylabel(nm.axis("epsilon", lang))
        fg.phi_axis(ax, lang, cycle_deg=results.cycle_deg)
        ax.set_title(fg.title(results, _t(lang, "epsilon")))
        fg.legend(ax)            # after the title: a title too wide is broken
        return fig
    return fg.drawn(build)


_SCHEME = (draw_scheme_fixed, draw_scheme_at, scheme_names)   # handed to plots_plans


def _scheme_legend_handles(results, lang: str):
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    h = [Line2D([], [], color="k", linewidth=2.5, label=_t(lang, "links")),
         Line2D([], [], linestyle="", marker="o", markerfacecolor="white", markeredgecolor="k",
                markersize=6.5, label=_t(lang, "joints"))]
    joints = set(results.drawing.joints)
    if any(n not in joints for n in results.drawing.moving_points):
        h.append(Line2D([], [], linestyle="", marker="o", color="k", markersize=4.5,
                        label=_t(lang, "other_points")))
    if results.drawing.fixed_points:
        h.append(Line2D([], [], linestyle="", marker="^", markerfacecolor="white",
                        markeredgecolor="k", markersize=8, label=_t(lang, "ground")))
    if results.drawing.guided_sliders or results.drawing.moving_blocks:
        h.append(Patch(facecolor="0.85", edgecolor="k", label=_t(lang, "sliders")))
    if results.drawing.guided_sliders:
        h.append(Line2D([], [], color="k", linewidth=1.0, label=_t(lang, "guides")))
    from flywheel.render.mathfmt import point_name

    for k, name in enumerate(results.drawing.moving_points):
        h.append(Line2D([], [], color=f"C{k % 10}", linewidth=0.8,
                        label=_t(lang, "trajectory", p=point_name(name))))
    return h


def figure_scheme(results, lang: str = "en"):
    """The kinematic scheme at each report angle (one panel each; φ = 0 if there is none):
    links, joints, fixed pivots, sliders on their guides, named points, and the trajectories
    of all moving points over the cycle."""
    def build():
        angles = [float(a.phi_deg) for a in results.at] or [0.0]
        n = len(angles)
        ncols = min(n, 2)
        nrows = math.ceil(n / ncols)
        handles = _scheme_legend_handles(results, lang)
        leg_h = math.ceil(len(handles) / _SCHEME_LEGEND_COLS) * fg._ROW_H + 0.2
        # A4 text width; the legend in rows below the panels
        panel = (6.25, 5.0) if ncols == 1 else (2.75, 3.2)     # [in]; 0.75 in between
        top = 0.75 if n > 1 else 0.4
        bottom = 0.55 + leg_h
        size = (fg.A4_W, top + bottom + panel[1] * nrows + 0.6 * (nrows - 1))
        fig, axes = fg.figure(size, nrows, ncols, squeeze=False, right=0.35, top=top,
                              bottom=bottom, hspace=0.6 / panel[1], wspace=0.75 / panel[0])
        scale = 0.035 * max(results.drawing.span, 1e-9)
        for k, ax in enumerate(axes.flat):
            if k >= n:
                ax.set_visible(False)
                continue
            i = results.index_of(math.radians(angles[k]) % results.cycle)
            draw_scheme(ax, results, i, scale, lang)
            ax.set_title(fg.title(results, _t(lang, "scheme", a=angles[k])) if n == 1
                         else _t(lang, "scheme", a=angles[k]))
        if n > 1:
            fg.fit_heading(fig, fig.suptitle(fg.title(results, _t(lang, "scheme_many"))),
                           fg.A4_W - 0.2)
        else:
            fg.fit_heading(fig, axes[0, 0].title, 6.25 + 0.7)
        fig.legend(handles=handles, loc="lower center", ncols=_SCHEME_LEGEND_COLS,
                   bbox_to_anchor=(0.5, 0.05 / float(fig.get_size_inches()[1])), frameon=False)
        return fig
    return fg.drawn(build)


# -- writing -----------------------------------------------------------------------------------------


def figures(results, lang: str = "en"):
    """(file name, figure-building function) of every plot, in a fixed order: an indicator
    diagram per cylinder; piston forces only if there are cylinders or technological forces."""
    out = [
        ("positions.png", lambda: figure_positions(results, lang)),
        ("velocity_analogues.png", lambda: figure_velocity_analogues(results, lang)),
        ("acceleration_analogues.png", lambda: figure_acceleration_analogues(results, lang)),
        ("J_II.png", lambda: figure_J_II(results, lang)),
    ]
    if results.analysis == "kinematics":     # the kinematics alone: no dynamics to draw
        return out[:3] + [("scheme.png", lambda: figure_scheme(results, lang))]
    if results.kinematics is None:   # tabulated kinematics (issue 5): no positions to draw
        out = out[-1:]
    for c in results.cylinders:
        out.append((f"{nm.indicator_stem(c.name)}.png", lambda c=c: figure_indicator(results, c, lang)
                    if c.stroke is None else _engine_plots().figure_indicator_strokes(results, c, lang)))
    if results.cylinders or any(k.startswith("F_") for k in results.columns):
        out.append(("piston_forces.png", lambda: figure_piston_forces(results, lang)))
    out += [
        ("reduced_moments.png", lambda: figure_reduced_moments(results, lang)),
        ("works.png", lambda: figure_works(results, lang)),
        ("omega.png", lambda: figure_omega(results, lang)),
        ("epsilon.png", lambda: figure_epsilon(results, lang)),
    ]
    if results.kinematics is not None:
        out.append(("scheme.png", lambda: figure_scheme(results, lang)))
    return out


def _engine_plots():
    from flywheel.render import plots_engine

    return plots_engine


def in_lang(results, lang: str):
    """``results`` with the case's title and source in ``lang`` (a case may give both
    languages: io.schema.Text), for the figures' titles; the same object if nothing changes."""
    from dataclasses import replace

    from flywheel.io.text import in_language

    title, source = in_language(results.title, lang), in_language(results.source, lang)
    if title == results.title and source == results.source:
        return results
    return replace(results, title=title, source=source)


def all_figures(results, lang: str = "en"):
    """:func:`figures` and those beyond the worksheet (plots_extra: the energy–mass diagram,
    the time law, and with --transients the start-up and run-down), for one pool of workers."""
    from flywheel.render import plots_extra as px
    from flywheel.render import plots_forces, plots_plans

    results = in_lang(results, lang)     # every title from the case's title in ``lang``
    if results.analysis == "kinematics":     # the kinematic plans only: no force analysis
        return figures(results, lang) + [
            (n, f) for n, f in plots_plans.figures(results, lang,
                                                   scheme=_SCHEME)
            if n.startswith(("plan_positions", "plan_velocity", "plan_acceleration"))]
    out = figures(results, lang) + plots_forces.figures(results, lang)   # force analysis
    out += plots_plans.figures(results, lang,      # the plans, at the report angles only
                               scheme=_SCHEME)
    out += [("energy_mass.png", lambda: px.figure_energy_mass(results, lang)),
            ("time_law.png", lambda: px.figure_time_law(results, lang))]
    if results.time_domain is not None:
        out.append(("transients.png", lambda: px.figure_transients(results, lang)))
    return out


def _save_some(results, folder: Path, lang: str, indices: list[int], fmt: str = "png",
               dpi: int = fg.DPI) -> None:
    """Draw figures ``indices`` and save each as PNG and, if ``fmt`` is another format, as
    ``fmt`` too (the reports embed the PNGs)."""
    specs = all_figures(results, lang)
    with fg.style(lang):
        for i in indices:
            name, build = specs[i]
            fig = build()
            try:
                for f in dict.fromkeys(("png", fmt)):
                    fg.save(fig, folder / Path(name).with_suffix("." + f).name, f, dpi)
            finally:
                # dropped, not cleared: Figure.clear() re-initialises every axes before
                # removing it (a tenth of a figure's time); the collector frees the figure
                _release(fig)


def _release(fig) -> None:
    """Let pyplot forget a figure if it made it (no figure of flywheel's is pyplot's now; a
    caller's pyplot keeps every open figure, and past 20 it warns)."""
    import sys

    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close(fig)


#: the relative cost of the heaviest figures (CPU seconds of benchmarks/bench_figures.py after
#: the glyph and PNG work of issue 26's third pass, compressor and engine_inline4; the others
#: about 1): the workers take the costliest first, so that none is left alone at the end
_COST = {"energy_mass": 4.0, "scheme": 3.0, "plan_forces": 3.0, "plan_positions": 2.5,
         "hodographs": 2.3, "positions": 2.1, "time_law": 1.8, "plan_lever": 1.6,
         "velocity_analogues": 1.6, "acceleration_analogues": 1.6, "reduced_moments": 1.6,
         "J_II": 1.5, "indicator": 1.5, "plan_acceleration": 1.4}

#: `run --plots record`: the figures of the записка of a course project (the sheets' diagrams:
#: kinematics, the plans, the reduced quantities, the energy–mass diagram and ω(φ)); the
#: others (the scheme, ε(φ), the time law, the transients, the reactions and hodographs, the
#: balancing moment) only with `--plots all`. Stems; a figure per cylinder or angle by prefix.
RECORD = ("positions", "velocity_analogues", "acceleration_analogues", "J_II", "indicator",
          "piston_forces", "reduced_moments", "works", "omega", "energy_mass", "plan_positions",
          "plan_velocity", "plan_acceleration", "plan_forces", "plan_lever")
#: the choices of `run --plots`
CHOICES = PLOT_CHOICES


def _stem_of(name: str) -> str:
    """A figure's kind: its file's stem without a cylinder's or an angle's part."""
    stem = name.rsplit(".", 1)[0]
    for kind in sorted(_COST.keys() | set(RECORD), key=len, reverse=True):
        if stem == kind or stem.startswith(kind + "_"):
            return kind
    return stem


def chosen(results, lang: str = "en", which: str = "all") -> list[str]:
    """The file names of the figures ``which`` ("all", "record", "none") picks, in the fixed
    order of :func:`all_figures`."""
    if which not in CHOICES:
        # library use only: no CLI input reaches this
        raise ValueError(f"which {which!r}: allowed {', '.join(CHOICES)}")
    names = [name for name, _ in all_figures(results, lang)]
    if which == "none":
        return []
    return names if which == "all" else [n for n in names if _stem_of(n) in RECORD]


def _save_next(results, folder: Path, lang: str, order: list[int], counter, fmt: str = "png",
               dpi: int = fg.DPI, done=None) -> None:
    """Draw figures ``order[k]`` for k taken one at a time from the shared ``counter``; count
    each one saved in ``done`` (a shared value, or None). One style for all of them: its
    caches (text sizes and bitmaps, glyphs, mathtext, fonts) serve every figure this process
    draws, not one each."""
    with fg.style(lang):
        while True:
            with counter.get_lock():
                k = counter.value
                counter.value += 1
            if k >= len(order):
                return
            _save_some(results, folder, lang, [order[k]], fmt, dpi)
            if done is not None:
                with done.get_lock():
                    done.value += 1


def _worker(results, folder: Path, lang: str, order: list[int], counter, fmt: str = "png",
            dpi: int = fg.DPI, done=None, parent: int | None = None) -> None:
    """A forked plotting process: it dies with its parent (Linux: PR_SET_PDEATHSIG), leaves
    Ctrl-C to the parent (which stops it) and ends quietly on SIGTERM."""
    worker_signals(parent)
    _save_next(results, folder, lang, order, counter, fmt, dpi, done)


def _first_worker(results, folder: Path, lang: str, order: list[int], counter, fmt: str,
                  dpi: int, done, parent: int, others: int) -> None:
    """The first plotting process: it imports matplotlib (0.5 s) while the parent writes the
    tables and texts, then draws with ``others`` workers it forks (:func:`draw_with_others`).
    (Started with the process instead, it is render/plot_start.py's.)"""
    worker_signals(parent)
    fg.prepare()                          # imported once here, for every worker
    draw_with_others(results, folder, lang, order, counter, fmt, dpi, done, others)


def draw_with_others(results, folder: Path, lang: str, order: list[int], counter, fmt: str,
                     dpi: int, done, others: int) -> None:
    """In the first plotting process, matplotlib imported: fork ``others`` workers that share
    that import and draw with them. A SIGTERM (the parent stopping it) ends its workers
    first, then it."""
    import multiprocessing as mp
    import os
    import signal

    ctx = mp.get_context("fork")
    me = os.getpid()
    workers = [ctx.Process(target=_worker, args=(results, folder, lang, order, counter, fmt,
                                                 dpi, done, me)) for _ in range(others)]

    def stop(signum, frame):
        for w in workers:
            if w.pid is not None:
                w.terminate()
        for w in workers:
            if w.pid is not None:
                w.join()
        os._exit(128 + signum)

    signal.signal(signal.SIGTERM, stop)
    start_held(workers, {signal.SIGTERM})
    try:
        _save_next(results, folder, lang, order, counter, fmt, dpi, done)
    finally:
        for w in workers:
            w.join()
    if any(w.exitcode != 0 for w in workers):
        raise RuntimeError("a plotting process failed")


class PlotJob:
    """The figures of one run being drawn (:func:`start_plots`): forked workers (Linux, macOS)
    draw them while the caller writes its tables and texts; :meth:`wait` waits for them,
    telling a progress bar each figure done. Used as a context manager, it stops the workers
    if the caller fails (or is stopped) before waiting: a worker left running would write into
    a temporary folder the run is removing."""

    def __init__(self, results, folder: Path, lang: str, names: list[str], jobs: int,
                 fmt: str, dpi: int):
        import multiprocessing as mp

        self.folder, self.fmt = folder, fmt
        self.names = names
        every = [name for name, _ in all_figures(results, lang)]
        # the costliest figures first, then the rest in order: each worker takes the next one
        # from a shared counter, so none waits while another draws
        order = sorted((every.index(n) for n in names),
                       key=lambda i: -_COST.get(_stem_of(every[i]), 1.0))
        self._draw_here = (results, folder, lang, order, fmt, dpi)
        self.children: list = []
        self._done = None
        others = min(jobs, len(names)) - 1      # the workers the first one forks
        early = plot_start.claim()          # started with the process (render/plot_start.py)
        if early is not None:
            if names and jobs > 1 and early.send(
                    (results, folder, lang, order, fmt, dpi, others)):
                self.children, self._done = [early.process], early.done
                return
            early.end()
        if names and jobs > 1 and "fork" in mp.get_all_start_methods():
            import os

            # one process forked now: it imports matplotlib while this one writes the tables
            # and texts, then forks the other workers, which share its import
            ctx = mp.get_context("fork")
            counter, self._done = ctx.Value("i", 0), ctx.Value("i", 0)
            self.children = [ctx.Process(target=_first_worker, args=(
                results, folder, lang, order, counter, fmt, dpi, self._done, os.getpid(),
                others))]
            try:
                start_held(self.children)
            except BaseException:
                self.stop()
                raise

    def __enter__(self) -> "PlotJob":
        return self

    def __exit__(self, kind, exc, tb) -> None:
        if kind is not None:
            self.stop()

    def stop(self) -> None:
        """Terminate the workers and wait for them."""
        for c in self.children:
            c.terminate()
        _join_all(self.children)

    def wait(self, progress=None) -> list[Path]:
        """Wait for every figure (drawn here if there are no workers), calling ``progress(done,
        total)`` as they come; return the paths of the ``fmt`` files in the fixed order."""
        total = len(self.names)
        if self.children:
            try:
                alive = list(self.children)
                while alive:
                    if progress is not None:
                        progress(self._done.value, total)
                    alive[0].join(0.1)
                    alive = [c for c in alive if c.is_alive()]
            except BaseException:        # Ctrl-C, SIGTERM: the workers stop now
                self.stop()
                raise
            _join_all(self.children)
            if any(c.exitcode != 0 for c in self.children):
                raise RuntimeError("a plotting process failed")
        else:
            results, folder, lang, order, fmt, dpi = self._draw_here
            with fg.style(lang):                  # one style: its caches serve every figure
                for k, i in enumerate(order):
                    if progress is not None:
                        progress(k, total)
                    _save_some(results, folder, lang, [i], fmt, dpi)
        if progress is not None:
            progress(total, total)
        return [self.folder / Path(n).with_suffix("." + self.fmt).name for n in self.names]


def start_plots(results, folder: Path, lang: str = "en", jobs: int = 1, fmt: str = "png",
                dpi: int = fg.DPI, which: str = "all") -> PlotJob:
    """Start drawing the plots of ``results`` that ``which`` picks (:func:`chosen`) into
    ``folder`` (created if missing) as PNG and, with ``fmt`` "svg" or "pdf", as that format
    too (the reports embed the PNGs), at ``dpi``, in ``jobs`` forked processes (Linux/macOS;
    each figure drawn whole by one; jobs = 1: drawn by :meth:`PlotJob.wait`). ``lang``: "en"
    or "ru" for the labels and titles.

    The files are byte-identical for the same input (fixed size and dpi, no metadata or dates).
    """
    if lang not in ("en", "ru"):
        # library use only: no CLI input reaches this
        raise ValueError(f"lang {lang!r}: allowed 'en' or 'ru'")
    if fmt not in fg.FORMATS:
        # library use only: no CLI input reaches this
        raise ValueError(f"fmt {fmt!r}: allowed {', '.join(fg.FORMATS)}")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    return PlotJob(results, folder, lang, chosen(results, lang, which), jobs, fmt, dpi)


def _join_all(children) -> None:
    """Wait for every plotting process. A Ctrl-C or SIGTERM that arrives while waiting stops
    them all first (a worker left running would go on writing into a temporary folder the run
    is removing), then goes on up."""
    stopped = None
    for c in children:
        while True:
            try:
                c.join()
                break
            except BaseException as exc:     # the signal's exception: terminate, keep waiting
                stopped = stopped or exc
                for d in children:
                    d.terminate()
    if stopped is not None:
        raise stopped


def write_plots(results, folder: Path, lang: str = "en", jobs: int = 1, fmt: str = "png",
                dpi: int = fg.DPI, which: str = "all", progress=None) -> list[Path]:
    """Write the plots of ``results`` (:func:`start_plots`) and wait for them; return the
    paths of the ``fmt`` files in a fixed order."""
    with start_plots(results, folder, lang, jobs, fmt, dpi, which) as job:
        return job.wait(progress)
