//! `plate.*` (without the centrifugal keys, `centrifugal.rs`): geometry,
//! material, the modes requested and their radial discretisation, read and
//! checked as `config/table.rs` states the rules, and the quantities the
//! model is built from checked to be representable. Called from
//! `config_from_params` in `validate.rs`.

use super::error::Degeneracy;
use super::raw::{positive, Reader};
use super::{Boundary, ConfigError, PlateConfig, PlateTheory, RadialSplines};

/// Largest nodal-diameter number k accepted.
const MAX_NODAL_DIAMETER: i64 = 200;
/// Largest nodal-circle number l accepted.
const MAX_NODAL_CIRCLE: i64 = 50;
/// Largest `plate.radial_splines`.
const MAX_RADIAL_SPLINES: i64 = 400;
/// Range of `plate.frequency_tolerance`.
const MIN_FREQUENCY_TOLERANCE: f64 = 1e-9;
const MAX_FREQUENCY_TOLERANCE: f64 = 1e-2;
/// Smallest r_i / r_a (paper 4.2: no solid circular plate).
const MIN_RADIUS_RATIO: f64 = 1e-6;
/// Smallest (r_a − r_i) / r_a (paper 4.2: frequencies of a narrow ring go to infinity).
const MIN_RELATIVE_WIDTH: f64 = 1e-3;

pub(super) fn read_plate(r: &Reader) -> Result<PlateConfig, ConfigError> {
    let inner = r.f64("plate.inner_radius")?;
    let outer = r.positive("plate.outer_radius")?;
    if inner < 0.0 {
        return Err(ConfigError::NotPositive {
            key: "plate.inner_radius".into(),
            value: inner,
        });
    }
    if inner >= outer {
        return Err(ConfigError::InnerRadiusNotBelowOuter { inner, outer });
    }
    if inner / outer < MIN_RADIUS_RATIO {
        return Err(ConfigError::DegenerateGeometry {
            kind: Degeneracy::SolidCircularPlate,
            inner,
            outer,
        });
    }
    // A ring exactly 1e-3 wide must pass despite the rounding of (r_a − r_i)/r_a.
    if (outer - inner) / outer < MIN_RELATIVE_WIDTH * (1.0 - 1e-9) {
        return Err(ConfigError::DegenerateGeometry {
            kind: Degeneracy::NarrowRing,
            inner,
            outer,
        });
    }

    let thickness = r.positive("plate.thickness")?;
    let density = r.positive("plate.density")?;
    let youngs_modulus = r.positive("plate.youngs_modulus")?;
    let poisson_ratio = read_poisson_ratio(r, youngs_modulus)?;

    let theory = read_theory(r)?;
    let shear_correction = read_shear_correction(r)?;
    let inner_boundary = read_boundary(r, "plate.inner_boundary", theory)?;
    let outer_boundary = read_boundary(r, "plate.outer_boundary", theory)?;

    let nodal_diameters = read_index_list(r, "plate.nodal_diameters", MAX_NODAL_DIAMETER)?;
    let nodal_circles = read_index_list(r, "plate.nodal_circles", MAX_NODAL_CIRCLE)?;
    let in_plane_nodal_diameters =
        read_indices(r, "plate.in_plane_nodal_diameters", MAX_NODAL_DIAMETER)?;
    let in_plane_orders = read_index_list(r, "plate.in_plane_orders", MAX_NODAL_CIRCLE)?;

    let radial_splines = read_radial_splines(r)?;
    let frequency_tolerance = r.positive("plate.frequency_tolerance")?;
    if !(MIN_FREQUENCY_TOLERANCE..=MAX_FREQUENCY_TOLERANCE).contains(&frequency_tolerance) {
        return Err(ConfigError::FrequencyToleranceOutOfRange {
            value: frequency_tolerance,
            low: MIN_FREQUENCY_TOLERANCE,
            high: MAX_FREQUENCY_TOLERANCE,
        });
    }

    let mut plate = PlateConfig {
        inner_radius: inner,
        outer_radius: outer,
        thickness,
        density,
        youngs_modulus,
        poisson_ratio,
        inner_boundary,
        outer_boundary,
        nodal_diameters,
        nodal_circles,
        damping: Vec::new(),
        radial_splines,
        frequency_tolerance,
        residual_flexibility: r.bool("plate.residual_flexibility")?,
        residual_patch_radius: read_patch_radius(r, theory, outer - inner)?,
        theory,
        shear_correction,
        in_plane_nodal_diameters,
        in_plane_orders,
    };

    check_derived(&plate)?;
    let needed = plate.min_radial_splines();
    if let RadialSplines::Fixed(splines) = plate.radial_splines {
        if splines < needed {
            let removed =
                inner_boundary.essential_conditions() + outer_boundary.essential_conditions();
            return Err(ConfigError::TooFewRadialSplines {
                splines,
                needed,
                free: splines.saturating_sub(removed),
                removed,
                max_l: plate.nodal_circles.iter().copied().max().unwrap_or(0),
                inner: inner_boundary.name(),
                outer: outer_boundary.name(),
            });
        }
    }

    let n_modes = plate.mode_count();
    if n_modes == 0 {
        return Err(ConfigError::NoElasticModes {
            skipped: rigid_body_modes_selected(&plate),
        });
    }
    let damping = r.f64_array("plate.damping")?;
    for (index, &value) in damping.iter().enumerate() {
        if !(0.0..1.0).contains(&value) {
            return Err(ConfigError::DampingOutOfRange { index, value });
        }
    }
    if damping.len() != 1 && damping.len() != n_modes {
        return Err(ConfigError::DampingLength {
            len: damping.len(),
            n_modes,
        });
    }
    plate.damping = damping;
    Ok(plate)
}

