//! The house's shape: the imports between the source files form no circle, and the numerical
//! core imports nothing of the game. Read from the sources themselves (`use crate::...`,
//! `use super::...`, a module's `use child::...`, and paths written inline), so a new
//! circle fails here, naming the files in it.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// Every source file under src/, with its path relative to src/ and its text.
fn source_files() -> Vec<(std::path::PathBuf, String)> {
    fn walk(dir: &Path, root: &Path, found: &mut Vec<(std::path::PathBuf, String)>) {
        for entry in fs::read_dir(dir).expect("src is readable") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                walk(&path, root, found);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let source = fs::read_to_string(&path).expect("a source file");
                found.push((path.strip_prefix(root).unwrap().to_owned(), source));
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut found = Vec::new();
    walk(&root, &root, &mut found);
    found
}

/// Every module of the crate (`physics::integrators::auto`; "" for the crate root) and its
/// source without comments.
fn modules() -> BTreeMap<String, String> {
    let mut found = BTreeMap::new();
    for (relative, source) in source_files() {
        let mut parts: Vec<String> = relative
            .with_extension("")
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        if matches!(
            parts.last().map(String::as_str),
            Some("mod" | "lib" | "main")
        ) {
            parts.pop();
        }
        let code: String = source
            .lines()
            .map(|line| line.split("//").next().unwrap_or(""))
            .collect::<Vec<_>>()
            .join("\n");
        found.insert(parts.join("::"), code);
    }
    // main.rs is the binary, not a module of the library: it may use anything.
    found.remove("");
    let lib = fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("src/lib.rs")).unwrap();
    found.insert(String::new(), lib);
    found
}

/// The longest known module that `path` (segments from the crate root) starts with.
fn owner(path: &[String], known: &BTreeMap<String, String>) -> Option<String> {
    (1..=path.len())
        .rev()
        .map(|n| path[..n].join("::"))
        .find(|candidate| known.contains_key(candidate))
}

/// The modules `module` imports.
fn imports(module: &str, code: &str, known: &BTreeMap<String, String>) -> BTreeSet<String> {
    let here: Vec<String> = if module.is_empty() {
        vec![]
    } else {
        module.split("::").map(str::to_owned).collect()
    };
    let mut found = BTreeSet::new();
    // Visibilities (`pub(super)`, `pub(crate)`) name no module to import.
    let code = code
        .replace("pub(super)", "pub")
        .replace("pub(crate)", "pub");
    let words: Vec<&str> = code
        .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ':' || c == '{'))
        .filter(|w| !w.is_empty())
        .collect();
    for word in words {
        let word = word.trim_end_matches([':', '{']);
        let segments: Vec<&str> = word.split("::").filter(|s| !s.is_empty()).collect();
        // A bare `super` or `crate` (a glob, `use super::*`, in a file's own test module)
        // names no item: skip it rather than guess which module it means.
        let Some((&first, rest)) = segments.split_first().filter(|(_, rest)| !rest.is_empty())
        else {
            continue;
        };
        let mut path: Vec<String> = match first {
            "crate" => vec![],
            "super" => here[..here.len().saturating_sub(1)].to_vec(),
            "self" => here.clone(),
            // A child module named from its parent (`use child::Item`, `child::f()`).
            child => {
                let mut path = here.clone();
                path.push(child.to_owned());
                if !known.contains_key(&path.join("::")) {
                    continue;
                }
                path
            }
        };
        let mut rest = rest;
        while let Some((&"super", tail)) = rest.split_first() {
            path.pop();
            rest = tail;
        }
        path.extend(rest.iter().map(|s| (*s).to_owned()));
        if let Some(target) = owner(&path, known)
            && target != module
            && !target.is_empty()
        {
            found.insert(target);
        }
    }
    found
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let known = modules();
    known
        .iter()
        .map(|(module, code)| (module.clone(), imports(module, code, &known)))
        .collect()
}

/// A circle through `start`, if there is one: the modules in order.
fn circle_from(start: &str, graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        start: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<String>,
        seen: &mut BTreeSet<String>,
    ) -> bool {
        for next in graph.get(node).into_iter().flatten() {
            if next == start {
                return true;
            }
            if seen.insert(next.clone()) {
                path.push(next.clone());
                if visit(next, start, graph, path, seen) {
                    return true;
                }
                path.pop();
            }
        }
        false
    }
    let mut path = vec![start.to_owned()];
    let mut seen = BTreeSet::new();
    visit(start, start, graph, &mut path, &mut seen).then_some(path)
}

#[test]
fn the_imports_between_source_files_form_no_circle() {
    let graph = graph();
    assert!(graph.len() > 20, "the walk found the sources: {graph:?}");
    // The reader sees real edges: a check that sees none would pass anything.
    assert!(graph["game::simulation"].contains("physics"));
    assert!(graph["physics::integrators::auto"].contains("physics::integrators::implicit"));
    assert!(graph["physics"].contains("physics::body"));
    let circles: Vec<String> = graph
        .keys()
        .filter_map(|module| circle_from(module, &graph))
        .map(|circle| format!("{} -> {}", circle.join(" -> "), circle[0]))
        .collect();
    assert!(
        circles.is_empty(),
        "import circles:\n{}",
        circles.join("\n")
    );
}

#[test]
fn the_numerical_core_imports_nothing_of_the_game() {
    for (module, imported) in graph() {
        if module == "physics" || module.starts_with("physics::") {
            for target in imported {
                assert!(
                    target.starts_with("physics"),
                    "{module} imports {target}: the core sits at the bottom"
                );
            }
        }
    }
}

#[test]
fn the_reader_finds_a_circle_when_there_is_one() {
    let mut known = BTreeMap::new();
    known.insert("a".to_owned(), "use crate::b::Thing;".to_owned());
    known.insert("b".to_owned(), "fn f() { super::a::g() }".to_owned());
    known.insert("c".to_owned(), "use crate::a;".to_owned());
    known.insert("a::d".to_owned(), "pub(super) fn h() {}".to_owned());
    let graph: BTreeMap<_, _> = known
        .iter()
        .map(|(m, code)| (m.clone(), imports(m, code, &known)))
        .collect();
    assert_eq!(circle_from("a", &graph), Some(vec!["a".into(), "b".into()]));
    assert_eq!(circle_from("c", &graph), None);
    assert!(graph["a::d"].is_empty(), "a visibility is not an import");
}

