"""Command line: `armrt info`, `armrt simulate`, `armrt experiments`."""
from __future__ import annotations

import argparse
import sys

import numpy as np

from .arm import DEFAULT_INTEGRATOR, INTEGRATORS


def _parse_assignments(items: list[str]) -> dict[str, float]:
    out = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep:
            raise SystemExit(f"armrt: expected NAME=VALUE, got {item!r}")
        try:
            out[name] = float(value)
        except ValueError:
            raise SystemExit(f"armrt: {item!r}: {value!r} is not a number") from None
    return out


def cmd_info(args) -> int:
    from .arm import Arm
    arm = Arm(model=args.model)
    print(f"model {arm.model_name}: {len(arm.dof_names)} DOF, {len(arm.muscle_names)} muscles, "
          f"{arm.n_elements} elements, arm mass {arm.info['arm_mass']:.3f} kg")
    for name, (lo, hi), rest in zip(arm.dof_names, arm.dof_ranges, arm.rest_posture):
        print(f"  {name:5s} range [{np.degrees(lo):7.1f}, {np.degrees(hi):7.1f}] deg, rest {np.degrees(rest):6.1f} deg")
    print("muscles: " + ", ".join(f"{m} ({len(arm.indices(m))})" for m in arm.muscle_names))
    print("groups:  " + ", ".join(arm.group_names))
    return 0


def cmd_simulate(args) -> int:
    from .arm import Arm
    arm = Arm(model=args.model, integrator=args.integrator, dt=args.dt)
    arm.reset(q=None if args.q is None else np.radians(args.q))
    excitation = _parse_assignments(args.excitation)
    res = arm.simulate(excitation, duration=args.duration)
    q0, q1 = np.degrees(res.q[0]), np.degrees(res.q[-1])
    for j, name in enumerate(arm.dof_names):
        print(f"{name:5s} {q0[j]:8.2f} -> {q1[j]:8.2f} deg")
    print(f"GHstab max {res.gh_stab.max():.3f}; TET mean {res.tet_ns[:-1].mean() / 1e3:.2f} us, "
          f"max {res.tet_ns.max() / 1e3:.2f} us over {len(res.time) - 1} steps")
    if args.out:
        res.save(args.out)
        print(f"saved {args.out}")
    return 0


def cmd_experiments(args) -> int:
    from .experiments import run_all
    return run_all(out_dir=args.out, quick=args.quick)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(prog="armrt", description="Real-time musculoskeletal arm simulator")
    sub = ap.add_subparsers(dest="command", required=True)
    p = sub.add_parser("info", help="describe the model")
    p.add_argument("--model", default="das2")
    p.set_defaults(func=cmd_info)
    p = sub.add_parser("simulate", help="run with constant excitations, e.g. elbow_flexors=0.3 rotator_cuff=0.05")
    p.add_argument("excitation", nargs="*", help="NAME=VALUE (element, muscle or group)")
    p.add_argument("--model", default="das2")
    p.add_argument("--integrator", default=DEFAULT_INTEGRATOR, choices=INTEGRATORS,
                   help="integration method (default: %(default)s, one linearly implicit step per 1 ms)")
    p.add_argument("--dt", type=float, default=1e-3)
    p.add_argument("--duration", type=float, default=2.0)
    p.add_argument("--q", type=float, nargs=5, metavar="DEG", help="initial joint angles (deg)")
    p.add_argument("-o", "--out", help="save the result (.npz)")
    p.set_defaults(func=cmd_simulate)
    p = sub.add_parser("experiments", help="the paper's experiments: figures and tables")
    p.add_argument("--out", default="results", help="output folder")
    p.add_argument("--quick", action="store_true", help="shorter runs (for tests)")
    p.set_defaults(func=cmd_experiments)
    from .view import add_cli
    add_cli(sub)  # view, animate, export (viser is imported only when `view` runs)
    args = ap.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":
    sys.exit(main())
