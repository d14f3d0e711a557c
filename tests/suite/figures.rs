//! Every figure docs/ quotes from a run is the snapshot's: the committed output of the command
//! that measured it (docs/snapshots/). Two ways keep them so:
//! - a generated block, a table rendered from a snapshot's CSV between
//!   `<!-- figures: FILE; COLUMN=VALUE|VALUE; show=COLUMN:FORMAT:LABEL,... -->` and
//!   `<!-- /figures -->`, which this test compares with what the CSV renders to today, and
//!   rewrites when run as `RBB_WRITE_FIGURES=1 cargo test --test suite figures::` (the one command that
//!   refreshes them after a new snapshot: point the marker at it);
//! - a figure in prose, listed in [`QUOTED`] with the cell it comes from: the page must hold the
//!   words, and the words the cell's value as the page prints it.

use crate::pages;

use std::collections::HashMap;
use std::fs;
use std::path::{Path, PathBuf};

use pages::{pages, root};

fn snapshots() -> PathBuf {
    root().join("docs/snapshots")
}

/// A CSV as the report writes it: a header, then rows; a field may be quoted (no commas inside).
fn read_csv(path: &Path) -> Result<Vec<HashMap<String, String>>, String> {
    let text = fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut lines = text.lines();
    let header: Vec<String> = lines
        .next()
        .ok_or_else(|| format!("{} is empty", path.display()))?
        .split(',')
        .map(str::to_owned)
        .collect();
    Ok(lines
        .filter(|line| !line.is_empty())
        .map(|line| {
            header
                .iter()
                .cloned()
                .zip(
                    line.split(',')
                        .map(|field| field.trim_matches('"').to_owned()),
                )
                .collect()
        })
        .collect())
}

/// A criterion summary (`cargo bench ... -- --noplot` kept as text): each benchmark's name
/// and its estimate, the middle of the three times, as printed with its unit ("59.337 µs").
fn read_bench(path: &Path) -> Result<Vec<HashMap<String, String>>, String> {
    let text = fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut rows = Vec::new();
    let mut name = String::new();
    for line in text.lines().filter(|line| !line.starts_with('#')) {
        let (head, times) = match line.split_once("time:") {
            Some((head, times)) => (head.trim(), times),
            None => {
                name = line.trim().to_owned();
                continue;
            }
        };
        if !head.is_empty() {
            name = head.to_owned();
        }
        let parts: Vec<&str> = times
            .trim()
            .trim_matches(|c| c == '[' || c == ']')
            .split_whitespace()
            .collect();
        if let [_, _, estimate, unit, ..] = parts.as_slice() {
            rows.push(HashMap::from([
                ("bench".to_owned(), name.clone()),
                ("estimate".to_owned(), (*estimate).to_owned()),
                ("unit".to_owned(), (*unit).to_owned()),
            ]));
        }
    }
    Ok(rows)
}

/// A snapshot's rows: a report's CSV, or a criterion summary.
fn read_rows(path: &Path) -> Result<Vec<HashMap<String, String>>, String> {
    if path.extension().is_some_and(|e| e == "txt") {
        read_bench(path)
    } else {
        read_csv(path)
    }
}

/// A cell's text matches a wanted value: as numbers when both are (`1e5` is `100000`).
fn matches(cell: &str, wanted: &str) -> bool {
    match (cell.parse::<f64>(), wanted.parse::<f64>()) {
        (Ok(a), Ok(b)) => a == b,
        _ => cell == wanted,
    }
}

/// A value as a page prints it: `e` one decimal in scientific notation (6.8e-11), `e2` two,
/// `us` nanoseconds as microseconds with one decimal, `ns` and `f0` whole numbers, `f1`..`f3` fixed
/// decimals, `k` a stiffness as 1e5, `x` a ratio with two decimals; anything else as written.
fn format(cell: &str, format: &str) -> String {
    let Ok(value) = cell.parse::<f64>() else {
        return cell.to_owned();
    };
    match format {
        "e" => format!("{value:.1e}"),
        "e2" => format!("{value:.2e}"),
        "us" => format!("{:.1}", value / 1000.0),
        "ns" | "f0" => format!("{value:.0}"),
        "f1" => format!("{value:.1}"),
        "f2" | "x" => format!("{value:.2}"),
        "f3" => format!("{value:.3}"),
        "k" => format!("{value:e}"),
        _ => cell.to_owned(),
    }
}

/// The rows of `rows` whose every filtered column holds one of its values.
fn select<'a>(
    rows: &'a [HashMap<String, String>],
    filters: &[(String, Vec<String>)],
) -> Vec<&'a HashMap<String, String>> {
    rows.iter()
        .filter(|row| {
            filters.iter().all(|(column, wanted)| {
                row.get(column)
                    .is_some_and(|cell| wanted.iter().any(|w| matches(cell, w)))
            })
        })
        .collect()
}

/// A generated block's marker: the snapshot, the filters and the columns shown.
#[derive(Debug)]
struct Marker {
    file: String,
    filters: Vec<(String, Vec<String>)>,
    /// (column, format, label)
    shown: Vec<(String, String, String)>,
}

