//! `Geometry`'s queries: every method the solve layer gives a geometry, in one place,
//! each handing over to the module that computes it (as parry groups its queries):
//! inverse kinematics, actuator values and their batches, Jacobians and conditioning,
//! servo angles, the scene frame, forward kinematics, assembly modes and sequences.

use nalgebra::{Matrix3, Matrix6, Vector3};

use crate::model::actuator::Quantity;
use crate::model::angle::Angle;
use crate::model::geometry::Geometry;
use crate::model::leg_solution::LegSolution;
use crate::model::pose::Pose;
use crate::model::rotary::Unreachable;
use crate::model::scene::SceneFrame;
use crate::solve::batch::{OutOfReach, RowError};
use crate::solve::chains::LegChain;
use crate::solve::forward::assembly::AssemblyModes;
use crate::solve::forward::sequence::{BranchChange, SequenceError, SequenceSolution};
use crate::solve::forward::{ForwardError, ForwardOptions, ForwardSolution};
use crate::solve::jacobian::Conditioning;

impl Geometry {
    /// Each leg as an open chain from its base joint at `pose` (see
    /// [`crate::solve::chains`]): a linear leg's universal joint and length, or a servo's
    /// angle and its rod's universal joint; refused where a servo cannot reach its joint.
    #[inline]
    pub fn leg_chains(&self, pose: &Pose) -> Result<[LegChain; 6], Unreachable> {
        crate::solve::chains::leg_chains(self, pose)
    }

    /// The far end of leg `k`'s `chain`, base frame, metres: the chain followed joint by
    /// joint (`None` for a chain of the other kind of actuator, or no leg `k`).
    #[inline]
    pub fn chain_tip(&self, k: usize, chain: &LegChain) -> Option<Vector3<f64>> {
        crate::solve::chains::chain_tip(self, k, chain)
    }

    /// The quantity that drives the joints: leg length or servo angle.
    #[inline]
    pub fn quantity(&self) -> Quantity {
        crate::solve::actuation::quantity(self)
    }

    /// The speed, acceleration and jerk limits of the actuator values (m/s… or °/s…),
    /// from `limits`' keys for this kind.
    #[inline]
    pub fn actuator_rate_limits(&self, limits: &crate::model::limits::Limits) -> [Option<f64>; 3] {
        crate::solve::actuation::actuator_rate_limits(self, limits)
    }

    /// Every assembly mode of actuator `values` (leg lengths in metres or servo angles in
    /// degrees): the poses that hold them.
    #[inline]
    pub fn actuator_assembly_modes(
        &self,
        values: &[f64; 6],
    ) -> Result<Vec<ForwardSolution>, ForwardError> {
        crate::solve::actuation::actuator_assembly_modes(self, values)
    }

    /// The map from a platform twist to the actuator rates: the legs' inverse Jacobian
    /// ([`Geometry::jacobian`]) or the servos' ([`Geometry::servo_jacobian`]), or the servo
    /// that cannot reach its joint.
    #[inline]
    pub fn actuator_jacobian(&self, pose: &Pose) -> Result<Matrix6<f64>, Unreachable> {
        crate::solve::actuation::actuator_jacobian(self, pose)
    }

    /// [`Geometry::actuator_jacobian`] and its conditioning, the Jacobian computed once
    /// (`None` when a servo cannot reach its joint).
    #[inline]
    pub fn actuator_jacobian_and_conditioning(
        &self,
        pose: &Pose,
    ) -> Option<(Matrix6<f64>, Conditioning)> {
        crate::solve::actuation::actuator_jacobian_and_conditioning(self, pose)
    }

    /// Conditioning of whatever drives the platform: the legs' ([`Geometry::conditioning`])
    /// or the servos' ([`Geometry::servo_conditioning`]; `None` when a servo cannot
    /// reach its joint).
    #[inline]
    pub fn actuated_conditioning(&self, pose: &Pose) -> Option<Conditioning> {
        crate::solve::actuation::actuated_conditioning(self, pose)
    }

    /// The limits of that quantity: the stroke (m) or the servo range (°), each end
    /// optional.
    #[inline]
    pub fn quantity_limits(&self) -> [Option<f64>; 2] {
        crate::solve::actuation::quantity_limits(self)
    }

    /// The quantity at one pose: leg lengths (m) or servo angles (°), or why a servo cannot
    /// reach its joint.
    #[inline]
    pub fn actuator_values_at(&self, pose: &Pose) -> Result<[f64; 6], Unreachable> {
        crate::solve::actuation::actuator_values_at(self, pose)
    }

