"""Fuzzy rules (thesis §II.4.2, eq IV.3): built from text, from a printed grid table, or in code.

A rule is ``IF x1 IS A1 AND x2 IS A2 THEN y1 IS B1 AND y2 IS B2 [WITH w]``: a conjunction of
premises (one term per input, an input may be left out = "any"), one conclusion term per output
it concludes on, and a weight w in [0, 1] (default 1) that scales its firing strength. Names are
checked against the system's variables when a :class:`~fuzzynav.fuzzy.system.FuzzySystem` is
built; this module only parses.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from numbers import Real

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.formula import decimal
from fuzzynav.validation import shown


@dataclass(frozen=True)
class Rule:
    """One rule: ``premises`` and ``conclusions`` are ((variable, term), ...) pairs."""

    premises: tuple[tuple[str, str], ...]
    conclusions: tuple[tuple[str, str], ...]
    weight: float = 1.0

    def __post_init__(self):
        for name in ("premises", "conclusions"):
            try:
                pairs = tuple((str(v), str(t)) for v, t in getattr(self, name))
            except (TypeError, ValueError):  # None, a string, a triple
                raise InputError(f"must be (variable, term) pairs, got {shown(getattr(self, name))}",
                                 field=name) from None
            object.__setattr__(self, name, pairs)
        if isinstance(self.weight, bool) or not isinstance(self.weight, Real):  # "0.5" and True were read as numbers
            raise InputError(f"rule weight must be a number in [0, 1], got {shown(self.weight)}", field=self.text())
        weight = float(self.weight)
        if not (0.0 <= weight <= 1.0) or math.isnan(weight):
            raise InputError(f"rule weight must be in [0, 1], got {self.weight!r}", field=self.text())
        object.__setattr__(self, "weight", weight)
        if not self.conclusions:
            raise InputError("rule has no conclusion", field=self.text())

    def text(self) -> str:
        """The rule in the text syntax :func:`parse_rule` reads (weight written exactly)."""
        premises = " AND ".join(f"{v} IS {t}" for v, t in self.premises) or "TRUE"
        conclusions = " AND ".join(f"{v} IS {t}" for v, t in self.conclusions)
        weight = "" if self.weight == 1.0 else f" WITH {self.weight!r}"
        return f"IF {premises} THEN {conclusions}{weight}"

    def __str__(self) -> str:
        return self.text()


def _clauses(words: list[str], where: str, text: str) -> tuple[tuple[str, str], ...]:
    if words == ["TRUE"]:
        return ()
    clauses, i = [], 0
    while i < len(words):
        chunk = words[i : i + 3]
        if len(chunk) != 3 or chunk[1].upper() != "IS":
            raise InputError(f"expected 'VARIABLE IS TERM' in the {where} of {text!r}")
        if chunk[2].upper() == "NOT":
            raise InputError(f"negated premises (IS NOT) are not supported: {text!r}")
        clauses.append((chunk[0], chunk[2]))
        i += 3
        if i < len(words):
            if words[i].upper() != "AND":
                raise InputError(f"only AND joins clauses, found {words[i]!r} in {text!r}")
            i += 1
            if i == len(words):
                raise InputError(f"dangling AND in {text!r}")
    return tuple(clauses)


def parse_rule(text: str) -> Rule:
    """Parse ``"IF drg IS P AND theta IS NG THEN alpha IS PM AND v IS F [WITH 0.5]"``.

    Keywords (IF, IS, AND, THEN, WITH) are case-insensitive; names are case-sensitive.
    """
    words = str(text).split()
    upper = [w.upper() for w in words]
    if not words or upper[0] != "IF" or "THEN" not in upper:
        raise InputError(f"a rule reads 'IF ... THEN ...', got {text!r}")
    then = upper.index("THEN")
    weight = 1.0
    tail = words[then + 1 :]
    tail_upper = upper[then + 1 :]
    if "WITH" in tail_upper:
        w = tail_upper.index("WITH")
        if w != len(tail) - 2:
            raise InputError(f"WITH must be followed by exactly one weight at the end of {text!r}")
        try:
            weight = decimal(tail[-1])  # ('0_1' was read as 1)
        except ValueError:
            raise InputError(f"rule weight {tail[-1]!r} is not a number in {text!r}") from None
        tail = tail[:w]
    return Rule(_clauses(words[1:then], "premise", text), _clauses(tail, "conclusion", text), weight)


def rules_from_grid(
    rows: str,
    columns: str,
    row_labels: Sequence[str],
    column_labels: Sequence[str],
    cells: Sequence[Sequence[str] | str],
    outputs: Sequence[str],
    *,
    columns_first: bool = True,
    source: str | None = None,
) -> list[Rule]:
    """Rules of a two-input table printed as rows × columns (Tables IV.1, IV.2, V.1).

    ``cells[i][j]`` concludes the rule ``IF rows IS row_labels[i] AND columns IS
    column_labels[j]``; a cell holds one label per output, separated by ``/`` (``"PM/F"`` for
    outputs ``("alpha", "v")``). A row may also be given as one string of whitespace-separated
    cells. Rules come out row by row; the premises read column
    first ("IF drg IS P AND theta IS NG", Table IV.1) unless ``columns_first=False``
    ("IF theta_er IS NG AND dtheta_er IS PG", Table V.1). A missing or malformed cell raises
    :class:`InputError` naming the cell.
    """
    outputs = list(outputs)
    if len(cells) != len(row_labels):
        raise InputError(f"table has {len(cells)} rows, expected {len(row_labels)} ({' '.join(row_labels)})",
                         source=source, field="rows")
    rules = []
    for row_label, row in zip(row_labels, cells):
        row = row.split() if isinstance(row, str) else list(row)
        if len(row) != len(column_labels):
            raise InputError(
                f"row {row_label} has {len(row)} cells, expected {len(column_labels)} ({' '.join(column_labels)})",
                source=source, field=f"row {row_label}")
        for column_label, cell in zip(column_labels, row):
            where = f"cell ({rows}={row_label}, {columns}={column_label})"
            parts = [p.strip() for p in str(cell if cell is not None else "").split("/")]
            if len(parts) != len(outputs) or not all(parts):
                raise InputError(
                    f"expected {len(outputs)} label(s) '{'/'.join(outputs)}', got {cell!r}", source=source, field=where)
            premises = ((columns, column_label), (rows, row_label))
            rules.append(Rule(premises if columns_first else premises[::-1], tuple(zip(outputs, parts))))
    return rules
