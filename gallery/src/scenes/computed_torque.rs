//! A three-joint spatial arm read from a URDF file (`gallery/urdf/arm3.urdf`) tracks a reference
//! trajectory q_d(t) under the computed-torque law (Spong, Hutchinson & Vidyasagar, *Robot
//! Modeling and Control*, 2006, §8.3 "inverse dynamics"):
//!
//! ```text
//! u = M(q) (q̈_d + K_d ė + K_p e) + b(q, q̇),     e = q_d − q,
//! ```
//!
//! which is inverse dynamics at the commanded acceleration: `sys.inverse_dynamics(&state, &a)`
//! returns the generalized forces that give q̈ = a, and with one effort acting on each joint those
//! are the efforts. With an exact model the law cancels the arm's dynamics and leaves each joint's
//! error the same linear equation, ë + K_d ė + K_p e = 0. With K_p = ω², K_d = 2ω (critically
//! damped), from e(0) = e₀, ė(0) = ė₀:
//!
//! ```text
//! e(t) = (e₀ + (ė₀ + ω e₀) t) e^{−ωt}.
//! ```
//!
//! The simulation sets the efforts once per step of h and holds them over it (a zero-order hold),
//! so the law is exact only at the start of each step. The hold's error, and the bound it gives on
//! |e − e_cf|, are derived at [`hold_rate`]: first order in h, the efforts in effect lagging the law
//! by h/2. Two checks per joint: e(t) against the closed form over the whole run, and the tracking
//! error after the transient, each within the bound the hold's error gives.

use crate::plot::{self, Series};
use crate::Check;
use lagrange::animation::Recorder;
use lagrange::prelude::*;
use std::path::Path;

#[lagrange::urdf("urdf/arm3.urdf")]
pub mod arm3 {}

use arm3::{Arm3, Coords, Efforts, State};

const SCENE: &str = "computed-torque arm (URDF)";

/// The error dynamics' natural frequency ω (rad/s): K_p = ω², K_d = 2ω, critically damped.
pub const OMEGA: f64 = 10.0;
const KP: f64 = OMEGA * OMEGA;
const KD: f64 = 2.0 * OMEGA;

/// The step over which the efforts are held (s).
pub const STEP: f64 = 1e-3;
/// The length of the run (s).
pub const DURATION: f64 = 4.0;
/// Where the transient is over: |e_cf| < 1e-7 rad from here on (e^{−ωt} = 2e-9 at 2 s).
pub const TRANSIENT: f64 = 2.0;

/// One term of a joint's reference, A sin(ν t + φ).
struct Sinusoid {
    /// A (rad).
    amplitude: f64,
    /// ν (rad/s).
    frequency: f64,
    /// φ (rad).
    phase: f64,
}

const fn wave(amplitude: f64, frequency: f64, phase: f64) -> Sinusoid {
    Sinusoid {
        amplitude,
        frequency,
        phase,
    }
}

/// The reference of each joint: c + Σᵢ Aᵢ sin(νᵢ t + φᵢ), an offset c (rad) and two sinusoids.
const REFERENCE: [(f64, [Sinusoid; 2]); 3] = [
    (0.0, [wave(0.8, 1.2, 0.0), wave(0.2, 3.1, 0.5)]),
    (0.4, [wave(0.5, 1.7, 0.3), wave(0.15, 4.0, 1.0)]),
    (0.9, [wave(0.6, 2.2, -0.4), wave(0.1, 5.0, 0.0)]),
];

/// The arm's initial error e₀ = q_d(0) − q(0) (rad); it starts at rest, so ė₀ = q̇_d(0).
const INITIAL_ERROR: [f64; 3] = [0.25, -0.2, 0.3];

/// (q_d, q̇_d, q̈_d) at t, in closed form.
pub fn reference(t: f64) -> [[f64; 3]; 3] {
    let mut out = [[0.0; 3]; 3];
    for (j, (offset, terms)) in REFERENCE.iter().enumerate() {
        out[0][j] = *offset;
        for w in terms {
            let (s, c) = (w.frequency * t + w.phase).sin_cos();
            out[0][j] += w.amplitude * s;
            out[1][j] += w.amplitude * w.frequency * c;
            out[2][j] -= w.amplitude * w.frequency * w.frequency * s;
        }
    }
    out
}

