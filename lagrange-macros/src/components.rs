//! Which coordinates each Cartesian row can depend on ([`dependencies`]; the generated
//! `Model::DEPENDS`), from the names each row of a body's position can depend on, read component by
//! component where the declaration writes the components out. `vec2(x, y)` gives rows depending on `x` and
//! on `y` alone; `planar(centre, angle)` gives the angle row the names of `angle` alone. What is
//! not written out component by component gives every row the names of the whole expression.
//!
//! Only operations that act component by component are split: `vec2(..)`/`vec3(..)`, a sum or
//! difference of vectors, a negation, and a vector times or divided by a factor written on its right
//! (`Vec * D`, `Vec / D` are the only such products in `lagrange_core::geometry`; a factor on the
//! left may be a rotation, `Rot3 * Vec3`, which mixes components, and is not split).

use crate::check::{Dim, Model, Shape};
use crate::names;
use proc_macro2::Span;
use std::collections::BTreeMap;
use syn::{BinOp, Block, Expr, Ident, Stmt};

/// The slots of each coordinate, by name (an array coordinate holds several).
pub fn coordinate_slots(model: &Model) -> BTreeMap<String, Vec<usize>> {
    let mut slots_of: BTreeMap<String, Vec<usize>> = BTreeMap::new();
    let mut slot = 0;
    for field in model.coords {
        slots_of.insert(
            field.ident.to_string(),
            (slot..slot + field.slots()).collect(),
        );
        slot += field.slots();
    }
    slots_of
}

/// Which coordinates each row of x can depend on, as the declaration states it: a body's rows
/// depend on the coordinates its function names (every element of an array coordinate it names)
/// and on those of the bodies it names, transitively; where the body writes its components out
/// (`vec2(x, y)`, `planar(centre, angle)`), each row on the names of its own component
/// ([`component_names`]); and each body's, by name (all members of a family together).
pub fn dependencies(model: &Model) -> (Vec<Vec<bool>>, BTreeMap<String, Vec<bool>>) {
    let n = model.dof();
    let slots_of = coordinate_slots(model);
    let mut body_deps: BTreeMap<String, Vec<bool>> = BTreeMap::new();
    let mut rows = vec![vec![true; n]; model.rows];
    // The coordinates a set of names can depend on, given the bodies read so far.
    let deps_of = |names: &[Ident], own: &str, body_deps: &BTreeMap<String, Vec<bool>>| {
        let mut deps = vec![false; n];
        for free in names {
            let free = free.to_string();
            if let Some(slots) = slots_of.get(&free) {
                slots.iter().for_each(|&j| deps[j] = true);
            } else if let Some(other) = body_deps.get(&free) {
                deps.iter_mut().zip(other).for_each(|(d, &o)| *d |= o);
            } else if free != own && model.bodies.iter().any(|b| b.decl.ident() == free.as_str()) {
                deps = vec![true; n];
            }
        }
        deps
    };
    // Bodies name earlier bodies only, so one pass in declaration order sees each dependency
    // complete; a name not yet known (impossible after the rules) counts as every coordinate.
    for body in &model.bodies {
        let name = body.decl.ident().to_string();
        let free = model.free_names.get(&name).cloned().unwrap_or_default();
        let deps = deps_of(&free, &name, &body_deps);
        // A single body written component by component: each row its own names (`vec2(x, y)`,
        // a planar body's angle).
        // A body declared by its frame: each centre-of-mass row mixes the frame's position with
        // its orientation, so every row gets the names of the whole.
        let components = match body.count {
            None if !body.is_framed() => {
                crate::components::component_names(&body.decl.block, body.shape)
            }
            _ => None,
        };
        match components {
            Some(components) => {
                for (row, names) in (body.row..).zip(&components) {
                    // Never wider than the body's own dependencies.
                    let own = deps_of(names, &name, &body_deps);
                    rows[row] = own.iter().zip(&deps).map(|(&o, &d)| o && d).collect();
                }
            }
            None => {
                for row in body.row..body.row + body.rows() {
                    rows[row] = deps.clone();
                }
            }
        }
        body_deps.insert(name, deps);
    }
    (rows, body_deps)
}

