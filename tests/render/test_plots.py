"""Plots: the files written, and the structure of each figure (lines, labels with units,
legends, titles), never pixels (style.md: python-control). The figures are pyplot-free
``matplotlib.figure.Figure`` objects; each test clears the ones it made."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import re

import pytest

from flywheel import analyze, load_case
from flywheel.render import figure as fg
from flywheel.render import plots

CASE = Path(__file__).resolve().parents[2] / "cases" / "compressor.toml"
EXPECTED = {
    "positions.png", "velocity_analogues.png", "acceleration_analogues.png", "J_II.png",
    "indicator_HP.png", "indicator_LP.png", "piston_forces.png", "reduced_moments.png",
    "works.png", "omega.png", "epsilon.png", "scheme.png", "energy_mass.png", "time_law.png",
    "reactions.png", "balancing_moment.png", "hodographs.png",      # the force analysis
    "plan_positions.png", "plan_velocity_120.png", "plan_acceleration_120.png",   # the plans
    "plan_forces_120.png", "plan_lever_120.png",
}


@pytest.fixture(scope="module")
def results():
    return analyze(load_case(CASE), n_points=720)


@pytest.fixture
def made():
    """Collects figures and clears them after the test."""
    figs = []
    yield figs.append
    for f in figs:
        f.clear()


def _legend_texts(fig) -> list[str]:
    out = []
    for leg in [ax.get_legend() for ax in fig.axes] + list(fig.legends):
        if leg is not None:
            out += [t.get_text() for t in leg.get_texts()]
    return out


def _data_axes(fig):
    """The visible axes that hold data (not secondary axes)."""
    return [ax for ax in fig.axes if ax.get_visible() and ax.lines]


def _check_common(fig, results, lang="en"):
    """A title naming the case, a y label with a unit on every plot, the φ or other x label
    with a unit on the bottom one, and a legend."""
    axes = _data_axes(fig)
    assert axes
    titles = [ax.get_title() for ax in axes] + [fig.get_suptitle()]
    assert any(results.title in t for t in titles)
    unit = r".+ \[[^\]]+\]|.+, \S+"       # "name [unit]" (English), "name, unit" (Russian)
    for ax in axes:
        assert re.fullmatch(unit, ax.get_ylabel()), ax.get_ylabel()
    assert any(re.fullmatch(unit, ax.get_xlabel()) for ax in axes)
    assert _legend_texts(fig)
    if lang == "ru":
        assert any(any("а" <= ch <= "я" for ch in t) for t in titles)


def _check_layout(fig):
    """Drawn once: every legend and every axes' labels lie inside the figure, and no legend
    covers the data area of any axes."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    r = canvas.get_renderer()
    box = fig.bbox
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    for leg in legends:
        lb = leg.get_window_extent(r)
        assert box.x0 - 1 <= lb.x0 and lb.x1 <= box.x1 + 1 and box.y0 - 1 <= lb.y0 and lb.y1 <= box.y1 + 1
        for ax in _data_axes(fig):
            assert not lb.overlaps(ax.get_window_extent(r)), "a legend covers an axes"
    for ax in fig.axes:
        if ax.get_visible():
            tb = ax.get_tightbbox(r)
            assert box.x0 - 1 <= tb.x0 and tb.x1 <= box.x1 + 1, ax.get_ylabel()
            assert box.y0 - 1 <= tb.y0 and tb.y1 <= box.y1 + 1, ax.get_xlabel()


# -- files ----------------------------------------------------------------------------------------
def test_write_plots_files_and_bytes(results, tmp_path):
    paths = plots.write_plots(results, tmp_path / "a")
    assert {p.name for p in paths} == EXPECTED
    assert {p.name for p in (tmp_path / "a").iterdir()} == EXPECTED
    for p in paths:
        assert p.read_bytes().startswith(b"\x89PNG\r\n\x1a\n")
        assert b"Software" not in p.read_bytes()[:4096]
    again = plots.write_plots(results, tmp_path / "b")
    for p, q in zip(paths, again):
        assert p.read_bytes() == q.read_bytes(), p.name


