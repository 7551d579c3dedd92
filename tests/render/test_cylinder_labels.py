"""A cylinder's ``label`` (a string or { ru, en }): its short name in the records, figures,
drawing sheets and task sheets — «цилиндр ВД» in Russian, "cylinder HP" in English — while its
``name`` stays the key of the CSV columns, summary.json and the figures' file names
(render/nomenclature.cylinder_label, LoadsResult.labels)."""
from __future__ import annotations

from pathlib import Path

import pytest

from flywheel import analyze, load_case
from flywheel.dynamics.loads import LoadKey
from flywheel.io.text import Text
from flywheel.render import nomenclature as nm
from flywheel.render import plots
from flywheel.render.document import build_document

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.fixture(scope="module")
def compressor():
    return analyze(load_case(CASES / "compressor.toml"), n_points=360)


def _unlabelled(tmp_path: Path) -> Path:
    """The compressor without its cylinders' labels and titles."""
    lines = (CASES / "compressor.toml").read_text(encoding="utf-8").splitlines()
    kept = [ln for ln in lines if not ln.startswith(("label = ", "title = { ru = \"газ"))]
    assert len(lines) - len(kept) == 4
    case = tmp_path / "unlabelled.toml"
    case.write_text("\n".join(kept) + "\n", encoding="utf-8")
    return case


def _text(doc) -> str:
    """Every caption, heading and cell of a record, one string."""
    out = []
    for b in doc.blocks:
        for attr in ("caption", "text", "header", "rows"):
            v = getattr(b, attr, None)
            out.append(repr(v) if v is not None else "")
    return "\n".join(out)


def test_the_label_reaches_the_result(compressor):
    hp, lp = compressor.cylinders
    assert (hp.name, nm.cylinder_label(hp, "ru"), nm.cylinder_label(hp, "en")) == ("HP", "ВД", "HP")
    assert (lp.name, nm.cylinder_label(lp, "ru")) == ("LP", "НД")
    # the data keep the name
    assert {"p_HP", "F_HP", "p_LP"} <= set(compressor.columns)


def test_the_russian_record_names_the_cylinders_in_russian(compressor):
    stems = [f"{nm.indicator_stem(c.name)}.png" for c in compressor.cylinders]
    assert stems == ["indicator_HP.png", "indicator_LP.png"]      # file names: the keys
    ru = _text(build_document(compressor, "ru", stems))
    assert "Индикаторная диаграмма цилиндра ВД" in ru and "цилиндра НД" in ru
    assert "цилиндра HP" not in ru and "цилиндра LP" not in ru
    en = _text(build_document(compressor, "en", stems))
    assert "cylinder HP" in en and "ВД" not in en


def test_the_figures_name_the_cylinders_in_russian(compressor):
    title = plots.figure_indicator(compressor, compressor.cylinders[0], "ru").axes[0].get_title()
    assert title.endswith("цилиндра ВД"), title
    fig = plots.figure_piston_forces(compressor, "ru")
    legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
    assert "сила давления газа на поршень 3, цилиндр ВД" in legend
    assert not any("HP" in x or "LP" in x for x in legend), legend


def test_the_drawing_sheet_names_the_cylinders_in_russian(compressor):
    from flywheel.render.drawings import sheet1
    from flywheel.render.drawings.model import Text as Lettering
    from flywheel.render.drawings.sheet import ROOM

    views = sheet1.views(compressor, "ru", ROOM["A1"])
    texts = [t.text for v in views for t in v.items if isinstance(t, Lettering)]
    assert any("цилиндра ВД" in x for x in texts) and any("цилиндра НД" in x for x in texts)
    assert not any("цилиндра HP" in x or "цилиндра LP" in x for x in texts)


def test_without_a_label_the_name_is_shown(tmp_path):
    r = analyze(load_case(_unlabelled(tmp_path)), n_points=360)
    assert [nm.cylinder_label(c, "ru") for c in r.cylinders] == ["HP", "LP"]
    assert r.loads.labels == {} and r.loads.titles == {}
    assert nm.load_name(LoadKey("gas", "HP"), "ru", r.loads.titles, r.loads.labels) == "газ HP"


