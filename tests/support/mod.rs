//! Shared helpers for the integration tests (each test crate does `mod support;`).
pub mod bessel;
pub mod bounded_run;
pub mod cli;
pub mod exact_plate;
pub mod fit;
pub mod fourth_order;
pub mod in_plane_exact;
pub mod left_growth;
pub mod library_plate;
pub mod mindlin_exact;
pub mod one_contact;
pub mod pair_quartic;
pub mod quadrature;
pub mod scene_files;
pub mod scenes;
pub mod squeal;
pub mod static_plate;
