//! `~/plate_marker`: the deformed plate as a visualization_msgs/MarkerArray
//! for RViz and Foxglove (docs/ros.md, "Seeing the plate").
//!
//! One TRIANGLE_LIST in the plate's body frame (`plate_rotor`): a polar grid
//! of `ros.marker_rings` rings × `ros.marker_sectors` sectors, each cell two
//! triangles, each vertex at (r cos φ, r sin φ, s·w(r, φ)) with w = Σ q_i w_i
//! the modal sum of eq. (13) in the Lagrangian description and s the
//! magnification (`ros.marker_scale`; `auto`: the largest |w| of the last
//! second drawn as 5 % of the outer radius). Each vertex is coloured by w on
//! the fixed diverging map [`colour`]. One ARROW per node frame with a
//! non-zero force, in that frame, ending at its origin. The first marker
//! deletes what the previous message drew (DELETEALL), so arrows of forces
//! that ended disappear.
//!
//! Per message the deflection costs modes × (rings + 1) × sectors products
//! from tables built once ([`MarkerGrid`]); the node builds and publishes it
//! on its own thread from a copy of the amplitudes ([`MarkerInput`]), so the
//! fixed-rate loop only copies.

use super::outputs::{FrameNames, Shared};
use super::types::{Header, Time, Vector3};
use super::visualization::{ColorRGBA, Marker, MarkerArray, Point};
use crate::dynamics::Simulation;
use crate::model::PlateModel;
use std::collections::VecDeque;

/// `ros.marker_scale`: the deflection's magnification.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum MarkerScale {
    /// The largest |w| of the last second drawn as [`AUTO_FRACTION`] of r_a.
    Auto,
    Fixed(f64),
}

/// Under `auto`, the largest deflection of the last second is drawn as this fraction of r_a.
pub const AUTO_FRACTION: f64 = 0.05;
/// The longest arrow (the largest node force of the message) as a fraction of r_a.
pub const ARROW_FRACTION: f64 = 0.25;
/// Largest rings × sectors (40,000 triangles, about 4.8 MB per message).
pub const MAX_CELLS: u32 = 20_000;

/// The marker's `ros.*` settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarkerSettings {
    /// Messages per second of wall (or simulated) time; 0 = no marker.
    pub rate_hz: f64,
    pub rings: u32,
    pub sectors: u32,
    pub scale: MarkerScale,
}

impl Default for MarkerSettings {
    /// The declared defaults of `ros.marker_*` (`config/table.rs`).
    fn default() -> Self {
        use crate::config::defaults::{default_f64, default_i64, default_of};
        use crate::config::table::Value;
        MarkerSettings {
            rate_hz: const { default_f64("ros.marker_rate_hz") },
            rings: const { default_i64("ros.marker_rings") } as u32,
            sectors: const { default_i64("ros.marker_sectors") } as u32,
            scale: match default_of("ros.marker_scale") {
                Value::Double(x) => MarkerScale::Fixed(x),
                _ => MarkerScale::Auto,
            },
        }
    }
}

impl MarkerSettings {
    /// Steps between two markers at a loop of `step_rate_hz` (None: off). The
    /// marker comes with the step whose count is a multiple of it, so its
    /// actual rate is `step_rate_hz / every`.
    pub fn every(&self, step_rate_hz: f64) -> Option<u64> {
        (self.rate_hz > 0.0).then(|| (step_rate_hz / self.rate_hz).round().max(1.0) as u64)
    }
}

/// The colour of `t = w / w_ref` on the fixed map of [`crate::colour_map`].
pub fn colour(t: f64) -> ColorRGBA {
    let [r, g, b] = crate::colour_map::rgb(t);
    ColorRGBA { r, g, b, a: 1.0 }
}

/// The polar grid and the mode shapes on it, built once per model.
#[derive(Debug, Clone)]
pub struct MarkerGrid {
    /// Ring radii r_i … r_a (rings + 1 values).
    pub radii: Vec<f64>,
    /// Sector angles 2π s / sectors.
    pub angles: Vec<f64>,
    /// R_i(r_j), mode-major: `radial[i * radii.len() + j]`.
    radial: Vec<f64>,
    /// Θ_i(φ_s), mode-major: `angular[i * angles.len() + s]`.
    angular: Vec<f64>,
    /// (cos φ_s, sin φ_s).
    directions: Vec<(f64, f64)>,
}

impl MarkerGrid {
    pub fn new(model: &PlateModel, rings: u32, sectors: u32) -> MarkerGrid {
        let p = model.plate();
        let (ri, ra) = (p.inner_radius, p.outer_radius);
        let radii: Vec<f64> = (0..=rings)
            .map(|j| ri + (ra - ri) * j as f64 / rings as f64)
            .collect();
        let angles: Vec<f64> = (0..sectors)
            .map(|s| std::f64::consts::TAU * s as f64 / sectors as f64)
            .collect();
        let mut radial = Vec::with_capacity(model.n_modes() * radii.len());
        let mut angular = Vec::with_capacity(model.n_modes() * angles.len());
        for m in model.modes() {
            let shape = &model.radial_shapes()[m.radial];
            radial.extend(radii.iter().map(|&r| shape.value(r)));
            angular.extend(angles.iter().map(|&phi| m.shape.eval(m.k, phi).0));
        }
        let directions = angles.iter().map(|a| (a.cos(), a.sin())).collect();
        MarkerGrid {
            radii,
            angles,
            radial,
            angular,
            directions,
        }
    }

