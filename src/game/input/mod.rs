//! Input: the pointer (mouse, touch) holds the band; the keys and the on-screen panel send
//! the same actions ([`controls::Action`]).

pub mod controls;
pub mod panel;
pub mod pointer;