/// `plate.residual_patch_radius`: `auto` (None) or a number of metres,
/// > 0 and at most half the annulus' `width`; only with Mindlin theory.
fn read_patch_radius(
    r: &Reader,
    theory: PlateTheory,
    width: f64,
) -> Result<Option<f64>, ConfigError> {
    const KEY: &str = "plate.residual_patch_radius";
    if !r.has(KEY) {
        return Ok(None);
    }
    if let Ok(name) = r.string(KEY) {
        return match name.trim() {
            "auto" => Ok(None),
            _ => Err(ConfigError::PatchRadiusNotAutoOrNumber {
                found: format!("\"{name}\""),
            }),
        };
    }
    let c = r.positive(KEY)?;
    if c > 0.5 * width {
        return Err(ConfigError::AboveMaximum {
            key: KEY.into(),
            value: c,
            max: 0.5 * width,
        });
    }
    if theory != PlateTheory::Mindlin {
        return Err(ConfigError::PatchRadiusNeedsMindlin);
    }
    Ok(Some(c))
}

/// `plate.radial_splines`: `auto` or an integer count in 0..=400 (the
/// minimum for the requested l is checked with the plate).
fn read_radial_splines(r: &Reader) -> Result<RadialSplines, ConfigError> {
    const KEY: &str = "plate.radial_splines";
    if !r.has(KEY) {
        return Ok(RadialSplines::Auto);
    }
    if let Ok(name) = r.string(KEY) {
        return match name.trim() {
            "auto" => Ok(RadialSplines::Auto),
            _ => Err(ConfigError::RadialSplinesNotAutoOrCount {
                found: format!("\"{name}\""),
            }),
        };
    }
    let splines = r.i64(KEY).map_err(|e| match e {
        ConfigError::WrongType { key, found, .. } => ConfigError::WrongType {
            key,
            expected: "`auto` or an integer",
            found,
        },
        other => other,
    })?;
    if splines < 0 {
        return Err(ConfigError::Negative {
            key: KEY.into(),
            value: splines as f64,
        });
    }
    if splines > MAX_RADIAL_SPLINES {
        return Err(ConfigError::AboveMaximum {
            key: KEY.into(),
            value: splines as f64,
            max: MAX_RADIAL_SPLINES as f64,
        });
    }
    Ok(RadialSplines::Fixed(splines as usize))
}

/// The quantities the model is built from must be representable with room
/// to spare: flexural rigidity D (eq. 2), mass per area ρh and the frequency
/// scale D/(ρh r_a⁴). Each is refused with the keys it comes from.
fn check_derived(plate: &PlateConfig) -> Result<(), ConfigError> {
    let rigidity =
        super::bending_rigidity(plate.youngs_modulus, plate.thickness, plate.poisson_ratio);
    let areal_density = plate.density * plate.thickness;
    let scale = rigidity / (areal_density * plate.outer_radius.powi(4));
    let checks = [
        (
            "the flexural rigidity D = E h³ / (12 (1 − ν²))",
            rigidity,
            DERIVED_RANGE,
            "plate.youngs_modulus, plate.thickness, plate.poisson_ratio",
        ),
        (
            "the mass per area ρ h",
            areal_density,
            DERIVED_RANGE,
            "plate.density, plate.thickness",
        ),
        (
            "the frequency scale D / (ρ h r_a⁴)",
            scale,
            FREQUENCY_SCALE_RANGE,
            "plate.youngs_modulus, plate.density, plate.thickness, plate.outer_radius",
        ),
    ];
    for (quantity, value, (low, high), keys) in checks {
        if !(low..=high).contains(&value) {
            return Err(ConfigError::DerivedOutOfRange {
                quantity,
                value,
                low,
                high,
                keys,
            });
        }
    }
    Ok(())
}

