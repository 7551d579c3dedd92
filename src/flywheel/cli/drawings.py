"""`flywheel drawings CASE`: the shorthand of `flywheel run CASE --drawings --no-plots` — the
run's output folder with the project's ЕСКД sheets in drawings/ (docs/drawings.md)."""
from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from flywheel.cli.options import CaseFile, Lang, Quiet


Out = Annotated[Optional[Path], typer.Option(
    "--out", "-o", metavar="DIR", help="Output folder (default: out/<case name>), as `flywheel run` writes it.")]
At = Annotated[Optional[list[float]], typer.Option(
    "--at", metavar="DEG", help="Report angle \\[deg] of sheet 2 (the first one given); default: the case's.")]
SheetSize = Annotated[str, typer.Option(
    "--sheet-size", metavar="SIZE", help="Format of the sheets, landscape: A1, A2 or A3.")]


def drawings_command(case: CaseFile, out: Out = None, at: At = None, lang: Lang = "en", quiet: Quiet = False,
                     sheet_size: SheetSize = "A1") -> None:
    """Write the project's drawing sheets (sheet 1 the law of motion, sheet 2 the force
    analysis) as PDF, SVG and DXF: `flywheel run CASE --drawings --no-plots`."""
    from flywheel.cli.run import run_command

    run_command(case=case, out=out, at=at, plots="none", no_plots=True, lang=lang, drawings=True,
                sheet_size=sheet_size)
