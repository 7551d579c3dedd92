"""Russian warnings and messages (errors.Notice, render/nomenclature.py MESSAGES_RU): every
Notice the code makes has a Russian template whose fields it gives; with --lang ru the CLI's
"warning:", "note:" and "written:" lines are Russian; in English a Notice is its text."""
from __future__ import annotations

import ast
import pickle
import re
import string
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest

from typer.testing import CliRunner

from flywheel.cli import app
from flywheel.errors import Notice
from flywheel.render import library_ru, message_params
from flywheel.render import messages as nm

SRC = Path(__file__).resolve().parents[1] / "src" / "flywheel"
CASES = Path(__file__).resolve().parents[1] / "cases"
runner = CliRunner()
# fields a template may take that render/nomenclature.py derives from the Notice's own
DERIVED = message_params.DERIVED
# the Russian templates of the catalogue (locale/ru/LC_MESSAGES/flywheel.po) by the Notice's code
RU = {code: nm.entry(code, "ru") for code in nm.notice_codes()}
# the errors io/schema.py.describe makes from pydantic's (code made from pydantic's error type;
# fields: pydantic's ctx and the value given)
DESCRIBED = {c for c in RU if c.startswith("pydantic_")} | {
    "missing", "not_a_table", "not_finite_number"}


def _notices():
    """(file, code, keyword names) of every Notice(…) call in the package."""
    for path in SRC.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "Notice"
                    and len(node.args) >= 2 and isinstance(node.args[1], ast.Constant)):
                yield path.name, node.args[1].value, {k.arg for k in node.keywords}


def test_every_notice_has_a_russian_template_with_its_fields():
    found = list(_notices())
    assert len(found) >= 15
    for file, code, keys in found:
        assert code in RU, (file, code)
        fields = {f for _, f, _, _ in string.Formatter().parse(RU[code]) if f}
        assert fields <= keys | DERIVED, (file, code, fields - keys)
    assert {c for _, c, _ in found} | DESCRIBED == set(RU)


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


# -- errors under --lang ru ------------------------------------------------------------------------
sys.path.insert(0, str(Path(__file__).resolve().parent))
import test_bad_inputs as bad  # noqa: E402

