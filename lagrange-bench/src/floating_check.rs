//! `floating-check`: lagrange's side of the floating-base peer benchmark
//! (`scripts/peers/floating.sh`), on `#[lagrange::urdf(.., floating)]` declarations against
//! Pinocchio's free flyer, at the states and with the values that `scripts/peers/floating.py`
//! wrote, converted to the declaration's coordinates — base position p, modified Rodrigues
//! parameters σ of the base's rotation (its velocities the base's angular velocity ω, as
//! Pinocchio's), joints — and back.
//!
//! ```text
//! floating-check check --robot R --states FILE   q̈ (`accelerations`) against Pinocchio's ABA and
//!                                                τ (`inverse_dynamics`) against its RNEA
//! floating-check time --robot R --states FILE    per-call times of both
//! floating-check count --robot R --states FILE --label LABEL --calls C
//!                                                C calls of one label (for callgrind)
//! ```
//!
//! ROBOT: `quadruped` (the tests' file), or `solo12` with the `example-robot-data` feature.
//! `check` exits 2 when an entry differs by more than 1e-10 relative to 1 + |Pinocchio's|. Every
//! call goes through the validated handle, as a simulation makes it; the time lines and the timing
//! loop are those of the C drivers (`robots_common.h`, `timing.h`).
//!
//! The conversions (Pinocchio's velocity: the base's linear velocity u and angular velocity ω in
//! the base frame, R the base's rotation; the declaration's: ṗ in the world frame and the same ω):
//! - velocity: ṗ = R u, ω as it is;
//! - acceleration: Pinocchio's is the derivative of (u, ω), so p̈ = R (u̇ + ω × u), ω̇ as it is;
//! - force: Pinocchio's (f, n) in the base frame does the work of (R f, n) on (ṗ, ω), the
//!   transpose of the velocity's map.

mod peer_timing;

use clap::{Parser, Subcommand, ValueEnum};
use lagrange::prelude::*;
use peer_timing::{as_coordinate, print_time};
use std::error::Error as StdError;
use std::hint::black_box;
use std::path::{Path, PathBuf};

type BoxResult<T> = std::result::Result<T, Box<dyn StdError>>;

/// The largest difference from Pinocchio's, relative to 1 + |Pinocchio's|, that `check` accepts:
/// both sides evaluate the same rigid-body dynamics in double precision with different
/// recursions and coordinates, which agree to about 1e-13 on these robots.
const TOLERANCE: f64 = 1e-10;

/// The tests' quadruped (12 joints) with a free-flying root.
#[lagrange::urdf("../tests/urdf/quadruped.urdf", floating)]
pub mod quadruped {}

/// Solo12 (the file `example_robots.py` prepares) with a free-flying root.
#[cfg(feature = "example-robot-data")]
#[lagrange::urdf("robots/example-robot-data/solo12.urdf", floating)]
pub mod solo12 {}

#[derive(Parser)]
#[command(
    about = "lagrange's side of the floating-base peer benchmark (scripts/peers/floating.sh)"
)]
struct Cli {
    #[command(subcommand)]
    mode: Mode,
}

#[derive(Subcommand)]
enum Mode {
    /// q̈ and τ at every state against Pinocchio's.
    Check {
        #[arg(long)]
        robot: String,
        #[arg(long)]
        states: PathBuf,
    },
    /// Per-call times of both labels.
    Time {
        #[arg(long)]
        robot: String,
        #[arg(long)]
        states: PathBuf,
    },
    /// CALLS calls of one label, cycling through the states.
    Count {
        #[arg(long)]
        robot: String,
        #[arg(long)]
        states: PathBuf,
        #[arg(long, value_enum)]
        label: Label,
        #[arg(long)]
        calls: usize,
    },
}

/// The label of a call, as the drivers and the report name it.
#[derive(Clone, Copy, ValueEnum)]
#[value(rename_all = "snake_case")]
enum Label {
    Accelerations,
    InverseDynamics,
}

/// The base of a state: its rotation R (from Pinocchio's unit quaternion), σ, and Pinocchio's
/// base-frame velocity (u, ω).
struct Base {
    rotation: Rot3<f64>,
    sigma: [f64; 3],
    linear: [f64; 3],
    omega: [f64; 3],
}

/// A state of the file in the declaration's coordinates, with Pinocchio's values.
struct Sample<C> {
    state: State<C>,
    /// Pinocchio's RNEA input b as the declaration's q̈.
    qdd: C,
    base: Base,
    /// Pinocchio's aba(q, v, 0), in its order.
    aba: Vec<f64>,
    /// Pinocchio's rnea(q, v, b) as the declaration's generalized forces.
    tau: Vec<f64>,
}

/// A file's states: where each of Pinocchio's joints stands among the declaration's coordinates,
/// and the samples.
type Samples<C> = (Vec<usize>, Vec<Sample<C>>);

