//! The free names of a function body: single-segment paths not bound by a local `let`, closure
//! parameter or pattern. These are what a declaration's functions may name (coordinates,
//! parameters, `t`, bodies, velocities) and what the checks resolve.

use std::collections::HashSet;
use syn::visit::{self, Visit};
use syn::{Expr, Ident, Pat};

/// Every free single-segment name in `block`, in order of appearance (with repeats).
pub fn free_names(block: &syn::Block) -> Vec<Ident> {
    let mut visitor = FreeNames::default();
    visitor.visit_block(block);
    visitor.free
}

/// Every free name of an expression (a mass or an inertia).
pub fn free_names_of_expr(expr: &Expr) -> Vec<Ident> {
    let mut visitor = FreeNames::default();
    visitor.visit_expr(expr);
    visitor.free
}

/// The free names of `block` that stand alone as an operand of an arithmetic operator
/// (`vec2(..) * l`, `-l`, `l + 1.0`): what must be a scalar there.
pub fn free_operands(block: &syn::Block) -> Vec<Ident> {
    let mut visitor = FreeNames::default();
    visitor.visit_block(block);
    visitor.operands
}

/// [`free_operands`] of an expression.
pub fn free_operands_of_expr(expr: &Expr) -> Vec<Ident> {
    let mut visitor = FreeNames::default();
    visitor.visit_expr(expr);
    visitor.operands
}

/// The free names the *value* of `block` depends on: like [`free_names`], but a top-level `let`
/// counts only through the uses of what it binds. `let _unused = theta; vec2(x, 0.0)` depends on
/// `x` alone. A statement that is not a `let` (`acc += theta[k];`, a loop, `v.push(x);`) passes its
/// names to every local it names, so mutation is followed; nested blocks count whole.
pub fn value_names(block: &syn::Block) -> Vec<Ident> {
    use std::collections::HashMap;
    // A `return` (reported) leaves the value anywhere: every name counts.
    if first_return(block).is_some() {
        return free_names(block);
    }
    let mut locals: HashMap<String, Vec<Ident>> = HashMap::new();
    // The free names of `names`, with each local replaced by what it depends on.
    let resolve = |locals: &HashMap<String, Vec<Ident>>, names: Vec<Ident>| -> Vec<Ident> {
        names
            .into_iter()
            .flat_map(|i| match locals.get(&i.to_string()) {
                Some(deps) => deps.clone(),
                None => vec![i],
            })
            .collect()
    };
    let last = block.stmts.len().saturating_sub(1);
    let mut value = Vec::new();
    for (k, stmt) in block.stmts.iter().enumerate() {
        match stmt {
            syn::Stmt::Local(local) => {
                let mut names = Vec::new();
                if let Some(init) = &local.init {
                    names.extend(free_names_of_expr(&init.expr));
                    if let Some((_, diverge)) = &init.diverge {
                        names.extend(free_names_of_expr(diverge));
                    }
                }
                let deps = resolve(&locals, names);
                let mut bindings = Bindings(Vec::new());
                bindings.visit_pat(&local.pat);
                for name in bindings.0 {
                    locals.insert(name, deps.clone());
                }
            }
            syn::Stmt::Expr(expr, None) if k == last => {
                value = resolve(&locals, free_names_of_expr(expr));
            }
            syn::Stmt::Expr(expr, _) => {
                let names = free_names_of_expr(expr);
                let deps = resolve(&locals, names.clone());
                for name in names {
                    if let Some(local) = locals.get_mut(&name.to_string()) {
                        local.extend(deps.iter().cloned());
                    }
                }
            }
            syn::Stmt::Item(_) | syn::Stmt::Macro(_) => {}
        }
    }
    value
}

struct FreeNames {
    scopes: Vec<HashSet<String>>,
    free: Vec<Ident>,
    /// The free names that are an operand of a binary or unary operator.
    operands: Vec<Ident>,
}

impl Default for FreeNames {
    fn default() -> Self {
        FreeNames {
            scopes: vec![HashSet::new()],
            free: Vec::new(),
            operands: Vec::new(),
        }
    }
}

