//! The fast validator of a named fixed layout, worked out at compile time.
//!
//! A [`Plan`] is computed by a `const fn` from a [`Layout`], one of its [`Fixed`] layouts and
//! the `NPROPS` the fast path is written for: per entry, which one test its class and pin
//! need (a bit in one of a few masks), and which [`Rule`]s can still fail. A rule whose switch
//! the fixed layout pins to another value, or whose entry it pins to 0, holds whatever the
//! other entries are and is dropped; a rule whose switch it pins to the rule's value becomes a
//! class test of the entry (0, or 0 < v < ∞); only the others are tested per call. A
//! [`Variant`](super::Variant) whose switch the fixed layout pins to the variant's value gives
//! its entries' classes instead of the layout's; one that the fixed layout neither rules out
//! nor pins is a compile-time error.
//!
//! [`admits_fixed`] reads the plan through an associated constant ([`FastLayout::PLAN`]), so
//! every mask is a constant in the compiled code: it is one OR of [`range_flag`]s (0 ≤ v < ∞,
//! |v| < ∞, 0 < v < ∞) tested by its top bit, one OR of the bits of the entries pinned to ±0,
//! and the few equality tests left: the shape of the hand-written readers it replaced.

use super::{Class, Fix, Fixed, Layout, Rule, range_flag};

/// Most entries a plan covers (`unrolled!` below lists this many indices).
const MAX: usize = 20;

/// Top bit clear exactly when 0 < v < ∞: [`range_flag`]'s test, and `b − 1` wraps to the top
/// for +0 (−0 is +0 after adding +0).
#[inline(always)]
pub(crate) fn positive_flag(v: f64) -> u64 {
    let b = (v + 0.0).to_bits();
    b | b.wrapping_add(1 << 52) | b.wrapping_sub(1)
}

/// What [`admits_fixed`] tests, entry by entry (bit `i` of a mask is `PROPS(i + 1)`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Plan {
    /// The layout.
    pub(crate) layout: &'static Layout,
    /// The `NPROPS` the fast path reads (entries past it are absent, i.e. 0).
    pub(crate) nprops: usize,
    /// 0 ≤ v < ∞.
    range: u32,
    /// |v| < ∞.
    finite: u32,
    /// 0 < v < ∞.
    positive: u32,
    /// ±0.
    zero: u32,
    /// Exactly `value[i]`.
    exact: u32,
    value: [i32; MAX],
    /// 0 or `PROPS(zero_or_equal[i])`; 0 for none.
    zero_or_equal: [usize; MAX],
    /// "None" (≤ 0) or `PROPS(none_or_equal[i])`; 0 for none.
    none_or_equal: [usize; MAX],
    /// In [lo, hi] (or [lo, hi) when `open_hi`) with |lo|, |hi| ≤ 1, tested as
    /// 0 ≤ v − lo < ∞ and 0 ≤ hi − v < ∞ (0 < hi − v < ∞): [`interval_flags`].
    interval: u32,
    /// The bounds of `interval`'s entries.
    lo: [f64; MAX],
    hi: [f64; MAX],
    open_hi: u32,
    /// The class's own test ([`Class::admits`]).
    other: u32,
    /// Each entry's class in this fixed layout (a variant's where it is pinned on).
    class: [Class; MAX],
    /// The rules tested per call (bit `r` is `layout.rules[r]`).
    rules: u32,
}

/// A named fixed layout whose validator is worked out at compile time: a unit type per fast
/// path, `impl FastLayout for Plain { const PLAN: Plan = Plan::of(&COULOMB, &PLAIN, 7); }`.
pub(crate) trait FastLayout {
    /// The plan (a constant: evaluated, and checked, when the crate compiles).
    const PLAN: Plan;
}

