"""report.md: the analysis written up the way a course project's explanatory note presents it
(input data, tables at the standard positions, the formulas used, the flywheel, the motion).

Text only: every number comes from Results; nothing is computed here but formatting.
"""
from __future__ import annotations

import math

T = {
    "en": {
        "title": "Dynamic analysis", "source": "Source", "input": "1. Input data",
        "kin": "2. Kinematics at the standard positions",
        "kin_note": "Velocity analogues v_q = dr/dφ [m/rad] of the points, ω_q = dθ/dφ of the links.",
        "red": "3. Reduction of masses and forces",
        "red_note": ("J_II = Σ m·v_qS² + J_S·ω_q² (the links' kinetic energy per ½ω²); the reduced "
                     "moment of a force is F·v_q, of a weight m·g⃗·v_qS."),
        "energy": "4. Works and kinetic energy",
        "sizing": "5. Flywheel", "motion": "6. True velocities and accelerations",
        "warn": "Warnings", "plots": "Plots", "pos": "position", "qty": "quantity",
        "val": "value", "unit": "unit", "point": "point", "link": "link",
        "time": "7. Motion in time",
        "time_note": ("The equation of motion J(φ)·φ̈ + ½·J′(φ)·φ̇² = M(φ, φ̇), J = J_I + J_II(φ), "
                      "integrated in time with scipy's solve_ivp; J, J′ and M are the tables of §3–4, "
                      "so the integration is independent of the energy solution of §5."),
        "verify": ("steady motion from the energy solution's state at φ = 0 over {n} cycles: ω repeats "
                   "from cycle to cycle to {rep} (relative), and follows ω(φ) of the energy equation to "
                   "{dev} (relative to ω_m)"),
        "period": "cycle time: {T} s from the integration, {Te} s from t(φ) = ∫dφ/ω",
        "motor": ("motor M_Д = M_п·(1 − ω/ω_x), reduced to the crank: M_п = {Mp} N·m, ω_x = {wx} rad/s; "
                  "the steady cycle-mean speed that the motor line balances against the loads "
                  "ω_s = {ws} rad/s; time constant τ = J/(M_п/ω_x) ≈ {tau} s"),
        "st_ok": ("start-up from rest: the cycle-mean speed is within δ/10 of ω_s after **{t} s** "
                  "({n} cycles); steady cycle-mean speed {w} rad/s"),
        "st_no": ("start-up from rest: the steady state was **not reached** within {n} cycles ({t} s); "
                  "the last cycle-mean speed is {w} rad/s"),
        "st_stall": "start-up from rest: the motor cannot start the machine — it stops at φ = {a}°",
        "st_none": "start-up: not computed ({reason})",
        "rd": "run-down after the drive is cut at φ = 0: {t} s, {rev} revolutions of the crank",
        "rd_not": " (not stopped within the integration limit)",
        "rd_never": ("run-down: none — the loads do no net work over a cycle, so without the drive "
                     "the machine keeps turning"),
    },
    "ru": {
        "title": "Динамический анализ", "source": "Источник", "input": "1. Исходные данные",
        "kin": "2. Кинематика в стандартных положениях",
        "kin_note": "Аналоги скоростей точек v_q = dr/dφ [м/рад], звеньев ω_q = dθ/dφ.",
        "red": "3. Приведение масс и сил",
        "red_note": ("J_II = Σ m·v_qS² + J_S·ω_q² (кинетическая энергия звеньев на ½ω²); "
                     "приведённый момент силы F·v_q, силы тяжести m·g⃗·v_qS."),
        "energy": "4. Работы и кинетическая энергия",
        "sizing": "5. Маховик", "motion": "6. Истинные скорости и ускорения",
        "warn": "Предупреждения", "plots": "Графики", "pos": "положение", "qty": "величина",
        "val": "значение", "unit": "ед.", "point": "точка", "link": "звено",
        "time": "7. Движение во времени",
        "time_note": ("Уравнение движения J(φ)·φ̈ + ½·J′(φ)·φ̇² = M(φ, φ̇), J = J_I + J_II(φ), "
                      "проинтегрировано во времени (solve_ivp из scipy); J, J′ и M взяты из таблиц "
                      "§3–4, поэтому интегрирование не зависит от энергетического решения §5."),
        "verify": ("установившееся движение из состояния энергетического решения при φ = 0, циклов: "
                   "{n}: ω повторяется от цикла к циклу с точностью {rep} (относительно) и совпадает "
                   "с ω(φ) уравнения энергии до {dev} (относительно ω_ср)"),
        "period": "время цикла: {T} с по интегрированию, {Te} с по t(φ) = ∫dφ/ω",
        "motor": ("двигатель M_Д = M_п·(1 − ω/ω_x), приведённый к кривошипу: M_п = {Mp} Н·м, "
                  "ω_x = {wx} рад/с; средняя за цикл скорость, при которой характеристика "
                  "уравновешивает нагрузку, ω_s = {ws} рад/с; постоянная времени τ = J/(M_п/ω_x) ≈ "
                  "{tau} с"),
        "st_ok": ("разгон из состояния покоя: средняя за цикл скорость отличается от ω_s меньше "
                  "чем на δ/10 через **{t} с** (циклов: {n}); установившаяся средняя скорость {w} рад/с"),
        "st_no": ("разгон из состояния покоя: установившийся режим **не достигнут** за {n} циклов "
                  "({t} с); средняя скорость последнего цикла {w} рад/с"),
        "st_stall": "разгон из состояния покоя: двигатель не может разогнать машину — остановка при φ = {a}°",
        "st_none": "разгон: не рассчитан ({reason})",
        "st_none_motor": ("в задании нет раздела [motor]: при постоянном движущем моменте работа за "
                          "цикл равна нулю при любой скорости, установившегося режима разгона нет"),
        "rd": "выбег после отключения привода при φ = 0: {t} с, оборотов кривошипа: {rev}",
        "rd_not": " (не остановился в пределах интегрирования)",
        "rd_never": ("выбега нет: работа нагрузок за цикл равна нулю, без привода машина продолжает "
                     "вращаться"),
    },
}


