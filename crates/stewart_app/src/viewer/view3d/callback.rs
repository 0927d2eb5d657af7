//! The 3D view inside the egui layout: an `egui_wgpu` paint callback that draws with the
//! shared wgpu device through the renderer kept in the callback resources, one prepared
//! view per on-screen view (so a layout may show several).
//!
//! Drawn straight into the window's pass ([`Drawn::Direct`]: its background first, as
//! one flat triangle), or, where that pass has no MSAA (a software rasteriser, see
//! [`crate::viewer::view3d::quality`]), rendered off screen and drawn in as one picture: at full
//! quality ([`Drawn::Full`]) or at a lower scale while moving ([`Drawn::Scaled`]).

use std::collections::HashMap;

use stewart_render::{DrawList, OrbitCamera, Picture, PreparedView, Renderer, Theme, ViewFrame};

use crate::viewer::view3d::quality::Drawn;

/// Samples of the off-screen full picture.
const FULL_SAMPLES: u32 = 4;

/// What the window registers in egui-wgpu's callback resources: the renderer, and the
/// per-frame buffers of each view drawn with it.
pub(crate) struct SceneResources {
    renderer: Renderer,
    views: HashMap<egui::Id, PreparedView>,
    /// Where the window's pass has one sample: the renderer of the full picture and each
    /// view's buffers and picture.
    full: Option<FullPicture>,
}

/// The off-screen full picture's renderer, each view's buffers for it, and each view's
/// pictures (full, and scaled).
struct FullPicture {
    renderer: Renderer,
    views: HashMap<egui::Id, PreparedView>,
    pictures: HashMap<(egui::Id, Drawn), Picture>,
}

/// The picture of `key` sized `size` with `samples`, made anew when it does not fit.
fn picture_for<'a>(
    pictures: &'a mut HashMap<(egui::Id, Drawn), Picture>,
    key: (egui::Id, Drawn),
    device: &wgpu::Device,
    shown_by: &Renderer,
    size: [u32; 2],
    samples: u32,
) -> &'a Picture {
    let filtered = key.1 == Drawn::Scaled;
    let picture = pictures
        .entry(key)
        .or_insert_with(|| Picture::new(device, shown_by, size, samples, filtered));
    if !picture.fits(size, samples, filtered) {
        *picture = Picture::new(device, shown_by, size, samples, filtered);
    }
    picture
}

impl SceneResources {
    /// Resources around `renderer` (built for the window's pass), with no view prepared
    /// yet; a window pass of one sample also gets the full picture's renderer.
    pub(crate) fn new(device: &wgpu::Device, renderer: Renderer) -> Self {
        let full = (renderer.samples == 1).then(|| FullPicture {
            renderer: Renderer::new(device, renderer.format, FULL_SAMPLES),
            views: HashMap::new(),
            pictures: HashMap::new(),
        });
        Self {
            renderer,
            views: HashMap::new(),
            full,
        }
    }
}

/// One frame of one 3D view.
pub(crate) struct SceneCallback {
    /// Which view (its buffers are kept from frame to frame).
    pub(crate) view: egui::Id,
    /// What to draw.
    pub(crate) list: DrawList,
    /// Seen from here.
    pub(crate) camera: OrbitCamera,
    /// In these colours.
    pub(crate) theme: Theme,
    /// Size of the view, physical pixels (text is laid out in them).
    pub(crate) viewport: [f32; 2],
    /// How it is drawn this frame.
    pub(crate) drawn: Drawn,
}

impl egui_wgpu::CallbackTrait for SceneCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        let Some(SceneResources {
            renderer,
            views,
            full,
        }) = resources.get_mut::<SceneResources>()
        else {
            return Vec::new();
        };
        let drawn = if full.is_some() {
            self.drawn
        } else {
            Drawn::Direct
        };
        // The window's own view: drawn straight in, or the scaled picture rendered from it
        // at its size; its bind group is bound when a picture is drawn in.
        let scaled = self
            .viewport
            .map(|v| (v * crate::viewer::view3d::quality::SCALE).round().max(1.0));
        let viewport = if drawn == Drawn::Scaled {
            scaled
        } else {
            self.viewport
        };
        let view = views
            .entry(self.view)
            .or_insert_with(|| renderer.new_view(device));
        let scale = if drawn == Drawn::Scaled {
            crate::viewer::view3d::quality::SCALE
        } else {
            1.0
        };
        // The full picture is prepared by its own renderer below: the window's view then
        // only lends its bind group to the copy, and is not prepared a second time.
        if drawn != Drawn::Full {
            let frame = ViewFrame::new(&self.list, &self.camera, &self.theme, viewport);
            renderer.prepare(device, queue, view, &frame.scaled(scale));
        }
        let Some(full) = full else {
            return Vec::new();
        };
        let size = viewport.map(|v| v.round().max(1.0) as u32);
        match drawn {
            Drawn::Direct => {}
            Drawn::Scaled => {
                let key = (self.view, Drawn::Scaled);
                picture_for(&mut full.pictures, key, device, renderer, size, 1)
                    .render(renderer, view, encoder);
            }
            Drawn::Full => {
                let off = full
                    .views
                    .entry(self.view)
                    .or_insert_with(|| full.renderer.new_view(device));
                let frame = ViewFrame::new(&self.list, &self.camera, &self.theme, viewport);
                full.renderer.prepare(device, queue, off, &frame);
                let key = (self.view, Drawn::Full);
                picture_for(
                    &mut full.pictures,
                    key,
                    device,
                    renderer,
                    size,
                    FULL_SAMPLES,
                )
                .render(&full.renderer, off, encoder);
            }
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        let Some(r) = resources.get::<SceneResources>() else {
            return;
        };
        let Some(view) = r.views.get(&self.view) else {
            return;
        };
        let picture = r
            .full
            .as_ref()
            .filter(|_| self.drawn != Drawn::Direct)
            .and_then(|f| f.pictures.get(&(self.view, self.drawn)));
        match picture {
            Some(picture) => r.renderer.paint_picture(view, picture, pass),
            None => {
                r.renderer.paint_background(view, pass);
                r.renderer.paint(view, pass);
            }
        }
    }
}
