"""Five robot files of the `example-robot-data` package, made ready for the robot peer benchmark
(`ROBOTS=example-robot-data scripts/peers/robots.sh`), and the random states every side reads.

    scripts/peers/.venv/bin/python scripts/peers/example_robots.py URDF_DIR STATES

Needs the venv's `example-robot-data` (the files) and `pin` (the coordinate order). The robots,
fixed-base as the files give them:

- `ur5`: UR5 (`ur_description/urdf/ur5_robot.urdf`), a 6-joint arm;
- `panda`: Franka Panda (`panda_description/urdf/panda.urdf`), 7 joints, the fingers locked;
- `solo12`: Solo12 (`solo_description/robots/solo12.urdf`), four legs of three joints, a tree;
- `anymal`: ANYmal C (`anymal_c_simple_description/urdf/anymal.urdf`), four legs, a tree;
- `talos`: Talos, whole (`talos_data/robots/talos_full_v2.urdf`), legs, torso, arms and head,
  the grippers locked: a tree.

What is changed in each file, the same file then being read by every side:
- a mimic joint and the joint it mimics become fixed (the Panda's fingers, Talos's grippers): a
  mimic joint is not a coordinate of its own, which `#[lagrange::urdf]` refuses and the other
  sides would each model their own way;
- `<dynamics>` goes: Pinocchio's ABA and RNEA apply neither joint damping nor friction, which
  `#[lagrange::urdf]` declares as generalized forces;
- `<visual>`, `<collision>`, `<transmission>` and `<gazebo>` go: their meshes are not needed by
  dynamics, and MuJoCo's URDF reader would look for them.

The states are written as `robots.py states` writes them (its seed, its count per robot, q, q̇ and
q̈ uniform in [-1, 1]), coordinates in Pinocchio's joint order, which is the file's depth-first
order.
"""

import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from robots import STATE_SEED, STATES_PER_ROBOT

ROBOTS = {
    "ur5": "ur_description/urdf/ur5_robot.urdf",
    "panda": "panda_description/urdf/panda.urdf",
    "solo12": "solo_description/robots/solo12.urdf",
    "anymal": "anymal_c_simple_description/urdf/anymal.urdf",
    "talos": "talos_data/robots/talos_full_v2.urdf",
}
DROPPED = ("visual", "collision", "transmission", "gazebo")


def package_dir() -> Path:
    """Where the venv's `example-robot-data` wheel put its robots (it ships data, no module)."""
    import cmeel

    robots = Path(cmeel.__file__).resolve().parent.parent / "cmeel.prefix" / "share" / \
        "example-robot-data" / "robots"
    if not robots.is_dir():
        sys.exit(f"no {robots}: install example-robot-data into the venv")
    return robots


def prepare(source: Path, target: Path) -> None:
    """The file with mimic joints and the joints they mimic locked, and no dynamics, meshes,
    transmissions or simulator tags."""
    tree = ET.parse(source)
    root = tree.getroot()
    for tag in DROPPED:
        for parent in root.iter():
            for child in parent.findall(tag):
                parent.remove(child)
    joints = root.findall("joint")
    locked = set()
    for joint in joints:
        mimic = joint.find("mimic")
        if mimic is not None:
            locked |= {joint.get("name"), mimic.get("joint")}
    for joint in joints:
        for child in joint.findall("dynamics"):
            joint.remove(child)
        if joint.get("name") in locked:
            joint.set("type", "fixed")
            for tag in ("mimic", "axis", "limit", "safety_controller", "calibration"):
                for child in joint.findall(tag):
                    joint.remove(child)
    tree.write(target, encoding="unicode", xml_declaration=True)


def write_states(urdf_dir: Path, path: Path) -> None:
    import pinocchio

    rng = np.random.default_rng(STATE_SEED)
    rows = []
    for robot in ROBOTS:
        model = pinocchio.buildModelFromUrdf(str(urdf_dir / f"{robot}.urdf"))
        if model.nq != model.nv or model.nv != model.njoints - 1:
            sys.exit(f"{robot}: a joint of more than one coordinate")
        rows.append("\t".join([robot, "names"] + list(model.names)[1:]))
        for k in range(STATES_PER_ROBOT):
            values = rng.uniform(-1.0, 1.0, 3 * model.nv)
            rows.append("\t".join([robot, str(k)] + [repr(float(x)) for x in values]))
        print(f"{robot}: {model.nv} joints", file=sys.stderr)
    path.write_text("\n".join(rows) + "\n")


def main() -> None:
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    urdf_dir, states = Path(sys.argv[1]), Path(sys.argv[2])
    urdf_dir.mkdir(parents=True, exist_ok=True)
    source = package_dir()
    for robot, file in ROBOTS.items():
        prepare(source / file, urdf_dir / f"{robot}.urdf")
    write_states(urdf_dir, states)


if __name__ == "__main__":
    main()