/// The rooms from the bottom up: a module may import its own room and those under it.
const LAYERS: [&str; 5] = ["physics", "replay", "game", "measure", "cli"];

/// The room a module lives in (its first segment), and that room's height in [`LAYERS`].
fn layer(module: &str) -> Option<usize> {
    let room = module.split("::").next().unwrap_or("");
    LAYERS.iter().position(|layer| *layer == room)
}

/// Which modules a check reads.
type Accepts = fn(&str) -> bool;

/// Every import, from a module `from` accepts to a target `to` accepts, that reaches up a level of
/// `level`, as "module -> target"; one whose ends `level` cannot place is named with `outside`.
fn upward(
    graph: &BTreeMap<String, BTreeSet<String>>,
    (from, to): (Accepts, Accepts),
    level: fn(&str) -> Option<usize>,
    outside: &str,
) -> Vec<String> {
    graph
        .iter()
        .filter(|(module, _)| from(module))
        .flat_map(|(module, imported)| {
            imported
                .iter()
                .filter(|target| to(target))
                .filter_map(move |target| match (level(module), level(target)) {
                    (Some(below), Some(above)) => {
                        (above > below).then(|| format!("{module} -> {target}"))
                    }
                    _ => Some(format!("{module} -> {target} (a room outside {outside})")),
                })
        })
        .collect()
}

/// Every import that reaches up a layer of [`LAYERS`].
fn upward_imports(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let rooms = format!("{LAYERS:?}");
    upward(graph, (|m| !m.is_empty(), |_| true), layer, &rooms)
}

#[test]
fn each_room_imports_only_the_rooms_under_it() {
    let graph = graph();
    // Every module lives in a known room: a new top-level module must be placed first.
    for module in graph.keys().filter(|module| !module.is_empty()) {
        assert!(
            layer(module).is_some(),
            "{module} is in no room of {LAYERS:?}"
        );
    }
    // The reader sees the edges the layers allow, so a check that saw none would not pass.
    assert!(graph["replay::format"].contains("physics"));
    assert!(graph["game::simulation"].contains("physics"));
    assert!(graph["measure::references"].contains("physics"));
    let upward = upward_imports(&graph);
    assert!(
        upward.is_empty(),
        "imports up a layer:\n{}",
        upward.join("\n")
    );
}

/// The game's rooms from the bottom up (docs/architecture.md): a room may import its own
/// level and those under it. `game` itself (mod.rs) and `play` wire everything.
///
/// A room listed nowhere is a leaf ([`LEAF`]): a card such as the Readouts card, which only the
/// wiring imports. So a new card is its folder and its lines in `game/mod.rs`, and nothing here.
const GAME_LAYERS: [&[&str]; 10] = [
    &["schedule", "shared", "theme", "web"],
    &["simulation", "budget"],
    &["ghosts", "layout", "pointer", "camera", "stability"],
    &["setup"],
    &["replays"],
    &["learn"],
    &["input"],
    &["hud"],
    &["screen"],
    &["play", ""],
];

/// The level of the rooms [`GAME_LAYERS`] does not list: over every listed room but the wiring.
const LEAF: usize = GAME_LAYERS.len() - 1;

/// Returns a game module's room: `game::replays::links` is in `replays`, `game` in "".
fn game_room(module: &str) -> Option<&str> {
    let room = module.strip_prefix("game")?;
    let room = room.strip_prefix("::").unwrap_or(room);
    Some(room.split("::").next().unwrap_or(""))
}

/// A game module's level: its room's in [`GAME_LAYERS`], or [`LEAF`] for a room listed nowhere.
///
/// A leaf sits under the wiring's level, which has the last index, so it counts as one more.
fn game_layer(module: &str) -> Option<usize> {
    let room = game_room(module)?;
    let listed = GAME_LAYERS.iter().position(|rooms| rooms.contains(&room));
    Some(match listed {
        Some(level) if level == LEAF => LEAF + 1,
        Some(level) => level,
        None => LEAF,
    })
}

/// Tells whether a game module is in a leaf room (listed nowhere in [`GAME_LAYERS`]).
fn is_leaf(module: &str) -> bool {
    game_room(module).is_some_and(|room| !GAME_LAYERS.iter().any(|rooms| rooms.contains(&room)))
}

/// Every import from one leaf room into another: a card reads the rooms under it, not a card.
fn leaves_importing_leaves(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let mut found = Vec::new();
    for (module, imports) in graph.iter().filter(|(module, _)| is_leaf(module)) {
        for import in imports.iter().filter(|import| is_leaf(import)) {
            if game_room(import) != game_room(module) {
                found.push(format!("{module} -> {import}"));
            }
        }
    }
    found
}

/// Every import inside the game that reaches up a level of [`GAME_LAYERS`].
fn upward_in_the_game(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let in_the_game: Accepts = |module| module.starts_with("game");
    upward(graph, (in_the_game, in_the_game), game_layer, "GAME_LAYERS")
}

#[test]
fn each_room_of_the_game_imports_only_the_rooms_under_it() {
    let graph = graph();
    // The reader sees the edges the levels allow.
    assert!(graph["game::replays::playback"].contains("game::pointer"));
    assert!(graph["game::input::controls"].contains("game::replays::scenes"));
    let upward = upward_in_the_game(&graph);
    assert!(
        upward.is_empty(),
        "imports up a level of the game:\n{}",
        upward.join("\n")
    );
    // The cards no other room reads are leaves, listed nowhere.
    for leaf in ["game::readouts", "game::energy::lines", "game::plot::axes"] {
        assert!(is_leaf(leaf), "{leaf}");
    }
    assert!(!is_leaf("game::stability::margins") && !is_leaf("game"));
    let between = leaves_importing_leaves(&graph);
    assert!(
        between.is_empty(),
        "a leaf room imports another:\n{}",
        between.join("\n")
    );
}

#[test]
fn the_leaf_check_finds_a_card_importing_a_card_and_one_imported_from_below() {
    let mut graph = BTreeMap::new();
    graph.insert(
        "game::readouts".to_owned(),
        BTreeSet::from([
            "game::energy::lines".to_owned(),
            "game::simulation".to_owned(),
        ]),
    );
    graph.insert(
        "game::hud".to_owned(),
        BTreeSet::from(["game::readouts".to_owned()]),
    );
    graph.insert(
        "game".to_owned(),
        BTreeSet::from(["game::readouts".to_owned()]),
    );
    assert_eq!(
        leaves_importing_leaves(&graph),
        ["game::readouts -> game::energy::lines"]
    );
    assert_eq!(
        upward_in_the_game(&graph).len(),
        1,
        "the HUD reaching up to a leaf"
    );
}

