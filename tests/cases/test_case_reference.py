"""The case file's field reference is generated, never drifting: docs/case-fields.md and
docs/ru/case-format.md are what tools/casedoc.py makes of the schema now, and
`flywheel schema --lang ru` describes every field in Russian (the descriptions live once, in the
models; their Russian in the catalogue, msgctxt "field")."""
import json
import re
from pathlib import Path

from typer.testing import CliRunner

from flywheel.cli import app

ROOT = Path(__file__).resolve().parents[2]
runner = CliRunner()


def _descriptions(node):
    if isinstance(node, dict):
        for k, v in node.items():
            if k == "description" and isinstance(v, str):
                yield v
            else:
                yield from _descriptions(v)
    elif isinstance(node, list):
        for v in node:
            yield from _descriptions(v)


def test_the_generated_references_are_up_to_date(capsys):
    """`python tools/casedoc.py check`, its main() run in this process."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("casedoc", ROOT / "tools" / "casedoc.py")
    casedoc = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(casedoc)
    assert casedoc.main(["casedoc.py", "check"]) == 0, capsys.readouterr().out


def test_schema_in_russian_describes_every_field_in_russian():
    en = runner.invoke(app, ["schema"])
    ru = runner.invoke(app, ["schema", "--lang", "ru"])
    assert en.exit_code == ru.exit_code == 0
    said_en = [d for d in _descriptions(json.loads(en.stdout)) if d.strip()]
    said_ru = [d for d in _descriptions(json.loads(ru.stdout)) if d.strip()]
    assert len(said_en) == len(said_ru) > 100
    untranslated = [e for e, r in zip(said_en, said_ru) if not re.search("[а-яё]", r, re.I)]
    assert untranslated == []
    # the rest of the schema is the same: only the descriptions differ
    strip = re.compile(r'"description": "(?:[^"\\]|\\.)*"')
    assert strip.sub("", en.stdout) == strip.sub("", ru.stdout)


def test_every_table_of_the_file_is_in_the_russian_reference():
    text = (ROOT / "docs" / "ru" / "case-format.md").read_text(encoding="utf-8")
    for heading in ("[machine]", "[crank]", '[[dyads]] kind = "RRR"', "[[cylinders]]",
                    "[flywheel.rim]", "[document]"):
        assert f"## `{heading}`" in text, heading
    assert "Режим работы машины." in text and "частота вращения кривошипа n₁ [об/с]" in text
