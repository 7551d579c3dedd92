"""report.md: the analysis written up the way a course project's explanatory note presents it
(input data, tables at the standard positions, the formulas used, the flywheel, the motion).

Text only: every number comes from Results; nothing is computed here but formatting.
"""
from __future__ import annotations

import math

from flywheel.render import nomenclature as nm
from flywheel.render.forces import report_section

# Section titles, table words and sentence templates only: every quantity's symbol, name and
# unit comes from the nomenclature (render/nomenclature.py), filled in where the templates
# say {…}.
T = {
    "en": {
        "title": "Dynamic analysis", "source": "Source", "input": "1. Input data",
        "kin": "2. Kinematics at the standard positions",
        "kin_note": "Velocity analogues {vq} = dr/dφ [{u}] of the points, {wq} = dθ/dφ of the links.",
        "red": "3. Reduction of masses and forces",
        "red_note": ("J_II = Σ m·v_qS² + J_S·ω_q² (the links' kinetic energy per ½ω²); the reduced "
                     "moment of a force is F·v_q, of a weight m·g⃗·v_qS."),
        "energy": "4. Works and kinetic energy",
        "sizing": "5. Flywheel", "motion": "6. True velocities and accelerations",
        "warn": "Warnings", "plots": "Plots", "pos": "position", "qty": "quantity",
        "val": "value", "unit": "unit", "point": "point", "link": "link",
        "first_group": "first group",
        "balance": "- {A_C} = ∮ {M_C} dφ = {A} {uJ}; {M_D} = −{A_C}/2π = {M} {uM} (the cycle balance)",
        "extremes": ("- {dT} max = {vmax} {uJ} at {amax}°, min = {vmin} {uJ} at {amin}° (global "
                     "extremes); {span} = {v} {uJ}"),
        "merzalov": "- Merzalov: {J} = {span}/(δ·{w}²) = {v} {uI}, δ achieved {d}",
        "exact": "- exact (energy–mass diagram): {J} = {v} {uI}, δ achieved {d}",
        "flywheel": "- flywheel {JM} = {J} − ({J1}) = {v} {uI}",
        "shaft": "; on a shaft {i:g} times faster: {v} {uI}",
        "disk": "- disk ({mat}): {dims}, {speed} {v} {u}",
        "rim": "- rim: {dims}, {speed} {v} {u} (limit {lim} {u})",
        "omega_extremes": "- {wmax} = {vmax} {uw} at {amax}°, {wmin} = {vmin} {uw} at {amin}°; {T} {v} {uT}",
        "at": "ω = {w} {uw}, ε = {e} {ue}",
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
        "kin_note": "Аналоги скоростей точек {vq} = dr/dφ [{u}], звеньев {wq} = dθ/dφ.",
        "red": "3. Приведение масс и сил",
        "red_note": ("J_II = Σ m·v_qS² + J_S·ω_q² (кинетическая энергия звеньев на ½ω²); "
                     "приведённый момент силы F·v_q, силы тяжести m·g⃗·v_qS."),
        "energy": "4. Работы и кинетическая энергия",
        "sizing": "5. Маховик", "motion": "6. Истинные скорости и ускорения",
        "warn": "Предупреждения", "plots": "Графики", "pos": "положение", "qty": "величина",
        "val": "значение", "unit": "ед.", "point": "точка", "link": "звено",
        "first_group": "первая группа",
        "balance": "- {A_C} = ∮ {M_C} dφ = {A} {uJ}; {M_D} = −{A_C}/2π = {M} {uM} (из условия цикла)",
        "extremes": ("- {dT} max = {vmax} {uJ} при {amax}°, min = {vmin} {uJ} при {amin}° "
                     "(глобальные экстремумы); {span} = {v} {uJ}"),
        "merzalov": "- по Мерцалову: {J} = {span}/(δ·{w}²) = {v} {uI}, достигнутый δ {d}",
        "exact": "- точно (диаграмма Виттенбауэра): {J} = {v} {uI}, достигнутый δ {d}",
        "flywheel": "- маховик {JM} = {J} − ({J1}) = {v} {uI}",
        "shaft": "; на валу, вращающемся в {i:g} раз быстрее: {v} {uI}",
        "disk": "- диск ({mat}): {dims}, {speed} {v} {u}",
        "rim": "- обод: {dims}, {speed} {v} {u} (допускаемая {lim} {u})",
        "omega_extremes": "- {wmax} = {vmax} {uw} при {amax}°, {wmin} = {vmin} {uw} при {amin}°; {T} {v} {uT}",
        "at": "ω = {w} {uw}, ε = {e} {ue}",
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

    def sym(key: str) -> str:
        return nm.symbol(key, lang)

    def u(key: str) -> str:
        return nm.unit_of(key, lang)

    def h(key: str, **kw) -> str:
        return nm.heading(key, lang, **kw)

    parts = [f"# {t['title']}: {results.title}\n"]
    if results.source:
        parts.append(f"{t['source']}: {results.source}\n")

    rows = [[t["qty"], t["val"], t["unit"]]]
    inputs = [
        (f"{sym('omega_mean')} = 2π·{sym('crank_speed')}", s["omega_mean"], u("omega_mean")),
        (sym("crank_speed"), s["omega_mean"] / (2 * math.pi), u("crank_speed")),
        (sym("delta"), s["delta"], u("delta")), (sym("crank_length"), s.get("crank_length"), u("crank_length")),
        (f"{sym('J_first_group')} ({t['first_group']})", s["J_first_group"], u("J_first_group")),
    ]
    parts.append(f"\n## {t['input']}\n\n" + _table(rows[0], [[a, _g(b, 6), c] for a, b, c in inputs]))

    idx = [(nm.position_label(label, lang), results.index_of(phi))
           for label, phi in results.position_angles]
    vq = [k for k in cols if k.startswith("vq_") and not k.startswith(("vqx_", "vqy_"))]
    wq = [k for k in cols if k.startswith("omega_q_")]
    if vq or wq:
        header = [t["pos"], h("phi_deg")] + [f"{sym(k)}{nm.member(k, lang)}" for k in vq + wq]
        body = [[lab, _g(cols["phi_deg"].values[i], 6)] + [_g(cols[k].values[i], 4) for k in vq + wq]
                for lab, i in idx]
        note = t["kin_note"].format(vq=sym("v_q"), u=u("v_q"), wq=sym("omega_q"))
        parts.append(f"\n## {t['kin']}\n\n{note}\n\n" + _table(header, body))

    mk = [k for k in cols if k.startswith("M ")]
    header = ([t["pos"], h("phi_deg"), h("J_II"), h("dJ_II")]
              + [h(k, label=nm.member(k, lang)) for k in mk] + [h("M_sum")])
    body = [[lab, _g(cols["phi_deg"].values[i], 6), _g(cols["J_II"].values[i], 4), _g(cols["dJ_II"].values[i], 4)]
            + [_g(cols[k].values[i], 5) for k in mk] + [_g(cols["M_sum"].values[i], 5)] for lab, i in idx]
    parts.append(f"\n## {t['red']}\n\n{t['red_note']}\n\n" + _table(header, body))

    energy = ("A_D", "A_C", "A", "T_II", "dT_I", "omega", "epsilon")
    header = [t["pos"], h("phi_deg")] + [h(k) for k in energy]
    body = [[lab, _g(cols["phi_deg"].values[i], 6)] + [_g(cols[k].values[i], 6) for k in energy]
            for lab, i in idx]
    energy_lines = [
        t["balance"].format(A_C=sym("cycle_work_resistance"), M_C=sym("M_C"), M_D=sym("driving_moment"),
                            A=_g(s["cycle_work_resistance"], 6), uJ=u("cycle_work_resistance"),
                            M=_g(s["driving_moment"], 6), uM=u("driving_moment")),
        f"- {sym('dT_I')}(φ) = A(φ) − ({sym('T_II')}(φ) − {sym('T_II')}(0)), "
        f"{sym('T_II')} = {sym('J_II')}·{sym('omega_mean')}²/2",
        t["extremes"].format(dT=sym("dT_I"), vmax=_g(s["delta_T_I_max"], 6), amax=f"{s['phi_delta_T_I_max_deg']:.2f}",
                             vmin=_g(s["delta_T_I_min"], 6), amin=f"{s['phi_delta_T_I_min_deg']:.2f}",
                             span=sym("delta_T_max"), v=_g(s["delta_T_max"], 6), uJ=u("delta_T_max")),
    ]
    parts.append(f"\n## {t['energy']}\n\n" + "\n".join(energy_lines) + "\n\n" + _table(header, body))

    def dims(d: dict, keys: tuple[str, ...], digits: tuple[int, ...]) -> str:
        return ", ".join(f"{sym(k)} = {_g(d[k], n)} {u(k)}" for k, n in zip(keys, digits))

    d, r = s["flywheel_disk"], s["flywheel_rim"]
    uI = u("J_required")
    fw = t["flywheel"].format(JM=sym("J_flywheel"), J=sym("J_required"), J1=sym("J_first_group"),
                              v=_g(s["J_flywheel"], 6), uI=uI)
    if s.get("flywheel_speed_ratio", 1) != 1:
        fw += t["shaft"].format(i=s["flywheel_speed_ratio"], v=_g(s["flywheel_J_on_its_shaft"], 6), uI=uI)
    sizing_lines = [
        t["merzalov"].format(J=sym("J_required"), span=sym("delta_T_max"), w=sym("omega_mean"),
                             v=_g(s["J_required"], 6), uI=uI, d=_g(s["delta_achieved"], 6)),
        t["exact"].format(J=sym("J_required_exact"), v=_g(s["J_required_exact"], 6), uI=uI,
                          d=_g(s["delta_achieved_exact"], 6)),
        fw,
        t["disk"].format(mat=nm.material(s.get("flywheel_material", "steel"), lang),
                         dims=dims(d, ("D", "b", "mass"), (4, 4, 5)), speed=nm.name("rim_speed", lang),
                         v=_g(d.get("rim_speed"), 4), u=u("rim_speed")),
        t["rim"].format(dims=dims(r, ("D", "D_inner", "b", "mass"), (4, 4, 4, 5)),
                        speed=nm.name("rim_speed", lang), v=_g(r.get("rim_speed"), 4), u=u("rim_speed"),
                        lim=_g(s.get("flywheel_rim_speed_limit"), 3)),
        t["omega_extremes"].format(wmax=sym("omega_max"), vmax=_g(s["omega_max"], 6),
                                   amax=f"{s['phi_omega_max_deg']:.2f}", wmin=sym("omega_min"),
                                   vmin=_g(s["omega_min"], 6), amin=f"{s['phi_omega_min_deg']:.2f}",
                                   uw=u("omega_max"), T=nm.name("cycle_time", lang),
                                   v=_g(s["cycle_time"], 6), uT=u("cycle_time")),
    ]
    parts.append(f"\n## {t['sizing']}\n\n" + "\n".join(sizing_lines) + "\n")

    point_keys, link_keys = ("v_q", "v", "a_q", "a"), ("omega_q", "omega", "epsilon_q", "epsilon")
    for a in results.at:
        motion = t["at"].format(w=_g(a["omega"], 6), uw=u("omega"), e=_g(a["epsilon"], 6), ue=u("epsilon"))
        parts.append(f"\n## {t['motion']}: φ = {_g(a['phi_deg'], 6)}°\n\n{motion}; "
                     "v = v_q·ω, a = |a_q·ω² + v_q·ε|, ω_i = ω_q·ω, ε_i = ε_q·ω² + ω_q·ε\n\n")
        body = [[n] + [_g(p.get(k), 5) for k in point_keys] for n, p in a["points"].items()]
        parts.append(_table([t["point"], *(h(k) for k in point_keys)], body))
        body = [[n] + [_g(lk.get(k), 5) for k in link_keys] for n, lk in a["links"].items()]
        parts.append("\n" + _table([t["link"], *(h(k) for k in link_keys)], body))

    parts.append(report_section(results, lang))     # the force analysis (render/forces.py)
    td = s.get("time_domain")
    if td:
        parts.append(f"\n## {t['time']}\n\n{t['time_note']}\n\n" + "\n".join(_time_lines(td, s, t)) + "\n")

    if results.warnings:
        parts.append(f"\n## {t['warn']}\n\n" + "\n".join(f"- {w}" for w in results.warnings) + "\n")
    if plots:
        parts.append(f"\n## {t['plots']}\n\n" + "\n".join(f"![{p}](plots/{p})" for p in plots) + "\n")
    return "".join(parts)
