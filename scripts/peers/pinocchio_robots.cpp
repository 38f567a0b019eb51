// Pinocchio peer on the robots of robots.py: q̈ by the articulated-body algorithm, τ by the
// recursive Newton–Euler algorithm, M by the composite-rigid-body algorithm, at the states of the
// states file (command line and output: robots_common.h; here the directory argument holds
// Pinocchio's models, <name>.txt).
//
// Model: Pinocchio's URDF parser reads robots/<name>.urdf with no root joint (a fixed base), each
// revolute joint about x, y or z becoming JointModelRX/RY/RZ; robots.sh runs the parser of the
// `pin` wheel (pinocchio.buildModelFromUrdf) and saves the model with Pinocchio's text
// serialization, which this driver loads (Model::loadFromText). The parser lives in the wheel's
// libpinocchio_parsers, compiled without -march=native: linked into this translation unit, the
// two disagree on Eigen's heap alignment (free() of a pointer the other side allocated), so the
// model crosses over as text, all 17 digits of each number kept. Gravity is checked to be
// (0, 0, −9.81); armature, damping and friction to be zero (no <dynamics> in the files). The
// timed algorithms are compiled from Pinocchio's headers in this translation unit (header-only
// templates, -O3 -march=native), not called through the wheel's prebuilt libpinocchio_default.
//
// Values: qdd = aba(q, v, τ = 0) (data.ddq), tau = rnea(q, v, q̈ of the states file), M = crba(q)
// (its upper triangle, mirrored). Self-check before printing: ‖M q̈_ABA + nle‖∞ ≤ 1e-10 · (1 +
// ‖nle‖∞) at every state (ABA against CRBA and RNEA); exit 2 when it fails.
//
// Timed labels, one call per state of the robot, per-call time printed:
//   aba    pinocchio::aba(model, data, q, v, tau = 0) (Convention::LOCAL, the default)
//   rnea   pinocchio::rnea(model, data, q, v, a)
//   crba   pinocchio::crba(model, data, q)
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/serialization.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "robots_common.h"

using pinocchio::Data;
using pinocchio::Model;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// A robot's model and its states in Pinocchio's velocity order (perm[i]: Pinocchio's index of
// the declaration's coordinate i).
struct Robot {
  const robot_states *states;
  Model model;
  std::vector<int> perm;
  std::vector<VectorXd> q, v, a;
};

static Robot load(const robot_states &s, const char *model_dir) {
  Robot r;
  r.states = &s;
  char path[4096];
  robots_path(path, sizeof path, model_dir, s.name, "txt");
  r.model.loadFromText(std::string(path));
  const Model &m = r.model;
  if (m.nq != s.n || m.nv != s.n) robots_fail("model size differs from the states file", s.name);
  if (!m.gravity.linear().isApprox(Eigen::Vector3d(0.0, 0.0, -9.81), 0.0) ||
      !m.gravity.angular().isZero(0.0))
    robots_fail("gravity is not (0, 0, -9.81)", s.name);
  if (!m.armature.isZero(0.0) || !m.damping.isZero(0.0) || !m.friction.isZero(0.0))
    robots_fail("armature, damping or friction is not zero", s.name);
  for (int i = 0; i < s.n; i++) {
    if (!m.existJointName(s.coord[i])) robots_fail("no joint named", s.coord[i]);
    const auto id = m.getJointId(s.coord[i]);
    if (m.joints[id].nv() != 1 || m.joints[id].nq() != 1)
      robots_fail("not a one-coordinate joint:", s.coord[i]);
    r.perm.push_back(m.joints[id].idx_v());
  }
  for (int k = 0; k < s.count; k++) {
    VectorXd q(s.n), v(s.n), a(s.n);
    for (int i = 0; i < s.n; i++) {
      q[r.perm[i]] = s.q[k][i];
      v[r.perm[i]] = s.v[k][i];
      a[r.perm[i]] = s.a[k][i];
    }
    r.q.push_back(q);
    r.v.push_back(v);
    r.a.push_back(a);
  }
  return r;
}

// Prints x (Pinocchio's order) in the declaration's order.
static void print_vector(const Robot &r, const char *quantity, int k, const VectorXd &x) {
  double out[ROBOTS_MAX_DOF];
  for (int i = 0; i < r.states->n; i++) out[i] = x[r.perm[i]];
  robots_print_values("pinocchio", r.states->name, quantity, k, r.states->n, out);
}

