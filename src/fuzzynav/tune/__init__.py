"""Tuning a controller's fuzzy system by stochastic search (``fuzzynav tune``; the thesis' closing
perspectives: genetic algorithms and ant colonies).

- :mod:`~fuzzynav.tune.space`: genes in [0, 1] ↔ breakpoints (order kept, strong partitions
  strong) and rule conclusions;
- :mod:`~fuzzynav.tune.episodes`: a population × its worlds in one compiled call of the
  simulator's own step;
- :mod:`~fuzzynav.tune.fitness`: the cost of an episode (success, then time) and the objectives;
- :mod:`~fuzzynav.tune.optimisers`: GA, DE, PSO, NSGA-II (pymoo), CMA-ES (cma) behind ask/tell;
- :mod:`~fuzzynav.tune.aco`: the ant colony system over the rule conclusions;
- :mod:`~fuzzynav.tune.session`: checked options, generations, checkpoint and resume, held-out test;
- :mod:`~fuzzynav.tune.curve`: the learning curve.
"""
