//! The animation recorder without a browser: what a declaration states about its drawing (links,
//! constraint bodies), sampling to a frame rate, marks, the embedded data, and every refusal.
//! `tests/browser.rs` opens the pages in Chromium.

use lagrange::animation::{AnimationError, BodyRef, Drawable, Link, Recorder, Shape};
use lagrange::prelude::*;
use lagrange_gallery::scenes::double_pendulum::double_pendulum;

#[mechanism]
pub mod chain {
    pub const LINKS: usize = 4;
    pub struct Coords {
        pub theta: [f64; LINKS],
    }
    pub struct Chain {
        pub m: f64,
        pub l: f64,
        pub g: f64,
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
    /// Named after the family: every member drawn from this point.
    #[point]
    fn hub() -> Vec2 {
        bob[0] * 0.5
    }
    /// Keeps the last bob on a circle: a constraint naming one member.
    #[constraint]
    fn reach() -> f64 {
        bob[3].norm() - 3.0 * l
    }
    /// Names the family whole.
    #[constraint]
    fn centre() -> f64 {
        bob.iter().fold(hub.y, |sum, b| sum + b.x)
    }
    #[gravity]
    fn down() -> Vec2 {
        vec2(0.0, -g)
    }
}

#[mechanism]
pub mod top {
    pub struct Coords {
        pub phi: f64,
        pub theta: f64,
    }
    pub struct Top {
        pub m: f64,
        pub a: f64,
        pub c: f64,
    }
    #[rigid_body(mass = m, inertia = [a, a, c])]
    fn body() -> Spatial {
        spatial(vec3(0.0, 0.0, 1.0), rot_z(phi) * rot_x(theta))
    }
    #[rigid_body(mass = m, inertia = a)]
    fn disc() -> Planar {
        planar(vec2(phi, 0.0), theta)
    }
}

/// Two links declared by their joint frames: the centre of mass off each frame's origin, and the
/// first link's full tensor turning its principal axes away from the frame's.
#[mechanism]
pub mod framed {
    pub struct Coords {
        pub q1: f64,
        pub q2: f64,
    }
    pub struct Framed {
        pub m: f64,
        pub d: f64,
    }
    #[rigid_body(mass = m, com = vec3(0.0, 0.1, 0.3),
                 inertia = [[0.02, 0.004, 0.0], [0.004, 0.03, 0.001], [0.0, 0.001, 0.015]])]
    fn link1() -> Spatial {
        spatial(vec3(0.0, 0.0, 0.0), rot_z(q1))
    }
    #[rigid_body(mass = m, com = vec3(0.2, 0.0, 0.0), inertia = [0.01, 0.02, 0.02])]
    fn link2() -> Spatial {
        link1.joint(vec3(0.0, 0.0, d), rot_y(q2))
    }
}

fn pendulum() -> double_pendulum::DoublePendulum {
    double_pendulum::DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    }
}

fn start() -> double_pendulum::State {
    double_pendulum::State::at_rest(double_pendulum::Coords {
        theta1: 1.2,
        theta2: -0.4,
    })
}

fn body(body: usize, member: usize) -> BodyRef {
    BodyRef { body, member }
}

#[test]
fn links_are_the_bodies_a_position_names() {
    type P = double_pendulum::DoublePendulum;
    assert_eq!(<P as Drawable<2>>::BODIES.len(), 2);
    assert_eq!(<P as Drawable<2>>::BODIES[1].shape, Shape::Particle2);
    assert_eq!(
        <P as Drawable<2>>::LINKS,
        [Link {
            from: body(1, 0),
            to: body(0, 0)
        }]
    );
    // A family written `if i == 0 { link } else { bob[i - 1] + link }`: member k on member k − 1;
    // the point names member 0.
    type C = chain::Chain;
    let links: Vec<_> = <C as Drawable<4>>::LINKS
        .iter()
        .map(|l| (l.from.body, l.from.member, l.to.body, l.to.member))
        .collect();
    assert_eq!(
        links,
        [(0, 1, 0, 0), (0, 2, 0, 1), (0, 3, 0, 2), (1, 0, 0, 0)]
    );
    // Constraints: one member by its index; a family named whole counts with every member.
    let rows = <C as Drawable<4>>::CONSTRAINT_BODIES;
    assert_eq!(rows[0].name, "reach");
    assert_eq!(rows[0].bodies, [body(0, 3)]);
    assert_eq!(
        rows[1].bodies,
        [body(0, 0), body(0, 1), body(0, 2), body(0, 3), body(1, 0)]
    );
}

