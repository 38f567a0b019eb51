//! The scale matrix: every gallery mechanism and the reference problems (Andrews' squeezer, a
//! satellite in polar coordinates), each declared in systems of units scaled by 10ᵏ in length, in
//! mass and in time separately (k ∈ {−6, −3, 3, 6, 9}) and in three mixed systems, run through
//! `accelerations`, every integrator, `equilibrium` and `normal_modes` (where the mechanism has an
//! equilibrium), the constrained solve (the constraint forces) and the projection
//! (`consistent_state`), and the contact solvers.
//!
//! Every result, taken back to SI, must equal the SI run's to within 10 times that run's own
//! error — for an integrator the difference from a finer run of it (half the step, or a tolerance
//! 1000 times tighter), for a direct evaluation its spread when the inputs are moved by a rounding
//! (the units changed by 1 ± 2⁻⁵⁰), and for a run that locates contact events at least the event
//! locator's tolerance — with the same counts (the adaptive methods' steps, rejections,
//! evaluations, Newton iterations, Jacobians and factorisations; the fixed methods' Jacobians and
//! factorisations), and every refusal must be one the SI run makes too. The fixed implicit
//! methods iterate Newton's method to round-off, so whether a last increment is taken depends on
//! roundings: their iterations must lie within the range the SI run gives under roundings (units
//! near SI). A state is measured against its start's size as well (a mechanism at rest has
//! q̇ = 0).
//!
//! Vectors are compared with each coordinate weighted by √Mᵢᵢ at the start, so components of
//! different units count by their share of the kinetic energy. The adaptive methods run with
//! rtol = 1e-8 and atol = 1e-300, a control relative to every component: a scalar atol has no one
//! unit for a state of angles, lengths and their rates, so only the relative control is the same in
//! every system; their first step is given.
//!
//! Each test prints its mechanism's table (`cargo test --test scale_matrix -- --nocapture`): one
//! line per entry point, one column per system of units, a cell the error over the SI run's own
//! error, "R" a refusal the SI run made as well, "FAIL" otherwise.

#[path = "../common/squeezer.rs"]
mod squeezer_model;
#[path = "../common/units.rs"]
#[allow(dead_code)]
mod units;

mod arm;
mod constrained;
mod harness;
mod satellite;

use harness::{entries, run_entry, systems, table, Entry, Setup};
use lagrange::prelude::*;
use lagrange_gallery::scenes;
use units::*;

