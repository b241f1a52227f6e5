"""whipple_bicycle: the lean/steer equations about straight running, A(v) = A0 + v A1 + v^2 A2.

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make bicycle-linear`` to regenerate.
Produced by derivation/bicycle_linear.py from tests/models/whipple_bicycle.py: the lean/steer block of the derived bicycle's
generated Jacobian at straight running at v = 0, 1, 2 m/s, at the benchmark's
parameters (Meijaard et al. 2007, Table 1).  SymPy 1.14.0; input hash sha256:faeb741aee43b210a3fdef6c6f5704e23d0a19af3519c4902c7e041f530da011
"""
#: the linear state: lean q2, steer q5 [rad], their rates [rad/s]
STATE_NAMES = ('q2', 'q5', 'q2_dot', 'q5_dot')
#: forward speeds [m/s] whose Jacobians gave the coefficients
SPEEDS = (0.0, 1.0, 2.0)
#: A(v) = A0 + v A1 + v^2 A2 (rows: rates of STATE_NAMES; columns: STATE_NAMES)
A0 = ((0.0, 0.0, 1.0, 0.0), (0.0, 0.0, 0.0, 1.0), (9.489774446773556, -0.5715231737292454, 0.0, 0.0), (11.719476871963291, 30.908753393240698, 0.0, 0.0))
A1 = ((0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0), (0.0, 3.3306690738754696e-16, -0.10552244980569103, -0.33051539899231064), (0.0, -3.552713678800501e-15, 3.676805233321529, -3.0848655274331125))
A2 = ((0.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0), (0.0, -0.8911977380590886, 0.0, 0.0), (0.0, -1.9717150849997225, 0.0, 0.0))
CHECK_SPEEDS = (5.0, 10.0)
#: largest |A(v) - polynomial| at CHECK_SPEEDS (the polynomial is exact)
FIT_RESIDUAL = 2.842170943040401e-14
#: SHA-256 of tests/models/whipple_bicycle.py, derivation/bicycle_linear.py and its PIPELINE
INPUT_HASH = 'faeb741aee43b210a3fdef6c6f5704e23d0a19af3519c4902c7e041f530da011'
SYMPY_VERSION = '1.14.0'
#: SHA-256 of this file's bytes above this line; knifeedge.load refuses the module if they differ
MODULE_SHA256 = 'a80ebb5e76d6f95f379341537fde7521a8898c84e9a04206508dea4d12256cda'
