"""A package directory -> its module import graph (ast, no imports run) -> the circles in it; and the
generator (codegen/) apart from the importers (codegen/importers/).

Every import counts, a function-level one too: a lazy import hides a circle from Python's import
machinery, not from the design (codegen/import_das3* called each other so before issue 25).
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
# Modules of codegen/ that may import the importers: the CLI name the model files record as their importer.
IMPORTER_SHIMS = {"codegen.import_das3"}


def modules_of(package_dir: Path, package: str) -> dict[str, Path]:
    """Dotted module name -> file, for every .py under package_dir (subpackages included)."""
    if not (package_dir / "__init__.py").is_file():
        raise FileNotFoundError(f"{package_dir} is not a package (no __init__.py)")
    out = {}
    for path in sorted(package_dir.rglob("*.py")):
        parts = list(path.relative_to(package_dir).with_suffix("").parts)
        if "__pycache__" in parts:
            continue
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join([package] + parts)] = path
    return out


def _extension_module(init: Path | None, name: str) -> bool:
    """name is a submodule of the package whose __init__.py is init but not Python source (armrt._core:
    _core.cpp in a checkout, _core.*.so installed), so `from package import name` does not import the
    package's own names."""
    if init is None or init.name != "__init__.py":
        return False
    return any(p.suffix != ".py" for p in init.parent.glob(f"{name}.*"))


def import_graph(package_dir: Path, package: str) -> dict[str, set[str]]:
    """Module -> the modules of the same package it imports anywhere in its body. `from X import name`
    counts as importing X.name when that is a module, else X."""
    mods = modules_of(package_dir, package)
    graph: dict[str, set[str]] = {m: set() for m in mods}
    for mod, path in mods.items():
        is_pkg = path.name == "__init__.py"
        tree = ast.parse(path.read_text(), filename=str(path))
        for node in ast.walk(tree):
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = mod.split(".") if is_pkg else mod.split(".")[:-1]
                    if node.level - 1 > len(base) - 1:
                        raise ValueError(f"{path}:{node.lineno}: relative import beyond the package {package}")
                    base = base[:len(base) - (node.level - 1)]
                    source = ".".join(base + ([node.module] if node.module else []))
                else:
                    source = node.module or ""
                for a in node.names:
                    sub = f"{source}.{a.name}"
                    if sub in mods:
                        targets.append(sub)
                    elif not _extension_module(mods.get(source), a.name):
                        targets.append(source)
            for t in targets:
                # `import codegen.importers.x` names x; an import of an outside module is not an edge.
                while t and t not in mods:
                    t = t.rpartition(".")[0] if t.startswith(package + ".") else ""
                if t and t != mod:
                    graph[mod].add(t)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iterative), each sorted; sorted."""
    index, low, on_stack, stack, out = {}, {}, set(), [], []
    counter = 0
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = counter
        counter += 1
        stack.append(start)
        on_stack.add(start)
        while work:
            v, it = work[-1]
            for w in it:
                if w not in index:
                    index[w] = low[w] = counter
                    counter += 1
                    stack.append(w)
                    on_stack.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                    break
                if w in on_stack:
                    low[v] = min(low[v], index[w])
            else:
                work.pop()
                if work:
                    low[work[-1][0]] = min(low[work[-1][0]], low[v])
                if low[v] == index[v]:
                    comp = []
                    while True:
                        w = stack.pop()
                        on_stack.discard(w)
                        comp.append(w)
                        if w == v:
                            break
                    if len(comp) > 1:
                        out.append(sorted(comp))
    return sorted(out)


def _describe(found) -> str:
    return "; ".join(" <-> ".join(c) for c in found)


def test_the_checker_finds_a_lazy_circle_and_passes_a_tree(tmp_path):
    pkg = tmp_path / "pkg"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "a.py").write_text("import os\nfrom . import b\n")
    (pkg / "b.py").write_text("def f():\n    from .sub.c import g\n")
    (pkg / "sub" / "c.py").write_text("def g():\n    from ..a import x\n")
    (pkg / "sub" / "d.py").write_text("import pkg.b\nfrom pkg import a, _ext, name_in_init\n")
    (pkg / "_ext.cpp").write_text("")
    graph = import_graph(pkg, "pkg")
    assert graph["pkg.sub.d"] == {"pkg.a", "pkg.b", "pkg"}
    assert cycles(graph) == [["pkg.a", "pkg.b", "pkg.sub.c"]]
    (pkg / "sub" / "c.py").write_text("def g():\n    import json\n")
    assert cycles(import_graph(pkg, "pkg")) == []


@pytest.mark.parametrize("package_dir, package", [
    pytest.param(ROOT / "codegen", "codegen", id="codegen"),
    pytest.param(ROOT / "python" / "armrt", "armrt", id="armrt"),
])
def test_no_import_circles(package_dir, package):
    found = cycles(import_graph(package_dir, package))
    assert not found, f"import circles in {package_dir.relative_to(ROOT)}: {_describe(found)}"


def test_the_generator_imports_nothing_from_the_importers():
    """codegen/ minus codegen/importers/ turns a model file into C++ and ships in every install; the
    importers (DAS3 release, OpenSim, fitting) depend on it, never the reverse."""
    graph = import_graph(ROOT / "codegen", "codegen")
    generator = [m for m in graph if not m.startswith("codegen.importers") and m not in IMPORTER_SHIMS]
    assert "codegen.generate" in generator and "codegen.importers.import_das3" in graph
    for mod in generator:
        seen, todo = set(), [mod]
        while todo:
            for t in graph[todo.pop()] - seen:
                seen.add(t)
                todo.append(t)
        bad = sorted(t for t in seen if t.startswith("codegen.importers"))
        assert not bad, f"{mod} imports the importers {bad} (directly or through another module)"
