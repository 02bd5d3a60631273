//! Bessel functions of integer order for the exact plate solution — written
//! from scratch so the reference shares no numerics with the library.
//!
//! * `J_n` — Miller's backward recurrence, normalised by
//!   `1 = J_0 + 2 Σ_{k≥1} J_{2k}` (relatively accurate where J_n is small,
//!   absolutely accurate — to the envelope `sqrt(2/(πx))` — where it oscillates).
//! * `Y_n` — Neumann series for `Y_0`, `Y_1` (A&S 9.1.88/9.1.89) built from the
//!   same J sequence, then the upward recurrence (stable for the dominant Y).
//! * `I_n` — the power series; all terms are positive, so it is relatively
//!   accurate for every x it is used for (`0 < x ≤ 700`). Beyond that (where
//!   `I_n(x)` itself overflows) `e^{-x} I_n(x)` comes from Miller's backward
//!   recurrence normalised by `e^x = I_0 + 2 Σ_{k≥1} I_k` (all terms positive).
//! * `K_0`, `K_1` — the trapezoid rule on `e^x K_ν(x) = ∫_0^∞ e^{-x(cosh t-1)} cosh(νt) dt`
//!   (analytic, double-exponentially decaying integrand: the trapezoid rule
//!   converges exponentially in 1/h), then the upward recurrence (stable for K).
//!
//! Exponentially scaled variants `e^{-x} I_n(x)`, `e^{x} K_n(x)` never overflow.
//! Derivatives come from the standard recurrences in a cancellation-free form.
//! Domain: integer `n ≥ 0`, `0 < x ≤ 1e5` (unscaled `I_n`, `K_n` only where they stay
//! in range, x ≲ 700). Accuracy ~1e-14 relative (J, Y: relative to their envelope near
//! zeros), checked by the self-tests below against tabulated values and the Wronskians
//! (n ≤ 35, x ≤ 300), and by `tests/model_hard_cases.rs` against mpmath for n ≤ 62
//! and x up to 1e5 (narrow rings need λ r_a ~ 1e4).

#![allow(dead_code)]

use std::f64::consts::PI;

/// Euler–Mascheroni constant γ.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

const X_MAX: f64 = 1.0e5;

/// Largest x for the power series of `I_n` (its unscaled sum must stay finite).
const I_SERIES_X_MAX: f64 = 700.0;

fn check_domain(x: f64) {
    assert!(
        x > 0.0 && x <= X_MAX && x.is_finite(),
        "Bessel argument x = {x} outside (0, {X_MAX}]"
    );
}

/// `J_0(x) ..= J_{n_max}(x)` and, beyond them, the Miller sequence up to the start order.
/// Returns (values 0..=len-1 normalised, where len ≥ n_max + 1 and the tail is usable for
/// the Neumann series).
fn j_sequence_full(n_max: usize, x: f64) -> Vec<f64> {
    check_domain(x);
    let m = (n_max as f64).max(x);
    // Start order: far enough into the evanescent region n > x that the Y-like
    // contamination of the backward recurrence has died by > 1e-20 at max(n_max, x).
    let mut start = (m + 30.0 + (40.0 * m).sqrt()).ceil() as usize;
    if start % 2 == 1 {
        start += 1;
    }
    let mut j = vec![0.0_f64; start + 2];
    j[start + 1] = 0.0;
    j[start] = 1e-30;
    const BIG: f64 = 1e250;
    for mm in (1..=start).rev() {
        let prev = (2.0 * mm as f64 / x) * j[mm] - j[mm + 1];
        j[mm - 1] = prev;
        if prev.abs() > BIG {
            // Rescale everything computed so far (orders ≥ mm-1).
            for v in j[mm - 1..].iter_mut() {
                *v /= BIG;
            }
        }
    }
    // Normalise with 1 = J_0 + 2 Σ J_{2k}.
    let mut sum = j[0];
    let mut k = 2;
    while k <= start {
        sum += 2.0 * j[k];
        k += 2;
    }
    for v in j.iter_mut() {
        *v /= sum;
    }
    j.truncate(start + 1);
    j
}

/// `J_0(x) ..= J_{n_max}(x)`.
pub fn j_seq(n_max: usize, x: f64) -> Vec<f64> {
    let mut j = j_sequence_full(n_max, x);
    j.truncate(n_max + 1);
    j
}

