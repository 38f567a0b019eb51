//! SVG plots of the report (plotters), drawn on log₁₀ axes.

use crate::kepler::{kepler, KEPLER};
use crate::problems::kepler_start;
use crate::setup::in_coordinates;
use crate::sweep::Row;
use lagrange_core::integrate::{Observation, Stepper};
use lagrange_core::{
    Dopri5, GaussLegendre2, ImplicitMidpoint, Integrator, Mechanism, Rk4, State, StormerVerlet,
    Variational,
};
use plotters::prelude::*;
use std::path::Path;

const COLOURS: [RGBColor; 12] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
    RGBColor(140, 86, 75),
    RGBColor(127, 127, 127),
    RGBColor(188, 189, 34),
    RGBColor(227, 119, 194),
    RGBColor(0, 0, 0),
    RGBColor(174, 199, 232),
];

/// File-name form of a problem name.
pub fn slug(problem: &str) -> String {
    problem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() {
                c.to_ascii_lowercase()
            } else {
                '-'
            }
        })
        .collect()
}

/// Lines of (x, y) points, already in log₁₀.
fn lines(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[(String, Vec<(f64, f64)>)],
    markers: bool,
) {
    let pts = || {
        series
            .iter()
            .flat_map(|s| s.1.iter())
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    };
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in pts() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if x0 > x1 {
        eprintln!("{}: nothing to plot", path.display());
        return;
    }
    let (px, py) = (0.05 * (x1 - x0).max(0.1), 0.05 * (y1 - y0).max(0.1));
    let root = SVGBackend::new(path, (900, 560)).into_drawing_area();
    let result = (|| -> Result<(), Box<dyn std::error::Error + '_>> {
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d((x0 - px)..(x1 + px), (y0 - py)..(y1 + py))?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .draw()?;
        for (i, (label, points)) in series.iter().enumerate() {
            let colour = COLOURS[i % COLOURS.len()];
            let finite: Vec<(f64, f64)> = points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            chart
                .draw_series(LineSeries::new(finite.clone(), colour.stroke_width(2)))?
                .label(label.clone())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
            if markers {
                chart.draw_series(finite.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
        Ok(())
    })();
    if let Err(e) = result {
        eprintln!("{}: {e}", path.display());
    }
}

/// End-point error against wall time, log–log, one line per method.
pub fn work_precision(dir: &Path, problem: &str, rows: &[Row]) {
    let mut methods: Vec<&str> = Vec::new();
    for r in rows.iter().filter(|r| r.problem == problem) {
        if !methods.contains(&r.method.as_str()) {
            methods.push(&r.method);
        }
    }
    let series: Vec<(String, Vec<(f64, f64)>)> = methods
        .iter()
        .map(|m| {
            let pts = rows
                .iter()
                .filter(|r| {
                    r.problem == problem && r.method == *m && r.status == "ok" && r.end_error > 0.0
                })
                .map(|r| (r.seconds.log10(), r.end_error.log10()))
                .collect();
            (m.to_string(), pts)
        })
        .collect();
    lines(
        &dir.join(format!("{}.svg", slug(problem))),
        &format!("{problem}: end-point error vs wall time"),
        "log10 wall time [s]",
        "log10 end-point error",
        &series,
        true,
    );
}

/// |E − E₀| sampled once per period on Kepler e = 0.6 with 200 steps per period (fixed-step
/// methods) and Dopri5 at tol 1e-8.
pub fn kepler_long_run(periods: usize) -> Vec<(String, Vec<(f64, f64)>)> {
    fn kepler_state() -> State<kepler::Coords> {
        in_coordinates::<kepler::Kepler, 2>(&kepler_start())
    }
    let per = 200;
    let h = 2.0 * std::f64::consts::PI / per as f64;
    fn fixed<I: Integrator>(periods: usize, per: usize, h: f64) -> Vec<(f64, f64)> {
        let mut s = kepler_state();
        let e0 = KEPLER.energy(&s).unwrap();
        let mut out = Vec::new();
        let mut steps = 0;
        // One run, the method's working memory kept from step to step (as a solver keeps it); a
        // method that fails ends its series there.
        let _ = KEPLER.simulate::<I>(&mut s, h, periods * per, |s| {
            steps += 1;
            if steps % per == 0 {
                out.push((s.t, (KEPLER.energy(s).unwrap() - e0).abs()));
            }
        });
        out
    }
    let mut series = vec![
        (Rk4::NAME.to_string(), fixed::<Rk4>(periods, per, h)),
        (
            ImplicitMidpoint::NAME.to_string(),
            fixed::<ImplicitMidpoint>(periods, per, h),
        ),
        (
            GaussLegendre2::NAME.to_string(),
            fixed::<GaussLegendre2>(periods, per, h),
        ),
        (
            Variational::NAME.to_string(),
            fixed::<Variational>(periods, per, h),
        ),
        (
            StormerVerlet::NAME.to_string(),
            fixed::<StormerVerlet>(periods, per, h),
        ),
    ];
    let s = kepler_state();
    let e0 = KEPLER.energy(&s).unwrap();
    let mut pts = Vec::new();
    let mut next = 2.0 * std::f64::consts::PI;
    let t_end = periods as f64 * 2.0 * std::f64::consts::PI;
    let mut solver = Stepper::new(&KEPLER, Dopri5::new(1e-8, 1e-8), &s).expect("start");
    let _ = solver.integrate(t_end, &mut [], |o| {
        if let Observation::Step { state, .. } = o {
            if state.t >= next {
                pts.push((state.t, (KEPLER.energy(state).unwrap() - e0).abs()));
                next += 2.0 * std::f64::consts::PI;
            }
        }
    });
    series.push(("Dopri5 tol 1e-8".into(), pts));
    series
}

pub fn energy_long_run(dir: &Path, series: &[(String, Vec<(f64, f64)>)]) {
    let logged: Vec<(String, Vec<(f64, f64)>)> = series
        .iter()
        .map(|(n, pts)| {
            (
                n.clone(),
                pts.iter()
                    .filter(|p| p.1 > 0.0)
                    .map(|&(t, e)| (t.log10(), e.log10()))
                    .collect(),
            )
        })
        .collect();
    lines(
        &dir.join("kepler-energy-long-run.svg"),
        "Kepler e = 0.6: energy error over the run (200 steps per period)",
        "log10 t",
        "log10 |E - E0|",
        &logged,
        false,
    );
}
