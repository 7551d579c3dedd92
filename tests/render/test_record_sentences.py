"""Every paragraph of a записка is a sentence: a capital first letter (a line of the terminal
copied into the record — «доля цикла, занятая операцией: …», «баланс работ за цикл …»,
«вынуждающая частота …», the crank pin's loads — had kept its small letter and no full stop).
A paragraph that opens with a formula's symbol (ω = …) is one; so is a heading's text."""
from __future__ import annotations

from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()

COMMANDS = {
    "run": ["run", str(CASES / "shaper.toml"), "--no-plots"],
    "duty-cycle": ["duty-cycle", str(CASES / "duty_khurmi_16_20_punch_stroke.toml")],
    "task2": ["task2", "--case", str(CASES / "task2_khurmi_16_9_power.toml")],
    "aggregate": ["aggregate", str(CASES / "aggregate.toml")],
}


def _paragraphs(md: str) -> list[str]:
    lines = md.split("\n")
    return [ln for i, ln in enumerate(lines)
            if ln and (i == 0 or not lines[i - 1]) and ln[0].isalpha()]


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_no_paragraph_begins_with_a_small_letter(command, lang, tmp_path):
    res = runner.invoke(app, [*COMMANDS[command], "--lang", lang, "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    # but the explanation of a formula's symbols, which opens with «где» («where») and no
    # colon (ГОСТ 7.32-2017, 6.8.2)
    small = [p for p in _paragraphs(md) if p[0].islower() and p[0] not in "ωεφδ"
             and not p.startswith(("где ", "where "))]
    assert not small, small


@pytest.mark.parametrize("case", ["compressor", "shaper"])
def test_the_records_sections_are_numbered_without_a_gap(case, tmp_path):
    """The markdown and HTML record number their sections 1, 2, … and subsections 1.1, 1.2, …
    as the ГОСТ PDF does: the compressor has no technological forces (section 1.5 of the
    builder), the shaper no cylinders (1.4); they had read 1.4 then 1.6, 1.3 then 1.5, and the
    force analysis had no number at all. The sources are unnumbered."""
    import re

    res = runner.invoke(app, ["run", str(CASES / f"{case}.toml"), "--no-plots", "--lang", "ru",
                              "-o", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    md = (tmp_path / "o" / "report.md").read_text(encoding="utf-8")
    heads = re.findall(r"^(##+) (.*)$", md, re.M)
    sections = [t for level, t in heads if level == "##"]
    assert sections[-1] == "Источники"
    assert [int(t.split(".")[0]) for t in sections[:-1]] == list(range(1, len(sections)))
    assert any(t.startswith("7. Силовой расчёт") for t in sections)
    n = 0
    for level, text in heads:
        if level == "##" and text != "Источники":
            n, m = int(text.split(".")[0]), 0
        elif level == "###":
            m += 1
            assert text.startswith(f"{n}.{m}. "), (text, n, m)


def test_a_formulas_symbols_are_explained_under_it_a_line_each(tmp_path):
    """ГОСТ 7.32-2017, 6.8.2: under the reduction's formulas and under the flywheel's, their
    symbols, each on a line of its own, the first line opening with «где» and no colon; in
    the markdown a hard break between the lines, in the PDF's typst a forced line break."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.blocks import Formula, Where
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography
    from flywheel.render.typst_blocks import typst_block

    case = load_case(CASES / "compressor.toml")
    with typography("ru"):
        doc = build_document(analyze(case, n_points=360), "ru", [], case=case)
    where = [(k, b) for k, b in enumerate(doc.blocks) if isinstance(b, Where)]
    assert len(where) == 4                        # reduction, energy, flywheel, motion
    for k, b in where:
        assert isinstance(doc.blocks[k - 1], Formula)            # directly under its formula
        assert b.lines[0].startswith("где ") and not b.lines[0].startswith("где:")
        assert len(b.lines) >= 3 and all(" — " in line for line in b.lines)
        assert typst_block(b, lambda x: x)[0].count(" \\\n") == len(b.lines) - 1
    assert where[1][1].lines[0].startswith("где M_С — приведённый момент сил сопротивления")
    assert "ΔT_нб — наибольшее изменение кинетической энергии" in where[2][1].text
    assert "J_10 + J_ред — момент инерции звеньев первой группы" in where[2][1].text
    # an engine's known moment is the driving one (its cycle balanced by M_С)
    case = load_case(CASES / "engine_4stroke.toml")
    with typography("ru"):
        doc = build_document(analyze(case, n_points=720), "ru", [], case=case)
    energy = [b for b in doc.blocks if isinstance(b, Where)][1]
    assert energy.lines[0].startswith("где M_Д — приведённый момент движущих сил")


def test_task2s_method_explains_its_symbols_under_its_formulas():
    """task2's «2. Метод решения»: under its formulas, their symbols a line each from «где»;
    ε and t where the task's graphs give them."""
    from flywheel.cases.task2 import load_task2_case, solve_case
    from flywheel.render.blocks import Formula, Where
    from flywheel.render.report_task2 import build_task2_document

    path = CASES / "task2_seed_triangle.toml"
    doc = build_task2_document(solve_case(load_task2_case(path), str(path)), "", "", "ru",
                               None)
    k, where = next((k, b) for k, b in enumerate(doc.blocks) if isinstance(b, Where))
    assert isinstance(doc.blocks[k - 1], Formula)
    assert where.lines[0] == "где M_Д, M_С — приведённые движущий момент и момент сопротивления;"
    assert where.lines[-1] == "ε — угловое ускорение, t — время от φ\u00a0=\u00a00."


def test_the_duty_cycles_formulas_are_explained_under_them():
    """The duty-cycle's «1. Метод»: its formulas' symbols from «где», a line each; the rim's
    too where the case designs one ([flywheel.rim])."""
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.render.blocks import Formula, Where
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    for name, rim in (("duty_khurmi_16_19_punch", False), ("duty_khurmi_16_23_punch_force", True)):
        path = CASES / f"{name}.toml"
        doc = build_duty_cycle_document(solve_case(load_duty_case(path), str(path)), "", "", "ru")
        k, where = next((k, b) for k, b in enumerate(doc.blocks) if isinstance(b, Where))
        assert isinstance(doc.blocks[k - 1], Formula)
        assert where.lines[0].startswith("где E — работа одной операции, t_оп — её время")
        assert where.lines[-1].startswith("D_ср — средний диаметр обода") == rim
        assert where.text.endswith(".") and not where.text.endswith(";.")


def test_the_aggregates_formulas_are_explained_under_them():
    """The aggregate's «Метод решения»: a_ij, b_ij, c_ij, q_j, Q_i, ω, f from «где»; the drive's
    δ and the margin from resonance where the case gives a drive."""
    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic.model import analyze as analyze_aggregate
    from flywheel.render.blocks import Formula, Where
    from flywheel.render.report_aggregate import FIGURE, build_aggregate_document

    path = CASES / "aggregate.toml"
    doc = build_aggregate_document(analyze_aggregate(*to_model(load_aggregate_case(path),
                                                               str(path))), "", "", "ru", FIGURE)
    k, where = next((k, b) for k, b in enumerate(doc.blocks) if isinstance(b, Where))
    assert isinstance(doc.blocks[k - 1], Formula)
    assert where.lines[0].startswith("где a_ij, b_ij, c_ij — инерционные коэффициенты")
    assert where.lines[-1].startswith("ω_вын — вынуждающая частота")


def test_the_aggregates_coordinates_are_set_without_underscores(tmp_path):
    """The aggregate's record had copied the terminal's «Σ_j a_ij·q̈_j …, q_(k+1) = φ_(k+1) − φ_k»
    before the formula that says the same: the PDF showed «q̈_j» and «q_(k+1)» with their
    underscores. It states the generalised coordinates alone, each subscript one the record
    sets (q_1, q_{k+1})."""
    from flywheel.render.mathfmt import subscripts

    for case in ("aggregate", "aggregate_branched_gear", "aggregate_khurmi_fixed_flywheel"):
        res = runner.invoke(app, ["aggregate", str(CASES / f"{case}.toml"), "--lang", "ru",
                                  "-o", str(tmp_path / case)])
        assert res.exit_code == 0, res.output
        md = (tmp_path / case / "report.md").read_text(encoding="utf-8")
        line = next(ln for ln in md.splitlines() if ln.startswith("Обобщённые координаты"))
        assert "Σ" not in line and "q̈" not in line
        assert not any("_" in text for text, _ in subscripts(line)), line


@pytest.mark.parametrize("name, lang", [("compressor", "ru"), ("engine_4stroke", "en"),
                                        ("shaper", "ru")])
def test_the_reduced_moments_sum_adds_up_with_the_constant_moment_it_names(name, lang):
    """The reduction table's M_Σ is its moments' columns plus the constant moment of the cycle
    balance, which has no column (the pump's φ = 0: −7,063 + 0 + 0 ≠ 882,4 had read as an
    error): the sentence under it names that moment, and each row's printed numbers add up to
    its printed M_Σ (to their printed digits)."""
    import re

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.blocks import Paragraph, Table
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    res = analyze(load_case(CASES / f"{name}.toml"), n_points=360)
    with typography(lang):
        doc = build_document(res, lang)
    k, table = next((k, b) for k, b in enumerate(doc.blocks)
                    if isinstance(b, Table) and b.header[-1].startswith("M_Σ"))
    note = doc.blocks[k + 1]
    where = "в таблице" if lang == "ru" else "in Table"
    assert isinstance(note, Paragraph) and note.text.startswith(f"M_Σ {where} {table.number}")

    def number(text: str) -> float:
        return float(text.replace("\u2212", "-").replace("\u202f", "").replace(",", "."))

    constant = number(re.search(r"= (\S+) (Н·м|N·m)", note.text).group(1))
    assert constant == pytest.approx(res.scalars.balancing_moment, rel=1e-3)
    first = next(j for j, h in enumerate(table.header) if h.startswith("dJ")) + 1
    for row in table.rows:
        parts = [number(c) for c in row[first:-1] if c != "—"]
        total = number(row[-1])
        assert sum(parts) + constant == pytest.approx(total, abs=2e-3 * max(1.0, abs(total))
                                                      + 5e-4 * sum(abs(p) for p in parts)), row
