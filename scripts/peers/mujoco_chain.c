/* MuJoCo peer: the N-link planar pendulum's q̈ from (q, q̇) through MuJoCo's C API, checked
 * against the closed form of benches/chain.rs, then timed.
 *
 * Model: hinge joints about z, gravity (0, −9.81, 0); body j has its hinge at its origin (the
 * previous bob) and a point mass 1 at (0, −l, 0) in its frame. Contacts are disabled
 * (<flag contact="disable"/>); there are no geoms, limits, equalities, tendons, actuators,
 * springs, damping, friction loss or armature, so no constraint rows (checked: nefc == 0) and
 * qacc = qacc_smooth.
 *
 * Point masses: MuJoCo's compiler rejects a moving body whose principal inertias are below
 * mjMINVAL (1e-15), so bodies are compiled with diaginertia 1e-14 and m->body_inertia is then set
 * to 0 in the compiled mjModel (the compile-time check does not run again; the runtime uses
 * body_inertia only to form the composite inertias). Both errors are printed.
 *
 * Timed, per N:
 *   mj_forward            the full forward pipeline; q̈ read from d->qacc.
 *   fwd_pos_vel_act_acc   mj_fwdPosition + mj_fwdVelocity + mj_fwdActuation + mj_fwdAcceleration
 *                         (mj_forward without sensors, energy and mj_fwdConstraint);
 *                         q̈ read from d->qacc_smooth.
 */
#include <mujoco/mujoco.h>

#include "chain_common.h"

static mjModel *load_chain(int n) {
  /* Each body adds < 200 characters. */
  size_t cap = 1024 + (size_t)n * 256;
  char *xml = (char *)malloc(cap);
  size_t len = 0;
  len += (size_t)snprintf(xml + len, cap - len,
                          "<mujoco model=\"chain%d\">\n"
                          "  <option gravity=\"0 %.17g 0\">\n"
                          "    <flag contact=\"disable\"/>\n"
                          "  </option>\n"
                          "  <worldbody>\n",
                          n, -CHAIN_G);
  for (int j = 0; j < n; j++) {
    len += (size_t)snprintf(xml + len, cap - len,
                            "<body name=\"b%d\" pos=\"0 %.17g 0\">"
                            "<joint name=\"j%d\" type=\"hinge\" axis=\"0 0 1\"/>"
                            "<inertial pos=\"0 %.17g 0\" mass=\"%.17g\" diaginertia=\"1e-14 1e-14 1e-14\"/>\n",
                            j, j == 0 ? 0.0 : -CHAIN_L, j, -CHAIN_L, CHAIN_M);
  }
  for (int j = 0; j < n; j++) len += (size_t)snprintf(xml + len, cap - len, "</body>");
  len += (size_t)snprintf(xml + len, cap - len, "\n  </worldbody>\n</mujoco>\n");

  char error[1000] = "";
  mjSpec *spec = mj_parseXMLString(xml, NULL, error, sizeof error);
  free(xml);
  if (!spec) {
    fprintf(stderr, "mj_parseXMLString (N=%d): %s\n", n, error);
    exit(1);
  }
  mjModel *m = mj_compile(spec, NULL);
  if (!m) {
    fprintf(stderr, "mj_compile (N=%d): %s\n", n, mjs_getError(spec));
    exit(1);
  }
  mj_deleteSpec(spec);
  if (m->nv != n || m->nq != n) {
    fprintf(stderr, "N=%d: model has nq=%ld nv=%ld\n", n, (long)m->nq, (long)m->nv);
    exit(1);
  }
  return m;
}

/* Runs mj_forward (full) or the four stages, converts q̈ to absolute angles, compares. */
static double check(const mjModel *m, mjData *d, int n, const double *expect, int full, int *ok,
                    const double *ref, double *err_ref) {
  double rel[CHAIN_MAX_N], abs_[CHAIN_MAX_N];
  if (full) {
    mj_forward(m, d);
    if (d->nefc != 0) {
      fprintf(stderr, "N=%d: nefc = %d, expected no constraint rows\n", n, d->nefc);
      exit(1);
    }
    for (int j = 0; j < n; j++) rel[j] = d->qacc[j];
  } else {
    mj_fwdPosition(m, d);
    mj_fwdVelocity(m, d);
    mj_fwdActuation(m, d);
    mj_fwdAcceleration(m, d);
    for (int j = 0; j < n; j++) rel[j] = d->qacc_smooth[j];
  }
  chain_to_absolute(n, rel, abs_);
  int ok_ref;
  *err_ref = chain_max_abs_diff(n, abs_, ref, &ok_ref);
  return chain_max_abs_diff(n, abs_, expect, ok);
}

int main(void) {
  printf("# mujoco %s (mj_version %d), header mjVERSION_HEADER %d\n", mj_versionString(),
         mj_version(), mjVERSION_HEADER);
  int all_ok = 1;
  for (int s = 0; s < CHAIN_NSIZES; s++) {
    int n = chain_sizes[s];
    double q[CHAIN_MAX_N], v[CHAIN_MAX_N], expect[CHAIN_MAX_N], ref[CHAIN_MAX_N];
    chain_state(n, q, v);
    chain_closed_form(n, q, v, expect);
    chain_reference(n, q, v, ref);
    int ok_cf;
    double err_cf = chain_max_abs_diff(n, expect, ref, &ok_cf);
    peer_timing none = {0.0, 0.0, 0};
    chain_report("closed_form", "double", n, 0.0, 1, err_cf, none);

    mjModel *m = load_chain(n);
    mjData *d = mj_makeData(m);
    chain_to_relative(n, q, d->qpos);
    chain_to_relative(n, v, d->qvel);

    int ok_tiny;
    double ref_tiny, ref_fwd, ref_part;
    double err_tiny = check(m, d, n, expect, 1, &ok_tiny, ref, &ref_tiny);
    for (int b = 1; b < m->nbody; b++)
      for (int i = 0; i < 3; i++) m->body_inertia[3 * b + i] = 0.0;
    int ok_fwd, ok_part;
    double err_fwd = check(m, d, n, expect, 1, &ok_fwd, ref, &ref_fwd);
    double err_part = check(m, d, n, expect, 0, &ok_part, ref, &ref_part);
    printf("# mujoco N=%d: max|q̈ − closed form| (− float128 reference) with diaginertia 1e-14: "
           "%.3e (%.3e); with body_inertia set to 0: %.3e (%.3e)\n",
           n, err_tiny, ref_tiny, err_fwd, ref_fwd);
    all_ok &= ok_fwd & ok_part;

    peer_timing t;
    PEER_TIME(t, mj_forward(m, d));
    chain_report("mujoco", "mj_forward", n, err_fwd, ok_fwd, ref_fwd, t);
    PEER_TIME(t, (mj_fwdPosition(m, d), mj_fwdVelocity(m, d), mj_fwdActuation(m, d),
                   mj_fwdAcceleration(m, d)));
    chain_report("mujoco", "fwd_pos_vel_act_acc", n, err_part, ok_part, ref_part, t);

    mj_deleteData(d);
    mj_deleteModel(m);
  }
  return all_ok ? 0 : 2;
}
