"""Structure (not pixels) of the energy–mass, time-law and transient plots."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.render import nomenclature as nm
from flywheel.render import plots_extra

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.fixture(scope="module")
def results():
    return analyze(load_case(CASES / "compressor.toml"), n_points=720, transients=True)


def _by_gid(ax, gid):
    (line,) = [ln for ln in ax.get_lines() if ln.get_gid() == gid]
    return line


def _check_energy_mass(results, lang="en"):
    """The construction of Wittenbauer's diagram as course projects draw it (structure, not
    pixels): the curve, the two tangents touching it from above and below, extended leftwards
    until they meet at (−J_I, −T0) — the origin of the full-energy axes, marked — and the
    dimension J_I from there to J_II = 0; the enlarged curve; Merzalov's ΔT_I beside it."""
    s = results.scalars
    fig = plots_extra.figure_energy_mass(results, lang)
    t = plots_extra.TEXT[lang]
    J_axis, T_axis = nm.axis("J_II", lang), plots_extra._f(t, "T", u=nm.unit_of("A", lang))
    axes = {a.get_label(): a for a in fig.axes}
    assert set(axes) == {"full", "zoom", "merzalov"}
    full, zoom, merz = axes["full"], axes["zoom"], axes["merzalov"]
    assert full.get_xlabel() == J_axis and full.get_ylabel() == T_axis == zoom.get_ylabel()
    curve, tmax, tmin, origin = (_by_gid(full, g) for g in ("curve", "tangent_max", "tangent_min", "origin"))
    labels = [x.get_text() for x in full.get_legend().get_texts()]
    assert any(r"\psi_{max}" in x for x in labels) and any(r"\psi_{min}" in x for x in labels)
    assert plots_extra._f(t, "origin", J="$J_I$", T="$T_0$") in labels
    J, A = curve.get_xdata(), curve.get_ydata()
    (x0, x1), (a0, a1) = tmax.get_xdata(), tmax.get_ydata()
    (y0, y1), (b0, b1) = tmin.get_xdata(), tmin.get_ydata()
    k_max, k_min = (a1 - a0) / (x1 - x0), (b1 - b0) / (y1 - y0)
    w_m, d = s.omega_mean, s.delta
    assert k_max == pytest.approx(w_m**2 * (1 + d / 2) ** 2 / 2, rel=1e-9)
    assert k_min == pytest.approx(w_m**2 * (1 - d / 2) ** 2 / 2, rel=1e-9)
    # the tangents touch the curve from above and below
    for k, xa, ya, side in ((k_max, x0, a0, 1), (k_min, y0, b0, -1)):
        gap = side * (ya + k * (J - xa) - A)
        assert gap.min() == pytest.approx(0, abs=1e-9 * np.ptp(A))
    # they meet at J_II = −J_I (exact): the origin of the full-energy axes, drawn there
    x_meet = ((b0 - k_min * y0) - (a0 - k_max * x0)) / (k_max - k_min)
    assert x_meet == pytest.approx(-s.J_required_exact, rel=1e-6)
    assert origin.get_xdata()[0] == pytest.approx(-s.J_required_exact, rel=1e-6)
    assert origin.get_ydata()[0] == pytest.approx(a0 + k_max * (x_meet - x0), rel=1e-6)
    assert min(x0, y0) <= x_meet * (1 - 1e-9)           # drawn all the way to it
    # the dimension arrow J_I from the meeting point to J_II = 0, and its label
    dims = [a for a in full.texts if getattr(a, "arrow_patch", None) is not None
            and a.xy[0] == 0.0 and a.xyann[0] == pytest.approx(x_meet, rel=1e-6)]
    assert len(dims) == 1
    assert any(x.get_text().startswith(f"$J_I$ = {s.J_required_exact:.5g}") for x in full.texts)
    assert zoom.get_xlabel() == J_axis
    assert merz.get_xlabel() == nm.axis("phi_deg", lang) == (r"$\varphi$, °" if lang == "ru" else r"$\varphi$ [deg]")
    assert (r"$\Delta T_{нб}$" if lang == "ru" else r"$\Delta T_{max}$") in " ".join(x.get_text() for x in merz.get_legend().get_texts())


