"""An answer worded as a task sheet, a feedback page and a Moodle question ask it
(render/sheet_labels.answer_words): the object of «Определить» in the accusative, as the
course's task sheets write it («Определить кинетическую энергию…», «…массу маховика»); a
name never cut by a symbol that only ends a word."""
from __future__ import annotations

from pathlib import Path

import pytest

from flywheel.render.sheet_labels import answer_words, object_form


@pytest.mark.parametrize("kind, key, what", [
    ("run", "delta_T.4.T_II", "кинетическую энергию второй группы в положении 4"),
    ("run", "delta_T.4.A", "суммарную работу в положении 4"),
    ("run", "reactions.O:0->1.R", "реакцию в кинематической паре O (0→1): модуль"),
    ("run", "at.0.omega", "угловую скорость звена приведения"),
    # already so, or masculine and neuter: as they are
    ("run", "flywheel_disk.mass", "массу маховика в виде сплошного диска"),
    ("run", "omega_max", "наибольшую угловую скорость"),
    ("run", "delta_T.4.dT_I", "изменение кинетической энергии первой группы в положении 4"),
    ("run", "analogues.3.vq_B", "аналог скорости точки B в положении 3"),
    ("run", "at.0.epsilon", "угловое ускорение звена приведения"),
    ("task2", "M_C", "момент сопротивления"),
    # task2's masses: their names are templates of a radius, not filled on a sheet
    ("task2", "flywheel_mass", "массу маховика"),
    ("task2", "rim_mass", "массу обода маховика"),
])
def test_the_object_of_determine_is_in_the_accusative(kind, key, what):
    assert answer_words(kind, key, "ru")[0] == what
    assert "{" not in answer_words(kind, key, "en")[0]


def test_a_name_is_not_cut_by_a_symbol_that_only_ends_its_last_word():
    """"the mass of the flywheel's rim" with its symbol m had lost its last letter."""
    assert answer_words("task2", "rim_mass", "en") == ("the mass of the flywheel's rim", "m", "kg")


def test_neuter_nouns_in_mya_and_symbols_stay():
    assert object_form("время цикла") == "время цикла"
    assert object_form("J_II, среднее за цикл") == "J_II, среднее за цикл"
    assert object_form("длина кривошипа") == "длину кривошипа"


@pytest.mark.parametrize("key, ru, en", [
    ("at.0.omega", "угловую скорость звена приведения при φ = 60°",
     "crank angular velocity at φ = 60°"),
    ("at.1.balancing_moment.kinetostatic", "уравновешивающий момент (кинетостатика) при φ = 250°",
     "balancing moment (kinetostatics) at φ = 250°"),
    ("at.0.balancing_moment.zhukovsky", "уравновешивающий момент по рычагу Жуковского при φ = 60°",
     "balancing moment by Zhukovsky's lever at φ = 60°"),
    ("at.0.joints.O:0->3.F", "реакцию в кинематической паре O (0→3): модуль при φ = 60°",
     "reaction O (0→3): magnitude at φ = 60°"),
    ("at.0.points.B.v", "скорость точки B при φ = 60°", "velocity of point B at φ = 60°"),
    ("at.0.links.3.epsilon", "угловое ускорение звена 3 при φ = 60°",
     "angular acceleration of link 3 at φ = 60°"),
    ("force_analysis.crank_pin_load_max", "наибольшую нагрузку на шатунную шейку за цикл",
     "the greatest load on the crank pin over the cycle"),
    ("at.0.slider_crank.3.piston_effort", "движущую силу на поршне 3 при φ = 60°",
     "piston effort, slider 3 at φ = 60°"),
    ("at.0.slider_crank.5.crank_pin_x",
     "нагрузку на шатунную шейку: проекция на ось x от шатуна ползуна 5 при φ = 60°",
     "load on the crank pin: x component from the rod of slider 5 at φ = 60°"),
    ("at.1.joints.B:0->3.angle_deg",
     "направление реакции в кинематической паре B (0→3), угол от оси x при φ = 250°",
     "the direction of the reaction in pair B (0→3), from the x axis at φ = 250°"),
    ("at.0.joints.B:0->3.offset",
     "смещение линии действия реакции в кинематической паре B (0→3) вдоль линии скольжения "
     "при φ = 60°",
     "the offset of the line of action of the reaction in pair B (0→3) along the slide at "
     "φ = 60°"),
    ("at.0.main_bearing_load.angle_deg",
     "направление нагрузки на коренной подшипник, угол от оси x при φ = 60°",
     "the direction of the load on the main bearing, from the x axis at φ = 60°"),
    ("at.0.moments.gravity 2", "приведённый момент: сила тяжести звена 2 при φ = 60°",
     "reduced moment: gravity, link 2 at φ = 60°"),
    ("firing_deg.3", "угол вспышки в цилиндре 3", "crank angle where cylinder 3 fires"),
    ("delta_T_I_max", "наибольшее изменение кинетической энергии первой группы",
     "the greatest change of the first group's kinetic energy"),
    ("output_link.stroke", "ход ползуна", "stroke of the slider"),
    ("output_link.extremes_phi_deg.1",
     "угол поворота кривошипа в крайнем положении 2 выходного звена",
     "crank angle of the output link's extreme position 2"),
    ("output_link.phi_transmission_angle_min_deg",
     "угол поворота кривошипа при наименьшем угле передачи",
     "crank angle of the least transmission angle"),
])
def test_a_report_angles_quantity_is_asked_at_its_angle(key, ru, en):
    """A template may ask any number of summary.json: a report angle's (``at.N.…``) is asked
    at the variant's angle N, a force analysis's extreme in words — the sheet had printed
    «Определить угловую скорость звена приведения ω» (at which angle?) and «Определить
    at.0.balancing_moment.kinetostatic»."""
    angles = (60.0, 250.0)
    assert answer_words("run", key, "ru", angles)[0] == ru
    assert answer_words("run", key, "en", angles)[0] == en


