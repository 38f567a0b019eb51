//! `robots`: lagrange's side of the robot peer benchmark (`scripts/peers/robots.sh`), on the five
//! declarations of `lagrange-robots` (and, with the feature `example-robot-data`, the five robot
//! files of that package), at the states of the file `robots.py states` (or
//! `example_robots.py`) writes.
//!
//! ```text
//! robots values --states FILE        q̈ (`accelerations`), τ (`inverse_dynamics` at the file's q̈)
//!                                    and M (`mass_matrix`) at every state
//! robots time --states FILE          per-call times of `accelerations`, `inverse_dynamics` and
//!                                    `mass_matrix`
//! robots count --states FILE --robot NAME --label LABEL --calls C
//!                                    C calls of one label (for callgrind)
//! ```
//!
//! Every call goes through the validated handle (`Arm7 { g: 9.81 }.validated()?`), as a
//! simulation makes it. The lines printed are those of the C drivers (tab-separated): `lagrange
//! robot quantity k x…` and `lagrange robot label min_ns median_ns calls_per_rep`; the timing
//! loop is theirs too (a warm-up of about 50 ms that sizes a repetition to about 10 ms, then 21
//! repetitions, each one call at every state of the robot; min and median per call).

mod peer_timing;

use clap::{Parser, Subcommand, ValueEnum};
use lagrange::prelude::*;
use lagrange_robots::quadruped::Quadruped;
use lagrange_robots::{arm14::Arm14, arm3::Arm3, arm7::Arm7, humanoid::Humanoid};
use peer_timing::{as_coordinate, print_time};
use std::error::Error as StdError;
use std::hint::black_box;
use std::path::{Path, PathBuf};

type BoxResult<T> = std::result::Result<T, Box<dyn StdError>>;

/// A state of the states file and the q̈ at which inverse dynamics is evaluated there.
type Sample<C> = (State<C>, C);

#[derive(Parser)]
#[command(about = "lagrange's side of the robot peer benchmark (scripts/peers/robots.sh)")]
struct Cli {
    #[command(subcommand)]
    mode: Mode,
}

#[derive(Subcommand)]
enum Mode {
    /// q̈, τ and M at every state of every robot.
    Values {
        #[arg(long)]
        states: PathBuf,
    },
    /// Per-call times of every label, every robot.
    Time {
        #[arg(long)]
        states: PathBuf,
    },
    /// CALLS calls of one label on one robot, cycling through its states.
    Count {
        #[arg(long)]
        states: PathBuf,
        #[arg(long)]
        robot: String,
        #[arg(long, value_enum)]
        label: Label,
        #[arg(long)]
        calls: usize,
    },
}

/// The label of a call, as the drivers and the report name it (`inverse_dynamics`).
#[derive(Clone, Copy, ValueEnum)]
#[value(rename_all = "snake_case")]
enum Label {
    Accelerations,
    InverseDynamics,
    MassMatrix,
}

impl Label {
    const ALL: [Label; 3] = [
        Label::Accelerations,
        Label::InverseDynamics,
        Label::MassMatrix,
    ];

    fn name(self) -> &'static str {
        match self {
            Label::Accelerations => "accelerations",
            Label::InverseDynamics => "inverse_dynamics",
            Label::MassMatrix => "mass_matrix",
        }
    }
}

/// One robot's rows of the states file: coordinate names, then (q, q̇, q̈) per state.
struct Rows {
    names: Vec<String>,
    states: Vec<Vec<f64>>,
}

/// The states file: per robot, a row `robot names c…`, then rows `robot k q… q̇… q̈…`.
fn read_states(path: &Path) -> BoxResult<Vec<(String, Rows)>> {
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(b'\t')
        .has_headers(false)
        .flexible(true)
        .from_path(path)?;
    let mut robots: Vec<(String, Rows)> = Vec::new();
    for record in reader.records() {
        let record = record?;
        let (robot, kind) = (&record[0], &record[1]);
        let rest = record.iter().skip(2);
        if kind == "names" {
            let names = rest.map(str::to_owned).collect();
            robots.push((
                robot.to_owned(),
                Rows {
                    names,
                    states: Vec::new(),
                },
            ));
            continue;
        }
        let rows = match robots.last_mut() {
            Some((name, rows)) if name == robot => rows,
            _ => return Err(format!("state row of `{robot}` before its names row").into()),
        };
        let values = rest
            .map(str::parse)
            .collect::<std::result::Result<Vec<f64>, _>>()?;
        if values.len() != 3 * rows.names.len() {
            return Err(format!("state row of `{robot}` has {} values", values.len()).into());
        }
        rows.states.push(values);
    }
    Ok(robots)
}

/// Where each of the file's coordinates stands in the declaration: `order[i]` is the declared
/// index of the file's `i`-th name. The file may list the coordinates in another order (the
/// peers' joint order) and by their URDF joint names, but every name must be a declared one, each
/// once.
fn declared_order<M: Mechanism<N>, const N: usize>(
    robot: &str,
    rows: &Rows,
) -> BoxResult<[usize; N]> {
    let declared = <M::Coords as Coordinates<N>>::NAMES;
    let mut order = [usize::MAX; N];
    if rows.names.len() != N {
        return Err(format!(
            "`{robot}`: the file has {} coordinates, the declaration {N}",
            rows.names.len()
        )
        .into());
    }
    for (i, name) in rows.names.iter().enumerate() {
        match declared.iter().position(|d| *d == as_coordinate(name)) {
            Some(k) if !order.contains(&k) => order[i] = k,
            _ => {
                return Err(format!(
                    "`{robot}`: the file's coordinate `{name}` is not one of the declaration's"
                )
                .into())
            }
        }
    }
    Ok(order)
}

