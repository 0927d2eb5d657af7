//! The Scenario panel's file side: the path typed, the outcome of the last open or save,
//! and the scenario files of the current folder (read at most once a second, not every
//! frame).

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The outcome of the last file or export action, shown until the next one.
pub type Status = Option<Result<String, String>>;

/// How long a folder listing is trusted before the folder is read again.
const LISTING_LIFETIME: Duration = Duration::from_secs(1);

/// The file side of the Scenario panel.
#[derive(Debug, Default)]
pub struct Files {
    /// The scenario file path typed in the panel.
    pub path: String,
    /// What the last open or save did.
    pub status: Status,
    listing: Option<(Instant, Vec<PathBuf>)>,
}

impl Files {
    /// The scenario files of the current folder, read again only when the last reading
    /// is older than a second.
    pub fn scenario_files(&mut self) -> &[PathBuf] {
        let fresh = self
            .listing
            .as_ref()
            .is_some_and(|(at, _)| at.elapsed() < LISTING_LIFETIME);
        if !fresh {
            self.listing = Some((Instant::now(), scenario_files(Path::new("."))));
        }
        self.listing.as_ref().map_or(&[], |(_, files)| files)
    }
}

/// The `.toml` files of a folder that have a `[geometry]` table, sorted (at most 200).
fn scenario_files(dir: &Path) -> Vec<PathBuf> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut files: Vec<PathBuf> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| {
            p.extension()
                .is_some_and(|e| e.eq_ignore_ascii_case("toml"))
        })
        .filter(|p| {
            // Only the start of each file: a scenario names its geometry early.
            std::fs::File::open(p).is_ok_and(|f| {
                let mut head = String::new();
                std::io::Read::read_to_string(&mut std::io::Read::take(f, 64 * 1024), &mut head)
                    .is_ok()
                    && head.contains("[geometry]")
            })
        })
        .map(|p| p.strip_prefix(".").map(Path::to_path_buf).unwrap_or(p))
        .take(200)
        .collect();
    files.sort();
    files
}
