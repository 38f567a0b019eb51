//! The globalization shared by the equilibrium searches: a descent direction for the merit
//! function ½‖r‖² of a residual r(z) = 0, and a backtracking line search along it.

use nalgebra::{allocator::Allocator, DefaultAllocator, Dim, OVector};

/// Armijo's sufficient-decrease constant (Nocedal & Wright, *Numerical Optimization*, 2nd ed.,
/// §3.1: "c₁ is chosen to be quite small, say c₁ = 10⁻⁴").
const ARMIJO: f64 = 1e-4;
/// Backtracking contraction factor ρ (Nocedal & Wright, Alg. 3.1).
const BACKTRACK: f64 = 0.5;
/// Smallest step length tried before the line search gives up (2⁻⁴⁰ ≈ 1e-12 of the Newton step).
const MIN_STEP: f64 = 1e-12;

/// The search direction p for ½‖r‖², its slope ∇(½‖r‖²)·p and whether it is the Newton step, from
/// the Newton step `newton` (J p = −r; `None` where J is singular or p not finite), the merit's
/// gradient `grad` = Jᵀr and ‖r‖²: the Newton step when it descends, otherwise steepest descent
/// scaled so its length is comparable to a Newton step for a Jacobian of the same size
/// (‖J‖ ‖p‖ ≈ ‖r‖). `None` where the gradient vanishes: a stationary point of ½‖r‖² that is not
/// a root.
pub(super) fn descent_direction<D: Dim>(
    newton: Option<OVector<f64, D>>,
    grad: &OVector<f64, D>,
    residual_norm_squared: f64,
) -> Option<(OVector<f64, D>, f64, bool)>
where
    DefaultAllocator: Allocator<D>,
{
    match newton {
        Some(p) if grad.dot(&p) < 0.0 => {
            let slope = grad.dot(&p);
            Some((p, slope, true))
        }
        _ => {
            let g2 = grad.norm_squared();
            if g2 == 0.0 {
                return None;
            }
            let p = -grad * (residual_norm_squared / g2);
            let slope = grad.dot(&p);
            Some((p, slope, false))
        }
    }
}

/// Backtracking line search on ½‖r‖² (Nocedal & Wright, Alg. 3.1): the point `trial(α)` gives
/// with its residual r for the first of α = 1, ½, ¼, … at which r is finite and Armijo's
/// condition ½‖r‖² ≤ `merit` + c₁ α `slope` holds; `None` once α falls below [`MIN_STEP`].
pub(super) fn backtrack<T, D: Dim>(
    merit: f64,
    slope: f64,
    mut trial: impl FnMut(f64) -> (T, OVector<f64, D>),
) -> Option<T>
where
    DefaultAllocator: Allocator<D>,
{
    let mut alpha = 1.0;
    loop {
        let (point, r) = trial(alpha);
        if r.iter().all(|x| x.is_finite())
            && 0.5 * r.norm_squared() <= merit + ARMIJO * alpha * slope
        {
            return Some(point);
        }
        alpha *= BACKTRACK;
        if alpha < MIN_STEP {
            return None;
        }
    }
}