    /// w at every grid vertex, ring-major (`w[j * sectors + s]`), for the
    /// Lagrangian amplitudes `q`.
    pub fn deflection(&self, q: &[f64], w: &mut [f64]) {
        let (nr, ns) = (self.radii.len(), self.angles.len());
        w.fill(0.0);
        for (i, &qi) in q.iter().enumerate() {
            let radial = &self.radial[i * nr..(i + 1) * nr];
            let angular = &self.angular[i * ns..(i + 1) * ns];
            for (j, &rj) in radial.iter().enumerate() {
                let a = qi * rj;
                for (wv, &t) in w[j * ns..(j + 1) * ns].iter_mut().zip(angular) {
                    *wv += a * t;
                }
            }
        }
    }

    pub fn vertex_count(&self) -> usize {
        self.radii.len() * self.angles.len()
    }
}

/// What a marker needs of a state, copied out of the loop.
#[derive(Debug, Clone, PartialEq)]
pub struct MarkerInput {
    pub stamp: Time,
    pub q_lagrange: Vec<f64>,
    /// Force at each ALE / Lagrangian node (held input + load models), in its node frame.
    pub ale_forces: Vec<[f64; 3]>,
    pub lagrange_forces: Vec<[f64; 3]>,
}

impl MarkerInput {
    /// Buffers sized for `sim`'s scene.
    pub fn new(sim: &Simulation) -> MarkerInput {
        MarkerInput {
            stamp: Time::default(),
            q_lagrange: vec![0.0; sim.model().n_modes()],
            ale_forces: vec![[0.0; 3]; sim.n_ale_nodes()],
            lagrange_forces: vec![[0.0; 3]; sim.n_lagrange_nodes()],
        }
    }

