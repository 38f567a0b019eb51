//! The checks on a parsed file and the bodies it gives: one tree rooted at one link, every joint
//! supported, and the links welded by fixed joints merged into the body they move with.
//!
//! A link moved by a revolute, continuous or prismatic joint is a body whose frame is the link's
//! frame; a link joined by a fixed joint moves with its parent, so its inertial is merged into the
//! parent's body (or dropped when it is welded to the ground, where it cannot move) and its
//! children are placed through the fixed joint's constant transform.

use super::frames::{combine, norm, MassPart, Transform};
use super::parse::{Inertial, JointType, Robot};

/// A mistake in the file's structure, naming the element (reported at the macro call).
pub type Refusal = String;

/// How a body moves relative to its joint frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    /// About the unit axis, by the body's coordinate.
    Revolute([f64; 3]),
    /// Along the unit axis.
    Prismatic([f64; 3]),
}

/// A body of the generated declaration: one moving link with what is welded to it.
#[derive(Debug)]
pub struct Body {
    pub link: String,
    /// The joint that moves it, its coordinate named after it.
    pub joint: usize,
    /// The body it is placed from (`None`: the ground).
    pub parent: Option<usize>,
    /// The joint frame in the parent body's frame: through the fixed joints between them, then the
    /// joint's own origin.
    pub placement: Transform,
    /// The same rotation as the file writes it: the `rpy` of each of those origins, in order
    /// (those of zero left out).
    pub rpys: Vec<[f64; 3]>,
    pub motion: Motion,
    pub inertia: MassPart,
}

/// Where a link is, relative to the body it moves with.
#[derive(Clone)]
struct Attached {
    body: Option<usize>,
    transform: Transform,
    rpys: Vec<[f64; 3]>,
}

/// The bodies, parents first, each moved by one joint of the file; with `floating`, also the root
/// link's mass with what is welded to it (a free-flying base, which the bodies without a parent
/// body are placed from), else the root is the ground.
pub fn bodies(robot: &Robot, floating: bool) -> Result<(Vec<Body>, Option<MassPart>), Refusal> {
    let order = topology(robot)?;
    let mut bodies: Vec<Body> = Vec::new();
    let mut parts: Vec<Vec<MassPart>> = Vec::new();
    let mut attached = vec![None; robot.links.len()];
    let root = order.root;
    // With a floating base, the root link's inertial and those welded to it.
    let mut base: Vec<MassPart> = Vec::new();
    if let (true, Some(i)) = (floating, &robot.links[root].inertial) {
        base.extend(link_mass(i, &Transform::IDENTITY));
    }
    attached[root] = Some(Attached {
        body: None,
        transform: Transform::IDENTITY,
        rpys: Vec::new(),
    });
    for &j in &order.joints {
        let joint = &robot.joints[j];
        let (p, c) = (order.parent_of[j], order.child_of[j]);
        let at: Attached = attached[p].clone().expect("parents first");
        let origin = Transform::of(&joint.origin);
        let mut rpys = at.rpys.clone();
        if joint.origin.rpy != [0.0; 3] {
            rpys.push(joint.origin.rpy);
        }
        let motion = match joint.kind {
            JointType::Fixed => None,
            JointType::Revolute | JointType::Continuous => Some(Motion::Revolute(unit(joint)?)),
            JointType::Prismatic => Some(Motion::Prismatic(unit(joint)?)),
            JointType::Floating | JointType::Planar => unreachable!("refused by the topology"),
        };
        let here = match motion {
            None => Attached {
                body: at.body,
                transform: at.transform.then(&origin),
                rpys,
            },
            Some(motion) => {
                bodies.push(Body {
                    link: robot.links[c].name.clone(),
                    joint: j,
                    parent: at.body,
                    placement: at.transform.then(&origin),
                    rpys,
                    motion,
                    inertia: MassPart {
                        mass: 0.0,
                        centre: [0.0; 3],
                        inertia: [[0.0; 3]; 3],
                    },
                });
                parts.push(Vec::new());
                Attached {
                    body: Some(bodies.len() - 1),
                    transform: Transform::IDENTITY,
                    rpys: Vec::new(),
                }
            }
        };
        match (here.body, &robot.links[c].inertial) {
            (Some(b), Some(i)) => parts[b].extend(link_mass(i, &here.transform)),
            (None, Some(i)) if floating => base.extend(link_mass(i, &here.transform)),
            _ => {}
        }
        attached[c] = Some(here);
    }
    finish(
        robot,
        bodies,
        &parts,
        floating.then_some((root, base.as_slice())),
    )
}

/// Each body's mass from its parts, and the floating base's from its own (`base`: the root link
/// and its parts) — refused where there is none; without a floating base, refused when nothing
/// moves.
fn finish(
    robot: &Robot,
    mut bodies: Vec<Body>,
    parts: &[Vec<MassPart>],
    base: Option<(usize, &[MassPart])>,
) -> Result<(Vec<Body>, Option<MassPart>), Refusal> {
    for (body, parts) in bodies.iter_mut().zip(parts) {
        body.inertia = combine(parts).ok_or_else(|| {
            format!(
                "link `{}`, moved by joint `{}`, has no mass (no `<inertial>` of positive mass on it \
                 or on a link fixed to it): its joint's acceleration is undefined; give it an \
                 inertial or make the joint fixed",
                body.link, robot.joints[body.joint].name
            )
        })?;
    }
    let Some((root, base)) = base else {
        if bodies.is_empty() {
            return Err(
                "the file has no revolute, continuous or prismatic joint: nothing moves".into(),
            );
        }
        return Ok((bodies, None));
    };
    let base_mass = combine(base).ok_or_else(|| {
        format!(
            "the root link `{}` is a floating base with no mass (no `<inertial>` of positive \
             mass on it or on a link fixed to it): its acceleration is undefined",
            robot.links[root].name
        )
    })?;
    Ok((bodies, Some(base_mass)))
}

