//! The transcendental functions the core calls, from one portable implementation (the `libm`
//! crate, pure Rust), so that a step computes the same bits on every platform. std's own are
//! the platform's: glibc's natively, a port of musl's on wasm32, and the two disagree in the
//! last bit on some arguments (docs/replays.md), which a stiff band grows into a different
//! trajectory. The avian and rapier crates do the same with their `enhanced-determinism`.
//! `sqrt` needs no such care: IEEE 754 rounds it exactly everywhere.

/// Returns (sin x, cos x).
pub fn sin_cos(x: f64) -> (f64, f64) {
    libm::sincos(x)
}

pub fn exp(x: f64) -> f64 {
    libm::exp(x)
}

/// Returns the natural logarithm of x.
pub fn ln(x: f64) -> f64 {
    libm::log(x)
}

/// Raises x to the power y.
pub fn powf(x: f64, y: f64) -> f64 {
    libm::pow(x, y)
}
