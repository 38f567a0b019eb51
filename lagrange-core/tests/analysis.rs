//! Statics and small oscillations (`lagrange_core::analysis`) on hand-written models (what
//! `#[mechanism]` generates), against closed forms.

use lagrange_core::analysis::{
    continuation, equilibrium, linearize, normal_modes, stability, unbalanced_forces,
    EquilibriumOptions, Stability, StabilityMethod,
};
#[macro_use]
mod support;

use lagrange_core::evaluation::Evaluate as _;
use lagrange_core::impl_mechanism;
use lagrange_core::{Error, Mechanism, Model, Rk4, Scalar, State};
use nalgebra::SMatrix;
use std::f64::consts::PI;

fn finite(parameters: &[(&'static str, f64)]) -> lagrange_core::Result<()> {
    for &(name, value) in parameters {
        if !value.is_finite() {
            return Err(Error::NonFiniteParameter { name, value });
        }
    }
    Ok(())
}

fn close(got: f64, want: f64, rel: f64) -> bool {
    (got - want).abs() <= rel * want.abs().max(1e-300)
}

// ---------------------------------------------------------------------------------------------
// 1. The lecture's wedge and block.
// ---------------------------------------------------------------------------------------------

/// Wedge (mass `big_m`) on a frictionless floor, block (mass `m`) on its frictionless incline of
/// angle `alpha`, a horizontal force `force` on the wedge. Coordinates (X, d) as in the lecture's
/// eqs. (27)–(28): r₁ = (X, 0), r₂ = (X + d cos α, h − d sin α).
struct WedgeBlock {
    big_m: f64,
    m: f64,
    alpha: f64,
    h: f64,
    g: f64,
    force: f64,
}

impl Model<2, 4> for WedgeBlock {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("M", self.big_m),
            ("m", self.m),
            ("alpha", self.alpha),
            ("h", self.h),
            ("g", self.g),
            ("F", self.force),
        ])
    }
    fn masses(&self) -> [f64; 4] {
        [self.big_m, self.big_m, self.m, self.m]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        [
            q[0],
            D::zero(),
            q[0] + q[1] * self.alpha.cos(),
            D::from(self.h) - q[1] * self.alpha.sin(),
        ]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        (x[1] * self.big_m + x[3] * self.m) * self.g
    }
    fn applied_forces<S: Scalar>(
        &self,
        _t: S,
        _q: &[S; 2],
        _v: &[S; 2],
        _x: &[S; 4],
        _x_dot: &[S; 4],
        cartesian_force: &mut [S; 4],
        _generalized_force: &mut [S; 2],
    ) {
        cartesian_force[0] = S::from(self.force);
    }
}
impl_mechanism!(WedgeBlock, 2, 4);

/// The block alone, described in the frame of a wedge that moves with constant acceleration A:
/// X(t) = ½At² is prescribed (rheonomic), d is the only coordinate. At rest relative to the wedge
/// (ḋ = 0) −b is the d'Alembert inertial force −m A of the accelerating frame.
struct BlockInAcceleratingWedge {
    m: f64,
    alpha: f64,
    h: f64,
    g: f64,
    acceleration: f64,
}

impl Model<1, 2> for BlockInAcceleratingWedge {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("m", self.m),
            ("alpha", self.alpha),
            ("h", self.h),
            ("g", self.g),
            ("A", self.acceleration),
        ])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m; 2]
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 2] {
        let wedge = t * t * (0.5 * self.acceleration);
        [
            wedge + q[0] * self.alpha.cos(),
            D::from(self.h) - q[0] * self.alpha.sin(),
        ]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}
impl_mechanism!(BlockInAcceleratingWedge, 1, 2);

#[test]
fn wedge_force_that_holds_the_block_by_virtual_work() {
    let (big_m, m, alpha, h, g) = (3.0, 1.0, 0.5f64, 1.0, 9.81);
    let closed_form = (big_m + m) * g * alpha.tan();
    let free = WedgeBlock {
        big_m,
        m,
        alpha,
        h,
        g,
        force: 0.0,
    };
    let q = [0.2, 0.4];

    // The lecture's generalized forces, eqs. (31)–(32): 𝓕_X = 0, 𝓕_d = m g sin α (at rest, F = 0).
    let f = unbalanced_forces(&free, 0.0, &q).unwrap();
    assert!(f[0].abs() < 1e-15, "{f:?}");
    assert!(close(f[1], m * g * alpha.sin(), 1e-15), "{f:?}");

    // With F on the wedge, 𝓕 = (F, m g sin α) and q̈ = M⁻¹𝓕: F enters through ∂q̈/∂u = M⁻¹, the input
    // matrix of a generalized force on X (F acts horizontally on the wedge, ∂r₁/∂X = (1, 0)).
    // The block is at rest relative to the wedge when d̈ = (M⁻¹𝓕)_d + (M⁻¹)_{dX} F = 0.
    let lin = linearize(&free, &State::at_rest(q)).unwrap();
    let force = -lin.accelerations[1] / lin.dqdd_du[(1, 0)];
    // Both sides are a 2×2 solve of O(1) numbers: agreement to a few ulps.
    assert!(
        close(force, closed_form, 1e-14),
        "F = {force}, (M + m) g tan α = {closed_form}"
    );

    // The whole system then accelerates rigidly with Ẍ = g tan α and d̈ = 0.
    let held = WedgeBlock { force, ..free };
    let qdd = held.accelerations(&State::at_rest(q)).unwrap();
    assert!(qdd[1].abs() < 1e-14 * g, "d̈ = {}", qdd[1]);
    assert!(close(qdd[0], g * alpha.tan(), 1e-14), "Ẍ = {}", qdd[0]);

    // The lecture's other reading: equilibrium of the block in the wedge's accelerating frame. There
    // the virtual work per δd is m g sin α − m A cos α (gravity and the d'Alembert force −m A); it is
    // affine in A, so two evaluations give the A that balances it, and F = (M + m) A.
    let frame = |acceleration| BlockInAcceleratingWedge {
        m,
        alpha,
        h,
        g,
        acceleration,
    };
    let r0 = unbalanced_forces(&frame(0.0), 0.0, &[0.4]).unwrap()[0];
    let r1 = unbalanced_forces(&frame(1.0), 0.0, &[0.4]).unwrap()[0];
    assert!(close(r0, m * g * alpha.sin(), 1e-15) && close(r1 - r0, -m * alpha.cos(), 1e-14));
    let a_star = -r0 / (r1 - r0);
    assert!(
        close((big_m + m) * a_star, closed_form, 1e-14),
        "F = {}",
        (big_m + m) * a_star
    );

    // At that acceleration every d is an equilibrium (neutral, K = 0): the search stops at the guess,
    // and stability cannot be decided at linear order.
    let options = EquilibriumOptions::default();
    let eq = equilibrium(&frame(a_star), 0.0, &[0.7], &options).unwrap();
    assert_eq!((eq.q, eq.iterations), ([0.7], 0));
    assert_eq!(
        stability(&frame(a_star), 0.0, &[0.7]).unwrap().stability,
        Stability::Marginal
    );
    // At any other acceleration there is none: a typed error, not a wrong answer.
    let err = equilibrium(&frame(1.1 * a_star), 0.0, &[0.7], &options).unwrap_err();
    assert!(matches!(err, Error::EquilibriumNotFound { .. }), "{err}");
}

// ---------------------------------------------------------------------------------------------
// 2. A bead on a spinning hoop.
// ---------------------------------------------------------------------------------------------

