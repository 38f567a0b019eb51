//! Inputs (`#[inputs]`): what a program sets between steps, read by the forces and held over each
//! evaluation. Each mechanism here is declared twice — with inputs, and with the same quantities
//! as parameters — and `sys.driven(&u)` must equal the parameter twin with the parameters set to
//! `u`, on every path the macro chooses for it (the dense pass, the rigid tree's recursions, the
//! constrained solve), for accelerations, the equations of motion, inverse dynamics and a run.
//!
//! Tolerances: the two declarations evaluate the same formulas, the twin reading `tau` as a
//! parameter (which the optimiser may fold with other constants), so they agree to a few rounding
//! errors; 1e-12 relative leaves a margin of ~10³ over the ~1e-15 seen.

use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;
use lagrange::{Inputs, Seed};

/// A disc on a shaft with viscous friction, driven by a motor: j θ̈ = τ − c θ̇.
#[mechanism]
pub mod motor {
    pub struct Coords {
        pub theta: f64,
    }
    pub struct Motor {
        pub j: f64,
        pub c: f64,
    }
    #[inputs]
    pub struct Torque {
        pub tau: f64,
    }
    #[rigid_body(mass = 1.0, inertia = j)]
    fn disc() -> Planar {
        planar(vec2(0.0, 0.0), theta)
    }
    #[generalized_force(on = theta)]
    fn drive() -> f64 {
        tau - c * theta_dot
    }
}

/// Two spatial links on revolute joints, a motor at each joint, gravity: the rigid tree pass. The
/// motors' torques are written at the call (a name bound by the declaration and read in a
/// `macro_rules!` body would be two names to the compiler).
macro_rules! two_link_arm {
    ($name:ident, $params:ident, { $($extra:tt)* }, { $($inputs:tt)* },
     $motor1:block, $motor2:block, $wrist:block) => {
        #[mechanism]
        pub mod $name {
            pub struct Coords {
                pub q1: f64,
                pub q2: f64,
            }
            pub struct $params {
                pub m1: f64,
                pub m2: f64,
                pub l: f64,
                pub g: f64,
                $($extra)*
            }
            $($inputs)*
            #[rigid_body(mass = m1, com = vec3(0.0, 0.02, 0.5 * l),
                         inertia = [[0.03, 0.001, 0.0], [0.001, 0.025, 0.0], [0.0, 0.0, 0.012]])]
            fn link1() -> Spatial {
                spatial(vec3(0.0, 0.0, 0.1), rot_y(q1))
            }
            #[rigid_body(mass = m2, com = vec3(0.01, 0.0, 0.4 * l),
                         inertia = [[0.02, 0.0, 0.002], [0.0, 0.02, 0.0], [0.002, 0.0, 0.011]])]
            fn link2() -> Spatial {
                link1.joint(vec3(0.0, 0.05, l), rot_x(0.2) * rot_y(q2))
            }
            #[gravity]
            fn down() -> Vec3 {
                vec3(0.0, 0.0, -g)
            }
            #[generalized_force(on = q1)]
            fn motor1() -> f64 $motor1
            #[generalized_force(on = q2)]
            fn motor2() -> f64 $motor2
            #[torque(on = link2)]
            fn wrist() -> Vec3 $wrist
        }
    };
}

two_link_arm!(
    driven_arm,
    DrivenArm,
    {},
    {
        #[inputs]
        pub struct Torques {
            pub tau: [f64; 2],
            pub push: f64,
        }
    },
    { tau[0] },
    { tau[1] },
    { vec3(0.0, 0.0, push) }
);
two_link_arm!(twin_arm, TwinArm, { pub tau: [f64; 2], pub push: f64, }, {},
    { tau[0] }, { tau[1] }, { vec3(0.0, 0.0, push) });

