"""The force analysis inside `flywheel run` (issue 12): the summary.json contract, the closure
with the dynamics, the two motions, forces.csv against summary.json, --lang ru, the tabulated
press, and the wiring of the case's loads against the independent construction of
tests/dynamics/test_forces.py.

Truths used, none of them the code under test: the equation of motion read backwards (with the
true motion M_y = M_D at every node; a wrong sign or a missing load breaks it); the cycle mean of
the steady M_y is the cycle balance's M_D (the inertia loads of a uniform rotation do no work
over a cycle: ∮½·J_II′·ω_m² dφ = 0); the seed 004 decomposition of the press's moment into its
static and dynamic parts, Мст + Мдин (eq. 5 with ε1 = 0); and the loads as tests/dynamics/test_forces.py
builds them by hand from the case file.
"""
from __future__ import annotations

import csv
import io
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case, parse_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.io.toml import read_toml

CASES = Path(__file__).resolve().parents[2] / "cases"
LINKAGES = ["compressor", "compressor_worksheet", "fourbar", "slotted_link"]
ALL = LINKAGES + ["press"]
SLIDER_CRANK = ("piston_effort", "side_thrust", "rod_thrust", "crank_pin_tangential",
                "crank_pin_radial", "turning_moment")
runner = CliRunner()


def _finite(x) -> bool:
    return isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x)


_RESULTS: dict = {}


def results_of(name: str, motion: str = "true"):
    if (name, motion) not in _RESULTS:
        _RESULTS[name, motion] = analyze(load_case(CASES / f"{name}.toml"), motion=motion)
    return _RESULTS[name, motion]


def document(name: str, motion: str = "true") -> dict:
    return json.loads(json.dumps(results_of(name, motion).to_document()))


def trapezoid_mean(y: np.ndarray, x: np.ndarray) -> float:
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(x)) / (x[-1] - x[0]))


# -- the contract ----------------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_contract_keys_present_and_finite(name):
    doc = document(name)
    r = doc["results"]
    assert _finite(r["balancing_moment_closure"])
    assert r["force_analysis"]["motion"] == "true"
    tabulated = name == "press"
    for a in r["at"]:
        bm = a["balancing_moment"]
        ways = ("power",) if tabulated else ("kinetostatic", "zhukovsky", "power", "groups")
        assert set(bm) == set(ways) and all(_finite(bm[w]) for w in ways)
        if tabulated:
            assert "joints" not in a and "slider_crank" not in a
            continue
        assert a["joints"]
        for key, j in a["joints"].items():
            point, _, pair = key.partition(":")
            by, _, on = pair.partition("->")
            assert (j["point"], j["by"], j["on"]) == (point, by, on)
            for q in ("F", "Fx", "Fy", "angle_deg"):
                assert _finite(j[q]), (key, q)
            assert j["F"] == pytest.approx(math.hypot(j["Fx"], j["Fy"]), rel=1e-12, abs=1e-12)
        for q in ("main_bearing_load", "crank_pin_load", "shaking_force"):
            assert _finite(a[q]["F"])
        assert _finite(a["shaking_moment"])
    # every existing key is still there, unchanged in kind
    assert {"driving_moment", "balancing_moment", "J_required", "at"} <= set(r)


def test_slider_crank_keys_where_a_rod_starts_at_the_crank_pin():
    """The compressor has two slider-crank groups (pistons 3 and 5); the slotted link's RRP
    starts at the rocker's end D, not at the crank pin, so it has none."""
    for name, sliders in (("compressor", {"3", "5"}), ("compressor_worksheet", {"3", "5"})):
        for a in document(name)["results"]["at"]:
            assert set(a["slider_crank"]) == sliders
            for sc in a["slider_crank"].values():
                assert all(_finite(sc[q]) for q in SLIDER_CRANK)
    for name in ("slotted_link", "fourbar"):
        assert all("slider_crank" not in a for a in document(name)["results"]["at"])


