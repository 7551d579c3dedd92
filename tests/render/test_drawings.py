"""The ЕСКД drawing sheets (render/drawings, docs/drawings.md): the layout, the title block, the
formats read back (pypdf, ezdxf), a plan measured in the DXF against the summary's
velocities, byte-identical reruns, the CLI."""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from flywheel.render.drawings.layout import pack
from flywheel.render.drawings.model import View, simplify
from flywheel.render.drawings.scheme import gost_scale
from flywheel.render.drawings.sheet import BLOCK_H, BLOCK_W, FORMATS, field_of, keep_out

ROOT = Path(__file__).resolve().parents[2]
MM_PER_PT = 25.4 / 72.0


def _overlap(a, b) -> bool:
    return a[0] < b[2] - 1e-6 and b[0] < a[2] - 1e-6 and a[1] < b[3] - 1e-6 and b[1] < a[3] - 1e-6


def _box_view(name, w, h) -> View:
    v = View(name)
    v.line((0, 0), (w, 0), (w, h), (0, h), closed=True)
    return v


def _a3_boxes(shapes):
    """(build, fill) of boxes named by ``shapes`` {name: (width, height) as shares of the A3
    field at sheet.ROOM}: build(room) the boxes at that room, fill(page) the page's boxes'
    area over the field."""
    from flywheel.render.drawings.sheet import ROOM

    x0, y0, x1, y1 = field_of("A3")
    W, H = x1 - x0, y1 - y0

    def build(room):
        f = room["plot_h"] / ROOM["A3"]["plot_h"]
        return [_box_view(n, a * W * f, b * H * f) for n, (a, b) in shapes.items()]

    def fill(page):
        return sum(v.size[0] * v.size[1] for v in page) / (W * H)

    return build, fill


# -- the pieces, fast ---------------------------------------------------------------------------

def test_gost_scales_are_the_largest_that_fit():
    # ГОСТ 2.302: 0.3 m in 200 mm → 1:2 (150 mm; 1:1 would be 300 mm); 0.05 m in 200 mm → 2.5:1
    assert gost_scale(0.3, 200.0) == (0.5, "1:2")
    assert gost_scale(0.05, 200.0) == (4.0, "4:1")
    assert gost_scale(2.0, 220.0) == (0.1, "1:10")
    assert gost_scale(0.5, 220.0, "ru") == (0.4, "1:2,5")      # ГОСТ 2.302: a decimal comma
    assert gost_scale(0.5, 220.0) == (0.4, "1:2.5")


def test_a_curve_thinned_stays_within_its_tolerance():
    xs = [i * 0.05 for i in range(3601)]
    pts = [(x, 30.0 * math.sin(x / 20.0)) for x in xs]
    kept = simplify(pts)
    assert len(kept) < len(pts) / 5
    # every original point within 0.05 mm of the segment of the thinned line over its abscissa
    import bisect

    xk = [p[0] for p in kept]
    worst = 0.0
    for x, y in pts:
        j = min(max(bisect.bisect_right(xk, x) - 1, 0), len(kept) - 2)
        (x0, y0), (x1, y1) = kept[j], kept[j + 1]
        d = abs((x - x0) * (y1 - y0) - (y - y0) * (x1 - x0)) / math.hypot(x1 - x0, y1 - y0)
        worst = max(worst, d)
    assert worst <= 0.05 + 1e-9


@pytest.mark.parametrize("size", ["A1", "A2", "A3"])
def test_packed_views_never_overlap_each_other_nor_the_title_block(size):
    views = [_box_view(f"v{k}", 60 + 37 * (k % 4), 40 + 23 * (k % 3)) for k in range(30)]
    sheets, left_out = pack(views, size)
    assert not left_out
    assert sum(len(s) for s in sheets) == 30
    fx0, fy0, fx1, fy1 = field_of(size)
    for placed in sheets:
        boxes = [v.box() for v in placed]
        for b in boxes:
            assert fx0 - 1e-6 <= b[0] and b[2] <= fx1 + 1e-6 and fy0 - 1e-6 <= b[1] \
                and b[3] <= fy1 + 1e-6
            assert not any(_overlap(b, k) for k in keep_out(size))
        for i, a in enumerate(boxes):
            for b in boxes[i + 1:]:
                assert not _overlap(a, b)


def test_views_side_by_side_with_their_captions_on_one_line_are_set_apart():
    """Two views whose tops (their captions) are level: the second moved CAPTION_GAP clear of
    the first, so that the captions read as two («…силами, 1:4 План сил звеньев 2, 3» read as
    one at GAP); where that would leave the field, a caption's line lower; where neither is
    free, at GAP; a view below is at GAP."""
    from flywheel.render.drawings.layout import CAPTION_GAP, _place
    from flywheel.render.drawings.sheet import GAP

    field = (0.0, 0.0, 200.0, 100.0)
    first = (0.0, 60.0, 80.0, 100.0)
    assert _place(50, 40, field, [first], 0)[0] == pytest.approx(80.0 + CAPTION_GAP)
    assert _place(50, 40, field, [first], 1)[0] == pytest.approx(80.0 + GAP)   # not a view
    from flywheel.render.drawings.layout import CAPTION_H

    right_edge = _place(115, 40, field, [first], 0)       # no room to the right: a line lower
    assert right_edge[0] == pytest.approx(80.0 + GAP)
    assert right_edge[3] == pytest.approx(100.0 - CAPTION_H)
    assert _place(115, 96, field, [first], 0)[3] == pytest.approx(100.0)    # no room below either
    lower = (0.0, 60.0, 80.0, 90.0)                       # its top 10 mm lower: not level
    assert _place(50, 40, field, [lower], 0)[0] == pytest.approx(80.0 + GAP)


