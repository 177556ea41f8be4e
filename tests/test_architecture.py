"""The package's architecture stays as its folders say.

* No import cycles between modules — every ``import`` counts, also those inside functions (lazy
  imports) and under ``TYPE_CHECKING``: two modules that import each other, directly or around a
  loop, are one concept split in two or a layer reaching back up.
* Layers: data flow one way, description → model → solution → report/plots. A package imports only
  its own or lower layers; the few lazy convenience imports that reach up (a result that draws itself
  with ``.plot()``) are listed in ``REACHING_UP`` with their reason, so a new one is a decision, not
  an accident.
* Every module stays under ``MAX_LINES`` lines.

The graph is read from the source with :mod:`ast` (nothing is imported), over ``src/epicyclic``.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "src" / "epicyclic"
MAX_LINES = 600

#: Sub-packages and top-level modules of ``epicyclic`` by layer, lowest first ("" is the package
#: itself, ``epicyclic/__init__.py``, which re-exports model, results and solver).
LAYERS: tuple[frozenset[str], ...] = tuple(frozenset(layer) for layer in (
    {"errors", "limits", "pickling", "text", "unit_registry", "units"},  # foundations: errors, limits, units, text, pickling
    {"model"},                                        # the description: elements, train, operating point
    {"geometry", "results"},                          # gear geometry of the model; solution value objects
    {"solver", ""},                                   # model → results
    {"analysis", "elastic", "losses", "rating", "transmission", "demo", "dynamics"},  # built on the solver: modes,
    #                                      losses, rating, gears, the elastic set, shifts as they happen
    {"explain", "explain_losses", "io", "plotting", "synthesis", "exchange", "export"},  # files (REXS, CAD), reports,
    #                                                                                      pictures
    {"cli", "web", "notebook"},                       # the front ends (notebook: Jupyter previews)
    {"__main__"},
))

#: Imports that reach up a layer, each lazy (inside the function that needs it) and why it is there.
REACHING_UP = {
    ("epicyclic", "epicyclic.notebook"):
        "import epicyclic registers the Jupyter previews of descriptions in a running IPython",
    ("epicyclic.transmission.transmission", "epicyclic.io"):
        "Transmission.from_file reads a train file (the format lives in io)",
    ("epicyclic.losses.efficiency_map", "epicyclic.plotting.efficiency_map"):
        "EfficiencyMap.plot() draws itself",
    ("epicyclic.losses.efficiency_map", "epicyclic.plotting._common"):
        "EfficiencyMap._repr_html_ and .save() render its figure",
    ("epicyclic.transmission.shift_map", "epicyclic.plotting.shift_map"):
        "ShiftMap.plot() draws itself",
    ("epicyclic.transmission.shift_map", "epicyclic.plotting._common"):
        "ShiftMap._repr_html_ and .save() render its figure",
    ("epicyclic.dynamics.results", "epicyclic.plotting.shift_bench"):
        "ShiftResult.plot() draws the test-bench picture",
    ("epicyclic.losses.breakdown", "epicyclic.plotting.loss_bars"):
        "LossBreakdown.plot() draws itself (stacked bars by source)",
}


def _modules() -> dict[str, tuple[Path, bool]]:
    """Dotted module name → (file, is a package's ``__init__``)."""
    found = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
        is_package = parts[-1] == "__init__"
        found[".".join(parts[:-1] if is_package else parts)] = (path, is_package)
    return found


def _imported(module: str, is_package: bool, node: ast.Import | ast.ImportFrom, known) -> list[str]:
    """The epicyclic modules one import statement names (a package where the name is not a module)."""
    if isinstance(node, ast.Import):
        names = [alias.name for alias in node.names]
    else:
        if node.level:
            base = module.split(".")[: None if is_package else -1]
            base = base[: len(base) - (node.level - 1)]
            origin = ".".join(base + ([node.module] if node.module else []))
        else:
            origin = node.module or ""
        names = [f"{origin}.{alias.name}" if f"{origin}.{alias.name}" in known else origin for alias in node.names]
    out = []
    for name in names:
        while name and name not in known:  # `import epicyclic.io.toml_format as x`, `from x import function`
            name = name.rpartition(".")[0]
        if name.startswith("epicyclic") and name != module:
            out.append(name)
    return out


def import_graph() -> dict[str, set[str]]:
    """Module → the epicyclic modules it imports anywhere in its source (also inside functions)."""
    known = _modules()
    graph = {}
    for module, (path, is_package) in known.items():
        tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
        graph[module] = {target for node in ast.walk(tree) if isinstance(node, (ast.Import, ast.ImportFrom))
                         for target in _imported(module, is_package, node, known)}
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan), each as a sorted list."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in sorted(graph.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def layer_of(module: str) -> int:
    top = module.split(".")[1] if "." in module else ""
    for level, names in enumerate(LAYERS):
        if top in names:
            return level
    raise AssertionError(f"{module}: its package {top!r} has no layer in LAYERS; add it where it belongs")


GRAPH = import_graph()


def test_the_graph_sees_every_kind_of_import():
    # The checks below mean something only if the graph holds relative, absolute and lazy imports.
    assert "epicyclic.solver.solve" in GRAPH["epicyclic.solver"]                 # from .solve import solve
    assert "epicyclic.results.solution" in GRAPH["epicyclic.solver.solve"]       # module level, relative
    assert "epicyclic.io" in GRAPH["epicyclic.transmission.transmission"]        # inside a method
    assert "epicyclic.cli.main" in GRAPH["epicyclic.__main__"]
    assert len(GRAPH) > 100 and all(m.startswith("epicyclic") for m in GRAPH)


def test_cycle_finder_finds_a_loop():
    assert cycles({"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}) == [["a", "b", "c"]]
    assert cycles({"a": {"b"}, "b": set()}) == []


def test_no_two_modules_import_each_other():
    found = cycles(GRAPH)
    assert not found, "import cycles (function-level imports count too): " + "; ".join(
        " ↔ ".join(c) for c in found)


def test_every_package_has_a_layer():
    for module in GRAPH:
        layer_of(module)


def test_layers_import_only_downwards():
    up = sorted((m, t) for m, targets in GRAPH.items() for t in targets if layer_of(t) > layer_of(m))
    unexplained = [f"{m} imports {t}" for m, t in up if (m, t) not in REACHING_UP]
    assert not unexplained, ("a lower layer imports a higher one (model → solver → results → io/plotting/cli/web): "
                             + "; ".join(unexplained))
    stale = set(REACHING_UP) - set(up)
    assert not stale, f"REACHING_UP lists imports that no longer exist: {sorted(stale)}"


@pytest.mark.parametrize("path", sorted(PACKAGE.rglob("*.py")), ids=lambda p: str(p.relative_to(PACKAGE)))
def test_modules_stay_small(path: Path):
    lines = len(path.read_text(encoding="utf-8").splitlines())
    assert lines <= MAX_LINES, f"{path.relative_to(PACKAGE.parent)} has {lines} lines; split it by concept"
