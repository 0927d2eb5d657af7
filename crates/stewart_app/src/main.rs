//! `stewart`: the Stewart-platform studio's one binary; the program is the library's
//! [`stewart_app::main`].
//!
//! Exit status: 0 success (and, for `check`, nothing found), 1 a check found a
//! problem, 2 unusable input or output (one sentence on standard error says which).

fn main() -> std::process::ExitCode {
    stewart_app::main()
}