def test_a_labelled_cylinder_without_a_title_names_its_gas_by_the_label():
    labels = {LoadKey("gas", "HP"): Text("HP", "ВД")}
    assert nm.load_name(LoadKey("gas", "HP"), "ru", {}, labels) == "газ ВД"
    assert nm.load_name(LoadKey("gas", "HP"), "en", {}, labels) == "gas HP"
    titles = {LoadKey("gas", "HP"): Text("gas, HP cylinder", "газ, цилиндр ВД")}
    assert nm.load_name(LoadKey("gas", "HP"), "ru", titles, labels) == "газ, цилиндр ВД"   # a title wins
    assert nm.member("M gas HP", "ru", None, labels) == "газ ВД"


def test_a_string_label_is_both_languages(tmp_path):
    text = _unlabelled(tmp_path).read_text(encoding="utf-8").replace(
        'name = "HP"\n', 'name = "HP"\nlabel = "II"\n')
    case = tmp_path / "string.toml"
    case.write_text(text, encoding="utf-8")
    hp = analyze(load_case(case), n_points=360).cylinders[0]
    assert {nm.cylinder_label(hp, lang) for lang in ("en", "ru")} == {"II"}


def test_a_label_table_needs_ru_and_en(tmp_path):
    from flywheel.errors import CaseFileError

    text = (CASES / "compressor.toml").read_text(encoding="utf-8").replace(
        'label = { ru = "ВД", en = "HP" }', 'label = { ru = "ВД" }')
    case = tmp_path / "bad.toml"
    case.write_text(text, encoding="utf-8")
    with pytest.raises(CaseFileError) as e:
        load_case(case)
    line = str(e.value)
    assert "\n" not in line and "cylinders[0].label" in line and "ru and en" in line, line


def test_the_task_sheet_names_the_cylinders_by_their_labels():
    import tomllib

    from flywheel.render.sheet_labels import field_label
    from flywheel.teaching.sheets import element_names

    doc = tomllib.loads((CASES / "variants_compressor.toml").read_text(encoding="utf-8"))
    names = element_names(doc)
    # each cylinder's own symbol: two d on one sheet are two quantities (seed 000: d2, d1)
    assert field_label("cylinders.0.bore", "ru", names) == "диаметр цилиндра ВД d_ВД"
    assert field_label("cylinders.1.bore", "en", names) == "bore of cylinder LP d_LP"
    assert field_label("cylinders.1.p_max", "ru", names) == \
        "максимальное давление в цилиндре НД p_max,НД"
    assert element_names({"cylinders": [{"name": "A"}]}) == {"cylinders.0": "A"}   # no label
    # a force's label is its F's subscript: «сила F_пс», not «сила пс»; a couple's its M's
    names = element_names({"forces": [{"name": "cutting", "label": {"ru": "пс", "en": "c"}}],
                           "couples": [{"name": "resistance", "label": "с"}]})
    assert field_label("forces.0.magnitude", "ru", names) == "сила F_пс: модуль F"
    assert field_label("forces.0.magnitude", "en", names) == "force F_c: magnitude F"
    assert field_label("couples.0.moment", "ru", names) == "пара сил M_с: момент M"
    assert element_names({"forces": [{"name": "cutting"}]}) == {"forces.0": "cutting"}