/// Frames are kept at the first state, then at the first state at or after each 1/rate;
/// `push_frame` keeps a state whatever its time.
#[test]
fn frames_are_kept_at_the_frame_rate() -> Result<(), Box<dyn std::error::Error>> {
    let sys = pendulum().validated()?;
    let mut s = start();
    let mut recorder = Recorder::new(&sys).frame_rate(10.0)?;
    recorder.push(&sys, &s)?;
    // 1.03 s in steps of 10 ms: frames at 0, 0.1, …, 1.0; the last state only when asked for.
    sys.simulate::<Rk4>(&mut s, 1e-2, 103, recorder.observer(&sys))?;
    let times = recorder.frame_times().to_vec();
    assert_eq!(times.len(), 11, "{times:?}");
    for (k, t) in times.iter().enumerate() {
        // A step of 10 ms lands on each multiple of 0.1 s, up to the round-off of adding 0.01.
        assert!((t - 0.1 * k as f64).abs() < 1e-12, "frame {k} at {t}");
    }
    recorder.push_frame(&sys, &s)?;
    recorder.push_frame(&sys, &s)?;
    assert_eq!(recorder.frames(), 12, "the last state, once");
    assert!((recorder.frame_times()[11] - 1.03).abs() < 1e-12);
    // Steps longer than a frame (an adaptive method's): one frame per step, none made up.
    let mut sparse = Recorder::new(&sys).frame_rate(10.0)?;
    for t in [0.0, 0.05, 0.35, 0.36, 0.9] {
        let state = double_pendulum::State { t, ..start() };
        sparse.push(&sys, &state)?;
    }
    assert_eq!(sparse.frame_times(), [0.0, 0.35, 0.9]);
    Ok(())
}

/// What a frame holds is what the generated `bodies` says, and a mark is the body's point.
#[test]
fn frames_hold_the_bodies_and_marks() -> Result<(), Box<dyn std::error::Error>> {
    let sys = pendulum();
    let mut s = start();
    let mut recorder = Recorder::new(&sys);
    recorder.push(&sys, &s)?;
    let mut states = vec![s];
    sys.simulate::<Rk4>(&mut s, 1e-3, 500, |s| states.push(*s))?;
    for state in &states {
        recorder.push(&sys, state)?;
    }
    for (k, &t) in recorder.frame_times().iter().enumerate() {
        let state = states
            .iter()
            .find(|s| s.t == t)
            .expect("a frame is a pushed state");
        let bodies = sys.bodies(state);
        assert_eq!(
            recorder.position("bob2", k),
            Some([bodies.bob2.x, bodies.bob2.y, 0.0])
        );
    }

    let top = top::Top {
        m: 1.0,
        a: 0.5,
        c: 0.8,
    };
    let state = top::State::new(
        0.0,
        top::Coords {
            phi: 0.3,
            theta: 0.7,
        },
        top::Coords {
            phi: 0.0,
            theta: 0.0,
        },
    );
    let mut recorder = Recorder::new(&top);
    recorder
        .mark("tip", "body", &[0.1, 0.2, 0.5])?
        .mark("edge", "disc", &[0.4, -0.1])?;
    recorder.push(&top, &state)?;
    let bodies = top.bodies(&state);
    let tip = bodies.body.point(vec3(0.1, 0.2, 0.5));
    let edge = bodies.disc.point(vec2(0.4, -0.1));
    // R o summed in a different order from `point`: a few ulps.
    let close = |a: [f64; 3], b: [f64; 3]| (0..3).all(|i| (a[i] - b[i]).abs() < 1e-15);
    assert!(close(
        recorder.position("tip", 0).unwrap(),
        [tip.x, tip.y, tip.z]
    ));
    assert!(close(
        recorder.position("edge", 0).unwrap(),
        [edge.x, edge.y, 0.0]
    ));
    Ok(())
}

