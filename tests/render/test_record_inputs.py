"""The записка's input data state the whole case (§1.1–1.2): each quantity by its name and its
symbol, each link's length by its two points as the course writes it (l_AB), the guides, the
fixed points, the crank's position at φ = 0 and its direction, and where every point of a link
sits (S₂ at AS₂/AB of link 2). The record had listed bare symbols («δ», «i», «l (звено 2)») and
left out the points, the guides' positions and the crank's start, so a teacher could not check
a student's data against the task."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from flywheel.cases.run import RPRSpec, RRPSpec, RRRSpec, load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.render.blocks import Paragraph, Table
from flywheel.render.document import T, build_document
from flywheel.render.numbers import typography

CASES = Path(__file__).resolve().parents[2] / "cases"
LINKAGES = sorted(p.stem for p in CASES.glob("*.toml")
                  if not p.stem.startswith(("task2", "aggregate", "duty", "variants"))
                  and load_case(p).crank is not None)


def _document(name: str, lang: str = "ru"):
    case = load_case(CASES / f"{name}.toml")
    with typography(lang):
        return case, build_document(analyze(case, n_points=360), lang, [], case=case)


def _rows(doc, caption: str) -> dict[str, str]:
    """The rows of the table captioned ``caption``: its first column → its second."""
    table = next(b for b in doc.blocks if isinstance(b, Table) and b.caption == caption)
    return {r[0]: r[1] for r in table.rows}


def _numbers(text: str) -> list[float]:
    """A Russian cell's numbers: «0,7; −0,2» → [0.7, −0.2]."""
    return [float(x.replace(",", ".").replace("−", "-").replace("\u202f", "").replace(" ", ""))
            for x in text.split("; ")]


def test_the_compressor_states_its_worksheets_lengths_by_their_points():
    """Seed 000 (the compressor's worksheet), §1.1: l1 = V_ср/(4·n1) = 4/(4·10) = 0,1 м and
    l2 = l4 = k·l1 = 4·0,1 = 0,4 м, the centroids at l_AS = 0,3·l: the case gives V_ср and k,
    the record states the lengths they give, by the links' points."""
    _, doc = _document("compressor")
    rows = _rows(doc, T["ru"]["lengths"])
    assert _numbers(rows["Длина кривошипа l_OA"]) == [pytest.approx(4.0 / (4 * 10.0))]
    assert _numbers(rows["Длина звена 2 l_AB"]) == [pytest.approx(4 * 0.1)]
    assert _numbers(rows["Длина звена 4 l_AC"]) == [pytest.approx(4 * 0.1)]
    assert rows["Точка S₂ звена 2: доля длины AB l_AS2/l_AB"] == "0,3"
    assert rows["Направляющая ползуна 3: угол к оси x α_3"] == "90"
    assert rows["Направление вращения кривошипа"] == "по часовой стрелке"
    assert rows["Положение кривошипа при φ = 0 (от оси x)"] == "90"
    machine = _rows(doc, T["ru"]["machine"])
    assert machine["Коэффициент неравномерности хода δ"] == "0,05"
    assert machine["в том числе: коленчатый вал"] == "0,6"
    assert machine["Передаточное отношение к валу маховика i"] == "1"
    assert not any(k in machine for k in ("δ", "i", "ρ", "n₁"))   # no bare symbol


@pytest.mark.parametrize("name", LINKAGES)
def test_every_length_guide_fixed_point_and_point_of_a_link_is_stated(name):
    """Every bundled linkage: each value of the case's geometry is in table 2, as given."""
    case, doc = _document(name)
    rows = _rows(doc, T["ru"]["lengths"])
    values = {k: _numbers(v) for k, v in rows.items() if re.match(r"^[−\d]", v)}

    def stated(prefix: str, *expected: float) -> None:
        found = [v for k, v in values.items() if k.startswith(prefix)]
        assert found, (name, prefix, list(rows))
        assert any(v == pytest.approx(list(expected), rel=1e-5, abs=1e-12) for v in found), (
            name, prefix, found, expected)

    stated(f"Длина кривошипа l_{case.crank.pivot}{case.crank.tip}", case.crank_length)
    for d in case.dyads:
        if isinstance(d, RRPSpec):
            stated(f"Длина звена {d.rod} l_", case.rod_length(d))
            stated(f"Направляющая ползуна {d.slider}: угол", d.guide.angle_deg)
            stated(f"Направляющая ползуна {d.slider}: точка", *d.guide.through)
        elif isinstance(d, RRRSpec):
            stated(f"Длина звена {d.link_from} l_", d.length_from)
            stated(f"Длина звена {d.link_to} l_", d.length_to)
        elif isinstance(d, RPRSpec) and d.offset:
            stated(f"Линия скольжения звена {d.rocker}", d.offset)
    for p, xy in case.ground.items():
        stated(f"Неподвижная точка {p} ", *xy)
    for p, spec in case.points.items():
        assert any(re.search(rf"[Тт]очка {re.escape(p[:1])}\S* звена {re.escape(spec.link)}:", k)
                   for k in rows), (name, p)
        if spec.distance is not None:
            stated(f"Точка {p[:1]}", spec.distance)
    assert not any(math.isnan(x) for v in values.values() for x in v)


