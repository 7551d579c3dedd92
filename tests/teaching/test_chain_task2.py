"""Issue 27: the chain of a task2 template (cases/variants_task2.toml, «Задача 2»). The
dependent answers are computed here from the student's wrong earlier one by the textbook:
A(φ) = ∫(M_D − M_C)dφ on a fine grid of the triangle, ω = √(ω0² + 2A/J), δ = (ω_max −
ω_min)/ω_ср, J = ΔT_нб/(ω_ср²·δ); the grader must recompute them with its own chain."""
import math

import numpy as np
import pytest

from chain_helpers import data_of, graded, key_of, make, verdicts, write_sheet


@pytest.fixture(scope="module")
def task2(tmp_path_factory):
    return make(tmp_path_factory, "variants_task2.toml", count=3, seed=5)


def textbook(data, M_C):
    """ω_max, ω_min, δ, ΔT_нб and J_required of «Задача 2» with the triangle's peak M_C."""
    phi = np.linspace(0, 2 * math.pi, 400_001)
    a, b = math.radians(data["resistance"]["from_deg"]), math.radians(data["resistance"]["to_deg"])
    mid = (a + b) / 2
    tri = np.where((phi > a) & (phi < b), M_C * (1 - np.abs(phi - mid) / (mid - a)), 0.0)
    net = data["driving"]["value"] - tri
    A = np.concatenate([[0.0], np.cumsum((net[1:] + net[:-1]) / 2 * np.diff(phi))])
    J, w0 = data["flywheel"]["J"], data["speed"]["omega0"]
    w_max, w_min = math.sqrt(w0 ** 2 + 2 * A.max() / J), math.sqrt(w0 ** 2 + 2 * A.min() / J)
    w_m = (w_max + w_min) / 2
    dT = float(A.max() - A.min())
    return {"omega_max": w_max, "omega_min": w_min, "delta": (w_max - w_min) / w_m,
            "delta_T_max": dT, "J_required": dT / (w_m ** 2 * data["flywheel"]["delta"])}


def test_the_key_is_the_textbooks(task2):
    key = key_of(task2)
    for vid, ans in key["variants"].items():
        t = textbook(data_of(task2, vid), ans["M_C"])
        for a, v in t.items():
            assert v == pytest.approx(ans[a], rel=1e-7), a


def test_one_wrong_early_answer_carries_forward_exactly_to_the_dependent_ones(task2, tmp_path):
    key = key_of(task2)
    rows = []
    for vid, ans in key["variants"].items():
        data = data_of(task2, vid)
        wrong = dict(ans, M_C=ans["M_C"] * 1.5)
        wrong.update(textbook(data, wrong["M_C"]))          # every later one from the wrong M_C
        rows.append((f"M{vid}", vid, wrong))
        dT = dict(ans, delta_T_max=ans["delta_T_max"] * 1.2)  # ΔT_нб wrong, J_I from it
        dT["J_required"] = dT["delta_T_max"] / (((ans["omega_max"] + ans["omega_min"]) / 2) ** 2
                                                * data["flywheel"]["delta"])
        rows.append((f"T{vid}", vid, dT))
    sheet = write_sheet(tmp_path / "s.csv", key, rows)
    got = graded(task2 / "answers.json", sheet, "--carried-forward", "0.5")
    for vid, ans in key["variants"].items():
        wrong = textbook(data_of(task2, vid), ans["M_C"] * 1.5)
        # a 50 % wrong M_C may move ω_max or ω_min by less than their tolerance (0.05 %);
        # then they pass against the key itself
        expected = {a: "pass" if abs(wrong[a] - ans[a]) <= key["tolerances"].get(
            a, key["tolerance"]) * abs(ans[a]) else "carried" for a in wrong}
        assert verdicts(got[f"M{vid}"]) == {"M_C": "fail", **expected}
        assert list(expected.values()).count("carried") >= 3
        assert verdicts(got[f"T{vid}"]) == {
            "M_C": "pass", "omega_max": "pass", "omega_min": "pass", "delta": "pass",
            "delta_T_max": "fail", "J_required": "carried"}
        assert got[f"T{vid}"]["score"] == pytest.approx((4 + 0.5) / 6)


def test_a_wrong_M_carries_forward_to_delta_and_J_without_the_speeds(task2, tmp_path):
    """At a machine's δ (0.007 – 0.14 here) a 50 % wrong M_C moves ω_ср by a few per cent:
    δ and J worked from it are the student's own only with his own ω_ср. Where he gave ω_max
    and ω_min the grader takes their mean (the test above); where he left them blank it finds
    the M that gives his ΔT_нб and that motion's ω_ср (chain_task2.mean_speed_for)."""
    key = key_of(task2)
    rows, moved = [], []
    for vid, ans in key["variants"].items():
        wrong = dict(ans, M_C=ans["M_C"] * 1.5)
        wrong.update(textbook(data_of(task2, vid), wrong["M_C"]))
        rows.append((f"B{vid}", vid, wrong))
        moved.append(abs((wrong["omega_max"] + wrong["omega_min"])
                         / (ans["omega_max"] + ans["omega_min"]) - 1))
    # the key's ω_ср would not do: δ ∝ 1/ω_ср² from it would be off by more than its 1 %
    assert max(moved) > 0.005, moved
    path = tmp_path / "b.csv"
    write_sheet(path, key, rows)
    text = path.read_text(encoding="utf-8").splitlines()
    head = text[0].split(",")
    blank = [head.index("omega_max"), head.index("omega_min")]
    lines = [text[0]] + [",".join("" if k in blank else c for k, c in enumerate(ln.split(",")))
                         for ln in text[1:]]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    got = graded(task2 / "answers.json", path, "--carried-forward", "0.5")
    for vid in key["variants"]:
        v = verdicts(got[f"B{vid}"])
        assert v["M_C"] == "fail" and v["omega_max"] == v["omega_min"] == "no answer", v
        assert v["delta_T_max"] == v["delta"] == v["J_required"] == "carried", v


def test_copying_the_wrong_number_earns_nothing(task2, tmp_path):
    key = key_of(task2)
    vid, ans = next(iter(key["variants"].items()))
    wrong = dict(ans, delta_T_max=ans["delta_T_max"] * 1.2)
    wrong["J_required"] = wrong["delta_T_max"]              # the wrong ΔT_нб copied
    got = graded(task2 / "answers.json", write_sheet(tmp_path / "c.csv", key, [("c", vid, wrong)]))
    assert verdicts(got["c"])["J_required"] == "fail"


def test_rev_per_minute_for_rad_per_second_is_named(task2, tmp_path):
    key = key_of(task2)
    vid, ans = next(iter(key["variants"].items()))
    w_m = (ans["omega_max"] + ans["omega_min"]) / 2
    n = w_m * 30 / math.pi                                   # ω_ср in rev/min
    data = data_of(task2, vid)
    wrong = dict(ans, J_required=ans["delta_T_max"] / (n ** 2 * data["flywheel"]["delta"]),
                 delta=ans["delta_T_max"] / (data["flywheel"]["J"] * n ** 2))
    got = graded(task2 / "answers.json", write_sheet(tmp_path / "r.csv", key, [("r", vid, wrong)]))
    named = {a["answer"]: a["diagnosis"] for a in got["r"]["answers"]}
    assert named["J_required"] == "rpm_for_rad_s"
    assert named["delta"] == "rpm_for_rad_s"