/// The closed-form error of one joint from (e₀, ė₀): (e, ė, ë) at t, e = (e₀ + c t) e^{−ωt} with
/// c = ė₀ + ω e₀; ė = (c − ω(e₀ + c t)) e^{−ωt}, ë = (ω²(e₀ + c t) − 2ωc) e^{−ωt}.
pub fn closed_form_error(e0: f64, ed0: f64, t: f64) -> [f64; 3] {
    let c = ed0 + OMEGA * e0;
    let (p, decay) = (e0 + c * t, (-OMEGA * t).exp());
    [
        p * decay,
        (c - OMEGA * p) * decay,
        (OMEGA * OMEGA * p - 2.0 * OMEGA * c) * decay,
    ]
}

/// The initial errors (e₀, ė₀) per joint.
fn initial_error() -> ([f64; 3], [f64; 3]) {
    (INITIAL_ERROR, reference(0.0)[1])
}

/// The closed-loop motion the law gives without the hold: q = q_d − e_cf, with its rates.
fn exact_motion(t: f64) -> [[f64; 3]; 3] {
    let (e0, ed0) = initial_error();
    let desired = reference(t);
    let mut out = desired;
    for j in 0..3 {
        let e = closed_form_error(e0[j], ed0[j], t);
        for k in 0..3 {
            out[k][j] -= e[k];
        }
    }
    out
}

/// The efforts the law sets at `state`: inverse dynamics at q̈_d + K_d ė + K_p e.
pub fn computed_torque(sys: &Validated<Arm3>, state: &State) -> lagrange::Result<Efforts> {
    let [qd, vd, ad] = reference(state.t);
    let (q, v) = (state.q.to_array(), state.v.to_array());
    let commanded: [f64; 3] =
        std::array::from_fn(|j| ad[j] + KD * (vd[j] - v[j]) + KP * (qd[j] - q[j]));
    let tau = sys.inverse_dynamics(state, &Coords::from_array(commanded))?;
    Ok(efforts_struct(tau.to_array()))
}

fn efforts_struct([yaw_effort, shoulder_effort, elbow_effort]: [f64; 3]) -> Efforts {
    Efforts {
        yaw_effort,
        shoulder_effort,
        elbow_effort,
    }
}

fn efforts_array(u: &Efforts) -> [f64; 3] {
    [u.yaw_effort, u.shoulder_effort, u.elbow_effort]
}

/// The hold's forcing rate a(t) = M(q)⁻¹ u̇ per joint, along the exact closed-loop motion.
///
/// Why it bounds the hold's error: over a step [t_k, t_k + h] the arm gets u(t_k) while the law
/// would give u(t) = u(t_k) + (t − t_k) u̇ + O(h²), so its acceleration falls short of the law's by
/// (t − t_k) M⁻¹u̇ and the error equation becomes ë + K_d ė + K_p e = w(t), w = (t − t_k) a(t) +
/// O(h²): a sawtooth of height h|a| and mean (h/2) a. The difference from the closed form is w
/// through the error equation's impulse response g(t) = t e^{−ωt} ≥ 0 (the inverse Laplace
/// transform of 1/(s + ω)²), so
///
/// ```text
/// |e − e_cf|(t) ≤ h ∫₀ᵗ g(t − s) |a(s)| ds · (1 + O(ωh))   ≤ h sup|a| / K_p,   ∫₀^∞ g = 1/ω².
/// ```
///
/// Its leading term is at most half of the bound (the sawtooth's mean, and a changing sign only
/// lowers it): the bound leaves a margin of 2 for the O(h²) terms, ωh = 1 % of the leading one.
///
/// u̇ by a central difference of inverse dynamics along the motion, δ = 1e-5 s: truncation
/// δ² u⃛ / 6 and rounding ε |u| / δ are both below 1e-8 of u̇'s scale. M⁻¹u̇ as the
/// accelerations are affine in the efforts: q̈(u̇) − q̈(0) = M⁻¹u̇.
pub fn hold_rate(sys: &Validated<Arm3>, t: f64) -> lagrange::Result<[f64; 3]> {
    const DELTA: f64 = 1e-5;
    let at = |t: f64| {
        let [q, v, a] = exact_motion(t);
        let s = State::new(t, Coords::from_array(q), Coords::from_array(v));
        (s, Coords::from_array(a))
    };
    let efforts = |t: f64| -> lagrange::Result<[f64; 3]> {
        let (s, a) = at(t);
        Ok(sys.inverse_dynamics(&s, &a)?.to_array())
    };
    let (after, before) = (efforts(t + DELTA)?, efforts(t - DELTA)?);
    let rate: [f64; 3] = std::array::from_fn(|j| (after[j] - before[j]) / (2.0 * DELTA));
    let (s, _) = at(t);
    let driven = sys
        .driven(&efforts_struct(rate))
        .accelerations(&s)?
        .to_array();
    let free = sys.accelerations(&s)?.to_array();
    Ok(std::array::from_fn(|j| driven[j] - free[j]))
}

