#!/usr/bin/env bash
# The cost of calling an RK4 step of the double pendulum from C: N steps called one by one from C
# against the same N steps in one call (a loop in Rust). Prints the wall-clock figures of
# `main bench`, then instructions per step under callgrind (the difference between 3000 and 1000
# steps, divided by 2000, so start-up cancels). Needs cc and valgrind.
set -euo pipefail
cd "$(dirname "$0")"
root=$(cd ../.. && pwd)
cargo build --release --quiet -p double-pendulum-ffi
out=$(mktemp -d)
cc -O2 -std=c11 main.c -I. "$root/target/release/libdouble_pendulum_ffi.a" \
  -lpthread -ldl -lm -lrt -lutil -lgcc_s -o "$out/main"
uptime
"$out/main" bench "${N:-1000000}"
count() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null "$out/main" "$1" "$2" 2>&1 |
    grep -o 'refs: *[0-9,]*' | tr -d ', ' | cut -d: -f2
}
for mode in calls loop; do
  a=$(count "$mode" 1000)
  b=$(count "$mode" 3000)
  echo "instructions_per_step_$mode $(( (b - a) / 2000 ))"
done
rm -rf "$out"
