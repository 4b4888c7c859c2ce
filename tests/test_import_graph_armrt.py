"""The armrt package's own import graph has no cycles (issue 25, A).

The graph is read from the source with `ast`, not by importing: every `import armrt.x` / `from .x import y`
inside python/armrt, at module level and inside functions alike. A lazy import inside a function that only
exists to dodge a circle is still a circle (the two modules still need each other, and the order they are
first imported in decides whether it works), so the test counts function-level edges too. Imports under
`if TYPE_CHECKING:` are left out: they never run.

An import of armrt.a.b also runs armrt/__init__.py and armrt/a/__init__.py first; those implied parent
edges are not counted (a package's __init__ importing its own submodules is how packages work). An
explicit `from . import name` of a value (not a submodule) *is* an edge to the package's __init__.
"""
from __future__ import annotations

import ast
from pathlib import Path

from tests.test_import_graph import cycles as strongly_connected

PACKAGE = Path(__file__).resolve().parents[1] / "python" / "armrt"


def module_names(root: Path = PACKAGE) -> dict[str, Path]:
    """{dotted module name: file} of the package's modules. Compiled extensions (armrt._core, from
    _core.cpp; the .so may be absent in a checkout) are nodes without edges: they import nothing of ours
    and so cannot close a cycle, but `from . import _core` must name them, not the package."""
    out = {}
    for p in sorted([*root.rglob("*.cpp"), *root.rglob("*.so"), *root.rglob("*.pyd")]):
        rel = p.relative_to(root.parent)
        out[".".join([*rel.parts[:-1], p.name.split(".")[0]])] = p
    for p in sorted(root.rglob("*.py")):
        rel = p.relative_to(root.parent).with_suffix("")
        parts = list(rel.parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        out[".".join(parts)] = p
    return out


def _is_type_checking(test: ast.expr) -> bool:
    return (isinstance(test, ast.Name) and test.id == "TYPE_CHECKING") or (
        isinstance(test, ast.Attribute) and test.attr == "TYPE_CHECKING")


def _imports(tree: ast.AST):
    """(node, at module level?) for every Import / ImportFrom outside `if TYPE_CHECKING:` blocks."""
    def walk(node, top: bool):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, ast.If) and _is_type_checking(child.test):
                for c in child.orelse:
                    yield from walk(ast.Module(body=[c], type_ignores=[]), top)
                continue
            if isinstance(child, (ast.Import, ast.ImportFrom)):
                yield child, top
            inner = top and not isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
            yield from walk(child, inner)
    yield from walk(tree, True)


def import_graph(root: Path = PACKAGE) -> dict[str, dict[str, str]]:
    """{module: {imported module: "module" | "function"}} within the package ("module" wins when a module
    imports another both ways)."""
    mods = module_names(root)
    graph: dict[str, dict[str, str]] = {m: {} for m in mods}
    for name, path in mods.items():
        is_pkg = path.name == "__init__.py"
        package = name if is_pkg else name.rpartition(".")[0]
        if path.suffix != ".py":
            continue
        for node, top in _imports(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            targets = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            else:
                if node.level:
                    base = package.split(".")
                    base = base[:len(base) - (node.level - 1)]
                    stem = ".".join(base + ([node.module] if node.module else []))
                else:
                    stem = node.module or ""
                for a in node.names:
                    sub = f"{stem}.{a.name}"
                    # `from pkg import submodule` imports the submodule; `from pkg import value` runs pkg.
                    targets.append(sub if sub in mods else stem)
            for t in targets:
                # `import armrt.x.y` counts as an edge to the deepest of our modules it names.
                while t and t not in mods:
                    t = t.rpartition(".")[0]
                if not t or t == name:
                    continue
                kind = "module" if top else "function"
                if graph[name].get(t) != "module":
                    graph[name][t] = kind
    return graph


def cycles(graph: dict[str, dict[str, str]], kinds=("module", "function")) -> list[list[str]]:
    """The strongly connected components with more than one module, each sorted, using edges of the given
    kinds (the one cycle finder, tests/test_import_graph.py)."""
    return strongly_connected(
        {v: {w for w, kind in edges.items() if kind in kinds and w in graph} for v, edges in graph.items()})


def describe(graph, comp: list[str]) -> str:
    edges = [f"{a} -> {b} ({graph[a][b]}-level)" for a in comp for b in sorted(graph[a]) if b in comp]
    return "{" + ", ".join(comp) + "}: " + "; ".join(edges)


def test_the_checker_finds_module_and_function_level_cycles(tmp_path):
    """The checker itself: a module-level cycle, a cycle closed by a lazy import, `from . import value`
    of the package, and an `if TYPE_CHECKING:` import that is not an edge."""
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "__init__.py").write_text("from .a import A\n__version__ = '1'\n")
    (pkg / "a.py").write_text("from .b import B\nA = 1\n")
    (pkg / "b.py").write_text("from . import a\nB = 2\n")
    (pkg / "c.py").write_text("def f():\n    from .d import D\n")
    (pkg / "d.py").write_text("from .c import f\nfrom typing import TYPE_CHECKING\n"
                              "if TYPE_CHECKING:\n    from .e import E\n")
    (pkg / "e.py").write_text("from .d import D\n")
    (pkg / "f.py").write_text("def v():\n    from . import __version__, _ext\n")
    (pkg / "_ext.cpp").write_text("// a compiled extension\n")
    g = import_graph(pkg)
    assert g["pkg.a"] == {"pkg.b": "module"} and g["pkg.b"] == {"pkg.a": "module"}
    assert g["pkg.c"] == {"pkg.d": "function"} and "pkg.e" not in g["pkg.d"]
    assert g["pkg.f"] == {"pkg": "function", "pkg._ext": "function"} and g["pkg._ext"] == {}
    assert cycles(g, kinds=("module",)) == [["pkg.a", "pkg.b"]]
    assert sorted(cycles(g)) == [["pkg.a", "pkg.b"], ["pkg.c", "pkg.d"]]


def test_no_import_cycle_among_module_level_imports():
    g = import_graph()
    found = cycles(g, kinds=("module",))
    assert not found, "import cycles at module level:\n" + "\n".join(describe(g, c) for c in found)


def test_no_import_cycle_closed_by_a_lazy_import():
    """A function-level import that closes a circle counts: restructure (move the shared piece to a
    lower module) rather than hide the circle inside a function."""
    g = import_graph()
    found = cycles(g)
    assert not found, "import cycles (counting imports inside functions):\n" + "\n".join(
        describe(g, c) for c in found)
