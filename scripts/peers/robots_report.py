"""The check and the table of robots.sh, from the drivers' tab-separated output (robots_common.h);
the table and the counts of floating.sh too.

    python3 robots_report.py check VALUES.tsv...            exit 2 when a check fails
    python3 robots_report.py table LOAD DOFS TIMES.tsv...   the timing table, one file per round
                                                            (DOFS: "arm3=3 arm7=7 ...")
    python3 robots_report.py counts COUNTS.tsv              instructions per call

check: Pinocchio's values are the reference. For every other side, robot, quantity and state,
the largest difference relative to the size of the reference, max_i |x_i − ref_i| / max_i |ref_i|
(q̈, τ: the vector's ∞-norm; M: the largest entry), must be ≤ 1e-10.

table: per robot and label (a column for each side and label present), the min over rounds of
each round's min per-call time, and the median over rounds of each round's median; ratios of the
mins; the growth exponent of each column from `arm7` to `humanoid`, log(t_humanoid / t_arm7) /
log(30 / 7) (from `panda` to `talos` for the robots of example-robot-data).
"""

import math
import statistics
import sys
from collections import defaultdict

import numpy as np

TOLERANCE = 1e-10
REFERENCE = "pinocchio"
COLUMNS = [
    ("lagrange", "accelerations", "lagrange `accelerations`"),
    ("pinocchio", "aba", "Pinocchio ABA"),
    ("mujoco", "mj_forward", "MuJoCo `mj_forward`"),
    ("lagrange", "inverse_dynamics", "lagrange `inverse_dynamics`"),
    ("pinocchio", "rnea", "Pinocchio RNEA"),
    ("pinocchio", "crba", "Pinocchio CRBA"),
    ("lagrange", "mass_matrix", "lagrange `mass_matrix`"),
]
RATIOS = [
    (("lagrange", "accelerations"), ("pinocchio", "aba"), "accelerations / ABA"),
    (("lagrange", "accelerations"), ("mujoco", "mj_forward"), "accelerations / mj_forward"),
    (("lagrange", "inverse_dynamics"), ("pinocchio", "rnea"), "inverse dynamics / RNEA"),
    (("lagrange", "mass_matrix"), ("pinocchio", "crba"), "mass_matrix / CRBA"),
]
GROWTH = [("arm7", "humanoid"), ("panda", "talos")]


def rows(paths):
    for path in paths:
        with open(path) as f:
            for line in f:
                if line.strip() and not line.startswith("#"):
                    yield line.rstrip("\n").split("\t")


def check(paths) -> int:
    values = {}  # (side, robot, quantity, k) -> array
    robots, sides = [], []
    for side, robot, quantity, k, *xs in rows(paths):
        values[side, robot, quantity, int(k)] = np.array([float(x) for x in xs])
        robots += [robot] if robot not in robots else []
        sides += [side] if side not in sides and side != REFERENCE else []
    worst = defaultdict(float)
    failed = []
    for (side, robot, quantity, k), x in values.items():
        if side == REFERENCE:
            continue
        ref = values.get((REFERENCE, robot, quantity, k))
        if ref is None or ref.shape != x.shape:
            failed.append(f"{side} {robot} {quantity} state {k}: no reference of that shape")
            continue
        err = np.max(np.abs(x - ref)) / np.max(np.abs(ref))
        worst[side, robot, quantity] = max(worst[side, robot, quantity], err)
        if not err <= TOLERANCE:
            failed.append(f"{side} {robot} {quantity} state {k}: {err:.2e}")
    quantities = ["qdd", "tau", "M"]
    header = [f"{s} {q}" for s in sides for q in quantities if any(
        (s, r, q) in worst for r in robots)]
    print("Largest difference from Pinocchio over the states, relative to the size of Pinocchio's"
          f" value (check: ≤ {TOLERANCE:g}):")
    print()
    print("| robot | " + " | ".join(header) + " |")
    print("|---|" + "---:|" * len(header))
    for robot in robots:
        cells = []
        for name in header:
            side, quantity = name.split(" ")
            err = worst.get((side, robot, quantity))
            cells.append("n/a" if err is None else f"{err:.1e}")
        print(f"| {robot} | " + " | ".join(cells) + " |")
    print()
    for line in failed[:20]:
        print("FAIL " + line)
    if len(failed) > 20:
        print(f"... and {len(failed) - 20} more")
    print("checks missed" if failed else f"all checks within {TOLERANCE:g}")
    return 2 if failed else 0


