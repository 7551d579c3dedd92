"""The rich summary on the terminal (`flywheel run`): the same numbers as summary.json."""
from __future__ import annotations

from flywheel.render.forces import print_forces

L10N = {
    "en": {
        "crank_length": "crank length l1", "omega_mean": "mean angular velocity ω_m",
        "cycle_work_resistance": "work of the resistance over a cycle A_C",
        "driving_moment": "driving moment M_D (cycle mean)",
        "delta_T_max": "largest energy fluctuation ΔT_нб", "J_II_mean": "J_II, cycle mean",
        "J_required": "required inertia of the first group J_I (Merzalov)",
        "J_required_exact": "required J_I, exact (energy–mass diagram)",
        "J_first_group": "already on the crank shaft", "J_flywheel": "flywheel J_M = J_I − first group",
        "delta": "target δ", "delta_achieved": "δ achieved with J_I (Merzalov)",
        "delta_achieved_exact": "δ achieved with the exact J_I",
        "omega_max": "ω_max", "omega_min": "ω_min",
        "dT": "ΔT_I max / min", "disk": "flywheel as a solid disk", "rim": "flywheel as a rim",
        "title_main": "Results", "title_at": "At φ = {phi}°: ω = {w} rad/s, ε = {e} rad/s²",
        "point": "point", "link": "link", "quantity": "quantity", "value": "value", "unit": "unit",
        "warning": "warning",
        "fw_shaft": "flywheel shaft: speed ratio i, J_M/i²", "fw_material": "flywheel material",
        "fw_rim_share": "rim share of J_M (hub and spokes the rest)",
        "at": "at", "steel": "steel", "cast-iron": "cast iron", "limit": "rim speed ≤",
        "td_verify": "time integration (solve_ivp, {n} cycles): repeats to {rep}, follows ω(φ) to "
                     "{dev}, period {T} s",
        "st_none": "start-up: not computed ({reason})",
        "st_stall": "start-up: the motor stalls at φ = {a}°",
        "st_ok": "start-up from rest: steady within δ/10 after {t} s ({n} cycles), mean speed "
                 "{w} rad/s",
        "st_no": "start-up from rest: steady state NOT reached within {n} cycles ({t} s); last "
                 "cycle-mean speed {w} rad/s, the motor line predicts {wp} rad/s",
        "rd": "run-down after the drive is cut: {t} s, {rev} revolutions",
        "rd_not": " (not stopped)",
        "rd_never": "run-down: none — the loads do no net work over a cycle, so without the drive "
                    "the machine keeps turning",
    },
    "ru": {
        "crank_length": "длина кривошипа l1", "omega_mean": "средняя угловая скорость ω_ср",
        "cycle_work_resistance": "работа сил сопротивления за цикл A_C",
        "driving_moment": "приведённый движущий момент M_PRD",
        "delta_T_max": "наибольшее изменение кин. энергии ΔT_нб", "J_II_mean": "J_II, среднее за цикл",
        "J_required": "необходимый момент инерции I группы J_PRI (Мерцалов)",
        "J_required_exact": "необходимый J_PRI, точно (диаграмма Виттенбауэра)",
        "J_first_group": "уже на валу кривошипа (J_10 + J_ред)",
        "J_flywheel": "момент инерции маховика J_доп",
        "delta": "заданный δ", "delta_achieved": "достигнутый δ (Мерцалов)",
        "delta_achieved_exact": "достигнутый δ (точный J)",
        "omega_max": "ω_max", "omega_min": "ω_min",
        "dT": "ΔT_I max / min", "disk": "маховик — сплошной диск", "rim": "маховик — обод",
        "title_main": "Результаты", "title_at": "При φ = {phi}°: ω = {w} рад/с, ε = {e} рад/с²",
        "point": "точка", "link": "звено", "quantity": "величина", "value": "значение",
        "unit": "ед.", "warning": "предупреждение",
        "fw_shaft": "вал маховика: передаточное отношение i, J_M/i²", "fw_material": "материал маховика",
        "fw_rim_share": "доля J_M на ободе (остальное — ступица и спицы)",
        "at": "при", "steel": "сталь", "cast-iron": "чугун", "limit": "окружная скорость ≤",
        "td_verify": "интегрирование во времени (solve_ivp, циклов: {n}): движение повторяется с "
                     "точностью {rep}, совпадает с ω(φ) до {dev}, период {T} с",
        "st_none": "разгон: не рассчитан ({reason})",
        "st_none_motor": "нет раздела [motor]: при постоянном движущем моменте работа за цикл равна "
                         "нулю при любой скорости, установившегося режима разгона нет",
        "st_stall": "разгон: двигатель останавливается при φ = {a}°",
        "st_ok": "разгон из состояния покоя: установившийся режим (в пределах δ/10) через {t} с "
                 "(циклов: {n}), средняя скорость {w} рад/с",
        "st_no": "разгон из состояния покоя: установившийся режим НЕ достигнут за {n} циклов ({t} с); "
                 "средняя скорость последнего цикла {w} рад/с, по характеристике двигателя {wp} рад/с",
        "rd": "выбег после отключения привода: {t} с, оборотов: {rev}",
        "rd_not": " (не остановился)",
        "rd_never": "выбега нет: работа нагрузок за цикл равна нулю, без привода машина "
                    "продолжает вращаться",
    },
}