def test_energy_mass_diagram(results):
    _check_energy_mass(results)
    _check_energy_mass(results, "ru")


@pytest.mark.parametrize("lang, parts", [("en", ("(a)", "(b)", "(c)")),
                                         ("ru", ("а)", "б)", "в)"))])
def test_energy_mass_diagram_names_its_parts_in_the_figures_language(results, lang, parts):
    """ГОСТ 2.105: a figure's parts are а), б), в) in Russian (Cyrillic letters), (a), (b), (c)
    in English; the whole construction marks where part b enlarges it."""
    from flywheel.render.figure import drawn

    fig = drawn(lambda: plots_extra.figure_energy_mass(results, lang))
    titles = [ax.get_title() for ax in fig.axes if ax.get_title()]
    assert [t.split(" ", 1)[0] for t in titles] == list(parts)
    marks = [t.get_text() for t in fig.axes[0].texts]
    assert parts[1] in marks
    assert all(ord(c) < 0x80 or c in "абв" for t in titles for c in t.split(" ", 1)[0])


@pytest.mark.parametrize("name", ["press.toml", "fourbar.toml"])
def test_energy_mass_diagram_other_cases(name):
    _check_energy_mass(analyze(load_case(CASES / name), n_points=360))


def test_energy_mass_diagram_constant_inertia():
    """No second-group masses: J_II ≡ 0, the curve is a segment on the ΔT axis."""
    from flywheel.cases.run import parse_case

    case = parse_case({
        "title": "constant inertia", "machine": {"speed_rpm": 600.0, "delta": 0.04, "gravity": [0.0, 0.0]},
        "crank": {"length": 0.05},
        "dyads": [{"kind": "RRP", "from": "A", "joint": "B", "rod": "2", "rod_length": 0.2,
                   "slider": "3", "guide": {"angle_deg": 0.0}}],
        "cylinders": [{"name": "c", "piston": "3", "bore": 0.1, "p_max": 1e6, "s": [0.0, 1.0],
                       "towards_head": [1.0, 1.0], "away_from_head": [0.0, 0.0]}]})
    _check_energy_mass(analyze(case, n_points=360))


def test_transients_plot_marks_the_steady_state(results):
    st = results.scalars.time_domain.startup
    fig = plots_extra.figure_transients(results)
    (ax,) = fig.axes
    labels = " ".join(x.get_text() for x in ax.get_legend().get_texts())
    assert rf"$\omega_s$ = {st.omega_final_predicted:.5g}" in labels
    assert f"{st.time_to_steady:.4g}" in labels


def test_time_law(results):
    fig = plots_extra.figure_time_law(results, lang="ru")
    assert [a.get_ylabel() for a in fig.axes] == [r"$\omega$, рад/с", r"$\varepsilon$, рад/с²"]
    assert fig.axes[1].get_xlabel() == "$t$, с"


def test_time_law_and_transients_written_with_every_figure(results, tmp_path):
    from flywheel.render import plots

    paths = plots.write_plots(results, tmp_path)          # with the worksheet's plots
    assert [p.name for p in paths][-3:] == ["energy_mass.png", "time_law.png", "transients.png"]
    assert all(p.read_bytes().startswith(b"\x89PNG") for p in paths)


def _dense(xy: np.ndarray, step: float = 0.5) -> np.ndarray:
    """The polyline ``xy`` (display pixels) sampled every ``step`` px along each piece."""
    out = [xy[:1]]
    for a, b in zip(xy[:-1], xy[1:]):
        n = max(1, int(np.hypot(*(b - a)) / step))
        out.append(a + (b - a) * (np.arange(1, n + 1) / n)[:, None])
    return np.concatenate(out)


@pytest.mark.parametrize("name, lang", [("compressor.toml", "en"), ("shaper.toml", "ru"),
                                        ("press.toml", "ru"), ("engine_inline4.toml", "en")])
