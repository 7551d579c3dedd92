"""The force analysis as people read it: forces.csv, forces_positions.csv, the rich summary's
section and the report's section, as document blocks (issue 12). Text only: every number comes from
``Results.forces`` (:class:`~flywheel.dynamics.results.ForceResult`); every quantity's name,
symbol and unit from :mod:`flywheel.render.nomenclature`; this module keeps the sentence
templates. Numbers in the CSV files follow render/tables.py: 12 significant digits (``%.12g``),
so the same input gives byte-identical files.
"""
from __future__ import annotations

import math

import numpy as np

from flywheel.dynamics.plans import link_pair
from flywheel.render.blocks import Bullets, Heading, Paragraph
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name
from flywheel.render.nomenclature import csv_header, name, symbol, unit, unit_of
from flywheel.render.positions import numbered, position_cells
from flywheel.render.numbers import column_zero, fmt as _number, fmt_rows, fmt_text

T = words("forces", {
    "title": "Force analysis (kinetostatics)",
    "motion_true": "motion: true — ω(φ), ε(φ) of the dynamics with the flywheel "
                   "(J_I = {J} kg·m² on the crank shaft)",
    "motion_steady": "motion: steady — ω = ω_m = {w} rad/s, ε = 0 (the crank turns uniformly)",
    "closure": "closure with the dynamics (true motion): max|M_y − {ref}|/|{ref}| = {c} "
               "over the cycle ({n} nodes){ok}",
    "closure_J": "closure with the dynamics (true motion): {ref} = 0, max|M_y|/max|J_I·ε| = {c} "
                 "over the cycle ({n} nodes){ok}",
    "ok": " — M_y = {ref} at every φ, the equation of motion read backwards (the closure check)",
    "bad": " — NOT round-off: check the loads",
    "mean": "cycle mean of M_y: {m} N·m ({ref} = {d} N·m)",
    "groups": ("balancing moment of the Assur groups M_y,gr (without the first group's inertia): "
               "from {lo} to {hi} N·m over the cycle; M_y = M_y,gr + J_I·ε"),
    "moments": "Balancing moment M_y at the report angles [N·m]",
    "kin": "kinetostatics", "zhuk": "Zhukovsky's lever", "power": "power balance",
    "grp": "Assur groups: M_y,gr = M_y − J_I·ε",
    "joints": "Joint reactions at φ = {a}° (R_ij: the force of link i on link j)",
    "sc": "Slider-crank quantities at φ = {a}°",
    "joint": "joint", "point": "point", "by": "by", "on": "on", "angle": "angle",
    "slider": "slider", "pos": "position", "no": "no.",
    "intro": ("Loads on every moving link: the given forces (gas, technological, weights), "
              "the couples, d'Alembert's inertia force −m·a_S at the centroid and couple "
              "−J_S·ε_i, and −J_I·ε on the crank (the first group as the flywheel sizing left "
              "it). The Assur groups are solved from the last one back to the crank; R_ij is "
              "the force of link i on link j at their joint (the frame is 0), its angle from "
              "+x counter-clockwise. M_y is the moment the drive applies to the crank, "
              "positive in the direction of rotation, found three ways: kinetostatics, "
              "Zhukovsky's lever (Σ F·v_q + Σ M·ω_q with the inertia loads, M_y = −that "
              "sum) and the power balance (M_y = J·ε + ½·J′·ω² − Σ F·v_q − Σ M·ω_q). With the "
              "true motion and the first group's inertia M_y equals the constant moment of the "
              "cycle condition at every φ: that is the check of the calculation. The moment the "
              "crank delivers to the Assur groups, M_y,gr = M_y + (−J_I·ε), varies over the "
              "cycle; the flywheel's inertia torque −J_I·ε makes up the difference. Zhukovsky's "
              "lever of the course (the groups' loads, the crank turning uniformly) gives "
              "M_y,gr."),
    "positions": "Reactions |R_ij| [N] and M_y [N·m] at the standard positions",
    "at": "At φ = {a}°",
    "frame": ("Crank-pin load {P} N (F_T = {T} N, F_R = {R} N); main bearing {B} N; "
              "shaking force {S} N, shaking moment {M} N·m."),
    # a linkage without a crankshaft (no cylinder): the same in English; in Russian the
    # crank's pin and bearing («палец», «опора»), not a crankshaft's («шатунная шейка»,
    # «коренной подшипник»)
    "frame_linkage": ("Crank-pin load {P} N (F_T = {T} N, F_R = {R} N); main bearing {B} N; "
                      "shaking force {S} N, shaking moment {M} N·m."),
    "tab_positions": ("M_y by the power balance at the table's positions [N·m], beside the "
                      "seed's static and dynamic moments at ω_m (with the steady motion "
                      "M_y = M_st + M_dyn)"),
    "note": ("joint reactions need a linkage: the kinematics are a table, so M_y is given by "
             "the power balance only, M_y = (J_I + J_II)·ε + ½·dJ_II/dφ·ω² − M_known"),
})

