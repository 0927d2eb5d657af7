//! What the measurements determine: the singular values of the identification Jacobian,
//! the parameter combinations no measurement changes, and each parameter's uncertainty.
//!
//! The Jacobian `J` (one row per measured pose, one column per free parameter, every
//! column in metres of residual per metre of parameter) is factorised `J = Q R`, and the
//! small `R` by an SVD: `J`'s singular values and right singular vectors without forming
//! `JᵀJ`, whose squaring would lose half the digits of a weak direction.

use nalgebra::{DMatrix, SVD};

/// A direction counts as undetermined when its singular value is below this fraction of
/// the largest: the measurements then change the residuals by less than rounding does.
pub(crate) const RANK_TOLERANCE: f64 = 1e-7;
/// Most SVD sweeps (bounded: nalgebra's unbounded SVD never returns on NaN).
const SVD_MAX_ITERATIONS: usize = 1000;

/// The identification of one leg's free parameters.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Identification {
    /// Singular values of `J / √m` (m measured poses), largest first: the RMS change of
    /// the residuals, metres, for a unit change of the parameters along each direction.
    pub singular_values: Vec<f64>,
    /// Combinations of the free parameters (column, coefficient) that change no residual,
    /// in reduced row echelon form (each led by a coefficient 1).
    pub undetermined: Vec<Vec<(usize, f64)>>,
    /// The direction of the smallest singular value (unit vector over the free columns):
    /// the parameter combination the measurements see least.
    pub weakest: Vec<f64>,
    /// Diagonal of `(JᵀJ)⁻¹` (times the noise variance: each parameter's variance); empty
    /// when some direction is undetermined.
    pub inverse_diagonal: Vec<f64>,
}

/// The identification from the Jacobian `jacobian` (rows: poses, columns: free parameters).
pub(crate) fn identify(jacobian: &DMatrix<f64>) -> Option<Identification> {
    let (m, n) = jacobian.shape();
    if n == 0 {
        return Some(Identification {
            singular_values: Vec::new(),
            undetermined: Vec::new(),
            weakest: Vec::new(),
            inverse_diagonal: Vec::new(),
        });
    }
    if m < n || jacobian.iter().any(|v| !v.is_finite()) {
        return None;
    }
    let r = jacobian.clone().qr().r();
    let svd = SVD::try_new(r, false, true, f64::EPSILON, SVD_MAX_ITERATIONS)?;
    let v_t = svd.v_t.as_ref()?;
    let mut order: Vec<usize> = (0..n).collect();
    order.sort_by(|&a, &b| svd.singular_values[b].total_cmp(&svd.singular_values[a]));
    let largest = svd.singular_values[order[0]];
    let null: Vec<usize> = order
        .iter()
        .copied()
        .filter(|&k| svd.singular_values[k] <= RANK_TOLERANCE * largest)
        .collect();
    let undetermined = echelon(
        &null
            .iter()
            .map(|&k| (0..n).map(|c| v_t[(k, c)]).collect())
            .collect::<Vec<Vec<f64>>>(),
    );
    let inverse_diagonal = if null.is_empty() {
        (0..n)
            .map(|c| {
                order
                    .iter()
                    .map(|&k| (v_t[(k, c)] / svd.singular_values[k]).powi(2))
                    .sum()
            })
            .collect()
    } else {
        Vec::new()
    };
    let smallest = order[n - 1];
    let weakest = (0..n).map(|c| v_t[(smallest, c)]).collect();
    let root_m = (m as f64).sqrt();
    Some(Identification {
        singular_values: order
            .iter()
            .map(|&k| svd.singular_values[k] / root_m)
            .collect(),
        undetermined,
        weakest,
        inverse_diagonal,
    })
}

