//! The Workspace panel's state: the reachable workspace at an orientation shown in the 3D
//! view as a translucent surface, and a horizontal slice coloured by the condition
//! number, both computed off the UI thread.
//!
//! A background job ([`crate::viewer::tools::job`]) takes the newest request only. A request is computed
//! coarse first (its result shown at once), then refined; a newer request — a slider
//! dragged on — cancels the refinement in flight (the job's flag is the
//! [`WorkspaceControl`]'s) and the job moves to the newest. The UI thread only swaps in
//! finished results (`poll`, never blocking); the meshes are built on the job too, so the
//! UI's share is uploading them once.
//!
//! While the request changes from frame to frame (playback with the surface following
//! the pose, a slider dragged) the frames come first: each request is computed coarser
//! still ([`MOVING_COLUMNS`]), on one thread, and the next not before [`REST_AFTER_MOVING`] times as long as
//! the last took has passed, so the surface's work takes at most a quarter of one core
//! from the drawing (on a software rasteriser, the drawing is the CPU's too). Once the
//! request stays the same from one frame to the next, it is refined with every core.

use std::sync::Arc;
use std::sync::atomic::Ordering;
use std::time::{Duration, Instant};

use nalgebra::Vector3;
use stewart_kinematics::analysis::workspace;
use stewart_kinematics::analysis::workspace::{Plane, WorkspaceControl, WorkspaceSurface};
use stewart_kinematics::{Angle, Geometry, Pose, model::limits::Limits};
use stewart_render::analysis::AnalysisMesh;

use crate::viewer::error::ViewerError;
use crate::viewer::tools::job::Job;

/// Columns a side of the first, coarse workspace.
pub(crate) const COARSE_COLUMNS: usize = 128;
/// Columns a side of the refinement.
pub(crate) const FINE_COLUMNS: usize = 512;
/// Columns a side of a workspace computed while its request changes every frame: a
/// quarter of the coarse one's cells (each surface drawn every frame costs its triangles
/// on a software rasteriser; the refinement follows once the request stays).
pub(crate) const MOVING_COLUMNS: usize = 64;
/// Columns a side of the surface mesh drawn at most (every other column of the
/// refinement).
pub(crate) const DRAWN_COLUMNS: usize = 256;

/// While moving, the pause after a computation, as a multiple of the time it took.
pub(crate) const REST_AFTER_MOVING: u32 = 3;

/// Cells a side of the conditioning slice with a workspace of `columns` a side: 40 with
/// the coarse pass, 160 with the refinement (each cell needs a Jacobian's singular values,
/// a column only six square roots).
fn slice_cells(columns: usize) -> usize {
    (columns * 5 / 16).clamp(8, 160)
}

/// What a surface is computed for.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Request {
    /// The platform.
    pub(crate) geometry: Geometry,
    /// Its limits.
    pub(crate) limits: Limits,
    /// Roll, pitch, yaw.
    pub(crate) orientation: [Angle; 3],
    /// The slice's height, metres (`None`: no slice).
    pub(crate) slice_at: Option<f64>,
    /// The near-singular threshold the slice is coloured to.
    pub(crate) condition_max: f64,
    /// Colour the slice by the platform's lowest stiffness for this actuator stiffness
    /// instead of the conditioning.
    pub(crate) slice_stiffness: Option<f64>,
    /// Linear colour of the surface.
    pub(crate) colour: [f32; 4],
}

/// One finished computation: the workspace's numbers and the meshes to draw.
#[derive(Clone, Debug)]
pub(crate) struct Outcome {
    /// What it was computed for.
    pub(crate) request: Request,
    /// Columns a side.
    pub(crate) resolution: usize,
    /// Volume and its error bound, m³.
    pub(crate) volume: f64,
    /// Error bound of `volume`, m³.
    pub(crate) volume_error: f64,
    /// `[[x_min, x_max], [y_min, y_max], [z_min, z_max]]`, `None` when nothing is reachable.
    pub(crate) extent: Option<[[f64; 2]; 3]>,
    /// Columns whose reachable heights split (drawn with their gaps as cavities).
    pub(crate) split_columns: usize,
    /// The surface.
    pub(crate) surface: Arc<AnalysisMesh>,
    /// The slice, when asked for.
    pub(crate) slice: Option<SliceOutcome>,
    /// Time the computation took.
    pub(crate) elapsed: Duration,
    /// Whether this is the refinement (else the coarse first look).
    pub(crate) refined: bool,
    /// The threads it was computed on.
    pub(crate) threads: usize,
}

