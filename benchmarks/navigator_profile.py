"""Per-step cost split of the default navigator ``fuzzy-5b``, one robot and batched.

``fuzzy-5b`` runs inside the simulator's compiled step, so its parts are timed by building it up
one layer at a time and timing each build in the same run, chunks interleaved (so every build
sees the same machine load): the simulator with the 271-beam lidar under a constant command
(``sim+lidar``), then the inner navigator ``fuzzy-5b-gap`` (sector readings, gap finding, the
five behaviours, the hit memory: ``navigator``), then the recovery and loop-escape layers with
their obstacle-point memory (``layers``), then the route guidance on the grid route alone
(``grid route``), then with the car route by hybrid A* searched at every plan (``car route``),
then with its pace (``pace``), then the whole ``fuzzy-5b``, which reuses a car route while it
stays valid (``plan reuse``: a negative part is a saving). Each part's cost is the difference of two builds' mean time
per running robot-step (µs); the builds drive differently from the layer they add on (the pace
above all: quicker, the robots reach clutter and plan sooner), so the split is an estimate, not
an exact account. :func:`plans` then counts how often ``fuzzy-5b`` plans and splits one car
route plan into its parts (CPU time), which the builds cannot separate. World:
``benchmarks/sim_core.py``'s 15 mixed obstacles, goal (19, 19); an episode that ends starts again. Run:

    python benchmarks/navigator_profile.py [--robots 1 64 1024] [--steps 400] [--json]
    python benchmarks/navigator_profile.py --singles --robots 64 --steps 300   # batch against one at a time
    python benchmarks/navigator_profile.py --searches --steps 6000              # what the car route searches cost
"""

from __future__ import annotations

import json
import statistics
import sys
from pathlib import Path

from fuzzynav.cli import Parser

sys.path.insert(0, str(Path(__file__).parent))

from sim_core import COMMAND, start_poses, world_of_15  # noqa: E402

from fuzzynav.control.batched import ConstantCommand  # noqa: E402
from fuzzynav.control.five_behaviours import FiveBehaviourNavigator  # noqa: E402
from fuzzynav.control.robust import RobustNavigator  # noqa: E402
from fuzzynav.control.through_gaps import fuzzy_5b_gap_robust  # noqa: E402
from fuzzynav.robot.sensors import named_ring  # noqa: E402
from fuzzynav.sim import BatchSimulator  # noqa: E402

CHUNKS = 5
SEARCHED = {"guide_car_reuse": 0.0}  # the car route searched at every plan, as before plans were reused
GOAL = (19.0, 19.0)  # the goal of world_of_15


def builds() -> dict:
    """The builds of ``fuzzy-5b``, each adding one part to the one before (module docstring)."""
    def layers_only():
        return RobustNavigator(FiveBehaviourNavigator(gap=True), "fuzzy-5b-layers")

    return {
        "sim+lidar": lambda: ConstantCommand(COMMAND[1], COMMAND[0]),
        "navigator": lambda: FiveBehaviourNavigator(gap=True),
        "layers": layers_only,
        "grid route": lambda: fuzzy_5b_gap_robust(guidance={"guide_car": 0.0}, paced=False),
        "car route": lambda: fuzzy_5b_gap_robust(paced=False, guidance=SEARCHED),
        "pace": lambda: fuzzy_5b_gap_robust(guidance=SEARCHED),
        "plan reuse": fuzzy_5b_gap_robust,
    }


class Run:
    """One build driving ``n`` robots, timed in chunks of running-robot steps."""

    def __init__(self, controller, n: int):
        import numpy as np

        scenario = world_of_15()
        starts = start_poses(scenario, n, clearance=3.0 if n == 1 else 0.5)
        self.sim = BatchSimulator(scenario, controller, starts=starts, record=False, sensors=named_ring("lidar"))
        self.np = np
        for _ in range(3):
            self.sim.step()

    def chunk(self, steps: int) -> float:
        """Mean seconds of wall clock per running robot-step over ``steps`` steps."""
        import time

        sim, done, wall = self.sim, 0, 0.0
        for _ in range(steps):
            if sim.done:
                sim.reset()
            running = int(self.np.count_nonzero(sim.active)) if sim.n > 1 else 1
            w0 = time.perf_counter()
            sim.step()
            wall += time.perf_counter() - w0
            done += running
        return wall / max(done, 1)


