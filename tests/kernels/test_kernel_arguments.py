"""No compiled kernel takes more than eight arguments: wider ones group theirs into named records
(the NamedTuples of :mod:`fuzzynav.kernels.records` and :mod:`fuzzynav.fuzzy.engine.records`,
read by field name) instead of positions kept by hand. Every ``@jit`` function of the package
(``kernels/``, ``fuzzy/engine/``, ``tune/episodes.py``) is inspected."""

import ast
from pathlib import Path

import fuzzynav

PACKAGE = Path(fuzzynav.__file__).resolve().parent
MOST = 8


def _is_jit(decorator: ast.expr) -> bool:
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    name = target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")
    return "jit" in name


def kernel_widths() -> dict[str, int]:
    """``"folder/module.py:function"`` → number of arguments, of every ``@jit`` function."""
    widths = {}
    for source in sorted(PACKAGE.rglob("*.py")):
        for node in ast.walk(ast.parse(source.read_text(encoding="utf-8"))):
            if isinstance(node, ast.FunctionDef) and any(_is_jit(d) for d in node.decorator_list):
                arguments = node.args
                count = len(arguments.posonlyargs) + len(arguments.args) + len(arguments.kwonlyargs)
                count += (arguments.vararg is not None) + (arguments.kwarg is not None)
                widths[f"{source.relative_to(PACKAGE).as_posix()}:{node.name}"] = count
    return widths


def test_the_kernels_are_found():
    widths = kernel_widths()
    assert len(widths) > 100
    assert widths["kernels/step.py:settle"] == 8 and widths["kernels/layers.py:places_of"] == 2
    assert widths["tune/episodes.py:run_jobs"] == 5 and widths["fuzzy/engine/centroid_rows.py:applies"] == 4


def test_no_kernel_takes_more_than_eight_arguments():
    widths = kernel_widths()
    wide = {name: count for name, count in widths.items() if count > MOST}
    assert wide == {}, f"group these kernels' arguments into named records (a records module): {wide}"
