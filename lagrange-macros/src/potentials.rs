//! Which coordinates each declared potential can depend on ([`narrow_potentials`]), so that its
//! gradient is taken on dual numbers seeded on those alone: a spring between two masses of a
//! chain of N costs a 2-wide gradient, not an N-wide one.
//!
//! A potential depends on the coordinates it names — an element `q[3]` of an array coordinate
//! indexed by an integer literal names that element, any other use of the array names all of
//! it — and on those of the bodies it names ([`crate::components::dependencies`]). The reading is
//! conservative: a set may be wider than the truth, never narrower; a potential written with a
//! macro invocation (whose tokens are not read) counts as depending on every coordinate.

use crate::check::Model;
use crate::components::{coordinate_slots, dependencies};
use std::collections::{BTreeMap, BTreeSet};
use syn::visit::{self, Visit};
use syn::{Expr, Lit};

/// The coordinate slots (sorted) each potential in `model.potentials` can depend on, when the
/// declaration allows narrow gradients: at least one potential, no field that varies in space
/// (its potential is not declared function by function), and every potential narrower than all
/// N coordinates. `None` otherwise (the dense gradient is as narrow).
pub fn narrow_potentials(model: &Model) -> Option<Vec<Vec<usize>>> {
    let n = model.dof();
    if model.potentials.is_empty() || !model.gravities.is_empty() || n < 2 {
        return None;
    }
    let slots_of = coordinate_slots(model);
    let (_, body_deps) = dependencies(model);
    let sets: Vec<Vec<usize>> = model
        .potentials
        .iter()
        .map(|decl| {
            let mut uses = Uses {
                arrays: &slots_of,
                elements: BTreeSet::new(),
                whole: BTreeSet::new(),
                opaque: false,
            };
            uses.visit_block(&decl.block);
            if uses.opaque {
                return (0..n).collect();
            }
            let mut deps = vec![false; n];
            for slot in uses.elements {
                deps[slot] = true;
            }
            for name in &uses.whole {
                if let Some(slots) = slots_of.get(name) {
                    slots.iter().for_each(|&j| deps[j] = true);
                } else if let Some(body) = body_deps.get(name) {
                    deps.iter_mut().zip(body).for_each(|(d, &b)| *d |= b);
                }
            }
            (0..n).filter(|&j| deps[j]).collect()
        })
        .collect();
    sets.iter().all(|s| s.len() < n).then_some(sets)
}

/// The names a block uses, with the literal-indexed elements of array coordinates apart.
struct Uses<'m> {
    arrays: &'m BTreeMap<String, Vec<usize>>,
    /// Slots named as `array[literal]`.
    elements: BTreeSet<usize>,
    /// Names used otherwise (coordinates, bodies, anything else).
    whole: BTreeSet<String>,
    /// Whether the block holds tokens that are not read (a macro invocation).
    opaque: bool,
}

impl<'ast> Visit<'ast> for Uses<'_> {
    fn visit_expr(&mut self, expr: &'ast Expr) {
        if let Expr::Index(index) = expr {
            let array = match &*index.expr {
                Expr::Path(p) => p.path.get_ident().map(|i| i.to_string()),
                _ => None,
            };
            let literal = match &*index.index {
                Expr::Lit(l) => match &l.lit {
                    Lit::Int(i) => i.base10_parse::<usize>().ok(),
                    _ => None,
                },
                _ => None,
            };
            if let (Some(array), Some(k)) = (array, literal) {
                if let Some(slots) = self.arrays.get(&array).filter(|s| s.len() > 1) {
                    if let Some(&slot) = slots.get(k) {
                        self.elements.insert(slot);
                        return;
                    }
                }
            }
        }
        if let Expr::Path(p) = expr {
            if let Some(ident) = p.path.get_ident() {
                self.whole.insert(ident.to_string());
            }
        }
        visit::visit_expr(self, expr);
    }

    fn visit_macro(&mut self, _: &'ast syn::Macro) {
        self.opaque = true;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (slots named element by element, other names, opaque) of a block, with `q` a 4-element
    /// array coordinate and `x` a scalar one.
    fn uses(src: &str) -> (Vec<usize>, Vec<String>, bool) {
        let arrays: BTreeMap<String, Vec<usize>> = [
            ("q".to_string(), vec![0, 1, 2, 3]),
            ("x".to_string(), vec![4]),
        ]
        .into();
        let block: syn::Block = syn::parse_str(src).unwrap();
        let mut u = Uses {
            arrays: &arrays,
            elements: BTreeSet::new(),
            whole: BTreeSet::new(),
            opaque: false,
        };
        u.visit_block(&block);
        (
            u.elements.into_iter().collect(),
            u.whole.into_iter().collect(),
            u.opaque,
        )
    }

    #[test]
    fn literal_elements_are_read_apart() {
        let (elements, whole, opaque) = uses("{ let d = q[2] - q[1]; k * d * d + x }");
        assert_eq!(elements, vec![1, 2]);
        assert!(whole.contains(&"x".to_string()) && !whole.contains(&"q".to_string()));
        assert!(!opaque);
    }

    #[test]
    fn any_other_use_of_an_array_names_all_of_it() {
        // A computed index, the array passed whole, a method on it.
        for src in [
            "{ q[i] * k }",
            "{ helper(q) }",
            "{ q.iter().sum::<f64>() }",
            "{ q[1 + 0] }",
        ] {
            let (_, whole, _) = uses(src);
            assert!(whole.contains(&"q".to_string()), "{src}");
        }
    }

    #[test]
    fn a_macro_makes_the_block_opaque() {
        assert!(uses("{ some_macro!(q[0]) }").2);
    }
}