#[test]
fn the_game_check_finds_an_import_up_a_level() {
    let mut graph = BTreeMap::new();
    graph.insert(
        "game::replays::recording".to_owned(),
        BTreeSet::from([
            "game::input::controls".to_owned(),
            "game::pointer".to_owned(),
        ]),
    );
    graph.insert(
        "game::pointer".to_owned(),
        BTreeSet::from(["game::layout".to_owned(), "physics".to_owned()]),
    );
    assert_eq!(
        upward_in_the_game(&graph),
        ["game::replays::recording -> game::input::controls"]
    );
}

#[test]
fn nothing_imports_the_command_line_and_the_shared_leaves_import_no_plugin() {
    let graph = graph();
    for (module, imported) in &graph {
        if !module.is_empty() && !module.starts_with("cli") {
            assert!(
                !imported.contains("cli"),
                "{module} imports the binary's cli"
            );
        }
    }
    // The frame's order and the shared resources sit under every plugin of the game.
    for leaf in ["game::schedule", "game::shared"] {
        let game: Vec<_> = graph[leaf]
            .iter()
            .filter(|target| target.starts_with("game"))
            .collect();
        assert!(game.is_empty(), "{leaf} imports {game:?}");
    }
}

#[test]
fn the_layer_check_finds_an_import_up_a_layer() {
    let mut graph = BTreeMap::new();
    graph.insert(
        "physics::body".to_owned(),
        BTreeSet::from(["game::simulation".to_owned()]),
    );
    graph.insert("replay".to_owned(), BTreeSet::from(["physics".to_owned()]));
    graph.insert(
        "game::hud".to_owned(),
        BTreeSet::from(["measure::report".to_owned(), "replay".to_owned()]),
    );
    assert_eq!(
        upward_imports(&graph),
        [
            "game::hud -> measure::report",
            "physics::body -> game::simulation"
        ]
    );
}

/// Words that end in "s" but do not say what a function does.
const NOT_VERBS: [&str; 10] = [
    "Its", "This", "Was", "Is", "Does", "Whether", "Unless", "Plus", "Ones", "Units",
];

/// Returns every item doc of `source` that breaks the house rule, as "line: problem".
///
/// An item doc's first paragraph is one line, its summary; a function's summary opens with a
/// verb in the third person ("Returns", "Steps", "Tells whether"), so that it says what the
/// function does rather than restating the code beside it.
fn doc_problems(source: &str) -> Vec<String> {
    let lines: Vec<&str> = source.lines().map(str::trim).collect();
    let mut problems = Vec::new();
    let mut at = 0;
    while at < lines.len() {
        if !lines[at].starts_with("///") {
            at += 1;
            continue;
        }
        let start = at;
        while at < lines.len() && lines[at].starts_with("///") {
            at += 1;
        }
        let doc: Vec<&str> = lines[start..at]
            .iter()
            .map(|line| line.trim_start_matches('/').trim())
            .collect();
        let item = lines[at..]
            .iter()
            .find(|line| !line.starts_with("#[") && !line.starts_with("//"))
            .copied()
            .unwrap_or("");
        let summary = doc.iter().take_while(|line| !line.is_empty()).count();
        if summary > 1 {
            problems.push(format!(
                "{}: a first paragraph of {summary} lines",
                start + 1
            ));
        }
        let first = doc[0].split(' ').next().unwrap_or("");
        let verb = first.ends_with('s')
            && first.starts_with(|c: char| c.is_ascii_uppercase())
            && first.chars().all(|c| c.is_ascii_alphabetic())
            && !NOT_VERBS.contains(&first);
        if is_function(item) && !verb {
            problems.push(format!(
                "{}: a function's summary opens with {first:?}, not a verb",
                start + 1
            ));
        }
    }
    problems
}

/// Tells whether a line declares a function (or method), whatever its visibility.
fn is_function(line: &str) -> bool {
    let mut rest = line;
    if let Some(after) = rest.strip_prefix("pub") {
        rest = after.trim_start();
        if rest.starts_with('(') {
            rest = rest
                .split_once(')')
                .map_or("", |(_, after)| after.trim_start());
        }
    }
    for qualifier in ["const ", "async ", "unsafe "] {
        rest = rest.strip_prefix(qualifier).unwrap_or(rest);
    }
    rest.starts_with("fn ")
}

#[test]
fn each_item_doc_opens_with_a_one_line_summary() {
    let mut problems = Vec::new();
    let mut docs = 0;
    for (relative, source) in source_files() {
        docs += source
            .lines()
            .zip(source.lines().skip(1))
            .filter(|(a, b)| a.trim().starts_with("///") && !b.trim().starts_with("///"))
            .count();
        for problem in doc_problems(&source) {
            problems.push(format!("src/{}:{problem}", relative.display()));
        }
    }
    // The walk reads the crate's docs, so a check that found none would not pass.
    assert!(docs > 500, "only {docs} item docs found");
    assert!(
        problems.is_empty(),
        "item docs to mend:\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_doc_check_finds_a_long_summary_and_a_noun_for_a_function() {
    let source = "\
/// The box's corners,
/// counted anticlockwise.
pub fn corners() {}

/// Returns the box's size.
///
/// In pixels.
fn size() {}

/// The step's state.
pub(crate) const fn state() {}

/// The box's state, over two lines
/// (a type may open with a noun).
struct State;

/// Whether the band holds.
fn holds() {}
";
    assert_eq!(
        doc_problems(source),
        [
            "1: a first paragraph of 2 lines",
            "1: a function's summary opens with \"The\", not a verb",
            "10: a function's summary opens with \"The\", not a verb",
            "13: a first paragraph of 2 lines",
            "17: a function's summary opens with \"Whether\", not a verb",
        ]
    );
}

/// The most parameters a function of the game takes; past it, a `SystemParam` says what they
/// are.
const MOST_PARAMETERS: usize = 8;

/// Splits `list` at its commas outside brackets, dropping empty parts.
fn top_level_parts(list: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut start) = (Vec::new(), 0i32, 0);
    for (at, c) in list.char_indices() {
        match c {
            '(' | '[' | '{' | '<' => depth += 1,
            ')' | ']' | '}' | '>' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&list[start..at]);
                start = at + 1;
            }
            _ => {}
        }
    }
    parts.push(&list[start..]);
    parts
        .into_iter()
        .map(str::trim)
        .filter(|part| !part.is_empty())
        .collect()
}

