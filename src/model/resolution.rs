//! The radial resolution per nodal-diameter number k: `plate.radial_splines`
//! fixed, or `auto` — the spline count whose estimated relative frequency
//! error of every requested l is at most `plate.frequency_tolerance`
//! (docs/convergence.md "Radial resolution that follows the request").
//!
//! The estimate is Richardson's: the cubic B-spline Ritz frequencies converge
//! from above as ω_n − ω ≈ C h⁴, h = (r_a − r_i)/(n − 3) (measured order
//! 4.0, docs/convergence.md), so two solves at n_c < n_f give
//!
//! e(n_f) ≈ (ω_{n_c} − ω_{n_f}) · ρ / (1 − ρ),   ρ = ((n_c − 3)/(n_f − 3))⁴,
//!
//! relative to ω_{n_f}. The search starts at the count predicted from the previous k's estimate (the
//! first k of a chain at [`first_guess`]), with n_c − 3 ≈ 0.6 (n_f − 3), and grows n_f by the
//! predicted factor (e/tol)^{1/4} (× [`GROWTH_MARGIN`], between 1.2 and
//! [`MAX_GROWTH`]; the previous fine solve becomes the coarse one) until the
//! estimate is within the tolerance. Above [`DENSE_LIMIT`] free coefficients
//! the eigenproblem is solved by shift-invert Lanczos on the banded factor
//! ([`super::lanczos`]), so the cost per solve grows like n, not n³.

use super::eigen::{lowest_modes, EigenFailure, EigenPairs};
use super::lanczos::lowest_modes_lanczos;
use super::modes::is_rigid_body;
use super::radial::RadialDiscretisation;
use super::ModelError;
use crate::config::PlateConfig;

/// Largest spline count `auto` uses (the validated maximum of `plate.radial_splines`).
pub const MAX_AUTO_SPLINES: usize = 400;
/// Convergence order of the frequencies in h assumed by the estimate.
pub const ORDER: f64 = 4.0;
/// Spans of the coarse solve relative to the fine one.
pub const COARSE_RATIO: f64 = 0.6;
/// Margin on the predicted growth of the spline count.
pub const GROWTH_MARGIN: f64 = 1.1;
/// Largest growth of the span count per step of the search.
pub const MAX_GROWTH: f64 = 1.6;
/// Up to this many free coefficients the dense solver is used.
pub const DENSE_LIMIT: usize = 48;

/// The radial resolution used for one k.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct KResolution {
    /// Nodal diameters.
    pub k: u32,
    /// Uniform cubic B-splines (`plate.radial_splines` semantics: before the
    /// edge conditions, without the graded knots of a small pinned hole).
    pub splines: usize,
    /// `auto`: the estimated largest relative frequency error of the requested
    /// elastic l of this k; `None` for a fixed count.
    pub estimated_error: Option<f64>,
}

/// The eigenpairs chosen for one k (the basis is `Discretisations::get(resolution.splines)`).
pub struct Resolved {
    pub pairs: EigenPairs,
    pub resolution: KResolution,
}

/// The radial discretisations built so far, by spline count: their
/// quadrature does not depend on k, and consecutive k mostly use the same counts.
pub struct Discretisations<'a> {
    plate: &'a PlateConfig,
    rigidity: f64,
    built: Vec<(usize, RadialDiscretisation)>,
}

impl<'a> Discretisations<'a> {
    pub fn new(plate: &'a PlateConfig, rigidity: f64) -> Self {
        Discretisations {
            plate,
            rigidity,
            built: Vec::new(),
        }
    }

    /// Take over the discretisations `other` built.
    fn absorb(&mut self, other: Discretisations<'a>) {
        for (n, d) in other.built {
            if !self.built.iter().any(|(m, _)| *m == n) {
                self.built.push((n, d));
            }
        }
    }

    /// The discretisation with `splines` uniform B-splines (built on first use).
    pub fn get(&mut self, splines: usize) -> &RadialDiscretisation {
        let i = match self.built.iter().position(|(n, _)| *n == splines) {
            Some(i) => i,
            None => {
                self.built.push((
                    splines,
                    RadialDiscretisation::new(self.plate, self.rigidity, splines),
                ));
                self.built.len() - 1
            }
        };
        &self.built[i].1
    }
}

/// The eigenproblem of k on `disc`: the `count` lowest pairs.
pub fn solve(
    disc: &RadialDiscretisation,
    sigma: f64,
    k: u32,
    count: usize,
) -> Result<EigenPairs, ModelError> {
    let (kk, mm) = disc.assemble(k);
    let pairs = lowest_pairs(&kk, &mm, sigma, count).map_err(|e| e.for_k(k))?;
    Ok(pairs)
}

/// Nodal-diameter sets at least this long are searched in two chains on
/// two threads: k in the lower and the upper half (the split does not
/// depend on the machine, so neither do the counts).
pub const PARALLEL_FROM: usize = 16;

