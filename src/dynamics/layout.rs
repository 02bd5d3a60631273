//! Which modes are axisymmetric and which form cos/sin pairs.

use crate::model::PlateModel;

/// A cos/sin mode pair with the same ⟨k, l⟩.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ModePair {
    pub k: u32,
    pub cos: usize,
    pub sin: usize,
}

/// Which modes are axisymmetric and which form pairs (indices into the mode table).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ModeLayout {
    pub axisymmetric: Vec<usize>,
    pub pairs: Vec<ModePair>,
    pub k_max: u32,
}

impl ModeLayout {
    pub fn new(model: &PlateModel) -> ModeLayout {
        let mut layout = ModeLayout::default();
        for (i, m) in model.modes().iter().enumerate() {
            layout.k_max = layout.k_max.max(m.k);
            match (m.k, m.partner) {
                (0, _) => layout.axisymmetric.push(i),
                (_, Some(j)) if m.shape == crate::model::AngularShape::Cos => {
                    layout.pairs.push(ModePair {
                        k: m.k,
                        cos: i,
                        sin: j,
                    })
                }
                _ => {}
            }
        }
        layout
    }
}
