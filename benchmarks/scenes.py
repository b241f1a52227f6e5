"""The paper's two scenes as benchmark problems (units g = ell = 1)."""
from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

import knifeedge as ke

#: small-oscillation period 2 pi sqrt(ell/g) in these units
PERIOD = 2 * math.pi


@dataclass(frozen=True)
class Scene:
    key: str
    title: str
    model_name: str
    params: dict
    y0: dict
    t_end: float
    fidelity: str = "full"
    pose: bool = False
    notes: str = field(default="")

    @property
    def model(self) -> ke.Model:
        return ke.load(self.model_name, self.fidelity, pose=self.pose)

    @property
    def p(self) -> np.ndarray:
        return self.model.params(**self.params)

    @property
    def y(self) -> np.ndarray:
        return self.model.state(**self.y0)

    def with_end(self, t_end: float) -> "Scene":
        return Scene(self.key, self.title, self.model_name, self.params, self.y0, t_end, self.fidelity, self.pose)


SINGLE = Scene(
    "single", "single mode (Fig. numerical), t = 0..300", "single_mode",
    dict(g=1.0, ell=1.0, L=1.0, D=1.0), dict(theta=1e-3, theta_dot=0.0, phi_dot=0.1), 300.0,
)
TWO = Scene(
    "two", "two modes (Fig. Numerical2), t = 0..3000", "two_mode",
    dict(g=1.0, ell=1.0, L=2.0, D=0.5, alpha=math.pi / 4),
    dict(theta1=1e-3, theta2=1e-3, theta1_dot=0.0, theta2_dot=0.0, phi_dot=0.1), 3000.0,
)
