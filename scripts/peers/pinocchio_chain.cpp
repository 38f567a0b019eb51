// Pinocchio peer: the N-link planar pendulum's q̈ from (q, q̇) with Pinocchio's articulated-body
// algorithm, checked against the closed form of benches/chain.rs, then timed.
//
// Model: N revolute joints about z (JointModelRZ), gravity (0, −9.81, 0); joint 0 at the
// origin, joint j+1 placed at (0, −l, 0) in joint j's frame (at bob j); each joint carries
// Inertia(m, (0, −l, 0), 0): a point mass with zero rotational inertia. No joint friction,
// damping or armature enters aba (tau = 0).
//
// The algorithms are compiled from Pinocchio's headers in this translation unit (header-only
// templates, -O3 -march=native), not called through the wheel's prebuilt libpinocchio_default.
//
// Timed, per N:
//   aba_local         pinocchio::aba(model, data, q, v, tau = 0) with the default
//                     Convention::LOCAL; q̈ read from data.ddq.
//   aba_world         the same with Convention::WORLD.
//   minverse_nle      computeMinverse(model, data, q), nonLinearEffects(model, data, q, v),
//                     q̈ = −Minv · nle (Minv's upper triangle, as computeMinverse fills it).
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/spatial.hpp>

#include <string>

#include "chain_common.h"

using pinocchio::Convention;
using pinocchio::Data;
using pinocchio::Inertia;
using pinocchio::JointIndex;
using pinocchio::Model;
using pinocchio::SE3;

static Model make_chain(int n) {
  Model model;
  model.gravity.linear(Eigen::Vector3d(0.0, -CHAIN_G, 0.0));
  JointIndex parent = 0;
  for (int j = 0; j < n; j++) {
    SE3 placement(Eigen::Matrix3d::Identity(),
                  Eigen::Vector3d(0.0, j == 0 ? 0.0 : -CHAIN_L, 0.0));
    JointIndex id = model.addJoint(parent, pinocchio::JointModelRZ(), placement,
                                   "j" + std::to_string(j));
    model.appendBodyToJoint(
        id, Inertia(CHAIN_M, Eigen::Vector3d(0.0, -CHAIN_L, 0.0), Eigen::Matrix3d::Zero()));
    parent = id;
  }
  return model;
}

// q̈ in relative coordinates → absolute, then the largest difference from expect and from ref.
static double compare(int n, const Eigen::VectorXd &rel, const double *expect, int *ok,
                      const double *ref, double *err_ref) {
  double abs_[CHAIN_MAX_N];
  chain_to_absolute(n, rel.data(), abs_);
  int ok_ref;
  *err_ref = chain_max_abs_diff(n, abs_, ref, &ok_ref);
  return chain_max_abs_diff(n, abs_, expect, ok);
}

static void minverse_nle(const Model &model, Data &data, const Eigen::VectorXd &q,
                         const Eigen::VectorXd &v, Eigen::VectorXd &out) {
  pinocchio::computeMinverse(model, data, q);
  pinocchio::nonLinearEffects(model, data, q, v);
  out.noalias() = -(data.Minv.selfadjointView<Eigen::Upper>() * data.nle);
}

int main() {
  std::printf("# pinocchio %s, Eigen %d.%d.%d\n", PINOCCHIO_VERSION, EIGEN_WORLD_VERSION,
              EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION);
  int all_ok = 1;
  for (int s = 0; s < CHAIN_NSIZES; s++) {
    const int n = chain_sizes[s];
    double th[CHAIN_MAX_N], thd[CHAIN_MAX_N], expect[CHAIN_MAX_N], ref[CHAIN_MAX_N];
    chain_state(n, th, thd);
    chain_closed_form(n, th, thd, expect);
    chain_reference(n, th, thd, ref);

    const Model model = make_chain(n);
    if (model.nq != n || model.nv != n) {
      std::fprintf(stderr, "N=%d: model has nq=%d nv=%d\n", n, (int)model.nq, (int)model.nv);
      return 1;
    }
    Data data(model);
    Eigen::VectorXd q(n), v(n), tau = Eigen::VectorXd::Zero(n), out(n);
    chain_to_relative(n, th, q.data());
    chain_to_relative(n, thd, v.data());

    int ok_local, ok_world, ok_minv;
    double ref_local, ref_world, ref_minv;
    pinocchio::aba(model, data, q, v, tau, Convention::LOCAL);
    double err_local = compare(n, data.ddq, expect, &ok_local, ref, &ref_local);
    pinocchio::aba(model, data, q, v, tau, Convention::WORLD);
    double err_world = compare(n, data.ddq, expect, &ok_world, ref, &ref_world);
    minverse_nle(model, data, q, v, out);
    double err_minv = compare(n, out, expect, &ok_minv, ref, &ref_minv);
    all_ok &= ok_local & ok_world & ok_minv;

    peer_timing t;
    PEER_TIME(t, pinocchio::aba(model, data, q, v, tau, Convention::LOCAL));
    chain_report("pinocchio", "aba_local", n, err_local, ok_local, ref_local, t);
    PEER_TIME(t, pinocchio::aba(model, data, q, v, tau, Convention::WORLD));
    chain_report("pinocchio", "aba_world", n, err_world, ok_world, ref_world, t);
    PEER_TIME(t, minverse_nle(model, data, q, v, out));
    chain_report("pinocchio", "minverse_nle", n, err_minv, ok_minv, ref_minv, t);
  }
  return all_ok ? 0 : 2;
}