/// One tracking run: the samples at the start of every step.
#[derive(Default)]
pub struct Tracking {
    /// The hold's step h.
    pub step: f64,
    /// t_k.
    pub times: Vec<f64>,
    /// The arm's state at t_k.
    pub states: Vec<State>,
    /// q_d(t_k).
    pub desired: Vec<[f64; 3]>,
    /// e(t_k) = q_d − q.
    pub error: Vec<[f64; 3]>,
    /// The closed form e_cf(t_k).
    pub closed_form: Vec<[f64; 3]>,
    /// The efforts set at t_k and held to t_k + h.
    pub efforts: Vec<[f64; 3]>,
}

/// Runs the arm from rest at q_d(0) − e₀ for `duration`, the efforts set by the law at the start
/// of every step of h and held over it (RK4: its error, O(h⁴), is far below the hold's O(h)).
pub fn track(h: f64, duration: f64) -> lagrange::Result<Tracking> {
    let sys = Arm3::default().validated()?;
    let (e0, ed0) = initial_error();
    let q0: [f64; 3] = std::array::from_fn(|j| reference(0.0)[0][j] - e0[j]);
    let mut state = State::at_rest(Coords::from_array(q0));
    let steps = (duration / h).round() as usize;
    let mut run = Tracking {
        step: h,
        ..Tracking::default()
    };
    for k in 0..=steps {
        let u = computed_torque(&sys, &state)?;
        let (t, q, qd) = (state.t, state.q.to_array(), reference(state.t)[0]);
        run.times.push(t);
        run.states.push(state);
        run.desired.push(qd);
        run.error.push(std::array::from_fn(|j| qd[j] - q[j]));
        run.closed_form.push(std::array::from_fn(|j| {
            closed_form_error(e0[j], ed0[j], t)[0]
        }));
        run.efforts.push(efforts_array(&u));
        if k < steps {
            sys.driven(&u).step::<Rk4>(&mut state, h)?;
        }
    }
    Ok(run)
}

/// The largest |x_j| over `rows`, per joint.
fn largest<'a>(rows: impl Iterator<Item = &'a [f64; 3]>) -> [f64; 3] {
    rows.fold([0.0; 3], |m, r| {
        std::array::from_fn(|j| m[j].max(r[j].abs()))
    })
}

/// The hold's bound on |e − e_cf| per joint at each of `times` (from 0, evenly spaced), with the
/// efforts held over steps of `h`: h ∫₀ᵗ g(t − s) |a(s)| ds ([`hold_rate`]), by the trapezoidal
/// rule on `times`. a and g vary on the scales 1/ω = 0.1 s and 1/ν ≥ 0.2 s, so on a spacing Δ of a
/// few ms the rule's relative error, ~(ωΔ)²/12, is below 0.1 %.
pub fn hold_bound(h: f64, times: &[f64]) -> lagrange::Result<Vec<[f64; 3]>> {
    let sys = Arm3::default().validated()?;
    let rates = times
        .iter()
        .map(|&t| Ok(hold_rate(&sys, t)?.map(f64::abs)))
        .collect::<lagrange::Result<Vec<[f64; 3]>>>()?;
    let g = |t: f64| t * (-OMEGA * t).exp();
    let bound = (0..times.len()).map(|n| {
        std::array::from_fn(|j| {
            let integrand = |i: usize| g(times[n] - times[i]) * rates[i][j];
            let inner: f64 = (1..n).map(integrand).sum();
            let spacing = if n > 0 { times[n] - times[n - 1] } else { 0.0 };
            h * spacing * (inner + 0.5 * (integrand(0) + integrand(n)))
        })
    });
    Ok(bound.collect())
}

