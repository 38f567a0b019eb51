//! The double pendulum through its C interface: the checked-in header is the generated one, and
//! `main.c`, compiled with the machine's `cc` against the static library, simulates the same runs
//! as Rust does here — free, and held upright by its motors under a PD controller written in C —
//! and gets the same numbers.

use double_pendulum_ffi::double_pendulum::{Coords, DoublePendulum, State, Torques};
use lagrange::ffi::Export;
use lagrange::prelude::*;
use std::f64::consts::PI;
use std::path::{Path, PathBuf};
use std::process::Command;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `double_pendulum.h` is what `export_c!` generates; `LAGRANGE_BLESS=1` rewrites it.
#[test]
fn header_is_current() {
    let path = crate_dir().join("double_pendulum.h");
    let generated = double_pendulum_ffi::dp::header();
    if std::env::var_os("LAGRANGE_BLESS").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let checked_in = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "{} is stale: regenerate it with `LAGRANGE_BLESS=1 cargo test -p double-pendulum-ffi --test c_program`",
        path.display()
    );
}

/// The static library cargo built for this test: in the test binary's `deps/` directory (where
/// `cargo test` writes it), else next to it (where `cargo build` copies it, possibly from an
/// older build).
fn static_library() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let deps = exe.parent().unwrap();
    let name = "libdouble_pendulum_ffi.a";
    [deps.join(name), deps.parent().unwrap().join(name)]
        .into_iter()
        .find(|p| p.exists())
        .unwrap_or_else(|| panic!("{name} not found next to {}", deps.display()))
}

/// Compiles `main.c` with the machine's `cc` (warnings are errors), linked against the static
/// library, or the shared one when `shared` (found at run time through the rpath).
fn compile_c_program(out: &Path, shared: bool) {
    let mut cc = Command::new("cc");
    cc.args([
        "-O2",
        "-std=c11",
        "-Wall",
        "-Wextra",
        "-Werror",
        "-pedantic",
    ])
    .arg(crate_dir().join("main.c"))
    .arg("-I")
    .arg(crate_dir());
    let library = static_library();
    if shared {
        // The shared library beside the static one, copied next to the program: the run finds
        // this build's, not one an older `cargo build` left on the loader's path.
        let name = "libdouble_pendulum_ffi.so";
        let own = out.parent().unwrap();
        std::fs::copy(library.parent().unwrap().join(name), own.join(name))
            .expect("the shared library is built beside the static one");
        let dir = own.display().to_string();
        cc.arg(format!("-L{dir}"))
            .arg(format!("-Wl,-rpath,{dir}"))
            .args(["-ldouble_pendulum_ffi", "-lm"]);
    } else {
        // What a Rust static library needs from the system (`rustc --print native-static-libs`).
        cc.arg(library)
            .args(["-lpthread", "-ldl", "-lm", "-lrt", "-lutil", "-lgcc_s"]);
    }
    let status = cc
        .arg("-o")
        .arg(out)
        .status()
        .expect("the machine's C compiler `cc` runs");
    assert!(status.success(), "cc failed on main.c");
}

/// Runs the compiled program with `args`; its standard output as lines of words. The loader's
/// path cargo sets for tests is removed: it would take precedence over the program's rpath.
fn run(program: &Path, args: &[&str]) -> Vec<Vec<String>> {
    let output = Command::new(program)
        .args(args)
        .env_remove("LD_LIBRARY_PATH")
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        output.status.success(),
        "{} failed:\n{stdout}\n{}",
        program.display(),
        String::from_utf8_lossy(&output.stderr)
    );
    stdout
        .lines()
        .map(|l| l.split_whitespace().map(str::to_string).collect())
        .collect()
}

/// The numbers after `label` on its line of the program's output.
fn numbers(lines: &[Vec<String>], label: &str) -> Vec<f64> {
    let line = lines
        .iter()
        .find(|l| l.first().map(String::as_str) == Some(label))
        .unwrap_or_else(|| panic!("no line `{label}` in the C program's output"));
    line[1..].iter().map(|x| x.parse().unwrap()).collect()
}

