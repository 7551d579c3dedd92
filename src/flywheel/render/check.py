"""`flywheel check`: print a case's :class:`~flywheel.dynamics.check.CheckReport` (rich): what it
describes, with the dead-centre kinematics. Formatting only."""
from __future__ import annotations

import math

from flywheel.io.text import in_language
from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name as P
from flywheel.render.numbers import fmt as _number
from flywheel.render.numbers import russian, separator
from flywheel.units import PA_PER_MPA

# the words of `flywheel check` (the quantities' names, symbols and units: the nomenclature)
W = words("check", {"case": "case", "given_fw": "a given flywheel, ",
                    "balance_driving": "cycle condition: the driving moment is constant "
                                       "(M_D = −A_C/Φ)",
                    "balance_resistance": "cycle condition: the moment of resistance is constant "
                                          "(M_C = −A_D/Φ)",
                    "cycle": "cycle Φ = {c}°",
                    "fires": "; fires: ", "fire_at": "{n} at {a}°", "mechanism": "Mechanism",
                    "group": "group", "links": "links", "points": "points", "data": "data",
                    "crank": "crank", "crank_pin": "crank pin", "cw": "cw", "ccw": "ccw",
                    "pin_at": "l = {l} m, at {a}° to {tip}",
                    "rrp": "rod {l} m; guide through {th} at {a}°, offset {o} m; branch {b}",
                    "rpr_where": "{o} on rocker about {p}", "rpr": "offset {o} m; branch {b}",
                    "rrr": "{a} m, {b} m; branch {br}", "point": "point", "of": "{f} of {o}→{t}",
                    "across": ", {a} m across", "from": "{d} m from {o} at {a}°", "Links": "Links",
                    "link": "link", "centroid": "centroid",
                    "first_group": "first group (on the crank shaft): ", "Cylinders": "Cylinders",
                    "name": "name", "piston": "piston", "head": "head", "interpolation": "interpolation",
                    "Dead centres": "Dead centres", "slider": "slider", "dead centre": "dead centre",
                    "x along guide": "x along guide", "stroke": "stroke", "outer": "outer",
                    "inner": "inner",
                    "pts_dc": "Points at the dead centres: {v} / {a}",
                    "links_dc": "Links at the dead centres: {w} / {e}", "valid": "case is valid",
                    "J_II_by": "{J} by {how}", "tab_kin": "Tabulated kinematics (one row per position)",
                    "tab_red": "Reduced to the crank ({M} = {w}²/2·{dJ}, {dJ} by {how})",
                    "loads": "loads: ", "force_at": "{n} at {p} ({how})", "moment": "moment {n} ({how})",
                    "at": "at", "row": "{w} row",
                    "kinematics_only": "the kinematics alone (ε = 0)"})



def _load(x, lang: str) -> str:
    """A tabulated force or moment as the Russian line names it: its Russian title where the
    case gives one («сила тяжести шатуна G2»), else (and in English) its name."""
    return in_language(x.title, lang) if lang == "ru" and x.title else x.name

def _g(x: float) -> str:
    """6 significant digits; round-off below 1e-12 shown as 0."""
    return _number(x, 6, zero=1e-12, nonfinite="show")


def _n(x: float, spec: str = "g", given: bool = False) -> str:
    """A number of the check: in English Python's ``format(x, spec)`` as it always printed;
    in Russian (within ``typography("ru")``: the CLI's ``typeset``) the formatter's policy —
    an input the case gave (``given``) with its own digits, a result to four."""
    return _number(x, spec=spec, zero=None, nonfinite="show", given=given)


def _deg(rad: float) -> str:
    """A dead centre's angle [deg]: four decimals in English as before; four significant
    digits in Russian (a result, as in the summary)."""
    return _n(math.degrees(rad), "g" if russian() else ".4f")


def _xy(p) -> str:
    """A point (x, y) [m] given by the case: «(0.0, 0.0)» in English as before; in Russian
    «(0; 0)» (the comma is the decimal sign)."""
    if not russian():
        return str(p)
    return "(" + separator().join(_n(v, given=True) for v in p) + ")"


def _crank_line(report, m, lang: str = "en") -> str:
    """n1, ω_m, δ and which constant moment balances the cycle."""
    w = W[lang]
    bal = w["balance_driving" if m.balance == "driving" else "balance_resistance"]
    speed = (f"{nm.name('crank_speed', lang)} = {_n(report.crank_speed_rps, '.6g')} "
             f"{nm.unit_of('crank_speed', lang)}, "
             f"{nm.symbol('omega_mean', lang)} = {_n(m.omega_mean, '.6g')} "
             f"{nm.unit_of('omega_mean', lang)}")
    if report.case.kinematics_only:
        return speed + ", " + w["kinematics_only"]
    return (speed + ", "
            + (f"{nm.symbol('delta', lang)} = {_n(m.delta, given=True)}, " if m.delta is not None else
               w["given_fw"]) + bal)


def _table(title: str, columns):
    """A rich table whose title and headers are plain text (units in brackets stay)."""
    from rich.markup import escape
    from rich.table import Table

    t = Table(title=escape(title))
    for col in columns:
        t.add_column(escape(col), justify="right" if col != columns[0] else "left")
    return t


