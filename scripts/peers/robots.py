"""Five synthetic fixed-base robots for the peer benchmark, written from a fixed seed.

    python3 scripts/peers/robots.py            # writes robots/<name>.urdf and the declarations
    python3 scripts/peers/robots.py states OUT  # writes the random states every side reads
    scripts/peers/.venv/bin/python scripts/peers/robots.py reference OUT
                                                # Pinocchio's values at two of those states

The robots are generic as robot files are: every link has its own mass, a centre of mass off the
joint axis, a full inertia tensor about the centre of mass (positive definite, principal moments
satisfying the triangle inequality, non-zero products of inertia) and a joint frame placed by an
offset and a general roll-pitch-yaw rotation in its parent's frame; every joint is revolute about
x, y or z of its own frame. The base is fixed; gravity is (0, 0, -9.81).

- `arm3`, `arm7`, `arm14`: serial arms, axes alternating z, y, z, y, ... (`arm14` is two 7-joint
  arms in series);
- `quadruped`: a fixed torso with four legs of three joints (x, y, y), a tree;
- `humanoid`: a fixed pelvis with two legs of six joints, a two-joint waist up to the chest, and on
  the chest two arms of seven joints and a two-joint head: 30 joints, a tree.

For each robot it writes `robots/<name>.urdf` beside this file and the same robot as a
`#[mechanism]` declaration, `lagrange-bench/robots/src/<name>.rs`, with the numbers as literals
(the same decimal strings in both files) and `g` the one parameter. Each number is rounded to a
few decimals, as robot files give them; the inertia tensors are checked after rounding.

`states OUT` writes, for every robot, eight states (q, q̇ uniform in [-1, 1]) and a random q̈
(uniform in [-1, 1], the input of inverse dynamics) as tab-separated rows `robot, k, q..., q̇...,
q̈...`, coordinates in the declaration's order, after a row `robot, names, coordinate names...`.
Plain Python 3.11 with numpy.

`reference OUT` writes Pinocchio's q̈, τ and M at the first two of those states, computed by the
`pin` wheel from the URDF files (rows `robot, k, quantity, values...`, quantity `state` holding
q, q̇, q̈): the reference of `lagrange-bench/robots/tests/pinocchio.rs`.
"""

import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import numpy as np

SEED = 2026
STATE_SEED = 7
STATES_PER_ROBOT = 8
REFERENCE_STATES = 2
HERE = Path(__file__).resolve().parent
URDF_DIR = HERE / "robots"
RUST_DIR = HERE.parent.parent / "lagrange-bench" / "robots" / "src"

# Decimals kept when a number is written: lengths and angles to 0.1 mm and 0.1 mrad, masses to
# grams, inertias to 1e-7 kg m² (the smallest principal moment generated is about 1e-4).
DECIMALS = {"length": 4, "angle": 4, "mass": 3, "inertia": 7}


@dataclass
class Link:
    name: str  # body (URDF link) name
    coord: str  # coordinate (URDF joint) name
    parent: str | None  # parent body, None for a link joined to the fixed base
    xyz: np.ndarray  # joint origin in the parent's frame
    rpy: np.ndarray  # constant rotation of the joint frame relative to the parent's
    axis: str  # "x", "y" or "z" of the joint frame
    mass: float
    com: np.ndarray  # centre of mass in the joint frame
    inertia: np.ndarray  # 3×3 about the centre of mass, in the joint frame's axes
    note: str  # what the link is, for the reader


@dataclass
class Robot:
    name: str
    type_name: str  # the parameter struct of the declaration
    base: str  # the fixed base's URDF link
    links: list[Link]


def rounded(x: float, kind: str) -> float:
    return float(round(float(x), DECIMALS[kind]))


def literal(x: float) -> str:
    """A decimal literal valid in Rust and URDF: at least one digit after the point, no exponent."""
    text = f"{x:.{max(DECIMALS.values())}f}".rstrip("0")
    if text.endswith("."):
        text += "0"
    return "0.0" if text == "-0.0" else text


def random_rotation(rng: np.random.Generator) -> np.ndarray:
    """A uniformly random rotation: QR of a Gaussian matrix, signs fixed, det +1."""
    q, r = np.linalg.qr(rng.standard_normal((3, 3)))
    q = q * np.sign(np.diag(r))
    if np.linalg.det(q) < 0:
        q[:, 0] = -q[:, 0]
    return q


