//! The comparison's tests.
