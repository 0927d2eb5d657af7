//! Colour themes: a dark one for the screen, a light one for slides and papers.

use stewart_kinematics::model::scene::LegStatus;

/// An sRGB colour with alpha, components 0..1.
pub type Srgba = [f32; 4];

/// The six actuators' own colours (Okabe–Ito: told apart with colour-blindness and in grey
/// print), as sRGB bytes: the plot's curves, the 3D legs and the leg bars all use them, in
/// both themes.
pub const SERIES_RGB: [[u8; 3]; 6] = [
    [0x00, 0x72, 0xB2],
    [0xD5, 0x5E, 0x00],
    [0x00, 0x9E, 0x73],
    [0xCC, 0x79, 0xA7],
    [0xE6, 0x9F, 0x00],
    [0x56, 0xB4, 0xE9],
];

/// Actuator `k`'s colour (0–5, wrapping), opaque sRGB.
pub fn series(k: usize) -> Srgba {
    let [r, g, b] = SERIES_RGB[k % 6];
    [
        f32::from(r) / 255.0,
        f32::from(g) / 255.0,
        f32::from(b) / 255.0,
        1.0,
    ]
}

/// Every colour the renderer uses, in sRGB.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Theme {
    /// Background.
    pub background: Srgba,
    /// Ground grid lines.
    pub grid: Srgba,
    /// The fixed base plate (translucent).
    pub base_plate: Srgba,
    /// The moving platform (translucent).
    pub platform: Srgba,
    /// Actuator bodies.
    pub leg_body: Srgba,
    /// Actuator rods.
    pub leg_rod: Srgba,
    /// A leg within 5 % of a stroke end.
    pub leg_near_limit: Srgba,
    /// A leg over its stroke.
    pub leg_over_limit: Srgba,
    /// Servo horns of a rotary platform (rods take `leg_rod`, servo bodies `leg_body`).
    pub horn: Srgba,
    /// Joints.
    pub joint: Srgba,
    /// The path traced by the platform centre.
    pub path: Srgba,
    /// x, y, z axes.
    pub axes: [Srgba; 3],
    /// The reachable workspace's surface (translucent).
    pub workspace: Srgba,
    /// The platform as the controller measured it (translucent ghost).
    pub ghost: Srgba,
}

impl Theme {
    /// Dark background for the screen.
    pub const DARK: Theme = Theme {
        background: [0.11, 0.12, 0.14, 1.0],
        grid: [0.32, 0.34, 0.38, 1.0],
        base_plate: [0.55, 0.57, 0.60, 0.55],
        platform: [0.55, 0.40, 0.82, 0.70],
        leg_body: [0.25, 0.45, 0.85, 1.0],
        leg_rod: [0.75, 0.80, 0.88, 1.0],
        leg_near_limit: [1.0, 0.88, 0.0, 1.0],
        leg_over_limit: [0.93, 0.12, 0.12, 1.0],
        horn: [0.96, 0.96, 0.93, 1.0],
        joint: [0.90, 0.90, 0.92, 1.0],
        path: [0.35, 0.85, 0.95, 1.0],
        axes: [
            [0.90, 0.25, 0.25, 1.0],
            [0.30, 0.80, 0.30, 1.0],
            [0.30, 0.50, 0.95, 1.0],
        ],
        workspace: [0.40, 0.80, 0.95, 0.26],
        ghost: [0.55, 0.95, 0.55, 0.35],
    };

    /// White background, dark lines: for slides and papers.
    pub const LIGHT: Theme = Theme {
        background: [1.0, 1.0, 1.0, 1.0],
        grid: [0.78, 0.79, 0.81, 1.0],
        base_plate: [0.45, 0.47, 0.50, 0.45],
        platform: [0.45, 0.30, 0.75, 0.65],
        leg_body: [0.12, 0.30, 0.70, 1.0],
        leg_rod: [0.45, 0.50, 0.58, 1.0],
        leg_near_limit: [0.95, 0.80, 0.0, 1.0],
        leg_over_limit: [0.84, 0.08, 0.08, 1.0],
        horn: [0.15, 0.62, 0.52, 1.0],
        joint: [0.20, 0.20, 0.22, 1.0],
        path: [0.05, 0.55, 0.70, 1.0],
        axes: [
            [0.80, 0.10, 0.10, 1.0],
            [0.10, 0.60, 0.10, 1.0],
            [0.10, 0.30, 0.85, 1.0],
        ],
        workspace: [0.10, 0.45, 0.65, 0.26],
        ghost: [0.10, 0.60, 0.20, 0.35],
    };

    /// The colours of a leg in `status`: actuator body and rod (one warning colour for
    /// both when the leg is near or over its stroke). The 3D view, exported frames and
    /// the viewer's leg bars all take them from here.
    pub fn leg_colours(&self, status: LegStatus) -> (Srgba, Srgba) {
        match status {
            LegStatus::Normal => (self.leg_body, self.leg_rod),
            LegStatus::NearLimit => (self.leg_near_limit, self.leg_near_limit),
            LegStatus::OverLimit => (self.leg_over_limit, self.leg_over_limit),
        }
    }

    /// The light theme when `light`, else the dark one.
    pub fn from_light(light: bool) -> Theme {
        if light { Theme::LIGHT } else { Theme::DARK }
    }
}

/// sRGB component to linear.
pub fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// An sRGB colour to linear RGB, alpha kept.
pub fn linear(c: Srgba) -> [f32; 4] {
    [
        srgb_to_linear(c[0]),
        srgb_to_linear(c[1]),
        srgb_to_linear(c[2]),
        c[3],
    ]
}
