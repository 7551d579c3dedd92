"""Structure (not pixels) of the energy–mass, time-law and transient plots."""
from __future__ import annotations

from pathlib import Path

import pytest

from flywheel.case import load_case
from flywheel.pipeline import analyze
from flywheel.render import plots_extra

CASES = Path(__file__).resolve().parents[1] / "cases"


@pytest.fixture(scope="module")
def results():
    return analyze(load_case(CASES / "compressor.toml"), n_points=720, transients=True)


def test_energy_mass_diagram(results):
    fig = plots_extra.figure_energy_mass(results)
    try:
        em, merz = fig.axes
        assert em.get_xlabel() == "J_II [kg·m²]" and em.get_ylabel().endswith("[J]")
        assert len(em.get_lines()) == 3                 # the curve and two tangents
        labels = [t.get_text() for t in em.get_legend().get_texts()]
        assert any("ψ_max" in s for s in labels) and any("ψ_min" in s for s in labels)
        # the tangents touch the curve from above and below
        import numpy as np

        curve, tmax, tmin = em.get_lines()
        J, A = curve.get_xdata(), curve.get_ydata()
        for line, side in ((tmax, 1), (tmin, -1)):
            x, y = line.get_xdata(), line.get_ydata()
            on_line = y[0] + (y[1] - y[0]) / (x[1] - x[0]) * (J - x[0])
            gap = side * (on_line - A)
            assert gap.min() == pytest.approx(0, abs=1e-9 * np.ptp(A))   # touches
        assert merz.get_xlabel() == "φ [deg]"
        assert "ΔT_нб" in " ".join(t.get_text() for t in merz.get_legend().get_texts())
    finally:
        plots_extra._plt().close(fig)


def test_time_law_and_transients(results, tmp_path):
    fig = plots_extra.figure_time_law(results, lang="ru")
    try:
        assert [a.get_ylabel() for a in fig.axes] == ["ω [рад/с]", "ε [рад/с²]"]
        assert fig.axes[1].get_xlabel() == "t [с]"
    finally:
        plots_extra._plt().close(fig)
    paths = plots_extra.write_extra_plots(results, tmp_path)
    assert [p.name for p in paths] == ["energy_mass.png", "time_law.png", "transients.png"]
    assert all(p.read_bytes().startswith(b"\x89PNG") for p in paths)
