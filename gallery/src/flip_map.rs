//! The double pendulum's flip-time map — the mechanism, the grid, the sweep and the picture, shared
//! by the `flip_map` example and `tests/ensemble.rs`: released at rest from every (θ₁, θ₂) of a grid, how long
//! until either arm first flips over (|θ| passes π)? Neighbouring releases that never flip form
//! smooth regions; where the motion is chaotic, flip times change from one pixel to the next and
//! the picture looks fractal.
//!
//! Each trajectory is RK4 at h = 1e-3 with the flip detected between steps (so a flip time is
//! known to one step), stopped at the cap `t_max`; the grid runs as one [`ensemble`] sweep, once on
//! one thread and once on two, which must give the same map bit for bit. The scene prints the
//! throughput of each (trajectories per second) and the speed-up, and draws the map into
//! `plots/flip_map.svg` (or `$LAGRANGE_PLOTS`).
//!
//! A release whose energy is below the lowest configuration with an arm upright can never flip
//! ([`can_flip`]); those cells are still integrated, so that the throughput is that of the whole
//! grid and the picture shows what was simulated, not what was argued.

use lagrange::ensemble::{self, rayon, PartError, Parts, Sweep};
use lagrange::prelude::*;
use std::f64::consts::PI;
use std::ops::Range;
use std::path::Path;
use std::time::Instant;

#[mechanism]
pub mod double_pendulum {
    /// Generalized coordinates: one field per degree of freedom.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    /// Parameters, fixed for one simulation.
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

pub use double_pendulum::{Coords, DoublePendulum, State};

/// The RK4 step.
pub const H: f64 = 1e-3;
/// The default grid: `N` × `N` releases.
pub const N: usize = 64;
/// The default cap on simulated time, in seconds.
pub const T_MAX: f64 = 5.0;

/// Unit masses and lengths, g = 9.81, checked once.
pub fn pendulum() -> Validated<DoublePendulum> {
    DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    }
    .validated()
    .expect("valid parameters")
}

/// The initial angles along one axis: the centres of `n` equal cells across (−π, π), so no release
/// starts at an upright arm.
pub fn angles(n: usize) -> Vec<f64> {
    let half_cell = PI / n as f64;
    ensemble::linspace(-PI + half_cell, PI - half_cell, n)
}

/// Every release of an `n` × `n` map, θ₁ varying fastest: cell (i, j) is element `j * n + i`,
/// (θ₁, θ₂) = (`angles[i]`, `angles[j]`).
pub fn grid(n: usize) -> Vec<(f64, f64)> {
    let a = angles(n);
    ensemble::grid2(&a, &a)
}

/// Whether a release at rest from (θ₁, θ₂) has the energy to flip an arm at all.
///
/// With the pivot at the origin, V = −(m₁ + m₂) g l₁ cos θ₁ − m₂ g l₂ cos θ₂, and E = V at rest.
/// T ≥ 0 and E is conserved, so the motion stays where V ≤ E. Arm 1 upright (θ₁ = ±π) has
/// V ≥ (m₁ + m₂) g l₁ − m₂ g l₂ = a (least with arm 2 hanging, cos θ₂ = 1); arm 2 upright has
/// V ≥ −(m₁ + m₂) g l₁ + m₂ g l₂ = −a (least with arm 1 hanging). A flip therefore needs
/// E ≥ min(a, −a) = −|a|: for unit masses and lengths, E ≥ −m g l, i.e. 2 cos θ₁ + cos θ₂ ≤ 1.
pub fn can_flip(sys: &Validated<DoublePendulum>, theta1: f64, theta2: f64) -> bool {
    let p = sys.get();
    let a = (p.m1 + p.m2) * p.g * p.l1 - p.m2 * p.g * p.l2;
    let energy = sys
        .energy(&State::at_rest(Coords { theta1, theta2 }))
        .expect("finite state");
    energy >= -a.abs()
}

/// The time at which either arm of a release at rest from (θ₁, θ₂) first flips over — the end of
/// the first RK4 step of size `h` after which |θ₁| or |θ₂| exceeds π — or `None` if neither does
/// within `t_max`.
pub fn flip_time(
    sys: &Validated<DoublePendulum>,
    (theta1, theta2): (f64, f64),
    h: f64,
    t_max: f64,
) -> Result<Option<f64>, Error> {
    let mut s = State::at_rest(Coords { theta1, theta2 });
    let steps = (t_max / h).round() as usize;
    for _ in 0..steps {
        sys.step::<Rk4>(&mut s, h)?;
        if s.q.theta1.abs() > PI || s.q.theta2.abs() > PI {
            return Ok(Some(s.t));
        }
    }
    Ok(None)
}

/// The flip times of the releases `grid[range]` (one shard of the map, or all of it), in grid
/// order, on the current rayon pool.
pub fn flip_times(
    sys: &Validated<DoublePendulum>,
    grid: &[(f64, f64)],
    range: Range<usize>,
    t_max: f64,
    progress: bool,
) -> Result<Vec<Option<f64>>, Error> {
    Sweep::new(grid)
        .shard(range)
        .progress(progress)
        .run(|&release| flip_time(sys, release, H, t_max))
        .into_iter()
        .collect()
}

