"""`flywheel grade` never writes over its inputs, refuses absurd options and keys in one line,
and refuses a sheet whose encoding cannot be trusted (issue 23, items 2, 4 and 6)."""
import json
import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.errors import CaseFileError
from flywheel.io.jsonfile import json_depth
from flywheel.teaching.grading import MAX_KEY_DEPTH, load_key
from helpers import err_text

runner = CliRunner()
KEY = '{"variants": {"01": {"M_C": 150.0, "J_required": 30.2}}}\n'
SHEET = "student,variant,M_C,J_required\nIvanov,01,150,30.2\n"


def one_line_error(res, *fragments):
    assert res.exit_code == 2, res.output
    assert "Traceback" not in res.output
    lines = [ln for ln in err_text(res).splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    for f in fragments:
        assert f in lines[0], lines[0]
    return lines[0]


@pytest.fixture
def class_dir(tmp_path):
    (tmp_path / "k.json").write_text(KEY)
    (tmp_path / "s.csv").write_text(SHEET)
    return tmp_path


def _contents(folder: Path) -> dict:
    return {p.name: p.read_bytes() for p in folder.rglob("*") if p.is_file()}


# -- outputs over inputs ------------------------------------------------------------------------

@pytest.mark.parametrize("option", ["--out", "--gradebook"])
def test_an_output_naming_the_sheet_or_the_key_is_refused_and_nothing_changes(class_dir, option):
    before = _contents(class_dir)
    for target, what in (("s.csv", "the answer sheet"), ("k.json", "the answer key")):
        res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv"),
                                  option, str(class_dir / target)])
        one_line_error(res, option, str(class_dir / target), what, "never writes over")
    assert _contents(class_dir) == before


def test_out_and_gradebook_naming_one_file_are_refused(class_dir):
    (class_dir / "sub").mkdir()
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv"),
                              "--out", str(class_dir / "o.csv"), "--gradebook",
                              str(class_dir / "sub" / ".." / "o.csv")])
    one_line_error(res, "--out", "--gradebook", "the same file")
    assert not (class_dir / "o.csv").exists()


def test_other_spellings_of_an_input_are_refused(class_dir, monkeypatch):
    """./x and x, a symbolic link, a hard link, a sheet found in a folder of sheets."""
    os.symlink(class_dir / "s.csv", class_dir / "link.csv")
    os.link(class_dir / "s.csv", class_dir / "hard.csv")
    (class_dir / "sub").mkdir()
    monkeypatch.chdir(class_dir)
    before = _contents(class_dir)
    for given, out in ((["s.csv"], "./s.csv"), (["s.csv"], "link.csv"),
                       (["s.csv"], "hard.csv"), (["."], "s.csv"), (["link.csv"], "s.csv"),
                       (["s.csv"], "sub/../k.json")):
        res = runner.invoke(app, ["grade", "k.json", *given, "--out", out])
        one_line_error(res, "--out", "never writes over")
    res = runner.invoke(app, ["grade", "k.json", "s.csv", "--out", "hard.csv",
                              "--gradebook", "link.csv"])
    one_line_error(res, "never writes over")
    assert _contents(class_dir) == before


def test_an_output_beside_the_inputs_is_written(class_dir):
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir),
                              "--out", str(class_dir / "report.txt"),
                              "--gradebook", str(class_dir / "book.txt")])
    assert res.exit_code == 0, res.output
    assert (class_dir / "report.txt").read_text().startswith("student,variant,file,row")
    assert (class_dir / "s.csv").read_text() == SHEET


# -- options --------------------------------------------------------------------------------------

@pytest.mark.parametrize("tol", ["1e308", "1.5", "100"])
def test_tolerance_above_one_is_refused(class_dir, tol):
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv"),
                              "--tolerance", tol])
    one_line_error(res, "--tolerance", "too large", "0 < tolerance ≤ 1")


def test_tolerance_of_one_is_allowed(class_dir):
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv"),
                              "--tolerance", "1", "--json"])
    assert res.exit_code == 0, res.output
    assert json.loads(res.stdout)["tolerance"] == 1.0


def test_sheets_format_without_sheets_is_refused_before_any_work(tmp_path):
    res = runner.invoke(app, ["variants", str(tmp_path / "no_such_template.toml"), "-n", "2",
                              "--out", str(tmp_path / "v"), "--sheets-format", "pdf"])
    one_line_error(res, "--sheets-format pdf", "without --sheets")
    assert list(tmp_path.iterdir()) == []


# -- the key --------------------------------------------------------------------------------------

