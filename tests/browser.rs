//! The animations in a real browser. Headless Chromium opens the pages the recorder and the
//! gallery write, with the network closed, and reads back what they drew through the probe every
//! page carries (`?probe=<JSON>` in the address: the page writes its answer into the document,
//! which `--dump-dom` prints): that frame 0 is not blank and the last frame differs from it, where
//! a chosen body is drawn at a chosen time, the pixel there, and every resource the page loaded.
//!
//! Chromium is found as `$CHROMIUM`, or `chromium`, `chromium-browser` or `google-chrome` on the
//! `PATH`. Without it the tests print why they do nothing and pass — except under `CI=true`,
//! where they fail (`.ci/run` installs Debian's `chromium`). The screenshot of the gallery's page
//! is kept at `target/tmp/browser/gallery.png`.

use lagrange::animation::{Drawable, Recorder};
use lagrange::prelude::*;
use lagrange_gallery::page::{run_scene, write_index};
use lagrange_gallery::scenes::double_pendulum::double_pendulum::{self, DoublePendulum};
use lagrange_gallery::scenes::rolling_wheel::rolling_wheel::{self, RollingWheel};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Duration;
use wait_timeout::ChildExt;

/// Headless Chromium with a fresh profile and every network path closed.
struct Chromium {
    program: PathBuf,
    profile: PathBuf,
}

/// The browser, or `None` (with the reason printed) when there is none outside CI.
fn chromium(name: &str) -> Option<Chromium> {
    let program = std::env::var_os("CHROMIUM").map(PathBuf::from).or_else(|| {
        ["chromium", "chromium-browser", "google-chrome"]
            .iter()
            .find_map(|name| {
                let paths = std::env::var_os("PATH")?;
                std::env::split_paths(&paths)
                    .map(|dir| dir.join(name))
                    .find(|p| p.is_file())
            })
    });
    let Some(program) = program else {
        assert!(
            std::env::var("CI").as_deref() != Ok("true"),
            "CI=true: the browser tests need Chromium (apt-get install chromium)"
        );
        eprintln!("skipped: no Chromium ($CHROMIUM, or chromium on the PATH); not CI");
        return None;
    };
    let profile = out_dir().join(format!("profile-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&profile);
    std::fs::create_dir_all(&profile).unwrap();
    Some(Chromium { program, profile })
}

/// `target/tmp/browser`: the pages, profiles and screenshot of these tests.
fn out_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("browser");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

impl Chromium {
    /// Runs Chromium on `url` with `extra` flags and returns what it printed. Virtual time runs
    /// the page's scripts for 5 s without waiting for them in real time.
    fn run(&self, extra: &[String], url: &str) -> String {
        let mut args = vec![
            "--headless".to_string(),
            "--no-sandbox".into(),
            "--disable-gpu".into(),
            "--disable-quic".into(),
            "--no-first-run".into(),
            "--disable-background-networking".into(),
            "--disable-component-update".into(),
            "--disable-sync".into(),
            format!("--user-data-dir={}", self.profile.display()),
            // The network closed: no name resolves and every proxied request goes nowhere.
            "--host-resolver-rules=MAP * ~NOTFOUND".into(),
            "--proxy-server=http://127.0.0.1:9".into(),
            "--virtual-time-budget=5000".into(),
        ];
        args.extend_from_slice(extra);
        args.push(url.to_string());
        let mut child = Command::new(&self.program)
            .args(&args)
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("Chromium starts");
        let mut stdout = child.stdout.take().unwrap();
        let reader = std::thread::spawn(move || {
            let mut out = String::new();
            std::io::Read::read_to_string(&mut stdout, &mut out).map(|_| out)
        });
        if child
            .wait_timeout(Duration::from_secs(180))
            .unwrap()
            .is_none()
        {
            let _ = child.kill();
            panic!("Chromium did not finish {url} in 180 s");
        }
        reader.join().unwrap().expect("Chromium's output is text")
    }

    /// The page at `file` with `?probe=<request>`: what its probe wrote into the document.
    fn probe(&self, file: &Path, request: &Value) -> Value {
        let url = format!("{}?probe={}", file_url(file), encode(&request.to_string()));
        let dom = self.run(&["--dump-dom".into()], &url);
        let start = dom
            .find("<pre id=\"lagrange-probe\"")
            .unwrap_or_else(|| panic!("no probe in the page:\n{dom}"));
        let text = &dom[start..];
        let text = &text[text.find('>').unwrap() + 1..text.find("</pre>").unwrap()];
        let text = text
            .replace("&lt;", "<")
            .replace("&gt;", ">")
            .replace("&amp;", "&");
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("probe `{text}`: {e}"))
    }

    fn screenshot(&self, file: &Path, png: &Path) {
        self.run(
            &[
                format!("--screenshot={}", png.display()),
                "--window-size=1280,1800".into(),
                "--hide-scrollbars".into(),
            ],
            &file_url(file),
        );
    }
}

impl Drop for Chromium {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.profile);
    }
}

