//! A particle sliding off a sphere, located by an adaptive method's event: the sphere as a
//! bilateral `#[constraint]` |r| − R = 0 integrated by Dop853, whose multiplier λ is the normal
//! force N the sphere would have to exert; the particle leaves where N reaches zero, an event on λ
//! located on the dense output. Against the closed form of `examples/sphere_release.rs`
//! (Goldstein, Poole & Safko, *Classical Mechanics*, 3rd ed., §2.4): from the top with speed v₀,
//! cos θ* = (2 + v₀²/(gR))/3 (2/3 released at rest) and t* = ∫₀^θ* R dθ / v(θ),
//! v² = v₀² + 2gR(1 − cos θ), by Gauss–Legendre quadrature.

use lagrange_gallery::scenes::sphere_release;

use lagrange::constraints::constraint_forces;
use lagrange::integrate::{Direction, Event, StopReason};
use lagrange::prelude::*;

#[mechanism]
pub mod sphere {
    /// The particle's position, sphere centre at the origin, z up.
    pub struct Coords {
        pub x: f64,
        pub y: f64,
        pub z: f64,
    }

    pub struct Sphere {
        pub m: f64,
        pub r: f64,
        pub g: f64,
    }

    #[particle(mass = m)]
    fn particle() -> Vec3 {
        vec3(x, y, z)
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }

    /// On the sphere; its multiplier is the normal force, outwards positive.
    #[constraint]
    fn surface() -> f64 {
        particle.norm() - r
    }
}

/// Dop853 from the top with speed v₀ along x, stopped where λ falls through 0: (t, cos θ) there and
/// the steps taken.
fn leave(v0: f64, tol: f64) -> (f64, f64, usize) {
    use sphere::{Coords, Sphere, State};
    let sys = Sphere {
        m: 0.7,
        r: 1.5,
        g: 9.81,
    };
    let s0 = State::new(
        0.0,
        Coords {
            x: 0.0,
            y: 0.0,
            z: sys.r,
        },
        Coords {
            x: v0,
            y: 0.0,
            z: 0.0,
        },
    );
    let normal = |s: &State| constraint_forces(&sys, s).expect("forces").multipliers[0];
    let mut events = [Event::new(&normal).direction(Direction::Falling).terminal()];
    let mut s = s0;
    let outcome = sys
        .integrate(Dop853::new(tol, tol), &mut s, 10.0, &mut events, |_| {})
        .expect("integration");
    let StopReason::Event(hit) = outcome.reason else {
        panic!("the particle did not leave: {:?}", outcome.reason)
    };
    let q = hit.state.q;
    let steps = outcome.stats.accepted + outcome.stats.rejected;
    (
        hit.state.t,
        q.z / (q.x * q.x + q.y * q.y + q.z * q.z).sqrt(),
        steps,
    )
}

/// The closed form: (t*, cos θ*).
fn closed_form(v0: f64) -> (f64, f64) {
    let (r, g) = (1.5, 9.81);
    let cos_star = (2.0 + v0 * v0 / (g * r)) / 3.0;
    let theta_star = cos_star.acos();
    let speed = |th: f64| (v0 * v0 + 2.0 * g * r * (1.0 - th.cos())).sqrt();
    // 400 panels of 5-point Gauss–Legendre on an analytic integrand (v ≥ v₀ > 0): error far below
    // round-off, so t* is exact to ~1e-16 relative.
    let t_star = sphere_release::gauss_legendre(|th| r / speed(th), 0.0, theta_star, 400);
    (t_star, cos_star)
}

#[test]
fn dop853_event_locates_where_the_particle_leaves_the_sphere() {
    // What bounds the located time |t − t*|: the root finder stops within 1e-13 (the event
    // tolerance), and λ on the dense output is off by Dop853's error δ in (q, q̇), moving the root
    // by δ·|∂λ/∂(q, q̇)|₁ / |λ̇|. With λ = m(g cos θ − v²/R) and v̇ = g sin θ: |∂λ/∂(q, q̇)|₁ ≈
    // m(g + 2v)/R ≈ 7.6 and |λ̇| = 3 m g v sin θ*/R ≈ 32 N/s at release, for both speeds. δ: at
    // most `steps` local errors of tol·(1 + |y|) ≤ 4.2 tol each (mixed tolerance, |y| ≤ v ≈ 3.2),
    // grown at most like e^{√(g/R) t*} ≤ e^{2.6} ≈ 13 (perturbations grow fastest off the unstable
    // top): with tol = 1e-15 and ≤ 50 steps (asserted), δ ≲ 2.7e-12 and |t − t*| ≲ 1e-13 + 6.4e-13,
    // within the required 1e-12. cos θ at the located state is off by δ/R + |d cos θ/dt|·|t − t*|
    // ≲ 1.8e-12 + 1.6 s⁻¹ · 7.4e-13 ≈ 3e-12: asserted to 5e-12.
    let tol = 1e-15;
    for v0 in [1.2, 0.5] {
        let (t_star, cos_star) = closed_form(v0);
        let (t, cos, steps) = leave(v0, tol);
        let (dt, dcos) = (t - t_star, cos - cos_star);
        eprintln!(
            "v₀ = {v0}: left at t = {t:.15} s (closed form {t_star:.15}, {dt:+.1e}), cos θ = {cos:.15} \
             ({dcos:+.1e}), {steps} steps"
        );
        assert!(
            steps <= 50,
            "v₀ = {v0}: {steps} steps, more than the error estimate assumes"
        );
        assert!(dt.abs() < 1e-12, "v₀ = {v0}: t = {t}, t* = {t_star}");
        assert!(
            dcos.abs() < 5e-12,
            "v₀ = {v0}: cos θ = {cos}, cos θ* = {cos_star}"
        );
    }
}
