//! A tabulated friction coefficient μ(γ̇_eq, p, θ̄), in the manner of Abaqus's `*FRICTION` data
//! lines (seed 000, section 5.2.3: μ "can be defined as a function of the contact pressure, the
//! slip rate, the average surface temperature"): rows `[μ, γ̇]`, `[μ, γ̇, p]` or
//! `[μ, γ̇, p, θ̄]`, the first independent variable varying fastest. Linear between rows,
//! constant outside the first and last row (the derivative is then zero); on a row the slope of
//! the segment to its right is used.
//!
//! Layout: rows of one (p, θ̄) together with γ̇ strictly increasing; within one θ̄ the pressures
//! strictly increasing; the temperatures strictly increasing. μ is interpolated in γ̇ on each
//! pressure, then linearly in p, then linearly in θ̄.

use crate::laws::table::{Table1, TableError};

/// Why a table was refused: the message, and the row (1-based) at fault, 0 for the whole table
/// (the configuration reader turns the row into a line of the file).
#[derive(Clone, Debug, PartialEq)]
pub struct FrictionTableError {
    /// Row at fault (1-based), 0 when no single row is.
    pub row: usize,
    /// What is wrong, naming the row.
    pub message: String,
}

fn refuse(row: usize, message: String) -> FrictionTableError {
    FrictionTableError { row, message }
}

/// One pressure family at one temperature: μ(γ̇) per pressure.
#[derive(Clone, Debug, PartialEq)]
struct PressureFamily {
    pressures: Vec<f64>,
    rates: Vec<Table1>,
}

/// μ(γ̇, p, θ̄), validated: finite, μ ≥ 0, γ̇ ≥ 0, every key strictly increasing.
#[derive(Clone, Debug, PartialEq)]
pub struct FrictionTable {
    temperatures: Vec<f64>,
    families: Vec<PressureFamily>,
    /// Number of columns of the rows it was built from (2, 3 or 4).
    width: usize,
}

/// μ and its partial derivatives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TableValue {
    /// μ.
    pub mu: f64,
    /// ∂μ/∂γ̇.
    pub d_rate: f64,
    /// ∂μ/∂p.
    pub d_pressure: f64,
    /// ∂μ/∂θ̄.
    pub d_temperature: f64,
}

/// Where `x` falls among sorted `keys`: (lo, hi, w, ∂w/∂x) with the value
/// y_lo + w (y_hi − y_lo); constant (w = 0, ∂w/∂x = 0) outside the keys.
#[inline]
fn bracket(keys: &[f64], x: f64) -> (usize, usize, f64, f64) {
    let n = keys.len();
    if n == 1 || x < keys[0] {
        return (0, 0, 0.0, 0.0);
    }
    if x >= keys[n - 1] {
        return (n - 1, n - 1, 0.0, 0.0);
    }
    let hi = keys.partition_point(|&k| k <= x);
    let lo = hi - 1;
    let inv = 1.0 / (keys[hi] - keys[lo]);
    (lo, hi, (x - keys[lo]) * inv, inv)
}

impl PressureFamily {
    /// (μ, ∂μ/∂γ̇, ∂μ/∂p).
    #[inline]
    fn eval(&self, rate: f64, pressure: f64) -> (f64, f64, f64) {
        let (lo, hi, w, dw) = bracket(&self.pressures, pressure);
        let (a, da) = self.rates[lo].eval(rate);
        if lo == hi {
            return (a, da, 0.0);
        }
        let (b, db) = self.rates[hi].eval(rate);
        (a + w * (b - a), da + w * (db - da), (b - a) * dw)
    }
}

impl FrictionTable {
    /// From rows `[μ, γ̇]`, `[μ, γ̇, p]` or `[μ, γ̇, p, θ̄]` (all of one width). Errors name the
    /// row (1-based) at fault.
    pub fn new(rows: &[Vec<f64>]) -> Result<Self, FrictionTableError> {
        let Some(first) = rows.first() else {
            return Err(refuse(0, "the table is empty".into()));
        };
        let width = first.len();
        if !(2..=4).contains(&width) {
            return Err(refuse(
                1,
                format!("row 1 has {width} entries; use [μ, γ̇], [μ, γ̇, p] or [μ, γ̇, p, θ̄]"),
            ));
        }
        for (i, r) in rows.iter().enumerate() {
            if r.len() != width {
                return Err(refuse(
                    i + 1,
                    format!(
                        "row {} has {} entries; every row needs {width} (as row 1)",
                        i + 1,
                        r.len()
                    ),
                ));
            }
            if let Some(j) = r.iter().position(|v| !v.is_finite()) {
                return Err(refuse(
                    i + 1,
                    format!("row {}: entry {} = {} is not finite", i + 1, j + 1, r[j]),
                ));
            }
            if r[0] < 0.0 {
                return Err(refuse(
                    i + 1,
                    format!("row {}: μ = {} is negative", i + 1, r[0]),
                ));
            }
            if r[1] < 0.0 {
                return Err(refuse(
                    i + 1,
                    format!("row {}: slip rate γ̇ = {} is negative", i + 1, r[1]),
                ));
            }
        }
        // Column c of row i, 0 when the table has no such column.
        let key = |i: usize, c: usize| rows[i].get(c).copied().unwrap_or(0.0);
        let mut temperatures: Vec<f64> = Vec::new();
        let mut families: Vec<PressureFamily> = Vec::new();
        let mut start = 0;
        while start < rows.len() {
            let (p, theta) = (key(start, 2), key(start, 3));
            let end = (start..rows.len())
                .find(|&i| key(i, 2) != p || key(i, 3) != theta)
                .unwrap_or(rows.len());
            let pairs: Vec<(f64, f64)> = rows[start..end].iter().map(|r| (r[1], r[0])).collect();
            let rates = Table1::new(&pairs).map_err(|TableError(_)| {
                let i = start + pairs.windows(2).position(|w| w[1].0 <= w[0].0).unwrap_or(0);
                refuse(
                    i + 2,
                    format!(
                        "rows {} and {}: slip rates must be strictly increasing within one \
                     pressure and temperature",
                        i + 1,
                        i + 2
                    ),
                )
            })?;
            let unsorted = |what: &str| {
                refuse(
                    start + 1,
                    format!(
                        "row {}: {what}; list the rows of one pressure together (slip rate \
                     increasing), pressures increasing within one temperature, temperatures \
                     increasing",
                        start + 1
                    ),
                )
            };
            let same_temperature = temperatures.last() == Some(&theta);
            if let Some(family) = families.last_mut().filter(|_| same_temperature) {
                if family.pressures.last().is_some_and(|&q| p <= q) {
                    return Err(unsorted(&format!(
                        "pressure {p} comes after a higher or equal one"
                    )));
                }
                family.pressures.push(p);
                family.rates.push(rates);
            } else {
                if temperatures.last().is_some_and(|&t| theta <= t) {
                    return Err(unsorted(&format!(
                        "temperature {theta} comes after a higher one"
                    )));
                }
                temperatures.push(theta);
                families.push(PressureFamily {
                    pressures: vec![p],
                    rates: vec![rates],
                });
            }
            start = end;
        }
        Ok(FrictionTable {
            temperatures,
            families,
            width,
        })
    }

