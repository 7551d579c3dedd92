"""Russian warnings and messages (errors.Notice, render/nomenclature.py MESSAGES_RU): every
Notice the code makes has a Russian template whose fields it gives; with --lang ru the CLI's
"warning:", "note:" and "written:" lines are Russian; in English a Notice is its text."""
from __future__ import annotations

import ast
import pickle
import re
import string
from pathlib import Path

from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.errors import Notice
from flywheel.render import nomenclature as nm

SRC = Path(__file__).resolve().parents[1] / "src" / "flywheel"
CASES = Path(__file__).resolve().parents[1] / "cases"
runner = CliRunner()
# fields a template may take that render/nomenclature.py derives from the Notice's own
DERIVED = {"target", "shape_ru", "material_ru", "files_ru"}


def _notices():
    """(file, code, keyword names) of every Notice(…) call in the package."""
    for path in SRC.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Notice"
                    and len(node.args) >= 2):
                yield path.name, node.args[1].value, {k.arg for k in node.keywords}


def test_every_notice_has_a_russian_template_with_its_fields():
    found = list(_notices())
    assert len(found) >= 15
    for file, code, keys in found:
        assert code in nm.MESSAGES_RU, (file, code)
        fields = {f for _, f, _, _ in string.Formatter().parse(nm.MESSAGES_RU[code]) if f}
        assert fields <= keys | DERIVED, (file, code, fields - keys)
    assert {c for _, c, _ in found} == set(nm.MESSAGES_RU)


def test_a_notice_is_its_english_text_and_survives_pickling():
    w = Notice("δ = 0.5: the speed swings by more than 30 % of the mean", "duty_delta_large",
               delta=0.5)
    assert w == "δ = 0.5: the speed swings by more than 30 % of the mean"
    assert nm.message(w) == str(w) and nm.message("plain text", "ru") == "plain text"
    back = pickle.loads(pickle.dumps(w))
    assert back == w and back.code == w.code and back.params == w.params
    assert nm.message(back, "ru") == "δ = 0.5: скорость колеблется больше чем на 30 % от средней"


def _no_english(line: str) -> bool:
    """No English word of three letters or more outside names the user gave ('pchip', field
    paths, the interpolation kind)."""
    allowed = {"pchip", "natural", "spline", "machine", "delta", "crank", "length", "flywheel",
               "allowable_stress", "width_ratio", "LP", "HP"}
    line = re.sub(r"\S+\.(csv|json|md|html|png|edited)\b", "", line)    # file names
    words = re.findall(r"[A-Za-z_]{3,}", line)
    return all(w in allowed or w.split("_")[0] in allowed for w in words)


def test_run_warnings_and_notes_are_russian(tmp_path):
    out = tmp_path / "o"
    args = ["run", str(CASES / "compressor.toml"), "--points", "360", "--no-plots", "--out", str(out)]
    en = runner.invoke(app, args)
    assert en.exit_code == 0
    assert "warning: cylinder LP: the natural-spline interpolation" in en.stderr
    (out / "table.csv").write_text("edited", encoding="utf-8")
    ru = runner.invoke(app, [*args, "--lang", "ru", "--report", "md"])
    assert ru.exit_code == 0
    lines = ru.stderr.strip().splitlines()
    assert any(x.startswith("предупреждение: цилиндр LP: интерполяция") for x in lines), lines
    assert any(x.startswith("примечание: ") and "оставлены файлы" in x for x in lines), lines
    assert any(x.startswith("примечание: ") and "удалены файлы" in x for x in lines), lines
    for x in lines:
        assert _no_english(x.split(str(out))[-1]), x
    assert f"записано: {out}/" in ru.stdout
    # the report's warnings section says it in Russian too
    md = (out / "report.md").read_text(encoding="utf-8")
    assert "отрицательное давление" in md and "negative pressure" not in md


def test_plausibility_and_duty_cycle_warnings_are_russian(tmp_path):
    case = (CASES / "fourbar.toml").read_text(encoding="utf-8")
    case = re.sub(r"(?m)^delta\s*=.*$", "delta = 0.5", case, count=1)
    (tmp_path / "c.toml").write_text(case, encoding="utf-8")
    res = runner.invoke(app, ["run", str(tmp_path / "c.toml"), "--points", "360", "--no-plots",
                              "--lang", "ru", "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert "предупреждение: machine.delta: δ = 0.5 вне обычных 1/300 … 1/5" in res.stderr
    assert "предупреждение: нагрузки не совершают работы за цикл" in res.stderr
    res = runner.invoke(app, ["duty-cycle", str(CASES / "duty_readme_press.toml"), "--lang", "ru"])
    assert res.exit_code == 0
    assert res.stderr.startswith("предупреждение: двигатель сильнее, чем нужно операциям")
    en = runner.invoke(app, ["duty-cycle", str(CASES / "duty_readme_press.toml")])
    assert en.stderr.startswith("warning: the motor is stronger than the operations need")


def test_task2_and_aggregate_written_lines_are_russian(tmp_path):
    res = runner.invoke(app, ["task2", "--out", str(tmp_path / "t"), "--lang", "ru"])
    assert res.exit_code == 0 and f"записано: {tmp_path / 't'}/" in res.stdout
    res = runner.invoke(app, ["task2", "--out", str(tmp_path / "t"), "--lang", "ru",
                              "--report", "md"])
    assert "примечание: " in res.stderr and "удалены файлы" in res.stderr
