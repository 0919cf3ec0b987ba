"""The simulator's guard on what a controller returns: nothing non-finite reaches the robot.

A NaN or infinite steering or speed from a controller (built-in, learned, or a user's own class)
stops that robot's episode before it moves, with the outcome ``"invalid_command"`` and the reason
recorded (:func:`invalid_reason`: the step and the values; ``Trace.invalid_command``, the
``invalid_command`` field of a run's metrics) — instead of turning the pose to NaN, which would
end as a silent "timeout" with no collision ever detected. The other robots of the batch run on.
A controller that returns no command at all (``None``, not numbers, the wrong number of them) is
a programming error: a :class:`~fuzzynav.errors.CommandError` naming the controller, the step and
the value. Start poses must be finite too.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import CommandError, InputError
from fuzzynav.kernels import step as step_kernel
from fuzzynav.world import limits

INVALID_COMMAND = 4  # outcome code beside the kernel's RUNNING, REACHED, COLLISION, TIMEOUT (0-3)


def invalid_reason(when: str, steering: float, speed: float) -> str:
    """The recorded reason of a stop on a non-finite command, ``when`` being ``"step 3"``:
    ``"step 3: steering nan, speed 1.0"``."""
    return f"{when}: steering {float(steering)!r}, speed {float(speed)!r}"


def command_values(command, controller: str, step: int) -> tuple[float, float, str]:
    """``(steering, speed, behaviour)`` of one robot's command, both numbers (possibly non-finite:
    the caller stops the robot)."""
    try:
        steering, speed = float(command.steering), float(command.speed)
    except (AttributeError, TypeError, ValueError, OverflowError):
        raise CommandError(f"returned {command!r}, not a command with numeric steering and speed",
                           source=f"controller {controller}", field=f"step {step}") from None
    return steering, speed, str(getattr(command, "behaviour", ""))


def check_commands(steering, speed, n: int, controller: str, step: int):
    """The batch commands as float arrays ``(n,)`` (non-finite values are the caller's to stop;
    robots that have finished may return anything: their commands are not used)."""
    try:
        steering, speed = np.asarray(steering, dtype=float), np.asarray(speed, dtype=float)
        if steering.shape != (n,) or speed.shape != (n,):
            steering, speed = np.broadcast_to(steering, (n,)), np.broadcast_to(speed, (n,))
    except (TypeError, ValueError):
        raise CommandError(f"returned steering {steering!r} and speed {speed!r}, not {n} numbers each",
                           source=f"controller {controller}", field=f"step {step}") from None
    return steering, speed


def controller_commands(controllers, batch: bool, obs, controller: str, step: int):
    """``(steering (N,), speed (N,), behaviours)`` the Python ``controllers`` return for the
    robots of ``obs`` (a :class:`~fuzzynav.control.base.BatchObservation`): ``act_batch`` of the
    one controller when ``batch``, else ``act`` of each running robot's own (one controller for
    one robot); possibly non-finite (the caller stops those robots)."""
    n = len(obs.active)
    if batch:
        out = controllers[0].act_batch(obs)
        if not isinstance(out, (tuple, list)) or len(out) not in (2, 3):
            raise CommandError(f"act_batch must return (steering, speed) or (steering, speed, labels), got "
                               f"{type(out).__name__}", source=f"controller {controller}", field=f"step {step}")
        steering, speed = check_commands(out[0], out[1], n, controller, step)
        labels = list(out[2]) if len(out) > 2 else [""] * n
        if len(labels) != n:
            raise CommandError(f"act_batch gave {len(labels)} labels for {n} robots", source=f"controller {controller}",
                               field=f"step {step}")
        return steering, speed, labels
    steering, speed, labels = np.zeros(n), np.zeros(n), [""] * n
    for i in np.flatnonzero(obs.active):
        command = controllers[0 if n == 1 else i].act(obs.single(i))
        steering[i], speed[i], labels[i] = command_values(command, controller, step)
    return steering, speed, labels


def invalid_states(state, step: int, history=None) -> dict[int, tuple[int, str]]:
    """After a compiled navigator's steps (it decides inside the compiled call, so its commands
    are found in the state; the simulator looks every few steps): ``{robot: (steps, reason)}``
    of each robot whose pose or command is not finite — ``steps`` the commands it took before the
    bad one and ``reason`` of :func:`invalid_reason`. With ``history`` (the states recorded so
    far, one per step) the first bad step is found; without, the robot is named ``by step``."""
    moved = state[:, step_kernel.X:step_kernel.SPEED + 1]
    found = {}
    for i in np.flatnonzero(~np.isfinite(moved).all(axis=1)):
        row, where, steps = state[i], f"by step {step}", step
        if history:
            bad = next(k for k, past in enumerate(history)
                       if not np.isfinite(past[i, step_kernel.X:step_kernel.SPEED + 1]).all())
            row, where, steps = history[bad][i], f"step {bad - 1}", bad - 1
        found[int(i)] = (steps, invalid_reason(where, row[step_kernel.STEERING], row[step_kernel.SPEED]))
    return found


def check_starts(starts, world=None) -> np.ndarray:
    """Start poses given to the simulator: one pose (x, y, θ) or ``(N, 3)`` of them, N at most
    ``validation.MAX_ROBOTS``, numbers, finite (``[[5, 5], [6, 6], [7, 7]]`` is refused, not
    read as two poses), headings in radians (:func:`fuzzynav.world.limits.angle`), inside ``world``
    when given (a start outside it ran as a collision)."""
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
    turned = np.flatnonzero(np.abs(poses[:, 2]) > limits.MAX_ANGLE)
    if turned.size:  # a heading in degrees, as a scenario file's theta
        limits.angle(float(poses[turned[0], 2]), field=f"starts[{int(turned[0])}].theta")
    outside = np.flatnonzero(~world.contains(poses[:, :2])) if world is not None else np.zeros(0, dtype=int)
    if outside.size:
        i = int(outside[0])
        raise InputError(f"({poses[i, 0]:g}, {poses[i, 1]:g}) is outside the {world.width:g} x {world.height:g} m world",
                         field=f"starts[{i}]")
    return poses
