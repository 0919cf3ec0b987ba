"""Thesis figures and tables by id: ``fuzzynav reproduce ID --out DIR`` looks them up here.

Each entry maps an id (``fig-V-28``, ``table-VI-1``…) to ``("module:function", description)``,
the function named after the id (``fig_v_28``, ``table_vi_1``) in its chapter's module. A
function takes ``(out_dir: Path, quick: bool, seed: int)`` and returns a dict of the numbers it
measured (written next to its figures as ``<id>.json``). ``quick`` shortens long experiments for
smoke runs; the full setting is what the thesis did.
"""

from __future__ import annotations

from fuzzynav.lookup import descriptions, resolve


def _chapter(module: str, experiments: dict[str, str]) -> dict[str, tuple[str, str]]:
    """The entries of ``module``'s experiments (id -> description): each id's function is named
    after it (``fig-V-28`` -> ``fig_v_28``)."""
    return {key: (f"{module}:{key.lower().replace('-', '_')}", text) for key, text in experiments.items()}


EXPERIMENTS: dict[str, tuple[str, str]] = {
    **_chapter("fuzzynav.experiments.chapter4", {
        "fig-IV-12": "free goal seeking from five starts per panel, Table IV.1 (§IV.6.1)",
        "fig-IV-13": "free navigation and its commands α, V_r (Figs IV.13-IV.14)",
        "fig-IV-15": "fuzzy-2b-thesis past circular obstacles, switches A...H (§IV.6.2)",
        "fig-IV-22": "fuzzy-5b-thesis in unknown cluttered worlds (§IV.7.1)",
        "fig-IV-23": "fuzzy-5b-thesis reaches a goal inside a U-shaped wall (§IV.7.1)",
        "fig-VI-28": "hand-made wall follower: bend followed, sharp corner hit (Figs VI.27-VI.28)",
        "eval-IV": "fuzzy-2b-thesis on circle worlds, fuzzy-5b-thesis on mixed worlds: success/collision rates",
    }),
    **_chapter("fuzzynav.experiments.chapter5", {
        "fig-V-7": "control surface of the fuzzy tracker, Table V.1",
        "fig-V-10": "fuzzy tracker CF on six straight lines from (10,10) (§V.3.1)",
        "fig-V-11": "fuzzy tracker CF on the N and trapezoid paths (§V.3.1)",
        "fig-V-15": "MLP tracker: validation on unseen pairs and training loss (§V.3.2)",
        "fig-V-18": "neural tracker CN on six straight lines from (10,10) (§V.3.2)",
        "fig-V-19": "neural tracker CN on the N and trapezoid paths (§V.3.2)",
        "fig-V-23": "ANFIS tracker: validation and training curve (§V.3.5)",
        "fig-V-26": "ANFIS tracker CNF on six straight lines from (10,10) (§V.3.5)",
        "fig-V-27": "ANFIS tracker CNF on the N and trapezoid paths (§V.3.5)",
        "fig-V-28": "V path by CF, CN, CNF with a zoom on the corner (§V.4)",
        "fig-V-29": "pursuit of a target on a line by CF, CN, CNF (§V.5)",
        "fig-V-30": "pursuit of a target on a circle by CF, CN, CNF (§V.5)",
        "fig-V-31": "pursuit of a target on a sinusoid by CF, CN, CNF (§V.5)",
        "fig-V-32": "pursuit of a target on a line, CF/CN/CNF compared at the capture (§V.5.1)",
        "fig-V-33": "pursuit of targets on two straight lines by CF, CN, CNF (§V.5.1)",
        "fig-V-34": "pursuit of a circular and a sinusoidal target by CF, CN, CNF (§V.5.1)",
    }),
    **_chapter("fuzzynav.experiments.chapter6", {
        "fig-VI-1": "tabular Q-learning goal seeking, fixed start: curve and trajectory (VI.1-VI.2)",
        "fig-VI-4": "tabular Q-learning, random starts: curve and trajectories (VI.3-VI.4)",
        "table-VI-1": "episodes to converge for 9/11/13/19 states (Table VI.1)",
        "fig-VI-8": "FQL 15 rules, fixed start (VI.7-VI.8)",
        "fig-VI-9": "FQL 15 rules, random starts, steering then speed (VI.9-VI.10)",
        "fig-VI-13": "FQL 35 rules x 5 conclusions (VI.13-VI.14)",
        "fig-VI-16": "FQL with eligibility traces (VI.15-VI.16)",
        "fig-VI-22": "FQL obstacle avoidance: curves and trajectories (VI.18-VI.22)",
        "fig-VI-24": "chapter IV navigator vs FQL navigator on the same world (VI.23-VI.24)",
        "fig-VI-29": "hand-made vs FQL-optimised wall follower: Fig VI.28 corners, wall courses (VI.29-VI.30)",
    }),
}

def available() -> dict[str, str]:
    """Experiment ids with their descriptions."""
    return descriptions(EXPERIMENTS)


def experiment(key: str):
    """The function that reproduces experiment ``key``."""
    return resolve(EXPERIMENTS, key, what="experiment", field="ID", listing="see 'fuzzynav reproduce --list'")
