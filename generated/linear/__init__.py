"""Linear models obtained by machine from derived nonlinear ones (``derivation/bicycle_linear.py``).

GENERATED FILE -- DO NOT EDIT BY HAND.  Run ``make bicycle-linear`` to regenerate.
"""
