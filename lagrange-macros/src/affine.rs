//! Whether a declaration's positions are affine in the coordinates with constant coefficients,
//! x(q) = A q + c, read from the expressions as written ([`is_affine`]).
//!
//! Then J = A and M = Aᵀ diag(μ) A are constants of the parameters, there are no velocity-product
//! terms, and `lagrange_core::affine` prepares J and the factorisation of M once, when the
//! mechanism is validated. The reading is conservative: an expression is affine when it is built
//! from coordinates, constants (literals, parameters, module constants, a family's index) and
//! earlier affine bodies by sums, differences, negation, products with a constant factor,
//! quotients by a constant, the vector constructors `vec2`, `vec3`, `planar`, and indexing of an
//! array coordinate or a family by a constant. Anything else that involves a coordinate (a method
//! call such as `theta.sin()`, a product of two coordinates, a closure, a macro) is not affine,
//! and neither is a declaration whose positions name `t` or that holds a spatial body (its rows
//! are a rotation matrix) or a body declared with its `com` (its centre of mass turns with it).

use crate::check::{family_index, Model, Shape};
use std::collections::HashMap;
use syn::{BinOp, Block, Expr, Pat, Stmt, UnOp};

/// How an expression depends on the coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
enum Degree {
    /// Not at all (literals, parameters, constants).
    Constant,
    /// Affine, with constant coefficients.
    Affine,
    /// Any other way, or unknown.
    Other,
}

use Degree::{Affine, Constant, Other};

/// Whether every row of x is affine in q with constant coefficients (see the module docs).
pub fn is_affine(model: &Model) -> bool {
    if model.rheonomic || model.bodies.is_empty() {
        return false;
    }
    let mut names: HashMap<String, Degree> = HashMap::new();
    for field in model.coords {
        names.insert(field.ident.to_string(), Affine);
    }
    for field in model.params {
        names.insert(field.ident.to_string(), Constant);
    }
    names.insert("t".to_string(), Other);
    // Bodies are read in declaration order and name earlier bodies only; a body not yet read (and
    // so not affine as far as is known) counts as `Other`.
    for body in &model.bodies {
        names.insert(body.decl.ident().to_string(), Other);
    }
    for body in &model.bodies {
        // A body declared by its frame has its centre of mass at its position plus its `com`
        // turned by its angle: not affine in the angle.
        if body.shape == Shape::Spatial || body.is_framed() {
            return false;
        }
        let own = body.decl.ident().to_string();
        let mut scope = names.clone();
        if let Some(index) = family_index(body.decl) {
            scope.insert(index.to_string(), Constant);
            // A member names earlier members: affine by induction over the index when the
            // member's own expression is, with the earlier members taken as affine.
            scope.insert(own.clone(), Affine);
        }
        if block_degree(&body.decl.block, &mut scope) == Other {
            return false;
        }
        names.insert(own, Affine);
    }
    true
}

/// The degree of a block's value, with its `let` bindings in scope.
fn block_degree(block: &Block, scope: &mut HashMap<String, Degree>) -> Degree {
    let mut value = Constant;
    for (k, stmt) in block.stmts.iter().enumerate() {
        match stmt {
            Stmt::Local(local) => {
                let Pat::Ident(pat) = strip_type(&local.pat) else {
                    return Other;
                };
                let degree = match &local.init {
                    Some(init) if init.diverge.is_none() => expr_degree(&init.expr, scope),
                    _ => return Other,
                };
                scope.insert(pat.ident.to_string(), degree);
            }
            Stmt::Expr(expr, None) if k + 1 == block.stmts.len() => {
                value = expr_degree(expr, scope)
            }
            _ => return Other,
        }
    }
    value
}

/// `x: f64` as a pattern: the `x`.
fn strip_type(pat: &Pat) -> &Pat {
    match pat {
        Pat::Type(typed) => &typed.pat,
        other => other,
    }
}

