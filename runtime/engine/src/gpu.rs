//! The GPU backend: the WGSL that `rinshan-shaders-gen` translated from `rules/kernel/` at build
//! time, run through wgpu (Vulkan, Metal, DX12 or GL; Mesa's software Vulkan driver without a GPU).
//! Inputs and outputs are the same raw kernel words as the CPU batch functions in [`crate::hand`],
//! so parity is a comparison of words.

use std::collections::HashMap;
use std::hash::{Hash, Hasher};
use std::sync::{mpsc, Arc, Mutex};

use wgpu::util::DeviceExt;

use crate::hand::{SCORE_IN_WORDS, SCORE_OUT_WORDS, SHANTEN_IN_WORDS, SHANTEN_OUT_WORDS};
use crate::{entries, tables, Variant};

const WORKGROUP: usize = 64;
const MAX_GROUPS: usize = 65_535;

/// What went wrong while bringing up or using the GPU.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum GpuError {
    /// No adapter: no GPU and no software driver (install Mesa's `mesa-vulkan-drivers`).
    NoAdapter(String),
    /// The adapter would not give a device, or the device failed.
    Device(String),
    /// Results could not be read back from the device.
    Readback(String),
    /// Inputs that are not whole kernel records.
    BadInput(String),
}

impl std::fmt::Display for GpuError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            GpuError::NoAdapter(m) => write!(f, "no GPU adapter found ({m}); on a machine without a GPU install Mesa's software Vulkan driver: apt-get install -y mesa-vulkan-drivers libvulkan1"),
            GpuError::Device(m) => write!(f, "GPU device error: {m}"),
            GpuError::Readback(m) => write!(f, "GPU readback failed: {m}"),
            GpuError::BadInput(m) => write!(f, "bad GPU input: {m}"),
        }
    }
}

impl std::error::Error for GpuError {}

/// A kernel entry point of the generated WGSL.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Kernel {
    /// Shanten of a hand ([`crate::hand::shanten_batch`] on the CPU).
    Shanten,
    /// Scoring a winning hand ([`crate::hand::score_batch`] on the CPU).
    Score,
}

impl Kernel {
    fn entry(self) -> &'static str {
        match self {
            Kernel::Shanten => "shanten_main",
            Kernel::Score => "score_main",
        }
    }

    fn words(self) -> (usize, usize) {
        match self {
            Kernel::Shanten => (SHANTEN_IN_WORDS, SHANTEN_OUT_WORDS),
            Kernel::Score => (SCORE_IN_WORDS, SCORE_OUT_WORDS),
        }
    }

    fn spec(self) -> EntrySpec {
        EntrySpec::map(self.entry())
    }
}

/// One compute entry point of the generated module and its storage bindings: the translator
/// gives the entry at binding slot k (in [`crate::entries`] order; a read entry takes two slots)
/// bindings 1+2k and 2+2k, and a read entry also 3+2k.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) struct EntrySpec {
    pub name: &'static str,
    /// (binding, read-only) of the entry's first, second and (read entries) third buffer.
    pub first: (u32, bool),
    pub second: (u32, bool),
    pub third: Option<(u32, bool)>,
}

impl EntrySpec {
    /// The entry's first binding slot.
    fn index(name: &str) -> u32 {
        let slots = entries::ENTRIES
            .iter()
            .map(|e| (e.0, 1))
            .chain(entries::UPDATE_ENTRIES.iter().map(|e| (e.0, 1)))
            .chain(entries::READ_ENTRIES.iter().map(|e| (e.0, 2)));
        let mut k = 0;
        for (n, size) in slots {
            if n == name {
                return k;
            }
            k += size;
        }
        unreachable!("`{name}` is not an entry point in entries.rs")
    }

    /// A read entry: state and arguments (read-only) at 1+2k and 2+2k, output at 3+2k.
    pub fn read(name: &'static str) -> EntrySpec {
        let k = EntrySpec::index(name);
        EntrySpec {
            name,
            first: (1 + 2 * k, true),
            second: (2 + 2 * k, true),
            third: Some((3 + 2 * k, false)),
        }
    }

    /// A map entry: input (read-only) at 1+2k, output (read-write) at 2+2k.
    pub fn map(name: &'static str) -> EntrySpec {
        let k = EntrySpec::index(name);
        EntrySpec {
            name,
            first: (1 + 2 * k, true),
            second: (2 + 2 * k, false),
            third: None,
        }
    }

    /// An update entry: state (read-write) at 1+2k, arguments (read-only) at 2+2k.
    pub fn update(name: &'static str) -> EntrySpec {
        let k = EntrySpec::index(name);
        EntrySpec {
            name,
            first: (1 + 2 * k, false),
            second: (2 + 2 * k, true),
            third: None,
        }
    }
}

/// The largest number of records one dispatch covers (workgroups of 64, at most 65,535 of them).
pub(crate) const MAX_DISPATCH: usize = WORKGROUP * MAX_GROUPS;

