"""The car route of the route guidance (kernels.car_route, kernels.car_search): hybrid A* with
forward and backward arcs on the obstacle points seen so far — a plan out of a chamber too narrow
to turn in holds a K-turn, every pose keeps the clearance, and a blocked route point is planned
again."""

import heapq
import math

import numpy as np
import pytest

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.kernels import car_route, car_search, guidance, layers, row_blocks
from fuzzynav.kernels.records import CarSearch, Clock, Layers, Navigator, Reading, Robot, SearchNodes, Sightings

PARAMS = make_controller("fuzzy-5b-gap-robust").params
# the route point the navigator is given round a wall of posts: only where the layer leaves the
# driving to the navigator, as it did before the default drove every arc within 2 m (version 12)
POINTED = make_controller("fuzzy-5b-gap-robust", guidance={"guide_car_tight": 0.5, "guide_off_heading": 0.0}).params
BODY = float(PARAMS[layers.PARAM.radius])


SEARCH = guidance.search_settings(PARAMS, 0)
RADIUS = BODY + PARAMS[layers.PARAM.guide_car_room]  # the radius the car route keeps


def test_the_search_settings_are_the_layer_parameters_of_their_names():
    at = layers.PARAM
    steering, count = PARAMS[at.guide_car_steering], int(PARAMS[at.guide_car_steerings])
    assert np.array_equal(SEARCH.curvatures, np.tan(np.linspace(-steering, steering, count)) / PARAMS[at.wheelbase])
    named = {"cell": at.guide_car_cell, "step": at.guide_car_step, "node_cell": at.guide_car_node,
             "headings": at.guide_car_headings, "weight": at.guide_car_weight, "comfort": at.guide_car_comfort,
             "turn_cost": at.guide_car_turn, "switch_cost": at.guide_car_switch, "reach": at.guide_car_reach,
             "budget": at.guide_car_budget, "reverse": at.guide_car_reverse, "gear": at.guide_car_gear}
    assert set(named) | {"curvatures", "shot"} == set(CarSearch._fields)
    for field, index in named.items():
        assert getattr(SEARCH, field) == PARAMS[index], field
    assert SEARCH.shot == 0 and guidance.search_settings(PARAMS, 7).shot == 7  # analytic expansions: off heading only
    assert SEARCH.reverse > 0
    forward_only = PARAMS.copy()
    forward_only[at.max_reverse_speed] = 0.0  # a robot that cannot reverse plans forward arcs only
    forward = guidance.search_settings(forward_only, 0)
    assert forward.reverse == 0.0
    assert forward._replace(curvatures=None, reverse=SEARCH.reverse) == SEARCH._replace(curvatures=None)


def chamber():
    """Points every 5 cm on three walls of a chamber 1.6 m wide, open at y = 0 (too narrow for
    a full-lock turn of the car: 2 × 0.69 m + its 0.6 m body)."""
    side = np.arange(0.0, 2.41, 0.05)
    end = np.arange(-0.8, 0.81, 0.05)
    return np.vstack([np.column_stack([np.full_like(side, -0.8), side]),
                      np.column_stack([np.full_like(side, 0.8), side]), np.column_stack([end, np.full_like(end, 2.4)])])


def _plan(points, pose, goal, reverse=True):
    search = SEARCH if reverse else SEARCH._replace(reverse=0.0)
    return car_route.plan(Sightings(points, len(points)), Robot(*pose, 0.0, *goal), RADIUS, BODY, search)


def test_a_plan_out_of_a_chamber_too_narrow_to_turn_in_backs_up():
    walls, pose, goal = chamber(), (0.0, 1.2, math.pi / 2), (0.0, -4.0)  # facing the closed end, goal behind
    found, poses, primitives = _plan(walls, pose, goal, reverse=False)
    assert not found  # forwards only, the car cannot leave
    found, poses, primitives = _plan(walls, pose, goal)
    assert found
    backwards = primitives[1:] >= len(SEARCH.curvatures)
    assert backwards.any() and not backwards.all()  # a K-turn: backward and forward legs
    assert np.hypot(*(poses[-1, :2] - goal)) <= SEARCH.reach
    route = np.column_stack([poses, primitives])
    leg = car_route.leg(route, 0, len(route), Sightings(walls, len(walls)),
                        SEARCH, BODY,
                        PARAMS[layers.PARAM.guide_car_ahead], PARAMS[layers.PARAM.guide_car_tight])
    assert leg[0]  # a manoeuvre the layer drives


