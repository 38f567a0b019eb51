//! Support for the example scenes of `lagrange`: a [`Check`] of a simulated quantity against its
//! closed form, the results table the gallery prints, SVG line plots, the gallery's page
//! ([`page`]), and the special functions the closed forms need.
//!
//! Every scene in [`scenes`] exposes `pub fn run(plots: &Path) -> Vec<Check>`; the `gallery` binary
//! of this crate and the `scenes` test both call it, so what the gallery prints is exactly what the
//! tests assert. The examples of `lagrange` tell the same stories as plain usage (declare, simulate,
//! print, plot) without the checks.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub mod flip_map;
pub mod page;
pub mod plot;
pub mod scenes;

use scenes::*;

/// Every scene, in the order the README lists them: what the gallery runs and its page shows.
pub const SCENES: &[fn(&Path) -> Vec<Check>] = &[
    wedge_block::run,
    ramp::run,
    breathing_ellipse::run,
    spinning_hoop::run,
    pendulum::run,
    double_pendulum::run,
    rigid_triangle::run,
    atwood::run,
    hoop_bifurcation::run,
    small_oscillations::run,
    sphere_release::run,
    rolling_wheel::run,
    four_bar::run,
    cartesian_pendulum::run,
    rough_ramp::run,
    rough_wedge::run,
    gyroscope::run,
    rough_plane::run,
    pushed_block::run,
    identify_pendulum::run,
    spatial_arm::run,
    computed_torque::run,
];

/// Runs too long for a debug build — the torque-free body's 10⁴ s — which the gallery runs after
/// the scenes (in release, as the README's command builds it) and prints in the same table; the
/// tests run them shortened (`tests/floating.rs`).
pub const LONG_RUNS: &[fn(&Path) -> Vec<Check>] = &[tumbling_body::run];

/// One simulated quantity against its exact value.
#[derive(Clone, Debug)]
pub struct Check {
    /// The scene ("wedge and block").
    pub scene: &'static str,
    /// What is compared ("wedge acceleration Ẍ").
    pub quantity: String,
    /// What the simulation gave.
    pub simulated: f64,
    /// The closed form (or published reference).
    pub exact: f64,
    /// Largest acceptable relative error, argued from the method's error in the scene file.
    pub tolerance: f64,
}

impl Check {
    /// A check of `simulated` against `exact` within relative `tolerance`.
    pub fn new(
        scene: &'static str,
        quantity: impl Into<String>,
        simulated: f64,
        exact: f64,
        tolerance: f64,
    ) -> Self {
        Check {
            scene,
            quantity: quantity.into(),
            simulated,
            exact,
            tolerance,
        }
    }

    /// |simulated − exact| / |exact| (absolute error when the exact value is 0).
    pub fn relative_error(&self) -> f64 {
        let diff = (self.simulated - self.exact).abs();
        if self.exact == 0.0 {
            diff
        } else {
            diff / self.exact.abs()
        }
    }

    /// Whether the error is within tolerance (NaN never passes).
    pub fn passed(&self) -> bool {
        self.relative_error() <= self.tolerance
    }
}

/// The results table: scene, quantity, simulated, exact, relative error, tolerance, verdict.
pub fn table(checks: &[Check]) -> String {
    let mut out = String::new();
    let w = checks
        .iter()
        .map(|c| c.quantity.chars().count())
        .max()
        .unwrap_or(8)
        .max(8);
    let s = checks
        .iter()
        .map(|c| c.scene.chars().count())
        .max()
        .unwrap_or(5)
        .max(5);
    let _ = writeln!(
        out,
        "{:<s$}  {:<w$}  {:>22}  {:>22}  {:>9}  {:>9}  ok",
        "scene", "quantity", "simulated", "exact", "rel.err", "tol"
    );
    for c in checks {
        let _ = writeln!(
            out,
            "{:<s$}  {:<w$}  {:>22.15e}  {:>22.15e}  {:>9.2e}  {:>9.1e}  {}",
            c.scene,
            c.quantity,
            c.simulated,
            c.exact,
            c.relative_error(),
            c.tolerance,
            if c.passed() { "yes" } else { "NO" }
        );
    }
    out
}