def test_energy_mass_tangency_angles_clear_of_the_curve_and_tangents(name, lang):
    """Part (b)'s two angles φ (the points of tangency) are placed by the label placer once
    the panels have their final places: in the saved figure each lies inside its panel, off
    the curve, off both tangents and off the other (each had been set at a fixed offset: over
    the curve in three of five bundled cases, over the panel's frame in two)."""
    import io

    from flywheel.render import figure as fg

    res = analyze(load_case(CASES / name), n_points=720)
    with fg.style(lang):
        fig = plots_extra.figure_energy_mass(res, lang)
        fg.save(fig, io.BytesIO())                     # laid out and drawn as a run draws it
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        renderer = FigureCanvasAgg(fig).get_renderer()
        zoom = next(a for a in fig.axes if a.get_label() == "zoom")
        angles = [t for t in zoom.texts if t.get_text().startswith("φ = ")]
        assert len(angles) == 2
        frame = zoom.get_window_extent(renderer)
        boxes = [t.get_window_extent(renderer) for t in angles]
        lines = [ln for ln in zoom.get_lines() if len(ln.get_xdata()) > 1]
        assert len(lines) == 3                         # the curve and the two tangents
        points = np.concatenate([_dense(zoom.transData.transform(
            np.column_stack([ln.get_xdata(), ln.get_ydata()]))) for ln in lines])
    for box in boxes:
        assert frame.x0 <= box.x0 and box.x1 <= frame.x1
        assert frame.y0 <= box.y0 and box.y1 <= frame.y1
        inside = ((points[:, 0] > box.x0 + 0.5) & (points[:, 0] < box.x1 - 0.5)
                  & (points[:, 1] > box.y0 + 0.5) & (points[:, 1] < box.y1 - 0.5))
        assert not inside.any()
    assert not boxes[0].overlaps(boxes[1])


@pytest.mark.parametrize("name", ["engine_measured.toml", "compressor.toml", "pump.toml"])
def test_energy_mass_tick_labels_do_not_run_together(name):
    """Every panel's tick labels stand apart in the saved figure (the engine's part b had
    run seven of them together, «0,00060,00080,0010…», in its half-width panel)."""
    import io

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg

    res = analyze(load_case(CASES / name), n_points=720)
    with fg.style("ru"):
        fig = plots_extra.figure_energy_mass(res, "ru")
        fg.save(fig, io.BytesIO())
        renderer = FigureCanvasAgg(fig).get_renderer()
        for ax in fig.axes:
            for axis in (ax.xaxis, ax.yaxis):
                boxes = [t.get_window_extent(renderer) for t in axis.get_ticklabels()
                         if t.get_visible() and t.get_text()]
                for a, b in zip(boxes, boxes[1:]):
                    assert not a.overlaps(b), (ax.get_label(), a, b)


@pytest.mark.parametrize("case, lang, names", [
    ("shaper.toml", "ru", ("epsilon.png", "time_law.png", "energy_mass.png")),
    ("engine_inline4.toml", "ru", ("indicator_1.png",)),
    ("compressor_worksheet.toml", "ru", ("indicator_HP.png", "time_law.png"))])
def test_a_long_case_title_is_broken_inside_the_figure(case, lang, names):
    """A case whose title is long (the shaper's, the worksheet compressor's in Russian) has its
    figures' headings broken into lines that stay inside the figure; they ran past both edges
    (a title's line count estimated with mathtext's markup, "$\\varepsilon$", as letters; the
    headings of the constrained-layout figures and the indicators never broken)."""
    import io

    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots

    res = analyze(load_case(CASES / case), n_points=360)
    specs = dict(plots.all_figures(res, lang))
    for name in names:
        with fg.style(lang):
            fig = specs[name]()
            fg.save(fig, io.BytesIO())
            renderer = FigureCanvasAgg(fig).get_renderer()
            width = fig.bbox.width
            heads = [fig._suptitle] + [ax.title for ax in fig.axes]
            for text in (t for t in heads if t is not None and t.get_text()):
                box = text.get_window_extent(renderer)
                assert 0.0 <= box.x0 and box.x1 <= width, (name, text.get_text())
