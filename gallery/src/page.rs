//! The gallery's page, `index.html` beside the plots: every scene's checks table, its animation
//! and its plots on one page, for a person to open after `cargo run --release -p lagrange-gallery`.
//!
//! A scene writes its plots (SVG) and its animation (a self-contained HTML page from
//! `lagrange::animation::Recorder`) into the plots folder; [`run_scene`] notes which files the
//! scene wrote, and [`write_index`] puts them on one page: the animation in a frame of the page,
//! the plots as images, the checks as a table. Nothing on it is fetched from a network.

use crate::Check;
use lagrange::animation::{escape_html, AnimationError, Drawable, Recorder};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// What one scene gave: its checks and the files it wrote.
#[derive(Clone, Debug)]
pub struct SceneOutput {
    /// The scene's name, as its checks give it.
    pub title: String,
    /// Its checks against closed forms.
    pub checks: Vec<Check>,
    /// The SVG plots it wrote, by file name, in name order.
    pub plots: Vec<String>,
    /// The animation page it wrote, by file name.
    pub animation: Option<String>,
}

/// Draws a fixed outline in `film` (a ramp, a patch of ground): the fixed points `name 1`,
/// `name 2`, … at `corners`, each joined to the next, the last to the first when `closed`.
pub fn outline<M: Drawable<N>, const N: usize>(
    film: &mut Recorder<M, N>,
    name: &str,
    corners: &[&[f64]],
    closed: bool,
) -> Result<(), AnimationError> {
    let names: Vec<String> = (1..=corners.len()).map(|k| format!("{name} {k}")).collect();
    for (corner, at) in names.iter().zip(corners) {
        film.fixed_point(corner, at)?;
    }
    for pair in names.windows(2) {
        film.link(&pair[0], &pair[1])?;
    }
    if closed && names.len() > 2 {
        film.link(&names[names.len() - 1], &names[0])?;
    }
    Ok(())
}

/// Every file in `dir` with its modification time.
fn listing(dir: &Path) -> HashMap<PathBuf, Option<SystemTime>> {
    std::fs::read_dir(dir)
        .into_iter()
        .flatten()
        .flatten()
        .map(|e| (e.path(), e.metadata().and_then(|m| m.modified()).ok()))
        .collect()
}

/// Runs `scene` with its plots going to `dir`, and notes the SVG and HTML files it wrote (new, or
/// modified during the run).
pub fn run_scene(dir: &Path, scene: fn(&Path) -> Vec<Check>) -> SceneOutput {
    let before = listing(dir);
    let checks = scene(dir);
    let mut written: Vec<String> = listing(dir)
        .into_iter()
        .filter(|(path, modified)| before.get(path) != Some(modified))
        .filter_map(|(path, _)| Some(path.file_name()?.to_str()?.to_string()))
        .collect();
    written.sort();
    let title = checks.first().map_or("scene", |c| c.scene).to_string();
    SceneOutput {
        title,
        checks,
        plots: written
            .iter()
            .filter(|f| f.ends_with(".svg"))
            .cloned()
            .collect(),
        animation: written.into_iter().find(|f| f.ends_with(".html")),
    }
}

/// The name a scene's section is found by (`#double_pendulum`): its animation's file stem, or its
/// title with every character that is not a letter or digit made `-`.
pub fn section_id(scene: &SceneOutput) -> String {
    match &scene.animation {
        Some(file) => file.trim_end_matches(".html").to_string(),
        None => scene
            .title
            .chars()
            .map(|c| if c.is_alphanumeric() { c } else { '-' })
            .collect(),
    }
}

const STYLE: &str = include_str!("page.css");
const SCRIPT: &str = include_str!("page.js");

/// Writes `index.html` into `dir` for `scenes`, and returns its path.
pub fn write_index(dir: &Path, scenes: &[SceneOutput]) -> std::io::Result<PathBuf> {
    let path = dir.join("index.html");
    std::fs::write(&path, index_html(scenes))?;
    Ok(path)
}

/// The page's HTML.
pub fn index_html(scenes: &[SceneOutput]) -> String {
    let checks: usize = scenes.iter().map(|s| s.checks.len()).sum();
    let failed: usize = scenes
        .iter()
        .flat_map(|s| &s.checks)
        .filter(|c| !c.passed())
        .count();
    let mut nav = String::new();
    for scene in scenes {
        let _ = writeln!(
            nav,
            "<a href=\"#{}\">{}</a>",
            escape_html(&section_id(scene)),
            escape_html(&scene.title)
        );
    }
    let sections: String = scenes.iter().map(section).collect();
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <title>lagrange gallery</title>\n<style>\n{STYLE}</style>\n</head>\n<body>\n<header>\n\
         <h1>lagrange gallery</h1>\n<p>Every scene declared with <code>#[mechanism]</code>, \
         simulated and compared with its closed form: {checks} checks, {failed} failed. Written by \
         <code>cargo run --release -p lagrange-gallery</code>.</p>\n<nav>\n{nav}</nav>\n</header>\n\
         <main>\n{sections}</main>\n<pre id=\"lagrange-probe\" hidden></pre>\n\
         <script>\n{SCRIPT}</script>\n</body>\n</html>\n"
    )
}

/// One scene: its heading, its animation beside its checks, its plots below.
fn section(scene: &SceneOutput) -> String {
    let id = escape_html(&section_id(scene));
    let title = escape_html(&scene.title);
    let animation = match &scene.animation {
        Some(file) => {
            let file = escape_html(file);
            format!(
                "<div class=\"animation\"><iframe src=\"{file}\" title=\"{title}: animation\" \
                 data-scene=\"{id}\"></iframe><a href=\"{file}\">open the animation alone</a></div>\n"
            )
        }
        None => "<div class=\"animation missing\">no animation</div>\n".to_string(),
    };
    let plots: String = scene
        .plots
        .iter()
        .map(|file| {
            let file = escape_html(file);
            format!("<a href=\"{file}\"><img src=\"{file}\" alt=\"{file}\"></a>\n")
        })
        .collect();
    format!(
        "<section id=\"{id}\">\n<h2>{title}</h2>\n<div class=\"row\">\n{animation}{}</div>\n\
         <div class=\"plots\">\n{plots}</div>\n</section>\n",
        checks_table(&scene.checks)
    )
}

/// The checks as a table: quantity, simulated, exact, relative error, tolerance, pass.
fn checks_table(checks: &[Check]) -> String {
    let mut rows = String::new();
    for c in checks {
        let (class, verdict) = match c.passed() {
            true => ("pass", "yes"),
            false => ("fail", "NO"),
        };
        let _ = writeln!(
            rows,
            "<tr class=\"{class}\"><td>{}</td><td>{:.10e}</td><td>{:.10e}</td><td>{:.2e}</td>\
             <td>{:.1e}</td><td>{verdict}</td></tr>",
            escape_html(&c.quantity),
            c.simulated,
            c.exact,
            c.relative_error(),
            c.tolerance
        );
    }
    format!(
        "<table class=\"checks\">\n<thead><tr><th>quantity</th><th>simulated</th><th>exact</th>\
         <th>rel. error</th><th>tolerance</th><th>pass</th></tr></thead>\n<tbody>\n{rows}</tbody>\n\
         </table>\n"
    )
}
