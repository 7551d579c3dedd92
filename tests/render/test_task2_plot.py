"""The task-2 figure (render/task2.py ``plot``) marks ω_max and ω_min where the solution puts
them, and its φ axis spans the whole cycle (720° for a four-stroke engine)."""
import math
from pathlib import Path

import pytest

from flywheel.cases.task2 import load_task2_case, solve_case

CASES = Path(__file__).resolve().parents[2] / "cases"


def _figure(monkeypatch, name):
    """The figure ``plot`` draws for a bundled case (caught at savefig, nothing written)."""
    from matplotlib.figure import Figure

    from flywheel.render.task2 import plot

    caught = []
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: caught.append(self))
    r = solve_case(load_task2_case(CASES / f"{name}.toml"))
    plot(r, "x.png", lang="en")
    return r, caught[0]


@pytest.mark.parametrize("name", ["task2_seed_triangle", "task2_khurmi_16_9"])
def test_omega_max_and_min_are_marked_at_the_solution(monkeypatch, name):
    r, fig = _figure(monkeypatch, name)
    omega_axis = fig.axes[2]
    marks = {line.get_marker(): (line.get_xdata()[0], line.get_ydata()[0], line.get_label())
             for line in omega_axis.lines if line.get_marker() in ("^", "v")}
    assert marks["^"][:2] == pytest.approx((math.degrees(r.phi_omega_max), r.omega_max))
    assert marks["v"][:2] == pytest.approx((math.degrees(r.phi_omega_min), r.omega_min))
    assert "max" in marks["^"][2] and "min" in marks["v"][2]
    # the marks are on the curve: its highest and lowest points
    curve = next(line for line in omega_axis.lines if line.get_marker() in ("None", ""))
    assert max(curve.get_ydata()) == pytest.approx(r.omega_max, rel=1e-9)
    assert min(curve.get_ydata()) == pytest.approx(r.omega_min, rel=1e-9)


@pytest.mark.parametrize("name, cycle", [("task2_khurmi_16_9", 720), 
                                         ("task2_seed_triangle", 360)])
def test_the_phi_axis_spans_the_cycle(monkeypatch, name, cycle):
    _, fig = _figure(monkeypatch, name)
    ticks = fig.axes[-1].get_xticks()
    assert ticks[0] == 0 and ticks[-1] == cycle


def test_omega_max_and_min_read_apart_in_russian(monkeypatch):
    """The textbook task's δ ≈ 1.1·10⁻⁴: the Russian policy's four digits wrote both ω_max and
    ω_min «200 рад/с». They are written to the decimals that tell them apart, and one more
    (numbers.apart): «200,011» and «199,989», as the task's table gives them (200,011044 and
    199,988955 rad/s)."""
    from matplotlib.figure import Figure

    from flywheel.render.numbers import typeset
    from flywheel.render.task2 import plot

    caught = []
    monkeypatch.setattr(Figure, "savefig", lambda self, *a, **k: caught.append(self))
    r = solve_case(load_task2_case(CASES / "task2_seed_triangle.toml"))
    assert round(r.omega_max, 3) == 200.011 and round(r.omega_min, 3) == 199.989
    typeset("ru", plot, r, "x.png", lang="ru")
    labels = [line.get_label() for line in caught[0].axes[2].lines
              if line.get_marker() in ("^", "v")]
    assert any("200,011 рад/с" in x for x in labels) and any("199,989 рад/с" in x for x in labels), labels

