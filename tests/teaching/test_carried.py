"""Issue 27, step 2: error carried forward («верно по вашим данным», "consistent with your
earlier answer"). The later answers are computed here by the textbook (seed 000 §4) from the
student's wrong earlier one; the grader must recompute them with its own chain."""
import json
import math

import pytest

from chain_helpers import data_of, graded, key_of, make, runner, textbook, verdicts, write_sheet
from flywheel.cli import app


@pytest.fixture(scope="module")
def compressor(tmp_path_factory):
    return make(tmp_path_factory, "variants_compressor.toml")


@pytest.fixture(scope="module")
def engine(tmp_path_factory):
    return make(tmp_path_factory, "variants_engine.toml", count=2)


def test_one_wrong_early_answer_carries_forward_exactly_to_the_dependent_ones(compressor,
                                                                                tmp_path):
    key = key_of(compressor)
    rows = []
    for i, (vid, ans) in enumerate(key["variants"].items()):
        data = data_of(compressor, vid)
        wrong_dT = dict(ans, delta_T_max=ans["delta_T_max"] * 1.3)
        wrong_dT.update(textbook(data, wrong_dT["delta_T_max"]))
        rows.append((f"dT{i}", vid, wrong_dT))
        t = textbook(data, ans["delta_T_max"])
        wrong_J = dict(ans, J_required=t["J_required"] * 0.7)   # ΔT right, J_I wrong
        later = textbook(data, wrong_J["J_required"] * data["machine"]["delta"]
                         * (2 * math.pi * data["machine"]["speed_rps"]) ** 2)
        wrong_J.update({"J_flywheel": later["J_flywheel"], "flywheel_disk.D": later["flywheel_disk.D"]})
        rows.append((f"J{i}", vid, wrong_J))
    sheet = write_sheet(tmp_path / "s.csv", key, rows)
    plain = graded(compressor / "answers.json", sheet)
    half = graded(compressor / "answers.json", sheet, "--carried-forward", "0.5")
    for i in range(len(key["variants"])):
        assert verdicts(plain[f"dT{i}"]) == {
            "driving_moment": "pass", "delta_T_max": "fail", "J_required": "carried",
            "J_flywheel": "carried", "flywheel_disk.D": "carried"}
        assert verdicts(plain[f"J{i}"]) == {
            "driving_moment": "pass", "delta_T_max": "pass", "J_required": "fail",
            "J_flywheel": "carried", "flywheel_disk.D": "carried"}
        assert plain[f"dT{i}"]["score"] == pytest.approx(1 / 5)          # default: not scored
        assert half[f"dT{i}"]["score"] == pytest.approx((1 + 0.5 * 3) / 5)
        assert half[f"J{i}"]["score"] == pytest.approx((2 + 0.5 * 2) / 5)
        assert half[f"J{i}"]["carried_forward"] == 2


def test_a_wrong_moment_carries_to_the_cycles_work_only(engine, tmp_path):
    """The engine: A_C = M_C·Φ (Φ = 4π over the 720° cycle) from the student's M_C; ΔT_нб
    and the rest as the key: right against the key."""
    key = key_of(engine)
    rows = []
    for vid, ans in key["variants"].items():
        M = ans["balancing_moment"] * 1.2
        rows.append((vid, vid, dict(ans, balancing_moment=M, cycle_work_resistance=M * 4 * math.pi)))
    got = graded(engine / "answers.json", write_sheet(tmp_path / "s.csv", key, rows))
    for vid in key["variants"]:
        assert verdicts(got[vid]) == {
            "balancing_moment": "fail", "cycle_work_resistance": "carried", "delta_T_max": "pass",
            "J_required": "pass", "J_flywheel": "pass", "flywheel_disk.D": "pass"}


def test_copying_one_wrong_number_everywhere_earns_nothing(compressor, tmp_path):
    key = key_of(compressor)
    rows = []
    for vid, ans in key["variants"].items():
        wrong = ans["delta_T_max"] * 1.3
        rows.append(("copy" + vid, vid, dict(ans, **{a: wrong for a in key["answers"][1:]})))
        J = ans["J_required"] * 0.6          # J_доп ≈ J_I would pass J_I − J_first only by luck
        rows.append(("copyJ" + vid, vid, dict(ans, J_required=J, J_flywheel=J)))
    got = graded(compressor / "answers.json", write_sheet(tmp_path / "s.csv", key, rows),
                 "--carried-forward", "1")
    for s in got.values():
        assert "carried" not in verdicts(s).values(), s
        assert s["carried_forward"] == 0


def test_carried_forward_share_is_checked(compressor, tmp_path):
    key = key_of(compressor)
    sheet = write_sheet(tmp_path / "s.csv", key, [("a", "01", key["variants"]["01"])])
    for bad in ("1.5", "-0.1", "nan"):
        res = runner.invoke(app, ["grade", str(compressor / "answers.json"), str(sheet),
                                  "--carried-forward", bad])
        assert res.exit_code == 2, res.output
        assert "--carried-forward" in res.output and "Traceback" not in res.output


def test_a_key_without_a_chain_grades_as_before(compressor, tmp_path):
    key = key_of(compressor)
    bare = {vid: ans for vid, ans in key["variants"].items()}
    (tmp_path / "k.json").write_text(json.dumps(bare), encoding="utf-8")
    vid, ans = next(iter(key["variants"].items()))
    wrong = dict(ans, delta_T_max=ans["delta_T_max"] * 1.3)
    wrong.update(textbook(data_of(compressor, vid), wrong["delta_T_max"]))
    got = graded(tmp_path / "k.json", write_sheet(tmp_path / "s.csv", key, [("a", vid, wrong)]))
    assert set(verdicts(got["a"]).values()) == {"pass", "fail"}


def test_a_broken_chain_in_the_key_is_one_line(compressor, tmp_path):
    key = key_of(compressor)
    key["chain"]["givens"]["01"]["phi"] = "nope"
    (tmp_path / "k.json").write_text(json.dumps(key), encoding="utf-8")
    sheet = write_sheet(tmp_path / "s.csv", key, [("a", "01", key["variants"]["01"])])
    res = runner.invoke(app, ["grade", str(tmp_path / "k.json"), str(sheet)])
    assert res.exit_code == 2 and "Traceback" not in res.output
    assert "chain.givens.01" in res.output
