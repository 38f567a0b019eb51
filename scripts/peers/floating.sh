#!/usr/bin/env bash
# Floating-base robots against Pinocchio's free flyer: the tests' quadruped
# (tests/urdf/quadruped.urdf) and, when `ROBOTS=example-robot-data scripts/peers/robots.sh check`
# has prepared its file, Solo12, each read with a free-flying root by
# `#[lagrange::urdf(.., floating)]` and by Pinocchio (`JointModelFreeFlyer`). lagrange's
# `accelerations` and `inverse_dynamics` (`floating-check`) against Pinocchio's ABA and RNEA
# (pinocchio_floating.cpp) at the random states of floating.py, checked to 1e-10 before anything
# is timed. Not part of CI. Writes only under scripts/peers/ (.venv, build) and cargo's target
# directory.
#
#   scripts/peers/floating.sh              # build and check only
#   scripts/peers/floating.sh check        # the same
#   scripts/peers/floating.sh callgrind    # check, then instructions per call (valgrind), CALLS (200)
#   scripts/peers/floating.sh time         # check, then ROUNDS (5) interleaved rounds of timing
#
# Environment: ROUNDS, CALLS; the versions and compilers of env.sh.
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-check}
case "$mode" in check | callgrind | time) ;; *)
  sed -n '2,16p' "$0" >&2
  exit 1
  ;;
esac
root=$(cd ../.. && pwd)
out=build/floating
mkdir -p "$out"

# 1. Virtual environment and compile commands (env.sh); Pinocchio's driver, rebuilt when a
# source is newer than the binary; lagrange's side, with Solo12 when its file is there.
# shellcheck source-path=SCRIPTDIR # env.sh
. ./env.sh
if stale build/pinocchio_floating pinocchio_floating.cpp robots_common.h timing.h; then
  build_pinocchio pinocchio_floating.cpp build/pinocchio_floating \
    -L"$prefix/lib" -lboost_serialization -Wl,-rpath,"$prefix/lib"
fi
features=
robots="quadruped:$root/tests/urdf/quadruped.urdf"
solo="$root/lagrange-bench/robots/example-robot-data/solo12.urdf"
if [ -e "$solo" ]; then
  features="--features example-robot-data"
  robots="$robots solo12:$solo"
else
  echo "no $solo: Solo12 skipped (ROBOTS=example-robot-data scripts/peers/robots.sh check prepares it)" >&2
fi
# shellcheck disable=SC2086 # $features is empty or two words
cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p lagrange-bench --bin floating-check $features
lagrange="$root/target/release/floating-check"
names=
for entry in $robots; do
  names="$names ${entry%%:*}"
done

# 2. The states and Pinocchio's values (the wheel's parser and algorithms), its model saved as
# text; the check, before any timing: the driver's ABA and RNEA against the wheel's (the model
# crossed over whole), then lagrange's q̈ and τ against them. A side exits 2 when it fails.
for entry in $robots; do
  name=${entry%%:*}
  .venv/bin/python floating.py "${entry#*:}" "$out/$name.tsv" "$out/$name.txt"
  build/pinocchio_floating values "$name" "$out/$name.tsv" "$out/$name.txt"
  "$lagrange" check --robot "$name" --states "$out/$name.tsv"
done
[ "$mode" = check ] && exit 0

# side SIDE MODE ROBOT [ARGS...]: one side's driver on one robot.
side() {
  case "$1" in
  lagrange) "$lagrange" "$2" --robot "$3" --states "$out/$3.tsv" "${@:4}" ;;
  pinocchio) build/pinocchio_floating "$2" "$3" "$out/$3.tsv" "$out/$3.txt" "${@:4}" ;;
  esac
}

# 3a. Instructions per call under callgrind: the difference between 3·CALLS and CALLS calls,
# divided by 2·CALLS (start-up cancels).
if [ "$mode" = callgrind ]; then
  calls=${CALLS:-200}
  # count_calls SIDE ROBOT LABEL N: the instructions of N calls (env.sh's counts_line).
  # shellcheck disable=SC2317 # called through counts_line
  count_calls() {
    if [ "$1" = lagrange ]; then
      instructions "$lagrange" count --robot "$2" --states "$out/$2.tsv" --label "$3" --calls "$4"
    else
      instructions build/pinocchio_floating count "$2" "$out/$2.tsv" "$out/$2.txt" "$3" "$4"
    fi
  }
  : >"$out/counts.tsv"
  for name in $names; do
    for pair in lagrange:accelerations pinocchio:aba lagrange:inverse_dynamics pinocchio:rnea; do
      counts_line "${pair%%:*}" "$name" "${pair#*:}" "$calls" >>"$out/counts.tsv"
    done
  done
  .venv/bin/python robots_report.py counts "$out/counts.tsv"
  echo
  echo "valgrind $(valgrind --version | sed 's/valgrind-//'); load: $(uptime)"
  exit 0
fi

# 3b. Timing: the two sides in turn, ROUNDS rounds, so that a change of the machine's load hits
# both alike; the table is robots.sh's (robots_report.py), the DoF being Pinocchio's nv.
rounds=${ROUNDS:-5}
load_before=$(uptime)
rm -f "$out"/time-*.tsv
for r in $(seq "$rounds"); do
  for name in $names; do
    for s in pinocchio lagrange; do
      side "$s" time "$name" >>"$out/time-$r.tsv"
    done
  done
done
load_after=$(uptime)
dofs=
for name in $names; do
  dofs="$dofs $name=$(($(head -n 1 "$out/$name.tsv" | awk -F'\t' '{ print NF - 1 }') + 6))"
done
echo
echo "Pinocchio $(.venv/bin/python -c 'import pinocchio; print(pinocchio.__version__)'), \
Eigen $EIGEN_VERSION; $(rustc --version); $("$CXX" --version | head -n 1); \
$(grep -m 1 'model name' /proc/cpuinfo | sed 's/.*: //')"
echo
.venv/bin/python robots_report.py table "before:$load_before; after:$load_after" "$dofs" \
  "$out"/time-*.tsv
