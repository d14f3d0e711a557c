//! What one step of any integrator reports: a leaf, so that `auto` and the table of methods
//! both use it without importing each other.

/// What one fixed step did.
///
/// How many substeps and how much work, whether it fell back to `implicit`, and the energy
/// damping took out during it (for the energy ledger).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StepInfo {
    pub substeps: u32,
    /// Force-law evaluations the step made, the one at its start included.
    ///
    /// For `auto` there is one per order of each Taylor step. They are the work done, counted
    /// rather than timed.
    pub evaluations: u32,
    pub fell_back: bool,
    pub dissipated: f64,
}

impl StepInfo {
    pub const SINGLE: Self = Self {
        substeps: 1,
        evaluations: 1,
        fell_back: false,
        dissipated: 0.0,
    };
}
