"""No compiled kernel takes more than eight arguments: wider kernels group theirs into named
records (the NamedTuples of :mod:`fuzzynav.kernels.records`, read by field name) instead of
positions kept by hand. Every ``@jit`` function under ``kernels/`` and ``fuzzy/engine/`` is
inspected; :data:`STILL_WIDE` lists the kernels not converted yet, and may only shrink (an entry
that is no longer wider than eight, or no longer exists, fails the test until it is removed)."""

import ast
from pathlib import Path

import fuzzynav

PACKAGE = Path(fuzzynav.__file__).resolve().parent
FOLDERS = (PACKAGE / "kernels", PACKAGE / "fuzzy" / "engine")
MOST = 8
STILL_WIDE = {  # "module.function": arguments, to convert
    "fuzzy/engine/staged_kernels.py:_integral": 14,
    "fuzzy/engine/staged_kernels.py:weighted_affine": 12,
    "fuzzy/engine/staged_kernels.py:integral": 11,
    "fuzzy/engine/staged_kernels.py:group": 9,
    "fuzzy/engine/sugeno_outputs.py:_group_degree": 12,
    "fuzzy/engine/sugeno_outputs.py:every_row_affine": 10,
    "fuzzy/engine/fused_kernel.py:_fuzzify": 12,
    "fuzzy/engine/centroid_rows.py:max_centroid": 10,
    "fuzzy/engine/centroid_rows.py:_one_unit_to_lane": 9,
    "fuzzy/engine/implication.py:max_four": 9,
}


def _is_jit(decorator: ast.expr) -> bool:
    target = decorator.func if isinstance(decorator, ast.Call) else decorator
    name = target.attr if isinstance(target, ast.Attribute) else getattr(target, "id", "")
    return "jit" in name


def kernel_widths() -> dict[str, int]:
    """``"folder/module.py:function"`` → number of arguments, of every ``@jit`` function."""
    widths = {}
    for folder in FOLDERS:
        for source in sorted(folder.glob("*.py")):
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
    assert widths["kernels/step.py:settle"] == 7 and widths["kernels/layers.py:places_of"] == 2


def test_no_kernel_takes_more_than_eight_arguments():
    widths = kernel_widths()
    wide = {name: count for name, count in widths.items() if count > MOST and name not in STILL_WIDE}
    assert wide == {}, f"group these kernels' arguments into named records (kernels/records.py): {wide}"


def test_the_list_of_kernels_still_wide_only_shrinks():
    widths = kernel_widths()
    stale = {name: widths.get(name) for name in STILL_WIDE if widths.get(name, 0) <= MOST}
    assert stale == {}, f"no longer wide (or gone): remove them from STILL_WIDE: {stale}"
