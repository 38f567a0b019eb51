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

    #[particle(mass = m)]
    fn bob() -> Vec2 {
        vec2(theta.sin(), -theta.cos()) * l
    }

    // The macro runs before `cfg` is evaluated: this body would still be laid out.
    #[cfg(any())]
    #[particle(mass = m)]
    fn extra() -> Vec2 {
        bob * 2.0
    }
}

fn main() {}
