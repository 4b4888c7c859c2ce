"""Validated model and the SHA-256 of its file -> <name>_model.cc: the parameter tables (DOFs, elements,
muscles, groups, girdle) and the ModelDef kModel that points the engine at them and at the generated
functions.
"""
from __future__ import annotations

import math

from . import cxx
from .signatures import GENERATED_FUNCTIONS, MODEL_DEF_ACCESSOR, SIGNATURES

def _arr(vals) -> str:
    return "{" + ", ".join(cxx.fmt(v) for v in vals) + "}"


def model_source(model: dict, ns: str, digest: str) -> str:
    f = cxx.fmt
    dof_index = {d["name"]: i for i, d in enumerate(model["dofs"])}
    NDOF = len(dof_index)
    els = model["elements"]
    el_index = {e["name"]: i for i, e in enumerate(els)}
    lines = ["#include \"" + ns + ".h\"", "", f"namespace armrt::generated::{ns} {{", "", "namespace {", ""]

    # Every struct is filled by member name (C++20 designated initialisers), never by position.
    lines.append(f"const DofParams kDofs[{NDOF}] = {{")
    for d in model["dofs"]:
        lines.append(f"    {{.name = {cxx.cstr(d['name'])}, .osim_name = {cxx.cstr(d['osim_name'])}, "
                     f".range_min = {f(d['range'][0])}, .range_max = {f(d['range'][1])}, .rest = {f(d['rest'])}}},")
    lines.append("};")
    lines.append("")
    lines.append(f"const ElementParams kElements[{len(els)}] = {{")
    for e in els:
        mask = sum(1 << dof_index[d] for d in e["dofs"])
        lines.append(f"    {{.name = {cxx.cstr(e['name'])}, .muscle = {cxx.cstr(e['muscle'])}, "
                     f".osim_name = {cxx.cstr(e.get('osim_name') or '')}, .fmax = {f(e['fmax'])}, "
                     f".lceopt = {f(e['lceopt'])}, .lslack = {f(e['lslack'])}, .pennopt = {f(e['pennopt'])}, "
                     f".vmax = {f(e['vmax'])}, .tact = {f(e['tact'])}, .tdeact = {f(e['tdeact'])}, "
                     f".peeslack = {f(e['peeslack'])}, .mass = {f(e['mass'])}, "
                     f".crosses_gh = {1 if e['crosses_gh'] else 0}, .dof_mask = {mask}, "
                     f".max_activation = {f(e.get('max_activation', 1.0))}}},")
    lines.append("};")
    lines.append("")

    muscle_elements = {}
    for k, m in enumerate(model["muscles"]):
        idx = [el_index[n] for n in m["elements"]]
        muscle_elements[m["name"]] = idx
        lines.append(f"const int kMuscle{k}[{len(idx)}] = {{{', '.join(map(str, idx))}}};")
    lines.append("")
    lines.append(f"const GroupDef kMuscles[{len(model['muscles'])}] = {{")
    for k, m in enumerate(model["muscles"]):
        lines.append(f"    {{.name = {cxx.cstr(m['name'])}, .num_elements = {len(muscle_elements[m['name']])}, "
                     f".elements = kMuscle{k}}},")
    lines.append("};")
    lines.append("")
    groups = list(model["groups"].items())
    for k, (gname, ms) in enumerate(groups):
        idx = sorted({i for mname in ms for i in muscle_elements[mname]})
        lines.append(f"const int kGroup{k}[{max(len(idx), 1)}] = {{{', '.join(map(str, idx)) or '0'}}};")
    lines.append("")
    if groups:
        lines.append(f"const GroupDef kGroups[{len(groups)}] = {{")
        for k, (gname, ms) in enumerate(groups):
            n = len({i for mname in ms for i in muscle_elements[mname]})
            lines.append(f"    {{.name = {cxx.cstr(gname)}, .num_elements = {n}, .elements = kGroup{k}}},")
        lines.append("};")
        groups_ptr = "kGroups"
    else:
        groups_ptr = "nullptr"
    lines.append("")

    base = model.get("base", "scapula")
    if base == "scapula":
        R, origin = model["scapula"]["rotation_in_thorax"], model["scapula"]["origin_in_thorax"]
    else:
        R, origin = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], [0.0, 0.0, 0.0]
    gt = model["gravity_thorax"]
    g_base = [math.fsum(R[i][k] * gt[i] for i in range(3)) for k in range(3)]   # R^T g
    gl = model["glenoid"]
    pj = model["passive_joint"]
    body_names = [b["name"] for b in model["bodies"]]
    humerus = body_names.index("humerus")
    arm_mass = math.fsum(b["mass"] for b in model["bodies"][humerus:])
    lines.append(f"const char* const kBodyNames[{len(body_names)}] = {{{', '.join(cxx.cstr(b) for b in body_names)}}};")
    if base == "thorax":
        gf = model["girdle_forces"]
        el, ct, co = gf["thorax_ellipsoid"], gf["contact"], gf["conoid"]
        pts = ct["points"]
        lines += [
            f"const char* const kContactPointNames[{len(pts)}] = {{{', '.join(cxx.cstr(p['name']) for p in pts)}}};",
            "",
            "const GirdleDef kGirdle = {",
            f"    .thorax = {{.centre = {_arr(el['centre'])}, .radii = {_arr(el['radii'])}, "
            f".k = {f(ct['stiffness'])}, .eps = {f(ct['eps'])}}},",
            f"    .num_contact_points = {len(pts)},",
            "    .contact_point_names = kContactPointNames,",
            f"    .conoid = {{.origin = {_arr(co['origin']['point'])}, .insertion = {_arr(co['insertion']['point'])}, "
            f".length = {f(co['length'])}, .stiffness = {f(co['stiffness'])}, .eps = {f(co['eps'])}}},",
            f"    .points = &{SIGNATURES['girdle_points'].name},",
            "};",
        ]
    lines.append("")
    lines += [
        "const ModelDef kModel = {",
        f"    .name = {cxx.cstr(model['name'])},",
        f"    .source_hash = {cxx.cstr(digest)},",
        f"    .num_dofs = {NDOF},",
        f"    .num_elements = {len(els)},",
        "    .dofs = kDofs,",
        "    .elements = kElements,",
        f"    .num_muscles = {len(model['muscles'])},",
        "    .muscles = kMuscles,",
        f"    .num_groups = {len(groups)},",
        f"    .groups = {groups_ptr},",
        f"    .base_body = {cxx.cstr(base)},",
        f"    .gravity_base = {_arr(g_base)},",
        f"    .base_rotation_in_thorax = {_arr([x for row in R for x in row])},",
        f"    .base_origin_in_thorax = {_arr(origin)},",
        f"    .num_bodies = {len(body_names)},",
        "    .body_names = kBodyNames,",
        f"    .scapula_body = {body_names.index('scapula') if 'scapula' in body_names else -1},",
        f"    .humerus_body = {humerus},",
        f"    .girdle = {'&kGirdle' if base == 'thorax' else 'nullptr'},",
        f"    .gh_centre = {_arr(gl['gh_centre'])},",
        f"    .glenoid_normal = {_arr(gl['normal'])},",
        f"    .glenoid_major_axis = {_arr(gl['major_axis'])},",
        f"    .glenoid_minor_axis = {_arr(gl['minor_axis'])},",
        f"    .rim_half_angle_major = {f(gl['rim_half_angle_major'])},",
        f"    .rim_half_angle_minor = {f(gl['rim_half_angle_minor'])},",
        f"    .arm_mass = {f(arm_mass)},",
        f"    .passive_stiffness_inside = {f(pj['stiffness_inside'])},",
        f"    .passive_stiffness_outside = {f(pj['stiffness_outside'])},",
        f"    .passive_damping = {f(pj['damping'])},",
    ] + [
        # The ModelDef member of each generated function is named as the function (model_def.h).
        f"    .{fn.name} = &{fn.name}," for fn in GENERATED_FUNCTIONS if not fn.thorax_only
    ] + [
        "};",
        "",
        "}  // namespace",
        "",
        f"const armrt::ModelDef& {MODEL_DEF_ACCESSOR}() {{ return kModel; }}",
        "",
        f"}}  // namespace armrt::generated::{ns}",
        "",
    ]
    return "\n".join(lines)
