"""Periodic piecewise-linear interpolation: a table over one cycle Φ, repeated with period Φ.

One rule, two implementations: :func:`periodic_linear` on numpy arrays (the tabulated route's
'linear' and 'finite-differences' kinds, the time integration's comparison with ω(φ)) and
:class:`PeriodicTables` in plain Python floats for the right-hand side of an ODE, called once
per step with a scalar angle. Both wrap x into [x_0, x_0 + Φ) and take the interval
[x_i, x_{i+1}) that holds it; they differ only in the last bit of the value (see
:class:`PeriodicTables`).
"""
from __future__ import annotations

from bisect import bisect_right

import numpy as np


def periodic_linear(xp: np.ndarray, fp: np.ndarray, x, period: float, derivative: bool = False,
                    snap: float = 0.0) -> np.ndarray:
    """fp [any unit] given at the closed, increasing nodes xp (xp[-1] = xp[0] + Φ, fp[-1] = fp[0])
    interpolated linearly at x, wrapped into [xp[0], xp[0] + period) first.

    The value is f_i + s_i·(x − x_i) with the slope s_i = (f_{i+1} − f_i)/(x_{i+1} − x_i) of
    the interval [x_i, x_{i+1}) that holds x: bit for bit ``np.interp`` on the wrapped x.
    ``derivative``: the slope s_i instead (a forward difference, seed 004 eq. 10). ``snap``
    [unit of x]: an x within ``snap`` below a node belongs to the interval that starts there.

    >>> xp = np.array([0.0, 1.0, 2.0]); fp = np.array([0.0, 4.0, 0.0])
    >>> periodic_linear(xp, fp, np.array([0.5, 2.5, -0.25]), 2.0).tolist()
    [2.0, 2.0, 1.0]
    """
    xp = np.asarray(xp, float)
    fp = np.asarray(fp, float)
    t = xp[0] + np.mod(np.asarray(x, float) - xp[0], period)
    k = np.clip(np.searchsorted(xp, t + snap, side="right") - 1, 0, xp.size - 2)
    slope = (fp[k + 1] - fp[k]) / (xp[k + 1] - xp[k])
    return slope if derivative else fp[k] + slope * (t - xp[k])


class PeriodicTables:
    """Several tables on one closed grid ``x`` (one cycle Φ = x[-1] − x[0]), interpolated
    linearly and repeated with period Φ, evaluated together at one scalar angle: one bisection
    for all tables, in plain Python floats (~10× faster per call than np.interp on a scalar,
    which dominates the cost of a time integration).

    The value is f_i + (f_{i+1} − f_i)·w with the weight w = (x − x_i)/(x_{i+1} − x_i): the
    same interpolant as :func:`periodic_linear`, rounded differently (the last bit may differ),
    and kept so, because the time-domain results are written with every digit.

    Three tables (J, J′, M of the equation of motion), unrolled for speed.

    >>> tab = PeriodicTables([0.0, 1.0, 2.0], [0.0, 4.0, 0.0], [1.0, 1.0, 1.0], [0.0, 2.0, 0.0])
    >>> tab(2.5), tab(-0.25)
    ((2.0, 1.0, 1.0), (1.0, 1.0, 0.5))
    """

    def __init__(self, x, a, b, c):
        self.x = [float(v) for v in x]
        self.a, self.b, self.c = (np.asarray(f, float).tolist() for f in (a, b, c))
        self.x0 = self.x[0]
        self.period = self.x[-1] - self.x0
        self.last = len(self.x) - 2

    def __call__(self, x: float) -> tuple[float, float, float]:
        x = (x - self.x0) % self.period + self.x0
        i = min(max(bisect_right(self.x, x) - 1, 0), self.last)
        w = (x - self.x[i]) / (self.x[i + 1] - self.x[i])
        a, b, c = self.a, self.b, self.c
        return (a[i] + (a[i + 1] - a[i]) * w, b[i] + (b[i + 1] - b[i]) * w,
                c[i] + (c[i + 1] - c[i]) * w)
