//! The crate's errors. Every message names the field at fault and says what is wrong with it,
//! so that a person can fix the input from the message alone.

/// What can go wrong with input to the crate.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Error {
    /// The text is not a scenario: malformed JSON, a wrong type, a missing or unknown key.
    #[error("{}{message}", if field.is_empty() { "malformed scenario: ".to_owned() } else { format!("{field}: ") })]
    Parse {
        /// Path of the offending field (`params.k_v`, `robots[2].goal`), empty for the document.
        field: String,
        /// What the parser found wrong.
        message: String,
    },
    /// A value outside its documented range.
    #[error("{field}: {message}")]
    Invalid {
        /// Path of the offending field.
        field: String,
        /// What is wrong and what would be accepted.
        message: String,
    },
    /// A preset name that does not exist.
    #[error("preset: no preset named `{name}` (available: {available})")]
    UnknownPreset {
        /// The name asked for.
        name: String,
        /// The names that exist, comma-separated.
        available: String,
    },
    /// A robot index out of range.
    #[error("robot: index {index} is out of range (the scenario has {count} robots)")]
    RobotIndex {
        /// The index asked for.
        index: usize,
        /// How many robots there are.
        count: usize,
    },
}
