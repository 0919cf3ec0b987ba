"""Markstein's quotient (fuzzynav.fuzzy.engine.quotient) has the bits of the division wherever it says so."""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.quotient import NORMAL, divided, fma, usable_reciprocal
from fuzzynav.jit import jit


@jit
def _quotients(n, d, out, exact):
    y = 1.0 / d
    for k in range(n.shape[0]):
        out[k], exact[k] = divided(n[k], d, y, False)


def _numerators(rng, d, size):
    """Quotients of every size below d's range, multiples of d, neighbours, tiny and special values."""
    n = rng.uniform(-1.0, 1.0, size) * d * rng.choice([1e-6, 0.5, 3.0, 1e6], size)
    n[:500] = np.nextafter(n[:500], 0.0)
    n[500:1000] = rng.integers(-1000, 1000, 500) * d
    n[1000:1500] = 2.0 ** rng.integers(-1074, -900, 500) * rng.choice([-1.0, 1.0], 500)
    n[1500:1507] = [np.inf, -np.inf, np.nan, 0.0, -0.0, 1e308, -1e308]
    return n


def _bits(values):
    return np.where(np.isnan(values), np.nan, values).view(np.int64)


def test_quotients_have_the_bits_of_the_division_where_exact_and_say_so_elsewhere():
    rng = np.random.default_rng(11)
    denominators = [3.0, 7.0, 0.1, 0.3, 1.0 / 3.0, 10.0, 1e-300, 1e300, 4 * NORMAL, 1.5 ** 0.5]
    denominators += [float(np.exp(rng.uniform(-690.0, 690.0))) for _ in range(20)]
    denominators += [float(np.nextafter(2.0 ** int(e), 0.0)) for e in rng.integers(-100, 100, 10)]  # significand all ones
    denominators += [float(rng.integers(1, 1 << 53)) * 2.0 ** int(e) for e in rng.integers(-60, 60, 10)]
    counted = 0
    for d in denominators + [-d for d in denominators[:10]]:
        assert usable_reciprocal(d)
        n = _numerators(rng, d, 100_000)
        ours, exact = np.empty_like(n), np.empty(n.shape, dtype=np.bool_)
        _quotients(n, d, ours, exact)
        with np.errstate(all="ignore"):
            expected = n / d
        np.testing.assert_array_equal(_bits(ours[exact]), _bits(expected[exact]), err_msg=f"d = {d!r}")
        assert not exact[~np.isfinite(n)].any()  # NaN and infinities: the caller divides
        counted += int(exact.sum())
    assert counted > 0.95 * len(denominators) * 100_000  # the fast path is the common one


def test_reciprocals_are_usable_only_when_normal_and_finite():
    assert usable_reciprocal(2.0) and usable_reciprocal(-1e-300) and usable_reciprocal(1e307)
    assert not any(usable_reciprocal(d) for d in (0.0, -0.0, 1e-310, 1e309, np.inf, np.nan, 4.6e307))


def test_plain_fma_rounds_once():
    a = 1.0 + 2.0 ** -30
    assert fma(a, a, -1.0) == 2.0 ** -29 + 2.0 ** -60  # a × a − 1 exactly: two roundings would lose 2⁻⁶⁰
    assert fma(0.1, 10.0, -1.0) == 5.551115123125783e-17
