//! SVG line plots with plotters.

use plotters::prelude::*;
use std::path::Path;

/// One named line.
pub struct Series {
    /// The legend entry.
    pub label: String,
    /// The line's points (x, y), drawn in this order.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A line named `label` through `points`.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Series {
            label: label.into(),
            points,
        }
    }
}

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// Writes an SVG line plot of `series` to `path`. Axis ranges cover every finite point.
pub fn lines(
    path: &Path,
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
) -> Result<(), String> {
    let finite = || {
        series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|(x, y)| x.is_finite() && y.is_finite())
    };
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in finite() {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    if x0 > x1 {
        return Err(format!("{}: nothing finite to plot", path.display()));
    }
    let pad = |a: f64, b: f64| {
        if b - a > 0.0 {
            0.05 * (b - a)
        } else {
            0.5 * a.abs().max(1e-12)
        }
    };
    let (px, py) = (pad(x0, x1), pad(y0, y1));
    let root = SVGBackend::new(path, (800, 500)).into_drawing_area();
    let err = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    root.fill(&WHITE).map_err(|e| err(&e))?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d((x0 - px)..(x1 + px), (y0 - py)..(y1 + py))
        .map_err(|e| err(&e))?;
    chart
        .configure_mesh()
        .x_desc(x_label)
        .y_desc(y_label)
        .x_label_formatter(&|v| tick(*v, x0.abs().max(x1.abs())))
        .y_label_formatter(&|v| tick(*v, y0.abs().max(y1.abs())))
        .draw()
        .map_err(|e| err(&e))?;
    for (i, s) in series.iter().enumerate() {
        let colour = COLOURS[i % COLOURS.len()];
        chart
            .draw_series(LineSeries::new(
                s.points
                    .iter()
                    .copied()
                    .filter(|(x, y)| x.is_finite() && y.is_finite()),
                colour.stroke_width(2),
            ))
            .map_err(|e| err(&e))?
            .label(s.label.clone())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(|e| err(&e))?;
    root.present().map_err(|e| err(&e))?;
    Ok(())
}

/// A tick label: plain for magnitudes a person reads at a glance, scientific for tiny or huge ones
/// (energy errors of 1e-9 would otherwise all print as "0.0").
fn tick(value: f64, magnitude: f64) -> String {
    // A tick at zero computed as a difference of bounds is round-off: print it as 0.
    let value = if value.abs() < 1e-9 * magnitude {
        0.0
    } else {
        value
    };
    if magnitude != 0.0 && !(1e-2..1e5).contains(&magnitude) {
        format!("{value:.1e}")
    } else {
        format!("{value:.2}")
    }
}
