//! A mechanism whose velocities are quasi-velocities (a free or ball joint's angular velocity,
//! q̇ = G(q) v, `Dynamics::QUASI_VELOCITIES`) seen in its coordinates' rates ([`InRates`]): what
//! the methods on momenta conjugate to q̇ step (implicit midpoint, Gauss–Legendre, the
//! variational integrator, converting at a step's ends) and what the analyses at rest linearize
//! (stiffness and mass in the coordinates, where δq̇ = G δv would otherwise stand between them).
//! A method that reads the mechanism only through its evaluations at (q, q̇) then computes exactly
//! what it computes on the same declaration written with the chart's rates for velocities: one
//! motion, two descriptions.

use super::{momentum_rate, Constants, Dynamics, Evaluate};
use crate::dynamics::EquationsOfMotion;
use crate::error::Result;
use crate::geometry::Scalar;
use crate::tree::rigid::free;
use nalgebra::SMatrix;

/// The mechanism `M` with the coordinates' rates q̇ for velocities. With v = B q̇ (B = G⁻¹), every
/// quantity is the mechanism's converted (see [`crate::tree::rigid::free`]):
///
/// ```text
/// T(q, q̇) = T_v(q, B q̇),   p = Bᵀ p_v,   𝓕 = Bᵀ 𝓕_v,   M = Bᵀ M_v B,
/// b = Bᵀ (b_v + M_v Ḃ q̇),   q̈ = G (v̇ − Ḃ q̇),   τ = Bᵀ τ_v(q, v, B q̈ + Ḃ q̇),
/// ```
///
/// the last three from M_v v̇ + b_v = 𝓕_v with v̇ = B q̈ + Ḃ q̇, multiplied by Bᵀ. The canonical
/// field is the generic one of these ([`momentum_rate`]: ∂T/∂q at fixed q̇ by
/// dual numbers through T(q, B(q) q̇)).
pub(crate) struct InRates<'m, M>(pub(crate) &'m M);

/// The joints whose velocities are angular velocities, among `M`'s.
#[inline(always)]
fn joints<M: Evaluate<N>, const N: usize>() -> &'static [crate::tree::rigid::Joint] {
    <M::Model as Dynamics<N>>::QUASI_VELOCITY_JOINTS
}

/// v = B q̇.
#[inline(always)]
pub(crate) fn velocities<M: Evaluate<N>, S: Scalar, const N: usize>(
    q: &[S; N],
    rates: &[S; N],
) -> [S; N] {
    free::velocities_from_rates(joints::<M, N>(), q, rates)
}

/// Bᵀ x.
#[inline(always)]
fn to_rates<M: Evaluate<N>, S: Scalar, const N: usize>(q: &[S; N], x: &[S; N]) -> [S; N] {
    free::rate_forces(joints::<M, N>(), q, x)
}

