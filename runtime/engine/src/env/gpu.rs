//! The GPU side of [`crate::env::Env`]: the B game states live in one storage buffer on the device.
//! A reset uploads the `ResetInput`s and runs `game_new_main` into the state buffer; a step
//! uploads B action ids, runs the step's five passes on the states in place (`game_step_main`,
//! then `game_claims_main`, `game_flow_main`, `game_settle_main` and `game_mask_main`: the step in
//! one shader took drivers minutes to compile), then `game_view_main`; only the `StepView`s come
//! back. A forced deal (log replay) uploads `DealInput`s and runs `game_deal_main` on the states
//! in place. Hero mode alternates `game_play_action_main` (the agents) and the step's passes
//! until every env waits for the caller, as the CPU kernel's `game_play` loops: one shader
//! holding the step and the agents took drivers minutes to compile, and NVIDIA's lost the device
//! on it.

use crate::generated::kernel as k;
use crate::gpu::{groups, EntrySpec, Gpu, GpuError};
use crate::observe::Form;
use crate::Variant;

fn make_buffer(device: &wgpu::Device, label: &str, size: u64, usage: wgpu::BufferUsages) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some(label),
        size,
        usage,
        mapped_at_creation: false,
    })
}

/// Records one dispatch of `pipeline` over `workgroups` groups, as a compute pass of its own (so
/// that wgpu orders it after the passes recorded before it).
fn encode_pass(
    encoder: &mut wgpu::CommandEncoder,
    label: &str,
    pipeline: &wgpu::ComputePipeline,
    bind_group: &wgpu::BindGroup,
    workgroups: u32,
) {
    let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
        label: Some(label),
        timestamp_writes: None,
    });
    pass.set_pipeline(pipeline);
    pass.set_bind_group(0, bind_group, &[]);
    pass.dispatch_workgroups(workgroups, 1, 1);
}

/// The read entry point that writes `form`.
fn observe_entry(form: Form) -> &'static str {
    match form {
        Form::Planes => "observe_planes_main",
        Form::Tokens => "observe_tokens_main",
        Form::Packed => "observe_packed_main",
        Form::Analysis => "observe_analysis_main",
        Form::Oracle => "observe_oracle_main",
    }
}

const NEW: &str = "game_new_main";
const VIEW: &str = "game_view_main";
const STEP: &str = "game_step_main";
const CLAIMS: &str = "game_claims_main";
const FLOW: &str = "game_flow_main";
const SETTLE: &str = "game_settle_main";
const MASK: &str = "game_mask_main";
const DEAL: &str = "game_deal_main";
const AGENT_ACTION: &str = "agent_action_main";
const PLAY_ACTION: &str = "game_play_action_main";

/// The passes, made on first use (a driver may take long to compile the step pipeline).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Stage {
    New = 0,
    Step = 1,
    Claims = 2,
    Flow = 3,
    Settle = 4,
    Mask = 5,
    View = 6,
    Deal = 7,
}

/// A step's passes, in order (entries.rs): the first reads the action ids (or hero mode's
/// decisions), the others only the states.
const STEP_PASSES: [Stage; 5] = [Stage::Step, Stage::Claims, Stage::Flow, Stage::Settle, Stage::Mask];

struct Pass {
    pipeline: wgpu::ComputePipeline,
    bind_group: wgpu::BindGroup,
}

pub(crate) struct GpuEnv {
    pub(super) gpu: Gpu,
    batch: usize,
    state_bytes: u64,
    view_bytes: u64,
    states: wgpu::Buffer,
    reset_inputs: wgpu::Buffer,
    actions: wgpu::Buffer,
    /// Made on the first forced deal: most envs never use it.
    deal_inputs: Option<wgpu::Buffer>,
    deal_words: usize,
    views_buffer: wgpu::Buffer,
    view_readback: wgpu::Buffer,
    wgsl: &'static str,
    passes: [Option<Pass>; Stage::Deal as usize + 1],
    /// Hero mode's passes and buffers, made on its first step.
    play: Option<PlayPasses>,
    /// The words of the last upload that the host rewrites first (clamped action ids, hero mode's
    /// first decisions), kept so that a step allocates nothing.
    upload: Vec<u32>,
    /// The last views read back (StepView words of every env).
    views: Vec<u32>,
    /// Observations, made on first use: observer seats, and per form its pass, output and readback.
    observer_args: Option<wgpu::Buffer>,
    reads: std::collections::HashMap<&'static str, ReadPass>,
}

/// Hero mode's agents pass (`game_play_action_main`) with its two argument buffers (the call's
/// first decision, the later ones), the decisions it writes, and the step's pass reading them.
struct PlayPasses {
    action: wgpu::ComputePipeline,
    first_group: wgpu::BindGroup,
    later_group: wgpu::BindGroup,
    step_group: wgpu::BindGroup,
    first_args: wgpu::Buffer,
    later_args: wgpu::Buffer,
    actions: wgpu::Buffer,
    readback: wgpu::Buffer,
    bytes: u64,
    words: Vec<u32>,
}