fn parse_marker(text: &str) -> Result<Marker, String> {
    let mut clauses = text.split(';').map(str::trim);
    let file = clauses.next().unwrap_or_default().to_owned();
    let mut filters = Vec::new();
    let mut shown = Vec::new();
    for clause in clauses {
        let (key, value) = clause
            .split_once('=')
            .ok_or_else(|| format!("'{clause}' is not KEY=VALUE"))?;
        if key == "show" {
            for column in value.split(',') {
                let mut parts = column.trim().splitn(3, ':');
                let name = parts.next().unwrap_or_default().to_owned();
                let format = parts.next().unwrap_or_default().to_owned();
                let label = parts.next().map_or_else(|| name.clone(), str::to_owned);
                shown.push((name, format, label));
            }
        } else {
            let values = value.split('|').map(|v| v.trim().to_owned()).collect();
            filters.push((key.trim().to_owned(), values));
        }
    }
    if shown.is_empty() {
        return Err(format!("{file}: no show= clause"));
    }
    Ok(Marker {
        file,
        filters,
        shown,
    })
}

/// The Markdown table a marker renders to, from its snapshot as it is now.
fn render(marker: &Marker) -> Result<String, String> {
    let rows = read_csv(&snapshots().join(&marker.file))?;
    for (column, ..) in &marker.shown {
        if rows.first().is_some_and(|row| !row.contains_key(column)) {
            return Err(format!("{} has no column {column}", marker.file));
        }
    }
    let picked = select(&rows, &marker.filters);
    if picked.is_empty() {
        return Err(format!(
            "{}: no row matches {:?}",
            marker.file, marker.filters
        ));
    }
    let labels: Vec<&str> = marker.shown.iter().map(|(.., l)| l.as_str()).collect();
    let mut table = format!(
        "| {} |\n|{}\n",
        labels.join(" | "),
        "---|".repeat(labels.len())
    );
    for row in picked {
        let cells: Vec<String> = marker
            .shown
            .iter()
            .map(|(column, f, _)| format(&row[column], f))
            .collect();
        table.push_str(&format!("| {} |\n", cells.join(" | ")));
    }
    Ok(table)
}

const OPEN: &str = "<!-- figures: ";
const CLOSE: &str = "<!-- /figures -->";

/// The page with every generated block rendered afresh, and how many it holds.
fn refreshed(page: &str) -> Result<(String, usize), String> {
    let mut out = String::new();
    let mut rest = page;
    let mut blocks = 0;
    // A marker opens a line; one quoted in a sentence is not a block.
    while let Some(start) = rest
        .match_indices(OPEN)
        .map(|(at, _)| at)
        .find(|&at| at == 0 || rest[..at].ends_with('\n'))
    {
        let head_end = rest[start..]
            .find("-->")
            .ok_or("a figures marker is not closed")?
            + start
            + 3;
        let marker = parse_marker(rest[start + OPEN.len()..head_end - 3].trim())?;
        let close = rest[head_end..]
            .find(CLOSE)
            .ok_or_else(|| format!("{}: no {CLOSE}", marker.file))?
            + head_end;
        out.push_str(&rest[..head_end]);
        out.push('\n');
        out.push_str(&render(&marker)?);
        rest = &rest[close..];
        blocks += 1;
    }
    out.push_str(rest);
    Ok((out, blocks))
}

#[test]
fn every_generated_block_is_what_its_snapshot_renders() {
    let write = std::env::var_os("RBB_WRITE_FIGURES").is_some();
    let mut stale = Vec::new();
    let mut blocks = 0;
    for page in pages() {
        let text = fs::read_to_string(&page).expect("a page");
        let (fresh, found) =
            refreshed(&text).unwrap_or_else(|error| panic!("{}: {error}", page.display()));
        blocks += found;
        if fresh != text {
            if write {
                // Beside the page, then renamed into place.
                let beside = page.with_extension("md.new");
                fs::write(&beside, &fresh).expect("write beside the page");
                fs::rename(&beside, &page).expect("rename into place");
            } else {
                stale.push(page.display().to_string());
            }
        }
    }
    assert!(blocks >= 2, "the reader found the blocks ({blocks})");
    assert!(
        stale.is_empty(),
        "generated figures differ from their snapshots in {}; refresh with \
         RBB_WRITE_FIGURES=1 cargo test --test suite figures::",
        stale.join(", ")
    );
}

/// A figure quoted in prose: the page, the words as written there (holding the value), and
/// the snapshot cell it comes from, with the format the words print it in.
struct Quoted {
    page: &'static str,
    words: &'static str,
    file: &'static str,
    row: &'static [(&'static str, &'static str)],
    column: &'static str,
    format: &'static str,
}

