//! The README's and the book's code blocks, run as written against the `dvf` binary
//! (docs/book/src/tests.md, "The documentation's own blocks"):
//!
//! - every fenced block names its kind (an unnamed block would be a Rust doctest to rustdoc);
//! - `sh` blocks run under `sh -e` in an empty folder under `target/tmp/doc-blocks/`, with the
//!   binary first on the `PATH`: every command succeeds;
//! - `json` blocks are scenarios: `dvf simulate` runs each.
//!
//! Rust blocks are doctests (src/doc_examples.rs); `html` and `js` blocks are loaded in Chromium
//! by tests/e2e/book.mjs; `python` blocks are run by python/tests/test_docs.py; `text` and
//! `toml` blocks are illustrations.
//!
//! Native only: it runs the binary as a child process.
#![cfg(not(target_arch = "wasm32"))]

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The info strings a block may carry.
const KINDS: &[&str] = &[
    "sh",
    "json",
    "rust",
    "rust,no_run",
    "html",
    "js",
    "text",
    "toml",
    "python",
];

/// A fenced code block of a Markdown file.
struct Block {
    /// `file:line` of its opening fence.
    place: String,
    /// A folder name for it: the file's stem and the line.
    slug: String,
    info: String,
    text: String,
}

/// The README, the notes and every chapter of the book.
fn documents() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = vec![
        root.join("README.md"),
        root.join("docs/notes-on-the-paper.md"),
    ];
    let mut chapters: Vec<PathBuf> = fs::read_dir(root.join("docs/book/src"))
        .expect("docs/book/src")
        .map(|e| e.expect("a chapter").path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    chapters.sort();
    files.extend(chapters);
    files
}

/// The fenced blocks of `path` (fences at the start of a line, as the docs write them).
fn blocks(path: &Path) -> Vec<Block> {
    let text = fs::read_to_string(path).expect("a document");
    let name = path.file_name().unwrap().to_string_lossy().into_owned();
    let stem = path.file_stem().unwrap().to_string_lossy().into_owned();
    let mut out = Vec::new();
    let mut open: Option<(usize, String, String)> = None;
    for (k, line) in text.lines().enumerate() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(info)) => open = Some((k + 1, info.trim().to_owned(), String::new())),
            (Some(_), Some(rest)) if rest.trim().is_empty() => {
                let (at, info, body) = open.take().unwrap();
                out.push(Block {
                    place: format!("{name}:{at}"),
                    slug: format!("{stem}-{at}"),
                    info,
                    text: body,
                });
            }
            (Some((_, _, body)), _) => {
                body.push_str(line);
                body.push('\n');
            }
            (None, None) => {}
        }
    }
    assert!(open.is_none(), "{name}: a block is not closed");
    out
}

fn all_blocks() -> Vec<Block> {
    documents().iter().flat_map(|p| blocks(p)).collect()
}

/// An empty folder for one block.
fn scratch(block: &Block) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("doc-blocks")
        .join(&block.slug);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("a scratch folder");
    dir
}

/// `PATH` with the folder of the `dvf` binary first.
fn path_with_dvf() -> String {
    let bin = Path::new(env!("CARGO_BIN_EXE_dvf")).parent().unwrap();
    let rest = std::env::var("PATH").unwrap_or_default();
    format!("{}:{rest}", bin.display())
}

#[test]
fn every_block_names_its_kind() {
    let blocks = all_blocks();
    assert!(blocks.len() > 10, "too few blocks found: {}", blocks.len());
    for b in &blocks {
        assert!(
            KINDS.contains(&b.info.as_str()),
            "{}: the block's kind `{}` is not one of {KINDS:?}",
            b.place,
            b.info
        );
    }
}

#[test]
fn shell_blocks_run_as_written() {
    let path = path_with_dvf();
    let mut ran = 0;
    for b in all_blocks().iter().filter(|b| b.info == "sh") {
        let dir = scratch(b);
        let out = Command::new("sh")
            .args(["-e", "-c", &b.text])
            .current_dir(&dir)
            .env("PATH", &path)
            .output()
            .expect("sh runs");
        assert!(
            out.status.success(),
            "{}: the block failed ({}):\n{}\nstderr:\n{}",
            b.place,
            out.status,
            b.text,
            String::from_utf8_lossy(&out.stderr)
        );
        ran += 1;
    }
    assert!(ran >= 5, "too few shell blocks ran: {ran}");
}

#[test]
fn json_blocks_are_scenarios_that_run() {
    let mut ran = 0;
    for b in all_blocks().iter().filter(|b| b.info == "json") {
        let dir = scratch(b);
        fs::write(dir.join("scenario.json"), &b.text).expect("a scenario file");
        let out = Command::new(env!("CARGO_BIN_EXE_dvf"))
            .args(["simulate", "scenario.json"])
            .current_dir(&dir)
            .output()
            .expect("dvf runs");
        assert!(
            out.status.success(),
            "{}: dvf simulate refused the scenario: {}",
            b.place,
            String::from_utf8_lossy(&out.stderr)
        );
        ran += 1;
    }
    assert!(ran >= 2, "too few scenario blocks ran: {ran}");
}