def _search_both_ways(points, pose, goal, directed=True):
    """The search on the whole cost-to-go grid and on the wavefront settled on demand (an A* towards
    the start, or Dijkstra), and that wavefront."""
    seen, robot = Sightings(points, len(points)), Robot(*pose, 0.0, *goal)
    radius, low_x, low_y, nx, ny = car_route.frame(seen, robot, RADIUS, BODY, SEARCH.cell)
    grid = car_route.clearance_grid(points, len(points), low_x, low_y, nx, ny, SEARCH.cell, radius + SEARCH.comfort)
    row, col = int((goal[1] - low_y) / SEARCH.cell), int((goal[0] - low_x) / SEARCH.cell)
    whole = car_route.cost_to_go(grid, SEARCH.cell, row, col, radius, SEARCH.weight, SEARCH.comfort)
    start, end = np.array([pose[0] - low_x, pose[1] - low_y, pose[2] % (2 * math.pi)]), np.array(goal) - (low_x, low_y)
    toward = (int(start[1] / SEARCH.cell), int(start[0] / SEARCH.cell)) if directed else (-1, -1)
    front = car_search.wavefront(grid, SEARCH.cell, row, col, radius, SEARCH.weight, SEARCH.comfort, toward)
    on_demand = car_search.search(grid, front.cost.reshape(ny, nx), start, end, radius, SEARCH, front)
    return car_search.search(grid, whole, start, end, radius, SEARCH), on_demand, front, whole


def _case(case):
    if case == "chamber":
        return chamber(), (0.0, 1.2, math.pi / 2), (0.0, -4.0)
    return np.random.default_rng(3).uniform([-3.0, 1.0], [3.0, 7.0], size=(25, 2)), (0.0, 0.0, math.pi / 2), (0.0, 9.0)


@pytest.mark.parametrize("directed", [False, True], ids=["dijkstra", "a-star"])
@pytest.mark.parametrize("case", ["chamber", "posts"])
def test_the_wavefront_settled_on_demand_gives_the_search_of_the_whole_cost_to_go(case, directed):
    whole_search, on_demand, front, whole = _search_both_ways(*_case(case), directed=directed)
    assert on_demand[-1] >= 0 and on_demand[-1] == whole_search[-1]
    for a, b in zip(whole_search[:-1], on_demand[:-1]):
        assert np.array_equal(a, b)
    settled = front.done.reshape(whole.shape)
    assert 0 < settled.sum() < np.isfinite(whole).sum()  # part of the grid settled, each cell as in the whole
    assert np.array_equal(front.cost.reshape(whole.shape)[settled], whole[settled])


def _textbook_dijkstra(grid, cell, goal, radius, weight, comfort):
    """The cost-to-go of ``car_route.cost_to_go`` by Python's binary heap (``heapq``, ties by cell)."""
    ny, nx = grid.shape
    cost, done, queue = np.full(grid.shape, np.inf), np.zeros(grid.shape, bool), [(0.0, goal)]
    cost[goal] = 0.0
    while queue:
        _, (row, col) = heapq.heappop(queue)
        if done[row, col]:
            continue
        done[row, col] = True
        for dr, dc in car_search.NEIGHBOURS:
            r, c = row + dr, col + dc
            if 0 <= r < ny and 0 <= c < nx and grid[r, c] >= radius:
                step = cell * (car_search.DIAGONAL if dr != 0 and dc != 0 else 1.0)
                total = cost[row, col] + step * (1.0 + weight * max(0.0, comfort - (grid[r, c] - radius)))
                if total < cost[r, c]:
                    cost[r, c] = total
                    heapq.heappush(queue, (total, (r, c)))
    return cost


@pytest.mark.parametrize("case", ["chamber", "posts"])
def test_the_wavefront_gives_the_costs_of_a_textbook_dijkstra_bit_for_bit(case):
    """The wavefront's heap (``car_search.FANOUT``) pops cells of equal keys in another order than a
    binary heap; each cell's cost is the least over its neighbours', whatever that order, so the
    same float."""
    _, _, front, whole = _search_both_ways(*_case(case))
    points, pose, goal = _case(case)
    seen, robot = Sightings(points, len(points)), Robot(*pose, 0.0, *goal)
    radius, low_x, low_y, nx, ny = car_route.frame(seen, robot, RADIUS, BODY, SEARCH.cell)
    grid = car_route.clearance_grid(points, len(points), low_x, low_y, nx, ny, SEARCH.cell, radius + SEARCH.comfort)
    target = (int((goal[1] - low_y) / SEARCH.cell), int((goal[0] - low_x) / SEARCH.cell))
    assert np.array_equal(whole, _textbook_dijkstra(grid, SEARCH.cell, target, radius, SEARCH.weight, SEARCH.comfort))


