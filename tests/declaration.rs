use lagrange::prelude::*;

#[mechanism]
pub mod double_pendulum {
    /// Generalized coordinates: one field per degree of freedom.
    pub struct Coords {
        pub theta1: f64,
        pub theta2: f64,
    }

    /// Parameters, fixed for one simulation.
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        vec2(theta1.sin(), -theta1.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(theta2.sin(), -theta2.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn readme() -> Result<(), lagrange::Error> {
    use double_pendulum::{Coords, DoublePendulum, State};
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let mut s = State::at_rest(Coords {
        theta1: 1.0,
        theta2: 0.5,
    });
    let qdd = sys.accelerations(&s)?; // Coords { theta1: .., theta2: .. }
    let e0 = sys.energy(&s)?;
    for _ in 0..1000 {
        sys.step::<Rk4>(&mut s, 1e-3)?; // allocation-free; the state is unchanged on error
    }
    assert!((sys.energy(&s)? - e0).abs() < 1e-8);
    println!("q̈(0) = {qdd:?}, q(1) = {:?}", s.q);
    Ok(())
}
