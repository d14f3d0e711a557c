//! No input breaks the game: arbitrary bytes, arbitrary JSON and structured mutations of a
//! valid replay and a valid link, fed to the readers and, where they are taken, to a headless
//! game stepped several frames. Nothing panics, no component holds a NaN, and a refusal names
//! the line or the key it is about.
//!
//! `RBB_FUZZ_CASES` sets the cases per property (a few hundred by default, for CI; the long
//! run docs/testing.md quotes is `RBB_FUZZ_CASES=20000 cargo test --test suite fuzz::`).

use crate::common;

use std::time::Duration;

use proptest::prelude::*;
use serde_json::Value;

use crate::common::open_replay;
use common::{Game, small_replay};
use rubber_band_box::game::simulation::RigidBox;
use rubber_band_box::physics::{AngularState, LinearState, MassProperties, SceneParams};
use rubber_band_box::replay::Replay;
use rubber_band_box::replay::link::{Key, Link, decode_replay, encode_replay};

fn config() -> ProptestConfig {
    let cases = std::env::var("RBB_FUZZ_CASES")
        .ok()
        .and_then(|cases| cases.parse().ok())
        .unwrap_or(256);
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// Whatever a link took lies in the game's ranges.
fn in_range(link: &Link) -> bool {
    let numbers = [
        (Key::Stiffness, link.stiffness),
        (Key::Mass, link.mass),
        (Key::LinearDamping, link.linear_damping),
        (Key::AngularDamping, link.angular_damping),
        (Key::StepRate, link.step_rate_hz),
        (Key::TimeScale, link.time_scale),
    ];
    numbers.iter().all(|(key, value)| {
        value.is_none_or(|value| key.range().is_some_and(|range| range.contains(value)))
    })
}

/// Opens `replay` in a headless game and steps it: the box stays finite and the scene valid.
fn played_in_a_game(replay: Replay) -> Result<(), TestCaseError> {
    let mut game = Game::new(Duration::from_millis(16));
    open_replay(game.world(), replay);
    game.update(20);
    let world = game.world();
    prop_assert!(world.resource::<SceneParams>().check_playable().is_ok());
    let mut boxes = world.query_filtered::<(&LinearState, &AngularState, &MassProperties), bevy::prelude::With<RigidBox>>();
    for (linear, angular, mass) in boxes.iter(world) {
        prop_assert!(linear.position.is_finite() && linear.velocity.is_finite());
        prop_assert!(angular.orientation.is_finite() && angular.angular_velocity.is_finite());
        prop_assert!(mass.mass().is_finite());
    }
    Ok(())
}

/// The values a number is replaced by: the edges of every range, and beyond.
fn nasty_number() -> impl Strategy<Value = String> {
    prop_oneof![
        Just("0".to_owned()),
        Just("-0".to_owned()),
        Just("-0.0".to_owned()),
        Just("1e-300".to_owned()),
        Just("1e300".to_owned()),
        Just("-1e300".to_owned()),
        Just("1e999".to_owned()),
        Just("18446744073709551616".to_owned()),
        Just("99999999999999999999999999".to_owned()),
        Just("-1".to_owned()),
        Just("4097".to_owned()),
        Just("7.99".to_owned()),
        Just("NaN".to_owned()),
        any::<f64>().prop_map(|v| format!("{v:e}")),
        any::<i64>().prop_map(|v| v.to_string()),
    ]
}

/// A change to a valid replay's lines.
#[derive(Clone, Debug)]
enum Mutation {
    /// The `nth` number of line `line` replaced.
    Number {
        line: usize,
        nth: usize,
        value: String,
    },
    Swap(usize, usize),
    Repeat(usize),
    /// The file cut after this many lines.
    Cut(usize),
    /// The file cut after this many bytes.
    CutBytes(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        6 => (any::<usize>(), any::<usize>(), nasty_number())
            .prop_map(|(line, nth, value)| Mutation::Number { line, nth, value }),
        1 => (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::Swap(a, b)),
        1 => any::<usize>().prop_map(Mutation::Repeat),
        1 => any::<usize>().prop_map(Mutation::Cut),
        1 => any::<usize>().prop_map(Mutation::CutBytes),
    ]
}

/// The byte ranges of the numbers in a line of JSON.
fn numbers_in(line: &str) -> Vec<(usize, usize)> {
    let bytes = line.as_bytes();
    let mut found = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit() || (bytes[i] == b'-' && i + 1 < bytes.len());
        // Not inside a string: numbers follow ':' '[' or ','.
        let after = i > 0 && matches!(bytes[i - 1], b':' | b'[' | b',');
        if starts && after {
            let mut j = i + 1;
            while j < bytes.len()
                && matches!(bytes[j], b'0'..=b'9' | b'.' | b'e' | b'E' | b'-' | b'+')
            {
                j += 1;
            }
            found.push((i, j));
            i = j;
        } else {
            i += 1;
        }
    }
    found
}