/// Where scenes write their plots: `plots/` at the workspace root, or `$LAGRANGE_PLOTS` if set.
pub fn plots_dir() -> PathBuf {
    let dir = std::env::var_os("LAGRANGE_PLOTS")
        .map(PathBuf::from)
        .unwrap_or_else(|| {
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("..")
                .join("plots")
        });
    let _ = std::fs::create_dir_all(&dir);
    dir.canonicalize().unwrap_or(dir)
}

/// The complete elliptic integral of the first kind K(k) = ∫₀^{π/2} dθ / √(1 − k² sin²θ) (modulus
/// k, |k| < 1), by the arithmetic–geometric mean: K(k) = π / (2 AGM(1, √(1 − k²)))
/// (Abramowitz & Stegun 17.6). Converges quadratically; exact to round-off.
///
/// ```
/// let k = lagrange_gallery::elliptic_k(0.0);
/// assert!((k - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
/// // A&S Table 17.1: K(sin 30°) = 1.685750354812596
/// assert!((lagrange_gallery::elliptic_k(0.5) - 1.685750354812596).abs() < 1e-14);
/// ```
pub fn elliptic_k(k: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (1.0 - k * k).sqrt());
    for _ in 0..64 {
        if (a - b).abs() <= 1e-16 * a {
            break;
        }
        let next = (0.5 * (a + b), (a * b).sqrt());
        a = next.0;
        b = next.1;
    }
    std::f64::consts::PI / (a + b)
}

/// Jacobi's elliptic functions (sn, cn, dn) of argument u and parameter m = k² (0 ≤ m < 1), by the
/// arithmetic–geometric mean and the descending Landen transformation (NIST DLMF §22.20(ii),
/// eqs. 22.20.1–22.20.4); dn = √(1 − m sn²) (DLMF 22.10.1's identity, positive for real u).
///
/// ```
/// use lagrange_gallery::{elliptic_k, jacobi_elliptic};
/// // At the quarter period K: sn = 1, cn = 0, dn = √(1 − m) (DLMF 22.5.1).
/// let m = 0.5f64;
/// let (sn, cn, dn) = jacobi_elliptic(elliptic_k(m.sqrt()), m);
/// assert!((sn - 1.0).abs() < 1e-14 && cn.abs() < 1e-7 && (dn - (1.0 - m).sqrt()).abs() < 1e-14);
/// // m = 0: the circular functions.
/// let (sn, cn, _) = jacobi_elliptic(0.7, 0.0);
/// assert!((sn - 0.7f64.sin()).abs() < 1e-15 && (cn - 0.7f64.cos()).abs() < 1e-15);
/// ```
pub fn jacobi_elliptic(u: f64, m: f64) -> (f64, f64, f64) {
    let (mut a, mut b, mut c) = (vec![1.0f64], vec![(1.0 - m).sqrt()], vec![m.sqrt()]);
    // Quadratic convergence: c falls below the rounding of a in a few iterations.
    while c[c.len() - 1].abs() > f64::EPSILON * a[a.len() - 1] && a.len() < 40 {
        let (an, bn) = (a[a.len() - 1], b[b.len() - 1]);
        a.push((an + bn) / 2.0);
        b.push((an * bn).sqrt());
        c.push((an - bn) / 2.0);
    }
    let n = a.len() - 1;
    let mut phi = 2f64.powi(n as i32) * a[n] * u;
    for j in (1..=n).rev() {
        phi = (phi + (c[j] / a[j] * phi.sin()).asin()) / 2.0;
    }
    let (sn, cn) = phi.sin_cos();
    (sn, cn, (1.0 - m * sn * sn).sqrt())
}

