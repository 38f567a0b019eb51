//! The runner: one mechanism through every entry point in every system of units, each result
//! taken back to SI and compared with the SI run's, against the SI run's own error.

use super::units::{Dim, Units, SI, TIME};
use lagrange::analysis::{equilibrium, normal_modes, EquilibriumOptions};
use lagrange::integrate::{Integrator, Stepper};
use lagrange::prelude::*;
use lagrange::{ContactOptions, Dop853, Dopri5};

/// What an entry point gave, in SI: the values compared (with the dimension of each, for the
/// weights), the counts that must be equal in every system of units, and the counts of an
/// iteration taken to round-off (see [`run_entry`]).
#[derive(Clone, Debug, Default)]
pub struct Value {
    pub parts: Vec<Part>,
    pub counts: Vec<usize>,
    /// The Newton iterations (and the evaluations they make) of a method that iterates to
    /// round-off: its last increment is compared with the rounding of the residual, so a rounding
    /// of the inputs may add or save an iteration. Each must lie within the range the SI run gives
    /// under such roundings.
    pub rounding_counts: Vec<usize>,
}

/// One vector of a result, compared on its own: its components in SI and each one's weight,
/// √Mᵢᵢ (or its inverse, for forces) taken at the SI start, so that a component of any unit
/// counts as much as its share of the kinetic energy says.
#[derive(Clone, Debug)]
pub struct Part {
    pub values: Vec<f64>,
    pub weights: Vec<f64>,
    /// A size the differences are measured against when the values are smaller (an equilibrium
    /// at q = 0 against the guess's size); 0 for none.
    pub floor: f64,
}

impl Part {
    /// max |wᵢ (aᵢ − bᵢ)| / max(max |wᵢ bᵢ|, floor), 0 when the difference is.
    fn relative_error(&self, reference: &Part) -> f64 {
        let mut diff = 0.0f64;
        let mut size = reference.floor;
        for i in 0..self.values.len() {
            let w = reference.weights[i];
            diff = diff.max(w * (self.values[i] - reference.values[i]).abs());
            size = size.max(w * reference.values[i].abs());
        }
        if diff == 0.0 {
            0.0
        } else {
            diff / size
        }
    }
}

impl Value {
    /// The largest relative error of the parts.
    pub fn relative_error(&self, reference: &Value) -> f64 {
        self.parts
            .iter()
            .zip(&reference.parts)
            .fold(0.0f64, |m, (a, b)| m.max(a.relative_error(b)))
    }
}

/// An entry point's outcome: a value, or the kind of error it refused with.
pub type Outcome = Result<Value, String>;

/// The error's variant name: what two refusals are compared by.
pub fn kind(e: &lagrange::Error) -> String {
    let text = format!("{e:?}");
    text.split([' ', '(', '{'])
        .next()
        .unwrap_or_default()
        .to_string()
}

/// The systems of units: each of length, mass and time scaled by 10ᵏ, k ∈ {−6, −3, 3, 6, 9}, and
/// three mixed ones.
pub fn systems() -> Vec<Units> {
    let mut all = Vec::new();
    for axis in 0..3 {
        for k in [-6, -3, 3, 6, 9] {
            let x = 10f64.powi(k);
            all.push(match axis {
                0 => Units { length: x, ..SI },
                1 => Units { mass: x, ..SI },
                _ => Units { time: x, ..SI },
            });
        }
    }
    all.push(Units {
        length: 1e-3,
        mass: 1e3,
        time: 1e-3,
    });
    all.push(Units {
        length: 1e6,
        mass: 1e-6,
        time: 1e9,
    });
    all.push(Units {
        length: 1e9,
        mass: 1e-3,
        time: 1e6,
    });
    all
}

