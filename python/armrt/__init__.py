"""armrt: a hard-real-time musculoskeletal simulator of the human arm.

The paper's model (fixed scapula, 5 DOF, 22 muscles in 102 Hill-type elements) from the DAS3 data,
integrated in C++; see armrt.Arm.
"""
from ._version import __version__
from .arm import Arm
from .batch import ArmBatch
from .checks import deg, rad
from .control import StaticOptimizationResult, StaticOptimizer, inverse_dynamics, static_optimization
from .control_motion import static_optimization_motion
from .control_tracking import TrackingResult, track_motion
from .data import Data, State
from .fes_control import (ControlRun, FeedforwardPID, PDController, PDParams, PIDParams, StimulationCoding,
                          run_offline)
from .errors import ConcurrentUseError, SimulationError, StaticOptimizationInfeasible, StepSizeWarning
from .model import Model, models
from .model_build import CompilerNotFoundError, ModelBuildError, ModelFileError
from .result import Result
from .snapshot import StatePart
from .stepper import Stepper, forward, step
from .sweeps import sweep

__all__ = ["Arm", "Stepper", "step", "forward", "Result", "SimulationError", "StepSizeWarning", "ConcurrentUseError", "deg", "rad", "ArmBatch",
           "sweep", "inverse_dynamics", "static_optimization", "static_optimization_motion", "track_motion", "TrackingResult", "StaticOptimizer", "StaticOptimizationResult",
           "StaticOptimizationInfeasible", "Model", "Data", "State", "StatePart", "models", "ModelFileError", "ModelBuildError", "CompilerNotFoundError",
           "FeedforwardPID", "PDController", "PIDParams", "PDParams", "StimulationCoding", "ControlRun", "run_offline",
           "RealtimeSession", "UdpClient"]
try:  # the packet layout comes from armrt._rt: without that extension the rest of armrt still works
    from .realtime import RealtimeSession, UdpClient
except ImportError:  # pragma: no cover (an incomplete build: PYTHONPATH=python with only _core copied)
    __all__ = __all__[:-2]
