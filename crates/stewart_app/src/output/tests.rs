use super::*;

fn tmp() -> tempfile::TempDir {
    tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn writes_regular_files_whole_and_follows_links() {
    let dir = tmp();
    let target = dir.path().join("target.csv");
    std::fs::write(&target, "old").unwrap_or_else(|e| panic!("{e}"));
    let link = dir.path().join("link.csv");
    #[cfg(unix)]
    std::os::unix::fs::symlink("target.csv", &link).unwrap_or_else(|e| panic!("{e}"));
    write_atomically(&link, b"new").unwrap_or_else(|e| panic!("{e}"));
    assert!(
        std::fs::symlink_metadata(&link)
            .map(|m| m.file_type().is_symlink())
            .unwrap_or(false),
        "the link stays a link"
    );
    assert_eq!(std::fs::read(&target).ok().as_deref(), Some(&b"new"[..]));
}

#[test]
fn an_input_is_never_an_output() {
    let dir = tmp();
    let input = dir.path().join("s.toml");
    std::fs::write(&input, "x").unwrap_or_else(|e| panic!("{e}"));
    let e = Destination::new(&input, &[("the scenario", &input)]).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "refusing to write `{}`: it is the scenario this command reads (`{}`); choose another output file",
            input.display(),
            input.display()
        )
    );
    // Through a different spelling of the same file.
    let other = dir.path().join(".").join("s.toml");
    assert!(Destination::new(&other, &[("the scenario", &input)]).is_err());
    assert_eq!(std::fs::read(&input).ok().as_deref(), Some(&b"x"[..]));
}

#[cfg(unix)]
#[test]
fn devices_are_written_not_replaced() {
    let null = Path::new("/dev/null");
    let d = Destination::new(null, NO_INPUTS).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(d.kind(), Kind::Special);
    d.write_bytes(b"anything").unwrap_or_else(|e| panic!("{e}"));
    let m = std::fs::metadata(null).unwrap_or_else(|e| panic!("{e}"));
    assert!(!m.is_file(), "/dev/null is still a device");
    let full =
        Destination::new(Path::new("/dev/full"), NO_INPUTS).unwrap_or_else(|e| panic!("{e}"));
    let e = full.write_bytes(&[0; 100_000]).unwrap_err();
    assert!(
        format!("{e:#}").starts_with("cannot write `/dev/full`: "),
        "{e:#}"
    );
}

#[test]
fn a_failed_write_leaves_nothing() {
    let dir = tmp();
    let out = dir.path().join("out.csv");
    let d = Destination::new(&out, NO_INPUTS).unwrap_or_else(|e| panic!("{e}"));
    let e = d
        .write_with(|w| {
            w.write_all(b"half")?;
            Err(std::io::Error::other("disk on fire"))
        })
        .unwrap_err();
    assert!(format!("{e:#}").contains("disk on fire"));
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .map(|d| d.flatten().map(|e| e.file_name()).collect())
        .unwrap_or_default();
    assert!(left.is_empty(), "{left:?}");
}
