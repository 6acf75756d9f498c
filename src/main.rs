//! The `durer` command line: flags to options, library calls, diagnostics, exit codes.

mod cli;

fn main() {
    std::process::exit(cli::run());
}
