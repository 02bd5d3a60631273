//! `annular_plate`: a rotating annular Kirchhoff plate (the DLR FlexibleBodies
//! `AnnularPlate`) as a flexible body with a floating frame of reference, a
//! rotational joint at the axis, and Lagrangian and ALE node frames.
//!
//! Layers, data flowing one way: [`config`] → [`model`] → [`dynamics`] → `ros` / `cli`.

// Every public item is documented: the CI gates deny this warning.
#![warn(missing_docs)]

#[cfg(feature = "ros")]
pub mod bag;
#[cfg(feature = "cli")]
pub mod cli;
pub mod colour_map;
pub mod config;
pub mod dynamics;
#[cfg(feature = "ros")]
pub mod messages;
pub mod model;
#[cfg(feature = "ros")]
pub mod ros;
pub mod study;
