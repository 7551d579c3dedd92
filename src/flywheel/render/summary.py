"""The rich summary on the terminal (`flywheel run`): the same numbers as summary.json."""
from __future__ import annotations

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name
from flywheel.render.forces import print_forces
from flywheel.render.numbers import fmt as _number, separator

# Sentence templates and table words only: every quantity's name, symbol and unit comes from
# the nomenclature (render/nomenclature.py), filled in where the templates say {…}.
L10N = words("summary", {
    "title_main": "Results", "title_at": "At φ = {phi}°: ω = {w} {uw}, ε = {e} {ue}",
    "point": "point", "link": "link", "quantity": "quantity", "value": "value", "unit": "unit",
    "warning": "warning", "at": "at",
    "fw_shaft": "flywheel shaft: speed ratio {i}, {J}",
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
    "rd_never": "run-down: none — {reason}",
})


def _g(x: float, digits: int = 6) -> str:
    return _number(x, digits, zero=1e-13, nonfinite="show")


def time_domain_lines(td, lang: str = "en") -> list[str]:
    """The --transients results (a :class:`~flywheel.dynamics.results.TimeDomainResult`, or
    None) as lines of text (verification, start-up, run-down).

    >>> from flywheel.dynamics.results import Rundown, StartupRun, TimeDomainResult, Verification
    >>> td = TimeDomainResult(
    ...     Verification(cycles=3, repeat_error=1e-9, max_deviation=2e-9, period=0.1),
    ...     StartupRun(converged=False, cycles_run=2000, time_run=150.0, omega_mean_last=60.0,
    ...                omega_final_predicted=62.8, time_constant=None, starting_torque=100.0,
    ...                no_load_speed=70.0),
    ...     Rundown(time=2.5, angle_deg=720.0, stopped=True), histories={})
    >>> print("\\n".join(time_domain_lines(td, "ru")))  # doctest: +NORMALIZE_WHITESPACE
    интегрирование во времени (численно, циклов: 3): движение повторяется с точностью 1.0e-09,
    совпадает с ω(φ) до 2.0e-09, период 0.1 с
    разгон из состояния покоя: установившийся режим НЕ достигнут за 2000 циклов (150 с); средняя
    скорость последнего цикла 60 рад/с, по характеристике двигателя 62.8 рад/с
    выбег после отключения привода: 2.5 с, оборотов: 2.00
    """
    if td is None:
        return []
    t = L10N[lang]
    v = td.verification
    out = [t["td_verify"].format(n=v.cycles, rep=_number(v.repeat_error, spec=".1e", zero=None, nonfinite="show"),
                                 dev=_number(v.max_deviation, spec=".1e", zero=None, nonfinite="show"), T=_g(v.period))]
    st = td.startup
    if not st.computed:
        out.append(t["st_none"].format(reason=nm.message(st.reason, lang)))
    elif st.stalled:
        out.append(t["st_stall"].format(a=_number(st.stall_angle_deg, spec=".1f", zero=None, nonfinite="show")))
    elif st.converged and st.time_to_steady is not None:
        out.append(t["st_ok"].format(t=_g(st.time_to_steady, 4), n=st.cycles_to_steady,
                                     w=_g(st.omega_mean_steady)))
    else:
        wp = st.omega_final_predicted
        out.append(t["st_no"].format(n=st.cycles_run, t=_g(st.time_run, 4),
                                     w=_g(st.omega_mean_last),
                                     wp=_g(wp) if wp is not None else "—"))
    rd = td.rundown
    if rd.reason:                # English: the fixed line; Russian: the reason itself
        out.append(t["rd_never"].format(reason=nm.message(rd.reason, lang)))
        return out
    out.append(t["rd"].format(t=_g(rd.time, 4), rev=_number(rd.angle_deg / 360, spec=".2f", zero=None, nonfinite="show"))
               + ("" if rd.stopped else t["rd_not"]))
    return out


