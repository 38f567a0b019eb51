//! The canonical field (p, ṗ) in closed form: where `#[mechanism]` derives M, 𝓕 and b as
//! straight-line code it writes p = M q̇ and ṗ = ∂T/∂q + 𝓕 the same way, ∂T/∂q from M's
//! polynomials differentiated by the macro. It must equal the hyper-dual pass
//! (`dynamics::canonical_field`) on `f64` and on dual numbers (the implicit methods differentiate
//! it for their Newton matrix), through the plain mechanism and through a validated handle (which
//! evaluates the prepared coefficients); and the implicit methods must step a closed-form
//! declaration as they step the same mechanism declared so that the closed form does not apply,
//! and, as a solver (the Newton matrix, the predictor and p₁ kept from step to step), as they step
//! one step at a time — also on a constrained linkage, projected after every step.

use lagrange::__private::{dynamics, Dynamics, Model};
use lagrange::evaluation::Evaluate;
use lagrange::prelude::*;
use lagrange::{GaussLegendre2, ImplicitMidpoint};
use nalgebra::SVector;
use num_dual::DualSVec;
// The gallery's declarations: the pendulum and the double pendulum in closed form, the four-bar not.
use lagrange_gallery::scenes::{
    double_pendulum::double_pendulum, four_bar::four_bar, pendulum::pendulum,
};

/// The same double pendulum with its weight written as a potential: not derived in closed form
/// (a potential is left to the dual-number passes).
#[mechanism]
pub mod double_pendulum_by_potential {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }
    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }
    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }
    #[potential]
    fn weight() -> f64 {
        (m1 * bob1.y + m2 * bob2.y) * g
    }
}

