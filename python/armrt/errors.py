"""The exceptions and warnings of the simulation API, in a module of their own so that every layer
(Data, Arm, ArmBatch, the checks) can raise them without importing the others."""
from __future__ import annotations


class StepSizeWarning(RuntimeWarning):
    """An integration step above the largest one validated against CVODE (armrt.integrators.DEFAULT_MAX_STEP)."""


class SimulationError(RuntimeError):
    """The simulation diverged or left the model's physical domain: a non-finite state, a joint faster
    than the physical bound, a fibre length, activation or joint angle out of range (docs/engine.md), or
    an explicit step too large for the model."""


class ConcurrentUseError(RuntimeError):
    """An Arm (or its Data) was used from a second thread while another thread was stepping or changing it."""


RESET_HINT = "; call reset() to continue"  # how a SimulationError of a failed step ends


def simulation_error(exc: RuntimeError) -> SimulationError:
    """The engine's RuntimeError as a SimulationError that says how to go on."""
    msg = str(exc)
    # A step the integrator cannot take fails again after reset(): the message says what to change.
    hint = "" if msg.startswith("step too large") else RESET_HINT
    return SimulationError(msg + hint)


class StaticOptimizationInfeasible(ValueError):
    """No activations within [0, max_activation] supply the required moments (with the GH bound, if asked):
    the message is the report (residual moment per DOF, binding constraints); .result is the closest
    solution (armrt.control.StaticOptimizationResult, feasible False)."""

    def __init__(self, report: str, result=None):
        super().__init__(report)
        self.report = report
        self.result = result