/// One read entry's pass (observations, agents' actions), its output buffer and its readback, and
/// the last words read.
struct ReadPass {
    pass: Pass,
    out: wgpu::Buffer,
    readback: wgpu::Buffer,
    bytes: u64,
    words: Vec<u32>,
}

impl GpuEnv {
    pub(crate) fn new(
        gpu: Gpu,
        variant: Variant,
        batch: usize,
        (reset_words, state_words, view_words): (usize, usize, usize),
        deal_words: usize,
    ) -> Result<GpuEnv, GpuError> {
        let wgsl = with_variant!(variant, v => v::WGSL);
        let words = |n: usize| (batch * n * 4) as u64;
        let (state_bytes, view_bytes) = (words(state_words), words(view_words));
        let buffer = |gpu: &Gpu, label: &str, size: u64, usage| make_buffer(gpu.device(), label, size, usage);
        use wgpu::BufferUsages as U;
        let states = buffer(
            &gpu,
            "rinshan states",
            state_bytes,
            U::STORAGE | U::COPY_SRC | U::COPY_DST,
        );
        let reset_inputs = buffer(
            &gpu,
            "rinshan reset inputs",
            words(reset_words),
            U::STORAGE | U::COPY_DST,
        );
        let actions = buffer(&gpu, "rinshan actions", words(1), U::STORAGE | U::COPY_DST);
        let views = buffer(&gpu, "rinshan views", view_bytes, U::STORAGE | U::COPY_SRC);
        let view_readback = buffer(&gpu, "rinshan views readback", view_bytes, U::MAP_READ | U::COPY_DST);
        Ok(GpuEnv {
            gpu,
            batch,
            state_bytes,
            view_bytes,
            states,
            reset_inputs,
            actions,
            deal_inputs: None,
            deal_words,
            views_buffer: views,
            view_readback,
            wgsl,
            passes: Default::default(),
            play: None,
            upload: Vec::with_capacity(batch),
            views: Vec::with_capacity(batch * view_words),
            observer_args: None,
            reads: std::collections::HashMap::new(),
        })
    }

    pub(crate) fn adapter(&self) -> String {
        self.gpu.adapter()
    }

    pub(crate) fn is_software(&self) -> bool {
        self.gpu.is_software()
    }

    fn ensure(&mut self, stage: Stage) {
        if self.passes[stage as usize].is_some() {
            return;
        }
        let (spec, first, second) = match stage {
            Stage::New => (EntrySpec::map(NEW), &self.reset_inputs, &self.states),
            Stage::Step => (EntrySpec::update(STEP), &self.states, &self.actions),
            // Their argument is unused: any buffer of a word per env binds.
            Stage::Claims => (EntrySpec::update(CLAIMS), &self.states, &self.actions),
            Stage::Flow => (EntrySpec::update(FLOW), &self.states, &self.actions),
            Stage::Settle => (EntrySpec::update(SETTLE), &self.states, &self.actions),
            Stage::Mask => (EntrySpec::update(MASK), &self.states, &self.actions),
            Stage::View => (EntrySpec::map(VIEW), &self.states, &self.views_buffer),
            Stage::Deal => {
                let Some(deals) = &self.deal_inputs else {
                    unreachable!("`deal` makes the buffer before the pass")
                };
                (EntrySpec::update(DEAL), &self.states, deals)
            }
        };
        let (pipeline, layout) = self.gpu.pipeline(self.wgsl, spec);
        let bind_group = self.gpu.bind_group(&layout, spec, first, second, None);
        self.passes[stage as usize] = Some(Pass { pipeline, bind_group });
    }

    /// Replaces every env's state with `states` and reads their views back.
    pub(crate) fn load(&mut self, states: &[u32]) -> Result<&[u32], GpuError> {
        self.gpu
            .queue()
            .write_buffer(&self.states, 0, bytemuck::cast_slice(states));
        self.dispatch(&[])
    }

