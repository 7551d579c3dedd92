"""Moved to :mod:`flywheel.io.serialize` (every result package uses the one serializer); this name
stays until the branches that import it are merged."""
from flywheel.io.serialize import document_keys, json_schema, to_json  # noqa: F401
