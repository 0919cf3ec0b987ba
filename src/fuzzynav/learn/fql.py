"""Fuzzy Q-learning (thesis §VI.3–VI.4, Algorithm VI.1), vectorised over rules and episodes.

A zero-order Takagi–Sugeno rule base with fixed membership functions (the *premise*: any object
with ``firing_strengths(X, normalise=True) -> (N, n_rules)``, e.g. the fuzzy library's system)
whose rule i holds N candidate conclusions a[i, j] with qualities q[i, j] (eq VI.9, q = 0 at
start). At each step, for a batch of B episodes at once:

1. w_i(s) for every rule (one call of the premise);
2. every rule picks a candidate j_i by the exploration policy over q[i, :] (:mod:`.exploration`);
3. inferred action A(s) = Σ_i w_i a[i, j_i] (VI.10) and its quality Q(s, A) = Σ_i w_i q[i, j_i]
   (VI.11);
4. after the move: V*(s') = Σ_i w_i(s') max_j q[i, j] and ΔQ = β [r + γ V*(s') − Q(s, A)]
   (by default no bootstrap on a terminal transition; with ``terminal_bootstrap`` the new state
   s' is valued at every step, the terminal one included, as Algorithm VI.1 writes it: steps vi–vii
   compute V*(s') before the loop's test "jusqu'à s_t ∈ F");
5. q[i, j_i] += ΔQ · w_i(s) (Algorithm VI.1 step viii writes q[i, j] += ΔQ[i, j]; the share of the
   correction given to each rule is its firing strength, as in Jouffe's FQL [JOU98, GLO00] —
   Q(s, A) is linear in q with gradient w_i, so this is the gradient step).

Eligibility traces (the faster variant of Figs VI.15–VI.16, §III.4.11 applied to FQL as in
[JOU98]): e[i, j] ← γλ e[i, j] + w_i(s)·[j = j_i], then q += β ΔQ e for every rule and candidate.
Traces are not cut after exploratory choices (each rule explores independently, so almost every
step would cut). λ = 0 is exactly the one-step algorithm.

Outputs. ``candidates`` has shape (H, R, N, D): H *heads* learned separately, each with its own
reward (B, H) and qualities (e.g. steering by reward VI.2 and speed by reward VI.14), each head's
conclusion a D-vector (D > 1 learns several outputs *jointly* under one reward). The helpers
:meth:`FuzzyQLearner.separate` and :meth:`FuzzyQLearner.joint` build the usual cases.

Batches. The learner holds L independent sets of qualities: L = B (one learner per batch row,
e.g. one per seed) or L = 1 (one rule base trained from B parallel episodes; their simultaneous
corrections add up).

Extraction (:meth:`FuzzyQLearner.greedy_indices`): each rule keeps its best candidate — unless the
quality gap between that candidate and the rule's *prior* conclusion is at most ``tolerance``, in
which case the prior is kept. :func:`extract_system` turns the result into an ordinary TS0
:class:`~fuzzynav.fuzzy.FuzzySystem` (savable, printable as a rule table) through the one
extractor of :mod:`fuzzynav.learn.extraction`. The prior defaults to the middle candidate (the neutral one of a
symmetric set such as {−π/5, 0, π/5}), may be the hand-made controller's conclusion (wall
following, §VI.5.3) or the previous extraction; rules never fired keep their prior. So tiny
quality differences cannot flip the extracted controller.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn.exploration import EpsilonGreedy, Policy, policy_from_dict, row_max
from fuzzynav.learn.extraction import rule_table
from fuzzynav.learn.schedules import schedule_to_dict, share_schedule
from fuzzynav.learn.state import restore_state


def _n_rules(premise) -> int | None:
    """Number of rules of a premise: its ``n_rules``, else ``len(premise.rules)``, else unknown."""
    if hasattr(premise, "n_rules"):
        return int(premise.n_rules)
    return len(premise.rules) if hasattr(premise, "rules") else None


def _as_candidates(candidates, n_rules: int | None) -> np.ndarray:
    """Candidates as (H, R, N, D); (N,) and (R, N) mean one scalar head."""
    values = np.asarray(candidates, dtype=float)
    if values.ndim == 1:
        if n_rules is None:
            raise InputError("the same candidates for every rule need n_rules", field="n_rules")
        values = np.broadcast_to(values, (n_rules, values.size))
    if values.ndim == 2:
        values = values[None, :, :, None]
    if values.ndim != 4:
        raise InputError(f"candidates must have shape (N,), (R, N) or (H, R, N, D), got {values.shape}",
                         field="candidates")
    if n_rules is not None and values.shape[1] != n_rules:
        raise InputError(f"{values.shape[1]} rules of candidates, the premise has {n_rules}",
                         field="candidates")
    return np.array(values)


class FuzzyQLearner:
    """Fuzzy Q-learning of the conclusions of a TS0 rule base (Algorithm VI.1, optional λ).

    ``alpha`` is β (number or schedule; :class:`~fuzzynav.learn.schedules.InverseVisits` counts
    fuzzy visits Σ w_i per candidate), ``policy`` the per-rule exploration policy (default
    ε-greedy, ε = 0.1) evaluated at the learner's ``episode`` counter, ``prior`` the index of each
    rule's a-priori conclusion, shape (R,) or (H, R); ``terminal_bootstrap`` values the state a
    terminal transition reaches like any other (step 4 of the module docstring).
    """

    kind = "fuzzy-q-learner"

    def __init__(self, premise, candidates, *, n_rules: int | None = None, gamma: float = 0.9,
                 alpha=0.1, policy: Policy | None = None, lam: float = 0.0, n_learners: int = 1,
                 prior=None, normalise: bool = True, initial_q: float = 0.0, terminal_bootstrap: bool = False):
        if n_rules is None:
            n_rules = _n_rules(premise)
        self.premise = premise
        self.candidates = _as_candidates(candidates, n_rules)
        n_heads, n_rules, n_candidates, _ = self.candidates.shape
        if int(n_learners) != n_learners or n_learners < 1:
            raise InputError(f"must be a positive integer, got {n_learners!r}", field="n_learners")
        self.gamma = validation.number(gamma, field="gamma", lo=0.0, hi=1.0)
        self.lam = validation.number(lam, field="lam", lo=0.0, hi=1.0)
        self.alpha = share_schedule(alpha, "alpha")
        self.policy = policy if policy is not None else EpsilonGreedy(0.1)
        self.normalise = bool(normalise)
        self.terminal_bootstrap = bool(terminal_bootstrap)
        if prior is None:
            prior = np.full((n_heads, n_rules), n_candidates // 2)
        self.prior = np.broadcast_to(np.asarray(prior, dtype=int), (n_heads, n_rules)).copy()
        if np.any((self.prior < 0) | (self.prior >= n_candidates)):
            raise InputError(f"prior indices must be in [0, {n_candidates})", field="prior")
        self.q = np.full((int(n_learners), n_heads, n_rules, n_candidates), float(initial_q))
        self.visits = np.zeros(self.q.shape)
        self.episode = 0
        self._traces = self._shares_now = self._quality = None

    @classmethod
    def separate(cls, premise, outputs, **options) -> FuzzyQLearner:
        """One head per output, each a candidate set (N,) or (R, N) with the same N."""
        n_rules = options.pop("n_rules", None) or _n_rules(premise)
        heads = [_as_candidates(c, n_rules)[0] for c in outputs]
        if len({head.shape for head in heads}) != 1:
            raise InputError("separately learned outputs need the same number of candidates",
                             field="candidates")
        return cls(premise, np.stack(heads), n_rules=n_rules, **options)

    @classmethod
    def joint(cls, premise, candidates, **options) -> FuzzyQLearner:
        """One head whose candidates are vectors: (N, D) for every rule, or (R, N, D)."""
        n_rules = options.pop("n_rules", None) or _n_rules(premise)
        values = np.asarray(candidates, dtype=float)
        if values.ndim == 2:
            if n_rules is None:
                raise InputError("the same candidates for every rule need n_rules", field="n_rules")
            values = np.broadcast_to(values, (n_rules,) + values.shape)
        if values.ndim != 3:
            raise InputError(f"joint candidates must be (N, D) or (R, N, D), got {values.shape}",
                             field="candidates")
        return cls(premise, values[None], n_rules=n_rules, **options)

    @property
    def n_learners(self) -> int:
        return self.q.shape[0]

    @property
    def n_outputs(self) -> int:
        """Length of an action vector: heads × conclusion size."""
        return self.candidates.shape[0] * self.candidates.shape[3]

    def _check_batch(self, batch: int) -> None:
        if self.n_learners not in (1, batch):
            raise InputError(f"a batch of {batch} rows needs 1 or {batch} learners, the learner has "
                             f"{self.n_learners}", field="batch")

    def strengths(self, X) -> np.ndarray:
        """Firing strengths w (B, R) of the premise for inputs X (B, n_in)."""
        w = np.asarray(self.premise.firing_strengths(np.asarray(X, dtype=float), normalise=self.normalise))
        if w.ndim != 2 or w.shape[1] != self.candidates.shape[1]:
            raise InputError(f"premise gave strengths of shape {w.shape}, expected (B, "
                             f"{self.candidates.shape[1]})", field="premise")
        return w

    def _shares(self, w, j) -> np.ndarray:
        """w_i(s)·[j = j_i] for chosen indices j (B, H, R): each rule's share of each candidate."""
        n = self.q.shape[-1]
        if j.size < 1024:
            return (j[..., None] == np.arange(n)) * w[:, None, :, None]
        shares = np.zeros(j.shape + (n,))  # large batches: scatter the strengths (faster than the comparison above)
        shares.reshape(-1, n)[np.arange(j.size), j.ravel()] = np.broadcast_to(w[:, None, :], j.shape).ravel()
        return shares

    def _infer(self, shares) -> np.ndarray:
        """A = Σ_i w_i a[i, j_i] (VI.10) from the shares (B, H, R, N); returns (B, H·D)."""
        return np.einsum("bhrn,hrnd->bhd", shares, self.candidates).reshape(shares.shape[0], -1)

    def _choose(self, w, rng) -> np.ndarray:
        self._check_batch(w.shape[0])
        if self.n_learners == 1:  # one table shared by every row: choose on it without copying
            j = self.policy.choose(self.q[0], rng, self.episode, batch=w.shape[0])
            self._shares_now = self._shares(w, j)
            self._quality = np.einsum("bhrn,hrn->bh", self._shares_now, self.q[0])  # Q(s, A), VI.11
        else:
            j = self.policy.choose(self.q, rng, self.episode)
            self._shares_now = self._shares(w, j)
            self._quality = np.einsum("bhrn,bhrn->bh", self._shares_now, self.q)
        return self._infer(self._shares_now)

    def begin(self, X, rng: np.random.Generator) -> np.ndarray:
        """Start a batch of episodes at inputs X: clear the traces, return the first actions."""
        w = self.strengths(X)
        self._traces = np.zeros((w.shape[0],) + self.q.shape[1:])
        return self._choose(w, rng)

    def step(self, r, X_next, terminated, rng: np.random.Generator, active=None) -> np.ndarray:
        """Learn from the last actions' outcome (rewards (B,) or (B, H)); return the next actions."""
        w_next = self.strengths(X_next)
        batch = w_next.shape[0]
        live = np.ones(batch) if active is None else np.asarray(active, dtype=float)
        ends = np.zeros(batch) if self.terminal_bootstrap else np.asarray(terminated, dtype=float)
        bootstrap = self.gamma * (1.0 - ends)
        best = row_max(self.q)
        v_star = (np.einsum("br,hr->bh", w_next, best[0]) if self.n_learners == 1
                  else np.einsum("br,bhr->bh", w_next, best))
        r = np.asarray(r, dtype=float).reshape(batch, -1)
        if not np.isfinite(r).all():  # one NaN would spread over every quality it touches
            raise InputError(f"rewards must be finite, got {r.ravel().tolist()}", field="reward")
        if r.shape[1] not in (1, self.q.shape[1]):
            raise InputError(f"rewards need 1 or {self.q.shape[1]} columns (one per head), got {r.shape[1]}",
                             field="reward")
        delta = (r + bootstrap[:, None] * v_star - self._quality) * live[:, None]
        credit = self._shares_now * live[:, None, None, None]
        if self.lam > 0.0:
            self._traces *= self.gamma * self.lam
            self._traces += credit
        else:
            self._traces = credit
        shared = self.n_learners == 1
        if self.alpha.per_visit:
            change = delta[:, :, None, None] * self._traces * self.alpha(self.visits)
            self.q += change.sum(axis=0) if shared else change
        else:
            delta *= float(self.alpha(self.episode))
            if shared:
                self.q[0] += np.einsum("bh,bhrn->hrn", delta, self._traces)
            else:
                self.q += delta[:, :, None, None] * self._traces
        self.visits += credit.sum(axis=0) if shared else credit
        return self._choose(w_next, rng)

    def end_episode(self) -> None:
        """Count the finished batch of episodes (the schedules' clock) and clear the traces."""
        self.episode += 1
        self._traces = None

    def greedy_indices(self, tolerance: float = 0.0, prior=None) -> np.ndarray:
        """Extracted conclusion index of every rule, (L, H, R) — see the module docstring."""
        prior = self.prior if prior is None else np.broadcast_to(np.asarray(prior, dtype=int), self.prior.shape)
        best = np.argmax(self.q, axis=-1)
        q_best = np.take_along_axis(self.q, best[..., None], -1)[..., 0]
        q_prior = np.take_along_axis(self.q, np.broadcast_to(prior, best.shape)[..., None], -1)[..., 0]
        return np.where(q_best - q_prior > tolerance, best, prior)

    def greedy_conclusions(self, tolerance: float = 0.0, prior=None) -> np.ndarray:
        """Values of the extracted conclusions, (L, H, R, D): the learned TS0 rule table."""
        j = self.greedy_indices(tolerance, prior)
        return np.take_along_axis(self.candidates[None], j[..., None, None], axis=3)[:, :, :, 0]

    def greedy_action(self, X, tolerance: float = 0.0, prior=None, learner: int | None = None) -> np.ndarray:
        """Output of the extracted controller for inputs X (B, n_in) → (B, H·D), no learning.

        Row b uses learner b (or the shared one); with ``learner = k`` every row uses learner k
        (e.g. to evaluate one seed's controller on many starts).
        """
        w = self.strengths(X)
        j = self.greedy_indices(tolerance, prior)
        if learner is not None:
            j = j[learner : learner + 1]
        if j.shape[0] not in (1, w.shape[0]):
            raise InputError(f"{w.shape[0]} rows for {j.shape[0]} learners; pass learner=k", field="X")
        return self._infer(self._shares(w, j))

    def action(self, X, indices) -> np.ndarray:
        """Output (B, H·D) for inputs X of the rule base whose rules conclude the candidates
        ``indices`` (1, H, R) — e.g. a :meth:`greedy_indices` kept while the learner is frozen."""
        return self._infer(self._shares(self.strengths(X), indices))

    def to_dict(self) -> dict:
        """JSON-safe learner state (the premise is stored by its owner, or via its ``to_dict``)."""
        document = {
            "kind": self.kind,
            "candidates": self.candidates.tolist(),
            "gamma": self.gamma,
            "lam": self.lam,
            "alpha": schedule_to_dict(self.alpha),
            "policy": self.policy.to_dict(),
            "normalise": self.normalise,
            "terminal_bootstrap": self.terminal_bootstrap,
            "prior": self.prior.tolist(),
            "n_learners": self.n_learners,
            "episode": self.episode,
            "q": self.q.tolist(),
            "visits": self.visits.tolist(),
        }
        if hasattr(self.premise, "to_dict"):
            document["premise"] = self.premise.to_dict()
        return document

    @classmethod
    def from_dict(cls, document: dict, premise) -> FuzzyQLearner:
        """Inverse of :meth:`to_dict`, given the premise (the fuzzy system of the rules)."""
        try:
            learner = cls(premise, document["candidates"], gamma=document["gamma"],
                          alpha=document["alpha"], policy=policy_from_dict(document["policy"]),
                          lam=document["lam"], n_learners=document["n_learners"],
                          prior=document["prior"], normalise=document["normalise"],
                          terminal_bootstrap=document.get("terminal_bootstrap", False))
        except KeyError as error:
            raise InputError("missing field", field=str(error.args[0])) from None
        restore_state(learner, document)
        return learner


