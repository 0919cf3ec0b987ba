"""The compiled loop over (candidate, world) jobs runs the simulator's step exactly as
BatchSimulator does: the same outcomes, step counts and final poses."""

import numpy as np
import pytest

from fuzzynav.bench.suites import parse_suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.kernels import step as step_kernel
from fuzzynav.sim import BatchSimulator
from fuzzynav.tune import episodes
from fuzzynav.tune.episodes import OUTCOME, STEPS, Worlds
from fuzzynav.tune.fitness import Fitness
from fuzzynav.tune.space import SearchSpace

CODES = {"reached": step_kernel.REACHED, "collision": step_kernel.COLLISION, "timeout": step_kernel.TIMEOUT}


def _reference(worlds, name):
    rows = []
    for world in worlds:
        sim = BatchSimulator(world, make_controller(name), record=False, seed=0).run()
        rows.append((CODES[sim.outcomes()[0]], int(sim.steps[0])))
    return rows


@pytest.mark.parametrize("name,suite", [("fuzzy-2b", "mixed:5"), ("goal-seeking", "circles:3"),
                                        ("fuzzy-5b-rays", "dense:3")])
def test_jobs_match_the_batch_simulator(name, suite):
    suite = parse_suite(suite)
    worlds = [suite.scenario(i, 0) for i in range(suite.size)]
    controller = make_controller(name)
    role = controller.roles[0]
    fitness = Fitness(controller, role, SearchSpace(controller.systems[role], "rules"), worlds)
    out = fitness.simulate(fitness.space.start[None])[0]
    assert [(int(o), int(k)) for o, k in out[:, [OUTCOME, STEPS]]] == _reference(worlds, name)


def test_jobs_that_outgrow_their_point_slots_run_again_with_the_same_result(monkeypatch):
    suite = parse_suite("mixed:3")
    worlds = [suite.scenario(i, 0) for i in range(suite.size)]
    controller = make_controller("fuzzy-2b")
    compiled = Worlds(worlds, controller)
    tables = np.asarray(controller.navigator.tables)[None]
    jobs = np.array([(0, w) for w in range(len(worlds))])
    roomy = compiled.run(tables, jobs)
    monkeypatch.setattr(episodes, "SLOTS", 1)
    calls = []
    original = episodes.run_jobs
    monkeypatch.setattr(episodes, "run_jobs", lambda *a: calls.append(1) or original(*a))
    tight = compiled.run(tables, jobs)
    assert len(calls) > 1  # some job overflowed one slot and ran again
    np.testing.assert_array_equal(tight, roomy)


def test_a_tuned_default_ends_its_car_route_inside_the_tightest_goal_tolerance():
    """One layer row serves every tuning world, so ``fuzzy-5b``'s car route ends within 0.8 of the
    smallest goal tolerance among them (:meth:`~fuzzynav.control.robust.RobustNavigator.for_goal`),
    as the simulator makes it end in each world."""
    from fuzzynav.kernels.layers import PARAM

    suite = parse_suite("mixed:2")
    worlds = [suite.scenario(i, 0) for i in range(suite.size)]
    compiled = Worlds(worlds, make_controller("fuzzy-5b"))
    tolerance = min(world.goal.tolerance for world in worlds)
    assert tolerance == 0.3
    assert compiled.layer_params[PARAM.guide_car_reach] == pytest.approx(0.8 * tolerance)


def test_the_jobs_give_the_same_rows_on_any_number_of_threads():
    """The jobs share nothing (each its own robot, navigator state and layer row), so chunks of
    them run at once on several threads give the rows one thread gives, bit for bit; the kernel
    releases the GIL, or the threads would take turns."""
    from fuzzynav import threads

    suite = parse_suite("mixed:6")
    worlds = [suite.scenario(i, 0) for i in range(suite.size)]
    controller = make_controller("fuzzy-2b")
    space = SearchSpace(controller.systems["oab"], "both")
    population = space.start + np.random.default_rng(0).normal(0.0, 0.05, (5, len(space.start)))
    rows = {}
    try:
        for count in (1, 2, 3):
            threads.set_count(count)
            rows[count] = Fitness(controller, "oab", space, worlds).simulate(population)
    finally:
        threads.set_count(None)
    steps = rows[1][:, :, STEPS]
    assert (steps != steps[0]).any()  # the candidates drive differently
    np.testing.assert_array_equal(rows[2], rows[1])
    np.testing.assert_array_equal(rows[3], rows[1])
    assert episodes.run_jobs.targetoptions["nogil"]
