"""`flywheel check`: print a case's :class:`~flywheel.dynamics.check.CheckReport` (rich): what it
describes, with the dead-centre kinematics. Formatting only."""
from __future__ import annotations

import math


def _g(x: float) -> str:
    """6 significant digits; round-off below 1e-12 shown as 0."""
    return f"{0.0 if abs(x) < 1e-12 else x:.6g}"


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
    console.print(f"crank speed n1 = {report.crank_speed_rps:.6g} rev/s, "
                  f"ω_m = {m.omega_mean:.6g} rad/s, δ = {m.delta:g}, "
                  f"balance: constant {m.balance} moment")
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
        t = _table("Links", ("link", "mass [kg]", "J_S [kg·m²]", "centroid"))
        for name, lk in case.links.items():
            t.add_row(name, f"{lk.mass:g}" if lk.mass else "—", f"{lk.J_S:g}", lk.centroid or "—")
        console.print(t)
    if m.first_group:
        console.print("first group (on the crank shaft): " + ", ".join(
            f"{k} = {v:g} kg·m²" for k, v in m.first_group.items()))
    if case.cylinders:
        t = _table("Cylinders", ("name", "piston", "bore [m]", "p_max [MPa]", "head",
                                 "interpolation", "points"))
        for cy in case.cylinders:
            t.add_row(cy.name, cy.piston, f"{cy.bore:g}", f"{cy.p_max / 1e6:g}", cy.head,
                      cy.interpolation, str(len(cy.s if cy.s is not None else cy.diagram.s)))
        console.print(t)

    if report.sliders:
        t = _table("Dead centres", ("slider", "dead centre", "φ [deg]", "x along guide [m]"))
        for sl in report.sliders:
            for dc in sl.dead_centres:
                t.add_row(sl.slider, dc.kind, f"{math.degrees(dc.phi):.4f}", f"{dc.x:.6g}")
            t.add_row(sl.slider, "stroke", "", f"{sl.stroke:.6g}")
        console.print(t)
        angles = report.dead_centre_angles
        if angles:
            t = _table("Points at the dead centres: |v_q| [m/rad] / |a_q| [m/rad²]",
                       ("φ [deg]", *report.point_analogues))
            for i, a in enumerate(angles):
                t.add_row(f"{math.degrees(a):.4f}", *(
                    f"{_g(v[i])} / {_g(acc[i])}" for v, acc in report.point_analogues.values()))
            console.print(t)
            t = _table("Links at the dead centres: ω_q [-] / ε_q [1/rad]", ("φ [deg]", *report.link_analogues))
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
    console.print(f"crank speed n1 = {report.crank_speed_rps:.6g} rev/s, ω_m = {m.omega_mean:.6g} "
                  f"rad/s, δ = {m.delta:g}, balance: constant {m.balance} moment; J_II by "
                  f"{tab.interpolation}", markup=False)
    kin = [("φ [deg]", tab.positions_deg)]
    kin += [(f"|V_q| {k} [m]", v) for k, v in tab.points.items()]
    kin += [(f"ω_q {k}", v) for k, v in tab.omega_q.items()]
    reduced = [("φ [deg]", tab.positions_deg), ("Мст [N·m]", red.static_moments),
               ("J_II [kg·m²]", red.J_II), ("dJ_II/dφ [kg·m²]", red.dJ_II),
               ("Мдин [N·m]", red.dynamic_moments)]
    for title, cols in (("Tabulated kinematics (one row per position)", kin),
                        (f"Reduced to the crank (Мдин = ω_m²/2·dJ_II/dφ, dJ_II/dφ by "
                         f"{tab.interpolation})", reduced)):
        t = _table(title, ("#", *(c[0] for c in cols)))
        for k in range(len(tab.positions_deg)):
            t.add_row(str(k + 1), *(_g(float(v[k])) for _, v in cols))
        console.print(t)
    if tab.forces or tab.moments:
        console.print("loads: " + ", ".join(
            [f"{f.name} at {f.point} ({f.interpolation})" for f in tab.forces]
            + [f"moment {mo.name} ({mo.interpolation})" for mo in tab.moments]), markup=False)
    t = _table("Links", ("link", "mass [kg]", "at", "J [kg·m²]", "ω_q row"))
    for name, lk in tab.links.items():
        t.add_row(name, f"{lk.mass:g}" if lk.mass else "—", lk.point or "—", f"{lk.J:g}",
                  (lk.omega_q or name) if lk.J else "—")
    console.print(t)
    console.print("[green]case is valid[/green]")
