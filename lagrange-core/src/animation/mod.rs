//! See it move: a trajectory of any declared mechanism as a self-contained HTML animation.
//!
//! A [`Recorder`] is fed states, in a loop or as a simulation's observer, keeps one frame per
//! `1 / frame_rate` of simulated time (so a long run stays small), and writes one HTML file
//! ([`Recorder::write_html`]) that needs nothing else: the player is JavaScript written in this
//! crate and the trajectory is embedded in the page as data. It draws what the declaration states:
//! particles and points as dots, planar and spatial rigid bodies with their frames (the body's axes
//! at its centre of mass, or, for a body declared by its frame, at that frame's origin), a line from each body to the bodies its position function names
//! ([`Drawable::LINKS`]), rings on the bodies each constraint row names, and the paths of chosen
//! points ([`Recorder::trail`]). A planar mechanism is drawn in its plane; a spatial one with a
//! camera turned by dragging the mouse and zoomed with the wheel. Play/pause, a time slider and the
//! playback speed are below the picture.
//!
//! A pendulum, written by hand here (a `#[mechanism]` declaration gets the same impls, its
//! [`Drawable`] impl included; the crate's README records one), swung for two seconds:
//!
//! ```
//! use lagrange_core::animation::{BodyLayout, ConstraintLayout, Drawable, Link, Recorder, Shape};
//! use lagrange_core::{impl_mechanism, vec2, Mechanism, Model, Rk4, Scalar, State};
//!
//! struct Pendulum {
//!     g: f64,
//! }
//!
//! impl Model<1, 2> for Pendulum {
//!     type Coords = [f64; 1];
//!     const RHEONOMIC: bool = false;
//!     const HAS_POTENTIAL: bool = true;
//!     const HAS_FORCES: bool = false;
//!     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
//!     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
//!     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
//!         vec2(q[0].sin(), -q[0].cos()).to_array()
//!     }
//!     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * self.g }
//! }
//! impl_mechanism!(Pendulum, 1, 2);
//!
//! impl Drawable<1> for Pendulum {
//!     const BODIES: &'static [BodyLayout] =
//!         &[BodyLayout { name: "bob", shape: Shape::Particle2, count: None, row: 0 }];
//!     const LINKS: &'static [Link] = &[];
//!     const CONSTRAINT_BODIES: &'static [ConstraintLayout] = &[];
//!     fn cartesian_rows(&self, t: f64, q: &[f64; 1], rows: &mut Vec<f64>) {
//!         rows.clear();
//!         rows.extend_from_slice(&self.cartesian(t, q));
//!     }
//! }
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let sys = Pendulum { g: 9.81 }.validated()?;
//! let mut s = State::at_rest([1.0]);
//! let mut recorder = Recorder::new(&sys).title("Pendulum").frame_rate(25.0)?;
//! recorder.fixed_point("pivot", &[0.0, 0.0])?.link("pivot", "bob")?.trail("bob")?;
//! recorder.push(&sys, &s)?;
//! // Two seconds at h = 1 ms: 2000 states pushed, a frame kept every 40 ms.
//! sys.simulate::<Rk4>(&mut s, 1e-3, 2000, recorder.observer(&sys))?;
//! assert_eq!(recorder.frames(), 51);
//! let dir = std::env::temp_dir().join("lagrange-animation-doc");
//! std::fs::create_dir_all(&dir)?;
//! recorder.write_html(dir.join("pendulum.html"))?;
//! # Ok(())
//! # }
//! ```

mod page;
mod recorder;

pub use page::escape_html;
pub use recorder::{AnimationError, Recorder};

use crate::evaluation::{Dynamics, Evaluate};
use crate::validated::Validated;

/// What a body or point of a declaration is, as it is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// A particle in the plane (`Vec2`): a dot.
    Particle2,
    /// A particle in space (`Vec3`): a dot.
    Particle3,
    /// A massless point in the plane: a small hollow dot.
    Point2,
    /// A massless point in space: a small hollow dot.
    Point3,
    /// A planar rigid body (`Planar`): its pose's origin (the centre of mass, or the origin of
    /// the frame it is declared by) and its two axes.
    Planar,
    /// A spatial rigid body (`Spatial`): its pose's origin (the centre of mass, or the origin of
    /// the frame it is declared by) and its three axes.
    Spatial,
}

