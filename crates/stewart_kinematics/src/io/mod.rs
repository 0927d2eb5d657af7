//! Files and user input: scenario files and presets, the settings every number is declared
//! in, numeric CSV tables, input text, and the accepted range of every kind of number.

pub mod bounds;
pub mod scenario;
pub mod settings;
pub mod table;
pub mod text;
