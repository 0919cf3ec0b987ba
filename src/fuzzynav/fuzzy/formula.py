"""fuzzylite's ``Function`` term: a formula in ``x`` and the engine's variables, parsed once, vectorised.

Grammar of fuzzylite 8 (operators by decreasing precedence): ``!`` ``~`` (not, negate); ``^`` ``**``
(power, right-associative) and unary ``-`` ``+``; ``*`` ``/`` ``%``; ``+`` ``-``; ``and``; ``or``.
Functions: gt ge eq neq le lt min max acos asin atan ceil cos cosh exp abs fabs floor log log10
round sin sinh sqrt tan tanh log1p acosh asinh atanh pow atan2 fmod, and the constant ``pi``.
The formula is parsed by a small precedence parser into a tree of NumPy calls: nothing is ever
passed to Python's ``eval``.
"""

from __future__ import annotations

import math
import re

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.membership import MembershipFunction
from fuzzynav.validation import MAX_DEPTH

_UNARY = {"acos": np.arccos, "asin": np.arcsin, "atan": np.arctan, "ceil": np.ceil, "cos": np.cos,
          "cosh": np.cosh, "exp": np.exp, "abs": np.fabs, "fabs": np.fabs, "floor": np.floor, "log": np.log,
          "log10": np.log10, "round": np.round, "sin": np.sin, "sinh": np.sinh, "sqrt": np.sqrt, "tan": np.tan,
          "tanh": np.tanh, "log1p": np.log1p, "acosh": np.arccosh, "asinh": np.arcsinh, "atanh": np.arctanh}
_BINARY = {"gt": np.greater, "ge": np.greater_equal, "eq": np.equal, "neq": np.not_equal, "le": np.less_equal,
           "lt": np.less, "min": np.minimum, "max": np.maximum, "pow": np.float_power, "atan2": np.arctan2,
           "fmod": np.fmod}
_INFIX = {  # operator: (precedence, function); higher binds tighter
    "or": (1, np.logical_or), "and": (2, np.logical_and), "+": (3, np.add), "-": (3, np.subtract),
    "*": (4, np.multiply), "/": (4, np.divide), "%": (4, np.fmod), "^": (5, np.float_power),
    "**": (5, np.float_power),
}
_TOKEN = re.compile(r"\s*(\d+\.?\d*(?:[eE][-+]?\d+)?|\.\d+(?:[eE][-+]?\d+)?|\*\*|[A-Za-z_][A-Za-z0-9_.]*|[-+*/%^(),!~])",
                    re.ASCII)  # (a digit of another script, ٢, was read as one)
_DECIMAL = re.compile(r"\s*[+-]?(?:(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|inf|infinity|nan)\s*", re.IGNORECASE | re.ASCII)


def decimal(text: str) -> float:
    """A number written in ASCII decimal (Python's ``float`` also reads ``1_000`` and other
    scripts' digits, ``٣``); ValueError otherwise, or when a finite literal overflows to infinity.
    How the command line reads a number, and the ``.fll`` reader (fuzzylite refuses the others)."""
    if not isinstance(text, str) or not _DECIMAL.fullmatch(text):
        raise ValueError(f"{text!r} is not a number")
    value = float(text)
    if math.isinf(value) and "inf" not in text.lower():
        raise ValueError(f"{text.strip()} is too large for a float")
    return value


def _tokens(text: str) -> list[str]:
    out, pos = [], 0
    text = text.strip()
    while pos < len(text):
        match = _TOKEN.match(text, pos)
        if not match:
            raise ValueError(f"unexpected character {text[pos]!r} at position {pos} of {text!r}")
        out.append(match.group(1))
        pos = match.end()
    return out


