//! Polynomials over the atoms of a declaration: sin qⱼ, cos qⱼ, qⱼ and q̇ⱼ (the variables), and
//! parameters, constants, masses and weights (the constants), with `f64` coefficients. Exponents
//! are integers; a constant or a coordinate may have a negative one (a quotient by a parameter, 1/r).
//!
//! Sums, products and ∂/∂qⱼ are exact on this representation; [`Poly::reduce`] brings a polynomial
//! to the normal form modulo sin² qⱼ + cos² qⱼ = 1 (every sin qⱼ to at most the first power), so
//! m l² (sin² θ + cos² θ) becomes m l² and −s c + s c becomes 0.

use std::collections::BTreeMap;

/// One factor of a monomial.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Atom {
    /// A parameter, by its index in the parameter struct.
    Param(usize),
    /// A constant subexpression of parameters and constants, by its index in the reader's table.
    Constant(usize),
    /// The mass (or moment of inertia) of row r of x.
    Mass(usize),
    /// sin qⱼ.
    Sin(usize),
    /// cos qⱼ.
    Cos(usize),
    /// qⱼ.
    Coord(usize),
    /// q̇ⱼ.
    Vel(usize),
}

impl Atom {
    /// Whether the atom changes with the state (q, q̇); the others are constants of the parameters.
    pub fn is_variable(self) -> bool {
        matches!(
            self,
            Atom::Sin(_) | Atom::Cos(_) | Atom::Coord(_) | Atom::Vel(_)
        )
    }
}

/// A product of atoms with their exponents, sorted by atom, no zero exponent.
pub type Monomial = Vec<(Atom, i32)>;

/// A sum of monomials with non-zero coefficients.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Poly {
    pub terms: BTreeMap<Monomial, f64>,
}

impl Poly {
    pub fn zero() -> Self {
        Poly::default()
    }

    pub fn number(c: f64) -> Self {
        let mut p = Poly::zero();
        p.add_term(Vec::new(), c);
        p
    }

    pub fn atom(a: Atom) -> Self {
        let mut p = Poly::zero();
        p.add_term(vec![(a, 1)], 1.0);
        p
    }

    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Whether no term has a variable atom.
    pub fn is_constant(&self) -> bool {
        self.terms
            .keys()
            .all(|m| m.iter().all(|(a, _)| !a.is_variable()))
    }

    /// The value of a polynomial that is a plain number.
    pub fn as_number(&self) -> Option<f64> {
        match self.terms.len() {
            0 => Some(0.0),
            1 => self
                .terms
                .iter()
                .next()
                .filter(|(m, _)| m.is_empty())
                .map(|(_, c)| *c),
            _ => None,
        }
    }

    fn add_term(&mut self, m: Monomial, c: f64) {
        if c == 0.0 {
            return;
        }
        let entry = self.terms.entry(m).or_insert(0.0);
        *entry += c;
        if *entry == 0.0 {
            self.terms.retain(|_, c| *c != 0.0);
        }
    }

    pub fn add(&self, other: &Poly) -> Poly {
        let mut out = self.clone();
        for (m, c) in &other.terms {
            out.add_term(m.clone(), *c);
        }
        out
    }

    pub fn scale(&self, s: f64) -> Poly {
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            out.add_term(m.clone(), c * s);
        }
        out
    }

    pub fn sub(&self, other: &Poly) -> Poly {
        self.add(&other.scale(-1.0))
    }

    pub fn mul(&self, other: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (a, ca) in &self.terms {
            for (b, cb) in &other.terms {
                out.add_term(multiply(a, b), ca * cb);
            }
        }
        out
    }

    /// 1/p of a polynomial that is one monomial with a non-zero coefficient whose variables, if
    /// any, are coordinates (1/r in polar coordinates; not 1/sin θ).
    pub fn reciprocal(&self) -> Option<Poly> {
        let invertible = self.terms.keys().all(|m| {
            m.iter()
                .all(|(a, _)| !a.is_variable() || matches!(a, Atom::Coord(_)))
        });
        if self.terms.len() != 1 || !invertible {
            return None;
        }
        let (m, c) = self.terms.iter().next()?;
        let inverse: Monomial = m.iter().map(|&(a, e)| (a, -e)).collect();
        let mut out = Poly::zero();
        out.add_term(inverse, 1.0 / c);
        Some(out)
    }

    /// ∂p/∂qⱼ: sin qⱼ → cos qⱼ, cos qⱼ → −sin qⱼ, qⱼ → 1, by the product rule.
    pub fn derivative(&self, j: usize) -> Poly {
        let mut out = Poly::zero();
        for (m, c) in &self.terms {
            for (k, &(atom, e)) in m.iter().enumerate() {
                let (inner, sign) = match atom {
                    Atom::Sin(i) if i == j => (Some(Atom::Cos(j)), 1.0),
                    Atom::Cos(i) if i == j => (Some(Atom::Sin(j)), -1.0),
                    Atom::Coord(i) if i == j => (None, 1.0),
                    _ => continue,
                };
                // d(aᵉ) = e aᵉ⁻¹ da.
                let mut rest = m.clone();
                rest[k].1 -= 1;
                rest.retain(|&(_, e)| e != 0);
                let rest = match inner {
                    Some(a) => multiply(&rest, &[(a, 1)]),
                    None => rest,
                };
                out.add_term(rest, c * e as f64 * sign);
            }
        }
        out
    }

    /// The normal form modulo sin² qⱼ + cos² qⱼ = 1: sinᵉ qⱼ = sinᵉ⁻² qⱼ (1 − cos² qⱼ) until
    /// every sine is at most linear.
    pub fn reduce(&self) -> Poly {
        let mut out = Poly::zero();
        let mut pending: Vec<(Monomial, f64)> =
            self.terms.iter().map(|(m, c)| (m.clone(), *c)).collect();
        while let Some((m, c)) = pending.pop() {
            let square = m
                .iter()
                .position(|&(a, e)| matches!(a, Atom::Sin(_)) && e >= 2);
            let Some(k) = square else {
                out.add_term(m, c);
                continue;
            };
            let Atom::Sin(j) = m[k].0 else { unreachable!() };
            let mut lower = m.clone();
            lower[k].1 -= 2;
            lower.retain(|&(_, e)| e != 0);
            pending.push((multiply(&lower, &[(Atom::Cos(j), 2)]), -c));
            pending.push((lower, c));
        }
        out
    }

    /// The terms grouped by their variable part: variable monomial → its constant coefficient
    /// (a polynomial in the constant atoms).
    pub fn by_variables(&self) -> BTreeMap<Monomial, Poly> {
        let mut out: BTreeMap<Monomial, Poly> = BTreeMap::new();
        for (m, c) in &self.terms {
            let (variable, constant): (Monomial, Monomial) =
                m.iter().partition(|(a, _)| a.is_variable());
            let mut coefficient = Poly::zero();
            coefficient.add_term(constant, *c);
            let entry = out.entry(variable).or_default();
            *entry = entry.add(&coefficient);
        }
        out.retain(|_, c| !c.is_zero());
        out
    }
}

