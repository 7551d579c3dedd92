"""Tabulated kinematics (issue 5): the press of seed 004_112cd67daf63ceba.txt.

Every Мст1 … Мст13 and Iпр1 … Iпр12 is recomputed from the seed's inputs (cases/press.toml,
whose rows are the seed's printed V/ω1, ω/ω1 and cos arguments) and compared with the seed term
by term. Style: the seed's printed number beside the exact value the test pins; a printed term
passes if it is within half a unit of its last printed digit, a printed sum if it equals the sum
of its printed terms to that precision. Where the seed is wrong, ERRATA names the position, the
printed value and the correct one, and the test asserts both.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.dynamics import tabulated
from flywheel.dynamics.loads import LoadKey
from flywheel.cases.run import load_case, parse_case
from flywheel.cli import app
from flywheel.errors import CaseFileError
from flywheel.dynamics.pipeline import analyze

CASES = Path(__file__).resolve().parents[2] / "cases"
runner = CliRunner()
OMEGA1 = 2 * math.pi * 140 / 60          # 14.6608 rad/s; the seed: "2·3,14·140/60 = 14,65"


@pytest.fixture(scope="module")
def press():
    return load_case(CASES / "press.toml")


def _half_unit(printed: str) -> float:
    """Half a unit of the last printed digit: '0,053' -> 0.0005, '-8,9' -> 0.05, '0' -> 0."""
    if printed.lstrip("-") == "0":
        return 1e-12
    decimals = len(printed.split(",")[1]) if "," in printed else 0
    return 0.5 * 10.0 ** -decimals


def _num(printed: str) -> float:
    return float(printed.replace(",", "."))


# -- Мст: the seed's lines, term by term -------------------------------------------------------
# Each line of the seed: Мстi = −(G2·V·cos + G3·V·cos + G5·V·cos − F·V_B4) = −(t1 + t2 + t3 + t4).
# The printed terms are the reduced moments of G2, G3, G5 and the punch force (design sign:
# positive when it drives); the printed total is Мст (resisting positive).
# Hand check (cos to 6 digits):
#  1: 2500·0,025·cos180 = −62,5;  800·0,025·(−1) = −20;  1500·0 = 0                 → Мст1 = 82,5
#  2: 2500·0,032·cos128 = 80·(−0,615661) = −49,2529; 25,6·(−0,615661) = −15,7609;
#     1500·0,012·cos79 = 18·0,190809 = 3,4346                                     → 61,5793
#  3: 115·cos104 = 115·(−0,241922) = −27,8210; 36,8·(−0,241922) = −8,9027;
#     34,5·cos84,5 = 34,5·0,095846 = 3,3067                                       → 33,4171
#  4: cos90 = 0 thrice; −1750·0,05 = −87,5                                         → 87,5
#  5: 107,5·cos77 = 107,5·0,224951 = 24,1822; 34,4·0,224951 = 7,7383;
#     30·cos98,5 = 30·(−0,147809) = −4,4343; −5540·0,042 = −232,68               → 205,1937
#  6: 77,5·cos52 = 77,5·0,615661 = 47,7138; 24,8·0,615661 = 15,2684;
#     16,5·cos102 = 16,5·(−0,207912) = −3,4305                                    → −59,5516
#  7: 62,5 + 20 + 0                                                               → −82,5
#  8: 92,5·cos46 = 92,5·0,694658 = 64,2559; 29,6·0,694658 = 20,5619;
#     21·cos78 = 21·0,207912 = 4,3661                                             → −89,1839
#  9: 112,5·cos69,5 = 112,5·0,350207 = 39,3983; 36·0,350207 = 12,6075;
#     31,5·cos82 = 31,5·0,139173 = 4,3840                                         → −56,3897
# 10: cos90 = 0 thrice                                                            → 0
# 11: 115·cos110 = 115·(−0,342020) = −39,3323; 36,8·(−0,342020) = −12,5863;
#     33·cos97 = 33·(−0,121869) = −4,0217                                         → 55,9403
# 12: 90·cos132 = 90·(−0,669131) = −60,2218; 28,8·(−0,669131) = −19,2710;
#     21·cos101 = 21·(−0,190809) = −4,0070                                        → 83,4997
# 13: = 1                                                                         → 82,5
MST_EXACT = [82.5, 61.57929, 33.41707, 87.5, 205.19373, -59.55163, -82.5, -89.18393, -56.38975,
             0.0, 55.94035, 83.49970, 82.5]
MST_SEED = {  # position: (printed terms t1, t2, t3, t4 for G2, G3, G5, punch; printed Мст)
    1: (["-62,5", "-20", "0", "0"], "82,5"),
    2: (["-49,25", "-15,76", "3,43", "0"], "61,58"),
    3: (["-27,82", "-8,9", "3,31", "0"], "33,41"),
    4: (["0", "0", "0", "-87,5"], "87,5"),
    5: (["24,18", "7,74", "-4,43", "-232,68"], "205,19"),
    6: (["47,71", "15,27", "-3,43", "0"], "-59,55"),
    7: (["62,5", "20", "0", "0"], "-82,5"),
    8: (["64,26", "20,56", "4,37", "0"], "-89,19"),
    9: (["39,4", "12,61", "4,38", "0"], "-56,39"),
    10: (["0", "0", "0", "0"], "0"),
    11: (["-39,33", "-12,59", "-4,02", "0"], "47,9"),
    12: (["-60,22", "-19,27", "-4,01", "0"], "75,48"),
    13: (["-62,5", "-20", "0", "0"], "82,5"),
}
# The seed's wrong results: (quantity, position) -> (printed, correct). Every term of these lines
# is right; the final additions are not.
ERRATA = {
    # Мст11 = −(−39,33 − 12,59 − 4,02) = +55,94, printed 47,9
    ("Мст", 11): ("47,9", 55.94035),
    # Мст12 = −(−60,22 − 19,27 − 4,01) = +83,50, printed 75,48
    ("Мст", 12): ("75,48", 83.49970),
    # Iпр10: the rocker's term 2,251·0,238² = 2,251·0,056644 = 0,1275 is printed 0,126 (position 4,
    # with the same inputs, prints 0,128), so Iпр10 = 0,842 + 0 + 0,1275 + 0,255 = 1,2243,
    # printed 1,223
    ("Iпр", 10): ("1,223", 1.224256),
    # Iпр2: the rod's rotation term 7,653·0,082² = 7,653·0,006724 = 0,05146 is printed 0,052 (it
    # rounds to 0,051), so Iпр2 = 0,34478 + 0,05146 + 0,02977 + 0,06375 = 0,4898, printed 0,491
    ("Iпр", 2): ("0,491", 0.489759),
}


def test_static_moments_every_position(press):
    """Мст1 … Мст13 from the seed's inputs; each printed term checked, each printed sum checked,
    the two wrong sums named."""
    mst = tabulated.static_moments(press.tabulated)
    assert mst.size == 13
    np.testing.assert_allclose(mst, MST_EXACT, atol=5e-6)
    parts = tabulated.load_moments_at_positions(press.tabulated)
    terms = np.column_stack([parts[LoadKey("force", n)] for n in ("G2", "G3", "G5", "punch")])
    for pos, (printed_terms, printed_total) in MST_SEED.items():
        i = pos - 1
        for k, t in enumerate(printed_terms):
            assert terms[i, k] == pytest.approx(_num(t), abs=_half_unit(t)), (pos, k, t)
        # the printed total against the sum of its own printed terms
        own = -sum(_num(t) for t in printed_terms)
        if ("Мст", pos) in ERRATA:
            printed, correct = ERRATA[("Мст", pos)]
            assert printed == printed_total
            assert abs(_num(printed) - own) > 1, f"Мст{pos}: the seed prints {printed}"
            assert mst[i] == pytest.approx(correct, abs=1e-4), \
                f"Мст{pos}: printed {printed}, correct {mst[i]:.2f}"
        else:
            assert own == pytest.approx(_num(printed_total), abs=1e-9), pos
            # and the exact value within the rounding of three or four printed terms
            assert mst[i] == pytest.approx(_num(printed_total), abs=0.025), pos


def test_static_moments_checked_by_hand_at_5_6_8_12(press):
    """The lines worth a second look: Мст5 and Мст6 change sign conventions (the punch's force,
    cos of obtuse angles), Мст8 rounds, Мст12 is wrong."""
    mst = tabulated.static_moments(press.tabulated)
    c = lambda d: math.cos(math.radians(d))       # noqa: E731
    assert mst[4] == pytest.approx(-(3300 * 0.043 * c(77) + 1500 * 0.02 * c(98.5) - 5540 * 0.042))
    assert mst[4] == pytest.approx(205.19, abs=0.005)    # seed: 205,19 (right)
    assert mst[5] == pytest.approx(-(3300 * 0.031 * c(52) + 1500 * 0.011 * c(102)))
    assert mst[5] == pytest.approx(-59.55, abs=0.005)    # seed: −59,55 (right)
    assert mst[7] == pytest.approx(-89.184, abs=5e-4)    # seed: −89,19 (sum of rounded terms)
    assert mst[11] == pytest.approx(83.4997, abs=5e-4)   # seed: 75,48 (wrong)


# -- Iпр: eq. (9), Iпр = 336,7·(VB2/ω1)² + 7,653·(ω2/ω1)² + 2,251·(ω5/ω1)² + 102·(VB4/ω1)² -------
# Hand check, term by term (336,7 = m2 + m3 = 255,1 + 81,6, the seed's eq. 9):
#  1: 336,7·0,000625 = 0,21044; 7,653·0,006889 = 0,05272; 0; 0                  = 0,26316
#  2: 336,7·0,001024 = 0,34478; 7,653·0,006724 = 0,05146; 2,251·0,013225 = 0,02977;
#     102·0,000625 = 0,06375                                                   = 0,48976
#  3: 336,7·0,002116 = 0,71246; 7,653·0,0025 = 0,01913; 2,251·0,0484 = 0,10895;
#     102·0,001936 = 0,19747                                                   = 1,03801
#  4: 336,7·0,0025 = 0,84175; 0; 2,251·0,056644 = 0,12751; 102·0,0025 = 0,255   = 1,22426
#  5: 336,7·0,001849 = 0,62256; 7,653·0,002601 = 0,01991; 2,251·0,037249 = 0,08385;
#     102·0,001764 = 0,17993                                                   = 0,90624
#  6: 336,7·0,000961 = 0,32357; 7,653·0,006241 = 0,04776; 2,251·0,011449 = 0,02577;
#     102·0,000576 = 0,05875                                                   = 0,45585
#  7: = 1                                                                      = 0,26316
#  8: 336,7·0,001369 = 0,46094; 7,653·0,004624 = 0,03539; 2,251·0,016641 = 0,03746;
#     102·0,000784 = 0,07997                                                   = 0,61376
#  9: 336,7·0,002025 = 0,68182; 7,653·0,001225 = 0,00937; 2,251·0,038809 = 0,08736;
#     102·0,001764 = 0,17993                                                   = 0,95848
# 10: = 4                                                                      = 1,22426
# 11: 0,71246; 0,00937; 2,251·0,0441 = 0,09927; 102·0,001849 = 0,18860           = 1,00970
# 12: 336,7·0,001296 = 0,43636; 7,653·0,003844 = 0,02942; 2,251·0,017689 = 0,03982;
#     102·0,000729 = 0,07436                                                   = 0,57996
IPR_EXACT = [0.263159, 0.489759, 1.038010, 1.224256, 0.906239, 0.455855, 0.263159, 0.613757,
             0.958479, 1.224256, 1.009699, 0.579957]
IPR_SEED = {  # position: (printed terms: rod + slider translation, rod rotation, rocker, punch; total)
    1: (["0,21", "0,053", "0", "0"], "0,263"),
    2: (["0,345", "0,052", "0,030", "0,064"], "0,491"),
    3: (["0,712", "0,019", "0,109", "0,197"], "1,037"),
    4: (["0,842", "0", "0,128", "0,255"], "1,225"),
    5: (["0,623", "0,02", "0,084", "0,180"], "0,907"),
    6: (["0,324", "0,048", "0,026", "0,059"], "0,457"),
    7: (["0,210", "0,053", "0", "0"], "0,263"),
    8: (["0,461", "0,035", "0,037", "0,08"], "0,613"),
    9: (["0,682", "0,01", "0,087", "0,18"], "0,959"),
    10: (["0,842", "0", "0,126", "0,255"], "1,223"),
    11: (["0,712", "0,01", "0,099", "0,189"], "1,01"),
    12: (["0,436", "0,029", "0,04", "0,074"], "0,579"),
}
IPR_TERM_SLIPS = {(2, 1): 0.05146, (10, 2): 0.12751}   # (position, term): correct value


def test_reduced_inertia_every_position(press):
    """Iпр1 … Iпр12 from the seed's inputs; each printed term and sum checked; the slips named."""
    spec = press.tabulated
    ipr = tabulated.reduced_inertia_at_positions(spec)
    np.testing.assert_allclose(ipr[:12], IPR_EXACT, atol=1e-6)
    assert ipr[12] == ipr[0]                                   # position 13 closes the cycle
    parts = tabulated.link_inertia_at_positions(spec)
    terms = np.column_stack([parts["2"] + parts["3"] - 7.653 * np.asarray(spec.omega_q["2"]) ** 2,
                             7.653 * np.asarray(spec.omega_q["2"]) ** 2, parts["5"], parts["4"]])
    for pos, (printed_terms, printed_total) in IPR_SEED.items():
        i = pos - 1
        for k, t in enumerate(printed_terms):
            if (pos, k) in IPR_TERM_SLIPS:
                correct = IPR_TERM_SLIPS[(pos, k)]
                assert terms[i, k] == pytest.approx(correct, abs=5e-6)
                assert abs(terms[i, k] - _num(t)) > _half_unit(t), \
                    f"Iпр{pos}, term {k + 1}: printed {t}, correct {correct}"
            else:
                assert terms[i, k] == pytest.approx(_num(t), abs=_half_unit(t)), (pos, k, t)
        # every printed total is the sum of its printed terms (the slips are in the terms)
        assert sum(_num(t) for t in printed_terms) == pytest.approx(_num(printed_total), abs=1e-9)
        if ("Iпр", pos) in ERRATA:
            printed, correct = ERRATA[("Iпр", pos)]
            assert ipr[i] == pytest.approx(correct, abs=1e-6), \
                f"Iпр{pos}: printed {printed}, correct {ipr[i]:.4f}"
        else:   # within the rounding of four printed terms
            assert ipr[i] == pytest.approx(_num(printed_total), abs=0.0025), pos