/// A chain of four links declared one by one, the last a planar rod.
#[mechanism]
pub mod chain {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
        pub d: f64,
    }
    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[particle(mass = m)]
    fn p1() -> Vec2 {
        vec2(a.sin(), -a.cos()) * l
    }
    #[particle(mass = 1.5 * m)]
    fn p2() -> Vec2 {
        p1 + vec2(b.sin(), -b.cos()) * l
    }
    #[particle(mass = m)]
    fn p3() -> Vec2 {
        p2 + vec2(c.sin(), -c.cos()) * (0.7 * l)
    }
    #[rigid_body(mass = m, inertia = m * l * l / 12.0)]
    fn rod() -> Planar {
        planar(p3 + vec2(d.sin(), -d.cos()) * (0.5 * l), d)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

// The cart-pendulum and the spherical pendulum, declared once for this file and another.
#[path = "common/closed_form_mechanisms.rs"]
mod closed_form_mechanisms;
use closed_form_mechanisms::{cart_pendulum, spherical, states};

fn double() -> double_pendulum::DoublePendulum {
    double_pendulum::DoublePendulum {
        m1: 1.0,
        m2: 1.3,
        l1: 1.0,
        l2: 0.8,
        g: 9.81,
    }
}

/// The closed-form field against the hyper-dual pass at every state, on `f64` and on gradient
/// duals seeded on q and on q̇. Both sum the same products of sines, cosines, coordinates and
/// velocities, in another order and the closed form simplified by sin² + cos² = 1 first: each
/// component is a sum of at most a few tens of terms (masses and lengths of order one, |q̇| ≤ 3,
/// so terms of order 1 to 100), whose round-off in either order is a few tens of ulps of the
/// largest term, ≲ 1e-13 of the scale used here (the quantity's largest component, or 1).
fn agrees_with_the_hyper_dual_pass<H, const N: usize, const K: usize>(sys: &H)
where
    H: Evaluate<N>,
    H::Model: Model<N, K>,
{
    assert!(
        <H::Model as Dynamics<N>>::CLOSED_FORM,
        "the declaration is not derived in closed form"
    );
    let close =
        |a: &SVector<f64, N>, b: &SVector<f64, N>| (a - b).amax() <= 1e-13 * b.amax().max(1.0);
    for (q, v) in states::<N>() {
        let (p, rate) = sys.canonical_field_at(0.0, &q, &v);
        let (p_dual, rate_dual) =
            dynamics::canonical_field::<H::Model, f64, N, K>(sys.model(), 0.0, &q, &v);
        let (p, rate, p_dual, rate_dual) = (
            SVector::from(p),
            SVector::from(rate),
            SVector::from(p_dual),
            SVector::from(rate_dual),
        );
        assert!(close(&p, &p_dual), "p at {q:?}, {v:?}: {p} vs {p_dual}");
        assert!(
            close(&rate, &rate_dual),
            "ṗ at {q:?}, {v:?}: {rate} vs {rate_dual}"
        );
        // The momenta alone come from the same code.
        assert!(close(&SVector::from(sys.momenta_at(0.0, &q, &v)), &p_dual));
        // The Newton matrix's derivatives: seeded on q, then on q̇.
        let t = DualSVec::<f64, N>::from_re(0.0);
        let plain = |x: &[f64; N]| -> [DualSVec<f64, N>; N] {
            std::array::from_fn(|j| DualSVec::from_re(x[j]))
        };
        let seeded = |x: &[f64; N]| -> [DualSVec<f64, N>; N] {
            std::array::from_fn(|j| DualSVec::from_re(x[j]).derivative(j))
        };
        for (qd, vd) in [(seeded(&q), plain(&v)), (plain(&q), seeded(&v))] {
            let closed = sys.canonical_field_at(t, &qd, &vd);
            let dual = dynamics::canonical_field::<H::Model, _, N, K>(sys.model(), t, &qd, &vd);
            for (a, b) in [(&closed.0, &dual.0), (&closed.1, &dual.1)] {
                for k in 0..N {
                    let d = |x: &DualSVec<f64, N>| x.eps.0.unwrap_or_else(SVector::zeros);
                    assert!(
                        (d(&a[k]) - d(&b[k])).amax() <= 1e-13 * d(&b[k]).amax().max(1.0),
                        "derivative of component {k} at {q:?}, {v:?}"
                    );
                }
            }
        }
    }
}

/// Through the plain mechanism (coefficients computed at the call) and through a validated handle
/// (the prepared coefficients).
fn both_ways<M, const N: usize, const K: usize>(sys: M)
where
    M: Model<N, K> + Dynamics<N>,
{
    agrees_with_the_hyper_dual_pass::<M, N, K>(&sys);
    agrees_with_the_hyper_dual_pass::<Validated<M>, N, K>(&sys.validated().unwrap());
}

#[test]
fn the_pendulums_closed_form_field_is_the_hyper_dual_pass() {
    both_ways(pendulum::Pendulum {
        m: 1.2,
        l: 0.7,
        g: 9.81,
    });
    both_ways(double());
}

#[test]
fn a_cart_pendulums_closed_form_field_is_the_hyper_dual_pass() {
    both_ways(cart_pendulum::CartPendulum {
        cart_mass: 2.0,
        m: 0.5,
        l: 0.8,
        g: 9.81,
    });
}

#[test]
fn a_chains_closed_form_field_is_the_hyper_dual_pass() {
    both_ways(chain::Chain {
        m: 0.6,
        l: 0.9,
        g: 9.81,
    });
}

#[test]
fn polar_coordinates_closed_form_field_is_the_hyper_dual_pass() {
    both_ways(spherical::Spherical {
        m: 0.9,
        m2: 1.7,
        l: 1.1,
        g: 9.81,
    });
}

/// The implicit methods on the double pendulum in closed form and on the same pendulum with its
/// weight as a potential (the dual-number passes): the same steps, as a solver takes them (the
/// Newton matrix kept) and one by one (`sys.step`, fresh memory). Each step iterates Newton's
/// method to round-off (increments ≤ 4ε·max(1, |x|)) on fields that agree to a few ulps, so the
/// two runs differ by round-off per step, accumulated over 300 steps of a motion whose
/// sensitivity to perturbations grows slowly over 0.3 s (|q|, |q̇| ≲ 3): 1e-12 bounds it with
/// margin (the measured difference is ≤ 2e-14).
#[test]
fn implicit_steps_on_the_closed_form_equal_those_on_the_dual_passes() {
    let closed = double();
    let by_potential = double_pendulum_by_potential::DoublePendulum {
        m1: 1.0,
        m2: 1.3,
        l1: 1.0,
        l2: 0.8,
        g: 9.81,
    };
    const {
        assert!(<double_pendulum::DoublePendulum as Dynamics<2>>::CLOSED_FORM);
        assert!(!<double_pendulum_by_potential::DoublePendulum as Dynamics<2>>::CLOSED_FORM);
    }
    let closed_handle = double().validated().unwrap();
    let (q0, v0) = ([0.7, -1.2], [1.1, -0.4]);
    let h = 1e-3;
    let compare = |label: &str, a: ([f64; 2], [f64; 2]), b: ([f64; 2], [f64; 2])| {
        for k in 0..2 {
            assert!(
                (a.0[k] - b.0[k]).abs() < 1e-12 && (a.1[k] - b.1[k]).abs() < 1e-12,
                "{label}: {a:?} vs {b:?}"
            );
        }
    };
    macro_rules! run {
        ($method:ident, $stages:literal) => {{
            use lagrange::integrate::NewtonMemory;
            let mut a = double_pendulum::State::new(
                0.0,
                double_pendulum::Coords::from_array(q0),
                double_pendulum::Coords::from_array(v0),
            );
            let mut c = a;
            let mut b = double_pendulum_by_potential::State::new(
                0.0,
                double_pendulum_by_potential::Coords::from_array(q0),
                double_pendulum_by_potential::Coords::from_array(v0),
            );
            let mut memory_a = NewtonMemory::<2, $stages>::default();
            let mut memory_b = NewtonMemory::<2, $stages>::default();
            let mut memory_c = NewtonMemory::<2, $stages>::default();
            for _ in 0..300 {
                $method::step_with_memory(&closed, &mut memory_a, &mut a, h).unwrap();
                $method::step_with_memory(&by_potential, &mut memory_b, &mut b, h).unwrap();
                $method::step_with_memory(&closed_handle, &mut memory_c, &mut c, h).unwrap();
            }
            let pair = |q: [f64; 2], v: [f64; 2]| (q, v);
            let a = pair([a.q.theta1, a.q.theta2], [a.v.theta1, a.v.theta2]);
            let b = pair([b.q.theta1, b.q.theta2], [b.v.theta1, b.v.theta2]);
            let c = pair([c.q.theta1, c.q.theta2], [c.v.theta1, c.v.theta2]);
            compare(stringify!($method), a, b);
            compare(concat!(stringify!($method), " through a handle"), c, b);
            // One-step shorthand (a fresh Newton matrix every step).
            let mut a1 = double_pendulum::State::new(
                0.0,
                double_pendulum::Coords::from_array(q0),
                double_pendulum::Coords::from_array(v0),
            );
            let mut b1 = double_pendulum_by_potential::State::new(
                0.0,
                double_pendulum_by_potential::Coords::from_array(q0),
                double_pendulum_by_potential::Coords::from_array(v0),
            );
            for _ in 0..300 {
                closed_handle.step::<$method>(&mut a1, h).unwrap();
                by_potential.step::<$method>(&mut b1, h).unwrap();
            }
            let a1 = pair([a1.q.theta1, a1.q.theta2], [a1.v.theta1, a1.v.theta2]);
            compare(
                concat!(stringify!($method), ", sys.step"),
                a1,
                pair([b1.q.theta1, b1.q.theta2], [b1.v.theta1, b1.v.theta2]),
            );
            // The solver's kept matrix, refreshed mass block, corrected predictor and carried p₁
            // change the Newton iteration's path, not the point it converges to.
            compare(concat!(stringify!($method), ", kept against fresh"), a, a1);
            // And the motion moved: the comparison is not of two resting states.
            assert!((a.0[1] - q0[1]).abs() > 0.2, "{a:?}");
        }};
    }
    run!(ImplicitMidpoint, 1);
    run!(GaussLegendre2, 2);
}

/// The gallery's four-bar linkage (two loop-closure constraints, not in closed form): each step ends with a
/// projection, so the next starts off the last step's end (p₀ evaluated anew) while its Newton
/// matrix takes the unprojected end's M. A solver's steps equal the one-step shorthand's (fresh
/// matrix, no memory) to round-off: Newton is iterated to round-off either way and the projection
/// is the same map, so the runs differ by a few ulps per step over 300 steps (|q̇| ≲ 3): 1e-12
/// bounds it with margin (the measured difference is ≤ 3e-14).
#[test]
fn a_solvers_steps_on_a_constrained_linkage_equal_the_one_step_shorthands() {
    use four_bar::State;
    use lagrange::integrate::NewtonMemory;
    // The gallery's linkage and its consistent start (the crank turning at 3 rad/s).
    let (sys, start) = lagrange_gallery::scenes::four_bar::linkage();
    let h = 1e-3;
    let close = |a: &State, b: &State| {
        let (qa, qb) = (a.q.to_array(), b.q.to_array());
        let (va, vb) = (a.v.to_array(), b.v.to_array());
        (0..3).all(|k| (qa[k] - qb[k]).abs() < 1e-12 && (va[k] - vb[k]).abs() < 1e-12)
    };
    let (mut kept, mut fresh) = (start, start);
    let mut memory = NewtonMemory::<3, 2>::default();
    for _ in 0..300 {
        GaussLegendre2::step_with_memory(&sys, &mut memory, &mut kept, h).unwrap();
        sys.step::<GaussLegendre2>(&mut fresh, h).unwrap();
    }
    assert!(close(&kept, &fresh), "{kept:?} vs {fresh:?}");
    let (mut kept, mut fresh) = (start, start);
    let mut memory = NewtonMemory::<3, 1>::default();
    for _ in 0..300 {
        ImplicitMidpoint::step_with_memory(&sys, &mut memory, &mut kept, h).unwrap();
        sys.step::<ImplicitMidpoint>(&mut fresh, h).unwrap();
    }
    assert!(close(&kept, &fresh), "{kept:?} vs {fresh:?}");
    assert!((kept.q.theta1 - start.q.theta1).abs() > 0.3, "{kept:?}");
}
