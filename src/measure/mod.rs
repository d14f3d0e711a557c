//! The measuring tools, native only: `simulate`'s runner (a trajectory as CSV), the report of
//! speed against error, the side-by-side with the peers (feature `peers`), the references both
//! measure against, and timing.

#[cfg(feature = "peers")]
pub mod peers;
pub mod references;
pub mod report;
pub mod simulate;
pub mod timing;
