"""Integrator kernel templates.

Each template is an ordinary module whose loop reaches the right-hand side
through the module-level name ``_rhs`` (numba cannot cache a function that
receives another compiled function as an argument).  The line marked
``# knifeedge:rhs`` imports a stand-in (:mod:`._stub`); :mod:`..specialize`
rewrites that line to import a generated model's ``rhs_into`` and the line
marked ``# knifeedge:variant`` to choose the method, writes the result to the
kernel cache and imports it, so each (model, method) pair is compiled once
and cached across processes.
"""
