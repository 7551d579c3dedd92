"""The typed results and their one serializer (io/serialize.py): summary.json of every
bundled run case validates against `flywheel schema --results`, the serializer's None rules,
and a missing quantity is an error where the result is built, not a silent default."""
from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import pytest

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.dynamics.results import (FlywheelShape, Headline, Rundown, StartupRun,
                                       summary_json_schema)
from flywheel.io.serialize import to_json

CASES = Path(__file__).resolve().parents[2] / "cases"
RUN_CASES = ["compressor", "compressor_given_flywheel", "compressor_worksheet", "engine_4stroke",
             "engine_inline4", "fourbar", "press", "pump", "shaper", "slotted_link"]

_TYPES = {"object": dict, "array": list, "string": str, "boolean": bool, "null": type(None)}


def errors(value, schema: dict, path: str = "$") -> list[str]:
    """Where ``value`` breaks ``schema`` (the subset flywheel's schema uses: type, properties,
    required, additionalProperties, items, anyOf); [] if it fits. A small validator of our own:
    jsonschema is not a dependency."""
    if "anyOf" in schema:
        if any(not errors(value, s, path) for s in schema["anyOf"]):
            return []
        return [f"{path}: fits none of anyOf"]
    out = []
    if "type" in schema:
        kinds = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]

        def fits(k):
            if k == "number":
                return isinstance(value, (int, float)) and not isinstance(value, bool)
            if k == "integer":
                return isinstance(value, int) and not isinstance(value, bool)
            return isinstance(value, _TYPES[k])
        if not any(fits(k) for k in kinds):
            return [f"{path}: {type(value).__name__} is not {kinds}"]
    if isinstance(value, dict):
        props = schema.get("properties", {})
        out += [f"{path}.{k}: missing" for k in schema.get("required", ()) if k not in value]
        extra = schema.get("additionalProperties", True)
        for k, v in value.items():
            if k in props:
                out += errors(v, props[k], f"{path}.{k}")
            elif extra is False:
                out.append(f"{path}.{k}: not in the schema")
            elif isinstance(extra, dict):
                out += errors(v, extra, f"{path}.{k}")
    if isinstance(value, list) and "items" in schema:
        for i, v in enumerate(value):
            out += errors(v, schema["items"], f"{path}[{i}]")
    return out


@pytest.fixture(scope="module")
def schema():
    return json.loads(json.dumps(summary_json_schema()))


@pytest.mark.parametrize("name", RUN_CASES)
def test_summary_json_of_every_bundled_case_fits_the_schema(name, schema):
    doc = json.loads(json.dumps(analyze(load_case(CASES / f"{name}.toml"), n_points=360).to_document()))
    assert errors(doc, schema) == []


@pytest.mark.parametrize("name", ["compressor", "fourbar"])
def test_summary_json_with_the_time_domain_fits_the_schema(name, schema):
    """compressor has a [motor] (a start-up run), fourbar none (not computed)."""
    r = analyze(load_case(CASES / f"{name}.toml"), n_points=360, transients=True)
    doc = json.loads(json.dumps(r.to_document()))
    assert "time_domain" in doc["results"]
    assert errors(doc, schema) == []


def test_the_validator_catches_a_renamed_key_and_a_wrong_type(schema):
    doc = json.loads(json.dumps(analyze(load_case(CASES / "fourbar.toml"), n_points=360).to_document()))
    renamed = json.loads(json.dumps(doc))
    renamed["results"]["J_II_average"] = renamed["results"].pop("J_II_mean")
    assert sorted(errors(renamed, schema)) == ["$.results.J_II_average: not in the schema",
                                               "$.results.J_II_mean: missing"]
    wrong = json.loads(json.dumps(doc))
    wrong["results"]["at"][0]["points"]["A"]["v"] = "fast"
    assert errors(wrong, schema) == ["$.results.at[0].points.A.v: str is not ['number', 'null']"]


def test_the_serializer_leaves_out_none_unless_kept_and_follows_the_document_order():
    shape = FlywheelShape(D=0.5, b=0.1, mass=20.0, D_inner=0.4)
    assert list(to_json(shape)) == ["D", "D_inner", "b", "mass"]        # rim_speed None: left out
    st = StartupRun(converged=False, omega_final_predicted=None, time_constant=2.0,
                    omega_mean_last=10.0, cycles_run=5, time_run=1.0, starting_torque=3.0,
                    no_load_speed=4.0)
    d = to_json(st)
    assert d["omega_final_predicted"] is None and d["time_to_steady"] is None   # kept as null
    assert "warning" not in d
    assert to_json(Rundown(stopped=True, time=1.5, angle_deg=90.0)) == {
        "stopped": True, "time": 1.5, "angle_deg": 90.0}


def test_a_missing_headline_quantity_is_an_error_not_a_default():
    r = analyze(load_case(CASES / "fourbar.toml"), n_points=360)
    fields = {f.name: getattr(r.scalars, f.name) for f in dataclasses.fields(Headline)}
    del fields["J_II_mean"]
    with pytest.raises(TypeError, match="J_II_mean"):
        Headline(**fields)
    with pytest.raises(AttributeError):
        r.scalars.J_II_average          # noqa: B018 (a renamed key fails loudly)


def test_scalars_are_built_once_and_frozen():
    r = analyze(load_case(CASES / "fourbar.toml"), n_points=360)
    assert r.scalars is r.scalars
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.scalars.delta = 0.1
    assert math.isfinite(r.scalars.J_II_mean)


def test_schema_command_prints_the_results_schema():
    from typer.testing import CliRunner

    from flywheel.cli import app

    res = CliRunner().invoke(app, ["schema", "--results"])
    assert res.exit_code == 0, res.output
    printed = json.loads(res.stdout)
    assert printed["properties"]["results"]["properties"]["at"]["items"]["properties"]["phi_deg"] \
        == {"type": ["number", "null"]}
