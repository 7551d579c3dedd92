"""Plots beyond the worksheet (issue 6): Wittenbauer's energy–mass diagram beside Merzalov's
ΔT_I construction, the time law ω(t), ε(t), and the start-up / run-down histories.

Figures are built by functions that return them (tests check structure); ``write_extra_plots``
saves them. matplotlib is imported inside the functions (0.7 s to import).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

TEXT = {
    "en": {"em": "Energy–mass diagram (Wittenbauer) and Merzalov's ΔT_I",
           "J": "J_II [kg·m²]", "T": "ΔT = A(φ) [J]", "phi": "φ [deg]", "dT": "ΔT_I [J]",
           "curve": "ΔT(J_II) over the cycle", "tan_max": "tangent at ψ_max", "tan_min": "tangent at ψ_min",
           "origin": "origin of the full-energy axes (−J_I, −T0)", "dTI": "ΔT_I(φ)",
           "span": "ΔT_нб", "time": "Time law over one cycle", "t": "t [s]", "w": "ω [rad/s]",
           "e": "ε [rad/s²]", "tr": "Start-up and run-down", "start": "start-up (motor)",
           "run": "run-down (drive cut)"},
    "ru": {"em": "Диаграмма энергомасс (Виттенбауэр) и ΔT_I по Мерцалову",
           "J": "J_II [кг·м²]", "T": "ΔT = A(φ) [Дж]", "phi": "φ [град]", "dT": "ΔT_I [Дж]",
           "curve": "ΔT(J_II) за цикл", "tan_max": "касательная под ψ_max", "tan_min": "касательная под ψ_min",
           "origin": "начало осей полной энергии (−J_I, −T0)", "dTI": "ΔT_I(φ)",
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
    """Left: ΔT = A(φ) against J_II(φ) with the two tangents whose slopes are
    ω_max²/2 = k₊ and ω_min²/2 = k₋ (δ target); they meet at (−J_I, −T0), the exact J_I
    (design.md §2). Right: Merzalov's ΔT_I(φ) with ΔT_нб."""
    plt = _plt()
    t = TEXT[lang]
    s = results.scalars
    J_II = results.columns["J_II"].values
    A = results.columns["A"].values
    w_m, delta = s["omega_mean"], s["delta"]
    k_p = w_m**2 * (1 + delta / 2) ** 2 / 2
    k_m = w_m**2 * (1 - delta / 2) ** 2 / 2
    J_I = s["J_required_exact"]
    top = np.max(A - k_p * J_II)
    bottom = np.min(A - k_m * J_II)
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(12, 5), constrained_layout=True)
    ax.plot(J_II, A, lw=1.2, label=t["curve"])
    j = np.linspace(J_II.min(), J_II.max(), 2)
    ax.plot(j, top + k_p * j, "--", color="tab:red", label=f"{t['tan_max']}: ω_max²/2 = {k_p:.5g}")
    ax.plot(j, bottom + k_m * j, "--", color="tab:green", label=f"{t['tan_min']}: ω_min²/2 = {k_m:.5g}")
    ax.set_xlabel(t["J"])
    ax.set_ylabel(t["T"])
    ax.set_title(f"{results.title}\n{t['em']}; J_I exact = {J_I:.5g} kg·m²", fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    phi_deg = np.degrees(results.phi)
    dT = results.columns["dT_I"].values
    bx.plot(phi_deg, dT, label=t["dTI"])
    bx.axhline(s["delta_T_I_max"], color="tab:red", lw=0.8, ls=":")
    bx.axhline(s["delta_T_I_min"], color="tab:green", lw=0.8, ls=":")
    bx.annotate("", xy=(s["phi_delta_T_I_max_deg"], s["delta_T_I_max"]),
                xytext=(s["phi_delta_T_I_max_deg"], s["delta_T_I_min"]),
                arrowprops={"arrowstyle": "<->"})
    bx.plot([], [], " ", label=f"{t['span']} = {s['delta_T_max']:.5g} J; J_I = {s['J_required']:.5g} kg·m²")
    bx.set_xlabel(t["phi"])
    bx.set_ylabel(t["dT"])
    bx.set_xlim(0, 360)
    bx.set_xticks(np.arange(0, 361, 30))
    bx.grid(True, alpha=0.3)
    bx.legend(fontsize=8, loc="best")
    bx.set_title("Merzalov" if lang == "en" else "Мерцалов", fontsize=10)
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
    a1.set_title(f"{results.title}\n{t['time']}: T = {results.scalars['cycle_time']:.5g} s", fontsize=10)
    return fig


def figure_transients(results, lang: str = "en"):
    """ω(t) during start-up (if the case has a motor) and run-down."""
    plt = _plt()
    t = TEXT[lang]
    hist = results.time_domain["histories"]
    fig, ax = plt.subplots(figsize=(9, 5), constrained_layout=True)
    if "startup" in hist:
        ax.plot(*hist["startup"], label=t["start"])
    ax.plot(*hist["rundown"], label=t["run"])
    ax.set_xlabel(t["t"])
    ax.set_ylabel(t["w"])
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title(f"{results.title}\n{t['tr']}", fontsize=10)
    return fig


def write_extra_plots(results, folder: Path, lang: str = "en") -> list[Path]:
    """Write energy_mass.png, time_law.png and (with --transients) transients.png."""
    plt = _plt()
    figs = {"energy_mass.png": figure_energy_mass, "time_law.png": figure_time_law}
    if results.time_domain is not None:
        figs["transients.png"] = figure_transients
    out = []
    for name, make in figs.items():
        fig = make(results, lang)
        path = Path(folder) / name
        fig.savefig(path, dpi=120, metadata={"Software": None})
        plt.close(fig)
        out.append(path)
    return out
