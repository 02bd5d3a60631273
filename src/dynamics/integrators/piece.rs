//! The exponential tables of one piece of a piecewise-smooth system
//! ẏ = f(y), linearised on it: f(y) ≈ f(y_r) + J (y − y_r), with its
//! switching functions s(y) ≈ s(y_r) + S (y − y_r) (docs/dynamics.md, "Stiff
//! contacts").
//!
//! On the piece the solution from y_r is y(t) = y_r + F(t) f(y_r) with
//! F(t) = ∫₀ᵗ e^{τJ} dτ = t φ₁(tJ), and E(t) = e^{tJ} = I + J F(t); a forcing
//! growing linearly from 0 adds G(t) = ∫₀ᵗ e^{(t−s)J} s ds = t² φ₂(tJ), one
//! growing as s²/2 adds H(t) = ∫₀ᵗ e^{(t−s)J} s²/2 ds = t³ φ₃(tJ). The
//! tables hold E, F, G and H at the dyadic fractions τ_j = h / 2^j of the step (j = 0..=L)
//! and S F(i τ_m) at the m-th level's sample times, so that a step, a
//! sample of the switching functions or a bisection of a switching instant
//! costs matrix–vector products only.
//!
//! Construction (scaling and squaring): J is balanced by a diagonal
//! similarity of powers of two (Parlett–Reinsch), so that ρ = ‖D⁻¹JD‖₁ is of
//! the order of the fastest rate; at the finest level τ ρ ≤ 1/8 and φ₁ is its
//! Taylor series to degree 10 (remainder below 2e-19); the coarser levels
//! follow from F(2τ) = (I + E(τ)) F(τ), G(2τ) = (I + E(τ)) G(τ) + τ F(τ),
//! H(2τ) = (I + E(τ)) H(τ) + τ G(τ) + τ²/2 F(τ), E(2τ) = E(τ)² (φ₃ by its
//! own Taylor series, so that E, F and G are the same bits with or without
//! H). Each level is exact
//! to rounding for any stiffness: a contact a thousand times stiffer only
//! adds squarings (one per factor two in ρ h).

/// The Taylor degree of φ₁ at the finest level (‖τJ‖ ≤ 1/8).
const TAYLOR_DEGREE: usize = 10;
/// ‖τ_L J‖₁ (balanced) at the finest level.
const FINEST_NORM: f64 = 0.125;
/// The switching functions are sampled every quarter radian of the piece's
/// fastest rate ρ: a contact that closes and opens again faster is not seen
/// (measured on config/brake_squeal_paper.yaml's chattering contacts: one
/// radian misses enough brief contacts to leave 1e-2, a quarter 2.6e-5 and a
/// twentieth 2e-6 of the peak against the converged reference).
pub(crate) const SAMPLE_ANGLE: f64 = 0.25;
/// Most samples in a piece's sample table, 2^8 per step: a piece whose
/// fastest rate needs finer samples has no table and is scanned along its
/// flow at its own sample level (which the stored levels always reach).
pub(crate) const MAX_TABLE_LEVEL: usize = 8;

/// The tables of one piece (see the module docs); buffers allocated once.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct PieceTables {
    n: usize,
    ns: usize,
    /// Dyadic levels stored: τ_j = h / 2^j for j = 0..levels.
    levels: usize,
    /// J (n × n, row-major) and S (ns × n).
    pub(crate) jac: Vec<f64>,
    pub(crate) s_rows: Vec<f64>,
    e: Vec<f64>,
    f: Vec<f64>,
    /// G(τ_j) = ∫₀^τ e^{(τ−s)J} s ds = τ² φ₂(τJ): the response to a
    /// forcing that grows linearly from 0.
    g: Vec<f64>,
    /// H(τ_j) = ∫₀^τ e^{(τ−s)J} s²/2 ds = τ³ φ₃(τJ): the response to a
    /// forcing that grows as s²/2 from 0.
    h: Vec<f64>,
    /// m: the switching functions are sampled every τ_m.
    sample_level: usize,
    /// |λ|max of J (estimated): the fastest rate of the piece, 1/s.
    rate: f64,
    /// S F(i τ_m) for i = 1..=2^m, each ns × n.
    sf: Vec<f64>,
    /// Whether `sf` and `bound` are filled for the current J (a piece kept
    /// for one step only samples its flow instead: filling them costs
    /// 2^(m+1) ns n² against ns n + 2n² per sample taken).
    sampled: bool,
    /// Per switching function, twice the largest ‖row of S F(i τ_m)‖₂ over
    /// the samples: |s(t) − s(0)| ≤ bound ‖f‖₂ along the step (between the
    /// samples the factor two covers e^{τ_m ρ/2} ≤ e^{1/8}).
    bound: Vec<f64>,
}

