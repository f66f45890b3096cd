//! Non-fatal problems met while loading. Each is logged (`log::warn!`) *and* kept, so the CLI
//! can print them even without a logger, and tests can assert on them.

use std::collections::HashSet;

#[derive(Debug, Default)]
pub(crate) struct Warnings {
    list: Vec<String>,
    seen: HashSet<String>,
}

impl Warnings {
    pub fn warn(&mut self, msg: impl Into<String>) {
        // Warnings quote file contents: escaped and truncated once, here.
        let msg = crate::text::sanitize(&msg.into());
        log::warn!("{msg}");
        self.list.push(msg);
    }

    /// Warns only the first time `key` is seen: an unsupported feature used by 500 materials
    /// is one warning, not 500.
    pub fn warn_once(&mut self, key: &str, msg: impl FnOnce() -> String) {
        if self.seen.insert(key.to_owned()) {
            self.warn(msg());
        }
    }

    pub fn into_vec(self) -> Vec<String> {
        self.list
    }
}
