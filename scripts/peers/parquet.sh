#!/usr/bin/env bash
# The flip map as a job array of K processes writing Parquet parts, merged by the example, then
# opened with pyarrow and polars (scripts/peers/parquet.py says what is checked). Not part of CI.
# Makes scripts/peers/.venv-parquet on first use (pip: pyarrow, polars).
#
#   scripts/peers/parquet.sh [N] [T_MAX] [K]      (defaults 40 4 3)
set -euo pipefail
cd "$(dirname "$0")"
n=${1:-40}
t_max=${2:-4}
k=${3:-3}

if ! .venv-parquet/bin/python -c "import pyarrow, polars" 2>/dev/null; then
  python3 -m venv .venv-parquet
  .venv-parquet/bin/pip install --quiet pyarrow polars
fi

root=$(cd ../.. && pwd)
(cd "$root" && cargo build --release --quiet --features parquet --example flip_map)
example="$root/target/release/examples/flip_map"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for i in $(seq 0 $((k - 1))); do
  "$example" --n "$n" --t-max "$t_max" --out "$out" --shard "$i/$k" --threads 1 &
done
wait
merged=$(LAGRANGE_PLOTS="$out" "$example" --n "$n" --t-max "$t_max" --out "$out" --parts "$k")
echo "$merged"
flipped=$(echo "$merged" | sed -n 's/^\([0-9]*\) of [0-9]* releases flip.*/\1/p')
.venv-parquet/bin/python parquet.py "$out" "$n" "$t_max" "$flipped"
