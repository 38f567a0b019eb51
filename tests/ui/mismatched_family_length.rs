use lagrange::prelude::*;

#[mechanism]
pub mod chain {
    pub const LINKS: usize = 8;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub c: f64,
    }

    #[particle(mass = m, count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
        if i == 0 {
            link
        } else {
            bob[i - 1] + link
        }
    }

    #[force(on = bob, count = 4)]
    fn drag(i: usize) -> Vec2 {
        bob_dot[i] * (-c)
    }
}

fn main() {}
