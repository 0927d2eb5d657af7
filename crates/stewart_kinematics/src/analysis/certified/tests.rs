use super::free::{Search, free_ball, free_range, proven_free};
use super::pose_box::{BoxLegs, PoseBox};
use super::regular::{naive_regular, proven_regular};
use crate::io::scenario::Scenario;
use crate::model::angle::Angle;
use crate::model::pose::Pose;

fn preset(name: &str) -> Scenario {
    Scenario::preset(name).unwrap_or_else(|e| panic!("{name}: {e}"))
}

fn never() -> bool {
    false
}

const SEARCH: Search = Search {
    budget: 20_000,
    stop: &never,
};

/// A xorshift stream from `seed`: numbers in [0, 1], the same on every run.
fn uniform(mut seed: u32) -> impl FnMut() -> f64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        f64::from(seed) / f64::from(u32::MAX)
    }
}

/// Poses about home: `n` of them, up to a fifth of the platform's size away and 20°
/// (60° in yaw) turned.
fn poses_about_home(s: &Scenario, n: usize) -> Vec<Pose> {
    let g = &s.geometry;
    let size = g.characteristic_length();
    let mut unit = uniform(0x1234_5678_u32);
    let mut next = || 2.0 * unit() - 1.0;
    (0..n)
        .map(|_| {
            let p = g.home_pose().position
                + nalgebra::Vector3::new(next(), next(), next()) * 0.3 * size;
            let [r, p2, y] = [20.0 * next(), 20.0 * next(), 60.0 * next()].map(Angle::from_degrees);
            Pose::new(p, r, p2, y)
        })
        .collect()
}

#[test]
fn the_seeds_layout_is_singular_everywhere_and_nothing_of_it_is_ever_certified() {
    let s = preset("seed");
    let g = &s.geometry;
    let home = g.home_pose();
    for k in 0..6 {
        assert_eq!(
            free_range(g, &home, k, 0.5, SEARCH).interval,
            None,
            "coordinate {k}"
        );
    }
    assert_eq!(free_ball(g, &home, 0.5, SEARCH).radius, None);
    // Every pose of the seed is singular (its joints lie on conics in projective
    // correspondence). Without outward rounding the test would "prove" many of them
    // regular: rounding alone lifts the Jacobian's zero singular value to about 1e-16.
    let poses = poses_about_home(&s, 3000);
    let naive = poses
        .iter()
        .filter(|p| {
            naive_regular(&BoxLegs::of(g, &PoseBox::at(p)).jacobian(g.characteristic_length()))
        })
        .count();
    let proven = poses
        .iter()
        .filter(|p| proven_free(g, &PoseBox::at(p)))
        .count();
    assert!(
        naive > 100,
        "rounded to nearest, {naive} of 3000 singular poses pass"
    );
    assert_eq!(proven, 0, "rounded outward, none may");
}

#[test]
fn a_planar_platform_turned_against_its_base_is_certified_up_to_fichters_torsion_singularity() {
    // The paired layout: joints in pairs on two parallel planes (semi-regular hexagons),
    // the platform's turned 60° against the base's. Fichter (1986): singular at a torsion
    // of ±90° about the vertical, at any height.
    let s = preset("paired");
    let g = &s.geometry;
    let home = g.home_pose();
    let yaw = free_range(g, &home, 5, std::f64::consts::PI, SEARCH);
    let [lo, hi] = yaw.interval.expect("home is regular").map(f64::to_degrees);
    assert!(
        (-90.0..=-89.0).contains(&lo) && (89.0..=90.0).contains(&hi),
        "{lo}° … {hi}°"
    );
    assert!(!yaw.cut_short);
    // The whole working range lies inside.
    let samples = s.motion.sample();
    for p in &samples.poses {
        assert!((lo..=hi).contains(&p.yaw.degrees()), "{p:?}");
        assert!(proven_free(g, &PoseBox::at(p)), "{p:?}");
    }
    // Past ±90°: the determinant changes sign there (a second method, sampled).
    let det = |deg: f64| {
        let pose = Pose::new(
            home.position,
            Angle::ZERO,
            Angle::ZERO,
            Angle::from_degrees(deg),
        );
        let j = BoxLegs::of(g, &PoseBox::at(&pose)).jacobian(1.0);
        nalgebra::Matrix6::from_fn(|r, c| j[r][c].mid()).determinant()
    };
    assert!(det(89.9) * det(90.1) < 0.0 && det(-89.9) * det(-90.1) < 0.0);
}

