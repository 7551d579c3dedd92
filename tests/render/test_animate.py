"""mechanism.gif (`flywheel run --animate`): the linkage over one cycle, 72 frames on the φ
grid, the same bytes on a rerun, drawn by the scheme's own code."""
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from flywheel import analyze, load_case
from flywheel.cli import app
from flywheel.render.animate import frame_indices, write_animation

CASES = Path(__file__).resolve().parents[2] / "cases"


@pytest.fixture(scope="module")
def fourbar():
    return analyze(load_case(CASES / "fourbar.toml"), n_points=720)


def test_frames_are_grid_nodes_every_5_degrees(fourbar):
    idx = frame_indices(fourbar)
    assert len(idx) == 72 and len(set(idx)) == 72
    np.testing.assert_allclose(np.degrees(fourbar.phi[idx]), np.arange(0, 360, 5), atol=1e-9)


def test_gif_has_72_frames_and_the_same_bytes_twice(fourbar, tmp_path):
    from PIL import Image

    a, b = write_animation(fourbar, tmp_path / "a.gif"), write_animation(fourbar, tmp_path / "b.gif")
    assert a.read_bytes() == b.read_bytes()
    im = Image.open(a)
    assert im.format == "GIF" and im.n_frames == 72 and im.info.get("loop") == 0
    # the mechanism moves: frames differ
    im.seek(0)
    f0 = np.asarray(im.convert("RGB"))
    im.seek(18)
    assert np.any(np.asarray(im.convert("RGB")) != f0)


def test_run_animate_writes_mechanism_gif(tmp_path):
    res = CliRunner().invoke(app, ["run", str(CASES / "slotted_link.toml"), "--animate",
                                   "--no-plots", "--points", "360", "--out", str(tmp_path / "o")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "o" / "mechanism.gif").read_bytes()[:6] == b"GIF89a"


def test_animate_a_tabulated_case_is_one_line(tmp_path):
    res = CliRunner().invoke(app, ["run", str(CASES / "press.toml"), "--animate", "--no-plots",
                                   "--out", str(tmp_path / "o")])
    assert res.exit_code == 2 and "--animate" in res.stderr and "[tabulated]" in res.stderr
    assert not (tmp_path / "o").exists()