/// Units a rounding away from SI (1 ± 2⁻⁵⁰, 2⁻⁵⁰ ≈ 8.9e-16, a few ulps), in length, mass and time
/// in turn: the SI run's sensitivity to the rounding of its inputs, which every other system of
/// units changes by as much.
fn nudged() -> Vec<Units> {
    let mut all = Vec::new();
    for x in [1.0 + 2f64.powi(-50), 1.0 - 2f64.powi(-50)] {
        all.push(Units { length: x, ..SI });
        all.push(Units { mass: x, ..SI });
        all.push(Units { time: x, ..SI });
    }
    all
}

/// Units near SI, each of length, mass and time by 0.7, 0.9, 1.1 and 1.3 in turn: the same
/// physics with every rounding of the run moved (a factor 1 ± 2⁻⁵⁰ moves only some), where the
/// decisions an iteration to round-off makes on its last increment spread as they may in any
/// system of units.
fn near_si() -> Vec<Units> {
    let mut all = Vec::new();
    for x in [0.7, 0.9, 1.1, 1.3] {
        all.push(Units { length: x, ..SI });
        all.push(Units { mass: x, ..SI });
        all.push(Units { time: x, ..SI });
    }
    all
}

/// A mechanism declared in any units, with the dimensions of its coordinates and a start (SI).
pub struct Setup<'a, M: Mechanism<N>, const N: usize> {
    pub name: &'static str,
    pub make: &'a dyn Fn(&Units) -> M,
    pub coords: [Dim; N],
    /// (q, q̇) at t = 0, SI.
    pub start: [[f64; N]; 2],
    /// The fixed methods' step (SI) and number of steps.
    pub h: f64,
    pub steps: usize,
    /// The adaptive methods' span (SI).
    pub span: f64,
    /// A guess for `equilibrium` (SI), when the mechanism has one.
    pub equilibrium: Option<[f64; N]>,
    /// Whether the declaration has contacts (unilateral or friction rows): see [`adaptive`].
    pub contacts: bool,
}

/// d − T·n: the dimension of the n-th time derivative.
pub fn rate(d: Dim, n: i32) -> Dim {
    Dim {
        time: d.time - n,
        ..d
    }
}

impl<M: Mechanism<N>, const N: usize> Setup<'_, M, N> {
    /// √Mᵢᵢ at the SI start.
    pub fn weights(&self) -> Vec<f64> {
        let sys = (self.make)(&SI);
        let m = sys
            .mass_matrix(&self.state(&SI))
            .expect("mass matrix at the start");
        (0..N).map(|i| m[(i, i)].abs().sqrt()).collect()
    }

    /// The start in `u`.
    pub fn state(&self, u: &Units) -> State<M::Coords> {
        self.state_from(u, 0.0, &self.start[0], &self.start[1])
    }

    /// (t, q, q̇) given in SI, in `u`.
    pub fn state_from(&self, u: &Units, t: f64, q: &[f64; N], v: &[f64; N]) -> State<M::Coords> {
        let q: [f64; N] = std::array::from_fn(|i| u.express(q[i], self.coords[i]));
        let v: [f64; N] = std::array::from_fn(|i| u.express(v[i], rate(self.coords[i], 1)));
        State::new(
            u.express(t, TIME),
            M::Coords::from_array(q),
            M::Coords::from_array(v),
        )
    }

    /// A vector of the coordinates' n-th derivatives in `u`, in SI, with the weights for it.
    pub fn part(&self, u: &Units, x: &[f64; N], n: i32) -> Part {
        Part {
            values: (0..N)
                .map(|i| u.in_si(x[i], rate(self.coords[i], n)))
                .collect(),
            weights: self.weights(),
            floor: 0.0,
        }
    }

    /// A state in `u` as two parts (q and q̇), in SI, each measured against the start's size as
    /// well (a mechanism that comes to rest has q̇ = 0, where a difference relative to q̇ alone
    /// would be infinite).
    pub fn state_parts(&self, u: &Units, s: &State<M::Coords>) -> Vec<Part> {
        let weights = self.weights();
        let size = |x: &[f64; N]| (0..N).fold(0.0f64, |m, i| m.max(weights[i] * x[i].abs()));
        let mut q = self.part(u, &s.q.to_array(), 0);
        let mut v = self.part(u, &s.v.to_array(), 1);
        q.floor = size(&self.start[0]);
        v.floor = size(&self.start[1]);
        vec![q, v]
    }
}