fn scene() -> (lagrange::Validated<DoublePendulum>, State) {
    let sys = DoublePendulum {
        m1: 1.0,
        m2: 1.0,
        l1: 1.0,
        l2: 1.0,
        g: 9.81,
    }
    .validated()
    .unwrap();
    let s = State::at_rest(Coords {
        theta1: 1.0,
        theta2: 0.5,
    });
    (sys, s)
}

/// [t, θ₁, θ₂, ω₁, ω₂, E₀, E] as the C program prints them.
fn summary(sys: &lagrange::Validated<DoublePendulum>, s0: &State, s: &State) -> Vec<f64> {
    let (e0, e) = (sys.energy(s0).unwrap(), sys.energy(s).unwrap());
    vec![s.t, s.q.theta1, s.q.theta2, s.v.theta1, s.v.theta2, e0, e]
}

/// The C program's runs end where the same runs in Rust end. The C side calls the same compiled
/// functions; what may differ is the `sin` and `cos` they reach: a C program links the system's
/// libm, a Rust executable may resolve them to its runtime's own. Both are faithful to 1 ulp but
/// not bit-identical, so the two runs can differ by round-off injected at any of the 4·10⁴
/// evaluations, amplified by the double pendulum's sensitivity over the run (a 1-ulp change of
/// θ₁(0) moves the end state by up to 80 ulp and E by 1.8·10⁻¹⁴). Independent injections add up
/// as a random walk: √(4·10⁴) · 10² · 2.2·10⁻¹⁶ · |E| (≈ 20) ≈ 10⁻¹⁰ bounds the difference. A
/// marshalling error (coordinates or parameters swapped, a state not copied back) moves the end
/// state by O(1).
#[test]
fn c_program_matches_rust() {
    let dir = std::env::temp_dir().join(format!("lagrange-ffi-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let program = dir.join("double_pendulum");
    compile_c_program(&program, false);
    let lines = run(&program, &[]);

    let (sys, s0) = scene();
    let mut s = s0;
    for _ in 0..10_000 {
        sys.step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    let rk4 = summary(&sys, &s0, &s);
    let mut s = s0;
    let outcome = sys
        .integrate(Dopri5::new(1e-10, 1e-12), &mut s, 20.0, &mut [], |_| {})
        .unwrap();
    let dopri5 = summary(&sys, &s0, &s);

    let mut largest: f64 = 0.0;
    for (label, rust) in [("rk4", &rk4), ("dopri5", &dopri5)] {
        let c = numbers(&lines, label);
        assert_eq!(c.len(), rust.len());
        for (k, (c, r)) in c.iter().zip(rust).enumerate() {
            largest = largest.max((c - r).abs());
            assert!(
                (c - r).abs() <= 1e-10,
                "{label}[{k}]: C {c:e} against Rust {r:e}"
            );
        }
    }
    eprintln!("largest difference between the C and the Rust runs: {largest:e}");
    assert_eq!(
        numbers(&lines, "dopri5_accepted"),
        [outcome.stats.accepted as f64]
    );
    // RK4's energy error here, which main.c bounds by 1e-8.
    eprintln!("RK4 energy error over 10 s: {:e}", (rk4[6] - rk4[5]).abs());

    // The bad-input calls all got their status and message.
    let nan = &lines
        .iter()
        .find(|l| l.first().map(String::as_str) == Some("nan_parameter"))
        .expect("the NaN parameter line");
    assert_eq!(nan[1], "3", "LAGRANGE_INVALID_PARAMETER is 3");
    assert!(nan[2..]
        .join(" ")
        .contains("parameter `l1` is not finite (NaN)"));
    assert!(lines.iter().any(|l| l == &["bad_input", "ok"]));
    std::fs::remove_dir_all(&dir).ok();
}

/// The same program linked against the shared library prints the same lines.
#[test]
fn shared_library_gives_the_same_output() {
    let dir = std::env::temp_dir().join(format!("lagrange-ffi-shared-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (static_program, shared_program) = (dir.join("static"), dir.join("shared"));
    compile_c_program(&static_program, false);
    compile_c_program(&shared_program, true);
    assert_eq!(run(&static_program, &[]), run(&shared_program, &[]));
    // The untimed benchmark modes run too (callgrind counts them).
    run(&shared_program, &["calls", "10"]);
    run(&shared_program, &["loop", "10"]);
    std::fs::remove_dir_all(&dir).ok();
}

/// `pd_torques` of main.c: each joint driven towards upright.
fn pd_torques(s: &State) -> Torques {
    let (kp, kd) = (100.0, 20.0);
    let (shoulder, shoulder_rate) = (s.q.theta1 - PI, s.v.theta1);
    let (elbow, elbow_rate) = (s.q.theta2 - s.q.theta1, s.v.theta2 - s.v.theta1);
    Torques {
        tau1: -kp * shoulder - kd * shoulder_rate,
        tau2: -kp * elbow - kd * elbow_rate,
    }
}

/// The C program's controller holds the pendulum upright, and its run is the same closed loop
/// run in Rust with `driven(&u)`.
///
/// Bound on the final error: linearized about upright (m = l = 1, g = 9.81), the closed loop is
/// M ë + KD K ė + (KP K − g diag(2, 1)) e = 0 with M = [[2, 1], [1, 1]] and K = [[2, −1], [−1, 1]]
/// (the map from joint torques to generalized forces, as the declaration's motors act); with
/// KP = 100, KD = 20 its eigenvalues are −111.6, −4.92 and −1.716 ± 2.910i (roots of
/// det(M s² + KD K s + KP K − g diag(2, 1)) = 0). From the initial error of 0.5 rad the slowest
/// modes' envelope after 10 s is 0.5 e^(−17.16) = 1.8·10⁻⁸ rad; RK4's error at h = 1 ms on these
/// rates (|hλ| ≤ 0.11) only shifts the rates by O((hλ)⁴). The bound 10⁻⁶ rad leaves a factor 50
/// for the nonlinear transient and the eigenvectors' scaling; torques that did not reach the
/// mechanism (or reached it with the elbow's reaction missing on θ₁) leave the rods to fall, an
/// error of O(1).
///
/// Agreement with Rust: as in `c_program_matches_rust` the two differ only by the libm they reach
/// for sin and cos, 1 ulp at an evaluation; the closed loop is contracting, so such round-off is
/// damped rather than amplified, and 4·10⁴ evaluations of at most 1 ulp of a state of order π add
/// up to √(4·10⁴) · 2.2·10⁻¹⁶ · π ≈ 10⁻¹³ as a random walk; 10⁻¹⁰ leaves a margin of 10³.
#[test]
fn c_controller_holds_the_pendulum_upright() {
    let dir = std::env::temp_dir().join(format!("lagrange-ffi-control-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let program = dir.join("double_pendulum");
    compile_c_program(&program, false);
    let lines = run(&program, &[]);

    let c = numbers(&lines, "control_final");
    let (t, theta1, theta2) = (c[0], c[1], c[2]);
    assert!((t - 10.0).abs() < 1e-9, "the run ends at t = 10, not {t}");
    let error = (theta1 - PI).abs().max((theta2 - PI).abs());
    eprintln!("angle error after 10 s under the C controller: {error:e} rad");
    assert!(error < 1e-6, "θ₁ = {theta1}, θ₂ = {theta2}: not upright");
    // It converges: the printed shoulder errors shrink from 0.5 rad to the final one.
    let printed: Vec<f64> = lines
        .iter()
        .filter(|l| l.first().map(String::as_str) == Some("control"))
        .map(|l| l[2].parse::<f64>().unwrap().abs())
        .collect();
    assert_eq!(printed.len(), 6, "six `control` lines");
    assert!((printed[0] - 0.5).abs() < 1e-12);
    assert!(printed[5] < 1e-6 && printed[4] < printed[1]);

    let (sys, _) = scene();
    let mut s = State::at_rest(Coords {
        theta1: PI - 0.5,
        theta2: PI + 0.3,
    });
    for _ in 0..10_000 {
        let u = pd_torques(&s);
        sys.driven(&u).step::<Rk4>(&mut s, 1e-3).unwrap();
    }
    let rust = [s.t, s.q.theta1, s.q.theta2, s.v.theta1, s.v.theta2];
    for (k, (c, r)) in c.iter().zip(rust).enumerate() {
        assert!(
            (c - r).abs() <= 1e-10,
            "control_final[{k}]: C {c:e} against Rust {r:e}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}
