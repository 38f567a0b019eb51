#!/usr/bin/env bash
# Peer benchmark of five synthetic fixed-base robots (robots.py: arms of 3, 7 and 14 joints, a
# quadruped, a humanoid of 30 joints): lagrange's generated `accelerations`, `inverse_dynamics`
# and `mass_matrix` against Pinocchio's ABA, RNEA and CRBA (C++) and MuJoCo's mj_forward (C), on
# the same URDF files at the same random states. Every side's values are checked against
# Pinocchio's to 1e-10 before anything is timed. Not part of CI. Writes only under
# scripts/peers/ (.venv, build) and cargo's target directory.
#
#   scripts/peers/robots.sh              # check, then ROUNDS (5) interleaved rounds of timing
#   scripts/peers/robots.sh check        # build and check only
#   scripts/peers/robots.sh callgrind    # instructions per call (valgrind), CALLS (500)
#   scripts/peers/robots.sh build-time   # release build time of the declarations' crate
#
# ROBOTS=example-robot-data: the same on five robot files of the `example-robot-data` package
# (UR5, Panda, Solo12, ANYmal C, Talos; example_robots.py says what it changes in them),
# read by lagrange through `#[lagrange::urdf]` (lagrange-robots' feature of that name).
#
# Environment: ROUNDS, CALLS, ROBOTS (synthetic, example-robot-data), ERD_VERSION; the versions
# and compilers of env.sh.
set -euo pipefail
cd "$(dirname "$0")"
mode=${1:-time}
case "$mode" in time | check | callgrind | build-time) ;; *)
  sed -n '2,15p' "$0" >&2
  exit 1
  ;;
esac
root=$(cd ../.. && pwd)
case "${ROBOTS:=synthetic}" in
synthetic)
  robots="arm3 arm7 arm14 quadruped humanoid"
  urdf_dir=robots
  out=build/robots
  features=
  sides="pinocchio mujoco lagrange"
  ;;
example-robot-data)
  [ "$mode" = build-time ] && { echo "build-time measures the synthetic robots only" >&2; exit 1; }
  robots="ur5 panda solo12 anymal talos"
  urdf_dir="$root/lagrange-bench/robots/example-robot-data"
  out=build/example-robot-data
  features="--features example-robot-data"
  # MuJoCo's URDF import fuses the bodies that fixed joints join and applies the files' joint
  # limits, which the driver's strict model check (mujoco_robots.c) refuses: Pinocchio only.
  sides="pinocchio lagrange"
  ;;
*)
  echo "ROBOTS is synthetic or example-robot-data" >&2
  exit 1
  ;;
esac
mkdir -p "$out/models"

# The release build of lagrange-robots (the five declarations) alone, its dependencies built
# first: each robot on its own (a cargo feature each), then all five.
if [ "$mode" = build-time ]; then
  cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p lagrange-robots
  echo "| robots declared | release build of lagrange-robots |"
  echo "|---|---:|"
  for set in $robots "$robots"; do
    touch "$root/lagrange-bench/robots/src/lib.rs"
    t0=$(date +%s.%N)
    cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p lagrange-robots \
      --no-default-features --features "${set// /,}"
    awk -v set="$set" -v t0="$t0" -v t1="$(date +%s.%N)" 'BEGIN { printf "| %s | %.1f s |\n", set, t1 - t0 }'
  done
  echo
  echo "load: $(uptime)"
  exit 0
fi

# 1. Virtual environment and compile commands (env.sh); the drivers, rebuilt when a source is
# newer than the binary; lagrange's side.
. ./env.sh
if stale build/mujoco_robots mujoco_robots.c robots_common.h timing.h "$mj_lib"; then
  build_mujoco mujoco_robots.c build/mujoco_robots
fi
if stale build/pinocchio_robots pinocchio_robots.cpp robots_common.h timing.h; then
  build_pinocchio pinocchio_robots.cpp build/pinocchio_robots \
    -L"$prefix/lib" -lboost_serialization -Wl,-rpath,"$prefix/lib"
fi
# 2. The states every side reads (for example-robot-data, after the files are copied from the
# package and made ready), and Pinocchio's models: its URDF parser (the wheel's
# libpinocchio_parsers), saved as text for the driver (see pinocchio_robots.cpp).
if [ "$ROBOTS" = synthetic ]; then
  .venv/bin/python robots.py states "$out/states.tsv"
