"""The plans drawn at the report angles (issue 12 item 6): velocity and acceleration plans, the
force polygons of the Assur groups, Zhukovsky's lever, their scales, and their drawings.

Truths used, none of them the code under test (flywheel.dynamics.plans): the points'
velocities and accelerations as numerical derivatives of their positions (central differences
of linkage.solve at φ ± h, with the force analysis's ω and ε: v = r′·ω, a = r″·ω² + r′·ε);
a rigid link's ω and ε from two of its points, ω = (d × Δv)/|d|², ε = (d × Δa)/|d|²; the
rocker's point under a slotted link's block as the rocker-fixed point it is, turned with the
rocker's numerical angle; Newton's second law for each group (its forces sum to zero); the
balancing moment of the kinetostatics (flywheel.dynamics.forces, a different formulation:
moment equations of the groups, not the lever); the scale rule (1, 2, 2.5, 5 × 10^k and
60–120 mm) checked from its statement.
"""
from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics import plans
from flywheel.dynamics.pipeline import analyze
from flywheel.linkage import solve
from flywheel.linkage.mechanism import RPR

CASES = Path(__file__).resolve().parents[2] / "cases"
NAMES = ["compressor", "fourbar", "slotted_link", "shaper", "engine_inline4"]
H = 1e-4                     # [rad] step of the central differences


@pytest.fixture(scope="module", params=NAMES)
def run(request):
    case = load_case(CASES / f"{request.param}.toml")
    return request.param, case, case.mechanism(), analyze(case, n_points=360)


def _numeric(mech, phi: float, w: float, e: float) -> dict:
    """Each point's r, v, a at the crank angle phi [rad] by central differences, with the
    crank's ω, ε; each link's θ, ω, ε likewise; and the rocker-fixed point under each slotted
    link's block (name as the plan names it)."""
    k = solve(mech, np.array([phi - H, phi, phi + H]))
    out = {}

    def put(name, r):                 # r: (3, 2) at φ − h, φ, φ + h
        d1 = (r[2] - r[0]) / (2 * H)
        d2 = (r[2] - 2 * r[1] + r[0]) / H**2
        out[name] = (r[1], d1 * w, d2 * w * w + d1 * e)

    for n, pm in k.points.items():
        put(n, pm.r)
    for d in mech.dyads:
        if isinstance(d, RPR):
            th = np.unwrap(k.links[d.rocker].theta)
            P, A = k.points[d.pivot].r, k.points[d.origin].r
            rel = A[1] - P[1]
            turned = []
            for j in range(3):
                c, s = math.cos(th[j] - th[1]), math.sin(th[j] - th[1])
                turned.append(P[j] + np.array([c * rel[0] - s * rel[1], s * rel[0] + c * rel[1]]))
            put(f"{d.origin}{d.rocker}", np.array(turned))
    return out