def test_the_task_sheet_and_the_moodle_bank_ask_at_the_variants_angle(tmp_path):
    """variants_shaper.toml asking M_у and a reaction at its report angle (output.at_deg =
    [60, 250]): the sheet's «Определить» items and the Moodle questions name the angle."""
    import re

    from typer.testing import CliRunner

    from flywheel.cli import app

    root = Path(__file__).resolve().parents[2]
    text = (root / "cases" / "variants_shaper.toml").read_text(encoding="utf-8")
    text = re.sub(r'\nanswers = \[[^\]]*\]', '\nanswers = ["at.0.balancing_moment.kinetostatic", '
                  '"at.1.joints.O:0->3.F", "force_analysis.balancing_moment_max", '
                  '"at.0.moments.force cutting"]', text)
    text = re.sub(r'\ntolerances = \{[^}]*\}', '', text)
    template = tmp_path / "t.toml"
    template.write_text(text, encoding="utf-8")
    res = CliRunner().invoke(app, ["variants", str(template), "--count", "1", "--seed", "1",
                                   "--out", str(tmp_path / "v"), "--lang", "ru", "--sheets",
                                   "--sheets-format", "html", "--moodle",
                                   str(tmp_path / "q.xml")])
    assert res.exit_code == 0, res.output
    sheet = re.sub(r"<[^>]+>", "", (tmp_path / "v" / "sheets" / "variant_01.html").read_text(
        encoding="utf-8"))
    bank = re.sub(r"<[^>]+>|&lt;sub&gt;|&lt;/sub&gt;", "", (tmp_path / "q.xml").read_text(
        encoding="utf-8"))
    for said in ("Определить уравновешивающий момент (кинетостатика) при φ = 60°",
                 "Определить реакцию в кинематической паре O (0→3): модуль при φ = 250°",
                 "Определить наибольший уравновешивающий момент за цикл",
                 # the force by the case's title, not its name «cutting»
                 "Определить приведённый момент: сила резания при φ = 60°"):
        assert said in sheet and said in bank, said
    assert "at.0." not in sheet and "force_analysis." not in sheet
    # the key keeps the variant's report angles, so a feedback page names them too
    import json

    key = json.loads((tmp_path / "v" / "answers.json").read_text(encoding="utf-8"))
    assert key["at_deg"] == {"01": [60.0, 250.0]}
    answers = key["variants"]["01"]
    sheet_csv = tmp_path / "s.csv"
    sheet_csv.write_text("student,variant," + ",".join(answers) + "\nИванов,01,"
                         + ",".join(repr(v) for v in answers.values()) + "\n", encoding="utf-8")
    res = CliRunner().invoke(app, ["grade", str(tmp_path / "v" / "answers.json"), str(sheet_csv),
                                   "--lang", "ru", "--feedback", str(tmp_path / "fb")])
    assert res.exit_code == 0, res.output
    page = next((tmp_path / "fb").iterdir()).read_text(encoding="utf-8")
    assert "уравновешивающий момент (кинетостатика) при φ = 60°" in page
    # the load by the case's title on the feedback page too: answers.json keeps it
    assert key["load_names"]["titles"]["force cutting"] == {"en": "cutting force",
                                                            "ru": "сила резания"}
    assert "приведённый момент: сила резания при φ = 60°" in page and "cutting при" not in page