# catalogue entries (tests/bad_inputs/catalogue.toml) run again with --lang ru: the Russian words
# the one `ошибка:` line must hold (besides the entry's file and field path)
RUSSIAN_ERRORS = {
    "run/missing-file": ["нет такого файла"],
    "run/folder-given-as-case": ["это папка, а нужен файл случая TOML"],
    "run/empty-file": ["machine: не задано обязательное поле"],
    "run/binary-png": ["текст не в кодировке UTF-8"],
    "run/toml-decimal-comma": ["синтаксическая ошибка TOML: после инструкции ожидается перевод "
                               "строки или конец документа (строка 11, столбец 14)"],
    "check/toml-syntax-error": ["синтаксическая ошибка TOML: в конце объявления таблицы "
                                "ожидается ']' (строка 33, столбец 8)"],
    "aggregate/toml-syntax-error": ["синтаксическая ошибка TOML: недопустимый первый символ "
                                    "ключа (строка 38, столбец 24)"],
    "variants/template-toml-syntax-error": ["синтаксическая ошибка TOML: после инструкции"],
    "run/misspelt-table": ["machin: неизвестный ключ; может быть, 'machine'?", "допустимы:"],
    "run/speed-quoted": ["machine.speed_rps: должно быть числом (задано '10.0')"],
    "run/speed-nan": ["machine.speed_rps: должно быть конечным числом (задано nan)"],
    "run/speed-negative": ["machine.speed_rps: должно быть больше 0 (задано -10.0)"],
    "run/speed-1e308": ["machine.speed_rps", "вне допустимого диапазона"],
    "run/balance-unknown": ["machine.balance: должно быть одним из: 'driving' или 'resistance'"],
    "run/machine-not-a-table": ["machine: должно быть таблицей ключей"],
    "run/rrr-cannot-assemble": ["dyads[0]: группа B (RRR, звенья 2–3) не собирается при угле "
                                "кривошипа φ = "],
    "run/rpr-rocker-pivot-on-crank-circle": ["dyads[0]: группа 3 (RPR, кулиса 3) имеет особое "
                                             "положение"],
    "run/task2-case": ["это случай задачи 2", "используйте `flywheel task2 --case"],
    "run/out-is-a-file": ["— это файл, а не папка"],
    "run/points-zero": ["--points: 0 вне допустимого диапазона (допустимо: 36 … 100000"],
    "task2/md-negative": ["--md должно быть положительным (задано -15 Н·м)"],
    "run/csv-dialect-unknown": ["--csv: 'excel' — недопустимое значение (допустимы: plain, "
                                "excel-ru)"],
    "run/dpi-too-small": ["--dpi: 10 вне допустимого диапазона (допустимо: 50 … 600)"],
    "task2/report-without-out": ["--report пишет в папку вывода: укажите также --out DIR"],
    "aggregate/report-unknown": ["--report: 'html5' — недопустимое значение"],
    "grade/tolerance-negative": ["--tolerance: должно быть положительным числом (задано -0.01)"],
    "variants/count-zero": ["--count: 0 — недопустимое значение (допустимо: 1…9999)"],
    "run/delta-missing": ["machine.delta: не задано: укажите machine.delta"],
    "run/crank-missing": ["(верхний уровень): задайте что-то одно: [crank] (механизм) или "
                          "[tabulated]"],
    "task2/case-delta-two": ["flywheel.delta: должно лежать между 0 и 2 (задано 2)"],
    "grade/key-answer-a-string": ["variants.01.J_required: должно быть конечным числом (задано "
                                  "'30.2')"],
    "task2/case-misspelt-key": ["неизвестный ключ"],
    "aggregate/misspelt-key": ["неизвестный ключ"],
    "variants/template-does-not-solve": ["сам шаблон не удаётся рассчитать", "не собирается"],
    "variants/template-does-not-validate": ["machine.delta: должно быть больше 0",
                                            "[проверено как случай для flywheel run]"],
}
# --- msgs2 --- the cross-field checks of the case files, the non-finite policy, --t-end, --at,
# --plot, the variants template's paths and answers, the answer key (json's own words stay English)
RUSSIAN_ERRORS.update({
    "run/aggregate-case": ['это случай агрегата (упругие муфты), а не случай для'],
    "run/variants-template": ['это шаблон вариантов, а не случай для flywheel run:'],
    "run/two-speeds": ['задайте что-то одно: speed_rps или speed_rpm'],
    "run/no-speed": ['задайте что-то одно: speed_rps или speed_rpm'],
    "run/no-crank-length": ['не задано: укажите crank.length или design.mean_piston_speed'],
    "run/ground-point-undefined": ["точка 'D' используется раньше, чем задана (заданы: A, O)"],
    "run/dyads-missing": ["звено '2' не задано (звенья: 1)"],
    "run/dyad-kind-unknown": ['должно быть одним из: RRP, RRR, RPR'],
    "run/dyad-from-undefined": ["точка 'Z' используется раньше, чем задана (заданы: A, B, O,"],
    "run/dyad-joint-reused": ["имя точки 'B' уже занято"],
    "run/dyad-link-reused": ["имя звена '2' уже занято"],
    "run/point-on-undefined-link": ["звено '9' не задано (звенья: 1, 2, 3, 4, 5)"],
    "run/point-from-undefined-point": ["точка 'Q' нигде не задана"],
    "run/point-to-and-distance": ['задайте что-то одно: `to` (с fraction) или `distance` (с'],
    "run/link-centroid-undefined": ["точка 'S9' не задана"],
    "run/link-undefined": ["нет звена '7' (звенья: 1, 2, 3)"],
    "run/link-mass-without-centroid": ['у звена с массой должен быть задан `centroid`'],
    "run/cylinder-table-one-short": ['нужно 11 значений, по одному на каждое s (задано 10)'],
    "run/cylinder-s-not-increasing": ['значения должны строго возрастать'],
    "run/cylinder-piston-undefined": ['не ползун группы RRP (ползуны: 3, 5)'],
    "run/cylinder-pressure-below-vacuum": ['даёт -17.64 МПа избыточного давления, ниже абсолютного'],
    "run/cylinder-pressure-above-p-max": ['больше 1: p_max = 882000 Па — наибольшее давление диаграммы'],
    "run/given-flywheel-too-small-no-steady-motion": ['заданный маховик (J = 0.001 кг·м²) слишком мал для этих'],
    "run/force-on-undefined-slider": ['не ползун группы RRP'],
    "run/force-range-reversed": ['должно быть 0 ≤ from < to ≤ 1 (задано 0.95, 0.05)'],
    "run/force-name-duplicate": ["имя нагрузки 'cutting' встречается дважды"],
    "run/couple-on-undefined-link": ["нет звена '8'"],
    "run/tabulated-row-one-short": ['нужно 13 значений, по одному на каждое положение'],
    "run/tabulated-positions-not-increasing": ['после 60°: положения должны возрастать'],
    "run/tabulated-force-at-undefined-point": ["аналогов скоростей точки 'B9' нет в [tabulated.points]"],
    "run/tabulated-link-at-undefined-point": ["аналогов скоростей точки 'B5' нет в [tabulated.points]"],
    "run/at-nan": ['не конечный угол в градусах'],
    "run/at-inf": ['не конечный угол в градусах'],
    "run/transients-rundown-too-long": ['выбег для --transients занял бы около 1.51e+03 циклов'],
    "run/transients-startup-too-long": ['разгон для --transients занял бы около 8.74e+03 циклов'],
    "check/task2-case": ['это случай задачи 2 (заданные графики моментов), а не'],
    "check/aggregate-chain": ['это случай агрегата (упругие муфты), а не случай для'],
    "check/point-from-undefined": ["точка 'X' нигде не задана"],
    "task2/profile-unknown": ["должно быть triangle или rectangle (задано 'square')"],
    "task2/md-1e308": ['не конечное число (баланс работ за цикл даёт момент'],
    "task2/to-beyond-the-cycle": ['и to должны лежать в пределах 0…360° (задано 90°, 720°)'],
    "task2/case-and-options": ['берёт данные из файла; уберите --md'],
    "task2/plot-is-a-folder": ['это папка, а нужен файл изображения'],
    "task2/case-run-case": ['это случай для flywheel run, а не случай задачи 2 (заданные'],
    "task2/case-aggregate-case": ['это случай агрегата (упругие муфты), а не случай задачи 2'],
    "task2/case-variants-template": ['это шаблон вариантов, а не случай задачи 2 (заданные'],
    "task2/case-two-speeds": ['задайте что-то одно: omega0, omega0_rpm, mean, mean_rpm или'],
    "task2/case-J-negative": ['должно быть положительным (задано -12 кг·м²)'],
    "task2/case-mass-without-radius": ['и radius_of_gyration задаются вместе (J = m·k²)'],
    "task2/case-driving-kind-unknown": ["неизвестный вид 'linear' (допустимы: constant, points,"],
    "task2/case-value-not-balance": ['должно быть числом, "balance" или "power" (задано'],
    "task2/case-two-balances": ['может заменять лишь одно значение (другое уже задано так:'],
    "task2/case-points-go-back": ['угол 200° идёт после 270°: углы не должны убывать'],
    "task2/case-points-three-at-one-angle": ['третье значение при 90°: у скачка их два (значение до и'],
    "task2/case-points-do-not-reach-the-cycle-end": ['должно охватывать цикл 0…360° (охвачено 0…300°)'],
    "task2/case-triangle-reversed": ['нужно 0 ≤ from_deg < to_deg ≤ 360 (задано 300, 270)'],
    "task2/case-trapezoid-top-outside": ['нужно from_deg ≤ top_from_deg ≤ top_to_deg ≤ to_deg'],
    "task2/case-harmonic-lengths-differ": ['задано порядков гармоник: 2, а членов ряда: 1'],
    "task2/case-diagram-areas-do-not-close": ['сумма 1, а не 0: за цикл площади над средней линией и под'],
    "task2/case-diagram-and-graphs": ['задайте что-то одно: [diagram] или [driving] и [resistance]'],
    "task2/case-diagram-scale-zero": ['должно быть положительным (задано 0)'],
    "task2/case-driving-1e308": ['не конечное число (баланс работ за цикл даёт момент'],
    "aggregate/empty-file": ['не задано: задайте двухмассовый агрегат ([motor],'],
    "aggregate/run-case": ['это случай для flywheel run, а не случай агрегата (упругие'],
    "aggregate/task2-case": ['это случай задачи 2 (заданные графики моментов), а не'],
    "aggregate/variants-template": ['это шаблон вариантов, а не случай агрегата (упругие муфты):'],
    "aggregate/motor-J-missing": ['не задано обязательное поле (J_Д, момент инерции ротора'],
    "aggregate/motor-slip-without-torque": ['задайте что-то одно: starting_torque или rated_torque с'],
    "aggregate/coupling-c-and-d-L": ['задайте что-то одно: c или d и L (с G)'],
    "aggregate/coupling-missing": ['не задано: двухмассовому агрегату нужны [motor], [coupling]'],
    "aggregate/flywheel-on-II-without-i21": ['не задано: маховику на валу II нужно i21 = ω_II/ω_I'],
    "aggregate/J-III-missing": ['не задано: укажите J_III (J_пр.III, кг·м²) или J_III_0 с'],
    "aggregate/one-rotor": ['цепочке нужно не меньше двух роторов (задано 1)'],
    "aggregate/shafts-one-short": ['роторов: 3, поэтому валов между ними нужно 2 вала (задано 1)'],
    "aggregate/rotor-names-repeat": ['имена роторов должны различаться'],
    "aggregate/shaft-G-missing": ['не задано: с d и L нужен модуль сдвига G (например, 8.0e10'],
    "aggregate/load-without-motor": ['не задано: для [load] нужен [motor] на первом роторе'],
    "aggregate/chain-and-two-mass": ['случай — либо двухмассовый агрегат ([coupling], [machine]),'],
    "aggregate/t-end-zero": ['с вне допустимого диапазона (допустимо: 0 … 600 с; разгон'],
    "aggregate/t-end-nan": ['с вне допустимого диапазона (допустимо: 0 … 600 с; разгон'],
    "aggregate/t-end-1e6": ['с вне допустимого диапазона (допустимо: 0 … 600 с; разгон'],
    "aggregate/t-end-too-many-steps": ['разгон потребовал бы около 1.88e+07 шагов интегрирования'],
    "aggregate/startup-stiff-motor-t-end": ['разгон потребовал бы около 3.99e+06 шагов интегрирования'],
    "aggregate/plot-without-motor": ['требует [motor]: у цепочки без двигателя нет движения во'],
    "variants/points-too-few": ['слишком мало (допустимо: 36 и больше)'],
    "variants/points-too-many": ['сам шаблон не удаётся рассчитать: --points: 100000000 вне'],
    "variants/template-empty": ['нет таблицы [variants] (в ней сказано, что менять и какие'],
    "variants/no-variants-table": ['нет таблицы [variants] (в ней сказано, что менять и какие'],
    "variants/path-misspelt": ["нет в [speed] (там есть: omega0); может быть, 'omega0'? —"],
    "variants/path-into-a-missing-table": ['нет в верхнем уровне (там есть: title, source, cycle_deg,'],
    "variants/answers-missing": ['не задано (ключи результатов для ключа ответов, например'],
    "variants/answers-empty": ['должно быть непустым списком имён результатов (задано [])'],
    "variants/answer-misspelt": ['не является результатом (числовые результаты: omega_max,'],
    "variants/answer-not-a-number": ['не является результатом (числовые результаты: omega_max,'],
    "variants/min-above-max": ['меньше min (30.0)'],
    "variants/step-zero": ['должно быть положительным (задано 0.0)'],
    "variants/values-empty": ['должно быть непустым списком (задано [])'],
    "variants/spec-a-bare-number": ['должно быть таблицей { values = [...] } или { min = …, max'],
    "variants/tolerance-for-unknown-answer": ['не является одним из ответов (допустимы: M_C, omega_max,'],
    "variants/every-draw-fails": ['вариант 1: 50 попыток подряд не прошли проверку или расчёт;'],
    "grade/key-missing": ['нет такого файла'],
    "grade/key-folder": ['это папка, а нужен answers.json команды flywheel variants'],
    "grade/key-binary": ['текст не в кодировке UTF-8 (invalid start byte в байте 0)'],
    "task2/plot-unknown-format": ["не удаётся записать изображение (формат 'xyz' не "
                                  "поддерживается (поддерживаются: "],
    "task2/plot-in-a-missing-folder": ["не удаётся записать изображение (нет такого файла или "
                                       "папки)"],
    "grade/key-not-json": ['не JSON: ожидается имя свойства в двойных кавычках (строка'],
    "grade/key-truncated": ['не JSON: незакрытая строка, её начало (строка 3, столбец'],
    "grade/key-a-list": ['должно быть объектом JSON {вариант: {ответ: значение}}'],
    "grade/key-no-variants": ['должно быть непустым объектом {вариант: {ответ: значение}}'],
    "grade/key-tolerances-zero": ['должно быть объектом {ответ: положительное число} (задано'],
    "grade/key-is-a-case-file": ['не JSON: ожидается значение (строка 1, столбец 1)'],
    "grade/key-and-sheet-swapped": ['не JSON: ожидается значение (строка 1, столбец 1)'],
    "grade/out-is-a-folder": ['это папка, а нужно имя файла CSV'],
    "grade/gradebook-is-a-folder": ['это папка, а нужно имя файла CSV'],
    "grade/out-inside-a-file": ['не существует (допустимо: имя файла CSV в существующей папке)'],
    "grade/sheet-blank-rows-only": ['нечего проверить: нет заполненных строк студентов (в строке'],
    "run/rim-share-zero": ['не доля J маховика (допустимо: 0 < share ≤ 1)'],
    "run/rim-share-above-one": ['не доля J маховика (допустимо: 0 < share ≤ 1)'],
    "run/rim-speed-above-the-allowable-stress": ['м/с даёт окружное напряжение ρ·v² = 49.92 МПа больше'],
    "run/rim-width-and-ratio": ['задайте что-то одно: width или width_to_thickness'],
    "run/rim-share-twice": ['при [flywheel.rim] доля задаётся как flywheel.rim.share'],
    "run/rim-thicker-than-its-diameter": ['обод получается толщиной 3009 м при среднем диаметре'],
    "task2/rim-share-zero": ['не доля J маховика (допустимо: 0 < share ≤ 1)'],
    "task2/rim-speed-above-the-allowable-stress": ['м/с даёт окружное напряжение ρ·v² = 11.6 МПа больше'],
    "run/given-flywheel-mass-without-radius": ['не задано: mass и radius_of_gyration задаются вместе (J ='],
    "run/given-flywheel-two-forms": ['заданный маховик — что-то одно из: J, mass с'],
    "run/given-rim-inner-above-outer": ['м — не меньше D = 0.5 м'],
    "run/pins-at-the-same-angle": ["ставит шейку 'A3' туда, где уже шейка (crank.pins[0]) 'A2'"],
    "run/firing-order-misses-a-cylinder": ["нет цилиндра '2' (порядок работы перечисляет каждый"],
    "run/firing-order-does-not-fit-the-crankshaft": ['не укладывается в один цикл 720°: цилиндр 4 (позиция 4)'],
    "run/four-stroke-diagram-on-a-360-cycle": ['четырёхтактная диаграмма занимает 720° угла кривошипа, а'],
    "run/strokes-do-not-meet": ['начинается с p/p_max = 0.5 при s = 0, где compression'],
    "run/animate-a-tabulated-case": ['задаёт кинематику таблицей ([tabulated]): анимировать'],
    "aggregate/fixed-end-without-a-shaft": ['не задано: неподвижный конец rotors[0] связан валом с'],
    "grade/gradebook-in-a-missing-folder": ['не существует (допустимо: имя файла CSV в существующей папке)'],
    "duty-cycle/speed-drop-beyond-the-speed": ['вне допустимого диапазона: скорость упала бы до нуля или'],
    "duty-cycle/min-speed-above-the-max": ['не меньше max_rpm = 225 (допустимо: 0 < min_rpm < max_rpm)'],
    "duty-cycle/given-flywheel-would-stop": ['маховик слишком мал: чтобы отдать 97000 Дж (ΔE) на каждую'],
})
# --- msgs_duty --- the duty cycle's case checks and solution, the variants template's paths,
# ranges and answers, the answer key's variants and answers
RUSSIAN_ERRORS.update({
    "duty-cycle/hole-without-thickness": ["operation.thickness: не задано: для hole_diameter "
                                          "нужна толщина листа (A = π·d·t)"],
    "duty-cycle/sheared-area-with-the-energy": ["operation.hole_diameter: задаётся только "
                                                "вместе с energy_per_area или shear_strength"],
    "duty-cycle/shape-with-the-energy": ["operation.shape: задаётся только вместе с force или "
                                         "shear_strength"],
    "duty-cycle/stroke-without-thickness": ["operation.thickness: не задано: ход задаёт долю "
                                            "цикла t/(2·s)"],
    "duty-cycle/stroke-shorter-than-half-the-thickness": [
        "0.01 м — меньше половины толщины 0.032 м", "(допустимо: stroke ≥ 0.016 м)"],
    "duty-cycle/delta-E-above-the-work": ["20000 Дж — больше работы операции E = 15000 Дж "
                                          "(допустимо: ΔE ≤ E)"],
    "duty-cycle/cycle-with-delta-E-alone": ["cycle: требует работы одной операции",
                                            "при одном delta_E подбирается только маховик"],
    "duty-cycle/speeds-in-two-units": ["задайте скорости в одних единицах (задано max_rpm, "
                                       "min_omega)"],
    "duty-cycle/given-flywheel-two-speeds": ["при заданном маховике задайте одну скорость",
                                             "(задано max_rpm, min_rpm)"],
    "duty-cycle/given-mass-without-radius": ["flywheel.mass: нужен радиус"],
    "duty-cycle/given-J-with-rim-speeds-without-radius": ["flywheel.J: при скоростях на радиусе "
                                                          "(м/с) задайте и радиус"],
    "duty-cycle/two-fluctuations": ["задайте что-то одно из: percent, total_percent, delta, "
                                    "drop_percent (задано percent, delta)"],
    "duty-cycle/one-speed-only": ["задайте две скорости (две из max, min, mean)",
                                  "(задано max_rpm)"],
    "duty-cycle/revolutions-with-rim-speeds-without-radius": [
        "cycle.every_revolutions: нужна скорость вала", "скорости в об/мин"],
    "duty-cycle/max-speed-twice-the-mean": ["225 при mean_rpm = 100 даёт min = 2·mean − max = "
                                            "-25 (допустимо: 100 < max_rpm < 200)"],
    "duty-cycle/drop-without-the-top-speed": ["flywheel.drop_percent: это падение от "
                                              "наибольшей скорости"],
    "duty-cycle/speeds-equal-in-rad-per-s": ["не дают её падения (допустимо: ω_max > ω_min > "
                                             "0)"],
    "duty-cycle/motor-power-too-small": ["motor.power: мощность двигателя 2000 Вт меньше "
                                         "средней мощности операций E/T_c = 3000 Вт"],
    "duty-cycle/motor-torque-too-small-for-the-rate": [
        "motor.torque: момент двигателя 1 Н·м (P = M_Д·ω_ср = 22.2529 Вт) меньше средней "
        "мощности операций"],
    "duty-cycle/motor-torque-too-small-for-the-revolutions": [
        "момент двигателя 100 Н·м меньше среднего момента операций E/(2π·k) = 212.207 Н·м",
        "(допустимо: не меньше 212.207 Н·м)"],
    "duty-cycle/operation-longer-than-the-cycle": ["операция длится 6 с — дольше цикла T_c = "
                                                   "5 с (допустимо: не дольше цикла)"],
    "variants/path-index-not-a-number": ["cylinders — массив; 'x' — не индекс (допустимо: "
                                         "0…1)"],
    "variants/path-index-out-of-range": ["в cylinders элементов: 2; индекс 7 вне допустимого "
                                         "диапазона (допустимо: 0…1)"],
    "variants/path-inside-a-number": ["speed.omega0 — значение, а не таблица; внутри него нет "
                                      "ничего с именем 'rpm'"],
    "variants/path-overlaps-another": ['variants."speed.omega0": пересекается с '
                                       'variants."speed.omega0"'],
    "variants/path-is-a-table": ["это таблица; меняйте её поля по одному"],
    "variants/values-are-tables": ["таблицы нельзя выбирать целиком"],
    "variants/vary-the-variants-table": ["нельзя менять саму таблицу [variants]"],
    "variants/variants-not-a-table": ["variants: должно быть таблицей (задано 3)"],
    "variants/nothing-to-vary": ["variants: нечего менять (добавьте, например,"],
    "variants/grid-without-step": ["не задано step (задайте min, max и step или values)"],
    "variants/grid-too-fine": ["значений сетки 2000001 — слишком много (допустимо: не больше "
                               "100000"],
    "variants/spec-unknown-key": ["неизвестный ключ 'vals'"],
    "variants/values-and-a-grid": ["задайте что-то одно: values или min, max, step"],
    "variants/grid-on-a-word": ["для min/max/step в шаблоне нужно число (там 'balance')"],
    "variants/answer-twice": ["variants.answers: 'M_C' указан дважды"],
    "variants/answer-with-a-semicolon": ["'M_C;delta' содержит символ, недопустимый в имени "
                                         "столбца CSV"],
    "variants/tolerances-a-number": ["variants.tolerances: должно быть таблицей { ответ = "
                                     "допуск } (задано 0.01)"],
    "grade/key-variant-not-an-object": ["variants.01: должно быть объектом {ответ: значение} "
                                        "(задано 150.0)"],
    "grade/key-answers-not-a-list": ["answers: должно быть списком имён ответов (задано "
                                     "'M_C')"],
    "grade/key-name-too-long": ["не удаётся прочитать (слишком длинное имя файла)"],
})
# --- msgs_tabulated --- the checks of a [tabulated] section (cases/tabulated.py)
RUSSIAN_ERRORS.update({
    "run/tabulated-position-outside-the-cycle": ["400° вне цикла (допустимо: 0 … 360)"],
    "run/tabulated-position-duplicated": ["угол 30° повторяется (положения 2 и 3)"],
    "run/tabulated-too-few-positions": ["различных положений 2 — слишком мало (допустимо: 6"],
    "run/tabulated-positions-leave-a-gap": ["между 3° и 120° нет ни одного (промежуток 117°;"],
    "run/tabulated-analogue-negative": ["-0.05 < 0: аналоги скоростей — модули |V_q| ≥ 0"],
    "run/tabulated-row-does-not-close": ["значение при 360° (0.03) должно повторять значение"],
    "run/tabulated-link-mass-without-point": ["у звена 3 масса 81.6 кг, но нет аналогов"],
    "run/tabulated-link-J-without-omega-row": ["в [tabulated.omega_q] нет строки '7' (строки: 2,"],
    "run/tabulated-load-name-twice": ["имя нагрузки 'G2' встречается дважды"],
    "run/tabulated-inertia-overflows": ["переполняется в положении 4 (90°): значения вне"],
    "run/tabulated-moment-overflows": ["приведённый момент нагрузки «сила G5» переполняется"],
})
# --- msgs_aggregate --- the aggregate's case checks across fields, the chain reduced to
# shaft I (gear pairs in series), the natural frequencies and the steady state
def test_aggregate_integration_failure_is_russian(monkeypatch):
    # no case file is known to make solve_ivp fail (the steps are bounded first): a failed
    # result stands in for it; scipy's own words stay English, as tomllib's do
    import numpy as np
    import scipy.integrate

    class Failed:
        success, t, y = False, None, np.zeros((3, 1))
        message = "Required step size is less than spacing between numbers."

    from flywheel.cases.aggregate import load_aggregate_case, to_model
    from flywheel.elastic.model import analyze

    case = str(CASES / "aggregate.toml")
    w = analyze(*to_model(load_aggregate_case(case)), time_domain=False).steady.omega_forcing
    t = f"{5 * 2 * np.pi / w:.4g}"              # the steady check: 5 forcing periods, first
    monkeypatch.setattr(scipy.integrate, "solve_ivp", lambda *a, **k: Failed())
    en = runner.invoke(app, ["aggregate", case, "--json"])
    ru = runner.invoke(app, ["aggregate", case, "--json", "--lang", "ru"])
    assert en.exit_code == ru.exit_code == 2 and en.stdout == ru.stdout == ""
    assert en.stderr == (f"error: {case}: solve_ivp (DOP853) failed over 0 … {t} s: "
                         "Required step size is less than spacing between numbers.\n")
    assert ru.stderr == (f"ошибка: {case}: solve_ivp (DOP853) не справился на отрезке 0 … "
                         f"{t} с: Required step size is less than spacing between numbers.\n")
    Failed.success, Failed.y = True, np.full((3, 1), np.nan)
    ru = runner.invoke(app, ["aggregate", case, "--json", "--lang", "ru"])
    assert ru.stderr.endswith("с: решение не конечно\n"), ru.stderr


