"""`--csv excel-ru` (`flywheel run`, and `flywheel grade`'s --out and --gradebook): ';'
separators, decimal commas and a UTF-8 BOM for a Russian Excel; read back with the csv module,
every file holds the same cells as the default (plain) CSV — text equal, numbers equal."""
import csv
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render.csvfmt import restyle

CASES = Path(__file__).resolve().parents[2] / "cases"
RUN_CSV = ("table.csv", "positions.csv", "forces.csv", "forces_positions.csv")
runner = CliRunner()


def read_plain(path: Path) -> list[list[str]]:
    raw = path.read_bytes()
    assert not raw.startswith(b"\xef\xbb\xbf")                   # the default has no BOM
    return list(csv.reader(raw.decode("utf-8").splitlines()))


def read_excel_ru(path: Path) -> list[list[str]]:
    raw = path.read_bytes()
    assert raw.startswith(b"\xef\xbb\xbf")                       # UTF-8 BOM
    assert b"\r\n" in raw                                        # Excel's line ends
    return list(csv.reader(raw.decode("utf-8-sig").splitlines(), delimiter=";"))


def same_cells(plain: list[list[str]], ru: list[list[str]]) -> int:
    """Assert the two readings hold the same cells: a number of the plain file is the same
    number with a decimal comma (never a point) in the excel-ru one; any other cell is equal.
    The count of numbers compared."""
    assert len(plain) == len(ru)
    numbers = 0
    for a, b in zip(plain, ru):
        assert len(a) == len(b), (a, b)
        for x, y in zip(a, b):
            try:
                value = float(x)
            except ValueError:
                assert y == x
                continue
            if not re.search(r"\d", x):                           # "nan", "inf" as text
                assert y == x
                continue
            assert "." not in y, y
            assert float(y.replace(",", ".")) == value, (x, y)
            numbers += 1
    return numbers


@pytest.fixture(scope="module")
def run_dirs(tmp_path_factory):
    base = tmp_path_factory.mktemp("csv")
    out = {}
    for style in ("plain", "excel-ru"):
        out[style] = base / style
        res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots",
                                  "--points", "360", "--csv", style, "--out", str(out[style])])
        assert res.exit_code == 0, res.output
    return out


@pytest.mark.parametrize("name", RUN_CSV)
def test_run_excel_ru_reads_back_to_the_same_numbers(run_dirs, name):
    plain = read_plain(run_dirs["plain"] / name)
    ru = read_excel_ru(run_dirs["excel-ru"] / name)
    n = same_cells(plain, ru)
    assert n >= len(plain) - 1                                    # a row of numbers at least
    assert any("," in c for row in ru[1:] for c in row)           # decimal commas are there


def test_run_default_is_plain_and_unchanged(run_dirs, tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "compressor.toml"), "--no-plots",
                              "--points", "360", "--out", str(tmp_path / "d")])
    assert res.exit_code == 0, res.output
    for name in RUN_CSV:
        assert (tmp_path / "d" / name).read_bytes() == (run_dirs["plain"] / name).read_bytes()


def test_restyle_changes_separators_and_decimal_marks_only():
    text = "position,x [m],n\n0° = 3 outer d.c.,-1.5e-05,12\n30°,0.25,nan\n"
    assert restyle(text, "plain") == text
    out = restyle(text, "excel-ru")
    assert out == ("\ufeffposition;x [m];n\r\n0° = 3 outer d.c.;-1,5e-05;12\r\n"
                   "30°;0,25;nan\r\n")
    with pytest.raises(ValueError):
        restyle(text, "excel")


def test_grade_outputs_excel_ru_read_back_to_the_same_numbers(tmp_path):
    import json

    from teaching.test_grading import sheet  # the test-side answer sheet writer (tests/teaching)

    key_dir = tmp_path / "v"
    res = runner.invoke(app, ["variants", str(CASES / "variants_task2.toml"), "--count", "4",
                              "--seed", "9", "--out", str(key_dir)])
    assert res.exit_code == 0, res.output
    key = json.loads((key_dir / "answers.json").read_text())
    first = key["answers"][0]
    answers = sheet(tmp_path / "a.csv", key,
                    change=lambda i, a: a.update({first: a[first] * (1 + 0.1 * i)}))
    files = {}
    for style in ("plain", "excel-ru"):
        out, book = tmp_path / f"out-{style}.csv", tmp_path / f"book-{style}.csv"
        res = runner.invoke(app, ["grade", str(key_dir / "answers.json"), str(answers),
                                  "--out", str(out), "--gradebook", str(book), "--csv", style])
        assert res.exit_code == 0, res.output
        files[style] = (out, book)
    for plain_file, ru_file in zip(files["plain"], files["excel-ru"]):
        n = same_cells(read_plain(plain_file), read_excel_ru(ru_file))
        assert n >= 4