@pytest.mark.parametrize("case", ["compressor", "engine_4stroke", "shaper"])
def test_the_captions_of_sheet_2_stand_apart(case):
    """Sheets 2 (A1): of two views side by side with level tops, the right one's caption (its
    topmost lettering) CAPTION_GAP or more from the left one's."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import sheet, sheet2
    from flywheel.render.drawings.layout import CAPTION_GAP, CAPTION_H

    res = analyze(load_case(Path(__file__).resolve().parents[2] / "cases" / f"{case}.toml"),
                  n_points=360)
    from flywheel.render.drawings.model import Text

    def caption(v):
        return max((t.box() for t in v.items if isinstance(t, Text)), key=lambda b: b[3])

    sheets, _ = pack(sheet2.views(res, "ru", sheet.ROOM["A1"]), "A1")
    level = 0
    for placed in sheets:
        for a in placed:
            for b in placed:
                ca, cb = caption(a), caption(b)
                if abs(ca[3] - cb[3]) < CAPTION_H and 0 <= cb[0] - ca[2] < 40:
                    level += 1
                    assert cb[0] - ca[2] >= CAPTION_GAP - 1.0, (a.name, b.name)
    assert level >= 2


def test_a_view_larger_than_the_field_is_left_out_by_name():
    sheets, left_out = pack([_box_view("huge", 500, 100), _box_view("small", 50, 50)], "A3")
    assert left_out == ["huge"] and [v.name for v in sheets[0]] == ["small"]


def test_the_room_is_grown_while_the_views_still_take_one_sheet():
    """fitted: views that take one sheet with room to spare are drawn larger (sheet.ROOM
    times the largest factor of GROW that still packs them onto one sheet)."""
    from flywheel.render.drawings import GROW, fitted
    from flywheel.render.drawings.sheet import ROOM

    x0, y0, x1, y1 = field_of("A3")
    rooms = []

    def build(room):          # two views as tall as the room's plot_h: 110 mm at ROOM × 1
        rooms.append(room["plot_h"] / ROOM["A3"]["plot_h"])
        h = 2.0 * room["plot_h"]
        return [_box_view("a", 150, h), _box_view("b", 150, h)]

    views, pages, left_out = fitted(build, "A3")
    assert len(pages) == 1 and not left_out
    # the largest factor whose views are at most the field's height (the two side by side)
    fits = [f for f in (1.0, *GROW) if 2.0 * ROOM["A3"]["plot_h"] * f <= y1 - y0]
    assert views[0].size[1] == pytest.approx(2.0 * ROOM["A3"]["plot_h"] * max(fits))
    assert max(fits) > 1.0 and rooms[0] == 1.0


def test_the_room_is_shrunk_where_that_saves_a_sheet():
    """fitted: views that take two sheets at sheet.ROOM are drawn at the largest factor of
    SHRINK that puts them on one; where none does, they stay as they are."""
    from flywheel.render.drawings import SHRINK, fitted
    from flywheel.render.drawings.sheet import ROOM

    x0, y0, x1, y1 = field_of("A3")

    def boxes(w, h):          # four views, w × h [mm] at ROOM × 1
        return lambda room: [_box_view(n, w * room["plot_h"] / ROOM["A3"]["plot_h"],
                                       h * room["plot_h"] / ROOM["A3"]["plot_h"])
                             for n in "abcd"]

    for (w, h), factor in (((100, 120), 0.9), ((120, 150), 0.8)):
        build = boxes(w, h)
        # the packer's own count at each factor: two sheets at 1, one only from ``factor`` on
        counts = {f: len(pack(build({"plot_h": ROOM["A3"]["plot_h"] * f}), "A3")[0])
                  for f in (1.0, *SHRINK)}
        assert counts[1.0] == 2 and counts[factor] == 1 and \
            all(counts[f] == 2 for f in SHRINK if f > factor), counts
        views, pages, _ = fitted(build, "A3")
        assert len(pages) == 1 and views[0].size == pytest.approx((w * factor, h * factor))

    def wide(room):           # views that need two sheets at any factor
        return [_box_view(n, (x1 - x0) * 0.9, (y1 - y0) * 0.6) for n in "ab"]

    views, pages, _ = fitted(wide, "A3")
    assert len(pages) == 2 and views[0].size[0] == pytest.approx((x1 - x0) * 0.9)


def test_a_last_sheet_of_its_own_has_its_views_grown():
    """fitted: views that take two sheets at any factor keep the first sheet's as they are,
    and the second sheet's views, alone on it, are drawn at the largest factor of GROW that
    keeps them to one sheet (the packer's own count decides)."""
    from flywheel.render.drawings import GROW, fitted
    from flywheel.render.drawings.sheet import ROOM

    x0, y0, x1, y1 = field_of("A3")
    W, H = x1 - x0, y1 - y0

    def build(room):
        f = room["plot_h"] / ROOM["A3"]["plot_h"]
        return [_box_view("a", 0.9 * W * f, 0.75 * H * f), _box_view("b", 0.5 * W * f, 0.5 * H * f)]

    assert len(pack(build({"plot_h": ROOM["A3"]["plot_h"] * 0.8}), "A3")[0]) == 2
    fits = [f for f in GROW if len(pack(build({"plot_h": ROOM["A3"]["plot_h"] * f})[1:],
                                        "A3")[0]) == 1]
    views, pages, left_out = fitted(build, "A3")
    assert len(pages) == 2 and not left_out and fits
    assert pages[0][0].size == pytest.approx((0.9 * W, 0.75 * H))         # as it was
    assert pages[1][0].size == pytest.approx((0.5 * W * max(fits), 0.5 * H * max(fits)))


def test_the_last_two_sheets_share_their_views():
    """fitted: where the views take two sheets whatever the room, views of the first go on to
    the second, in their order, so that the emptier of the two is as full as it can be (it
    had kept the first sheet as packed and a last sheet of one small view)."""
    from flywheel.render.drawings import fitted
    from flywheel.render.drawings.sheet import ROOM

    shapes = {"v1": (0.95, 0.4), "v2": (0.45, 0.3), "v3": (0.45, 0.3), "v4": (0.95, 0.35)}
    build, fill = _a3_boxes(shapes)

    packed, _ = pack(build(ROOM["A3"]), "A3")
    assert [[v.name for v in p] for p in packed] == [["v1", "v2", "v3"], ["v4"]]
    assert fill(packed[1]) < 0.35 and len(pack(build({"plot_h": ROOM["A3"]["plot_h"] * 0.8}),
                                               "A3")[0]) == 2     # two sheets at any room
    views, pages, left_out = fitted(build, "A3")
    assert len(pages) == 2 and not left_out
    assert [v.name for p in pages for v in p] == list(shapes)            # in their order
    assert min(fill(p) for p in pages) > 0.45


def test_the_last_two_sheets_share_their_views_where_a_smaller_room_saved_a_sheet():
    """fitted: where 0.8 of the room saves a sheet (three at the room, two at 0.8) and leaves
    the last with one small view, the last two sheets still share, each drawn alone at 0.8,
    0.9 or the room (no larger: no more builds than the search for the smaller room made) —
    it had returned the shrunk sheets as packed, the last a fifth full (engine_inline4's
    sheet 2-4 at A3: the hodograph alone at 12 %)."""
    from flywheel.render.drawings import fitted
    from flywheel.render.drawings.sheet import ROOM

    shapes = {"v1": (0.95, 0.55), "v2": (0.6, 0.55), "v3": (0.6, 0.5), "v4": (0.3, 0.25)}
    build, fill = _a3_boxes(shapes)

    def packed(f):
        return pack(build({"plot_h": ROOM["A3"]["plot_h"] * f}), "A3")[0]

    assert len(packed(1.0)) == len(packed(0.9)) == 3
    shrunk = packed(0.8)
    assert len(shrunk) == 2 and fill(shrunk[1]) < 0.2
    views, pages, left_out = fitted(build, "A3")
    assert len(pages) == 2 and not left_out
    assert sorted(v.name for p in pages for v in p) == sorted(shapes)
    assert min(fill(p) for p in pages) > 0.4


@pytest.mark.parametrize("case", ["compressor", "shaper"])
def test_fitted_sheets_are_never_more_and_their_lettering_never_smaller(case):
    """Against sheet.ROOM as it is: at every format no more sheets and no view left out, the
    same heights of lettering; at A1, where both sheets take one, drawings larger."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import fitted, sheet1, sheet2
    from flywheel.render.drawings.model import Text as Lettering
    from flywheel.render.drawings.sheet import ROOM

    results = analyze(load_case(ROOT / "cases" / f"{case}.toml"), n_points=720)

    def heights(views):
        return {it.height for v in views for it in v.items if isinstance(it, Lettering)}

    for size in ("A1", "A2", "A3"):
        for kind in (sheet1, sheet2):
            plain = kind.views(results, "ru", ROOM[size])
            pages, left_out = pack(plain, size)
            views, fit_pages, fit_left_out = fitted(
                lambda room: kind.views(results, "ru", room), size)
            assert len(fit_left_out) <= len(left_out) and len(fit_pages) <= len(pages)
            assert heights(views) == heights(plain), (size, kind.__name__)
            if size == "A1":
                assert len(fit_pages) == 1
                grown = {v.name: v.size for v in views}
                assert all(grown[v.name][0] * grown[v.name][1] >= v.size[0] * v.size[1] - 1e-9
                           for v in plain)
                assert sum(grown[v.name][0] * grown[v.name][1] for v in plain) > \
                    1.1 * sum(v.size[0] * v.size[1] for v in plain)


# -- a whole run: the sheets written and read back ---------------------------------------------

DOCUMENT = """
[document]
student = "Иванов И. И."
teacher = "Петров П. П."
group = "МТ-301"
university = "МГТУ им. Н. Э. Баумана"
"""


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    """compressor.toml with a [document] table, run with --drawings (Russian); its folder."""
    from typer.testing import CliRunner

    from flywheel.cli import app

    tmp = tmp_path_factory.mktemp("drawings")
    case = tmp / "c.toml"
    case.write_text((ROOT / "cases" / "compressor.toml").read_text(encoding="utf-8") + DOCUMENT,
                    encoding="utf-8")
    r = CliRunner().invoke(app, ["run", str(case), "--no-plots", "--drawings", "--lang", "ru",
                                 "--out", str(tmp / "out"), "--report", "md"])
    assert r.exit_code == 0, r.output
    return tmp / "out"


@pytest.mark.slow
def test_the_pdf_pages_are_a1_landscape(run):
    from pypdf import PdfReader

    for name in ("sheet1.pdf", "sheet2.pdf"):
        box = PdfReader(run / "drawings" / name).pages[0].mediabox
        assert float(box.width) * MM_PER_PT == pytest.approx(841.0, abs=0.05)
        assert float(box.height) * MM_PER_PT == pytest.approx(594.0, abs=0.05)


def _texts(doc) -> list:
    return [e for e in doc.modelspace() if e.dxftype() == "TEXT"]


@pytest.mark.slow
def test_the_dxf_has_its_layers_frame_and_title_block(run):
    import ezdxf

    doc = ezdxf.readfile(run / "drawings" / "sheet1.dxf")
    assert doc.dxfversion >= "AC1027"                                # R2013 or later
    assert doc.header["$INSUNITS"] == 4                              # millimetres
    layers = {layer.dxf.name: layer for layer in doc.layers}
    for name, weight in (("MAIN", 70), ("THIN", 35), ("AXIS", 35), ("DASHED", 35)):
        assert layers[name].dxf.lineweight == weight
    assert "TEXT" in layers
    assert doc.styles.get("GOST type B").dxf.oblique == pytest.approx(15.0)
    msp = doc.modelspace()
    assert all(e.dxf.layer == "TEXT" for e in _texts(doc))
    # the frame: 20 mm from the left edge, 5 mm from the others (ГОСТ 2.104)
    frames = [e for e in msp.query("LWPOLYLINE[layer=='MAIN']") if e.closed
              and sorted(map(tuple, e.get_points("xy"))) == [(20.0, 5.0), (20.0, 589.0),
                                                             (836.0, 5.0), (836.0, 589.0)]]
    assert len(frames) == 1
    # the title block: 185 × 55 mm in the frame's lower right corner
    x0, y0 = 836.0 - BLOCK_W, 5.0
    inside = [e for e in _texts(doc) if x0 <= e.dxf.align_point[0] <= 836.0
              and y0 <= e.dxf.align_point[1] <= y0 + BLOCK_H]
    words = {e.dxf.text for e in inside}
    assert {"Лист 1", "Листов 2", "Иванов И. И.", "Петров П. П.", "Разраб.", "Пров.", "У",
            "ТММ.КП.00.01"} <= words
    # the machine's name, over one or two lines of the name field (65 … 135 mm of the block)
    name = [e for e in inside if x0 + 65 < e.dxf.align_point[0] < x0 + 135
            and y0 + 15 < e.dxf.align_point[1] < y0 + 40]
    name.sort(key=lambda e: -e.dxf.align_point[1])
    # in the sheet's language: the case's Russian title (summary.json keeps the English one)
    from flywheel.cases.run import load_case
    from flywheel.io.text import in_language

    title = in_language(load_case(ROOT / "cases" / "compressor.toml").title, "ru")
    assert title.startswith("Двухступенчатый")
    assert " ".join(e.dxf.text for e in name).startswith(title)
    # column 26: the designation turned 180° in the upper left corner
    assert any(e.dxf.text == "ТММ.КП.00.01" and e.dxf.rotation == 180.0
               and e.dxf.align_point[1] > 594 - 5 - 14 for e in _texts(doc))


def _points(e):
    kind = e.dxftype()
    if kind == "LWPOLYLINE":
        return [tuple(p) for p in e.get_points("xy")]
    if kind == "CIRCLE":
        (x, y, _), r = e.dxf.center, e.dxf.radius
        return [(x - r, y - r), (x + r, y + r)]
    if kind == "TEXT":
        return [tuple(e.dxf.align_point)[:2], tuple(e.dxf.insert)[:2]]
    if kind == "HATCH":
        pts = []
        for path in e.paths:
            pts += [tuple(v)[:2] for v in getattr(path, "vertices", [])]
            for edge in getattr(path, "edges", []):
                c, r = edge.center, edge.radius
                pts += [(c[0] - r, c[1] - r), (c[0] + r, c[1] + r)]
        return pts
    raise AssertionError(f"unexpected entity {kind}")


@pytest.mark.slow
@pytest.mark.parametrize("name", ["sheet1.dxf", "sheet2.dxf"])
def test_every_dxf_entity_lies_on_the_sheet_and_texts_are_legible(run, name):
    import ezdxf

    doc = ezdxf.readfile(run / "drawings" / name)
    W, H = FORMATS["A1"]
    n = 0
    for e in doc.modelspace():
        for x, y in _points(e):
            assert -1e-6 <= x <= W + 1e-6 and -1e-6 <= y <= H + 1e-6, (e.dxftype(), x, y)
        if e.dxftype() == "TEXT":
            assert e.dxf.height >= 0.7 * 2.5 - 1e-9     # a subscript: 0.7 of 2.5 mm at least
        n += 1
    assert n > 200


@pytest.mark.slow
def test_the_views_of_each_sheet_do_not_overlap():
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import build_sheets

    case = load_case(ROOT / "cases" / "compressor.toml")
    results = analyze(case, n_points=720)
    for size in ("A1", "A3"):
        sheets = build_sheets(results, case.document, lang="ru", size=size)
        assert not any(s.left_out for s in sheets)
        names = [v.name for s in sheets for v in s.views[1:]]
        assert {"scheme", "velocity", "acceleration", "lever", "reactions", "hodograph",
                "wittenbauer", "omega", "epsilon", "results", "indicator HP"} <= set(names)
        for s in sheets:
            boxes = [v.box() for v in s.views[1:]]
            for i, a in enumerate(boxes):
                assert not any(_overlap(a, k) for k in keep_out(size))
                for b in boxes[i + 1:]:
                    assert not _overlap(a, b), (s.stem, a, b)
        if size == "A3":
            assert len(sheets) > 2 and sheets[0].count == len(sheets)


@pytest.mark.slow
def test_the_velocity_plan_measures_the_summarys_velocities(run):
    """Sheet 2's velocity plan read back from the DXF: every vector from the pole, its length
    times the stated μ_v, is the velocity of its point in summary.json (results.at[0])."""
    import ezdxf

    doc = ezdxf.readfile(run / "drawings" / "sheet2.dxf")
    group = doc.groups.get("velocity")
    texts = [e.dxf.text for e in group if e.dxftype() == "TEXT"]
    mu_text = next(t for t in texts if "(м/с)/мм" in t)
    mu = float(re.search(r"=\s*([0-9,]+)", mu_text).group(1).replace(",", "."))
    lines = [[tuple(p) for p in e.get_points("xy")] for e in group
             if e.dxftype() == "LWPOLYLINE" and len(e) == 2]
    starts = [ln[0] for ln in lines]
    pole = max(set(starts), key=starts.count)
    from_pole = [math.dist(*ln) * mu for ln in lines if math.dist(ln[0], pole) < 1e-9]
    at = json.loads((run / "summary.json").read_text(encoding="utf-8"))["results"]["at"][0]
    moving = {p: d["v"] for p, d in at["points"].items() if d["v"] > 1e-9}
    assert len(moving) >= 4
    for p, v in moving.items():
        assert any(abs(m - v) <= 1e-6 * v + 1e-9 for m in from_pole), (p, v, from_pole)


@pytest.mark.slow
def test_reruns_write_the_same_bytes(tmp_path):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import write_drawings

    case = load_case(ROOT / "cases" / "fourbar.toml")
    results = analyze(case, n_points=720)
    a = write_drawings(results, tmp_path / "a", case.document, lang="en", size="A2")
    b = write_drawings(results, tmp_path / "b", case.document, lang="en", size="A2")
    assert [p.name for p in a] == [p.name for p in b] and len(a) >= 6
    for p, q in zip(a, b):
        assert p.read_bytes() == q.read_bytes(), p.name


@pytest.mark.slow
def test_a_tabulated_case_gets_sheet1_without_the_scheme(tmp_path):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import build_sheets

    case = load_case(ROOT / "cases" / "press.toml")         # [tabulated]: no linkage
    assert case.tabulated is not None
    results = analyze(case, n_points=720)
    sheets = build_sheets(results, case.document, lang="ru")
    names = [v.name for s in sheets for v in s.views]
    assert "scheme" not in names and "omega" in names and "velocity" not in names


@pytest.mark.slow
def test_the_drawings_command_writes_the_sheets(tmp_path):
    from typer.testing import CliRunner

    from flywheel.cli import app

    r = CliRunner().invoke(app, ["drawings", str(ROOT / "cases" / "fourbar.toml"), "--out",
                                 str(tmp_path / "o"), "--sheet-size", "A3", "--lang", "en"])
    assert r.exit_code == 0, r.output
    names = sorted(p.name for p in (tmp_path / "o" / "drawings").iterdir())
    assert {"sheet1.pdf", "sheet1.svg", "sheet1.dxf", "sheet2.pdf"} <= set(names)
    from pypdf import PdfReader

    box = PdfReader(tmp_path / "o" / "drawings" / "sheet1.pdf").pages[0].mediabox
    assert (round(float(box.width) * MM_PER_PT), round(float(box.height) * MM_PER_PT)) == (420, 297)


def test_the_title_block_fits_long_names_in_its_cells():
    """Every text of the title block within its 185 × 55 mm, none below 2.5 mm; a long name
    narrowed (squeeze ≥ 0.8) or cut with «…», never spilling into the next cell."""
    from types import SimpleNamespace

    from flywheel.render.drawings.sheet import frame_view

    doc = SimpleNamespace(student="Константинопольский К. К.", teacher="Петров П. П.",
                          tech_control="", norm_control="Кузнецова А. В.", approved="",
                          university="Московский государственный технический университет "
                                     "имени Н. Э. Баумана", group="МТ-301",
                          designation_or_default="ТММ.КП.23.01.00.000.000.000.000.000")
    v = frame_view("A1", "ru", document=doc, title="Поперечно-строгальный станок с кулисным "
                   "механизмом и ползуном, привод от электродвигателя через редуктор",
                   sheet_name="Динамический анализ механизма", number=1, count=2, scale="1:2")
    x0, y0 = 836.0 - BLOCK_W, 5.0
    from flywheel.render.drawings.model import Text

    texts = [t for t in v.items if isinstance(t, Text)]
    for t in texts:
        assert t.height >= 2.5 and t.squeeze >= 0.8 - 1e-9, t
        bx0, by0, bx1, by1 = t.box()
        if t.angle == 0.0:
            assert x0 - 1e-6 <= bx0 and bx1 <= x0 + BLOCK_W + 1e-6, t
            assert y0 - 1e-6 <= by0 and by1 <= y0 + BLOCK_H + 1e-6, t
    student = next(t for t in texts if t.text.startswith("Константин"))
    sx0, _, sx1, _ = student.box()                      # in its 23 mm column (17 … 40 mm)
    assert x0 + 17 <= sx0 and sx1 <= x0 + 40


def test_an_a3_frame_written_as_dxf_reads_back_with_its_layers_and_frame(tmp_path):
    """The frame and title block of an A3 sheet written as DXF alone (the whole sheets of a run:
    the slow tests above): millimetres, the ГОСТ 2.303 line weights on their layers, the frame
    20 mm from the left edge and 5 mm from the others (ГОСТ 2.104), every text on TEXT."""
    import ezdxf
    from types import SimpleNamespace

    from flywheel.render.drawings.dxf import write_dxf
    from flywheel.render.drawings.sheet import frame_view

    doc = SimpleNamespace(student="Иванов И. И.", teacher="", tech_control="", norm_control="",
                          approved="", university="", group="",
                          designation_or_default="ТММ.КП.00.01")
    v = frame_view("A3", "ru", document=doc, title="Компрессор", sheet_name="Лист", number=1,
                   count=1, scale="")
    write_dxf(tmp_path / "s.dxf", FORMATS["A3"], [v])
    dxf = ezdxf.readfile(tmp_path / "s.dxf")
    assert dxf.header["$INSUNITS"] == 4
    layers = {layer.dxf.name: layer for layer in dxf.layers}
    for name, weight in (("MAIN", 70), ("THIN", 35)):
        assert layers[name].dxf.lineweight == weight
    msp = dxf.modelspace()
    frames = [e for e in msp.query("LWPOLYLINE[layer=='MAIN']") if e.closed
              and sorted(map(tuple, e.get_points("xy"))) == [(20.0, 5.0), (20.0, 292.0),
                                                              (415.0, 5.0), (415.0, 292.0)]]
    assert len(frames) == 1
    texts = _texts(dxf)
    assert texts and all(e.dxf.layer == "TEXT" for e in texts)
    assert any("Иванов" in e.dxf.text for e in texts)


def test_without_osifont_the_sheet_is_lettered_in_dejavu(monkeypatch, tmp_path):
    from flywheel.render.drawings import fonts, model
    from flywheel.render.drawings.paper import write_paper
    from flywheel.render.drawings.sheet import frame_view

    monkeypatch.setattr(fonts, "OSIFONT", ())
    for cached in (fonts.font_path, fonts._font):
        cached.cache_clear()
    monkeypatch.setattr(fonts, "_ADVANCE", {})
    monkeypatch.setattr(model, "_WIDTHS", {})
    try:
        assert fonts.font_name() == "DejaVu Sans"
        from types import SimpleNamespace

        doc = SimpleNamespace(student="Иванов И. И.", teacher="", tech_control="",
                              norm_control="", approved="", university="", group="",
                              designation_or_default="ТММ.КП.00.01")
        v = frame_view("A3", "ru", document=doc, title="Компрессор", sheet_name="Лист",
                       number=1, count=1, scale="")
        write_paper({"pdf": tmp_path / "s.pdf", "svg": tmp_path / "s.svg"}, FORMATS["A3"],
                    v.items)
        import xml.etree.ElementTree as ET

        root = ET.parse(tmp_path / "s.svg").getroot()
        assert (root.get("width"), root.get("height")) == ("420mm", "297mm")
        assert len(root.findall(".//{http://www.w3.org/2000/svg}use")) > 20   # letters placed
        from pypdf import PdfReader

        box = PdfReader(tmp_path / "s.pdf").pages[0].mediabox
        assert round(float(box.width) * MM_PER_PT, 1) == 420.0
    finally:
        for cached in (fonts.font_path, fonts._font):
            cached.cache_clear()


def test_curve_names_are_set_off_the_curves_and_the_other_lettering():
    """Five curves of one diagram crowded at the same crest (the velocity analogues: a crank
    point's constant |v_q| on top of the others' maxima), a level line and a mark: the one
    placer (render/labels.py) sets every name where no curve passes under it and no other
    lettering is, which the crest of each curve — the old place — was not."""
    import numpy as np

    from flywheel.render.drawings.diagram import diagram
    from flywheel.render.drawings.model import Polyline, Text

    phi = np.linspace(0.0, 360.0, 721)
    r = np.radians(phi)
    curves = [(np.full_like(r, 0.1), "v_qA", "main"),
              (0.1 * np.abs(np.sin(r)), "v_qB", "thin"),
              (0.1 * np.abs(np.sin(r + 0.8)), "v_qC", "main"),
              (0.07 + 0.03 * np.cos(2 * r), "v_qS2", "dashed"),
              (0.07 + 0.03 * np.sin(2 * r), "v_qS4", "thin")]
    v = diagram("analogues", "Аналоги скоростей", phi, curves, x_mu=2.0, x_symbol="φ",
                x_unit="°", x_label="φ, °", y_symbol="v", y_unit="м/рад", y_label="v_q, м/рад",
                lang="ru", lines=[((0.0, 0.05), (360.0, 0.05), "dashdot", "v_ср")],
                marks=[(180.0, 0.0, "k")])
    assert len(v.labels) == 8          # the abscissa's name, 5 curves', the line's, the mark's
    points = []
    for it in v.items:
        if isinstance(it, Polyline):
            xy = np.asarray(it.points)
            for a, b in zip(xy[:-1], xy[1:]):
                n = max(2, int(np.hypot(*(b - a)) / 0.2) + 1)
                points.append(a + np.linspace(0.0, 1.0, n)[:, None] * (b - a))
    points = np.concatenate(points)
    lettering = [it.box() for it in v.items if isinstance(it, Text)]
    for x0, y0, x1, y1 in v.labels:
        inside = ((points[:, 0] > x0) & (points[:, 0] < x1)
                  & (points[:, 1] > y0) & (points[:, 1] < y1))
        assert not inside.any(), ((x0, y0, x1, y1), points[inside][:3])
        own = [b for b in lettering if x0 <= b[0] and b[2] <= x1 and y0 <= b[1] and b[3] <= y1]
        others = [b for b in lettering if b not in own]
        assert not any(_overlap((x0, y0, x1, y1), b) for b in others)


@pytest.mark.parametrize("case", ["compressor", "engine_inline4", "shaper", "fourbar"])
def test_no_force_name_on_sheet_2_lies_along_a_line(case):
    """A force's name in a group drawing, a plan or the lever lies over less than 3 mm
    (drawings.model.ON_LINE) of the lines drawn: where every place by its arrow does, the
    placer tries the rings round it. Before, 60 of the 657 names of ten bundled cases' sheets 2
    lay along a line — «Rn₁₂» along the connecting rod it acts on, «G₃» across it (the
    compressor's group 2–3)."""
    import numpy as np

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import sheet, sheet2
    from flywheel.render.drawings.model import ON_LINE, Polyline
    from flywheel.render.labels import Placer

    res = analyze(load_case(Path(__file__).resolve().parents[2] / "cases" / f"{case}.toml"),
                  n_points=360)
    named = 0
    for v in sheet2.views(res, "ru", sheet.ROOM["A1"]):
        lines = Placer(step=0.25)                    # finer than the placer's own sampling
        for it in v.items:
            if isinstance(it, Polyline):
                lines.curve(list(it.points) + ([it.points[0]] if it.closed else []))
        if v.labels:
            under = lines.costs(np.array(v.labels)) * lines.step      # [mm] of line
            assert under.max() < ON_LINE + 2 * lines.step, (v.name, under.max())
            named += len(v.labels)
    assert named > 20


@pytest.mark.parametrize("case", ["compressor", "compressor_given_flywheel", "pump"])
@pytest.mark.parametrize("lang", ["ru", "en"])
def test_sheet_1s_results_name_each_row_once(case, lang):
    """The main results' table of sheet 1 has four columns — name, symbol, value, unit — and
    every row a name of words from a capital letter (ГОСТ 2.105, 4.4): its rows had mixed a
    symbol alone («M_Д») with words («маховик (диск): масса m»), and its two δ had both read
    «δ». No two rows share a name; the two δ are told apart by it (the target and the
    achieved); a given flywheel has one δ, the one it achieves, and a J_I not «required»."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import sheet1
    from flywheel.render.drawings.model import Polyline, Text

    res = analyze(load_case(Path(__file__).resolve().parents[2] / "cases" / f"{case}.toml"),
                  n_points=360)
    v = sheet1.results_table(res, lang)
    y0 = v.box()[1]
    cells = [t for t in v.items if isinstance(t, Text) and t.height < 5]   # not its title
    # the column lines: the vertical lines of the grid, the outline's aside
    walls = sorted({it.points[0][0] for it in v.items if isinstance(it, Polyline)
                    and len(it.points) == 2 and it.points[0][0] == it.points[1][0]})
    rows: dict[int, list[str]] = {}              # each row's lettering, column by column
    for t in cells:                              # (rows 8 mm high, a subscript 1 mm lower)
        k = int((t.y - y0) // 8.0)
        col = sum(t.x > x for x in walls)
        rows.setdefault(k, ["", "", "", ""])[col] += t.text
    table = [rows[k] for k in sorted(rows, reverse=True)]
    head, body = table[0], table[1:]
    assert head == {"ru": ["Величина", "Обозначение", "Значение", "Ед. изм."],
                    "en": ["Quantity", "Symbol", "Value", "Unit"]}[lang], head
    names = [r[0] for r in body]
    assert len(names) >= 8 and len(set(names)) == len(names), names
    assert all(n[0].isupper() and len(n.split()) >= 2 for n in names), names
    deltas = [r[0] for r in body if r[1] == "δ"]
    given = "given" in case
    word = {"ru": ["при заданном маховике"] if given else ["Заданный", "Достигнутый"],
            "en": ["given flywheel"] if given else ["target", "achieved"]}[lang]
    assert len(deltas) == len(word) and all(w in d for w, d in zip(word, deltas)), deltas
    J_I = next(r[0] for r in body if r[1].startswith("J") and r[1].endswith("I"))
    assert (("Необходимый" in J_I or "Required" in J_I) != given), J_I
    # the disk is sized on the flywheel's shaft: the pump's (i = 10) J_М/i² is a row of its own,
    # from which the disk's m·D²/8 is worked (m D² / 8 = J of a solid disk)
    s = res.scalars
    on_shaft = [r for r in body if "/i" in r[1]]
    assert len(on_shaft) == (s.flywheel_speed_ratio != 1.0), on_shaft
    if on_shaft:
        assert "i = 10" in on_shaft[0][0]
        value = float(on_shaft[0][2].replace(",", ".").replace("\u202f", ""))
        assert value == pytest.approx(s.J_flywheel / s.flywheel_speed_ratio ** 2, rel=1e-3)
        disk = s.flywheel_disk
        assert disk.mass * disk.D ** 2 / 8 == pytest.approx(value, rel=1e-3)


def test_the_sheets_lowercase_letters_stand_at_one_x_height():
    """osifont (2022) draws «ь» as tall as «Ь» and «з» 0.85 of a capital, and has no «э», whose
    fallback (DejaVu Sans) stood 0.77 of a capital: «звеньев», «энергомасс» read with capitals
    inside. Every Cyrillic lowercase letter without an ascender or a mark now tops out at the
    sheet font's x-height (the top of its «x»), an overshoot of 3 % allowed."""
    from flywheel.render.drawings import fonts

    if fonts.font_path() == fonts.fallback_path():
        pytest.skip("osifont is not installed: the sheets are lettered in DejaVu Sans alone")
    x_height = fonts._top(fonts.outline("x"))
    assert 0.6 < x_height < 0.8
    for ch in "авгдежзиклмнопрстухцчшщъыьэюя":
        top = fonts._top(fonts.outline(ch))
        assert 0.97 * x_height <= top <= 1.03 * x_height, (ch, top, x_height)
    assert fonts.advance("э") < fonts.advance("Э")       # narrowed with it, as lettered


@pytest.mark.parametrize("case", ["compressor", "shaper", "fourbar_rocker_load"])
def test_russian_sheets_have_decimal_commas_and_russian_names(case):
    """Every lettering of the Russian sheets at A1 (views, title block, column 26): no decimal
    point — the scales too, «1:2,5» as ГОСТ 2.302 writes it, where the sheet is large enough
    for the scheme at 1:2.5 (the compressor's) — and no force or group named by a case key in
    Latin letters: F_ВД, F_пс, F_пр, M_с by the loads' labels, ВВП for RRP."""
    import re as _re

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import build_sheets
    from flywheel.render.drawings.model import Text

    c = load_case(ROOT / "cases" / f"{case}.toml")
    res = analyze(c, n_points=720)
    texts = [it.text for s in build_sheets(res, c.document, lang="ru", size="A1")
             for it in s.items if isinstance(it, Text)]
    designation = c.document.designation or "ТММ.КП.00.01"      # its dots are the code's own
    numbers = [t for t in texts if designation not in t]
    assert not [t for t in numbers if _re.search(r"\d\.\d", t)], numbers
    # symbols' Latin (J_II, Rn_12, v_qA) and none of three letters or more (cutting, RRP)
    latin = {w for t in texts for w in _re.findall(r"[A-Za-z]{3,}", t)}
    assert not latin, latin
    if case == "compressor":
        assert any("1:2,5" in t for t in texts) and {"ВД", "НД"} <= set(texts)
        assert not {"HP", "LP"} & set(texts)


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_no_number_on_a_sheet_is_in_e_notation(lang):
    """engine_inline4's reactions reach 17 693 N: the table printed «1,769e+04». A number of
    more digits than four is printed whole, in Russian grouped by threes with a narrow space
    (render/numbers.py's policy); the table's magnitudes read back to the reactions to 4
    significant digits or better."""
    import re as _re

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import sheet2
    from flywheel.render.drawings.diagram import num
    from flywheel.render.drawings.model import Text

    res = analyze(load_case(Path(__file__).resolve().parents[2] / "cases"
                            / "engine_inline4.toml"), n_points=360)
    texts = [t.text for t in sheet2.reactions_table(res, lang).items if isinstance(t, Text)]
    assert not [t for t in texts if _re.search(r"\d[eE][-+−]?\d", t)], texts
    forces = [j.F for j in res.at[0].joints.values()]
    assert max(forces) > 1e4
    for F in forces:
        shown = num(F, lang)
        assert shown in texts
        back = float(shown.replace("\u202f", "").replace(",", ".").replace("−", "-"))
        assert back == pytest.approx(F, rel=5e-4)
    if lang == "ru":
        assert any("\u202f" in t for t in texts)


def test_a_subscript_in_braces_holds_a_pair_of_names():
    """Sheet lettering: «R_{1,r4}» is R with the whole pair «1,r4» as its subscript (a comma
    ends a bare subscript: «R_1,r4» lettered R₁,r4); the reactions' table and the polygons
    name engine_inline4's pairs so."""
    from flywheel.render.drawings.model import _runs
    from flywheel.render.drawings.sheet2 import force_label

    assert [(r, sub) for r, sub, _ in _runs("R_{1,r4} = 5", 3.5)] == [
        ("R", False), ("1,r4", True), (" = 5", False)]
    assert [(r, sub) for r, sub, _ in _runs("R_1,r4", 3.5)] == [
        ("R", False), ("1", True), (",r4", False)]
    assert force_label("R_1,r4^τ", "ru") == "Rτ_{1,r4}"
    assert force_label("R_12^τ", "ru") == "Rτ_12"


def test_the_letters_osifont_lacks_are_made_of_its_own():
    """osifont draws «ё», «Ё», «э», «Э» as empty boxes; the fallback's were heavier than its
    strokes («Приведённый», «энергомасс»). They are made of osifont's letters: «ё» the Latin
    «ë» in the Cyrillic «е»'s place and advance; «э» the «с» turned over with a bar at half its
    height, wound as the letter so that the fill stays whole."""
    from flywheel.render.drawings import fonts

    if fonts.font_path() == fonts.fallback_path():
        pytest.skip("osifont is not installed: the sheets are lettered in DejaVu Sans alone")
    sheet = fonts._font(fonts.font_path())
    for ch, like in (("ё", "е"), ("Ё", "Е"), ("э", "с"), ("Э", "С")):
        assert fonts._font_of(ch) is sheet, ch
        assert fonts.advance(ch) == pytest.approx(fonts.advance(like))
    dots = fonts.outline("ё")
    assert fonts._left(dots) == pytest.approx(fonts._left(fonts.outline("е")))
    assert fonts._top(dots) > 1.2 * fonts._top(fonts.outline("е"))        # the two dots
    e, c = fonts.outline("э"), fonts.outline("с")
    assert len(e) == len(c) + 1
    bar = e[-1]
    ys = [p[1] for _, ps in bar for p in ps]
    assert (min(ys) + max(ys)) / 2 == pytest.approx(0.35)
    assert max(ys) - min(ys) == pytest.approx(fonts.STROKE)
    outer = max(e[:-1], key=lambda k: abs(fonts._signed_area(fonts._points(k))))
    assert (fonts._signed_area(fonts._points(bar)) > 0) \
        == (fonts._signed_area(fonts._points(outer)) > 0)
    xs = [p[0] for k in e[:-1] for _, ps in k for p in ps]
    bx = [p[0] for _, ps in bar for p in ps]
    assert min(xs) < min(bx) < max(bx) < max(xs)                          # inside the letter


def test_the_abscissas_name_is_set_off_a_curve_running_to_its_end():
    """The energy–mass diagram's curve runs along its abscissa to the arrow (its J_II is
    largest where ΔT is near 0): «J_II, кг·м²» above the arrow lay on it (the compressor at
    A3). The name goes where no curve passes under it — past the tip here."""
    import numpy as np

    from flywheel.render.drawings.diagram import diagram
    from flywheel.render.drawings.model import Polyline

    J = np.linspace(0.0, 0.03, 200)
    dT = 800.0 * (1.0 - J / 0.03) + 20.0 * np.sin(40 * J / 0.03)     # falls to ~0 at J's end
    v = diagram("wittenbauer", "Диаграмма энергомасс", J, [(dT, "", "main")], x_mu=0.001,
                x_symbol="J", x_unit="кг·м²", x_label="J_II, кг·м²", y_symbol="T",
                y_unit="Дж", y_label="ΔT, Дж", lang="ru", y_mu=20.0)
    (box,) = v.labels
    pts = np.concatenate([np.asarray(it.points) for it in v.items if isinstance(it, Polyline)
                          and len(it.points) > 2])
    inside = ((pts[:, 0] > box[0]) & (pts[:, 0] < box[2]) & (pts[:, 1] > box[1])
              & (pts[:, 1] < box[3]))
    assert not inside.any(), box


def test_a_title_block_states_its_own_sheets_scale():
    """The title block's «Масштаб» is its own sheet's: the scheme's on a sheet with the
    scheme, a group's where a group drawn to a ГОСТ scale leads its sheet, blank on a sheet of
    diagrams, plans and the lever only — it had repeated the scheme's scale of the sheet
    before (compressor at A3: sheet 1-2 and 1-3 hold φ diagrams only)."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import build_sheets
    from flywheel.render.drawings.model import Text

    c = load_case(ROOT / "cases" / "compressor.toml")
    res = analyze(c, n_points=720)
    for s in build_sheets(res, c.document, lang="ru", size="A3"):
        ratios = [it.text for it in s.views[0].items
                  if isinstance(it, Text) and re.fullmatch(r"\d+(,\d+)?:\d+(,\d+)?", it.text)]
        own = [v.scales["label"] for v in s.views[1:] if "label" in v.scales]
        assert ratios == own[:1], (s.stem, ratios, own)
    assert any(not [v for v in s.views[1:] if "label" in v.scales]
               for s in build_sheets(res, c.document, lang="ru", size="A3"))


def test_the_dxf_does_not_follow_the_hash_seed(tmp_path, monkeypatch):
    """ezdxf writes a CLASS entry per object type in use in the order of a set of names, which
    follows PYTHONHASHSEED: the same sheet had other bytes in another process. The set's
    order is taken here as given and as reversed; the files are the same."""
    from ezdxf.entitydb import EntityDB

    from flywheel.render.drawings.dxf import write_dxf

    view = _box_view("box", 50, 40)
    view.text(5.0, 5.0, "Лист", 3.5)
    own = EntityDB.dxf_types_in_use
    files = []
    for k, order in enumerate((lambda names: names, lambda names: names[::-1])):
        monkeypatch.setattr(EntityDB, "dxf_types_in_use",
                            lambda self, order=order: dict.fromkeys(order(sorted(own(self)))))
        files.append(tmp_path / f"{k}.dxf")
        write_dxf(files[-1], FORMATS["A3"], [view])
    assert files[0].read_bytes() == files[1].read_bytes()


@pytest.mark.parametrize("case", ["shaper", "compressor"])
def test_every_standard_position_is_numbered_on_the_scheme(case):
    """Sheet 1's scheme numbers the crank's standard positions 0 … 11, the one drawn in main
    lines (the first report angle: the shaper's 60° is position 2) too — it had been left
    unnumbered."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings.model import Text
    from flywheel.render.drawings.scheme import scheme_view

    results = analyze(load_case(ROOT / "cases" / f"{case}.toml"))
    i = results.at_index(results.at[0].phi_deg)
    v = scheme_view(results, i, 200.0, "ru", positions=True)
    numbers = {t.text for t in v.items if isinstance(t, Text) and t.text.isdigit()}
    assert numbers == {str(p.number) for p in results.position_angles if p.number is not None}
    assert any(results.index_of(p.phi) == i for p in results.position_angles
               if p.number is not None)


def test_a_views_box_follows_the_items_appended_after_it_was_asked():
    """View.box is kept as items are appended (the layout asks it thousands of times): it is
    always the box of every item, as model.bounds computes it afresh."""
    from flywheel.render.drawings.model import bounds

    v = View("v")
    v.line((0, 0), (10, 5))
    assert v.box() == bounds(v.items) == (0.0, 0.0, 10.0, 5.0)
    v.circle((20, -3), 2.0)
    assert v.box() == bounds(v.items) == (0.0, -5.0, 22.0, 5.0)
    v.text(-4.0, 1.0, "AB", 3.5)
    assert v.box() == bounds(v.items) and v.box()[0] == -4.0
    w = v.moved(1.0, 1.0)
    assert w.box() == bounds(w.items) == tuple(a + 1.0 for a in v.box())


def test_listov_is_written_on_the_first_sheet_only():
    """ГОСТ 2.104-2006, 5.2: column 8 «Листов» (the sheets of the document) is filled on the
    first sheet only, column 7 «Лист» left blank on a document of one sheet — every sheet had
    said «Листов 2»."""
    from flywheel.cases.run import DocumentSpec
    from flywheel.render.drawings.model import Text
    from flywheel.render.drawings.sheet import frame_view

    def block(number: int, count: int) -> set[str]:
        v = frame_view("A1", "ru", document=DocumentSpec(), title="Компрессор",
                       sheet_name="Динамический анализ механизма", number=number, count=count,
                       scale="1:2")
        return {it.text for it in v.items if isinstance(it, Text)}

    first, second, alone = block(1, 2), block(2, 2), block(1, 1)
    assert {"Лист 1", "Листов 2"} <= first
    assert "Лист 2" in second and "Листов" in second and "Листов 2" not in second
    assert {"Лист", "Листов 1"} <= alone and "Лист 1" not in alone


def test_a_force_polygon_of_one_link_is_named_in_the_singular():
    """The crank's force polygon on sheet 2 read «План сил звеньев 1» (as a group's «звеньев
    2, 3»): one link is «звена 1», "of link 1"; a group keeps the plural."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.drawings import build_sheets
    from flywheel.render.drawings.model import Text

    c = load_case(ROOT / "cases" / "compressor.toml")
    res = analyze(c, n_points=360)
    for lang, one, group in (("ru", "План сил звена 1", "План сил звеньев 2, 3"),
                             ("en", "Force polygon of link 1", "Force polygon of links 2, 3")):
        texts = {it.text for s in build_sheets(res, c.document, lang=lang, size="A1")
                 for it in s.items if isinstance(it, Text)}
        assert one in texts and group in texts, sorted(t for t in texts if "сил" in t or "olygon" in t)
        assert not any(t.endswith(("звеньев 1", "links 1")) for t in texts)


@pytest.mark.parametrize("title, height", [
    ("Двухступенчатый воздушный компрессор", 5.0),
    ("Поперечно-строгальный станок: кривошипно-кулисный механизм с быстрым обратным ходом и "
     "ползуном", 2.5),
])
def test_the_title_blocks_name_holds_a_long_title_whole(title, height):
    """The name field of the title block (70 × 25 mm, ГОСТ 2.104 form 1) holds the shaper's long
    title whole at 2.5 mm (ГОСТ 2.304's sizes), the sheet's name with it; it had been cut at
    3.5 mm, «механизм с быстрым обратн…». A short title keeps 5 mm. Every line within the
    field's 66 mm, all within its 24 mm."""
    from flywheel.render.drawings.model import text_width
    from flywheel.render.drawings.sheet import name_lines

    lines = name_lines(title, "Динамический анализ механизма", 0.0)
    said = [" ".join(ln for ln, _, _ in lines[:n]) for n in range(len(lines) + 1)]
    n = said.index(title)                           # the title's lines, whole, then the name's
    assert {h for _, h, _ in lines[:n]} == {height} and not any("…" in ln for ln, _, _ in lines)
    assert " ".join(ln for ln, _, _ in lines[n:]) == "Динамический анализ механизма"
    assert all(text_width(ln, h) <= 66.0 for ln, h, _ in lines)
    top = max(y + h / 2 for _, h, y in lines)
    bottom = min(y - h / 2 for _, h, y in lines)
    assert top - bottom <= 24.0
