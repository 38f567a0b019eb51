#!/usr/bin/env bash
# Instructions per `accelerations` call, generated and hand-written, under callgrind: the difference
# between 3000 and 1000 calls, divided by 2000 (start-up cancels). Needs valgrind. `BIN=adaptive`
# counts whole integrations of the report's double pendulum, Kepler or FPU chain instead (modes in
# src/bin/adaptive.rs), with
# CALLS=100 (the difference between 300 and 100 runs, divided by 200).
set -euo pipefail
cd "$(dirname "$0")"
cargo build --release --quiet
bin=${CARGO_TARGET_DIR:-target}/release/${BIN:-lagrange-callgrind}
calls=${CALLS:-1000}
count() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$bin" "$1" "$2" 2>&1 |
    grep -o 'refs: *[0-9,]*' | tr -d ', ' | cut -d: -f2
}
for m in ${MODES:-pendulum hw_pendulum double_pendulum hw_double_pendulum wedge_block hw_wedge_block assembled_wedge_block cart_pendulum hw_cart_pendulum}; do
  a=$(count "$m" "$calls")
  b=$(count "$m" $((3 * calls)))
  echo "$m $(( (b - a) / (2 * calls) ))"
done
