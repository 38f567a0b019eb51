//! `Constraints::position_constraint_derivatives` against the dual-number passes it replaces: each
//! model below is declared twice, `WRITTEN = true` with its rows' derivatives written by hand, and
//! `WRITTEN = false` with only g (the dual numbers differentiate it), and every path that builds
//! rows agrees: the rows themselves, q̈ (general and prepared solve), and the projection.

use lagrange_core::affine::AffineConstants;
use lagrange_core::constraints::{
    self, constraint_rows, CartesianMotion, ConstraintKind, ConstraintRows, Constraints, Mode,
};
use lagrange_core::{vec2, Model, Scalar};
use nalgebra::SVector;

/// Agreement of two evaluations of the same formulas in a different order: a few ulps of the
/// largest term (values here are O(1)–O(10)), so 1e-13 absolute is ≈ 100 ulps of 10.
const ROUND_OFF: f64 = 1e-13;

fn close(a: f64, b: f64, what: &str) {
    assert!(
        (a - b).abs() <= ROUND_OFF * (1.0 + a.abs().max(b.abs())),
        "{what}: {a} vs {b}"
    );
}

fn same_rows<const N: usize, const C: usize>(
    a: &ConstraintRows<f64, N, C>,
    b: &ConstraintRows<f64, N, C>,
) {
    for i in 0..C {
        close(a.value[i], b.value[i], "value");
        close(a.rate[i], b.rate[i], "rate");
        close(a.bias[i], b.bias[i], "bias");
        for j in 0..N {
            close(a.rows[i][j], b.rows[i][j], "row");
        }
    }
}

/// A bob on an arm of length 1 at angle θ, and a slider at distance s along x from the bob:
/// x = (sin θ, −cos θ, sin θ + s, −cos θ), not affine. Row 0: the slider at distance L = 1.5
/// from the pivot, written on its rows of x, g = |p| − L with p = (x₂, x₃). Row 1: a unilateral
/// row on the coordinates, c = s sin θ + 1.
struct Slider<const WRITTEN: bool>;

impl<const WRITTEN: bool> Model<2, 4> for Slider<WRITTEN> {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = false;
    const HAS_FORCES: bool = false;
    const HAS_GRAVITY: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 4] {
        [1.0, 1.0, 0.5, 0.5]
    }
    fn weights(&self) -> [f64; 4] {
        [0.0, -9.81, 0.0, -0.5 * 9.81]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let (s, c) = (q[0].sin(), q[0].cos());
        [s, -c, s + q[1], -c]
    }
}

