"""Issue 28, Russian typography outside the записка: `check --lang ru`, the terminal lines of
`variants` and `grade` and the task sheets in Russian, the tick labels and the numbers of a
Russian figure, and the aggregate's notes — all through render/numbers.py's one formatter
(decimal comma, true minus U+2212, narrow spaces in long numbers, no exponent); English as it
was."""
from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.render.numbers import MINUS, THIN

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
#: a number in English notation: a decimal point between digits, or an exponent
ENGLISH_NUMBER = re.compile(r"\d\.\d|\d[eE][+-]?\d")


def _invoke(*args) -> str:
    res = runner.invoke(app, [str(a) for a in args], env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    return res.output


def test_check_in_russian_writes_russian_numbers():
    ru = _invoke("check", CASES / "compressor.toml", "--lang", "ru")
    assert not ENGLISH_NUMBER.search(ru), ENGLISH_NUMBER.search(ru)
    # ω_ср = 2π·n₁ with n₁ = 10 rev/s, a result: four significant digits
    assert f"ω_ср = {2 * math.pi * 10:.2f}".replace(".", ",") + " рад/с" in ru
    assert "δ = 0,05" in ru and "l = 0,1 м" in ru            # inputs: their own digits
    assert "через (0; 0)" in ru                             # a point: «;» between its numbers
    en = _invoke("check", CASES / "compressor.toml")
    assert "ω_m = 62.8319 rad/s" in en or "62.8319" in en   # English as it was: six digits


def test_variants_in_russian_write_russian_numbers(tmp_path):
    out = _invoke("variants", CASES / "variants_compressor.toml", "-n", "2", "--seed", "5",
                  "--out", tmp_path / "v", "--lang", "ru", "--sheets", "--sheets-format", "html")
    table = out.split("seed")[0]
    assert not ENGLISH_NUMBER.search(table), ENGLISH_NUMBER.search(table)
    assert re.search(r"цилиндре ВД p_max,ВД = 0,\d+ МПа", table)     # 840 000 Па: 0,84 МПа
    sheet = (tmp_path / "v" / "sheets" / "variant_01.html").read_text(encoding="utf-8")
    body = re.sub(r"<style.*?</style>", "", sheet, flags=re.S)
    text = re.sub(r"<[^>]+>", " ", body)
    assert f"0; {MINUS}9,81" in text                      # g = (0, −9.81) m/s²
    assert not ENGLISH_NUMBER.search(text), ENGLISH_NUMBER.search(text)


def test_grade_in_russian_writes_russian_numbers(tmp_path):
    _invoke("variants", CASES / "variants_task2.toml", "-n", "2", "--seed", "5", "--out",
            tmp_path / "v")
    import json

    key = json.loads((tmp_path / "v" / "answers.json").read_text())
    names = list(key["answers"])
    rows = ["student,variant," + ",".join(names)]
    for i, (vid, ans) in enumerate(key["variants"].items()):
        vals = [repr(ans[a] * (1.5 if i == 1 and k == 0 else 1.0)) for k, a in enumerate(names)]
        rows.append(f"s{i},{vid}," + ",".join(vals))
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("\n".join(rows) + "\n", encoding="utf-8")
    ru = _invoke("grade", tmp_path / "v" / "answers.json", sheet, "--lang", "ru")
    assert not ENGLISH_NUMBER.search(ru), ENGLISH_NUMBER.search(ru)
    assert "50 %" in ru                                    # the wrong answer: 1.5 × the key


def test_a_note_of_the_aggregate_has_no_exponent():
    """The note that printed «1.456e+04 periods» (a stiff coupling) in Russian."""
    from flywheel.render import nomenclature as nm
    from flywheel.render.numbers import typography

    fields = dict(fast=14556.3, f_top=29265.2, limit=500)
    with typography("ru"):
        ru = nm.name("note_radau", "ru", **fields)
    assert f"14{THIN}556 периодов" in ru and f"29{THIN}265 Гц" in ru and "e+" not in ru
    assert "1.456e+04 periods" in nm.name("note_radau", "en", **fields)   # English as it was


# -- figures ------------------------------------------------------------------------------------
@pytest.mark.parametrize("locs, decimals", [
    ([0, 30, 60, 90], 0), ([0.0, 0.25, 0.5], 2), ([-0.8, -0.6, -0.4], 1), ([5.0], None),
    ([0.03, 0.032, 0.034], 3), ([-10000, -8000, -6000], 0),
])
def test_tick_decimals_tell_the_ticks_apart(locs, decimals):
    from flywheel.render.figure import _tick_decimals

    assert _tick_decimals(locs) == decimals


def _tick_texts(lang: str):
    from flywheel.render import figure as fg

    with fg.style(lang):
        fig, ax = fg.figure((6.0, 4.0), right=0.3)
        ax.plot([0.0, 1.0], [-12000.0, 0.75])
        fig.canvas.draw()
        return ([t.get_text() for t in ax.get_yticklabels()],
                [t.get_text() for t in ax.get_xticklabels()], type(ax.yaxis.get_major_formatter()))


def test_a_russian_figure_ticks_in_russian_typography():
    ys, xs, kind = _tick_texts("ru")
    assert kind.__name__ == "FuncFormatter"
    assert any(t.startswith(MINUS) and THIN in t for t in ys), ys        # −12 000
    assert any("," in t for t in xs) and not any("." in t for t in xs + ys), (xs, ys)
    values = [float(t.replace(MINUS, "-").replace(THIN, "").replace(",", ".")) for t in xs]
    assert values == sorted(values) and len(set(values)) == len(values)   # told apart


def test_an_english_figure_keeps_matplotlibs_ticks():
    ys, xs, kind = _tick_texts("en")
    assert kind.__name__ == "ScalarFormatter"
    assert any("." in t for t in xs)
    from flywheel.render import figure as fg

    with fg.style("ru"):                                    # undone after the block
        pass
    with fg.style():
        fig, ax = fg.figure((6.0, 4.0), right=0.3)
        assert type(ax.yaxis.get_major_formatter()).__name__ == "ScalarFormatter"
