//! Mechanisms declared from `macro_rules!`: a length passed as `$n:literal` or `$n:expr` arrives in
//! an invisible group, and the macro looks through it.
use lagrange::prelude::*;

macro_rules! chain {
    ($name:ident, $params:ident, $n:literal) => {
        #[mechanism]
        pub mod $name {
            pub const LINKS: usize = $n;
            pub struct Coords {
                pub theta: [f64; $n],
            }
            pub struct $params {
                pub m: f64,
                pub l: f64,
                pub g: f64,
            }
            #[particle(mass = m, count = $n)]
            fn bob(i: usize) -> Vec2 {
                let link = vec2(theta[i].sin(), -theta[i].cos()) * l;
                if i == 0 {
                    link
                } else {
                    bob[i - 1] + link
                }
            }
            #[gravity]
            fn down() -> Vec2 {
                vec2(0.0, -g)
            }
        }
    };
}

macro_rules! pendulum_of {
    ($name:ident, $len:expr, $mass:expr, $down:ty) => {
        #[mechanism]
        pub mod $name {
            pub struct Coords {
                pub theta: [f64; $len],
            }
            pub struct P {
                pub m: f64,
                pub g: f64,
            }
            #[particle(mass = $mass, count = $len)]
            fn bob(i: usize) -> Vec2 {
                vec2(theta[i].sin(), -theta[i].cos())
            }
            #[gravity]
            fn down() -> $down {
                vec2(0.0, -g)
            }
        }
    };
}

chain!(chain2, Chain2, 2);
chain!(chain5, Chain5, 5);
pendulum_of!(pendulums, 1 + 2, 1.5, Vec2);

fn main() {
    let s = chain5::State::at_rest(chain5::Coords { theta: [0.1; 5] });
    let sys = chain5::Chain5 { m: 1.0, l: 1.0, g: 9.81 };
    assert_eq!(chain5::DOF, 5);
    assert!(sys.accelerations(&s).unwrap().theta.iter().all(|a| a.is_finite()));
    assert_eq!(chain2::DOF, 2);
    let p = pendulums::P { m: 1.0, g: 9.81 };
    let s = pendulums::State::at_rest(pendulums::Coords { theta: [0.2, 0.3, 0.4] });
    assert!(p.accelerations(&s).is_ok());
}
