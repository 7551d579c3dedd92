"""Four-stroke engines (issue 13 items 2–5): indicator diagrams stroke by stroke over a 720°
cycle, firing orders, multi-throw crankshafts, and the bundled engine cases.

Independent truths: the cycle work of a cylinder is the area of its indicator diagram times
the bore area and the stroke, integrated here by scipy/numpy from the case's own tables; the
pressure at an angle is the table at the closed-form slider-crank travel; the in-line four's
reciprocating inertia torque against its closed form; an engine's ΔT_нб as cylinders are added.
"""
from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.run import load_case, parse_case
from flywheel.cli import app
from flywheel.dynamics.loads import LoadKey
from flywheel.dynamics.pipeline import analyze
from flywheel.errors import CaseFileError, InputError
from flywheel.io.toml import read_toml
from helpers import check_numerical  # 8th-order central differences (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
STROKES = ("intake", "compression", "expansion", "exhaust")
runner = CliRunner()


def single():
    return read_toml(CASES / "engine_4stroke.toml")


def parsed(data, name="e.toml"):
    return parse_case(data, name)


def diagram_area(cy: dict, method: str = "linear") -> float:
    """∮ (p/p_max) ds of a four-stroke diagram: the strokes away from the head (intake,
    expansion) give the gas work, those towards it (compression, exhaust) take it back.
    Linear tables by scipy's trapezoid rule (exact for a polyline), pchip by scipy's own
    monotone cubic integrated exactly — not through the code under test."""
    from scipy.integrate import trapezoid

    s = np.asarray(cy["s"], float)
    st = cy["strokes"]
    if method == "linear":
        integral = {k: trapezoid(np.asarray(st[k], float), s) for k in STROKES}
    else:
        from scipy.interpolate import PchipInterpolator

        integral = {k: float(PchipInterpolator(s, st[k]).integrate(0.0, 1.0)) for k in STROKES}
    return (integral["expansion"] + integral["intake"] - integral["compression"]
            - integral["exhaust"])


# -- item 2: four strokes ---------------------------------------------------------------------

@pytest.mark.parametrize("method", ["linear", "pchip"])
def test_cycle_work_is_the_indicator_diagram_area(method):
    """W = p_max·∮(p/p_max) ds·(πd²/4)·stroke per cylinder and cycle; the engine's constant
    resistance takes exactly that: A_C = −W over the 720° cycle, M_C = −W/4π. Gravity does no
    net work; the stroke of a central slider-crank is 2r."""
    data = single()
    cy = data["cylinders"][0]
    cy["interpolation"] = method
    r = analyze(parsed(data), n_points=7200)
    stroke = 2 * data["crank"]["length"]
    W = cy["p_max"] * diagram_area(cy, method) * math.pi * cy["bore"] ** 2 / 4 * stroke
    assert W > 0                                                   # the gas drives
    assert r.scalars.cycle_work_resistance == pytest.approx(-W, rel=2e-6)
    assert r.scalars.balancing_moment == pytest.approx(-W / (4 * math.pi), rel=2e-6)
    assert r.scalars.driving_moment == pytest.approx(W / (4 * math.pi), rel=2e-6)
    assert r.scalars.balance == "resistance" and r.scalars.cycle_deg == 720


def test_two_stroke_engine_is_two_tables_over_one_revolution():
    """A two-stroke engine: compression towards the head, expansion away from it, every
    revolution (docs/case-format.md): W = p_max·∫(p_exp − p_comp) ds·(πd²/4)·stroke per 360°."""
    data = single()
    cy = data["cylinders"][0]
    st = cy.pop("strokes")
    cy.pop("fires_at_deg")
    cy.update(towards_head=st["compression"], away_from_head=st["expansion"])
    data["machine"]["cycle_deg"] = 360
    r = analyze(parsed(data), n_points=3600)
    s = np.asarray(cy["s"])
    W = (cy["p_max"] * (np.trapezoid(st["expansion"], s) - np.trapezoid(st["compression"], s))
         * math.pi * cy["bore"] ** 2 / 4 * 2 * data["crank"]["length"])
    assert r.scalars.cycle_work_resistance == pytest.approx(-W, rel=2e-6)
    assert r.scalars.driving_moment == pytest.approx(W / (2 * math.pi), rel=2e-6)


