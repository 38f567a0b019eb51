//! Rigid bodies declared by their frames: `#[rigid_body(com = .., inertia = [[..], [..], [..]])]`
//! with the pose of a joint frame, against the same bodies declared by their centres of mass and
//! principal axes (today's form: principal moments, an explicit rotation by the tensor's
//! eigenvectors and an explicit centre-of-mass offset). The two declarations are the same physics;
//! every quantity must agree to round-off at random states, and a free-swinging arm must conserve
//! its energy over a run as RK4 promises.

use lagrange::prelude::*;
use proptest::prelude::*;

#[allow(dead_code)]
mod common;

// The arm declared by its frames and by its principal axes, shared with `scripts/callgrind`.
#[path = "common/framed_arms.rs"]
mod framed_arms;
use framed_arms::{framed, framed_arm, principal, principal_arm};

fn states(q: [f64; 3], v: [f64; 3]) -> (framed_arm::State, principal_arm::State) {
    let [q1, q2, q3] = q;
    let [v1, v2, v3] = v;
    (
        framed_arm::State::new(
            0.0,
            framed_arm::Coords { q1, q2, q3 },
            framed_arm::Coords {
                q1: v1,
                q2: v2,
                q3: v3,
            },
        ),
        principal_arm::State::new(
            0.0,
            principal_arm::Coords { q1, q2, q3 },
            principal_arm::Coords {
                q1: v1,
                q2: v2,
                q3: v3,
            },
        ),
    )
}

/// |a − b| ≤ tol · max(scale, 1) entry by entry, with the scale the larger magnitude of either.
fn assert_close(what: &str, a: &[f64], b: &[f64], tol: f64) {
    let scale = a.iter().chain(b).fold(1.0_f64, |m, x| m.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= tol * scale, "{what}: {a:?} vs {b:?}");
    }
}

