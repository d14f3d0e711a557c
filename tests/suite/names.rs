//! Every name README.md and docs/*.md use resolves against the code, read without building:
//! - a repository path (`src/…`, `tests/…`, `docs/…`, `assets/…`, `benches/…`, `.ci/…`, a
//!   top-level file), in backticks or in prose, exists, and so does a source file's short path;
//! - a backticked `module::item` resolves, module by module, to a file that defines it; a
//!   `snake_case` name is in the code, a `CamelCase` one defined in it (or on the list of
//!   outside names); an item said to be in a file ("`x` in `path`", "`path`'s `x`",
//!   `path::x`) is defined there, a test as a `fn` of its test file;
//! - a `snake_case` name beside a test file's path is a test of that file, or the sources' item;
//! - a `--flag` is the command line's (clap's `#[arg]`s), cargo's, a harness's or its script's,
//!   and `cargo test --test T F` names a target, a module of it and a test;
//! - an environment variable is read by src/, tests/, benches/, examples/ or .ci/, or is on the
//!   list of outside ones.
//!
//! Each failure says page:line, the name, why, and where the name went if it is elsewhere.

use std::collections::{BTreeSet, HashMap, HashSet};
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use crate::pages::{pages, root};

// ---------------------------------------------------------------------------------------------
// The lists of names that are not the project's, each with its reason.

/// Names the pages use from outside the project: Bevy's, the peers', the platform's.
const OUTSIDE_NAMES: &[(&str, &str)] = &[
    // Bevy's API, as the pages name what the game builds on.
    ("App", "Bevy"),
    ("Camera", "Bevy"),
    ("Commands", "Bevy"),
    ("Component", "Bevy"),
    ("Resource", "Bevy"),
    ("SystemSet", "Bevy"),
    ("SystemParam", "Bevy"),
    ("QueryData", "Bevy"),
    ("FixedUpdate", "Bevy"),
    ("Update", "Bevy"),
    ("PreUpdate", "Bevy"),
    ("PostUpdate", "Bevy"),
    ("Startup", "Bevy"),
    ("PreStartup", "Bevy"),
    ("PostStartup", "Bevy"),
    ("Last", "Bevy"),
    ("RunFixedMainLoop", "Bevy"),
    ("StateTransition", "Bevy"),
    ("OnEnter", "Bevy"),
    ("OnExit", "Bevy"),
    ("NextState", "Bevy"),
    ("State", "Bevy"),
    ("Res", "Bevy"),
    ("MinimalPlugins", "Bevy"),
    ("TransformPlugin", "Bevy"),
    ("TimeUpdateStrategy", "Bevy"),
    ("InputFocusVisible", "Bevy"),
    ("AccessibilityNode", "Bevy"),
    ("Text", "Bevy"),
    ("Node", "Bevy"),
    ("Transform", "Bevy"),
    ("Time", "Bevy"),
    ("Schedule", "Bevy"),
    ("Schedules", "Bevy"),
    ("DVec2", "Bevy's maths (glam)"),
    ("Button", "Bevy's widgets, and AccessKit's role"),
    ("Slider", "Bevy's widgets, and AccessKit's role"),
    ("Executor", "async-executor, under Bevy"),
    ("ConcurrentQueue", "concurrent-queue, under Bevy"),
    ("Label", "AccessKit's role"),
    ("Group", "AccessKit's role"),
    // The peers' API (feature `peers`).
    ("TimestepMode", "bevy_rapier2d"),
    ("SpringJointBuilder", "bevy_rapier2d"),
    ("DistanceJoint", "avian2d"),
    ("NarrowPhaseConfig", "avian2d"),
    ("BvhBroadPhasePlugin", "avian2d"),
    ("LinearDamping", "avian2d"),
    ("AngularDamping", "avian2d"),
    ("Damping", "bevy_rapier2d"),
    // Bevy's sets around the fixed loop, the game's sets' parents.
    ("BeforeFixedMainLoop", "Bevy"),
    ("AfterFixedMainLoop", "Bevy"),
    // Keys as the keyboard names them.
    ("Space", "a key"),
    ("Tab", "a key"),
    ("Esc", "a key"),
    ("Enter", "a key"),
    ("Home", "a key"),
    ("End", "a key"),
    ("Shift", "a key"),
    ("PgUp", "a key"),
    ("PgDn", "a key"),
    ("PageUp", "a key"),
    ("PageDown", "a key"),
    // What cargo prints.
    ("Running", "cargo's output"),
    ("Compiling", "cargo's output"),
    // Other crates' and tools' names that read as code.
    ("max_delta", "Bevy's `Time<Virtual>` field"),
    ("get_resource_mut", "Bevy's `World` method"),
    ("run_fixed_main_schedule", "Bevy's system"),
    ("physics_in_fixed_timestep", "Bevy's example"),
    ("default_font", "Bevy's cargo feature"),
    ("ui_picking", "Bevy's cargo feature"),
    ("auto_register_inventory", "Bevy's cargo feature"),
    ("accesskit_unix", "Bevy's cargo feature"),
    ("float_roundtrip", "serde_json's cargo feature"),
    ("gzip_static", "nginx's setting"),
    ("brotli_static", "nginx's setting"),
    (
        "remove_existing",
        "history: dead code removed (docs/testing.md tells it)",
    ),
];

/// Environment variables the project does not read but the pages name: cargo's, the shell's,
/// the display's.
const OUTSIDE_VARIABLES: &[(&str, &str)] = &[
    (
        "CARGO_TARGET_DIR",
        "cargo's target folder (.ci/ passes it on)",
    ),
    (
        "CARGO_MANIFEST_DIR",
        "cargo's, read by the tests through env!",
    ),
    ("RUSTDOCFLAGS", "cargo doc's flags"),
    ("RUSTFLAGS", "rustc's flags"),
    ("RUST_LOG", "the log filter"),
    ("DISPLAY", "the X display"),
    ("WAYLAND_DISPLAY", "the Wayland display"),
    ("HOME", "the shell's"),
    ("PATH", "the shell's"),
    ("CI", "set by CI runners and by .ci/run"),
];

/// Flags of cargo's own commands.
const CARGO_FLAGS: &[&str] = &[
    "--release",
    "--features",
    "--all-features",
    "--no-default-features",
    "--test",
    "--tests",
    "--bench",
    "--benches",
    "--bin",
    "--bins",
    "--lib",
    "--example",
    "--examples",
    "--all-targets",
    "--profile",
    "--target",
    "--no-run",
    "--no-fail-fast",
    "--no-deps",
    "--timings",
    "--version",
    "--check",
    "--doc",
    "--workspace",
    "--package",
    "--locked",
    "--offline",
    "--jobs",
    "--message-format",
    "--manifest-path",
    "--quiet",
    "--verbose",
    "--config",
];

/// Flags of the test harness (libtest), after `--`.
const LIBTEST_FLAGS: &[&str] = &[
    "--nocapture",
    "--exact",
    "--test-threads",
    "--ignored",
    "--include-ignored",
    "--list",
    "--skip",
    "--show-output",
    "--quiet",
];

/// Flags of criterion's harness, after `--` in `cargo bench`.
const CRITERION_FLAGS: &[&str] = &[
    "--noplot",
    "--profile-time",
    "--warm-up-time",
    "--measurement-time",
    "--save-baseline",
    "--baseline",
    "--sample-size",
    "--bench",
    "--list",
];

/// Flags of other tools the pages quote: cargo-mutants, cargo install, wasm-bindgen, python's
/// server, clap's own.
const TOOL_FLAGS: &[&str] = &[
    "--in-place",
    "--no-shuffle",
    "--timeout",
    "--file",
    "--version",
    "--directory",
    "--help",
    "--target",
    "--out-dir",
    "--no-typescript",
    "--remove-name-section",
    "--remove-producers-section",
];

// ---------------------------------------------------------------------------------------------
// The code, indexed once.

/// What one source file defines and says.
#[derive(Default)]
struct Source {
    /// Items defined: fns, types, traits, consts, statics, modules, macros, enum variants and
    /// struct fields.
    defined: HashSet<String>,
    /// Functions defined (a test is one).
    fns: HashSet<String>,
    /// Names a `use` statement brings in (a re-export counts as being there).
    used: HashSet<String>,
    /// Every identifier in the file, comments and strings too.
    words: HashSet<String>,
    /// Every string literal's text.
    strings: HashSet<String>,
}