@pytest.mark.parametrize("case", ["chamber", "posts"])
def test_the_wavefront_headed_for_the_start_settles_fewer_cells_than_dijkstra(case):
    plain, directed = (_search_both_ways(*_case(case), directed=d)[2].done.sum() for d in (False, True))
    assert directed < 0.8 * plain


def test_every_pose_of_the_plan_keeps_the_clearance_asked():
    rng = np.random.default_rng(3)
    posts = rng.uniform([-3.0, 1.0], [3.0, 7.0], size=(25, 2))
    found, poses, _ = _plan(posts, (0.0, 0.0, math.pi / 2), (0.0, 9.0))
    assert found
    gaps = np.hypot(poses[:, None, 0] - posts[None, :, 0], poses[:, None, 1] - posts[None, :, 1]).min(axis=1)
    # the search tests cell centres on a 0.1 m grid: each pose is within half a cell diagonal of one
    assert gaps.min() >= RADIUS - SEARCH.cell / math.sqrt(2)
    assert np.all(np.hypot(*np.diff(poses[:, :2], axis=0).T) < SEARCH.step + 1e-9)


def test_a_route_point_that_newly_seen_points_block_is_planned_again():
    state = layers.fresh_state(1, POINTED)[0]
    posts = np.array([(x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)])
    robot = Robot(0.0, 0.0, math.pi / 2, 0.0, 0.0, 10.0)
    first = guidance.aim(state, POINTED, Sightings(posts, len(posts)), robot, 0.0, BODY)
    point = state[[layers.STATE.guide_x, layers.STATE.guide_y]].copy()
    assert np.isfinite(point).all()
    seen = np.vstack([posts, point + np.array([[0.0, 0.0], [0.1, 0.0], [-0.1, 0.0]])])
    assert guidance.aim(state, POINTED, Sightings(seen, len(seen)), robot, 0.1, BODY) != first
    assert state[layers.STATE.guide_planned] == pytest.approx(0.1)
    # a new route point clear of the blocked one, or (the plan now passing close to the new
    # points) an arc the layer drives itself
    moved = np.hypot(*(state[[layers.STATE.guide_x, layers.STATE.guide_y]] - point)) > BODY
    assert moved or state[layers.STATE.guide_gear] != 0.0


def test_a_robot_that_cannot_reverse_gets_no_backward_arc():
    walls, pose, goal = chamber(), (0.0, 1.2, math.pi / 2), (0.0, 6.0)  # the goal beyond the closed end
    for reverse_speed, gear in ((0.5, -1.0), (0.0, 0.0)):
        params = PARAMS.copy()
        params[layers.PARAM.max_reverse_speed] = reverse_speed
        state = layers.fresh_state(1, params)[0]
        guidance.aim(state, params, Sightings(walls, len(walls)), Robot(*pose, 0.0, *goal), 0.0, BODY)
        assert state[layers.STATE.guide_gear] == gear  # backs up if it can; else no arc is driven


def test_no_arc_is_kept_or_planned_while_the_recovery_drives_and_its_end_plans_again():
    walls, pose, goal = chamber(), (0.0, 1.2, math.pi / 2), (0.0, 6.0)  # the goal beyond the closed end
    state = layers.fresh_state(1, PARAMS)[0]
    guidance.aim(state, PARAMS, Sightings(walls, len(walls)), Robot(*pose, 0.0, *goal), 0.0, BODY)
    assert state[layers.STATE.guide_gear] == -1.0  # a backward arc pending
    state[layers.STATE.phase] = layers.BACK  # the recovery manoeuvre takes over and moves the robot
    moved = (0.1, 1.0, math.pi / 2 + 0.3)
    for t in (0.1, 2.0):  # before and after guide_replan
        guidance.aim(state, PARAMS, Sightings(walls, len(walls)), Robot(*moved, 0.0, *goal), t, BODY)
        assert state[layers.STATE.guide_gear] == 0.0 and state[layers.STATE.guide_planned] == -math.inf
    state[layers.STATE.phase] = layers.NO_PHASE  # the recovery ends: planned again at once, from where the robot is
    guidance.aim(state, PARAMS, Sightings(walls, len(walls)), Robot(*moved, 0.0, *goal), 2.1, BODY)
    fresh = layers.fresh_state(1, PARAMS)[0]
    guidance.aim(fresh, PARAMS, Sightings(walls, len(walls)), Robot(*moved, 0.0, *goal), 2.1, BODY)
    at = layers.STATE
    columns = [at.guide_planned, at.guide_gear, at.guide_kappa, at.guide_run, at.guide_driven]
    np.testing.assert_array_equal(state[columns], fresh[columns])
    assert state[layers.STATE.guide_planned] == pytest.approx(2.1)