/// Runs every entry point in every system of units, prints the table and fails on any cell that
/// is not a pass or a shared refusal.
fn check(entries: Vec<Entry<'_>>, mechanism: &'static str) {
    let systems = systems();
    let rows: Vec<_> = entries
        .iter()
        .map(|e| run_entry(mechanism, e, &systems))
        .collect();
    println!("{}", table(&rows));
    let failures: Vec<String> = rows.iter().flat_map(|r| r.failures()).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn pendulum() {
    use scenes::pendulum::pendulum::Pendulum;
    let make = |u: &Units| Pendulum {
        m: u.express(1.3, MASS),
        l: u.express(0.9, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "pendulum",
        make: &make,
        coords: [ONE],
        start: [[0.6], [0.8]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: Some([0.3]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn double_pendulum() {
    use scenes::double_pendulum::double_pendulum::DoublePendulum;
    let make = |u: &Units| DoublePendulum {
        m1: u.express(1.0, MASS),
        m2: u.express(1.3, MASS),
        l1: u.express(1.0, LENGTH),
        l2: u.express(0.8, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "double pendulum",
        make: &make,
        coords: [ONE, ONE],
        start: [[0.7, -1.2], [1.1, -0.4]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: Some([0.2, -0.1]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn spinning_hoop() {
    use scenes::spinning_hoop::spinning_hoop::SpinningHoop;
    let make = |u: &Units| SpinningHoop {
        m: u.express(0.2, MASS),
        r: u.express(0.5, LENGTH),
        omega: u.express(7.0, RATE),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "spinning hoop",
        make: &make,
        coords: [ONE],
        start: [[0.4], [0.3]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        // cos θ* = g/(ω²R) = 0.4.
        equilibrium: Some([1.0]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn breathing_ellipse() {
    use scenes::breathing_ellipse::breathing_ellipse::BreathingEllipse;
    let make = |u: &Units| BreathingEllipse {
        m: u.express(0.5, MASS),
        a0: u.express(0.6, LENGTH),
        b0: u.express(0.4, LENGTH),
        eps: 0.2,
        omega: u.express(3.0, RATE),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "breathing ellipse",
        make: &make,
        coords: [ONE],
        start: [[0.5], [0.7]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn wedge_block() {
    use scenes::wedge_block::wedge_block::WedgeBlock;
    let make = |u: &Units| WedgeBlock {
        wedge_mass: u.express(3.0, MASS),
        block_mass: u.express(1.0, MASS),
        alpha: 0.5,
        h: u.express(1.0, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "wedge and block",
        make: &make,
        coords: [LENGTH, LENGTH],
        start: [[0.1, 0.2], [0.3, 0.5]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn ramp() {
    use scenes::ramp::ramp::Ramp;
    let make = |u: &Units| Ramp {
        m: u.express(1.0, MASS),
        alpha: 0.4,
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "ramp",
        make: &make,
        coords: [LENGTH],
        start: [[0.2], [0.5]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn atwood() {
    use scenes::atwood::atwood::Atwood;
    let make = |u: &Units| Atwood {
        m1: u.express(2.0, MASS),
        m2: u.express(1.5, MASS),
        pulley_mass: u.express(0.5, MASS),
        pulley_inertia: u.express(0.01, INERTIA),
        r: u.express(0.1, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "Atwood machine",
        make: &make,
        coords: [LENGTH],
        start: [[0.1], [0.4]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn rigid_triangle() {
    use scenes::rigid_triangle::lamina::Lamina;
    use scenes::rigid_triangle::three_particles::ThreeParticles;
    let make = |u: &Units| ThreeParticles {
        m1: u.express(1.0, MASS),
        m2: u.express(2.0, MASS),
        m3: u.express(1.5, MASS),
        x1: u.express(0.3, LENGTH),
        y1: u.express(-0.2, LENGTH),
        x2: u.express(-0.1, LENGTH),
        y2: u.express(-0.5, LENGTH),
        x3: u.express(0.4, LENGTH),
        y3: u.express(-0.6, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "three particles",
        make: &make,
        coords: [ONE],
        start: [[0.3], [0.5]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: Some([0.2]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
    let make = |u: &Units| Lamina {
        mass: u.express(2.0, MASS),
        inertia: u.express(0.3, INERTIA),
        cx: u.express(0.2, LENGTH),
        cy: u.express(-0.1, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "lamina",
        make: &make,
        coords: [ONE],
        start: [[0.3], [0.5]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: Some([0.2]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn identify_pendulum() {
    use scenes::identify_pendulum::damped_pendulum::DampedPendulum;
    let make = |u: &Units| DampedPendulum {
        m: u.express(1.0, MASS),
        l: u.express(1.0, LENGTH),
        g: u.express(9.81, ACCELERATION),
        // A torque per angular velocity: M L² T⁻¹.
        c: u.express(0.3, dim(2, 1, -1)),
    };
    let setup = Setup {
        name: "damped pendulum",
        make: &make,
        coords: [ONE],
        start: [[0.5], [0.2]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: Some([0.3]),
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn gyroscope() {
    use scenes::gyroscope::gyroscope::Gyroscope;
    let make = |u: &Units| Gyroscope {
        m: u.express(1.0, MASS),
        a: u.express(0.02, INERTIA),
        c: u.express(0.04, INERTIA),
        k: u.express(0.3, TORQUE),
    };
    let setup = Setup {
        name: "gyroscope",
        make: &make,
        coords: [ONE, ONE, ONE],
        start: [[0.1, 0.5, 0.2], [0.3, 0.1, 20.0]],
        h: 1e-3,
        steps: 20,
        span: 0.02,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn kepler_polar() {
    // A 1000 kg satellite at 7000 km from the Earth's centre (GM from the IERS Conventions 2010,
    // Table 1.1), slightly eccentric; one minute in steps of 3 s.
    use satellite::kepler_polar::KeplerPolar;
    let gm = 3.986004418e14;
    let make = |u: &Units| KeplerPolar {
        m: u.express(1000.0, MASS),
        gm: u.express(gm, dim(3, 0, -2)),
    };
    let r = 7e6;
    let rate = 1.1 * (gm / (r * r * r)).sqrt();
    let setup = Setup {
        name: "satellite",
        make: &make,
        coords: [LENGTH, ONE],
        start: [[r, 0.3], [120.0, rate]],
        h: 3.0,
        steps: 20,
        span: 60.0,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}

#[test]
fn cartesian_pendulum() {
    use scenes::cartesian_pendulum::cartesian_pendulum::CartesianPendulum;
    let make = |u: &Units| CartesianPendulum {
        m: u.express(1.5, MASS),
        l: u.express(0.8, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    let setup = Setup {
        name: "Cartesian pendulum",
        make: &make,
        coords: [LENGTH, LENGTH],
        start: [[0.48, -0.64], [0.8, 0.6]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    check(list, setup.name);
}

#[test]
fn four_bar() {
    use scenes::four_bar::{four_bar::FourBar, linkage};
    let (sys, s) = linkage();
    let make = move |u: &Units| FourBar {
        l1: u.express(sys.l1, LENGTH),
        l2: u.express(sys.l2, LENGTH),
        l3: u.express(sys.l3, LENGTH),
        m1: u.express(sys.m1, MASS),
        m2: u.express(sys.m2, MASS),
        m3: u.express(sys.m3, MASS),
        d: u.express(sys.d, LENGTH),
        g: u.express(sys.g, ACCELERATION),
    };
    let setup = Setup {
        name: "four-bar",
        make: &make,
        coords: [ONE, ONE, ONE],
        start: [s.q.to_array(), s.v.to_array()],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    check(list, setup.name);
}

#[test]
fn rolling_wheel() {
    use scenes::rolling_wheel::rolling_wheel::RollingWheel;
    let make = |u: &Units| RollingWheel {
        m: u.express(1.0, MASS),
        r: u.express(0.3, LENGTH),
    };
    // Rolling: ẋ = r θ̇ cos φ, ẏ = r θ̇ sin φ.
    let (phi, phi_dot, theta_dot) = (0.2f64, 0.5, 2.0);
    let setup = Setup {
        name: "rolling wheel",
        make: &make,
        coords: [LENGTH, LENGTH, ONE, ONE],
        start: [
            [0.1, 0.2, phi, 0.3],
            [
                0.3 * theta_dot * phi.cos(),
                0.3 * theta_dot * phi.sin(),
                phi_dot,
                theta_dot,
            ],
        ],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    check(list, setup.name);
}

#[test]
fn sphere_release() {
    use scenes::sphere_release::sphere_release::SphereRelease;
    let make = |u: &Units| SphereRelease {
        m: u.express(1.0, MASS),
        r: u.express(1.0, LENGTH),
        g: u.express(9.81, ACCELERATION),
    };
    // On the sphere 0.3 rad from the top, sliding off at 0.5 m/s: it leaves at cos θ = 2/3 + v²/3gR,
    // within the span.
    let (theta, speed) = (0.3f64, 0.5);
    let setup = Setup {
        name: "sphere release",
        make: &make,
        coords: [LENGTH, LENGTH],
        start: [
            [theta.sin(), theta.cos()],
            [speed * theta.cos(), -speed * theta.sin()],
        ],
        h: 1e-2,
        steps: 40,
        span: 0.5,
        equilibrium: None,
        contacts: true,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    list.extend(constrained::contact_entries(&setup));
    check(list, setup.name);
}

#[test]
fn rough_ramp() {
    use scenes::rough_ramp::rough_ramp::RoughRamp;
    let alpha = 0.5f64;
    let make = |u: &Units| RoughRamp {
        m: u.express(1.0, MASS),
        alpha,
        g: u.express(9.81, ACCELERATION),
        mu_k: 0.3,
        mu_s: 0.4,
    };
    // On the ramp, sliding up at 1 m/s: it stops within the span and slides back
    // (tan α = 0.55 > μs = 0.4).
    let setup = Setup {
        name: "rough ramp",
        make: &make,
        coords: [LENGTH, LENGTH],
        start: [[1.0, alpha.tan()], [alpha.cos(), alpha.sin()]],
        h: 1e-2,
        steps: 40,
        span: 0.4,
        equilibrium: None,
        contacts: true,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    list.extend(constrained::contact_entries(&setup));
    check(list, setup.name);
}

#[test]
fn rough_wedge() {
    use scenes::rough_wedge::rough_wedge::RoughWedge;
    let alpha = 0.5f64;
    let make = |u: &Units| RoughWedge {
        wedge_mass: u.express(3.0, MASS),
        block_mass: u.express(1.0, MASS),
        alpha,
        h: u.express(1.0, LENGTH),
        g: u.express(9.81, ACCELERATION),
        mu_k: 0.2,
        mu_s: 0.3,
    };
    // The block on the face (bx − x) sin α + (by − h) cos α = 0, sliding down it at 0.4 m/s.
    let (x, bx) = (0.0, 0.3);
    let by = 1.0 - (bx - x) * alpha.tan();
    let (xd, slide) = (0.1, 0.4);
    let setup = Setup {
        name: "rough wedge",
        make: &make,
        coords: [LENGTH, LENGTH, LENGTH],
        start: [
            [x, bx, by],
            [xd, xd + slide * alpha.cos(), -slide * alpha.sin()],
        ],
        h: 1e-2,
        steps: 20,
        span: 0.2,
        equilibrium: None,
        contacts: true,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    list.extend(constrained::contact_entries(&setup));
    check(list, setup.name);
}

#[test]
fn rough_plane() {
    use scenes::rough_plane::rough_plane::RoughPlane;
    let make = |u: &Units| RoughPlane {
        m: u.express(1.0, MASS),
        g: u.express(9.81, ACCELERATION),
        mu_k: 0.3,
        mu_s: 0.4,
        push: u.express(1.0, FORCE),
    };
    let setup = Setup {
        name: "rough plane",
        make: &make,
        coords: [LENGTH, LENGTH, LENGTH],
        start: [[0.1, 0.2, 0.0], [0.5, 0.3, 0.0]],
        h: 1e-2,
        steps: 30,
        span: 0.3,
        equilibrium: None,
        contacts: true,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    list.extend(constrained::contact_entries(&setup));
    check(list, setup.name);
}

#[test]
fn pushed_block() {
    use scenes::pushed_block::pushed_block::PushedBlock;
    let alpha = 0.3f64;
    let make = |u: &Units| PushedBlock {
        m: u.express(1.0, MASS),
        g: u.express(9.81, ACCELERATION),
        alpha,
        mu_k: 0.3,
        mu_s: 0.4,
        push: u.express(0.5, FORCE),
    };
    let setup = Setup {
        name: "pushed block",
        make: &make,
        coords: [LENGTH, LENGTH, LENGTH],
        start: [
            [0.2, 1.0, alpha.tan()],
            [0.2, 0.3 * alpha.cos(), 0.3 * alpha.sin()],
        ],
        h: 1e-2,
        steps: 30,
        span: 0.3,
        equilibrium: None,
        contacts: true,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    list.extend(constrained::contact_entries(&setup));
    check(list, setup.name);
}

#[test]
fn andrews_squeezer() {
    use squeezer_model::{andrews_in, ANDREWS};
    let make = |u: &Units| andrews_in(|value, [l, m, t]| u.express(value, dim(l, m, t)));
    // From the state 20 Gauss-Legendre steps of 1e-5 s after Hairer & Wanner's start, where every
    // velocity is nonzero (the adaptive methods' control is relative to each component).
    let mut s = squeezer_model::start();
    for _ in 0..20 {
        ANDREWS
            .step::<lagrange::GaussLegendre2>(&mut s, 1e-5)
            .unwrap();
    }
    let setup = Setup {
        name: "Andrews' squeezer",
        make: &make,
        coords: [ONE; 7],
        start: [s.q.to_array(), s.v.to_array()],
        h: 1e-5,
        steps: 10,
        span: 2e-4,
        equilibrium: None,
        contacts: false,
    };
    let mut list = entries(&setup);
    list.extend(constrained::entries(&setup));
    check(list, setup.name);
}

#[test]
fn spatial_arm() {
    use arm::arm::Arm;
    // The gallery's arm (`scenes::spatial_arm`), swinging about its base.
    let make = |u: &Units| Arm {
        m1: u.express(3.0, MASS),
        m2: u.express(2.0, MASS),
        m3: u.express(1.2, MASS),
        d1: u.express(0.4, LENGTH),
        d2: u.express(0.5, LENGTH),
        d3: u.express(0.4, LENGTH),
        e: u.express(0.06, LENGTH),
        g: u.express(9.81, ACCELERATION),
        i1x: u.express(0.04, INERTIA),
        i1y: u.express(0.04, INERTIA),
        i1z: u.express(0.01, INERTIA),
        i2x: u.express(0.03, INERTIA),
        i2y: u.express(0.03, INERTIA),
        i2z: u.express(0.004, INERTIA),
        i3x: u.express(0.02, INERTIA),
        i3y: u.express(0.018, INERTIA),
        i3z: u.express(0.003, INERTIA),
    };
    let setup = Setup {
        name: "spatial arm",
        make: &make,
        coords: [ONE, ONE, ONE],
        start: [[0.0, 1.1, -0.6], [2.0, 0.3, 0.5]],
        h: 1e-3,
        steps: 20,
        span: 0.05,
        equilibrium: None,
        contacts: false,
    };
    check(entries(&setup), setup.name);
}
