"""Chapter VI's claims can fail: numbers that contradict the thesis give a failed check and a verdict
other than "reproduced"; numbers that agree give "reproduced"."""

import pytest

from fuzzynav.catalog import experiments as registry
from fuzzynav.experiments.chapter6 import rank_correlation
from fuzzynav.experiments.claims import NOT_REPRODUCED, PARTLY, REPRODUCED
from fuzzynav.experiments.claims_vi import relative_over_seeds


def verdict(key, numbers):
    return registry.spec(key).claim.evaluate(numbers)


def goal_numbers(converged=2000, budget=2250, success=1.0, stopped=0.95, speed=(-0.1, -0.02), **extra):
    return {"converged_at": {"steering": converged, "speed": None}, "episodes": {"steering": budget, "speed": 750},
            "curve": {"speed": {"first": speed[0], "last": speed[1]}},
            "evaluation": {"runs": 100, "success": success, "stopped": stopped}, **extra}


def test_fig_vi_9_fails_when_the_robot_does_not_stop_or_the_speed_curve_falls():
    assert verdict("fig-VI-9", goal_numbers())[0] == REPRODUCED
    state, checks = verdict("fig-VI-9", goal_numbers(stopped=0.3))  # arrives at 1-3 m/s
    assert state == PARTLY and [c.name for c in checks if not c.passed] == ["runs reaching the goal at ≤ 0.2 m/s (of 100)"]
    state, checks = verdict("fig-VI-9", goal_numbers(speed=(0.0, -0.05)))  # a falling curve
    assert state == PARTLY and not checks[1].passed
    assert verdict("fig-VI-9", goal_numbers(converged=None, success=0.2, stopped=0.0, speed=(0, 0)))[0] == NOT_REPRODUCED


def test_relative_claims_need_the_thesis_order():
    small = {"converged_at": 1800, "episodes": 2250}
    assert verdict("fig-VI-13", goal_numbers(2600, 3000, rules_15=small))[0] == REPRODUCED
    state, checks = verdict("fig-VI-13", goal_numbers(1500, 3000, rules_15=small))  # 35 rules faster than 15
    assert state == PARTLY and not checks[1].passed
    both_unconverged = verdict("fig-VI-13", goal_numbers(None, 3000, rules_15={"converged_at": None, "episodes": 2250}))
    assert not both_unconverged[1][1].passed  # nothing converged: no order to claim
    assert verdict("fig-VI-16", goal_numbers(900, 1500, no_traces={"converged_at": 1400, "episodes": 2250}))[0] == REPRODUCED
    assert not verdict("fig-VI-16", goal_numbers(900, 1500, no_traces={"converged_at": 600, "episodes": 2250}))[1][1].passed
    fixed = {"converged_at": {"steering": 200}, "episodes": {"steering": 1000}, "trajectories": ["reached"]}
    assert verdict("fig-VI-8", {**fixed, "q_learning": {"converged_at": 900, "episodes": 1500}})[0] == REPRODUCED
    assert verdict("fig-VI-8", {**fixed, "q_learning": {"converged_at": 100, "episodes": 1500}})[0] == PARTLY


def test_relative_claims_over_seeds_compare_medians_not_the_best_seed():
    def runs(pairs):  # fig-VI-13: (35 rules, 15 rules) episodes to converge per seed
        return [goal_numbers(big, 3000, rules_15={"converged_at": small, "episodes": 2250}) for big, small in pairs]
    slower = relative_over_seeds("fig-VI-13", runs([(900, 600), (1200, 700), (500, 650), (800, 500), (1000, 640)]))
    assert slower.passed and slower.value["medians"] == [900.0, 640.0]
    once = relative_over_seeds("fig-VI-13", runs([(323, 522), (135, 698), (955, 635), (400, 501), (300, 654)]))
    assert not once.passed and once.value["slower"] == [323, 135, 955, 400, 300]  # slower on one seed of five
    unconverged = relative_over_seeds("fig-VI-13", runs([(None, 600), (None, 700), (500, 650)]))
    assert unconverged.passed and unconverged.value["medians"][0] == 3001  # not converged: budget + 1
    fixed = {"converged_at": {"steering": 480}, "episodes": {"steering": 1000}, "trajectories": ["reached"]}
    tabular = [{**fixed, "q_learning": {"converged_at": e, "episodes": 1500}} for e in (175, 222, 95)]
    assert not relative_over_seeds("fig-VI-8", tabular).passed
    assert not relative_over_seeds("fig-VI-16", []).passed  # no seed, no claim


def avoid_numbers(**changes):
    numbers = {"converged_at": {"steering": 300, "speed": 900}, "episodes": {"steering": 1000, "speed": 1000},
               "collisions_first_20": 4, "wall_following": "reached", "rules_changed": 12, "rules_learned": 14,
               "evaluation": {"runs": 100, "success": 0.95, "collisions": 0},
               "initial_table": {"runs": 100, "success": 0.4, "collisions": 60}}
    return {**numbers, **changes}


