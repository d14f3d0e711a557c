//! Rubber Band Box: a 2D rigid box pulled by a rubber band, on Bevy.
//!
//! Rooms by who uses them, each importing only the ones above it in this list
//! (`tests/architecture.rs` holds them to it; `docs/architecture.md` is the map):
//! - [`physics`]: the numerical core, plain Rust over f64 state (no `App`);
//! - [`replay`]: a game's input as data, read, written and stepped again with the core;
//! - [`game`]: every Bevy plugin of the game, wired in one place ([`game::GamePlugin`]);
//! - `measure` (native only): the report, the peers, the references and timing;
//! - `cli` (native only): the command line the binary parses.

#[cfg(not(target_arch = "wasm32"))]
pub mod cli;
pub mod game;
#[cfg(not(target_arch = "wasm32"))]
pub mod measure;
pub mod physics;
pub mod replay;
