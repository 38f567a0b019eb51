use lagrange::prelude::*;

#[mechanism]
pub mod top {
    pub struct Coords {
        pub yaw: f64,
        pub pitch: f64,
        pub roll: f64,
    }

    pub struct Top {
        pub m: f64,
        pub i: f64,
        pub tau: f64,
    }

    #[rigid_body(mass = m, inertia = [i, i, i])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(yaw) * rot_y(pitch) * rot_x(roll))
    }

    #[torque(on = body)]
    fn drive() -> f64 {
        tau
    }
}

fn main() {}
