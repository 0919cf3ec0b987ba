"""The evasive command of ``fuzzy-5b`` version 9 (kernels/evasion.py): a command on a collision
course with a predicted track is replaced by one of a sampled fan that keeps clear of the tracks
and, when one does, of the standing echoes; closed loop, it gets through a world where version 8
is run into."""

import numpy as np

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.control.through_gaps import fuzzy_5b_gap_robust
from fuzzynav.kernels import evasion, scan_tracks
from fuzzynav.kernels.records import Scans
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import run_episode
from fuzzynav.world.generate import generate_world

ROBOT = DEFAULT_PARAMS.array()
T = 1.0  # s, the tracks' time now


def one_track(centre, velocity, radius=0.3):
    """Robot 0's tracks: one confirmed track seen every 0.1 s up to ``T``, now at ``centre``."""
    tracks = scan_tracks.empty(1)
    times = T - 0.1 * np.arange(scan_tracks.WINDOW)[::-1]
    tracks.times[0, 0] = times
    tracks.centres[0, 0] = np.asarray(centre) + np.outer(times - T, velocity)
    tracks.sightings[0, 0], tracks.radius[0, 0], tracks.count[0] = scan_tracks.WINDOW, radius, 1
    tracks.velocity[0, 0] = velocity
    return tracks


def scan(points=None):
    """Robot 0's scan: ``points`` (P, 2) as echoes (none: nothing in reach)."""
    points = np.zeros((1, 2)) if points is None else np.asarray(points, dtype=float)
    valid = np.ones(len(points), dtype=bool) if len(points) > 1 else np.zeros(1, dtype=bool)
    return Scans(points[None], valid[None], np.zeros((1, 2)))


def evade(command, tracks, echoes=None):
    """(evaded?, the command left) for robot 0 at the origin heading along +x."""
    steering, speed = np.array([command[0]]), np.array([command[1]])
    evaded = evasion.evade(np.zeros((1, 3)), steering, speed, np.ones(1, dtype=bool), tracks, scan(echoes), ROBOT, T)
    return bool(evaded[0]), (float(steering[0]), float(speed[0]))


def gaps(command, tracks, echoes=None):
    """(gap to the tracks, gap to the echoes) of ``command`` held from the origin."""
    path = np.empty((int(round(evasion.HORIZON / DEFAULT_PARAMS.dt)), 2))
    evasion.rollout(np.zeros(3), command[0], command[1], ROBOT, path)
    centres, velocities, radii = np.empty((4, 2)), np.empty((4, 2)), np.empty(4)
    m = evasion.tracks_now(tracks, 0, T, False, centres, velocities, radii)
    points = np.zeros((1, 2)) if echoes is None else np.asarray(echoes, dtype=float)
    return (evasion.track_gap(path, DEFAULT_PARAMS.dt, centres, velocities, radii, m, DEFAULT_PARAMS.radius),
            evasion.standing_gap(path, points, 0 if echoes is None else len(points), DEFAULT_PARAMS.radius))


def test_a_command_that_keeps_clear_is_left_alone():
    away = one_track((3.0, 0.0), (2.0, 0.0))  # ahead, drawing away faster than the robot drives
    assert evade((0.0, 1.0), away) == (False, (0.0, 1.0))
    aside = one_track((0.0, 3.0), (1.0, 0.0))  # passing well to the left
    assert evade((0.0, 1.0), aside) == (False, (0.0, 1.0))


def test_a_head_on_track_is_evaded():
    head_on = one_track((3.0, 0.0), (-1.0, 0.0))
    assert gaps((0.0, 1.0), head_on)[0] < evasion.TRIGGER
    evaded, command = evade((0.0, 1.0), head_on)
    assert evaded and command != (0.0, 1.0)
    assert gaps(command, head_on)[0] >= evasion.MARGIN


def test_a_robot_crossed_from_the_side_gets_out_of_the_way():
    """Standing still, a disc coming from the left at 1 m/s would hit it; it drives or backs off."""
    crossing = one_track((0.0, 2.0), (0.0, -1.0))
    evaded, command = evade((0.0, 0.0), crossing)
    assert evaded and command[1] != 0.0
    assert gaps(command, crossing)[0] >= evasion.MARGIN


def test_never_through_what_stands_when_a_command_keeps_off_it():
    """A mover will hit the robot whatever it does (it comes fast from behind and the robot
    cannot outrun it), and a wall stands just ahead: the fallback (the most room) must not drive
    into the wall."""
    chasing = one_track((-1.5, 0.3), (5.0, 0.0), radius=0.5)
    wall = np.column_stack([np.full(41, 0.45), np.linspace(-2.0, 2.0, 41)])
    evaded, command = evade((0.0, 0.0), chasing, wall)
    assert evaded
    assert gaps(command, chasing, wall)[1] >= 0.0
    assert command[1] <= 0.0  # into the wall is the only way that does not back off


def test_it_gets_through_a_world_where_version_8_is_run_into():
    """``dynamic`` seed 5 (a development seed), world 2: version 8 is run into; version 9 evades
    (``EVADE``) and reaches the goal (both driving the car route's arcs in tight places only, as
    then); today's default reaches it too."""
    scenario = generate_world("dynamic", 5, 2)
    then = {"guidance": {"guide_car_tight": 0.5, "guide_off_heading": 0.0}, "pace": {"pace_horizon": 1.5}}
    before = run_episode(scenario, fuzzy_5b_gap_robust(evade=False, **then), seed=0)
    assert before.outcome == "collision"
    after = run_episode(scenario, fuzzy_5b_gap_robust(**then), seed=0)
    assert after.outcome == "reached"
    assert "EVADE" in set(after.behaviour)
    assert run_episode(scenario, make_controller("fuzzy-5b"), seed=0).outcome == "reached"