def random_inertia(rng: np.random.Generator, mass: float, size: float) -> np.ndarray:
    """The inertia of a solid box of random sides in [0.3, 1] · size about its centre,
    I = m/12 (b² + c², a² + c², a² + b²), turned by a random rotation: positive definite with
    Iᵢ + Iⱼ − Iₖ = m cₖ²/6 > 0 (triangle inequality), generic products of inertia."""
    a, b, c = rng.uniform(0.3, 1.0, 3) * size
    principal = mass / 12.0 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
    rot = random_rotation(rng)
    full = rot @ np.diag(principal) @ rot.T
    full = np.vectorize(lambda x: rounded(x, "inertia"))(0.5 * (full + full.T))
    check_inertia(full)
    return full


def check_inertia(inertia: np.ndarray) -> None:
    moments = np.linalg.eigvalsh(inertia)
    off = inertia[np.triu_indices(3, 1)]
    if not (np.all(moments > 1e-5) and moments[0] + moments[1] > moments[2] + 1e-6
            and np.all(np.abs(off) > 0.0)):
        raise ValueError(f"inertia after rounding is not generic and physical: {inertia}")


def random_link(rng, name, coord, parent, axis, mass, length, note, origin=None) -> Link:
    """One link: joint origin at distance `length` in a random direction of the parent's frame
    (or at `origin`), a random rpy in [-1.2, 1.2]³, mass ±20 %, centre of mass within
    0.4 · length of the joint, box inertia of size `length`."""
    if origin is None:
        direction = rng.standard_normal(3)
        origin = length * direction / np.linalg.norm(direction)
    xyz = np.array([rounded(v, "length") for v in np.asarray(origin, dtype=float)])
    rpy = np.array([rounded(v, "angle") for v in rng.uniform(-1.2, 1.2, 3)])
    m = rounded(mass * rng.uniform(0.8, 1.2), "mass")
    com = np.array([rounded(v, "length") for v in rng.uniform(-0.4, 0.4, 3) * length])
    return Link(name, coord, parent, xyz, rpy, axis, m, com, random_inertia(rng, m, length), note)


def serial_arm(rng, count, masses, note) -> list[Link]:
    """`count` links in series, axes z, y, z, y, ..., masses interpolated over `masses`."""
    links = []
    for j in range(count):
        mass = float(np.interp(j, [0, count - 1], masses))
        parent = links[-1].name if links else None
        links.append(random_link(rng, f"link{j + 1}", f"q{j + 1}", parent, "zy"[j % 2], mass,
                                 rng.uniform(0.1, 0.35), f"{note}, joint {j + 1} of {count}"))
    return links


def limb(rng, prefix, parent, axes, masses, lengths, origin, note) -> list[Link]:
    """A limb of len(axes) joints in series from `parent` (None: the fixed base), the first joint
    at `origin` plus a few centimetres of noise."""
    links = []
    for j, (axis, mass, length) in enumerate(zip(axes, masses, lengths)):
        start = None if j else np.asarray(origin) + rng.uniform(-0.02, 0.02, 3)
        up = links[-1].name if links else parent
        links.append(random_link(rng, f"{prefix}{j + 1}", f"q_{prefix}{j + 1}", up, axis, mass,
                                 length, f"{note}, joint {j + 1} of {len(axes)}", start))
    return links


def quadruped(rng) -> list[Link]:
    links = []
    for prefix, sx, sy, note in (("fl", 1, 1, "front left leg"), ("fr", 1, -1, "front right leg"),
                                 ("hl", -1, 1, "hind left leg"), ("hr", -1, -1, "hind right leg")):
        links += limb(rng, prefix, None, "xyy", [1.0, 1.5, 0.4], [0.08, 0.22, 0.22],
                      [0.25 * sx, 0.12 * sy, 0.0], note)
    return links


