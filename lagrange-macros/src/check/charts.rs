//! Rotation charts: `rot_vector(vec3(a, b, c))` and `rot_mrp(vec3(a, b, c))` write a rotation in
//! three coordinates that the generated code keeps regular — past a rotation angle of π it moves
//! them, and their rates, to the equivalent point of the chart
//! (`lagrange_core::geometry::switch_chart`). So the three must be coordinates, each in one chart.

use super::model::Model;
use crate::ctxt::Ctxt;
use crate::structure::strip;
use syn::visit::Visit;
use syn::{Expr, ExprCall};

/// Which chart: the rotation vector or modified Rodrigues parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ChartKind {
    Vector,
    Mrp,
}

impl ChartKind {
    /// The chart a function of the declarations names: `rot_vector` or `rot_mrp`.
    pub fn named(function: &str) -> Option<ChartKind> {
        match function {
            "rot_vector" => Some(ChartKind::Vector),
            "rot_mrp" => Some(ChartKind::Mrp),
            _ => None,
        }
    }
}

/// A chart and the flat indices of its three coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Chart {
    pub kind: ChartKind,
    pub slots: [usize; 3],
}

/// The declaration's rotation charts, once each. Reported: an argument that is not `vec3` of three
/// coordinates, a coordinate twice in one chart, a coordinate in two different charts.
pub(super) fn rotation_charts(cx: &Ctxt, model: &Model) -> Vec<Chart> {
    let mut visitor = Charts {
        cx,
        model,
        charts: Vec::new(),
    };
    for decl in &model.mechanism.decls {
        visitor.visit_block(&decl.block);
    }
    visitor.charts
}

struct Charts<'c, 'm> {
    cx: &'c Ctxt,
    model: &'c Model<'m>,
    charts: Vec<Chart>,
}

impl<'ast> Visit<'ast> for Charts<'_, '_> {
    fn visit_expr_call(&mut self, call: &'ast ExprCall) {
        syn::visit::visit_expr_call(self, call);
        let Some(kind) = called(&call.func).as_deref().and_then(ChartKind::named) else {
            return;
        };
        let [argument] = call.args.iter().collect::<Vec<_>>()[..] else {
            return; // rustc reports the count.
        };
        match self.slots(argument) {
            Some(slots) => self.record(argument, Chart { kind, slots }),
            None => self.cx.error_spanned_by(
                argument,
                format!(
                    "`{}` takes `vec3(a, b, c)` of three coordinates of its own: the generated \
                     code moves them to the equivalent rotation past an angle of π",
                    called(&call.func).unwrap_or_default()
                ),
            ),
        }
    }
}

impl Charts<'_, '_> {
    /// The flat indices of `vec3(a, b, c)`'s three distinct coordinates.
    fn slots(&self, argument: &Expr) -> Option<[usize; 3]> {
        let Expr::Call(vec3) = strip(argument) else {
            return None;
        };
        if called(&vec3.func).as_deref() != Some("vec3") || vec3.args.len() != 3 {
            return None;
        }
        let mut slots = [0; 3];
        for (slot, a) in slots.iter_mut().zip(&vec3.args) {
            *slot = crate::ast::flat_slot(self.model.coords, a)?;
        }
        let distinct = slots[0] != slots[1] && slots[1] != slots[2] && slots[0] != slots[2];
        distinct.then_some(slots)
    }

    fn record(&mut self, at: &Expr, chart: Chart) {
        let overlaps = |c: &Chart| c.slots.iter().any(|s| chart.slots.contains(s));
        match self.charts.iter().find(|c| overlaps(c)) {
            None => self.charts.push(chart),
            Some(c) if *c == chart => {}
            Some(_) => self.cx.error_spanned_by(
                at,
                "these coordinates are already in another rotation chart: each coordinate may \
                 write one rotation, in one chart",
            ),
        }
    }
}

fn called(func: &Expr) -> Option<String> {
    match strip(func) {
        Expr::Path(p) => Some(p.path.segments.last()?.ident.to_string()),
        _ => None,
    }
}
