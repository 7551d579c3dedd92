"""The one number formatter of every output a person reads (summaries, reports, sheets, CSV).

The policy (the defaults of :func:`fmt`):

- ``sig`` significant digits (6), Python's ``g`` presentation: trailing zeros dropped, the
  exponent form when the exponent is below −4 or at least ``sig`` (also after rounding:
  999 999.5 to 6 digits is ``1e+06``, 9.9996 to 4 digits is ``10``);
- zero: −0, and round-off below ``zero`` in magnitude (1e-12), print as ``0``;
- no value (None) prints as ``—``;
- NaN and ±inf are refused (ValueError): a non-finite number is refused where it enters
  (docs/architecture.md), so one reaching a renderer is a bug.

The Russian decimal comma and true minus are applied to the formatted text by the templates
that hold it (render/nomenclature.py), not here.

The renderers' own formatters (``_g``, ``g``, ``_fmt``, ``_num``) are thin calls of
:func:`fmt` that keep today's outputs byte for byte. Where they differ from the policy they
pass it as a parameter: differences to remove later, each a visible change of output —

- ``zero``: the cut-off differs (1e-12 in check, task2, report_task2; 1e-13 in summary, forces,
  document; 1e-300 in aggregate, report_aggregate, duty_cycle; exactly 0, turning −0 into 0, in
  the CSV tables and sheets; none at all, so −0 prints ``-0``, in grading and plans: ``None``);
- ``nonfinite``: "show" prints ``nan``/``inf`` (check, summary, the CSV tables, duty_cycle,
  aggregate, grading, plans), "dash" prints ``—`` (document, forces, report_aggregate,
  report_task2), "dash-nan" prints ``—`` for NaN and ``inf`` for ±inf (task2);
- ``spec``: a format spec given whole (``.6f``, ``.0f``) instead of ``sig`` digits;
- ``integers_above``: the velocity and acceleration plans write values of ``sig`` digits or
  more as whole numbers, never in exponent form (12345.6 → ``12346``).
"""
from __future__ import annotations

import math

import numpy as np

DASH = "—"
NONFINITE = ("refuse", "show", "dash", "dash-nan")


def fmt(x, sig: int = 6, *, zero: float | None = 1e-12, spec: str | None = None,
        nonfinite: str = "refuse", integers_above: bool = False) -> str:
    """``x`` (a real number or None) as text under the policy of this module's docstring.

    sig: significant digits (``g`` presentation), unless ``spec`` (a whole format spec such as
    ".6f") is given; zero: |x| below it, and −0, print as 0 (None: −0 stays ``-0``; 0: only
    ±0 → 0); nonfinite: "refuse" (ValueError), "show" (``nan``, ``inf``), "dash" (``—``),
    "dash-nan" (``—`` for NaN, ``inf`` shown); integers_above: |x| ≥ 10^sig as a whole number.

    >>> fmt(-0.0), fmt(3e-13), fmt(1234567.0), fmt(0.1 + 0.2), fmt(None)
    ('0', '0', '1.23457e+06', '0.3', '—')
    """
    if x is None:
        return DASH
    x = float(x)
    if not math.isfinite(x):
        if nonfinite == "show" or (nonfinite == "dash-nan" and not math.isnan(x)):
            return format(x, spec or f".{sig}g")
        if nonfinite in ("dash", "dash-nan"):
            return DASH
        # library use only: no CLI input reaches this
        raise ValueError(f"a non-finite number ({x}) to format: it should have been refused "
                         f"where it entered")
    if zero is not None and (x == 0 or abs(x) < zero):
        x = 0.0
    if integers_above and abs(x) >= 10.0 ** sig:
        return f"{x:.0f}"
    return format(x, spec or f".{sig}g")


def fmt_rows(data, sig: int = 12) -> list[str]:
    """Each row of a 2-D array as its numbers joined by commas, each as :func:`fmt` writes it
    with ``zero=0.0, nonfinite="show"`` (−0 → 0, nan shown): the CSV files' numbers. One
    %-format per row (half the time of one per number; the in-line four's table has 150
    columns), the same text as ``"%.{sig}g"`` per number."""
    data = np.asarray(data, dtype=float) + 0.0          # + 0.0: −0.0 becomes 0.0, nothing else
    row = ",".join([f"%.{sig}g"] * data.shape[1])
    return [row % tuple(r) for r in data.tolist()]
