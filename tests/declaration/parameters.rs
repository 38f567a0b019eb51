//! Invalid parameters give a clear error naming the parameter or the body.

use super::positions::double_pendulum;
use super::rigid_bodies::{free_body, physical_pendulum};
use lagrange::prelude::*;

#[test]
fn parameters_are_validated() {
    use lagrange::Error;
    let s = double_pendulum::State::at_rest(double_pendulum::Coords {
        theta1: 0.1,
        theta2: 0.2,
    });
    let good = double_pendulum::DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let nan_g = double_pendulum::DoublePendulum {
        g: f64::NAN,
        ..good
    };
    assert!(matches!(
        nan_g.accelerations(&s),
        Err(Error::NonFiniteParameter { name: "g", .. })
    ));
    let negative_mass = double_pendulum::DoublePendulum { m2: -1.0, ..good };
    assert!(matches!(
        negative_mass.energy(&s),
        Err(Error::InvalidInertia { body: "bob2", .. })
    ));

    let s = physical_pendulum::State::at_rest(physical_pendulum::Coords { theta: 0.1 });
    let flat = physical_pendulum::PhysicalPendulum {
        m: 1.0,
        i: 0.0,
        d: 0.5,
        g: 9.81,
        tau: 0.0,
    };
    assert!(matches!(
        flat.accelerations(&s),
        Err(Error::InvalidInertia { body: "bar", .. })
    ));

    let s = free_body::State::at_rest(free_body::Coords::default());
    let impossible = free_body::FreeBody {
        m: 1.0,
        i1: 1.0,
        i2: 1.0,
        i3: 3.0,
    };
    let err = impossible.accelerations(&s).unwrap_err();
    assert!(
        matches!(&err, Error::InvalidInertia { body: "body", reason } if reason.contains("triangle")),
        "{err}"
    );
    // A flat plate (I₃ = I₁ + I₂) is allowed.
    let plate = free_body::FreeBody {
        m: 1.0,
        i1: 1.0,
        i2: 2.0,
        i3: 3.0,
    };
    assert!(plate.energy(&s).is_ok());
}