const QUOTED: &[Quoted] = &[
    // integrators.md: implicit's price, the default's case, the engines.
    Quoted {
        page: "docs/integrators.md",
        words: "(15 px of error on the tutorial scene at 100 Hz",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "implicit"),
            ("dt", "0.01"),
        ],
        column: "error_px",
        format: "f0",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "some 34 Taylor steps a 10 ms step at k = 1e6",
        file: "2026-11-25-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "mean_substeps",
        format: "f0",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "24 Taylor steps of up to 28 orders",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "mean_substeps",
        format: "f0",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "(6.8e-9 px at k = 1e6",
        file: "2026-11-27-lanes-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "taylor 28 3e-11")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "(6.8e-9 px at k = 1e6: 4.6 µs",
        file: "2026-11-27-lanes-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "taylor 28 3e-11")],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "against 37.2 for DOP853 at 9.3e-9 px",
        file: "2026-11-27-lanes-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "dop853 1e-11")],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "against 37.2 for DOP853 at 9.3e-9 px",
        file: "2026-11-27-lanes-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "dop853 1e-11")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "2.0e-11 px at 100 Hz",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "auto"),
            ("dt", "0.01"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "1.9e-11 px at 64 Hz",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "auto"),
            ("dt", "0.015625"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "plain `rk4` 1.2e-4 px",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[("scene", "tutorial"), ("integrator", "rk4"), ("dt", "0.01")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "`implicit` is 15 px off",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "implicit"),
            ("dt", "0.01"),
        ],
        column: "error_px",
        format: "f0",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "bevy_rapier2d end 2.1 px off at 100 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "error_px",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "and 3.2 to 3.3 px at 64 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "64"),
            ("contender", "avian2d"),
        ],
        column: "error_px",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "and 3.2 to 3.3 px at 64 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "error_px",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "costs 3.1 to 3.2 times ours",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "costs 3.1 to 3.2 times ours",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "2.8e-14 px at k = 1e3",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e3"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "4.3e-10 px at 1e5",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e5"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "6.8e-9 px at 1e6",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "4.0e-5 px at 1e7 (100 Hz)",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "other method is 49 px or more off",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e4"), ("rate_hz", "64"), ("integrator", "implicit")],
        column: "error_px",
        format: "f0",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "k = 1e6 at 100 Hz (5 ticks) 59.3 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e6/100Hz/5ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "at 64 Hz (3 ticks) 57.9 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e6/64Hz/3ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "k = 1e7 at 100 Hz (2 ticks) 74.2 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e7/100Hz/2ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "at 64 Hz (1 tick) 58.6 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e7/64Hz/1ticks")],
        column: "estimate",
        format: "f1",
    },
    // report.md: the tables of the newest run, read.
    Quoted {
        page: "docs/report.md",
        words: "has `auto` at 2.0e-11 px",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "auto"),
            ("dt", "0.01"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "RK4 at 1.2e-4 px",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[("scene", "tutorial"), ("integrator", "rk4"), ("dt", "0.01")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "the seed's own step at 1.2 px",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "seed"),
            ("dt", "0.01"),
        ],
        column: "error_px",
        format: "f1",
    },
    Quoted {
        page: "docs/report.md",
        words: "(`auto` 12291 ns per simulated second",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[
            ("scene", "tutorial"),
            ("integrator", "auto"),
            ("dt", "0.01"),
        ],
        column: "ns_per_simulated_second",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "RK4 5082)",
        file: "2026-11-27-lanes-report/work_precision.csv",
        row: &[("scene", "tutorial"), ("integrator", "rk4"), ("dt", "0.01")],
        column: "ns_per_simulated_second",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "symplectic Euler held to k = 3.09e4",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "symplectic"), ("rate_hz", "100")],
        column: "largest_stable_k",
        format: "e2",
    },
    Quoted {
        page: "docs/report.md",
        words: "(ω·dt = 1.57)",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "symplectic"), ("rate_hz", "100")],
        column: "omega_dt",
        format: "f2",
    },
    Quoted {
        page: "docs/report.md",
        words: "Verlet to 3.47e4",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "verlet"), ("rate_hz", "100")],
        column: "largest_stable_k",
        format: "e2",
    },
    Quoted {
        page: "docs/report.md",
        words: "RK4 to 3.55e5",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "rk4"), ("rate_hz", "100")],
        column: "largest_stable_k",
        format: "e2",
    },
    Quoted {
        page: "docs/report.md",
        words: "explicit Euler to 631 (0.22)",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "euler"), ("rate_hz", "100")],
        column: "largest_stable_k",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "explicit Euler to 631 (0.22)",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "euler"), ("rate_hz", "100")],
        column: "omega_dt",
        format: "f2",
    },
    Quoted {
        page: "docs/report.md",
        words: "at most 5.2e-9 px to k = 1e6 (at 64 Hz)",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "64"), ("integrator", "auto")],
        column: "references_agree_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "k = 1e7 2.1e-5 px at 100 Hz",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "references_agree_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "6.4e-8 px at 64 Hz. At k = 1e7",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "64"), ("integrator", "auto")],
        column: "references_agree_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "(152 ns, one Taylor step",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "2e1"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "ns_per_tick",
        format: "ns",
    },
    Quoted {
        page: "docs/report.md",
        words: "4.3e-10 px at 1e5",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e5"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "6.8e-9 px at 1e6 (24 Taylor steps",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "(24 Taylor steps a fixed step",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "mean_substeps",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "a fixed step, 4.6 µs)",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/report.md",
        words: "and 4.0e-5 px at 1e7.",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "it ended that step 4.0e2 px off",
        file: "2026-11-27-lanes-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "64"), ("integrator", "euler")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "is 4.0e-5 px at 100 Hz (the median",
        file: "2026-11-27-lanes-report/anchors.csv",
        row: &[("k", "1e7"), ("rate_hz", "100")],
        column: "error_max_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "(the median 6.2e-6)",
        file: "2026-11-27-lanes-report/anchors.csv",
        row: &[("k", "1e7"), ("rate_hz", "100")],
        column: "error_median_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "and 1.2e-7 px at 64 Hz",
        file: "2026-11-27-lanes-report/anchors.csv",
        row: &[("k", "1e7"), ("rate_hz", "64")],
        column: "error_max_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "the errors run from 6.8e-9 to 2.7e-6 px",
        file: "2026-11-27-lanes-report/anchors.csv",
        row: &[("k", "1e6"), ("rate_hz", "100")],
        column: "error_min_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "the errors run from 6.8e-9 to 2.7e-6 px",
        file: "2026-11-27-lanes-report/anchors.csv",
        row: &[("k", "1e6"), ("rate_hz", "100")],
        column: "error_max_px",
        format: "e",
    },
    Quoted {
        page: "docs/report.md",
        words: "(at step 657 at 100 Hz",
        file: "2026-11-27-lanes-report/hard_cases.csv",
        row: &[
            ("case", "stiff band k = 1e3 at 100 Hz"),
            ("integrator", "euler"),
        ],
        column: "diverged_at_step",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "199 at 64 Hz",
        file: "2026-11-27-lanes-report/hard_cases.csv",
        row: &[
            ("case", "stiff band k = 1e3 at 64 Hz"),
            ("integrator", "euler"),
        ],
        column: "diverged_at_step",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "past its stable k of 631 and 407",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "euler"), ("rate_hz", "100")],
        column: "largest_stable_k",
        format: "f0",
    },
    Quoted {
        page: "docs/report.md",
        words: "past its stable k of 631 and 407",
        file: "2026-11-27-lanes-report/stability.csv",
        row: &[("integrator", "euler"), ("rate_hz", "64")],
        column: "largest_stable_k",
        format: "f0",
    },
    // peers.md: three runs in a row, and the side-by-side table.
    Quoted {
        page: "docs/peers.md",
        words: "which read 4.75, 3.19 and 3.26",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "which read 4.75, 3.19 and 3.26",
        file: "2026-11-27-lanes-report/repeat-2/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "which read 4.75, 3.19 and 3.26",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "rapier's own tick was 20.7 µs in the first run",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/peers.md",
        words: "and 13.9 and 14.7 µs in the other two",
        file: "2026-11-27-lanes-report/repeat-2/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/peers.md",
        words: "and 13.9 and 14.7 µs in the other two",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/peers.md",
        words: "diagonal at 100 Hz: 3.62",
        file: "2026-11-25-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "3.62, 2.99 and 3.13",
        file: "2026-11-25-report/repeat-2/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "2.99 and 3.13)",
        file: "2026-11-25-report/repeat-3/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "ours ends 2.0e-11 px",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "are 3.13 to 3.15 and 3.11 to 3.24 times ours",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "are 3.13 to 3.15 and 3.11 to 3.24 times ours",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "are 3.13 to 3.15 and 3.11 to 3.24 times ours",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "are 3.13 to 3.15 and 3.11 to 3.24 times ours",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "2.50 to 2.75 times ours at 100 Hz",
        file: "2026-11-27-lanes-report/repeat-2/peers.csv",
        row: &[
            ("scene", "stiff"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "2.50 to 2.75 times ours at 100 Hz",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "stiff"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "2.34 to 2.65 at 64 Hz",
        file: "2026-11-27-lanes-report/repeat-3/peers.csv",
        row: &[
            ("scene", "stiff"),
            ("rate_hz", "64"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "2.34 to 2.65 at 64 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "stiff"),
            ("rate_hz", "64"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "x",
    },
    Quoted {
        page: "docs/peers.md",
        words: "ours by 3.3e-15 at 100 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "undamped"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "energy_drift",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "and 4.7e-15 at 64 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "undamped"),
            ("rate_hz", "64"),
            ("contender", "ours (auto)"),
        ],
        column: "energy_drift",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(k = 1e7: 4.0e-5 px at 100 Hz, 8.6e-8 at 64 Hz; k = 1e6: 6.8e-9 and 1.2e-8)",
        file: "2026-11-27-lanes-report/peers_stiffness.csv",
        row: &[
            ("k", "1e7"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(k = 1e7: 4.0e-5 px at 100 Hz, 8.6e-8 at 64 Hz; k = 1e6: 6.8e-9 and 1.2e-8)",
        file: "2026-11-27-lanes-report/peers_stiffness.csv",
        row: &[
            ("k", "1e7"),
            ("rate_hz", "64"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(k = 1e7: 4.0e-5 px at 100 Hz, 8.6e-8 at 64 Hz; k = 1e6: 6.8e-9 and 1.2e-8)",
        file: "2026-11-27-lanes-report/peers_stiffness.csv",
        row: &[
            ("k", "1e6"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(k = 1e7: 4.0e-5 px at 100 Hz, 8.6e-8 at 64 Hz; k = 1e6: 6.8e-9 and 1.2e-8)",
        file: "2026-11-27-lanes-report/peers_stiffness.csv",
        row: &[
            ("k", "1e6"),
            ("rate_hz", "64"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "ours 4.0e-14 px, avian2d 0.11 px,",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/peers.md",
        words: "ours 4.0e-14 px, avian2d 0.11 px,",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "error_px",
        format: "f2",
    },
    Quoted {
        page: "docs/peers.md",
        words: "bevy_rapier2d 0.17 px at 100 Hz",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "diagonal"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "error_px",
        format: "f2",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(`app_tick/box_and_band` 4.61 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/box_and_band/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/peers.md",
        words: "against `app_tick/empty` 4.27 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/empty/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(k = 1e6 at 64 Hz 57.9 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e6/64Hz/3ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/peers.md",
        words: "k = 1e7 at 64 Hz 58.6 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e7/64Hz/1ticks")],
        column: "estimate",
        format: "f1",
    },
    // README.md: the result.
    Quoted {
        page: "README.md",
        words: "2.0e-11 px from the converged answer after 4 s",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "ours (auto)"),
        ],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "README.md",
        words: "for under a third of their `App` tick",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "third",
    },
    Quoted {
        page: "README.md",
        words: "for under a third of their `App` tick",
        file: "2026-11-27-lanes-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "bevy_rapier2d"),
        ],
        column: "tick_over_ours",
        format: "third",
    },
    // benchmarks.md and lab.md: criterion on 2026-11-25, after the vector lanes.
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 25 ns, symplectic 26, Verlet 48, RK4 61, seed 28,",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/euler")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 25 ns, symplectic 26, Verlet 48, RK4 61, seed 28,",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/symplectic")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 25 ns, symplectic 26, Verlet 48, RK4 61, seed 28,",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/verlet")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 25 ns, symplectic 26, Verlet 48, RK4 61, seed 28,",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/rk4")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 25 ns, symplectic 26, Verlet 48, RK4 61, seed 28,",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/seed")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "implicit 186, `auto` 121 ns",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/implicit")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "implicit 186, `auto` 121 ns",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "core_step/auto")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "129 ns in the run before",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "core_step/auto")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e5 at 100 Hz (10 ticks) 38.7 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e5/100Hz/10ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 59.3 µs at 100 Hz (5 ticks)",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e6/100Hz/5ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "and 57.9 µs at 64 Hz (3 ticks)",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e6/64Hz/3ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 74.2 µs at 100 Hz (2 ticks)",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e7/100Hz/2ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "and 58.6 µs at 64 Hz (1 tick)",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "stiff_auto/k1e7/64Hz/1ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "executor: 4.27 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/empty/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "empty, 4.61 µs with the box and its band",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/box_and_band/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "multi-threaded executor 198 and 245 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/empty/multi_threaded")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "multi-threaded executor 198 and 245 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "app_tick/box_and_band/multi_threaded")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "4.6 µs for one",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "boxes_with_bands/1")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "20 µs for 100",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "boxes_with_bands/100")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "1.7 ms for 10⁴",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "boxes_with_bands/10000")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "67 ms for 10⁵",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "boxes_with_bands/100000")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "2.1 ms and 99 ms in the run before",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "boxes_with_bands/10000")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "2.1 ms and 99 ms in the run before",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "boxes_with_bands/100000")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "tutorial 4.8 → 6.4 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/tutorial/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "tutorial 4.8 → 6.4 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/tutorial/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.3 → 8.3 µs, k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.3 → 8.3 µs, k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.3 → 8.3 µs, k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff-k1e12/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.3 → 8.3 µs, k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff-k1e12/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "tutorial 4.8 → 6.4 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/tutorial/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "tutorial 4.8 → 6.4 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/tutorial/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "(k = 1e5) 5.3 → 8.3 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "(k = 1e5) 5.3 → 8.3 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff-k1e12/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "k = 1e12 5.1 → 7.1 µs",
        file: "2026-11-25-bench-2.txt",
        row: &[("bench", "ghosts/stiff-k1e12/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/tutorial/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/tutorial/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/stiff/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/stiff/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "5.0 → 6.7, 5.9 → 9.7 and 5.3 → 7.3 µs:",
        file: "2026-11-25-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/on")],
        column: "estimate",
        format: "f1",
    },
    // criterion on 2026-11-27, after the turning frame and the lanes.
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 31 ns, symplectic 30, Verlet 57, RK4 67, seed 33,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/euler")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 31 ns, symplectic 30, Verlet 57, RK4 67, seed 33,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/symplectic")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 31 ns, symplectic 30, Verlet 57, RK4 67, seed 33,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/verlet")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 31 ns, symplectic 30, Verlet 57, RK4 67, seed 33,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/rk4")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "explicit Euler 31 ns, symplectic 30, Verlet 57, RK4 67, seed 33,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/seed")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "implicit 227, `auto` 131 ns",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/implicit")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "implicit 227, `auto` 131 ns",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "core_step/auto")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e5 at 100 Hz (10 ticks) 22.5 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e5/100Hz/10ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 31.9 µs at 100 Hz (5 ticks)",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e6/100Hz/5ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "and 29.9 µs at 64 Hz (3 ticks)",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e6/64Hz/3ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 38.4 µs at 100 Hz (2 ticks)",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e7/100Hz/2ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "and 30.1 µs at 64 Hz (1 tick)",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e7/64Hz/1ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 20 at 100 Hz 168 and 221 ns",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k2e1/100Hz/as_run")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 20 at 100 Hz 168 and 221 ns",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k2e1/100Hz/portable")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 at 100 Hz 6.9 and 12.0 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e6/100Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 at 100 Hz 6.9 and 12.0 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e6/100Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 at 64 Hz 10.1 and 17.5 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e6/64Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e6 at 64 Hz 10.1 and 17.5 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e6/64Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 at 100 Hz 19.5 and 33.0 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/100Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 at 100 Hz 19.5 and 33.0 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/100Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 at 64 Hz 30.2 and 56.4 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/64Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "k = 1e7 at 64 Hz 30.2 and 56.4 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/64Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "executor: empty 4.61 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/empty/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "does nothing 4.83 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/one_empty_fixed_system/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "4.70 µs, with the box and its band 5.45 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/settings_check/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "4.70 µs, with the box and its band 5.45 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/box_and_band/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "191 and 234 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/empty/multi_threaded")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "191 and 234 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/box_and_band/multi_threaded")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.5 µs for one, 23 µs for 100, 2.1 ms for 10⁴,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "boxes_with_bands/1")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.5 µs for one, 23 µs for 100, 2.1 ms for 10⁴,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "boxes_with_bands/100")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "5.5 µs for one, 23 µs for 100, 2.1 ms for 10⁴,",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "boxes_with_bands/10000")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "49 ms for 10⁵",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "boxes_with_bands/100000")],
        column: "estimate",
        format: "f0",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "tutorial 6.9 → 13.2 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/tutorial/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "tutorial 6.9 → 13.2 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/tutorial/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/benchmarks.md",
        words: "7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/tutorial/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/tutorial/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/off")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/lab.md",
        words: "6.9 → 13.2 µs, the stiff scene (k = 1e5) 7.1 → 16.8 µs, k = 1e12 7.2 → 13.9 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "ghosts/stiff-k1e12/on")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "in lanes, the same machine): k = 1e6 at 100 Hz 31.9 µs, at 64 Hz 29.9 µs; k = 1e7 at 100 Hz",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e6/100Hz/5ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "in lanes, the same machine): k = 1e6 at 100 Hz 31.9 µs, at 64 Hz 29.9 µs; k = 1e7 at 100 Hz",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e6/64Hz/3ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "38.4 µs, at 64 Hz 30.1 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e7/100Hz/2ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "38.4 µs, at 64 Hz 30.1 µs.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "stiff_auto/k1e7/64Hz/1ticks")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "took 19.5 µs as run and 33.0 µs portable at 100 Hz, 30.2 and 56.4 µs at 64 Hz.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/100Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "took 19.5 µs as run and 33.0 µs portable at 100 Hz, 30.2 and 56.4 µs at 64 Hz.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/100Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "took 19.5 µs as run and 33.0 µs portable at 100 Hz, 30.2 and 56.4 µs at 64 Hz.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/64Hz/as_run")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "took 19.5 µs as run and 33.0 µs portable at 100 Hz, 30.2 and 56.4 µs at 64 Hz.",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "taylor_lanes/k1e7/64Hz/portable")],
        column: "estimate",
        format: "f1",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(4.83 against the empty `App`'s 4.61 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/one_empty_fixed_system/single_threaded")],
        column: "estimate",
        format: "f2",
    },
    Quoted {
        page: "docs/peers.md",
        words: "(4.83 against the empty `App`'s 4.61 µs",
        file: "2026-11-27-bench.txt",
        row: &[("bench", "app_tick/empty/single_threaded")],
        column: "estimate",
        format: "f2",
    },
];

