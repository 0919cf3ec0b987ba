"""The optimisers of ``fuzzynav tune``, all behind one ask/tell interface over genes in [0, 1].

- ``ga``: pymoo's genetic algorithm (real-coded: simulated binary crossover, polynomial
  mutation, tournament selection, elitist survival; Deb & Agrawal 1995, Deb 2001);
- ``de``: pymoo's differential evolution (DE/rand/1/bin, Storn & Price 1997);
- ``pso``: pymoo's particle swarm (Kennedy & Eberhart 1995, with the adaptive inertia of Zhan et
  al. 2009);
- ``cmaes``: the ``cma`` package's CMA-ES (Hansen & Ostermeier 2001), box-bounded to [0, 1];
- ``nsga2``: pymoo's NSGA-II (Deb et al. 2002) on several objectives — a Pareto front;
- ``aco``: the ant colony system over the discrete rule conclusions (:mod:`fuzzynav.tune.aco`).

Every optimiser starts from the system being tuned: it and neighbours of it make the first
population (for CMA-ES: it is the mean of the first distribution and its first candidate). All randomness comes from ``seed``, so the
same calls with the same fitness values replay the same run (what ``--resume`` relies on).
pymoo (Apache-2.0) and cma (BSD-3-Clause) are the ``tune`` extra.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError

METHODS = ("ga", "pso", "aco", "de", "cmaes", "nsga2")
CMA_SIGMA = 0.1  # CMA-ES's first step size, in genes (the box is [0, 1]; as SPREAD of the first populations)


PACKAGES = {"ga": "pymoo", "pso": "pymoo", "de": "pymoo", "nsga2": "pymoo", "cmaes": "cma"}  # aco: this package's


def check_available(method: str) -> None:
    """The package ``method`` runs on can be imported: checked with the options, before the training
    worlds are built (and kernels compiled) for nothing."""
    if method in PACKAGES:
        _needs(PACKAGES[method])


def _needs(module: str):
    try:
        return __import__(module)
    except ImportError:
        raise InputError(f"needs the {module} package: pip install -e '.[tune]' in the clone", field="--method") from None


class PymooOptimiser:
    """A pymoo algorithm driven by ask/tell; its first population is the start and neighbours of it
    (:meth:`~fuzzynav.tune.space.SearchSpace.around_start`)."""

    def __init__(self, method: str, space, pop_size: int, seed: int, n_obj: int):
        _needs("pymoo")
        from pymoo.algorithms.moo.nsga2 import NSGA2
        from pymoo.algorithms.soo.nonconvex.de import DE
        from pymoo.algorithms.soo.nonconvex.ga import GA
        from pymoo.algorithms.soo.nonconvex.pso import PSO
        from pymoo.core.problem import Problem
        from pymoo.core.termination import NoTermination

        first = space.around_start(pop_size, np.random.default_rng(seed))
        algorithm = {"ga": GA, "de": DE, "pso": PSO, "nsga2": NSGA2}[method](pop_size=pop_size, sampling=first)
        self.problem = Problem(n_var=space.size, n_obj=n_obj, xl=0.0, xu=1.0)
        algorithm.setup(self.problem, termination=NoTermination(), seed=seed, verbose=False)
        self.algorithm, self._pop = algorithm, None

    def ask(self) -> np.ndarray:
        self._pop = self.algorithm.ask()
        return np.asarray(self._pop.get("X"), dtype=float)

    def tell(self, population: np.ndarray, values: np.ndarray) -> None:
        from pymoo.core.evaluator import Evaluator
        from pymoo.problems.static import StaticProblem

        Evaluator().eval(StaticProblem(self.problem, F=np.asarray(values, dtype=float)), self._pop)
        self.algorithm.tell(infills=self._pop)


class CmaOptimiser:
    """CMA-ES of the ``cma`` package, started at ``start`` with step :data:`CMA_SIGMA`; the start
    is the first candidate of the first generation (``inject``)."""

    def __init__(self, start: np.ndarray, pop_size: int, seed: int):
        cma = _needs("cma")
        self.es = cma.CMAEvolutionStrategy(np.asarray(start, dtype=float), CMA_SIGMA, {
            "bounds": [0.0, 1.0], "popsize": pop_size, "seed": seed + 1, "verbose": -9})
        self.es.inject([np.asarray(start, dtype=float)], force=True)  # the start itself is the first candidate

    def ask(self) -> np.ndarray:
        return np.asarray(self.es.ask(), dtype=float)

    def tell(self, population: np.ndarray, values: np.ndarray) -> None:
        self.es.tell(list(population), np.asarray(values, dtype=float)[:, 0].tolist())


def make_optimiser(method: str, space, pop_size: int, seed: int, n_obj: int = 1):
    """The optimiser ``method`` over ``space`` (a :class:`~fuzzynav.tune.space.SearchSpace`)."""
    if method not in METHODS:
        raise InputError(f"must be one of {', '.join(METHODS)}, got {method!r}", field="--method")
    if method == "aco":
        from fuzzynav.tune.aco import AntColonySystem

        return AntColonySystem(space, pop_size, seed)
    if method == "cmaes":
        return CmaOptimiser(space.start, pop_size, seed)
    return PymooOptimiser(method, space, pop_size, seed, n_obj)