struct Index {
    root: PathBuf,
    /// Every file of the repository (not target/, .git/, site/, node_modules/), relative.
    files: Vec<String>,
    /// Every folder of the repository, relative, no trailing slash.
    folders: HashSet<String>,
    /// The Rust files of src/, tests/, benches/ and examples/, read.
    sources: HashMap<String, Source>,
    /// The other files of .ci/ and Cargo.toml, as text.
    scripts: HashMap<String, String>,
    /// The command line's flags: subcommand ("" for every one) to its flags.
    cli_flags: HashMap<String, HashSet<String>>,
    /// Cargo.toml's features.
    features: HashSet<String>,
    /// Cargo.lock's packages, `-` written `_`: a crate's name is no item of ours.
    crates: HashSet<String>,
}

fn index() -> &'static Index {
    static INDEX: OnceLock<Index> = OnceLock::new();
    INDEX.get_or_init(|| Index::read(&root()))
}

fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

fn is_ident_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Returns the identifiers of `text`, in order.
fn identifiers(text: &str) -> Vec<&str> {
    let mut found = Vec::new();
    let mut start = None;
    for (at, c) in text.char_indices() {
        match (start, is_ident_char(c)) {
            (None, true) => start = Some(at),
            (Some(from), false) => {
                found.push(&text[from..at]);
                start = None;
            }
            _ => {}
        }
    }
    if let Some(from) = start {
        found.push(&text[from..]);
    }
    found
        .into_iter()
        .filter(|word| word.starts_with(is_ident_start))
        .collect()
}

/// Returns the identifier that opens `text`, if one does.
fn leading_ident(text: &str) -> Option<&str> {
    let end = text.find(|c: char| !is_ident_char(c)).unwrap_or(text.len());
    (end > 0 && text.starts_with(is_ident_start)).then(|| &text[..end])
}

/// Reads a Rust file's definitions, line by line: good enough for rustfmt's layout.
fn read_source(text: &str) -> Source {
    let mut source = Source::default();
    for word in identifiers(text) {
        source.words.insert(word.to_owned());
    }
    for (at, _) in text.match_indices('"') {
        let rest = &text[at + 1..];
        if let Some(end) = rest.find('"') {
            source.strings.insert(rest[..end].to_owned());
        }
    }
    // The innermost block that lists variants or fields, by its brace depth.
    let mut depth: i32 = 0;
    let mut blocks: Vec<(i32, bool)> = Vec::new(); // (depth inside, is an enum)
    let mut in_use = false;
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("");
        let trimmed = code.trim_start();
        let mut rest = trimmed;
        // Visibility and qualifiers.
        loop {
            let before = rest;
            for prefix in [
                "pub(crate) ",
                "pub(super) ",
                "pub(self) ",
                "pub ",
                "async ",
                "unsafe ",
                "extern \"C\" ",
                "default ",
            ] {
                if let Some(after) = rest.strip_prefix(prefix) {
                    rest = after;
                }
            }
            if let Some(after) = rest.strip_prefix("const ")
                && after.starts_with("fn ")
            {
                rest = after;
            }
            if let Some(after) = rest.strip_prefix("pub(in ") {
                rest = after.split_once(") ").map_or("", |(_, r)| r);
            }
            if rest == before {
                break;
            }
        }
        for keyword in [
            "fn ",
            "struct ",
            "enum ",
            "trait ",
            "type ",
            "const ",
            "static ",
            "mod ",
            "union ",
            "macro_rules! ",
        ] {
            if let Some(after) = rest.strip_prefix(keyword) {
                let after = after.strip_prefix("mut ").unwrap_or(after);
                if let Some(name) = leading_ident(after) {
                    source.defined.insert(name.to_owned());
                    if keyword == "fn " {
                        source.fns.insert(name.to_owned());
                    }
                }
            }
        }
        // A variant or a field: an identifier opening a line directly inside an enum or a
        // struct's braces.
        if let Some(&(inside, is_enum)) = blocks.last()
            && depth == inside
            && let Some(name) = leading_ident(rest)
        {
            let after = rest[name.len()..].trim_start();
            let variant = is_enum && (after.is_empty() || after.starts_with([',', '(', '{', '=']));
            let field = !is_enum && after.starts_with(':') && !after.starts_with("::");
            if variant || field {
                source.defined.insert(name.to_owned());
            }
        }
        if rest.starts_with("use ") || in_use {
            in_use = !code.contains(';');
            if trimmed.starts_with("pub") || in_use || rest.starts_with("use ") {
                for word in identifiers(code) {
                    source.used.insert(word.to_owned());
                }
            }
        }
        let opens_block = (rest.starts_with("enum ") || rest.starts_with("struct "))
            && code.contains('{')
            && !code.contains('}');
        for c in code.chars() {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    while blocks.last().is_some_and(|&(inside, _)| inside > depth) {
                        blocks.pop();
                    }
                }
                _ => {}
            }
        }
        if opens_block {
            blocks.push((depth, rest.starts_with("enum ")));
        }
    }
    source
}

/// Returns the command line's flags by subcommand, from clap's `#[arg(...)]` attributes.
fn read_cli_flags(
    sources: &HashMap<String, Source>,
    root: &Path,
) -> HashMap<String, HashSet<String>> {
    let mut flags: HashMap<String, HashSet<String>> = HashMap::new();
    let all = flags.entry(String::new()).or_default();
    all.insert("--help".to_owned());
    all.insert("--version".to_owned());
    for path in sources.keys().filter(|path| path.starts_with("src/")) {
        let Ok(text) = fs::read_to_string(root.join(path)) else {
            continue;
        };
        let mut owner = String::new();
        let mut pending: Option<Option<String>> = None; // an #[arg(long...)] seen: its long name
        let mut attribute = String::new();
        for line in text.lines() {
            let trimmed = line.trim();
            if let Some(name) = trimmed.strip_prefix("pub struct ").and_then(leading_ident) {
                // A subcommand's arguments, `<Name>Args`: its flags are `name`'s.
                owner = name
                    .strip_suffix("Args")
                    .map(str::to_lowercase)
                    .unwrap_or_default();
            }
            if trimmed.starts_with("#[arg(") || !attribute.is_empty() {
                attribute.push_str(trimmed);
                if trimmed.ends_with(")]") {
                    let inner = attribute.trim_start_matches("#[arg(").to_owned();
                    attribute.clear();
                    let long = inner.split(',').map(str::trim).find_map(|part| {
                        if part == "long" || part == "long)]" {
                            Some(None)
                        } else {
                            part.strip_prefix("long = \"")
                                .map(|name| Some(name.split('"').next().unwrap_or("").to_owned()))
                        }
                    });
                    if let Some(long) = long {
                        pending = Some(long);
                    }
                }
                continue;
            }
            if let Some(long) = pending.take() {
                let field = trimmed
                    .trim_start_matches("pub ")
                    .split(':')
                    .next()
                    .unwrap_or("")
                    .trim();
                if field.is_empty() || field.starts_with("///") || field.starts_with("#[") {
                    pending = Some(long);
                    continue;
                }
                let name = long.unwrap_or_else(|| field.replace('_', "-"));
                let flag = format!("--{name}");
                flags.entry(owner.clone()).or_default().insert(flag.clone());
                flags.entry(String::new()).or_default().insert(flag);
            }
        }
    }
    flags
}