/// Returns each function of `source` with more than [`MOST_PARAMETERS`], as "name: count".
///
/// A parameter whose type is a tuple counts as its parts: a tuple groups parameters without
/// saying what they are.
fn long_signatures(source: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = source;
    while let Some(at) = rest.find("fn ") {
        let after = &rest[at + 3..];
        rest = after;
        let name: String = after
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        let Some(open) = after.find('(') else {
            break;
        };
        // Only a declaration: `fn name(` or `fn name<...>(`.
        let between = after[name.len()..open].trim();
        if name.is_empty() || !(between.is_empty() || between.starts_with('<')) {
            continue;
        }
        let mut depth = 0i32;
        let Some(close) = after[open..].char_indices().find_map(|(at, c)| {
            match c {
                '(' => depth += 1,
                ')' => depth -= 1,
                _ => {}
            }
            (depth == 0).then_some(open + at)
        }) else {
            break;
        };
        let count: usize = top_level_parts(&after[open + 1..close])
            .iter()
            .map(|parameter| match parameter.split_once(':') {
                Some((_, kind)) if kind.trim().starts_with('(') => {
                    let kind = kind.trim();
                    top_level_parts(&kind[1..kind.len() - 1]).len()
                }
                _ => 1,
            })
            .sum();
        if count > MOST_PARAMETERS {
            found.push(format!("{name}: {count} parameters"));
        }
    }
    found
}

#[test]
fn no_function_of_the_game_takes_more_than_eight_parameters() {
    let mut long = Vec::new();
    let mut functions = 0;
    for (relative, source) in source_files() {
        if !relative.starts_with("game") {
            continue;
        }
        functions += source.matches("fn ").count();
        for problem in long_signatures(&source) {
            long.push(format!("src/{}: {problem}", relative.display()));
        }
    }
    assert!(functions > 200, "only {functions} functions read");
    assert!(
        long.is_empty(),
        "group these with a SystemParam that says what they are:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_parameter_check_counts_a_tuples_parts() {
    let source = "\
fn nine(a: A, b: B, c: C, d: D, e: E, f: F, g: G, h: H, i: Query<(&A, &B), With<C>>) {}
fn eight((a, b, c): (Res<A>, Res<B>, Res<C>), d: D, e: E, f: F, g: G, h: H) {}
fn tupled(a: A, (b, c, d, e, f): (B, C, D, E, F), g: G, h: H, i: I) {}
let f = |x: fn(A, B, C, D, E, F, G, H, I)| x;
";
    assert_eq!(
        long_signatures(source),
        ["nine: 9 parameters", "tupled: 9 parameters"]
    );
}

// --- A card lives in one place. ---

/// Returns where each card is named (`pub const NAME: Card = Card(..)`): its home, the folder
/// of the file that names it (`game/stability/`), or the file itself at the game's top.
fn card_homes(files: &[(std::path::PathBuf, String)]) -> BTreeMap<String, String> {
    let mut homes = BTreeMap::new();
    for (relative, source) in files {
        for line in source.lines() {
            let Some(rest) = line.trim().strip_prefix("pub const ") else {
                continue;
            };
            if let Some((name, _)) = rest.split_once(": Card = Card(") {
                let path = relative.display().to_string();
                let home = match path.rsplit_once('/') {
                    Some((folder, _)) if folder != "game" => format!("{folder}/"),
                    _ => path,
                };
                homes.insert(name.to_owned(), home);
            }
        }
    }
    homes
}

/// Returns each use of a card's name outside its home (comments aside), as "file: Card::NAME".
fn cards_away_from_home(files: &[(std::path::PathBuf, String)]) -> Vec<String> {
    let homes = card_homes(files);
    let mut away = Vec::new();
    for (relative, source) in files {
        let path = relative.display().to_string();
        let code = source
            .lines()
            .filter(|line| !line.trim_start().starts_with("//"));
        for line in code {
            for (name, home) in &homes {
                if line.contains(&format!("Card::{name}")) && !path.starts_with(home) {
                    away.push(format!("src/{path}: Card::{name}"));
                }
            }
        }
    }
    away.sort();
    away.dedup();
    away
}

#[test]
fn a_card_is_named_only_in_its_own_room() {
    let files = source_files();
    let homes = card_homes(&files);
    assert_eq!(homes.len(), 7, "{homes:?}");
    assert_eq!(homes["STABILITY"], "game/stability/");
    assert_eq!(homes["READOUTS"], "game/readouts/");
    assert_eq!(homes["ENERGY"], "game/energy/");
    let away = cards_away_from_home(&files);
    assert!(
        away.is_empty(),
        "a card named outside its own room:\n{}",
        away.join("\n")
    );
}

#[test]
fn the_card_check_finds_a_card_named_in_another_room() {
    let files = vec![
        (
            "game/stability/card.rs".into(),
            "pub const STABILITY: Card = Card(\"stability\");\nlet a = Card::STABILITY;".to_owned(),
        ),
        (
            "game/hud/mod.rs".into(),
            "// Card::STABILITY in a comment is fine\nlet b = Card::STABILITY;".to_owned(),
        ),
    ];
    assert_eq!(
        cards_away_from_home(&files),
        ["src/game/hud/mod.rs: Card::STABILITY"]
    );
}

// --- Visibility: what is public only because a test reads it. ---

/// The most top-level items of `src/` that may be `pub` only for the tests: a ratchet, lowered
/// as tests of private logic move beside the code (`#[cfg(test)]`); it may never rise.
///
/// It counts the core's, the replay format's and the tools' API too (`spectral_radius`,
/// `encode_replay`, `reference_state`): public for their users, whom the tests stand in for.
const PUB_FOR_TESTS_AT_MOST: usize = 37;

/// The most items of the game (`src/game/`, its plugins aside) that may be `pub` only for the
/// tests: components, resources and helpers a headless test reads where no other room does.
const GAME_PUB_FOR_TESTS_AT_MOST: usize = 20;

/// Tells whether a found item ("src/game/hud/mod.rs: HINT") is the game's, not a plugin.
fn is_the_games_own(item: &str) -> bool {
    item.starts_with("src/game/") && !item.ends_with("Plugin")
}

/// Returns a source without its `pub use` statements: a re-export names an item, but uses none.
fn without_re_exports(source: &str) -> String {
    let mut kept = String::new();
    let mut in_re_export = false;
    for line in source.lines() {
        in_re_export |= line.trim_start().starts_with("pub use ");
        if !in_re_export {
            kept.push_str(line);
            kept.push('\n');
        }
        in_re_export &= !line.contains(';');
    }
    kept
}

/// Returns the top-level `pub` items that no other file of `src/` names but `tests/` or
/// `benches/` do, as "file: name".
///
/// A `pub use` elsewhere does not count: a folder's `mod.rs` re-exporting a child's item for
/// the tests is not a use.
fn pub_only_for_tests(src: &[(std::path::PathBuf, String)], tests: &str) -> Vec<String> {
    let kinds = [
        "const fn ",
        "fn ",
        "struct ",
        "enum ",
        "const ",
        "static ",
        "type ",
        "trait ",
    ];
    let names = |text: &str, wanted: &str| {
        text.split(|c: char| !(c.is_alphanumeric() || c == '_'))
            .filter(|word| *word == wanted)
            .count()
    };
    let used: Vec<String> = src
        .iter()
        .map(|(_, text)| without_re_exports(text))
        .collect();
    let mut found = Vec::new();
    for (relative, source) in src {
        for line in source.lines() {
            let Some(rest) = line.strip_prefix("pub ") else {
                continue;
            };
            let Some(item) = kinds.iter().find_map(|kind| rest.strip_prefix(kind)) else {
                continue;
            };
            let name: String = item
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let elsewhere: usize = src
                .iter()
                .zip(&used)
                .filter(|((other, _), _)| other != relative)
                .map(|(_, text)| names(text, &name))
                .sum();
            if elsewhere == 0 && names(tests, &name) > 0 {
                found.push(format!("src/{}: {name}", relative.display()));
            }
        }
    }
    found.sort();
    found
}

#[test]
fn no_more_items_are_public_only_for_the_tests() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut tests = String::new();
    for folder in ["tests", "benches"] {
        let mut stack = vec![root.join(folder)];
        while let Some(dir) = stack.pop() {
            for entry in fs::read_dir(&dir).expect("a readable folder") {
                let path = entry.expect("an entry").path();
                if path.is_dir() {
                    stack.push(path);
                } else if path.extension().is_some_and(|e| e == "rs") {
                    tests += &fs::read_to_string(&path).expect("a test file");
                }
            }
        }
    }
    let found = pub_only_for_tests(&source_files(), &tests);
    let games: Vec<&String> = found.iter().filter(|item| is_the_games_own(item)).collect();
    assert!(
        games.len() <= GAME_PUB_FOR_TESTS_AT_MOST,
        "{} items of the game are pub only for the tests (at most \
         {GAME_PUB_FOR_TESTS_AT_MOST}):\n{games:#?}",
        games.len()
    );
    assert!(
        found.len() <= PUB_FOR_TESTS_AT_MOST,
        "{} items are pub only for the tests (at most {PUB_FOR_TESTS_AT_MOST}): test them \
         beside the code (#[cfg(test)]) or say why they are public:\n{}",
        found.len(),
        found.join("\n")
    );
}