RUSSIAN_ERRORS.update({
    "aggregate/shaft-stiffness-and-segments": ["задайте что-то одно: жёсткость прямо (c или d и L) или"],
    "aggregate/shaft-segments-empty": ["нужен хотя бы один отрезок вала"],
    "aggregate/shaft-L-missing": ["не задано: задайте c или d и L (с G)"],
    "aggregate/chain-motor-with-J": ["в цепочке двигатель — это первый ротор: задайте его J в"],
    "aggregate/motor-linear-with-speed": ["только при characteristic = \"constant\" (двигатель с линейной"],
    "aggregate/motor-synchronous-missing": ["не задано: линейной характеристике нужна синхронная скорость"],
    "aggregate/motor-rated-slip-missing": ["не задано: нужно вместе с rated_torque (M_п = M_н/s_н)"],
    "aggregate/motor-slip-with-starting-torque": ["задаётся только вместе с rated_torque"],
    "aggregate/motor-cannot-drive": ["двигатель не может привести машину в движение: M_п = 4191.17"],
    "aggregate/motor-constant-with-synchronous": ["только при characteristic = \"linear\""],
    "aggregate/motor-constant-without-speed": ["не задано: двигателю с постоянным моментом нужна"],
    "aggregate/two-mass-without-motor": ["не задано: двухмассовому агрегату нужен [motor] с J (J_Д)"],
    "aggregate/J-III-and-its-positions": ["задайте что-то одно: J_III или J_III_0 с J_III_positions"],
    "aggregate/J-III-positions-empty": ["нужно хотя бы одно значение"],
    "aggregate/J-III-positions-zero": ["J_пр.III получается равным нулю: должен быть положительным"],
    "aggregate/coupling-gear-pair": ["муфта соединяет двигатель с валом I: зубчатой пары в ней нет"],
    "aggregate/coupling-between": ["муфта соединяет двигатель с машиной: between задаётся только"],
    "aggregate/fixed-rotor-with-J": ["неподвижный конец (fixed = true) — это стойка: момента"],
    "aggregate/rotor-J-missing": ["не задано обязательное поле (момент инерции, кг·м²; или fixed"],
    "aggregate/motor-on-a-fixed-system": ["вал, закреплённый в стойке, не может вращаться непрерывно:"],
    "aggregate/motor-on-a-branched-system": ["вынужденные колебания и пуск рассчитываются для", "требуют свободной неразветвлённой цепочки"],
    "aggregate/between-for-one-shaft-only": ["не задано: задайте between для каждого вала или ни для одного"],
    "aggregate/between-one-name": ["нужны имена двух роторов, первым — со стороны входа (задано 1)"],
    "aggregate/between-unknown-rotor": ["нет ротора 'X' (роторы: A, B, C)"],
    "aggregate/between-to-itself": ["соединяет ротор 'A' с ним самим"],
    "aggregate/fixed-end-in-the-middle": ["неподвижный конец — конец системы: к нему подходит один вал"],
    "aggregate/every-rotor-fixed": ["все роторы неподвижны: хотя бы один должен вращаться"],
    "aggregate/rotors-in-a-loop": ["роторы и валы должны образовывать одну связную систему без"],
    "aggregate/damping-of-a-shaft-to-the-frame": ["вал к стойке: его демпфирование в модели не учитывается"],
    "aggregate/reduced-J-overflows": ["ротор 51: приведённое к валу I значение момента инерции — не", "оно выходит за пределы двойной точности"],
    "aggregate/reduced-stiffness-to-the-frame-overflows": ["ротор 56: жёсткость связи со стойкой, приведённая к валу I,"],
    "aggregate/reduced-stiffness-to-the-frame-underflows": ["системе, закреплённой в стойке, нужен вал к стойке"],
    "aggregate/reduced-J-underflows": ["ротор 54: момент инерции должен быть положительным (получено"],
    "aggregate/reduced-stiffness-underflows": ["соединение 55: жёсткость должна быть положительной (получено"],
    "aggregate/natural-frequencies-overflow": ["собственные частоты не конечны: задача K·x = ω²·M·x выходит"],
    "aggregate/resonance-undamped": ["частота возмущения 31.4159 рад/с (5 Гц) совпадает с", "амплитуда установившихся колебаний неограниченна"],
    "aggregate/forcing-swings-the-rigid-body": ["частота возмущения 1.0472e-07 рад/с намного ниже низшей", "которую двигатель с постоянным моментом не удерживает"],
    "aggregate/forcing-reverses-a-rotor": ["скорость ротора машина J_пр.I колебалась бы на ±358.758 рад/с", "вращалась в обратную сторону каждый период"],
    "aggregate/forcing-frequency-zero": ["амплитуды установившихся колебаний не конечны при частоте"],
})
# --- msgs_task2 --- flywheel task2: the cross-field checks of a case, the mean power, the cycle
# balance, the area diagram, --at (the angles that coincide only in radians included)
RUSSIAN_ERRORS.update({
    "task2/case-speed-max-without-min": ["не задано: пределы скорости задаются парой (max с min)"],
    "task2/case-speed-min-above-max": ["должно быть меньше max_rpm (задано 1900 об/мин, а max_rpm "
                                       "= 1800 об/мин)"],
    "task2/case-speed-limits-and-delta": ["пределы скорости уже дают δ = (max − min)/ω_ср: "
                                          "задайте что-то одно"],
    "task2/case-flywheel-gives-nothing": ["задайте J, или mass и radius_of_gyration, или "
                                          "требуемое delta"],
    "task2/case-at-deg-beyond-the-cycle": ["должно лежать в пределах цикла 0…360° (задано 400)"],
    "task2/case-diagram-with-at-deg": ["у диаграммы, заданной площадями, нет моментов между "
                                       "точками пересечения"],
    "task2/case-resistance-missing": ["не задано: задайте графики [driving] и [resistance] или "
                                      "[diagram]"],
    "task2/case-points-one-point": ["нужно не меньше двух точек [угол, момент]"],
    "task2/case-apex-outside-the-triangle": ["должно лежать в пределах 90…270° (задано 300)"],
    "task2/case-interval-empty-in-radians": ["интервал графика 14.5…14.5° должен удовлетворять"],
    "task2/case-two-powers": ['"power" может заменять лишь одно значение (другое уже задано так: '
                              "driving.value)"],
    "task2/case-power-value-without-power": ['для "power" нужна средняя мощность: задайте power '
                                             "[Вт] на верхнем уровне"],
    "task2/case-power-value-with-omega0": ["(средний момент M_ср = P/ω_ср) нужна средняя "
                                           "скорость"],
    "task2/case-power-unused": ['используется только значением графика "power" (M_ср = P/ω_ср)'],
    "task2/case-power-value-does-no-work": ["значение движущего момента не меняет его работу: по "
                                            "средней мощности его не найти"],
    "task2/case-power-needs-a-negative-moment": ["средняя мощность 10 Вт требует отрицательного "
                                                 "значения движущего момента (-692)",
                                                 "P·Φ/ω_ср = 6.28319 Дж"],
    "task2/case-balance-value-does-no-work": ["неизвестное значение движущего момента не меняет "
                                              "его работу: по балансу работ"],
    "task2/case-balance-needs-a-negative-resistance": [
        "баланс работ за цикл требует отрицательного момента сопротивления (-240 Н·м): движущий "
        "момент совершает больше работы"],
    "task2/case-balance-needs-a-negative-driving": [
        "баланс работ за цикл требует отрицательного движущего момента (-600 Н·м): момент "
        "сопротивления совершает меньше работы"],
    "task2/case-J-too-small-for-the-mean-speed": ["J = 0.001 кг·м² слишком мал для средней "
                                                  "скорости 1 рад/с"],
    "task2/case-delta-with-omega0": ["чтобы найти J по δ, задайте среднюю скорость, а не ω0"],
    "task2/case-delta-without-fluctuation": ["энергия не колеблется: при любом J δ = 0"],
    "task2/case-mean-speed-not-steady": ["средняя скорость требует установившегося движения "
                                         "(работа за цикл 78.5398 Дж, а не 0)"],
    "task2/case-fluctuation-percent-100": ["δ должно лежать между 0 и 2 (задано 2)"],
    "task2/case-diagram-fluctuation-percent-100": ["δ должно лежать между 0 и 2 (задано 2)"],
    "task2/case-speed-comes-too-close-to-zero": ["не удаётся найти на 90…270°: интеграл не "
                                                 "сходится"],
    "task2/case-diagram-two-forms": ["задайте что-то одно: areas (с moment_scale и "
                                     "angle_scale_deg)", "(задано areas, energies)"],
    "task2/case-diagram-empty": ["задайте что-то одно: areas (с moment_scale и angle_scale_deg)"],
    "task2/case-diagram-work-per-cycle-with-areas": ["задаётся только вместе с "
                                                     "energy_fluctuation_coefficient"],
    "task2/case-diagram-crossings-with-delta-E": ["задаётся только с areas или energies (а не с "
                                                  "delta_E)"],
    "task2/case-diagram-areas-without-scale": ["не задано: для площадей нужны масштабы чертежа"],
    "task2/case-diagram-one-area": ["нужно не меньше двух площадей"],
    "task2/case-diagram-areas-close-only-in-mm2": ["сумма площадей -4.94066e-324, а не 0"],
    "task2/case-diagram-crossings-one-short": ["углов должно быть на один больше, чем площадей: 8 "
                                               "(задано 2)"],
    "task2/case-diagram-crossings-go-back": ["углы должны возрастать"],
    "task2/case-diagram-crossings-equal-in-radians": ["углы пересечений со средней линией должны "
                                                      "возрастать"],
    "task2/case-diagram-crossings-beyond-the-cycle": ["должны лежать в пределах 0…360°"],
    "task2/case-diagram-coefficient-without-work": ["нужна работа за цикл: задайте "
                                                    "diagram.work_per_cycle [Дж]"],
    "task2/case-diagram-power-with-omega0": ["для работы за цикл P·Φ/ω_ср нужна средняя "
                                             "скорость"],
    "task2/case-diagram-power-unused": ["здесь её ничто не использует"],
    "task2/case-points-plus-and-minus-1e308": ["work_driving — не конечное число (−inf + inf при "
                                               "суммировании)"],
    "task2/case-rim-radius-1e-300": ["результат — не конечное число (деление на ноль)"],
    "task2/case-at-option-with-a-diagram": ["задаёт диаграмму площадями, у неё нет моментов"],
    "task2/at-beyond-the-cycle": ["--at 400: должно лежать в пределах цикла 0…360°"],
    "task2/from-and-to-equal-in-radians": ["from (14.5°) должно быть меньше to (14.5°)"],
})
# --- msgs_run --- the run case's points, cylinders (a four-stroke diagram over the cycle) and
# firing order, the dynamics and the force analysis, files the system will not read or write
RUSSIAN_ERRORS.update({
    "run/point-fraction-with-distance": ["points.S3: `fraction` и `across` задаются с `to`, а не с"],
    "run/point-angle-with-to": ["points.S2: `angle_deg` задаётся с `distance`, а не с `to`"],
    "run/point-from-not-on-its-link": ["точка 'A' не лежит на звене 3 (его точки: B, D): точка, "
                                       "закреплённая на звене, строится по точкам"],
    "run/centroid-not-on-its-link": ["точка 'S2' не лежит на звене 3 (его точки: B, D, S3)"],
    "run/rod-length-missing": ["не задано: укажите rod_length или design.rod_to_crank"],
    "run/tabulated-with-ground": ["ground: не допускается вместе с [tabulated]: задайте массы"],
    "run/diagram-too-short": ["нужно не меньше 5 значений (0, 1, 0, 1, 0: четыре такта)"],
    "run/diagram-p-one-short": ["нужно 5 значений, по одному на каждое s (задано 4)"],
    "run/diagram-s-outside-the-stroke": ["1.5 выходит за пределы хода (допустимо: 0 … 1)"],
    "run/diagram-starts-off-the-head": ["0.5: диаграмма начинается в верхней мёртвой точке"],
    "run/diagram-steps-at-a-dead-centre": ["p/p_max меняется скачком с 0.1 до 0.5 при s = 1, где "
                                           "такт расширения кончается, а такт выпуска "
                                           "начинается: такты не смыкаются (скачок 0.4;"],
    "run/diagram-does-not-close": ["где такт сжатия кончается, а такт расширения начинался"],
    "run/diagram-ends-inside-a-stroke": ["обрывается внутри такта впуска (допустимо: s проходит"],
    "run/diagram-goes-back": ["0.3 после 0.5: на такте расширения s должно расти до 1"],
    "run/diagram-goes-on-after-the-cycle": ["продолжается после того, как такт сжатия замкнул"],
    "run/diagram-and-strokes": ["задайте что-то одно: diagram (одна таблица на весь цикл) или s"],
    "run/cylinder-s-missing": ["cylinders[0].s: не задано обязательное поле (или задайте diagram"],
    "run/cylinder-s-one-value": ["cylinders[0].s: нужно не меньше 2 значений"],
    "run/cylinder-s-short-of-1": ["должно охватывать [0, 1] (задано 0.0 … 0.95)"],
    "run/cylinder-one-table": ["не задано: укажите towards_head и away_from_head или strokes"],
    "run/two-table-cylinder-fires-at": ["задаётся только со strokes (четырёхтактной диаграммой)"],
    "run/two-tables-and-strokes": ["задайте что-то одно: towards_head и away_from_head"],
    "run/firing-order-unknown-cylinder": ["нет цилиндра '9' (четырёхтактные цилиндры: 1, 2, 3, 4)"],
    "run/firing-order-of-a-compressor": ["у цилиндра 'HP' нет четырёхтактной диаграммы",
                                         "(четырёхтактные цилиндры: нет)"],
    "run/firing-order-cylinder-twice": ["цилиндр '3' уже есть в порядке работы"],
    "run/firing-order-and-fires-at": ["machine.firing_order задаёт, где срабатывает цилиндр '2'"],
    "run/fires-at-far-from-a-dead-centre": ["cylinders[0].fires_at_deg: 100° отстоит на 100° от "
                                            "ближайшей верхней мёртвой точки поршня 3 (0°, 360°)"],
    "run/piston-that-does-not-move": ["у поршня 3 нет пары мёртвых положений"],
    "run/link-named-like-the-frame": ["силовой анализ: звено названо '0', а это имя стойки"],
    "run/no-inertia": ["у машины нет инерции: нагрузки не вызывают колебаний энергии"],
    "run/given-flywheel-vanishes-on-the-crank-shaft": ["у машины нет инерции (допустимо: "
                                                       "flywheel.J > 0"],
    "run/given-flywheel-and-no-fluctuation": ["заданный маховик (J = 1 кг·м²) не проверить: "
                                              "скорость не колеблется вовсе (δ = 0"],
    "run/tabulated-mass-out-of-range": ["tabulated.links.2.mass: 1e+308 кг вне допустимого "
                                        "диапазона (0 … 1e+06 кг)"],
    "run/case-path-through-a-file": ["не удаётся прочитать (часть пути — не папка)"],
    "run/out-name-too-long": ["не удаётся записать (слишком длинное имя файла)"],
    "grade/out-name-too-long": ["не удаётся записать (слишком длинное имя файла)"],
    "grade/gradebook-name-too-long": ["не удаётся записать (слишком длинное имя файла)"],
    "run/out-a-folder-where-a-file-goes": ["forces.csv — папка, а flywheel записывает туда файл"],
})
# English words that must not be left in a translated line (names the user gave aside)
ENGLISH = re.compile(r"\b(the|is|not|must|be|allowed|out|of|range|given|cannot|no|such|should|"
                     r"input|valid|missing|required|unknown|key|file|folder|number|use|this)\b")


