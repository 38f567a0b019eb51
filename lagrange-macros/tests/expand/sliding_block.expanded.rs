pub mod sliding_block {
    pub struct SlidingBlock {
        pub m: f64,
        pub g: f64,
        pub mu: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq,
        ::lagrange::__private::core::default::Default
    )]
    pub struct Coords<T = f64> {
        pub x: T,
        pub y: T,
    }
    impl ::lagrange::__private::Coordinates<2> for Coords<f64> {
        const NAMES: [&'static str; 2] = ["x", "y"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 2] {
            [self.x, self.y]
        }
        #[inline(always)]
        fn from_array(values: [f64; 2]) -> Self {
            Coords {
                x: values[0],
                y: values[1],
            }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 2;
    /// The state of this mechanism: time, coordinates, velocities.
    #[allow(dead_code)]
    pub type State = ::lagrange::__private::State<Coords>;
    /// Every body and point of the mechanism, by name: a particle or point's position, a rigid
    /// body's pose as its function returns it (its centre of mass and orientation, or, for a
    /// body declared with its `com`, its frame).
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    #[allow(dead_code)]
    pub struct Bodies<T = f64> {
        pub block: ::lagrange::__private::geometry::Vec2<T>,
    }
    /// The velocity of every body and point, by name: a particle or point's velocity; for a
    /// planar body, its centre-of-mass velocity and angular velocity (as a `Planar`); for a
    /// spatial body, a `SpatialVelocity` (centre-of-mass and angular velocity, world frame).
    /// For a body declared with its `com`, the velocity of its frame's origin in place of the
    /// centre of mass's.
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    #[allow(dead_code)]
    pub struct BodyVelocities<T = f64> {
        pub block: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl SlidingBlock {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                2,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                2,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                2,
                2,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [x, y] = *__q;
            let block: ::lagrange::__private::geometry::Vec2<__D> = { vec2(x, y) };
            Bodies { block }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 2],
        ) -> Bodies<__D> {
            Bodies {
                block: ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 2],
            __x_dot: &[__D; 2],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                block: ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
            }
        }
    }
    impl ::lagrange::__private::Model<2, 2> for SlidingBlock {
        type Coords = Coords;
        const INERTIAL: usize = 2;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 2]; 2] = [[true, false], [false, true]];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m: f64 = self.m;
            let g: f64 = self.g;
            let mu: f64 = self.mu;
            let __mass_block: f64 = m;
            ((0.0 + self.m + self.g + self.mu + __mass_block) * 0.0 == 0.0)
                & (__mass_block > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<2, 2>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            if !self.mu.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "mu",
                    value: self.mu,
                });
            }
            let m: f64 = self.m;
            let g: f64 = self.g;
            let mu: f64 = self.mu;
            let __mass_block: f64 = m;
            if !(__mass_block.is_finite() && __mass_block > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "block",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_block
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 2] {
            let m: f64 = self.m;
            let g: f64 = self.g;
            let mu: f64 = self.mu;
            let __mass_block: f64 = m;
            [__mass_block, __mass_block]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> [__D; 2] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.block.x, __bodies.block.y]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 2] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<2, 2>>::masses(self);
            let mut __weights = [0.0; 2];
            let __gravity_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights
        }
    }
    impl ::lagrange::__private::Prepare for SlidingBlock {
        type Prepared = ::lagrange::__private::lagrange_core::affine::AffineConstants<
            2,
            2,
        >;
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::lagrange_core::affine::AffineConstants::of::<
                Self,
            >(self)
        }
    }
    impl ::lagrange::__private::Dynamics<2> for SlidingBlock {
        type Coords = Coords;
        type Contacts = ::lagrange::__private::lagrange_core::constraints::ContactState<
            2,
            2,
        >;
        const CONSTRAINT_COUNTS: ::lagrange::__private::core::option::Option<
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts,
        > = ::lagrange::__private::core::option::Option::Some(
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts::of(
                &<Self as ::lagrange::__private::lagrange_core::constraints::Constraints<
                    2,
                    2,
                    2,
                >>::KINDS,
            ),
        );
        const SCLERONOMIC: bool = true;
        const CLOSED_FORM: bool = false;
        #[inline]
        fn check_parameters(&self) -> ::lagrange::__private::Result<()> {
            <Self as ::lagrange::__private::Model<2, 2>>::validate(self)?;
            <Self as ::lagrange::__private::lagrange_core::constraints::Constraints<
                2,
                2,
                2,
            >>::validate_constraints(self)?;
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[inline(always)]
        fn equations_of_motion_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 2> {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::equations_of_motion::<
                Self,
                S,
                2,
                2,
            >(self, t, q, v)
        }
        #[inline]
        fn accelerations_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> ::lagrange::__private::Result<[S; 2]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::constraints::accelerations_prepared::<
                        Self,
                        S,
                        2,
                        2,
                        2,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    ::lagrange::__private::lagrange_core::constraints::accelerations::<
                        Self,
                        S,
                        2,
                        2,
                        2,
                    >(self, t, q, v)
                }
            }
        }
        #[inline]
        fn kinetic_energy_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::kinetic_energy::<
                Self,
                S,
                2,
                2,
            >(self, t, q, v)
        }
        #[inline]
        fn potential_energy_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                2,
                2,
            >(self, t, q)
        }
        #[inline]
        fn lagrangian_time_derivative_at(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: f64,
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                2,
                2,
            >(self, t, q, v)
        }
        #[inline]
        fn momenta_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> [S; 2] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 2, 2>(self, t, q, v)
        }
        #[inline]
        fn canonical_field_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 2],
            v: &[S; 2],
        ) -> ([S; 2], [S; 2]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    Self,
                    S,
                    2,
                    2,
                >(self, t, q, v)
            }
        }
        #[inline]
        fn holonomic_constraints_at<S: ::lagrange::__private::Scalar>(
            &self,
            t: S,
            q: &[S; 2],
        ) -> ::lagrange::__private::core::option::Option<[S; 2]> {
            ::lagrange::__private::core::option::Option::Some(
                ::lagrange::__private::lagrange_core::constraints::holonomic_values::<
                    Self,
                    S,
                    2,
                    2,
                    2,
                >(self, t, q),
            )
        }
        fn project(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: f64,
            q: &mut [f64; 2],
            v: &mut [f64; 2],
        ) -> ::lagrange::__private::Result<()> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::constraints::project_prepared::<
                        Self,
                        2,
                        2,
                        2,
                    >(self, prepared, t, q, v)
                }
                ::lagrange::__private::core::option::Option::None => {
                    let mode = ::lagrange::__private::lagrange_core::constraints::infer_mode::<
                        Self,
                        2,
                        2,
                        2,
                    >(self, t, q, v)?;
                    ::lagrange::__private::lagrange_core::constraints::project::<
                        Self,
                        2,
                        2,
                        2,
                    >(self, t, q, v, &mode)
                }
            }
        }
        #[inline]
        fn check_declaration_at(
            &self,
            t: f64,
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> ::lagrange::__private::Result<()> {
            ::lagrange::__private::lagrange_core::constraints::check_velocity_rows_affine::<
                Self,
                2,
                2,
                2,
            >(self, t, q, v)
        }
        fn check_constraints(
            &self,
            t: f64,
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> ::lagrange::__private::Result<()> {
            ::lagrange::__private::lagrange_core::constraints::check_consistent::<
                Self,
                2,
                2,
                2,
            >(
                self,
                t,
                q,
                v,
                ::lagrange::__private::lagrange_core::constraints::CONSISTENCY_TOLERANCE,
            )
        }
    }
    impl ::lagrange::__private::lagrange_core::constraints::Constraints<2, 2, 2>
    for SlidingBlock {
        const NAMES: [&'static str; 2] = ["floor", "slide"];
        const KINDS: [::lagrange::__private::lagrange_core::constraints::ConstraintKind; 2] = [
            ::lagrange::__private::lagrange_core::constraints::ConstraintKind::Unilateral,
            ::lagrange::__private::lagrange_core::constraints::ConstraintKind::Friction {
                normal: 0,
            },
        ];
        #[allow(unused_variables, clippy::all)]
        #[inline(always)]
        fn position_constraints<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __x: &[__D; 2],
        ) -> [__D; 2] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [x, y] = *__q;
            let Bodies { block } = self.__lagrange_bodies_from_cartesian(__x);
            [
                {
                    let __row: __D = { block.y };
                    __row
                },
                <__D>::zero(),
            ]
        }
        #[allow(unused_variables, clippy::all)]
        #[inline(always)]
        fn velocity_constraints<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
            __v: &[__D; 2],
            __x: &[__D; 2],
            __x_dot: &[__D; 2],
        ) -> [__D; 2] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [x, y] = *__q;
            let Bodies { block } = self.__lagrange_bodies_from_cartesian(__x);
            let [x_dot, y_dot] = *__v;
            let BodyVelocities { block: block_dot } = self
                .__lagrange_velocities_from_cartesian(__x, __x_dot);
            [
                <__D>::zero(),
                {
                    let __row: __D = { block_dot.x };
                    __row
                },
            ]
        }
        #[allow(unused_variables, clippy::all)]
        fn friction_coefficients(
            &self,
            row: usize,
        ) -> ::lagrange::__private::lagrange_core::constraints::Coulomb {
            let m: f64 = self.m;
            let g: f64 = self.g;
            let mu: f64 = self.mu;
            match row {
                1 => {
                    ::lagrange::__private::lagrange_core::constraints::Coulomb {
                        kinetic: mu,
                        stiction: mu,
                    }
                }
                _ => {
                    ::lagrange::__private::lagrange_core::constraints::Coulomb::default()
                }
            }
        }
        const POSITION_DERIVATIVES: [bool; 2] = [true, false];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn position_constraint_derivatives<__S: ::lagrange::__private::Scalar>(
            &self,
            __t: __S,
            __q: &[__S; 2],
            __v: &[__S; 2],
            __motion: &::lagrange::__private::lagrange_core::constraints::CartesianMotion<
                __S,
                2,
                2,
            >,
            __out: &mut ::lagrange::__private::lagrange_core::constraints::ConstraintRows<
                __S,
                2,
                2,
            >,
        ) {
            let m: f64 = self.m;
            let g: f64 = self.g;
            let mu: f64 = self.mu;
            let (__x, __x_dot, __x_accel, __jacobian) = (
                &__motion.x,
                &__motion.x_dot,
                &__motion.x_accel,
                &__motion.jacobian,
            );
            let __e3: __S = __q[1];
            let __e4: __S = __v[1];
            __out.value[0] = __e3;
            __out.rows[0] = ::lagrange::__private::nalgebra::SVector::from([
                <__S>::from(0.0),
                <__S>::from(1.0),
            ]);
            __out.rate[0] = __e4;
            __out.bias[0] = <__S>::from(0.0);
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration
    for SlidingBlock {
        const DOF: usize = 2;
        const PARAMETERS: &'static [&'static str] = &["m", "g", "mu"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(SlidingBlock {
                m: values[0],
                g: values[1],
                mu: values[2],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.g, self.mu]
        }
        const CONSTRAINT_ROWS: &'static [&'static str] = &["floor", "slide"];
        fn constraint_forces(
            &self,
            inputs: &[f64],
            t: f64,
            q: &[f64],
            v: &[f64],
        ) -> ::lagrange::__private::Result<
            ::lagrange::__private::lagrange_core::declaration::FlatConstraintForces,
        > {
            let _ = inputs;
            ::lagrange::__private::lagrange_core::declaration::flat_constraint_forces::<
                Self,
                2,
                2,
                2,
            >(self, t, q, v)
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<2> for SlidingBlock {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "block",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[
            ::lagrange::__private::lagrange_core::animation::ConstraintLayout {
                name: "floor",
                bodies: &[
                    ::lagrange::__private::lagrange_core::animation::BodyRef {
                        body: 0,
                        member: 0,
                    },
                ],
            },
            ::lagrange::__private::lagrange_core::animation::ConstraintLayout {
                name: "slide",
                bodies: &[],
            },
        ];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 2],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(&[__bodies.block.x, __bodies.block.y]);
        }
    }
    impl SlidingBlock {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 2]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [x, y] = *__q;
            let block: ::lagrange::__private::geometry::Vec2<__D> = { vec2(x, y) };
            Bodies { block }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<2, 2, 3> for SlidingBlock {
        const PARAMETER_NAMES: [&'static str; 3] = ["m", "g", "mu"];
        const SEEDABLE: [bool; 3] = [false, false, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 3] {
            [self.m, self.g, self.mu]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 3], __t: __D, __q: &[__D; 2]) -> [__D; 2] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.block.x, __bodies.block.y]
        }
    }
}