fn angle() -> impl Strategy<Value = f64> {
    -std::f64::consts::PI..std::f64::consts::PI
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every quantity of the two declarations at random states. They differ in round-off only:
    /// one takes the principal axes from the tensor by an eigen-decomposition, accurate to
    /// ~ε·|I|/gap with gaps ≥ 10% of |I|, and composes its rotations by other formulas (Rodrigues,
    /// roll-pitch-yaw multiplied out). Measured: every quantity within 5e-16 of its scale, q̈
    /// within 3e-15; 1e-13 is ~500 ε, and q̈, a solve with M (condition number < 1e3 here), gets
    /// 1e-12.
    #[test]
    fn a_body_declared_by_its_frame_is_the_same_body(
        q in [angle(), angle(), angle()],
        v in [-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64],
    ) {
        let (a, b) = (framed(), principal());
        let (sa, sb) = states(q, v);
        let m = a.mass_matrix(&sa).unwrap();
        assert_close("M", m.as_slice(), b.mass_matrix(&sb).unwrap().as_slice(), 1e-13);
        let cond = m.symmetric_eigenvalues().max() / m.symmetric_eigenvalues().min();
        prop_assert!(cond < 1e3, "cond M = {cond}");
        let to = |c: framed_arm::Coords| [c.q1, c.q2, c.q3];
        let tp = |c: principal_arm::Coords| [c.q1, c.q2, c.q3];
        assert_close(
            "q̈",
            &to(a.accelerations(&sa).unwrap()),
            &tp(b.accelerations(&sb).unwrap()),
            1e-12,
        );
        assert_close(
            "𝓕",
            &to(a.generalized_forces(&sa).unwrap()),
            &tp(b.generalized_forces(&sb).unwrap()),
            1e-13,
        );
        assert_close("p", &to(a.momenta(&sa).unwrap()), &tp(b.momenta(&sb).unwrap()), 1e-13);
        let energies = |t: f64, u: f64, e: f64| [t, u, e];
        assert_close(
            "T, V, E",
            &energies(a.kinetic_energy(&sa).unwrap(), a.potential_energy(&sa).unwrap(), a.energy(&sa).unwrap()),
            &energies(b.kinetic_energy(&sb).unwrap(), b.potential_energy(&sb).unwrap(), b.energy(&sb).unwrap()),
            1e-13,
        );
        // Through the validated handle, the same.
        let handle = a.validated().unwrap();
        assert_close(
            "q̈ (validated)",
            &to(handle.accelerations(&sa).unwrap()),
            &tp(b.accelerations(&sb).unwrap()),
            1e-12,
        );
    }

    /// `Bodies` holds each link's frame as its function returns it, `BodyVelocities` the velocity
    /// of the frame's origin and the angular velocity; the centre of mass is `frame.point(com)`.
    #[test]
    fn bodies_are_frames_and_their_velocities_the_frames_velocities(
        q in [angle(), angle(), angle()],
        v in [-5.0..5.0f64, -5.0..5.0f64, -5.0..5.0f64],
    ) {
        let (a, b) = (framed(), principal());
        let (sa, sb) = states(q, v);
        let (frames, centres) = (a.bodies(&sa), b.bodies(&sb));
        // The same rotations by other formulas (Rodrigues against Rz·Rx·Rz, roll-pitch-yaw
        // multiplied out against the product): a few ulps apart (measured 5e-16).
        let (o3, r3) = principal_arm::frame3(q[0], q[1], q[2], a.l1, a.l2);
        assert_close("o₃", &frames.link3.position.to_array(), &o3.to_array(), 1e-14);
        let flat = |r: Rot3<f64>| r.rows.concat();
        assert_close("R₃", &flat(frames.link3.rotation), &flat(r3), 1e-14);
        let com3 = vec3(a.c3x, a.c3y, a.c3z);
        assert_close(
            "centre of mass 3",
            &frames.link3.point(com3).to_array(),
            &centres.link3.position.to_array(),
            1e-14,
        );
        let (wa, wb) = (a.body_velocities(&sa), b.body_velocities(&sb));
        // ω is the body's, whatever frame it is read in.
        assert_close("ω₃", &wa.link3.angular.to_array(), &wb.link3.angular.to_array(), 1e-13);
        // ṙ = ċ − ω × (R c).
        let offset = frames.link3.rotation * com3;
        let expected = wb.link3.linear - wb.link3.angular.cross(&offset);
        assert_close("ṙ₃", &wa.link3.linear.to_array(), &expected.to_array(), 1e-13);
        // And ṙ is the derivative of the frame's origin: a central difference along q̇, whose
        // error h²/6 |d³r/ds³| (h = 1e-5, |d³r/ds³| ≲ 10³ at these speeds) is below 1e-7.
        let h = 1e-5;
        let shifted = |s: f64| {
            let qs: [f64; 3] = std::array::from_fn(|j| q[j] + s * v[j]);
            a.bodies(&states(qs, v).0).link2.position
        };
        let difference = (shifted(h) - shifted(-h)) / (2.0 * h);
        assert_close("ṙ₂ by differences", &wa.link2.linear.to_array(), &difference.to_array(), 1e-7);
    }
}

/// The arm swinging free under gravity (no spring, force or torque) for one second: RK4's energy
/// error over a fixed time is O(h⁴), so halving the step must divide it by about 16 (measured:
/// 19 from 2 ms to 1 ms, 17 from 1 ms to 0.5 ms), and at 0.5 ms it is 3e-10 J (measured), ~1e-11
/// of the energy's scale m g l ≈ 10 J.
#[test]
fn a_free_swinging_arm_conserves_its_energy() {
    let mut arm = framed();
    (arm.k, arm.f, arm.tau) = (0.0, 0.0, 0.0);
    let sys = arm.validated().unwrap();
    let drift = |h: f64| {
        let (mut s, _) = states([0.3, 1.2, -0.8], [1.0, -0.5, 2.0]);
        let e0 = sys.energy(&s).unwrap();
        for _ in 0..(1.0 / h).round() as usize {
            sys.step::<Rk4>(&mut s, h).unwrap();
        }
        (sys.energy(&s).unwrap() - e0).abs()
    };
    let (coarse, fine) = (drift(1e-3), drift(5e-4));
    let ratio = coarse / fine;
    assert!(
        (12.0..22.0).contains(&ratio),
        "{coarse:e} / {fine:e} = {ratio}"
    );
    assert!(fine < 1e-9, "{fine:e}");
}

