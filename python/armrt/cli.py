"""Command line: `armrt info | simulate | model | experiments | view | animate | export`.

Units: radians in the API and in files; a flag takes degrees only when its name says so (`--q-deg`).
A user mistake (unknown name, missing file, bad value, unsupported format) prints one line
`armrt <command>: error: ...` and exits 2; `--traceback` shows the Python traceback instead.
"""
from __future__ import annotations

import argparse
import sys

import numpy as np

from .cli_common import USER_ERRORS, CliError, check_suffix, error_text, parse_assignments  # noqa: F401


def cmd_info(args) -> int:
    from .arm import Arm
    arm = Arm(model=args.model)
    print(f"model {arm.model_name}: {len(arm.dof_names)} DOF, {len(arm.muscle_names)} muscles, "
          f"{arm.n_elements} elements, arm mass {arm.info['arm_mass']:.3f} kg")
    for name, osim, (lo, hi), rest in zip(arm.dof_names, arm.dof_osim_names, arm.dof_ranges, arm.rest_posture):
        print(f"  {name:5s} ({osim:5s}) range [{lo:7.3f}, {hi:7.3f}] rad = [{np.degrees(lo):6.1f}, "
              f"{np.degrees(hi):6.1f}] deg, rest {rest:.3f} rad = {np.degrees(rest):5.1f} deg")
    print("muscles: " + ", ".join(f"{m} ({len(arm.indices(m))})" for m in arm.muscle_names))
    print("groups:  " + ", ".join(arm.group_names))
    print("OpenSim force names (delt_scap_1) and muscle names (delt_scap) are accepted as aliases.")
    return 0


def start_posture(args, arm) -> np.ndarray | None:
    """q (rad) from --q (rad), --q-deg (deg) or --q-mot (first row of a .mot, or at --q-mot-time)."""
    if args.q is not None:
        return np.asarray(args.q)
    if args.q_deg is not None:
        return np.radians(args.q_deg)
    if args.q_mot is not None:
        from .opensim_io import read_motion
        return read_motion(args.q_mot, model=arm.model_name).posture(args.q_mot_time)
    return None


def cmd_simulate(args) -> int:
    from .arm import Arm
    check_suffix(args.out, (".npz",), "--out")
    if not (np.isfinite(args.settle_duration) and args.settle_duration >= 0):
        raise CliError(f"--settle-duration must be a finite number of seconds >= 0, got {args.settle_duration:g}")
    excitation = parse_assignments(args.excitation)
    arm = Arm(model=args.model, integrator=args.integrator, dt=args.dt)
    arm.reset(q=start_posture(args, arm))
    arm.set_excitation(excitation)  # unknown names fail here, before any work
    if args.settle:
        arm.settle(args.settle_duration)
        print(f"settled for {args.settle_duration:g} s with no excitation")
    res = arm.simulate(excitation, duration=args.duration, record_every=args.record_every,
                       progress=None if args.progress else False)
    q0, q1 = np.degrees(res.q[0]), np.degrees(res.q[-1])
    for j, name in enumerate(arm.dof_names):
        print(f"{name:5s} {q0[j]:8.2f} -> {q1[j]:8.2f} deg")
    tet = res.tet_ns[:-1] if len(res.tet_ns) > 1 else res.tet_ns
    print(f"GHstab max {res.gh_stab.max():.3f}; TET mean {tet.mean() / 1e3:.2f} us, "
          f"max {res.tet_ns.max() / 1e3:.2f} us over {len(res.time)} recorded rows "
          f"(every {args.record_every} of {int(round(args.duration / arm.dt))} steps)")
    if args.out:
        res.save(args.out)
        print(f"saved {args.out}")
    return 0


def cmd_model_build(args) -> int:
    from .model import Model
    from .model_build import build
    res = build(args.file, force=args.force)
    model = Model.load(args.file)  # loads what was just built: the library is usable, not only compiled
    how = "found in the cache" if res.cached else "built"
    print(f"model {model.name}: {model.n_dofs} DOF, {model.n_muscles} muscles, {model.n_elements} elements; "
          f"{how} in {res.seconds:.2f} s")
    print(f"library {res.library}")
    if not res.cached:
        print(f"build log {res.log}")
    return 0


