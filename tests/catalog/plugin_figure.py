"""A figure written as CONTRIBUTING.md's recipe says, outside the package: its function and its
spec with the claim it is checked against, declared under the ``fuzzynav.experiments`` entry point
group (used by tests/experiments/test_report.py)."""

from fuzzynav.catalog.experiments import Experiment
from fuzzynav.experiments.claims import Check, Claim


def fig_ix_2(out_dir, quick=False, seed=0):
    """The numbers the claim reads: 42 for seed 0, another answer for any other seed."""
    return {"answer": 42 + seed}


EXPERIMENTS = [Experiment("fig-IX-2", "tests.catalog.plugin_figure:fig_ix_2",
                          "a figure of a chapter the thesis does not have, from a plug-in", "§IX.2",
                          Claim("The answer is 42.", "The answer is 42.",
                                lambda numbers: [Check("answer", numbers["answer"], "= 42", numbers["answer"] == 42)]))]
