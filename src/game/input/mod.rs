//! Input: the keys and the on-screen panel, which send the same actions
//! ([`controls::Action`]). The pointer, which holds the band, sits lower ([`super::pointer`]):
//! the replays record it, and the controls open replays.

pub mod controls;
pub mod focus;
pub mod panel;
