#!/usr/bin/env bash
# The sympy peer of BENCHMARKS.md: makes a virtual environment in scripts/.venv-sympy with sympy and
# numpy from PyPI (once), then times LagrangesMethod for the N-link pendulum, N = 1..8 (or the
# sizes given as arguments). Not part of CI.
set -euo pipefail
cd "$(dirname "$0")"
if [ ! -x .venv-sympy/bin/python ]; then
  python3 -m venv .venv-sympy
  .venv-sympy/bin/pip install --quiet sympy numpy
fi
.venv-sympy/bin/python --version
.venv-sympy/bin/python -c 'import sympy; print("sympy", sympy.__version__)'
exec .venv-sympy/bin/python sympy_peer.py "$@"
