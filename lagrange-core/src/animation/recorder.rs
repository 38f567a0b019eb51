//! [`Recorder`]: states in, one frame kept per `1 / frame_rate` of simulated time, one HTML page
//! out.

use super::page;
use super::{Drawable, Shape};
use crate::model::{check_state, Coordinates, State};
use std::marker::PhantomData;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// What can go wrong while recording or writing an animation. The recorder is left as it was.
#[derive(Clone, Debug, thiserror::Error)]
#[non_exhaustive]
pub enum AnimationError {
    /// A state pushed was refused (not finite): the mechanism's own error.
    #[error(transparent)]
    State(#[from] crate::Error),
    /// A name given to [`Recorder::trail`], [`Recorder::link`] or [`Recorder::mark`] is no body,
    /// point, family member, mark or fixed point of the drawing.
    #[error("nothing drawn is named `{name}`; the names are {known}")]
    UnknownName {
        /// The name asked for.
        name: String,
        /// Every name that is drawn, comma-separated.
        known: String,
    },
    /// A name given to [`Recorder::mark`] or [`Recorder::fixed_point`] is taken already.
    #[error("`{name}` is drawn already: a mark or fixed point needs a name of its own")]
    DuplicateName {
        /// The name.
        name: String,
    },
    /// [`Recorder::mark`] on a mark or a fixed point.
    #[error("`{name}` is not a body: a point is marked on a body, point or family member")]
    NotABody {
        /// The name given.
        name: String,
    },
    /// Coordinates of the wrong length or not finite.
    #[error("{what}: {reason}")]
    InvalidCoordinates {
        /// What they are for (`fixed point \`pivot\``).
        what: String,
        /// What is wrong with them.
        reason: String,
    },
    /// A frame rate or an axis length that is not positive and finite.
    #[error("{setting} must be positive and finite, got {value}")]
    InvalidSetting {
        /// The setting.
        setting: &'static str,
        /// The value given.
        value: f64,
    },
    /// [`Recorder::mark`] after the first state: the frames before it would lack the mark.
    #[error("points are marked before the first state is pushed")]
    AlreadyRecording,
    /// A state earlier than the last one pushed.
    #[error("state at t = {t} is earlier than the last one pushed, at t = {last}")]
    TimeGoesBack {
        /// The state's time.
        t: f64,
        /// The last time pushed.
        last: f64,
    },
    /// A finite state placed a body at a non-finite position.
    #[error("`{name}` is not finite at t = {t}")]
    NonFinitePosition {
        /// The body, member or mark.
        name: String,
        /// The state's time.
        t: f64,
    },
    /// Nothing to write: no state was pushed.
    #[error("no state was pushed: there is nothing to animate")]
    Empty,
    /// The page could not be written.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// Why.
        source: Arc<std::io::Error>,
    },
}

type Result<T> = std::result::Result<T, AnimationError>;

/// Where an item's values in a frame come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Source {
    /// A body or family member: its rows of x, from this one.
    Rows(usize, Shape),
    /// A point carried by the body drawn as item `on` (of `shape`), at `offset` in its frame.
    Mark {
        on: usize,
        offset: [f64; 3],
        shape: Shape,
    },
    /// A point fixed in the world.
    Fixed([f64; 3]),
}

/// One thing drawn: a body, a family member (`bob[2]`), a marked point or a fixed point.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Item {
    pub name: String,
    pub source: Source,
    /// Its first value in a frame.
    pub offset: usize,
    /// Its values per frame: a position (2 or 3), a planar body's position and angle (3), a
    /// spatial body's position and rotation columns (12); none for a fixed point.
    pub width: usize,
}

