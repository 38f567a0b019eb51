"""Floating-base robots against Pinocchio's free flyer: random states of a URDF file read with a
`JointModelFreeFlyer` root, Pinocchio's ABA and RNEA at them, and its model saved as text for the
C++ driver (pinocchio_floating.cpp), for `floating-check` (lagrange-bench) to compare with
`#[lagrange::urdf(.., floating)]`'s and to time both.

    scripts/peers/.venv/bin/python scripts/peers/floating.py URDF STATES MODEL

One line per state: q (base position, unit quaternion x y z w with w >= 0, joints), v (base
linear and angular velocity in the base frame, joint rates), a = aba(q, v, 0) (the derivative of
v in the base frame, joint accelerations), a random acceleration b of v's kind, and
tau = rnea(q, v, b) (the base's force and torque in the base frame, joint torques), all in
Pinocchio's joint order; a first line names the joints. Gravity is Pinocchio's default, 9.81 m/s²
along -z, as the macro's. MODEL: the model by `Model.saveToText`, which the driver loads.
"""

import sys

import numpy as np
import pinocchio as pin

STATES = 20
SEED = 20261129


def main() -> None:
    urdf, out, saved = sys.argv[1], sys.argv[2], sys.argv[3]
    model = pin.buildModelFromUrdf(urdf, pin.JointModelFreeFlyer())
    model.saveToText(saved)
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
            a = pin.aba(model, data, q, v, np.zeros(model.nv)).copy()
            b = rng.uniform(-2, 2, model.nv)
            tau = pin.rnea(model, data, q, v, b).copy()
            f.write("\t".join(repr(float(x)) for x in [*q, *v, *a, *b, *tau]) + "\n")


if __name__ == "__main__":
    main()