impl Index {
    fn read(root: &Path) -> Self {
        let mut files = Vec::new();
        let mut folders = HashSet::new();
        let mut stack = vec![PathBuf::new()];
        while let Some(folder) = stack.pop() {
            let Ok(entries) = fs::read_dir(root.join(&folder)) else {
                continue;
            };
            for entry in entries.flatten() {
                let name = entry.file_name().to_string_lossy().into_owned();
                let relative = folder.join(&name);
                let text = relative.to_string_lossy().replace('\\', "/");
                let is_dir = entry.file_type().is_ok_and(|t| t.is_dir());
                if is_dir {
                    // Build output, copies and downloads: not the repository's.
                    let top = folder.as_os_str().is_empty()
                        && (["target", ".git", "site"].contains(&name.as_str())
                            || name.starts_with("mutants.out"));
                    if top || name == "node_modules" {
                        continue;
                    }
                    folders.insert(text);
                    stack.push(relative);
                } else {
                    files.push(text);
                }
            }
        }
        files.sort();
        let mut sources = HashMap::new();
        let mut scripts = HashMap::new();
        for file in &files {
            let code_root = ["src/", "tests/", "benches/", "examples/"]
                .iter()
                .any(|prefix| file.starts_with(prefix));
            if code_root && file.ends_with(".rs") {
                if let Ok(text) = fs::read_to_string(root.join(file)) {
                    let mut source = read_source(&text);
                    if file.ends_with("/names.rs") {
                        // This file's made-up pages name what exists nowhere.
                        source.words.clear();
                        source.strings.clear();
                    }
                    sources.insert(file.clone(), source);
                }
            } else if ((file.starts_with(".ci/") && !file.ends_with(".json"))
                || file == "Cargo.toml")
                && let Ok(text) = fs::read_to_string(root.join(file))
            {
                scripts.insert(file.clone(), text);
            }
        }
        let cli_flags = read_cli_flags(&sources, root);
        let features = scripts
            .get("Cargo.toml")
            .map(|toml| {
                toml.split("\n[features]\n")
                    .nth(1)
                    .unwrap_or("")
                    .lines()
                    .take_while(|line| !line.starts_with('['))
                    .filter_map(|line| {
                        line.split_once(" = ")
                            .map(|(name, _)| name.trim().to_owned())
                    })
                    .collect()
            })
            .unwrap_or_default();
        let crates = fs::read_to_string(root.join("Cargo.lock"))
            .unwrap_or_default()
            .lines()
            .filter_map(|line| line.strip_prefix("name = \""))
            .map(|name| name.trim_end_matches('"').replace('-', "_"))
            .collect();
        Index {
            crates,
            root: root.to_owned(),
            files,
            folders,
            sources,
            scripts,
            cli_flags,
            features,
        }
    }

    fn exists(&self, path: &str) -> bool {
        let path = path.trim_end_matches('/');
        self.folders.contains(path) || self.files.binary_search(&path.to_owned()).is_ok()
    }

    /// The Rust files a path names: the file, or every one under the folder.
    fn rust_files_of(&self, path: &str) -> Vec<&str> {
        let path = path.trim_end_matches('/');
        if path.ends_with(".rs") {
            return self
                .sources
                .get_key_value(path)
                .map(|(k, _)| k.as_str())
                .into_iter()
                .collect();
        }
        let folder = format!("{path}/");
        self.sources
            .keys()
            .filter(|file| file.starts_with(&folder))
            .map(String::as_str)
            .collect()
    }

    /// The files that define `name` (a test: as a `fn`), sorted.
    fn defining(&self, name: &str, prefixes: &[&str], fns_only: bool) -> Vec<&str> {
        let mut found: Vec<&str> = self
            .sources
            .iter()
            .filter(|(path, _)| prefixes.iter().any(|prefix| path.starts_with(prefix)))
            .filter(|(_, source)| {
                if fns_only {
                    source.fns.contains(name)
                } else {
                    source.defined.contains(name)
                }
            })
            .map(|(path, _)| path.as_str())
            .collect();
        found.sort();
        found
    }

    /// Tells whether `name` is anywhere in the code: sources, scripts, Cargo.toml.
    fn mentions(&self, name: &str) -> bool {
        self.sources
            .values()
            .any(|source| source.words.contains(name) || source.defined.contains(name))
            || self
                .scripts
                .values()
                .any(|text| identifiers(text).contains(&name))
    }

    /// The module file a module's name opens at: the crate's own, a game room, or any module
    /// of that name (the tests' `common` too).
    fn module(&self, name: &str) -> Option<String> {
        let candidates = [
            format!("src/{name}.rs"),
            format!("src/{name}/mod.rs"),
            format!("src/game/{name}.rs"),
            format!("src/game/{name}/mod.rs"),
        ];
        if let Some(found) = candidates
            .iter()
            .find(|path| self.sources.contains_key(*path))
        {
            return Some(found.clone());
        }
        if name == "common" {
            for path in ["tests/suite/common.rs", "tests/common/mod.rs"] {
                if self.sources.contains_key(path) {
                    return Some(path.to_owned());
                }
            }
        }
        let file = format!("/{name}.rs");
        let folder = format!("/{name}/mod.rs");
        let mut any: Vec<&String> = self
            .sources
            .keys()
            .filter(|path| {
                path.starts_with("src/") && (path.ends_with(&file) || path.ends_with(&folder))
            })
            .collect();
        any.sort();
        any.first().map(|path| (*path).clone())
    }

    /// The submodule `name` of the module in `file`, if there is one.
    fn submodule(&self, file: &str, name: &str) -> Option<String> {
        let folder = match file.strip_suffix("/mod.rs") {
            Some(folder) => folder.to_owned(),
            None => file.trim_end_matches(".rs").to_owned(),
        };
        [
            format!("{folder}/{name}.rs"),
            format!("{folder}/{name}/mod.rs"),
        ]
        .into_iter()
        .find(|path| self.sources.contains_key(path))
    }

    /// Tells whether a type or a trait (a CamelCase name) is the project's.
    fn is_project_type(&self, name: &str) -> bool {
        !self
            .defining(name, &["src/", "tests/", "benches/"], false)
            .is_empty()
    }

    /// Resolves a repository path relative to the sources (`screen/view.rs`, `game/learn`):
    /// the files and folders whose path ends with it.
    fn resolve_relative(&self, path: &str) -> Vec<String> {
        let path = path.trim_end_matches('/');
        let tail = format!("/{path}");
        let module = format!("/{path}.rs");
        let mut found: Vec<String> = self
            .files
            .iter()
            .chain(self.folders.iter())
            .filter(|file| {
                ["src/", "tests/", "benches/", ".ci/"]
                    .iter()
                    .any(|p| file.starts_with(p))
                    && (file.ends_with(&tail) || (!path.contains('.') && file.ends_with(&module)))
            })
            .cloned()
            .collect();
        found.sort();
        found
    }
}

// ---------------------------------------------------------------------------------------------
// The pages, read into units: a sentence, a table row or a line of a code block.

#[derive(Clone, Copy, PartialEq, Debug)]
enum Kind {
    Prose,
    Row,
    Code,
}

/// A code span: its text and where it lies in its unit.
#[derive(Debug)]
struct Span {
    text: String,
    start: usize,
    end: usize,
}

#[derive(Debug)]
struct Unit {
    kind: Kind,
    text: String,
    /// (byte offset in `text`, line number in the page) at each line's start.
    lines: Vec<(usize, usize)>,
    spans: Vec<Span>,
}

impl Unit {
    fn line_at(&self, offset: usize) -> usize {
        self.lines
            .iter()
            .take_while(|(start, _)| *start <= offset)
            .last()
            .map_or(1, |(_, line)| *line)
    }
}

/// Returns the code spans of `text`: a run of backticks to the next run as long.
fn code_spans(text: &str) -> Vec<Span> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let mut at = 0;
    while at < bytes.len() {
        if bytes[at] != b'`' {
            at += 1;
            continue;
        }
        let run = bytes[at..].iter().take_while(|b| **b == b'`').count();
        let open_end = at + run;
        let ticks = "`".repeat(run);
        let mut search = open_end;
        let mut close = None;
        while let Some(found) = text[search..].find(&ticks) {
            let from = search + found;
            let length = bytes[from..].iter().take_while(|b| **b == b'`').count();
            if length == run {
                close = Some(from);
                break;
            }
            search = from + length;
        }
        match close {
            Some(close) => {
                let inner = text[open_end..close].replace('\n', " ");
                spans.push(Span {
                    text: inner.trim().to_owned(),
                    start: at,
                    end: close + run,
                });
                at = close + run;
            }
            None => at = open_end,
        }
    }
    spans
}

