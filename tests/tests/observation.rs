//! The observation shows a seat only what it may know, and the same game seen from any seat
//! gives the same picture:
//! - hidden resampling: permuting every tile the observer cannot see (other hands, the wall, the
//!   hidden dead wall) and scrambling other seats' waits, furiten, claim options and choices, the
//!   seeds and the step counter leaves both forms and the analysis tier byte-identical;
//! - seat rotation: the same game with the seats relabelled gives each seat the same observation;
//! - the packed form unpacks to the planes' bytes, at every position the two tests above visit;
//! - the event tokens replay the round (each seat's discards in order, every draw of the
//!   observer with its tile).

use rinshan_engine::generated::kernel::{
    self, GameState, ObsAnalysis, ObsPacked, ObsPlanes, ObsTokens, ResetInput, MODE_HALF, OBSERVE_CURRENT,
};
use rinshan_engine::observe::{resample_hidden, unpack_planes, OwnDraws};
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// One variant's kernels, as plain functions.
#[derive(Clone, Copy)]
struct Kernels {
    variant: Variant,
    new: fn(ResetInput) -> GameState,
    step: fn(&mut GameState, u32),
    planes: fn(GameState, u32) -> ObsPlanes,
    tokens: fn(GameState, u32) -> ObsTokens,
    packed: fn(GameState, u32) -> ObsPacked,
    analysis: fn(GameState, u32) -> ObsAnalysis,
}

/// The kernels of `variant`.
fn kernels(variant: Variant) -> Kernels {
    rinshan_engine::with_variant!(variant, m => Kernels {
        variant,
        new: m::game_new,
        step: m::game_step,
        planes: m::observe_planes,
        tokens: m::observe_tokens,
        packed: m::observe_packed,
        analysis: m::observe_analysis,
    })
}

fn reset_input(seed: u64, dealer: u32, wall: Option<[u32; 136]>) -> ResetInput {
    ResetInput {
        seed: [seed as u32, (seed >> 32) as u32],
        mode: MODE_HALF,
        dealer,
        use_wall: u32::from(wall.is_some()),
        wall: wall.unwrap_or([0; 136]),
        uma: [15000, 5000, -5000, -15000],
        penalty: -1.0,
        auto_reset: 0,
    }
}

/// Planes followed by the packed planes, and tokens followed by the analysis tier; the packed
/// planes are checked to unpack to the planes.
fn both(k: &Kernels, s: &GameState, seat: u32) -> (Vec<u32>, Vec<u32>) {
    let mut tokens: Vec<u32> = bytemuck::cast_slice(&[(k.tokens)(*s, seat)]).to_vec();
    tokens.extend_from_slice(bytemuck::cast_slice(&[(k.analysis)(*s, seat)]));
    let planes = (k.planes)(*s, seat);
    let packed = (k.packed)(*s, seat);
    let unpacked = unpack_planes(bytemuck::bytes_of(&packed)).expect("one packed record");
    if unpacked != bytemuck::bytes_of(&planes) {
        let i = unpacked
            .iter()
            .zip(bytemuck::bytes_of(&planes))
            .position(|(a, b)| a != b)
            .unwrap_or(0);
        panic!(
            "{}: step {}, seat {seat}: packed planes unpack to {} at row {} type {}, the planes say {}",
            k.variant,
            s.steps,
            unpacked[i],
            i / 34,
            i % 34,
            bytemuck::bytes_of(&planes)[i]
        );
    }
    let mut planes: Vec<u32> = bytemuck::cast_slice(&[planes]).to_vec();
    planes.extend_from_slice(bytemuck::cast_slice(&[packed]));
    (planes, tokens)
}

