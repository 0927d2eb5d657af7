use super::*;
use proptest::prelude::*;

fn solver(g: &[f64], n: usize) -> DenseQp {
    DenseQp::new(g, n, 16).unwrap_or_else(|_| panic!("G is positive definite"))
}

#[test]
fn without_constraints_it_is_the_closed_form_minimiser() {
    // G = [[4, 1], [1, 3]], a = [1, 2]: x = −G⁻¹ a = −[1, 7] / 11.
    let mut qp = solver(&[4.0, 1.0, 1.0, 3.0], 2);
    let c = Constraints::new(2, 0);
    let x = qp
        .solve(&[1.0, 2.0], &c)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert!((x[0] + 1.0 / 11.0).abs() < 1e-15 && (x[1] + 7.0 / 11.0).abs() < 1e-15);
}

#[test]
fn a_hand_solved_programme_gives_its_point_and_multiplier() {
    // min ½|x|² − x₁ − x₂ with x₁ + x₂ ≤ 1: x = (½, ½), λ = ½ on the upper side.
    let mut qp = solver(&[1.0, 0.0, 0.0, 1.0], 2);
    let mut c = Constraints::new(2, 2);
    c.push(f64::NEG_INFINITY, 1.0).copy_from_slice(&[1.0, 1.0]);
    // A bound that never binds.
    c.push(-5.0, f64::INFINITY).copy_from_slice(&[1.0, 0.0]);
    let x = qp
        .solve(&[-1.0, -1.0], &c)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert!(
        (x[0] - 0.5).abs() < 1e-15 && (x[1] - 0.5).abs() < 1e-15,
        "{x:?}"
    );
    let mut m = [0.0; 2];
    qp.row_multipliers(2, &mut m);
    assert!((m[0] + 0.5).abs() < 1e-15 && m[1] == 0.0, "{m:?}");
}

#[test]
fn an_equality_is_met_exactly() {
    // min ½|x|² with x₁ + 2 x₂ = 5: x = (1, 2).
    let mut qp = solver(&[1.0, 0.0, 0.0, 1.0], 2);
    let mut c = Constraints::new(2, 1);
    c.push_equality(5.0)
        .unwrap_or_else(|| panic!("first"))
        .copy_from_slice(&[1.0, 2.0]);
    let x = qp
        .solve(&[0.0, 0.0], &c)
        .unwrap_or_else(|e| panic!("{e:?}"));
    assert!(
        (x[0] - 1.0).abs() < 1e-14 && (x[1] - 2.0).abs() < 1e-14,
        "{x:?}"
    );
}

#[test]
fn contradicting_constraints_are_infeasible() {
    let mut qp = solver(&[1.0, 0.0, 0.0, 1.0], 2);
    let mut c = Constraints::new(2, 2);
    c.push(1.0, f64::INFINITY).copy_from_slice(&[1.0, 0.0]);
    c.push(f64::NEG_INFINITY, 0.0).copy_from_slice(&[1.0, 0.0]);
    assert_eq!(qp.solve(&[0.0, 0.0], &c), Err(QpFailure::Infeasible));
    // Two equalities that disagree.
    let mut c = Constraints::new(2, 2);
    c.push_equality(1.0)
        .unwrap_or_else(|| panic!("first"))
        .copy_from_slice(&[1.0, 1.0]);
    c.push_equality(2.0)
        .unwrap_or_else(|| panic!("second"))
        .copy_from_slice(&[2.0, 2.0]);
    // After an inequality, an equality is refused.
    c.push(0.0, 1.0);
    assert!(c.push_equality(0.0).is_none());
    assert_eq!(qp.solve(&[0.0, 0.0], &c), Err(QpFailure::Infeasible));
}

#[test]
fn a_matrix_that_is_not_positive_definite_is_refused() {
    assert!(DenseQp::new(&[1.0, 2.0, 2.0, 1.0], 2, 0).is_err());
    assert!(DenseQp::new(&[1.0, 0.0, 0.0, f64::NAN], 2, 0).is_err());
}

/// A programme: `n`, `G` (column-major), `a`, the rows with their bounds, the equalities.
type Programme = (usize, Vec<f64>, Vec<f64>, Vec<(Vec<f64>, f64, f64)>, usize);

