//! Reading a rendered texture back to the CPU: a buffer whose rows are padded to wgpu's
//! copy alignment, the copy into it, and the wait for its rows, unpadded. Shared by the
//! off-screen renderer and the viewer's whole-window shots.

/// A buffer for a `width × height` image of 4-byte pixels, its rows padded to 256 bytes
/// as texture-to-buffer copies require.
pub struct Readback {
    buffer: wgpu::Buffer,
    width: u32,
    height: u32,
    padded_row: u32,
}

impl Readback {
    /// A buffer for `width × height` pixels.
    pub fn new(device: &wgpu::Device, label: &str, width: u32, height: u32) -> Self {
        let align = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let padded_row = (4 * width).div_ceil(align) * align;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: u64::from(padded_row) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Self {
            buffer,
            width,
            height,
            padded_row,
        }
    }

    /// Record the copy of `texture` (of this size, 4 bytes a pixel) into the buffer.
    pub fn copy_from(&self, encoder: &mut wgpu::CommandEncoder, texture: &wgpu::Texture) {
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &self.buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(self.padded_row),
                    rows_per_image: Some(self.height),
                },
            },
            wgpu::Extent3d {
                width: self.width,
                height: self.height,
                depth_or_array_layers: 1,
            },
        );
    }

    /// Wait for the submitted copy and return the pixels' bytes, row after row without
    /// padding (the buffer is free for the next copy after).
    pub fn read(&self, device: &wgpu::Device) -> Result<Vec<u8>, String> {
        let slice = self.buffer.slice(..);
        let (sender, receiver) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = sender.send(r);
        });
        device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| e.to_string())?;
        receiver
            .recv()
            .map_err(|e| e.to_string())?
            .map_err(|e| e.to_string())?;
        let row = 4 * self.width as usize;
        let mut bytes = Vec::with_capacity(row * self.height as usize);
        {
            let data = slice.get_mapped_range().map_err(|e| e.to_string())?;
            for y in 0..self.height as usize {
                let start = y * self.padded_row as usize;
                bytes.extend_from_slice(&data[start..start + row]);
            }
        }
        self.buffer.unmap();
        Ok(bytes)
    }
}
