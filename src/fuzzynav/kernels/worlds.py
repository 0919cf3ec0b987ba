"""The stepping core for N robots each in its own world, commands given: the compiled loop of
:class:`fuzzynav.world.fleet.Fleet` (the training and Gymnasium environments).

Each robot ``n`` has its own scene array ``scenes[scene_bounds[n, 0]:scene_bounds[n, 1]]``
(several worlds' packed arrays end to end, :mod:`fuzzynav.kernels.layout`) and its own set-up
array ``setups[setup_bounds[n, 0]:setup_bounds[n, 1]]`` (robot, sensors and task:
:func:`fuzzynav.kernels.step.setup_array`); ``state``, ``ranges`` and ``status`` are the arrays
of :mod:`fuzzynav.kernels.step`. A robot's step is the simulator's: :func:`~fuzzynav.kernels.step.limit`
then :func:`~fuzzynav.kernels.step.move` (kinematics, then the stop tests in their order —
collision, task, time limit — and the sensing of :func:`~fuzzynav.kernels.step.settle`).
"""

from __future__ import annotations

from fuzzynav.jit import jit
from fuzzynav.kernels.step import OUTCOME, RUNNING, SPEED, STEPS, limit, move, settle


@jit
def settle_rows(scenes, scene_bounds, setups, setup_bounds, rows, state, ranges, status):
    """Stop tests and sensing at step 0 of the robots ``rows`` (indices), each in its world."""
    for n in rows:
        settle(setups[setup_bounds[n, 0]:setup_bounds[n, 1]], scenes[scene_bounds[n, 0]:scene_bounds[n, 1]], 0,
               state, ranges, status, n, None)


@jit
def step(scenes, scene_bounds, setups, setup_bounds, commands, live, robots):
    """One step Δt of every robot that is ``live`` (N,) bool and still running, under its command
    ``commands[n]`` = (α, V); the others stand still at speed 0. ``robots`` is a
    :class:`~fuzzynav.kernels.records.Robots` (its ``moves`` unused). Each robot's step count is
    its own (``status[n, STEPS]``). Returns how many still run."""
    state, status = robots.state, robots.status
    running = 0
    for n in range(state.shape[0]):
        if not live[n] or status[n, OUTCOME] != RUNNING:
            state[n, SPEED] = 0.0
            continue
        setup = setups[setup_bounds[n, 0]:setup_bounds[n, 1]]
        steering, speed = limit(setup, commands[n, 0], commands[n, 1])
        move(setup, scenes[scene_bounds[n, 0]:scene_bounds[n, 1]], status[n, STEPS] + 1, robots, n, steering, speed,
             None)
        running += status[n, OUTCOME] == RUNNING
    return running
