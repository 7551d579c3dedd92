"""`flywheel variants … --sheets`: one printable task sheet per variant (HTML and a one-page
PDF, and sheets.pdf with them all) carrying the variant's own values with units, the answers
asked with their units and the grader's tolerances — and no answer, no command; the same bytes
on a rerun; Russian and English; run (compressor) and task2 templates; a tabulated template
gets sheets without a drawing and one note line."""
import json
import re
import tomllib
from html.parser import HTMLParser
from pathlib import Path

import pytest
from typer.testing import CliRunner

from flywheel.cli import app
from helpers import err_text  # a CliRunner result's stderr (tests/helpers.py)
from helpers import ru_numbers  # a Russian text's numbers (tests/helpers.py)

CASES = Path(__file__).resolve().parents[2] / "cases"
COMPRESSOR = CASES / "variants_compressor.toml"
TASK2 = CASES / "variants_task2.toml"
runner = CliRunner()


def invoke(*args):
    return runner.invoke(app, ["variants", *map(str, args)])



class Sheet(HTMLParser):
    """The text of a sheet as a person reads it: the tables' rows (cells), the paragraphs, the
    headings; images counted. Attributes (the embedded PNG) are not text. A subscript
    (<sub>нб</sub>) is read back in the underscore notation ("ΔT_нб")."""

    def __init__(self, html: str):
        super().__init__()
        self.tables: list[list[list[str]]] = []
        self.captions: list[str] = []
        self.paragraphs: list[str] = []
        self.headings: list[str] = []
        self.images = 0
        self._cell: list[str] | None = None
        self._text: list[str] | None = None
        self._where = ""
        self.feed(html)

    def handle_starttag(self, tag, attrs):
        if tag == "table":
            self.tables.append([])
        elif tag == "tr":
            self.tables[-1].append([])
        elif tag in ("td", "th"):
            self._cell = []
        elif tag in ("p", "h1", "h2", "figcaption"):
            self._text, self._where = [], tag
        elif tag == "img":
            self.images += 1
        elif tag == "sub":
            self.handle_data("_")

    def handle_endtag(self, tag):
        if tag in ("td", "th") and self._cell is not None:
            self.tables[-1][-1].append("".join(self._cell).strip())
            self._cell = None
        elif tag in ("p", "h1", "h2", "figcaption") and self._text is not None:
            text = "".join(self._text).strip()
            {"p": self.paragraphs, "figcaption": self.captions}.get(tag, self.headings).append(text)
            self._text = None

    def handle_data(self, data):
        if self._cell is not None:
            self._cell.append(data)
        if self._text is not None:
            self._text.append(data)

    @property
    def text(self) -> str:
        return "\n".join([*self.headings, *self.paragraphs, *self.captions,
                          *("\t".join(r) for t in self.tables for r in t)])


def pages(pdf: bytes) -> int:
    return len(re.findall(rb"/Type\s*/Page\b", pdf))


@pytest.fixture(scope="module")
def compressor_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("s") / "compressor"
    res = invoke(COMPRESSOR, "--count", 3, "--seed", 11, "--out", out, "--sheets", "--lang", "ru")
    assert res.exit_code == 0, res.output
    return out


@pytest.fixture(scope="module")
def task2_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("s") / "task2"
    res = invoke(TASK2, "--count", 4, "--seed", 5, "--out", out, "--sheets", "--lang", "en")
    assert res.exit_code == 0, res.output
    return out


def key_of(folder: Path) -> dict:
    return json.loads((folder / "answers.json").read_text(encoding="utf-8"))


def sheet_of(folder: Path, vid: str) -> Sheet:
    return Sheet((folder / "sheets" / f"variant_{vid}.html").read_text(encoding="utf-8"))