def test_existing_keys_unchanged_by_the_force_analysis():
    """summary.json without the new keys is what the run gave before (results.forces = None)."""
    res = results_of("compressor")
    new = json.loads(json.dumps(res.to_document()))
    force_keys = ("balancing_moment", "joints", "slider_crank", "main_bearing_load",
                  "crank_pin_load", "shaking_force", "shaking_moment")
    bare = tuple(replace(a, **dict.fromkeys(force_keys)) for a in res.at)
    old = json.loads(json.dumps(replace(res, forces=None, at=bare).to_document()))
    for k in ("balancing_moment_closure", "force_analysis"):
        new["results"].pop(k)
    for a in new["results"]["at"]:
        for k in force_keys:
            a.pop(k, None)
    assert new == old


# -- closure and the three balancing moments -------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_closure_is_round_off(name):
    """True motion: M_y = M_D at every node (relative to |M_D|; the four-bar's loads do no
    net work, M_D = 0, so relative to max|J_I·ε|)."""
    r = document(name)["results"]
    assert r["balancing_moment_closure"] <= 1e-9
    ref = "J_I·ε" if name == "fourbar" else "M_D"
    assert r["force_analysis"]["closure_reference"] == ref
    f = results_of(name).forces
    M_D = r["balancing_moment"]
    assert np.max(np.abs(f.M_y - M_D)) <= 1e-9 * max(abs(M_D), float(np.max(
        np.abs(results_of(name).motion.J_I * results_of(name).motion.epsilon))))


@pytest.mark.parametrize("name", LINKAGES)
@pytest.mark.parametrize("motion", ["true", "steady"])
def test_three_balancing_moments_equal_at_the_report_angles(name, motion):
    r = document(name, motion)["results"]
    scale = max(abs(r["balancing_moment"]), r["force_analysis"]["balancing_moment_max"],
                -r["force_analysis"]["balancing_moment_min"], 1.0)
    for a in r["at"]:
        bm = a["balancing_moment"]
        assert abs(bm["zhukovsky"] - bm["kinetostatic"]) <= 1e-11 * scale
        assert abs(bm["power"] - bm["kinetostatic"]) <= 1e-11 * scale


def test_closure_catches_a_wrong_gas_force_direction():
    """A check that can fail: with the gas forces pulling instead of pushing, the kinetostatic
    M_y no longer reproduces the dynamics' M_D."""
    from flywheel.dynamics import forces as fo

    res = results_of("compressor")
    case = load_case(CASES / "compressor.toml")
    from flywheel.dynamics.grid import standard_positions
    from flywheel.dynamics.pipeline import force_loads

    mech = case.mechanism()
    _, dcs = standard_positions(mech)
    loads = force_loads(case, mech, dcs, res.kinematics, res.loads, res.motion.J_I)
    flipped = replace(loads, forces=tuple(replace(f, F=-f.F) for f in loads.forces))
    fa = fo.kinetostatics(mech, res.kinematics, res.motion.omega, res.motion.epsilon, flipped)
    assert fo.closure(fa, res.energy.balancing_moment) > 0.1
    fa = fo.kinetostatics(mech, res.kinematics, res.motion.omega, res.motion.epsilon, loads)
    assert fo.closure(fa, res.energy.balancing_moment) < 1e-12


# -- steady motion ---------------------------------------------------------------------------------

@pytest.mark.parametrize("name", ALL)
def test_steady_motion_mean_of_M_y_is_M_D(name):
    """ω = ω_m, ε = 0: M_y varies over the cycle; its cycle mean is M_D (the inertia loads of a
    uniform rotation do no work over a cycle). The slotted link's cutting force switches on and
    off inside grid intervals, where the trapezoid rule is first order and the cycle balance
    uses the exact work: 1e-4 there."""
    res = results_of(name, "steady")
    f = res.forces
    assert f.motion == "steady"
    assert np.all(f.omega == res.sizing.omega_mean) and np.all(f.epsilon == 0)
    M_D = res.energy.balancing_moment
    scale = max(abs(M_D), float(np.max(np.abs(f.M_y))))
    assert np.ptp(f.M_y) > 0.05 * scale                       # not the constant of the dynamics
    mean = trapezoid_mean(f.M_y, res.phi)
    assert mean == pytest.approx(f.M_y_cycle_mean, rel=1e-12, abs=1e-12 * scale)
    tol = 2e-4 if name == "slotted_link" else 1e-9
    assert abs(mean - M_D) <= tol * scale
    # the closure is still that of the true motion
    assert document(name, "steady")["results"]["balancing_moment_closure"] <= 1e-9


