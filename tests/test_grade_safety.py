"""`flywheel grade` never writes over its inputs, refuses absurd options and keys in one line,
and refuses a sheet whose encoding cannot be trusted (issue 23, items 2, 4 and 6)."""
import json
import os
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.errors import CaseFileError
from flywheel.teaching.grading import MAX_KEY_DEPTH, json_depth, load_key
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
