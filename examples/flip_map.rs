//! The double pendulum's flip-time map: released at rest from every (θ₁, θ₂) of a grid, how long
//! until either arm first flips over (|θ| passes π)? Neighbouring releases that never flip form
//! smooth regions; where the motion is chaotic, flip times change from one pixel to the next and
//! the picture looks fractal.
//!
//! Each trajectory is RK4 at h = 1e-3 with the flip detected between steps (so a flip time is
//! known to one step), stopped at the cap `t_max`; the grid runs as one [`ensemble`] sweep, once on
//! one thread and once on two, which must give the same map bit for bit. The scene prints the
//! throughput of each (trajectories per second) and the speed-up, and draws the map into
//! `plots/flip_map.svg` (or `$LAGRANGE_PLOTS`).
//!
//! A release whose energy is below the lowest configuration with an arm upright can never flip
//! ([`can_flip`]); those cells are still integrated, so that the throughput is that of the whole
//! grid and the picture shows what was simulated, not what was argued.
//!
//! ```text
//! cargo run --release --example flip_map                        # 64 × 64, t_max = 5 s
//! cargo run --release --example flip_map -- --n 400 --t-max 30  # the detailed picture
//! ```

use lagrange_gallery::flip_map::{can_flip, draw, grid, pendulum, timed_map, H, N, T_MAX};

/// `--n N` and `--t-max T` from the command line, defaulting to [`N`] and [`T_MAX`].
fn options() -> (usize, f64) {
    let (mut n, mut t_max) = (N, T_MAX);
    let args: Vec<String> = std::env::args().skip(1).collect();
    for pair in args.chunks(2) {
        match (pair[0].as_str(), pair.get(1).map(|v| v.parse::<f64>())) {
            ("--n", Some(Ok(v))) if v >= 1.0 && v.fract() == 0.0 => n = v as usize,
            ("--t-max", Some(Ok(v))) if v > 0.0 && v.is_finite() => t_max = v,
            _ => {
                eprintln!("usage: flip_map [--n CELLS_PER_AXIS] [--t-max SECONDS]");
                std::process::exit(2);
            }
        }
    }
    (n, t_max)
}

fn main() {
    let (n, t_max) = options();
    let sys = pendulum();
    let cells = (n * n) as f64;
    println!("flip map: {n}×{n} releases, RK4 h = {H}, cap {t_max} s");

    let (one, t1) = timed_map(&sys, n, t_max, 1);
    println!("1 thread:  {t1:7.2} s, {:9.0} trajectories/s", cells / t1);
    let (two, t2) = timed_map(&sys, n, t_max, 2);
    println!("2 threads: {t2:7.2} s, {:9.0} trajectories/s", cells / t2);
    println!("speed-up 1 → 2 threads: {:.2}", t1 / t2);

    let bits = |m: &[Option<f64>]| m.iter().map(|t| t.map(f64::to_bits)).collect::<Vec<_>>();
    assert_eq!(
        bits(&one),
        bits(&two),
        "the map depends on the thread count"
    );
    println!("maps on 1 and 2 threads identical bit for bit");

    let flipped = two.iter().flatten().count();
    let possible = grid(n)
        .iter()
        .filter(|&&(a, b)| can_flip(&sys, a, b))
        .count();
    println!(
        "{flipped} of {} releases flip within {t_max} s; {possible} have the energy to",
        n * n
    );

    let path = lagrange_gallery::plots_dir().join("flip_map.svg");
    match draw(&path, n, t_max, &two) {
        Ok(()) => println!("wrote {}", path.display()),
        Err(e) => {
            eprintln!("could not draw {}: {e}", path.display());
            std::process::exit(1);
        }
    }
}
