//! Shared by the integration tests: a wrapper model that keeps another model's kinematics, masses
//! and forces, so a test can give the same mechanism other constraints (or none).

/// `delegate_model!(Wrapper(Inner), N, K)`: `impl Model<N, K> for Wrapper` forwarding everything to
/// the wrapped `Inner` in field `.0`.
#[macro_export]
macro_rules! delegate_model {
    ($wrapper:ty, $inner:ty, $n:literal, $k:literal) => {
        impl lagrange_core::Model<$n, $k> for $wrapper {
            type Coords = <$inner as lagrange_core::Model<$n, $k>>::Coords;
            const INERTIAL: usize = <$inner as lagrange_core::Model<$n, $k>>::INERTIAL;
            const RHEONOMIC: bool = <$inner as lagrange_core::Model<$n, $k>>::RHEONOMIC;
            const HAS_POTENTIAL: bool = <$inner as lagrange_core::Model<$n, $k>>::HAS_POTENTIAL;
            const HAS_FORCES: bool = <$inner as lagrange_core::Model<$n, $k>>::HAS_FORCES;
            const HAS_GRAVITY: bool = <$inner as lagrange_core::Model<$n, $k>>::HAS_GRAVITY;
            fn validate(&self) -> lagrange_core::Result<()> {
                lagrange_core::Model::validate(&self.0)
            }
            fn masses(&self) -> [f64; $k] {
                self.0.masses()
            }
            fn weights(&self) -> [f64; $k] {
                self.0.weights()
            }
            fn cartesian<D: lagrange_core::Scalar>(&self, t: D, q: &[D; $n]) -> [D; $k] {
                self.0.cartesian(t, q)
            }
            fn potential<D: lagrange_core::Scalar>(&self, t: D, q: &[D; $n], x: &[D; $k]) -> D {
                self.0.potential(t, q, x)
            }
            fn applied_forces<S: lagrange_core::Scalar>(
                &self,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
                x: &[S; $k],
                x_dot: &[S; $k],
                cartesian_force: &mut [S; $k],
                generalized_force: &mut [S; $n],
            ) {
                self.0
                    .applied_forces(t, q, v, x, x_dot, cartesian_force, generalized_force)
            }
        }
    };
}

/// q̈ = q² (V = −q³/3, unit mass): from q = 1, q̇ = √(2/3) (zero energy) the solution
/// q = 6/(√6 − t)² blows up at t = √6.
#[allow(dead_code)]
pub struct BlowUp;

impl lagrange_core::Model<1, 1> for BlowUp {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 1] {
        [1.0]
    }
    fn cartesian<D: lagrange_core::Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 1] {
        [q[0]]
    }
    fn potential<D: lagrange_core::Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 1]) -> D {
        -(x[0] * x[0] * x[0]) / 3.0
    }
}
lagrange_core::impl_mechanism!(BlowUp, 1, 1);