def test_steady_press_is_the_seeds_static_plus_dynamic_moment():
    """Seed 004, eq. (5) with ε1 = 0: the moment the drive needs at uniform rotation is
    Мст + Мдин, Мдин = ω1²/2·dIпр/dφ — TabulatedResult's M_st and M_dyn, at every node."""
    res = results_of("press", "steady")
    tab = res.tabulated
    np.testing.assert_allclose(res.forces.M_y_power, tab.M_st + tab.M_dyn, rtol=0,
                               atol=1e-12 * float(np.max(np.abs(tab.M_st))))


def test_motion_from_the_case_and_the_option(tmp_path):
    data = read_toml(CASES / "fourbar.toml")
    data["force_analysis"] = {"motion": "steady"}
    case = parse_case(data, "fourbar.toml")
    assert analyze(case, n_points=360).forces.motion == "steady"
    assert analyze(case, n_points=360, motion="true").forces.motion == "true"
    data["force_analysis"] = {"motion": "uniform"}
    with pytest.raises(Exception, match="force_analysis.motion"):
        parse_case(data, "fourbar.toml")
    res = runner.invoke(app, ["run", str(CASES / "fourbar.toml"), "--no-plots", "--json",
                              "--points", "360", "--motion", "steady", "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["results"]["force_analysis"]["motion"] == "steady"
    res = runner.invoke(app, ["run", str(CASES / "fourbar.toml"), "--no-plots", "--motion", "fast",
                              "--out", str(tmp_path / "p")])
    assert res.exit_code == 2
    lines = res.output.strip().splitlines()
    assert len(lines) == 1 and "--motion" in lines[0] and "true, steady" in lines[0]


# -- the wiring of the loads -----------------------------------------------------------------------

@pytest.mark.parametrize("name", ["compressor", "fourbar", "slotted_link"])
def test_reactions_equal_the_hand_built_loads_of_test_forces(name):
    """tests/dynamics/test_forces.py builds the same loads from the case file by hand (gas forces away
    from the head, technological forces against the velocity, weights, couples, J_I); the
    run's reactions are those to round-off."""
    from test_forces import analysed

    ref = analysed(name)["fa"]
    f = results_of(name).forces
    assert set(f.joints) == set(ref.joints)
    scale = max(float(np.max(r.magnitude)) for r in ref.joints.values())
    for key, r in f.joints.items():
        assert np.max(np.abs(r.x - ref.joints[key].x)) <= 1e-11 * scale, key
        assert np.max(np.abs(r.y - ref.joints[key].y)) <= 1e-11 * scale, key


def test_crank_pin_load_is_the_sum_of_the_rods():
    """The compressor's two rods share the crank pin: the load on it is the sum of their
    forces on the crank (forces.SliderCrank's crank_pin_x, _y) and, the crank carrying only its
    own weight and inertia besides, close to the main-bearing load."""
    f = results_of("compressor").forces
    sc = f.slider_crank
    np.testing.assert_allclose(f.crank_pin_load[:, 0], sc["3"].crank_pin_x + sc["5"].crank_pin_x,
                               rtol=0, atol=1e-9)
    np.testing.assert_allclose(f.crank_pin_load[:, 1], sc["3"].crank_pin_y + sc["5"].crank_pin_y,
                               rtol=0, atol=1e-9)
    np.testing.assert_allclose(f.crank_pin_tangential,
                               sc["3"].crank_pin_tangential + sc["5"].crank_pin_tangential,
                               rtol=0, atol=1e-9)


# -- files -----------------------------------------------------------------------------------------

def _csv(path: Path) -> tuple[list[str], np.ndarray, list[str]]:
    rows = list(csv.reader(io.StringIO(path.read_text(encoding="utf-8"))))
    return rows[0], rows[1:], [r[0] for r in rows[1:]]


@pytest.mark.parametrize("name", ["compressor", "slotted_link", "press"])
def test_forces_csv_agrees_with_summary_json(tmp_path, name):
    out = tmp_path / name
    res = runner.invoke(app, ["run", str(CASES / f"{name}.toml"), "--no-plots", "--out", str(out),
                              "--at", "75", "--at", "200"])
    assert res.exit_code == 0, res.output
    doc = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    header, rows, _ = _csv(out / "forces.csv")
    assert header[0] == "phi_deg [deg]" and all(h.endswith("]") and " [" in h for h in header)
    col = {h.rsplit(" [", 1)[0]: k for k, h in enumerate(header)}
    data = np.array(rows, float)
    assert data.shape[0] == doc["results"]["n_points"]
    for a in doc["results"]["at"]:
        row = data[int(np.argmin(np.abs(data[:, 0] - a["phi_deg"])))]
        assert row[0] == pytest.approx(a["phi_deg"], abs=1e-9)

        def same(key, value):
            assert row[col[key]] == pytest.approx(value, rel=1e-11, abs=1e-9), key

        bm = a["balancing_moment"]
        same("M_y_power", bm["power"])
        if name == "press":
            assert set(col) == {"phi_deg", "omega", "epsilon", "M_y_power"}
            continue
        same("M_y", bm["kinetostatic"])
        same("M_y_zhukovsky", bm["zhukovsky"])
        for key, j in a["joints"].items():
            same(f"R_{key}", j["F"])
            same(f"Rx_{key}", j["Fx"])
            same(f"Ry_{key}", j["Fy"])
        for s, sc in a.get("slider_crank", {}).items():
            for q in SLIDER_CRANK:
                same(f"{q}_{s}", sc[q])
        same("main_bearing_F", a["main_bearing_load"]["F"])
        same("crank_pin_F", a["crank_pin_load"]["F"])
        same("shaking_F", a["shaking_force"]["F"])
        same("shaking_M", a["shaking_moment"])
    # forces_positions.csv: the rows of forces.csv at the standard positions, labelled and
    # numbered as in positions.csv
    pheader, prows, plabels = _csv(out / "forces_positions.csv")
    _, posrows, labels = _csv(out / "positions.csv")
    assert pheader == ["position", "number"] + header and plabels == labels
    assert [r[1] for r in prows] == [r[1] for r in posrows]
    for r in prows:
        match = [k for k, row in enumerate(rows) if row[0] == r[2]]
        assert match and rows[match[0]] == r[2:]


def test_forces_csv_is_byte_identical_between_runs(tmp_path):
    outs = []
    for k in range(2):
        out = tmp_path / f"o{k}"
        assert runner.invoke(app, ["run", str(CASES / "fourbar.toml"), "--no-plots", "--points",
                                   "360", "--out", str(out)]).exit_code == 0
        outs.append((out / "forces.csv").read_bytes() + (out / "forces_positions.csv").read_bytes())
    assert outs[0] == outs[1] and b"-0," not in outs[0] and not outs[0].startswith(b"-0\n")


def test_lang_ru_runs(tmp_path):
    out = tmp_path / "ru"
    res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots", "--lang", "ru",
                              "--points", "720", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "Силовой расчёт (кинетостатика)" in res.output
    assert "сходимость с динамикой" in res.output and "рычаг Жуковского" in res.output
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "## 7. Силовой расчёт (кинетостатика)" in report       # numbered as the rest
    assert "Реакции в кинематических парах при φ = 120°" in report
    assert "движущая сила на поршне" in report and "боковое давление на стенку цилиндра" in report
    en = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots", "--points", "720",
                             "--out", str(tmp_path / "en")])
    assert "Force analysis (kinetostatics)" in en.output and "closure with the dynamics" in en.output
    report = (tmp_path / "en" / "report.md").read_text(encoding="utf-8")
    assert "## 7. Force analysis (kinetostatics)" in report and "piston effort" in report


