// Pinocchio peer of the floating-base robots (floating.sh): the articulated-body algorithm and the
// recursive Newton–Euler algorithm on a model with a free-flying root (JointModelFreeFlyer), at
// the states of the file floating.py writes (its format: floating.py).
//
//   pinocchio_floating values ROBOT STATES MODEL             aba and rnea against the file's
//   pinocchio_floating time ROBOT STATES MODEL               per-call times of aba and rnea
//   pinocchio_floating count ROBOT STATES MODEL LABEL CALLS  CALLS calls of one label (callgrind)
//
// MODEL is the model floating.py saved with Pinocchio's text serialization (Model::saveToText):
// the wheel's URDF parser and this translation unit must not share Eigen objects (see the comment
// at the top of pinocchio_robots.cpp). Gravity is checked to be (0, 0, −9.81), armature, damping
// and friction to be zero, joint 1 to be the free flyer and every other joint to have one
// coordinate.
//
// values: a = aba(q, v, 0) and τ = rnea(q, v, b) at every state, against the values the wheel's
// Pinocchio wrote into the file (the same algorithms, compiled otherwise), to 1e-10 relative to
// 1 + |the file's|: the model crossed over whole. Exit 2 when it fails.
//
// Timed labels (time: one call at each state of the file per batch, per-call time printed as
// robots_common.h's time lines):
//   aba    pinocchio::aba(model, data, q, v, τ = 0) (Convention::LOCAL, the default)
//   rnea   pinocchio::rnea(model, data, q, v, b)
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody.hpp>
#include <pinocchio/serialization.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "robots_common.h"

using pinocchio::Data;
using pinocchio::Model;
using Eigen::VectorXd;

// A state of the file: q, v, a = aba(q, v, 0), b and τ = rnea(q, v, b).
struct FloatingState {
  VectorXd q, v, a, b, tau;
};

static Model load_model(const char *path, const char *robot) {
  Model m;
  m.loadFromText(std::string(path));
  if (m.njoints < 2 || m.joints[1].shortname() != "JointModelFreeFlyer")
    robots_fail("joint 1 is not a free flyer in the model of", robot);
  for (int j = 2; j < m.njoints; j++)
    if (m.joints[j].nq() != 1 || m.joints[j].nv() != 1)
      robots_fail("not a one-coordinate joint:", m.names[j].c_str());
  if (!m.gravity.linear().isApprox(Eigen::Vector3d(0.0, 0.0, -9.81), 0.0) ||
      !m.gravity.angular().isZero(0.0))
    robots_fail("gravity is not (0, 0, -9.81) in the model of", robot);
  if (!m.armature.isZero(0.0) || !m.damping.isZero(0.0) || !m.friction.isZero(0.0))
    robots_fail("armature, damping or friction is not zero in the model of", robot);
  return m;
}

// The file's states; its header must name the model's joints after the free flyer, in order.
static std::vector<FloatingState> read_states(const char *path, const Model &m) {
  std::ifstream in(path);
  if (!in) robots_fail("cannot open states file", path);
  std::string line;
  std::getline(in, line);
  std::istringstream header(line);
  std::string word;
  std::getline(header, word, '\t');
  for (int j = 2; j < m.njoints; j++)
    if (!std::getline(header, word, '\t') || word != m.names[j])
      robots_fail("the states file's joints differ from the model's:", path);
  std::vector<FloatingState> states;
  const int nq = m.nq, nv = m.nv;
  while (std::getline(in, line)) {
    std::vector<double> x;
    std::istringstream row(line);
    while (std::getline(row, word, '\t')) x.push_back(std::strtod(word.c_str(), nullptr));
    if ((int)x.size() != nq + 4 * nv) robots_fail("a state row of the wrong length in", path);
    const auto part = [&](int start, int n) { return Eigen::Map<VectorXd>(&x[start], n); };
    states.push_back({part(0, nq), part(nq, nv), part(nq + nv, nv), part(nq + 2 * nv, nv),
                      part(nq + 3 * nv, nv)});
  }
  if (states.empty()) robots_fail("no state in", path);
  return states;
}

// The largest |x − expected| / (1 + |expected|).
static double worst(const VectorXd &x, const VectorXd &expected) {
  return ((x - expected).array().abs() / (1.0 + expected.array().abs())).maxCoeff();
}

static int values(const char *robot, const Model &m, const std::vector<FloatingState> &states) {
  Data data(m);
  const VectorXd zero = VectorXd::Zero(m.nv);
  double aba = 0.0, rnea = 0.0;
  for (const FloatingState &s : states) {
    aba = std::max(aba, worst(pinocchio::aba(m, data, s.q, s.v, zero), s.a));
    rnea = std::max(rnea, worst(pinocchio::rnea(m, data, s.q, s.v, s.b), s.tau));
  }
  std::printf("%s: Pinocchio %s (Eigen %d.%d.%d) against the wheel's: aba %.1e, rnea %.1e\n",
              robot, PINOCCHIO_VERSION, EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
              EIGEN_MINOR_VERSION, aba, rnea);
  return aba <= 1e-10 && rnea <= 1e-10;
}

static void time_all(const char *robot, const Model &m, const std::vector<FloatingState> &states) {
  Data data(m);
  const VectorXd zero = VectorXd::Zero(m.nv);
  const int count = (int)states.size();
  peer_timing t;
  PEER_TIME(t, for (const FloatingState &s : states) pinocchio::aba(m, data, s.q, s.v, zero));
  robots_print_time("pinocchio", robot, "aba", t, count);
  PEER_TIME(t, for (const FloatingState &s : states) pinocchio::rnea(m, data, s.q, s.v, s.b));
  robots_print_time("pinocchio", robot, "rnea", t, count);
}

static void count_calls(const Model &m, const std::vector<FloatingState> &states,
                        const std::string &label, long calls) {
  if (label != "aba" && label != "rnea") robots_fail("unknown label", label.c_str());
  Data data(m);
  const VectorXd zero = VectorXd::Zero(m.nv);
  for (long c = 0; c < calls; c++) {
    const FloatingState &s = states[c % states.size()];
    if (label == "aba")
      pinocchio::aba(m, data, s.q, s.v, zero);
    else
      pinocchio::rnea(m, data, s.q, s.v, s.b);
    __asm__ __volatile__("" ::: "memory");
  }
}

int main(int argc, char **argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (!((argc == 5 && (mode == "values" || mode == "time")) || (argc == 7 && mode == "count"))) {
    std::fprintf(stderr,
                 "usage: %s values|time ROBOT STATES MODEL\n"
                 "       %s count ROBOT STATES MODEL LABEL CALLS\n",
                 argv[0], argv[0]);
    return 1;
  }
  const char *robot = argv[2];
  const Model m = load_model(argv[4], robot);
  const std::vector<FloatingState> states = read_states(argv[3], m);
  if (mode == "values") return values(robot, m, states) ? 0 : 2;
  if (mode == "time")
    time_all(robot, m, states);
  else
    count_calls(m, states, argv[5], std::strtol(argv[6], nullptr, 10));
  return 0;
}
