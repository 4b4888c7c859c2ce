"""The generated functions' C signatures, written once -> the model header (<name>.h), the extern "C"
entry point of a model built on demand (<name>_entry.cc), and the declarations every emitter defines.

The engine calls these through the ModelDef's function pointers (cpp/include/armrt/model_def.h): the
table's parameter lists must match those pointer types, and each emitter checks that the arrays it
fills are the ones a signature names, so a renamed or added argument is changed here only.
"""
from __future__ import annotations

from dataclasses import dataclass

# The accessor every generated model defines, and the two symbols the engine dlopens a model library by
# (cpp/include/armrt/registry.h kModelAbiSymbol, kModelDefSymbol).
MODEL_DEF_ACCESSOR = "model_def"
ABI_VERSION_SYMBOL = "armrt_model_abi_version"
MODEL_DEF_SYMBOL = "armrt_model_def"


@dataclass(frozen=True)
class Signature:
    name: str
    params: str                 # the C parameter list
    emitter: str                # "dynamics" (dynamics_emitter.py) or "paths" (paths_emitter.py)
    thorax_only: bool = False   # only thorax-based models have it; GirdleDef.points, not ModelDef, holds it
    note: str = ""              # the header's comment on it

    def declaration(self, name: str | None = None) -> str:
        """`void name(params)`; name: another function of the same type (eom_chain.py's stand-alone
        das3 dynamics call girdle_points `points`)."""
        return f"void {name or self.name}({self.params})"

    @property
    def arrays(self) -> list[str]:
        """The parameter names in order: the arrays the emitter reads and writes."""
        return [p.split("*")[-1].strip() for p in self.params.split(",")]

    def check_arrays(self, names) -> None:
        """Refuse an emitter whose input/output arrays are not this signature's parameters (the code would
        compile against the header only by luck)."""
        if list(names) != self.arrays:
            raise ValueError(f"emitter of {self.name}: arrays {list(names)} are not the parameters {self.arrays} "
                             f"of its signature in codegen/signatures.py")


# In the header's order; the ModelDef lists the pointers (all but the thorax-only ones) in the same order.
GENERATED_FUNCTIONS = (
    Signature("mass_matrix", "const double* q, double* M", "dynamics"),
    Signature("bias_force", "const double* q, const double* qd, const double* g_base, double* b", "dynamics"),
    Signature("dynamics", "const double* q, const double* qd, const double* g_base, double* M, double* b", "dynamics"),
    Signature("hand_position", "const double* q, double* p", "dynamics"),
    Signature("hand_jacobian", "const double* q, double* Jv, double* Jw", "dynamics"),
    Signature("arm_momentum_rate", "const double* q, const double* qd, double* A, double* c", "dynamics"),
    Signature("body_poses", "const double* q, double* R, double* p", "dynamics"),
    Signature("muscle_lengths", "const double* q, double* L", "paths"),
    Signature("muscle_paths", "const double* q, double* L, double* moment_arm", "paths"),
    Signature("gh_directions", "const double* q, double* d", "paths"),
    Signature("girdle_points", "const double* q, double* p, double* J", "dynamics", thorax_only=True,
              note="thorax-based models only"),
)
SIGNATURES = {s.name: s for s in GENERATED_FUNCTIONS}


def emitted_by(emitter: str, thorax: bool = False) -> list[str]:
    """The functions an emitter must define for a model (thorax: a thorax-based one), in table order."""
    return [s.name for s in GENERATED_FUNCTIONS if s.emitter == emitter and (thorax or not s.thorax_only)]


def check_emitted(emitter: str, names, thorax: bool = False) -> None:
    """Refuse an emitter that defined other functions than the table gives it."""
    want = emitted_by(emitter, thorax)
    if list(names) != want:
        raise ValueError(f"{emitter} emitter defined {list(names)}; codegen/signatures.py gives it {want}")


def header_source(ns: str) -> str:
    decls = []
    for s in GENERATED_FUNCTIONS:
        decls.append(s.declaration() + ";" + (f"  // {s.note}" if s.note else ""))
    return (f"#pragma once\n\n#include \"armrt/model_def.h\"\n\nnamespace armrt::generated::{ns} {{\n\n"
            f"const armrt::ModelDef& {MODEL_DEF_ACCESSOR}();\n\n" + "\n".join(decls)
            + f"\n\n}}  // namespace armrt::generated::{ns}\n")


def entry_source(ns: str) -> str:
    """The extern "C" entry point of a model built as a shared library on demand (armrt/model_build.py):
    the engine dlopens the library, checks the ModelDef layout version and registers the model
    (cpp/src/registry.cc). Not part of the engine's own build: built-in models are registered by name."""
    return f"""#include "{ns}.h"

extern "C" __attribute__((visibility("default"))) int {ABI_VERSION_SYMBOL}() {{
  return armrt::kModelDefAbiVersion;
}}

extern "C" __attribute__((visibility("default"))) const armrt::ModelDef* {MODEL_DEF_SYMBOL}() {{
  return &armrt::generated::{ns}::{MODEL_DEF_ACCESSOR}();
}}
"""
