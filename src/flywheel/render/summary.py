"""The rich summary on the terminal (`flywheel run`): the same numbers as summary.json."""
from __future__ import annotations

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
    },
}


def _g(x: float, digits: int = 6) -> str:
    return f"{0.0 if abs(x) < 1e-13 else x:.{digits}g}"


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
    tab.add_row(t["dT"], f"{_g(s['delta_T_I_max'])} J at {s['phi_delta_T_I_max_deg']:.2f}° / "
                         f"{_g(s['delta_T_I_min'])} J at {s['phi_delta_T_I_min_deg']:.2f}°", "")
    for key, unit in [("J_required", "kg·m²"), ("J_required_exact", "kg·m²"),
                      ("J_first_group", "kg·m²"), ("J_flywheel", "kg·m²"), ("delta", ""),
                      ("delta_achieved", ""), ("delta_achieved_exact", "")]:
        tab.add_row(t[key], _g(s[key]), unit)
    tab.add_row(t["omega_max"], f"{_g(s['omega_max'])} at {s['phi_omega_max_deg']:.2f}°", "rad/s")
    tab.add_row(t["omega_min"], f"{_g(s['omega_min'])} at {s['phi_omega_min_deg']:.2f}°", "rad/s")
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
    td = s.get("time_domain")
    if td:
        v = td["verification"]
        console.print(f"time integration (solve_ivp, {v['cycles']} cycles): repeats to "
                      f"{v['repeat_error']:.1e}, follows ω(φ) to {v['max_deviation']:.1e}, "
                      f"period {_g(v['period'])} s")
        st = td["startup"]
        if st.get("computed") is False:
            console.print(f"start-up: not computed ({st['reason']})", markup=False)
        elif st.get("stalled"):
            console.print(f"start-up: the motor stalls at φ = {st['stall_angle_deg']:.1f}°")
        else:
            console.print(f"start-up from rest: steady within δ/10 after {_g(st['time_to_steady'], 4)} s "
                          f"({st['cycles_to_steady']} cycles), mean speed {_g(st['omega_mean_steady'])} rad/s")
        rd = td["rundown"]
        console.print(f"run-down after the drive is cut: {_g(rd['time'], 4)} s, "
                      f"{rd['angle_deg'] / 360:.2f} revolutions" + ("" if rd["stopped"] else " (not stopped)"))
    for w in results.warnings:
        console.print(f"[yellow]{t['warning']}:[/yellow] {escape(w)}")
