"""Fuzzy Q-learning against stable-baselines3 (PPO, SAC, DQN) on the same Gymnasium tasks.

Every agent trains on the same environment (``fuzzynav/GoalSeeking-v0``,
``fuzzynav/ObstacleAvoidance-v0``), the same thesis reward (``reward="thesis"``), the same
budget of environment steps, for the same seeds; at the same step counts (``--checkpoints``,
denser early on) its greedy policy runs the same held-out episodes (:func:`fuzzynav.gym.evaluate.success_rate`):

- goal seeking: 100 random starts and goals in the empty workspace, sub-environment seeds
  10,000 + i (training draws from seeds 0 … 7 + 100 × seed);
- obstacle avoidance: training on the ``circles`` family (pool of 1,000, ``world_seed`` 0),
  evaluation on the first 100 worlds of ``world_seed`` 1 — worlds never seen in training.

PPO and SAC act in the continuous Box, DQN in the Discrete set of the thesis' candidate actions,
FQL through :class:`fuzzynav.gym.fql_agent.FQLAgent` — on obstacle avoidance the thesis' method
(:mod:`fuzzynav.gym.fql_avoid`: the avoider inside its goal navigator) twice: ``fql`` from the
a-priori conclusions (its success before any learning is that of the priors and the navigator)
and ``fql-none`` from q = 0 (every rule neutral until learned: deep RL compared with learning, not
with a hand-written table). PPO and FQL gather with 8 robots in
parallel, SAC and DQN with one (their usual set-up); hyper-parameters are the library's defaults
except where the small budget needs otherwise (listed in :data:`SB3_SETTINGS`). Wall time is
the training time alone (evaluations excluded), one thread for torch. Every evaluation also
records the training episodes finished so far, for the episodes to 90 %.

Needs the ``sb3`` extra (stable-baselines3 and a CPU torch). Writes ``OUT.json`` (every curve
of every seed), ``OUT.png`` (success against steps, mean ± std over seeds) and prints the
table of the README::

    python benchmarks/rl_compare.py --tasks goal avoid --seeds 5 --steps 20000 --out rl_compare

(or one process per task and agent group, then ``--merge A.json B.json … --out rl_compare``).
"""

from __future__ import annotations

import json
import os
import time
from pathlib import Path

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.gym import FuzzynavEnv, FuzzynavVectorEnv
from fuzzynav.gym.evaluate import success_rate
from fuzzynav.gym.fql_agent import FQLAgent
from fuzzynav.gym.sources import FamilySource

TRAIN_OPTIONS = {"goal": {}, "avoid": {"worlds": "circles", "n_worlds": 1000, "world_seed": 0}}
N_PARALLEL = 8
SB3_SETTINGS = {
    "ppo": {"n_steps": 256, "batch_size": 64},  # rollouts of 8 × 256 steps (default 2,048 each)
    "sac": {},
    "dqn": {"target_update_interval": 1000, "learning_starts": 1000},  # default 10,000: a third of the budget
}
TARGET = 0.9
CHECKPOINTS = (500, 1000, 2000, 3000, 5000, 7500, 10000, 15000, 20000, 30000, 50000, 100000)


def held_out(task: str) -> dict:
    """Arguments of :func:`success_rate` for the held-out episodes of ``task``."""
    if task == "avoid":
        pool = FamilySource("circles", 100, world_seed=1)
        return {"scenarios": [pool.world(i) for i in range(100)], "seed": 10_000}
    return {"seed": 10_000}


def evaluate(policy, task: str, discrete: bool, held: dict) -> float:
    return success_rate(policy, task, episodes=100, actions="discrete" if discrete else "continuous",
                        **TRAIN_OPTIONS[task], **held)["success"]


class Clock:
    """Training time between evaluations, the step counts still to evaluate at, and the number of
    training episodes finished so far (``episodes``, counted by the caller)."""

    def __init__(self, checkpoints):
        self.pending = list(checkpoints)
        self.train = 0.0
        self.since = time.perf_counter()
        self.curve = []  # (environment steps, finished training episodes, held-out success)
        self.episodes = 0

    def due(self, steps: int) -> bool:
        return bool(self.pending) and steps >= self.pending[0]

    def record(self, steps: int, success) -> None:
        """Stop the training clock, evaluate (``success()``), restart the clock."""
        self.train += time.perf_counter() - self.since
        self.curve.append((int(steps), int(self.episodes), success()))
        while self.pending and steps >= self.pending[0]:
            self.pending.pop(0)
        self.since = time.perf_counter()