def print_summary(results, console=None, lang: str = "en") -> None:
    """Print the headline results, the flywheel, and the motion at each report angle."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    t = L10N[lang]
    console = console or Console()
    s = results.scalars

    def u(*keys: str) -> str:
        return ", ".join(nm.unit_of(k, lang) for k in keys)

    def at(key: str) -> str:
        """The value of ``key`` and where (φ) it is, with no trailing zeros (224.3°, not
        224.30°): ΔT_I's angle, refined between the grid's nodes, to 0.01°; ω's and ε's, nodes
        of the grid, as the node is."""
        phi = getattr(s, f"phi_{key}_deg")
        return f"{_g(getattr(s, key))} {t['at']} {_g(round(phi, 2) if key.startswith('delta_T') else phi)}°"

    from flywheel.io.text import cut_end   # a long title or source cut with «…» (issue 23)

    from flywheel.io.text import in_language

    title, source = in_language(results.title, lang), in_language(results.source, lang)
    console.print(f"[bold]{escape(cut_end(title))}[/bold]"
                  + (f"  ({escape(cut_end(source))})" if source else ""))
    tab = Table(title=t["title_main"])
    tab.add_column(t["quantity"])
    tab.add_column(t["value"], justify="right")
    tab.add_column(t["unit"])
    from flywheel.render.document import cycle_balance

    bal = cycle_balance(results)            # A_С, M_Д of a driven machine; A_Д, M_С of an engine
    for key in ("crank_length", "omega_mean"):
        tab.add_row(nm.name(key, lang), _g(getattr(s, key)), u(key))
    tab.add_row(nm.name(bal.keys[0], lang), _g(bal.work), u(bal.keys[0]))
    tab.add_row(nm.name(bal.keys[2], lang), _g(bal.moment), u(bal.keys[2]))
    for key in ("J_II_mean", "delta_T_max"):
        tab.add_row(nm.name(key, lang), _g(getattr(s, key)), u(key))
    tab.add_row(f"{nm.symbol('dT_I', lang)} max / min", f"{at('delta_T_I_max')} / {at('delta_T_I_min')}",
                u("dT_I"))
    given = bool(s.flywheel_given)          # a given flywheel: δ is its answer
    if given:
        tab.add_row(nm.name("J_flywheel_given", lang), _g(s.J_flywheel_given),
                    u("J_flywheel_given"))
    for key in ("J_required", "J_required_exact", "J_first_group", "J_flywheel", "delta",
                "delta_achieved", "delta_achieved_exact"):
        tab.add_row(nm.name("delta_given" if given and key == "delta" else key, lang),
                    _g(getattr(s, key)), u(key))
    if s.power is not None:
        for key in ("power", "power_moment", "power_from_loads"):
            tab.add_row(nm.name(key, lang), _g(getattr(s, key)), u(key))
    for key in ("omega_max", "omega_min", *(("epsilon_max", "epsilon_min") if given else ())):
        tab.add_row(nm.name(key, lang), at(key), u(key))
    sep = separator(lang)                   # numbers listed in a cell: «; » in Russian
    tab.add_row(t["fw_shaft"].format(i=nm.symbol("flywheel_speed_ratio", lang),
                                     J=nm.symbol("flywheel_J_on_its_shaft", lang)),
                f"{nm.symbol('flywheel_speed_ratio', lang)} = {_g(s.flywheel_speed_ratio)}{sep}"
                f"{_g(s.flywheel_J_on_its_shaft)}",
                u("flywheel_speed_ratio", "flywheel_J_on_its_shaft"))
    lim = s.flywheel_rim_speed_limit
    tab.add_row(nm.name("flywheel_material", lang),
                f"{nm.material(s.flywheel_material, lang)}, "
                f"{nm.symbol('flywheel_material_density', lang)} = "
                f"{_g(s.flywheel_material_density, 5)}"
                + (f"; {nm.name('flywheel_rim_speed_limit', lang)} {_g(lim, 3)}" if lim else ""),
                u("flywheel_material_density", *(["flywheel_rim_speed_limit"] if lim else [])))
    share = s.flywheel_rim_share
    if share < 1 - 1e-9:
        tab.add_row(nm.name("flywheel_rim_share", lang), _g(share, 4), u("flywheel_rim_share"))
    designed = s.rim_designed          # [flywheel.rim]: the designed rim
    rim_fields = (("D_mean", "thickness", "width", "mass", "rim_speed", "stress"),
                  (4, 4, 4, 5, 4, 4)) if designed else (("D", "D_inner", "b", "mass"), (4, 4, 4, 5))
    for key, fields, digits in (("flywheel_disk", ("D", "b", "mass"), (4, 4, 5)),
                                ("flywheel_rim", *rim_fields)):
        d = getattr(s, key)
        tab.add_row(nm.name("flywheel_rim_design" if key == "flywheel_rim" and designed else key,
                            lang),
                    sep.join(f"{nm.symbol(f, lang)} = {_g(getattr(d, f), n)}"
                             for f, n in zip(fields, digits)), u(*fields))
    console.print(tab)
    for a in results.at:
        pt = Table(title=t["title_at"].format(phi=_g(a.phi_deg), w=_g(a.omega), e=_g(a.epsilon),
                                              uw=nm.unit_of("omega", lang),
                                              ue=nm.unit_of("epsilon", lang)))
        point_keys = ("x", "y", "v_q", "a_q", "v", "a")
        for col in (t["point"], *(nm.heading(k, lang) for k in point_keys)):
            pt.add_column(escape(col), justify="right")
        for name, p in a.points.items():
            pt.add_row(escape(point_name(name)), *(_g(getattr(p, k), 5) if getattr(p, k) is not None else "—" for k in point_keys))
        console.print(pt)
        lt = Table()
        link_keys = ("omega_q", "epsilon_q", "omega", "epsilon")
        for col in (t["link"], *(nm.heading(k, lang) for k in link_keys)):
            lt.add_column(escape(col), justify="right")
        for name, lk in a.links.items():
            lt.add_row(name, *(_g(getattr(lk, k), 5) if getattr(lk, k) is not None else "—" for k in link_keys))
        console.print(lt)
    print_forces(results, console, lang)            # the force analysis (render/forces.py)
    for line in time_domain_lines(s.time_domain, lang):
        console.print(line, markup=False)
    # the warnings: once, on stderr, by the command (cli.options.warn), not here on stdout