def profile(n: int, steps: int) -> dict:
    """µs per running robot-step of each build and each part (the difference to the build before)."""
    runs = {name: Run(make(), n) for name, make in builds().items()}
    times = {name: [] for name in runs}
    for _ in range(CHUNKS):
        for name, run in runs.items():
            times[name].append(run.chunk(steps))
    total = {name: statistics.median(t) * 1e6 for name, t in times.items()}
    names, parts = list(total), {}
    for before, name in zip([None, *names], names):
        parts[name] = total[name] - (total[before] if before else 0.0)
    return {"us_per_robot_step": {k: round(v, 1) for k, v in total.items()},
            "part_us": {k: round(v, 1) for k, v in parts.items()},
            "part_share": {k: round(v / total[names[-1]], 3) for k, v in parts.items()}}


def plans(n: int, steps: int) -> dict:
    """How often ``fuzzy-5b``'s robots plan and search a car route, with the route searched at every
    plan and reused: ``n`` robots drive ``steps`` steps (a route planned again shows as a new
    ``guide_planned`` time, a search as a new ``guide_made``); then, for
    each robot still running (at most 64) whose straight line to the goal is not free, the plan it
    would make there is made again part by part, as ``fuzzynav.kernels.car_route.plan`` makes it
    (CPU time of 3 repeats): the clearance grid, then the hybrid A* search with its cost-to-go, the
    wavefront the search settles as far as it looks (the two cannot be timed apart)."""
    import time

    import numpy as np

    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels import car_route, car_search, guidance, layers, row_blocks
    from fuzzynav.kernels.records import Robot, Sightings

    counts = {}
    for name, options in (("searched every plan", SEARCHED), ("reused", {})):
        controller = make_controller("fuzzy-5b", guidance=options)
        run = Run(controller, n)
        sim, planned, searches, robot_steps = run.sim, 0, 0, 0
        columns = [layers.STATE.guide_planned, layers.STATE.guide_made]
        for _ in range(steps):
            if sim.done:
                break
            before = controller.compiled(n, sim.sensors.angles)[-1][:, columns].copy()
            robot_steps += int(np.count_nonzero(sim.active))
            sim.step()
            changed = controller.compiled(n, sim.sensors.angles)[-1][:, columns] != before
            planned, searches = planned + int(np.count_nonzero(changed[:, 0])), searches + int(np.count_nonzero(changed[:, 1]))
        counts[name] = {"plans_per_robot_step": round(planned / max(robot_steps, 1), 4),
                        "car_searches_per_robot_step": round(searches / max(robot_steps, 1), 4)}
    params, rows = controller.params, controller.compiled(n, sim.sensors.angles)[-1]
    search, radius = guidance.search_settings(params, 0), float(params[layers.PARAM.radius])
    tx, ty = GOAL
    seconds, searched = {"clearance grid": 0.0, "search with its cost-to-go": 0.0}, 0
    running = np.flatnonzero(sim.active)[:64]
    for i in running:
        points, count = row_blocks.points_of(params, rows[i]), int(rows[i, layers.STATE.count])
        x, y, theta = sim.pose[i]
        if guidance.line_free(points, count, x, y, tx, ty, radius + params[layers.PARAM.guide_room],
                              params[layers.PARAM.guide_direct]):
            continue
        seen, robot = Sightings(points, count), Robot(x, y, theta, 0.0, tx, ty)
        room = params[layers.PARAM.guide_car_room]
        kept, low_x, low_y, nx, ny = car_route.frame(seen, robot, radius + room, radius, search.cell)
        comfort = search.comfort
        start, goal = np.array([x - low_x, y - low_y, theta % (2 * np.pi)]), np.array([tx - low_x, ty - low_y])
        row, col = int((ty - low_y) / search.cell), int((tx - low_x) / search.cell)
        here = (int(np.floor(start[1] / search.cell)), int(np.floor(start[0] / search.cell)))
        shots = int(params[layers.PARAM.guide_car_shot]) if guidance.off_heading(params, robot) else 0
        for _ in range(3):
            t0 = time.process_time()
            grid = car_route.clearance_grid(points, count, low_x, low_y, nx, ny, search.cell, kept + comfort)
            t1 = time.process_time()
            front = car_search.wavefront(grid, search.cell, row, col, kept, search.weight, comfort, here)
            car_search.search(grid, front.cost.reshape(ny, nx), start, goal, kept, search._replace(shot=shots),
                              front)  # as guidance.car
            t2 = time.process_time()
            for name, spent in zip(seconds, (t1 - t0, t2 - t1)):
                seconds[name] += spent / 3
        searched += 1
    total = sum(seconds.values())
    return {**counts, "robots_needing_the_search": f"{searched} of {len(running)}",
            "ms_per_search_plan": round(1e3 * total / max(searched, 1), 2),
            "plan_share": {name: round(value / total, 3) if total else None for name, value in seconds.items()}}


