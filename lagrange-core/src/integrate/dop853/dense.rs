//! Completion of an accepted Dormand–Prince 8(5,3) step: the FSAL evaluation and the continuous
//! extension of order 7 (or the cubic Hermite interpolant).

use super::attempt::{evaluate_stage, Stages};
use super::tableau::D;
use super::Dop853;
use crate::error::Result;
use crate::integrate::dense::{hermite_rows, DenseOutput};
use crate::integrate::pair::AccelerationField;
use crate::integrate::Stats;

/// Completes an accepted [`attempt`](super::attempt) of size h from (t, q, v, q̈) to (q₁, q̇₁),
/// whose stages are in `k`: the FSAL evaluation q̈₁ at the new point (stage 13), and the dense
/// output — the 7th-order continuous extension of `dop853.f` (CONTD8, stages 14–16 evaluated
/// here), or the cubic Hermite interpolant with `dense: false`, written into `dense` once every
/// evaluation has succeeded.
#[allow(clippy::too_many_arguments)]
#[inline]
pub(crate) fn accept<const N: usize>(
    st: &Dop853,
    (t, q, v, a): (f64, &[f64; N], &[f64; N], &[f64; N]),
    h: f64,
    (q1, v1): (&[f64; N], &[f64; N]),
    k: &mut Stages<N>,
    stats: &mut Stats,
    field: &impl AccelerationField<N>,
    dense: &mut DenseOutput<N>,
) -> Result<[f64; N]> {
    stats.evaluations += 1;
    let a1 = field.accelerations(t + h, q1, v1)?;
    k.kq[12] = field.position_rates(q1, v1);
    k.ka[12] = a1;
    if !st.dense {
        let rates = (&k.kq[0], &k.kq[12]);
        dense.set_hermite(t, h, (q, v, a), (q1, v1, &a1), rates);
        return Ok(a1);
    }
    let y = (t, q, v);
    evaluate_stage::<13, N>(y, h, k, stats, field)?;
    evaluate_stage::<14, N>(y, h, k, stats, field)?;
    evaluate_stage::<15, N>(y, h, k, stats, field)?;
    let make = |y0: &[f64; N], y1: &[f64; N], k: &[[f64; N]; 16]| {
        let mut r = [[0.0; N]; 8];
        // Stage 1 is the derivative at the step's start, stage 13 (FSAL) the one at its end.
        hermite_rows(&mut r, h, y0, y1, &k[0], &k[12]);
        for n in 0..N {
            for (row, d) in D.iter().enumerate() {
                let mut s = 0.0;
                for j in 0..16 {
                    s += d[j] * k[j][n];
                }
                r[4 + row][n] = h * s;
            }
        }
        r
    };
    *dense = DenseOutput::from_coefficients(t, h, make(q, q1, &k.kq), make(v, v1, &k.ka));
    Ok(a1)
}