/// An entry point's run in a system of units (`true`: the finer SI reference).
pub type Run<'a> = Box<dyn Fn(&Units, bool) -> Outcome + 'a>;

/// One entry point: a name, and the run in any units (`fine` asks for the SI reference that
/// measures the run's own error, where that is a finer run rather than a rounding).
pub struct Entry<'a> {
    pub name: &'static str,
    pub run: Run<'a>,
    /// Whether the own error is a finer run's difference (integrators) or the spread under a
    /// rounding of the inputs (direct evaluations).
    pub integrates: bool,
    /// Whether the run locates contact events: each is found to within
    /// `event_tolerance·(|t| + h)` ([`ContactOptions`]), relative in time, which a finer run
    /// does not refine, so that tolerance is a least own error of the run.
    pub events: bool,
}

/// The common entry points of any mechanism.
pub fn entries<'a, M: Mechanism<N>, const N: usize>(setup: &'a Setup<'a, M, N>) -> Vec<Entry<'a>> {
    let mut list = vec![Entry {
        name: "accelerations",
        integrates: false,
        events: false,
        run: Box::new(move |u, _| {
            let sys = (setup.make)(u);
            let a = sys.accelerations(&setup.state(u)).map_err(|e| kind(&e))?;
            Ok(Value {
                rounding_counts: Vec::new(),
                parts: vec![setup.part(u, &a.to_array(), 2)],
                counts: vec![],
            })
        }),
    }];
    list.push(fixed::<M, lagrange::Rk4, N>(setup, "RK4"));
    list.push(fixed::<M, lagrange::ImplicitMidpoint, N>(setup, "midpoint"));
    list.push(fixed::<M, lagrange::GaussLegendre2, N>(
        setup,
        "Gauss-Legendre 2",
    ));
    list.push(fixed::<M, lagrange::Variational, N>(setup, "variational"));
    list.push(fixed::<M, lagrange::StormerVerlet, N>(
        setup,
        "Stormer-Verlet",
    ));
    list.push(adaptive(setup, "Dopri5"));
    list.push(adaptive(setup, "Dop853"));
    list.push(adaptive(setup, "Radau5"));
    if let Some(guess) = setup.equilibrium {
        list.push(Entry {
            name: "equilibrium",
            integrates: false,
            events: false,
            run: Box::new(move |u, _| {
                let sys = (setup.make)(u);
                let q = M::Coords::from_array(std::array::from_fn(|i| {
                    u.express(guess[i], setup.coords[i])
                }));
                let eq = equilibrium(&sys, 0.0, &q, &EquilibriumOptions::default())
                    .map_err(|e| kind(&e))?;
                let mut q_si = setup.part(u, &eq.q.to_array(), 0);
                // q* may be 0: measured against the guess's size as well.
                let guess_si = setup.part(&SI, &guess, 0);
                q_si.floor = (0..N).fold(0.0f64, |m, i| {
                    m.max(guess_si.weights[i] * guess_si.values[i].abs())
                });
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts: vec![q_si],
                    counts: vec![eq.iterations],
                })
            }),
        });
        list.push(Entry {
            name: "normal modes",
            integrates: false,
            events: false,
            run: Box::new(move |u, _| {
                let sys = (setup.make)(u);
                let q = M::Coords::from_array(std::array::from_fn(|i| {
                    u.express(guess[i], setup.coords[i])
                }));
                let eq = equilibrium(&sys, 0.0, &q, &EquilibriumOptions::default())
                    .map_err(|e| kind(&e))?;
                let modes = normal_modes(&sys, 0.0, &eq.q).map_err(|e| kind(&e))?;
                let frequencies = Part {
                    values: modes
                        .frequencies
                        .iter()
                        .map(|w| u.in_si(*w, super::units::RATE))
                        .collect(),
                    weights: vec![1.0; N],
                    floor: 0.0,
                };
                // M-normalized shapes (shapeⱼᵀ M shapeₖ = δⱼₖ): √Mᵢᵢ·shapeᵢⱼ, with Mᵢᵢ in these
                // units, has no unit.
                let at_rest = State::new(0.0, eq.q, M::Coords::from_array([0.0; N]));
                let mass = sys.mass_matrix(&at_rest).map_err(|e| kind(&e))?;
                let mut shapes = Part {
                    values: Vec::new(),
                    weights: Vec::new(),
                    floor: 0.0,
                };
                for j in 0..N {
                    for i in 0..N {
                        shapes
                            .values
                            .push(mass[(i, i)].abs().sqrt() * modes.shapes[(i, j)]);
                        shapes.weights.push(1.0);
                    }
                }
                Ok(Value {
                    rounding_counts: Vec::new(),
                    parts: vec![frequencies, shapes],
                    counts: vec![],
                })
            }),
        });
    }
    list
}