def _entry(eid):
    return next(e for e in bad.load_catalogue() if e.id == eid)


@pytest.mark.parametrize("eid", sorted(RUSSIAN_ERRORS))
def test_errors_are_russian_with_lang_ru(eid, tmp_path):
    entry = _entry(eid)
    bad.build_files(entry, tmp_path)
    o = bad.invoke(replace(entry, args=[*entry.args, "--lang", "ru"]), tmp_path)
    assert o.code == 2 and o.stdout == "", o
    lines = o.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("ошибка: "), lines
    line = lines[0]
    for f in RUSSIAN_ERRORS[eid]:
        assert f in line, (f, line)
    # the entry's file and field path (its fragments that are no English words) are kept
    for f in entry.fragments:
        if re.search(r"\b[a-z]{2,}\b", re.sub(r"\S*[/.]\S*", "", f)):  # English words: files only
            for path in re.findall(r"\{(?:tmp|cases)\}\S*", f):
                assert bad.subst(path, tmp_path) in line, (path, line)
            continue
        f = bad.subst(f, tmp_path)
        if "/" in f or "." in f and " " not in f:
            assert f in line, (f, line)
    said = re.sub(r"\S*[/.]\S*|'[^']*'|`[^`]*`|\([a-z_, ]+\)$|--[a-z-]+", "", line)
    said = re.sub(r"допустимы: [\w, ]+", "", said)
    assert not ENGLISH.search(said), line