/// A body declared by its frame is drawn at that frame — its origin, and its axes (a point marked
/// on it turns with the frame, not with the principal axes x holds) — as `Bodies` gives it.
#[test]
fn a_body_declared_by_its_frame_is_drawn_at_its_frame() -> Result<(), Box<dyn std::error::Error>> {
    let sys = framed::Framed { m: 1.0, d: 0.5 };
    let state = framed::State::at_rest(framed::Coords { q1: 0.4, q2: -0.9 });
    let mut recorder = Recorder::new(&sys);
    recorder
        .mark("link1 x", "link1", &[1.0, 0.0, 0.0])?
        .mark("link1 com", "link1", &[0.0, 0.1, 0.3])?
        .mark("link2 z", "link2", &[0.0, 0.0, 1.0])?;
    recorder.push(&sys, &state)?;
    let bodies = sys.bodies(&state);
    let xyz = |p: Vec3<f64>| [p.x, p.y, p.z];
    // The same position function evaluated twice: equal to the bit.
    assert_eq!(
        recorder.position("link1", 0),
        Some(xyz(bodies.link1.position))
    );
    assert_eq!(
        recorder.position("link2", 0),
        Some(xyz(bodies.link2.position))
    );
    // Drawn at the joint, not at the centre of mass the Cartesian model holds.
    let x = <framed::Framed as lagrange::model::Model<2, 24>>::cartesian(&sys, 0.0, &[0.4, -0.9]);
    assert_ne!(recorder.position("link2", 0), Some([x[12], x[13], x[14]]));
    // R o summed in a different order from `point`: a few ulps of numbers of order 1.
    let close = |a: [f64; 3], b: [f64; 3]| (0..3).all(|i| (a[i] - b[i]).abs() < 1e-15);
    for (mark, body, offset) in [
        ("link1 x", bodies.link1, vec3(1.0, 0.0, 0.0)),
        ("link1 com", bodies.link1, vec3(0.0, 0.1, 0.3)),
        ("link2 z", bodies.link2, vec3(0.0, 0.0, 1.0)),
    ] {
        let drawn = recorder.position(mark, 0).unwrap();
        assert!(close(drawn, xyz(body.point(offset))), "{mark}: {drawn:?}");
    }
    // The link the declaration states: link2 is written from link1.
    assert_eq!(
        <framed::Framed as Drawable<2>>::LINKS,
        &[Link {
            from: body(1, 0),
            to: body(0, 0)
        }]
    );
    Ok(())
}