#[test]
fn every_quoted_figure_is_its_snapshots_cell() {
    let mut wrong = Vec::new();
    for quoted in QUOTED {
        let page = fs::read_to_string(root().join(quoted.page)).expect("a page");
        let rows = read_rows(&snapshots().join(quoted.file)).expect("a snapshot");
        let filters: Vec<(String, Vec<String>)> = quoted
            .row
            .iter()
            .map(|(c, v)| ((*c).to_owned(), vec![(*v).to_owned()]))
            .collect();
        let picked = select(&rows, &filters);
        let [row] = picked.as_slice() else {
            wrong.push(format!(
                "{}: {} rows of {} match {:?}",
                quoted.page,
                picked.len(),
                quoted.file,
                quoted.row
            ));
            continue;
        };
        let number = row[quoted.column].parse::<f64>();
        let value = match quoted.format {
            // Their tick at least three times ours: "under a third".
            "third" => match number {
                Ok(ratio) if ratio >= 3.0 => "under a third".to_owned(),
                _ => format!("not under a third ({})", row[quoted.column]),
            },
            f => format(&row[quoted.column], f),
        };
        if !quoted.words.contains(&value) {
            wrong.push(format!(
                "{}: '{}' does not hold {value}, the {} of {} {:?}",
                quoted.page, quoted.words, quoted.column, quoted.file, quoted.row
            ));
        } else if !page.contains(quoted.words) {
            wrong.push(format!(
                "{}: no longer says '{}'",
                quoted.page, quoted.words
            ));
        }
    }
    assert!(
        wrong.is_empty(),
        "figures off their snapshots:\n{}",
        wrong.join("\n")
    );
}

