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

from flywheel.render import nomenclature as nm
from flywheel.render.numbers import fmt as _number, separator
from flywheel.units import RPM_PER_RAD_S, TWO_PI


def to_json(r, title: str = "", source: str = "") -> str:
    """The result's document as JSON text; a non-finite number is a ValueError (JSON has no NaN
    or Infinity; the command refuses such a result before it gets here)."""
    import json

    return json.dumps(r.to_document(title, source), indent=2, ensure_ascii=False, allow_nan=False)


def _g(x, fmt: str = ".6g") -> str:
    return _number(x, spec=fmt, zero=1e-300, nonfinite="show")


def _matrix(name: str, m, unit: str, lang: str = "en"):
    from rich.markup import escape
    from rich.table import Table

    n = m.shape[0]
    t = Table(title=escape(f"{name}, {unit}" if lang == "ru" else f"{name} [{unit}]"))
    t.add_column("")
    for j in range(n):
        t.add_column(nm.name("matrix_j", lang, j=j + 1), justify="right")
    for i in range(n):
        t.add_row(nm.name("matrix_i", lang, i=i + 1), *(_g(m[i, j]) for j in range(n)))
    return t


def print_summary(r, title: str = "", source: str = "", console=None, lang: str = "en",
                  modes: bool = False) -> None:
    """Coefficients, natural frequencies, resonance margins and the steady state; labels,
    symbols and units in ``lang`` (en, ru: :mod:`flywheel.render.nomenclature`). ``modes``
    adds every mode's frequency in Hz and rpm with its nodes, and the shafts' equivalent
    lengths."""
    from rich.console import Console
    from rich.markup import escape as e
    from rich.table import Table

    def L(key: str, **fields) -> str:
        return nm.name(key, lang, **fields)

    def U(u: str) -> str:
        return nm.unit(u, lang)

    def table(title, columns):
        t = Table(title=e(title))
        for col in columns:
            t.add_column(e(col))
        return t

    def row(t, *cells):
        t.add_row(*(e(str(x)) for x in cells))

    console = console or Console()
    if title:
        from flywheel.io.text import cut_end   # a long title or source cut with «…»

        console.print(f"[bold]{e(cut_end(title))}[/bold]"
                      + (f"  ({e(cut_end(source))})" if source else ""))
    ch = r.chain
    names = [nm.rotor_name(n, lang) for n in ch.names]
    t = table(L("ag_rotors"), (L("row_no"), L("rotor"), L("J_reduced"), L("u")))
    for k, (n, j, u) in enumerate(zip(names, ch.J, ch.ratio)):
        row(t, k + 1, n, _g(j), _g(u))
    console.print(t)
    t = table(L("ag_connections"), (L("row_no"), L("between"), L("c"), L("damping")))
    for k, (c, b, (i, j)) in enumerate(zip(ch.c, ch.damping, ch.pairs)):
        row(t, k + 1, f"{names[i]} – {names[j]}", _g(c), _g(b))
    if ch.fixed:
        k = len(ch.c)
        for line in ch.lines:
            if min(line.ends) < 0:
                k += 1
                a, b = (nm.rotor_name(n, lang) for n in line.names)
                row(t, k, f"{a} – {b} ({L('frame')})", _g(line.c_input * _u_in(ch, line) ** 2),
                    _g(0.0))
    console.print(t)
    console.print(e(L("ag_equations_fixed" if ch.fixed else
                      "ag_equations" if ch.ends is None else "ag_equations_tree")))
    console.print(_matrix(L("a_ij"), r.a, U("kg·m²"), lang))
    console.print(_matrix(L("c_ij"), r.c, U("N·m/rad"), lang))

    t = table(L("ag_modes"), (L("mode"), L("omega_n"), L("f_n"), L("shape")))
    rigid = r.modes.rigid
    for k, w in enumerate(r.modes.omega):
        shape = separator(lang).join(_g(x, ".4g") for x in r.modes.shapes[:, k])
        row(t, L("rigid_body") if k < rigid else k - rigid + 1, _g(w), _g(w / TWO_PI), shape)
    console.print(t)
    if modes:
        _print_modes(r, console, lang)
    st = r.steady
    if st is None:
        console.print(e(L("ag_no_motor")))
        return
    console.print(e(L("ag_forcing", w=_g(st.omega_forcing), f=_g(st.omega_forcing / TWO_PI),
                      omega=_g(st.omega_mean), n=_g(st.omega_mean * RPM_PER_RAD_S))))
    t = table(L("ag_resonance"), (L("mode"), L("f_n_col"), L("ratio"), L("margin")))
    for k, x in enumerate(r.resonance):
        row(t, k + 1, _g(x.omega_n / TWO_PI), _g(x.ratio, ".4f"), _g(x.margin, ".4f"))
    console.print(t)
    t = table(L("ag_steady"), (L("quantity"), L("value"), L("unit"), L("solve_ivp")))
    u_last = float(ch.ratio[-1])
    row(t, L("twist_mean"), _g(st.twist_mean[0]), U("rad"), "")
    row(t, L("twist_amp"), _g(st.twist_amplitude[0]), U("rad"), _g(r.check_twist_amplitude))
    row(t, L("moment_mean"), _g(st.moment_mean[0]), U("N·m"), "")
    row(t, L("moment_amp"), _g(st.moment_amplitude[0]), U("N·m"), "")
    row(t, L("omega_motor"), f"{_g(st.omega_mean - st.omega_amplitude[0])} … "
        f"{_g(st.omega_mean + st.omega_amplitude[0])}", U("rad/s"), "")
    row(t, L("delta_motor"), _g(st.delta[0]), "", _g(r.check_delta[0] if r.check_delta else None))
    row(t, L("omega_machine"),
        f"{_g((st.omega_mean - st.omega_amplitude[-1]) * u_last)} … "
        f"{_g((st.omega_mean + st.omega_amplitude[-1]) * u_last)}", U("rad/s"), "")
    row(t, L("delta_machine"), _g(st.delta[-1]), "",
        _g(r.check_delta[1] if r.check_delta else None))
    if r.startup is not None:
        row(t, L("startup_peak"), _g(r.startup_peak_moment), U("N·m"),
            L("startup_over", t=_g(r.startup.t[-1], '.4g')))
        if r.startup_time is not None:
            row(t, L("startup_time"), _g(r.startup_time), U("s"), "")
    console.print(t)
    for note in r.notes:
        console.print(e(L("note", note=L(f"note_{note.kind}", **dict(note.values)))))


