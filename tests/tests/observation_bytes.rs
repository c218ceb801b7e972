//! The bytes of the observation forms over random play are pinned, each seat's view at many
//! positions of four rule sets (red, no-red and M-League for four players, sanma for three):
//! making the view faster must keep them. The pinned
//! values were computed by the per-tile view code that the bit-parallel one replaced; a change of
//! meaning changes them, and its commit says why.

use rinshan_engine::env::{Config, Env, Observer};
use rinshan_engine::observe::{unpack_planes, Form};
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

use crate::game_invariants::Fingerprint;

/// Every seat's planes and tokens at every 4th step of random self-play (auto-reset, so many
/// rounds and games), and the analysis tier at every 40th. The packed planes, not hashed, must
/// unpack to the planes there.
fn fingerprint(variant: Variant) -> u64 {
    let mut config = Config::new(variant, 48);
    config.auto_reset = true;
    config.seed = 11;
    let mut env = Env::new(config).expect("env");
    env.reset().expect("reset");
    let mut rng = Rng::new(11);
    let mut hash = Fingerprint::new();
    for step in 0..1600 {
        if step % 4 == 0 {
            for seat in 0..variant.seats() {
                for form in [Form::Planes, Form::Tokens] {
                    hash.add_bytes(env.observe(form, Observer::Seat(seat)).expect("observe"));
                }
                let packed = env
                    .observe(Form::Packed, Observer::Seat(seat))
                    .expect("observe")
                    .to_vec();
                let planes = env.observe(Form::Planes, Observer::Seat(seat)).expect("observe");
                assert!(
                    packed
                        .chunks(Form::Packed.bytes())
                        .map(unpack_planes)
                        .eq(planes.chunks(Form::Planes.bytes()).map(|p| Some(p.to_vec()))),
                    "{variant}: step {step}: seat {seat}'s packed planes do not unpack to its planes"
                );
                if step % 40 == 0 {
                    hash.add_bytes(env.observe(Form::Analysis, Observer::Seat(seat)).expect("observe"));
                }
            }
        }
        let actions: Vec<u32> = env.last().legal_action_mask.iter().map(|m| rng.pick_legal(m)).collect();
        env.step(&actions).expect("legal random actions");
    }
    hash.0
}

#[test]
fn red_observation_bytes_are_pinned() {
    assert_eq!(format!("{:016x}", fingerprint(Variant::Red)), "201fdcd40f33bc08");
}

#[test]
fn no_red_observation_bytes_are_pinned() {
    assert_eq!(format!("{:016x}", fingerprint(Variant::NoRed)), "9fc4f0e155a7e0d7");
}

#[test]
fn mleague_observation_bytes_are_pinned() {
    assert_eq!(format!("{:016x}", fingerprint(Variant::Mleague)), "b60ce4613669aa65");
}

/// Three players' observations come from the kernel's writers on the CPU too (the views that
/// follow the log take four seats). Re-pinned when the kan dora of a kan whose replacement tile is
/// set aside as a North came to show at the kita: positions after such a kita show one more dora
/// indicator (without that change alone the old value comes back), though the 10,000-game
/// fingerprint of sanma's outcomes held.
#[test]
fn sanma_observation_bytes_are_pinned() {
    assert_eq!(format!("{:016x}", fingerprint(Variant::Sanma)), "0bc74301a2a5d184");
}
