//! The hostile-input suite: the real binary fed random, mutated and absurd input, failing
//! sinks and signals, asserting the promises docs/guide/bad-input.md makes ("What happens on bad
//! input"): no panic, no hang, exit 2 with one `error:` line naming the file, line, key or
//! value, no output file after a refusal, nothing destroyed at an output path.
//!
//! `HOSTILE_CASES=N` sets the random cases per property (`scripts/hostile.sh` runs many).

mod edges;
mod files;
mod paths;
mod run;
mod sinks;
mod values;