/// Scratch of [`PieceTables::build`], allocated once for n.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct BuildScratch {
    a: Vec<f64>,
    d: Vec<f64>,
    e: Vec<f64>,
    f: Vec<f64>,
    g_level: Vec<f64>,
    h_level: Vec<f64>,
    p: Vec<f64>,
    t1: Vec<f64>,
    t2: Vec<f64>,
    g: Vec<f64>,
    g2: Vec<f64>,
}

impl BuildScratch {
    pub(crate) fn new(n: usize, ns: usize) -> BuildScratch {
        BuildScratch {
            a: vec![0.0; n * n],
            d: vec![1.0; n],
            e: vec![0.0; n * n],
            f: vec![0.0; n * n],
            g_level: vec![0.0; n * n],
            h_level: vec![0.0; n * n],
            p: vec![0.0; n * n],
            t1: vec![0.0; n * n],
            t2: vec![0.0; n * n],
            g: vec![0.0; ns * n],
            g2: vec![0.0; ns * n],
        }
    }
}

impl PieceTables {
    /// Tables for n unknowns, ns switching functions and `levels` dyadic levels.
    pub(crate) fn new(n: usize, ns: usize, levels: usize) -> PieceTables {
        PieceTables {
            n,
            ns,
            levels,
            jac: vec![0.0; n * n],
            s_rows: vec![0.0; ns * n],
            e: Vec::new(),
            f: Vec::new(),
            g: Vec::new(),
            h: Vec::new(),
            sample_level: 0,
            rate: 0.0,
            sf: Vec::new(),
            sampled: false,
            bound: vec![0.0; ns],
        }
    }

    /// E(τ_j), n × n.
    #[cfg(test)]
    pub(crate) fn e(&self, j: usize) -> &[f64] {
        let nn = self.n * self.n;
        &self.e[j * nn..(j + 1) * nn]
    }

    /// F(τ_j), n × n.
    pub(crate) fn f(&self, j: usize) -> &[f64] {
        let nn = self.n * self.n;
        &self.f[j * nn..(j + 1) * nn]
    }

    /// G(τ_j) = τ_j² φ₂(τ_j J), n × n.
    pub(crate) fn g(&self, j: usize) -> &[f64] {
        let nn = self.n * self.n;
        &self.g[j * nn..(j + 1) * nn]
    }

    /// H(τ_j) = τ_j³ φ₃(τ_j J), n × n.
    pub(crate) fn h(&self, j: usize) -> &[f64] {
        let nn = self.n * self.n;
        &self.h[j * nn..(j + 1) * nn]
    }

    /// |λ|max of J (estimated), 1/s.
    pub(crate) fn rate(&self) -> f64 {
        self.rate
    }

    /// m: samples every τ_m, 2^m of them per step.
    pub(crate) fn sample_level(&self) -> usize {
        self.sample_level
    }

    /// Whether the samples τ_m of a step h are within [`SAMPLE_ANGLE`] of
    /// the piece's fastest rate (the stored levels may stop short of it).
    pub(crate) fn samples_every_quarter_radian(&self, h: f64) -> bool {
        h / (self.sample_level as f64).exp2() * self.rate <= SAMPLE_ANGLE
    }

    /// S F(i τ_m), ns × n, for i = 1..=2^m.
    pub(crate) fn sampled(&self, i: usize) -> &[f64] {
        let size = self.ns * self.n;
        &self.sf[(i - 1) * size..i * size]
    }

    /// [`PieceTables::bound`] of each switching function.
    pub(crate) fn bound(&self) -> &[f64] {
        &self.bound
    }

    /// Whether the sample table and the bounds are filled for this piece.
    pub(crate) fn has_samples(&self) -> bool {
        self.sampled
    }