/// A request as sent to the job: refined after its coarse result, or (while the request
/// changes every frame) coarse only, on one thread.
#[derive(Clone, Debug, PartialEq)]
struct Sent {
    request: Request,
    refine: bool,
}

/// The conditioning slice's mesh and its counts.
#[derive(Clone, Debug)]
pub(crate) struct SliceOutcome {
    /// The coloured cells.
    pub(crate) mesh: Arc<AnalysisMesh>,
    /// Reachable cells.
    pub(crate) reachable: usize,
    /// Reachable cells past the near-singular threshold (or singular); none for a
    /// stiffness slice.
    pub(crate) past: usize,
    /// A stiffness slice's lowest and highest stiffness, N/m (`None`: conditioning).
    pub(crate) stiffness: Option<[f64; 2]>,
}

/// The Workspace panel's switches, the worker and the newest result.
pub struct WorkspaceTool {
    /// Draw the surface in the 3D view.
    pub show: bool,
    /// Use the pose's own orientation (else `orientation_deg`).
    pub(crate) follow_pose: bool,
    /// The chosen roll, pitch, yaw, degrees.
    pub(crate) orientation_deg: [f64; 3],
    /// Draw the conditioning slice.
    pub(crate) show_slice: bool,
    /// Colour the slice by stiffness (else by conditioning).
    pub(crate) slice_by_stiffness: bool,
    /// Put the slice at the platform centre's height (else `slice_height`).
    pub(crate) slice_follows: bool,
    /// The chosen slice height, metres.
    pub(crate) slice_height: f64,
    /// The newest finished result.
    pub(crate) latest: Option<Outcome>,
    /// Why the last request could not be computed.
    pub(crate) error: Option<ViewerError>,
    /// The request last sent.
    sent: Option<Sent>,
    /// A newer request waiting for the one in flight to give its first (coarse) result: a
    /// pose that moves every frame (playback on a slow machine) would otherwise cancel
    /// every computation before it gave anything. While moving, it also waits for the
    /// rest after the last computation.
    pending: Option<Sent>,
    /// The request asked for at the last frame (one that differs is moving).
    asked: Option<Request>,
    /// While moving, no computation starts before this.
    rest_until: Option<Instant>,
    /// The one-thread pool moving requests are computed on (made at the first).
    one_thread: Option<Arc<rayon::ThreadPool>>,
    job: Job<Result<Outcome, ViewerError>>,
    resolutions: [usize; 2],
    /// The certified bracket, asked for with a button.
    pub(crate) certified: super::certified::CertifiedTool,
}

impl Default for WorkspaceTool {
    fn default() -> Self {
        Self::with_resolutions(COARSE_COLUMNS, FINE_COLUMNS)
    }
}

impl WorkspaceTool {
    /// The orientation the workspace is shown at when `pose` is shown: the pose's, or the
    /// one chosen.
    pub(crate) fn orientation_at(&self, pose: &Pose) -> [Angle; 3] {
        if self.follow_pose {
            [pose.roll, pose.pitch, pose.yaw]
        } else {
            self.orientation_deg.map(Angle::from_degrees)
        }
    }

    /// A tool computing `coarse` then `fine` columns a side (tests choose slow ones).
    pub(crate) fn with_resolutions(coarse: usize, fine: usize) -> Self {
        Self {
            show: false,
            follow_pose: true,
            orientation_deg: [0.0; 3],
            show_slice: true,
            slice_by_stiffness: false,
            slice_follows: true,
            slice_height: 0.0,
            latest: None,
            error: None,
            sent: None,
            pending: None,
            asked: None,
            rest_until: None,
            one_thread: None,
            job: Job::new("workspace"),
            resolutions: [coarse, fine],
            certified: super::certified::CertifiedTool::default(),
        }
    }

