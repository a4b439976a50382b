//! What the tests of the `dvf` binary share (tests/cli.rs, tests/simulate.rs,
//! tests/sweep_cli.rs, tests/compare.rs): running it, reading what it wrote, and temporary files.
// Each test file uses a part of this module.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The binary under test.
pub const DVF: &str = env!("CARGO_BIN_EXE_dvf");

/// Runs `dvf args` and returns what it did. A panic would also print a backtrace hint, which
/// the error tests look for.
pub fn dvf(args: &[&str]) -> Output {
    Command::new(DVF)
        .args(args)
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("the dvf binary runs")
}

/// `dvf args`, which must succeed with nothing on stderr: its stdout.
pub fn ok(args: &[&str]) -> String {
    let o = dvf(args);
    assert!(
        o.status.success() && o.stderr.is_empty(),
        "dvf {args:?}: {}",
        stderr(&o)
    );
    stdout(&o)
}

/// What a run wrote on standard output.
pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).expect("stdout is UTF-8")
}

/// What a run wrote on standard error.
pub fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).expect("stderr is UTF-8")
}

/// Runs `dvf args` on a pseudo-terminal (util-linux's `script`), asserts that it succeeds, and
/// returns what the terminal showed: standard output and standard error together.
pub fn on_a_terminal(args: &[&str]) -> String {
    let command = format!("{DVF} {}", args.join(" "));
    let o = Command::new("script")
        .args(["-qec", &command, "/dev/null"])
        .env("TERM", "xterm")
        .output()
        .expect("script (util-linux) runs dvf on a pseudo-terminal");
    assert_eq!(o.status.code(), Some(0), "dvf {args:?} on a terminal");
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A file in the system temp directory with a name unique to this process and call; removed
/// when dropped.
pub struct TempFile(pub PathBuf);

impl TempFile {
    /// A path `…-stem.ext`, not created.
    pub fn new(stem: &str, ext: &str) -> Self {
        static COUNTER: AtomicUsize = AtomicUsize::new(0);
        let n = COUNTER.fetch_add(1, Ordering::Relaxed);
        let name = format!("dvf-test-{}-{n}-{stem}.{ext}", std::process::id());
        Self(std::env::temp_dir().join(name))
    }

    /// A file `…-stem.json` holding `text`.
    pub fn with_text(stem: &str, text: &str) -> Self {
        let f = Self::new(stem, "json");
        std::fs::write(&f.0, text).expect("write the scenario file");
        f
    }

    /// Its path.
    pub fn path(&self) -> &Path {
        &self.0
    }

    /// Its path as a command-line argument.
    pub fn arg(&self) -> &str {
        self.0.to_str().expect("temp path is UTF-8")
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}
