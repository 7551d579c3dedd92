"""mechanism.gif: the linkage moving over one cycle, drawn by the same code as the kinematic
scheme (render/plots.draw_scheme: links, joints, sliders on their guides, the trajectories of
the moving points), with the crank angle on every frame.

Frames are nodes of the φ grid (the node nearest each of ``frames`` equal steps of the cycle),
so what moves is what was computed; the axes are fixed to the whole motion, so nothing jumps.
What does not move is drawn once and each frame is blitted onto it (matplotlib's animation
technique on the Agg canvas), then Pillow writes the GIF with one palette for all frames; the
same results give the same bytes.
"""
from __future__ import annotations

import math
from pathlib import Path

import numpy as np

FRAMES = 72          # every 5° of a 360° cycle
FPS = 12             # a revolution in 6 s
DPI = 80

_TITLE = {"en": "φ = {a:.0f}°", "ru": "φ = {a:.0f}°"}


def frame_indices(results, frames: int = FRAMES) -> list[int]:
    """Grid nodes of the frames: the node nearest each of ``frames`` equal steps of the cycle
    (the closing node, equal to the first, is not repeated)."""
    cycle = float(results.phi[-1] - results.phi[0])
    return [results.index_of(results.phi[0] + cycle * k / frames) for k in range(frames)]


def write_animation(results, path: Path, lang: str = "en", frames: int = FRAMES,
                    fps: int = FPS) -> Path:
    """Write the animation of a linkage case's mechanism to ``path`` (GIF). Raises ValueError
    for a case without geometry (tabulated kinematics: nothing to draw)."""
    if results.kinematics is None:
        # library use only: no CLI input reaches this
        raise ValueError("tabulated kinematics have no geometry to animate")
    from PIL import Image

    from flywheel.render import figure as fg
    from flywheel.render import plots

    with fg.style(lang):
        fig, ax = fg.figure((6.4, 6.0), left=0.8, right=0.2, bottom=0.6, top=0.45)
        fig.set_dpi(DPI)
        b = results.drawing.bounds
        lo, hi = np.array(b[:2]), np.array(b[2:])
        span = float(max(hi[0] - lo[0], hi[1] - lo[1], 1e-9))
        size = 0.035 * span
        mid = (lo + hi) / 2
        half = 0.5 * span + 3 * size
        idx = frame_indices(results, frames)
        plots.draw_scheme_fixed(ax, results, size)       # drawn once: it does not move
        ax.set_xlim(mid[0] - half, mid[0] + half)
        ax.set_ylim(mid[1] - half, mid[1] + half)
        ax.set_aspect("equal", adjustable="box")
        ax.set_xlabel(plots.nm.axis("x", lang))
        ax.set_ylabel(plots.nm.axis("y", lang))
        fixed = set(ax.get_children())
        title = _TITLE.get(lang, _TITLE["en"])
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        canvas = FigureCanvasAgg(fig)
        canvas.draw()
        background = canvas.copy_from_bbox(fig.bbox)
        images, palette = [], None
        for i in idx:
            canvas.restore_region(background)
            for artist in [a for a in ax.get_children() if a not in fixed]:
                artist.remove()
            plots.draw_scheme_at(ax, results, i, size)
            ax.set_xlim(mid[0] - half, mid[0] + half)
            ax.set_ylim(mid[1] - half, mid[1] + half)
            for artist in sorted((a for a in ax.get_children() if a not in fixed),
                                 key=lambda a: a.get_zorder()):
                ax.draw_artist(artist)
            text = fig.text(0.5, 1 - 0.3 / 6.0, title.format(
                a=math.degrees(float(results.phi[i] - results.phi[0]))),
                ha="center", va="center", fontsize=12)
            fig.draw_artist(text)
            text.remove()
            rgb = Image.fromarray(np.asarray(canvas.buffer_rgba())[..., :3].copy())
            if palette is None:                 # one palette for every frame: same colours
                palette = rgb.quantize(colors=64, method=Image.Quantize.MEDIANCUT)
            images.append(rgb.quantize(palette=palette, dither=Image.Dither.NONE))
    images[0].save(str(path), save_all=True, append_images=images[1:], loop=0,
                   duration=round(1000 / fps), optimize=False)
    return Path(path)
