"""The learning tasks: one module per task family, each owning its phases, rewards, extraction and model file.

=====================  =======================================================================
:mod:`.trackers`       ``neural-tracker``, ``anfis-tracker``: inverse models of the tricycle by
                       generalized learning (§V.3.2, §V.3.5)
:mod:`.tabular_goal`   ``q-goal``: tabular Q-learning goal seeking (§VI.2)
:mod:`.fql_goal`       ``fql-goal``, ``fql-goal-35``, ``fql-goal-traces``: FQL goal seeking (§VI.5.1)
:mod:`.fql_avoid`      ``fql-avoid``: FQL obstacle avoidance inside the goal navigator (§VI.5.2)
:mod:`.fql_wall`       ``fql-wall``: the wall follower of Table VI.2 optimised by FQL (§VI.5.3.2)
:mod:`.common`         what they share: the request, phases, budgets, convergence, curves, files
:mod:`.plan`           a phase's batches: full ones, a smaller last one, from where its checkpoint stopped
=====================  =======================================================================

A task module exposes ``train_…(request) -> dict`` (the results ``fuzzynav train`` prints, at
least ``model``) and ``load_model(document, path) -> Controller`` for the model kind it writes;
the command line finds both by name (docs/ARCHITECTURE.md, "Name tables"). The controller a model
file runs is the class of :mod:`fuzzynav.control.learned` or :mod:`fuzzynav.control.tracking`
that the task extracted.
"""
