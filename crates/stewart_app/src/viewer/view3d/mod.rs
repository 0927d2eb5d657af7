//! The 3D view's services, below the state and the panels that use them and the window
//! shell that hosts them: its quality on a slow rasteriser ([`quality`]), the paint
//! callback that draws it inside egui's pass ([`callback`]), and screenshots of it
//! ([`shots`]).

pub(crate) mod callback;
pub(crate) mod quality;
pub(crate) mod shots;
