"""An answer worded as a task sheet, a feedback page and a Moodle question ask it
(render/sheet_labels.answer_words): the object of «Определить» in the accusative, as the
course's task sheets write it («Определить кинетическую энергию…», «…массу маховика»); a
name never cut by a symbol that only ends a word."""
from __future__ import annotations

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
