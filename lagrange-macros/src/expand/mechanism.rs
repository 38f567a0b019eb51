//! The `Dynamics` impl (with `Prepare`): how the equations are evaluated, with or without the
//! constants a validated handle prepares, and the constraint hooks of a constrained mechanism.

mod hooks;

use super::{lit, private};
use crate::check::Chart;
use hooks::{constraint_hooks, quasi_velocities, switch_charts};
use proc_macro2::{Ident, Literal, TokenStream};
use quote::quote;

/// How `equations_of_motion_at` forms M, 𝓕 and b.
pub(super) enum Equations {
    /// The straight-line code of `expand::closed_form`, with its number of coefficients (what a
    /// validated handle prepares).
    ClosedForm(usize),
    /// `lagrange_core::tree` over a tree of translations (seed width, bodies).
    Tree(usize, usize),
    /// `lagrange_core::tree::rigid` over a kinematic tree of rigid bodies (bodies).
    Rigid(usize),
    /// The dual-number passes of `lagrange_core::dynamics`.
    Dense,
}

/// Whether the positions are affine in the coordinates (`crate::affine`), so a validated handle
/// prepares J and the factors of M.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum Positions {
    Affine {
        /// q̈ from the prepared constants is straight-line code that runs no user code: no force
        /// is declared, every potential's gradient is derived on its expression tree
        /// (`Model::potential_gradient`), and every constraint is holonomic with derivatives
        /// derived on its tree (`expand::constraints::written_holonomic`). Then `accelerations`
        /// through the handle checks a call in one branch (`lagrange_core::affine::regular_accelerations`,
        /// `lagrange_core::constraints::regular_accelerations_prepared`).
        straight_line: bool,
    },
    General,
}

/// What the `Dynamics` impl of a declaration is generated from.
pub(super) struct Glue<'a> {
    /// The parameter struct: the mechanism's type.
    pub(super) params: &'a Ident,
    /// Degrees of freedom N and Cartesian rows K.
    pub(super) n: usize,
    pub(super) k: usize,
    /// The number of constraint rows C, when there are any.
    pub(super) constrained: Option<usize>,
    pub(super) equations: Equations,
    pub(super) rheonomic: bool,
    pub(super) positions: Positions,
    /// The number of inputs, flat, when the declaration has `#[inputs]`.
    pub(super) inputs: Option<usize>,
    /// The rotations written in a chart of three coordinates.
    pub(super) charts: &'a [Chart],
    /// The charts' slots whose velocities are the angular velocity (`#[angular_velocity]`).
    pub(super) angular_velocities: &'a [[usize; 3]],
}

/// What a validated handle prepares.
#[derive(Clone, Copy)]
enum Prepared {
    /// J and the factors of the constant mass matrix (`crate::affine`); whether q̈ is then
    /// straight-line code (see [`Positions`]).
    Affine {
        straight_line: bool,
    },
    /// The closed form's coefficients (`expand::closed_form`).
    Coefficients(usize),
    /// A rigid tree's joint frames and inertias (`lagrange_core::tree::rigid::RigidConstants`),
    /// for its bodies.
    Rigid(usize),
    Nothing,
}

