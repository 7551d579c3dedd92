"""render/numbers.py: the one number formatter's policy on its edge cases, and the renderers'
formatters as thin calls of it that print what they printed before (their old bodies are
written out here as the independent reference)."""
from __future__ import annotations

import math
import random

import numpy as np
import pytest

from flywheel.render.numbers import DASH, fmt, fmt_rows


@pytest.mark.parametrize("x, text", [
    (0.0, "0"), (-0.0, "0"), (0, "0"),
    (3e-13, "0"), (-9.9e-13, "0"), (1e-12, "1e-12"), (2e-12, "2e-12"),   # the cut-off is strict
    (1e-5, "1e-05"), (1e-4, "0.0001"),
    (123456.4, "123456"), (1234567.0, "1.23457e+06"), (-1e300, "-1e+300"),
    (999999.4, "999999"), (999999.5, "1e+06"),         # rounding carries into the exponent form
    (0.1 + 0.2, "0.3"), (-2.5, "-2.5"), (7, "7"),
    (None, DASH),
])
def test_the_policy(x, text):
    assert fmt(x) == text


def test_rounding_up_to_the_next_power_of_ten():
    # 9.9996 to 4 digits is 10 (not 10.00, not 1e+01); to 2 digits 99.6 becomes the exponent form
    assert fmt(9.9996, 4) == "10"
    assert fmt(9.995, 3) == "9.99"          # 9.995 is 9.99499999… in binary: it rounds down
    assert fmt(9.9951, 3) == "10"
    assert fmt(99.6, 2) == "1e+02"
    assert fmt(12345.6, 4, integers_above=True) == "12346"
    assert fmt(-12345.6, 4, integers_above=True) == "-12346"
    assert fmt(9999.4, 4, integers_above=True) == "9999"


@pytest.mark.parametrize("x", [math.nan, math.inf, -math.inf])
def test_non_finite_refused_by_default(x):
    with pytest.raises(ValueError, match="non-finite"):
        fmt(x)


def test_non_finite_modes():
    assert [fmt(x, nonfinite="show") for x in (math.nan, math.inf, -math.inf)] == ["nan", "inf", "-inf"]
    assert [fmt(x, nonfinite="dash") for x in (math.nan, math.inf, -math.inf)] == [DASH] * 3
    assert [fmt(x, nonfinite="dash-nan") for x in (math.nan, math.inf, -math.inf)] == [DASH, "inf", "-inf"]


def test_zero_modes():
    assert fmt(-0.0, zero=None) == "-0"                     # no cut-off at all
    assert fmt(-0.0, zero=0.0) == "0" and fmt(1e-320, zero=0.0) == "9.99989e-321"
    assert fmt(1e-13, zero=1e-13) == "1e-13" and fmt(9e-14, zero=1e-13) == "0"
    assert fmt(-1e-301, zero=1e-300) == "0"


def test_spec_replaces_significant_digits():
    assert fmt(2.0 / 3.0, spec=".6f") == "0.666667"
    assert fmt(-1e-13, spec=".4f") == "0.0000"
    assert fmt(-1e-13, spec=".4f", zero=None) == "-0.0000"


# -- the renderers' formatters print what their own bodies printed ---------------------------

def _values():
    rng = random.Random(22)
    out = [0.0, -0.0, 1e-12, -1e-12, 5e-13, 1e-13, 5e-14, 1e-300, 1e-301, -1e-320, 1.0, -1.0, 7,
           0, 9.9996, 999999.5, 12345.6, -12345.6, 1e20, math.nan, math.inf, -math.inf]
    for _ in range(2000):
        out.append(rng.choice((-1, 1)) * 10.0 ** rng.uniform(-320, 300))
        out.append(rng.choice((-1, 1)) * round(rng.uniform(0, 1e6), rng.randint(0, 8)))
    return out


def _old(kind, x):
    """The formatters' bodies before they called render/numbers.py (copied verbatim)."""
    if kind == "check":
        return f"{0.0 if abs(x) < 1e-12 else x:.6g}"
    if kind == "csv":
        return "%.12g" % (0.0 if x == 0 else x)
    if kind == "report5":
        if x is None or (isinstance(x, float) and not math.isfinite(x)):
            return "—"
        return f"{0.0 if abs(x) < 1e-13 else x:.5g}"
    if kind == "duty":
        return f"{0.0 if abs(x) < 1e-300 else x:.6g}"
    if kind == "task2":
        if x is None or (isinstance(x, float) and math.isnan(x)):
            return "—"
        return format(0.0 if abs(x) < 1e-12 else x, ".6f")
    if kind == "report_aggregate":
        if x is None or not math.isfinite(float(x)):
            return "—"
        return format(0.0 if abs(x) < 1e-300 else float(x), ".4g")
    if kind == "plans":
        v = float(x)
        if v == 0.0 or not math.isfinite(v):
            return f"{v:g}"
        if abs(v) >= 10.0 ** 4:
            return f"{v:.0f}"
        return f"{v:.4g}"
    if kind == "aggregate":
        return format(0.0 if abs(x) < 1e-300 else float(x), ".6g")
    if kind == "sheets":
        return "%.6g" % (0.0 if x == 0 else x)
    if kind == "summary":
        return f"{0.0 if abs(x) < 1e-13 else x:.6g}"
    if kind == "grading":
        return format(float(x), ".3f")
    if kind == "report_task2":
        if x is None or (isinstance(x, float) and not math.isfinite(x)):
            return "—"
        return format(0.0 if abs(x) < 1e-12 else x, ".4g")
    raise KeyError(kind)


def _new(kind, x):
    from flywheel.render import (aggregate, check, document, duty_cycle, forces, grading,
                                 plots_plans, report_aggregate, report_task2, sheets, summary,
                                 tables, task2)
    return {"check": lambda: check._g(x), "csv": lambda: tables._fmt(x),
            "report5": lambda: document.g(x), "duty": lambda: duty_cycle._g(x),
            "task2": lambda: task2._g(x, ".6f"), "report_aggregate": lambda: report_aggregate.g(x, ".4g"),
            "plans": lambda: plots_plans._num(x), "aggregate": lambda: aggregate._g(x),
            "sheets": lambda: sheets._num(x), "summary": lambda: summary._g(x),
            "grading": lambda: grading._g(float(x), ".3f"),
            "report_task2": lambda: report_task2.g(x, ".4g")}[kind]()


@pytest.mark.parametrize("kind", ["check", "csv", "report5", "duty", "task2", "report_aggregate",
                                  "plans", "aggregate", "sheets", "summary", "grading",
                                  "report_task2"])
def test_each_renderer_prints_what_it_printed(kind):
    from flywheel.render import forces
    bad = [x for x in _values() if _new(kind, x) != _old(kind, x)]
    assert not bad, f"{kind}: {bad[:5]}"
    if kind == "csv":     # the CSV files' rows: the same numbers a row at a time
        values = _values()[: 4000]
        rows = [",".join(_old("csv", x) for x in values[i:i + 8]) for i in range(0, 4000, 8)]
        assert fmt_rows(np.array(values).reshape(-1, 8)) == rows
    if kind == "report5":
        assert all(forces._g(x) == _old("report5", x) for x in _values())
