//! Arrays of parameters and families whose masses, inertias and centres of mass name their index:
//! a spatial arm written as one family of links read from a table (`mass = m[i]`, `com = vec3(..,
//! c[i])`, `inertia = [[ixx[i], ..], ..]`, joint offsets `d[i]`) takes the rigid tree pass and
//! equals the same arm written link by link with one scalar parameter per entry; a planar chain of
//! point masses of different masses and lengths equals its body-by-body declaration too. Each
//! element of an array is checked by `validate`, named in errors and sensitivities by its index.
//!
//! Tolerances: the family and the body-by-body declaration evaluate the same formulas in the same
//! order, so they agree to a few rounding errors (1e-12 relative leaves a margin of ~10³ over the
//! ~1e-15 seen); against the dense pass, see `common/tree_vs_dense.rs`.

use lagrange::prelude::*;
use lagrange::tree::rigid::RigidTree;

#[path = "common/tree_vs_dense.rs"]
mod tree_vs_dense;
use tree_vs_dense::{agrees_with_dense, states};

/// Three links, each a row of a robot's table: the joint 's offset along the parent's z, a roll
/// before the joint, the joint about its own z, the centre of mass and the inertia tensor in the
/// link's frame.
#[mechanism]
pub mod table_arm {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub q: [f64; LINKS],
    }

    pub struct TableArm {
        pub m: [f64; LINKS],
        pub d: [f64; LINKS],
        pub roll: [f64; LINKS],
        pub c: [f64; LINKS],
        pub ixx: [f64; LINKS],
        pub ixy: [f64; LINKS],
        pub izz: [f64; LINKS],
        pub g: f64,
    }

    #[rigid_body(mass = m[i], count = LINKS, com = vec3(0.02, -0.01, c[i]),
                 inertia = [[ixx[i], ixy[i], 0.0], [ixy[i], 1.3 * ixx[i], 0.0], [0.0, 0.0, izz[i]]])]
    fn link(i: usize) -> Spatial {
        if i == 0 {
            spatial(vec3(0.0, 0.0, d[0]), rot_z(q[0]))
        } else {
            link[i - 1].joint(vec3(0.0, 0.0, d[i]), rpy(roll[i], 0.0, 0.0) * rot_z(q[i]))
        }
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

/// The same arm, link by link, one scalar parameter per entry of the table.
#[mechanism]
pub mod written_out {
    pub struct Coords {
        pub q0: f64,
        pub q1: f64,
        pub q2: f64,
    }

    pub struct WrittenOut {
        pub m0: f64,
        pub m1: f64,
        pub m2: f64,
        pub d0: f64,
        pub d1: f64,
        pub d2: f64,
        pub roll1: f64,
        pub roll2: f64,
        pub c0: f64,
        pub c1: f64,
        pub c2: f64,
        pub ixx0: f64,
        pub ixx1: f64,
        pub ixx2: f64,
        pub ixy0: f64,
        pub ixy1: f64,
        pub ixy2: f64,
        pub izz0: f64,
        pub izz1: f64,
        pub izz2: f64,
        pub g: f64,
    }

    #[rigid_body(mass = m0, com = vec3(0.02, -0.01, c0),
                 inertia = [[ixx0, ixy0, 0.0], [ixy0, 1.3 * ixx0, 0.0], [0.0, 0.0, izz0]])]
    fn link0() -> Spatial {
        spatial(vec3(0.0, 0.0, d0), rot_z(q0))
    }

    #[rigid_body(mass = m1, com = vec3(0.02, -0.01, c1),
                 inertia = [[ixx1, ixy1, 0.0], [ixy1, 1.3 * ixx1, 0.0], [0.0, 0.0, izz1]])]
    fn link1() -> Spatial {
        link0.joint(vec3(0.0, 0.0, d1), rpy(roll1, 0.0, 0.0) * rot_z(q1))
    }

    #[rigid_body(mass = m2, com = vec3(0.02, -0.01, c2),
                 inertia = [[ixx2, ixy2, 0.0], [ixy2, 1.3 * ixx2, 0.0], [0.0, 0.0, izz2]])]
    fn link2() -> Spatial {
        link1.joint(vec3(0.0, 0.0, d2), rpy(roll2, 0.0, 0.0) * rot_z(q2))
    }

    #[gravity]
    fn down() -> Vec3 {
        vec3(0.0, 0.0, -g)
    }
}