def _cross(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def _at(run):
    name, case, mech, r = run
    assert r.plans and len(r.plans) == len(case.output.at_deg)
    for ps in r.plans:
        i = ps.index
        assert math.isclose(math.degrees(r.phi[i]), ps.phi_deg % r.cycle_deg, abs_tol=1e-9)
        w, e = float(r.forces.omega[i]), float(r.forces.epsilon[i])
        yield ps, i, _numeric(mech, float(r.phi[i]), w, e)


# -- the velocity plan -------------------------------------------------------------------------------

def test_velocity_images_are_the_derivatives_of_the_positions(run):
    for ps, i, num in _at(run):
        vp = ps.velocity
        big = max(np.hypot(*v) for v in vp.images.values())
        assert big > 0
        for point, img in vp.images.items():
            assert np.allclose(img, num[point][1], atol=1e-7 * big), (point, img, num[point][1])


def test_velocity_plan_closes(run):
    """v_B = v_A + v_BA: every relative vector runs from the image of its base to the image of
    its point (an RRR's second equation ends where the first put b), is perpendicular to the
    link (or along the slot) and as long as ω·l."""
    _, _, mech, r = run
    slots = {f"{d.origin}{d.rocker}": d for d in mech.dyads if isinstance(d, RPR)}
    for ps, i, num in _at(run):
        vp = ps.velocity
        big = vp.longest
        for v in vp.vectors:
            if v.kind == "absolute":
                assert np.allclose(v.tail, 0.0) and np.allclose(v.head, vp.images[v.to])
                continue
            d = num[v.to][0] - num[v.rel][0]
            dv = num[v.to][1] - num[v.rel][1]
            assert np.allclose(v.tail, vp.images[v.rel], atol=1e-9 * big)
            assert np.allclose(v.head, vp.images[v.to], atol=1e-7 * big), v.label
            assert np.allclose(v.vector, dv, atol=1e-7 * big), v.label   # v_B − v_A
            if v.kind == "relative":
                assert abs(v.vector @ d) <= 1e-9 * big * np.hypot(*d)     # ⊥ AB
                omega = _cross(d, dv) / (d @ d)                          # the link's ω
                assert math.isclose(v.value, abs(omega) * np.hypot(*d), rel_tol=1e-6,
                                    abs_tol=1e-9 * big)
            else:                                                        # along the slot
                s = slots[v.to]
                slot = num[s.origin][0] - num[s.pivot][0]
                assert abs(_cross(v.vector, slot)) <= 1e-7 * big * np.hypot(*slot)


# -- the acceleration plan ----------------------------------------------------------------------------

def test_acceleration_components(run):
    """aⁿ = v_rel²/l towards the centre, aτ = |ε|·l, aᵏ = 2·|ω|·|v_rel|, and each chain of
    components from a base's image ends at the point's absolute acceleration."""
    _, _, mech, r = run
    slots = {f"{d.origin}{d.rocker}": d for d in mech.dyads if isinstance(d, RPR)}
    seen = set()
    for ps, i, num in _at(run):
        ap = ps.acceleration
        big = ap.longest
        vec = list(ap.vectors)
        for v in vec:
            assert np.allclose(ap.images[v.to], num[v.to][2], atol=1e-6 * big), v.to
        for k, v in enumerate(vec):
            seen.add(v.kind)
            if v.kind == "absolute":
                assert np.allclose(v.head, num[v.to][2], atol=1e-6 * big)
                continue
            d = num[v.to][0] - num[v.rel][0]
            l = float(np.hypot(*d))
            dv = num[v.to][1] - num[v.rel][1]
            da = num[v.to][2] - num[v.rel][2]
            if v.kind == "normal":
                assert math.isclose(v.value, (dv @ dv) / l, rel_tol=1e-6, abs_tol=1e-7 * big)
                assert v.value == 0 or v.vector @ d < 0                     # towards the centre
                assert abs(_cross(v.vector, d)) <= 1e-9 * big * l
                assert np.allclose(v.tail, num[v.rel][2], atol=1e-6 * big)  # from the base's image
                t = vec[k + 1]
                assert t.kind == "tangential" and (t.to, t.rel) == (v.to, v.rel)
                assert np.allclose(np.add(v.tail, v.vector + t.vector), num[v.to][2],
                                   atol=1e-6 * big)                         # a_B = a_A + n + τ
            elif v.kind == "tangential":
                eps = _cross(d, da) / (d @ d)                               # the link's ε
                assert math.isclose(v.value, abs(eps) * l, rel_tol=1e-6, abs_tol=1e-6 * big)
                assert abs(v.vector @ d) <= 1e-9 * big * l
            elif v.kind == "coriolis":
                s = slots[v.to]
                rocker = num[s.pivot][0] - num[v.to][0]
                w3 = _cross(num[v.to][0] - num[s.pivot][0],
                            num[v.to][1] - num[s.pivot][1]) / (rocker @ rocker)
                v_rel = num[v.to][1] - num[s.origin][1]
                assert math.isclose(v.value, 2 * abs(w3) * np.hypot(*v_rel), rel_tol=1e-6,
                                    abs_tol=1e-6 * big)
                assert abs(v.vector @ v_rel) <= 1e-6 * big * max(np.hypot(*v_rel), 1e-12)
                t = vec[k + 1]
                assert t.kind == "sliding"
                assert abs(_cross(t.vector, rocker)) <= 1e-6 * big * np.hypot(*rocker)  # ∥ slot
                assert np.allclose(np.add(v.tail, v.vector + t.vector), num[v.to][2],
                                   atol=1e-6 * big)                         # a_A3 = a_A + k + r
                assert np.allclose(v.tail, num[s.origin][2], atol=1e-6 * big)
        pairs = {(v.to, v.rel) for v in vec if v.kind == "normal"}
        for d in mech.dyads:            # each group's equations, as the course writes them
            if isinstance(d, RPR):
                x = f"{d.origin}{d.rocker}"
                assert (x, d.pivot) in pairs and any(v.kind == "coriolis" and v.to == x for v in vec)
            elif hasattr(d, "guide"):
                assert (d.joint, d.origin) in pairs
            else:
                assert {(d.joint, d.point_a), (d.joint, d.point_b)} <= pairs
    name = run[0]
    assert {"absolute", "normal", "tangential"} <= seen
    if name in ("slotted_link", "shaper"):
        assert {"coriolis", "sliding"} <= seen


# -- the force polygons ---------------------------------------------------------------------------------

def test_force_polygons_close(run):
    """Each group's forces, head to tail, sum to zero (the group is in equilibrium); each
    inertia force is −m·a_S and each weight m·g; every group and the crank has a polygon."""
    _, case, mech, r = run
    g = np.asarray(case.machine.gravity, float)
    for ps, i, num in _at(run):
        assert len(ps.polygons) == len(mech.dyads) + 1
        assert ps.polygons[-1].kind == "crank"
        for pg in ps.polygons:
            assert pg.vectors
            total = np.zeros(2)
            for k, v in enumerate(pg.vectors):
                if k:
                    assert v.tail == pg.vectors[k - 1].head
                total = total + v.vector
                if v.kind == "inertia":
                    lk = case.links[v.rel]
                    assert np.allclose(v.vector, -lk.mass * num[lk.centroid][2],
                                       rtol=1e-6, atol=1e-6 * pg.longest)
                if v.kind == "weight":
                    assert np.allclose(v.vector, case.links[v.rel].mass * g)
            assert np.hypot(*total) <= 1e-10 * pg.longest, (pg.group, total)
            assert np.allclose(pg.vectors[0].tail, 0.0)
            for c in pg.chords:           # the whole reaction across: Rⁿ + Rτ
                parts = [v.vector for v in pg.vectors if v.label in (c.label + "^n", c.label + "^τ")]
                assert np.allclose(np.sum(parts, axis=0), c.vector)
                assert any(np.allclose(c.head, v.head) or np.allclose(c.head, v.tail)
                           for v in pg.vectors)


# -- Zhukovsky's lever ------------------------------------------------------------------------------------

def test_lever_moment_is_the_balancing_moment(run):
    """Σ (turned image × F) + Σ M·ω_i + M_y·ω = 0 about the pole: M_y equals the kinetostatics'
    M_y at that angle; the images are the velocity plan's turned 90° clockwise; the balancing
    force at the crank pin has the moment M_y·ω."""
    _, case, mech, r = run
    for ps, i, num in _at(run):
        lv = ps.lever
        w = float(r.forces.omega[i])
        for p, (x, y) in ps.velocity.images.items():
            assert lv.images[p] == pytest.approx((y, -x))
        total = sum(_cross(f.image, f.force) for f in lv.forces)
        for c in lv.couples:
            total += c.M * c.omega
            k = solve(mech, np.array([r.phi[i] - H, r.phi[i] + H])).links[c.link].theta
            dth = (k[1] - k[0] + math.pi) % (2 * math.pi) - math.pi
            assert math.isclose(c.omega, dth / (2 * H) * w, rel_tol=1e-6, abs_tol=1e-9 * w)
        My = -total / w
        ref = float(r.forces.analysis.balancing_moment[i])
        scale = max(abs(ref), float(np.max(np.abs(r.forces.analysis.first_group_couple))), 1.0)
        assert My == pytest.approx(ref, abs=1e-9 * scale)
        assert lv.balancing_moment == pytest.approx(ref, abs=1e-9 * scale)
        P = lv.balancing_force
        assert _cross(P.image, P.force) == pytest.approx(My * w, abs=1e-9 * scale * w)


# -- the scales --------------------------------------------------------------------------------------------

def _round(mu: float) -> bool:
    m = mu / 10 ** math.floor(math.log10(mu))
    return any(math.isclose(m, x, rel_tol=1e-12) for x in (1.0, 2.0, 2.5, 5.0, 10.0))


def test_scales_are_round_and_the_longest_vector_is_60_to_120_mm(run):
    for ps, i, num in _at(run):
        for plan in (ps.velocity, ps.acceleration) + ps.polygons:
            assert _round(plan.scale), plan.scale
            assert 60.0 < plan.longest / plan.scale <= 120.0 + 1e-9, (plan.longest, plan.scale)
        lv = ps.lever
        assert lv.scale == ps.velocity.scale
        forces = [np.hypot(*f.force) for f in lv.forces + (lv.balancing_force,)]
        assert _round(lv.force_scale) and 30.0 < max(forces) / lv.force_scale <= 60.0 + 1e-9


def test_round_scale():
    assert plans.round_scale(120.0) == 1.0                 # exactly 120 mm
    assert plans.round_scale(120.0001) == 2.0              # 60.00005 mm
    assert plans.round_scale(6.0) == 0.05                  # 120 mm
    assert plans.round_scale(0.0) == 1.0
    for x in np.geomspace(1e-4, 1e6, 157):
        mu = plans.round_scale(float(x))
        assert _round(mu) and 60.0 < x / mu <= 120.0 * (1 + 1e-12), (x, mu)


def test_steady_motion_plans_use_its_omega():
    """With the steady motion the lever's ω is ω_m and its M_y the steady kinetostatics'."""
    case = load_case(CASES / "compressor.toml")
    r = analyze(case, n_points=360, motion="steady")
    ps = r.plans[0]
    assert ps.velocity.omega == pytest.approx(case.machine.omega_mean)
    assert ps.acceleration.epsilon == 0.0
    assert ps.lever.balancing_moment == pytest.approx(
        float(r.forces.analysis.balancing_moment[ps.index]), rel=1e-9)


def test_tabulated_case_has_no_plans():
    from flywheel.render import plots_plans

    r = analyze(load_case(CASES / "press.toml"), n_points=360)
    assert r.plans == ()
    assert plots_plans.figures(r) == []


# -- the drawings -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("name", NAMES)
def test_plans_are_drawn(name, tmp_path):
    """The plan figures of each case (one report angle, to keep the test short) are written as
    PNG by run's own saving code, the same bytes twice; Russian too for the compressor."""
    from flywheel.render import plots

    case = load_case(CASES / f"{name}.toml")
    r = analyze(case, n_points=360, at_deg=case.output.at_deg[-1:])
    langs = ("en", "ru") if name == "compressor" else ("en",)
    for lang in langs:
        specs = plots.all_figures(r, lang)
        idx = [k for k, (n, _) in enumerate(specs) if n.startswith("plan_")]
        a = _fmt(case.output.at_deg[-1])
        assert [specs[k][0] for k in idx] == ["plan_positions.png", f"plan_velocity_{a}.png",
                                              f"plan_acceleration_{a}.png", f"plan_forces_{a}.png",
                                              f"plan_lever_{a}.png"]
        for run_ in ("1", "2") if lang == "en" and name == "compressor" else ("1",):
            folder = tmp_path / f"{lang}{run_}"
            folder.mkdir()
            plots._save_some(r, folder, lang, idx)
        for k in idx:
            data = (tmp_path / f"{lang}1" / specs[k][0]).read_bytes()
            assert data.startswith(b"\x89PNG\r\n\x1a\n") and len(data) > 10_000
            # A4's text width at most (issue 15): the PNG's width [px] from its IHDR at 120 dpi
            assert int.from_bytes(data[16:20], "big") <= 7.5 * 120, specs[k][0]
            if (tmp_path / f"{lang}2").exists():
                assert data == (tmp_path / f"{lang}2" / specs[k][0]).read_bytes(), specs[k][0]


def _fmt(a: float) -> str:
    return f"{a:g}".replace("-", "m").replace(".", "_")


@pytest.mark.parametrize("name", NAMES)
def test_force_polygon_panels_fit_a4_apart(name):
    """The force polygons at every report angle on A4's text width (≤ 7.5 in): each panel,
    measured with its title and tick labels as drawn, inside the page and clear of every other
    panel (rows as fit, the rest stacked); the legend below them all."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp

    r = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    with fg.style():
        for ps in r.plans:
            fig = pp.figure_force_polygons(r, ps)
            W, H = fig.get_size_inches()
            assert W <= 7.5 and H <= 11.0
            canvas = FigureCanvasAgg(fig)
            canvas.draw()
            ren = canvas.get_renderer()
            boxes = [ax.get_tightbbox(ren) for ax in fig.axes]
            assert len(boxes) == len(ps.polygons)
            for i, b in enumerate(boxes):
                assert b.x0 >= 0 and b.x1 <= W * fig.dpi and b.y0 >= 0 and b.y1 <= H * fig.dpi
                for j in range(i):
                    assert not b.overlaps(boxes[j]), (name, ps.phi_deg, i, j)
            leg = fig.legends[0].get_window_extent(ren)
            assert leg.x0 >= 0 and leg.x1 <= W * fig.dpi and leg.y0 >= 0
            assert leg.y1 <= min(b.y0 for b in boxes)
            fig.clear()


@pytest.mark.parametrize("name", NAMES)
def test_no_label_sits_on_another_on_any_plan(name):
    """Every text on the axes of the velocity and acceleration plans, the force polygons and
    Zhukovsky's lever at every report angle, measured as drawn on the A4-wide page: no two
    meet (issue 15; the crowded corners of the in-line four's polygons and the slotted link's
    group E had their values drawn over each other), and none leaves the page."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp

    r = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    with fg.style():
        for ps in r.plans:
            for build in (pp.figure_velocity_plan, pp.figure_acceleration_plan,
                          pp.figure_force_polygons, pp.figure_lever):
                fig = build(r, ps)
                canvas = FigureCanvasAgg(fig)
                canvas.draw()
                ren = canvas.get_renderer()
                W = fig.get_size_inches()[0] * fig.dpi
                for ax in fig.axes:
                    texts = [t for t in ax.texts if t.get_text()]
                    boxes = [t.get_window_extent(ren) for t in texts]
                    for i, a in enumerate(boxes):
                        assert 0 <= a.x0 and a.x1 <= W, (build.__name__, texts[i].get_text())
                        for j in range(i):
                            assert not a.overlaps(boxes[j]), (build.__name__, ps.phi_deg,
                                                              texts[i].get_text(),
                                                              texts[j].get_text())
                fig.clear()


@pytest.mark.parametrize("name", ["compressor", "slotted_link", "engine_4stroke"])
def test_position_numbers_match_the_drawing(name, tmp_path):
    """The course's position numbers: positions.csv and forces_positions.csv number each row
    as plan_positions.png numbers the crank's positions (0 … 11 every 30° from φ = 0, 0 … 23
    over the four-stroke's 720°); a dead centre between two 30° positions (the slotted link's)
    has no number, one on a 30° position shares its row's."""
    import csv as csv_

    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp
    from flywheel.render.forces import forces_positions_csv
    from flywheel.render.tables import positions_csv

    r = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    tables = [list(csv_.reader(text.splitlines())) for text in (positions_csv(r),
                                                                forces_positions_csv(r))]
    for rows in tables:
        assert rows[0][:3] == ["position", "number", "phi_deg [deg]"]
        for label, number, phi, *_ in rows[1:]:
            k = float(phi) / 30.0                       # the course: position k at 30°·k
            on_grid = abs(k - round(k)) < 1e-9
            assert number == (str(round(k)) if on_grid else ""), (label, phi)
            assert on_grid or "d.c." in label
    numbers = [int(row[1]) for row in tables[0][1:] if row[1]]
    assert numbers == list(range(24 if name == "engine_4stroke" else 12))
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    with fg.style():                                   # the numbers drawn, at crank pin and sliders
        fig = pp.figure_positions_plan(r)
        texts = fig.axes[0].texts
        drawn = {int(x) for t in texts for x in t.get_text().split(", ")}
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        boxes = [t.get_window_extent(canvas.get_renderer()) for t in texts]
        for i, a in enumerate(boxes):                  # none on another (the sliders' crowd)
            for j in range(i):
                assert not a.overlaps(boxes[j]), (texts[i].get_text(), texts[j].get_text())
        fig.clear()
    assert drawn == set(numbers)
    from flywheel.render.document import build_document

    want = [(row[0], row[1]) for row in tables[0][1:]]  # the report's tables: the same numbers
    for lang, no in (("en", "No."), ("ru", "№")):
        at_positions = [tb for tb in build_document(r, lang).tables if no in tb.header]
        assert len(at_positions) >= 4         # kinematics, reduction, energy, reactions
        for tb in at_positions:
            k = tb.header.index(no)
            assert [row[k] for row in tb.rows] == [n or "—" for _, n in want], tb.caption  # no number: a dash
    from flywheel.render import nomenclature as nm

    assert [lab for lab, _ in want] == [p.label for p in r.position_angles]
    # the tables give the number alone (its angle is the φ column beside it); the record names
    # the dead centres once, under the first of them, each at its number or its angle
    assert tb.header[:2] == ("№", "φ, °")
    _, note = nm.position_cells(r.position_angles, "ru")
    blocks = build_document(r, "ru").blocks
    assert [getattr(b, "text", "") for b in blocks].count(note) == 1
    said = {part.split(" — ")[0].lower(): part.split(" — ")[1] for part in note.rstrip(".").split("; ")}
    for p in r.position_angles:
        if p.dead_centres:
            where = f"положение {p.number}" if p.number is not None else \
                next(w for w in said if w.startswith("φ = ") and
                     abs(float(w[4:-1].replace(",", ".")) - math.degrees(p.phi)) < 0.1)
            assert {dc.slider for dc in p.dead_centres} == set(re.findall(r"\d+", said[where]))


def test_point_letters_do_not_touch_on_a_crowded_plan():
    """The slotted link's velocity plan at φ = 200°: six images within 15 mm (a₃ and s₃ 1 mm
    apart, their letters drawn over each other before); each point's bold letters are placed
    off the others' (issue 15: no label on a label)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp

    case = load_case(CASES / "slotted_link.toml")
    r = analyze(case, n_points=360, at_deg=[200.0])
    with fg.style():
        fig = pp.figure_velocity_plan(r, r.plans[0])
        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        ren = canvas.get_renderer()
        ax = fig.axes[0]
        bold = [t for t in ax.texts if t.get_fontweight() == "bold"]
        assert len(bold) >= 5
        boxes = [t.get_window_extent(ren) for t in bold]
        for i, a in enumerate(boxes):
            for j in range(i):
                assert not a.overlaps(boxes[j]), (bold[i].get_text(), bold[j].get_text())


def test_plan_images_keep_their_order_under_any_hash_seed():
    """The images (and so the letters drawn at one point, 'p, o, c') come in the same order
    whatever PYTHONHASHSEED is: no set's order reaches a plan (byte-identical reruns)."""
    import os
    import subprocess
    import sys

    code = ("from flywheel.cases.run import load_case; from flywheel.dynamics.pipeline import analyze; "
            f"r = analyze(load_case(r'{CASES / 'shaper.toml'}'), n_points=72, at_deg=[60.0]); "
            "print(list(r.plans[0].velocity.images))")
    out = {subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                          env={**os.environ, "PYTHONHASHSEED": seed}).stdout
           for seed in ("1", "2", "3")}
    assert len(out) == 1, out