impl Glue<'_> {
    fn prepared(&self) -> Prepared {
        match (self.positions, &self.equations) {
            (Positions::Affine { straight_line }, _) => Prepared::Affine { straight_line },
            (_, Equations::ClosedForm(count)) => Prepared::Coefficients(*count),
            (_, Equations::Rigid(b)) => Prepared::Rigid(*b),
            _ => Prepared::Nothing,
        }
    }

    fn closed_form(&self) -> bool {
        matches!(self.equations, Equations::ClosedForm(_))
    }

    fn sizes(&self) -> (Literal, Literal) {
        (lit(self.n), lit(self.k))
    }

    /// The model the forces are evaluated on, as a type and a value: the declaration itself, or
    /// with inputs the declaration with the inputs its method's constants hold
    /// (`lagrange_core::inputs::WithInputs`).
    fn forces(&self) -> (TokenStream, TokenStream) {
        let p = private();
        match self.inputs {
            None => (quote!(Self), quote!(self)),
            Some(nu) => {
                let nu = lit(nu);
                let ty = quote!(#p::lagrange_core::inputs::WithInputs<'_, Self, f64, #nu>);
                let value = quote!(&#p::lagrange_core::inputs::WithInputs::<Self, f64, #nu>::held(self, __constants.inputs));
                (ty, value)
            }
        }
    }
}

/// The `Prepare` and `Dynamics` impls, forwarding to `lagrange_core`.
pub(super) fn mechanism_impl(glue: &Glue) -> TokenStream {
    let p = private();
    let (params, (n, k)) = (glue.params, glue.sizes());
    let prepare = prepare_impl(params, &n, &k, glue.prepared());
    let scleronomic = !glue.rheonomic;
    let closed_form = glue.closed_form();
    let (counts, contacts) = declared_rows(glue);
    let validate_constraints = glue.constrained.map(|c| {
        let c = lit(c);
        quote!(<Self as #p::lagrange_core::constraints::Constraints<#n, #k, #c>>::validate_constraints(self)?;)
    });
    let equations_of_motion = equations_of_motion(glue);
    let accelerations = accelerations(glue);
    let regular = regular_accelerations(glue);
    let canonical = canonical_field(glue);
    let (kinetic, inverse_dynamics) = (kinetic_energy(glue), inverse_dynamics(glue));
    let mass_matrix = mass_matrix(glue);
    let constraint_hooks = glue.constrained.map(|c| constraint_hooks(glue, lit(c)));
    let switch_charts = switch_charts(glue);
    let quasi_velocities = quasi_velocities(glue);
    let inputs = (glue.inputs).map(|nu| {
        let rigid = matches!(glue.equations, Equations::Rigid(_));
        super::inputs::dynamics_items((glue.n, glue.k, nu), glue.constrained, rigid)
    });
    quote! {
        #prepare
        impl #p::Dynamics<#n> for #params {
            type Coords = Coords;
            type Contacts = #contacts;
            const CONSTRAINT_COUNTS: #p::core::option::Option<#p::lagrange_core::constraints::ConstraintCounts> =
                #p::core::option::Option::Some(#counts);
            const SCLERONOMIC: bool = #scleronomic;
            const CLOSED_FORM: bool = #closed_form;
            #[inline]
            fn check_parameters(&self) -> #p::Result<()> {
                <Self as #p::Model<#n, #k>>::validate(self)?;
                #validate_constraints
                #p::core::result::Result::Ok(())
            }
            #equations_of_motion
            #mass_matrix
            #accelerations
            #regular
            #inverse_dynamics
            #kinetic
            #[inline]
            fn potential_energy_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n]) -> S {
            let _prepared = __constants.prepared;
                #p::dynamics::potential_energy::<Self, S, #n, #k>(self, t, q)
            }
            #[inline]
            fn lagrangian_time_derivative_at(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: f64, q: &[f64; #n], v: &[f64; #n]) -> f64 {
            let _prepared = __constants.prepared;
                #p::dynamics::lagrangian_time_derivative::<Self, #n, #k>(self, t, q, v)
            }
            #canonical
            #constraint_hooks
            #switch_charts
            #quasi_velocities
            #inputs
        }
    }
}

