//! Piecewise-linear tables in the manner of Abaqus's `*GAP CONDUCTANCE` data lines: linear
//! between rows, constant outside the first and last row (so the derivative is zero there), and
//! optionally a family of such tables over the mean surface temperature θ̄, interpolated
//! linearly between temperatures and constant outside them.

/// y(x), piecewise linear, constant outside `[x_first, x_last]`.
#[derive(Clone, Debug, PartialEq)]
pub struct Table1 {
    xs: Vec<f64>,
    ys: Vec<f64>,
}

/// Why a table was refused (the configuration reader adds file, line and key).
#[derive(Clone, Debug, PartialEq)]
pub struct TableError(pub String);

impl Table1 {
    /// From `(x, y)` rows: at least one row, finite values, x strictly increasing.
    pub fn new(rows: &[(f64, f64)]) -> Result<Self, TableError> {
        if rows.is_empty() {
            return Err(TableError("the table is empty".into()));
        }
        for (i, (x, y)) in rows.iter().enumerate() {
            if !x.is_finite() || !y.is_finite() {
                return Err(TableError(format!("row {} is not finite", i + 1)));
            }
        }
        if let Some(i) = rows.windows(2).position(|w| w[1].0 <= w[0].0) {
            return Err(TableError(format!(
                "rows {} and {} are not in strictly increasing order of the first column",
                i + 1,
                i + 2
            )));
        }
        Ok(Table1 {
            xs: rows.iter().map(|r| r.0).collect(),
            ys: rows.iter().map(|r| r.1).collect(),
        })
    }

    /// Number of rows.
    #[must_use]
    pub fn len(&self) -> usize {
        self.xs.len()
    }

    /// Never true: a table has at least one row.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.xs.is_empty()
    }

    /// The smallest tabulated y.
    #[must_use]
    pub fn min_value(&self) -> f64 {
        self.ys.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// y(x) and dy/dx. On a row, the segment to its right is used; outside, dy/dx = 0.
    #[inline]
    #[must_use]
    pub fn eval(&self, x: f64) -> (f64, f64) {
        let n = self.xs.len();
        if x < self.xs[0] {
            return (self.ys[0], 0.0);
        }
        if x >= self.xs[n - 1] {
            return (self.ys[n - 1], 0.0);
        }
        // First row strictly above x; x is inside, so 1 ≤ hi ≤ n − 1.
        let hi = self.xs.partition_point(|&r| r <= x);
        let lo = hi - 1;
        let slope = (self.ys[hi] - self.ys[lo]) / (self.xs[hi] - self.xs[lo]);
        (self.ys[lo] + slope * (x - self.xs[lo]), slope)
    }
}

/// y(x, θ̄): one [`Table1`] per temperature, linear in θ̄ between them, constant outside.
#[derive(Clone, Debug, PartialEq)]
pub struct TemperatureTable {
    temperatures: Vec<f64>,
    tables: Vec<Table1>,
}

impl TemperatureTable {
    /// From rows `(x, y, θ̄)`, grouped by θ̄ (all rows of one temperature together, temperatures
    /// strictly increasing, x strictly increasing within a temperature), as Abaqus lists them.
    pub fn new(rows: &[(f64, f64, f64)]) -> Result<Self, TableError> {
        if rows.is_empty() {
            return Err(TableError("the table is empty".into()));
        }
        let mut temperatures = Vec::new();
        let mut tables = Vec::new();
        let mut start = 0;
        while start < rows.len() {
            let theta = rows[start].2;
            if !theta.is_finite() {
                return Err(TableError(format!(
                    "row {}: the temperature is not finite",
                    start + 1
                )));
            }
            if temperatures.last().is_some_and(|&t| theta <= t) {
                return Err(TableError(format!(
                    "row {}: temperature {theta} comes after a higher or equal one; list the rows \
                     of each temperature together, temperatures increasing",
                    start + 1
                )));
            }
            let end = rows[start..]
                .iter()
                .position(|r| r.2 != theta)
                .map_or(rows.len(), |k| start + k);
            let group: Vec<(f64, f64)> = rows[start..end].iter().map(|r| (r.0, r.1)).collect();
            let table = Table1::new(&group).map_err(|TableError(m)| {
                TableError(format!(
                    "temperature {theta} (rows {}–{end}): {m}",
                    start + 1
                ))
            })?;
            temperatures.push(theta);
            tables.push(table);
            start = end;
        }
        Ok(TemperatureTable {
            temperatures,
            tables,
        })
    }