    /// Fill the tables from `jac` and `s_rows` (already set) for a step h.
    /// The sample table grows to the first piece that needs it (then no
    /// allocation).
    pub(crate) fn build(&mut self, h: f64, b: &mut BuildScratch) {
        let n = self.n;
        // The levels' storage is taken at a slot's first piece (a cache of
        // many slots costs memory only for the pieces a scene visits).
        self.e.resize(self.levels * n * n, 0.0);
        self.f.resize(self.levels * n * n, 0.0);
        self.g.resize(self.levels * n * n, 0.0);
        self.h.resize(self.levels * n * n, 0.0);
        b.a.copy_from_slice(&self.jac);
        balance(&mut b.a, &mut b.d, n);
        let rho = norm1(&b.a, n);
        let finest = finest_level(h, rho, self.levels - 1);
        self.sampled = false;
        let tau = h / (finest as f64).exp2();
        taylor_phi(tau, n, b);
        for level in (0..=finest).rev() {
            if level < self.levels {
                self.store(level, b);
            }
            if level > 0 {
                double(b, n, h / (level as f64).exp2());
            }
        }
        self.rate = spectral_radius(&b.a, n, &mut b.t1, &mut b.t2);
        self.sample_level = sample_level(h, self.rate, self.levels - 1);
    }

    /// Fill S F(i τ_m) and the bounds (ns n² per sample) where the piece
    /// samples at most 2^[`MAX_TABLE_LEVEL`] times a step (else it is
    /// scanned along its flow). The table grows to the first piece that
    /// needs it (then no allocation).
    pub(crate) fn fill_sample_table(&mut self, b: &mut BuildScratch) {
        if self.sample_level > MAX_TABLE_LEVEL {
            return;
        }
        let size = (1usize << self.sample_level) * self.ns * self.n;
        if self.sf.len() < size {
            self.sf.resize(size, 0.0);
        }
        self.fill_samples(b);
        self.sampled = true;
    }

    /// Level j of the balanced E, F back in the original coordinates:
    /// X_ik = d_i X̂_ik / d_k.
    fn store(&mut self, j: usize, b: &BuildScratch) {
        let n = self.n;
        let nn = n * n;
        for i in 0..n {
            for k in 0..n {
                let s = b.d[i] / b.d[k];
                let at = j * nn + i * n + k;
                self.e[at] = s * b.e[i * n + k];
                self.f[at] = s * b.f[i * n + k];
                self.g[at] = s * b.g_level[i * n + k];
                self.h[at] = s * b.h_level[i * n + k];
            }
        }
    }

    /// S F(i τ_m) by F((i+1)τ) = F(iτ) + E(iτ) F(τ): G = S E(iτ) carried along.
    fn fill_samples(&mut self, b: &mut BuildScratch) {
        let (n, ns, m) = (self.n, self.ns, self.sample_level);
        let size = ns * n;
        if size == 0 {
            return;
        }
        b.g[..size].copy_from_slice(&self.s_rows);
        let mut acc_start = 0;
        for i in 1..=(1usize << m) {
            let (done, rest) = self.sf.split_at_mut(acc_start);
            let out = &mut rest[..size];
            matmul_rect(
                &b.g[..size],
                &self.f[m * n * n..(m + 1) * n * n],
                out,
                ns,
                n,
            );
            if i > 1 {
                for (o, prev) in out.iter_mut().zip(&done[acc_start - size..acc_start]) {
                    *o += prev;
                }
            }
            matmul_rect(
                &b.g[..size],
                &self.e[m * n * n..(m + 1) * n * n],
                &mut b.g2[..size],
                ns,
                n,
            );
            std::mem::swap(&mut b.g, &mut b.g2);
            acc_start += size;
        }
        self.bound.iter_mut().for_each(|v| *v = 0.0);
        for sample in self.sf[..acc_start].chunks_exact(size) {
            for (b, row) in self.bound.iter_mut().zip(sample.chunks_exact(n)) {
                let norm = row.iter().map(|v| v * v).sum::<f64>().sqrt();
                *b = b.max(2.0 * norm);
            }
        }
    }
}

/// The finest level: at least `levels_needed`, and τ ρ ≤ 1/8.
fn finest_level(h: f64, rho: f64, levels_needed: usize) -> usize {
    let mut level = levels_needed;
    while h / (level as f64).exp2() * rho > FINEST_NORM && level < 1000 {
        level += 1;
    }
    level
}

/// m with τ_m ρ ≤ [`SAMPLE_ANGLE`], at most the stored levels (which
/// `ContactExponential::levels_for` makes fine enough for the scene's rates).
fn sample_level(h: f64, rho: f64, max_level: usize) -> usize {
    let mut m = 0;
    while h / (m as f64).exp2() * rho > SAMPLE_ANGLE && m < max_level {
        m += 1;
    }
    m
}

