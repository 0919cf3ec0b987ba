"""Figures and tables of chapter VI (§VI.2, §VI.5): learning curves, learned trajectories, comparisons.

Every function has the registry signature ``(out_dir, quick, seed) -> dict``: it trains what it
needs with the tasks of :mod:`fuzzynav.learn.tasks` under the thesis' protocol (one robot, one
episode after another, q = 0 at start, the conclusion of best quality extracted:
:data:`fuzzynav.learn.tasks.common.THESIS`; models and checkpoints under ``out_dir/models``),
writes PNGs and returns the numbers it measured; :mod:`fuzzynav.experiments.claims_vi` checks
them against the thesis. ``quick`` cuts the episode budgets (a smoke run, not the protocol).

- ``fig-VI-1`` (with VI.2): tabular Q-learning from a fixed start — mean reinforcement per
  episode and the trajectory after learning;
- ``fig-VI-4`` (with VI.3): the same with random starts and goals, four learned trajectories;
- ``table-VI-1``: episodes to converge for 9, 11, 13 states × 3 actions and 19 states × 5, and
  their rank correlation with the number of state–action pairs;
- ``fig-VI-8`` (VI.7): FQL, 15 rules × 3, fixed start, beside tabular Q-learning from the same
  start with the same exploration and learning rate; ``fig-VI-9`` (VI.10): random starts, steering then speed (the arrival speed measured);
  ``fig-VI-13`` (VI.14): 35 rules × 5, beside the 15 rules; ``fig-VI-16`` (VI.15): traces,
  beside FQL without;
- ``fig-VI-22`` (VI.18–VI.22): FQL obstacle avoidance from q = 0 (``--prior none``) —
  trajectories of training episodes 1 and 20, curves of both phases, the learned navigator in
  300 random worlds and along a wall to its goal (VI.21), against its initial table;
- ``fig-VI-24`` (VI.23): the chapter IV navigator and the learned one on a world whose straight
  route to the goal is blocked, side by side, with their success over 100 random worlds;
- ``fig-VI-29`` (VI.28–VI.30): the hand-made wall follower and the FQL-optimised one at two
  sharp corners and on 100 random wall courses.
"""

from __future__ import annotations

import json
from dataclasses import replace
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure
from scipy.stats import spearmanr

from fuzzynav import progress
from fuzzynav.catalog.tasks import load_controller
from fuzzynav.control.learned import LearnedAvoidanceNavigator
from fuzzynav.experiments import chapter6_worlds as worlds, evaluation, rule_bases
from fuzzynav.learn.checkpoint import load_checkpoint
from fuzzynav.learn.envs import RandomObstacles
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal, fql_wall, tabular_goal
from fuzzynav.learn.tasks.common import TrainRequest
from fuzzynav.sim import run_episode
from fuzzynav.viz.curves import plot_learning_curve
from fuzzynav.viz.trajectories import draw_world, plot_trajectory, save_in
from fuzzynav.world.scenario import load_scenario

TABLE_VI_1_EPISODES = 10_000  # the thesis' 8,950 plus a hold of 500 reachable
EARLY_EPISODES = (1, 20)  # Figs VI.18–VI.19
EVALUATION_RUNS = 100
AVOID_EVALUATION_RUNS = 300
"""Held-out obstacle worlds of fig-VI-22's claim: its target is no collision, and a learned avoider
that collides in about 1 % of worlds shows none in 100 worlds about a third of the time
(docs/results/chapter-vi.md, "The 0-collision bar on 300 fresh worlds")."""


def _request(out_dir, name: str, episodes, seed: int, **options) -> TrainRequest:
    return TrainRequest(out=Path(out_dir) / "models" / f"{name}-{seed}.json", task=name, episodes=episodes, seed=seed,
                        progress=progress.enabled(), **options)


