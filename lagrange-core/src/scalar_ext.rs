//! The `f64` methods [`DualNum`](num_dual::DualNum) does not have, on every [`Scalar`]: what a
//! declaration's function bodies may call on coordinates as they would on `f64`
//! (`theta.cos().max(0.0)`, `x.hypot(y)`, `a.clamp(-1.0, 1.0)`).
//!
//! On `f64` itself the inherent methods are found first, so nothing changes there. On a dual
//! number the piecewise functions follow the branch taken by the real part, with its derivative
//! (`max(a, b)` is `a` or `b` with its derivatives); `floor`-like functions are constant between
//! their jumps, with zero derivative.

use crate::geometry::Scalar;

/// `f64` methods on any [`Scalar`]. The other operand may be an `f64` or the scalar itself.
pub trait ScalarExt: Scalar {
    /// The larger of `self` and `other`, by real part; NaN loses, as for `f64::max`.
    fn max(self, other: impl Into<Self>) -> Self {
        let other = other.into();
        if self.re().is_nan() || other.re() > self.re() {
            other
        } else {
            self
        }
    }
    /// The smaller of `self` and `other`, by real part; NaN loses, as for `f64::min`.
    fn min(self, other: impl Into<Self>) -> Self {
        let other = other.into();
        if self.re().is_nan() || other.re() < self.re() {
            other
        } else {
            self
        }
    }
    /// `self` limited to `[lo, hi]`, by real part.
    fn clamp(self, lo: impl Into<Self>, hi: impl Into<Self>) -> Self {
        let (lo, hi) = (lo.into(), hi.into());
        if self.re() < lo.re() {
            lo
        } else if self.re() > hi.re() {
            hi
        } else {
            self
        }
    }
    /// √(self² + other²).
    fn hypot(self, other: impl Into<Self>) -> Self {
        let other = other.into();
        (self * self + other * other).sqrt()
    }
    /// Radians to degrees.
    fn to_degrees(self) -> Self {
        self * (180.0 / core::f64::consts::PI)
    }
    /// Degrees to radians.
    fn to_radians(self) -> Self {
        self * (core::f64::consts::PI / 180.0)
    }
    /// The largest integer ≤ `self` (zero derivative).
    fn floor(self) -> Self {
        Self::from(self.re().floor())
    }
    /// The smallest integer ≥ `self` (zero derivative).
    fn ceil(self) -> Self {
        Self::from(self.re().ceil())
    }
    /// The nearest integer, half away from zero (zero derivative).
    fn round(self) -> Self {
        Self::from(self.re().round())
    }
    /// The integer part (zero derivative).
    fn trunc(self) -> Self {
        Self::from(self.re().trunc())
    }
    /// `self` raised to an exponent that is an `f64` or a scalar: `powf` with a constant
    /// exponent, and the exponent's own derivative `ln(self) · self^e` where it has one (a
    /// positive base).
    fn pow_scalar(self, exponent: impl Into<Self>) -> Self {
        let e = exponent.into();
        let e0 = e.re();
        let constant = self.powf(e0);
        if self.re() > 0.0 {
            constant * ((e - Self::from(e0)) * self.ln()).exp()
        } else {
            constant
        }
    }
}

impl<D: Scalar> ScalarExt for D {}

/// A function from outside a declaration's module called from one of its function bodies
/// (`super::arm(theta)`), whose signature the macro cannot see: the call is made through
/// [`call_helper`], with the function as a function pointer, which implements this trait for the
/// arguments' types when it takes them. A function that takes `f64` where the body passes the
/// scalar — a dual number: the bodies are evaluated on them to differentiate them — does not, and
/// rustc says so once, at the call, in these words rather than as type mismatches on the
/// generated scalar type.
#[diagnostic::on_unimplemented(
    message = "`{Self}` does not take the scalar a mechanism's functions run on",
    label = "called from a mechanism's function, whose values are dual numbers (that is how they are differentiated)",
    note = "make the helper generic, `fn f<D: lagrange::Scalar>(x: D) -> D`, or write its expression inline"
)]
pub trait ScalarHelper<Args> {
    /// What the function returns.
    type Output;
    /// Calls the function with the arguments of the tuple.
    fn call_with(self, args: Args) -> Self::Output;
}

/// `f(args…)` through [`ScalarHelper`]: the arguments first, so that their types, not the
/// function's signature, decide which implementation is asked for.
///
/// ```
/// use lagrange_core::scalar_ext::call_helper;
/// use lagrange_core::Scalar;
/// use num_dual::Dual64;
/// fn arm<D: Scalar>(angle: D) -> D {
///     angle.sin()
/// }
/// let x = Dual64::from(0.5).derivative();
/// let helper: fn(_) -> _ = arm;
/// assert_eq!(call_helper((x,), helper).eps, 0.5f64.cos());
/// ```
#[inline(always)]
pub fn call_helper<Args, F: ScalarHelper<Args>>(args: Args, f: F) -> F::Output {
    f.call_with(args)
}

macro_rules! scalar_helper {
    ($($arg:ident),*) => {
        impl<R, $($arg),*> ScalarHelper<($($arg,)*)> for fn($($arg),*) -> R {
            type Output = R;
            #[inline(always)]
            #[allow(non_snake_case)]
            fn call_with(self, ($($arg,)*): ($($arg,)*)) -> R {
                self($($arg),*)
            }
        }
    };
}

scalar_helper!();
scalar_helper!(A);
scalar_helper!(A, B);
scalar_helper!(A, B, C);
scalar_helper!(A, B, C, E);
scalar_helper!(A, B, C, E, G);
scalar_helper!(A, B, C, E, G, H);
scalar_helper!(A, B, C, E, G, H, I);
scalar_helper!(A, B, C, E, G, H, I, J);

#[cfg(test)]
mod tests {
    use super::ScalarExt;
    use num_dual::Dual64;

    #[test]
    fn branches_carry_their_derivatives() {
        let x = Dual64::from(0.5).derivative();
        assert_eq!(ScalarExt::max(x, 0.0).eps, 1.0);
        assert_eq!(ScalarExt::max(x, 2.0).eps, 0.0);
        assert_eq!(ScalarExt::min(x, 2.0).eps, 1.0);
        assert_eq!(ScalarExt::clamp(x, -1.0, 0.25).re, 0.25);
        let h = ScalarExt::hypot(x, 1.2);
        assert!((h.re - 1.3).abs() < 1e-15 && (h.eps - 0.5 / 1.3).abs() < 1e-15);
        // d/dx x^x = x^x (ln x + 1).
        let p = x.pow_scalar(x);
        assert!((p.eps - 0.5f64.powf(0.5) * (0.5f64.ln() + 1.0)).abs() < 1e-14);
        assert_eq!(x.pow_scalar(2.0).eps, 1.0);
        assert_eq!(ScalarExt::floor(x).eps, 0.0);
    }
}
