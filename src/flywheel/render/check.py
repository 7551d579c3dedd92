"""`flywheel check`: print a case's :class:`~flywheel.dynamics.check.CheckReport` (rich): what it
describes, with the dead-centre kinematics. Formatting only."""
from __future__ import annotations

import math

from flywheel.render import nomenclature as nm


def _g(x: float) -> str:
    """6 significant digits; round-off below 1e-12 shown as 0."""
    return f"{0.0 if abs(x) < 1e-12 else x:.6g}"


def _crank_line(report, m) -> str:
    """n1, ω_m, δ and which constant moment balances the cycle."""
    return (f"{nm.name('crank_speed')} = {report.crank_speed_rps:.6g} {nm.unit_of('crank_speed')}, "
            f"{nm.symbol('omega_mean')} = {m.omega_mean:.6g} {nm.unit_of('omega_mean')}, "
            + (f"{nm.symbol('delta')} = {m.delta:g}, " if m.delta is not None else
               "a given flywheel, ") + f"balance: constant {m.balance} moment")


def _table(title: str, columns):
    """A rich table whose title and headers are plain text (units in brackets stay)."""
    from rich.markup import escape
    from rich.table import Table

    t = Table(title=escape(title))
    for col in columns:
        t.add_column(escape(col), justify="right" if col != columns[0] else "left")
    return t


def print_check(report, console=None) -> None:
    """Print a :class:`~flywheel.dynamics.check.CheckReport`: the mechanism, links, cylinders
    and the kinematics at each slider's dead centres (or a tabulated case's table)."""
    from rich.console import Console
    from rich.table import Table

    from flywheel.cases.run import RPRSpec, RRPSpec

    console = console or Console()
    case = report.case
    if report.tabulated is not None:
        return _print_tabulated(report, console)
    mech = report.mechanism
    m = case.machine
    console.print(f"[bold]{case.title or 'case'}[/bold]  ({case.source})" if case.source
                  else f"[bold]{case.title or 'case'}[/bold]")
    console.print(_crank_line(report, m))
    if m.cycle_deg != 360 or report.firing_deg:
        console.print(f"cycle Φ = {m.cycle_deg:g}°" + ("; fires: " + ", ".join(
            f"{n} at {a:.6g}°" for n, a in report.firing_deg.items()) if report.firing_deg else ""))
    c = mech.crank
    t = Table(title="Mechanism", show_lines=False)
    for col in ("group", "links", "points", "data"):
        t.add_column(col)
    t.add_row("crank", c.name, f"{c.pivot} → {c.tip}",
              f"l = {c.length:.6g} m, θ0 = {math.degrees(c.start_angle):g}°, "
              f"{'cw' if c.direction < 0 else 'ccw'}")
    for pin in c.pins:
        t.add_row("crank pin", c.name, f"{c.pivot} → {pin.name}",
                  f"l = {pin.length:.6g} m, at {math.degrees(pin.angle):g}° to {c.tip}")
    for spec, d in zip(case.dyads, mech.dyads):
        if isinstance(spec, RRPSpec):
            t.add_row(f"RRP {d.name}", f"{d.rod}, {d.slider}", f"{d.origin} → {d.joint}",
                      f"rod {d.rod_length:.6g} m; guide through {d.guide.through} at "
                      f"{math.degrees(d.guide.angle):g}°, offset {d.guide.offset:g} m; branch {spec.branch}")
        elif isinstance(spec, RPRSpec):
            t.add_row(f"RPR {d.name}", f"{d.rocker}, {d.slider}", f"{d.origin} on rocker about {d.pivot}",
                      f"offset {d.offset:g} m; branch {spec.branch}")
        else:
            t.add_row(f"RRR {d.name}", f"{d.link_a}, {d.link_b}",
                      f"{d.point_a} → {d.joint} ← {d.point_b}",
                      f"{d.length_a:.6g} m, {d.length_b:.6g} m; branch {spec.branch}")
    for p in mech.points:
        how = (f"{p.fraction:g} of {p.origin}→{p.toward}" + (f", {p.across:g} m across" if p.across else "")
               if p.toward else f"{p.distance:g} m from {p.origin} at {math.degrees(p.angle):g}°")
        t.add_row("point", p.link, p.name, how)
    console.print(t)

    if case.links:
        t = _table("Links", ("link", nm.heading("link_mass", label=nm.name("link_mass")),
                             nm.heading("J_S"), "centroid"))
        for name, lk in case.links.items():
            t.add_row(name, f"{lk.mass:g}" if lk.mass else "—", f"{lk.J_S:g}", lk.centroid or "—")
        console.print(t)
    if m.first_group:
        console.print("first group (on the crank shaft): " + ", ".join(
            f"{k} = {v:g} {nm.unit_of('J_first_group')}" for k, v in m.first_group.items()))
    if case.cylinders:
        t = _table("Cylinders", ("name", "piston", nm.heading("bore", label=nm.name("bore")),
                                 nm.heading("p_max", si="MPa"), "head", "interpolation", "points"))
        for cy in case.cylinders:
            t.add_row(cy.name, cy.piston, f"{cy.bore:g}", f"{cy.p_max / 1e6:g}", cy.head,
                      cy.interpolation, str(len(cy.s if cy.s is not None else cy.diagram.s)))
        console.print(t)

    if report.sliders:
        t = _table("Dead centres", ("slider", "dead centre", nm.heading("phi_deg"),
                                    nm.heading("x", label="x along guide")))
        for sl in report.sliders:
            for dc in sl.dead_centres:
                t.add_row(sl.slider, dc.kind, f"{math.degrees(dc.phi):.4f}", f"{dc.x:.6g}")
            t.add_row(sl.slider, "stroke", "", f"{sl.stroke:.6g}")
        console.print(t)
        angles = report.dead_centre_angles
        if angles:
            vq = nm.heading("v_q", label=f"|{nm.symbol('v_q')}|")
            aq = nm.heading("a_q", label=f"|{nm.symbol('a_q')}|")
            t = _table(f"Points at the dead centres: {vq} / {aq}",
                       (nm.heading("phi_deg"), *report.point_analogues))
            for i, a in enumerate(angles):
                t.add_row(f"{math.degrees(a):.4f}", *(
                    f"{_g(v[i])} / {_g(acc[i])}" for v, acc in report.point_analogues.values()))
            console.print(t)
            t = _table(f"Links at the dead centres: {nm.heading('omega_q')} / {nm.heading('epsilon_q')}",
                       (nm.heading("phi_deg"), *report.link_analogues))
            for i, a in enumerate(angles):
                t.add_row(f"{math.degrees(a):.4f}", *(
                    f"{_g(w[i])} / {_g(e[i])}" for w, e in report.link_analogues.values()))
            console.print(t)
    console.print("[green]case is valid[/green]")


