//! The closed-form equations of motion ([`crate::symbolic`]) as straight-line code, in four
//! inherent functions:
//! - `__lagrange_coefficients()`: every distinct constant factor (of parameters, masses and
//!   constants as written) as an `f64` array — what a validated handle prepares once
//!   (`Prepare::Prepared`), since parameters do not change while it exists;
//! - `__lagrange_closed_form_with(k, q, q̇)`: M, 𝓕 and b from those coefficients (prepared, or
//!   computed after the trigonometric calls when `k` is `None`), the sines and
//!   cosines of the coordinates evaluated once each (one `sin_cos` where both appear) and each
//!   distinct product of variables once;
//! - `__lagrange_closed_form(q, q̇)`: the two together, what `equations_of_motion_at` calls;
//! - `__lagrange_canonical_field_with(k, q, q̇)`: the canonical field the methods on (q, p)
//!   evaluate, p = M q̇ and ṗ = ∂T/∂q + 𝓕 with T = ½ q̇ᵀ M q̇, so
//!   ∂T/∂qₖ = ½ Σᵢⱼ q̇ᵢ q̇ⱼ ∂Mᵢⱼ/∂qₖ: M's polynomials differentiated here ([`Poly::derivative`],
//!   d sin = cos, d cos = −sin), from the same coefficients.

use super::{lit, private, scalar};
use crate::check::Model;
use crate::symbolic::poly::{Atom, Monomial, Poly};
use crate::symbolic::Equations;
use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote, ToTokens};
use std::collections::{BTreeMap, BTreeSet};

/// The inherent impl holding the four functions, and the number of coefficients.
pub(super) fn closed_form_impl(model: &Model, equations: &Equations) -> (TokenStream, usize) {
    let mut out = Writer {
        params: model
            .params
            .iter()
            .map(|f| f.ident.to_token_stream())
            .collect(),
        coefficient_values: Vec::new(),
        coefficients: BTreeMap::new(),
        atoms: BTreeSet::new(),
        body: Body::default(),
    };
    // The entries first, in this order (it numbers the coefficients and products); the
    // coefficients' inputs once every entry has named its atoms.
    let motion = out.motion(equations);
    let canonical = out.canonical(equations);
    let constants = out.constant_inputs(model, equations);
    let count = out.coefficient_values.len();
    let coefficients = coefficients_fn(&out.coefficient_values, &constants);
    let motion = closed_form_fns(model, &motion, count);
    let canonical = canonical_field_fn(model, &canonical, count);
    let params_ident = model.params_ident;
    let tokens = quote! {
        impl #params_ident {
            #coefficients
            #motion
            #canonical
        }
    };
    (tokens, count)
}

/// The entries of the equations of motion M q̈ = 𝓕 − b, and the products and variables they use.
struct Motion {
    /// M's columns, `[Mᵢⱼ for i]` for each j.
    columns: Vec<TokenStream>,
    forces: Vec<TokenStream>,
    inertial: Vec<TokenStream>,
    body: Body,
}

/// The entries of the canonical field (p, ṗ), and the products and variables they use.
struct Canonical {
    momenta: Vec<TokenStream>,
    rates: Vec<TokenStream>,
    body: Body,
}

/// `__lagrange_coefficients()`: the `f64` coefficients from the parameters, constants and masses.
fn coefficients_fn(coefficients: &[TokenStream], constants: &TokenStream) -> TokenStream {
    let count = lit(coefficients.len());
    let prelude = super::prelude();
    quote! {
        /// The constant factors of the closed-form equations of motion.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_coefficients(&self) -> [f64; #count] {
            #prelude
            #constants
            [#(#coefficients),*]
        }
    }
}