def test_write_plots_russian(results, tmp_path):
    paths = plots.write_plots(results, tmp_path, lang="ru")
    assert {p.name for p in paths} == EXPECTED        # file names stay English


def test_write_plots_rejects_unknown_language(results, tmp_path):
    with pytest.raises(ValueError, match="lang 'de'"):
        plots.write_plots(results, tmp_path, lang="de")


def test_the_users_style_neither_changes_the_plots_nor_is_changed(results, made):
    import matplotlib

    with matplotlib.rc_context({"lines.linewidth": 7.0, "axes.grid": False}):
        fig = plots.figure_epsilon(results)
        made(fig)
        assert matplotlib.rcParams["lines.linewidth"] == 7.0
    ax = fig.axes[0]
    assert ax.lines[0].get_linewidth() == fg.RC["lines.linewidth"]
    assert ax.xaxis.get_gridlines()[0].get_visible()


def test_importing_plots_does_not_import_matplotlib():
    code = ("import sys, flywheel.render.plots; "
            "sys.exit(1 if any(m.startswith('matplotlib') for m in sys.modules) else 0)")
    assert subprocess.run([sys.executable, "-c", code], check=False).returncode == 0


# -- every figure -----------------------------------------------------------------------------------
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_figure_has_title_labels_legend_and_fits(results, made, lang):
    for name, build in plots.figures(results, lang):
        fig = build()
        made(fig)
        _check_common(fig, results, lang)
        _check_layout(fig)
        assert fig.get_size_inches()[0] <= 7.5, name       # A4's text width (issue 15)


# -- one figure at a time -----------------------------------------------------------------------------
def test_positions(results, made):
    fig = plots.figure_positions(results)
    made(fig)
    ax_x, ax_y, ax_s = fig.axes
    # x of B and y of C are constant (vertical and horizontal guides): left out
    assert _legend_texts(fig)[:4] == ["$x_{A}$", "$x_{S2}$", "$x_{C}$", "$x_{S4}$"]
    assert [t.get_text() for t in ax_y.get_legend().get_texts()] == [
        "$y_{A}$", "$y_{B}$", "$y_{S2}$", "$y_{S4}$"]
    assert ax_s.get_ylabel() == "$S$ [m]"
    assert ax_s.get_xlabel() == r"$\varphi$ [deg]"
    assert len(ax_s.lines) == 2                       # sliders 3 and 5
    for line in ax_s.lines:                           # each travel spans the stroke 2·l1
        y = line.get_ydata()
        assert min(y) == pytest.approx(0.0, abs=1e-12)
        assert max(y) == pytest.approx(2 * results.scalars.crank_length, rel=1e-9)
    assert ax_x.get_xlim() == (0.0, 360.0)


def test_analogues(results, made):
    fig = plots.figure_velocity_analogues(results)
    made(fig)
    top, bottom = fig.axes
    assert len(top.lines) == 6                        # A, B, S2, C, S4 and the zero line
    assert top.get_ylabel().endswith(" [m/rad]")
    # the sliders B and C signed along their guides (below zero half the cycle), the others
    # magnitudes
    labels = [t.get_text() for t in top.get_legend().get_texts()]
    signed = [ln for ln in top.lines[:5] if "slider" in ln.get_label()]
    assert len(signed) == 2 and all(min(ln.get_ydata()) < 0 < max(ln.get_ydata())
                                    for ln in signed), labels
    assert all(min(ln.get_ydata()) >= 0 for ln in top.lines[:5] if ln not in signed)
    assert [t.get_text() for t in bottom.get_legend().get_texts()] == [
        r"$\omega_q$ link 2", r"$\omega_q$ link 4"]
    fig = plots.figure_acceleration_analogues(results)
    made(fig)
    top, bottom = fig.axes
    assert top.get_ylabel().endswith(" [m/rad²]")
    assert bottom.get_ylabel().endswith(" [1/rad]")