fn hidden_resampling(k: Kernels) {
    let variant = k.variant;
    let mut rng = Rng::new(77);
    let mut states = 0usize;
    let mut game = 0u64;
    while states < 100_000 {
        let mut s = (k.new)(reset_input(1000 + game, 4, None));
        let mut draws: [OwnDraws; 4] = Default::default();
        for (q, d) in draws.iter_mut().enumerate() {
            d.update(variant, &s, &mut s.clone(), q as u32);
        }
        let mut policy = Rng::new(5000 + game);
        while s.terminated == 0 {
            let observer = rng.below(variant.seats());
            let (p, t) = both(&k, &s, observer);
            let r = resample_hidden(variant, &s, observer, &draws[observer as usize].positions, &mut rng);
            let (rp, rt) = both(&k, &r, observer);
            assert!(
                p == rp,
                "{variant}: game {game}, step {}: planes of seat {observer} changed when hidden tiles were resampled",
                s.steps
            );
            if t != rt {
                let i = t.iter().zip(&rt).position(|(a, b)| a != b).unwrap_or(0);
                eprintln!(
                    "word {i}: {:08x} vs {:08x}; own draws {:?}, next_draw {}, current {}, drawn {}",
                    t[i], rt[i], draws[observer as usize].positions, s.next_draw, s.current, s.drawn
                );
            }
            assert!(
                t == rt,
                "{variant}: game {game}, step {}: tokens of seat {observer} changed when hidden tiles were resampled",
                s.steps
            );
            states += 1;
            let before = s;
            let a = policy.pick_legal(&s.mask);
            (k.step)(&mut s, a);
            for (q, d) in draws.iter_mut().enumerate() {
                d.update(variant, &before, &mut s, q as u32);
            }
        }
        game += 1;
    }
    eprintln!("{variant}: {states} states of {game} half games, hidden tiles resampled, observations unchanged");
}

/// The same walls dealt with the seats relabelled by `shift`: seat q of the first game is seat
/// q + shift of the second, and must see exactly what it saw.
fn seat_rotation(k: Kernels) {
    let variant = k.variant;
    let mut checked = 0usize;
    for game in 0..12u64 {
        let first = (k.new)(reset_input(300 + game, 4, None));
        let wall: [u32; 136] = std::array::from_fn(|i| kernel::wall_tile(&mut first.clone(), i as u32));
        let dealer = first.dealer;
        let seats = variant.seats();
        let shift = 1 + (game as u32) % (seats - 1);
        let mut a = (k.new)(reset_input(300 + game, dealer, Some(wall)));
        let mut b = (k.new)(reset_input(300 + game, (dealer + shift) % seats, Some(wall)));
        let mut policy = Rng::new(9000 + game);
        while a.terminated == 0 {
            assert_eq!(
                (a.current + shift) % seats,
                b.current,
                "{variant}: game {game}: the relabelled game went another way"
            );
            for q in 0..seats {
                assert!(
                    both(&k, &a, q) == both(&k, &b, (q + shift) % seats),
                    "{variant}: game {game}, step {}: seat {q} and its relabelled seat {} see different things",
                    a.steps,
                    (q + shift) % seats
                );
            }
            checked += 1;
            let act = policy.pick_legal(&a.mask);
            (k.step)(&mut a, act);
            (k.step)(&mut b, act);
        }
        assert_eq!(b.terminated, 1);
    }
    eprintln!(
        "{variant}: {checked} positions x {} seats equal under seat relabelling",
        variant.seats()
    );
}

/// Both checks for each rule set, one test each, so that they run side by side.
macro_rules! each_rule_set {
    ($($variant:ident: $hidden:ident, $relabelled:ident;)*) => {$(
        #[test]
        fn $hidden() {
            hidden_resampling(kernels(Variant::$variant));
        }

        #[test]
        fn $relabelled() {
            seat_rotation(kernels(Variant::$variant));
        }
    )*};
}

each_rule_set! {
    Red: red_observations_do_not_depend_on_hidden_tiles, red_observations_are_the_same_from_relabelled_seats;
    NoRed: no_red_observations_do_not_depend_on_hidden_tiles, no_red_observations_are_the_same_from_relabelled_seats;
    Mjsoul: mjsoul_observations_do_not_depend_on_hidden_tiles, mjsoul_observations_are_the_same_from_relabelled_seats;
    Mleague: mleague_observations_do_not_depend_on_hidden_tiles, mleague_observations_are_the_same_from_relabelled_seats;
    Wrc: wrc_observations_do_not_depend_on_hidden_tiles, wrc_observations_are_the_same_from_relabelled_seats;
    Sanma: sanma_observations_do_not_depend_on_hidden_tiles, sanma_observations_are_the_same_from_relabelled_seats;
    MjsoulSanma: mjsoul_sanma_observations_do_not_depend_on_hidden_tiles, mjsoul_sanma_observations_are_the_same_from_relabelled_seats;
}

fn token_byte(t: &ObsTokens, at: u32) -> u8 {
    bytemuck::cast_slice::<u32, u8>(&t.words)[at as usize]
}