    /// Ask for `request` (once a frame while the surface is shown) unless it was the last
    /// one asked: a refinement in flight for an older request stops, and the job takes
    /// this one next; a request whose first result has not come yet is finished first
    /// (this one waits, replaced by any newer). A request other than the last frame's is
    /// moving: coarse only, on one thread, after the rest (see the module docs); one
    /// asked again at the next frame is refined. Never blocks.
    pub(crate) fn request(&mut self, request: Request) {
        let moving = self.asked.as_ref() != Some(&request);
        self.asked = Some(request.clone());
        let wanted = Sent {
            request,
            refine: !moving,
        };
        if self
            .sent
            .as_ref()
            .is_some_and(|s| s.request == wanted.request && (s.refine || !wanted.refine))
        {
            self.pending = None;
            return;
        }
        self.pending = Some(wanted);
        self.start_pending();
    }

    /// Start the request waiting when the job may take it: the one in flight has given
    /// its first result (or nothing runs) and, for a moving request, the rest is over.
    fn start_pending(&mut self) {
        let Some(wanted) = &self.pending else {
            return;
        };
        if self.job.busy() && !self.first_result_in() && self.error.is_none() {
            return;
        }
        if !wanted.refine && self.rest_until.is_some_and(|at| Instant::now() < at) {
            return;
        }
        if let Some(next) = self.pending.take() {
            self.start(next);
        }
    }

    /// Whether the request in flight has given its first (coarse) result.
    fn first_result_in(&self) -> bool {
        self.latest
            .as_ref()
            .is_some_and(|o| self.sent.as_ref().is_some_and(|s| s.request == o.request))
    }

    /// Whether the surface shown was computed for another request than the newest (the
    /// pose moved on while it was computed).
    pub(crate) fn stale(&self) -> bool {
        let newest = self.pending.as_ref().or(self.sent.as_ref());
        self.latest
            .as_ref()
            .is_some_and(|o| newest.is_none_or(|s| s.request != o.request))
    }

    /// Start computing `sent`: coarse then refined, or coarse only on one thread.
    fn start(&mut self, sent: Sent) {
        let [coarse, fine] = self.resolutions;
        // A refinement of what is already shown coarse starts at the refinement.
        let coarse_in = (self.latest.as_ref())
            .is_some_and(|o| o.request == sent.request && o.resolution == coarse.min(fine));
        let passes: Vec<usize> = match (sent.refine, coarse_in) {
            (false, _) => vec![MOVING_COLUMNS.min(coarse).min(fine)],
            (true, true) => vec![fine],
            (true, false) => vec![coarse.min(fine), fine],
        };
        let pool = if sent.refine {
            None
        } else {
            self.one_thread_pool()
        };
        let (request, refine) = (sent.request.clone(), sent.refine);
        self.sent = Some(sent);
        self.job.start(move |worker| {
            for resolution in passes {
                if worker.cancelled() {
                    return;
                }
                let control = WorkspaceControl::stopped_by(worker.cancel_flag());
                let run = || compute(&request, resolution, slice_cells(resolution), &control);
                let result = match &pool {
                    Some(pool) => pool.install(run),
                    None => run(),
                };
                match result {
                    Ok(mut outcome) => {
                        outcome.refined = refine && resolution == fine;
                        if !worker.send(Ok(outcome)) {
                            return;
                        }
                    }
                    // Cancelled: a newer request replaced this one.
                    Err(None) => return,
                    Err(Some(e)) => {
                        worker.send(Err(e));
                        return;
                    }
                }
            }
        });
    }

    /// The one-thread pool for moving requests (`None`, all cores, if it cannot be made).
    fn one_thread_pool(&mut self) -> Option<Arc<rayon::ThreadPool>> {
        if self.one_thread.is_none() {
            self.one_thread = rayon::ThreadPoolBuilder::new()
                .num_threads(1)
                .thread_name(|_| "workspace-moving".to_owned())
                .build()
                .ok()
                .map(Arc::new);
        }
        self.one_thread.clone()
    }

