pub mod double_pendulum {
    pub struct DoublePendulum {
        pub m1: f64,
        pub m2: f64,
        pub l1: f64,
        pub l2: f64,
        pub g: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq,
        ::lagrange::__private::core::default::Default
    )]
    pub struct Coords<T = f64> {
        pub theta1: T,
        pub theta2: T,
    }
    impl ::lagrange::__private::Coordinates<2> for Coords<f64> {
        const NAMES: [&'static str; 2] = ["theta1", "theta2"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 2] {
            [self.theta1, self.theta2]
        }
        #[inline(always)]
        fn from_array(values: [f64; 2]) -> Self {
            Coords {
                theta1: values[0],
                theta2: values[1],
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
        pub bob1: ::lagrange::__private::geometry::Vec2<T>,
        pub bob2: ::lagrange::__private::geometry::Vec2<T>,
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
        pub bob1: ::lagrange::__private::geometry::Vec2<T>,
        pub bob2: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl DoublePendulum {
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
                4,
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
            let [theta1, theta2] = *__q;
            let l1 = <__D>::from(self.l1);
            let l2 = <__D>::from(self.l2);
            let (__sin_theta1, __cos_theta1) = theta1.sin_cos();
            let (__sin_theta2, __cos_theta2) = theta2.sin_cos();
            let bob1: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(__sin_theta1, -__cos_theta1) * l1
            };
            let bob2: ::lagrange::__private::geometry::Vec2<__D> = {
                bob1 + vec2(__sin_theta2, -__cos_theta2) * l2
            };
            Bodies { bob1, bob2 }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 4],
            __x_dot: &[__D; 4],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                bob1: ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                bob2: ::lagrange::__private::geometry::vec2(__x_dot[2], __x_dot[3]),
            }
        }
    }
    impl ::lagrange::__private::Model<2, 4> for DoublePendulum {
        type Coords = Coords;
        const INERTIAL: usize = 4;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = false;
        const DEPENDS: [[bool; 2]; 4] = [
            [true, false],
            [true, false],
            [true, true],
            [true, true],
        ];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let l1: f64 = self.l1;
            let l2: f64 = self.l2;
            let g: f64 = self.g;
            let __mass_bob1: f64 = m1;
            let __mass_bob2: f64 = m2;
            ((0.0 + self.m1 + self.m2 + self.l1 + self.l2 + self.g + __mass_bob1
                + __mass_bob2) * 0.0 == 0.0) & (__mass_bob1 > 0.0) & (__mass_bob2 > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<2, 4>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m1.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m1",
                    value: self.m1,
                });
            }
            if !self.m2.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m2",
                    value: self.m2,
                });
            }
            if !self.l1.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "l1",
                    value: self.l1,
                });
            }
            if !self.l2.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "l2",
                    value: self.l2,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let l1: f64 = self.l1;
            let l2: f64 = self.l2;
            let g: f64 = self.g;
            let __mass_bob1: f64 = m1;
            let __mass_bob2: f64 = m2;
            if !(__mass_bob1.is_finite() && __mass_bob1 > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bob1",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_bob1
                    ),
                });
            }
            if !(__mass_bob2.is_finite() && __mass_bob2 > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bob2",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_bob2
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 4] {
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let l1: f64 = self.l1;
            let l2: f64 = self.l2;
            let g: f64 = self.g;
            let __mass_bob1: f64 = m1;
            let __mass_bob2: f64 = m2;
            [__mass_bob1, __mass_bob1, __mass_bob2, __mass_bob2]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 2],
        ) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.bob1.x, __bodies.bob1.y, __bodies.bob2.x, __bodies.bob2.y]
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 4] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<2, 4>>::masses(self);
            let mut __weights = [0.0; 4];
            let __gravity_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights[2] += __gravity_down.x * __masses[2];
            __weights[3] += __gravity_down.y * __masses[3];
            __weights
        }
    }
    impl DoublePendulum {
        /// The constant factors of the closed-form equations of motion.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_coefficients(&self) -> [f64; 5] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let m1: f64 = self.m1;
            let m2: f64 = self.m2;
            let l1: f64 = self.l1;
            let l2: f64 = self.l2;
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<2, 4>>::masses(self);
            [
                l1 * l1 * __masses[0] + l1 * l1 * __masses[2],
                l1 * l2 * __masses[2],
                l2 * l2 * __masses[2],
                l1 * g * __masses[0] + l1 * g * __masses[2],
                l2 * g * __masses[2],
            ]
        }
        #[inline(always)]
        fn __lagrange_closed_form<__D: ::lagrange::__private::Scalar>(
            &self,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<__D, 2> {
            self.__lagrange_closed_form_with(
                ::lagrange::__private::core::option::Option::None,
                __q,
                __v,
            )
        }
        /// With the coefficients prepared (`Some`) or computed here (`None`), after the sines
        /// and cosines: values computed before those calls would be kept on the stack across
        /// them.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_closed_form_with<__D: ::lagrange::__private::Scalar>(
            &self,
            __prepared: ::lagrange::__private::core::option::Option<&[f64; 5]>,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<__D, 2> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let (__sin_0, __cos_0) = __q[0].sin_cos();
            let (__sin_1, __cos_1) = __q[1].sin_cos();
            let __computed: [f64; 5];
            let __k: &[f64; 5] = match __prepared {
                ::lagrange::__private::core::option::Option::Some(__k) => __k,
                ::lagrange::__private::core::option::Option::None => {
                    __computed = self.__lagrange_coefficients();
                    &__computed
                }
            };
            let (
                __product_0,
                __product_1,
                __product_2,
                __product_3,
                __product_4,
                __product_5,
            ) = (
                __sin_0 * __sin_1,
                __cos_0 * __cos_1,
                __v[1] * __v[1],
                __sin_0 * __cos_1,
                __sin_1 * __cos_0,
                __v[0] * __v[0],
            );
            ::lagrange::__private::dynamics::EquationsOfMotion::from_columns(
                [
                    [<__D>::from(__k[0]), (__product_0 + __product_1) * __k[1]],
                    [(__product_0 + __product_1) * __k[1], <__D>::from(__k[2])],
                ],
                [-__sin_0 * __k[3], -__sin_1 * __k[4]],
                [
                    (__product_3 - __product_4) * __k[1] * __product_2,
                    -(__product_3 - __product_4) * __k[1] * __product_5,
                ],
            )
        }
        /// The canonical field (p, ṗ) = (M q̇, ∂T/∂q + 𝓕), with the coefficients prepared
        /// (`Some`) or computed here (`None`).
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_canonical_field_with<__D: ::lagrange::__private::Scalar>(
            &self,
            __prepared: ::lagrange::__private::core::option::Option<&[f64; 5]>,
            __q: &[__D; 2],
            __v: &[__D; 2],
        ) -> ([__D; 2], [__D; 2]) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let (__sin_0, __cos_0) = __q[0].sin_cos();
            let (__sin_1, __cos_1) = __q[1].sin_cos();
            let __computed: [f64; 5];
            let __k: &[f64; 5] = match __prepared {
                ::lagrange::__private::core::option::Option::Some(__k) => __k,
                ::lagrange::__private::core::option::Option::None => {
                    __computed = self.__lagrange_coefficients();
                    &__computed
                }
            };
            let (__product_0, __product_1, __product_2, __product_3, __product_4) = (
                __sin_0 * __sin_1,
                __cos_0 * __cos_1,
                __v[0] * __v[1],
                __sin_0 * __cos_1,
                __sin_1 * __cos_0,
            );
            (
                [
                    __v[0] * <__D>::from(__k[0])
                        + (__product_0 + __product_1) * __k[1] * __v[1],
                    (__product_0 + __product_1) * __k[1] * __v[0]
                        + __v[1] * <__D>::from(__k[2]),
                ],
                [
                    -__sin_0 * __k[3]
                        - (__product_3 - __product_4) * __k[1] * __product_2,
                    -__sin_1 * __k[4]
                        + (__product_3 - __product_4) * __k[1] * __product_2,
                ],
            )
        }
    }
    impl ::lagrange::__private::Prepare for DoublePendulum {
        type Prepared = [f64; 5];
        #[inline]
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::core::result::Result::Ok(
                self.__lagrange_coefficients(),
            )
        }
    }
    impl ::lagrange::__private::Dynamics<2> for DoublePendulum {
        type Coords = Coords;
        type Contacts = ::lagrange::__private::lagrange_core::constraints::NoContacts;
        const CONSTRAINT_COUNTS: ::lagrange::__private::core::option::Option<
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts,
        > = ::lagrange::__private::core::option::Option::Some(
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts::NONE,
        );
        const SCLERONOMIC: bool = true;
        const CLOSED_FORM: bool = true;
        #[inline]
        fn check_parameters(&self) -> ::lagrange::__private::Result<()> {
            <Self as ::lagrange::__private::Model<2, 4>>::validate(self)?;
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
            self.__lagrange_closed_form::<S>(q, v)
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
                    let eom = self
                        .__lagrange_closed_form_with::<
                            S,
                        >(
                            ::lagrange::__private::core::option::Option::Some(prepared),
                            q,
                            v,
                        );
                    ::lagrange::__private::dynamics::solve_accelerations::<
                        Coords,
                        S,
                        2,
                    >(&eom, t, q)
                }
                ::lagrange::__private::core::option::Option::None => {
                    let eom = <Self as ::lagrange::__private::Dynamics<
                        2,
                    >>::equations_of_motion_at(
                        self,
                        ::lagrange::__private::lagrange_core::evaluation::Constants::NONE
                            .with_inputs(__constants.inputs),
                        t,
                        q,
                        v,
                    );
                    ::lagrange::__private::dynamics::solve_accelerations::<
                        Coords,
                        S,
                        2,
                    >(&eom, t, q)
                }
            }
        }
        #[inline(always)]
        fn regular_accelerations_at(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: f64,
            q: &[f64; 2],
            v: &[f64; 2],
        ) -> ::lagrange::__private::core::option::Option<[f64; 2]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    let eom = self
                        .__lagrange_closed_form_with::<
                            f64,
                        >(
                            ::lagrange::__private::core::option::Option::Some(prepared),
                            q,
                            v,
                        );
                    ::lagrange::__private::dynamics::regular_accelerations::<
                        2,
                    >(&eom, t, q, v, true)
                }
                ::lagrange::__private::core::option::Option::None => {
                    let eom = self.__lagrange_closed_form::<f64>(q, v);
                    let parameters_pass = <Self as ::lagrange::__private::Model<
                        2,
                        4,
                    >>::parameters_pass(self);
                    ::lagrange::__private::dynamics::regular_accelerations::<
                        2,
                    >(&eom, t, q, v, parameters_pass)
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
                4,
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
                4,
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
                4,
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
            self.__lagrange_canonical_field_with::<
                    S,
                >(::lagrange::__private::core::option::Option::None, q, v)
                .0
        }
        #[inline(always)]
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
            self.__lagrange_canonical_field_with::<S>(prepared, q, v)
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration
    for DoublePendulum {
        const DOF: usize = 2;
        const PARAMETERS: &'static [&'static str] = &["m1", "m2", "l1", "l2", "g"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(DoublePendulum {
                m1: values[0],
                m2: values[1],
                l1: values[2],
                l2: values[3],
                g: values[4],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m1, self.m2, self.l1, self.l2, self.g]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<2>
    for DoublePendulum {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "bob1",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "bob2",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
                count: ::lagrange::__private::core::option::Option::None,
                row: 2,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[
            ::lagrange::__private::lagrange_core::animation::Link {
                from: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 1,
                    member: 0,
                },
                to: ::lagrange::__private::lagrange_core::animation::BodyRef {
                    body: 0,
                    member: 0,
                },
            },
        ];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 2],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[__bodies.bob1.x, __bodies.bob1.y, __bodies.bob2.x, __bodies.bob2.y],
            );
        }
    }
    impl DoublePendulum {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 5], __t: __D, __q: &[__D; 2]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta1, theta2] = *__q;
            let l1: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[2]);
            let l2: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[3]);
            let (__sin_theta1, __cos_theta1) = theta1.sin_cos();
            let (__sin_theta2, __cos_theta2) = theta2.sin_cos();
            let bob1: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(__sin_theta1, -__cos_theta1) * l1
            };
            let bob2: ::lagrange::__private::geometry::Vec2<__D> = {
                bob1 + vec2(__sin_theta2, -__cos_theta2) * l2
            };
            Bodies { bob1, bob2 }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<2, 4, 5> for DoublePendulum {
        const PARAMETER_NAMES: [&'static str; 5] = ["m1", "m2", "l1", "l2", "g"];
        const SEEDABLE: [bool; 5] = [false, false, true, true, false];
        #[inline(always)]
        fn parameters(&self) -> [f64; 5] {
            [self.m1, self.m2, self.l1, self.l2, self.g]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 5], __t: __D, __q: &[__D; 2]) -> [__D; 4] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.bob1.x, __bodies.bob1.y, __bodies.bob2.x, __bodies.bob2.y]
        }
    }
}
