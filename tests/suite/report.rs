//! The report's quick mode as CI's smoke test: it runs, and its files exist and parse.

use crate::common;

use std::ffi::OsStr;
use std::fs;
use std::process::Output;

/// `report` with `args`, run as a user runs it.
fn report(args: impl IntoIterator<Item = impl AsRef<OsStr>>) -> Output {
    common::binary("report").args(args).output().unwrap()
}

#[test]
fn the_quick_report_writes_tables_and_a_plot_that_parse() {
    let out = common::scratch("report");
    let output = report([OsStr::new("--quick"), OsStr::new("--out"), out.as_os_str()]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let printed = String::from_utf8(output.stdout).unwrap();
    assert!(printed.contains("## Work-precision") && printed.contains("## Stability"));

    let csv = |name: &str, columns: usize| -> Vec<Vec<String>> {
        let text = fs::read_to_string(out.join(name)).unwrap();
        let rows: Vec<Vec<String>> = text
            .lines()
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect();
        assert!(rows.len() > 1, "{name} has no rows");
        for row in &rows {
            assert_eq!(row.len(), columns, "{name}: {row:?}");
        }
        rows
    };
    // The quick sweep's cases with a horizon (k = 20 and 1e5, both rates), each over anchors.
    let anchors = csv("anchors.csv", 8);
    assert_eq!(anchors.len() - 1, 4);
    assert!(anchors[1..].iter().all(|row| row[3] == "5"), "{anchors:?}");
    let work = csv("work_precision.csv", 8);
    // scenes x steps x integrators, each with a finite cost and an error or a divergence.
    assert_eq!(work.len() - 1, 4 * 3 * 7);
    for row in &work[1..] {
        let cost: f64 = row[6].parse().unwrap();
        assert!(cost.is_finite() && cost > 0.0);
        assert!(
            row[4].parse::<f64>().is_ok() || row[7].parse::<u64>().is_ok(),
            "{row:?}"
        );
    }
    let stability = csv("stability.csv", 4);
    assert_eq!(stability.len() - 1, 2 * 7);
    let implicit: Vec<_> = stability.iter().filter(|r| r[0] == "implicit").collect();
    assert!(
        implicit.iter().all(|r| r[2] == "inf"),
        "implicit is stable at every k"
    );
    let euler_100: f64 = stability
        .iter()
        .find(|r| r[0] == "euler" && r[1] == "100")
        .unwrap()[2]
        .parse()
        .unwrap();
    assert!(euler_100 > 1.0 && euler_100 < 1e4, "{euler_100}");

    let svg = fs::read_to_string(out.join("work_precision.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("rk4") && svg.contains("diverged"));
    fs::remove_dir_all(&out).ok();
}

#[cfg(not(feature = "peers"))]
#[test]
fn asking_for_the_peers_without_them_says_how_to_get_them() {
    let out = common::scratch("no-peers");
    let output = report([
        OsStr::new("--quick"),
        OsStr::new("--peers"),
        OsStr::new("--out"),
        out.as_os_str(),
    ]);
    assert!(!output.status.success());
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(message.contains("--features peers"), "{message}");
}

/// The quick report's files in a fresh folder: (work precision, stability, report.md).
fn quick_report(tag: &str) -> (Vec<Vec<String>>, Vec<Vec<String>>, String) {
    let out = common::scratch(&format!("report-{tag}"));
    let output = report([OsStr::new("--quick"), OsStr::new("--out"), out.as_os_str()]);
    assert!(output.status.success());
    let rows = |name: &str| -> Vec<Vec<String>> {
        fs::read_to_string(out.join(name))
            .unwrap()
            .lines()
            .skip(1)
            .map(|l| l.split(',').map(str::to_owned).collect())
            .collect()
    };
    let files = (
        rows("work_precision.csv"),
        rows("stability.csv"),
        fs::read_to_string(out.join("report.md")).unwrap(),
    );
    fs::remove_dir_all(&out).ok();
    files
}

/// What docs/report.md says the report shows, as orderings and bounds the report could break: on the
/// tutorial scene `auto` beats `rk4` beats `verlet` beats the first-order methods at every
/// step, `rk4` and `verlet` converge at their orders, the stability table orders the methods
/// as their stability regions do, and `auto`'s energy books balance to 1e-6.
#[test]
fn the_quick_report_bears_out_the_claims_readme_makes() {
    let (work, stability, markdown) = quick_report("claims");
    let error = |integrator: &str, dt: &str| -> f64 {
        let row = work
            .iter()
            .find(|r| r[0] == "tutorial" && r[1] == integrator && r[2] == dt)
            .unwrap_or_else(|| panic!("tutorial {integrator} {dt}"));
        row[4].parse().unwrap_or(f64::INFINITY)
    };
    let steps: Vec<String> = work
        .iter()
        .filter(|r| r[0] == "tutorial" && r[1] == "rk4")
        .map(|r| r[2].clone())
        .collect();
    assert_eq!(steps.len(), 3);
    for dt in &steps {
        let ranked = ["auto", "rk4", "verlet", "symplectic", "euler"].map(|i| error(i, dt));
        assert!(
            ranked.windows(2).all(|w| w[0] < w[1]),
            "dt {dt}: {ranked:?}"
        );
        assert!(ranked[0] < 1e-9, "auto at dt {dt}: {}", ranked[0]);
    }
    // From 0.01 s to 0.001 s: ten times smaller steps, 10^order times smaller error.
    for (integrator, order) in [("rk4", 4.0), ("verlet", 2.0), ("euler", 1.0)] {
        let observed = (error(integrator, "0.01") / error(integrator, "0.001")).log10();
        assert!((observed - order).abs() < 0.3, "{integrator}: {observed}");
    }

    let largest_k = |integrator: &str, rate: &str| -> f64 {
        let row = stability
            .iter()
            .find(|r| r[0] == integrator && r[1] == rate)
            .unwrap();
        row[2].parse().unwrap()
    };
    let omega_dt = |integrator: &str, rate: &str| -> f64 {
        let row = stability
            .iter()
            .find(|r| r[0] == integrator && r[1] == rate)
            .unwrap();
        row[3].parse().unwrap()
    };
    for rate in ["64", "100"] {
        let k = |i: &str| largest_k(i, rate);
        let w = |i: &str| omega_dt(i, rate);
        assert!(
            k("implicit").is_infinite() && k("auto").is_infinite(),
            "{rate} Hz"
        );
        // In ω·dt of the stiffest mode, 2√(k/m) at a corner: explicit Euler holds only while
        // damping outweighs its growth; the three second-order symplectic steps share the
        // linear limit of 2 (lowered by the box's swing); RK4's is 2.83, up to twice that once
        // the box hangs on the band's line, where the mode is half as fast.
        assert!(w("euler") < 0.5, "{rate} Hz: {}", w("euler"));
        let symplectic = ["symplectic", "verlet", "seed"].map(w);
        for limit in symplectic {
            assert!((1.5..=2.2).contains(&limit), "{rate} Hz: {symplectic:?}");
        }
        let rk4 = w("rk4");
        assert!((2.78..=2.0 * 2.83).contains(&rk4), "{rate} Hz: {rk4}");
        assert!(symplectic.iter().all(|&limit| limit < rk4), "{rate} Hz");
    }

    let ledger = markdown
        .split("## Energy ledger")
        .nth(1)
        .expect("the report has its ledger table");
    let auto_row = ledger
        .lines()
        .find(|l| l.starts_with("| auto |"))
        .expect("auto's row");
    let cells: Vec<f64> = auto_row
        .split('|')
        .map(str::trim)
        .filter(|c| !c.is_empty() && *c != "auto")
        .map(|c| c.parse().unwrap())
        .collect();
    assert_eq!(cells.len(), 2, "{auto_row}");
    assert!(cells.iter().all(|&r| r < 1e-6), "{auto_row}");
}

/// `report --replay` on a recorded drag: every integrator at the recorded rate and four times
/// it; `auto` within 1e-9 px of the reference, RK4 converging at its order between the two
/// rates, and a bad file refused with status 2 and the line.
#[test]
fn the_replay_report_sweeps_every_integrator_over_the_recorded_hand() {
    let folder = common::scratch("replay-report");
    fs::create_dir_all(&folder).unwrap();
    let file = folder.join("small.jsonl");
    fs::write(&file, common::small_replay().to_bytes()).unwrap();
    let output = report([
        OsStr::new("--quick"),
        OsStr::new("--out"),
        folder.as_os_str(),
        OsStr::new("--replay"),
        file.as_os_str(),
    ]);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let text = fs::read_to_string(folder.join("replay.csv")).unwrap();
    let rows: Vec<Vec<&str>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 7 * 2);
    let error = |integrator: &str, substeps: &str| -> f64 {
        let row = rows
            .iter()
            .find(|r| r[0] == integrator && r[1] == substeps)
            .unwrap();
        row[3].parse().unwrap()
    };
    assert!(error("auto", "1") < 1e-9, "{}", error("auto", "1"));
    let rk4_order = (error("rk4", "1") / error("rk4", "4")).log(4.0);
    assert!((rk4_order - 4.0).abs() < 0.5, "rk4's order {rk4_order}");

    let bad = folder.join("bad.jsonl");
    fs::write(&bad, "{}\n").unwrap();
    let output = report([OsStr::new("--replay"), bad.as_os_str()]);
    assert_eq!(output.status.code(), Some(2));
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(
        message.contains("bad.jsonl: line 1: not a replay header"),
        "{message}"
    );
}
