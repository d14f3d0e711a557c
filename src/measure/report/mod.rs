//! The speed-against-error report (`report`): every integrator measured in one process, a
//! section at a time (the work-precision sweep, the stability table, the hard cases, the
//! stiffness sweep with its invariants and the engines for `auto`, the energy ledger, and with
//! `--peers` the side-by-side with avian2d and bevy_rapier2d), then the plots. Each section
//! builds its tables (`table::Table`); `run` writes them: `report.md` and a CSV file per table.
//!
//! Errors are final-pose errors: the largest distance between where a corner of the box is
//! and where the reference says it should be (px). Costs are nanoseconds of this machine (the
//! median of repeated runs of the core alone, no `App`, but in the side-by-side).

use std::error::Error;
use std::fs;
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;

mod anchors;
mod engines;
mod hard_cases;
mod invariants;
mod ledger;
#[cfg(feature = "peers")]
mod peers;
mod plots;
mod replay;
mod stability;
mod stiffness;
mod table;
mod work_precision;

pub use engines::EnginePoint;
pub use hard_cases::{HardCase, hard_cases};
pub use plots::{ExtraLines, Line};
pub use stability::{STIFFEST_TRIED, StabilityRow};
pub use stiffness::{SWEEP_RATES, StiffPoint, ks_swept, stiff_cases};
pub use work_precision::WorkPoint;

use table::Table;

#[derive(Args, Debug)]
pub struct ReportArgs {
    /// Where to write the CSV files and the plot.
    #[arg(long, default_value = "target/report")]
    pub out: PathBuf,
    /// A reduced sweep that runs in well under a minute (CI's smoke test).
    #[arg(long)]
    pub quick: bool,
    /// Also run avian2d and bevy_rapier2d beside ours (needs a build with `--features peers`).
    #[arg(long)]
    pub peers: bool,
    /// Only the sweep on a recorded game (`play --record`).
    ///
    /// Every integrator at the recorded step rate and finer, against the tightest reference.
    #[arg(long, value_name = "FILE")]
    pub replay: Option<PathBuf>,
}

/// An argument the report cannot run with (a bad replay file): exit status 2, as `simulate`.
#[derive(Debug)]
pub struct BadInput(pub String);

impl std::fmt::Display for BadInput {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl Error for BadInput {}

/// What `report --peers` says in a build without the peers compiled in.
pub const NO_PEERS: &str = "this build has no peers: run it as \
`cargo run --release --features peers -- report --peers`";

pub fn run(args: &ReportArgs) -> Result<(), Box<dyn Error>> {
    if args.peers && !cfg!(feature = "peers") {
        return Err(NO_PEERS.into());
    }
    fs::create_dir_all(&args.out)?;
    let started = Instant::now();
    let quick = args.quick;
    if let Some(path) = &args.replay {
        let recorded = crate::replay::Replay::read_file(path).map_err(BadInput)?;
        // Run once, measured against by the integrators and, with `--peers`, the peers.
        let reference = crate::measure::references::ReplayReference::of(&recorded);
        let points = replay::sweep(&recorded, &reference, quick);
        let name = path.display().to_string();
        #[allow(unused_mut)]
        let mut tables = vec![replay::table(&recorded, &name, &points)];
        #[cfg(feature = "peers")]
        if args.peers {
            tables.push(peers::replay_table(&recorded, &reference, quick));
        }
        return write(&args.out, &tables, started);
    }

    let work = work_precision::sweep(quick);
    let mut tables = vec![
        work_precision::table(&work),
        stability::table(),
        hard_cases::table(quick),
    ];
    let cases = stiff_cases(quick);
    let sweep = stiffness::sweep(&cases, quick);
    tables.extend([
        stiffness::table(&cases, &sweep),
        anchors::table(&cases),
        engines::table(&cases, quick),
        invariants::table(quick),
        ledger::table(quick),
    ]);
    #[cfg(feature = "peers")]
    let extra = if args.peers {
        let (peer_tables, extra) = peers::section(&cases, quick);
        tables.extend(peer_tables);
        extra
    } else {
        ExtraLines::default()
    };
    #[cfg(not(feature = "peers"))]
    let extra = ExtraLines::default();
    plots::plot_work_precision(&work, extra.work, &args.out.join("work_precision.svg"))?;
    plots::plot_stiffness(&sweep, extra.stiffness, &args.out.join("stiffness.svg"))?;

    write(&args.out, &tables, started)
}

/// Writes every table's CSV file, then `report.md`, the tables one after another (also printed).
fn write(out: &Path, tables: &[Table], started: Instant) -> Result<(), Box<dyn Error>> {
    let mut markdown = Vec::new();
    for table in tables {
        if let Some(file) = table.file() {
            fs::write(out.join(file), table.csv())?;
        }
        markdown.push(table.markdown());
    }
    let markdown = format!(
        "{}\nWritten to {} in {:.1} s.\n",
        markdown.join("\n"),
        out.display(),
        started.elapsed().as_secs_f64()
    );
    fs::write(out.join("report.md"), &markdown)?;
    print!("{markdown}");
    Ok(())
}