    /// The pose whose actuator values are `values` (leg lengths in metres or servo angles
    /// in degrees): forward kinematics searched from `near` (the last pose known, or
    /// home), or why there is none.
    #[inline]
    pub fn pose_from_actuator_values(
        &self,
        values: &[f64; 6],
        near: &Pose,
    ) -> Result<Pose, ForwardError> {
        crate::solve::actuation::pose_from_actuator_values(self, values, near)
    }

    /// [`Geometry::pose_from_actuator_values`] with the forward solver's `options`.
    #[inline]
    pub fn pose_from_actuator_values_with(
        &self,
        values: &[f64; 6],
        near: &Pose,
        options: &ForwardOptions,
    ) -> Result<Pose, ForwardError> {
        crate::solve::actuation::pose_from_actuator_values_with(self, values, near, options)
    }

    /// The quantity at every pose, on all cores (leg lengths in metres or servo angles in
    /// degrees), or the earliest pose (its index) a servo cannot reach, and why.
    #[inline]
    pub fn actuator_values_batch(
        &self,
        poses: &[Pose],
    ) -> Result<Vec<[f64; 6]>, (usize, Unreachable)> {
        crate::solve::actuation::actuator_values_batch(self, poses)
    }

    /// The quantity at every pose, on all cores for legs: lengths in metres, or servo
    /// angles in degrees with NaN where a servo cannot reach its joint (a gap in a plot).
    #[inline]
    pub fn actuator_values(&self, poses: &[Pose]) -> Vec<[f64; 6]> {
        crate::solve::actuation::actuator_values(self, poses)
    }

    /// The scene for `pose`, with the platform-centre path `path` (already in metres).
    #[inline]
    pub fn scene_frame(&self, pose: &Pose, path: Vec<Vector3<f64>>) -> SceneFrame {
        crate::solve::scene_frame::scene_frame(self, pose, path)
    }

    /// Platform joints, leg vectors and lengths for `pose`.
    #[inline]
    pub fn inverse(&self, pose: &Pose) -> LegSolution {
        crate::solve::inverse::inverse(self, pose)
    }

    /// The six leg lengths for `pose`, metres.
    #[inline]
    pub fn leg_lengths(&self, pose: &Pose) -> [f64; 6] {
        crate::solve::inverse::leg_lengths(self, pose)
    }

    /// Platform joints in the base frame for a position and rotation matrix.
    #[inline]
    pub fn platform_joints_for(
        &self,
        position: &Vector3<f64>,
        rotation: &Matrix3<f64>,
    ) -> [Vector3<f64>; 6] {
        crate::solve::inverse::platform_joints_for(self, position, rotation)
    }

    /// Where the platform centre is in the base frame for `pose` (differs from
    /// `pose.position` only when the pivot is offset and the platform is rotated).
    #[inline]
    pub fn platform_centre(&self, pose: &Pose) -> Vector3<f64> {
        crate::solve::inverse::platform_centre(self, pose)
    }

    /// The home pose: level, centred, at the home height.
    #[inline]
    pub fn home_pose(&self) -> Pose {
        crate::solve::inverse::home_pose(self)
    }

    /// The 6×6 inverse Jacobian at `pose`: rows `[u_iᵀ, (r_i × u_i)ᵀ]` (see the module docs).
    #[inline]
    pub fn jacobian(&self, pose: &Pose) -> Matrix6<f64> {
        crate::solve::jacobian::jacobian(self, pose)
    }

    /// The first leg (from 0) whose two joints meet at `pose` (closer than a billionth of
    /// the platform's size): it has no direction, so the Jacobian, the leg forces and
    /// the stiffness there are undefined.
    #[inline]
    pub fn leg_without_direction(&self, pose: &Pose) -> Option<usize> {
        crate::solve::jacobian::leg_without_direction(self, pose)
    }

    /// The characteristic length used to normalise rotations: the root-mean-square
    /// distance of the platform joints from the platform frame's origin (the radius, for
    /// joints on a circle). A rotation by 1 rad then moves the joints by about as much as
    /// a translation by this length.
    #[inline]
    pub fn characteristic_length(&self) -> f64 {
        crate::solve::jacobian::characteristic_length(self)
    }

    /// The 6×6 map from a platform twist `(v, ω)` about the pivot point to the six servo
    /// rates (rad/s) of a rotary platform (`None` for linear legs), or the servo that
    /// cannot reach its joint. Differentiating the rod closure `|q_i − H_i(θ_i)|² = s²`
    /// with rod vector `d_i = q_i − H_i` and horn tip velocity per radian
    /// `h_i = ∂H_i/∂θ_i = a(−sin θ cos β, −sin θ sin β, cos θ)` gives the row
    /// `[d_iᵀ, (r_i × d_i)ᵀ] / (d_i · h_i)`. Where `d_i · h_i = 0` the rod pulls across the
    /// horn's motion and the servo loses control of it: that row is infinite, and the
    /// conditioning says singular.
    #[inline]
    pub fn servo_jacobian(&self, pose: &Pose) -> Option<Result<Matrix6<f64>, Unreachable>> {
        crate::solve::jacobian::servo_jacobian(self, pose)
    }

