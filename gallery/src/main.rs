//! The gallery: every scene, simulated and printed against its closed form, with plots written to
//! `plots/` (or `$LAGRANGE_PLOTS`). Exits non-zero if any check fails.
//!
//! A binary of this crate rather than an example of `lagrange`, so that building it builds only
//! `lagrange` and its normal dependencies, not the root package's test and benchmark
//! dev-dependencies. The scenes and their checks are this crate's `lagrange_gallery::scenes` modules; the
//! `examples/` of `lagrange` tell the same stories as plain usage.
//!
//! ```text
//! cargo run --release -p lagrange-gallery
//! ```

use lagrange_gallery::scenes::*;
use lagrange_gallery::{plots_dir, table, Check};
use std::path::Path;

/// Every scene, in the order the README lists them.
pub const SCENES: &[fn(&Path) -> Vec<Check>] = &[
    wedge_block::run,
    ramp::run,
    breathing_ellipse::run,
    spinning_hoop::run,
    pendulum::run,
    double_pendulum::run,
    rigid_triangle::run,
    atwood::run,
    hoop_bifurcation::run,
    small_oscillations::run,
    sphere_release::run,
    rolling_wheel::run,
    four_bar::run,
    cartesian_pendulum::run,
    rough_ramp::run,
    rough_wedge::run,
    gyroscope::run,
    rough_plane::run,
    pushed_block::run,
    identify_pendulum::run,
    spatial_arm::run,
];

fn main() {
    let plots = plots_dir();
    let checks: Vec<Check> = SCENES.iter().flat_map(|run| run(&plots)).collect();
    println!();
    print!("{}", table(&checks));
    let failed = checks.iter().filter(|c| !c.passed()).count();
    println!(
        "\n{} checks, {} failed; plots in {}",
        checks.len(),
        failed,
        plots.display()
    );
    if failed > 0 {
        std::process::exit(1);
    }
}
