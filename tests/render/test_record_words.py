"""The Russian записка speaks Russian (issue 28): every bundled case's record (run, task2,
aggregate, duty-cycle) as md and html has no developer text — no `docs/` path, no ASCII arrow
"->", no Latin word but the symbols, the case's own names and the sources — and says the cycle
condition in the machine's own words: a driven machine finds M_Д from A_С, an engine M_С from
A_Д. The records are built from the results with every figure's name (their captions), without
drawing the figures."""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path

import pytest

from flywheel.io.text import in_language
from flywheel.io.toml import read_toml
from flywheel.render.report import markdown
from flywheel.render.report_formats import html

CASES = Path(__file__).resolve().parents[2] / "cases"
RUN = sorted(p.stem for p in CASES.glob("*.toml")
             if not p.stem.startswith(("task2", "aggregate", "duty", "variants")))
OTHER = sorted(p.stem for p in CASES.glob("*.toml") if p.stem.startswith(("task2", "aggregate",
                                                                            "duty")))
#: Latin that is a symbol: extremes, Roman numerals of the groups, the Assur groups' kinds, and
#: the values a case file takes that a warning names (the interpolations), and the cosine of a
#: formula in the text (M = F·|V_q|·cos α)
SYMBOLS = {"max", "min", "II", "III", "RRR", "RRP", "RPR", "pchip", "linear", "natural", "spline",
           "periodic", "cos"}
#: a Latin word of three letters or more standing alone (not part of a symbol like v_qA, J_II)
WORD = re.compile(r"(?<![\w_/\\])[A-Za-z]{3,}(?![\w_])")


def _user_words(data) -> set[str]:
    """The Latin words of the case's own values (names of links, loads, rotors, the first
    group's parts, interpolations): the user's, kept as written."""
    out: set[str] = set()
    if isinstance(data, dict):
        for k, v in data.items():
            if k not in ("title", "source"):
                out |= _user_words(v)
    elif isinstance(data, list):
        for v in data:
            out |= _user_words(v)
    elif isinstance(data, str):
        out |= set(re.findall(r"[A-Za-z]+", data))
    for k in (data if isinstance(data, dict) else {}):
        if isinstance(data[k], (int, float, dict)) and k not in ("title", "source"):
            out |= set(re.findall(r"[A-Za-z]+", k))          # a table keyed by names
    return out


def _latin(md: str, source: str, allowed: set[str]) -> set[str]:
    words = set()
    for line in md.replace(source, "").splitlines():
        if line.startswith(("$$", "![")) or re.match(r"^- \[\d+\] ", line):   # formulas, sources
            continue
        line = re.sub(r"\$[^$]*\$", "", line)                                # inline math
        words |= set(WORD.findall(line)) - allowed
    return words


def _text_of_html(page: str) -> str:
    page = re.sub(r"(?s)<(style|script)\b.*?</\1>", "", page)
    page = re.sub(r"(?s)<!--.*?-->", "", page)
    return re.sub(r"<[^>]+>", " ", page)


def _check(doc, case_path: Path, source: str) -> None:
    md = markdown(doc)
    page = _text_of_html(html(doc))
    for text in (md, page):
        assert "docs/" not in text and "->" not in text, [
            ln for ln in text.splitlines() if "docs/" in ln or "->" in ln]
    left = _latin(md, source, SYMBOLS | _user_words(read_toml(case_path)))
    assert not left, left


@lru_cache(maxsize=None)
def _run_document(name: str, lang: str = "ru"):
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.plots import all_figures

    case = load_case(CASES / f"{name}.toml")
    res = analyze(case, n_points=360)
    return case, res, build_document(res, lang, [f for f, _ in all_figures(res, lang)], case=case)


@pytest.mark.parametrize("name", RUN)
def test_a_russian_run_record_has_no_developer_text(name):
    case, _, doc = _run_document(name)
    assert doc.title == in_language(case.title, "ru") and re.search("[а-я]", doc.title)
    _check(doc, CASES / f"{name}.toml", in_language(case.source, "ru"))


#: a number as the Russian record writes it: digits (narrow spaces between thousands), a
#: decimal comma, a sign
_NUMBER = re.compile(r"(?<![\w.,])[−-]?\d[\d\u202f]*(?:,\d+)?(?![\w])")


