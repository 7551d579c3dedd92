"""The case loader (src/flywheel/case.py): bad input gives one CaseFileError line naming the file
and the field; equivalent spellings give the same case; the JSON Schema is well-formed.

Each bad file is cases/compressor.toml with one textual change, so every test shows exactly
what the user got wrong.
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from flywheel.cases.run import case_json_schema, load_case, parse_case, to_mechanism
from flywheel.errors import CaseFileError

CASES = Path(__file__).resolve().parents[2] / "cases"
BASE = (CASES / "compressor.toml").read_text(encoding="utf-8")
S_ROW = "s              = [0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1]"


def variant(tmp_path: Path, old: str, new: str, name: str = "bad.toml") -> Path:
    """cases/compressor.toml with the first ``old`` replaced by ``new``, written to tmp_path."""
    assert old in BASE, f"{old!r} is not in cases/compressor.toml"
    path = tmp_path / name
    path.write_text(BASE.replace(old, new, 1), encoding="utf-8")
    return path


def load_error(path: Path) -> str:
    """The message of the CaseFileError that loading ``path`` raises (one line, file first)."""
    with pytest.raises(CaseFileError) as exc:
        load_case(path)
    msg = str(exc.value)
    assert "\n" not in msg
    assert msg.startswith(f"{path}: ")
    return msg


BAD = [
    # (id, old text, new text, expected message after "FILE: ", as a regex)
    ("toml-syntax", "speed_rps = 10.0", "speed_rps = = 10.0",
     r"TOML syntax error: .* \(at line 10, column 13\)"),
    ("toml-duplicate-key", "delta     = 0.05", "delta     = 0.05\ndelta = 0.06",
     r"TOML syntax error: .*\(at line 12, column \d+\)"),
    ("unknown-key", "speed_rps = 10.0", "speed_rsp = 10.0",
     r"machine\.speed_rsp: unknown key; did you mean 'speed_rps'\? \(allowed: speed_rps, "),
    ("unknown-key-deg", "start_angle_deg = 90.0", "start_angle = 90.0",
     r"crank\.start_angle: unknown key; did you mean 'start_angle_deg'\?"),
    ("unknown-key-in-dyad", 'joint = "C"', 'joint = "C"\nrod_lenght = 0.4',
     r"dyads\[1\]\.rod_lenght: unknown key; did you mean 'rod_length'\?"),
    ("unknown-key-of-another-dyad-kind", 'slider = "5"', 'slider = "5"\nrocker = "9"',
     r"dyads\[1\]\.rocker: unknown key \(allowed: kind, name, from, joint, rod, rod_length, slider, "
     r"guide, branch\)$"),   # an RRP's own keys, not every dyad kind's
    ("unknown-key-in-guide", "angle_deg = 0.0 }", "angle_deg = 0.0, ofset = 0.1 }",
     r"dyads\[1\]\.guide\.ofset: unknown key; did you mean 'offset'\? \(allowed: through, angle_deg, offset\)"),
    ("unknown-top-level-key", "title  =", "titel  =",
     r"titel: unknown key; did you mean 'title'\?"),
    ("missing-field", "bore = 0.12                      # d2 [m]", "",
     r"cylinders\[0\]\.bore: missing required field"),
    ("misspelled-table", "[machine]", "[machin]",   # not "machine: missing": the cause comes first
     r"machin: unknown key; did you mean 'machine'\?"),
    ("misspelled-required-key", "bore = 0.12 ", "bor = 0.12 ",
     r"cylinders\[0\]\.bor: unknown key; did you mean 'bore'\?"),
    ("missing-speed", "speed_rps = 10.0", "", r"machine: give exactly one of speed_rps, speed_rpm"),
    ("both-speeds", "speed_rps = 10.0", "speed_rps = 10.0\nspeed_rpm = 600.0",
     r"machine: give exactly one of speed_rps, speed_rpm"),
    ("wrong-type-string", "bore = 0.12 ", 'bore = "wide" ',
     r"cylinders\[0\]\.bore: input should be a valid number.*\(got 'wide'\)"),
    # numbers are strict: a quoted number or a boolean is a mistake, not a number to convert
    ("quoted-number", "delta     = 0.05", 'delta     = "0.05"',
     r"machine\.delta: must be a number, written without quotes \(a decimal point, not a comma\): 0\.05 \(got '0\.05'\)"),
    ("boolean-as-number", "start_angle_deg = 90.0", "start_angle_deg = true",
     r"crank\.start_angle_deg: input should be a valid number \(got True\)"),
    ("boolean-in-a-pair", "through = [0.0, 0.0], angle_deg = 90.0", "through = [0.0, false], angle_deg = 90.0",
     r"dyads\[0\]\.guide\.through\[1\]: input should be a valid number \(got False\)"),
    ("wrong-type-list", "delta     = 0.05", "delta     = [0.05]",
     r"machine\.delta: input should be a valid number"),
    ("wrong-type-table", "guide = { through = [0.0, 0.0], angle_deg = 0.0 }", "guide = 5",
     r"dyads\[1\]\.guide: must be a table of keys, e\.g\. \{ key = value, … \} \(got 5\)"),
    ("wrong-kind", 'kind = "RRP"\nfrom = "A"\njoint = "C"', 'kind = "RPP"\nfrom = "A"\njoint = "C"',
     r"dyads\[1\]: kind must be one of RRP, RRR, RPR"),
    ("wrong-branch", "branch = \"+\"                     # B above A", 'branch = "up"',
     r"dyads\[0\]\.branch: input should be '\+' or '-' \(got 'up'\)"),
    ("nan", "bore = 0.12 ", "bore = nan ", r"cylinders\[0\]\.bore: must be a finite number \(got nan\)"),
    ("inf", "p_max = 0.882e6", "p_max = inf",
     r"cylinders\[0\]\.p_max: must be a finite number \(got inf\)"),
    ("minus-inf-angle", "start_angle_deg = 90.0", "start_angle_deg = -inf",
     r"crank\.start_angle_deg: must be a finite number \(got -inf\)"),
    ("nan-in-a-pair", "through = [0.0, 0.0], angle_deg = 90.0", "through = [0.0, nan], angle_deg = 90.0",
     r"dyads\[0\]\.guide\.through\[1\]: must be a finite number \(got nan\)"),
    ("zero-crank-length", "[crank]\n", "[crank]\nlength = 0.0\n",
     r"crank\.length: input should be greater than 0 \(got 0\.0\)"),
    ("negative-rod-length", 'slider = "5"', 'slider = "5"\nrod_length = -0.4',
     r"dyads\[1\]\.rod_length: input should be greater than 0 \(got -0\.4\)"),
    ("negative-design-speed", "mean_piston_speed = 4.0", "mean_piston_speed = -4.0",
     r"design\.mean_piston_speed: input should be greater than 0 \(got -4\.0\)"),
    ("zero-bore", "bore = 0.2 ", "bore = 0 ", r"cylinders\[1\]\.bore: input should be greater than 0"),
    ("negative-mass", '"3" = { mass = 0.6,', '"3" = { mass = -0.6,',
     r"links\.3\.mass: input should be greater than 0 \(got -0\.6\)"),
    ("zero-mass", '"3" = { mass = 0.6,', '"3" = { mass = 0.0,',
     r"links\.3\.mass: input should be greater than 0 \(got 0\.0\)"),
    ("link-point-not-on-the-link", 'S4 = { link = "4", from = "A", to = "C"', 'S4 = { link = "2", from = "A", to = "C"',
     r"points\.S4\.to: point 'C' is not on link 2 \(its points: A, B, S2\)"),
    ("centroid-not-on-the-link", 'centroid = "S2" }', 'centroid = "S4" }',
     r"links\.2\.centroid: point 'S4' is not on link 2 \(its points: A, B, S2\)"),
    ("negative-inertia", "J_S = 0.21, centroid = \"S4\"", "J_S = -0.21, centroid = \"S4\"",
     r"links\.4\.J_S: input should be greater than or equal to 0"),
    ("point-used-before-defined", 'from = "A"\njoint = "B"', 'from = "C"\njoint = "B"',
     r"dyads\[0\]\.from: point 'C' is used before it is defined \(defined so far: A, O\)"),
    ("point-never-defined", 'S4 = { link = "4", from = "A", to = "C"', 'S4 = { link = "4", from = "A", to = "X"',
     r"points\.S4: point 'X' is never defined"),
    ("centroid-not-defined", 'centroid = "S2" }', 'centroid = "S9" }',
     r"links\.2\.centroid: point 'S9' is not defined"),
    ("link-not-defined", '"5" = { mass = 1.0', '"7" = { mass = 1.0',
     r"links\.7: no link named '7'"),
    ("duplicate-point", 'joint = "C"', 'joint = "B"',
     r"dyads\[1\]\.joint: point name 'B' is already defined"),
    ("duplicate-point-in-points", "S4 = { link", "B = { link",
     r"points\.B: point name 'B' is already defined"),
    ("duplicate-link", 'rod = "4"', 'rod = "2"', r"dyads\[1\]\.rod: link name '2' is already defined"),
    ("duplicate-cylinder", 'name = "LP"', 'name = "HP"',
     r"cylinders\[1\]\.name: load name 'HP' is used twice"),
    ("delta-zero", "delta     = 0.05", "delta     = 0", r"machine\.delta: input should be greater than 0"),
    ("delta-one", "delta     = 0.05", "delta     = 1", r"machine\.delta: input should be less than 1"),
    ("delta-negative", "delta     = 0.05", "delta     = -0.05", r"machine\.delta: input should be greater than 0"),
    ("piston-not-a-slider", 'piston = "3"', 'piston = "2"',
     r"cylinders\[0\]\.piston: '2' is not the slider of an RRP dyad \(sliders: 3, 5\)"),
    ("s-not-increasing", S_ROW, S_ROW.replace("0.3, 0.4", "0.4, 0.3"),
     r"cylinders\[0\]\.s: must be strictly increasing"),
    ("s-repeated", S_ROW, S_ROW.replace("0.3, 0.4", "0.3, 0.3"),
     r"cylinders\[0\]\.s: must be strictly increasing"),
    ("s-short-of-1", S_ROW, S_ROW.replace("0.9, 1]", "0.9, 0.95]"),
     r"cylinders\[0\]\.s: must span \[0, 1\] \(got 0\.0 … 0\.95\)"),
    ("s-not-from-0", S_ROW, S_ROW.replace("[0, 0.1", "[0.05, 0.1"),
     r"cylinders\[0\]\.s: must span \[0, 1\]"),
    ("table-length", "away_from_head = [1, 0.52, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3, 0.3]",
     "away_from_head = [1, 0.52, 0.3]",
     r"cylinders\[0\]\.away_from_head: needs 11 values, one per s \(got 3\)"),
    ("design-missing", "mean_piston_speed = 4.0", "",
     r"crank\.length: missing: give crank\.length or design\.mean_piston_speed"),
    ("rod-length-missing", "rod_to_crank      = 4.0", "",
     r"dyads\[0\]\.rod_length: missing: give rod_length or design\.rod_to_crank"),
]


@pytest.mark.parametrize("old, new, expected", [b[1:] for b in BAD], ids=[b[0] for b in BAD])
def test_bad_input_is_one_line_naming_file_and_field(tmp_path, old, new, expected):
    path = variant(tmp_path, old, new)
    with pytest.raises(CaseFileError, match=re.escape(str(path)) + ": " + expected) as exc:
        load_case(path)
    assert "\n" not in str(exc.value)


def test_syntax_error_position_points_at_the_mistake(tmp_path):
    path = variant(tmp_path, "speed_rps = 10.0", "speed_rps = = 10.0")
    msg = load_error(path)
    line, col = map(int, re.search(r"line (\d+), column (\d+)", msg).groups())
    bad_line = path.read_text(encoding="utf-8").splitlines()[line - 1]
    assert bad_line.startswith("speed_rps = =")
    assert bad_line[col - 1] == "="                       # the second '='


def test_unknown_key_lists_the_allowed_ones(tmp_path):
    msg = load_error(variant(tmp_path, "bore = 0.12 ", "bor = 0.12 "))
    assert "cylinders[0].bor: unknown key; did you mean 'bore'?" in msg
    assert "allowed: name, title, label, piston, bore, p_max, head, interpolation, s, towards_head, away_from_head" in msg


def test_unknown_key_far_from_any_gives_no_guess(tmp_path):
    msg = load_error(variant(tmp_path, "[flywheel]", "[flywheel]\nzzz = 1"))
    assert "flywheel.zzz: unknown key (allowed: " in msg and "did you mean" not in msg


@pytest.mark.parametrize("content, expected", [
    (None, r": no such file"),
    (b"\xff\xfe speed", r": not UTF-8 text"),
    (b"", r": machine: missing required field"),
])
def test_unreadable_files(tmp_path, content, expected):
    path = tmp_path / "case.toml"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(CaseFileError, match=re.escape(str(path)) + expected) as exc:
        load_case(path)
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize("encoding, said", [("cp1251", "Windows-1251"), ("cp866", "DOS (cp866)"),
                                             ("utf-16", "UTF-16"), ("utf-32", "UTF-32")])
def test_a_case_saved_in_another_encoding_is_told_so(tmp_path, encoding, said):
    """A Russian starter case saved by a Windows or DOS editor in its own encoding: the line
    names that encoding and says to save the file as UTF-8 (it had said «not UTF-8 text
    (invalid continuation byte at byte 2)», Python's English words in a Russian line too)."""
    from flywheel.cases.starter import starter_text

    path = tmp_path / "case.toml"
    path.write_bytes(starter_text("slider-crank", "ru").encode(encoding, errors="replace"))
    with pytest.raises(CaseFileError) as exc:
        load_case(path)
    assert str(exc.value) == (f"{path}: not UTF-8 text but {said} (allowed: UTF-8 only; save "
                              "the file again as UTF-8)")


def test_binary_data_is_not_given_an_encoding(tmp_path):
    path = tmp_path / "case.toml"
    path.write_bytes(bytes.fromhex("89504e470d0a1a0a0000000d4948445200000010"))
    with pytest.raises(CaseFileError) as exc:
        load_case(path)
    assert str(exc.value) == (f"{path}: not UTF-8 text (byte 0 is not part of a UTF-8 character; "
                              "allowed: a text file saved as UTF-8)")


def test_a_folder_is_not_a_case(tmp_path):
    with pytest.raises(CaseFileError, match="is a folder"):
        load_case(tmp_path)


def test_parse_case_names_its_source():
    with pytest.raises(CaseFileError, match=r"^<notebook>: machine: missing required field$"):
        parse_case({"crank": {"length": 0.1}}, "<notebook>")


# -- equivalent spellings -----------------------------------------------------------------------

def test_lengths_from_design_equal_lengths_given(tmp_path):
    # seed 000 §1.1: l1 = V_ср/(4·n1) = 4/(4·10) = 0.1 m; l2 = l4 = k·l1 = 0.4 m
    text = BASE.replace("mean_piston_speed = 4.0", "").replace("rod_to_crank      = 4.0", "")
    text = text.replace("[crank]\n", "[crank]\nlength = 0.1\n")
    text = text.replace('slider = "3"\n', 'slider = "3"\nrod_length = 0.4\n')
    text = text.replace('slider = "5"\n', 'slider = "5"\nrod_length = 0.4\n')
    path = tmp_path / "direct.toml"
    path.write_text(text, encoding="utf-8")
    direct, derived = load_case(path), load_case(CASES / "compressor.toml")
    assert direct.design.mean_piston_speed is None and direct.design.rod_to_crank is None
    assert derived.crank.length is None
    assert derived.crank_length == pytest.approx(0.1, abs=1e-15)
    assert [derived.rod_length(d) for d in derived.dyads] == pytest.approx([0.4, 0.4], abs=1e-15)
    assert to_mechanism(direct) == to_mechanism(derived)   # 4/(4·10) and 4·0.1 are exact here


def test_speed_rpm_equals_speed_rps(tmp_path):
    rpm = load_case(variant(tmp_path, "speed_rps = 10.0", "speed_rpm = 600.0"))
    rps = load_case(CASES / "compressor.toml")
    assert rpm.machine.omega_mean == pytest.approx(rps.machine.omega_mean, rel=1e-15)
    assert rps.machine.omega_mean == pytest.approx(62.832, abs=5e-4)   # seed: ω_1ср = 62.832
    assert to_mechanism(rpm) == to_mechanism(rps)                    # l1 = V/(4·n1) alike


def test_degrees_become_radians_and_rotation_a_sign():
    m = to_mechanism(load_case(CASES / "compressor.toml"))
    assert m.crank.start_angle == pytest.approx(math.pi / 2, abs=1e-15)
    assert m.crank.direction == -1                                   # rotation = "cw"
    assert [d.guide.angle for d in m.dyads] == pytest.approx([math.pi / 2, 0.0], abs=1e-15)


@pytest.mark.parametrize("name", ["compressor.toml", "fourbar.toml", "slotted_link.toml"])
def test_bundled_cases_load(name):
    case = load_case(CASES / name)
    assert case.title
    assert to_mechanism(case).dyads


# -- JSON Schema --------------------------------------------------------------------------------

def test_json_schema_is_valid_json_with_the_tables():
    schema = json.loads(json.dumps(case_json_schema()))
    assert schema["title"] == "flywheel case file"
    assert schema["type"] == "object"
    props = set(schema["properties"])
    assert {"title", "source", "machine", "design", "crank", "ground", "dyads", "points", "links",
            "cylinders", "forces", "couples", "flywheel", "output"} <= props
    assert set(schema["required"]) == {"machine"}
    assert schema["additionalProperties"] is False
    # the dyads are a tagged union on `kind`, and `from` keeps its TOML spelling
    defs = schema["$defs"]
    assert {"RRPSpec", "RRRSpec", "RPRSpec"} <= set(defs)
    assert "from" in defs["RRPSpec"]["properties"] and "from_" not in defs["RRPSpec"]["properties"]
    assert "mapping" in schema["properties"]["dyads"]["items"]["discriminator"]
    # units are in the descriptions
    assert "[m]" in defs["CylinderSpec"]["properties"]["bore"]["description"]


# -- docs/case-format.md stays in step with the models ---------------------------------------

DOC = Path(__file__).resolve().parents[2] / "docs" / "case-format.md"


def test_every_field_is_documented():
    from flywheel.cases import run as models

    text = DOC.read_text(encoding="utf-8")
    tables = [models.Machine, models.Design, models.CrankSpec, models.GuideSpec, models.RRPSpec,
              models.RRRSpec, models.RPRSpec, models.PointSpec, models.LinkSpec,
              models.CylinderSpec, models.ForceSpec, models.CoupleSpec, models.SpringSpec,
              models.FlywheelSpec,
              models.MotorSpec, models.OutputSpec, models.ForceAnalysisSpec, models.Case]
    missing = [f"{m.__name__}.{f.alias or n}" for m in tables for n, f in m.model_fields.items()
               if f"`{f.alias or n}`" not in text and f"[{f.alias or n}]" not in text]
    assert not missing, f"not in docs/case-format.md: {missing}"


def test_annotated_example_loads_and_matches_its_closed_forms(tmp_path):
    from flywheel.linkage.deadcentres import dead_centres

    example = re.findall(r"```toml\n(.*?)```", DOC.read_text(encoding="utf-8"), re.S)[-1]
    path = tmp_path / "pump.toml"
    path.write_text(example, encoding="utf-8")
    case = load_case(path)
    # the doc's numbers: outer at asin(e/(l + r)), inner at 180° + asin(e/(l − r)), the stroke
    dcs = {d.kind: d for d in dead_centres(to_mechanism(case), "3")}
    assert math.degrees(dcs["outer"].phi) == pytest.approx(2.29, abs=5e-3)
    assert math.degrees(dcs["inner"].phi) == pytest.approx(183.82, abs=5e-3)
    assert dcs["outer"].x - dcs["inner"].x == pytest.approx(0.10013, abs=5e-6)


def test_point_fields_that_do_not_go_together():
    from flywheel.cases.run import parse_case
    from flywheel.errors import CaseFileError

    base = {
        "machine": {"speed_rps": 1.0, "delta": 0.1},
        "crank": {"length": 0.1},
        "dyads": [{"kind": "RRP", "from": "A", "joint": "B", "rod": "2", "rod_length": 0.4,
                   "slider": "3", "guide": {"angle_deg": 0.0}}],
    }
    for bad, msg in (({"link": "2", "from": "A", "distance": 0.1, "fraction": 0.3}, "fraction"),
                     ({"link": "2", "from": "A", "to": "B", "fraction": 0.3, "angle_deg": 10}, "angle_deg")):
        with pytest.raises(CaseFileError, match=rf"points\.S: .*{msg}"):
            parse_case({**base, "points": {"S": bad}}, "x.toml")
