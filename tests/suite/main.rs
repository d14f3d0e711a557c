//! Every test but the peers' in one binary: one link of Bevy, one process (docs/testing.md).
//! A module a subject; run one with `cargo test --test suite <module>::`.

mod common;
mod pages;

mod access;
mod architecture;
mod camera;
mod cli;
mod controls;
mod core;
mod docs;
mod draw;
mod example;
mod figures;
mod fixed_step;
mod focus;
mod fuzz;
mod hud;
mod integrators;
mod keyboard;
mod lab;
mod layout;
mod learn;
mod links;
mod monkey;
mod names;
mod panel;
mod play;
mod pointer;
mod properties;
mod recording;
mod replay;
mod report;
mod signals;
mod stability;