/// At the finest level: φ₂(X) = Σ X^k/(k+2)! by Horner, φ₁ = I + X φ₂,
/// E = I + X φ₁ (X = τA); F = τ φ₁ into `b.f`, E into `b.e`, G = τ² φ₂
/// into `b.g_level`; φ₃(X) = Σ X^k/(k+3)! by its own Horner, H = τ³ φ₃ into
/// `b.h_level`.
fn taylor_phi(tau: f64, n: usize, b: &mut BuildScratch) {
    let (x, t) = (&mut b.t2, &mut b.t1);
    for (xi, ai) in x.iter_mut().zip(&b.a) {
        *xi = tau * ai;
    }
    let p = &mut b.p;
    nested_series(x, p, t, n, 2);
    // φ₂ = p; φ₁ = I + X φ₂; E = I + X φ₁.
    let x = &b.t2;
    let t = &mut b.t1;
    matmul(x, p, t, n);
    set_identity(&mut b.f, n);
    for (fi, ti) in b.f.iter_mut().zip(t.iter()) {
        *fi += ti;
    }
    matmul(x, &b.f, t, n);
    set_identity(&mut b.e, n);
    for (ei, ti) in b.e.iter_mut().zip(t.iter()) {
        *ei += ti;
    }
    b.f.iter_mut().for_each(|v| *v *= tau);
    for (g, p) in b.g_level.iter_mut().zip(&b.p) {
        *g = tau * tau * p;
    }
    // The same nesting with (k + 3) gives 2 φ₃ (its last factor is 1/3, not 1/3!).
    nested_series(&b.t2, &mut b.p, &mut b.t1, n, 3);
    for (h, p) in b.h_level.iter_mut().zip(&b.p) {
        *h = 0.5 * tau * tau * tau * p;
    }
}

/// p ← the nested form p = (I + X p)/(k + first) for k = D−1 … 0 from
/// p = I/(D + first), D = [`TAYLOR_DEGREE`] (first = 2: φ₂(X); 3: 2 φ₃(X));
/// `t` scratch.
fn nested_series(x: &[f64], p: &mut [f64], t: &mut [f64], n: usize, first: usize) {
    set_identity(p, n);
    p.iter_mut()
        .for_each(|v| *v /= (TAYLOR_DEGREE + first) as f64);
    for k in (0..TAYLOR_DEGREE).rev() {
        matmul(x, p, t, n);
        set_identity(p, n);
        let inv = 1.0 / (k + first) as f64;
        for (pi, ti) in p.iter_mut().zip(t.iter()) {
            *pi = inv * (*pi + ti);
        }
    }
}

/// From span t to 2t: H(2t) = (I + E) H + t G + t²/2 F,
/// G(2t) = (I + E) G + t F, F(2t) = (I + E) F, E(2t) = E² (G over [t, 2t]:
/// ∫₀ᵗ e^{(t−u)J} (t + u) du = t F + G; H: ∫₀ᵗ e^{(t−u)J} (t + u)²/2 du =
/// t²/2 F + t G + H).
fn double(b: &mut BuildScratch, n: usize, t: f64) {
    matmul(&b.e, &b.h_level, &mut b.t1, n);
    for (((h, eh), g), f) in b.h_level.iter_mut().zip(&b.t1).zip(&b.g_level).zip(&b.f) {
        *h += eh + t * g + 0.5 * t * t * f;
    }
    matmul(&b.e, &b.g_level, &mut b.t1, n);
    for ((g, eg), f) in b.g_level.iter_mut().zip(&b.t1).zip(&b.f) {
        *g += eg + t * f;
    }
    matmul(&b.e, &b.f, &mut b.t1, n);
    for (f, ef) in b.f.iter_mut().zip(&b.t1) {
        *f += ef;
    }
    matmul(&b.e, &b.e, &mut b.t1, n);
    b.e.copy_from_slice(&b.t1);
}

/// |λ|max of A by the power iteration's growth ‖A^k v‖^(1/k) over 2 × 16
/// products (complex pairs make single ratios oscillate), at least a tenth
/// of ‖A‖₁ / n against a start orthogonal to the dominant vector.
fn spectral_radius(a: &[f64], n: usize, v: &mut [f64], w: &mut [f64]) -> f64 {
    for (i, x) in v[..n].iter_mut().enumerate() {
        *x = 1.0 + 0.1 * i as f64;
    }
    let norm = |x: &[f64]| x.iter().map(|v| v * v).sum::<f64>().sqrt();
    let mut log_growth = 0.0;
    let rounds = 32;
    for k in 0..rounds {
        let before = norm(&v[..n]);
        for x in v[..n].iter_mut() {
            *x /= before;
        }
        for i in 0..n {
            w[i] = (0..n).map(|j| a[i * n + j] * v[j]).sum();
        }
        v[..n].copy_from_slice(&w[..n]);
        if k >= rounds / 2 {
            log_growth += norm(&v[..n]).max(f64::MIN_POSITIVE).ln();
        }
    }
    let rate = (log_growth / (rounds / 2) as f64).exp();
    rate.max(0.1 * norm1(a, n) / n as f64)
}