def test_the_error_language_comes_from_the_raw_arguments_too(tmp_path):
    """An error found before the command's options are parsed (no click context yet) takes the
    language from sys.argv: run in a subprocess."""
    res = subprocess.run([sys.executable, "-m", "flywheel", "run", str(tmp_path / "nope.toml"),
                          "--lang=ru"], capture_output=True, text=True)
    assert res.returncode == 2
    assert res.stderr == f"ошибка: {tmp_path / 'nope.toml'}: нет такого файла\n"
    res = subprocess.run([sys.executable, "-m", "flywheel", "run", str(tmp_path / "nope.toml")],
                         capture_output=True, text=True)
    assert res.stderr == f"error: {tmp_path / 'nope.toml'}: no such file\n"
    from flywheel.cli.guard import lang

    saved = sys.argv
    try:
        sys.argv = ["flywheel", "grade", "--lang", "ru"]
        assert lang() == "ru"
        sys.argv = ["flywheel", "grade", "--lang", "de"]
        assert lang() == "en"
    finally:
        sys.argv = saved


def test_an_english_error_is_unchanged_by_its_notice():
    """The English text of a translated error is byte for byte the old one."""
    from flywheel.errors import CaseFileError, led, said

    e = CaseFileError(led("c.toml: ", led("x: ", Notice("missing required field", "missing"))))
    assert str(e) == "c.toml: x: missing required field"
    assert nm.message(said(e), "ru") == "c.toml: x: не задано обязательное поле"
    assert nm.message(said(CaseFileError("plain")), "ru") == "plain"