def cmd_model_list(args) -> int:
    import json
    from .model import Model, models
    from .model_build import cache_dir, cache_entry
    for name in models():
        print(repr(Model(name)))
    folder = cache_dir() / "models"
    built = []
    for meta_path in sorted(folder.glob("*/model.json")):
        try:
            meta = json.loads(meta_path.read_text())
            # An entry of another armrt, generator or compiler configuration is never used by this one.
            stale = cache_entry(meta["source_hash"]) != meta_path.parent
            note = "; for another armrt, generator or compiler: unused" if stale else ""
            built.append(f"  {meta['name']}: {meta['model_file']} (sha256 {meta['source_hash'][:12]}..., built "
                         f"{meta['built']} in {meta['seconds']} s{note})")
        except (OSError, ValueError, KeyError):
            continue
    print(f"built on demand, in {folder}:" + ("" if built else " none"))
    if built:
        print("\n".join(built))
    return 0


def cmd_experiments(args) -> int:
    if args.model == "das3":
        # The 11-DOF girdle (armrt/experiments_das3.py): settling, Fig. 1-3 beside das2, scapulohumeral rhythm.
        from .experiments_das3 import run_all as run_das3
        return run_das3(out_dir=args.out, quick=args.quick)
    if args.model != "das2":
        # The participant experiment (armrt/participant.py): Fig. 1 at full stimulation, four variants.
        from .checks import known_model
        from .participant import run_all as run_participant
        return run_participant(model=known_model(args.model), out_dir=args.out, quick=args.quick)
    from .experiments import run_all
    return run_all(out_dir=args.out, quick=args.quick)


class DefaultsOnceFormatter(argparse.ArgumentDefaultsHelpFormatter):
    """ArgumentDefaultsHelpFormatter, but a default is said once and only where it says something: not
    after a help that already names it ("(default: rest posture)"), nor for None or an empty list (the
    help says what happens without the option), nor for a flag (--no-progress is not "True")."""

    def _get_help_string(self, action):
        text = action.help or ""
        if "default" in text or action.nargs == 0 or action.default is None or action.default == []:
            return text
        return super()._get_help_string(action)


def _formatter(prog):
    return DefaultsOnceFormatter(prog, max_help_position=32)