/// A bead of mass m on a hoop of radius R spun about its vertical diameter at the constant rate ω;
/// θ from the bottom: x = R sin θ cos ωt, y = R sin θ sin ωt, z = −R cos θ (rheonomic).
#[derive(Clone, Copy)]
struct Hoop {
    m: f64,
    r: f64,
    g: f64,
    omega: f64,
}

impl Model<1, 3> for Hoop {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("m", self.m),
            ("R", self.r),
            ("g", self.g),
            ("omega", self.omega),
        ])
    }
    fn masses(&self) -> [f64; 3] {
        [self.m; 3]
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 1]) -> [D; 3] {
        let spin = t * self.omega;
        let rho = q[0].sin() * self.r;
        [rho * spin.cos(), rho * spin.sin(), -q[0].cos() * self.r]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 3]) -> D {
        x[2] * (self.m * self.g)
    }
}
impl_mechanism!(Hoop, 1, 3);

const M_BEAD: f64 = 0.2;
const R_HOOP: f64 = 0.5;
const G: f64 = 9.81;

fn hoop(omega: f64) -> Hoop {
    Hoop {
        m: M_BEAD,
        r: R_HOOP,
        g: G,
        omega,
    }
}

// Closed forms from the effective potential V_eff = −m g R cos θ − ½ m R² ω² sin²θ with the mass
// m R²: V_eff' = m R sin θ (g − ω² R cos θ), V_eff'' = m g R cos θ − m R² ω² cos 2θ. At θ = 0,
// ω₀² = V_eff''/(m R²) = g/R − ω²; at cos θ* = g/(ω² R), V_eff'' = m R² ω² sin²θ*, so
// ω_osc² = ω² sin²θ* = ω² − g²/(ω² R²).

#[test]
fn hoop_bottom_is_stable_below_critical_spin() {
    let omega = 3.0; // ω² = 9 < g/R = 19.62
    let h = hoop(omega);
    let eq = equilibrium(&h, 0.0, &[0.4], &EquilibriumOptions::default()).unwrap();
    // Newton on r(θ) = −m R sin θ (g − ω²R cos θ): quadratic convergence to θ = 0; the step test
    // stops once |δθ| ≤ 1e-12, so what is left is ~|δθ|² (or exact zero).
    assert!(eq.q[0].abs() < 1e-12, "θ* = {}", eq.q[0]);
    let s = stability(&h, 0.0, &eq.q).unwrap();
    assert_eq!(
        (s.stability, s.method),
        (Stability::Stable, StabilityMethod::Potential)
    );
    let modes = normal_modes(&h, 0.0, &eq.q).unwrap();
    let want = G / R_HOOP - omega * omega;
    // K and M come from exact derivatives; ω₀² is a difference of two O(20) numbers giving ~10.6,
    // so a few ulps of 20 relative to 10.6: 1e-14 is generous.
    assert!(
        close(modes.frequencies[0].powi(2), want, 1e-14),
        "ω₀² = {} vs {want}",
        modes.frequencies[0].powi(2)
    );
}

#[test]
fn hoop_off_bottom_equilibria_above_critical_spin() {
    let omega = 6.0; // ω² = 36 > g/R = 19.62
    let h = hoop(omega);
    let cos_star = G / (omega * omega * R_HOOP);
    let freq2 = omega * omega - G * G / (omega * omega * R_HOOP * R_HOOP);
    for guess in [1.0, -1.0, 0.7, 1.5] {
        let eq = equilibrium(&h, 0.0, &[guess], &EquilibriumOptions::default()).unwrap();
        // cos θ* from a root found to ~1e-16 in θ: |δ cos| ≤ sin θ* |δθ|.
        assert!(
            (eq.q[0].cos() - cos_star).abs() < 1e-14,
            "guess {guess}: θ* = {}",
            eq.q[0]
        );
        assert_eq!(eq.q[0].signum(), guess.signum());
        assert_eq!(
            stability(&h, 0.0, &eq.q).unwrap().stability,
            Stability::Stable
        );
        let modes = normal_modes(&h, 0.0, &eq.q).unwrap();
        assert!(
            close(modes.frequencies[0].powi(2), freq2, 1e-13),
            "ω² = {} vs {freq2}",
            modes.frequencies[0].powi(2)
        );
    }
    // The bottom is still an equilibrium, now unstable: λ = g/R − ω² < 0.
    let bottom = stability(&h, 0.0, &[0.0]).unwrap();
    assert_eq!(bottom.stability, Stability::Unstable);
    assert!(close(
        bottom.stiffness_eigenvalues[0],
        G / R_HOOP - omega * omega,
        1e-14
    ));
    let err = normal_modes(&h, 0.0, &[0.0]).unwrap_err();
    assert!(matches!(err, Error::NoNormalModes { .. }), "{err}");
    // The stiffness K = ∂(b − 𝓕)/∂θ at θ* is V_eff'' = m R² ω² sin²θ*.
    let eq = equilibrium(&h, 0.0, &[1.0], &EquilibriumOptions::default()).unwrap();
    let k = M_BEAD * R_HOOP * R_HOOP * omega * omega * (1.0 - cos_star * cos_star);
    assert!(
        close(eq.stiffness[(0, 0)], k, 1e-13),
        "K = {} vs {k}",
        eq.stiffness[(0, 0)]
    );
    // The same equilibrium at a later time (the hoop has turned): rheonomic, but steady.
    let later = equilibrium(&h, 0.37, &[1.0], &EquilibriumOptions::default()).unwrap();
    assert!((later.q[0].cos() - cos_star).abs() < 1e-14);
}

#[test]
fn hoop_at_critical_spin_is_marginal() {
    let h = hoop((G / R_HOOP).sqrt());
    let s = stability(&h, 0.0, &[0.0]).unwrap();
    assert_eq!(
        s.stability,
        Stability::Marginal,
        "λ = {:?}",
        s.stiffness_eigenvalues
    );
    assert!(matches!(
        normal_modes(&h, 0.0, &[0.0]),
        Err(Error::NoNormalModes { .. })
    ));
}

#[test]
fn hoop_bifurcation_by_continuation() {
    let critical = (G / R_HOOP).sqrt();
    // The off-bottom branch, from fast spin down through the pitchfork at ω_c = √(g/R).
    let omegas: Vec<f64> = (0..=60)
        .map(|i| critical * (2.5 - 0.03 * i as f64))
        .collect();
    let branch = continuation(hoop, &omegas, 0.0, &[1.3], &EquilibriumOptions::default());
    assert!(branch.stopped.is_none(), "{:?}", branch.stopped);
    assert_eq!(branch.points.len(), omegas.len());
    println!("  ω/ω_c   θ* (rad)   stability   closed form θ*");
    for p in &branch.points {
        let omega = p.parameter;
        let theta = p.equilibrium.q[0];
        let want = if omega > critical {
            (G / (omega * omega * R_HOOP)).acos()
        } else {
            0.0
        };
        println!(
            "  {:5.2}   {theta:8.5}   {:?}   {want:8.5}",
            omega / critical,
            p.stability
        );
        if omega > 1.05 * critical {
            assert!(
                (theta - want).abs() < 1e-12,
                "ω = {omega}: θ* = {theta}, want {want}"
            );
            assert_eq!(p.stability, Stability::Stable);
        } else if omega < 0.95 * critical {
            // Below ω_c the branch has merged into the bottom, which is stable again.
            assert!(theta.abs() < 1e-10, "ω = {omega}: θ* = {theta}");
            assert_eq!(p.stability, Stability::Stable);
        } else {
            // Within 5 % of the pitchfork θ* ∝ √(ω − ω_c) is steep, and at ω_c itself the root is
            // triple (r ∝ θ³): Newton converges only linearly there and the residual reaches its
            // tolerance (1e-14 of the terms, relative) at θ ~ (1e-14)^(1/3) ≈ 2e-5. Hence 1e-4.
            assert!(
                (theta - want).abs() < 1e-4,
                "ω = {omega}: θ* = {theta}, want {want}"
            );
        }
    }
    // The bottom branch over the same range: stable below ω_c, unstable above.
    let bottom = continuation(hoop, &omegas, 0.0, &[0.0], &EquilibriumOptions::default());
    assert!(bottom.stopped.is_none());
    for p in &bottom.points {
        assert_eq!(p.equilibrium.q, [0.0]);
        let want = if p.parameter > 1.01 * critical {
            Stability::Unstable
        } else if p.parameter < 0.99 * critical {
            Stability::Stable
        } else {
            p.stability
        };
        assert_eq!(p.stability, want, "ω = {}", p.parameter);
    }
}

