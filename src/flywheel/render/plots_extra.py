"""Plots beyond the worksheet (issue 6): Wittenbauer's energy–mass diagram beside Merzalov's
ΔT_I construction, the time law ω(t), ε(t), and the start-up / run-down histories.

Figures are built by functions that return them (tests check structure);
:func:`flywheel.render.plots.write_plots` saves them with the worksheet's plots, in the same
worker processes. matplotlib is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations


import numpy as np

TEXT = {
    "en": {"em": "Energy–mass diagram (Wittenbauer) and Merzalov's ΔT_I",
           "J": "J_II [kg·m²]", "T": "ΔT = A(φ) [J]", "phi": "φ [deg]", "dT": "ΔT_I [J]",
           "curve": "ΔT(J_II) over the cycle", "tan_max": "tangent at ψ_max", "tan_min": "tangent at ψ_min",
           "origin": "origin of the full-energy axes (−J_I, −T0)", "dTI": "ΔT_I(φ)",
           "full": "the whole construction: the tangents meet at O′ (−J_I, −T0)",
           "zoom": "the curve enlarged: points of tangency", "merz": "Merzalov: ΔT_I(φ)",
           "exact": "exact", "uJ": "J", "us": "s", "uw": "rad/s",
           "steady": "steady within δ/10 after", "means": "cycle-mean speed (1/Φ)∮ω dφ", "band": "for the cycle mean", "not_reached": "steady state not reached (see summary)", "uI": "kg·m²", "axT": "T = T0 + ΔT", "axJ": "J = J_I + J_II",
           "span": "ΔT_нб", "time": "Time law over one cycle", "t": "t [s]", "w": "ω [rad/s]",
           "e": "ε [rad/s²]", "tr": "Start-up and run-down", "start": "start-up (motor)",
           "run": "run-down (drive cut)"},
    "ru": {"em": "Диаграмма энергомасс (Виттенбауэр) и ΔT_I по Мерцалову",
           "J": "J_II [кг·м²]", "T": "ΔT = A(φ) [Дж]", "phi": "φ [град]", "dT": "ΔT_I [Дж]",
           "curve": "ΔT(J_II) за цикл", "tan_max": "касательная под ψ_max", "tan_min": "касательная под ψ_min",
           "origin": "начало осей полной энергии (−J_I, −T0)", "dTI": "ΔT_I(φ)",
           "full": "построение целиком: касательные пересекаются в O′ (−J_I, −T0)",
           "zoom": "кривая в крупном масштабе: точки касания", "merz": "Мерцалов: ΔT_I(φ)",
           "exact": "точно", "uJ": "Дж", "us": "с", "uw": "рад/с",
           "steady": "установившийся режим (δ/10) через", "means": "средняя за цикл скорость (1/Φ)∮ω dφ", "band": "для средней за цикл", "not_reached": "установившийся режим не достигнут", "uI": "кг·м²", "axT": "T = T0 + ΔT", "axJ": "J = J_I + J_II",
           "span": "ΔT_нб", "time": "Закон движения за цикл", "t": "t [с]", "w": "ω [рад/с]",
           "e": "ε [рад/с²]", "tr": "Разгон и выбег", "start": "разгон (двигатель)",
           "run": "выбег (привод отключён)"},
}


def _plt():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


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

    plt = _plt()
    t = TEXT[lang]
    s = results.scalars
    sz = results.sizing
    J_II = results.reduction.J_II
    A = results.energy.A
    k_p, k_m = sz.k_plus, sz.k_minus
    J_I, T0 = sz.J_required_exact, sz.T0_exact
    top, bottom = sz.T_k, sz.T_l              # the tangents at J_II = 0: points k and l
    i_max, i_min = sz.i_tangent_max, sz.i_tangent_min    # tangency points (ψ_max, ψ_min)
    kl = top - bottom

    fig, axd = plt.subplot_mosaic([["full", "full"], ["zoom", "merzalov"]], figsize=(12, 9.5),
                                  constrained_layout=True, height_ratios=[1.1, 1])
    ax, zx, bx = axd["full"], axd["zoom"], axd["merzalov"]
    for name, a in axd.items():
        a.set_label(name)
    fig.suptitle(f"{results.title}\n{t['em']}; J_I ({t['exact']}) = {J_I:.5g} {t['uI']}", fontsize=11)

    # -- (a) the whole construction -----------------------------------------------------------
    x_hi = max(J_II.max(), 0.0)
    span_x = x_hi + J_I
    ax.plot(J_II, A, lw=1.2, color="tab:blue", gid="curve", label=t["curve"])
    j = np.array([-J_I, x_hi + 0.04 * span_x])
    ax.plot(j, top + k_p * j, "--", color="tab:red", gid="tangent_max",
            label=f"{t['tan_max']}: ω_max²/2 = {k_p:.5g} {t['uJ']}/({t['uI']})")
    ax.plot(j, bottom + k_m * j, "--", color="tab:green", gid="tangent_min",
            label=f"{t['tan_min']}: ω_min²/2 = {k_m:.5g} {t['uJ']}/({t['uI']})")
    ax.plot([-J_I], [-T0], "o", color="black", ms=6, gid="origin", label=t["origin"])
    y_lo, y_hi = -T0, max(A.max(), top + k_p * j[1])
    H = y_hi - y_lo
    # full-energy axes through O' (thin), and the ΔT axis J_II = 0
    ax.axvline(0.0, color="0.3", lw=0.8)
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.annotate("", xy=(-J_I, y_hi + 0.06 * H), xytext=(-J_I, -T0),
                arrowprops={"arrowstyle": "->", "color": "0.45", "lw": 0.8})
    ax.annotate("", xy=(x_hi + 0.06 * span_x, -T0), xytext=(-J_I, -T0),
                arrowprops={"arrowstyle": "->", "color": "0.45", "lw": 0.8})
    ax.text(-J_I + 0.01 * span_x, y_hi + 0.05 * H, t["axT"], fontsize=8, color="0.3", va="top")
    ax.text(x_hi + 0.05 * span_x, -T0 + 0.015 * H, t["axJ"], fontsize=8, color="0.3", ha="right")
    ax.annotate("O′", xy=(-J_I, -T0), xytext=(-8, 6), textcoords="offset points", ha="right",
                fontsize=10, fontweight="bold")
    # dimension: J_I from O′ to J_II = 0
    y_dim = -T0 - 0.07 * H
    ax.plot([-J_I, -J_I], [-T0, y_dim - 0.02 * H], color="black", lw=0.6)
    ax.plot([0.0, 0.0], [y_dim - 0.02 * H, -T0], color="black", lw=0.6)
    ax.annotate("", xy=(0.0, y_dim), xytext=(-J_I, y_dim), arrowprops={"arrowstyle": "<|-|>", "lw": 1.0})
    ax.text(-J_I / 2, y_dim + 0.012 * H, f"J_I = {J_I:.5g} {t['uI']} ({t['exact']})", ha="center",
            va="bottom", fontsize=9, bbox={"fc": "white", "ec": "none", "pad": 1})
    # k and l on the ΔT axis, and the segment kl
    ax.plot([0.0, 0.0], [bottom, top], "s", color="black", ms=4)
    ax.annotate("k", xy=(0.0, top), xytext=(-6, 4), textcoords="offset points", ha="right", fontsize=9)
    ax.annotate("l", xy=(0.0, bottom), xytext=(-6, -10), textcoords="offset points", ha="right",
                fontsize=9)
    ax.annotate(f"kl = {kl:.5g} {t['uJ']},  J_I = kl/(δ·ω_m²)", xy=(0.0, (top + bottom) / 2),
                xytext=(-0.03 * span_x, top + 0.05 * H), ha="right", va="bottom", fontsize=8,
                bbox={"fc": "white", "ec": "none", "pad": 1},
                arrowprops={"arrowstyle": "-", "lw": 0.6, "color": "0.3"})
    # where the curve is (enlarged in b)
    x0, x1 = J_II.min(), J_II.max()
    ax.add_patch(Rectangle((x0, A.min()), max(x1 - x0, 0.002 * span_x), A.max() - A.min(),
                           fill=False, ec="tab:blue", lw=0.8, ls=":"))
    ax.annotate("(b)", xy=(x1, A.max()), xytext=(3, 3), textcoords="offset points", fontsize=8,
                color="tab:blue")
    ax.set_xlim(-J_I - 0.05 * span_x, x_hi + 0.08 * span_x)
    ax.set_ylim(y_dim - 0.06 * H, y_hi + 0.12 * H)
    ax.set_xlabel(t["J"])
    ax.set_ylabel(t["T"])
    ax.set_title(f"(a) {t['full']}", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.0, 0.9))

    # -- (b) the curve enlarged ----------------------------------------------------------------
    pad = 0.08 * (x1 - x0) if x1 > x0 else 0.02 * J_I
    z = np.array([x0 - pad, x1 + pad])
    zx.plot(J_II, A, lw=1.2, color="tab:blue", label=t["curve"])
    zx.plot(z, top + k_p * z, "--", color="tab:red", label=t["tan_max"])
    zx.plot(z, bottom + k_m * z, "--", color="tab:green", label=t["tan_min"])
    zx.plot(J_II[i_max], A[i_max], "o", color="tab:red", ms=5)
    zx.plot(J_II[i_min], A[i_min], "o", color="tab:green", ms=5)
    phi_deg = np.degrees(results.phi)
    for i, dy in ((i_max, 8), (i_min, -14)):
        zx.annotate(f"φ = {phi_deg[i]:.1f}°", xy=(J_II[i], A[i]), xytext=(4, dy),
                    textcoords="offset points", fontsize=8)
    zx.set_xlim(*z)
    zx.set_xlabel(t["J"])
    zx.set_ylabel(t["T"])
    zx.set_title(f"(b) {t['zoom']}", fontsize=10)
    zx.grid(True, alpha=0.3)
    zx.legend(fontsize=8, loc="best")

    # -- (c) Merzalov --------------------------------------------------------------------------
    dT = results.columns["dT_I"].values
    bx.plot(phi_deg, dT, label=t["dTI"])
    bx.axhline(s["delta_T_I_max"], color="tab:red", lw=0.8, ls=":")
    bx.axhline(s["delta_T_I_min"], color="tab:green", lw=0.8, ls=":")
    bx.annotate("", xy=(s["phi_delta_T_I_max_deg"], s["delta_T_I_max"]),
                xytext=(s["phi_delta_T_I_max_deg"], s["delta_T_I_min"]),
                arrowprops={"arrowstyle": "<->"})
    bx.plot([], [], " ", label=f"{t['span']} = {s['delta_T_max']:.5g} {t['uJ']}\n"
                              f"J_I = {t['span']}/(δ·ω_m²) = {s['J_required']:.5g} {t['uI']}")
    bx.set_xlabel(t["phi"])
    bx.set_ylabel(t["dT"])
    cycle = results.cycle_deg
    bx.set_xlim(0, cycle)
    bx.set_xticks(np.arange(0, cycle + 1, 30 * cycle // 360))
    bx.grid(True, alpha=0.3)
    bx.legend(fontsize=8, loc="best")
    bx.set_title(f"(c) {t['merz']}", fontsize=10)
    return fig


def figure_time_law(results, lang: str = "en"):
    """ω(t) and ε(t) over one cycle of steady motion (t(φ) = ∫dφ/ω)."""
    plt = _plt()
    t = TEXT[lang]
    time = results.columns["t"].values
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True, constrained_layout=True)
    a1.plot(time, results.columns["omega"].values, label="ω(t)")
    a1.set_ylabel(t["w"])
    a2.plot(time, results.columns["epsilon"].values, color="tab:orange", label="ε(t)")
    a2.set_ylabel(t["e"])
    a2.set_xlabel(t["t"])
    for a in (a1, a2):
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8, loc="upper right")
    a1.set_title(f"{results.title}\n{t['time']}: T = {results.scalars['cycle_time']:.5g} {t['us']}",
                 fontsize=10)
    return fig


def figure_transients(results, lang: str = "en"):
    """ω(t) during start-up (if the case has a motor) and run-down; the start-up with the steady
    speed ω_s of the motor line, its band ±δ/10 and the time to steady state (or a note that
    the steady state was not reached)."""
    plt = _plt()
    t = TEXT[lang]
    hist = results.time_domain.histories
    st = results.time_domain.startup
    fig, ax = plt.subplots(figsize=(9, 5), constrained_layout=True)
    if "startup" in hist:
        ts, ws_ = hist["startup"]
        ax.plot(ts, ws_, lw=0.8, label=t["start"])
        mids, means = results.time_domain.startup_cycle_means
        if len(means):
            ax.plot(mids, means, ".", color="tab:blue", ms=4, label=t["means"])
        ws = st.get("omega_final_predicted")
        if ws:
            band = results.scalars["delta"] / 10
            ax.axhspan(ws * (1 - band), ws * (1 + band), color="tab:blue", alpha=0.12,
                       label=f"ω_s = {ws:.5g} {t['uw']} ± δ/10 ({t['band']})")
        if st.get("time_to_steady") is not None:
            ax.axvline(st["time_to_steady"], color="tab:blue", ls=":", lw=1.0,
                       label=f"{t['steady']} {st['time_to_steady']:.4g} {t['us']}")
        elif not st.get("stalled"):
            ax.plot([], [], " ", label=t["not_reached"])
    ax.plot(*hist["rundown"], lw=0.8, label=t["run"])
    ax.set_xlabel(t["t"])
    ax.set_ylabel(t["w"])
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{results.title}\n{t['tr']}", fontsize=10)
    return fig