def _g(x: float, digits: int = 6) -> str:
    return f"{0.0 if abs(x) < 1e-13 else x:.{digits}g}"


def time_domain_lines(td: dict | None, lang: str = "en") -> list[str]:
    """The --transients results as lines of text (verification, start-up, run-down).

    >>> td = {"verification": {"cycles": 3, "repeat_error": 1e-9, "max_deviation": 2e-9, "period": 0.1},
    ...       "startup": {"stalled": False, "converged": False, "cycles_run": 2000, "time_run": 150.0,
    ...                   "omega_mean_last": 60.0, "omega_final_predicted": 62.8},
    ...       "rundown": {"time": 2.5, "angle_deg": 720.0, "stopped": True}}
    >>> print("\\n".join(time_domain_lines(td, "ru")))  # doctest: +NORMALIZE_WHITESPACE
    интегрирование во времени (solve_ivp, циклов: 3): движение повторяется с точностью 1.0e-09,
    совпадает с ω(φ) до 2.0e-09, период 0.1 с
    разгон из состояния покоя: установившийся режим НЕ достигнут за 2000 циклов (150 с); средняя
    скорость последнего цикла 60 рад/с, по характеристике двигателя 62.8 рад/с
    выбег после отключения привода: 2.5 с, оборотов: 2.00
    """
    if not td:
        return []
    t = L10N[lang]
    v = td["verification"]
    out = [t["td_verify"].format(n=v["cycles"], rep=f"{v['repeat_error']:.1e}",
                                 dev=f"{v['max_deviation']:.1e}", T=_g(v["period"]))]
    st = td["startup"]
    if st.get("computed") is False:
        reason = st["reason"]
        if lang == "ru" and reason.startswith("no [motor]"):
            reason = t["st_none_motor"]
        out.append(t["st_none"].format(reason=reason))
    elif st.get("stalled"):
        out.append(t["st_stall"].format(a=f"{st['stall_angle_deg']:.1f}"))
    elif st.get("converged", True) and st.get("time_to_steady") is not None:
        out.append(t["st_ok"].format(t=_g(st["time_to_steady"], 4), n=st["cycles_to_steady"],
                                     w=_g(st["omega_mean_steady"])))
    else:
        wp = st.get("omega_final_predicted")
        out.append(t["st_no"].format(n=st.get("cycles_run"), t=_g(st.get("time_run", 0.0), 4),
                                     w=_g(st.get("omega_mean_last", 0.0)),
                                     wp=_g(wp) if wp is not None else "—"))
    rd = td["rundown"]
    if rd.get("reason"):
        out.append(t["rd_never"])
        return out
    out.append(t["rd"].format(t=_g(rd["time"], 4), rev=f"{rd['angle_deg'] / 360:.2f}")
               + ("" if rd["stopped"] else t["rd_not"]))
    return out


