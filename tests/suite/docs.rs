//! The way in stays walkable: every relative link in README.md and docs/ points at a file of
//! the repository that exists and every anchor at one of its headings, none leaves the
//! repository, and README stays an entrance.

use crate::pages;

use std::fs;
use std::path::{Component, Path, PathBuf};

use pages::{pages, root};

/// The targets of a page's Markdown links and images: `](target)` and `](target "title")`.
fn links(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = text;
    while let Some(start) = rest.find("](") {
        rest = &rest[start + 2..];
        let end = rest.find(')').unwrap_or(rest.len());
        let target = rest[..end].split_whitespace().next().unwrap_or("");
        found.push(target.to_owned());
        rest = &rest[end..];
    }
    found
}

/// A link's file, if it names one inside the repository: web addresses and in-page anchors
/// name none. `Err` for a path that climbs out of the repository.
fn local_file(page: &Path, target: &str) -> Option<Result<PathBuf, String>> {
    if target.is_empty() || target.starts_with('#') || target.contains("://") {
        return None;
    }
    if target.starts_with("mailto:") {
        return None;
    }
    let path = target.split('#').next().unwrap_or("");
    let joined = page.parent().unwrap().join(path);
    // Resolved by hand: the file may not exist, so `canonicalize` cannot be used.
    let mut resolved = PathBuf::new();
    for part in joined.components() {
        match part {
            Component::ParentDir => {
                resolved.pop();
            }
            Component::CurDir => {}
            other => resolved.push(other),
        }
    }
    Some(if resolved.starts_with(root()) {
        Ok(resolved)
    } else {
        Err(format!("{target} leaves the repository"))
    })
}

#[test]
fn every_relative_link_points_at_a_file_in_the_repository() {
    let mut broken = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = fs::read_to_string(&page).expect("a page");
        for target in links(&text) {
            match local_file(&page, &target) {
                None => {}
                Some(Ok(file)) if file.exists() => checked += 1,
                Some(Ok(_)) => broken.push(format!("{}: {target} does not exist", page.display())),
                Some(Err(message)) => broken.push(format!("{}: {message}", page.display())),
            }
        }
    }
    assert!(checked > 20, "the reader found the links ({checked})");
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
}

/// The anchors a page's headings make, as GitHub makes them: lowercased, punctuation other
/// than `-` and `_` dropped, spaces to `-`, a repeated one numbered from `-1`. Headings inside
/// fenced code are not headings.
fn anchors(text: &str) -> Vec<String> {
    let mut made: Vec<String> = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        let Some(title) = line.strip_prefix('#').filter(|_| !fenced) else {
            continue;
        };
        let title = title.trim_start_matches('#').trim();
        let slug: String = title
            .to_lowercase()
            .chars()
            .filter(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | ' '))
            .map(|c| if c == ' ' { '-' } else { c })
            .collect();
        let repeats = made
            .iter()
            .filter(|anchor| {
                **anchor == slug
                    || anchor
                        .strip_prefix(&slug)
                        .and_then(|rest| rest.strip_prefix('-'))
                        .is_some_and(|n| n.parse::<u32>().is_ok())
            })
            .count();
        made.push(if repeats == 0 {
            slug
        } else {
            format!("{slug}-{repeats}")
        });
    }
    made
}

/// A link's anchor names a heading of the page it points at (or of its own page).
#[test]
fn every_anchor_names_a_heading_of_its_page() {
    let mut dead = Vec::new();
    let mut checked = 0;
    for page in pages() {
        let text = fs::read_to_string(&page).expect("a page");
        for target in links(&text) {
            let Some((file, anchor)) = target.split_once('#') else {
                continue;
            };
            if target.contains("://") {
                continue;
            }
            let file = if file.is_empty() {
                page.clone()
            } else {
                match local_file(&page, file) {
                    Some(Ok(file)) if file.exists() => file,
                    // The file test names a missing file.
                    _ => continue,
                }
            };
            if file.extension().is_none_or(|e| e != "md") {
                continue;
            }
            let headings = anchors(&fs::read_to_string(&file).expect("a page"));
            checked += 1;
            if !headings.iter().any(|heading| heading == anchor) {
                dead.push(format!(
                    "{}: {target} names no heading of {}",
                    page.display(),
                    file.display()
                ));
            }
        }
    }
    assert!(checked > 20, "the reader found the anchors ({checked})");
    assert!(dead.is_empty(), "dead anchors:\n{}", dead.join("\n"));
}

#[test]
fn the_anchor_reader_makes_githubs_anchors() {
    let page = "# Rubber Band Box\n## `auto`: the game's default\n```\n# not a heading\n```\n\
                ## Size and load\n## Size and load\n### Measured (2026-11-25)";
    assert_eq!(
        anchors(page),
        [
            "rubber-band-box",
            "auto-the-games-default",
            "size-and-load",
            "size-and-load-1",
            "measured-2026-11-25"
        ]
    );
}

#[test]
fn the_link_reader_sees_a_broken_link_and_one_that_leaves() {
    let readme = root().join("README.md");
    let text = "see [a](docs/nowhere.md), [b](../shared/NOTES.md \"t\"), [c](#play), \
                [d](https://bevyengine.org) and ![e](assets/screenshot.png)";
    let found = links(text);
    assert_eq!(
        found,
        [
            "docs/nowhere.md",
            "../shared/NOTES.md",
            "#play",
            "https://bevyengine.org",
            "assets/screenshot.png"
        ]
    );
    assert!(!local_file(&readme, &found[0]).unwrap().unwrap().exists());
    assert!(local_file(&readme, &found[1]).unwrap().is_err());
    assert!(local_file(&readme, &found[2]).is_none());
    assert!(local_file(&readme, &found[3]).is_none());
    assert!(local_file(&readme, &found[4]).unwrap().unwrap().exists());
}

