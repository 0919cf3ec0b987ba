"""Thesis figures and tables by id: ``fuzzynav reproduce ID --out DIR`` looks them up here.

Each entry maps an id (``fig-V-28``, ``table-VI-1``…) to ``("module:function", description)``.
A function takes ``(out_dir: Path, quick: bool, seed: int)`` and returns a dict of the numbers it
measured (written next to its figures as ``<id>.json``). ``quick`` shortens long experiments for
smoke runs; the full setting is what the thesis did.
"""

from __future__ import annotations

from fuzzynav.lookup import descriptions, resolve

EXPERIMENTS: dict[str, tuple[str, str]] = {}
_CH4 = "fuzzynav.experiments.chapter4"
EXPERIMENTS["fig-IV-12"] = (f"{_CH4}:fig_iv_12", "free goal seeking from five starts per panel, Table IV.1 (§IV.6.1)")
EXPERIMENTS["fig-IV-13"] = (f"{_CH4}:fig_iv_13", "free navigation and its commands α, V_r (Figs IV.13-IV.14)")
EXPERIMENTS["fig-IV-15"] = (f"{_CH4}:fig_iv_15", "fuzzy-2b-thesis past circular obstacles, switches A...H (§IV.6.2)")
EXPERIMENTS["fig-IV-22"] = (f"{_CH4}:fig_iv_22", "fuzzy-5b-thesis in unknown cluttered worlds (§IV.7.1)")
EXPERIMENTS["fig-IV-23"] = (f"{_CH4}:fig_iv_23", "fuzzy-5b-thesis reaches a goal inside a U-shaped wall (§IV.7.1)")
EXPERIMENTS["fig-VI-28"] = (f"{_CH4}:fig_vi_28", "hand-made wall follower: bend followed, sharp corner hit (Figs VI.27-VI.28)")
EXPERIMENTS["eval-IV"] = (f"{_CH4}:eval_iv", "fuzzy-2b-thesis on circle worlds, fuzzy-5b-thesis on mixed worlds: success/collision rates")
_CH5 = "fuzzynav.experiments.chapter5"
EXPERIMENTS["fig-V-7"] = (f"{_CH5}:fig_v_7", "control surface of the fuzzy tracker, Table V.1")
EXPERIMENTS["fig-V-10"] = (f"{_CH5}:fig_v_10", "fuzzy tracker CF on six straight lines from (10,10) (§V.3.1)")
EXPERIMENTS["fig-V-11"] = (f"{_CH5}:fig_v_11", "fuzzy tracker CF on the N and trapezoid paths (§V.3.1)")
EXPERIMENTS["fig-V-15"] = (f"{_CH5}:fig_v_15", "MLP tracker: validation on unseen pairs and training loss (§V.3.2)")
EXPERIMENTS["fig-V-18"] = (f"{_CH5}:fig_v_18", "neural tracker CN on six straight lines from (10,10) (§V.3.2)")
EXPERIMENTS["fig-V-19"] = (f"{_CH5}:fig_v_19", "neural tracker CN on the N and trapezoid paths (§V.3.2)")
EXPERIMENTS["fig-V-23"] = (f"{_CH5}:fig_v_23", "ANFIS tracker: validation and training curve (§V.3.5)")
EXPERIMENTS["fig-V-26"] = (f"{_CH5}:fig_v_26", "ANFIS tracker CNF on six straight lines from (10,10) (§V.3.5)")
EXPERIMENTS["fig-V-27"] = (f"{_CH5}:fig_v_27", "ANFIS tracker CNF on the N and trapezoid paths (§V.3.5)")
EXPERIMENTS["fig-V-28"] = (f"{_CH5}:fig_v_28", "V path by CF, CN, CNF with a zoom on the corner (§V.4)")
EXPERIMENTS["fig-V-29"] = (f"{_CH5}:fig_v_29", "pursuit of a target on a line by CF, CN, CNF (§V.5)")
EXPERIMENTS["fig-V-30"] = (f"{_CH5}:fig_v_30", "pursuit of a target on a circle by CF, CN, CNF (§V.5)")
EXPERIMENTS["fig-V-31"] = (f"{_CH5}:fig_v_31", "pursuit of a target on a sinusoid by CF, CN, CNF (§V.5)")
EXPERIMENTS["fig-V-32"] = (f"{_CH5}:fig_v_32", "pursuit of a target on a line, CF/CN/CNF compared at the capture (§V.5.1)")
EXPERIMENTS["fig-V-33"] = (f"{_CH5}:fig_v_33", "pursuit of targets on two straight lines by CF, CN, CNF (§V.5.1)")
EXPERIMENTS["fig-V-34"] = (f"{_CH5}:fig_v_34", "pursuit of a circular and a sinusoidal target by CF, CN, CNF (§V.5.1)")
_CH6 = "fuzzynav.experiments.chapter6"
EXPERIMENTS["fig-VI-1"] = (f"{_CH6}:fig_vi_1", "tabular Q-learning goal seeking, fixed start: curve and trajectory (VI.1-VI.2)")
EXPERIMENTS["fig-VI-4"] = (f"{_CH6}:fig_vi_4", "tabular Q-learning, random starts: curve and trajectories (VI.3-VI.4)")
EXPERIMENTS["table-VI-1"] = (f"{_CH6}:table_vi_1", "episodes to converge for 9/11/13/19 states (Table VI.1)")
EXPERIMENTS["fig-VI-8"] = (f"{_CH6}:fig_vi_8", "FQL 15 rules, fixed start (VI.7-VI.8)")
EXPERIMENTS["fig-VI-9"] = (f"{_CH6}:fig_vi_9", "FQL 15 rules, random starts, steering then speed (VI.9-VI.10)")
EXPERIMENTS["fig-VI-13"] = (f"{_CH6}:fig_vi_13", "FQL 35 rules x 5 conclusions (VI.13-VI.14)")
EXPERIMENTS["fig-VI-16"] = (f"{_CH6}:fig_vi_16", "FQL with eligibility traces (VI.15-VI.16)")
EXPERIMENTS["fig-VI-22"] = (f"{_CH6}:fig_vi_22", "FQL obstacle avoidance: curves and trajectories (VI.18-VI.22)")
EXPERIMENTS["fig-VI-24"] = (f"{_CH6}:fig_vi_24", "chapter IV navigator vs FQL navigator on the same world (VI.23-VI.24)")
EXPERIMENTS["fig-VI-29"] = (f"{_CH6}:fig_vi_29", "hand-made vs FQL-optimised wall follower: Fig VI.28 corners, wall courses (VI.29-VI.30)")


def available() -> dict[str, str]:
    """Experiment ids with their descriptions."""
    return descriptions(EXPERIMENTS)


def experiment(key: str):
    """The function that reproduces experiment ``key``."""
    return resolve(EXPERIMENTS, key, what="experiment", field="ID", listing="see 'fuzzynav reproduce --list'")