// ---------------------------------------------------------------------------------------------
// 3. and 5. The double pendulum.
// ---------------------------------------------------------------------------------------------

struct DoublePendulum {
    m: f64,
    l: f64,
    g: f64,
}

impl Model<2, 4> for DoublePendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("l", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 4] {
        [self.m; 4]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let (x1, y1) = (q[0].sin() * self.l, -q[0].cos() * self.l);
        [x1, y1, x1 + q[1].sin() * self.l, y1 - q[1].cos() * self.l]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        (x[1] + x[3]) * (self.m * self.g)
    }
}
impl_mechanism!(DoublePendulum, 2, 4);

const DP: DoublePendulum = DoublePendulum {
    m: 0.7,
    l: 1.3,
    g: 9.81,
};

#[test]
fn double_pendulum_normal_modes() {
    let eq = equilibrium(&DP, 0.0, &[0.3, -0.2], &EquilibriumOptions::default()).unwrap();
    assert!(eq.q.iter().all(|x| x.abs() < 1e-12), "{:?}", eq.q);
    let modes = normal_modes(&DP, 0.0, &eq.q).unwrap();
    let unit = (DP.g / DP.l).sqrt();
    // Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §6.4 (two coupled pendula) gives
    // ω² = (2 ∓ √2) g/l for equal masses and lengths, with shapes θ₂/θ₁ = ±√2.
    let want = [
        (2.0 - 2f64.sqrt()).sqrt() * unit,
        (2.0 + 2f64.sqrt()).sqrt() * unit,
    ];
    for (j, want) in want.into_iter().enumerate() {
        // A 2×2 symmetric eigenproblem from exact derivatives: ~1e-15 relative.
        assert!(
            close(modes.frequencies[j], want, 1e-14),
            "ω{j} = {} vs {want}",
            modes.frequencies[j],
        );
    }
    let ratio = |j: usize| modes.shapes[(1, j)] / modes.shapes[(0, j)];
    assert!(close(ratio(0), 2f64.sqrt(), 1e-13) && close(ratio(1), -(2f64.sqrt()), 1e-13));
    // M-orthonormal shapes.
    let m = DP.mass_matrix(&State::at_rest([0.0, 0.0])).unwrap();
    let gram = modes.shapes.transpose() * m * modes.shapes;
    assert!(
        (gram - SMatrix::<f64, 2, 2>::identity()).norm() < 1e-14,
        "{gram}"
    );
    // The other equilibria are unstable (one pendulum or both upside down).
    for q in [[PI, 0.0], [0.0, PI], [PI, PI]] {
        assert_eq!(
            stability(&DP, 0.0, &q).unwrap().stability,
            Stability::Unstable,
            "{q:?}"
        );
    }
}

/// RK4 on the linear system d/dt (δq, δv) = (δv, A_qq δq + A_qv δv).
fn rk4_linear(
    a_qq: &SMatrix<f64, 2, 2>,
    a_qv: &SMatrix<f64, 2, 2>,
    x: [nalgebra::Vector2<f64>; 2],
    h: f64,
) -> [nalgebra::Vector2<f64>; 2] {
    let f = |[q, v]: [nalgebra::Vector2<f64>; 2]| [v, a_qq * q + a_qv * v];
    let add = |[q, v]: [nalgebra::Vector2<f64>; 2],
               s: f64,
               [dq, dv]: [nalgebra::Vector2<f64>; 2]| [q + dq * s, v + dv * s];
    let k1 = f(x);
    let k2 = f(add(x, 0.5 * h, k1));
    let k3 = f(add(x, 0.5 * h, k2));
    let k4 = f(add(x, h, k3));
    let mut out = x;
    for i in 0..2 {
        out[i] += (k1[i] + (k2[i] + k3[i]) * 2.0 + k4[i]) * (h / 6.0);
    }
    out
}

#[test]
fn linearized_double_pendulum_agrees_to_second_order_in_amplitude() {
    let lin = linearize(&DP, &State::at_rest([0.0, 0.0])).unwrap();
    assert_eq!(lin.accelerations, [0.0, 0.0]);
    assert!(lin.dqdd_dv.norm() == 0.0); // no velocity terms at rest for a scleronomic conservative system
    let a = lin.a_matrix();
    assert_eq!(a.shape(), (4, 4));
    // One test of the assembled A: its lower-left block is −M⁻¹K.
    assert_eq!(a[(2, 0)], lin.dqdd_dq[(0, 0)]);
    assert_eq!(a[(0, 2)], 1.0);

    // Start from rest at ε·(1, −0.7) (a mix of both modes), run both for 3 s (several periods of the
    // slow mode, T ≈ 3 s) with h = 1e-3 and record the largest relative deviation. RK4's own error,
    // (hω)⁴·ωT ~ 1e-12 relative, is the same for both runs to O(ε²) and far below the ε² effect.
    let h = 1e-3;
    let steps = 3000;
    let deviation = |eps: f64| -> f64 {
        let (mut q, mut v) = ([eps, -0.7 * eps], [0.0, 0.0]);
        let mut x = [
            nalgebra::Vector2::new(eps, -0.7 * eps),
            nalgebra::Vector2::zeros(),
        ];
        let mut worst = 0.0f64;
        for i in 0..steps {
            (q, v) = Rk4::step_arrays(&DP, i as f64 * h, &q, &v, h).unwrap();
            x = rk4_linear(&lin.dqdd_dq, &lin.dqdd_dv, x, h);
            worst = worst.max((q[0] - x[0][0]).abs().max((q[1] - x[0][1]).abs()));
        }
        worst / eps
    };
    let amplitudes = [0.08, 0.04, 0.02, 0.01];
    let relative: Vec<f64> = amplitudes.iter().map(|&e| deviation(e)).collect();
    println!("amplitude  relative deviation  ratio to previous");
    for (i, (e, d)) in amplitudes.iter().zip(&relative).enumerate() {
        let ratio = if i > 0 { relative[i - 1] / d } else { f64::NAN };
        println!("{e:9.3}  {d:18.3e}  {ratio:8.4}");
    }
    // The nonlinear terms are cubic (sin θ = θ − θ³/6, cos(θ₁ − θ₂) = 1 − …), so the relative
    // deviation is C ε² + O(ε⁴): halving ε divides it by 4 (1 ± 0.05 covers the O(ε²) correction,
    // which is a few per cent at ε = 0.08 and shrinks fourfold each halving).
    for i in 1..relative.len() {
        let ratio = relative[i - 1] / relative[i];
        assert!(
            (ratio - 4.0).abs() < 0.2,
            "ratio {ratio} at ε = {}",
            amplitudes[i]
        );
    }
    assert!(
        relative[0] < 0.1,
        "linearization is poor even at ε = 0.08: {}",
        relative[0]
    );
}

