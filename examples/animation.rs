//! See it move: two mechanisms declared here — a double pendulum in the plane and an arm of two
//! rigid rods in space, declared by their joint frames — simulated and recorded into self-contained HTML animations,
//! `plots/animation_double_pendulum.html` and `plots/animation_arm.html`. Open them in a browser:
//! play, pause, drag the time slider, change the speed; turn the arm's camera by dragging, zoom with
//! the wheel. Each page carries its player and its trajectory, and needs no network.
//!
//! ```text
//! cargo run --release --example animation
//! ```

use lagrange::animation::Recorder;
use lagrange::prelude::*;

#[mechanism]
pub mod double_pendulum {
    /// Angles of the two arms from the downward vertical.
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

    /// Written from `bob1`: the animation draws the line between them.
    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod arm {
    /// The shoulder turns the upper arm about the vertical (yaw) and lifts it (pitch); the elbow
    /// bends the forearm about the same axis as the pitch, carried by the upper arm.
    pub struct Coords {
        pub yaw: f64,
        pub pitch: f64,
        pub elbow: f64,
    }

    pub struct Arm {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    /// A uniform rod of length l along its frame's z axis, declared by its joint frame as a
    /// robot's link is: the frame at the shoulder (the origin), the centre of mass `com` halfway
    /// along; moments m l²/12 across the rod, and a thin rod's small one along it. The animation
    /// draws the frame, at the joint.
    #[rigid_body(mass = m, com = vec3(0.0, 0.0, 0.5 * l),
                 inertia = [m * l * l / 12.0, m * l * l / 12.0, m * l * l / 1200.0])]
    fn upper() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(yaw) * rot_y(pitch))
    }

    /// The same rod, its frame at the elbow: the upper arm's far end, turned about its y axis.
    #[rigid_body(mass = m, com = vec3(0.0, 0.0, 0.5 * l),
                 inertia = [m * l * l / 12.0, m * l * l / 12.0, m * l * l / 1200.0])]
    fn forearm() -> Spatial {
        upper.joint(vec3(0.0, 0.0, l), rot_y(elbow))
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let plots = lagrange_gallery::plots_dir();

    // Twenty seconds of the double pendulum released with both arms horizontal.
    use double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    }
    .validated()?;
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut s = State::at_rest(Coords {
        theta1: half_pi,
        theta2: half_pi,
    });
    // 30 frames per simulated second, the outer bob's path over the last 2 s.
    let mut recorder = Recorder::new(&sys)
        .title("Double pendulum released from horizontal")
        .trail_length(2.0)?;
    recorder
        .fixed_point("pivot", &[0.0, 0.0])?
        .link("pivot", "bob1")?
        .trail("bob2")?;
    recorder.push(&sys, &s)?;
    sys.simulate::<Rk4>(&mut s, 1e-3, 20_000, recorder.observer(&sys))?;
    let page = plots.join("animation_double_pendulum.html");
    recorder.write_html(&page)?;
    println!("{} frames: {}", recorder.frames(), page.display());

    // Ten seconds of the arm, released at an angle and turning about the vertical.
    let arm = arm::Arm {
        m: 1.0,
        l: 0.8,
        g: 9.81,
    }
    .validated()?;
    let mut s = arm::State::new(
        0.0,
        arm::Coords {
            yaw: 0.0,
            pitch: 1.2,
            elbow: 0.6,
        },
        arm::Coords {
            yaw: 1.5,
            pitch: 0.0,
            elbow: 0.0,
        },
    );
    let mut recorder = Recorder::new(&arm).title("An arm of two rods swinging in space");
    // Each link is drawn at its joint (the shoulder, the elbow), the line between them from the
    // declaration; the hand is the forearm's far end.
    recorder
        .mark("hand", "forearm", &[0.0, 0.0, 0.8])?
        .trail("hand")?;
    recorder.push(&arm, &s)?;
    arm.simulate::<Rk4>(&mut s, 1e-3, 10_000, recorder.observer(&arm))?;
    let page = plots.join("animation_arm.html");
    recorder.write_html(&page)?;
    println!("{} frames: {}", recorder.frames(), page.display());
    Ok(())
}
