"""`flywheel task2` output: the JSON text, the rich summary and the plot.

Renderers compute no physics: they format a :class:`flywheel.constant_inertia.solve.Task2Result`
(its JSON document is the result's own :meth:`~flywheel.constant_inertia.solve.Task2Result.to_document`).
rich and matplotlib are imported inside the functions that use them.
"""
from __future__ import annotations

import math

from flywheel.constant_inertia.solve import RPM


def to_dict(r, title: str = "", source: str = "") -> dict:
    """The result's JSON document, :meth:`~flywheel.constant_inertia.solve.Task2Result.to_document`."""
    return r.to_document(title, source)


def to_json(r, title: str = "", source: str = "") -> str:
    """The result's document as indented JSON text (byte-identical for the same input)."""
    import json

    return json.dumps(r.to_document(title, source), indent=2, ensure_ascii=False)


def _g(x: float | None, fmt: str = ".6g") -> str:
    if x is None or (isinstance(x, float) and math.isnan(x)):
        return "—"
    return format(0.0 if abs(x) < 1e-12 else x, fmt)


def _angle(phi: float | None) -> str:
    if phi is None or math.isnan(phi):
        return "(angle not given)"
    return f"φ = {_g(math.degrees(phi))}° ({_g(phi / math.pi)}π rad)"


def print_summary(r, title: str = "", source: str = "", console=None) -> None:
    """The segment table and the results, as the seed presents them, on a rich console."""
    from rich.console import Console
    from rich.table import Table

    console = console or Console()
    if title:
        from rich.markup import escape

        console.print(f"[bold]{escape(title)}[/bold]" + (f"  ({escape(source)})" if source else ""))
    if r.unknown:
        name = {"resistance": "M_C", "driving": "M_D"}[r.unknown]
        val = r.M_C if r.unknown == "resistance" else r.M_D
        console.print(f"cycle balance ∮M_D dφ = ∮M_C dφ gives {name} = {_g(val)} N·m "
                      f"(work per cycle {_g(r.work_driving)} J)")
    elif r.M_C is not None:
        console.print(f"M_D = {_g(r.M_D)} N·m, M_C = {_g(r.M_C)} N·m (given)")
    if not r.steady:
        console.print(f"[yellow]the motion is not steady:[/yellow] the work over the cycle is "
                      f"{r.work_end:.6g} J, so ω after one cycle is {_g(r.omega_end, '.6f')} "
                      f"rad/s (ω0 = {_g(r.omega0, '.6f')} rad/s)")

    t = Table(title="Segments: ½·J·(ω² − ω0²) = A(φ) = ∫(M_D − M_C) dφ\n"
                    "φ \\[deg], M \\[N·m], A \\[J], ω \\[rad/s]")
    for col, just in (("#", "right"), ("φ°", "right"), ("φ/π", "right"),
                      ("point", "left"), ("M_D", "right"), ("M_C", "right"),
                      ("A", "right"), ("ω", "right")):
        t.add_column(col, justify=just, no_wrap=True)
    for i, row in enumerate(r.rows):
        deg = None if math.isnan(row.phi) else math.degrees(row.phi)
        t.add_row(str(i), _g(deg), _g(None if math.isnan(row.phi) else row.phi / math.pi),
                  "M_D = M_C" if row.kind == "crossing" and row.M_D is not None else
                  ("crossing" if row.kind == "crossing" else "bound"),
                  _g(row.M_D), _g(row.M_C), _g(row.A), _g(row.omega, ".6f"))
    console.print(t)

    t = Table(title="Results")
    for col in ("quantity", "value", "unit", ""):
        t.add_column(col)
    t.add_row("J (reduced inertia)", _g(r.J), "kg·m²", "")
    t.add_row("ω0 (at φ = 0)", _g(r.omega0, ".6f"), "rad/s", f"{_g(r.omega0 * RPM)} rpm")
    t.add_row("ω_max", _g(r.omega_max, ".6f"), "rad/s",
              f"{_g(r.omega_max * RPM)} rpm at {_angle(r.phi_omega_max)}")
    t.add_row("ω_min", _g(r.omega_min, ".6f"), "rad/s",
              f"{_g(r.omega_min * RPM)} rpm at {_angle(r.phi_omega_min)}")
    t.add_row("ω_ср = (ω_max + ω_min)/2", _g(r.omega_mean, ".6f"), "rad/s",
              f"{_g(r.omega_mean * RPM)} rpm")
    t.add_row("δ = (ω_max − ω_min)/ω_ср", _g(r.delta), "", "")
    t.add_row("ΔT_нб = A_max − A_min", _g(r.delta_T_max), "J", "")
    if r.power is not None:
        t.add_row("power = mean M_D · ω_ср", _g(r.power), "W", "")
    if r.J_required is not None:
        t.add_row(f"J for δ = {_g(r.delta_target)}", _g(r.J_required), "kg·m²",
                  "ΔT_нб/(δ·ω_ср²)")
    if r.rim_mass is not None:
        t.add_row(f"rim mass at R = {_g(r.rim_radius)} m", _g(r.rim_mass), "kg", "m = J/R²")
    console.print(t)


def plot(r, path, title: str = "") -> None:
    """M_D, M_C, A and ω against φ [deg] into an image file (matplotlib, Agg backend)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from flywheel.constant_inertia.solve import sample

    if r.driving is not None:
        s = sample(r)
        x = [math.degrees(p) for p in s["phi"]]
        fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
        ax = axes[0]
        ax.plot(x, s["M_D"], label="M_D (driving)")
        ax.plot(x, s["M_C"], label="M_C (resistance)")
        ax.set_ylabel("moment [N·m]")
        ax.legend()
        axes[1].plot(x, s["A"], color="tab:green", label="A(φ) = ∫(M_D − M_C) dφ")
        axes[1].set_ylabel("A [J]")
        axes[1].legend()
        axes[2].plot(x, s["omega"], color="tab:red", label="ω(φ)")
    else:
        known = not math.isnan(r.rows[0].phi)
        x = [math.degrees(row.phi) if known else i for i, row in enumerate(r.rows)]
        fig, axes = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
        axes = [None, *axes]
        axes[1].plot(x, [row.A for row in r.rows], "o-", color="tab:green",
                     label="energy at the crossings")
        axes[1].set_ylabel("A [J]")
        axes[1].legend()
        axes[2].plot(x, [row.omega for row in r.rows], "o-", color="tab:red",
                     label="ω at the crossings")
    ax = axes[2]
    ax.axhline(r.omega_mean, color="grey", linestyle="--", linewidth=0.8, label="ω_ср")
    ax.set_ylabel("ω [rad/s]")
    ax.set_xlabel("φ [deg]" if r.driving is not None or not math.isnan(r.rows[0].phi)
                  else "crossing number")
    ax.legend()
    for a in axes:
        if a is not None:
            a.grid(True, alpha=0.3)
    fig.suptitle(title or f"task 2: δ = {r.delta:.6g}, ΔT_нб = {r.delta_T_max:.6g} J")
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)
