use lagrange::mechanism;

#[mechanism]
pub mod m {
    pub struct Coords {
        pub x: f64,
    }

    pub struct P {
        pub m: f64,
        pub i: f64,
    }

    #[rigid_body(mass = m, inertia = i, count = 2)]
    fn bars(j: usize) -> Planar {
        planar(vec2(x, j as f64), x)
    }

    #[torque(on = bars)]
    fn motor() -> f64 {
        1.0
    }
}

fn main() {}
