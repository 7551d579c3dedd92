"""The values `run`'s output options take — light (no renderer imported), so that checking
the options (cli/run.py ``_check_options``, cli/guard.py) imports none of the renderers that
define what the values mean: each renderer re-exports its own (csvfmt.STYLES, figure.FORMATS
and DPI_RANGE, plots.CHOICES, report_formats.FORMATS, drawings.SIZES, report_frame.FRAMES).
"""
from __future__ import annotations

CSV_STYLES = ("plain", "excel-ru")               # `--csv`: render/csvfmt.py
FIGURE_FORMATS = ("png", "svg", "pdf")           # `--figure-format`: render/figure.py
DPI_RANGE = (50, 600)                            # `--dpi` [dots per inch], inclusive
PLOT_CHOICES = ("all", "record", "none")         # `--plots`: render/plots.py
REPORT_FORMATS = ("md", "html", "pdf", "docx")   # `--report`: render/report_formats.py
SHEET_SIZES = ("A1", "A2", "A3")                 # `--sheet-size`: render/drawings/
FRAMES = ("none", "eskd")                        # `--frame`: render/report_frame.py