#[test]
fn inside_a_certified_range_every_sampled_pose_is_regular() {
    // The studio's own conditioning (for servos, the servo Jacobian's, which also turns
    // singular as a servo nears the edge of its reach) at 201 poses of each range, its
    // ends included.
    for name in ["paired", "dietmaier", "circle", "servo-desk", "crank-rig"] {
        let s = preset(name);
        let g = &s.geometry;
        let home = g.home_pose();
        for k in 0..6 {
            let reach = if k < 3 {
                g.characteristic_length()
            } else {
                std::f64::consts::PI
            };
            let Some([lo, hi]) = free_range(g, &home, k, reach, SEARCH).interval else {
                panic!("{name}: home regular");
            };
            for step in 0..=200 {
                let v = lo + (hi - lo) * f64::from(step) / 200.0;
                let mut c = home.to_coordinates();
                c[k] = v;
                let pose = Pose::from_coordinates(c);
                let cond = match g.servo_conditioning(&pose) {
                    Some(servo) => servo.condition_number,
                    None => g.conditioning(&pose).condition_number,
                };
                assert!(
                    cond.is_some_and(f64::is_finite),
                    "{name} coordinate {k} at {v}: {cond:?}"
                );
            }
        }
    }
}

#[test]
fn a_certified_ball_holds_only_regular_poses_and_grows_with_the_budget() {
    let s = preset("paired");
    let g = &s.geometry;
    let home = g.home_pose();
    let small = free_ball(
        g,
        &home,
        0.5,
        Search {
            budget: 2_000,
            stop: &never,
        },
    );
    let large = free_ball(
        g,
        &home,
        0.5,
        Search {
            budget: 40_000,
            stop: &never,
        },
    );
    let radius = |b: super::free::FreeBall| b.radius.expect("regular");
    let (r1, r2) = (radius(small), radius(large));
    assert!(r1 > 0.0 && r2 >= r1, "{r1} {r2}");
    // Every corner and face centre of the certified cube is regular, sampled.
    for corner in 0..27 {
        let d = nalgebra::Vector3::new(
            f64::from(corner % 3) - 1.0,
            f64::from(corner / 3 % 3) - 1.0,
            f64::from(corner / 9) - 1.0,
        ) * r2;
        let pose = home.with_position(home.position + d);
        assert!(g.conditioning(&pose).condition_number.is_some(), "{d:?}");
    }
}

#[test]
fn a_stop_request_ends_the_search_with_what_is_certified_so_far() {
    let s = preset("paired");
    let g = &s.geometry;
    let stop = || true;
    let r = free_range(
        g,
        &g.home_pose(),
        5,
        3.0,
        Search {
            budget: 1_000_000,
            stop: &stop,
        },
    );
    assert!(r.cut_short);
    assert_eq!(r.interval.map(|[lo, hi]| (lo, hi)), Some((0.0, 0.0)));
    let j = BoxLegs::of(g, &PoseBox::at(&g.home_pose())).jacobian(1.0);
    assert!(proven_regular(&j));
}

mod workspace {
    use super::*;
    use crate::analysis::certified::workspace::{BoxClass, WorkspaceRequest, certified_workspace};
    use crate::analysis::workspace::{constant_orientation_workspace, pose_within_limits};
    use crate::model::limits::Limits;

    fn bracket(
        s: &Scenario,
        limits: &Limits,
        width: f64,
    ) -> crate::analysis::certified::workspace::CertifiedWorkspace {
        let level = s.geometry.home_pose();
        let request = WorkspaceRequest {
            orientation: &level,
            boundary_width: width,
            budget: 5_000_000,
            stop: &never,
        };
        certified_workspace(&s.geometry, limits, &request).expect("both stroke limits")
    }

