//! The `stewart` program for the end-to-end suites: [`stewart_app::main`], as the
//! shipped binary runs it.

fn main() -> std::process::ExitCode {
    stewart_app::main()
}
