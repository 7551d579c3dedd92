"""`flywheel aggregate` output: the JSON document, the rich summary and the plots against time.

Renderers compute no physics: they format a :class:`flywheel.elastic.model.AggregateResult` (its
JSON document is the result's own :meth:`~flywheel.elastic.model.AggregateResult.to_document`).
rich and matplotlib are imported inside the functions that use them. Every text handed to rich
goes through :func:`rich.markup.escape`: units in square brackets ("[kg·m²]", "[rad/s]") and
"[motor]" would otherwise be taken for markup tags and vanish.

Sign convention of the elastic moment: the twist is q2 = φ2 − φ1 (seed 003), negative while the
motor drives the machine; the moment the coupling transmits is c·(φ1 − φ2) = −c·q2, positive
(its mean is M_0·i31). Amplitudes are the same for c·q2 and −c·q2.
"""
from __future__ import annotations

import math

TWO_PI = 2.0 * math.pi
RPM = 30.0 / math.pi  # rad/s → rev/min


def to_json(r, title: str = "", source: str = "") -> str:
    """The result's document as JSON text; a non-finite number is a ValueError (JSON has no NaN
    or Infinity; the command refuses such a result before it gets here)."""
    import json

    return json.dumps(r.to_document(title, source), indent=2, ensure_ascii=False, allow_nan=False)


def _g(x, fmt: str = ".6g") -> str:
    if x is None:
        return "—"
    return format(0.0 if abs(x) < 1e-300 else float(x), fmt)


def _matrix(name: str, m, unit: str):
    from rich.markup import escape
    from rich.table import Table

    n = m.shape[0]
    t = Table(title=escape(f"{name} [{unit}]"))
    t.add_column("")
    for j in range(n):
        t.add_column(f"j = {j + 1}", justify="right")
    for i in range(n):
        t.add_row(f"i = {i + 1}", *(_g(m[i, j]) for j in range(n)))
    return t


