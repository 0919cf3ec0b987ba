"""The thesis' shared numbers are defined once, in :mod:`fuzzynav.fuzzy.constants`: no other module
of the package writes α_max = π/5 or the other steering singletons of Fig IV.7 (π/10, π/20) as
an expression of π, nor their decimal values; everyone imports them."""

import ast
import math
from pathlib import Path

import fuzzynav
from fuzzynav.fuzzy import constants

PACKAGE = Path(fuzzynav.__file__).resolve().parent
HOME = PACKAGE / "fuzzy" / "constants.py"
DIVISORS = (5, 10, 20)  # π/5, π/10, π/20: Fig IV.7's PG, PM, PP


def _is_pi(node: ast.AST) -> bool:
    """``pi``, ``math.pi``, ``np.pi``, the aliases modules give it (``PI``, ``common.PI``), negated or not."""
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
        node = node.operand
    name = node.attr if isinstance(node, ast.Attribute) else node.id if isinstance(node, ast.Name) else ""
    return name.lower() == "pi"


def _definitions(tree: ast.AST) -> list[str]:
    """Source of every π / 5, π / 10, π / 20 and every float literal equal to one of them."""
    found = []
    for node in ast.walk(tree):
        if (isinstance(node, ast.BinOp) and isinstance(node.op, ast.Div) and _is_pi(node.left)
                and isinstance(node.right, ast.Constant) and node.right.value in DIVISORS):
            found.append(ast.unparse(node))
        if isinstance(node, ast.Constant) and isinstance(node.value, float) and any(
                abs(node.value - math.pi / d) < 1e-4 for d in DIVISORS):
            found.append(repr(node.value))
    return found


def test_the_steering_singletons_are_written_once():
    elsewhere = {}
    for source in sorted(PACKAGE.rglob("*.py")):
        if source != HOME:
            found = _definitions(ast.parse(source.read_text(encoding="utf-8")))
            if found:
                elsewhere[str(source.relative_to(PACKAGE))] = found
    assert elsewhere == {}, f"import them from fuzzynav.fuzzy.constants instead: {elsewhere}"
    assert sorted(_definitions(ast.parse(HOME.read_text(encoding="utf-8")))) == [
        "-math.pi / 10", "-math.pi / 20", "math.pi / 10", "math.pi / 20", "math.pi / 5"]


def test_an_alias_of_pi_is_caught():
    for text in ("PI / 5", "-common.PI / 10", "np.pi / 20", "0.6283185"):
        assert _definitions(ast.parse(text)), text
    assert not _definitions(ast.parse("PI / 4 + math.pi / 2"))


def test_the_constants_are_the_figures_values():
    assert constants.ALPHA_MAX == math.pi / 5
    assert constants.STEERING_SINGLETONS == {"NG": -math.pi / 5, "NM": -math.pi / 10, "NP": -math.pi / 20, "Z": 0.0,
                                             "PP": math.pi / 20, "PM": math.pi / 10, "PG": math.pi / 5}
    assert constants.SPEED_SINGLETONS == {"Z": 0.0, "F": 1.0, "M": 1.8, "G": 3.0, "TG": 4.0}
