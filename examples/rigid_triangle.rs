//! The lecture's example 3, a rigid body made of particles: three point masses held at fixed
//! offsets from a pivot swing as a physical pendulum. The same body declared as one planar rigid
//! body — total mass M at the centre of mass c, moment of inertia I_c = Σ mᵢ|sᵢ − c|² about it —
//! moves identically, because a rigid body's kinetic energy depends only on M, c and I_c.
//!
//! Closed form: with V = M g (c rotated by θ)_y,
//!   θ̈ = −M g (c_x cos θ − c_y sin θ) / (I_c + M|c|²).
//!
//! ```text
//! cargo run --release --example rigid_triangle
//! ```
//!
//! The gallery's scene `lagrange_gallery::scenes::rigid_triangle` checks both declarations' θ̈
//! against the closed form and their motions against each other over 5 s.

use lagrange::prelude::*;
use lagrange_gallery::plot::{self, Series};

use lagrange_gallery::scenes::rigid_triangle::three_particles;

use lagrange_gallery::scenes::rigid_triangle::lamina;

fn main() -> Result<(), lagrange::Error> {
    let particles = three_particles::ThreeParticles {
        m1: 1.0,
        m2: 2.0,
        m3: 1.5,
        x1: 0.0,
        y1: -1.0,
        x2: 0.5,
        y2: -1.5,
        x3: -0.3,
        y3: -1.2,
        g: 9.81,
    };
    let p = &particles;
    // M, c = Σ mᵢ sᵢ / M, and I_c = Σ mᵢ|sᵢ|² − M|c|² (parallel axes).
    let list = [(p.m1, p.x1, p.y1), (p.m2, p.x2, p.y2), (p.m3, p.x3, p.y3)];
    let mass: f64 = list.iter().map(|&(m, _, _)| m).sum();
    let (mut cx, mut cy, mut about_pivot) = (0.0, 0.0, 0.0);
    for (m, x, y) in list {
        cx += m * x / mass;
        cy += m * y / mass;
        about_pivot += m * (x * x + y * y);
    }
    let inertia = about_pivot - mass * (cx * cx + cy * cy);
    let g = p.g;
    let body = lamina::Lamina {
        mass,
        inertia,
        cx,
        cy,
        g,
    };

    let theta0: f64 = 1.2;
    let mut a = three_particles::State::at_rest(three_particles::Coords { theta: theta0 });
    let mut b = lamina::State::at_rest(lamina::Coords { theta: theta0 });
    let closed_form = -mass * g * (cx * theta0.cos() - cy * theta0.sin()) / about_pivot;
    println!(
        "θ̈ three particles {:.12}",
        particles.accelerations(&a)?.theta
    );
    println!("θ̈ one rigid body  {:.12}", body.accelerations(&b)?.theta);
    println!("θ̈ closed form     {closed_form:.12}");
    println!("   t (s)   θ, particles     θ, rigid body");
    let (mut trace_a, mut trace_b) = (Vec::new(), Vec::new());
    for step in 1..=5000 {
        particles.step::<Rk4>(&mut a, 1e-3)?;
        body.step::<Rk4>(&mut b, 1e-3)?;
        trace_a.push((a.t, a.q.theta));
        trace_b.push((b.t, b.q.theta));
        if step % 1000 == 0 {
            println!("{:8.2} {:16.12} {:16.12}", a.t, a.q.theta, b.q.theta);
        }
    }
    let plots = lagrange_gallery::plots_dir();
    plot::lines(
        &plots.join("rigid_triangle_example.svg"),
        "Three particles and the equivalent rigid body: θ(t)",
        "t",
        "θ",
        &[
            Series::new("three particles", trace_a),
            Series::new("one planar rigid body", trace_b),
        ],
    )
    .map_err(|e| eprintln!("{e}"))
    .ok();
    Ok(())
}
