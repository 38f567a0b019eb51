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
            Node::Mul(a, b) if a == b => self.along_square(a, direction),
            Node::Mul(a, b) => self.along_product(a, b, direction),
            Node::Div(a, b) => self.along_quotient(id, a, b, direction),
            Node::Neg(a) => {
                let da = self.along(a, direction);
                self.neg(da)
            }
            Node::Powi(a, n) => self.along_power(a, n, direction),
            Node::Sqrt(a) => self.along_sqrt(id, a, direction),
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
            // (eᵃ)' = eᵃ a'.
            Node::Exp(a) => {
                let da = self.along(a, direction);
                self.mul(id, da)
            }
            // (ln a)' = a' / a.
            Node::Ln(a) => {
                let da = self.along(a, direction);
                self.div(da, a)
            }
        };
        self.derivatives.insert((id, direction), d);
        d
    }

    /// (a a)' = 2 a a': the dual numbers' a' a + a a', whose two terms are equal. Where a' varies,
    /// as 2 (a a'): the rates of a sum of squares then add up to 2 Σ a a' (see `Graph::add`),
    /// whose 2 the rule for √ cancels; a constant a' joins the 2 instead.
    fn along_square(&mut self, a: Id, direction: Direction) -> Id {
        let da = self.along(a, direction);
        let two = self.literal(2.0);
        if self.varies[da] {
            let product = self.mul(a, da);
            self.mul(two, product)
        } else {
            let twice = self.mul(two, a);
            self.mul(twice, da)
        }
    }

    /// (a b)' = a' b + a b'.
    fn along_product(&mut self, a: Id, b: Id, direction: Direction) -> Id {
        let (da, db) = (self.along(a, direction), self.along(b, direction));
        let (l, r) = (self.mul(da, b), self.mul(a, db));
        self.add(l, r)
    }

    /// (a / b)' = (a' − (a / b) b') / b for the quotient `id` = a / b; for a constant a,
    /// −((a / b) / b) b', the factor (a / b) / b shared by every variable.
    fn along_quotient(&mut self, id: Id, a: Id, b: Id, direction: Direction) -> Id {
        if !self.varies[a] {
            let db = self.along(b, direction);
            let factor = self.div(id, b);
            let product = self.mul(factor, db);
            return self.neg(product);
        }
        let (da, db) = (self.along(a, direction), self.along(b, direction));
        let v_db = self.mul(id, db);
        let numerator = self.sub(da, v_db);
        self.div(numerator, b)
    }

    /// (aⁿ)' = n aⁿ⁻¹ a'.
    fn along_power(&mut self, a: Id, n: i32, direction: Direction) -> Id {
        let da = self.along(a, direction);
        let (n, lower) = (self.literal(n as f64), self.powi(a, n - 1));
        let slope = self.mul(n, lower);
        self.mul(slope, da)
    }

    /// (√a)' = a' / (2 √a) for the root `id` = √a; for a' = 2 y (a sum of squares), y / √a, the
    /// same quotient (the factors 2 cancel exactly).
    fn along_sqrt(&mut self, id: Id, a: Id, direction: Direction) -> Id {
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
    fn a_distance_moves_at_its_radial_velocity() {
        // s = √(x x + y y) along (ẋ, ẏ): (x x)' = 2 (x ẋ), the rates add up to 2 (x ẋ + y ẏ), and
        // √'s rule cancels the 2: ṡ = (x ẋ + y ẏ)/s.
        let mut g = Graph::default();
        let (x, y) = (g.node(Node::Coordinate(0)), g.node(Node::Coordinate(1)));
        let (xx, yy) = (g.mul(x, x), g.mul(y, y));
        let sum = g.add(xx, yy);
        let s = g.node(Node::Sqrt(sum));
        let (vx, vy) = (g.node(Node::Velocity(0)), g.node(Node::Velocity(1)));
        let motion = g.direction(&[(x, vx), (y, vy)]);
        let rate = g.along(s, motion);
        let (xvx, yvy) = (g.mul(x, vx), g.mul(y, vy));
        let radial = g.add(xvx, yvy);
        assert_eq!(rate, g.div(radial, s));
        // Along it again with the velocities fixed: (ẋ ẋ + ẏ ẏ − ṡ ṡ)/s, ṡ's own node reused.
        let fixed = g.direction(&[(x, vx), (y, vy)]);
        let second = g.along(rate, fixed);
        let (vxx, vyy) = (g.mul(vx, vx), g.mul(vy, vy));
        let speed = g.add(vxx, vyy);
        let square = g.mul(rate, rate);
        let numerator = g.sub(speed, square);
        assert_eq!(second, g.div(numerator, s));
        // By one variable, as before: ∂s/∂x = x/s.
        let dx = g.derivative(s, Variable::Coordinate(0));
        assert_eq!(dx, g.div(x, s));
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