def table(load, paths) -> int:
    mins, medians, dof = defaultdict(list), defaultdict(list), {}
    robots = []
    for side, robot, label, mn, md, _calls in rows(paths):
        mins[side, label, robot].append(float(mn))
        medians[side, label, robot].append(float(md))
        robots += [robot] if robot not in robots else []
    for robot, n in (r.split("=") for r in load[1]):
        dof[robot] = int(n)

    def best(key):
        return min(mins[key]) if key in mins else None

    def cell(side, label, robot):
        key = (side, label, robot)
        if key not in mins:
            return "n/a"
        return f"{fmt_ns(min(mins[key]))} ({fmt_ns(statistics.median(medians[key]))})"

    # The columns of the sides and labels timed (floating.sh times two of each).
    columns = [c for c in COLUMNS if any((c[0], c[1], r) in mins for r in robots)]
    ratios = [r for r in RATIOS if any((*r[0], x) in mins and (*r[1], x) in mins
                                       for x in robots)]
    rounds = max((len(v) for v in mins.values()), default=0)
    print(f"Per call, min (median) over {rounds} interleaved rounds; each round's figure is the "
          "min (median) of 21 repetitions of ≈ 10 ms, one call at each of the robot's states.")
    print()
    print("| robot | DoF | " + " | ".join(c[2] for c in columns) + " | "
          + " | ".join(r[2] for r in ratios) + " |")
    print("|---|---:|" + "---:|" * (len(columns) + len(ratios)))
    for robot in robots:
        cells = [cell(side, label, robot) for side, label, _ in columns]
        for (a, b, _) in ratios:
            ta, tb = best((*a, robot)), best((*b, robot))
            cells.append("n/a" if ta is None or tb is None else f"{ta / tb:.2f}")
        print(f"| {robot} | {dof.get(robot, '?')} | " + " | ".join(cells) + " |")
    for lo, hi in GROWTH:
        if lo not in dof or hi not in dof or lo not in robots:
            continue
        cells = []
        for side, label, _ in columns:
            ta, tb = best((side, label, lo)), best((side, label, hi))
            cells.append("n/a" if ta is None or tb is None else
                         f"{math.log(tb / ta) / math.log(dof[hi] / dof[lo]):.2f}")
        print(f"| growth exponent {lo} → {hi} | {dof[lo]} → {dof[hi]} | " + " | ".join(cells)
              + " |" + " |" * len(ratios))
    print()
    print(f"load: {load[0]}")
    return 0


def fmt_ns(ns: float) -> str:
    return f"{ns / 1000:.2f} µs" if ns >= 1000 else f"{ns:.0f} ns"


def counts(path) -> int:
    by = {}
    robots = []
    for side, robot, label, per_call in rows([path]):
        by[side, label, robot] = int(per_call)
        robots += [robot] if robot not in robots else []
    present = [c for c in COLUMNS if any((c[0], c[1], r) in by for r in robots)]
    print("Instructions per call (callgrind: the difference between 3·C and C calls over 2·C):")
    print()
    print("| robot | " + " | ".join(c[2] for c in present) + " |")
    print("|---|" + "---:|" * len(present))
    for robot in robots:
        cells = [f"{by[key] / 1000:.1f} k" if (key := (s, l, robot)) in by else "n/a"
                 for s, l, _ in present]
        print(f"| {robot} | " + " | ".join(cells) + " |")
    return 0


def main() -> int:
    args = sys.argv[1:]
    if len(args) >= 2 and args[0] == "check":
        return check(args[1:])
    if len(args) >= 4 and args[0] == "table":
        # table "LOAD" "robot=dof robot=dof ..." TIMES...
        return table((args[1], args[2].split()), args[3:])
    if len(args) == 2 and args[0] == "counts":
        return counts(args[1])
    sys.exit(__doc__)


if __name__ == "__main__":
    sys.exit(main())
