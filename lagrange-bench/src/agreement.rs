//! The phase before any timing: the peers and lagrange solve the same problem. Each peer and
//! lagrange's Dopri5 and Radau5 run at tol 1e-8 from the same start; their end states are compared
//! with each other (max-norm distance to lagrange's Radau5) and with the reference. A peer that
//! computed another problem would stand out by orders of magnitude.

use crate::diffsol_peer;
use crate::peer::{run_peer, PeerMethod};
use crate::runs::{run_adaptive, run_diffsol, Adaptive, RunResult};
use crate::setup::{distance, Setup};
use lagrange_core::Mechanism;

/// The report's sentence on one problem: how far lagrange's Radau5 ends from the reference, and
/// every other run from Radau5 and from the reference.
pub fn peer_agreement<M: Mechanism<N>, const N: usize, const N2: usize>(
    setup: &Setup<M, N, N2>,
) -> String {
    let tol = 1e-8;
    let ours = run_adaptive(setup, Adaptive::Radau5, tol, false);
    let Ok((q0, v0, ..)) = ours else {
        return format!("{}: lagrange Radau5 failed at tol 1e-8", setup.name);
    };
    let mut runs: Vec<(&str, RunResult<N>)> = vec![
        (
            Adaptive::Dopri5.name(),
            run_adaptive(setup, Adaptive::Dopri5, tol, false),
        ),
        (
            PeerMethod::Dopri5.name(),
            run_peer(setup, PeerMethod::Dopri5, tol, false),
        ),
        (
            PeerMethod::Dop853.name(),
            run_peer(setup, PeerMethod::Dop853, tol, false),
        ),
    ];
    if setup.jacobian_times.is_some() {
        for m in [diffsol_peer::Method::Bdf, diffsol_peer::Method::Esdirk34] {
            runs.push((m.name(), run_diffsol(setup, m, tol)));
        }
    }
    let mut s = format!(
        "{}: at tol 1e-8, lagrange Radau5 ends {:.1e} from the reference; ",
        setup.name,
        distance(&q0, &v0, &setup.reference)
    );
    let parts: Vec<String> = runs
        .into_iter()
        .map(|(name, r)| match r {
            Ok((q, v, ..)) => format!(
                "{name} {:.1e} from Radau5 ({:.1e} from the reference)",
                distance(&q, &v, &(q0, v0)),
                distance(&q, &v, &setup.reference)
            ),
            Err(e) => format!("{name} failed ({e})"),
        })
        .collect();
    s.push_str(&parts.join(", "));
    s.push('.');
    s
}