/// The reduced row echelon form of the rows `basis` (a basis of the null space), each row
/// as its non-negligible (column, coefficient) pairs: a readable basis of the same space.
/// For pure translations this turns any rotated basis into `b.x + a.x`, `b.y + a.y`, ….
fn echelon(basis: &[Vec<f64>]) -> Vec<Vec<(usize, f64)>> {
    let mut rows: Vec<Vec<f64>> = basis.to_vec();
    let Some(n) = rows.first().map(Vec::len) else {
        return Vec::new();
    };
    let mut lead = 0;
    for col in 0..n {
        if lead == rows.len() {
            break;
        }
        let Some(pivot) =
            (lead..rows.len()).max_by(|&a, &b| rows[a][col].abs().total_cmp(&rows[b][col].abs()))
        else {
            break;
        };
        if rows[pivot][col].abs() < 1e-6 {
            continue;
        }
        rows.swap(lead, pivot);
        let p = rows[lead][col];
        rows[lead].iter_mut().for_each(|v| *v /= p);
        let led = rows[lead].clone();
        for (i, row) in rows.iter_mut().enumerate() {
            if i != lead {
                let f = row[col];
                row.iter_mut().zip(&led).for_each(|(v, l)| *v -= f * l);
            }
        }
        lead += 1;
    }
    rows.iter()
        .map(|row| {
            row.iter()
                .enumerate()
                .filter(|(_, v)| v.abs() > 1e-6)
                .map(|(c, v)| (c, *v))
                .collect()
        })
        .filter(|row: &Vec<(usize, f64)>| !row.is_empty())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_rank_jacobian_has_no_undetermined_direction_and_its_exact_inverse() {
        // J = diag(2, 4) stacked on zeros: singular values 4/√3, 2/√3; (JᵀJ)⁻¹ = diag(1/4, 1/16).
        let j = DMatrix::from_row_slice(3, 2, &[2.0, 0.0, 0.0, 4.0, 0.0, 0.0]);
        let id = identify(&j).unwrap_or_else(|| panic!("identifiable"));
        let root3 = 3f64.sqrt();
        assert!((id.singular_values[0] - 4.0 / root3).abs() < 1e-15);
        assert!((id.singular_values[1] - 2.0 / root3).abs() < 1e-15);
        assert!(id.undetermined.is_empty());
        assert!((id.inverse_diagonal[0] - 0.25).abs() < 1e-15);
        assert!((id.inverse_diagonal[1] - 1.0 / 16.0).abs() < 1e-15);
    }

    #[test]
    fn columns_that_always_cancel_are_named_as_one_combination() {
        // Columns 0 and 2 are opposite in every row: only their difference is seen, so
        // x0 + x2 changes nothing.
        let j = DMatrix::from_row_slice(
            4,
            3,
            &[
                1.0, 0.5, -1.0, 2.0, -1.0, -2.0, 0.3, 2.0, -0.3, -1.0, 1.0, 1.0,
            ],
        );
        let id = identify(&j).unwrap_or_else(|| panic!("finite"));
        assert_eq!(id.undetermined.len(), 1);
        let combo = &id.undetermined[0];
        assert_eq!(combo.len(), 2);
        assert_eq!(combo[0].0, 0);
        assert!((combo[0].1 - 1.0).abs() < 1e-12);
        assert_eq!(combo[1].0, 2);
        assert!((combo[1].1 - 1.0).abs() < 1e-12);
        assert!(id.inverse_diagonal.is_empty());
    }

    #[test]
    fn a_rotated_null_basis_comes_back_in_echelon_form() {
        // The span of (1,0,1,0) and (0,1,0,1), given rotated by 30°.
        let (s, c) = 30f64.to_radians().sin_cos();
        let basis = vec![vec![c, s, c, s], vec![-s, c, -s, c]];
        let rows = echelon(&basis);
        assert_eq!(rows.len(), 2);
        assert_eq!(rows[0].iter().map(|p| p.0).collect::<Vec<_>>(), vec![0, 2]);
        assert_eq!(rows[1].iter().map(|p| p.0).collect::<Vec<_>>(), vec![1, 3]);
        for row in &rows {
            for (_, v) in row {
                assert!((v - 1.0).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn non_finite_or_too_short_jacobians_are_not_identified() {
        assert!(identify(&DMatrix::from_row_slice(1, 2, &[1.0, 2.0])).is_none());
        assert!(identify(&DMatrix::from_row_slice(2, 1, &[1.0, f64::NAN])).is_none());
    }
}
