//! Forward-mode differentiation of a [`Graph`] along a direction: each leaf (a coordinate, a row of
//! x, time, a velocity) moves at a rate, itself a node, and d/ds of a node follows by the chain rule
//! (Griewank & Walther, *Evaluating Derivatives*, 2nd ed., 2008, §2.2 and Table 2.3). A partial
//! derivative ∂/∂v is the direction in which v alone moves, at rate one; the motion of a mechanism,
//! q → q + s q̇, x → x + s ẋ, t → t + s, is another, and differentiating the result again along the
//! motion (ẋ → ẋ + s ẍ) gives second derivatives along it.

use super::{operands, Graph, Id, Node, Variable};

/// A direction's index in its [`Graph`].
pub type Direction = usize;

impl Graph {
    /// The direction in which each leaf of `rates` moves at its rate (the others are fixed).
    pub fn direction(&mut self, rates: &[(Id, Id)]) -> Direction {
        let mut key: Vec<(Id, Id)> = rates
            .iter()
            .copied()
            .filter(|&(_, rate)| !self.is_zero(rate))
            .collect();
        key.sort_unstable();
        if let Some(&d) = self.direction_index.get(&key) {
            return d;
        }
        let d = self.directions.len();
        self.directions.push(key.iter().copied().collect());
        self.direction_index.insert(key, d);
        d
    }

    /// The leaf node of a variable.
    pub fn leaf(&mut self, v: Variable) -> Id {
        self.node(match v {
            Variable::Coordinate(j) => Node::Coordinate(j),
            Variable::Row(r) => Node::Row(r),
            Variable::Time => Node::Time,
        })
    }

    /// ∂node/∂variable: the derivative along the direction in which the variable alone moves.
    pub fn derivative(&mut self, id: Id, by: Variable) -> Id {
        if !self.varies[id] {
            return self.literal(0.0);
        }
        let (leaf, one) = (self.leaf(by), self.literal(1.0));
        let unit = self.direction(&[(leaf, one)]);
        self.along(id, unit)
    }

    /// d/ds of the node as its leaves move along `direction`, by the chain rule (the tangent rules
    /// in the module docs of [`super`]).
    pub fn along(&mut self, id: Id, direction: Direction) -> Id {
        if !self.varies[id] {
            return self.literal(0.0);
        }
        if let Some(&d) = self.derivatives.get(&(id, direction)) {
            return d;
        }
        let d = match self.nodes[id].clone() {
            Node::Literal(_) | Node::Constant(_) => self.literal(0.0),
            Node::Time
            | Node::Coordinate(_)
            | Node::Row(_)
            | Node::Velocity(_)
            | Node::RowVelocity(_)
            | Node::RowAcceleration(_)
            | Node::Jacobian(..) => match self.directions[direction].get(&id) {
                Some(&rate) => rate,
                None => self.literal(0.0),
            },
            Node::Add(a, b) => {
                let (da, db) = (self.along(a, direction), self.along(b, direction));
                self.add(da, db)
            }
            Node::Sub(a, b) => {
                let (da, db) = (self.along(a, direction), self.along(b, direction));
                self.sub(da, db)
            }
            // (a a)' = 2 a a': the dual numbers' a' a + a a', whose two terms are equal.
            Node::Mul(a, b) if a == b => {
                let da = self.along(a, direction);
                let two = self.literal(2.0);
                let twice = self.mul(two, a);
                self.mul(twice, da)
            }
            // (a b)' = a' b + a b'.
            Node::Mul(a, b) => {
                let (da, db) = (self.along(a, direction), self.along(b, direction));
                let (l, r) = (self.mul(da, b), self.mul(a, db));
                self.add(l, r)
            }
            // (a / b)' = (a' − (a / b) b') / b; for a constant a, −((a / b) / b) b', the factor
            // (a / b) / b shared by every variable.
            Node::Div(a, b) if !self.varies[a] => {
                let db = self.along(b, direction);
                let factor = self.div(id, b);
                let product = self.mul(factor, db);
                self.neg(product)
            }
            Node::Div(a, b) => {
                let (da, db) = (self.along(a, direction), self.along(b, direction));
                let v_db = self.mul(id, db);
                let numerator = self.sub(da, v_db);
                self.div(numerator, b)
            }
            Node::Neg(a) => {
                let da = self.along(a, direction);
                self.neg(da)
            }
            // (aⁿ)' = n aⁿ⁻¹ a'.
            Node::Powi(a, n) => {
                let da = self.along(a, direction);
                let (n, lower) = (self.literal(n as f64), self.powi(a, n - 1));
                let slope = self.mul(n, lower);
                self.mul(slope, da)
            }
            Node::Sqrt(a) => match self.gradient_along(id, direction) {
                Some(d) => d,
                None => {
                    // (√a)' = a' / (2 √a); for a' = 2 y (a sum of squares by one variable),
                    // y / √a, the same quotient (the factors 2 cancel exactly).
                    let da = self.along(a, direction);
                    let two = self.literal(2.0);
                    match self.scaled(da) {
                        Some((power, y)) if power == two => self.div(y, id),
                        _ => {
                            let twice = self.mul(two, id);
                            self.div(da, twice)
                        }
                    }
                }
            },
            Node::Sin(a) => {
                let da = self.along(a, direction);
                let cos = self.node(Node::Cos(a));
                self.mul(cos, da)
            }
            Node::Cos(a) => {
                let da = self.along(a, direction);
                let sin = self.node(Node::Sin(a));
                let product = self.mul(sin, da);
                self.neg(product)
            }
            Node::Exp(a) => {
                let da = self.along(a, direction);
                self.mul(id, da)
            }
            Node::Ln(a) => {
                let da = self.along(a, direction);
                self.div(da, a)
            }
        };
        self.derivatives.insert((id, direction), d);
        d
    }