/// Workgroups for `n` records.
pub(crate) fn groups(n: usize) -> u32 {
    n.div_ceil(WORKGROUP) as u32
}

fn request_adapter(backends: wgpu::Backends) -> Result<wgpu::Adapter, GpuError> {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = backends;
    let instance = wgpu::Instance::new(desc);
    pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
        power_preference: wgpu::PowerPreference::HighPerformance,
        force_fallback_adapter: false,
        compatible_surface: None,
        ..Default::default()
    }))
    .map_err(|e| GpuError::NoAdapter(e.to_string()))
}

/// A GPU device with the tables uploaded once and one pipeline per (variant, kernel), made on first use.
pub struct Gpu {
    device: wgpu::Device,
    queue: wgpu::Queue,
    info: wgpu::AdapterInfo,
    tables: wgpu::Buffer,
    // Keyed by a hash of the WGSL source, so custom modules (a spec compiled at run time) work too.
    modules: HashMap<u64, wgpu::ShaderModule>,
    pipelines: HashMap<(u64, EntrySpec), (wgpu::ComputePipeline, wgpu::BindGroupLayout)>,
    // Why the driver lost the device, if it did: a failed map then says so instead of only that
    // the buffer could not be mapped.
    lost: Arc<Mutex<Option<String>>>,
}