/// Splits a paragraph into sentences: at `.`, `?` or `!` and a space before a capital, a
/// backtick, a bracket or emphasis, outside code spans.
fn sentences(text: &str, spans: &[Span]) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let in_span = |at: usize| spans.iter().any(|span| span.start <= at && at < span.end);
    let mut cuts = vec![0];
    for at in 0..bytes.len().saturating_sub(2) {
        if matches!(bytes[at], b'.' | b'?' | b'!')
            && matches!(bytes[at + 1], b' ' | b'\n')
            && !in_span(at)
        {
            let next = text[at + 1..].trim_start().chars().next();
            let before = text[..at].rsplit(' ').next().unwrap_or("");
            let abbreviation = ["e.g", "i.e", "vs", "cf", "etc"].contains(&before);
            if next.is_some_and(|c| c.is_uppercase() || "`([*".contains(c)) && !abbreviation {
                cuts.push(at + 1);
            }
        }
    }
    cuts.push(text.len());
    cuts.windows(2).map(|w| (w[0], w[1])).collect()
}

/// Reads a page into units.
fn units_of(page: &str) -> Vec<Unit> {
    let mut units = Vec::new();
    let mut paragraph: Vec<(usize, &str)> = Vec::new();
    let flush = |paragraph: &mut Vec<(usize, &str)>, units: &mut Vec<Unit>| {
        if paragraph.is_empty() {
            return;
        }
        let mut text = String::new();
        let mut lines = Vec::new();
        for (number, line) in paragraph.drain(..) {
            if !text.is_empty() {
                text.push('\n');
            }
            lines.push((text.len(), number));
            text.push_str(line);
        }
        let spans = code_spans(&text);
        for (from, to) in sentences(&text, &spans) {
            let piece = &text[from..to];
            let shifted: Vec<(usize, usize)> = lines
                .iter()
                .map(|(start, line)| (start.saturating_sub(from), *line))
                .filter(|(start, _)| *start < piece.len() || *start == 0)
                .collect();
            let mut own: Vec<(usize, usize)> = Vec::new();
            for (start, line) in shifted {
                if own.last().is_some_and(|(s, _)| *s == start) {
                    own.pop();
                }
                own.push((start, line));
            }
            units.push(Unit {
                kind: Kind::Prose,
                text: piece.to_owned(),
                lines: own,
                spans: code_spans(piece),
            });
        }
    };
    let mut fenced = false;
    let mut comment = false;
    for (index, line) in page.lines().enumerate() {
        let number = index + 1;
        let trimmed = line.trim_start();
        if trimmed.starts_with("```") {
            flush(&mut paragraph, &mut units);
            fenced = !fenced;
            continue;
        }
        if fenced {
            units.push(Unit {
                kind: Kind::Code,
                text: line.to_owned(),
                lines: vec![(0, number)],
                spans: Vec::new(),
            });
            continue;
        }
        if comment || trimmed.starts_with("<!--") {
            comment = !trimmed.contains("-->") && (comment || !trimmed.ends_with("-->"));
            flush(&mut paragraph, &mut units);
            continue;
        }
        if trimmed.is_empty() {
            flush(&mut paragraph, &mut units);
        } else if trimmed.starts_with('|') || trimmed.starts_with('#') {
            flush(&mut paragraph, &mut units);
            units.push(Unit {
                kind: if trimmed.starts_with('|') {
                    Kind::Row
                } else {
                    Kind::Prose
                },
                text: line.to_owned(),
                lines: vec![(0, number)],
                spans: code_spans(line),
            });
        } else {
            let item = trimmed.starts_with("- ")
                || trimmed.starts_with("* ")
                || trimmed
                    .split_once(". ")
                    .is_some_and(|(n, _)| !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()));
            if item {
                flush(&mut paragraph, &mut units);
            }
            paragraph.push((number, line));
        }
    }
    flush(&mut paragraph, &mut units);
    units
}

// ---------------------------------------------------------------------------------------------
// What the units name.

const PREFIXES: [&str; 7] = [
    "src/",
    "tests/",
    "docs/",
    "assets/",
    "benches/",
    "examples/",
    ".ci/",
];
const TOP_FILES: [&str; 7] = [
    "Cargo.toml",
    "Cargo.lock",
    "README.md",
    "LICENSE-MIT",
    "LICENSE-APACHE",
    "build.rs",
    "rust-toolchain.toml",
];

/// Strips what ends a path in a sentence: punctuation, a possessive.
fn trim_path(word: &str) -> &str {
    let word = word.trim_start_matches(['(', '[', '"', '\'']);
    let word = word.strip_suffix("'s").unwrap_or(word);
    word.trim_end_matches([',', ';', ':', ')', ']', '(', '.', '"', '\'', '!', '?'])
}

/// Tells whether a path holds a placeholder rather than a name: `…`, `<x>`, `FILE`.
fn is_placeholder(path: &str) -> bool {
    path.contains("...")
        || path.contains('…')
        || path.contains(['<', '>', '{', '$'])
        || path.split('/').any(|segment| {
            segment.len() > 1 && segment.chars().all(|c| c.is_ascii_uppercase() || c == '_')
        })
}

/// A repository path as the page writes it, and the item after `::` if any.
fn split_item(word: &str) -> (&str, Option<&str>) {
    match word.split_once("::") {
        Some((path, item)) => (path, Some(item)),
        None => (word, None),
    }
}

fn is_repo_path(word: &str) -> bool {
    PREFIXES.iter().any(|prefix| word.starts_with(prefix)) || TOP_FILES.contains(&word)
}

/// The repository paths of a unit's prose (outside code spans and link targets).
fn prose_paths(unit: &Unit) -> Vec<(usize, String)> {
    let mut text: Vec<u8> = unit.text.as_bytes().to_vec();
    let mut blank = |from: usize, to: usize| {
        for byte in &mut text[from..to] {
            *byte = b' ';
        }
    };
    for span in &unit.spans {
        blank(span.start, span.end);
    }
    let mut at = 0;
    while let Some(found) = unit.text[at..].find("](") {
        let from = at + found + 2;
        let to = unit.text[from..]
            .find(')')
            .map_or(unit.text.len(), |end| from + end);
        blank(from, to);
        at = to;
    }
    let text = String::from_utf8_lossy(&text).into_owned();
    let mut found = Vec::new();
    for prefix in PREFIXES.iter().chain(TOP_FILES.iter()) {
        for (at, _) in text.match_indices(prefix) {
            let before = text[..at].chars().next_back();
            if before.is_some_and(|c| c.is_alphanumeric() || "/.-_~$".contains(c)) {
                continue;
            }
            let word: String = text[at..]
                .chars()
                .take_while(|c| !c.is_whitespace() && *c != '`')
                .collect();
            let word = trim_path(&word);
            if TOP_FILES.contains(prefix) && word != *prefix {
                continue;
            }
            found.push((at, word.to_owned()));
        }
    }
    found
}

/// The words of a code span or a code line.
fn words(text: &str) -> Vec<(usize, &str)> {
    let mut found = Vec::new();
    let mut start = None;
    for (at, c) in text.char_indices() {
        match (start, c.is_whitespace()) {
            (None, false) => start = Some(at),
            (Some(from), true) => {
                found.push((from, &text[from..at]));
                start = None;
            }
            _ => {}
        }
    }
    if let Some(from) = start {
        found.push((from, &text[from..]));
    }
    found
}

/// A span that is a name: `a::b::C`, `Name`, `name`, with arguments or generics after it.
fn name_of(span: &str) -> Option<&str> {
    let mut end = 0;
    let bytes = span.as_bytes();
    loop {
        let ident = leading_ident(&span[end..])?;
        end += ident.len();
        if span[end..].starts_with("::") && span[end + 2..].starts_with(is_ident_start) {
            end += 2;
        } else {
            break;
        }
    }
    let rest = &span[end..];
    let fits = rest.is_empty()
        || rest.starts_with('(')
        || rest.starts_with('<')
        || rest.starts_with("::<")
        || rest == "!"
        || rest.starts_with("!(");
    // `a.b` and `a b` are no names; a backticked word of plain English is not one either.
    (fits
        && bytes
            .first()
            .is_some_and(|b| b.is_ascii_alphabetic() || *b == b'_'))
    .then(|| &span[..end])
}

fn is_snake(name: &str) -> bool {
    name.contains('_')
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_')
        && name.starts_with(|c: char| c.is_ascii_lowercase())
}

