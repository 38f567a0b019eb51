//! The equations of motion in closed form, derived by the macro when every position is a
//! polynomial in the coordinates and their sines and cosines (a pendulum, a double pendulum, a
//! pendulum on a cart, a chain of links declared one by one).
//!
//! With x(q) read as polynomials ([`read`]), the terms of M q̈ = 𝓕 − b (Goldstein, Poole & Safko,
//! *Classical Mechanics*, 3rd ed., §1.4; the notation of `lagrange_core::dynamics`) are
//! polynomials too, formed here by exact differentiation:
//!
//! ```text
//! Jᵣⱼ = ∂xᵣ/∂qⱼ,   Mᵢⱼ = Σᵣ μᵣ Jᵣᵢ Jᵣⱼ,   aᵣ = Σⱼₖ ∂²xᵣ/∂qⱼ∂qₖ q̇ⱼ q̇ₖ,   bᵢ = Σᵣ μᵣ Jᵣᵢ aᵣ,
//! 𝓕ᵢ = Σᵣ wᵣ Jᵣᵢ   (a uniform field g: wᵣ = μᵣ gₖ on the k-th position row of a body),
//! ```
//!
//! each brought to its normal form modulo sin² + cos² = 1 ([`poly::Poly::reduce`]). The
//! simplification is what dual numbers cannot do: the pendulum's M = m l² (cos² θ + sin² θ) is the
//! constant m l², its b = m l² θ̇² (−sin θ cos θ + cos θ sin θ) vanishes, and only sin θ is left to
//! evaluate, as in θ̈ = −(g/l) sin θ written by hand. `expand::closed_form` writes the
//! polynomials out as straight-line code.
//!
//! The path is taken when the declaration is scleronomic and unconstrained, its bodies are
//! particles, points and planar bodies declared one by one (no family, no spatial body; a planar
//! body's `com` turned by its angle, read like `Planar::point`), its only
//! field is uniform and it has no potential and no force; and every position is read (an array
//! coordinate by literal indices), with no sum of coordinates multiplying the same factor unless
//! the row is affine in the coordinates (its derivatives are then constants). Otherwise the dual-number passes of `lagrange_core::dynamics` serve it.
//!
//! That last rule, and leaving potentials to the dual numbers, keep the closed form as accurate as
//! the dual-number passes. Expanded, a polynomial in a difference of coordinates cancels: a spring's
//! ¼ k (q₂ − q₁)⁴ has the gradient k (q₂ − q₁)³, whose expansion q₂³ − 3 q₂² q₁ + … loses every
//! digit the difference has below the coordinates' size; so would a pendulum of length q₂ − q₁,
//! whose M has (q₂ − q₁)². Sines and cosines expand safely: sin θ₁ sin θ₂ + cos θ₁ cos θ₂ is
//! cos(θ₁ − θ₂) to an error of the size of M's entries, as in the hand-derived forms.

pub mod constraint_rows;
pub mod expr;
pub mod gradient;
pub mod poly;
pub mod read;
pub mod read_tree;

use crate::check::{Body, Dim, Model, Shape};
use poly::{Atom, Poly};
use proc_macro2::TokenStream;
use read::{Reader, Value};
use std::collections::HashMap;

/// The closed-form terms of M q̈ = 𝓕 − b.
pub struct Equations {
    /// Mᵢⱼ for j ≤ i (the lower triangle, row by row).
    pub mass_matrix: Vec<Vec<Poly>>,
    /// 𝓕: a uniform field's generalized forces (zero without one).
    pub generalized_forces: Vec<Poly>,
    /// b: the velocity-product terms.
    pub inertial_terms: Vec<Poly>,
    /// The opaque constants the positions name, as written ([`Atom::Constant`]).
    pub constants: Vec<TokenStream>,
}

