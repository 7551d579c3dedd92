"""`flywheel duty-cycle` output: the JSON document and the rich summary.

Renderers compute no physics: they format a :class:`flywheel.duty_cycle.solve.DutyCycleResult`
(by attribute). Every label comes from :mod:`flywheel.render.nomenclature`; this module
keeps only the sentence templates. rich is imported inside the function that prints; every text
handed to rich goes through :func:`rich.markup.escape`.
"""
from __future__ import annotations

import json

from flywheel.render import nomenclature as nm
from flywheel.render.catalogue import words
from flywheel.render.numbers import fmt as _number

L10N = words("duty_cycle", {
    "operation": "Operation", "motor": "Motor", "speeds": "Speeds of the flywheel shaft",
    "flywheel": "Flywheel", "rim": "Rim of the flywheel ([flywheel.rim])", "timing": "Time and angle of turn of each phase (one from the other at ω_m)",
    "checks": "Checks (identities; residuals)", "quantity": "quantity", "symbol": "symbol",
    "value": "value", "unit": "unit", "phase": "phase",
    "no_radius": "the radius is not given: J, ω and angles are unknown (speeds at the radius)",
    "shape": {"constant": "constant", "falling": "falling linearly to 0",
              "triangle": "triangle 0 → F_max → 0"},
})


def to_dict(r, title: str = "", source: str = "") -> dict:
    """The JSON document: ``title``, ``source`` and ``r.to_document()`` (SI units)."""
    d: dict = {}
    if title:
        d["title"] = title
    if source:
        d["source"] = source
    d.update(r.to_document())
    return d


def to_json(r, title: str = "", source: str = "") -> str:
    """``to_dict`` as indented JSON text (byte-identical for the same input); a non-finite number
    is a ValueError (JSON has no NaN or Infinity)."""
    return json.dumps(to_dict(r, title, source), indent=2, ensure_ascii=False, allow_nan=False)


def _g(x, digits: int = 6) -> str:
    if isinstance(x, str):
        return x
    return _number(x, digits, zero=1e-300, nonfinite="show")


def _rows(keys_values, lang: str) -> list[tuple[str, str, str, str]]:
    """(name, symbol, value, unit) of each (nomenclature key, value) whose value is known (the
    name without the symbol its own column prints)."""
    return [(nm.bare_name(k, lang), nm.symbol(k, lang), _g(v), nm.unit_of(k, lang))
            for k, v in keys_values if v is not None]


def summary_tables(r, lang: str = "en") -> list[tuple[str, tuple, list, str, tuple]]:
    """The summary's tables of the result ``r`` (its document, and its Work: how the work of
    an operation was found, None if E was given): (title, header, rows, a note after it or "",
    the columns' justification), empty tables included (the caller skips them). The rich
    summary and the записка (render/report_duty_cycle.py) print the same."""
    t = L10N[lang]
    head = (t["quantity"], t["symbol"], t["value"], t["unit"])
    just = ("left", "left", "right", "left")
    w = r.work

    def work(name: str):
        return None if w is None else getattr(w, name)
    shape = work("shape")
    out = [(t["operation"], head, _rows([
        ("sheared_area", work("sheared_area")), ("energy_per_area", work("energy_per_area")),
        ("force_max", work("force_max")), ("plate_thickness", work("thickness")),
        ("energy_per_operation", r.energy), ("delta_E", r.delta_E),
        ("energy_fluctuation_coefficient", r.energy_fluctuation_coefficient),
        ("operation_moment", r.operation_moment)], lang)
        + ([(nm.name("force_shape", lang), nm.symbol("force_shape", lang),
             t["shape"][shape], nm.unit_of("force_shape", lang))] if shape else []), "", just)]
    out.append((t["motor"], head, _rows([
        ("motor_power", r.motor_power),
        ("motor_efficiency", r.efficiency if r.efficiency != 1.0 else None),
        ("motor_input_power", r.motor_input_power if r.efficiency != 1.0 else None),
        ("motor_torque", r.motor_torque), ("mean_power", r.mean_power),
        ("operations_per_hour", r.operations_per_hour),
        ("operations_per_minute", r.operations_per_minute),
        ("revolutions_per_operation", r.revolutions_per_operation)], lang), "", just))
    out.append((t["speeds"], head, _rows([
        ("rpm_max", r.rpm_max), ("rpm_min", r.rpm_min), ("rpm_mean", r.rpm_mean),
        ("omega_max", r.omega_max), ("omega_min", r.omega_min),
        ("omega_mean", r.omega_mean),
        ("rim_speed_max", r.rim_speed_max), ("rim_speed_min", r.rim_speed_min),
        ("rim_speed_mean", r.rim_speed_mean), ("speed_fluctuation", r.delta)], lang), "",
        just))
    out.append((t["flywheel"], head, _rows([
        ("flywheel_J", r.J), ("flywheel_radius", r.radius), ("flywheel_mass", r.mass)],
        lang), t["no_radius"] if r.omega_max is None else "", just))
    if r.rim is not None:                # [flywheel.rim]: the rim designed as `run` designs it
        d = r.rim
        out.append((t["rim"], head, _rows([
            ("share", d.share), ("D_mean", d.D_mean), ("thickness", d.thickness),
            ("width", d.width), ("rim_area", d.area), ("rim_mass_designed", d.mass),
            ("rim_speed", d.rim_speed), ("stress", d.stress)], lang), "", just))
    if r.cycle_time is not None:
        rows = [(f"{nm.name(k, lang)} ({nm.symbol(k, lang)})", _g(time), _g(angle))
                for k, time, angle in (
                    ("operation_time", r.operation_time, r.operation_angle_deg),
                    ("recovery_time", r.recovery_time, r.recovery_angle_deg),
                    ("idle_time", r.idle_time, r.idle_angle_deg),
                    ("cycle_phase", r.cycle_time, r.cycle_angle_deg))]
        out.append((t["timing"], (t["phase"], *(f"{nm.symbol(k, lang)}, {nm.unit_of(k, lang)}"
                                                for k in ("phase_time", "phase_angle_deg"))),
                    rows, f"{nm.name('operation_share', lang)}: "
                          f"{nm.symbol('operation_share', lang)} = {_g(r.operation_share)}",
                    ("left", "right", "right")))
    return out


def print_summary(r, title: str = "", source: str = "", lang: str = "en", console=None) -> None:
    """The operation, motor, speeds, flywheel, timing and checks on a rich console."""
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = console or Console()
    t = L10N[lang]
    if title:
        from flywheel.io.text import cut_end   # a long title or source cut with «…»

        console.print(f"[bold]{escape(cut_end(title))}[/bold]"
                      + (f"  ({escape(cut_end(source))})" if source else ""))
    for head, columns, rows, note, just in summary_tables(r, lang):
        if rows:
            tab = Table(title=escape(head), title_justify="left")
            for col, j in zip(columns, just):
                tab.add_column(escape(col), justify=j)
            for row in rows:
                tab.add_row(*(escape(x) for x in row))
            console.print(tab)
        if note:
            console.print(escape(note))
    if r.checks:
        tab = Table(title=escape(t["checks"]), title_justify="left")
        tab.add_column(t["quantity"])
        tab.add_column(t["value"], justify="right")
        tab.add_column(t["unit"])
        for k, v in r.checks:
            tab.add_row(escape(nm.name(k, lang)), _number(v, spec=".1e", zero=None, nonfinite="show"),
                        nm.unit_of(k, lang))
        console.print(tab)