/// Records a trajectory of a declared mechanism and writes it as a self-contained HTML animation
/// (see the [module documentation](super) for an example).
///
/// Feed it every state of a simulation — [`push`](Self::push) in a loop, or
/// [`observer`](Self::observer) as a simulation's observer — and it keeps the first state, then
/// the first state at or after each multiple of `1 / frame_rate` from it: a long run at a small
/// step stays a few frames per second of simulated time, and a state that is not kept costs a
/// finiteness check. [`push_frame`](Self::push_frame) keeps a state whatever its time (the end of
/// a run, an event). Every
/// body and point of the declaration is drawn; [`trail`](Self::trail) adds the path of a point,
/// [`mark`](Self::mark) a point fixed in a rigid body, [`fixed_point`](Self::fixed_point) and
/// [`link`](Self::link) what the declaration does not name (a pivot, the line from it to a bob).
pub struct Recorder<M, const N: usize> {
    title: String,
    pub(super) dim: usize,
    pub(super) items: Vec<Item>,
    pub(super) links: Vec<[usize; 2]>,
    pub(super) constraints: Vec<(&'static str, Vec<usize>)>,
    pub(super) trails: Vec<usize>,
    pub(super) axis: Option<f64>,
    pub(super) trail_length: Option<f64>,
    pub(super) stride: usize,
    interval: f64,
    /// Kept frames: their times, and `stride` values each.
    pub(super) times: Vec<f64>,
    pub(super) values: Vec<f64>,
    /// The time of the first frame, of the next one due, and of the last state pushed.
    start: Option<f64>,
    next_due: f64,
    last: Option<f64>,
    /// Scratch: x at the state being pushed, and its frame values.
    rows: Vec<f64>,
    scratch: Vec<f64>,
    /// The first error met by [`observer`](Self::observer).
    deferred: Option<AnimationError>,
    mechanism: PhantomData<fn(&M)>,
}

impl<M: Drawable<N>, const N: usize> Recorder<M, N> {
    /// A recorder for `sys`'s declaration, at 30 frames per second, titled with the parameter
    /// struct's name. `sys` is the mechanism (or its [`Validated`](crate::Validated) handle) the
    /// states will come from.
    pub fn new(sys: &M) -> Self {
        let _ = sys;
        let type_name = std::any::type_name::<M>();
        let title = type_name
            .trim_end_matches('>')
            .rsplit("::")
            .next()
            .unwrap_or(type_name);
        let mut recorder = Recorder {
            title: title.to_string(),
            dim: 2,
            items: Vec::new(),
            links: Vec::new(),
            constraints: Vec::new(),
            trails: Vec::new(),
            axis: None,
            trail_length: None,
            stride: 0,
            interval: 1.0 / 30.0,
            times: Vec::new(),
            values: Vec::new(),
            start: None,
            next_due: 0.0,
            last: None,
            rows: Vec::new(),
            scratch: Vec::new(),
            deferred: None,
            mechanism: PhantomData,
        };
        recorder.lay_out_declaration();
        recorder
    }

    /// One item per body and family member, then the declaration's links and constraint bodies.
    fn lay_out_declaration(&mut self) {
        let mut first_item = Vec::with_capacity(M::BODIES.len());
        for body in M::BODIES {
            first_item.push(self.items.len());
            for member in 0..body.members() {
                let name = match body.count {
                    Some(_) => format!("{}[{member}]", body.name),
                    None => body.name.to_string(),
                };
                let row = body.row + member * body.shape.rows();
                self.add_item(name, Source::Rows(row, body.shape), body.shape.rows());
            }
            self.dim = self.dim.max(body.shape.dim());
        }
        let item = |r: &super::BodyRef| first_item[r.body] + r.member;
        self.links = M::LINKS
            .iter()
            .map(|l| [item(&l.from), item(&l.to)])
            .collect();
        self.constraints = M::CONSTRAINT_BODIES
            .iter()
            .map(|c| (c.name, c.bodies.iter().map(item).collect()))
            .collect();
    }

    fn add_item(&mut self, name: String, source: Source, width: usize) -> usize {
        self.items.push(Item {
            name,
            source,
            offset: self.stride,
            width,
        });
        self.stride += width;
        self.items.len() - 1
    }

    /// The page's title (the parameter struct's name by default).
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = title.into();
        self
    }

    /// Frames kept per second of simulated time (30 by default). Playback at speed 1 shows one
    /// second of simulated time per second.
    ///
    /// Errors: a rate that is not positive and finite ([`AnimationError::InvalidSetting`]).
    pub fn frame_rate(mut self, frames_per_second: f64) -> Result<Self> {
        self.interval = 1.0 / positive("frame rate", frames_per_second)?;
        Ok(self)
    }

