"""armrt.Stepper, armrt.step and armrt.forward: the engine's three-part API in Python, one to one with C++
(cpp/include/armrt/stepper.h): a shared immutable Model, a Data per arm, and a Stepper saying how a Data is
advanced (integrator, control step dt, substeps).

    model = armrt.Model("das2")
    data = armrt.Data(model)
    stepper = armrt.Stepper(model, "ros2", dt=1e-3)
    armrt.step(model, data, stepper, n=100)   # 100 control steps of 1 ms
    outputs = armrt.forward(model, data)      # the outputs at data's state (computed once per state)

armrt.Arm is Model + Data + Stepper + the input checks; most users want it."""
from __future__ import annotations

from dataclasses import dataclass

from .integrators import DEFAULT_INTEGRATOR, control_step
from .model import Model


@dataclass(frozen=True)
class Stepper:
    """How a Data is advanced: integrator ("ros2", "ros2_adaptive", "rk4", "euler", "cvode"), control step dt
    (s: inputs held, outputs reported, TET measured per dt) and substeps (integration steps per control step;
    None: the integrator's validated default). Raises ValueError / TypeError as Arm does for the same input.
    The integrator's workspace and memory (ROS2's path history, CVODE's) live with the Data it steps, as the C++
    Stepper is bound to one Data."""

    model: Model
    integrator: str = DEFAULT_INTEGRATOR
    dt: float = 1e-3
    substeps: int | None = None

    def __post_init__(self):
        object.__setattr__(self, "model", Model(self.model))
        dt, substeps = control_step(self.integrator, self.dt, self.substeps)
        object.__setattr__(self, "dt", dt)
        object.__setattr__(self, "substeps", substeps)


def _check(model, data, what: str) -> None:
    from .data import Data
    if not isinstance(data, Data):
        raise TypeError(f"{what}: data must be an armrt.Data, got {type(data).__name__}")
    if Model(model) is not data.model:
        raise ValueError(f"{what}: data belongs to model {data.model.name!r}, not {Model(model).name!r}")


def step(model, data, stepper: Stepper, n: int = 1) -> None:
    """Advances data by n control steps of stepper (C++ step(model, data, stepper, n)). Raises
    SimulationError on divergence (the state stays where it stopped), ValueError for a Data of another model or
    a Stepper of another model. Changing a Data's stepper (another integrator, dt or substeps) starts the
    integrator's memory afresh; an Arm's Data (arm.data) goes back to the Arm's own integrator after the steps."""
    from .checks import count
    _check(model, data, "step")
    if not isinstance(stepper, Stepper):
        raise TypeError(f"step: stepper must be an armrt.Stepper, got {type(stepper).__name__}")
    if stepper.model is not data.model:
        raise ValueError(f"step: the stepper is for model {stepper.model.name!r}, data for {data.model.name!r}")
    data._step(stepper.integrator, stepper.dt, stepper.substeps, count(n, "n"))


def forward(model, data) -> dict:
    """The outputs at data's current state (C++ forward() with record; computed only if they do not already
    describe it): the dict armrt.Data.outputs() gives. ValueError for a Data of another model."""
    _check(model, data, "forward")
    return data.outputs()