/// The tensor's principal moments are refused by name as sensitivities' seeds, like masses: they
/// enter the dynamics as plain numbers. A centre of mass too.
#[test]
fn centres_of_mass_and_tensors_are_not_seedable() {
    use lagrange::sensitivity::Seed;
    let sys = framed();
    let (s, _) = states([0.3, 1.2, -0.8], [1.0, -0.5, 2.0]);
    let seeded = |name| {
        Stepper::new(&sys, Rk4::with_step(1e-3), &s)?.with_sensitivities([Seed::Parameter(name)])
    };
    for name in ["c2x", "t1xy", "m3"] {
        let refused = seeded(name);
        assert!(
            matches!(refused, Err(Error::UnseedableParameter { .. })),
            "{name}: {:?}",
            refused.err()
        );
    }
    assert!(seeded("l1").is_ok());
}

/// Two rods in the plane, each declared by its joint frame with its centre of mass off the rod's
/// line: the upper turning about the origin, the lower at the upper's end by a relative angle.
#[mechanism]
pub mod framed_rods {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct FramedRods {
        pub m1: f64,
        pub m2: f64,
        pub i1: f64,
        pub i2: f64,
        pub l1: f64,
        pub c1: f64,
        pub c2: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m1, inertia = i1, com = vec2(c1, 0.05))]
    fn upper() -> Planar {
        planar(vec2(0.0, 0.0), theta1)
    }
    #[rigid_body(mass = m2, inertia = i2, com = vec2(c2, -0.03))]
    fn lower() -> Planar {
        upper.joint(vec2(l1, 0.0), theta2)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The same rods by their centres of mass, written out.
#[mechanism]
pub mod explicit_rods {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct ExplicitRods {
        pub m1: f64,
        pub m2: f64,
        pub i1: f64,
        pub i2: f64,
        pub l1: f64,
        pub c1: f64,
        pub c2: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m1, inertia = i1)]
    fn upper() -> Planar {
        let (along, across) = (
            vec2(theta1.cos(), theta1.sin()),
            vec2(-theta1.sin(), theta1.cos()),
        );
        planar(along * c1 + across * 0.05, theta1)
    }
    #[rigid_body(mass = m2, inertia = i2)]
    fn lower() -> Planar {
        let a = theta1 + theta2;
        let elbow = vec2(theta1.cos(), theta1.sin()) * l1;
        let (along, across) = (vec2(a.cos(), a.sin()), vec2(-a.sin(), a.cos()));
        planar(elbow + along * c2 - across * 0.03, a)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

fn rods() -> (framed_rods::FramedRods, explicit_rods::ExplicitRods) {
    let (m1, m2, i1, i2, l1, c1, c2, g) = (1.1, 0.7, 0.09, 0.05, 0.9, 0.42, 0.35, 9.81);
    (
        framed_rods::FramedRods {
            m1,
            m2,
            i1,
            i2,
            l1,
            c1,
            c2,
            g,
        },
        explicit_rods::ExplicitRods {
            m1,
            m2,
            i1,
            i2,
            l1,
            c1,
            c2,
            g,
        },
    )
}

/// States over several turns, velocities of both signs.
fn rod_states() -> impl Iterator<Item = ([f64; 2], [f64; 2])> {
    (0..25).map(|i| {
        let f = i as f64;
        (
            [(0.9 * f).sin() * 4.0, (0.9 * f + 1.7).sin() * 4.0],
            [(1.3 * f).cos() * 3.0, (1.3 * f - 0.6).cos() * 3.0],
        )
    })
}

/// A planar body's `com` is read by the closed form (its centre of mass is `frame.point(com)`, a
/// polynomial in the sines and cosines): the declaration takes the closed form, which must agree
/// with the dual-number passes over the same positions and with the rods written out. The same
/// sums of products in another order: a few ulps of each term's scale (1e-13).
#[test]
fn planar_bodies_declared_by_their_frames_take_the_closed_form() {
    use lagrange::__private::{dynamics, Dynamics};
    use lagrange::evaluation::Evaluate;
    let (framed, explicit) = rods();
    const { assert!(<framed_rods::FramedRods as Dynamics<2>>::CLOSED_FORM) };
    for (q, v) in rod_states() {
        let closed = Evaluate::equations_of_motion_at(&framed, 0.0, &q, &v);
        let dual = dynamics::equations_of_motion::<_, f64, 2, 6>(&framed, 0.0, &q, &v);
        let written = Evaluate::equations_of_motion_at(&explicit, 0.0, &q, &v);
        for other in [&dual, &written] {
            assert_close(
                "M",
                closed.mass_matrix.as_slice(),
                other.mass_matrix.as_slice(),
                1e-13,
            );
            assert_close(
                "𝓕",
                closed.generalized_forces.as_slice(),
                other.generalized_forces.as_slice(),
                1e-13,
            );
            assert_close(
                "b",
                closed.inertial_terms.as_slice(),
                other.inertial_terms.as_slice(),
                1e-13,
            );
        }
    }
}

/// The rods with a spring at the lower rod's tip and a damper on its joint frame's origin (the
/// elbow): the potential reads the lower rod's frame (`lower.point`), the force its velocity
/// (`lower_dot.position`, the elbow's velocity) and acts at its centre of mass.
#[mechanism]
pub mod sprung_framed_rods {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct SprungFramedRods {
        pub m1: f64,
        pub m2: f64,
        pub i1: f64,
        pub i2: f64,
        pub l1: f64,
        pub l2: f64,
        pub k: f64,
        pub c: f64,
    }
    #[rigid_body(mass = m1, inertia = i1, com = vec2(0.4, 0.05))]
    fn upper() -> Planar {
        planar(vec2(0.0, 0.0), theta1)
    }
    #[rigid_body(mass = m2, inertia = i2, com = vec2(0.3, -0.03))]
    fn lower() -> Planar {
        upper.joint(vec2(l1, 0.0), theta2)
    }
    #[potential]
    fn spring() -> f64 {
        let stretch = lower.point(vec2(l2, 0.0)) - vec2(0.5, -1.0);
        0.5 * k * stretch.norm_squared()
    }
    #[force(on = lower)]
    fn damper() -> Vec2 {
        lower_dot.position * (-c)
    }
}

/// The same, written out: the tip and the elbow's velocity from the angles.
#[mechanism]
pub mod sprung_explicit_rods {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }
    pub struct SprungExplicitRods {
        pub m1: f64,
        pub m2: f64,
        pub i1: f64,
        pub i2: f64,
        pub l1: f64,
        pub l2: f64,
        pub k: f64,
        pub c: f64,
    }
    #[rigid_body(mass = m1, inertia = i1)]
    fn upper() -> Planar {
        let (along, across) = (
            vec2(theta1.cos(), theta1.sin()),
            vec2(-theta1.sin(), theta1.cos()),
        );
        planar(along * 0.4 + across * 0.05, theta1)
    }
    #[rigid_body(mass = m2, inertia = i2)]
    fn lower() -> Planar {
        let a = theta1 + theta2;
        let elbow = vec2(theta1.cos(), theta1.sin()) * l1;
        let (along, across) = (vec2(a.cos(), a.sin()), vec2(-a.sin(), a.cos()));
        planar(elbow + along * 0.3 - across * 0.03, a)
    }
    #[potential]
    fn spring() -> f64 {
        let a = theta1 + theta2;
        let tip = vec2(theta1.cos(), theta1.sin()) * l1 + vec2(a.cos(), a.sin()) * l2;
        let stretch = tip - vec2(0.5, -1.0);
        0.5 * k * stretch.norm_squared()
    }
    #[force(on = lower)]
    fn damper() -> Vec2 {
        let elbow_velocity = vec2(-theta1.sin(), theta1.cos()) * (l1 * theta1_dot);
        elbow_velocity * (-c)
    }
}

/// Potentials and forces see a planar body declared by its frame as that frame, and its velocity
/// as the frame's: the same equations as the rods written out, to round-off (1e-13 of the scale,
/// as above; q̈ through a solve with a well-conditioned 2×2 M, 1e-12).
#[test]
fn potentials_and_forces_see_a_planar_body_by_its_frame() {
    let framed = sprung();
    let explicit = sprung_explicit_rods::SprungExplicitRods {
        m1: 1.1,
        m2: 0.7,
        i1: 0.09,
        i2: 0.05,
        l1: 0.9,
        l2: 0.8,
        k: 12.0,
        c: 0.6,
    };
    for (q, v) in rod_states() {
        let [t1, t2] = q;
        let [w1, w2] = v;
        let sa = sprung_framed_rods::State::new(
            0.0,
            sprung_framed_rods::Coords {
                theta1: t1,
                theta2: t2,
            },
            sprung_framed_rods::Coords {
                theta1: w1,
                theta2: w2,
            },
        );
        let sb = sprung_explicit_rods::State::new(
            0.0,
            sprung_explicit_rods::Coords {
                theta1: t1,
                theta2: t2,
            },
            sprung_explicit_rods::Coords {
                theta1: w1,
                theta2: w2,
            },
        );
        let qa = framed.accelerations(&sa).unwrap();
        let qb = explicit.accelerations(&sb).unwrap();
        assert_close("q̈", &[qa.theta1, qa.theta2], &[qb.theta1, qb.theta2], 1e-12);
        let fa = framed.generalized_forces(&sa).unwrap();
        let fb = explicit.generalized_forces(&sb).unwrap();
        assert_close("𝓕", &[fa.theta1, fa.theta2], &[fb.theta1, fb.theta2], 1e-13);
        let (ea, eb) = (framed.energy(&sa).unwrap(), explicit.energy(&sb).unwrap());
        assert_close("E", &[ea], &[eb], 1e-13);
        // The frame's origin is the elbow; its velocity l₁ θ̇₁ (−sin θ₁, cos θ₁).
        let lower = framed.body_velocities(&sa).lower;
        let elbow = vec2(-t1.sin(), t1.cos()) * (framed.l1 * w1);
        assert_close("ṙ", &lower.position.to_array(), &elbow.to_array(), 1e-13);
        assert_close("θ̇", &[lower.angle], &[w1 + w2], 1e-15);
    }
}

fn sprung() -> sprung_framed_rods::SprungFramedRods {
    sprung_framed_rods::SprungFramedRods {
        m1: 1.1,
        m2: 0.7,
        i1: 0.09,
        i2: 0.05,
        l1: 0.9,
        l2: 0.8,
        k: 12.0,
        c: 0.6,
    }
}

/// Sensitivities by the parameters that place the frames: `l1` (the lower rod's joint, in a
/// position) and `l2` (the spring's end on the lower rod's frame, in the potential), through the
/// generated `Parametrized` functions that map each frame to its centre of mass. Against finite
/// differences of the same discrete map (1 s of RK4, h = 1e-3), to the differences' own error
/// (estimated in `common::check_against_finite_differences`).
#[test]
fn sensitivities_by_the_parameters_that_place_the_frames() {
    use lagrange::sensitivity::Seed;
    use sprung_framed_rods::{Coords, State};
    let s0 = State::new(
        0.0,
        Coords {
            theta1: 1.2,
            theta2: -0.4,
        },
        Coords {
            theta1: 0.3,
            theta2: 0.1,
        },
    );
    let seeds = [Seed::Parameter("l1"), Seed::Parameter("l2")];
    let (h, steps) = (1e-3, 1000);
    let (real, jacobian) = common::rk4_tangent_end(&sprung(), s0, seeds, h, steps);
    let plain = common::rk4_end(&sprung(), s0, h, steps);
    // Rounding only: the same steps through two orderings of the same arithmetic.
    assert_close("real parts", &real, &plain, 1e-11);
    let central = |seed: usize, delta: f64| -> [f64; 4] {
        let shifted = |sign: f64| {
            let mut p = sprung();
            match seed {
                0 => p.l1 += sign * delta,
                _ => p.l2 += sign * delta,
            }
            common::rk4_end(&p, s0, h, steps)
        };
        let (plus, minus) = (shifted(1.0), shifted(-1.0));
        std::array::from_fn(|i| (plus[i] - minus[i]) / (2.0 * delta))
    };
    let labels: Vec<String> = seeds.iter().map(Seed::label).collect();
    common::check_against_finite_differences(&jacobian, &labels, plain, steps, central);
    assert!(jacobian
        .iter()
        .all(|column| column.iter().any(|x| x.abs() > 1e-2)));
}

/// A family of three rods, each declared by its joint frame at the end of the one before, with
/// the same centre of mass offset in every frame.
#[mechanism]
pub mod framed_chain {
    pub const LINKS: usize = 3;
    pub struct Coords {
        pub theta: [f64; LINKS],
    }
    pub struct FramedChain {
        pub m: f64,
        pub i: f64,
        pub l: f64,
        pub c: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = i, com = vec2(c, 0.02), count = LINKS)]
    fn rod(k: usize) -> Planar {
        if k == 0 {
            planar(vec2(0.0, 0.0), theta[0])
        } else {
            rod[k - 1].joint(vec2(l, 0.0), theta[k])
        }
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// The same chain by its centres of mass: each rod's frame origin recovered from the centre of
/// mass before it.
#[mechanism]
pub mod explicit_chain {
    pub const LINKS: usize = 3;
    pub struct Coords {
        pub theta: [f64; LINKS],
    }
    pub struct ExplicitChain {
        pub m: f64,
        pub i: f64,
        pub l: f64,
        pub c: f64,
        pub g: f64,
    }
    #[rigid_body(mass = m, inertia = i, count = LINKS)]
    fn rod(k: usize) -> Planar {
        if k == 0 {
            planar(vec2(c, 0.02).rotated(theta[0]), theta[0])
        } else {
            let before = rod[k - 1];
            let joint = before.position - vec2(c, 0.02).rotated(before.angle)
                + vec2(l, 0.0).rotated(before.angle);
            let angle = before.angle + theta[k];
            planar(joint + vec2(c, 0.02).rotated(angle), angle)
        }
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

/// A family declared by its frames is the family written out: q̈ and E to round-off (as above), and
/// each member's frame at the end of the one before.
#[test]
fn a_family_of_bodies_declared_by_their_frames() {
    let framed = framed_chain::FramedChain {
        m: 0.6,
        i: 0.02,
        l: 0.5,
        c: 0.22,
        g: 9.81,
    };
    let explicit = explicit_chain::ExplicitChain {
        m: 0.6,
        i: 0.02,
        l: 0.5,
        c: 0.22,
        g: 9.81,
    };
    for k in 0..10 {
        let f = k as f64;
        let q = [
            (0.7 * f).sin() * 3.0,
            (0.7 * f + 1.0).sin(),
            (0.7 * f + 2.0).cos() * 2.0,
        ];
        let v = [
            (1.1 * f).cos(),
            (1.1 * f - 0.5).cos() * 2.0,
            (0.3 * f).sin(),
        ];
        let sa = framed_chain::State::new(
            0.0,
            framed_chain::Coords { theta: q },
            framed_chain::Coords { theta: v },
        );
        let sb = explicit_chain::State::new(
            0.0,
            explicit_chain::Coords { theta: q },
            explicit_chain::Coords { theta: v },
        );
        let (qa, qb) = (
            framed.accelerations(&sa).unwrap(),
            explicit.accelerations(&sb).unwrap(),
        );
        assert_close("q̈", &qa.theta, &qb.theta, 1e-12);
        assert_close(
            "E",
            &[framed.energy(&sa).unwrap()],
            &[explicit.energy(&sb).unwrap()],
            1e-13,
        );
        let rods = framed.bodies(&sa).rod;
        let joint = rods[1].point(vec2(framed.l, 0.0));
        assert_close(
            "joint",
            &rods[2].position.to_array(),
            &joint.to_array(),
            1e-15,
        );
    }
}

/// What the C export builds a mechanism from: the parameters by name and as flat values, the
/// centres of mass and tensors among them; a mechanism rebuilt from them is the same mechanism.
#[test]
fn the_declaration_of_a_framed_arm_round_trips_its_parameters() {
    use lagrange::declaration::Declaration;
    type Arm = framed_arm::FramedArm;
    assert_eq!(<Arm as Declaration>::DOF, 3);
    let names = <Arm as Declaration>::PARAMETERS;
    assert!(names.contains(&"c2y") && names.contains(&"t3yz"));
    let arm = framed();
    let values = arm.parameters();
    assert_eq!(values.len(), names.len());
    let rebuilt = Arm::from_parameters(&values).unwrap();
    let (s, _) = states([0.3, 1.2, -0.8], [1.0, -0.5, 2.0]);
    assert_eq!(arm.accelerations(&s), rebuilt.accelerations(&s));
}
