"""aggregate: a shaft end fixed to the frame (a boundary condition), branched systems, the nodes
and shapes of every mode, the equivalent length of a stepped shaft, frequencies in Hz and rpm.

Truths independent of the code: closed forms (a disc on a fixed shaft ω = √(c/J); two discs
ω = √(c·(J1 + J2)/(J1·J2)) with the node at L·J2/(J1 + J2) from disc 1; a disc between two fixed
ends; the symmetric branch), Holzer's transfer method (a residual torque, not an eigenproblem),
the limit of a huge inertia, and the worked examples of R.S. Khurmi & J.K. Gupta, ch. 24.
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel.cases.aggregate import load_aggregate_case, parse_aggregate_case, to_model
from flywheel.elastic.chain import coefficients, mass_matrix, stiffness_matrix, tree_transform
from flywheel.elastic.model import analyze
from flywheel.elastic.modes import natural_frequencies
from flywheel.errors import CaseFileError

CASES = Path(__file__).resolve().parents[2] / "cases"
G, D = 80e9, 0.05
GJ = G * math.pi * D ** 4 / 32          # C·J of a 50 mm steel shaft [N·m²]


def model(doc: dict):
    return to_model(parse_aggregate_case(doc, "x.toml"), "x.toml")


def result(doc: dict):
    return analyze(*model(doc))


def doc_of(doc: dict) -> dict:
    return result(doc).to_document()


def rotors(*spec):
    """[[rotors]] from (name, J) pairs; J None for a fixed end."""
    return [{"name": n, "fixed": True} if J is None else {"name": n, "J": J} for n, J in spec]


# -- a fixed end ---------------------------------------------------------------------------------

@pytest.mark.parametrize("frame_first", [True, False])
def test_fixed_free_single_disc(frame_first):
    # a disc of J on a shaft of length L fixed at its other end: ω = √(c/J), c = C·J_p/L; the
    # fixed end is the node, at the frame's end of the shaft
    J, L = 3.0, 1.2
    spec = [("frame", None), ("disc", J)] if frame_first else [("disc", J), ("frame", None)]
    d = doc_of({"rotors": rotors(*spec), "shafts": [{"G": G, "d": D, "L": L}]})
    w = math.sqrt(GJ / L / J)
    assert d["natural_frequencies_rad_s"] == [pytest.approx(w, rel=1e-14)]
    assert d["natural_frequencies_hz"] == [pytest.approx(w / (2 * math.pi), rel=1e-14)]
    assert d["natural_frequencies_rpm"] == [pytest.approx(w * 30 / math.pi, rel=1e-14)]
    assert d["fixed_ends"] == ["frame"] and [r["name"] for r in d["rotors"]] == ["disc"]
    assert d["mode_shapes"] == [[1.0]] and d["modes"][0]["shape"] == [1.0]
    (node,) = d["modes"][0]["nodes"]
    assert node["distance"] == (0.0 if frame_first else pytest.approx(L, rel=1e-15))
    assert node["fraction"] == (0.0 if frame_first else 1.0)
    assert d["a"] == [[J]] and d["c"] == [[pytest.approx(GJ / L, rel=1e-15)]]


def test_disc_between_two_fixed_ends_khurmi():
    # Khurmi & Gupta ch. 24: a flywheel (500 kg, k = 0.5 m) on a 50 mm vertical shaft fixed at
    # both ends, l1 = 0.9 m and l2 = 0.6 m (the figure as reproduced elsewhere; the book's
    # printed answer was not at hand, so none is asserted). The two parts hold the flywheel in
    # parallel: q = C·J·(1/l1 + 1/l2), ω = √(q/I) = 33.028 rad/s, 5.2565 Hz.
    case = load_aggregate_case(CASES / "aggregate_khurmi_fixed_flywheel.toml")
    r = analyze(*to_model(case))
    q = GJ * (1 / 0.9 + 1 / 0.6)
    w = math.sqrt(q / (500 * 0.5 ** 2))
    assert r.modes.rigid == 0
    assert r.modes.elastic.tolist() == [pytest.approx(w, rel=1e-14)]
    assert w / (2 * math.pi) == pytest.approx(5.2565, abs=5e-5)
    d = r.to_document()
    assert d["fixed_ends"] == ["upper end", "lower end"]
    nodes = d["modes"][0]["nodes"]
    assert [(n["between"], n["distance"]) for n in nodes] == [
        (["upper end", "flywheel"], 0.0), (["flywheel", "lower end"], pytest.approx(0.6))]


def _chain_doc(frame: bool, J_big: float | None = None) -> dict:
    spec = [("A", 0.15), ("B", 0.3), ("C", 0.09)]
    shafts = [{"G": 84e9, "d": 0.07, "L": 1.5}, {"G": 84e9, "d": 0.07, "L": 1.0}]
    if frame:
        spec.append(("ground", None))
        shafts.append({"G": 84e9, "d": 0.05, "L": 0.8})
    elif J_big is not None:
        spec.append(("ground", J_big))
        shafts.append({"G": 84e9, "d": 0.05, "L": 0.8})
    return {"rotors": rotors(*spec), "shafts": shafts}


def test_fixed_end_is_the_limit_of_a_huge_inertia():
    # what the old model faked: a huge rotor at the end. Its torsional frequencies tend to the
    # fixed end's as J → ∞ (the rigid-body mode aside), the error falling like 1/J
    fixed = result(_chain_doc(True)).modes
    assert fixed.rigid == 0 and len(fixed.elastic) == 3
    errs = []
    for J_big in (1e4, 1e6, 1e8):
        huge = result(_chain_doc(False, J_big)).modes
        assert huge.rigid == 1 and huge.omega[0] == 0.0
        errs.append(np.max(np.abs(huge.elastic[:3] / fixed.elastic - 1)))
    assert errs[0] < 1e-3 and errs[2] < 1e-8
    assert errs[1] < errs[0] / 50 and errs[2] < errs[1] / 50
    # and the shapes of the free rotors agree
    huge = result(_chain_doc(False, 1e8)).modes
    assert np.allclose(huge.elastic_shapes[:3, :3], fixed.elastic_shapes, atol=1e-6)


def _holzer(J, c, w, fixed_end: bool) -> float:
    """Holzer's table: amplitude 1 at the free first rotor, the torque passed on grows by
    ω²·J·θ at each rotor and twists each shaft by T/c. The residual — the torque beyond the
    last rotor (free end) or the angle at the frame (fixed end) — is zero at a natural
    frequency. Returned relative to the largest term."""
    theta, T, scale = 1.0, 0.0, 0.0
    for k, Jk in enumerate(J):
        T += w * w * Jk * theta
        scale = max(scale, abs(T))
        if k < len(c):
            theta -= T / c[k]
    if fixed_end:
        return abs(theta) / max(1.0, abs(T / c[-1]))
    return abs(T) / scale


def test_holzer_residual_vanishes_at_every_frequency():
    # fixed at the end: J = A, B, C and the shaft C–ground
    r = result(_chain_doc(True))
    ch = r.chain
    c_all = [*ch.c, float(ch.ground[-1])]
    for w in r.modes.elastic:
        assert _holzer(ch.J, c_all, w, True) < 1e-9
    # and free-free (Khurmi's three rotors)
    r = analyze(*to_model(load_aggregate_case(CASES / "aggregate_khurmi_three_rotor.toml")))
    for w in r.modes.elastic:
        assert _holzer(r.chain.J, r.chain.c, w, False) < 1e-9
    assert _holzer(r.chain.J, r.chain.c, 1.01 * r.modes.elastic[0], False) > 1e-3


def test_a_fixed_system_has_absolute_coordinates():
    r = result(_chain_doc(True))
    a, c = coefficients(r.chain)
    assert (a == mass_matrix(r.chain)).all() and (c == stiffness_matrix(r.chain)).all()
    assert r.chain.ground.tolist()[:2] == [0.0, 0.0] and r.chain.ground[2] > 0


# -- two discs, stepped shaft, equivalent length ------------------------------------------------

def test_two_disc_free_free_closed_form_and_node():
    # ω = √(c·(J1 + J2)/(J1·J2)); the node at l1 = L·J2/(J1 + J2) from disc 1 (Khurmi & Gupta,
    # ch. 24, two rotor system: l1·J1 = l2·J2)
    J1, J2, L = 5.0, 2.0, 1.4
    d = doc_of({"rotors": rotors(("1", J1), ("2", J2)), "shafts": [{"G": G, "d": D, "L": L}]})
    c = GJ / L
    assert d["natural_frequencies_rad_s"] == [pytest.approx(math.sqrt(c * (J1 + J2) / (J1 * J2)),
                                                            rel=1e-14)]
    (node,) = d["modes"][0]["nodes"]
    assert node["shaft"] == 0 and node["between"] == ["1", "2"]
    assert node["distance"] == pytest.approx(L * J2 / (J1 + J2), rel=1e-13)
    assert node["fraction"] == pytest.approx(J2 / (J1 + J2), rel=1e-13)
    assert d["modes"][0]["shape"] == d["mode_shapes"][0]


def test_stepped_shaft_equivalent_length_and_node():
    # a shaft of 75, 50 and 37.5 mm over 0.275, 0.5 and 0.475 m between discs of 75 and
    # 50 kg·m² (one material): the torsionally equivalent 75 mm shaft (Khurmi & Gupta ch. 24)
    # L_eq = 0.275 + 0.5·(75/50)⁴ + 0.475·(75/37.5)⁴ = 10.40625 m; the node at
    # L_eq·J2/(J1 + J2) = 4.1625 m of equivalent length from disc 1, i.e. beyond the first two
    # pieces (0.275 + 2.53125 m): 0.775 m + (4.1625 − 2.80625)·(37.5/75)⁴ m = 0.859766 m
    J1, J2 = 75.0, 50.0
    d = doc_of({"rotors": rotors(("1", J1), ("2", J2)),
                "shafts": [{"G": G, "segments": [{"d": 0.075, "L": 0.275}, {"d": 0.05, "L": 0.5},
                                                 {"d": 0.0375, "L": 0.475}]}]})
    L_eq = 0.275 + 0.5 * 1.5 ** 4 + 0.475 * 2 ** 4
    (shaft,) = d["shafts"]
    assert shaft["equivalent_length"] == pytest.approx(L_eq, rel=1e-14) and L_eq == 10.40625
    assert shaft["reference_diameter"] == 0.075 and shaft["length"] == pytest.approx(1.25)
    GJ1 = G * math.pi * 0.075 ** 4 / 32
    w = math.sqrt(GJ1 / L_eq * (J1 + J2) / (J1 * J2))
    assert d["natural_frequencies_rad_s"] == [pytest.approx(w, rel=1e-13)]
    l_eq1 = L_eq * J2 / (J1 + J2)
    (node,) = d["modes"][0]["nodes"]
    assert node["distance"] == pytest.approx(0.775 + (l_eq1 - 0.275 - 0.5 * 1.5 ** 4) / 2 ** 4,
                                             rel=1e-13)


def test_equivalent_length_behind_a_gear_pair():
    # a piece after the gear pair counts at the input speed: L·(d_ref/d)⁴/i²
    d = doc_of({"rotors": rotors(("1", 1.0), ("2", 1.0)),
                "shafts": [{"G": G, "i": 0.5, "segments": [{"d": 0.05, "L": 0.3},
                                                            {"d": 0.05, "L": 0.2, "side": "out"}]}]})
    assert d["shafts"][0]["equivalent_length"] == pytest.approx(0.3 + 0.2 / 0.25, rel=1e-14)
    assert d["shafts"][0]["gear_ratio"] == 0.5


def test_khurmi_three_rotor_nodes_in_the_document():
    # Khurmi & Gupta ch. 24, oil engine and pump: nodes 0.4356 m from A and 0.726 m from C in
    # the two-node mode (book values, printed to 0.1 mm and 1 mm); 277 Hz
    d = json.loads(_cli(CASES / "aggregate_khurmi_three_rotor.toml", "--json").stdout)
    two = d["modes"][1]
    assert two["natural_hz"] == pytest.approx(277, abs=0.5)
    ab, bc = two["nodes"]
    assert ab["between"] == ["A", "B"] and ab["distance"] == pytest.approx(0.4356, abs=1e-4)
    assert bc["between"] == ["B", "C"] and 1.0 - bc["distance"] == pytest.approx(0.726, abs=5e-4)
    assert two["natural_rpm"] == pytest.approx(two["natural_hz"] * 60, rel=1e-14)
    (one,) = d["modes"][0]["nodes"]                       # the single-node mode: l_A = 1.148 m
    assert one["between"] == ["A", "B"] and one["distance"] == pytest.approx(1.1477, abs=1e-4)


# -- branched systems ----------------------------------------------------------------------------

def test_branched_gear_closed_form():
    # cases/aggregate_branched_gear.toml: two equal branches (c, J) reduced to the engine (J0):
    # antisymmetric ω² = c/J with the engine a node; symmetric ω² = c·(J0 + 2J)/(J0·J) with a
    # node in each shaft at 2J/(2J + J0) of its compliance from the engine
    r = analyze(*to_model(load_aggregate_case(CASES / "aggregate_branched_gear.toml")))
    c, J, J0 = 1e4, 1.0, 2.0
    assert r.modes.rigid == 1 and r.modes.omega[0] == 0.0
    assert r.modes.elastic.tolist() == pytest.approx(
        [math.sqrt(c / J), math.sqrt(c * (J0 + 2 * J) / (J0 * J))], rel=1e-13)
    assert r.chain.J.tolist() == [2.0, 1.0, 1.0] and r.chain.ratio.tolist() == [1.0, 1.0, 0.5]
    d = r.to_document()
    assert d["modes"][0]["nodes"] == [{"shaft": None, "between": None, "fraction": None,
                                       "distance": None, "rotor": "engine"}]
    fr = [n["fraction"] for n in d["modes"][1]["nodes"]]
    assert fr == pytest.approx([2 * J / (2 * J + J0)] * 2, rel=1e-12)
    # the coefficients in q = (φ_engine, twist of each shaft): a = TᵀMT, c = diag(0, c, c)
    a, cc = coefficients(r.chain)
    T = tree_transform(r.chain)
    assert a == pytest.approx(T.T @ mass_matrix(r.chain) @ T, rel=1e-15)
    assert cc.tolist() == [[0.0, 0.0, 0.0], [0.0, c, 0.0], [0.0, 0.0, c]]


def test_branched_with_between_in_line_is_the_chain():
    # `between` naming consecutive rotors gives the same numbers as the default chain
    plain = {"rotors": rotors(("A", 1.0), ("B", 2.0), ("C", 0.5)),
             "shafts": [{"c": 100.0}, {"c": 300.0, "i": 2.0}]}
    named = {"rotors": plain["rotors"],
             "shafts": [{"c": 100.0, "between": ["A", "B"]},
                        {"c": 300.0, "i": 2.0, "between": ["B", "C"]}]}
    a, b = result(plain), result(named)
    assert a.modes.omega.tolist() == b.modes.omega.tolist()
    assert b.chain.ends is None and b.chain.is_line
    # written the other way round the same shaft reduces by the inverse ratio
    rev = {"rotors": plain["rotors"],
           "shafts": [{"c": 100.0, "between": ["A", "B"]},
                      {"c": 300.0 / 4.0, "i": 0.5, "between": ["C", "B"]}]}
    assert result(rev).modes.omega == pytest.approx(a.modes.omega, rel=1e-13)


def test_branch_with_a_fixed_end_and_a_gear():
    # a gear wheel (J0) held by a shaft to the frame (c0) drives two equal branches: the
    # antisymmetric mode ω² = c/J does not move the wheel; the symmetric one solves
    # J0·J·ω⁴ − (J0·c + J·(c0 + 2c))·ω² + c0·c = 0
    J0, J, c0, c = 2.0, 1.0, 5e3, 1e4
    # R turns twice as fast as the wheel: J/4 reduces to J
    r = result({"rotors": rotors(("frame", None), ("wheel", J0), ("L", J), ("R", J / 4)),
                "shafts": [{"c": c0, "between": ["frame", "wheel"]},
                           {"c": c, "between": ["wheel", "L"]},
                           {"c": c, "between": ["wheel", "R"], "i": 2.0}]})
    roots = np.roots([J0 * J, -(J0 * c + J * (c0 + 2 * c)), c0 * c])
    expect = sorted([math.sqrt(c / J), *np.sqrt(roots)])
    assert r.modes.rigid == 0
    assert r.modes.elastic.tolist() == pytest.approx(expect, rel=1e-12)


# -- errors -------------------------------------------------------------------------------------

@pytest.mark.parametrize("doc, message", [
    ({"rotors": rotors(("frame", None), ("disc", 1.0))},
     "x.toml: shafts: missing: the fixed end rotors[0] holds a rotor through a shaft"),
    ({"rotors": rotors(("frame", None), ("disc", 1.0)), "shafts": []},
     "x.toml: shafts: missing: the fixed end rotors[0]"),
    ({"rotors": [{"name": "frame", "fixed": True, "J": 1.0}, {"name": "d", "J": 1.0}],
      "shafts": [{"c": 1.0}]}, "rotors[0].J: a fixed end (fixed = true) is the frame"),
    ({"rotors": [{"name": "d"}, {"name": "e", "J": 1.0}], "shafts": [{"c": 1.0}]},
     "rotors[0].J: missing required field"),
    ({"rotors": rotors(("a", 1.0), ("frame", None), ("b", 1.0)),
      "shafts": [{"c": 1.0}, {"c": 1.0}]}, "rotors[1]: a fixed end is an end of the system"),
    ({"rotors": rotors(("f", None), ("g", None)), "shafts": [{"c": 1.0}]},
     "rotors: every rotor is fixed"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0)), "shafts": [{"c": 1.0, "between": ["a", "x"]}]},
     "shafts[0].between: unknown rotor 'x' (rotors: a, b)"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0)), "shafts": [{"c": 1.0, "between": ["a", "a"]}]},
     "shafts[0].between: joins rotor 'a' to itself"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0), ("c", 1.0)),
      "shafts": [{"c": 1.0, "between": ["a", "b"]}, {"c": 1.0}]},
     "shafts[1].between: missing: give between for every shaft or for none"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0), ("c", 1.0)),
      "shafts": [{"c": 1.0, "between": ["a", "b"]}, {"c": 1.0, "between": ["b", "a"]}]},
     "shafts: the rotors and shafts must form one connected system without loops: 'c'"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0)), "shafts": [{"c": 1.0, "between": ["a"]}]},
     "shafts[0].between: needs two rotor names"),
    ({"rotors": rotors(("frame", None), ("a", 1.0), ("b", 1.0)),
      "shafts": [{"c": 1.0}, {"c": 1.0}],
      "motor": {"synchronous_rpm": 1500.0, "starting_torque": 100.0}},
     "motor: a shaft fixed to the frame cannot turn continuously"),
    ({"rotors": rotors(("a", 1.0), ("b", 1.0), ("c", 1.0)),
      "shafts": [{"c": 1.0, "between": ["a", "b"]}, {"c": 1.0, "between": ["a", "c"]}],
      "motor": {"synchronous_rpm": 1500.0, "starting_torque": 100.0}},
     "motor: the forced vibration and the start-up are computed for an unbranched chain"),
    ({"rotors": rotors(("frame", None), ("a", 1.0)), "shafts": [{"c": 1.0, "damping": 2.0}]},
     "shafts[0].damping: a shaft to the frame"),
])
def test_errors_are_one_line(doc, message):
    with pytest.raises(CaseFileError) as exc:
        model(doc)
    text = str(exc.value)
    assert message in text and "\n" not in text and text.startswith("x.toml: ")


def _cli(*args):
    from flywheel.cli import app

    return CliRunner().invoke(app, ["aggregate", *map(str, args)])


def _err(res):
    try:
        return res.stderr
    except (ValueError, AttributeError):
        return res.output


def test_cli_fixed_end_without_a_shaft_is_one_line_exit_2(tmp_path):
    case = tmp_path / "f.toml"
    case.write_text('[[rotors]]\nname = "frame"\nfixed = true\n[[rotors]]\nJ = 2.0\n')
    res = _cli(case)
    assert res.exit_code == 2
    err = _err(res)
    assert err.startswith(f"error: {case}: shafts: missing: the fixed end rotors[0]")
    assert err.count("\n") == 1 and "Traceback" not in err


def test_cli_modes_table(tmp_path):
    res = _cli(CASES / "aggregate_khurmi_three_rotor.toml", "--modes")
    assert res.exit_code == 0, res.output
    assert "n [vib/min]" in res.stdout and "0.435667 m from A" in res.stdout
    plain = _cli(CASES / "aggregate_khurmi_three_rotor.toml")
    assert "vib/min" not in plain.stdout
    ru = _cli(CASES / "aggregate_khurmi_fixed_flywheel.toml", "--modes", "--lang", "ru")
    assert ru.exit_code == 0 and "заделка upper end" in ru.stdout and "кол/мин" in ru.stdout
    assert "в абсолютных углах" in ru.stdout
    fixed = _cli(CASES / "aggregate_khurmi_fixed_flywheel.toml")
    assert "rigid body" not in fixed.stdout and "(frame)" in fixed.stdout


def test_existing_keys_unchanged_and_new_keys_present():
    d = json.loads(_cli(CASES / "aggregate.toml", "--json").stdout)
    assert d["fixed_ends"] == [] and len(d["modes"]) == len(d["natural_frequencies_hz"]) == 1
    assert d["shafts"][0]["between"] == ["motor J_Д", "machine J_пр.I"]
    assert d["shafts"][0]["c"] == d["connections"][0]["c_reduced"] == 3000.0
    assert d["modes"][0]["natural_rpm"] == pytest.approx(d["natural_frequencies_hz"][0] * 60,
                                                         rel=1e-14)


def test_a_fixed_end_costs_no_more_than_a_free_end(monkeypatch):
    """The boundary condition removes a row and a column; nothing iterates. The work counted:
    one generalized eigenproblem each (scipy.linalg.eigh), the fixed chain's one order smaller
    than the free chain with a huge inertia instead, and no time integration in either (the
    timing of the two is in benchmarks/README.md, never asserted)."""
    import scipy.integrate
    import scipy.linalg

    sizes: dict[str, list[int]] = {}
    eigh, solve_ivp = scipy.linalg.eigh, scipy.integrate.solve_ivp
    which = ["?"]

    def counting_eigh(K, M=None, *args, **kwargs):
        sizes.setdefault(which[0], []).append(K.shape[0])
        return eigh(K, M, *args, **kwargs)

    def no_integration(*args, **kwargs):
        sizes.setdefault(which[0] + " solve_ivp", []).append(1)
        return solve_ivp(*args, **kwargs)

    monkeypatch.setattr(scipy.linalg, "eigh", counting_eigh)
    monkeypatch.setattr(scipy.integrate, "solve_ivp", no_integration)
    for name, doc in (("free", _chain_doc(False, 1e8)), ("fixed", _chain_doc(True))):
        which[0] = name
        ch, drive = model(doc)
        analyze(ch, drive)
    assert sizes == {"free": [4], "fixed": [3]}
    assert natural_frequencies(model(_chain_doc(True))[0]).rigid == 0
