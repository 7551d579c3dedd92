"""Issue 27, step 5: a feedback page per student (HTML, in the teacher's --lang, --no-reveal)
and the diagnosis column of the gradebook."""
import csv
import math
import re
from html.parser import HTMLParser

import pytest

from chain_helpers import data_of, key_of, make, runner, textbook, write_sheet
from helpers import ru_numbers  # a Russian text's numbers (tests/helpers.py)
from flywheel.cli import app


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    return make(tmp_path_factory, "variants_compressor.toml", count=2, seed=31)


class Cells(HTMLParser):
    """The text of every <td> of a page, row by row (and that tags are balanced)."""

    def __init__(self):
        super().__init__()
        self.rows, self.open, self.cell = [], [], None

    def handle_starttag(self, tag, attrs):
        if tag not in ("meta", "br"):
            self.open.append(tag)
        if tag == "tr":
            self.rows.append([])
        if tag == "td":
            self.cell = ""

    def handle_endtag(self, tag):
        assert self.open.pop() == tag
        if tag == "td":
            self.rows[-1].append(self.cell)
            self.cell = None

    def handle_data(self, data):
        if self.cell is not None:
            self.cell += data


def parse(path):
    p = Cells()
    p.feed(path.read_text(encoding="utf-8"))
    p.close()
    assert not p.open
    return [r for r in p.rows if r]


@pytest.fixture(scope="module")
def sheet(compressor, tmp_path_factory):
    key = key_of(compressor)
    a1, a2 = key["variants"]["01"], key["variants"]["02"]
    carried = dict(a1, delta_T_max=a1["delta_T_max"] * 1.3)
    carried.update(textbook(data_of(compressor, "01"), carried["delta_T_max"]))
    half = dict(a2, J_required=a2["J_required"] * 2)              # δ/2 for δ
    return write_sheet(tmp_path_factory.mktemp("fb") / "s.csv", key,
                       [("Иванов И. И.", "01", carried), ("Petrova/../x", "02", half)])


def test_a_page_per_student_in_russian_with_verdicts_diagnosis_and_the_key(compressor, sheet,
                                                                            tmp_path):
    out = tmp_path / "fb"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--feedback", str(out), "--lang", "ru", "--carried-forward", "0.5"])
    assert res.exit_code == 0, res.output
    pages = sorted(p.name for p in out.glob("*.html"))
    assert pages == ["001_Иванов_И_И.html", "002_Petrova_x.html"]   # no path out of the folder
    key = key_of(compressor)
    text = (out / pages[0]).read_text(encoding="utf-8")
    assert 'lang="ru"' in text and "Разбор: Иванов И. И., вариант 01" in text
    rows = parse(out / pages[0])
    verdict = {r[0].split("\n")[0]: r[2] for r in rows}
    assert list(verdict.values()) == ["верно", "НЕВЕРНО", "верно по вашим данным",
                                      "верно по вашим данным", "верно по вашим данным"]
    # the expected value is the key's in Russian typography (a decimal comma, four digits)
    assert "," in rows[1][4] and "." not in rows[1][4]
    # the table's heads from a capital letter (ГОСТ 2.105-2019, 4.4.5), the tolerance as ±
    heads = re.findall(r"<th>([^<]*)</th>", text)
    assert heads == ["Величина", "Ваш ответ", "Итог", "В чём ошибка", "Ожидалось", "Допуск"]
    assert all(r[5] == "±1 %" or r[5].startswith("±") for r in rows), [r[5] for r in rows]
    assert ru_numbers(rows[1][4]) == pytest.approx([key["variants"]["01"]["delta_T_max"]],
                                                   rel=5e-4)
    rows = parse(out / pages[1])
    J = next(r for r in rows if "J_required" in r[0])
    assert J[2] == "НЕВЕРНО" and J[3] == "вместо δ взято δ/2"
    assert not any(c.isascii() and c.isalpha() for c in J[3])


def test_no_reveal_leaves_the_key_out(compressor, sheet, tmp_path):
    out = tmp_path / "fb"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--feedback", str(out), "--no-reveal"])
    assert res.exit_code == 0, res.output
    key = key_of(compressor)["variants"]
    page = next(out.glob("001_*.html"))
    rows = parse(page)
    assert {len(r) for r in rows} == {5}             # answer, given, verdict, diagnosis, tol.
    text = page.read_text(encoding="utf-8")
    for a in ("delta_T_max", "J_required", "J_flywheel"):     # wrong or carried: not shown
        assert f"{key['01'][a]:.6g}" not in text
    assert "The expected values are not shown." in text


