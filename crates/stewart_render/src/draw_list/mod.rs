//! From the kinematics' [`SceneFrame`] to GPU-ready instances, plates and lines.
//! Pure CPU work, tested without a GPU.

use glam::{Mat3, Mat4, Quat, Vec3};
use stewart_kinematics::model::scene::{LegStatus, SceneFrame, ServoFrame};

use stewart_kinematics::model::appearance::Part;

use crate::appearance::parts::PartSet;

mod appearance;
use crate::gpu_types::{LineVertex, MeshInstance};
use crate::mesh::Mesh;
use crate::plate_shape::plate_shape;
use crate::theme::{Theme, linear};
pub use appearance::{PartDetail, PartInstance, frame_matrix, frame_rotation};

/// What to show besides the platform itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Overlays {
    /// The ground grid.
    pub grid: bool,
    /// The base frame's axes at the origin.
    pub base_axes: bool,
    /// The platform's own axes at its centre.
    pub platform_axes: bool,
    /// The path traced by the platform centre.
    pub path: bool,
    /// Each actuator in its own colour (the plot's); off: all in the theme's leg colour.
    pub coloured_legs: bool,
    /// Numbered labels (L1…L6 for legs, S1…S6 for servos) beside the actuators.
    pub labels: bool,
    /// The labels' size against the usual (larger for a projector).
    pub label_scale: f32,
    /// Which of the CAD parts' meshes are drawn.
    pub part_detail: PartDetail,
}

impl Default for Overlays {
    fn default() -> Self {
        Self {
            grid: true,
            base_axes: true,
            platform_axes: false,
            path: true,
            coloured_legs: true,
            labels: true,
            label_scale: 1.0,
            part_detail: PartDetail::File,
        }
    }
}

/// Everything to draw, in world coordinates (f32).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct DrawList {
    /// Instances of the unit cylinder.
    pub cylinders: Vec<MeshInstance>,
    /// Instances of the unit sphere.
    pub spheres: Vec<MeshInstance>,
    /// Instances of the unit cone.
    pub cones: Vec<MeshInstance>,
    /// Instances of the unit box (servo bodies).
    pub boxes: Vec<MeshInstance>,
    /// Translucent plates: mesh (world coordinates), linear colour, centre (for sorting).
    pub plates: Vec<(Mesh, [f32; 4], Vec3)>,
    /// Line segments (pairs of vertices).
    pub lines: Vec<LineVertex>,
    /// Text drawn over the scene (leg labels, readouts), in screen space.
    pub texts: Vec<crate::text::TextItem>,
    /// Translucent analysis meshes (workspace surface, conditioning slice), drawn in this
    /// order after the opaque scene and the plates (a slice at the platform's height shows
    /// over it); a view keeps each on the GPU while the same `Arc`
    /// comes back.
    pub analysis: Vec<std::sync::Arc<crate::analysis::AnalysisMesh>>,
    /// CAD parts (`[appearance]`): each piece of each placed part, opaque, lit, seen from
    /// both sides; the renderer keeps each mesh on the GPU while the same `Arc` comes back.
    pub parts: Vec<PartInstance>,
}

/// An actuator body's radius, as a fraction of the larger plate's radius.
pub const BODY_RADIUS: f32 = 0.030;
/// A rod's radius, likewise.
pub const ROD_RADIUS: f32 = 0.017;
/// A joint ball's radius, likewise.
pub const JOINT_RADIUS: f32 = 0.040;
/// A plate's thickness, likewise.
pub const PLATE_THICKNESS: f32 = 0.025;

fn v3(v: &nalgebra::Vector3<f64>) -> Vec3 {
    Vec3::new(v.x as f32, v.y as f32, v.z as f32)
}

/// The length a linear leg's body is drawn: 92 % of the shortest leg (at most 90 % of the
/// leg now), or 55 % of the leg without a stroke.
pub fn body_length(min_length: Option<f64>, length: f32) -> f32 {
    min_length.map_or(0.55 * length, |m| (0.92 * m as f32).min(0.9 * length))
}

