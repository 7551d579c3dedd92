"""The nomenclature (render/nomenclature.py) is the one source of every quantity's label: every
column of every bundled run case and every key of its summary.json resolves there with the
unit the results carry, so the two can never drift."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from flywheel.cases import kind_of
from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.io.toml import read_toml
from flywheel.render import nomenclature as nm

ROOT = Path(__file__).resolve().parents[2]
RUN_CASES = [p for p in sorted((ROOT / "cases").glob("*.toml")) if kind_of(read_toml(p)) == "run"]


@pytest.fixture(scope="module", params=RUN_CASES, ids=lambda p: p.name)
def results(request):
    return analyze(load_case(request.param), n_points=360, transients=False)


def test_the_bundled_run_cases_are_found():
    assert {p.stem for p in RUN_CASES} >= {"compressor", "fourbar", "press", "slotted_link"}


def test_every_column_resolves_with_its_own_unit(results):
    for key, col in results.columns.items():
        assert nm.si_unit(key) == col.unit, key
        assert nm.csv_header(key) == f"{key} [{col.unit}]"
        assert nm.name(key, "en") and nm.name(key, "ru")


def test_every_summary_key_resolves(results):
    doc = results.to_document()["results"]
    for key in doc:
        nm.term(key)
    for a in doc["at"]:
        for key in a:
            if key not in ("moments", "forces", "points", "links"):
                nm.term(key)
        for p in a["points"].values():
            for key in p:
                nm.term(key)
        for lk in a["links"].values():
            for key in lk:
                nm.term(key)


def test_russian_labels_say_nothing_in_english(results):
    """What a Russian student reads: names, units and the standard positions' labels."""
    latin_word = re.compile(r"\b(?!max\b|min\b|const\b|rim\b)[a-z]{3,}\b")
    for key in results.columns:
        for text in (nm.name(key, "ru"), nm.unit_of(key, "ru"), nm.heading(key, "ru")):
            if key.startswith(("M ", "F_")):       # load names: "газ HP", "сила punch"
                text = text.replace(nm.term(key)[1].partition(" ")[2] or nm.term(key)[1], "")
            assert not latin_word.search(text), (key, text)
    for pos in results.position_angles:
        assert "d.c." not in nm.position_label(pos, "ru")


def test_units_in_russian():
    assert [nm.unit(u, "ru") for u in ("rad/s", "kg·m²", "N·m", "J", "deg", "-", "m/rad²")] == [
        "рад/с", "кг·м²", "Н·м", "Дж", "°", "–", "м/рад²"]


def test_every_term_has_both_languages_with_the_same_fields():
    """One table for every command: each entry names itself in English and Russian, a
    template's {fields} are the same in both, and its unit prints in Russian without Latin
    letters (task2 and aggregate labels included)."""
    import string

    def fields(template):
        return sorted(f for _, f, _, _ in string.Formatter().parse(template) if f)

    for key, t in nm.TERMS.items():
        assert t.en and t.ru, key
        assert fields(t.en) == fields(t.ru), key
        assert not re.search(r"[A-Za-z]", nm.unit(t.unit, "ru").replace("max", "")), (key, t.unit)
    assert nm.name("t2_balance", "ru", name="M_С", value="60", work="94.2478") == (
        "баланс работ за цикл ∮M_Д dφ = ∮M_С dφ даёт M_С = 60 Н·м (работа за цикл 94.2478 Дж)")
    assert nm.symbol("t2_M_D", "en") == "M_D" and nm.symbol("t2_M_D", "ru") == "M_Д"
    assert nm.rotor_name("motor J_Д", "ru") == "двигатель J_Д"


def test_families_and_headings():
    assert nm.term("M gravity 2")[0] is nm.TERMS["M {load}"]
    assert nm.name("M gravity 2", "ru") == "приведённый момент: сила тяжести звена 2"
    assert nm.heading("dJ_II", "en") == "dJ_II/dφ [kg·m²/rad]"
    assert nm.heading("omega_q", "ru") == "ω_q"                       # dimensionless: no unit
    assert nm.axis("phi_deg", "en") == r"$\varphi$ [deg]"
    assert nm.axis("omega_mean", "en") == r"$\omega_m$ [rad/s]"
    assert nm.axis("omega_mean", "ru") == r"$\omega_{ср}$, рад/с"
    assert nm.legend("A_D", "ru") == "$A_Д$: работа движущих сил"
    assert nm.name_tex("J_II", "en") == r"reduced moment of inertia of the second group $J_{II}$"
    from flywheel.dynamics.results import DeadCentre, Position

    pos = Position(phi=0.0, number=0, standard_deg=0, dead_centres=(DeadCentre("3", "outer"),))
    assert nm.position_label(pos, "en") == pos.label == "0° = 3 outer d.c."
    assert nm.position_label(pos, "ru") == "0° = ползун 3: внешняя мёртвая точка"
    with pytest.raises(KeyError, match="not in the nomenclature"):
        nm.term("no such quantity")