fn is_camel(name: &str) -> bool {
    name.starts_with(|c: char| c.is_ascii_uppercase())
        && name.chars().any(|c| c.is_ascii_lowercase())
        && name.chars().all(|c| c.is_ascii_alphanumeric())
}

fn is_upper(name: &str) -> bool {
    name.len() > 1
        && name
            .chars()
            .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '_')
        && name.starts_with(|c: char| c.is_ascii_uppercase())
}

fn outside_name(name: &str) -> bool {
    OUTSIDE_NAMES.iter().any(|(outside, _)| *outside == name)
}

/// A test name written short: `claim_1_…` stands for every test it opens.
fn test_prefix(span: &str) -> Option<&str> {
    let short = span
        .strip_suffix('…')
        .or_else(|| span.strip_suffix("..."))?
        .trim_end_matches('_');
    is_snake(short).then_some(short)
}

// ---------------------------------------------------------------------------------------------
// The checks.

/// One finding: where, and what.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
struct Finding {
    page: String,
    line: usize,
    message: String,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: {}", self.page, self.line, self.message)
    }
}

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Check {
    Paths,
    Items,
    Tests,
    Flags,
    Variables,
}

struct Checker<'a> {
    index: &'a Index,
    page: String,
    found: Vec<(Check, Finding)>,
}