/// A unit cylinder or cone (along +z) placed from `from` to `to` with `radius`.
pub fn along(from: Vec3, to: Vec3, radius: f32, color: [f32; 4]) -> MeshInstance {
    let d = to - from;
    let length = d.length();
    let rotation = Quat::from_rotation_arc(Vec3::Z, d.normalize_or(Vec3::Z));
    let model = Mat4::from_scale_rotation_translation(
        Vec3::new(radius, radius, length.max(1e-6)),
        rotation,
        from,
    );
    MeshInstance {
        model: model.to_cols_array_2d(),
        color,
    }
}

/// Black or white, whichever reads on the sRGB colour `rgb` (by its relative luminance).
pub(crate) fn ink_on(rgb: [f32; 3]) -> crate::theme::Srgba {
    let lin = rgb.map(|c| c.powf(2.2));
    let luminance = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
    if luminance > 0.2 {
        [0.0, 0.0, 0.0, 1.0]
    } else {
        [1.0, 1.0, 1.0, 1.0]
    }
}

fn ball(at: Vec3, radius: f32, color: [f32; 4]) -> MeshInstance {
    let model = Mat4::from_scale_rotation_translation(Vec3::splat(radius), Quat::IDENTITY, at);
    MeshInstance {
        model: model.to_cols_array_2d(),
        color,
    }
}

/// How actuators are coloured.
pub(crate) struct LegColours<'a> {
    pub(crate) theme: &'a Theme,
    pub(crate) coloured: bool,
}

/// Which bodies keep their usual drawing (those without a CAD part).
#[derive(Clone, Copy)]
struct Drawn {
    base: bool,
    platform: bool,
    cylinder: bool,
    rod: bool,
    horn: bool,
}

impl Drawn {
    fn of(parts: &PartSet) -> Self {
        let usual = |part| parts.get(part).is_none();
        Self {
            base: usual(Part::Base),
            platform: usual(Part::Platform),
            cylinder: usual(Part::Cylinder),
            rod: usual(Part::Rod),
            horn: usual(Part::Horn),
        }
    }
}

impl LegColours<'_> {
    /// Body and rod of actuator `k` in `status`. Coloured: the body always in the
    /// actuator's own colour (so it can be told apart), the rod neutral or, near or over
    /// a limit, the warning colour. Single-coloured: the theme's colours, the warning
    /// colour on both.
    pub(crate) fn of(
        &self,
        k: usize,
        status: LegStatus,
    ) -> (crate::theme::Srgba, crate::theme::Srgba) {
        let (body, rod) = self.theme.leg_colours(status);
        if self.coloured {
            (crate::theme::series(k), rod)
        } else {
            (body, rod)
        }
    }

    /// Servo `k`'s horn in `status`: the servo's colour (coloured) or the theme's horn
    /// colour, the warning colour near or past the range.
    pub(crate) fn horn(&self, k: usize, status: LegStatus) -> crate::theme::Srgba {
        match (status, self.coloured) {
            (LegStatus::Normal, true) => crate::theme::series(k),
            (LegStatus::Normal, false) => self.theme.horn,
            // Near or past the range: the horn shows it.
            (_, _) => self.theme.leg_colours(status).0,
        }
    }
}

impl DrawList {
    /// Build the draw list of `frame` in `theme`, every part drawn as usual.
    pub fn build(frame: &SceneFrame, theme: &Theme, overlays: &Overlays) -> DrawList {
        Self::build_with_parts(frame, theme, overlays, &PartSet::none())
    }