def test_seed_constants(press):
    """m = G/g with g = 9,8; I2 = m2·l2²/12, I5 = m5·l5²/3 (seed eq. 8); ω1 from 140 rpm."""
    links = press.tabulated.links
    assert links["2"].mass == pytest.approx(2500 / 9.8, abs=0.05)               # 255,1
    assert links["3"].mass == pytest.approx(800 / 9.8, abs=0.05)                # 81,6
    assert links["4"].mass == pytest.approx(1000 / 9.8, abs=0.05)               # 102
    assert links["2"].J == pytest.approx(255.1 * 0.6**2 / 12, abs=5e-4)        # 7,653
    # I5 with the seed's rounded m5 = 153,1 (1500/9,8 = 153,06 would give 2,250)
    assert links["5"].J == pytest.approx(153.1 * 0.21**2 / 3, abs=5e-4)        # 2,251
    assert links["2"].mass + links["3"].mass == pytest.approx(336.7)           # eq. (9)
    assert press.machine.omega_mean == pytest.approx(OMEGA1)
    # the seed: ω1 = 2·3,14·140/60 = 14,65 and ω1²/2 = 107,3113 (π = 3,14 and ω1 rounded);
    # exactly 14,6608 rad/s and 107,469 rad²/s², 0,15 % more
    assert OMEGA1**2 / 2 == pytest.approx(107.469, abs=5e-4)
    assert 14.65**2 / 2 == pytest.approx(107.3113, abs=1e-4)


