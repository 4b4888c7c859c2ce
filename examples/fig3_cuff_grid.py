"""Worked example of armrt.sweep: the paper's Fig. 3 question (how much rotator-cuff drive keeps the
gleno-humeral joint stable while the deltoid abducts the arm?) as a grid of whole simulations.

    python examples/fig3_cuff_grid.py                      # Ray on this machine (ray.init() implicit)
    python examples/fig3_cuff_grid.py --address auto       # an existing Ray cluster (`ray start --head` ...)
    python examples/fig3_cuff_grid.py --backend local      # no Ray: one simulation after another

Writes fig3_grid.png (worst GHstab per cell, elevation reached) and fig3_grid.json. Each cell is a
9 s simulation (about 1 s of CPU); the default 3 x 7 grid takes ~20 s on one core.
"""
import argparse
import json
import time

import numpy as np

from armrt.cuff_grid import cuff_grid, plot_grid


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--backend", choices=["ray", "local"], default="ray")
    p.add_argument("--address", default=None, help="Ray cluster address (default: start Ray on this machine)")
    p.add_argument("--levels", type=float, nargs="+", default=[0.10, 0.149, 0.20], help="deltoid excitations")
    p.add_argument("--boosts", type=float, nargs="+", default=list(np.round(np.arange(0, 0.301, 0.05), 2)),
                   help="rotator-cuff boosts (added to each cuff muscle while the deltoid is on)")
    p.add_argument("--out", default="fig3_grid")
    a = p.parse_args(argv)
    t0 = time.perf_counter()
    grid = cuff_grid(a.levels, a.boosts, backend=a.backend, address=a.address)
    wall = time.perf_counter() - t0
    plot_grid(grid, a.out + ".png")
    with open(a.out + ".json", "w") as f:
        json.dump({k: np.asarray(v).tolist() for k, v in grid.items()} | {"backend": a.backend, "wall_s": wall}, f, indent=1)
    safe = grid["gh_stab_max"] < 0.5
    print(f"{grid['gh_stab_max'].size} simulations in {wall:.1f} s ({a.backend}); "
          f"cells with worst GHstab < 0.5: {int(safe.sum())}; wrote {a.out}.png, {a.out}.json")
    for i, lv in enumerate(grid["levels"]):
        ok = grid["boosts"][safe[i]]
        print(f"  deltoid {lv:.3f}: smallest safe boost on the grid "
              f"{ok.min():.2f}" if ok.size else f"  deltoid {lv:.3f}: no boost on the grid keeps GHstab < 0.5")


if __name__ == "__main__":
    main()
