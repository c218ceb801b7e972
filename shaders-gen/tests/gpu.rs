//! Runs the translated sample kernel (a map entry) and update kernel (in-place update
//! entries) on a GPU (any wgpu adapter, e.g. Mesa's lavapipe software Vulkan driver) and
//! compares with the same Rust compiled natively.
//!
//! Without an adapter the test prints why and passes, unless `RINSHAN_REQUIRE_GPU=1`.

use rinshan_shaders_gen::{translate, translate_entry_points, Entry, EntryPoint, Source, UpdateEntry};
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

#[allow(dead_code, clippy::all)]
mod native_update {
    include!("fixtures/update_kernel.rs");
}

// SAFETY: #[repr(C)] structs of 4-byte integers and f32s only (no padding; any bit pattern
// is a valid value).
unsafe impl bytemuck::Zeroable for native_update::GameState {}
unsafe impl bytemuck::Pod for native_update::GameState {}
unsafe impl bytemuck::Zeroable for native_update::StepArg {}
unsafe impl bytemuck::Pod for native_update::StepArg {}

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

/// The default adapter's device, or `None` (after `no_gpu`) when there is none.
fn gpu() -> Option<(wgpu::Device, wgpu::Queue)> {
    let instance = wgpu::Instance::default();
    let adapter = match pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions::default())) {
        Ok(a) => a,
        Err(e) => {
            no_gpu(&format!("no adapter ({e})"));
            return None;
        }
    };
    eprintln!("GPU adapter: {:?}", adapter.get_info());
    match pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor::default())) {
        Ok(d) => Some(d),
        Err(e) => {
            no_gpu(&format!("no device ({e})"));
            None
        }
    }
}

fn storage_entry(binding: u32, read_only: bool) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::COMPUTE,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only },
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
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

    let Some((device, queue)) = gpu() else { return };

    let input = inputs(300);
    let expected: Vec<native::Output> = input.iter().map(|i| native::score(*i)).collect();

    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("sample_kernel"),
        source: wgpu::ShaderSource::Wgsl(wgsl.into()),
    });
    let bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: None,
        entries: &[storage_entry(0, true), storage_entry(1, true), storage_entry(2, false)],
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

fn xorshift(seed: u32) -> impl FnMut() -> u32 {
    let mut state = seed;
    move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    }
}

fn game_states(n: usize) -> Vec<native_update::GameState> {
    let mut next = xorshift(0x9e37_79b9);
    (0..n)
        .map(|k| {
            let mut wall = [0u32; 34];
            for w in wall.iter_mut() {
                *w = next() % 5;
            }
            let mut hands = [0u32; 20];
            for h in hands.iter_mut() {
                // Counts 0..3 in every nibble.
                *h = next() & 0x3333_3333;
            }
            native_update::GameState {
                seed: [next() | 1, next()],
                round: next() % 8,
                dealer: next() % 4,
                scores: [250, 250, 250, 250],
                wall,
                next_draw: 0,
                hands,
                melds: [0; 16],
                rivers: [0; 24],
                river_lens: 0,
                discarded: [0; 8],
                seat_flags: [0; 4],
                rewards: [1.0; 4],
                current: next() % 4,
                drawn: 0,
                // Some games end during the run, some are already over.
                steps: if k % 7 == 0 { 197 } else { next() % 50 },
                terminated: u32::from(k % 11 == 0),
                history: [0; 64],
            }
        })
        .collect()
}