def test_a_cylinders_indicator_columns_are_said_once():
    """The indicator tables' s and arrows are explained under the first of them, once."""
    _, doc = _document("compressor")
    notes = [b for b in doc.blocks if isinstance(b, Paragraph) and b.text == T["ru"]["ind_note"]]
    assert len(notes) == 1 and "к головке" in notes[0].text


def test_a_centroid_is_lettered_as_the_figures_letter_it():
    _, doc = _document("compressor")
    table = next(b for b in doc.blocks if isinstance(b, Table) and b.caption == T["ru"]["masses"])
    assert [r[-1] for r in table.rows] == ["S₂", "B", "S₄", "C"]
    at = next(b for b in doc.blocks if isinstance(b, Table)
              and b.caption == T["ru"]["points_caption"].format(a="120"))
    assert "S₂" in [r[0] for r in at.rows] and "S2" not in [r[0] for r in at.rows]


def test_a_tabulated_case_states_its_links_and_loads():
    """The press (cases/press.toml, the course project «Динамический анализ пресса», eqs. (8),
    (9) and the moments Мст4 = −1750·0,05, Мст5 = −5540·0,042): the record states each link's
    mass and J and the row it moves with, each force at its point, and the per-position values
    in a table of their own — the punch's 1750 N at 90° and 5540 N at 120°, its weights' angles.
    A tabulated case's record had said only that its kinematics are a table."""
    _, doc = _document("press")
    ru = T["ru"]
    masses = next(b for b in doc.blocks if isinstance(b, Table) and b.caption == ru["tab_masses"])
    assert [list(r[:4]) for r in masses.rows] == [["2", "255,1", "7,653", "B₂"], ["3", "81,6", "—", "B₂"],
                                            ["4", "102", "—", "B₄"], ["5", "—", "2,251", "—"]]
    # the ω_q row a rotating link uses, by its name: «ω_q2» under «Вращение (ω_q)» (a bare «2»
    # under «ω_q» had read as a value of ω_q)
    assert masses.header[-1] == "Вращение (ω_q)"
    assert [r[4] for r in masses.rows] == ["ω_q2", "—", "—", "ω_q5"]
    loads = _rows(doc, ru["tab_loads"])
    assert loads["Сила полезного сопротивления (штамповки)"] == "B₄"
    per = next(b for b in doc.blocks if isinstance(b, Table) and b.caption == ru["tab_rows"])
    assert per.header[-1] == "F (сила полезного сопротивления (штамповки)), Н"
    punch = {r[0]: r[-1] for r in per.rows}
    assert (punch["90"], punch["120"], punch["150"]) == ("1750", "5540", "0")
    assert [r[1] for r in per.rows][:3] == ["180", "128", "104"]      # α(G2) at 0°, 30°, 60°
    # the positions' tables: a row's label without the angle the φ column beside it says
    # («1 (0°) | 0» had said it twice); the report angle's tables without the columns the
    # table's kinematics cannot fill (no acceleration analogues: a_q, a, ε_q, ε all «—»)
    kin = next(b for b in doc.blocks if isinstance(b, Table) and b.header[1] == "φ, °")
    assert [r[:2] for r in kin.rows[:2]] == [("1", "0"), ("2", "30")], kin.rows[:2]
    at = [b for b in doc.blocks if isinstance(b, Table) and "φ = 120°" in b.caption]
    assert [b.header for b in at] == [("Точка", "v_q, м/рад", "v, м/с"),
                                      ("Звено", "ω_q", "ω, рад/с")], [b.header for b in at]


def test_a_measured_indicator_diagram_is_said_not_listed():
    """engine_measured's pressure trace (361 points of a CSV file) is said in one sentence with
    its greatest gauge pressure, read here from the file itself: max p (bar, absolute) − 1
    atmosphere, 4 digits — not listed row by row."""
    import csv

    with open(CASES / "data" / "engine_measured_p_phi.csv", encoding="utf-8") as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))][1:]
    p_max = max(float(r[1]) for r in rows) * 1e5 - 101325.0          # [Pa], gauge
    _, doc = _document("engine_measured")
    said = [b.text for b in doc.blocks if isinstance(b, Paragraph)
            and b.text.startswith("Индикаторная диаграмма цилиндра 1 задана записью давления "
                                  "по углу поворота кривошипа")]
    assert len(said) == 1, said
    printed = float(re.search(r"p_max = ([\d,]+) МПа", said[0]).group(1).replace(",", "."))
    assert printed == pytest.approx(p_max / 1e6, rel=5e-4)                 # 4 digits
    assert not any(isinstance(b, Table) and b.caption.startswith("Индикаторная") for b in doc.blocks)