def humanoid(rng) -> list[Link]:
    leg = dict(axes="zxyyyx", masses=[1.5, 1.5, 4.0, 3.0, 1.0, 1.0],
               lengths=[0.08, 0.08, 0.4, 0.4, 0.08, 0.1])
    arm = dict(axes="yxzyzyx", masses=[1.5, 1.5, 2.0, 1.2, 1.0, 0.6, 0.4],
               lengths=[0.08, 0.08, 0.28, 0.08, 0.26, 0.06, 0.08])
    links = limb(rng, "lleg", None, origin=[0.0, 0.1, -0.1], note="left leg", **leg)
    links += limb(rng, "rleg", None, origin=[0.0, -0.1, -0.1], note="right leg", **leg)
    links += limb(rng, "waist", None, "zy", [2.0, 12.0], [0.1, 0.3], [0.0, 0.0, 0.15], "waist")
    chest = links[-1].name
    links += limb(rng, "larm", chest, origin=[0.0, 0.22, 0.35], note="left arm", **arm)
    links += limb(rng, "rarm", chest, origin=[0.0, -0.22, 0.35], note="right arm", **arm)
    links += limb(rng, "head", chest, "zy", [0.5, 3.0], [0.05, 0.15], [0.0, 0.0, 0.45], "head")
    return links


def robots() -> list[Robot]:
    def rng(index):
        return np.random.default_rng([SEED, index])

    return [
        Robot("arm3", "Arm3", "base", serial_arm(rng(0), 3, [3.0, 1.0], "arm")),
        Robot("arm7", "Arm7", "base", serial_arm(rng(1), 7, [4.0, 0.6], "arm")),
        Robot("arm14", "Arm14", "base", serial_arm(rng(2), 14, [4.0, 0.4], "two arms in series")),
        Robot("quadruped", "Quadruped", "torso", quadruped(rng(3))),
        Robot("humanoid", "Humanoid", "pelvis", humanoid(rng(4))),
    ]


def xyz_text(v) -> str:
    return " ".join(literal(x) for x in v)


def urdf(robot: Robot) -> str:
    out = ['<?xml version="1.0"?>',
           "<!-- Written by scripts/peers/robots.py; do not edit. -->",
           f'<robot name="{robot.name}">', f'  <link name="{robot.base}"/>']
    for link in robot.links:
        i = link.inertia
        axis = {"x": "1 0 0", "y": "0 1 0", "z": "0 0 1"}[link.axis]
        out += [
            f"  <!-- {link.note} -->",
            f'  <link name="{link.name}">',
            "    <inertial>",
            f'      <origin xyz="{xyz_text(link.com)}" rpy="0 0 0"/>',
            f'      <mass value="{literal(link.mass)}"/>',
            f'      <inertia ixx="{literal(i[0, 0])}" ixy="{literal(i[0, 1])}" '
            f'ixz="{literal(i[0, 2])}" iyy="{literal(i[1, 1])}" iyz="{literal(i[1, 2])}" '
            f'izz="{literal(i[2, 2])}"/>',
            "    </inertial>",
            "  </link>",
            f'  <joint name="{link.coord}" type="revolute">',
            f'    <parent link="{link.parent or robot.base}"/>',
            f'    <child link="{link.name}"/>',
            f'    <origin xyz="{xyz_text(link.xyz)}" rpy="{xyz_text(link.rpy)}"/>',
            f'    <axis xyz="{axis}"/>',
            '    <limit lower="-3.1416" upper="3.1416" effort="100.0" velocity="10.0"/>',
            "  </joint>",
        ]
    out.append("</robot>")
    return "\n".join(out) + "\n"


def vec3(v) -> str:
    return f"vec3({', '.join(literal(x) for x in v)})"


