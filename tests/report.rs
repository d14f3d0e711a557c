//! The report's quick mode as CI's smoke test: it runs, and its files exist and parse.

use std::fs;
use std::process::Command;

#[test]
fn the_quick_report_writes_tables_and_a_plot_that_parse() {
    let out = std::env::temp_dir().join(format!("rubber-band-box-report-{}", std::process::id()));
    let output = Command::new(env!("CARGO_BIN_EXE_rubber_band_box"))
        .args(["report", "--quick", "--out"])
        .arg(&out)
        .output()
        .unwrap();
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
    let output = Command::new(env!("CARGO_BIN_EXE_rubber_band_box"))
        .args(["report", "--quick", "--peers", "--out"])
        .arg(std::env::temp_dir().join("rubber-band-box-no-peers"))
        .output()
        .unwrap();
    assert!(!output.status.success());
    let message = String::from_utf8_lossy(&output.stderr);
    assert!(message.contains("--features peers"), "{message}");
}
