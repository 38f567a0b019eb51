use lagrange::prelude::*;

// A family of three links reads its masses from an array of two: member 2 has none.
#[mechanism]
pub mod chain {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Chain {
        pub m: [f64; 2],
        pub l: [f64; LINKS],
    }

    #[particle(mass = m[i], count = LINKS)]
    fn bob(i: usize) -> Vec2 {
        let link = vec2(theta[i].sin(), -theta[i].cos()) * l[i];
        if i == 0 {
            link
        } else {
            bob[i - 1] + link
        }
    }
}

fn main() {}