def declaration(robot: Robot) -> str:
    coords = "\n".join(f"        pub {link.coord}: f64," for link in robot.links)
    out = [
        f"// Written by scripts/peers/robots.py; do not edit. The robot `{robot.name}`: "
        f"{len(robot.links)} revolute joints,",
        f"// the same numbers as scripts/peers/robots/{robot.name}.urdf (fixed base `{robot.base}`).",
        "#[lagrange::mechanism]",
        f"pub mod {robot.name} {{",
        "    pub struct Coords {",
        coords,
        "    }",
        f"    pub struct {robot.type_name} {{",
        "        pub g: f64,",
        "    }",
    ]
    for link in robot.links:
        rows = (",\n" + " " * 28).join(
            "[" + ", ".join(literal(x) for x in row) + "]" for row in link.inertia)
        joint = f"rpy({', '.join(literal(x) for x in link.rpy)}) * rot_{link.axis}({link.coord})"
        if link.parent is None:
            pose = f"spatial({vec3(link.xyz)}, {joint})"
        else:
            pose = f"{link.parent}.joint({vec3(link.xyz)}, {joint})"
        out += [
            "",
            f"    // {link.note}",
            f"    #[rigid_body(mass = {literal(link.mass)}, com = {vec3(link.com)},",
            f"                 inertia = [{rows}])]",
            f"    fn {link.name}() -> Spatial {{",
            f"        {pose}",
            "    }",
        ]
    out += ["", "    #[gravity]", "    fn down() -> Vec3 {", "        vec3(0.0, 0.0, -g)", "    }",
            "}"]
    return "\n".join(out) + "\n"


def write_states(path: Path) -> None:
    rng = np.random.default_rng(STATE_SEED)
    rows = []
    for robot in robots():
        n = len(robot.links)
        rows.append("\t".join([robot.name, "names"] + [link.coord for link in robot.links]))
        for k in range(STATES_PER_ROBOT):
            values = rng.uniform(-1.0, 1.0, 3 * n)
            rows.append("\t".join([robot.name, str(k)] + [repr(float(x)) for x in values]))
    path.write_text("\n".join(rows) + "\n")


def write_reference(path: Path) -> None:
    """Pinocchio's q̈ (ABA, τ = 0), τ (RNEA at the state's q̈) and M (CRBA) at the first
    REFERENCE_STATES states of each robot, parsed from the URDF by Pinocchio itself; rows
    `robot, k, quantity, values...` in the declaration's order. Needs the venv's `pin`."""
    import pinocchio  # the venv's wheel; only this subcommand needs it

    states = HERE / "build" / "reference-states.tsv"
    states.parent.mkdir(exist_ok=True)
    write_states(states)
    rows, names = [f"# pinocchio {pinocchio.__version__}"], {}
    for line in states.read_text().splitlines():
        robot, kind, *rest = line.split("\t")
        if kind == "names":
            names[robot] = rest
            continue
        if int(kind) >= REFERENCE_STATES:
            continue
        model = pinocchio.buildModelFromUrdf(str(URDF_DIR / f"{robot}.urdf"))
        data = model.createData()
        perm = [model.joints[model.getJointId(c)].idx_v for c in names[robot]]
        n = len(perm)
        q, v, a = (np.zeros(n) for _ in range(3))
        values = np.array([float(x) for x in rest])
        q[perm], v[perm], a[perm] = values[:n], values[n:2 * n], values[2 * n:]
        qdd = pinocchio.aba(model, data, q, v, np.zeros(n))[perm]
        tau = pinocchio.rnea(model, data, q, v, a)[perm]
        mass = pinocchio.crba(model, data, q)
        mass = (np.triu(mass) + np.triu(mass, 1).T)[np.ix_(perm, perm)]
        for quantity, x in (("state", values), ("qdd", qdd), ("tau", tau),
                            ("M", mass.ravel())):
            rows.append("\t".join([robot, kind, quantity] + [repr(float(y)) for y in x]))
    path.write_text("\n".join(rows) + "\n")


def main() -> None:
    if sys.argv[1:2] == ["states"] and len(sys.argv) == 3:
        write_states(Path(sys.argv[2]))
        return
    if sys.argv[1:2] == ["reference"] and len(sys.argv) == 3:
        write_reference(Path(sys.argv[2]))
        return
    if len(sys.argv) != 1:
        sys.exit(__doc__)
    URDF_DIR.mkdir(exist_ok=True)
    RUST_DIR.mkdir(parents=True, exist_ok=True)
    for robot in robots():
        (URDF_DIR / f"{robot.name}.urdf").write_text(urdf(robot))
        (RUST_DIR / f"{robot.name}.rs").write_text(declaration(robot))
        print(f"{robot.name}: {len(robot.links)} joints", file=sys.stderr)
    # The declarations laid out as `cargo fmt` keeps them.
    subprocess.run(["rustfmt", "--edition", "2021"]
                   + [str(RUST_DIR / f"{robot.name}.rs") for robot in robots()], check=True)


if __name__ == "__main__":
    main()
