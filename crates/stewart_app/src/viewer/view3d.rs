//! The 3D view inside the egui layout: an `egui_wgpu` paint callback that draws with the
//! shared wgpu device through the renderer kept in the callback resources.

use stewart_render::{DrawList, OrbitCamera, Renderer, Theme};

/// One frame of the 3D view.
pub struct SceneCallback {
    /// What to draw.
    pub list: DrawList,
    /// Seen from here.
    pub camera: OrbitCamera,
    /// In these colours.
    pub theme: Theme,
    /// Width / height of the view.
    pub aspect: f32,
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
        if let Some(renderer) = resources.get_mut::<Renderer>() {
            renderer.prepare(
                device,
                queue,
                &self.list,
                &self.camera,
                &self.theme,
                self.aspect,
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
        if let Some(renderer) = resources.get::<Renderer>() {
            renderer.paint(pass);
        }
    }
}