impl<M: Evaluate<N>, const N: usize> Evaluate<N> for InRates<'_, M> {
    type Model = M::Model;
    type Coords = M::Coords;
    const CONSTRAINT_COUNTS: Option<crate::constraints::ConstraintCounts> = M::CONSTRAINT_COUNTS;
    const CONSTRAINTS: Option<usize> = M::CONSTRAINTS;
    const SCLERONOMIC: bool = M::SCLERONOMIC;
    const QUASI_VELOCITIES: bool = false;
    const ONE_BRANCH: bool = false;

    #[inline(always)]
    fn model(&self) -> &M::Model {
        self.0.model()
    }
    #[inline(always)]
    fn prepared(&self) -> Constants<'_, M::Model> {
        self.0.prepared()
    }
    #[inline(always)]
    fn position_rates_at<S: Scalar>(&self, _q: &[S; N], rates: &[S; N]) -> [S; N] {
        *rates
    }
    fn equations_of_motion_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        rates: &[S; N],
    ) -> EquationsOfMotion<S, N> {
        let v = velocities::<M, S, N>(q, rates);
        let eom = self.0.equations_of_motion_at(t, q, &v);
        free::equations_in_rates(joints::<M, N>(), q, rates, eom)
    }
    fn mass_matrix_at<S: Scalar>(&self, t: S, q: &[S; N]) -> SMatrix<S, N, N> {
        free::congruent(joints::<M, N>(), q, &self.0.mass_matrix_at(t, q))
    }
    fn accelerations_at<S: Scalar>(&self, t: S, q: &[S; N], rates: &[S; N]) -> Result<[S; N]> {
        let v = velocities::<M, S, N>(q, rates);
        let v_dot = self.0.accelerations_at(t, q, &v)?;
        Ok(free::rate_accelerations(joints::<M, N>(), q, rates, &v_dot))
    }
    fn regular_accelerations_at(&self, _: f64, _: &[f64; N], _: &[f64; N]) -> Option<[f64; N]> {
        None
    }
    fn inverse_dynamics_at<S: Scalar>(
        &self,
        t: S,
        q: &[S; N],
        rates: &[S; N],
        qdd: &[S; N],
    ) -> [S; N] {
        let v = velocities::<M, S, N>(q, rates);
        let v_dot = free::velocity_accelerations(joints::<M, N>(), q, rates, qdd);
        to_rates::<M, S, N>(q, &self.0.inverse_dynamics_at(t, q, &v, &v_dot))
    }
    fn kinetic_energy_at<S: Scalar>(&self, t: S, q: &[S; N], rates: &[S; N]) -> S {
        self.0
            .kinetic_energy_at(t, q, &velocities::<M, S, N>(q, rates))
    }
    fn momenta_at<S: Scalar>(&self, t: S, q: &[S; N], rates: &[S; N]) -> [S; N] {
        let p = self.0.momenta_at(t, q, &velocities::<M, S, N>(q, rates));
        to_rates::<M, S, N>(q, &p)
    }
    fn lagrangian_time_derivative_at(&self, t: f64, q: &[f64; N], rates: &[f64; N]) -> f64 {
        self.0
            .lagrangian_time_derivative_at(t, q, &velocities::<M, f64, N>(q, rates))
    }
    fn canonical_field_at<S: Scalar>(&self, t: S, q: &[S; N], rates: &[S; N]) -> ([S; N], [S; N]) {
        let rate = momentum_rate(self, t, q, rates);
        (self.momenta_at(t, q, rates), rate)
    }
    #[inline(always)]
    fn holonomic_constraints_at<S: Scalar>(&self, t: S, q: &[S; N]) -> Option<[S; N]> {
        self.0.holonomic_constraints_at(t, q)
    }
    #[inline(always)]
    fn enforced_holonomic_rows(&self) -> Option<usize> {
        self.0.enforced_holonomic_rows()
    }
    /// The mechanism's projection of (q, v = B q̇), its q̇ = G v back (the same projection: see
    /// `constraints::quasi`).
    fn project(&self, t: f64, q: &mut [f64; N], rates: &mut [f64; N]) -> Result<()> {
        let mut v = velocities::<M, f64, N>(q, rates);
        self.0.project(t, q, &mut v)?;
        *rates = self.0.position_rates_at(q, &v);
        Ok(())
    }
    fn check_constraints(&self, t: f64, q: &[f64; N], rates: &[f64; N]) -> Result<()> {
        self.0
            .check_constraints(t, q, &velocities::<M, f64, N>(q, rates))
    }
    fn check_declaration_at(&self, t: f64, q: &[f64; N], rates: &[f64; N]) -> Result<()> {
        self.0
            .check_declaration_at(t, q, &velocities::<M, f64, N>(q, rates))
    }
    fn switch_charts<S: Scalar>(&self, _: &mut [S; N], _: &mut [S; N]) -> bool {
        // The loop switches the mechanism's charts, on its own velocities, after converting back.
        false
    }
}