    /// Take the newest finished result (older ones that arrived meanwhile are skipped).
    pub(crate) fn poll(&mut self) {
        self.certified.poll();
        let mut rest_begun = false;
        match self.job.poll() {
            Some(Ok(Ok(outcome))) => {
                if outcome.threads == 1 {
                    self.rest_until =
                        Instant::now().checked_add(outcome.elapsed * REST_AFTER_MOVING);
                    rest_begun = true;
                }
                self.latest = Some(outcome);
                self.error = None;
            }
            Some(Ok(Err(e))) => self.error = Some(e),
            Some(Err(e)) => self.error = Some(e.into()),
            None => {}
        }
        // The request in flight gave its first result (or ended): the newest waiting one
        // goes next — a moving one not in the poll its rest began in, however short the
        // rest (a busy machine may stall this thread longer than the rest lasts).
        if rest_begun && self.pending.as_ref().is_some_and(|w| !w.refine) {
            return;
        }
        self.start_pending();
    }

    /// Whether the newest request is not yet refined.
    pub(crate) fn busy(&self) -> bool {
        self.pending.is_some()
            || self.sent.as_ref().is_some_and(|s| {
                !self
                    .latest
                    .as_ref()
                    .is_some_and(|o| o.refined && o.request == s.request)
            }) && self.error.is_none()
    }

    /// Wait until the newest request is refined (tests, screenshots), at most `limit`: the
    /// last asked for is asked again, as at a frame where it stayed the same.
    pub(crate) fn wait(&mut self, limit: Duration) {
        if let Some(asked) = self.asked.clone() {
            self.request(asked);
        }
        let start = Instant::now();
        while self.busy() && start.elapsed() < limit {
            self.poll();
            std::thread::sleep(Duration::from_millis(2));
        }
    }
    /// Computations stopped because a newer request came.
    #[cfg(test)]
    pub(crate) fn cancelled(&self) -> usize {
        self.job.replaced()
    }
}

