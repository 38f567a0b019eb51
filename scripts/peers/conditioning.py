"""Context for the peers' errors: the chain's mass matrix in absolute angles (the closed form's
coordinates) and in relative hinge angles (MuJoCo's and Pinocchio's), and what a plain double
Cholesky solve in relative coordinates loses against the closed form in absolute ones.

With θ = T φ (T lower-triangular ones), M_rel = Tᵀ M T and f_rel = Tᵀ f. Run by run.sh with the
venv's numpy.
"""

import numpy as np

M_, L_, G_ = 1.0, 0.5, 9.81

print("| N | cond(M) absolute | cond(M) relative | max err, double Cholesky in relative coordinates |")
print("|---:|---:|---:|---:|")
for n in (1, 2, 4, 8, 16, 32, 64):
    j = np.arange(n)
    th = 0.3 + 0.7 * np.sin(0.9 * j)
    w = 0.5 * np.cos(1.3 * j)
    weight = M_ * L_ * L_ * (n - np.maximum.outer(j, j))
    mass = weight * np.cos(np.subtract.outer(th, th))
    force = -M_ * G_ * L_ * (n - j) * np.sin(th) - (weight * np.sin(np.subtract.outer(th, th))) @ (w * w)
    absolute = np.linalg.solve(mass, force)
    t = np.tril(np.ones((n, n)))
    mass_rel, force_rel = t.T @ mass @ t, t.T @ force
    chol = np.linalg.cholesky(mass_rel)
    phi = np.linalg.solve(chol.T, np.linalg.solve(chol, force_rel))
    err = np.abs(t @ phi - absolute).max()
    print(f"| {n} | {np.linalg.cond(mass):.3g} | {np.linalg.cond(mass_rel):.3g} | {err:.1e} |")
