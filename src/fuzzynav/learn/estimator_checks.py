"""Input checks of the learned estimators (ANFIS, MLP): arrays, hyper-parameters, fitted-model documents.

Every failure is an :class:`~fuzzynav.errors.InputError` naming the field (and the file, when a
document is read from one).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn import anfis_mf
from fuzzynav.storage import supported_version


def check_format(document, fmt: str, version: int, what: str, source: str | None = None, *, keys=(),
                 required=()) -> None:
    """A fitted-model document of format ``fmt`` and ``version`` (``what``: "an ANFIS", "an MLP")
    whose keys are all in ``keys`` (a typo is refused, not read as its default) and hold ``required``."""
    if not isinstance(document, dict) or document.get("format") != fmt:
        raise InputError(f"not {what} document (format must be {fmt!r})", source=source, field="format")
    supported_version(document, version, source, required=True)
    validation.known_keys(document, keys, source, required=required)


def check_xy(X, y) -> tuple[np.ndarray, np.ndarray]:
    X = check_x(X, None)
    y = np.asarray(y, dtype=float)
    if y.ndim == 2 and y.shape[1] == 1:
        y = y[:, 0]
    if y.shape != (X.shape[0],):
        raise InputError(f"expected shape ({X.shape[0]},), got {y.shape}", field="y")
    if not np.isfinite(y).all():
        raise InputError("contains NaN or infinite values", field="y")
    return X, y


def check_x(X, n_features: int | None) -> np.ndarray:
    try:
        X = np.asarray(X, dtype=float)
    except (TypeError, ValueError) as error:
        raise InputError(f"not a numeric array ({error})", field="X") from None
    if X.ndim != 2 or X.shape[0] == 0 or (n_features is not None and X.shape[1] != n_features):
        want = f"(N, {n_features})" if n_features is not None else "(N, n_features)"
        raise InputError(f"expected a non-empty array of shape {want}, got {X.shape}", field="X")
    if not np.isfinite(X).all():
        raise InputError("contains NaN or infinite values", field="X")
    return X


MAX_RULES = 100_000  # rules of the grid partition (the product of the inputs' MF counts): memory and time


def checked_rules(counts: list[int], source: str | None = None, field: str = "n_mfs") -> list[int]:
    """``counts`` (MFs per input) when their grid of rules holds at most :data:`MAX_RULES` rules,
    checked before any array of that size is made; otherwise an :class:`InputError` on ``field``."""
    rules = math.prod(counts)
    if rules > MAX_RULES:
        raise InputError(f"{' x '.join(map(str, counts))} membership functions make {rules:,} rules, more than the "
                         f"{MAX_RULES:,} a grid-partition ANFIS may hold", source=source, field=field)
    return counts


def check_premises(premises, family: str, n_features: int, field: str, source: str | None = None) -> list[np.ndarray]:
    width = len(anfis_mf.PARAMETER_NAMES[family])
    if not isinstance(premises, (list, tuple)) or len(premises) != n_features:
        raise InputError(f"expected one parameter table per input ({n_features})", source=source, field=field)
    tables = []
    for i, p in enumerate(premises):
        try:
            table = np.array(p, dtype=float)
        except (TypeError, ValueError):
            table = None
        if table is None or table.ndim != 2 or table.shape[0] < 1 or table.shape[1] != width:
            raise InputError(f"expected rows of {width} numbers {anfis_mf.PARAMETER_NAMES[family]}",
                             source=source, field=f"{field}[{i}]")
        if not np.isfinite(table).all() or not (table[:, 0] > 0).all() or (family == "bell" and not (table[:, 1] > 0).all()):
            raise InputError("parameters must be finite with widths (and bell slopes b) > 0",
                             source=source, field=f"{field}[{i}]")
        tables.append(table)
    return tables