    /// The length of the axes drawn on rigid bodies, in the mechanism's units (by default a tenth
    /// of the largest side of the box the motion fills).
    ///
    /// Errors: a length that is not positive and finite ([`AnimationError::InvalidSetting`]).
    pub fn axis_length(mut self, length: f64) -> Result<Self> {
        self.axis = Some(positive("axis length", length)?);
        Ok(self)
    }

    /// How much of each trail is drawn: the path over the last `seconds` of simulated time before
    /// the frame shown (by default the whole path from the first frame).
    ///
    /// Errors: a duration that is not positive and finite ([`AnimationError::InvalidSetting`]).
    pub fn trail_length(mut self, seconds: f64) -> Result<Self> {
        self.trail_length = Some(positive("trail length", seconds)?);
        Ok(self)
    }

    /// Draws the path of `name` (a body, a family member `bob[2]`, a mark or a fixed point) up to
    /// the frame shown.
    ///
    /// Errors: no such name ([`AnimationError::UnknownName`]).
    pub fn trail(&mut self, name: &str) -> Result<&mut Self> {
        let item = self.item(name)?;
        if !self.trails.contains(&item) {
            self.trails.push(item);
        }
        Ok(self)
    }

    /// Draws a line between `a` and `b` (bodies, members, marks or fixed points), beyond the
    /// links the declaration states.
    ///
    /// Errors: no such name ([`AnimationError::UnknownName`]).
    pub fn link(&mut self, a: &str, b: &str) -> Result<&mut Self> {
        let link = [self.item(a)?, self.item(b)?];
        if !self.links.contains(&link) {
            self.links.push(link);
        }
        Ok(self)
    }

    /// A point fixed in the world (a pivot), drawn as a small square: `at` has 2 coordinates for a
    /// planar mechanism, 3 for a spatial one.
    ///
    /// Errors: a name taken ([`AnimationError::DuplicateName`]), coordinates of the wrong length
    /// or not finite ([`AnimationError::InvalidCoordinates`]).
    pub fn fixed_point(&mut self, name: &str, at: &[f64]) -> Result<&mut Self> {
        self.check_new_name(name)?;
        let at = coordinates(&format!("fixed point `{name}`"), at, self.dim)?;
        self.add_item(name.to_string(), Source::Fixed(at), 0);
        Ok(self)
    }

    /// A point carried by a body (a rod's end, a point on a wheel's rim, a corner of a block) at
    /// `offset` in the body's frame: turned with a `Planar` or `Spatial` body, only moved with a
    /// particle or point. The offset has the body's dimension (2 or 3 coordinates). It is drawn as
    /// a small dot with a line to the body, and can be given a [`trail`](Self::trail) or
    /// [`link`](Self::link)s (the outline of a wedge drawn as a particle).
    ///
    /// Errors: `on` names no body or family member ([`AnimationError::UnknownName`],
    /// [`AnimationError::NotABody`]), a name taken ([`AnimationError::DuplicateName`]), an offset
    /// of the wrong length or not finite ([`AnimationError::InvalidCoordinates`]), a state pushed
    /// already ([`AnimationError::AlreadyRecording`]).
    pub fn mark(&mut self, name: &str, on: &str, offset: &[f64]) -> Result<&mut Self> {
        let body = self.item(on)?;
        let Source::Rows(_, shape) = self.items[body].source else {
            return Err(AnimationError::NotABody { name: on.into() });
        };
        self.check_new_name(name)?;
        let offset = coordinates(&format!("mark `{name}` on `{on}`"), offset, shape.dim())?;
        if self.start.is_some() {
            return Err(AnimationError::AlreadyRecording);
        }
        let source = Source::Mark {
            on: body,
            offset,
            shape,
        };
        let mark = self.add_item(name.to_string(), source, shape.dim());
        self.links.push([mark, body]);
        Ok(self)
    }

    fn item(&self, name: &str) -> Result<usize> {
        self.items
            .iter()
            .position(|i| i.name == name)
            .ok_or_else(|| AnimationError::UnknownName {
                name: name.into(),
                known: self.names(),
            })
    }

    fn names(&self) -> String {
        let names: Vec<&str> = self.items.iter().map(|i| i.name.as_str()).collect();
        names.join(", ")
    }