def test_a_sliders_force_says_where_it_acts():
    """The shaper's cutting force (cases/shaper.toml: 2500 N on s = 0.05 … 0.95 from the outer
    dead centre, on the working stroke towards it): the record says where and when it acts, not
    its size alone."""
    _, doc = _document("shaper")
    table = next(b for b in doc.blocks if isinstance(b, Table) and b.caption == T["ru"]["forces"])
    assert [list(r) for r in table.rows] == [[
        "Сила резания", "5", "2500; при s = 0,05 … 0,95 от внешней мёртвой точки, при движении "
        "ползуна к этой мёртвой точке", "Н"]]


def test_the_report_angles_subsections_are_headed_alike():
    """§6 (true velocities) and §7 (force analysis) head a report angle's subsection alike,
    «При φ = 120°» (§6 had «φ = 120°»)."""
    from flywheel.render.blocks import Heading

    _, doc = _document("compressor")
    heads = [b.text for b in doc.blocks if isinstance(b, Heading) and b.level == 3
             and "φ = 120°" in b.text]
    assert heads == ["6.1. При φ = 120°", "7.1. При φ = 120°"], heads


def test_the_english_input_tables_have_no_russian_letters():
    """The English record's input tables are English throughout: the first group's inertia is
    J_10 + J_red (it had the Russian J_ред), the parts, the guides and the points in English."""
    _, doc = _document("compressor", "en")
    en = T["en"]
    for caption in (en["machine"], en["lengths"]):
        cells = [c for r in next(b for b in doc.blocks if isinstance(b, Table)
                                 and b.caption == caption).rows for c in r]
        assert not [c for c in cells if re.search("[а-яА-ЯёЁ]", c)], caption
    assert "J_10 + J_red" in " ".join(r[0] for r in next(
        b for b in doc.blocks if isinstance(b, Table) and b.caption == en["machine"]).rows)


def test_task2s_given_data_take_their_units_from_the_schema():
    """task2's table of the data as the task states them prints each number's unit as the case
    schema's description states it (cases/describe.unit_of_path, the task sheets' source too):
    a mean speed «об/мин», the ± fluctuation «%», the diagram's scales «мм²», «°/мм»; no number
    of it without a unit but the dimensionless ones."""
    from pathlib import Path

    from flywheel.cases.task2 import load_task2_case
    from flywheel.render.numbers import typeset
    from flywheel.render.report_task2 import _case_rows

    cases = Path(__file__).resolve().parents[2] / "cases"
    units = {}
    for name in ("task2_khurmi_16_5", "task2_khurmi_16_4"):
        c = load_task2_case(cases / f"{name}.toml")
        for label, _, u in typeset("ru", _case_rows, c, "ru"):
            units[label] = u
    assert units["средняя частота вращения n_ср"] == "об/мин", units
    assert any(u == "%" for u in units.values()), units
    assert {"мм²", "°/мм"} <= set(units.values()), units
    assert not [k for k, u in units.items() if not u and "δ" not in k], units


def test_a_first_group_part_is_named_in_words_in_english_too():
    """The shaper's English record listed «of which: crank_gear» (the case's key); a part the
    catalogue knows is named in words in both languages, another by its key."""
    from flywheel.render.sheet_labels import part_name

    en = _rows(_document("shaper", "en")[1], T["en"]["machine"])
    assert any("crank gear" in k for k in en) and not any("crank_gear" in k for k in en), en
    ru = _rows(_document("shaper", "ru")[1], T["ru"]["machine"])
    assert any("кривошипное колесо" in k for k in ru), ru
    assert part_name("my_rotor", "en") == part_name("my_rotor", "ru") == "my_rotor"


@pytest.mark.parametrize("name, caption, title", [
    ("press", "Уравновешивающий момент на кривошипе из баланса мощностей", "из баланса мощностей"),
    ("compressor", "Уравновешивающий момент на кривошипе: групп Ассура и с учётом инерции маховика",
     "группы Ассура и маховик")])
def test_the_balancing_moments_figure_says_the_methods_it_draws(name, caption, title):
    """A tabulated case (the press) has no Assur groups and no kinetostatics: its figure draws
    M_у from the power balance alone, and its caption and title say so (they had said «групп
    Ассура …» and «три способа» over one line)."""
    from flywheel.render import figure as fg
    from flywheel.render.blocks import Figure
    from flywheel.render.plots_forces import figure_balancing_moment

    case = load_case(CASES / f"{name}.toml")
    res = analyze(case, n_points=360)
    with typography("ru"):
        doc = build_document(res, "ru", ["balancing_moment.png"], case=case)
    (fig,) = [b for b in doc.blocks if isinstance(b, Figure)]
    assert fig.caption == caption
    with fg.style("ru"):
        plot = figure_balancing_moment(res, "ru")
    assert title in plot.axes[0].get_title().replace("\n", " ")
