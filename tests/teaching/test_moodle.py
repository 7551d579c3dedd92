"""Issue 27, step 6: the Moodle bridge. The question bank is checked against the structure of
Moodle's documented XML format (docs.moodle.org "Moodle XML format": <quiz>; a
<question type="category"> with <category><text>; a <question type="numerical"> with
<name><text>, <questiontext format><text>, <answer fraction="100"> holding <text> and an
absolute <tolerance>, and <units><unit><multiplier>, <unit_name>); a quiz's Responses export
(Surname, First name, …, Question N, Response N; "-" for no answer) grades as the equivalent
native sheet does."""
import csv
import json
import xml.etree.ElementTree as ET

import pytest

from chain_helpers import data_of, key_of, runner, textbook
from flywheel.cli import app
from flywheel.teaching.moodle import MAX_SLOTS


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    base = tmp_path_factory.mktemp("moodle")
    res = runner.invoke(app, ["variants", "cases/variants_compressor.toml", "--count", "3",
                              "--seed", "41", "--out", str(base / "v"), "--moodle",
                              str(base / "quiz.xml")])
    assert res.exit_code == 0, res.output
    return base


def questions(path):
    root = ET.parse(path).getroot()
    assert root.tag == "quiz"
    category, out = None, []
    for q in root:
        assert q.tag == "question"
        if q.get("type") == "category":
            category = q.find("category/text").text
            continue
        assert q.get("type") == "numerical"
        for needed in ("name/text", "questiontext/text", "answer/text", "answer/tolerance",
                       "defaultgrade"):
            assert q.find(needed) is not None, needed
        assert q.find("questiontext").get("format") == "html"
        answers = q.findall("answer")
        assert len(answers) == 1 and answers[0].get("fraction") == "100"
        unit = q.find("units/unit")
        out.append({"category": category, "name": q.find("name/text").text,
                    "text": q.find("questiontext/text").text,
                    "value": float(answers[0].find("text").text),
                    "tolerance": float(answers[0].find("tolerance").text),
                    "unit": None if unit is None else unit.find("unit_name").text,
                    "general": q.find("generalfeedback/text").text or "",
                    "multiplier": None if unit is None else float(unit.find("multiplier").text)})
    return out


def test_the_bank_holds_one_question_per_answer_with_its_tolerance(made):
    key = key_of(made / "v")
    qs = questions(made / "quiz.xml")
    assert len(qs) == len(key["variants"]) * len(key["answers"])
    by = {q["name"]: q for q in qs}
    for vid, ans in key["variants"].items():
        for a, v in ans.items():
            q = by[f"{vid} {a}"]
            assert q["category"].endswith(f"/Variant {vid}")
            assert q["value"] == v
            rel = key["tolerances"].get(a, key["tolerance"])
            assert q["tolerance"] == pytest.approx(rel * abs(v), rel=1e-12)   # absolute
            assert q["text"].startswith(f"[flywheel {vid} {a}]")
            assert q["multiplier"] == 1
    assert by["01 delta_T_max"]["unit"] == "J" and by["01 J_required"]["unit"] == "kg·m²"
    # the question's HTML sets a symbol's subscript as the task sheet does (not «ΔT_max»)
    assert "ΔT<sub>max</sub>" in by["01 delta_T_max"]["text"]
    assert "M<sub>D</sub>" in by["01 driving_moment"]["text"]


def responses_csv(path, key, attempts, qs):
    """A Responses report as Moodle downloads it, for attempts [(surname, first, vid, ans)],
    each attempt's slots in the key's answer order; a None value is no answer ("-")."""
    text = {q["name"]: q["text"] for q in qs}
    n = len(key["answers"])
    head = ["Surname", "First name", "Email address", "State", "Started on", "Completed",
            "Time taken", f"Grade/{n}.00"]
    for i in range(1, n + 1):
        head += [f"Question {i}", f"Response {i}"]
    rows = [head]
    for surname, first, vid, ans in attempts:
        row = [surname, first, "x@example.org", "Finished", "1 May 2026 10:00 AM",
               "1 May 2026 10:40 AM", "40 mins", "3.00"]
        for a in key["answers"]:
            v = ans[a]
            row += [text[f"{vid} {a}"], "-" if v is None else f"{v!r} J"]
        rows.append(row)
    rows.append(["Overall average", "", "", "", "", "", "", "3.00"] + [""] * (2 * n))
    with open(path, "w", newline="", encoding="utf-8-sig") as f:
        csv.writer(f).writerows(rows)
    return path


