// What a yaku condition in `rules/yaku.toml` may name. `codegen` reads this struct to learn the
// feature names and their types (bool or u32), so adding a field here makes it usable in the spec.
// The scoring kernel fills one `Features` per reading of the winning hand.

#[derive(Clone, Copy)]
pub struct Features {
    /// No open meld (closed kans keep the hand concealed).
    pub concealed: bool,
    /// Won by self-draw.
    pub tsumo: bool,
    /// Riichi accepted before the win.
    pub riichi: bool,
    /// Riichi declared on the first uninterrupted turn.
    pub double_riichi: bool,
    /// Won within one uninterrupted go-around after riichi.
    pub ippatsu: bool,
    /// Tsumo on the last live tile.
    pub haitei: bool,
    /// Ron on the last discard.
    pub houtei: bool,
    /// Tsumo on a kan replacement tile.
    pub rinshan: bool,
    /// Ron on a tile added to a pon (robbing the kan).
    pub chankan: bool,
    /// Dealer's tsumo on the first draw.
    pub tenhou: bool,
    /// Non-dealer's tsumo on the first uninterrupted draw.
    pub chiihou: bool,
    /// The winner is the dealer.
    pub dealer: bool,
    /// This reading is four sets and a pair.
    pub standard: bool,
    /// This reading is seven distinct pairs.
    pub seven_pairs: bool,
    /// This reading is thirteen orphans.
    pub thirteen_orphans: bool,
    /// Thirteen orphans waiting on all thirteen kinds.
    pub thirteen_wait: bool,
    /// Every tile (melds included) is a simple (2-8).
    pub all_simples: bool,
    /// Every tile is a terminal or an honor.
    pub no_simples: bool,
    /// Every tile is an honor.
    pub honors_only: bool,
    /// Every tile is one of 2s 3s 4s 6s 8s or the green dragon.
    pub green_only: bool,
    /// At least one honor tile.
    pub has_honors: bool,
    /// Number of suits (m, p, s) that appear.
    pub suits: u32,
    /// Every set and the pair contain a terminal or an honor.
    pub outside: bool,
    /// Number of runs (chi melds included).
    pub runs: u32,
    /// Number of triplets and quads (melds included).
    pub triplets: u32,
    /// Triplets and quads counted as concealed (closed kans included, a triplet completed by ron excluded).
    pub concealed_triplets: u32,
    /// Number of quads (kans of any kind).
    pub kans: u32,
    /// Number of pairs of identical concealed runs (1 = iipeikou, 2 = ryanpeikou).
    pub identical_runs: u32,
    /// The winning tile completed a two-sided run wait.
    pub two_sided_wait: bool,
    /// The winning tile completed the pair.
    pub pair_wait: bool,
    /// The pair would give fu (dragon, seat wind or round wind).
    pub pair_is_value: bool,
    /// Triplet or quad of the seat wind.
    pub seat_wind_set: bool,
    /// Triplet or quad of the round wind.
    pub round_wind_set: bool,
    /// Triplet or quad of the white dragon.
    pub white_set: bool,
    /// Triplet or quad of the green dragon.
    pub green_set: bool,
    /// Triplet or quad of the red dragon.
    pub red_set: bool,
    /// Number of dragon triplets and quads.
    pub dragon_sets: u32,
    /// Number of wind triplets and quads.
    pub wind_sets: u32,
    /// The pair is a dragon.
    pub dragon_pair: bool,
    /// The pair is a wind.
    pub wind_pair: bool,
    /// Runs 123, 456 and 789 of one suit.
    pub straight: bool,
    /// The same run in all three suits.
    pub three_colour_runs: bool,
    /// The same triplet number in all three suits.
    pub three_colour_triplets: bool,
    /// Concealed 1112345678999 plus one tile of the same suit.
    pub nine_gates: bool,
    /// Nine gates whose hand before the win was exactly 1112345678999 (nine-sided wait).
    pub nine_gates_nine_wait: bool,
}