/// The block reader renders a table, and sees a stale one.
#[test]
fn a_block_renders_from_its_csv_and_a_changed_one_is_stale() {
    let marker = parse_marker(
        "2026-11-25-report/engines.csv; k=1e6; engine=taylor 20 1e-10|dop853 1e-11; \
         show=k:k:k,engine,error_px:e:error (px),ns_per_tick:us:µs",
    )
    .unwrap();
    let table = render(&marker).unwrap();
    let lines: Vec<&str> = table.lines().collect();
    assert_eq!(lines[0], "| k | engine | error (px) | µs |");
    assert_eq!(lines.len(), 4, "{table}");
    assert!(lines[2].starts_with("| 1e6 | "), "{table}");
    let page = format!(
        "text\n{OPEN}2026-11-25-report/engines.csv; k=1e6; engine=dop853 1e-11; \
         show=ns_per_tick:us -->\n| ns_per_tick |\n|---|\n| 1.0 |\n{CLOSE}\nmore"
    );
    let (fresh, blocks) = refreshed(&page).unwrap();
    assert_eq!(blocks, 1);
    assert_ne!(fresh, page, "a changed figure is seen");
    assert_eq!(refreshed(&fresh).unwrap().0, fresh, "a fresh block stays");
    assert!(fresh.ends_with(&format!("{CLOSE}\nmore")));
}