/// The rotation of a unit quaternion (x, y, z, w).
fn quaternion_rotation([x, y, z, w]: [f64; 4]) -> Rot3<f64> {
    Rot3 {
        rows: [
            [
                1.0 - 2.0 * (y * y + z * z),
                2.0 * (x * y - z * w),
                2.0 * (x * z + y * w),
            ],
            [
                2.0 * (x * y + z * w),
                1.0 - 2.0 * (x * x + z * z),
                2.0 * (y * z - x * w),
            ],
            [
                2.0 * (x * z - y * w),
                2.0 * (y * z + x * w),
                1.0 - 2.0 * (x * x + y * y),
            ],
        ],
    }
}

/// The base of Pinocchio's q (position, quaternion x y z w with w ≥ 0, …) and v (u, ω, …).
fn base(q: &[f64], v: &[f64]) -> BoxResult<Base> {
    let quaternion = [q[3], q[4], q[5], q[6]];
    let rotation = quaternion_rotation(quaternion);
    // σ = (x, y, z)/(1 + w), in the chart's ball for w ≥ 0; R(σ) must be the quaternion's.
    let sigma = [0, 1, 2].map(|k| quaternion[k] / (1.0 + quaternion[3]));
    let r_sigma = rot_mrp(vec3(sigma[0], sigma[1], sigma[2]));
    for (row, other) in rotation.rows.iter().zip(r_sigma.rows) {
        if row.iter().zip(other).any(|(a, b)| (a - b).abs() >= 1e-13) {
            return Err("R(σ) differs from the quaternion's rotation".into());
        }
    }
    Ok(Base {
        rotation,
        sigma,
        linear: [v[0], v[1], v[2]],
        omega: [v[3], v[4], v[5]],
    })
}

/// R x.
fn rotate(r: &Rot3<f64>, x: [f64; 3]) -> [f64; 3] {
    let y = *r * vec3(x[0], x[1], x[2]);
    [y.x, y.y, y.z]
}

/// u × w.
fn cross(u: [f64; 3], w: [f64; 3]) -> [f64; 3] {
    let c = vec3(u[0], u[1], u[2]).cross(&vec3(w[0], w[1], w[2]));
    [c.x, c.y, c.z]
}

/// A declared vector from its base block and Pinocchio's joint entries (`order[k]`: the declared
/// index of Pinocchio's k-th joint).
fn declared<const N: usize>(
    linear: [f64; 3],
    angular: [f64; 3],
    joints: &[f64],
    order: &[usize],
) -> [f64; N] {
    let mut x = [0.0; N];
    x[..3].copy_from_slice(&linear);
    x[3..6].copy_from_slice(&angular);
    for (k, &i) in order.iter().enumerate() {
        x[i] = joints[k];
    }
    x
}

/// Pinocchio's acceleration (u̇, ω̇, joints) as the declaration's v̇: p̈ = R (u̇ + ω × u), ω̇.
fn acceleration_to_ours<const N: usize>(b: &Base, a: &[f64], order: &[usize]) -> [f64; N] {
    let turn = cross(b.omega, b.linear);
    let linear = rotate(&b.rotation, [0, 1, 2].map(|k| a[k] + turn[k]));
    declared(linear, [a[3], a[4], a[5]], &a[6..], order)
}

/// The declaration's v̇ as Pinocchio's acceleration: u̇ = Rᵀ p̈ − ω × u, ω̇.
fn acceleration_to_pinocchio(b: &Base, qdd: &[f64], order: &[usize]) -> Vec<f64> {
    let body = rotate(&b.rotation.transpose(), [qdd[0], qdd[1], qdd[2]]);
    let turn = cross(b.omega, b.linear);
    let mut a: Vec<f64> = (0..3).map(|k| body[k] - turn[k]).collect();
    a.extend([qdd[3], qdd[4], qdd[5]]);
    a.extend(order.iter().map(|&i| qdd[i]));
    a
}

/// Pinocchio's generalized force (f, n in the base frame, joints) as the declaration's: R f, n.
fn force_to_ours<const N: usize>(b: &Base, tau: &[f64], order: &[usize]) -> [f64; N] {
    let linear = rotate(&b.rotation, [tau[0], tau[1], tau[2]]);
    declared(linear, [tau[3], tau[4], tau[5]], &tau[6..], order)
}