/// A pendulum in Cartesian coordinates held by a rod (a bilateral constraint), pushed sideways:
/// the constrained solve.
macro_rules! pushed_pendulum {
    ($name:ident, $params:ident, { $($extra:tt)* }, { $($inputs:tt)* }, $push:block) => {
        #[mechanism]
        pub mod $name {
            pub struct Coords {
                pub x: f64,
                pub y: f64,
            }
            pub struct $params {
                pub m: f64,
                pub l: f64,
                pub g: f64,
                $($extra)*
            }
            $($inputs)*
            #[particle(mass = m)]
            fn bob() -> Vec2 {
                vec2(x, y)
            }
            #[gravity]
            fn down() -> Vec2 {
                vec2(0.0, -g)
            }
            #[force(on = bob)]
            fn push() -> Vec2 $push
            #[constraint]
            fn rod() -> f64 {
                x * x + y * y - l * l
            }
        }
    };
}

pushed_pendulum!(
    driven_pendulum,
    DrivenPendulum,
    {},
    {
        #[inputs]
        pub struct Push {
            pub f: f64,
        }
    },
    { vec2(f, 0.0) }
);
pushed_pendulum!(twin_pendulum, TwinPendulum, { pub f: f64, }, {}, { vec2(f, 0.0) });

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn a_motor_torque_is_read_where_the_mechanism_is_driven_and_zero_where_it_is_not() {
    let sys = motor::Motor { j: 0.5, c: 0.1 };
    let state = motor::State {
        t: 0.0,
        q: motor::Coords { theta: 0.3 },
        v: motor::Coords { theta: 2.0 },
    };
    let u = motor::Torque { tau: 1.5 };
    // j θ̈ = τ − c θ̇, exactly (one division and two products).
    let driven = sys.driven(&u).accelerations(&state).unwrap();
    assert!((driven.theta - (1.5 - 0.1 * 2.0) / 0.5).abs() < 1e-15);
    let plain = sys.accelerations(&state).unwrap();
    assert!((plain.theta - (-0.1 * 2.0) / 0.5).abs() < 1e-15);
    assert_eq!(
        sys.driven(&motor::Torque::default())
            .accelerations(&state)
            .unwrap(),
        plain
    );
    // Through a validated handle, the same.
    let handle = sys.validated().unwrap();
    assert_eq!(handle.driven(&u).accelerations(&state).unwrap(), driven);
    assert_eq!(<motor::Torque as lagrange::Inputs<1>>::NAMES, ["tau"]);
}

fn arm_pair(
    tau: [f64; 2],
    push: f64,
) -> (
    driven_arm::DrivenArm,
    driven_arm::Torques,
    twin_arm::TwinArm,
) {
    let (m1, m2, l, g) = (1.2, 0.8, 0.45, 9.81);
    (
        driven_arm::DrivenArm { m1, m2, l, g },
        driven_arm::Torques { tau, push },
        twin_arm::TwinArm {
            m1,
            m2,
            l,
            g,
            tau,
            push,
        },
    )
}

#[test]
fn a_driven_rigid_arm_equals_its_twin_with_the_inputs_as_parameters() {
    // The inputs do not change the path: the arm takes the rigid tree's recursions.
    assert_eq!(<driven_arm::DrivenArm as RigidTree<2, 2>>::JOINTS.len(), 2);
    for (tau, push) in [([0.0, 0.0], 0.0), ([1.5, -0.7], 0.3), ([-4.0, 2.5], -1.1)] {
        let (arm, u, twin) = arm_pair(tau, push);
        let handle = arm_pair(tau, push).0.validated().unwrap();
        let twin_handle = twin.validated().unwrap();
        for (q1, q2, v1, v2) in [(0.3, -0.8, 0.5, 1.2), (1.9, 0.4, -2.0, 0.1)] {
            let state = driven_arm::State {
                t: 0.0,
                q: driven_arm::Coords { q1, q2 },
                v: driven_arm::Coords { q1: v1, q2: v2 },
            };
            let twin_state = twin_arm::State {
                t: 0.0,
                q: twin_arm::Coords { q1, q2 },
                v: twin_arm::Coords { q1: v1, q2: v2 },
            };
            let expected = twin_handle.accelerations(&twin_state).unwrap();
            for a in [
                handle.driven(&u).accelerations(&state).unwrap(),
                arm.driven(&u).accelerations(&state).unwrap(),
            ] {
                assert!(
                    close(a.q1, expected.q1) && close(a.q2, expected.q2),
                    "{a:?} {expected:?}"
                );
            }
            let forces = handle.driven(&u).generalized_forces(&state).unwrap();
            let twin_forces = twin_handle.generalized_forces(&twin_state).unwrap();
            assert!(close(forces.q1, twin_forces.q1) && close(forces.q2, twin_forces.q2));
            // Inverse dynamics (Newton–Euler) sees the inputs as the twin sees its parameters.
            let wanted = driven_arm::Coords { q1: 0.7, q2: -1.3 };
            let tau_id = handle.driven(&u).inverse_dynamics(&state, &wanted).unwrap();
            let twin_id = twin_handle
                .inverse_dynamics(&twin_state, &twin_arm::Coords { q1: 0.7, q2: -1.3 })
                .unwrap();
            assert!(close(tau_id.q1, twin_id.q1) && close(tau_id.q2, twin_id.q2));
        }
    }
}