def test_json_depth_counts_brackets_outside_strings():
    assert json_depth('{"a": "[[[[{{{{", "b": [1, [2, {"c": "\\"]]"}]]}') == 4
    assert json_depth('[' * 5000 + ']' * 5000) == 5000      # no recursion


@pytest.mark.parametrize("text, fragments", [
    ("[" * 2000 + "]" * 2000, ["nested too deep", "2000 levels", f"up to {MAX_KEY_DEPTH}"]),
    ('{"variants": ' + '{"a": ' * 100 + "1" + "}" * 100 + "}",
     ["nested too deep", "101 levels"]),
    ('{"variants": {"01": {"M_C": ' + "7" * 5000 + "}}}", ["5000 digits", "too long"]),
    ('{"variants": {"01": {"M_C": -' + "7" * 401 + "}}}", ["401 digits", "too long"]),
])
def test_a_key_nested_too_deep_or_with_a_long_number_is_one_line(class_dir, text, fragments):
    (class_dir / "k.json").write_text(text)
    with pytest.raises(CaseFileError) as e:
        load_key(class_dir / "k.json")
    for f in [str(class_dir / "k.json"), *fragments]:
        assert f in str(e.value)
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv")])
    one_line_error(res, str(class_dir / "k.json"), *fragments)


def test_an_integer_too_large_for_a_float_is_not_finite(class_dir):
    (class_dir / "k.json").write_text('{"variants": {"01": {"M_C": 1' + "0" * 399 + "}}}")
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv")])
    one_line_error(res, "variants.01.M_C", "finite number")


def test_a_key_of_ordinary_depth_and_long_floats_still_reads(class_dir):
    (class_dir / "k.json").write_text('{"variants": {"01": {"M_C": 150.' + "0" * 600
                                      + ', "J_required": 30.2}}, "note": [[[[1]]]]}')
    k = load_key(class_dir / "k.json")
    assert k.variants["01"] == {"M_C": 150.0, "J_required": 30.2}


# -- sheets whose encoding cannot be trusted ------------------------------------------------------

RUSSIAN = ["Иванов Пётр", "Сидорова Анна", "Шевченко Тарас", "Щукина Эльвира", "Ёлкин Юрий",
           "Кузнецов Дмитрий", "Смирнова Ольга", "Шаров Михаил"]
HEADER_RU = "student,variant,группа,M_C,J_required\n"


def _russian_sheet(rows: int = 8) -> str:
    return HEADER_RU + "".join(f"{RUSSIAN[i % len(RUSSIAN)]},01,ТММ-21,150,30.2\n"
                               for i in range(rows))


def _graded_names(res) -> list[str]:
    return [s["student"] for s in json.loads(res.stdout)["students"]]


@pytest.mark.parametrize("encoding", ["cp1251", "cp866", "koi8_r"])
def test_russian_sheets_in_their_encodings_still_read_right(class_dir, encoding):
    """cp866 has «Ш» at 0x98, the byte Windows-1251 leaves undefined: still cp866."""
    data = _russian_sheet().encode(encoding)
    assert encoding != "cp866" or b"\x98" in data
    (class_dir / "s.csv").write_bytes(data)
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "s.csv"),
                              "--json"])
    assert res.exit_code == 0, res.output
    assert _graded_names(res) == RUSSIAN
    problems = json.loads(res.stdout)["problems"]
    assert [p["message"] for p in problems] == [
        "column(s) 'группа' are not answers of the key (ignored; answers: M_C, J_required)"]


@pytest.mark.parametrize("rows, stray_in", [(1, 0), (2, 1), (8, 0), (8, 7)])
def test_a_cp1251_sheet_with_a_stray_byte_is_refused_and_the_batch_goes_on(class_dir, rows,
                                                                           stray_in):
    """0x98 is no Windows-1251 character: charset-normalizer read such a sheet of one or two
    rows as cp866 (garbled names, graded as if fine) and one of eight as binary data."""
    data = _russian_sheet(rows).encode("cp1251")
    cut = data.index(RUSSIAN[stray_in].encode("cp1251")) + 3
    (class_dir / "bad.csv").write_bytes(data[:cut] + b"\x98" + data[cut:])
    (class_dir / "good.csv").write_bytes(_russian_sheet().encode("cp1251"))
    res = runner.invoke(app, ["grade", str(class_dir / "k.json"), str(class_dir / "bad.csv"),
                              str(class_dir / "good.csv"), "--json"])
    assert res.exit_code == 0, res.output
    report = json.loads(res.stdout)
    assert _graded_names(res) == RUSSIAN                # good.csv only
    bad = [p for p in report["problems"] if p["file"] == str(class_dir / "bad.csv")]
    assert len(bad) == 1 and bad[0]["row"] is None, bad
    assert f"stray byte 0x98 at byte {cut}" in bad[0]["message"], bad


