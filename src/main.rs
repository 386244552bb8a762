//! The `gearloss` command: argument parsing and exit codes live in `cli.rs`.

mod cli;

fn main() -> std::process::ExitCode {
    cli::main()
}
