"""No compiled kernel takes more than eight arguments: wider ones group theirs into named records
(the NamedTuples of :mod:`fuzzynav.kernels.records` and :mod:`fuzzynav.fuzzy.engine.records`,
read by field name) instead of positions kept by hand. Every compiled function of every module of
the package is inspected: those decorated ``@jit`` (or numba's ``@overload``, a compiled
implementation), and those compiled by a call, ``name = jit(function)``."""

import ast
from pathlib import Path

import fuzzynav

PACKAGE = Path(fuzzynav.__file__).resolve().parent
MOST = 8


def _name(node: ast.expr) -> str:
    target = node.func if isinstance(node, ast.Call) else node
    return target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")


def _is_compiler(node: ast.expr) -> bool:
    return "jit" in _name(node) or _name(node) == "overload"


def _width(function: ast.FunctionDef) -> int:
    arguments = function.args
    count = len(arguments.posonlyargs) + len(arguments.args) + len(arguments.kwonlyargs)
    return count + (arguments.vararg is not None) + (arguments.kwarg is not None)


def _module_file(module: str) -> str:
    """``"fuzzynav.kernels.angles"`` → ``"kernels/angles.py"``."""
    return module.removeprefix("fuzzynav.").replace(".", "/") + ".py"


def compiled_in(tree: ast.Module, module: str) -> set[tuple[str, str]]:
    """(module file, function name) of every function that ``tree`` compiles: those it decorates,
    and those it passes to ``jit(...)`` (defined there or imported from a module of the package)."""
    imported = {alias.asname or alias.name: _module_file(node.module) for node in ast.walk(tree)
                if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("fuzzynav.")
                for alias in node.names}
    found = {(module, node.name) for node in ast.walk(tree)
             if isinstance(node, ast.FunctionDef) and any(_is_compiler(d) for d in node.decorator_list)}
    for node in ast.walk(tree):
        if isinstance(node, ast.Call) and "jit" in _name(node) and node.args and isinstance(node.args[0], ast.Name):
            found.add((imported.get(node.args[0].id, module), node.args[0].id))
    return found


def widths_of(trees: dict[str, ast.Module]) -> dict[str, int]:
    """``"module file:function"`` → number of arguments, of every function the modules ``trees``
    (module file → syntax tree) compile."""
    functions = {(module, node.name): node for module, tree in trees.items() for node in ast.walk(tree)
                 if isinstance(node, ast.FunctionDef)}
    compiled = set().union(*(compiled_in(tree, module) for module, tree in trees.items()))
    # (a name that is no function of the package: the helper jit's own parameter)
    return {f"{module}:{name}": _width(functions[module, name]) for module, name in sorted(compiled)
            if (module, name) in functions}


def kernel_widths() -> dict[str, int]:
    """``"folder/module.py:function"`` → number of arguments, of every compiled function of the package."""
    return widths_of({source.relative_to(PACKAGE).as_posix(): ast.parse(source.read_text(encoding="utf-8"))
                      for source in sorted(PACKAGE.rglob("*.py"))})


def test_the_kernels_are_found():
    widths = kernel_widths()
    assert len(widths) > 100
    assert widths["kernels/step.py:settle"] == 8 and widths["kernels/row_blocks.py:places_of"] == 2
    assert widths["tune/episodes.py:run_jobs"] == 5 and widths["fuzzy/engine/centroid_rows.py:applies"] == 4


def test_overloads_and_functions_compiled_by_a_call_are_found():
    widths = kernel_widths()
    assert widths["fuzzy/engine/centroid_lanes.py:_lane_sums_compiled"] == 4  # @overload(lane_sums)
    # no module of the package compiles a function by a call today; the rule still finds one
    wide = ast.parse("def wide(a, b, c, d, e, f, g, h, i):\n    pass\n")
    probe = ast.parse("from fuzzynav.wide import wide\n\nkernel = numba.njit(wide)\n")
    assert widths_of({"wide.py": wide, "probe.py": probe}) == {"wide.py:wide": 9}


def test_no_kernel_takes_more_than_eight_arguments():
    widths = kernel_widths()
    wide = {name: count for name, count in widths.items() if count > MOST}
    assert wide == {}, f"group these kernels' arguments into named records (a records module): {wide}"