def test_tabulated_press_one_line_note_and_no_joints(tmp_path):
    out = tmp_path / "press"
    res = runner.invoke(app, ["run", str(CASES / "press.toml"), "--no-plots", "--out", str(out)])
    assert res.exit_code == 0, res.output
    notes = [ln for ln in res.output.splitlines() if "joint reactions need a linkage" in ln]
    assert len(notes) == 1
    doc = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    assert "joint reactions need a linkage" in doc["results"]["force_analysis"]["note"]
    assert all("joints" not in a for a in doc["results"]["at"])
    assert not any("linkage" in w for w in doc["warnings"])     # a note, not a warning
    report = (out / "report.md").read_text(encoding="utf-8")
    assert "joint reactions need a linkage" in report
    ru = runner.invoke(app, ["run", str(CASES / "press.toml"), "--no-plots", "--lang", "ru",
                             "--out", str(tmp_path / "ru")])
    assert sum("реакции в кинематических парах требуют схемы механизма" in ln
               for ln in ru.output.splitlines()) == 1


# -- plots -----------------------------------------------------------------------------------------

@pytest.mark.parametrize("lang", ["en", "ru"])
def test_force_figures(lang):
    from flywheel.render import plots_forces as pf

    res = results_of("compressor")
    names = [n for n, _ in pf.figures(res, lang)]
    assert names == ["reactions.png", "balancing_moment.png", "hodographs.png"]
    N, Nm = (", Н", ", Н·м") if lang == "ru" else (" [N]", " [N·m]")
    fig = pf.figure_reactions(res, lang)
    (ax,) = fig.axes
    assert res.title in ax.get_title() and ax.get_ylabel().endswith(N)
    assert len(ax.lines) == len(res.forces.joints) and ax.get_legend() is not None
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), next(iter(res.forces.joints.values())).magnitude)
    fig.clear()
    fig = pf.figure_balancing_moment(res, lang)
    (ax,) = fig.axes
    labels = [t.get_text() for t in ax.get_legend().get_texts()]
    assert len(labels) == 4 and ax.get_ylabel().endswith(Nm)
    # the true motion: M_y of the groups, the flywheel's −J_I·ε, M_y with it and M_D
    assert ("групп Ассура" if lang == "ru" else "Assur groups") in labels[0]
    assert ("маховика" if lang == "ru" else "flywheel") in labels[1]
    fa = res.forces.analysis
    np.testing.assert_array_equal(ax.lines[0].get_ydata(), fa.balancing_moment_groups)
    np.testing.assert_array_equal(ax.lines[1].get_ydata(), fa.first_group_torque)
    fig.clear()
    steady = pf.figure_balancing_moment(results_of("compressor", "steady"), lang)
    labels = [t.get_text() for t in steady.axes[0].get_legend().get_texts()]
    assert ("рычагу Жуковского" if lang == "ru" else "Zhukovsky's lever") in " ".join(labels)
    steady.clear()
    fig = pf.figure_hodographs(res, lang)
    assert len(fig.axes) == 3 and res.title in fig.get_suptitle()
    assert all(ax.get_xlabel().endswith(N) and ax.get_ylabel().endswith(N)
               for ax in fig.axes)
    np.testing.assert_array_equal(fig.axes[0].lines[0].get_xdata(), res.forces.crank_pin_tangential)
    fig.clear()
    assert [n for n, _ in pf.figures(results_of("press"), lang)] == ["balancing_moment.png"]


