"""Classic navigators of the literature, for comparison with the thesis' ones on the same robot.

All drive the same tricycle (eq IV.1: no reverse gear, |α| ≤ π/4) and, except ``astar-pp``, see
only what the thesis' navigators see: the seven range readings C1…C7 (remembered over the last
second, :mod:`fuzzynav.control.classic.local_map`) and the nearest obstacle point (D_ro, θ_o).

- ``dwa`` — Dynamic Window Approach (Fox, Burgard & Thrun 1997), :mod:`.dwa`;
- ``apf`` — artificial potential field (Khatib 1986), :mod:`.apf`;
- ``vfh`` — VFH+ (Ulrich & Borenstein 1998), :mod:`.vfh`;
- ``astar-pp`` — **map-aware** reference: shortest path on the inflated map (A*), followed with
  pure pursuit, :mod:`.astar_pp`. It knows the whole map, which no reactive navigator does.
"""