    /// Build the draw list of `frame` in `theme`, the parts `parts` has meshes for drawn
    /// from them in place of the usual plate, body, rod or horn.
    pub fn build_with_parts(
        frame: &SceneFrame,
        theme: &Theme,
        overlays: &Overlays,
        parts: &PartSet,
    ) -> DrawList {
        let mut list = DrawList::default();
        let s = frame.base_radius.max(frame.platform_radius) as f32;
        let joint_radius = JOINT_RADIUS * s;
        let colours = LegColours {
            theme,
            coloured: overlays.coloured_legs,
        };
        let drawn = Drawn::of(parts);
        match &frame.servos {
            None => list.linear_legs(frame, &colours, s, drawn),
            Some(servos) => list.servos(frame, servos, &colours, s, drawn),
        }
        list.appearance_parts(frame, &colours, parts, overlays.part_detail);
        if overlays.labels {
            list.labels(frame, &colours, overlays.label_scale);
        }
        for p in &frame.platform_joints {
            list.spheres
                .push(ball(v3(p), joint_radius, linear(theme.joint)));
        }

        let rotation = Mat3::from_cols_array(&std::array::from_fn(|k| {
            frame.platform_rotation[(k % 3, k / 3)] as f32
        }));
        let centre = v3(&frame.platform_centre);
        list.add_plates(frame, theme, drawn, (centre, rotation), s);

        if overlays.base_axes {
            list.axes(Vec3::ZERO, Mat3::IDENTITY, 0.45 * s, 0.012 * s, theme);
        }
        if overlays.platform_axes {
            list.axes(centre, rotation, 0.30 * s, 0.009 * s, theme);
        }
        if overlays.grid {
            list.grid(1.6 * s, theme);
        }
        if overlays.path {
            list.add_path(frame, theme);
        }
        list
    }

    /// The plates the usual drawing shows (not those a CAD part replaces): the convex hull
    /// of the joints in each plate's z = 0 plane (the base's top face at z = 0), joints off
    /// that plane on posts; the platform's at `centre` turned by `rotation`.
    fn add_plates(
        &mut self,
        frame: &SceneFrame,
        theme: &Theme,
        drawn: Drawn,
        (centre, rotation): (Vec3, Mat3),
        s: f32,
    ) {
        let plate_thickness = PLATE_THICKNESS * s;
        for (origin, axes, joints, colour, usual) in [
            (
                Vec3::ZERO,
                Mat3::IDENTITY,
                &frame.base_joints,
                theme.base_plate,
                drawn.base,
            ),
            (
                centre,
                rotation,
                &frame.platform_joints,
                theme.platform,
                drawn.platform,
            ),
        ] {
            if !usual {
                continue;
            }
            let world: Vec<Vec3> = joints.iter().map(v3).collect();
            let shape = plate_shape(origin, axes, &world, plate_thickness);
            self.plates.push((
                Mesh::plate(shape.centre, shape.normal, &shape.corners, plate_thickness),
                linear(colour),
                origin,
            ));
            for (foot, joint) in shape.posts {
                self.cylinders.push(along(
                    foot,
                    joint,
                    0.6 * ROD_RADIUS * s,
                    linear([colour[0], colour[1], colour[2], 1.0]),
                ));
            }
        }
    }

    /// The traced path as line segments.
    fn add_path(&mut self, frame: &SceneFrame, theme: &Theme) {
        if frame.path.len() < 2 {
            return;
        }
        let c = linear(theme.path);
        for pair in frame.path.windows(2) {
            self.lines.push(LineVertex {
                position: v3(&pair[0]).to_array(),
                color: c,
            });
            self.lines.push(LineVertex {
                position: v3(&pair[1]).to_array(),
                color: c,
            });
        }
    }

    /// The platform as the controller measured it (`frame`: the scene at the pose its
    /// measured values give), drawn beside the commanded one as a ghost: a translucent
    /// plate in the theme's ghost colour and thin lines along its legs (rods for servos).
    pub fn ghost(&mut self, frame: &SceneFrame, theme: &Theme) {
        let s = frame.base_radius.max(frame.platform_radius) as f32;
        let rotation = Mat3::from_cols_array(&std::array::from_fn(|k| {
            frame.platform_rotation[(k % 3, k / 3)] as f32
        }));
        let centre = v3(&frame.platform_centre);
        let world: Vec<Vec3> = frame.platform_joints.iter().map(v3).collect();
        let thickness = 0.02 * s;
        let shape = plate_shape(centre, rotation, &world, thickness);
        self.plates.push((
            Mesh::plate(shape.centre, shape.normal, &shape.corners, thickness),
            linear(theme.ghost),
            centre,
        ));
        let c = linear(theme.ghost);
        let line = [c[0], c[1], c[2], 1.0];
        for leg in &frame.legs {
            for p in [&leg.base, &leg.top] {
                self.lines.push(LineVertex {
                    position: v3(p).to_array(),
                    color: line,
                });
            }
        }
    }