/// `auto` for every k of `ks` (ascending): each k starts where the previous
/// k of its chain ended.
pub fn choose_all<'a>(
    plate: &'a PlateConfig,
    rigidity: f64,
    sigma: f64,
    ks: &[u32],
    count: usize,
) -> Result<(Vec<Resolved>, Discretisations<'a>), ModelError> {
    let chain = |part: &[u32]| -> Result<(Vec<Resolved>, Discretisations<'a>), ModelError> {
        let mut discs = Discretisations::new(plate, rigidity);
        let mut start = first_guess(plate);
        let mut out = Vec::with_capacity(part.len());
        for &k in part {
            let ls: Vec<u32> = (0..count as u32)
                .filter(|l| {
                    plate.nodal_circles.contains(l)
                        && !is_rigid_body(plate.inner_boundary, plate.outer_boundary, k, *l)
                })
                .collect();
            let r = choose(&mut discs, sigma, k, &ls, count, start)?;
            start = predicted(r.resolution, plate.frequency_tolerance);
            out.push(r);
        }
        Ok((out, discs))
    };
    if ks.len() < PARALLEL_FROM {
        return chain(ks);
    }
    let (low, high) = ks.split_at(ks.len() / 2);
    let (a, b) = std::thread::scope(|s| {
        let upper = s.spawn(|| chain(high));
        let lower = chain(low);
        (lower, upper.join())
    });
    let (mut resolved, mut discs) = a?;
    let (more, other) = b.unwrap_or_else(|panic| std::panic::resume_unwind(panic))?;
    resolved.extend(more);
    discs.absorb(other);
    Ok((resolved, discs))
}

/// Dense below [`DENSE_LIMIT`] free coefficients, Lanczos above (dense if it
/// does not converge). Also the Mindlin modes' solver.
pub fn lowest_pairs(
    kk: &faer::Mat<f64>,
    mm: &faer::Mat<f64>,
    sigma: f64,
    count: usize,
) -> Result<EigenPairs, EigenFailure> {
    if kk.nrows() > DENSE_LIMIT {
        if let Some(pairs) = lowest_modes_lanczos(kk, mm, sigma, count)? {
            return Ok(pairs);
        }
    }
    lowest_modes(kk, mm, sigma, count)
}

/// The count the search starts from for the first k: 32, or 12 per requested
/// nodal circle (about what l needs for 1e-6 on the lathe disc).
pub fn first_guess(plate: &PlateConfig) -> usize {
    let max_l = plate.nodal_circles.iter().copied().max().unwrap_or(0) as usize;
    (crate::config::DEFAULT_RADIAL_SPLINES)
        .max(12 * max_l + 16)
        .max(plate.min_radial_splines())
        .min(MAX_AUTO_SPLINES)
}

/// Richardson estimate of the largest relative error of the fine solve's
/// ω_l, l in `ls`, from a coarse and a fine solve.
pub fn estimate(coarse: (usize, &EigenPairs), fine: (usize, &EigenPairs), ls: &[u32]) -> f64 {
    let rho = ((coarse.0 as f64 - 3.0) / (fine.0 as f64 - 3.0)).powf(ORDER);
    ls.iter()
        .map(|&l| {
            let (wc, wf) = (
                coarse.1.omega_squared[l as usize].max(0.0).sqrt(),
                fine.1.omega_squared[l as usize].max(0.0).sqrt(),
            );
            (wc - wf).abs() / wf * rho / (1.0 - rho)
        })
        .fold(0.0, f64::max)
}

/// The count predicted to just reach the tolerance from a resolved k (× the
/// growth margin): where the next k's search starts.
fn predicted(r: KResolution, tolerance: f64) -> usize {
    let e = r.estimated_error.unwrap_or(tolerance).max(1e-3 * tolerance);
    let spans = (r.splines - 3) as f64 * (e / tolerance).powf(1.0 / ORDER) * GROWTH_MARGIN;
    (3 + spans.ceil() as usize).min(r.splines)
}

fn coarse_of(fine: usize) -> usize {
    3 + ((fine - 3) as f64 * COARSE_RATIO).round() as usize
}

/// `auto` for one k: the elastic requested `ls` (the eigenproblem returns
/// `count` = max l + 1 pairs) to `plate.frequency_tolerance`, starting at `start`.
pub fn choose(
    discs: &mut Discretisations,
    sigma: f64,
    k: u32,
    ls: &[u32],
    count: usize,
    start: usize,
) -> Result<Resolved, ModelError> {
    let plate = discs.plate;
    let tolerance = plate.frequency_tolerance;
    let min = plate.min_radial_splines();
    // The coarse solve must have at least the minimum count too.
    let lowest_fine = 3 + ((min.saturating_sub(3)) as f64 / COARSE_RATIO).ceil() as usize + 1;
    let mut fine_n = start.max(lowest_fine).min(MAX_AUTO_SPLINES);
    let coarse_n = coarse_of(fine_n).max(min);
    let mut coarse = (coarse_n, solve(discs.get(coarse_n), sigma, k, count)?);
    loop {
        let pairs = solve(discs.get(fine_n), sigma, k, count)?;
        let e = estimate((coarse.0, &coarse.1), (fine_n, &pairs), ls);
        if e <= tolerance {
            return Ok(Resolved {
                pairs,
                resolution: KResolution {
                    k,
                    splines: fine_n,
                    estimated_error: Some(e),
                },
            });
        }
        if fine_n >= MAX_AUTO_SPLINES {
            return Err(ModelError::FrequencyToleranceNotReached {
                k,
                tolerance,
                reached: e,
                splines: fine_n,
            });
        }
        let grow = ((e / tolerance).powf(1.0 / ORDER) * GROWTH_MARGIN).clamp(1.2, MAX_GROWTH);
        let next = 3 + ((fine_n - 3) as f64 * grow).ceil() as usize;
        coarse = (fine_n, pairs);
        fine_n = next.min(MAX_AUTO_SPLINES);
    }
}
