//! The renderer: pipelines and buffers, and one entry point that draws a scene into a
//! colour view (a window's surface, an egui viewport or an offscreen texture).

use crate::camera::OrbitCamera;
use crate::draw_list::DrawList;
use crate::gpu_mesh::GpuMesh;
use crate::gpu_types::{Globals, MeshInstance, MeshVertex, TextVertex};
use crate::mesh::Mesh;
use crate::pipelines::Pipelines;
use crate::text::{ATLAS_SIZE, Fonts, GlyphAtlas};
use crate::theme::{Theme, linear};
use crate::view::{Batches, PreparedView};

pub use crate::pipelines::DEPTH_FORMAT;

/// One frame of a view: what is drawn, from where, in which colours, at what size.
#[derive(Clone, Copy)]
pub struct ViewFrame<'a> {
    /// What is drawn.
    pub list: &'a DrawList,
    /// From where.
    pub camera: &'a OrbitCamera,
    /// In which colours.
    pub theme: &'a Theme,
    /// The viewport the frame is shown in: width × height, pixels.
    pub viewport: [f32; 2],
    /// The picture's size against the viewport: 1 pixel for pixel; below 1 a picture
    /// rendered smaller and filtered up, whose text keeps its size in the view.
    pub scale: f32,
}

impl<'a> ViewFrame<'a> {
    /// `list` seen by `camera` in `theme`, in a `viewport` pixel for pixel.
    pub fn new(
        list: &'a DrawList,
        camera: &'a OrbitCamera,
        theme: &'a Theme,
        viewport: [f32; 2],
    ) -> Self {
        Self {
            list,
            camera,
            theme,
            viewport,
            scale: 1.0,
        }
    }

    /// The same frame rendered at `scale` of its viewport.
    pub fn scaled(self, scale: f32) -> Self {
        Self { scale, ..self }
    }
}

/// Pipelines and meshes for drawing a Stewart platform: built once per device and
/// colour format, shared by every view. What one view draws in one frame lives in a
/// [`PreparedView`], so a window can draw several views (the 3D view, thumbnails, a
/// workspace view) with one renderer.
pub struct Renderer {
    pipelines: Pipelines,
    cylinder: GpuMesh,
    sphere: GpuMesh,
    cone: GpuMesh,
    cuboid: GpuMesh,
    atlas_texture: wgpu::Texture,
    atlas_bind_group: wgpu::BindGroup,
    atlas: std::sync::Mutex<GlyphAtlas>,
    fonts: &'static Fonts,
    /// MSAA sample count the pipelines were built for.
    pub samples: u32,
    /// Colour format the pipelines were built for.
    pub format: wgpu::TextureFormat,
}