    fn check_new_name(&self, name: &str) -> Result<()> {
        match self.items.iter().any(|i| i.name == name) {
            true => Err(AnimationError::DuplicateName { name: name.into() }),
            false => Ok(()),
        }
    }

    /// Records `state` of `sys`: kept as a frame when it is the first state pushed or a frame is
    /// due, otherwise only checked and its time noted.
    ///
    /// Errors: a state that is not finite ([`AnimationError::State`]), earlier than the last one
    /// pushed ([`AnimationError::TimeGoesBack`]), or, kept, placing a body at a non-finite
    /// position ([`AnimationError::NonFinitePosition`]). The recorder is unchanged on error.
    pub fn push(&mut self, sys: &M, state: &State<M::Coords>) -> Result<()> {
        let q = self.check(state)?;
        let due = self.times.is_empty() || state.t >= self.next_due - 1e-9 * self.interval;
        if due {
            self.keep(sys, state.t, &q)?;
        }
        self.last = Some(state.t);
        Ok(())
    }

    /// Records `state` of `sys` as a frame whatever its time (unless it is the last frame kept
    /// already): the last state of a run, or an event, shown as it is.
    ///
    /// Errors: those of [`push`](Self::push).
    pub fn push_frame(&mut self, sys: &M, state: &State<M::Coords>) -> Result<()> {
        let q = self.check(state)?;
        if self.times.last() != Some(&state.t) {
            self.keep(sys, state.t, &q)?;
        }
        self.last = Some(state.t);
        Ok(())
    }

    /// `state`'s coordinates, when it is finite and not earlier than the last state pushed.
    fn check(&self, state: &State<M::Coords>) -> Result<[f64; N]> {
        let (t, q, v) = (state.t, state.q.to_array(), state.v.to_array());
        check_state(&<M::Coords as Coordinates<N>>::NAMES, t, &q, &v)?;
        match self.last {
            Some(last) if t < last => Err(AnimationError::TimeGoesBack { t, last }),
            _ => Ok(q),
        }
    }

    /// Keeps the state at (t, q) as a frame, and sets the next one due at the first multiple of
    /// `1 / frame_rate` from the first frame after t.
    fn keep(&mut self, sys: &M, t: f64, q: &[f64; N]) -> Result<()> {
        sys.cartesian_rows(t, q, &mut self.rows);
        frame_values(&self.items, &self.rows, &mut self.scratch);
        if let Some(bad) = self.items.iter().find(|i| {
            let values = &self.scratch[i.offset..i.offset + i.width];
            values.iter().any(|x| !x.is_finite())
        }) {
            let name = bad.name.clone();
            return Err(AnimationError::NonFinitePosition { name, t });
        }
        let t0 = *self.start.get_or_insert(t);
        let k = ((t - t0) / self.interval + 1e-9).floor();
        self.next_due = t0 + (k + 1.0) * self.interval;
        self.times.push(t);
        self.values.extend_from_slice(&self.scratch);
        Ok(())
    }

    /// [`push`](Self::push) as a simulation's observer:
    /// `sys.simulate::<Rk4>(&mut s, h, steps, recorder.observer(&sys))`. The first error stops
    /// the recording and is returned by [`html`](Self::html) and [`write_html`](Self::write_html).
    pub fn observer<'r>(&'r mut self, sys: &'r M) -> impl FnMut(&State<M::Coords>) + 'r {
        move |state| {
            if self.deferred.is_none() {
                if let Err(e) = self.push(sys, state) {
                    self.deferred = Some(e);
                }
            }
        }
    }

    /// The frames kept: what the page shows.
    pub fn frames(&self) -> usize {
        self.times.len()
    }

    /// The time of every frame kept.
    pub fn frame_times(&self) -> &[f64] {
        &self.times
    }

    /// Where `name` (a body, member, mark or fixed point) is in `frame`: its position, with z = 0
    /// in a planar mechanism. `None` for an unknown name or frame.
    pub fn position(&self, name: &str, frame: usize) -> Option<[f64; 3]> {
        let item = self.items.get(self.item(name).ok()?)?;
        Some(position(item, self.frame(frame)?))
    }

    /// The values of `frame`.
    pub(super) fn frame(&self, frame: usize) -> Option<&[f64]> {
        self.values
            .get(frame * self.stride..(frame + 1) * self.stride)
            .filter(|_| frame < self.times.len())
    }