# -- Мдин = ω1²/2·dIпр/dφ ----------------------------------------------------------------------

def test_dynamic_moment_by_finite_differences(press):
    """The seed's eq. (10) on the 12 positions: I′i = (I_{i+1} − I_i)/(π/6), Мдин_i = ω1²/2·I′i.
    (The seed's own I′пр1 … I′пр20 use positions it does not print, so they are not comparable.)"""
    spec = press.tabulated.model_copy(update={"interpolation": "finite-differences"})
    I = np.array(IPR_EXACT + IPR_EXACT[:1])
    expected = OMEGA1**2 / 2 * np.diff(I) / (math.pi / 6)
    # e.g. position 1: 107,469·(0,48976 − 0,26316)/0,523599 = 107,469·0,43277 = 46,510
    assert expected[0] == pytest.approx(46.5098, abs=5e-4)
    mdyn = tabulated.dynamic_moments(spec, OMEGA1)
    np.testing.assert_allclose(mdyn[:12], expected, rtol=1e-5)    # IPR_EXACT has 6 decimals
    # the same numbers come out of the whole analysis, at every position of positions.csv
    case = press.model_copy(update={"tabulated": spec})
    r = analyze(case, n_points=720)
    col = r.columns["M_dyn"].values
    got = [col[r.index_of(phi)] for phi in (p.phi for p in r.position_angles[:12])]
    np.testing.assert_allclose(got, mdyn[:12], rtol=1e-9)