#[test]
fn computed_torque_from_inverse_dynamics_gives_the_wanted_accelerations() {
    // With the motors the only inputs and each acting on its own coordinate, the generalized
    // forces inverse dynamics returns at zero inputs are the motor torques that produce q̈.
    let (arm, _, _) = arm_pair([0.0, 0.0], 0.0);
    let handle = arm.validated().unwrap();
    let state = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.4, q2: 1.1 },
        v: driven_arm::Coords { q1: -0.3, q2: 0.9 },
    };
    let wanted = driven_arm::Coords { q1: 2.0, q2: -0.5 };
    let tau = handle.inverse_dynamics(&state, &wanted).unwrap();
    let u = driven_arm::Torques {
        tau: [tau.q1, tau.q2],
        push: 0.0,
    };
    let a = handle.driven(&u).accelerations(&state).unwrap();
    assert!(close(a.q1, wanted.q1) && close(a.q2, wanted.q2), "{a:?}");
}

#[test]
fn a_driven_run_holds_the_inputs_over_each_step() {
    let (arm, u, twin) = arm_pair([0.8, -0.4], 0.2);
    let state = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.2, q2: -0.5 },
        v: driven_arm::Coords { q1: 0.0, q2: 0.0 },
    };
    let twin_state = twin_arm::State {
        t: 0.0,
        q: twin_arm::Coords { q1: 0.2, q2: -0.5 },
        v: twin_arm::Coords { q1: 0.0, q2: 0.0 },
    };
    let handle = arm.validated().unwrap();
    let driven = handle.driven(&u);
    let (mut s, mut s_twin) = (state, twin_state);
    for _ in 0..200 {
        driven.step::<Rk4>(&mut s, 1e-3).unwrap();
        twin.step::<Rk4>(&mut s_twin, 1e-3).unwrap();
    }
    assert!(close(s.q.q1, s_twin.q.q1) && close(s.q.q2, s_twin.q.q2));
    assert!(close(s.v.q1, s_twin.v.q1) && close(s.v.q2, s_twin.v.q2));
    // A zero-order hold: stepping in two halves with the inputs set again between them is the
    // same run (the inputs are constant over each step, and nothing else is held between steps).
    let mut halves = state;
    for _ in 0..2 {
        let driven = handle.driven(&u);
        for _ in 0..100 {
            driven.step::<Rk4>(&mut halves, 1e-3).unwrap();
        }
    }
    assert_eq!(halves, s);
}