    /// Linear legs: an actuator body from the base joint and a thinner rod from the
    /// platform joint; the body is as long as the shortest leg (or 55 % of the leg).
    /// `s` is the size of the larger plate.
    fn linear_legs(&mut self, frame: &SceneFrame, colours: &LegColours, s: f32, drawn: Drawn) {
        let theme = colours.theme;
        for (k, leg) in frame.legs.iter().enumerate() {
            let (base, top) = (v3(&leg.base), v3(&leg.top));
            let length = leg.length as f32;
            let dir = (top - base).normalize_or(Vec3::Z);
            let body_length = body_length(leg.min_length, length);
            let (body, rod) = colours.of(k, leg.status);
            if drawn.cylinder {
                self.cylinders.push(along(
                    base,
                    base + dir * body_length,
                    BODY_RADIUS * s,
                    linear(body),
                ));
            }
            if drawn.rod {
                self.cylinders.push(along(
                    base + dir * (body_length - 0.02 * s),
                    top,
                    ROD_RADIUS * s,
                    linear(rod),
                ));
            }
        }
        for p in &frame.base_joints {
            self.spheres
                .push(ball(v3(p), JOINT_RADIUS * s, linear(theme.joint)));
        }
    }

    /// Rotary servos: a servo body (box) beside each shaft on the side facing the base
    /// centre, a short shaft, the horn (thick, in the horn colour) from shaft to tip, a
    /// ball joint on the tip and the thin rod to the platform joint. Body, horn and rod
    /// take the warning colours when the servo is near or past its range.
    fn servos(
        &mut self,
        frame: &SceneFrame,
        servos: &[ServoFrame; 6],
        colours: &LegColours,
        s: f32,
        drawn: Drawn,
    ) {
        let theme = colours.theme;
        for (k, (servo, leg)) in servos.iter().zip(&frame.legs).enumerate() {
            let shaft = v3(&servo.shaft);
            let tip = v3(&servo.horn_tip);
            let horn = (tip - shaft).length().max(1e-6);
            let axis = v3(&servo.axis).normalize_or(Vec3::Y);
            let side = if (-shaft).dot(axis) >= 0.0 {
                axis
            } else {
                -axis
            };
            let (body, rod) = colours.of(k, servo.status);
            let horn_colour = colours.horn(k, servo.status);
            // The body: 1.3 horns long along the horn's zero direction, 1.1 high, 0.6
            // deep along the shaft, the shaft near its front end.
            let forward = Vec3::Z.cross(side);
            let gap = 0.18 * horn;
            let origin = shaft + side * gap - forward * (0.35 * horn) - Vec3::Z * (0.15 * horn);
            let model = Mat4::from_cols(
                (forward * 1.3 * horn).extend(0.0),
                (Vec3::Z * 1.1 * horn).extend(0.0),
                (side * 0.6 * horn).extend(0.0),
                origin.extend(1.0),
            );
            self.boxes.push(MeshInstance {
                model: model.to_cols_array_2d(),
                color: linear(body),
            });
            self.cylinders.push(along(
                shaft - side * (0.06 * horn),
                shaft + side * gap,
                0.10 * horn,
                linear(theme.joint),
            ));
            if drawn.horn {
                self.cylinders
                    .push(along(shaft, tip, 0.13 * horn, linear(horn_colour)));
            }
            if drawn.rod {
                self.cylinders
                    .push(along(tip, v3(&leg.top), ROD_RADIUS * s, linear(rod)));
            }
            self.spheres
                .push(ball(tip, 0.16 * horn, linear(theme.joint)));
        }
    }