impl Plan {
    /// The plan of `fixed` over `layout` for `NPROPS = nprops`. Panics (at compile time, as
    /// the plans are constants) when the fixed layout leaves a variant possible, pins an entry
    /// past `nprops` or a rule needs what the plan cannot test.
    #[must_use]
    pub(crate) const fn of(layout: &'static Layout, fixed: &Fixed, nprops: usize) -> Plan {
        assert!(nprops <= MAX && nprops <= layout.entries.len() && layout.rules.len() <= 32);
        let mut p = Plan {
            layout,
            nprops,
            range: 0,
            finite: 0,
            positive: 0,
            zero: 0,
            exact: 0,
            value: [0; MAX],
            zero_or_equal: [0; MAX],
            none_or_equal: [0; MAX],
            interval: 0,
            lo: [0.0; MAX],
            hi: [0.0; MAX],
            open_hi: 0,
            other: 0,
            class: [Class::Finite; MAX],
            rules: 0,
        };
        let mut k = 0;
        while k < fixed.fixed.len() {
            assert!(fixed.fixed[k].0 <= nprops, "a pinned entry past NPROPS");
            k += 1;
        }
        let mut i = 0;
        while i < nprops {
            let bit = 1 << i;
            let entry = &layout.entries[i];
            assert!(entry.index == i + 1);
            p.class[i] = class_in(layout, fixed, entry.index);
            match fixed.pin(entry.index) {
                Some(Fix::Zero) => p.zero |= bit,
                Some(Fix::NoneOrEqual(j)) => {
                    assert!(j <= nprops && j != entry.index);
                    p.none_or_equal[i] = j;
                }
                Some(Fix::ZeroOrEqual(j)) => {
                    assert!(j <= nprops && j != entry.index);
                    p.zero_or_equal[i] = j;
                }
                Some(Fix::Is(c)) => {
                    p.exact |= bit;
                    p.value[i] = c;
                }
                // Tested by the reader's match.
                Some(Fix::MappedBy(_)) => {}
                None => match p.class[i] {
                    Class::NonNegative | Class::OffOrPositive => p.range |= bit,
                    Class::Finite | Class::FiniteOrNone => p.finite |= bit,
                    Class::Positive => p.positive |= bit,
                    Class::Code(c) => {
                        p.exact |= bit;
                        p.value[i] = c;
                    }
                    Class::Interval { lo, hi, open_hi } if lo <= hi && -1.0 <= lo && hi <= 1.0 => {
                        p.interval |= bit;
                        p.lo[i] = lo;
                        p.hi[i] = hi;
                        if open_hi {
                            p.open_hi |= bit;
                        }
                    }
                    _ => p.other |= bit,
                },
            }
            i += 1;
        }
        let mut v = 0;
        while v < layout.variants.len() {
            let variant = &layout.variants[v];
            assert!(
                !possible(layout, fixed, nprops, variant.on, variant.value)
                    || matches!(pinned_value(fixed, variant.on), Some(c) if c == variant.value),
                "the fixed layout leaves a variant possible"
            );
            v += 1;
        }
        let mut r = 0;
        while r < layout.rules.len() {
            let rule = layout.rules[r];
            let (a, b) = (rule.entry(), rule.other());
            let live = match rule {
                // Holds when the mode cannot occur (and a `ZeroWhen` entry that is always 0);
                // always in the mode: the entry's own test, 0 where the mode does not read it,
                // 0 < v < ∞ where it needs it.
                Rule::ZeroWhen { value, .. } | Rule::PositiveWhen { value, .. } => {
                    let zero = matches!(rule, Rule::ZeroWhen { .. });
                    // 0 or equal to the switch, which must be 0 for the rule to apply: 0.
                    let zero_or_switch = zero
                        && value == 0
                        && matches!(fixed.pin(a), Some(Fix::ZeroOrEqual(j)) if j == b);
                    if !possible(layout, fixed, nprops, b, value)
                        || (zero && always_zero(fixed, nprops, a))
                        || zero_or_switch
                    {
                        false
                    } else if matches!(known(layout, fixed, nprops, b), Some(c) if c == value) {
                        let test = if zero { Test::Zero } else { Test::Positive };
                        p = p.retest(a, test, fixed);
                        false
                    } else {
                        true
                    }
                }
                // Pinned to "none" (or 0) or to the floor itself: holds.
                Rule::AtLeastWhenGiven { floor, .. } => {
                    !(always_zero(fixed, nprops, a)
                        || matches!(fixed.pin(a),
                        Some(Fix::NoneOrEqual(j) | Fix::ZeroOrEqual(j)) if j == floor))
                }
            };
            if live {
                assert!(a <= nprops && b <= nprops, "a rule about an absent entry");
                p.rules |= 1 << r;
            }
            r += 1;
        }
        p
    }

    /// `PROPS(index)` (unpinned, within `nprops`) tested as `test` instead of its class alone.
    const fn retest(mut self, index: usize, test: Test, fixed: &Fixed) -> Plan {
        assert!(
            index <= self.nprops && fixed.pin(index).is_none(),
            "a rule turns a pinned or absent entry into a class test"
        );
        let bit = 1 << (index - 1);
        match test {
            // 0 is in every optional class (a schema test), so only the pin is left.
            Test::Zero => {
                self.range &= !bit;
                self.finite &= !bit;
                self.positive &= !bit;
                self.other &= !bit;
                self.interval &= !bit;
                self.zero |= bit;
            }
            // 0 < v < ∞ is within 0 ≤ v < ∞; any other class keeps its own test as well.
            Test::Positive => {
                self.range &= !bit;
                self.positive |= bit;
            }
        }
        self
    }

