//! The Rust blocks of the README and of the book, compiled and run by `cargo test --doc`: one
//! item per file, its documentation the file itself, so that every block in it is a doctest.
//! Compiled only for doctests (`#[cfg(doctest)]` on the module in `lib.rs`).

#[doc = include_str!("../README.md")]
struct Readme;

#[doc = include_str!("../docs/book/src/library.md")]
struct BookLibrary;