@pytest.mark.parametrize("starts", [True, False])
def test_the_loop_escape_beginning_or_ending_drops_the_arc_pending(starts):
    """An arc planned towards the goal is not driven once the escape's virtual goal replaces it
    (or once the escape ends); the route is planned again from the pose the robot has."""
    from fuzzynav.kernels import robust

    controller = make_controller("fuzzy-5b-gap-robust")
    angles = np.ascontiguousarray(controller.sensors.angles, dtype=float)
    kind, params, tables, nav_state, memory, layer_params, rows = controller.compiled(1, angles)
    row = rows[0]
    at = layers.STATE
    row[[at.guide_gear, at.guide_kappa, at.guide_run, at.guide_planned]] = 1.0, 0.0, 5.0, 29.9
    if starts:  # the robot is back where it was 15 s ago, not nearer the goal for 30 s
        row[layers.PLACES_AT:layers.PLACES_AT + 3] = 15.0, 0.0, 0.0
        row[[layers.STATE.places, layers.STATE.best, layers.STATE.t_best]] = 1.0, 10.0, 0.0
    else:  # following a boundary for longer than its limit
        row[[layers.STATE.active, layers.STATE.side, layers.STATE.t_follow]] = 1.0, 1.0, -100.0
    ranges = np.full(len(angles), controller.sensors.max_range)
    steering, speed, code = robust.act_one(Navigator(kind, params, tables), nav_state[0], memory[0],
                                           Layers(layer_params, row), Robot(0.0, 0.0, 0.0, 0.5, 10.0, 0.0),
                                           Reading(ranges, angles, controller.sensors.max_range, math.inf, 0.0),
                                           Clock(0.05, 30.0), layer_params)
    assert row[layers.STATE.active] == (1.0 if starts else 0.0)
    assert controller.labels[int(code)] != "CAR-FWD"  # the arc pending is not driven
    assert row[layers.STATE.guide_gear] == 0.0 and row[layers.STATE.guide_planned] == 30.0  # planned again at once


def test_a_kept_route_is_reused_until_a_newly_seen_point_lies_on_it_or_it_grows_old():
    at, age = layers.STATE, POINTED[layers.PARAM.guide_car_reuse]
    assert age > 0.0  # the default reuses its car route
    state = layers.fresh_state(1, POINTED)[0]
    posts = np.array([(x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)])  # a wall to go round on its right
    guidance.aim(state, POINTED, Sightings(posts, len(posts)), Robot(0.0, 0.0, math.pi / 2, 0.0, 0.0, 10.0), 0.0, BODY)
    assert state[at.guide_made] == 0.0 and state[at.guide_poses] > 10
    route = row_blocks.route_of(POINTED, state)[:int(state[at.guide_poses])].copy()
    on = Robot(route[3, 0], route[3, 1], route[3, 2], 0.0, 0.0, 10.0)  # the robot drove along it
    guidance.aim(state, POINTED, Sightings(posts, len(posts)), on, 1.0, BODY)
    assert state[at.guide_planned] == 1.0 and state[at.guide_made] == 0.0  # planned again, not searched again
    assert state[at.guide_at] >= 3 and state[at.guide_gear] == 0.0
    # nothing new, but the route older than guide_car_reuse: searched again
    old = state.copy()
    guidance.aim(old, POINTED, Sightings(posts, len(posts)), on, age + 0.5, BODY)
    assert old[at.guide_made] == age + 0.5
    # a post newly seen on the rest of the route: the route is dropped and searched again, round it
    post = route[8, :2]
    seen = np.vstack([posts, post])
    guidance.aim(state, POINTED, Sightings(seen, len(seen)), on, 2.0, BODY)
    assert state[at.guide_made] == 2.0
    fresh = row_blocks.route_of(POINTED, state)[:int(state[at.guide_poses])]
    assert np.hypot(*(fresh[:, :2] - post).T).min() >= BODY - POINTED[layers.PARAM.guide_car_cell] / math.sqrt(2)


