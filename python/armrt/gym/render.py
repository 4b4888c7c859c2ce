"""render(): one frame of the `armrt animate` figure as an RGB array (armrt.animate.build_figure)."""
from __future__ import annotations

import numpy as np


def render_frame(result, target=None, dpi: int = 50) -> np.ndarray:
    """(H, W, 3) uint8 of the last row of `result` (time, q, gh_stab, activation, element_names,
    model), with `target` (3, m, thorax frame) drawn as a star in both arm views when given."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    from ..animate import build_figure

    fig, draw, views = build_figure(result, np.array([len(result.time) - 1]), dpi=dpi)
    try:
        draw(0)
        if target is not None:
            t = np.asarray(target, dtype=float)
            for ax, proj in views:
                h, v = proj(t)
                ax.plot([h], [v], marker="*", ms=12, color="tab:purple", ls="none")
                x0, x1 = ax.get_xlim()
                y0, y1 = ax.get_ylim()
                ax.set_xlim(min(x0, h - 0.03), max(x1, h + 0.03))
                ax.set_ylim(min(y0, v - 0.03), max(y1, v + 0.03))
        fig.canvas.draw()
        return np.array(fig.canvas.buffer_rgba())[..., :3]
    finally:
        plt.close(fig)