#[test]
fn the_visibility_check_finds_an_item_only_a_test_names() {
    let src = vec![
        (
            "game/layout.rs".into(),
            "pub fn shown() {}\npub fn used() {}\nfn private() {}".to_owned(),
        ),
        ("game/hud/mod.rs".into(), "fn f() { used(); }".to_owned()),
        (
            "game/mod.rs".into(),
            "pub use layout::{\n    shown,\n};\npub use layout::shown;".to_owned(),
        ),
    ];
    let tests = "shown(); used(); private();";
    assert_eq!(
        pub_only_for_tests(&src, tests),
        ["src/game/layout.rs: shown"]
    );
    assert!(is_the_games_own("src/game/hud/mod.rs: HINT"));
    assert!(!is_the_games_own("src/game/mod.rs: GameLogicPlugin"));
    assert!(!is_the_games_own("src/physics/stability.rs: omega_at"));
}

// ---------------------------------------------------------------------------------------------
// docs/architecture.md read against the code: its room table, its diagram of the game's levels,
// its table of who reads whom (generated), and what it says the core takes from Bevy.

/// docs/architecture.md as it is.
fn architecture_page() -> String {
    fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.md"))
        .expect("docs/architecture.md")
}

/// Returns the rooms a page's table names: each row's first cell, a path in backticks.
fn table_rooms(page: &str, heading: &str) -> Vec<String> {
    let section = page.split(heading).nth(1).expect("the heading");
    let section = section.split("\n## ").next().unwrap_or(section);
    section
        .lines()
        .filter(|line| line.starts_with("| `"))
        .filter_map(|line| line.split('`').nth(1).map(str::to_owned))
        .collect()
}

/// Returns every room of the source tree: `src/`'s files and folders, and `src/game/`'s.
fn rooms_on_disk() -> BTreeSet<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut rooms = BTreeSet::new();
    for folder in ["src", "src/game"] {
        for entry in fs::read_dir(root.join(folder)).expect("a source folder") {
            let path = entry.expect("an entry").path();
            let name = path.file_name().unwrap().to_string_lossy().into_owned();
            if path.is_dir() {
                rooms.insert(format!("{folder}/{name}/"));
            } else if name.ends_with(".rs") && name != "mod.rs" {
                rooms.insert(format!("{folder}/{name}"));
            }
        }
    }
    rooms
}

#[test]
fn the_architecture_page_lists_every_room_and_only_rooms_there_are() {
    let listed = table_rooms(&architecture_page(), "## The rooms");
    let on_disk = rooms_on_disk();
    assert!(on_disk.contains("src/game/ghosts/") && on_disk.contains("src/cli.rs"));
    let missing: Vec<_> = on_disk
        .iter()
        .filter(|room| !listed.contains(room))
        .collect();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let gone: Vec<_> = listed
        .iter()
        .filter(|room| !root.join(room).exists())
        .collect();
    assert!(
        missing.is_empty() && gone.is_empty(),
        "docs/architecture.md's room table: rooms it misses {missing:?}, rooms that are gone {gone:?}"
    );
}

