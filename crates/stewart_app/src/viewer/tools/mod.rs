//! The background computations the panels ask for: one [`job`] runner (newest request
//! wins, the work in flight cancelled), the [`workspace`] surface and slice, the
//! [`design`] search, [`reach`] at the pose shown, the Dynamics panel's [`mode_view`], and
//! the [`assembly`] modes of the legs shown.

pub(crate) mod assembly;
pub(crate) mod design;
pub(crate) mod job;
pub(crate) mod mode_view;
pub(crate) mod reach;
pub(crate) mod workspace;