    /// `PROPS(index)`'s class in this plan (for tests).
    #[cfg(test)]
    #[must_use]
    pub(crate) fn class_of(&self, index: usize) -> Class {
        self.class[index - 1]
    }

    /// The rules tested per call (for tests).
    #[cfg(test)]
    #[must_use]
    pub(crate) fn live_rules(&self) -> Vec<&'static Rule> {
        let rules = self.layout.rules;
        (0..rules.len())
            .filter(|r| self.rules >> r & 1 == 1)
            .map(|r| &rules[r])
            .collect()
    }
}

/// How a rule turns into a test of one entry.
#[derive(Clone, Copy)]
enum Test {
    Zero,
    Positive,
}

/// `PROPS(index)` is 0 whatever the host passes (absent, or pinned to ±0).
const fn always_zero(fixed: &Fixed, nprops: usize, index: usize) -> bool {
    index > nprops || matches!(fixed.pin(index), Some(Fix::Zero))
}

/// The one value the fixed layout pins `PROPS(index)` to, if it does.
const fn pinned_value(fixed: &Fixed, index: usize) -> Option<i32> {
    match fixed.pin(index) {
        Some(Fix::Zero) => Some(0),
        Some(Fix::Is(c)) => Some(c),
        Some(Fix::MappedBy(list)) if list.len() == 1 => Some(list[0]),
        _ => None,
    }
}

/// `PROPS(index)`'s class in this fixed layout: the entry of a variant whose switch the fixed
/// layout pins to the variant's value, else the layout's.
const fn class_in(layout: &Layout, fixed: &Fixed, index: usize) -> Class {
    let mut v = 0;
    while v < layout.variants.len() {
        let variant = &layout.variants[v];
        if matches!(pinned_value(fixed, variant.on), Some(c) if c == variant.value) {
            let mut k = 0;
            while k < variant.entries.len() {
                if variant.entries[k].index == index {
                    return variant.entries[k].class;
                }
                k += 1;
            }
        }
        v += 1;
    }
    layout.entries[index - 1].class
}

/// The one value `PROPS(index)` can take in this fixed layout, if there is one.
const fn known(layout: &Layout, fixed: &Fixed, nprops: usize, index: usize) -> Option<i32> {
    if index > nprops {
        return Some(0);
    }
    match fixed.pin(index) {
        Some(_) => pinned_value(fixed, index),
        None => match class_in(layout, fixed, index) {
            Class::Code(c) => Some(c),
            _ => None,
        },
    }
}

/// Whether `PROPS(index) = x` can pass this fixed layout's tests (true when unsure).
const fn possible(layout: &Layout, fixed: &Fixed, nprops: usize, index: usize, x: i32) -> bool {
    if index > nprops {
        return x == 0;
    }
    match fixed.pin(index) {
        Some(Fix::Zero) => x == 0,
        Some(Fix::Is(c)) => c == x,
        Some(Fix::MappedBy(list)) => {
            let mut k = 0;
            while k < list.len() {
                if list[k] == x {
                    return true;
                }
                k += 1;
            }
            false
        }
        Some(Fix::NoneOrEqual(_) | Fix::ZeroOrEqual(_)) => true,
        None => match class_in(layout, fixed, index) {
            Class::Code(c) => c == x,
            Class::Switch { .. } => x == 0 || x == 1,
            Class::Choice(options) => {
                let mut k = 0;
                while k < options.len() {
                    if options[k].0 == x {
                        return true;
                    }
                    k += 1;
                }
                false
            }
            _ => true,
        },
    }
}

/// Top bit clear exactly when `v` is in [lo, hi] ([lo, hi) when `open_hi`), for bounds of
/// magnitude ≤ 1: the difference of two finite doubles is 0 only when they are equal and keeps
/// the sign of the exact difference, and with bounds this small it overflows only for an
/// infinite `v`, which both tests refuse; NaN sets the flag.
#[inline(always)]
pub(crate) fn interval_flags(v: f64, lo: f64, hi: f64, open_hi: bool) -> u64 {
    range_flag(v - lo)
        | if open_hi {
            positive_flag(hi - v)
        } else {
            range_flag(hi - v)
        }
}