    #[test]
    fn the_grid_volume_lies_in_the_bracket_and_the_bracket_tightens() {
        // Linear legs, and rotary servos on both kinds of rig (the desk's servos in a
        // range; the crank rig's cranks).
        for name in ["paired", "servo-desk", "crank-rig"] {
            let s = preset(name);
            let size = s.geometry.characteristic_length();
            for limits in [Limits::default(), s.limits] {
                let grid =
                    constant_orientation_workspace(&s.geometry, &limits, [Angle::ZERO; 3], 400)
                        .expect("workspace");
                let mut last = f64::INFINITY;
                for width in [0.08, 0.04, 0.02] {
                    let w = bracket(&s, &limits, width * size);
                    assert!(!w.cut_short);
                    let (lo, hi) = (w.inner_m3, w.inner_m3 + w.boundary_m3);
                    assert!(
                        lo <= grid.volume + grid.volume_error
                            && grid.volume - grid.volume_error <= hi,
                        "{name}, width {width}: grid {} ± {} outside [{lo}, {hi}]",
                        grid.volume,
                        grid.volume_error
                    );
                    assert!(
                        w.boundary_m3 < last,
                        "{name}: {} then {}",
                        last,
                        w.boundary_m3
                    );
                    assert!(lo > 0.0, "{name}: nothing proven at width {width}");
                    last = w.boundary_m3;
                }
            }
        }
    }

