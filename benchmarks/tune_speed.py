"""Episodes per second of the tuner's fitness: a population × its worlds in compiled calls
(:mod:`fuzzynav.tune.episodes`) on one thread and on one thread per core (:mod:`fuzzynav.threads`,
``--rounds`` rounds alternating the two, the ratio the median of the rounds' ratios), against the
same episodes through ``BatchSimulator`` one world at a time (the Python step loop ``run``,
``evaluate`` and ``bench`` use). All run the candidates around the hand-made system that a
tuning's first generation holds; the outcomes are checked equal.

    python benchmarks/tune_speed.py --target fuzzy-2b:oab --worlds mixed:40 --population 10 [--rounds 5]
"""

from __future__ import annotations

import statistics
import time

import numpy as np

from fuzzynav import threads
from fuzzynav.catalog.roles import make_with_systems
from fuzzynav.cli import Parser
from fuzzynav.sim import BatchSimulator
from fuzzynav.tune.episodes import OUTCOME, STEPS
from fuzzynav.tune.fitness import Fitness
from fuzzynav.tune.session import TuneRequest, check
from fuzzynav.tune.space import SearchSpace


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--target", default="fuzzy-2b:oab")
    parser.add_argument("--worlds", default="mixed:40")
    parser.add_argument("--population", type=int, default=10)
    parser.add_argument("--rounds", type=int, default=5, help="rounds of one thread against one per core")
    args = parser.parse_args()
    request = TuneRequest(target=args.target, worlds=args.worlds, population=args.population, budget=10**6)
    controller, system, suite, _ = check(request)
    scenarios = [suite.scenario(i, 0) for i in range(suite.size)]
    space = SearchSpace(system, "both")
    population = space.around_start(args.population, np.random.default_rng(0))
    fitness = Fitness(controller, request.role, space, scenarios)
    fitness.simulate(population[:1])  # compile
    cores, times, outs = threads.cores(), {1: [], threads.cores(): []}, []
    for _ in range(args.rounds):
        for count in times:
            threads.set_count(count)
            started = time.perf_counter()
            outs.append(fitness.simulate(population))
            times[count].append(time.perf_counter() - started)
    threads.set_count(1)
    out = outs[0]
    same_threads = all(np.array_equal(o, out) for o in outs)
    batched = statistics.median(times[1])
    spread = statistics.median(times[cores])
    ratio = statistics.median(a / b for a, b in zip(times[1], times[cores]))
    started = time.perf_counter()
    outcomes = []
    for genes in population:
        systems = {request.role: space.decode(genes)}
        for scenario in scenarios:
            sim = BatchSimulator(scenario, make_with_systems(request.controller, systems), record=False, seed=0).run()
            outcomes.append((int(sim.status[0]), int(sim.steps[0])))
    looped = time.perf_counter() - started
    same = outcomes == [(int(o), int(k)) for o, k in out.reshape(-1, out.shape[-1])[:, [OUTCOME, STEPS]]]
    episodes, steps = out.shape[0] * out.shape[1], int(out[:, :, STEPS].sum())
    print(f"{args.target} on {args.worlds}, {args.population} candidates: {episodes} episodes, {steps} steps")
    print(f"  compiled, 1 thread: {batched:6.2f} s  {episodes / batched:7.1f} episodes/s  "
          f"{1e6 * batched / steps:5.1f} µs/step")
    print(f"  compiled, {cores} threads: {spread:6.2f} s  {episodes / spread:7.1f} episodes/s  "
          f"(x{ratio:.2f} the one thread, median of {args.rounds} rounds; same rows: {same_threads})")
    print(f"  BatchSimulator    : {looped:6.2f} s  {episodes / looped:7.1f} episodes/s  "
          f"{1e6 * looped / steps:5.1f} µs/step  (x{looped / batched:.1f})")
    print(f"  same outcomes and steps: {same}")


if __name__ == "__main__":
    main()
