//! The binary: with no command (and always on the web) it plays; natively `simulate` and
//! `report` run the core headless. The command line is parsed and answered in
//! `rubber_band_box::cli`; the game is set up in `rubber_band_box::game::play`.

use std::process::ExitCode;

#[cfg(not(target_arch = "wasm32"))]
fn main() -> ExitCode {
    use clap::Parser;
    rubber_band_box::cli::run(rubber_band_box::cli::Cli::parse())
}

/// Plays what the page's address says, as the web build has no command line.
#[cfg(target_arch = "wasm32")]
fn main() -> ExitCode {
    use rubber_band_box::game::play::{PlayOptions, play};
    // The page's address is a link (docs/links.md).
    let options = PlayOptions {
        link: Some(rubber_band_box::game::web::page_address()),
        ..PlayOptions::default()
    };
    match play(&options) {
        Ok(()) => ExitCode::SUCCESS,
        Err(_) => ExitCode::from(2),
    }
}
