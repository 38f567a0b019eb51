use lagrange::mechanism;

#[mechanism]
pub mod pendulum {
    pub struct Coords {
        pub theta: f64,
    }

    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
    }

    #[rigid_body(mass = m)]
    fn bar() -> Planar {
        planar(vec2(theta.sin(), -theta.cos()) * l, theta)
    }

}

fn main() {}
