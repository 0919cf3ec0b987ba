"""fuzzynav — neuro-fuzzy navigation of a simulated tricycle mobile robot.

Implements the systems of L. Cherroun, *Navigation autonome d'un robot mobile par des
techniques neuro-floues* (doctoral thesis, Université de Biskra, 2014): fuzzy behaviours
(chapter IV), fuzzy / neural / ANFIS trajectory tracking (chapter V) and (fuzzy) Q-learning
(chapter VI).

Layers (imports only point downwards): ``fuzzy`` → ``robot``/``world`` → ``control``/``learn``
→ ``sim`` → ``experiments``/``cli``.
"""

__version__ = "0.1.0"
