pub mod pendulum {
    pub struct Pendulum {
        pub m: f64,
        pub l: f64,
        pub g: f64,
        pub c: f64,
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
        pub bob: ::lagrange::__private::geometry::Vec2<T>,
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
        pub bob: ::lagrange::__private::geometry::Vec2<T>,
    }
    impl Pendulum {
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
                2,
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
            let l = <__D>::from(self.l);
            let (__sin_theta, __cos_theta) = theta.sin_cos();
            let bob: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(__sin_theta, -__cos_theta) * l
            };
            Bodies { bob }
        }
        #[inline(always)]
        fn __lagrange_bodies_from_cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __x: &[__D; 2],
        ) -> Bodies<__D> {
            Bodies {
                bob: ::lagrange::__private::geometry::vec2(__x[0], __x[1]),
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
                bob: ::lagrange::__private::geometry::vec2(__x_dot[0], __x_dot[1]),
            }
        }
    }
    impl ::lagrange::__private::Model<1, 2> for Pendulum {
        type Coords = Coords;
        const INERTIAL: usize = 2;
        const RHEONOMIC: bool = false;
        const HAS_POTENTIAL: bool = false;
        const HAS_FORCES: bool = true;
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn parameters_pass(&self) -> bool {
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let c: f64 = self.c;
            let __mass_bob: f64 = m;
            ((0.0 + self.m + self.l + self.g + self.c + __mass_bob) * 0.0 == 0.0)
                & (__mass_bob > 0.0)
        }
        #[allow(unused_variables, clippy::all)]
        fn validate(&self) -> ::lagrange::__private::Result<()> {
            if <Self as ::lagrange::__private::Model<1, 2>>::parameters_pass(self) {
                return ::lagrange::__private::core::result::Result::Ok(());
            }
            if !self.m.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "m",
                    value: self.m,
                });
            }
            if !self.l.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "l",
                    value: self.l,
                });
            }
            if !self.g.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "g",
                    value: self.g,
                });
            }
            if !self.c.is_finite() {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::NonFiniteParameter {
                    name: "c",
                    value: self.c,
                });
            }
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let c: f64 = self.c;
            let __mass_bob: f64 = m;
            if !(__mass_bob.is_finite() && __mass_bob > 0.0) {
                return ::lagrange::__private::core::result::Result::Err(::lagrange::__private::Error::InvalidInertia {
                    body: "bob",
                    reason: ::lagrange::__private::std::format!(
                        "mass must be positive and finite, got {}", __mass_bob
                    ),
                });
            }
            ::lagrange::__private::core::result::Result::Ok(())
        }
        #[allow(unused_variables, clippy::all)]
        fn masses(&self) -> [f64; 2] {
            let m: f64 = self.m;
            let l: f64 = self.l;
            let g: f64 = self.g;
            let c: f64 = self.c;
            let __mass_bob: f64 = m;
            [__mass_bob, __mass_bob]
        }
        #[inline(always)]
        fn cartesian<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
        ) -> [__D; 2] {
            let __bodies = self.__lagrange_bodies(__t, __q);
            [__bodies.bob.x, __bodies.bob.y]
        }
        #[allow(unused_variables, clippy::all)]
        fn applied_forces<__D: ::lagrange::__private::Scalar>(
            &self,
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 2],
            __x_dot: &[__D; 2],
            __cartesian_force: &mut [__D; 2],
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
            let __param_0: __D = <__D>::from({
                let c: f64 = self.c;
                -c
            });
            let [theta_dot] = *__v;
            let BodyVelocities { bob: bob_dot } = self
                .__lagrange_velocities_from_cartesian(__x, __x_dot);
            let __force_drag: ::lagrange::__private::geometry::Vec2<__D> = {
                bob_dot * (__param_0)
            };
            __cartesian_force[0] += __force_drag.x;
            __cartesian_force[1] += __force_drag.y;
        }
        const HAS_GRAVITY: bool = true;
        #[allow(unused_variables, clippy::all)]
        fn weights(&self) -> [f64; 2] {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{vec2, vec3};
            let g: f64 = self.g;
            let __masses = <Self as ::lagrange::__private::Model<1, 2>>::masses(self);
            let mut __weights = [0.0; 2];
            let __gravity_down: ::lagrange::__private::geometry::Vec2<f64> = {
                vec2(0.0, -g)
            };
            __weights[0] += __gravity_down.x * __masses[0];
            __weights[1] += __gravity_down.y * __masses[1];
            __weights
        }
    }
    impl ::lagrange::__private::Prepare for Pendulum {
        type Prepared = ();
        #[inline(always)]
        fn prepare(&self) -> ::lagrange::__private::Result<()> {
            ::lagrange::__private::core::result::Result::Ok(())
        }
    }
    impl ::lagrange::__private::Dynamics<1> for Pendulum {
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
            <Self as ::lagrange::__private::Model<1, 2>>::validate(self)?;
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
                Self,
                S,
                1,
                2,
            >(self, t, q, v)
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
            q: &[S; 1],
        ) -> S {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::potential_energy::<
                Self,
                S,
                1,
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
            q: &[f64; 1],
            v: &[f64; 1],
        ) -> f64 {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::lagrangian_time_derivative::<
                Self,
                1,
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
            q: &[S; 1],
            v: &[S; 1],
        ) -> [S; 1] {
            let _prepared = __constants.prepared;
            ::lagrange::__private::dynamics::momenta::<Self, S, 1, 2>(self, t, q, v)
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
                    Self,
                    S,
                    1,
                    2,
                >(self, t, q, v)
            }
        }
    }
    impl ::lagrange::__private::lagrange_core::declaration::Declaration for Pendulum {
        const DOF: usize = 1;
        const PARAMETERS: &'static [&'static str] = &["m", "l", "g", "c"];
        fn from_parameters(
            values: &[f64],
        ) -> ::lagrange::__private::core::option::Option<Self> {
            if values.len() != Self::PARAMETERS.len() {
                return ::lagrange::__private::core::option::Option::None;
            }
            ::lagrange::__private::core::option::Option::Some(Pendulum {
                m: values[0],
                l: values[1],
                g: values[2],
                c: values[3],
            })
        }
        fn parameters(&self) -> ::lagrange::__private::std::vec::Vec<f64> {
            ::lagrange::__private::std::vec![self.m, self.l, self.g, self.c]
        }
    }
    impl ::lagrange::__private::lagrange_core::animation::Drawable<1> for Pendulum {
        const BODIES: &'static [::lagrange::__private::lagrange_core::animation::BodyLayout] = &[
            ::lagrange::__private::lagrange_core::animation::BodyLayout {
                name: "bob",
                shape: ::lagrange::__private::lagrange_core::animation::Shape::Particle2,
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
            rows.extend_from_slice(&[__bodies.bob.x, __bodies.bob.y]);
        }
    }
    impl Pendulum {
        #[inline(always)]
        #[allow(unused_variables, clippy::all)]
        fn __lagrange_bodies_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 4], __t: __D, __q: &[__D; 1]) -> Bodies<__D> {
            #[allow(unused_imports)]
            use ::lagrange::__private::geometry::{
                planar, rot3, rot_axis, rot_mrp, rot_vector, rot_x, rot_y, rot_z, rpy,
                spatial, vec2, vec3, Planar, Rot3, Spatial, Vec2, Vec3,
            };
            #[allow(unused_imports)]
            use ::lagrange::__private::DualNum as _;
            let [theta] = *__q;
            let l: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[1]);
            let (__sin_theta, __cos_theta) = theta.sin_cos();
            let bob: ::lagrange::__private::geometry::Vec2<__D> = {
                vec2(__sin_theta, -__cos_theta) * l
            };
            Bodies { bob }
        }
    }
    impl ::lagrange::__private::parameters::Parametrized<1, 2, 4> for Pendulum {
        const PARAMETER_NAMES: [&'static str; 4] = ["m", "l", "g", "c"];
        const SEEDABLE: [bool; 4] = [false, true, false, true];
        #[inline(always)]
        fn parameters(&self) -> [f64; 4] {
            [self.m, self.l, self.g, self.c]
        }
        #[inline(always)]
        fn cartesian_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(&self, __p: &[__S; 4], __t: __D, __q: &[__D; 1]) -> [__D; 2] {
            let __bodies = self.__lagrange_bodies_with(__p, __t, __q);
            [__bodies.bob.x, __bodies.bob.y]
        }
        #[allow(unused_variables, clippy::all)]
        fn applied_forces_with<
            __S: ::lagrange::__private::Scalar,
            __D: ::lagrange::__private::Scalar,
        >(
            &self,
            __p: &[__S; 4],
            __t: __D,
            __q: &[__D; 1],
            __v: &[__D; 1],
            __x: &[__D; 2],
            __x_dot: &[__D; 2],
            __cartesian_force: &mut [__D; 2],
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
            let c: __D = ::lagrange::__private::parameters::lift::<__S, __D>(&__p[3]);
            let [theta_dot] = *__v;
            let BodyVelocities { bob: bob_dot } = self
                .__lagrange_velocities_from_cartesian(__x, __x_dot);
            let __force_drag: ::lagrange::__private::geometry::Vec2<__D> = {
                bob_dot * (-c)
            };
            __cartesian_force[0] += __force_drag.x;
            __cartesian_force[1] += __force_drag.y;
        }
    }
}