fn table() -> table_arm::TableArm {
    table_arm::TableArm {
        m: [3.0, 2.2, 1.1],
        d: [0.1, 0.33, 0.29],
        roll: [0.0, -1.2, 0.9],
        c: [0.12, 0.15, 0.08],
        ixx: [0.02, 0.015, 0.006],
        ixy: [0.001, -0.002, 0.0005],
        izz: [0.01, 0.008, 0.004],
        g: 9.81,
    }
}

fn written_out() -> written_out::WrittenOut {
    let t = table();
    written_out::WrittenOut {
        m0: t.m[0],
        m1: t.m[1],
        m2: t.m[2],
        d0: t.d[0],
        d1: t.d[1],
        d2: t.d[2],
        roll1: t.roll[1],
        roll2: t.roll[2],
        c0: t.c[0],
        c1: t.c[1],
        c2: t.c[2],
        ixx0: t.ixx[0],
        ixx1: t.ixx[1],
        ixx2: t.ixx[2],
        ixy0: t.ixy[0],
        ixy1: t.ixy[1],
        ixy2: t.ixy[2],
        izz0: t.izz[0],
        izz1: t.izz[1],
        izz2: t.izz[2],
        g: t.g,
    }
}

fn assert_close(a: &[f64], b: &[f64], what: &str) {
    let scale = b.iter().fold(1.0f64, |s, x| s.max(x.abs()));
    for (x, y) in a.iter().zip(b) {
        assert!(
            (x - y).abs() <= 1e-12 * scale,
            "{what}: {a:?} against {b:?}"
        );
    }
}

#[test]
fn an_arm_read_from_a_table_takes_the_tree_pass_and_equals_the_arm_written_link_by_link() {
    // The generated impl is the proof the recursion is taken: three links.
    assert_eq!(<table_arm::TableArm as RigidTree<3, 3>>::JOINTS.len(), 3);
    let family = table().validated().unwrap();
    let written = written_out().validated().unwrap();
    for (q, v) in states::<3>(6) {
        let s = table_arm::State::new(0.0, table_arm::Coords { q }, table_arm::Coords { q: v });
        let [q0, q1, q2] = q;
        let [v0, v1, v2] = v;
        let w = written_out::State::new(
            0.0,
            written_out::Coords { q0, q1, q2 },
            written_out::Coords {
                q0: v0,
                q1: v1,
                q2: v2,
            },
        );
        let (a, b) = (
            family.accelerations(&s).unwrap(),
            written.accelerations(&w).unwrap(),
        );
        assert_close(&a.q, &[b.q0, b.q1, b.q2], "q̈");
        let (ma, mb) = (
            family.mass_matrix(&s).unwrap(),
            written.mass_matrix(&w).unwrap(),
        );
        assert_close(ma.as_slice(), mb.as_slice(), "M");
        let (ea, eb) = (family.energy(&s).unwrap(), written.energy(&w).unwrap());
        assert_close(&[ea], &[eb], "E");
    }
    // And the family's tree pass against its own dense pass.
    agrees_with_dense::<_, _, 3, 36>(&table(), &family);
}