def test_dynamic_moment_by_periodic_spline(press):
    """Default: the derivative of the periodic spline through Iпр; the column at each position
    equals tabulated.dynamic_moments, and the spline's derivative agrees in sign with the
    central difference at every position."""
    r = analyze(press, n_points=720)
    mdyn = tabulated.dynamic_moments(press.tabulated, OMEGA1)
    col = r.columns["M_dyn"].values
    got = np.array([col[r.index_of(phi)] for phi in (p.phi for p in r.position_angles)])
    np.testing.assert_allclose(got, mdyn, rtol=1e-9, atol=1e-9)
    I = np.array(IPR_EXACT)
    central = OMEGA1**2 / 2 * (np.roll(I, -1) - np.roll(I, 1)) / (math.pi / 3)
    assert np.all(np.sign(central[np.abs(central) > 5]) == np.sign(mdyn[:12][np.abs(central) > 5]))


# -- the whole analysis ------------------------------------------------------------------------

def test_positions_carry_static_moment_and_inertia(press):
    """positions.csv: one row per table position, with Мст (M_st) and Iпр (J_II) exactly the
    recomputed values, the interpolants passing through the table."""
    from flywheel.render.tables import positions_csv

    r = analyze(press, n_points=720)
    rows = positions_csv(r).splitlines()
    header = rows[0].split(",")
    assert len(rows) == 14 and rows[1].startswith("1 (0°),") and rows[13].startswith("13 (360°),")
    i_mst, i_j = header.index("M_st [N·m]"), header.index("J_II [kg·m²]")
    mst = [float(row.split(",")[i_mst]) for row in rows[1:]]
    jii = [float(row.split(",")[i_j]) for row in rows[1:]]
    np.testing.assert_allclose(mst, MST_EXACT, atol=5e-6)
    np.testing.assert_allclose(jii[:12], IPR_EXACT, atol=1e-6)
    # cycle balance: the driving moment is the mean of Мст (trapezoid over the linear punch
    # moment, spline over the weights): the punch alone absorbs
    # (π/6)·(87,5 + 232,68) = 167,64 J, the weights' sampled moments almost nothing
    assert r.scalars.driving_moment == pytest.approx(-r.scalars.cycle_work_resistance / (2 * math.pi))
    assert -r.scalars.cycle_work_resistance == pytest.approx(167.64, rel=0.02)


