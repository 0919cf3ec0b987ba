"""Loop and trap escape of the default chapter IV navigators: circling detection and boundary
following, in the spirit of the Bug algorithms (V. Lumelsky, A. Stepanov, "Path-planning
strategies for a point mobile automaton moving amidst unknown obstacles of arbitrary shape",
Algorithmica 2, 1987; the leaving rule of DistBug, I. Kamon, E. Rivlin, IEEE Trans. Robotics
and Automation 13(6), 1997).

A reactive navigator can circle for ever: around a group of obstacles, or inside a U-shaped
wall whose opening faces away from the goal, goal seeking turns the robot back into the
pocket each time the avoiders have brought it out. The Bug algorithms end this with a memory
of one number: on meeting an obstacle, record the distance to the goal (the *hit* distance),
follow the obstacle's boundary, and leave it only where the goal is nearer than that and the
way towards it is free.

- the loop detector says when the robot circles: it is back within ``revisit`` of a place
  it passed at least ``min_lap`` ago (and at most ``horizon``), and its best distance to the
  goal has not improved by ``loop_gain`` for ``patience``.
- boundary following is the escape mode (``BF``). It drives the navigator's own
  behaviours towards a *virtual goal*: a point 2.5 m along the shortest route to the goal round
  the obstacles remembered so far (:mod:`fuzzynav.kernels.route`, unseen space assumed free),
  which runs along the boundaries of what traps the robot, on the side the memory says is
  shorter; the navigator's avoiders keep it off the boundary. Only where the memory leaves no
  route does it fall back on following one side: the virtual goal ``offset`` to that side of
  the heading, ``reach`` ahead (``search``, nearer the heading, while no obstacle is near), so
  goal seeking pulls the robot towards the boundary and the avoiders push it away, the way the
  thesis' navigator runs along the U-wall of Fig IV.23. The mode ends — the real goal handed
  back — when the goal is ``leave_gain`` nearer than the hit distance, taken as the best distance
  reached before following (DistBug's d_min), and the range ray nearest the goal direction reads
  the way free for ``free`` (or up to the goal); or after ``follow_time``. (DistBug's own rule,
  leave where the free range towards the goal would beat d_min, hands a reactive navigator back
  to the loop it was caught in: its way to the goal is not the straight line.) The side
  followed without a route is the nearest obstacle's; after a following that ran out of time,
  or looped, the next one takes the other side.

Both run compiled (:mod:`fuzzynav.kernels.escape`); this module holds their constants.
"""

from __future__ import annotations

import math

from fuzzynav.kernels.layers import Follow, Loop

# the loop detector and boundary following (their units and meaning: kernels.layers.Loop, Follow)
LOOP = Loop(revisit=1.5, min_lap=8.0, patience=20.0, loop_gain=0.5, sample_every=0.5, horizon=90.0)
FOLLOW = Follow(offset=math.radians(75.0), search=math.radians(25.0), near=2.0, reach=3.0, leave_gain=0.5, free=2.0,
                follow_time=40.0, room=0.7, tight=0.2, ahead=2.5, replan=1.0)
