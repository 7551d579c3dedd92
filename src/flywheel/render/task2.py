"""`flywheel task2` output: the JSON text, the rich summary and the plot.

Renderers compute no physics: they format a :class:`flywheel.constant_inertia.solve.Task2Result`
(its JSON document is the result's own :meth:`~flywheel.constant_inertia.solve.Task2Result.to_document`).
rich and matplotlib are imported inside the functions that use them.
"""
from __future__ import annotations

import math

from flywheel.render import nomenclature as nm
from flywheel.render.numbers import apart, fmt as _number
from flywheel.units import PA_PER_MPA, RPM_PER_RAD_S


def to_dict(r, title: str = "", source: str = "") -> dict:
    """The result's JSON document, :meth:`~flywheel.constant_inertia.solve.Task2Result.to_document`."""
    return r.to_document(title, source)


def to_json(r, title: str = "", source: str = "") -> str:
    """The result's document as indented JSON text (byte-identical for the same input)."""
    import json

    return json.dumps(r.to_document(title, source), indent=2, ensure_ascii=False)


def _g(x: float | None, fmt: str = ".6g") -> str:
    return _number(x, spec=fmt, zero=1e-12, nonfinite="dash-nan")


def _angle(phi: float | None, lang: str = "en") -> str:
    if phi is None or math.isnan(phi):
        return nm.name("angle_unknown", lang)
    return nm.name("angle", lang, deg=_g(math.degrees(phi)), pi=_pi(phi / math.pi))


def _pi(k: float) -> str:
    """An angle of ``k``·π as written: «0», «π», «−π», «0,625π»."""
    text = _g(k)
    return "0" if text in ("0", "-0", "−0") else text[:-1] + "π" if text in ("1", "-1", "−1") \
        else f"{text}π"


def print_summary(r, title: str = "", source: str = "", console=None, lang: str = "en",
                  motion: bool = False) -> None:
    """The segment table and the results, as the seed presents them, on a rich console; labels,
    symbols and units in ``lang`` (en, ru: :mod:`flywheel.render.nomenclature`). ``motion``
    (or angles asked in ``r.at``) adds ε(φ)'s extremes, the time law and the asked angles."""
    from rich.console import Console
    from rich.table import Table

    def L(key: str, **fields) -> str:
        return nm.name(key, lang, **fields)

    def U(u: str) -> str:
        return nm.unit(u, lang)

    console = console or Console()
    if title:
        from rich.markup import escape

        from flywheel.io.text import cut_end   # a long title or source cut with «…»

        console.print(f"[bold]{escape(cut_end(title))}[/bold]"
                      + (f"  ({escape(cut_end(source))})" if source else ""))
    if r.unknown:
        name = nm.symbol({"resistance": "t2_M_C", "driving": "t2_M_D"}[r.unknown], lang)
        val = r.M_C if r.unknown == "resistance" else r.M_D
        console.print(L("t2_balance", name=name, value=_g(val), work=_g(r.work_driving)))
    elif r.M_C is not None:
        console.print(L("t2_given", M_D=_g(r.M_D), M_C=_g(r.M_C)))
    if r.power_found is not None and r.power is not None:   # the mean power needs steady motion
        name = nm.symbol("t2_M_D" if r.power_found == "driving" else "t2_M_C", lang)
        console.print(L("t2_power", P=_g(r.power), name=name, T=_g(r.power / r.omega_mean)))
    if not r.steady:
        console.print(L("t2_unsteady", work=_number(r.work_end, spec=".6g", zero=None, nonfinite="show"), omega_end=_g(r.omega_end, ".6f"),
                        omega0=_g(r.omega0, ".6f")))

    t = Table(title=L("t2_segments"))
    for col, just in ((L("row_no"), "right"), (L("t2_phi_deg"), "right"), (L("phi_pi"), "right"),
                      (L("point"), "left"), (nm.symbol("t2_M_D", lang), "right"),
                      (nm.symbol("t2_M_C", lang), "right"), (L("t2_A"), "right"), (L("t2_omega"), "right")):
        t.add_column(col, justify=just, no_wrap=True)
    for i, row in enumerate(r.rows):
        deg = None if math.isnan(row.phi) else math.degrees(row.phi)
        t.add_row(str(i), _g(deg), _g(None if math.isnan(row.phi) else row.phi / math.pi),
                  L("crossing_MD_MC") if row.kind == "crossing" and row.M_D is not None else
                  L("crossing" if row.kind == "crossing" else "bound"),
                  _g(row.M_D), _g(row.M_C), _g(row.A), _g(row.omega, ".6f"))
    console.print(t)

    def rpm(x: float) -> str:
        return L("rpm", n=_g(x * RPM_PER_RAD_S))

    def rpm_at(x: float, phi: float | None) -> str:
        return L("rpm_at", n=_g(x * RPM_PER_RAD_S), angle=_angle(phi, lang))

    t = Table(title=L("results"))
    for col in (L("quantity"), L("value"), L("unit"), ""):
        t.add_column(col)
    t.add_row(L("t2_J"), _g(r.J), U("kg·m²"), "")
    t.add_row(L("omega0"), _g(r.omega0, ".6f"), U("rad/s"), rpm(r.omega0))
    t.add_row(L("omega_max"), _g(r.omega_max, ".6f"), U("rad/s"),
              rpm_at(r.omega_max, r.phi_omega_max))
    t.add_row(L("omega_min"), _g(r.omega_min, ".6f"), U("rad/s"),
              rpm_at(r.omega_min, r.phi_omega_min))
    t.add_row(L("t2_omega_mean"), _g(r.omega_mean, ".6f"), U("rad/s"), rpm(r.omega_mean))
    t.add_row(L("t2_delta"), _g(r.delta), "", "")
    t.add_row(L("t2_delta_T_max"), _g(r.delta_T_max), U("J"), "")
    if r.power is not None:
        t.add_row(L("t2_P"), _g(r.power), U("W"), "")
    if r.J_required is not None:
        t.add_row(L("t2_J_required", delta=_g(r.delta_target)), _g(r.J_required), U("kg·m²"),
                  L("t2_J_required_how"))
    if r.rim_mass is not None:
        t.add_row(L("rim_mass", R=_g(r.rim_radius)), _g(r.rim_mass), U("kg"), L("rim_mass_how"))
    if r.flywheel_mass is not None:
        t.add_row(L("t2_flywheel_mass", k=_g(r.radius_of_gyration)), _g(r.flywheel_mass), U("kg"),
                  L("flywheel_mass_how"))
    if r.rim is not None:                     # [flywheel.rim]: the designed rim
        d = r.rim
        t.add_row(L("rim_design", share=_g(d.share, ".4g"), ratio=_g(d.width / d.thickness, ".4g")
                    if d.thickness > 0 else "—"),
                  L("rim_design_dims", D=_g(d.D_mean, ".4g"), t=_g(d.thickness, ".4g"),
                    b=_g(d.width, ".4g"), m=_g(d.mass, ".5g")), "",
                  L("rim_design_how", v=_g(d.rim_speed, ".4g"), sigma=_g(d.stress / PA_PER_MPA, ".4g"),
                    src=L("rim_from_stress" if d.speed_from == "allowable stress"
                          else "rim_from_given")))
    if r.driving is None and r.energy_fluctuation_coefficient is not None:
        t.add_row(L("t2_energy_fluctuation_coefficient"), _g(r.energy_fluctuation_coefficient), "",
                  "")
    console.print(t)
    if (motion or r.at) and r.driving is not None:
        _print_motion(r, console, lang)