def test_run_json_contract(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "press.toml"), "--no-plots", "--json",
                              "--out", str(tmp_path / "o"), "--points", "720"])
    assert res.exit_code == 0, res.output
    r = json.loads(res.stdout)["results"]
    for key in ("omega_mean", "cycle_work_resistance", "driving_moment", "delta_T_max",
                "J_II_mean", "J_required", "J_required_exact", "J_flywheel", "delta_achieved"):
        assert isinstance(r[key], float), key
    assert r["crank_length"] == 0.05            # inferred in the case, reported only
    assert set(r["flywheel_disk"]) >= {"D", "b", "mass"}
    assert set(r["flywheel_rim"]) >= {"D", "D_inner", "b", "mass"}
    assert r["kinematics"] == "tabulated"
    a = r["at"][0]
    assert a["phi_deg"] == 120.0
    assert set(a["points"]) == {"B2", "S5", "B4"} and set(a["links"]) == {"2", "5"}
    assert a["points"]["B4"]["v_q"] == pytest.approx(0.042)      # position 5 of the table
    assert a["points"]["B4"]["v"] == pytest.approx(0.042 * a["omega"])
    assert a["links"]["5"]["omega_q"] == pytest.approx(0.193)
    assert a["M_st"] == pytest.approx(205.19373, abs=1e-5)
    assert 0.04 < r["delta_achieved"] <= 0.05 + 1e-9
    assert r["J_required_exact"] == pytest.approx(r["J_required"], rel=0.1)
    assert (tmp_path / "o" / "positions.csv").exists()