/// `Y_0(x) ..= Y_{n_max}(x)`.
pub fn y_seq(n_max: usize, x: f64) -> Vec<f64> {
    let j = j_sequence_full(n_max.max(1), x);
    y_seq_from_j(n_max, x, &j)
}

/// `J_0 ..= J_{n_max}` and `Y_0 ..= Y_{n_max}` from one Miller pass.
pub fn jy_seq(n_max: usize, x: f64) -> (Vec<f64>, Vec<f64>) {
    let j = j_sequence_full(n_max.max(1), x);
    let y = y_seq_from_j(n_max, x, &j);
    let mut j = j;
    j.truncate(n_max + 1);
    (j, y)
}

/// Y from the full (normalised) Miller J sequence.
fn y_seq_from_j(n_max: usize, x: f64, j: &[f64]) -> Vec<f64> {
    let ln_term = (x / 2.0).ln() + EULER_GAMMA;
    // Y_0 = (2/π)(ln(x/2)+γ) J_0 − (4/π) Σ_{k≥1} (−1)^k J_{2k}/k          (A&S 9.1.89)
    // Y_1 = −2 J_0/(π x) + (2/π)(ln(x/2)+γ−1) J_1
    //       − (2/π) Σ_{k≥1} (−1)^k (2k+1) J_{2k+1}/(k(k+1))                (A&S 9.1.88, n = 1)
    let mut s0 = 0.0;
    let mut s1 = 0.0;
    let mut k = 1;
    while 2 * k + 1 < j.len() {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        s0 += sign * j[2 * k] / k as f64;
        s1 += sign * (2 * k + 1) as f64 * j[2 * k + 1] / (k * (k + 1)) as f64;
        k += 1;
    }
    let y0 = (2.0 / PI) * ln_term * j[0] - (4.0 / PI) * s0;
    let y1 = -2.0 * j[0] / (PI * x) + (2.0 / PI) * (ln_term - 1.0) * j[1] - (2.0 / PI) * s1;
    let mut y = Vec::with_capacity(n_max + 1);
    y.push(y0);
    if n_max >= 1 {
        y.push(y1);
    }
    for m in 1..n_max {
        let next = (2.0 * m as f64 / x) * y[m] - y[m - 1];
        y.push(next);
    }
    y
}

/// `e^{-x} I_n(x)` by the power series (all terms positive).
pub fn i_scaled(n: usize, x: f64) -> f64 {
    check_domain(x);
    if x > I_SERIES_X_MAX {
        return i_scaled_miller(n, x);
    }
    let half = 0.5 * x;
    // t0 = (x/2)^n / n!, built as a product to stay in range.
    let mut t = 1.0_f64;
    for m in 1..=n {
        t *= half / m as f64;
    }
    let q = half * half;
    // Scale the leading term by e^{-x} in pieces so neither the sum overflows nor t0 underflows.
    // For x ≤ 700 the unscaled sum stays below ~1e303, so sum unscaled then multiply.
    let mut sum = 0.0;
    let mut m = 0usize;
    loop {
        sum += t;
        m += 1;
        t *= q / (m as f64 * (m + n) as f64);
        if t < 1e-17 * sum && m as f64 > half {
            break;
        }
        if t == 0.0 {
            break;
        }
    }
    sum * (-x).exp()
}

/// `e^{-x} I_n(x)` for large x: backward recurrence `I_{k-1} = I_{k+1} + (2k/x) I_k`
/// (stable: I is the minimal solution as k grows), normalised by
/// `e^x = I_0 + 2 Σ_{k≥1} I_k`. Start order: beyond n and far enough that
/// `I_k / I_0 ≈ e^{-k²/(2x)}` has fallen below 1e-30.
fn i_scaled_miller(n: usize, x: f64) -> f64 {
    let start = (n as f64 + 12.0 * x.sqrt() + 40.0).ceil() as usize;
    let (mut above, mut cur) = (0.0_f64, 1e-30_f64); // I_{k+1}, I_k at k = start
    let mut sum = 0.0_f64; // Σ_{k≥1} I_k over the orders done so far
    let mut at_n = 0.0_f64;
    const BIG: f64 = 1e250;
    let mut k = start;
    while k >= 1 {
        if k == n {
            at_n = cur;
        }
        sum += cur;
        let below = above + (2.0 * k as f64 / x) * cur;
        above = cur;
        cur = below;
        k -= 1;
        if cur > BIG {
            above /= BIG;
            cur /= BIG;
            sum /= BIG;
            at_n /= BIG;
        }
    }
    // cur = I_0 now
    if n == 0 {
        at_n = cur;
    }
    at_n / (cur + 2.0 * sum)
}