COMMA_UNIT = (r",\s*(°|deg|rad|rad/s|rad/s²|kg|kg·m²|N|N·m|J|W|Pa|MPa|m|mm|m/s|m/s²|s|"
              r"\(m/s\)/mm|\(m/s²\)/mm|N/mm)\s*$")
"""An English label in the Russian style 'ω, rad/s' (English writes 'ω [rad/s]')."""


def _figure_texts(fig) -> list[str]:
    """Every text drawn on a figure: titles, axis labels, legends, annotations."""
    from matplotlib.text import Text

    return [t.get_text() for t in fig.findobj(Text) if t.get_text()]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_figure_text_has_no_literal_underscores_and_one_unit_style(lang):
    """Every figure: a symbol with a subscript is mathtext, never 'J_II' as typed; one unit
    style per language (issue 15): Russian 'ω, рад/с' (never brackets, no English unit),
    English 'ω [rad/s]' (never 'ω, rad/s')."""
    from flywheel.render.plots import all_figures

    r = analyze(load_case(ROOT / "cases" / "compressor.toml"), n_points=360, transients=True)
    for name, build in all_figures(r, lang):
        fig = build()
        try:
            for text in _figure_texts(fig):
                plain = re.sub(r"\$[^$]*\$", "", text)
                assert "_" not in plain, (name, text)
                if lang == "ru":
                    assert not re.search(r"\[[^\]]*\]", plain.replace("[motor]", "")), (name, text)
                    assert not re.search(r"\b(rad|kg|deg|MPa|N·m)\b", plain), (name, text)
                else:
                    assert not re.search(COMMA_UNIT, plain), (name, text)
        finally:
            fig.clear()


# -- docs/results.md against the table (generated by tools/resultsdoc.py: tests/render/test_results_doc.py) --
def _doc_tables() -> list[list[dict[str, str]]]:
    """The Markdown tables of docs/results.md whose first column is "key" or "column", as rows
    {header: cell}."""
    tables, rows, header = [], None, None
    for line in (ROOT / "docs" / "results.md").read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]] if line.startswith("|") else None
        if cells is None:
            rows = header = None
            continue
        if header is None:
            header = cells
            rows = [] if header[0] in ("key", "column") else None
            if rows is not None:
                tables.append(rows)
        elif rows is not None and not set(cells[0]) <= set("-"):
            rows.append(dict(zip(header, cells)))
    return tables


def _doc_keys(cell: str) -> list[str]:
    """The keys of a row: its `backticked` names, a `*` standing for any part."""
    import fnmatch

    keys = []
    for k in re.findall(r"`([^`]+)`", cell):
        found = [t for t in nm.TERMS if fnmatch.fnmatchcase(t, k)] if "*" in k else [k]
        assert found, f"docs/results.md: `{k}` matches nothing in the nomenclature"
        keys += found
    return keys


def _printed(u: str) -> str:
    return "–" if u == "-" else u


def test_docs_results_tables_agree_with_the_nomenclature():
    tables = _doc_tables()
    assert len(tables) == 3                              # summary.json, its at entries, table.csv
    for rows in tables:
        for row in rows:
            keys = _doc_keys(row.get("key", row.get("column", "")))
            assert keys, row
            for k in keys:
                nm.term(k)                               # KeyError: not in the nomenclature
            units = list(dict.fromkeys(_printed(nm.si_unit(k)) for k in keys if nm.si_unit(k)))
            stated = [u for u in (x.strip() for x in row["unit"].split(",")) if u]
            assert stated == units, (keys, row["unit"])
            if row.get("symbol"):
                symbols = {s for k in keys for s in (nm.symbol(k, "ru"), nm.symbol(k, "en"))}
                stated = {x.strip().replace("\\|", "|") for x in row["symbol"].split(", ")}
                assert stated == symbols, (keys, row["symbol"])


def test_docs_results_names_every_output(results):
    """Every summary.json key and every table.csv column of the bundled cases is in the doc."""
    summary, at, columns = _doc_tables()
    documented = {nm.term(k)[0] for rows in (summary, at) for row in rows for k in _doc_keys(row["key"])}
    doc = results.to_document()["results"]
    for key in doc:
        assert nm.term(key)[0] in documented, key
    families = {nm.term(k)[0] for row in columns for k in _doc_keys(row["column"])}
    for key in results.columns:
        assert nm.term(key)[0] in families, key


def test_catalogue_terms_are_what_gettext_gives():
    """The "term:" labels' Russian, read from the compiled catalogue without gettext (an English
    run never parses the whole Russian catalogue), is what gettext's own pgettext gives."""
    from flywheel.render.catalogue import _english, catalogue

    english = {ctx: en for ctx, en in _english().items() if ctx.startswith("term:")}
    assert len(english) > 50
    for ctx, en in english.items():
        t = nm.TERMS[ctx[5:]]
        assert (t.en, t.ru) == (en, catalogue("ru").pgettext(ctx, en)), ctx
        assert t.ru, ctx
