/* Shared by mujoco_chain.c and pinocchio_chain.cpp: the N-link planar pendulum of
 * benches/chain.rs (its state, its hand-written closed form, the conversion between absolute and
 * relative joint angles); the timing loop is in timing.h.
 *
 * Chain: N point masses m = 1 on massless rods of length l = 0.5; absolute angles θⱼ from the
 * downward vertical; bob k at Σ_{j≤k} l (sin θⱼ, −cos θⱼ); gravity g = 9.81 along −y.
 * MuJoCo and Pinocchio use relative hinge angles φ₀ = θ₀, φⱼ = θⱼ − θⱼ₋₁ (same for rates), so
 * θ̈ⱼ = Σ_{i≤j} φ̈ᵢ.
 */
#ifndef LAGRANGE_PEERS_CHAIN_COMMON_H
#define LAGRANGE_PEERS_CHAIN_COMMON_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "timing.h"

#include <quadmath.h>

#define CHAIN_M 1.0
#define CHAIN_L 0.5
#define CHAIN_G 9.81
#define CHAIN_MAX_N 64

static const int chain_sizes[] = {1, 2, 4, 8, 16, 32, 64};
#define CHAIN_NSIZES ((int)(sizeof chain_sizes / sizeof chain_sizes[0]))

/* The state of benches/chain.rs: θⱼ = 0.3 + 0.7 sin(0.9 j), θ̇ⱼ = 0.5 cos(1.3 j). */
static void chain_state(int n, double *theta, double *theta_dot) {
  for (int j = 0; j < n; j++) {
    theta[j] = 0.3 + 0.7 * sin(0.9 * j);
    theta_dot[j] = 0.5 * cos(1.3 * j);
  }
}

/* Absolute → relative: φ₀ = θ₀, φⱼ = θⱼ − θⱼ₋₁. */
static void chain_to_relative(int n, const double *abs_, double *rel) {
  for (int j = 0; j < n; j++) rel[j] = j == 0 ? abs_[0] : abs_[j] - abs_[j - 1];
}

/* Relative → absolute: θⱼ = Σ_{i≤j} φᵢ. */
static void chain_to_absolute(int n, const double *rel, double *abs_) {
  double sum = 0.0;
  for (int j = 0; j < n; j++) {
    sum += rel[j];
    abs_[j] = sum;
  }
}

/* The closed form of benches/chain.rs: M_jk = m l² (N − max(j,k)) cos(θⱼ − θₖ),
 * force_j = −m g l (N − j) sin θⱼ − Σₖ m l² (N − max(j,k)) sin(θⱼ − θₖ) θ̇ₖ²,
 * q̈ = M⁻¹ force by LDLᵀ (no pivoting; M is symmetric positive definite). Written once for a
 * scalar type T: chain_closed_form in double (the compared closed form) and
 * chain_reference in __float128 (a reference for the rounding error of both sides). */
#define CHAIN_DEFINE_CLOSED_FORM(NAME, T, SIN, COS)                                      \
  static void NAME(int n, const double *q, const double *v, double *qdd) {               \
    static T mass[CHAIN_MAX_N][CHAIN_MAX_N], d[CHAIN_MAX_N];                            \
    T s[CHAIN_MAX_N], c[CHAIN_MAX_N], f[CHAIN_MAX_N], x[CHAIN_MAX_N];                   \
    const T m = CHAIN_M, l = CHAIN_L, g = CHAIN_G;                                      \
    for (int j = 0; j < n; j++) {                                                       \
      s[j] = SIN((T)q[j]);                                                              \
      c[j] = COS((T)q[j]);                                                              \
    }                                                                                   \
    for (int j = 0; j < n; j++) {                                                       \
      f[j] = -m * g * l * (T)(n - j) * s[j];                                            \
      for (int k = 0; k < n; k++) {                                                     \
        T w = m * l * l * (T)(n - (j > k ? j : k));                                     \
        mass[j][k] = w * (c[j] * c[k] + s[j] * s[k]);                                   \
        f[j] -= w * (s[j] * c[k] - c[j] * s[k]) * (T)v[k] * (T)v[k];                    \
      }                                                                                 \
    }                                                                                   \
    /* LDLᵀ: the strict lower triangle of `mass` becomes L, d the diagonal. */          \
    for (int j = 0; j < n; j++) {                                                       \
      T dj = mass[j][j];                                                                \
      for (int k = 0; k < j; k++) dj -= mass[j][k] * mass[j][k] * d[k];                 \
      d[j] = dj;                                                                        \
      for (int i = j + 1; i < n; i++) {                                                 \
        T y = mass[i][j];                                                               \
        for (int k = 0; k < j; k++) y -= mass[i][k] * mass[j][k] * d[k];                \
        mass[i][j] = y / dj;                                                            \
      }                                                                                 \
    }                                                                                   \
    for (int i = 0; i < n; i++) {                                                       \
      T y = f[i];                                                                       \
      for (int k = 0; k < i; k++) y -= mass[i][k] * x[k];                               \
      x[i] = y;                                                                         \
    }                                                                                   \
    for (int i = 0; i < n; i++) x[i] /= d[i];                                           \
    for (int i = n - 1; i >= 0; i--) {                                                  \
      T y = x[i];                                                                       \
      for (int k = i + 1; k < n; k++) y -= mass[k][i] * x[k];                           \
      x[i] = y;                                                                         \
    }                                                                                   \
    for (int i = 0; i < n; i++) qdd[i] = (double)x[i];                                  \
  }

CHAIN_DEFINE_CLOSED_FORM(chain_closed_form, double, sin, cos)
CHAIN_DEFINE_CLOSED_FORM(chain_reference, __float128, sinq, cosq)

/* Largest |a − b| over j, and the check of benches/chain.rs with a 1e-10 tolerance:
 * |a − b| ≤ 1e-10 (1 + |b|) for every j. */
static double chain_max_abs_diff(int n, const double *a, const double *b, int *ok) {
  double worst = 0.0;
  *ok = 1;
  for (int j = 0; j < n; j++) {
    double e = fabs(a[j] - b[j]);
    if (!(e <= 1e-10 * (1.0 + fabs(b[j])))) *ok = 0;
    if (!(e <= worst)) worst = e; /* also catches NaN */
  }
  return worst;
}

/* One result line, tab-separated, read by run.sh:
 * peer  variant  N  max|q̈ − closed form|  check  max|q̈ − float128 reference|  min_ns  median_ns
 * calls_per_rep. check is "ok" when |q̈ⱼ − closed formⱼ| ≤ 1e-10 (1 + |closed formⱼ|) for all j. */
static void chain_report(const char *peer, const char *variant, int n, double err, int ok,
                         double err_ref, peer_timing t) {
  printf("%s\t%s\t%d\t%.3e\t%s\t%.3e\t%.1f\t%.1f\t%ld\n", peer, variant, n, err,
         ok ? "ok" : "FAIL", err_ref, t.min_ns, t.median_ns, t.iters);
  fflush(stdout);
}

#endif
