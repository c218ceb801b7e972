//! A policy for tests that want games to reach every situation: it always wins when it can,
//! declares riichi and kans, calls often, and otherwise discards towards tenpai (a quarter of
//! the time at random), so that riichi, tenpai draws, double rons and kans come up often.

use rinshan_engine::env::ActionMap;
use rinshan_engine::generated::kernel::{self as kernel, GameState};
use rinshan_engine::generated::red as k;
use rinshan_engine::hand::shanten;
use rinshan_engine::random::Rng;
use rinshan_engine::Variant;

/// Whether action `a` is set in a legal-action mask.
pub fn legal(mask: &[u32; 3], a: u32) -> bool {
    mask[(a / 32) as usize] >> (a % 32) & 1 == 1
}

/// The biased policy of the red variant, from its own random stream.
pub struct Policy(pub Rng);

impl Policy {
    fn pick(&mut self, options: &[u32]) -> Option<u32> {
        (!options.is_empty()).then(|| options[self.0.below(options.len() as u32) as usize])
    }

    pub fn act(&mut self, s: &GameState, mask: &[u32; 3]) -> u32 {
        let all = |range: std::ops::Range<u32>| range.filter(|&a| legal(mask, a)).collect::<Vec<_>>();
        for (a, percent) in [
            (k::ACTION_TSUMO, 100),
            (k::ACTION_RON, 100),
            (k::ACTION_KYUUSHU, 50),
            (k::ACTION_RIICHI, 90),
        ] {
            if legal(mask, a) && self.0.chance(percent) {
                return a;
            }
        }
        let kans = all(k::ACTION_SELF_KAN..k::ACTION_SELF_KAN + k::ACTION_SELF_KAN_COUNT);
        let calls = [
            (all(k::ACTION_OPEN_KAN..k::ACTION_OPEN_KAN + 1), 70),
            (all(k::ACTION_PON..k::ACTION_PON_RED + 1), 50),
            (all(k::ACTION_CHI_LEFT..k::ACTION_CHI_RIGHT_RED + 1), 35),
            (kans, 80),
        ];
        for (options, percent) in calls {
            if !options.is_empty() && self.0.chance(percent) {
                return self.pick(&options).unwrap_or(k::ACTION_PASS);
            }
        }
        if legal(mask, k::ACTION_PASS) {
            return k::ACTION_PASS;
        }
        let mut discards = all(k::ACTION_DISCARD..k::ACTION_DISCARD + k::ACTION_DISCARD_COUNT);
        discards.extend(all(k::ACTION_TSUMOGIRI..k::ACTION_TSUMOGIRI + 1));
        if self.0.chance(25) {
            return self.pick(&discards).unwrap_or(k::ACTION_PASS);
        }
        let p = s.current as usize;
        let hand: [u8; 34] = kernel::hand_counts(&mut { *s }, p as u32).map(|n| n as u8);
        let after = |a: u32| {
            let v = if a == k::ACTION_TSUMOGIRI {
                s.drawn
            } else {
                a - k::ACTION_DISCARD
            };
            let t = kernel::value_type(v) as usize;
            let mut h = hand;
            h[t] -= 1;
            shanten(&h).shanten
        };
        let best = discards.iter().map(|&a| after(a)).min();
        let best: Vec<u32> = discards.iter().copied().filter(|&a| Some(after(a)) == best).collect();
        self.pick(&best).unwrap_or(k::ACTION_PASS)
    }
}

/// [`Policy`] for a game of any variant: the same choices, read and made in red's layout (every
/// variant's actions are red's kinds, [`ActionMap`]), and three players' kita, which red has
/// not, taken most times it is legal and no tsumo is.
pub struct VariantPolicy {
    policy: Policy,
    to_red: ActionMap,
    from_red: ActionMap,
    /// The variant's kita (`ACTION_ABSENT` for four players, never legal).
    kita: u32,
}

impl VariantPolicy {
    pub fn new(variant: Variant, rng: Rng) -> VariantPolicy {
        VariantPolicy {
            policy: Policy(rng),
            to_red: ActionMap::new(variant, Variant::Red),
            from_red: ActionMap::new(Variant::Red, variant),
            kita: rinshan_engine::with_variant!(variant, v => v::ACTION_KITA),
        }
    }

    pub fn act(&mut self, s: &GameState, mask: &[u32; 3]) -> u32 {
        let kita = self.kita < 96 && legal(mask, self.kita);
        // Only a legal kita draws from the stream: four-player games stay as they were.
        if kita && self.policy.0.chance(80) {
            let tsumo = self.from_red.get(k::ACTION_TSUMO);
            if !tsumo.is_some_and(|t| legal(mask, t)) {
                return self.kita;
            }
        }
        let mut red = [0u32; 3];
        for a in (0..96).filter(|&a| legal(mask, a)) {
            if let Some(r) = self.to_red.get(a) {
                red[(r / 32) as usize] |= 1 << (r % 32);
            }
        }
        let chosen = self.policy.act(s, &red);
        // The policy picks among the legal actions, which all have an id here.
        self.from_red.get(chosen).unwrap_or(0)
    }
}
