"""Controllers by name: ``fuzzynav run SCENARIO --controller NAME`` looks names up here.

Each entry maps a command-line name to ``"module:factory"``; the module is imported only when
the controller is made, so listing names stays cheap. A factory takes keyword options and
returns a :class:`~fuzzynav.control.base.Controller`.
"""

from __future__ import annotations

from fuzzynav import validation
from fuzzynav.control.base import Controller
from fuzzynav.lookup import descriptions, resolve

# name -> ("module:factory", one-line description)
CONTROLLERS: dict[str, tuple[str, str]] = {}
CONTROLLERS["goal-seeking"] = ("fuzzynav.control.goal_seeking:make", "goal seeking alone, Table IV.1 (§IV.5.1)")
CONTROLLERS["fuzzy-2b"] = ("fuzzynav.control.robust:fuzzy_2b",
                           "fuzzy-2b-thesis with recovery (backing out) and loop escape (boundary following)")
CONTROLLERS["fuzzy-5b"] = ("fuzzynav.control.through_gaps:fuzzy_5b_gap_robust",
                           "fuzzy-5b-gap (lidar) aimed along a car route round what it has seen, with recovery "
                           "and loop escape (the default)")
CONTROLLERS["fuzzy-5b-rays"] = ("fuzzynav.control.robust:fuzzy_5b",
                                "fuzzy-5b-thesis (7 range sensors) with recovery (backing out) and loop escape "
                                "(boundary following); the default before fuzzy-5b moved to the lidar")
CONTROLLERS["fuzzy-2b-thesis"] = ("fuzzynav.control.robust:fuzzy_2b_thesis",
                                  "goal seeking + obstacle avoidance by D_ro, θ_o, Table IV.2, switch of Fig IV.9")
CONTROLLERS["fuzzy-5b-thesis"] = ("fuzzynav.control.robust:fuzzy_5b_thesis",
                                  "GSB, FOA, ROA, LOA, VRB with the supervisor of Fig IV.16 (§IV.7), 7 range sensors")
CONTROLLERS["fuzzy-2b-gap"] = ("fuzzynav.control.avoidance:make_gap",
                               "fuzzy-2b-thesis on a lidar, steering through the widest gap that fits (opt-in)")
CONTROLLERS["fuzzy-5b-gap"] = ("fuzzynav.control.five_behaviours:make_gap",
                               "fuzzy-5b-thesis on a lidar, steering through the widest gap that fits (inside fuzzy-5b)")
CONTROLLERS["fuzzy-5b-gap-robust"] = ("fuzzynav.control.through_gaps:fuzzy_5b_gap_robust",
                                      "another name of fuzzy-5b (the same navigator)")
CONTROLLERS["wall-follow"] = ("fuzzynav.control.wall_following:make", "hand-made fuzzy wall follower, Table VI.2")
CONTROLLERS["fuzzy-tracker"] = ("fuzzynav.control.tracking:fuzzy_tracker", "fuzzy path/target tracker, Table V.1 (§V.3.1)")
CONTROLLERS["neural-tracker"] = ("fuzzynav.learn.tasks.trackers:neural_tracker",
                                 "MLP inverse-model tracker (§V.3.2), trained on the fly")
CONTROLLERS["anfis-tracker"] = ("fuzzynav.learn.tasks.trackers:anfis_tracker",
                                "ANFIS tracker, 1 input, 5 MFs (§V.3.5), trained on the fly")
CONTROLLERS["pure-pursuit"] = ("fuzzynav.control.baselines:pure_pursuit", "pure pursuit baseline (Coulter 1992)")
CONTROLLERS["stanley"] = ("fuzzynav.control.baselines:stanley", "Stanley steering baseline (Thrun et al. 2006)")
CONTROLLERS["dwa"] = ("fuzzynav.control.classic.dwa:make",
                      "Dynamic Window Approach (Fox, Burgard & Thrun 1997) on the 7 range sensors")
CONTROLLERS["apf"] = ("fuzzynav.control.classic.apf:make",
                      "artificial potential field (Khatib 1986) on the 7 range sensors")
CONTROLLERS["vfh"] = ("fuzzynav.control.classic.vfh:make", "VFH+ (Ulrich & Borenstein 1998) on the 7 range sensors")
CONTROLLERS["astar-pp"] = ("fuzzynav.control.classic.astar_pp:make",
                           "MAP-AWARE reference: A* on the inflated map + pure pursuit (knows the whole map)")


def available() -> dict[str, str]:
    """Names of the built-in controllers with their one-line descriptions."""
    return descriptions(CONTROLLERS)


def make_controller(name: str, **options) -> Controller:
    """Build the controller registered as ``name`` (an :class:`InputError` names close matches);
    a factory registered under two names (``fuzzy-5b``, ``fuzzy-5b-gap-robust``) gives its
    controller the name asked for, which its traces and metrics show."""
    validation.text(name, field="name", max_length=200)
    controller = resolve(CONTROLLERS, name, what="controller", field="--controller")(**options)
    if sum(factory == CONTROLLERS[name][0] for factory, _ in CONTROLLERS.values()) > 1:
        controller.name = name
    return controller