def test_a_robot_off_the_kept_route_or_with_another_target_searches_again():
    at = layers.STATE
    posts = np.array([(x, 2.0) for x in np.arange(-4.0, 1.01, 0.1)])
    for moved in (Robot(-1.0, 0.0, math.pi / 2, 0.0, 0.0, 10.0), Robot(0.0, 0.0, math.pi / 2, 0.0, 1.0, 10.0),
                  Robot(0.0, 0.0, 0.0, 0.0, 0.0, 10.0)):  # strayed, another target, turned away
        state = layers.fresh_state(1, POINTED)[0]
        guidance.aim(state, POINTED, Sightings(posts, len(posts)), Robot(0.0, 0.0, math.pi / 2, 0.0, 0.0, 10.0), 0.0,
                     BODY)
        guidance.aim(state, POINTED, Sightings(posts, len(posts)), moved, 1.0, BODY)
        assert state[at.guide_made] == 1.0, moved


def test_an_arc_never_costs_less_than_its_bound_before_its_points_are_tested():
    """The search drops an arc when ``arc_cost`` with the least clearance factor (1) cannot beat the
    node's best cost; that is safe only if a larger factor never gives a smaller cost."""
    rng = np.random.default_rng(5)
    kmax = float(np.abs(SEARCH.curvatures).max())
    for _ in range(2000):
        settings = SEARCH._replace(step=rng.uniform(0.05, 0.5), turn_cost=rng.uniform(0.0, 0.2),
                                   reverse=rng.uniform(1.0, 3.0), switch_cost=rng.uniform(0.0, 0.1))
        kappa = float(rng.choice(SEARCH.curvatures))
        came_by, by, backwards = int(rng.integers(-1, 14)), int(rng.integers(0, 14)), bool(rng.integers(0, 2))
        costs = [car_search.arc_cost(clear, kappa, kmax, backwards, came_by, by, settings)
                 for clear in (1.0, 1.0 + rng.uniform(0.0, 1e-12), 1.0 + rng.uniform(0.0, 3.0))]
        assert costs[0] <= costs[1] <= costs[2]


def _facing_away(shot):
    """The search of the first step of ``benchmarks/sim_core.py``'s robot: 148° off a goal 12.7 m
    away, four lidar hits of an obstacle near the way, with analytic expansions every ``shot``
    expanded nodes (0: none)."""
    hits = np.array([[10.36, 15.55], [10.26, 15.61], [10.19, 15.66], [10.02, 16.0]])
    seen, robot = Sightings(hits, len(hits)), Robot(6.765, 15.48, -2.303, 0.0, 19.0, 19.0)
    radius, low_x, low_y, nx, ny = car_route.frame(seen, robot, RADIUS, BODY, SEARCH.cell)
    grid = car_route.clearance_grid(hits, len(hits), low_x, low_y, nx, ny, SEARCH.cell, radius + SEARCH.comfort)
    start = np.array([robot.x - low_x, robot.y - low_y, robot.theta % (2 * math.pi)])
    goal = np.array([robot.tx - low_x, robot.ty - low_y])
    toward = (int(start[1] / SEARCH.cell), int(start[0] / SEARCH.cell))
    front = car_search.wavefront(grid, SEARCH.cell, int(goal[1] / SEARCH.cell), int(goal[0] / SEARCH.cell), radius,
                                 SEARCH.weight, SEARCH.comfort, toward)
    xs, ys, ths, parents, primitives, end = car_search.search(grid, front.cost.reshape(ny, nx), start, goal, radius,
                                                              SEARCH._replace(shot=shot), front)
    chain = [end]
    while parents[chain[-1]] >= 0:
        chain.append(parents[chain[-1]])
    return len(xs), np.column_stack([xs, ys])[chain[::-1]], primitives[chain[::-1]], goal, grid