def _print_tabulated(report, console) -> None:
    """A case with tabulated kinematics: its table, one row per position, with Мст and J_II."""
    case, red = report.case, report.tabulated
    tab, m = case.tabulated, case.machine
    console.print(f"[bold]{case.title or 'case'}[/bold]" + (f"  ({case.source})" if case.source else ""))
    console.print(f"{_crank_line(report, m)}; {nm.symbol('J_II')} by {tab.interpolation}",
                  markup=False)
    phi = nm.heading("phi_deg")
    kin = [(phi, tab.positions_deg)]
    kin += [(nm.heading(f"vq_{k}", label=f"|{nm.symbol(f'vq_{k}')}| {k}"), v) for k, v in tab.points.items()]
    kin += [(nm.heading(f"omega_q_{k}", label=f"{nm.symbol(f'omega_q_{k}')} {k}"), v)
            for k, v in tab.omega_q.items()]
    reduced = [(phi, tab.positions_deg), (nm.heading("M_st"), red.static_moments),
               (nm.heading("J_II"), red.J_II), (nm.heading("dJ_II"), red.dJ_II),
               (nm.heading("M_dyn"), red.dynamic_moments)]
    dJ = nm.symbol("dJ_II")
    for title, cols in (("Tabulated kinematics (one row per position)", kin),
                        (f"Reduced to the crank ({nm.symbol('M_dyn')} = {nm.symbol('omega_mean')}²/2·{dJ}, "
                         f"{dJ} by {tab.interpolation})", reduced)):
        t = _table(title, ("#", *(c[0] for c in cols)))
        for k in range(len(tab.positions_deg)):
            t.add_row(str(k + 1), *(_g(float(v[k])) for _, v in cols))
        console.print(t)
    if tab.forces or tab.moments:
        console.print("loads: " + ", ".join(
            [f"{f.name} at {f.point} ({f.interpolation})" for f in tab.forces]
            + [f"moment {mo.name} ({mo.interpolation})" for mo in tab.moments]), markup=False)
    t = _table("Links", ("link", nm.heading("link_mass", label=nm.name("link_mass")), "at",
                         nm.heading("link_J"), f"{nm.symbol('omega_q')} row"))
    for name, lk in tab.links.items():
        t.add_row(name, f"{lk.mass:g}" if lk.mass else "—", lk.point or "—", f"{lk.J:g}",
                  (lk.omega_q or name) if lk.J else "—")
    console.print(t)
    console.print("[green]case is valid[/green]")
