"""The one number formatter of every output a person reads (summaries, reports, sheets, CSV).

The policy (the defaults of :func:`fmt`):

- ``sig`` significant digits (6), Python's ``g`` presentation: trailing zeros dropped, the
  exponent form when the exponent is below −4 or at least ``sig`` (also after rounding:
  999 999.5 to 6 digits is ``1e+06``, 9.9996 to 4 digits is ``10``);
- zero: −0, and round-off below ``zero`` in magnitude (1e-12), print as ``0``;
- no value (None) prints as ``—``;
- NaN and ±inf are refused (ValueError): a non-finite number is refused where it enters
  (docs/architecture.md), so one reaching a renderer is a bug.

Russian typography (issue 28, every Russian document: the записка in md/html/pdf/docx, the
terminal summary in ru) is a second policy of the same function, switched on for a stretch of
rendering by ``with typography("ru"):`` (the CLI wraps the building of a Russian document and
summary in it; machine-readable outputs — summary.json, the CSV files — are never written inside
it):

- results to ``RESULT_SIG`` (4) significant digits (a larger ``sig`` or a ``g``/``e`` spec is
  capped at it); an input the case gave (``given=True``) with the digits it was given (the
  shortest text that reads back as the same number); an ``f`` spec (``.2f``) keeps its decimals;
- never the exponent form: fixed notation; a number of more than ``RESULT_SIG`` integer digits
  printed whole (12 345,6 → «12 346»);
- round-off as 0: |x| below the computation's noise (``typography(lang, noise=…)``, default
  ``NOISE`` = 1e-9 in SI units, or the caller's larger ``zero``) prints «0»;
- decimal comma, true minus «−» (U+2212), the integer part of five digits or more in groups of
  three separated by a narrow no-break space (U+202F): «−12 345,6».

The CSV dialect ``excel-ru`` writes the plain text of a number with :func:`excel_ru` (a decimal
comma only: a hyphen-minus and the exponent stay, so that Excel reads a number).

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
import re
from contextlib import contextmanager
from functools import lru_cache
from contextvars import ContextVar
from dataclasses import dataclass
from decimal import Decimal

import numpy as np

DASH = "—"
NONFINITE = ("refuse", "show", "dash", "dash-nan")
#: Russian typography: significant digits of a result; the noise below which a value is 0 (SI)
RESULT_SIG, NOISE = 4, 1e-9
#: a column of results: round-off relative to its largest magnitude (:func:`column_zero`)
COLUMN_NOISE = 1e-9
MINUS, THIN = "\u2212", "\u202f"


@dataclass(frozen=True)
class Typography:
    """The policy in force for a stretch of rendering (:func:`typography`)."""

    lang: str = "en"
    noise: float = NOISE


_POLICY: ContextVar[Typography | None] = ContextVar("flywheel_typography", default=None)


@contextmanager
def typography(lang: str, noise: float = NOISE):
    """Within the block, :func:`fmt` writes ``lang``'s typography ("ru": the Russian policy of
    the module's docstring, with ``noise`` the computation's round-off; "en": the default).

    >>> with typography("ru"):
    ...     fmt(-12345.678), fmt(0.0496522), fmt(5.7e-14), fmt(1.5e-5, 2), fmt(142.8, spec=".2f")
    ('−12\u202f346', '0,04965', '0', '0,000015', '142,80')
    >>> with typography("ru"):
    ...     fmt(0.086603, given=True), fmt(1200.0, given=True), fmt(2.5e-6, given=True)
    ('0,086603', '1200', '0,0000025')
    """
    token = _POLICY.set(Typography(lang, noise) if lang == "ru" else None)
    try:
        yield
    finally:
        _POLICY.reset(token)


def russian() -> bool:
    """Whether the Russian policy is in force (a renderer that writes more than a number — a
    point «(x; y)», whose comma would be the decimal sign — asks)."""
    return _POLICY.get() is not None


def separator(lang: str | None = None) -> str:
    """Between numbers listed in one place: «; » in Russian, where the comma is the decimal mark
    («i = 1; 3,968», «(0,7; 0,3)»), ", " in English; ``lang`` None: the typography in force.

    >>> separator("ru"), separator("en")
    ('; ', ', ')
    """
    return "; " if (russian() if lang is None else lang == "ru") else ", "


def typeset(lang: str, build, /, *args, **kwargs):
    """``build(*args, **kwargs)`` under ``lang``'s typography (:func:`typography`): a Russian
    document or summary built with Russian numbers."""
    with typography(lang):
        return build(*args, **kwargs)


def excel_ru(text: str) -> str:
    """A number's plain text as the CSV dialect ``excel-ru`` writes it: the decimal comma (the
    minus and an exponent stay as Excel reads them).

    >>> excel_ru("-1.5e-05")
    '-1,5e-05'
    """
    return text.replace(".", ",")


def _grouped(digits: str) -> str:
    """An integer part of five digits or more in groups of three (ГОСТ 8.417 / Russian usage)."""
    if len(digits) < 5:
        return digits
    head = len(digits) % 3 or 3
    return THIN.join([digits[:head]] + [digits[i:i + 3] for i in range(head, len(digits), 3)])


def _russian(x: float, sig: int, spec: str | None, given: bool, noise: float) -> str:
    """A finite ``x`` under the Russian policy (the module's docstring)."""
    if x == 0 or abs(x) < noise:
        return "0"
    a = abs(x)
    m = _SPEC.fullmatch(spec or "")
    plus = "+" if m and m["sign"] == "+" and x > 0 else ""
    if spec is not None and m is None:            # a spec of another kind: as it asks
        return format(x, spec.replace(",", "").replace("_", "")).replace("-", MINUS).replace(".", ",")
    if m and m["type"] in ("f", "F"):
        text = format(a, f".{m['digits'] or 6}f")
        spec = ".f"
    elif given:
        text = format(Decimal(repr(a)), "f")
    else:
        if m and m["digits"]:                     # ".6g", ".1e": their digits, capped
            sig = int(m["digits"]) + (m["type"] in ("e", "E"))
        sig = max(1, min(sig, RESULT_SIG))
        if a >= 10.0 ** sig:
            text = f"{a:.0f}"
        else:
            text = format(Decimal(format(a, f".{sig - 1}e")).normalize(), "f")
    if "." in text:
        whole, frac = text.split(".")
        frac = frac.rstrip("0") if not (spec and spec.endswith("f")) else frac
    else:
        whole, frac = text, ""
    if text.strip("0.") == "":                    # rounded away entirely
        return "0" if not frac else "0," + frac
    return (MINUS if x < 0 else plus) + _grouped(whole) + ("," + frac if frac else "")


_SPEC = re.compile(r"(?P<sign>[+ -]?)(?:\.(?P<digits>\d+))?(?P<type>[eEfFgG]?)")


class _Typeset(float):
    """A number a sentence's template formats (``{work:+.1e}``) as :func:`fmt` writes it."""

    def __format__(self, spec: str) -> str:
        return fmt(float(self), spec=spec or None, zero=None, nonfinite="show")


def typeset_params(params: dict) -> dict:
    """A sentence's parameters with their real numbers written by the policy in force: within
    ``typography("ru")`` a warning copied into a Russian document has Russian numbers; outside
    it (stderr, English) the parameters are returned as they are."""
    if _POLICY.get() is None:
        return params
    return {k: _Typeset(v) if isinstance(v, float) else v for k, v in params.items()}


def fmt(x, sig: int = 6, *, zero: float | None = 1e-12, spec: str | None = None,
        nonfinite: str = "refuse", integers_above: bool = False, given: bool = False) -> str:
    """``x`` (a real number or None) as text under the policy of this module's docstring.

    sig: significant digits (``g`` presentation), unless ``spec`` (a whole format spec such as
    ".6f") is given; zero: |x| below it, and −0, print as 0 (None: −0 stays ``-0``; 0: only
    ±0 → 0); nonfinite: "refuse" (ValueError), "show" (``nan``, ``inf``), "dash" (``—``),
    "dash-nan" (``—`` for NaN, ``inf`` shown); integers_above: |x| ≥ 10^sig as a whole number;
    given: ``x`` is an input of the case (Russian typography prints it with its own digits).

    >>> fmt(-0.0), fmt(3e-13), fmt(1234567.0), fmt(0.1 + 0.2), fmt(None)
    ('0', '0', '1.23457e+06', '0.3', '—')
    """
    if x is None:
        return DASH
    x = float(x)
    if not math.isfinite(x):
        if nonfinite == "show" or (nonfinite == "dash-nan" and not math.isnan(x)):
            text = format(x, spec or f".{sig}g")
            return text.replace("-", MINUS) if _POLICY.get() is not None else text
        if nonfinite in ("dash", "dash-nan"):
            return DASH
        # library use only: no CLI input reaches this
        raise ValueError(f"a non-finite number ({x}) to format: it should have been refused "
                         f"where it entered")
    policy = _POLICY.get()
    if policy is not None:
        return _russian(x, sig, spec, given, max(policy.noise, zero or 0.0))
    if zero is not None and (x == 0 or abs(x) < zero):
        x = 0.0
    if integers_above and abs(x) >= 10.0 ** sig:
        return f"{x:.0f}"
    return format(x, spec or f".{sig}g")


#: the significant digits of a number put into a worked formula (:func:`fmt_worked`)
WORKED_SIG = 6


def fmt_worked(x: float) -> str:
    """A number put into a formula the record works («J_I = 916,283/(0,05·62,8319²) = 4,642»):
    :data:`WORKED_SIG` significant digits in every language, trailing zeros dropped — the
    Russian policy's four (:data:`RESULT_SIG`) would not always give the result back to its
    last printed digit (2,656 printed, 2,654 worked again from four-digit inputs).

    >>> fmt_worked(62.83185307), fmt_worked(9000.0), fmt_worked(0.05)
    ('62.8319', '9000', '0.05')
    """
    places = max(0, WORKED_SIG - 1 - math.floor(math.log10(abs(x)))) if x else 0
    text = fmt(x, spec=f".{places}f", zero=None, nonfinite="dash")
    return text.rstrip("0").rstrip(",.") if places else text


def column_zero(values, floor: float = 0.0) -> float:
    """The ``zero`` of :func:`fmt` for the numbers of one column of results over the cycle:
    ``COLUMN_NOISE`` times its largest magnitude (at least ``floor``). A work integrated over
    the grid returns to its start with a round-off of 10⁻¹² of its scale, a few 10⁻⁹ J for
    hundreds of joules: it prints «0», not «−0,00000000106» (a Russian record) or
    «-1.06e-09».

    >>> column_zero([0.0, -1.06e-9, 556.9, -545.5]) > 1.06e-9, column_zero([0.0, 0.0])
    (True, 0.0)
    """
    a = np.abs(np.asarray(values, dtype=float))
    a = a[np.isfinite(a)]
    return max(floor, COLUMN_NOISE * float(a.max()) if a.size else 0.0)


def to_tolerance(x: float, tolerance: float, sig: int = RESULT_SIG, most: int = 12) -> str | None:
    """A ".{d}f" spec that writes an answer ``x`` to a tenth of its relative ``tolerance``
    where ``sig`` significant digits (the Russian policy's cap) would not: a key of ω_max
    within 0.001 % as «250,0101», not «250», beside a student's «250,01»; None where ``sig``
    digits do (a 1 % tolerance), or at most ``most`` decimals could not.

    >>> to_tolerance(250.0101036, 1e-5), to_tolerance(197.9, 0.01), to_tolerance(7.06e-5, 0.01)
    ('.4f', None, None)
    """
    if not x or not tolerance or not math.isfinite(x) or not math.isfinite(tolerance):
        return None
    step = abs(x) * tolerance / 10                          # the digit the answer needs
    last = 10.0 ** (math.floor(math.log10(abs(x))) - sig + 1)   # the last of sig digits
    if last <= step:
        return None
    d = max(0, math.ceil(-math.log10(step)))
    return f".{d}f" if d <= most else None


def apart(a: float, b: float, sig: int = RESULT_SIG, most: int = 9) -> str | None:
    """A format spec that writes ``a`` and ``b`` differently where ``sig`` significant digits
    (the Russian policy's cap) write them alike: ".{d}f" with one decimal more than the fewest
    that tell them apart (ω_max = 200,011 against ω_min = 199,989 rad/s where four digits write
    200 and 200), at most ``most``; None where ``sig`` digits already do, or none can.

    >>> apart(200.011044, 199.988955), apart(64.97, 61.76)
    ('.3f', None)
    """
    if a == b or format(a, f".{sig}g") != format(b, f".{sig}g"):
        return None
    for d in range(most):
        if format(a, f".{d}f") != format(b, f".{d}f"):
            return f".{d + 1}f"
    return None


def fmt_rows(data, sig: int = 12) -> list[str]:
    """Each row of a 2-D array as its numbers joined by commas, each as :func:`fmt` writes it
    with ``zero=0.0, nonfinite="show"`` (−0 → 0, nan shown): the CSV files' numbers, the same
    text as ``"%.{sig}g"`` per number (:func:`fmt_text`, split into its lines)."""
    return fmt_text(data, sig).split("\n")[:-1]


def fmt_text(data, sig: int = 12) -> str:
    """The rows of :func:`fmt_rows` as one text, each row ended by a newline. Up to 12 digits
    the text is made for a block of rows at once (:func:`_g_bytes`; two thirds of the CPU time
    of one ``%`` per row)."""
    data = np.asarray(data, dtype=float) + 0.0          # + 0.0: −0.0 becomes 0.0, nothing else
    if data.ndim != 2 or data.size == 0 or not 1 <= sig <= _FAST_SIG:
        row = ",".join([f"%.{sig}g"] * data.shape[1])
        return "".join([row % tuple(r) + "\n" for r in data.tolist()])
    n_cols = data.shape[1]
    step = max(1, _BLOCK // n_cols)                     # rows of a block: it stays in the cache
    pieces = []
    for start in range(0, len(data), step):
        cells = _g_bytes(data[start:start + step].ravel(), sig)
        cells[:, -1] = ord(",")
        cells[n_cols - 1::n_cols, -1] = ord("\n")
        flat = cells.ravel()
        pieces.append(flat[flat != 0].tobytes())
    return b"".join(pieces).decode("ascii")


#: the most digits :func:`_g_bytes` writes (10**12 · 2.3e-16 ≪ _TIE: the rounding is decided)
_FAST_SIG = 12
#: numbers formatted together by fmt_rows: a block's arrays stay in the cache and below
#: malloc's 128 KiB mmap threshold (a larger one is mapped afresh for each block)
_BLOCK = 4096
#: |fraction − ½| below this: too near a tie for the float arithmetic, written by ``%``
_TIE = 1e-3


@lru_cache(maxsize=None)
def _g_tables() -> tuple:
    """The tables of :func:`_g_bytes`, made at its first call (a command that writes no CSV
    never pays for them): 10**k as the nearest float, k = 0 … 300 (``float`` of an exact
    integer: correctly rounded); the four ASCII digits of 0 … 9999, each as one 4-byte word;
    how many zeros end 0 … 9999 (0: 4); keep[sig][j], a mask over sig digits keeping the
    first j + 1."""
    quad = np.indices((10, 10, 10, 10)).reshape(4, -1)     # the four digits of 0 … 9999
    pow10 = np.array([float(10 ** k) for k in range(301)])
    digits4 = np.ascontiguousarray(quad.T + ord("0"), dtype=np.uint8).view(np.uint32).ravel()
    zeros4 = np.logical_and.accumulate(quad[::-1] == 0, axis=0).sum(axis=0, dtype=np.intp)
    keep = [np.where(np.arange(s)[None, :] <= np.arange(s)[:, None], 255, 0).astype(np.uint8)
            for s in range(_FAST_SIG + 1)]
    return pow10, digits4, zeros4, keep


def _g_bytes(x: np.ndarray, sig: int) -> np.ndarray:
    """``"%.{sig}g" % v`` of every number of the 1-D ``x`` (−0 already 0), as ASCII bytes: one
    row each, left-aligned and padded with zero bytes, one spare zero column at the end.

    The rounding to ``sig`` digits is Python's (round half to even of the exact binary value):
    q = |v|·10^k in floats is within 2.3e-16·q < 2.3e-4 of the exact product (10^k correctly
    rounded, one more rounding), so rint(q) is the exact rounding unless q's fraction is within
    :data:`_TIE` of ½; such numbers, and zero's neighbours below 1e-280, those above 1e280,
    nan and ±inf, are written by ``%``. ``%g``'s layout (C99 7.21.6.1, Python's format spec):
    exponent X of the rounded number; fixed notation when −4 ≤ X < sig, else d.ddde±XX;
    trailing zeros and a bare point dropped."""
    n, width = len(x), sig + 8                 # -d.ddd…e-308, then the separator's column
    _POW10, _DIGITS4, _ZEROS4, _KEEP = _g_tables()
    out = np.zeros((n, width), np.uint8)
    ax = np.abs(x)
    fast = (ax > 1e-280) & (ax < 1e280)        # finite, not zero, 10^k a normal float
    lo, hi = 10.0 ** (sig - 1), 10.0 ** sig
    with np.errstate(all="ignore"):            # nan, inf and the extremes go to ``%``
        e0 = np.floor(np.log10(np.where(fast, ax, 1.0))).astype(np.int64)
        k = sig - 1 - e0
        scale = _POW10[np.minimum(np.abs(k), 300)]
        q = ax * scale
        up = k < 0
        q[up] = ax[up] / scale[up]
        frac = q - np.floor(q)
        # q in [10^(sig-1) − 0.04, 10^(sig-1)): |v| is just below 10^e0 and rounds up to it
        fast &= (np.abs(frac - 0.5) >= _TIE) & (q >= lo - 0.04) & (q < hi)
    zero = x == 0
    out[zero, 0] = ord("0")
    for i in np.flatnonzero(~(fast | zero)):
        text = (f"%.{sig}g" % x[i]).encode("ascii")
        out[i, :len(text)] = np.frombuffer(text, np.uint8)
    idx = np.flatnonzero(fast)
    d = np.rint(q[idx])                        # an integer below 10^12: exact in a float
    roll = d == hi                             # 9.99…95 rounded up to the next decade
    d[roll] = lo
    e = (e0[idx] + roll).astype(np.int16)
    order = np.argsort(e, kind="stable")       # the numbers of one exponent together
    idx, d, e = idx[order], d[order], e[order]
    high = np.floor(d / 1e8)                   # d / 1e8 is ≥ 1e-8 short of the next integer
    rest = d - high * 1e8
    mid = np.floor(rest / 1e4)
    high, mid, low = high.astype(np.intp), mid.astype(np.intp), (rest - mid * 1e4).astype(np.intp)
    digits = np.stack([_DIGITS4[high], _DIGITS4[mid], _DIGITS4[low]], axis=1).view(np.uint8)
    digits = digits[:, 12 - sig:]
    last = np.where(low > 0, 11 - _ZEROS4[low],           # the last digit not 0, of sig
                    np.where(mid > 0, 7 - _ZEROS4[mid], 3 - _ZEROS4[high])) - (12 - sig)
    fixed = (e >= -4) & (e < sig)
    point_after = np.where(fixed, np.maximum(e, -1), 0)   # digits before the point, minus one
    digits &= _KEEP[sig][np.maximum(last, point_after)]   # trailing zeros dropped
    point = np.where(last > point_after, ord("."), 0).astype(np.uint8)
    rows = np.zeros((len(idx), width), np.uint8)
    rows[:, 0] = np.where(x[idx] < 0, ord("-"), 0)
    starts = np.flatnonzero(np.diff(e, prepend=-999, append=999))
    for a, b in zip(starts[:-1], starts[1:]):
        ex, r, dg = int(e[a]), rows[a:b], digits[a:b]
        if 0 <= ex < sig:                      # fixed notation, ex + 1 digits before the point
            r[:, 1:ex + 2], r[:, ex + 2] = dg[:, :ex + 1], point[a:b]
            r[:, ex + 3:sig + 2] = dg[:, ex + 1:]
        elif -4 <= ex < 0:                     # 0.000ddd
            head = np.frombuffer(b"0." + b"0" * (-ex - 1), np.uint8)
            r[:, 1:len(head) + 1], r[:, len(head) + 1:len(head) + 1 + sig] = head, dg
        else:                                  # d.ddde±XX
            tail = np.frombuffer(f"e{'-' if ex < 0 else '+'}{abs(ex):02d}".encode(), np.uint8)
            r[:, 1], r[:, 2], r[:, 3:sig + 2] = dg[:, 0], point[a:b], dg[:, 1:]
            r[:, sig + 2:sig + 2 + len(tail)] = tail
    out[idx] = rows
    return out
