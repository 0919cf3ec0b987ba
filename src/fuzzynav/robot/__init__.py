"""Robot layer: tricycle kinematics (eq IV.1–IV.2) and the range-sensor ring (§IV.7)."""

from fuzzynav.robot.sensors import THESIS_SENSOR_ANGLES, SensorRing
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams, step

__all__ = ["DEFAULT_PARAMS", "THESIS_SENSOR_ANGLES", "SensorRing", "TricycleParams", "step"]