def print_check(report, console=None, lang: str = "en") -> None:
    """Print a :class:`~flywheel.dynamics.check.CheckReport`: the mechanism, links, cylinders
    and the kinematics at each slider's dead centres (or a tabulated case's table); the words
    in ``lang``."""
    from rich.console import Console
    from rich.table import Table

    from flywheel.cases.run import RPRSpec, RRPSpec

    console = console or Console()
    case = report.case
    w = W[lang]
    if report.tabulated is not None:
        return _print_tabulated(report, console, lang)
    mech = report.mechanism
    m = case.machine
    title, source = in_language(case.title, lang), in_language(case.source, lang)
    console.print(f"[bold]{title or w['case']}[/bold]  ({source})" if source
                  else f"[bold]{title or w['case']}[/bold]")
    console.print(_crank_line(report, m, lang))
    if m.cycle_deg != 360 or report.firing_deg:
        console.print(w["cycle"].format(c=_n(m.cycle_deg, given=True)) + (w["fires"] + ", ".join(
            w["fire_at"].format(n=n, a=_n(a, ".6g")) for n, a in report.firing_deg.items())
            if report.firing_deg else ""))
    c = mech.crank
    t = Table(title=w["mechanism"], show_lines=False)
    for col in ("group", "links", "points", "data"):
        t.add_column(w[col])
    t.add_row(w["crank"], c.name, f"{P(c.pivot)} → {P(c.tip)}",
              f"l = {_n(c.length, '.6g', True)} {nm.unit('m', lang)}, "
              f"θ0 = {_n(math.degrees(c.start_angle))}°, "
              f"{w['cw'] if c.direction < 0 else w['ccw']}")
    for pin in c.pins:
        t.add_row(w["crank_pin"], c.name, f"{P(c.pivot)} → {P(pin.name)}",
                  w["pin_at"].format(l=_n(pin.length, ".6g", True), a=_n(math.degrees(pin.angle)),
                                     tip=P(c.tip)))
    for spec, d in zip(case.dyads, mech.dyads):
        if isinstance(spec, RRPSpec):
            t.add_row(f"{nm.dyad_kind('RRP', lang)} {P(d.name)}", ", ".join(d.links), f"{P(d.origin)} → {P(d.joint)}",
                      w["rrp"].format(l=_n(d.rod_length, ".6g", True), th=_xy(d.guide.through),
                                      a=_n(math.degrees(d.guide.angle)),
                                      o=_n(d.guide.offset, given=True), b=spec.branch))
        elif isinstance(spec, RPRSpec):
            t.add_row(f"{nm.dyad_kind('RPR', lang)} {P(d.name)}", ", ".join(d.links),
                      w["rpr_where"].format(o=P(d.origin), p=P(d.pivot)),
                      w["rpr"].format(o=_n(d.offset, given=True), b=spec.branch))
        else:
            t.add_row(f"{nm.dyad_kind('RRR', lang)} {P(d.name)}", ", ".join(d.links),
                      f"{P(d.point_a)} → {P(d.joint)} ← {P(d.point_b)}",
                      w["rrr"].format(a=_n(d.length_a, ".6g", True), b=_n(d.length_b, ".6g", True),
                                      br=spec.branch))
    for p in mech.points:
        how = (w["of"].format(f=_n(p.fraction, given=True), o=P(p.origin), t=P(p.toward))
               + (w["across"].format(a=_n(p.across, given=True)) if p.across else "")
               if p.toward else w["from"].format(d=_n(p.distance, given=True), o=P(p.origin),
                                                 a=_n(math.degrees(p.angle))))
        t.add_row(w["point"], p.link, P(p.name), how)
    console.print(t)

    if case.links:
        t = _table(w["Links"], (w["link"], nm.heading("link_mass", lang,
                                                      label=nm.name("link_mass", lang)),
                                nm.heading("J_S", lang), w["centroid"]))
        for name, lk in case.links.items():
            t.add_row(name, _n(lk.mass, given=True) if lk.mass else "—", _n(lk.J_S, given=True),
                      P(lk.centroid) if lk.centroid else "—")
        console.print(t)
    if m.first_group:
        from flywheel.render.sheet_labels import part_name

        console.print(w["first_group"] + ", ".join(
            f"{part_name(k, lang)} = {_n(v, given=True)} {nm.unit_of('J_first_group', lang)}"
            for k, v in m.first_group.items()))
    if case.cylinders:
        t = _table(w["Cylinders"], (w["name"], w["piston"],
                                    nm.heading("bore", lang, label=nm.name("bore", lang)),
                                    nm.heading("p_max", lang, si="MPa"), w["head"],
                                    w["interpolation"], w["points"]))
        for k, cy in enumerate(case.cylinders):
            label = nm.cylinder_label(cy, lang)          # «HP (ВД)»: the key, then its label
            t.add_row(cy.name if label == cy.name else f"{cy.name} ({label})", cy.piston,
                      _n(cy.bore, given=True),
                      _n(cy.p_max / PA_PER_MPA), w.get(cy.head, cy.head),
                      nm.field_value(f"cylinders.{k}.interpolation", cy.interpolation, lang), str(len(cy.s if cy.s is not None else cy.diagram.s)))
        console.print(t)

    if report.sliders:
        t = _table(w["Dead centres"], (w["slider"], w["dead centre"], nm.heading("phi_deg", lang),
                                       nm.heading("x", lang, label=w["x along guide"])))
        for sl in report.sliders:
            for dc in sl.dead_centres:
                t.add_row(sl.slider, w.get(dc.kind, dc.kind), _deg(dc.phi),
                          _n(dc.x, ".6g"))
            t.add_row(sl.slider, w["stroke"], "", _n(sl.stroke, ".6g"))
        console.print(t)
        angles = report.dead_centre_angles
        if angles:
            vq = nm.heading("v_q", lang, label=f"|{nm.symbol('v_q', lang)}|")
            aq = nm.heading("a_q", lang, label=f"|{nm.symbol('a_q', lang)}|")
            t = _table(w["pts_dc"].format(v=vq, a=aq),
                       (nm.heading("phi_deg", lang), *map(P, report.point_analogues)))
            for i, a in enumerate(angles):
                t.add_row(_deg(a), *(
                    f"{_g(v[i])} / {_g(acc[i])}" for v, acc in report.point_analogues.values()))
            console.print(t)
            t = _table(w["links_dc"].format(w=nm.heading("omega_q", lang),
                                            e=nm.heading("epsilon_q", lang)),
                       (nm.heading("phi_deg", lang), *report.link_analogues))
            for i, a in enumerate(angles):
                t.add_row(_deg(a), *(
                    f"{_g(w[i])} / {_g(e[i])}" for w, e in report.link_analogues.values()))
            console.print(t)
    if report.output_link is not None:                  # render/output_link.py
        from flywheel.render.output_link import print_check as print_output_link

        print_output_link(report.output_link, console, lang,
                          driven=case.machine.balance == "resistance")
    console.print(f"[green]{w['valid']}[/green]")