def test_J_II(results, made):
    fig = plots.figure_J_II(results)
    made(fig)
    top, bottom = fig.axes
    # J_II, the four links' shares, the mean
    assert len(top.get_legend().get_texts()) == 1 + len(results.J_parts) + 1
    assert top.get_ylabel().endswith(" [kg·m²]")
    assert bottom.get_ylabel().endswith(" [kg·m²/rad]")


def test_indicator(results, made):
    cyl = results.cylinders[1]
    fig = plots.figure_indicator(results, cyl)
    made(fig)
    ax = fig.axes[0]
    assert "cylinder LP" in ax.get_title()
    assert ax.get_xlabel() == "$s$ [–]"
    texts = _legend_texts(fig)
    assert texts == ["piston moving towards the head", "piston moving away from the head",
                     "table points: towards the head", "table points: away from the head"]
    markers = [ln for ln in ax.lines if ln.get_linestyle() == "None"]
    assert [len(m.get_xdata()) for m in markers] == [cyl.table_s.size] * 2
    # the curves are what the program used: the grid's p/p_max, every node once
    curves = [ln for ln in ax.lines if ln.get_linestyle() == "-" and len(ln.get_xdata()) > 20]
    assert sum(len(c.get_xdata()) for c in curves) == results.phi.size
    assert [a.get_ylabel() for a in ax.child_axes] == ["$p$ [MPa]"]     # secondary axis


