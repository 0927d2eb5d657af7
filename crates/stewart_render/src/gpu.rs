//! Choosing an adapter and opening a device, with or without a window.

use std::sync::{Mutex, PoisonError};

use thiserror::Error;

/// Why no GPU device could be opened.
#[derive(Debug, Error)]
pub enum GpuError {
    /// No adapter at all.
    #[error(
        "no graphics adapter found: install a GPU driver, or Mesa's software Vulkan driver (Debian: `apt-get install mesa-vulkan-drivers libvulkan1`)"
    )]
    NoAdapter,
    /// `WGPU_ADAPTER_NAME` matched nothing.
    #[error(
        "WGPU_ADAPTER_NAME is `{wanted}` but no adapter's name contains it (adapters: {available})"
    )]
    NoMatchingAdapter {
        /// The name asked for.
        wanted: String,
        /// The adapters found.
        available: String,
    },
    /// An environment variable that chooses the adapter holds a value wgpu does not know
    /// (wgpu would silently find no adapter).
    #[error("{name} is `{value}`, which is not one of {expected}")]
    BadSetting {
        /// The variable.
        name: &'static str,
        /// Its value.
        value: String,
        /// What it may be.
        expected: &'static str,
    },
    /// The adapter refused to open a device.
    #[error("the graphics adapter `{adapter}` could not open a device: {message}")]
    Device {
        /// Adapter name.
        adapter: String,
        /// The driver's words.
        message: String,
    },
}

/// An instance, adapter, device and queue (handles: a clone shares the same device).
#[derive(Clone)]
pub struct Gpu {
    /// The instance.
    pub instance: wgpu::Instance,
    /// The adapter in use.
    pub adapter: wgpu::Adapter,
    /// The device.
    pub device: wgpu::Device,
    /// Its queue.
    pub queue: wgpu::Queue,
}

/// The backend names `WGPU_BACKEND` may list (comma-separated), as wgpu reads them.
const BACKEND_NAMES: [&str; 10] = [
    "vulkan", "vk", "dx12", "d3d12", "metal", "mtl", "opengl", "gles", "gl", "webgpu",
];

/// Check the environment variables that choose the adapter: a misspelt `WGPU_BACKEND`
/// (say `vulcan`) would otherwise look like a machine without any adapter.
pub fn check_environment() -> Result<(), GpuError> {
    if let Some(value) = std::env::var_os("WGPU_BACKEND") {
        let text = value.to_string_lossy().into_owned();
        let known = |name: &str| BACKEND_NAMES.contains(&name.trim().to_lowercase().as_str());
        if text.trim().is_empty() || !text.split(',').all(known) {
            return Err(GpuError::BadSetting {
                name: "WGPU_BACKEND",
                value: text,
                expected: "vulkan, gl, metal, dx12 or webgpu (comma-separated)",
            });
        }
    }
    if let Some(value) = std::env::var_os("WGPU_POWER_PREF") {
        let text = value.to_string_lossy().into_owned();
        if !["low", "high", "none"].contains(&text.to_lowercase().as_str()) {
            return Err(GpuError::BadSetting {
                name: "WGPU_POWER_PREF",
                value: text,
                expected: "low, high or none",
            });
        }
    }
    Ok(())
}

/// The process's one headless device, opened by the first [`Gpu::shared`] and kept to the
/// end of the process.
/// Whether a window on this machine would be drawn by a software rasteriser (lavapipe,
/// llvmpipe, SwiftShader): the adapter `WGPU_ADAPTER_NAME` names is a CPU, or no adapter
/// but a CPU is there. A window then spends its frame time on every sample of every
/// pixel, and the viewer chooses cheaper ways to draw.
pub fn renders_in_software() -> bool {
    let instance =
        wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
    let adapters = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::all()));
    let cpu = |a: &wgpu::Adapter| a.get_info().device_type == wgpu::DeviceType::Cpu;
    match std::env::var("WGPU_ADAPTER_NAME") {
        Ok(wanted) => {
            let wanted = wanted.to_lowercase();
            adapters
                .iter()
                .find(|a| a.get_info().name.to_lowercase().contains(&wanted))
                .is_some_and(cpu)
        }
        Err(_) => !adapters.is_empty() && adapters.iter().all(cpu),
    }
}