impl FreeNames {
    /// Records `operand` when it is a free name alone (in parentheses or not).
    fn note_operand(&mut self, operand: &Expr) {
        let operand = match crate::ast::ungroup(operand) {
            Expr::Paren(p) => crate::ast::ungroup(&p.expr),
            other => other,
        };
        if let Expr::Path(p) = operand {
            if let Some(ident) = p.path.get_ident().filter(|i| !self.is_bound(i)) {
                self.operands.push(ident.clone());
            }
        }
    }

    fn is_bound(&self, ident: &Ident) -> bool {
        let name = ident.to_string();
        self.scopes.iter().any(|s| s.contains(&name))
    }

    fn bind_pattern(&mut self, pat: &Pat) {
        let mut bindings = Bindings(Vec::new());
        bindings.visit_pat(pat);
        let scope = self.scopes.last_mut().unwrap();
        scope.extend(bindings.0);
    }

    fn scoped(&mut self, f: impl FnOnce(&mut Self)) {
        self.scopes.push(HashSet::new());
        f(self);
        self.scopes.pop();
    }
}

/// The names a pattern binds.
struct Bindings(Vec<String>);

impl<'ast> Visit<'ast> for Bindings {
    fn visit_pat_ident(&mut self, p: &'ast syn::PatIdent) {
        self.0.push(p.ident.to_string());
        visit::visit_pat_ident(self, p);
    }
    // Paths inside patterns (`Some(x)`, `Foo { .. }`) bind nothing themselves.
    fn visit_path(&mut self, _: &'ast syn::Path) {}
}

impl<'ast> Visit<'ast> for FreeNames {
    fn visit_block(&mut self, block: &'ast syn::Block) {
        self.scoped(|v| {
            // Items in a block are visible throughout it.
            for stmt in &block.stmts {
                if let syn::Stmt::Item(item) = stmt {
                    if let Some(ident) = item_ident(item) {
                        v.scopes.last_mut().unwrap().insert(ident.to_string());
                    }
                }
            }
            for stmt in &block.stmts {
                v.visit_stmt(stmt);
            }
        });
    }

    fn visit_local(&mut self, local: &'ast syn::Local) {
        if let Some(init) = &local.init {
            self.visit_expr(&init.expr);
            if let Some((_, diverge)) = &init.diverge {
                self.visit_expr(diverge);
            }
        }
        self.bind_pattern(&local.pat);
    }