@pytest.mark.parametrize("name", RUN)
def test_a_russian_run_record_prints_no_number_past_seven_digits(name):
    """Sensible significant figures: no number of the record (formulas aside) has more than 7
    significant digits — a measured indicator diagram (engine_measured) had been listed as 360
    rows of its travel and pressure to 17 digits."""
    from flywheel.render.numbers import typography

    with typography("ru"):
        md = markdown(_run_document(name)[2])
    long = [m.group() for line in md.splitlines() if not line.startswith("$$")
            for m in _NUMBER.finditer(line)
            if len(re.sub(r"\D", "", m.group()).strip("0" if "," in m.group() else "")
                   .lstrip("0")) > 7]
    assert not long, long[:5]


def _other_document(name: str, lang: str = "ru"):
    p = CASES / f"{name}.toml"
    if name.startswith("task2"):
        from flywheel.cases.task2 import load_task2_case, solve_case
        from flywheel.render.report_task2 import build_task2_document

        c = load_task2_case(p)
        return c, build_task2_document(solve_case(c, str(p)), in_language(c.title, lang),
                                       in_language(c.source, lang), lang, "task2.png")
    if name.startswith("aggregate"):
        from flywheel.cases.aggregate import load_aggregate_case, to_model
        from flywheel.elastic.model import analyze
        from flywheel.render.report_aggregate import FIGURE, build_aggregate_document

        c = load_aggregate_case(p)
        r = analyze(*to_model(c, str(p)))
        return c, build_aggregate_document(r, in_language(c.title, lang),
                                           in_language(c.source, lang), lang, FIGURE)
    from flywheel.cases.duty_cycle import load_duty_case, solve_case
    from flywheel.render.report_duty_cycle import build_duty_cycle_document

    c = load_duty_case(p)
    return c, build_duty_cycle_document(solve_case(c, str(p)), in_language(c.title, lang),
                                        in_language(c.source, lang), lang)


@pytest.mark.parametrize("name", OTHER)
def test_a_russian_task2_aggregate_duty_record_has_no_developer_text(name):
    c, doc = _other_document(name)
    _check(doc, CASES / f"{name}.toml", in_language(c.source, "ru"))
    # a table's rows numbered under «№», as the run's record numbers its positions (task2's
    # segments and phases, the aggregate's rotors and connections had a bare «#»)
    assert not [tb.caption for tb in doc.tables if "#" in tb.header]
    numbered = [tb.header[0] for tb in doc.tables if tb.header[1:2] in (("φ, °",), ("φ₁, °",))
                or "Между" in tb.header]
    assert numbered.count("№") >= (1 if name.startswith(("task2", "aggregate")) else 0)


def test_every_bundled_case_gives_its_title_and_source_in_both_languages():
    """title and source of every case kind are { ru = "…", en = "…" } tables (io.text.Text),
    the Russian in Cyrillic; a case that has no source has none."""
    from flywheel.io.text import Text

    for p in sorted(CASES.glob("*.toml")):
        if p.stem.startswith("variants"):
            continue            # templates: their sheets take the title as a string
        data = read_toml(p)
        for key in ("title", "source"):
            if key == "source" and key not in data:
                continue
            v = data[key]
            assert isinstance(v, dict) and set(v) == {"ru", "en"}, (p.name, key)
            assert re.search("[А-Яа-яЁё]", v["ru"]) and v["ru"] != v["en"], (p.name, key)
        loader = _loader(p.stem)
        case = loader(p)
        assert isinstance(case.title, Text) and case.title.ru == data["title"]["ru"]
        assert str(case.title) == data["title"]["en"]


def _loader(stem: str):
    if stem.startswith("task2"):
        from flywheel.cases.task2 import load_task2_case as load
    elif stem.startswith("aggregate"):
        from flywheel.cases.aggregate import load_aggregate_case as load
    elif stem.startswith("duty"):
        from flywheel.cases.duty_cycle import load_duty_case as load
    else:
        from flywheel.cases.run import load_case as load
    return load


def test_a_plain_string_title_is_the_same_in_both_languages():
    from flywheel.cases.run import parse_case

    data = read_toml(CASES / "fourbar.toml")
    data["title"] = "Четырёхзвенник 4-bar"
    case = parse_case(data)
    assert in_language(case.title, "ru") == in_language(case.title, "en") == "Четырёхзвенник 4-bar"


