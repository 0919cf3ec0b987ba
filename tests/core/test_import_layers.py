"""Imports only point downwards and never loop: the layers of docs/ARCHITECTURE.md, checked on the source.

Every ``import`` of the package (at module level or inside a function) is an edge; so is every
string constant outside a docstring that names a module of the package (``"fuzzynav.x.y:make"``,
the name tables). A module may use its own layer and the layers below it, never one above; the
modules must form no import cycle. A new package must be given a layer in the table below and in
docs/ARCHITECTURE.md.
"""

import ast
import re
from pathlib import Path

SRC = Path(__file__).resolve().parents[2] / "src"
PACKAGE = SRC / "fuzzynav"

# layer number: the higher, the nearer the user. Longest prefix wins (fuzzynav.learn.tasks
# sits above fuzzynav.learn). Keep in step with the table of docs/ARCHITECTURE.md.
LAYERS = {
    "fuzzynav.errors": 0, "fuzzynav.yaml_loader": 0, "fuzzynav.lookup": 0, "fuzzynav.storage": 0,
    "fuzzynav.progress": 0, "fuzzynav.jit": 0, "fuzzynav.threads": 0, "fuzzynav.validation": 0, "fuzzynav.settings": 0,
    "fuzzynav.fuzzy": 1,
    "fuzzynav.kernels": 2,
    "fuzzynav.robot": 3, "fuzzynav.world": 3,
    "fuzzynav.control": 4,
    "fuzzynav.learn": 5,
    "fuzzynav.sim": 6,
    "fuzzynav.viz": 7,
    "fuzzynav.learn.tasks": 8,
    "fuzzynav.experiments": 9, "fuzzynav.bench": 9, "fuzzynav.catalog": 9, "fuzzynav.gym": 9,
    "fuzzynav.tune": 9,
    "fuzzynav.cli": 10, "fuzzynav.__main__": 10, "fuzzynav": 10,
}
# What kernels may use besides their own layer: the fuzzy library (and numpy / numba).
ONLY = {"fuzzynav.kernels": {"fuzzynav.fuzzy", "fuzzynav.kernels", "fuzzynav.errors", "fuzzynav.jit"}}
# Cycles between packages that are tolerated: none.
ALLOWED_CYCLES: set[frozenset] = set()
MODULE_NAME = re.compile(r"\bfuzzynav(?:\.\w+)+")


def module_name(path: Path) -> str:
    parts = list(path.relative_to(SRC).with_suffix("").parts)
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {module_name(p): p for p in PACKAGE.rglob("*.py")}


def layer_of(name: str) -> tuple[str, int]:
    prefixes = [p for p in LAYERS if name == p or name.startswith(p + ".")]
    assert prefixes, f"{name}: no layer; give its package one in docs/ARCHITECTURE.md and in LAYERS"
    best = max(prefixes, key=len)
    return best, LAYERS[best]


def resolve(name: str) -> str | None:
    """The package module that ``name`` (a module, or a module attribute) refers to."""
    while name and name not in MODULES:
        name = name.rpartition(".")[0]
    return name or None


def docstring_nodes(tree) -> set[int]:
    found = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.Module, ast.ClassDef, ast.FunctionDef, ast.AsyncFunctionDef)) and node.body:
            first = node.body[0]
            if isinstance(first, ast.Expr) and isinstance(first.value, ast.Constant):
                found.add(id(first.value))
    return found


def edges(name: str, path: Path) -> set[tuple[str, str]]:
    """(target module, how) of every import and module-naming string of ``name``."""
    tree = ast.parse(path.read_text(), str(path))
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    skip = docstring_nodes(tree)
    found = set()
    for node in ast.walk(tree):
        targets = []
        if isinstance(node, ast.Import):
            targets = [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parent = package.split(".")[: len(package.split(".")) - node.level + 1]
                base = ".".join(parent + ([base] if base else []))
            targets = [f"{base}.{alias.name}" for alias in node.names]
        elif isinstance(node, ast.Constant) and isinstance(node.value, str) and id(node) not in skip:
            targets = [m.group(0) for m in MODULE_NAME.finditer(node.value)]
            # a dotted name no module of the package starts (an entry point group such as
            # "fuzzynav.controllers") names no module
            found |= {(t, "string") for t in filter(None, map(resolve, targets)) if t != "fuzzynav"}
            continue
        found |= {(t, "import") for t in filter(None, map(resolve, targets)) if t.startswith("fuzzynav")}
    found.discard((name, "import"))
    found.discard((name, "string"))
    return found


GRAPH = {name: edges(name, path) for name, path in MODULES.items()}


def test_the_layer_table_of_the_architecture_page_is_this_one():
    page = (SRC.parent / "docs" / "ARCHITECTURE.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| (\d+) \| ([^|]+) \|", page, flags=re.M)
    documented = {name: int(layer) for layer, packages in rows for name in re.findall(r"`([\w.]+)`", packages)}
    assert documented == LAYERS


def test_every_module_has_a_layer():
    for name in MODULES:
        layer_of(name)


def test_no_module_uses_a_layer_above_its_own():
    upward = []
    for name, targets in GRAPH.items():
        home, level = layer_of(name)
        for target, how in targets:
            there, target_level = layer_of(target)
            allowed = ONLY.get(home)
            if target_level > level or (allowed and there not in allowed and not target.startswith(home)):
                upward.append(f"{name} ({home}, layer {level}) -> {target} ({there}, layer {target_level}) by {how}")
    assert not upward, "upward references:\n" + "\n".join(sorted(upward))


def strongly_connected(graph: dict[str, set[str]]) -> list[set[str]]:
    """Tarjan's components of more than one node (or a node with a self-loop)."""
    index, low, stack, on_stack, found = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = set()
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.add(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(component)

    for v in graph:
        if v not in index:
            visit(v)
    return found


def test_no_import_cycles_between_modules():
    imports = {name: {t for t, how in targets if how == "import"} for name, targets in GRAPH.items()}
    cycles = [" <-> ".join(sorted(component)) for component in strongly_connected(imports)]
    assert not cycles, "import cycles:\n" + "\n".join(cycles)


def test_no_import_cycles_between_packages():
    packages = {}
    for name, targets in GRAPH.items():
        home = layer_of(name)[0]
        packages.setdefault(home, set()).update(layer_of(t)[0] for t, how in targets if how == "import")
    for home, targets in packages.items():
        targets.discard(home)
    cycles = [" <-> ".join(sorted(c)) for c in strongly_connected(packages) if frozenset(c) not in ALLOWED_CYCLES]
    assert not cycles, "cycles between packages:\n" + "\n".join(cycles)


def test_the_checker_sees_an_upward_import(tmp_path):
    """The walk finds a lazy import inside a function and a module named in a string."""
    probe = tmp_path / "probe.py"
    probe.write_text('"""Doc naming fuzzynav.cli is fine."""\n\ndef f():\n    from fuzzynav.cli import main\n'
                     '    return "fuzzynav.cli.train:run"\n')
    assert edges("fuzzynav.world.probe", probe) == {("fuzzynav.cli", "import"), ("fuzzynav.cli.train", "string")}
