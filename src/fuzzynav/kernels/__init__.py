"""The compiled hot path: one implementation, plain loops compiled with numba, serving one robot
and a batch alike (one robot is a batch of one; the loops over robots are inside the kernels).

- :mod:`~fuzzynav.kernels.angles` — the angle convention (wrap to (−π, π]), for floats, arrays and
  the kernels;
- :mod:`~fuzzynav.kernels.scene` — rays of a sensor ring and the nearest obstacle against
  circles, polygons (walls are rectangles), ellipses and the boundary, with a broad phase;
- :mod:`~fuzzynav.kernels.motion` — angle wrapping, command clipping, tricycle kinematics
  (eq IV.2 and the exact arc of eq IV.1);
- :mod:`~fuzzynav.kernels.ts0` — strong-partition TS0 systems evaluated from their breakpoint
  and coefficient arrays (so an edited rule table runs compiled too);
- :mod:`~fuzzynav.kernels.guard` — the supervisor's selection and switch, hit memory, cone
  echo, turning room and safety stop of the chapter IV navigators;
- :mod:`~fuzzynav.kernels.navigators` — the navigators' ``act``;
- :mod:`~fuzzynav.kernels.robust` — the default navigators' ``act``: any navigator inside the
  recovery (:mod:`~fuzzynav.kernels.recovery`) and loop-escape (:mod:`~fuzzynav.kernels.escape`,
  :mod:`~fuzzynav.kernels.route`) layers and the route guidance of the default ``fuzzy-5b``
  (:mod:`~fuzzynav.kernels.guidance`), on the obstacle points seen
  (:mod:`~fuzzynav.kernels.sightings`), arrays laid out in :mod:`~fuzzynav.kernels.layers`;
- :mod:`~fuzzynav.kernels.step` — the simulator's step: clip, move, stop tests, sense;
- :mod:`~fuzzynav.kernels.threats` — the yield layer's times to collision with moving obstacles,
  from the echoes that moved off the scan before (:mod:`~fuzzynav.kernels.outline`) and the
  obstacles tracked over the scans (:mod:`~fuzzynav.kernels.scan_tracks`).

Every kernel is a module-level function over arrays (no closures), compiled on first use and
cached on disk (:func:`fuzzynav.jit.jit`). ``NUMBA_DISABLE_JIT=1`` runs the very
same code as plain Python, the way to debug it. Importing this package does not import numba.
"""
