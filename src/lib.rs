//! `annular_plate`: a rotating annular Kirchhoff plate (the DLR FlexibleBodies
//! `AnnularPlate`) as a flexible body with a floating frame of reference, a
//! rotational joint at the axis, and Lagrangian and ALE node frames.
//!
//! Layers, data flowing one way: [`config`] → [`model`] → [`dynamics`] → `ros` / `cli`.

// Every public item is documented (the CI gates deny this warning), but for
// the declarations marked `allow(missing_docs)`: `cli` and `config` below,
// four modules of `dynamics`, and in `messages` and `ros` the wire structs
// (`types`, `visualization`, `simulation_interfaces`), `settings` and
// `params_service`. Their public items are still to be documented one by one.
#![warn(missing_docs)]

#[cfg(feature = "ros")]
pub mod bag;
#[cfg(feature = "cli")]
#[allow(missing_docs)]
pub mod cli;
pub mod colour_map;
#[allow(missing_docs)]
pub mod config;
pub mod dynamics;
#[cfg(feature = "ros")]
pub mod messages;
pub mod model;
#[cfg(feature = "ros")]
pub mod ros;
pub mod study;