#[test]
fn a_driven_constrained_mechanism_equals_its_twin() {
    let (m, l, g, f) = (0.7, 1.3, 9.81, 2.2);
    let sys = driven_pendulum::DrivenPendulum { m, l, g };
    let twin = twin_pendulum::TwinPendulum { m, l, g, f };
    let (x, y) = (l * 0.6f64.sin(), -l * 0.6f64.cos());
    let (vx, vy) = (0.8 * 0.6f64.cos(), 0.8 * 0.6f64.sin());
    let state = driven_pendulum::State {
        t: 0.0,
        q: driven_pendulum::Coords { x, y },
        v: driven_pendulum::Coords { x: vx, y: vy },
    };
    let twin_state = twin_pendulum::State {
        t: 0.0,
        q: twin_pendulum::Coords { x, y },
        v: twin_pendulum::Coords { x: vx, y: vy },
    };
    let u = driven_pendulum::Push { f };
    for handle_or_not in [false, true] {
        let a = match handle_or_not {
            false => sys.driven(&u).accelerations(&state).unwrap(),
            true => driven_pendulum::DrivenPendulum { m, l, g }
                .validated()
                .unwrap()
                .driven(&u)
                .accelerations(&state)
                .unwrap(),
        };
        let expected = twin.accelerations(&twin_state).unwrap();
        assert!(
            close(a.x, expected.x) && close(a.y, expected.y),
            "{a:?} {expected:?}"
        );
    }
    let (mut s, mut s_twin) = (state, twin_state);
    for _ in 0..100 {
        sys.driven(&u).step::<Rk4>(&mut s, 1e-3).unwrap();
        twin.step::<Rk4>(&mut s_twin, 1e-3).unwrap();
    }
    assert!(close(s.q.x, s_twin.q.x) && close(s.q.y, s_twin.q.y));
}

#[test]
fn the_input_matrix_is_the_derivative_of_the_accelerations_by_the_inputs() {
    use lagrange::inputs::input_matrix;
    // The motor: j θ̈ = τ − c θ̇, so ∂θ̈/∂τ = 1/j exactly.
    let motor = motor::Motor { j: 0.5, c: 0.1 };
    let state = motor::State {
        t: 0.0,
        q: motor::Coords { theta: 0.3 },
        v: motor::Coords { theta: 2.0 },
    };
    let b = input_matrix(&motor, &motor::Torque { tau: 1.0 }, &state).unwrap();
    assert!((b[(0, 0)] - 2.0).abs() < 1e-15);
    // The arm, against central differences of the driven accelerations. The accelerations are
    // affine in the inputs, so the differences' error is rounding alone: ~1e-16 |q̈| / h with
    // h = 1e-4, far inside 1e-9.
    let (arm, u, _) = arm_pair([0.6, -0.2], 0.4);
    let state = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.5, q2: -0.9 },
        v: driven_arm::Coords { q1: 0.3, q2: 0.7 },
    };
    let b = input_matrix(&arm, &u, &state).unwrap();
    let flat = |u: &driven_arm::Torques| [u.tau[0], u.tau[1], u.push];
    let h = 1e-4;
    for j in 0..3 {
        let shifted = |s: f64| {
            let mut values = flat(&u);
            values[j] += s;
            let u = driven_arm::Torques {
                tau: [values[0], values[1]],
                push: values[2],
            };
            arm.driven(&u).accelerations(&state).unwrap()
        };
        let (plus, minus) = (shifted(h), shifted(-h));
        let column = [
            (plus.q1 - minus.q1) / (2.0 * h),
            (plus.q2 - minus.q2) / (2.0 * h),
        ];
        for i in 0..2 {
            assert!(
                (b[(i, j)] - column[i]).abs() < 1e-9,
                "B[{i},{j}] = {} vs {}",
                b[(i, j)],
                column[i]
            );
        }
    }
    // The wrist torque acts on both joints through the arm's geometry: a column of its own.
    assert!(b[(1, 2)].abs() > 1e-3);
}

