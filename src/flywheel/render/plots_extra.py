"""Plots beyond the worksheet (issue 6): Wittenbauer's energy–mass diagram beside Merzalov's
ΔT_I construction, the time law ω(t), ε(t), and the start-up / run-down histories.

Figures are built by functions that return them (tests check structure);
:func:`flywheel.render.plots.write_plots` saves them with the worksheet's plots, in the same
worker processes. matplotlib is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations


import numpy as np

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.figure import A4_W, lay_out, wrap_lines
from flywheel.render.numbers import fmt, typeset_params

# Sentence templates only; every quantity's symbol, name and unit comes from the nomenclature
# (render/nomenclature.py), filled in where the templates say {…}.
TEXT = words("plots_extra", {"em": "Energy–mass diagram (Wittenbauer) and Merzalov's {dT}",
                             "T": r"$\Delta T = A(\varphi)$ [{u}]",
                             "curve": r"$\Delta T(J_{{II}})$ over the cycle", "tan_max": r"tangent at $\psi_{{max}}$",
                             "tan_min": r"tangent at $\psi_{{min}}$", "tan_slope": "{tan}: {w}²/2 = {k:.5g} {uJ}/({uI})",
                             "origin": "origin of the full-energy axes (−{J}, −{T})",
                             "full": "the whole construction: the tangents meet at O′ (−{J}, −{T})",
                             "zoom": "the curve enlarged: points of tangency", "merz": "Merzalov: {dT}(φ)",
                             "exact": "exact", "J_exact": "{J} ({exact}) = {v:.5g} {u}",
                             "J_dim": "{J} = {v:.5g} {u} ({exact})",
                             "kl": "kl = {kl:.5g} {uJ},  {J} = kl/(δ·{w}²)",
                             "span": "{span} = {v:.5g} {uJ}\n{J} = {span}/(δ·{w}²) = {J_v:.5g} {uI}",
                             "steady": "steady within δ/10 after {time:.4g} {u}",
                             "means": "cycle-mean speed (1/Φ)∮ω dφ", "band": "{w} = {v:.5g} {u} ± δ/10 (for the cycle mean)",
                             "not_reached": "steady state not reached (see summary)",
                             "axT": r"$T = T_0 + \Delta T$", "axJ": r"$J = J_I + J_{{II}}$",
                             "time": "Time law over one cycle: {T} = {v:.5g} {u}",
                             "tr": "Start-up and run-down", "start": "start-up (motor)", "run": "run-down (drive cut)",
                             # the parts of a figure (ГОСТ 2.105: а), б), в) in Russian)
                             "part_a": "(a)", "part_b": "(b)", "part_c": "(c)"})


def _f(t: dict, key: str, **kw) -> str:
    """The template ``key`` of ``t`` with the symbols, numbers and units filled in."""
    return t[key].format(**typeset_params(kw))         # Russian numbers in a Russian figure


#: the width [in] an axes' title has in a figure as wide as A4's text: it is centred on the
#: axes, which the y axis's labels move to the right (a suptitle, centred on the figure, has
#: A4_W − 0.2)
_TITLE_W = A4_W - 1.3


def _figure(size):
    """A pyplot-free Figure (render/figure.py) of ``size`` [in], laid out by matplotlib's
    constrained layout (its panels' labels and legends vary with the case)."""
    from matplotlib.figure import Figure

    from flywheel.render.figure import DPI

    return Figure(figsize=size, dpi=DPI, layout="constrained")


def figure_energy_mass(results, lang: str = "en"):
    """Wittenbauer's energy–mass diagram as course projects draw it, and Merzalov's ΔT_I beside it.

    (a) the whole construction: ΔT = A(φ) against J_II(φ) and the two tangents of slopes
    k± = ω_m²(1 ± δ/2)²/2 = ω_max²/2, ω_min²/2, extended leftwards until they meet at
    (−J_I, −T0), the origin of the full-energy axes (J = J_I + J_II, T = T0 + ΔT) — the exact
    J_I is the horizontal distance from that point to J_II = 0 (a dimension arrow). The tangents
    cut the ΔT axis (J_II = 0) at k and l: since k₊ − k₋ = δ·ω_m², J_I = kl/(δ·ω_m²)
    (design.md §2). (b) the curve enlarged, with the tangency points. (c) Merzalov's ΔT_I(φ)
    with ΔT_нб. Axes and key lines carry ``gid``/labels for tests: axes labels "full", "zoom",
    "merzalov"; lines "curve", "tangent_max", "tangent_min", "origin".
    """
    from matplotlib.patches import Rectangle

    t = TEXT[lang]
    s = results.scalars
    sz = results.sizing
    uJ, uI = nm.unit_of("A", lang), nm.unit_of("J_II", lang)
    J_sym, T0_sym, dT_sym = nm.tex("J_required", lang), nm.tex("T0", lang), nm.tex("dT_I", lang)
    w_m = nm.tex("omega_mean", lang)
    J_II = results.reduction.J_II
    A = results.energy.A
    k_p, k_m = sz.k_plus, sz.k_minus
    J_I, T0 = sz.J_required_exact, sz.T0_exact
    top, bottom = sz.T_k, sz.T_l              # the tangents at J_II = 0: points k and l
    i_max, i_min = sz.i_tangent_max, sz.i_tangent_min    # tangency points (ψ_max, ψ_min)
    kl = top - bottom

    fig = _figure((7.45, 9.0))
    axd = fig.subplot_mosaic([["full", "full"], ["zoom", "merzalov"]], height_ratios=[1.1, 1])
    ax, zx, bx = axd["full"], axd["zoom"], axd["merzalov"]
    for name, a in axd.items():
        a.set_label(name)
    heading = fig.suptitle(f"{results.title}\n{_f(t, 'em', dT=dT_sym)}; "
                           + _f(t, "J_exact", J=J_sym, exact=_f(t, "exact"), v=J_I, u=uI),
                           fontsize=11)
    wrap_lines(heading, A4_W - 0.2)               # a long case title in two lines

    # -- (a) the whole construction -----------------------------------------------------------
    x_hi = max(J_II.max(), 0.0)
    span_x = x_hi + J_I
    ax.plot(J_II, A, lw=1.2, color="tab:blue", gid="curve", label=_f(t, "curve"))
    j = np.array([-J_I, x_hi + 0.04 * span_x])
    ax.plot(j, top + k_p * j, "--", color="tab:red", gid="tangent_max",
            label=_f(t, "tan_slope", tan=_f(t, "tan_max"), w=nm.tex("omega_max", lang), k=k_p, uJ=uJ,
                     uI=uI))
    ax.plot(j, bottom + k_m * j, "--", color="tab:green", gid="tangent_min",
            label=_f(t, "tan_slope", tan=_f(t, "tan_min"), w=nm.tex("omega_min", lang), k=k_m, uJ=uJ,
                     uI=uI))
    ax.plot([-J_I], [-T0], "o", color="black", ms=6, gid="origin",
            label=_f(t, "origin", J=J_sym, T=T0_sym))
    y_lo, y_hi = -T0, max(A.max(), top + k_p * j[1])
    H = y_hi - y_lo
    # full-energy axes through O' (thin), and the ΔT axis J_II = 0
    ax.axvline(0.0, color="0.3", lw=0.8)
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.annotate("", xy=(-J_I, y_hi + 0.06 * H), xytext=(-J_I, -T0),
                arrowprops={"arrowstyle": "->", "color": "0.45", "lw": 0.8})
    ax.annotate("", xy=(x_hi + 0.06 * span_x, -T0), xytext=(-J_I, -T0),
                arrowprops={"arrowstyle": "->", "color": "0.45", "lw": 0.8})
    ax.text(-J_I + 0.01 * span_x, y_hi + 0.05 * H, _f(t, "axT"), fontsize=8, color="0.3", va="top")
    ax.text(x_hi + 0.05 * span_x, -T0 + 0.015 * H, _f(t, "axJ"), fontsize=8, color="0.3", ha="right")
    ax.annotate("O′", xy=(-J_I, -T0), xytext=(-8, 6), textcoords="offset points", ha="right",
                fontsize=10, fontweight="bold")
    # dimension: J_I from O′ to J_II = 0
    y_dim = -T0 - 0.07 * H
    ax.plot([-J_I, -J_I], [-T0, y_dim - 0.02 * H], color="black", lw=0.6)
    ax.plot([0.0, 0.0], [y_dim - 0.02 * H, -T0], color="black", lw=0.6)
    ax.annotate("", xy=(0.0, y_dim), xytext=(-J_I, y_dim), arrowprops={"arrowstyle": "<|-|>", "lw": 1.0})
    ax.text(-J_I / 2, y_dim + 0.012 * H, _f(t, "J_dim", J=J_sym, exact=_f(t, "exact"), v=J_I, u=uI),
            ha="center",
            va="bottom", fontsize=9, bbox={"fc": "white", "ec": "none", "pad": 1})
    # k and l on the ΔT axis, and the segment kl
    ax.plot([0.0, 0.0], [bottom, top], "s", color="black", ms=4)
    ax.annotate("k", xy=(0.0, top), xytext=(-6, 4), textcoords="offset points", ha="right", fontsize=9)
    ax.annotate("l", xy=(0.0, bottom), xytext=(-6, -10), textcoords="offset points", ha="right",
                fontsize=9)
    ax.annotate(_f(t, "kl", kl=kl, uJ=uJ, J=J_sym, w=w_m), xy=(0.0, (top + bottom) / 2),
                xytext=(-0.03 * span_x, top + 0.05 * H), ha="right", va="bottom", fontsize=8,
                bbox={"fc": "white", "ec": "none", "pad": 1},
                arrowprops={"arrowstyle": "-", "lw": 0.6, "color": "0.3"})
    # where the curve is (enlarged in b)
    x0, x1 = J_II.min(), J_II.max()
    ax.add_patch(Rectangle((x0, A.min()), max(x1 - x0, 0.002 * span_x), A.max() - A.min(),
                           fill=False, ec="tab:blue", lw=0.8, ls=":"))
    ax.annotate(_f(t, "part_b"), xy=(x1, A.max()), xytext=(3, 3), textcoords="offset points", fontsize=8,
                color="tab:blue")
    ax.set_xlim(-J_I - 0.05 * span_x, x_hi + 0.08 * span_x)
    ax.set_ylim(y_dim - 0.06 * H, y_hi + 0.12 * H)
    ax.set_xlabel(nm.axis("J_II", lang))
    ax.set_ylabel(_f(t, "T", u=uJ))
    ax.set_title(f"{_f(t, 'part_a')} {_f(t, 'full', J=J_sym, T=T0_sym)}", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, 0.9))

    # -- (b) the curve enlarged ----------------------------------------------------------------
    pad = 0.08 * (x1 - x0) if x1 > x0 else 0.02 * J_I
    z = np.array([x0 - pad, x1 + pad])
    zx.plot(J_II, A, lw=1.2, color="tab:blue", label=_f(t, "curve"))
    zx.plot(z, top + k_p * z, "--", color="tab:red", label=_f(t, "tan_max"))
    zx.plot(z, bottom + k_m * z, "--", color="tab:green", label=_f(t, "tan_min"))
    zx.plot(J_II[i_max], A[i_max], "o", color="tab:red", ms=5)
    zx.plot(J_II[i_min], A[i_min], "o", color="tab:green", ms=5)
    phi_deg = np.degrees(results.phi)
    zx.set_xlim(*z)
    # a half-width panel: at most five ticks, whose labels («0,0014») do not run together
    from matplotlib.ticker import MaxNLocator

    zx.xaxis.set_major_locator(MaxNLocator(4))
    zx.set_xlabel(nm.axis("J_II", lang))
    zx.set_ylabel(_f(t, "T", u=uJ))
    zx.set_title(f"{_f(t, 'part_b')} {_f(t, 'zoom')}", fontsize=10)
    zx.grid(True, alpha=0.3)
    zx.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), frameon=False)   # below: off the curve

    # -- (c) Merzalov --------------------------------------------------------------------------
    dT = results.columns["dT_I"].values
    bx.plot(phi_deg, dT, label=f"{dT_sym}(φ)")
    bx.axhline(s.delta_T_I_max, color="tab:red", lw=0.8, ls=":")
    bx.axhline(s.delta_T_I_min, color="tab:green", lw=0.8, ls=":")
    bx.annotate("", xy=(s.phi_delta_T_I_max_deg, s.delta_T_I_max),
                xytext=(s.phi_delta_T_I_max_deg, s.delta_T_I_min),
                arrowprops={"arrowstyle": "<->"})
    bx.plot([], [], " ", label=_f(t, "span", span=nm.tex("delta_T_max", lang), v=s.delta_T_max,
                                  uJ=uJ, J=J_sym, w=w_m, J_v=s.J_required, uI=uI))
    bx.set_xlabel(nm.axis("phi_deg", lang))
    bx.set_ylabel(nm.axis("dT_I", lang))
    cycle = results.cycle_deg
    bx.set_xlim(0, cycle)
    bx.set_xticks(np.arange(0, cycle + 1, 60 * cycle // 360))      # a half-width panel
    bx.grid(True, alpha=0.3)
    bx.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.13), frameon=False)
    bx.set_title(f"{_f(t, 'part_c')} {_f(t, 'merz', dT=dT_sym)}", fontsize=10)

    # the points of tangency's angles, placed once the panels have their final places
    lay_out(fig)
    _tangency_labels(zx, J_II, A, [(i_max, top, k_p), (i_min, bottom, k_m)], z, phi_deg)
    return fig


