"""render/numbers.fmt_rows and fmt_text, the CSV files' numbers made a block of rows at a time:
byte for byte the text of Python's own ``"%.{sig}g" % x`` for every number (the independent
truth), on edge cases, on a hypothesis sample of every float, and on large random tables."""
from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from flywheel.render import numbers
from flywheel.render.numbers import fmt_rows, fmt_text


def _reference(data, sig: int = 12) -> list[str]:
    """Python's %-format, one number at a time (−0 written as 0, as the CSV files do)."""
    return [",".join(f"%.{sig}g" % (float(x) + 0.0) for x in row) for row in data]


def _edge_values() -> list[float]:
    out = [0.0, -0.0, 1.0, -1.0, 7.0, 0.5, 2.5, 0.125, 1e16, 1e15, 1e12, 1e11, 123456789012.0,
           1234567890123.0, 999999999999.5, 999999999999.4, 999999999999.6, 99999999999.95,
           99999999999.96, 9.9999999999995, 9.99999999999949, 0.1, 0.2, 0.3, 0.1 + 0.2,
           1.000244140625, 1.000732421875, 0.0001220703125, 2.0 ** 40 + 0.5, 2.0 ** 52 + 1,
           5e-324, 2.2250738585072014e-308, 1e-280, 1.0000000000000002e-280, 1e280, 9.99e279,
           1.7976931348623157e308, 1e-5, 1e-4, 9.99999999999e-5, 0.00099999999999995,
           math.nan, -math.nan, math.inf, -math.inf, 6.123233995736766e-17, 1e100, 1e-100,
           4503599627370497.0, 123.456, -123.456e-7]
    for k in range(-40, 41):                           # powers of ten and their neighbours
        p = 10.0 ** k
        out += [p, np.nextafter(p, 0), np.nextafter(p, math.inf), -p]
    for n in range(1, 60):                             # halves in the 13th digit: exact ties
        out += [(2 ** n + 1) / 2 ** n, 1 + 5 / 2 ** n, 3 * 2.0 ** -n]
    return out


@pytest.mark.parametrize("sig", [1, 2, 3, 6, 11, 12, 13, 17])
def test_edge_cases_as_python_formats_them(sig):
    values = _edge_values()
    values += [0.0] * (-len(values) % 7)
    data = np.array(values).reshape(-1, 7)
    assert fmt_rows(data, sig) == _reference(data, sig)


def test_ties_and_decade_carries_are_python_s():
    # round half to even on the exact binary value (…62|5 → …62, …98|5 → …98, …99|5 → 1e+12),
    # 99999999999.95 is …949999 in binary, 9.99… carried into the next decade
    assert fmt_rows(np.array([[1.000244140625, 999999999998.5, 999999999999.5, 99999999999.95,
                               -0.0]])) == ["1.00024414062,999999999998,1e+12,99999999999.9,0"]
    assert fmt_rows(np.array([[9.9999999999995, 0.00099999999999995, 1e16, 5e-324]])) == [
        "10,0.001,1e+16,4.94065645841e-324"]


@settings(deadline=None, derandomize=True, max_examples=300)
@given(st.lists(st.floats(allow_nan=True, allow_infinity=True, allow_subnormal=True),
                min_size=1, max_size=60),
       st.integers(1, 6), st.sampled_from([1, 4, 7, 12]))
def test_any_floats(values, width, sig):
    values += [1.5] * (-len(values) % width)
    data = np.array(values, dtype=float).reshape(-1, width)
    assert fmt_rows(data, sig) == _reference(data, sig)


@pytest.mark.parametrize("seed", [0, 1])
def test_large_random_tables_in_many_blocks(seed):
    # magnitudes across 1e-30 … 1e30, numbers rounded to a few decimals (as inputs are), small
    # integers, zeros: more rows than one block holds, so several blocks join
    rng = np.random.default_rng(seed)
    n = 3 * numbers._BLOCK
    x = rng.choice([-1.0, 1.0], n) * 10.0 ** rng.uniform(-30, 30, n)
    x[::5] = np.round(rng.normal(0, 100, len(x[::5])), rng.integers(0, 6))
    x[1::7] = rng.integers(-1000, 1000, len(x[1::7]))
    x[2::11] = 0.0
    data = x.reshape(-1, 13 if n % 13 == 0 else 8)
    rows = _reference(data)
    assert fmt_rows(data) == rows
    assert fmt_text(data) == "".join(row + "\n" for row in rows)


def test_one_row_and_one_column_tables():
    for data in (np.array([[0.1, -2.0, 3e-9]]), np.array([[0.1], [-2.0], [math.nan]]),
                 np.zeros((0, 3)), np.zeros((2, 0))):
        assert fmt_rows(data) == _reference(data)
        assert fmt_text(data) == "".join(row + "\n" for row in _reference(data))
