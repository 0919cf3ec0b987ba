"""Probes of chapter VI's learned controllers: which rule causes the collisions, and how far the
wall follower's interpretations can go (thesis §VI.5.2, §VI.5.3.2; docs/results/chapter-vi.md).

``avoid-rules MODEL``: an ``fql-avoid`` model learned from q = 0, evaluated on the 100 held-out
obstacle worlds (:func:`fuzzynav.experiments.evaluation.evaluate_avoid`) as learned, then once per
rule whose steering differs from the a-priori table (:func:`fuzzynav.learn.tasks.fql_avoid.avoid_prior`)
with that one rule given its a-priori conclusion — the rules whose learned turn costs collisions.

``wall-bound rays|modules``: the best per-rule interpretations of Table VI.2's follower (the
learner's candidates, :func:`fuzzynav.learn.tasks.fql_wall.wall_parts`: steering value − 10°,
value, + 10°; speed × 0.7, 1, 1.3) that a coordinate descent finds *on the evaluation courses
themselves* (:func:`fuzzynav.experiments.evaluation.evaluate_wall`'s 100 courses, seed 777),
starting from the hand-made choice: an optimistic bound of what any learner choosing among the
same interpretations, reading the same distances, can reach on those courses. Prints one line
per tried variable, then the best table as JSON.

``wall-corners``: can any choice among those interpretations go round both corners of Fig VI.28
(fig-VI-29's corner check)? Every steering choice (3^8 tables) with every rule's speed at the same
interpretation (× 0.7, 1 or 1.3), run at both corners; then, from each table that goes round the
second corner, a coordinate descent over all 16 per-rule choices for both. Prints the counts of
the outcome pairs and the tables that reach both goals, as JSON (about 45 minutes with 2 workers).

``wall-collisions MODEL|wall-follow``: where a wall follower collides on those 96 courses — per
collision, the time, whether the start leaves the robot any clear constant-steering forward arc
(:func:`clear_arc`: full lock either way down to straight ahead; none clear means the start can
be survived only by a manoeuvre or by stopping), and the corner nearest the collision (distance;
its wedge angle when the robot is inside it, i.e. an inner corner of the followed wall), and
whether the robot hit the workspace's boundary, having left the course. Prints
one JSON line per collision, then the counts.

``relative ID DIR…``: a relative claim of §VI.5.1.1 (``fig-VI-8``: FQL faster than tabular
Q-learning; ``fig-VI-13``: 35 rules slower than 15; ``fig-VI-16``: traces faster) over the seeds
whose ``fuzzynav reproduce ID --seed S --out DIR`` numbers are in the DIRs: the check of
:func:`fuzzynav.experiments.claims_vi.relative_over_seeds` (medians), as JSON.

    python benchmarks/chapter6_probes.py avoid-rules avoid-4.json
    python benchmarks/chapter6_probes.py wall-bound rays --sweeps 2
    python benchmarks/chapter6_probes.py wall-collisions wall-4.json
    python benchmarks/chapter6_probes.py wall-corners --workers 2
``table-vi-1 SEED``: Table VI.1's four tabular learners (§VI.2) trained as ``fuzzynav reproduce
table-VI-1`` trains them, but with another exploration and learning-rate schedule, to see whether
the thesis' trend (more state–action pairs, more episodes) hides behind the package's schedule:
``--schedule fql`` is fuzzy Q-learning's (:data:`fuzzynav.learn.tasks.common.THESIS`: ε per
episode, β = 1/(1 + visits) floored); ``--schedule per-state`` lets each state's ε decay with that
state's own visits, ε_s = max(0.02, 0.3 · 0.99^visits_s), the same β — exploration that lasts
longer in a table of more states. ``--schedule own`` is the package's tabular schedule, the one
``fuzzynav reproduce table-VI-1`` trains with. ``--reading policy`` reads "la convergence de
l'algorithme" (§VI.2, the sentence above Table VI.1) as the greedy policy's: it records each state's
greedy action after every episode and reports, per size, the first episode from which the policy
stays the same for the criterion's hold of 500 episodes (``policy_settled``) and the last episode
that changed it (``last_change``), with Spearman's ρ of each. Prints one JSON line per size, then
Spearman's ρ.

``fixed-start SEED``: Fig VI.1's tabular learner from the fixed start (13 states × 3, 1,500
single episodes) with fuzzy Q-learning's schedule (``--schedule fql``, the default: what
``fuzzynav reproduce fig-VI-8`` now trains beside FQL) or ``per-state``. Prints its episodes to
converge as JSON.

    python benchmarks/chapter6_probes.py relative fig-VI-13 out-0 out-1 out-2 out-3 out-4
    python benchmarks/chapter6_probes.py fixed-start 0 --out probe/
    python benchmarks/chapter6_probes.py table-vi-1 0 --schedule per-state --episodes 3000 --out probe/
    python benchmarks/chapter6_probes.py table-vi-1 0 --schedule own --reading policy --episodes 10000 --out probe/
"""