def test_the_indicator_diagram_is_a_closed_loop_with_russian_ticks_on_both_axes(made):
    """The pump's cylinder (cases/pump.toml: p/p_max = 1 towards the head, 0 away) drawn as the
    course draws it, a closed loop: the pressure's jumps where the piston turns are vertical
    lines at s = 0 and s = 1 (the diagram had been two horizontal lines). In Russian the right
    axis (p [МПа], a secondary axis) writes its ticks with a decimal comma as the left does (it
    had «0.2 … 1.2»)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render.numbers import typography

    r = analyze(load_case(CASE.parent / "pump.toml"), n_points=360)
    with fg.style("ru"), typography("ru"):
        fig = plots.figure_indicator(r, r.cylinders[0], "ru")
        FigureCanvasAgg(fig).draw()
        made(fig)
        ax = fig.axes[0]
        verticals = sorted((float(ln.get_xdata()[0]), *sorted(map(float, ln.get_ydata())))
                           for ln in ax.lines if len(ln.get_xdata()) == 2
                           and ln.get_xdata()[0] == ln.get_xdata()[1])
        assert verticals == [(0.0, 0.0, 1.0), (1.0, 0.0, 1.0)]
        right = [t.get_text() for t in ax.child_axes[0].yaxis.get_ticklabels() if t.get_text()]
        assert "1,2" in right and not any("." in t for t in right), right


def test_piston_forces_mark_the_report_angle(made):
    from flywheel.cases.run import parse_case
    from flywheel.io.toml import read_toml

    data = read_toml(CASE)          # the worksheet's natural spline (the case's own is PCHIP)
    for cy in data["cylinders"]:
        cy["interpolation"] = "natural-spline"
    fig = plots.figure_piston_forces(analyze(parse_case(data), n_points=720))
    made(fig)
    texts = _legend_texts(fig)
    # seed 000 prints F_B(120°) = 2993 N, F_C(120°) = 3957 N
    assert "HP at φ = 120°: 2993 N" in texts
    assert "LP at φ = 120°: 3957 N" in texts
    assert fig.axes[0].get_ylabel() == "$F$ [N]"


def test_reduced_moments(results, made):
    fig = plots.figure_reduced_moments(results)
    made(fig)
    top, bottom = fig.axes
    texts = [t.get_text() for t in top.get_legend().get_texts()]
    assert texts[:2] == ["gas HP", "gas LP"]
    assert texts[-1] == r"$M_\Sigma$: total"
    m_d = results.scalars.balancing_moment
    assert any(t.startswith(f"$M_D$ = {m_d:.5g} N·m") for t in texts)
    assert len(bottom.get_legend().get_texts()) == 4   # gravity of links 2..5
    assert top.get_ylabel().endswith(" [N·m]")


def test_works_marks_the_extremes_of_delta_T_I(results, made):
    fig = plots.figure_works(results)
    made(fig)
    ax = fig.axes[0]
    texts = _legend_texts(fig)
    assert len(texts) == 7                            # A_D, A_C, T_II, ΔT_I, A, max, min
    sc = results.scalars
    assert (rf"$\Delta T_{{I\,max}}$ = {sc.delta_T_I_max:.5g} J at φ = "
            rf"{sc.phi_delta_T_I_max_deg:.1f}°") in texts
    assert (rf"$\Delta T_{{I\,min}}$ = {sc.delta_T_I_min:.5g} J at φ = "
            rf"{sc.phi_delta_T_I_min_deg:.1f}°") in texts
    marker = next(ln for ln in ax.lines if ln.get_marker() == "^")
    assert marker.get_xdata()[0] == pytest.approx(sc.phi_delta_T_I_max_deg)
    assert ax.get_ylabel() == "work, energy [J]"


def test_omega(results, made):
    fig = plots.figure_omega(results)
    made(fig)
    ax = fig.axes[0]
    assert len(ax.lines) == 5                          # ω, ω exact, ω_max, ω_min, ω_m
    assert sum(ln.get_linestyle() == "--" for ln in ax.lines) == 1   # ω exact, dashed
    levels = sorted(ln.get_ydata()[0] for ln in ax.lines if len(ln.get_ydata()) == 2)
    sc = results.scalars
    assert levels == pytest.approx(sorted([sc.omega_min, sc.omega_mean, sc.omega_max]))
    assert ax.get_ylabel() == r"$\omega$ [rad/s]"


def test_epsilon(results, made):
    fig = plots.figure_epsilon(results)
    made(fig)
    assert fig.axes[0].get_ylabel() == r"$\varepsilon$ [rad/s²]"
    assert len(fig.axes[0].lines) == 2                 # ε and the zero line


def test_scheme(results, made):
    fig = plots.figure_scheme(results)
    made(fig)
    (ax,) = _data_axes(fig)
    assert ax.get_aspect() == 1.0
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("$x$ [m]", "$y$ [m]")
    labels = {t.get_text() for t in ax.texts}
    # every named point, a centroid's digit a subscript as the course and the sheets write it
    assert {"O", "A", "B", "C", "S₂", "S₄"} <= labels and not {"S2", "S4"} & labels
    assert "trajectory of S₂" in _legend_texts(fig)
    assert {"1", "2", "3", "4", "5"} <= labels                  # every link
    texts = _legend_texts(fig)
    assert sum(t.startswith("trajectory of ") for t in texts) == 5
    # a closed trajectory for every moving point, over the whole cycle
    full = [ln for ln in ax.lines if len(ln.get_xdata()) == results.phi.size]
    assert len(full) == 5
    assert len(ax.patches) >= 3                        # two slider blocks and a fixed pivot


def test_scheme_at_several_angles(made):
    r = analyze(load_case(CASE), n_points=360, at_deg=[30.0, 120.0, 250.0, 300.0])
    fig = plots.figure_scheme(r)
    made(fig)
    shown = _data_axes(fig)
    assert [ax.get_title() for ax in shown] == [
        f"kinematic scheme at φ = {a:g}°" for a in (30, 120, 250, 300)]
    assert r.title in fig.get_suptitle()
    _check_layout(fig)


# -- figure formats (run --figure-format, --dpi; task2/aggregate --plot by suffix) ----------------
@pytest.mark.parametrize("fmt", ["svg", "pdf"])
def test_svg_and_pdf_are_the_same_bytes_on_a_rerun(tmp_path, results, fmt):
    """Two figures drawn from the same results, saved apart: the same bytes (no date, a fixed
    SVG hash salt), and a real file of that format."""
    paths = []
    for k in range(2):
        fig = plots.figure_J_II(results)
        try:
            path = tmp_path / f"J_II_{k}.{fmt}"
            fg.save(fig, path, fmt)
            paths.append(path)
        finally:
            fig.clear()
    a, b = (p.read_bytes() for p in paths)
    assert a == b
    assert a.startswith(b"%PDF") if fmt == "pdf" else b"<svg" in a[:2000]


def test_write_plots_svg_keeps_the_pngs_the_reports_embed(tmp_path, results):
    out = plots.write_plots(results, tmp_path, fmt="svg", dpi=60)
    assert out and all(p.suffix == ".svg" and p.is_file() for p in out)
    assert all(p.with_suffix(".png").is_file() for p in out)
    from PIL import Image

    assert out[0].name == "positions.svg"
    with Image.open(out[0].with_suffix(".png")) as im:      # the positions: 7.45 in (A4) at 60 dpi
        assert im.size[0] == round(7.45 * 60)


@pytest.mark.parametrize("suffix", [".svg", ".pdf"])
def test_task2_plot_by_suffix_is_the_same_bytes_on_a_rerun(tmp_path, suffix):
    from typer.testing import CliRunner

    from flywheel.cli import app

    paths = [tmp_path / f"a{suffix}", tmp_path / f"b{suffix}"]
    for p in paths:
        res = CliRunner().invoke(app, ["task2", "--profile", "triangle", "--plot", str(p)])
        assert res.exit_code == 0, res.output
    assert paths[0].read_bytes() == paths[1].read_bytes()


def test_plan_arrows_added_as_artists_keep_the_pixels_of_patches(results, monkeypatch):
    """plots_plans._arrows adds its arrows with add_artist (no display-space layout for the
    data limits: a plan's limits are its frame's); the plans of velocities and of forces are
    the same pixels as with matplotlib's add_patch, which widens the data limits by each arrow."""
    import io

    from matplotlib.axes import Axes
    from matplotlib.patches import FancyArrowPatch

    specs = dict(plots.all_figures(results, "en"))
    names = [n for n in specs if n.startswith(("plan_velocity", "plan_forces"))]
    assert len(names) == 2

    def pngs() -> list[bytes]:
        out = []
        with fg.style("en"):
            for n in names:
                buf = io.BytesIO()
                fg.save(specs[n](), buf)
                out.append(buf.getvalue())
        return out

    ours = pngs()
    own = Axes.add_artist
    monkeypatch.setattr(Axes, "add_artist", lambda self, a: self.add_patch(a)
                        if isinstance(a, FancyArrowPatch) else own(self, a))
    assert pngs() == ours