/// The closed-form equations of `model`, or `None` when the declaration is not of the kind read
/// (see the module docs).
pub fn equations(model: &Model) -> Option<Equations> {
    if !read_in_closed_form(model) {
        return None;
    }
    let (coords, arrays) = coordinate_slots(model);
    // An array of parameters is read by element (`m[2]`), as an opaque constant.
    let params = model
        .params
        .iter()
        .enumerate()
        .filter(|(_, p)| p.array.is_none())
        .map(|(i, p)| (p.ident.to_string(), i))
        .collect();
    let mut reader = Reader::new(coords, arrays, params);
    let fields = uniform_fields(model, &mut reader)?;
    let mut rows: Vec<Row> = Vec::new();
    for body in &model.bodies {
        let value = reader.block(&body.decl.block)?;
        let field = &fields[(body.shape.dim() == Dim::Three) as usize];
        rows.extend(body_rows(&mut reader, body, &value, field)?);
        reader.define_body(body.decl.ident().to_string(), value);
    }
    if !rows.iter().all(|row| free_of_cancellation(&row.x)) {
        return None;
    }
    let equations = assemble(model, &rows, reader.constants)?;
    (equations.terms() <= MAX_TERMS && equations.has_finite_factors()).then_some(equations)
}

/// Whether the declaration is of the kind read: scleronomic, no constraint, no potential or force
/// but uniform fields, single bodies, none spatial.
fn read_in_closed_form(model: &Model) -> bool {
    !model.rheonomic
        && model.constraints.is_empty()
        && model.potentials.is_empty()
        && model.gravities.is_empty()
        && model.forces.is_empty()
        && !model.bodies.is_empty()
        && model
            .bodies
            .iter()
            .all(|b| b.count.is_none() && b.shape != Shape::Spatial)
}

/// The uniform fields, summed by dimension (`[planar, spatial]`): constant vectors, their zero
/// components known; `None` when one is not a constant vector.
fn uniform_fields(model: &Model, reader: &mut Reader) -> Option<[Option<Vec<Poly>>; 2]> {
    let mut fields: [Option<Vec<Poly>>; 2] = [None, None];
    for (decl, dim) in &model.uniform_gravities {
        let Value::Vector(g) = reader.block(&decl.block)? else {
            return None;
        };
        if !g.iter().all(Poly::is_constant) {
            return None;
        }
        let field = &mut fields[(*dim == Dim::Three) as usize];
        *field = Some(match field.take() {
            Some(sum) => sum.iter().zip(&g).map(|(a, b)| a.add(b)).collect(),
            None => g,
        });
    }
    Some(fields)
}

/// The rows of x of a body whose function reads as `value`, with their masses and, in the
/// uniform field `field` of the body's dimension, their weights.
fn body_rows(
    reader: &mut Reader,
    body: &Body,
    value: &Value,
    field: &Option<Vec<Poly>>,
) -> Option<Vec<Row>> {
    // A planar body declared by its frame enters x by its centre of mass.
    let mass_frame = match &body.decl.args.com {
        Some(com) => reader.centre_of_mass(value, com)?,
        None => value.clone(),
    };
    let components = match (&mass_frame, body.shape) {
        (Value::Vector(v), Shape::Particle(d) | Shape::Point(d))
            if v.len() == Shape::Particle(d).rows() =>
        {
            v.clone()
        }
        (Value::Planar(position, angle), Shape::Planar) => {
            let mut rows = position.clone();
            rows.push(angle.clone());
            rows
        }
        _ => return None,
    };
    let rows = components.into_iter().enumerate().map(|(k, x)| {
        let angle = body.shape == Shape::Planar && k == 2;
        let mass = Atom::Mass(if angle { body.row + k } else { body.row });
        // wᵣ = μᵣ gₖ on a position row of a massive body.
        let weight = match field {
            Some(g) if body.shape.has_mass() && !angle => Some(Poly::atom(mass).mul(&g[k])),
            _ => None,
        };
        Row {
            x,
            mass: body.shape.has_mass().then_some(mass),
            weight,
        }
    });
    Some(rows.collect())
}

