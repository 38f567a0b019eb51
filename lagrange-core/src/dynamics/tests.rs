use super::*;
use crate::test_models::test_model_items;

/// The lecture's wedge and block written by hand: rows wedge (X, 0) and block
/// (X + d cos α, h − d sin α). The wedge's height never depends on q (no Jacobian row) and every
/// row is linear in q (no second-order part), so this exercises the sums that skip absent
/// derivatives.
struct Wedge {
    wedge_mass: f64,
    block_mass: f64,
    alpha: f64,
    g: f64,
}

impl Model<2, 4> for Wedge {
    test_model_items!(2; rheonomic: false, potential: false, forces: false, gravity: true);
    fn masses(&self) -> [f64; 4] {
        let (big_m, m) = (self.wedge_mass, self.block_mass);
        [big_m, big_m, m, m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let (s, c) = self.alpha.sin_cos();
        [q[0], D::from(0.0), q[0] + q[1] * c, D::from(1.0) - q[1] * s]
    }
    fn weights(&self) -> [f64; 4] {
        let (big_m, m, g) = (self.wedge_mass, self.block_mass, self.g);
        [0.0, -big_m * g, 0.0, -m * g]
    }
}

#[test]
fn absent_jacobian_rows_and_second_order_parts_are_skipped_not_lost() {
    let p = Wedge {
        wedge_mass: 3.0,
        block_mass: 1.0,
        alpha: 0.5,
        g: 9.81,
    };
    let (s, c) = p.alpha.sin_cos();
    let eom = equations_of_motion(&p, 0.0, &[0.1, 0.2], &[-0.3, 0.5]);
    // By hand: M = [[M + m, m c], [m c, m]], 𝓕 = (0, m g sin α), b = 0 (every row linear).
    let m = p.block_mass;
    let want = [[p.wedge_mass + m, m * c], [m * c, m * (c * c + s * s)]];
    for (r, row) in want.iter().enumerate() {
        for (k, entry) in row.iter().enumerate() {
            // A few roundings of O(1) terms.
            assert!((eom.mass_matrix[(r, k)] - entry).abs() < 1e-15);
        }
    }
    assert_eq!(eom.mass_matrix[(0, 1)], eom.mass_matrix[(1, 0)]);
    assert_eq!(eom.generalized_forces[0], 0.0);
    assert!((eom.generalized_forces[1] - m * p.g * s).abs() < 1e-15);
    assert_eq!(eom.inertial_terms, SVector::<f64, 2>::zeros());
    // And the closed-form accelerations (the lecture's wedge); the 2×2 solve and the closed form
    // round differently, by a few ulps of values of order 1–5.
    let qdd = solve_accelerations::<[f64; 2], f64, 2>(&eom, 0.0, &[0.1, 0.2]).unwrap();
    let den = p.wedge_mass + m * s * s;
    assert!((qdd[0] + m * p.g * s * c / den).abs() < 1e-14);
    assert!((qdd[1] - (p.wedge_mass + m) * p.g * s / den).abs() < 1e-14);
}

/// A bead on a rod shaken along itself and carried up and down: x = (q + A sin ωt, B cos ωt).
/// The second row depends on t only (no Jacobian row, but an acceleration of its own).
struct ShakenRod {
    amplitude: f64,
    lift: f64,
    omega: f64,
}

impl Model<1, 2> for ShakenRod {
    test_model_items!(1; rheonomic: true, potential: false, forces: false, gravity: false);
    fn masses(&self) -> [f64; 2] {
        [2.0, 2.0]
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 2] {
        [
            q[0] + (t * self.omega).sin() * self.amplitude,
            (t * self.omega).cos() * self.lift,
        ]
    }
}

#[test]
fn rheonomic_rows_without_jacobian_do_not_enter_the_inertial_terms() {
    let p = ShakenRod {
        amplitude: 0.3,
        lift: 0.7,
        omega: 2.0,
    };
    let t = 0.4;
    let eom = equations_of_motion(&p, t, &[0.1], &[0.5]);
    // M = m; b = m · d²/dt²(A sin ωt) = −m A ω² sin ωt; the vertical motion does no virtual work.
    assert_eq!(eom.mass_matrix[(0, 0)], 2.0);
    let want = -2.0 * p.amplitude * p.omega * p.omega * (p.omega * t).sin();
    // The second-order dual's sin rule against the formula: a few ulps of |b| ≈ 1.7.
    assert!((eom.inertial_terms[0] - want).abs() < 1e-15);
    assert_eq!(eom.generalized_forces[0], 0.0);
}