    /// Every frame's values, in order.
    pub(super) fn every_frame(&self) -> impl Iterator<Item = &[f64]> {
        (0..self.frames()).filter_map(|k| self.frame(k))
    }

    /// The page's title.
    pub(super) fn page_title(&self) -> &str {
        &self.title
    }

    /// The whole page: the player, the drawing's layout and every frame, in one HTML document.
    ///
    /// Errors: the first error the [`observer`](Self::observer) met, or no state pushed
    /// ([`AnimationError::Empty`]).
    pub fn html(&self) -> Result<String> {
        if let Some(e) = &self.deferred {
            return Err(e.clone());
        }
        if self.times.is_empty() {
            return Err(AnimationError::Empty);
        }
        Ok(page::html(self))
    }

    /// Writes [`html`](Self::html) to `path`.
    ///
    /// Errors: those of [`html`](Self::html), and a file that cannot be written
    /// ([`AnimationError::Io`]).
    pub fn write_html(&self, path: impl AsRef<Path>) -> Result<()> {
        let path = path.as_ref();
        let html = self.html()?;
        std::fs::write(path, html).map_err(|source| AnimationError::Io {
            path: path.to_path_buf(),
            source: Arc::new(source),
        })
    }
}

fn positive(setting: &'static str, value: f64) -> Result<f64> {
    match value.is_finite() && value > 0.0 {
        true => Ok(value),
        false => Err(AnimationError::InvalidSetting { setting, value }),
    }
}

/// `values` as a point of the drawing's space (z = 0 for a planar one).
fn coordinates(what: &str, values: &[f64], dim: usize) -> Result<[f64; 3]> {
    let invalid = |reason: String| AnimationError::InvalidCoordinates {
        what: what.to_string(),
        reason,
    };
    if values.len() != dim {
        return Err(invalid(format!(
            "{} coordinates given, {dim} expected",
            values.len()
        )));
    }
    if let Some(x) = values.iter().find(|x| !x.is_finite()) {
        return Err(invalid(format!("{x} is not finite")));
    }
    let mut point = [0.0; 3];
    point[..dim].copy_from_slice(values);
    Ok(point)
}

/// One frame's values from x: each item's rows as they are; a mark at its body's position plus
/// the offset turned by the body's orientation (R(θ) o in the plane, R o in space).
fn frame_values(items: &[Item], rows: &[f64], out: &mut Vec<f64>) {
    out.clear();
    for item in items {
        match item.source {
            Source::Rows(row, shape) => out.extend_from_slice(&rows[row..row + shape.rows()]),
            Source::Mark { on, offset, shape } => {
                let body = &out[items[on].offset..items[on].offset + items[on].width];
                let p = mark_position(shape, body, &offset);
                out.extend_from_slice(&p[..item.width]);
            }
            Source::Fixed(_) => {}
        }
    }
}

/// A point at `offset` in the frame of a body of `shape` whose values are `body`: p + R(θ) o in
/// the plane (values x, y, θ), p + R o in space (values p, then the columns of R), p + o for a
/// particle or point.
fn mark_position(shape: Shape, body: &[f64], offset: &[f64; 3]) -> [f64; 3] {
    match shape {
        Shape::Planar => {
            let (sin, cos) = body[2].sin_cos();
            [
                body[0] + cos * offset[0] - sin * offset[1],
                body[1] + sin * offset[0] + cos * offset[1],
                0.0,
            ]
        }
        Shape::Spatial => std::array::from_fn(|r| {
            body[r] + (0..3).map(|k| body[3 + 3 * k + r] * offset[k]).sum::<f64>()
        }),
        _ => std::array::from_fn(|r| body.get(r).copied().unwrap_or(0.0) + offset[r]),
    }
}

/// An item's position in a frame (z = 0 in the plane).
pub(super) fn position(item: &Item, frame: &[f64]) -> [f64; 3] {
    if let Source::Fixed(at) = item.source {
        return at;
    }
    let values = &frame[item.offset..item.offset + item.width];
    let dim = match item.source {
        Source::Rows(_, shape) => shape.dim(),
        _ => item.width,
    };
    let mut p = [0.0; 3];
    p[..dim].copy_from_slice(&values[..dim]);
    p
}