    /// Runs the passes of `stages` in order over the batch, then the view pass, and reads the
    /// views back.
    fn dispatch(&mut self, stages: &[Stage]) -> Result<&[u32], GpuError> {
        let stages = stages.iter().chain([&Stage::View]);
        for &stage in stages.clone() {
            self.ensure(stage);
        }
        let mut encoder = self
            .gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("rinshan env"),
            });
        for &stage in stages {
            let Some(p) = &self.passes[stage as usize] else {
                unreachable!("every stage's pass is made above")
            };
            encode_pass(
                &mut encoder,
                "rinshan env",
                &p.pipeline,
                &p.bind_group,
                groups(self.batch),
            );
        }
        encoder.copy_buffer_to_buffer(&self.views_buffer, 0, &self.view_readback, 0, self.view_bytes);
        self.gpu.queue().submit([encoder.finish()]);
        self.gpu.read_words(&self.view_readback, &mut self.views)?;
        Ok(&self.views)
    }

    pub(crate) fn reset(&mut self, inputs: &[u32]) -> Result<&[u32], GpuError> {
        self.gpu
            .queue()
            .write_buffer(&self.reset_inputs, 0, bytemuck::cast_slice(inputs));
        self.dispatch(&[Stage::New])
    }

    /// One step (`play`: hero mode, `actions` are `game_play` arguments).
    pub(crate) fn step(&mut self, actions: &[u32], play: bool) -> Result<&[u32], GpuError> {
        if play {
            return self.play(actions);
        }
        // `game_step_main` reads the hero-mode flags from the high bits: any id that high is
        // illegal, and stays so.
        self.upload.clear();
        self.upload.extend(actions.iter().map(|&a| a.min(k::PLAY_ADD - 1)));
        self.gpu
            .queue()
            .write_buffer(&self.actions, 0, bytemuck::cast_slice(&self.upload));
        self.dispatch(&STEP_PASSES)
    }

    /// Hero mode: the decisions of `game_play` (its arguments in `args`), one pass of the agents
    /// and the step's passes at a time, in growing batches of passes between checks for an env
    /// that still plays.
    fn play(&mut self, args: &[u32]) -> Result<&[u32], GpuError> {
        for stage in STEP_PASSES {
            self.ensure(stage);
        }
        if self.play.is_none() {
            self.play = Some(self.play_passes());
        }
        let Some(play) = &mut self.play else {
            unreachable!("made above")
        };
        // The step's passes: the first reads the decisions the agents' pass wrote.
        let mut step = [None; STEP_PASSES.len()];
        for (pass, stage) in step.iter_mut().zip(STEP_PASSES) {
            let Some(p) = &self.passes[stage as usize] else {
                unreachable!("made above")
            };
            let group = if stage == Stage::Step {
                &play.step_group
            } else {
                &p.bind_group
            };
            *pass = Some((&p.pipeline, group));
        }
        let queue = self.gpu.queue();
        self.upload.clear();
        self.upload.extend(args.iter().map(|&a| a | k::PLAY_FIRST));
        queue.write_buffer(&play.first_args, 0, bytemuck::cast_slice(&self.upload));
        queue.write_buffer(&play.later_args, 0, bytemuck::cast_slice(args));
        let groups = groups(self.batch);
        let encode = |encoder: &mut wgpu::CommandEncoder, pipeline, bind_group| {
            encode_pass(encoder, "rinshan hero mode", pipeline, bind_group, groups)
        };
        let encode_step = |encoder: &mut wgpu::CommandEncoder| {
            for (pipeline, group) in step.iter().flatten() {
                encode(encoder, pipeline, group);
            }
        };
        let device = self.gpu.device();
        let mut encoder = device.create_command_encoder(&Default::default());
        encode(&mut encoder, &play.action, &play.first_group);
        encode_step(&mut encoder);
        let mut played = 1;
        let mut chunk = 4;
        loop {
            for _ in 0..chunk.min(k::PLAY_LIMIT - played) {
                encode(&mut encoder, &play.action, &play.later_group);
                encode_step(&mut encoder);
                played += 1;
            }
            // The next decisions, to see whether any env still plays.
            encode(&mut encoder, &play.action, &play.later_group);
            encoder.copy_buffer_to_buffer(&play.actions, 0, &play.readback, 0, play.bytes);
            queue.submit([encoder.finish()]);
            self.gpu.read_words(&play.readback, &mut play.words)?;
            if played >= k::PLAY_LIMIT || play.words.iter().all(|&a| a == k::PLAY_DONE) {
                break;
            }
            chunk = (chunk * 2).min(256);
            encoder = device.create_command_encoder(&Default::default());
        }
        self.dispatch(&[])
    }

    fn play_passes(&mut self) -> PlayPasses {
        let device = self.gpu.device();
        let bytes = (self.batch * 4) as u64;
        let buffer = |label: &str, usage: wgpu::BufferUsages| make_buffer(device, label, bytes, usage);
        use wgpu::BufferUsages as U;
        let first_args = buffer("rinshan hero first args", U::STORAGE | U::COPY_DST);
        let later_args = buffer("rinshan hero args", U::STORAGE | U::COPY_DST);
        let actions = buffer("rinshan hero actions", U::STORAGE | U::COPY_SRC);
        let readback = buffer("rinshan hero actions readback", U::MAP_READ | U::COPY_DST);
        let spec = EntrySpec::read(PLAY_ACTION);
        let (action, layout) = self.gpu.pipeline(self.wgsl, spec);
        let first_group = self
            .gpu
            .bind_group(&layout, spec, &self.states, &first_args, Some(&actions));
        let later_group = self
            .gpu
            .bind_group(&layout, spec, &self.states, &later_args, Some(&actions));
        // The step's pipeline, cached: its layout for a bind group reading the decisions.
        let step = EntrySpec::update(STEP);
        let (_, step_layout) = self.gpu.pipeline(self.wgsl, step);
        let step_group = self.gpu.bind_group(&step_layout, step, &self.states, &actions, None);
        PlayPasses {
            action,
            first_group,
            later_group,
            step_group,
            first_args,
            later_args,
            actions,
            readback,
            bytes,
            words: Vec::new(),
        }
    }

    /// Deals the rounds of `inputs` (`DealInput` words of every env; `deal == 0` leaves an env alone).
    pub(crate) fn deal(&mut self, inputs: &[u32]) -> Result<&[u32], GpuError> {
        if self.deal_inputs.is_none() {
            self.deal_inputs = Some(make_buffer(
                self.gpu.device(),
                "rinshan deal inputs",
                (self.batch * self.deal_words * 4) as u64,
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            ));
        }
        if let Some(deals) = &self.deal_inputs {
            self.gpu.queue().write_buffer(deals, 0, bytemuck::cast_slice(inputs));
        }
        self.dispatch(&[Stage::Deal])
    }

    /// Observations of `form` for the seats in `args` (one per env; 4 = the current player), read
    /// back from the device.
    pub(crate) fn observe(&mut self, form: Form, args: &[u32]) -> Result<&[u32], GpuError> {
        self.read(observe_entry(form), form.words(), args)
    }

    /// The actions of the built-in agents seated as `args` says (a seats word per env).
    pub(crate) fn agent_actions(&mut self, args: &[u32]) -> Result<&[u32], GpuError> {
        self.read(AGENT_ACTION, 1, args)
    }

    /// Runs the read entry `entry` (`words` output words per env) on the states with `args`.
    fn read(&mut self, entry: &'static str, words: usize, args: &[u32]) -> Result<&[u32], GpuError> {
        let device = self.gpu.device().clone();
        let args_buffer = self.observer_args.get_or_insert_with(|| {
            make_buffer(
                &device,
                "rinshan observer seats",
                (self.batch * 4) as u64,
                wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
            )
        });
        self.gpu
            .queue()
            .write_buffer(args_buffer, 0, bytemuck::cast_slice(args));
        if !self.reads.contains_key(entry) {
            let bytes = (self.batch * words * 4) as u64;
            let buffer = |label: &str, usage: wgpu::BufferUsages| make_buffer(&device, label, bytes, usage);
            use wgpu::BufferUsages as U;
            let out = buffer("rinshan observations", U::STORAGE | U::COPY_SRC);
            let readback = buffer("rinshan observations readback", U::MAP_READ | U::COPY_DST);
            let spec = EntrySpec::read(entry);
            let (pipeline, layout) = self.gpu.pipeline(self.wgsl, spec);
            let Some(args_buffer) = &self.observer_args else {
                unreachable!("made above")
            };
            let bind_group = self
                .gpu
                .bind_group(&layout, spec, &self.states, args_buffer, Some(&out));
            self.reads.insert(
                entry,
                ReadPass {
                    pass: Pass { pipeline, bind_group },
                    out,
                    readback,
                    bytes,
                    words: Vec::new(),
                },
            );
        }
        let Some(o) = self.reads.get_mut(entry) else {
            unreachable!("made above")
        };
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("rinshan observe"),
        });
        encode_pass(
            &mut encoder,
            "rinshan observe",
            &o.pass.pipeline,
            &o.pass.bind_group,
            groups(self.batch),
        );
        encoder.copy_buffer_to_buffer(&o.out, 0, &o.readback, 0, o.bytes);
        self.gpu.queue().submit([encoder.finish()]);
        self.gpu.read_words(&o.readback, &mut o.words)?;
        Ok(&o.words)
    }

    /// Every env's `GameState` words, read back from the device.
    pub(crate) fn states(&self) -> Result<Vec<u32>, GpuError> {
        let readback = make_buffer(
            self.gpu.device(),
            "rinshan states readback",
            self.state_bytes,
            wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        );
        let mut encoder = self
            .gpu
            .device()
            .create_command_encoder(&wgpu::CommandEncoderDescriptor {
                label: Some("rinshan states"),
            });
        encoder.copy_buffer_to_buffer(&self.states, 0, &readback, 0, self.state_bytes);
        self.gpu.queue().submit([encoder.finish()]);
        let mut out = Vec::new();
        self.gpu.read_words(&readback, &mut out)?;
        Ok(out)
    }
}
