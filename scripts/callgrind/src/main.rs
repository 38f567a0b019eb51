//! Driver for callgrind: `lagrange-callgrind MODE [CALLS]` runs one mode CALLS times (1000 if
//! omitted) and prints a number its loop computed (a sum of results, or the state at the end), so
//! that the work is not optimised away. The modes (the table `MODES`; an unknown MODE lists them):
//!
//! - `accelerations` of a generated mechanism (`pendulum`, `four_bar`, `chainN_links`, …) on its
//!   parameters; `validated_NAME` through a validated handle; `hot_NAME` the hook integrators call
//!   on that handle (`accelerations_at`);
//! - `hw_NAME` (and `assembled_wedge_block`), the hand-written closed form of the same mechanism;
//! - `project_cartesian_pendulum` (`validated_project_…` through the handle): the projection after
//!   a step, from a state off the circle by a step's drift;
//! - steps of the integrators, one per call (`rk4_…`, `midpoint_…`, `gl2_…`, `sensitivity_…`,
//!   `dopri5_…`, `hw_rk4_double_pendulum`), on the double pendulum, Andrews' squeezer and a block
//!   in frictional contact;
//! - `none`, the start-up alone; `check`, the cart pendulum's q̈ generated and by hand, printed.
//!
//! See count.sh: instructions per call, the difference of two runs divided by that of their CALLS.

mod calls;
mod mechanisms;
mod modes;

use calls::Via;
use modes::{accelerations, arms, chains, closed_forms, constrained, contacts, squeezer, steps};
use Run::{Fixed, Generated};

/// What a mode runs, given the number of calls: it returns the number `main` prints.
#[derive(Clone, Copy)]
enum Run {
    /// On a generated mechanism, along the path the name's prefix picks (see `Via`).
    Generated(fn(usize, Via) -> f64),
    /// On its own path: a `validated_` or `hot_` prefix is read off the name and not used.
    Fixed(fn(usize) -> f64),
}