    #[test]
    fn every_position_of_an_inner_box_is_reachable_and_none_outside_the_kept_boxes_is() {
        for name in ["paired", "servo-desk", "crank-rig"] {
            let s = preset(name);
            let size = s.geometry.characteristic_length();
            let w = bracket(&s, &s.limits, 0.03 * size);
            let level = s.geometry.home_pose();
            let mut unit = uniform(0x2545_f491_u32);
            let inside = |b: &[crate::ground::interval::Interval; 3],
                          p: &nalgebra::Vector3<f64>| {
                (0..3).all(|k| b[k].contains(p[k]))
            };
            let inner: Vec<_> = w
                .boxes
                .iter()
                .filter(|b| b.class == BoxClass::Inner)
                .collect();
            assert!(inner.len() > 100, "{name}: {}", inner.len());
            for b in inner.iter().step_by(inner.len() / 100) {
                for _ in 0..5 {
                    let p = nalgebra::Vector3::from_fn(|k, _| {
                        b.position[k].lo() + unit() * b.position[k].width()
                    });
                    assert!(
                        pose_within_limits(&s.geometry, &s.limits, &level.with_position(p)),
                        "{name}: {p:?}"
                    );
                }
            }
            // Positions in no kept box (outer boxes are dropped) are all unreachable.
            let (mut outside, mut reachable) = (0, 0);
            let centre = level.position;
            for _ in 0..20_000 {
                let p = centre
                    + nalgebra::Vector3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5)
                        * (2.0 * size);
                let within = pose_within_limits(&s.geometry, &s.limits, &level.with_position(p));
                reachable += usize::from(within);
                if w.boxes.iter().any(|b| inside(&b.position, &p)) {
                    continue;
                }
                outside += 1;
                assert!(!within, "{name}: {p:?}");
            }
            assert!(
                outside > 1000 && reachable > 500,
                "{name}: {outside} {reachable}"
            );
        }
    }

    #[test]
    fn the_clearance_bound_over_a_box_holds_every_position_inside_it() {
        // Random boxes of positions about the workspace, from a thousandth to a tenth of
        // the platform's size: the least distance between legs (rods, rods and horns) at
        // random positions inside, by the studio's own measure, lies within the bounds.
        use crate::analysis::certified::workspace::least_distance_bounds;
        use crate::analysis::checks::servos::rod_distances;
        use crate::ground::interval::Interval;
        use crate::model::limits::pair_distances;
        for name in ["servo-desk", "crank-rig", "paired"] {
            let s = preset(name);
            let g = &s.geometry;
            let home = g.home_pose();
            let size = g.characteristic_length();
            let least = |pose: &Pose| -> Option<f64> {
                let solution = g.inverse(pose);
                Some(match g.rotary() {
                    Some(servos) => {
                        let angles = g.servo_angles(pose)?.ok()?;
                        let tips = std::array::from_fn(|i| {
                            servos.horn_tip(i, &g.base_joints()[i], angles[i])
                        });
                        let (rods, horns) =
                            rod_distances(g.base_joints(), &solution.platform_joints, &tips);
                        rods.iter()
                            .chain(&horns)
                            .copied()
                            .fold(f64::INFINITY, f64::min)
                    }
                    None => pair_distances(&solution)
                        .into_iter()
                        .fold(f64::INFINITY, f64::min),
                })
            };
            let mut unit = uniform(0x6a09_e667_u32);
            let (mut bounded, mut tight) = (0, 0);
            for _ in 0..600 {
                let centre = home.position
                    + nalgebra::Vector3::new(unit() - 0.5, unit() - 0.5, unit() - 0.5) * size;
                let half = size * 10f64.powf(-3.0 + 2.0 * unit());
                let b: [Interval; 3] = std::array::from_fn(|k| Interval::around(centre[k], half));
                let Some((lo, hi)) = least_distance_bounds(g, &home, &b) else {
                    continue;
                };
                bounded += 1;
                tight += usize::from(hi - lo < 0.1 * size);
                for _ in 0..20 {
                    let p = nalgebra::Vector3::from_fn(|k, _| b[k].lo() + unit() * b[k].width());
                    if let Some(d) = least(&home.with_position(p)) {
                        assert!(lo <= d && d <= hi, "{name}: {d} not in [{lo}, {hi}]");
                    }
                }
            }
            assert!(bounded > 200 && tight > 50, "{name}: {bounded} {tight}");
        }
    }

    #[test]
    fn nothing_outside_the_kept_boxes_is_reachable_down_to_the_base_plane() {
        // The whole region searched, from the base plane (where a servo's joint may sit
        // level with its shaft: the angle's formula turns there) to the highest a joint
        // can be, with and without the limits.
        for name in ["servo-desk", "crank-rig", "paired"] {
            let s = preset(name);
            let g = &s.geometry;
            let home = g.home_pose();
            let top = match g.rotary() {
                Some(servos) => servos.horn_length() + servos.rod_length(),
                None => g.stroke().max.expect("stroke"),
            };
            for limits in [Limits::default(), s.limits] {
                let w = bracket(&s, &limits, 0.03 * g.characteristic_length());
                let mut unit = uniform(0x1b87_3593_u32);
                let reach = g.plate_radius(crate::model::geometry::Plate::Base) + top;
                let (mut outside, mut reachable) = (0, 0);
                for _ in 0..20_000 {
                    let p = nalgebra::Vector3::new(
                        (2.0 * unit() - 1.0) * reach,
                        (2.0 * unit() - 1.0) * reach,
                        unit() * top,
                    );
                    let within = pose_within_limits(g, &limits, &home.with_position(p));
                    reachable += usize::from(within);
                    if w.boxes
                        .iter()
                        .any(|b| (0..3).all(|k| b.position[k].contains(p[k])))
                    {
                        continue;
                    }
                    outside += 1;
                    assert!(!within, "{name}: {p:?}");
                }
                assert!(
                    outside > 10_000 && reachable > 20,
                    "{name}: {outside} {reachable}"
                );
            }
        }
    }

    #[test]
    fn a_spent_budget_counts_the_undecided_as_boundary() {
        let s = preset("paired");
        let level = s.geometry.home_pose();
        let request = WorkspaceRequest {
            orientation: &level,
            boundary_width: 0.001,
            budget: 10_000,
            stop: &never,
        };
        let w = certified_workspace(&s.geometry, &s.limits, &request).expect("stroke");
        assert!(w.cut_short);
        let grid = constant_orientation_workspace(&s.geometry, &s.limits, [Angle::ZERO; 3], 200)
            .expect("grid");
        assert!(w.inner_m3 <= grid.volume && grid.volume <= w.inner_m3 + w.boundary_m3);
        // Breadth first: even cut short, most of the volume is already proven.
        assert!(
            w.inner_m3 > 0.5 * grid.volume,
            "{} of {}",
            w.inner_m3,
            grid.volume
        );
    }
}