from __future__ import annotations

import itertools
import json
import multiprocessing
import re
from collections import Counter
from pathlib import Path

import numpy as np

from fuzzynav.catalog.tasks import load_controller
from fuzzynav.cli import Parser
from fuzzynav.control.learned import LearnedWallFollower
from fuzzynav.experiments import chapter6_worlds
from fuzzynav.experiments.chapter6 import rank_correlation
from fuzzynav.experiments.claims_vi import RELATIVE, relative_over_seeds
from fuzzynav.experiments.evaluation import evaluate_avoid, starts_in_a_wall, wall_course_scenario
from fuzzynav.experiments.rule_bases import controller as named_controller
from fuzzynav.learn.exploration import greedy_choice
from fuzzynav.learn.extraction import rule_table
from fuzzynav.learn.tabular import TabularLearner
from fuzzynav.learn.tasks import tabular_goal
from fuzzynav.learn.tasks.common import STEERING3, Phase, TrainRequest, checkpoint_path, run_phases
from fuzzynav.learn.tasks.fql_avoid import avoid_prior, free_rules
from fuzzynav.learn.tasks.fql_wall import wall_parts
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import BatchSimulator, run_episode
from fuzzynav.storage import save_document
from fuzzynav.world.scenario import load_scenario

RUNS = 100
POLICY_HOLD = 500  # episodes the greedy policy must stay the same: the hold of the goal tasks' criterion


def avoid_rules(model: str, scratch: str) -> None:
    """Collisions of ``model`` as learned, then with each differing rule set to its prior."""
    document = json.loads(open(model).read())
    labels = list(STEERING3)
    print("as learned", evaluate_avoid(load_controller(model), RUNS))
    for r, prior in enumerate(avoid_prior()[:free_rules()[0]]):
        rule = document["rules"][r]
        learned = re.search(r"alpha IS (\w+)", rule).group(1)
        if learned == labels[prior]:
            continue
        patched = {**document, "rules": list(document["rules"])}
        patched["rules"][r] = rule.replace(f"alpha IS {learned}", f"alpha IS {labels[prior]}")
        save_document(scratch, patched)
        print(f"rule {r} ({rule.split(' THEN')[0][3:]}): {learned} -> {labels[prior]}",
              evaluate_avoid(load_controller(scratch), RUNS), flush=True)


def evaluation_courses() -> list:
    """(index, scenario) of evaluate_wall's courses (seed 777) whose start is collision-free."""
    rng = np.random.default_rng(777)
    drawn = [wall_course_scenario(rng, f"wall-course-{k}") for k in range(RUNS)]
    return [(k, course) for k, course in enumerate(drawn) if not starts_in_a_wall(course)]


def clear_arc(world, pose, params=DEFAULT_PARAMS) -> bool:
    """Is some constant steering |α| ≤ max_steering (41 values) a forward path that keeps the
    footprint clear: a whole circle of radius l / tan α, or 12 m straight ahead?"""
    x, y, theta = pose
    for alpha in np.linspace(-params.max_steering, params.max_steering, 41):
        if abs(alpha) < 1e-9:
            s = np.linspace(0.0, 12.0, 400)
            points = np.column_stack([x + s * np.cos(theta), y + s * np.sin(theta)])
        else:
            radius = params.wheelbase / np.tan(alpha)
            phi = theta + np.linspace(0.0, 2 * np.pi, 400) * np.sign(radius)
            points = np.column_stack([x - radius * np.sin(theta) + radius * np.sin(phi),
                                      y + radius * np.cos(theta) - radius * np.cos(phi)])
        if world.clearance(points).min() >= params.radius:
            return True
    return False