/// The names each row of a body of `shape` (one member, not a family) depends on, with the block's
/// `let` locals resolved to what they depend on. `None` where the rows are not written out (a
/// spatial body, a final expression that is not a vector built component by component).
pub fn component_names(block: &Block, shape: Shape) -> Option<Vec<Vec<Ident>>> {
    let Some(Stmt::Expr(value, None)) = block.stmts.last() else {
        return None;
    };
    let components = match shape {
        Shape::Particle(dim) | Shape::Point(dim) => split(value, width(dim))?,
        Shape::Planar => {
            let Expr::Call(call) = strip(value) else {
                return None;
            };
            if !is_function(&call.func, "planar") || call.args.len() != 2 {
                return None;
            }
            let mut rows = split_or_whole(&call.args[0], 2);
            rows.push(names::free_names_of_expr(&call.args[1]));
            rows
        }
        Shape::Spatial => return None,
    };
    // Each component's names with the block's locals resolved: the block with its value replaced
    // by a call naming exactly those names, read by `names::value_names`.
    Some(
        components
            .into_iter()
            .map(|names| {
                let mut resolved = block.clone();
                let args = names.iter();
                let probe: Expr = syn::parse_quote!(__component(#(#args),*));
                *resolved.stmts.last_mut().unwrap() = Stmt::Expr(probe, None);
                names::value_names(&resolved)
                    .into_iter()
                    .filter(|n| n != "__component")
                    .collect()
            })
            .collect(),
    )
}

fn width(dim: Dim) -> usize {
    match dim {
        Dim::Two => 2,
        Dim::Three => 3,
    }
}

/// The names of each of `n` components of the vector `expr`, where it is built component by
/// component (see the module docs).
fn split(expr: &Expr, n: usize) -> Option<Vec<Vec<Ident>>> {
    match strip(expr) {
        Expr::Call(call) => {
            let name = if n == 2 { "vec2" } else { "vec3" };
            (is_function(&call.func, name) && call.args.len() == n)
                .then(|| call.args.iter().map(names::free_names_of_expr).collect())
        }
        Expr::Unary(u) if matches!(u.op, syn::UnOp::Neg(_)) => split(&u.expr, n),
        Expr::Binary(b) => match b.op {
            // Component i of a ± b depends on component i of each side; a side not written out
            // lends all its names to every component.
            BinOp::Add(_) | BinOp::Sub(_) => {
                let (left, right) = (split(&b.left, n), split(&b.right, n));
                if left.is_none() && right.is_none() {
                    return None;
                }
                let left = left.unwrap_or_else(|| whole(&b.left, n));
                let right = right.unwrap_or_else(|| whole(&b.right, n));
                Some(
                    left.into_iter()
                        .zip(right)
                        .map(|(mut l, r)| {
                            l.extend(r);
                            l
                        })
                        .collect(),
                )
            }
            // A vector scaled by a factor on its right.
            BinOp::Mul(_) | BinOp::Div(_) => {
                let factor = names::free_names_of_expr(&b.right);
                let mut rows = split(&b.left, n)?;
                rows.iter_mut()
                    .for_each(|r| r.extend(factor.iter().cloned()));
                Some(rows)
            }
            _ => None,
        },
        _ => None,
    }
}

fn split_or_whole(expr: &Expr, n: usize) -> Vec<Vec<Ident>> {
    split(expr, n).unwrap_or_else(|| whole(expr, n))
}

/// Every name of `expr`, for each of `n` components.
fn whole(expr: &Expr, n: usize) -> Vec<Vec<Ident>> {
    vec![names::free_names_of_expr(expr); n]
}

fn is_function(func: &Expr, name: &str) -> bool {
    matches!(strip(func), Expr::Path(p) if p.path.is_ident(&Ident::new(name, Span::call_site())))
}

/// The expression inside parentheses and invisible groups.
fn strip(expr: &Expr) -> &Expr {
    match expr {
        Expr::Paren(p) => strip(&p.expr),
        Expr::Group(g) => strip(&g.expr),
        e => e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rows(block: Block, shape: Shape) -> Option<Vec<Vec<String>>> {
        component_names(&block, shape).map(|rows| {
            rows.into_iter()
                .map(|r| {
                    let mut r: Vec<String> = r.iter().map(|i| i.to_string()).collect();
                    r.retain(|n| !matches!(n.as_str(), "vec2" | "vec3" | "planar"));
                    r.sort();
                    r.dedup();
                    r
                })
                .collect()
        })
    }

    #[test]
    fn coordinates_written_as_components_depend_on_themselves() {
        let got = rows(syn::parse_quote!({ vec2(x, y) }), Shape::Particle(Dim::Two));
        assert_eq!(
            got,
            Some(vec![vec!["x".to_string()], vec!["y".to_string()]])
        );
    }

    #[test]
    fn a_planar_angle_row_names_only_the_angle() {
        let got = rows(
            syn::parse_quote!({
                let tip = vec2(a.cos(), a.sin()) * l1;
                planar(tip + vec2(b.cos(), b.sin()) * (0.5 * l2), b)
            }),
            Shape::Planar,
        )
        .unwrap();
        // The centre: the local's names and the second term's, in both components.
        for row in &got[..2] {
            assert_eq!(row, &["a", "b", "l1", "l2"]);
        }
        assert_eq!(got[2], ["b"]);
    }

    #[test]
    fn sums_and_right_factors_split_component_by_component() {
        let got = rows(
            syn::parse_quote!({ -(vec2(d, 0.0) + vec2(c, s) * (0.5 * l)) / k }),
            Shape::Point(Dim::Two),
        )
        .unwrap();
        assert_eq!(got, [vec!["c", "d", "k", "l"], vec!["k", "l", "s"]]);
    }

    #[test]
    fn what_mixes_components_is_not_split() {
        // A factor on the left may be a rotation.
        assert_eq!(
            rows(
                syn::parse_quote!({ rot * vec3(x, 0.0, 0.0) }),
                Shape::Particle(Dim::Three)
            ),
            None
        );
        // A vector held in a local is not written out.
        assert_eq!(
            rows(
                syn::parse_quote!({
                    let v = vec2(x, y);
                    v
                }),
                Shape::Particle(Dim::Two)
            ),
            None
        );
        assert_eq!(
            rows(syn::parse_quote!({ vec2(x, y) }), Shape::Spatial),
            None
        );
        // Planar: a centre not written out gives both centre rows all its names.
        let got = rows(
            syn::parse_quote!({ planar(centre(x, y), th) }),
            Shape::Planar,
        )
        .unwrap();
        assert_eq!(got[0], ["centre", "x", "y"]);
        assert_eq!(got[1], ["centre", "x", "y"]);
        assert_eq!(got[2], ["th"]);
    }
}