SLIDER_CRANK = ("piston_effort", "side_thrust", "rod_thrust", "crank_pin_tangential",
                "crank_pin_radial", "turning_moment")
CLOSURE_OK = 1e-9           # a closure above this is not round-off


def _g(x, digits: int = 5, zero: float = 1e-13) -> str:
    return _number(x, digits, zero=zero, nonfinite="dash")


# -- the columns ------------------------------------------------------------------------------------

def force_columns(results) -> dict[str, np.ndarray]:
    """forces.csv's columns by nomenclature key, in order: φ, the crank's ω and ε used, M_y
    (three ways), every reaction (x, y, magnitude), the slider-crank quantities, the loads on
    the crank pin and the main bearing, the shaking force and moment. Arrays of the result,
    selected — nothing computed here but degrees."""
    f = results.forces
    cols = {"phi_deg": np.degrees(results.phi), "omega": f.omega, "epsilon": f.epsilon}
    fa = f.analysis
    if fa is None:
        cols["M_y_power"] = f.M_y_power
        return cols
    cols.update({"M_y": fa.balancing_moment, "M_y_groups": fa.balancing_moment_groups,
                 "M_y_zhukovsky": f.M_y_zhukovsky, "M_y_power": f.M_y_power})
    for key, r in f.joints.items():
        cols[f"Rx_{key}"], cols[f"Ry_{key}"], cols[f"R_{key}"] = r.x, r.y, r.magnitude
    for s, sc in f.slider_crank.items():
        for q in SLIDER_CRANK:
            cols[f"{q}_{s}"] = getattr(sc, q)
    P = f.crank_pin_load
    cols.update({"crank_pin_Fx": P[:, 0], "crank_pin_Fy": P[:, 1],
                 "crank_pin_F": np.hypot(P[:, 0], P[:, 1]),
                 "crank_pin_tangential": f.crank_pin_tangential,
                 "crank_pin_radial": f.crank_pin_radial})
    mb = fa.main_bearing_load
    cols.update({"main_bearing_Fx": mb.x, "main_bearing_Fy": mb.y, "main_bearing_F": mb.magnitude})
    S = fa.shaking_force
    cols.update({"shaking_Fx": S[:, 0], "shaking_Fy": S[:, 1],
                 "shaking_F": np.hypot(S[:, 0], S[:, 1]), "shaking_M": fa.shaking_moment})
    return cols


def _data(cols: dict[str, np.ndarray]) -> np.ndarray:
    return np.column_stack(list(cols.values()))


def forces_csv(results) -> str:
    """forces.csv: every column of :func:`force_columns` on the grid; header ``name [unit]``.

    The rows' text made whole, a block of rows at a time (numbers.fmt_text: the same
    ``%.12g`` as render/tables.py's per value, negative zero written as 0)."""
    cols = force_columns(results)
    return ",".join(csv_header(k) for k in cols) + "\n" + fmt_text(_data(cols), 12)


def forces_positions_csv(results) -> str:
    """forces_positions.csv: the columns of forces.csv at the standard positions (every 30° and
    the sliders' dead centres; the table's positions for a tabulated case), a ``position``
    label and ``number`` first, as positions.csv."""
    from flywheel.render.tables import number_cell

    cols = force_columns(results)
    idx = [results.index_of(pos.phi) for pos in results.position_angles]
    labels = [f"{pos.label},{number_cell(pos.number)}" for pos in results.position_angles]
    rows = fmt_rows(_data(cols)[idx], 12)
    header = "position,number," + ",".join(csv_header(k) for k in cols)
    return "\n".join([header] + [f"{lab},{row}" for lab, row in zip(labels, rows)]) + "\n"


# -- sentences ------------------------------------------------------------------------------------

def note(results, lang: str) -> str:
    """The one line of a tabulated case: no joint reactions without a linkage."""
    f = results.forces
    if not f.note:
        return ""
    return T["ru"]["note"] if lang == "ru" else f.note     # T["en"]["note"]: dynamics/stages.py's