@pytest.mark.parametrize("name, known, found", [
    ("compressor", ("A_С", "M_С"), "M_Д"),          # a driven machine: M_Д from A_С
    ("engine_4stroke", ("A_Д", "M_Д"), "M_С"),      # an engine: M_С from A_Д
])
def test_the_cycle_condition_speaks_of_the_machine(name, known, found):
    """The energy section's sentence, the summary's rows and the force section follow
    machine.balance; one sign rule stated once; no code symbol (M_const) anywhere."""
    _, res, doc = _run_document(name)
    md = markdown(doc)
    A, M = known
    formula = next(ln for ln in md.splitlines() if ln.startswith(f"$$ {found} = "))
    assert f"{found} = -\\frac{{{A}}}{{\\Phi}}" in formula
    assert f"$$ {A} = \\oint {M} d\\varphi" in md
    sentence = next(ln for ln in md.splitlines() if ln.startswith(f"- {A} = "))
    assert f"; {found} = " in sentence and "условие цикла" in sentence
    assert md.count("Правило знаков") == 1 and "M_const" not in md and "M_{const}" not in md
    assert f"M_у = {found} при каждом φ" in md
    # the value is the result's: M_Д of a compressor, M_С (negative) of an engine
    M_found = res.scalars.driving_moment if found == "M_Д" else res.scalars.balancing_moment
    assert (M_found > 0) == (found == "M_Д")
    en = markdown(_run_document(name, "en")[2])
    A_en, M_en = (a.replace("Д", "D").replace("С", "C") for a in known)
    assert f"$$ {A_en} = \\oint {M_en} d\\varphi" in en and "M_const" not in en


def test_the_summary_rows_follow_the_balance():
    """The terminal summary of an engine: A_Д (positive) and M_С (negative), not A_С and M_Д."""
    import io

    from rich.console import Console

    from flywheel.render.summary import print_summary

    _, res, _ = _run_document("engine_4stroke")
    buf = io.StringIO()
    print_summary(res, Console(file=buf, width=200), "ru")
    out = buf.getvalue()
    assert "работа движущих сил за цикл A_Д" in out and "M_С (постоянный" in out
    assert "работа сил сопротивления за цикл A_С" not in out
    assert "приведённый движущий момент M_Д" not in out
    assert res.title.ru in out                      # the Russian title in a Russian summary


def test_the_russian_summary_lists_numbers_with_semicolons():
    """Russian typography: numbers listed in one cell are set apart by «;», the comma being
    the decimal mark («i = 1; 3,968», «D = 0,4816; b = 0,09632; m = 136,9»: the summary had
    written «i = 1, 3,968»); English keeps commas."""
    import io

    from rich.console import Console

    from flywheel.render.numbers import typography
    from flywheel.render.summary import print_summary

    _, res, _ = _run_document("compressor")
    for lang, sep in (("ru", "; "), ("en", ", ")):
        buf = io.StringIO()
        with typography(lang):                       # as the command line prints it
            print_summary(res, Console(file=buf, width=200), lang)
        rows = [ln for ln in buf.getvalue().splitlines() if re.search(r"[│ ]D = ", ln)]
        assert len(rows) == 2, rows                                  # the disk, the rim
        for ln in rows:
            cell = ln.split("│")[2].strip()
            assert cell.count(" = ") >= 3 and cell.count(sep) == cell.count(" = ") - 1, cell
        i_row = next(ln for ln in buf.getvalue().splitlines() if re.search(r"│ +i = ", ln))
        assert re.search(rf"i = 1{re.escape(sep)}\S", i_row), i_row
        assert ("0,4816" if lang == "ru" else "0.4816") in buf.getvalue()


def test_a_points_coordinates_are_set_apart_by_a_semicolon_in_russian():
    """The записка's input data: a point of the frame as «E (x; y) | 0,7; 0,3» in Russian (it
    wrote «0,7, 0,3», the decimal commas and the separator alike), "0.7, 0.3" in English."""
    from flywheel.render.numbers import typography

    for lang, row_g, row_E in (("ru", " g (x; y) | 0; −9,81 |", "| Неподвижная точка E (x; y) | 0,7; 0,3 |"),
                               ("en", " g (x, y) | 0, -9.81 |", "| Fixed point E (x, y) | 0.7, 0.3 |")):
        with typography(lang):
            md = markdown(_run_document("fourbar_rocker_load", lang)[2])
        assert row_g in md and row_E in md, lang


@pytest.mark.parametrize("name, words, not_words", [
    ("engine_4stroke", ("Звено 3 последней группы (ползун)", "Крайние положения звена 3"),
     ("Выходное звено", "выходного звена", "выходному звену")),
    ("compressor", ("Выходное звено 5 (ползун)", "Крайние положения выходного звена 5"),
     ("последней группы",)),
])
def test_an_engines_piston_is_not_called_its_output_link(name, words, not_words):
    """An engine's given forces drive it: its output is the crank, and the piston of its last
    group is «звено 3 последней группы», not «выходное звено 3» (a driven compressor's is)."""
    from flywheel.render.numbers import typography

    with typography("ru"):
        md = markdown(_run_document(name, "ru")[2])
    assert all(w in md for w in words) and not any(w in md for w in not_words), name