def test_the_stray_byte_message_names_the_byte_and_its_place(class_dir):
    from flywheel.teaching.grading import SheetError, sheet_codec

    data = ("student,variant,M_C,J_required\n" + "".join(
        f"{n},01,150,30.2\n" for n in ("Кузнецов Юрий", "Шаров Тарас"))).encode("cp1251")
    at = data.index("Шаров".encode("cp1251"))
    with pytest.raises(SheetError) as e:
        sheet_codec(data[:at] + b"\x98" + data[at:])
    assert f"stray byte 0x98 at byte {at}" in str(e.value)
    assert "Windows-1251" in str(e.value)


def test_a_guess_the_rest_of_the_sheet_does_not_decode_in_is_refused(class_dir, monkeypatch):
    """The encoding is guessed from the sheet's start; a byte later on that the guess cannot
    decode refuses that sheet (naming the byte), the other sheets are graded."""
    from flywheel.teaching import grading, sheet_text

    monkeypatch.setattr(sheet_text, "DETECT_BYTES", 400)
    monkeypatch.setattr(sheet_text, "READ_BYTES", 64)
    data = _russian_sheet(40).encode("cp1251")
    at = len(data) - 20
    (class_dir / "bad.csv").write_bytes(data[:at] + b"\x98" + data[at:])
    report = grading.grade(load_key(class_dir / "k.json"),
                           [class_dir / "bad.csv", class_dir / "s.csv"])
    assert [s.student for s in report.students] == ["Ivanov"]
    (p,) = [p for p in report.problems if p.file.endswith("bad.csv")]
    assert p.row is None and f"not cp1251 text at byte {at}" in p.message


# -- bounded memory: the structure (the figures are benchmarks/bench_grade_memory.py's) -----------

def test_a_sheet_is_read_in_bounded_pieces_and_past_rows_are_not_kept(class_dir, monkeypatch):
    from flywheel.teaching import grading, sheet_text

    sizes = []
    real_open = open

    class Spy:
        def __init__(self, f):
            self.f = f

        def __enter__(self):
            return self

        def __exit__(self, *exc):
            self.f.close()

        def read(self, n=-1):
            sizes.append(n)
            return self.f.read(n)

    monkeypatch.setattr(sheet_text, "open", lambda *a, **k: Spy(real_open(*a, **k)),
                        raising=False)
    monkeypatch.setattr(sheet_text, "READ_BYTES", 256)
    text = "student,variant,M_C,J_required\n" + "".join(
        f"s{i},01,150,30.2\n" for i in range(200)) + "late,99,1,2\n"
    (class_dir / "s.csv").write_text(text)
    graded, problems, over, first = grading._grade_sheet(load_key(class_dir / "k.json"),
                                                         class_dir / "s.csv", None, 50)
    assert sizes and all(0 < n <= 256 for n in sizes)   # never the whole file at once
    assert [s.student for s in graded] == [f"s{i}" for i in range(50)]
    assert over == 150 and first == 52                  # counted, not kept
    assert [p.row for p in problems] == [202]           # rows past the limit still checked
    assert not hasattr(graded[0], "__dict__")           # a slotted record per row


def test_the_json_report_in_pieces_is_json_dumps_of_the_whole(class_dir):
    from flywheel.teaching.grading import grade, report_dict, report_json

    (class_dir / "s.csv").write_text(SHEET + "Petrov,01,151,\nSidorov,02,1,2\n,01,1,2\n")
    for paths in ([class_dir / "s.csv"], [class_dir / "none.csv"]):
        r = grade(load_key(class_dir / "k.json"), paths)
        pieces = list(report_json(r))
        assert "".join(pieces) == json.dumps(report_dict(r), indent=2,
                                             ensure_ascii=False) + "\n"
    assert len(pieces) > 3


def test_problems_past_the_run_limit_are_counted_not_kept(class_dir, monkeypatch):
    """A sheet graded against another class's key: every row a problem."""
    from flywheel.teaching import grading, sheet_text

    monkeypatch.setattr(grading, "MAX_PROBLEMS", 5)
    (class_dir / "wrong.csv").write_text("student,variant,M_C,J_required\n" + "".join(
        f"s{i},07,1,2\n" for i in range(12)))
    r = grading.grade(load_key(class_dir / "k.json"), [class_dir / "wrong.csv",
                                                      class_dir / "s.csv"])
    assert [s.student for s in r.students] == ["Ivanov"]
    assert [p.row for p in r.problems[:5]] == [2, 3, 4, 5, 6]
    assert len(r.problems) == 6 and "7 more problem(s)" in r.problems[5].message
