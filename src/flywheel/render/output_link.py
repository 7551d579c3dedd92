"""The output link of the last group (:class:`flywheel.linkage.output_link.OutputLink`) as a
person reads it: a short section of the записка and of `flywheel check` — the extreme
positions, the swing or stroke, the time ratio K and the least transmission angle. Formatting
only; numbers as the rest of the record and of `check` print them (decimal point in both
languages, as tests/render/test_messages.py holds for `check`)."""
from __future__ import annotations

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.numbers import fmt

W = words("output_link", {
    "title": "Output link {link} ({kind}): extreme positions, time ratio, transmission angle",
    "kind": {"rocker": "rocker", "slotted link": "slotted link", "slider": "slider"},
    "extreme": "extreme position", "output_angle": "angle of the link", "output_x": "x along the guide",
    "caption": "Extreme positions of the output link {link}",
    # a machine its given forces drive (an engine: balance "resistance"): the crank is its
    # output, the last group's slider the piston its gas drives, not an output link
    "title_driven": "Link {link} of the last group ({kind}): extreme positions, time ratio, "
                    "transmission angle",
    "caption_driven": "Extreme positions of link {link}",
    "swing": "swing of the rocker {sym} = {v}°",
    "swing_slotted": "swing of the slotted link {sym} = {v}°",
    "stroke": "stroke of the slider {sym} = {v} {u}",
    "strokes": ("working stroke {w}°, return stroke {r}° of the crank (the slower stroke taken as "
                "the working one): {sym} = {w}/{r} = {K}"),
    "no_ratio": "{n} extreme positions in a revolution: no time ratio",
    "gamma": "least transmission angle {sym} = {v}° at φ = {phi}°",
    "gamma_const": "transmission angle {sym} = {v}° in every position",
    "note": ("Extreme positions where the output's velocity analogue vanishes (found by "
             "bisection); transmission angle: the acute angle between the force the group "
             "passes to the output link and that link's velocity, 90° minus the pressure angle."),
    "note_driven": ("Extreme positions where the link's velocity analogue vanishes (found by "
                    "bisection); transmission angle: the acute angle between the force the "
                    "group passes to the link and that link's velocity, 90° minus the pressure "
                    "angle."),
})


def _n(x: float, lang: str, digits: int = 6) -> str:
    """A number to ``digits`` significant digits (``lang``: kept for a later decimal comma)."""
    return fmt(x, digits, zero=1e-12)


def title(ol, lang: str, driven: bool = False) -> str:
    """The section's title; ``driven``: the machine's given forces drive it (an engine), so
    that the crank is its output and the link is not called so."""
    w = W[lang]
    return w["title_driven" if driven else "title"].format(link=ol.link, kind=w["kind"][ol.kind])


def table(ol, lang: str, driven: bool = False) -> tuple[str, list[str], list[list[str]]]:
    """(caption, header, rows): each extreme's crank angle and the output's angle or x
    (``driven``: as :func:`title`)."""
    w = W[lang]
    value = (nm.heading("x", lang, label=w["output_x"]) if ol.kind == "slider" else
             f"{w['output_angle']}, °" if lang == "ru" else f"{w['output_angle']} [deg]")
    header = [w["extreme"], nm.heading("phi_deg", lang), value]
    rows = [[str(i), _n(p, lang, 8), _n(v, lang, 6)]
            for i, (p, v) in enumerate(zip(ol.extremes_phi_deg, ol.extremes_output), 1)]
    return w["caption_driven" if driven else "caption"].format(link=ol.link), header, rows


def lines(ol, lang: str) -> list[str]:
    """The swing or stroke, the strokes' crank angles and K, the least transmission angle."""
    w = W[lang]
    swing = w["swing_slotted" if ol.kind == "slotted link" else "swing"]
    out = [swing.format(sym=nm.symbol("swing_deg", lang), v=_n(ol.swing_deg, lang))
           if ol.stroke is None else
           w["stroke"].format(sym=nm.symbol("output_stroke", lang), v=_n(ol.stroke, lang),
                              u=nm.unit_of("output_stroke", lang))]
    if ol.time_ratio_K is None:
        out.append(w["no_ratio"].format(n=len(ol.extremes_phi_deg)))
    else:
        out.append(w["strokes"].format(w=_n(ol.strokes_deg[0], lang), r=_n(ol.strokes_deg[1], lang),
                                       sym=nm.symbol("time_ratio_K", lang),
                                       K=_n(ol.time_ratio_K, lang)))
    sym = nm.symbol("transmission_angle_min_deg", lang)
    v = _n(ol.transmission_angle_min_deg, lang)
    out.append(w["gamma_const"].format(sym="γ", v=v) if ol.phi_transmission_angle_min_deg is None
               else w["gamma"].format(sym=sym, v=v, phi=_n(ol.phi_transmission_angle_min_deg, lang)))
    return out


def add_report_section(b, ol, lang: str, number: str, driven: bool = False) -> None:
    """The record's section ``number`` (a sub-section of the kinematics) into the builder ``b``
    of :mod:`flywheel.render.document` (``driven``: as :func:`title`)."""
    from flywheel.render.blocks import Bullets, Heading, Paragraph

    b.add(Heading(3, f"{number}. {title(ol, lang, driven)}"))
    b.add(Paragraph(W[lang]["note_driven" if driven else "note"]))
    caption, header, rows = table(ol, lang, driven)
    b.table(caption, header, rows)
    b.add(Bullets(tuple(lines(ol, lang))))


def print_check(ol, console, lang: str, driven: bool = False) -> None:
    """The section of `flywheel check` (rich; ``driven``: as :func:`title`)."""
    from rich.markup import escape
    from rich.table import Table

    caption, header, rows = table(ol, lang, driven)
    t = Table(title=escape(title(ol, lang, driven)))
    for i, col in enumerate(header):
        t.add_column(escape(col), justify="left" if i == 0 else "right")
    for r in rows:
        t.add_row(*r)
    console.print(t)
    for line in lines(ol, lang):
        console.print(line, markup=False)
