//! The suites that cross crates live in this package's `tests` targets (`cli`, `hostile`,
//! `render`); the library itself is empty.
