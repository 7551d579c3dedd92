"""The output folder of `flywheel task2 --out DIR` and `flywheel aggregate CASE --out DIR`:
summary.json (the same document as --json), the figure under plots/, and report.<ext> for each
asked format, written through io/output.py's write_folder (whole or not at all, with its
manifest: a rerun replaces only its own files). The figure and the document are made by the
command's own renderers; this module only puts them together.
"""
from __future__ import annotations

from pathlib import Path

from flywheel.errors import InputError, Notice


def check_formats(formats) -> list[str]:
    """The asked report formats (default md and html); an unknown one is an InputError."""
    from flywheel.render.report_formats import FORMATS

    formats = list(formats or ["md", "html"])
    for f in formats:
        if f not in FORMATS:
            raise InputError(Notice.of(
                "option_choice", "{option}: {got} is not {what} (allowed: {allowed})",
                option="--report", got=repr(f), what="a report format",
                allowed=", ".join(FORMATS)))
    return list(dict.fromkeys(formats))


def write_report_folder(out: Path, kind: str, json_text: str, draw, figure: str | None,
                        document, formats) -> tuple[list[str], list[str]]:
    """Write the folder ``out`` (``kind``: "task2" or "aggregate", recorded in the manifest so
    one command never replaces another's folder): summary.json, ``draw(path)`` into
    plots/<figure> (None: no figure), ``document(figure_or_None)`` as report.<ext> for each
    format. Returns (the names written, the notes of write_folder for stderr)."""
    from flywheel.io.output import write_folder
    from flywheel.render.report_formats import write_reports

    names: list[str] = []

    def build(folder: Path) -> None:
        (folder / "summary.json").write_text(json_text, encoding="utf-8")
        names.append("summary.json")
        if figure is not None:
            (folder / "plots").mkdir()
            draw(folder / "plots" / figure)
        doc = document(figure)
        names.extend(write_reports(doc, folder, formats,
                                    folder / "plots" if figure is not None else None))
        if figure is not None:
            names.append(f"plots/{figure}")

    notes: list[str] = []
    write_folder(Path(out), build, "summary.json", kind=kind, notes=notes)
    return names, notes
