//! Shortest round-trip float text for the CSV, byte for byte what Rust's
//! `{:e}` (LowerExp) and `{}` (Display) print, at Żmij's speed (the `zmij`
//! crate, a port of Zverovich's Żmij; about 13 % faster than Ryū here).
//!
//! Both Rust's formatter (Grisu with a Dragon fallback) and Żmij give the
//! shortest digit string that reads back to the same `f64`, the one closest to
//! the exact value; they differ in layout, and when the exact value lies
//! midway between two shortest candidates (the digit generators may round the tie to even, Rust
//! up). [`write_exp`] and [`push_display`] take Żmij's digits and decimal
//! exponent and lay them out as Rust does, and leave the values that can be
//! such a tie (an exact expansion of at most 18 significant digits — never a
//! simulation's amplitudes) to Rust's formatter, so `simulate` writes the
//! same bytes as before
//! (tests/outputs_match_recorded_before_refactor.rs), and the unit tests below
//! compare against `format!` on millions of bit patterns.

/// The shortest decimal of a finite, nonzero |v|: digits d1 d2 … dn (no
/// leading or trailing zero) and E with |v| = d1.d2…dn × 10^E.
struct Decimal {
    digits: [u8; 24],
    n: usize,
    exp: i32,
}

/// Żmij's text of a finite, nonzero |v| in its decimal notation (`123.45`,
/// `1000.0`, `0.00123`: what it prints for 1e-5 ≤ |v| < 1e16) read back into
/// digits and exponent.
fn from_decimal_notation(text: &[u8]) -> Decimal {
    let mut d = Decimal {
        digits: [0; 24],
        n: 0,
        exp: 0,
    };
    let point = text.iter().position(|&c| c == b'.').unwrap_or(text.len());
    let (int, frac) = (&text[..point], text.get(point + 1..).unwrap_or(&[]));
    if int == b"0" {
        let zeros = frac.iter().take_while(|&&c| c == b'0').count();
        let digits = &frac[zeros..];
        d.digits[..digits.len()].copy_from_slice(digits);
        d.n = digits.len();
        d.exp = -(zeros as i32) - 1;
    } else {
        d.digits[..int.len()].copy_from_slice(int);
        d.digits[int.len()..int.len() + frac.len()].copy_from_slice(frac);
        d.n = int.len() + frac.len();
        d.exp = int.len() as i32 - 1;
    }
    while d.n > 1 && d.digits[d.n - 1] == b'0' {
        d.n -= 1;
    }
    d
}

/// Żmij's text in scientific notation (`1.5e-7`, `1e+21`), read back.
fn from_scientific(text: &[u8], e: usize) -> Decimal {
    let mut d = from_decimal_notation(&text[..e]);
    let (negative, digits) = match text[e + 1] {
        b'-' => (true, &text[e + 2..]),
        b'+' => (false, &text[e + 2..]),
        _ => (false, &text[e + 1..]),
    };
    let magnitude = digits
        .iter()
        .fold(0i32, |acc, &c| acc * 10 + (c - b'0') as i32);
    d.exp += if negative { -magnitude } else { magnitude };
    d
}