/// The file's states in the declaration's coordinates (the file: `floating.py`).
fn read_samples<M: Mechanism<N>, const N: usize>(path: &Path) -> BoxResult<Samples<M::Coords>> {
    let text = std::fs::read_to_string(path)?;
    let mut lines = text.lines();
    let header = lines.next().ok_or("an empty states file")?;
    let names = <M::Coords as Coordinates<N>>::NAMES;
    let order = header
        .split('\t')
        .skip(1)
        .map(|joint| {
            names
                .iter()
                .position(|m| *m == as_coordinate(joint))
                .ok_or_else(|| format!("Pinocchio's joint `{joint}` is not declared"))
        })
        .collect::<std::result::Result<Vec<usize>, _>>()?;
    let nj = order.len();
    if N != 6 + nj {
        return Err(format!("{nj} joints in the file, {N} declared coordinates").into());
    }
    let mut samples = Vec::new();
    for line in lines {
        let x = line
            .split('\t')
            .map(str::parse)
            .collect::<std::result::Result<Vec<f64>, _>>()?;
        if x.len() != 7 + nj + 4 * N {
            return Err(format!("a state row of {} values", x.len()).into());
        }
        let (q, rest) = x.split_at(7 + nj);
        let [v, a, b, tau] = [0, 1, 2, 3].map(|k| &rest[k * N..(k + 1) * N]);
        let base = base(q, v)?;
        let position = [q[0], q[1], q[2]];
        let coords = declared(position, base.sigma, &q[7..], &order);
        let velocities = declared(
            rotate(&base.rotation, base.linear),
            base.omega,
            &v[6..],
            &order,
        );
        samples.push(Sample {
            state: State::new(
                0.0,
                Coordinates::from_array(coords),
                Coordinates::from_array(velocities),
            ),
            qdd: Coordinates::from_array(acceleration_to_ours(&base, b, &order)),
            tau: force_to_ours::<N>(&base, tau, &order).to_vec(),
            aba: a.to_vec(),
            base,
        });
    }
    Ok((order, samples))
}

/// The largest |x − expected| / (1 + |expected|).
fn worst(x: &[f64], expected: &[f64]) -> f64 {
    x.iter()
        .zip(expected)
        .map(|(m, p)| (m - p).abs() / (1.0 + p.abs()))
        .fold(0.0, f64::max)
}

/// q̈ and τ against Pinocchio's at every state; false when either misses [`TOLERANCE`].
fn check<M: Mechanism<N>, const N: usize>(
    sys: &M,
    robot: &str,
    order: &[usize],
    samples: &[Sample<M::Coords>],
) -> BoxResult<bool> {
    let (mut qdd, mut tau) = (0.0f64, 0.0f64);
    for s in samples {
        let ours = sys.accelerations(&s.state)?.to_array();
        qdd = qdd.max(worst(
            &acceleration_to_pinocchio(&s.base, &ours, order),
            &s.aba,
        ));
        let force = sys.inverse_dynamics(&s.state, &s.qdd)?.to_array();
        tau = tau.max(worst(&force, &s.tau));
    }
    println!(
        "{robot}: max |q̈ − Pinocchio's aba| / (1 + |aba|) = {qdd:.1e}, \
         max |τ − Pinocchio's rnea| / (1 + |rnea|) = {tau:.1e} ({} states)",
        samples.len()
    );
    Ok(qdd <= TOLERANCE && tau <= TOLERANCE)
}

/// One call of `label` at a sample; the result is kept from the optimiser.
#[inline(always)]
fn call<M: Mechanism<N>, const N: usize>(
    sys: &M,
    label: Label,
    s: &Sample<M::Coords>,
) -> lagrange::Result<()> {
    match label {
        Label::Accelerations => {
            black_box(sys.accelerations(black_box(&s.state))?);
        }
        Label::InverseDynamics => {
            black_box(sys.inverse_dynamics(black_box(&s.state), black_box(&s.qdd))?);
        }
    }
    Ok(())
}

/// Runs `mode` on one robot; false when the check failed.
fn run<M: Mechanism<N>, const N: usize>(sys: &M, robot: &str, mode: &Mode) -> BoxResult<bool> {
    let (Mode::Check { states, .. } | Mode::Time { states, .. } | Mode::Count { states, .. }) =
        mode;
    let (order, samples) = read_samples::<M, N>(states)?;
    if samples.is_empty() {
        return Err("no state in the file".into());
    }
    match *mode {
        Mode::Check { .. } => return check(sys, robot, &order, &samples),
        Mode::Time { .. } => {
            for (label, name) in [
                (Label::Accelerations, "accelerations"),
                (Label::InverseDynamics, "inverse_dynamics"),
            ] {
                // Every state evaluated once first: a call that failed would be timed as a
                // quick return.
                for s in &samples {
                    call(sys, label, s)?;
                }
                print_time(robot, name, samples.len(), || {
                    for s in &samples {
                        let _ = call(sys, label, s);
                    }
                });
            }
        }
        Mode::Count { label, calls, .. } => {
            for c in 0..calls {
                call(sys, label, &samples[c % samples.len()])?;
            }
        }
    }
    Ok(true)
}

fn main() -> BoxResult<()> {
    let cli = Cli::parse();
    let (Mode::Check { robot, .. } | Mode::Time { robot, .. } | Mode::Count { robot, .. }) =
        &cli.mode;
    let passed = match robot.as_str() {
        "quadruped" => run(
            &quadruped::Quadruped::default().validated()?,
            robot,
            &cli.mode,
        )?,
        #[cfg(feature = "example-robot-data")]
        "solo12" => run(&solo12::Solo12::default().validated()?, robot, &cli.mode)?,
        other => return Err(format!("no floating declaration of the robot `{other}`").into()),
    };
    if !passed {
        std::process::exit(2);
    }
    Ok(())
}