def test_variants_and_grade_say_their_warnings_and_problems_in_russian(tmp_path):
    """`variants --lang ru`: the repeat warning, the seed and written lines; `grade --lang ru`:
    every problem of a sheet ("строка N: …") and the written line. English unchanged."""
    tpl = (CASES / "variants_task2.toml").read_text(encoding="utf-8")
    tpl = tpl[:tpl.index("\n[variants]") + 1] + ('[variants]\n"flywheel.J" = { values = [5.0, 8.0] }\n'
                                           'answers = ["M_C", "omega_max"]\n')
    (tmp_path / "t.toml").write_text(tpl, encoding="utf-8")
    args = ["variants", str(tmp_path / "t.toml"), "--count", "3", "--seed", "1"]
    en = runner.invoke(app, [*args, "--out", str(tmp_path / "en")])
    assert en.exit_code == 0, en.output
    assert "warning: only 2 different variants are possible; 3 asked, so some repeat" in en.stdout
    assert "seed 1 (the same seed gives the same files)" in en.stdout
    ru = runner.invoke(app, [*args, "--out", str(tmp_path / "v"), "--lang", "ru"])
    assert ru.exit_code == 0, ru.output
    text = " ".join(ru.stdout.split())
    assert ("предупреждение: различных вариантов возможно лишь 2; запрошено 3, поэтому некоторые "
            "повторяются") in text
    assert "seed 1 (тот же seed даёт те же файлы)" in text
    assert f"записано: {tmp_path / 'v'}/" in text
    sheet = tmp_path / "s.csv"
    sheet.write_text("student,variant,M_C,omega_max\nIvanov,01,90,abc\nPetrov,07,1,1\n"
                     "Sidorov,02,90,280\nSidorov,01,90,280\n,01,1,\n", encoding="utf-8")
    key = str(tmp_path / "v" / "answers.json")
    ru = runner.invoke(app, ["grade", key, str(sheet), "--lang", "ru", "--out",
                             str(tmp_path / "m.csv")])
    assert ru.exit_code == 0, ru.output
    out = " ".join(ru.stdout.split())
    assert f"{sheet}, строка 2: 'Ivanov': не число: omega_max = 'abc'; строка пропущена" in out
    assert f"{sheet}, строка 3: 'Petrov': вариант '07' отсутствует в ключе" in out
    assert f"{sheet}, строка 6: нет имени студента; строка пропущена" in out
    assert f"'Sidorov' встречается снова (впервые: {sheet}, строка 4)" in out
    assert f"записано: {tmp_path / 'm.csv'}" in out
    en = runner.invoke(app, ["grade", key, str(sheet)])
    assert f"{sheet}, row 2: 'Ivanov': not a number: omega_max = 'abc'; row skipped" in \
        " ".join(en.stdout.split())
    ru = runner.invoke(app, ["grade", key, str(tmp_path / "nope.csv"), "--lang", "ru"])
    assert ru.exit_code == 2
    assert ru.stderr == (f"ошибка: нечего проверить (замечаний: 1; первое: {tmp_path}/nope.csv: "
                         "нет такого файла или папки)\n")


def test_transients_reasons_are_russian(tmp_path):
    """--transients without [motor] on an engine: the start-up and run-down reasons in the
    summary and the report say in Russian why there is none (the loads drive: +work)."""
    out = tmp_path / "o"
    res = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--points", "720",
                              "--no-plots", "--transients", "--lang", "ru", "--report", "md",
                              "--out", str(out)])
    assert res.exit_code == 0, res.output
    text = " ".join(res.stdout.split())
    md = (out / "report.md").read_text(encoding="utf-8")
    for said in (text, md):
        assert "разгон: не рассчитан (в задании нет раздела [motor]" in said
        assert "выбега нет: нагрузки совершают за цикл положительную работу (+" in said
        assert "no [motor]" not in said and "positive work" not in said
    # English keeps its lines
    en = runner.invoke(app, ["run", str(CASES / "engine_4stroke.toml"), "--points", "720",
                             "--no-plots", "--transients", "--out", str(tmp_path / "e")])
    assert "start-up: not computed (no [motor] in the case" in " ".join(en.stdout.split())