def _tangency_labels(zx, J_II, A, points, z, phi_deg) -> None:
    """Part (b)'s angles φ beside the points of tangency by the one label placer
    (render/labels.py): off the curve and the tangents, inside the panel, 4, 10 or 18 pt from
    the point (the nearest free place). ``points``: (index,
    the tangent's ΔT at J_II = 0, its slope) each; ``z``: the panel's J_II limits. The labels
    take no part in the layout (it is done: the panels keep their places when it runs again
    at saving)."""
    from flywheel.render.labels import AxesLabels, around

    places = np.vstack([around(4.0), around(10.0), around(18.0)])   # nearest first
    labels = AxesLabels(zx)
    labels.curve(np.column_stack([J_II, A]))
    for _, at0, slope in points:
        labels.curve(np.column_stack([z, at0 + slope * z]))
    labels.markers([(J_II[i], A[i]) for i, _, _ in points], 3.0)
    for i, _, _ in points:
        label = labels.point((float(J_II[i]), float(A[i])),
                             f"φ = {fmt(phi_deg[i], spec='.1f', zero=None)}°", places=places,
                             fontsize=8)
        label.set_in_layout(False)


def figure_time_law(results, lang: str = "en"):
    """ω(t) and ε(t) over one cycle of steady motion (t(φ) = ∫dφ/ω)."""
    t = TEXT[lang]
    time = results.columns["t"].values
    fig = _figure((7.45, 5.6))
    a1, a2 = fig.subplots(2, 1, sharex=True)
    a1.plot(time, results.columns["omega"].values, label="ω(t)")
    a1.set_ylabel(nm.axis("omega", lang))
    a2.plot(time, results.columns["epsilon"].values, color="tab:orange", label="ε(t)")
    a2.set_ylabel(nm.axis("epsilon", lang))
    a2.set_xlabel(nm.axis("t", lang))
    for a in (a1, a2):
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8, loc="best", framealpha=0.85)
    a1.set_title(f"{results.title}\n" + _f(t, "time", T=nm.tex("cycle_time", lang),
                                             v=results.scalars.cycle_time,
                                             u=nm.unit_of("cycle_time", lang)),
                 fontsize=10)
    wrap_lines(a1.title, _TITLE_W)                # a long case title in two lines
    return fig