// ---------------------------------------------------------------------------------------------
// 4. A chain of masses and springs between two walls.
// ---------------------------------------------------------------------------------------------

const CHAIN: usize = 10;

/// N = 10 masses m on a line, joined to each other and to walls at 0 and (N + 1)a by N + 1 springs
/// of stiffness κ and natural length a; qᵢ is the displacement of mass i from its rest position.
struct Chain {
    m: f64,
    kappa: f64,
    a: f64,
}

impl Model<CHAIN, CHAIN> for Chain {
    type Coords = [f64; CHAIN];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("kappa", self.kappa), ("a", self.a)])
    }
    fn masses(&self) -> [f64; CHAIN] {
        [self.m; CHAIN]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; CHAIN]) -> [D; CHAIN] {
        std::array::from_fn(|i| q[i] + self.a * (i + 1) as f64)
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; CHAIN], x: &[D; CHAIN]) -> D {
        let mut v = D::zero();
        let mut left = D::zero();
        for &xi in x
            .iter()
            .chain(std::iter::once(&D::from(self.a * (CHAIN + 1) as f64)))
        {
            let stretch = xi - left - self.a;
            v += stretch * stretch * (0.5 * self.kappa);
            left = xi;
        }
        v
    }
}
impl_mechanism!(Chain, CHAIN, CHAIN);

#[test]
fn spring_chain_normal_modes() {
    let chain = Chain {
        m: 0.3,
        kappa: 40.0,
        a: 0.25,
    };
    let guess: [f64; CHAIN] = std::array::from_fn(|i| 0.05 * (i as f64).sin());
    let eq = equilibrium(&chain, 0.0, &guess, &EquilibriumOptions::default()).unwrap();
    // Linear forces: Newton lands on the root in one step (up to rounding of the step).
    assert!(eq.iterations <= 2, "{} iterations", eq.iterations);
    assert!(eq.q.iter().all(|x| x.abs() < 1e-14), "{:?}", eq.q);
    let modes = normal_modes(&chain, 0.0, &eq.q).unwrap();
    // Closed form for the fixed–fixed chain (e.g. Goldstein, Poole & Safko, §6.4; Fetter & Walecka,
    // *Theoretical Mechanics of Particles and Continua*, §24): ω_j = 2√(κ/m) sin(jπ/(2(N+1))).
    for j in 1..=CHAIN {
        let want = 2.0
            * (chain.kappa / chain.m).sqrt()
            * (j as f64 * PI / (2.0 * (CHAIN + 1) as f64)).sin();
        // The symmetric QR eigen-solver is backward stable: |δλ| ≲ N ε ‖K̃‖ with ‖K̃‖ ≤ 4κ/m, i.e.
        // ≲ 2e-14 relative to the smallest λ₁ ≈ 0.08 κ/m; 1e-12 on ω leaves a margin.
        assert!(
            close(modes.frequencies[j - 1], want, 1e-12),
            "ω_{j} = {} vs {want}",
            modes.frequencies[j - 1]
        );
        // Shapes are sines: q_i ∝ sin(i j π/(N+1)).
        let shape = modes.shapes.column(j - 1);
        let i_max = (0..CHAIN)
            .max_by(|&a, &b| shape[a].abs().total_cmp(&shape[b].abs()))
            .unwrap();
        let scale = shape[i_max] / ((i_max + 1) as f64 * j as f64 * PI / (CHAIN + 1) as f64).sin();
        for i in 0..CHAIN {
            let s = scale * ((i + 1) as f64 * j as f64 * PI / (CHAIN + 1) as f64).sin();
            assert!(
                (shape[i] - s).abs() < 1e-10 * scale.abs(),
                "mode {j}, mass {i}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Non-conservative forces and bad input.
// ---------------------------------------------------------------------------------------------

/// A unit mass in the plane on an isotropic spring (stiffness k), with a circulatory force
/// c (q₁, −q₀) (velocity-independent but not a gradient) and linear damping −d q̇. Its linearized
/// equations λ² + dλ + k ± i c = 0 have a root on the imaginary axis λ = iy exactly when y² = k and
/// d y = ∓c, i.e. it is stable iff c² < d² k (Ziegler's destabilizing effect of circulatory forces;
/// H. Ziegler, *Principles of Structural Stability*, 1968). Optionally also a gyroscopic force
/// γ (q̇₁, −q̇₀) (a charge in a magnetic field, or Coriolis forces in a rotating frame).
struct Circulatory {
    k: f64,
    c: f64,
    d: f64,
    gyro: f64,
}

impl Model<2, 2> for Circulatory {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("k", self.k),
            ("c", self.c),
            ("d", self.d),
            ("gyro", self.gyro),
        ])
    }
    fn masses(&self) -> [f64; 2] {
        [1.0; 2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, q: &[D; 2], _x: &[D; 2]) -> D {
        (q[0] * q[0] + q[1] * q[1]) * (0.5 * self.k)
    }
    fn applied_forces<S: Scalar>(
        &self,
        _t: S,
        q: &[S; 2],
        v: &[S; 2],
        _x: &[S; 2],
        _x_dot: &[S; 2],
        _cartesian_force: &mut [S; 2],
        generalized_force: &mut [S; 2],
    ) {
        generalized_force[0] = q[1] * self.c - v[0] * self.d + v[1] * self.gyro;
        generalized_force[1] = -q[0] * self.c - v[1] * self.d - v[0] * self.gyro;
    }
}
impl_mechanism!(Circulatory, 2, 2);

#[test]
fn circulatory_forces_are_classified_by_the_linearized_system() {
    let (k, c) = (1.0, 0.5);
    for (d, want) in [
        (0.0, Stability::Unstable),
        (0.3, Stability::Unstable),
        (1.0, Stability::Stable),
    ] {
        let s = stability(&Circulatory { k, c, d, gyro: 0.0 }, 0.0, &[0.0, 0.0]).unwrap();
        assert_eq!(
            (s.stability, s.method),
            (want, StabilityMethod::Linearized),
            "d = {d}: {:?}",
            s.system_eigenvalues
        );
        // The eigenvalues: roots of λ² + dλ + k ± i c, largest real part first.
        let roots: Vec<f64> = [1.0, -1.0]
            .iter()
            .flat_map(|&sign| {
                let disc = nalgebra::Complex::new(d * d - 4.0 * k, -4.0 * sign * c).sqrt();
                [(-d + disc.re) / 2.0, (-d - disc.re) / 2.0]
            })
            .collect();
        let max_re = roots.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        assert!(
            (s.system_eigenvalues[0].re - max_re).abs() < 1e-12,
            "{:?} vs {max_re}",
            s.system_eigenvalues
        );
    }
    // Damping alone keeps a potential minimum stable (decided from K relative to M).
    let damped = stability(
        &Circulatory {
            k,
            c: 0.0,
            d: 0.3,
            gyro: 0.0,
        },
        0.0,
        &[0.0, 0.0],
    )
    .unwrap();
    assert_eq!(
        (damped.stability, damped.method),
        (Stability::Stable, StabilityMethod::Potential)
    );
    // Circulatory forces: no normal modes even where stable.
    let err = normal_modes(
        &Circulatory {
            k,
            c,
            d: 1.0,
            gyro: 0.0,
        },
        0.0,
        &[0.0, 0.0],
    )
    .unwrap_err();
    assert!(matches!(err, Error::NoNormalModes { .. }), "{err}");
}

#[test]
fn gyroscopic_stabilization_and_its_loss_to_damping() {
    let at = |k, d, gyro| stability(&Circulatory { k, c: 0.0, d, gyro }, 0.0, &[0.0, 0.0]).unwrap();
    // A potential minimum stays stable with gyroscopic forces (Kelvin–Tait–Chetaev; decided from K).
    let s = at(1.0, 0.0, 1.0);
    assert_eq!(
        (s.stability, s.method),
        (Stability::Stable, StabilityMethod::Potential)
    );
    // A maximum (k = −1): the linearized equations give (λ² + k)² + γ²λ² = 0, i.e.
    // λ = (±iγ ± √(−γ² − 4k))/2, all imaginary when γ² ≥ −4k = 4. Strong spin: linearly stable,
    // which the linear analysis can only call marginal; weak spin: unstable.
    let strong = at(-1.0, 0.0, 3.0);
    assert_eq!(
        (strong.stability, strong.method),
        (Stability::Marginal, StabilityMethod::Linearized)
    );
    for mu in &strong.system_eigenvalues {
        // |λ| = (3 ± √5)/2.
        let want = [(3.0 + 5f64.sqrt()) / 2.0, (3.0 - 5f64.sqrt()) / 2.0];
        assert!(
            mu.re.abs() < 1e-12 && want.iter().any(|w| (mu.im.abs() - w).abs() < 1e-12),
            "{mu}"
        );
    }
    assert_eq!(at(-1.0, 0.0, 1.0).stability, Stability::Unstable);
    // Any damping destroys gyroscopic stabilization of a maximum (Kelvin–Tait–Chetaev).
    assert_eq!(at(-1.0, 0.1, 3.0).stability, Stability::Unstable);
}

/// A pendulum with a constant torque τ at the pivot: equilibria sin θ = τ/(m g l), none for τ > m g l.
struct TorquedPendulum {
    m: f64,
    l: f64,
    g: f64,
    torque: f64,
}

impl Model<1, 2> for TorquedPendulum {
    type Coords = [f64; 1];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = true;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("m", self.m),
            ("l", self.l),
            ("g", self.g),
            ("torque", self.torque),
        ])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m; 2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
        [q[0].sin() * self.l, -q[0].cos() * self.l]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
    fn applied_forces<S: Scalar>(
        &self,
        _t: S,
        _q: &[S; 1],
        _v: &[S; 1],
        _x: &[S; 2],
        _x_dot: &[S; 2],
        _cartesian_force: &mut [S; 2],
        generalized_force: &mut [S; 1],
    ) {
        generalized_force[0] = S::from(self.torque);
    }
}
impl_mechanism!(TorquedPendulum, 1, 2);

