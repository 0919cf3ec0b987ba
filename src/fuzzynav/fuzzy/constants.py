"""The thesis' numbers that more than one module uses, each defined once.

- :data:`ALPHA_MAX` — α_max = π/5 rad, the largest steering singleton of Fig IV.7 (NG / PG): the
  full-lock turn of the navigators, their recovery and turning-room checks;
- :data:`STEERING_SINGLETONS` — α of Fig IV.7, NG … PG = −π/5, −π/10, −π/20, 0, π/20, π/10, π/5 rad;
- :data:`SPEED_SINGLETONS` — V_r of Fig IV.8, Z 0, F 1, M 1.8, G 3, TG 4 m/s.

The fuzzy library, the compiled kernels, the controllers and the world generator import them
from here; ``grep`` finds one definition of each.
"""

from __future__ import annotations

import math

ALPHA_MAX = math.pi / 5  # rad, Fig IV.7
STEERING_SINGLETONS = {"NG": -ALPHA_MAX, "NM": -math.pi / 10, "NP": -math.pi / 20, "Z": 0.0,
                       "PP": math.pi / 20, "PM": math.pi / 10, "PG": ALPHA_MAX}  # rad, Fig IV.7
SPEED_SINGLETONS = {"Z": 0.0, "F": 1.0, "M": 1.8, "G": 3.0, "TG": 4.0}  # m/s, Fig IV.8