def test_task2_report_of_an_unknown_driving_moment(tmp_path):
    """A task2 case whose driving moment comes from the cycle balance writes its report in both
    languages (it raised KeyError 'M_D' before)."""
    for lang, said in (("en", "gives M_D = 375 N·m"), ("ru", "даёт M_Д = 375 Н·м")):
        res = runner.invoke(app, ["task2", "--case", str(CASES / "task2_readme_press.toml"),
                                  "--out", str(tmp_path / lang), "--report", "md", "--lang", lang])
        assert res.exit_code == 0, res.output
        assert said in (tmp_path / lang / "report.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("case", ["fourbar", "shaper", "engine_inline4", "press"])
def test_check_speaks_russian(case):
    """`flywheel check --lang ru`: the tables' titles, headings and words in Russian (units
    "φ, °", "масса, кг"), the same numbers as in English; English unchanged by the option."""
    en = runner.invoke(app, ["check", str(CASES / f"{case}.toml")], terminal_width=200)
    ru = runner.invoke(app, ["check", str(CASES / f"{case}.toml"), "--lang", "ru"],
                       terminal_width=200)
    assert en.exit_code == 0 and ru.exit_code == 0, ru.output
    assert ru.stdout.rstrip().endswith("случай корректен")
    assert en.stdout.rstrip().endswith("case is valid")
    num = re.compile(r"(?<!\w)-?\d+(?:\.\d+)?(?:e[+-]?\d+)?")
    assert num.findall(ru.stdout) == num.findall(en.stdout)
    start = ru.stdout.index("частота вращения кривошипа")   # the title, source are the user's
    lines = ru.stdout[start:].splitlines()
    words = {w for ln in lines for w in re.findall(r"[A-Za-z]{4,}", ln)}
    assert words <= {"periodic", "spline", "pchip", "natural", "linear", "crank", "gearbox",
                     "head", "gear", "crankshaft", "punch", "cubic"}, words      # interpolations, the user's names


def test_balance_and_stopping_errors_are_russian(tmp_path):
    """Two errors students meet: loads whose work has the wrong sign for the balance, a
    machine that stops (task2)."""
    for eid, said in (("run/loads-give-negative-driving-moment",
                       "нагрузки совершают за цикл работу +731.25 Дж: постоянный движущий момент "
                       "должен был бы быть -116.382 Н·м ≤ 0"),
                      ("task2/case-speed-falls-to-zero",
                       "speed: машина останавливается при φ = 181.938°: кинетической энергии "
                       "½·J·ω0² = 1.5 Дж не хватает")):
        entry = _entry(eid)
        d = tmp_path / eid.replace("/", "_")
        d.mkdir()
        bad.build_files(entry, d)
        o = bad.invoke(replace(entry, args=[*entry.args, "--lang", "ru"]), d)
        assert o.code == 2 and o.stderr.startswith("ошибка: ") and said in o.stderr, o.stderr


def test_motion_option_error_is_russian(tmp_path):
    """`run --motion` with a motion that is not one: the English line unchanged, the Russian one
    Russian (no catalogue entry: the option is checked before any output)."""
    args = ["run", str(CASES / "fourbar.toml"), "--points", "360", "--no-plots", "--motion",
            "fast", "--out", str(tmp_path / "o")]
    en = runner.invoke(app, args)
    assert en.exit_code == 2
    assert en.stderr == "error: --motion: 'fast' is not a motion (allowed: true, steady)\n"
    ru = runner.invoke(app, [*args, "--lang", "ru"])
    assert ru.exit_code == 2
    assert ru.stderr == ("ошибка: --motion: 'fast' — недопустимое значение (допустимы: true, "
                         "steady)\n")


@pytest.mark.parametrize("edit, en_said, ru_said", [
    (("energy = 4000.0", "force = 4000.0"), "operation.thickness: missing: the force's travel",
     "operation.thickness: не задано: работу определяет путь силы (толщина листа)"),
    (("energy = 4000.0", "energy = 4000.0\nforce = 10.0"), "operation: give the work one way",
     "operation: задайте работу одним способом: energy, или energy_per_area"),
    (("energy = 4000.0", ""), "operation: missing: give the work of one operation",
     "operation: не задано: укажите работу одной операции"),
    (("angle_deg = 90", "angle_deg = 90\ncycle_share = 0.25"), "operation: give exactly one of",
     "operation: задайте что-то одно из: "),
    (("rim_diameter = 0.8", "J = 5.0\nmass = 10.0\nrim_diameter = 0.8"),
     "flywheel: give J or mass, not both", "flywheel: задайте что-то одно: J или mass"),
])
def test_duty_cycle_case_errors_are_russian(tmp_path, edit, en_said, ru_said):
    """The duty cycle's checks of the operation and the flywheel: English unchanged, Russian
    under --lang ru (one line, no English words)."""
    text = (CASES / "duty_readme_press.toml").read_text(encoding="utf-8").replace(*edit, 1)
    (tmp_path / "c.toml").write_text(text, encoding="utf-8")
    en = runner.invoke(app, ["duty-cycle", str(tmp_path / "c.toml")])
    assert en.exit_code == 2 and en.stderr.startswith(f"error: {tmp_path / 'c.toml'}: {en_said}")
    ru = runner.invoke(app, ["duty-cycle", str(tmp_path / "c.toml"), "--lang", "ru"])
    assert ru.exit_code == 2, ru.output
    lines = ru.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"ошибка: {tmp_path / 'c.toml'}: {ru_said}")
    said = re.sub(r"\S*[/.]\S*|'[^']*'|--[a-z-]+", "", lines[0])
    assert not ENGLISH.search(said), lines[0]


# --- msgs_cli --- the command-line parser's own errors, the interruption, an internal error
FLYWHEEL = str(Path(sys.executable).with_name("flywheel"))   # the console script: its name
USAGE_RU = [
    (["run", "CASE", "--foo"], "ошибка: flywheel run: нет такого параметра: --foo (похожие: "
     "--motion, --out) (см. flywheel run --help)"),
    (["run"], "ошибка: flywheel run: не задан аргумент 'case' (см. flywheel run --help)"),
    (["run", "CASE", "--points", "abc"], "ошибка: flywheel run: --points: должно быть целым "
     "числом (задано 'abc') (см. flywheel run --help)"),
    (["task2", "--md", "x"], "ошибка: flywheel task2: --md: должно быть числом (задано 'x') "
     "(см. flywheel task2 --help)"),
    (["bogus"], "ошибка: flywheel: нет такой команды: 'bogus' (см. flywheel --help)"),
    (["run", "CASE", "extra"], "ошибка: flywheel run: лишние аргументы: extra (см. flywheel run "
     "--help)"),
    (["run", "CASE", "--no-plots=3"], "ошибка: параметр --no-plots не принимает значения"),
]


@pytest.mark.parametrize("args,expected", USAGE_RU, ids=[" ".join(a) for a, _ in USAGE_RU])
def test_usage_errors_are_russian_and_english_is_the_parsers_own(args, expected):
    """The parser's errors (cli/usage.py) under --lang ru: one Russian line, exit 2, in a real
    process (the console script's main() says them); in English the parser's own words."""
    case = str(CASES / "compressor.toml")
    args = [case if a == "CASE" else a for a in args]
    ru = subprocess.run([FLYWHEEL, *args, "--lang", "ru"],
                        capture_output=True, text=True)
    assert ru.returncode == 2 and ru.stdout == ""
    assert ru.stderr == expected + "\n"
    en = subprocess.run([FLYWHEEL, *args], capture_output=True, text=True)
    assert en.returncode == 2 and en.stderr.startswith("error: ")
    assert len(en.stderr.splitlines()) == 1 and not re.search("[а-я]", en.stderr)


def test_a_value_of_an_option_given_last_is_still_said(capsys):
    """`--out` given last takes no value: the parser's BadOptionUsage (no command context)."""
    res = subprocess.run([FLYWHEEL, "run", str(CASES / "compressor.toml"),
                          "--lang", "ru", "--out"], capture_output=True, text=True)
    assert res.returncode == 2 and res.stderr == "ошибка: параметру --out нужно значение\n"


