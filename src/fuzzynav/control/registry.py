"""Controllers by name: ``fuzzynav run SCENARIO --controller NAME`` looks names up here.

Each entry maps a command-line name to ``"module:factory"``; the module is imported only when
the controller is made, so listing names stays cheap. A factory takes keyword options and
returns a :class:`~fuzzynav.control.base.Controller`.
"""

from __future__ import annotations

from fuzzynav.control.base import Controller
from fuzzynav.lookup import descriptions, resolve

# name -> ("module:factory", one-line description)
CONTROLLERS: dict[str, tuple[str, str]] = {}
CONTROLLERS["goal-seeking"] = ("fuzzynav.control.goal_seeking:make", "goal seeking alone, Table IV.1 (§IV.5.1)")
CONTROLLERS["fuzzy-2b"] = ("fuzzynav.control.avoidance:make",
                           "goal seeking + obstacle avoidance by D_ro, θ_o, Table IV.2, switch of Fig IV.9")
CONTROLLERS["fuzzy-5b"] = ("fuzzynav.control.five_behaviours:make",
                           "GSB, FOA, ROA, LOA, VRB with the supervisor of Fig IV.16 (§IV.7), 7 range sensors")
CONTROLLERS["fuzzy-2b-thesis"] = ("fuzzynav.control.avoidance:make_thesis",
                                  "fuzzy-2b as published: 7 single rays, no gap finding")
CONTROLLERS["fuzzy-5b-thesis"] = ("fuzzynav.control.five_behaviours:make_thesis",
                                  "fuzzy-5b as published: 7 single rays, no gap finding")
CONTROLLERS["wall-follow"] = ("fuzzynav.control.wall_following:make", "hand-made fuzzy wall follower, Table VI.2")
CONTROLLERS["fuzzy-tracker"] = ("fuzzynav.control.tracking:fuzzy_tracker", "fuzzy path/target tracker, Table V.1 (§V.3.1)")
CONTROLLERS["neural-tracker"] = ("fuzzynav.experiments.train_trackers:neural_tracker",
                                 "MLP inverse-model tracker (§V.3.2), trained on the fly")
CONTROLLERS["anfis-tracker"] = ("fuzzynav.experiments.train_trackers:anfis_tracker",
                                "ANFIS tracker, 1 input, 5 MFs (§V.3.5), trained on the fly")
CONTROLLERS["pure-pursuit"] = ("fuzzynav.control.baselines:pure_pursuit", "pure pursuit baseline (Coulter 1992)")
CONTROLLERS["stanley"] = ("fuzzynav.control.baselines:stanley", "Stanley steering baseline (Thrun et al. 2006)")


def available() -> dict[str, str]:
    """Names of the built-in controllers with their one-line descriptions."""
    return descriptions(CONTROLLERS)


def make_controller(name: str, **options) -> Controller:
    """Build the controller registered as ``name`` (an :class:`InputError` names close matches)."""
    return resolve(CONTROLLERS, name, what="controller", field="--controller")(**options)
