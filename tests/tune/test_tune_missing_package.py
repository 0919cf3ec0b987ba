"""A method whose package is not installed is refused with the other options, before any world is
built: ``tune --method ga`` without pymoo built the training worlds, compiling kernels on a cold
cache ("fuzzynav: compiling kernels not yet in the cache ..."), before saying ``needs the pymoo
package``."""

from __future__ import annotations

import sys

import pytest

from fuzzynav.cli import main
from fuzzynav.tune import session


@pytest.mark.parametrize("method, package", [("ga", "pymoo"), ("pso", "pymoo"), ("de", "pymoo"), ("cmaes", "cma")])
def test_a_method_without_its_package_is_refused_before_any_episode(method, package, monkeypatch, capsys):
    monkeypatch.setitem(sys.modules, package, None)  # `import pymoo` raises ImportError

    def fitness(*args, **kwargs):
        raise AssertionError("the training worlds were built (and their kernels compiled) before the check")

    monkeypatch.setattr(session, "Fitness", fitness)
    argv = ["tune", "fuzzy-2b:oab", "--method", method, "--worlds", "mixed:2", "--budget", "40", "--validation", "none"]
    assert main(argv) == 2
    err = capsys.readouterr().err
    assert f"--method: needs the {package} package: pip install -e '.[tune]'" in err and "Traceback" not in err


def test_the_ant_colony_needs_no_package(monkeypatch):
    for package in ("pymoo", "cma"):
        monkeypatch.setitem(sys.modules, package, None)
    request = session.TuneRequest(target="fuzzy-2b:oab", worlds="mixed:2", what="rules", method="aco", budget=40,
                                  validation="none")
    session.check(request)  # no error: aco is this package's own