/// Samples every 5 ms of a run: where the bound is evaluated.
const SAMPLING: f64 = 5e-3;

pub fn run(plots: &Path) -> Vec<Check> {
    let run = track(STEP, DURATION).expect("simulation");
    draw(plots, &run);
    let every = ((SAMPLING / run.step).round() as usize).max(1);
    let samples: Vec<usize> = (0..run.times.len()).step_by(every).collect();
    let times: Vec<f64> = samples.iter().map(|&k| run.times[k]).collect();
    let bound = hold_bound(run.step, &times).expect("the hold's bound");
    let settled = times.iter().position(|&t| t >= TRANSIENT).unwrap_or(0);
    let joints = Coords::NAMES.iter().enumerate();
    // Over the whole run, at the sample where |e − e_cf| comes closest to its bound.
    let against_closed_form = joints.clone().map(|(j, joint)| {
        let departure =
            |n: usize| (run.error[samples[n]][j] - run.closed_form[samples[n]][j]).abs();
        let closest = (1..times.len())
            .max_by(|&a, &b| (departure(a) / bound[a][j]).total_cmp(&(departure(b) / bound[b][j])))
            .unwrap_or(0);
        Check::new(
            SCENE,
            format!(
                "{joint}: |e − (e₀ + (ė₀+ωe₀)t)e^(−ωt)| nearest its bound, t = {:.3} s",
                times[closest]
            ),
            departure(closest),
            0.0,
            bound[closest][j],
        )
    });
    // After the transient: |e| ≤ |e_cf| + the hold's bound, the largest of each.
    let after_transient = joints.map(|(j, joint)| {
        let tracking = largest(run.error[samples[settled]..].iter())[j];
        let allowed = (settled..times.len())
            .map(|n| run.closed_form[samples[n]][j].abs() + bound[n][j])
            .fold(0.0, f64::max);
        Check::new(
            SCENE,
            format!("{joint}: tracking error max |e| for t ≥ {TRANSIENT} s"),
            tracking,
            0.0,
            allowed,
        )
    });
    against_closed_form.chain(after_transient).collect()
}

/// The plots (every 10th sample) and the arm's animation.
fn draw(plots: &Path, run: &Tracking) {
    let every = 10;
    let series = |label: String, value: &dyn Fn(usize) -> f64| {
        let points = (0..run.times.len())
            .step_by(every)
            .map(|k| (run.times[k], value(k)))
            .collect();
        Series::new(label, points)
    };
    let names = Coords::NAMES;
    let mut joints = Vec::new();
    let mut errors = Vec::new();
    let mut efforts = Vec::new();
    for (j, name) in names.iter().enumerate() {
        joints.push(series(name.to_string(), &|k| run.states[k].q.to_array()[j]));
        joints.push(series(format!("{name} reference"), &|k| run.desired[k][j]));
        errors.push(series(format!("{name} |e|"), &|k| {
            run.error[k][j].abs().log10()
        }));
        // Zero at t = 0 by construction, to rounding: drawn from the first step on.
        errors.push(series(format!("{name} |e − e_cf|"), &|k| match k {
            0 => f64::NAN,
            _ => (run.error[k][j] - run.closed_form[k][j]).abs().log10(),
        }));
        efforts.push(series(format!("{name}_effort"), &|k| run.efforts[k][j]));
    }
    let h = run.step;
    let _ = plot::lines(
        &plots.join("computed_torque_joints.svg"),
        "Computed torque: joint angles and their references",
        "t (s)",
        "q (rad)",
        &joints,
    );
    let _ = plot::lines(
        &plots.join("computed_torque_error.svg"),
        &format!(
            "Tracking error and its departure from the closed form (efforts held over h = {h} s)"
        ),
        "t (s)",
        "log₁₀ |·| (rad)",
        &errors,
    );
    let _ = plot::lines(
        &plots.join("computed_torque_efforts.svg"),
        "Computed torque: the efforts u = ID(q, q̇, q̈_d + K_d ė + K_p e)",
        "t (s)",
        "u (N·m)",
        &efforts,
    );
    let sys = Arm3::default();
    let mut film = Recorder::new(&sys).title(SCENE);
    for state in run.states.iter().step_by(every) {
        let _ = film.push(&sys, state);
    }
    let _ = film.write_html(plots.join("computed_torque.html"));
}