/// `I_n(x)`.
pub fn i_n(n: usize, x: f64) -> f64 {
    let s = i_scaled(n, x);
    s * x.exp()
}

/// `e^{x} K_0(x)`, `e^{x} K_1(x)` by the trapezoid rule on the integral representation.
fn k01_scaled(x: f64) -> (f64, f64) {
    check_domain(x);
    // Step: the integrand is entire; in the strip |Im t| < d it is bounded by
    // e^{x(1−cos d)} so the error is ~ exp(−2π d/h + x d²/2); h = min(0.2, 0.5/√x)
    // keeps it below e^{-40} for all x.
    let h = (0.2_f64).min(0.5 / x.sqrt());
    let f = |t: f64| {
        // cosh t − 1 = 2 sinh²(t/2) without cancellation: for large x the exponent
        // x (cosh t − 1) needs full relative precision at small t.
        let s = (0.5 * t).sinh();
        let e = (-x * 2.0 * s * s).exp();
        (e, e * t.cosh())
    };
    let (e0, e1) = f(0.0);
    let mut s0 = 0.5 * e0;
    let mut s1 = 0.5 * e1;
    let mut i = 1usize;
    loop {
        let t = i as f64 * h;
        let (a, b) = f(t);
        s0 += a;
        s1 += b;
        if b < 1e-18 * s1 {
            break;
        }
        i += 1;
        assert!(i < 1_000_000, "K integral did not converge for x = {x}");
    }
    (h * s0, h * s1)
}

/// `e^{x} K_0(x) ..= e^{x} K_{n_max}(x)`.
pub fn k_scaled_seq(n_max: usize, x: f64) -> Vec<f64> {
    let (k0, k1) = k01_scaled(x);
    let mut k = Vec::with_capacity(n_max + 1);
    k.push(k0);
    if n_max >= 1 {
        k.push(k1);
    }
    for m in 1..n_max {
        let next = k[m - 1] + (2.0 * m as f64 / x) * k[m];
        k.push(next);
    }
    k
}

/// `J_n(x)`.
pub fn j_n(n: usize, x: f64) -> f64 {
    j_seq(n, x)[n]
}
/// `Y_n(x)`.
pub fn y_n(n: usize, x: f64) -> f64 {
    y_seq(n, x)[n]
}
/// `e^{x} K_n(x)`.
pub fn k_scaled(n: usize, x: f64) -> f64 {
    k_scaled_seq(n, x)[n]
}
/// `K_n(x)`.
pub fn k_n(n: usize, x: f64) -> f64 {
    k_scaled(n, x) * (-x).exp()
}

/// Value and first derivative of a cylinder function of order n at x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValDer {
    pub value: f64,
    pub deriv: f64,
}

/// `J_n(x)`, `J_n'(x)` (`J_n' = J_{n−1} − (n/x) J_n`, `J_0' = −J_1`).
pub fn j_val_der(n: usize, x: f64) -> ValDer {
    let j = j_seq(n + 1, x);
    let deriv = if n == 0 {
        -j[1]
    } else {
        j[n - 1] - n as f64 / x * j[n]
    };
    ValDer { value: j[n], deriv }
}

/// `Y_n(x)`, `Y_n'(x)`.
pub fn y_val_der(n: usize, x: f64) -> ValDer {
    let y = y_seq(n + 1, x);
    let deriv = if n == 0 {
        -y[1]
    } else {
        y[n - 1] - n as f64 / x * y[n]
    };
    ValDer { value: y[n], deriv }
}

/// `(J_n, J_n')` and `(Y_n, Y_n')` from one Miller pass.
pub fn jy_val_der(n: usize, x: f64) -> (ValDer, ValDer) {
    let (j, y) = jy_seq(n + 1, x);
    let d = |v: &[f64]| {
        if n == 0 {
            -v[1]
        } else {
            v[n - 1] - n as f64 / x * v[n]
        }
    };
    (
        ValDer {
            value: j[n],
            deriv: d(&j),
        },
        ValDer {
            value: y[n],
            deriv: d(&y),
        },
    )
}