/// Range of D (N·m) and ρ h (kg/m²): 40 decades around any real plate.
const DERIVED_RANGE: (f64, f64) = (1e-20, 1e20);
/// Range of D / (ρ h r_a⁴) (1/s²): frequencies from 1e-10 to 1e15 rad/s.
const FREQUENCY_SCALE_RANGE: (f64, f64) = (1e-20, 1e30);

/// ν from `plate.poisson_ratio` or from `plate.shear_modulus` (ν = E/2G − 1), exactly one of them.
fn read_poisson_ratio(r: &Reader, youngs_modulus: f64) -> Result<f64, ConfigError> {
    let given = r.f64_opt("plate.poisson_ratio")?;
    let shear = r.f64_opt("plate.shear_modulus")?;
    let (nu, from_shear_modulus) = match (given, shear) {
        (Some(poisson_ratio), Some(shear_modulus)) => {
            return Err(ConfigError::PoissonAndShearModulus {
                poisson_ratio,
                shear_modulus,
            })
        }
        (Some(nu), None) => (nu, false),
        (None, Some(g)) => {
            let g = positive("plate.shear_modulus", g)?;
            (youngs_modulus / (2.0 * g) - 1.0, true)
        }
        (None, None) => (r.f64("plate.poisson_ratio")?, false),
    };
    if !(nu > -1.0 && nu < 0.5) {
        return Err(ConfigError::PoissonRatioOutOfRange {
            nu,
            from_shear_modulus,
        });
    }
    Ok(nu)
}

/// An edge condition; `supported_soft` only under Mindlin theory.
fn read_boundary(
    r: &Reader,
    key: &'static str,
    theory: PlateTheory,
) -> Result<Boundary, ConfigError> {
    let name = r.string(key)?;
    let boundary = Boundary::from_name(name.trim()).ok_or(ConfigError::UnknownBoundary {
        key: key.to_string(),
        value: name,
    })?;
    if boundary == Boundary::SupportedSoft && theory == PlateTheory::Kirchhoff {
        return Err(ConfigError::SoftSupportNeedsMindlin { key });
    }
    Ok(boundary)
}

/// `plate.theory`: `kirchhoff` or `mindlin`.
fn read_theory(r: &Reader) -> Result<PlateTheory, ConfigError> {
    const KEY: &str = "plate.theory";
    let name = r.string(KEY)?;
    PlateTheory::from_name(name.trim()).ok_or(ConfigError::UnknownChoice {
        key: KEY.into(),
        value: name,
        allowed: PlateTheory::NAMES,
    })
}

/// `plate.shear_correction`: κ in (0, 1].
fn read_shear_correction(r: &Reader) -> Result<f64, ConfigError> {
    const KEY: &str = "plate.shear_correction";
    let kappa = r.positive(KEY)?;
    if kappa > 1.0 {
        return Err(ConfigError::AboveMaximum {
            key: KEY.into(),
            value: kappa,
            max: 1.0,
        });
    }
    Ok(kappa)
}

/// A non-empty list of distinct integers in 0..=max.
fn read_index_list(r: &Reader, key: &str, max: i64) -> Result<Vec<u32>, ConfigError> {
    let out = read_indices(r, key, max)?;
    if out.is_empty() {
        return Err(ConfigError::Empty {
            key: key.to_string(),
        });
    }
    Ok(out)
}

/// A list (possibly empty) of distinct integers in 0..=max.
fn read_indices(r: &Reader, key: &str, max: i64) -> Result<Vec<u32>, ConfigError> {
    let values = r.i64_array(key)?;
    let mut out: Vec<u32> = Vec::with_capacity(values.len());
    for &v in &values {
        if v < 0 {
            return Err(ConfigError::Negative {
                key: key.to_string(),
                value: v as f64,
            });
        }
        if v > max {
            return Err(ConfigError::AboveMaximum {
                key: key.to_string(),
                value: v as f64,
                max: max as f64,
            });
        }
        if out.contains(&(v as u32)) {
            return Err(ConfigError::Duplicate {
                key: key.to_string(),
                value: v,
            });
        }
        out.push(v as u32);
    }
    Ok(out)
}

/// The requested ⟨k, l⟩ that are rigid-body motions of a free–free plate.
fn rigid_body_modes_selected(plate: &PlateConfig) -> Vec<(u32, u32)> {
    if !(plate.inner_boundary == Boundary::Free && plate.outer_boundary == Boundary::Free) {
        return Vec::new();
    }
    [(0, 0), (1, 0)]
        .into_iter()
        .filter(|(k, l)| plate.nodal_diameters.contains(k) && plate.nodal_circles.contains(l))
        .collect()
}
