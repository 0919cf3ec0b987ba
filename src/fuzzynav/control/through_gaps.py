"""The gap-aware five-behaviour navigator inside the recovery and loop-escape layers, guided by
a route round the obstacles seen so far: ``fuzzy-5b``, the default five-behaviour navigator
(``fuzzy-5b-gap-robust`` is another name of it; the one on the seven range sensors it replaced
as the default is ``fuzzy-5b-rays``, :mod:`fuzzynav.control.robust`).

- The inner navigator is the compiled ``fuzzy-5b-gap`` (:mod:`fuzzynav.control.five_behaviours`:
  the lidar ring, readings by sector, VFH+-style gap finding with follow-the-gap's choice nearest
  to the goal).
- The route guidance (:mod:`fuzzynav.kernels.guidance`) aims it along the shortest route to the
  goal round the obstacle points remembered so far, unseen space assumed free (the freespace
  assumption of D*, Stentz 1994): the navigator is given a goal in the direction of the point
  ``guide_ahead`` m along that route, at the goal's distance, so Table IV.1 and the gap finder
  steer towards the passage the route takes instead of the straight line's, while the fuzzy
  behaviours keep the body off what the memory has not seen yet. This is the split of the ROS
  navigation stack that the BARN challenge's DWA baseline runs (a global planner on the sensed
  costmap, a local controller following it). The route keeps the body's radius plus
  ``guide_room``, else ``guide_narrow``, else ``guide_bare`` (none: the real goal); where the
  straight line to the goal keeps the radius plus ``guide_room`` from every remembered point for
  ``guide_direct`` m, the goal itself is given.
- Before that grid route, the guidance plans a route the car can drive (``guide_car_*``,
  :mod:`fuzzynav.kernels.car_route`): hybrid A* (Dolgov et al. 2008) with forward and backward
  arcs at the navigator's full lock (Reeds & Shepp 1990), on the remembered points, from the
  robot's pose, so the route respects the 0.69 m turning radius and holds the K-turns a tight
  chamber needs. Where it stays ``guide_car_tight`` m (2 m) clear of what was seen, the navigator
  follows its point ``guide_car_ahead`` m ahead; where it passes closer (a corridor, a door, the
  posts of a forest) or turns back at a cusp, the layer drives its arcs (``CAR-FWD`` at
  ``guide_car_speed``, ``CAR-BACK`` at the recovery's backing speed, each step checked against
  the remembered points) and plans again after each — after a back-up in the same step
  (``guide_car_chain``), so that the navigator does not drive forward over what was just backed.
  The grid route is the fallback when the search gives up within ``guide_car_budget`` nodes.
  Its search ends ``guide_car_reach`` m from the goal, or within :data:`GOAL_SHARE` of the goal's
  tolerance where that is nearer (told by the simulator: ``for_goal``), so that where the route
  ends the goal is reached, not passed 0.4 m off to one side.
- The pace (:mod:`fuzzynav.kernels.pace`, ``pace_*``): where the navigator drives (not the
  layers' manoeuvres), its speed is raised to the one that leaves ``pace_horizon`` s of travel on
  the arc of its steering before the body comes within ``pace_room`` m of a lidar hit (at most
  the robot's top speed and the target's distance per ``pace_goal`` s), when the safety stop's
  test passes at that speed; the thesis' speeds (Table IV.1, VRB) stay the floor. With ``pace_car``
  the car route's forward arcs are paced alike (on the arc's curvature, ``guide_car_speed`` the
  floor, the recovery's safety test passing at the speed, never past the arc's end).
- Among moving obstacles only (the simulator says so: ``for_traffic``), the yield / evade layer
  with tracked obstacles (:mod:`fuzzynav.control.yield_layer`, that of ``fuzzy-5b-yield-tracks``)
  adjusts the command: it predicts the obstacles from successive scans and speeds the robot out of
  the way of, or slows and swerves from, what would run into it; when the command it leaves would
  still meet a predicted track, a sampled evasive command replaces it (:mod:`fuzzynav.kernels.evasion`).
- :class:`~fuzzynav.control.robust.RobustNavigator` around both adds the reversing recovery
  (``REC-BACK``, ``REC-TURN``) that leaves a pocket the car cannot leave forwards, and the loop
  escape (``BF``) when the robot circles anyway; the guidance aims at the escape's virtual goal
  while it follows a boundary.

All three layers run inside the simulator's compiled step (:mod:`fuzzynav.kernels.robust`); the
yield layer, among moving obstacles only, runs in Python after it, so a static scenario's run is
the compiled step's alone, unchanged.
"""

