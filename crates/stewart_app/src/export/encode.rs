//! Encoding rendered frames into a PNG sequence, a GIF or an MP4, on worker threads in
//! parallel with rendering; the output appears only when complete.

use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::sync_channel;
use std::sync::{Arc, Mutex};

use anyhow::{Context, Result, anyhow, bail};
use indicatif::ProgressBar;
use stewart_render::Frame;

use super::frames::FrameSource;

/// Where frames go, chosen by the output path.
#[derive(Clone, Debug, PartialEq)]
pub enum Target {
    /// A folder of numbered PNG files.
    Folder(PathBuf),
    /// A looping animated GIF.
    Gif(PathBuf),
    /// An H.264 MP4 made by `ffmpeg`.
    Mp4(PathBuf),
}

impl Target {
    /// `.gif` and `.mp4` paths are videos; anything else is a folder.
    pub fn from_path(path: &Path) -> Target {
        match path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase)
            .as_deref()
        {
            Some("gif") => Target::Gif(path.to_path_buf()),
            Some("mp4") => Target::Mp4(path.to_path_buf()),
            _ => Target::Folder(path.to_path_buf()),
        }
    }
}

/// One frame after a worker has dealt with it.
enum Encoded {
    /// Written to its own file already.
    Written,
    /// A quantised GIF frame.
    Gif(gif::Frame<'static>),
    /// Raw RGBA for ffmpeg.
    Raw(Vec<u8>),
}

/// The folder (or file) being written, moved into place at the end.
enum Staging {
    Folder {
        dir: tempfile::TempDir,
        out: PathBuf,
        digits: usize,
    },
    Gif {
        encoder: gif::Encoder<std::fs::File>,
        file: tempfile::TempPath,
        out: PathBuf,
        delay_cs: u16,
    },
    Mp4 {
        child: Child,
        file: tempfile::TempPath,
        out: PathBuf,
    },
}

fn parent_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

fn temp_file_beside(out: &Path, suffix: &str) -> Result<tempfile::NamedTempFile> {
    tempfile::Builder::new()
        .prefix(".stewart-")
        .suffix(suffix)
        .tempfile_in(parent_of(out))
        .with_context(|| format!("cannot write `{}`", out.display()))
}

/// Check that `ffmpeg` runs, or say how to install it.
pub fn check_ffmpeg() -> Result<()> {
    match Command::new("ffmpeg")
        .arg("-version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
    {
        Ok(s) if s.success() => Ok(()),
        _ => bail!(
            "MP4 export needs the `ffmpeg` program, which was not found: install it (Debian: `apt-get install ffmpeg`)"
        ),
    }
}

impl Staging {
    fn open(
        target: &Target,
        width: u32,
        height: u32,
        fps: f64,
        last_index: usize,
    ) -> Result<Staging> {
        match target {
            Target::Folder(out) => {
                if out.exists()
                    && std::fs::read_dir(out)
                        .map(|mut d| d.next().is_some())
                        .unwrap_or(true)
                {
                    bail!(
                        "`{}` exists and is not an empty folder: choose a new folder for the frames",
                        out.display()
                    );
                }
                let dir = tempfile::Builder::new()
                    .prefix(".stewart-frames-")
                    .tempdir_in(parent_of(out))
                    .with_context(|| format!("cannot write `{}`", out.display()))?;
                let digits = last_index.to_string().len().max(5);
                Ok(Staging::Folder {
                    dir,
                    out: out.clone(),
                    digits,
                })
            }
            Target::Gif(out) => {
                let (file, path) = temp_file_beside(out, ".gif")?.into_parts();
                let (w, h) = (u16::try_from(width), u16::try_from(height));
                let (Ok(w), Ok(h)) = (w, h) else {
                    bail!("a GIF can be at most 65535 pixels wide and high")
                };
                let mut encoder =
                    gif::Encoder::new(file, w, h, &[]).context("cannot start the GIF")?;
                encoder
                    .set_repeat(gif::Repeat::Infinite)
                    .context("cannot start the GIF")?;
                let delay_cs = (100.0 / fps).round().clamp(1.0, 65535.0) as u16;
                Ok(Staging::Gif {
                    encoder,
                    file: path,
                    out: out.clone(),
                    delay_cs,
                })
            }
            Target::Mp4(out) => {
                check_ffmpeg()?;
                let file = temp_file_beside(out, ".mp4")?.into_temp_path();
                let child = Command::new("ffmpeg")
                    .args([
                        "-hide_banner",
                        "-loglevel",
                        "error",
                        "-y",
                        "-f",
                        "rawvideo",
                        "-pix_fmt",
                        "rgba",
                    ])
                    .args([
                        "-s",
                        &format!("{width}x{height}"),
                        "-framerate",
                        &format!("{fps}"),
                        "-i",
                        "-",
                    ])
                    .args([
                        "-vf",
                        "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                        "-c:v",
                        "libx264",
                        "-preset",
                        "veryfast",
                        "-crf",
                        "18",
                    ])
                    .args([
                        "-pix_fmt",
                        "yuv420p",
                        "-movflags",
                        "+faststart",
                        "-f",
                        "mp4",
                    ])
                    .arg(file.as_os_str())
                    .stdin(Stdio::piped())
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .context("cannot start ffmpeg")?;
                Ok(Staging::Mp4 {
                    child,
                    file,
                    out: out.clone(),
                })
            }
        }
    }

    /// What a worker does with a frame.
    fn encode(
        kind: &Target,
        dir: Option<&Path>,
        digits: usize,
        index: usize,
        frame: Frame,
    ) -> Result<Encoded> {
        match kind {
            Target::Folder(_) => {
                let dir = dir.ok_or_else(|| anyhow!("no staging folder"))?;
                let path = dir.join(format!("frame_{index:0digits$}.png"));
                let file = std::io::BufWriter::new(
                    std::fs::File::create(&path)
                        .with_context(|| format!("cannot write `{}`", path.display()))?,
                );
                let encoder = image::codecs::png::PngEncoder::new_with_quality(
                    file,
                    image::codecs::png::CompressionType::Fast,
                    image::codecs::png::FilterType::Adaptive,
                );
                image::ImageEncoder::write_image(
                    encoder,
                    &frame.rgba,
                    frame.width,
                    frame.height,
                    image::ExtendedColorType::Rgba8,
                )
                .with_context(|| format!("cannot write `{}`", path.display()))?;
                Ok(Encoded::Written)
            }
            Target::Gif(_) => {
                let mut rgba = frame.rgba;
                let (Ok(w), Ok(h)) = (u16::try_from(frame.width), u16::try_from(frame.height))
                else {
                    bail!("a GIF can be at most 65535 pixels wide and high")
                };
                Ok(Encoded::Gif(gif::Frame::from_rgba_speed(
                    w, h, &mut rgba, 10,
                )))
            }
            Target::Mp4(_) => Ok(Encoded::Raw(frame.rgba)),
        }
    }

    /// Append one encoded frame, in order.
    fn write(&mut self, encoded: Encoded) -> Result<()> {
        match (self, encoded) {
            (Staging::Folder { .. }, Encoded::Written) => Ok(()),
            (
                Staging::Gif {
                    encoder, delay_cs, ..
                },
                Encoded::Gif(mut frame),
            ) => {
                frame.delay = *delay_cs;
                encoder.write_frame(&frame).context("cannot write the GIF")
            }
            (Staging::Mp4 { child, .. }, Encoded::Raw(bytes)) => {
                let stdin = child
                    .stdin
                    .as_mut()
                    .ok_or_else(|| anyhow!("ffmpeg closed its input"))?;
                stdin
                    .write_all(&bytes)
                    .context("ffmpeg stopped reading frames")
            }
            _ => bail!("internal error: a frame of the wrong kind"),
        }
    }

    /// Move the finished output into place.
    fn finish(self) -> Result<()> {
        match self {
            Staging::Folder { dir, out, .. } => {
                let staged = dir.keep();
                crate::output::readable_by_all(&staged);
                if out.exists() {
                    std::fs::remove_dir(&out).with_context(|| {
                        format!("cannot replace the empty folder `{}`", out.display())
                    })?;
                }
                std::fs::rename(&staged, &out)
                    .with_context(|| format!("cannot create `{}`", out.display()))
            }
            Staging::Gif {
                encoder, file, out, ..
            } => {
                let mut f = encoder.into_inner().context("cannot finish the GIF")?;
                f.flush().context("cannot finish the GIF")?;
                crate::output::readable_by_all(&file);
                file.persist(&out)
                    .map_err(|e| e.error)
                    .with_context(|| format!("cannot write `{}`", out.display()))
            }
            Staging::Mp4 {
                mut child,
                file,
                out,
            } => {
                drop(child.stdin.take());
                let output = child.wait_with_output().context("ffmpeg did not finish")?;
                if !output.status.success() {
                    bail!(
                        "ffmpeg failed: {}",
                        String::from_utf8_lossy(&output.stderr).trim()
                    );
                }
                crate::output::readable_by_all(&file);
                file.persist(&out)
                    .map_err(|e| e.error)
                    .with_context(|| format!("cannot write `{}`", out.display()))
            }
        }
    }
}

/// Render `indices` from `source` and encode them into `target` at `fps`, reporting on `progress`.
///
/// When `stop` becomes true (Ctrl-C), the export ends with an error and every staged file
/// is removed: nothing half-written is left.
pub fn export(
    source: &mut FrameSource,
    indices: std::ops::Range<usize>,
    fps: f64,
    target: &Target,
    progress: &ProgressBar,
    stop: &AtomicBool,
) -> Result<()> {
    let first = source.frame_size();
    let mut staging = Staging::open(target, first.0, first.1, fps, indices.end.saturating_sub(1))?;
    let staged_dir = match &staging {
        Staging::Folder { dir, .. } => Some(dir.path().to_path_buf()),
        _ => None,
    };
    let digits = match &staging {
        Staging::Folder { digits, .. } => *digits,
        _ => 0,
    };
    let workers = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .clamp(1, 8);
    let (to_workers, from_render) = sync_channel::<(usize, Frame)>(2 * workers);
    let from_render = Arc::new(Mutex::new(from_render));
    let (to_writer, from_workers) = sync_channel::<(usize, Result<Encoded>)>(4 * workers);
    let start = indices.start;
    let count = indices.len();
    std::thread::scope(|scope| -> Result<()> {
        for _ in 0..workers {
            let rx = Arc::clone(&from_render);
            let tx = to_writer.clone();
            let dir = staged_dir.clone();
            scope.spawn(move || {
                loop {
                    let next = rx.lock().map(|r| r.recv());
                    let Ok(Ok((k, frame))) = next else { break };
                    let result = Staging::encode(target, dir.as_deref(), digits, k, frame);
                    if tx.send((k, result)).is_err() {
                        break;
                    }
                }
            });
        }
        drop(to_writer);
        let writer = scope.spawn(move || -> Result<Staging> {
            let mut pending: BTreeMap<usize, Encoded> = BTreeMap::new();
            let mut next = start;
            for (k, result) in from_workers {
                pending.insert(k, result?);
                while let Some(e) = pending.remove(&next) {
                    staging.write(e)?;
                    progress.inc(1);
                    next += 1;
                }
            }
            if next != start + count {
                bail!("only {} of {count} frames were encoded", next - start);
            }
            Ok(staging)
        });
        let mut render_result = Ok(());
        for k in indices.clone() {
            if stop.load(Ordering::Relaxed) {
                render_result = Err(anyhow!("interrupted: nothing was written"));
                break;
            }
            match source.frame(k) {
                Ok(frame) => {
                    if to_workers.send((k, frame)).is_err() {
                        break; // the writer stopped: its error is reported below
                    }
                }
                Err(e) => {
                    render_result = Err(e);
                    break;
                }
            }
        }
        drop(to_workers);
        let written = writer
            .join()
            .map_err(|_| anyhow!("the encoder thread panicked"))?;
        // A rendering failure or an interruption explains a short output: report it first.
        render_result?;
        written?.finish()
    })
}
