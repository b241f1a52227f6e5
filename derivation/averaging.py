"""First-order averaging: amplitude equations (the ``amplitude`` fidelity) from a ``reduced`` system.

The ``reduced`` equations of a knife edge have fast tilt oscillations and a
slow spin rate,

    theta_i_ddot = -omega_i^2 theta_i + F_i(theta, theta_dot, phi_dot),
    phi_ddot     = G(theta, theta_dot, phi_dot),

with ``F_i`` vanishing at ``phi_dot = 0`` (paper section II.C, ``Chap1``,
``Chap2``; section III, ``eqs_2modes``).  :func:`average` substitutes

    theta_i = A_i cos(psi_i),   theta_i_dot = -omega_i A_i sin(psi_i),
    psi_i = omega_i t + beta_i,

so that exactly (variation of constants)

    A_i_dot    = -sin(psi_i) F_i / omega_i,
    beta_i_dot = -cos(psi_i) F_i / (omega_i A_i),
    A_phi_dot  = G,

and averages the right-hand sides over the fast phases ``psi_i``, treated as
independent (non-resonant: the frequencies must be distinct, which is
checked).  Each averaged equation is then kept to its leading order in
``phi_dot/omega`` (the spin rates are scaled by a bookkeeping ``delta`` and
the lowest non-vanishing power is kept).  Nothing in this module knows which
model it averages: the tilts, their frequencies and the spin rates come from
the :class:`~derivation.engine.ModelSpec` and the reduced equations.

The result (:class:`AmplitudeSystem`) carries the slow flow on the state
``(A_1, ..., A_n, A_phi)``, the averaged phase drifts (zero for both knife
edges at this order, so the phases are not part of the state), the averaged
energy (a conserved quantity of the slow flow, checked symbolically) and, when
every amplitude equation has the form ``A_i_dot = c_i A_phi A_i``, the
integrals ``c_j ln A_i - c_i ln A_j`` that make the two-mode slow flow
integrable (Moffatt & Tokieda, Proc. R. Soc. Edinb. 138A (2008) 361).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction

import sympy as sp

from .engine import ReducedSystem, tidy

#: bookkeeping scale of the spin rates (leading order in phi_dot/omega)
delta = sp.Symbol("delta", positive=True)


@dataclass
class AmplitudeSystem:
    """Averaged slow flow of a reduced system.

    Attributes
    ----------
    spec : the model (:class:`~derivation.engine.ModelSpec`).
    source : the reduced system that was averaged.
    tilts, spins : the reduced system's tilt coordinates and spin rates.
    amplitudes : amplitude symbols ``A_i``, one per tilt (same order).
    spin_amplitudes : slow spin-rate symbols (``A_phi`` for ``phi_dot``).
    state : ``amplitudes + spin_amplitudes``.
    rates : averaged right-hand sides, aligned with ``state``.
    frequencies : ``omega_i`` of the tilts at zero spin.
    phase_rates : averaged ``beta_i_dot`` (leading order).
    energy : averaged energy per unit mass, conserved by ``rates``.
    invariants : further conserved quantities (name -> expression).
    growth : ``c_i`` with ``A_i_dot = c_i A_phi A_i`` (``None`` if not of that form).
    dimensions : state name -> (length exponent, time exponent).
    """

    spec: object
    source: ReducedSystem
    tilts: tuple
    spins: tuple
    amplitudes: tuple
    spin_amplitudes: tuple
    state: tuple
    rates: list
    frequencies: tuple
    phase_rates: list
    energy: sp.Expr
    invariants: dict = field(default_factory=dict)
    growth: tuple | None = None
    dimensions: dict = field(default_factory=dict)

    def state_rhs(self) -> list:
        """Right-hand side of ``d(state)/dt``."""
        return list(self.rates)


def amplitude_name(tilt: sp.Symbol) -> str:
    """``theta -> A_theta``, ``theta1 -> A1`` (the paper's ``A_theta``; numbered tilts by their index)."""
    name = str(tilt)
    stem = name.rstrip("0123456789")
    if stem != name and stem == "theta":
        return "A" + name[len(stem):]
    return "A_" + name


def spin_amplitude_name(rate: sp.Symbol) -> str:
    """``phi_dot -> A_phi`` (the paper's ``A_phi = phi_dot``)."""
    name = str(rate)
    return "A_" + (name[: -len("_dot")] if name.endswith("_dot") else name)


def phase_average(monomial_powers: tuple) -> sp.Rational:
    """Average of ``prod_i cos(psi_i)^m_i sin(psi_i)^n_i`` over independent phases.

    ``monomial_powers`` is ``((m_1, n_1), (m_2, n_2), ...)``.  Each factor
    averages to ``(m-1)!! (n-1)!! / (m+n)!!`` when ``m`` and ``n`` are both
    even, else to zero.
    """
    out = Fraction(1)
    for m, n in monomial_powers:
        if m % 2 or n % 2:
            return sp.S.Zero
        out *= Fraction(_double_factorial(m - 1) * _double_factorial(n - 1), _double_factorial(m + n))
    return sp.Rational(out.numerator, out.denominator)


def _double_factorial(k: int) -> int:
    out = 1
    while k > 1:
        out *= k
        k -= 2
    return out


def _average(e: sp.Expr, cos_s: list, sin_s: list) -> sp.Expr:
    """Average a polynomial in ``cos_s``/``sin_s`` (coefficients anything) over the phases."""
    gens = [v for pair in zip(cos_s, sin_s) for v in pair]
    poly = sp.Poly(sp.expand(e), *gens)
    out = sp.S.Zero
    for powers, coeff in poly.terms():
        pairs = tuple(zip(powers[0::2], powers[1::2]))
        out += phase_average(pairs) * coeff
    return out


def _leading_order(e: sp.Expr, scaled: dict) -> sp.Expr:
    """Lowest non-vanishing power of ``delta`` in ``e`` after ``scaled`` (spin rate -> delta * rate)."""
    d = sp.expand(e.subs(scaled, simultaneous=True))
    if d == 0:
        return sp.S.Zero
    poly = sp.Poly(d, delta)
    k = min(m[0] for m in poly.monoms())
    return sp.expand(poly.coeff_monomial(delta**k))


def frequencies(system: ReducedSystem) -> tuple:
    """``omega_i`` with ``theta_i_ddot = -omega_i^2 theta_i`` at zero spin and infinitesimal tilts.

    Raises ``ValueError`` when the linear tilt dynamics at zero spin is not a
    set of uncoupled, undamped oscillators of distinct frequencies (the
    averaging below would not apply).
    """
    spec = system.spec
    tilts = list(spec.small)
    n = len(tilts)
    rates = [spec.velocity_of(q) for q in tilts]
    spins = list(system.state[2 * n:])
    at_rest = {s: 0 for s in spins}
    out = []
    for i, q in enumerate(tilts):
        acc = sp.expand(system.explicit[i].subs(at_rest))
        lin = sp.Poly(acc, *tilts, *rates)
        if lin.total_degree() > 1:
            raise ValueError(f"{spec.name}: tilt equation {i} is not linear at zero spin")
        for v in tilts + rates:
            c = sp.simplify(lin.coeff_monomial(v))
            if v != q and c != 0:
                raise ValueError(f"{spec.name}: tilt {q} is coupled to {v} at zero spin (coefficient {c})")
        w2 = sp.factor(-lin.coeff_monomial(q))
        if not w2.is_positive:
            raise ValueError(f"{spec.name}: omega^2 = {w2} of tilt {q} is not positive")
        out.append(sp.sqrt(w2))
    for i in range(n):
        for j in range(i + 1, n):
            if sp.simplify(out[i] ** 2 - out[j] ** 2) == 0:
                raise ValueError(f"{spec.name}: tilts {tilts[i]} and {tilts[j]} are resonant (equal frequencies)")
    return tuple(out)


def _growth_rates(rates, amplitudes, spin) -> tuple | None:
    """``c_i`` if every ``A_i_dot == c_i * A_phi * A_i`` with ``c_i`` free of the state."""
    cs = []
    state = set(amplitudes) | {spin}
    for A, r in zip(amplitudes, rates):
        c = sp.simplify(r / (spin * A))
        if c.free_symbols & state:
            return None
        cs.append(c)
    return tuple(cs)


def _is_conserved(q: sp.Expr, state, rates) -> bool:
    return sp.simplify(sum(sp.diff(q, s) * r for s, r in zip(state, rates))) == 0


def average(system: ReducedSystem) -> AmplitudeSystem:
    """First-order averaging of a ``reduced`` system (see the module docstring)."""
    spec = system.spec
    tilts = tuple(spec.small)
    n = len(tilts)
    if tuple(system.state[:n]) != tilts:
        raise ValueError(f"{spec.name}: the state must start with the tilts {tilts}")
    tilt_rates = tuple(system.state[n:2 * n])
    spins = tuple(system.state[2 * n:])
    if len(spins) != 1:
        raise ValueError(f"{spec.name}: averaging needs exactly one spin rate, got {spins}")
    omegas = frequencies(system)

    amps = tuple(sp.Symbol(amplitude_name(q), nonnegative=True) for q in tilts)
    spin_amps = tuple(sp.Symbol(spin_amplitude_name(s), real=True) for s in spins)
    cos_s = [sp.Symbol(f"_c{i}", real=True) for i in range(n)]
    sin_s = [sp.Symbol(f"_s{i}", real=True) for i in range(n)]
    fast = {}
    for i in range(n):
        fast[tilts[i]] = amps[i] * cos_s[i]
        fast[tilt_rates[i]] = -omegas[i] * amps[i] * sin_s[i]
    fast.update(dict(zip(spins, spin_amps)))
    scaled = {a: delta * a for a in spin_amps}

    rates, phase_rates = [], []
    for i in range(n):
        F = sp.expand(system.explicit[i] + omegas[i] ** 2 * tilts[i]).subs(fast, simultaneous=True)
        rates.append(_leading_order(_average(-sin_s[i] * F / omegas[i], cos_s, sin_s), scaled))
        phase = _average(-cos_s[i] * F / omegas[i], cos_s, sin_s)
        phase_rates.append(_leading_order(sp.expand(phase / amps[i]), scaled))
    for k in range(len(spins)):
        G = system.explicit[n + k].subs(fast, simultaneous=True)
        rates.append(_leading_order(_average(G, cos_s, sin_s), scaled))

    state = amps + spin_amps
    rates = [tidy(r, list(state)) for r in rates]
    phase_rates = [tidy(r, list(state)) if r != 0 else sp.S.Zero for r in phase_rates]

    energy = _averaged_energy(system, fast, cos_s, sin_s, state)
    if not _is_conserved(energy, state, rates):
        raise ValueError(f"{spec.name}: the averaged energy {energy} is not conserved by the slow flow")
    growth = _growth_rates(rates[:n], amps, spin_amps[0])
    invariants = {"energy": energy}
    if growth is not None:
        for i in range(n):
            for j in range(i + 1, n):
                q = sp.log(amps[j]) - sp.factor(growth[j] / growth[i]) * sp.log(amps[i])
                if not _is_conserved(q, state, rates):
                    raise ValueError(f"{spec.name}: {q} is not conserved")
                invariants[f"log_{amps[i]}_{amps[j]}"] = q
    dims = {str(a): (0, 0) for a in amps}
    dims.update({str(a): (0, -1) for a in spin_amps})
    return AmplitudeSystem(
        spec=spec, source=system, tilts=tilts, spins=spins, amplitudes=amps, spin_amplitudes=spin_amps,
        state=state, rates=rates, frequencies=omegas, phase_rates=phase_rates, energy=energy,
        invariants=invariants, growth=growth, dimensions=dims,
    )


def _averaged_energy(system, fast, cos_s, sin_s, state) -> sp.Expr:
    """Phase average of the energy, kept to degree 2 in the amplitudes and the spin rate.

    The reduced energy is quadratic plus quartic terms (``D^2 theta^2
    phi_dot^2``); the quadratic part is the leading order and the one the
    slow flow conserves.
    """
    avg = _average(system.energy.subs(fast, simultaneous=True), cos_s, sin_s)
    lam = sp.Symbol("_lambda", positive=True)
    scaled = sp.expand(avg.subs({s: lam * s for s in state}, simultaneous=True))
    quad = sp.Poly(scaled, lam).coeff_monomial(lam**2)
    return tidy(quad, list(state))