from __future__ import annotations

import math
from dataclasses import fields, replace

from fuzzynav import validation
from fuzzynav.control.robust import BARRIER, RobustNavigator
from fuzzynav.control.yield_layer import YieldLayer
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.kernels.layers import Guidance, Pace
from fuzzynav.settings import ROOM, SHARE, STEERING, Range, checked, within

# the route guidance and its car route (units and meaning: kernels.layers.Guidance); the car's
# steering values span Fig IV.7's largest singleton
GUIDANCE = Guidance(guide=1.0, guide_cell=0.15, guide_ahead=1.5, guide_replan=1.0, guide_direct=3.0,
                    guide_room=0.1, guide_narrow=0.05, guide_bare=0.0,
                    guide_car=1.0, guide_car_room=0.0, guide_car_step=0.2, guide_car_node=0.1,
                    guide_car_headings=72, guide_car_weight=3.0, guide_car_comfort=0.3, guide_car_turn=0.1,
                    guide_car_switch=0.05, guide_car_reach=0.5, guide_car_budget=60000, guide_car_reverse=2.0,
                    guide_car_gear=1.0, guide_car_cell=0.1, guide_car_steerings=7, guide_car_steering=ALPHA_MAX,
                    guide_car_ahead=1.0, guide_car_tight=2.0, guide_car_speed=0.8,
                    guide_car_reuse=5.0, guide_car_keep=0.1, guide_car_stray=0.3, guide_car_swerve=0.5,
                    guide_car_chain=1.0, guide_off_heading=math.pi / 6, guide_car_shot=10)
GOAL_SHARE = 0.8  # the car route ends within this share of the goal's tolerance (RobustNavigator.for_goal)
# the pace (units and meaning: kernels.layers.Pace)
PACE = Pace(pace=1.0, pace_room=0.05, pace_horizon=1.25, pace_goal=1.0, pace_car=1.0)


# the ranges of the settings the kernels' reasoning needs (:mod:`fuzzynav.settings`; any other
# must be a finite number): the sizes, lengths and periods they divide by or step with are > 0, the
# rooms, costs and angles >= 0 (the car route's wavefront is exact only for a clearance weight >= 0),
# the steering of the arcs below a right angle; the counts are whole numbers (:data:`WHOLE`)
MAX = validation.MAX_MAGNITUDE
ANY, ABOVE_0, AT_LEAST_0 = Range(-MAX, MAX), Range(0.0, MAX, lo_open=True), Range(0.0, MAX)
BOUNDS: dict[str, Range] = {
    **dict.fromkeys(("guide_cell", "guide_car_step", "guide_car_node", "guide_car_cell", "guide_car_reach",
                     "guide_car_speed", "pace_horizon", "pace_goal"), ABOVE_0),
    **dict.fromkeys((
        "guide_ahead", "guide_replan", "guide_direct", "guide_room", "guide_narrow", "guide_bare", "guide_car_room",
        "guide_car_weight", "guide_car_comfort", "guide_car_turn", "guide_car_switch", "guide_car_reverse",
        "guide_car_gear", "guide_car_ahead", "guide_car_tight", "guide_car_reuse", "guide_car_keep",
        "guide_car_stray", "guide_car_swerve", "pace_room"), AT_LEAST_0),
    "guide_off_heading": Range(0.0, math.pi),
    "guide_car_steering": STEERING,
}
# the counts: heading bins of a search node, steering values of its arcs (both ends at least),
# nodes before it gives up (each costs about 100 bytes), expanded nodes between analytic expansions
# (whole numbers, as floats too: the kernels' records hold them as floats)
WHOLE = {"guide_car_headings": Range(1, 3600), "guide_car_steerings": Range(2, 101),
         "guide_car_budget": Range(1, 10_000_000), "guide_car_shot": Range(0, 10**9)}


