"""Linearised dynamics of an arm at its current state and inputs (Arm.linearize; engine: cpp/src/linearize.cc).

x = [q | qdot | lce | activation] (rad, rad/s, m, 1), u = excitation (1, one per element). The continuous
linearisation dx/dt ~ f(x0, u0) + dfdx dx + dfdu du is forward()'s tangent; the discrete one
x+ ~ x0+ + A dx + B du is the derivative of one ROS2 step of dt (docs/control.md "Linearised dynamics": method, residuals, kinks).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

# What each state block is measured in (the rows and columns of A, B, dfdx, dfdu).
STATE_UNITS = {"q": "rad", "qdot": "rad/s", "lce": "m", "activation": "1"}


@dataclass(frozen=True)
class Linearization:
    """One linearisation. ns = 2 n_dofs + 2 n_elements (das2: 214), m = n_elements (das2: 102).

    A: (ns, ns) dx+/dx of one ROS2 step of dt, None when continuous; B: (ns, m) dx+/du, None when continuous;
    dfdx: (ns, ns) 1/s (per the row/column units) d(dx/dt)/dx of forward(); dfdu: (ns, m) d(dx/dt)/du, nonzero only
    in the activation rows. x0: (ns,) the state, u0: (m,) the excitation as the dynamics use it (capped), x0_next:
    (ns,) where the step from (x0, u0) lands (None when continuous); dt: s. slices: {block name: slice} of the state
    (q, qdot, lce, activation); units: {block name: unit}; state_names, input_names: one name a row / a column."""
    A: np.ndarray | None
    B: np.ndarray | None
    dfdx: np.ndarray
    dfdu: np.ndarray
    x0: np.ndarray
    u0: np.ndarray
    x0_next: np.ndarray | None
    dt: float
    slices: dict
    units: dict
    state_names: list
    input_names: list

    def block(self, matrix: str, rows: str, cols: str) -> np.ndarray:
        """A sub-block by state block names, e.g. block("A", "q", "activation"); cols "u" for B and dfdu. KeyError for
        an unknown matrix or block name, ValueError for A or B of a continuous linearisation."""
        if matrix not in ("A", "B", "dfdx", "dfdu"):
            raise KeyError(f"unknown matrix {matrix!r}: one of 'A', 'B', 'dfdx', 'dfdu'")
        M = getattr(self, matrix)
        if M is None:
            raise ValueError(f"{matrix} is not computed in a continuous linearisation")
        if rows not in self.slices:
            raise KeyError(f"unknown state block {rows!r}: one of {sorted(self.slices)}")
        if matrix in ("B", "dfdu"):
            if cols != "u":
                raise KeyError(f"{matrix}'s columns are the excitation: cols='u'")
            return M[self.slices[rows]]
        if cols not in self.slices:
            raise KeyError(f"unknown state block {cols!r}: one of {sorted(self.slices)}")
        return M[self.slices[rows], self.slices[cols]]


def state_names(arm) -> list[str]:
    """One name per state entry: q[GHy], qdot[GHy], lce[bicl], activation[bicl], ..."""
    names = []
    for block, (offset, size) in arm.model.state_layout.items():
        labels = arm.dof_names if block in ("q", "qdot") else arm.element_names
        names += [f"{block}[{labels[k]}]" for k in range(size)]
    return names