/// A fixed-step method through its solver: `steps` steps of h (twice as many of h/2 for the
/// reference), the final state and the Newton counts.
fn fixed<'a, M: Mechanism<N>, I: Integrator + 'a, const N: usize>(
    setup: &'a Setup<'a, M, N>,
    name: &'static str,
) -> Entry<'a> {
    Entry {
        name,
        integrates: true,
        events: setup.contacts,
        run: Box::new(move |u, fine| {
            let sys = (setup.make)(u);
            let refine = if fine { 2 } else { 1 };
            let h = u.express(setup.h, TIME) / refine as f64;
            let mut solver =
                Stepper::new(&sys, I::with_step(h), &setup.state(u)).map_err(|e| kind(&e))?;
            for _ in 0..setup.steps * refine {
                // Steps of exactly h, never shortened to land on an end time.
                solver.step(f64::MAX).map_err(|e| kind(&e))?;
            }
            let st = solver.stats();
            Ok(Value {
                parts: setup.state_parts(u, &solver.state()),
                counts: vec![st.jacobians, st.factorizations],
                rounding_counts: vec![st.evaluations, st.newton_iterations],
            })
        }),
    }
}

/// An adaptive method over the span, rtol 1e-8 (1e-11 for the reference) and atol 1e-300: a
/// control relative to each component, which is what is the same in every system of units (a
/// scalar atol has no one unit for components of several), with the first step given (h).
///
/// A declaration with contacts holds components at zero (the normal coordinate and its rate on a
/// closed contact), where a relative control cannot be met: there atol is 1e-10 m, in the
/// length unit — every coordinate of those declarations is a length, so q and q̇ share it in the
/// systems that scale length or mass, and the entry is "n/a" in those that scale time, where q and
/// q̇ scale apart and no one number is atol for both.
fn adaptive<'a, M: Mechanism<N>, const N: usize>(
    setup: &'a Setup<'a, M, N>,
    name: &'static str,
) -> Entry<'a> {
    Entry {
        name,
        integrates: true,
        events: setup.contacts,
        run: Box::new(move |u, fine| {
            let sys = (setup.make)(u);
            let rtol = if fine { 1e-11 } else { 1e-8 };
            let atol = match (setup.contacts, u.time == 1.0) {
                (false, _) => 1e-300,
                (true, true) => u.express(1e-10, super::units::LENGTH),
                (true, false) => return Err(NOT_APPLICABLE.to_string()),
            };
            let h0 = Some(u.express(setup.h, TIME));
            let t_end = u.express(setup.span, TIME);
            let mut s = setup.state(u);
            let outcome = match name {
                "Dopri5" => sys.integrate(
                    Dopri5 {
                        h_init: h0,
                        ..Dopri5::new(rtol, atol)
                    },
                    &mut s,
                    t_end,
                    &mut [],
                    |_| {},
                ),
                "Dop853" => sys.integrate(
                    Dop853 {
                        h_init: h0,
                        ..Dop853::new(rtol, atol)
                    },
                    &mut s,
                    t_end,
                    &mut [],
                    |_| {},
                ),
                _ => sys.integrate(
                    Radau5 {
                        h_init: h0,
                        ..Radau5::new(rtol, atol)
                    },
                    &mut s,
                    t_end,
                    &mut [],
                    |_| {},
                ),
            }
            .map_err(|e| kind(&e))?;
            let st = outcome.stats;
            Ok(Value {
                rounding_counts: Vec::new(),
                parts: setup.state_parts(u, &s),
                counts: vec![
                    st.accepted,
                    st.rejected,
                    st.evaluations,
                    st.newton_iterations,
                    st.jacobians,
                    st.factorizations,
                ],
            })
        }),
    }
}