def test_an_analytic_expansion_ends_a_search_that_starts_facing_away_at_a_similar_route():
    searched, plain, plain_arcs, goal, _ = _facing_away(0)
    nodes, shot, shot_arcs, _, grid = _facing_away(10)
    assert nodes < searched / 2  # the search no longer spreads over every heading round the start
    assert np.hypot(*(shot[-1] - goal)) <= SEARCH.reach
    assert len(shot) <= len(plain) + 2  # within two arcs (0.4 m) of the search's own route
    assert np.all(shot_arcs[1:] < len(SEARCH.curvatures))  # forward arcs
    cells = (shot / SEARCH.cell).astype(int)
    assert grid[cells[:, 1], cells[:, 0]].min() >= BODY  # clear of the posts


def test_an_analytic_expansion_stops_at_a_wall_across_the_way():
    nodes = SearchNodes(np.zeros(100), np.zeros(100), np.zeros(100), np.full(100, -1), np.full(100, -1))
    nodes.xs[0], nodes.ys[0] = 1.0, 1.0  # facing +x
    grid = np.full((20, 80), RADIUS + SEARCH.comfort)
    goal = np.array([7.0, 1.0])
    end, cost = car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, math.inf)
    assert end == 28 and cost == pytest.approx(5.6)  # 28 straight arcs of 0.2 m: 6.6 m, within 0.5 m of the goal
    grid[:, 40] = RADIUS + SEARCH.comfort / 2  # passable by the search, but within the comfort margin
    assert car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, math.inf)[0] == -1
    grid[:, 40] = 0.0  # a wall across the straight line at x = 4 m
    assert car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, math.inf)[0] == -1


def test_an_analytic_expansion_is_cut_only_where_the_search_would_refuse_it():
    """``shot`` gives up once the path must cost more than the spare cost it is given
    (``car_search.dearer``); the search takes a path of cost c only when c is within that spare.
    So a shot given exactly the cost it reaches the goal at must still reach it, from any pose,
    with the goal at any distance (a last arc that just reaches the goal included)."""
    rng = np.random.default_rng(11)
    nodes = SearchNodes(np.zeros(400), np.zeros(400), np.zeros(400), np.full(400, -1), np.full(400, -1))
    grid = np.full((200, 200), RADIUS + SEARCH.comfort)
    reached, cut = 0, 0
    for trial in range(400):
        nodes.xs[0], nodes.ys[0], nodes.ths[0] = rng.uniform(5.0, 15.0, 2).tolist() + [rng.uniform(0.0, 2 * math.pi)]
        along = SEARCH.reach + SEARCH.step * rng.integers(1, 40) * (1.0 + rng.choice([0.0, 1e-12, -1e-12]))
        if trial % 2:  # straight ahead: the goal exactly whole arcs beyond the reach
            goal = np.array([nodes.xs[0] + along * math.cos(nodes.ths[0]), nodes.ys[0] + along * math.sin(nodes.ths[0])])
        else:
            goal = rng.uniform(2.0, 18.0, 2)
        end, cost = car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, math.inf)
        if end < 0:
            continue
        assert car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, cost) == (end, cost)
        reached += 1
        cut += car_search.shot(grid, goal, RADIUS, SEARCH, nodes, 0, 1, cost - SEARCH.step)[0] < 0
    assert reached > 200 and cut > reached / 2  # a spare too small mostly ends the shot early


def _swapped(heap_f, heap_n, i, j):
    heap_f[i], heap_f[j] = heap_f[j], heap_f[i]
    heap_n[i], heap_n[j] = heap_n[j], heap_n[i]