impl Checker<'_> {
    fn report(&mut self, check: Check, line: usize, message: String) {
        self.found.push((
            check,
            Finding {
                page: self.page.clone(),
                line,
                message,
            },
        ));
    }

    /// Says where a missing path's file went, if a file of its name is elsewhere.
    fn whereabouts(&self, path: &str) -> String {
        let path = path.trim_end_matches('/');
        // A folder's `mod.rs` may have become a file of the folder's name.
        let (name, module) = match path.strip_suffix("/mod.rs") {
            Some(folder) => {
                let folder = folder.rsplit('/').next().unwrap_or(folder);
                ("mod.rs".to_owned(), Some(format!("{folder}.rs")))
            }
            None => (path.rsplit('/').next().unwrap_or(path).to_owned(), None),
        };
        let top = path.split('/').next().unwrap_or("");
        let mut elsewhere: Vec<&String> = self
            .index
            .files
            .iter()
            .chain(self.index.folders.iter())
            .filter(|file| !file.starts_with("docs/snapshots") && file.as_str() != path)
            .filter(|file| {
                let last = file.rsplit('/').next();
                match &module {
                    Some(module) => last == Some(module.as_str()),
                    None => last == Some(name.as_str()),
                }
            })
            .collect();
        // Those under the same top folder first: a test moved stays a test.
        elsewhere.sort_by_key(|file| (file.split('/').next() != Some(top), (*file).clone()));
        elsewhere.truncate(3);
        if elsewhere.is_empty() {
            String::new()
        } else {
            let list: Vec<&str> = elsewhere.iter().map(|s| s.as_str()).collect();
            format!(" (there is {})", list.join(", "))
        }
    }

    fn check_path(&mut self, line: usize, path: &str) {
        if is_placeholder(path) || path.is_empty() {
            return;
        }
        if path.contains('*') {
            let (folder, pattern) = path.rsplit_once('/').unwrap_or(("", path));
            let (head, tail) = pattern.split_once('*').unwrap_or((pattern, ""));
            let tail = tail.trim_start_matches('*');
            let any = self.index.files.iter().any(|file| {
                file.rsplit_once('/').is_some_and(|(dir, name)| {
                    dir == folder && name.starts_with(head) && name.ends_with(tail)
                })
            });
            if !any {
                self.report(Check::Paths, line, format!("`{path}` matches no file"));
            }
            return;
        }
        if !self.index.exists(path) {
            let hint = self.whereabouts(path);
            self.report(Check::Paths, line, format!("`{path}` does not exist{hint}"));
        }
    }

    /// Resolves a path as a page writes it to the repository's: whole, relative to the
    /// sources, or a bare file name. None when it names nothing.
    fn resolve(&self, path: &str) -> Option<String> {
        let path = path.trim_end_matches('/');
        if self.index.exists(path) {
            return Some(path.to_owned());
        }
        if is_repo_path(path) {
            return None;
        }
        let found = self.index.resolve_relative(path);
        // A bare name or a short path names the one file of that name, or the first.
        found.into_iter().next()
    }

    /// Checks that `name` is defined in `path` (a test file: as a `fn`).
    fn check_item_in(&mut self, line: usize, name: &str, path: &str, wrote: &str) {
        let Some(file) = self.resolve(path) else {
            return; // The path check reports it.
        };
        let is_test_file = file.starts_with("tests/") && !file.starts_with("tests/fixtures");
        let segments: Vec<&str> = name.split("::").collect();
        let files = self.index.rust_files_of(&file);
        if files.is_empty() {
            return; // Not a Rust file or folder: a script, a page.
        }
        let defined_here = |segment: &str| {
            files.iter().any(|f| {
                let source = &self.index.sources[*f];
                if is_test_file {
                    source.fns.contains(segment)
                        || test_prefix(segment)
                            .is_some_and(|p| source.fns.iter().any(|t| t.starts_with(p)))
                } else {
                    source.defined.contains(segment) || source.used.contains(segment)
                }
            })
        };
        if segments.iter().any(|segment| defined_here(segment)) {
            return;
        }
        let last = segments.last().copied().unwrap_or(name);
        let prefixes: &[&str] = if is_test_file {
            &["tests/"]
        } else {
            &["src/", "tests/", "benches/"]
        };
        let elsewhere = self.index.defining(last, prefixes, is_test_file);
        let elsewhere = if elsewhere.is_empty() && is_test_file {
            self.index.defining(last, &["src/", "benches/"], true)
        } else {
            elsewhere
        };
        let what = if is_test_file {
            "a test in"
        } else {
            "defined in"
        };
        let hint = if elsewhere.is_empty() {
            "; it is defined nowhere".to_owned()
        } else {
            format!(" (it is in {})", elsewhere.join(", "))
        };
        self.report(
            Check::Items,
            line,
            format!("`{wrote}` is not {what} {file}{hint}"),
        );
    }

    /// Checks a name in backticks against the code.
    fn check_name(&mut self, line: usize, name: &str) {
        let index = self.index;
        let mut segments: Vec<&str> = name.split("::").collect();
        if segments.first() == Some(&"rubber_band_box") {
            segments.remove(0);
        }
        match segments.as_slice() {
            [] => {}
            [single] => {
                let single = *single;
                if outside_name(single) || index.crates.contains(single) {
                    return;
                }
                if is_snake(single) {
                    if !index.mentions(single) {
                        self.report(
                            Check::Items,
                            line,
                            format!("`{name}` is nowhere in the code"),
                        );
                    }
                } else if is_camel(single) && !index.is_project_type(single) {
                    self.report(
                        Check::Items,
                        line,
                        format!("`{name}` is defined nowhere in src/ or tests/ (nor on the list of outside names)"),
                    );
                }
            }
            [first, rest @ ..] => {
                if first.starts_with(|c: char| c.is_ascii_uppercase()) {
                    // Type::member: the type the project's (its member then defined somewhere)
                    // or an outside one.
                    if outside_name(first) {
                        return;
                    }
                    if !index.is_project_type(first) {
                        self.report(
                            Check::Items,
                            line,
                            format!("`{name}`: `{first}` is defined nowhere in src/ or tests/"),
                        );
                        return;
                    }
                    let member = rest[0];
                    if index
                        .defining(member, &["src/", "tests/", "benches/"], false)
                        .is_empty()
                    {
                        self.report(
                            Check::Items,
                            line,
                            format!("`{name}`: `{member}` is defined nowhere in src/ or tests/"),
                        );
                    }
                    return;
                }
                let Some(mut file) = index.module(first) else {
                    if !outside_name(first) && !index.crates.contains(*first) {
                        self.report(
                            Check::Items,
                            line,
                            format!("`{name}`: there is no module `{first}`"),
                        );
                    }
                    return;
                };
                let mut at = 0;
                while at < rest.len() {
                    match index.submodule(&file, rest[at]) {
                        Some(sub) => {
                            file = sub;
                            at += 1;
                        }
                        None => break,
                    }
                }
                let Some(item) = rest.get(at) else {
                    return; // A module path, resolved.
                };
                let source = &index.sources[&file];
                if source.defined.contains(*item) || source.used.contains(*item) {
                    if let Some(member) = rest.get(at + 1)
                        && index
                            .defining(member, &["src/", "tests/"], false)
                            .is_empty()
                    {
                        self.report(
                            Check::Items,
                            line,
                            format!("`{name}`: `{member}` is defined nowhere in src/ or tests/"),
                        );
                    }
                    return;
                }
                let elsewhere = index.defining(item, &["src/", "tests/", "benches/"], false);
                let hint = if elsewhere.is_empty() {
                    "; it is defined nowhere".to_owned()
                } else {
                    format!(" (it is in {})", elsewhere.join(", "))
                };
                self.report(
                    Check::Items,
                    line,
                    format!("`{name}` is not defined in {file}{hint}"),
                );
            }
        }
    }

    /// Checks an environment variable: read by the project, or an outside one.
    fn check_variable(&mut self, line: usize, name: &str) {
        if OUTSIDE_VARIABLES
            .iter()
            .any(|(outside, _)| *outside == name)
        {
            return;
        }
        let read_by_code = self
            .index
            .sources
            .values()
            .any(|source| source.strings.contains(name));
        let read_by_scripts = self
            .index
            .scripts
            .iter()
            .filter(|(path, _)| path.starts_with(".ci/"))
            .any(|(_, text)| identifiers(text).contains(&name));
        if !read_by_code && !read_by_scripts {
            self.report(
                Check::Variables,
                line,
                format!("`{name}` is read nowhere in src/, tests/, benches/, examples/ or .ci/"),
            );
        }
    }

    /// Checks a command: its flags, and what its `--test`, `--bench`, `--features` and scripts
    /// name.
    fn check_command(&mut self, line: usize, command: &str) {
        let mut tokens: Vec<&str> = command.split_whitespace().collect();
        // What runs the command: timing, and variables set for it.
        loop {
            match tokens.first() {
                Some(&"time") | Some(&"/usr/bin/time") | Some(&"-v") => {
                    tokens.remove(0);
                }
                Some(token)
                    if token.contains('=') && token.split('=').next().is_some_and(is_upper) =>
                {
                    let variable = token.split('=').next().unwrap_or("");
                    self.check_variable(line, variable);
                    tokens.remove(0);
                }
                _ => break,
            }
        }
        let Some(&program) = tokens.first() else {
            return;
        };
        let flags = |tokens: &[&str]| -> Vec<String> {
            tokens
                .iter()
                .filter(|t| t.starts_with("--") && t.len() > 2)
                .map(|t| {
                    t.split('=')
                        .next()
                        .unwrap_or(t)
                        .trim_end_matches([',', ')', ';'])
                        .to_owned()
                })
                .collect()
        };
        match program {
            "cargo" => {
                let sub = tokens.get(1).copied().unwrap_or("");
                let split = tokens
                    .iter()
                    .position(|t| *t == "--")
                    .unwrap_or(tokens.len());
                let (own, after) = (&tokens[..split], &tokens[(split + 1).min(tokens.len())..]);
                for flag in flags(own) {
                    let known = CARGO_FLAGS.contains(&flag.as_str())
                        || (sub != "run"
                            && sub != "test"
                            && sub != "bench"
                            && TOOL_FLAGS.contains(&flag.as_str()));
                    if !known {
                        self.report(
                            Check::Flags,
                            line,
                            format!("`{flag}` is not a flag of `cargo {sub}`"),
                        );
                    }
                }
                let value_of = |flag: &str| {
                    own.iter()
                        .position(|t| *t == flag)
                        .and_then(|at| own.get(at + 1))
                        .copied()
                };
                if let Some(features) = value_of("--features") {
                    for feature in features.split(',') {
                        if !self.index.features.contains(feature) {
                            self.report(
                                Check::Flags,
                                line,
                                format!(
                                    "`--features {feature}`: Cargo.toml has no feature `{feature}`"
                                ),
                            );
                        }
                    }
                }
                if let Some(bench) = value_of("--bench")
                    && !self.index.exists(&format!("benches/{bench}.rs"))
                {
                    self.report(
                        Check::Flags,
                        line,
                        format!("`--bench {bench}`: there is no benches/{bench}.rs"),
                    );
                }
                let target = value_of("--test");
                if let Some(target) = target {
                    self.check_test_target(line, target, own, after);
                }
                match sub {
                    "run" => {
                        let subcommand = after
                            .first()
                            .filter(|t| ["play", "simulate", "report"].contains(t))
                            .copied()
                            .unwrap_or("play");
                        for flag in flags(after) {
                            self.check_cli_flag(line, subcommand, &flag);
                        }
                    }
                    "test" => {
                        for flag in flags(after) {
                            if !LIBTEST_FLAGS.contains(&flag.as_str()) {
                                self.report(
                                    Check::Flags,
                                    line,
                                    format!("`{flag}` is not a flag of the test harness"),
                                );
                            }
                        }
                    }
                    "bench" => {
                        for flag in flags(after) {
                            if !CRITERION_FLAGS.contains(&flag.as_str()) {
                                self.report(
                                    Check::Flags,
                                    line,
                                    format!("`{flag}` is not a flag of criterion's harness"),
                                );
                            }
                        }
                    }
                    _ => {}
                }
            }
            "bash" | "sh" => {
                if let Some(script) = tokens.get(1) {
                    self.check_script(line, script, &flags(&tokens[2..]));
                }
            }
            script if script.starts_with(".ci/") => {
                self.check_script(line, script, &flags(&tokens[1..]));
            }
            "play" | "simulate" | "report" | "rubber_band_box" => {
                let subcommand = if program == "rubber_band_box" {
                    tokens.get(1).copied().unwrap_or("play")
                } else {
                    program
                };
                for flag in flags(&tokens[1..]) {
                    self.check_cli_flag(line, subcommand, &flag);
                }
            }
            _ => {}
        }
    }

    fn check_script(&mut self, line: usize, script: &str, flags: &[String]) {
        let script = trim_path(script);
        if !is_repo_path(script) {
            return;
        }
        self.check_path(line, script);
        if let Some(text) = self.index.scripts.get(script) {
            for flag in flags {
                if !text.contains(flag.as_str()) {
                    self.report(
                        Check::Flags,
                        line,
                        format!("`{flag}` is not a flag of {script}"),
                    );
                }
            }
        }
    }

    fn check_cli_flag(&mut self, line: usize, subcommand: &str, flag: &str) {
        let known = |sub: &str| {
            self.index
                .cli_flags
                .get(sub)
                .is_some_and(|flags| flags.contains(flag))
        };
        if known(subcommand) || (flag == "--help" || flag == "--version") {
            return;
        }
        let elsewhere = ["play", "simulate", "report"]
            .into_iter()
            .find(|sub| known(sub));
        let hint = elsewhere.map_or(String::new(), |sub| format!(" (it is `{sub}`'s)"));
        self.report(
            Check::Flags,
            line,
            format!("`{flag}` is not a flag of `{subcommand}`{hint}"),
        );
    }

    /// `cargo test --test TARGET [FILTER]`: the target exists, and the filter (`module::test`
    /// in the suite) names a module of it and matches a test.
    fn check_test_target(&mut self, line: usize, target: &str, own: &[&str], after: &[&str]) {
        let file = [
            format!("tests/{target}.rs"),
            format!("tests/{target}/main.rs"),
        ]
        .into_iter()
        .find(|path| self.index.exists(path));
        let Some(file) = file else {
            let moved = format!("tests/suite/{target}.rs");
            let hint = if self.index.exists(&moved) {
                format!(" (it is the module {moved}: `--test suite {target}::`)")
            } else {
                String::new()
            };
            self.report(
                Check::Flags,
                line,
                format!("`--test {target}`: there is no test target {target}{hint}"),
            );
            return;
        };
        // The filter: the first word after the target that is no flag (before `--`), or after
        // `--` the libtest positional.
        let mut filter = None;
        let mut skip = false;
        for token in own.iter().chain(after.iter()) {
            if skip {
                skip = false;
                continue;
            }
            if token.starts_with("--") {
                skip = [
                    "--test",
                    "--features",
                    "--profile",
                    "--target",
                    "--test-threads",
                    "--bench",
                    "--bin",
                ]
                .contains(token);
                continue;
            }
            if ["cargo", "test", target].contains(token) {
                continue;
            }
            filter = Some(*token);
            break;
        }
        let Some(filter) = filter else {
            return;
        };
        let folder = file.trim_end_matches("main.rs");
        let (files, test): (Vec<String>, &str) = match filter.split_once("::") {
            Some((module, test)) if file.ends_with("main.rs") => {
                let path = format!("{folder}{module}.rs");
                if !self.index.exists(&path) {
                    self.report(
                        Check::Flags,
                        line,
                        format!("`{filter}`: there is no module {path}"),
                    );
                    return;
                }
                (vec![path], test)
            }
            _ => (vec![file.clone()], filter),
        };
        if test.is_empty() {
            return;
        }
        let matches = files.iter().any(|path| {
            self.index
                .sources
                .get(path)
                .is_some_and(|source| source.fns.iter().any(|f| f.contains(test)))
        });
        if !matches {
            self.report(
                Check::Flags,
                line,
                format!("`{filter}` matches no test in {}", files.join(", ")),
            );
        }
    }

    /// Checks one unit.
    fn check_unit(&mut self, unit: &Unit) {
        if unit.kind == Kind::Code {
            let code = unit.text.split(" # ").next().unwrap_or("");
            let code = code.split("  #").next().unwrap_or(code);
            for command in code.split(['|', ';']).flat_map(|c| c.split("&&")) {
                self.check_command(unit.line_at(0), command.trim());
            }
            for (_, word) in words(code) {
                let word = trim_path(word);
                if is_repo_path(word) {
                    self.check_path(unit.line_at(0), split_item(word).0);
                }
            }
            return;
        }
        // Paths in prose.
        for (at, path) in prose_paths(unit) {
            let (path, _) = split_item(&path);
            self.check_path(unit.line_at(at), path);
        }
        // Test files this unit cites, for its test names.
        let mut test_files: BTreeSet<String> = BTreeSet::new();
        let mut attributed: HashSet<usize> = HashSet::new();
        let mut paths_at: Vec<Option<String>> = Vec::new();
        for span in &unit.spans {
            let line = unit.line_at(span.start);
            let mut path_here = None;
            for (_, word) in words(&span.text) {
                let word = trim_path(word);
                let (path, item) = split_item(word);
                if is_repo_path(path) {
                    self.check_path(line, path);
                    if path.starts_with("tests/") && !path.starts_with("tests/fixtures") {
                        test_files.insert(path.trim_end_matches('/').to_owned());
                    }
                    if let Some(item) = item {
                        self.check_item_in(line, item, path, word);
                    }
                    path_here = Some(path.to_owned());
                } else if !is_placeholder(path)
                    && path.contains('/')
                    && path
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || "_/.".contains(c))
                    && (path.ends_with(".rs") || path.ends_with('/') || !path.contains('.'))
                {
                    // A path relative to the sources: its first folder is one of theirs.
                    let first = path.split('/').next().unwrap_or("");
                    let theirs = self.index.folders.iter().any(|f| {
                        (f.starts_with("src/") || f.starts_with("tests/"))
                            && f.rsplit('/').next() == Some(first)
                    });
                    if theirs {
                        if self.index.resolve_relative(path).is_empty() {
                            self.report(
                                Check::Paths,
                                line,
                                format!(
                                    "`{path}` names no file or folder under src/ or tests/{}",
                                    self.whereabouts(path)
                                ),
                            );
                        } else {
                            path_here = Some(path.to_owned());
                        }
                    }
                } else if !is_placeholder(path)
                    && !path.contains('/')
                    && [".rs", ".sh", ".mjs", ".py"]
                        .iter()
                        .any(|ext| path.ends_with(ext))
                    && path
                        .chars()
                        .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c))
                {
                    if self.index.resolve_relative(path).is_empty() {
                        self.report(
                            Check::Paths,
                            line,
                            format!("`{path}` is no file of src/, tests/, benches/ or .ci/"),
                        );
                    } else {
                        path_here = Some(path.to_owned());
                    }
                }
            }
            // A span with a command in it.
            let text = span.text.as_str();
            if text.starts_with("cargo ")
                || text.starts_with("bash ")
                || text.starts_with("time ")
                || text.starts_with("/usr/bin/time")
                || text.starts_with("play ")
                || text.starts_with("simulate ")
                || text.starts_with("report ")
                || text
                    .split_whitespace()
                    .next()
                    .is_some_and(|w| w.contains('=') && w.split('=').next().is_some_and(is_upper))
            {
                self.check_command(line, text);
            } else if text.starts_with("--") {
                for flag in text.split_whitespace().filter(|w| w.starts_with("--")) {
                    self.check_any_flag(line, flag);
                }
            }
            paths_at.push(path_here);
        }
        // Names, and the file a sentence puts them in.
        for (at, span) in unit.spans.iter().enumerate() {
            let line = unit.line_at(span.start);
            let Some(name) =
                name_of(&span.text).or_else(|| test_prefix(&span.text).map(|_| span.text.as_str()))
            else {
                continue;
            };
            if paths_at[at].is_some() {
                continue;
            }
            // "`name` in `path`", "`name`, in `path`", "`name` (`path`": the name is there.
            let between_next = unit
                .spans
                .get(at + 1)
                .map(|next| unit.text[span.end..next.start].replace('\n', " "));
            let between_next = between_next.as_deref();
            let before_prev = at
                .checked_sub(1)
                .map(|p| unit.text[unit.spans[p].end..span.start].replace('\n', " "));
            let before_prev = before_prev.as_deref();
            // Only a name that reads as code is put in a file: not a key, not a plain word.
            let code_like =
                name.contains("::") || is_snake(name) || is_camel(name) || is_upper(name);
            let mut home = None;
            if let Some(between) = between_next
                && code_like
                && ([" in ", ", in ", " in the file "].contains(&between)
                    || (between == " (" && !is_snake(name)))
                && let Some(path) = &paths_at[at + 1]
            {
                home = Some(path.clone());
            }
            if let Some(between) = before_prev
                && code_like
                && between == "'s "
                && let Some(path) = &paths_at[at - 1]
            {
                home = Some(path.clone());
            }
            if is_upper(name) && !name.contains("::") {
                let defined = !self
                    .index
                    .defining(name, &["src/", "tests/", "benches/"], false)
                    .is_empty();
                if !defined {
                    self.check_variable(line, name);
                    continue;
                }
            }
            if let Some(home) = home {
                attributed.insert(at);
                self.check_item_in(line, name, &home, name);
            } else if test_prefix(&span.text).is_none()
                && (test_files.is_empty() || !is_snake(name))
            {
                // (A snake_case name beside a test file is a test's: checked below.)
                self.check_name(line, name);
            }
        }
        // Test names: a snake_case name beside a test file's path is a test of it, unless it
        // is the sources' item.
        if test_files.is_empty() {
            return;
        }
        for (at, span) in unit.spans.iter().enumerate() {
            if attributed.contains(&at) || paths_at[at].is_some() {
                continue;
            }
            let name = span.text.as_str();
            let prefix = test_prefix(name);
            if !is_snake(name) && prefix.is_none() {
                continue;
            }
            let wanted = prefix.unwrap_or(name);
            let is_test_of = |path: &str| {
                self.index.rust_files_of(path).iter().any(|file| {
                    let fns = &self.index.sources[*file].fns;
                    fns.contains(wanted)
                        || (prefix.is_some() && fns.iter().any(|f| f.starts_with(wanted)))
                })
            };
            if test_files.iter().any(|path| is_test_of(path)) {
                continue;
            }
            if prefix.is_none()
                && !self
                    .index
                    .defining(name, &["src/", "benches/"], false)
                    .is_empty()
            {
                continue; // The sources' own item: the names check holds it.
            }
            let named_by_the_code =
                self.index.sources.iter().any(|(path, source)| {
                    !path.starts_with("tests/") && source.words.contains(name)
                }) || self
                    .index
                    .scripts
                    .values()
                    .any(|text| identifiers(text).contains(&name));
            if prefix.is_none() && named_by_the_code {
                continue; // A field, a column, a bench's name: not a test.
            }
            let elsewhere = self.index.defining(wanted, &["tests/", "src/"], true);
            let hint = if elsewhere.is_empty() {
                "no test has that name".to_owned()
            } else {
                format!("it is in {}", elsewhere.join(", "))
            };
            let files: Vec<&str> = test_files.iter().map(String::as_str).collect();
            self.report(
                Check::Tests,
                unit.line_at(span.start),
                format!("`{name}` is not a test in {} ({hint})", files.join(", ")),
            );
        }
    }

    /// A flag alone in backticks: the command line's, cargo's, the harnesses', a script's.
    fn check_any_flag(&mut self, line: usize, flag: &str) {
        let flag = flag.split('=').next().unwrap_or(flag);
        let known = self
            .index
            .cli_flags
            .get("")
            .is_some_and(|flags| flags.contains(flag))
            || CARGO_FLAGS.contains(&flag)
            || LIBTEST_FLAGS.contains(&flag)
            || CRITERION_FLAGS.contains(&flag)
            || TOOL_FLAGS.contains(&flag)
            || self
                .index
                .scripts
                .iter()
                .any(|(path, text)| path.starts_with(".ci/") && text.contains(flag));
        if !known {
            self.report(
                Check::Flags,
                line,
                format!("`{flag}` is no flag of the command line, cargo, the harnesses or .ci/"),
            );
        }
    }
}

