//! The Stewart-platform studio's program, as a library the `stewart` binary (and the
//! export benchmark) use: command-line definitions, one module per command, exports.

pub mod cli;
pub mod commands;
pub mod csv_io;
pub mod export;

pub mod i18n;
pub mod interrupt;
pub mod link_plan;
pub mod live_cue;
pub mod long_work;
pub mod output;
pub mod readout;
pub mod shot_scale;
pub mod source;
pub mod vehicle_table;
pub mod viewer;