def _setting(name: str, value, field: str) -> float:
    """``value`` of the setting ``name`` checked against :data:`BOUNDS` and :data:`WHOLE`."""
    where = f"{field}.{name}"
    number = within(value, where, WHOLE.get(name) or BOUNDS.get(name, ANY))
    if name in WHOLE and not number.is_integer():
        validation.fail(f"must be a whole number, got {validation.shown(value)}", field=where)
    return number


def _replaced(record, values: dict | None, field: str):
    """``record`` with the fields named in ``values`` (an option of the factory) replaced; an
    unknown name, or a value that is not a finite number within :data:`BOUNDS` (a whole one within
    :data:`WHOLE`), is an :class:`~fuzzynav.errors.InputError` naming the option."""
    names = {item.name for item in fields(record)} - {"guide", "pace"}
    unknown = sorted(set(validation.mapping(values, field=field) if values is not None else {}) - names)
    if unknown:
        raise InputError(f"{field} has no {unknown}; it takes {sorted(names)}", field=field)
    return replace(record, **{name: _setting(name, value, field) for name, value in (values or {}).items()})


@checked(barrier=BARRIER, barrier_within=ROOM, goal_share=SHARE)
def fuzzy_5b_gap_robust(*, recovery: bool = True, escape: bool = True, guidance: dict | None = None,
                        paced: bool = True, pace: dict | None = None, forget_moving: bool = True,
                        yield_in_traffic: bool = True, evade: bool = True, barrier: float = 0.5,
                        barrier_within: float = 0.05, goal_share: float = GOAL_SHARE, **options) -> RobustNavigator:
    """``fuzzy-5b`` (and ``fuzzy-5b-gap-robust``): ``fuzzy-5b-gap`` (``options`` go to it), route-guided
    (``guidance``: values replacing those of :data:`GUIDANCE`), paced by the room ahead (``pace``:
    values replacing those of :data:`PACE`), with recovery and loop escape (either, and the pace,
    can be switched off: ``paced=False`` drives at the thesis' speeds, as version 2 did;
    ``forget_moving=False`` keeps every point seen among moving obstacles, as version 4 did;
    ``yield_in_traffic=False`` runs no yield layer among them, as version 6 did; ``evade=False``
    runs it without the last check of its command against the tracks' predicted motion
    (:mod:`fuzzynav.kernels.evasion`), as version 8 did; ``guidance={"guide_car_chain": 0}`` lets the
    navigator drive the step after a back-up of the car route, as version 9 did; ``goal_share=0``
    ends the car route ``guide_car_reach`` m from the goal whatever its tolerance, as version 10 did;
    ``guidance={"guide_car_tight": 0.5}`` lets the navigator drive wherever the route keeps 0.5 m
    beyond the radius, as version 11 did; ``guidance={"guide_off_heading": 0}`` steers straight at
    a target the line to which is free wherever it is, as version 12 did; ``guidance={"guide_car_shot": 0}``
    searches a route to a target off the heading to its end, without analytic expansions, as version 13 did;
    ``pace={"pace_horizon": 1.5}`` leaves 1.5 s of travel ahead where the pace raises the speed, as
    version 14 did;
    ``barrier`` > 0 lets the recovery back on steps that close that share of the body's gap
    (:func:`fuzzynav.kernels.recovery.may_step`) during the first ``barrier_within`` m of a
    back-up (0: throughout, the turn included); ``barrier=0`` backs only on safe steps, as
    version 7 did)."""
    from fuzzynav.control.five_behaviours import FiveBehaviourNavigator

    navigator = FiveBehaviourNavigator(gap=True, **options)
    navigator.name = "fuzzy-5b-gap-robust"
    return RobustNavigator(navigator, navigator.name, recovery=recovery, escape=escape, barrier=barrier,
                           barrier_within=barrier_within,
                           guidance=_replaced(GUIDANCE, guidance, "guidance"),
                           pace=_replaced(PACE, pace, "pace") if paced else None, compensate=True,
                           forget_moving=forget_moving, goal_share=goal_share,
                           traffic=YieldLayer(tracks=True, evade=evade) if yield_in_traffic else None)
