//! One problem of the report as the phases see it: a [`Setup`] (mechanism, start, end time,
//! reference end state, the peers' hand-written right-hand side and the ladders), and the
//! [`Problem`] trait through which the report's list holds setups of different mechanisms and
//! dimensions.

use crate::sweep::{Progress, Row};
use crate::{agreement, diffsol_peer, dop853_steps, sweep};
use lagrange_core::{Coordinates, Mechanism, State};

/// Hand-written accelerations q̈(t, q, v): the right-hand side the peers integrate.
pub type Rhs<const N: usize> = fn(f64, &[f64; N], &[f64; N]) -> [f64; N];

/// A problem: mechanism, start, end time, reference end state, hand-written accelerations.
/// `N2` = 2N is the dimension of the first-order system y = (q, v) the peers integrate (stable
/// Rust cannot compute it from `N`).
pub struct Setup<M, const N: usize, const N2: usize> {
    pub name: &'static str,
    pub mechanism: M,
    pub start: State<[f64; N]>,
    pub t_end: f64,
    pub reference: ([f64; N], [f64; N]),
    pub rhs: Rhs<N>,
    /// Fixed-step ladder: numbers of steps.
    pub steps: Vec<usize>,
    /// Tolerance ladder of the adaptive methods.
    pub tolerances: Vec<f64>,
    /// Whether Störmer–Verlet applies (constant mass matrix).
    pub verlet: bool,
    /// Whether the mechanism has constraints (the variational integrator and Störmer–Verlet
    /// refuse it).
    pub constrained: bool,
    /// The Jacobian-vector product of the first-order system, by hand: given for the stiff
    /// problems, on which diffsol's implicit solvers run as a second peer.
    pub jacobian_times: Option<diffsol_peer::JacobianTimes<N>>,
    /// Energy error above which a run counts as unstable (relative to 1 + |E₀|).
    pub unstable_energy: f64,
    /// Whether the peers' end states are compared with lagrange's before timing (the report's
    /// "Same answers before timing").
    pub peers_checked: bool,
}

/// What the phases of the report do with one problem, whatever its mechanism and dimension.
pub trait Problem {
    fn name(&self) -> &'static str;
    /// The number of timed runs (for the progress line).
    fn run_count(&self) -> usize;
    /// The peers' end states against lagrange's at tol 1e-8 (see [`agreement::peer_agreement`]),
    /// or `None` for a problem whose peers are not checked.
    fn peer_agreement(&self) -> Option<String>;
    /// Every method over its ladder, timed: one row per run.
    fn time_runs(&self, quick: bool, rows: &mut Vec<Row>, progress: &mut Progress);
    /// The `--dop853-steps` table of this problem (see [`dop853_steps::table`]).
    fn dop853_steps(&self) -> (String, [[Option<usize>; 2]; 3]);
}

impl<M: Mechanism<N>, const N: usize, const N2: usize> Problem for Setup<M, N, N2> {
    fn name(&self) -> &'static str {
        self.name
    }

    fn run_count(&self) -> usize {
        sweep::count_runs(self)
    }

    fn peer_agreement(&self) -> Option<String> {
        self.peers_checked.then(|| agreement::peer_agreement(self))
    }

    fn time_runs(&self, quick: bool, rows: &mut Vec<Row>, progress: &mut Progress) {
        sweep::run_setup(self, quick, rows, progress);
    }

    fn dop853_steps(&self) -> (String, [[Option<usize>; 2]; 3]) {
        dop853_steps::table(self)
    }
}

/// A state in the mechanism's own coordinates type.
pub fn in_coordinates<M: Mechanism<N>, const N: usize>(s: &State<[f64; N]>) -> State<M::Coords> {
    State::new(s.t, M::Coords::from_array(s.q), M::Coords::from_array(s.v))
}

/// The max-norm distance of (q, v) from the state `r`.
pub fn distance<const N: usize>(q: &[f64; N], v: &[f64; N], r: &([f64; N], [f64; N])) -> f64 {
    q.iter()
        .zip(&r.0)
        .chain(v.iter().zip(&r.1))
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

/// (q, v) from a first-order state y = (q, v) of length 2N.
pub fn split_qv<const N: usize>(y: &[f64]) -> ([f64; N], [f64; N]) {
    (
        std::array::from_fn(|i| y[i]),
        std::array::from_fn(|i| y[N + i]),
    )
}
