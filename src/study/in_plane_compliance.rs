//! The in-plane load case (the ALE nodes' in-plane forces, read at the
//! first) and the static response there as the in-plane response axis
//! (src/study/in_plane_response.rs) reads it: per retained ⟨k, l⟩ (one
//! entry per family, a cos/sin pair for k ≥ 1) its share X(a) Y(b) / (ω² m)
//! of the compliance between the read node a and each loaded node b (module
//! doc of src/model/in_plane/residual.rs), with the modes' point values or
//! their load-patch means, and the residual of the modes a set leaves out.

use super::response::nested_tail;
use crate::config::{Config, NodePosition};
use crate::model::in_plane::{
    modal_kernel, residual_kernel, InPlaneDiscretisation, InPlaneKernel, InPlaneMode,
    InPlanePatchHarmonics, LoadPatch,
};
use serde::Serialize;
use std::f64::consts::TAU;

/// Where the in-plane response is read and which forces act.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InPlaneLoadCase {
    /// ξ of the point read (the first ALE node with an in-plane force).
    pub point: NodePosition,
    /// 1-based ALE node number of that point.
    pub ale_node: usize,
    /// The ALE nodes with in-plane forces and their (F_r, F_θ), N.
    pub loads: Vec<(NodePosition, [f64; 2])>,
    /// Half-width c of the nodes' load patches
    /// (`PlateConfig::residual_patch_half_width`), m.
    pub patch_half_width_m: f64,
}

/// The ALE nodes' in-plane forces (F_r, F_θ), read at the first.
pub(crate) fn load_case(config: &Config) -> Option<InPlaneLoadCase> {
    let loads: Vec<(usize, NodePosition, [f64; 2])> = (0..config.nodes.ale.len())
        .filter_map(|j| {
            let w = config.loads.ale.get(j).copied().unwrap_or_default();
            let xi = config.nodes.ale[j];
            let (s, c) = (xi.angular * TAU).sin_cos();
            let polar = [
                c * w.force[0] + s * w.force[1],
                -s * w.force[0] + c * w.force[1],
            ];
            (w.force[0] != 0.0 || w.force[1] != 0.0).then_some((j, xi, polar))
        })
        .collect();
    let &(j, point, _) = loads.first()?;
    Some(InPlaneLoadCase {
        point,
        ale_node: j + 1,
        loads: loads.iter().map(|&(_, xi, f)| (xi, f)).collect(),
        patch_half_width_m: config.plate.residual_patch_half_width(),
    })
}

/// A predicate on ⟨k, l⟩: the modes a set retains.
pub(crate) type Keep<'a> = &'a dyn Fn(u32, u32) -> bool;

/// The modes' shares of the response at the read node and the static series.
pub(crate) struct InPlaneStatics<'a> {
    case: &'a InPlaneLoadCase,
    modes: Vec<InPlaneMode>,
    /// The read node's patch, then each load's.
    patches: Vec<LoadPatch>,
    harmonics: InPlanePatchHarmonics,
    /// Per mode its (u_r, u_θ) at the read node with point values.
    point: Vec<[f64; 2]>,
    /// The same with patch means.
    patch: Vec<[f64; 2]>,
}

impl<'a> InPlaneStatics<'a> {
    /// The shares of `modes` on `disc` under `case`.
    pub(crate) fn new(
        disc: &InPlaneDiscretisation,
        modes: Vec<InPlaneMode>,
        case: &'a InPlaneLoadCase,
    ) -> Self {
        let patches = patches(disc, case);
        let (ra, rb) = (patches[0].centre, |b: usize| patches[b + 1].centre);
        let point = modes
            .iter()
            .map(|m| respond(case, |b| point_kernel(m, ra, rb(b))))
            .collect();
        let patch = modes
            .iter()
            .map(|m| {
                respond(case, |b| {
                    let one = std::slice::from_ref(m);
                    let (pa, pb) = (&patches[0], &patches[b + 1]);
                    modal_kernel(one, pa, pb, m.k as usize + 1, |_, _| false)
                })
            })
            .collect();
        InPlaneStatics {
            case,
            harmonics: disc.patch_harmonics(&patches),
            modes,
            patches,
            point,
            patch,
        }
    }