@pytest.mark.parametrize("changes, failing", [
    ({"rules_changed": 0}, "rules that differ from the initial table (q = 0)"),  # the learned table is the start
    ({"collisions_first_20": 0}, "collisions in training episodes 1–20 (Figs VI.18–VI.19)"),
    ({"wall_following": "timeout"}, "after learning, along a wall to its goal (Fig VI.21)"),
    ({"evaluation": {"runs": 100, "success": 0.94, "collisions": 6}}, "collisions on the random worlds"),
    ({"initial_table": {"runs": 100, "success": 0.95, "collisions": 0}}, "success of the initial table on the same worlds"),
    ({"evaluation": {"runs": 300, "success": 0.85, "collisions": 0}}, "success on 300 random obstacle worlds"),
])
def test_fig_vi_22_fails_when_avoidance_was_not_learned(changes, failing):
    assert verdict("fig-VI-22", avoid_numbers())[0] == REPRODUCED
    state, checks = verdict("fig-VI-22", avoid_numbers(**changes))
    assert state == PARTLY and failing in [c.name for c in checks if not c.passed]


def test_a_fixed_start_run_fails_when_its_learned_route_misses_the_goal():
    fixed = {"converged_at": {"steering": 200}, "episodes": {"steering": 1000}, "trajectories": ["reached"]}
    assert verdict("fig-VI-1", fixed)[0] == REPRODUCED
    state, checks = verdict("fig-VI-1", {**fixed, "trajectories": ["collision"]})
    assert state == PARTLY and [c.name for c in checks if not c.passed] == ["trajectory after learning"]


def test_fig_vi_24_needs_both_navigators_to_reach_a_blocked_goal():
    numbers = {"world": "blocked world 3", "fuzzy": {"outcome": "reached"}, "fql": {"outcome": "reached"}}
    assert verdict("fig-VI-24", numbers)[0] == REPRODUCED
    assert verdict("fig-VI-24", {**numbers, "fql": {"outcome": "collision"}})[0] == PARTLY


def wall_numbers(learned=("reached", "reached"), handmade=("collision", "collision"), collisions=(2, 40)):
    return {"corners": {"wall-follow": dict(zip("ab", handmade)), "fql-wall": dict(zip("ab", learned))},
            "evaluation": {"fql-wall": {"courses": 100, "collisions": collisions[0]},
                           "wall-follow": {"courses": 100, "collisions": collisions[1]}}}


def test_fig_vi_29_a_timeout_at_a_corner_or_too_many_collisions_fails():
    assert verdict("fig-VI-29", wall_numbers())[0] == REPRODUCED
    assert not verdict("fig-VI-29", wall_numbers(learned=("reached", "timeout")))[1][1].passed  # stopped following
    assert not verdict("fig-VI-29", wall_numbers(collisions=(9, 40)))[1][2].passed  # more than a fifth
    assert verdict("fig-VI-29", wall_numbers(handmade=("reached", "collision")))[0] == PARTLY


def rows(episodes):
    sizes = ((9, 3, 3260), (11, 3, 4100), (13, 3, 6200), (19, 5, 8950))
    return [{"states": s, "actions": a, "thesis_episodes": t, "episodes": 10000, "episodes_to_converge": e,
             "success": 0.9} for (s, a, t), e in zip(sizes, episodes)]


def test_table_vi_1_needs_the_trend_not_only_convergence():
    increasing, scrambled = rows([1000, 2000, 2500, 6000]), rows([850, 100, 250, 500])  # the latter: audit's seed 0
    assert rank_correlation(increasing) == 1.0 and rank_correlation(scrambled) == -0.2
    assert verdict("table-VI-1", {"rows": increasing, "rank_correlation": 1.0})[0] == REPRODUCED
    state, checks = verdict("table-VI-1", {"rows": scrambled, "rank_correlation": rank_correlation(scrambled)})
    assert state == PARTLY and not checks[0].passed
    one_unconverged = rows([1000, 2000, None, 6000])  # ranked last: ρ 0.8, the trend still holds
    state, checks = verdict("table-VI-1", {"rows": one_unconverged, "rank_correlation": rank_correlation(one_unconverged)})
    assert state == PARTLY and [c.name for c in checks if not c.passed] == ["13 × 3: episodes to converge (thesis 6200)"]
    unconverged = rows([None, None, None, None])
    assert rank_correlation(unconverged) is None
    assert not verdict("table-VI-1", {"rows": unconverged, "rank_correlation": None})[1][0].passed
    assert rank_correlation(rows([1000, None, 3000, None])) > 0  # not converged ranks after the converged
