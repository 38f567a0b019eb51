//! Radau5 on a mechanism with quasi-velocities (a free or ball joint's angular velocity, q̇ =
//! G(q) v): its stage equations and Newton matrix are written for q' = q̇, so it steps the
//! coordinates' rates ([`RatesField`], q̈ = G (v̇ − Ħ) with Ħ = Ḃ q̇, and its Jacobians by the chain
//! rule), converting at a step's ends: (q, v, v̇) to (q, q̇, q̈) at its start, q̇ to v = B q̇ at its
//! end, and the dense output's velocities at every evaluation. It then takes exactly the steps it
//! takes on the same declaration written with the chart's rates for velocities.

use crate::error::Result;
use crate::integrate::dense::DenseOutput;
use crate::integrate::newton::{jacobian_rows, seeded};
use crate::integrate::pair::{AccelerationField, Accepted, StepStart};
use crate::tree::rigid::{free, Joint};
use nalgebra::SMatrix;
use num_dual::DualSVec;

/// `field` seen in the coordinates' rates.
pub(super) struct RatesField<'f, F> {
    pub(super) field: &'f F,
    pub(super) joints: &'static [Joint],
}

impl<F: AccelerationField<N>, const N: usize> AccelerationField<N> for RatesField<'_, F> {
    fn accelerations(&self, t: f64, q: &[f64; N], rates: &[f64; N]) -> Result<[f64; N]> {
        let v = free::velocities_from_rates(self.joints, q, rates);
        let v_dot = self.field.accelerations(t, q, &v)?;
        Ok(free::rate_accelerations(self.joints, q, rates, &v_dot))
    }

    /// With v = B(q) q̇, w = v̇(q, v) − Ḃ(q) q̇ and q̈ = G(q) w, by the chain rule:
    ///
    /// ```text
    /// ∂q̈/∂q = ∂(G w)/∂q|w + G (A_q + A_v ∂v/∂q − ∂(Ḃ q̇)/∂q),   ∂q̈/∂q̇ = G (A_v B − ∂(Ḃ q̇)/∂q̇),
    /// ```
    ///
    /// A_q, A_v the field's Jacobians; the maps' derivatives by dual numbers.
    fn jacobians(
        &self,
        t: f64,
        q: &[f64; N],
        rates: &[f64; N],
    ) -> Result<(SMatrix<f64, N, N>, SMatrix<f64, N, N>)> {
        let joints = self.joints;
        let v = free::velocities_from_rates(joints, q, rates);
        let v_dot = self.field.accelerations(t, q, &v)?;
        let (a_q, a_v) = self.field.jacobians(t, q, &v)?;
        let bias = free::velocity_bias(joints, q, rates);
        let w: [f64; N] = std::array::from_fn(|i| v_dot[i] - bias[i]);
        // Seeded on q, then on q̇: v = B q̇, Ḃ q̇, and G w at w fixed.
        let (qd, rd) = (seeded(q), seeded(rates));
        let (q0, r0, w0) = (constant(q), constant(rates), constant(&w));
        let v_q = jacobian_rows(&free::velocities_from_rates(joints, &qd, &r0));
        let v_r = jacobian_rows(&free::velocities_from_rates(joints, &q0, &rd));
        let bias_q = jacobian_rows(&free::velocity_bias(joints, &qd, &r0));
        let bias_r = jacobian_rows(&free::velocity_bias(joints, &q0, &rd));
        let g_w_q = jacobian_rows(&free::position_rates(joints, &qd, &w0));
        let w_q = a_q + a_v * v_q - bias_q;
        let w_r = a_v * v_r - bias_r;
        let g = |m: SMatrix<f64, N, N>| {
            SMatrix::<f64, N, N>::from_columns(&std::array::from_fn::<_, N, _>(|j| {
                let column: [f64; N] = m.column(j).into_owned().into();
                free::position_rates(joints, q, &column).into()
            }))
        };
        Ok((g_w_q + g(w_q), g(w_r)))
    }
}

fn constant<const N: usize>(x: &[f64; N]) -> [DualSVec<f64, N>; N] {
    std::array::from_fn(|j| DualSVec::from_re(x[j]))
}

/// A step's start (q, v, v̇) as (q̇, q̈) in the rates.
pub(super) fn start_in_rates<F: AccelerationField<N>, const N: usize>(
    rates_field: &RatesField<'_, F>,
    q: &[f64; N],
    v: &[f64; N],
    v_dot: &[f64; N],
) -> ([f64; N], [f64; N]) {
    let rates = free::position_rates(rates_field.joints, q, v);
    let qdd = free::rate_accelerations(rates_field.joints, q, &rates, v_dot);
    (rates, qdd)
}

/// A step's end in the velocities: v = B(q) q̇ (q̈ not evaluated).
pub(super) fn accepted_in_velocities<const N: usize>(
    joints: &'static [Joint],
    accepted: Accepted<N>,
) -> Accepted<N> {
    Accepted {
        v: free::velocities_from_rates(joints, &accepted.q, &accepted.v),
        a: None,
        ..accepted
    }
}

/// `step` (a step of Radau5, or the memory at the start) taken in the rates of `field`'s
/// quasi-velocities from `start` (t, q, v, v̇) converted to (t, q, q̇, q̈).
pub(super) fn in_rates<F: AccelerationField<N>, X, const N: usize>(
    field: &F,
    (t, q, v, v_dot): StepStart<'_, N>,
    step: impl FnOnce(&RatesField<'_, F>, StepStart<'_, N>) -> X,
) -> X {
    let rates_field = RatesField {
        field,
        joints: field.quasi_joints(),
    };
    let (rates, qdd) = start_in_rates(&rates_field, q, v, v_dot);
    step(&rates_field, (t, q, &rates, &qdd))
}

/// A step taken [`in_rates`] seen in the velocities: its end's v = B q̇, and its dense output
/// (a polynomial in the rates, which the memory keeps as it is for the next step's starting
/// values) evaluating v.
pub(super) fn in_velocities<const N: usize>(
    joints: &'static [Joint],
    accepted: Result<Accepted<N>>,
    dense: &mut DenseOutput<N>,
) -> Result<Accepted<N>> {
    let accepted = accepted?;
    dense.evaluate_velocities(joints);
    Ok(accepted_in_velocities(joints, accepted))
}
