//! [`impl_mechanism!`](crate::impl_mechanism): the glue `#[mechanism]` generates, for models
//! written by hand.

/// Implements [`Mechanism`](crate::Mechanism) for a hand-written [`Model`](crate::Model) with `N` coordinates and `K`
/// Cartesian coordinates, forwarding every method to [`crate::dynamics`]: the same glue
/// `#[mechanism]` generates, for models written by hand (tests, benchmarks, peers).
///
/// ```
/// use lagrange_core::{impl_mechanism, vec2, Mechanism, Model, Scalar, State};
///
/// /// A pendulum of unit mass and length, written by hand.
/// struct Pendulum;
///
/// impl Model<1, 2> for Pendulum {
///     type Coords = [f64; 1];
///     const RHEONOMIC: bool = false;
///     const HAS_POTENTIAL: bool = true;
///     const HAS_FORCES: bool = false;
///     fn validate(&self) -> lagrange_core::Result<()> { Ok(()) }
///     fn masses(&self) -> [f64; 2] { [1.0, 1.0] }
///     fn cartesian<D: Scalar>(&self, _t: D, q: &[D; 1]) -> [D; 2] {
///         vec2(q[0].sin(), -q[0].cos()).to_array()
///     }
///     fn potential<D: Scalar>(&self, _t: D, _q: &[D; 1], x: &[D; 2]) -> D { x[1] * 9.81 }
/// }
/// impl_mechanism!(Pendulum, 1, 2);
///
/// let a = Pendulum.accelerations(&State::at_rest([0.5])).unwrap();
/// assert!((a[0] + 9.81 * 0.5f64.sin()).abs() < 1e-14);
/// ```
///
/// `impl_mechanism!(Type, N, K, constraints)` is the same for a model that also implements
/// [`Constraints`](crate::constraints::Constraints): accelerations solve the constrained system,
/// integrators project after every step and refuse inconsistent states.
///
/// `impl_mechanism!(Type, N, K, inputs NU)` is for a model without constraints whose forces read
/// `NU` inputs: it implements [`ActuatedModel`](crate::inputs::ActuatedModel) and
/// [`Actuated`](crate::inputs::Actuated) too, and every evaluation reads the inputs a
/// [`Driven`](crate::inputs::Driven) holds (zeros without).
///
/// `impl_mechanism!(Type, N, K, affine)` is for a model without constraints whose x is affine in
/// q with constant coefficients and independent of t (x = A q + c; [`crate::affine`]): its
/// [`Validated`](crate::Validated) handle computes J = A and the factorisation of the constant
/// mass matrix once. The model promises it; a position that is not affine gives wrong
/// accelerations through the handle.
#[macro_export]
macro_rules! impl_mechanism {
    ($ty:ty, $n:tt, $k:tt, constraints) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, none, {
            type Contacts = $crate::constraints::ContactState<$k, {
                use $crate::constraints::Constraints as _;
                $crate::constraints::row_count(&<$ty>::NAMES)
            }>;
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> = {
                use $crate::constraints::Constraints as _;
                Some($crate::constraints::ConstraintCounts::of(&<$ty>::KINDS))
            };
            fn holonomic_constraints_at<S: $crate::Scalar>(&self, t: S, q: &[S; $n]) -> Option<[S; $n]> {
                Some($crate::constraints::holonomic_values(self, t, q))
            }
            fn accelerations_at<S: $crate::Scalar>(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> $crate::Result<[S; $n]> {
                $crate::constraints::accelerations(self, t, q, v)
            }
            fn project(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: f64,
                q: &mut [f64; $n],
                v: &mut [f64; $n],
            ) -> $crate::Result<()> {
                let mode = $crate::constraints::infer_mode(self, t, q, v)?;
                $crate::constraints::project(self, t, q, v, &mode)
            }
            fn check_declaration_at(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> $crate::Result<()> {
                $crate::constraints::check_velocity_rows_affine(self, t, q, v)
            }
            fn check_constraints(&self, t: f64, q: &[f64; $n], v: &[f64; $n]) -> $crate::Result<()> {
                $crate::constraints::check_consistent(
                    self,
                    t,
                    q,
                    v,
                    $crate::constraints::CONSISTENCY_TOLERANCE,
                )
            }
        });
        $crate::impl_mechanism!(@prepare_nothing $ty);
    };
    ($ty:ty, $n:tt, $k:tt, affine) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, none, {
            type Contacts = $crate::constraints::NoContacts;
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> =
                Some($crate::constraints::ConstraintCounts::NONE);
            fn accelerations_at<S: $crate::Scalar>(
                &self,
                constants: $crate::evaluation::Constants<'_, Self>,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> $crate::Result<[S; $n]> {
                match constants.prepared {
                    Some(prepared) => {
                        $crate::affine::accelerations::<$ty, S, $n, $k>(self, prepared, t, q, v)
                    }
                    None => $crate::dynamics::accelerations_generic::<$ty, S, $n, $k>(self, t, q, v),
                }
            }
        });
        impl $crate::evaluation::Prepare for $ty {
            type Prepared = $crate::affine::AffineConstants<$n, $k>;
            fn prepare(&self) -> $crate::Result<Self::Prepared> {
                $crate::affine::AffineConstants::of::<$ty>(self)
            }
        }
    };
    ($ty:ty, $n:tt, $k:tt) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, none, {
            type Contacts = $crate::constraints::NoContacts;
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> =
                Some($crate::constraints::ConstraintCounts::NONE);
        });
        $crate::impl_mechanism!(@prepare_nothing $ty);
    };
    ($ty:ty, $n:tt, $k:tt, inputs $nu:tt) => {
        $crate::impl_mechanism!(@impl $ty, $n, $k, [inputs $nu], {
            type Contacts = $crate::constraints::NoContacts;
            const CONSTRAINT_COUNTS: Option<$crate::constraints::ConstraintCounts> =
                Some($crate::constraints::ConstraintCounts::NONE);
        });
        $crate::impl_mechanism!(@prepare_nothing $ty);
    };
    // M, 𝓕 and b: of the model, or of the model with the inputs its constants hold.
    (@equations $ty:ty, $n:tt, $k:tt, none) => {
        fn equations_of_motion_at<S: $crate::Scalar>(
            &self,
            _constants: $crate::evaluation::Constants<'_, Self>,
            t: S,
            q: &[S; $n],
            v: &[S; $n],
        ) -> $crate::dynamics::EquationsOfMotion<S, $n> {
            $crate::dynamics::equations_of_motion::<$ty, S, $n, $k>(self, t, q, v)
        }
    };
    (@equations $ty:ty, $n:tt, $k:tt, [inputs $nu:tt]) => {
        fn equations_of_motion_at<S: $crate::Scalar>(
            &self,
            constants: $crate::evaluation::Constants<'_, Self>,
            t: S,
            q: &[S; $n],
            v: &[S; $n],
        ) -> $crate::dynamics::EquationsOfMotion<S, $n> {
            let held = $crate::inputs::WithInputs::<$ty, f64, $nu>::held(self, constants.inputs);
            $crate::dynamics::equations_of_motion::<_, S, $n, $k>(&held, t, q, v)
        }
        const INPUT_NAMES: &'static [&'static str] = &<<$ty as $crate::inputs::Actuated<$nu>>::Inputs as $crate::inputs::Inputs<$nu>>::NAMES;
        fn accelerations_with_inputs_at<S: $crate::Scalar>(
            &self,
            inputs: &[S],
            t: S,
            q: &[S; $n],
            v: &[S; $n],
        ) -> $crate::Result<[S; $n]> {
            let held = $crate::inputs::WithInputs::<$ty, S, $nu>::held(self, inputs);
            $crate::dynamics::accelerations_generic::<_, S, $n, $k>(&held, t, q, v)
        }
    };
    (@prepare_nothing $ty:ty) => {
        impl $crate::evaluation::Prepare for $ty {
            type Prepared = ();
            fn prepare(&self) -> $crate::Result<()> {
                Ok(())
            }
        }
    };
    (@impl $ty:ty, $n:tt, $k:tt, $inputs:tt, { $($extra:tt)* }) => {
        // A hand-written model reads no parameter through an array: there is nothing to seed.
        impl $crate::parameters::Parametrized<$n, $k, 0> for $ty {
            const PARAMETER_NAMES: [&'static str; 0] = [];
            const SEEDABLE: [bool; 0] = [];
            fn parameters(&self) -> [f64; 0] {
                []
            }
            fn cartesian_with<S: $crate::Scalar, D: $crate::Scalar>(
                &self,
                _p: &[S; 0],
                t: D,
                q: &[D; $n],
            ) -> [D; $k] {
                <$ty as $crate::Model<$n, $k>>::cartesian(self, t, q)
            }
        }
        impl $crate::evaluation::Dynamics<$n> for $ty {
            type Coords = <$ty as $crate::Model<$n, $k>>::Coords;
            fn check_parameters(&self) -> $crate::Result<()> {
                <$ty as $crate::Model<$n, $k>>::validate(self)
            }
            $crate::impl_mechanism!(@equations $ty, $n, $k, $inputs);
            fn kinetic_energy_at<S: $crate::Scalar>(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> S {
                $crate::dynamics::kinetic_energy::<$ty, S, $n, $k>(self, t, q, v)
            }
            fn potential_energy_at<S: $crate::Scalar>(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: S,
                q: &[S; $n],
            ) -> S {
                $crate::dynamics::potential_energy::<$ty, S, $n, $k>(self, t, q)
            }
            fn momenta_at<S: $crate::Scalar>(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: S,
                q: &[S; $n],
                v: &[S; $n],
            ) -> [S; $n] {
                $crate::dynamics::momenta::<$ty, S, $n, $k>(self, t, q, v)
            }
            fn lagrangian_time_derivative_at(
                &self,
                _constants: $crate::evaluation::Constants<'_, Self>,
                t: f64,
                q: &[f64; $n],
                v: &[f64; $n],
            ) -> f64 {
                $crate::dynamics::lagrangian_time_derivative::<$ty, $n, $k>(self, t, q, v)
            }
            $($extra)*
        }
    };
}