/// README is the entrance: short, with play, test and the controls on its first screen.
#[test]
fn readme_is_an_entrance_with_play_test_and_controls_first() {
    let readme = fs::read_to_string(root().join("README.md")).expect("README.md");
    let lines: Vec<&str> = readme.lines().collect();
    assert!(lines.len() <= 250, "README has {} lines", lines.len());
    let line_of = |needle: &str| lines.iter().position(|line| line.contains(needle));
    for needle in ["cargo run", "cargo test", "## Controls"] {
        let at = line_of(needle).unwrap_or_else(|| panic!("README lacks {needle}"));
        assert!(
            at < 50,
            "{needle} is on line {}, past the first screen",
            at + 1
        );
    }
}

/// docs/architecture.md's frame names every system set that src/game/schedule.rs declares, in
/// the order declared (the frame's order), so that the page cannot drift from the one place
/// the order is written.
#[test]
fn the_docs_frame_names_every_set_in_the_schedules_order() {
    let schedule = fs::read_to_string(root().join("src/game/schedule.rs")).expect("schedule.rs");
    let mut sets = Vec::new();
    let mut inside = false;
    for line in schedule.lines() {
        if line.starts_with("pub enum ") {
            inside = true;
        } else if line.starts_with('}') {
            inside = false;
        } else if inside
            && let Some(name) = line.strip_prefix("    ").and_then(|l| l.strip_suffix(','))
            && name.chars().next().is_some_and(|c| c.is_ascii_uppercase())
            && name.chars().all(char::is_alphanumeric)
        {
            sets.push(name.to_owned());
        }
    }
    assert!(sets.len() >= 15, "the reader found the sets: {sets:?}");
    let page = fs::read_to_string(root().join("docs/architecture.md")).expect("the page");
    let start = page.find("## The frame").expect("a frame section");
    let section = &page[start..];
    let section = &section[..section[3..]
        .find("\n## ")
        .map_or(section.len(), |end| end + 3)];
    let mut from = 0;
    for set in &sets {
        let at = [format!("`{set}`"), format!("::{set}`"), format!("`{set} ")]
            .iter()
            .filter_map(|written| section[from..].find(written.as_str()))
            .min();
        match at {
            Some(at) => from += at + 1,
            None => panic!("docs/architecture.md's frame lacks `{set}` after what precedes it"),
        }
    }
}

/// The `auto` defaults the pages quote are the code's own (`AutoSettings::default()`): the
/// command line's page, and the integrators' page in its table and its paragraph of defaults.
/// (Its order, 20 then 28, once stood in three versions across the pages while every test
/// passed.)
#[test]
fn the_pages_quote_autos_defaults_as_the_code_has_them() {
    use rubber_band_box::physics::AutoSettings;
    let auto = AutoSettings::default();
    let (tolerance, order, budget) = (
        format!("{:e}", auto.tolerance),
        auto.order,
        auto.max_substeps,
    );
    let read = |page: &str| fs::read_to_string(root().join(page)).expect(page);
    let simulate = read("docs/simulate.md");
    let integrators = read("docs/integrators.md");
    for (page, text, quoted) in [
        (
            "docs/simulate.md",
            &simulate,
            format!("(defaults {tolerance}, {order} and {budget})"),
        ),
        (
            "docs/integrators.md",
            &integrators,
            format!("order {order}, tolerance {tolerance} px per step, budget {budget} steps."),
        ),
        (
            "docs/integrators.md",
            &integrators,
            format!("Taylor-series steps of order up to {order},"),
        ),
        (
            "docs/integrators.md",
            &integrators,
            format!("| {order} in its step (fewer"),
        ),
    ] {
        assert!(text.contains(&quoted), "{page} does not say \"{quoted}\"");
    }
}

/// The bounds the pages quote are the code's own: the sliders' and a link's ranges
/// (`physics::scene`), the heaviest settings they allow, and the frame's budget of steps.
#[test]
fn the_pages_quote_the_ranges_and_bounds_as_the_code_has_them() {
    use rubber_band_box::game::budget::FrameBudget;
    use rubber_band_box::physics::scene::{
        MASS_RANGE, SIZE_RANGE, STEP_RATE_RANGE, STIFFNESS_RANGE, TIME_SCALE_RANGE,
    };
    let read = |page: &str| fs::read_to_string(root().join(page)).expect(page);
    let (k, mass, size, rate) = (STIFFNESS_RANGE, MASS_RANGE, SIZE_RANGE, STEP_RATE_RANGE);
    for (page, quoted) in [
        (
            "docs/controls.md",
            format!(
                "(k from {:e} to {:e} and the mass from {:e} to {:e}",
                k.low, k.high, mass.low, mass.high
            ),
        ),
        (
            "docs/controls.md",
            format!("box from {} to {} px", size.low, size.high),
        ),
        (
            "docs/links.md",
            format!("{} to {} Hz, k, the mass", rate.low, rate.high),
        ),
        (
            "docs/links.md",
            format!("size from {} to {}", size.low, size.high),
        ),
        (
            "docs/measurements.md",
            format!(
                "k = {:e}, {} Hz, ×{}",
                k.high, rate.high, TIME_SCALE_RANGE.high
            ),
        ),
        (
            "docs/architecture.md",
            format!("or {} steps", FrameBudget::MAX_STEPS),
        ),
    ] {
        assert!(
            read(page).contains(&quoted),
            "{page} does not say \"{quoted}\""
        );
    }
}
