//! The entry points of a mechanism with constraints: the constrained solve (its generalized
//! constraint forces), the projection onto the constraints (`consistent_state` from a guess off
//! them), and for contacts the fixed-step contact solvers (RK4, and Gauss–Legendre 2 in the same
//! event loop).

use super::harness::{kind, Entry, Part, Setup, Value};
use super::units::{dim, Dim, Units, TIME};
use lagrange::constraints::Constraints;
use lagrange::model::Model;
use lagrange::prelude::*;
use lagrange::{consistent_state, constraint_forces, ContactOptions};

/// The dimension of the generalized force on a coordinate of dimension `d`: an energy over d.
fn force_on(d: Dim) -> Dim {
    let energy = dim(2, 1, -2);
    Dim {
        length: energy.length - d.length,
        mass: energy.mass - d.mass,
        time: energy.time - d.time,
    }
}

/// The constraint forces and the projection of a constrained mechanism.
pub fn entries<'a, M, const N: usize, const K: usize, const C: usize>(
    setup: &'a Setup<'a, M, N>,
) -> Vec<Entry<'a>>
where
    M: Constraints<N, K, C> + Mechanism<N, Coords = <M as Model<N, K>>::Coords>,
{
    vec![
        Entry {
            name: "constraint forces",
            integrates: false,
            events: false,
            run: Box::new(move |u: &Units, _| {
                let sys = (setup.make)(u);
                let f = constraint_forces(&sys, &setup.state(u)).map_err(|e| kind(&e))?;
                // Σᵢ λᵢ rᵢ on each coordinate, weighted by 1/√Mᵢᵢ (a force over √mass: one unit).
                let weights = setup.weights();
                let values = (0..N)
                    .map(|k| {
                        let total: f64 = (0..C).map(|i| f.generalized[i][k]).sum();
                        u.in_si(total, force_on(setup.coords[k]))
                    })
                    .collect();
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts: vec![Part {
                        values,
                        weights: weights.iter().map(|w| 1.0 / w).collect(),
                        floor: 0.0,
                    }],
                    counts: vec![],
                })
            }),
        },
        Entry {
            name: "projection",
            integrates: false,
            events: false,
            run: Box::new(move |u: &Units, _| {
                let sys = (setup.make)(u);
                // The start moved off the constraints by 1e-3 of each coordinate's unit in SI (a
                // milliradian, a millimetre) and 1e-3 of that per second.
                let [q, v] = setup.start;
                let off: [f64; N] = std::array::from_fn(|i| q[i] + 1e-3 * (i as f64 + 1.0));
                let off_v: [f64; N] = std::array::from_fn(|i| v[i] - 1e-3 * (i as f64 + 1.0));
                let guess = setup.state_from(u, 0.0, &off, &off_v);
                let s = consistent_state(&sys, &guess).map_err(|e| kind(&e))?;
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts: setup.state_parts(u, &s),
                    counts: vec![],
                })
            }),
        },
    ]
}

/// The fixed-step contact solvers of a declaration with unilateral or friction rows.
pub fn contact_entries<'a, M, const N: usize, const K: usize, const C: usize>(
    setup: &'a Setup<'a, M, N>,
) -> Vec<Entry<'a>>
where
    M: Constraints<N, K, C> + Mechanism<N, Coords = <M as Model<N, K>>::Coords>,
{
    vec![
        Entry {
            name: "ContactRk4",
            integrates: true,
            events: true,
            run: Box::new(move |u: &Units, fine| {
                let sys = (setup.make)(u);
                let refine = if fine { 2 } else { 1 };
                let h = u.express(setup.h, TIME) / refine as f64;
                let mut solver = Stepper::new(&sys, Rk4::with_step(h), &setup.state(u))
                    .and_then(|solver| solver.with_contact_options(ContactOptions::default()))
                    .map_err(|e| kind(&e))?;
                for _ in 0..setup.steps * refine {
                    solver.step(f64::MAX).map_err(|e| kind(&e))?;
                }
                let st = solver.stats();
                // The mode changes and their times, compared as a part of their own.
                let events = solver.mode_changes().to_vec();
                let mut parts = setup.state_parts(u, &solver.state());
                if !fine {
                    parts.push(Part {
                        values: events.iter().map(|e| u.in_si(e.t, TIME)).collect(),
                        weights: vec![1.0; events.len()],
                        floor: 0.0,
                    });
                }
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts,
                    counts: if fine {
                        vec![]
                    } else {
                        vec![st.evaluations, st.accepted, events.len()]
                    },
                })
            }),
        },
        Entry {
            name: "contact GL2",
            integrates: true,
            events: true,
            run: Box::new(move |u: &Units, fine| {
                // `sys.step::<GaussLegendre2>` on a contact declaration: one step of the contact
                // loop with Gauss-Legendre 2 as its one-step method.
                let sys = (setup.make)(u);
                let refine = if fine { 2 } else { 1 };
                let h = u.express(setup.h, TIME) / refine as f64;
                let mut s = setup.state(u);
                for _ in 0..setup.steps * refine {
                    sys.step::<GaussLegendre2>(&mut s, h)
                        .map_err(|e| kind(&e))?;
                }
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts: setup.state_parts(u, &s),
                    counts: vec![],
                })
            }),
        },
    ]
}
