//! The gallery: every scene, simulated and printed against its closed form, with plots and
//! animations written to `plots/` (or `$LAGRANGE_PLOTS`) and all of it on one page,
//! `plots/index.html`. Exits non-zero if any check fails.
//!
//! A binary of this crate rather than an example of `lagrange`, so that building it builds only
//! `lagrange` and its normal dependencies, not the root package's test and benchmark
//! dev-dependencies. The scenes and their checks are this crate's `lagrange_gallery::scenes` modules; the
//! `examples/` of `lagrange` tell the same stories as plain usage.
//!
//! ```text
//! cargo run --release -p lagrange-gallery
//! ```

use lagrange_gallery::page::{run_scene, write_index, SceneOutput};
use lagrange_gallery::{plots_dir, table, Check, LONG_RUNS, SCENES};

fn main() {
    let plots = plots_dir();
    let mut scenes: Vec<SceneOutput> = SCENES.iter().map(|run| run_scene(&plots, *run)).collect();
    // The long runs last, so that the scenes' results come first.
    scenes.extend(LONG_RUNS.iter().map(|run| run_scene(&plots, *run)));
    let checks: Vec<Check> = scenes.iter().flat_map(|s| s.checks.clone()).collect();
    println!();
    print!("{}", table(&checks));
    let failed = checks.iter().filter(|c| !c.passed()).count();
    println!(
        "\n{} checks, {} failed; plots in {}",
        checks.len(),
        failed,
        plots.display()
    );
    match write_index(&plots, &scenes) {
        Ok(page) => println!("the page: {}", page.display()),
        Err(e) => eprintln!("cannot write the page: {e}"),
    }
    if failed > 0 {
        std::process::exit(1);
    }
}