@pytest.mark.parametrize("lang, zero", [("en", "closes to 0 N"), ("ru", "невязка 0 Н")])
def test_force_polygons_closing_by_round_off_say_zero(lang, zero):
    """A group in equilibrium closes its polygon to round-off (engine_inline4: 4.5e-13 N of
    forces up to 18 kN): the panel says 0 through the one formatter, never an exponent such as
    "4.5e-13" (nor a decimal point in a Russian figure)."""
    res = analyze(load_case(CASE.parent / "engine_inline4.toml"), n_points=360)
    name = next(n for n, _ in plots.all_figures(res, lang) if n.startswith("plan_forces"))
    fig = fg.drawn(dict(plots.all_figures(res, lang))[name])
    closes = [a.get_title().splitlines()[-1] for a in fig.axes if a.get_title()]
    assert len(closes) >= 5 and set(closes) == {zero}


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_force_polygons_of_five_panels_stay_inside_the_figure(lang):
    """engine_inline4's five polygons go three to a row, each widened to its title's width:
    the row then ran past the figure's right edge by 0.15 in (the third panel's frame and
    title cut). Every panel, its title and tick labels inside the figure, none over another."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    res = analyze(load_case(CASE.parent / "engine_inline4.toml"), n_points=360)
    specs = dict(plots.all_figures(res, lang))
    for name in [n for n in specs if n.startswith("plan_forces")]:
        fig = fg.drawn(specs[name])
        _check_layout(fig)
        r = FigureCanvasAgg(fig).get_renderer()
        boxes = [ax.get_tightbbox(r) for ax in fig.axes]
        assert len(boxes) == 5
        W = fig.get_size_inches()[0]
        for ax in fig.axes:                   # each frame whole, 0.1 in or more from an edge
            p = ax.get_position()
            assert p.x0 * W >= 0.1 - 1e-9 and p.x1 * W <= W - 0.1 + 1e-9, (name, p.x0, p.x1)
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                assert not a.overlaps(b), name


def test_a_row_of_widened_panels_gives_up_the_widening_to_fit():
    """plots_plans._within_width: a row within its width is kept; one past it loses just its
    excess, taken from the widening in proportion, never below the polygons' own widths."""
    from flywheel.render.plots_plans import _within_width

    natural = [2.0, 4.0, 1.0]                 # height / width: 1, 0.5 and 2 in wide at ah = 2
    widened = [2.0 / 1.9, 2.0 / 1.9, 1.0]     # the first two widened to 1.9 in
    same = _within_width([[0, 1, 2]], widened, natural, 2.0, 3 * 0.6 + 1.9 + 1.9 + 2.0, 0.6)
    assert same == widened
    fit = _within_width([[0, 1, 2]], widened, natural, 2.0, 3 * 0.6 + 5.0, 0.6)
    widths = [2.0 / a for a in fit]
    assert sum(widths) == pytest.approx(5.0, abs=1e-12)          # exactly the room
    assert widths[2] == pytest.approx(2.0)                       # not widened: untouched
    assert (widths[0] - 1.0) / (widths[1] - 0.5) == pytest.approx(0.9 / 1.4)   # in proportion
    tight = _within_width([[0, 1, 2]], widened, natural, 2.0, 3 * 0.6 + 3.5, 0.6)
    assert [2.0 / a for a in tight] == pytest.approx([1.0, 0.5, 2.0])