    /// True when μ depends on θ̄ (more than one temperature).
    #[must_use]
    pub fn depends_on_temperature(&self) -> bool {
        self.temperatures.len() > 1
    }

    /// The columns of the rows the table was built from.
    #[must_use]
    pub fn width(&self) -> usize {
        self.width
    }

    /// μ(γ̇, p, θ̄) and its partial derivatives.
    #[inline]
    #[must_use]
    pub fn eval(&self, rate: f64, pressure: f64, temperature: f64) -> TableValue {
        let (lo, hi, w, dw) = bracket(&self.temperatures, temperature);
        let (a, a_r, a_p) = self.families[lo].eval(rate, pressure);
        if lo == hi {
            return TableValue {
                mu: a,
                d_rate: a_r,
                d_pressure: a_p,
                d_temperature: 0.0,
            };
        }
        let (b, b_r, b_p) = self.families[hi].eval(rate, pressure);
        TableValue {
            mu: a + w * (b - a),
            d_rate: a_r + w * (b_r - a_r),
            d_pressure: a_p + w * (b_p - a_p),
            d_temperature: (b - a) * dw,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(rows: &[&[f64]]) -> Result<FrictionTable, FrictionTableError> {
        FrictionTable::new(&rows.iter().map(|r| r.to_vec()).collect::<Vec<_>>())
    }

    #[test]
    fn rate_table_is_linear_inside_constant_outside() {
        let t = table(&[&[0.5, 0.0], &[0.3, 2.0]]).unwrap();
        let v = t.eval(1.0, 7.0, 99.0);
        assert!((v.mu - 0.4).abs() < 1e-15);
        assert!((v.d_rate + 0.1).abs() < 1e-15);
        assert_eq!((v.d_pressure, v.d_temperature), (0.0, 0.0));
        assert_eq!(t.eval(5.0, 0.0, 0.0).mu, 0.3);
        assert_eq!(t.eval(5.0, 0.0, 0.0).d_rate, 0.0);
        assert!(!t.depends_on_temperature());
    }

    #[test]
    fn trilinear_interpolation() {
        // μ = 0.1 + 0.01 γ̇ + 0.001 p + 0.0001 θ̄ on the corners is reproduced exactly inside.
        let mu = |r: f64, p: f64, th: f64| 0.1 + 0.01 * r + 0.001 * p + 0.0001 * th;
        let mut rows = Vec::new();
        for th in [0.0, 100.0] {
            for p in [0.0, 50.0] {
                for r in [0.0, 10.0] {
                    rows.push(vec![mu(r, p, th), r, p, th]);
                }
            }
        }
        let t = FrictionTable::new(&rows).unwrap();
        let v = t.eval(3.0, 20.0, 40.0);
        assert!((v.mu - mu(3.0, 20.0, 40.0)).abs() < 1e-15);
        assert!((v.d_rate - 0.01).abs() < 1e-15);
        assert!((v.d_pressure - 0.001).abs() < 1e-15);
        assert!((v.d_temperature - 0.0001).abs() < 1e-15);
        assert!(t.depends_on_temperature());
    }

    #[test]
    fn bad_tables_name_the_row() {
        for (rows, needle) in [
            (&[][..], "empty"),
            (&[&[0.5, 1.0][..], &[0.4, 0.5]][..], "rows 1 and 2"),
            (&[&[0.5, 0.0][..], &[f64::NAN, 1.0]][..], "row 2: entry 1"),
            (&[&[-0.1, 0.0][..]][..], "negative"),
            (&[&[0.1, -1.0][..]][..], "slip rate"),
            (&[&[0.1, 0.0, 5.0][..], &[0.1, 0.0]][..], "row 2 has 2"),
            (&[&[0.1, 0.0, 5.0][..], &[0.1, 0.0, 1.0]][..], "pressure 1"),
            (
                &[&[0.1, 0.0, 0.0, 9.0][..], &[0.1, 0.0, 0.0, 1.0]][..],
                "temperature 1",
            ),
            (&[&[0.1][..]][..], "row 1 has 1"),
        ] {
            let e = table(rows).unwrap_err().message;
            assert!(e.contains(needle), "{e}");
        }
    }
}