impl<const WRITTEN: bool> Constraints<2, 4, 2> for Slider<WRITTEN> {
    const NAMES: [&'static str; 2] = ["reach", "wall"];
    const KINDS: [ConstraintKind; 2] = [ConstraintKind::Holonomic, ConstraintKind::Unilateral];
    const POSITION_DERIVATIVES: [bool; 2] = [WRITTEN; 2];
    fn position_constraints<D: Scalar>(&self, _t: D, q: &[D; 2], x: &[D; 4]) -> [D; 2] {
        [
            vec2(x[2], x[3]).norm() - D::from(1.5),
            q[1] * q[0].sin() + D::from(1.0),
        ]
    }
    fn position_constraint_derivatives<S: Scalar>(
        &self,
        _t: S,
        q: &[S; 2],
        v: &[S; 2],
        motion: &CartesianMotion<S, 2, 4>,
        rows: &mut ConstraintRows<S, 2, 2>,
    ) {
        // |p| − L: ∂g/∂p = n = p/|p|, ∂²g/∂p² = (I − n nᵀ)/|p|, so along the motion
        // β = (|ṗ|² − (n·ṗ)²)/|p| + n·p̈ and G = nᵀ ∂p/∂q.
        let (p, p_dot, p_accel) = (
            [motion.x[2], motion.x[3]],
            [motion.x_dot[2], motion.x_dot[3]],
            [motion.x_accel[2], motion.x_accel[3]],
        );
        let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
        let n = [p[0] / r, p[1] / r];
        let rate = n[0] * p_dot[0] + n[1] * p_dot[1];
        rows.value[0] = r - S::from(1.5);
        rows.rows[0] = motion.jacobian[2] * n[0] + motion.jacobian[3] * n[1];
        rows.rate[0] = rate;
        rows.bias[0] = (p_dot[0] * p_dot[0] + p_dot[1] * p_dot[1] - rate * rate) / r
            + n[0] * p_accel[0]
            + n[1] * p_accel[1];
        // s sin θ + 1: G = (s cos θ, sin θ), β = 2 cos θ θ̇ ṡ − s sin θ θ̇².
        let (sin, cos) = (q[0].sin(), q[0].cos());
        rows.value[1] = q[1] * sin + S::one();
        rows.rows[1] = SVector::from([q[1] * cos, sin]);
        rows.rate[1] = q[1] * cos * v[0] + sin * v[1];
        rows.bias[1] = cos * v[0] * v[1] * S::from(2.0) - q[1] * sin * v[0] * v[0];
    }
}

/// A particle (x = q, affine) on a rod of driven length L(t) = 1 + 0.2 sin 3t: rheonomic through
/// its constraint, g = |q| − L(t), so ġ = n·q̇ − L̇ and β = (|q̇|² − (n·q̇)²)/|q| − L̈.
struct DrivenRod<const WRITTEN: bool>;

impl<const WRITTEN: bool> Model<2, 2> for DrivenRod<WRITTEN> {
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
}

impl<const WRITTEN: bool> Constraints<2, 2, 1> for DrivenRod<WRITTEN> {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    const POSITION_DERIVATIVES: [bool; 1] = [WRITTEN];
    fn position_constraints<D: Scalar>(&self, t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [vec2(x[0], x[1]).norm() - ((t * 3.0).sin() * 0.2 + 1.0)]
    }
    fn position_constraint_derivatives<S: Scalar>(
        &self,
        t: S,
        q: &[S; 2],
        v: &[S; 2],
        _motion: &CartesianMotion<S, 2, 2>,
        rows: &mut ConstraintRows<S, 2, 1>,
    ) {
        let r = (q[0] * q[0] + q[1] * q[1]).sqrt();
        let n = [q[0] / r, q[1] / r];
        let radial = n[0] * v[0] + n[1] * v[1];
        let three_t = t * 3.0;
        rows.value[0] = r - (three_t.sin() * 0.2 + 1.0);
        rows.rows[0] = SVector::from(n);
        rows.rate[0] = radial - three_t.cos() * 0.6;
        rows.bias[0] = (v[0] * v[0] + v[1] * v[1] - radial * radial) / r + three_t.sin() * 1.8;
    }
}

/// States off the constraints, moving: the rows are compared wherever they are defined.
fn states() -> impl Iterator<Item = (f64, [f64; 2], [f64; 2])> {
    (0..12).map(|i| {
        let k = i as f64;
        (
            0.3 * k,
            [0.4 + 0.5 * k, 0.9 - 0.2 * k],
            [1.3 - 0.4 * k, -0.7 + 0.3 * k],
        )
    })
}

#[test]
fn written_rows_agree_with_the_dual_numbers() {
    for (t, q, v) in states() {
        same_rows(
            &constraint_rows(&Slider::<true>, t, &q, &v),
            &constraint_rows(&Slider::<false>, t, &q, &v),
        );
        same_rows(
            &constraint_rows(&DrivenRod::<true>, t, &q, &v),
            &constraint_rows(&DrivenRod::<false>, t, &q, &v),
        );
    }
}

#[test]
fn accelerations_agree_on_every_path() {
    let constants = [
        AffineConstants::of(&DrivenRod::<true>).unwrap(),
        AffineConstants::of(&DrivenRod::<false>).unwrap(),
    ];
    let all = Mode::all_active::<Slider<true>, 2, 4>();
    for (t, q, v) in states() {
        // The scleronomic slider takes the hyper-dual pass of the equations of motion (both rows
        // enforced, so the written rows reach q̈ whatever c's sign).
        let a = constraints::accelerations_in_mode(&Slider::<true>, t, &q, &v, &all);
        let b = constraints::accelerations_in_mode(&Slider::<false>, t, &q, &v, &all);
        match (a, b) {
            (Ok(a), Ok(b)) => {
                for j in 0..2 {
                    close(a.accelerations[j], b.accelerations[j], "slider q̈");
                }
            }
            (a, b) => assert_eq!(a.is_err(), b.is_err(), "{a:?} vs {b:?}"),
        }
        let a = constraints::accelerations(&DrivenRod::<true>, t, &q, &v).unwrap();
        let b = constraints::accelerations(&DrivenRod::<false>, t, &q, &v).unwrap();
        let c = constraints::accelerations_prepared(&DrivenRod::<true>, &constants[0], t, &q, &v)
            .unwrap();
        let d = constraints::accelerations_prepared(&DrivenRod::<false>, &constants[1], t, &q, &v)
            .unwrap();
        for j in 0..2 {
            close(a[j], b[j], "driven rod q̈");
            close(c[j], d[j], "driven rod q̈, prepared");
            close(a[j], c[j], "driven rod q̈, prepared against general");
        }
    }
}

#[test]
fn projection_agrees() {
    // The projection takes G and g at rest (Newton on q), then G and ġ (the velocity correction).
    for (t, q, v) in states() {
        let mode = Mode::all_active::<DrivenRod<true>, 2, 2>();
        let (mut qa, mut va, mut qb, mut vb) = (q, v, q, v);
        constraints::project(&DrivenRod::<true>, t, &mut qa, &mut va, &mode).unwrap();
        constraints::project(&DrivenRod::<false>, t, &mut qb, &mut vb, &mode).unwrap();
        for j in 0..2 {
            close(qa[j], qb[j], "projected q");
            close(va[j], vb[j], "projected q̇");
        }
    }
}