/// `__lagrange_closed_form(q, q̇)` and `__lagrange_closed_form_with(k, q, q̇)`: M, 𝓕 and b.
fn closed_form_fns(model: &Model, motion: &Motion, count: usize) -> TokenStream {
    let (p, d) = (private(), scalar());
    let n = lit(model.dof());
    let count = lit(count);
    let opening = motion.body.opening(model, &count);
    let Motion {
        columns,
        forces,
        inertial,
        ..
    } = motion;
    quote! {
        #[inline(always)]
        fn __lagrange_closed_form<#d: #p::Scalar>(
            &self,
            __q: &[#d; #n],
            __v: &[#d; #n],
        ) -> #p::dynamics::EquationsOfMotion<#d, #n> {
            self.__lagrange_closed_form_with(#p::core::option::Option::None, __q, __v)
        }
        /// With the coefficients prepared (`Some`) or computed here (`None`), after the sines
        /// and cosines: values computed before those calls would be kept on the stack across
        /// them.
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_closed_form_with<#d: #p::Scalar>(
            &self,
            __prepared: #p::core::option::Option<&[f64; #count]>,
            __q: &[#d; #n],
            __v: &[#d; #n],
        ) -> #p::dynamics::EquationsOfMotion<#d, #n> {
            #opening
            #p::dynamics::EquationsOfMotion::from_columns(
                [#(#columns),*],
                [#(#forces),*],
                [#(#inertial),*],
            )
        }
    }
}

/// `__lagrange_canonical_field_with(k, q, q̇)`: (p, ṗ).
fn canonical_field_fn(model: &Model, canonical: &Canonical, count: usize) -> TokenStream {
    let (p, d) = (private(), scalar());
    let n = lit(model.dof());
    let count = lit(count);
    let opening = canonical.body.opening(model, &count);
    let Canonical { momenta, rates, .. } = canonical;
    quote! {
        /// The canonical field (p, ṗ) = (M q̇, ∂T/∂q + 𝓕), with the coefficients prepared
        /// (`Some`) or computed here (`None`).
        #[inline(always)]
        #[allow(unused_variables, non_snake_case, clippy::all)]
        fn __lagrange_canonical_field_with<#d: #p::Scalar>(
            &self,
            __prepared: #p::core::option::Option<&[f64; #count]>,
            __q: &[#d; #n],
            __v: &[#d; #n],
        ) -> ([#d; #n], [#d; #n]) {
            #opening
            ([#(#momenta),*], [#(#rates),*])
        }
    }
}

/// `__k`: the prepared coefficients, or those computed here after the trigonometric calls.
fn select_coefficients(count: &Literal) -> TokenStream {
    let p = private();
    quote! {
        let __computed: [f64; #count];
        let __k: &[f64; #count] = match __prepared {
            #p::core::option::Option::Some(__k) => __k,
            #p::core::option::Option::None => {
                __computed = self.__lagrange_coefficients();
                &__computed
            }
        };
    }
}

/// The canonical field's polynomials from M and 𝓕: pᵢ = Σⱼ Mᵢⱼ q̇ⱼ and
/// ṗₖ = ∂T/∂qₖ + 𝓕ₖ, T = ½ q̇ᵀ M q̇ = Σᵢ ½ Mᵢᵢ q̇ᵢ² + Σᵢ>ⱼ Mᵢⱼ q̇ᵢ q̇ⱼ (the Euler–Lagrange equations
/// in momentum form, d/dt ∂L/∂q̇ = ∂L/∂q, with 𝓕 holding the field's −∂V/∂q; Goldstein, Poole &
/// Safko, *Classical Mechanics*, 3rd ed., §1.4), ∂T/∂qₖ brought to its normal form modulo
/// sin² + cos² = 1.
fn canonical_field(equations: &Equations) -> (Vec<Poly>, Vec<Poly>) {
    let m = &equations.mass_matrix;
    let n = m.len();
    let velocity = |j: usize| Poly::atom(Atom::Vel(j));
    let entry = |i: usize, j: usize| if i >= j { &m[i][j] } else { &m[j][i] };
    let momenta = (0..n)
        .map(|i| {
            (0..n).fold(Poly::zero(), |sum, j| {
                sum.add(&entry(i, j).mul(&velocity(j)))
            })
        })
        .collect();
    let mut kinetic = Poly::zero();
    for (i, row) in m.iter().enumerate() {
        for (j, mij) in row.iter().enumerate() {
            let term = mij.mul(&velocity(i)).mul(&velocity(j));
            kinetic = kinetic.add(&if i == j { term.scale(0.5) } else { term });
        }
    }
    let rates = (0..n)
        .map(|k| {
            kinetic
                .derivative(k)
                .reduce()
                .add(&equations.generalized_forces[k])
        })
        .collect();
    (momenta, rates)
}

/// What the entries written so far share: the coefficients (`__k[i]`) by their constant
/// polynomial and the atoms they name; the function being written (its products and variables)
/// is [`Body`].
struct Writer {
    /// The parameters' names, by index.
    params: Vec<TokenStream>,
    /// The `f64` coefficients' values, `__k[i]` in the equations.
    coefficient_values: Vec<TokenStream>,
    coefficients: BTreeMap<String, TokenStream>,
    /// Every atom named, by the coefficients and by every function.
    atoms: BTreeSet<Atom>,
    body: Body,
}

/// One function's share: the products of variables by their monomial, and the variables named.
#[derive(Default)]
struct Body {
    /// Products of variables on `__D`, by name.
    product_lets: Vec<(Ident, TokenStream)>,
    products: BTreeMap<Monomial, TokenStream>,
    variables: BTreeSet<Atom>,
}

impl Writer {
    /// M (its lower triangle written, column j read from it), 𝓕 and b, in that order.
    fn motion(&mut self, equations: &Equations) -> Motion {
        let lower: Vec<Vec<TokenStream>> = equations
            .mass_matrix
            .iter()
            .map(|row| row.iter().map(|m| self.entry(m)).collect())
            .collect();
        let forces = equations
            .generalized_forces
            .iter()
            .map(|f| self.entry(f))
            .collect();
        let inertial = equations
            .inertial_terms
            .iter()
            .map(|b| self.entry(b))
            .collect();
        // Column j of the symmetric M: Mᵢⱼ from the lower triangle.
        let n = lower.len();
        let columns = (0..n)
            .map(|j| {
                let column = (0..n).map(|i| {
                    let (r, c) = if i >= j { (i, j) } else { (j, i) };
                    &lower[r][c]
                });
                quote!([#(#column),*])
            })
            .collect();
        Motion {
            columns,
            forces,
            inertial,
            body: std::mem::take(&mut self.body),
        }
    }

    /// p and ṗ ([`canonical_field`]), in that order.
    fn canonical(&mut self, equations: &Equations) -> Canonical {
        let (momenta, rates) = canonical_field(equations);
        Canonical {
            momenta: momenta.iter().map(|p| self.entry(p)).collect(),
            rates: rates.iter().map(|r| self.entry(r)).collect(),
            body: std::mem::take(&mut self.body),
        }
    }

    /// An entry on `__D`, factored as Σ (± products of sines, cosines and coordinates) ×
    /// coefficient × product of velocities: the terms that share a velocity product and a
    /// coefficient up to its sign are summed before they are scaled (the double pendulum's
    /// M₁₂ = m₂ l₁ l₂ (sin θ₁ sin θ₂ + cos θ₁ cos θ₂): one product by the coefficient, not two).
    fn entry(&mut self, poly: &Poly) -> TokenStream {
        let d = scalar();
        type Members = Vec<(bool, Monomial)>;
        let mut groups: BTreeMap<(Monomial, String), (Poly, Members)> = BTreeMap::new();
        for (variables, coefficient) in poly.by_variables() {
            let (velocities, positions): (Monomial, Monomial) = variables
                .into_iter()
                .partition(|(a, _)| matches!(a, Atom::Vel(_)));
            let negative = coefficient.terms.values().next().is_some_and(|&c| c < 0.0);
            let coefficient = if negative {
                coefficient.scale(-1.0)
            } else {
                coefficient
            };
            let key = (velocities, format!("{coefficient:?}"));
            groups
                .entry(key)
                .or_insert_with(|| (coefficient, Vec::new()))
                .1
                .push((negative, positions));
        }
        let terms: Vec<(bool, TokenStream)> = groups
            .into_iter()
            .map(|((velocities, _), (coefficient, members))| {
                let velocities = self.product(&velocities);
                if let [(negative, positions)] = &members[..] {
                    if positions.is_empty() {
                        // A constant times the velocities.
                        let sign = if *negative { -1.0 } else { 1.0 };
                        let c = self.coefficient(&coefficient.scale(sign));
                        let c = quote!(<#d>::from(#c));
                        return (false, velocities.map_or(c.clone(), |v| quote!(#v * #c)));
                    }
                }
                // The group's sign taken out so that its first member is positive: b has
                // sin θ₁ cos θ₂ − cos θ₁ sin θ₂ in one entry and its negative in another, and
                // the compiler evaluates the one difference once.
                let negative = members[0].0;
                let mut sum = TokenStream::new();
                for (k, (member_negative, positions)) in members.iter().enumerate() {
                    let x = self
                        .product(positions)
                        .unwrap_or_else(|| quote!(<#d>::from(1.0)));
                    sum.extend(match (k, member_negative != &negative) {
                        (0, _) => quote!(#x),
                        (_, false) => quote!(+ #x),
                        (_, true) => quote!(- #x),
                    });
                }
                let mut term = if members.len() > 1 {
                    quote!((#sum))
                } else {
                    sum
                };
                if coefficient.as_number() != Some(1.0) {
                    let c = self.coefficient(&coefficient);
                    term = quote!(#term * #c);
                }
                if let Some(v) = velocities {
                    term = quote!(#term * #v);
                }
                (negative, term)
            })
            .collect();
        let mut out = TokenStream::new();
        for (k, (negative, term)) in terms.iter().enumerate() {
            out.extend(match (k, negative) {
                (0, false) => quote!(#term),
                (0, true) => quote!(-#term),
                (_, false) => quote!(+ #term),
                (_, true) => quote!(- #term),
            });
        }
        if terms.is_empty() {
            out = quote!(<#d>::from(0.0));
        }
        out
    }

    /// The `f64` value of a constant polynomial: a literal, or `__k[i]`, shared by every use.
    fn coefficient(&mut self, coefficient: &Poly) -> TokenStream {
        if let Some(c) = coefficient.as_number() {
            return number(c);
        }
        let key = format!("{coefficient:?}");
        if let Some(k) = self.coefficients.get(&key) {
            return k.clone();
        }
        let i = lit(self.coefficient_values.len());
        let value = self.constant_expr(coefficient);
        self.coefficient_values.push(value);
        self.coefficients.insert(key, quote!(__k[#i]));
        quote!(__k[#i])
    }

    /// Σ c Π atomᵉ in `f64`, a negative exponent as a quotient.
    fn constant_expr(&mut self, poly: &Poly) -> TokenStream {
        let terms: Vec<TokenStream> = poly
            .terms
            .iter()
            .map(|(monomial, &c)| {
                let mut term = (c != 1.0 || monomial.is_empty()).then(|| number(c));
                for &(atom, e) in monomial {
                    let a = self.atom(atom);
                    for _ in 0..e.abs() {
                        term = Some(match (term, e > 0) {
                            (None, true) => quote!(#a),
                            (None, false) => quote!(1.0 / #a),
                            (Some(t), true) => quote!(#t * #a),
                            (Some(t), false) => quote!(#t / #a),
                        });
                    }
                }
                term.expect("a term has a factor")
            })
            .collect();
        let (first, rest) = terms.split_first().expect("a coefficient is not zero");
        quote!(#first #(+ #rest)*)
    }

    /// A product of variables on `__D` (`None` for the empty product), shared by every use; a
    /// negative exponent (1/r) as a quotient.
    fn product(&mut self, variables: &Monomial) -> Option<TokenStream> {
        let mut factors: Vec<(TokenStream, bool)> = Vec::new();
        for &(atom, e) in variables {
            let a = self.atom(atom);
            factors.extend(std::iter::repeat_n((a, e > 0), e.unsigned_abs() as usize));
        }
        if let [(a, true)] = &factors[..] {
            return Some(a.clone());
        }
        if factors.is_empty() {
            return None;
        }
        if let Some(ident) = self.body.products.get(variables) {
            return Some(ident.clone());
        }
        let d = scalar();
        let mut value = quote!(<#d>::from(1.0));
        for (k, (a, multiply)) in factors.iter().enumerate() {
            value = match (k, multiply) {
                (0, true) => quote!(#a),
                (_, true) => quote!(#value * #a),
                (_, false) => quote!(#value / #a),
            };
        }
        let ident = format_ident!("__product_{}", self.body.products.len());
        self.body.product_lets.push((ident.clone(), value));
        self.body.products.insert(variables.clone(), quote!(#ident));
        Some(quote!(#ident))
    }

    /// The name an atom is bound to (see [`Writer::inputs`]).
    fn atom(&mut self, atom: Atom) -> TokenStream {
        self.atoms.insert(atom);
        if atom.is_variable() {
            self.body.variables.insert(atom);
        }
        match atom {
            Atom::Param(i) => self.params[i].clone(),
            Atom::Constant(i) => format_ident!("__constant_{}", i).into_token_stream(),
            Atom::Mass(r) => {
                let r = lit(r);
                quote!(__masses[#r])
            }
            Atom::Sin(j) => format_ident!("__sin_{}", j).into_token_stream(),
            Atom::Cos(j) => format_ident!("__cos_{}", j).into_token_stream(),
            Atom::Coord(j) => {
                let j = lit(j);
                quote!(__q[#j])
            }
            Atom::Vel(j) => {
                let j = lit(j);
                quote!(__v[#j])
            }
        }
    }

    /// The bindings the coefficients use: the parameters by name, the constants as written and
    /// the masses.
    fn constant_inputs(&self, model: &Model, equations: &Equations) -> TokenStream {
        let (p, n, k) = (private(), lit(model.dof()), lit(model.rows));
        let mut out = TokenStream::new();
        out.extend(model.params.iter().map(|f| f.bind_f64()));
        for (i, constant) in equations.constants.iter().enumerate() {
            if self.atoms.contains(&Atom::Constant(i)) {
                let ident = format_ident!("__constant_{}", i);
                out.extend(quote!(let #ident: f64 = #constant;));
            }
        }
        if self.atoms.iter().any(|a| matches!(a, Atom::Mass(_))) {
            out.extend(quote!(let __masses = <Self as #p::Model<#n, #k>>::masses(self);));
        }
        out
    }
}

impl Body {
    /// What the function opens with: the prelude, its sines and cosines, the coefficients
    /// (after the trigonometric calls) and its products.
    fn opening(&self, model: &Model, count: &Literal) -> TokenStream {
        let prelude = super::prelude();
        let variables = self.variable_inputs(model);
        let select_coefficients = select_coefficients(count);
        // One `let` for the products: each `let` opens a scope, and thousands of nested scopes (a
        // chain of 64 links) overflow the compiler's stack when it writes debug information.
        let products = tuple_let(&self.product_lets);
        quote! {
            #prelude
            #variables
            #select_coefficients
            #products
        }
    }

    /// The sines and cosines used: one `sin_cos` per coordinate whose sine and cosine both
    /// appear.
    fn variable_inputs(&self, model: &Model) -> TokenStream {
        let mut out = TokenStream::new();
        for j in 0..model.dof() {
            let (sin, cos) = (format_ident!("__sin_{}", j), format_ident!("__cos_{}", j));
            let jl = lit(j);
            match (
                self.variables.contains(&Atom::Sin(j)),
                self.variables.contains(&Atom::Cos(j)),
            ) {
                (true, true) => out.extend(quote!(let (#sin, #cos) = __q[#jl].sin_cos();)),
                (true, false) => out.extend(quote!(let #sin = __q[#jl].sin();)),
                (false, true) => out.extend(quote!(let #cos = __q[#jl].cos();)),
                (false, false) => {}
            }
        }
        out
    }
}

/// `let (a, b, …) = (value of a, value of b, …);`, nothing for no names.
fn tuple_let(lets: &[(Ident, TokenStream)]) -> TokenStream {
    if lets.is_empty() {
        return TokenStream::new();
    }
    let (names, values): (Vec<_>, Vec<_>) = lets.iter().cloned().unzip();
    quote!(let (#(#names,)*) = (#(#values,)*);)
}

/// An `f64` literal, negative ones parenthesised.
fn number(c: f64) -> TokenStream {
    let literal = crate::symbolic::expr::f64_tokens(c.abs());
    if c < 0.0 {
        quote!((-#literal))
    } else {
        quote!(#literal)
    }
}