def nearest_corner(world, point) -> tuple[float, float]:
    """(distance, wedge) of the course's joint nearest ``point``: the wedge angle (degrees) between
    the two walls when ``point`` lies inside it, negative (minus the reflex angle) outside."""
    best = (np.inf, 0.0)
    for a, b in zip(world.obstacles[:-1], world.obstacles[1:]):
        u, v, q = a.start - b.start, b.end - b.start, np.asarray(point) - b.start
        wedge = np.degrees(np.arccos(np.clip(u @ v / np.hypot(*u) / np.hypot(*v), -1.0, 1.0)))
        cross = lambda p, r: p[0] * r[1] - p[1] * r[0]
        inside = cross(u, q) * cross(u, v) > 0 and cross(q, v) * cross(u, v) > 0
        if np.hypot(*q) < best[0]:
            best = (float(np.hypot(*q)), float(wedge if inside else wedge - 360.0))
    return best


def wall_collisions(model: str) -> dict:
    """Where ``model`` (a model file, or ``wall-follow``: Table VI.2) collides (module docstring)."""
    follower = named_controller("wall-follow") if model == "wall-follow" else load_controller(model)
    rows = []
    for k, course in evaluation_courses():
        trace = run_episode(course, follower, max_time=30.0)
        if trace.outcome == "collision":
            x, y = trace.pose[-1, :2]
            distance, wedge = nearest_corner(course.world, (x, y))
            border = min(x, y, course.world.width - x, course.world.height - y)
            rows.append({"course": k, "t": round(float(trace.t[-1]), 1), "clear_arc": clear_arc(course.world, course.start),
                         "corner_m": round(distance, 2), "wedge_deg": round(wedge),
                         "boundary": bool(border < 1.5 * DEFAULT_PARAMS.radius)})
            print(json.dumps(rows[-1]), flush=True)
    inner = [r for r in rows if r["wedge_deg"] > 0 and r["corner_m"] < 3.0]
    return {"model": model, "collisions": len(rows), "no_clear_arc": sum(not r["clear_arc"] for r in rows),
            "first_3_s": sum(r["t"] < 3.0 for r in rows), "inside_an_inner_corner_within_3_m": len(inner),
            "of_which_first_3_s": sum(r["t"] < 3.0 for r in inner),
            "inner_wedges_deg": sorted(r["wedge_deg"] for r in inner),
            "workspace_boundary": sum(r["boundary"] for r in rows),
            "starts_without_clear_arc": sum(not clear_arc(c.world, c.start) for _, c in evaluation_courses())}


def interpreted(choice, sensing: str = "rays") -> LearnedWallFollower:
    """Table VI.2's follower with the interpretations ``choice`` = (steering, speed): per rule, the
    index of the learner's candidate (0, 1, 2: the label's value − 10° / × 0.7, itself, + 10° / × 1.3)."""
    handmade, _, alpha, speed = wall_parts()
    system = rule_table(handmade, [("alpha", alpha, np.asarray(choice[0])), ("v", speed, np.asarray(choice[1]))],
                        name="probe", description="interpretation probe")
    return LearnedWallFollower(system, sensing)


def wall_bound(sensing: str, sweeps: int) -> dict:
    """Coordinate descent of the per-rule interpretations on the 100 evaluation courses."""
    rules = wall_parts()[2].shape[0]
    courses = [course for _, course in evaluation_courses()]

    def collisions(choice):
        controller = interpreted(choice, sensing)
        return sum(BatchSimulator(s, controller, record=False).run().outcomes()[0] == "collision" for s in courses)

    choice = [np.ones(rules, dtype=int), np.ones(rules, dtype=int)]  # the hand-made value of every label
    best = start = collisions(choice)
    for sweep in range(sweeps):
        improved = False
        for output in (0, 1):
            for r in range(rules):
                keep = choice[output][r]
                for j in {0, 1, 2} - {keep}:
                    choice[output][r] = j
                    count = collisions(choice)
                    if count < best:
                        best, keep, improved = count, j, True
                choice[output][r] = keep
                print(f"sweep {sweep} output {output} rule {r}: {best} collisions", flush=True)
        if not improved:
            break
    return {"sensing": sensing, "hand-made": int(start), "best": int(best),
            "alpha": choice[0].tolist(), "v": choice[1].tolist()}


def corner_outcomes(choice) -> tuple[str, str]:
    """The outcomes of :func:`interpreted` ``choice`` at the corners of Fig VI.28 (a, b), as
    ``fuzzynav reproduce fig-VI-29`` runs them."""
    controller = interpreted(choice)
    return tuple(run_episode(corner, controller).outcome
                 for corner in (load_scenario("fig-VI-28"), chapter6_worlds.second_corner()))


def corners_reached(choice) -> int:
    return sum(outcome == "reached" for outcome in corner_outcomes(choice))


