"""The simulator's guard on what a controller returns: nothing non-finite reaches the robot.

A controller (built-in, learned, or a user's own class) that returns ``None``, a non-number or a
NaN / infinite steering or speed stops the run with a :class:`~fuzzynav.errors.CommandError`
naming the controller, the step and the value, instead of turning the pose to NaN (which would
end as a silent "timeout" with no collision ever detected); start poses must be finite too.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import CommandError, InputError
from fuzzynav.kernels import step as step_kernel


def command_values(command, controller: str, step: int) -> tuple[float, float, str]:
    """``(steering, speed, behaviour)`` of one robot's command, both numbers finite."""
    try:
        steering, speed = float(command.steering), float(command.speed)
    except (AttributeError, TypeError, ValueError, OverflowError):
        raise CommandError(f"returned {command!r}, not a command with numeric steering and speed",
                           source=f"controller {controller}", field=f"step {step}") from None
    if not (math.isfinite(steering) and math.isfinite(speed)):
        raise CommandError(f"returned a non-finite command (steering {steering!r}, speed {speed!r})",
                           source=f"controller {controller}", field=f"step {step}")
    return steering, speed, str(getattr(command, "behaviour", ""))


def check_commands(steering, speed, active, n: int, controller: str, step: int):
    """The batch commands ``(n,)`` of the running robots (``active``) as finite float arrays
    (robots that have finished may return anything: their commands are not used)."""
    try:
        steering, speed = np.asarray(steering, dtype=float), np.asarray(speed, dtype=float)
        if steering.shape != (n,) or speed.shape != (n,):
            steering, speed = np.broadcast_to(steering, (n,)), np.broadcast_to(speed, (n,))
    except (TypeError, ValueError):
        raise CommandError(f"returned steering {steering!r} and speed {speed!r}, not {n} numbers each",
                           source=f"controller {controller}", field=f"step {step}") from None
    if np.isfinite(steering).all() and np.isfinite(speed).all():
        return steering, speed
    bad = np.flatnonzero(np.asarray(active, dtype=bool) & ~(np.isfinite(steering) & np.isfinite(speed)))
    if bad.size:
        i = int(bad[0])
        raise CommandError(f"returned a non-finite command for robot {i} (steering {float(steering[i])!r}, "
                           f"speed {float(speed[i])!r})", source=f"controller {controller}", field=f"step {step}")
    return steering, speed


def check_state(state, controller: str, step: int, history=None) -> None:
    """After a compiled navigator's steps: the pose and command of every robot finite (the
    navigator decides inside the compiled call, so its commands are checked in the state; the
    simulator does so every few steps). With ``history`` (the states recorded so far, one per
    step) the first step that went non-finite is named, else the step ``step`` it was found by."""
    moved = state[:, step_kernel.X:step_kernel.SPEED + 1]
    if np.isfinite(moved).all():
        return
    i = int(np.flatnonzero(~np.isfinite(moved).all(axis=1))[0])
    where = f"by step {step}"
    if history:
        step = next(k for k, past in enumerate(history)
                    if not np.isfinite(past[i, step_kernel.X:step_kernel.SPEED + 1]).all())
        state, where = history[step], f"step {step}"
    steering, speed = float(state[i, step_kernel.STEERING]), float(state[i, step_kernel.SPEED])
    raise CommandError(f"returned a non-finite command for robot {i} (steering {steering!r}, speed {speed!r})",
                       source=f"controller {controller}", field=where)


def check_starts(starts) -> np.ndarray:
    """Start poses given to the simulator: one pose (x, y, θ) or ``(N, 3)`` of them, N at most
    ``validation.MAX_ROBOTS``, numbers, finite (``[[5, 5], [6, 6], [7, 7]]`` is refused, not
    read as two poses)."""
    try:
        poses = np.asarray(starts, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"must be poses (x, y, theta), got {validation.shown(starts)}", field="starts") from None
    if poses.shape == (3,):
        poses = poses[None]
    if poses.ndim != 2 or poses.shape[1] != 3 or not 1 <= len(poses) <= validation.MAX_ROBOTS:
        raise InputError(f"must be one pose (x, y, theta) or a list of 1 to {validation.MAX_ROBOTS} of them, "
                         f"got an array of shape {poses.shape}", field="starts")
    if not np.isfinite(poses).all():
        raise InputError("must be finite", field="starts")
    return poses