def against_singles(n: int, steps: int) -> dict:
    """Wall µs per running robot-step of ``fuzzy-5b`` driving ``n`` robots in one batch, and of the
    same robots (same starts, same ``steps``) run one at a time: whether batching itself costs."""
    import time

    import numpy as np

    from fuzzynav.catalog.controllers import make_controller

    scenario = world_of_15()
    starts = start_poses(scenario, n)

    def run(poses) -> tuple[float, int]:
        sim = BatchSimulator(scenario, make_controller("fuzzy-5b"), starts=poses, record=False,
                             sensors=named_ring("lidar"))
        robot_steps, began = 0, time.perf_counter()
        for _ in range(steps):
            if sim.done:
                break
            robot_steps += int(np.count_nonzero(sim.active))
            sim.step()
        return time.perf_counter() - began, robot_steps

    run(starts[:1])  # compiled before the clock
    batch_wall, batch_steps = run(starts)
    singles = [run(starts[i:i + 1]) for i in range(n)]
    singles_wall, singles_steps = sum(w for w, _ in singles), sum(k for _, k in singles)
    return {"robots": n, "steps": steps, "robot_steps": batch_steps,
            "batch_us_per_robot_step": round(1e6 * batch_wall / max(batch_steps, 1), 1),
            "singles_us_per_robot_step": round(1e6 * singles_wall / max(singles_steps, 1), 1)}


def search_steps(steps: int) -> dict:
    """One ``fuzzy-5b`` robot stepped ``steps`` times (finished episodes restarted), each step
    timed alone and counted as a car route search (``guide_made`` stamped with the step's time;
    apart, the search of an episode's first step), a plan without a search (a new
    ``guide_planned``) or neither: a direct measure of what the searches cost in the whole
    navigator, which the builds of :func:`profile` only estimate."""
    import time

    import numpy as np

    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.kernels import layers

    controller = make_controller("fuzzy-5b")
    run = Run(controller, 1)
    columns = [layers.STATE.guide_planned, layers.STATE.guide_made]
    kinds = {"searched at the start": [], "searched": [], "planned, no search": [], "neither": []}
    for _ in range(steps):
        if run.sim.done:
            run.sim.reset()
        before = controller.compiled(1, run.sim.sensors.angles)[-1][0, columns].copy()
        now = run.sim.k * run.sim.params.dt
        began = time.perf_counter()
        run.sim.step()
        spent = time.perf_counter() - began
        after = controller.compiled(1, run.sim.sensors.angles)[-1][0, columns]
        # a search stamps guide_made with the step's time (t = 0 too: a new episode's stamp is -inf)
        kind = ("searched" if now > 0.0 else "searched at the start") if after[1] == now else (
            "planned, no search" if after[0] != before[0] else "neither")
        kinds[kind].append(spent)
    total = sum(sum(times) for times in kinds.values())
    return {"steps": steps, "us_per_step": round(1e6 * total / steps, 1),
            "kinds": {name: {"steps": len(times), "mean_us": round(1e6 * float(np.mean(times)), 1) if times else None,
                             "share_of_time": round(sum(times) / total, 3)} for name, times in kinds.items()}}


def main(argv=None) -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--robots", type=int, nargs="+", default=[1, 64, 1024])
    parser.add_argument("--steps", type=int, default=400, help="steps per timed chunk (one robot; batches: /n·64)")
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    parser.add_argument("--singles", action="store_true",
                        help="instead: each batch against its robots run one at a time (against_singles)")
    parser.add_argument("--searches", action="store_true",
                        help="instead: one robot's steps timed one by one, split by car route searches (search_steps)")
    args = parser.parse_args(argv)
    if args.searches:
        print(json.dumps({"benchmark": "navigator_profile", "search_steps": search_steps(args.steps)}))
        return
    if args.singles:
        print(json.dumps({"benchmark": "navigator_profile", "singles": [against_singles(n, args.steps)
                                                                      for n in args.robots]}))
        return
    report = {"benchmark": "navigator_profile", "controller": "fuzzy-5b", "chunks": CHUNKS, "robots": {}}
    for n in args.robots:
        steps = args.steps if n == 1 else max(5, args.steps * 64 // (n * 4))
        report["robots"][str(n)] = {"steps_per_chunk": steps, **profile(n, steps), "plans": plans(n, steps)}
    if not args.json:
        for n, row in report["robots"].items():
            print(f"{n} robot(s), {row['steps_per_chunk']} steps a chunk:")
            for name, us in row["part_us"].items():
                print(f"  {name:12s} {us:>10.1f} µs/robot-step  {100 * row['part_share'][name]:5.1f} %   "
                      f"(build total {row['us_per_robot_step'][name]:.1f})")
            print(f"  plans: {row['plans']}")
    print(json.dumps(report))


if __name__ == "__main__":
    main()