def test_the_gradebook_has_the_diagnosis(compressor, sheet, tmp_path):
    book = tmp_path / "b.csv"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--gradebook", str(book)])
    assert res.exit_code == 0, res.output
    rows = list(csv.DictReader(book.open(encoding="utf-8")))
    # student 1's ΔT_max is 1.3 times the key's, no classic mistake: the formula to check, and
    # what it gives from the student's own (right) M_D: the key's value
    key = key_of(compressor)["variants"]["01"]
    assert rows[0]["carried forward"] == "3"
    assert rows[0]["diagnosis"] == (
        "delta_T_max: check ΔT_max = max ΔT_I − min ΔT_I over the whole cycle, ΔT_I = A − "
        f"(T_II − T_II(0)); from the student's M_D = {key['driving_moment']:.6g} it is "
        f"{key['delta_T_max']:.6g}")
    assert rows[1]["diagnosis"] == "J_required: δ/2 used for δ"


def test_the_russian_gradebook_says_what_to_check_with_decimal_commas(compressor, sheet,
                                                                      tmp_path):
    book = tmp_path / "b.csv"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--gradebook", str(book), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    rows = list(csv.reader(book.open(encoding="utf-8")))
    diagnosis = rows[1][-1]
    assert diagnosis.startswith("delta_T_max: проверить ΔT_нб = "), diagnosis
    assert "из M_Д = " in diagnosis and "студента получается" in diagnosis, diagnosis
    key = key_of(compressor)["variants"]["01"]
    assert ru_numbers(diagnosis)[-1] == pytest.approx(key["delta_T_max"], rel=5e-4)
    assert "." not in diagnosis.split("проверить")[1].split("студента")[1], diagnosis


@pytest.mark.parametrize("args, fragment", [
    (["--no-reveal"], "--no-reveal: given without --feedback"),
    (["--feedback", "{key}"], "is the answer key"),
    (["--feedback", "{sheet}"], "is the answer sheet"),
])
def test_feedback_options_refused_in_one_line(compressor, sheet, args, fragment):
    args = [a.format(key=compressor / "answers.json", sheet=sheet) for a in args]
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet), *args])
    assert res.exit_code == 2, res.output
    assert fragment in res.output and "Traceback" not in res.output


def test_a_folder_of_the_users_is_not_written_into(compressor, sheet, tmp_path):
    mine = tmp_path / "mine"
    mine.mkdir()
    (mine / "notes.txt").write_text("mine", encoding="utf-8")
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--feedback", str(mine)])
    assert res.exit_code == 2, res.output
    assert (mine / "notes.txt").read_text(encoding="utf-8") == "mine"
    assert sorted(p.name for p in mine.iterdir()) == ["notes.txt"]