@pytest.mark.parametrize("name", ["shaper", "slotted_link", "compressor", "engine_inline4"])
@pytest.mark.parametrize("lang", ["en", "ru"])
def test_hodograph_angle_labels_do_not_overlap(name, lang):
    """The 30° labels along each hodograph (over the whole cycle: 720° for a four-stroke
    engine): measured on the drawn page, no label's box meets
    another's, 0° is always labelled and every label names a mark it sits beside; where the
    marks crowd (the shaper's shaking force: twelve marks within 400 N of a 460 N offset)
    some labels are left out rather than drawn over each other (issue 15)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots_forces as pf

    res = results_of(name)
    with fg.style():
        fig = pf.figure_hodographs(res, lang)
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        ren = canvas.get_renderer()
        counts = []
        for ax in fig.axes:
            texts = list(ax.texts)
            boxes = [t.get_window_extent(ren) for t in texts]
            for i, a in enumerate(boxes):
                for j in range(i):
                    assert not a.overlaps(boxes[j]), (ax.get_title(), texts[i].get_text(),
                                                      texts[j].get_text())
            angles = [t.get_text() for t in texts]
            assert "0" in angles and set(angles) <= {f"{a}" for a in pf._mark_angles(res)}
            marks = ax.lines[2]                     # the curve, the origin, the 30° marks
            xy = np.column_stack([marks.get_xdata(), marks.get_ydata()])
            for t in texts:                         # beside its own mark: within 12 pt
                p = ax.transData.transform(xy[int(t.get_text()) // 30])
                b = t.get_window_extent(ren)
                gap = np.hypot(max(b.x0 - p[0], 0, p[0] - b.x1), max(b.y0 - p[1], 0, p[1] - b.y1))
                assert gap <= 12 * fig.dpi / 72, (t.get_text(), gap)
            counts.append(len(texts))
        fig.clear()
    if name == "shaper":
        assert min(counts) < 12            # crowded: some left out


def test_round_off_is_not_magnified_on_the_balancing_moment_plot():
    """The four-bar's loads do no net work: with the true motion M_y = M_D = 0 to 1e-15 N·m; the
    axis spans a tenth of the first group's couple, not the round-off."""
    from flywheel.render import plots_forces as pf

    res = results_of("fourbar")
    fig = pf.figure_balancing_moment(res)
    lo, hi = fig.axes[0].get_ylim()
    fig.clear()
    couple = float(np.max(np.abs(res.forces.analysis.first_group_couple)))
    assert hi - lo >= 0.2 * couple and lo < 0 < hi
    steady = results_of("fourbar", "steady")
    fig = pf.figure_balancing_moment(steady)
    lo, hi = fig.axes[0].get_ylim()
    fig.clear()
    assert lo <= float(np.min(steady.forces.M_y)) and hi >= float(np.max(steady.forces.M_y))


