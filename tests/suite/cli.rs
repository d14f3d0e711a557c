//! The `simulate` command, run as a user runs it.

use crate::common;

use std::process::Output;

use rubber_band_box::physics::Integrator;
use rubber_band_box::replay::run::ReplayRun;

fn simulate(args: &[&str]) -> Output {
    common::binary("simulate")
        .args(args)
        .output()
        .expect("the binary runs")
}

fn stdout(output: &Output) -> String {
    String::from_utf8(output.stdout.clone()).unwrap()
}

fn stderr(output: &Output) -> String {
    String::from_utf8(output.stderr.clone()).unwrap()
}

#[test]
fn simulate_writes_a_header_and_a_row_per_step_from_the_initial_state() {
    let output = simulate(&["--steps", "10"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let lines: Vec<&str> = text.lines().collect();
    assert!(lines[0].starts_with("step,t,x,y,theta,vx,vy,omega,energy"));
    assert_eq!(lines.len(), 1 + 11);
    let row0: Vec<f64> = lines[1].split(',').map(|v| v.parse().unwrap()).collect();
    assert_eq!(&row0[..8], &[0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let last: Vec<f64> = lines[11].split(',').map(|v| v.parse().unwrap()).collect();
    assert_eq!(last[0], 10.0);
    assert!((last[1] - 0.1).abs() < 1e-12);
    // The tutorial scene pulls up and to the right.
    assert!(last[2] > 0.0 && last[3] > 0.0);
}

#[test]
fn simulate_is_bit_identical_across_runs() {
    let args = [
        "--integrator",
        "rk4",
        "--steps",
        "300",
        "--pull",
        "0:100:-200,80",
        "--pull",
        "150:250:100,-150",
    ];
    let first = simulate(&args);
    let second = simulate(&args);
    assert!(first.status.success());
    assert_eq!(first.stdout, second.stdout);
}

#[test]
fn simulate_applies_overrides_initial_state_and_pulls() {
    let output = simulate(&[
        "--scene",
        "rest",
        "--integrator",
        "symplectic",
        "--init",
        "10,-20,0.5,3,4,-1",
        "--linear-damping",
        "0",
        "--angular-damping",
        "0",
        "--steps",
        "2",
        "--dt",
        "0.5",
    ]);
    assert!(output.status.success(), "{}", stderr(&output));
    let text = stdout(&output);
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(&rows[0][2..8], &[10.0, -20.0, 0.5, 3.0, 4.0, -1.0]);
    // No force: uniform motion.
    assert_eq!(&rows[2][2..8], &[13.0, -16.0, -0.5, 3.0, 4.0, -1.0]);
}

#[test]
fn a_pull_pulls_only_during_its_steps() {
    let output = simulate(&["--scene", "rest", "--steps", "6", "--pull", "2:4:100,0"]);
    assert!(output.status.success());
    let text = stdout(&output);
    let column = text
        .lines()
        .next()
        .unwrap()
        .split(',')
        .position(|name| name == "band")
        .unwrap();
    let band: Vec<&str> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').nth(column).unwrap())
        .collect();
    // Row s shows whether the band pulls during step s (from row s to row s + 1).
    assert_eq!(band, ["0", "0", "1", "1", "0", "0", "0"]);
}

#[test]
fn bad_arguments_get_a_clear_message_naming_the_flag_and_status_2() {
    let cases: &[(&[&str], &str)] = &[
        (&["--scene", "moon"], "unknown scene 'moon'"),
        (&["--integrator", "rk5"], "unknown integrator 'rk5'"),
        (&["--dt", "NaN"], "not a finite number"),
        (&["--dt", "0"], "greater than zero"),
        (&["--mass", "-5"], "greater than zero"),
        (&["--width", "0"], "greater than zero"),
        (&["--k", "-1"], "zero or more"),
        (&["--angular-damping", "inf"], "not a finite number"),
        (&["--pull", "10:5:1,2"], "must end after it starts"),
        (&["--pull", "0:5"], "expected START:END:X,Y"),
        (&["--pull", "0:5:1"], "expected X,Y"),
        (&["--pull", "a:5:1,2"], "not a step number"),
        (&["--init", "1,2,3"], "expected X,Y,THETA,VX,VY,OMEGA"),
        (&["--steps", "-3"], "--steps"),
        (&["--k", "abc"], "'abc' is not a number"),
        (&["--auto-max-substeps", "0"], "--auto-max-substeps"),
        (&["--auto-tolerance", "-1e-8"], "greater than zero"),
        (&["--frobnicate"], "--frobnicate"),
    ];
    for (args, message) in cases {
        let output = simulate(args);
        // docs/simulate.md: a bad argument exits with status 2 (not 1, nor a panic's 101).
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(output.stdout.is_empty(), "{args:?} wrote output");
        let err = stderr(&output);
        assert!(err.contains(message), "{args:?}: {err}");
        // ... with a message naming it: each case's first word is the flag at fault (clap
        // writes "invalid value '0' for '--dt <DT>'", or "unexpected argument '--frobnicate'").
        let flag = args[0];
        assert!(err.contains(flag), "{args:?}: {flag} not named in {err}");
        assert!(!err.contains("panicked"), "{args:?}: {err}");
    }
}

#[test]
fn a_mass_too_small_for_its_size_is_refused_by_validation() {
    let output = simulate(&[
        "--mass", "1e-300", "--width", "1e-200", "--height", "1e-200",
    ]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("moment of inertia"),
        "{}",
        stderr(&output)
    );
}

#[test]
fn a_divergence_is_reported_with_the_integrator_and_step() {
    let output = simulate(&["--scene", "stiff", "--k", "1e9", "--integrator", "euler"]);
    assert_eq!(output.status.code(), Some(3));
    let err = stderr(&output);
    assert!(err.contains("integrator euler diverged at step"), "{err}");
    // The rows before the divergence were written, all finite.
    let text = stdout(&output);
    assert!(text.lines().count() > 1);
    assert!(!text.contains("NaN") && !text.contains("inf"));
}

#[test]
fn a_failed_write_is_reported_not_panicked() {
    let Ok(full) = std::fs::File::create("/dev/full") else {
        return; // not on this system
    };
    let output = common::binary("simulate")
        .args(["--steps", "100000"])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let err = stderr(&output);
    assert!(err.contains("cannot write the trajectory"), "{err}");
}

#[test]
fn the_report_says_when_it_cannot_write_its_files() {
    let output = common::binary("report")
        .args(["--quick", "--out", "/dev/null/report"])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(1));
    let err = stderr(&output);
    assert!(
        err.starts_with("error: ") && !err.contains("panicked"),
        "{err}"
    );
}

/// The named scenes live once, in the core (`Scene::NAMES`): docs/simulate.md's `--scene` row and the
/// CLI's help name each of them, and the CLI accepts each.
#[test]
fn the_docs_and_the_help_name_every_scene_the_core_has() {
    use rubber_band_box::physics::Scene;
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/simulate.md"))
        .expect("docs/simulate.md");
    let row = page
        .lines()
        .find(|line| line.starts_with("| `--scene NAME` |"))
        .expect("docs/simulate.md documents --scene");
    let listed = row.matches("`").count() / 2 - 1;
    assert_eq!(listed, Scene::NAMES.len(), "{row}");
    let help = common::binary("simulate")
        .arg("--help")
        .output()
        .expect("the binary runs");
    let help = String::from_utf8_lossy(&help.stdout).replace('\n', " ");
    for name in Scene::NAMES {
        assert!(
            row.contains(&format!("`{name}`")),
            "docs/simulate.md lacks {name}"
        );
        assert!(help.contains(name), "--help lacks {name}");
        assert!(
            simulate(&["--scene", name, "--steps", "1"])
                .status
                .success()
        );
    }
}

/// Input the core refuses before any step: named, status 2, no row written. A state beyond
/// the bounds a step is held to, or one whose energy overflows, is bad input, not a
/// divergence at step 1; a sub-normal step is named as the step, not as an infinite rate.
#[test]
fn an_initial_state_out_of_bounds_and_a_sub_normal_dt_are_refused_as_arguments() {
    let cases: &[(&[&str], &str)] = &[
        (&["--init", "2e12,0,0,0,0,0"], "initial state"),
        (&["--init", "0,0,0,0,0,-1e13"], "initial state"),
        (
            &["--init", "1e11,0,0,1e11,0,0", "--k", "1e300"],
            "initial energy",
        ),
        (&["--dt", "1e-310"], "at least 1e-6 s"),
        (&["--dt", "1e-7"], "at least 1e-6 s"),
    ];
    for (args, message) in cases {
        let output = simulate(args);
        assert_eq!(output.status.code(), Some(2), "{args:?}");
        assert!(output.stdout.is_empty(), "{args:?} wrote output");
        let err = stderr(&output);
        assert!(err.contains(message), "{args:?}: {err}");
        assert!(
            !err.contains("diverged") && !err.contains("step rate"),
            "{args:?}: {err}"
        );
    }
}

/// The last row of `simulate` with `args`, as numbers.
fn last_row(args: &[&str]) -> Vec<f64> {
    let output = simulate(args);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
    let text = stdout(&output);
    let last = text.lines().last().unwrap();
    last.split(',').map(|v| v.parse().unwrap()).collect()
}

/// Each override changes the run as it says: the CSV equals a run built in the core with that
/// value and differs from the run without it.
#[test]
fn the_scene_overrides_change_what_they_name() {
    use rubber_band_box::physics::{Integrator, Run, Scene};
    let base = ["--integrator", "rk4", "--steps", "50"];
    let plain = last_row(&base);
    for (flag, value) in [
        ("--k", 40.0),
        ("--mass", 2.0),
        ("--width", 30.0),
        ("--height", 90.0),
        ("--linear-damping", 0.5),
        ("--angular-damping", 7.0),
    ] {
        let mut args = base.to_vec();
        let text = value.to_string();
        args.extend([flag, text.as_str()]);
        let row = last_row(&args);
        assert_ne!(row[2..8], plain[2..8], "{flag} changed nothing");
        let scene = Scene::named("tutorial").unwrap();
        let mut params = scene.params;
        match flag {
            "--k" => params.stiffness = value,
            "--mass" => params.mass = value,
            "--width" => params.size.x = value,
            "--height" => params.size.y = value,
            "--linear-damping" => params.linear_damping = value,
            _ => params.angular_damping = value,
        }
        let mut run = Run::new(
            params,
            scene.initial,
            scene.pulls_in_steps(0.01),
            Integrator::Rk4,
            0.01,
        )
        .unwrap();
        run.advance_by(50).unwrap();
        assert_eq!(row[2..8], run.stepper.state.to_array(), "{flag}");
    }
}

/// `auto`'s settings reach `auto`: a looser tolerance takes fewer Taylor steps; a low order
/// needs more steps than the budget allows on the stiff scene, and so does a budget of one.
#[test]
fn the_auto_overrides_change_autos_steps() {
    let stiff = ["--scene", "stiff", "--steps", "5"];
    let column = |args: &[&str], index: usize| last_row(args)[index];
    let (substeps, fallbacks) = (10, 11);
    let with = |extra: &[&'static str]| {
        let mut args = stiff.to_vec();
        args.extend_from_slice(extra);
        args
    };
    let default_steps = column(&stiff, substeps);
    assert!(default_steps > 1.0);
    assert!(column(&with(&["--auto-tolerance", "1e-2"]), substeps) < default_steps);
    assert_eq!(column(&stiff, fallbacks), 0.0);
    assert!(column(&with(&["--auto-order", "6"]), fallbacks) > 0.0);
    assert_eq!(column(&with(&["--auto-max-substeps", "1"]), fallbacks), 5.0);
}

/// docs/simulate.md's table of `simulate`'s options and `simulate --help` name the same options.
#[test]
fn the_docs_document_exactly_the_options_simulate_has() {
    let page = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/simulate.md"))
        .expect("docs/simulate.md");
    let section = page
        .split("\n## Simulate\n")
        .nth(1)
        .and_then(|rest| rest.split("\n## ").next())
        .expect("docs/simulate.md has a Simulate section");
    let flags = |text: &str| -> std::collections::BTreeSet<String> {
        text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
            .filter(|word| word.starts_with("--") && word.len() > 2)
            .map(str::to_owned)
            .collect()
    };
    let documented = flags(
        &section
            .lines()
            .filter(|line| line.starts_with("| `--"))
            .map(|line| line.split('|').nth(1).unwrap_or(""))
            .collect::<Vec<_>>()
            .join(" "),
    );
    let output = common::binary("simulate")
        .arg("--help")
        .output()
        .expect("the binary runs");
    let mut offered = flags(&String::from_utf8_lossy(&output.stdout));
    offered.remove("--help");
    assert_eq!(documented, offered);
}

/// A replay file in a scratch folder of this test process.
fn replay_file(name: &str, text: &str) -> std::path::PathBuf {
    let path = common::scratch(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// `simulate --replay` writes a row per recorded step, and `--hash` the recording's own hash
/// (its states are the recorded ones); another integrator gives another hash.
#[test]
fn simulate_replays_a_recording_and_hashes_its_states() {
    let replay = common::small_replay();
    let text = String::from_utf8(replay.to_bytes()).unwrap();
    let path = replay_file("small.jsonl", &text);
    let file = path.to_str().unwrap();

    let output = simulate(&["--replay", file]);
    assert!(output.status.success(), "{}", stderr(&output));
    let rows: Vec<String> = stdout(&output).lines().map(str::to_owned).collect();
    assert_eq!(rows.len(), 2 + 12);
    assert!(rows[1].starts_with("0,0,"));
    let last: Vec<&str> = rows[13].split(',').collect();
    let mut run = ReplayRun::new(&replay, None).unwrap();
    run.finish();
    let [x, y, ..] = run.stepper.state.to_array();
    assert_eq!(
        (last[0], last[2], last[3]),
        ("12", &*x.to_string(), &*y.to_string())
    );

    let output = simulate(&["--replay", file, "--hash"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert_eq!(stdout(&output), format!("{}\n", replay.hash));

    let output = simulate(&["--replay", file, "--hash", "--integrator", "rk4"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let rk4 = ReplayRun::new(&replay, Some(Integrator::Rk4))
        .unwrap()
        .finish();
    assert_eq!(stdout(&output), format!("{rk4}\n"));
    assert_ne!(rk4, replay.hash);
}

/// A recording whose states this build does not reproduce fails with status 4; a bad file,
/// a missing one, or a scene option beside `--replay` with status 2 and a message.
#[test]
fn simulate_refuses_bad_replays_and_reports_a_mismatch() {
    let text = String::from_utf8(common::small_replay().to_bytes()).unwrap();
    let hash = text.rsplit("\"hash\":\"").next().unwrap()[..16].to_owned();
    let first = if hash.starts_with('0') { "1" } else { "0" };
    let tampered = replay_file(
        "tampered.jsonl",
        &text.replace(&hash, &format!("{first}{}", &hash[1..])),
    );
    let output = simulate(&["--replay", tampered.to_str().unwrap(), "--hash"]);
    assert_eq!(output.status.code(), Some(4), "{}", stderr(&output));
    assert!(stderr(&output).contains("the states differ from the recorded game's"));

    let truncated = replay_file("truncated.jsonl", &text[..text.len() / 2]);
    let output = simulate(&["--replay", truncated.to_str().unwrap()]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("truncated.jsonl: line "),
        "{}",
        stderr(&output)
    );

    let output = simulate(&["--replay", "/no/such/replay.jsonl"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("cannot open"),
        "{}",
        stderr(&output)
    );

    let output = simulate(&["--replay", truncated.to_str().unwrap(), "--k", "5"]);
    assert_eq!(output.status.code(), Some(2));
    assert!(
        stderr(&output).contains("cannot be used with"),
        "{}",
        stderr(&output)
    );
}