/// The page is one document: the player, and the recording as JSON with every frame.
#[test]
fn the_page_embeds_the_player_and_the_recording() -> Result<(), Box<dyn std::error::Error>> {
    let sys = pendulum();
    let mut s = start();
    let mut recorder = Recorder::new(&sys).title("a <double> pendulum & more");
    recorder
        .fixed_point("pivot", &[0.0, 0.0])?
        .link("pivot", "bob1")?
        .trail("bob2")?;
    recorder.push(&sys, &s)?;
    sys.simulate::<Rk4>(&mut s, 1e-3, 1000, recorder.observer(&sys))?;
    let html = recorder.html()?;
    assert!(html.contains("<title>a &lt;double&gt; pendulum &amp; more</title>"));
    assert!(html.contains("class Player"), "the player is in the page");
    assert!(!html.contains("http://") && !html.contains("https://") && !html.contains("src="));
    let start_tag = "<script id=\"lagrange-data\" type=\"application/json\">";
    let data = &html[html.find(start_tag).unwrap() + start_tag.len()..];
    let data = &data[..data.find("</script>").unwrap()];
    assert!(!data.contains('<'));
    let scene: serde_json::Value = serde_json::from_str(data)?;
    assert_eq!(scene["title"], "a <double> pendulum & more");
    assert_eq!(scene["dim"], 2);
    let frames = recorder.frames();
    assert_eq!(scene["times"].as_array().unwrap().len(), frames);
    assert_eq!(scene["stride"], 4);
    assert_eq!(scene["frames"].as_array().unwrap().len(), 4 * frames);
    let names: Vec<&str> = scene["items"]
        .as_array()
        .unwrap()
        .iter()
        .map(|i| i["name"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["bob1", "bob2", "pivot"]);
    assert_eq!(scene["links"], serde_json::json!([[1, 0], [2, 0]]));
    assert_eq!(scene["trails"], serde_json::json!([1]));
    // The box holds both bobs over the run: bob2 reaches below y = −1.
    assert!(scene["extent"][0][1].as_f64().unwrap() < -1.0);

    let path = std::env::temp_dir().join("lagrange-animation-test.html");
    recorder.write_html(&path)?;
    assert_eq!(std::fs::read_to_string(&path)?, html);
    Ok(())
}

#[test]
fn bad_input_is_refused_and_the_recorder_kept() -> Result<(), Box<dyn std::error::Error>> {
    let sys = pendulum();
    let mut recorder = Recorder::new(&sys);
    let unknown = recorder.trail("bob3").err().unwrap();
    assert!(matches!(&unknown, AnimationError::UnknownName { known, .. } if known == "bob1, bob2"));
    assert!(matches!(
        recorder.mark("m", "bob1", &[0.1]),
        Err(AnimationError::InvalidCoordinates { .. })
    ));
    assert!(matches!(
        recorder.fixed_point("bob1", &[0.0, 0.0]),
        Err(AnimationError::DuplicateName { .. })
    ));
    assert!(matches!(
        recorder.fixed_point("p", &[0.0, f64::NAN]),
        Err(AnimationError::InvalidCoordinates { .. })
    ));
    recorder.fixed_point("pivot", &[0.0, 0.0])?;
    assert!(matches!(
        recorder.mark("m", "pivot", &[0.0, 0.0]),
        Err(AnimationError::NotABody { .. })
    ));
    for rate in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            Recorder::new(&sys).frame_rate(rate),
            Err(AnimationError::InvalidSetting { .. })
        ));
    }
    assert!(matches!(recorder.html(), Err(AnimationError::Empty)));

    recorder.push(&sys, &start())?;
    let page = recorder.html()?;
    let mut bad = start();
    bad.q.theta2 = f64::NAN;
    assert!(matches!(
        recorder.push(&sys, &bad),
        Err(AnimationError::State(Error::NonFiniteState { .. }))
    ));
    let earlier = double_pendulum::State { t: -1.0, ..start() };
    assert!(matches!(
        recorder.push(&sys, &earlier),
        Err(AnimationError::TimeGoesBack { .. })
    ));
    assert!(matches!(
        recorder.mark("m", "bob1", &[0.0, 0.0]),
        Err(AnimationError::AlreadyRecording)
    ));
    assert_eq!(
        recorder.html()?,
        page,
        "refusals leave the recording as it was"
    );

    // The observer keeps the first refusal for the page.
    let mut observed = Recorder::new(&sys);
    {
        let mut observe = observed.observer(&sys);
        observe(&start());
        observe(&bad);
    }
    assert!(matches!(observed.html(), Err(AnimationError::State(_))));
    let missing = std::env::temp_dir().join("no-such-dir").join("page.html");
    let mut fine = Recorder::new(&sys);
    fine.push(&sys, &start())?;
    assert!(matches!(
        fine.write_html(missing),
        Err(AnimationError::Io { .. })
    ));
    Ok(())
}
