"""Opens the flip map's Parquet parts with pyarrow and with polars and checks them.

Usage: parquet.py DIR N T_MAX FLIPPED
DIR holds the parts of one sharded run of `examples/flip_map.rs`; N, T_MAX are the run's
arguments; FLIPPED is the number of releases that flipped, as the Rust merge printed it.
Checks: every part has the same schema (index: the input's place in the sweep; theta1, theta2:
double; flip_time: double, null where no flip) and the same sweep metadata but its own
`lagrange.shard`; the rows, concatenated in part order, are the N x N grid with theta1
varying fastest; pyarrow and polars read the same values bit for bit; the flip count agrees with
the Rust side's. Exits non-zero on the first failed check.
"""
import glob
import math
import struct
import sys

import polars as pl
import pyarrow as pa
import pyarrow.parquet as pq


def bits(xs):
    return [None if x is None else struct.pack("<d", x) for x in xs]


def shared(metadata):
    """The sweep's metadata without the part's own shard."""
    return {k: v for k, v in metadata.items() if k != "lagrange.shard"}


def main():
    folder, n, t_max, flipped = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4])
    paths = sorted(glob.glob(f"{folder}/flip_map-part-*.parquet"))
    assert paths, f"no parts in {folder}"
    tables = [pq.read_table(p) for p in paths]
    schema = tables[0].schema
    names = [f.name for f in schema]
    assert names == ["index", "theta1", "theta2", "flip_time"], names
    meta = {k.decode(): v.decode() for k, v in (schema.metadata or {}).items()}
    for key in ("mechanism", "integrator", "h", "t_max", "grid"):
        assert key in meta, f"metadata lacks {key}: {meta}"
    assert meta["grid"] == f"{n}x{n}", meta["grid"]
    assert float(meta["t_max"]) == t_max, meta["t_max"]
    for p, t in zip(paths, tables):
        assert t.schema.equals(schema, check_metadata=False), f"{p}: schema differs"
        m = {k.decode(): v.decode() for k, v in (t.schema.metadata or {}).items()}
        assert shared(m) == shared(meta), f"{p}: metadata differs"
    theta1 = [x for t in tables for x in t.column("theta1").to_pylist()]
    theta2 = [x for t in tables for x in t.column("theta2").to_pylist()]
    flip = [x for t in tables for x in t.column("flip_time").to_pylist()]
    assert len(flip) == n * n, f"{len(flip)} rows, expected {n * n}"
    index = [x for t in tables for x in t.column("index").to_pylist()]
    assert index == list(range(n * n)), "the parts' rows are not the sweep's inputs in order"

    # The grid of gallery/src/flip_map.rs: cell centres from -pi + pi/n to pi - pi/n, written
    # start + (end - start) k / (n - 1) as ensemble::linspace computes it.
    lo, hi = -math.pi + math.pi / n, math.pi - math.pi / n
    angles = [lo + (hi - lo) * k / (n - 1) for k in range(n)] if n > 1 else [lo]
    if n > 1:
        angles[-1] = hi
    want1 = [angles[i] for j in range(n) for i in range(n)]
    want2 = [angles[j] for j in range(n) for i in range(n)]
    assert max(abs(a - b) for a, b in zip(theta1, want1)) <= 4e-16 * math.pi, "theta1 is not the grid"
    assert max(abs(a - b) for a, b in zip(theta2, want2)) <= 4e-16 * math.pi, "theta2 is not the grid"

    frame = pl.concat([pl.read_parquet(p) for p in paths])
    assert bits(frame["flip_time"].to_list()) == bits(flip), "polars and pyarrow disagree"
    assert bits(frame["theta1"].to_list()) == bits(theta1), "polars and pyarrow disagree"
    count = sum(1 for x in flip if x is not None)
    assert count == flipped, f"{count} flips read, the Rust merge printed {flipped}"
    assert all(0.0 < x <= t_max for x in flip if x is not None), "a flip time outside (0, t_max]"
    print(f"{len(paths)} parts, {len(flip)} rows, {count} flips: pyarrow {pa.__version__}"
          f" and polars {pl.__version__} read the same values bit for bit; metadata {sorted(meta)}")


if __name__ == "__main__":
    main()
