//! Tenhou's mjlog XML, the format of its Phoenix-room archive.
//!
//! * [`meld`] — the 16-bit meld codes of `N` tags
//! * [`read`] — an mjlog as a [`crate::tenhou::log::Game`], through the MJAI reader's builder

pub mod meld;
pub mod read;

#[cfg(test)]
mod tests;