/// Whether the first `N` entries `e` (`e[i - 1] = PROPS(i)`, `N` the plan's `NPROPS`) pass the
/// fixed layout `P`'s tests: each entry's class (a stick mode pinned `MappedBy` is left to the
/// caller's match), its pin, and the rules that can still fail. Straight-line: every mask is
/// a constant, so each entry keeps only its one test.
#[inline(always)]
pub(crate) fn admits_fixed<P: FastLayout, const N: usize>(e: &[f64; N]) -> bool {
    const { assert!(N == P::PLAN.nprops) };
    let mut flags = 0u64;
    let mut zeros = 0u64;
    let mut ok = true;
    // Every part of the plan is read in a `const` block: a constant, also in a debug build
    // (where a read of `P::PLAN` itself copies the whole plan to the stack, once per read).
    unrolled!(I in [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19] {
        if I < N {
            let v = e[I];
            if const { P::PLAN.range >> I & 1 == 1 } {
                flags |= range_flag(v);
            }
            if const { P::PLAN.finite >> I & 1 == 1 } {
                flags |= range_flag(v.abs());
            }
            if const { P::PLAN.positive >> I & 1 == 1 } {
                flags |= positive_flag(v);
            }
            if const { P::PLAN.zero >> I & 1 == 1 } {
                zeros |= v.to_bits();
            }
            if const { P::PLAN.exact >> I & 1 == 1 } {
                ok &= v == f64::from(const { P::PLAN.value[I] });
            }
            let none_or_equal = const { P::PLAN.none_or_equal[I] };
            if none_or_equal != 0 {
                // "None" is −∞ < v ≤ 0, i.e. 0 ≤ −v < ∞: the same top-bit test.
                flags |= if v == e[none_or_equal - 1] { 0 } else { range_flag(-v) };
            }
            if const { P::PLAN.interval >> I & 1 == 1 } {
                let (lo, hi) = const { (P::PLAN.lo[I], P::PLAN.hi[I]) };
                flags |= interval_flags(v, lo, hi, const { P::PLAN.open_hi >> I & 1 == 1 });
            }
            if const { P::PLAN.other >> I & 1 == 1 } {
                ok &= const { P::PLAN.class[I] }.admits(v);
            }
        }
    });
    unrolled!(R in [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31] {
        let live = const {
            if P::PLAN.rules >> R & 1 == 1 {
                Some(P::PLAN.layout.rules[R])
            } else {
                None
            }
        };
        match live {
            // v = 0 when w = the value: v's bits among those that must be ±0 (a select).
            Some(Rule::ZeroWhen { entry, on, value, .. }) => {
                zeros |= if e[on - 1] == f64::from(value) { e[entry - 1].to_bits() } else { 0 };
            }
            Some(rule) => ok &= rule.holds(e[rule.entry() - 1], e[rule.other() - 1]),
            None => {}
        }
    });
    if !(ok && flags >> 63 == 0 && zeros << 1 == 0) {
        return false;
    }
    // "0 or equal to another entry" last, one branch each, 0 (isotropy's usual value) first:
    // as an `&=` it became a branch-free sequence of 4 more instructions per call.
    unrolled!(I in [0 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19] {
        let zero_or_equal = const { P::PLAN.zero_or_equal[I] };
        if I < N && zero_or_equal != 0 {
            let v = e[I];
            if !(v == 0.0 || v == e[zero_or_equal - 1]) {
                return false;
            }
        }
    });
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`interval_flags`] against [`Class::admits`] for the intervals of the layouts and a few
    /// more, at the f64 edges and next to each bound.
    #[test]
    fn interval_flags_are_the_class_test() {
        let bounds = [
            (-0.5, 0.0),
            (0.0, 1.0),
            (-1.0, 1.0),
            (0.25, 0.75),
            (-1.0, -0.5),
        ];
        for (lo, hi) in bounds {
            for open_hi in [false, true] {
                let class = Class::Interval { lo, hi, open_hi };
                let near = [lo, hi]
                    .into_iter()
                    .flat_map(|b: f64| [b, b.next_down(), b.next_up(), -b, b * 0.5, b * 2.0]);
                for v in crate::testing::EDGE_VALUES.into_iter().chain(near) {
                    assert_eq!(
                        interval_flags(v, lo, hi, open_hi) >> 63 == 0,
                        class.admits(v),
                        "{v:e} in {class:?}"
                    );
                }
            }
        }
    }

    /// [`positive_flag`] against the plain comparisons, at the edges of 0 < v < ∞.
    #[test]
    fn positive_flag_is_zero_to_infinity_open() {
        for v in crate::testing::EDGE_VALUES {
            let expected = v.is_finite() && v > 0.0;
            assert_eq!(positive_flag(v) >> 63 == 0, expected, "{v:e}");
        }
    }
}
