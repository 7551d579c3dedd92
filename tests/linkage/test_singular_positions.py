"""Singular positions inside the cycle are refused like an assembly failure, naming the group
and the angle (issue 17): a slotted link whose block passes through the rocker's pivot, a
four-bar whose links fall in line."""
import math

import numpy as np
import pytest

from flywheel.errors import AssemblyError
from flywheel.linkage import RPR, RRR, Crank, Mechanism, solve


def slotted(pivot_radius: float, at: float = 1.0) -> Mechanism:
    """Crank 0.1 m about O; the rocker's pivot P at ``pivot_radius`` from O, at angle ``at``."""
    P = (pivot_radius * math.cos(at), pivot_radius * math.sin(at))
    return Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, 0.0, 1),
                     (RPR("r", "A", "P", "3", "2", 0.0, 1),), (), {"P": P})


@pytest.mark.parametrize("n", [36, 360, 1000, 3600, 100_000])
def test_pivot_on_the_crank_circle_is_found_between_nodes(n):
    """P on the circle A runs on, at 57.2958°: no grid here has a node there."""
    with pytest.raises(AssemblyError) as e:
        solve(slotted(0.1), np.linspace(0, 2 * np.pi, n + 1))
    msg = str(e.value)
    assert "dyad r (RPR, rocker 3) has a singular position near crank angle" in msg
    deg = float(msg.split("φ = ")[1].split("°")[0])
    assert abs(deg - math.degrees(1.0)) <= 360 / n + 0.005      # the message has 2 decimals
    assert e.value.dyad == "r"


def test_pivot_just_off_the_circle_is_a_mechanism():
    """1 mm off the circle: a real (if violent) slotted link, solved; ω_q peaks near l/(1 mm)."""
    k = solve(slotted(0.101), np.linspace(0, 2 * np.pi, 3601))
    assert 50 < np.abs(k.links["3"].omega_q).max() < 200


def test_four_bar_in_line_everywhere_is_a_dead_position():
    m = Mechanism(Crank("1", "O", (0.0, 0.0), "A", 0.1, 0.0, 1),
                  (RRR("d", "A", "2", 0.3, "O", "3", 0.2, "B", 1),), (), {})
    with pytest.raises(AssemblyError, match=r"reaches \|0.3 − 0.2\| = 0.1 m: the links lie in line"):
        solve(m, np.linspace(0, 2 * np.pi, 37))