@pytest.mark.parametrize("name", RUN + [n for n in OTHER if not n.startswith("aggregate")])
def test_a_quantity_column_names_each_quantity_in_words(name):
    """A table whose first column is «величина» names every row in words, its symbol beside
    them: the duty-cycle's table of speeds had «ω_max», «ω_min» bare among «наибольшая частота
    вращения», and task2's results the same."""
    doc = _run_document(name)[2] if name in RUN else _other_document(name)[1]
    bare = [(t.caption, r[0]) for t in doc.tables if t.header and t.header[0] == "Величина"
            for r in t.rows if not re.search(r"[а-яё]{3,}", r[0])]
    assert not bare, bare


@pytest.mark.parametrize("lang, head", [("ru", "Группы Ассура: M_угр = M_у − J_I·ε"),
                                        ("en", "Assur groups: M_y,gr = M_y − J_I·ε")])
def test_the_groups_column_of_the_moments_says_what_it_holds(lang, head):
    """Table «Уравновешивающий момент M_у в расчётных положениях» set the groups' −441,2 N·m
    beside M_у = 197,5 three ways under «группы Ассура» alone, which read as a fourth M_у that
    disagreed. Its header states the identity, and the compressor's numbers at 120° hold it:
    M_угр = M_у − J_I·ε with J_I by Merzalov and the true ε."""
    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.document import build_document
    from flywheel.render.numbers import typography

    case = load_case(CASES / "compressor.toml")
    res = analyze(case, n_points=720)
    with typography(lang):
        doc = build_document(res, lang, [], case=case)
    table = next(t for t in doc.tables if head in t.header)
    row = table.rows[0]
    num = lambda c: float(c.replace("\u2212", "-").replace(",", "."))     # noqa: E731
    kin, groups = num(row[1]), num(row[table.header.index(head)])
    a = res.at[0]
    assert groups == pytest.approx(kin - res.scalars.J_required * a.epsilon, rel=2e-3)
    assert abs(groups - kin) > 100                    # the two differ: the header must say why


#: a Cyrillic letter (the course's subscripts нб, ср, ц in an English document)
CYRILLIC = re.compile(r"[А-Яа-яЁё]")


@pytest.mark.parametrize("name", ["compressor", "engine_4stroke", "shaper",
                                  "task2_seed_triangle", "task2_khurmi_16_4", "aggregate",
                                  "duty_khurmi_16_19_punch"])
def test_an_english_record_writes_no_cyrillic(name):
    """English records had written the course's ΔT_нб (task 2's ω_ср, T_ц; the aggregate's
    ω_ср, ω_в and its rotors J_Д, J_пр.I; the duty cycle's ω_ср) beside M_D, ω_m, J_red: every
    symbol of an English record is English now (ΔT_max, ω_m, T_c, ω_f, J_D, J_red.I). The
    case's own title and source, quoted, may be Russian."""
    if name.startswith(("task2", "aggregate", "duty")):
        c, doc = _other_document(name, "en")
    else:
        c, _, doc = _run_document(name, "en")
    quoted = [in_language(c.title, "en"), in_language(c.source, "en")]
    text = markdown(doc)
    for q in quoted:
        text = text.replace(q, "")
    body = text.split("## Sources")[0]
    assert not [ln for ln in body.splitlines() if CYRILLIC.search(ln)], name


def test_a_tables_empty_cell_is_a_dash_and_its_heads_open_with_a_capital():
    """ГОСТ 2.105-2019, 4.4.5 and 4.4.15: column and row heads from a capital letter, a dash where
    a cell has no data. The shaper's dead centre between two numbered positions has no number
    («—»), a text value no unit («движущий», «—»), a task-2 result without rev/min no note; a
    subordinate row («в том числе: …») and a symbol («φ, °») keep their lower case."""
    shaper = _run_document("shaper")[2]
    kin = next(t for t in shaper.tables if t.header[:2] == ("№", "φ, °"))
    dead = [r for r in kin.rows if r[1].startswith("22")]
    assert dead and dead[0][0] == "—", dead
    compressor = _run_document("compressor")[2]
    rows = {r[0]: r for t in compressor.tables for r in t.rows}
    assert rows["Постоянный момент из условия цикла"][1:] == ("движущий", "—")
    assert "в том числе: коленчатый вал" in rows
    assert all(c.strip() for t in compressor.tables + shaper.tables for r in t.rows for c in r)
    _, task2 = _other_document("task2_khurmi_16_1")
    mean = next(r for t in task2.tables for r in t.rows if r[0].startswith("Средняя угловая"))
    assert mean[-1] == "—", mean
