"""The classical rattleback (celt) as a rigid body, written with the public front end.

An ellipsoidal bottom with semi-axes ``a, b, c`` along the body axes
``x, y, z``; body frame with its origin at the centre of mass, ``z`` along
``c`` pointing up (from the contact toward the body); the centre of mass a
distance ``h`` below the centre of the ellipsoid.  The inertia tensor about
the centre of mass is given by its six matrix entries in that frame; a
non-zero ``I_xy`` turns its principal axes about the vertical body axis
relative to the ellipsoid's axes -- the chirality.  Dissipation: a torque
``-sigma * omega`` about the centre of mass.

Presets (SI units):

- ``kane_levinson_1982``: T. R. Kane and D. A. Levinson, "Realistic
  mathematical modeling of the rattleback", Int. J. Non-Linear Mech. 17
  (1982) 175-186.
- ``schoemer``: the rattleback of E. Schömer's rattleback simulation
  (golden-ratio ellipsoid), as given in the issue that introduced it.
"""
from __future__ import annotations

import sympy as sp

from .rigid import Ellipsoid, RigidBody
from .steady import UPRIGHT_SPIN

a, b, c, h, m, g = sp.symbols("a b c h m g", positive=True)
I_xx, I_yy, I_zz = sp.symbols("I_xx I_yy I_zz", positive=True)
I_xy, I_xz, I_yz = sp.symbols("I_xy I_xz I_yz", real=True)
sigma = sp.Symbol("sigma", nonnegative=True)

PRESETS = {
    "kane_levinson_1982": {"a": 0.20, "b": 0.03, "c": 0.02, "h": 0.01, "m": 1.0, "g": 9.81,
                           "I_xx": 2e-4, "I_yy": 1.6e-3, "I_zz": 1.7e-3, "I_xy": 2e-5, "I_xz": 0.0,
                           "I_yz": 0.0, "sigma": 0.0},
    "schoemer": {"a": (1 + 5**0.5) / 2, "b": 1.0, "c": 1.0, "h": 0.1875, "m": 0.2, "g": 9.81,
                 "I_xx": 0.05796875, "I_yy": 0.09032943, "I_zz": 0.12236068, "I_xy": -0.025,
                 "I_xz": 0.0, "I_yz": 0.0, "sigma": 0.0},
}
PRESET_SOURCES = {
    "kane_levinson_1982": "Kane & Levinson, Int. J. Non-Linear Mech. 17 (1982) 175-186",
    "schoemer": "E. Schoemer's rattleback (golden-ratio ellipsoid)",
}


def celt() -> RigidBody:
    """The rattleback of the module docstring."""
    inertia = sp.Matrix([[I_xx, I_xy, I_xz], [I_xy, I_yy, I_yz], [I_xz, I_yz, I_zz]])
    return RigidBody(
        name="celt",
        steady=(UPRIGHT_SPIN,),
        mass=m,
        inertia=inertia,
        shape=Ellipsoid(a, b, c, centre=(0, 0, h)),
        gravity=g,
        params=(a, b, c, h, m, g, I_xx, I_yy, I_zz, I_xy, I_xz, I_yz, sigma),
        sigma=sigma,
        param_units={"a": "m", "b": "m", "c": "m", "h": "m", "m": "kg", "g": "m/s^2",
                     **{str(s): "kg m^2" for s in (I_xx, I_yy, I_zz, I_xy, I_xz, I_yz)}, "sigma": "N m s"},
        param_domains={"I_xy": "real", "I_xz": "real", "I_yz": "real", "sigma": "nonnegative"},
        description=(
            "Classical rattleback (celt): a rigid body with an ellipsoidal bottom (semi-axes a, b, c along the "
            "body axes x, y, z; centre of mass a distance h below the ellipsoid's centre), inertia tensor about "
            "the centre of mass with entries I_xx..I_yz in body axes, rolling without slipping on a horizontal "
            "table under gravity g, dissipation torque -sigma*omega.  State: upward vertical n and angular "
            "velocity omega in body axes, vertical spin omega_n = omega.n; pose: heading psi of the body x axis, "
            "centre of mass (x, y)."
        ),
        presets=PRESETS,
        preset_sources=PRESET_SOURCES,
        source=__name__,
        default_state={"n0": (0.0087262, 0.0087265, 0.9999238), "omega0": (0.0, 0.0, 5.0),
                       # the small-tilt fidelities' default: tilts 1e-4 rad, spin 0.2 rad/s (Moffatt-Tokieda regime)
                       "small": {"n0": (1e-4, 1e-4, 1.0), "omega0": (0.0, 0.0, 0.2)}},
        small=("n_x", "n_y", "omega_x", "omega_y"),  # -> fidelities reduced and amplitude (derivation/rigid_small.py)
    )