static void print_matrix(const Robot &r, int k, const MatrixXd &mat) {
  const int n = r.states->n;
  std::vector<double> out(n * n);
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) out[i * n + j] = mat(r.perm[i], r.perm[j]);
  robots_print_values("pinocchio", r.states->name, "M", k, n * n, out.data());
}

// Prints every quantity at every state; returns 0 when the self-check failed.
static int values(const Robot &r) {
  Data data(r.model);
  const VectorXd zero = VectorXd::Zero(r.model.nv);
  int ok = 1;
  for (int k = 0; k < r.states->count; k++) {
    const VectorXd qdd = pinocchio::aba(r.model, data, r.q[k], r.v[k], zero);
    print_vector(r, "qdd", k, qdd);
    print_vector(r, "tau", k, pinocchio::rnea(r.model, data, r.q[k], r.v[k], r.a[k]));
    pinocchio::crba(r.model, data, r.q[k]);
    MatrixXd mass = data.M;
    mass.triangularView<Eigen::StrictlyLower>() = mass.transpose();
    print_matrix(r, k, mass);
    const VectorXd nle = pinocchio::nonLinearEffects(r.model, data, r.q[k], r.v[k]);
    const double residual = (mass * qdd + nle).lpNorm<Eigen::Infinity>();
    if (!(residual <= 1e-10 * (1.0 + nle.lpNorm<Eigen::Infinity>()))) {
      std::fprintf(stderr, "%s state %d: |M q̈_ABA + nle| = %.3e\n", r.states->name, k, residual);
      ok = 0;
    }
  }
  return ok;
}

// One call of `label` at state k.
static void call(const Robot &r, Data &data, const VectorXd &zero, const std::string &label,
                 int k) {
  if (label == "aba")
    pinocchio::aba(r.model, data, r.q[k], r.v[k], zero);
  else if (label == "rnea")
    pinocchio::rnea(r.model, data, r.q[k], r.v[k], r.a[k]);
  else
    pinocchio::crba(r.model, data, r.q[k]);
}

static void time_all(const Robot &r) {
  Data data(r.model);
  const VectorXd zero = VectorXd::Zero(r.model.nv);
  const int count = r.states->count;
  peer_timing t;
  PEER_TIME(t, for (int k = 0; k < count; k++)
                   pinocchio::aba(r.model, data, r.q[k], r.v[k], zero));
  robots_print_time("pinocchio", r.states->name, "aba", t, count);
  PEER_TIME(t, for (int k = 0; k < count; k++)
                   pinocchio::rnea(r.model, data, r.q[k], r.v[k], r.a[k]));
  robots_print_time("pinocchio", r.states->name, "rnea", t, count);
  PEER_TIME(t, for (int k = 0; k < count; k++) pinocchio::crba(r.model, data, r.q[k]));
  robots_print_time("pinocchio", r.states->name, "crba", t, count);
}

int main(int argc, char **argv) {
  const robots_args args = robots_parse_args(argc, argv);
  static robot_states states[ROBOTS_MAX];
  const int count = robots_read(args.states, states);
  int ok = 1;
  if (!std::strcmp(args.mode, "values"))
    std::printf("# pinocchio %s, Eigen %d.%d.%d\n", PINOCCHIO_VERSION, EIGEN_WORLD_VERSION,
                EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  for (int i = 0; i < count; i++) {
    if (!std::strcmp(args.mode, "count")) {
      if (std::strcmp(states[i].name, args.robot)) continue;
      const std::string label = args.label;
      if (label != "aba" && label != "rnea" && label != "crba")
        robots_fail("unknown label", args.label);
      const Robot r = load(states[i], args.model_dir);
      Data data(r.model);
      const VectorXd zero = VectorXd::Zero(r.model.nv);
      for (long c = 0; c < args.calls; c++) {
        call(r, data, zero, label, (int)(c % states[i].count));
        __asm__ __volatile__("" ::: "memory");
      }
      return 0;
    }
    const Robot r = load(states[i], args.model_dir);
    if (!std::strcmp(args.mode, "values"))
      ok &= values(r);
    else
      time_all(r);
  }
  if (!std::strcmp(args.mode, "count")) robots_fail("no robot named", args.robot);
  return ok ? 0 : 2;
}
