#!/usr/bin/env bash
# Floating-base robots against Pinocchio: the tests' quadruped (tests/urdf/quadruped.urdf) and,
# when `ROBOTS=example-robot-data scripts/peers/robots.sh check` has prepared the files, Solo12,
# each read with a free-flying root by `#[lagrange::urdf(.., floating)]` and by Pinocchio
# (`JointModelFreeFlyer`); q̈ compared at random states (floating.py, `floating-check`). Not in CI.
set -euo pipefail
cd "$(dirname "$0")"
root=$(cd ../.. && pwd)
. ./env.sh
mkdir -p build/floating
features=
robots="quadruped:$root/tests/urdf/quadruped.urdf"
solo="$root/lagrange-bench/robots/example-robot-data/solo12.urdf"
if [ -e "$solo" ]; then
  features="--features example-robot-data"
  robots="$robots solo12:$solo"
fi
# shellcheck disable=SC2086 # $features is empty or two words
cargo build --release --quiet --manifest-path "$root/Cargo.toml" -p lagrange-bench --bin floating-check $features
for entry in $robots; do
  name=${entry%%:*}
  .venv/bin/python floating.py "${entry#*:}" "build/floating/$name.tsv"
  "$root/target/release/floating-check" "$name" "build/floating/$name.tsv"
done
