pub mod motor {
    pub struct Motor {
        pub j: f64,
        pub c: f64,
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq
    )]
    pub struct Torque {
        pub tau: f64,
    }
    impl ::lagrange::__private::core::default::Default for Torque {
        /// Every input zero.
        fn default() -> Self {
            <Self as ::lagrange::__private::lagrange_core::inputs::Inputs<
                1,
            >>::from_array([0.0; 1])
        }
    }
    impl ::lagrange::__private::lagrange_core::inputs::Inputs<1> for Torque {
        const NAMES: [&'static str; 1] = ["tau"];
        #[inline]
        fn to_array(&self) -> [f64; 1] {
            [self.tau]
        }
        #[inline]
        fn from_array(__values: [f64; 1]) -> Self {
            Torque { tau: __values[0] }
        }
    }
    impl ::lagrange::__private::lagrange_core::inputs::Actuated<1> for Motor {
        type Inputs = Torque;
    }
    impl ::lagrange::__private::lagrange_core::inputs::ActuatedModel<1, 3, 1> for Motor {
        #[allow(unused_variables, clippy::all)]
        fn applied_forces_with_inputs<
            __D: ::lagrange::__private::Scalar,
            __U: ::lagrange::__private::Scalar,
        >(
            &self,
            __u: &[__U; 1],
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 3],
            __x_dot: &[__D; 3],
            __cartesian_force: &mut [__D; 3],
            __generalized_force: &mut [__D; 1],
        ) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let c = <__D>::from(self.c);
            let tau: __D = ::lagrange::__private::lagrange_core::inputs::input::<
                __U,
                __D,
            >(&__u[0]);
            let [theta_dot] = *__v;
            let __generalized_force_drive: __D = { tau - c * theta_dot };
            __generalized_force[0] += __generalized_force_drive;
        }
        #[allow(unused_variables, clippy::all)]
        fn coordinate_forces_with_inputs<
            __D: ::lagrange::__private::Scalar,
            __U: ::lagrange::__private::Scalar,
        >(
            &self,
            __u: &[__U; 1],
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __generalized_force: &mut [__D; 1],
        ) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let c = <__D>::from(self.c);
            let tau: __D = ::lagrange::__private::lagrange_core::inputs::input::<
                __U,
                __D,
            >(&__u[0]);
            let [theta_dot] = *__v;
            let __generalized_force_drive: __D = { tau - c * theta_dot };
            __generalized_force[0] += __generalized_force_drive;
        }
    }
    #[derive(
        ::lagrange::__private::core::clone::Clone,
        ::lagrange::__private::core::marker::Copy,
        ::lagrange::__private::core::fmt::Debug,
        ::lagrange::__private::core::cmp::PartialEq,
        ::lagrange::__private::core::default::Default
    )]
    pub struct Coords<T = f64> {
        pub theta: T,
    }
    impl ::lagrange::__private::Coordinates<1> for Coords<f64> {
        const NAMES: [&'static str; 1] = ["theta"];
        #[inline(always)]
        fn to_array(&self) -> [f64; 1] {
            [self.theta]
        }
        #[inline(always)]
        fn from_array(values: [f64; 1]) -> Self {
            Coords { theta: values[0] }
        }
    }
    /// Degrees of freedom: the number of generalized coordinates.
    #[allow(dead_code)]
    pub const DOF: usize = 1;
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
        pub disc: ::lagrange::__private::geometry::Planar<T>,
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
        pub disc: ::lagrange::__private::geometry::Planar<T>,
    }
    impl Motor {
        /// Every body and point at `state`, by name.
        #[allow(dead_code)]
        pub fn bodies(&self, state: &State) -> Bodies {
            let q = <Coords as ::lagrange::__private::Coordinates<
                1,
            >>::to_array(&state.q);
            self.__lagrange_bodies(state.t, &q)
        }
        /// The velocity of every body and point at `state`, by name (one forward-mode pass
        /// along (q̇, 1), q̇ the coordinates' rates at the state's velocities).
        #[allow(dead_code)]
        pub fn body_velocities(&self, state: &State) -> BodyVelocities {
            let q = <Coords as ::lagrange::__private::Coordinates<
                1,
            >>::to_array(&state.q);
            let v = <Coords as ::lagrange::__private::Coordinates<
                1,
            >>::to_array(&state.v);
            let v = <Self as ::lagrange::__private::Dynamics<
                1,
            >>::position_rates_at(self, &q, &v);
            let (x, x_dot) = ::lagrange::__private::dynamics::cartesian_velocities::<
                Self,
                f64,
                1,
                3,
            >(self, state.t, &q, &v);
            self.__lagrange_velocities_from_cartesian(&x, &x_dot)
        }
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
        ) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let disc: ::lagrange::__private::geometry::Planar<__D> = {
                planar(vec2(<__D>::from(0.0), <__D>::from(0.0)), theta)
            };
            Bodies { disc }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 3],
        ) -> Bodies<__D> {
            Bodies {
                disc: ::lagrange::__private::geometry::planar(
                    ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
                    __x[2],
                ),
            }
        }
        #[inline(always)]
        #[allow(unused_variables)]
        fn __lagrange_velocities_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 3],
            __x_dot: &[__D; 3],
        ) -> BodyVelocities<__D> {
            BodyVelocities {
                disc: ::lagrange::__private::geometry::planar(
                    ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
                    __x_dot[2],
                ),
            }
        }
    }
    impl ::lagrange::__private::Model<1, 3> for Motor {
        type Coords = Coords;
        const INERTIAL: usize = 3;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = true;
        const GENERALIZED_FORCES_ONLY: bool = true;
        #[inline(always)]
        fn coordinate_forces<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __generalized_force: &mut [__D; 1],
        ) {
            <Self as ::lagrange::__private::lagrange_core::inputs::ActuatedModel<
                1,
                3,
                1,
            >>::coordinate_forces_with_inputs::<
                __D,
                f64,
            >(self, &[0.0; 1], __t, __q, __v, __generalized_force)
        }
        const DEPENDS: [[bool; 1]; 3] = [[false], [false], [true]];
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let j: f64 = self.j;
            let c: f64 = self.c;
            let __mass_disc: f64 = 1.0;
            let __inertia_disc: f64 = j;
            ((0.0 + self.j + self.c + __mass_disc + __inertia_disc) * 0.0 == 0.0)
                & (__mass_disc > 0.0) & (__inertia_disc > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<1, 3>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.j.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "j",
                    value: self.j,
                });
            }
            if !self.c.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "c",
                    value: self.c,
                });
            }
            let j: f64 = self.j;
            let c: f64 = self.c;
            let __mass_disc: f64 = 1.0;
            let __inertia_disc: f64 = j;
            if !(__mass_disc.is_finite() && __mass_disc > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "disc",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_disc
                    ),
                });
            }
            if !(__inertia_disc.is_finite() && __inertia_disc > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "disc",
                    reason: ::lagrange::__private::std::format!(
                        "moment of inertia must be positive and finite, got {}",
                        __inertia_disc
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 3] {
            let j: f64 = self.j;
            let c: f64 = self.c;
            let __mass_disc: f64 = 1.0;
            let __inertia_disc: f64 = j;
            [__mass_disc, __mass_disc, __inertia_disc]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
        ) -> [__D; 3] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.disc.position.x, __bodies.disc.position.y, __bodies.disc.angle]
        }
        #[inline(always)]
        fn applied_forces<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 3],
            __x_dot: &[__D; 3],
            __cartesian_force: &mut [__D; 3],
            __generalized_force: &mut [__D; 1],
        ) {
            <Self as ::lagrange::__private::lagrange_core::inputs::ActuatedModel<
                1,
                3,
                1,
            >>::applied_forces_with_inputs::<
                __D,
                f64,
            >(
                self,
                &[0.0; 1],
                __t,
                __q,
                __v,
                __x,
                __x_dot,
                __cartesian_force,
                __generalized_force,
            )
        }
    }
    impl ::lagrange::__private::Prepare for Motor {
        type Prepared = ::lagrange::__private::lagrange_core::affine::AffineConstants<
            1,
            3,
        >;
        fn prepare(&self) -> ::lagrange::__private::Result<Self::Prepared> {
            ::lagrange::__private::lagrange_core::affine::AffineConstants::of::<
                Self,
            >(self)
        }
    }
    impl ::lagrange::__private::Dynamics<1> for Motor {
        type Coords = Coords;
        type Contacts = ::lagrange::__private::lagrange_core::constraints::NoContacts;
        const CONSTRAINT_COUNTS: ::lagrange::__private::core::option::Option<
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts,
        > = ::lagrange::__private::core::option::Option::Some(
            ::lagrange::__private::lagrange_core::constraints::ConstraintCounts::NONE,
        );
        const SCLERONOMIC: bool = true;
        const CLOSED_FORM: bool = false;
        #[inline]
        fn check_parameters(&self) -> ::lagrange::__private::Result<()> {
            <Self as ::lagrange::__private::Model<1, 3>>::validate(self)?;
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
            q: &[S; 1],
            v: &[S; 1],
        ) -> ::lagrange::__private::dynamics::EquationsOfMotion<S, 1> {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::equations_of_motion::<
                ::lagrange::__private::lagrange_core::inputs::WithInputs<
                    '_,
                    Self,
                    f64,
                    1,
                >,
                S,
                1,
                3,
            >(
                &::lagrange::__private::lagrange_core::inputs::WithInputs::<
                    Self,
                    f64,
                    1,
                >::held(self, __constants.inputs),
                t,
                q,
                v,
            )
        }
        #[inline]
        fn accelerations_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 1],
            v: &[S; 1],
        ) -> ::lagrange::__private::Result<[S; 1]> {
            let prepared = __constants.prepared;
            match prepared {
                ::lagrange::__private::core::option::Option::Some(prepared) => {
                    ::lagrange::__private::lagrange_core::affine::accelerations::<
                        ::lagrange::__private::lagrange_core::inputs::WithInputs<
                            '_,
                            Self,
                            f64,
                            1,
                        >,
                        S,
                        1,
                        3,
                    >(
                        &::lagrange::__private::lagrange_core::inputs::WithInputs::<
                            Self,
                            f64,
                            1,
                        >::held(self, __constants.inputs),
                        prepared,
                        t,
                        q,
                        v,
                    )
                }
                ::lagrange::__private::core::option::Option::None => {
                    let eom = <Self as ::lagrange::__private::Dynamics<
                        1,
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
                        1,
                    >(&eom, t, q)
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
            q: &[S; 1],
            v: &[S; 1],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::kinetic_energy::<
                Self,
                S,
                1,
                3,
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
            q: &[S; 1],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                1,
                3,
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
            q: &[f64; 1],
            v: &[f64; 1],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                1,
                3,
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
            q: &[S; 1],
            v: &[S; 1],
        ) -> [S; 1] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 1, 3>(self, t, q, v)
        }
        #[inline]
        fn canonical_field_at<S: ::lagrange::__private::Scalar>(
            &self,
            __constants: ::lagrange::__private::lagrange_core::evaluation::Constants<
                '_,
                Self,
            >,
            t: S,
            q: &[S; 1],
            v: &[S; 1],
        ) -> ([S; 1], [S; 1]) {
            let prepared = __constants.prepared;
            {
                let _ = prepared;
                ::lagrange::__private::dynamics::canonical_field::<
                    ::lagrange::__private::lagrange_core::inputs::WithInputs<
                        '_,
                        Self,
                        f64,
                        1,
                    >,
                    S,
                    1,
                    3,
                >(
                    &::lagrange::__private::lagrange_core::inputs::WithInputs::<
                        Self,
                        f64,
                        1,
                    >::held(self, __constants.inputs),
                    t,
                    q,
                    v,
                )
            }
        }
        const INPUT_NAMES: &'static [&'static str] = &<<Self as ::lagrange::__private::lagrange_core::inputs::Actuated<
            1,
        >>::Inputs as ::lagrange::__private::lagrange_core::inputs::Inputs<1>>::NAMES;
        #[inline]
        fn accelerations_with_inputs_at<S: ::lagrange::__private::Scalar>(
            &self,
            inputs: &[S],
            t: S,
            q: &[S; 1],
            v: &[S; 1],
        ) -> ::lagrange::__private::Result<[S; 1]> {
            ::lagrange::__private::dynamics::accelerations_generic::<
                _,
                S,
                1,
                3,
            >(
                &::lagrange::__private::lagrange_core::inputs::WithInputs::<
                    '_,
                    Self,
                    S,
                    1,
                >::held(self, inputs),
                t,
                q,
                v,
            )
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Motor {
        const DOF: usize = 1;
        const PARAMETERS: &'static [&'static str] = &["j", "c"];
        const INPUTS: &'static [&'static str] = &<Torque as ::lagrange::__private::lagrange_core::inputs::Inputs<
            1,
        >>::NAMES;
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Motor {
                j: values[0],
                c: values[1],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.j, self.c]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<1> for Motor {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "disc",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Planar,
                count: ::lagrange::__private::core::option::Option::None,
                row: 0,
            },
        ];
        const LINKS: &'static [::lagrange::__private::lagrange_core::animation::Link] = &[];
        const CONSTRAINT_BODIES: &'static [::lagrange::__private::lagrange_core::animation::ConstraintLayout] = &[];
        fn cartesian_rows(
            &self,
            t: f64,
            q: &[f64; 1],
            rows: &mut ::lagrange::__private::std::vec::Vec<f64>,
        ) {
            let __bodies = self.__lagrange_bodies(t, q);
            rows.clear();
            rows.extend_from_slice(
                &[
                    __bodies.disc.position.x,
                    __bodies.disc.position.y,
                    __bodies.disc.angle,
                ],
            );
        }
    }
    impl Motor {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 2], __t: __D, __q: &[__D; 1]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let disc: ::lagrange::__private::geometry::Planar<__D> = {
                planar(vec2(<__D>::from(0.0), <__D>::from(0.0)), theta)
            };
            Bodies { disc }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<1, 3, 2> for Motor {
        const PARAMETER_NAMES: [&'static str; 2] = ["j", "c"];
        const SEEDABLE: [bool; 2] = [false, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 2] {
            [self.j, self.c]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 2], __t: __D, __q: &[__D; 1]) -> [__D; 3] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.disc.position.x, __bodies.disc.position.y, __bodies.disc.angle]
        }
        #[inline(always)]
        fn applied_forces_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(
            &self,
            __p: &[__S; 2],
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 3],
            __x_dot: &[__D; 3],
            __cartesian_force: &mut [__D; 3],
            __generalized_force: &mut [__D; 1],
        ) {
            <Self as ::lagrange::__private::parameters::Parametrized<
                1,
                3,
                2,
            >>::applied_forces_with_inputs_held::<
                __S,
                __D,
            >(
                self,
                __p,
                &[],
                __t,
                __q,
                __v,
                __x,
                __x_dot,
                __cartesian_force,
                __generalized_force,
            )
        }
        #[allow(unused_variables, clippy::all)]
        fn applied_forces_with_inputs_held<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(
            &self,
            __p: &[__S; 2],
            __u: &[f64],
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 3],
            __x_dot: &[__D; 3],
            __cartesian_force: &mut [__D; 3],
            __generalized_force: &mut [__D; 1],
        ) {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let c: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[1]);
            let tau: __D = <__D>::from(__u.get(0).copied().unwrap_or(0.0));
            let [theta_dot] = *__v;
            let __generalized_force_drive: __D = { tau - c * theta_dot };
            __generalized_force[0] += __generalized_force_drive;
        }
    }
}