#[test]
fn sensitivities_to_a_parameter_of_a_driven_mechanism_read_the_inputs() {
    // The motor, j θ̈ = τ − c θ̇, seeded on the friction c: θ̇(t) = τ/c + (θ̇₀ − τ/c) e^{−ct/j},
    // so ∂θ̇/∂c and ∂θ/∂c depend on τ, which the lifted forces must read.
    let (j, c, tau, v0, t_end) = (0.5, 0.1, 1.5, 2.0, 1.0);
    let motor = motor::Motor { j, c };
    let driven = motor.driven(&motor::Torque { tau });
    let start = motor::State {
        t: 0.0,
        q: motor::Coords { theta: 0.3 },
        v: motor::Coords { theta: v0 },
    };
    let mut run = Stepper::new(&driven, Rk4::with_step(1e-3), &start)
        .unwrap()
        .with_sensitivities([Seed::Parameter("c")])
        .unwrap();
    run.integrate(t_end, &mut [], |_| {}).unwrap();
    let s = run.sensitivities();
    // θ = θ₀ + a t + w (1 − E)/k with a = τ/c, w = θ̇₀ − a, k = c/j, E = e^{−kt}, differentiated
    // by c (∂a/∂c = −τ/c², ∂w/∂c = τ/c², ∂k/∂c = 1/j, ∂E/∂c = −tE/j).
    let (a, k) = (tau / c, c / j);
    let (w, e) = (v0 - a, (-k * t_end).exp());
    let dv_dc = -tau / (c * c) + tau / (c * c) * e - w * t_end / j * e;
    let dq_dc = -tau * t_end / (c * c)
        + tau / (c * c) * (1.0 - e) / k
        + w * (t_end * e / j / k - (1.0 - e) / (k * k * j));
    // RK4's error on this linear equation (rate k = 0.2, h = 1e-3) is ~(kh)⁵/120 per step, far
    // below rounding; what is left is ~1e-13 of rounding over the 1000 steps.
    assert!(
        (s.dv[0].theta - dv_dc).abs() < 1e-10,
        "{} vs {dv_dc}",
        s.dv[0].theta
    );
    assert!(
        (s.dq[0].theta - dq_dc).abs() < 1e-10,
        "{} vs {dq_dc}",
        s.dq[0].theta
    );
    // Without the torque the derivative is another: the inputs are read, not dropped.
    assert!((dv_dc - (-v0 * t_end / j * e)).abs() > 1.0);
}