/// The first time after `times[0]` where `values` crosses zero upward, by linear interpolation
/// between samples refined by cubic Hermite interpolation with the given derivatives.
/// Returns `None` if there is no upward crossing.
pub fn upward_crossing(times: &[f64], values: &[f64], derivatives: &[f64]) -> Option<f64> {
    for i in 1..times.len() {
        let (y0, y1) = (values[i - 1], values[i]);
        if y0 < 0.0 && y1 >= 0.0 {
            let (t0, t1) = (times[i - 1], times[i]);
            let h = t1 - t0;
            let (d0, d1) = (derivatives[i - 1] * h, derivatives[i] * h);
            // Cubic Hermite p(s), s ∈ [0, 1]; Newton from the secant guess.
            let p = |s: f64| {
                let (s2, s3) = (s * s, s * s * s);
                (2.0 * s3 - 3.0 * s2 + 1.0) * y0
                    + (s3 - 2.0 * s2 + s) * d0
                    + (-2.0 * s3 + 3.0 * s2) * y1
                    + (s3 - s2) * d1
            };
            let dp = |s: f64| {
                let s2 = s * s;
                (6.0 * s2 - 6.0 * s) * y0
                    + (3.0 * s2 - 4.0 * s + 1.0) * d0
                    + (-6.0 * s2 + 6.0 * s) * y1
                    + (3.0 * s2 - 2.0 * s) * d1
            };
            let mut s = y0 / (y0 - y1);
            for _ in 0..20 {
                let step = p(s) / dp(s);
                s = (s - step).clamp(0.0, 1.0);
                if step.abs() < 1e-16 {
                    break;
                }
            }
            return Some(t0 + s * h);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn check_verdicts() {
        assert!(Check::new("s", "q", 1.0 + 1e-9, 1.0, 1e-8).passed());
        assert!(!Check::new("s", "q", 1.1, 1.0, 1e-8).passed());
        assert!(!Check::new("s", "q", f64::NAN, 1.0, 1e-8).passed());
    }

    #[test]
    fn hermite_crossing_is_exact_for_cubics() {
        // y = t³ − 0.3 crosses at t = 0.3^(1/3), sampled coarsely.
        let ts: Vec<f64> = (0..5).map(|i| i as f64 * 0.25).collect();
        let ys: Vec<f64> = ts.iter().map(|t| t * t * t - 0.3).collect();
        let ds: Vec<f64> = ts.iter().map(|t| 3.0 * t * t).collect();
        let root = upward_crossing(&ts, &ys, &ds).unwrap();
        assert!((root - 0.3f64.cbrt()).abs() < 1e-14);
    }

    /// sn′ = cn dn and cn′ = −sn dn (DLMF 22.13.1–2) by central differences (step 1e-5:
    /// truncation ~1e-11, rounding ~1e-11).
    #[test]
    fn jacobi_functions_solve_their_differential_equations() {
        let (m, d) = (0.5, 1e-5);
        for u in [0.3, 1.7, -2.2, 11.0] {
            let (sn, cn, dn) = jacobi_elliptic(u, m);
            let (sp, cp, _) = jacobi_elliptic(u + d, m);
            let (sm, cm, _) = jacobi_elliptic(u - d, m);
            assert!(((sp - sm) / (2.0 * d) - cn * dn).abs() < 1e-9);
            assert!(((cp - cm) / (2.0 * d) + sn * dn).abs() < 1e-9);
        }
    }

    #[test]
    fn elliptic_k_matches_series_near_zero() {
        // K(k) = π/2 (1 + k²/4 + 9k⁴/64 + …) (A&S 17.3.11)
        let k: f64 = 1e-3;
        let series = std::f64::consts::FRAC_PI_2 * (1.0 + k * k / 4.0 + 9.0 * k.powi(4) / 64.0);
        assert!((elliptic_k(k) - series).abs() < 1e-15);
    }
}
