//! Real shader toolchains (feature `gpu`): compute kernels in WGSL, SPIR-V or GLSL run
//! on a GPU adapter through `wgpu`, their values read back and judged by the test kit
//! as `check` judges any implementation's.
//!
//! In CI the adapter is lavapipe (Mesa's Vulkan driver on the CPU, which compiles the
//! SPIR-V with LLVM); where a real GPU is present, `wgpu` picks it. WGSL goes through
//! naga to SPIR-V; GLSL through glslang (`glslangValidator -V`, found on `PATH`) to
//! SPIR-V, which naga reads and writes again for the driver.
//!
//! The kernel interface (docs/conformance.md §6) is the same for every kernel: three
//! storage buffers at group 0 — `spans` (binding 0, read-only: per span `N_a`, `N_b`,
//! `L` as `vec4<f32>` with `w` unused, then `n`, `first` and two `u32` of padding, 64
//! bytes), `pixel_span` (binding 1, read-only: the span of each pixel) and `out`
//! (binding 2, read-write: the values, span `k`'s pixel `i` at `spans[k].first + i`) —
//! and an entry point `main` with `@workgroup_size(64)`, dispatched once per pixel.
//! A kernel that runs a recurrence lets pixel 0's invocation do the whole span.
//!
//! [`kernels`] lists this repository's own kernels (`harness/gpu/`) and evaluates
//! each one's source on the CPU in round-to-nearest `f32`, to show what the driver did
//! differently.

pub mod kernels;

use crate::testkit::Inputs;
use std::mem::ManuallyDrop;
use std::path::Path;
use std::time::{Duration, Instant};

mod source;
pub use source::Source;

/// The largest kernel source read (1 MiB).
pub const MAX_SOURCE_BYTES: u64 = 1 << 20;

/// The bits every pixel holds before the kernel runs: a NaN no arithmetic makes, so a
/// value read back with these bits is a pixel the kernel never wrote ([`unwritten`]).
pub const UNWRITTEN: u32 = 0x7fa0_0bad;

/// How many of `values` the kernel did not write (they still hold [`UNWRITTEN`]): a
/// loop the driver cut short (lavapipe stops an invocation's loops after about
/// 65535 iterations in all), a
/// workgroup size other than 64, an early return.
pub fn unwritten(values: &[f32]) -> usize {
    values.iter().filter(|v| v.to_bits() == UNWRITTEN).count()
}

/// The workgroup size every kernel declares (`@workgroup_size(64)`,
/// `layout(local_size_x = 64)`).
pub const WORKGROUP_SIZE: u32 = 64;

/// What went wrong on the way to a kernel's values.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter: no Vulkan (or other `wgpu`) driver is installed.
    #[error("no GPU adapter ({0}); on Linux without a GPU, install Mesa's Vulkan drivers (Debian: apt-get install mesa-vulkan-drivers) for lavapipe")]
    NoAdapter(String),
    /// The adapter would not open a device.
    #[error("the GPU adapter would not open a device: {0}")]
    Device(String),
    /// The kernel's file: unreadable, too large, an unknown extension, no glslang.
    #[error("{path}: {message}")]
    Source {
        /// The file.
        path: String,
        /// What is wrong with it.
        message: String,
    },
    /// The shader compiler rejected the kernel (its messages, with line numbers).
    #[error("{path}: the kernel does not compile:\n{message}")]
    Compile {
        /// The file.
        path: String,
        /// The compiler's messages.
        message: String,
    },
    /// The kernel compiles but does not have the interface: entry point `main`, the
    /// three bindings.
    #[error("{path}: the kernel does not have the interface (entry point `main`; bindings 0 spans, 1 pixel_span, 2 out; docs/conformance.md §6):\n{message}")]
    Interface {
        /// The file.
        path: String,
        /// The validation messages.
        message: String,
    },
    /// The dispatch did not finish in time (a loop that does not end?).
    #[error("{path}: the dispatch did not finish within {seconds} s (a loop that does not end?)")]
    Timeout {
        /// The file.
        path: String,
        /// The limit.
        seconds: u64,
    },
    /// Too many pixels for one dispatch.
    #[error("{pixels} pixels are more than one dispatch takes ({max})")]
    TooLarge {
        /// Pixels asked for.
        pixels: usize,
        /// The most one dispatch takes.
        max: usize,
    },
    /// The device was lost or the read-back failed.
    #[error("the GPU run failed: {0}")]
    Run(String),
}

