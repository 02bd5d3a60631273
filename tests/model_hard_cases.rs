//! Hard cases of the plate model (plate-model issue; paper sections 3.1 and 4.2),
//! measured against the exact Bessel-function solution (`tests/support/exact_plate.rs`)
//! and, for that solution's own range, against mpmath:
//!
//! * k up to 60 nodal diameters with up to 10 nodal circles (lathe disc and a free–free
//!   annulus): finite, complete, ordered, l nodal circles, and the accuracy measured
//!   per l at the default 32 radial splines and at the counts that reach 1e-4;
//! * r_i/r_a = 1e-4 with every inner edge: a free tiny hole is the solid circular plate;
//!   a supported or clamped one is a point support (k = 0 to the centrally pinned plate,
//!   k = 1 only logarithmically in r_i), compared with the exact annulus at that ratio;
//! * r_i/r_a = 0.98 and 0.99 for all edge pairs; the 1e-3 width limit of the validation;
//! * thickness 1e-4 … 0.1 m, E 1e3 … 1e15 Pa, ρ 1 … 1e5 kg/m³: ω ∝ h sqrt(E/ρ) to 1e-10;
//!   ν = −0.99 and 0.49 against the exact solution.
//!
//! The measured tables and the library problems found are in `docs/hard_cases.md`.
//! Run with `-- --nocapture` to see them.

mod support;

use annular_plate::config::{Boundary, Config, PlateConfig};
use annular_plate::model::{AngularShape, PlateModel};
use support::bessel;
use support::exact_plate::{Annulus, CircularPlate, Edge, Material};
use support::library_plate::edge;

const RA: f64 = 0.15;

fn plate(
    ri: f64,
    inner: Boundary,
    outer: Boundary,
    ks: Vec<u32>,
    ls: Vec<u32>,
    splines: usize,
) -> PlateConfig {
    let mut c = PlateConfig::lathe_disc();
    c.inner_radius = ri;
    c.outer_radius = RA;
    c.inner_boundary = inner;
    c.outer_boundary = outer;
    c.nodal_diameters = ks;
    c.nodal_circles = ls;
    c.radial_splines = annular_plate::config::RadialSplines::Fixed(splines);
    c
}

fn material(c: &PlateConfig) -> Material {
    Material {
        thickness: c.thickness,
        density: c.density,
        youngs_modulus: c.youngs_modulus,
        poisson_ratio: c.poisson_ratio,
    }
}

fn annulus(c: &PlateConfig) -> Annulus {
    Annulus::new(
        c.inner_radius,
        c.outer_radius,
        c.poisson_ratio,
        edge(c.inner_boundary),
        edge(c.outer_boundary),
    )
}

/// The first `count` λ for k (index = l; a free–free plate's rigid-body mode is λ = 0
/// at l = 0 for k ≤ 1), by the exact solver's scan and bisection, in chunks.
fn lambdas(a: &Annulus, k: u32, count: usize) -> Vec<f64> {
    let step = a.default_step();
    let mut lo = Annulus::LAMBDA_MIN_TIMES_RA / a.outer_radius;
    let mut v = Vec::new();
    if a.has_rigid_body_mode(k) {
        v.push(0.0);
    }
    while v.len() < count {
        let hi = lo + 200.0 * step;
        v.extend(a.determinant_roots(k, lo, hi, step));
        lo = hi;
    }
    v.truncate(count);
    v
}

/// Exact λ for every requested (k, l): `exact[k][l]` (k indexes 0..=max k; unrequested k empty).
fn exact_table(c: &PlateConfig) -> Vec<Vec<f64>> {
    let a = annulus(c);
    let kmax = *c.nodal_diameters.iter().max().unwrap() as usize;
    let nl = *c.nodal_circles.iter().max().unwrap() as usize + 1;
    (0..=kmax as u32)
        .map(|k| {
            if c.nodal_diameters.contains(&k) {
                lambdas(&a, k, nl)
            } else {
                vec![]
            }
        })
        .collect()
}

/// Signed relative frequency error of every library mode (cos and sin alike) against `exact`.
fn errors(model: &PlateModel, c: &PlateConfig, exact: &[Vec<f64>]) -> Vec<(u32, u32, f64)> {
    let mat = material(c);
    model
        .modes()
        .iter()
        .map(|m| {
            (
                m.k,
                m.l,
                m.frequency_hz / mat.frequency_hz(exact[m.k as usize][m.l as usize]) - 1.0,
            )
        })
        .collect()
}

fn worst(errs: &[(u32, u32, f64)]) -> (u32, u32, f64) {
    errs.iter()
        .copied()
        .max_by(|a, b| a.2.abs().total_cmp(&b.2.abs()))
        .unwrap_or((0, 0, 0.0))
}

/// What must hold for every model, whatever its accuracy: finite positive frequencies
/// and masses, `mode_count()` modes sorted by frequency, every requested ⟨k, l⟩ exactly
/// once (a cos/sin pair of partners for k ≥ 1), rigid-body modes skipped, and R_l with
/// l nodal circles (sign changes inside (r_i, r_a); `samples` points).
fn check_structure(c: &PlateConfig, m: &PlateModel, samples: usize) {
    let name = format!(
        "{}–{} r_i/r_a = {:e}",
        c.inner_boundary.name(),
        c.outer_boundary.name(),
        c.inner_radius / c.outer_radius
    );
    assert_eq!(m.n_modes(), c.mode_count(), "{name}: mode count");
    for (i, md) in m.modes().iter().enumerate() {
        assert!(
            md.omega.is_finite() && md.omega > 0.0 && md.frequency_hz.is_finite(),
            "{name}: mode {i} {md:?}"
        );
        assert!(
            md.modal_mass.is_finite() && md.modal_mass > 0.0,
            "{name}: mode {i} mass {}",
            md.modal_mass
        );
    }
    assert!(
        m.modes().windows(2).all(|w| w[0].omega <= w[1].omega),
        "{name}: modes not sorted by frequency"
    );
    let free_free = c.inner_boundary == Boundary::Free && c.outer_boundary == Boundary::Free;
    for &k in &c.nodal_diameters {
        for &l in &c.nodal_circles {
            let found: Vec<(usize, &annular_plate::model::Mode)> = m
                .modes()
                .iter()
                .enumerate()
                .filter(|(_, x)| x.k == k && x.l == l)
                .collect();
            if free_free && l == 0 && k <= 1 {
                assert!(
                    found.is_empty() && m.skipped_rigid_body_modes().contains(&(k, l)),
                    "{name}: rigid ⟨{k},{l}⟩"
                );
                continue;
            }
            if k == 0 {
                assert!(
                    found.len() == 1 && found[0].1.shape == AngularShape::Axisymmetric,
                    "{name}: ⟨0,{l}⟩ {} modes",
                    found.len()
                );
            } else {
                assert_eq!(found.len(), 2, "{name}: ⟨{k},{l}⟩");
                let (ia, a) = found[0];
                let (ib, b) = found[1];
                assert!(
                    a.shape != b.shape
                        && a.shape != AngularShape::Axisymmetric
                        && b.shape != AngularShape::Axisymmetric,
                    "{name}: ⟨{k},{l}⟩ shapes"
                );
                assert!(
                    a.partner == Some(ib)
                        && b.partner == Some(ia)
                        && a.omega == b.omega
                        && a.radial == b.radial,
                    "{name}: ⟨{k},{l}⟩ pair"
                );
            }
            let shape = &m.radial_shapes()[found[0].1.radial];
            assert_eq!((shape.k, shape.l), (k, l));
            let circles =
                nodal_circles(|r| shape.value(r), c.inner_radius, c.outer_radius, samples);
            assert_eq!(
                circles, l as usize,
                "{name}: ⟨{k},{l}⟩ has {circles} nodal circles"
            );
        }
    }
}