/// Returns the game's levels as the page draws them, from the bottom up: each level's rooms
/// (`mod.rs` is the wiring, "").
fn drawn_levels(page: &str) -> Vec<Vec<String>> {
    let after = page
        .split("Inside the game the rooms are layered")
        .nth(1)
        .expect("the game's diagram");
    let block = after
        .split("```text\n")
        .nth(1)
        .and_then(|b| b.split("```").next())
        .expect("a text block");
    let mut levels: Vec<Vec<String>> = Vec::new();
    let mut continued = false;
    for line in block.lines() {
        // The rooms, then two spaces or more, then what they are.
        let rooms = line.trim_start().split("  ").next().unwrap_or("").trim();
        let names: Vec<String> = rooms
            .split(',')
            .map(|room| room.trim().trim_end_matches('/').trim_end_matches(".rs"))
            .filter(|room| !room.is_empty())
            .map(|room| {
                if room == "mod" {
                    String::new()
                } else {
                    room.to_owned()
                }
            })
            .collect();
        if continued {
            levels.last_mut().unwrap().extend(names);
        } else {
            levels.push(names);
        }
        continued = rooms.ends_with(',');
    }
    levels.reverse();
    levels
}

#[test]
fn the_architecture_page_draws_the_game_levels_the_check_holds() {
    let drawn = drawn_levels(&architecture_page());
    let graph = graph();
    let leaves: BTreeSet<String> = graph
        .keys()
        .filter(|module| is_leaf(module))
        .filter_map(|module| game_room(module).map(str::to_owned))
        .collect();
    assert!(leaves.contains("readouts"), "{leaves:?}");
    let mut held: Vec<BTreeSet<String>> = GAME_LAYERS
        .iter()
        .map(|rooms| rooms.iter().map(|room| (*room).to_owned()).collect())
        .collect();
    held.insert(LEAF, leaves);
    let drawn: Vec<BTreeSet<String>> = drawn.into_iter().map(BTreeSet::from_iter).collect();
    assert_eq!(
        drawn, held,
        "docs/architecture.md's diagram of the game's levels (bottom up) against GAME_LAYERS \
         and the leaves the sources have"
    );
}

/// Returns the Markdown table of which rooms read each room: a room's modules imported by
/// another room's, the wiring (`game/mod.rs`, `play.rs`) left out. Rooms bottom up.
fn who_reads_whom(graph: &BTreeMap<String, BTreeSet<String>>) -> String {
    let room_of = |module: &str| -> Option<String> {
        if let Some(room) = game_room(module) {
            return (!room.is_empty() && room != "play").then(|| format!("game/{room}"));
        }
        (!module.is_empty()).then(|| module.split("::").next().unwrap().to_owned())
    };
    let height = |room: &str| match room.strip_prefix("game/") {
        Some(_) => (
            LAYERS.len(),
            game_layer(&room.replace('/', "::")).unwrap_or(0),
        ),
        None => (layer(room).unwrap_or(0), 0),
    };
    let mut readers: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (module, imported) in graph {
        let Some(reader) = room_of(module) else {
            continue;
        };
        readers.entry(reader.clone()).or_default();
        for target in imported {
            if let Some(room) = room_of(target)
                && room != reader
            {
                readers.entry(room).or_default().insert(reader.clone());
            }
        }
    }
    let mut rooms: Vec<&String> = readers.keys().collect();
    rooms.sort_by_key(|room| (height(room), (*room).clone()));
    let mut table = "| room | read by |\n|---|---|\n".to_owned();
    for room in rooms {
        let by: Vec<String> = readers[room].iter().map(|r| format!("`{r}`")).collect();
        let by = if by.is_empty() {
            "nothing but the wiring".to_owned()
        } else {
            by.join(", ")
        };
        table.push_str(&format!("| `{room}` | {by} |\n"));
    }
    table
}

const READERS_OPEN: &str = "<!-- rooms: who reads whom -->\n";
const READERS_CLOSE: &str = "<!-- /rooms -->";

#[test]
fn the_architecture_page_says_who_reads_whom_as_the_code_does() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.md");
    let page = architecture_page();
    let start = page.find(READERS_OPEN).expect("the who-reads-whom block") + READERS_OPEN.len();
    let end = start + page[start..].find(READERS_CLOSE).expect("its end");
    let table = who_reads_whom(&graph());
    assert!(table.contains("| `game/web` | ") && table.contains("| `physics` | "));
    if page[start..end] == table {
        return;
    }
    if std::env::var_os("RBB_WRITE_ROOMS").is_some() {
        let fresh = format!("{}{table}{}", &page[..start], &page[end..]);
        let beside = path.with_extension("md.new");
        fs::write(&beside, fresh).expect("write beside the page");
        fs::rename(&beside, &path).expect("rename into place");
        return;
    }
    panic!(
        "docs/architecture.md's table of who reads whom is not the code's; rewrite it with \
         RBB_WRITE_ROOMS=1 cargo test --test suite architecture::, then read what changed:\n{table}"
    );
}

#[test]
fn the_who_reads_whom_table_names_a_reader_and_leaves_out_the_wiring() {
    let mut graph = BTreeMap::new();
    for (module, imports) in [
        ("game::hud", vec!["game::web", "game::shared"]),
        ("game::replays::recording", vec!["game::web", "replay"]),
        ("game", vec!["game::hud", "game::web"]),
        ("game::web", vec![]),
        ("game::shared", vec![]),
        ("replay", vec!["physics"]),
        ("physics", vec![]),
    ] {
        graph.insert(
            module.to_owned(),
            imports
                .into_iter()
                .map(str::to_owned)
                .collect::<BTreeSet<_>>(),
        );
    }
    let table = who_reads_whom(&graph);
    assert!(
        table.contains("| `game/web` | `game/hud`, `game/replays` |"),
        "{table}"
    );
    assert!(
        table.contains("| `game/hud` | nothing but the wiring |"),
        "{table}"
    );
    assert!(table.contains("| `physics` | `replay` |"), "{table}");
    assert!(
        table.find("`physics`").unwrap() < table.find("`game/shared`").unwrap(),
        "bottom up: {table}"
    );
}

/// Returns each use of Bevy in the core other than its maths and the two derives the game
/// reads the core's types through (`Component`, `Resource`), as "module: path".
fn bevy_in_the_core(modules: &BTreeMap<String, String>) -> Vec<String> {
    let allowed = [
        "bevy::math",
        "bevy::prelude::Component",
        "bevy::prelude::Resource",
    ];
    let mut found = Vec::new();
    for (module, code) in modules.iter().filter(|(m, _)| m.starts_with("physics")) {
        for (at, _) in code.match_indices("bevy::") {
            let path: String = code[at..]
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
                .collect();
            if !allowed.iter().any(|a| path.starts_with(a)) {
                found.push(format!("{module}: {path}"));
            }
        }
    }
    found
}