def test_run_rich_summary(tmp_path):
    res = runner.invoke(app, ["run", str(CASES / "press.toml"), "--no-plots", "--out",
                              str(tmp_path / "o"), "--points", "360"])
    assert res.exit_code == 0, res.output
    # point B4 lettered as the figures and the sheets letter it, its digit a subscript
    assert "B₄" in res.output and "B4" not in res.output and "written" in res.output


def test_check_prints_the_table():
    res = runner.invoke(app, ["check", str(CASES / "press.toml")])
    assert res.exit_code == 0, res.output
    assert "Tabulated kinematics" in res.output and "case is valid" in res.output
    assert "0.238" in res.output


def test_transients_run(press):
    r = analyze(press, n_points=720, transients=True)
    assert r.scalars.time_domain.verification.max_deviation < 1e-3


# -- bad input: one line, exit 2 ----------------------------------------------------------------

BASE = (CASES / "press.toml").read_text(encoding="utf-8")


def _bad(tmp_path, old: str, new: str, *fragments: str):
    assert old in BASE, old
    path = tmp_path / "bad.toml"
    path.write_text(BASE.replace(old, new, 1), encoding="utf-8")
    res = runner.invoke(app, ["run", str(path), "--no-plots", "--out", str(tmp_path / "o")])
    assert res.exit_code == 2, res.output
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), res.stderr
    for f in (str(path),) + fragments:
        assert f in lines[0], lines[0]
    assert "Traceback" not in res.output
    assert not (tmp_path / "o").exists()
    return lines[0]


POS = "positions_deg    = [  0,   30,   60,   90,  120,   150,   180,   210,   240,   270,   300,   330,   360]"


def test_positions_that_do_not_cover_the_cycle(tmp_path):
    # 13 values kept, so no row has the wrong length: the cycle stops at 180°
    _bad(tmp_path, POS, "positions_deg = [0, 15, 30, 45, 60, 75, 90, 105, 120, 135, 150, 165, 180]",
         "tabulated.positions_deg", "do not cover the cycle", "180° and 0°")


def test_duplicated_angle(tmp_path):
    _bad(tmp_path, POS, "positions_deg = [0, 30, 60, 90, 120, 150, 180, 210, 240, 270, 300, 300, 360]",
         "tabulated.positions_deg[11]", "duplicated angle 300°")


def test_fewer_than_six_positions(tmp_path):
    data = {"machine": {"speed_rpm": 60.0, "delta": 0.05},
            "tabulated": {"positions_deg": [0, 72, 144, 216, 288, 360]}}
    with pytest.raises(CaseFileError, match=r"^x\.toml: tabulated\.positions_deg: 5 distinct "
                                            r"positions are too few \(allowed: 6 or more\)$"):
        parse_case(data, "x.toml")


def test_no_positions_at_all(tmp_path):
    _bad(tmp_path, POS, "positions_deg = []", "tabulated.positions_deg: no positions",
         "allowed: 6 or more")


def test_values_that_overflow_are_named(tmp_path):
    # finite in the file, but 255.1·(1e200)² is not a number any more
    _bad(tmp_path, "B2 = [0.025, 0.032,", "B2 = [0.025, 1e200,", "tabulated.links.2:",
         "overflows at position 2 (30°)")