#[test]
fn torqued_pendulum_equilibrium_and_no_equilibrium() {
    let (m, l, g) = (1.0, 1.0, 9.81);
    let p = TorquedPendulum {
        m,
        l,
        g,
        torque: 0.5 * m * g * l,
    };
    let options = EquilibriumOptions::default();
    // Which of the two equilibria is found depends on the side of θ = π/2 (where the Jacobian
    // vanishes) the guess is on.
    let eq = equilibrium(&p, 0.0, &[0.1], &options).unwrap();
    assert!((eq.q[0] - (0.5f64).asin()).abs() < 1e-14, "{:?}", eq.q);
    let upper = equilibrium(&p, 0.0, &[2.0], &options).unwrap();
    assert!(
        (upper.q[0] - (PI - 0.5f64.asin())).abs() < 1e-14,
        "{:?}",
        upper.q
    );
    assert_eq!(
        stability(&p, 0.0, &eq.q).unwrap().stability,
        Stability::Stable
    );
    assert_eq!(
        stability(&p, 0.0, &upper.q).unwrap().stability,
        Stability::Unstable
    );

    // τ > m g l: the residual τ − m g l sin θ never vanishes; the merit function has its minimum
    // at θ = π/2 where the Jacobian is singular. A typed error naming the configuration.
    let too_strong = TorquedPendulum {
        torque: 1.5 * m * g * l,
        ..p
    };
    let guess = [0.3];
    let err = equilibrium(&too_strong, 0.0, &guess, &options).unwrap_err();
    match &err {
        Error::EquilibriumNotFound {
            residual,
            configuration,
            ..
        } => {
            // At best the residual reaches τ − m g l = 0.5 m g l.
            assert!(*residual >= 0.5 * m * g * l * (1.0 - 1e-9), "{err}");
            assert!(configuration.contains("q0 = "), "{err}");
        }
        other => panic!("unexpected {other}"),
    }
    assert_eq!(guess, [0.3]); // the guess is untouched
                              // An iteration budget that is too small is reported the same way.
    let tight = EquilibriumOptions {
        max_iterations: 1,
        ..options
    };
    assert!(matches!(
        equilibrium(&p, 0.0, &[2.9], &tight),
        Err(Error::EquilibriumNotFound { iterations: 1, .. })
    ));
}

#[test]
fn bad_input_is_a_typed_error() {
    let options = EquilibriumOptions::default();
    assert!(matches!(
        equilibrium(&DP, 0.0, &[f64::NAN, 0.0], &options),
        Err(Error::NonFiniteState { .. })
    ));
    assert!(matches!(
        equilibrium(&DP, f64::INFINITY, &[0.0, 0.0], &options),
        Err(Error::NonFiniteState { .. })
    ));
    let bad = DoublePendulum { g: f64::NAN, ..DP };
    assert!(matches!(
        equilibrium(&bad, 0.0, &[0.0, 0.0], &options),
        Err(Error::NonFiniteParameter { name: "g", .. })
    ));
    assert!(matches!(
        stability(&bad, 0.0, &[0.0, 0.0]),
        Err(Error::NonFiniteParameter { .. })
    ));
    assert!(matches!(
        normal_modes(&DP, 0.0, &[0.5, 0.0]),
        Err(Error::NotAnEquilibrium { .. })
    ));
    assert!(matches!(
        linearize(&DP, &State::new(0.0, [0.0, f64::NAN], [0.0, 0.0])),
        Err(Error::NonFiniteState { .. })
    ));
    // A degenerate mechanism (zero lengths): M is singular, reported by name.
    let degenerate = DoublePendulum { l: 0.0, ..DP };
    let err = stability(&degenerate, 0.0, &[0.0, 0.0]).unwrap_err();
    assert!(matches!(err, Error::SingularMassMatrix { .. }), "{err}");
    assert!(matches!(
        linearize(&degenerate, &State::at_rest([0.0, 0.0])),
        Err(Error::SingularMassMatrix { .. })
    ));
}

#[test]
fn linearization_about_a_moving_state_matches_finite_differences() {
    // Not an equilibrium: θ = (0.4, −0.9), θ̇ = (1.1, 0.3). Central differences of the accelerations
    // with step 1e-5 are accurate to ~(1e-5)² · |q̈'''| ~ 1e-9 (truncation) + ε/1e-5 ~ 1e-11 (rounding).
    let state = State::new(0.0, [0.4, -0.9], [1.1, 0.3]);
    let lin = linearize(&DP, &state).unwrap();
    let acc = |q: [f64; 2], v: [f64; 2]| DP.accelerations_at(0.0, &q, &v).unwrap();
    let e = 1e-5;
    for j in 0..2 {
        let (mut qp, mut qm, mut vp, mut vm) = (state.q, state.q, state.v, state.v);
        qp[j] += e;
        qm[j] -= e;
        vp[j] += e;
        vm[j] -= e;
        for i in 0..2 {
            let dq = (acc(qp, state.v)[i] - acc(qm, state.v)[i]) / (2.0 * e);
            let dv = (acc(state.q, vp)[i] - acc(state.q, vm)[i]) / (2.0 * e);
            assert!(
                (lin.dqdd_dq[(i, j)] - dq).abs() < 1e-7,
                "∂q̈{i}/∂q{j}: {} vs {dq}",
                lin.dqdd_dq[(i, j)]
            );
            assert!(
                (lin.dqdd_dv[(i, j)] - dv).abs() < 1e-7,
                "∂q̈{i}/∂v{j}: {} vs {dv}",
                lin.dqdd_dv[(i, j)]
            );
        }
    }
    // B = [0; M⁻¹].
    let m = DP.mass_matrix(&state).unwrap();
    assert!((m * lin.dqdd_du - SMatrix::<f64, 2, 2>::identity()).norm() < 1e-14);
    let b = lin.b_matrix();
    assert_eq!(b.shape(), (4, 2));
    assert_eq!(b[(0, 0)], 0.0);
    assert_eq!(b[(3, 1)], lin.dqdd_du[(1, 1)]);
}