def _print_motion(r, console, lang: str) -> None:
    """ε(φ)'s extremes, the cycle time, C_E, the phases and the asked angles (all from ``r``)."""
    from rich.table import Table

    def L(key: str, **fields) -> str:
        return nm.name(key, lang, **fields)

    t = Table(title=L("t2_motion"))
    for col in (L("quantity"), L("value"), L("unit"), ""):
        t.add_column(col)
    t.add_row(L("t2_epsilon_max"), _g(r.epsilon_max), nm.unit("rad/s²", lang),
              L("at_angle", angle=_angle(r.phi_epsilon_max, lang)))
    t.add_row(L("t2_epsilon_min"), _g(r.epsilon_min), nm.unit("rad/s²", lang),
              L("at_angle", angle=_angle(r.phi_epsilon_min, lang)))
    t.add_row(L("t2_cycle_time"), _g(r.cycle_time), nm.unit("s", lang), "")
    if r.energy_fluctuation_coefficient is not None:
        t.add_row(L("t2_energy_fluctuation_coefficient"), _g(r.energy_fluctuation_coefficient), "",
                  "")
    console.print(t)
    t = Table(title=L("t2_phases"))
    for col, just in ((L("row_no"), "right"), (L("phi_from"), "right"), (L("phi_to"), "right"),
                      (L("trend"), "left"), (L("t_start"), "right"), (L("duration"), "right")):
        t.add_column(col, justify=just, no_wrap=True)
    for i, ph in enumerate(r.phases):
        t.add_row(str(i), _g(math.degrees(ph.phi_start)), _g(math.degrees(ph.phi_end)),
                  L(f"trend_{ph.trend}"), _g(ph.t_start), _g(ph.duration))
    console.print(t)
    if r.at:
        t = Table(title=L("t2_at"))
        for col in (L("phi_col"), L("omega_col"), L("epsilon_col"), L("t2_t")):
            t.add_column(col, justify="right", no_wrap=True)
        for a in r.at:
            t.add_row(_g(math.degrees(a.phi)), _g(a.omega, ".6f"), _g(a.epsilon), _g(a.t))
        console.print(t)