def print_summary(results, console=None, lang: str = "en") -> None:
    """Print the headline results, the flywheel, and the motion at each report angle."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    t = L10N[lang]
    console = console or Console()
    s = results.scalars
    console.print(f"[bold]{results.title}[/bold]" + (f"  ({results.source})" if results.source else ""))
    tab = Table(title=t["title_main"])
    tab.add_column(t["quantity"])
    tab.add_column(t["value"], justify="right")
    tab.add_column(t["unit"])
    rows = [
        ("crank_length", "m"), ("omega_mean", "rad/s"), ("cycle_work_resistance", "J"),
        ("driving_moment", "N·m"), ("J_II_mean", "kg·m²"), ("delta_T_max", "J"),
    ]
    for key, unit in rows:
        tab.add_row(t[key], _g(s[key]), unit)
    tab.add_row(t["dT"], f"{_g(s['delta_T_I_max'])} {t['at']} {s['phi_delta_T_I_max_deg']:.2f}° / "
                         f"{_g(s['delta_T_I_min'])} {t['at']} {s['phi_delta_T_I_min_deg']:.2f}°", "J")
    for key, unit in [("J_required", "kg·m²"), ("J_required_exact", "kg·m²"),
                      ("J_first_group", "kg·m²"), ("J_flywheel", "kg·m²"), ("delta", ""),
                      ("delta_achieved", ""), ("delta_achieved_exact", "")]:
        tab.add_row(t[key], _g(s[key]), unit)
    tab.add_row(t["omega_max"], f"{_g(s['omega_max'])} {t['at']} {s['phi_omega_max_deg']:.2f}°", "rad/s")
    tab.add_row(t["omega_min"], f"{_g(s['omega_min'])} {t['at']} {s['phi_omega_min_deg']:.2f}°", "rad/s")
    if "flywheel_speed_ratio" in s:
        tab.add_row(t["fw_shaft"], f"i = {_g(s['flywheel_speed_ratio'])}, {_g(s['flywheel_J_on_its_shaft'])}",
                    "–, kg·m²")
    if "flywheel_material" in s:
        mat = t.get(s["flywheel_material"], s["flywheel_material"])
        lim = s.get("flywheel_rim_speed_limit")
        tab.add_row(t["fw_material"], f"{mat}, ρ = {_g(s['flywheel_material_density'], 5)}"
                    + (f"; {t['limit']} {_g(lim, 3)}" if lim else ""), "kg/m³" + (", m/s" if lim else ""))
    share = results.sizing.rim_share
    if share < 1 - 1e-9:
        tab.add_row(t["fw_rim_share"], _g(share, 4), "")
    d, r = s["flywheel_disk"], s["flywheel_rim"]
    tab.add_row(t["disk"], f"D = {_g(d['D'], 4)}, b = {_g(d['b'], 4)}, m = {_g(d['mass'], 5)}", "m, m, kg")
    tab.add_row(t["rim"], f"D = {_g(r['D'], 4)}, D1 = {_g(r['D_inner'], 4)}, b = {_g(r['b'], 4)}, "
                          f"m = {_g(r['mass'], 5)}", "m, m, m, kg")
    console.print(tab)
    for a in results.at:
        pt = Table(title=t["title_at"].format(phi=_g(a["phi_deg"]), w=_g(a["omega"]), e=_g(a["epsilon"])))
        for col in (t["point"], "x [m]", "y [m]", "v_q [m]", "a_q [m]", "v [m/s]", "a [m/s²]"):
            pt.add_column(col, justify="right")
        for name, p in a["points"].items():
            pt.add_row(name, *(_g(p[k], 5) if k in p else "—" for k in ("x", "y", "v_q", "a_q", "v", "a")))
        console.print(pt)
        lt = Table()
        for col in (t["link"], "ω_q", "ε_q [1/rad]", "ω [rad/s]", "ε [rad/s²]"):
            lt.add_column(col, justify="right")
        for name, lk in a["links"].items():
            lt.add_row(name, *(_g(lk[k], 5) if k in lk else "—" for k in ("omega_q", "epsilon_q", "omega", "epsilon")))
        console.print(lt)
    print_forces(results, console, lang)            # the force analysis (render/forces.py)
    for line in time_domain_lines(s.get("time_domain"), lang):
        console.print(line, markup=False)
    for w in results.warnings:
        console.print(f"[yellow]{t['warning']}:[/yellow] {escape(w)}")