def test_a_machine_without_inertia_is_refused(tmp_path):
    # every analogue 0: no J_II, no load fluctuation, so no flywheel and nothing to turn
    import re

    head, links = BASE.split("[tabulated.links]")
    zero = re.sub(r"^(\s*(?!positions_deg)\"?\w+\"?\s*=\s*)\[([-\d.,\s]*)\]",
                  lambda m: m.group(1) + "[" + ", ".join("0" for _ in m.group(2).split(",")) + "]",
                  head, flags=re.M)
    assert POS in zero and "B2 = [0, 0," in zero
    text = zero + "[tabulated.links]" + links
    path = tmp_path / "still.toml"
    path.write_text(text, encoding="utf-8")
    res = runner.invoke(app, ["run", str(path), "--no-plots", "--out", str(tmp_path / "o")])
    assert res.exit_code == 2, res.output
    assert res.stderr.startswith(f"error: {path}: the machine has no inertia"), res.stderr
    assert len(res.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "o").exists()


def test_mass_without_velocity_analogues(tmp_path):
    _bad(tmp_path, '"4" = { mass = 102.0, point = "B4" }', '"4" = { mass = 102.0 }',
         "tabulated.links.4.point", "no velocity analogues")
    _bad(tmp_path, '"4" = { mass = 102.0, point = "B4" }', '"4" = { mass = 102.0, point = "B5" }',
         "tabulated.links.4.point", "'B5' are missing from [tabulated.points]")
    _bad(tmp_path, '"5" = { J = 2.251 }', '"6" = { J = 2.251 }',
         "tabulated.links.6.omega_q", "no row '6'")


def test_row_of_the_wrong_length(tmp_path):
    _bad(tmp_path, "B4 = [0,     0.025,", "B4 = [0.025,",
         "tabulated.points.B4", "needs 13 values", "got 12")
    _bad(tmp_path, "magnitude = [0, 0, 0, 1750, 5540, 0, 0, 0, 0, 0, 0, 0, 0]",
         "magnitude = [0, 0, 0, 1750, 5540, 0, 0, 0, 0, 0, 0, 0]",
         "tabulated.forces[3].magnitude", "needs 13 values")


def test_closing_row_must_repeat_the_first(tmp_path):
    _bad(tmp_path, "0.021, 0.025, 0.022, 0.014, 0]", "0.021, 0.025, 0.022, 0.014, 0.001]",
         "tabulated.points.S5[12]", "must repeat the value at 0°")


def test_crank_and_table_together_or_neither(tmp_path):
    _bad(tmp_path, "[tabulated]\n", '[crank]\nlength = 0.05\n\n[tabulated]\n',
         "give exactly one of [crank] (a linkage) and [tabulated]")
    _bad(tmp_path, "[tabulated]\n", '[[dyads]]\nkind = "RRP"\nfrom = "A"\njoint = "B"\nrod = "2"\n'
                                    'slider = "3"\nguide = { angle_deg = 0.0 }\n\n[tabulated]\n',
         "dyads: not allowed with [tabulated]")


def test_unknown_key_in_the_table(tmp_path):
    _bad(tmp_path, 'interpolation    = "periodic-spline"', 'interpolaton = "periodic-spline"',
         "tabulated.interpolaton", "did you mean 'interpolation'")


def test_bad_entry_of_a_per_position_row_is_named_by_index(tmp_path):
    # angle_deg is "one number or one per position": the error names the entry, not the union
    row = "angle_deg = [180, 128, 104"
    _bad(tmp_path, row, 'angle_deg = [180, "128", 104', "tabulated.forces[0].angle_deg[1]:",
         "must be a number, written without quotes (a decimal point, not a comma): 128 (got '128')")
    _bad(tmp_path, row, "angle_deg = [180, inf, 104", "tabulated.forces[0].angle_deg[1]:",
         "must be a finite number (got inf)")
    _bad(tmp_path, "B2 = [0.025, 0.032,", "B2 = [0.025, true,", "tabulated.points.B2[1]:",
         "valid number (got True)")


def test_negative_velocity_analogue(tmp_path):
    _bad(tmp_path, "B2 = [0.025, 0.032,", "B2 = [0.025, -0.032,", "tabulated.points.B2[1]",
         "magnitudes")


