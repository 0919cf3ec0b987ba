"""Human-readable result lines: each number printed with its meaning and its unit.

Result dicts use the JSON key conventions of the package (``time_s``, ``validation_rmse_rad``,
``mean_speed_mps``, ``..._rate`` as a fraction); :func:`result_lines` turns them into lines such
as ``training time: 0.05 s`` or ``validation RMSE: 5.05e-04 rad``. ``--json`` output keeps the keys.
"""

from __future__ import annotations

LABELS = {
    "model": "model file",
    "solver_iterations": "solver iterations (L-BFGS)",
    "epochs": "training epochs",
    "n_train": "training pairs",
    "train_seconds": "training time",
    "validation_rmse_rad": "validation RMSE (steering angle)",
    "validation_max_error_rad": "largest validation error (steering angle)",
    "source": "training data",
    "seed": "seed",
}
SUFFIX_UNITS = (("_seconds", "s"), ("_s", "s"), ("_rad", "rad"), ("_mps", "m/s"), ("_m", "m"), ("_rate", "%"))


def _number(value: float) -> str:
    return f"{value:.3g}" if abs(value) >= 1e-3 or value == 0 else f"{value:.2e}"


def value_text(key: str, value) -> str:
    """``value`` with the unit its key names (fractions of ``..._rate`` keys as percentages)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return str(value)
    for suffix, unit in SUFFIX_UNITS:
        if key.endswith(suffix):
            return f"{100 * value:.1f} %" if unit == "%" else f"{_number(value)} {unit}"
    return str(value) if isinstance(value, int) else _number(value)


def result_lines(result: dict) -> list[str]:
    """One ``meaning: value unit`` line per entry of ``result``."""
    return [f"{LABELS.get(key, key.replace('_', ' '))}: {value_text(key, value)}" for key, value in result.items()]
