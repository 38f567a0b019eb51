/* MuJoCo peer on the robots of robots.py: q̈ from mj_forward at the states of the states file
 * (command line and output: robots_common.h).
 *
 * Model: mj_loadXML on robots/<name>.urdf, MuJoCo's own URDF import. What the import could lose
 * or add is checked on the compiled model before anything is printed: one hinge per declared
 * joint (found by name, nq = nv = joints), no geoms (so no contacts; contacts are also disabled),
 * no equality, tendon or actuator, zero armature, damping, friction loss and stiffness, gravity
 * (0, 0, −9.81), and every body's mass and full inertia as in the file (MuJoCo diagonalises the
 * tensor into body_inertia and body_iquat; the driver turns it back and prints the largest
 * difference from the URDF's numbers as a comment line, which robots.sh shows). Joint ranges stay
 * as in the file (±3.1416) and are never reached at |q| ≤ 1; mj_forward is checked to give no
 * constraint rows (nefc = 0), so qacc is the unconstrained q̈.
 *
 * Values: qdd = d->qacc after mj_forward; M = mj_fullM (MuJoCo's composite-rigid-body matrix).
 *
 * Timed label, one call per state of the robot (q, q̇ copied into mjData first), per-call time:
 *   mj_forward   the whole forward pipeline, q̈ in d->qacc.
 */
#include <math.h>
#include <mujoco/mujoco.h>

#include "robots_common.h"

typedef struct {
  const robot_states *states;
  mjModel *m;
  mjData *d;
  int qadr[ROBOTS_MAX_DOF], dadr[ROBOTS_MAX_DOF]; /* MuJoCo's qpos, dof index of coordinate i */
} robot;

/* Largest |I_mujoco − I_urdf| over the bodies, I_mujoco = R diag(body_inertia) Rᵀ with R from
 * body_iquat; the URDF's tensors are read back from its <inertia> elements by name order, which
 * MuJoCo keeps (bodies in file order). Returns the largest difference of masses in *dmass. */
static double inertia_difference(const robot *r, const char *path, double *dmass) {
  FILE *f = fopen(path, "r");
  if (!f) robots_fail("cannot open", path);
  static char line[ROBOTS_LINE];
  double worst = 0.0;
  *dmass = 0.0;
  int body = 0;
  while (fgets(line, sizeof line, f)) {
    double mass, ixx, ixy, ixz, iyy, iyz, izz;
    const char *p;
    if ((p = strstr(line, "<link name=\""))) {
      char name[ROBOTS_NAME];
      if (sscanf(p, "<link name=\"%63[^\"]\"", name) == 1)
        body = mj_name2id(r->m, mjOBJ_BODY, name);
    } else if ((p = strstr(line, "<mass value=\"")) && sscanf(p, "<mass value=\"%lf\"", &mass) == 1) {
      if (body < 1) robots_fail("mass of an unknown or fused body in", path);
      *dmass = fmax(*dmass, fabs(r->m->body_mass[body] - mass));
    } else if ((p = strstr(line, "<inertia ")) &&
               sscanf(p,
                      "<inertia ixx=\"%lf\" ixy=\"%lf\" ixz=\"%lf\" iyy=\"%lf\" iyz=\"%lf\" "
                      "izz=\"%lf\"",
                      &ixx, &ixy, &ixz, &iyy, &iyz, &izz) == 6) {
      double rot[9], urdf[9] = {ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz};
      mju_quat2Mat(rot, r->m->body_iquat + 4 * body);
      const double *moments = r->m->body_inertia + 3 * body;
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
          double x = 0.0;
          for (int k = 0; k < 3; k++) x += rot[3 * i + k] * moments[k] * rot[3 * j + k];
          worst = fmax(worst, fabs(x - urdf[3 * i + j]));
        }
    }
  }
  fclose(f);
  return worst;
}