# -- plots: no geometry to draw -----------------------------------------------------------------

def test_plots_skip_the_geometry(press, tmp_path):
    from flywheel.render.plots import figures

    r = analyze(press, n_points=360)
    names = [n for n, _ in figures(r)]
    assert names == ["J_II.png", "reduced_moments.png", "works.png", "omega.png", "epsilon.png"]


# -- issue 5, item 5: what the graphical method costs --------------------------------------------

def _compressor_as_table(case, exact, n: int, loads: str = "linear") -> dict:
    """The compressor's exact kinematics sampled at n positions (|V_q| of S2, B, S4, C; ω_q of
    links 2, 4) and its reduced moments (gas HP, gas LP, gravity) sampled as moments per position:
    the table a student would draw, without drawing errors."""
    from flywheel.cases.run import to_mechanism
    from flywheel.linkage import solve

    pos = [k * 360.0 / n for k in range(n)]
    kin = solve(to_mechanism(case), np.radians(pos))
    idx = [exact.index_of(math.radians(p)) for p in pos]
    return {
        "title": "compressor, tabulated", "machine": case.machine.model_dump(),
        "flywheel": case.flywheel.model_dump(),
        "tabulated": {
            "positions_deg": pos,
            "points": {p: np.hypot(*kin.points[p].v_q.T).tolist() for p in ("S2", "B", "S4", "C")},
            "omega_q": {k: kin.links[k].omega_q.tolist() for k in ("2", "4")},
            "links": {"2": {"mass": 0.8, "point": "S2", "J": 0.21}, "3": {"mass": 0.6, "point": "B"},
                      "4": {"mass": 0.8, "point": "S4", "J": 0.21}, "5": {"mass": 1.0, "point": "C"}},
            "moments": [{"name": str(k), "values": [float(v[i]) for i in idx], "interpolation": loads}
                        for k, v in exact.M_parts.items()],
        },
    }


def test_graphical_method_cost_on_the_compressor():
    """cases/compressor.toml through the tabulated route, from 12 positions every 30°, against
    the exact route (3600 intervals). Measured (δ = 0.05, the indicator tables joined by PCHIP,
    J_required ≈ 4.642 kg·m² exact):

    ============  ===============  =======================
    positions     J_required       J_II (max error)
    ============  ===============  =======================
    12, linear    −6.8 %           0.24 %
    12, spline    −4.6 %
    24, linear    −1.7 %
    72, linear    −0.1 %
    ============  ===============  =======================

    (loads joined linearly or by a periodic spline; J_II by the periodic spline.) The inertia
    side costs nothing worth noting: J_II is small beside J_I, and its spline through 12 exact
    values is close. The cost is in the loads: 12 samples miss the peaks of the gas moments
    (the valves open between positions), so the cycle work and ΔT_нб come out low and the
    flywheel ~7 % too small. The seed's own 12-position press table carries the same risk.
    """
    case = load_case(CASES / "compressor.toml")
    exact = analyze(case)
    e = exact.scalars

    def pct(n, loads="linear"):
        r = analyze(parse_case(_compressor_as_table(case, exact, n, loads)))
        return r, 100 * (r.scalars.J_required / e.J_required - 1)

    r12, p12 = pct(12)
    _, p12s = pct(12, "periodic-spline")
    _, p24 = pct(24)
    _, p72 = pct(72)
    J_err = np.max(np.abs(r12.columns["J_II"].values - exact.columns["J_II"].values)) / e.J_II_max
    report = (f"J_required, tabulated vs exact: 12 positions {p12:+.2f} % (loads linear), "
              f"{p12s:+.2f} % (loads spline); 24: {p24:+.2f} %; 72: {p72:+.2f} %; "
              f"J_II max error at 12 positions {100 * J_err:.2f} % of its max")
    print(report)
    assert -8.0 < p12 < -6.0, report
    assert -6.0 < p12s < -4.0, report
    assert abs(p24) < 2.0 and abs(p72) < 0.2 and abs(p72) < abs(p24) < abs(p12), report
    assert r12.scalars.J_II_mean == pytest.approx(e.J_II_mean, rel=1e-3), report
    assert J_err < 0.005, report