/// Two point masses on massless rods, a motor at the elbow only (an acrobot): underactuated.
#[mechanism]
pub mod acrobot {
    pub struct Coords {
        pub shoulder: f64,
        pub elbow: f64,
    }
    pub struct Acrobot {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }
    #[inputs]
    pub struct Motor {
        pub torque: f64,
    }
    #[particle(mass = m)]
    fn upper() -> Vec2 {
        vec2(shoulder.sin(), -shoulder.cos()) * l
    }
    #[particle(mass = m)]
    fn lower() -> Vec2 {
        upper + vec2((shoulder + elbow).sin(), -(shoulder + elbow).cos()) * l
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
    #[generalized_force(on = elbow)]
    fn motor() -> f64 {
        torque
    }
}

#[test]
fn inverse_dynamics_gives_the_inputs_where_each_acts_on_a_coordinate_of_its_own() {
    use lagrange::inputs::Actuated;
    assert_eq!(<acrobot::Acrobot as Actuated<1>>::COORDINATES, Some([1]));
    // The arm's wrist torque acts through the body: no coordinate map.
    assert_eq!(<driven_arm::DrivenArm as Actuated<3>>::COORDINATES, None);
    let sys = acrobot::Acrobot {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    };
    let state = acrobot::State {
        t: 0.0,
        q: acrobot::Coords {
            shoulder: 0.4,
            elbow: -0.3,
        },
        v: acrobot::Coords {
            shoulder: 1.0,
            elbow: 0.5,
        },
    };
    // Accelerations the motor can produce (those of a torque of 2.5) give back that torque; the
    // shoulder's generalized force is then zero to rounding.
    let reachable = sys
        .driven(&acrobot::Motor { torque: 2.5 })
        .accelerations(&state)
        .unwrap();
    let u = sys.inverse_dynamics_inputs(&state, &reachable).unwrap();
    assert!((u.torque - 2.5).abs() < 1e-12, "{u:?}");
    // Accelerations that need a shoulder torque are refused, naming the shoulder.
    let wanted = acrobot::Coords {
        shoulder: 1.0,
        elbow: 1.0,
    };
    let refused = sys.inverse_dynamics_inputs(&state, &wanted);
    assert!(
        matches!(&refused, Err(Error::UnsuitableMethod { reason, .. }) if reason.contains("`shoulder`")),
        "{refused:?}"
    );
    // Inputs that are not one generalized force per coordinate are refused.
    let (arm, _, _) = arm_pair([0.0, 0.0], 0.0);
    let arm_state = driven_arm::State::at_rest(driven_arm::Coords { q1: 0.1, q2: 0.2 });
    assert!(matches!(
        arm.inverse_dynamics_inputs(&arm_state, &driven_arm::Coords { q1: 0.0, q2: 0.0 }),
        Err(Error::UnsuitableMethod { .. })
    ));
}

#[test]
fn linearize_driven_gives_the_input_matrix_of_the_declared_inputs() {
    use lagrange::analysis::{linearize, linearize_driven};
    let (arm, u, _) = arm_pair([0.6, -0.2], 0.4);
    let state = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.5, q2: -0.9 },
        v: driven_arm::Coords { q1: 0.3, q2: 0.7 },
    };
    let lin = linearize_driven(&arm, &state, &u).unwrap();
    // A is linearize's at the driven state, q̈₀ the driven accelerations.
    assert_eq!(
        lin.linearization,
        linearize(&arm.driven(&u), &state).unwrap()
    );
    let a = arm.driven(&u).accelerations(&state).unwrap();
    assert!(close(lin.linearization.accelerations[0], a.q1));
    assert!(close(lin.linearization.accelerations[1], a.q2));
    assert_eq!(lin.inputs, [0.6, -0.2, 0.4]);
    // B = [0; ∂q̈/∂u], 2N × NU, against central differences of the driven accelerations. q̈ is
    // affine in the inputs here (motor torques and a wrist torque), so the differences have no
    // truncation error (their error term is h²/6 ∂³q̈/∂u³ = 0); rounding leaves ~1e-16 |q̈| / h
    // with h = 1e-4, ~1e-11 — 1e-9 is a margin of 100 over it.
    let b = lin.b_matrix();
    assert_eq!(b.shape(), (4, 3));
    let h = 1e-4;
    for (j, name) in <driven_arm::Torques as Inputs<3>>::NAMES.iter().enumerate() {
        let shifted = |s: f64| {
            let mut values = u.to_array();
            values[j] += s;
            arm.driven(&driven_arm::Torques::from_array(values))
                .accelerations(&state)
                .unwrap()
        };
        let (plus, minus) = (shifted(h), shifted(-h));
        let column = [
            (plus.q1 - minus.q1) / (2.0 * h),
            (plus.q2 - minus.q2) / (2.0 * h),
        ];
        for i in 0..2 {
            assert_eq!(b[(i, j)], 0.0);
            assert!(
                (b[(2 + i, j)] - column[i]).abs() < 1e-9,
                "B[{}, {name}] = {} vs {}",
                2 + i,
                b[(2 + i, j)],
                column[i]
            );
        }
    }
    // Through a validated handle, the same.
    let handle = arm.validated().unwrap();
    let through_handle = linearize_driven(&handle, &state, &u).unwrap();
    for (x, y) in through_handle
        .dqdd_dinputs
        .iter()
        .zip(lin.dqdd_dinputs.iter())
    {
        assert!(close(*x, *y));
    }
}

