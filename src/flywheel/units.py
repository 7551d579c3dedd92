"""The conversion constants, each named for its direction: ``A_PER_B`` turns a value in B into
one in A by multiplying (``n_rpm * RAD_S_PER_RPM`` is rad/s), or one in A into B by dividing
(``p_pa / PA_PER_MPA`` is MPa).

A leaf module (it imports only ``math``): every layer may use it. Source: the SI definitions
(1 rev = 2π rad, 1 min = 60 s, 1° = π/180 rad, 1 MPa = 10⁶ Pa).

Each constant is the very float the code computed in place before (``math.pi / 30.0``,
``30.0 / math.pi``), so a conversion through it gives the same bits; an expression of another
order (``n * 2 * math.pi / 60``) is written with ``TWO_PI`` and ``SECONDS_PER_MINUTE`` in that
order rather than folded into a constant, which could change its last bit.
"""
from __future__ import annotations

import math

#: 2π [rad per revolution]
TWO_PI = 2.0 * math.pi
#: [s per min]
SECONDS_PER_MINUTE = 60.0
#: rev/min → rad/s: π/30 (2π rad per revolution over 60 s per minute)
RAD_S_PER_RPM = math.pi / 30.0
#: rad/s → rev/min: 30/π
RPM_PER_RAD_S = 30.0 / math.pi
#: degrees → radians: π/180 (the factor of ``math.radians``)
RAD_PER_DEG = math.pi / 180.0
#: radians → degrees: 180/π (the factor of ``math.degrees``)
DEG_PER_RAD = 180.0 / math.pi
#: MPa → Pa: 10⁶ (divide a pressure or stress in Pa by it for MPa)
PA_PER_MPA = 1e6