/// What an entry returns where it does not apply in a system of units (see [`adaptive`]).
pub const NOT_APPLICABLE: &str = "n/a";

/// One cell of the table: how an entry point did in one system of units.
#[derive(Clone, Debug)]
pub enum Cell {
    /// Not run in this system of units (see [`NOT_APPLICABLE`]).
    NotApplicable,
    /// Equal to the SI run to this multiple of its own error, with the same counts.
    Pass(f64),
    /// Refused as the SI run was.
    Refused,
    /// Different: the reason.
    Fail(String),
}

/// One entry point over every system of units.
pub struct Row {
    pub mechanism: &'static str,
    pub entry: &'static str,
    /// The SI run's own error (relative), or its refusal.
    pub own: Result<f64, String>,
    pub cells: Vec<(Units, Cell)>,
}

impl Row {
    pub fn failures(&self) -> Vec<String> {
        self.cells
            .iter()
            .filter_map(|(u, c)| match c {
                Cell::Fail(why) => Some(format!(
                    "{} / {} / {}: {why}",
                    self.mechanism,
                    self.entry,
                    u.label()
                )),
                _ => None,
            })
            .collect()
    }
}

/// The SI run's own error, and the range of its round-off counts (per count, the least and the
/// most) over the SI run, the runs with its inputs moved by a rounding and those in units near SI
/// ([`near_si`]).
type Own = Result<(f64, Vec<(usize, usize)>), String>;