def numbers(cell: str) -> list[float]:
    return [float(x) for x in re.findall(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?", cell)]


@pytest.mark.parametrize("which", ["compressor_dir", "task2_dir"])
def test_one_sheet_per_variant_html_and_one_page_pdf(request, which):
    folder = request.getfixturevalue(which)
    key = key_of(folder)
    stems = sorted(p.stem for p in folder.glob("variant_*.toml"))
    assert stems == [f"variant_{v}" for v in key["variants"]]
    assert sorted(p.name for p in (folder / "sheets").iterdir()) == sorted(
        [f"{s}.html" for s in stems] + [f"{s}.pdf" for s in stems])
    for s in stems:
        pdf = (folder / "sheets" / f"{s}.pdf").read_bytes()
        assert pdf.startswith(b"%PDF") and pages(pdf) == 1          # one A4 page each
        assert sheet_of(folder, s.split("_")[1]).images == 1        # the drawing, inline
    assert pages((folder / "sheets.pdf").read_bytes()) == len(stems)   # the class set


def test_the_sheet_carries_the_variants_own_values(compressor_dir):
    key = key_of(compressor_dir)
    for vid, drawn in key["drawn"].items():
        sh = sheet_of(compressor_dir, vid)
        given, other = sh.tables[0], sh.tables[1]
        assert given[0] == ["Величина", "Значение", "Ед. изм."]
        # the drawn values, in the template's order, each with its unit
        # (the pressure in MPa, as the course gives it: seed 000's p_max2 = 0.882 MPa)
        expected = [v / 1e6 if path.endswith("p_max") else v for path, v in drawn.items()]
        assert [ru_numbers(r[1])[0] for r in given[1:]] == pytest.approx(expected, rel=1e-9)
        assert [r[2] for r in given[1:]] == ["об/с", "—", "кг", "кг", "МПа", "м"]
        # the fixed data a student needs, from the variant file itself
        doc = tomllib.loads((compressor_dir / f"variant_{vid}.toml").read_text(encoding="utf-8"))
        rows = {r[0]: r[1:] for r in other[1:]}
        assert rows["Масса звена 5 m_5"] == [("%g" % doc["links"]["5"]["mass"]).replace(".", ","),
                                             "кг"]
        assert rows["Плотность материала маховика ρ"] == ["7800", "кг/м³"]
        assert ru_numbers(rows["Цилиндр НД: p/p_max при движении поршня к головке"][0]) == \
            doc["cylinders"][1]["towards_head"]
        assert rows["Момент инерции редуктора (приведённый к кривошипу) J_ред"] == ["0,074", "кг·м²"]


def test_the_find_list_is_worded_as_a_task_with_units_and_tolerances(compressor_dir, task2_dir):
    sh = sheet_of(compressor_dir, "1".zfill(2))
    items = [p for p in sh.paragraphs if re.match(r"\d+\. ", p)]
    assert len(items) == len(key_of(compressor_dir)["answers"])
    assert "4. Определить момент инерции маховика J_М, кг·м² (допуск ±1 %)." in items
    assert "5. Определить наружный диаметр маховика в виде сплошного диска D, м (допуск ±2 %)." \
        in items                                    # the per-answer tolerance of the template
    en = [p for p in sheet_of(task2_dir, "01").paragraphs if re.match(r"\d+\. ", p)]
    assert en[0] == "1. Determine the resistance moment M_C [N·m]; accepted within ±1 %."
    assert en[1] == ("2. Determine the greatest angular velocity ω_max [rad/s]; accepted within "
                     "±0.05 %.")                   # tolerances.omega_max = 5e-4


@pytest.mark.parametrize("which", ["compressor_dir", "task2_dir"])
def test_no_answer_and_no_command_on_a_sheet(request, which):
    folder = request.getfixturevalue(which)
    key = key_of(folder)
    for vid, answers in key["variants"].items():
        sh = sheet_of(folder, vid)
        text = sh.text
        data = [x for t in sh.tables for r in t[1:] for x in numbers(r[1])]
        for value in answers.values():
            spellings = {repr(value), "%.6g" % value}
            # an answer that is close to a datum (ω_max to ω0 within 0.1 %) is checked at 6
            # digits only: its rounder spellings are the datum's
            if not any(abs(value - d) <= 1e-3 * abs(value) for d in data):
                spellings |= {"%.4g" % value, "%.5g" % value}
            for spelled in spellings:
                if len(spelled.replace("-", "").replace(".", "")) >= 3:
                    assert spelled not in text, (vid, spelled)
        assert "flywheel" not in text and "solve" not in text.lower()
        assert ".toml" not in text


def test_the_pdf_carries_the_same_values_and_no_answer(tmp_path):
    """The PDF is typst's: its source, and the text read back from the PDFs (pypdf), hold the
    Russian headings, the variant's number, its drawn values and worded text data, and none of
    the answers; the class set sheets.pdf has each variant on its own page."""
    import pypdf

    from flywheel.render.sheets import build_sheet, sheet_typst
    from flywheel.teaching.sheets import sheets_of
    from flywheel.teaching.variants import generate, load_template

    vs = generate(load_template(COMPRESSOR), 2, 11)
    for v, s in zip(vs.variants, sheets_of(vs)):
        src = sheet_typst(build_sheet(s, "ru", "x.png"))
        for path, value in v.drawn.items():
            value = value / 1e6 if path.endswith("p_max") else value     # a pressure in MPa
            assert f'[#"{"%.6g" % value}"]' in src, (path, value)
        for value in v.answers.values():
            assert "%.5g" % value not in src
    out = tmp_path / "v"
    assert invoke(COMPRESSOR, "--count", 2, "--seed", 11, "--out", out, "--sheets",
                  "--sheets-format", "pdf", "--lang", "ru").exit_code == 0
    key = key_of(out)
    combined = pypdf.PdfReader(out / "sheets.pdf").pages
    assert len(combined) == 2
    for n, v in enumerate(vs.variants, 1):
        assert key["drawn"][v.id] == pytest.approx(v.drawn, rel=1e-12)    # the same variants
        pages_of = pypdf.PdfReader(out / "sheets" / f"variant_{v.id}.pdf").pages
        assert len(pages_of) == 1
        for text in (pages_of[0].extract_text(), combined[n - 1].extract_text()):
            lines = text.splitlines()
            assert lines[0] == f"Вариант {n}"
            assert {"Дано", "Задание", "Таблица 1\u00a0— Данные варианта"} <= set(lines)
            assert any(ln.startswith("Студент ___") and "Группа ___" in ln for ln in lines)
            for path, value in v.drawn.items():         # in Russian typography
                value = value / 1e6 if path.endswith("p_max") else value     # MPa
                assert value in ru_numbers(text), (n, value)
            assert "Направление вращения кривошипа по часовой стрелке" in text
            assert "Плотность материала маховика ρ 7800 кг/м³" in text
            assert "(допуск ±2 %)" in text and "Определить момент инерции маховика" in text
            for value in key["variants"][v.id].values():
                assert ("%.4g" % value).replace(".", ",") not in text


def test_byte_identical_on_rerun(tmp_path, compressor_dir):
    out = tmp_path / "again"
    res = invoke(COMPRESSOR, "--count", 3, "--seed", 11, "--out", out, "--sheets", "--lang", "ru")
    assert res.exit_code == 0, res.output
    for f in [*(compressor_dir / "sheets").iterdir(), compressor_dir / "sheets.pdf"]:
        rel = f.relative_to(compressor_dir)
        assert (out / rel).read_bytes() == f.read_bytes(), rel


def test_russian_and_english_wording(compressor_dir, task2_dir, tmp_path):
    ru = sheet_of(compressor_dir, "02")
    assert ru.headings[:3] == ["Вариант 2", "Дано", "Задание"]
    assert any(p.startswith("Студент ____") and "Группа ____" in p for p in ru.paragraphs)
    assert ru.captions == ["Рис. 1\u00a0— Кинематическая схема механизма при φ = 120°"]
    # a point's coordinates set apart as its value is, «0; 0,15» under «(x; y)», not «(x, y)»
    points = [r for t in ru.tables for r in t if "(x; y)" in r[0]]
    assert points and all("; " in r[1] for r in points)
    assert not any("(x, y)" in r[0] for t in ru.tables for r in t)
    en = sheet_of(task2_dir, "03")
    assert en.headings[:3] == ["Variant 3", "Given", "Task"]
    assert any(p.startswith("Student ____") and "Group ____" in p for p in en.paragraphs)
    assert en.captions == ["Figure 1\u00a0— The given moment graphs M_D(φ) and M_C(φ)"]
    # the same task2 variants in Russian: the course's symbols
    out = tmp_path / "ru"
    assert invoke(TASK2, "--count", 1, "--seed", 5, "--out", out, "--sheets",
                  "--lang", "ru").exit_code == 0
    sh = sheet_of(out, "01")
    assert sh.captions == ["Рис. 1\u00a0— Заданные графики моментов M_Д(φ) и M_С(φ)"]
    assert sh.paragraphs[-6] == "1. Определить момент сопротивления M_С, Н·м (допуск ±1 %)."


def test_task2_sheet_gives_the_graphs_data(task2_dir):
    key = key_of(task2_dir)
    for vid, drawn in key["drawn"].items():
        sh = sheet_of(task2_dir, vid)
        rows = {r[0]: r[1:] for r in sh.tables[0][1:]}
        assert rows["Angular velocity at φ = 0, ω0"] == ["%g" % drawn["speed.omega0"], "rad/s"]
        assert rows["Driving moment M_D"] == ["%g" % drawn["driving.value"], "N·m"]
        assert rows["M_C: start of its graph"] == ["%g" % drawn["resistance.from_deg"], "°"]
        other = {r[0]: r[1:] for r in sh.tables[1][1:]}
        assert other["Allowed coefficient of speed fluctuation [δ]"] == ["0.05", "—"]


def test_tabulated_template_sheets_without_drawing_one_note(tmp_path):
    template = tmp_path / "press_variants.toml"
    template.write_text((CASES / "press.toml").read_text(encoding="utf-8")
                        + '\n[variants]\n"machine.delta" = { values = [0.04, 0.05, 0.06] }\n'
                        'answers = ["J_required"]\n', encoding="utf-8")
    out = tmp_path / "v"
    res = invoke(template, "--count", 3, "--seed", 1, "--out", out, "--sheets",
                 "--sheets-format", "html", "--lang", "ru")
    assert res.exit_code == 0, res.output
    notes = [ln for ln in err_text(res).splitlines() if "sheet" in ln]
    assert len(notes) == 1 and notes[0].startswith("примечание: --sheets: ")   # --lang ru
    assert "таблицей" in notes[0] and "нет чертежа механизма" in notes[0]
    for vid in ("1", "2", "3"):
        sh = sheet_of(out, vid.zfill(2))
        assert sh.images == 0 and sh.captions == []
        assert sh.headings[0] == f"Вариант {vid}"
    assert not (out / "sheets.pdf").exists()          # html only


def test_without_sheets_nothing_changes(tmp_path, compressor_dir):
    out = tmp_path / "plain"
    assert invoke(COMPRESSOR, "--count", 3, "--seed", 11, "--out", out).exit_code == 0
    assert not (out / "sheets").exists() and not (out / "sheets.pdf").exists()
    for f in out.glob("*.*"):
        if f.name != ".flywheel-manifest.json":
            assert f.read_bytes() == (compressor_dir / f.name).read_bytes()


def test_the_default_language_is_english_as_every_other_command(tmp_path):
    out = tmp_path / "en"
    assert invoke(TASK2, "--count", 1, "--seed", 5, "--out", out, "--sheets",
                  "--sheets-format", "html").exit_code == 0
    sh = sheet_of(out, "01")
    assert sh.headings[:3] == ["Variant 1", "Given", "Task"]


def test_symbols_are_typeset_with_subscripts_not_underscores(compressor_dir):
    """M_Д, ΔT_нб, J_I, J_М, p_max: a subscript in the HTML (<sub>) and in the PDF's typst
    source (#sub[…]), never a literal underscore in what a student reads."""
    from flywheel.render.sheets import build_sheet, sheet_typst
    from flywheel.teaching.sheets import sheets_of
    from flywheel.teaching.variants import generate, load_template

    page = (compressor_dir / "sheets" / "variant_01.html").read_text(encoding="utf-8")
    for sym in ("M<sub>Д</sub>", "ΔT<sub>нб</sub>", "J<sub>I</sub>", "J<sub>М</sub>",
                "p/p<sub>max</sub>", "m<sub>5</sub>", "J<sub>S2</sub>"):
        assert sym in page, sym

    class Visible(Sheet):                   # the text as printed: no underscore added back
        def handle_starttag(self, tag, attrs):
            if tag != "sub":
                super().handle_starttag(tag, attrs)

    assert "_" not in re.sub(r"_{2,}", "", Visible(page).text)     # the name line's blanks aside
    s = sheets_of(generate(load_template(COMPRESSOR), 1, 11))[0]
    for lang in ("ru", "en"):
        src = sheet_typst(build_sheet(s, lang, "x.png"))
        body = src.split("\n\n", 1)[1]
        assert '#sub[#"max"]' in body and "\ue000" not in body and "\ue001" not in body
        assert "_" not in re.sub(r"_{2,}", "", body), lang


def test_engine_and_shaper_sheets_name_every_field(tmp_path):
    """The four-stroke template's stroke tables and firing angle and the shaper's fixed pivot
    have names on the sheet, not the case file's dotted paths."""
    for name in ("variants_engine.toml", "variants_shaper.toml"):
        out = tmp_path / name
        assert invoke(CASES / name, "--count", 1, "--seed", 2, "--out", out, "--sheets",
                      "--sheets-format", "html", "--lang", "ru").exit_code == 0
        sh = sheet_of(out, "01")
        labels = [r[0] for t in sh.tables for r in t[1:]]
        assert not [x for x in labels if re.fullmatch(r"[\w.]+", x) and "." in x], labels
    engine = sheet_of(tmp_path / "variants_engine.toml", "01")
    labels = [r[0] for t in engine.tables for r in t[1:]]
    assert "Цилиндр 1: p/p_max на такте сжатия" in labels
    assert "Цилиндр 1: воспламенение при φ" in labels
    items = [p for p in sheet_of(tmp_path / "variants_shaper.toml", "01").paragraphs
             if re.match(r"\d+\. ", p)]
    assert "4. Определить момент инерции маховика на его валу J_М/i², кг·м² (допуск ±1 %)." \
        in items                                 # the symbol once


def rows_of(sh: Sheet) -> dict[str, list[str]]:
    """label → [value, unit] over both data tables."""
    return {r[0]: r[1:] for t in sh.tables for r in t[1:]}


def test_text_data_are_on_the_sheet_in_words(tmp_path):
    """A four-stroke engine's firing order, each cylinder's head, the crank's rotation and
    which constant moment the cycle balance finds are data a student needs: on the sheet, in
    words (the firing order as engines write it), not as the case file spells them."""
    template = tmp_path / "inline4_variants.toml"
    template.write_text((CASES / "engine_inline4.toml").read_text(encoding="utf-8")
                        + '\n[variants]\n"machine.delta" = { values = [0.008, 0.01] }\n'
                        'answers = ["J_required"]\n', encoding="utf-8")
    for lang, order, head, turn, balance in (
            ("ru", "Порядок работы цилиндров", "Цилиндр 3: мёртвая точка у головки",
             ["Направление вращения кривошипа", "по часовой стрелке"],
             ["Постоянный момент, определяемый из условия цикла", "момент сопротивления M_С"]),
            ("en", "Firing order of the cylinders", "Cylinder 3: dead centre at the head",
             ["Direction of the crank's rotation", "clockwise"],
             ["The constant moment, found from the cycle balance",
              "the resistance moment M_C"])):
        out = tmp_path / lang
        res = invoke(template, "--count", 1, "--seed", 1, "--out", out, "--sheets",
                     "--sheets-format", "html", "--lang", lang)
        assert res.exit_code == 0, res.output
        rows = rows_of(sheet_of(out, "01"))
        assert rows[order] == ["1-3-4-2", "—"]
        assert rows[head][0] == ("внешняя (дальняя от оси кривошипа)" if lang == "ru"
                                 else "outer (farther from the crank axis)")
        assert rows[turn[0]] == [turn[1], "—"]
        assert rows[balance[0]] == [balance[1], "—"]
        # the element names and the computing choices are not data of the task
        values = [v[0] for v in rows.values()]
        assert not {"outer", "cw", "resistance", "RRP", "p1", "r1"} & set(values)
    shaper = tmp_path / "shaper"
    assert invoke(CASES / "variants_shaper.toml", "--count", 1, "--seed", 2, "--out", shaper,
                  "--sheets", "--sheets-format", "html", "--lang", "ru").exit_code == 0
    rows = rows_of(sheet_of(shaper, "01"))
    assert rows["Материал маховика"] == ["чугун", "—"]
    assert rows["Сила F_пс: действует при движении ползуна"] == ["к этой мёртвой точке", "—"]
    assert rows["Сила F_пс: мёртвая точка начала отсчёта перемещения s"][0] == \
        "внешняя (дальняя от оси кривошипа)"
    # a force's magnitude is worded as its other rows are (its label the subscript of F)
    assert [k for k in rows if k.startswith("Сила F_пс")][0] == "Сила F_пс: модуль F"


def test_flywheel_J_is_worded_by_the_case_kind(tmp_path):
    """flywheel.J of a `flywheel run` case is the given flywheel's J on its own shaft (J_M, or
    J_M/i² on a shaft of speed ratio i); of a task2 case, the reduced moment of inertia of the
    whole machine (docs/case-format.md, docs/task2.md)."""
    text = (CASES / "compressor_given_flywheel.toml").read_text(encoding="utf-8")
    variants = '\n[variants]\n"flywheel.J" = { values = [3.0, 4.0, 5.0] }\nanswers = ["delta"]\n'
    labels = {}
    for name, body in (("given", text), ("geared", text.replace(
            "[flywheel]                       # given", "[flywheel]\nspeed_ratio = 2.0\n#", 1))):
        assert body != text or name == "given"
        template = tmp_path / f"{name}.toml"
        template.write_text(body + variants, encoding="utf-8")
        for lang in ("ru", "en"):
            out = tmp_path / f"{name}-{lang}"
            res = invoke(template, "--count", 1, "--seed", 3, "--out", out, "--sheets",
                         "--sheets-format", "html", "--lang", lang)
            assert res.exit_code == 0, res.output
            sh = sheet_of(out, "01")
            labels[name, lang] = sh.tables[0][1][0]
            assert sh.tables[0][1][1:] == ["%g" % key_of(out)["drawn"]["01"]["flywheel.J"],
                                           "кг·м²" if lang == "ru" else "kg·m²"]
    assert labels == {("given", "ru"): "Момент инерции заданного маховика J_М",
                      ("given", "en"): "Moment of inertia of the given flywheel J_M",
                      ("geared", "ru"): "Момент инерции заданного маховика на его валу J_М/i²",
                      ("geared", "en"): "Moment of inertia of the given flywheel on its own "
                                        "shaft J_M/i²"}
    out = tmp_path / "task2"
    assert invoke(TASK2, "--count", 1, "--seed", 5, "--out", out, "--sheets",
                  "--sheets-format", "html", "--lang", "ru").exit_code == 0
    assert rows_of(sheet_of(out, "01"))["Приведённый момент инерции J_пр"][1] == "кг·м²"


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_every_field_of_every_bundled_case_has_a_name(lang):
    """Every datum a sheet would show of every bundled run and task2 case (a [tabulated]
    table's aside, docs/teacher.md) has a label, not its dotted path, and every text datum is
    in words of ``lang``."""
    from flywheel.render import nomenclature as nm, sheet_labels
    from flywheel.teaching.sheets import element_names, given_rows

    seen_text = set()
    for path in sorted(CASES.glob("*.toml")):
        if path.name.startswith(("aggregate", "duty", "variants")):
            continue
        doc = tomllib.loads(path.read_text(encoding="utf-8"))
        kind = "task2" if path.name.startswith("task2") else "run"
        names = element_names(doc)
        for g in given_rows(kind, doc, []):
            if g.path.startswith("tabulated."):
                continue
            label = sheet_labels.field_label(g.path, lang, names, (kind,))
            assert label != g.path and not re.fullmatch(r"[\w.]+", label), (path.name, g.path)
            first = g.value[0] if isinstance(g.value, tuple) else g.value
            if isinstance(first, str):
                pattern = re.sub(r"\.\d+\.", ".#.", g.path)
                seen_text.add(pattern)
                words = sheet_labels.field_value(g.path, g.value, lang)
                if pattern != "machine.firing_order":      # names: as the case file has them
                    assert g.value in sheet_labels.SHEET_VALUES[pattern], (path.name, g.path)
                    assert lang == "en" or re.search("[а-я]", words), (path.name, words)
    assert seen_text == {"machine.firing_order", "machine.balance", "crank.rotation",
                         "cylinders.#.head", "flywheel.material", "forces.#.reference",
                         "forces.#.stroke"}


def test_the_sheet_gives_the_defaults_a_flywheels_diameter_needs(tmp_path):
    """The engine template asks flywheel_disk.D but leaves the material out (cases/run.py's
    default: steel, ρ = 7800 kg/m³): the sheet gives ρ and b/D, and from them and the key's
    J_flywheel a student's D = (32·J/(π·ρ·b/D))^(1/5) (a solid disk) is the key's D. The
    compressor template gives its density: no second row."""
    out = tmp_path / "e"
    res = invoke(CASES / "variants_engine.toml", "--count", 2, "--seed", 3, "--out", out,
                 "--sheets", "--sheets-format", "html", "--lang", "en")
    assert res.exit_code == 0, res.output
    key = key_of(out)["variants"]
    for vid, answers in key.items():
        rows = {r[0]: r for t in sheet_of(out, vid).tables for r in t}
        (rho,) = [numbers(r[1])[0] for label, r in rows.items() if "Density" in label]
        (ratio,) = [numbers(r[1])[0] for label, r in rows.items() if "b/D" in label]
        assert rho == 7800.0
        D = (32 * answers["J_flywheel"] / (3.141592653589793 * rho * ratio)) ** 0.2
        assert D == pytest.approx(answers["flywheel_disk.D"], rel=1e-9)
    res = invoke(COMPRESSOR, "--count", 1, "--seed", 3, "--out", tmp_path / "c", "--sheets",
                 "--sheets-format", "html", "--lang", "en")
    rows = [r[0] for t in sheet_of(tmp_path / "c", "01").tables for r in t]
    assert sum("Density" in label for label in rows) == 1


def test_a_flywheels_proportion_no_answer_needs_is_not_on_the_sheet(tmp_path):
    """The compressor template gives the rim's D₁/D but asks a solid disk's D: «D₁/D = 0,8»
    beside «a solid disk D» read as a contradiction; it is given where a rim is asked, and ρ,
    b/D only where a flywheel's dimension is."""
    text = COMPRESSOR.read_text(encoding="utf-8")
    assert "inner_ratio = 0.8" in text and '"flywheel_disk.D"' in text
    variants = [("disk", text),
                ("rim", text.replace('"flywheel_disk.D"]', '"flywheel_rim.D"]')),
                ("none", text.replace(', "flywheel_disk.D"]', ']'))]
    for name, template in variants:
        path = tmp_path / f"{name}.toml"
        path.write_text(template.replace('tolerances = { "flywheel_disk.D" = 0.02 }', ""),
                        encoding="utf-8")
        res = invoke(path, "--count", 1, "--seed", 3, "--out", tmp_path / name, "--sheets",
                     "--sheets-format", "html", "--lang", "en")
        assert res.exit_code == 0, res.output
        rows = [r[0] for t in sheet_of(tmp_path / name, "01").tables for r in t]
        assert sum("D1/D" in label for label in rows) == (name == "rim"), (name, rows)
        assert sum("Density" in label for label in rows) == (name != "none"), (name, rows)
        assert sum("b/D" in label for label in rows) == (name != "none"), (name, rows)


def test_the_title_is_in_the_sheets_language(compressor_dir, task2_dir):
    """A template's title given in both languages ({ ru, en }, as the bundled cases give
    theirs) is on each sheet in the sheet's language."""
    ru = sheet_of(compressor_dir, "01")
    assert ru.paragraphs[0] == "Двухступенчатый V-образный воздушный компрессор"
    en = sheet_of(task2_dir, "01")
    assert en.paragraphs[0] == "«Задача 2», task 1: triangular resistance moment"


@pytest.mark.parametrize("template, kind_ru", [
    (COMPRESSOR, "Динамический анализ машины"),
    (TASK2, "Движение машины с постоянным приведённым моментом инерции")])
def test_an_english_only_title_gives_way_to_the_tasks_russian_name(template, kind_ru, tmp_path):
    """A template whose title is an English string only: the Russian sheet carries the Russian
    name of the kind of task (the catalogue's), never the English words; the English sheet keeps
    the template's title."""
    text = template.read_text(encoding="utf-8")
    # the case's own title (the first; the loads' titles come later)
    text, n = re.subn(r"(?m)^title\s*=\s*\{[^}]*en = (\"[^\"]*\") \}$", r"title = \1", text,
                      count=1)
    assert n == 1
    (tmp_path / "t.toml").write_text(text, encoding="utf-8")
    english = tomllib.loads(text)["title"]
    for lang in ("ru", "en"):
        out = tmp_path / lang
        res = invoke(tmp_path / "t.toml", "--count", 1, "--seed", 3, "--out", out, "--sheets",
                     "--sheets-format", "html", "--lang", lang)
        assert res.exit_code == 0, res.output
        title = sheet_of(out, "01").paragraphs[0]
        assert title == (kind_ru if lang == "ru" else english)
        if lang == "ru":
            assert not re.search(r"[A-Za-z]{2,}", title)


def test_a_russian_sheet_names_the_first_groups_parts_in_russian():
    """«момент инерции: crankshaft» was printed on a Russian sheet: a part the catalogue knows
    is named in Russian, in the genitive its label needs (render/sheet_labels.py PART_OF), with
    the course's symbol where it has one (seed 000: J_10 the crankshaft's, J_ред the
    gearbox's, as J_М = J_I − (J_10 + J_ред) names them); a part of the case's own naming stays
    as written."""
    from flywheel.render.sheet_labels import field_label

    assert field_label("machine.first_group.crankshaft", "ru") == \
        "момент инерции коленчатого вала (приведённый к кривошипу) J_10"
    assert field_label("machine.first_group.gearbox", "ru") == \
        "момент инерции редуктора (приведённый к кривошипу) J_ред"
    assert field_label("machine.first_group.flywheel", "ru") == \
        "момент инерции маховика (приведённый к кривошипу)"
    for part in ("crankshaft", "gearbox", "flywheel"):
        assert part in field_label(f"machine.first_group.{part}", "en")
    assert "my_part" in field_label("machine.first_group.my_part", "ru")


def test_the_drawings_letters_print_at_a_readable_size():
    """The linkage is drawn at about its printed size (render/sheets.py IMAGE_MM high on the
    sheet): every letter of it — tick labels, the joints' names, the links' numbers — prints at
    6.5 pt or more (drawn at 6 × 4.6 in and printed 52 mm high, the tick labels had printed at
    4 pt)."""
    from flywheel.render import sheets as render_sheets
    from flywheel.teaching.sheets import sheets_of
    from flywheel.teaching.variants import generate, load_template

    sheet = sheets_of(generate(load_template(COMPRESSOR), 1, 5))[0]
    with render_sheets._style("ru"):
        fig = render_sheets.linkage_figure(sheet, "ru")
        scale = render_sheets.IMAGE_MM / 25.4 / fig.get_figheight()
        texts = [t for t in fig.findobj(lambda a: hasattr(a, "get_fontsize")
                                        and hasattr(a, "get_text"))
                 if t.get_text().strip() and t.get_visible()]
        sizes = {t.get_text(): t.get_fontsize() * scale for t in texts}
    assert {"A", "B", "C", "O"} <= set(sizes), sizes
    assert min(sizes.values()) >= 6.5, sorted(sizes.items(), key=lambda kv: kv[1])[:5]


def test_a_set_with_a_negative_answer_says_the_sign_convention(tmp_path):
    """The engine template asks M_С and A_С, negative in the key (the resistance works against
    the crank's rotation): each of its sheets says which sign is which; the compressor's
    answers are all positive and its sheets say nothing of signs."""
    for template, signed in (("variants_engine.toml", True), ("variants_compressor.toml", False)):
        out = tmp_path / template
        res = invoke(CASES / template, "--count", 2, "--seed", 7, "--out", out, "--sheets",
                     "--sheets-format", "html", "--lang", "ru")
        assert res.exit_code == 0, res.output
        negative = any(x < 0 for answers in key_of(out)["variants"].values()
                       for x in answers.values())
        assert negative == signed
        for page in (out / "sheets").glob("variant_*.html"):
            text = page.read_text(encoding="utf-8").replace("\xa0", " ")
            assert ("Моменты и работы — со знаком: положительные направлены по вращению "
                    "кривошипа" in text) == signed, page.name


def test_a_points_place_on_its_link_says_from_which_joint():
    """«Точка S₂: доля длины звена 0,3» left the student to guess which end it is measured
    from: the label names the link and the joints as the записка does, «точка S₂ звена 2:
    доля длины AB l_AS2/l_AB» (cases/variants_compressor.toml: S2 on link 2 from A to B)."""
    import tomllib

    from flywheel.render.sheet_labels import field_label
    from flywheel.teaching.sheets import element_names

    doc = tomllib.loads(COMPRESSOR.read_text(encoding="utf-8"))
    names = element_names(doc)
    assert field_label("points.S2.fraction", "ru", names) == \
        "точка S₂ звена 2: доля длины AB l_AS2/l_AB"
    assert field_label("points.S4.fraction", "en", names) == \
        "point S₄ of link 4: share of AC l_AS4/l_AC"
    shaper = tomllib.loads((CASES / "variants_shaper.toml").read_text(encoding="utf-8"))
    assert field_label("points.Q.distance", "ru", element_names(shaper)) == \
        "точка Q звена 3: расстояние от O l_OQ"
    assert field_label("points.S2.fraction", "ru") == "точка S₂: доля длины звена"   # no names