/// The workspace, its surface and the slice for `request` at `resolution`; `Err(None)`
/// when cancelled.
pub(crate) fn compute(
    request: &Request,
    resolution: usize,
    slice_cells: usize,
    control: &WorkspaceControl,
) -> Result<Outcome, Option<ViewerError>> {
    use stewart_kinematics::analysis::workspace::WorkspaceError;
    let start = Instant::now();
    let ws = workspace::constant_orientation_workspace_with(
        &request.geometry,
        &request.limits,
        request.orientation,
        resolution,
        control,
    )
    .map_err(|e| match e {
        WorkspaceError::Cancelled => None,
        e => Some(e.into()),
    })?;
    // The mesh drawn has at most DRAWN_COLUMNS a side (lighter to upload and draw); the
    // numbers are the full grid's.
    let surface = WorkspaceSurface::from_workspace(&ws.every(resolution.div_ceil(DRAWN_COLUMNS)));
    let mesh = AnalysisMesh::surface(&surface, request.colour);
    let slice = match (request.slice_at, ws.extent) {
        (Some(at), Some([ex, ey, _])) => {
            if control.cancel.load(Ordering::Relaxed) {
                return Err(None);
            }
            // The workspace is of platform centres; poses place the platform's reference
            // point, which sits `shift` from the centre at this orientation.
            let [roll, pitch, yaw] = request.orientation;
            let level = Pose::new(Vector3::zeros(), roll, pitch, yaw);
            let shift = request.geometry.platform_centre(&level);
            // A square over the extent, two cells' margin around it.
            let half = 0.5 * (ex[1] - ex[0]).max(ey[1] - ey[0]) + 2.0 * ws.cell;
            let centre = [0.5 * (ex[0] + ex[1]), 0.5 * (ey[0] + ey[1])];
            let range = [0, 1].map(|k| [centre[k] - shift[k] - half, centre[k] - shift[k] + half]);
            let (g, limits, level) = (&request.geometry, &request.limits, at - shift.z);
            let (o, cells) = (request.orientation, [slice_cells; 2]);
            let cut = match request.slice_stiffness {
                Some(k) => workspace::stiffness_slice(
                    g,
                    limits,
                    o,
                    Plane::Horizontal,
                    level,
                    range,
                    cells,
                    k,
                ),
                None => {
                    workspace::workspace_slice(g, limits, o, Plane::Horizontal, level, range, cells)
                }
            };
            let stiffness = request.slice_stiffness.map(|_| {
                let values = cut.values.iter().flatten();
                [
                    values.clone().fold(f64::INFINITY, |a, &b| a.min(b)),
                    values.fold(f64::NEG_INFINITY, |a, &b| a.max(b)),
                ]
            });
            let mut mesh = match stiffness {
                Some(range) => AnalysisMesh::stiffness_slice(&cut, range, 0.85),
                None => AnalysisMesh::slice(&cut, request.condition_max, 0.85),
            };
            for v in &mut mesh.vertices {
                for k in 0..3 {
                    v.position[k] += shift[k] as f32;
                }
            }
            let reachable: Vec<f64> = cut.values.iter().flatten().copied().collect();
            let past = if stiffness.is_some() {
                0
            } else {
                reachable
                    .iter()
                    .filter(|&&k| {
                        stewart_render::colormap::condition_fraction(k, request.condition_max)
                            .is_none()
                    })
                    .count()
            };
            Some(SliceOutcome {
                mesh: Arc::new(mesh),
                reachable: reachable.len(),
                past,
                stiffness,
            })
        }
        _ => None,
    };
    Ok(Outcome {
        request: request.clone(),
        resolution,
        volume: ws.volume,
        volume_error: ws.volume_error,
        extent: ws.extent,
        split_columns: surface.split_columns,
        surface: Arc::new(mesh),
        slice,
        elapsed: start.elapsed(),
        refined: false,
        threads: rayon::current_num_threads(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::Scenario;

    fn request(preset: &str, yaw: f64) -> Request {
        let s = Scenario::preset(preset).unwrap_or_else(|e| panic!("{e}"));
        Request {
            geometry: s.geometry,
            limits: s.limits,
            orientation: [0.0, 0.0, yaw].map(Angle::from_degrees),
            slice_at: Some(0.8),
            condition_max: s.checks.condition_max,
            slice_stiffness: None,
            colour: [0.5, 0.5, 0.5, 0.3],
        }
    }

    #[test]
    fn coarse_comes_first_then_the_refinement_with_the_exact_volume() {
        let mut tool = WorkspaceTool::with_resolutions(32, 128);
        let r = request("paired", 0.0);
        tool.request(r.clone());
        tool.wait(Duration::from_secs(60));
        let o = tool.latest.as_ref().unwrap_or_else(|| panic!("no result"));
        assert!(o.refined && o.resolution == 128 && o.request == r);
        let ws =
            workspace::constant_orientation_workspace(&r.geometry, &r.limits, r.orientation, 128)
                .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(o.volume, ws.volume);
        assert_eq!(o.volume_error, ws.volume_error);
        let slice = o.slice.as_ref().unwrap_or_else(|| panic!("no slice"));
        assert!(slice.reachable > 100 && slice.past == 0, "{slice:?}");
        assert!(!o.surface.is_empty());
    }

    #[test]
    fn a_new_request_cancels_the_refinement_in_flight() {
        // A refinement slow enough (2048² columns) to be caught in flight.
        let mut tool = WorkspaceTool::with_resolutions(16, 2048);
        let first = request("paired", 0.0);
        tool.request(first.clone());
        let start = Instant::now();
        while tool.latest.is_none() && start.elapsed() < Duration::from_secs(30) {
            tool.poll();
            std::thread::sleep(Duration::from_millis(1));
        }
        assert!(
            tool.latest
                .as_ref()
                .is_some_and(|o| !o.refined && o.request == first)
        );
        // The first is asked again at the next frame: refined; the geometry changes while
        // that refinement runs.
        tool.request(first.clone());
        while !tool.job.busy() {
            tool.poll();
        }
        std::thread::sleep(Duration::from_millis(20));
        let second = request("seed", 10.0);
        tool.request(second.clone());
        let mut seen = Vec::new();
        let start = Instant::now();
        while tool.busy() && start.elapsed() < Duration::from_secs(120) {
            // The second stays: asked again at every frame.
            tool.request(second.clone());
            tool.poll();
            if let Some(o) = &tool.latest {
                seen.push((o.request == first, o.refined));
            }
            std::thread::sleep(Duration::from_millis(2));
        }
        let last = tool.latest.as_ref().unwrap_or_else(|| panic!("no result"));
        assert!(last.refined && last.request == second && last.resolution == 2048);
        assert!(
            !seen.contains(&(true, true)),
            "the first request's refinement was shown"
        );
        // The first's refinement, at least (a coarse pass that has just sent its result
        // may be counted too).
        assert!(tool.cancelled() >= 1);
        assert!(tool.error.is_none());
    }

    #[test]
    fn a_pose_moving_every_frame_still_gets_surfaces_and_they_say_they_are_behind() {
        // A coarse pass (256²) slower than the frames that ask for a new orientation each
        // time: every request used to cancel the one in flight, and nothing was ever shown.
        let mut tool = WorkspaceTool::with_resolutions(256, 512);
        let start = Instant::now();
        let mut yaw = 0.0;
        let mut results = 0;
        let mut last_shown = None;
        while start.elapsed() < Duration::from_secs(120) && results < 3 {
            yaw += 0.5;
            tool.request(request("paired", yaw));
            tool.poll();
            if let Some(o) = &tool.latest
                && last_shown.as_ref() != Some(&o.request)
            {
                last_shown = Some(o.request.clone());
                results += 1;
            }
            std::thread::sleep(Duration::from_millis(2));
        }
        assert!(results >= 3, "only {results} surfaces in two minutes");
        // The surface shown is for an orientation the pose has left.
        assert!(tool.stale());
        // Once the pose rests, the newest is computed and refined, and no longer stale.
        tool.wait(Duration::from_secs(120));
        let o = tool.latest.as_ref().unwrap_or_else(|| panic!("no result"));
        assert!(o.refined && o.request == request("paired", yaw));
        assert!(!tool.stale());
    }

    #[test]
    fn a_request_changing_every_frame_is_computed_coarse_on_one_thread_with_rests() {
        // Playback with the surface following the pose: the frames come first. Each
        // changing request is computed coarser still, on one thread, and the next waits
        // three times as long as the last took; once the request stays, it is refined on
        // every core.
        let mut tool = WorkspaceTool::with_resolutions(128, 256);
        let mut yaw = 0.0;
        let mut shown: Vec<Request> = Vec::new();
        let start = Instant::now();
        while shown.len() < 3 && start.elapsed() < Duration::from_secs(120) {
            yaw += 0.5;
            tool.request(request("paired", yaw));
            tool.poll();
            if let Some(o) = &tool.latest
                && shown.last() != Some(&o.request)
            {
                shown.push(o.request.clone());
                assert!(
                    !o.refined && o.resolution == MOVING_COLUMNS && o.threads == 1,
                    "{o:?}"
                );
                // The newest request waits for the rest, which begins with this result:
                // nothing newer was started in the poll that took it (the job's thread
                // may still be ending, so it is judged by what was sent, not by the job).
                assert!(tool.rest_until.is_some(), "no rest");
                assert_eq!(tool.sent.as_ref().map(|s| &s.request), Some(&o.request));
            }
            std::thread::sleep(Duration::from_millis(1));
        }
        assert_eq!(shown.len(), 3);
        // The pose rests: the same request at the next frame is refined on every core.
        tool.request(request("paired", yaw));
        tool.wait(Duration::from_secs(120));
        let o = tool.latest.as_ref().unwrap_or_else(|| panic!("no result"));
        assert!(o.refined && o.resolution == 256 && o.request == request("paired", yaw));
        assert_eq!(o.threads, rayon::current_num_threads());
    }

    #[test]
    fn the_same_request_twice_is_computed_once() {
        let mut tool = WorkspaceTool::with_resolutions(16, 32);
        let r = request("paired", 5.0);
        tool.request(r.clone());
        tool.wait(Duration::from_secs(30));
        let first = tool.latest.as_ref().map(|o| Arc::clone(&o.surface));
        tool.request(r);
        tool.poll();
        assert!(!tool.busy());
        let again = tool.latest.as_ref().map(|o| Arc::clone(&o.surface));
        assert!(first.zip(again).is_some_and(|(a, b)| Arc::ptr_eq(&a, &b)));
    }
}