/// Runs `entry` in SI, measures its own error, then in every system of units.
pub fn run_entry(mechanism: &'static str, entry: &Entry<'_>, systems: &[Units]) -> Row {
    let reference = (entry.run)(&SI, false);
    let own: Own = match &reference {
        Err(e) => Err(e.clone()),
        Ok(value) => {
            // 4ε: no result is resolved better than its own rounding; then its spread when the
            // inputs move by a rounding, and for an integrator its difference from a finer run.
            let mut own = 4.0 * f64::EPSILON;
            let mut range: Vec<(usize, usize)> =
                value.rounding_counts.iter().map(|&c| (c, c)).collect();
            let probes = if range.is_empty() { vec![] } else { near_si() };
            let nudges = nudged();
            for (k, u) in nudges.iter().chain(&probes).enumerate() {
                if let Ok(x) = (entry.run)(u, false) {
                    // Only a rounding's spread is the values' own error (a unit of 0.7 m rounds
                    // them as any other system does: it is what is tested).
                    if k < nudges.len() {
                        own = own.max(x.relative_error(value));
                    }
                    for (r, &c) in range.iter_mut().zip(&x.rounding_counts) {
                        *r = (r.0.min(c), r.1.max(c));
                    }
                }
            }
            if entry.integrates {
                if let Ok(fine) = (entry.run)(&SI, true) {
                    own = own.max(value.relative_error(&fine));
                }
            }
            if entry.events {
                own = own.max(ContactOptions::default().event_tolerance);
            }
            Ok((own, range))
        }
    };
    let cells = systems
        .iter()
        .map(|u| {
            let outcome = (entry.run)(u, false);
            let cell = match (&reference, &outcome, &own) {
                (_, Err(b), _) if b == NOT_APPLICABLE => Cell::NotApplicable,
                (Err(a), Err(b), _) if a == b => Cell::Refused,
                (Err(a), Err(b), _) => Cell::Fail(format!("refused with {b}, SI with {a}")),
                (Err(a), Ok(_), _) => Cell::Fail(format!("ran, SI refused with {a}")),
                (Ok(_), Err(b), _) => Cell::Fail(format!("refused with {b}, SI ran")),
                (Ok(r), Ok(x), Ok((own, range))) => {
                    let within = x
                        .rounding_counts
                        .iter()
                        .zip(range)
                        .all(|(c, (least, most))| (least..=most).contains(&c));
                    if x.counts != r.counts {
                        Cell::Fail(format!("counts {:?}, SI {:?}", x.counts, r.counts))
                    } else if !within {
                        Cell::Fail(format!(
                            "iterations {:?}, SI {range:?} under roundings (units near SI)",
                            x.rounding_counts
                        ))
                    } else {
                        let ratio = x.relative_error(r) / own;
                        if ratio <= 10.0 {
                            Cell::Pass(ratio)
                        } else {
                            Cell::Fail(format!(
                                "relative error {:.1e}, {ratio:.0} times the SI run's own {own:.1e}",
                                x.relative_error(r)
                            ))
                        }
                    }
                }
                (Ok(_), Ok(_), Err(_)) => unreachable!("an own error for every run"),
            };
            (*u, cell)
        })
        .collect();
    Row {
        mechanism,
        entry: entry.name,
        own: own.map(|(e, _)| e),
        cells,
    }
}

/// The rows of one mechanism as a table: one line per entry point, one column per system of
/// units; a cell is the error over the SI run's own error ("0.3"), "R" for a refusal the SI run
/// made too, "FAIL" otherwise.
pub fn table(rows: &[Row]) -> String {
    let mut out = String::new();
    let Some(first) = rows.first() else {
        return out;
    };
    out.push_str(&format!("{:<16} {:<17} {:>8}", "mechanism", "entry", "own"));
    for (u, _) in &first.cells {
        out.push_str(&format!(" {:>9}", short(u)));
    }
    out.push('\n');
    for row in rows {
        let own = match &row.own {
            Ok(e) => format!("{e:.0e}"),
            Err(_) => "refused".to_string(),
        };
        out.push_str(&format!(
            "{:<16} {:<17} {:>8}",
            row.mechanism, row.entry, own
        ));
        for (_, c) in &row.cells {
            let text = match c {
                Cell::Pass(r) => format!("{r:.1}"),
                Cell::Refused => "R".to_string(),
                Cell::NotApplicable => NOT_APPLICABLE.to_string(),
                Cell::Fail(_) => "FAIL".to_string(),
            };
            out.push_str(&format!(" {text:>9}"));
        }
        out.push('\n');
    }
    out
}

/// "L-6", "M9", "T3", or "X" and the exponents of a mixed system ("X-3+3-3"): a column heading.
fn short(u: &Units) -> String {
    let exp = |x: f64| x.log10().round() as i32;
    match (u.length != 1.0, u.mass != 1.0, u.time != 1.0) {
        (true, false, false) => format!("L{}", exp(u.length)),
        (false, true, false) => format!("M{}", exp(u.mass)),
        (false, false, true) => format!("T{}", exp(u.time)),
        _ => format!("X{:+}{:+}{:+}", exp(u.length), exp(u.mass), exp(u.time)),
    }
}