// ---------------------------------------------------------------------------------------------
// Equilibria of constrained mechanisms: q* and the multipliers λ.
// ---------------------------------------------------------------------------------------------

use lagrange_core::analysis::constrained_equilibrium;
use lagrange_core::constraints::{self, ConstraintKind, Constraints};

/// A plane pendulum in Cartesian coordinates (x, y): bob of mass m, gravity −g ŷ, the rod as one
/// holonomic row, either √(x² + y²) − L (`squared: false`) or x² + y² − L² (`squared: true`).
#[derive(Clone, Copy)]
struct CartesianPendulum {
    m: f64,
    l: f64,
    g: f64,
    squared: bool,
}

impl Model<2, 2> for CartesianPendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("L", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 2] {
        [self.m; 2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * (self.m * self.g)
    }
}

impl Constraints<2, 2, 1> for CartesianPendulum {
    const NAMES: [&'static str; 1] = ["rod"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        let r2 = x[0] * x[0] + x[1] * x[1];
        if self.squared {
            [r2 - self.l * self.l]
        } else {
            [r2.sqrt() - self.l]
        }
    }
}
impl_mechanism!(CartesianPendulum, 2, 2, constraints);

const L_ROD: f64 = 2.0;
const M_BOB: f64 = 1.5;

#[test]
fn cartesian_pendulum_equilibria_and_rod_tension() {
    let options = EquilibriumOptions::default();
    for squared in [false, true] {
        let p = CartesianPendulum {
            m: M_BOB,
            l: L_ROD,
            g: G,
            squared,
        };
        // The multiplier of row g is λ with generalized force λ ∇g (constraints module). The rod
        // pulls the bob towards the pivot with the tension T: λ ∇g = −T r̂. ∇(|r| − L) = r̂ gives
        // λ = −T; ∇(|r|² − L²) = 2 r gives λ = −T/(2L). At the bottom T = m g, at the top the rod
        // is compressed, T = −m g.
        let per_tension = if squared { -1.0 / (2.0 * L_ROD) } else { -1.0 };
        // Guesses off the bottom and off the circle (inside and outside it).
        for guess in [[0.7, -1.2], [-1.1, -2.9], [1.9, -0.4], [-0.2, -0.5]] {
            let kept = guess;
            let eq = constrained_equilibrium(&p, 0.0, &guess, &options).unwrap();
            assert_eq!(guess, kept);
            // Newton converges quadratically and stops on a step ≤ 1e-12·max(1, |q|) (the error
            // left is ~ its square) or on a residual at rounding level: q* = (0, −L) to a few
            // ulps of L = 2.
            assert!(
                eq.q[0].abs() < 1e-13 && (eq.q[1] + L_ROD).abs() < 1e-13,
                "squared {squared}, guess {guess:?}: q* = {:?}",
                eq.q
            );
            // λ from r + Gᵀλ = 0 at q*: m g (≈ 14.7) divided by |∇g| ∈ {1, 4}, to the rounding
            // of the force balance (a few ulps of m g).
            let tension = M_BOB * G;
            assert!(
                close(eq.multipliers[0], per_tension * tension, 1e-14),
                "squared {squared}: λ = {} vs {}",
                eq.multipliers[0],
                per_tension * tension
            );
            assert_eq!(eq.multiplier("rod"), Some(eq.multipliers[0]));
            assert_eq!(eq.active, [true]);
            assert!(eq.residual < 1e-13 && eq.constraint_residual < 1e-13);
            assert!(eq.iterations > 0);
            // The dynamics runtime agrees: at rest at q* the accelerations vanish and its
            // multiplier (the KKT solve of M q̈ = 𝓕 − b + Gᵀλ, G q̈ = −β) is the same λ.
            let forces = constraints::constraint_forces(&p, &State::at_rest(eq.q)).unwrap();
            assert!(forces.accelerations.iter().all(|a| a.abs() < 1e-12));
            assert!(close(forces.multipliers[0], eq.multipliers[0], 1e-13));
            // Stability on the tangent space: V = m g y has no curvature; the stiffness comes
            // entirely from −λ∇²g, giving ω² = g/L at the bottom (the pendulum's frequency).
            // Exact derivatives and a 1×1 reduced problem: rounding only.
            assert_eq!(eq.stability, Stability::Stable);
            assert_eq!(eq.tangent_eigenvalues.len(), 1);
            assert!(close(eq.tangent_eigenvalues[0], G / L_ROD, 1e-13));
        }
        // The top is an equilibrium too, reached from a guess near it: tension −m g, unstable
        // with the eigenvalue −g/L.
        for guess in [[0.3, 1.6], [-0.5, 2.4]] {
            let top = constrained_equilibrium(&p, 0.0, &guess, &options).unwrap();
            assert!(
                top.q[0].abs() < 1e-13 && (top.q[1] - L_ROD).abs() < 1e-13,
                "squared {squared}, guess {guess:?}: q* = {:?}",
                top.q
            );
            assert!(close(top.multipliers[0], -per_tension * M_BOB * G, 1e-14));
            assert_eq!(top.stability, Stability::Unstable);
            assert!(close(top.tangent_eigenvalues[0], -G / L_ROD, 1e-13));
        }
    }
}

/// A bead of mass m on a circular wire of radius R in a vertical plane that spins about the
/// vertical at ω. Coordinates in the rotating plane, q = (ρ, z): x = (ρ cos ωt, ρ sin ωt, z)
/// (rheonomic), the wire as the holonomic row |x| − R = 0 written on the Cartesian position.
/// The same physics as `Hoop` above, which absorbs the wire into the angle θ.
#[derive(Clone, Copy)]
struct WireBead {
    m: f64,
    r: f64,
    g: f64,
    omega: f64,
}

impl Model<2, 3> for WireBead {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = true;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[
            ("m", self.m),
            ("R", self.r),
            ("g", self.g),
            ("omega", self.omega),
        ])
    }
    fn masses(&self) -> [f64; 3] {
        [self.m; 3]
    }
    fn cartesian<D: Scalar>(&self, t: D, q: &[D; 2]) -> [D; 3] {
        let spin = t * self.omega;
        [q[0] * spin.cos(), q[0] * spin.sin(), q[1]]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 3]) -> D {
        x[2] * (self.m * self.g)
    }
}

