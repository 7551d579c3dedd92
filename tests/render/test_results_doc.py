"""docs/results.md is generated, never drifting: it is what tools/resultsdoc.py makes now of
docs/results.template.md, the quantities table (render/nomenclature.py) and the JSON Schema of
summary.json (`flywheel schema --results`); and its table of every key covers each key a run
really writes."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from flywheel.cases.run import load_case
from flywheel.dynamics.pipeline import analyze
from flywheel.dynamics.results import summary_json_schema

ROOT = Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "results.md"


def test_docs_results_is_what_the_script_writes_now():
    res = subprocess.run([sys.executable, str(ROOT / "tools" / "resultsdoc.py"), "check"],
                         capture_output=True, text=True)
    assert res.returncode == 0, res.stdout + res.stderr


def _paths(doc, schema: dict, path: str):
    """Every key path of a summary.json document, as the reference writes it: ``[]`` for each
    entry of a list, ``*`` for each member of a record named by the case (the schema's
    ``additionalProperties``)."""
    if isinstance(doc, dict):
        shapes = schema.get("anyOf", [schema])
        shape = next(s for s in shapes if set(doc) <= set(s.get("properties", {}))
                     or isinstance(s.get("additionalProperties"), dict))
        for key, value in doc.items():
            if key in shape.get("properties", {}):
                child, where = shape["properties"][key], f"{path}.{key}"
            else:
                child, where = shape["additionalProperties"], f"{path}.*"
            yield where
            yield from _paths(value, child, where)
    elif isinstance(doc, list):
        for value in doc:
            yield from _paths(value, schema.get("items", {}), path + "[]")


def test_every_key_a_run_writes_is_in_the_reference():
    """The compressor with --transients (the time domain, the force analysis, cylinders,
    points and links): each of its keys is a row of "Every key of summary.json"."""
    listed = set(re.findall(r"^\| `(results[^`]*)` \|", DOC.read_text(encoding="utf-8"), re.M))
    r = analyze(load_case(ROOT / "cases" / "compressor.toml"), n_points=360, transients=True)
    written = set(_paths(r.to_document()["results"],
                         summary_json_schema()["properties"]["results"], "results"))
    assert {"results.at[].points.*.v", "results.time_domain.startup.time_constant",
            "results.at[].joints.*.Fx"} <= written          # the walk reached the leaves
    assert written - listed == set()


def test_the_reference_names_quantities_with_the_nomenclatures_units():
    """A row of a quantity carries the unit the nomenclature gives its key; a member of a
    point or a link is named by its family (x_{point}, omega_{link}), not by the crank's ω."""
    from flywheel.render import nomenclature as nm

    rows = {m[0]: m[1:] for m in re.findall(
        r"^\| `(results[^`]*)` \| [^|]* \|[^|]*\| ([^|]*) \| ([^|]*) \| ([^|]*) \|$",
        DOC.read_text(encoding="utf-8"), re.M)}
    assert rows["results.omega_mean"][1] == nm.si_unit("omega_mean") == "rad/s"
    assert rows["results.at[].links.*.omega"][2] == nm.name("omega_2").replace("2", "L")
    assert rows["results.at[].points.*.x"][1] == nm.si_unit("x_B") == "m"