def test_a_task2_page_names_the_answers_as_its_task_sheet_does(tmp_path_factory, tmp_path):
    """The page of a task2 key asks J_required as task2's sheet does — «приведённый момент
    инерции, обеспечивающий заданный δ, J_пр» — not as a run's («необходимый момент инерции
    первой группы звеньев J_I»: the page had named every key's answers as a run's)."""
    folder = make(tmp_path_factory, "variants_task2.toml", count=1, seed=5)
    key = key_of(folder)
    assert key["kind"] == "task2" and "J_required" in key["answers"]
    ans = dict(key["variants"]["01"])
    ans["J_required"] *= 1.3
    sheet = write_sheet(tmp_path / "s.csv", key, [("Иванов", "01", ans)])
    out = tmp_path / "fb"
    res = runner.invoke(app, ["grade", str(folder / "answers.json"), str(sheet),
                              "--feedback", str(out), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    page = next(out.glob("*.html"))
    J = next(r[0] for r in parse(page) if "J_required" in r[0])
    assert "Jтреб" in J and "при [δ]" in J and "первой группы" not in J, J
    # a key within 0.001 % (ω_max) expected to the digits its tolerance tells apart, not to
    # the four digits of a result (ω_max and ω_min had both read «250»)
    w = next(r for r in parse(page) if "omega_max" in r[0])
    assert re.fullmatch(r"\d+,\d{3,}", w[4]), w
    # a table's row names its answer in the nominative, as a table does: «наибольшая угловая
    # скорость», not the sheet's «Определить наибольшую угловую скорость» (it had)
    assert w[0].startswith("наибольшая угловая скорость ωmax"), w[0]
    # the symbols' subscripts as the task sheet sets them, in <sub> (not «J_пр»)
    text = page.read_text(encoding="utf-8")
    assert "J<sub>треб</sub>" in text and "ΔT<sub>нб</sub>" in text and "J_треб" not in text


def test_a_wrong_answer_no_mistake_explains_points_at_its_formula(compressor, sheet, tmp_path):
    """Ivanov's ΔT_нб is 1.3 times the key's, which no classic mistake gives: the page had said
    «—» in «в чём ошибка»; it names the formula to check, in the course's notation (seed 000
    §4). An answer right, carried forward or with a named mistake keeps its own words."""
    out = tmp_path / "fb"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--feedback", str(out), "--lang", "ru", "--no-reveal"])
    assert res.exit_code == 0, res.output
    rows = {r[0].split("\n")[0]: r for r in parse(next(out.glob("001_*.html")))}
    dT = next(r for k, r in rows.items() if "delta_T_max" in "".join(r))
    assert dT[2] == "НЕВЕРНО"
    assert dT[3] == "проверьте ΔTнб = max ΔTI − min ΔTI за весь цикл, ΔTI = A − (TII − TII(0))"
    assert all(r[3] == "—" for r in rows.values() if r[2] != "НЕВЕРНО")
    rows = parse(next(out.glob("002_*.html")))
    assert next(r for r in rows if "J_required" in r[0])[3] == "вместо δ взято δ/2"


def test_every_formula_of_the_feedback_is_a_chains_answer():
    """The formulas name answers the chains compute (teaching/chain.py, chain_task2.py)."""
    from flywheel.render.grading import FORMULAS_RUN, FORMULAS_TASK2
    from flywheel.teaching import chain, chain_task2

    assert set(FORMULAS_RUN["en"]) <= set(chain.STEPS)
    assert set(FORMULAS_TASK2["en"]) <= set(chain_task2.STEPS["resistance"]) | set(
        chain_task2.STEPS["driving"])
    assert set(FORMULAS_RUN["ru"]) == set(FORMULAS_RUN["en"])


def test_a_wrong_answer_is_worked_from_the_students_own_earlier_answer(compressor, sheet,
                                                                       tmp_path):
    """With the key revealed, the formula to check goes with what the student's own earlier
    answer gives by it (the chain, teaching/chain.py): Ivanov's M_Д is right, so his ΔT_нб
    worked from it is the key's; without the key shown, the formula alone."""
    out = tmp_path / "fb"
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--feedback", str(out), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    key = key_of(compressor)["variants"]["01"]
    rows = parse(next(out.glob("001_*.html")))
    dT = next(r for r in rows if "delta_T_max" in r[0])
    m = re.fullmatch(r"проверьте .*; из вашего MД = ([\d,\u202f]+) получается ([\d,\u202f]+)",
                     dT[3])
    assert m, dT[3]
    assert ru_numbers(m.group(2)) == pytest.approx([key["delta_T_max"]], rel=5e-4)
    assert m.group(2) == dT[4]                      # as the expected value is printed
    hidden = tmp_path / "hidden"
    runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                        "--feedback", str(hidden), "--lang", "ru", "--no-reveal"])
    assert "из вашего" not in next(hidden.glob("001_*.html")).read_text(encoding="utf-8")


def test_the_terminal_report_points_a_wrong_answer_at_its_formula_too(compressor, sheet):
    """The teacher's terminal report had left the diagnosis of a wrong answer no classic mistake
    explains empty (the feedback page gave the formula): it names the formula to check and what
    the student's own earlier answer gives by it. Ivanov's M_Д is right, so his ΔT_нб worked
    from it is the key's (within the printing's four digits)."""
    res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                              "--lang", "ru"], env={"COLUMNS": "400"}, terminal_width=400)
    assert res.exit_code == 0, res.output
    key = key_of(compressor)["variants"]["01"]
    row = next(ln for ln in res.output.splitlines() if ln.startswith("│ ΔT_нб") and "НЕВЕРНО" in ln)
    said = row.split("│")[7].strip()
    m = re.fullmatch(r"проверить ΔT_нб = .*; из M_Д = ([\d,\u202f]+) студента получается "
                     r"([\d,\u202f]+)", said)
    assert m, said
    assert ru_numbers(m.group(2)) == pytest.approx([key["delta_T_max"]], rel=5e-4)
    half = next(ln for ln in res.output.splitlines() if ln.startswith("│ J_I") and "НЕВЕРНО" in ln)
    assert half.split("│")[7].strip() == "вместо δ взято δ/2"      # a named mistake: its name
    # the teacher's report names a carried-forward verdict in the third person (the student's
    # own page says «верно по вашим данным»)
    assert "верно по данным студента" in res.output and "по вашим данным" not in res.output
    # the default share is 0: the carried-forward answers are counted and said not credited
    assert ("верно по данным студента (следуют из его же предыдущих ответов): 3; не засчитаны"
            in " ".join(res.output.split()))