def test_a_hodograph_over_720_degrees_marks_both_turns():
    """A four-stroke engine's loads differ between the crank's two turns: its hodographs mark
    every 30° of the 720° cycle (24 marks), labelled up to 690°; a 360° cycle's, 12. Before,
    only 0 … 330° were marked, the second turn's loop unlabelled."""
    from flywheel.render.plots_forces import _mark_angles

    eng = analyze(load_case(CASE.parent / "engine_inline4.toml"), n_points=360)
    assert _mark_angles(eng) == list(range(0, 720, 30))
    assert _mark_angles(analyze(load_case(CASE), n_points=360)) == list(range(0, 360, 30))
    fig = fg.drawn(dict(plots.all_figures(eng, "en"))["hodographs.png"])
    pin = fig.axes[0]
    marks = [ln for ln in pin.lines if ln.get_marker() == "o"]
    assert len(marks) == 1 and len(marks[0].get_xdata()) == 24
    labels = {t.get_text() for t in pin.texts}
    assert "0" in labels and len(labels & {str(a) for a in range(360, 720, 30)}) >= 6, labels


def test_the_crank_pins_circle_is_drawn_over_the_others_on_it():
    """The plan of positions' legend names the crank pin's circle by colour C0; an engine's
    other crank pin (A2, C1) runs on the same circle and was drawn over it, so the circle the
    legend calls blue was orange. The first moving point's trajectory is drawn last."""
    import numpy as np
    from matplotlib.colors import to_hex

    eng = analyze(load_case(CASE.parent / "engine_inline4.toml"), n_points=360)
    fig = fg.drawn(dict(plots.all_figures(eng, "en"))["plan_positions.png"])
    ax = fig.axes[0]
    paths = [ln for ln in ax.lines if ln.get_alpha() == 0.8 and len(ln.get_xdata()) > 100]
    assert len(paths) == len(eng.drawing.moving_points)
    assert to_hex(paths[-1].get_color()) == to_hex("C0")
    pin = eng.kinematics.points[eng.drawing.moving_points[0]].r
    assert np.allclose(np.column_stack([paths[-1].get_xdata(), paths[-1].get_ydata()]), pin)


