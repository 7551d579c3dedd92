"""Issue 27, step 4: answers that are tables, graded cell by cell. The key's cells are checked
against `flywheel run`'s own positions.csv and summary.json of the variant file and against
the slider-crank's textbook velocity analogue; a sheet with one cell changed is graded with
exactly that cell off; a sheet with every cell right earns full credit; a cell changed by a
classic mistake (rev/min for rad/s in T_II, ΔT_I built with −M) is named."""
import csv
import json
import math
import xml.etree.ElementTree as ET

import pytest

from chain_helpers import CASES, data_of, key_of, runner
from flywheel.cli import app

TABLES = '\ntables = ["analogues", "delta_T", "reactions"]\n'


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    base = tmp_path_factory.mktemp("tables")
    text = (CASES / "variants_compressor.toml").read_text(encoding="utf-8")
    template = base / "with_tables.toml"
    template.write_text(text.replace("\nanswers ", TABLES + "answers ", 1), encoding="utf-8")
    res = runner.invoke(app, ["variants", str(template), "--count", "2", "--seed", "7",
                              "--out", str(base / "v"), "--moodle", str(base / "quiz.xml"),
                              "--sheets", "--sheets-format", "html", "--lang", "ru"])
    assert res.exit_code == 0, res.output
    return base


def write(path, key, rows):
    names = list(next(iter(key["variants"].values())))
    with open(path, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(["student", "variant", *names])
        for name, vid, ans in rows:
            w.writerow([name, vid, *(repr(ans[a]) for a in names)])
    return path


def grade(made, sheet, *options):
    res = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(sheet), "--json",
                              *options])
    assert res.exit_code == 0, res.output
    return {s["student"]: s for s in json.loads(res.stdout)["students"]}


def test_the_cells_are_what_flywheel_run_writes(made, tmp_path):
    key = key_of(made / "v")
    t = key["tables"]
    assert list(t) == ["analogues", "delta_T", "reactions"]
    assert t["analogues"]["rows"] == [str(k) for k in range(12)]
    assert t["delta_T"]["columns"] == ["A", "T_II", "dT_I"]
    out = tmp_path / "run"
    res = runner.invoke(app, ["run", str(made / "v" / "variant_01.toml"), "--points", "1440",
                              "--no-plots", "--out", str(out)])
    assert res.exit_code == 0, res.output
    with open(out / "positions.csv", encoding="utf-8") as f:
        positions = {r["number"]: r for r in csv.DictReader(f) if r["number"]}
    cells = key["variants"]["01"]
    for name in ("analogues", "delta_T"):
        for r in t[name]["rows"]:
            for c, u in zip(t[name]["columns"], t[name]["units"]):
                head = next(h for h in positions[r] if h.split(" [")[0] == c)
                assert cells[f"{name}.{r}.{c}"] == pytest.approx(float(positions[r][head]),
                                                                 rel=1e-10, abs=1e-12)
    joints = json.loads((out / "summary.json").read_text(encoding="utf-8"))["results"]["at"][0]
    for r in t["reactions"]["rows"]:
        j = joints["joints"][r]
        for c, attr in (("Rx", "Fx"), ("Ry", "Fy"), ("R", "F")):
            assert cells[f"reactions.{r}.{c}"] == pytest.approx(j[attr], rel=1e-9)


def test_the_slider_analogue_is_the_textbooks(made):
    """Piston 3 on the vertical through O, the crank from the upward vertical: |v_qB| =
    r·|sin φ|·(1 + r·cos φ/√(l² − r²·sin² φ)), r = V_ср/(4·n1), l = k·r."""
    key = key_of(made / "v")
    for vid, cells in key["variants"].items():
        d = data_of(made / "v", vid)
        r = d["design"]["mean_piston_speed"] / (4 * d["machine"]["speed_rps"])
        ell = d["design"]["rod_to_crank"] * r
        for k in range(12):
            phi = math.radians(30 * k)
            s = math.sin(phi)
            vq = r * abs(s) * (1 + r * math.cos(phi) / math.sqrt(ell ** 2 - (r * s) ** 2))
            assert cells[f"analogues.{k}.vq_B"] == pytest.approx(vq, rel=1e-9, abs=1e-12)


