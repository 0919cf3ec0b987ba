"""``fuzzynav train TASK [--episodes N] [--seed S] [--out FILE] [--resume] [--parallel N] [--prior P]`` — train a controller.

Reinforcement-learning tasks follow the thesis' protocol by default (one robot, one episode after
another); ``--parallel N`` trains N robots per batch on one rule base (faster; its curves count
episodes in batches of N). ``--prior`` (fql-avoid): the initial table, ``none`` (every q = 0, the
conclusion of best quality extracted: the thesis') or ``thesis`` (the a-priori avoidance table of
§IV.7's principle, kept unless a learned conclusion beats it clearly).
"""

from __future__ import annotations

import json
import sys
from functools import partial
from pathlib import Path

from fuzzynav import progress, validation
from fuzzynav.catalog import tasks
from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError
from fuzzynav.learn.tasks.common import GOAL_CONVERGENCE, PhaseSummary, TrainRequest, checkpoint_path
from fuzzynav.storage import document_format

PHASE_NOTE = ("success: the share of the last training episodes that reached the goal (a wall follower's: "
              "that lasted without collision), exploration still on; not converged: no plateau of the mean "
              "reward per episode held for the criterion's whole hold before the budget ended (more --episodes "
              "may show one, which may begin before this run's end)")
"""What the words of a phase's line (:class:`~fuzzynav.learn.tasks.common.PhaseSummary`) mean, said once after them."""

PRIORS = ("none", "thesis")
MAX_PARALLEL = 1000  # robots per batch of --parallel (a batch of 1,000 already fills a core for seconds)
# the reinforcement-learning tasks: --parallel, and --resume from checkpoints (the trackers train in one pass)
PARALLEL_TASKS = ("q-goal", "fql-goal", "fql-goal-35", "fql-goal-traces", "fql-avoid", "fql-wall")
CHECKPOINT_EVERY = 100  # episodes: the checkpoints of a reinforcement-learning run when none is asked
# tasks whose convergence is read on windows of episodes (learn.curves): a batch must divide them
GOAL_TASKS = ("q-goal", "fql-goal", "fql-goal-35", "fql-goal-traces")


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "train", run,
                               help=help_line("train"),
                               description="Train a learning controller and write its model file (atomically). Tasks: "
                               + ", ".join(f"{name} ({text})" for name, text in tasks.available().items()),
                               example="""
fuzzynav train anfis-tracker --out anfis.json
fuzzynav train fql-goal --episodes 3000 --seed 0 --out fql.npz --curve fql.png
fuzzynav train fql-goal --episodes 6000 --out fql.npz --resume   # 3000 more, to 6000 in all""")
    parser.add_argument("task", metavar="TASK", help="training task name")
    parser.add_argument("--episodes", type=arguments.whole,
                        help=f"number of episodes / epochs in all, 1 to {validation.MAX_EPISODES:,} (task default); "
                             "a task learned in two phases, steering then speed, gives the speed phase a quarter "
                             "(fql-goal, fql-goal-35, fql-wall) or a half (fql-avoid)")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (default 0)")
    parser.add_argument("--out", type=arguments.path, help="model file to write, .json or .npz (default TASK.json)")
    parser.add_argument("--resume", action="store_true", help="continue from the checkpoint of --out")
    parser.add_argument("--checkpoint-every", type=arguments.whole, metavar="K",
                        help=f"write a checkpoint every K episodes, 1 to {validation.MAX_EPISODES:,} (reinforcement "
                             f"learning: default {CHECKPOINT_EVERY}, so that --resume goes on after Ctrl-C; the "
                             "trackers train in one go)")
    parser.add_argument("--curve", type=arguments.figure_path, help="write the learning curve plot (PNG; any "
                        "suffix matplotlib writes, checked before training)")
    parser.add_argument("--parallel", type=arguments.count(MAX_PARALLEL), metavar="N",
                        help="reinforcement learning: N robots per batch sharing one rule base, 1 to "
                             f"{MAX_PARALLEL:,}; for the goal tasks a divisor of 50 (default: the thesis' one "
                             "robot, episodes one by one)")
    parser.add_argument("--prior", choices=PRIORS,
                        help="fql-avoid: initial table, none (q = 0, best-quality extraction; default) or thesis")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--json", action="store_true", help="print the results as one JSON object")


def run(args) -> int:
    train = tasks.trainer(args.task)
    for flag, value in (("--episodes", args.episodes), ("--checkpoint-every", args.checkpoint_every)):
        if value is not None:
            validation.integer(value, field=flag, lo=1, hi=validation.MAX_EPISODES)
    if args.parallel is not None:  # its type checked the range
        if args.task not in PARALLEL_TASKS:
            raise InputError(f"only for {', '.join(PARALLEL_TASKS)}, not {args.task}", field="--parallel")
        window = int(GOAL_CONVERGENCE["window"])
        if args.task in GOAL_TASKS and window % args.parallel:
            divisors = [str(k) for k in range(1, window + 1) if window % k == 0]
            raise InputError(f"for {args.task}, N must divide the convergence window of {window} episodes "
                             f"({', '.join(divisors[:-1])} or {divisors[-1]}), got {args.parallel}", field="--parallel")
    if args.prior is not None and args.task != "fql-avoid":
        raise InputError(f"only for fql-avoid, not {args.task}", field="--prior")
    out = args.out or Path(f"{args.task}.json")
    if args.task in PARALLEL_TASKS:
        args.when_stopped = (f"the same command with --resume goes on from the last checkpoint "
                             f"({checkpoint_path(out, 'PHASE').name.replace('PHASE', '…')})")
    for flag, target in (("--out", out), ("--curve", args.curve)):  # refused before any training
        if target is not None:
            arguments.check_writable(target, flag)
    document_format(out)  # .json or .npz
    request = TrainRequest(
        out=out,
        task=args.task,
        episodes=args.episodes,
        seed=args.seed,
        resume=args.resume,
        checkpoint_every=args.checkpoint_every or (CHECKPOINT_EVERY if args.task in PARALLEL_TASKS else None),
        curve=None if args.curve is None else Path(args.curve),
        parallel=args.parallel,
        prior=args.prior,
        progress=progress.enabled() and not (args.quiet or args.json),
        # said before hours of training, once every checkpoint it goes on from was checked
        on_resume=partial(_say_where_it_resumes, out) if args.resume and args.task in PARALLEL_TASKS else None,
    )
    result = train(request)
    if args.json:
        print(json.dumps(result, default=str))
    else:
        from fuzzynav.cli.printing import result_lines

        print("\n".join(result_lines(result)))
        if any(isinstance(value, PhaseSummary) for value in result.values()):
            print(f"note: {PHASE_NOTE}")
        if args.curve is not None:
            print(f"learning curve: {args.curve}")
    return 0


def _say_where_it_resumes(out: Path, found: list) -> None:
    """``--resume``: the episodes each phase's checkpoint holds, ``found`` [(phase, checkpoint,
    episodes done)] (a resumed run prints the same report as a fresh one), or that there is none
    to resume."""
    for phase, path, done in found:
        print(f"--resume: the {phase} phase goes on from {path}, {done} episodes done", file=sys.stderr)
    if not found:
        print(f"--resume: no checkpoint at {checkpoint_path(out, 'steering')}: training from the start",
              file=sys.stderr)
