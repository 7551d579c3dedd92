"""`flywheel drawings CASE`: the shorthand of `flywheel run CASE --drawings --no-plots` — the
run's output folder with the project's ЕСКД sheets in drawings/ (docs/drawings.md)."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

import typer

from flywheel.cli.options import Lang


def drawings_command(
    case: Path = typer.Argument(..., help="Case file (TOML)."),
    out: Optional[Path] = typer.Option(None, "--out", "-o", help="Output folder (default: "
                                       "out/<case name>), as `flywheel run` writes it."),
    at: Optional[list[float]] = typer.Option(None, "--at", help="Report angle \\[deg] of sheet "
                                             "2 (the first one given); default: the case's."),
    lang: Lang = "en",
    sheet_size: str = typer.Option("A1", "--sheet-size", help="Format of the sheets, "
                                   "landscape: A1, A2 or A3."),
) -> None:
    """Write the project's drawing sheets (sheet 1 the law of motion, sheet 2 the force
    analysis) as PDF, SVG and DXF: `flywheel run CASE --drawings --no-plots`."""
    from flywheel.cli.run import run_command

    run_command(case=case, out=out, points=3600, at=at, plots="none", no_plots=True, as_json=False,
                lang=lang, transients=False, animate=False, motion=None, report=None,
                csv_style="plain", figure_format="png", dpi=120, drawings=True,
                sheet_size=sheet_size, snapshot=None, at_travel=None, roots=None, student=None,
                group=None, teacher=None)