    /// Copy the current state into the buffers (no allocation).
    pub fn capture(&mut self, sim: &Simulation, stamp: Time) {
        self.stamp = stamp;
        // The bending modes' amplitudes (the marker draws w).
        let n = self.q_lagrange.len();
        self.q_lagrange.copy_from_slice(&sim.q_lagrange()[..n]);
        let inputs = sim.inputs();
        for (j, f) in self.ale_forces.iter_mut().enumerate() {
            *f = add(inputs.ale[j].force, sim.ale_model_wrench(j).force);
        }
        for (j, f) in self.lagrange_forces.iter_mut().enumerate() {
            *f = add(inputs.lagrange[j].force, sim.lagrange_model_wrench(j).force);
        }
    }
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

fn norm(f: [f64; 3]) -> f64 {
    (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt()
}

/// The largest |w| of the last second, at the marker's rate.
#[derive(Debug, Clone)]
struct RecentMaximum {
    window: VecDeque<f64>,
    len: usize,
}

impl RecentMaximum {
    fn push(&mut self, value: f64) -> f64 {
        if self.window.len() == self.len {
            self.window.pop_front();
        }
        self.window.push_back(value);
        self.window.iter().copied().fold(0.0, f64::max)
    }
}

/// The marker builder of one scene.
#[derive(Debug)]
pub struct PlateMarker {
    grid: MarkerGrid,
    settings: MarkerSettings,
    frames: FrameNames,
    outer_radius: f64,
    recent: RecentMaximum,
    w: Vec<f64>,
    message: Shared<MarkerArray>,
    scale: f64,
    colour_reference: f64,
    force_scale: f64,
}

impl PlateMarker {
    /// `markers_per_second`: the actual marker rate (for the one-second window of `auto`).
    pub fn new(
        model: &PlateModel,
        frames: &FrameNames,
        settings: &MarkerSettings,
        markers_per_second: f64,
    ) -> PlateMarker {
        let grid = MarkerGrid::new(model, settings.rings, settings.sectors);
        let w = vec![0.0; grid.vertex_count()];
        let len = markers_per_second.ceil().max(1.0) as usize;
        PlateMarker {
            grid,
            settings: *settings,
            frames: frames.clone(),
            outer_radius: model.plate().outer_radius,
            recent: RecentMaximum {
                window: VecDeque::with_capacity(len),
                len,
            },
            w,
            message: Shared::new(MarkerArray::default()),
            scale: 1.0,
            colour_reference: 0.0,
            force_scale: 0.0,
        }
    }

    pub fn message(&self) -> &Shared<MarkerArray> {
        &self.message
    }

    /// Build the message for `input`.
    pub fn update(&mut self, input: &MarkerInput) {
        self.grid.deflection(&input.q_lagrange, &mut self.w);
        let w_max = self.w.iter().fold(0.0f64, |m, w| m.max(w.abs()));
        self.colour_reference = self.recent.push(w_max);
        self.scale = match self.settings.scale {
            MarkerScale::Fixed(s) => s,
            MarkerScale::Auto if self.colour_reference > 0.0 => {
                AUTO_FRACTION * self.outer_radius / self.colour_reference
            }
            MarkerScale::Auto => 1.0,
        };
        let f_max = input
            .ale_forces
            .iter()
            .chain(&input.lagrange_forces)
            .map(|f| norm(*f))
            .fold(0.0, f64::max);
        self.force_scale = if f_max > 0.0 {
            ARROW_FRACTION * self.outer_radius / f_max
        } else {
            0.0
        };
        let header = |frame: &str| Header {
            stamp: input.stamp,
            frame_id: frame.to_string(),
        };
        let mut markers =
            Vec::with_capacity(2 + input.ale_forces.len() + input.lagrange_forces.len());
        markers.push(Marker {
            header: header(&self.frames.rotor),
            action: Marker::DELETEALL,
            ..Marker::default()
        });
        markers.push(self.mesh(header(&self.frames.rotor)));
        let nodes = self
            .frames
            .ale
            .iter()
            .zip(&input.ale_forces)
            .chain(self.frames.lagrange.iter().zip(&input.lagrange_forces));
        for (frame, force) in nodes {
            if norm(*force) > 0.0 {
                let id = markers.len() as i32 - 2;
                markers.push(self.arrow(header(frame), id, *force));
            }
        }
        // A new message: the previous one may still be with the DDS or bag writer.
        self.message = Shared::new(MarkerArray { markers });
    }

    /// The triangle list: cell (j, s) → (j, s), (j + 1, s), (j + 1, s + 1) and
    /// (j, s), (j + 1, s + 1), (j, s + 1), counter-clockwise seen from +z.
    fn mesh(&self, header: Header) -> Marker {
        let (nr, ns) = (self.grid.radii.len(), self.grid.angles.len());
        let mut points = Vec::with_capacity(6 * (nr - 1) * ns);
        let mut colors = Vec::with_capacity(points.capacity());
        let vertex = |j: usize, s: usize| {
            let s = s % ns;
            let (r, (c, sn), w) = (
                self.grid.radii[j],
                self.grid.directions[s],
                self.w[j * ns + s],
            );
            let t = if self.colour_reference > 0.0 {
                w / self.colour_reference
            } else {
                0.0
            };
            (
                Point {
                    x: r * c,
                    y: r * sn,
                    z: self.scale * w,
                },
                colour(t),
            )
        };
        for j in 0..nr - 1 {
            for s in 0..ns {
                for (jj, ss) in [
                    (j, s),
                    (j + 1, s),
                    (j + 1, s + 1),
                    (j, s),
                    (j + 1, s + 1),
                    (j, s + 1),
                ] {
                    let (p, c) = vertex(jj, ss);
                    points.push(p);
                    colors.push(c);
                }
            }
        }
        Marker {
            header,
            ns: "plate".into(),
            id: 0,
            kind: Marker::TRIANGLE_LIST,
            action: Marker::ADD,
            pose: Default::default(),
            scale: Vector3 {
                x: 1.0,
                y: 1.0,
                z: 1.0,
            },
            color: ColorRGBA {
                r: 1.0,
                g: 1.0,
                b: 1.0,
                a: 1.0,
            },
            points,
            colors,
            text: self.text(),
            ..Marker::default()
        }
    }

    /// An arrow ending at the node frame's origin, length |F| × force scale.
    fn arrow(&self, header: Header, id: i32, f: [f64; 3]) -> Marker {
        let s = self.force_scale;
        let d = 0.01 * self.outer_radius;
        Marker {
            header,
            ns: "forces".into(),
            id,
            kind: Marker::ARROW,
            action: Marker::ADD,
            pose: Default::default(),
            scale: Vector3 {
                x: d,
                y: 2.0 * d,
                z: 3.0 * d,
            },
            color: ColorRGBA {
                r: 0.1,
                g: 0.6,
                b: 0.1,
                a: 1.0,
            },
            points: vec![
                Point {
                    x: -s * f[0],
                    y: -s * f[1],
                    z: -s * f[2],
                },
                Point::default(),
            ],
            text: format!("force_n={:e}", norm(f)),
            ..Marker::default()
        }
    }

    /// The numbers a viewer needs to read the picture (parsed by the tests).
    fn text(&self) -> String {
        format!(
            "scale={:e} colour_ref_m={:e} force_scale_m_per_n={:e} | deflection drawn x scale ({}); blue = -colour_ref, grey = 0, red = +colour_ref; arrow length = force x force_scale",
            self.scale,
            self.colour_reference,
            self.force_scale,
            match self.settings.scale {
                MarkerScale::Auto => "auto: the largest |w| of the last second as 5 % of the outer radius".to_string(),
                MarkerScale::Fixed(_) => "ros.marker_scale".to_string(),
            }
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_decimates_the_loop() {
        let s = MarkerSettings::default();
        assert_eq!(s.every(1000.0), Some(33));
        assert_eq!(MarkerSettings { rate_hz: 0.0, ..s }.every(1000.0), None);
        assert_eq!(
            MarkerSettings {
                rate_hz: 5000.0,
                ..s
            }
            .every(1000.0),
            Some(1)
        );
    }
}
