//! The k axis that the master tables and the restitution tables share: which table is a k's own,
//! and which k lie between tables, where the polynomial in ln k through the tables around k
//! answers (where its checks vouch). One rule for both kinds of table.

/// Two k closer than this (relative) are the same k: a query at a table's own k uses that table
/// alone (the tables' k are stored to 17 digits; the difference is rounding).
pub const SAME_K: f64 = 1e-12;

/// The fewest tables that answer a k between their own (a cubic in ln k through four; more
/// tables give the higher degrees of the stencils).
pub const MIN_TABLES_BETWEEN: usize = 4;

/// Whether `k` is the table k `t` to within [`SAME_K`] (dimensionless).
pub fn same_k(k: f64, t: f64) -> bool {
    // |k/t - 1| < SAME_K without a division
    (k - t).abs() < SAME_K * t
}

/// The index in `ks` (the tables' k, increasing) of the table whose own k is `k`.
pub fn own_table(ks: &[f64], k: f64) -> Option<usize> {
    ks.iter().position(|&t| same_k(k, t))
}

/// Whether `k` lies strictly between the first and the last of at least
/// [`MIN_TABLES_BETWEEN`] tables of k `ks` (increasing).
pub fn between_tables(ks: &[f64], k: f64) -> bool {
    let n = ks.len();
    n >= MIN_TABLES_BETWEEN && k > ks[0] && k < ks[n - 1]
}

/// Whether tables of k `ks` answer at `k` anywhere: one of their own k, or between them.
pub fn covered(ks: &[f64], k: f64) -> bool {
    own_table(ks, k).is_some() || between_tables(ks, k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn own_k_between_and_outside() {
        let ks = [0.005, 0.01, 0.02, 0.04];
        assert_eq!(own_table(&ks, 0.01 * (1.0 + 1e-13)), Some(1));
        assert_eq!(own_table(&ks, 0.011), None);
        assert!(between_tables(&ks, 0.011) && covered(&ks, 0.011));
        assert!(covered(&ks, 0.04) && !between_tables(&ks, 0.04));
        assert!(!covered(&ks, 0.05) && !covered(&ks, 0.004));
        // fewer than four tables: only their own k
        assert!(!covered(&ks[..3], 0.011) && covered(&ks[..3], 0.02));
    }
}