impl Constraints<2, 3, 1> for WireBead {
    const NAMES: [&'static str; 1] = ["wire"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 3]) -> [D; 1] {
        [(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt() - self.r]
    }
}
impl_mechanism!(WireBead, 2, 3, constraints);

#[test]
fn bead_on_spinning_wire_equilibrium_and_normal_force() {
    // In the rotating plane the bead feels gravity (0, −m g), the centrifugal force (m ω² ρ, 0)
    // (−b at rest: T = ½ m (ρ̇² + ρ² ω² + ż²)) and the wire's force λ ∇g = λ (ρ, z)/R. Balance:
    // ρ (m ω² + λ/R) = 0 and −m g + λ z/R = 0. Off the axis (ρ ≠ 0): λ = −m ω² R and
    // z = −g/ω², i.e. cos θ* = g/(ω² R) as for `Hoop`; the wire presses inwards with m ω² R.
    // Tangent stiffness: K = diag(−m ω², 0), −λ∇²g = m ω² (I − n nᵀ) with n = (sin θ, −cos θ),
    // along t = (cos θ, sin θ): m ω² sin²θ*, relative to the mass m: ω² − g²/(ω² R²), the
    // frequency of `hoop_off_bottom_equilibria_above_critical_spin`.
    let options = EquilibriumOptions::default();
    let omega = 6.0;
    let bead = WireBead {
        m: M_BEAD,
        r: R_HOOP,
        g: G,
        omega,
    };
    let cos_star = G / (omega * omega * R_HOOP);
    let sin_star = (1.0 - cos_star * cos_star).sqrt();
    let freq2 = omega * omega - G * G / (omega * omega * R_HOOP * R_HOOP);
    for (t, guess) in [(0.0, [0.3, -0.2]), (0.0, [-0.6, -0.1]), (0.37, [0.4, -0.3])] {
        let eq = constrained_equilibrium(&bead, t, &guess, &options).unwrap();
        let rho = guess[0].signum() * R_HOOP * sin_star;
        // q* to a few ulps of R (quadratic convergence, step test 1e-12).
        assert!(
            (eq.q[0] - rho).abs() < 1e-14 && (eq.q[1] + R_HOOP * cos_star).abs() < 1e-14,
            "t = {t}, guess {guess:?}: q* = {:?} vs ({rho}, {})",
            eq.q,
            -R_HOOP * cos_star
        );
        // λ = −m ω² R = −3.6: the sum of forces of size ~m ω² R, so a few ulps of that.
        assert!(
            close(eq.multipliers[0], -M_BEAD * omega * omega * R_HOOP, 1e-14),
            "λ = {}",
            eq.multipliers[0]
        );
        // Against the hoop in the angle coordinate: the same configuration.
        let hoop_eq = equilibrium(&hoop(omega), t, &[guess[0].signum()], &options).unwrap();
        assert!((R_HOOP * hoop_eq.q[0].sin() - eq.q[0]).abs() < 1e-14);
        // Stable, ω² − g²/(ω²R²) ≈ 25.3 from a difference of terms of size ω² = 36: 1e-13.
        assert_eq!(eq.stability, Stability::Stable);
        assert!(
            close(eq.tangent_eigenvalues[0], freq2, 1e-13),
            "ω² = {} vs {freq2}",
            eq.tangent_eigenvalues[0]
        );
    }
    // On the axis (ρ = 0) the bottom balances with λ = −m g, unstable above the critical spin:
    // tangent eigenvalue g/R − ω².
    let bottom = constrained_equilibrium(&bead, 0.0, &[0.0, -0.4], &options).unwrap();
    assert!(bottom.q[0].abs() < 1e-14 && (bottom.q[1] + R_HOOP).abs() < 1e-14);
    assert!(close(bottom.multipliers[0], -M_BEAD * G, 1e-14));
    assert_eq!(bottom.stability, Stability::Unstable);
    assert!(close(
        bottom.tangent_eigenvalues[0],
        G / R_HOOP - omega * omega,
        1e-13
    ));
    // Below the critical spin only the axis equilibria exist; the bottom is stable.
    let slow = WireBead { omega: 3.0, ..bead };
    let eq = constrained_equilibrium(&slow, 0.0, &[0.3, -0.2], &options).unwrap();
    assert!(eq.q[0].abs() < 1e-14 && (eq.q[1] + R_HOOP).abs() < 1e-14);
    assert_eq!(eq.stability, Stability::Stable);
    assert!(close(eq.tangent_eigenvalues[0], G / R_HOOP - 9.0, 1e-13));
}

/// A bob in space (x, y, z) on a sphere of radius L about the origin and in the plane x = 0:
/// two holonomic rows (a pendulum in the y–z plane). With `redundant`, a third row 2x = 0 repeats
/// the plane.
#[derive(Clone, Copy)]
struct PlanarBob {
    m: f64,
    l: f64,
    g: f64,
}

impl Model<3, 3> for PlanarBob {
    type Coords = [f64; 3];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        finite(&[("m", self.m), ("L", self.l), ("g", self.g)])
    }
    fn masses(&self) -> [f64; 3] {
        [self.m; 3]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 3]) -> [D; 3] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 3]) -> D {
        x[2] * (self.m * self.g)
    }
}

impl Constraints<3, 3, 2> for PlanarBob {
    const NAMES: [&'static str; 2] = ["sphere", "plane"];
    const KINDS: [ConstraintKind; 2] = [ConstraintKind::Holonomic; 2];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 3], x: &[D; 3]) -> [D; 2] {
        [
            (x[0] * x[0] + x[1] * x[1] + x[2] * x[2]).sqrt() - self.l,
            x[0],
        ]
    }
}
impl_mechanism!(PlanarBob, 3, 3, constraints);

/// `PlanarBob` with the plane declared twice.
#[derive(Clone, Copy)]
struct RedundantBob(PlanarBob);

delegate_model!(RedundantBob, PlanarBob, 3, 3);