/// Whether the finite, nonzero `abs` could lie midway between two shortest
/// decimals: its exact value m·2^e has at most 18 significant digits
/// (m' · 5^-e' < 10^18 with m' odd, e' < 0), or it is an integer beyond 2^53.
fn may_tie(abs: f64) -> bool {
    let bits = abs.to_bits();
    let (biased, fraction) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
    let (m, e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    let t = m.trailing_zeros() as i32;
    let (m, e) = (m >> t, e + t);
    if e >= 0 {
        return abs >= 9_007_199_254_740_992.0;
    }
    -e <= 26 && (m as u128) * 5u128.pow(-e as u32) < 1_000_000_000_000_000_000
}

/// The shortest decimal of a finite |v|; `None` for zero.
fn decimal(abs: f64, digits: &mut zmij::Buffer) -> Option<Decimal> {
    if abs == 0.0 {
        return None;
    }
    let text = digits.format_finite(abs).as_bytes();
    Some(match text.iter().position(|&c| c == b'e') {
        Some(e) => from_scientific(text, e),
        None => from_decimal_notation(text),
    })
}

/// Non-finite values as Rust prints them (`NaN`, `inf`, `-inf`); `false` for finite ones.
fn push_non_finite(out: &mut Vec<u8>, v: f64) -> bool {
    if v.is_nan() {
        out.extend_from_slice(b"NaN");
    } else if v.is_infinite() {
        out.extend_from_slice(if v < 0.0 { b"-inf" } else { b"inf" });
    } else {
        return false;
    }
    true
}

/// Bytes [`write_exp`] needs: a sign, 17 digits, the point, `e`, the
/// exponent's sign and three digits (24), rounded up.
pub(crate) const EXP_SLOT: usize = 32;

/// Copy `src` (at most `dst.len()` bytes) to the start of `dst` by two
/// overlapping fixed-size copies (no call to `memcpy` for a 20-byte value).
#[inline]
fn copy_short(dst: &mut [u8], src: &[u8]) {
    let n = src.len();
    if n >= 16 {
        dst[..16].copy_from_slice(&src[..16]);
        dst[n - 16..n].copy_from_slice(&src[n - 16..]);
    } else if n >= 8 {
        dst[..8].copy_from_slice(&src[..8]);
        dst[n - 8..n].copy_from_slice(&src[n - 8..]);
    } else {
        dst[..n].copy_from_slice(src);
    }
}

/// Write `v` as `format!("{v:e}")` would (`0e0`, `-1e0`, `1.5e-7`,
/// `1.2345e2`) at the start of `out`; the length written.
///
/// |v| < 1e-5 or ≥ 1e16 (Żmij's scientific notation, the magnitudes of
/// most amplitudes) is Żmij's text as it is, but for the `+` of a positive
/// exponent: digits without trailing zeros, lowercase `e`, an unpadded
/// exponent. In between, Żmij prints decimal notation, read back into digits
/// and exponent. (Żmij's text is scientific exactly when the shortest
/// decimal's exponent is outside −5..=15; for an `f64` the shortest decimal of
/// a value below the `f64` 1e-5 is below 1e-5, so comparing the `f64` decides.)
pub(crate) fn write_exp(out: &mut [u8; EXP_SLOT], v: f64, digits: &mut zmij::Buffer) -> usize {
    if v.is_nan() {
        return write_exp_rare(out, v);
    }
    out[0] = b'-';
    let at = v.is_sign_negative() as usize;
    let abs = v.abs();
    if abs == 0.0 {
        out[at..at + 3].copy_from_slice(b"0e0");
        return at + 3;
    }
    if !abs.is_finite() || may_tie(abs) {
        return at + write_exp_rare(&mut out[at..], abs);
    }
    let text = digits.format_finite(abs).as_bytes();
    if abs < 1e-5 {
        copy_short(&mut out[at..], text);
        return at + text.len();
    }
    if abs >= 1e16 {
        // `d.ddde+X`: the text without its `+`.
        let e = text.iter().position(|&c| c == b'e').unwrap_or(text.len());
        let mut n = at;
        for &c in text[..=e].iter().chain(&text[e + 2..]) {
            out[n] = c;
            n += 1;
        }
        return n;
    }
    let d = from_decimal_notation(text);
    let mut n = at;
    out[n] = d.digits[0];
    n += 1;
    if d.n > 1 {
        out[n] = b'.';
        out[n + 1..n + d.n].copy_from_slice(&d.digits[1..d.n]);
        n += d.n;
    }
    out[n] = b'e';
    n += 1;
    // The exponent is in −5..=15 here.
    if d.exp < 0 {
        out[n] = b'-';
        n += 1;
    }
    let e = d.exp.unsigned_abs() as u8;
    if e >= 10 {
        out[n] = b'1';
        n += 1;
    }
    out[n] = b'0' + e % 10;
    n + 1
}

/// `{:e}` of NaN, an infinite |v| or a possible tie, by Rust's
/// formatter (rare: not the amplitudes of a simulation's rows).
#[cold]
fn write_exp_rare(out: &mut [u8], v: f64) -> usize {
    use std::io::Write as _;
    let space = out.len();
    let mut rest = &mut out[..];
    let _ = write!(rest, "{v:e}");
    space - rest.len()
}

/// Append `v` as `format!("{v}")` would: no exponent, no trailing `.0`
/// (`0`, `-0`, `11.11111111111111`, `0.0001`, `1000000000000000000000`).
pub(crate) fn push_display(out: &mut Vec<u8>, v: f64, digits: &mut zmij::Buffer) {
    if push_non_finite(out, v) {
        return;
    }
    if v.is_sign_negative() {
        out.push(b'-');
    }
    let abs = v.abs();
    if abs != 0.0 && may_tie(abs) {
        use std::io::Write as _;
        let _ = write!(out, "{abs}");
        return;
    }
    if (1e-5..1e16).contains(&abs) {
        // Żmij's decimal notation is Rust's but for the `.0` of an integer.
        let text = digits.format_finite(abs).as_bytes();
        out.extend_from_slice(text.strip_suffix(b".0").unwrap_or(text));
        return;
    }
    let Some(d) = decimal(abs, digits) else {
        out.push(b'0');
        return;
    };
    let digits = &d.digits[..d.n];
    if d.exp < 0 {
        out.extend_from_slice(b"0.");
        out.resize(out.len() + (-d.exp - 1) as usize, b'0');
        out.extend_from_slice(digits);
    } else {
        let int_len = d.exp as usize + 1;
        if d.n <= int_len {
            out.extend_from_slice(digits);
            out.resize(out.len() + int_len - d.n, b'0');
        } else {
            out.extend_from_slice(&digits[..int_len]);
            out.push(b'.');
            out.extend_from_slice(&digits[int_len..]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Append `v` as `format!("{v:e}")` would: [`write_exp`] on a `Vec`.
    fn push_exp(out: &mut Vec<u8>, v: f64, digits: &mut zmij::Buffer) {
        let mut slot = [0u8; EXP_SLOT];
        let n = write_exp(&mut slot, v, digits);
        out.extend_from_slice(&slot[..n]);
    }

    fn check(v: f64, digits: &mut zmij::Buffer, out: &mut Vec<u8>) {
        out.clear();
        push_exp(out, v, digits);
        assert_eq!(
            std::str::from_utf8(out).unwrap(),
            format!("{v:e}"),
            "{{:e}} of bits {:#x}",
            v.to_bits()
        );
        out.clear();
        push_display(out, v, digits);
        assert_eq!(
            std::str::from_utf8(out).unwrap(),
            format!("{v}"),
            "{{}} of bits {:#x}",
            v.to_bits()
        );
    }

    #[test]
    fn special_values_print_as_rust_does() {
        let (mut digits, mut out) = (zmij::Buffer::new(), Vec::new());
        for v in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            10.0,
            0.1,
            1e-7,
            1.5e-7,
            123.456,
            1e15,
            1e16,
            1e21,
            1e22,
            1e-5,
            1e-6,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::EPSILON,
            11.11111111111111,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.3,
            2.0f64.powi(60),
            9007199254740993.0,
            // Exactly between 1.3948654250235362e15 and …63e15: a digit generator may round to even, Rust up.
            f64::from_bits(0x4313_d27d_a8ac_08c1),
            // Where Żmij's text turns from scientific to decimal notation and back.
            1e-5f64.next_down(),
            1e-5f64.next_up(),
            -1e-5,
            9.99999e-6,
            1e16f64.next_down(),
            1e16f64.next_up(),
            -1e16,
            1.2345678901234567e16,
            9.999999999999998e15,
            -f64::NAN,
        ] {
            check(v, &mut digits, &mut out);
        }
    }

    /// Random bit patterns over the whole `f64` range and values of the
    /// magnitudes a simulation writes (1e-12 … 1e4), both signs.
    #[test]
    fn random_values_print_as_rust_does() {
        let (mut digits, mut out) = (zmij::Buffer::new(), Vec::new());
        let mut x: u64 = 0x9e37_79b9_7f4a_7c15;
        for i in 0..400_000u32 {
            // xorshift64*
            x ^= x >> 12;
            x ^= x << 25;
            x ^= x >> 27;
            let r = x.wrapping_mul(0x2545_f491_4f6c_dd1d);
            check(f64::from_bits(r), &mut digits, &mut out);
            let scaled = (r >> 11) as f64 / (1u64 << 53) as f64 * 10f64.powi((i % 17) as i32 - 12);
            check(
                if i % 2 == 0 { scaled } else { -scaled },
                &mut digits,
                &mut out,
            );
            // Short decimals and large integers with fractions (where ties
            // between two shortest candidates are).
            check((r % 100_000) as f64 / 1000.0, &mut digits, &mut out);
            check(
                (r >> 10) as f64 + 0.25 * (r % 4) as f64,
                &mut digits,
                &mut out,
            );
            check(
                f64::from_bits(0x4313_d27d_a8ac_08c1) + (r % 64) as f64,
                &mut digits,
                &mut out,
            );
        }
    }
}