#[test]
fn the_input_matrix_of_a_constrained_mechanism_is_the_constrained_solves() {
    use lagrange::analysis::linearize_driven;
    // The bob on its rod, pushed along x by f: only the push's component along the circle
    // accelerates it, ∂q̈/∂f = (I − n nᵀ) eₓ / m with n = (x, y) / l the rod's direction
    // (the rod takes the rest) — not the unconstrained M⁻¹ eₓ = (1/m, 0).
    let (m, l, g) = (0.7, 1.3, 9.81);
    let sys = driven_pendulum::DrivenPendulum { m, l, g };
    let angle: f64 = 0.6;
    let (x, y) = (l * angle.sin(), -l * angle.cos());
    let state = driven_pendulum::State {
        t: 0.0,
        q: driven_pendulum::Coords { x, y },
        v: driven_pendulum::Coords {
            x: 0.8 * angle.cos(),
            y: 0.8 * angle.sin(),
        },
    };
    let u = driven_pendulum::Push { f: 2.2 };
    let lin = linearize_driven(&sys, &state, &u).unwrap();
    let b = lin.dqdd_dinputs;
    let expected = [(1.0 - x * x / (l * l)) / m, -x * y / (l * l) / m];
    for i in 0..2 {
        // The constrained solve's few operations: a few rounding errors.
        assert!(
            (b[(i, 0)] - expected[i]).abs() < 1e-12,
            "{} vs {}",
            b[(i, 0)],
            expected[i]
        );
    }
    // Against central differences of the driven accelerations: q̈ of the constrained solve is
    // affine in the force at a fixed state (λ solves a linear system whose right-hand side is
    // affine in 𝓕), so no truncation error; rounding ~1e-16 |q̈| / h with h = 1e-4.
    let h = 1e-4;
    let at = |f: f64| {
        sys.driven(&driven_pendulum::Push { f })
            .accelerations(&state)
            .unwrap()
    };
    let (plus, minus) = (at(u.f + h), at(u.f - h));
    let column = [
        (plus.x - minus.x) / (2.0 * h),
        (plus.y - minus.y) / (2.0 * h),
    ];
    for i in 0..2 {
        assert!(
            (b[(i, 0)] - column[i]).abs() < 1e-9,
            "{} vs {}",
            b[(i, 0)],
            column[i]
        );
    }
}

/// The arm stepped by RK4 (h = 1e-3) to `t_end` from `start` with the inputs `u` held.
fn driven_run(u: &driven_arm::Torques, start: &driven_arm::State, t_end: f64) -> driven_arm::State {
    let (arm, _, _) = arm_pair(u.tau, u.push);
    let driven = arm.driven(u);
    let mut run = Stepper::new(&driven, Rk4::with_step(1e-3), start).unwrap();
    run.integrate(t_end, &mut [], |_| {}).unwrap();
    run.state()
}

#[test]
fn sensitivities_seeded_on_inputs_match_differences_of_driven_runs() {
    let (arm, u, _) = arm_pair([0.6, -0.2], 0.4);
    let driven = arm.driven(&u);
    let start = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.5, q2: -0.9 },
        v: driven_arm::Coords { q1: 0.3, q2: 0.7 },
    };
    let t_end = 0.5;
    let seeds = [
        Seed::Input("tau[1]"),
        Seed::Input("push"),
        Seed::Coordinate("q1"),
    ];
    let mut run = Stepper::new(&driven, Rk4::with_step(1e-3), &start)
        .unwrap()
        .with_sensitivities(seeds)
        .unwrap();
    run.integrate(t_end, &mut [], |_| {}).unwrap();
    let s = run.sensitivities();
    assert_eq!(s.seeds, seeds);
    assert_eq!(Seed::Input("tau[1]").label(), "tau[1]");
    // The state is the driven run's (the same RK4 steps, on the duals' real parts).
    let plain = driven_run(&u, &start, t_end);
    assert!(close(s.state.q.q1, plain.q.q1) && close(s.state.q.q2, plain.q.q2));
    // ∂q(T)/∂u against central differences of two driven runs of the same steps: both are
    // derivatives of the same discrete RK4 map, so they differ by the differences' error alone,
    // δ²/6 |∂³(q, q̇)(T)/∂u³| + ~1e-16 |(q, q̇)| / δ. The arm swings far over T = 0.5 and the third
    // derivatives are large (the differences close in on the tangent as δ², from ~6e-5 relative
    // at δ = 1e-3 to ~6e-9 at δ = 1e-5 for ∂q₁/∂τ₁, ~2e-8 for ∂q̇₁/∂τ₁): at δ = 1e-5 the
    // truncation is ≲ 2e-8 relative and rounding ~1e-10, inside 1e-7 (relative to 1 + |∂/∂u|).
    let delta = 1e-5;
    for (j, slot) in [(0, 1), (1, 2)] {
        let shifted = |s: f64| {
            let mut values = u.to_array();
            values[slot] += s;
            driven_run(&driven_arm::Torques::from_array(values), &start, t_end)
        };
        let (plus, minus) = (shifted(delta), shifted(-delta));
        let dq = [
            (plus.q.q1 - minus.q.q1) / (2.0 * delta),
            (plus.q.q2 - minus.q.q2) / (2.0 * delta),
        ];
        let dv = [
            (plus.v.q1 - minus.v.q1) / (2.0 * delta),
            (plus.v.q2 - minus.v.q2) / (2.0 * delta),
        ];
        let tangent = [s.dq[j].q1, s.dq[j].q2, s.dv[j].q1, s.dv[j].q2];
        for (k, (got, want)) in tangent.iter().zip(dq.iter().chain(dv.iter())).enumerate() {
            assert!(
                (got - want).abs() < 1e-7 * (1.0 + want.abs()),
                "seed {:?}, component {k}: {got} vs {want}",
                seeds[j]
            );
        }
        // An input that acts moves the state.
        assert!(tangent.iter().any(|x| x.abs() > 1e-3), "{tangent:?}");
    }
}

