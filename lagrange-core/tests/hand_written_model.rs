//! A [`Model`] written by hand (what `#[mechanism]` generates for a double pendulum), checked against
//! the closed-form equations of motion. This pins the runtime down independently of the macro.

use lagrange_core::evaluation::Evaluate as _;
use lagrange_core::{vec2, Error, Mechanism, Model, Rk4, Scalar, State};

struct DoublePendulum {
    m1: f64,
    m2: f64,
    l1: f64,
    l2: f64,
    g: f64,
}

impl Model<2, 4> for DoublePendulum {
    type Coords = [f64; 2];
    const RHEONOMIC: bool = false;
    const HAS_POTENTIAL: bool = true;
    const HAS_FORCES: bool = false;

    fn validate(&self) -> lagrange_core::Result<()> {
        for (name, value) in [
            ("m1", self.m1),
            ("m2", self.m2),
            ("l1", self.l1),
            ("l2", self.l2),
            ("g", self.g),
        ] {
            if !value.is_finite() {
                return Err(Error::NonFiniteParameter { name, value });
            }
        }
        Ok(())
    }
    fn masses(&self) -> [f64; 4] {
        [self.m1, self.m1, self.m2, self.m2]
    }
    fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 2]) -> [D; 4] {
        let (l1, l2) = (D::from(self.l1), D::from(self.l2));
        let bob1 = vec2(q[0].sin(), -q[0].cos()) * l1;
        let bob2 = bob1 + vec2(q[1].sin(), -q[1].cos()) * l2;
        [bob1.x, bob1.y, bob2.x, bob2.y]
    }
    fn potential<D: Scalar>(&self, _t: D, _q: &[D; 2], x: &[D; 4]) -> D {
        (x[1] * self.m1 + x[3] * self.m2) * self.g
    }
}

lagrange_core::impl_mechanism!(DoublePendulum, 2, 4);

/// Closed form (e.g. Goldstein §1.4 style derivation; as written in myphysicslab's double pendulum).
fn closed_form(p: &DoublePendulum, q: [f64; 2], v: [f64; 2]) -> [f64; 2] {
    let DoublePendulum { m1, m2, l1, l2, g } = *p;
    let d = q[0] - q[1];
    let den = m1 + m2 * d.sin().powi(2);
    let a1 = (m2 * g * q[1].sin() * d.cos()
        - m2 * d.sin() * (l1 * v[0] * v[0] * d.cos() + l2 * v[1] * v[1])
        - (m1 + m2) * g * q[0].sin())
        / (l1 * den);
    let a2 = ((m1 + m2) * (l1 * v[0] * v[0] * d.sin() - g * q[1].sin() + g * q[0].sin() * d.cos())
        + m2 * l2 * v[1] * v[1] * d.sin() * d.cos())
        / (l2 * den);
    [a1, a2]
}

const P: DoublePendulum = DoublePendulum {
    m1: 1.3,
    m2: 0.7,
    l1: 1.1,
    l2: 0.9,
    g: 9.81,
};

#[test]
fn accelerations_match_closed_form() {
    for (q, v) in [
        ([0.3, -1.2], [0.5, 2.0]),
        ([2.9, 0.1], [-3.0, 0.2]),
        ([0.0, 0.0], [0.0, 0.0]),
    ] {
        let got = P.accelerations_at(0.0, &q, &v).unwrap();
        let want = closed_form(&P, q, v);
        for k in 0..2 {
            // Both are a handful of flops from the same inputs: agreement to a few ulps of the scale.
            assert!(
                (got[k] - want[k]).abs() <= 1e-12 * (1.0 + want[k].abs()),
                "{got:?} vs {want:?}"
            );
        }
    }
}

#[test]
fn momenta_and_energy_are_consistent_with_mass_matrix() {
    let (q, v): ([f64; 2], [f64; 2]) = ([0.4, -0.8], [1.5, -0.3]);
    let m = P.equations_of_motion_at(0.0, &q, &v).mass_matrix;
    let v_vec = nalgebra::Vector2::from(v);
    let t = P.kinetic_energy_at(0.0, &q, &v);
    assert!((0.5 * v_vec.dot(&(m * v_vec)) - t).abs() < 1e-14);
    let p = P.momenta_at(0.0, &q, &v);
    let mv = m * v_vec;
    assert!((p[0] - mv[0]).abs() < 1e-14 && (p[1] - mv[1]).abs() < 1e-14);
}

#[test]
fn rk4_conserves_energy_to_its_order() {
    let mut s = State::new(0.0, [1.0, -0.5], [0.0, 0.0]);
    let e0 = P.energy(&s).unwrap();
    let mut worst = 0.0f64;
    for _ in 0..2000 {
        P.step::<Rk4>(&mut s, 1e-3).unwrap();
        worst = worst.max((P.energy(&s).unwrap() - e0).abs());
    }
    // RK4 with h = 1e-3 on a problem with frequencies ~3/s: local error ~ (hω)⁵ ≈ 2e-13 per step,
    // 2000 steps ≲ 1e-9 relative to |E| ~ 10.
    assert!(worst < 1e-8 * e0.abs().max(1.0), "energy error {worst}");
}

#[test]
fn bad_input_is_an_error_and_leaves_state_alone() {
    let mut s = State::new(0.0, [f64::NAN, 0.0], [0.0, 0.0]);
    let before = s;
    assert!(matches!(
        P.step::<Rk4>(&mut s, 1e-3),
        Err(Error::NonFiniteState { .. })
    ));
    assert_eq!(format!("{before:?}"), format!("{s:?}"));
    let mut s = State::at_rest([0.1, 0.2]);
    for h in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            P.step::<Rk4>(&mut s, h),
            Err(Error::InvalidStep { .. })
        ));
    }
    assert_eq!(s, State::at_rest([0.1, 0.2]));
    let bad = DoublePendulum {
        g: f64::INFINITY,
        ..P
    };
    assert!(matches!(
        bad.accelerations(&s),
        Err(Error::NonFiniteParameter { name: "g", .. })
    ));
    // Zero lengths make the mass matrix singular: an error naming the configuration, not NaN.
    let degenerate = DoublePendulum {
        l1: 0.0,
        l2: 0.0,
        ..P
    };
    let err = degenerate.accelerations(&s).unwrap_err();
    assert!(matches!(err, Error::SingularMassMatrix { .. }), "{err}");
    assert!(err.to_string().contains("q0 = 0.1"), "{err}");
}