def _u_in(ch, line) -> float:
    """The speed ratio of a shaft's input (``from``) end: its rotor's, or for a fixed ``from``
    end the other rotor's over the gear ratio."""
    if line.ends[0] >= 0:
        return float(ch.ratio[line.ends[0]])
    return float(ch.ratio[line.ends[1]]) / line.gear


def _node_text(node, lang: str) -> str:
    if node.rotor is not None:
        return nm.name("node_rotor", lang, name=nm.rotor_name(node.rotor, lang))
    a, b = (nm.rotor_name(n, lang) for n in node.between)
    dist = "" if node.distance is None else nm.name("node_dist", lang, d=_g(node.distance), a=a)
    return nm.name("node_shaft", lang, a=a, b=b, dist=dist, frac=_g(100 * node.fraction, ".4g"))


def _print_modes(r, console, lang: str) -> None:
    """Every torsional mode's frequency (Hz, vibrations per minute) and nodes; the shafts'
    stiffness, length and equivalent length. All from the result."""
    from rich.markup import escape as e
    from rich.table import Table

    def L(key: str, **fields) -> str:
        return nm.name(key, lang, **fields)

    ch = r.chain
    frames = set(ch.frames)
    t = Table(title=e(L("ag_mode_nodes")))
    for col in (L("mode"), L("f_n"), L("rpm_col"), L("nodes")):
        t.add_column(e(col))
    for k, (w, nodes) in enumerate(zip(r.modes.elastic, r.nodes)):
        parts = []
        for node in nodes:
            if node.between is not None and (set(node.between) & frames):
                name = next(n for n in node.between if n in frames)
                parts.append(L("node_frame", name=nm.rotor_name(name, lang)))
            else:
                parts.append(_node_text(node, lang))
        t.add_row(str(k + 1), e(_g(w / TWO_PI)), e(_g(w * RPM_PER_RAD_S)), e("; ".join(parts) or "—"))
    console.print(t)
    t = Table(title=e(L("ag_shafts")))
    for col in (L("row_no"), L("between"), L("gear_ratio"), L("c_input"), L("length"),
                L("equivalent_length"), L("d_ref")):
        t.add_column(e(col))
    for line in ch.lines:
        a, b = (nm.rotor_name(n, lang) for n in line.names)
        t.add_row(str(line.index + 1), e(f"{a} – {b}"), e(_g(line.gear)), e(_g(line.c_input)),
                  e(_g(line.total_length)), e(_g(line.equivalent_length)), e(_g(line.d_ref)))
    console.print(t)