/// The replay docs quote the cross-platform fixture's own end: its steps and its hash.
#[test]
fn the_replay_docs_quote_the_fixtures_end() {
    let fixture = fs::read_to_string(root().join("tests/fixtures/cross-platform.jsonl"))
        .expect("the fixture");
    let end = fixture.lines().last().expect("an end line");
    let field = |name: &str| {
        let from = end.find(&format!("\"{name}\":")).expect("a field") + name.len() + 3;
        end[from..]
            .trim_start_matches('"')
            .split(['"', ',', '}'])
            .next()
            .unwrap()
            .to_owned()
    };
    let (steps, hash) = (field("steps"), field("hash"));
    assert_eq!(hash.len(), 16, "{end}");
    let docs = fs::read_to_string(root().join("docs/replays.md")).expect("docs/replays.md");
    assert!(
        docs.contains(&format!("replay over: {steps} steps")),
        "steps {steps}"
    );
    assert!(docs.contains(&format!("(hash {hash})")), "hash {hash}");
}

// ---------------------------------------------------------------------------------------------
// Every figure names its snapshot where a reader sees it, and none from a superseded snapshot is
// called current.

/// Returns the snapshots snapshots/README.md lists, in its order: the first cell of each row,
/// a link's text or a name in backticks (`2026-11-25-report/repeat-2/` belongs to its report).
fn listed_snapshots() -> Vec<String> {
    let readme = fs::read_to_string(snapshots().join("README.md")).expect("snapshots/README.md");
    readme
        .lines()
        .filter(|line| line.starts_with("| [") || line.starts_with("| `"))
        .filter_map(|line| {
            let cell = line.trim_start_matches("| ");
            let name = match cell.strip_prefix('[') {
                Some(link) => link.split(']').next()?,
                None => cell.trim_start_matches('`').split('`').next()?,
            };
            Some(name.split(',').next()?.trim_end_matches('/').to_owned())
        })
        .collect()
}