/// Five `step` updates and one `pay_dealer` update of the same state buffer, each a separate
/// dispatch: the state stays on the device between them, as in the engine's GPU backend.
#[test]
fn update_kernel_matches_native_on_gpu() {
    let source = Source {
        path: "tests/fixtures/update_kernel.rs".into(),
        text: include_str!("fixtures/update_kernel.rs").into(),
    };
    let update = |name: &str, function: &str, arg: &str| {
        EntryPoint::Update(UpdateEntry {
            name: name.into(),
            function: function.into(),
            state: "GameState".into(),
            arg: arg.into(),
            guard: None,
        })
    };
    let wgsl = translate_entry_points(
        &[source],
        &[
            update("step_main", "step", "StepArg"),
            update("pay_main", "pay_dealer", "u32"),
        ],
    )
    .unwrap_or_else(|e| panic!("{e}"));

    let Some((device, queue)) = gpu() else { return };

    const N: usize = 300;
    const STEPS: usize = 5;
    let initial = game_states(N);
    let mut next = xorshift(0x1234_5677);
    let step_args: Vec<Vec<native_update::StepArg>> = (0..STEPS)
        .map(|_| {
            (0..N)
                .map(|_| native_update::StepArg {
                    action: next() % 110,
                    bonus: (next() % 61) as i32 - 30,
                })
                .collect()
        })
        .collect();
    let pay_args: Vec<u32> = (0..N).map(|_| next() % 1000).collect();

    let mut expected = initial.clone();
    for args in &step_args {
        for (s, a) in expected.iter_mut().zip(args) {
            native_update::step(s, *a);
        }
    }
    for (s, a) in expected.iter_mut().zip(&pay_args) {
        native_update::pay_dealer(s, *a);
    }

    let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some("update_kernel"),
        source: wgpu::ShaderSource::Wgsl(wgsl.into()),
    });
    let tables = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("tables"),
        // The kernel does not read tables; WebGPU does not allow empty bindings.
        contents: bytemuck::cast_slice(&[0u32]),
        usage: wgpu::BufferUsages::STORAGE,
    });
    let state_size = std::mem::size_of_val(initial.as_slice()) as u64;
    let states = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("states"),
        contents: bytemuck::cast_slice(&initial),
        usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
    });
    let readback = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: state_size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });

    // (entry point, k, argument bytes) in dispatch order.
    let mut dispatches: Vec<(&str, u32, &[u8])> = step_args
        .iter()
        .map(|a| ("step_main", 0, bytemuck::cast_slice::<_, u8>(a)))
        .collect();
    dispatches.push(("pay_main", 1, bytemuck::cast_slice(&pay_args)));

    let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor::default());
    for (entry, k, arg_bytes) in dispatches {
        let (bstate, barg) = (1 + 2 * k, 2 + 2 * k);
        let bgl = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: None,
            entries: &[
                storage_entry(0, true),
                storage_entry(bstate, false),
                storage_entry(barg, true),
            ],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: None,
            bind_group_layouts: &[Some(&bgl)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some(entry),
            layout: Some(&layout),
            module: &module,
            entry_point: Some(entry),
            compilation_options: Default::default(),
            cache: None,
        });
        let args = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("args"),
            contents: arg_bytes,
            usage: wgpu::BufferUsages::STORAGE,
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
                    binding: bstate,
                    resource: states.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: barg,
                    resource: args.as_entire_binding(),
                },
            ],
        });
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor::default());
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &bind_group, &[]);
        pass.dispatch_workgroups((N as u32).div_ceil(64), 1, 1);
    }
    encoder.copy_buffer_to_buffer(&states, 0, &readback, 0, state_size);
    queue.submit([encoder.finish()]);
    readback.map_async(wgpu::MapMode::Read, .., |r| r.expect("map readback buffer"));
    device.poll(wgpu::PollType::wait_indefinitely()).expect("poll");
    let view = readback.get_mapped_range(..).expect("mapped range");
    let got: &[native_update::GameState] = bytemuck::cast_slice(&view);

    assert_eq!(got.len(), N);
    assert!(
        expected.iter().zip(&initial).any(|(e, i)| e.terminated != i.terminated),
        "the run should end some games"
    );
    for (k, (g, e)) in got.iter().zip(&expected).enumerate() {
        let g: &[u32] = bytemuck::cast_slice(std::slice::from_ref(g));
        let e: &[u32] = bytemuck::cast_slice(std::slice::from_ref(e));
        assert_eq!(g, e, "state {k}: GPU (left) differs from native (right)");
    }
}