def test_pressure_stroke_by_stroke_at_the_closed_form_travel():
    """At an angle inside each stroke the pressure is that stroke's table at the travel of the
    centric slider-crank, s = (r + l − x)/(2r), x = r·cos φ + √(l² − r² sin² φ): expansion from
    the firing at 0°, exhaust from 180°, intake from 360°, compression from 540°."""
    data = single()
    cy = data["cylinders"][0]
    r_, l_ = data["crank"]["length"], data["dyads"][0]["rod_length"]
    at = [20.0, 250.0, 400.0, 700.0]
    res = analyze(parsed(data), n_points=720, at_deg=at)
    c = res.cylinders[0]
    for a, name in zip(at, ("expansion", "exhaust", "intake", "compression")):
        phi = math.radians(a)
        x = r_ * math.cos(phi) + math.sqrt(l_ ** 2 - (r_ * math.sin(phi)) ** 2)
        s = (r_ + l_ - x) / (2 * r_)
        want = np.interp(s, cy["s"], cy["strokes"][name]) * cy["p_max"]
        i = res.index_of(phi)
        assert c.p[i] == pytest.approx(want, rel=1e-12), name
        assert c.F[i] == pytest.approx(want * math.pi * cy["bore"] ** 2 / 4, rel=1e-12)
        assert STROKES[c.stroke[i]] == name


def test_firing_in_the_second_revolution_shifts_the_cycle_by_360():
    """fires_at_deg = 360: the same engine, its cycle half a cycle later: the gas moment at φ
    equals the first one's at φ − 360°."""
    a = analyze(parsed(single()), n_points=720)
    data = single()
    data["cylinders"][0]["fires_at_deg"] = 350.0          # the head dead centre nearest: 360°
    b = analyze(parsed(data), n_points=720)
    Ma, Mb = a.M_parts[LoadKey("gas", "1")], b.M_parts[LoadKey("gas", "1")]
    tol = dict(rtol=1e-9, atol=1e-9 * np.abs(Ma).max())
    assert a.phi.size == 721                                # 1° nodes: 360° is 360 nodes
    assert np.allclose(Mb[360:], Ma[:361], **tol) and np.allclose(Mb[:361], Ma[360:], **tol)
    assert b.cylinders[0].fires_at == pytest.approx(2 * math.pi)
    assert b.scalars.delta_T_max == pytest.approx(a.scalars.delta_T_max, rel=1e-9)


