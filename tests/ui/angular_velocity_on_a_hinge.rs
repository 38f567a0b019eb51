use lagrange::prelude::*;

// A hinge's velocity is its angle's rate: only a free or ball joint's chart has an angular
// velocity of three components.
#[mechanism]
pub mod arm {
    pub struct Coords {
        #[angular_velocity]
        pub hinge: f64,
    }

    pub struct Arm {
        pub i: f64,
    }

    #[rigid_body(mass = 1.0, inertia = [i, i, 2.0 * i])]
    fn link() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(hinge))
    }
}

fn main() {}
