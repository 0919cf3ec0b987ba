"""Thesis figures and tables by id: ``fuzzynav reproduce ID --out DIR`` looks them up here.

Each experiment is one :class:`Experiment`: its id (``fig-V-28``, ``table-VI-1``…), the function
that runs it, a one-line description, its place in the thesis and the :class:`Claim` its numbers
are checked against — so a figure cannot exist without its claim. A function takes
``(out_dir: Path, quick: bool, seed: int)`` and returns a dict of the numbers it measured
(written next to its figures as ``<id>.json``). ``quick`` shortens long experiments for smoke
runs; the full setting is what the thesis did.

The thesis' experiments are declared chapter by chapter beside their claims
(:mod:`fuzzynav.experiments.claims_iv`, ``claims_v``, ``claims_vi``); code outside the package adds
its own with :func:`register_experiment`, and an installed distribution through the entry point
group ``fuzzynav.experiments`` (an :class:`Experiment` or a list of them, read on first use, after
the thesis' own)::

    [project.entry-points."fuzzynav.experiments"]
    my-figures = "my_package.figures:EXPERIMENTS"

Ids list in the thesis' order: by chapter, then by the number of the figure (``fig-V-7`` before
``fig-V-10``).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass
from importlib import import_module
from typing import Protocol

from fuzzynav.lookup import Registry


class ClaimLike(Protocol):
    """What the registry needs of a claim (:class:`fuzzynav.experiments.claims.Claim`)."""

    @property
    def thesis(self) -> str: ...

    @property
    def asserted(self) -> str: ...

    def evaluate(self, numbers: dict) -> tuple[str, list]: ...


_ID = re.compile(r"^[a-z]+-(?P<chapter>[IVX]+)(?:-(?P<number>\d+)[a-z]?|-[a-z]+)?$")  # fig-VI-22, cmp-VI-tuning
_ROMAN = {"I": 1, "V": 5, "X": 10}


@dataclass(frozen=True)
class Experiment:
    """One reproducible figure or table of the thesis, with the claim its numbers are checked against."""

    id: str  # "fig-VI-22": kind, chapter in Roman numerals, number
    run: str | Callable  # "module:function" (imported when run) or the function itself
    description: str  # one line for ``fuzzynav reproduce --list``
    reference: str  # the thesis' place, e.g. "§VI.5.2, Figs VI.18–VI.24"
    claim: ClaimLike
    position: float | None = None  # its place in its chapter when not its own number (a table between figures)

    def __post_init__(self):
        if not _ID.match(self.id):
            raise ValueError(f"experiment id {self.id!r} is not of the form kind-CHAPTER[-NUMBER] (e.g. fig-VI-22)")

    @property
    def name(self) -> str:
        """Its id: the name the registry knows it by."""
        return self.id

    @property
    def aliases(self) -> tuple[str, ...]:
        """None: an experiment answers to its id only."""
        return ()

    def function(self) -> Callable:
        """The function that runs the experiment."""
        if callable(self.run):
            return self.run
        module_name, attribute = self.run.split(":")
        return getattr(import_module(module_name), attribute)

    def order(self) -> tuple:
        """Sort key in the thesis' order: chapter, then figure number (``position`` if given)."""
        match = _ID.match(self.id)
        assert match is not None  # checked when made
        chapter = _roman(match["chapter"])
        number = self.position if self.position is not None else (
            float(match["number"]) if match["number"] else math.inf)
        return chapter, number, self.id


def _roman(numeral: str) -> int:
    values = [_ROMAN[c] for c in numeral]
    return sum(-v if v < after else v for v, after in zip(values, values[1:] + [0]))


EXPERIMENTS: Registry[Experiment] = Registry("experiment", "ID", Experiment, group="fuzzynav.experiments")
_THESIS_MODULES: tuple[str, ...] = ("fuzzynav.experiments.claims_iv", "fuzzynav.experiments.claims_v", "fuzzynav.experiments.claims_vi",
                   "fuzzynav.experiments.claims_tuning")


def register_experiment(spec: Experiment) -> None:
    """Add ``spec`` to the experiments ``fuzzynav reproduce`` knows; an id registered twice is a
    ``ValueError``."""
    EXPERIMENTS.register(spec)


def _register_thesis() -> None:
    """The thesis' own experiments, registered once, the first time the registry is read (before
    the plug-ins, which the registry reads on first use)."""
    global _THESIS_MODULES
    modules, _THESIS_MODULES = _THESIS_MODULES, ()
    for name in modules:
        for spec in import_module(name).EXPERIMENTS:
            register_experiment(spec)


def specs() -> dict[str, Experiment]:
    """Every registered experiment by id, in the thesis' order."""
    _register_thesis()
    return {spec.id: spec for spec in sorted(EXPERIMENTS.values(), key=Experiment.order)}


def available() -> dict[str, str]:
    """Experiment ids with their descriptions, in the thesis' order."""
    return {key: spec.description for key, spec in specs().items()}


def spec(key: str) -> Experiment:
    """The experiment registered as ``key``; an unknown id is an :class:`~fuzzynav.errors.InputError`."""
    _register_thesis()
    return EXPERIMENTS.find(key, listing="see 'fuzzynav reproduce --list'")


def experiment(key: str) -> Callable:
    """The function that reproduces experiment ``key``."""
    return spec(key).function()
