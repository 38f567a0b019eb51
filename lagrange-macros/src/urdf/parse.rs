//! A URDF file read into plain data (roxmltree parses the XML): the robot's links with their
//! inertial elements, and its joints. Only what the dynamics needs is read; `<visual>`,
//! `<collision>`, `<limit>`, `<transmission>`, `<gazebo>` and other elements are skipped. Every
//! mistake in the file is reported with its line and column.

use roxmltree::{Document, Node};

/// A mistake in the file, at a line and column (1-based) when one is known.
#[derive(Debug)]
pub struct ParseError {
    pub position: Option<(u32, u32)>,
    pub message: String,
}

/// A rigid transform as a URDF `<origin xyz=".." rpy=".."/>` writes it: translation, then the
/// roll-pitch-yaw rotation Rz(yaw)·Ry(pitch)·Rx(roll).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Origin {
    pub xyz: [f64; 3],
    pub rpy: [f64; 3],
}

/// A link's `<inertial>`: mass, and the inertia tensor about the centre of mass in the frame
/// `origin` (relative to the link's frame).
#[derive(Clone, Copy, Debug)]
pub struct Inertial {
    pub origin: Origin,
    pub mass: f64,
    /// ixx, ixy, ixz, iyy, iyz, izz.
    pub inertia: [f64; 6],
}

#[derive(Debug)]
pub struct Link {
    pub name: String,
    pub inertial: Option<Inertial>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JointType {
    Revolute,
    Continuous,
    Prismatic,
    Fixed,
    Floating,
    Planar,
}

#[derive(Debug)]
pub struct Joint {
    pub name: String,
    pub kind: JointType,
    pub parent: String,
    pub child: String,
    pub origin: Origin,
    /// The joint axis in the joint frame as the file writes it (URDF's default: x).
    pub axis: [f64; 3],
    /// `<dynamics damping=".." friction=".."/>`, zero when absent.
    pub damping: f64,
    pub friction: f64,
    /// Whether the joint has a `<mimic>` element.
    pub mimic: bool,
}

#[derive(Debug)]
pub struct Robot {
    pub links: Vec<Link>,
    pub joints: Vec<Joint>,
}

/// Reads a URDF document.
pub fn parse(text: &str) -> Result<Robot, ParseError> {
    let doc = Document::parse(text).map_err(|e| {
        let p = e.pos();
        let message = e.to_string();
        // roxmltree ends its message with the position, which the caller writes first.
        let suffix = format!(" at {}:{}", p.row, p.col);
        ParseError {
            position: Some((p.row, p.col)),
            message: message.strip_suffix(&suffix).unwrap_or(&message).to_owned(),
        }
    })?;
    let root = doc.root_element();
    if root.tag_name().name() != "robot" {
        return Err(at(root, "the root element is not `<robot>`"));
    }
    let mut links = Vec::new();
    let mut joints = Vec::new();
    for node in root.children().filter(Node::is_element) {
        match node.tag_name().name() {
            "link" => links.push(link(node)?),
            "joint" => joints.push(joint(node)?),
            _ => {}
        }
    }
    Ok(Robot { links, joints })
}

fn link(node: Node) -> Result<Link, ParseError> {
    let name = required(node, "name")?.to_owned();
    let inertial = match child(node, "inertial") {
        None => None,
        Some(i) => {
            let mass_node =
                child(i, "mass").ok_or_else(|| at(i, "`<inertial>` without `<mass>`"))?;
            let t = child(i, "inertia").ok_or_else(|| at(i, "`<inertial>` without `<inertia>`"))?;
            let mut inertia = [0.0; 6];
            for (k, attr) in ["ixx", "ixy", "ixz", "iyy", "iyz", "izz"]
                .iter()
                .enumerate()
            {
                inertia[k] = number(t, attr, required(t, attr)?)?;
            }
            Some(Inertial {
                origin: origin(i)?,
                mass: number(mass_node, "value", required(mass_node, "value")?)?,
                inertia,
            })
        }
    };
    Ok(Link { name, inertial })
}

fn joint(node: Node) -> Result<Joint, ParseError> {
    let name = required(node, "name")?.to_owned();
    let kind = match required(node, "type")? {
        "revolute" => JointType::Revolute,
        "continuous" => JointType::Continuous,
        "prismatic" => JointType::Prismatic,
        "fixed" => JointType::Fixed,
        "floating" => JointType::Floating,
        "planar" => JointType::Planar,
        other => {
            return Err(at(
                node,
                &format!("joint `{name}` has an unknown type `{other}`"),
            ))
        }
    };
    let link_of = |tag: &str| -> Result<String, ParseError> {
        let c = child(node, tag)
            .ok_or_else(|| at(node, &format!("joint `{name}` has no `<{tag}>`")))?;
        Ok(required(c, "link")?.to_owned())
    };
    let axis = match child(node, "axis") {
        Some(a) => triple(a, "xyz", required(a, "xyz")?)?,
        None => [1.0, 0.0, 0.0],
    };
    let (mut damping, mut friction) = (0.0, 0.0);
    if let Some(d) = child(node, "dynamics") {
        if let Some(v) = d.attribute("damping") {
            damping = number(d, "damping", v)?;
        }
        if let Some(v) = d.attribute("friction") {
            friction = number(d, "friction", v)?;
        }
    }
    Ok(Joint {
        parent: link_of("parent")?,
        child: link_of("child")?,
        origin: origin(node)?,
        axis,
        damping,
        friction,
        mimic: child(node, "mimic").is_some(),
        name,
        kind,
    })
}

/// The `<origin>` child of `node`, identity when absent (as URDF specifies).
fn origin(node: Node) -> Result<Origin, ParseError> {
    let Some(o) = child(node, "origin") else {
        return Ok(Origin::default());
    };
    let read = |attr: &str| match o.attribute(attr) {
        Some(v) => triple(o, attr, v),
        None => Ok([0.0; 3]),
    };
    Ok(Origin {
        xyz: read("xyz")?,
        rpy: read("rpy")?,
    })
}

fn child<'a, 'i>(node: Node<'a, 'i>, tag: &str) -> Option<Node<'a, 'i>> {
    node.children()
        .find(|c| c.is_element() && c.tag_name().name() == tag)
}

fn required<'a>(node: Node<'a, '_>, attr: &str) -> Result<&'a str, ParseError> {
    node.attribute(attr).ok_or_else(|| {
        at(
            node,
            &format!("`<{}>` has no `{attr}` attribute", node.tag_name().name()),
        )
    })
}

/// A finite number.
fn number(node: Node, attr: &str, text: &str) -> Result<f64, ParseError> {
    match text.trim().parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err(at(
            node,
            &format!(
                "`{attr}` of `<{}>` is not a finite number: `{text}`",
                node.tag_name().name()
            ),
        )),
    }
}

/// Three finite numbers separated by white space.
fn triple(node: Node, attr: &str, text: &str) -> Result<[f64; 3], ParseError> {
    let parts: Vec<&str> = text.split_whitespace().collect();
    if parts.len() != 3 {
        return Err(at(
            node,
            &format!(
                "`{attr}` of `<{}>` must be three numbers: `{text}`",
                node.tag_name().name()
            ),
        ));
    }
    let mut out = [0.0; 3];
    for (o, p) in out.iter_mut().zip(parts) {
        *o = number(node, attr, p)?;
    }
    Ok(out)
}

fn position(node: Node) -> (u32, u32) {
    let p = node.document().text_pos_at(node.range().start);
    (p.row, p.col)
}

fn at(node: Node, message: &str) -> ParseError {
    ParseError {
        position: Some(position(node)),
        message: message.to_owned(),
    }
}