/// Each coordinate's first slot in q, by name: the scalar coordinates', and the arrays' with their
/// lengths (what both readers resolve names against).
pub(crate) fn coordinate_slots(
    model: &Model,
) -> (HashMap<String, usize>, HashMap<String, (usize, usize)>) {
    let (mut coords, mut arrays) = (HashMap::new(), HashMap::new());
    let mut slot = 0;
    for c in model.coords {
        if c.array.is_some() {
            arrays.insert(c.ident.to_string(), (slot, c.slots()));
        } else {
            coords.insert(c.ident.to_string(), slot);
        }
        slot += c.slots();
    }
    (coords, arrays)
}

/// At most this many products of terms in forming M and b (an estimate from the sizes of J's rows):
/// beyond it the equations would be past [`MAX_TERMS`] anyway, and forming them would only make the
/// build slow (a chain of 16 links: 4·10⁴; of 32 links: 6·10⁵; of 64 links: 9·10⁶).
const MAX_WORK: usize = 1_000_000;

/// At most this many terms in M, 𝓕 and b together: a chain of 16 links declared one by one has
/// 752, one of 32 has 3 040. Beyond it the straight-line code outgrows what it saves, and the
/// sweeps of `lagrange_core::tree` are faster (BENCHMARKS.md §2). (A tree whose coordinates each
/// move one body leaves the closed form far earlier, for the articulated-body recursion: see
/// `expand::recursion_is_cheaper`.)
const MAX_TERMS: usize = 1024;

impl Equations {
    /// Whether every numeric factor is finite: a literal past `f64`'s range, or a product of
    /// large ones, cannot be written as a constant (the dual-number passes take the declaration).
    fn has_finite_factors(&self) -> bool {
        let finite = |p: &Poly| p.terms.values().all(|c| c.is_finite());
        self.mass_matrix.iter().flatten().all(finite)
            && self.generalized_forces.iter().all(finite)
            && self.inertial_terms.iter().all(finite)
    }

    /// The number of terms evaluated at a state: products of sines, cosines, coordinates and
    /// velocities, each with its constant coefficient.
    pub(crate) fn terms(&self) -> usize {
        let count = |polys: &[Poly]| polys.iter().map(|p| p.by_variables().len()).sum::<usize>();
        self.mass_matrix.iter().map(|row| count(row)).sum::<usize>()
            + count(&self.generalized_forces)
            + count(&self.inertial_terms)
    }
}

/// Whether no two terms of `x` share their sines and cosines while they multiply different
/// coordinates: (q₂ − q₁) sin θ would, and its products in M would cancel (see the module docs).
fn free_of_cancellation(x: &Poly) -> bool {
    // A row affine in q (each term at most one coordinate, to the first power, times constants:
    // a block on a wedge, x + d cos α) has constant derivatives, so nothing formed from it can
    // cancel.
    let affine = x.terms.keys().all(|monomial| {
        let degree: i32 = monomial
            .iter()
            .filter(|(a, _)| matches!(a, Atom::Coord(_)))
            .map(|&(_, power)| power)
            .sum();
        degree <= 1
            && monomial
                .iter()
                .all(|(a, _)| !matches!(a, Atom::Sin(_) | Atom::Cos(_) | Atom::Vel(_)))
    });
    if affine {
        return true;
    }
    let mut seen: Vec<Vec<(Atom, i32)>> = Vec::new();
    for monomial in x.terms.keys() {
        let coordinates = monomial
            .iter()
            .filter(|(a, _)| matches!(a, Atom::Coord(_)))
            .count();
        if coordinates == 0 {
            continue;
        }
        let rest: Vec<(Atom, i32)> = monomial
            .iter()
            .copied()
            .filter(|(a, _)| matches!(a, Atom::Sin(_) | Atom::Cos(_)))
            .collect();
        if seen.contains(&rest) {
            return false;
        }
        seen.push(rest);
    }
    true
}

