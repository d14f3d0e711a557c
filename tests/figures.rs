//! Every figure docs/ quotes from a run is the snapshot's: the committed output of the command
//! that measured it (docs/snapshots/). Two ways keep them so:
//! - a generated block, a table rendered from a snapshot's CSV between
//!   `<!-- figures: FILE; COLUMN=VALUE|VALUE; show=COLUMN:FORMAT:LABEL,... -->` and
//!   `<!-- /figures -->`, which this test compares with what the CSV renders to today, and
//!   rewrites when run as `RBB_WRITE_FIGURES=1 cargo test --test figures` (the one command that
//!   refreshes them after a new snapshot: point the marker at it);
//! - a figure in prose, listed in [`QUOTED`] with the cell it comes from: the page must hold the
//!   words, and the words the cell's value as the page prints it.

mod pages;

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
         RBB_WRITE_FIGURES=1 cargo test --test figures",
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
    // integrators.md: the case for the default.
    Quoted {
        page: "docs/integrators.md",
        words: "6.8e-11 px at 1e5",
        file: "2026-11-25-report/stiffness.csv",
        row: &[("k", "1e5"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "8.4e-9 px at 1e6",
        file: "2026-11-25-report/stiffness.csv",
        row: &[("k", "1e6"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "6.7e-5 px at 1e7",
        file: "2026-11-25-report/stiffness.csv",
        row: &[("k", "1e7"), ("rate_hz", "100"), ("integrator", "auto")],
        column: "error_px",
        format: "e",
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
        words: "1.9e-11 px at 100 Hz",
        file: "2026-11-25-report/work_precision.csv",
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
        words: "(8.4e-9 px at k = 1e6: 11.6 µs",
        file: "2026-11-25-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "taylor 20 1e-10")],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "against 39.3 for DOP853",
        file: "2026-11-25-report/engines.csv",
        row: &[("k", "1e6"), ("engine", "dop853 1e-11")],
        column: "ns_per_tick",
        format: "us",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "2.3e-11 px at 64 Hz",
        file: "2026-11-25-report/work_precision.csv",
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
        file: "2026-11-25-report/work_precision.csv",
        row: &[("scene", "tutorial"), ("integrator", "rk4"), ("dt", "0.01")],
        column: "error_px",
        format: "e",
    },
    Quoted {
        page: "docs/integrators.md",
        words: "`implicit` is 15 px off",
        file: "2026-11-25-report/work_precision.csv",
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
        file: "2026-11-25-report/peers.csv",
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
        words: "costs 3.1 to 3.6 times ours",
        file: "2026-11-25-report/peers.csv",
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
        words: "ours by 2.5e-15 at 100 Hz",
        file: "2026-11-25-report/peers.csv",
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
        words: "and 5.0e-15 at 64 Hz",
        file: "2026-11-25-report/peers.csv",
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
        words: "1.92 to 2.10 times ours at 100 Hz",
        file: "2026-11-25-report/peers.csv",
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
    Quoted {
        page: "README.md",
        words: "1.9e-11 px from the converged answer after 4 s",
        file: "2026-11-25-report/peers.csv",
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
        file: "2026-11-25-report/peers.csv",
        row: &[
            ("scene", "tutorial"),
            ("rate_hz", "100"),
            ("contender", "avian2d"),
        ],
        column: "tick_over_ours",
        format: "third",
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
