//! A sweep's inputs and results as rows of numbers: what a part file stores (a column per cell)
//! and what MPI ranks send to each other.

/// A value stored as a fixed number of cells, each an `f64` or missing (`None`): a cell is a
/// column of a part file (`Parts`, with the `parquet` feature), and a missing cell is a null there.
///
/// Implemented for `f64` (one cell, never missing), `Option<f64>` (one cell, missing for `None`),
/// arrays `[f64; N]`, and pairs and triples of implementors (their cells side by side).
/// `from_cells(&cells)` after `write_cells(&mut cells)` gives the value back bit for bit.
///
/// ```
/// use lagrange_core::ensemble::Cells;
///
/// let mut cells = Vec::new();
/// ((0.5, -1.25), Some(3.0)).write_cells(&mut cells);
/// assert_eq!(cells, [Some(0.5), Some(-1.25), Some(3.0)]);
/// assert_eq!(<((f64, f64), Option<f64>)>::WIDTH, 3);
/// let back = <((f64, f64), Option<f64>)>::from_cells(&cells);
/// assert_eq!(back, Some(((0.5, -1.25), Some(3.0))));
/// // An `f64` cell cannot be missing.
/// assert_eq!(f64::from_cells(&[None]), None);
/// ```
pub trait Cells: Sized {
    /// The number of cells.
    const WIDTH: usize;

    /// Appends the value's `WIDTH` cells to `out`.
    fn write_cells(&self, out: &mut Vec<Option<f64>>);

    /// The value of the first `WIDTH` cells, or `None` if there are fewer or one that must be
    /// present is missing.
    fn from_cells(cells: &[Option<f64>]) -> Option<Self>;
}

impl Cells for f64 {
    const WIDTH: usize = 1;

    fn write_cells(&self, out: &mut Vec<Option<f64>>) {
        out.push(Some(*self));
    }

    fn from_cells(cells: &[Option<f64>]) -> Option<Self> {
        *cells.first()?
    }
}

impl Cells for Option<f64> {
    const WIDTH: usize = 1;

    fn write_cells(&self, out: &mut Vec<Option<f64>>) {
        out.push(*self);
    }

    fn from_cells(cells: &[Option<f64>]) -> Option<Self> {
        cells.first().copied()
    }
}

impl<const N: usize> Cells for [f64; N] {
    const WIDTH: usize = N;

    fn write_cells(&self, out: &mut Vec<Option<f64>>) {
        out.extend(self.iter().map(|&x| Some(x)));
    }

    fn from_cells(cells: &[Option<f64>]) -> Option<Self> {
        let cells = cells.get(..N)?;
        let mut out = [0.0; N];
        for (o, c) in out.iter_mut().zip(cells) {
            *o = (*c)?;
        }
        Some(out)
    }
}

impl<A: Cells, B: Cells> Cells for (A, B) {
    const WIDTH: usize = A::WIDTH + B::WIDTH;

    fn write_cells(&self, out: &mut Vec<Option<f64>>) {
        self.0.write_cells(out);
        self.1.write_cells(out);
    }

    fn from_cells(cells: &[Option<f64>]) -> Option<Self> {
        Some((
            A::from_cells(cells)?,
            B::from_cells(cells.get(A::WIDTH..)?)?,
        ))
    }
}

impl<A: Cells, B: Cells, C: Cells> Cells for (A, B, C) {
    const WIDTH: usize = A::WIDTH + B::WIDTH + C::WIDTH;

    fn write_cells(&self, out: &mut Vec<Option<f64>>) {
        self.0.write_cells(out);
        self.1.write_cells(out);
        self.2.write_cells(out);
    }

    fn from_cells(cells: &[Option<f64>]) -> Option<Self> {
        let ((a, b), c) = <((A, B), C)>::from_cells(cells)?;
        Some((a, b, c))
    }
}

/// The cells of every value, row after row (`values.len() · T::WIDTH` cells).
#[cfg(any(feature = "mpi", test))]
pub(crate) fn rows_to_cells<T: Cells>(values: &[T]) -> Vec<Option<f64>> {
    let mut cells = Vec::with_capacity(values.len() * T::WIDTH);
    for v in values {
        v.write_cells(&mut cells);
    }
    cells
}

/// The values of rows of `T::WIDTH` cells, or `None` at the first row that is not a `T`.
#[cfg(any(feature = "mpi", feature = "parquet", test))]
pub(crate) fn cells_to_rows<T: Cells>(cells: &[Option<f64>]) -> Option<Vec<T>> {
    if T::WIDTH == 0 {
        return None;
    }
    cells.chunks(T::WIDTH).map(T::from_cells).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_round_trip_bit_for_bit() {
        let rows = [
            ([0.1, -0.0], Some(f64::MIN_POSITIVE)),
            ([f64::MAX, 1e-300], None),
        ];
        let cells = rows_to_cells(&rows);
        assert_eq!(cells.len(), 6);
        let back: Vec<([f64; 2], Option<f64>)> = cells_to_rows(&cells).unwrap();
        let bits = |r: &([f64; 2], Option<f64>)| (r.0.map(f64::to_bits), r.1.map(f64::to_bits));
        assert_eq!(
            back.iter().map(bits).collect::<Vec<_>>(),
            rows.iter().map(bits).collect::<Vec<_>>()
        );
        // A missing cell where a number is required is not a row.
        assert!(cells_to_rows::<(f64, f64)>(&[Some(1.0), None]).is_none());
        assert!(<(f64, f64, f64)>::from_cells(&[Some(1.0), Some(2.0)]).is_none());
    }
}
