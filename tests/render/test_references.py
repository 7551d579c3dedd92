"""Every table and every figure of a Russian записка is referred to in its text before it
(ГОСТ 7.32-2017, 6.5 and 6.6, as ГОСТ 2.105: «На все таблицы … должны быть ссылки в тексте»,
«На все иллюстрации должны быть даны ссылки»): render/blocks.py ``referenced`` adds «Аналоги
скоростей в стандартных положениях — в таблице 7.» where the text says nothing of it."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from flywheel.render.blocks import (Bullets, Figure, Heading, Paragraph, Table, Where,
                                    referenced)

CASES = Path(__file__).resolve().parents[2] / "cases"


def table(n: int, caption: str = "Аналоги скоростей") -> Table:
    return Table(n, caption, ("φ",), (("0",),))


def texts(blocks) -> list[str]:
    return [b.text for b in blocks if isinstance(b, Paragraph)]


def test_a_table_and_a_figure_get_a_sentence_before_them():
    out = referenced([Heading(2, "2. Кинематика"), Paragraph("Аналоги скоростей точек."),
                      table(1), Figure(1, "Работы и кинетическая энергия", "w.png")], "ru")
    assert texts(out) == ["Аналоги скоростей точек.", "Аналоги скоростей — в таблице 1.",
                          "Работы и кинетическая энергия — на рисунке 1."]
    assert isinstance(out[3], Table) and isinstance(out[5], Figure)   # the sentence first


def test_a_table_the_text_names_gets_no_second_reference():
    blocks = [Paragraph("Значения приведены в таблице 1."), table(1),
              Bullets(("по Мерцалову (рисунок 1): J_I = 4,2",)), Figure(1, "Диаграмма", "d.png")]
    assert referenced(blocks, "ru") == blocks


def test_the_sources_own_table_and_figure_are_no_reference():
    """Task 2's source names the textbook's «таблица 27, рис. 5» (and so does the list of
    sources): not this record's table 1 or figure 1, which keep their sentences; a record with a
    fifth figure had lost its reference to that «рис. 5»."""
    from flywheel.render.blocks import Source

    src = Source("Источник: учебная задача «Задача 2» (таблица 1), рис. 1")
    out = referenced([src, table(1), Figure(1, "Графики моментов", "m.png"),
                      Heading(2, "Источники"), Bullets(("[1] то же, таблица 2",)), table(2)], "ru")
    assert texts(out) == [src.text, "Аналоги скоростей — в таблице 1.",
                          "Графики моментов — на рисунке 1.", "Аналоги скоростей — в таблице 2."]


def test_a_mention_after_the_table_is_no_reference_to_it():
    """A table stands after the text that first names it: «M_Σ в таблице 9 — …» under the
    table does not spare the sentence before it."""
    out = referenced([table(9), Paragraph("M_Σ в таблице 9 — сумма её столбцов.")], "ru")
    assert texts(out) == ["Аналоги скоростей — в таблице 9.", "M_Σ в таблице 9 — сумма её столбцов."]


def test_figures_one_after_another_are_referred_to_once():
    out = referenced([Figure(k, f"График {k}", f"{k}.png") for k in (3, 4, 5)]
                     + [Paragraph("Далее."), Figure(6, "Одна", "6.png")], "ru")
    assert texts(out) == ["Графики — на рисунках 3–5.", "Далее.", "Одна — на рисунке 6."]


def test_the_short_reference_for_a_long_caption_or_the_headings_own_words():
    long = "Реакции в кинематических парах; R_ij — сила, с которой звено i действует на звено j"
    out = referenced([Heading(3, "1.1. Машина и маховик"), table(1, "Машина и маховик"),
                      table(2, long)], "ru")
    assert texts(out) == ["Данные приведены в таблице 1.", "Данные приведены в таблице 2."]


def test_a_lead_in_paragraph_stays_with_its_table():
    lead = Paragraph("Результаты по положениям:")
    out = referenced([lead, table(4)], "ru")
    assert out == [Paragraph("Аналоги скоростей — в таблице 4."), lead, table(4)]


def test_an_english_record_is_left_as_it_is():
    blocks = [table(1), Figure(1, "Works", "w.png")]
    assert referenced(blocks, "en") == blocks


#: the figures a compressor's run writes (plots/)
PLOTS = ["J_II.png", "acceleration_analogues.png", "balancing_moment.png", "energy_mass.png",
         "epsilon.png", "hodographs.png", "omega.png", "piston_forces.png",
         "plan_acceleration_120.png", "plan_forces_120.png", "plan_lever_120.png",
         "plan_positions.png", "plan_velocity_120.png", "positions.png", "reactions.png",
         "reduced_moments.png", "scheme.png", "time_law.png", "velocity_analogues.png",
         "works.png"]


def _cited_before(blocks) -> None:
    """Each table and figure is named by a paragraph or bullet before it."""
    seen = {"table": set(), "figure": set()}
    for b in blocks:
        for t in (b.items if isinstance(b, Bullets) else (b.text,)
                  if isinstance(b, (Paragraph, Where)) else ()):
            seen["table"] |= {int(x) for x in re.findall(r"таблиц\w*\s+(\d+)", t)}
            for first, last in re.findall(r"рисун\w*\s+(\d+)(?:–(\d+))?", t):
                seen["figure"] |= set(range(int(first), int(last or first) + 1))
        if isinstance(b, Table):
            assert b.number in seen["table"], b.caption
        if isinstance(b, Figure):
            assert b.number in seen["figure"], b.caption


@pytest.mark.parametrize("name", ["compressor", "shaper", "engine_4stroke"])
def test_every_table_and_figure_of_a_russian_run_record_is_cited(name):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    case = load_case(CASES / f"{name}.toml")
    res = analyze(case, n_points=360)
    with typography("ru"):
        doc = build_document(res, "ru", PLOTS, case)
    assert doc.tables and doc.figures
    _cited_before(doc.blocks)
    with typography("en"):
        english = build_document(res, "en", PLOTS, case)
    assert not any("Table" in t and " — in " in t for t in texts(english.blocks))


def test_every_table_and_figure_of_the_other_russian_records_is_cited():
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.cases.duty_cycle import load_duty_case, solve_case as solve_duty
    from flywheel.cases.task2 import load_task2_case, solve_case as solve_task2
    from flywheel.elastic.model import analyze as analyze_aggregate
    from flywheel.render.numbers import typography
    from flywheel.render.report_aggregate import build_aggregate_document
    from flywheel.render.report_duty_cycle import build_duty_cycle_document
    from flywheel.render.report_task2 import build_task2_document

    with typography("ru"):
        docs = [build_task2_document(solve_task2(load_task2_case(
                    CASES / "task2_seed_triangle.toml"), "t"), "T", "S", "ru", figure="f.png"),
                build_duty_cycle_document(solve_duty(load_duty_case(
                    CASES / "duty_khurmi_16_21_riveting.toml"), "d"), "T", "S", "ru"),
                build_aggregate_document(analyze_aggregate(*to_model(load_aggregate_case(
                    CASES / "aggregate.toml"), "a")), "T", "S", "ru", figure="f.png")]
    for doc in docs:
        assert doc.tables
        _cited_before(doc.blocks)


@pytest.mark.parametrize("name, lang", [("compressor", "ru"), ("pump", "en"),
                                        ("compressor_given_flywheel", "ru")])
def test_the_run_record_ends_with_a_conclusion_of_its_main_results(name, lang):
    """«Заключение» before the sources (ГОСТ 7.32-2017: the conclusion states the results):
    the main results a line each, as drawing sheet 1's table has them, each value the
    summary's to the record's digits."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    res = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    with typography(lang):
        doc = build_document(res, lang)
    heads = [b.text for b in doc.blocks if isinstance(b, Heading) and b.level == 2]
    word = "Заключение" if lang == "ru" else "Conclusion"
    assert heads[-2].endswith(word) and heads[-1] in ("Источники", "Sources"), heads
    k = next(k for k, b in enumerate(doc.blocks) if isinstance(b, Bullets)
             and isinstance(doc.blocks[k - 2], Heading) and doc.blocks[k - 2].text.endswith(word))
    items = doc.blocks[k].items
    s = res.scalars

    def value(symbol: str) -> float:
        item = next(x for x in items if f" {symbol} = " in x)
        text = item.split(f" {symbol} = ")[1].split()[0].rstrip(";.")
        return float(text.replace("\u2212", "-").replace("\u202f", "").replace(",", "."))

    sym = {"ru": ("ΔT_нб", "J_I", "J_М"), "en": ("ΔT_max", "J_I", "J_M")}[lang]
    for symbol, expected in zip(sym, (s.delta_T_max, s.J_required, s.J_flywheel)):
        assert value(symbol) == pytest.approx(expected, rel=1e-3), symbol
    assert value("D") == pytest.approx(s.flywheel_disk.D, rel=1e-3)
    assert value("m") == pytest.approx(s.flywheel_disk.mass, rel=1e-3)
    assert items[-1].endswith(".") and all(x.endswith(";") for x in items[:-1])
    assert (s.flywheel_speed_ratio != 1.0) == any("/i" in x for x in items)


def test_a_tables_dashes_are_one_dash():
    """A «Ед.» column had mixed «–» (a dimensionless quantity) and «—» (a text value, no data):
    a table keeps one dash, «—», for both (ГОСТ 2.105-2019, 4.4.15: «ставится прочерк»)."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    t = Table(1, "x", ("Величина", "Значение", "Ед."), (("δ", "0,05", "–"), ("материал", "сталь", "")))
    assert [r[2] for r in t.rows] == ["—", "—"]
    res = analyze(load_case(CASES / "compressor.toml"), n_points=360)
    with typography("ru"):
        doc = build_document(res, "ru")
    cells = [c for b in doc.tables for r in b.rows for c in r]
    assert "—" in cells and "–" not in cells