/// A robot's states as the declaration's `State`s, with the q̈ for inverse dynamics.
fn states<M: Mechanism<N>, const N: usize>(
    rows: &Rows,
    order: &[usize; N],
) -> Vec<Sample<M::Coords>> {
    let part = |s: &[f64], i: usize| {
        let mut declared = [0.0; N];
        for (j, &k) in order.iter().enumerate() {
            declared[k] = s[i * N + j];
        }
        M::Coords::from_array(declared)
    };
    rows.states
        .iter()
        .map(|s| {
            (
                State {
                    t: 0.0,
                    q: part(s, 0),
                    v: part(s, 1),
                },
                part(s, 2),
            )
        })
        .collect()
}

fn print_values(robot: &str, quantity: &str, k: usize, values: impl IntoIterator<Item = f64>) {
    let mut line = format!("lagrange\t{robot}\t{quantity}\t{k}");
    for x in values {
        // `{}` prints an f64's shortest decimal that reads back to the same value.
        line.push_str(&format!("\t{x}"));
    }
    println!("{line}");
}

/// One call of `label` at a state; the result is kept from the optimiser.
#[inline(always)]
fn call<M: Mechanism<N>, const N: usize>(
    sys: &M,
    label: Label,
    (state, qdd): &Sample<M::Coords>,
) -> lagrange::Result<()> {
    match label {
        Label::Accelerations => {
            black_box(sys.accelerations(black_box(state))?);
        }
        Label::InverseDynamics => {
            black_box(sys.inverse_dynamics(black_box(state), black_box(qdd))?);
        }
        Label::MassMatrix => {
            black_box(sys.mass_matrix(black_box(state))?);
        }
    }
    Ok(())
}

fn run<M: Mechanism<N>, const N: usize>(
    sys: &M,
    robot: &str,
    rows: &Rows,
    mode: &Mode,
) -> BoxResult<()> {
    let order = declared_order::<M, N>(robot, rows)?;
    let states = states::<M, N>(rows, &order);
    // A declared vector in the file's order.
    let in_file_order = |x: [f64; N]| order.map(|k| x[k]);
    match *mode {
        Mode::Values { .. } => {
            for (k, (state, qdd)) in states.iter().enumerate() {
                let qdd_out = in_file_order(sys.accelerations(state)?.to_array());
                print_values(robot, "qdd", k, qdd_out);
                let tau = in_file_order(sys.inverse_dynamics(state, qdd)?.to_array());
                print_values(robot, "tau", k, tau);
                // Row-major in the file's order: M(i, j) for i, then j.
                let m = sys.mass_matrix(state)?;
                let rows = order
                    .iter()
                    .flat_map(|&i| order.iter().map(move |&j| (i, j)));
                print_values(robot, "M", k, rows.map(|ij| m[ij]));
            }
        }
        Mode::Time { .. } => {
            for label in Label::ALL {
                // Every state evaluated once first: a call that failed would be timed as a
                // quick return.
                for s in &states {
                    call(sys, label, s)?;
                }
                print_time(robot, label.name(), states.len(), || {
                    for s in &states {
                        let _ = call(sys, label, s);
                    }
                });
            }
        }
        Mode::Count { label, calls, .. } => {
            for c in 0..calls {
                call(sys, label, &states[c % states.len()])?;
            }
        }
    }
    Ok(())
}

/// The robots of `example-robot-data` (feature of that name), with the values their files give.
#[cfg(feature = "example-robot-data")]
fn example_robot_data(robot: &str, rows: &Rows, mode: &Mode) -> BoxResult<()> {
    use lagrange_robots::example_robot_data::{anymal, panda, solo12, talos, ur5};
    match robot {
        "ur5" => run(&ur5::Ur5::default().validated()?, robot, rows, mode),
        "panda" => run(&panda::Panda::default().validated()?, robot, rows, mode),
        "solo12" => run(&solo12::Solo12::default().validated()?, robot, rows, mode),
        "anymal" => run(&anymal::Anymal::default().validated()?, robot, rows, mode),
        "talos" => run(&talos::Talos::default().validated()?, robot, rows, mode),
        other => Err(format!("no declaration of the robot `{other}`").into()),
    }
}

fn main() -> BoxResult<()> {
    let cli = Cli::parse();
    let (Mode::Values { states } | Mode::Time { states } | Mode::Count { states, .. }) = &cli.mode;
    let only = match &cli.mode {
        Mode::Count { robot, .. } => Some(robot.as_str()),
        _ => None,
    };
    let mut found = false;
    for (robot, rows) in read_states(states)? {
        if only.is_some_and(|name| name != robot) {
            continue;
        }
        found = true;
        let mode = &cli.mode;
        match robot.as_str() {
            "arm3" => run(&Arm3 { g: 9.81 }.validated()?, &robot, &rows, mode)?,
            "arm7" => run(&Arm7 { g: 9.81 }.validated()?, &robot, &rows, mode)?,
            "arm14" => run(&Arm14 { g: 9.81 }.validated()?, &robot, &rows, mode)?,
            "quadruped" => run(&Quadruped { g: 9.81 }.validated()?, &robot, &rows, mode)?,
            "humanoid" => run(&Humanoid { g: 9.81 }.validated()?, &robot, &rows, mode)?,
            #[cfg(feature = "example-robot-data")]
            name @ ("ur5" | "panda" | "solo12" | "anymal" | "talos") => {
                example_robot_data(name, &rows, mode)?
            }
            other => return Err(format!("no declaration of the robot `{other}`").into()),
        }
    }
    if !found {
        return Err("no robot of that name in the states file".into());
    }
    Ok(())
}