#[test]
fn the_core_takes_from_bevy_only_its_maths_and_two_derives() {
    let found = bevy_in_the_core(&modules());
    assert!(
        found.is_empty(),
        "docs/architecture.md says the core is plain Rust with no App, using Bevy's maths and \
         deriving Component and Resource only:\n{}",
        found.join("\n")
    );
    let mut known = BTreeMap::new();
    known.insert(
        "physics::body".to_owned(),
        "use bevy::math::DVec2;\nuse bevy::prelude::App;".to_owned(),
    );
    assert_eq!(
        bevy_in_the_core(&known),
        ["physics::body: bevy::prelude::App"]
    );
}

/// Each line of code (comments left out) in the files `wanted` picks by their path under src/:
/// the path, the line's number and the line, trimmed.
fn code_lines(
    files: &[(std::path::PathBuf, String)],
    wanted: impl Fn(&str) -> bool,
) -> Vec<(String, usize, &str)> {
    let mut found = Vec::new();
    for (path, code) in files {
        let file = path.to_string_lossy().replace('\\', "/");
        if !wanted(&file) {
            continue;
        }
        for (n, line) in code.lines().enumerate() {
            let line = line.trim();
            if !line.starts_with("//") {
                found.push((file.clone(), n + 1, line));
            }
        }
    }
    found
}

/// Returns each line outside the core's stepper that steps an integrator or opens the books.
///
/// The core's booked step (`Books::step` in src/physics/stepper.rs) is the one step with its
/// books: a second one would keep them its own way.
fn second_steps(files: &[(std::path::PathBuf, String)]) -> Vec<String> {
    let core = [
        "physics/stepper.rs",
        "physics/energy.rs",
        "physics/integrators/",
    ];
    code_lines(files, |file| {
        !core.iter().any(|part| file.starts_with(part))
    })
    .into_iter()
    .filter(|(_, _, line)| {
        [".open_step(", ".step_with(", ".step_from("]
            .iter()
            .any(|call| line.contains(call))
    })
    .map(|(file, n, line)| format!("{file}:{n}: {line}"))
    .collect()
}