def _curves(request, phases) -> dict:
    """Per-episode mean reinforcement of each phase, read back from its checkpoint."""
    return {p: common.episode_curve(load_checkpoint(common.checkpoint_path(request.out, p))["curve"], "mean_reward")
            for p in phases}


def _curve_ends(curves: dict) -> dict:
    """Mean reinforcement per episode over the first and the last tenth of each phase's curve."""
    ends = {}
    for phase, curve in curves.items():
        tenth = max(1, curve.size // 10)
        ends[phase] = {"first": round(float(curve[:tenth].mean()), 4), "last": round(float(curve[-tenth:].mean()), 4)}
    return ends


def _figure(curves: dict, converged: dict, controller, starts, title: str, out_dir, name: str,
            obstacles: bool = False, window: int = common.GOAL_CONVERGENCE["window"]) -> dict:
    """Learning curves (one panel per phase, the training's episodes to converge marked) and
    trajectories of the learned controller, in a grid of at most three panels per row."""
    panels = len(curves) + len(starts)
    columns = min(3, panels)
    rows = -(-panels // columns)
    figure = Figure(figsize=(5.2 * columns, 4.6 * rows), layout="constrained")
    axes = figure.subplots(rows, columns, squeeze=False).ravel()
    for ax in axes[panels:]:
        ax.set_visible(False)
    budget = {phase: converged[phase]["episodes"] for phase in curves}
    converged = {phase: converged[phase]["converged_at"] for phase in curves}
    for ax, (phase, curve) in zip(axes, curves.items()):
        plot_learning_curve(curve, ax=ax, window=window, title=f"{title}: {phase}", label=phase,
                            converged_at=converged[phase] or len(curve) + 1)  # past the curve: not converged
    outcomes = []
    for ax, scenario in zip(axes[len(curves):], starts):
        trace = run_episode(scenario, controller)
        plot_trajectory(trace, scenario, ax, markers=obstacles)
        outcomes.append(trace.outcome)
    return {"figure": save_in(figure, out_dir, name), "converged_at": converged, "episodes": budget,
            "trajectories": outcomes, "curve": _curve_ends(curves)}


# -- tabular Q-learning (§VI.2) ----------------------------------------------------------------
def _q_run(out_dir, name, episodes, seed, n_states=13, n_actions=3, fixed=False, schedule="own"):
    """Tabular Q-learning under the thesis' protocol (one robot, episodes one by one); ``schedule``
    as :func:`~fuzzynav.learn.tasks.tabular_goal.q_goal_parts` takes it."""
    request = _request(out_dir, name, episodes, seed)
    env, learner, disc, steering = tabular_goal.q_goal_parts(n_states, n_actions, fixed, batch=common.THESIS["robots"],
                                                             schedule=schedule)
    result, _ = common.run_phases([common.Phase("steering", env, learner, episodes,
                                                common.checkpoint_path(request.out, "steering"))], request)
    phase = result["steering"]
    converged = phase["converged_at"] if phase["converged_at"] <= phase["episodes"] else None  # None: not within budget
    return request, tabular_goal.q_goal_controller(learner, disc, steering), {"episodes": phase["episodes"],
                                                                              "converged_at": converged}


def fig_vi_1(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.1–VI.2: tabular Q-learning, fixed start (thesis: converges from episode ~1000)."""
    request, controller, result = _q_run(out_dir, "q-goal-fixed", 500 if quick else 1500, seed, fixed=True)
    return _figure(_curves(request, ["steering"]), {"steering": result}, controller, worlds.fixed_scenario(),
                   "Q-learning, fixed start", out_dir, "fig-VI-1.png")


def fig_vi_4(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.3–VI.4: tabular Q-learning, random starts and goals (thesis: ~3,500 episodes)."""
    request, controller, result = _q_run(out_dir, "q-goal", 600 if quick else 3000, seed)
    numbers = _figure(_curves(request, ["steering"]), {"steering": result}, controller, worlds.goal_scenarios(seed),
                      "Q-learning, random starts", out_dir, "fig-VI-4.png")
    return {**numbers, "evaluation": evaluation.evaluate_goal(controller, 20 if quick else EVALUATION_RUNS)}


def rank_correlation(rows) -> float | None:
    """Spearman's ρ between the state–action pairs of Table VI.1's rows and their episodes to
    converge (a run that did not converge ranks after every converged one: budget + 1)."""
    pairs = [r["states"] * r["actions"] for r in rows]
    episodes = [r["episodes"] + 1 if r["episodes_to_converge"] is None else r["episodes_to_converge"] for r in rows]
    if len(set(episodes)) < 2:
        return None  # no order at all (e.g. nothing converged)
    return round(float(spearmanr(pairs, episodes).statistic), 4)


def table_vi_1(out_dir, quick=False, seed=0) -> dict:
    """Table VI.1: episodes to converge as the number of states (and actions) grows, with a
    budget of :data:`TABLE_VI_1_EPISODES` per size (the thesis' largest count reachable)."""
    rows = []
    for n_states, n_actions, thesis in ((9, 3, 3260), (11, 3, 4100), (13, 3, 6200), (19, 5, 8950)):
        _, controller, result = _q_run(out_dir, f"q-goal-{n_states}x{n_actions}",
                                       500 if quick else TABLE_VI_1_EPISODES, seed, n_states, n_actions)
        rows.append({"states": n_states, "actions": n_actions, "thesis_episodes": thesis,
                     "episodes": result["episodes"], "episodes_to_converge": result["converged_at"],
                     "success": evaluation.evaluate_goal(controller, 20 if quick else EVALUATION_RUNS)["success"]})
    figure = Figure(figsize=(9, 2.2), layout="constrained")
    ax = figure.add_subplot(111)
    ax.axis("off")
    here = lambda r: (f"not converged within {r['episodes']}" if r["episodes_to_converge"] is None
                      else r["episodes_to_converge"])
    table = ax.table(cellText=[[r["states"], r["actions"], r["thesis_episodes"], here(r), f"{r['success']:.0%}"]
                               for r in rows],
                     colLabels=["states", "actions", "thesis: episodes to converge", "here: episodes to converge",
                                "success on random goals"], colWidths=[0.1, 0.1, 0.27, 0.3, 0.23],
                     cellLoc="center", loc="center")
    table.auto_set_font_size(False)
    table.set_fontsize(10)
    table.scale(1.0, 1.6)
    return {"rows": rows, "rank_correlation": rank_correlation(rows), "figure": save_in(figure, out_dir, "table-VI-1.png")}


# -- fuzzy Q-learning goal seeking (§VI.5.1) ---------------------------------------------------
def _fql_goal(out_dir, task: fql_goal.GoalFQL, quick, episodes, seed, title, name, starts) -> dict:
    request = _request(out_dir, task.name + ("-fixed" if task.fixed else ""), episodes, seed)
    summary = fql_goal.train_goal_fql(task, request)
    controller = load_controller(request.out)
    phases = ["steering", "speed"] if task.learn_speed else ["steering"]
    numbers = _figure(_curves(request, phases), summary, controller, starts, title, out_dir, name)
    model = json.loads(Path(request.out).read_text())
    return {**numbers, "rules": model["rules"], "rules_changed": model["training"]["rules_changed"],
            "evaluation": evaluation.evaluate_goal(controller, 20 if quick else EVALUATION_RUNS)}


def _steering_converged(out_dir, task: fql_goal.GoalFQL, episodes: int, seed: int) -> dict:
    """Episodes to converge of ``task``'s steering phase alone (a comparison's other arm): the
    same episodes, seed and criterion as the steering phase of the task's own run."""
    task = replace(task, learn_speed=False)
    request = _request(out_dir, f"{task.name}-steering", episodes, seed)
    phases, _ = common.run_phases(fql_goal.goal_fql_phases(task, request.out, episodes), request)
    steering = common.summarise(phases)["steering"]
    return {"task": task.name, "episodes": steering["episodes"], "converged_at": steering["converged_at"]}


def _steering_budget(task: fql_goal.GoalFQL, quick: bool, quick_episodes: int) -> int:
    total = quick_episodes if quick else task.episodes
    return common.steering_episodes(total, common.SPEED_SHARE if task.learn_speed else 0.0)


def fig_vi_8(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.7–VI.8: FQL, 15 rules × 3, fixed start, steering only (thesis: ~180 episodes,
    faster than tabular Q-learning from the same start, Fig VI.1). The tabular learner beside it
    explores and learns with FQL's ε and β (the thesis gives neither, for either learner), so the
    two differ only in what they learn on: rules or states."""
    task = replace(fql_goal.GOAL_TASKS["fql-goal"], fixed=True, learn_speed=False)
    numbers = _fql_goal(out_dir, task, quick, 200 if quick else 1000, seed, "FQL 15 rules, fixed start",
                        "fig-VI-8.png", worlds.fixed_scenario())
    _, _, tabular = _q_run(out_dir, "q-goal-fixed-fql", 500 if quick else 1500, seed, fixed=True, schedule="fql")
    return {**numbers, "q_learning": tabular}


def fig_vi_9(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.9–VI.10: FQL, 15 rules × 3, random starts, steering then speed (thesis: ~3,000 /
    ~900; the robot "s'arrête lorsqu'il atteint la cible")."""
    return _fql_goal(out_dir, fql_goal.GOAL_TASKS["fql-goal"], quick, 400 if quick else None, seed, "FQL 15 rules",
                     "fig-VI-9.png", worlds.goal_scenarios(seed))


def fig_vi_13(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.13–VI.14: FQL on the chapter IV partition, 35 rules × 5 (thesis: ~5,000 episodes,
    slower than the 15 rules)."""
    task = fql_goal.GOAL_TASKS["fql-goal-35"]
    numbers = _fql_goal(out_dir, task, quick, 400 if quick else None, seed, "FQL 35 rules", "fig-VI-13.png",
                        worlds.goal_scenarios(seed))
    small = fql_goal.GOAL_TASKS["fql-goal"]
    return {**numbers, "rules_15": _steering_converged(out_dir, small, _steering_budget(small, quick, 400), seed)}


def fig_vi_16(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.15–VI.16: FQL 15 rules × 3 with eligibility traces (thesis: ~1,400 episodes,
    faster than FQL without, Fig VI.10)."""
    numbers = _fql_goal(out_dir, fql_goal.GOAL_TASKS["fql-goal-traces"], quick, 300 if quick else None, seed,
                        "FQL with eligibility traces", "fig-VI-16.png", worlds.goal_scenarios(seed))
    plain = fql_goal.GOAL_TASKS["fql-goal"]
    return {**numbers, "no_traces": _steering_converged(out_dir, plain, _steering_budget(plain, quick, 400), seed)}


# -- obstacle avoidance (§VI.5.2) --------------------------------------------------------------
class _EpisodeRecorder:
    """Records the outcome of the first training episodes of a phase, and the robot's path in
    some of them (Figs VI.18–VI.19): wraps its env's ``reset`` and ``step`` (row 0 of the batch:
    the thesis' single robot)."""

    def __init__(self, env, paths, upto: int):
        self.wanted, self.upto, self.count = set(paths), upto, 0
        self.paths, self.outcomes = {}, []
        self._reset, self._step = env.reset, env.step
        env.reset, env.step = self.reset, self.step
        self.env = env

    def reset(self, rng):
        observation = self._reset(rng)
        self.count += 1
        if self.count <= self.upto:
            self.outcomes.append("timeout")
        if self.count in self.wanted:
            state = self.env.state
            self.paths[self.count] = {"world": state.world, "goal": state.target[0].copy(),
                                      "xy": [state.pose[0, :2].copy()], "start": state.pose[0].copy()}
        return observation

    def step(self, action, rng):
        out = self._step(action, rng)
        info = out[4]
        if self.count in self.paths:
            self.paths[self.count]["xy"].append(self.env.state.pose[0, :2].copy())
        if self.count <= self.upto and self.outcomes[-1] == "timeout":
            self.outcomes[-1] = ("collision" if info["collision"][0] else "reached" if info["success"][0]
                                 else "timeout")
        return out


def _avoid_model(out_dir, quick, seed, prior: str = "none"):
    """Train fql-avoid under the thesis' protocol from ``prior``; returns the request, the
    learned navigator, the train summary and the paths of training episodes 1 and 20."""
    request = _request(out_dir, f"fql-avoid-{prior}", 400 if quick else None, seed, prior=prior)
    recorders = {}

    def watch(phase):
        if phase.name == "steering":
            recorders[phase.name] = _EpisodeRecorder(phase.env, EARLY_EPISODES, max(EARLY_EPISODES))

    summary = fql_avoid.train_fql_avoid(request, watch=watch)
    return request, load_controller(request.out), summary, recorders["steering"]


def initial_avoider(prior: str = "none") -> LearnedAvoidanceNavigator:
    """The navigator of fql-avoid's initial table (:func:`~fuzzynav.learn.tasks.fql_avoid.initial_tables`),
    i.e. what learning starts from (``none``: every rule Z at the middle speed)."""
    steering, speed = fql_avoid.initial_tables(prior)
    learned = fql_avoid.free_rules()[0]
    system = fql_avoid.avoid_system(np.asarray(steering)[:learned], np.full(learned, speed))
    return LearnedAvoidanceNavigator(system, constant_speed=fql_avoid.AVOID_SPEED, name=f"fql-avoid initial ({prior})")


def _training_panel(ax, path, episode: int, outcome: str) -> None:
    scenario = evaluation.scenario_of(path["world"], path["start"], path["goal"], f"episode {episode}", 60.0)
    draw_world(ax, scenario)
    xy = np.array(path["xy"])
    ax.plot(xy[:, 0], xy[:, 1], color="tab:blue", linewidth=1.8, label="robot (exploring)")
    if outcome == "collision":
        ax.plot(*xy[-1], "rX", markersize=12, label="collision")
    ax.set_title(f"training episode {episode}: {outcome}")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.12), ncol=3, fontsize=8)


def fig_vi_22(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.18–VI.22: FQL avoidance learned from q = 0 (``--prior none``) — training episodes
    1 and 20, curves of steering and speed, the learned navigator in random worlds and along a
    wall to its goal (Fig VI.21), and the initial table in the same worlds (thesis: collisions
    early, steering converged by ~250 episodes, speed by ~2,000)."""
    request, controller, summary, early = _avoid_model(out_dir, quick, seed)
    runs = 20 if quick else AVOID_EVALUATION_RUNS
    figure = Figure(figsize=(11, 5.8), layout="constrained")
    for ax, episode in zip(figure.subplots(1, 2), EARLY_EPISODES):
        _training_panel(ax, early.paths[episode], episode, early.outcomes[episode - 1])
    training_figure = save_in(figure, out_dir, "fig-VI-18-19.png")
    window = common.convergence_window(common.WORLD_CONVERGENCE, common.THESIS["robots"])[0]
    numbers = _figure(_curves(request, ["steering", "speed"]), summary, controller,
                      worlds.goal_scenarios(seed, 3, layout=RandomObstacles()) + [worlds.wall_to_goal_scenario()],
                      "FQL obstacle avoidance", out_dir, "fig-VI-22.png", obstacles=True, window=window)
    model = json.loads(Path(request.out).read_text())
    return {**numbers, "training_figure": training_figure, "wall_following": numbers["trajectories"][-1],
            "early_episodes": {str(k): early.outcomes[k - 1] for k in EARLY_EPISODES},
            f"collisions_first_{max(EARLY_EPISODES)}": early.outcomes.count("collision"),
            "rules_changed": model["training"]["rules_changed"], "rules_learned": model["training"]["rules_learned"],
            "rules": model["rules"], "evaluation": evaluation.evaluate_avoid(controller, runs),
            "initial_table": evaluation.evaluate_avoid(initial_avoider(), runs)}


def fig_vi_24(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.23–VI.24: the chapter IV fuzzy navigator (fuzzy-2b-thesis) and the FQL navigator
    learned from q = 0 on the same world, one whose straight route is blocked, and both over
    the same random worlds."""
    _, learned, _, _ = _avoid_model(out_dir, quick, seed)
    fuzzy = rule_bases.controller("fuzzy-2b-thesis")  # with the --fis replacements of its tables
    scenario = worlds.blocked_scenario(seed)
    figure = Figure(figsize=(11, 5.5), layout="constrained")
    numbers = {}
    for ax, (name, controller) in zip(figure.subplots(1, 2), (("fuzzy-2b-thesis, hand-made (Fig VI.23)", fuzzy),
                                                               ("FQL learned from q = 0 (Fig VI.24)", learned))):
        trace = run_episode(scenario, controller)
        plot_trajectory(trace, scenario, ax)
        ax.set_title(f"{name}: {trace.outcome}")
        numbers[name] = {"outcome": trace.outcome,
                         "evaluation": evaluation.evaluate_avoid(controller, 20 if quick else EVALUATION_RUNS)}
    return {**numbers, "world": scenario.name, "figure": save_in(figure, out_dir, "fig-VI-24.png")}


# -- wall following (§VI.5.3) ------------------------------------------------------------------
def _corner_outcomes(controller, corners) -> dict:
    return {scenario.name: run_episode(scenario, controller).outcome for scenario in corners}


def fig_vi_29(out_dir, quick=False, seed=0) -> dict:
    """Figs VI.28–VI.30: the hand-made follower collides at sharp corners; the FQL-optimised one
    (Table VI.2's rules, learned interpretations, the same single rays at −90°, 0°, +90°)
    goes round both corners to the goal along the wall, and collides on at most a fifth as many
    random wall courses."""
    request = _request(out_dir, "fql-wall", 300 if quick else None, seed)
    fql_wall.train_fql_wall(request)
    learned, handmade = load_controller(request.out), rule_bases.controller("wall-follow")
    corners = (load_scenario("fig-VI-28"), worlds.second_corner())
    course = evaluation.wall_course_scenario(np.random.default_rng(seed + 1000), "wall course")
    figure = Figure(figsize=(16, 11), layout="constrained")
    axes = figure.subplots(2, 3)
    for row, (name, controller) in zip(axes, (("wall-follow (Table VI.2)", handmade), ("FQL-optimised", learned))):
        for ax, scenario in zip(row, corners + (course,)):
            trace = run_episode(scenario, controller, max_time=30.0 if scenario is course else None)
            plot_trajectory(trace, scenario, ax, markers=False)
            ax.set_title(f"{name}, {scenario.name}: {trace.outcome}")
    courses = 10 if quick else EVALUATION_RUNS
    model = json.loads(Path(request.out).read_text())
    return {"corners": {"wall-follow": _corner_outcomes(handmade, corners),
                        "fql-wall": _corner_outcomes(learned, corners)},
            "evaluation": {"wall-follow": evaluation.evaluate_wall(handmade, courses),
                           "fql-wall": evaluation.evaluate_wall(learned, courses)},
            "rules": model["rules"], "sensing": model["sensing"],
            "rules_changed": model["training"]["rules_changed"], "figure": save_in(figure, out_dir, "fig-VI-29.png")}
