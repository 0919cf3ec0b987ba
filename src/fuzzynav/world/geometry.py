"""Where :func:`wrap_angle` used to live; it is :mod:`fuzzynav.kernels.angles` now."""

from fuzzynav.kernels.angles import wrap_angle  # noqa: F401
