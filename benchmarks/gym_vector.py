"""Steps per second of the batched vector environment against ``gymnasium.vector.SyncVectorEnv``.

Both step the same environment (``FuzzynavVectorEnv(n, task, **options)`` against
``SyncVectorEnv`` of n ``FuzzynavEnv(task, **options)``), with the same seeded random actions
and autoreset, in interleaved rounds (the median of ``--rounds`` is reported, so both see the same
machine load). One step of the vector environment moves every robot one decision (the task's
``decision_steps`` of 0.1 s); steps/s counts robot decisions::

    python benchmarks/gym_vector.py --robots 64 --steps 200 --rounds 5
"""

from __future__ import annotations

import statistics
import time

import gymnasium

from fuzzynav.cli import Parser
from fuzzynav.gym import FuzzynavEnv, FuzzynavVectorEnv

CASES = {
    "GoalSeeking (empty workspace)": ("goal", {}),
    "ObstacleAvoidance, scenario fig-IV-22a": ("avoid", {"scenario": "fig-IV-22a"}),
    "ObstacleAvoidance, circles pool of 8 worlds": ("avoid", {"worlds": "circles", "n_worlds": 8}),
    "ObstacleAvoidance, a new random world per episode": ("avoid", {}),
    "WallFollowing, a new course per episode": ("wall", {}),
    "PathTracking, a new path per episode": ("path", {}),
}


def rate(env, actions) -> float:
    """Robot decisions per second over ``actions`` (the env already reset)."""
    start = time.perf_counter()
    for action in actions:
        env.step(action)
    return len(actions) * env.num_envs / (time.perf_counter() - start)


def measure(task: str, options: dict, robots: int, steps: int, rounds: int) -> tuple[float, float]:
    """(median steps/s of the batched env, of SyncVectorEnv)."""
    batched = FuzzynavVectorEnv(robots, task, **options)
    sync = gymnasium.vector.SyncVectorEnv([lambda: FuzzynavEnv(task, **options) for _ in range(robots)])
    batched.action_space.seed(0)
    actions = [batched.action_space.sample() for _ in range(steps)]
    rates = {"batched": [], "sync": []}
    for _ in range(rounds):
        for name, env in (("batched", batched), ("sync", sync)):
            env.reset(seed=0)
            rates[name].append(rate(env, actions))
    return statistics.median(rates["batched"]), statistics.median(rates["sync"])


def main(argv=None) -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--robots", type=int, default=64)
    parser.add_argument("--steps", type=int, default=200, help="vector steps per round")
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args(argv)
    print(f"| environment ({args.robots} robots) | FuzzynavVectorEnv steps/s | SyncVectorEnv steps/s | ratio |")
    print("| --- | --- | --- | --- |")
    for label, (task, options) in CASES.items():
        batched, sync = measure(task, options, args.robots, args.steps, args.rounds)
        print(f"| {label} | {batched:,.0f} | {sync:,.0f} | {batched / sync:.1f}× |", flush=True)


if __name__ == "__main__":
    main()