def _g(x, digits: int = 5) -> str:
    if x is None:
        return "—"
    return f"{0.0 if abs(x) < 1e-13 else x:.{digits}g}"


def _table(header: list[str], rows: list[list[str]]) -> str:
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out) + "\n"


def _time_lines(td: dict, s: dict, t: dict) -> list[str]:
    """The bullet lines of the "Motion in time" section (--transients)."""
    v, st, rd = td["verification"], td["startup"], td["rundown"]
    lines = [
        "- " + t["verify"].format(n=v["cycles"], rep=f"{v['repeat_error']:.1e}", dev=f"{v['max_deviation']:.1e}"),
        "- " + t["period"].format(T=_g(v["period"], 6), Te=_g(s["cycle_time"], 6)),
    ]
    if st.get("computed") is False:
        reason = st["reason"]
        if "st_none_motor" in t and reason.startswith("no [motor]"):
            reason = t["st_none_motor"]
        return lines + ["- " + t["st_none"].format(reason=reason), _rundown_line(rd, t)]
    if "starting_torque" in st:
        lines.append("- " + t["motor"].format(Mp=_g(st["starting_torque"], 5), wx=_g(st["no_load_speed"], 5),
                                              ws=_g(st.get("omega_final_predicted"), 6),
                                              tau=_g(st.get("time_constant"), 3)))
    if st.get("stalled"):
        lines.append("- " + t["st_stall"].format(a=f"{st['stall_angle_deg']:.1f}"))
    elif st.get("converged", True) and st.get("time_to_steady") is not None:
        lines.append("- " + t["st_ok"].format(t=_g(st["time_to_steady"], 4), n=st["cycles_to_steady"],
                                              w=_g(st["omega_mean_steady"], 6)))
    else:
        lines.append("- " + t["st_no"].format(n=st.get("cycles_run"), t=_g(st.get("time_run"), 4),
                                              w=_g(st.get("omega_mean_last"), 6)))
        if st.get("warning"):
            lines.append(f"- **{st['warning']}**")
    return lines + [_rundown_line(rd, t)]