impl Renderer {
    /// Build the pipelines for colour `format` with `samples` (1 or 4) MSAA samples.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat, samples: u32) -> Self {
        let (pipelines, atlas_texture, atlas_bind_group) = Pipelines::new(device, format, samples);
        Self {
            pipelines,
            atlas_texture,
            atlas_bind_group,
            atlas: std::sync::Mutex::new(GlyphAtlas::new()),
            fonts: Fonts::system(),
            cylinder: GpuMesh::new(device, &Mesh::cylinder(), "cylinder"),
            sphere: GpuMesh::new(device, &Mesh::sphere(), "sphere"),
            cone: GpuMesh::new(device, &Mesh::cone(), "cone"),
            cuboid: GpuMesh::new(device, &Mesh::cuboid(), "box"),
            samples,
            format,
        }
    }

    /// A new view's per-frame buffers (grown as its scenes need).
    pub fn new_view(&self, device: &wgpu::Device) -> PreparedView {
        PreparedView::new(device, &self.pipelines.globals_layout)
    }

    /// The fonts text is drawn with (found on the system once).
    pub fn fonts(&self) -> &'static Fonts {
        self.fonts
    }

    /// Upload one frame of `view`: the camera for the frame's viewport, the theme and
    /// the draw list (text laid out in the viewport's pixels).
    pub fn prepare(
        &self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        view: &mut PreparedView,
        frame: &ViewFrame<'_>,
    ) {
        let ViewFrame {
            list,
            camera,
            theme,
            viewport,
            scale,
        } = *frame;
        let viewport = [viewport[0].max(1.0), viewport[1].max(1.0)];
        let aspect = viewport[0] / viewport[1];
        let globals = self.globals(camera, theme, aspect);
        queue.write_buffer(&view.globals, 0, bytemuck::bytes_of(&globals));
        view.clear = self.clear_colour(theme);
        let mut instances = Vec::with_capacity(
            list.cylinders.len()
                + list.spheres.len()
                + list.cones.len()
                + list.boxes.len()
                + list.plates.len()
                + list.parts.len(),
        );
        // Instances: cylinders, spheres, cones, boxes, parts, then one per plate.
        let cylinders = push_range(&list.cylinders, &mut instances);
        let spheres = push_range(&list.spheres, &mut instances);
        let cones = push_range(&list.cones, &mut instances);
        let boxes = push_range(&list.boxes, &mut instances);
        let slots = view.keep_parts(device, list.parts.iter().map(|p| &p.mesh));
        let parts = slots
            .into_iter()
            .zip(&list.parts)
            .map(|(slot, part)| {
                instances.push(part.instance);
                (slot, instances.len() as u32 - 1)
            })
            .collect();
        let plate_mesh = plates_back_to_front(list, camera.eye(), &mut instances);
        view.instances
            .write(device, queue, bytemuck::cast_slice(&instances));
        view.plate_vertices
            .write(device, queue, bytemuck::cast_slice(&plate_mesh.vertices));
        view.plate_indices
            .write(device, queue, bytemuck::cast_slice(&plate_mesh.indices));
        view.line_vertices
            .write(device, queue, bytemuck::cast_slice(&list.lines));
        view.keep_analysis(device, &list.analysis);
        let text = self.prepare_text(queue, list, camera.view_proj(aspect), viewport, scale);
        view.text_vertices
            .write(device, queue, bytemuck::cast_slice(&text));
        view.batches = Batches {
            cylinders,
            spheres,
            cones,
            boxes,
            plates: plate_mesh.plates,
            lines: list.lines.len() as u32,
            text: text.len() as u32,
            parts,
        };
    }

    /// The frame's uniforms: the camera for `aspect`, its lights, the shading and the
    /// theme's background.
    fn globals(&self, camera: &OrbitCamera, theme: &Theme, aspect: f32) -> Globals {
        let eye = camera.eye();
        // Key light over the viewer's right shoulder and above; fill from the other side.
        let forward = -camera.direction();
        let right = forward.cross(glam::Vec3::Z).normalize_or(glam::Vec3::X);
        let key = (-forward + right * 0.6 + glam::Vec3::Z * 0.9).normalize();
        let fill = (-forward - right * 0.8 + glam::Vec3::Z * 0.2).normalize();
        Globals {
            view_proj: camera.view_proj(aspect).to_cols_array_2d(),
            eye: [eye.x, eye.y, eye.z, 1.0],
            key_light: [key.x, key.y, key.z, 0.75],
            fill_light: [fill.x, fill.y, fill.z, 0.25],
            shading: [
                0.22,
                0.25,
                48.0,
                if self.format.is_srgb() { 0.0 } else { 1.0 },
            ],
            background: {
                let bg = linear(theme.background);
                [bg[0], bg[1], bg[2], theme.background[3]]
            },
        }
    }

    /// The colour a pass clears to: the theme's background written as it is, linear into
    /// an sRGB target, encoded into one that is not (a window's surface, a picture drawn
    /// into it).
    fn clear_colour(&self, theme: &Theme) -> wgpu::Color {
        let bg = if self.format.is_srgb() {
            linear(theme.background)
        } else {
            theme.background
        };
        wgpu::Color {
            r: bg[0] as f64,
            g: bg[1] as f64,
            b: bg[2] as f64,
            a: f64::from(theme.background[3]),
        }
    }

    /// Lay out the draw list's text and upload the glyphs it added to the atlas.
    fn prepare_text(
        &self,
        queue: &wgpu::Queue,
        list: &DrawList,
        view_proj: glam::Mat4,
        viewport: [f32; 2],
        scale: f32,
    ) -> Vec<TextVertex> {
        if list.texts.is_empty() {
            return Vec::new();
        }
        let mut atlas = self
            .atlas
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let vertices = atlas.layout(self.fonts, &list.texts, view_proj, viewport, scale);
        if atlas.dirty {
            queue.write_texture(
                wgpu::TexelCopyTextureInfo {
                    texture: &self.atlas_texture,
                    mip_level: 0,
                    origin: wgpu::Origin3d::ZERO,
                    aspect: wgpu::TextureAspect::All,
                },
                &atlas.pixels,
                wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(ATLAS_SIZE),
                    rows_per_image: Some(ATLAS_SIZE),
                },
                wgpu::Extent3d {
                    width: ATLAS_SIZE,
                    height: ATLAS_SIZE,
                    depth_or_array_layers: 1,
                },
            );
            atlas.dirty = false;
        }
        vertices
    }

    /// Draw `view`'s prepared frame into an open render pass.
    pub fn paint(&self, view: &PreparedView, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        if view.batches.lines > 0 {
            pass.set_pipeline(&self.pipelines.lines);
            pass.set_vertex_buffer(0, view.line_vertices.buffer.slice(..));
            pass.draw(0..view.batches.lines, 0..1);
        }
        pass.set_pipeline(&self.pipelines.opaque);
        pass.set_vertex_buffer(1, view.instances.buffer.slice(..));
        for (mesh, range) in [
            (&self.cylinder, &view.batches.cylinders),
            (&self.sphere, &view.batches.spheres),
            (&self.cone, &view.batches.cones),
            (&self.cuboid, &view.batches.boxes),
        ] {
            if range.is_empty() {
                continue;
            }
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            pass.draw_indexed(0..mesh.count, 0, range.clone());
        }
        if !view.batches.parts.is_empty() {
            pass.set_pipeline(&self.pipelines.parts);
            for &(slot, instance) in &view.batches.parts {
                let mesh = &view.parts[slot].1;
                if mesh.count == 0 {
                    continue;
                }
                pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.count, 0, instance..instance + 1);
            }
        }
        if !view.batches.plates.is_empty() {
            pass.set_pipeline(&self.pipelines.translucent);
            pass.set_vertex_buffer(0, view.plate_vertices.buffer.slice(..));
            pass.set_index_buffer(
                view.plate_indices.buffer.slice(..),
                wgpu::IndexFormat::Uint32,
            );
            for &(first, count, instance) in &view.batches.plates {
                pass.draw_indexed(first..first + count, 0, instance..instance + 1);
            }
        }
        if !view.analysis.is_empty() {
            pass.set_pipeline(&self.pipelines.analysis);
            for (_, mesh) in &view.analysis {
                pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..mesh.count, 0, 0..1);
            }
        }
        if view.batches.text > 0 {
            pass.set_pipeline(&self.pipelines.text);
            pass.set_bind_group(1, &self.atlas_bind_group, &[]);
            pass.set_vertex_buffer(0, view.text_vertices.buffer.slice(..));
            pass.draw(0..view.batches.text, 0..1);
        }
    }

    /// Draw `view`'s background (the theme's colour) over the whole viewport of an open
    /// pass: what a clear would do, where the view shares its pass with a UI.
    pub fn paint_background(&self, view: &PreparedView, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        pass.set_pipeline(&self.pipelines.background);
        pass.draw(0..3, 0..1);
    }

    /// Draw a picture rendered off screen ([`crate::Picture`]) over the whole viewport of
    /// an open pass; `view` is any view prepared by this renderer (its globals are bound).
    pub fn paint_picture(
        &self,
        view: &PreparedView,
        picture: &crate::Picture,
        pass: &mut wgpu::RenderPass<'_>,
    ) {
        pass.set_bind_group(0, &view.bind_group, &[]);
        pass.set_bind_group(1, picture.bind_group(), &[]);
        pass.set_pipeline(&self.pipelines.picture);
        pass.draw(0..3, 0..1);
    }

    /// The layout of a picture's bind group (its texture and sampler), for
    /// [`crate::Picture::new`].
    pub(crate) fn picture_layout(&self) -> &wgpu::BindGroupLayout {
        &self.pipelines.picture_layout
    }

    /// Record a whole pass: clear `target` (and `depth`), draw, resolve into `resolve` when MSAA is on.
    pub fn render(
        &self,
        view: &PreparedView,
        encoder: &mut wgpu::CommandEncoder,
        target: &wgpu::TextureView,
        resolve: Option<&wgpu::TextureView>,
        depth: &wgpu::TextureView,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("stewart scene"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: target,
                depth_slice: None,
                resolve_target: resolve,
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(view.clear),
                    store: wgpu::StoreOp::Store,
                },
            })],
            depth_stencil_attachment: Some(crate::targets::cleared_depth(depth)),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        self.paint(view, &mut pass);
    }
}