def test_a_moodle_responses_export_grades_as_the_native_sheet(made, tmp_path):
    key = key_of(made / "v")
    qs = questions(made / "quiz.xml")
    attempts = []
    for i, (vid, ans) in enumerate(key["variants"].items()):
        wrong = dict(ans, delta_T_max=ans["delta_T_max"] * 1.3)
        wrong.update(textbook(data_of(made / "v", vid), wrong["delta_T_max"]))
        if i == 1:
            wrong["J_flywheel"] = None
        if i == 2:
            wrong["J_required"] = ans["J_required"] * 2          # δ/2 for δ
        attempts.append((f"Фамилия{i}", "Имя", vid, wrong))
    moodle = responses_csv(tmp_path / "responses.csv", key, attempts, qs)
    native = tmp_path / "native.csv"
    with open(native, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", *key["answers"]])
        for s, first, vid, ans in attempts:
            w.writerow([f"{s} {first}", vid, *("" if ans[a] is None else repr(ans[a])
                                               for a in key["answers"])])

    def report(sheet):
        res = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(sheet),
                                  "--json", "--carried-forward", "0.5"])
        assert res.exit_code == 0, res.output
        doc = json.loads(res.stdout)
        for s in doc["students"]:
            del s["file"], s["row"]
        return doc["students"], doc["summary"]

    got, expected = report(moodle), report(native)
    assert got == expected
    assert [s["student"] for s in got[0]] == ["Фамилия0 Имя", "Фамилия1 Имя", "Фамилия2 Имя"]
    assert got[0][2]["answers"][2]["diagnosis"] == "half_delta"
    assert got[0][0]["carried_forward"] == 3


def test_an_export_without_the_questions_text_is_one_problem(made, tmp_path):
    path = tmp_path / "r.csv"
    path.write_text("Surname,First name,State,Response 1,Response 2\nA,B,Finished,1,2\n",
                    encoding="utf-8")
    res = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(path)])
    assert res.exit_code == 2 and "Traceback" not in res.output
    assert "without the questions' text" in res.output


def test_too_many_slots_are_refused(made, tmp_path):
    path = tmp_path / "r.csv"
    head = ["Surname", "First name"] + [f"Response {i}" for i in range(1, MAX_SLOTS + 2)]
    path.write_text(",".join(head) + "\nA,B\n", encoding="utf-8")
    res = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(path)])
    assert res.exit_code == 2 and f"at most {MAX_SLOTS}" in res.output


def test_moodle_inside_the_variants_folder_is_refused(tmp_path):
    res = runner.invoke(app, ["variants", "cases/variants_task2.toml", "--count", "2", "--seed",
                              "1", "--out", str(tmp_path / "v"), "--moodle",
                              str(tmp_path / "v" / "q.xml")])
    assert res.exit_code == 2 and "--moodle" in res.output and "Traceback" not in res.output
    assert not (tmp_path / "v").exists()


def test_each_question_shows_its_formula_after_the_attempt(made, tmp_path):
    """A question's general feedback (Moodle shows it once the attempt is over) is the course's
    formula the answer is computed by, where the chain has one (seed 000 §4): J_М = J_I −
    (J_10 + J_ред) for the flywheel's J, J = π·ρ·b·D⁴/32 for the disk's diameter. It had been
    empty."""
    qs = {q["name"].split()[1]: q for q in questions(made / "quiz.xml") if q["name"].startswith("01")}
    assert qs["J_flywheel"]["general"] == ("How it is computed: J<sub>M</sub> = J<sub>I</sub> − "
                                           "(J<sub>10</sub> + J<sub>red</sub>)")
    assert qs["J_required"]["general"].endswith("J<sub>I</sub> = ΔT<sub>max</sub>/(δ·ω<sub>m</sub>²)")
    assert qs["flywheel_disk.D"]["general"] == ("How it is computed: J = π·ρ·b·D⁴/32 of a solid "
                                                "disk, b = ψ·D, so D = ⁵√(32·J/(π·ρ·ψ))")
    res = runner.invoke(app, ["variants", "cases/variants_task2.toml", "--count", "1", "--seed",
                              "1", "--out", str(tmp_path / "v"), "--moodle",
                              str(tmp_path / "quiz.xml"), "--lang", "ru"])
    assert res.exit_code == 0, res.output
    qs = {q["name"].split()[1]: q for q in questions(tmp_path / "quiz.xml")}
    assert qs["omega_max"]["general"] == ("Как считается: ω<sub>max</sub> = √(ω₀² + "
                                          "2·A<sub>max</sub>/J<sub>пр</sub>)")