/// The declaration's constraint rows by kind, and its contact modes: `ContactState` over its rows
/// when it has any (the loops hold a mode only where unilateral or friction rows switch it), with
/// inputs `DrivenContacts` (the same mode, evaluated with the inputs the loop's call holds),
/// `NoContacts` otherwise. Declared, so integrators decide from the declaration which constraint
/// forces act.
fn declared_rows(glue: &Glue) -> (TokenStream, TokenStream) {
    let p = private();
    let (n, k) = glue.sizes();
    let constraints = quote!(#p::lagrange_core::constraints);
    match glue.constrained {
        Some(c) => {
            let c = lit(c);
            let counts = quote!(#constraints::ConstraintCounts::of(
                &<Self as #constraints::Constraints<#n, #k, #c>>::KINDS
            ));
            let contacts = match glue.inputs {
                None => quote!(#constraints::ContactState<#k, #c>),
                Some(nu) => {
                    let nu = lit(nu);
                    quote!(#p::lagrange_core::inputs::DrivenContacts<#k, #c, #nu>)
                }
            };
            (counts, contacts)
        }
        None => (
            quote!(#constraints::ConstraintCounts::NONE),
            quote!(#constraints::NoContacts),
        ),
    }
}

/// `equations_of_motion_at`: M, 𝓕 and b as the macro decided to form them (the prepared constants
/// are not used: the closed form's plain call computes its coefficients where it needs them).
fn equations_of_motion(glue: &Glue) -> TokenStream {
    let p = private();
    let (n, k) = glue.sizes();
    let (forces_ty, forces) = glue.forces();
    let body = match glue.equations {
        Equations::ClosedForm(_) => quote!(self.__lagrange_closed_form::<S>(q, v)),
        Equations::Tree(w, b) => {
            let (w, b) = (lit(w), lit(b));
            quote!(#p::tree::equations_of_motion::<Self, S, #n, #k, #w, #b>(self, t, q, v))
        }
        Equations::Rigid(b) => {
            let b = lit(b);
            with_rigid_constants(
                quote!(#p::tree::rigid::equations_of_motion::<#forces_ty, S, #n, #k, #b>(#forces, __k, t, q, v)),
            )
        }
        Equations::Dense => {
            quote!(#p::dynamics::equations_of_motion::<#forces_ty, S, #n, #k>(#forces, t, q, v))
        }
    };
    let prepared = prepared_argument(glue);
    quote! {
        #[inline(always)]
        fn equations_of_motion_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n]) -> #p::dynamics::EquationsOfMotion<S, #n> {
            let #prepared = __constants.prepared;
            #body
        }
    }
}

/// The name of the constants' argument of a method that evaluates the equations: used by a rigid
/// tree (its joint frames and inertias), not by the other forms.
fn prepared_argument(glue: &Glue) -> TokenStream {
    match glue.equations {
        Equations::Rigid(_) => quote!(prepared),
        _ => quote!(_prepared),
    }
}

/// `call`, with `__k` the rigid tree's constants: the handle's, or computed for the call on the
/// plain mechanism.
fn with_rigid_constants(call: TokenStream) -> TokenStream {
    let p = private();
    quote!({
        let __owned;
        let __k = match prepared {
            #p::core::option::Option::Some(__k) => __k,
            #p::core::option::Option::None => {
                __owned = self.__lagrange_rigid_constants();
                &__owned
            }
        };
        #call
    })
}

/// `kinetic_energy_at`: T by the rigid tree's recursion, or by the dual-number pass.
fn kinetic_energy(glue: &Glue) -> TokenStream {
    let p = private();
    let (n, k) = glue.sizes();
    let body = match glue.equations {
        Equations::Rigid(b) => {
            let b = lit(b);
            with_rigid_constants(
                quote!(#p::tree::rigid::kinetic_energy::<S, #n, #b>(&<Self as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS, __k, q, v)),
            )
        }
        _ => quote!(#p::dynamics::kinetic_energy::<Self, S, #n, #k>(self, t, q, v)),
    };
    let prepared = prepared_argument(glue);
    quote! {
        #[inline]
        fn kinetic_energy_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n]) -> S {
            let #prepared = __constants.prepared;
            #body
        }
    }
}

/// `mass_matrix_at` of a rigid tree: the composite-rigid-body algorithm alone (the default, from
/// the equations of motion, otherwise).
fn mass_matrix(glue: &Glue) -> Option<TokenStream> {
    let p = private();
    let n = lit(glue.n);
    let Equations::Rigid(b) = glue.equations else {
        return None;
    };
    let b = lit(b);
    let body = with_rigid_constants(quote!(
        #p::tree::rigid::mass_matrix::<S, #n, #b>(&<Self as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS, __k, q)
    ));
    Some(quote! {
        #[inline]
        fn mass_matrix_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, _t: S, q: &[S; #n]) -> #p::nalgebra::SMatrix<S, #n, #n> {
            let prepared = __constants.prepared;
            #body
        }
    })
}

/// `inverse_dynamics_at` of a rigid tree: the recursive Newton–Euler algorithm (the default, from
/// the equations of motion, otherwise).
fn inverse_dynamics(glue: &Glue) -> Option<TokenStream> {
    let p = private();
    let (_, forces) = glue.forces();
    let n = lit(glue.n);
    let Equations::Rigid(_) = glue.equations else {
        return None;
    };
    let body = with_rigid_constants(quote!(
        self.__lagrange_rigid_inverse_dynamics(#forces, __k, t, q, v, a)
    ));
    Some(quote! {
        #[inline]
        fn inverse_dynamics_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n], a: &[S; #n]) -> [S; #n] {
            let prepared = __constants.prepared;
            #body
        }
    })
}

/// `accelerations_at`: without the constants, the constrained solve, a tree's articulated-body
/// recursion where each coordinate moves one body, or the default (M q̈ = 𝓕 − b solved); with
/// them, an affine mechanism's prepared J and factors of M, or the closed form's prepared
/// coefficients. Nothing is generated where both are the default.
fn accelerations(glue: &Glue) -> Option<TokenStream> {
    let p = private();
    let (n, k) = glue.sizes();
    let (forces_ty, forces) = glue.forces();
    let constraints = quote!(#p::lagrange_core::constraints);
    let plain = match (&glue.equations, glue.constrained) {
        (_, Some(c)) => {
            let c = lit(c);
            Some(quote!(#constraints::accelerations::<#forces_ty, S, #n, #k, #c>(#forces, t, q, v)))
        }
        (Equations::Tree(w, b), None) => {
            let (w, b) = (lit(*w), lit(*b));
            Some(quote!(#p::tree::accelerations::<Self, S, #n, #k, #w, #b>(self, t, q, v)))
        }
        // The constants computed for the call: a validated handle prepares them once.
        (Equations::Rigid(_), None) => Some(quote!(self.__lagrange_rigid_accelerations(
            #forces,
            &self.__lagrange_rigid_constants(),
            t,
            q,
            v
        ))),
        _ => None,
    };
    let with_constants = match (glue.prepared(), glue.constrained) {
        (Prepared::Affine { .. }, Some(c)) => {
            let c = lit(c);
            Some(
                quote!(#constraints::accelerations_prepared::<#forces_ty, S, #n, #k, #c>(#forces, prepared, t, q, v)),
            )
        }
        (Prepared::Affine { .. }, None) => Some(
            quote!(#p::lagrange_core::affine::accelerations::<#forces_ty, S, #n, #k>(#forces, prepared, t, q, v)),
        ),
        (Prepared::Coefficients(_), _) => Some(quote!({
            let eom = self.__lagrange_closed_form_with::<S>(#p::core::option::Option::Some(prepared), q, v);
            #p::dynamics::solve_accelerations::<Coords, S, #n>(&eom, t, q)
        })),
        (Prepared::Rigid(_), None) => Some(quote!(
            self.__lagrange_rigid_accelerations(#forces, prepared, t, q, v)
        )),
        (Prepared::Rigid(_), Some(_)) | (Prepared::Nothing, _) => None,
    };
    if plain.is_none() && with_constants.is_none() {
        return None;
    }
    // The default: M q̈ = 𝓕 − b from the equations of motion.
    let plain = plain.unwrap_or_else(|| {
        quote!({
            let eom = <Self as #p::Dynamics<#n>>::equations_of_motion_at(self, #p::lagrange_core::evaluation::Constants::NONE.with_inputs(__constants.inputs), t, q, v);
            #p::dynamics::solve_accelerations::<Coords, S, #n>(&eom, t, q)
        })
    });
    let with_constants = with_constants.unwrap_or_else(|| plain.clone());
    Some(quote! {
        #[inline]
        fn accelerations_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n]) -> #p::Result<[S; #n]> {
            let prepared = __constants.prepared;
            match prepared {
                #p::core::option::Option::Some(prepared) => #with_constants,
                #p::core::option::Option::None => #plain,
            }
        }
    })
}

/// `regular_accelerations_at`, every check of a call in one branch where q̈ is straight-line code:
/// the closed form (its parameters' test joining the branch on the plain mechanism; checked once
/// through a handle), and through a handle an affine mechanism whose prepared q̈ runs no user code.
fn regular_accelerations(glue: &Glue) -> Option<TokenStream> {
    let p = private();
    let (n, k) = glue.sizes();
    let none = quote!(#p::core::option::Option::None);
    let plain = glue.closed_form().then(|| {
        quote!({
            let eom = self.__lagrange_closed_form::<f64>(q, v);
            let parameters_pass = <Self as #p::Model<#n, #k>>::parameters_pass(self);
            #p::dynamics::regular_accelerations::<#n>(&eom, t, q, v, parameters_pass)
        })
    });
    let with_constants = match (glue.prepared(), glue.constrained) {
        (
            Prepared::Affine {
                straight_line: true,
            },
            Some(c),
        ) => {
            let c = lit(c);
            Some(
                quote!(#p::lagrange_core::constraints::regular_accelerations_prepared::<Self, #n, #k, #c>(self, prepared, t, q, v)),
            )
        }
        (
            Prepared::Affine {
                straight_line: true,
            },
            None,
        ) => Some(
            quote!(#p::lagrange_core::affine::regular_accelerations::<Self, #n, #k>(self, prepared, t, q, v)),
        ),
        // Affine positions whose q̈ runs user code: the checked path, one check at a time.
        (Prepared::Affine { .. }, _) => plain.as_ref().map(|_| quote!(#none)),
        (Prepared::Coefficients(_), _) => Some(quote!({
            let eom = self.__lagrange_closed_form_with::<f64>(#p::core::option::Option::Some(prepared), q, v);
            #p::dynamics::regular_accelerations::<#n>(&eom, t, q, v, true)
        })),
        (Prepared::Rigid(_), _) | (Prepared::Nothing, _) => None,
    };
    if plain.is_none() && with_constants.is_none() {
        return None;
    }
    let plain = plain.unwrap_or_else(|| none.clone());
    let with_constants = with_constants.unwrap_or_else(|| plain.clone());
    Some(quote! {
        #[inline(always)]
        fn regular_accelerations_at(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: f64, q: &[f64; #n], v: &[f64; #n]) -> #p::core::option::Option<[f64; #n]> {
            let prepared = __constants.prepared;
            match prepared {
                #p::core::option::Option::Some(prepared) => #with_constants,
                #p::core::option::Option::None => #plain,
            }
        }
    })
}

/// `momenta_at` and `canonical_field_at`: in closed form (with the prepared coefficients through a
/// handle), otherwise a scleronomic mechanism's from one hyper-dual pass, else the defaults.
fn canonical_field(glue: &Glue) -> TokenStream {
    let p = private();
    let (n, k) = glue.sizes();
    let (forces_ty, forces) = glue.forces();

    let none = quote!(#p::core::option::Option::None);
    let prepared_argument = prepared_argument(glue);
    let momenta = match glue.equations {
        Equations::ClosedForm(_) => {
            quote!(self.__lagrange_canonical_field_with::<S>(#none, q, v).0)
        }
        Equations::Rigid(b) => {
            let b = lit(b);
            with_rigid_constants(
                quote!(#p::tree::rigid::momenta::<S, #n, #b>(&<Self as #p::tree::rigid::RigidTree<#n, #b>>::JOINTS, __k, q, v)),
            )
        }
        _ => quote!(#p::dynamics::momenta::<Self, S, #n, #k>(self, t, q, v)),
    };
    let field = match (&glue.equations, glue.prepared()) {
        (Equations::ClosedForm(_), Prepared::Coefficients(_)) => Some(quote!(
            self.__lagrange_canonical_field_with::<S>(prepared, q, v)
        )),
        (Equations::ClosedForm(_), _) => Some(quote!({
            let _ = prepared;
            self.__lagrange_canonical_field_with::<S>(#none, q, v)
        })),
        _ => (!glue.rheonomic).then(|| {
            quote!({
                let _ = prepared;
                #p::dynamics::canonical_field::<#forces_ty, S, #n, #k>(#forces, t, q, v)
            })
        }),
    };
    let inline = match glue.equations {
        Equations::ClosedForm(_) => quote!(#[inline(always)]),
        _ => quote!(#[inline]),
    };
    let field = field.map(|body| {
        quote! {
            #inline
            fn canonical_field_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n]) -> ([S; #n], [S; #n]) {
                let prepared = __constants.prepared;
                #body
            }
        }
    });
    quote! {
        #[inline]
        fn momenta_at<S: #p::Scalar>(&self, __constants: #p::lagrange_core::evaluation::Constants<'_, Self>, t: S, q: &[S; #n], v: &[S; #n]) -> [S; #n] {
            let #prepared_argument = __constants.prepared;
            #momenta
        }
        #field
    }
}

/// The `Prepare` impl (see [`Prepared`]).
fn prepare_impl(params: &Ident, n: &Literal, k: &Literal, prepared: Prepared) -> TokenStream {
    let p = private();
    match prepared {
        Prepared::Coefficients(count) => {
            let count = lit(count);
            quote! {
                impl #p::Prepare for #params {
                    type Prepared = [f64; #count];
                    #[inline]
                    fn prepare(&self) -> #p::Result<Self::Prepared> {
                        #p::core::result::Result::Ok(self.__lagrange_coefficients())
                    }
                }
            }
        }
        Prepared::Affine { straight_line } => {
            let one_branch = straight_line.then(|| {
                quote!(
                    const PREPARED_IN_ONE_BRANCH: bool = true;
                )
            });
            quote! {
                impl #p::Prepare for #params {
                    type Prepared = #p::lagrange_core::affine::AffineConstants<#n, #k>;
                    #one_branch
                    fn prepare(&self) -> #p::Result<Self::Prepared> {
                        #p::lagrange_core::affine::AffineConstants::of::<Self>(self)
                    }
                }
            }
        }
        Prepared::Rigid(b) => {
            let b = lit(b);
            quote! {
                impl #p::Prepare for #params {
                    type Prepared = #p::tree::rigid::RigidConstants<#b>;
                    #[inline]
                    fn prepare(&self) -> #p::Result<Self::Prepared> {
                        #p::core::result::Result::Ok(self.__lagrange_rigid_constants())
                    }
                }
            }
        }
        Prepared::Nothing => quote! {
            impl #p::Prepare for #params {
                type Prepared = ();
                #[inline(always)]
                fn prepare(&self) -> #p::Result<()> {
                    #p::core::result::Result::Ok(())
                }
            }
        },
    }
}