def summary_lines(results, lang: str = "en") -> list[str]:
    """The motion, the closure check and the cycle mean of M_y, as lines of text.

    The closure is round-off (≤ 1e-9) when the force analysis and the dynamics agree."""
    t = T[lang]
    f = results.forces
    s = results.scalars
    lines = [note(results, lang)] if f.note else []
    if f.motion == "true":
        lines.append(t["motion_true"].format(J=_g(results.motion.J_I, 6)))
    else:
        lines.append(t["motion_steady"].format(w=_g(float(f.omega[0]), 6)))
    n = results.phi.size
    ref = symbol("driving_moment" if results.energy.balance == "driving" else "M_C", lang)
    ok = t["ok"].format(ref=ref) if f.closure <= CLOSURE_OK else t["bad"]
    if f.closure_reference == "M_D":
        lines.append(t["closure"].format(ref=ref, c=_number(f.closure, spec=".2e", zero=None, nonfinite="show"), n=n, ok=ok))
    else:
        lines.append(t["closure_J"].format(ref=ref, c=_number(f.closure, spec=".2e", zero=None,
                                                              nonfinite="show"), n=n, ok=ok))
    lines.append(t["mean"].format(m=_g(f.M_y_cycle_mean, 8), ref=ref, d=_g(s.balancing_moment, 8)))
    if f.analysis is not None and f.motion == "true":
        grp = f.analysis.balancing_moment_groups
        lines.append(t["groups"].format(lo=_g(float(np.min(grp)), 6), hi=_g(float(np.max(grp)), 6)))
    return lines


def reaction_label(r, lang: str = "en") -> str:
    """A joint's reaction as the course writes it: R₀₁ (O) — the force of link 0 on link 1 at
    O (Russian, subscript digits where both links' names are digits); R_01 (O) in English; a
    point's trailing digits a subscript (B₁), as the figures letter it."""
    pair = link_pair(r.by, r.on)
    digits = pair.replace(",", "").isdigit()
    sub = pair.translate(_SUBSCRIPT) if lang == "ru" and digits else f"_{pair}"
    return f"R{sub} ({point_name(r.joint)})"


_SUBSCRIPT = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _moment_rows(results) -> list[list[str]]:
    """Rows of M_y at the report angles: φ, then kinetostatics, Zhukovsky, power balance (the
    power balance alone for a tabulated case)."""
    f = results.forces
    rows = []
    for a in results.at:
        i = results.at_index(a.phi_deg)
        if f.analysis is None:
            rows.append([_g(a.phi_deg, 6), _g(float(f.M_y_power[i]), 8)])
        else:
            rows.append([_g(a.phi_deg, 6), _g(float(f.analysis.balancing_moment[i]), 8),
                         _g(float(f.M_y_zhukovsky[i]), 8), _g(float(f.M_y_power[i]), 8),
                         _g(float(f.analysis.balancing_moment_groups[i]), 8)])
    return rows


# -- the rich summary -----------------------------------------------------------------------------

def print_forces(results, console, lang: str = "en") -> None:
    """The rich summary's section: the motion, the closure check, M_y three ways at the report
    angles, and at each the slider-crank quantities (or the tabulated case's one-line note)."""
    if results.forces is None:
        return
    from rich.table import Table

    t = T[lang]
    f = results.forces
    console.print(f"[bold]{t['title']}[/bold]")
    for line in summary_lines(results, lang):
        console.print(line, markup=False)
    tab = Table(title=t["moments"])
    tab.add_column(_h("φ", unit("deg", lang), lang), justify="right")
    heads = [t["power"]] if f.analysis is None else [t["kin"], t["zhuk"], t["power"], t["grp"]]
    for h in heads:
        tab.add_column(h, justify="right")
    for row in _moment_rows(results):
        tab.add_row(*row)
    console.print(tab)
    if f.analysis is None:
        return
    for a in results.at:
        i = results.at_index(a.phi_deg)
        if f.slider_crank:
            st = Table(title=t["sc"].format(a=_g(a.phi_deg, 6)))
            st.add_column(t["slider"], justify="right")
            for q in SLIDER_CRANK:
                st.add_column(_h(symbol(q, lang), unit_of(q, lang), lang), justify="right")
            for s, sc in f.slider_crank.items():
                st.add_row(s, *(_g(float(getattr(sc, q)[i]), 6) for q in SLIDER_CRANK))
            console.print(st)


def _h(sym: str, u: str, lang: str) -> str:
    """A column heading: "R [N]" in English, "R, Н" in Russian (the course's style, as
    nomenclature.heading)."""
    return f"{sym}, {u}" if lang == "ru" else f"{sym} [{u}]"


# -- the report's section (document blocks) -------------------------------------------------------

def _cells(row) -> tuple[str, ...]:
    return tuple(str(c).strip() for c in row)


