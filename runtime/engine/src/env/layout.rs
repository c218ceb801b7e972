//! One variant's action ids in another's terms. The layouts of `rules/variants/*.toml` differ
//! only in which kinds of action they hold (no-red has no `pon_red` and 34 discards, M-League no
//! `kyuushu`, three players no chi but `kita`), so an action keeps its name from one layout to the
//! next ([`action_names`]): the log readers and writers work in red's layout, which has every
//! four-player kind, and meet other variants through this map.

use super::step::action_names;
use crate::Variant;

/// The ids of `from`'s actions in `to`'s layout.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ActionMap {
    to: Vec<Option<u32>>,
}

impl ActionMap {
    /// Maps every action of `from` to the action of the same name in `to`, if it has one.
    pub fn new(from: Variant, to: Variant) -> ActionMap {
        let target = action_names(to);
        let to = action_names(from)
            .iter()
            .map(|name| target.iter().position(|t| t == name).map(|i| i as u32))
            .collect();
        ActionMap { to }
    }

    /// Action `id` of `from` in `to`'s layout; `None` where `to` has no such action or `id` is
    /// not an action of `from`.
    pub fn get(&self, id: u32) -> Option<u32> {
        self.to.get(id as usize).copied().flatten()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn actions_keep_their_names_between_layouts() {
        let red = action_names(Variant::Red);
        for v in Variant::ALL.iter().copied() {
            let names = action_names(v);
            let (there, back) = (ActionMap::new(v, Variant::Red), ActionMap::new(Variant::Red, v));
            for (id, name) in names.iter().enumerate() {
                // Red's layout has every four-player kind; only three players set North aside.
                if name == "kita" {
                    assert_eq!((v.seats(), there.get(id as u32)), (3, None), "{v}");
                    continue;
                }
                let r = there
                    .get(id as u32)
                    .unwrap_or_else(|| panic!("{v}: {name} is not in red's layout"));
                assert_eq!(&red[r as usize], name);
                assert_eq!(back.get(r), Some(id as u32), "{v}: {name}");
            }
            assert_eq!(there.get(names.len() as u32), None);
        }
        let no_red = ActionMap::new(Variant::Red, Variant::NoRed);
        let pon_red = red.iter().position(|n| n == "pon_red").expect("red has pon_red") as u32;
        assert_eq!(no_red.get(pon_red), None);
        let to_mleague = ActionMap::new(Variant::Red, Variant::Mleague);
        let kyuushu = red.iter().position(|n| n == "kyuushu").expect("red has kyuushu") as u32;
        assert_eq!(to_mleague.get(kyuushu), None);
        // The discard of a black 5m keeps its id; the self kan after it moves down by three.
        let self_kan_1m = red.iter().position(|n| n == "self_kan_1m").expect("self_kan_1m") as u32;
        assert_eq!((no_red.get(4), no_red.get(self_kan_1m)), (Some(4), Some(34)));
        let to_sanma = ActionMap::new(Variant::Red, Variant::Sanma);
        let chi_left = red.iter().position(|n| n == "chi_left").expect("red has chi_left") as u32;
        assert_eq!(to_sanma.get(chi_left), None);
    }
}