def test_engine_case_runs_end_to_end(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    out = tmp_path / "o"
    assert (out / "plots" / "indicator_1.png").exists()
    rows = (out / "positions.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(rows) == 24 and rows[12].startswith("360° = 3 outer d.c.")


# -- bad input ----------------------------------------------------------------------------------

def _error(data) -> str:
    with pytest.raises(CaseFileError) as e:
        parsed(data)
    msg = str(e.value)
    assert "\n" not in msg
    return msg


def test_a_720_diagram_for_a_360_cycle():
    data = single()
    data["machine"]["cycle_deg"] = 360
    assert _error(data) == (
        "e.toml: cylinders[0].strokes: a four-stroke diagram spans 720° of crank angle, the "
        "machine's cycle is 360° (allowed: machine.cycle_deg = 720, or a multiple of 720)")


def test_strokes_that_do_not_meet():
    data = single()
    data["cylinders"][0]["strokes"]["expansion"][0] = 1.0        # a jump at firing
    msg = _error(data)
    assert msg.startswith("e.toml: cylinders[0].strokes.expansion: begins at p/p_max = 1 at "
                          "s = 0, where compression ends at 0.2639: the strokes do not meet "
                          "(a jump of 0.7361; allowed: at most join_tolerance = 0.02")
    data["cylinders"][0]["join_tolerance"] = 0.8                 # stated: allowed
    parsed(data)
    data = single()
    data["cylinders"][0]["strokes"]["compression"][-1] = 0.1     # intake ends at −0.0022
    assert "cylinders[0].strokes.compression: begins at p/p_max = 0.1 at s = 1, where intake " \
           "ends at -0.0022" in _error(data)


@pytest.mark.parametrize("change, words", [
    (lambda c: c.update(towards_head=[0.0] * 15), "cylinders[0].towards_head: give either "
                                                  "towards_head and away_from_head"),
    (lambda c: c["strokes"].update(exhaust=[0.0] * 3), "cylinders[0].strokes.exhaust: needs 15 "
                                                       "values, one per s (got 3)"),
    (lambda c: c["strokes"].pop("intake"), "cylinders[0].strokes.intake"),
    (lambda c: c.pop("strokes"), "cylinders[0].towards_head: missing"),
    (lambda c: c.update(strokes={**c["strokes"], "compression": [-0.03] * 15}, join_tolerance=1.0),
     "cylinders[0].strokes.compression: p/p_max = -0.03 gives -0.158 MPa gauge, below absolute "
     "vacuum"),
])
def test_bad_strokes(change, words):
    data = single()
    change(data["cylinders"][0])
    assert words in _error(data)


def test_fires_far_from_a_dead_centre():
    data = single()
    data["cylinders"][0]["fires_at_deg"] = 180.0
    with pytest.raises(InputError, match=r"^cylinders\[0\]\.fires_at_deg: 180° is 180° from the "
                                         r"nearest head dead centre of piston 3 \(0°, 360°\)"):
        analyze(parsed(data), n_points=360)
    res = runner.invoke(app, ["check", str(_write(data))])
    assert res.exit_code == 2 and "cylinders[0].fires_at_deg: 180°" in res.output


def _write(data) -> Path:
    import tempfile

    import tomli_w

    path = Path(tempfile.mkdtemp()) / "e.toml"
    path.write_bytes(tomli_w.dumps(data).encode())
    return path


# -- item 3: multi-throw crankshafts --------------------------------------------------------------

def inline4(keep=("1", "2", "3", "4"), order=None, **machine):
    """cases/engine_inline4.toml with only the cylinders ``keep`` (their rods, pistons, points)
    and the firing ``order`` (default: 1-3-4-2 restricted to them)."""
    d = read_toml(CASES / "engine_inline4.toml")
    d["dyads"] = [x for x in d["dyads"] if x["joint"][1:] in keep]      # pins B1 … B4
    links = {x[k] for x in d["dyads"] for k in ("rod", "slider")}
    d["points"] = {k: v for k, v in d["points"].items() if v["link"] in links}
    d["links"] = {k: v for k, v in d["links"].items() if k in links}
    d["cylinders"] = [c for c in d["cylinders"] if c["name"] in keep]
    d["machine"]["firing_order"] = order or [c for c in ("1", "3", "4", "2") if c in keep]
    d["machine"].update(machine)
    if all(x["from"] != "A2" for x in d["dyads"]):
        d["crank"].pop("pins")
    return d


def test_firing_angles_of_the_inline_four():
    """1-3-4-2 on throws 0°, 180°, 180°, 0°: 1 at 0°, 3 at 180°, 4 at 360°, 2 at 540°; 1-2-4-3
    is an order of the same crankshaft too."""
    for order, want in ((["1", "3", "4", "2"], {"1": 0, "3": 180, "4": 360, "2": 540}),
                        (["1", "2", "4", "3"], {"1": 0, "2": 180, "4": 360, "3": 540})):
        r = analyze(parsed(inline4(order=order)), n_points=720)
        got = {c.name: math.degrees(c.fires_at) for c in r.cylinders}
        assert got == pytest.approx(want, abs=1e-9), order


def test_inline_four_reciprocating_inertia_torque_closed_form():
    """The pistons' inertia torque at constant ω, −½ω²·dJ_II/dφ (only the pistons have mass),
    against the closed forms. Exact: each piston on its throw α_k = φ − β_k (β = 0, π, π, 0)
    has y = r cos α + √(l² − r² sin² α), and M = −m ω² Σ y′ y″. Series (Артоболевский;
    λ = r/l): one cylinder's M = m r² ω² [(λ/4) sin α − ½ sin 2α − (3λ/4) sin 3α
    − (λ²/4) sin 4α] + O(λ³); over the four the first-order terms (sin φ, sin 3φ) cancel and the
    second-order ones add: M = m r² ω² (−2 sin 2φ − λ² sin 4φ) + O(λ³)."""
    d = inline4()
    pistons = {c["piston"] for c in d["cylinders"]}
    d["links"] = {k: v for k, v in d["links"].items() if k in pistons}       # pistons only
    d["cylinders"], d["machine"]["gravity"] = [], [0.0, 0.0]
    d["machine"].pop("firing_order")
    d["machine"]["balance"] = "driving"       # no work to balance (a "resistance" would refuse it)
    r = analyze(parsed(d), n_points=720)
    phi, w = r.phi, r.scalars.omega_mean
    m, rr, ll = 0.45, 0.04, 0.16
    lam, unit = rr / ll, m * rr ** 2 * w ** 2
    M = -0.5 * w ** 2 * r.reduction.dJ_II

    def y1y2(a):
        s, c = np.sin(a), np.cos(a)
        q = np.sqrt(ll ** 2 - rr ** 2 * s ** 2)
        y1 = -rr * s - rr ** 2 * s * c / q
        y2 = -rr * c - rr ** 2 * (c ** 2 - s ** 2) / q - rr ** 4 * s ** 2 * c ** 2 / q ** 3
        return y1, y2

    exact = sum(-m * w ** 2 * np.prod(y1y2(phi - b), axis=0) for b in (0, np.pi, np.pi, 0))
    assert np.allclose(M, exact, rtol=0, atol=1e-12 * unit)
    series = unit * (-2 * np.sin(2 * phi) - lam ** 2 * np.sin(4 * phi))
    assert np.max(np.abs(M - series)) < lam ** 3 * unit          # O(λ³) = 0.0156·m r² ω²

    def b(k, f):                        # sine coefficient over the cycle (the trapezoid rule)
        return 2 / r.cycle * np.trapezoid(f * np.sin(k * phi), phi) / unit

    one = -m * w ** 2 * np.prod(y1y2(phi), axis=0)             # one cylinder, for comparison
    assert b(1, one) == pytest.approx(lam / 4, abs=lam ** 3) and abs(b(1, M)) < 1e-12
    assert b(3, one) == pytest.approx(-3 * lam / 4, abs=lam ** 3) and abs(b(3, M)) < 1e-12
    assert b(2, M) == pytest.approx(4 * b(2, one), rel=1e-9) == pytest.approx(-2, abs=lam ** 3)
    assert b(4, M) == pytest.approx(4 * b(4, one), rel=1e-9) == pytest.approx(-lam ** 2, abs=lam ** 3)


def test_delta_T_falls_as_cylinders_are_added_in_a_balanced_firing_order():
    """The same cylinder, one, two (1 and 4 on one throw: a firing every 360°) and four (1-3-4-2:
    every 180°): the energy to be stored, ΔT_нб, falls while the work per cycle grows with the
    cylinders; an uneven twin (1 and 2: firings 180° and 540° apart) is worse than the even one."""
    dT, work = {}, {}
    for keep in (("1",), ("1", "4"), ("1", "2", "3", "4")):
        s = analyze(parsed(inline4(keep))).scalars
        dT[len(keep)], work[len(keep)] = s.delta_T_max, -s.cycle_work_resistance
    assert dT[1] > dT[2] > dT[4] and dT[4] < 0.25 * dT[1]
    assert work[2] == pytest.approx(2 * work[1], rel=1e-9)
    assert work[4] == pytest.approx(4 * work[1], rel=1e-9)
    uneven = analyze(parsed(inline4(("1", "2"), order=["1", "2"]))).scalars.delta_T_max
    assert uneven > dT[2]


def test_a_firing_order_that_does_not_fit_the_crankshaft():
    data = inline4(order=["1", "2", "3", "4"])
    with pytest.raises(InputError) as e:
        analyze(parsed(data), n_points=360)
    assert str(e.value).startswith(
        "machine.firing_order: 1-2-3-4 does not fit in one 720° cycle: cylinder 4 (position 4) "
        "would fire at 720°, not before cylinder 1 fires again at 720°")
    res = runner.invoke(app, ["run", str(_write(data)), "--no-plots", "--out", str(_write(data).parent / "o")])
    assert res.exit_code == 2
    assert res.output.count("\n") == 1 and ": machine.firing_order: 1-2-3-4 does not fit" in res.output


@pytest.mark.parametrize("order, words", [
    (["1", "3", "4"], "machine.firing_order: cylinder '2' is missing"),
    (["1", "3", "4", "2", "5"], "machine.firing_order[4]: no cylinder named '5' (four-stroke "
                                "cylinders: 1, 2, 3, 4)"),
    (["1", "3", "3", "2"], "machine.firing_order[2]: cylinder '3' is already in the order"),
])
def test_a_firing_order_that_does_not_match_the_cylinders(order, words):
    assert words in _error(inline4(order=order))


def test_fires_at_only_on_the_first_of_an_order():
    data = inline4()
    data["cylinders"][2]["fires_at_deg"] = 180.0
    assert "cylinders[2].fires_at_deg: machine.firing_order sets where cylinder '3' fires" in _error(data)


def test_pins_at_the_same_angle_with_different_names():
    data = inline4()
    data["crank"]["pins"].append({"name": "A4", "angle_deg": 0.0})
    assert _error(data) == (
        "e.toml: crank.pins[1].angle_deg: 0° puts pin 'A4' where the crank's tip 'A1' is (same "
        "angle and throw): pins at the same angle are one pin with one name (allowed: attach the "
        "rods to 'A1', or give another angle)")
    data["crank"]["pins"][-1] = {"name": "A3", "angle_deg": -180.0}
    assert "crank.pins[1].angle_deg: -180° puts pin 'A3' where pin (crank.pins[0]) 'A2' is" in _error(data)
    data["crank"]["pins"][-1] = {"name": "A3", "angle_deg": 180.0, "length": 0.03}   # another throw
    parsed(data)
    data["crank"]["pins"][-1] = {"name": "A2", "angle_deg": 90.0}
    assert "crank.pins[1].name: point name 'A2' is already defined" in _error(data)


@pytest.mark.parametrize("layout", ["inline4", "boxer", "vtwin", "odd"])
def test_multi_throw_kinematics_against_numerical_derivatives(layout):
    """Pins at stated angles and throws, with slider dyads and a four-bar on them: every
    analogue against central differences of the positions; each pin stays on its circle at its
    angle to the tip."""
    from flywheel.linkage import RRP, RRR, Crank, CrankPin, Guide, Mechanism, solve

    r, l = 0.04, 0.16
    if layout == "inline4":       # 0, 180, 180, 0: two pins, four vertical cylinders
        crank = Crank("1", "O", (0.0, 0.0), "A1", r, math.pi / 2, -1, (CrankPin("A2", math.pi, r),))
        dyads = tuple(RRP(f"B{c}", p, f"B{c}", f"r{c}", l, f"p{c}", Guide((0.0, 0.0), math.pi / 2))
                      for c, p in ((1, "A1"), (2, "A2"), (3, "A2"), (4, "A1")))
    elif layout == "boxer":       # opposed cylinders on throws 180° apart
        crank = Crank("1", "O", (0.0, 0.0), "A1", r, 0.0, 1, (CrankPin("A2", math.pi, r),))
        dyads = (RRP("B1", "A1", "B1", "r1", l, "p1", Guide((0.0, 0.0), 0.0)),
                 RRP("B2", "A2", "B2", "r2", l, "p2", Guide((0.0, 0.0), math.pi)))
    elif layout == "vtwin":       # a 90° V, both rods side by side on one pin
        crank = Crank("1", "O", (0.0, 0.0), "A", r, math.pi / 2, -1)
        dyads = (RRP("B1", "A", "B1", "r1", l, "p1", Guide((0.0, 0.0), math.radians(45))),
                 RRP("B2", "A", "B2", "r2", l, "p2", Guide((0.0, 0.0), math.radians(135))))
    else:                         # a throw of another length at 73°, a four-bar on it
        crank = Crank("1", "O", (0.01, -0.02), "A", r, 0.3, 1,
                      (CrankPin("P", math.radians(73), 0.03),))
        dyads = (RRP("B", "A", "B", "2", l, "3", Guide((0.0, 0.0), 0.2, 0.01)),
                 RRR("C", "P", "4", 0.2, "D", "5", 0.15, "C"))
    mech = Mechanism(crank, dyads, (), {"D": (0.12, 0.13)} if layout == "odd" else {})
    phi0 = np.radians(np.arange(7.0, 360.0, 23.0))
    check_numerical(mech, phi0, 0.2)
    k = solve(mech, phi0)
    for pin in crank.pins:
        d = k.points[pin.name].r - np.asarray(crank.pivot_at)
        assert np.allclose(np.hypot(*d.T), pin.length, rtol=1e-14)
        tip = k.points[crank.tip].r - np.asarray(crank.pivot_at)
        between = np.arctan2(tip[:, 0] * d[:, 1] - tip[:, 1] * d[:, 0], np.sum(tip * d, axis=1))
        assert np.allclose(np.mod(between - pin.angle + np.pi, 2 * np.pi) - np.pi, 0, atol=1e-12)
    if layout == "boxer":          # opposed pistons: mirror images through the crank axis
        assert np.allclose(k.points["B1"].r, -k.points["B2"].r, atol=1e-15)


# -- item 4: the bundled engine cases ---------------------------------------------------------------

def test_inline_four_case_runs_end_to_end(tmp_path):
    """`flywheel run --no-plots --json` on cases/engine_inline4.toml: the 720° cycle, each
    cylinder's firing, the work of four cylinders of cases/engine_4stroke.toml."""
    import json

    res = runner.invoke(app, ["run", str(CASES / "engine_inline4.toml"), "--no-plots", "--json",
                              "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    r = json.loads(res.stdout)["results"]
    one = analyze(load_case(CASES / "engine_4stroke.toml")).scalars
    assert r["cycle_deg"] == 720 and r["balance"] == "resistance"
    assert r["cycle_work_resistance"] == pytest.approx(4 * one.cycle_work_resistance, rel=1e-9)
    assert r["delta_T_max"] < 0.25 * one.delta_T_max
    header = (tmp_path / "o" / "table.csv").read_text(encoding="utf-8").splitlines()[0]
    assert all(f"stroke_{c} [-]" in header for c in "1234")
    rows = (tmp_path / "o" / "positions.csv").read_text(encoding="utf-8").splitlines()[1:]
    assert len(rows) == 24                  # every 30° over 720°; the dead centres fall on them


@pytest.mark.parametrize("name", ["engine_4stroke.toml", "engine_inline4.toml"])
def test_engine_cases_are_listed_in_the_readme_and_checked(name):
    readme = (CASES.parent / "README.md").read_text(encoding="utf-8")
    assert f"cases/{name}" in readme
    res = runner.invoke(app, ["check", str(CASES / name)])
    assert res.exit_code == 0, res.output


def test_double_acting_pump_case(tmp_path):
    """cases/pump.toml end to end: both sides of the piston deliver once per revolution, so the
    work per revolution is p_d·(π/4)(d² + d_eq²)·stroke (the liquid switches between suction
    and delivery at the dead centres; d_eq² = d² − d_rod² for the rod side)."""
    import json

    res = runner.invoke(app, ["run", str(CASES / "pump.toml"), "--no-plots", "--json",
                              "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    r = json.loads(res.stdout)["results"]
    W = 1.2e6 * math.pi / 4 * (0.125 ** 2 + 0.118427 ** 2) * 0.2
    # the trapezoid rule on F·dx/dφ at the default grid: 2.5e-7 (O(h²))
    assert r["cycle_work_resistance"] == pytest.approx(-W, rel=1e-6)
    assert r["driving_moment"] == pytest.approx(W / (2 * math.pi), rel=1e-6)
    assert r["flywheel_J_on_its_shaft"] == pytest.approx(r["J_flywheel"] / 100, rel=1e-12)
    assert "cases/pump.toml" in (CASES.parent / "README.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("name", ["engine_4stroke.toml", "engine_inline4.toml"])
def test_kinetostatics_closes_on_the_engines(name):
    """The force analysis (flywheel.dynamics.forces) of the engines with the true motion:
    the balancing moment on the crank, found group by group from the last rod back to the
    pins, equals the constant moment of the cycle balance at every node (design.md §9: the
    equation of motion read backwards), and Zhukovsky's lever agrees. An independent check of
    the pins, the four-stroke gas forces and ω(φ), ε(φ) over the 720° cycle."""
    from helpers import case_setup          # the loads built in the test, not by the pipeline

    from flywheel.dynamics import forces as fo

    st = case_setup(name.removesuffix(".toml"))
    mech, kin, w, e, loads = st["mech"], st["kin"], st["omega"], st["eps"], st["loads"]
    s = st["res"].scalars
    fa = fo.kinetostatics(mech, kin, w, e, loads)
    assert fo.closure(fa, s.balancing_moment) < 1e-10
    lever = fo.zhukovsky_moment(mech, kin, w, e, loads)
    assert np.max(np.abs(lever - fa.balancing_moment)) < 1e-10 * abs(s.balancing_moment)


def _twin(layout: str) -> dict:
    """Two cylinders of cases/engine_4stroke.toml as a 90° V-twin (both rods side by side on
    the one pin, guides at 45° and 135°) or a boxer (a pin at 180°, opposed guides at 0° and
    180°); the crank clockwise from the upward vertical, firing order 1-2."""
    d = single()
    cyl = d["cylinders"][0]
    cyl.pop("fires_at_deg")
    rod, piston = dict(d["dyads"][0]), d["links"]["3"]
    guides = {"vtwin": ((45.0, "A"), (135.0, "A")), "boxer": ((0.0, "A"), (180.0, "A2"))}[layout]
    if layout == "boxer":
        d["crank"]["pins"] = [{"name": "A2", "angle_deg": 180.0}]
    d["dyads"], d["cylinders"], d["points"], d["links"] = [], [], {}, {}
    for k, (angle, pin) in enumerate(guides, start=1):
        d["dyads"].append({**rod, "from": pin, "joint": f"B{k}", "rod": f"r{k}", "slider": f"p{k}",
                           "guide": {"through": [0.0, 0.0], "angle_deg": angle}})
        d["points"][f"S{k}"] = {"link": f"r{k}", "from": pin, "to": f"B{k}", "fraction": 0.3}
        d["links"][f"r{k}"] = {"mass": 0.55, "J_S": 0.0016, "centroid": f"S{k}"}
        d["links"][f"p{k}"] = {**piston, "centroid": f"B{k}"}
        d["cylinders"].append({**copy.deepcopy(cyl), "name": str(k), "piston": f"p{k}"})
    d["machine"]["firing_order"] = ["1", "2"]
    return d


@pytest.mark.parametrize("layout, fires", [("vtwin", (45.0, 315.0)), ("boxer", (90.0, 450.0))])
def test_v_twin_and_boxer_fire_where_their_cranks_point_up_their_cylinders(layout, fires):
    """A centric cylinder's head dead centre is where its throw points along its guide towards
    the head: θ1 = 90° − φ (+180° for the boxer's second throw) equal to the guide's angle.
    90° V-twin: 1 at 45°, 2 at 315° (firing intervals 270° and 450°, the uneven V-twin beat);
    boxer: both throws point to their heads at 90°, so 1 fires at 90° and 2 at 450° (evenly,
    360° apart); the two cylinders' work is twice the single's."""
    r = analyze(parsed(_twin(layout)), n_points=7200)
    got = tuple(math.degrees(c.fires_at) for c in r.cylinders)
    assert got == pytest.approx(fires, abs=1e-9)
    one = analyze(parsed(single()), n_points=7200).scalars
    assert r.scalars.cycle_work_resistance == pytest.approx(2 * one.cycle_work_resistance,
                                                               rel=1e-6)


def test_offset_engine_and_a_cycle_of_four_revolutions():
    """An offset (désaxé) engine, the dead centres not 180° apart: the strokes still change at
    the exact dead centres, and the cycle work is the diagram's area times the bore area and
    the stroke between them, √((l+r)² − e²) − √((l−r)² − e²). Over a cycle of 1440° the
    four-stroke pattern runs twice: twice the work, the same balancing moment."""
    data = single()
    data["dyads"][0]["guide"]["offset"] = 0.012
    cy = data["cylinders"][0]
    r_, l_, e = 0.04, 0.16, 0.012
    stroke = math.sqrt((l_ + r_) ** 2 - e ** 2) - math.sqrt((l_ - r_) ** 2 - e ** 2)
    W = cy["p_max"] * diagram_area(cy) * math.pi * cy["bore"] ** 2 / 4 * stroke
    res = analyze(parsed(data), n_points=7200)
    assert res.scalars.cycle_work_resistance == pytest.approx(-W, rel=2e-6)
    # the dead centres of this offset slider-crank (guide x = −e, crank clockwise from the
    # vertical): outer at −asin(e/(l + r)), inner at 180° − asin(e/(l − r)); fires_at_deg = 0
    # picks the outer one nearest to 0°, −3.44° ≡ 716.56°
    outer = -math.degrees(math.asin(e / (l_ + r_)))
    inner = 180.0 - math.degrees(math.asin(e / (l_ - r_)))
    c = res.cylinders[0]
    assert math.degrees(c.fires_at) == pytest.approx(720.0 + outer, abs=1e-9)
    phis = np.degrees(res.phi)
    first = {STROKES[k]: phis[np.argmax(c.stroke == k)] for k in range(4)}  # first node of each
    assert first["expansion"] == 0.0
    assert first["exhaust"] == pytest.approx(inner, abs=1e-9)
    assert first["intake"] == pytest.approx(360.0 + outer, abs=1e-9)
    assert first["compression"] == pytest.approx(360.0 + inner, abs=1e-9)
    data["machine"]["cycle_deg"] = 1440
    res4 = analyze(parsed(data), n_points=14400)
    assert res4.scalars.cycle_work_resistance == pytest.approx(-2 * W, rel=2e-6)
    assert res4.scalars.balancing_moment == pytest.approx(res.scalars.balancing_moment, rel=1e-9)
    assert res4.scalars.delta_T_max == pytest.approx(res.scalars.delta_T_max, rel=1e-9)


# -- a four-stroke diagram as one table over the cycle --------------------------------------------

def _as_loop(data: dict) -> dict:
    """engine_4stroke.toml's strokes as one table over the cycle, from the firing: expansion
    s 0 → 1, exhaust 1 → 0, intake 0 → 1, compression 1 → 0 (each dead centre once)."""
    cy = data["cylinders"][0]
    s, st = cy.pop("s"), cy.pop("strokes")
    loop_s, loop_p = list(s), list(st["expansion"])
    for name, up in (("exhaust", False), ("intake", True), ("compression", False)):
        ss, pp = (s, st[name]) if up else (s[::-1], st[name][::-1])
        loop_s += ss[1:]
        loop_p += pp[1:]              # the dead centre is shared: the strokes meet (within 0.02)
    cy["diagram"] = {"s": loop_s, "p": loop_p}
    return data


def test_one_table_over_the_cycle_equals_the_four_strokes():
    """The same diagram as one table gives the same pressures bit for bit (split into the same
    four strokes), and the cycle work is the area of the closed polygon by the shoelace
    formula, p_max·πd²/4·stroke·|Σ (s_i p_{i+1} − s_{i+1} p_i)/2|, independent of how the
    program splits it."""
    a = analyze(parsed(single()), n_points=7200)
    data = _as_loop(single())
    b = analyze(parsed(data), n_points=7200)
    cy = data["cylinders"][0]
    s, p = np.asarray(cy["diagram"]["s"]), np.asarray(cy["diagram"]["p"])
    area = 0.5 * abs(np.sum(s * np.roll(p, -1) - np.roll(s, -1) * p))
    W = cy["p_max"] * area * math.pi * cy["bore"] ** 2 / 4 * 2 * data["crank"]["length"]
    assert b.scalars.cycle_work_resistance == pytest.approx(-W, rel=2e-6)
    assert np.array_equal(a.cylinders[0].p, b.cylinders[0].p)
    assert b.scalars.delta_T_max == a.scalars.delta_T_max


@pytest.mark.parametrize("change, words", [
    (lambda d: d["s"].__setitem__(0, 0.1), "cylinders[0].diagram.s[0]: 0.1: the diagram begins at "
                                           "the head dead centre where the cylinder fires"),
    (lambda d: d["s"].__setitem__(3, 0.04), "cylinders[0].diagram.s[3]: 0.04 after 0.05: on the "
                                            "expansion stroke s must grow to 1"),
    (lambda d: d.update(s=d["s"][:20], p=d["p"][:20]), "cylinders[0].diagram.s: ends inside the "
                                                       "exhaust stroke"),
    (lambda d: d.update(s=d["s"] + [0.5], p=d["p"] + [0.0]), "cylinders[0].diagram.s[57]: goes on "
                                                             "after compression closed the cycle"),
    (lambda d: (d["s"].insert(15, 1.0), d["p"].insert(15, 0.3)),
     "cylinders[0].diagram.p[15]: steps from p/p_max = 0.0734 to 0.3 at s = 1, where expansion "
     "ends and exhaust begins: the strokes do not meet (a jump of 0.2266"),
    (lambda d: d["p"].__setitem__(-1, 0.5), "cylinders[0].diagram.p[56]: steps from p/p_max = "
                                            "0.2639 to 0.5 at s = 0, where compression ends and "
                                            "expansion began"),
    (lambda d: d["p"].pop(), "cylinders[0].diagram.p: needs 57 values, one per s (got 56)"),
])
def test_bad_tables_over_the_cycle(change, words):
    data = _as_loop(single())
    change(data["cylinders"][0]["diagram"])
    assert words in _error(data)


def test_a_diagram_and_stroke_tables_together():
    data = _as_loop(single())
    data["cylinders"][0]["s"] = [0.0, 1.0]
    assert "cylinders[0].s: give either diagram (one table over the cycle) or s with its " \
           "tables, not both" in _error(data)
    data = _as_loop(single())
    data["machine"]["cycle_deg"] = 360
    assert "cylinders[0].diagram: a four-stroke diagram spans 720°" in _error(data)
