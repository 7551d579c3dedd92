"""`flywheel grade`: scores against the key of `flywheel variants`, tolerances, the group
statistics, and a batch that goes on past broken files and rows."""
import csv
import json
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.errors import CaseFileError
from flywheel.teaching.grading import grade, parse_key, parse_number, rel_error
from helpers import err_text  # a CliRunner result's stderr (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()


def invoke(*args):
    return runner.invoke(app, ["grade", *map(str, args)])



def one_line_error(res, *fragments):
    assert res.exit_code == 2, res.output
    assert "Traceback" not in res.output
    lines = [ln for ln in err_text(res).splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    for f in fragments:
        assert f in lines[0], lines[0]


@pytest.fixture(scope="module")
def key_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("g") / "variants"
    res = runner.invoke(app, ["variants", str(CASES / "variants_task2.toml"), "--count", "4",
                              "--seed", "9", "--out", str(out)])
    assert res.exit_code == 0, res.output
    return out


@pytest.fixture(scope="module")
def key(key_dir):
    return json.loads((key_dir / "answers.json").read_text())


def sheet(path: Path, key: dict, change=None, names=("ivanov", "petrova", "sidorov", "kim"),
          delimiter=",", encoding="utf-8", fmt=repr) -> Path:
    """The key's own answers as a filled sheet; change(row_index, answers) edits a row."""
    rows = [["student", "variant", *key["answers"]]]
    for i, (vid, ans) in enumerate(key["variants"].items()):
        ans = dict(ans)
        if change:
            change(i, ans)
        rows.append([names[i], vid, *(fmt(ans[a]) if isinstance(ans[a], float) else ans[a]
                                      for a in key["answers"])])
    with open(path, "w", newline="", encoding=encoding) as f:
        csv.writer(f, delimiter=delimiter).writerows(rows)
    return path


def as_json(*args):
    res = invoke(*args, "--json")
    return res, (json.loads(res.stdout) if res.stdout.strip() else None)


def test_perfect_sheet_scores_100(tmp_path, key_dir, key):
    res, rep = as_json(key_dir / "answers.json", sheet(tmp_path / "a.csv", key))
    assert res.exit_code == 0, res.output
    assert [s["score"] for s in rep["students"]] == [1.0] * 4
    assert rep["summary"]["mean_score"] == 1.0 and rep["summary"]["full_marks"] == 4
    assert rep["summary"]["most_often_wrong"] is None and rep["problems"] == []
    assert all(a["error"] == 0 for s in rep["students"] for a in s["answers"])


def test_one_wrong_answer_is_named(tmp_path, key_dir, key):
    def wrong(i, ans):
        if i == 1:
            ans["J_required"] *= 1.5
    res, rep = as_json(key_dir / "answers.json", sheet(tmp_path / "a.csv", key, wrong))
    assert res.exit_code == 0
    petrova = rep["students"][1]
    assert petrova["student"] == "petrova" and petrova["wrong"] == ["J_required"]
    assert petrova["passed"] == 5 and petrova["total"] == 6
    assert petrova["score"] == pytest.approx(5 / 6)
    bad = next(a for a in petrova["answers"] if a["answer"] == "J_required")
    assert bad["error"] == pytest.approx(0.5) and bad["pass"] is False
    assert rep["summary"]["mean_score"] == pytest.approx((3 + 5 / 6) / 4)
    assert rep["summary"]["most_often_wrong"] == {"answers": ["J_required"], "wrong": 1}
    # the rich report says the same
    res = invoke(key_dir / "answers.json", tmp_path / "a.csv")
    assert res.exit_code == 0
    assert "petrova — variant 02 — 5/6" in res.output
    assert "most often wrong: J_required (1 of 4)" in res.output
    assert "FAIL" in res.output


def test_tolerances_default_option_and_per_answer(tmp_path, key_dir, key):
    def off(i, ans):   # 0.5 % off: within the key's 1 %
        ans["delta_T_max"] *= 1.005
        ans["omega_max"] *= 1 + 2.5e-4   # per-answer tolerance 5e-4 in the template
    path = sheet(tmp_path / "a.csv", key, off)
    res, rep = as_json(key_dir / "answers.json", path)
    assert res.exit_code == 0 and rep["summary"]["mean_score"] == 1.0
    _, rep = as_json(key_dir / "answers.json", path, "--tolerance", 0.001)
    assert all(s["wrong"] == ["delta_T_max"] for s in rep["students"])   # omega_max keeps 5e-4
    assert rep["tolerances"]["omega_max"] == 5e-4 and rep["tolerances"]["delta"] == 0.001


def test_missing_answer_fails_that_answer_only(tmp_path, key_dir, key):
    def blank(i, ans):
        if i == 0:
            ans["M_C"] = ""
    _, rep = as_json(key_dir / "answers.json", sheet(tmp_path / "a.csv", key, blank))
    ivanov = rep["students"][0]
    assert ivanov["wrong"] == ["M_C"] and ivanov["answers"][0]["given"] is None


def test_broken_files_and_rows_are_reported_and_skipped(tmp_path, key_dir, key):
    good = sheet(tmp_path / "good.csv", key)
    rows = good.read_text().splitlines()
    rows[2] = rows[2].replace(",02,", ",77,")            # petrova: unknown variant
    rows[3] = "sidorov,03,abc" + rows[3][rows[3].index(",", len("sidorov,03,")):]
    (tmp_path / "rows.csv").write_text("\n".join(rows) + "\n")
    (tmp_path / "binary.csv").write_bytes(b"\x00\x01\x02garbage")
    (tmp_path / "header.csv").write_text("name,var,J\nx,1,2\n")
    res, rep = as_json(key_dir / "answers.json", tmp_path / "rows.csv", tmp_path / "binary.csv",
                       tmp_path / "header.csv", tmp_path / "missing.csv")
    assert res.exit_code == 0, res.output
    assert [s["student"] for s in rep["students"]] == ["ivanov", "kim"]
    problems = [(Path(p["file"]).name, p["row"], p["message"]) for p in rep["problems"]]
    text = "\n".join(map(str, problems))
    assert ("rows.csv", 3) in [(f, r) for f, r, _ in problems]
    assert "variant '77' is not in the key" in text
    assert "'sidorov': not a number: M_C = 'abc'" in text
    assert "binary data" in text and "no 'student' and no 'variant' column" in text
    assert "no such file or folder" in text
    # the rich report lists them too
    res = invoke(key_dir / "answers.json", tmp_path / "rows.csv", tmp_path / "binary.csv")
    assert res.exit_code == 0 and "3 problem(s)" in res.output


def test_nothing_graded_exits_2(tmp_path, key_dir):
    (tmp_path / "binary.csv").write_bytes(b"\x00\x01")
    res = invoke(key_dir / "answers.json", tmp_path / "binary.csv")
    one_line_error(res, "nothing could be graded", "binary data")
    # the blank sheet of flywheel variants: every row unfilled, silently skipped
    res = invoke(key_dir / "answers.json", key_dir / "students.csv")
    one_line_error(res, "nothing could be graded: no filled-in student rows")


def test_folders_excel_style_sheets_and_variant_spellings(tmp_path, key_dir, key):
    folder = tmp_path / "sheets"
    folder.mkdir()
    # a Russian Excel's CSV: semicolons, decimal commas, Windows-1251, variant "3" for "03"
    sheet(folder / "group_a.csv", key, names=("Иванов", "Петрова", "Сидоров", "Ким"),
          delimiter=";", encoding="cp1251", fmt=lambda x: repr(x).replace(".", ","))
    text = (folder / "group_a.csv").read_bytes().decode("cp1251").replace(";03;", ";3;")
    (folder / "group_a.csv").write_bytes(text.encode("cp1251"))
    sheet(folder / "group_b.csv", key, names=("a", "b", "c", "d"), encoding="utf-8-sig")
    (folder / "notes.txt").write_text("not a sheet")
    res, rep = as_json(key_dir / "answers.json", folder)
    assert res.exit_code == 0, res.output
    assert [s["student"] for s in rep["students"]] == ["Иванов", "Петрова", "Сидоров", "Ким",
                                                       "a", "b", "c", "d"]
    assert rep["students"][2]["variant"] == "03"
    assert rep["summary"]["mean_score"] == 1.0


def test_out_writes_one_line_per_answer(tmp_path, key_dir, key):
    out = tmp_path / "grades.csv"
    res = invoke(key_dir / "answers.json", sheet(tmp_path / "a.csv", key), "--out", out)
    assert res.exit_code == 0, res.output
    with open(out, newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 4 * len(key["answers"])
    assert rows[0]["student"] == "ivanov" and rows[0]["answer"] == key["answers"][0]
    assert {r["pass"] for r in rows} == {"1"}
    one_line_error(invoke(key_dir / "answers.json", tmp_path / "a.csv", "--out", tmp_path),
                   "--out", "is a folder")
    # a file in a folder that does not exist (a mistyped path): refused before grading, as
    # task2 --plot does; nothing is created
    for option in ("--out", "--gradebook"):
        one_line_error(invoke(key_dir / "answers.json", tmp_path / "a.csv", option,
                              tmp_path / "no" / "such" / "book.csv"),
                       option, "book.csv: the folder", "no/such does not exist")
        assert not (tmp_path / "no").exists()


def test_bad_key_and_options(tmp_path, key_dir, key):
    sheet_path = sheet(tmp_path / "a.csv", key)
    one_line_error(invoke(tmp_path / "nope.json", sheet_path), "nope.json: no such file")
    (tmp_path / "k.json").write_text("{not json")
    one_line_error(invoke(tmp_path / "k.json", sheet_path), "k.json: not JSON")
    (tmp_path / "k.json").write_text(json.dumps({"variants": {"01": {"J": "big"}}}))
    one_line_error(invoke(tmp_path / "k.json", sheet_path), "variants.01.J: must be a finite")
    one_line_error(invoke(key_dir / "answers.json", sheet_path, "--tolerance", 0),
                   "--tolerance: must be a positive number")


def test_library_plain_key_and_zero_key(tmp_path):
    """A hand-written key {variant: {answer: value}}; a key of 0 is graded by absolute error."""
    k = parse_key({"1": {"A": 0.0, "B": 2.0}, "2": {"A": 1.0, "B": -2.0}})
    assert k.answers == ("A", "B") and k.tolerance == 0.01
    (tmp_path / "s.csv").write_text("student,variant,A,B\nx,1,0.005,2.01\ny,02,1,2\n")
    r = grade(k, [tmp_path / "s.csv"])
    x, y = r.students
    assert x.answers[0].error_kind == "absolute" and x.answers[0].error == pytest.approx(0.005)
    assert x.score == 1.0
    assert y.wrong == ["B"] and y.answers[1].error == pytest.approx(2.0)   # sign matters
    with pytest.raises(CaseFileError, match="must be an object"):
        parse_key({"1": 5})


def test_numbers_and_errors():
    assert parse_number(" 1\u00a0204,5 ") == 1204.5
    assert parse_number("\u22123.5e-2") == -0.035
    with pytest.raises(ValueError):
        parse_number("1,2,3")
    with pytest.raises(ValueError):
        parse_number("nan")
    assert rel_error(99.0, 100.0) == (pytest.approx(0.01), "relative")


NAMES_RU = ("Иванов Пётр", "Петрова Анна", "Сидоров Илья", "Ким Юлия")


@pytest.mark.parametrize("encoding, delimiter", [
    ("utf-8", ","), ("utf-8-sig", ";"), ("utf-16", "\t"),      # Excel's "Unicode text" is UTF-16
    ("cp1251", ";"), ("cp866", ","), ("koi8_r", ";")])
def test_sheets_in_every_common_encoding_are_read(tmp_path, key_dir, key, encoding, delimiter):
    path = sheet(tmp_path / f"{encoding}.csv", key, names=NAMES_RU, delimiter=delimiter,
                 encoding=encoding)
    res, rep = as_json(key_dir / "answers.json", path)
    assert res.exit_code == 0, res.output
    assert [s["student"] for s in rep["students"]] == list(NAMES_RU)
    assert rep["summary"]["mean_score"] == 1.0


def test_binary_and_undecodable_sheets_are_one_problem_each(tmp_path, key_dir, key):
    png = tmp_path / "photo.csv"                        # an image renamed .csv
    png.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + bytes(range(256)) * 4)
    good = sheet(tmp_path / "good.csv", key)
    res, rep = as_json(key_dir / "answers.json", png, good)
    assert res.exit_code == 0, res.output               # the batch goes on past it
    assert len(rep["students"]) == 4
    bad = [p for p in rep["problems"] if p["file"] == str(png)]
    assert len(bad) == 1 and "binary data" in bad[0]["message"], rep["problems"]
    # a UTF-8 BOM followed by bytes that are not UTF-8: refused, not guessed
    broken = tmp_path / "broken.csv"
    broken.write_bytes(b"\xef\xbb\xbfstudent,variant\n\xff\xfe\x98,01\n")
    res = invoke(key_dir / "answers.json", broken)
    one_line_error(res, "nothing could be graded", "byte-order mark")


def test_a_huge_variant_cell_is_just_an_unknown_variant(tmp_path, key_dir, key):
    path = sheet(tmp_path / "a.csv", key)
    text = path.read_text().replace(",01,", "," + "7" * 5000 + ",", 1)
    path.write_text(text)
    res, rep = as_json(key_dir / "answers.json", path)
    assert res.exit_code == 0, res.output
    assert len(rep["students"]) == 3
    assert any("is not in the key" in p["message"] for p in rep["problems"])


def test_a_large_sheet_grades_in_linear_time_and_prints_a_page(tmp_path, key_dir, key):
    """10⁵ rows: graded (the library is linear in the rows: no per-row search of the key), and
    the terminal gets the group table cut at a few hundred rows, not a table per student."""
    ids = list(key["variants"])
    rows = [["student", "variant", *key["answers"]]]
    for i in range(100_000):
        v = ids[i % len(ids)]
        rows.append([f"s{i}", v, *(repr(key["variants"][v][a]) for a in key["answers"])])
    big = tmp_path / "big.csv"
    with open(big, "w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows(rows)
    rep = grade(parse_key(key), [big])
    assert len(rep.students) == 100_000 and not [p for p in rep.problems
                                                 if "graded before" not in p.message]
    res = invoke(key_dir / "answers.json", big)
    assert res.exit_code == 0
    assert len(res.stdout.splitlines()) < 1500 and "… and 99500 more students" in res.stdout


def test_gradebook_one_row_per_student_in_sheet_order(tmp_path, key_dir, key):
    def wrong_first(i, ans):
        if i == 1:
            ans[key["answers"][0]] *= 1.5
    path = sheet(tmp_path / "a.csv", key, change=wrong_first)
    book = tmp_path / "book.csv"
    res = invoke(key_dir / "answers.json", path, "--gradebook", book)
    assert res.exit_code == 0, res.output
    rows = list(csv.reader(book.open(encoding="utf-8")))
    first = key["answers"][0]
    assert rows[0][:4] == ["student", "variant", f"{first} verdict", f"{first} error"]
    # a task2 key has a chain (issue 27): carried forward and the diagnosis after the score
    assert rows[0][-5:] == ["answers passed", "total", "score", "carried forward", "diagnosis"]
    assert [r[0] for r in rows[1:]] == ["ivanov", "petrova", "sidorov", "kim"]
    assert rows[2][2] == "FAIL" and float(rows[2][3]) == pytest.approx(0.5)
    assert rows[1][2] == "pass" and float(rows[1][-3]) == 1.0
    n = len(key["answers"])
    assert rows[2][-5:-2] == [str(n - 1), str(n), f"{(n - 1) / n:.4g}"]


def test_excel_ru_gradebook_and_report_open_in_a_russian_excel(tmp_path, key_dir, key):
    path = sheet(tmp_path / "a.csv", key, names=NAMES_RU,
                 change=lambda i, ans: ans.update({key["answers"][0]: ans[key["answers"][0]] * 1.25}))
    book, out = tmp_path / "book.csv", tmp_path / "out.csv"
    res = invoke(key_dir / "answers.json", path, "--gradebook", book, "--out", out,
                 "--csv", "excel-ru", "--lang", "ru")
    assert res.exit_code == 0, res.output
    for f in (book, out):
        raw = f.read_bytes()
        assert raw.startswith(b"\xef\xbb\xbf")                     # UTF-8 BOM
        rows = list(csv.reader(raw.decode("utf-8-sig").splitlines(), delimiter=";"))
        assert len({len(r) for r in rows}) == 1                    # every row splits alike
    rows = list(csv.reader(book.read_bytes().decode("utf-8-sig").splitlines(), delimiter=";"))
    assert rows[0][:2] == ["студент", "вариант"] and rows[1][0] == NAMES_RU[0]
    assert rows[1][2] == "НЕВЕРНО" and rows[1][3] == "0,25"       # a decimal comma
    one_line_error(invoke(key_dir / "answers.json", "--csv", "excel", path),
                   "--csv: 'excel' is not a CSV dialect (allowed: plain, excel-ru)")


def test_summary_prints_the_class_summary_only(tmp_path, key_dir, key):
    path = sheet(tmp_path / "a.csv", key)
    with open(path, "a", encoding="utf-8") as f:                  # one who handed in nothing
        f.write("nobody," + list(key["variants"])[0] + "," * len(key["answers"]) + "\n")
    res = invoke(key_dir / "answers.json", path, "--summary")
    assert res.exit_code == 0, res.output
    assert "Class summary: 5 graded" in res.stdout
    assert "Handed in nothing (1): nobody" in res.stdout
    assert "ivanov" not in res.stdout                              # no per-student tables
    res = invoke(key_dir / "answers.json", path, "--summary", "--lang", "ru")
    assert "Итоги группы: проверено 5" in res.stdout and "Не сдали ответов (1): nobody" in res.stdout
    _, rep = as_json(key_dir / "answers.json", path)
    assert rep["summary"]["handed_in_nothing"] == ["nobody"]
    assert sum(rep["summary"]["score_distribution"].values()) == 5


def test_the_whole_report_in_russian(tmp_path, key_dir, key):
    """--lang ru words the per-student tables, the group and the statistics in Russian; the
    numbers are the English report's, in Russian typography (four digits for a result)."""
    from helpers import en_numbers, ru_numbers, same_numbers

    path = sheet(tmp_path / "a.csv", key)
    en = invoke(key_dir / "answers.json", path)
    ru = invoke(key_dir / "answers.json", path, "--lang", "ru")
    assert en.exit_code == ru.exit_code == 0, ru.output
    assert "By answer" in en.stdout and "variant" in en.stdout
    for words in ("ivanov — вариант", "ответ", "допуск", "верно", "Группа: проверено 4",
                  "По ответам", "средний балл 100 %; все ответы верны: 4 из 4"):
        assert words in ru.stdout, words
    assert "By answer" not in ru.stdout and "mean score" not in ru.stdout
    # the answers by the symbols of task2's sheet, not by the keys the English report keeps
    for sym in ("M_С", "ω_max", "ω_min", "δ", "ΔT_нб", "J_треб"):
        assert re.search(rf"│ {sym} +│", ru.stdout), sym
    for k in ("omega_max", "J_required", "delta_T_max"):
        assert k not in ru.stdout and re.search(rf"│ {k} +│", en.stdout), k
    # a key within 0.001 % (ω_max, ω_min) to the digits its tolerance tells apart: «250,0103»,
    # not the four digits of a result («250», ω_min's too)
    rows = [[c.strip() for c in ln.split("│")[1:-1]] for ln in ru.stdout.splitlines()
            if ln.startswith("│ ω_m")]
    keys = [r[2] for r in rows if len(r) >= 6]            # a student's table: the key column
    assert keys and all(re.fullmatch(r"\d+,\d{3,}", v) for v in keys), keys
    assert not re.search(r"\d\.\d", ru.stdout)
    assert same_numbers(ru_numbers(ru.stdout), en_numbers(en.stdout))


def test_a_student_twice_the_later_row_counts(tmp_path, key_dir, key):
    a = sheet(tmp_path / "a.csv", key)
    b = sheet(tmp_path / "b.csv", key, names=("ivanov", "x1", "x2", "x3"),
              change=lambda i, ans: ans.update({k: v * 2 for k, v in ans.items()
                                                if isinstance(v, float)}) if i == 0 else None)
    res, rep = as_json(key_dir / "answers.json", a, b)
    names = [s["student"] for s in rep["students"]]
    assert names.count("ivanov") == 1 and names[0] == "ivanov"     # in the first's place …
    iv = rep["students"][0]
    assert iv["file"] == str(b) and iv["score"] < 1                # … with the later row
    assert any("'ivanov' appears again" in p["message"] and "the later row counts" in p["message"]
               for p in rep["problems"])


def test_a_class_batch_scored_as_a_teacher_would(tmp_path, key_dir, key):
    """One batch: right (ivanov), slightly off but inside every tolerance (petrova), badly
    wrong (sidorov: every answer 1.5 times the key), handed in nothing (kim), and ivanov again
    in a second file with his first answer wrong. A teacher's marks: the later ivanov row in
    the first's place, n−1 of n; petrova n of n; sidorov 0; kim 0 with every answer missing."""
    answers, n = key["answers"], len(key["answers"])
    tol = {a: key["tolerances"].get(a, key["tolerance"]) for a in answers}

    def edit(i, ans):
        for a in answers:
            if i == 1:
                ans[a] *= 1 + tol[a] / 2                       # within its own tolerance
            elif i == 2:
                ans[a] *= 1.5
            elif i == 3:
                ans[a] = ""
    first = sheet(tmp_path / "a.csv", key, change=edit)
    again = tmp_path / "b.csv"
    vid = list(key["variants"])[0]
    redo = dict(key["variants"][vid], **{answers[0]: 2 * key["variants"][vid][answers[0]]})
    with open(again, "w", newline="", encoding="utf-8") as f:
        csv.writer(f).writerows([["student", "variant", *answers],
                                 ["ivanov", vid, *(repr(redo[a]) for a in answers)]])
    book = tmp_path / "book.csv"
    res, rep = as_json(key_dir / "answers.json", first, again, "--gradebook", book)
    assert res.exit_code == 0, res.output
    marks = {s["student"]: (s["passed"], s["total"]) for s in rep["students"]}
    assert marks == {"ivanov": (n - 1, n), "petrova": (n, n), "sidorov": (0, n), "kim": (0, n)}
    assert rep["summary"]["handed_in_nothing"] == ["kim"]
    assert rep["summary"]["full_marks"] == 1
    assert rep["summary"]["score_distribution"] == {
        str(k): v for k, v in {0: 2, n - 1: 1, n: 1}.items()} | {
        str(k): 0 for k in range(n + 1) if k not in (0, n - 1, n)}
    assert [p for p in rep["problems"] if "'ivanov' appears again" in p["message"]]
    rows = list(csv.reader(book.open(encoding="utf-8")))
    assert [r[0] for r in rows[1:]] == ["ivanov", "petrova", "sidorov", "kim"]
    verdicts = {r[0]: r[2:2 + 2 * n:2] for r in rows[1:]}
    assert verdicts["ivanov"] == ["FAIL"] + ["pass"] * (n - 1)
    assert verdicts["petrova"] == ["pass"] * n
    # every answer 1.5 times the key: the later ones are consistent with the student's own
    # earlier ones (a task2 key's chain, issue 27) and say so; none passes
    assert verdicts["sidorov"][0] == "FAIL" and set(verdicts["sidorov"]) <= {
        "FAIL", "consistent with the student's earlier answer"} and verdicts["kim"] == ["no answer"] * n
    errors = {r[0]: r[3:3 + 2 * n:2] for r in rows[1:]}
    assert [float(e) for e in errors["sidorov"]] == pytest.approx([0.5] * n)
    assert [float(e) for e in errors["petrova"]] == pytest.approx([tol[a] / 2 for a in answers])