def print_summary(r, title: str = "", source: str = "", console=None) -> None:
    """Coefficients, natural frequencies, resonance margins and the steady state."""
    from rich.console import Console
    from rich.markup import escape as e
    from rich.table import Table

    def table(title, columns):
        t = Table(title=e(title))
        for col in columns:
            t.add_column(e(col))
        return t

    def row(t, *cells):
        t.add_row(*(e(str(x)) for x in cells))

    console = console or Console()
    if title:
        console.print(f"[bold]{e(title)}[/bold]" + (f"  ({e(source)})" if source else ""))
    ch = r.chain
    t = table("Rotors reduced to shaft I (J·u², u = ω/ω_I)", ("#", "rotor", "J_reduced [kg·m²]", "u"))
    for k, (n, j, u) in enumerate(zip(ch.names, ch.J, ch.ratio)):
        row(t, k + 1, n, _g(j), _g(u))
    console.print(t)
    t = table("Connections reduced to shaft I (c·u²)",
              ("#", "between", "c [N·m/rad]", "damping [N·m·s/rad]"))
    for k, (c, b) in enumerate(zip(ch.c, ch.damping)):
        row(t, k + 1, f"{ch.names[k]} – {ch.names[k + 1]}", _g(c), _g(b))
    console.print(t)
    console.print(e("Equations (9.24): Σ_j a_ij·q̈_j + Σ_j c_ij·q_j = Q_i, "
                    "q1 = φ1, q_(k+1) = φ_(k+1) − φ_k"))
    console.print(_matrix("inertia coefficients a_ij", r.a, "kg·m²"))
    console.print(_matrix("stiffness coefficients c_ij", r.c, "N·m/rad"))

    t = table("Natural frequencies (K·x = ω²·M·x)", ("mode", "ω [rad/s]", "f [Hz]",
                                                    "shape (φ, largest = 1)"))
    for k, w in enumerate(r.modes.omega):
        shape = ", ".join(_g(x, ".4g") for x in r.modes.shapes[:, k])
        row(t, "rigid body" if k == 0 else k, _g(w), _g(w / TWO_PI), shape)
    console.print(t)
    st = r.steady
    if st is None:
        console.print(e("no [motor]: natural frequencies only"))
        return
    console.print(e(f"forcing ω_III = {_g(st.omega_forcing)} rad/s ({_g(st.omega_forcing / TWO_PI)} "
                    f"Hz) at the steady speed ω_I = {_g(st.omega_mean)} rad/s "
                    f"({_g(st.omega_mean * RPM)} rev/min)"))
    t = table("Resonance margins", ("mode", "f_n [Hz]", "ω_forcing/ω_n", "margin |1 − ω_f/ω_n|"))
    for k, x in enumerate(r.resonance):
        row(t, k + 1, _g(x.omega_n / TWO_PI), _g(x.ratio, ".4f"), _g(x.margin, ".4f"))
    console.print(t)
    t = table("Steady state (closed form; solve_ivp check on the periodic orbit)",
              ("quantity", "value", "unit", "solve_ivp"))
    u_last = float(ch.ratio[-1])
    row(t, "twist q2 = φ2 − φ1, mean", _g(st.twist_mean[0]), "rad", "")
    row(t, "twist q2, amplitude", _g(st.twist_amplitude[0]), "rad", _g(r.check_twist_amplitude))
    row(t, "elastic moment c·(φ1 − φ2) = −c·q2, mean", _g(st.moment_mean[0]), "N·m", "")
    row(t, "elastic moment −c·q2, amplitude", _g(st.moment_amplitude[0]), "N·m", "")
    row(t, "ω1 (motor) min … max", f"{_g(st.omega_mean - st.omega_amplitude[0])} … "
        f"{_g(st.omega_mean + st.omega_amplitude[0])}", "rad/s", "")
    row(t, "δ motor", _g(st.delta[0]), "", _g(r.check_delta[0] if r.check_delta else None))
    row(t, "ω2 (machine, own shaft) min … max",
        f"{_g((st.omega_mean - st.omega_amplitude[-1]) * u_last)} … "
        f"{_g((st.omega_mean + st.omega_amplitude[-1]) * u_last)}", "rad/s", "")
    row(t, "δ machine", _g(st.delta[-1]), "", _g(r.check_delta[1] if r.check_delta else None))
    if r.startup is not None:
        row(t, "start-up: peak elastic moment", _g(r.startup_peak_moment), "N·m",
            f"over {_g(r.startup.t[-1], '.4g')} s")
        if r.startup_time is not None:
            row(t, "start-up: time to 95 % of ω1", _g(r.startup_time), "s", "")
    console.print(t)
    for note in r.notes:
        console.print(e(f"note: {note}"))


def plot(r, path, title: str = "") -> None:
    """Speeds and the elastic moment against time: start-up and steady state (2×2 panels)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ch = r.chain
    fig, axes = plt.subplots(2, 2, figsize=(11, 7))
    for col, (h, name) in enumerate(((r.startup, "start-up"), (r.check, "steady state"))):
        ax = axes[0, col]
        ax.plot(h.t, h.omega[0], label=f"ω1, {ch.names[0]}")
        ax.plot(h.t, h.omega[-1], label=f"ω{ch.n}, {ch.names[-1]} (reduced to shaft I)")
        ax.set_ylabel("ω [rad/s]")
        ax.set_title(name)
        ax.legend(fontsize=8)
        ax = axes[1, col]
        ax.plot(h.t, -ch.c[0] * h.twist[0], color="tab:red",
                label="elastic moment c·(φ1 − φ2) = −c·q2")
        ax.set_ylabel("moment [N·m]")
        ax.set_xlabel("t [s]")
        ax.legend(fontsize=8)
    for ax in axes.flat:
        ax.grid(True, alpha=0.3)
    fig.suptitle(title or "machine aggregate")
    fig.tight_layout()
    from pathlib import Path

    png = Path(path).suffix.lower() == ".png"
    fig.savefig(path, dpi=100, **({"metadata": {"Software": None}} if png else {}))
    plt.close(fig)
