# knifeedge developer targets. PYTHON defaults to the active interpreter.
PYTHON ?= python
export PYTHONHASHSEED = 0

.PHONY: derive bicycle-linear check-bicycle-linear test test-all demo bench figures check-generated

## derive: regenerate generated/ from the Lagrangians (SymPy; deterministic)
derive:
	$(PYTHON) -m knifeedge.derive --out generated

## bicycle-linear: the Whipple bicycle's lean/steer coefficients from its derived Jacobian (generated/linear/;
## about a minute: not part of derive); check-bicycle-linear: fail if they differ from a fresh derivation
bicycle-linear:
	$(PYTHON) -m knifeedge.derive.bicycle_linear

check-bicycle-linear:
	$(PYTHON) -m knifeedge.derive.bicycle_linear --check

## check-generated: fail if generated/ differs from a fresh derivation (made in a temporary folder;
## generated/ is never written, so a hand edit is reported, not erased)
check-generated:
	$(PYTHON) -m knifeedge.derive --check --out generated

## test: the test suite on every core (the README's test command); test-all: then the slow checks (CI runs both)
test:
	$(PYTHON) -m pytest

test-all: test
	$(PYTHON) -m pytest -m slow

## demo: the main job
demo:
	knifeedge demo

## bench: speed and accuracy benchmarks (not part of the tests)
bench:
	$(PYTHON) -m benchmarks
	$(PYTHON) -m benchmarks.recording
	$(PYTHON) -m benchmarks.mechanics_peers
	$(PYTHON) -m benchmarks.rigid_pydy
	$(PYTHON) -m benchmarks.lyapunov_speed

## figures: every figure of the paper
figures:
	knifeedge figures --out figures