/// The flip time of one release for a sweep whose results are stored cells
/// ([`ensemble::Cells`]): [`flip_time`] at the map's step `H`. The parameters are validated and a
/// release at rest is finite, so an RK4 step of this smooth, bounded system cannot fail; if one
/// did, that would be a defect of the integrator, and it panics naming the release.
pub fn flip_cell(sys: &Validated<DoublePendulum>, release: (f64, f64), t_max: f64) -> Option<f64> {
    flip_time(sys, release, H, t_max)
        .unwrap_or_else(|e| panic!("RK4 failed from the release {release:?}: {e}"))
}

/// The map of an `n` × `n` grid capped at `t_max`, stored as `count` Parquet parts in `dir`
/// (`flip_map-part-I-of-K.parquet`): columns `theta1`, `theta2` (the release) and `flip_time`
/// (null for no flip), and metadata naming the mechanism, the integrator and its settings.
pub fn parts(dir: &Path, n: usize, t_max: f64, count: usize) -> Result<Parts, PartError> {
    Ok(Parts::new(dir, "flip_map", count)?
        .columns(&["theta1", "theta2"], &["flip_time"])
        .metadata(
            "mechanism",
            "double_pendulum: m1 = m2 = 1, l1 = l2 = 1, g = 9.81, released at rest",
        )
        .metadata("integrator", "Rk4")
        .metadata("h", H)
        .metadata("t_max", t_max)
        .metadata("grid", format!("{n}x{n}")))
}

/// The map of an `n` × `n` grid on a pool of `threads` threads, and the wall time it took.
pub fn timed_map(
    sys: &Validated<DoublePendulum>,
    n: usize,
    t_max: f64,
    threads: usize,
) -> (Vec<Option<f64>>, f64) {
    let grid = grid(n);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("thread pool");
    let start = Instant::now();
    let map = pool
        .install(|| flip_times(sys, &grid, 0..grid.len(), t_max, true))
        .expect("flip map");
    (map, start.elapsed().as_secs_f64())
}

/// Draws the map: θ₁ across, θ₂ up, colour the logarithm of the flip time, white for no flip
/// within `t_max`, with a colour bar.
pub fn draw(
    path: &Path,
    n: usize,
    t_max: f64,
    map: &[Option<f64>],
) -> Result<(), Box<dyn std::error::Error>> {
    use plotters::prelude::*;

    let t_min = map.iter().flatten().copied().fold(t_max, f64::min);
    let (lo, hi) = (t_min.log10(), t_max.log10().max(t_min.log10() + 1e-9));
    let colour = |t: f64| ramp((t.log10() - lo) / (hi - lo));
    let a = angles(n);
    let half = PI / n as f64;

    let root = SVGBackend::new(path, (760, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(640);

    let mut chart = ChartBuilder::on(&left)
        .caption(
            format!(
                "Double pendulum flip time, {n}×{n} releases at rest (white: none by {t_max} s)"
            ),
            ("sans-serif", 16),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(-PI..PI, -PI..PI)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .x_desc("θ₁ (rad)")
        .y_desc("θ₂ (rad)")
        .draw()?;
    chart.draw_series(map.iter().enumerate().filter_map(|(k, t)| {
        let (x, y) = (a[k % n], a[k / n]);
        t.map(|t| {
            Rectangle::new(
                [(x - half, y - half), (x + half, y + half)],
                colour(t).filled(),
            )
        })
    }))?;

    let mut bar = ChartBuilder::on(&right)
        .margin_top(40)
        .margin_bottom(50)
        .margin_right(10)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..1.0, lo..hi)?;
    bar.configure_mesh()
        .disable_mesh()
        .disable_x_axis()
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .y_desc("log₁₀ flip time (s)")
        .draw()?;
    let steps = 100;
    bar.draw_series((0..steps).map(|k| {
        let (y0, y1) = (
            lo + (hi - lo) * k as f64 / steps as f64,
            lo + (hi - lo) * (k + 1) as f64 / steps as f64,
        );
        Rectangle::new([(0.0, y0), (1.0, y1)], ramp((y0 - lo) / (hi - lo)).filled())
    }))?;
    root.present()?;
    Ok(())
}

/// A dark-blue to yellow colour ramp (close to viridis) at `u` ∈ [0, 1].
fn ramp(u: f64) -> plotters::style::RGBColor {
    const STOPS: [[f64; 3]; 5] = [
        [68.0, 1.0, 84.0],
        [59.0, 82.0, 139.0],
        [33.0, 145.0, 140.0],
        [94.0, 201.0, 98.0],
        [253.0, 231.0, 37.0],
    ];
    let x = u.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let k = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - k as f64;
    let c = |i: usize| (STOPS[k][i] + (STOPS[k + 1][i] - STOPS[k][i]) * f).round() as u8;
    plotters::style::RGBColor(c(0), c(1), c(2))
}