    /// Conditioning of a rotary platform at `pose` (`None` for linear legs, or when a
    /// servo cannot reach its joint): the singular values and weakest twist of the servo
    /// Jacobian with its rows scaled by the horn length (servo rates as horn-tip speeds,
    /// m/s per m/s) and its rotation columns by the characteristic length, as for legs.
    ///
    /// The condition number is the rods' own (the Jacobian with unit rows, as for legs)
    /// divided by the worst servo's transmission `|cos|` of the angle between its rod and
    /// its horn tip's motion (1: the rod pulls straight along it; 0: across it, at the edge
    /// of reach). Near the edge of reach a row grows without bound; when all six reach it
    /// together (pure heave of a symmetric platform) the rows grow alike and their ratio
    /// alone stays finite (12.3 for servo-desk at 141.70 mm), so the transmission is taken
    /// into account on its own, and the verdict becomes singular either way.
    #[inline]
    pub fn servo_conditioning(&self, pose: &Pose) -> Option<Conditioning> {
        crate::solve::jacobian::servo_conditioning(self, pose)
    }

    /// [`Geometry::servo_conditioning`] of a servo Jacobian already computed (`None` for
    /// linear legs).
    #[inline]
    pub fn servo_conditioning_of(&self, j: &Matrix6<f64>) -> Option<Conditioning> {
        crate::solve::jacobian::servo_conditioning_of(self, j)
    }

    /// Singular values, condition number and weakest twist of the normalised Jacobian.
    #[inline]
    pub fn conditioning(&self, pose: &Pose) -> Conditioning {
        crate::solve::jacobian::conditioning(self, pose)
    }

    /// The home height at which the servos stand level (mean servo angle zero) with the
    /// platform centred and level, for a rotary platform: where the horns have the most
    /// travel both ways. `None` for linear legs, or when no height between the base and
    /// `a + s` above it gets there. Found by a scan for the sign change of the mean
    /// angle, then bisection to the last bit.
    #[inline]
    pub fn servo_home_height(&self) -> Option<f64> {
        crate::solve::servo_angles::servo_home_height(self)
    }

    /// The six servo angles that hold `pose`, for a rotary platform (`None` for linear
    /// legs), or the first servo that cannot reach its joint.
    #[inline]
    pub fn servo_angles(&self, pose: &Pose) -> Option<Result<[Angle; 6], Unreachable>> {
        crate::solve::servo_angles::servo_angles(self, pose)
    }

    /// Servo angles (degrees) of many poses of a rotary platform, on all cores (`None`
    /// for linear legs); an unreachable pose is the error, with its index and servo
    /// (both from 0). The earliest such pose is reported.
    #[inline]
    pub fn servo_angles_batch(&self, poses: &[Pose]) -> Option<Result<Vec<[f64; 6]>, OutOfReach>> {
        crate::solve::batch::servo_angles_batch(self, poses)
    }

    /// Leg lengths of many poses, on all cores; allocates only the result.
    #[inline]
    pub fn leg_lengths_batch(&self, poses: &[Pose]) -> Vec<[f64; 6]> {
        crate::solve::batch::leg_lengths_batch(self, poses)
    }

    /// Actuator values — leg lengths (m), or servo angles (degrees) of a rotary platform —
    /// of pose rows `[x, y, z, roll, pitch, yaw]` (metres, degrees) into `out`, on all
    /// cores. Rows become poses a few hundred at a time inside each core's chunk (no pose
    /// table is built), with the bits [`Geometry::actuator_values_batch`] gives for the
    /// same poses. A value that is not finite, or outside the accepted range of poses
    /// ([`crate::ground::bounds::POSE_ROW`], as every pose table is checked), is refused (checked
    /// while the chunk is in cache: no pass of its own), and so is a row a servo cannot
    /// reach: the earliest such row is the error; `out` is then unspecified.
    ///
    /// # Panics
    /// If `out` is shorter than `rows` (a programming error, not a user error).
    #[inline]
    pub fn actuator_values_rows(
        &self,
        rows: &[[f64; 6]],
        out: &mut [[f64; 6]],
    ) -> Result<(), RowError> {
        crate::solve::batch::actuator_values_rows(self, rows, out)
    }

