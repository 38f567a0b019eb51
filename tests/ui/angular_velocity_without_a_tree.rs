use lagrange::prelude::*;

// A particle turned by a chart is no rigid tree: its coordinates' velocities stay their rates.
#[mechanism]
pub mod bead {
    pub struct Coords {
        #[angular_velocity]
        pub attitude: [f64; 3],
    }

    pub struct Bead {
        pub m: f64,
    }

    #[particle(mass = m)]
    fn bead() -> Vec3 {
        rot_mrp(vec3(attitude[0], attitude[1], attitude[2])) * vec3(1.0, 0.0, 0.0)
    }
}

fn main() {}