/// The adapter a [`Gpu`] runs on, as the driver names itself.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Adapter {
    /// The device, e.g. `llvmpipe (LLVM 15.0.6, 256 bits)`.
    pub name: String,
    /// The driver, e.g. `llvmpipe`.
    pub driver: String,
    /// The driver's version, e.g. `Mesa 22.3.6 (LLVM 15.0.6)`.
    pub driver_info: String,
    /// The API, e.g. `Vulkan`.
    pub backend: String,
    /// `Cpu` (a software driver), `DiscreteGpu`, `IntegratedGpu`, ...
    pub device_type: String,
}

impl std::fmt::Display for Adapter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} ({}, driver {} {}, {})",
            self.name, self.backend, self.driver, self.driver_info, self.device_type
        )
    }
}

/// One span as the kernels read it (binding 0): 64 bytes, `std430` and WGSL alike.
#[repr(C)]
#[derive(Clone, Copy, bytemuck::Pod, bytemuck::Zeroable)]
struct GpuSpan {
    na: [f32; 4],
    nb: [f32; 4],
    l: [f32; 4],
    n: u32,
    first: u32,
    pad: [u32; 2],
}

/// A device and its queue, opened once, that runs kernels.
pub struct Gpu {
    // Not dropped after a dispatch that timed out: dropping waits for the device.
    device: ManuallyDrop<wgpu::Device>,
    queue: ManuallyDrop<wgpu::Queue>,
    adapter: Adapter,
    layout: wgpu::PipelineLayout,
    bind_layout: wgpu::BindGroupLayout,
    hung: std::cell::Cell<bool>,
    /// Errors no scope caught (a lost device, a failed submission), as text.
    uncaptured: std::sync::Arc<std::sync::Mutex<Vec<String>>>,
}

impl std::fmt::Debug for Gpu {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Gpu")
            .field("adapter", &self.adapter)
            .finish()
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        if !self.hung.get() {
            // SAFETY: dropped once, here, and never used again.
            unsafe {
                ManuallyDrop::drop(&mut self.queue);
                ManuallyDrop::drop(&mut self.device);
            }
        }
    }
}