/// The product of two monomials, exponents added.
fn multiply(a: &[(Atom, i32)], b: &[(Atom, i32)]) -> Monomial {
    let mut out: BTreeMap<Atom, i32> = a.iter().copied().collect();
    for &(atom, e) in b {
        *out.entry(atom).or_insert(0) += e;
    }
    out.into_iter().filter(|&(_, e)| e != 0).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(j: usize) -> Poly {
        Poly::atom(Atom::Sin(j))
    }
    fn c(j: usize) -> Poly {
        Poly::atom(Atom::Cos(j))
    }

    #[test]
    fn pythagoras_reduces_to_one() {
        let l = Poly::atom(Atom::Param(0));
        let m = Poly::atom(Atom::Mass(0));
        // The pendulum's M = m (l cos θ)² + m (l sin θ)².
        let jx = l.mul(&c(0));
        let jy = l.mul(&s(0));
        let mass_matrix = m.mul(&jx.mul(&jx)).add(&m.mul(&jy.mul(&jy))).reduce();
        assert_eq!(mass_matrix, m.mul(&l).mul(&l));
        // sin⁴ + 2 sin² cos² + cos⁴ = (sin² + cos²)² = 1.
        let s2 = s(0).mul(&s(0));
        let c2 = c(0).mul(&c(0));
        let square = s2.mul(&s2).add(&s2.mul(&c2).scale(2.0)).add(&c2.mul(&c2));
        assert_eq!(square.reduce(), Poly::number(1.0));
        // Different angles do not combine.
        assert_eq!(s(0).mul(&s(1)).reduce(), s(0).mul(&s(1)));
    }

    #[test]
    fn derivatives_by_the_product_rule() {
        // d/dθ (θ² sin θ) = 2 θ sin θ + θ² cos θ.
        let q = Poly::atom(Atom::Coord(0));
        let f = q.mul(&q).mul(&s(0));
        let expected = q.mul(&s(0)).scale(2.0).add(&q.mul(&q).mul(&c(0)));
        assert_eq!(f.derivative(0), expected);
        // cos of another coordinate is a constant for ∂/∂q₀.
        assert_eq!(c(1).derivative(0), Poly::zero());
        assert_eq!(c(1).derivative(1), s(1).scale(-1.0));
    }

    #[test]
    fn reciprocal_of_a_constant_monomial() {
        let l = Poly::atom(Atom::Param(0));
        let half_over_l = l.scale(2.0).reciprocal().unwrap();
        assert_eq!(half_over_l.mul(&l), Poly::number(0.5));
        assert!(s(0).reciprocal().is_none());
        // 1/r², and its derivative −2/r³.
        let r = Poly::atom(Atom::Coord(1));
        let inverse_square = r.mul(&r).reciprocal().unwrap();
        assert_eq!(inverse_square.mul(&r).mul(&r), Poly::number(1.0));
        assert_eq!(
            inverse_square.derivative(1).mul(&r).mul(&r).mul(&r),
            Poly::number(-2.0)
        );
        assert!(l.add(&Poly::number(1.0)).reciprocal().is_none());
    }

    #[test]
    fn grouping_by_variables() {
        let m = Poly::atom(Atom::Mass(0));
        let p = m.mul(&c(0)).add(&c(0).scale(2.0)).add(&m);
        let groups = p.by_variables();
        assert_eq!(groups.len(), 2);
        assert_eq!(groups[&vec![(Atom::Cos(0), 1)]], m.add(&Poly::number(2.0)));
        assert_eq!(groups[&Vec::new()], m);
    }
}
