"""Floating-base robots against Pinocchio's free-flyer ABA: random states of a URDF file read with
a `JointModelFreeFlyer` root, and Pinocchio's accelerations at them, for `floating-check`
(lagrange-bench) to compare with `#[lagrange::urdf(.., floating)]`'s.

    scripts/peers/.venv/bin/python scripts/peers/floating.py URDF STATES

One line per state: q (base position, unit quaternion x y z w with w >= 0, joints), v (base
linear and angular velocity in the base frame, joint rates), a = aba(q, v, 0) (the derivative of
v in the base frame, joint accelerations), all in Pinocchio's joint order; a first line names the
joints. Gravity is Pinocchio's default, 9.81 m/s² along -z, as the macro's.
"""

import sys

import numpy as np
import pinocchio as pin

STATES = 20
SEED = 20261129


def main() -> None:
    urdf, out = sys.argv[1], sys.argv[2]
    model = pin.buildModelFromUrdf(urdf, pin.JointModelFreeFlyer())
    data = model.createData()
    # Joint 0 is the universe, 1 the free flyer; every other joint has one coordinate.
    names = [model.names[j] for j in range(2, model.njoints)]
    assert model.nq == 7 + len(names) and model.nv == 6 + len(names)
    rng = np.random.default_rng(SEED)
    with open(out, "w") as f:
        f.write("names\t" + "\t".join(names) + "\n")
        for _ in range(STATES):
            quat = rng.normal(size=4)
            quat /= np.linalg.norm(quat)
            if quat[3] < 0:
                quat = -quat
            q = np.concatenate([rng.uniform(-1, 1, 3), quat, rng.uniform(-1.5, 1.5, len(names))])
            v = rng.uniform(-2, 2, model.nv)
            a = pin.aba(model, data, q, v, np.zeros(model.nv))
            f.write("\t".join(repr(float(x)) for x in [*q, *v, *a]) + "\n")


if __name__ == "__main__":
    main()
