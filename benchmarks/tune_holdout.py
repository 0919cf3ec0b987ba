"""Why a tuned obstacle avoider can do worse on held-out worlds than Table IV.2: the start, random
neighbours of it (the moves of a tuner's first population, :meth:`SearchSpace.around_start`) and
tuned files, world by world (docs/tuning.md, *The acceptance run*)::

    python benchmarks/tune_holdout.py --neighbours 30 --suites mixed:100:1000 mixed:100:3000
    python benchmarks/tune_holdout.py --neighbours 30 --spread 0.03 --repick 0.03 --suites mixed:100:3000
    python benchmarks/tune_holdout.py --files oab.yaml --suites mixed:40 mixed:100:1000
    python benchmarks/tune_holdout.py --files oab-0.yaml oab-1.yaml --suites mixed:1000:1000 mixed:1000:7000 --paired

prints, per suite, the success of the start, the mean success of the neighbours, the share of them
that reach every goal and how many of them fail each world; then each file's success, mean time and
failed worlds. ``--paired`` compares each file with the start world by world instead of listing the
failed worlds (for pools too large to list): the worlds only it reaches, those only the start
reaches (a difference in success is sampling noise unless it is large against their sum: McNemar's
test), and both mean times over the worlds both reach.
"""

from __future__ import annotations

import numpy as np

import fuzzynav.tune.space as space_module
from fuzzynav.bench.suites import parse_suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.catalog.roles import default_system
from fuzzynav.cli import Parser
from fuzzynav.fuzzy.io import load
from fuzzynav.kernels.step import REACHED
from fuzzynav.tune.episodes import OUTCOME, STEPS
from fuzzynav.tune.fitness import Fitness
from fuzzynav.tune.space import SearchSpace


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--target", default="fuzzy-2b:oab")
    parser.add_argument("--suites", nargs="+", required=True)
    parser.add_argument("--neighbours", type=int, default=0)
    parser.add_argument("--what", default="both")
    parser.add_argument("--spread", type=float, default=space_module.SPREAD)
    parser.add_argument("--repick", type=float, default=space_module.REPICK)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--files", nargs="*", default=[])
    parser.add_argument("--paired", action="store_true")
    args = parser.parse_args()
    controller, role = args.target.split(":")
    space = SearchSpace(default_system(controller, role), args.what)
    space_module.SPREAD, space_module.REPICK = args.spread, args.repick
    genes = space.around_start(args.neighbours + 1, np.random.default_rng(args.seed)) if args.neighbours \
        else space.start[None]
    for spec in args.suites:
        suite = parse_suite(spec)
        fitness = Fitness(make_controller(controller), role, space, [suite.scenario(i, 0) for i in range(suite.size)])
        rows = fitness.simulate(genes)
        reached = rows[:, :, OUTCOME] == REACHED
        print(f"{spec}: start {reached[0].mean():.3f}", end="")
        if args.neighbours:
            print(f"; {args.neighbours} neighbours ({args.what}, spread {args.spread}, repick {args.repick}): mean "
                  f"{reached[1:].mean():.4f}, share at 100 % {reached[1:].all(axis=1).mean():.2f}; neighbours "
                  f"failing each world: {dict((i, int(n)) for i, n in enumerate((~reached[1:]).sum(axis=0)) if n)}",
                  end="")
        print()
        for path in args.files:
            out = fitness.worlds.run(fitness.tables(load(path))[None],
                                     np.column_stack([np.zeros(suite.size, dtype=np.int64), np.arange(suite.size)]))
            numbers = fitness.summary(out)
            print(f"  {path}: success {numbers['success_rate']:.3f}, collisions {numbers['collisions']}, mean time "
                  f"{numbers['mean_time_s']:.2f} s, ", end="")
            if args.paired:
                print(_paired(out, rows[0], fitness.worlds.dt))
            else:
                print(f"failed {[i for i in range(suite.size) if out[i, OUTCOME] != REACHED]}")


def _paired(rows: np.ndarray, start: np.ndarray, dt: np.ndarray) -> str:
    """A file's episodes against the start's on the same worlds: discordant arrivals, paired times."""
    mine, theirs = rows[:, OUTCOME] == REACHED, start[:, OUTCOME] == REACHED
    both = mine & theirs
    return (f"reached by it alone {int((mine & ~theirs).sum())}, by the start alone {int((theirs & ~mine).sum())}; "
            f"mean time where both reach {(rows[both, STEPS] * dt[both]).mean():.2f} s against the start's "
            f"{(start[both, STEPS] * dt[both]).mean():.2f} s")


if __name__ == "__main__":
    main()
