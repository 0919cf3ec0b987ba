"""Tabular temporal-difference learners (thesis §III.4.9, §VI.2) and the (d_rg, θ_rg) discretiser.

:class:`TabularLearner` implements, over integer states and actions,

- Q-learning, eq III.26 / VI.1 (Algorithm III.2):
  Q(s, a) ← Q(s, a) + β [r + γ max_a' Q(s', a') − Q(s, a)];
- SARSA, eq III.25 (Algorithm III.1): the target uses the action a' actually chosen in s';
- Watkins' Q(λ) (Algorithm III.3, eligibility traces eq III.33): δ as in Q-learning, accumulating
  traces e(s_t, a_t) += 1, Q += β δ e for every pair, then e ← γλ e — or e ← 0 when the next
  action is exploratory (not greedy), Watkins' cut that keeps Q(λ) an off-policy estimate of Q*
  (Algorithm III.3 as printed omits the cut; without it the traces credit exploratory moves).

It steps a batch of ``B`` episodes at once: every call takes arrays ``(B,)`` of states, actions,
rewards. The learner holds ``n_tables`` Q tables: either one per batch row (``n_tables == B``,
independent learners, e.g. one per seed, stepped in lock-step) or a single table shared by all
rows (``n_tables == 1``, synchronous parallel data collection; simultaneous updates of one pair
add up). A terminal transition (``done``) does not bootstrap; rows with ``active == False`` (their
episode already ended) are not updated.

Agent-style use, one batch of episodes::

    a = learner.begin(s, rng)                      # resets traces, first actions
    while ...:
        s2, r, done = env_step(a)
        a = learner.step(r, s2, done, rng, active)  # update, then next actions
    learner.end_episode()
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn.exploration import EpsilonGreedy, Policy, policy_from_dict
from fuzzynav.learn.schedules import schedule_to_dict, share_schedule
from fuzzynav.learn.state import restore_state
from fuzzynav.world.geometry import wrap_angle

METHODS = ("q_learning", "sarsa", "q_lambda")


def _add_unique(array: np.ndarray, index: tuple, values) -> None:
    """``np.add.at`` where no pair repeats (one row, or one table per row): the same sums, cheaper."""
    array[index] += values


def _indices(values, size: int, field: str) -> np.ndarray:
    """``values`` as state or action indices in [0, ``size``) (a negative one would wrap round)."""
    indices = np.asarray(values, dtype=int)
    if indices.size and (indices.min() < 0 or indices.max() >= size):
        raise InputError(f"must be indices in [0, {size}), got {indices.ravel().tolist()[:10]}", field=field)
    return indices


def _owners(n_tables: int, batch: int) -> np.ndarray:
    """Table index of each batch row: one table per row, or one shared table."""
    if n_tables == batch:
        return np.arange(batch)
    if n_tables == 1:
        return np.zeros(batch, dtype=int)
    raise InputError(f"a batch of {batch} rows needs 1 or {batch} tables, the learner has {n_tables}",
                     field="batch")


class TabularLearner:
    """Q-learning, SARSA or Watkins' Q(λ) over ``n_tables`` tables of shape (n_states, n_actions).

    ``alpha`` is the learning rate β (a number or a schedule of :mod:`.schedules`; with
    :class:`~fuzzynav.learn.schedules.InverseVisits` it is eq III.24 per pair); ``policy`` is an
    exploration policy of :mod:`.exploration` (default ε-greedy, ε = 0.1), evaluated at the
    learner's episode counter ``episode``.
    """

    kind = "tabular-learner"

    def __init__(self, n_states: int, n_actions: int, *, method: str = "q_learning",
                 gamma: float = 0.9, alpha=0.1, policy: Policy | None = None, lam: float = 0.0,
                 n_tables: int = 1, initial_q: float = 0.0):
        if method not in METHODS:
            raise InputError(f"unknown method {method!r}; known: {', '.join(METHODS)}", field="method")
        for name, value in (("n_states", n_states), ("n_actions", n_actions), ("n_tables", n_tables)):
            if int(value) != value or value < 1:
                raise InputError(f"must be a positive integer, got {value!r}", field=name)
        self.method = method
        self.gamma = validation.number(gamma, field="gamma", lo=0.0, hi=1.0)
        self.lam = validation.number(lam, field="lam", lo=0.0, hi=1.0)
        self.alpha = share_schedule(alpha, "alpha")
        self.policy = policy if policy is not None else EpsilonGreedy(0.1)
        self.q = np.full((int(n_tables), int(n_states), int(n_actions)), float(initial_q))
        self.visits = np.zeros(self.q.shape)
        self.episode = 0
        self._traces = None
        self._s = self._a = None

    @property
    def n_tables(self) -> int:
        return self.q.shape[0]

    def _rate(self, owners, s, a):
        """β for the pairs (owners, s, a) (a scalar unless the schedule counts visits)."""
        if self.alpha.per_visit:
            return self.alpha(self.visits[owners, s, a])
        return float(self.alpha(self.episode))

    def act(self, s, rng: np.random.Generator) -> np.ndarray:
        """Actions for states ``s`` (B,) by the exploration policy."""
        s = _indices(s, self.q.shape[1], "s")
        return self.policy.choose(self.q[_owners(self.n_tables, s.size), s], rng, self.episode)

    def greedy(self) -> np.ndarray:
        """Greedy action of every state of every table, (n_tables, n_states); ties → lowest index."""
        return np.argmax(self.q, axis=-1)

    def update(self, s, a, r, s_next, done, a_next=None, active=None) -> np.ndarray:
        """One TD update for a batch of transitions (s, a, r, s', done[, a']); returns δ (B,).

        ``a_next`` is required by SARSA; for Q(λ) it decides Watkins' trace cut (omitted: no cut).
        """
        s, a, s_next = (_indices(x, n, name) for x, n, name in ((s, self.q.shape[1], "s"), (a, self.q.shape[2], "a"),
                                                                (s_next, self.q.shape[1], "s_next")))
        r = np.asarray(r, dtype=float)
        if not np.isfinite(r).all():  # one NaN would spread over the whole table through the max
            raise InputError(f"rewards must be finite, got {r.ravel().tolist()}", field="r")
        owners = _owners(self.n_tables, s.size)
        live = np.ones(s.size) if active is None else np.asarray(active, dtype=float)
        bootstrap = self.gamma * (1.0 - np.asarray(done, dtype=float))
        q_next = self.q[owners, s_next]
        if self.method == "sarsa":
            if a_next is None:
                raise InputError("SARSA needs the next actions", field="a_next")
            target = r + bootstrap * q_next[np.arange(s.size), a_next]
        else:
            target = r + bootstrap * q_next.max(axis=-1)
        delta = (target - self.q[owners, s, a]) * live
        # rows sharing one table may update the same pair, where each addition must count
        add = np.add.at if s.size > 1 and self.n_tables == 1 else _add_unique
        if self.method == "q_lambda":
            self._trace_update(owners, s, a, delta, q_next, a_next, live)
        else:
            add(self.q, (owners, s, a), self._rate(owners, s, a) * delta)
        add(self.visits, (owners, s, a), live)
        return delta

    def _trace_update(self, owners, s, a, delta, q_next, a_next, live):
        """Algorithm III.3 with accumulating traces and Watkins' cut, for every pair at once."""
        rows = np.arange(s.size)
        if self._traces is None or self._traces.shape[0] != s.size:
            self._traces = np.zeros((s.size,) + self.q.shape[1:])
        self._traces[rows, s, a] += live
        step = delta[:, None, None] * self._traces
        if self.alpha.per_visit:
            step *= self.alpha(self.visits[owners])
        else:
            step *= float(self.alpha(self.episode))
        if self.n_tables == 1:
            self.q[0] += step.sum(axis=0)
        else:
            self.q += step
        keep = self.gamma * self.lam * np.ones(s.size)
        if a_next is not None:
            greedy_next = q_next[rows, a_next] >= q_next.max(axis=-1)
            keep = np.where(greedy_next, keep, 0.0)
        self._traces *= np.where(live > 0, keep, 1.0)[:, None, None]

    def begin(self, s, rng: np.random.Generator) -> np.ndarray:
        """Start a batch of episodes in states ``s``: clear the traces, return the first actions."""
        s = np.asarray(s, dtype=int)
        self._traces = np.zeros((s.size,) + self.q.shape[1:]) if self.method == "q_lambda" else None
        self._s, self._a = s, self.act(s, rng)
        return self._a

    def step(self, r, s_next, done, rng: np.random.Generator, active=None) -> np.ndarray:
        """Learn from the last actions' outcome and return the next actions (agent-style API).

        Q-learning updates first and then chooses in s' (Algorithm III.2); SARSA and Q(λ) choose
        a' first because their update needs it (Algorithms III.1, III.3).
        """
        s_next = np.asarray(s_next, dtype=int)
        if self.method == "q_learning":
            self.update(self._s, self._a, r, s_next, done, active=active)
            a_next = self.act(s_next, rng)
        else:
            a_next = self.act(s_next, rng)
            self.update(self._s, self._a, r, s_next, done, a_next, active)
        self._s, self._a = s_next, a_next
        return a_next

    def end_episode(self) -> None:
        """Count the finished batch of episodes (one per table: the schedules' clock) and clear traces."""
        self.episode += 1
        self._traces = None

    def to_dict(self) -> dict:
        """JSON-safe state (hyper-parameters, tables, visit counts, episode counter)."""
        return {
            "kind": self.kind,
            "method": self.method,
            "n_states": self.q.shape[1],
            "n_actions": self.q.shape[2],
            "n_tables": self.n_tables,
            "gamma": self.gamma,
            "lam": self.lam,
            "alpha": schedule_to_dict(self.alpha),
            "policy": self.policy.to_dict(),
            "episode": self.episode,
            "q": self.q.tolist(),
            "visits": self.visits.tolist(),
        }

    @classmethod
    def from_dict(cls, document: dict) -> TabularLearner:
        """Inverse of :meth:`to_dict`."""
        try:
            learner = cls(document["n_states"], document["n_actions"], method=document["method"],
                          gamma=document["gamma"], alpha=document["alpha"], lam=document["lam"],
                          policy=policy_from_dict(document["policy"]), n_tables=document["n_tables"])
        except KeyError as error:
            raise InputError("missing field", field=str(error.args[0])) from None
        restore_state(learner, document)
        return learner