/// `text` mutated, and the line (counted from 1) a number mutation changed.
fn mutate(text: &str, mutation: &Mutation) -> (String, Option<usize>) {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let n = lines.len();
    let mut changed = None;
    match mutation {
        Mutation::Number { line, nth, value } => {
            let line = line % n;
            let spans = numbers_in(&lines[line]);
            if !spans.is_empty() {
                let (a, b) = spans[nth % spans.len()];
                lines[line].replace_range(a..b, value);
                changed = Some(line + 1);
            }
        }
        Mutation::Swap(a, b) => lines.swap(a % n, b % n),
        Mutation::Repeat(a) => {
            let again = lines[a % n].clone();
            lines.insert(a % n, again);
        }
        Mutation::Cut(a) => lines.truncate(a % n),
        Mutation::CutBytes(a) => {
            let joined = lines.join("\n");
            let mut at = a % (joined.len() + 1);
            while !joined.is_char_boundary(at) {
                at -= 1;
            }
            return (joined[..at].to_owned(), None);
        }
    }
    (lines.join("\n") + "\n", changed)
}

/// Arbitrary JSON, a few levels deep.
fn json() -> impl Strategy<Value = Value> {
    let leaf = prop_oneof![
        Just(Value::Null),
        any::<bool>().prop_map(Value::Bool),
        any::<f64>()
            .prop_map(|v| serde_json::Number::from_f64(v).map_or(Value::Null, Value::Number)),
        any::<i64>().prop_map(|v| Value::Number(v.into())),
        prop_oneof![
            Just("rubber-band-box replay".to_owned()),
            Just("step".to_owned()),
            Just("settings".to_owned()),
            Just("rk4".to_owned()),
            "[a-z_]{0,8}",
        ]
        .prop_map(Value::String),
    ];
    leaf.prop_recursive(3, 24, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(Value::Array),
            prop::collection::vec(
                (
                    prop_oneof![
                        Just("kind".to_owned()),
                        Just("step".to_owned()),
                        Just("band".to_owned()),
                        Just("settings".to_owned()),
                        Just("format".to_owned()),
                        Just("version".to_owned()),
                        "[a-z_]{1,8}",
                    ],
                    inner
                ),
                0..6
            )
            .prop_map(|pairs| Value::Object(pairs.into_iter().collect())),
        ]
    })
}

proptest! {
    #![proptest_config(config())]

    /// Bytes of any kind: a replay reader's error or a replay, never a panic; a link takes
    /// only values in range.
    #[test]
    fn arbitrary_bytes_are_refused_or_read_never_a_panic(
        bytes in prop::collection::vec(any::<u8>(), 0..3000),
    ) {
        let _ = Replay::from_bytes(&bytes);
        let text = String::from_utf8_lossy(&bytes);
        let (link, _) = Link::parse(&text);
        prop_assert!(in_range(&link));
        let _ = decode_replay(&text);
    }

    /// JSON lines of any shape after a valid header, or in its place.
    #[test]
    fn arbitrary_json_is_refused_or_read_never_a_panic(
        values in prop::collection::vec(json(), 1..8),
        after_a_header in any::<bool>(),
    ) {
        let mut text = String::new();
        if after_a_header {
            let valid = String::from_utf8(small_replay().to_bytes()).unwrap();
            text.push_str(valid.lines().next().unwrap());
            text.push('\n');
        }
        for value in &values {
            text.push_str(&value.to_string());
            text.push('\n');
        }
        if let Ok(replay) = Replay::from_bytes(text.as_bytes())
            && replay.check_playable().is_ok()
        {
            played_in_a_game(replay)?;
        }
    }

    /// A valid replay changed in one place: read and held to the game's ranges, or refused
    /// naming the changed line; what is taken plays in a game without a NaN.
    #[test]
    fn a_mutated_replay_is_refused_at_its_line_or_plays(mutation in mutation()) {
        let valid = String::from_utf8(small_replay().to_bytes()).unwrap();
        let (text, changed) = mutate(&valid, &mutation);
        let checked = Replay::from_bytes(text.as_bytes())
            .map_err(|error| error.to_string())
            .and_then(|replay| {
                replay.check_playable().map_err(|error| error.to_string())?;
                Ok(replay)
            });
        match checked {
            Err(error) => {
                if let Some(line) = changed {
                    prop_assert!(error.starts_with(&format!("line {line}: ")), "{mutation:?}: {error}");
                }
            }
            Ok(replay) => {
                // The same replay rides in a link and comes back whole.
                let back = decode_replay(&encode_replay(&replay)).map_err(TestCaseError::fail)?;
                prop_assert_eq!(back.to_bytes(), replay.to_bytes());
                played_in_a_game(replay)?;
            }
        }
    }

    /// A valid link with one value replaced: taken if in range, else the one problem names
    /// that key; a link's game the same as a file's.
    #[test]
    fn a_mutated_link_names_the_key_it_cannot_take(
        key in 0..Key::ALL.len(),
        value in prop_oneof![nasty_number(), "[a-z0-9%+.-]{0,12}"],
    ) {
        let key = Key::ALL[key];
        let query = format!(
            "?v=1&scene=stiff&integrator=rk4&k=1e5&rate=64&time=2&ghosts=on&{}={value}",
            key.name()
        );
        let (link, problems) = Link::parse(&query);
        prop_assert!(in_range(&link));
        prop_assert!(problems.len() <= 1, "{problems:?}");
        if let Some(problem) = problems.first() {
            prop_assert_eq!(&problem.key, key.name());
        }
    }
}

/// The game's own recording of a scene rides in a link and plays back in a game.
#[test]
fn a_scene_in_a_link_plays() {
    let replay = small_replay();
    let data = encode_replay(&replay);
    let (link, problems) = Link::parse(&format!("#replay={data}"));
    assert!(problems.is_empty(), "{problems:?}");
    played_in_a_game(link.replay.expect("the replay")).unwrap();
}
