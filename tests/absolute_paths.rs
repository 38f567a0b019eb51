//! Generated code names only absolute paths: a declaration in a module that shadows the prelude's
//! `Result`, `Ok`, `Err`, `Option`, `Some`, `None`, `Vec` and `Box` still compiles and runs.

#![allow(dead_code, non_camel_case_types)]

use lagrange::prelude::{Mechanism, Rk4};

pub mod shadowed {
    use lagrange::mechanism;

    #[mechanism]
    pub mod pendulum {
        pub struct Result;
        pub struct Option;
        pub struct Vec;
        pub struct Box;
        pub struct Ok;
        pub struct Err;
        pub struct Some;
        pub struct None;

        pub struct Coords {
            pub theta: f64,
        }

        pub struct Pendulum {
            pub m: f64,
            pub l: f64,
            pub g: f64,
            pub c: f64,
        }

        #[particle(mass = m)]
        fn bob() -> Vec2 {
            vec2(theta.sin(), -theta.cos()) * l
        }

        #[gravity]
        fn down() -> Vec2 {
            vec2(0.0, -g)
        }

        #[force(on = bob)]
        fn drag() -> Vec2 {
            bob_dot * (-c)
        }
    }
}

#[test]
fn shadowed_prelude_names_do_not_break_generated_code() {
    use shadowed::pendulum::{Coords, Pendulum, State};
    let p = Pendulum {
        m: 1.0,
        l: 1.0,
        g: 9.81,
        c: 0.1,
    };
    let mut s = State::at_rest(Coords { theta: 0.5 });
    p.step::<Rk4>(&mut s, 1e-2).unwrap();
    assert!(s.q.theta < 0.5);
}