def figure_transients(results, lang: str = "en"):
    """ω(t) during start-up (if the case has a motor) and run-down; the start-up with the steady
    speed ω_s of the motor line, its band ±δ/10 and the time to steady state (or a note that
    the steady state was not reached)."""
    t = TEXT[lang]
    hist = results.time_domain.histories
    st = results.time_domain.startup
    fig = _figure((7.45, 4.8))
    ax = fig.subplots()
    if "startup" in hist:
        ts, ws_ = hist["startup"]
        ax.plot(ts, ws_, lw=0.8, label=_f(t, "start"))
        mids, means = results.time_domain.startup_cycle_means
        if len(means):
            ax.plot(mids, means, ".", color="tab:blue", ms=4, label=_f(t, "means"))
        ws = st.omega_final_predicted
        if ws:
            band = results.scalars.delta / 10
            ax.axhspan(ws * (1 - band), ws * (1 + band), color="tab:blue", alpha=0.12,
                       label=_f(t, "band", w=nm.tex("omega_final_predicted", lang), v=ws,
                                u=nm.unit_of("omega_final_predicted", lang)))
        if st.stalled:
            pass
        elif st.time_to_steady is not None:
            ax.axvline(st.time_to_steady, color="tab:blue", ls=":", lw=1.0,
                       label=_f(t, "steady", time=st.time_to_steady, u=nm.unit_of("t", lang)))
        else:
            ax.plot([], [], " ", label=_f(t, "not_reached"))
    ax.plot(*hist["rundown"], lw=0.8, label=_f(t, "run"))
    ax.set_xlabel(nm.axis("t", lang))
    ax.set_ylabel(nm.axis("omega", lang))
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{results.title}\n{_f(t, 'tr')}", fontsize=10)
    wrap_lines(ax.title, _TITLE_W)
    return fig

