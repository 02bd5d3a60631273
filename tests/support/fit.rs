//! Fits the tests share.
#![allow(dead_code)]

/// The least-squares slope of y against x: Σ(x − x̄)(y − ȳ) / Σ(x − x̄)².
/// With x the times and y = ln|amplitude| of a run, its growth rate (1/s).
pub fn least_squares_slope(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    x.iter()
        .zip(y)
        .map(|(x, y)| (x - mx) * (y - my))
        .sum::<f64>()
        / x.iter().map(|x| (x - mx).powi(2)).sum::<f64>()
}
