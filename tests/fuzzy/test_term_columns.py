"""The kernel's trapezoid and S / Z / Pi-shape loops give the bits of the NumPy terms (fuzzylite's formulas)."""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.fuzzify_terms import TRAPEZOID, pack_term, term_column
from fuzzynav.fuzzy.membership import Trapezoidal
from fuzzynav.fuzzy.terms import PiShape, SShape, ZShape


def _bits(values: np.ndarray) -> np.ndarray:
    return np.where(np.isnan(values), np.nan, values).view(np.int64)  # one NaN pattern


def test_trapezoids_and_triangles_give_the_numpy_bits_at_every_edge_and_special_value():
    rng = np.random.default_rng(5)
    shapes = [(0.0, 1.0, 1.0, 2.0), (-3.0, -1.0, 2.5, 7.0), (1e-300, 2e-300, 3e-300, 4e-300), (-1e300, 0.0, 0.0, 1e300),
              (0.0, 0.0, 1.0, 2.0), (0.0, 1.0, 2.0, 2.0), (-np.inf, -np.inf, 1.0, 2.0), (0.0, 1.0, np.inf, np.inf),
              (5.0, 5.0, 5.0, 5.0)]
    shapes += [tuple(np.sort(rng.normal(0.0, 10.0, 4))) for _ in range(40)]
    shapes += [(a, b, b, d) for a, b, d in np.sort(rng.uniform(-1.0, 1.0, (20, 3)), axis=1)]
    for a, b, c, d in shapes:
        edges = np.array([a, b, c, d])
        finite = edges[np.isfinite(edges)]
        x = np.concatenate([rng.uniform(a - 1.0 if np.isfinite(a) else -5.0, d + 1.0 if np.isfinite(d) else 5.0, 2000),
                            finite, np.nextafter(finite, np.inf), np.nextafter(finite, -np.inf),
                            [np.nan, np.inf, -np.inf, 0.0, -0.0, 0.5 * (b + c) if np.isfinite(b + c) else 0.0]])
        mf = Trapezoidal(a, b, c, d)
        code, params, height = pack_term(mf)
        assert code == TRAPEZOID
        ours = np.empty_like(x)
        term_column(code, np.array(params), 0, len(params), height, x, ours)
        with np.errstate(all="ignore"):
            np.testing.assert_array_equal(_bits(ours), _bits(mf(x)), err_msg=f"trapezoid {(a, b, c, d)}")


def _around(edges, rng) -> np.ndarray:
    """Random values over the edges' span and 1 beyond, the edges, their neighbours, special values."""
    edges = np.asarray(edges, dtype=float)
    return np.concatenate([rng.uniform(edges.min() - 1.0, edges.max() + 1.0, 2000), edges, np.nextafter(edges, np.inf),
                           np.nextafter(edges, -np.inf), [np.nan, np.inf, -np.inf, 0.0, -0.0]])


def test_s_z_and_pi_shapes_give_the_numpy_bits_at_every_edge_and_special_value():
    rng = np.random.default_rng(6)
    pairs = [(0.0, 1.0), (1.0, 0.0), (2.0, 2.0), (-1e-300, 1e-300)] + [tuple(rng.normal(0.0, 5.0, 2)) for _ in range(30)]
    terms = [kind(s, e) for s, e in pairs for kind in (SShape, ZShape)]
    terms += [PiShape(*np.sort(rng.normal(0.0, 5.0, 4))) for _ in range(30)] + [PiShape(0.0, 1.0, 1.0, 2.0)]
    for mf in terms:
        params = mf.params()
        x = np.concatenate([_around(params, rng), 0.5 * (np.array(params[::2]) + np.array(params[1::2]))])
        code, packed, height = pack_term(mf)
        ours = np.empty_like(x)
        term_column(code, np.array(packed), 0, len(packed), height, x, ours)
        with np.errstate(all="ignore"):
            np.testing.assert_array_equal(_bits(ours), _bits(mf(x)), err_msg=f"{mf.kind} {params}")
