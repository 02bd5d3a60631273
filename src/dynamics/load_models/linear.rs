//! What a load model adds to the linear stability analysis
//! (`dynamics::stability`, paper 5.3).
//!
//! About steady motion at constant joint speed Ω the equations are linear,
//! ẏ = A y, with
//!
//!   y = (q̄, q̄̇, ξ, ξ̇, ζ):
//!
//! the ALE amplitudes q̄ and their rates (the plate's own terms, which
//! `dynamics::stability` assembles), then every model's second-order
//! coordinates ξ, their rates ξ̇ in the same order, and every model's
//! first-order states ζ (each block in registry order). A model declares how
//! many it adds ([`linear_states`](super::LoadModel::linear_states)) and
//! writes its first-order terms — on the modes' rows and columns and on its
//! own — in [`add_linear_terms`](super::LoadModel::add_linear_terms):
//! context in ([`LinearContext`]), outputs out ([`LinearOut`]), as
//! [`evaluate`](super::LoadModel::evaluate) does for the simulation. A model
//! that writes nothing is not part of the linearisation (a delay such as the
//! tool, prescribed forces).
//!
//! The analysis is a map over the friction coefficient μ and the clamp
//! forces of the models whose friction can make the plate squeal; such a
//! model says which values it starts with
//! ([`operating_point`](super::LoadModel::operating_point)).

use crate::dynamics::in_plane::InPlaneDynamics;
use crate::dynamics::node_frame::NodeFrame;
use faer::Mat;

/// The states a model adds to y ([module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LinearStates {
    /// Second-order coordinates ξ, each with its rate ξ̇ (the massive pads' compressions).
    pub coordinates: usize,
    /// First-order states ζ (the lining's patches).
    pub first_order: usize,
}

/// The friction coefficient and clamp forces a scene starts with: the
/// operating point the analysis linearises about unless told otherwise.
#[derive(Debug, Clone, PartialEq)]
pub struct OperatingPoint {
    /// The friction coefficient μ.
    pub friction_coefficient: f64,
    /// A clamp force per clamped body (a pad), N.
    pub clamp_force: Vec<f64>,
}

/// What a model's linearisation sees: the node data the simulation uses and
/// the operating point.
#[derive(Clone, Copy)]
pub struct LinearContext<'a> {
    /// The ALE node frames.
    pub ale_nodes: &'a [NodeFrame],
    /// The in-plane modes after the bending ones (their shapes under the
    /// ALE contacts; None without `plate.in_plane_nodal_diameters`).
    pub in_plane: Option<&'a InPlaneDynamics>,
    /// Modal masses m_i, kg, of every mode: the bending modes, then the in-plane ones.
    pub modal_mass: &'a [f64],
    /// Joint speed Ω, rad/s (held constant).
    pub speed: f64,
    /// The friction coefficient μ of the friction contacts.
    pub friction_coefficient: f64,
    /// The clamp forces of the clamped ones, N.
    pub clamp_force: &'a [f64],
}

/// Where a model's states lie in y: the first index of each of its blocks.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LinearLayout {
    /// The number of modes n: q̄ is y[..n], q̄̇ is y[n..2n].
    pub modes: usize,
    /// Its first coordinate ξ.
    pub coordinates: usize,
    /// The rate ξ̇ of its first coordinate.
    pub rates: usize,
    /// Its first first-order state ζ.
    pub first_order: usize,
}

/// Where a model writes its linearisation: the matrix A of ẏ = A y (its
/// terms added to what is there) and where its own states lie.
pub struct LinearOut<'a> {
    /// A, len(y) × len(y).
    pub a: &'a mut Mat<f64>,
    /// Its states' indices in y.
    pub at: LinearLayout,
}

/// The layout of y for a scene's models: where each model's states lie.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StateLayout {
    /// Per model (in registry order), where its states lie.
    pub models: Vec<LinearLayout>,
    /// The number of modes n.
    pub modes: usize,
    /// All models' coordinates ξ together.
    pub coordinates: usize,
    /// The length of y.
    pub len: usize,
}

impl StateLayout {
    /// The layout of y for `modes` modes and the models' states (each
    /// model's [`linear_states`](super::LoadModel::linear_states), in
    /// registry order).
    pub fn new(states: impl IntoIterator<Item = LinearStates>, modes: usize) -> StateLayout {
        let states: Vec<LinearStates> = states.into_iter().collect();
        let coordinates: usize = states.iter().map(|s| s.coordinates).sum();
        let first_order: usize = states.iter().map(|s| s.first_order).sum();
        let mut at = LinearLayout {
            modes,
            coordinates: 2 * modes,
            rates: 2 * modes + coordinates,
            first_order: 2 * modes + 2 * coordinates,
        };
        let mut layouts = Vec::with_capacity(states.len());
        for s in &states {
            layouts.push(at);
            at.coordinates += s.coordinates;
            at.rates += s.coordinates;
            at.first_order += s.first_order;
        }
        StateLayout {
            models: layouts,
            modes,
            coordinates,
            len: 2 * modes + 2 * coordinates + first_order,
        }
    }

    /// Whether entry `r` of y is a position: an amplitude q̄ or a coordinate ξ
    /// (not a rate, nor a first-order state ζ).
    pub fn is_position(&self, r: usize) -> bool {
        let n = self.modes;
        r < n || (r >= 2 * n && r < 2 * n + self.coordinates)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_s_coordinates_then_their_rates_then_the_first_order_states() {
        let (a, b) = (
            LinearStates {
                coordinates: 2,
                first_order: 3,
            },
            LinearStates {
                coordinates: 4,
                first_order: 1,
            },
        );
        // n = 5: q̄ 0..5, q̄̇ 5..10; ξ: a 10..12, b 12..16; ξ̇: a 16..18,
        // b 18..22; ζ: a 22..25, b 25..26.
        let y = StateLayout::new([a, LinearStates::default(), b], 5);
        assert_eq!(y.len, 26);
        assert_eq!(y.coordinates, 6);
        let at = |coordinates, rates, first_order| LinearLayout {
            modes: 5,
            coordinates,
            rates,
            first_order,
        };
        assert_eq!(y.models, [at(10, 16, 22), at(12, 18, 25), at(12, 18, 25)]);
        let positions: Vec<usize> = (0..y.len).filter(|&r| y.is_position(r)).collect();
        assert_eq!(positions, [0, 1, 2, 3, 4, 10, 11, 12, 13, 14, 15]);
        // Without the models' states: (q̄, q̄̇) alone.
        assert_eq!(StateLayout::new([], 5).len, 10);
    }
}