/// A link's inertial seen from the frame of the body it moves with (the link's frame at `link`
/// in it); nothing for a massless inertial.
fn link_mass(i: &Inertial, link: &Transform) -> Option<MassPart> {
    let [xx, xy, xz, yy, yz, zz] = i.inertia;
    let own = MassPart {
        mass: i.mass,
        centre: [0.0; 3],
        inertia: [[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]],
    };
    (i.mass > 0.0).then(|| own.moved(&link.then(&Transform::of(&i.origin))))
}

/// The joint's axis, normalised.
fn unit(joint: &super::parse::Joint) -> Result<[f64; 3], Refusal> {
    let n = norm(joint.axis);
    if n == 0.0 {
        return Err(format!("joint `{}` has an axis of zero length", joint.name));
    }
    // An axis written with one non-zero component is kept exact (±1), so that the joint is written
    // as a rotation about a coordinate axis.
    Ok(joint.axis.map(|c| c / n))
}

/// The root link's index (the file's one link no joint moves).
pub fn root_link(robot: &Robot) -> Result<usize, Refusal> {
    topology(robot).map(|order| order.root)
}

struct Order {
    root: usize,
    /// Joints, each after the joint that moves its parent.
    joints: Vec<usize>,
    parent_of: Vec<usize>,
    child_of: Vec<usize>,
}

/// One root, every link with at most one parent, no loop, every joint supported.
fn topology(robot: &Robot) -> Result<Order, Refusal> {
    for (k, l) in robot.links.iter().enumerate() {
        if robot.links[..k].iter().any(|m| m.name == l.name) {
            return Err(format!("link `{}` is declared twice", l.name));
        }
    }
    let mut parent_of = Vec::new();
    let mut child_of = Vec::new();
    let mut parent_joint: Vec<Option<usize>> = vec![None; robot.links.len()];
    for (j, joint) in robot.joints.iter().enumerate() {
        if robot.joints[..j].iter().any(|k| k.name == joint.name) {
            return Err(format!("joint `{}` is declared twice", joint.name));
        }
        supported(joint)?;
        let (p, c) = (
            link_index(robot, &joint.parent, &joint.name)?,
            link_index(robot, &joint.child, &joint.name)?,
        );
        if let Some(other) = parent_joint[c] {
            return Err(format!(
                "link `{}` has two parents, by joints `{}` and `{}`: a URDF model is a tree",
                joint.child, robot.joints[other].name, joint.name
            ));
        }
        parent_joint[c] = Some(j);
        parent_of.push(p);
        child_of.push(c);
    }
    let root = root(robot, &parent_joint)?;
    let joints = depth_first(robot, root, &parent_of, &child_of, &parent_joint)?;
    Ok(Order {
        root,
        joints,
        parent_of,
        child_of,
    })
}

/// The index of the link `name` that joint `joint` names.
fn link_index(robot: &Robot, name: &str, joint: &str) -> Result<usize, Refusal> {
    robot
        .links
        .iter()
        .position(|l| l.name == name)
        .ok_or_else(|| {
            format!("joint `{joint}` names link `{name}`, which the file does not declare")
        })
}

/// A joint the declaration can write: no mimic, no floating or planar joint.
fn supported(joint: &super::parse::Joint) -> Result<(), Refusal> {
    if joint.mimic {
        return Err(format!(
            "joint `{}` is a mimic joint, which is not supported (its coordinate would be \
             another's multiple: declare it by hand, or as a constraint)",
            joint.name
        ));
    }
    if matches!(joint.kind, JointType::Floating | JointType::Planar) {
        let kind = if joint.kind == JointType::Floating {
            "floating"
        } else {
            "planar"
        };
        return Err(format!(
            "joint `{}` is {kind}, which is not supported: only revolute, continuous, \
             prismatic and fixed joints (for a free-flying root link, \
             `#[urdf(\"robot.urdf\", floating)]`)",
            joint.name
        ));
    }
    Ok(())
}

/// The one link no joint moves.
fn root(robot: &Robot, parent_joint: &[Option<usize>]) -> Result<usize, Refusal> {
    let roots: Vec<usize> = (0..robot.links.len())
        .filter(|&l| parent_joint[l].is_none())
        .collect();
    match roots.as_slice() {
        [root] => Ok(*root),
        [] if robot.links.is_empty() => Err("the file declares no link".into()),
        [] => Err(format!(
            "the joints form a loop (link `{}` is its own ancestor): a URDF model is a tree",
            robot.links[0].name
        )),
        [a, b, ..] => Err(format!(
            "links `{}` and `{}` both have no parent: a URDF model has one root link",
            robot.links[*a].name, robot.links[*b].name
        )),
    }
}

/// The joints depth first from the root, children in file order: parents first, every link
/// reached once; a link not reached lies on a loop.
fn depth_first(
    robot: &Robot,
    root: usize,
    parent_of: &[usize],
    child_of: &[usize],
    parent_joint: &[Option<usize>],
) -> Result<Vec<usize>, Refusal> {
    let mut joints = Vec::new();
    let mut stack = vec![root];
    while let Some(l) = stack.pop() {
        if l != root {
            joints.push(parent_joint[l].expect("a link below the root has a parent"));
        }
        let children = (0..robot.joints.len()).filter(|&j| parent_of[j] == l);
        stack.extend(children.rev().map(|j| child_of[j]));
    }
    if let Some(j) = (0..robot.joints.len()).find(|j| !joints.contains(j)) {
        return Err(format!(
            "the joints form a loop through link `{}`: a URDF model is a tree",
            robot.joints[j].child
        ));
    }
    Ok(joints)
}
