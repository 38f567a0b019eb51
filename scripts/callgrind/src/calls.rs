//! The loop the modes on a generated mechanism share: `n` evaluations of q̈, along the path a
//! mode's prefix picks (`validated_`, `hot_`).

use lagrange::prelude::*;
use std::hint::black_box;

/// How `calls` evaluates q̈: `accelerations` on the parameters (checked every call) or through a
/// validated handle, or the hook the integrators call (`hot_NAME`).
#[derive(Clone, Copy, PartialEq)]
pub enum Via {
    /// No prefix: `accelerations` on the parameters.
    Parameters,
    /// `validated_`: `accelerations` on `sys.validated()`.
    Validated,
    /// `hot_`: `accelerations_at` on `sys.validated()`.
    Hot,
}

impl Via {
    /// The path a mode's name picks, and the name without its prefix.
    pub fn read(name: &str) -> (Via, &str) {
        match (name.strip_prefix("validated_"), name.strip_prefix("hot_")) {
            (Some(mode), _) => (Via::Validated, mode),
            (_, Some(mode)) => (Via::Hot, mode),
            _ => (Via::Parameters, name),
        }
    }
}

/// Σ q̈₀ over `n` calls: of `accelerations`, on the parameters or through a validated handle,
/// whose parameters were checked once; or (`Via::Hot`) of the hook the integrators call on every
/// stage, `Evaluate::accelerations_at` on the validated handle (with the constants it prepared): no
/// parameter or state check, as within a step.
pub fn calls<M: lagrange::evaluation::Dynamics<N>, const N: usize>(
    sys: M,
    s: &State<M::Coords>,
    n: usize,
    via: Via,
) -> f64 {
    fn run<M: Mechanism<N>, const N: usize>(sys: &M, s: &State<M::Coords>, n: usize) -> f64 {
        let mut acc = 0.0;
        for _ in 0..n {
            acc += black_box(sys)
                .accelerations(black_box(s))
                .unwrap()
                .to_array()[0];
        }
        acc
    }
    fn hot<M: Mechanism<N>, const N: usize>(sys: &M, s: &State<M::Coords>, n: usize) -> f64 {
        let (q, v) = (s.q.to_array(), s.v.to_array());
        let mut acc = 0.0;
        for _ in 0..n {
            acc += black_box(sys)
                .accelerations_at(black_box(s.t), black_box(&q), black_box(&v))
                .unwrap()[0];
        }
        acc
    }
    match via {
        Via::Parameters => run(&sys, s, n),
        Via::Validated => run(&sys.validated().unwrap(), s, n),
        Via::Hot => hot(&sys.validated().unwrap(), s, n),
    }
}