def corner_descent(start) -> tuple[int, list, list]:
    """Coordinate descent of the 16 per-rule choices from ``start``, for the most corners reached
    (two sweeps at most; stops when both are)."""
    choice = [list(start[0]), list(start[1])]
    best = corners_reached(choice)
    for _ in range(2):
        improved = False
        for output in choice:
            for r in range(len(output)):
                keep = output[r]
                for j in {0, 1, 2} - {keep}:
                    output[r] = j
                    if (reached := corners_reached(choice)) > best:
                        best, keep, improved = reached, j, True
                output[r] = keep
                if best == 2:
                    return best, *choice
        if not improved:
            break
    return best, *choice


def wall_corners(workers: int) -> dict:
    """Every steering choice (3^8) at each of the three speed interpretations taken by every rule:
    the outcomes at the two corners; then, from each table that goes round corner b, a coordinate
    descent over all 16 choices (:func:`corner_descent`)."""
    rules = wall_parts()[2].shape[0]
    tables = [(steering, (v,) * rules) for v in (0, 1, 2) for steering in itertools.product((0, 1, 2), repeat=rules)]
    with multiprocessing.Pool(workers) as pool:
        outcomes = pool.map(corner_outcomes, tables, chunksize=64)
        counts = Counter(" / ".join(pair) for pair in outcomes)
        starts = [table for table, pair in zip(tables, outcomes) if pair[1] == "reached"]
        descents = pool.map(corner_descent, starts, chunksize=1)
    return {"tables": len(tables), "outcomes (a / b)": dict(counts.most_common()),
            "both reached": counts["reached / reached"], "descents from b reached": len(starts),
            "corners reached after the descent": dict(Counter(best for best, _, _ in descents)),
            "both reached after the descent": [[a, v] for best, a, v in descents if best == 2]}


class PerStateEpsilon(TabularLearner):
    """A tabular learner whose ε-greedy exploration decays with the visits of the state it acts
    in (ε_s = max(floor, ε0 · decay^visits_s)) instead of with the episode."""

    start, decay, floor = 0.3, 0.99, 0.02

    def act(self, s, rng):
        s = np.asarray(s, dtype=int)
        q = self.q[0, s]
        epsilon = np.maximum(self.floor, self.start * self.decay ** self.visits[0, s].sum(axis=-1))
        u = rng.random(s.size)
        explore = np.minimum((u / epsilon * q.shape[-1]).astype(int), q.shape[-1] - 1)
        return np.where(u < epsilon, explore, greedy_choice(q, rng))


class PolicyRecorder(TabularLearner):
    """A tabular learner that keeps each state's greedy action after every episode (``policies``)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.policies: list[np.ndarray] = []

    def end_episode(self) -> None:
        super().end_episode()
        self.policies.append(self.greedy()[0].copy())


def policy_readings(policies: list, hold: int = POLICY_HOLD) -> dict:
    """(first episode from which the greedy policy stays the same for ``hold`` episodes, None: not
    within the run; the last episode that changed it, 0: none) of the policies after each episode."""
    changed = [k + 1 for k in range(1, len(policies)) if not np.array_equal(policies[k], policies[k - 1])]
    last = changed[-1] if changed else 0
    bounds = [0, *changed, len(policies) + 1]  # a run of episodes without a change lies between two bounds
    settled = next((a if a else 1 for a, b in zip(bounds, bounds[1:]) if b - max(a, 1) > hold), None)
    return {"policy_settled": settled, "last_change": last}


def table_vi_1(seed: int, schedule: str, episodes: int, out: Path, reading: str = "reward") -> dict:
    """Table VI.1's four sizes under ``schedule`` (module docstring), one robot, ``episodes`` each;
    ``reading="policy"`` adds the greedy policy's readings of convergence."""
    rows = []
    for n_states, n_actions in ((9, 3), (11, 3), (13, 3), (19, 5)):
        model = out / f"table-vi-1-{schedule}-{n_states}x{n_actions}-{seed}.json"
        converged, learner = _tabular_run(model, seed, schedule, episodes, n_states, n_actions, record=reading == "policy")
        rows.append({"states": n_states, "actions": n_actions, "episodes": episodes, "episodes_to_converge": converged,
                     **(policy_readings(learner.policies) if reading == "policy" else {})})
        print(json.dumps({"seed": seed, "schedule": schedule, **rows[-1]}), flush=True)
    result = {"seed": seed, "schedule": schedule, "rank_correlation": rank_correlation(rows)}
    if reading == "policy":
        for key in ("policy_settled", "last_change"):
            result[f"rank_correlation_{key}"] = rank_correlation([{**r, "episodes_to_converge": r[key]} for r in rows])
    return result


