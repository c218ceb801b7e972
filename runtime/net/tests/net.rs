//! A net's file read and played: the forward pass against a plain reference written from the
//! training example's definition (the tile head as one layer over the column and the context side
//! by side), legal play over whole games, the same decisions whatever the hidden tiles are, and
//! files that do not fit refused with the reason.

use std::collections::HashMap;
use std::sync::Arc;

use rinshan_engine::env::{action_names, Mode};
use rinshan_engine::generated::kernel::GameState;
use rinshan_engine::observe::{field_values, record, resample_hidden, Form, OwnDraws, PLANE_ROWS};
use rinshan_engine::random::Rng;
use rinshan_engine::{with_variant, Variant};
use rinshan_net::inputs::Inputs;
use rinshan_net::model::MASKED;
use rinshan_net::random::{net_file, Shape};
use rinshan_net::{Net, NetAgent};
use safetensors::SafeTensors;

fn step(variant: Variant, s: &mut GameState, a: u32) {
    with_variant!(variant, v => v::game_step(s, a))
}

fn load(bytes: &[u8]) -> Net {
    Net::from_bytes(bytes, "test.safetensors", "test".into()).expect("a random net reads")
}

/// The tensors of a file as f32 values by name.
fn weights(bytes: &[u8]) -> HashMap<String, (Vec<usize>, Vec<f64>)> {
    let st = SafeTensors::deserialize(bytes).expect("safetensors");
    st.tensors()
        .into_iter()
        .map(|(name, view)| {
            let values: Vec<f64> = match view.dtype() {
                safetensors::Dtype::F32 => view
                    .data()
                    .chunks(4)
                    .map(|c| f64::from(f32::from_le_bytes([c[0], c[1], c[2], c[3]])))
                    .collect(),
                _ => view
                    .data()
                    .chunks(8)
                    .map(|c| i64::from_le_bytes(c.try_into().expect("8 bytes")) as f64)
                    .collect(),
            };
            (name, (view.shape().to_vec(), values))
        })
        .collect()
}

/// `W x + b` for `name`.
fn linear(w: &HashMap<String, (Vec<usize>, Vec<f64>)>, name: &str, x: &[f64]) -> Vec<f64> {
    let (shape, weight) = &w[&format!("{name}.weight")];
    let bias = &w[&format!("{name}.bias")].1;
    (0..shape[0])
        .map(|o| bias[o] + (0..shape[1]).map(|i| weight[o * shape[1] + i] * x[i]).sum::<f64>())
        .collect()
}

fn relu(x: Vec<f64>) -> Vec<f64> {
    x.into_iter().map(|v| v.max(0.0)).collect()
}

/// The training example's `Net.forward` for one decision, in f64, from the state.
fn reference(w: &HashMap<String, (Vec<usize>, Vec<f64>)>, variant: Variant, s: &GameState, analysis: bool) -> Vec<f64> {
    let planes = record(variant, Form::Planes, s, 4);
    let mut rows: Vec<f64> = field_values(Form::Planes, &planes, "planes")
        .into_iter()
        .map(|v| v as f64)
        .collect();
    let drawn = PLANE_ROWS.iter().find(|r| r.name == "drawn").expect("a drawn row").row as usize;
    let drawn_row: Vec<f64> = rows[drawn * 34..(drawn + 1) * 34].to_vec();
    if analysis {
        let a = record(variant, Form::Analysis, s, 4);
        rows.extend(
            field_values(Form::Analysis, &a, "discard_shanten")
                .into_iter()
                .map(|v| (v + 1) as f64),
        );
        rows.extend(
            field_values(Form::Analysis, &a, "discard_ukeire")
                .into_iter()
                .map(|v| v as f64),
        );
        rows.extend(
            field_values(Form::Analysis, &a, "improving")
                .into_iter()
                .map(|v| v as f64),
        );
    }
    let n_rows = rows.len() / 34;
    let scale = &w["row_scale"].1;
    let x: Vec<f64> = rows.iter().enumerate().map(|(i, v)| v * scale[i / 34]).collect();
    let (mean, std) = (&w["scalar_mean"].1, &w["scalar_std"].1);
    let scalars = field_values(Form::Planes, &planes, "scalars");
    let mut g: Vec<f64> = x.clone();
    g.extend(scalars.iter().enumerate().map(|(i, &v)| (v as f64 - mean[i]) / std[i]));
    let mut layer = 0;
    while w.contains_key(&format!("torso.{layer}.weight")) {
        g = relu(linear(w, &format!("torso.{layer}"), &g));
        layer += 2;
    }
    let mut logits = linear(w, "head", &g);
    if w.contains_key("tile_context.weight") {
        let context = linear(w, "tile_context", &g);
        let per_tile: Vec<f64> = (0..34)
            .map(|t| {
                let mut input: Vec<f64> = (0..n_rows).map(|r| x[r * 34 + t]).collect();
                input.extend(&context);
                linear(w, "tile_head.2", &relu(linear(w, "tile_head.0", &input)))[0]
            })
            .collect();
        let drawn = (0..34).fold(0, |b, i| if drawn_row[i] > drawn_row[b] { i } else { b });
        let columns = &w["discard_column"].1;
        let is_discard = &w["is_discard"].1;
        for (a, l) in logits.iter_mut().enumerate() {
            let c = columns[a] as usize;
            *l += is_discard[a] * if c == 34 { per_tile[drawn] } else { per_tile[c] };
        }
    }
    logits
}