fn set_identity(m: &mut [f64], n: usize) {
    m.iter_mut().for_each(|v| *v = 0.0);
    for i in 0..n {
        m[i * n + i] = 1.0;
    }
}

/// out = a b, all n × n row-major.
pub(crate) fn matmul(a: &[f64], b: &[f64], out: &mut [f64], n: usize) {
    matmul_rect(a, b, out, n, n);
}

/// out = a b with a rows × n, b n × n (row-major).
fn matmul_rect(a: &[f64], b: &[f64], out: &mut [f64], rows: usize, n: usize) {
    out.iter_mut().for_each(|v| *v = 0.0);
    for i in 0..rows {
        let row = &mut out[i * n..(i + 1) * n];
        for k in 0..n {
            let aik = a[i * n + k];
            if aik != 0.0 {
                for (o, bk) in row.iter_mut().zip(&b[k * n..(k + 1) * n]) {
                    *o += aik * bk;
                }
            }
        }
    }
}

/// out += m x with m rows × n.
#[inline]
pub(crate) fn mul_add(m: &[f64], x: &[f64], out: &mut [f64]) {
    let n = x.len();
    for (o, row) in out.iter_mut().zip(m.chunks_exact(n)) {
        *o += row.iter().zip(x).map(|(a, b)| a * b).sum::<f64>();
    }
}

/// ‖A‖₁: the largest column sum of |A_ik|.
fn norm1(a: &[f64], n: usize) -> f64 {
    (0..n)
        .map(|k| (0..n).map(|i| a[i * n + k].abs()).sum::<f64>())
        .fold(0.0, f64::max)
}