#[test]
fn servo_ranges_stop_just_short_of_where_the_sampled_servo_jacobian_first_fails() {
    // A second method: march out from home along each coordinate in 20 000 steps, with
    // the studio's own servo Jacobian, until its determinant changes sign or a servo no
    // longer reaches. The certified range must stop before that and not far short of it.
    for name in ["servo-desk", "crank-rig"] {
        let s = preset(name);
        let g = &s.geometry;
        let home = g.home_pose();
        let sign = |p: &Pose| -> Option<f64> {
            let d = g.servo_jacobian(p)?.ok()?.determinant();
            d.is_finite().then_some(d.signum())
        };
        let at_home = sign(&home);
        assert!(at_home.is_some(), "{name}");
        for k in 0..6 {
            let reach = if k < 3 {
                g.characteristic_length()
            } else {
                std::f64::consts::PI
            };
            let range = free_range(g, &home, k, reach, SEARCH);
            let certified = range.interval.expect("home is regular");
            assert!(!range.cut_short);
            let start = home.to_coordinates();
            let steps = 20_000;
            let step = reach / f64::from(steps);
            for (side, direction) in [-1.0, 1.0].into_iter().enumerate() {
                let first_failure = (1..=steps).map(f64::from).find_map(|i| {
                    let mut c = start;
                    c[k] += direction * i * step;
                    (sign(&Pose::from_coordinates(c)) != at_home).then_some(c[k])
                });
                let Some(edge) = first_failure else {
                    assert_eq!(certified[side], start[k] + direction * reach, "{name} {k}");
                    continue;
                };
                let (proven, sampled) =
                    ((certified[side] - start[k]).abs(), (edge - start[k]).abs());
                assert!(
                    proven < sampled,
                    "{name} {k}: proven {proven}, fails at {sampled}"
                );
                assert!(
                    sampled - proven < 2.0 * step + 1e-3 * sampled,
                    "{name} {k}: proven {proven}, fails at {sampled}"
                );
            }
        }
    }
}

#[test]
fn a_servos_bounds_over_a_box_hold_every_pose_inside_it() {
    use super::servos::{BoxServos, Reach};
    use crate::solve::servo_closure::servo_angle;
    for name in ["servo-desk", "crank-rig"] {
        let s = preset(name);
        let g = &s.geometry;
        let servos = g.rotary().expect("rotary");
        let size = g.characteristic_length();
        let mut unit = uniform(0x9e37_79b9_u32);
        let (mut every, mut none, mut undecided, mut bounded) = (0, 0, 0, 0);
        for centre in poses_about_home(&s, 400) {
            // Boxes from a thousandth to a tenth of the platform's size (and as many
            // hundredths of a radian) about the pose.
            let half = 10f64.powf(-3.0 + 2.0 * unit());
            let mut b = PoseBox::at(&centre);
            for k in 0..6 {
                let r = if k < 3 { half * size } else { half };
                b.coordinates[k] =
                    crate::ground::interval::Interval::around(b.coordinates[k].mid(), r);
            }
            let legs = BoxLegs::of(g, &b);
            let over = BoxServos::of(servos, g.base_joints(), &legs);
            for _ in 0..20 {
                let c: [f64; 6] = std::array::from_fn(|k| {
                    b.coordinates[k].lo() + unit() * b.coordinates[k].width()
                });
                let pose = Pose::from_coordinates(c);
                let joints = g.inverse(&pose).platform_joints;
                for (i, joint) in joints.iter().enumerate() {
                    let angle = servo_angle(servos, i, &g.base_joints()[i], joint);
                    match over.reach[i] {
                        Reach::Every => {
                            assert!(angle.is_ok(), "{name}: a box said reachable");
                            every += 1;
                        }
                        Reach::None => {
                            none += 1;
                            assert!(angle.is_err(), "{name}: reached in a box said unreachable");
                        }
                        Reach::Undecided => undecided += 1,
                    }
                    // Wherever the pose reaches, the servo's bounds hold it (also in a box
                    // that straddles the edge of reach).
                    if let (Ok(angle), Some(servo)) = (angle, over.servos[i]) {
                        let theta = angle.radians();
                        assert!(servo.angle.contains(theta), "{name}: {theta}");
                        let tip = servos.horn_tip(i, &g.base_joints()[i], angle);
                        for k in 0..3 {
                            assert!(servo.tip[k].contains(tip[k]));
                            assert!(servo.rod[k].contains(joint[k] - tip[k]));
                        }
                        bounded += 1;
                    }
                }
            }
        }
        assert!(
            every > 10_000 && none > 100 && undecided > 100 && bounded > 10_000,
            "{name}: {every} {none} {undecided} {bounded}"
        );
    }
}
