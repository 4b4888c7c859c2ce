"""The paper's Fig. 3 question as a sweep (armrt.sweep): over a grid of middle+anterior deltoid
levels and rotator-cuff boosts, the worst GHstab of the deltoid sequence (Fig. 2/3: ramp on 1 s,
hold 3 s, ramp off 2 s) and the humeral elevation it reaches. `armrt.experiments` searches this
space one simulation after another for the smallest safe boost; here every point is an independent
whole simulation, so the grid runs in parallel (backend="ray") or in-process (backend="local").

    from armrt.cuff_grid import cuff_grid
    grid = cuff_grid(levels=[0.10, 0.15, 0.20], boosts=[0, 0.05, 0.1, 0.2], backend="ray")
    grid["gh_stab_max"]          # (levels, boosts)
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .experiments_protocol import (deltoid_sequence, find_baseline, middle_anterior_deltoid, new_arm,
                                   plateau_elevation, run_sequence)
from .sweeps import sweep


@dataclass(frozen=True)
class GridSetup:
    baseline: dict          # rotator-cuff baseline excitations (Table III), muscle -> level
    deltoid: tuple          # element names of the middle and anterior deltoid
    q0: np.ndarray          # rad, start posture: the arm settled at the baseline


def grid_setup() -> GridSetup:
    """The experiments' own Table III baseline, settled posture and deltoid elements."""
    arm = new_arm()
    base = find_baseline(arm)
    return GridSetup(dict(base.levels), tuple(middle_anterior_deltoid(arm)), base.settled.q.copy())


def grid_point(item) -> dict:
    """One whole simulation: item = (GridSetup, deltoid level, cuff boost on each cuff muscle).
    Returns gh_stab_max (worst GHstab at every 1 ms control step) and elevation_deg
    (thorax-humerus elevation at the end of the hold)."""
    setup, level, boost = item
    seq = deltoid_sequence("grid", setup.baseline, list(setup.deltoid), float(level), float(boost), setup.q0)
    _, res = run_sequence(seq, record_every=1)
    return {"gh_stab_max": float(res.gh_stab.max()), "elevation_deg": plateau_elevation(res)}


def cuff_grid(levels, boosts, backend: str = "local", setup: GridSetup | None = None, **sweep_kwargs) -> dict:
    """Runs every (level, boost) pair through armrt.sweep. Returns {"levels": (L,), "boosts": (B,),
    "gh_stab_max": (L, B), "elevation_deg": (L, B)}. sweep_kwargs go to armrt.sweep (address=,
    progress=, ...)."""
    levels, boosts = np.asarray(levels, dtype=float), np.asarray(boosts, dtype=float)
    setup = setup or grid_setup()
    items = [(setup, lv, b) for lv in levels for b in boosts]
    out = sweep(grid_point, items, backend=backend, desc="Fig. 3 grid", **sweep_kwargs)
    shape = (len(levels), len(boosts))
    return {"levels": levels, "boosts": boosts,
            "gh_stab_max": out["gh_stab_max"].reshape(shape), "elevation_deg": out["elevation_deg"].reshape(shape)}


def plot_grid(grid: dict, path, limit: float = 0.5) -> None:
    """Heat map of the worst GHstab over the grid, the safe region (GHstab < limit) outlined,
    elevations written in the cells."""
    import matplotlib
    matplotlib.use("Agg", force=False)
    import matplotlib.pyplot as plt

    g, e = grid["gh_stab_max"], grid["elevation_deg"]
    fig, ax = plt.subplots(figsize=(7, 4.5), dpi=100)
    im = ax.imshow(g, origin="lower", cmap="RdYlGn_r", vmin=0, vmax=max(1.0, float(np.nanmax(g))), aspect="auto")
    ax.set_xticks(range(len(grid["boosts"])), [f"{b:.2f}" for b in grid["boosts"]])
    ax.set_yticks(range(len(grid["levels"])), [f"{v:.2f}" for v in grid["levels"]])
    ax.set_xlabel("rotator-cuff boost (excitation added to each cuff muscle)")
    ax.set_ylabel("deltoid excitation")
    for i in range(g.shape[0]):
        for j in range(g.shape[1]):
            ax.text(j, i, f"{g[i, j]:.2f}\n{e[i, j]:.0f}°", ha="center", va="center", fontsize=7,
                    fontweight="bold" if g[i, j] < limit else "normal")
    fig.colorbar(im, ax=ax, label="worst GHstab over the sequence")
    ax.set_title(f"Fig. 3 grid: worst GHstab (bold: < {limit}) and elevation at the hold", fontsize=9)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


