//! Files and user input: the one gate every file read goes through (`file`), scenario files and presets, the settings every number is declared
//! in, numeric CSV tables, input text, and the accepted range of every kind of number;
//! `load` reads a scenario (file, preset or text) and applies the settings' ranges, above
//! both so that the file format and the settings do not depend on each other.

pub mod file;
mod load;
pub mod scenario;
pub mod settings;
pub mod table;
