"""A reproduced claim and its checks: what the thesis says, and the tests of it on our numbers.

Each experiment of :mod:`fuzzynav.catalog.experiments` carries a :class:`Claim`: the thesis'
statement (translated from the French, with its numbers), what this package asserts of its own
run, and a test that turns the numbers the experiment returned into a list of :class:`Check`
— each a measured value, the bound it must meet and whether it does. A check belongs either
to the thesis (``source="thesis"``: the figure or text says so) or to this package
(``source="package"``: a target the thesis does not give, e.g. a success rate over random
worlds), and the report keeps the two apart.

The verdict over the checks is ``reproduced`` (every check passes), ``partly`` (some pass) or
``not reproduced`` (none passes, or the run did not report the numbers the claim needs).
The chapters' claims live beside their experiments' specs: :mod:`fuzzynav.experiments.claims_iv`,
:mod:`~fuzzynav.experiments.claims_v` and :mod:`~fuzzynav.experiments.claims_vi`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import asdict, dataclass

REPRODUCED, PARTLY, NOT_REPRODUCED = "reproduced", "partly", "not reproduced"
SOURCES = ("thesis", "package")


@dataclass(frozen=True)
class Check:
    """One measured value against its bound: ``passed`` says whether ``value`` meets ``target``."""

    name: str  # what is checked, e.g. "speed at arrival"
    value: object  # the measured value (JSON-able: a number, a string, a list, None)
    target: str  # the bound in words, e.g. "≤ 0.15 m/s"
    passed: bool
    source: str = "thesis"  # "thesis": the thesis' claim; "package": a target of this package

    def __post_init__(self):
        if self.source not in SOURCES:
            raise ValueError(f"Check {self.name!r}: source must be one of {SOURCES}, not {self.source!r}")
        object.__setattr__(self, "passed", bool(self.passed))

    def as_json(self) -> dict:
        """The check as ``claim.json`` writes it (``pass`` for ``passed``)."""
        record = asdict(self)
        record["pass"] = record.pop("passed")
        return record


def verdict_of(checks: list[Check]) -> str:
    """``reproduced`` when every check passes, ``partly`` when some do, else ``not reproduced``."""
    passed = sum(check.passed for check in checks)
    if checks and passed == len(checks):
        return REPRODUCED
    return PARTLY if passed else NOT_REPRODUCED


@dataclass(frozen=True)
class Claim:
    """The thesis' statement for one figure or table, our asserted claim and its checks."""

    thesis: str  # the thesis' words and numbers, translated
    asserted: str  # what this package checks of its own run
    test: Callable[[dict], list[Check]]  # numbers of the run -> its checks

    def evaluate(self, numbers: dict) -> tuple[str, list[Check]]:
        """(verdict, checks); numbers missing from the run make one failed check, not a crash."""
        try:
            checks = list(self.test(numbers))
        except (KeyError, TypeError, IndexError) as error:
            checks = [Check("the numbers the claim needs", f"missing: {error!r}", "reported by the run", False)]
        if not checks:
            raise ValueError(f"a claim's test returned no check: {self.asserted!r}")
        return verdict_of(checks), checks