    // Nested items cannot capture locals; rustc checks them.
    fn visit_item(&mut self, _: &'ast syn::Item) {}

    fn visit_expr_closure(&mut self, closure: &'ast syn::ExprClosure) {
        self.scoped(|v| {
            closure.inputs.iter().for_each(|p| v.bind_pattern(p));
            v.visit_expr(&closure.body);
        });
    }

    fn visit_expr_for_loop(&mut self, e: &'ast syn::ExprForLoop) {
        self.visit_expr(&e.expr);
        self.scoped(|v| {
            v.bind_pattern(&e.pat);
            v.visit_block(&e.body);
        });
    }

    fn visit_arm(&mut self, arm: &'ast syn::Arm) {
        self.scoped(|v| {
            v.bind_pattern(&arm.pat);
            if let Some((_, guard)) = &arm.guard {
                v.visit_expr(guard);
            }
            v.visit_expr(&arm.body);
        });
    }

    fn visit_expr_if(&mut self, e: &'ast syn::ExprIf) {
        self.scoped(|v| {
            v.visit_expr(&e.cond);
            v.visit_block(&e.then_branch);
        });
        if let Some((_, else_branch)) = &e.else_branch {
            self.visit_expr(else_branch);
        }
    }

    fn visit_expr_while(&mut self, e: &'ast syn::ExprWhile) {
        self.scoped(|v| {
            v.visit_expr(&e.cond);
            v.visit_block(&e.body);
        });
    }

    // `if let PAT = EXPR`: the pattern binds in the enclosing (if's) scope.
    fn visit_expr_let(&mut self, e: &'ast syn::ExprLet) {
        self.visit_expr(&e.expr);
        self.bind_pattern(&e.pat);
    }

    fn visit_expr_path(&mut self, e: &'ast syn::ExprPath) {
        if e.qself.is_none() && e.path.leading_colon.is_none() && e.path.segments.len() == 1 {
            let ident = &e.path.segments[0].ident;
            if !self.is_bound(ident) {
                self.free.push(ident.clone());
            }
        }
        // Longer paths (`std::f64::consts::PI`, `f64::EPSILON`) are rustc's to resolve.
    }

    fn visit_expr_binary(&mut self, e: &'ast syn::ExprBinary) {
        self.note_operand(&e.left);
        self.note_operand(&e.right);
        visit::visit_expr_binary(self, e);
    }

    fn visit_expr_unary(&mut self, e: &'ast syn::ExprUnary) {
        if !matches!(e.op, syn::UnOp::Deref(_)) {
            self.note_operand(&e.expr);
        }
        visit::visit_expr_unary(self, e);
    }

    // Macro bodies are opaque token streams.
    fn visit_macro(&mut self, _: &'ast syn::Macro) {}
}

fn item_ident(item: &syn::Item) -> Option<&Ident> {
    match item {
        syn::Item::Fn(f) => Some(&f.sig.ident),
        syn::Item::Const(c) => Some(&c.ident),
        syn::Item::Static(s) => Some(&s.ident),
        syn::Item::Struct(s) => Some(&s.ident),
        syn::Item::Enum(e) => Some(&e.ident),
        _ => None,
    }
}

/// The first `return` of a function body (not inside a closure or nested item).
pub fn first_return(block: &syn::Block) -> Option<syn::token::Return> {
    struct FirstReturn(Option<syn::token::Return>);
    impl<'ast> Visit<'ast> for FirstReturn {
        fn visit_expr_return(&mut self, e: &'ast syn::ExprReturn) {
            self.0.get_or_insert(e.return_token);
        }
        fn visit_expr_closure(&mut self, _: &'ast syn::ExprClosure) {}
        fn visit_item(&mut self, _: &'ast syn::Item) {}
    }
    let mut visitor = FirstReturn(None);
    visitor.visit_block(block);
    visitor.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn names(src: &str) -> Vec<String> {
        free_names(&syn::parse_str(src).unwrap())
            .iter()
            .map(|i| i.to_string())
            .collect()
    }

    #[test]
    fn locals_closures_and_patterns_bind() {
        assert_eq!(
            names("{ let a = b; let f = |x| x + a + c; f(d) }"),
            ["b", "c", "d"]
        );
        assert_eq!(names("{ if let Some(y) = z { y } else { y } }"), ["z", "y"]);
        assert_eq!(names("{ match w { (p, q) => p + q + r } }"), ["w", "r"]);
        assert_eq!(names("{ std::f64::consts::PI * x.powf(e) }"), ["x", "e"]);
    }

    fn value(src: &str) -> Vec<String> {
        value_names(&syn::parse_str(src).unwrap())
            .iter()
            .map(|i| i.to_string())
            .collect()
    }

    #[test]
    fn unused_lets_do_not_reach_the_value() {
        assert_eq!(
            value("{ let _unused = theta; vec2(x, 0.0) }"),
            ["vec2", "x"]
        );
        assert_eq!(value("{ let _ = theta; x }"), ["x"]);
        // Through a chain of locals, shadowing, and mutation by a later statement.
        assert_eq!(value("{ let a = theta; let b = a * l; b }"), ["theta", "l"]);
        assert_eq!(value("{ let a = theta; let a = x; a }"), ["x"]);
        assert_eq!(
            value("{ let mut acc = 0.0; for k in 0..2 { acc += phi[k]; } acc }"),
            ["phi"]
        );
        assert_eq!(value("{ let f = |s| s * theta; f(x) }"), ["theta", "x"]);
    }
}
