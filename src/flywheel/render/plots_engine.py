"""The indicator diagram of a four-stroke cylinder (DIR/plots/indicator_NAME.png).

Drawn with :mod:`flywheel.render.figure`'s toolkit inside its style (plots' writer builds
every figure in it).

Two panels: the closed diagram p/p_max against the relative travel s as the program used it
(the grid values, stroke by stroke, with each stroke's table as markers), and the pressure
against φ over the 720° cycle with the strokes named. Renderers compute no physics: the strokes
at each node are in the results (:attr:`~flywheel.dynamics.results.CylinderResult.stroke`).
"""
from __future__ import annotations

import numpy as np

from flywheel.render import figure as fg
from flywheel.render import nomenclature as nm
from flywheel.units import PA_PER_MPA

_COLORS = ("C0", "C2", "C3", "C1")     # intake, compression, expansion, exhaust


def figure_indicator_strokes(results, cylinder, lang: str = "en"):
    """The four strokes of ``cylinder`` (a four-stroke :class:`CylinderResult`)."""
    from flywheel.dynamics.loads import FOUR_STROKES

    from flywheel.render.mathfmt import sub_mathtext

    def t(key: str, **fields) -> str:
        return nm.name(f"engine_{key}", lang, **fields)

    def build():
        # A4 width; each panel's legend in rows below it (never over a curve)
        fig, (ax, bx) = fg.figure((fg.A4_W, 9.6), 2, 1, left=0.8, right=0.8, bottom=1.05, top=0.45,
                                  hspace=0.42)
        s = np.asarray(cylinder.s, float)
        rel = np.asarray(cylinder.p, float) / cylinder.p_max
        stroke = np.asarray(cylinder.stroke)
        deg = np.degrees(results.phi)
        p_max = float(cylinder.p_max)
        for k, name in enumerate(FOUR_STROKES):
            mask = stroke == k
            order = np.argsort(s[mask], kind="stable")
            ax.plot(s[mask][order], rel[mask][order], color=_COLORS[k], label=t(name))
            ax.plot(cylinder.stroke_s[name], cylinder.stroke_tables[name], "o", color=_COLORS[k],
                    markersize=4, markerfacecolor="none", label=t("table", k=t(name)))
            bx.plot(np.where(mask, deg, np.nan), np.where(mask, cylinder.p / PA_PER_MPA, np.nan),
                    color=_COLORS[k], label=t(name))
        ax.axhline(0.0, color="0.3", linewidth=0.6)
        ax.set_xlim(0.0, 1.0)
        ax.set_xlabel(t("s_axis"))
        ax.set_ylabel(sub_mathtext(t("p_axis")))
        sec = ax.secondary_yaxis("right", functions=(lambda r: r * p_max / PA_PER_MPA,
                                                     lambda p: p * PA_PER_MPA / p_max))
        sec.set_ylabel(t("p_MPa"))
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=4, frameon=False)
        bx.axhline(0.0, color="0.3", linewidth=0.6)
        for r in range(results.cycle_deg // 720):
            a = np.degrees(cylinder.fires_at) + 720 * r
            bx.axvline(a, color="0.4", linewidth=0.8, linestyle=":")
        bx.plot([], [], " ", label=t("fires", a=float(np.degrees(cylinder.fires_at))))
        fg.phi_axis(bx, lang, label=False, cycle_deg=results.cycle_deg)
        bx.set_xlabel(t("phi"))
        bx.set_ylabel(t("p_MPa"))
        bx.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15), ncols=5, frameon=False)
        ax.set_title(t("title", t=results.title, c=nm.cylinder_label(cylinder, lang)))
        fg.fit_heading(fig, ax.title, fg.A4_W)    # a long Russian title in two lines
        fg.fit_left(fig, (ax, bx))
        return fig
    return build()