    /// The retained modes' response, with point values or patch means, m.
    pub(crate) fn modal(&self, keep: Keep, patch_means: bool) -> [f64; 2] {
        let values = if patch_means {
            &self.patch
        } else {
            &self.point
        };
        self.modes
            .iter()
            .zip(values)
            .filter(|(m, _)| keep(m.k, m.l))
            .fold([0.0; 2], |s, (_, v)| add(s, *v))
    }

    /// The residual of the modes the set leaves out, m.
    pub(crate) fn residual(&self, keep: Keep) -> [f64; 2] {
        let kept: Vec<InPlaneMode> = self
            .modes
            .iter()
            .filter(|m| keep(m.k, m.l))
            .cloned()
            .collect();
        respond(self.case, |b| {
            residual_kernel(&self.harmonics, &kept, 0, b + 1)
        })
    }

    /// The static series of `disc` (another discretisation of the same
    /// plate) over the same patches, m.
    pub(crate) fn static_series(&self, disc: &InPlaneDiscretisation) -> [f64; 2] {
        let h = disc.patch_harmonics(&self.patches);
        respond(self.case, |b| h.kernel(0, b + 1))
    }

    /// The in-plane modes in the set (a cos/sin pair counts two).
    pub(crate) fn count(&self, keep: Keep) -> usize {
        let pair = |m: &InPlaneMode| if m.k == 0 { 1 } else { 2 };
        self.modes.iter().filter(|m| keep(m.k, m.l)).map(pair).sum()
    }
}

/// The read node's load patch, then each load's.
fn patches(disc: &InPlaneDiscretisation, case: &InPlaneLoadCase) -> Vec<LoadPatch> {
    let (ri, ra) = (disc.plate().inner_radius, disc.plate().outer_radius);
    std::iter::once(case.point)
        .chain(case.loads.iter().map(|&(xi, _)| xi))
        .map(|xi| LoadPatch::new(ri, ra, ri + xi.radial * (ra - ri), case.patch_half_width_m))
        .collect()
}

/// The compliance of one mode with point values at radii a and b.
fn point_kernel(m: &InPlaneMode, ra: f64, rb: f64) -> InPlaneKernel {
    let (a, b) = (m.eval(ra), m.eval(rb));
    let mut coefficients = vec![[0.0; 4]; m.k as usize + 1];
    let s = 1.0 / (m.omega * m.omega * m.modal_mass);
    coefficients[m.k as usize] = [s * a.u * b.u, s * a.u * b.v, s * a.v * b.u, s * a.v * b.v];
    InPlaneKernel { coefficients }
}

/// Σ over the loads b of C_b(θ_a − θ_b) (F_r, F_θ)_b at the read node a.
fn respond(case: &InPlaneLoadCase, kernel: impl Fn(usize) -> InPlaneKernel) -> [f64; 2] {
    let theta = |xi: NodePosition| xi.angular * TAU;
    let mut u = [0.0; 2];
    for (b, &(xi, f)) in case.loads.iter().enumerate() {
        let c = kernel(b).at(theta(case.point) - theta(xi));
        u[0] += c[0][0] * f[0] + c[0][1] * f[1];
        u[1] += c[1][0] * f[0] + c[1][1] * f[1];
    }
    u
}

/// The nested sets' uncertainty (src/study/in_plane_response.rs): the larger of the two
/// components' estimated tails, relative to |u_ref|.
pub(crate) fn nested_uncertainty(nested: &[((u32, u32), [f64; 2])]) -> (f64, String) {
    let norm = nested[2].1[0].hypot(nested[2].1[1]);
    let tail = |c: usize| {
        nested_tail(
            nested[1].1[c] - nested[0].1[c],
            nested[2].1[c] - nested[1].1[c],
        )
    };
    let ((tr, mr), (tt, mt)) = (tail(0), tail(1));
    if tr > tt {
        (tr / norm, format!("{mr} (of u_r, the larger)"))
    } else {
        (tt / norm, format!("{mt} (of u_θ, the larger)"))
    }
}

/// a + b.
pub(crate) fn add(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] + b[0], a[1] + b[1]]
}

/// |u − u_ref| / |u_ref| (Euclidean norms).
pub(crate) fn relative(u: [f64; 2], reference: [f64; 2]) -> f64 {
    (u[0] - reference[0]).hypot(u[1] - reference[1]) / reference[0].hypot(reference[1])
}