def _push_by_swaps(heap_f, heap_n, size, f, node):
    """The textbook binary heap's push (the entry swapped up step by step), which the search's
    order of equal keys, and so its route, was made with."""
    i = size
    heap_f[i], heap_n[i] = f, node
    while i > 0 and heap_f[(i - 1) // 2] > heap_f[i]:
        _swapped(heap_f, heap_n, i, (i - 1) // 2)
        i = (i - 1) // 2
    return size + 1


def _pop_by_swaps(heap_f, heap_n, size):
    node, size = heap_n[0], size - 1
    heap_f[0], heap_n[0] = heap_f[size], heap_n[size]
    i = 0
    while True:
        smallest = i
        for child in (2 * i + 1, 2 * i + 2):
            if child < size and heap_f[child] < heap_f[smallest]:
                smallest = child
        if smallest == i:
            return node, size
        _swapped(heap_f, heap_n, i, smallest)
        i = smallest


def test_the_heap_leaves_its_entries_where_swapping_them_would():
    """``push`` and ``pop`` move a hole instead of swapping; with two children an entry (the
    search's heap) the heap they leave, ties included, is the textbook one's, so the search pops
    nodes of equal keys in the same order."""
    rng = np.random.default_rng(2)
    ours = np.empty(3000), np.empty(3000, np.int64)
    textbook = np.empty(3000), np.empty(3000, np.int64)
    size = same_size = 0
    for node, key in enumerate(np.round(rng.uniform(0.0, 5.0, 2000), 1)):  # many equal keys
        size = car_search.push(*ours, size, key, node, 1)
        same_size = _push_by_swaps(*textbook, same_size, key, node)
        for _ in range(min(int(rng.integers(0, 3)), size)):
            assert car_search.pop(*ours, size, 1) == _pop_by_swaps(*textbook, same_size)
            size = same_size = size - 1
        assert size == same_size
        assert np.array_equal(ours[0][:size], textbook[0][:size]) and np.array_equal(ours[1][:size], textbook[1][:size])


def test_the_cells_an_arc_can_sample_share_the_clearance_the_search_takes_for_them():
    """Where every cell near an arc's chord has one clearance (``car_search.uniform``), the search
    takes it for each sample without computing them: every sample, computed as the search does,
    must lie in a cell of that clearance, on any arc of the search's set from any pose."""
    rng = np.random.default_rng(4)
    grid = np.where(rng.random((60, 60)) < 0.02, 0.5, 0.6)  # rare cells of another clearance
    kappas, step, samples, taken = SEARCH.curvatures, SEARCH.step, 4, 0
    for _ in range(20000):
        x, y, theta = *rng.uniform(0.5, 5.5, 2), rng.uniform(0.0, 2 * math.pi)
        kappa, length = float(rng.choice(kappas)), step * rng.choice([-1.0, 1.0])
        points = [car_search.arc_point(x, y, theta, kappa, length * j / samples)[:2] for j in range(1, samples + 1)]
        shared = car_search.uniform(grid, SEARCH.cell, (x, y), points[-1], step, kappa)
        if shared >= 0:
            taken += 1
            assert all(grid[int(math.floor(py / SEARCH.cell)), int(math.floor(px / SEARCH.cell))] == shared
                       for px, py in points)
    assert taken > 10000
    grid[:30] = 0.5  # below y = 3 m: arcs whose chord lies just above it dip into it by their sagitta
    for kappa in kappas[kappas > 0]:
        sagitta = step * step * kappa / 8.0
        for above in (0.3, 0.8, 0.95):
            x, y, theta = 2.0, 3.0 + above * sagitta, -kappa * step / 2.0  # a chord along +x
            points = [car_search.arc_point(x, y, theta, kappa, step * j / samples)[:2] for j in range(1, samples + 1)]
            assert min(py for _, py in points) < 3.0  # the middle sample in the row below
            assert car_search.uniform(grid, SEARCH.cell, (x, y), points[-1], step, kappa) == -1.0


def test_a_target_beyond_the_largest_grid_gets_no_plan_and_no_grid():
    """A goal farther than the largest grid (``route.MAX_CELLS``: a box of 100 m at the car
    route's 0.1 m cells) is left to the reactive layers: neither search builds the grid, whose
    arrays would otherwise exhaust the memory (a 3 km world once failed to allocate 57 GB). Just
    inside the bound both still plan."""
    from fuzzynav.kernels import route

    post = np.array([[3.0, 0.4]])
    side = math.sqrt(route.MAX_CELLS) * SEARCH.cell  # the box's side at the bound, margins included
    ahead = (0.0, 0.0, math.pi / 4)  # heading to the goal: a straight route, found at once where a grid is built
    near = side - 2 * car_route.MARGIN - 1.0  # the box, margins included, just inside the bound
    assert _plan(post, ahead, (near, near))[0]
    found, poses, primitives = _plan(post, ahead, (side + 20.0, side + 20.0))
    assert not found and poses.shape == (1, 3) and primitives.tolist() == [-1]
    sightings = Sightings(post, 1)
    assert not route.target(sightings, 0.0, 0.0, 300.0, 300.0, 0.5, 2.0)[0]  # 0.25 m cells: 250 m at most
    assert route.target(sightings, 0.0, 0.0, 100.0, 100.0, 0.5, 2.0)[0]
