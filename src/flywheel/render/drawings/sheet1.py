"""Sheet 1, the law of motion: the scheme in its standard positions, the indicator diagrams,
the velocity analogues, J_II(φ), the reduced moments, the works, ΔT_I and T_II, the
energy–mass (Wittenbauer) diagram with its tangents, ω(φ), ε(φ) — each to round scale factors
μ stated beside its title — and the table of the main results. Everything read from the
results (dynamics/results.py); a tabulated case's sheet has no scheme.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.drawings.diagram import diagram, num
from flywheel.render.drawings.model import View, text_width
from flywheel.render.drawings.scheme import scheme_view
from flywheel.units import PA_PER_MPA

T = words("drawings1", {
    "scheme": "Kinematic scheme: the standard positions, scale {s}",
    "indicator": "Indicator diagram of cylinder {c}",
    "analogues": "Velocity analogues of the points",
    "J_II": "Reduced moment of inertia of the second group",
    "moments": "Reduced moments",
    "works": "Works of the driving forces and of the resistance",
    "energy": "Change of kinetic energy",
    "wittenbauer": "Energy–mass diagram",
    "omega": "Angular velocity of the crank",
    "epsilon": "Angular acceleration of the crank",
    "results": "Main results",
    "stroke": "stroke of the piston = 100 mm",
    "quantity": "Quantity",
    "symbol": "Symbol",
    "value": "Value",
    "unit": "Unit",
})

DIAGRAM_W = 180.0     # a φ diagram's abscissa over the cycle [mm]


def _t(lang: str) -> dict:
    return T["ru" if lang == "ru" else "en"]


def _phi_axis(results, lang: str, height: float = 70.0) -> dict:
    """The φ abscissa: φ in degrees over the cycle at a round μ_φ (2 °/mm for 360°)."""
    cycle = float(results.cycle_deg)
    mu = cycle / DIAGRAM_W
    step = 30.0 * cycle / 360.0
    return dict(x_mu=mu, x_symbol="φ", x_unit="°", x_label="φ, °",
                x_ticks=[k * step for k in range(int(round(cycle / step)) + 1)], lang=lang,
                height=height)


def _y(key: str, lang: str) -> dict:
    sym = nm.symbol(key, lang)
    u = nm.unit_of(key, lang)
    base = sym.split("_")[0].lstrip("Δ") or sym
    return dict(y_symbol=base, y_unit=u, y_label=f"{sym}, {u}")


def views(results, lang: str, room: dict) -> list[View]:
    """The views of sheet 1, in the order the layout places them; ``room``: sheet.ROOM of the
    format."""
    t = _t(lang)
    deg = np.degrees(results.phi)
    cols = results.columns
    out: list[View] = []
    if results.drawing is not None:
        i = results.index_of(math.radians(results.at[0].phi_deg) % results.cycle) \
            if results.at else 0
        sv = scheme_view(results, i, room["scheme"], lang, positions=True)
        x0, y0, x1, y1 = sv.box()
        sv.text(x0, y1 + 3.0, t["scheme"].format(s=sv.scales["label"]), 5.0)
        out.append(sv)
    for cyl in results.cylinders:
        # the loop p(s) in the order of φ, a piece per stroke (towards or away from the head):
        # a four-stroke engine's four strokes, a compressor's two
        s = np.asarray(cyl.s, float)
        p_mpa = np.asarray(cyl.p, float) / PA_PER_MPA
        towards = np.asarray(cyl.towards_head, bool)
        cuts = [0] + [int(k) + 1 for k in np.flatnonzero(towards[1:] != towards[:-1])] + [len(s)]
        curves = [(p_mpa[a:b + 1], "", "main", s[a:b + 1]) for a, b in zip(cuts[:-1], cuts[1:])
                  if b - a >= 1]
        mpa = nm.unit("MPa", lang)
        out.append(diagram(
            f"indicator {cyl.name}", t["indicator"].format(c=nm.cylinder_label(cyl, lang)), np.array([0.0, 1.0]),
            curves, x_mu=0.01, x_symbol="s", x_unit="–", x_label=nm.symbol("s_{cylinder}", lang),
            x_ticks=[0.0, 0.25, 0.5, 0.75, 1.0], y_symbol="p", y_unit=mpa,
            y_label=f"p, {mpa}", height=room["plot_h"], lang=lang, x_scale_text=t["stroke"]))
    moving = results.drawing.moving_points if results.drawing is not None else ()
    # a slider on a fixed guide: v_q along the guide, signed (dS/dφ: Drawing.slider_analogues);
    # any other point: |v_q|
    sliders = {j: link for link, j, _ in results.drawing.guided_sliders} if moving else {}
    vq = [(results.drawing.slider_analogues[sliders[p]][0] if p in sliders
           else cols[f"vq_{p}"].values, f"v_q{p}", ["main", "thin", "dashed"][k % 3])
          for k, p in enumerate(moving) if f"vq_{p}" in cols]
    if vq:
        out.append(diagram("analogues", t["analogues"], deg, vq, **_phi_axis(results, lang, room['plot_h']),
                           **_y("v_q", lang)))
    out.append(diagram("J_II", t["J_II"], deg, [(cols["J_II"].values, "", "main")],
                       **_phi_axis(results, lang, room['plot_h']), **_y("J_II", lang)))
    sc = results.scalars
    key = "driving_moment" if sc.balance == "driving" else "M_C"
    cyc = float(results.cycle_deg)
    out.append(diagram(
        "moments", t["moments"], deg,
        [(cols["M_known"].values, nm.symbol("M_known", lang), "thin"),
         (cols["M_sum"].values, nm.symbol("M_sum", lang), "main")],
        lines=[((0.0, sc.balancing_moment), (cyc, sc.balancing_moment), "dashed",
                nm.symbol(key, lang))],
        **_phi_axis(results, lang, room['plot_h']), **_y("M_sum", lang)))
    out.append(diagram(
        "works", t["works"], deg,
        [(cols["A_D"].values, nm.symbol("A_D", lang), "thin"),
         (cols["A_C"].values, nm.symbol("A_C", lang), "dashed"),
         (cols["A"].values, nm.symbol("A", lang), "main")],
        **_phi_axis(results, lang, room['plot_h']), **_y("A", lang)))
    out.append(diagram(
        "energy", t["energy"], deg,
        [(cols["T_II"].values, nm.symbol("T_II", lang), "thin"),
         (cols["dT_I"].values, nm.symbol("dT_I", lang), "main")],
        marks=[(sc.phi_delta_T_I_max_deg, sc.delta_T_I_max, ""),
               (sc.phi_delta_T_I_min_deg, sc.delta_T_I_min, "")],
        **_phi_axis(results, lang, room['plot_h']), **_y("dT_I", lang)))
    out.append(_wittenbauer(results, lang, 1.1 * room['plot_h']))
    out.append(diagram(
        "omega", t["omega"], deg, [(cols["omega"].values, "", "main")], lifted=True,
        lines=[((0.0, sc.omega_mean), (cyc, sc.omega_mean), "axis", nm.symbol("omega_mean", lang))],
        **_phi_axis(results, lang, room['plot_h']), **_y("omega", lang)))
    out.append(diagram("epsilon", t["epsilon"], deg, [(cols["epsilon"].values, "", "main")],
                       **_phi_axis(results, lang, room['plot_h']), **_y("epsilon", lang)))
    out.append(results_table(results, lang))
    return out


def _wittenbauer(results, lang: str, side: float) -> View:
    """ΔT = A against J_II with the tangents of slopes ω_max²/2 and ω_min²/2 through their
    tangency points, cut at J_II = 0 in k and l (results.sizing: k_plus, k_minus, T_k, T_l,
    i_tangent_max, i_tangent_min)."""
    t = _t(lang)
    sz = results.sizing
    J = np.asarray(results.reduction.J_II, float)
    A = np.asarray(results.energy.A, float)
    jm = float(J.max()) * 1.05
    lines = []
    for i, k_slope, T0, lab in ((sz.i_tangent_max, sz.k_plus, sz.T_k, "k"),
                                (sz.i_tangent_min, sz.k_minus, sz.T_l, "l")):
        lines.append(((0.0, T0), (jm, T0 + k_slope * jm), "thin", ""))
    from flywheel.dynamics.plans import round_scale

    lo = min(0.0, float(A.min()), sz.T_l, sz.T_k)
    hi = max(0.0, float(A.max()), sz.T_k, sz.T_l, sz.T_k + sz.k_plus * jm)
    lo = min(lo, sz.T_l + sz.k_minus * jm)
    mu_T = round_scale(hi - lo, side)
    mu_J = round_scale(jm, side)
    v = diagram("wittenbauer", t["wittenbauer"], J, [(A, "", "main")], x_mu=mu_J,
                x_symbol="J", x_unit=nm.unit_of("J_II", lang),
                x_label=f"{nm.symbol('J_II', lang)}, {nm.unit_of('J_II', lang)}",
                y_symbol="T", y_unit=nm.unit_of("A", lang),
                y_label=f"ΔT, {nm.unit_of('A', lang)}", lang=lang, y_mu=mu_T,
                lines=lines, marks=[(0.0, sz.T_k, "k"), (0.0, sz.T_l, "l"),
                                    (float(J[sz.i_tangent_max]), float(A[sz.i_tangent_max]), ""),
                                    (float(J[sz.i_tangent_min]), float(A[sz.i_tangent_min]), "")])
    return v


def results_table(results, lang: str) -> View:
    """The main results (render/main_results.py) as a table of four columns — name, symbol,
    value, unit (ГОСТ 2.105-2019, 4.4: a table's column heads and its cells' text from a
    capital letter)."""
    from flywheel.render.main_results import main_results

    t = _t(lang)
    rows = main_results(results, lang, ratio_text=lambda i: num(i, lang))
    head = (t["quantity"], t["symbol"], t["value"], t["unit"])
    w0 = max(text_width(r[0], 3.5) for r in rows + [head]) + 6.0
    w1 = max(text_width(r[1].replace("_", ""), 3.5) for r in rows + [head]) + 8.0
    widths = (max(w0, 40.0), w1, 30.0, 24.0)
    row_h = 8.0
    v = View("results")
    n = len(rows) + 1
    W, H = v.grid(widths, n, row_h)
    for k, row in enumerate([head] + [(a, b, num(c, lang), d) for a, b, c, d in rows]):
        y = H - (k + 0.5) * row_h
        x = 0.0
        for j, (w, cell) in enumerate(zip(widths, row)):
            if j == 0:
                v.rich(x + 2.0, y, cell, 3.5, valign="middle")
            else:
                v.rich(x + w / 2, y, cell, 3.5, halign="center", valign="middle")
            x += w
    v.text(0.0, H + 3.0, t["results"], 5.0)
    return v