def plot(r, path, title: str = "", lang: str = "en") -> None:
    """M_D, M_C, A and ω against φ [deg] into an image file (a pyplot-free matplotlib figure in
    render/figure.py's fixed style, laid out by matplotlib's constrained layout, the legends
    inside the axes); labels in ``lang``, the symbols' subscripts (M_Д, ω_ср, ε_max) as
    mathtext (mathfmt.sub_mathtext), units as the other figures write them ("ω, рад/с")."""
    import os
    from pathlib import Path

    import matplotlib
    from matplotlib.figure import Figure

    from flywheel.constant_inertia.solve import sample
    from flywheel.render import figure as fg
    from flywheel.render.mathfmt import sub_mathtext

    def L(key: str, **fields) -> str:
        return sub_mathtext(nm.name(key, lang, **fields))

    with fg.style(lang):
        if r.driving is not None:
            s = sample(r)
            x = [math.degrees(p) for p in s["phi"]]
            fig = Figure(figsize=(7.45, 10), dpi=100, layout="constrained")
            axes = fig.subplots(4, 1, sharex=True)
            ax = axes[3]
            ax.plot(x, s["epsilon"], color="tab:purple", label=L("t2_plot_epsilon"))
            ax.axhline(0.0, color="grey", linewidth=0.6)
            for value, phi, key, marker in ((r.epsilon_max, r.phi_epsilon_max,
                                             "t2_plot_epsilon_max", "^"),
                                            (r.epsilon_min, r.phi_epsilon_min,
                                             "t2_plot_epsilon_min", "v")):
                ax.plot([math.degrees(phi)], [value], marker, color="tab:purple",
                        label=L(key, value=_number(value, spec=".4g", zero=None, nonfinite="show"),
                                deg=_number(math.degrees(phi), spec=".4g", zero=None,
                                            nonfinite="show")))
            ax.set_ylabel(L("t2_plot_epsilon_axis"))
            ax.legend(fontsize=8)
            ax = axes[0]
            ax.plot(x, s["M_D"], label=L("t2_plot_MD"))
            ax.plot(x, s["M_C"], label=L("t2_plot_MC"))
            ax.set_ylabel(L("t2_plot_moment"))
            ax.legend()
            axes[1].plot(x, s["A"], color="tab:green", label=L("t2_plot_A"))
            axes[1].set_ylabel(L("t2_plot_A_axis"))
            axes[1].legend()
            axes[2].plot(x, s["omega"], color="tab:red", label=L("t2_plot_omega"))
        else:
            known = not math.isnan(r.rows[0].phi)
            x = [math.degrees(row.phi) if known else i for i, row in enumerate(r.rows)]
            fig = Figure(figsize=(7.45, 5.6), dpi=100, layout="constrained")
            axes = [None, *fig.subplots(2, 1, sharex=True)]
            axes[1].plot(x, [row.A for row in r.rows], "o-", color="tab:green",
                         label=L("t2_plot_A_areas"))
            axes[1].set_ylabel(L("t2_plot_A_axis"))
            axes[1].legend()
            axes[2].plot(x, [row.omega for row in r.rows], "o-", color="tab:red",
                         label=L("t2_plot_omega_areas"))
        ax = axes[2]
        ax.axhline(r.omega_mean, color="grey", linestyle="--", linewidth=0.8,
                   label=L("t2_plot_omega_mean"))
        # ω_max and ω_min told apart: a small δ writes both 200 to four digits (numbers.apart)
        spec = apart(r.omega_max, r.omega_min) or ".6g"
        for value, phi, key, marker in ((r.omega_max, r.phi_omega_max, "t2_plot_omega_max", "^"),
                                        (r.omega_min, r.phi_omega_min, "t2_plot_omega_min", "v")):
            if phi is not None and not math.isnan(phi):      # an area diagram may give no angle
                ax.plot([math.degrees(phi)], [value], marker, color="tab:red",
                        label=L(key, value=_number(value, spec=spec, zero=None, nonfinite="show"),
                                deg=_number(math.degrees(phi), spec=".4g", zero=None,
                                            nonfinite="show")))
        ax.set_ylabel(L("t2_plot_omega_axis"))
        if lang != "ru":                                    # Russian ticks have no offset
            ax.ticklabel_format(axis="y", useOffset=False)  # 200.01, not "+2e2" and 0.01
        phi_known = r.driving is not None or not math.isnan(r.rows[0].phi)
        axes[-1].set_xlabel(L("t2_plot_phi_axis") if phi_known else L("t2_plot_crossing_no"))
        if phi_known:
            cycle_deg = round(math.degrees(r.cycle))
            step = 30 if cycle_deg <= 360 else 60 if cycle_deg <= 720 else 90 * (cycle_deg // 1080 + 1)
            axes[-1].set_xticks(range(0, cycle_deg + 1, step))
        ax.legend()
        for a in axes:
            if a is not None:
                a.grid(True, alpha=0.3)
        fig.suptitle(title or L("t2_plot_title",
                                delta=_number(r.delta, spec=".4g", zero=None, nonfinite="show"),
                                dT=_number(r.delta_T_max, spec=".4g", zero=None,
                                           nonfinite="show")))
        from flywheel.render.figure import SVG_SALT, stable_metadata

        fmt = Path(path).suffix.lower()[1:] if isinstance(path, (str, os.PathLike)) else ""
        kw = {"metadata": {"Software": None}} if fmt == "png" else stable_metadata(fmt)
        with matplotlib.rc_context({"svg.hashsalt": SVG_SALT}):  # SVG, PDF: same bytes on a rerun
            fig.savefig(path, dpi=100, **kw)
