"""Numbers are checked where they enter, in a physically meaningful range stated in the
message (issue 17: 1e308 lengths, 1e-298 speeds and the like reached the arithmetic and
overflowed), and unusual but allowed values are named in plausibility warnings."""
import tomllib
from pathlib import Path

import pytest

from flywheel.cases.run import parse_case, plausibility_warnings
from flywheel.errors import CaseFileError

CASES = Path(__file__).resolve().parents[2] / "cases"
BASE = tomllib.loads((CASES / "compressor.toml").read_text(encoding="utf-8"))


def _with(path: str, value):
    import copy

    doc = copy.deepcopy(BASE)
    node = doc
    parts = path.split(".")
    for p in parts[:-1]:
        node = node[int(p)] if isinstance(node, list) else node[p]
    last = parts[-1]
    if isinstance(node, list):
        node[int(last)] = value
    else:
        node[last] = value
    return doc


@pytest.mark.parametrize("path, value, fragment", [
    ("machine.speed_rps", 1e308, "machine.speed_rps: 1e+308 rev/s is out of range (allowed: 0.001 … 10000 rev/s)"),
    ("machine.speed_rps", 1e-298, "machine.speed_rps: 1e-298 rev/s is out of range"),
    ("design.rod_to_crank", 4e300, "design.rod_to_crank: 4e+300 is out of range (allowed: 0.001 … 1000)"),
    ("links.2.mass", 1e300, "links.2.mass: 1e+300 kg is out of range (allowed: 0 … 1e+06 kg)"),
    ("links.2.J_S", 1e30, "links.2.J_S: 1e+30 kg·m² is out of range"),
    ("machine.gravity", [0.0, -1e300], "machine.gravity: -1e+300 m/s² is out of range"),
    ("machine.first_group.crank", 1e300, "machine.first_group.crank: 1e+300 kg·m² is out of range"),
    ("cylinders.0.p_max", 1e300, "cylinders[0].p_max: 1e+300 Pa is out of range (allowed: 1 … 1e+10 Pa)"),
    ("cylinders.0.bore", 1e3, "cylinders[0].bore: 1000 m is out of range"),
    ("cylinders.0.towards_head", [-20.0] * 11, "cylinders[0].towards_head: p/p_max = -20 gives "),
    ("flywheel.density", 1e300, "flywheel.density: 1e+300 kg/m³ is out of range"),
])
def test_out_of_range_values_are_refused_with_the_range(path, value, fragment):
    with pytest.raises(CaseFileError) as e:
        parse_case(_with(path, value), "c.toml")
    assert str(e.value).startswith("c.toml: ") and fragment in str(e.value), str(e.value)


def test_a_length_of_1e308_is_refused_before_the_kinematics():
    doc = _with("dyads.0.rod_length", 1e308)
    with pytest.raises(CaseFileError, match=r"dyads\[0\]\.rod_length: 1e\+308 m is out of range "
                                            r"\(allowed: 1e-06 … 1000 m\)"):
        parse_case(doc, "c.toml")


def test_the_bundled_cases_raise_no_plausibility_warning():
    from flywheel.cases.run import load_case

    for name in ("compressor", "compressor_worksheet", "fourbar", "press", "slotted_link"):
        assert plausibility_warnings(load_case(CASES / f"{name}.toml")) == [], name


@pytest.mark.parametrize("path, value, fragment", [
    ("machine.delta", 1e-5, "machine.delta: δ = 1e-05 is outside the usual 1/300 … 1/5"),
    ("machine.delta", 0.5, "machine.delta: δ = 0.5 is outside the usual"),
    ("machine.speed_rps", 0.005, "outside the usual 1 … 20 000 rpm"),
    ("cylinders.0.away_from_head", [-0.05] + [0.3] * 10, "cylinders[0].away_from_head: p/p_max down to -0.05"),
])
def test_unusual_values_are_warned_about(path, value, fragment):
    warnings = plausibility_warnings(parse_case(_with(path, value), "c.toml"))
    assert any(fragment in w for w in warnings), warnings


def test_a_crank_in_millimetres_is_warned_about():
    doc = _with("crank.length", 0.0001)
    doc.get("design", {}).pop("mean_piston_speed", None)
    warnings = plausibility_warnings(parse_case(doc, "c.toml"))
    assert any("crank.length: 0.0001 m is unusually short" in w for w in warnings), warnings