/// The event tokens replay each round: every seat's discards appear in its river's order with
/// the river's tsumogiri and called flags, the observer's draws show the tiles it received, and
/// nobody else's draw shows a tile.
#[test]
fn event_tokens_replay_the_rivers_and_own_draws() {
    let k = kernels(Variant::Red);
    let mut positions = 0;
    for game in 0..20u64 {
        let mut s = (k.new)(reset_input(40 + game, 4, None));
        let mut policy = Rng::new(game);
        let mut own: Vec<Vec<u32>> = vec![Vec::new(); 4];
        let mut round = (s.rounds, s.games);
        while s.terminated == 0 {
            if (s.rounds, s.games) != round {
                round = (s.rounds, s.games);
                own.iter_mut().for_each(Vec::clear);
            }
            if s.drawn != kernel::NO_TILE_VALUE && own[s.current as usize].last() != Some(&(s.next_draw * 64 + s.kans))
            {
                own[s.current as usize].push(s.next_draw * 64 + s.kans);
            }
            for seat in 0..4u32 {
                let t = (k.tokens)(s, seat);
                let n = token_byte(&t, kernel::T_EVENTS_LEN) as u32;
                let mut rivers: Vec<Vec<u32>> = vec![Vec::new(); 4];
                let mut draws = 0;
                for i in 0..n {
                    let e = t.words[(kernel::T_EVENTS / 4 + i) as usize];
                    let (kind, actor, tile, flags) = (e & 255, (e >> 8) & 255, (e >> 16) & 255, e >> 24);
                    let abs = (seat + actor) % 4;
                    if kind == kernel::EV_DISCARD {
                        rivers[abs as usize].push(
                            tile | (flags & kernel::LOG_TSUMOGIRI) << 7
                                | u32::from(flags & kernel::LOG_CALLED != 0) << 6,
                        );
                    }
                    if kind == kernel::EV_DRAW {
                        assert_eq!(
                            tile == kernel::NO_TILE_BYTE,
                            actor != 0,
                            "game {game}: a draw's tile is shown to its drawer only"
                        );
                        draws += u32::from(actor == 0);
                    }
                }
                for q in 0..4u32 {
                    let len = kernel::byte_of(s.river_lens, q);
                    let river: Vec<u32> = (0..len)
                        .map(|i| kernel::byte_of(s.rivers[(q * 6 + i / 4) as usize], i % 4))
                        .collect();
                    assert_eq!(
                        rivers[q as usize], river,
                        "game {game}, step {}: seat {seat}'s events disagree with seat {q}'s river",
                        s.steps
                    );
                }
                assert_eq!(
                    draws as usize,
                    own[seat as usize].len(),
                    "game {game}, step {}: seat {seat}'s own draws",
                    s.steps
                );
                positions += 1;
            }
            let a = policy.pick_legal(&s.mask);
            (k.step)(&mut s, a);
        }
    }
    assert!(positions > 10_000);
    let _ = OBSERVE_CURRENT;
}

/// Three players: each seat block's `meld_tiles` row counts, at North, the Norths the seat set
/// aside (counted here from the actions played) beside those of its melds; the fourth block stays
/// empty. Both forms that hold the row (planes, packed) are checked, the packed one through
/// `both`'s unpacking.
#[test]
fn sanma_planes_show_each_seats_norths_set_aside() {
    let k = kernels(Variant::Sanma);
    let names = rinshan_engine::env::action_names(Variant::Sanma);
    let kita_action = names.iter().position(|n| n == "kita").expect("sanma has kita") as u32;
    let north = 30usize;
    let row = |j: u32| ((kernel::P_SEAT + j * kernel::P_SEAT_ROWS + kernel::P_SEAT_MELD_TILES) * 34) as usize;
    let (mut positions, mut with_kita) = (0, 0);
    for game in 0..12u64 {
        let mut s = (k.new)(reset_input(70 + game, 0, None));
        let mut policy = Rng::new(game);
        let mut kita = [0u32; 3];
        let mut round = (s.rounds, s.games);
        while s.terminated == 0 {
            if (s.rounds, s.games) != round {
                round = (s.rounds, s.games);
                kita = [0; 3];
            }
            for seat in 0..3u32 {
                let (planes, _) = both(&k, &s, seat);
                let bytes: &[u8] = bytemuck::cast_slice(&planes);
                for j in 0..3u32 {
                    let q = (seat + j) % 3;
                    let in_melds: u32 = (0..kernel::meld_count(&mut s.clone(), q))
                        .map(|i| s.melds[(q * 4 + i) as usize])
                        .filter(|&m| kernel::meld_tile(m) == north as u32)
                        .map(|m| if kernel::meld_kind(m) == kernel::MELD_PON { 3 } else { 4 })
                        .sum();
                    assert_eq!(
                        u32::from(bytes[row(j) + north]),
                        kita[q as usize] + in_melds,
                        "game {game}, step {}: seat {seat}'s block {j}",
                        s.steps
                    );
                    with_kita += usize::from(kita[q as usize] > 0);
                }
                assert!(bytes[row(3)..row(3) + 34].iter().all(|&b| b == 0));
                positions += 1;
            }
            let a = policy.pick_legal(&s.mask);
            if a == kita_action {
                kita[s.current as usize] += 1;
            }
            (k.step)(&mut s, a);
        }
    }
    assert!(positions > 3_000 && with_kita > 1_000, "{positions} {with_kita}");
}