/// Nodal circles of R on (a, b): sign changes between the lobes (runs of one sign,
/// `samples` points) whose peak is at least 1e-4 of max |R|. Smaller lobes are not
/// resolved features of the mode: where the true R ~ r^k is below the approximation
/// error (next to a tiny hole, or the inner part of a k = 60 mode) the Ritz shape
/// ripples with lobes of ≤ 2.5e-6 of its peak (measured), which `count_sign_changes`
/// (threshold 1e-8) would count as nodal circles.
fn nodal_circles(f: impl Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> usize {
    let mut lobes: Vec<f64> = Vec::new(); // signed peak of each run
    for i in 1..samples {
        let v = f(a + (b - a) * i as f64 / samples as f64);
        match lobes.last_mut() {
            Some(last) if last.signum() == v.signum() || v == 0.0 => {
                if v.abs() > last.abs() {
                    *last = v;
                }
            }
            _ => lobes.push(v),
        }
    }
    let peak = lobes.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let kept: Vec<f64> = lobes
        .into_iter()
        .filter(|v| v.abs() >= 1e-4 * peak)
        .collect();
    kept.windows(2)
        .filter(|w| w[0].signum() != w[1].signum())
        .count()
}

/// Peak of the lobes `nodal_circles` leaves out, relative to max |R|.
fn ripple(f: impl Fn(f64) -> f64, a: f64, b: f64, samples: usize) -> f64 {
    let vals: Vec<f64> = (1..samples)
        .map(|i| f(a + (b - a) * i as f64 / samples as f64))
        .collect();
    let peak = vals.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let mut lobes: Vec<f64> = Vec::new();
    for v in vals {
        match lobes.last_mut() {
            Some(last) if last.signum() == v.signum() || v == 0.0 => {
                if v.abs() > last.abs() {
                    *last = v;
                }
            }
            _ => lobes.push(v),
        }
    }
    lobes
        .iter()
        .map(|v| v.abs())
        .filter(|v| *v < 1e-4 * peak)
        .fold(0.0, f64::max)
        / peak
}

/// The library's order of ⟨k, l⟩ against the exact one: any two modes whose exact
/// frequencies differ by more than `gap` (relative) must come in the exact order.
fn check_order(m: &PlateModel, exact: &[Vec<f64>], gap: f64) {
    check_order_of(m, exact, gap, |_| true)
}

/// `check_order` over the modes whose k passes `include`.
fn check_order_of(m: &PlateModel, exact: &[Vec<f64>], gap: f64, include: impl Fn(u32) -> bool) {
    let lam: Vec<f64> = m
        .modes()
        .iter()
        .map(|x| {
            if include(x.k) {
                exact[x.k as usize][x.l as usize]
            } else {
                f64::NAN
            }
        })
        .collect();
    for i in 0..lam.len() {
        for j in i + 1..lam.len() {
            if lam[i].is_nan() || lam[j].is_nan() {
                continue;
            }
            let (fi, fj) = (lam[i] * lam[i], lam[j] * lam[j]);
            assert!(
                fi <= fj * (1.0 + gap),
                "order: ⟨{},{}⟩ before ⟨{},{}⟩ but exact {fi} > {fj}",
                m.modes()[i].k,
                m.modes()[i].l,
                m.modes()[j].k,
                m.modes()[j].l
            );
        }
    }
}

// ---- the reference itself, over the range these cases need ----------------------

/// (n, x, J_n, Y_n, e^{-x} I_n, e^{x} K_n) from mpmath 1.3 at 40 digits: orders to 62
/// (k = 60 plus the two orders the derivatives use), arguments from 1e-3 (tiny inner
/// radius) to 1e5 (narrow rings reach λ r_a ~ 1e4), on both sides of the I power
/// series' limit x = 700.
#[allow(clippy::excessive_precision)] // mpmath's digits as printed, not rounded by hand
const MPMATH: &[(usize, f64, f64, f64, f64, f64)] = &[
    (
        0,
        0.001,
        9.9999975000001562e-1,
        -4.4714166113759233,
        9.9900074958351556e-1,
        7.0307160023782515,
    ),
    (
        0,
        0.005,
        9.9999375000976562e-1,
        -3.4467923694892915,
        9.9501869803039419e-1,
        5.4414282077370991,
    ),
    (
        0,
        699.0,
        2.1436359010795065e-2,
        2.1242414640112689e-2,
        1.5092083422186381e-2,
        4.7396223917524728e-2,
    ),
    (
        0,
        701.0,
        -2.8196042543151933e-2,
        1.063684167984554e-2,
        1.5070530981047303e-2,
        4.7328587433553188e-2,
    ),
    (
        0,
        1000.0,
        2.4786686152420175e-2,
        4.7159179776228134e-3,
        1.2617240455891257e-2,
        3.9628321600754217e-2,
    ),
    (
        0,
        3000.0,
        -7.7918452618898996e-3,
        1.2308279134657472e-2,
        7.2839597465456906e-3,
        2.2881327571932437e-2,
    ),
    (
        0,
        10000.0,
        -7.0961603533888015e-3,
        3.6478055589866059e-3,
        3.9894726746047321e-3,
        1.2532984717699285e-2,
    ),
    (
        0,
        30000.0,
        -4.5573449277751978e-3,
        -6.7176356350559928e-4,
        2.3033039270485619e-3,
        7.2359823960956972e-3,
    ),
    (
        0,
        100000.0,
        -1.7192011162359722e-3,
        1.8467661588650641e-3,
        1.2615678379767768e-3,
        3.9633223434747559e-3,
    ),
    (
        1,
        0.001,
        4.9999993750000261e-4,
        -6.3662216723113941e+2,
        4.9950031235422135e-4,
        1.0009967345590684e+3,
    ),
    (
        1,
        0.005,
        2.4999921875081381e-3,
        -1.2733336725981384e+2,
        2.487538971524797e-3,
        2.0098764438410949e+2,
    ),
    (
        1,
        699.0,
        2.1257753656885556e-2,
        -2.1421169642411206e-2,
        1.5081284073901373e-2,
        4.7430114687678729e-2,
    ),
    (
        1,
        701.0,
        1.0616733095852832e-2,
        2.820363661725065e-2,
        1.5059777833173032e-2,
        4.7362333319790197e-2,
    ),
    (
        1,
        1000.0,
        4.7283119070895239e-3,
        -2.4784331292351779e-2,
        1.2610930256928629e-2,
        3.964813081296021e-2,
    ),
    (
        1,
        3000.0,
        1.2306980664764856e-2,
        7.7938967499087473e-3,
        7.2827456520547525e-3,
        2.288514080883742e-2,
    ),
    (
        1,
        10000.0,
        3.6474507555295803e-3,
        7.0963427525364951e-3,
        3.9892731959836623e-3,
        1.2533611351270506e-2,
    ),
    (
        1,
        30000.0,
        -6.7183951934767493e-4,
        4.5573337323487737e-3,
        2.3032655383298637e-3,
        7.2361029947973347e-3,
    ),
    (
        1,
        100000.0,
        1.8467575628825677e-3,
        1.7192103500882563e-3,
        1.2615615301218171e-3,
        3.9633421600369322e-3,
    ),
    (
        2,
        0.001,
        1.2499998958333366e-7,
        -1.2732398630456674e+6,
        1.2487507288542741e-7,
        2.0020004998341392e+6,
    ),
    (
        2,
        0.005,
        3.1249934895884197e-6,
        -5.0929900111556044e+4,
        3.1094204754280213e-6,
        8.0400499181851532e+4,
    ),
    (
        2,
        699.0,
        -2.1375535681304692e-2,
        -2.1303705540377098e-2,
        1.5048932394793244e-2,
        4.7531932400179031e-2,
    ),
    (
        2,
        701.0,
        2.8226332794495308e-2,
        -1.0556374813605167e-2,
        1.5027564425175197e-2,
        4.7463715346020492e-2,
    ),
    (
        2,
        1000.0,
        -2.4777229528605996e-2,
        -4.765486640207517e-3,
        1.2592018595377399e-2,
        3.9707617862380138e-2,
    ),
    (
        2,
        3000.0,
        7.8000499156664095e-3,
        -1.2303083203490866e-2,
        7.2791045827776541e-3,
        2.2896584332471662e-2,
    ),
    (
        2,
        10000.0,
        7.0968898435399074e-3,
        -3.6463862904360986e-3,
        3.9886748199655354e-3,
        1.2535491439969539e-2,
    ),
    (
        2,
        30000.0,
        4.557300138473908e-3,
        6.7206738575442254e-4,
        2.3031503760126732e-3,
        7.236464802962017e-3,
    ),
    (
        2,
        100000.0,
        1.7192380513872298e-3,
        -1.8467317746580623e-3,
        1.2615426067461743e-3,
        3.9634016103179566e-3,
    ),
    (
        10,
        0.001,
        2.6911443943049993e-40,
        -1.1828049377990414e+38,
        2.6884547172369639e-40,
        1.8598044232213e+38,
    ),
    (
        10,
        0.005,
        2.6280692640707238e-33,
        -1.2111930637680282e+31,
        2.6149646854821896e-33,
        1.9120714694336345e+31,
    ),
    (
        10,
        699.0,
        -1.9864341191379981e-2,
        -2.2721329867378276e-2,
        1.404953853329519e-2,
        5.0908047617117073e-2,
    ),
    (
        10,
        701.0,
        2.8883876056441054e-2,
        -8.6007754798333097e-3,
        1.4032342321445485e-2,
        5.0825041382919509e-2,
    ),
    (
        10,
        1000.0,
        -2.4520622306036558e-2,
        -5.9490005741626686e-3,
        1.2001595024124219e-2,
        4.1659051428005658e-2,
    ),
    (
        10,
        3000.0,
        7.9959139614490732e-3,
        -1.2176745324513755e-2,
        7.1635466862146022e-3,
        2.3265813760076077e-2,
    ),
    (
        10,
        10000.0,
        7.1143123833542745e-3,
        -3.612280207880416e-3,
        3.9695741057832239e-3,
        1.2595803411170465e-2,
    ),
    (
        10,
        30000.0,
        4.5562191192619348e-3,
        6.7935822080082609e-4,
        2.2994682205859435e-3,
        7.2480522208776956e-3,
    ),
    (
        10,
        100000.0,
        1.7201242886778252e-3,
        -1.8459063321110935e-3,
        1.260937208575637e-3,
        3.9653044902295597e-3,
    ),
    (
        30,
        699.0,
        -4.3945008864298008e-3,
        -2.9871156520685393e-2,
        7.9250726112746026e-3,
        9.0175814212850328e-2,
    ),
    (
        30,
        701.0,
        2.8964486244145971e-2,
        8.3696200456023752e-3,
        7.9283180988881192e-3,
        8.9882198762127602e-2,
    ),
    (
        30,
        1000.0,
        -2.0271896981075845e-2,
        -1.5031851431420546e-2,
        8.0435680099375336e-3,
        6.2133522489405566e-2,
    ),
    (
        30,
        3000.0,
        9.5439297518270526e-3,
        -1.1005934937897841e-2,
        6.2692133092063969e-3,
        2.6583612337232426e-2,
    ),
    (
        30,
        10000.0,
        7.2530889890212512e-3,
        -3.3249005632267094e-3,
        3.8139173772688167e-3,
        1.3109821246264083e-2,
    ),
    (
        30,
        30000.0,
        4.5467572962654418e-3,
        7.4004579261455785e-4,
        2.2690116346332432e-3,
        7.345338420156816e-3,
    ),
    (
        30,
        100000.0,
        1.727494167951443e-3,
        -1.8390111227964077e-3,
        1.2559035087259676e-3,
        3.9811973932095228e-3,
    ),
    (
        40,
        0.001,
        1.1146925604908664e-180,
        -7.1389613953993215e+177,
        1.1135784386711449e-180,
        1.1225073656246258e+178,
    ),
    (
        40,
        0.005,
        1.0138068295101561e-152,
        -7.8493722720811763e+149,
        1.0087507543992882e-152,
        1.239156436589377e+150,
    ),
    (
        40,
        0.5,
        1.0122626959003594e-72,
        -7.8619604848825331e+69,
        6.1584307184609693e-73,
        2.0295792082361479e+70,
    ),
    (
        40,
        5.0,
        8.7022416173888181e-33,
        -9.2168165716493142e+29,
        7.953654429953234e-35,
        1.5594612455249592e+32,
    ),
    (
        40,
        30.0,
        3.6120236088965853e-4,
        -3.3393668907330314e+1,
        2.2510414876317662e-12,
        4.4422122833365872e+9,
    ),
    (
        40,
        45.0,
        1.26600621268202e-1,
        1.1933217757749344e-1,
        2.5613237339087824e-9,
        3.2422121444563077e+6,
    ),
    (
        40,
        55.0,
        1.1887807685038795e-1,
        5.2079276692331053e-2,
        4.0772132801999278e-8,
        1.8032049941466858e+5,
    ),
    (
        40,
        60.0,
        -7.7646197404715065e-2,
        -9.0545084909696293e-2,
        1.1807080815876919e-7,
        5.8724848200411238e+4,
    ),
    (
        40,
        65.0,
        1.0720635256135248e-3,
        1.1144760561733738e-1,
        2.9310510283833083e-7,
        2.235095757073961e+4,
    ),
    (
        40,
        90.0,
        -5.744904177955725e-2,
        -6.7789987629946427e-2,
        6.3723837920295857e-6,
        7.9667837921208533e+2,
    ),
    (
        40,
        120.0,
        7.2088646997365717e-2,
        2.0738937536620077e-2,
        4.7962127466403987e-5,
        8.2416297593639422e+1,
    ),
    (
        40,
        300.0,
        4.4315329332453656e-2,
        1.3316614800550279e-2,
        1.6002898291930657e-3,
        1.0323433247057447,
    ),
    (
        60,
        0.001,
        1.0423784133801967e-280,
        -5.0894806553633742e+277,
        1.0413365645178825e-280,
        8.0025359870406234e+277,
    ),
    (
        60,
        0.005,
        9.0411906334129359e-239,
        -5.8677722915715592e+235,
        8.9960993504686558e-239,
        9.2632739810237642e+235,
    ),
    (
        60,
        0.5,
        9.0319327113893073e-119,
        -5.8739908800922681e+115,
        5.4893813206636417e-119,
        1.5180297067004803e+116,
    ),
    (
        60,
        5.0,
        8.1600240380935178e-59,
        -6.5241072937823727e+55,
        6.7486042164703579e-61,
        1.2305567026022445e+58,
    ),
    (
        60,
        30.0,
        9.8075576431286246e-14,
        -6.2466251044728679e+10,
        1.4930811028383652e-23,
        4.9919831555026304e+20,
    ),
    (
        60,
        45.0,
        2.0328758193272825e-5,
        -3.949786391998116e+2,
        1.1611451739583858e-17,
        5.7413573273802875e+14,
    ),
    (
        60,
        55.0,
        1.9046683078586297e-2,
        -7.2035748963950022e-1,
        3.1942588513655119e-15,
        1.9230940873864912e+12,
    ),
    (
        60,
        60.0,
        1.1425208221300292e-1,
        -1.9791252085183111e-1,
        2.9078999809113393e-14,
        2.0263694856018204e+11,
    ),
    (
        60,
        65.0,
        1.3952542367524131e-1,
        7.2984156946671409e-2,
        1.9688436207351423e-13,
        2.8708581713469441e+10,
    ),
    (
        60,
        90.0,
        -9.6702366626675046e-2,
        -1.1681633305787132e-2,
        1.5272497325194549e-10,
        3.0266714882322348e+7,
    ),
    (
        60,
        120.0,
        -6.725905609891957e-2,
        4.0023045003923406e-2,
        1.4108617830286293e-8,
        2.6414918919094789e+5,
    ),
    (
        60,
        300.0,
        -4.084340882273173e-2,
        -2.230776680334423e-2,
        5.7686472934079617e-5,
        2.8330780823887567e+1,
    ),
    (
        60,
        699.0,
        -2.953235530204165e-2,
        -6.4785431055733221e-3,
        1.1488972691926317e-3,
        6.203226897538143e-1,
    ),
    (
        60,
        701.0,
        1.7976538976214073e-2,
        -2.4255890507336532e-2,
        1.155712982586885e-3,
        6.149178204780838e-1,
    ),
    (
        60,
        1000.0,
        -1.0245851850792056e-2,
        2.3082270887938173e-2,
        2.0848652623389349e-3,
        2.3939316011392821e-1,
    ),
    (
        60,
        3000.0,
        -1.3382117966821875e-2,
        5.7591631866001483e-3,
        3.9972020027738675e-3,
        4.1687496784561918e-2,
    ),
    (
        60,
        10000.0,
        -7.634647642329329e-3,
        2.3184646818887072e-3,
        3.3322594905730831e-3,
        1.500456378869328e-2,
    ),
    (
        60,
        30000.0,
        -4.5088670229326706e-3,
        -9.4383244642666009e-4,
        2.1691678227001007e-3,
        7.6834227215310908e-3,
    ),
    (
        60,
        100000.0,
        -1.7521627676800736e-3,
        1.8155232042218132e-3,
        1.239062659289562e-3,
        4.0353077082716535e-3,
    ),
    (
        61,
        0.001,
        8.5440853561401691e-286,
        -6.107376786004737e+282,
        8.5355456102380937e-286,
        9.6030431851269289e+282,
    ),
    (
        61,
        0.005,
        3.7054060034238071e-243,
        -1.40826534749083e+240,
        3.6869259572139423e-243,
        2.2231857593708195e+240,
    ),
    (
        61,
        0.5,
        3.7016729404849902e-121,
        -1.4097329209756712e+118,
        2.2497092655868133e-121,
        3.6433356181990415e+118,
    ),
    (
        61,
        5.0,
        3.3498168219035091e-60,
        -1.5630162303654322e+57,
        2.7612655086906525e-62,
        2.958540821445409e+59,
    ),
    (
        61,
        30.0,
        2.5748704831507557e-14,
        -2.3277032845170653e+11,
        3.4754706036792973e-24,
        2.1163206876145751e+21,
    ),
    (
        61,
        45.0,
        8.9033726230358852e-6,
        -8.6890443024669169e+2,
        3.8243797646031837e-18,
        1.7247205253010862e+15,
    ),
    (
        61,
        55.0,
        1.1745203700436828e-2,
        -1.0519233360697148,
        1.2293258732226083e-15,
        4.9519183007947666e+12,
    ),
    (
        61,
        60.0,
        8.7825819596683578e-2,
        -2.4500349008546756e-1,
        1.1924294301297813e-14,
        4.9005688466809058e+11,
    ),
    (
        61,
        65.0,
        1.6405755547861677e-1,
        1.5620465258681914e-2,
        8.5387432420818185e-14,
        6.5689642221711101e+10,
    ),
    (
        61,
        90.0,
        -7.4143335127973121e-2,
        6.4191167081127974e-2,
        8.1149268634856529e-11,
        5.667042625800999e+7,
    ),
    (
        61,
        120.0,
        6.5926689208075967e-4,
        7.8484284606594358e-2,
        8.6725771585150065e-9,
        4.2828285388413878e+5,
    ),
    (
        61,
        300.0,
        -3.0096688335693521e-2,
        3.5517995308436912e-2,
        4.7199088220807238e-5,
        3.4603369010675647e+1,
    ),
    (
        61,
        699.0,
        -9.0108814739723302e-3,
        2.8862598584391838e-2,
        1.053688148829911e-3,
        6.7629066471963307e-1,
    ),
    (
        61,
        701.0,
        -2.2615319597694767e-2,
        -2.0004113781583319e-2,
        1.0602002138069489e-3,
        6.7023346666870413e-1,
    ),
    (
        61,
        1000.0,
        2.2420795748143635e-2,
        1.1623913084063455e-2,
        1.9624837845135284e-3,
        2.5430650830555773e-1,
    ),
    (
        61,
        3000.0,
        5.4881377141862364e-3,
        1.349558497021314e-2,
        3.9173913338397878e-3,
        4.2536527946805231e-2,
    ),
    (
        61,
        10000.0,
        2.272233320069596e-3,
        7.648536942478998e-3,
        3.312159302619215e-3,
        1.5095611433575691e-2,
    ),
    (
        61,
        30000.0,
        -9.5292344102112316e-4,
        4.5069546103193097e-3,
        2.1647976724322977e-3,
        7.6989329892702832e-3,
    ),
    (
        61,
        100000.0,
        1.814462818972701e-3,
        1.7532608438544711e-3,
        1.2383132493986923e-3,
        4.0377497957327756e-3,
    ),
    (
        62,
        0.5,
        1.4926339406890114e-123,
        -3.4396895872718367e+120,
        9.0712631817285027e-124,
        8.8898907113763313e+120,
    ),
    (
        62,
        5.0,
        1.3529007351044442e-61,
        -3.8072354947978723e+58,
        1.1116375265165844e-63,
        7.2311451713528203e+60,
    ),
    (
        62,
        30.0,
        6.6358232168444867e-15,
        -8.8413308465887788e+11,
        7.9723057342117651e-25,
        9.1055691118495352e+21,
    ),
    (
        62,
        45.0,
        3.8092742514022411e-6,
        -1.9607178161356637e+3,
        1.2431332666596712e-18,
        5.2500447124431959e+15,
    ),
    (
        62,
        55.0,
        7.006314220564485e-3,
        -1.6129997285515036,
        4.6739055076263524e-16,
        1.2907349227331246e+13,
    ),
    (
        62,
        60.0,
        6.4327084300253692e-2,
        -3.0026124232195293e-1,
        4.8329347298078406e-15,
        1.1990859473852995e+12,
    ),
    (
        62,
        65.0,
        1.6839798814616247e-1,
        -4.3665745230376124e-2,
        3.6618719683670864e-14,
        1.5200298711421951e+11,
    ),
    (
        62,
        90.0,
        -3.8030432134662954e-3,
        9.8696326460205051e-2,
        4.2722631324695525e-11,
        1.0708662603206922e+8,
    ),
    (
        62,
        120.0,
        6.7929310772535009e-2,
        3.9769311012780858e-2,
        5.2914977191293701e-9,
        6.9957009063982231e+5,
    ),
    (
        62,
        300.0,
        2.8604088899549699e-2,
        3.6751751562108574e-2,
        3.8492177057618007e-5,
        4.2402817554895663e+1,
    ),
];

#[test]
fn bessel_functions_agree_with_mpmath_to_order_62_and_argument_1e5() {
    let mut worst = [0.0_f64; 4];
    for &(n, x, j, y, i, k) in MPMATH {
        // J and Y relative to the modulus sqrt(J² + Y²) where they oscillate (n ≤ x), else to themselves.
        let modulus = if n as f64 <= x {
            (j * j + y * y).sqrt()
        } else {
            0.0
        };
        let e = [
            (bessel::j_n(n, x) - j).abs() / j.abs().max(modulus),
            (bessel::y_n(n, x) - y).abs() / y.abs().max(modulus),
            ((bessel::i_scaled(n, x) - i) / i).abs(),
            ((bessel::k_scaled(n, x) - k) / k).abs(),
        ];
        for w in 0..4 {
            worst[w] = worst[w].max(e[w]);
        }
    }
    println!("worst relative errors vs mpmath (n ≤ 62, 1e-3 ≤ x ≤ 1e5): J {:.1e}, Y {:.1e}, e^-x I {:.1e}, e^x K {:.1e}", worst[0], worst[1], worst[2], worst[3]);
    // Measured: J 6.1e-14, Y 8.9e-14 (both at x ≥ 3e4, where x itself carries ~1e-16 · x
    // of phase), e^-x I 1.6e-15, e^x K 1.1e-15.
    assert!(worst[0] < 1.5e-13 && worst[1] < 1.5e-13, "{worst:?}");
    assert!(worst[2] < 4e-15 && worst[3] < 4e-15, "{worst:?}");
}

#[test]
fn bessel_wronskians_hold_to_order_61_and_argument_1e5() {
    let xs = [
        1e-3, 6e-3, 0.05, 0.5, 3.0, 20.0, 45.0, 59.0, 61.0, 90.0, 250.0, 699.0, 701.0, 2e3, 1e4,
        4e4, 1e5,
    ];
    let (mut worst_jy, mut worst_ik) = (0.0_f64, 0.0_f64);
    for n in [0usize, 1, 2, 3, 10, 20, 35, 45, 55, 59, 60, 61] {
        for &x in &xs {
            let (j, y) = bessel::jy_val_der(n, x);
            let (i, k) = (
                bessel::i_scaled_val_der(n, x),
                bessel::k_scaled_val_der(n, x),
            );
            if !(y.deriv.is_finite() && k.deriv.is_finite() && y.deriv != 0.0) {
                continue; // Y_n, K_n beyond f64 (n ≥ 45 at x = 1e-3): not used there
            }
            let w = j.value * y.deriv - j.deriv * y.value;
            let scale = (j.value.abs() + j.deriv.abs()) * (y.value.abs() + y.deriv.abs());
            worst_jy = worst_jy.max(
                (w - 2.0 / (std::f64::consts::PI * x)).abs()
                    / scale.max(2.0 / (std::f64::consts::PI * x)),
            );
            worst_ik = worst_ik.max((i.value * k.deriv - i.deriv * k.value + 1.0 / x).abs() * x);
        }
    }
    println!(
        "worst Wronskian errors (n ≤ 61, 1e-3 ≤ x ≤ 1e5): J/Y {worst_jy:.1e}, I/K {worst_ik:.1e}"
    );
    assert!(
        worst_jy < 1e-13 && worst_ik < 1e-13,
        "J/Y {worst_jy:e}, I/K {worst_ik:e}"
    );
}

/// λ of the exact solver against roots of the same 4×4 frequency determinant in mpmath
/// (50–80 digits, Bessel derivatives from the order recurrences, not from Bessel's
/// equation as in the solver), bracketed by a sign change.
#[test]
fn exact_roots_agree_with_mpmath_in_the_hard_range() {
    use Boundary::*;
    // (r_i, ν, inner, outer, k, l, λ from mpmath, measured |relative difference|); the
    // clamped–clamped 0.99 ring has λ r_a = 1100, beyond the I power series (x > 700).
    type Case = (f64, f64, Boundary, Boundary, u32, usize, f64, f64);
    #[allow(clippy::excessive_precision)] // mpmath's λ as printed, not rounded by hand
    let cases: &[Case] = &[
        (
            0.075,
            0.3,
            Clamped,
            Free,
            60,
            0,
            415.850_889_993_812_491_05,
            9.4e-17,
        ),
        (
            0.075,
            0.3,
            Clamped,
            Free,
            60,
            1,
            467.179_492_591_851_415_22,
            6.5e-17,
        ),
        (
            0.075,
            0.3,
            Clamped,
            Free,
            60,
            10,
            726.446_544_098_067_533_56,
            6.0e-19,
        ),
        (
            0.075,
            0.3,
            Free,
            Free,
            60,
            10,
            726.040_557_703_175_591_38,
            6.3e-17,
        ),
        (
            1.5e-5,
            0.3,
            Clamped,
            Free,
            1,
            0,
            7.880_276_076_905_371_498_5,
            1.0e-10,
        ),
        (
            1.5e-5,
            0.3,
            Supported,
            Clamped,
            0,
            1,
            52.472_791_442_867_911_062,
            8.6e-17,
        ),
        (
            1.5e-5,
            0.3,
            Free,
            Free,
            2,
            0,
            15.432_044_197_109_142_115,
            3.8e-17,
        ),
        (
            0.1485,
            0.3,
            Free,
            Free,
            2,
            0,
            10.915_748_689_734_596_692,
            4.7e-15,
        ),
        (
            0.1485,
            0.3,
            Clamped,
            Clamped,
            0,
            2,
            7_330.404_599_097_051_992_8,
            2.1e-16,
        ),
        (
            0.075,
            -0.99,
            Free,
            Free,
            0,
            1,
            7.610_754_690_692_633_848,
            5.6e-15,
        ),
        (
            0.075,
            0.49,
            Free,
            Free,
            2,
            0,
            13.052_957_406_643_957_980,
            3.2e-16,
        ),
    ];
    for &(ri, nu, inner, outer, k, l, want, measured) in cases {
        let a = Annulus::new(ri, RA, nu, edge(inner), edge(outer));
        let got = lambdas(&a, k, l + 1)[l];
        let rel = (got / want - 1.0).abs();
        println!("r_i = {ri}, ν = {nu}, {}–{}, ⟨{k},{l}⟩: λ = {got:.15e}, mpmath {want:.15e}, rel {rel:.1e}", inner.name(), outer.name());
        // The tiny clamped hole loses digits in Y_1 + (2/π) K_1 ~ 1/z cancelling at z ~ 1e-4.
        assert!(
            rel <= 2.0 * measured.max(1e-15),
            "{rel:e} (measured {measured:e})"
        );
    }
}

// ---- 1. up to 60 nodal diameters --------------------------------------------------

/// Largest relative frequency error per l (over k = 0..=60) at the default 32 radial
/// splines, as measured (clamped–free lathe disc, free–free annulus r_i/r_a = 0.5).
/// The error is set by l (radial wavelength against the knot spacing); for l = 0 it
/// grows with k from 4.5e-8 (k = 0) to 7.2e-5 (k = 60) as the mode gathers at the
/// outer edge (R ~ r^k): see docs/hard_cases.md.
const K60_CLAMPED_FREE_PER_L: [f64; 11] = [
    7.21e-5, 5.84e-5, 7.49e-5, 1.01e-4, 1.39e-4, 1.95e-4, 2.75e-4, 3.85e-4, 6.09e-4, 9.93e-4,
    1.56e-3,
];
const K60_FREE_FREE_PER_L: [f64; 11] = [
    7.21e-5, 5.84e-5, 7.49e-5, 1.01e-4, 1.39e-4, 1.95e-4, 2.75e-4, 3.85e-4, 5.34e-4, 7.30e-4,
    1.00e-3,
];

#[test]
fn sixty_nodal_diameters_and_ten_nodal_circles_are_complete_ordered_and_accurate() {
    let t0 = std::time::Instant::now();
    for (inner, outer, per_l, n_all, n_k60) in [
        (
            Boundary::Clamped,
            Boundary::Free,
            K60_CLAMPED_FREE_PER_L,
            58,
            52,
        ),
        (Boundary::Free, Boundary::Free, K60_FREE_FREE_PER_L, 53, 51),
    ] {
        let c = plate(
            0.075,
            inner,
            outer,
            (0..=60).collect(),
            (0..=10).collect(),
            32,
        );
        let exact = exact_table(&c);
        let m = PlateModel::new(&c).expect("k ≤ 60, l ≤ 10 builds");
        check_structure(&c, &m, 4000);
        let errs = errors(&m, &c, &exact);
        let mut worst_l = [0.0_f64; 11];
        let mut lowest = f64::INFINITY;
        for &(_, l, e) in &errs {
            worst_l[l as usize] = worst_l[l as usize].max(e.abs());
            lowest = lowest.min(e);
        }
        println!(
            "{}–{} k ≤ 60, 32 splines: worst per l {:?}; most negative {lowest:.1e}",
            inner.name(),
            outer.name(),
            worst_l.map(|e| format!("{e:.2e}"))
        );
        for l in 0..11 {
            assert!(
                worst_l[l] <= 1.2 * per_l[l],
                "l = {l}: {:e} vs measured {:e}",
                worst_l[l],
                per_l[l]
            );
        }
        // Ritz: above the exact value (measured lowest −0.0: no mode below).
        assert!(lowest > -1e-9, "{lowest:e}");
        // Order: two modes may swap only where their exact frequencies are within 2× the error.
        check_order(&m, &exact, 2.0 * 1.56e-3);

        // Splines that reach 1e-4: ⟨60, 0⟩ alone at 30, every l ≤ 10 of k = 60 at n_k60,
        // every k ≤ 60, l ≤ 10 at n_all (measured: clamped–free 30 / 52 / 58, free–free 30 / 51 / 53).
        let c30 = plate(0.075, inner, outer, vec![60], vec![0], 30);
        let e600 = worst(&errors(&PlateModel::new(&c30).unwrap(), &c30, &exact)).2;
        let ck = plate(0.075, inner, outer, vec![60], (0..=10).collect(), n_k60);
        let ek60 = worst(&errors(&PlateModel::new(&ck).unwrap(), &ck, &exact));
        let ca = plate(
            0.075,
            inner,
            outer,
            (0..=60).collect(),
            (0..=10).collect(),
            n_all,
        );
        let ma = PlateModel::new(&ca).unwrap();
        check_structure(&ca, &ma, 4000);
        let eall = worst(&errors(&ma, &ca, &exact));
        println!("  ⟨60,0⟩ at 30 splines {e600:.2e}; k = 60, l ≤ 10 at {n_k60}: {:.2e} ⟨{},{}⟩; all at {n_all}: {:.2e} ⟨{},{}⟩", ek60.2, ek60.0, ek60.1, eall.2, eall.0, eall.1);
        assert!(e600 > 0.0 && e600 < 1e-4, "{e600:e}");
        assert!(ek60.2 > 0.0 && ek60.2 < 1e-4, "{ek60:?}");
        assert!(eall.2 > 0.0 && eall.2 < 1e-4, "{eall:?}");
    }
    println!("({:.1?})", t0.elapsed());
}

// ---- 2. a tiny inner radius, r_i/r_a = 1e-4 ---------------------------------------

const TINY: f64 = 1e-4;

/// Roots λa of the solid circular plate (J, I) for k, padded with the free plate's
/// rigid-body modes (λ = 0 for k ≤ 1) so that index = l as in the annulus with a free hole.
fn solid_plate(outer: Boundary, k: u32, count: usize) -> Vec<f64> {
    let p = CircularPlate {
        radius: RA,
        poisson_ratio: 0.3,
        edge: edge(outer),
    };
    let mut v = if outer == Boundary::Free && k <= 1 {
        vec![0.0]
    } else {
        vec![]
    };
    let mut x_max = 10.0 + k as f64;
    loop {
        let roots = p.roots(k, x_max);
        if v.len() + roots.len() >= count {
            v.extend(roots.iter().map(|x| x / RA));
            v.truncate(count);
            return v;
        }
        x_max *= 1.5;
    }
}

/// The solid plate pinned at its centre (w(0) = 0), axisymmetric modes: the limit of a
/// supported or clamped tiny hole for k = 0. R = A J₀(λr) + B G(λr) + C I₀(λr) with
/// G = Y₀ + (2/π) K₀ (regular, G(0) = 0: the point-force solution ~ r² ln r), A + C = 0
/// and the two outer conditions. Roots λ (1/m) in ascending order.
fn centrally_pinned_plate(outer: Boundary, count: usize) -> Vec<f64> {
    let nu = 0.3;
    let det = |lam: f64| {
        let z = lam * RA;
        let (j, y) = bessel::jy_val_der(0, z);
        let (i, k) = (bessel::i_val_der(0, z), bessel::k_val_der(0, z));
        let osc = |v: f64, d: f64| {
            let d2 = -d / z - v;
            [v, d, d2, -d2 / z + d / (z * z) - d]
        };
        let modi = |v: f64, d: f64| {
            let d2 = -d / z + v;
            [v, d, d2, -d2 / z + d / (z * z) + d]
        };
        let fj = osc(j.value, j.deriv);
        let fg: Vec<f64> = osc(y.value, y.deriv)
            .iter()
            .zip(modi(k.value, k.deriv))
            .map(|(a, b)| a + 2.0 / std::f64::consts::PI * b)
            .collect();
        let fi = modi(i.value, i.deriv);
        let q = |d: &[f64], which: usize| match which {
            0 => d[0],
            1 => d[1],
            2 => d[2] + nu * d[1] / z,
            _ => d[3] + d[2] / z - d[1] / (z * z),
        };
        let rows: [usize; 2] = match outer {
            Boundary::Clamped => [0, 1],
            Boundary::Supported => [0, 2],
            Boundary::Free => [2, 3],
            Boundary::SupportedSoft => unreachable!("Kirchhoff edges only"),
        };
        // columns (J − I, G) after A + C = 0 (C = −A)
        let m = rows.map(|r| [q(&fj, r) - q(&fi, r), q(&fg, r)]);
        let s = |row: [f64; 2]| row[0].abs().max(row[1].abs());
        (m[0][0] * m[1][1] - m[0][1] * m[1][0]) / (s(m[0]) * s(m[1]))
    };
    let mut out = Vec::new();
    let (mut x0, step) = (0.05 / RA, 0.002 / RA);
    let mut f0 = det(x0);
    while out.len() < count {
        let x1 = x0 + step;
        let f1 = det(x1);
        if f0.signum() != f1.signum() {
            let (mut a, mut b, mut fa) = (x0, x1, f0);
            for _ in 0..100 {
                let mid = 0.5 * (a + b);
                let fm = det(mid);
                if fm.signum() == fa.signum() {
                    a = mid;
                    fa = fm;
                } else {
                    b = mid;
                }
            }
            out.push(0.5 * (a + b));
        }
        x0 = x1;
        f0 = f1;
    }
    out
}

#[test]
fn a_free_tiny_hole_is_the_solid_circular_plate() {
    let ks: Vec<u32> = (0..=6).collect();
    for outer in Boundary::KIRCHHOFF {
        let c = plate(
            TINY * RA,
            Boundary::Free,
            outer,
            ks.clone(),
            vec![0, 1, 2],
            32,
        );
        let exact = exact_table(&c);
        let m = PlateModel::new(&c).unwrap();
        check_structure(&c, &m, 4000);
        check_order(&m, &exact, 1e-5);
        let lib = worst(&errors(&m, &c, &exact));
        // exact annulus against the solid plate, and the library's R(r_i) (paper 4.2: the
        // inner-edge displacements R(r_i) cos kφ of a k ≥ 1 mode must vanish as r_i → 0)
        let (mut gap, mut at) = (0.0_f64, (0, 0));
        let mut edge_value = 0.0_f64;
        for k in 0..=6u32 {
            let solid = solid_plate(outer, k, 3);
            for l in 0..3 {
                if exact[k as usize][l] == 0.0 {
                    assert_eq!(solid[l], 0.0);
                    continue;
                }
                let d = (exact[k as usize][l] / solid[l]).powi(2) - 1.0;
                if d.abs() > gap.abs() {
                    (gap, at) = (d, (k, l));
                }
            }
        }
        let mut edge_higher = 0.0_f64;
        for md in m.modes().iter().filter(|x| x.k >= 1) {
            let v = m.radial_shapes()[md.radial].value(c.inner_radius).abs();
            if md.k == 1 {
                edge_value = edge_value.max(v);
            } else {
                edge_higher = edge_higher.max(v);
            }
        }
        println!("free–{}, r_i/r_a = 1e-4: library vs exact annulus worst {:.2e} ⟨{},{}⟩; annulus vs solid plate {gap:.1e} ⟨{},{}⟩; max |R(r_i)| (unit peak) k = 1 {edge_value:.2e}, k ≥ 2 {edge_higher:.1e}", outer.name(), lib.2, lib.0, lib.1, at.0, at.1);
        // measured (k ≤ 6, l ≤ 2): library 2.61e-5 (clamped outer), 1.95e-5 (supported),
        // 1.06e-5 (free), all at ⟨6,2⟩; the hole lowers the solid plate's frequencies by
        // ≤ 6.3e-8 (∝ (r_i/r_a)², k = 0 and 2); R(r_i) of the k ≥ 1 modes ≤ 9.4e-4 of the
        // peak, as in the exact modes (k = 1: R ≈ R'(0) r_i, compatible in the limit).
        let measured = match outer {
            Boundary::Clamped => 2.61e-5,
            Boundary::Supported => 1.95e-5,
            Boundary::Free => 1.06e-5,
            Boundary::SupportedSoft => unreachable!("Kirchhoff edges only"),
        };
        assert!(lib.2 > 0.0 && lib.2 < 1.3 * measured, "{lib:?}");
        assert!(gap < 0.0 && gap.abs() < 8e-8, "{gap:e}");
        // k = 1 ~ R'(0) r_i (measured ≤ 9.4e-4), k ≥ 2 at the Ritz shape's ripple level (≤ 5.1e-7)
        assert!(
            edge_value < 1.2e-3 && edge_higher < 7e-7,
            "{edge_value:e} {edge_higher:e}"
        );
    }
}

#[test]
fn a_supported_or_clamped_tiny_hole_is_a_point_support() {
    let ks: Vec<u32> = (0..=6).collect();
    for inner in [Boundary::Supported, Boundary::Clamped] {
        for outer in Boundary::KIRCHHOFF {
            let c = plate(TINY * RA, inner, outer, ks.clone(), vec![0, 1, 2], 32);
            let exact = exact_table(&c);
            let m = PlateModel::new(&c).unwrap();
            check_structure(&c, &m, 4000);
            // With knots graded towards the hole (src/model/radial.rs) the order is exact for every k.
            check_order_of(&m, &exact, 1e-5, |_| true);
            let errs = errors(&m, &c, &exact);
            let by = |pred: &dyn Fn(u32) -> bool| {
                worst(
                    &errs
                        .iter()
                        .copied()
                        .filter(|e| pred(e.0))
                        .collect::<Vec<_>>(),
                )
            };
            let (e0, e1, e2) = (by(&|k| k == 0), by(&|k| k == 1), by(&|k| k >= 2));
            // The limits: k = 0 → the centrally pinned plate, k ≥ 2 → the solid plate.
            let pinned = centrally_pinned_plate(outer, 3);
            let d0 = (0..3)
                .map(|l| ((exact[0][l] / pinned[l]).powi(2) - 1.0).abs())
                .fold(0.0, f64::max);
            let d2 = (2..=6u32)
                .flat_map(|k| {
                    let s = solid_plate(outer, k, 3);
                    let e = &exact[k as usize];
                    (0..3).map(move |l| ((e[l] / s[l]).powi(2) - 1.0).abs())
                })
                .fold(0.0, f64::max);
            println!(
                "{}–{}, 1e-4: library vs exact k = 0 {:.1e} ⟨0,{}⟩, k = 1 {:.1e} ⟨1,{}⟩, k ≥ 2 {:.1e} ⟨{},{}⟩; exact vs pinned plate (k = 0) {d0:.1e}, vs solid (k ≥ 2) {d2:.1e}",
                inner.name(), outer.name(), e0.2, e0.1, e1.2, e1.1, e2.2, e2.0, e2.1
            );
            // Ritz upper bounds throughout.
            assert!(errs.iter().all(|e| e.2 > 0.0), "{errs:?}");
            // k ≥ 2: the hole is invisible: library ≤ 2.6e-5 (⟨6,2⟩) against the annulus,
            // annulus ≤ 9.9e-8 above the solid plate (measured).
            assert!(e2.2 < 3.4e-5 && d2 < 1.3e-7, "{e2:?} {d2:e}");
            // k = 0: the centrally pinned plate (annulus ≤ 1.1e-5 below it at 1e-4, falling
            // ~100× per decade of r_i); the library resolves the point force's r² ln r to
            // ≤ 1.8e-5 with graded knots (6.1e-4 with uniform ones; measured).
            assert!(d0 < 1.5e-5, "{d0:e}");
            assert!(e0.2 < 2.5e-5, "{e0:?}");
            // k = 1: the hole's slope (clamped) or its deflection R(r_i) = 0 (supported) acts
            // on ∇w at the centre through a layer of width ~r_i. Uniform knots (5 mm here)
            // missed it by up to 26 % (clamped–free ⟨1,0⟩); the 12 knots graded down to
            // r_i/4 resolve it: measured ≤ 6.7e-5 (clamped–free ⟨1,0⟩) for every edge pair.
            assert!(e1.2 < 1e-4, "{e1:?}");
        }
    }
}

#[test]
fn a_pinned_tiny_hole_reaches_its_limit_fast_for_k0_and_only_logarithmically_for_k1() {
    // Exact annulus, clamped hole. k = 0: the centrally pinned plate, the gap falling
    // ~ (r_i ln r_i)². k = 1: ⟨1,0⟩ against the solid plate's k = 1 mode (clamped outer
    // edge), and the tilt about the pin (free outer edge), which falls to zero.
    let mut last = (f64::INFINITY, f64::INFINITY, f64::INFINITY);
    let solid = solid_plate(Boundary::Clamped, 1, 1)[0];
    let pinned = centrally_pinned_plate(Boundary::Clamped, 1)[0];
    for ratio in [1e-2, 1e-3, 1e-4, 1e-5, 1e-6] {
        let k0 = lambdas(
            &Annulus::new(ratio * RA, RA, 0.3, Edge::Clamped, Edge::Clamped),
            0,
            1,
        )[0];
        let d0 = ((k0 / pinned).powi(2) - 1.0).abs();
        // measured 8.7e-3, 2.9e-4, 6.1e-6, 1.1e-7, 1.6e-9: ≥ 30× per decade
        assert!(d0 > 0.0 && d0 < last.2 / 30.0, "{d0:e}");
        last.2 = d0;
        let clamped = lambdas(
            &Annulus::new(ratio * RA, RA, 0.3, Edge::Clamped, Edge::Clamped),
            1,
            1,
        )[0];
        let free = lambdas(
            &Annulus::new(ratio * RA, RA, 0.3, Edge::Clamped, Edge::Free),
            1,
            1,
        )[0];
        let excess = (clamped / solid).powi(2) - 1.0;
        println!("r_i/r_a = {ratio:e}: clamped–clamped ⟨0,0⟩ differs from the pinned plate by {d0:.1e}; ⟨1,0⟩ λa = {:.5} (+{:.2} % in f over the solid plate, × ln(r_a/r_i) = {:.3}); clamped–free ⟨1,0⟩ λa = {:.5}", clamped * RA, 100.0 * excess, excess * (1.0 / ratio).ln(), free * RA);
        assert!(excess < last.0 && free < last.1);
        (last.0, last.1) = (excess, free);
    }
    // measured: still +1.5 % (clamped outer) and λa = 1.057 (free outer) at 1e-6
    assert!(last.0 > 0.01 && last.1 * RA > 1.0, "{last:?}");
}

#[test]
fn sixty_nodal_diameters_around_a_tiny_hole_match_the_solid_plate() {
    for ratio in [1e-4, 1e-6] {
        for inner in Boundary::KIRCHHOFF {
            let c = plate(
                ratio * RA,
                inner,
                Boundary::Free,
                vec![59, 60],
                vec![0, 1, 2],
                32,
            );
            let m = PlateModel::new(&c).expect("k = 60 around a tiny hole builds");
            check_structure(&c, &m, 4000);
            let mut exact = vec![vec![]; 61];
            exact[59] = solid_plate(Boundary::Free, 59, 3);
            exact[60] = solid_plate(Boundary::Free, 60, 3);
            let w = worst(&errors(&m, &c, &exact));
            let rip = m
                .radial_shapes()
                .iter()
                .map(|r| ripple(|x| r.value(x), c.inner_radius, RA, 4000))
                .fold(0.0, f64::max);
            println!("{}–free r_i/r_a = {ratio:e}, k = 59, 60: worst {:.2e} ⟨{},{}⟩ against the solid plate; ripple inside {rip:.1e} of the peak", inner.name(), w.2, w.0, w.1);
            // measured ≤ 3.7e-7: far below the 1e-4 lobe threshold of `nodal_circles`
            assert!(rip < 1e-5, "{rip:e}");
            // measured 1.01e-3 at ⟨60,2⟩ for every inner edge and both ratios: the mode lives
            // in the outer ~10 mm, where 32 uniform splines over the whole radius put knots
            // 5.2 mm apart (the lathe disc's 2.6 mm give 7.5e-5): see docs/hard_cases.md.
            assert!(w.2 > 0.0 && w.2 < 1.3e-3, "{w:?}");
        }
    }
}

// ---- 3. narrow rings ----------------------------------------------------------------

const NARROW_KS: [u32; 7] = [0, 1, 2, 5, 10, 20, 60];

#[test]
fn narrow_rings_with_a_supported_or_clamped_edge_match_the_exact_annulus() {
    // measured worst over k ∈ NARROW_KS, l ≤ 2 at 32 splines: 1.48e-5 (clamped–clamped ⟨0,2⟩),
    // the same at 0.98 and 0.99 (the error depends on λ(r_a − r_i), i.e. on l).
    for ratio in [0.98, 0.99] {
        for inner in Boundary::KIRCHHOFF {
            for outer in Boundary::KIRCHHOFF {
                if inner == Boundary::Free && outer == Boundary::Free {
                    continue;
                }
                let c = plate(
                    ratio * RA,
                    inner,
                    outer,
                    NARROW_KS.to_vec(),
                    vec![0, 1, 2],
                    32,
                );
                let exact = exact_table(&c);
                let m = PlateModel::new(&c).unwrap();
                check_structure(&c, &m, 2000);
                check_order(&m, &exact, 1e-4);
                let errs = errors(&m, &c, &exact);
                let w = worst(&errs);
                let lowest = errs.iter().map(|e| e.2).fold(f64::INFINITY, f64::min);
                let width = RA * (1.0 - ratio);
                println!(
                    "{ratio} {}–{}: worst {:.2e} ⟨{},{}⟩, lowest {lowest:+.1e}; λ(r_a − r_i) of ⟨0,0⟩ {:.4}; {:.3e} … {:.3e} Hz",
                    inner.name(), outer.name(), w.2, w.0, w.1, exact[0][0] * width, m.modes()[0].frequency_hz, m.modes().last().unwrap().frequency_hz
                );
                assert!(w.2 < 2e-5, "{w:?}");
                // roundoff: a free edge's rigid-like ⟨k,0⟩ come out up to 2.5e-7 below exact (measured)
                assert!(lowest > -5e-7, "{lowest:e}");
            }
        }
    }
}

#[test]
fn a_narrow_ring_between_edges_that_hold_it_is_a_beam_and_stiffens_as_one_over_width_squared() {
    // Clamped–clamped / supported–supported: λ(r_a − r_i) → 4.7300 / π (beam across the
    // width), so ω ∝ 1/(r_a − r_i)² without bound (paper 4.2).
    for (inner, beam) in [
        (Boundary::Clamped, 4.730_040_744_862_704),
        (Boundary::Supported, std::f64::consts::PI),
    ] {
        let mut last = 0.0;
        for ratio in [0.9, 0.98, 0.99, 0.995] {
            let c = plate(ratio * RA, inner, inner, vec![0, 2], vec![0], 32);
            let m = PlateModel::new(&c).unwrap();
            let width = RA * (1.0 - ratio);
            let lam = lambdas(&annulus(&c), 0, 1)[0];
            let f = m.modes()[0].frequency_hz;
            let f_beam = material(&c).frequency_hz(beam / width);
            println!("{} both edges, r_i/r_a = {ratio}: λ w = {:.6} (beam {beam:.6}); f = {f:.4e} Hz, f·w² = {:.6e}, library/beam − 1 = {:.1e}", inner.name(), lam * width, f * width * width, f / f_beam - 1.0);
            assert!(f > last);
            last = f;
            assert!((f / material(&c).frequency_hz(lam) - 1.0).abs() < 2e-5);
            assert!((lam * width / beam - 1.0).abs() < 0.5 * (1.0 - ratio));
        }
    }
}

#[test]
fn free_free_narrow_rings() {
    // The ⟨k,0⟩ ring modes of a free–free narrow ring are nearly rigid across the width;
    // their energies are far below the B-spline stiffness entries, and with B-splines only
    // round-off of ~ε·((n−3) r_a/(k (r_a − r_i)))⁴ swamped them (1.1e-3 at 0.99, 2.7e-2 at
    // 0.995, 0.998 refused with ω² < 0; docs/hard_cases.md problem 1). The library now spans
    // {1, r − r_m} with those exact functions: measured worst 5.4e-7 (⟨60,2⟩, a Ritz error)
    // at the default 32 splines from 0.98 to 0.998; 2.0e-6 at 24 splines; 6.0e-5 at 12.
    let cases = [
        (0.98, 32, 5.40e-7),
        (0.99, 32, 5.07e-7),
        (0.995, 32, 5.00e-7),
        (0.998, 32, 4.99e-7),
        (0.98, 24, 1.98e-6),
        (0.99, 12, 5.98e-5),
    ];
    for (ratio, splines, measured) in cases {
        let c = plate(
            ratio * RA,
            Boundary::Free,
            Boundary::Free,
            NARROW_KS.to_vec(),
            vec![0, 1, 2],
            splines,
        );
        let exact = exact_table(&c);
        let m = PlateModel::new(&c).unwrap();
        check_structure(&c, &m, 2000);
        check_order_of(&m, &exact, 1e-5, |_| true);
        let errs = errors(&m, &c, &exact);
        let w = worst(&errs);
        println!(
            "free–free {ratio}, {splines} splines: worst {:.2e} ⟨{},{}⟩",
            w.2, w.0, w.1
        );
        assert!(
            errs.iter().all(|e| e.2 > -1e-9),
            "not an upper bound: {errs:?}"
        );
        assert!(w.2.abs() < 1.5 * measured, "{w:?} vs measured {measured:e}");
    }
}

fn yaml_plate(keys: &str) -> Result<Config, annular_plate::config::ConfigError> {
    let mut text = String::from("annular_plate:\n  ros__parameters:\n    plate:\n");
    for line in keys.lines() {
        text += &format!("      {}\n", line.trim());
    }
    Config::from_yaml_str(&text, "annular_plate")
}

#[test]
fn validation_limits_of_the_degenerate_geometries() {
    // r_i/r_a ≥ 1e-6 and (r_a − r_i)/r_a ≥ 1e-3 (paper 4.2)
    assert!(yaml_plate("inner_radius: 1.5e-5\nouter_radius: 0.15").is_ok());
    assert!(yaml_plate("inner_radius: 1.5e-7\nouter_radius: 0.15").is_ok());
    let e = yaml_plate("inner_radius: 1.4e-7\nouter_radius: 0.15")
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("plate.inner_radius") && e.contains("1e-6"),
        "{e}"
    );
    // 0.999 is the limit itself: (0.15 − 0.14985)/0.15 = 0.000999999999999987 in f64,
    // accepted all the same (the check allows for that rounding).
    for ri in ["0.147", "0.1485", "0.1497", "0.14985"] {
        assert!(
            yaml_plate(&format!("inner_radius: {ri}\nouter_radius: 0.15")).is_ok(),
            "{ri}"
        );
    }
    for ri in ["0.14986", "0.1499"] {
        let e = yaml_plate(&format!("inner_radius: {ri}\nouter_radius: 0.15"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("narrower than 1e-3"), "{e}");
    }
    // the notes (not errors) that accompany the accepted extremes
    let notes = yaml_plate("inner_radius: 1.5e-5\nouter_radius: 0.15\ninner_boundary: free")
        .unwrap()
        .plate
        .geometry_notes();
    assert!(
        notes.iter().any(|n| n.contains("compatibility")),
        "{notes:?}"
    );
    let notes = yaml_plate("inner_radius: 0.1485\nouter_radius: 0.15")
        .unwrap()
        .plate
        .geometry_notes();
    assert!(notes.iter().any(|n| n.contains("narrow ring")), "{notes:?}");
}

// ---- 4. thickness and moduli ------------------------------------------------------

#[test]
fn frequencies_scale_as_thickness_times_sqrt_of_e_over_rho_to_1e_10() {
    for (ri, inner, outer) in [
        (0.075, Boundary::Clamped, Boundary::Free),
        (TINY * RA, Boundary::Free, Boundary::Free),
        (0.98 * RA, Boundary::Supported, Boundary::Clamped),
    ] {
        let base = plate(
            ri,
            inner,
            outer,
            (0..=7).chain([60]).collect(),
            vec![0, 1, 2],
            32,
        );
        let reference = PlateModel::new(&base).unwrap();
        let scale0 = base.thickness * (base.youngs_modulus / base.density).sqrt();
        let (mut worst_f, mut worst_m, mut at) = (0.0_f64, 0.0_f64, (0, 0, 0.0, 0.0, 0.0));
        for h in [1e-4f64, 0.01, 0.1] {
            for e in [1e3f64, 2.1e11, 1e15] {
                for rho in [1.0, 7850.0, 1e5] {
                    let text = format!("inner_radius: {ri}\nouter_radius: {RA}\nthickness: {h}\nyoungs_modulus: {e}\ndensity: {rho}\ninner_boundary: {}\nouter_boundary: {}", inner.name(), outer.name());
                    let mut c = yaml_plate(&text).expect("extreme but valid material").plate;
                    c.nodal_diameters = base.nodal_diameters.clone();
                    c.nodal_circles = base.nodal_circles.clone();
                    c.damping = vec![0.0];
                    // The same fixed count as the reference (the parameter's default is `auto`).
                    c.radial_splines = base.radial_splines;
                    let m = PlateModel::new(&c).unwrap();
                    check_structure(&c, &m, 500);
                    let s = h * (e / rho).sqrt() / scale0;
                    for (a, b) in m.modes().iter().zip(reference.modes()) {
                        assert_eq!((a.k, a.l, a.shape), (b.k, b.l, b.shape));
                        let d = (a.omega / (s * b.omega) - 1.0).abs();
                        if d > worst_f {
                            (worst_f, at) = (d, (a.k, a.l, h, e, rho));
                        }
                        // unit-peak shapes: m = ρh ∫R² dA
                        worst_m = worst_m.max(
                            (a.modal_mass
                                / (b.modal_mass * rho * h / (base.density * base.thickness))
                                - 1.0)
                                .abs(),
                        );
                    }
                }
            }
        }
        println!("{}–{} r_i/r_a = {:e}: ω/(h √(E/ρ)) constant to {worst_f:.1e} (⟨{},{}⟩ at h = {}, E = {:e}, ρ = {}), m/(ρh) to {worst_m:.1e} over 27 materials", inner.name(), outer.name(), ri / RA, at.0, at.1, at.2, at.3, at.4);
        // Measured 6.1e-11 / 2.4e-11 / 6.7e-13 (frequencies) and 6.7e-12 / 1.5e-11 / 1.6e-13
        // (masses) for the three plates: not the ~1e-15 of an exact scaling, because the
        // library assembles and solves the dimensional K̄, M̄ — the round-off of the
        // ill-conditioned pencil differs with the units (docs/hard_cases.md, problem 4).
        assert!(
            worst_f < 1e-10 && worst_m < 2.5e-11,
            "{worst_f:e} {worst_m:e}"
        );
    }
}

#[test]
fn poisson_ratio_near_its_limits_matches_the_exact_solution() {
    // measured worst at 32 splines over k ≤ 7, l ≤ 2
    let cases = [
        (Boundary::Clamped, Boundary::Free, -0.99, 4.62e-6),
        (Boundary::Clamped, Boundary::Free, 0.49, 4.16e-6),
        (Boundary::Free, Boundary::Free, -0.99, 1.16e-6),
        (Boundary::Free, Boundary::Free, 0.49, 2.03e-6),
        (Boundary::Supported, Boundary::Free, -0.99, 2.55e-6),
        (Boundary::Free, Boundary::Supported, 0.49, 3.99e-6),
    ];
    for (inner, outer, nu, measured) in cases {
        let text = format!("inner_radius: 0.075\nouter_radius: {RA}\npoisson_ratio: {nu}\ninner_boundary: {}\nouter_boundary: {}", inner.name(), outer.name());
        let mut c = yaml_plate(&text).expect("ν in (−1, 0.5) is valid").plate;
        c.nodal_diameters = (0..=7).collect();
        c.nodal_circles = vec![0, 1, 2];
        c.damping = vec![0.0];
        let exact = exact_table(&c);
        let m = PlateModel::new(&c).unwrap();
        check_structure(&c, &m, 2000);
        check_order(&m, &exact, 1e-5);
        let w = worst(&errors(&m, &c, &exact));
        println!(
            "{}–{} ν = {nu}: worst {:.2e} ⟨{},{}⟩; lowest {:.4e} Hz",
            inner.name(),
            outer.name(),
            w.2,
            w.0,
            w.1,
            m.modes()[0].frequency_hz
        );
        assert!(w.2 > 0.0 && w.2 < 1.3 * measured, "{w:?}");
    }
}