    /// "L1"…"L6" (or "S1"…"S6") beside each actuator's middle, `scale` times the usual
    /// size: on a box of the leg's colour in black or white ink, whichever reads on it
    /// (a yellow label reads on a white background too), or with single-coloured legs in
    /// the joint colour on a box of the background's.
    fn labels(&mut self, frame: &SceneFrame, colours: &LegColours, scale: f32) {
        let letter = if frame.servos.is_some() { 'S' } else { 'L' };
        for (k, leg) in frame.legs.iter().enumerate() {
            let middle = v3(&(leg.base + (leg.top - leg.base) * 0.45));
            let (colour, background) = if colours.coloured {
                let [r, g, b, _] = crate::theme::series(k);
                (ink_on([r, g, b]), [r, g, b, 0.92])
            } else {
                let [r, g, b, _] = colours.theme.background;
                (colours.theme.joint, [r, g, b, 0.75])
            };
            self.texts.push(crate::text::TextItem {
                text: format!("{letter}{}", k + 1),
                anchor: crate::text::Anchor::World(middle, [0.6, 0.0]),
                align: [0.0, 0.5],
                size: crate::text::TextSize::OfView(0.034 * scale.clamp(0.5, 4.0)),
                colour,
                background: Some(background),
            });
        }
    }

    /// Three arrows (shaft and cone) along the columns of `axes`.
    fn axes(&mut self, origin: Vec3, axes: Mat3, length: f32, radius: f32, theme: &Theme) {
        for k in 0..3 {
            let dir = axes.col(k);
            let color = linear(theme.axes[k]);
            let shaft_end = origin + dir * (0.82 * length);
            self.cylinders.push(along(origin, shaft_end, radius, color));
            self.cones
                .push(along(shaft_end, origin + dir * length, 2.6 * radius, color));
        }
    }