/// Every finding on `text`, read as the page `page`.
fn check_page(index: &Index, page: &str, text: &str) -> Vec<(Check, Finding)> {
    let mut checker = Checker {
        index,
        page: page.to_owned(),
        found: Vec::new(),
    };
    for unit in units_of(text) {
        checker.check_unit(&unit);
    }
    checker.found.sort_by(|a, b| a.1.cmp(&b.1));
    checker.found.dedup_by(|a, b| a.1 == b.1);
    checker.found
}

/// Every finding on every page.
fn findings() -> &'static Vec<(Check, Finding)> {
    static FOUND: OnceLock<Vec<(Check, Finding)>> = OnceLock::new();
    FOUND.get_or_init(|| {
        let index = index();
        let mut found = Vec::new();
        for path in pages() {
            let text = fs::read_to_string(&path).expect("a page");
            let page = path
                .strip_prefix(&index.root)
                .unwrap_or(&path)
                .to_string_lossy()
                .replace('\\', "/");
            found.extend(check_page(index, &page, &text));
        }
        found
    })
}

fn assert_none(check: Check, what: &str) {
    let wrong: Vec<String> = findings()
        .iter()
        .filter(|(kind, _)| *kind == check)
        .map(|(_, finding)| finding.to_string())
        .collect();
    assert!(
        wrong.is_empty(),
        "{} {what}:\n{}",
        wrong.len(),
        wrong.join("\n")
    );
}