def run_fql(task, seed, steps, checkpoints, held, prior="thesis"):
    clock = Clock(checkpoints)

    def checkpoint(agent, done):
        clock.episodes = agent.episodes_
        if clock.due(done):
            clock.record(done, lambda: evaluate(agent.predict, task, False, held))

    env = FuzzynavVectorEnv(N_PARALLEL, task, **TRAIN_OPTIONS[task])
    agent = FQLAgent(task, prior=prior)
    if clock.due(0):  # the untrained controller: learn() of 0 steps sets up the initial rules
        clock.record(0, lambda: evaluate(agent.learn(env, 0, seed=100 * seed).predict, task, False, held))
    agent.learn(env, steps, seed=100 * seed, callback=checkpoint)  # from scratch
    return clock.curve, clock.train


def run_sb3(algo, task, seed, steps, checkpoints, held):
    import torch
    from stable_baselines3 import DQN, PPO, SAC
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.env_util import make_vec_env

    torch.set_num_threads(1)
    discrete = algo == "dqn"
    n_envs = N_PARALLEL if algo == "ppo" else 1
    env = make_vec_env(lambda: FuzzynavEnv(task, actions="discrete" if discrete else "continuous",
                                           **TRAIN_OPTIONS[task]), n_envs=n_envs, seed=100 * seed)
    model = {"ppo": PPO, "sac": SAC, "dqn": DQN}[algo]("MlpPolicy", env, seed=seed, verbose=0, device="cpu",
                                                     **SB3_SETTINGS[algo])
    clock = Clock(checkpoints)

    class Checkpoints(BaseCallback):
        def _on_step(self):
            clock.episodes += int(np.sum(self.locals["dones"]))
            if clock.due(self.num_timesteps):
                clock.record(self.num_timesteps, lambda: evaluate(
                    lambda o: model.predict(o, deterministic=True)[0], task, discrete, held))
            return True

    if clock.due(0):
        clock.record(0, lambda: evaluate(lambda o: model.predict(o, deterministic=True)[0], task, discrete, held))
    model.learn(steps, callback=Checkpoints())
    return clock.curve, clock.train


def reach_target(curve, target=TARGET):
    """(steps, training episodes) at the first evaluation with success ≥ ``target`` (None if never)."""
    return next(((steps, episodes) for steps, episodes, success in curve if success >= target), None)


def summarise(runs: list[dict]) -> dict:
    """Final success (mean, std over seeds) and the median steps / episodes to 90 % over the seeds
    that reach it (reported only when most seeds do)."""
    finals = np.array([r["curve"][-1][2] for r in runs])
    hit = [point for point in (reach_target(r["curve"]) for r in runs) if point is not None]
    most = len(hit) * 2 > len(runs)
    return {"final_mean": float(finals.mean()), "final_std": float(finals.std()),
            "steps_to_90_median": float(np.median([s for s, _ in hit])) if most else None,
            "episodes_to_90_median": float(np.median([e for _, e in hit])) if most else None,
            "seeds_reaching_90": len(hit), "seeds": len(runs),
            "wall_time_mean_s": float(np.mean([r["train_seconds"] for r in runs]))}