/// A row of x as read.
struct Row {
    x: Poly,
    /// The atom of its mass, for a row that carries mass: one per body's position, so a
    /// particle's rows share it and sin² + cos² can meet.
    mass: Option<Atom>,
    /// Its weight μᵣ gₖ, for a position row of a massive body in a uniform field.
    weight: Option<Poly>,
}

/// M, 𝓕 and b from the rows of x (see the module docs).
fn assemble(model: &Model, rows: &[Row], constants: Vec<TokenStream>) -> Option<Equations> {
    let n = model.dof();
    let jacobian: Vec<Vec<Poly>> = rows
        .iter()
        .map(|row| (0..n).map(|j| row.x.derivative(j)).collect())
        .collect();
    // Row r's share of M costs about (Σᵢ |Jᵣᵢ|)² products, of b that times the size of aᵣ.
    let work: usize = jacobian
        .iter()
        .map(|row| {
            let size: usize = row.iter().map(|p| p.terms.len()).sum();
            size * size * (1 + size)
        })
        .sum();
    if work > MAX_WORK {
        return None;
    }
    // aᵣ = d/ds (Σⱼ Jᵣⱼ q̇ⱼ) along q̇: the second derivative of xᵣ along the motion at q̈ = 0.
    let velocity = |j: usize| Poly::atom(Atom::Vel(j));
    let accelerations: Vec<Poly> = jacobian
        .iter()
        .map(|row| {
            let x_dot = (0..n).fold(Poly::zero(), |sum, j| sum.add(&row[j].mul(&velocity(j))));
            (0..n).fold(Poly::zero(), |sum, k| {
                sum.add(&x_dot.derivative(k).mul(&velocity(k)))
            })
        })
        .collect();
    let massive: Vec<(usize, Poly)> = rows
        .iter()
        .enumerate()
        .filter_map(|(r, row)| row.mass.map(|m| (r, Poly::atom(m))))
        .collect();
    let mass_matrix = (0..n)
        .map(|i| {
            (0..=i)
                .map(|j| {
                    massive
                        .iter()
                        .fold(Poly::zero(), |sum, (r, mu)| {
                            sum.add(&mu.mul(&jacobian[*r][i].mul(&jacobian[*r][j])))
                        })
                        .reduce()
                })
                .collect()
        })
        .collect();
    let inertial_terms = (0..n)
        .map(|i| {
            massive
                .iter()
                .fold(Poly::zero(), |sum, (r, mu)| {
                    sum.add(&mu.mul(&jacobian[*r][i].mul(&accelerations[*r])))
                })
                .reduce()
        })
        .collect();
    let generalized_forces = (0..n)
        .map(|i| {
            rows.iter()
                .zip(&jacobian)
                .filter_map(|(row, j)| Some(row.weight.as_ref()?.mul(&j[i])))
                .fold(Poly::zero(), |sum, term| sum.add(&term))
                .reduce()
        })
        .collect();
    Some(Equations {
        mass_matrix,
        generalized_forces,
        inertial_terms,
        constants,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sums_of_coordinates_under_one_factor_are_refused() {
        let (q1, q2) = (Poly::atom(Atom::Coord(1)), Poly::atom(Atom::Coord(2)));
        let s = Poly::atom(Atom::Sin(0));
        // (q₂ − q₁) sin θ: its square in M would cancel.
        assert!(!free_of_cancellation(&q2.sub(&q1).mul(&s)));
        assert!(!free_of_cancellation(&q2.sub(&q1).mul(&q1)));
        // q₂ − q₁ on its own, or x + d cos α (a constant factor): affine rows, whose derivatives
        // are constants.
        assert!(free_of_cancellation(&q2.sub(&q1)));
        let cos_alpha = Poly::atom(Atom::Constant(0));
        assert!(free_of_cancellation(&q1.add(&q2.mul(&cos_alpha))));
        // A cart plus an arm, polar coordinates: one coordinate per factor.
        let c = Poly::atom(Atom::Cos(0));
        assert!(free_of_cancellation(&q1.add(&s)));
        assert!(free_of_cancellation(&q1.mul(&c).add(&q2.mul(&s))));
    }
}