impl Gpu {
    /// Opens the first adapter `wgpu` offers (the environment's `WGPU_BACKEND`,
    /// `WGPU_ADAPTER_NAME` choose among several).
    ///
    /// # Errors
    /// [`GpuError::NoAdapter`] when there is none, [`GpuError::Device`] when it will
    /// not open.
    pub fn new() -> Result<Gpu, GpuError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        if std::env::var_os("WGPU_BACKEND").is_none() {
            // Vulkan (and Metal, DX12) only: without a Vulkan driver `wgpu` would
            // otherwise fall back to an OpenGL context that a headless machine lacks.
            desc.backends = wgpu::Backends::PRIMARY;
        }
        let instance = wgpu::Instance::new(desc);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|e| GpuError::NoAdapter(e.to_string()))?;
        let info = adapter.get_info();
        let (device, queue) = pollster::block_on(adapter.request_device(&Default::default()))
            .map_err(|e| GpuError::Device(e.to_string()))?;
        let uncaptured = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
        let sink = uncaptured.clone();
        device.on_uncaptured_error(std::sync::Arc::new(move |e: wgpu::Error| {
            if let Ok(mut v) = sink.lock() {
                v.push(error_text(&e));
            }
        }));
        let storage = |binding, read_only| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let bind_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("spans, pixel_span, out"),
            entries: &[storage(0, true), storage(1, true), storage(2, false)],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("the kernel interface"),
            bind_group_layouts: &[Some(&bind_layout)],
            immediate_size: 0,
        });
        Ok(Gpu {
            device: ManuallyDrop::new(device),
            queue: ManuallyDrop::new(queue),
            adapter: Adapter {
                name: info.name,
                driver: info.driver,
                driver_info: info.driver_info,
                backend: format!("{:?}", info.backend),
                device_type: format!("{:?}", info.device_type),
            },
            layout,
            bind_layout,
            hung: std::cell::Cell::new(false),
            uncaptured,
        })
    }

    /// The adapter this device is on.
    pub fn adapter(&self) -> &Adapter {
        &self.adapter
    }

    /// Runs `source` (named `name` in messages) once over `spans`, one invocation per
    /// pixel, and returns each span's `n + 1` values. Pixels the kernel does not write
    /// come back NaN. `timeout` bounds the dispatch.
    ///
    /// # Errors
    /// [`GpuError::Compile`], [`GpuError::Interface`], [`GpuError::Timeout`],
    /// [`GpuError::TooLarge`], [`GpuError::Run`].
    pub fn run(
        &self,
        source: &Source,
        name: &str,
        spans: &[Inputs<'_, f32>],
        timeout: Duration,
    ) -> Result<Vec<Vec<f32>>, GpuError> {
        use wgpu::util::DeviceExt;
        if self.hung.get() {
            return Err(GpuError::Run(
                "an earlier dispatch on this device did not finish".into(),
            ));
        }
        let device = &*self.device;
        let mut table = Vec::with_capacity(spans.len());
        let mut pixel_span = Vec::new();
        for (k, s) in spans.iter().enumerate() {
            let v = |x: [f32; 3]| [x[0], x[1], x[2], 0.0];
            table.push(GpuSpan {
                na: v(s.na),
                nb: v(s.nb),
                l: v(s.l),
                n: s.n,
                first: pixel_span.len() as u32,
                pad: [0; 2],
            });
            let k = u32::try_from(k).unwrap_or(u32::MAX);
            pixel_span.extend(std::iter::repeat_n(k, s.n as usize + 1));
        }
        let pixels = pixel_span.len();
        let max = WORKGROUP_SIZE as usize * 65_535;
        if pixels > max || pixels == 0 {
            return Err(GpuError::TooLarge { pixels, max });
        }

        // Compile: WGSL and SPIR-V both go through naga, whose messages keep the lines.
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some(name),
            source: match source {
                Source::Wgsl(t) => wgpu::ShaderSource::Wgsl(t.as_str().into()),
                Source::SpirV(w) => wgpu::ShaderSource::SpirV(w.as_slice().into()),
            },
        });
        let info = pollster::block_on(module.get_compilation_info());
        if let Some(e) = pollster::block_on(scope.pop()) {
            let mut lines: Vec<String> = Vec::new();
            for m in info
                .messages
                .iter()
                .filter(|m| m.message_type == wgpu::CompilationMessageType::Error)
            {
                // naga's text: "Shader 'NAME' parsing error: …" and an excerpt of
                // the source with its line numbers.
                let text = m.message.trim().replace(&format!("Shader '{name}' "), "");
                let mut text = text.lines();
                let head = text.next().unwrap_or("");
                lines.push(match &m.location {
                    Some(at) => format!("{name}:{}:{}: {head}", at.line_number, at.line_position),
                    None => format!("{name}: {head}"),
                });
                lines.extend(text.map(str::to_string));
            }
            if lines.is_empty() {
                lines.push(error_text(&e));
            }
            return Err(GpuError::Compile {
                path: name.into(),
                message: lines.join("\n"),
            });
        }

        // The interface: entry point `main` and the three bindings of the layout.
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(name),
            layout: Some(&self.layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Interface {
                path: name.into(),
                message: error_text(&e),
            });
        }

        let spans_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("spans"),
            contents: bytemuck::cast_slice(&table),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let pixel_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("pixel_span"),
            contents: bytemuck::cast_slice(&pixel_span),
            usage: wgpu::BufferUsages::STORAGE,
        });
        // A NaN in every pixel first: one the kernel does not write fails its case.
        let nan = vec![f32::from_bits(UNWRITTEN); pixels];
        let out_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("out"),
            contents: bytemuck::cast_slice(&nan),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        });
        let size = (pixels * 4) as u64;
        let read_buf = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("read back"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("spans, pixel_span, out"),
            layout: &self.bind_layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: spans_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: pixel_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 2,
                    resource: out_buf.as_entire_binding(),
                },
            ],
        });
        let mut encoder = device.create_command_encoder(&Default::default());
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups((pixels as u32).div_ceil(WORKGROUP_SIZE), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&out_buf, 0, &read_buf, 0, size);
        let submitted = self.queue.submit([encoder.finish()]);
        let slice = read_buf.slice(..);
        let (tx, rx) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = tx.send(r);
        });
        let start = Instant::now();
        let polled = device.poll(wgpu::PollType::Wait {
            submission_index: Some(submitted),
            timeout: Some(timeout),
        });
        if matches!(polled, Err(wgpu::PollError::Timeout)) || start.elapsed() > timeout {
            // The device is busy for good: keep everything alive (dropping would wait).
            self.hung.set(true);
            std::mem::forget((
                module, pipeline, spans_buf, pixel_buf, out_buf, read_buf, bind,
            ));
            return Err(GpuError::Timeout {
                path: name.into(),
                seconds: timeout.as_secs().max(1),
            });
        }
        polled.map_err(|e| GpuError::Run(e.to_string()))?;
        match rx.recv_timeout(Duration::from_secs(5)) {
            Ok(Ok(())) => {}
            Ok(Err(e)) => return Err(GpuError::Run(e.to_string())),
            Err(_) => return Err(GpuError::Run("the read-back was never mapped".into())),
        }
        let values: Vec<f32> = {
            let view = slice
                .get_mapped_range()
                .map_err(|e| GpuError::Run(format!("{e:?}")))?;
            bytemuck::cast_slice(&view).to_vec()
        };
        read_buf.unmap();
        let errors: Vec<String> = self
            .uncaptured
            .lock()
            .map(|mut v| v.drain(..).collect())
            .unwrap_or_default();
        if !errors.is_empty() {
            return Err(GpuError::Run(errors.join("; ")));
        }
        Ok(table
            .iter()
            .map(|s| values[s.first as usize..=(s.first + s.n) as usize].to_vec())
            .collect())
    }
}

