#!/usr/bin/env python3
"""A peer for BENCHMARKS.md: sympy.physics.mechanics deriving the N-link planar pendulum's
equations with LagrangesMethod (N = 1..8), and the per-call cost of its lambdified right-hand
side q̈ = M⁻¹ f. Run through scripts/sympy_peer.sh, which makes a virtual environment with sympy.

Prints one line per N: derivation time, and µs per call of the lambdified RHS (numpy solve).
"""

import sys
import time
import timeit

import numpy as np
import sympy as sp
from sympy.physics.mechanics import (
    LagrangesMethod,
    Lagrangian,
    Particle,
    Point,
    ReferenceFrame,
    dynamicsymbols,
)


def derive(n):
    """Equations of the n-link pendulum (equal masses m, lengths l, gravity g along −y)."""
    q = dynamicsymbols(f"q0:{n}")
    m, l, g = sp.symbols("m l g", positive=True)
    frame = ReferenceFrame("N")
    pivot = Point("O")
    pivot.set_vel(frame, 0)
    particles = []
    point = pivot
    potential = 0
    for i in range(n):
        nxt = point.locatenew(f"P{i}", l * sp.sin(q[i]) * frame.x - l * sp.cos(q[i]) * frame.y)
        nxt.set_vel(frame, nxt.pos_from(pivot).dt(frame))
        particle = Particle(f"b{i}", nxt, m)
        potential += m * g * nxt.pos_from(pivot).dot(frame.y)
        particle.potential_energy = m * g * nxt.pos_from(pivot).dot(frame.y)
        particles.append(particle)
        point = nxt
    lagrangian = Lagrangian(frame, *particles)
    method = LagrangesMethod(lagrangian, q)
    method.form_lagranges_equations()
    return method, q, (m, l, g)


def main():
    sizes = [int(a) for a in sys.argv[1:]] or list(range(1, 9))
    print(f"{'N':>3} {'derive [s]':>11} {'rhs [µs/call]':>14}")
    for n in sizes:
        start = time.perf_counter()
        method, q, (m, l, g) = derive(n)
        mass = method.mass_matrix
        forcing = method.forcing
        derive_s = time.perf_counter() - start
        qd = [qi.diff() for qi in q]
        args = list(q) + qd + [m, l, g]
        mass_f = sp.lambdify(args, mass, "numpy")
        forcing_f = sp.lambdify(args, forcing, "numpy")

        def rhs(values):
            return np.linalg.solve(mass_f(*values), np.asarray(forcing_f(*values), dtype=float).ravel())

        values = [0.3 + 0.7 * np.sin(0.9 * j) for j in range(n)]
        values += [0.5 * np.cos(1.3 * j) for j in range(n)]
        values += [1.0, 0.5, 9.81]
        rhs(values)
        calls, total = timeit.Timer(lambda: rhs(values)).autorange()
        print(f"{n:>3} {derive_s:>11.3f} {total / calls * 1e6:>14.1f}", flush=True)


if __name__ == "__main__":
    main()