fn file_url(file: &Path) -> String {
    format!("file://{}", file.canonicalize().unwrap().display())
}

/// `text` percent-encoded for a query: every byte but letters, digits and `-._~`.
fn encode(text: &str) -> String {
    text.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' => {
                (b as char).to_string()
            }
            _ => format!("%{b:02X}"),
        })
        .collect()
}

/// A player's answer: something drawn at frame 0, and the last frame different from it.
fn assert_draws(name: &str, player: &Value) {
    assert!(player["frames"].as_u64().unwrap() > 1, "{name}: {player}");
    assert!(
        player["drawnPixels"].as_u64().unwrap() > 0,
        "{name}: blank at frame 0: {player}"
    );
    assert!(
        player["changedPixels"].as_u64().unwrap() > 0,
        "{name}: nothing moves: {player}"
    );
}

/// Every resource the page loaded is a local file.
fn assert_local(name: &str, resources: &Value) {
    for r in resources.as_array().unwrap() {
        assert!(
            r.as_str().unwrap().starts_with("file://"),
            "{name} loaded {r}"
        );
    }
}

/// The position the page drew for `body` at the time it reports equals `reference` at the state
/// of that time, and the pixel there has the body's colour. The frames are stored as `f32`, so
/// each coordinate is the trajectory's to within an `f32` rounding (relative 2⁻²⁴) and the
/// shortest decimal that reads back as that `f32` (another 2⁻²⁴): 2⁻²² leaves a factor 2.
fn assert_drawn_at<S>(
    name: &str,
    answer: &Value,
    states: &[S],
    time: impl Fn(&S) -> f64,
    reference: impl Fn(&S) -> [f64; 3],
) {
    let position = &answer["position"];
    let t = position["t"]
        .as_f64()
        .unwrap_or_else(|| panic!("{name}: {answer}"));
    let state = states
        .iter()
        .find(|s| time(s) == t)
        .unwrap_or_else(|| panic!("{name}: the page shows t = {t}, which no state had"));
    let want = reference(state);
    let got: Vec<f64> = position["world"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    for i in 0..3 {
        let tolerance = want[i].abs() * 2f64.powi(-22);
        assert!(
            (got[i] - want[i]).abs() <= tolerance,
            "{name} at t = {t}: drawn at {got:?}, the trajectory has {want:?}"
        );
    }
    assert_eq!(position["pixel"], position["colour"], "{name}: {position}");
}

#[test]
fn recorded_positions_are_drawn_where_the_trajectory_is() {
    let Some(browser) = chromium("positions") else {
        return;
    };
    let dir = out_dir();

    // The plane: the double pendulum's outer bob at t = 0.77 s.
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    };
    let mut s = double_pendulum::State::at_rest(double_pendulum::Coords {
        theta1: 1.5,
        theta2: 1.5,
    });
    let mut recorder = Recorder::new(&sys);
    let mut states = vec![s];
    recorder.push(&sys, &s).unwrap();
    sys.simulate::<Rk4>(&mut s, 1e-3, 1500, |s| {
        recorder.push(&sys, s).unwrap();
        states.push(*s);
    })
    .unwrap();
    let page = dir.join("double_pendulum.html");
    recorder.write_html(&page).unwrap();
    let answer = browser.probe(&page, &serde_json::json!({"body": "bob2", "t": 0.77}));
    assert_local("double pendulum", &answer["resources"]);
    let player = &answer["players"][0];
    assert_draws("double pendulum", player);
    assert_drawn_at(
        "double pendulum",
        player,
        &states,
        |s| s.t,
        |s| {
            let bob = sys.bodies(s).bob2;
            [bob.x, bob.y, 0.0]
        },
    );

    // Space: the rolling wheel's centre, and a point on its rim, at t = 0.63 s.
    let wheel = RollingWheel { m: 2.0, r: 0.3 };
    let mut s = rolling_wheel::State::new(
        0.0,
        rolling_wheel::Coords {
            x: 0.0,
            y: 0.0,
            phi: 0.4,
            theta: 0.0,
        },
        rolling_wheel::Coords {
            x: 1.5 * 0.4f64.cos(),
            y: 1.5 * 0.4f64.sin(),
            phi: 0.7,
            theta: 5.0,
        },
    );
    let mut recorder = Recorder::new(&wheel);
    recorder.mark("rim", "wheel", &[0.3, 0.0, 0.0]).unwrap();
    let mut states = vec![s];
    recorder.push(&wheel, &s).unwrap();
    for _ in 0..1000 {
        wheel.step::<Rk4>(&mut s, 1e-3).unwrap();
        recorder.push(&wheel, &s).unwrap();
        states.push(s);
    }
    assert_eq!(<RollingWheel as Drawable<4>>::BODIES[0].name, "wheel");
    let page = dir.join("rolling_wheel.html");
    recorder.write_html(&page).unwrap();
    for body in ["wheel", "rim"] {
        let answer = browser.probe(&page, &serde_json::json!({"body": body, "t": 0.63}));
        let player = &answer["players"][0];
        assert_draws("rolling wheel", player);
        assert_drawn_at(
            "rolling wheel",
            player,
            &states,
            |s| s.t,
            |s| {
                let w = wheel.bodies(s).wheel;
                let p = if body == "rim" {
                    w.point(vec3(0.3, 0.0, 0.0))
                } else {
                    w.position
                };
                [p.x, p.y, p.z]
            },
        );
    }
}