    /// A square grid on z = 0 reaching `half` metres from the origin, lines every
    /// "nice" step (1, 2 or 5 × 10ⁿ) giving about ten cells per side.
    fn grid(&mut self, half: f32, theme: &Theme) {
        let step = crate::ticks::nice_step(f64::from(half) / 5.0) as f32;
        let n = (half / step).floor() as i32;
        let extent = n as f32 * step;
        let c = linear(theme.grid);
        for k in -n..=n {
            let t = k as f32 * step;
            for (a, b) in [
                ([t, -extent, 0.0], [t, extent, 0.0]),
                ([-extent, t, 0.0], [extent, t, 0.0]),
            ] {
                self.lines.push(LineVertex {
                    position: a,
                    color: c,
                });
                self.lines.push(LineVertex {
                    position: b,
                    color: c,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use stewart_kinematics::{Geometry, GeometryParams, model::geometry::StrokeLimits};

    #[test]
    fn legs_take_the_warning_colour_over_the_stroke() {
        let mut p = GeometryParams::seed();
        p.stroke = StrokeLimits::new(0.5, 0.97); // home legs are 0.98 m: all over
        let g = Geometry::new(p).unwrap_or_else(|e| panic!("{e}"));
        let list = DrawList::build(
            &g.scene_frame(&g.home_pose(), Vec::new()),
            &Theme::DARK,
            &Overlays::default(),
        );
        let warning = linear(Theme::DARK.leg_over_limit);
        // Coloured legs: the rods warn, the bodies keep each leg's colour.
        assert_eq!(
            list.cylinders.iter().filter(|c| c.color == warning).count(),
            6
        );
        // Single-coloured: body and rod both warn.
        let single = DrawList::build(
            &g.scene_frame(&g.home_pose(), Vec::new()),
            &Theme::DARK,
            &Overlays {
                coloured_legs: false,
                ..Overlays::default()
            },
        );
        assert_eq!(
            single
                .cylinders
                .iter()
                .filter(|c| c.color == warning)
                .count(),
            12
        );
        let g = Geometry::seed();
        let list = DrawList::build(
            &g.scene_frame(&g.home_pose(), Vec::new()),
            &Theme::DARK,
            &Overlays::default(),
        );
        assert_eq!(
            list.cylinders.iter().filter(|c| c.color == warning).count(),
            0
        );
    }

    #[test]
    fn leg_cylinders_span_base_to_platform_joint() {
        let g = Geometry::seed();
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        let list = DrawList::build(
            &frame,
            &Theme::LIGHT,
            &Overlays {
                grid: false,
                base_axes: false,
                platform_axes: false,
                path: false,
                coloured_legs: true,
                labels: true,
                label_scale: 1.0,
                part_detail: PartDetail::File,
            },
        );
        assert_eq!(list.cylinders.len(), 12);
        // One label per leg, in its colour.
        let labels: Vec<&str> = list.texts.iter().map(|t| t.text.as_str()).collect();
        assert_eq!(labels, ["L1", "L2", "L3", "L4", "L5", "L6"]);
        // Label k on a box of series colour k.
        let [r, g3, b, _] = crate::theme::series(2);
        assert_eq!(list.texts[2].background, Some([r, g3, b, 0.92]));
        // Coloured legs: body k in series colour k, rods neutral.
        for k in 0..6 {
            assert_eq!(list.cylinders[2 * k].color, linear(crate::theme::series(k)));
            assert_eq!(
                list.cylinders[2 * k + 1].color,
                linear(Theme::LIGHT.leg_rod)
            );
        }
        assert_eq!(list.spheres.len(), 12);
        assert!(list.lines.is_empty() && list.cones.is_empty());
        // The rod's far end (model · (0, 0, 1)) is the platform joint.
        let rod = Mat4::from_cols_array_2d(&list.cylinders[1].model);
        let end = rod.transform_point3(Vec3::Z);
        assert!((end - v3(&frame.platform_joints[0])).length() < 1e-5);
        let body = Mat4::from_cols_array_2d(&list.cylinders[0].model);
        assert!((body.transform_point3(Vec3::ZERO) - v3(&frame.base_joints[0])).length() < 1e-6);
    }

    #[test]
    fn servos_get_a_body_a_horn_from_shaft_to_tip_and_a_rod_to_the_joint() {
        let s =
            stewart_kinematics::Scenario::preset("servo-desk").unwrap_or_else(|e| panic!("{e}"));
        let g = &s.geometry;
        let frame = g.scene_frame(&g.home_pose(), Vec::new());
        let overlays = Overlays {
            grid: false,
            base_axes: false,
            platform_axes: false,
            path: false,
            coloured_legs: false,
            labels: false,
            label_scale: 1.0,
            part_detail: PartDetail::File,
        };
        let list = DrawList::build(&frame, &Theme::LIGHT, &overlays);
        let servos = frame.servos.unwrap_or_else(|| panic!("rotary scene"));
        assert_eq!(list.boxes.len(), 6);
        // Per servo: shaft stub, horn, rod; balls on the horn tips and platform joints.
        assert_eq!(list.cylinders.len(), 18);
        assert_eq!(list.spheres.len(), 12);
        let horn_colour = linear(Theme::LIGHT.horn);
        for (k, servo) in servos.iter().enumerate() {
            let horn = &list.cylinders[3 * k + 1];
            assert_eq!(horn.color, horn_colour);
            let m = Mat4::from_cols_array_2d(&horn.model);
            assert!((m.transform_point3(Vec3::ZERO) - v3(&servo.shaft)).length() < 1e-6);
            assert!((m.transform_point3(Vec3::Z) - v3(&servo.horn_tip)).length() < 1e-6);
            let rod = Mat4::from_cols_array_2d(&list.cylinders[3 * k + 2].model);
            let end = rod.transform_point3(Vec3::Z);
            assert!((end - v3(&frame.platform_joints[k])).length() < 1e-6);
            // The body sits beside the shaft, not on the horn's swing plane.
            let body = Mat4::from_cols_array_2d(&list.boxes[k].model);
            let centre = body.transform_point3(Vec3::new(0.0, 0.0, 0.5));
            let along_shaft = (centre - v3(&servo.shaft)).dot(v3(&servo.axis)).abs();
            assert!(along_shaft > 0.3 * 0.025, "{along_shaft}");
        }
    }
}