/// States of `variant` games played by the rule agent, every `every`-th decision.
fn positions(variant: Variant, mode: Mode, games: u64, every: usize) -> Vec<GameState> {
    let mut out = Vec::new();
    for g in 0..games {
        let mut s: GameState = variant.new_game(g, mode);
        let mut k = 0;
        while s.terminated == 0 {
            if k % every == 0 {
                out.push(s);
            }
            k += 1;
            let a = rinshan_engine::agents::Agent::Rule.act(variant, &s);
            step(variant, &mut s, a);
        }
    }
    out
}

#[test]
fn the_forward_pass_is_the_training_examples_function() {
    for (shape, variant, mode) in [
        (Shape::default(), Variant::Red, Mode::Half),
        (
            Shape {
                analysis: false,
                tile_hidden: None,
                layers: 1,
                hidden: 32,
                kita: false,
            },
            Variant::NoRed,
            Mode::Single,
        ),
        (Shape::default(), Variant::Sanma, Mode::East),
        (
            Shape {
                layers: 3,
                ..Shape::default()
            },
            Variant::NoRed,
            Mode::East,
        ),
    ] {
        let bytes = net_file(shape, 7);
        let (net, w) = (load(&bytes), weights(&bytes));
        let agent = NetAgent::new(Arc::new(net), variant).expect("the net's actions cover the variant's");
        let states = positions(variant, mode, 2, 3);
        let mut inputs = agent.inputs();
        for s in &states {
            agent.push(&mut inputs, s);
        }
        let got = agent.net().logits(&inputs).expect("forward");
        let names = action_names(variant);
        let actions = agent.net().actions.len();
        let mut checked = 0;
        for (s, row) in states.iter().zip(got.chunks(actions)) {
            let want = reference(&w, variant, s, shape.analysis);
            for (a, name) in agent.net().actions.iter().enumerate() {
                let legal = names
                    .iter()
                    .position(|n| n == name)
                    .is_some_and(|e| s.mask[e / 32] >> (e % 32) & 1 == 1);
                if !legal {
                    assert_eq!(row[a], MASKED, "{name} is not legal: masked");
                    continue;
                }
                let tolerance = 1e-4 * (1.0 + want[a].abs());
                assert!(
                    (f64::from(row[a]) - want[a]).abs() < tolerance,
                    "{name}: {} vs {}",
                    row[a],
                    want[a]
                );
                checked += 1;
            }
        }
        assert!(checked > 200, "{checked} logits checked");
    }
}

#[test]
fn a_net_plays_whole_games_legally_in_every_variant() {
    let net = Arc::new(load(&net_file(Shape::default(), 3)));
    let red_only = Arc::new(load(&net_file(Shape::red_only(), 3)));
    for &variant in Variant::ALL.iter() {
        // A net of red's actions alone is refused exactly where the variant has one red lacks
        // (three players' kita); a net of every variant's actions plays them all.
        let missing = action_names(variant)
            .into_iter()
            .any(|a| !action_names(Variant::Red).contains(&a));
        assert_eq!(NetAgent::new(red_only.clone(), variant).is_err(), missing, "{variant}");
        let agent = NetAgent::new(net.clone(), variant).expect("every variant's actions");
        for g in 0..2 {
            let mut s: GameState = variant.new_game(100 + g, Mode::East);
            let mut decisions = 0;
            while s.terminated == 0 {
                let a = agent.act(&s).expect("a decision");
                assert!(s.mask[a as usize / 32] >> (a % 32) & 1 == 1, "{variant}: illegal {a}");
                step(variant, &mut s, a);
                decisions += 1;
            }
            assert_eq!(s.illegal, 0);
            assert!(decisions > 50, "{variant}: a game of {decisions} decisions");
        }
    }
}

