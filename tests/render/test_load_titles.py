"""A load's own title (``title`` of a force, couple, spring or cylinder; a string or
{ ru, en }): documents and figures name the load by it in the chosen language, and a load
without one keeps "kind name" (LoadsResult.titles, render/nomenclature.load_name)."""
from __future__ import annotations

from pathlib import Path

import pytest

from flywheel import analyze, load_case
from flywheel.dynamics.loads import LoadKey
from flywheel.render import nomenclature as nm
from flywheel.render import plots

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.fixture(scope="module")
def rocker():
    return analyze(load_case(CASES / "fourbar_rocker_load.toml"), n_points=360)


def test_titles_reach_the_result(rocker):
    titles = rocker.loads.titles
    assert nm.load_name(LoadKey("couple", "resistance"), "ru", titles) == "момент сопротивления на коромысле"
    assert nm.load_name(LoadKey("spring", "return"), "en", titles) == "return spring"
    assert nm.load_name(LoadKey("gravity", "2"), "ru", titles) == "сила тяжести звена 2"   # untitled


def test_a_string_title_is_both_languages(tmp_path):
    text = (CASES / "fourbar_rocker_load.toml").read_text(encoding="utf-8").replace(
        'title = { ru = "возвратная пружина", en = "return spring" }', 'title = "spring R"')
    case = tmp_path / "c.toml"
    case.write_text(text, encoding="utf-8")
    titles = analyze(load_case(case), n_points=360).loads.titles
    assert {nm.load_name(LoadKey("spring", "return"), lang, titles) for lang in ("en", "ru")} == {"spring R"}


def test_the_figure_says_the_title(rocker):
    fig = plots.figure_reduced_moments(rocker, "ru")
    labels = {t.get_text() for ax in fig.axes if ax.get_legend() for t in ax.get_legend().get_texts()}
    assert "момент сопротивления на коромысле" in labels and "возвратная пружина" in labels
    assert not any("resistance" in x or "return" in x for x in labels)


def test_the_russian_record_has_no_english_load_names(tmp_path):
    from typer.testing import CliRunner

    from flywheel.cli import app

    for case in ("shaper", "fourbar_rocker_load", "press", "pump"):
        out = tmp_path / case
        res = CliRunner().invoke(app, ["run", str(CASES / f"{case}.toml"), "--lang", "ru",
                                       "--plots", "none", "--points", "360", "--out", str(out)])
        assert res.exit_code == 0, res.output
        md = (out / "report.md").read_text(encoding="utf-8")
        for english in ("cutting", "resistance", "return", "punch", "газ HS"):
            assert english not in md, (case, english)


def test_a_machine_without_pistons_draws_applied_forces():
    """piston_forces.png of the shaper (a cutting force, no cylinder) is titled and captioned
    «заданные силы», not «силы, действующие на поршни»."""
    from flywheel.render.document import _figure_caption

    shaper = analyze(load_case(CASES / "shaper.toml"), n_points=360)
    title = plots.figure_piston_forces(shaper, "ru").axes[0].get_title()
    assert "заданные силы" in title and "порш" not in title
    assert _figure_caption("piston_forces.png", "ru", pistons=False) == "Заданные силы"
    assert "порш" in _figure_caption("piston_forces.png", "ru")
