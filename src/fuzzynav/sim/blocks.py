"""A large batch's step in row blocks on the process' threads.

The compiled step (:func:`fuzzynav.kernels.step.step`) releases the GIL, and a robot's step writes
only its own rows of the batch's arrays and reads the shared world — but for one flag of the
layers' parameters, ``grow`` (its obstacle-point slots are nearly full), which any robot may set to
1 and the simulator reads once the step has ended. So the rows can be cut into blocks
that threads step at once (:func:`fuzzynav.threads.spread`), each block one call of the step on
views of its rows. The moving obstacles are placed once, before the blocks, and the blocks are
given the world with the obstacles in place.
"""

from __future__ import annotations

from fuzzynav import threads
from fuzzynav.kernels import step, traffic
from fuzzynav.kernels.records import Robots, StepNavigator, Traffic

ROBOTS_PER_THREAD = 32  # running robots a thread must have before a batch is cut


def step_in_blocks(running: int, params, layer_params, navigator, setup, world, k, robots, imperfect) -> int:
    """:func:`~fuzzynav.kernels.step.step` (the arguments after ``running``, the robots running
    before it; returns how many still run), in row blocks on the process' threads when there are
    at least :data:`ROBOTS_PER_THREAD` running robots a thread and the robot is perfect and moved
    by the step; otherwise one call. The result is the same for any number of threads, but for a
    navigator that raises on a non-finite input: there every other block ends its step, where one
    call stops at the robot that raised. (A block's share of the batch is fixed by its rows, so
    blocks whose robots have ended sooner wait for the others.)"""
    count = 1 if running < 2 * ROBOTS_PER_THREAD else min(threads.count(), running // ROBOTS_PER_THREAD)
    if count <= 1 or imperfect is not None or not robots.moves:
        return step.step(params, layer_params, navigator, setup, world, k, robots, imperfect)
    traffic.place(world.base, world.movers, world.offsets, world.scene)
    placed = Traffic(world.scene, world.movers[:0], world.offsets[:0], world.scene)
    counts = []

    def block(first: int, last: int) -> None:
        rows = slice(first, last)
        layer_state = navigator.layer_state  # None without layers (lean_arguments)
        part = StepNavigator(navigator.kind, navigator.tables, navigator.state[rows], navigator.memory[rows],
                             None if layer_state is None else layer_state[rows], navigator.route)
        counts.append(step.step(params, layer_params, part, setup, placed, k, Robots(
            robots.state[rows], robots.ranges[rows], robots.status[rows], True), None))

    threads.spread(block, robots.state.shape[0], threads=count, per_thread=1)
    return sum(counts)