def plot(r, path, title: str = "", lang: str = "en") -> None:
    """Speeds and the elastic moment against time: start-up and steady state (2×2 panels; a
    pyplot-free figure in render/figure.py's fixed style, constrained layout, legends inside);
    labels in ``lang``, symbols' subscripts as mathtext (mathfmt.sub_mathtext)."""
    from pathlib import Path

    import matplotlib
    from matplotlib.figure import Figure

    from flywheel.render import figure as fg
    import textwrap

    from flywheel.render.figure import SVG_SALT, stable_metadata
    from flywheel.render.mathfmt import sub_mathtext

    def L(key: str, **fields) -> str:
        return sub_mathtext(nm.name(key, lang, **fields))

    ch = r.chain
    names = [nm.rotor_name(n, lang) for n in ch.names]
    with fg.style(lang):
        fig = Figure(figsize=(7.45, 6.4), dpi=100, layout="constrained")
        axes = fig.subplots(2, 2)
        for col, (h, name) in enumerate(((r.startup, L("ag_plot_startup")),
                                         (r.check, L("ag_plot_steady")))):
            ax = axes[0, col]
            ax.plot(h.t, h.omega[0], label=L("ag_plot_omega1", name=names[0]))
            ax.plot(h.t, h.omega[-1], label=L("ag_plot_omegaN", n=ch.n, name=names[-1]))
            ax.set_ylabel(L("ag_plot_omega_axis"))
            ax.set_title(name)
            ax = axes[1, col]
            ax.plot(h.t, -ch.c[0] * h.twist[0], color="tab:red", label=L("ag_plot_moment"))
            ax.set_ylabel(L("ag_plot_moment_axis"))
            ax.set_xlabel(L("ag_plot_t_axis"))
        for ax in axes.flat:
            ax.grid(True, alpha=0.3)
        # one legend for the four panels, below them: the steady state's curves fill their axes
        handles = axes[0, 0].get_lines() + axes[1, 0].get_lines()
        fig.legend(handles=handles, loc="outside lower center", ncols=len(handles), fontsize=8)
        # a long title broken at spaces to the A4 figure's width (about 75 characters a line)
        fig.suptitle(textwrap.fill(title or L("ag_plot_title"), 75))
        fmt = Path(path).suffix.lower()[1:]
        kw = {"metadata": {"Software": None}} if fmt == "png" else stable_metadata(fmt)
        with matplotlib.rc_context({"svg.hashsalt": SVG_SALT}):  # SVG, PDF: same bytes on a rerun
            fig.savefig(path, dpi=100, **kw)
