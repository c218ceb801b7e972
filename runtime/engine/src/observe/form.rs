//! The observation forms, and writing them on the CPU.

use super::fields::{Field, ANALYSIS_FIELDS, ORACLE_FIELDS, PACKED_FIELDS, PLANES_FIELDS, TOKENS_FIELDS};
use super::table_view::{TableView, EVENT_LIST, SEAT_ROWS};
use crate::batch::{each, each_followed};
use crate::generated::kernel as k;
use crate::names::UnknownName;

/// A form of the observation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Form {
    /// `planes (64, 34) uint8` and `scalars (48,) int16`: for MLP/CNN agents.
    Planes,
    /// Hand, melds, dora, the round's public events in order, and the scalars: for Transformers.
    Tokens,
    /// The planes in 1,336 bytes instead of 2,272: their yes/no rows as `bits (36,) uint64` (bit t
    /// = tile type t), their other rows as `counts (28, 34) uint8`, and the same scalars; for
    /// learners that unpack on their device ([`super::unpack_planes`], or `rinshan.unpack_planes`
    /// in Python).
    Packed,
    /// The opt-in analysis tier: shanten and ukeire after each discard, waits, improving draws.
    /// Computed from the observer's hand and the tiles it has seen: no more than it may know.
    Analysis,
    /// The opt-in oracle: what the observer cannot see (other hands, shanten, waits, furiten, the
    /// live wall in draw order, the replacement tiles, every dora and ura indicator). Hidden
    /// information for oracle guiding and centralised critics; never part of an observation.
    Oracle,
}

impl Form {
    /// Every form.
    pub const ALL: [Form; 5] = [Form::Planes, Form::Tokens, Form::Packed, Form::Analysis, Form::Oracle];

    /// The observation's forms (what an agent may see).
    pub const OBSERVATIONS: [Form; 4] = [Form::Planes, Form::Tokens, Form::Packed, Form::Analysis];

    /// The name users write: `planes`, `tokens`, `packed`, `analysis` or `oracle`.
    pub fn name(self) -> &'static str {
        match self {
            Form::Planes => "planes",
            Form::Tokens => "tokens",
            Form::Packed => "packed",
            Form::Analysis => "analysis",
            Form::Oracle => "oracle",
        }
    }

    /// 32-bit words of one observation.
    pub const fn words(self) -> usize {
        match self {
            Form::Planes => crate::hand::words::<k::ObsPlanes>(),
            Form::Tokens => crate::hand::words::<k::ObsTokens>(),
            Form::Packed => crate::hand::words::<k::ObsPacked>(),
            Form::Analysis => crate::hand::words::<k::ObsAnalysis>(),
            Form::Oracle => crate::hand::words::<k::ObsOracle>(),
        }
    }

    /// Bytes of one observation.
    pub const fn bytes(self) -> usize {
        self.words() * 4
    }

    /// The fields of this form.
    pub fn fields(self) -> &'static [Field] {
        match self {
            Form::Planes => &PLANES_FIELDS,
            Form::Tokens => &TOKENS_FIELDS,
            Form::Packed => &PACKED_FIELDS,
            Form::Analysis => &ANALYSIS_FIELDS,
            Form::Oracle => &ORACLE_FIELDS,
        }
    }

    /// The field called `name`.
    pub fn field(self, name: &str) -> Option<&'static Field> {
        self.fields().iter().find(|f| f.name == name)
    }
}

impl std::fmt::Display for Form {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Form {
    type Err = UnknownName;

    fn from_str(name: &str) -> Result<Form, UnknownName> {
        UnknownName::find("observation form", name, &Form::ALL)
    }
}

/// One `form` record of `state` seen by `seat` (0..3, or 4 for the player to move), computed on
/// the CPU: for a single position (a log's, a test's); batches go through
/// [`crate::env::Env::observe`].
pub fn record(variant: crate::Variant, form: Form, state: &k::GameState, seat: u32) -> Vec<u8> {
    let mut words = vec![0u32; form.words()];
    observe_cpu(
        variant,
        form,
        bytemuck::bytes_of(state),
        &[seat],
        &mut words,
        &mut Vec::new(),
        true,
    );
    bytemuck::cast_slice(&words).to_vec()
}

/// Writes `form` observations of `states` (GameState words) for the seats in `args` into `out`.
/// `tables` holds a [`TableView`] per state, made here on first use, that the planes, packed planes
/// and tokens follow from one call to the next.
pub(crate) fn observe_cpu<S: bytemuck::Pod>(
    variant: crate::Variant,
    form: Form,
    states: &[S],
    args: &[u32],
    out: &mut [u32],
    tables: &mut Vec<TableView>,
    serial: bool,
) {
    let sts: &[k::GameState] = bytemuck::cast_slice(states);
    // The views follow four-player rounds; three players' observations come from the kernel's
    // own writers, which rescan the round (the GPU's, and the views' oracle).
    if variant.seats() != 4 {
        with_variant!(variant, v => match form {
            Form::Planes => each(out, sts, args, serial, v::observe_planes),
            Form::Tokens => each(out, sts, args, serial, v::observe_tokens),
            Form::Packed => each(out, sts, args, serial, v::observe_packed),
            Form::Analysis => each(out, sts, args, serial, v::observe_analysis),
            Form::Oracle => each(out, sts, args, serial, v::observe_oracle),
        });
        return;
    }
    if matches!(form, Form::Planes | Form::Packed | Form::Tokens) {
        tables.resize_with(sts.len(), TableView::default);
    }
    with_variant!(variant, v => match form {
        Form::Planes => {
            each_followed(out, sts, args, tables, SEAT_ROWS, serial, |s, arg, table, o: &mut k::ObsPlanes| {
                table.write_seats(v::observer(s, arg), o);
                v::planes_but_seats_into(s, arg, table.tiles(), o);
            })
        }
        Form::Tokens => {
            each_followed(out, sts, args, tables, EVENT_LIST, serial, |s, arg, table, o: &mut k::ObsTokens| {
                v::tokens_but_events_into(s, arg, table.tiles(), o);
                let observer = v::observer(s, arg);
                table.write_events(s, observer, o);
            })
        }
        Form::Packed => {
            each_followed(out, sts, args, tables, SEAT_ROWS, serial, |s, arg, table, o: &mut k::ObsPacked| {
                table.write_packed_seats(v::observer(s, arg), o);
                v::packed_but_seats_into(s, arg, table.tiles(), o);
            })
        }
        Form::Analysis => each(out, sts, args, serial, v::observe_analysis),
        Form::Oracle => each(out, sts, args, serial, v::observe_oracle),
    })
}