/// Every `src` and `href` of the page `file` is a file beside it or a place on the page.
fn assert_links_are_local(file: &Path) {
    let html = std::fs::read_to_string(file).unwrap();
    for attribute in ["src=\"", "href=\""] {
        for (at, _) in html.match_indices(attribute) {
            let value = &html[at + attribute.len()..];
            let value = &value[..value.find('"').unwrap()];
            let local = value.starts_with('#') || file.with_file_name(value).is_file();
            assert!(
                local,
                "{}: {attribute}{value}\" is not a local file",
                file.display()
            );
        }
    }
}

#[test]
fn the_gallery_page_shows_every_scene_moving() {
    let Some(browser) = chromium("gallery") else {
        return;
    };
    let dir = out_dir().join("gallery");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let scenes: Vec<_> = lagrange_gallery::SCENES
        .iter()
        .map(|run| run_scene(&dir, *run))
        .collect();
    let index = write_index(&dir, &scenes).unwrap();
    assert_links_are_local(&index);
    for scene in &scenes {
        let page = scene.animation.as_ref().unwrap_or_else(|| {
            panic!("{}: no animation written", scene.title);
        });
        let page = dir.join(page);
        assert_links_are_local(&page);
        let size = std::fs::metadata(&page).unwrap().len();
        assert!(size < 2_000_000, "{}: {size} bytes", page.display());
    }

    // The double pendulum's outer bob: the probe reads it back from the scene's own page.
    let request = serde_json::json!({"double_pendulum": {"body": "bob2", "t": 1.0}});
    let answer = browser.probe(&index, &request);
    assert_local("index", &answer["resources"]);
    for scene in &scenes {
        let id = lagrange_gallery::page::section_id(scene);
        let reply = &answer["scenes"][id.as_str()];
        assert!(
            reply.is_object(),
            "{id}: no answer from its animation: {answer}"
        );
        assert_local(&id, &reply["resources"]);
        assert_draws(&id, &reply["players"][0]);
    }
    let bob = &answer["scenes"]["double_pendulum"]["players"][0]["position"];
    assert_eq!(bob["pixel"], bob["colour"], "{bob}");

    let png = out_dir().join("gallery.png");
    let _ = std::fs::remove_file(&png);
    browser.screenshot(&index, &png);
    let bytes = std::fs::read(&png).expect("the screenshot is written");
    assert!(bytes.starts_with(b"\x89PNG"), "{} is a PNG", png.display());
    eprintln!("screenshot of the gallery's page: {}", png.display());
}