class _Parser:
    def __init__(self, text: str):
        self.text, self.tokens, self.i, self.depth = text, _tokens(text), 0, 0

    def peek(self):
        return self.tokens[self.i] if self.i < len(self.tokens) else None

    def take(self, expected=None):
        token = self.peek()
        if token is None or (expected and token != expected):
            raise ValueError(f"expected {expected or 'more'} in {self.text!r}")
        self.i += 1
        return token

    def parse(self):
        tree = self.binary(1)
        if self.peek() is not None:
            raise ValueError(f"unexpected {self.peek()!r} in {self.text!r}")
        if _depth(tree) > MAX_DEPTH:  # a long chain (1+1+...+1) nests as deep as brackets would
            raise ValueError(f"formula nested deeper than {MAX_DEPTH} levels (split a long chain with brackets)")
        return tree

    def binary(self, level: int):
        self.depth += 1  # every nesting (brackets, signs, calls, ^ chains) passes here
        if self.depth > MAX_DEPTH:
            raise ValueError(f"formula nested deeper than {MAX_DEPTH} levels")
        left = self.unary()
        while (op := self.peek()) in _INFIX and _INFIX[op][0] >= level:
            self.take()
            precedence, fn = _INFIX[op]
            right = self.binary(precedence if precedence == 5 else precedence + 1)  # ^ is right-associative
            left = ("call", fn, [left, right])
        self.depth -= 1
        return left

    def unary(self):
        token = self.peek()
        if token in ("-", "+", "~", "!"):
            self.take()
            operand = self.binary(5)
            fn = {"-": np.negative, "~": np.negative, "+": np.positive, "!": np.logical_not}[token]
            return ("call", fn, [operand])
        return self.atom()

    def atom(self):
        token = self.take()
        if token == "(":
            tree = self.binary(1)
            self.take(")")
            return tree
        if token[0].isdigit() or token[0] == ".":
            return ("num", float(token))
        if token == "pi":
            return ("num", float(np.pi))
        if token in _UNARY or token in _BINARY:
            self.take("(")
            args = [self.binary(1)]
            while self.peek() == ",":
                self.take()
                args.append(self.binary(1))
            self.take(")")
            arity = 1 if token in _UNARY else 2
            if len(args) != arity:
                raise ValueError(f"{token} takes {arity} argument(s), got {len(args)} in {self.text!r}")
            return ("call", _UNARY.get(token) or _BINARY[token], args)
        if token[0].isalpha() or token[0] == "_":
            return ("var", token)
        raise ValueError(f"unexpected {token!r} in {self.text!r}")


def _depth(tree) -> int:
    """Nesting depth of a parsed formula, found without recursion."""
    deepest, stack = 0, [(tree, 1)]
    while stack:
        node, depth = stack.pop()
        deepest = max(deepest, depth)
        if node[0] == "call":
            stack.extend((argument, depth + 1) for argument in node[2])
    return deepest


def _run(tree, values: dict):
    kind = tree[0]
    if kind == "num":
        return tree[1]
    if kind == "var":
        return values[tree[1]]
    args = [_run(a, values) for a in tree[2]]
    with np.errstate(all="ignore"):
        return np.asarray(tree[1](*args), dtype=float)


def _names(tree) -> set[str]:
    if tree[0] == "var":
        return {tree[1]}
    if tree[0] == "call":
        return set().union(*(_names(a) for a in tree[2]))
    return set()


class Function(MembershipFunction):
    """μ(x) = formula(x, engine variables) — fuzzylite's ``Function`` term."""

    kind = "function"

    def __init__(self, formula: str):
        self.formula = str(formula).strip()
        self.tree = _Parser(self.formula).parse()
        self.reads = _names(self.tree)
        self.variables = self.reads - {"x"}

    def params(self) -> tuple:
        return (self.formula,)

    def __call__(self, x, variables: dict | None = None):
        values = dict(variables or {})
        values["x"] = np.asarray(x, dtype=float)
        missing = self.variables - values.keys()
        if missing:
            raise ValueError(f"formula {self.formula!r} uses unknown variable(s) {', '.join(sorted(missing))}")
        result = np.broadcast_to(_run(self.tree, values), np.shape(values["x"])).astype(float)
        if np.isinf(result).any():
            self._refuse_infinite(result, values)
        return result

    def _refuse_infinite(self, result: np.ndarray, values: dict) -> None:
        """An :class:`InputError` where the formula gives ±inf from finite values of what it reads
        (a pole, a log of 0): no membership degree or conclusion is infinite, and inference would
        turn it into NaN, which an output's default then hides. NaN passes on as fuzzylite passes
        it (``sin(x)/x`` at 0 in its own examples), and so does an infinite value read."""
        read = {name: np.broadcast_to(np.asarray(values[name], dtype=float), result.shape) for name in sorted(self.reads)}
        broken = np.isinf(result)
        for value in read.values():
            broken &= np.isfinite(value)
        if broken.any():
            at = np.argwhere(broken)[0]
            where = ", ".join(f"{name}={float(value[tuple(at)])!r}" for name, value in read.items()) or "every input"
            raise InputError(f"gives {float(result[tuple(at)])!r} at {where}: a membership degree or conclusion "
                             "must be finite", field=f"formula {self.formula!r}")
