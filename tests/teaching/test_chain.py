"""Issue 27, steps 1 and 2: the dependency chain written into the key, and error carried
forward. The truths are the textbook's formulas written out here (seed 000 §4: J_I =
ΔT_нб/(ω_ср²·δ), J_доп = J_I − J_10 − J_ред, the disk D = (32·J/(π·ρ·b/D))^(1/5)) from the
variant file's own data, and `flywheel run`'s table of ΔT_I(φ)."""
import csv
import math

import pytest

from chain_helpers import data_of, key_of, make, runner, textbook
from flywheel.cli import app
from flywheel.teaching.chain import Chain, Givens


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    return make(tmp_path_factory, "variants_compressor.toml")


@pytest.fixture(scope="module")
def engine(tmp_path_factory):
    return make(tmp_path_factory, "variants_engine.toml", count=2)


# -- 1. the chain in the key --------------------------------------------------------------------

def test_the_key_says_what_each_answer_is_computed_from(compressor, engine):
    steps = key_of(compressor)["chain"]["steps"]
    # the course's chain M_Д → ΔT_нб → J_I → J_доп → D
    assert {a: s["from"] for a, s in steps.items()} == {
        "driving_moment": [], "delta_T_max": ["driving_moment"],
        "J_required": ["delta_T_max"], "J_flywheel": ["J_required"],
        "flywheel_disk.D": ["J_flywheel"]}
    assert "J_required_merzalov" in steps["J_required"]["by"]
    steps = key_of(engine)["chain"]["steps"]
    assert steps["cycle_work_resistance"]["from"] == ["balancing_moment"]
    assert steps["delta_T_max"]["from"] == ["balancing_moment"]


def test_the_chain_recomputes_later_answers_by_the_textbook(compressor):
    key = key_of(compressor)
    for vid, ans in key["variants"].items():
        chain = Chain(Givens.from_document(key["chain"]["givens"][vid]), key["answers"])
        for a in key["answers"]:          # from the key's own values: the key
            assert chain.recompute(a, ans)[0][0] == pytest.approx(ans[a], rel=1e-6)
        student = dict(ans, delta_T_max=ans["delta_T_max"] * 1.37)
        truth = textbook(data_of(compressor, vid), student["delta_T_max"])
        assert chain.recompute("J_required", student) == ((truth["J_required"],), "delta_T_max")
        assert chain.recompute("J_flywheel", student)[0][0] == pytest.approx(ans["J_flywheel"])
        # the student's own J_I feeds J_доп; J_доп (not given) is computed on the way to D
        gone = dict(student, J_required=truth["J_required"], J_flywheel=math.nan)
        value, source = chain.recompute("flywheel_disk.D", gone)
        assert source == "J_required"
        assert value[0] == pytest.approx(truth["flywheel_disk.D"], rel=1e-12)


def test_energy_swing_from_a_students_moment_agrees_with_the_runs_table(compressor, tmp_path):
    """ΔT_I(φ) is linear in the constant moment: from `flywheel run`'s dT_I column, a moment
    M' gives ΔT_I + (M' − M)·φ; its swing is the ΔT_нб a student with M' should find."""
    key = key_of(compressor)
    vid = "01"
    res = runner.invoke(app, ["run", str(compressor / f"variant_{vid}.toml"), "--points", "1440",
                              "--no-plots", "--out", str(tmp_path / "r")])
    assert res.exit_code == 0, res.output
    with open(tmp_path / "r" / "table.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    phi = [math.radians(float(r["phi_deg [deg]"])) for r in rows]
    dT = [float(r["dT_I [J]"]) for r in rows]
    M = key["variants"][vid]["driving_moment"]
    chain = Chain(Givens.from_document(key["chain"]["givens"][vid]), key["answers"])
    for factor in (0.8, 1.1, 1.25):
        curve = [t + (factor - 1) * M * p for t, p in zip(dT, phi)]
        truth = max(curve) - min(curve)
        got, source = chain.recompute("delta_T_max", {"driving_moment": factor * M})
        assert source == "driving_moment"
        assert got[0] == pytest.approx(truth, rel=2e-3)