#[test]
fn seeds_on_inputs_are_refused_where_there_is_no_such_input() {
    let (arm, u, twin) = arm_pair([0.6, -0.2], 0.4);
    let start = driven_arm::State {
        t: 0.0,
        q: driven_arm::Coords { q1: 0.5, q2: -0.9 },
        v: driven_arm::Coords { q1: 0.3, q2: 0.7 },
    };
    let driven = arm.driven(&u);
    // A name the inputs do not have (the array field's name alone is not an input).
    for name in ["tau", "tau[2]", "l"] {
        let refused = Stepper::new(&driven, Rk4::with_step(1e-3), &start)
            .unwrap()
            .with_sensitivities([Seed::Input(name)])
            .err();
        assert!(
            matches!(&refused, Some(Error::UnknownInput { name: n, known })
                if n == name && known == "`tau[0]`, `tau[1]`, `push`"),
            "{refused:?}"
        );
    }
    // A mechanism that declares no inputs.
    let twin_start = twin_arm::State::at_rest(twin_arm::Coords { q1: 0.5, q2: -0.9 });
    let refused = Stepper::new(&twin, Rk4::with_step(1e-3), &twin_start)
        .unwrap()
        .with_sensitivities([Seed::Input("push")])
        .err();
    assert!(
        matches!(&refused, Some(Error::UnknownInput { known, .. }) if known.starts_with("none")),
        "{refused:?}"
    );
    // A parameter beside an input: the lifted forces read no inputs.
    let refused = Stepper::new(&arm, Rk4::with_step(1e-3), &start)
        .unwrap()
        .with_sensitivities([Seed::Input("push"), Seed::Parameter("l")])
        .err();
    assert!(matches!(
        refused,
        Some(Error::ParameterSeedWithInputs { name: "l" })
    ));
    // A constrained mechanism: the projection is not differentiated, inputs or not.
    let (m, l, g) = (0.7, 1.3, 9.81);
    let pendulum = driven_pendulum::DrivenPendulum { m, l, g };
    let push = driven_pendulum::Push { f: 1.0 };
    let pushed = pendulum.driven(&push);
    let hanging = driven_pendulum::State::at_rest(driven_pendulum::Coords { x: 0.0, y: -l });
    let refused = Stepper::new(&pushed, Rk4::with_step(1e-3), &hanging)
        .unwrap()
        .with_sensitivities([Seed::Input("f")])
        .err();
    assert!(
        matches!(refused, Some(Error::UnsuitableMethod { .. })),
        "{refused:?}"
    );
}