/// `e^{-x} I_n(x)` and `e^{-x} I_n'(x)` (`I_n' = I_{n+1} + (n/x) I_n`, no cancellation).
pub fn i_scaled_val_der(n: usize, x: f64) -> ValDer {
    let a = i_scaled(n, x);
    let b = i_scaled(n + 1, x);
    ValDer {
        value: a,
        deriv: b + n as f64 / x * a,
    }
}

/// `e^{x} K_n(x)` and `e^{x} K_n'(x)` (`K_n' = −K_{n−1} − (n/x) K_n`, `K_0' = −K_1`; no cancellation).
pub fn k_scaled_val_der(n: usize, x: f64) -> ValDer {
    let k = k_scaled_seq(n + 1, x);
    let deriv = if n == 0 {
        -k[1]
    } else {
        -k[n - 1] - n as f64 / x * k[n]
    };
    ValDer { value: k[n], deriv }
}

/// Unscaled `I_n`, `I_n'`.
pub fn i_val_der(n: usize, x: f64) -> ValDer {
    let s = i_scaled_val_der(n, x);
    let e = x.exp();
    ValDer {
        value: s.value * e,
        deriv: s.deriv * e,
    }
}

/// Unscaled `K_n`, `K_n'`.
pub fn k_val_der(n: usize, x: f64) -> ValDer {
    let s = k_scaled_val_der(n, x);
    let e = (-x).exp();
    ValDer {
        value: s.value * e,
        deriv: s.deriv * e,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    #[allow(clippy::excessive_precision)] // reference values as published, to their last digit
    fn tabulated_values() {
        // Reference values (A&S tables / mpmath to 16 digits).
        let cases: &[(&str, f64, f64)] = &[
            ("J0(1)", j_n(0, 1.0), 0.765_197_686_557_966_6),
            ("Y0(1)", y_n(0, 1.0), 0.088_256_964_215_676_96),
            ("I0(1)", i_n(0, 1.0), 1.266_065_877_752_008_2),
            ("K0(1)", k_n(0, 1.0), 0.421_024_438_240_708_34),
            ("J5(10)", j_n(5, 10.0), -0.234_061_528_186_793_65),
            ("Y5(10)", y_n(5, 10.0), 0.135_403_047_689_362_37),
            ("I5(10)", i_n(5, 10.0), 777.188_286_403_259_9),
            // (K5(10) is 5.754…e-5, not e-4: K_0(10) = 1.778e-5, K_1(10) = 1.865e-5 and the
            // upward recurrence K_{n+1} = K_{n-1} + (2n/x) K_n give 2.151e-5, 2.725e-5, 3.786e-5, 5.754e-5.)
            ("K5(10)", k_n(5, 10.0), 5.754_184_998_531_228e-5),
            ("J1(1)", j_n(1, 1.0), 0.440_050_585_744_933_5),
            ("Y1(1)", y_n(1, 1.0), -0.781_212_821_300_288_7),
            ("I1(1)", i_n(1, 1.0), 0.565_159_103_992_485_0),
            ("K1(1)", k_n(1, 1.0), 0.601_907_230_197_234_6),
        ];
        for (name, got, want) in cases {
            assert!(
                rel(*got, *want) < 1e-13,
                "{name}: got {got:e}, want {want:e}, rel {:e}",
                rel(*got, *want)
            );
        }
    }

    /// (n, x, J_n, Y_n, e^{-x} I_n, e^{x} K_n), generated with mpmath 1.3 at 30 digits.
    #[allow(clippy::excessive_precision)] // mpmath's digits as printed, not rounded by hand
    const MPMATH: &[(usize, f64, f64, f64, f64, f64)] = &[
        (
            0,
            0.05,
            9.9937509764946858e-1,
            -1.9793110008172097,
            9.5182403579097663e-1,
            3.273904222534542,
        ),
        (
            0,
            1.0,
            7.6519768655796655e-1,
            8.8256964215676958e-2,
            4.6575960759364044e-1,
            1.144463079806895,
        ),
        (
            0,
            5.0,
            -1.775967713143383e-1,
            -3.0851762524903378e-1,
            1.8354081260932835e-1,
            5.4780756431351899e-1,
        ),
        (
            0,
            20.0,
            1.6702466434058315e-1,
            6.2640596809383831e-2,
            8.9780311884826022e-2,
            2.7854487665718222e-1,
        ),
        (
            0,
            60.0,
            -9.147180408906187e-2,
            4.7358952209449399e-2,
            5.1611549173609841e-2,
            1.6146817823629393e-1,
        ),
        (
            0,
            200.0,
            -1.5437439930565092e-2,
            -5.4265775249817911e-2,
            2.8227159949111916e-2,
            8.8567458339296658e-2,
        ),
        (
            1,
            0.05,
            2.4992188313759699e-2,
            -1.278985517117497e+1,
            2.3788167866549569e-2,
            2.093046515706008e+1,
        ),
        (
            1,
            1.0,
            4.4005058574493352e-1,
            -7.8121282130028872e-1,
            2.0791041534970845e-1,
            1.6361534862632582,
        ),
        (
            1,
            5.0,
            -3.2757913759146522e-1,
            1.4786314339122684e-1,
            1.6397226694454236e-1,
            6.0027385878831258e-1,
        ),
        (
            1,
            20.0,
            6.6833124175850046e-2,
            -1.655116143625213e-1,
            8.7506222183288665e-2,
            2.8542549694072645e-1,
        ),
        (
            1,
            60.0,
            4.6598383758166318e-2,
            9.1869609369866895e-2,
            5.1179630189028718e-2,
            1.6280823094404427e-1,
        ),
        (
            1,
            200.0,
            -5.4304538182378223e-2,
            1.5301824580389989e-2,
            2.8156503394832918e-2,
            8.878860158500368e-2,
        ),
        (
            2,
            0.05,
            3.1243490091938443e-4,
            -5.0961489584618161e+2,
            2.973211289938687e-4,
            8.4049251050493774e+2,
        ),
        (
            2,
            1.0,
            1.1490348493190048e-1,
            -1.6506826068162544,
            4.9938776894223539e-2,
            4.4167700523334115,
        ),
        (
            2,
            5.0,
            4.6565116277752216e-2,
            3.6766288260552452e-1,
            1.1795190583151141e-1,
            7.8791710782884402e-1,
        ),
        (
            2,
            20.0,
            -1.6034135192299815e-1,
            -7.9191758245635961e-2,
            8.1029689666497155e-2,
            3.0708742635125487e-1,
        ),
        (
            2,
            60.0,
            9.3025083547667413e-2,
            -4.4296631897120503e-2,
            4.9905561500642217e-2,
            1.6689511926776207e-1,
        ),
        (
            2,
            200.0,
            1.4894394548741309e-2,
            5.4418793495621811e-2,
            2.7945594915163586e-2,
            8.9455344355146695e-2,
        ),
        (
            7,
            0.05,
            1.2109203976980749e-15,
            -3.7553273698049782e+13,
            1.1520431056914942e-15,
            6.2000033708940143e+13,
        ),
        (
            7,
            1.0,
            1.5023258174368082e-6,
            -3.0588957052123989e+4,
            5.8831950920540458e-7,
            1.2016714005856377e+5,
        ),
        (
            7,
            5.0,
            5.3376410155890715e-2,
            -1.2628988357693235,
            1.7282088952139873e-3,
            3.3588590932179199e+1,
        ),
        (
            7,
            20.0,
            -1.8422139772059443e-1,
            -4.4312047131198162e-3,
            2.5894012606505574e-2,
            9.1137303641056451e-1,
        ),
        (
            7,
            60.0,
            -7.1266351474327106e-3,
            -1.0311201709526646e-1,
            3.4207043762592772e-2,
            2.4198097713967818e-1,
        ),
        (
            7,
            200.0,
            5.5762660213175077e-2,
            -8.692870092287339e-3,
            2.4965363433932033e-2,
            1.0007776987952704e-1,
        ),
        (
            15,
            0.05,
            7.1216980181425867e-37,
            -2.9797356535927847e+34,
            6.7748979754951762e-37,
            4.9200958366565509e+34,
        ),
        (
            15,
            1.0,
            2.2975315322103444e-17,
            -9.256973275752208e+14,
            8.7204462262271363e-18,
            3.8139309896939031e+15,
        ),
        (
            15,
            5.0,
            4.7967432775179572e-7,
            -4.6940495637945749e+4,
            7.0612180331907296e-9,
            4.4775903260693662e+6,
        ),
        (
            15,
            20.0,
            -8.1206905515374787e-4,
            2.1826661420754131e-1,
            3.6208232769207902e-4,
            5.5230389117487105e+1,
        ),
        (
            15,
            60.0,
            1.0327644058741856e-1,
            -1.7079267853295044e-2,
            7.8688324670919619e-3,
            1.0274327724549238,
        ),
        (
            15,
            200.0,
            5.4209892942437708e-2,
            1.5917487470239086e-2,
            1.6064918662919372e-2,
            1.5518321726810041e-1,
        ),
        (
            30,
            0.05,
            3.2698770962977482e-81,
            -3.2448755656489022e+78,
            3.1105287305162715e-81,
            5.3581384184970973e+78,
        ),
        (
            30,
            1.0,
            3.4828697942514829e-42,
            -3.0481287832256432e+39,
            1.3021094983785914e-42,
            1.2792629867539754e+40,
        ),
        (
            30,
            5.0,
            2.6711772782507988e-21,
            -4.0285684185540876e+18,
            2.6937267526846669e-23,
            6.1029451020974106e+20,
        ),
        (
            30,
            20.0,
            1.2401536360354328e-4,
            -1.1497814626308341e+2,
            1.6928762259616172e-10,
            8.1910865525376815e+7,
        ),
        (
            30,
            60.0,
            6.8198567826733513e-2,
            8.7170518711026985e-2,
            3.120382095712135e-5,
            2.3886689615482653e+2,
        ),
        (
            30,
            200.0,
            -5.2122279029882832e-2,
            -2.2422775512171563e-2,
            2.9709528289877782e-3,
            8.3217324588632814e-1,
        ),
    ];

    #[test]
    fn against_mpmath_over_the_range() {
        let mut worst = [0.0_f64; 4];
        for &(n, x, j, y, i, k) in MPMATH {
            // J and Y: relative to the modulus sqrt(J² + Y²) (meaningful near zeros)
            let modulus = (j * j + y * y).sqrt();
            let ej = (j_n(n, x) - j).abs()
                / j.abs()
                    .max(1e-300)
                    .max(if n as f64 <= x { modulus } else { 0.0 });
            let ey = (y_n(n, x) - y).abs() / y.abs().max(if n as f64 <= x { modulus } else { 0.0 });
            let ei = rel(i_scaled(n, x), i);
            let ek = rel(k_scaled(n, x), k);
            for (w, e, name) in [
                (0, ej, "J"),
                (1, ey, "Y"),
                (2, ei, "e^-x I"),
                (3, ek, "e^x K"),
            ] {
                worst[w] = worst[w].max(e);
                assert!(e < 1e-13, "{name}_{n}({x}): rel error {e:e}");
            }
        }
        eprintln!(
            "worst errors vs mpmath: J {:e}, Y {:e}, I {:e}, K {:e}",
            worst[0], worst[1], worst[2], worst[3]
        );
    }

    #[test]
    fn wronskians_over_the_range() {
        let xs = [
            1e-3, 0.01, 0.1, 0.5, 1.0, 2.0, 3.7, 7.5, 10.0, 15.0, 25.0, 40.0, 63.0, 100.0, 150.0,
            200.0, 300.0,
        ];
        let mut worst_jy: f64 = 0.0;
        let mut worst_ik: f64 = 0.0;
        for n in 0..=35usize {
            for &x in &xs {
                let j = j_val_der(n, x);
                let y = y_val_der(n, x);
                assert_eq!((j, y), jy_val_der(n, x));
                // Wronskian J Y' − J' Y = 2/(πx); relative to the product of envelopes
                let w = j.value * y.deriv - j.deriv * y.value;
                let want = 2.0 / (PI * x);
                let scale = (j.value.abs() + j.deriv.abs()) * (y.value.abs() + y.deriv.abs());
                let e = (w - want).abs() / scale.max(want);
                worst_jy = worst_jy.max(e);
                let i = i_scaled_val_der(n, x);
                let k = k_scaled_val_der(n, x);
                // (e^{-x}I)(e^{x}K') − (e^{-x}I')(e^{x}K) = −1/x
                let w = i.value * k.deriv - i.deriv * k.value;
                let e = (w + 1.0 / x).abs() * x;
                worst_ik = worst_ik.max(e);
                assert!(
                    worst_jy < 1e-12,
                    "J/Y Wronskian n={n} x={x}: rel error {worst_jy:e}"
                );
                assert!(
                    worst_ik < 1e-12,
                    "I/K Wronskian n={n} x={x}: rel error {worst_ik:e}"
                );
            }
        }
        eprintln!("worst Wronskian errors: J/Y {worst_jy:e}, I/K {worst_ik:e}");
    }
}
