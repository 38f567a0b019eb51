//! The prepared constrained solve (`constraints::accelerations_prepared`) for a constraint that reads
//! time on affine positions: its rows take ∂/∂t as well, and q̈ agrees with the general path.

use lagrange_core::affine::AffineConstants;
use lagrange_core::constraints::{self, ConstraintKind, Constraints};
use lagrange_core::{vec2, Model, Scalar};

/// A particle in Cartesian coordinates (x = q, affine, independent of t) on a rod whose length is
/// driven, L(t) = 1 + 0.2 sin 3t: the constraint, not the positions, makes the mechanism rheonomic.
struct DrivenRod;

impl Model<2, 2> for DrivenRod {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = false;
    const HAS_FORCES: bool = false;
    const HAS_GRAVITY: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [0.8, 0.8]
    }
    fn weights(&self) -> [f64; 2] {
        [0.0, -0.8 * 9.81]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> D {
        D::zero()
    }
}

impl Constraints<2, 2, 1> for DrivenRod {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - ((t * 3.0).sin() * 0.2 + 1.0)]
    }
}

#[test]
fn a_driven_constraint_on_affine_positions_agrees_with_the_general_path() {
    let constants = AffineConstants::of(&DrivenRod).unwrap();
    for i in 0..10 {
        let t = 0.37 * i as f64;
        let length = 1.0 + 0.2 * (3.0 * t).sin();
        let angle = 0.4 + 0.6 * i as f64;
        let q = [length * angle.sin(), -length * angle.cos()];
        // Along the rod at its rate L̇ = 0.6 cos 3t, plus a swing across it.
        let rate = 0.6 * (3.0 * t).cos();
        let v = [
            rate * angle.sin() + 1.1 * angle.cos(),
            -rate * angle.cos() + 1.1 * angle.sin(),
        ];
        let prepared =
            constraints::accelerations_prepared(&DrivenRod, &constants, t, &q, &v).unwrap();
        let direct = constraints::accelerations(&DrivenRod, t, &q, &v).unwrap();
        // The same Schur solve; the constraint's ∂²g/∂t² term (−L̈ ≈ 1.8 sin 3t) enters β either way.
        // M = 0.8 I is factorised with the same operations, so agreement is to a few ulps of |q̈| ≈ 10.
        for j in 0..2 {
            assert!(
                (prepared[j] - direct[j]).abs() <= 1e-13,
                "t = {t}: {prepared:?} vs {direct:?}"
            );
        }
        // The driven length is what the multiplier enforces: on the constraint r̈ = L̈, so the
        // radial acceleration is L̈ − L θ̇², with θ̇ = 1.1/L (the swing across the rod); round-off
        // of the solve only, a few ulps of |q̈| ≈ 10.
        let n = [angle.sin(), -angle.cos()];
        let radial = prepared[0] * n[0] + prepared[1] * n[1];
        let omega = 1.1 / length;
        let expected = -1.8 * (3.0 * t).sin() - length * omega * omega;
        assert!(
            (radial - expected).abs() <= 1e-12,
            "t = {t}: radial {radial} vs {expected}"
        );
    }
}