def extract_system(learners, outputs, *, learner_index: int = 0, tolerance: float = 0.0, prior=None,
                   rules: int | None = None, name: str = "", description: str = ""):
    """The learned controller as an ordinary TS0 :class:`~fuzzynav.fuzzy.FuzzySystem` (§VI.4),
    through the one extractor :func:`fuzzynav.learn.extraction.rule_table`.

    ``learners``: one :class:`FuzzyQLearner`, or several over the same premise (learned in turn,
    e.g. the steering, then the speed); the premise must be a fuzzy system (or hold one as
    ``system``), whose inputs and rule premises are kept (the first ``rules`` rules, default all).
    Each rule concludes the candidate :meth:`FuzzyQLearner.greedy_indices` extracts (row
    ``learner_index``). ``outputs`` names the H·D outputs of each learner in turn: a name, a
    :class:`~fuzzynav.fuzzy.Variable` or an :class:`~fuzzynav.learn.extraction.Interpretations`
    (:mod:`fuzzynav.learn.extraction`). Inference: product / weighted average, i.e. Σ w_i a_i with
    the normalised strengths of FQL (weighted sum when the learners do not normalise).
    """
    learners = [learners] if isinstance(learners, FuzzyQLearner) else list(learners)
    columns = []
    for learner in learners:
        chosen = learner.greedy_indices(tolerance, prior)[learner_index]  # (H, R)
        h_count, _, _, d_count = learner.candidates.shape
        columns += [(learner.candidates[h, :, :, d], chosen[h]) for h in range(h_count) for d in range(d_count)]
    outputs = list(outputs)
    if len(outputs) != len(columns):
        raise InputError(f"{len(outputs)} output(s) for {len(columns)} learned output(s)", field="outputs")
    return rule_table(learners[0].premise, [(o, *column) for o, column in zip(outputs, columns)], rules=rules,
                      defuzzifier="weighted_average" if learners[0].normalise else "weighted_sum",
                      name=name or "fuzzy-q-learned", description=description or
                      "TS0 rule base whose conclusions were learned by fuzzy Q-learning (Algorithm VI.1)")
