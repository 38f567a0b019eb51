use lagrange::mechanism;

#[mechanism]
pub mod double_pendulum {
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
    }

    #[particle]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l3
    }
}

// The rest of the program still type-checks against the stubs: no cascade of errors.
fn main() {
    use lagrange::prelude::*;
    use double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum { m1: 1.0, m2: 1.0, l1: 1.0, l2: 1.0 };
    let s = State::at_rest(Coords { theta1: 1.0, theta2: 0.5 });
    let _ = sys.accelerations(&s);
    let _ = sys.bodies(&s).bob2.x;
}
