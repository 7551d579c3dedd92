"""io/jsonfile.py: the limits of every JSON flywheel reads (depth, digits, size, links)."""
import json
import os

import pytest

from flywheel.io.jsonfile import (MAX_DEPTH, MAX_DIGITS, JsonNumberTooLong, JsonTooDeep,
                                  JsonTooLarge, json_depth, parse_json, read_json)
from flywheel.io.output import MANIFEST, _read_manifest


def test_depth_and_digits_at_and_beyond_the_limits():
    at = "[" * MAX_DEPTH + "]" * MAX_DEPTH
    assert json_depth(at) == MAX_DEPTH and parse_json(at) == json.loads(at)
    with pytest.raises(JsonTooDeep) as e:
        parse_json("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1))
    assert e.value.depth == MAX_DEPTH + 1
    with pytest.raises(JsonTooDeep):                     # far beyond the recursion limit
        parse_json("[" * 100_000 + "]" * 100_000)
    assert parse_json("-" + "9" * MAX_DIGITS) == -int("9" * MAX_DIGITS)
    with pytest.raises(JsonNumberTooLong) as e:
        parse_json('{"a": ' + "1" * (MAX_DIGITS + 1) + "}")
    assert e.value.digits == MAX_DIGITS + 1


def test_read_json_bom_size_and_links(tmp_path):
    p = tmp_path / "a.json"
    p.write_bytes(b'\xef\xbb\xbf{"x": [1, 2.5]}')
    assert read_json(p) == {"x": [1, 2.5]}
    with pytest.raises(JsonTooLarge):
        read_json(p, max_bytes=5)
    link = tmp_path / "l.json"
    link.symlink_to("a.json")
    assert read_json(link) == {"x": [1, 2.5]}
    with pytest.raises(OSError):
        read_json(link, follow_links=False)
    with pytest.raises(IsADirectoryError):
        read_json(tmp_path)


def test_a_manifest_nested_too_deep_is_nobodys(tmp_path):
    """A hand-made manifest deeper than Python's recursion: not flywheel's (no traceback)."""
    (tmp_path / MANIFEST).write_text("[" * 100_000 + "]" * 100_000)
    assert _read_manifest(tmp_path, "output") is None
    (tmp_path / MANIFEST).write_text('{"files": {"a": ' + "7" * 5000 + "}}")
    assert _read_manifest(tmp_path, "output") is None