def test_a_broken_load_names_of_a_key_is_one_line():
    from flywheel.dynamics.loads import LoadKey
    from flywheel.errors import CaseFileError
    from flywheel.teaching.grading import parse_key

    doc = {"variants": {"01": {"at.0.omega": 62.8}}, "tolerance": 0.01,
           "load_names": {"titles": {"force cutting": "cutting force"}}}
    with pytest.raises(CaseFileError) as e:
        parse_key(doc, "answers.json")
    assert str(e.value).startswith('answers.json: load_names: must be an object {"titles": ')
    assert "\n" not in str(e.value)
    doc["load_names"] = {"titles": {"force cutting": {"en": "cutting force", "ru": "сила резания"}}}
    titles, labels = parse_key(doc, "answers.json").loads
    assert titles[LoadKey("force", "cutting")].ru == "сила резания" and labels == {}


def test_a_broken_at_deg_of_a_key_is_one_line():
    from flywheel.errors import CaseFileError
    from flywheel.teaching.grading import parse_key

    doc = {"variants": {"01": {"at.0.omega": 62.8}}, "tolerance": 0.01,
           "at_deg": {"01": "sixty"}}
    with pytest.raises(CaseFileError) as e:
        parse_key(doc, "answers.json")
    assert "answers.json: at_deg: must be an object {variant: [angles in degrees]}" in str(e.value)
    doc["at_deg"] = {"01": [60, 250.0]}
    assert parse_key(doc, "answers.json").at_deg == {"01": (60.0, 250.0)}


@pytest.mark.parametrize("case", ["compressor", "engine_inline4", "shaper", "fourbar_rocker_load"])
def test_every_number_of_summary_json_is_asked_in_words(case):
    """Each number a run's summary.json holds, asked as a template may ask it: in words, never
    by its key (a dotted path, a key's snake_case word such as angle_deg or crank_pin_x) — the
    sheets had asked «Определить at.0.joints.B:0->3.angle_deg»."""
    import json
    import re

    from flywheel.cases.run import load_case
    from flywheel.dynamics.pipeline import analyze
    from flywheel.render.tables import summary_json

    root = Path(__file__).resolve().parents[2]
    doc = json.loads(summary_json(analyze(load_case(root / "cases" / f"{case}.toml"),
                                          n_points=360)))

    def numbers(d, pre=""):
        if isinstance(d, dict):
            for k, v in d.items():
                yield from numbers(v, f"{pre}{k}.")
        elif isinstance(d, list):
            for i, v in enumerate(d):
                yield from numbers(v, f"{pre}{i}.")
        elif isinstance(d, (int, float)) and not isinstance(d, bool):
            yield pre[:-1]

    keys = list(numbers(doc["results"]))
    assert any(k.startswith("at.0.joints.") for k in keys)
    for key in keys:
        for lang in ("ru", "en"):
            what = answer_words("run", key, lang, (60.0,))[0]
            assert what != key and not re.search(r"[a-z]+_[a-z]+|->|\.\d", what), (key, what)


def test_a_load_is_asked_by_the_title_the_case_gives_it():
    """A report angle's load is named by its title (LoadsResult.titles) or its cylinder's
    label where the variant's case gives one: «силу резания», not «силу cutting»."""
    from flywheel.dynamics.loads import LoadKey
    from flywheel.io.text import Text

    loads = ({LoadKey("force", "cutting"): Text("cutting force", "сила резания")},
             {LoadKey("gas", "HP"): Text("HP", "ВД")})
    assert answer_words("run", "at.0.forces.cutting", "ru", (60.0,), loads)[0] == \
        "силу резания при φ = 60°"
    assert answer_words("run", "at.0.moments.gas HP", "ru", (60.0,), loads)[0] == \
        "приведённый момент: газ ВД при φ = 60°"
    assert answer_words("run", "at.0.forces.cutting", "ru", (60.0,))[0] == "силу cutting при φ = 60°"


def test_a_point_in_a_field_label_is_lettered_as_the_figures_letter_it():
    """A task sheet's «Дано» and the записка name a point S₂, O₁ (mathfmt.point_name), as the
    scheme beside them draws it (they had «точка S2»)."""
    from flywheel.render.sheet_labels import field_label

    assert field_label("points.S2.fraction", "ru") == "точка S₂: доля длины звена"
    assert field_label("ground.O1", "ru") == "неподвижная точка O₁ (x; y)"