#[test]
fn batched_decisions_are_the_single_ones() {
    let agent = NetAgent::new(Arc::new(load(&net_file(Shape::default(), 5))), Variant::Red).expect("red");
    let states = positions(Variant::Red, Mode::East, 2, 2);
    let batch = agent.act_many(&states).expect("batch");
    let single: Vec<u32> = states.iter().map(|s| agent.act(s).expect("one")).collect();
    assert_eq!(batch, single);
}

#[test]
fn decisions_do_not_change_when_the_hidden_tiles_are_dealt_again() {
    let variant = Variant::Red;
    let agent = NetAgent::new(Arc::new(load(&net_file(Shape::default(), 9))), variant).expect("red");
    let mut rng = Rng::new(1);
    let mut checked = 0;
    for g in 0..3 {
        let mut s: GameState = variant.new_game(g, Mode::East);
        let mut own: [OwnDraws; 4] = Default::default();
        for (q, o) in own.iter_mut().enumerate() {
            o.update(variant, &s, &mut s.clone(), q as u32);
        }
        while s.terminated == 0 {
            let me = s.current;
            let a = agent.act(&s).expect("a decision");
            for _ in 0..2 {
                let other = resample_hidden(variant, &s, me, &own[me as usize].positions, &mut rng);
                assert_eq!(agent.act(&other).expect("a decision"), a, "seat {me} saw hidden tiles");
                checked += 1;
            }
            let before = s;
            step(variant, &mut s, a);
            for (q, o) in own.iter_mut().enumerate() {
                o.update(variant, &before, &mut s.clone(), q as u32);
            }
        }
    }
    assert!(checked > 300);
}

#[test]
fn files_that_do_not_fit_are_refused_with_the_reason() {
    let good = net_file(Shape::default(), 1);
    let read = |bytes: &[u8]| {
        Net::from_bytes(bytes, "x.safetensors", "x".into())
            .map(|_| ())
            .unwrap_err()
            .to_string()
    };
    assert!(read(b"not a net").contains("x.safetensors: not a safetensors file"));
    // The same tensors under other metadata.
    let st = SafeTensors::deserialize(&good).expect("safetensors");
    let (_, header) = SafeTensors::read_metadata(&good).expect("metadata");
    let meta = header.metadata().clone().expect("metadata");
    let with = |key: &str, value: &str, drop: Option<&str>| {
        let mut m = meta.clone();
        m.insert(key.into(), value.into());
        let tensors: Vec<_> = st
            .tensors()
            .into_iter()
            .filter(|(n, _)| Some(n.as_str()) != drop)
            .collect();
        safetensors::serialize(tensors, Some(m)).expect("serialize")
    };
    assert!(read(&with("format", "onnx", None)).contains("this reader takes rinshan-net version 1"));
    assert!(read(&with("plane_rows", "63", None)).contains("trained on observations of 63 plane_rows"));
    assert!(read(&with("analysis_rows", "[\"tenpai_odds\"]", None)).contains("lacks"));
    assert!(read(&with("actions", "[\"pass\"]", None)).contains("logits for 1 action names"));
    assert!(read(&with("version", "1", Some("head.bias"))).contains("no tensor `head.bias`"));
    let missing = std::env::temp_dir().join("rinshan-net-test-no-such-file.safetensors");
    let e = Net::load(&missing).unwrap_err().to_string();
    assert!(e.starts_with(&missing.display().to_string()), "{e}");
    // Inputs of another net's width are an error, not a panic.
    let net = load(&good);
    let mut inputs = Inputs::new(0, net.actions.len());
    assert!(inputs.push(&[0.0; 10], &[0.0; 48], |_| true).is_err());
    inputs
        .push(&vec![0.0; 64 * 34], &[0.0; 48], |_| true)
        .expect("a decision of 64 rows");
    assert!(net.logits(&inputs).is_err(), "a net of analysis rows given none");
}