def add_report_section(b, results, lang: str = "en") -> None:
    """The report's section as document blocks (render/blocks.py), added to the report's
    builder ``b`` (its ``add(block)`` and ``table(caption, header, rows)``, which numbers the
    tables): method, closure, the reactions and M_y at the standard positions, and at each
    report angle M_y three ways, every reaction and the slider-crank quantities."""
    if results.forces is None:
        return
    t = T[lang]
    f = results.forces
    fa = f.analysis
    b.add(Heading(2, t["title"].strip()))
    if fa is not None:
        b.add(Paragraph(t["intro"].rstrip()))
    b.add(Bullets(tuple(line.strip() for line in summary_lines(results, lang))))
    deg = _h("φ", unit("deg", lang), lang)
    My = _h(symbol("M_y", lang), unit_of("M_y", lang), lang)

    def table(caption, header, rows):
        b.table(caption, _cells(header), [_cells(r) for r in rows])

    # each position by its number (its dead centres are named under the record's first table
    # of the positions, §2), or a tabulated case's by its row's label
    cells, _ = position_cells(results.position_angles, lang)
    first = t["no"] if numbered(results.position_angles) else t["pos"]

    if fa is None:
        parts_of = [k for k in ("M_st", "M_dyn") if k in results.columns]    # seed 004's Мст, Мдин
        header = ([first, deg]
                  + [_h(symbol(k, lang), unit_of(k, lang), lang) for k in parts_of] + [My])
        body = []
        for pos, cell in zip(results.position_angles, cells):
            i = results.index_of(pos.phi)
            body.append([cell, _g(math.degrees(pos.phi), 6)]
                        + [_g(float(results.columns[k].values[i]), 6) for k in parts_of]
                        + [_g(float(f.M_y_power[i]), 6)])
        table(t["tab_positions"], header, body)
        table(t["moments"], [deg, t["power"]], _moment_rows(results))
        return
    keys = list(f.joints)
    header = [first, deg, My] + [reaction_label(f.joints[k], lang) for k in keys]
    body = []
    for pos, cell in zip(results.position_angles, cells):
        i = results.index_of(pos.phi)
        body.append([cell, _g(math.degrees(pos.phi), 6),
                     _g(float(fa.balancing_moment[i]), 6)]
                    + [_g(float(fa.joints[k].magnitude[i]), 5) for k in keys])
    table(t["positions"], header, body)
    table(t["moments"], [deg, t["kin"], t["zhuk"], t["power"], t["grp"]], _moment_rows(results))
    N = unit("N", lang)
    for a in results.at:
        i = results.at_index(a.phi_deg)
        b.add(Heading(3, t["at"].format(a=_g(a.phi_deg, 6)).strip()))
        # a component of 10⁻⁹ of its reaction is the round-off of a projection: 0
        rows = [[reaction_label(r, lang), point_name(r.joint), r.by, r.on,
                 *(_g(float(c[i]), 6, column_zero((r.magnitude[i],), 1e-13)) for c in (r.x, r.y)),
                 _g(float(r.magnitude[i]), 6), _g(math.degrees(float(r.angle[i])), 5)]
                for k, r in f.joints.items()]
        table(t["joints"].format(a=_g(a.phi_deg, 6)),
              [t["joint"], t["point"], t["by"], t["on"], _h("R_x", N, lang), _h("R_y", N, lang),
               _h("R", N, lang), _h(t["angle"], unit("deg", lang), lang)], rows)
        if f.slider_crank:
            head = [t["slider"]] + [_h(symbol(q, lang), unit_of(q, lang), lang) for q in SLIDER_CRANK]
            rows = [[s] + [_g(float(getattr(sc, q)[i]), 6) for q in SLIDER_CRANK]
                    for s, sc in f.slider_crank.items()]
            table(f"{t['sc'].format(a=_g(a.phi_deg, 6))}: "
                  + "; ".join(f"{symbol(q, lang)} — {name(q, lang)}" for q in SLIDER_CRANK),
                  head, rows)
        P, S = f.crank_pin_load[i], fa.shaking_force[i]
        b.add(Paragraph(t["frame" if results.cylinders else "frame_linkage"].format(
            P=_g(float(np.hypot(*P)), 6), T=_g(float(f.crank_pin_tangential[i]), 6),
            R=_g(float(f.crank_pin_radial[i]), 6), B=_g(float(fa.main_bearing_load.magnitude[i]), 6),
            S=_g(float(np.hypot(*S)), 6), M=_g(float(fa.shaking_moment[i]), 6)).rstrip()))