/// A `wgpu` error as text: its lines without wgpu's boilerplate ("Validation Error",
/// "Caused by:") and without repeats.
fn error_text(e: &wgpu::Error) -> String {
    let mut seen = std::collections::HashSet::new();
    e.to_string()
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && *l != "Validation Error" && *l != "Caused by:")
        .filter(|l| seen.insert(l.to_string()))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Every published case's `f32` inputs (the diffuse part), set by set, in the order of
/// the vector files.
pub fn published_spans() -> Vec<(&'static str, Inputs<'static, f32>)> {
    crate::testkit::SETS
        .iter()
        .filter_map(|set| Some((*set, crate::testkit::published(set)?)))
        .flat_map(|(set, file)| file.cases.iter().map(move |c| (set, Inputs::of_case(c))))
        .collect()
}

/// Judges a kernel's values (by case id, every published case) as the test kit judges
/// an implementation of `method` under `profile` in `f32`; a case without values
/// fails.
pub fn judge(
    method: crate::Method,
    profile: crate::tolerance::profile::Profile,
    values: &std::collections::HashMap<String, Vec<f32>>,
) -> crate::testkit::Report {
    crate::testkit::Suite::published()
        .method(method)
        .profile(profile)
        .check_f32(|s| values.get(s.id).cloned().unwrap_or_default())
}
