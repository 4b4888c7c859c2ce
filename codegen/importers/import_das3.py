"""Import the DAS3 release into the armrt model file (docs/model_schema.md).

    python -m codegen.import_das3 --das3 ../shared/reference/das3 --out models/das2.json

builds the paper's fixed-scapula, 5-DOF, 102-element model: DOFs and ranges, the fixed SC/AC posture,
the arm's bodies and joints from das3.osim, the Hill parameters of the 102 elements, glenoid geometry,
and muscle paths. `--paths opensim` (the default) fits length and line-of-action polynomials against
OpenSim path geometry (codegen/importers/fit_paths.py; needs `pip install opensim`); `--paths das3` keeps the
DAS3 release polynomials with the girdle angles substituted, which needs no OpenSim but does not
match das3.osim for a fixed girdle (see docs/path_accuracy.md). With all 11 DOFs free (`--free
SCy,SCz,SCx,ACy,ACz,ACx,GHy,GHz,GHyy,ELx,PSy`) it builds the shoulder-girdle model das3
(codegen/importers/import_das3_girdle.py); other DOF sets go to codegen/importers/import_reduced.py.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

import numpy as np

from . import das3_source as src
from .das3_source import ModelInputError
from ..polynomial import substitute
from .glenoid import glenoid_geometry
from .model_defaults import GRAVITY_THORAX, GROUPS, PASSIVE_JOINT, SCHEMA_VERSION, check_against_readme, sha256

ARM_BODIES = [("humerus", "humerus_r"), ("ulna", "ulna_r"), ("radius", "radius_r"), ("hand", "hand_r")]
OSIM_DOF = {"SCy": "SC_y", "SCz": "SC_z", "SCx": "SC_x", "ACy": "AC_y", "ACz": "AC_z", "ACx": "AC_x",
            "GHy": "GH_y", "GHz": "GH_z", "GHyy": "GH_yy", "ELx": "EL_x", "PSy": "PS_y"}


def reduce_length_poly(element: src.Das3Element, girdle: dict[str, float]) -> dict:
    """The DAS3 length polynomial with the fixed girdle angles substituted and equal monomials merged."""
    fixed = {j: girdle[d] for j, d in enumerate(element.dof_names) if d in girdle}
    kept, exps, coefs = substitute(element.lparams, element.lcoefs, fixed)
    return {"dofs": [element.dof_names[j] for j in kept], "exponents": exps, "coefs": coefs}


def reduce_direction_poly(element: src.Das3Element, girdle: dict[str, float]) -> dict | None:
    if element.direction is None:
        return None
    fixed = {j: girdle[d] for j, d in enumerate(element.dof_names) if d in girdle}
    out = {"dofs": [d for d in element.dof_names if d not in girdle]}
    for axis, (e, c) in element.direction.items():
        _, exps, coefs = substitute(e, c, fixed)
        out[axis] = {"exponents": exps, "coefs": coefs}
    return out


def build_model(das3_dir: Path, paths: str = "opensim", cache_dir: Path | None = None, seed: int = 0) -> dict:
    das3_dir = Path(das3_dir)
    files = {k: das3_dir / k for k in ["model_struct.mat", "equilibrium.mat", "das3.osim"]}
    for f in files.values():
        if not f.exists():
            raise ModelInputError(f"missing input file {f}")
    struct = src.read_model_struct(files["model_struct.mat"])
    posture = src.read_equilibrium(files["equilibrium.mat"])
    osim = src.read_osim(files["das3.osim"])
    girdle = {d: posture[d] for d in src.GIRDLE_DOFS}
    coords = {OSIM_DOF[d]: v for d, v in posture.items()}

    for needed in ["scapula_r", "humerus_r", "ulna_r", "radius_r", "hand_r"]:
        if needed not in osim:
            raise ModelInputError(f"das3.osim: missing Body '{needed}'")
    R_scap, p_scap = src.body_in_frame(osim, "scapula_r", "ground", coords)

    # Arm bodies. The GH joint is three massless CustomJoints in series (gh1..gh3), collapsed into one
    # joint of three body-fixed rotations at gh1's location in the scapula.
    bodies, dof_axes = {}, {}
    for name, osim_name in ARM_BODIES:
        b = osim[osim_name]
        if name == "humerus":
            chain, jname, parent = ["humerus_1", "humerus_2", "humerus_r"], "gh", "scapula"
        else:
            chain, jname = [osim_name], b.joint.name
            parent = {"ulna": "humerus", "radius": "ulna", "hand": "radius"}[name]
        axes, dofs = [], []
        for link in chain:
            j = osim[link].joint
            for axis, coord, slope, const in j.rotations:
                if coord is None:
                    if const != 0.0:
                        raise ModelInputError(f"das3.osim: joint '{j.name}' has a constant rotation")
                    continue
                if slope != 1.0:
                    raise ModelInputError(f"das3.osim: joint '{j.name}' coordinate {coord} has slope {slope}")
                dof = {v: k for k, v in OSIM_DOF.items()}[coord]
                axes.append(axis.tolist())
                dofs.append(dof)
                dof_axes[dof] = axis
            if link != chain[0] and np.any(j.location_in_parent != 0):
                raise ModelInputError(f"das3.osim: joint '{j.name}' is offset from its parent")
        jtype = {3: "gimbal_yzy", 1: "pin", 0: "weld"}[len(dofs)]
        bodies[name] = {
            "name": name, "osim_name": osim_name, "parent": parent,
            "mass": b.mass, "com": b.com.tolist(), "inertia": b.inertia.tolist(),
            "joint": {"name": jname, "type": jtype,
                      "location_in_parent": osim[chain[0]].joint.location_in_parent.tolist(),
                      "axes": axes, "dofs": dofs},
        }
    if [d for b in bodies.values() for d in b["joint"]["dofs"]] != src.ARM_DOFS:
        raise ModelInputError("das3.osim: the arm joints do not carry GHy, GHz, GHyy, ELx, PSy in order")
    check_against_readme(bodies, dof_axes)

    arm = [e for e in struct.elements if src.muscle_of(e.name) in src.PAPER_MUSCLES]
    gh_centre = np.array(bodies["humerus"]["joint"]["location_in_parent"])
    import scipy.io as sio
    ms = sio.loadmat(files["model_struct.mat"], squeeze_me=True, struct_as_record=False)["model"]
    glenoid = glenoid_geometry(gh_centre)

    if paths == "opensim":
        from .fit_paths import fit_paths  # needs OpenSim
        fits = fit_paths(str(files["das3.osim"]), {OSIM_DOF[d]: v for d, v in girdle.items()},
                         [{"name": e.name, "osim_name": e.osim_name} for e in arm],
                         str(cache_dir or Path("build")), seed=seed)
        rom = {d: [float(v) for v in fits["rom"][d]] for d in src.ARM_DOFS}
        # The model file's words as models/das2.json records them (its bytes are hashed into cpp/generated):
        # the module has moved to codegen/importers/ since.
        path_note = "length and line-of-action polynomials fitted against das3.osim (codegen/importers/fit_paths.py)"
    elif paths == "das3":
        fits = None
        rom = {d: [float(v) for v in struct.dof_ranges[d]] for d in src.ARM_DOFS}
        path_note = "DAS3 release polynomials with the fixed girdle angles substituted (not refitted)"
    else:
        raise ValueError(f"paths must be 'opensim' or 'das3', got {paths!r}")

    elements = []
    for e in arm:
        p = e.params
        entry = {
            "name": e.name, "osim_name": e.osim_name, "muscle": src.muscle_of(e.name),
            "fmax": p["fmax"], "lceopt": p["lceopt"], "lslack": p["lslack"], "pennopt": p["pennopt"],
            "vmax": p["vmax"], "tact": p["tact"], "tdeact": p["tdeact"], "peeslack": p["PEEslack"],
            "mass": p["mass"],
        }
        if fits is None:
            length = reduce_length_poly(e, girdle)
            entry.update({"dofs": [d for d in src.ARM_DOFS if d in length["dofs"]], "crosses_gh": e.crosses_gh,
                          "length_poly": length, "gh_direction": reduce_direction_poly(e, girdle),
                          "fit": None})
        else:
            f = fits["elements"][e.name]
            entry.update({"dofs": list(f["dofs"]), "crosses_gh": bool(f["crosses_gh"]),
                          "length_poly": f["length_poly"], "gh_direction": f["gh_direction"], "fit": f["fit"]})
        elements.append(entry)

    muscles = []
    for m in src.PAPER_MUSCLES:
        members = [e for e in elements if e["muscle"] == m]
        dofs = {d for e in members for d in e["dofs"]}
        crosses = [j for j, ds in [("GH", {"GHy", "GHz", "GHyy"}), ("HU", {"ELx"}), ("RU", {"PSy"})] if dofs & ds]
        muscles.append({"name": m, "elements": [e["name"] for e in members], "crosses": crosses})

    return {
        "schema": "armrt-model",
        "schema_version": SCHEMA_VERSION,
        "name": "das2",
        "description": ("The paper's real-time arm model: fixed scapula, 5 DOF (GH 3, elbow flexion, forearm "
                        "pronation), 22 muscles in 102 Hill-type elements, from the DAS3 release. Ranges of "
                        "motion: the paper's Table I (Gunal et al.) was lost; see dofs[].range and "
                        "docs/path_accuracy.md for how the fixed-scapula range was chosen inside the DAS3 "
                        "ranges. Muscle paths: " + path_note + "."),
        "source": {"importer": "python -m codegen.import_das3 --paths " + paths,
                   "files": {k: sha256(f) for k, f in files.items()}},
        "gravity_thorax": GRAVITY_THORAX,
        "dofs": [{"name": d, "osim_name": OSIM_DOF[d], "range": rom[d],
                  "das3_range": [float(v) for v in struct.dof_ranges[d]], "rest": posture[d]}
                 for d in src.ARM_DOFS],
        "girdle": {"dofs": [{"name": d, "osim_name": OSIM_DOF[d], "angle": v} for d, v in girdle.items()],
                   "source": "equilibrium.mat x[0:6]"},
        "scapula": {"rotation_in_thorax": R_scap.tolist(), "origin_in_thorax": p_scap.tolist()},
        "bodies": [bodies[n] for n, _ in ARM_BODIES],
        "hand_point": {"body": "hand", "point": bodies["hand"]["com"]},
        "glenoid": glenoid,
        "passive_joint": PASSIVE_JOINT,
        "muscles": muscles,
        "groups": GROUPS,
        "elements": elements,
    }


def write_model(model: dict, path: Path):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(model, indent=1, sort_keys=False) + "\n")


DEFAULT_DAS3 = Path(__file__).resolve().parents[2] / ".." / "shared" / "reference" / "das3"


def is_das2_call(mat: Path, free: list[str], posture: dict) -> bool:
    """The paper's model: the DAS3 release (das3.osim and equilibrium.mat beside model_struct.mat) with
    the five arm DOFs free and the default posture. It keeps its OpenSim-based path (build_model)."""
    return (mat.name == "model_struct.mat" and (mat.parent / "das3.osim").exists()
            and (mat.parent / "equilibrium.mat").exists() and sorted(free) == sorted(src.ARM_DOFS) and not posture)


def is_das3_call(mat: Path, free: list[str], posture: dict) -> bool:
    """The 11-DOF shoulder-girdle model: the DAS3 release with all 11 DOFs free (thorax fixed) and the
    default posture. Built by import_das3_girdle.build_das3_model from models/das3_paths.json."""
    return (mat.name == "model_struct.mat" and (mat.parent / "das3.osim").exists()
            and (mat.parent / "equilibrium.mat").exists() and sorted(free) == sorted(src.ALL_DOFS) and not posture)


def import_any(mat: Path, free: list[str], out: Path, name: str | None = None, posture: dict | None = None,
               equilibrium: Path | None = None, paths: str | None = None, cache_dir: Path | None = None,
               seed: int = 0, command: str = "") -> dict:
    """One entry for every DAS-format file (`armrt model import` and `python -m codegen.import_das3`):
    das2 when is_das2_call(), das3 when is_das3_call(), else import_reduced.build_reduced_model. Writes
    `out`; returns the model."""
    from .import_reduced import build_reduced_model
    mat = Path(mat)
    if not mat.exists():
        raise ModelInputError(f"missing input file {mat}")
    if is_das3_call(mat, free, posture or {}):
        from .import_das3_girdle import build_das3_model
        if paths is not None:
            raise ModelInputError(f"--paths {paths}: das3 takes its paths, already fitted against das3.osim, from "
                                  "models/das3_paths.json (python -m codegen.importers.das3_fit refits them)")
        if equilibrium is not None and Path(equilibrium).resolve() != (mat.parent / "equilibrium.mat").resolve():
            raise ModelInputError("--equilibrium: das3 rests at the equilibrium.mat beside model_struct.mat")
        model = build_das3_model(mat.parent)
        if name is not None and name != model["name"]:
            raise ModelInputError(f"--name: the DAS3 release with all 11 DOFs free is das3 (got {name!r})")
    elif is_das2_call(mat, free, posture or {}):
        model = build_model(mat.parent, paths=paths or "opensim", cache_dir=cache_dir, seed=seed)
        if name is not None and name != model["name"]:
            raise ModelInputError(f"--name: the DAS3 release with the five arm DOFs free is das2 (got {name!r})")
    else:
        if paths == "opensim":
            raise ModelInputError("--paths opensim: OpenSim-fitted paths exist for das2 only (the DAS3 release with "
                                  "GHy,GHz,GHyy,ELx,PSy free); other imports use the file's own polynomials")
        if equilibrium is None:
            # Beside MAT, then the DAS3 release's in the reference layout (<reference>/participant_A/ beside
            # <reference>/das3/), found from MAT so that an installed importer, far from the checkout's
            # ../shared, picks the same file as the checkout's; then the checkout's default.
            for cand in (mat.parent / "equilibrium.mat", mat.parent.parent / "das3" / "equilibrium.mat",
                         DEFAULT_DAS3 / "equilibrium.mat"):
                if cand.exists():
                    equilibrium = cand
                    break
        default_name = mat.stem.replace("model_struct", "model").strip("_") or "model"
        model = build_reduced_model(mat, free, name or default_name, posture=posture,
                                    equilibrium_path=equilibrium, command=command)
    write_model(model, out)
    return model


def main(argv=None, prog="python -m codegen.import_das3", raise_errors: bool = False):
    """The command; 2 after printing `PROG: error: ...` for a bad request (ModelInputError), or with
    raise_errors that error raised (armrt model import reports it, and --traceback shows it, as for any
    armrt command)."""
    ap = argparse.ArgumentParser(prog=prog, description=__doc__.split("\n\n")[0] + " Any DAS-format "
                                 "model_struct*.mat with chosen free DOFs (docs/model_schema.md).")
    ap.add_argument("mat", nargs="?", type=Path, help="DAS-format model_struct*.mat (default: --das3/model_struct.mat)")
    ap.add_argument("--das3", type=Path, default=DEFAULT_DAS3,
                    help="folder with model_struct.mat, equilibrium.mat, das3.osim (used when MAT is not given)")
    ap.add_argument("--free", default=",".join(src.ARM_DOFS),
                    help="comma-separated free DOFs (default: the paper's five, GHy,GHz,GHyy,ELx,PSy)")
    ap.add_argument("--posture", action="append", default=[], metavar="NAME=RAD[,...]",
                    help="fixed angles in radians overriding the default posture (repeatable)")
    ap.add_argument("--posture-deg", action="append", default=[], metavar="NAME=DEG[,...]",
                    help="the same in degrees")
    ap.add_argument("--equilibrium", type=Path, default=None,
                    help="equilibrium.mat for the default posture (default: beside MAT, else ../das3/ beside MAT's "
                         "folder, else the DAS3 release beside the checkout)")
    ap.add_argument("--name", default=None, help="model name (a C identifier; default das2 for das2, else from MAT)")
    ap.add_argument("-o", "--out", type=Path, default=None,
                    help="model file to write (default: models/das3.json for all 11 DOFs, else models/das2.json)")
    ap.add_argument("--paths", choices=["opensim", "das3"], default=None,
                    help="das2 only: fit paths against OpenSim (default) or keep the DAS3 polynomials")
    ap.add_argument("--cache", type=Path, default=Path("build"), help="where OpenSim samples are cached")
    ap.add_argument("--seed", type=int, default=0)
    args = ap.parse_args(argv)
    from .import_reduced import posture_angles
    mat = args.mat if args.mat is not None else args.das3 / "model_struct.mat"
    try:
        posture = posture_angles(args.posture)
        posture.update(posture_angles(args.posture_deg, degrees=True))
        free = [f.strip() for f in args.free.split(",") if f.strip()]
        if args.out is None:
            args.out = Path("models/das3.json" if sorted(free) == sorted(src.ALL_DOFS) else "models/das2.json")
        # The same command whichever entry ran it (armrt model import calls this main), so both write
        # the same bytes.
        cmd = f"python -m codegen.import_das3 {mat.name} --free {','.join(free)}" + "".join(f" --posture {p}" for p in args.posture) \
            + "".join(f" --posture-deg {p}" for p in args.posture_deg) + (f" --name {args.name}" if args.name else "")
        model = import_any(mat, free, args.out, name=args.name, posture=posture, equilibrium=args.equilibrium,
                           paths=args.paths, cache_dir=args.cache, seed=args.seed, command=cmd)
    except ModelInputError as exc:
        if raise_errors:
            raise
        print(f"{prog}: error: {exc}", file=sys.stderr)
        return 2
    dropped = model["source"].get("dropped_elements", [])
    print(f"wrote {args.out}: {model['name']}, {len(model['dofs'])} DOFs, {len(model['elements'])} elements, "
          f"{len(model['muscles'])} muscles" + (f"; dropped {len(dropped)} elements crossing no free DOF: "
                                                  f"{', '.join(dropped)}" if dropped else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())