def _rundown_line(rd: dict, t: dict) -> str:
    if rd.get("reason"):
        return "- " + t["rd_never"]
    return "- " + t["rd"].format(t=_g(rd["time"], 4), rev=f"{rd['angle_deg'] / 360:.2f}") + (
        "" if rd["stopped"] else t["rd_not"])


def report_markdown(results, lang: str = "en", plots: list[str] | None = None) -> str:
    """The report as Markdown; ``plots``: PNG file names under plots/ to embed."""
    t = T[lang]
    s = results.scalars
    cols = results.columns
    parts = [f"# {t['title']}: {results.title}\n"]
    if results.source:
        parts.append(f"{t['source']}: {results.source}\n")

    rows = [[t["qty"], t["val"], t["unit"]]]
    inputs = [
        ("ω_m = 2π·n1", s["omega_mean"], "rad/s"), ("n1", s["omega_mean"] / (2 * math.pi), "rev/s"),
        ("δ", s["delta"], "–"), ("l1", s.get("crank_length"), "m"),
        ("J_10 + J_ред (first group)", s["J_first_group"], "kg·m²"),
    ]
    parts.append(f"\n## {t['input']}\n\n" + _table(rows[0], [[a, _g(b, 6), c] for a, b, c in inputs]))

    idx = [(label, results.index_of(phi)) for label, phi in results.position_angles]
    vq = [k for k in cols if k.startswith("vq_") and not k.startswith(("vqx_", "vqy_"))]
    wq = [k for k in cols if k.startswith("omega_q_")]
    if vq or wq:
        header = [t["pos"], "φ [deg]"] + [f"v_q{k[3:]}" for k in vq] + [f"ω_q{k[8:]}" for k in wq]
        body = [[lab, _g(cols["phi_deg"].values[i], 6)] + [_g(cols[k].values[i], 4) for k in vq + wq]
                for lab, i in idx]
        parts.append(f"\n## {t['kin']}\n\n{t['kin_note']}\n\n" + _table(header, body))

    mk = [k for k in cols if k.startswith("M ")]
    header = [t["pos"], "φ [deg]", "J_II [kg·m²]", "dJ_II/dφ"] + [f"{k[2:]} [N·m]" for k in mk] + ["M_Σ [N·m]"]
    body = [[lab, _g(cols["phi_deg"].values[i], 6), _g(cols["J_II"].values[i], 4), _g(cols["dJ_II"].values[i], 4)]
            + [_g(cols[k].values[i], 5) for k in mk] + [_g(cols["M_sum"].values[i], 5)] for lab, i in idx]
    parts.append(f"\n## {t['red']}\n\n{t['red_note']}\n\n" + _table(header, body))

    header = [t["pos"], "φ [deg]", "A_D [J]", "A_C [J]", "A [J]", "T_II [J]", "ΔT_I [J]", "ω [rad/s]", "ε [rad/s²]"]
    body = [[lab, _g(cols["phi_deg"].values[i], 6)] + [_g(cols[k].values[i], 6) for k in
                                                        ("A_D", "A_C", "A", "T_II", "dT_I", "omega", "epsilon")]
            for lab, i in idx]
    energy_lines = [
        f"- A_C = ∮ M_C dφ = {_g(s['cycle_work_resistance'], 6)} J; "
        f"M_D = −A_C/{s['cycle_deg'] // 180}π = {_g(s['driving_moment'], 6)} N·m (the cycle balance)",
        "- ΔT_I(φ) = A(φ) − (T_II(φ) − T_II(0)), T_II = J_II·ω_m²/2",
        f"- ΔT_I max = {_g(s['delta_T_I_max'], 6)} J at {s['phi_delta_T_I_max_deg']:.2f}°, "
        f"min = {_g(s['delta_T_I_min'], 6)} J at {s['phi_delta_T_I_min_deg']:.2f}° (global extremes); "
        f"ΔT_нб = {_g(s['delta_T_max'], 6)} J",
    ]
    parts.append(f"\n## {t['energy']}\n\n" + "\n".join(energy_lines) + "\n\n" + _table(header, body))

    d, r = s["flywheel_disk"], s["flywheel_rim"]
    sizing_lines = [
        f"- Merzalov: J_I = ΔT_нб/(δ·ω_m²) = {_g(s['J_required'], 6)} kg·m², "
        f"δ achieved {_g(s['delta_achieved'], 6)}",
        f"- exact (energy–mass diagram): J_I = {_g(s['J_required_exact'], 6)} kg·m², "
        f"δ achieved {_g(s['delta_achieved_exact'], 6)}",
        f"- flywheel J_M = J_I − J_first = {_g(s['J_flywheel'], 6)} kg·m²"
        + (f"; on a shaft {s['flywheel_speed_ratio']:g} times faster: {_g(s['flywheel_J_on_its_shaft'], 6)} kg·m²"
           if s.get("flywheel_speed_ratio", 1) != 1 else ""),
        f"- disk ({s.get('flywheel_material', 'steel')}): D = {_g(d['D'], 4)} m, b = {_g(d['b'], 4)} m, "
        f"m = {_g(d['mass'], 5)} kg, rim speed {_g(d.get('rim_speed'), 4)} m/s",
        f"- rim: D = {_g(r['D'], 4)} m, D1 = {_g(r['D_inner'], 4)} m, b = {_g(r['b'], 4)} m, "
        f"m = {_g(r['mass'], 5)} kg, rim speed {_g(r.get('rim_speed'), 4)} m/s "
        f"(limit {_g(s.get('flywheel_rim_speed_limit'), 3)} m/s)",
        f"- ω_max = {_g(s['omega_max'], 6)} rad/s at {s['phi_omega_max_deg']:.2f}°, "
        f"ω_min = {_g(s['omega_min'], 6)} rad/s at {s['phi_omega_min_deg']:.2f}°; cycle time {_g(s['cycle_time'], 6)} s",
    ]
    parts.append(f"\n## {t['sizing']}\n\n" + "\n".join(sizing_lines) + "\n")

    for a in results.at:
        parts.append(f"\n## {t['motion']}: φ = {_g(a['phi_deg'], 6)}°\n\n"
                     f"ω = {_g(a['omega'], 6)} rad/s, ε = {_g(a['epsilon'], 6)} rad/s²; "
                     "v = v_q·ω, a = |a_q·ω² + v_q·ε|, ω_i = ω_q·ω, ε_i = ε_q·ω² + ω_q·ε\n\n")
        body = [[n, _g(p.get("v_q"), 5), _g(p.get("v"), 5), _g(p.get("a_q"), 5), _g(p.get("a"), 5)]
                for n, p in a["points"].items()]
        parts.append(_table([t["point"], "v_q [m/rad]", "v [m/s]", "a_q [m/rad²]", "a [m/s²]"], body))
        body = [[n, _g(lk.get("omega_q"), 5), _g(lk.get("omega"), 5), _g(lk.get("epsilon_q"), 5),
                 _g(lk.get("epsilon"), 5)] for n, lk in a["links"].items()]
        parts.append("\n" + _table([t["link"], "ω_q", "ω [rad/s]", "ε_q [1/rad]", "ε [rad/s²]"], body))

    td = s.get("time_domain")
    if td:
        parts.append(f"\n## {t['time']}\n\n{t['time_note']}\n\n" + "\n".join(_time_lines(td, s, t)) + "\n")

    if results.warnings:
        parts.append(f"\n## {t['warn']}\n\n" + "\n".join(f"- {w}" for w in results.warnings) + "\n")
    if plots:
        parts.append(f"\n## {t['plots']}\n\n" + "\n".join(f"![{p}](plots/{p})" for p in plots) + "\n")
    return "".join(parts)
