//! The `bidir` command line: wires the library's layers together; `anyhow` lives only here.

#![deny(unsafe_code)]

mod cli;

fn main() -> std::process::ExitCode {
    cli::signals::default_sigpipe();
    match cli::run() {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {}", message(&e));
            std::process::ExitCode::FAILURE
        }
    }
}

/// The error and its causes joined by ": ", each cause only where its text is not already
/// said (an I/O error's reason is often in its context's message too), escaped and truncated
/// (messages quote file contents).
fn message(e: &anyhow::Error) -> String {
    let mut msg = String::new();
    for cause in e.chain() {
        let s = cause.to_string();
        if msg.is_empty() {
            msg = s;
        } else if !msg.contains(&s) {
            msg.push_str(": ");
            msg.push_str(&s);
        }
    }
    bidir::text::sanitize(&msg)
}
