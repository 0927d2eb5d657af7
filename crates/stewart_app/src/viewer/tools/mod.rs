//! The background computations the panels ask for: one [`job`] runner (newest request
//! wins, the work in flight cancelled), the [`workspace`] surface and slice, the
//! [`design`] search, [`reach`] at the pose shown, the Dynamics panel's [`mode_view`], and
//! the [`assembly`] modes of the legs shown.

pub mod assembly;
pub mod design;
pub mod job;
pub mod mode_view;
pub mod reach;
pub mod workspace;