/// Every mode, by topic, one a row.
#[rustfmt::skip]
const MODES: &[(&str, Run)] = &[
    // `accelerations` of the generated mechanisms, and their closed forms by hand.
    ("pendulum", Generated(accelerations::pendulum)),
    ("hw_pendulum", Fixed(closed_forms::hw_pendulum)),
    ("double_pendulum", Generated(accelerations::double_pendulum)),
    ("hw_double_pendulum", Fixed(closed_forms::hw_double_pendulum)),
    ("wedge_block", Generated(accelerations::wedge_block)),
    ("hw_wedge_block", Fixed(closed_forms::hw_wedge_block)),
    ("assembled_wedge_block", Fixed(closed_forms::assembled_wedge_block)),
    ("cart_pendulum", Generated(accelerations::cart_pendulum)),
    ("hw_cart_pendulum", Fixed(closed_forms::hw_cart_pendulum)),
    ("check", Fixed(closed_forms::check)),
    ("fpu", Generated(accelerations::fpu)),
    ("fpu_springs", Generated(accelerations::fpu_springs)),
    ("hw_fpu", Fixed(closed_forms::hw_fpu)),
    ("kepler", Generated(accelerations::kepler)),
    ("hw_kepler", Fixed(closed_forms::hw_kepler)),
    ("drag", Generated(accelerations::drag)),
    ("driven", Generated(accelerations::driven)),
    // The N-link chains.
    ("chain1_links", Generated(chains::chain1_links)),
    ("chain2_links", Generated(chains::chain2_links)),
    ("chain4_links", Generated(chains::chain4_links)),
    ("chain8_links", Generated(chains::chain8_links)),
    ("chain16_links", Generated(chains::chain16_links)),
    ("chain32_links", Generated(chains::chain32_links)),
    ("chain64_links", Generated(chains::chain64_links)),
    ("hw_chain1", Fixed(chains::hw_chain::<1>)),
    ("hw_chain2", Fixed(chains::hw_chain::<2>)),
    ("hw_chain4", Fixed(chains::hw_chain::<4>)),
    ("hw_chain8", Fixed(chains::hw_chain::<8>)),
    ("hw_chain16", Fixed(chains::hw_chain::<16>)),
    ("hw_chain32", Fixed(chains::hw_chain::<32>)),
    ("hw_chain64", Fixed(chains::hw_chain::<64>)),
    ("chain32", Fixed(chains::chain32)),
    // Spatial arms: by joint frames, by principal axes.
    ("framed_arm", Generated(arms::framed_arm)),
    ("principal_arm", Generated(arms::principal_arm)),
    ("principal_axes", Fixed(arms::principal_axes)),
    // Constrained mechanisms, and the projection after a step.
    ("cartesian_pendulum", Generated(constrained::cartesian_pendulum)),
    ("hw_cartesian_pendulum", Fixed(constrained::hw_cartesian_pendulum)),
    ("project_cartesian_pendulum", Generated(constrained::project_cartesian_pendulum)),
    ("four_bar", Generated(constrained::four_bar)),
    ("hw_four_bar", Fixed(constrained::hw_four_bar)),
    // Steps of the integrators on the double pendulum.
    ("rk4_double_pendulum", Fixed(steps::rk4_double_pendulum)),
    ("rk4_validated_double_pendulum", Fixed(steps::rk4_validated_double_pendulum)),
    ("rk4_recorded_double_pendulum", Fixed(steps::rk4_recorded_double_pendulum)),
    ("hw_rk4_double_pendulum", Fixed(steps::hw_rk4_double_pendulum)),
    ("sensitivity_double_pendulum_1", Fixed(steps::sensitivity_double_pendulum_1)),
    ("sensitivity_double_pendulum_2", Fixed(steps::sensitivity_double_pendulum_2)),
    ("sensitivity_double_pendulum_4", Fixed(steps::sensitivity_double_pendulum_4)),
    ("sensitivity_double_pendulum_l1", Fixed(steps::sensitivity_double_pendulum_l1)),
    ("sensitivity_double_pendulum_l1_l2", Fixed(steps::sensitivity_double_pendulum_l1_l2)),
    ("sensitivity_double_pendulum_l1_l2_4", Fixed(steps::sensitivity_double_pendulum_l1_l2_4)),
    ("midpoint_double_pendulum", Fixed(steps::midpoint_double_pendulum)),
    ("gl2_double_pendulum", Fixed(steps::gl2_double_pendulum)),
    ("midpoint_validated_double_pendulum", Fixed(steps::midpoint_validated_double_pendulum)),
    ("gl2_validated_double_pendulum", Fixed(steps::gl2_validated_double_pendulum)),
    ("midpoint_fresh_double_pendulum", Fixed(steps::midpoint_fresh_double_pendulum)),
    ("gl2_fresh_double_pendulum", Fixed(steps::gl2_fresh_double_pendulum)),
    ("radau5_double_pendulum", Fixed(steps::radau5_double_pendulum)),
    // Steps of Andrews' squeezer.
    ("rk4_squeezer", Fixed(squeezer::rk4_squeezer)),
    ("rk4_simulate_squeezer", Fixed(squeezer::rk4_simulate_squeezer)),
    ("gl2_squeezer", Fixed(squeezer::gl2_squeezer)),
    ("gl2_fresh_squeezer", Fixed(squeezer::gl2_fresh_squeezer)),
    ("gl2_stepper_squeezer", Fixed(squeezer::gl2_stepper_squeezer)),
    ("gl2_simulate_squeezer", Fixed(squeezer::gl2_simulate_squeezer)),
    // Steps of a block in frictional contact.
    ("rk4_pushed_block", Fixed(contacts::rk4_pushed_block)),
    ("dopri5_pushed_block", Fixed(contacts::dopri5_pushed_block)),
    // The start-up alone.
    ("none", Fixed(|_| 0.0)),
];

fn main() {
    let mut args = std::env::args().skip(1);
    let Some(name) = args.next() else {
        exit_with_modes("no MODE given")
    };
    let n: usize = args
        .next()
        .map(|calls| calls.parse().expect("CALLS is a number of calls"))
        .unwrap_or(1000);
    let (via, mode) = Via::read(&name);
    let Some(&(_, run)) = MODES.iter().find(|(known, _)| *known == mode) else {
        exit_with_modes(&format!("unknown mode `{name}`"))
    };
    let acc = match run {
        Generated(run) => run(n, via),
        Fixed(run) => run(n),
    };
    println!("{acc}");
}

/// Prints `why`, the usage and every mode to stderr, and exits with status 2.
fn exit_with_modes(why: &str) -> ! {
    eprintln!("{why}\nusage: lagrange-callgrind MODE [CALLS]");
    eprintln!("modes (* also as validated_MODE and hot_MODE):");
    for (name, run) in MODES {
        let prefixed = if matches!(run, Generated(_)) {
            " *"
        } else {
            ""
        };
        eprintln!("  {name}{prefixed}");
    }
    std::process::exit(2)
}
