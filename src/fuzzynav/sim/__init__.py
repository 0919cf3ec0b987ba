"""Simulation layer: episode loop, tasks, traces, metrics and batch stepping of many robots."""

from fuzzynav.control.base import BatchObservation
from fuzzynav.sim.metrics import metrics
from fuzzynav.sim.simulator import BatchSimulator, Simulator, run_episode
from fuzzynav.sim.trace import Trace

__all__ = ["BatchObservation", "BatchSimulator", "Simulator", "Trace", "metrics", "run_episode"]