else
  .venv/bin/python -m pip show --quiet example-robot-data 2>/dev/null ||
    .venv/bin/python -m pip install --quiet "example-robot-data==${ERD_VERSION:-6.0.0}"
  .venv/bin/python example_robots.py "$urdf_dir" "$out/states.tsv"
fi
.venv/bin/python -c "
import sys, pinocchio
for name in sys.argv[1:]:
    pinocchio.buildModelFromUrdf(f'$urdf_dir/{name}.urdf').saveToText(f'$out/models/{name}.txt')
" $robots
# shellcheck disable=SC2086 # $features is empty or two words
cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p lagrange-bench --bin robots $features
lagrange="$root/target/release/robots"
dofs=$(awk -F'\t' '$2 == "names" { printf "%s%s=%d", sep, $1, NF - 2; sep = " " }' "$out/states.tsv")

# side NAME MODE ARGS...: one side's driver.
side() {
  local name=$1
  shift
  case "$name" in
  lagrange) "$lagrange" "$1" --states "$out/states.tsv" "${@:2}" ;;
  pinocchio) build/pinocchio_robots "$1" "$out/states.tsv" "$out/models" "${@:2}" ;;
  mujoco) build/mujoco_robots "$1" "$out/states.tsv" "$urdf_dir" "${@:2}" ;;
  esac
}

# 3. The check, before any timing: q̈ of every side, τ and M of lagrange (and M of MuJoCo),
# against Pinocchio's. A driver exits 2 when its own check failed; the report exits 2 when a
# side's values miss Pinocchio's.
rm -f "$out"/values-*.tsv
for s in $sides; do
  rc=0
  side "$s" values >"$out/values-$s.tsv" || rc=$?
  if [ "$rc" -ne 0 ]; then
    echo "$s values failed with exit code $rc" >&2
    exit "$rc"
  fi
done
grep -h '^#' "$out"/values-*.tsv
echo
rc=0
.venv/bin/python robots_report.py check "$out"/values-*.tsv || rc=$?
if [ "$rc" -ne 0 ] || [ "$mode" = check ]; then
  exit "$rc"
fi

# 4a. Instructions per call under callgrind: the difference between 3·CALLS and CALLS calls,
# divided by 2·CALLS (start-up cancels).
if [ "$mode" = callgrind ]; then
  calls=${CALLS:-500}
  # count_calls SIDE ROBOT LABEL N: the instructions of N calls (env.sh's counts_line).
  # shellcheck disable=SC2317 # called through counts_line
  count_calls() {
    if [ "$1" = lagrange ]; then
      instructions "$lagrange" count --states "$out/states.tsv" --robot "$2" --label "$3" --calls "$4"
    else
      dir=$urdf_dir
      [ "$1" = pinocchio ] && dir="$out/models"
      instructions "build/$1_robots" count "$out/states.tsv" "$dir" "$2" "$3" "$4"
    fi
  }
  : >"$out/counts.tsv"
  for robot in $robots; do
    for pair in lagrange:accelerations pinocchio:aba mujoco:mj_forward \
      lagrange:inverse_dynamics pinocchio:rnea pinocchio:crba lagrange:mass_matrix; do
      s=${pair%%:*} label=${pair#*:}
      case " $sides " in *" $s "*) ;; *) continue ;; esac
      counts_line "$s" "$robot" "$label" "$calls" >>"$out/counts.tsv"
    done
  done
  .venv/bin/python robots_report.py counts "$out/counts.tsv"
  echo
  echo "valgrind $(valgrind --version | sed 's/valgrind-//'); load: $(uptime)"
  exit 0
fi

# 4b. Timing: the sides in turn, A B C A B C ..., ROUNDS rounds, so that a change of the
# machine's load hits every side alike.
rounds=${ROUNDS:-5}
load_before=$(uptime)
rm -f "$out"/time-*.tsv
for r in $(seq "$rounds"); do
  for s in $sides; do
    side "$s" time >"$out/time-$r-$s.tsv"
  done
done
load_after=$(uptime)
echo
echo "MuJoCo $(.venv/bin/python -c 'import mujoco; print(mujoco.__version__)'), \
Pinocchio $(.venv/bin/python -c 'import pinocchio; print(pinocchio.__version__)'), \
Eigen $EIGEN_VERSION; $(rustc --version); $("$CC" --version | head -n 1); \
$(grep -m 1 'model name' /proc/cpuinfo | sed 's/.*: //')"
echo
.venv/bin/python robots_report.py table "before:$load_before; after:$load_after" "$dofs" \
  "$out"/time-*.tsv
