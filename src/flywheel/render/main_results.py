"""The main results of a run, a row each — name, symbol, value, unit — as drawing sheet 1's
table and the записка's conclusion give them (ГОСТ 7.32-2017: the conclusion, «Заключение»,
states the results of the work): the constant moment of the cycle balance, ΔT_нб, J_I, J_М
(and J_М/i² on the flywheel's own shaft), the δ asked and the δ achieved (a given flywheel's
one), the disk flywheel's D, b, m. Values in SI; the renderers format them.
"""
from __future__ import annotations

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words

T = words("main_results", {
    "row_driving": "Driving moment (cycle mean)",
    "row_resistance": "Moment of the resistance (cycle mean)",
    "row_delta_T": "Largest change of kinetic energy",
    "row_J_I": "Required inertia of the first group",
    "row_J_I_given": "Moment of inertia of the first group",
    "row_J_M": "Moment of inertia of the flywheel",
    "row_J_M_shaft": "Moment of inertia of the flywheel on its shaft (i = {i})",
    "row_delta_target": "Coefficient of speed fluctuation, target",
    "row_delta_given": "Coefficient of speed fluctuation with the given flywheel",
    "row_delta_achieved": "Coefficient of speed fluctuation, achieved",
    "row_D": "Outer diameter of the flywheel disk",
    "row_b": "Width of the flywheel disk",
    "row_m": "Mass of the flywheel disk",
})


def main_results(results, lang: str, ratio_text=str) -> list[tuple[str, str, float, str]]:
    """(name, symbol, value [SI], unit) of each main result of ``results`` in ``lang``: M_Д (or
    M_С), ΔT_нб, J_I, J_М, J_М/i² where the flywheel turns faster than the crank (the disk is
    sized on its own shaft: the pump's J_М = 296,3 kg·m² beside a disk of 111 kg had read as a
    contradiction), the two δ (the target and the achieved: both «δ», told apart by their
    names; a given flywheel's one, which it achieves), the disk flywheel's D, b, m. A given
    flywheel's J_I is the first group's, J_М + (J_10 + J_ред), not a required one.
    ``ratio_text`` writes the speed ratio i in the name."""
    t = T["ru" if lang == "ru" else "en"]
    sc = results.scalars
    key = "driving_moment" if sc.balance == "driving" else "M_C"
    disk = sc.flywheel_disk
    rows = [(t["row_driving" if key == "driving_moment" else "row_resistance"],
             nm.symbol(key, lang), sc.balancing_moment, nm.unit_of(key, lang)),
            (t["row_delta_T"], nm.symbol("delta_T_max", lang), sc.delta_T_max,
             nm.unit_of("delta_T_max", lang)),
            (t["row_J_I_given" if sc.flywheel_given else "row_J_I"],
             nm.symbol("J_required", lang), sc.J_required, nm.unit_of("J_required", lang)),
            (t["row_J_M"], nm.symbol("J_flywheel", lang), sc.J_flywheel,
             nm.unit_of("J_flywheel", lang))]
    if sc.flywheel_speed_ratio != 1.0:      # the disk below is sized for the flywheel's shaft
        rows.append((t["row_J_M_shaft"].format(i=ratio_text(sc.flywheel_speed_ratio)),
                     nm.symbol("flywheel_J_on_its_shaft", lang), sc.flywheel_J_on_its_shaft,
                     nm.unit_of("flywheel_J_on_its_shaft", lang)))
    if sc.flywheel_given:           # its δ is the one it achieves: one row
        rows.append((t["row_delta_given"], "δ", sc.delta_achieved, "–"))
    else:
        rows += [(t["row_delta_target"], "δ", sc.delta, "–"),
                 (t["row_delta_achieved"], "δ", sc.delta_achieved, "–")]
    rows += [(t["row_D"], "D", disk.D, nm.unit_of("D", lang)),
             (t["row_b"], "b", disk.b, nm.unit_of("b", lang)),
             (t["row_m"], "m", disk.mass, nm.unit_of("mass", lang))]
    return rows