/// A planar chain of point masses, each link with its own mass and length.
#[mechanism]
pub mod uneven_chain {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct UnevenChain {
        pub m: [f64; LINKS],
        pub l: [f64; LINKS],
        pub g: f64,
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

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod uneven_written_out {
    pub struct Coords {
        pub a: f64,
        pub b: f64,
        pub c: f64,
    }

    pub struct UnevenWrittenOut {
        pub m0: f64,
        pub m1: f64,
        pub m2: f64,
        pub l0: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }

    #[particle(mass = m0)]
    fn bob0() -> Vec2 {
        vec2(a.sin(), -a.cos()) * l0
    }

    #[particle(mass = m1)]
    fn bob1() -> Vec2 {
        bob0 + vec2(b.sin(), -b.cos()) * l1
    }

    #[particle(mass = m2)]
    fn bob2() -> Vec2 {
        bob1 + vec2(c.sin(), -c.cos()) * l2
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn a_chain_of_uneven_links_equals_its_body_by_body_declaration() {
    let family = uneven_chain::UnevenChain {
        m: [1.0, 2.5, 0.7],
        l: [0.9, 0.4, 1.3],
        g: 9.81,
    };
    let written = uneven_written_out::UnevenWrittenOut {
        m0: 1.0,
        m1: 2.5,
        m2: 0.7,
        l0: 0.9,
        l1: 0.4,
        l2: 1.3,
        g: 9.81,
    };
    for (q, v) in states::<3>(6) {
        let s = uneven_chain::State::new(
            0.0,
            uneven_chain::Coords { theta: q },
            uneven_chain::Coords { theta: v },
        );
        let [a, b, c] = q;
        let w = uneven_written_out::State::new(
            0.0,
            uneven_written_out::Coords { a, b, c },
            uneven_written_out::Coords {
                a: v[0],
                b: v[1],
                c: v[2],
            },
        );
        let (x, y) = (
            family.accelerations(&s).unwrap(),
            written.accelerations(&w).unwrap(),
        );
        assert_close(&x.theta, &[y.a, y.b, y.c], "q̈");
        let (ma, mb) = (
            family.mass_matrix(&s).unwrap(),
            written.mass_matrix(&w).unwrap(),
        );
        assert_close(ma.as_slice(), mb.as_slice(), "M");
    }
}

#[test]
fn validate_names_the_element_and_the_member_at_fault() {
    let mut sys = table();
    sys.d[1] = f64::NAN;
    match sys.validate() {
        Err(Error::NonFiniteParameter { name, .. }) => assert_eq!(name, "d[1]"),
        other => panic!("expected NonFiniteParameter for d[1], got {other:?}"),
    }
    let mut sys = table();
    sys.m[2] = -1.0;
    match sys.validate() {
        Err(Error::InvalidInertia { body, .. }) => assert_eq!(body, "link[2]"),
        other => panic!("expected InvalidInertia for link[2], got {other:?}"),
    }
    // The inertia tensor of member 1 only: not positive definite.
    let mut sys = table();
    sys.izz[1] = -0.1;
    match sys.validate() {
        Err(Error::InvalidInertia { body, .. }) => assert_eq!(body, "link[1]"),
        other => panic!("expected InvalidInertia for link[1], got {other:?}"),
    }
    assert!(table().validate().is_ok());
}

#[test]
fn an_array_of_parameters_is_flat_in_the_declaration_and_the_sensitivities() {
    use lagrange::declaration::Declaration;
    use lagrange::parameters::Parametrized;
    let names = <uneven_chain::UnevenChain as Declaration>::PARAMETERS;
    assert_eq!(names, ["m[0]", "m[1]", "m[2]", "l[0]", "l[1]", "l[2]", "g"]);
    let values = [1.0, 2.5, 0.7, 0.9, 0.4, 1.3, 9.81];
    let sys = uneven_chain::UnevenChain::from_parameters(&values).unwrap();
    assert_eq!(sys.m, [1.0, 2.5, 0.7]);
    assert_eq!(sys.l, [0.9, 0.4, 1.3]);
    assert_eq!(Declaration::parameters(&sys), values);
    assert_eq!(
        <uneven_chain::UnevenChain as Parametrized<3, 6, 7>>::PARAMETER_NAMES,
        names
    );
    assert_eq!(Parametrized::<3, 6, 7>::parameters(&sys), values);
    // The lengths enter the positions only: each can carry a derivative; the masses cannot.
    let seedable = <uneven_chain::UnevenChain as Parametrized<3, 6, 7>>::SEEDABLE;
    assert_eq!(seedable, [false, false, false, true, true, true, false]);
}

#[test]
fn a_sensitivity_is_seeded_on_one_element_of_an_array() -> Result<(), Error> {
    use lagrange::integrate::Stepper;
    use lagrange::sensitivity::Seed;
    use uneven_chain::{Coords, State, UnevenChain};
    let sys = |l1: f64| UnevenChain {
        m: [1.0, 2.5, 0.7],
        l: [0.9, l1, 1.3],
        g: 9.81,
    };
    let s0 = State::new(
        0.0,
        Coords {
            theta: [0.4, -0.3, 0.9],
        },
        Coords { theta: [0.0; 3] },
    );
    let (h, steps) = (1e-3, 500);
    let nominal = sys(0.4);
    let mut run = Stepper::new(&nominal, Rk4::with_step(h), &s0)?
        .with_sensitivities([Seed::Parameter("l[1]")])?;
    run.integrate(h * steps as f64, &mut [], |_| {})?;
    let by_l1 = run.sensitivities().dq[0].theta;
    let end = |l1: f64| -> Result<[f64; 3], Error> {
        let mut s = s0;
        for _ in 0..steps {
            sys(l1).step::<Rk4>(&mut s, h)?;
        }
        Ok(s.q.theta)
    };
    // Central differences: truncation O(δ²) ~ 1e-8 of a derivative of order one, rounding
    // ε/δ ~ 1e-12; 1e-6 leaves a margin for both while catching a wrong column.
    let delta = 1e-4;
    let (plus, minus) = (end(0.4 + delta)?, end(0.4 - delta)?);
    for k in 0..3 {
        let central = (plus[k] - minus[k]) / (2.0 * delta);
        assert!(
            (by_l1[k] - central).abs() < 1e-6,
            "∂θ{k}/∂l[1]: {} against {central}",
            by_l1[k]
        );
    }
    assert!(
        by_l1.iter().any(|x| x.abs() > 1e-2),
        "the seed moves the chain: {by_l1:?}"
    );
    // A mass element is not seedable, by name.
    let refused = Stepper::new(&nominal, Rk4::with_step(h), &s0)?
        .with_sensitivities([Seed::Parameter("m[0]")]);
    assert!(matches!(refused, Err(Error::UnseedableParameter { .. })));
    Ok(())
}

/// Planar bars of different lengths, each placed by its joint with its centre of mass and moment
/// of inertia by member.
#[mechanism]
pub mod uneven_bars {
    pub const BARS: usize = 3;

    pub struct Coords {
        pub phi: [f64; BARS],
    }

    pub struct UnevenBars {
        pub m: [f64; BARS],
        pub l: [f64; BARS],
        pub g: f64,
    }

    #[rigid_body(mass = m[i], count = BARS, com = vec2(0.5 * l[i], 0.0),
                 inertia = m[i] * l[i] * l[i] / 12.0)]
    fn bar(i: usize) -> Planar {
        if i == 0 {
            planar(vec2(0.0, 0.0), phi[0])
        } else {
            planar(
                bar[i - 1].point(vec2(l[i - 1], 0.0)),
                bar[i - 1].angle + phi[i],
            )
        }
    }

    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[test]
fn planar_bars_by_member_take_the_tree_pass_and_agree_with_the_dense_one() {
    assert_eq!(
        <uneven_bars::UnevenBars as RigidTree<3, 3>>::JOINTS.len(),
        3
    );
    let sys = || uneven_bars::UnevenBars {
        m: [1.0, 0.6, 2.0],
        l: [0.8, 0.5, 1.1],
        g: 9.81,
    };
    agrees_with_dense::<_, _, 3, 9>(&sys(), &sys());
    agrees_with_dense::<_, _, 3, 9>(&sys(), &sys().validated().unwrap());
    // Bar 1 without mass: its mass and its moment m l²/12 are zero.
    let mut bad = sys();
    bad.m[1] = 0.0;
    match bad.validate() {
        Err(Error::InvalidInertia { body, .. }) => assert_eq!(body, "bar[1]"),
        other => panic!("expected InvalidInertia for bar[1], got {other:?}"),
    }
}

/// A family whose masses follow from its index by arithmetic, without an array.
#[mechanism]
pub mod tapered {
    pub const LINKS: usize = 3;

    pub struct Coords {
        pub theta: [f64; LINKS],
    }

    pub struct Tapered {
        pub m: f64,
        pub l: f64,
        pub g: f64,
    }

    #[particle(mass = m * (3.0 - 0.3 * i as f64), count = LINKS)]
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

#[test]
fn a_family_s_masses_may_be_arithmetic_in_its_index() {
    use lagrange::model::Model;
    let sys = tapered::Tapered {
        m: 2.0,
        l: 1.0,
        g: 9.81,
    };
    let masses = Model::<3, 6>::masses(&sys);
    let expected = [6.0, 6.0, 5.4, 5.4, 4.8, 4.8];
    for (a, b) in masses.iter().zip(expected) {
        // 2 (3 − 0.3 i) in floating point: one rounding of 0.3 i and one of the product.
        assert!((a - b).abs() < 1e-14, "{masses:?}");
    }
}