/// Parlett–Reinsch balancing in place: A ← D⁻¹ A D with D = diag(d), powers
/// of two, so that each row and column have comparable norms.
fn balance(a: &mut [f64], d: &mut [f64], n: usize) {
    d.iter_mut().for_each(|v| *v = 1.0);
    for _ in 0..32 {
        let mut converged = true;
        for i in 0..n {
            let (mut c, mut r) = (0.0, 0.0);
            for k in (0..n).filter(|&k| k != i) {
                c += a[k * n + i].abs();
                r += a[i * n + k].abs();
            }
            if c == 0.0 || r == 0.0 || !(c.is_finite() && r.is_finite()) {
                continue;
            }
            let s = c + r;
            let mut scale = 1.0;
            while c < 0.5 * r {
                c *= 2.0;
                r *= 0.5;
                scale *= 2.0;
            }
            while c >= 2.0 * r {
                c *= 0.5;
                r *= 2.0;
                scale *= 0.5;
            }
            if (c + r) < 0.95 * s * scale && scale != 1.0 {
                converged = false;
                d[i] *= scale;
                for k in 0..n {
                    a[i * n + k] /= scale;
                    a[k * n + i] *= scale;
                }
            }
        }
        if converged {
            break;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The undamped oscillator ẍ = −ω² x: E(t) = [[cos, sin/ω], [−ω sin, cos]],
    /// F(t) = [[sin/ω, (1 − cos)/ω²], [cos − 1, sin/ω]], G(t) = [[(1 − cos)/ω²,
    /// (ωt − sin)/ω³], [−(ωt − sin)/ω, (1 − cos)/ω²]].
    #[test]
    fn tables_of_a_stiff_oscillator_are_its_exact_rotation_at_every_level() {
        let omega = 3.0e4; // hω = 30 at h = 1 ms: far beyond any explicit step
        let mut t = PieceTables::new(2, 1, 12);
        t.jac.copy_from_slice(&[0.0, 1.0, -omega * omega, 0.0]);
        t.s_rows.copy_from_slice(&[1.0, 0.0]);
        let h = 1.0e-3;
        let mut b = BuildScratch::new(2, 1);
        t.build(h, &mut b);
        t.fill_sample_table(&mut b);
        for j in 0..12 {
            let tau = h / (j as f64).exp2();
            let (s, c) = (omega * tau).sin_cos();
            let e = [c, s / omega, -omega * s, c];
            let f = [s / omega, (1.0 - c) / (omega * omega), c - 1.0, s / omega];
            // G(t) = ∫₀ᵗ e^{(t−s)J} s ds, written out from E.
            let wt = omega * tau;
            let g = [
                (1.0 - c) / (omega * omega),
                (wt - s) / omega.powi(3),
                -(wt - s) / omega,
                (1.0 - c) / (omega * omega),
            ];
            // H(t) = Σ_k J^k t^(k+3)/(k+3)! with J² = −ω²: a I + b J.
            let a = (wt - s) / omega.powi(3);
            let bj = (0.5 * wt * wt - 1.0 + c) / omega.powi(4);
            let hh = [a, bj, -omega * omega * bj, a];
            let scale = [1.0, 1.0 / omega, omega, 1.0];
            for i in 0..4 {
                let err_h = (t.h(j)[i] - hh[i]).abs() / scale[i] * omega.powi(3) / (1.0 + wt * wt);
                assert!(err_h < 1e-12, "H level {j} entry {i}: {err_h:e}");
                let err_e = (t.e(j)[i] - e[i]).abs() / scale[i];
                let err_f = (t.f(j)[i] - f[i]).abs() / scale[i] * omega;
                let err_g = (t.g(j)[i] - g[i]).abs() / scale[i] * omega * omega;
                assert!(
                    err_e < 1e-12 && err_f < 1e-12 && err_g < 1e-12,
                    "level {j} entry {i}: {err_e:e} {err_f:e} {err_g:e}"
                );
            }
        }
        // Sampled every τ_m with τ_m ω ≤ 1: S F(i τ_m) = the first row of F(i τ_m).
        let m = t.sample_level();
        assert!(h / (m as f64).exp2() * omega <= 2.0 * SAMPLE_ANGLE);
        for i in 1..=(1usize << m) {
            let ti = i as f64 * h / (m as f64).exp2();
            let (s, c) = (omega * ti).sin_cos();
            let want = [s / omega, (1.0 - c) / (omega * omega)];
            let got = t.sampled(i);
            assert!((got[0] - want[0]).abs() * omega < 1e-11, "{i}");
            assert!((got[1] - want[1]).abs() * omega * omega < 1e-11, "{i}");
        }
    }

    /// A damped, gyroscopically coupled pair against the matrix exponential
    /// summed term by term at a small step (an independent route).
    #[test]
    fn tables_match_the_exponential_series_for_a_nonnormal_badly_scaled_matrix() {
        let j = [
            0.0, 0.0, 1.0, 0.0, //
            0.0, 0.0, 0.0, 1.0, //
            -4.0e6, 1.0e5, -20.0, -300.0, //
            -2.0e5, -9.0e6, 300.0, -35.0,
        ];
        let mut t = PieceTables::new(4, 2, 4);
        t.jac.copy_from_slice(&j);
        t.s_rows
            .copy_from_slice(&[1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0]);
        let h = 2.0e-3;
        t.build(h, &mut BuildScratch::new(4, 2));
        // Series at h / 2^20, then 20 doublings, each in f64: a separate path.
        let steps = 20;
        let tau = h / (steps as f64).exp2();
        let mut e = [0.0; 16];
        let mut f = [0.0; 16];
        let mut term = [0.0; 16];
        for i in 0..4 {
            term[i * 4 + i] = 1.0;
        }
        for k in 0..30 {
            for i in 0..16 {
                e[i] += term[i];
                f[i] += tau * term[i] / (k + 1) as f64;
            }
            let mut next = [0.0; 16];
            matmul(&j, &term, &mut next, 4);
            for v in next.iter_mut() {
                *v *= tau / (k + 1) as f64;
            }
            term = next;
        }
        for _ in 0..steps {
            let mut ef = [0.0; 16];
            matmul(&e, &f, &mut ef, 4);
            for i in 0..16 {
                f[i] += ef[i];
            }
            let mut ee = [0.0; 16];
            matmul(&e, &e, &mut ee, 4);
            e = ee;
        }
        let big = e.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for i in 0..16 {
            assert!(
                (t.e(0)[i] - e[i]).abs() < 1e-9 * big,
                "E[{i}] {} vs {}",
                t.e(0)[i],
                e[i]
            );
            let fb = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            assert!(
                (t.f(0)[i] - f[i]).abs() < 1e-9 * fb,
                "F[{i}] {} vs {}",
                t.f(0)[i],
                f[i]
            );
        }
    }
}
