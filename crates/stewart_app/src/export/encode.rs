//! Encoding rendered frames into a PNG sequence, a GIF or an MP4, on worker threads in
//! parallel with rendering; the output appears only when complete.

use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, SyncSender, TrySendError, sync_channel};
use std::sync::{Arc, Mutex};

use anyhow::{Context, Result, anyhow, bail};
use indicatif::ProgressBar;
use stewart_render::Image;

use crate::output::{Destination, Kind};

use super::frames::FrameSource;

/// Where frames go, chosen by the output path.
#[derive(Clone, Debug, PartialEq)]
pub enum FrameSink {
    /// A folder of numbered PNG files.
    Folder(PathBuf),
    /// A looping animated GIF.
    Gif(PathBuf),
    /// An H.264 MP4 made by `ffmpeg`.
    Mp4(PathBuf),
}

impl FrameSink {
    /// `.gif` and `.mp4` paths are videos; anything else is a folder.
    pub fn from_path(path: &Path) -> FrameSink {
        match crate::output::extension(path).as_deref() {
            Some("gif") => FrameSink::Gif(path.to_path_buf()),
            Some("mp4") => FrameSink::Mp4(path.to_path_buf()),
            _ => FrameSink::Folder(path.to_path_buf()),
        }
    }

    /// The output path, checked before any work: a folder of frames must be new or
    /// empty, a video must be a file (or a device or FIFO), and none of them an input.
    pub(crate) fn destination(&self) -> Result<Destination> {
        match self {
            FrameSink::Folder(out) => {
                let dest = Destination::new(out, crate::output::NO_INPUTS)?;
                match dest.kind() {
                    Kind::Folder => {
                        let empty = std::fs::read_dir(dest.real())
                            .map(|mut d| d.next().is_none())
                            .unwrap_or(false);
                        if !empty {
                            bail!(
                                "`{}` exists and is not an empty folder: choose a new folder for the frames",
                                out.display()
                            );
                        }
                    }
                    Kind::Special => bail!(
                        "`{}` is not a folder: PNG frames go into a new folder (or give a .gif or .mp4 file)",
                        out.display()
                    ),
                    Kind::File if dest.real().exists() => bail!(
                        "`{}` is a file: PNG frames go into a new folder (or give a .gif or .mp4 file)",
                        out.display()
                    ),
                    Kind::File => {}
                }
                Ok(dest)
            }
            FrameSink::Gif(out) | FrameSink::Mp4(out) => {
                let dest = Destination::new(out, crate::output::NO_INPUTS)?;
                dest.require_file()?;
                Ok(dest)
            }
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
    Raw(Arc<Image>),
}

/// A running `ffmpeg`: killed and waited for when dropped, so that no path (an error,
/// Ctrl-C, a panic elsewhere) leaves it running or writing behind our back.
struct FfmpegChild {
    child: Child,
    /// Drains ffmpeg's standard error (so it can never block on a full pipe) and keeps
    /// the end of it for the error message.
    stderr: Option<std::thread::JoinHandle<String>>,
}

impl FfmpegChild {
    /// Stop ffmpeg now (a writer blocked on its input then fails at once).
    fn kill(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }

    /// Whether ffmpeg exits with a failure within `patience` (polled, never blocking
    /// longer): after its input broke, this tells an ffmpeg that quit from one that hangs.
    fn exited_with_failure(&mut self, patience: std::time::Duration) -> bool {
        let until = std::time::Instant::now() + patience;
        loop {
            match self.child.try_wait() {
                Ok(Some(status)) => return !status.success(),
                Ok(None) if std::time::Instant::now() < until => std::thread::sleep(POLL),
                _ => return false,
            }
        }
    }

    /// Wait for ffmpeg to finish after its input was closed; its error output on failure.
    fn finish(&mut self, staged: &Path, out: &Path) -> Result<()> {
        let status = self.child.wait().context("ffmpeg did not finish")?;
        // At `-loglevel error` anything ffmpeg says is an error, and some errors (a full
        // disk while it rewrites the file for `+faststart`) still end with status 0.
        let said = self.said();
        if status.success() && said.trim().is_empty() {
            return Ok(());
        }
        bail!("ffmpeg failed: {}", one_line(&said, staged, out));
    }

    /// What ffmpeg wrote to its standard error (once; empty afterwards).
    fn said(&mut self) -> String {
        self.stderr
            .take()
            .and_then(|h| h.join().ok())
            .unwrap_or_default()
    }

    /// ffmpeg's last words, with the staged file's name replaced by the output's.
    fn message(&mut self, staged: &Path, out: &Path) -> String {
        let said = self.said();
        one_line(&said, staged, out)
    }
}

/// ffmpeg's words on one line, like every error, naming the output instead of the
/// staged file.
fn one_line(said: &str, staged: &Path, out: &Path) -> String {
    let text = said.replace(&staged.display().to_string(), &out.display().to_string());
    let lines: Vec<&str> = text
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect();
    if lines.is_empty() {
        "it stopped without saying why".to_owned()
    } else {
        lines.join("; ")
    }
}

impl Drop for FfmpegChild {
    fn drop(&mut self) {
        if let Ok(None) = self.child.try_wait() {
            self.kill();
        }
    }
}

/// The folder (or file) being written, moved into place at the end.
enum Staging {
    Folder {
        dir: tempfile::TempDir,
        out: PathBuf,
        digits: usize,
    },
    Gif {
        encoder: gif::Encoder<std::io::BufWriter<std::fs::File>>,
        file: tempfile::TempPath,
        out: Destination,
        delay_cs: u16,
    },
    Mp4 {
        stdin: Option<std::process::ChildStdin>,
        file: tempfile::TempPath,
        out: Destination,
    },
}

/// Check that `ffmpeg` runs, or say how to install it.
pub(crate) fn check_ffmpeg() -> Result<()> {
    match Command::new("ffmpeg")
        .arg("-version")
        .stdin(Stdio::null())
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

/// Start ffmpeg encoding raw RGBA frames from its input into `file`.
fn spawn_ffmpeg(width: u32, height: u32, fps: f64, file: &Path) -> Result<FfmpegChild> {
    check_ffmpeg()?;
    let mut command = Command::new("ffmpeg");
    command
        .args(["-hide_banner", "-loglevel", "error", "-nostdin", "-y"])
        .args(["-f", "rawvideo", "-pix_fmt", "rgba"])
        .args(["-s", &format!("{width}x{height}")])
        .args(["-framerate", &format!("{fps}"), "-i", "-"])
        .args(["-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2"])
        .args(["-c:v", "libx264", "-preset", "veryfast", "-crf", "18"])
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
        .stderr(Stdio::piped());
    // Its own process group: Ctrl-C in a terminal reaches only us, and we stop ffmpeg
    // ourselves (left to itself it would finish the file it was writing).
    #[cfg(unix)]
    std::os::unix::process::CommandExt::process_group(&mut command, 0);
    let mut child = command.spawn().context("cannot start ffmpeg")?;
    let stderr = child.stderr.take().map(|mut pipe| {
        std::thread::spawn(move || {
            let mut text = Vec::new();
            let mut buf = [0u8; 4096];
            while let Ok(n) = std::io::Read::read(&mut pipe, &mut buf) {
                if n == 0 {
                    break;
                }
                text.extend_from_slice(&buf[..n]);
                if text.len() > 16384 {
                    text.drain(..text.len() - 8192);
                }
            }
            String::from_utf8_lossy(&text).into_owned()
        })
    });
    Ok(FfmpegChild { child, stderr })
}

/// An output opened for writing: the staging and, for MP4, the ffmpeg process.
struct Opened {
    staging: Staging,
    ffmpeg: Option<FfmpegChild>,
}

impl Staging {
    fn open(
        target: &FrameSink,
        width: u32,
        height: u32,
        fps: f64,
        last_index: usize,
    ) -> Result<Opened> {
        let opened = |staging| Opened {
            staging,
            ffmpeg: None,
        };
        match target {
            FrameSink::Folder(out) => {
                let dest = target.destination()?;
                let dir = tempfile::Builder::new()
                    .prefix(".stewart-frames-")
                    .tempdir_in(dest.staging_dir())
                    .with_context(|| format!("cannot write `{}`", out.display()))?;
                let digits = last_index.to_string().len().max(5);
                Ok(opened(Staging::Folder {
                    dir,
                    out: dest.real().to_path_buf(),
                    digits,
                }))
            }
            FrameSink::Gif(_) => {
                let dest = target.destination()?;
                let (Ok(w), Ok(h)) = (u16::try_from(width), u16::try_from(height)) else {
                    bail!("a GIF can be at most 65535 pixels wide and high")
                };
                let (file, path) = dest.staged_file(".gif")?.into_parts();
                let mut encoder = gif::Encoder::new(std::io::BufWriter::new(file), w, h, &[])
                    .context("cannot start the GIF")?;
                encoder
                    .set_repeat(gif::Repeat::Infinite)
                    .context("cannot start the GIF")?;
                let delay_cs = gif_delay_cs(fps);
                Ok(opened(Staging::Gif {
                    encoder,
                    file: path,
                    out: dest,
                    delay_cs,
                }))
            }
            FrameSink::Mp4(_) => {
                let dest = target.destination()?;
                let file = dest.staged_file(".mp4")?.into_temp_path();
                let mut ffmpeg = spawn_ffmpeg(width, height, fps, &file)?;
                let stdin = ffmpeg.child.stdin.take();
                Ok(Opened {
                    staging: Staging::Mp4 {
                        stdin,
                        file,
                        out: dest,
                    },
                    ffmpeg: Some(ffmpeg),
                })
            }
        }
    }

    /// What a worker does with a frame.
    fn encode(
        kind: &FrameSink,
        dir: Option<&Path>,
        digits: usize,
        index: usize,
        frame: Arc<Image>,
        previous: Option<&Image>,
    ) -> Result<Encoded> {
        match kind {
            FrameSink::Folder(out) => {
                let dir = dir.ok_or_else(|| anyhow!("no staging folder"))?;
                let name = format!("frame_{index:0digits$}.png");
                let path = dir.join(&name);
                let shown = out.join(&name);
                let file = std::io::BufWriter::new(
                    std::fs::File::create(&path)
                        .with_context(|| format!("cannot write `{}`", shown.display()))?,
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
                .with_context(|| format!("cannot write `{}`", shown.display()))?;
                Ok(Encoded::Written)
            }
            // The size was checked when the GIF was opened.
            FrameSink::Gif(_) => Ok(Encoded::Gif(super::gif_delta::delta_frame(
                previous, &frame,
            ))),
            FrameSink::Mp4(_) => Ok(Encoded::Raw(frame)),
        }
    }

    /// Append one encoded frame, in order.
    fn write(&mut self, encoded: Encoded) -> Result<()> {
        match (self, encoded) {
            (Staging::Folder { .. }, Encoded::Written) => Ok(()),
            (
                Staging::Gif {
                    encoder,
                    delay_cs,
                    out,
                    ..
                },
                Encoded::Gif(mut frame),
            ) => {
                frame.delay = *delay_cs;
                encoder
                    .write_frame(&frame)
                    .with_context(|| format!("cannot write `{}`", out.shown().display()))
            }
            (Staging::Mp4 { stdin, .. }, Encoded::Raw(frame)) => {
                let stdin = stdin
                    .as_mut()
                    .ok_or_else(|| anyhow!("ffmpeg closed its input"))?;
                stdin
                    .write_all(&frame.rgba)
                    .context("ffmpeg stopped reading frames")
            }
            _ => bail!("internal error: a frame of the wrong kind"),
        }
    }
    /// A folder of frames' staging folder and the digits of its file names (`None`, 0 for
    /// a file).
    fn folder(&self) -> (Option<PathBuf>, usize) {
        match self {
            Staging::Folder { dir, digits, .. } => (Some(dir.path().to_path_buf()), *digits),
            _ => (None, 0),
        }
    }

    /// Move the finished output into place (ffmpeg, when there is one, has finished).
    fn finish(self, ffmpeg: Option<&mut FfmpegChild>) -> Result<()> {
        match self {
            Staging::Folder { dir, out, .. } => {
                let staged = dir.keep();
                crate::output::readable_by_all(&staged);
                let placed = (|| {
                    if out.exists() {
                        std::fs::remove_dir(&out).with_context(|| {
                            format!("cannot replace the empty folder `{}`", out.display())
                        })?;
                    }
                    std::fs::rename(&staged, &out)
                        .with_context(|| format!("cannot create `{}`", out.display()))
                })();
                if placed.is_err() {
                    let _ = std::fs::remove_dir_all(&staged);
                }
                placed
            }
            Staging::Gif {
                encoder, file, out, ..
            } => {
                let shown = out.shown().display().to_string();
                let mut w = encoder
                    .into_inner()
                    .with_context(|| format!("cannot write `{shown}`"))?;
                w.flush()
                    .and_then(|()| w.get_ref().sync_all())
                    .with_context(|| format!("cannot write `{shown}`"))?;
                drop(w);
                out.deliver(file)
            }
            Staging::Mp4 { stdin, file, out } => {
                drop(stdin);
                let ffmpeg = ffmpeg.ok_or_else(|| anyhow!("internal error: no ffmpeg"))?;
                ffmpeg.finish(&file, out.shown())?;
                out.deliver(file)
            }
        }
    }
}

/// A frame to encode: its index, its pixels and, for a GIF, the frame before it.
type Job = (usize, Arc<Image>, Option<Arc<Image>>);

/// An encoding worker: frames from `jobs` encoded for `target` (staged in `dir` with
/// `digits`-digit names when it is a folder), each sent to `done` with its index, until
/// the queue closes or nobody takes the results.
fn encode_frames(
    target: &FrameSink,
    dir: Option<&Path>,
    digits: usize,
    jobs: &Mutex<Receiver<Job>>,
    done: &SyncSender<(usize, Result<Encoded>)>,
) {
    loop {
        let next = jobs.lock().map(|r| r.recv());
        let Ok(Ok((k, frame, previous))) = next else {
            break;
        };
        let result = Staging::encode(target, dir, digits, k, frame, previous.as_deref());
        if done.send((k, result)).is_err() {
            break;
        }
    }
}

/// Why an export failed, if it did: a rendering failure or an interruption explains a
/// short output, so it comes before the writer's error.
fn first_failure(
    rendered: Result<()>,
    written: Result<()>,
    stop: &AtomicBool,
) -> Option<anyhow::Error> {
    match (rendered, written) {
        (Err(e), _) | (Ok(()), Err(e)) => Some(e),
        (Ok(()), Ok(())) if stop.load(Ordering::Relaxed) => {
            Some(anyhow!("interrupted: nothing was written"))
        }
        (Ok(()), Ok(())) => None,
    }
}

/// Shortest GIF frame delay that plays as written: browsers and most viewers show a
/// delay of 0 or 1 centisecond as 10.
pub(crate) const GIF_MIN_DELAY_CS: u16 = 2;

/// A GIF frame's delay for `fps` frames per second: whole centiseconds, at least
/// [`GIF_MIN_DELAY_CS`].
pub(crate) fn gif_delay_cs(fps: f64) -> u16 {
    (100.0 / fps)
        .round()
        .clamp(f64::from(GIF_MIN_DELAY_CS), 65535.0) as u16
}

/// How long the render loop waits for a busy encoder before looking at the stop and
/// failure flags again.
const POLL: std::time::Duration = std::time::Duration::from_millis(20);

/// Write the encoded frames `indices` to `staging` in order as they come from the workers
/// (out of order), counting each on `progress`; an error ends it (the render loop sees it
/// through the failure flag).
fn write_in_order(
    staging: &mut Staging,
    from_workers: Receiver<(usize, Result<Encoded>)>,
    indices: std::ops::Range<usize>,
    progress: &ProgressBar,
) -> Result<()> {
    let mut pending: BTreeMap<usize, Encoded> = BTreeMap::new();
    let mut next = indices.start;
    for (k, result) in from_workers {
        pending.insert(k, result?);
        while let Some(e) = pending.remove(&next) {
            staging.write(e)?;
            progress.inc(1);
            next += 1;
        }
    }
    if next != indices.end {
        bail!(
            "only {} of {} frames were encoded",
            next - indices.start,
            indices.len()
        );
    }
    Ok(())
}

/// Render `indices` from `source` and hand each frame (with the one before it when
/// `keeps_previous`) to the encoders, looking at `stop` (an interruption: an error) and
/// `failed` (the writer's error, reported by the writer) while they are busy.
fn feed_frames(
    source: &mut FrameSource,
    indices: std::ops::Range<usize>,
    keeps_previous: bool,
    to_workers: &SyncSender<Job>,
    stop: &AtomicBool,
    failed: &AtomicBool,
) -> Result<()> {
    let interrupted = || anyhow!("interrupted: nothing was written");
    let mut previous: Option<Arc<Image>> = None;
    for k in indices {
        if stop.load(Ordering::Relaxed) {
            return Err(interrupted());
        }
        if failed.load(Ordering::Relaxed) {
            return Ok(());
        }
        let frame = Arc::new(source.frame(k)?);
        let before = std::mem::replace(&mut previous, keeps_previous.then(|| Arc::clone(&frame)));
        let mut item = (k, frame, before);
        // Hand the frame over, looking at the flags while the encoders are busy.
        loop {
            match to_workers.try_send(item) {
                Ok(()) => break,
                Err(TrySendError::Disconnected(_)) => return Ok(()),
                Err(TrySendError::Full(back)) => {
                    if stop.load(Ordering::Relaxed) {
                        return Err(interrupted());
                    }
                    if failed.load(Ordering::Relaxed) {
                        return Ok(());
                    }
                    item = back;
                    std::thread::sleep(POLL);
                }
            }
        }
    }
    Ok(())
}

/// Render `indices` from `source` and encode them into `target` at `fps`, reporting on `progress`.
///
/// When `stop` becomes true (Ctrl-C), the export ends with an error and every staged file
/// is removed: nothing half-written is left. A failing sink (a full disk, a folder that
/// vanished, an ffmpeg that quit) ends the export within a frame or two with its error,
/// and ffmpeg is killed and waited for on every path.
pub fn export(
    source: &mut FrameSource,
    indices: std::ops::Range<usize>,
    fps: f64,
    target: &FrameSink,
    progress: &ProgressBar,
    stop: &AtomicBool,
) -> Result<()> {
    let first = source.frame_size();
    let Opened {
        mut staging,
        mut ffmpeg,
    } = Staging::open(target, first.0, first.1, fps, indices.end.saturating_sub(1))?;
    let (staged_dir, digits) = staging.folder();
    let workers = std::thread::available_parallelism()
        .map_or(2, |n| n.get())
        .clamp(1, 8);
    // Set by the writer when the sink fails, so that rendering stops at once.
    let failed = AtomicBool::new(false);
    // Each frame goes with the one before it when the GIF needs it for its changed part.
    let (to_workers, from_render) = sync_channel::<Job>(2 * workers);
    let from_render = Arc::new(Mutex::new(from_render));
    let (to_writer, from_workers) = sync_channel::<(usize, Result<Encoded>)>(4 * workers);
    let start = indices.start;
    let count = indices.len();
    let (staging, written, rendered) = std::thread::scope(|scope| {
        for _ in 0..workers {
            let rx = Arc::clone(&from_render);
            let tx = to_writer.clone();
            let dir = staged_dir.clone();
            scope.spawn(move || encode_frames(target, dir.as_deref(), digits, &rx, &tx));
        }
        // Only the workers hold the frame queue's receiver: when they have all stopped,
        // sending fails instead of waiting forever.
        drop(from_render);
        drop(to_writer);
        let failed = &failed;
        // The writer hands the staging back whatever happens: on an error ffmpeg must be
        // stopped before the staged file (and ffmpeg's input) are dropped.
        let writer = scope.spawn(move || {
            let result = write_in_order(&mut staging, from_workers, start..start + count, progress);
            if result.is_err() {
                failed.store(true, Ordering::Relaxed);
            }
            (staging, result)
        });
        let keeps_previous = matches!(target, FrameSink::Gif(_));
        let render_result = feed_frames(
            source,
            indices.clone(),
            keeps_previous,
            &to_workers,
            stop,
            failed,
        );
        drop(to_workers);
        if render_result.is_err()
            && let Some(f) = ffmpeg.as_mut()
        {
            // A writer blocked on ffmpeg's input fails at once.
            f.kill();
        }
        match writer.join() {
            Ok((staging, written)) => (Some(staging), written, render_result),
            Err(_) => (
                None,
                Err(anyhow!("the encoder thread panicked")),
                render_result,
            ),
        }
    });
    let sink_failed = rendered.is_ok() && written.is_err();
    if let Some(e) = first_failure(rendered, written, stop) {
        return Err(failed_export(e, sink_failed, staging, ffmpeg.as_mut()));
    }
    let staging = staging.ok_or_else(|| anyhow!("internal error: no output"))?;
    staging.finish(ffmpeg.as_mut())
}

/// The error an export ends with, `e` or what ffmpeg said when it quit by itself (the
/// sink failed: ffmpeg explains a failed write better than the write does); ffmpeg
/// stopped and only then the staged files dropped.
fn failed_export(
    e: anyhow::Error,
    sink_failed: bool,
    staging: Option<Staging>,
    ffmpeg: Option<&mut FfmpegChild>,
) -> anyhow::Error {
    let mut e = e;
    if let Some(f) = ffmpeg {
        // ffmpeg that quit by itself explains a failed write better than the write does;
        // its input may close a moment before it exits, so give it a little time.
        let quit = sink_failed && f.exited_with_failure(std::time::Duration::from_secs(2));
        f.kill();
        if quit && let Some(Staging::Mp4 { file, out, .. }) = &staging {
            e = anyhow!("ffmpeg failed: {}", f.message(file, out.shown()));
        }
    }
    // Staged files go only now, after ffmpeg is gone.
    drop(staging);
    e
}