def test_all_cells_right_earn_full_credit_and_one_cell_changed_is_exactly_that_cell(made,
                                                                                    tmp_path):
    key = key_of(made / "v")
    rows = []
    for vid, ans in key["variants"].items():
        rows.append((f"right{vid}", vid, ans))
        one = dict(ans)
        one["analogues.7.vq_C"] *= 1.05
        rows.append((f"one{vid}", vid, one))
        reaction = dict(ans)
        reaction["reactions.A:1->2.R"] *= 0.9
        rows.append((f"pair{vid}", vid, reaction))
    got = grade(made, write(tmp_path / "s.csv", key, rows))
    n_cells = {name: len(t["rows"]) * len(t["columns"]) for name, t in key["tables"].items()}
    total = len(key["answers"]) + len(key["tables"])
    for vid in key["variants"]:
        right = got[f"right{vid}"]
        assert right["score"] == 1.0 and right["passed"] == right["total"] == total
        assert all(t["right"] == t["cells"] and not t["off"] for t in right["tables"])
        one = got[f"one{vid}"]
        assert [a["answer"] for a in one["answers"] if not a["pass"]] == ["analogues.7.vq_C"]
        tables = {t["table"]: t for t in one["tables"]}
        assert tables["analogues"]["off"] == [{"column": "vq_C", "rows": ["7"]}]
        assert tables["analogues"]["right"] == n_cells["analogues"] - 1
        assert one["wrong"] == ["analogues"]
        assert one["score"] == pytest.approx((total - 1 + (n_cells["analogues"] - 1)
                                              / n_cells["analogues"]) / total)
        pair = got[f"pair{vid}"]
        assert {t["table"]: t["off"] for t in pair["tables"]}["reactions"] == [
            {"column": "R", "rows": ["A:1->2"]}]


def test_a_cell_near_zero_is_judged_against_its_column(made, tmp_path):
    """At the dead centre (position 0) B's analogue is 0 (round-off): 0 and 1e-6 m/rad pass,
    a tenth of the column's largest value fails."""
    key = key_of(made / "v")
    vid, ans = next(iter(key["variants"].items()))
    top = max(abs(ans[f"analogues.{k}.vq_B"]) for k in range(12))
    assert abs(ans["analogues.0.vq_B"]) < 1e-9 * top
    rows = [(f"z{i}", vid, dict(ans, **{"analogues.0.vq_B": x}))
            for i, x in enumerate((0.0, 1e-6, 0.1 * top))]
    got = grade(made, write(tmp_path / "z.csv", key, rows))
    assert [got[f"z{i}"]["tables"][0]["right"] for i in range(3)] == [72, 72, 71]


def test_classic_mistakes_in_cells_are_named(made, tmp_path):
    """T_II with n = ω·30/π in rev/min; ΔT_I = A − (T_II − T_II(0)) with the constant
    driving moment's sign lost: A_known − M·φ instead of A_known + M·φ."""
    key = key_of(made / "v")
    vid, ans = next(iter(key["variants"].items()))
    wrong = dict(ans)
    wrong["delta_T.4.T_II"] = ans["delta_T.4.T_II"] * (30 / math.pi) ** 2
    M = ans["driving_moment"]           # the compressor's balance finds the driving moment
    wrong["delta_T.5.dT_I"] = ans["delta_T.5.dT_I"] - 2 * M * math.radians(150)
    got = grade(made, write(tmp_path / "m.csv", key, [("m", vid, wrong)]), "--gradebook",
                str(tmp_path / "book.csv"))
    named = {a["answer"]: a["diagnosis"] for a in got["m"]["answers"] if a["diagnosis"]}
    assert named == {"delta_T.4.T_II": "rpm_for_rad_s", "delta_T.5.dT_I": "sign_lost"}
    with open(tmp_path / "book.csv", encoding="utf-8") as f:
        book = list(csv.DictReader(f))
    assert "delta_T: row 4: T_II off; row 5: dT_I off" in book[0]["diagnosis"]
    assert book[0]["delta_T verdict"] == "34/36 cells"


