"""Six-bar mechanisms (issue 13 item 4): groups attached to a link other than the crank.

Independent truths: the shaper of cases/shaper.toml against its textbook exercise (the time
ratio of the cutting and return strokes 1.647) and the closed forms of the crank and slotted
lever (the lever's extremes where it is tangent to the crank circle); the cutting work is the
force times the travel it acts over; a toggle press and the shaper against numerical
derivatives of their positions.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case
from flywheel.cli import app
from flywheel.dynamics.pipeline import analyze
from flywheel.linkage import RRP, RRR, Crank, Guide, LinkPoint, Mechanism, solve
from helpers import check_numerical  # 8th-order central differences (tests/helpers.py)
from flywheel.linkage.deadcentres import dead_centres

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def test_shaper_against_its_exercise():
    """Fixed centres 200 mm apart, crank 75 mm: at the ram's dead centres the lever is tangent
    to the crank circle (the crank ⟂ the lever), so the return takes 2·acos(75/200) of crank
    angle and the cut the rest: the time ratio (360° − 135.95°)/135.95° = 1.648 (the exercise's
    answer: 1.647). The lever then leans 90° − acos(75/200) = 22.02° from the vertical, and the
    ram, whose line passes 150 mm beyond C, moves as Q does between the extremes:
    2·0.36·sin 22.02° = 2·0.36·0.375 = 0.27 m (sin(90° − acos x) = x)."""
    case = load_case(CASES / "shaper.toml")
    dcs = {dc.kind: dc for dc in dead_centres(case.mechanism(), "5")}
    quick = 2 * math.degrees(math.acos(0.075 / 0.2))
    span = math.degrees(dcs["inner"].phi - dcs["outer"].phi) % 360
    assert span == pytest.approx(quick, abs=1e-9)                   # out → in: the return
    ratio = (360 - span) / span
    assert ratio == pytest.approx((360 - quick) / quick, rel=1e-12)  # 1.64801
    # the exercise prints 1.647: its angles rounded (224.04°/135.96° = 1.6478) and cut to 3
    # decimals; the exact ratio is 1.6480, 1.0e-3 above the printed one
    assert ratio == pytest.approx(1.647, abs=1.1e-3)
    lean = math.pi / 2 - math.acos(0.075 / 0.2)
    stroke = 2 * 0.36 * math.sin(lean)
    assert dcs["outer"].x - dcs["inner"].x == pytest.approx(stroke, rel=1e-12)


def test_shaper_cuts_on_the_slow_stroke_only(tmp_path):
    """The cutting force acts over the 224° of the working stroke and not on the return; its
    work per cycle is −F·0.9·stroke (over s = 0.05 … 0.95), which the constant driving
    moment supplies: M_D = F·0.9·stroke/2π (gravity does no net work)."""
    res = analyze(load_case(CASES / "shaper.toml"))
    stroke = 2 * 0.36 * math.sin(math.pi / 2 - math.acos(0.075 / 0.2))
    W = 2500.0 * 0.9 * stroke
    assert res.scalars.cycle_work_resistance == pytest.approx(-W, rel=1e-9)
    assert res.scalars.driving_moment == pytest.approx(W / (2 * math.pi), rel=1e-9)
    F = res.columns["F_cutting"].values
    phi = np.degrees(res.phi)
    out = math.degrees(math.pi / 2 - math.acos(0.075 / 0.2))        # outer dead centre, 22.02°
    ret = (phi > out + 1) & (phi < out + 2 * math.degrees(math.acos(0.075 / 0.2)) - 1)
    assert np.all(F[ret] == 0) and F.max() == 2500.0
    vx = res.kinematics.points["R"].v_q[:, 0]
    assert np.all(vx[F > 0] >= 0)                                   # cutting towards +x
    cli = runner.invoke(app, ["run", str(CASES / "shaper.toml"), "--out", str(tmp_path / "o")])
    assert cli.exit_code == 0, cli.output
    assert "cases/shaper.toml" in (CASES.parent / "README.md").read_text(encoding="utf-8")


def toggle_press() -> Mechanism:
    """A crank press with a toggle (кривошипно-коленный пресс): crank 1 (0.08 m) drives the
    connecting rod 2 to the knee B, where the upper toggle link 3 (about the fixed D) and the
    lower toggle link 4 meet; link 4 drives the slide 5 down a vertical guide. Groups: RRR
    (2, 3) from the crank pin and D, then RRP (4, 5) from the knee — a six-bar."""
    crank = Crank("1", "O", (0.0, 0.0), "A", 0.08, 0.0, 1)
    return Mechanism(crank, (RRR("B", "A", "2", 0.35, "D", "3", 0.25, "B", -1),
                             RRP("C", "B", "C", "4", 0.3, "5", Guide((0.3, 0.0), -math.pi / 2))),
                     (LinkPoint("S2", "2", "A", "B", 0.5),
                      LinkPoint("S4", "4", "B", "C", 0.5)),
                     {"D": (0.3, 0.4)})


def test_toggle_press_kinematics_against_numerical_derivatives():
    mech = toggle_press()
    phi0 = np.radians(np.arange(3.0, 360.0, 17.0))
    assert check_numerical(mech, phi0, 0.3) == 2 * (7 + 5)
    k = solve(mech, np.linspace(0, 2 * np.pi, 721))
    # loop closure: every link keeps its length, the slide stays on its guide
    for a, b, L in (("A", "B", 0.35), ("D", "B", 0.25), ("B", "C", 0.3)):
        assert np.allclose(np.hypot(*(k.points[a].r - k.points[b].r).T), L, rtol=1e-13)
    assert np.allclose(k.points["C"].r[:, 0], 0.3, atol=1e-15)
    # near the straightened toggle the slide's speed ratio falls: the press's mechanical advantage
    vy = np.abs(k.points["C"].v_q[:, 1])
    u, w = k.points["B"].r - k.points["D"].r, k.points["C"].r - k.points["B"].r
    straight = np.argmin(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]))   # the toggle in line
    assert vy[straight] < 0.15 * vy.max()


def test_shaper_and_four_bar_with_a_slider_against_numerical_derivatives():
    """The shaper of cases/shaper.toml (RPR, then RRP from a point of the lever) and a
    four-bar whose coupler point drives a slider (RRR, then RRP from [points])."""
    mech = load_case(CASES / "shaper.toml").mechanism()
    phi0 = np.radians(np.arange(5.0, 360.0, 19.0))
    assert check_numerical(mech, phi0, 0.3) > 0
    fb = load_case(CASES / "fourbar.toml").mechanism()
    coupler = [p.name for p in fb.points if p.link == "2"][0]
    mech = Mechanism(fb.crank, fb.dyads + (RRP("G", coupler, "G", "6", 0.5, "7",
                                               Guide((0.0, -0.25), 0.0)),), fb.points, fb.ground)
    assert check_numerical(mech, phi0, 0.3) > 0


def test_a_slotted_link_group_lists_its_links_in_the_order_of_its_chain(tmp_path):
    """The shaper's group RPR is block 2 on the crank pin, then the lever 3 (the course writes
    «группа звеньев 2, 3»): the record's structure, `check`, the force polygons and the link
    tables list 2 before 3. They had said «звенья 3, 2» and ordered the links 1, 3, 2, 4, 5."""
    mech = load_case(CASES / "shaper.toml").mechanism()
    assert [d.links for d in mech.dyads] == [("2", "3"), ("4", "5")]
    res = solve(mech, np.radians([60.0]))
    assert list(res.links) == ["1", "2", "3", "4", "5"]
    out = tmp_path / "o"
    run = runner.invoke(app, ["run", str(CASES / "shaper.toml"), "--no-plots", "--lang", "ru",
                              "-o", str(out)])
    assert run.exit_code == 0, run.output
    assert "вида ВПВ: звенья 2, 3" in (out / "report.md").read_text(encoding="utf-8")
    check = runner.invoke(app, ["check", str(CASES / "shaper.toml"), "--lang", "ru"],
                          env={"COLUMNS": "200"})
    assert "2, 3" in check.stdout and "3, 2" not in check.stdout
