//! Runs the translated sample kernel on a GPU (any wgpu adapter, e.g. Mesa's lavapipe
//! software Vulkan driver) and compares with the same Rust compiled natively.
//!
//! Without an adapter the test prints why and passes, unless `RINSHAN_REQUIRE_GPU=1`.

use rinshan_shaders_gen::{translate, Entry, Source};
use wgpu::util::DeviceExt;

#[allow(dead_code, clippy::all)]
mod native {
    pub fn table(i: u32) -> u32 {
        super::TABLE[i as usize]
    }

    include!("fixtures/sample_kernel.rs");
}

// SAFETY: both are #[repr(C)] structs of 4-byte integers only (no padding, any bit
// pattern is valid).
unsafe impl bytemuck::Zeroable for native::Input {}
unsafe impl bytemuck::Pod for native::Input {}
unsafe impl bytemuck::Zeroable for native::Output {}
unsafe impl bytemuck::Pod for native::Output {}

const TABLE: [u32; 16] = [7, 1, 4, 9, 16, 25, 3, 8, 100, 5, 0, 11, 2, 6, 13, 21];

fn inputs(n: usize) -> Vec<native::Input> {
    let mut state = 0x2545_f491_u32;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    };
    (0..n)
        .map(|_| {
            let mut tiles = [0u32; 34];
            for t in tiles.iter_mut() {
                *t = next() % 5;
            }
            native::Input {
                tiles,
                seat: next() % 4,
                flags: next(),
                delta: (next() % 101) as i32 - 50,
            }
        })
        .collect()
}

fn no_gpu(why: &str) {
    if std::env::var("RINSHAN_REQUIRE_GPU").as_deref() == Ok("1") {
        panic!("RINSHAN_REQUIRE_GPU=1 but {why}");
    }
    eprintln!("skipping GPU comparison: {why}");
}

#[test]
fn sample_kernel_matches_native_on_gpu() {
    let source = Source {
        path: "tests/fixtures/sample_kernel.rs".into(),
        text: include_str!("fixtures/sample_kernel.rs").into(),
    };
    let entry = Entry {
        name: "score_main".into(),
        function: "score".into(),
        input: "Input".into(),
        output: "Output".into(),
    };
    let wgsl = translate(&[source], &[entry]).unwrap_or_else(|e| panic!("{e}"));

    let instance = wgpu::Instance::default();
    let adapter = match pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default())) {
        Ok(a) => a,
        Err(e) => return no_gpu(&format!("no adapter ({e})")),
    };
    eprintln!("GPU adapter: {:?}", adapter.get_info());
    let (device, queue) = match pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())) {
        Ok(d) => d,
        Err(e) => return no_gpu(&format!("no device ({e})")),
    };

    let input = inputs(300);
    let expected: Vec<native::Output> = input.iter().map(|i| native::score(*i)).collect();

    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("sample_kernel"),
        source: wgpu::ShaderSource::Wgsl(wgsl.into()),
    });
    let storage = |binding: u32, read_only: bool| wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    };
    let bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[storage(0, true), storage(1, true), storage(2, false)],
    });
    let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: None,
        bind_group_layouts: &[Some(&bgl)],
        immediate_size: 0,
    });
    let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: None,
        layout: Some(&layout),
        module: &module,
        entry_point: Some("score_main"),
        compilation_options: Default::default(),
        cache: None,
    });

    let tables = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("tables"),
        contents: bytemuck::cast_slice(&TABLE),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let input_buf = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("in"),
        contents: bytemuck::cast_slice(&input),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let out_size = std::mem::size_of_val(expected.as_slice()) as u64;
    let output_buf = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("out"),
        size: out_size,
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
        mapped_at_creation: false,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: out_size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: None,
        layout: &bgl,
        entries: &[
            wgpu::BindGroupEntry {
                binding: 0,
                resource: tables.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 1,
                resource: input_buf.as_entire_binding(),
            },
            wgpu::BindGroupEntry {
                binding: 2,
                resource: output_buf.as_entire_binding(),
            },
        ],
    });

    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups((input.len() as u32).div_ceil(64), 1, 1);
    }
    encoder.copy_buffer_to_buffer(&output_buf, 0, &readback, 0, out_size);
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |r| r.expect("map readback buffer"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let view = readback.get_mapped_range(..).expect("mapped range");
    let got: &[native::Output] = bytemuck::cast_slice(&view);

    assert_eq!(got.len(), expected.len());
    for (k, (g, e)) in got.iter().zip(&expected).enumerate() {
        let g: &[u32] = bytemuck::cast_slice(std::slice::from_ref(g));
        let e: &[u32] = bytemuck::cast_slice(std::slice::from_ref(e));
        assert_eq!(g, e, "input {k}: GPU (left) differs from native (right)");
    }
}