    /// Validate leg lengths against the stroke.
    #[inline]
    pub fn check_lengths(&self, lengths: &[f64; 6]) -> Result<(), ForwardError> {
        crate::solve::forward::check_lengths(self, lengths)
    }

    /// The pose with leg lengths `lengths`, searched from `start`.
    #[inline]
    pub fn forward(
        &self,
        lengths: &[f64; 6],
        start: &Pose,
        options: &ForwardOptions,
    ) -> Result<ForwardSolution, ForwardError> {
        crate::solve::forward::forward(self, lengths, start, options)
    }

    /// [`Geometry::forward`] without the stroke check (for searches that may pass through any length).
    #[inline]
    pub(crate) fn forward_unchecked(
        &self,
        lengths: &[f64; 6],
        start: &Pose,
        options: &ForwardOptions,
    ) -> Result<ForwardSolution, ForwardError> {
        crate::solve::forward::forward_unchecked(self, lengths, start, options)
    }

    /// The pose of a rotary platform whose servos stand at `angles`, searched from `start`:
    /// the horn tips are then fixed points and the rods legs of one length, so the same
    /// damped Newton method solves it (residual: each rod's closure, metres).
    #[inline]
    pub fn forward_servos(
        &self,
        angles: &[Angle; 6],
        start: &Pose,
        options: &ForwardOptions,
    ) -> Result<ForwardSolution, ForwardError> {
        crate::solve::forward::forward_servos(self, angles, start, options)
    }

    /// The horn tips of a rotary platform whose servos stand at `angles`, and the rod
    /// length: the fixed anchors and the leg length of its forward problem.
    #[inline]
    pub(crate) fn servo_anchors(
        &self,
        angles: &[Angle; 6],
    ) -> Result<([Vector3<f64>; 6], f64), ForwardError> {
        crate::solve::forward::servo_anchors(self, angles)
    }

    /// The damped Newton solve for legs from `anchors` of lengths `lengths`.
    #[inline]
    pub(crate) fn forward_from(
        &self,
        anchors: &[Vector3<f64>; 6],
        lengths: &[f64; 6],
        start: &Pose,
        options: &ForwardOptions,
    ) -> Result<ForwardSolution, ForwardError> {
        crate::solve::forward::forward_from(self, anchors, lengths, start, options)
    }

    /// Every real assembly for `lengths`, sorted by height (highest first). Fails like
    /// [`Geometry::forward`] for invalid lengths, and with [`ForwardError::NoRealPose`]
    /// when no real pose has these lengths.
    #[inline]
    pub fn assembly_modes(&self, lengths: &[f64; 6]) -> Result<Vec<ForwardSolution>, ForwardError> {
        crate::solve::forward::assembly::assembly_modes(self, lengths)
    }

    /// [`Geometry::assembly_modes`] with the count of complex solutions.
    #[inline]
    pub fn all_assembly_modes(&self, lengths: &[f64; 6]) -> Result<AssemblyModes, ForwardError> {
        crate::solve::forward::assembly::all_assembly_modes(self, lengths)
    }

    /// Every real assembly of a rotary platform whose servos stand at `angles` (the horn
    /// tips are then fixed and the rods legs of one length), sorted by height. Fails like
    /// [`Geometry::forward_servos`].
    #[inline]
    pub fn servo_assembly_modes(
        &self,
        angles: &[Angle; 6],
    ) -> Result<Vec<ForwardSolution>, ForwardError> {
        crate::solve::forward::assembly::servo_assembly_modes(self, angles)
    }

    /// Solve every row of `lengths`; each starts from the previous solution, or from the
    /// home pose when `cold`. Stops at the first row that fails.
    #[inline]
    pub fn forward_sequence(
        &self,
        lengths: &[[f64; 6]],
        cold: bool,
        options: &ForwardOptions,
    ) -> Result<SequenceSolution, SequenceError> {
        crate::solve::forward::sequence::forward_sequence(self, lengths, cold, options)
    }

    /// [`Geometry::forward_sequence`] with another first (and, when `cold`, every) start pose.
    #[inline]
    pub fn forward_sequence_from(
        &self,
        lengths: &[[f64; 6]],
        home: &Pose,
        cold: bool,
        options: &ForwardOptions,
    ) -> Result<SequenceSolution, SequenceError> {
        crate::solve::forward::sequence::forward_sequence_from(self, lengths, home, cold, options)
    }

    /// Where `det J` changes sign between consecutive solutions.
    #[inline]
    pub fn branch_changes(&self, solutions: &[ForwardSolution]) -> Vec<BranchChange> {
        crate::solve::forward::sequence::branch_changes(self, solutions)
    }
}