/// Returns a snapshot's name as the pages write it: its folder, or its file without `.txt`.
fn snapshot_name(file: &str) -> String {
    let first = file.split('/').next().unwrap_or(file);
    first.trim_end_matches(".txt").to_owned()
}

/// Returns a snapshot's kind, which a newer of the same kind supersedes: a report, a
/// criterion run, a mutation run or a real-time measure.
fn snapshot_kind(name: &str) -> &'static str {
    ["report", "bench", "mutants", "real-time"]
        .into_iter()
        .find(|kind| name.contains(kind))
        .unwrap_or("other")
}

/// Returns the snapshot that supersedes `name`, if any: the last listed of its kind.
fn superseded_by(name: &str, listed: &[String]) -> Option<String> {
    let newest = listed
        .iter()
        .rev()
        .find(|other| snapshot_kind(other) == snapshot_kind(name) && !other.contains('/'))?;
    (snapshot_name(newest) != name).then(|| snapshot_name(newest))
}

/// Words that call a figure current; a figure from a superseded snapshot must not stand under
/// them.
const CURRENT: [&str; 6] = [
    "the snapshot",
    "now",
    "today",
    "newest",
    "latest",
    "current",
];

/// Returns the paragraph of `page` that holds byte `at`: the lines between blank lines.
fn paragraph_at(page: &str, at: usize) -> &str {
    let start = page[..at].rfind("\n\n").map_or(0, |i| i + 2);
    let end = page[at..].find("\n\n").map_or(page.len(), |i| at + i);
    &page[start..end]
}