    /// Σᵥ (∂node/∂v) · (v's rate) when the node's partial derivatives by all its variables are
    /// already taken and it depends on nothing else: the chain rule in another order, equal to
    /// round-off, that reuses them. Taken for a square root, whose partials y/√a are the quotients
    /// a gradient is made of (the unit normal r/|r| of a distance): its rate along the motion is
    /// then the gradient's product with the velocities, r̂·ṙ, formed once for ġ and shared, where
    /// the rule for √ would form ȧ/(2√a) anew.
    fn gradient_along(&mut self, id: Id, direction: Direction) -> Option<Id> {
        let one = *self.index.get(&Node::Literal(1f64.to_bits()))?;
        let rates = &self.directions[direction];
        // A partial derivative is not itself taken this way.
        if rates.len() == 1 && rates.values().all(|&rate| rate == one) {
            return None;
        }
        let mut terms = Vec::new();
        for leaf in self.leaves(id) {
            let unit = *self.direction_index.get(&vec![(leaf, one)])?;
            let partial = *self.derivatives.get(&(id, unit))?;
            if !matches!(
                self.nodes[leaf],
                Node::Coordinate(_) | Node::Row(_) | Node::Time
            ) {
                return None;
            }
            if let Some(&rate) = self.directions[direction].get(&leaf) {
                terms.push((partial, rate));
            }
        }
        let mut sum = self.literal(0.0);
        for (partial, rate) in terms {
            let term = self.mul(partial, rate);
            sum = self.add(sum, term);
        }
        Some(sum)
    }

    /// The leaves the node depends on (coordinates, rows, time, velocities), in the order built.
    fn leaves(&self, id: Id) -> Vec<Id> {
        let mut seen = vec![false; self.nodes.len()];
        let mut stack = vec![id];
        let mut out = Vec::new();
        while let Some(n) = stack.pop() {
            if std::mem::replace(&mut seen[n], true) || !self.varies[n] {
                continue;
            }
            match operands(&self.nodes[n]) {
                ops if ops.is_empty() => out.push(n),
                ops => stack.extend(ops),
            }
        }
        out.sort_unstable();
        out
    }

    /// The variables the node depends on, sorted.
    pub fn variables(&self, id: Id) -> Vec<Variable> {
        let mut out: Vec<Variable> = self
            .leaves(id)
            .into_iter()
            .filter_map(|leaf| match self.nodes[leaf] {
                Node::Coordinate(j) => Some(Variable::Coordinate(j)),
                Node::Row(r) => Some(Variable::Row(r)),
                Node::Time => Some(Variable::Time),
                _ => None,
            })
            .collect();
        out.sort();
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_distance_moves_at_its_gradient_times_the_velocities() {
        // s = √(x x + y y): ∂s/∂x = x/s, ∂s/∂y = y/s, and along (ẋ, ẏ) the rate is the gradient's
        // product with the velocities, the node ġ is made of, not ȧ/(2s) formed anew.
        let mut g = Graph::default();
        let (x, y) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let (xx, yy) = (g.mul(x, x), g.mul(y, y));
        let sum = g.add(xx, yy);
        let s = g.node(Node::Sqrt(sum));
        let dx = g.derivative(s, Variable::Coordinate(0));
        let dy = g.derivative(s, Variable::Coordinate(1));
        assert_eq!(dx, g.div(x, s));
        let (vx, vy) = (g.node(Node::Velocity(0)), g.node(Node::Velocity(1)));
        let (tx, ty) = (g.mul(dx, vx), g.mul(dy, vy));
        let rate = g.add(tx, ty);
        let motion = g.direction(&[(x, vx), (y, vy)]);
        assert_eq!(g.along(s, motion), rate);
        // The velocities are fixed along it: d(x/s) = (ẋ − (x/s) ṡ)/s.
        let d = g.along(dx, motion);
        let product = g.mul(dx, rate);
        let numerator = g.sub(vx, product);
        assert_eq!(d, g.div(numerator, s));
        // Without the partials taken, the rule for √ as before: ȧ/(2s).
        let mut h = Graph::default();
        let (x, y) = (h.node(Node::Coordinate(0)), h.node(Node::Coordinate(1)));
        let (xx, yy) = (h.mul(x, x), h.mul(y, y));
        let sum = h.add(xx, yy);
        let s = h.node(Node::Sqrt(sum));
        let (vx, vy) = (h.node(Node::Velocity(0)), h.node(Node::Velocity(1)));
        let motion = h.direction(&[(x, vx), (y, vy)]);
        let rate = h.along(s, motion);
        let da = h.along(sum, motion);
        let two = h.literal(2.0);
        let twice = h.mul(two, s);
        assert_eq!(rate, h.div(da, twice));
    }

    #[test]
    fn time_is_a_variable_and_directions_are_interned() {
        let mut g = Graph::default();
        let (t, q) = (g.node(Node::Time), g.node(Node::Coordinate(0)));
        let product = g.mul(t, q);
        let sin = g.node(Node::Sin(product));
        assert_eq!(
            g.variables(sin),
            vec![Variable::Coordinate(0), Variable::Time]
        );
        let dt = g.derivative(sin, Variable::Time);
        let cos = g.node(Node::Cos(product));
        assert_eq!(dt, g.mul(cos, q));
        let (v, one, zero) = (g.node(Node::Velocity(0)), g.literal(1.0), g.literal(0.0));
        let a = g.direction(&[(q, v), (t, one)]);
        let b = g.direction(&[(t, one), (q, v), (product, zero)]);
        assert_eq!(a, b);
    }
}
