//! The page: the player (`player.js`, written for this crate), its style sheet (`player.css`) and
//! the recording as JSON, in one HTML document that opens without a network.

use super::recorder::{position, Item, Recorder, Source};
use super::{Drawable, Shape};
use serde::Serialize;

const PLAYER: &str = include_str!("player.js");
const STYLE: &str = include_str!("player.css");

/// The recording as the player reads it.
#[derive(Serialize)]
struct Scene<'a> {
    title: &'a str,
    dim: usize,
    items: Vec<ItemData<'a>>,
    links: &'a [[usize; 2]],
    constraints: Vec<ConstraintData<'a>>,
    trails: &'a [usize],
    /// The simulated time a trail covers before the frame shown (`null`: all of it).
    trail_length: Option<f64>,
    /// The length of a rigid body's axes.
    axis: f64,
    /// The box the motion fills, axes included: lowest and highest x, y, z.
    extent: [[f64; 3]; 2],
    stride: usize,
    times: Vec<f64>,
    /// Every frame's values, rounded to `f32` (7 significant digits: far below a pixel).
    frames: Vec<f32>,
}

#[derive(Serialize)]
struct ItemData<'a> {
    name: &'a str,
    kind: &'static str,
    offset: usize,
    width: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    at: Option<[f64; 3]>,
}

#[derive(Serialize)]
struct ConstraintData<'a> {
    name: &'a str,
    items: &'a [usize],
}

fn kind(item: &Item) -> &'static str {
    match item.source {
        Source::Rows(_, Shape::Particle2 | Shape::Particle3) => "particle",
        Source::Rows(_, Shape::Point2 | Shape::Point3) => "point",
        Source::Rows(_, Shape::Planar) => "planar",
        Source::Rows(_, Shape::Spatial) => "spatial",
        Source::Mark { .. } => "mark",
        Source::Fixed(_) => "fixed",
    }
}

fn is_rigid(item: &Item) -> bool {
    matches!(item.source, Source::Rows(_, Shape::Planar | Shape::Spatial))
}

/// The lowest and highest coordinates of every item over every frame, and the axis length: the
/// one set, or a tenth of the box's largest side (1 when nothing moves away from one point). The
/// box is widened by the axis length where a rigid body is drawn, so its axes stay in view.
fn extent_and_axis<M: Drawable<N>, const N: usize>(r: &Recorder<M, N>) -> ([[f64; 3]; 2], f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for frame in r.every_frame() {
        for item in &r.items {
            let p = position(item, frame);
            for i in 0..3 {
                lo[i] = lo[i].min(p[i]);
                hi[i] = hi[i].max(p[i]);
            }
        }
    }
    let side = (0..r.dim).map(|i| hi[i] - lo[i]).fold(0.0, f64::max);
    let axis = r.axis.unwrap_or(if side > 0.0 { 0.1 * side } else { 1.0 });
    if r.items.iter().any(is_rigid) {
        for i in 0..r.dim {
            lo[i] -= axis;
            hi[i] += axis;
        }
    }
    ([lo, hi], axis)
}

/// The recording as JSON, safe inside a `<script>` element (no `<` is left in it).
fn scene_json<M: Drawable<N>, const N: usize>(r: &Recorder<M, N>) -> String {
    let (extent, axis) = extent_and_axis(r);
    let frames = r.every_frame().flatten().map(|&x| x as f32).collect();
    let scene = Scene {
        title: r.page_title(),
        dim: r.dim,
        items: r
            .items
            .iter()
            .map(|item| ItemData {
                name: &item.name,
                kind: kind(item),
                offset: item.offset,
                width: item.width,
                at: match item.source {
                    Source::Fixed(at) => Some(at),
                    _ => None,
                },
            })
            .collect(),
        links: &r.links,
        constraints: r
            .constraints
            .iter()
            .map(|(name, items)| ConstraintData { name, items })
            .collect(),
        trails: &r.trails,
        trail_length: r.trail_length,
        axis,
        extent,
        stride: r.stride,
        times: r.frame_times().to_vec(),
        frames,
    };
    serde_json::to_string(&scene)
        .expect("a recording of finite numbers and strings is valid JSON")
        .replace('<', "\\u003c")
}

/// `text` with the characters HTML gives a meaning (`&`, `<`, `>`, `"`) escaped: for a page that
/// shows a recording's title, or embeds animations beside other text.
pub fn escape_html(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The whole page.
pub(super) fn html<M: Drawable<N>, const N: usize>(r: &Recorder<M, N>) -> String {
    let title = escape_html(r.page_title());
    let data = scene_json(r);
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>{title}</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n\
         <main class=\"lagrange-page\">\n<h1>{title}</h1>\n<div id=\"lagrange-animation\"></div>\n\
         <pre id=\"lagrange-probe\" hidden></pre>\n</main>\n\
         <script id=\"lagrange-data\" type=\"application/json\">{data}</script>\n\
         <script>\n{PLAYER}</script>\n</body>\n</html>\n"
    )
}
