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
