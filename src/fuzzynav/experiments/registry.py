"""Thesis figures and tables by id: ``fuzzynav reproduce ID --out DIR`` looks them up here.

Each entry maps an id (``fig-V-28``, ``table-VI-1``…) to ``("module:function", description)``.
A function takes ``(out_dir: Path, quick: bool, seed: int)`` and returns a dict of the numbers it
measured (written next to its figures as ``<id>.json``). ``quick`` shortens long experiments for
smoke runs; the full setting is what the thesis did.
"""

from __future__ import annotations

import difflib
from importlib import import_module

from fuzzynav.errors import InputError

EXPERIMENTS: dict[str, tuple[str, str]] = {}
_CH5 = "fuzzynav.experiments.chapter5"
EXPERIMENTS["fig-V-7"] = (f"{_CH5}:fig_v_7", "control surface of the fuzzy tracker, Table V.1")
EXPERIMENTS["fig-V-15"] = (f"{_CH5}:fig_v_15", "MLP tracker: validation on unseen pairs and training loss (§V.3.2)")
EXPERIMENTS["fig-V-23"] = (f"{_CH5}:fig_v_23", "ANFIS tracker: validation and training curve (§V.3.5)")
EXPERIMENTS["fig-V-28"] = (f"{_CH5}:fig_v_28", "V path by CF, CN, CNF with a zoom on the corner (§V.4)")
EXPERIMENTS["fig-V-29"] = (f"{_CH5}:fig_v_29", "pursuit of a target on a line by CF, CN, CNF (§V.5)")
EXPERIMENTS["fig-V-30"] = (f"{_CH5}:fig_v_30", "pursuit of a target on a circle by CF, CN, CNF (§V.5)")
EXPERIMENTS["fig-V-31"] = (f"{_CH5}:fig_v_31", "pursuit of a target on a sinusoid by CF, CN, CNF (§V.5)")


def available() -> dict[str, str]:
    """Experiment ids with their descriptions."""
    return {key: description for key, (_, description) in sorted(EXPERIMENTS.items())}


def experiment(key: str):
    """The function that reproduces experiment ``key``."""
    if key not in EXPERIMENTS:
        close = difflib.get_close_matches(key, EXPERIMENTS, n=3)
        hint = f" (did you mean {', '.join(close)}?)" if close else ""
        raise InputError(f"unknown experiment {key!r}{hint}; see 'fuzzynav reproduce --list'", field="ID")
    module_name, function_name = EXPERIMENTS[key][0].split(":")
    return getattr(import_module(module_name), function_name)
