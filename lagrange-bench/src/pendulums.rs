//! The report's pendulum and double pendulum: the gallery's `#[mechanism]` declarations, with unit
//! masses and lengths and g = 1 (the macro derives their equations in closed form).

pub use lagrange_gallery::scenes::double_pendulum::double_pendulum;
pub use lagrange_gallery::scenes::pendulum::pendulum;

/// q̈ = −sin q.
pub const PENDULUM: pendulum::Pendulum = pendulum::Pendulum {
    m: 1.0,
    l: 1.0,
    g: 1.0,
};

/// m₁ = m₂ = l₁ = l₂ = g = 1.
pub const DOUBLE_PENDULUM: double_pendulum::DoublePendulum = double_pendulum::DoublePendulum {
    m1: 1.0,
    m2: 1.0,
    l1: 1.0,
    l2: 1.0,
    g: 1.0,
};