def build_parser() -> argparse.ArgumentParser:
    from ._version import __version__
    from .integrators import DEFAULT_INTEGRATOR, INTEGRATORS
    ap = argparse.ArgumentParser(
        prog="armrt", formatter_class=_formatter,
        description="Real-time musculoskeletal arm simulator. Angles in radians unless an option's "
                    "name says deg; times in seconds.")
    ap.add_argument("--version", action="version", version=f"armrt {__version__}")
    ap.add_argument("--traceback", action="store_true", help="show the Python traceback on errors")
    sub = ap.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("info", help="describe the model: DOFs, ranges, muscles, groups", formatter_class=_formatter)
    p.add_argument("--model", default="das2", help="model name, or a model file (.json, built on demand)")
    p.set_defaults(func=cmd_info)

    p = sub.add_parser("simulate", formatter_class=_formatter,
                       help="run with constant excitations, e.g. elbow_flexors=0.3 rotator_cuff=0.05")
    p.add_argument("excitation", nargs="*", metavar="NAME=VALUE",
                   help="excitation in [0, 1] of an element, muscle or group (armrt or OpenSim name); others 0")
    p.add_argument("--model", default="das2", help="model name, or a model file (.json, built on demand)")
    p.add_argument("--integrator", default=DEFAULT_INTEGRATOR, choices=list(INTEGRATORS),
                   help="integration method (ros2: one linearly implicit step per 1 ms)")
    p.add_argument("--dt", type=float, default=1e-3, help="control step, s")
    p.add_argument("--duration", type=float, default=2.0, help="simulated time, s")
    p.add_argument("--record-every", type=int, default=1, metavar="K",
                   help="keep every K-th step in the result (long runs: a 1 h run at K=1 needs 15 GB)")
    q = p.add_mutually_exclusive_group()
    q.add_argument("--q", type=float, nargs="+", metavar="RAD",
                   help="initial joint angles, one per DOF of the model in its order (das2: GHy GHz GHyy ELx PSy), "
                        "rad (default: rest posture)")
    q.add_argument("--q-deg", type=float, nargs="+", metavar="DEG", help="initial joint angles, deg")
    q.add_argument("--q-mot", metavar="FILE.mot", help="initial joint angles from an OpenSim motion file")
    p.add_argument("--q-mot-time", type=float, default=None, metavar="S",
                   help="time in --q-mot to start from, s (default: its first row)")
    p.add_argument("--settle", action="store_true",
                   help="first relax the arm from the start posture with no excitation (Arm.settle, "
                        "--settle-duration s): das3's rest posture, DAS3's equilibrium.mat, is not its equilibrium, "
                        "and without this the run starts with that transient")
    p.add_argument("--settle-duration", type=float, default=3.0, metavar="S",
                   help="seconds of --settle (>= 0)")
    p.add_argument("--no-progress", dest="progress", action="store_false",
                   help="no progress bar (shown on a terminal for runs longer than 1 s)")
    p.add_argument("-o", "--out", metavar="FILE.npz", help="save the result (.npz)")
    p.set_defaults(func=cmd_simulate)

    p = sub.add_parser("model", help="model files: import a DAS-format .mat, build FILE on demand, list",
                       formatter_class=_formatter)
    msub = p.add_subparsers(dest="model_command", required=True, metavar="MODEL_COMMAND",
                            help="import: a DAS-format .mat to a model file; build: compile a model file into "
                                 "the cache; list: registered and cached models")
    m = msub.add_parser("build", formatter_class=_formatter,
                        help="generate and compile a model file into the user cache (as armrt.Model.load does)")
    m.add_argument("file", metavar="FILE.json", help="model file (docs/model_schema.md)")
    m.add_argument("--force", action="store_true", help="rebuild even if the cache has it")
    m.set_defaults(func=cmd_model_build)
    m = msub.add_parser("list", help="the registered models and the models built into the cache",
                        formatter_class=_formatter)
    m.set_defaults(func=cmd_model_list)

    p = sub.add_parser("experiments", help="the paper's experiments: figures and tables", formatter_class=_formatter)
    p.add_argument("--out", default="results", help="output folder")
    p.add_argument("--quick", action="store_true", help="shorter runs (for tests)")
    p.add_argument("--model", default="das2",
                   help="das2: the paper's experiments; das3: the shoulder girdle's settling, Fig. 1-3 beside das2 and "
                        "the scapulohumeral rhythm; participant_A (or another compiled model): the Fig. 1 "
                        "sequence at full stimulation for participant A's intact, injured, paralysed and FES variants")
    p.set_defaults(func=cmd_experiments)
    from .view import add_cli
    add_cli(sub, _formatter)  # view, animate, export (viser is imported only when `view` runs)
    from .tasks_cli import add_cli as add_task_cli
    add_task_cli(sub, _formatter)  # task: target tasks with the simulated decoder (docs/tasks.md)
    from .display import add_cli as add_display_cli
    add_display_cli(sub, _formatter)  # display: participant display of the armrt-rt state stream (docs/tasks.md)
    from .model_cli import add_cli as add_model_cli
    add_model_cli(sub, _formatter, msub)  # model import (codegen from the source checkout), beside build and list
    return ap


def main(argv=None) -> int:
    ap = build_parser()
    args = ap.parse_args(argv)
    prog = f"armrt {args.command}" + (f" {args.model_command}" if getattr(args, "model_command", None) else "")
    import warnings

    def one_line_warning(message, category, filename, lineno, file=None, line=None):
        print(f"{prog}: warning: {message}", file=sys.stderr)
    warnings.showwarning = one_line_warning
    try:
        return args.func(args)
    except KeyboardInterrupt:
        print(f"{prog}: interrupted", file=sys.stderr)
        return 130
    except CliError as exc:
        if args.traceback:
            raise
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return 2
    except USER_ERRORS as exc:
        if args.traceback:
            raise
        print(f"{prog}: error: {error_text(exc)}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
