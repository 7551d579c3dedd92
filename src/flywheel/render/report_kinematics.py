"""The записка and the terminal summary of the kinematics alone
(:class:`flywheel.dynamics.kinematics_only.KinematicsResults`): the input data and structure,
the analogues at the standard positions, the output link, the true velocities and
accelerations at the report angles at ω = ω_m = const. Formatting only; the sections'
words are the report's (render/document.py) where they are the same."""
from __future__ import annotations

import math

from flywheel.render import nomenclature as nm
from flywheel.render.blocks import Source, referenced
from flywheel.render.positions import numbered, position_cells
from flywheel.render.catalogue import words
from flywheel.render.mathfmt import point_name
from flywheel.render.document import (T, Bullets, Formula, Heading, Paragraph, Where, _Builder,
                                      _input_of_case, _structure, g)

K = words("report_kinematics", {
    "title": "Kinematics",
    "note": ("The kinematics alone: the crank turns at the constant speed {w} = {v} {u} "
             "(ε = 0); no masses, loads or flywheel are analysed."),
    "motion": "3. True velocities and accelerations at the constant crank speed",
    "summary": "kinematics alone at {w} = {v} {u} (ε = 0)",
    # the symbols of the formula, a line each (ГОСТ 7.32-2017, 6.8.2)
    "where": ("where v_q, a_q are the velocity and acceleration analogues of a point, ω the "
              "crank's constant angular velocity;\n"
              "ω_qi, ε_qi the angular velocity and acceleration analogues of link i."),
})


def build_kinematics_document(results, lang: str = "en", plots: list[str] | None = None,
                              case=None):
    """The записка of a kinematics-only run (a :class:`~flywheel.render.blocks.Document`)."""
    t, k = T[lang], K[lang]
    b = _Builder(results.title, lang, plots)

    def h(key, **kw):
        return nm.heading(key, lang, **kw)

    b.add(Heading(1, f"{k['title']}: {results.title}"))
    if results.source:
        b.add(Source(f"{t['source']}: {results.source}"))
    w = results.omega_mean
    b.add(Paragraph(k["note"].format(w=nm.symbol("omega_mean", lang), v=g(w, 6),
                                     u=nm.unit_of("omega_mean", lang))))
    if not plots:
        b.add(Paragraph(t["no_plots"]))
    b.add(Heading(2, t["input"]))
    sym = lambda key: nm.symbol(key, lang)        # noqa: E731
    b.add(Heading(3, f"1.1. {t['machine']}"))
    b.table(t["machine"], [t["qty"], t["val"], t["unit"]], [
        [f"{sym('omega_mean')} = 2π·{sym('crank_speed')}", g(w, 6), nm.unit_of("omega_mean", lang)],
        [sym("crank_speed"), g(w / (2 * math.pi), 6), nm.unit_of("crank_speed", lang)],
        [sym("crank_length"), g(results.crank_length, 6), nm.unit_of("crank_length", lang)]])
    if case is not None:
        _input_of_case(b, case, t, lang)
        _structure(b, case, t, lang)

    cols = results.columns
    pos = [t["no"]] if numbered(results.position_angles) else [t["pos"]]
    cells, dead_note = position_cells(results.position_angles, lang)
    idx = [([c], results.index_of(p.phi)) for c, p in zip(cells, results.position_angles)]
    vq = [c for c in cols if c.startswith("vq_")]
    wq = [c for c in cols if c.startswith("omega_q_")]
    b.add(Heading(2, t["kin"]))
    b.add(Paragraph(t["kin_note"].format(vq=sym("v_q"), u=nm.unit_of("v_q", lang),
                                         wq=sym("omega_q"))))
    header = pos + [h("phi_deg")] + [f"{nm.symbol(c, lang)}{nm.member(c, lang)}" for c in vq + wq]
    body = [[*lab, g(cols["phi_deg"].values[i], 6)] + [g(cols[c].values[i], 4) for c in vq + wq]
            for lab, i in idx]
    b.table(t["kin_caption"], header, body)
    if dead_note:
        b.add(Paragraph(dead_note))
    b.figures_of("kin")
    if results.output_link is not None:
        from flywheel.render.output_link import add_report_section

        add_report_section(b, results.output_link, lang, "2.1")

    b.add(Heading(2, k["motion"]))
    b.add(Formula(r"v = v_{q} \omega, a = a_{q} \omega^{2}, \omega_{i} = \omega_{qi} \omega, "
                  r"\varepsilon_{i} = \varepsilon_{qi} \omega^{2}"))
    b.add(Where(k["where"]))
    point_keys, link_keys = ("v_q", "v", "a_q", "a"), ("omega_q", "omega", "epsilon_q", "epsilon")
    for n, a in enumerate(results.at, 1):
        b.add(Heading(3, f"3.{n}. φ = {g(a.phi_deg, 6)}°"))
        b.table(t["points_caption"].format(a=g(a.phi_deg, 6)), [t["point"], *(h(x) for x in point_keys)],
                [[point_name(p)] + [g(getattr(pt, x), 5) for x in point_keys]
                 for p, pt in a.points.items()])
        b.table(t["links_caption"].format(a=g(a.phi_deg, 6)), [t["link"], *(h(x) for x in link_keys)],
                [[n_] + [g(getattr(lk, x), 5) for x in link_keys] for n_, lk in a.links.items()])
    if b.plots:
        b.add(Heading(2, t["figures"]))
        b.figures_of("figures")
    b.add(Heading(2, t["sources"]))
    src = [t["book"]]
    if results.source:
        src.insert(0, t["case_source"].format(s=results.source))
    b.add(Bullets(tuple(f"[{i}] {x}" for i, x in enumerate(src, 1))))
    b.doc.blocks[:] = referenced(b.doc.blocks, lang)     # every table and figure cited
    return b.doc


def print_kinematics_summary(results, lang: str = "en", console=None) -> None:
    """The terminal summary: what was computed, the output link, and at each report angle the
    points' and links' true velocities and accelerations."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = console or Console()
    t, k = T[lang], K[lang]
    console.print(f"[bold]{escape(results.title)}[/bold]" if results.title else "")
    console.print(k["summary"].format(w=nm.symbol("omega_mean", lang), v=g(results.omega_mean, 6),
                                      u=nm.unit_of("omega_mean", lang)), markup=False)
    if results.output_link is not None:
        from flywheel.render.output_link import print_check

        print_check(results.output_link, console, lang)
    for a in results.at:
        tab = Table(title=escape(t["points_caption"].format(a=g(a.phi_deg, 6))))
        for col in (t["point"], *(nm.heading(x, lang) for x in ("v", "a"))):
            tab.add_column(escape(col), justify="right")
        for p, pt in a.points.items():
            tab.add_row(escape(point_name(p)), g(pt.v, 6), g(pt.a, 6))
        console.print(tab)
        tab = Table(title=escape(t["links_caption"].format(a=g(a.phi_deg, 6))))
        for col in (t["link"], *(nm.heading(x, lang) for x in ("omega", "epsilon"))):
            tab.add_column(escape(col), justify="right")
        for n_, lk in a.links.items():
            tab.add_row(n_, g(lk.omega, 6), g(lk.epsilon, 6))
        console.print(tab)