def _print_tabulated(report, console, lang: str = "en") -> None:
    """A case with tabulated kinematics: its table, one row per position, with Мст and J_II."""
    case, red = report.case, report.tabulated
    tab, m = case.tabulated, case.machine
    w = W[lang]
    title, source = in_language(case.title, lang), in_language(case.source, lang)
    console.print(f"[bold]{title or w['case']}[/bold]"
                  + (f"  ({source})" if source else ""))
    how = nm.field_value("tabulated.interpolation", tab.interpolation, lang)   # J_II's, in words
    console.print(f"{_crank_line(report, m, lang)}; "
                  + w["J_II_by"].format(J=nm.symbol("J_II", lang), how=how), markup=False)
    phi = nm.heading("phi_deg", lang)
    kin = [(phi, tab.positions_deg)]
    kin += [(nm.heading(f"vq_{k}", lang, label=f"|{nm.symbol(f'vq_{k}', lang)}| {k}"), v)
            for k, v in tab.points.items()]
    kin += [(nm.heading(f"omega_q_{k}", lang, label=f"{nm.symbol(f'omega_q_{k}', lang)} {k}"), v)
            for k, v in tab.omega_q.items()]
    reduced = [(phi, tab.positions_deg), (nm.heading("M_st", lang), red.static_moments),
               (nm.heading("J_II", lang), red.J_II), (nm.heading("dJ_II", lang), red.dJ_II),
               (nm.heading("M_dyn", lang), red.dynamic_moments)]
    dJ = nm.symbol("dJ_II", lang)
    for title, cols in ((w["tab_kin"], kin),
                        (w["tab_red"].format(M=nm.symbol("M_dyn", lang),
                                             w=nm.symbol("omega_mean", lang), dJ=dJ,
                                             how=how), reduced)):
        t = _table(title, (nm.name("row_no", lang), *(c[0] for c in cols)))
        for k in range(len(tab.positions_deg)):
            t.add_row(str(k + 1), *(_g(float(v[k])) for _, v in cols))
        console.print(t)
    if tab.forces or tab.moments:
        console.print(w["loads"] + ", ".join(
            [w["force_at"].format(n=_load(f, lang), p=f.point, how=nm.field_value(
                f"tabulated.forces.{k}.interpolation", f.interpolation, lang))
             for k, f in enumerate(tab.forces)]
            + [w["moment"].format(n=_load(mo, lang), how=nm.field_value(
                f"tabulated.moments.{k}.interpolation", mo.interpolation, lang))
               for k, mo in enumerate(tab.moments)]),
            markup=False)
    t = _table(w["Links"], (w["link"], nm.heading("link_mass", lang,
                                                  label=nm.name("link_mass", lang)), w["at"],
                            nm.heading("link_J", lang),
                            w["row"].format(w=nm.symbol("omega_q", lang))))
    for name, lk in tab.links.items():
        t.add_row(name, _n(lk.mass, given=True) if lk.mass else "—", lk.point or "—",
                  _n(lk.J, given=True),
                  (lk.omega_q or name) if lk.J else "—")
    console.print(t)
    console.print(f"[green]{w['valid']}[/green]")