/// Tells whether `text` holds `word` as a word of its own, whatever its case.
fn holds_word(text: &str, word: &str) -> bool {
    let text = text.to_lowercase();
    text.match_indices(word).any(|(at, _)| {
        let before = text[..at].chars().next_back();
        let after = text[at + word.len()..].chars().next();
        !before.is_some_and(char::is_alphanumeric) && !after.is_some_and(char::is_alphanumeric)
    })
}

/// Returns what is wrong with a figure from `file` quoted in `paragraph`: its snapshot not
/// named there, or a superseded snapshot called current.
fn figure_problems(paragraph: &str, file: &str, listed: &[String]) -> Vec<String> {
    let name = snapshot_name(file);
    let mut problems = Vec::new();
    if !paragraph.contains(&name) {
        problems.push(format!("does not name its snapshot, {name}"));
    }
    if let Some(newer) = superseded_by(&name, listed) {
        for word in CURRENT.iter().filter(|word| holds_word(paragraph, word)) {
            problems.push(format!(
                "says \"{word}\" over a figure of {name}, which {newer} supersedes"
            ));
        }
    }
    problems
}

/// Returns every generated block of a page: the byte where its marker opens, and its file.
fn blocks_of(page: &str) -> Vec<(usize, String)> {
    page.match_indices(OPEN)
        .filter(|(at, _)| *at == 0 || page[..*at].ends_with('\n'))
        .filter_map(|(at, _)| {
            let head = &page[at + OPEN.len()..];
            let marker = parse_marker(head[..head.find("-->")?].trim()).ok()?;
            Some((at, marker.file))
        })
        .collect()
}

#[test]
fn every_figure_names_its_snapshot_and_none_superseded_is_called_current() {
    let listed = listed_snapshots();
    assert!(listed.len() >= 10, "the reader found the list: {listed:?}");
    let mut wrong = Vec::new();
    for quoted in QUOTED {
        let page = fs::read_to_string(root().join(quoted.page)).expect("a page");
        let Some(at) = page.find(quoted.words) else {
            continue; // The figures test names a page that no longer says it.
        };
        for problem in figure_problems(paragraph_at(&page, at), quoted.file, &listed) {
            wrong.push(format!("{}: '{}' {problem}", quoted.page, quoted.words));
        }
    }
    let mut blocks = 0;
    for path in pages() {
        let page = fs::read_to_string(&path).expect("a page");
        for (at, file) in blocks_of(&page) {
            blocks += 1;
            // The block's own paragraph is the marker; the reader's is the one before it.
            let before = page[..at].trim_end();
            let paragraph = paragraph_at(before, before.len().saturating_sub(1));
            for problem in figure_problems(paragraph, &file, &listed) {
                wrong.push(format!("{}: the table of {file} {problem}", path.display()));
            }
        }
    }
    assert!(blocks >= 2, "the reader found the blocks ({blocks})");
    assert!(
        wrong.is_empty(),
        "figures whose snapshot a reader cannot see or that are called current when a newer \
         snapshot supersedes theirs:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn the_snapshot_check_fails_a_superseded_figure_called_current_and_an_unnamed_one() {
    let listed: Vec<String> = [
        "2026-11-25-report",
        "2026-11-25-bench-2.txt",
        "2026-11-27-report",
    ]
    .map(str::to_owned)
    .to_vec();
    let file = "2026-11-25-report/peers.csv";
    // The 2026-11-25 report's figure under "the snapshot", with a newer report listed.
    let stale = "The snapshot (2026-11-25-report) ends 1.9e-11 px off.";
    assert_eq!(figure_problems(stale, file, &listed).len(), 1);
    assert!(figure_problems(stale, file, &listed)[0].contains("2026-11-27-report supersedes"));
    // The same figure as history passes; with no name it fails.
    let history = "On 2026-11-25 (2026-11-25-report) it ended 1.9e-11 px off.";
    assert!(figure_problems(history, file, &listed).is_empty());
    assert_eq!(
        figure_problems("It ends 1.9e-11 px off.", file, &listed).len(),
        1
    );
    // The newest may be called current; "known" holds no "now".
    let newest = "The newest run, 2026-11-27-report, is known to end 2.0e-11 px off now.";
    assert!(figure_problems(newest, "2026-11-27-report/peers.csv", &listed).is_empty());
    assert_eq!(
        snapshot_name("2026-11-25-bench-2.txt"),
        "2026-11-25-bench-2"
    );
    assert_eq!(superseded_by("2026-11-25-bench-2", &listed), None);
}

#[test]
fn snapshots_readme_lists_every_snapshot() {
    let listed = listed_snapshots();
    let mut missing = Vec::new();
    for entry in fs::read_dir(snapshots()).expect("docs/snapshots") {
        let name = entry
            .expect("an entry")
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name != "README.md" && !listed.contains(&name) {
            missing.push(name);
        }
    }
    assert!(
        missing.is_empty(),
        "docs/snapshots/README.md does not list {missing:?}"
    );
}