def table(results: dict) -> str:
    lines = ["| task | agent | episodes to 90 % (median) | steps to 90 % (median) | seeds reaching 90 % "
             "| final success (mean ± std) | train time (s) |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for task, algos in results.items():
        for algo, runs in algos.items():
            s = summarise(runs)
            steps, episodes = ("—" if s[key] is None else f"{s[key]:,.0f}"
                               for key in ("steps_to_90_median", "episodes_to_90_median"))
            lines.append(f"| {task} | {algo.upper()} | {episodes} | {steps} | {s['seeds_reaching_90']}/{s['seeds']} | "
                         f"{s['final_mean']:.2f} ± {s['final_std']:.2f} | {s['wall_time_mean_s']:.0f} |")
    return "\n".join(lines)


def plot(results: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(1, len(results), figsize=(6.0 * len(results), 4.0), squeeze=False)
    for ax, (task, algos) in zip(axes[0], results.items()):
        for algo, runs in algos.items():
            steps = np.array([point[0] for point in runs[0]["curve"]])
            success = np.array([[point[2] for point in r["curve"]][: len(steps)] for r in runs])
            mean, std = success.mean(axis=0), success.std(axis=0)
            ax.plot(steps, mean, label=algo.upper())
            ax.fill_between(steps, mean - std, mean + std, alpha=0.2)
        ax.axhline(TARGET, color="0.5", linestyle=":", linewidth=1)
        ax.set_title({"goal": "GoalSeeking-v0", "avoid": "ObstacleAvoidance-v0"}[task])
        ax.set_xlabel("environment steps")
        ax.set_ylabel("success on 100 held-out episodes")
        ax.set_ylim(-0.02, 1.02)
        ax.legend()
    figure.savefig(path, dpi=120, bbox_inches="tight")
    plt.close(figure)


def main(argv=None) -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tasks", nargs="+", default=["goal", "avoid"], choices=sorted(TRAIN_OPTIONS))
    parser.add_argument("--algos", nargs="+", default=["fql", "fql-none", "ppo", "sac", "dqn"],
                        choices=["fql", "fql-none", "ppo", "sac", "dqn"],
                        help="fql: FQL from the a-priori avoidance table (--prior thesis); fql-none: FQL from q = 0 "
                             "(--prior none; on goal seeking the same as fql)")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--first-seed", type=int, default=0, help="run seeds FIRST … FIRST + SEEDS − 1")
    parser.add_argument("--steps", type=int, default=20_000, help="environment steps per run")
    parser.add_argument("--checkpoints", type=int, nargs="+", default=list(CHECKPOINTS),
                        help="step counts to evaluate at (those beyond --steps are dropped; --steps is added; "
                             "0: the untrained policy, e.g. FQL's a-priori rules)")
    parser.add_argument("--out", type=Path, default=Path("rl_compare"), help="writes OUT.json and OUT.png")
    parser.add_argument("--merge", type=Path, nargs="+", metavar="JSON",
                        help="only combine the results of earlier runs (e.g. one per task or agent) into OUT")
    args = parser.parse_args(argv)
    if args.merge:
        results = {}
        for path in args.merge:  # runs of the same task and agent are pooled, one per seed
            for task, algos in json.loads(path.read_text())["results"].items():
                for algo, runs in algos.items():
                    pooled = {r["seed"]: r for r in results.setdefault(task, {}).get(algo, []) + runs}
                    results[task][algo] = [pooled[seed] for seed in sorted(pooled)]
        args.out.with_suffix(".json").write_text(json.dumps({"merged": [str(p) for p in args.merge],
                                                             "results": results}, indent=1))
        plot(results, args.out.with_suffix(".png"))
        print(table(results))
        return
    checkpoints = sorted({c for c in args.checkpoints if c < args.steps} | {args.steps})
    results = {}
    for task in args.tasks:
        held = held_out(task)
        results[task] = {}
        for algo in args.algos:
            results[task][algo] = []
            for seed in range(args.first_seed, args.first_seed + args.seeds):
                if algo in ("fql", "fql-none"):
                    prior = "none" if algo == "fql-none" else "thesis"
                    curve, seconds = run_fql(task, seed, args.steps, checkpoints, held, prior)
                else:
                    curve, seconds = run_sb3(algo, task, seed, args.steps, checkpoints, held)
                results[task][algo].append({"seed": seed, "curve": curve, "train_seconds": seconds})
                print(f"{task} {algo} seed {seed}: final success {curve[-1][2]:.2f}, "
                      f"(steps, episodes) to 90 %: {reach_target(curve)}, {seconds:.0f} s", flush=True)
                partial = args.out.with_suffix(".json.tmp")
                partial.write_text(json.dumps({"args": {k: str(v) for k, v in vars(args).items()},
                                               "results": results}, indent=1))
                os.replace(partial, args.out.with_suffix(".json"))
    plot(results, args.out.with_suffix(".png"))
    print(table(results))


if __name__ == "__main__":
    main()