#[test]
fn the_step_and_its_books_are_written_once_in_the_core() {
    let found = second_steps(&source_files());
    assert!(
        found.is_empty(),
        "steps outside the booked step:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_step_check_finds_a_second_booked_step() {
    let file = (
        std::path::PathBuf::from("game/ghosts/steppers.rs"),
        "fn step(&mut self) {\n    self.ledger.open_step(self.settled, now);\n}\n".to_owned(),
    );
    assert_eq!(second_steps(&[file]).len(), 1);
}

// --- No type of the crate is named as one of Bevy's. ---

/// Tells whether a word is a type's name: CamelCase.
fn is_type_name(word: &str) -> bool {
    word.starts_with(|c: char| c.is_ascii_uppercase())
}

/// Returns the types a module brings in from Bevy by name: those its `use bevy…;` statements
/// list, and the type of each `bevy::…::Name` path it writes inline.
fn bevy_names(code: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    let mut rest = code;
    while let Some(at) = rest.find("use bevy") {
        let statement = &rest[at..];
        let end = statement.find(';').unwrap_or(statement.len());
        let words = statement[..end].split(|c: char| !c.is_ascii_alphanumeric() && c != '_');
        names.extend(words.filter(|w| is_type_name(w)).map(str::to_owned));
        rest = &statement[end..];
    }
    for (at, _) in code.match_indices("bevy::") {
        let path: String = code[at..]
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_' || *c == ':')
            .collect();
        if let Some(name) = path.split("::").find(|w| is_type_name(w)) {
            names.insert(name.to_owned());
        }
    }
    names
}

/// Returns the structs and enums a module defines.
fn defined_types(code: &str) -> BTreeSet<String> {
    code.lines()
        .filter_map(|line| {
            let line = line.trim_start();
            let line = ["pub ", "pub(crate) ", "pub(super) "]
                .iter()
                .find_map(|p| line.strip_prefix(p))
                .unwrap_or(line);
            ["struct ", "enum "]
                .iter()
                .find_map(|k| line.strip_prefix(k))
        })
        .map(|rest| {
            rest.chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect()
        })
        .collect()
}

/// Returns each type defined under a name some module brings in from Bevy, as
/// "module: Name (Bevy's, in other)".
fn names_shared_with_bevy(modules: &BTreeMap<String, String>) -> Vec<String> {
    let imported: Vec<(&String, BTreeSet<String>)> = modules
        .iter()
        .map(|(module, code)| (module, bevy_names(code)))
        .collect();
    let mut shared = Vec::new();
    for (module, code) in modules {
        for name in defined_types(code) {
            for (other, names) in &imported {
                if names.contains(&name) {
                    shared.push(format!("{module}: {name} (Bevy's, in {other})"));
                }
            }
        }
    }
    shared
}

/// A marker named as a Bevy type that another module imports reads as Bevy's there: `access`
/// once queried Bevy's `ViewportNode`, not the layout's, and found no node (issue 61).
#[test]
fn no_type_of_the_crate_is_named_as_one_brought_in_from_bevy() {
    let shared = names_shared_with_bevy(&modules());
    assert!(
        shared.is_empty(),
        "types named as Bevy's:\n{}",
        shared.join("\n")
    );
}

#[test]
fn the_bevy_name_check_finds_a_marker_named_as_bevys() {
    let modules: BTreeMap<String, String> = [
        ("game::layout", "#[derive(Component)]\nstruct ViewportNode;"),
        (
            "game::access",
            "use bevy::prelude::*;\nuse bevy::ui::widget::{\n    Label,\n    ViewportNode,\n};",
        ),
        (
            "game::screen",
            "let a = bevy::ui::widget::ViewportNode::new(camera);",
        ),
    ]
    .into_iter()
    .map(|(module, code)| (module.to_owned(), code.to_owned()))
    .collect();
    assert_eq!(
        names_shared_with_bevy(&modules),
        [
            "game::layout: ViewportNode (Bevy's, in game::access)",
            "game::layout: ViewportNode (Bevy's, in game::screen)",
        ]
    );
}

/// Returns each line outside the replay's format, its reader and its writer that reads a record
/// for what it does.
///
/// The one reader (`replay::play::cue`) tells every player (the core's run, the game's playback,
/// the peers' and the writer's model) what each record puts in place.
fn second_readers(files: &[(std::path::PathBuf, String)]) -> Vec<String> {
    let own = [
        "replay/format.rs",
        "replay/play.rs",
        "replay/read.rs",
        "replay/write.rs",
    ];
    code_lines(files, |file| !own.contains(&file))
        .into_iter()
        .filter(|(_, _, line)| line.contains("Record::"))
        .map(|(file, n, line)| format!("{file}:{n}: {line}"))
        .collect()
}

#[test]
fn a_replay_is_read_once() {
    let found = second_readers(&source_files());
    assert!(
        found.is_empty(),
        "records read outside the one reader:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_reader_check_finds_a_second_reader() {
    let file = (
        std::path::PathBuf::from("game/replays/playback.rs"),
        "match record {\n    Record::Reset { .. } => reset(),\n}\n".to_owned(),
    );
    assert_eq!(second_readers(&[file]).len(), 1);
}

/// Every other plugin sends `Say`; the HUD alone keeps what the status line says (its row of
/// [`OWNERS`]).
#[test]
fn only_the_hud_writes_the_status_line() {
    let found: Vec<String> = foreign_writes(&source_files())
        .into_iter()
        .filter(|write| write.contains("StatusMessage"))
        .collect();
    assert!(
        found.is_empty(),
        "status written outside the HUD:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_status_check_finds_a_writer() {
    let file = (
        std::path::PathBuf::from("game/input/controls.rs"),
        "fn f(mut status: ResMut<StatusMessage>) {}\n".to_owned(),
    );
    assert_eq!(foreign_writes(&[file]).len(), 1);
}

// --- Every setting written by its owner (issue 61). ---

/// The exclusive functions and queued closures the game keeps, each with why.
const EXCLUSIVE: [(&str, &str); 1] = [(
    "game/schedule.rs: fn change_the_mode(world: &mut World) {",
    "runs Bevy's StateTransition again, so a mode a control asked for this frame is in place \
     for its steps; it writes State<Mode>, learn mode's, through Bevy",
)];

/// Returns each line of the game that takes the whole world or queues a closure over it.
fn exclusive_lines(files: &[(std::path::PathBuf, String)]) -> Vec<String> {
    code_lines(files, |file| file.starts_with("game/"))
        .into_iter()
        .filter(|(_, _, line)| line.contains("&mut World") || line.contains(".queue("))
        .map(|(file, _, line)| format!("{file}: {line}"))
        .collect()
}

#[test]
fn the_game_keeps_one_exclusive_system_and_says_why() {
    let found = exclusive_lines(&source_files());
    let kept: Vec<String> = EXCLUSIVE
        .iter()
        .map(|(line, _)| (*line).to_owned())
        .collect();
    assert_eq!(
        found, kept,
        "exclusive functions or queued closures in src/game"
    );
}

/// Who may write each resource the game's settings are kept in: its owner's files.
///
/// `Time<Fixed>` has a second writer, the frame's budget, which drops the time a slow frame
/// still owes (a message a step would cost a system a step: docs/peers.md).
const OWNERS: [(&str, &[&str]); 14] = [
    ("SceneParams", &["game/simulation.rs"]),
    ("Integrator", &["game/simulation.rs"]),
    ("AutoSettings", &["game/simulation.rs"]),
    ("Time<Fixed>", &["game/simulation.rs", "game/budget.rs"]),
    ("Time<Virtual>", &["game/simulation.rs"]),
    ("Overlays", &["game/shared.rs"]),
    ("DockHidden", &["game/shared.rs"]),
    ("SceneName", &["game/shared.rs"]),
    ("Cards", &["game/layout/"]),
    ("CameraFrame", &["game/camera.rs"]),
    ("Playback", &["game/replays/playback.rs"]),
    ("StatusMessage", &["game/hud/"]),
    ("InputFocus", &["game/input/focus.rs"]),
    ("NextState<Mode>", &["game/learn/"]),
];

/// Returns each write of a setting's resource outside its owner's files.
///
/// A write is a `ResMut` of it, a `resource_mut` of it, or an `insert_resource` in a system
/// (the play command's set-up, before the plugins, puts the first values in).
fn foreign_writes(files: &[(std::path::PathBuf, String)]) -> Vec<String> {
    let mut found = Vec::new();
    for (file, n, line) in code_lines(files, |file| file.starts_with("game/")) {
        if line.contains("insert_resource(") && file != "game/play.rs" {
            found.push(format!("{file}:{n}: {line}"));
        }
        for (resource, owners) in OWNERS {
            let writes = [
                format!("ResMut<{resource}>"),
                format!("ResMut<'w, {resource}>"),
                format!("::{resource}>"),
                format!("resource_mut::<{resource}>"),
            ];
            let written = writes.iter().any(|write| {
                line.contains(write.as_str())
                    && (write.starts_with("ResMut")
                        || write.starts_with("resource_mut")
                        || line.contains("ResMut<"))
            });
            if written && !owners.iter().any(|owner| file.starts_with(owner)) {
                found.push(format!("{file}:{n}: {resource}: {line}"));
            }
        }
    }
    found
}

#[test]
fn every_setting_is_written_by_its_owner() {
    let found = foreign_writes(&source_files());
    assert!(
        found.is_empty(),
        "settings written outside their owners:\n{}",
        found.join("\n")
    );
}

#[test]
fn the_owner_check_finds_a_foreign_writer() {
    let files = [
        (
            std::path::PathBuf::from("game/learn/mod.rs"),
            "fn go_to(mut frame: ResMut<CameraFrame>) {}\n".to_owned(),
        ),
        (
            std::path::PathBuf::from("game/access/mod.rs"),
            "    mut focus: ResMut<bevy::input_focus::InputFocus>,\n".to_owned(),
        ),
        (
            std::path::PathBuf::from("game/replays/links.rs"),
            "    commands.insert_resource(params);\n".to_owned(),
        ),
    ];
    assert_eq!(foreign_writes(&files).len(), 3);
    let exclusive = (
        std::path::PathBuf::from("game/learn/mod.rs"),
        "fn go_to(world: &mut World, index: usize) {\n".to_owned(),
    );
    assert_eq!(exclusive_lines(&[exclusive]).len(), 1);
}