def _tabular_run(model: Path, seed: int, schedule: str, episodes: int, n_states: int = 13, n_actions: int = 3,
                 fixed: bool = False, record: bool = False) -> tuple[int | None, TabularLearner]:
    """(episodes to converge, None: not within ``episodes``; the learner) of one tabular learner
    (one robot) under ``schedule``; ``record``: a :class:`PolicyRecorder`."""
    request = TrainRequest(out=model, task="q-goal", episodes=episodes, seed=seed, progress=False)
    env, learner, disc, steering = tabular_goal.q_goal_parts(n_states, n_actions, fixed, batch=1,
                                                             schedule="own" if schedule == "own" else "fql")
    kind = PerStateEpsilon if schedule == "per-state" else PolicyRecorder if record else None
    if kind is not None:
        learner = kind(disc.n_states, len(steering), gamma=learner.gamma, alpha=learner.alpha, policy=learner.policy)
    result, _ = run_phases([Phase("steering", env, learner, episodes, checkpoint_path(model, "steering"))], request)
    converged = result["steering"]["converged_at"]
    return (converged if converged <= episodes else None), learner


def fixed_start(seed: int, schedule: str, episodes: int, out: Path) -> dict:
    """Fig VI.1's tabular learner (13 states × 3, the fixed start of ``fuzzynav reproduce fig-VI-8``)
    under ``schedule`` instead of its own."""
    model = out / f"fixed-start-{schedule}-{seed}.json"
    return {"seed": seed, "schedule": schedule, "episodes": episodes,
            "episodes_to_converge": _tabular_run(model, seed, schedule, episodes, fixed=True)[0]}


def main() -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="probe", required=True)
    avoid = sub.add_parser("avoid-rules")
    avoid.add_argument("model")
    avoid.add_argument("--scratch", default="avoid-probe.json", help="patched model file (overwritten)")
    wall = sub.add_parser("wall-bound")
    wall.add_argument("sensing", choices=("rays", "modules"))
    wall.add_argument("--sweeps", type=int, default=2)
    corners = sub.add_parser("wall-corners")
    corners.add_argument("--workers", type=int, default=2)
    collisions = sub.add_parser("wall-collisions")
    collisions.add_argument("model", help="an fql-wall model file, or wall-follow (Table VI.2)")
    relative = sub.add_parser("relative")
    relative.add_argument("id", choices=sorted(RELATIVE))
    relative.add_argument("dirs", nargs="+", help="the --out DIR of one reproduce run per seed")
    table = sub.add_parser("table-vi-1")
    table.add_argument("seed", type=int)
    table.add_argument("--schedule", choices=("fql", "per-state", "own"), default="per-state")
    table.add_argument("--reading", choices=("reward", "policy"), default="reward",
                       help="policy: also the greedy policy's convergence (module docstring)")
    table.add_argument("--episodes", type=int, default=3000, help="single episodes per size")
    table.add_argument("--out", default=".", help="folder of the models and checkpoints")
    fixed = sub.add_parser("fixed-start")
    fixed.add_argument("seed", type=int)
    fixed.add_argument("--schedule", choices=("fql", "per-state"), default="fql")
    fixed.add_argument("--episodes", type=int, default=1500, help="single episodes (fig-VI-8's tabular budget)")
    fixed.add_argument("--out", default=".", help="folder of the model and checkpoint")
    args = parser.parse_args()
    if args.probe in ("table-vi-1", "fixed-start"):
        Path(args.out).mkdir(parents=True, exist_ok=True)
        if args.probe == "table-vi-1":
            print(json.dumps(table_vi_1(args.seed, args.schedule, args.episodes, Path(args.out), args.reading)))
        else:
            print(json.dumps(fixed_start(args.seed, args.schedule, args.episodes, Path(args.out))))
    elif args.probe == "avoid-rules":
        avoid_rules(args.model, args.scratch)
    elif args.probe == "wall-corners":
        print(json.dumps(wall_corners(args.workers)))
    elif args.probe == "wall-collisions":
        print(json.dumps(wall_collisions(args.model)))
    elif args.probe == "relative":
        runs = [json.loads((Path(d) / args.id / f"{args.id}.json").read_text()) for d in args.dirs]
        print(json.dumps(relative_over_seeds(args.id, runs).as_json()))
    else:
        print(json.dumps(wall_bound(args.sensing, args.sweeps)))


if __name__ == "__main__":
    main()
