"""The output link in summary.json, `flywheel check` and the record: exactly the contract's keys,
the numbers of the closed forms (the four-bar of cases/fourbar.toml: extremes where crank and
coupler are collinear), in both languages."""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.render.document import build_document
from flywheel.render.report import markdown
from helpers import flywheel_in_process

ROOT = Path(__file__).resolve().parents[2]
KEYS = {"link", "extremes_phi_deg", "time_ratio_K", "transmission_angle_min_deg",
        "phi_transmission_angle_min_deg"}


def _law(x, y, z):
    return math.degrees(math.acos((x * x + y * y - z * z) / (2 * x * y)))


@pytest.fixture(scope="module")
def fourbar():
    return analyze(load_case(ROOT / "cases" / "fourbar.toml"), n_points=360)


def test_summary_json_has_exactly_the_contract_keys(fourbar):
    doc = fourbar.to_document()["results"]["output_link"]
    assert set(doc) == KEYS | {"swing_deg"}
    theta = _law(0.5, 0.4, 0.3) - _law(0.3, 0.4, 0.3)     # ψ_ext − ψ_fold (a negative θ)
    assert doc["time_ratio_K"] == pytest.approx((180 - theta) / (180 + theta), rel=1e-12)
    slider = analyze(load_case(ROOT / "cases" / "shaper.toml"), n_points=360)
    assert set(slider.to_document()["results"]["output_link"]) == KEYS | {"stroke"}


def test_a_tabulated_case_has_none():
    res = analyze(load_case(ROOT / "cases" / "press.toml"), n_points=360)
    assert "output_link" not in res.to_document()["results"]


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_the_record_has_its_section(fourbar, lang):
    text = markdown(build_document(fourbar, lang))
    head = {"en": "### 2.1. Output link 3 (rocker)", "ru": "### 2.1. Выходное звено 3 (коромысло)"}
    assert head[lang] in text
    K = f"{fourbar.scalars.output_link.time_ratio_K:.6g}"
    assert ("K = 191.32/168.68 = " + K) in text


def test_check_prints_it():
    res = flywheel_in_process("check", ROOT / "cases" / "fourbar.toml", "--lang", "ru", cwd=ROOT,
                              columns=80)
    assert res.returncode == 0, res.stderr
    out = res.stdout
    assert "наименьший угол передачи γ_min = 48,19° при φ = 0°" in out    # Russian numbers
    assert "угол размаха коромысла ψ = 41,81°" in out