@pytest.mark.parametrize("case, pin, bearing", [
    ("compressor", "шатунную шейку", "коренной подшипник"),
    ("shaper", "палец кривошипа", "опору кривошипа")])
def test_the_crank_pin_is_a_crankshafts_only_where_there_is_one(case, pin, bearing):
    """«Шатунная шейка» and «коренной подшипник» are a crankshaft's: a compressor's or an
    engine's (a case with cylinders). The shaper's crank carries a block in a slotted lever —
    no connecting rod, no crankshaft —: its crank pin is «палец кривошипа», its bearing «опора
    кривошипа», in the hodographs' titles, the record's caption and its sentence, sheet 2."""
    from flywheel.render.document import build_document
    from flywheel.render.drawings import sheet, sheet2
    from flywheel.render.drawings.model import Text
    from flywheel.render.numbers import typeset

    c = load_case(CASE.parent / f"{case}.toml")
    res = analyze(c, n_points=360)
    fig = fg.drawn(dict(plots.all_figures(res, "ru"))["hodographs.png"])
    titles = " | ".join(ax.get_title() for ax in fig.axes)
    doc = str(typeset("ru", build_document, res, "ru", ["hodographs.png"], case=c))
    views = sheet2.views(res, "ru", sheet.ROOM["A1"])
    lettering = " ".join(t.text for v in views for t in v.items if isinstance(t, Text))
    for text in (titles, doc):
        assert pin in text and bearing in text, text[:300]
    assert pin.split()[0] in lettering                       # «Годограф нагрузки на …»
    if case == "shaper":
        for text in (titles, doc, lettering):
            assert "шатунн" not in text and "коренн" not in text


@pytest.mark.parametrize("case", ["compressor", "engine_inline4", "shaper"])
def test_the_plan_of_positions_numbers_stay_inside_its_frame(case):
    """The positions' numbers are set outwards of the drawing: the plan's limits leave them
    room (engine_inline4's «6, 18», below the crank pin's lowest place, lay across the frame's
    lower edge)."""
    res = analyze(load_case(CASE.parent / f"{case}.toml"), n_points=360)
    fig = fg.drawn(dict(plots.all_figures(res, "ru"))["plan_positions.png"])
    ax = fig.axes[0]
    pt = 72.0 / fig.dpi
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    frame = ax.get_window_extent(FigureCanvasAgg(fig).get_renderer())
    f = (frame.x0 * pt, frame.y0 * pt, frame.x1 * pt, frame.y1 * pt)
    numbers = [(t, b) for t, b in fig.flywheel_labels if t.get_text()[:1].isdigit()]
    assert len(numbers) >= 12
    for t, b in numbers:
        assert f[0] - 0.5 <= b[0] and b[2] <= f[2] + 0.5 and f[1] - 0.5 <= b[1] \
            and b[3] <= f[3] + 0.5, (t.get_text(), b, f)


def test_many_reactions_are_told_apart_by_their_line_style(made):
    """engine_inline4's 13 reactions: past the ten colours of the cycle the curves are dashed
    (fg.series) — R₀₁ and R₈₉ had been drawn alike in blue; a pair's point lettered B₁."""
    from flywheel.render import plots_forces

    r = analyze(load_case(CASE.parent / "engine_inline4.toml"), n_points=360)
    with fg.style("ru"):
        fig = plots_forces.figure_reactions(r, "ru")
        made(fig)
        lines = [ln for ln in fig.axes[0].lines if len(ln.get_xdata()) == r.phi.size]
        styles = [(ln.get_color(), ln.get_linestyle()) for ln in lines]
        assert len(lines) == 13 and len(set(styles)) == 13, styles
        assert any("(B₁)" in t for t in _legend_texts(fig))