def test_a_warning_names_the_cylinder_by_its_label_in_each_language():
    """A Notice's parameter given in two languages (a label: io.text.Text) is said in the
    Russian message by its Russian (render/messages.message); its English text, stderr's and
    summary.json's, by the English."""
    from flywheel.errors import Notice
    from flywheel.render.messages import message

    r = analyze(load_case(CASES / "compressor_worksheet.toml"), n_points=360)
    (w,) = [w for w in r.warnings if getattr(w, "code", "") == "cylinder_negative_p"]
    assert str(w).startswith("cylinder LP: the natural-spline interpolation")
    assert message(w, "ru").startswith("цилиндр НД: интерполяция (natural-spline)")
    plain = Notice.of("cylinder_negative_p", "cylinder {cylinder}: the {kind} interpolation of "
                      "its indicator table gives negative pressure, down to {p:.4g} MPa at "
                      "φ = {phi_deg:.1f}° (use 'pchip' to avoid overshoot)", cylinder="C1",
                      kind="linear", p=-0.5, phi_deg=10.0)
    assert message(plain, "ru").startswith("цилиндр C1: ")          # a plain name as it is


def _texts(fig) -> list[str]:
    from matplotlib.text import Text as MplText

    return [t.get_text() for t in fig.findobj(MplText)]


@pytest.mark.parametrize("case, ru, en", [
    ("compressor", ["F(ВД)", "F(НД)"], ["F(HP)", "F(LP)"]),          # the cylinders' labels
    ("shaper", ["F(пс)"], ["F(cutting)"]),                            # a force's
    ("fourbar_rocker_load", ["F(пр)", "M(с) на звене 3"], ["F(return)", "M(resistance) on link 3"]),
])
def test_the_plans_name_the_loads_by_their_labels(case, ru, en):
    """The force polygons and Zhukovsky's lever name a given load F_<label> (M_<label> for a
    couple) in the figure's language: F(ВД) for the compressor's cylinder HP, F(пс) for the
    shaper's cutting force, M(с) for the rocker's couple (dynamics.plans._called); the groups
    by their links and their kind, ВВП in Russian."""
    from flywheel.render.plots_plans import figure_force_polygons, figure_lever

    r = analyze(load_case(CASES / f"{case}.toml"), n_points=360)
    for lang, want in (("ru", ru), ("en", en)):      # every report angle (a cutting force acts
        text = "\n".join(t for ps in r.plans for t in                   # on one stroke only)
                         _texts(figure_force_polygons(r, ps, lang)) + _texts(figure_lever(r, ps, lang)))
        assert all(w in text for w in want), (lang, want)
        if lang == "ru":
            assert "группа звеньев" in text and not any(k in text for k in ("RRP", "RPR", "RRR"))
            assert not any(w in text for w in en if w not in ru), text


@pytest.mark.parametrize("case, want", [
    ("engine_4stroke", {"F_3"}),                          # cylinder "1", its piston link 3
    ("engine_inline4", {"F_3", "F_5", "F_7", "F_9"}),    # cylinders 1 … 4, pistons 3, 5, 7, 9
])
def test_an_unlabelled_cylinders_gas_force_is_named_by_its_piston(case, want):
    """Without a label a gas force is F with its piston's link, as the piston's weight and
    inertia force are (G₃, Φ₃): named by the cylinder, engine_inline4's cylinder 2 would have
    put an F₂ on piston 5 of the group of links 4, 5."""
    r = analyze(load_case(CASES / f"{case}.toml"), n_points=360)
    for ps in r.plans:
        given = {(str(v.label), v.rel) for pg in ps.polygons for v in pg.vectors
                 if v.kind == "given"}
        assert {label for label, _ in given} == want
        assert all(label == f"F_{link}" for label, link in given)


def test_sheet2_names_a_group_as_the_force_polygons_do(compressor):
    """Sheet 2's group views and the figures' polygons list a group's links alike, «4, 5»
    (the sheet had «4–5», which reads as a range once the links are numbers)."""
    from flywheel.render.drawings import sheet2
    from flywheel.render.drawings.model import Text as Lettering
    from flywheel.render.drawings.sheet import ROOM

    texts = [t.text for v in sheet2.views(compressor, "ru", ROOM["A1"]) for t in v.items
             if isinstance(t, Lettering)]
    groups = [x for x in texts if x.startswith("Группа звеньев")]
    assert groups and all(x.startswith(("Группа звеньев 4, 5 (", "Группа звеньев 2, 3 ("))
                          for x in groups), groups
