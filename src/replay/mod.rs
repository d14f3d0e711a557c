//! Replays: what reached the physics at each fixed step of a game (the band, the settings the
//! controls changed, the resets), as data. The game records one;
//! `simulate --replay` and the tests step it again with the core ([`run::ReplayRun`]) and get
//! the game's states to the bit.
//!
//! The file is JSON Lines (docs/replays.md): a header line, then one record per line, then
//! an end record that counts the steps and hashes the states the game had. Reading checks
//! every line and names the first bad one; nothing in a file can make it panic.
//!
//! [`mod@format`] holds the format's types (the header, the records, the hash, a whole replay and
//! its writing), [`read`] reads and checks a file, and [`play`] is the one reader of its
//! records, which the core's run, the game's playback and the writer share.

pub mod format;
pub mod link;
pub mod play;
pub mod read;
pub mod run;
#[cfg(not(target_arch = "wasm32"))]
pub mod save;
pub mod script;
pub mod write;

pub use format::{
    AUTO_ORDERS, AutoRecord, BandRecord, CHECK_EVERY, FORMAT, Header, Integrity, MAX_LINE_BYTES,
    MAX_STEPS, Record, Replay, Settings, TrajectoryHash, VERSION, made_by,
};
pub use link::{Link, LinkProblem};
pub use read::ReplayError;