static SHARED: Mutex<Option<Gpu>> = Mutex::new(None);

impl Gpu {
    /// The process's headless device (see [`Gpu::headless`]), opened on first use and
    /// shared by every later caller on any thread. Drivers can deadlock when instances
    /// and devices are created and destroyed on several threads at once (seen with
    /// NVIDIA's Vulkan driver), so offscreen renderers share this one device instead of
    /// opening their own; it is never dropped.
    pub fn shared() -> Result<Gpu, GpuError> {
        let mut shared = SHARED.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some(gpu) = shared.as_ref() {
            return Ok(gpu.clone());
        }
        let gpu = Self::headless()?;
        *shared = Some(gpu.clone());
        Ok(gpu)
    }

    /// Make `gpu` the process's shared device (a window's, so that offscreen shots and
    /// exports draw on the device the window opened instead of opening a second one).
    /// Returns false, changing nothing, when a shared device is already in use.
    pub fn adopt(gpu: Gpu) -> bool {
        let mut shared = SHARED.lock().unwrap_or_else(PoisonError::into_inner);
        if shared.is_some() {
            return false;
        }
        *shared = Some(gpu);
        true
    }

    /// A new device of its own for offscreen rendering: a real GPU when present,
    /// otherwise a software adapter (lavapipe). Honours `WGPU_BACKEND` (e.g. `vulkan`,
    /// `gl`) and `WGPU_ADAPTER_NAME` (a part of the adapter's name, e.g. `llvmpipe`).
    /// Prefer [`Gpu::shared`], or a window's device when there is one.
    pub fn headless() -> Result<Gpu, GpuError> {
        pollster::block_on(Self::headless_async())
    }

    async fn headless_async() -> Result<Gpu, GpuError> {
        check_environment()?;
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = Self::choose_adapter(&instance).await?;
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("stewart"),
                required_limits: wgpu::Limits::downlevel_webgl2_defaults()
                    .using_resolution(adapter.limits()),
                ..Default::default()
            })
            .await
            .map_err(|e| GpuError::Device {
                adapter: adapter.get_info().name,
                message: e.to_string(),
            })?;
        Ok(Gpu {
            instance,
            adapter,
            device,
            queue,
        })
    }

    async fn choose_adapter(instance: &wgpu::Instance) -> Result<wgpu::Adapter, GpuError> {
        if let Ok(wanted) = std::env::var("WGPU_ADAPTER_NAME") {
            let adapters = instance.enumerate_adapters(wgpu::Backends::all()).await;
            let names: Vec<String> = adapters
                .iter()
                .map(|a| {
                    let info = a.get_info();
                    format!("{} ({:?})", info.name, info.backend)
                })
                .collect();
            let lower = wanted.to_lowercase();
            return adapters
                .into_iter()
                .find(|a| a.get_info().name.to_lowercase().contains(&lower))
                .ok_or(GpuError::NoMatchingAdapter {
                    wanted,
                    available: names.join(", "),
                });
        }
        let options = |fallback| wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::from_env()
                .unwrap_or(wgpu::PowerPreference::HighPerformance),
            force_fallback_adapter: fallback,
            compatible_surface: None,
            ..Default::default()
        };
        if let Ok(a) = instance.request_adapter(&options(false)).await {
            return Ok(a);
        }
        instance
            .request_adapter(&options(true))
            .await
            .map_err(|_| GpuError::NoAdapter)
    }

    /// A one-line description of the adapter: name, backend, type.
    pub fn describe(&self) -> String {
        let info = self.adapter.get_info();
        format!("{} ({:?}, {:?})", info.name, info.backend, info.device_type)
    }
}