@pytest.mark.parametrize("lang,line", [("ru", "ошибка: прервано (Ctrl-C)\n"),
                                       ("en", "error: interrupted (Ctrl-C)\n")])
def test_the_interruption_line_is_said_in_the_users_language(monkeypatch, capsys, lang, line):
    import signal

    import flywheel.cli as cli

    def interrupted(*a, **k):
        raise cli.Stopped(signal.SIGINT)

    monkeypatch.setattr(cli, "app", interrupted)
    monkeypatch.setattr(signal, "signal", lambda *a: None)   # leave pytest's handlers alone
    monkeypatch.setattr(sys, "argv", ["flywheel", "run", "c.toml", "--lang", lang])
    with pytest.raises(SystemExit) as e:
        cli.main()
    assert e.value.code == 130 and capsys.readouterr().err == line


def test_an_internal_error_is_said_in_russian(monkeypatch, capsys):
    import signal

    import flywheel.cli as cli

    def broken(*a, **k):
        raise ZeroDivisionError("division by zero")

    monkeypatch.setattr(cli, "app", broken)
    monkeypatch.setattr(signal, "signal", lambda *a: None)
    monkeypatch.setattr(sys, "argv", ["flywheel", "run", "c.toml", "--lang", "ru"])
    with pytest.raises(SystemExit) as e:
        cli.main()
    err = capsys.readouterr().err
    assert e.value.code == 1 and err.startswith("ошибка: внутренняя ошибка flywheel ")
    assert "ZeroDivisionError: division by zero; пожалуйста, сообщите о ней" in err
    assert err.endswith("(--debug покажет трассировку)\n")
# --- msgs_duty ---
def test_variants_without_a_new_combination_and_a_students_infinity(tmp_path, monkeypatch):
    """`variants` that finds no new combination within its draws (fewer draws allowed here
    than the 2000 of the program, so that seed 4 draws the one variant again three times):
    English unchanged, Russian under --lang ru; a student's "inf" is no number."""
    from flywheel.teaching import grading, variants

    monkeypatch.setattr(variants, "MAX_DUPLICATE_DRAWS", 2)
    (tmp_path / "t.toml").write_text(
        "cycle_deg = 360\n\n[speed]\nomega0 = 200.0\n\n[flywheel]\nJ = 12.0\n\n[driving]\n"
        "kind = \"constant\"\nvalue = 15.0\n\n[resistance]\nkind = \"constant\"\nvalue = "
        "\"balance\"\n\n[variants]\n\"flywheel.J\" = { values = [10.0, 12.0] }\n"
        "answers = [\"omega_max\"]\n", encoding="utf-8")
    args = ["variants", str(tmp_path / "t.toml"), "--count", "2", "--seed", "4", "--out",
            str(tmp_path / "v")]
    en = runner.invoke(app, args)
    assert en.exit_code == 2 and en.stderr == (
        "error: variant 2: no new combination found in 2 draws; widen the ranges or ask for "
        "fewer variants\n")
    ru = runner.invoke(app, [*args, "--lang", "ru"])
    assert ru.exit_code == 2 and ru.stderr == (
        "ошибка: вариант 2: за 2 попытки не найдено новой комбинации; расширьте диапазоны или "
        "запросите меньше вариантов\n")
    assert not (tmp_path / "v").exists()
    with pytest.raises(ValueError) as exc:
        grading.parse_number("−inf")
    assert nm.message(exc.value.args[0], "ru") == "'−inf' — не конечное число"
    import errno

    unreadable = Notice("cannot be read (File name too long)", "sheet_unreadable",
                        reason="File name too long", errno=errno.ENAMETOOLONG)
    assert nm.message(unreadable, "ru") == "не удаётся прочитать (слишком длинное имя файла)"


def test_the_progress_bar_names_its_stages_in_the_users_language():
    """The stages the computations report (dynamics/stages.py, elastic/model.py) all have
    their Russian name; an unknown one stays as it is."""
    stages = set()
    for path in (SRC / "dynamics" / "stages.py", SRC / "elastic" / "model.py"):
        stages |= {b or a for a, b in re.findall(r'progress\("([^"]+)"|stage\("([^"]+)"\)',
                                                 path.read_text(encoding="utf-8"))}
    assert {"start-up", "run-down", "steady check"} <= stages
    for st in stages:
        assert nm.stage_name(st, "en") == st and re.search("[а-я]", nm.stage_name(st, "ru")), st
    assert nm.stage_name("anything", "ru") == "anything"
    # the teaching commands' bars: every stage they name is in the table, English as before
    named = re.findall(r'stage_name\("([^"]+)", lang\)',
                       (SRC / "cli" / "teaching.py").read_text(encoding="utf-8"))
    assert set(named) == {"variants", "task sheets", "answer sheets"}
    assert [nm.stage_name(n) for n in named] == ["variants", "sheets", "sheets"]
    assert all(re.search("[а-я]", nm.stage_name(n, "ru")) for n in named)


# every user error is a Notice: a raise of a FlywheelError, a FieldError or a validator's
# ValueError passes an errors.Notice (or a variable holding one), so --lang ru says it; an internal
# guard no command-line input reaches says so in a comment on the line above the raise
_USER_ERRORS = {"CaseFileError", "InputError", "AssemblyError", "FlywheelError", "ValueError",
                "DutyCycleError", "TableError", "SheetError", "NotFiniteError",
                "FieldError", "PydanticCustomError", "BadParameter"}
_LIBRARY_ONLY = "# library use only: no CLI input reaches this"


def _notice_builders() -> set[str]:
    """Names of the package's functions that return an errors.Notice (``needs_out``, …)."""
    names = set()
    for path in SRC.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef) and any(
                    isinstance(r, ast.Return) and r.value is not None
                    and "Notice(" in ast.unparse(r.value) for r in ast.walk(node)):
                names.add(node.name)
    return names


def _english_raises():
    """(file:line, source) of every raise of a user error whose message is a plain string."""
    builders = _notice_builders()
    for path in sorted(SRC.rglob("*.py")):
        text = path.read_text(encoding="utf-8")
        lines = text.splitlines()
        for node in ast.walk(ast.parse(text)):
            if not (isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call)):
                continue
            fn = node.exc.func
            kind = fn.id if isinstance(fn, ast.Name) else getattr(fn, "attr", "")
            if kind not in _USER_ERRORS or not node.exc.args:
                continue
            args = node.exc.args
            msg = args[1] if kind in ("FieldError", "TableError", "DutyCycleError", "NotFiniteError") and len(args) > 1 else args[0]
            called = msg.func.id if isinstance(msg, ast.Call) and isinstance(msg.func, ast.Name) \
                else ""
            if isinstance(msg, ast.Name) or called in builders or "Notice(" in ast.unparse(msg) \
                    or "led(" in ast.unparse(msg):
                continue
            if lines[node.lineno - 2].strip() == _LIBRARY_ONLY:
                continue
            yield f"{path.relative_to(SRC)}:{node.lineno}", ast.unparse(msg)[:100]


def test_every_user_error_is_raised_with_a_notice():
    left = list(_english_raises())
    assert not left, "\n".join(f"{w}: {m}" for w, m in left)


@pytest.mark.parametrize("text", ["a = 1,5", "[a\nb = 1", "a = [1, 2", "= 3", "a = 1\na = 2",
                                  "a = \"x", "[t]\n[t]", "a = tru", "a = {b = 1, b = 2}",
                                  "a = \"\\q\"", "[[a]\n", "a = 1979-13-01"])
def test_tomllibs_own_words_are_said_in_russian(text):
    """Every message Python 3.11's tomllib raises has its Russian form (render/nomenclature.py
    _TOML_RU); its place «(строка N, столбец M)» or «(в конце документа)»."""
    import tomllib

    with pytest.raises(tomllib.TOMLDecodeError) as e:
        tomllib.loads(text)
    ru = library_ru.toml_detail_ru(str(e.value))
    assert not re.search(r"[A-Za-z]{3,}", re.sub(r"'[^']*'|\([^)]*'[^)]*\)", "", ru)), ru
    assert re.search(r"\((строка \d+, столбец \d+|в конце документа)\)$", ru), ru


@pytest.mark.parametrize("text", ['{a:1}', '{"a" 1}', '[1 2]', '', '{} x', '"abc', '"a\\qb"',
                                  '"\\u12"', '"a\tb"'])
def test_jsons_own_words_are_said_in_russian(text):
    import json

    with pytest.raises(json.JSONDecodeError) as e:
        json.loads(text)
    ru = library_ru.said_ru(e.value.msg, library_ru.JSON_RU)
    assert ru != e.value.msg and not re.search(r"[A-Za-z]{4,}", ru.replace("escape", "").replace("uXXXX", "")), ru