/// Append `items` to `all`; the range of instance indices they took.
fn push_range(items: &[MeshInstance], all: &mut Vec<MeshInstance>) -> std::ops::Range<u32> {
    let start = all.len() as u32;
    all.extend_from_slice(items);
    start..all.len() as u32
}

/// A frame's plates in one mesh, farthest first.
struct PlateMesh {
    vertices: Vec<MeshVertex>,
    indices: Vec<u32>,
    /// Each plate's first index, index count and instance.
    plates: Vec<(u32, u32, u32)>,
}

/// The draw list's plates, farthest from `eye` first: their vertices and indices in one
/// mesh, and each plate's first index, index count and instance (appended to `instances`,
/// one identity instance of its colour each).
fn plates_back_to_front(
    list: &DrawList,
    eye: glam::Vec3,
    instances: &mut Vec<MeshInstance>,
) -> PlateMesh {
    let mut order: Vec<usize> = (0..list.plates.len()).collect();
    order.sort_by(|&a, &b| {
        let da = (list.plates[a].2 - eye).length_squared();
        let db = (list.plates[b].2 - eye).length_squared();
        db.total_cmp(&da)
    });
    let mut vertices: Vec<MeshVertex> = Vec::new();
    let mut indices: Vec<u32> = Vec::new();
    let mut plates = Vec::new();
    for k in order {
        let (mesh, color, _) = &list.plates[k];
        let base = vertices.len() as u32;
        let first = indices.len() as u32;
        vertices.extend_from_slice(&mesh.vertices);
        indices.extend(mesh.indices.iter().map(|i| i + base));
        let instance = instances.len() as u32;
        instances.push(MeshInstance {
            model: glam::Mat4::IDENTITY.to_cols_array_2d(),
            color: *color,
        });
        plates.push((first, mesh.indices.len() as u32, instance));
    }
    PlateMesh {
        vertices,
        indices,
        plates,
    }
}
