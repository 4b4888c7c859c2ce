"""das3.osim -> the time to generate and to run das3's equations of motion, unrolled recursive algorithms
(codegen/eom_chain.py) against the symbolic route of codegen/eom.py (Kane's method, sympy.cse).

    python -m codegen.importers.das3_eom_timing --out build/das3_eom --symbolic --bench

The numbers of docs/das3.md. Here rather than in eom_chain.py because it reads the chain from the DAS3
release (das3_chain.py), which the generator must not import.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from ..eom_chain import _distal_subchain, bench, generate_source, symbolic_source
from .das3_chain import DAS3_DOFS, das3_bodies, girdle_points


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m codegen.importers.das3_eom_timing", description=__doc__.split("\n\n")[0])
    ap.add_argument("--das3", default=None, help="folder with das3.osim (default ../shared/reference/das3)")
    ap.add_argument("--out", default=None, help="write das3_dynamics.h/.cc here")
    ap.add_argument("--symbolic", action="store_true",
                    help="also time the sympy (Kane + cse) mass matrix of the distal N DOFs, N in --symbolic-dofs")
    ap.add_argument("--symbolic-dofs", type=int, nargs="+", default=[5, 8, 11], help="5, 8 or 11 (whole joints from the hand up)")
    ap.add_argument("--bench", action="store_true",
                    help="with --out: compile the generated dynamics (and the symbolic ones) and time one call (g++ -O2)")
    args = ap.parse_args(argv)

    das3 = Path(args.das3) if args.das3 else Path(__file__).resolve().parents[2] / ".." / "shared" / "reference" / "das3"
    bodies = das3_bodies(das3 / "das3.osim")
    t0 = time.perf_counter()
    header, source, stats = generate_source(DAS3_DOFS, bodies, "thorax", "das3",
                                            points=girdle_points(das3 / "model_struct.mat"))
    t1 = time.perf_counter()
    print(f"recursive (unrolled CRBA + RNEA), 11 DOF: generated in {t1 - t0:.3f} s; operations: {stats}")
    if args.out:
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        (out / "das3_dynamics.h").write_text(header)
        (out / "das3_dynamics.cc").write_text(source)
        print(f"wrote {out}/das3_dynamics.h, .cc")
    if args.symbolic:
        for k in args.symbolic_dofs:
            dofs, sub, base = _distal_subchain(bodies, DAS3_DOFS, k)
            t0 = time.perf_counter()
            text, ntemps = symbolic_source(dofs, sub, base)
            t1 = time.perf_counter()
            print(f"symbolic (Kane + sympy.cse) M and b, {k} DOF ({' '.join(dofs)}): generated in {t1 - t0:.1f} s, "
                  f"{ntemps} temporaries, {text.count(chr(10))} lines", flush=True)
            if args.out:
                (Path(args.out) / f"das3_symbolic_{k}dof.cc").write_text(
                    f"#include \"armrt/fast_math.h\"\nnamespace armrt::generated::das3_symbolic{k} {{\n"
                    + text + "}\n")
    if args.bench and args.out:
        variants = [("recursive", "das3_dynamics.cc", "armrt::generated::das3")]
        if args.symbolic:
            variants += [(f"symbolic {k} DOF", f"das3_symbolic_{k}dof.cc", f"armrt::generated::das3_symbolic{k}")
                         for k in args.symbolic_dofs]
        for label, ns_us in bench(Path(args.out), variants):
            print(f"run cost, {label}: {ns_us:.0f} ns per dynamics(q, qd, g, M, b) call")
    return 0


if __name__ == "__main__":
    sys.exit(main())