/// A random strictly convex programme with a known feasible point.
fn programme() -> impl Strategy<Value = Programme> {
    (2usize..9).prop_flat_map(|n| {
        let m = prop::collection::vec(-1.0..1.0f64, n * n);
        let a = prop::collection::vec(-10.0..10.0f64, n);
        let feasible = prop::collection::vec(-1.0..1.0f64, n);
        let rows = prop::collection::vec(
            (
                prop::collection::vec(-1.0..1.0f64, n),
                0.01..2.0f64,
                0.01..2.0f64,
                0u8..3,
            ),
            0..3 * n,
        );
        let equalities = 0usize..n.min(3);
        (Just(n), m, a, feasible, rows, equalities).prop_map(
            |(n, m, a, feasible, rows, equalities)| {
                // G = MᵀM + ½ I.
                let mut g = vec![0.0; n * n];
                for i in 0..n {
                    for j in 0..n {
                        g[j * n + i] = (0..n).map(|k| m[i * n + k] * m[j * n + k]).sum::<f64>()
                            + if i == j { 0.5 } else { 0.0 };
                    }
                }
                let mut built = Vec::new();
                for (k, (c, below, above, kind)) in rows.into_iter().enumerate() {
                    let v: f64 = c.iter().zip(&feasible).map(|(x, y)| x * y).sum();
                    let (l, u) = if k < equalities {
                        (v, v)
                    } else {
                        match kind {
                            0 => (v - below, f64::INFINITY),
                            1 => (f64::NEG_INFINITY, v + above),
                            _ => (v - below, v + above),
                        }
                    };
                    built.push((c, l, u));
                }
                let equalities = equalities.min(built.len());
                (n, g, a, built, equalities)
            },
        )
    })
}

/// The rows into `c`: those with equal bounds (the first) as equalities.
fn push_all(c: &mut Constraints, rows: &[(Vec<f64>, f64, f64)]) {
    for (row, l, u) in rows {
        let coefficients = if l == u {
            c.push_equality(*l)
                .unwrap_or_else(|| panic!("equalities first"))
        } else {
            c.push(*l, *u)
        };
        coefficients.copy_from_slice(row);
    }
}

proptest! {
    /// The answer meets the optimality conditions (Karush–Kuhn–Tucker), which for a
    /// strictly convex programme make it the one minimiser: every row met, `G x + a`
    /// a combination of the active rows, lower sides with multipliers ≥ 0 and upper
    /// sides ≤ 0, each inactive row's multiplier 0.
    #[test]
    fn every_answer_meets_the_optimality_conditions((n, g, a, rows, _eq) in programme()) {
        let mut qp = solver(&g, n);
        let mut c = Constraints::new(n, rows.len());
        push_all(&mut c, &rows);
        let x = qp.solve(&a, &c).unwrap_or_else(|e| panic!("{e:?}")).to_vec();
        let mut m = vec![0.0; rows.len()];
        qp.row_multipliers(rows.len(), &mut m);
        for (k, (row, l, u)) in rows.iter().enumerate() {
            let v: f64 = row.iter().zip(&x).map(|(p, q)| p * q).sum();
            prop_assert!(v >= l - 1e-8 && v <= u + 1e-8, "row {k}: {l} ≤ {v} ≤ {u}");
            if l != u {
                if m[k] > 0.0 { prop_assert!((v - l).abs() < 1e-8, "row {k} not at its lower side"); }
                if m[k] < 0.0 { prop_assert!((v - u).abs() < 1e-8, "row {k} not at its upper side"); }
            }
        }
        for i in 0..n {
            let gx: f64 = (0..n).map(|j| g[j * n + i] * x[j]).sum::<f64>() + a[i];
            let combination: f64 = rows.iter().zip(&m).map(|((row, _, _), mk)| mk * row[i]).sum();
            prop_assert!((gx - combination).abs() < 1e-7 * (1.0 + gx.abs()), "stationarity {i}: {gx} vs {combination}");
        }
    }

    /// The same programme twice, and once after another (the warm start's order), gives
    /// the same answer.
    #[test]
    fn a_warm_start_changes_nothing_but_the_path((n, g, a, rows, _eq) in programme()) {
        let mut qp = solver(&g, n);
        let mut c = Constraints::new(n, rows.len());
        push_all(&mut c, &rows);
        let cold = solver(&g, n).solve(&a, &c).map(<[f64]>::to_vec);
        let _ = qp.solve(&a.iter().map(|v| -v).collect::<Vec<_>>(), &c);
        let warm = qp.solve(&a, &c).map(<[f64]>::to_vec);
        match (cold, warm) {
            (Ok(x), Ok(y)) => {
                for (p, q) in x.iter().zip(&y) {
                    prop_assert!((p - q).abs() < 1e-7 * (1.0 + p.abs()), "{x:?} vs {y:?}");
                }
            }
            (x, y) => prop_assert_eq!(x, y),
        }
    }
}