    /// A table with no temperature dependence.
    #[must_use]
    pub fn constant_in_temperature(table: Table1) -> Self {
        TemperatureTable {
            temperatures: vec![0.0],
            tables: vec![table],
        }
    }

    /// The smallest tabulated y over all temperatures (linear interpolation never goes below).
    #[must_use]
    pub fn min_value(&self) -> f64 {
        self.tables
            .iter()
            .map(Table1::min_value)
            .fold(f64::INFINITY, f64::min)
    }

    /// Total number of rows.
    #[must_use]
    pub fn rows(&self) -> usize {
        self.tables.iter().map(Table1::len).sum()
    }

    /// y(x, θ̄), ∂y/∂x and ∂y/∂θ̄.
    #[inline]
    #[must_use]
    pub fn eval(&self, x: f64, theta: f64) -> (f64, f64, f64) {
        let n = self.temperatures.len();
        // On the first temperature the slope in θ̄ is the one to its right, as on any row.
        if n == 1 || theta < self.temperatures[0] {
            let (y, dy) = self.tables[0].eval(x);
            return (y, dy, 0.0);
        }
        if theta >= self.temperatures[n - 1] {
            let (y, dy) = self.tables[n - 1].eval(x);
            return (y, dy, 0.0);
        }
        let hi = self.temperatures.partition_point(|&t| t <= theta);
        let lo = hi - 1;
        let (t0, t1) = (self.temperatures[lo], self.temperatures[hi]);
        let w = (theta - t0) / (t1 - t0);
        let (y0, d0) = self.tables[lo].eval(x);
        let (y1, d1) = self.tables[hi].eval(x);
        (
            y0 + w * (y1 - y0),
            d0 + w * (d1 - d0),
            (y1 - y0) / (t1 - t0),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_inside_constant_outside() {
        let t = Table1::new(&[(0.0, 1.0), (100.0, 3.0)]).unwrap();
        assert_eq!(t.eval(-5.0), (1.0, 0.0));
        assert_eq!(t.eval(0.0), (1.0, 0.02));
        assert_eq!(t.eval(50.0), (2.0, 0.02));
        assert_eq!(t.eval(100.0), (3.0, 0.0));
        assert_eq!(t.eval(1e9), (3.0, 0.0));
    }

    #[test]
    fn bad_tables_are_refused() {
        assert!(Table1::new(&[]).is_err());
        assert!(Table1::new(&[(1.0, 1.0), (1.0, 2.0)]).is_err());
        assert!(Table1::new(&[(1.0, f64::NAN)]).is_err());
        assert!(TemperatureTable::new(&[(0.0, 1.0, 50.0), (0.0, 1.0, 20.0)]).is_err());
    }

    #[test]
    fn temperature_family_interpolates_bilinearly() {
        let t = TemperatureTable::new(&[
            (0.0, 1.0, 0.0),
            (10.0, 2.0, 0.0),
            (0.0, 3.0, 100.0),
            (10.0, 5.0, 100.0),
        ])
        .unwrap();
        // At θ̄ = 25: y(5) = 0.75·1.5 + 0.25·4 = 2.125; ∂y/∂x = 0.75·0.1 + 0.25·0.2;
        // ∂y/∂θ̄ = (4 − 1.5)/100.
        let (y, dx, dt) = t.eval(5.0, 25.0);
        assert!((y - 2.125).abs() < 1e-15);
        assert!((dx - 0.125).abs() < 1e-15);
        assert!((dt - 0.025).abs() < 1e-15);
        assert_eq!(t.eval(5.0, -10.0), (1.5, 0.1, 0.0));
        // On the first temperature: the value there, the slope to the right.
        assert_eq!(t.eval(5.0, 0.0), (1.5, 0.1, 0.025));
        assert_eq!(t.eval(5.0, 200.0), (4.0, 0.2, 0.0));
    }
}