static void check_model(const robot *r, const char *path) {
  const mjModel *m = r->m;
  const char *name = r->states->name;
  if (m->nq != r->states->n || m->nv != r->states->n || m->njnt != r->states->n)
    robots_fail("joint count differs from the states file", name);
  if (m->ngeom || m->neq || m->ntendon || m->nu)
    robots_fail("geoms, equalities, tendons or actuators in", name);
  for (int i = 0; i < m->nv; i++)
    if (m->dof_armature[i] != 0.0 || m->dof_damping[i] != 0.0 || m->dof_frictionloss[i] != 0.0 ||
        m->jnt_stiffness[i] != 0.0 || m->jnt_type[i] != mjJNT_HINGE)
      robots_fail("a joint with armature, damping, friction, stiffness or not a hinge in", name);
  if (m->opt.gravity[0] != 0.0 || m->opt.gravity[1] != 0.0 || m->opt.gravity[2] != -9.81)
    robots_fail("gravity is not (0, 0, -9.81) in", name);
  double dmass;
  double dinertia = inertia_difference(r, path, &dmass);
  printf("# mujoco %s: %d bodies (world included), max |mass - URDF| = %.1e, "
         "max |inertia - URDF| = %.1e\n",
         name, (int)m->nbody, dmass, dinertia);
  if (!(dmass <= 1e-12 && dinertia <= 1e-12)) robots_fail("masses or inertias changed in", name);
}

static robot load(const robot_states *s, const char *model_dir) {
  robot r = {.states = s};
  char path[4096], error[1000] = "";
  robots_path(path, sizeof path, model_dir, s->name, "urdf");
  r.m = mj_loadXML(path, NULL, error, sizeof error);
  if (!r.m) robots_fail(path, error);
  r.m->opt.disableflags |= mjDSBL_CONTACT;
  for (int i = 0; i < s->n; i++) {
    int id = mj_name2id(r.m, mjOBJ_JOINT, s->coord[i]);
    if (id < 0) robots_fail("no joint named", s->coord[i]);
    r.qadr[i] = r.m->jnt_qposadr[id];
    r.dadr[i] = r.m->jnt_dofadr[id];
  }
  check_model(&r, path);
  r.d = mj_makeData(r.m);
  return r;
}

static void set_state(const robot *r, int k) {
  for (int i = 0; i < r->states->n; i++) {
    r->d->qpos[r->qadr[i]] = r->states->q[k][i];
    r->d->qvel[r->dadr[i]] = r->states->v[k][i];
  }
}

static void values(const robot *r) {
  const int n = r->states->n;
  static double full[ROBOTS_MAX_DOF * ROBOTS_MAX_DOF], out[ROBOTS_MAX_DOF * ROBOTS_MAX_DOF];
  for (int k = 0; k < r->states->count; k++) {
    set_state(r, k);
    mj_forward(r->m, r->d);
    if (r->d->nefc != 0) robots_fail("constraint rows at a state of", r->states->name);
    for (int i = 0; i < n; i++) out[i] = r->d->qacc[r->dadr[i]];
    robots_print_values("mujoco", r->states->name, "qdd", k, n, out);
    mj_fullM(r->m, r->d, full);
    for (int i = 0; i < n; i++)
      for (int j = 0; j < n; j++) out[i * n + j] = full[r->dadr[i] * n + r->dadr[j]];
    robots_print_values("mujoco", r->states->name, "M", k, n * n, out);
  }
}

int main(int argc, char **argv) {
  robots_args args = robots_parse_args(argc, argv);
  static robot_states states[ROBOTS_MAX];
  int count = robots_read(args.states, states);
  int values_mode = !strcmp(args.mode, "values"), count_mode = !strcmp(args.mode, "count");
  if (values_mode)
    printf("# mujoco %s (mj_version %d), header mjVERSION_HEADER %d\n", mj_versionString(),
           mj_version(), mjVERSION_HEADER);
  for (int i = 0; i < count; i++) {
    if (count_mode && strcmp(states[i].name, args.robot)) continue;
    robot r = load(&states[i], args.model_dir);
    int n_states = states[i].count;
    if (values_mode) {
      values(&r);
    } else if (count_mode) {
      if (strcmp(args.label, "mj_forward")) robots_fail("unknown label", args.label);
      for (long c = 0; c < args.calls; c++) {
        set_state(&r, (int)(c % n_states));
        mj_forward(r.m, r.d);
        __asm__ __volatile__("" ::: "memory");
      }
      return 0;
    } else {
      peer_timing t;
      PEER_TIME(t, for (int k = 0; k < n_states; k++) {
        set_state(&r, k);
        mj_forward(r.m, r.d);
      });
      robots_print_time("mujoco", states[i].name, "mj_forward", t, n_states);
    }
    mj_deleteData(r.d);
    mj_deleteModel(r.m);
  }
  if (count_mode) robots_fail("no robot named", args.robot);
  return 0;
}
