//! The names each Cartesian row of a body's position can depend on, read component by component
//! where the declaration writes the components out. `vec2(x, y)` gives rows depending on `x` and
//! on `y` alone; `planar(centre, angle)` gives the angle row the names of `angle` alone. What is
//! not written out component by component gives every row the names of the whole expression.
//!
//! Only operations that act component by component are split: `vec2(..)`/`vec3(..)`, a sum or
//! difference of vectors, a negation, and a vector times or divided by a factor written on its right
//! (`Vec * D`, `Vec / D` are the only such products in `lagrange_core::geometry`; a factor on the
//! left may be a rotation, `Rot3 * Vec3`, which mixes components, and is not split).

use crate::check::{Dim, Shape};
use crate::names;
use proc_macro2::Span;
use syn::{BinOp, Block, Expr, Ident, Stmt};

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