# -- the balancing moment of the Assur groups (issue 28) ---------------------------------------------

def test_groups_moment_varies_while_M_y_with_the_first_group_is_M_D():
    """With the true motion M_y (the first group's inertia on the crank) equals M_D at every φ —
    the closure check — while the moment the crank delivers to the Assur groups swings over
    the cycle by more than 20 % of M_D: the fluctuation the flywheel takes up."""
    res = results_of("compressor")
    fa, M_D = res.forces.analysis, res.scalars.driving_moment
    grp = fa.balancing_moment_groups
    assert np.max(np.abs(fa.balancing_moment - M_D)) < 1e-9 * abs(M_D)
    assert np.ptp(grp) > 0.2 * abs(M_D)
    # M_y = M_y,gr + J_I·ε: the groups' moment and the flywheel's −J_I·ε make up M_y
    J_eps = res.motion.J_I * res.forces.epsilon
    np.testing.assert_allclose(grp + J_eps, fa.balancing_moment, rtol=0, atol=1e-9 * abs(M_D))
    np.testing.assert_allclose(grp, fa.balancing_moment + fa.first_group_torque, rtol=0,
                               atol=1e-12 * abs(M_D))


def test_groups_moment_is_the_power_balance_without_the_first_group():
    """An independent truth for M_y,gr at the true motion: the power balance of the links alone
    (J_I = 0 in forces.power_balance_moment: kinetic energy instead of inertia forces, no
    reactions), with the dynamics' ω(φ), ε(φ)."""
    from flywheel.dynamics import forces as fo
    from flywheel.dynamics import pipeline as pp

    for name in ("compressor", "engine_4stroke", "shaper"):
        res = results_of(name)
        case = load_case(CASES / f"{name}.toml")
        mech = case.mechanism()
        _, dcs = pp.standard_positions(mech, case.machine.cycle)
        loads = pp.force_loads(case, mech, dcs, res.kinematics, res.loads, 0.0)   # J_I = 0
        alone = fo.power_balance_moment(mech, res.kinematics, res.forces.omega,
                                        res.forces.epsilon, loads)
        grp = res.forces.analysis.balancing_moment_groups
        np.testing.assert_allclose(grp, alone, rtol=0, atol=1e-7 * np.max(np.abs(grp)))


def test_groups_moment_at_steady_motion_is_zhukovskys_lever():
    """At --motion steady (ε = 0) the course's comparison: M_y,gr = M_y by Zhukovsky's lever."""
    res = results_of("compressor", "steady")
    grp = res.forces.analysis.balancing_moment_groups
    np.testing.assert_allclose(grp, res.forces.M_y_zhukovsky, rtol=0, atol=1e-9 * np.max(np.abs(grp)))
    assert np.ptp(grp) > 0.2 * abs(res.scalars.driving_moment)


def test_forces_csv_has_the_groups_column():
    from flywheel.render.forces import forces_csv

    res = results_of("compressor")
    header = forces_csv(res).splitlines()[0].split(",")
    col = [h for h in header if h.startswith("M_y_groups")]
    assert col == ["M_y_groups [N·m]"]
    assert header.index(col[0]) == header.index("M_y [N·m]") + 1
