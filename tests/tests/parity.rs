//! CPU/GPU parity: the native kernels and their WGSL translation give identical words.

use rinshan_engine::gpu::Kernel;
use rinshan_engine::hand::{self, score_input, SCORE_OUT_WORDS, SHANTEN_OUT_WORDS};
use rinshan_engine::random::{random_hand, random_win, Rng};
use rinshan_engine::Variant;
use rinshan_tests::gpu_or_skip;

const HANDS: usize = 100_000;

fn first_difference(cpu: &[u32], gpu: &[u32], record: usize) -> Option<(usize, Vec<u32>, Vec<u32>)> {
    (0..cpu.len() / record).find_map(|i| {
        let (c, g) = (&cpu[i * record..(i + 1) * record], &gpu[i * record..(i + 1) * record]);
        (c != g).then(|| (i, c.to_vec(), g.to_vec()))
    })
}

#[test]
fn shanten_is_identical_on_cpu_and_gpu() {
    let Some(mut gpu) = gpu_or_skip("shanten parity") else {
        return;
    };
    let mut rng = Rng::new(11);
    let inputs: Vec<u32> = (0..HANDS)
        .flat_map(|i| hand::shanten_input(&random_hand(&mut rng, [14, 13, 11, 10, 8, 7, 5, 4, 2, 1][i % 10])))
        .collect();
    let mut cpu = vec![0u32; HANDS * SHANTEN_OUT_WORDS];
    hand::shanten_batch_par(&inputs, &mut cpu);
    let out = gpu.run(Variant::Red, Kernel::Shanten, &inputs).expect("gpu run");
    assert_eq!(out.len(), cpu.len());
    assert_eq!(
        first_difference(&cpu, &out, SHANTEN_OUT_WORDS),
        None,
        "first differing hand (index, cpu, gpu)"
    );
}

#[test]
fn scoring_is_identical_on_cpu_and_gpu() {
    let Some(mut gpu) = gpu_or_skip("scoring parity") else {
        return;
    };
    for (seed, &variant) in Variant::ALL.iter().enumerate() {
        let mut rng = Rng::new(100 + seed as u64);
        let mut inputs = Vec::with_capacity(HANDS * hand::SCORE_IN_WORDS);
        for _ in 0..HANDS {
            inputs.extend(score_input(&random_win(&mut rng)).expect("random wins are consistent"));
        }
        let mut cpu = vec![0u32; HANDS * SCORE_OUT_WORDS];
        hand::score_batch_par(variant, &inputs, &mut cpu);
        let wins = cpu.chunks(SCORE_OUT_WORDS).filter(|o| o[0] == 0).count();
        assert!(wins > HANDS / 2, "{variant}: most random wins have a yaku ({wins})");
        let out = gpu.run(variant, Kernel::Score, &inputs).expect("gpu run");
        assert_eq!(
            first_difference(&cpu, &out, SCORE_OUT_WORDS),
            None,
            "{variant}: first differing hand"
        );
    }
}

#[test]
fn garbage_score_inputs_are_rejected_identically() {
    let Some(mut gpu) = gpu_or_skip("bad input parity") else {
        return;
    };
    let mut rng = Rng::new(5);
    let n = 20_000;
    // Random words: the kernel must reject them (status 3) or judge them the same way on both sides.
    let inputs: Vec<u32> = (0..n * hand::SCORE_IN_WORDS)
        .map(|i| {
            if i % hand::SCORE_IN_WORDS < 34 {
                rng.below(3)
            } else {
                rng.below(40)
            }
        })
        .collect();
    let mut cpu = vec![0u32; n * SCORE_OUT_WORDS];
    hand::score_batch(Variant::Red, &inputs, &mut cpu);
    let out = gpu.run(Variant::Red, Kernel::Score, &inputs).expect("gpu run");
    assert_eq!(first_difference(&cpu, &out, SCORE_OUT_WORDS), None);
}
