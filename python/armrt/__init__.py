"""armrt: a hard-real-time musculoskeletal simulator of the human arm.

The paper's model (fixed scapula, 5 DOF, 22 muscles in 102 Hill-type elements) from the DAS3 data,
integrated in C++; see armrt.Arm.
"""
from .arm import Arm, Result, SimulationError, deg, rad
from .realtime import RealtimeSession, UdpClient

__all__ = ["Arm", "Result", "SimulationError", "deg", "rad", "RealtimeSession", "UdpClient"]
__version__ = "0.1.0"