impl Shape {
    /// Rows of the Cartesian coordinates x one body (one family member) of this shape occupies:
    /// the position, then a planar body's angle or a spatial body's rotation, column by column.
    pub const fn rows(self) -> usize {
        match self {
            Shape::Particle2 | Shape::Point2 => 2,
            Shape::Particle3 | Shape::Point3 | Shape::Planar => 3,
            Shape::Spatial => 12,
        }
    }

    /// The dimension of the space it moves in: 2 or 3.
    pub const fn dim(self) -> usize {
        match self {
            Shape::Particle2 | Shape::Point2 | Shape::Planar => 2,
            Shape::Particle3 | Shape::Point3 | Shape::Spatial => 3,
        }
    }
}

/// A body or point of a declaration, where its rows are in x (see [`crate::Model::cartesian`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BodyLayout {
    /// The declared name (`bob1`).
    pub name: &'static str,
    /// What it is.
    pub shape: Shape,
    /// A family's number of members (`count = LINKS`); `None` for a single body.
    pub count: Option<usize>,
    /// Its first row in x; member k of a family starts `k * shape.rows()` later.
    pub row: usize,
}

impl BodyLayout {
    /// Members: 1, or the family's count.
    pub const fn members(&self) -> usize {
        match self.count {
            Some(n) => n,
            None => 1,
        }
    }
}

/// One body, or one member of a family: an index into [`Drawable::BODIES`] and the member (0 for
/// a single body).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BodyRef {
    /// Index into [`Drawable::BODIES`].
    pub body: usize,
    /// The family member (0 for a single body).
    pub member: usize,
}

/// A line drawn between two bodies: `from`'s position function names `to`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Link {
    /// The body whose declaration names the other.
    pub from: BodyRef,
    /// The body it names.
    pub to: BodyRef,
}

/// A constraint row (`#[constraint]`, `#[unilateral]`, `#[velocity_constraint]`, `#[friction]`)
/// and the bodies and points its function names: where it acts, marked with a ring.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ConstraintLayout {
    /// The declared name.
    pub name: &'static str,
    /// The bodies and points it names (every member of a family named whole).
    pub bodies: &'static [BodyRef],
}

/// What a declaration looks like: its bodies and points, the links its declaration states and
/// where its constraints act, and the rows of x that place them. `#[mechanism]` implements it
/// for every parameter struct (and [`Validated`] forwards it), so a [`Recorder`] can draw any
/// declared mechanism.
pub trait Drawable<const N: usize>: Evaluate<N> {
    /// Every body and point, in declaration order.
    const BODIES: &'static [BodyLayout];
    /// A link from each body (each member of a family) to each earlier body its position function
    /// names: `bob2` written as `bob1 + …` is linked to `bob1`; member i of a family written as
    /// `bob[i - 1] + …` to member i − 1. A family member named at an index the macro cannot
    /// evaluate is not linked.
    const LINKS: &'static [Link];
    /// Each constraint row with the bodies and points it names, in declaration order.
    const CONSTRAINT_BODIES: &'static [ConstraintLayout];

    /// Every body's pose at (t, q) into `rows` (cleared first), laid out as x's rows
    /// ([`BodyLayout::row`]): the pose as the declaration names it — x itself, except that a
    /// body declared by its frame (`#[rigid_body(com = ..)]`, or a full inertia tensor) gives
    /// that frame, not its centre of mass and principal axes. A recorder reuses one buffer, so a
    /// push allocates nothing.
    fn cartesian_rows(&self, t: f64, q: &[f64; N], rows: &mut Vec<f64>);
}

impl<M: Drawable<N> + Dynamics<N>, const N: usize> Drawable<N> for Validated<M> {
    const BODIES: &'static [BodyLayout] = M::BODIES;
    const LINKS: &'static [Link] = M::LINKS;
    const CONSTRAINT_BODIES: &'static [ConstraintLayout] = M::CONSTRAINT_BODIES;

    fn cartesian_rows(&self, t: f64, q: &[f64; N], rows: &mut Vec<f64>) {
        self.get().cartesian_rows(t, q, rows)
    }
}