impl Gpu {
    /// Opens the first adapter wgpu offers (a real GPU first, else a software one).
    pub fn new() -> Result<Gpu, GpuError> {
        // GL is only a fallback: probing it first prints EGL/Wayland noise on headless machines.
        let adapter = match wgpu::Backends::from_env() {
            Some(backends) => request_adapter(backends),
            None => request_adapter(wgpu::Backends::PRIMARY).or_else(|_| request_adapter(wgpu::Backends::GL)),
        }?;
        let info = adapter.get_info();
        let mut limits = wgpu::Limits::default();
        let available = adapter.limits();
        limits.max_storage_buffer_binding_size = available.max_storage_buffer_binding_size;
        limits.max_buffer_size = available.max_buffer_size;
        limits.max_storage_buffers_per_shader_stage = available
            .max_storage_buffers_per_shader_stage
            .max(limits.max_storage_buffers_per_shader_stage);
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("rinshan"),
            required_limits: limits,
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        let lost = Arc::new(Mutex::new(None));
        let record = Arc::clone(&lost);
        device.set_device_lost_callback(move |reason, message| {
            if let Ok(mut why) = record.lock() {
                *why = Some(format!("{reason:?}: {message}"));
            }
        });
        let tables = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rinshan tables"),
            contents: tables::bytes(),
            usage: wgpu::BufferUsages::STORAGE,
        });
        Ok(Gpu {
            device,
            queue,
            info,
            tables,
            modules: HashMap::new(),
            pipelines: HashMap::new(),
            lost,
        })
    }

    /// The adapter's name and backend, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan)`.
    pub fn adapter(&self) -> String {
        format!(
            "{} ({:?}, {:?})",
            self.info.name, self.info.backend, self.info.device_type
        )
    }

    /// The driver's own version line, e.g. `Mesa 25.0.7-2~bpo12+1 (LLVM 15.0.6)` for lavapipe.
    pub fn driver_info(&self) -> &str {
        &self.info.driver_info
    }

    /// Whether the adapter is a software rasterizer on the CPU (Mesa's lavapipe, WARP...).
    pub fn is_software(&self) -> bool {
        self.info.device_type == wgpu::DeviceType::Cpu
    }

    pub(crate) fn device(&self) -> &wgpu::Device {
        &self.device
    }

    pub(crate) fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// The pipeline of one entry point of `wgsl` and its bind group layout (tables at 0 and the
    /// entry's two buffers); the module and the pipeline are made once and cached.
    pub(crate) fn pipeline(&mut self, wgsl: &str, entry: EntrySpec) -> (wgpu::ComputePipeline, wgpu::BindGroupLayout) {
        let device = &self.device;
        let mut hasher = std::collections::hash_map::DefaultHasher::new();
        wgsl.hash(&mut hasher);
        let key = hasher.finish();
        let modules = &mut self.modules;
        let found = self.pipelines.entry((key, entry)).or_insert_with(|| {
            let module = modules.entry(key).or_insert_with(|| {
                device.create_shader_module(wgpu::ShaderModuleDescriptor {
                    label: Some("rinshan kernels"),
                    source: wgpu::ShaderSource::Wgsl(wgsl.to_string().into()),
                })
            });
            let storage = |(binding, read_only): (u32, bool)| wgpu::BindGroupLayoutEntry {
                binding,
                visibility: wgpu::ShaderStages::COMPUTE,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Storage { read_only },
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
                count: None,
            };
            let mut bindings = vec![storage((0, true)), storage(entry.first), storage(entry.second)];
            bindings.extend(entry.third.map(storage));
            let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
                label: Some(entry.name),
                entries: &bindings,
            });
            let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
                label: Some(entry.name),
                bind_group_layouts: &[Some(&layout)],
                immediate_size: 0,
            });
            let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(entry.name),
                layout: Some(&pipeline_layout),
                module,
                entry_point: Some(entry.name),
                compilation_options: Default::default(),
                cache: None,
            });
            (pipeline, layout)
        });
        found.clone()
    }

    /// A bind group for `entry`: the tables and its buffers (`third` for a read entry's output).
    pub(crate) fn bind_group(
        &self,
        layout: &wgpu::BindGroupLayout,
        entry: EntrySpec,
        first: &wgpu::Buffer,
        second: &wgpu::Buffer,
        third: Option<&wgpu::Buffer>,
    ) -> wgpu::BindGroup {
        let mut entries = vec![
            wgpu::BindGroupEntry {
                binding: 0,
                resource: self.tables.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: entry.first.0,
                resource: first.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: entry.second.0,
                resource: second.as_entire_binding(),
            },
        ];
        if let (Some((binding, _)), Some(buffer)) = (entry.third, third) {
            entries.push(wgpu::BindGroupEntry {
                binding,
                resource: buffer.as_entire_binding(),
            });
        }
        self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(entry.name),
            layout,
            entries: &entries,
        })
    }

    fn readback_error(&self, e: impl std::fmt::Display) -> GpuError {
        match self.lost.lock().ok().and_then(|why| why.clone()) {
            Some(why) => GpuError::Readback(format!("{e}: the device was lost ({why})")),
            None => GpuError::Readback(e.to_string()),
        }
    }

    /// Maps `readback` (already filled by submitted work), waits, and copies out its words.
    pub(crate) fn read_words(&self, readback: &wgpu::Buffer, out: &mut Vec<u32>) -> Result<(), GpuError> {
        let (tx, rx) = mpsc::channel();
        readback.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| self.readback_error(e))?;
        match rx.recv() {
            Ok(Ok(())) => {}
            Ok(Err(e)) => return Err(self.readback_error(e)),
            Err(e) => return Err(self.readback_error(e)),
        }
        {
            let view = readback
                .get_mapped_range(..)
                .map_err(|e| GpuError::Readback(format!("{e:?}")))?;
            out.clear();
            out.extend_from_slice(bytemuck::cast_slice(&view));
        }
        readback.unmap();
        Ok(())
    }

    /// Runs `kernel` of `variant` over `inputs` (whole records of raw words) and reads back the outputs.
    pub fn run(&mut self, variant: Variant, kernel: Kernel, inputs: &[u32]) -> Result<Vec<u32>, GpuError> {
        self.run_wgsl(with_variant!(variant, v => v::WGSL), kernel, inputs)
    }

    /// As [`Gpu::run`] with WGSL translated elsewhere, e.g. from a spec edited at run time through
    /// `rinshan-codegen` and `rinshan-shaders-gen`; it must have the same entry points and bindings.
    pub fn run_wgsl(&mut self, wgsl: &str, kernel: Kernel, inputs: &[u32]) -> Result<Vec<u32>, GpuError> {
        let (in_words, out_words) = kernel.words();
        if !inputs.len().is_multiple_of(in_words) {
            return Err(GpuError::BadInput(format!(
                "{} words is not a whole number of {in_words}-word records",
                inputs.len()
            )));
        }
        let n = inputs.len() / in_words;
        let mut outputs = Vec::with_capacity(n * out_words);
        // One dispatch covers at most MAX_GROUPS workgroups; bigger batches go in chunks.
        for chunk in inputs.chunks(in_words * WORKGROUP * MAX_GROUPS) {
            outputs.extend(self.run_chunk(wgsl, kernel, chunk)?);
        }
        Ok(outputs)
    }

    fn run_chunk(&mut self, wgsl: &str, kernel: Kernel, inputs: &[u32]) -> Result<Vec<u32>, GpuError> {
        let (in_words, out_words) = kernel.words();
        let n = inputs.len() / in_words;
        if n == 0 {
            return Ok(Vec::new());
        }
        let out_bytes = (n * out_words * 4) as u64;
        let input_buffer = self.device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("rinshan input"),
            contents: bytemuck::cast_slice(inputs),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let output_buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("rinshan output"),
            size: out_bytes,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("rinshan readback"),
            size: out_bytes,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let spec = kernel.spec();
        let (pipeline, layout) = self.pipeline(wgsl, spec);
        let bind_group = self.bind_group(&layout, spec, &input_buffer, &output_buffer, None);
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("rinshan") });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some(kernel.entry()),
                timestamp_writes: None,
            });
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind_group, &[]);
            pass.dispatch_workgroups(groups(n), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output_buffer, 0, &readback, 0, out_bytes);
        self.queue.submit([encoder.finish()]);
        let mut words = Vec::with_capacity(n * out_words);
        self.read_words(&readback, &mut words)?;
        Ok(words)
    }
}