class ZoneSectorDiscretiser:
    """States of the tabular goal seeker (§VI.2): zones of d_rg × sectors of θ_rg.

    ``zone_edges`` (increasing, metres) split the distance into ``len(zone_edges) + 1`` zones;
    the angle is split into ``n_sectors`` equal sectors, sector 0 centred on θ_rg = 0 (goal
    straight ahead — the situation eq VI.2 rewards with +3), the following ones counter-clockwise.
    With ``merge_inner`` the innermost zone (next to the goal, where the bearing matters little)
    is a single state, so there are ``1 + (n_zones − 1) · n_sectors`` states — which gives the
    state counts of Table VI.1 (9 = 1 + 2·4, 11 = 1 + 2·5, 13 = 1 + 2·6, 19 = 1 + 2·9 or 1 + 3·6);
    otherwise ``n_zones · n_sectors``. Vectorised over arrays of (d_rg, θ_rg).
    """

    def __init__(self, zone_edges, n_sectors: int, merge_inner: bool = False):
        edges = np.asarray(zone_edges, dtype=float).reshape(-1)
        if edges.size and (np.any(np.diff(edges) <= 0) or edges[0] <= 0):
            raise InputError(f"zone edges must be positive and increasing, got {edges.tolist()}",
                             field="zone_edges")
        if int(n_sectors) != n_sectors or n_sectors < 1:
            raise InputError(f"must be a positive integer, got {n_sectors!r}", field="n_sectors")
        if merge_inner and edges.size == 0:
            raise InputError("merging the inner zone needs at least one zone edge", field="merge_inner")
        self.zone_edges = edges
        self.n_sectors = int(n_sectors)
        self.merge_inner = bool(merge_inner)

    @classmethod
    def from_counts(cls, n_zones: int, n_sectors: int, d_max: float, merge_inner: bool = False):
        """``n_zones`` zones of equal width up to ``d_max`` (the last zone extends beyond)."""
        if int(n_zones) != n_zones or n_zones < 1:
            raise InputError(f"must be a positive integer, got {n_zones!r}", field="n_zones")
        return cls(np.linspace(0.0, d_max, int(n_zones) + 1)[1:-1], n_sectors, merge_inner)

    @property
    def n_zones(self) -> int:
        return self.zone_edges.size + 1

    @property
    def n_states(self) -> int:
        if self.merge_inner:
            return 1 + (self.n_zones - 1) * self.n_sectors
        return self.n_zones * self.n_sectors

    def sector(self, angle) -> np.ndarray:
        """Sector index of θ_rg (radians), sector 0 centred on 0."""
        width = 2.0 * np.pi / self.n_sectors
        return np.floor((wrap_angle(angle) + 0.5 * width) / width).astype(int) % self.n_sectors

    def __call__(self, distance, angle) -> np.ndarray:
        """State index of each (d_rg, θ_rg)."""
        zone = np.searchsorted(self.zone_edges, np.asarray(distance, dtype=float), side="right")
        sector = self.sector(angle)
        if self.merge_inner:
            return np.where(zone == 0, 0, 1 + (zone - 1) * self.n_sectors + sector)
        return zone * self.n_sectors + sector