impl Constraints<3, 3, 3> for RedundantBob {
    const NAMES: [&'static str; 3] = ["sphere", "plane", "plane again"];
    const KINDS: [ConstraintKind; 3] = [ConstraintKind::Holonomic; 3];
    fn position_constraints<D: Scalar>(&self, t: D, q: &[D; 3], x: &[D; 3]) -> [D; 3] {
        let [sphere, plane] = self.0.position_constraints(t, q, x);
        [sphere, plane, plane * 2.0]
    }
}
impl_mechanism!(RedundantBob, 3, 3, constraints);

#[test]
fn two_rows_and_redundant_rows() {
    let options = EquilibriumOptions::default();
    let bob = PlanarBob {
        m: M_BOB,
        l: L_ROD,
        g: G,
    };
    // Off the plane and off the sphere: back to the bottom (0, 0, −L); the sphere carries the
    // weight (λ = −m g, as for the rod), the plane nothing (its normal is horizontal).
    let eq = constrained_equilibrium(&bob, 0.0, &[0.4, 0.6, -1.5], &options).unwrap();
    assert!(eq.q[0].abs() < 1e-14 && eq.q[1].abs() < 1e-13 && (eq.q[2] + L_ROD).abs() < 1e-13);
    assert!(close(eq.multiplier("sphere").unwrap(), -M_BOB * G, 1e-14));
    assert!(eq.multiplier("plane").unwrap().abs() < 1e-12);
    // One degree of freedom left, the pendulum in the y–z plane.
    assert_eq!(eq.tangent_eigenvalues.len(), 1);
    assert!(close(eq.tangent_eigenvalues[0], G / L_ROD, 1e-13));
    assert_eq!(eq.stability, Stability::Stable);
    // The plane twice: the multipliers of the two copies are not determined.
    let err =
        constrained_equilibrium(&RedundantBob(bob), 0.0, &[0.4, 0.6, -1.5], &options).unwrap_err();
    match &err {
        Error::SingularConstraints { constraints, .. } => {
            assert!(constraints.contains("`plane`") && constraints.contains("`plane again`"));
            assert!(!constraints.contains("`sphere`"), "{err}");
        }
        other => panic!("expected SingularConstraints, got {other}"),
    }
}

/// The Cartesian pendulum on a string: the unilateral row L − |r| ≥ 0 (the string only pulls).
#[derive(Clone, Copy)]
struct StringPendulum(CartesianPendulum);

delegate_model!(StringPendulum, CartesianPendulum, 2, 2);

impl Constraints<2, 2, 1> for StringPendulum {
    const NAMES: [&'static str; 1] = ["string"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Unilateral];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [-(x[0] * x[0] + x[1] * x[1]).sqrt() + self.0.l]
    }
}
impl_mechanism!(StringPendulum, 2, 2, constraints);

/// A particle in the plane whose velocity row ẋ = 0 cannot be used for statics.
#[derive(Clone, Copy)]
struct Rail(CartesianPendulum);

delegate_model!(Rail, CartesianPendulum, 2, 2);

impl Constraints<2, 2, 1> for Rail {
    const NAMES: [&'static str; 1] = ["no_sideways"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Velocity];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], _x: &[D; 2]) -> [D; 1] {
        [D::zero()]
    }
    fn velocity_constraints<D: Scalar>(
        &self,
        _t: D,
        _q: &[D; 2],
        v: &[D; 2],
        _x: &[D; 2],
        _x_dot: &[D; 2],
    ) -> [D; 1] {
        [v[0]]
    }
}
impl_mechanism!(Rail, 2, 2, constraints);

#[test]
fn unilateral_rows_by_active_set_and_refused_rows() {
    let options = EquilibriumOptions::default();
    let p = CartesianPendulum {
        m: M_BOB,
        l: L_ROD,
        g: G,
        squared: false,
    };
    let string = StringPendulum(p);
    // On the circle (string taut) or beyond it (stretched): the string holds the bob at the
    // bottom and pulls, λ = +m g ≥ 0 (∇c = −r̂, so λ∇c = −λ r̂ is a pull of λ towards the pivot).
    for guess in [[0.6, -(L_ROD * L_ROD - 0.36f64).sqrt()], [1.0, -2.5]] {
        let eq = constrained_equilibrium(&string, 0.0, &guess, &options).unwrap();
        assert!(eq.q[0].abs() < 1e-13 && (eq.q[1] + L_ROD).abs() < 1e-13);
        assert!(close(eq.multipliers[0], M_BOB * G, 1e-14));
        assert_eq!(eq.active, [true]);
        assert_eq!(eq.stability, Stability::Stable);
    }
    // At the top the string would have to push (λ = −m g): released, and a free bob under gravity
    // has no equilibrium. Slack (inside the circle) from the start: the same.
    for guess in [[0.0, L_ROD], [0.3, 1.5], [0.2, -0.5]] {
        let err = constrained_equilibrium(&string, 0.0, &guess, &options).unwrap_err();
        assert!(
            matches!(err, Error::EquilibriumNotFound { .. }),
            "guess {guess:?}: {err}"
        );
    }
    // A velocity row gives no equation for q at rest: refused.
    let err = constrained_equilibrium(&Rail(p), 0.0, &[0.0, 0.0], &options).unwrap_err();
    assert!(
        matches!(err, Error::UnsuitableMethod { ref reason, .. } if reason.contains("no_sideways")),
        "{err}"
    );
    // Non-finite guesses and parameters, and a cap of one iteration.
    assert!(matches!(
        constrained_equilibrium(&p, 0.0, &[f64::NAN, -1.0], &options),
        Err(Error::NonFiniteState { .. })
    ));
    let bad = CartesianPendulum { g: f64::NAN, ..p };
    assert!(matches!(
        constrained_equilibrium(&bad, 0.0, &[0.1, -1.0], &options),
        Err(Error::NonFiniteParameter { name: "g", .. })
    ));
    let one = EquilibriumOptions {
        max_iterations: 1,
        ..options
    };
    assert!(matches!(
        constrained_equilibrium(&p, 0.0, &[0.7, -1.2], &one),
        Err(Error::EquilibriumNotFound { iterations: 1, .. })
    ));
}

#[test]
fn enforced_row_without_gradient_is_singular_constraints_not_a_panic() {
    // x² + y² − L² has zero gradient at the pivot: the row cannot be enforced there (as
    // `consistent_state` and the accelerations report).
    let p = CartesianPendulum {
        m: M_BOB,
        l: L_ROD,
        g: G,
        squared: true,
    };
    let err =
        constrained_equilibrium(&p, 0.0, &[0.0, 0.0], &EquilibriumOptions::default()).unwrap_err();
    assert!(
        matches!(err, Error::SingularConstraints { ref constraints, .. } if constraints.contains("`rod`")),
        "{err}"
    );
    assert!(matches!(
        constraints::accelerations(&p, 0.0, &[0.0, 0.0], &[0.0, 0.0]),
        Err(Error::SingularConstraints { .. })
    ));
}

#[test]
fn equilibrium_options_are_validated() {
    let defaults = EquilibriumOptions::default();
    let p = CartesianPendulum {
        m: M_BOB,
        l: L_ROD,
        g: G,
        squared: false,
    };
    for value in [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        -1e-12,
        1.0,
        1e300,
    ] {
        for (name, options) in [
            (
                "residual_tolerance",
                EquilibriumOptions {
                    residual_tolerance: value,
                    ..defaults
                },
            ),
            (
                "step_tolerance",
                EquilibriumOptions {
                    step_tolerance: value,
                    ..defaults
                },
            ),
        ] {
            let is_invalid =
                |e: &Error| matches!(e, Error::InvalidSetting { setting, .. } if *setting == name);
            let err = equilibrium(&DP, 0.0, &[0.4, 0.1], &options).unwrap_err();
            assert!(is_invalid(&err), "{name} = {value}: {err}");
            let err = constrained_equilibrium(&p, 0.0, &[0.7, -1.2], &options).unwrap_err();
            assert!(is_invalid(&err), "{name} = {value}: {err}");
            let branch = continuation(|_| DP, &[1.0], 0.0, &[0.4, 0.1], &options);
            assert!(branch.points.is_empty());
            assert!(matches!(&branch.stopped, Some((_, e)) if is_invalid(e)));
        }
    }
}

/// A bead on a vertical rail x = 0 whose mass sits in x only: the rail leaves it the y direction,
/// which carries no mass (M = diag(m, 0)); a spring k y²/2 gives it an equilibrium at y = 0.
#[derive(Clone, Copy)]
struct MasslessAlongRail;

impl Model<2, 2> for MasslessAlongRail {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;
    fn validate(&self) -> lagrange_core::Result<()> {
        Ok(())
    }
    fn masses(&self) -> [f64; 2] {
        [1.0, 0.0]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 2] {
        *q
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> D {
        x[1] * x[1] * 0.5
    }
}

impl Constraints<2, 2, 1> for MasslessAlongRail {
    const NAMES: [&'static str; 1] = ["rail"];
    const KINDS: [ConstraintKind; 1] = [ConstraintKind::Holonomic];
    fn position_constraints<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 2]) -> [D; 1] {
        [x[0]]
    }
}
impl_mechanism!(MasslessAlongRail, 2, 2, constraints);

#[test]
fn singular_mass_on_the_tangent_space_names_the_coordinate_without_mass() {
    let err = constrained_equilibrium(
        &MasslessAlongRail,
        0.0,
        &[0.1, 0.2],
        &EquilibriumOptions::default(),
    )
    .unwrap_err();
    // M = diag(1, 0): the factorisation stops at q1 with pivot 0.
    assert!(
        matches!(err, Error::SingularMassMatrix { coordinate: "q1", pivot, .. } if pivot == 0.0),
        "{err}"
    );
}