#[test]
fn every_path_the_pages_name_exists() {
    assert_none(Check::Paths, "paths the pages name that do not exist");
}

#[test]
fn every_item_the_pages_name_is_defined_where_they_say() {
    assert_none(
        Check::Items,
        "names the pages use that the code does not define where they say",
    );
}

#[test]
fn every_test_the_pages_cite_is_in_its_file() {
    assert_none(
        Check::Tests,
        "tests the pages cite that are not in the file they name",
    );
}

#[test]
fn every_flag_and_test_target_the_pages_quote_exists() {
    assert_none(
        Check::Flags,
        "flags or targets the pages quote that the commands do not have",
    );
}

#[test]
fn every_environment_variable_the_pages_name_is_read() {
    assert_none(
        Check::Variables,
        "environment variables the pages name that nothing reads",
    );
}

// ---------------------------------------------------------------------------------------------
// The rules themselves, on made-up pages: each wrong name is reported, each right one not.

fn messages(page: &str) -> Vec<String> {
    check_page(index(), "made-up.md", page)
        .into_iter()
        .map(|(_, finding)| finding.to_string())
        .collect()
}

#[test]
fn an_item_put_in_the_wrong_file_is_reported_with_where_it_is() {
    let found = messages(
        "Intro.\n\nThe step (`nothing_here` in `src/physics/mod.rs`) and `mechanical_energies` in\n\
         `src/game/camera.rs`; `SceneParams` in `src/physics/scene.rs`.\n",
    );
    assert!(
        found
            .iter()
            .any(|m| m
                .starts_with("made-up.md:3: `nothing_here` is not defined in src/physics/mod.rs")),
        "{found:#?}"
    );
    assert!(
        found.iter().any(|m| m.starts_with("made-up.md:3: `mechanical_energies` is not defined in src/game/camera.rs (it is in src/game/simulation.rs)")),
        "{found:#?}"
    );
    assert_eq!(
        found.len(),
        2,
        "`SceneParams` is where it is said to be: {found:#?}"
    );
}

#[test]
fn a_missing_path_a_module_path_and_a_test_are_reported() {
    let found = messages(
        "See `src/physics/nowhere.rs`, src/game/also_nowhere.rs and `physics::scene`.\n\n\
         | `tests/suite/names.rs` | `an_item_put_in_the_wrong_file_is_reported_with_where_it_is`, `no_such_test_at_all` |\n\n\
         `physics::scene::NoSuchItem` and `game::shared::Mode`.\n",
    );
    let wanted = [
        "made-up.md:1: `src/physics/nowhere.rs` does not exist",
        "made-up.md:1: `src/game/also_nowhere.rs` does not exist",
        "made-up.md:3: `no_such_test_at_all` is not a test in tests/suite/names.rs (no test has that name)",
        "made-up.md:5: `physics::scene::NoSuchItem` is not defined in src/physics/scene.rs; it is defined nowhere",
    ];
    for message in wanted {
        assert!(found.iter().any(|m| m == message), "{message}\n{found:#?}");
    }
    assert_eq!(found.len(), wanted.len(), "{found:#?}");
}

#[test]
fn flags_targets_and_variables_are_held_to_the_code() {
    let found = messages(
        "```sh\nRBB_NO_SUCH=1 cargo test --test no_such_target\ncargo run -- simulate --no-such-flag\n\
         cargo run -- simulate --scene stiff --hash\ncargo test --test suite no_such_module::x\n```\n\n\
         `RBB_WRITE_FIGURES` and `CARGO_TARGET_DIR`; `--nowhere`.\n",
    );
    let wanted = [
        "made-up.md:2: `RBB_NO_SUCH` is read nowhere in src/, tests/, benches/, examples/ or .ci/",
        "made-up.md:2: `--test no_such_target`: there is no test target no_such_target",
        "made-up.md:3: `--no-such-flag` is not a flag of `simulate`",
        "made-up.md:5: `no_such_module::x`: there is no module tests/suite/no_such_module.rs",
        "made-up.md:8: `--nowhere` is no flag of the command line, cargo, the harnesses or .ci/",
    ];
    for message in wanted {
        assert!(found.iter().any(|m| m == message), "{message}\n{found:#?}");
    }
    assert_eq!(found.len(), wanted.len(), "{found:#?}");
}

#[test]
fn sentences_and_spans_are_read_as_markdown_writes_them() {
    let spans = code_spans("a `b c` and ``d`e`` and `f\ng`");
    let texts: Vec<&str> = spans.iter().map(|s| s.text.as_str()).collect();
    assert_eq!(texts, ["b c", "d`e", "f g"]);
    let units = units_of("One `a`. Two, e.g. three,\nfour `b`. Five.\n\n| `x` | y |\n");
    let texts: Vec<&str> = units.iter().map(|u| u.text.trim()).collect();
    assert_eq!(
        texts,
        [
            "One `a`.",
            "Two, e.g. three,\nfour `b`.",
            "Five.",
            "| `x` | y |"
        ]
    );
    assert_eq!(units[1].line_at(units[1].text.find("four").unwrap()), 2);
    assert_eq!(units[2].line_at(0), 2);
    assert_eq!(
        name_of("App::keep_across_learn::<R>()"),
        Some("App::keep_across_learn")
    );
    assert_eq!(name_of("in_state(Mode::Learn)"), Some("in_state"));
    assert_eq!(name_of("a.b"), None);
}