/// The degree of an expression (see the module docs for the forms read).
fn expr_degree(expr: &Expr, scope: &mut HashMap<String, Degree>) -> Degree {
    match expr {
        Expr::Lit(_) => Constant,
        Expr::Paren(e) => expr_degree(&e.expr, scope),
        Expr::Group(e) => expr_degree(&e.expr, scope),
        Expr::Path(path) => match path.path.get_ident() {
            Some(ident) => scope.get(&ident.to_string()).copied().unwrap_or(Constant),
            // `std::f64::consts::PI`, an associated constant.
            None => Constant,
        },
        Expr::Unary(unary) => match unary.op {
            UnOp::Neg(_) => expr_degree(&unary.expr, scope),
            _ => all_constant([&*unary.expr], scope),
        },
        Expr::Binary(binary) => {
            let (lhs, rhs) = (
                expr_degree(&binary.left, scope),
                expr_degree(&binary.right, scope),
            );
            match binary.op {
                BinOp::Add(_) | BinOp::Sub(_) => lhs.max(rhs),
                BinOp::Mul(_) if lhs == Constant || rhs == Constant => lhs.max(rhs),
                BinOp::Div(_) if rhs == Constant => lhs,
                _ if lhs == Constant && rhs == Constant => Constant,
                _ => Other,
            }
        }
        Expr::Call(call) => {
            let constructor = matches!(
                &*call.func,
                Expr::Path(p) if p.path.get_ident().is_some_and(|i| i == "vec2" || i == "vec3" || i == "planar")
            );
            if constructor {
                call.args
                    .iter()
                    .map(|a| expr_degree(a, scope))
                    .max()
                    .unwrap_or(Constant)
            } else {
                all_constant(call.args.iter().chain([&*call.func]), scope)
            }
        }
        Expr::MethodCall(call) => all_constant(call.args.iter().chain([&*call.receiver]), scope),
        Expr::Cast(cast) => all_constant([&*cast.expr], scope),
        Expr::Index(index) => {
            if expr_degree(&index.index, scope) != Constant {
                return Other;
            }
            expr_degree(&index.expr, scope)
        }
        Expr::Field(field) => expr_degree(&field.base, scope),
        Expr::Block(block) => block_degree(&block.block, &mut scope.clone()),
        Expr::If(branch) => {
            if expr_degree(&branch.cond, scope) != Constant {
                return Other;
            }
            let then = block_degree(&branch.then_branch, &mut scope.clone());
            match &branch.else_branch {
                Some((_, other)) => then.max(expr_degree(other, scope)),
                None => Other,
            }
        }
        _ => Other,
    }
}

/// `Constant` when every operand is, otherwise `Other`: an operation that is not one of the
/// affine forms keeps only constants constant.
fn all_constant<'e>(
    operands: impl IntoIterator<Item = &'e Expr>,
    scope: &mut HashMap<String, Degree>,
) -> Degree {
    let constant = operands
        .into_iter()
        .all(|e| expr_degree(e, scope) == Constant);
    if constant {
        Constant
    } else {
        Other
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn degree(src: &str, coords: &[&str], params: &[&str]) -> Degree {
        let block: Block = syn::parse_str(src).unwrap();
        let mut scope: HashMap<String, Degree> = HashMap::new();
        coords.iter().for_each(|c| {
            scope.insert(c.to_string(), Affine);
        });
        params.iter().for_each(|p| {
            scope.insert(p.to_string(), Constant);
        });
        scope.insert("t".into(), Other);
        block_degree(&block, &mut scope)
    }

    #[test]
    fn affine_forms() {
        let c = ["x", "d"];
        let p = ["alpha", "h"];
        assert_eq!(degree("{ vec2(x, 0.0) }", &c, &p), Affine);
        assert_eq!(
            degree("{ vec2(x + d * alpha.cos(), h - d * alpha.sin()) }", &c, &p),
            Affine
        );
        assert_eq!(
            degree("{ let s = alpha.sin(); vec2(x, -d / s) * 2.0 }", &c, &p),
            Affine
        );
        assert_eq!(degree("{ vec2(h, alpha) }", &c, &p), Constant);
        assert_eq!(degree("{ planar(vec2(x, 0.0), d) }", &c, &p), Affine);
        assert_eq!(
            degree("{ vec2(std::f64::consts::PI * x, -x) }", &c, &p),
            Affine
        );
    }

    #[test]
    fn other_forms() {
        let c = ["x", "d"];
        let p = ["alpha"];
        // Nonlinear in a coordinate.
        assert_eq!(degree("{ vec2(x.sin(), 0.0) }", &c, &p), Other);
        assert_eq!(degree("{ vec2(x * d, 0.0) }", &c, &p), Other);
        assert_eq!(degree("{ vec2(alpha / x, 0.0) }", &c, &p), Other);
        assert_eq!(degree("{ let y = x; vec2(y * y, 0.0) }", &c, &p), Other);
        // Time, closures, macros and conditions on coordinates are not read as affine.
        assert_eq!(degree("{ vec2(x + t, 0.0) }", &c, &p), Other);
        assert_eq!(
            degree("{ let f = |s: f64| s; vec2(f(x), 0.0) }", &c, &p),
            Other
        );
        assert_eq!(
            degree(
                "{ if x > 0.0 { vec2(x, 0.0) } else { vec2(-x, 0.0) } }",
                &c,
                &p
            ),
            Other
        );
        assert_eq!(degree("{ vec2(x.abs(), 0.0) }", &c, &p), Other);
        assert_eq!(degree("{ vec2(x as f64, 0.0) }", &c, &p), Other);
    }

    #[test]
    fn families_by_constant_index() {
        let c = ["q"];
        let p = ["l"];
        let mut scope: HashMap<String, Degree> = HashMap::new();
        scope.insert("q".into(), Affine);
        scope.insert("l".into(), Constant);
        scope.insert("i".into(), Constant);
        scope.insert("bead".into(), Affine);
        let block: Block = syn::parse_str(
            "{ if i == 0 { vec2(q[i], 0.0) } else { bead[i - 1] + vec2(q[i] * l, 0.0) } }",
        )
        .unwrap();
        assert_eq!(block_degree(&block, &mut scope), Affine);
        // An index that is a coordinate is not a constant index.
        assert_eq!(degree("{ vec2(q[q[0] as usize], 0.0) }", &c, &p), Other);
    }
}
