//! The last step's end and stages, from which the next step's stages are predicted.

use nalgebra::{SMatrix, SVector};

/// The last step's end and velocities, from which the next step's stages are predicted.
#[derive(Clone, Copy, Debug)]
pub(super) struct PreviousStep<const N: usize, const S: usize> {
    pub(super) t_end: f64,
    pub(super) h: f64,
    pub(super) v0: SVector<f64, N>,
    pub(super) stages: [SVector<f64, N>; S],
    /// The stages minus their extrapolation from the step before (zero without one). With h
    /// fixed, the extrapolation error is a smooth function of the state, O(h^(S+1)), that changes
    /// by O(h) of itself from one step to the next: added to the next extrapolation, it leaves a
    /// predictor O(h^(S+2)) from the stages (on the double pendulum at h = 10⁻³, Gauss–Legendre 2's
    /// first Newton increment drops from 4·10⁻⁸ to ~10⁻¹⁰).
    pub(super) extrapolation_error: [SVector<f64, N>; S],
    /// The end state (q₁, v₁, p₁) before any projection: when the next step starts from exactly
    /// (q₁, v₁), its p₀ is p₁, the Gauss method's own sequence on (q, p), not re-evaluated.
    pub(super) q1: SVector<f64, N>,
    pub(super) v1: SVector<f64, N>,
    pub(super) p1: SVector<f64, N>,
    /// M(q₁), which the velocity recovery solved with (a scleronomic mechanism): the next step's
    /// Newton matrix takes it as its ∂p/∂v block.
    pub(super) mass1: Option<SMatrix<f64, N, N>>,
}

impl<const N: usize, const S: usize> PreviousStep<N, S> {
    /// The next step's stage velocities, extrapolated by the polynomial of degree S + 1 through the
    /// last step's velocities v₀, Vᵢ (at cᵢ) and v₁ (at 1) to 1 + cⱼ (Hairer & Wanner, *Solving
    /// ODEs II*, §IV.8, "starting values"): O(h^(S+1)) from the solution (the stage order), where
    /// v₀ + cⱼ h q̈₀ is O(h²). `shift` moves it by the projection's change of v₁.
    pub(super) fn extrapolate(
        &self,
        c: &[f64; S],
        shift: &SVector<f64, N>,
    ) -> [SVector<f64, N>; S] {
        // Nodes 0, c₁…c_S, 1 and their values; Lagrange weights at x.
        let node = |k: usize| match k {
            0 => 0.0,
            k if k <= S => c[k - 1],
            _ => 1.0,
        };
        let value = |k: usize| match k {
            0 => self.v0,
            k if k <= S => self.stages[k - 1],
            _ => self.v1,
        };
        std::array::from_fn(|j| {
            let x = 1.0 + c[j];
            let mut sum = *shift;
            for k in 0..S + 2 {
                let mut w = 1.0;
                for l in 0..S + 2 {
                    if l != k {
                        w *= (x - node(l)) / (node(k) - node(l));
                    }
                }
                sum += value(k) * w;
            }
            sum
        })
    }
}
