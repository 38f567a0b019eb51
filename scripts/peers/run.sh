#!/usr/bin/env bash
# Peer benchmark of the N-link planar pendulum's forward dynamics (q̈ from q, q̇), N = 1..64:
# MuJoCo's C API and Pinocchio's C++ ABA, each checked against the closed form of
# benches/chain.rs, then timed. Not part of CI. Writes only under scripts/peers/ (.venv, build).
#
#   scripts/peers/run.sh            # full run (first run: venv, pip install, ≈ 2-3 min compile)
#
# Environment: MUJOCO_VERSION, PIN_VERSION, EIGEN_VERSION override the pinned PyPI versions;
# CC, CXX the compilers (env.sh).
set -euo pipefail
cd "$(dirname "$0")"

# 1. Virtual environment and compile commands (env.sh); 2. drivers, rebuilt when a source is
# newer than the binary.
. ./env.sh
if stale build/mujoco_chain mujoco_chain.c chain_common.h timing.h "$mj_lib"; then
  build_mujoco mujoco_chain.c build/mujoco_chain
fi
if stale build/pinocchio_chain pinocchio_chain.cpp chain_common.h timing.h; then
  build_pinocchio pinocchio_chain.cpp build/pinocchio_chain
fi

# 3. Check and time. A driver exits 2 when a check failed (it still times); anything else
# non-zero is an error.
run() {
  local rc=0
  "$@" >"build/$(basename "$1").tsv" || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 2 ]; then
    echo "$1 failed with exit code $rc" >&2
    exit "$rc"
  fi
}
run build/mujoco_chain
run build/pinocchio_chain
load=$(uptime)

# 4. Report.
cat build/mujoco_chain.tsv build/pinocchio_chain.tsv >build/results.tsv
echo
echo "MuJoCo $(.venv/bin/python -c 'import mujoco; print(mujoco.__version__)'), \
Pinocchio $(.venv/bin/python -c 'import pinocchio; print(pinocchio.__version__)'), \
Eigen $EIGEN_VERSION; $("$CC" --version | head -n 1); $(grep -m 1 'model name' /proc/cpuinfo | sed 's/.*: //')"
grep '^#' build/results.tsv
awk -F'\t' -v load="$load" '
  !/^#/ { key = $1 "/" $2 "/" $3; err[key] = $4; chk[key] = $5; ref[key] = $6;
          mn[key] = $7; md[key] = $8; if (!($3 in seen)) { seen[$3] = 1; ns[++k] = $3 } }
  function t(key) { return (key in mn) ? sprintf("%.0f (%.0f)", mn[key], md[key]) : "n/a" }
  function e(key) { return (key in err) ? sprintf("%.1e%s", err[key], chk[key] == "ok" ? "" : " **FAIL**") : "n/a" }
  function r(key) { return (key in ref) ? sprintf("%.1e", ref[key]) : "n/a" }
  END {
    print ""
    print "ns per call, min (median) over 21 repetitions of ≈ 10 ms; errors are max_j |θ̈ⱼ − closed formⱼ|,"
    print "check: |θ̈ⱼ − closed formⱼ| ≤ 1e-10 (1 + |closed formⱼ|) for every j (FAIL marks a miss)."
    print ""
    print "| N | MuJoCo mj_forward ns | Pinocchio ABA ns | max err MuJoCo mj_forward | max err Pinocchio ABA |"
    print "|---:|---:|---:|---:|---:|"
    for (i = 1; i <= k; i++) { n = ns[i]
      printf "| %s | %s | %s | %s | %s |\n", n, t("mujoco/mj_forward/" n), t("pinocchio/aba_local/" n),
        e("mujoco/mj_forward/" n), e("pinocchio/aba_local/" n) }
    print ""
    print "Other variants (ns per call, min (median)), and max_j |θ̈ⱼ − float128 closed form| per peer:"
    print ""
    print "| N | MuJoCo fwdPosition+Velocity+Actuation+Acceleration ns | Pinocchio ABA WORLD ns | Pinocchio computeMinverse+nonLinearEffects ns | max err Minverse+nle | float128 err: closed form (double) | MuJoCo mj_forward | Pinocchio ABA |"
    print "|---:|---:|---:|---:|---:|---:|---:|---:|"
    for (i = 1; i <= k; i++) { n = ns[i]
      printf "| %s | %s | %s | %s | %s | %s | %s | %s |\n", n, t("mujoco/fwd_pos_vel_act_acc/" n),
        t("pinocchio/aba_world/" n), t("pinocchio/minverse_nle/" n), e("pinocchio/minverse_nle/" n),
        r("closed_form/double/" n), r("mujoco/mj_forward/" n), r("pinocchio/aba_local/" n) }
    print ""
    print "uptime:" load
  }' build/results.tsv
echo
echo "Conditioning (numpy, double; the error is against numpy's solve in absolute angles):"
echo
.venv/bin/python conditioning.py
failed=$(awk -F'\t' '!/^#/ && $5 == "FAIL" { printf "%s%s %s N=%s", sep, $1, $2, $3; sep = "; " }' build/results.tsv)
echo
if [ -n "$failed" ]; then
  echo "checks missed (timed all the same): $failed"
else
  echo "all checks within 1e-10"
fi