/// The analysis tier against its definition, computed the slow way with the shanten kernel (itself
/// checked against the shanten case files): after each discard, the shanten and the unseen copies
/// of every draw that lowers it; for a hand waiting to draw, those draws; the waits as in the
/// planes. The hand and the seen counts are read from the planes.
#[test]
fn analysis_is_shanten_and_ukeire_counted_draw_by_draw() {
    use kernel::{
        shanten, ShantenInput, A_DISCARD_SHANTEN, A_DISCARD_UKEIRE, A_IMPROVING, A_WAITS, P_HAND, P_SEEN, P_WAITS,
    };
    let k = kernels(Variant::Red);
    let sh = |h: &[u32; 34]| shanten(ShantenInput { hand: *h }).shanten;
    // The unseen copies of each draw that lowers the shanten of `h`.
    let improving = |h: &[u32; 34], unseen: &[u32; 34]| -> [u32; 34] {
        let base = sh(h);
        std::array::from_fn(|t| {
            let mut x = *h;
            x[t] += 1;
            if h[t] < 4 && sh(&x) < base {
                unseen[t]
            } else {
                0
            }
        })
    };
    let mut rng = Rng::new(31);
    let mut positions = 0;
    for game in 0..40u64 {
        let mut s = (k.new)(reset_input(7000 + game, 4, None));
        while s.terminated == 0 {
            let seat = rng.below(4);
            let planes = (k.planes)(s, seat);
            let p: &[u8] = bytemuck::cast_slice(&planes.planes);
            let cell = |row: u32, t: usize| u32::from(p[row as usize * 34 + t]);
            let hand: [u32; 34] = std::array::from_fn(|t| (0..4).map(|r| cell(P_HAND + r, t)).sum());
            let unseen: [u32; 34] = std::array::from_fn(|t| 4 - cell(P_SEEN, t));
            let analysis = (k.analysis)(s, seat);
            let a: &[u8] = bytemuck::cast_slice(&analysis.words);
            let at = |field: u32, t: usize| u32::from(a[field as usize + t]);
            let tiles: u32 = hand.iter().sum();
            for t in 0..34 {
                assert_eq!(at(A_WAITS, t), cell(P_WAITS, t), "game {game}, step {}: waits", s.steps);
                let (want_shanten, want_ukeire, want_improving) = if tiles % 3 == 2 {
                    let mut h = hand;
                    if h[t] == 0 {
                        (255, 0, 0)
                    } else {
                        h[t] -= 1;
                        (sh(&h) as u32, improving(&h, &unseen).iter().sum(), 0)
                    }
                } else {
                    (255, 0, improving(&hand, &unseen)[t])
                };
                let got = (at(A_DISCARD_SHANTEN, t), at(A_DISCARD_UKEIRE, t), at(A_IMPROVING, t));
                assert_eq!(
                    got,
                    (want_shanten, want_ukeire, want_improving),
                    "game {game}, step {}, seat {seat}, type {t}: hand {hand:?}",
                    s.steps
                );
            }
            positions += 1;
            let a = rng.pick_legal(&s.mask);
            (k.step)(&mut s, a);
        }
    }
    eprintln!("analysis: {positions} positions, each type's shanten and ukeire counted draw by draw");
}
