//! The 3D view inside the egui layout: an `egui_wgpu` paint callback that draws with the
//! shared wgpu device through the renderer kept in the callback resources, one prepared
//! view per on-screen view (so a layout may show several).

use std::collections::HashMap;

use stewart_render::{DrawList, OrbitCamera, PreparedView, Renderer, Theme};

/// What the window registers in egui-wgpu's callback resources: the renderer, and the
/// per-frame buffers of each view drawn with it.
pub struct SceneResources {
    renderer: Renderer,
    views: HashMap<egui::Id, PreparedView>,
}

impl SceneResources {
    /// Resources around `renderer`, with no view prepared yet.
    pub fn new(renderer: Renderer) -> Self {
        Self {
            renderer,
            views: HashMap::new(),
        }
    }
}

/// One frame of one 3D view.
pub struct SceneCallback {
    /// Which view (its buffers are kept from frame to frame).
    pub view: egui::Id,
    /// What to draw.
    pub list: DrawList,
    /// Seen from here.
    pub camera: OrbitCamera,
    /// In these colours.
    pub theme: Theme,
    /// Size of the view, physical pixels (text is laid out in them).
    pub viewport: [f32; 2],
}

impl egui_wgpu::CallbackTrait for SceneCallback {
    fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        _screen: &egui_wgpu::ScreenDescriptor,
        _encoder: &mut wgpu::CommandEncoder,
        resources: &mut egui_wgpu::CallbackResources,
    ) -> Vec<wgpu::CommandBuffer> {
        if let Some(SceneResources { renderer, views }) = resources.get_mut::<SceneResources>() {
            let view = views
                .entry(self.view)
                .or_insert_with(|| renderer.new_view(device));
            renderer.prepare(
                device,
                queue,
                view,
                &self.list,
                &self.camera,
                &self.theme,
                self.viewport,
            );
        }
        Vec::new()
    }

    fn paint(
        &self,
        _info: egui::PaintCallbackInfo,
        pass: &mut wgpu::RenderPass<'static>,
        resources: &egui_wgpu::CallbackResources,
    ) {
        if let Some(r) = resources.get::<SceneResources>()
            && let Some(view) = r.views.get(&self.view)
        {
            r.renderer.paint(view, pass);
        }
    }
}