def test_the_sheet_and_the_moodle_bank_carry_the_cells(made, tmp_path):
    key = key_of(made / "v")
    page = (made / "v" / "sheets" / "variant_01.html").read_text(encoding="utf-8")
    assert "Аналоги скоростей в положениях механизма" in page
    assert "Реакции в кинематических парах при φ = 120°" in page
    assert "O (0→1)" in page and "_" not in page.split("<body", 1)[1].split("Задание")[1]
    # the cells to fill in are blank: not the dash of a record's cell without data
    to_fill = page.split("Задание", 1)[1]
    assert "<td>\u00a0" in to_fill.replace("&nbsp;", "\u00a0") and "<td>—</td>" not in to_fill
    names = list(key["variants"]["01"])
    assert str(key["variants"]["01"]["analogues.3.vq_B"]) not in page
    root = ET.parse(made / "quiz.xml").getroot()
    qs = [q for q in root if q.get("type") == "numerical"]
    assert len(qs) == len(key["variants"]) * len(names)
    by = {q.find("name/text").text: q for q in qs}
    q = by["01 analogues.0.vq_B"]
    assert q.find("questiontext/text").text.startswith("[flywheel 01 analogues.0.vq_B]")
    # a cell at zero: Moodle's absolute tolerance is the column's scale times the tolerance
    top = max(abs(key["variants"]["01"][f"analogues.{k}.vq_B"]) for k in range(12))
    assert float(q.find("answer/tolerance").text) == pytest.approx(0.01 * 0.01 * top)


def test_no_tables_no_change_and_a_bad_list_is_one_line(made, tmp_path):
    plain = tmp_path / "p"
    res = runner.invoke(app, ["variants", str(CASES / "variants_shaper.toml"), "--count", "1",
                              "--seed", "3", "--out", str(plain)])
    assert res.exit_code == 0
    assert "tables" not in key_of(plain)
    text = (made / "with_tables.toml").read_text(encoding="utf-8")
    for bad, words in (('["analogues", "nope"]', "'nope' is not a table"),
                       ('"analogues"', "must be an array of table names"),
                       ('["delta_T", "delta_T"]', "listed twice")):
        t = tmp_path / "bad.toml"
        t.write_text(text.replace(TABLES.strip().split(" = ")[1], bad, 1), encoding="utf-8")
        res = runner.invoke(app, ["variants", str(t), "--count", "1", "--out",
                                  str(tmp_path / "o")])
        assert res.exit_code == 2 and words in res.output, res.output
        assert len(res.output.strip().splitlines()) == 1


def test_the_russian_report_names_tables_rows_and_columns_as_the_sheet_does(made, tmp_path):
    """`grade --lang ru` lists a table by its Russian name and a cell by its column's symbol
    and its row as the task sheet prints them (a position's number, a pair «A (1→2)»): the
    report had printed the keys («delta_T.4.T_II», «строка A:1->2: R неверно»). The
    gradebook's diagnosis and the feedback page say the rows so too; English keeps the keys
    but prints a pair as the sheet does."""
    key = key_of(made / "v")
    vid, ans = next(iter(key["variants"].items()))
    wrong = dict(ans)
    wrong["delta_T.4.T_II"] = ans["delta_T.4.T_II"] * (30 / math.pi) ** 2   # a named mistake
    wrong["analogues.3.vq_B"] *= 1.3
    wrong["analogues.7.vq_B"] *= 1.3
    wrong["reactions.A:1->2.R"] *= 0.9
    sheet = write(tmp_path / "s.csv", key, [("m", vid, wrong)])
    res = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(sheet),
                              "--lang", "ru", "--gradebook", str(tmp_path / "book.csv"),
                              "--feedback", str(tmp_path / "fb")], env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    out = res.stdout
    assert "T_II, положение 4" in out and "delta_T.4.T_II" not in out
    assert "положения 3, 7: v_q(B) неверно" in out
    assert "пара A (1→2): R неверно" in out
    assert "аналоги скоростей" in out and "реакции в парах" in out
    assert "analogues" not in out and "A:1->2" not in out and "строк" not in out
    with open(tmp_path / "book.csv", encoding="utf-8") as f:
        book = next(csv.DictReader(f))
    assert "delta_T: положение 4: T_II неверно" in book["диагностика"]
    page = next((tmp_path / "fb").iterdir()).read_text(encoding="utf-8")
    assert "пара A (1→2): R неверно" in page
    assert "реакцию в кинематической паре A (1→2): модуль" in page   # the object of «Определить»
    english = runner.invoke(app, ["grade", str(made / "v" / "answers.json"), str(sheet)],
                            env={"COLUMNS": "200"})
    assert "rows 3, 7: vq_B off" in english.stdout and "pair A (1→2): R off" in english.stdout