def test_a_plans_notes_name_each_links_value_and_vector_as_the_course_does():
    """The compressor's acceleration plan at 120° (Russian): the links' ε as «ε₂ = …» with the
    value the plan holds (it had read «2 12,32», a link's number against its value) and a
    relative acceleration of a centroid as «aⁿ S₂A» (was «S2A» beside «πs₂»)."""
    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp
    from flywheel.render.numbers import fmt, typography

    r = analyze(load_case(CASES / "compressor.toml"), n_points=360, at_deg=[120.0])
    ps = r.plans[0]
    with fg.style(), typography("ru"):
        fig = pp.figure_acceleration_plan(r, ps, "ru")
        text = " ".join(t.get_text() for t in fig.texts).replace("\n", " ")
        eps_2 = fmt(ps.acceleration.links["2"], 4)
    assert f"ε₂ = {eps_2}" in text, text
    assert "aⁿ S₂A" in text and "S2" not in text, text


@pytest.mark.parametrize("name", NAMES)
def test_every_force_polygons_value_stays_inside_its_panel(name):
    """A force polygon's values are set inside their panel's frame: the shaper's group 4, 5 at
    60° had G₄'s value over the panel's tick labels (the placer lets a label out by a few
    points where the frame is crowded; the frame is grown instead)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp
    from flywheel.render.numbers import typography

    r = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    with fg.style(), typography("ru"):
        for ps in r.plans:
            fig = pp.figure_force_polygons(r, ps, "ru")
            ren = FigureCanvasAgg(fig).get_renderer()
            for ax in fig.axes:
                f = ax.get_window_extent(ren)
                for t in ax.texts:
                    b = t.get_window_extent(ren)
                    assert (f.x0 - 0.5 <= b.x0 and b.x1 <= f.x1 + 0.5 and f.y0 - 0.5 <= b.y0
                            and b.y1 <= f.y1 + 0.5), (ps.phi_deg, t.get_text())


def test_a_fractional_report_angle_is_written_with_a_decimal_comma_in_russian():
    """A report angle of 224.2° (compressor_given_flywheel's ω_max): the Russian plans' titles
    and the записка's captions write «φ = 224,2°» (they had «224.2°»)."""
    from flywheel.render import figure as fg
    from flywheel.render import plots_plans as pp
    from flywheel.render.document import _figure_caption
    from flywheel.render.numbers import typography

    r = analyze(load_case(CASES / "compressor.toml"), n_points=360, at_deg=[224.2])
    with fg.style("ru"), typography("ru"):
        for build in (pp.figure_velocity_plan, pp.figure_acceleration_plan,
                      pp.figure_force_polygons, pp.figure_lever):
            fig = build(r, r.plans[0], "ru")
            titles = " ".join(t.get_text() for t in fig.findobj(lambda o: hasattr(o, "get_text")))
            assert "φ = 224,2°" in titles and "224.2" not in titles, build.__name__
        assert _figure_caption("plan_velocity_224_2.png", "ru") == "План скоростей при φ = 224,2°"
        assert _figure_caption("plan_lever_m22_5.png", "ru") == "Рычаг Жуковского при φ = −22,5°"
    assert _figure_caption("plan_velocity_224_2.png", "en") == "Velocity plan at φ = 224.2°"
